// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Models of the SparseSolverTraits concept: analyse the pattern once per
// topology, factorize and solve every Newton iteration.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SPARSE_SOLVER_TRAITS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SPARSE_SOLVER_TRAITS_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Block_ldlt.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Serial_openmp_scope.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_SMSO_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <algorithm>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Eigen's CHOLMOD wrappers are the solvers with a `cholmod()` common
template <typename Solver, typename = void>
struct Is_cholmod_solver : std::false_type {};
template <typename Solver>
struct Is_cholmod_solver<Solver, std::void_t<decltype(std::declval<Solver&>().cholmod())> >
  : std::true_type {};

} // namespace internal

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Wraps any Eigen sparse direct solver with `analyzePattern()`,
/// `factorize()`, `solve()` and `info()` (the solver reads the lower triangle).
/// For CHOLMOD's solvers (`Eigen::Cholmod*`), CHOLMOD prints nothing (a
/// failure is the return value), and OpenMP parallel regions that CHOLMOD
/// opens during a call run on the calling thread alone: CHOLMOD 3 built with
/// OpenMP uses a fixed 4 threads for memory loops that gain nothing from
/// them (measured 1.6x slower on 2 cores); the setting is the calling
/// thread's own and is restored after each call.
/// \cgalModels `SparseSolverTraits`
template <typename EigenSolver>
class Eigen_sparse_solver_traits
{
  static constexpr bool is_cholmod = internal::Is_cholmod_solver<EigenSolver>::value;

public:
  typedef Eigen::SparseMatrix<double> Matrix;
  typedef Eigen::VectorXd Vector;

  Eigen_sparse_solver_traits() : m_solver(new EigenSolver)
  {
    quiet(*m_solver, std::integral_constant<bool, is_cholmod>());
  }

  /// symbolic analysis; called once per sparsity pattern
  bool analyze_pattern(const Matrix& A)
  {
    internal::Serial_openmp_scope scope(is_cholmod);
    m_solver->analyzePattern(A);
    return m_solver->info() == Eigen::Success;
  }
  /// numeric factorization of a matrix with the analysed pattern
  bool factorize(const Matrix& A)
  {
    internal::Serial_openmp_scope scope(is_cholmod);
    m_solver->factorize(A);
    return m_solver->info() == Eigen::Success;
  }
  bool solve(const Vector& b, Vector& x)
  {
    internal::Serial_openmp_scope scope(is_cholmod);
    x = m_solver->solve(b);
    return m_solver->info() == Eigen::Success && x.allFinite();
  }
  EigenSolver& eigen_solver() { return *m_solver; }

private:
  static void quiet(EigenSolver&, std::false_type) {}
  // print level 0: no warning on stdout when a factorization fails (the
  // default solver then falls back to LDL^T; the caller sees the result)
  static void quiet(EigenSolver& solver, std::true_type) { solver.cholmod().print = 0; }

  // Eigen's solvers are not copyable; traits are passed by value like CGAL's.
  std::shared_ptr<EigenSolver> m_solver;
};

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Eigen's simplicial LDL^T with AMD ordering (the default's choice below
/// 40000 unknowns for matrices not made of 2x2 blocks, see
/// `Default_sparse_solver_traits`). The permuted matrix's pattern, and where
/// each entry of the given lower triangle goes in it, are computed with the
/// ordering, so that every factorization only scatters the values (Eigen's
/// `SimplicialLDLT` with an ordering permutes a copy of the matrix at every
/// factorization); the factors are those of
/// `SimplicialLDLT<Matrix, Lower, AMDOrdering<int> >`, to the last bit.
/// \cgalModels `SparseSolverTraits`
class Eigen_simplicial_ldlt_traits
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  typedef Eigen::VectorXd Vector;

  Eigen_simplicial_ldlt_traits() : m(new Data) {}

  /// symbolic analysis; called once per sparsity pattern
  bool analyze_pattern(const Matrix& A)
  {
    const int n = int(A.cols());
    {
      // (the self-adjoint overload: the general one makes A + A^T of the full matrix, the same pattern)
      Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
      Eigen::AMDOrdering<int>()(A.selfadjointView<Eigen::Lower>(), inverse);
      m->perm.resize(n);
      for(int k = 0; k < n; ++k) m->perm[inverse.indices()[k]] = k;
    }
    // the upper triangle of P A P^T, its entries in the order in which
    // Eigen's permutation puts them (the factorization's rounding depends on it)
    const Matrix& a = compressed(A);
    const int* perm = m->perm.data();
    const int* outer = a.outerIndexPtr();
    const int* inner = a.innerIndexPtr();
    std::vector<int> count(n + 1, 0);
    for(int j = 0; j < n; ++j)
      for(int k = outer[j]; k < outer[j + 1]; ++k)
        if(inner[k] >= j) ++count[(std::max)(perm[inner[k]], perm[j]) + 1];
    for(int j = 0; j < n; ++j) count[j + 1] += count[j];
    Matrix& U = m->permuted;
    U.resize(n, n);
    U.resizeNonZeros(count[n]);
    std::copy(count.begin(), count.end(), U.outerIndexPtr());
    std::fill(U.valuePtr(), U.valuePtr() + count[n], 0.);
    m->slot.assign(std::size_t(a.nonZeros()), -1);
    for(int j = 0; j < n; ++j)
      for(int k = outer[j]; k < outer[j + 1]; ++k)
      {
        if(inner[k] < j) continue;
        const int ip = perm[inner[k]], jp = perm[j];
        const int slot = count[(std::max)(ip, jp)]++;
        U.innerIndexPtr()[slot] = (std::min)(ip, jp);
        m->slot[std::size_t(k)] = slot;
      }
    m->ldlt.analyze_preordered(U);
    return m->ldlt.info() == Eigen::Success;
  }
  /// numeric factorization of a matrix with the analysed pattern
  bool factorize(const Matrix& A)
  {
    double* values = m->permuted.valuePtr();
    const double* a = compressed(A).valuePtr();
    for(std::size_t k = 0; k < m->slot.size(); ++k)
      if(m->slot[k] >= 0) values[m->slot[k]] = a[k];
    m->ldlt.factorize(m->permuted);
    return m->ldlt.info() == Eigen::Success;
  }
  bool solve(const Vector& b, Vector& x)
  {
    const Eigen::Index n = b.size();
    m->rhs.resize(n);
    for(Eigen::Index i = 0; i < n; ++i) m->rhs[m->perm[i]] = b[i];
    m->solution = m->ldlt.solve(m->rhs);
    if(m->ldlt.info() != Eigen::Success) return false;
    x.resize(n);
    for(Eigen::Index i = 0; i < n; ++i) x[i] = m->solution[m->perm[i]];
    return x.allFinite();
  }

private:
  const Matrix& compressed(const Matrix& A)
  {
    if(A.isCompressed()) return A;
    m->compressed = A;
    m->compressed.makeCompressed();
    return m->compressed;
  }

  // SimplicialLDLT's analyzePattern() copies the matrix twice when the
  // ordering is NaturalOrdering<int> (it tests for NaturalOrdering<Index>);
  // the given matrix is the permuted one, so only the elimination tree is due.
  struct Preordered_ldlt : Eigen::SimplicialLDLT<Matrix, Eigen::Upper, Eigen::NaturalOrdering<int> >
  {
    void analyze_preordered(const Matrix& U) { this->analyzePattern_preordered(U, true); }
  };

  struct Data
  {
    Matrix compressed; // a copy of an uncompressed input
    Preordered_ldlt ldlt;
    std::vector<int> perm, slot; // new index of each unknown; entry of A -> entry of the permuted matrix
    Matrix permuted;
    Vector rhs, solution;
  };
  // like Eigen_sparse_solver_traits: copies share the factorization
  std::shared_ptr<Data> m;
};

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
/// The default: below a threshold of unknowns, a simplicial LDL^T by 2x2
/// blocks where the matrix is made of them (the Hessians of UV maps: the two
/// coordinates of a vertex with the two of each neighbour; the same fill as
/// by scalars, 2.5-4 times faster factorizations than `SimplicialLDLT` at
/// 10k-48k unknowns), else `Eigen_simplicial_ldlt_traits`; above it CHOLMOD's
/// supernodal Cholesky factorization (BLAS level 3: measured 1.4x faster than
/// the scalar LDL^T at 48k faces, 2.3x at 97k and 5.6x at 386k with
/// OpenBLAS), when the package is built with CHOLMOD (see `Cholmod_traits`);
/// without it, always the former. The threshold is 65536 unknowns for a
/// matrix made of 2x2 blocks (the block factorization is faster than
/// CHOLMOD's up to about 97k unknowns with AMD, 70k against nested
/// dissection) and 40000 for others. The choice depends on the number of
/// unknowns and the pattern alone (the result is deterministic), and a
/// supernodal or block factorization that fails (a matrix that is positive
/// semi-definite only up to rounding) is done again by the scalar simplicial
/// LDL^T of the same matrix.
/// \cgalModels `SparseSolverTraits`
class Default_sparse_solver_traits
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;
  typedef Eigen::VectorXd Vector;

  /// the default `threshold`
  static constexpr Eigen::Index default_threshold = 40000;
  /// the default `block_threshold`: the factorization by blocks is faster
  /// than CHOLMOD's up to about 97k unknowns with AMD (2x at 48k) and about
  /// 70k against nested dissection (notes/issue20/session_2026-12-01)
  static constexpr Eigen::Index default_block_threshold = 65536;

  /// `threshold`: the number of unknowns from which CHOLMOD is used
  /// (`block_threshold` for a matrix made of 2x2 blocks);
  /// `nested_dissection`: CHOLMOD orders the unknowns by nested dissection
  /// (METIS) instead of its default (AMD), for half the floating-point
  /// operations per factorization at about 100k unknowns but a symbolic
  /// analysis 4-5 times slower: worth it when a pattern serves many
  /// factorizations (`minimize_distortion()` sets it), not when it changes
  /// every few iterations (the seam loop).
  explicit Default_sparse_solver_traits(Eigen::Index threshold = default_threshold,
                                        bool nested_dissection = false,
                                        Eigen::Index block_threshold = default_block_threshold)
    : m_threshold(threshold), m_block_threshold(block_threshold)
  {
#ifdef CGAL_SMSO_HAS_CHOLMOD
    cholmod_common& c = m_supernodal.eigen_solver().cholmod();
    if(nested_dissection)
    {
      c.nmethods = 1;
      c.method[0].ordering = CHOLMOD_NESDIS;
    }
    // Every supernode has a fixed cost (BLAS calls and, in an OpenMP build of
    // CHOLMOD, parallel regions: a futex system call each, even serial), so
    // small supernodes are merged 3x more eagerly than CHOLMOD's default
    // {4, 16, 48} columns, at some extra fill. Factorization of mesh
    // Hessians (2x2 blocks): 48k unknowns 0.096 -> 0.065 s, 97k 0.216 ->
    // 0.152 s (AMD: 0.32 -> 0.23 s), 386k 1.05 -> 0.80 s; the optimum was
    // 3-4x, 8x is slower again.
    c.nrelax[0] = 12;
    c.nrelax[1] = 48;
    c.nrelax[2] = 144;
#else
    (void)nested_dissection;
#endif
  }

  /// whether the last analysed pattern is factorized by CHOLMOD
  bool uses_cholmod() const { return m_large && !m_fallback; }

  /// whether the last analysed pattern is factorized by 2x2 blocks (below the threshold)
  bool uses_blocks() const { return m_blocks && !m_fallback; }

  bool analyze_pattern(const Matrix& A) { return analyze(A, nullptr); }

  /// `analyze_pattern()` with the 2x2 blocks (vertices) eliminated in the
  /// order given where the matrix is factorized by blocks (`block_ordering[v]`:
  /// the position of block `v`, a permutation), instead of an AMD ordering of
  /// its own; otherwise the same as `analyze_pattern()`
  bool analyze_pattern(const Matrix& A, const std::vector<int>& block_ordering) { return analyze(A, &block_ordering); }

  /// the order of the 2x2 blocks of the last pattern analysed (as for
  /// `analyze_pattern()`), empty unless it is factorized by blocks
  const std::vector<int>& block_ordering() const
  {
    static const std::vector<int> none;
    return uses_blocks() ? m_block->ordering() : none;
  }
  bool factorize(const Matrix& A)
  {
    if(!m_fallback && (m_large || m_blocks))
    {
#ifdef CGAL_SMSO_HAS_CHOLMOD
      if(m_large ? m_supernodal.factorize(A) : m_block->factorize(A)) return true;
#else
      if(m_block->factorize(A)) return true;
#endif
      m_fallback = true; // for the rest of this pattern
      if(!m_ldlt.analyze_pattern(A)) return false;
    }
    return m_ldlt.factorize(A);
  }
  bool solve(const Vector& b, Vector& x)
  {
    if(!m_fallback && m_blocks) return m_block->solve(b, x);
#ifdef CGAL_SMSO_HAS_CHOLMOD
    if(m_large && !m_fallback) return m_supernodal.solve(b, x);
#endif
    return m_ldlt.solve(b, x);
  }

private:
  bool analyze(const Matrix& A, const std::vector<int>* block_ordering)
  {
    m_fallback = false;
    m_blocks = false;
    // (the Hessians of UV maps; other patterns by scalars)
    std::vector<int> graph_outer, graph_inner;
    const bool blocks = internal::Block_ldlt::block_graph(A, graph_outer, graph_inner);
#ifdef CGAL_SMSO_HAS_CHOLMOD
    m_large = A.rows() >= (blocks ? m_block_threshold : m_threshold);
    if(m_large) return m_supernodal.analyze_pattern(A);
#endif
    m_blocks = blocks && m_block->analyze_blocks(A, graph_outer, graph_inner, block_ordering);
    return m_blocks || m_ldlt.analyze_pattern(A);
  }

  Eigen::Index m_threshold, m_block_threshold;
  bool m_large = false, m_fallback = false, m_blocks = false;
  Eigen_simplicial_ldlt_traits m_ldlt;
  // (shared by copies, as the factorizations of the other members are)
  std::shared_ptr<internal::Block_ldlt> m_block = std::make_shared<internal::Block_ldlt>();
#ifdef CGAL_SMSO_HAS_CHOLMOD
  Eigen_sparse_solver_traits<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> > m_supernodal;
#endif
};

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
