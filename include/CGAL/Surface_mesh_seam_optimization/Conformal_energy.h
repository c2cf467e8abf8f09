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
/// Because scaling is free, a chart's size is not controlled by this energy.
///
/// \cgalModels `DistortionEnergy`
class Conformal_energy
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

  /// Returns \f$\psi(J)\f$ and writes \f$\partial\psi/\partial J\f$ into `dJ`
  /// (set to zero when the value is \f$+\infty\f$).
  double value_and_gradient(const Eigen::Matrix2d& J, Eigen::Matrix2d& dJ) const
  {
    const double psi = value(J);
    if(psi == std::numeric_limits<double>::infinity()) { dJ.setZero(); return psi; }
    const internal::Signed_svd_2 svd(J);
    internal::isotropic_gradient(svd, derivatives(svd.s1, svd.s2), dJ);
    return psi;
  }

  /// Returns \f$\psi(J)\f$, writes \f$\partial\psi/\partial J\f$ into `dJ` and
  /// the 4x4 Hessian with respect to vec(J) = (J00, J10, J01, J11) into `H`.
  /// With `project`, negative eigenvalues of `H` are set to 0 (analytic
  /// eigensystem). `dJ` and `H` are set to zero when the value is \f$+\infty\f$.
  double value_gradient_and_hessian(const Eigen::Matrix2d& J, Eigen::Matrix2d& dJ,
                                    Eigen::Matrix4d& H, bool project = true) const
  {
    const double psi = value(J);
    if(psi == std::numeric_limits<double>::infinity()) { dJ.setZero(); H.setZero(); return psi; }
    const internal::Signed_svd_2 svd(J);
    const internal::Isotropic_derivatives_2 d = derivatives(svd.s1, svd.s2);
    internal::isotropic_gradient(svd, d, dJ);
    internal::isotropic_hessian(svd, d, project, H);
    return psi;
  }

  /// Value at every similarity, the global minimum.
  static constexpr double minimum_value() { return 2.0; }

  /// Identifier of the energy.
  const char* name() const { return "mips"; }

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
