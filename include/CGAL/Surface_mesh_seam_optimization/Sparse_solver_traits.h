// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Models of the SparseSolverTraits concept: analyse the pattern once per
// topology, factorize and solve every Newton iteration.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SPARSE_SOLVER_TRAITS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SPARSE_SOLVER_TRAITS_H

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_SMSO_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <memory>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Wraps any Eigen sparse direct solver with `analyzePattern()`,
/// `factorize()`, `solve()` and `info()` (the solver reads the lower triangle).
/// \cgalModels `SparseSolverTraits`
template <typename EigenSolver>
class Eigen_sparse_solver_traits
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  typedef Eigen::VectorXd Vector;

  Eigen_sparse_solver_traits() : m_solver(new EigenSolver) {}

  /// symbolic analysis; called once per sparsity pattern
  bool analyze_pattern(const Matrix& A)
  {
    m_solver->analyzePattern(A);
    return m_solver->info() == Eigen::Success;
  }
  /// numeric factorization of a matrix with the analysed pattern
  bool factorize(const Matrix& A)
  {
    m_solver->factorize(A);
    return m_solver->info() == Eigen::Success;
  }
  bool solve(const Vector& b, Vector& x)
  {
    x = m_solver->solve(b);
    return m_solver->info() == Eigen::Success && x.allFinite();
  }
  EigenSolver& eigen_solver() { return *m_solver; }

private:
  // Eigen's solvers are not copyable; traits are passed by value like CGAL's.
  std::shared_ptr<EigenSolver> m_solver;
};

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// The default: Eigen's simplicial LDL^T with AMD ordering (measured faster
/// than CHOLMOD supernodal on 10k-50k face meshes here).
typedef Eigen_sparse_solver_traits<
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::AMDOrdering<int> > >
  Eigen_simplicial_ldlt_traits;

#if defined(CGAL_SMSO_HAS_CHOLMOD) || defined(DOXYGEN_RUNNING)
/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// SuiteSparse CHOLMOD (supernodal or simplicial, chosen by CHOLMOD).
/// Declared only if the macro `CGAL_SMSO_HAS_CHOLMOD` is defined: the CMake
/// target `CGAL::Surface_mesh_seam_optimization` defines it (and links
/// CHOLMOD) when CHOLMOD was found; without that target, define it, add
/// SuiteSparse's include directory and link `cholmod` (see \ref SMSO_Extending).
typedef Eigen_sparse_solver_traits<Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> >
  Cholmod_traits;
#endif

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
