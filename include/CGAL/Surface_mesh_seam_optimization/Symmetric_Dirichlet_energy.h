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
/// The distortion bound of `optimize_seams()` is a bound on this energy's
/// mean, E_SD, of the map as it is written; minimizing it also optimizes the
/// scale, so at a converged result E_SD at the optimal uniform scale is the
/// same but for the stopping tolerance.
///
/// \cgalModels `DistortionEnergy`
class Symmetric_Dirichlet_energy
  : public internal::Isotropic_energy<Symmetric_Dirichlet_energy>
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

  // value_and_gradient() and value_gradient_and_hessian(J, dJ, H, project)
  // come from internal::Isotropic_energy (analytic eigensystem).

  /// Value at every rotation, the global minimum.
  static constexpr double minimum_value() { return 4.0; }

  /// The default distortion bound of `optimize_seams()` with this energy (OptCuts' 4.1).
  static constexpr double default_bound() { return 4.1; }

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
