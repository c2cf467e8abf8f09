// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Symmetric Dirichlet energy (Smith and Schaefer 2015), the default
// distortion energy of OptCuts.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SYMMETRIC_DIRICHLET_ENERGY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SYMMETRIC_DIRICHLET_ENERGY_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Isotropic_energy_eigensystem.h>

#include <Eigen/Core>

#include <limits>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationEnergies
/// Symmetric Dirichlet energy density
/// \f$ \psi(J) = \sigma_1^2 + \sigma_2^2 + \sigma_1^{-2} + \sigma_2^{-2}
///            = \|J\|_F^2 \, (1 + \det(J)^{-2}) \f$.
/// It penalizes both stretch and compression, equals 4 exactly at rotations,
/// and is a barrier: it tends to \f$+\infty\f$ as a triangle degenerates and
/// is \f$+\infty\f$ for \f$\det(J) \le 0\f$.
///
/// \cgalModels `DistortionEnergy`
class Symmetric_Dirichlet_energy
{
public:
  /// \f$\psi(J)\f$, or \f$+\infty\f$ if \f$\det(J) \le 0\f$.
  double value(const Eigen::Matrix2d& J) const
  {
    const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
    if(!(det > 0))
      return std::numeric_limits<double>::infinity();
    return J.squaredNorm() * (1 + 1 / (det * det));
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

  /// Value at every rotation, the global minimum.
  static constexpr double minimum_value() { return 4.0; }

  /// Identifier of the energy.
  const char* name() const { return "symmetric_dirichlet"; }

  /// \cond SKIP_IN_MANUAL
  // Derivatives with respect to the singular values (requires s1, s2 > 0).
  static internal::Isotropic_derivatives_2 derivatives(double s1, double s2)
  {
    const double i1 = 1 / s1, i2 = 1 / s2;
    const double i1s = i1 * i1, i2s = i2 * i2;
    const double ip = i1 * i2, ip3 = ip * ip * ip; // 1 / (s1 s2)^3
    internal::Isotropic_derivatives_2 d;
    d.d1 = 2 * s1 - 2 * i1s * i1;
    d.d2 = 2 * s2 - 2 * i2s * i2;
    d.d11 = 2 + 6 * i1s * i1s;
    d.d22 = 2 + 6 * i2s * i2s;
    d.d12 = 0;
    // Quotients simplified by s1^3 +- s2^3 = (s1 +- s2)(s1^2 -+ s1 s2 + s2^2):
    // no cancellation at s1 = s2.
    d.twist = 2 - 2 * (s1 * s1 - s1 * s2 + s2 * s2) * ip3;
    d.flip  = 2 + 2 * (s1 * s1 + s1 * s2 + s2 * s2) * ip3;
    return d;
  }
  /// \endcond
};

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SYMMETRIC_DIRICHLET_ENERGY_H
