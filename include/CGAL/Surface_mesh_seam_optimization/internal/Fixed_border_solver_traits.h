// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Linear algebra traits for CGAL's fixed-border parameterizers (Tutte's map
// of each chart). They solve A x = b twice, for u and for v, where A keeps an
// identity row for every border vertex; CGAL's default solves each by
// BiCGSTAB after its own incomplete LU, which dominates the initial map of a
// dense chart (96544 faces: 1.4 s, 386176: 10 s). With the border rows
// eliminated, Tutte's uniform Laplacian is symmetric definite: one sparse
// Cholesky factorization (the package's default solver) then serves both
// coordinates. Below `minimum_unknowns` interior vertices, and for matrices
// that are not symmetric (mean value coordinates), CGAL's default solver
// runs as before, so small charts keep their maps to the last bit.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_FIXED_BORDER_SOLVER_TRAITS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_FIXED_BORDER_SOLVER_TRAITS_H

#include <CGAL/Surface_mesh_seam_optimization/Sparse_solver_traits.h>

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

class Fixed_border_solver_traits
{
public:
  // CGAL's default for Barycentric_mapping_parameterizer_3
  typedef CGAL::Eigen_solver_traits<
    Eigen::BiCGSTAB<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::IncompleteLUT<double> > >
    Iterative;
  typedef Iterative::Matrix Matrix;
  typedef Iterative::Vector Vector;
  typedef Iterative::NT NT;

  // interior vertices from which the factorization takes over: half the
  // unknowns from which Default_sparse_solver_traits uses CHOLMOD (2 per
  // vertex in the Newton systems), so that every chart of the 40-mesh
  // benchmark (at most 20000 faces) keeps its map
  static constexpr Eigen::Index default_minimum_unknowns = Default_sparse_solver_traits::default_threshold / 2;

  explicit Fixed_border_solver_traits(Eigen::Index minimum_unknowns = default_minimum_unknowns)
    : m(new Data), m_minimum(minimum_unknowns) {}

  // whether the last system was solved by the factorization (else by CGAL's default)
  bool used_factorization() const { return m->direct; }

  bool linear_solver(const Matrix& A, const Vector& B, Vector& X, NT& D)
  {
    D = 1;
    const Eigen::SparseMatrix<double>& M = A.eigen_object();
    // (fewer rows than the minimum: no copy, no comparison, CGAL's solver)
    if(M.rows() < m_minimum) { m->direct = false; return m->iterative.linear_solver(A, B, X, D); }
    if(!m->prepared || !same_matrix(M)) prepare(M);
    if(!m->direct) return m->iterative.linear_solver(A, B, X, D);

    // K x_F = s (b_F - A_FD x_D), K = s A_FF; x_D = b_D (identity rows)
    const Eigen::Index n = M.rows();
    X.resize(n);
    for(Eigen::Index i = 0; i < n; ++i)
      if(m->free_index[std::size_t(i)] < 0) X[i] = B[i];
    Eigen::VectorXd rhs(m->n_free), x;
    for(Eigen::Index i = 0; i < n; ++i)
      if(m->free_index[std::size_t(i)] >= 0) rhs[m->free_index[std::size_t(i)]] = m->sign * B[i];
    for(Eigen::Index j = 0; j < n; ++j)
    {
      if(m->free_index[std::size_t(j)] >= 0) continue;
      for(Eigen::SparseMatrix<double>::InnerIterator it(M, j); it; ++it)
        if(m->free_index[std::size_t(it.row())] >= 0)
          rhs[m->free_index[std::size_t(it.row())]] -= m->sign * it.value() * X[j];
    }
    if(!m->solver.solve(rhs, x)) return false;
    for(Eigen::Index i = 0; i < n; ++i)
      if(m->free_index[std::size_t(i)] >= 0) X[i] = x[m->free_index[std::size_t(i)]];
    return X.allFinite();
  }

private:
  bool same_matrix(const Eigen::SparseMatrix<double>& M) const
  {
    if(M.rows() != m->copy.rows() || M.nonZeros() != m->copy.nonZeros()) return false;
    for(Eigen::Index j = 0; j < M.outerSize(); ++j)
    {
      Eigen::SparseMatrix<double>::InnerIterator a(M, j), b(m->copy, j);
      for(; a && b; ++a, ++b)
        if(a.row() != b.row() || a.value() != b.value()) return false;
      if(a || b) return false;
    }
    return true;
  }

  void prepare(const Eigen::SparseMatrix<double>& M)
  {
    m->prepared = true;
    m->direct = false;
    m->copy = M;
    m->copy.makeCompressed();
    const Eigen::Index n = M.rows();
    if(M.cols() != n) return;
    // border rows: a single entry, 1 on the diagonal
    std::vector<int> row_entries(std::size_t(n), 0);
    std::vector<double> diagonal(std::size_t(n), 0.);
    for(Eigen::Index j = 0; j < n; ++j)
      for(Eigen::SparseMatrix<double>::InnerIterator it(M, j); it; ++it)
      {
        ++row_entries[std::size_t(it.row())];
        if(it.row() == j) diagonal[std::size_t(j)] = it.value();
      }
    m->free_index.assign(std::size_t(n), -1);
    m->n_free = 0;
    for(Eigen::Index i = 0; i < n; ++i)
      if(!(row_entries[std::size_t(i)] == 1 && diagonal[std::size_t(i)] == 1.))
        m->free_index[std::size_t(i)] = int(m->n_free++);
    if(m->n_free < m_minimum || m->n_free == 0) return;
    // (CGAL's rows: positive diagonal; either sign makes a definite K)
    m->sign = 1;
    for(Eigen::Index i = 0; i < n; ++i)
      if(m->free_index[std::size_t(i)] >= 0) { m->sign = diagonal[std::size_t(i)] < 0 ? -1. : 1.; break; }

    std::vector<Eigen::Triplet<double> > entries;
    entries.reserve(std::size_t(M.nonZeros()));
    for(Eigen::Index j = 0; j < n; ++j)
    {
      const int fj = m->free_index[std::size_t(j)];
      if(fj < 0) continue;
      for(Eigen::SparseMatrix<double>::InnerIterator it(M, j); it; ++it)
      {
        const int fi = m->free_index[std::size_t(it.row())];
        if(fi >= 0) entries.emplace_back(fi, fj, m->sign * it.value());
      }
    }
    Eigen::SparseMatrix<double> K(m->n_free, m->n_free);
    K.setFromTriplets(entries.begin(), entries.end());
    // symmetric (uniform or cotangent weights), with a positive diagonal
    const Eigen::SparseMatrix<double> Kt = K.transpose();
    if(!((K - Kt).norm() <= 1e-14 * K.norm())) return;
    for(Eigen::Index i = 0; i < K.rows(); ++i)
      if(!(K.coeff(i, i) > 0)) return;
    m->direct = m->solver.analyze_pattern(K) && m->solver.factorize(K);
  }

  struct Data
  {
    Iterative iterative;
    Default_sparse_solver_traits solver;
    Eigen::SparseMatrix<double> copy; // the matrix prepared for
    std::vector<int> free_index;      // -1 for border rows
    Eigen::Index n_free = 0;
    double sign = 1;
    bool prepared = false, direct = false;
  };
  // traits are copied by value (CGAL's parameterizers): copies share the factor
  std::shared_ptr<Data> m;
  Eigen::Index m_minimum;
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
