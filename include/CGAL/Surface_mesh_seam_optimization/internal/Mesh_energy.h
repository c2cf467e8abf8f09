// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The distortion of a whole Cut_mesh: its area-weighted energy, E_SD as a
// bound judges it, the optimal uniform scale. Kept apart from the solver so
// that measuring a map does not pull in the scaffold's triangulation.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_MESH_ENERGY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_MESH_ENERGY_H

#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Element_energy.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Energies may declare `bool is_scale_invariant() const`.
template <typename Energy, typename = void>
struct Has_scale_invariance : std::false_type {};
template <typename Energy>
struct Has_scale_invariance<Energy, std::void_t<decltype(std::declval<const Energy&>().is_scale_invariant())> >
  : std::true_type {};

template <typename Energy>
bool is_scale_invariant(const Energy& energy)
{
  if constexpr(Has_scale_invariance<Energy>::value)
    return energy.is_scale_invariant();
  else
    return false;
}

// Energies may declare `double default_bound() const`.
template <typename Energy, typename = void>
struct Has_default_bound : std::false_type {};
template <typename Energy>
struct Has_default_bound<Energy, std::void_t<decltype(std::declval<const Energy&>().default_bound())> >
  : std::true_type {};

// False, with `message`, if `energy` falls below its own minimum_value() on
// a few maps (a negative area_weight): minimizing it or bounding it would be
// meaningless.
template <typename Energy>
bool check_energy(const Energy& energy, std::string& message)
{
  for(double k : {0.5, 1., 2.})
  {
    Eigen::Matrix2d J;
    J << k, k == 1 ? 0.3 : 0., 0, k;
    if(!(energy.value(J) >= Energy::minimum_value()))
    {
      message = std::string("the energy '") + energy.name() +
                "' takes values below its minimum_value() (a negative area_weight?)";
      return false;
    }
  }
  return true;
}

// The distortion bound: `distortion_bound` if given, else the energy's
// default_bound(). False, with `message`, if there is none or it is not a
// finite number above the energy's minimum.
template <typename Energy, typename NamedParameters>
bool read_distortion_bound(const NamedParameters& np, const Energy& energy, double& bound, std::string& message)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::distortion_bound_t>::value)
    bound = choose_parameter(get_parameter(np, internal_np::distortion_bound), 0.);
  else if constexpr(Has_default_bound<Energy>::value)
    bound = energy.default_bound();
  else
  {
    message = std::string("the energy '") + energy.name() + "' has no default_bound(): give distortion_bound";
    return false;
  }
  if(!check_energy(energy, message))
    return false;
  if(!(bound > Energy::minimum_value()) || !std::isfinite(bound))
  {
    std::ostringstream s;
    s << "distortion_bound must be a finite number > " << Energy::minimum_value() << " (the minimum of '"
      << energy.name() << "')";
    message = s.str();
    return false;
  }
  return true;
}

// Whether the energy grows without bound as a triangle degenerates (SD,
// MIPS), measured on a sliver: ARAP stays near 1 there.
template <typename Energy>
bool is_barrier_energy(const Energy& energy)
{
  Eigen::Matrix2d J;
  J << 1, 0, 0, 1e-8;
  return energy.value(J) > 1e4;
}

// The area floor of a descent with an energy that is no barrier
// (Newton_settings::area_floor): a face's twice UV area may not fall below
// this times its 3D area, `floor` times the map's mean area ratio.
inline double area_floor_ratio2(const Cut_mesh& cm, double floor)
{
  double uv_area2 = 0;
  for(std::size_t f = 0; f < cm.number_of_faces(); ++f) uv_area2 += cm.signed_uv_area2(f);
  return floor * uv_area2 / cm.total_area;
}

// Faces whose UV area is below that floor: such a descent cannot expand them.
inline std::size_t number_of_faces_below_area_floor(const Cut_mesh& cm, double floor)
{
  const std::size_t nf = cm.number_of_faces();
  const double ratio = area_floor_ratio2(cm, floor);
  std::size_t n = 0;
  for(std::size_t f = 0; f < nf; ++f)
    if(cm.signed_uv_area2(f) < ratio * cm.face_area[f]) ++n;
  return n;
}

// The E_SD bound allowing the small strains that `bound` allows `energy`: at
// singular values (1 + h, 1), E_SD - 4 ~ 4 h^2; the energy's own curvature
// there is measured (ARAP: h^2, so ARAP 0.025 gives E_SD 4.1).
template <typename Energy>
double symmetric_dirichlet_bound_with_same_strains(const Energy& energy, double bound)
{
  const double h = 1e-3;
  Eigen::Matrix2d J;
  J << 1 + h, 0, 0, 1;
  const double c = (energy.value(J) - Energy::minimum_value()) / (h * h);
  const double b = 4 + 4 * (bound - Energy::minimum_value()) / c;
  return std::isfinite(b) && b > 4 ? b : Symmetric_Dirichlet_energy::default_bound();
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

// The energy density psi(J_f) of face f under the UVs `uv`.
template <typename Energy>
double face_energy_density(const Cut_mesh& cm, std::size_t f, const double* uv, const Energy& energy)
{
  Eigen::Matrix2d J;
  face_jacobian(cm, f, uv, J);
  return energy.value(J);
}

// Total normalized energy sum_t A_t psi(J_t) / A; +inf if a face is flipped.
template <typename Energy>
double total_energy(const Cut_mesh& cm, const Energy& energy, const double* uv)
{
  double e = 0;
  const std::size_t nf = cm.number_of_faces();
  for(std::size_t f = 0; f < nf; ++f)
    e += cm.face_area[f] * face_energy_density(cm, f, uv, energy);
  return e / cm.total_area;
}

// The figure a distortion bound is judged on: the normalized energy itself,
// in its own units (E_SD for E_SD; a scale-invariant energy needs no scale).
template <typename Energy>
double judged_distortion(const Cut_mesh& cm, const Energy& energy, const double* uv)
{
  return total_energy(cm, energy, uv);
}

// The map of a scale-invariant energy has no meaningful scale: it is written
// at the one that minimizes E_SD (else E_SD as written is arbitrary: MIPS on
// cat_f1500 with its seams fixed gave 9.2e8 as it was, 41.05 at that scale).
template <typename Energy>
void scale_for_output(Cut_mesh& cm, const Energy& energy)
{
  if(is_scale_invariant(energy))
  {
    double s = 1;
    symmetric_dirichlet_at_optimal_scale(cm, cm.uv.data(), &s);
    if(std::isfinite(s) && s > 0)
      for(double& x : cm.uv) x *= s;
  }
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
