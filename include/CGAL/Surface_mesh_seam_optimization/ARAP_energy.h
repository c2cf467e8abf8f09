// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// As-rigid-as-possible energy density (Liu et al. 2008).

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_ARAP_ENERGY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_ARAP_ENERGY_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Isotropic_energy_eigensystem.h>

#include <Eigen/Core>

#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationEnergies
/// As-rigid-as-possible energy density
/// \f$ \psi(J) = (\sigma_1 - 1)^2 + (\sigma_2 - 1)^2 \f$, 0 at rotations.
///
/// Unlike `Symmetric_Dirichlet_energy` it is not a barrier: it stays bounded
/// as a triangle degenerates, so nothing in the energy itself prevents
/// flips or collapses. The optimizer's line search keeps, for an energy that
/// is no barrier, every UV triangle's area above a floor (a thousandth of
/// its area at the map's mean area ratio, or half its initial area if that
/// is smaller): a triangle that ARAP would flip is left thin, never flipped
/// or degenerate. For consistency with the other models, the value is
/// \f$+\infty\f$ for \f$\det(J) \le 0\f$.
///
/// The energy fixes the scale (isometries are its minima). A squeezed
/// triangle costs it at most 2, so from the initial map of a closed mesh no
/// split pays enough to cut into the squeezed parts: `optimize_seams()`
/// starts a run with this energy from the E_SD result at the E_SD bound of
/// the same small strains (4.1 for the default 0.025).
///
/// \cgalModels `DistortionEnergy`
class ARAP_energy
  : public internal::Isotropic_energy<ARAP_energy>
{
public:
  /// \f$\psi(J)\f$, or \f$+\infty\f$ if \f$\det(J) \le 0\f$.
  double value(const Eigen::Matrix2d& J) const
  {
    const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
    if(!(det > 0))
      return std::numeric_limits<double>::infinity();
    // s1 + s2 = |conformal part| = |(J00 + J11, J10 - J01)| when det > 0.
    const double e = J(0, 0) + J(1, 1), h = J(1, 0) - J(0, 1);
    return J.squaredNorm() - 2 * std::sqrt(e * e + h * h) + 2;
  }

  // value_and_gradient() and value_gradient_and_hessian(J, dJ, H, project)
  // come from internal::Isotropic_energy (analytic eigensystem).

  /// Value at every rotation, the global minimum.
  static constexpr double minimum_value() { return 0.0; }

  /// The default distortion bound of `optimize_seams()` with this energy: it allows the strains that
  /// E_SD <= 4.1 allows. At small strains \f$\sigma_i = 1 + \epsilon_i\f$, this energy is
  /// \f$ \epsilon_1^2 + \epsilon_2^2 \f$ and E_SD - 4 four times that: 0.1 / 4.
  static constexpr double default_bound() { return 0.025; }

  /// Identifier of the energy.
  const char* name() const { return "arap"; }

  /// \cond SKIP_IN_MANUAL
  // Derivatives with respect to the singular values.
  static internal::Isotropic_derivatives_2 derivatives(double s1, double s2)
  {
    internal::Isotropic_derivatives_2 d;
    d.d1 = 2 * (s1 - 1);
    d.d2 = 2 * (s2 - 1);
    d.d11 = d.d22 = 2;
    d.d12 = 0;
    d.twist = 2 - 4 / (s1 + s2); // negative below s1 + s2 = 2 (compression)
    d.flip = 2;
    return d;
  }
  /// \endcond
};

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_ARAP_ENERGY_H
