// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Seams for other distortion energies: the bound is on the run's energy, in
// its own units, and each energy has a default bound allowing the same small
// strains as E_SD <= 4.1. The conformal energy (MIPS plus a small area term)
// trades some area distortion for angles; ARAP measures stretch symmetrically.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/ARAP_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/Conformal_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>          Kernel;
typedef Kernel::Point_2                         Point_2;
typedef CGAL::Surface_mesh<Kernel::Point_3>     Mesh;
typedef Mesh::Property_map<Mesh::Halfedge_index, Point_2> UV_map;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace NP = CGAL::Surface_mesh_seam_optimization::parameters;

// Runs `energy` at its default bound and prints its figures; false on failure.
template <typename Energy>
bool run(Mesh& mesh, const char* label, const Energy& energy)
{
  UV_map uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>(std::string("h:uv_") + label).first;
  const SMSO::Optimization_result r = SMSO::optimize_seams(mesh, uvmap, NP::energy(energy));
  if(!r.has_result())
  {
    std::cerr << label << ": " << SMSO::get_error_message(r.status) << ": " << r.message << std::endl;
    return false;
  }
  // angle distortion alone: pure MIPS (the conformal energy without its area term)
  const double mips = SMSO::distortion(mesh, uvmap, NP::energy(SMSO::Conformal_energy(0.)));
  std::cout << label << ": energy " << r.energy_value << " (bound " << energy.default_bound()
            << (r.bound_met ? ", met" : ", NOT met") << "), E_SD " << r.distortion << ", MIPS " << mips
            << ", normalized seam length " << r.seam_length_normalized << ", " << r.charts << " chart(s)"
            << std::endl;
  return r.bound_met && SMSO::number_of_flipped_triangles(mesh, uvmap) == 0;
}

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : SMSO_DATA_DIR "/cat_f1500.obj";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh))
  {
    std::cerr << "Cannot read a mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  const bool ok = run(mesh, "symmetric Dirichlet", SMSO::Symmetric_Dirichlet_energy()) &&
                  run(mesh, "conformal", SMSO::Conformal_energy()) &&
                  run(mesh, "ARAP", SMSO::ARAP_energy());
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
