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
#include <vector>

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
/// An Eigen ordering functor (as `Eigen::AMDOrdering`): Eigen's approximate
/// minimum degree ordering of the graph of the 2x2 blocks of unknowns
/// (2k, 2k+1), the two coordinates of a UV vertex, expanded to the
/// unknowns. That graph has a quarter of the entries, and the pattern is
/// analysed anew after every change of the UV topology (hundreds of times
/// per run). On a matrix of odd size, the ordering of the unknowns.
template <typename StorageIndex>
class Block_amd_ordering
{
public:
  /// the permutation type of Eigen's orderings
  typedef Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, StorageIndex> PermutationType;

  /// the fill-reducing permutation of the symmetric matrix `A` (both
  /// triangles stored, as Eigen's simplicial factorizations pass it)
  template <typename MatrixType>
  void operator()(const MatrixType& A, PermutationType& perm)
  {
    const StorageIndex n = StorageIndex(A.cols());
    if(n % 2 != 0) { Eigen::AMDOrdering<StorageIndex>()(A, perm); return; }
    const StorageIndex m = n / 2;
    Eigen::SparseMatrix<double, Eigen::ColMajor, StorageIndex> B(m, m);
    std::vector<StorageIndex> outer(m + 1, 0), inner, mark(m, -1);
    inner.reserve(std::size_t(A.nonZeros() / 3 + m));
    for(StorageIndex k = 0; k < m; ++k)
    {
      for(StorageIndex j = 2 * k; j < 2 * k + 2; ++j)
        for(typename MatrixType::InnerIterator it(A, j); it; ++it)
        {
          const StorageIndex b = StorageIndex(it.index() / 2);
          if(mark[b] == k) continue;
          mark[b] = k;
          inner.push_back(b);
        }
      outer[k + 1] = StorageIndex(inner.size());
    }
    B.resizeNonZeros(Eigen::Index(inner.size()));
    std::copy(outer.begin(), outer.end(), B.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), B.innerIndexPtr());
    std::fill(B.valuePtr(), B.valuePtr() + inner.size(), 1.);
    PermutationType block;
    Eigen::internal::minimum_degree_ordering(B, block);
    perm.resize(n);
    for(StorageIndex k = 0; k < m; ++k)
      for(StorageIndex c = 0; c < 2; ++c) perm.indices()[2 * k + c] = 2 * block.indices()[k] + c;
  }
};

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Eigen's simplicial LDL^T with the AMD ordering of the UV vertices
/// (`Block_amd_ordering`; faster than CHOLMOD's supernodal factorization
/// below about 30k unknowns, see `Default_sparse_solver_traits`).
typedef Eigen_sparse_solver_traits<
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Block_amd_ordering<int> > >
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

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// The default: `Eigen_simplicial_ldlt_traits` for systems of fewer unknowns
/// than a threshold, and above it CHOLMOD's supernodal Cholesky factorization
/// (BLAS level 3: measured 1.4x faster at 48k faces, 2.3x at 97k and 5.6x at
/// 386k with OpenBLAS, and slower below about 30k unknowns), when the package
/// is built with CHOLMOD (see `Cholmod_traits`); without it, always the
/// former. The choice depends on the number of unknowns alone (the result is
/// deterministic), and a supernodal factorization that fails (a matrix that
/// is positive semi-definite only up to rounding) is done again by the
/// simplicial LDL^T of the same matrix.
/// \cgalModels `SparseSolverTraits`
class Default_sparse_solver_traits
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  typedef Eigen::VectorXd Vector;

  /// `threshold`: the number of unknowns from which CHOLMOD is used
  explicit Default_sparse_solver_traits(Eigen::Index threshold = 40000) : m_threshold(threshold) {}

  /// whether the last analysed pattern is factorized by CHOLMOD
  bool uses_cholmod() const { return m_large && !m_fallback; }

  bool analyze_pattern(const Matrix& A)
  {
    m_fallback = false;
#ifdef CGAL_SMSO_HAS_CHOLMOD
    m_large = A.rows() >= m_threshold;
    if(m_large) return m_supernodal.analyze_pattern(A);
#endif
    return m_ldlt.analyze_pattern(A);
  }
  bool factorize(const Matrix& A)
  {
#ifdef CGAL_SMSO_HAS_CHOLMOD
    if(m_large && !m_fallback)
    {
      if(m_supernodal.factorize(A)) return true;
      m_fallback = true; // for the rest of this pattern
      if(!m_ldlt.analyze_pattern(A)) return false;
    }
#endif
    return m_ldlt.factorize(A);
  }
  bool solve(const Vector& b, Vector& x)
  {
#ifdef CGAL_SMSO_HAS_CHOLMOD
    if(m_large && !m_fallback) return m_supernodal.solve(b, x);
#endif
    return m_ldlt.solve(b, x);
  }

private:
  Eigen::Index m_threshold;
  bool m_large = false, m_fallback = false;
  Eigen_simplicial_ldlt_traits m_ldlt;
#ifdef CGAL_SMSO_HAS_CHOLMOD
  Eigen_sparse_solver_traits<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> > m_supernodal;
#endif
};

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
