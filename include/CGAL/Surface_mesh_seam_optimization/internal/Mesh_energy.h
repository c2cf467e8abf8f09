// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The distortion of a whole Cut_mesh: its area-weighted energy, E_SD as a
// bound judges it, the optimal uniform scale. Kept apart from the solver so
// that measuring a map does not pull in the scaffold's triangulation.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_MESH_ENERGY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_MESH_ENERGY_H

#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Element_energy.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Energies may declare `static constexpr bool is_scale_invariant()`.
template <typename Energy, typename = void>
struct Is_scale_invariant : std::false_type {};
template <typename Energy>
struct Is_scale_invariant<Energy, std::void_t<decltype(Energy::is_scale_invariant())> >
  : std::integral_constant<bool, Energy::is_scale_invariant()> {};

// Whether the energy grows without bound as a triangle degenerates (SD,
// MIPS), measured on a sliver: ARAP stays near 1 there.
template <typename Energy>
bool is_barrier_energy(const Energy& energy)
{
  Eigen::Matrix2d J;
  J << 1, 0, 0, 1e-8;
  return energy.value(J) > 1e4;
}

// E_SD(s uv) = s^2 a + b / s^2 with a = sum A_t |J|^2, b = sum A_t |J|^2 / det^2
// (over the total area): minimal at s^2 = sqrt(b / a), value 2 sqrt(ab).
inline double symmetric_dirichlet_at_optimal_scale(const Cut_mesh& cm, const double* uv, double* scale = nullptr)
{
  double a = 0, b = 0;
  Eigen::Matrix2d J;
  for(std::size_t f = 0; f < cm.number_of_faces(); ++f)
  {
    face_jacobian(cm, f, uv, J);
    const double det = J.determinant(), n2 = J.squaredNorm();
    if(!(det > 0)) { if(scale) *scale = 1; return std::numeric_limits<double>::infinity(); }
    a += cm.face_area[f] * n2;
    b += cm.face_area[f] * n2 / (det * det);
  }
  if(scale) *scale = std::sqrt(std::sqrt(b / a));
  return 2 * std::sqrt(a * b) / cm.total_area;
}

// Total normalized energy sum_t A_t psi(J_t) / A; +inf if a face is flipped.
template <typename Energy>
double total_energy(const Cut_mesh& cm, const Energy& energy, const double* uv)
{
  double e = 0;
  Eigen::Matrix2d J;
  const std::size_t nf = cm.number_of_faces();
  for(std::size_t f = 0; f < nf; ++f)
  {
    face_jacobian(cm, f, uv, J);
    e += cm.face_area[f] * energy.value(J);
  }
  return e / cm.total_area;
}

// The E_SD a distortion bound is judged on: that of the map as it is, or at
// its optimal uniform scale for a scale-invariant energy (whose map's scale
// means nothing: MIPS on cat_f1500, seams fixed, E_SD 9.2e8 as it is, 41.05 at the scale).
template <typename Energy>
double judged_distortion(const Cut_mesh& cm, const Energy&, const double* uv)
{
  if constexpr(Is_scale_invariant<Energy>::value)
    return symmetric_dirichlet_at_optimal_scale(cm, uv);
  else
    return total_energy(cm, Symmetric_Dirichlet_energy(), uv);
}

// Scales all UVs (about their centroid) to the energy-minimizing factor:
// a golden-section search on the log of the factor (energies are smooth in it).
template <typename Energy>
double rescale_to_optimal(Cut_mesh& cm, const Energy& energy)
{
  const std::size_t n = cm.number_of_uv_vertices();
  std::vector<double> trial(cm.uv.size());
  auto eval = [&](double s) {
    const double k = std::exp(s);
    for(std::size_t i = 0; i < 2 * n; ++i) trial[i] = k * cm.uv[i];
    return total_energy(cm, energy, trial.data());
  };
  double lo = -8, hi = 8;
  const double g = 0.5 * (std::sqrt(5.) - 1.);
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = eval(x1), f2 = eval(x2);
  for(int it = 0; it < 80 && hi - lo > 1e-10; ++it)
  {
    if(f1 <= f2) { hi = x2; x2 = x1; f2 = f1; x1 = hi - g * (hi - lo); f1 = eval(x1); }
    else         { lo = x1; x1 = x2; f1 = f2; x2 = lo + g * (hi - lo); f2 = eval(x2); }
  }
  const double s = 0.5 * (lo + hi);
  const double e0 = total_energy(cm, energy, cm.uv.data());
  if(!(eval(s) < e0)) return 1.;
  const double k = std::exp(s);
  for(double& x : cm.uv) x *= k;
  return k;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
