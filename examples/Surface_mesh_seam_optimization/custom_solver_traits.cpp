// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Choosing the sparse linear solver of the Newton steps: CHOLMOD when the
// package was built with it, else an Eigen solver wrapped by the user.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/Sparse_solver_traits.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>

#include <Eigen/SparseCholesky>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>          Kernel;
typedef Kernel::Point_2                         Point_2;
typedef CGAL::Surface_mesh<Kernel::Point_3>     Mesh;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;

#ifdef CGAL_SMSO_HAS_CHOLMOD
typedef SMSO::Cholmod_traits                    Solver_traits;
const char* solver_name = "CHOLMOD";
#else
// Any Eigen sparse direct solver with analyzePattern()/factorize()/solve();
// the Hessian is symmetric positive semi-definite, and only its lower
// triangle is filled.
typedef SMSO::Eigen_sparse_solver_traits<
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int> > >
                                                Solver_traits;
const char* solver_name = "Eigen SimplicialLLT";
#endif

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : SMSO_DATA_DIR "/bunny_i_f10000.obj";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh))
  {
    std::cerr << "Cannot read a mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  auto uv_default = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv_default").first;
  auto uv_custom = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv_custom").first;

  // Default: Eigen's SimplicialLDLT (SMSO::Eigen_simplicial_ldlt_traits).
  const SMSO::Optimization_result d = SMSO::minimize_distortion(mesh, uv_default);
  const SMSO::Optimization_result c =
    SMSO::minimize_distortion(mesh, uv_custom, CGAL::parameters::sparse_linear_solver(Solver_traits()));
  if(!d.has_result() || !c.has_result())
  {
    std::cerr << "Failed: " << SMSO::get_error_message(d.status) << " / "
              << SMSO::get_error_message(c.status) << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "default (Eigen SimplicialLDLT): E_SD " << d.distortion << ", " << d.iterations
            << " iterations, " << d.seconds << " s\n"
            << solver_name << ": E_SD " << c.distortion << ", " << c.iterations
            << " iterations, " << c.seconds << " s" << std::endl;

  // Both solve the same systems up to rounding: the minimum must agree.
  const double relative_difference = std::abs(c.distortion - d.distortion) / d.distortion;
  const std::size_t flipped = SMSO::number_of_flipped_triangles(mesh, uv_default) +
                              SMSO::number_of_flipped_triangles(mesh, uv_custom);
  std::cout << "relative E_SD difference " << relative_difference << ", " << flipped
            << " flipped triangles" << std::endl;
  return (relative_difference <= 1e-6 && flipped == 0) ? EXIT_SUCCESS : EXIT_FAILURE;
}
