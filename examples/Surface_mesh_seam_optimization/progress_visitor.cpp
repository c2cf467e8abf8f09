// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A visitor that prints the progress of optimize_seams() and cancels the run
// after a number of Newton iterations or a time budget. A cancelled run
// returns WARNING_CANCELLED and still writes a valid, flip-free result: the
// shortest seams met so far within the bound, if any.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/IO/OBJ.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>          Kernel;
typedef Kernel::Point_2                         Point_2;
typedef CGAL::Surface_mesh<Kernel::Point_3>     Mesh;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace NP = CGAL::Surface_mesh_seam_optimization::parameters;

// Only the members it overrides differ from the default (which never cancels).
struct Progress_visitor : public SMSO::Default_seam_optimization_visitor
{
  std::size_t max_iterations;
  double time_budget; // seconds
  std::size_t last_iteration = 0;
  bool cancelled = false;

  Progress_visitor(std::size_t max_iterations, double time_budget)
    : max_iterations(max_iterations), time_budget(time_budget) {}

  bool on_iteration(const SMSO::Seam_optimization_progress& p)
  {
    last_iteration = p.iterations;
    if(p.iterations % 20 == 0)
      std::cout << "  iteration " << p.iterations << ": E_SD " << p.distortion << ", E_se "
                << p.seam_length_normalized << ", " << p.seconds << " s" << std::endl;
    cancelled = p.iterations >= max_iterations || p.seconds >= time_budget;
    return !cancelled; // false: cancel
  }
  bool on_lambda_update(const SMSO::Seam_optimization_progress& p)
  {
    std::cout << "  lambda " << p.lambda << " after " << p.topology_operations << " topology operations"
              << std::endl;
    cancelled = p.seconds >= time_budget;
    return !cancelled;
  }
};

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : SMSO_DATA_DIR "/cat_f1500.obj";
  const std::size_t max_iterations = (argc > 2) ? std::strtoul(argv[2], nullptr, 10) : 60;
  const double time_budget = (argc > 3) ? std::atof(argv[3]) : 30;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh))
  {
    std::cerr << "Cannot read a mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;
  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;

  // std::ref: the function must call this object, not a copy of it
  Progress_visitor visitor(max_iterations, time_budget);
  const SMSO::Optimization_result r =
    SMSO::optimize_seams(mesh, uvmap, NP::edge_is_seam_map(seams).visitor(std::ref(visitor)));
  std::cout << "status " << SMSO::get_error_code_name(r.status) << " (" << SMSO::get_error_message(r.status)
            << ") after " << visitor.last_iteration << " Newton iterations" << std::endl;
  if(!r.has_result()) // only error codes leave the maps untouched
  {
    std::cerr << r.message << std::endl;
    return EXIT_FAILURE;
  }
  // In bound mode the result is the configuration with the shortest seams
  // met within the bound, or the last one if none was met yet.
  std::cout << "result written: E_SD " << r.distortion << ", E_se " << r.seam_length_normalized << ", "
            << r.charts << " chart(s), "
            << (r.bound_met ? "the best one within the bound 4.1" : "bound 4.1 not met yet: the last one")
            << std::endl;

  // The written maps are a valid result even though the run was cut short.
  const SMSO::Uv_map_measures m = SMSO::measure_uv_map(mesh, uvmap, NP::edge_is_seam_map(seams));
  // WARNING_CANCELLED exactly when the visitor asked for it, and no Newton
  // iteration after that.
  const bool ok = (r.status == SMSO::WARNING_CANCELLED) == visitor.cancelled &&
                  r.iterations <= visitor.last_iteration && m.flipped_triangles == 0 &&
                  std::abs(m.distortion - r.distortion) <= 1e-9 * r.distortion &&
                  std::abs(m.seam_length - r.seam_length) <= 1e-9 * (1 + r.seam_length) &&
                  (!r.bound_met || r.distortion <= 4.1);
  if(!ok)
  {
    std::cerr << "Invalid result: " << m.flipped_triangles << " flipped triangles, measured E_SD "
              << m.distortion << std::endl;
    return EXIT_FAILURE;
  }
  const std::string out = "progress_visitor.obj";
  if(!SMSO::IO::write_OBJ_with_uv_map(out, mesh, uvmap))
  {
    std::cerr << "Cannot write " << out << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "UV map written to " << out << std::endl;
  // The cat needs about 100 iterations: with the default limit (60) the run
  // must have been cancelled.
  return (argc > 2 || r.status == SMSO::WARNING_CANCELLED) ? EXIT_SUCCESS : EXIT_FAILURE;
}
