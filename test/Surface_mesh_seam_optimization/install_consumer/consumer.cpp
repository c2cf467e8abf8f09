// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// consumer MESH: optimize_seams() with the installed headers; exit code 0
// only if the result is OK and meets the bound.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>

#include <cstdlib>
#include <iostream>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh) || is_empty(mesh))
  {
    std::cerr << "usage: consumer MESH (a triangle mesh)" << std::endl;
    return EXIT_FAILURE;
  }
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Kernel::Point_2>("h:uv").first;
  const SMSO::Optimization_result r =
    SMSO::optimize_seams(mesh, uvmap, SMSO::parameters::distortion_bound(4.1).number_of_recut_rounds(1));
  std::cout << SMSO::get_error_code_name(r.status) << ": E_SD " << r.distortion << ", " << r.charts
            << " charts, " << r.iterations << " iterations" << std::endl;
  return (r.status == SMSO::OK && r.bound_met) ? EXIT_SUCCESS : EXIT_FAILURE;
}
