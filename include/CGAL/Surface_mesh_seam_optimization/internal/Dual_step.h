// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The dual step of bound mode: the seam weight lambda follows the distortion
// bound, through rho = (1 - lambda) / lambda, the price of E_SD in units of
// seam length.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DUAL_STEP_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DUAL_STEP_H

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// How the dual step prices E_SD while above the bound. The two rules lead to
// different seams, each shorter on some meshes: optimize_seams() runs one
// start with each and keeps the shorter result (`number_of_starts`).
enum Dual_step_rule
{
  RAISE_PRICE,            // OptCuts: rho grows by kappa (E_SD - bound) at every step
  HOLD_PRICE_WHILE_PAYING // rho kept while some split already pays at it: the
                          // cheap cuts are bought before the price climbs
};

// rho <- max(0, rho + kappa (E_SD - bound)), repeated until one of `ops`
// (each with the changes d_sd of E_SD and d_se of the seam cost it brings)
// pays: d_sd rho + d_se < 0, a split while above the bound, a merge while
// below. Returns false (lambda unchanged) if none can pay at any rho.
// With HOLD_PRICE_WHILE_PAYING, above the bound, rho stays while some split
// pays at it, and the step gives up (false) when no split lowers E_SD at a
// seam cost.
template <typename OperationRange>
bool dual_step(double e_sd, double bound, double kappa, const OperationRange& ops, double& lambda,
               Dual_step_rule rule = RAISE_PRICE)
{
  double rho = (1 - lambda) / lambda;
  const double step = kappa * (e_sd - bound);
  if(rule == HOLD_PRICE_WHILE_PAYING && e_sd > bound)
  {
    bool pays = false, can_pay = false;
    for(const auto& op : ops)
    {
      pays = pays || op.d_sd * rho + op.d_se < 0;
      can_pay = can_pay || (op.d_se > 0 && op.d_sd < 0);
    }
    if(pays) return true;
    if(!can_pay) return false;
  }
  rho = (std::max)(0., rho + step);
  // rho threshold of each operation: profitable iff (d_sd * rho + d_se) < 0
  double need = std::numeric_limits<double>::infinity();
  bool any_now = false;
  for(const auto& op : ops)
  {
    if(op.d_sd * rho + op.d_se < 0) { any_now = true; break; }
    if(e_sd > bound && op.d_se > 0 && op.d_sd < 0) need = (std::min)(need, op.d_se / -op.d_sd);
  }
  if(!any_now && e_sd > bound)
  {
    if(!std::isfinite(need)) return false;
    const double m = std::ceil((need - rho) / step);
    rho += (std::max)(1., m) * step;
    if(!(rho * 1 > need)) rho = need * (1 + 1e-9);
  }
  else if(!any_now && e_sd < bound)
  {
    double best = -1; // largest rho at which some merge pays
    for(const auto& op : ops)
      if(op.d_se < 0) best = (std::max)(best, op.d_sd <= 0 ? std::numeric_limits<double>::infinity() : -op.d_se / op.d_sd);
    if(best < 0) return false;
    if(rho >= best)
    {
      const double m = std::ceil((rho - best) / -step);
      rho = (std::max)(0., rho + (std::max)(1., m) * step);
      if(rho >= best) rho = best * (1 - 1e-9);
    }
  }
  lambda = 1. / (1. + rho);
  return true;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
