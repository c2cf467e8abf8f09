// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Conformal energy density: MIPS (Hormann and Greiner 2000) with an area term.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_CONFORMAL_ENERGY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_CONFORMAL_ENERGY_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Isotropic_energy_eigensystem.h>

#include <Eigen/Core>

#include <limits>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationEnergies
/// Conformal energy density: MIPS (Hormann and Greiner 2000) with an area term,
/// \f[ \psi(J) = \frac{\sigma_1}{\sigma_2} + \frac{\sigma_2}{\sigma_1}
///   + w \left(\sigma_1\sigma_2 + \frac{1}{\sigma_1\sigma_2} - 2\right)
///   = \frac{\|J\|_F^2}{\det J} + w \left(\det J + \frac{1}{\det J} - 2\right). \f]
/// The first term measures angle distortion only. Alone (`area_weight` 0) it
/// is scale invariant and leaves areas free: minimizing it on a closed mesh
/// cut by a short slit shrinks parts of the map exponentially (the ears of
/// bunny_i_f10000 fell below \f$10^{-12}\f$ of their chart's area, a
/// degenerate map, while the bound on angles was met without a seam). The
/// area term, weighted `area_weight` (default 0.01, a hundredth of the
/// weight E_SD gives area against angles at small strains), keeps every
/// triangle's area within a bounded factor, so that the topology steps cut
/// where area distortion cannot be relieved otherwise; angles dominate.
/// Minimum 2, at every rotation (at every similarity if `area_weight` is 0);
/// a barrier (\f$+\infty\f$ for \f$\det(J) \le 0\f$).
///
/// \cgalModels `DistortionEnergy`
class Conformal_energy
  : public internal::Isotropic_energy<Conformal_energy>
{
public:
  /// \pre `area_weight >= 0`
  explicit Conformal_energy(double area_weight = 0.01) : m_area_weight(area_weight) {}

  /// The weight of the area term.
  double area_weight() const { return m_area_weight; }

  /// \f$\psi(J)\f$, or \f$+\infty\f$ if \f$\det(J) \le 0\f$.
  double value(const Eigen::Matrix2d& J) const
  {
    const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
    if(!(det > 0))
      return std::numeric_limits<double>::infinity();
    return J.squaredNorm() / det + m_area_weight * (det + 1 / det - 2);
  }

  // value_and_gradient() and value_gradient_and_hessian(J, dJ, H, project)
  // come from internal::Isotropic_energy (analytic eigensystem).

  /// Value at every rotation, the global minimum.
  static constexpr double minimum_value() { return 2.0; }

  /// The default distortion bound of `optimize_seams()` with this energy: it allows the strains that
  /// E_SD <= 4.1 allows. At small strains \f$\sigma_i = 1 + \epsilon_i\f$, E_SD - 4 is
  /// \f$ 4(\epsilon_1^2 + \epsilon_2^2) \f$ and this energy minus 2 is
  /// \f$ (\epsilon_1 - \epsilon_2)^2 + w (\epsilon_1 + \epsilon_2)^2 \f$, \f$(1 + w)/4\f$ of it on
  /// average over independent strains: \f$2 + (1 + w)\, 0.1 / 4\f$ (2.02525 by default).
  double default_bound() const { return 2 + (1 + m_area_weight) * 0.025; }

  /// Identifier of the energy.
  const char* name() const { return "conformal"; }

  /// Whether the energy is unchanged when the map is scaled (only without the area term): then the
  /// map is written at the scale that minimizes E_SD.
  bool is_scale_invariant() const { return m_area_weight == 0; }

  /// \cond SKIP_IN_MANUAL
  // Derivatives with respect to the singular values (requires s1, s2 > 0).
  internal::Isotropic_derivatives_2 derivatives(double s1, double s2) const
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
    if(m_area_weight != 0)
    {
      // w (P + 1/P - 2), P = s1 s2
      const double w = m_area_weight, q = 1 - ip2, ip3 = ip2 * ip;
      d.d1 += w * s2 * q;
      d.d2 += w * s1 * q;
      d.d11 += 2 * w * s2 * s2 * ip3;
      d.d22 += 2 * w * s1 * s1 * ip3;
      d.d12 += w * (1 + ip2);
      d.twist += w * q;  // (d1 + d2) / (s1 + s2)
      d.flip -= w * q;   // (d1 - d2) / (s1 - s2)
    }
    return d;
  }
  /// \endcond

private:
  double m_area_weight;
};

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_CONFORMAL_ENERGY_H
