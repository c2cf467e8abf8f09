// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Conformal (MIPS) energy density (Hormann and Greiner 2000).

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_CONFORMAL_ENERGY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_CONFORMAL_ENERGY_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Isotropic_energy_eigensystem.h>

#include <Eigen/Core>

#include <limits>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationEnergies
/// Conformal (MIPS) energy density
/// \f$ \psi(J) = \sigma_1 / \sigma_2 + \sigma_2 / \sigma_1 = \|J\|_F^2 / \det(J) \f$.
/// It measures angle distortion only: it is scale invariant, equals 2 at
/// every similarity, and is a barrier (\f$+\infty\f$ for \f$\det(J) \le 0\f$).
/// Because scaling is free, a chart's size is not controlled by this energy
/// (a map can shrink a thousandfold while it is minimized), so the
/// distortion bound is judged on E_SD at the map's optimal uniform scale
/// (`Optimization_result::distortion_at_optimal_scale`), not on the map as
/// it is written (`Optimization_result::distortion`).
///
/// \cgalModels `DistortionEnergy`
class Conformal_energy
  : public internal::Isotropic_energy<Conformal_energy>
{
public:
  /// \f$\psi(J)\f$, or \f$+\infty\f$ if \f$\det(J) \le 0\f$.
  double value(const Eigen::Matrix2d& J) const
  {
    const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
    if(!(det > 0))
      return std::numeric_limits<double>::infinity();
    return J.squaredNorm() / det;
  }

  // value_and_gradient() and value_gradient_and_hessian(J, dJ, H, project)
  // come from internal::Isotropic_energy (analytic eigensystem).

  /// Value at every similarity, the global minimum.
  static constexpr double minimum_value() { return 2.0; }

  /// Identifier of the energy.
  const char* name() const { return "mips"; }

  /// The energy does not change when the map is scaled: the bound is judged at the optimal scale.
  static constexpr bool is_scale_invariant() { return true; }

  /// \cond SKIP_IN_MANUAL
  // Derivatives with respect to the singular values (requires s1, s2 > 0).
  static internal::Isotropic_derivatives_2 derivatives(double s1, double s2)
  {
    const double i1 = 1 / s1, i2 = 1 / s2;
    const double ip = i1 * i2, ip2 = ip * ip; // 1 / (s1 s2)^2
    internal::Isotropic_derivatives_2 d;
    d.d1 = i2 - s2 * i1 * i1;
    d.d2 = i1 - s1 * i2 * i2;
    d.d11 = 2 * s2 * i1 * i1 * i1;
    d.d22 = 2 * s1 * i2 * i2 * i2;
    d.d12 = -(i1 * i1 + i2 * i2);
    // Twist <= 0 and det of the scaling block = -(1/s1^2 - 1/s2^2)^2 <= 0:
    // indefinite everywhere but at similarities, so projection always matters.
    d.twist = -(s1 - s2) * (s1 - s2) * ip2;
    d.flip = (s1 + s2) * (s1 + s2) * ip2;
    return d;
  }
  /// \endcond
};

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_CONFORMAL_ENERGY_H
