// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Conjugate gradients preconditioned by the factorization of an earlier
// matrix of the same pattern: between topology operations the projected
// Hessian changes little from one Newton iteration to the next, and a few
// triangular solves with the last factor cost far less than a new
// factorization.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_STALE_FACTOR_CG_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_STALE_FACTOR_CG_H

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

struct Stale_factor_cg_result
{
  bool converged = false;
  int iterations = 0; // conjugate gradient iterations (one triangular solve pair each)
  bool negative_curvature = false; // A is not positive along a search direction
  bool on_radius = false; // truncated at the radius
};

// Solves A x = b to |b - A x| <= tolerance |b|, A symmetric positive
// definite with its lower triangle stored, preconditioned by `solver`'s
// current factorization (SparseSolverTraits::solve). Not converged (x then
// meaningless) when the solver fails, A is not positive along a search
// direction, or the rate observed from the third iteration on cannot reach
// the tolerance within `max_iterations`: a stale factor shows itself in the
// first iterations, and giving up then wastes little (Eigen's
// ConjugateGradient would run to its maximum).
//
// With `truncate` (A may be indefinite: the minimization of the quadratic
// model b.x - x.A.x / 2 is truncated as in Steihaug's method), the iterate
// reached at negative curvature, at `max_iterations`, or on the sphere of
// radius `radius_factor` times the first iterate's norm (if > 0) counts as
// converged: it still raises the model, but is no solution of A x = b.
template <typename SolverTraits>
Stale_factor_cg_result stale_factor_cg(const Eigen::SparseMatrix<double>& A_lower, SolverTraits& solver,
                                       const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                       double tolerance, int max_iterations, bool truncate = false,
                                       double radius_factor = 0)
{
  Stale_factor_cg_result result;
  const auto A = A_lower.template selfadjointView<Eigen::Lower>();
  if(!solver.solve(b, x)) return result;
  const double radius = radius_factor * x.norm();
  Eigen::VectorXd r = b - A * x;
  const double r_tol = tolerance * b.norm();
  double r_norm = r.norm();
  if(r_norm <= r_tol) { result.converged = true; return result; }
  const double r0 = r_norm;
  Eigen::VectorXd z, p, Ap;
  if(!solver.solve(r, z)) return result;
  p = z;
  double rz = r.dot(z);
  for(int it = 1; it <= max_iterations; ++it)
  {
    result.iterations = it;
    Ap = A * p;
    const double pAp = p.dot(Ap);
    if(!(pAp > 0)) {
      result.negative_curvature = true;
      result.converged = truncate;
      return result;
    }
    double alpha = rz / pAp;
    if(radius > 0 && (x + alpha * p).norm() > radius)
    {
      // to the sphere: |x + a p| = radius
      const double pp = p.squaredNorm(), xp = x.dot(p), xx = x.squaredNorm();
      alpha = (-xp + std::sqrt((std::max)(0., xp * xp + pp * (radius * radius - xx)))) / pp;
      x += alpha * p;
      result.on_radius = true;
      result.converged = truncate;
      return result;
    }
    x += alpha * p;
    r -= alpha * Ap;
    r_norm = r.norm();
    if(r_norm <= r_tol) { result.converged = true; return result; }
    if(it == max_iterations) { result.converged = truncate; return result; }
    if(it >= 2 && !truncate)
    {
      const double rate = std::pow(r_norm / r0, 1. / it);
      if(r_norm * std::pow(rate, max_iterations - it) > r_tol) return result;
    }
    if(!solver.solve(r, z)) return result;
    const double rz_next = r.dot(z);
    p = z + (rz_next / rz) * p;
    rz = rz_next;
  }
  return result;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
