// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Closed-form signed SVD of a 2x2 matrix and the analytic eigensystem of the
// Hessian of an isotropic energy psi(s1, s2) with respect to J
// (Smith, de Goes, Kim 2019, "Analytic eigensystems for isotropic distortion
// energies"; Teran et al. 2005). Runs once per triangle per Newton iteration:
// fixed-size, no heap, no iterative solver.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ISOTROPIC_ENERGY_EIGENSYSTEM_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ISOTROPIC_ENERGY_EIGENSYSTEM_H

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

/// Signed SVD `J = U diag(s1, s2) V^T` with `U`, `V` rotations (det = +1),
/// `s1 >= |s2|`, and `s2 < 0` exactly when `det(J) < 0`.
struct Signed_svd_2
{
  Eigen::Matrix2d U;
  Eigen::Matrix2d V;
  double s1;
  double s2;

  Signed_svd_2() {}
  explicit Signed_svd_2(const Eigen::Matrix2d& J) { compute(J); }

  // J = Q R(a2) + R [[cos a1, sin a1], [sin a1, -cos a1]] (conformal +
  // anticonformal parts), so s1 = Q + R, s2 = Q - R, U = R((a1 + a2) / 2),
  // V^T = R((a2 - a1) / 2). Half angles are taken without trigonometry.
  void compute(const Eigen::Matrix2d& J)
  {
    const double a = J(0, 0), b = J(0, 1), c = J(1, 0), d = J(1, 1);
    const double E = 0.5 * (a + d), F = 0.5 * (a - d);
    const double G = 0.5 * (c + b), H = 0.5 * (c - b);
    const double Q = std::sqrt(E * E + H * H);
    const double R = std::sqrt(F * F + G * G);

    // Any angle is valid when a part vanishes (J conformal or anticonformal).
    double c2 = 1, n2 = 0, c1 = 1, n1 = 0;
    if(Q > 0) { const double iq = 1 / Q; c2 = E * iq; n2 = H * iq; }
    if(R > 0) { const double ir = 1 / R; c1 = F * ir; n1 = G * ir; }

    // (x, y) = (cos, sin)(a1 + a2), phi = (a1 + a2) / 2. The larger of
    // |cos phi|, |sin phi| from the half-angle formula, the other from
    // sin(2 phi) = 2 cos phi sin phi: accurate everywhere, and a select
    // rather than an unpredictable branch.
    const double x = c1 * c2 - n1 * n2;
    const double y = n1 * c2 + c1 * n2;
    const double big = std::sqrt(0.5 * (1 + std::abs(x)));
    const double small = y / (2 * big);
    const double cp = x >= 0 ? big : small;
    const double sp = x >= 0 ? small : big;
    // theta = a2 - phi
    const double ct = c2 * cp + n2 * sp;
    const double st = n2 * cp - c2 * sp;

    U << cp, -sp,
         sp,  cp;
    V << ct,  st,
        -st,  ct;
    s1 = Q + R;
    // Q - R cancels near det = 0, where barrier energies need s2 accurately.
    s2 = s1 > 0 ? (a * d - b * c) / s1 : 0.;
  }
};

/// Derivatives of psi(s1, s2) with respect to the signed singular values, and
/// the two eigenvalues of d2psi/dJ2 that are quotients (twist, flip). Energies
/// with a cancellation-free closed form for the quotients fill them directly;
/// others use `twist_eigenvalue()` / `flip_eigenvalue()`.
struct Isotropic_derivatives_2
{
  double d1, d2;          // dpsi/ds1, dpsi/ds2
  double d11, d12, d22;   // second derivatives
  double twist;           // (d1 + d2) / (s1 + s2)
  double flip;            // (d1 - d2) / (s1 - s2)
};

// Below this relative gap the quotients are replaced by their limits: the
// quotient loses ~eps/gap, the limit is off by ~gap; sqrt(eps) balances both.
inline double quotient_limit_threshold() { return 1.5e-8; }

/// (d1 + d2) / (s1 + s2); limit d11 + d12 as s2 -> -s1 (only reachable with
/// det < 0), valid for an energy smooth there: a smooth isotropic psi is a
/// function of |J|^2 and det J, so psi(s1, s2) = psi(-s2, -s1). Signed ARAP
/// is not smooth there and its quotient really diverges.
inline double twist_eigenvalue(double s1, double s2, const Isotropic_derivatives_2& d)
{
  const double den = s1 + s2;
  if(std::abs(den) > quotient_limit_threshold() * (std::abs(s1) + std::abs(s2)))
    return (d.d1 + d.d2) / den;
  return d.d11 + d.d12;
}

/// (d1 - d2) / (s1 - s2); limit d11 - d12 as s2 -> s1, from the symmetry
/// psi(s1, s2) = psi(s2, s1).
inline double flip_eigenvalue(double s1, double s2, const Isotropic_derivatives_2& d)
{
  const double den = s1 - s2;
  if(std::abs(den) > quotient_limit_threshold() * (std::abs(s1) + std::abs(s2)))
    return (d.d1 - d.d2) / den;
  return d.d11 - d.d12;
}

/// dpsi/dJ = U diag(d1, d2) V^T.
inline void isotropic_gradient(const Signed_svd_2& svd, const Isotropic_derivatives_2& d,
                               Eigen::Matrix2d& dJ)
{
  dJ.noalias() = svd.U * Eigen::Vector2d(d.d1, d.d2).asDiagonal() * svd.V.transpose();
}

/// d2psi/dvec(J)^2, vec column-major (J00, J10, J01, J11), assembled as
/// B M B^T over the orthonormal modes
///   D1 = vec(u1 v1^T), D2 = vec(u2 v2^T)          (scaling, 2x2 block M_s = [d_ij]),
///   T  = vec(U [[0,-1],[1,0]] V^T) / sqrt(2)        (twist, eigenvalue `twist`),
///   F  = vec(U [[0, 1],[1,0]] V^T) / sqrt(2)        (flip,  eigenvalue `flip`).
/// With `project`, every negative eigenvalue is set to 0: the result is the
/// nearest positive semi-definite matrix, exactly symmetric.
inline void isotropic_hessian(const Signed_svd_2& svd, const Isotropic_derivatives_2& d,
                              bool project, Eigen::Matrix4d& H)
{
  double p = d.d11, r = d.d12, q = d.d22;
  double lt = d.twist, lf = d.flip;
  if(project)
  {
    lt = (std::max)(lt, 0.);
    lf = (std::max)(lf, 0.);
    const double m = 0.5 * (p + q);
    const double h = 0.5 * (p - q);
    const double disc = std::sqrt(h * h + r * r);
    const double lmin = m - disc, lmax = m + disc;
    // One negative eigenvalue: keep lmax v v^T, with v v^T = (M_s - lmin I) /
    // (lmax - lmin), so no eigenvector is needed. k = 1, shift = 0 leaves a
    // PSD block bit for bit unchanged.
    const double k = lmin < 0 ? (lmax > 0 ? lmax / (2 * disc) : 0.) : 1.;
    const double shift = lmin < 0 ? lmin : 0.;
    p = k * (p - shift);
    q = k * (q - shift);
    r = k * r;
  }

  const double u00 = svd.U(0, 0), u10 = svd.U(1, 0), u01 = svd.U(0, 1), u11 = svd.U(1, 1);
  const double v00 = svd.V(0, 0), v10 = svd.V(1, 0), v01 = svd.V(0, 1), v11 = svd.V(1, 1);
  const double is2 = 0.70710678118654752440;

  // vec(u_i v_j^T) = (u_i0 v_j0, u_i1 v_j0, u_i0 v_j1, u_i1 v_j1)
  const double b0[4] = { u00 * v00, u10 * v00, u00 * v10, u10 * v10 };   // u1 v1^T
  const double b1[4] = { u01 * v01, u11 * v01, u01 * v11, u11 * v11 };   // u2 v2^T
  double b2[4], b3[4];
  {
    const double w21[4] = { u01 * v00, u11 * v00, u01 * v10, u11 * v10 }; // u2 v1^T
    const double w12[4] = { u00 * v01, u10 * v01, u00 * v11, u10 * v11 }; // u1 v2^T
    for(int i = 0; i < 4; ++i)
    {
      b2[i] = is2 * (w21[i] - w12[i]);
      b3[i] = is2 * (w21[i] + w12[i]);
    }
  }

  // H = B M B^T with M = diag([[p, r], [r, q]], lt, lf); upper triangle then
  // mirrored, so H is exactly symmetric.
  double c0[4], c1[4], c2[4], c3[4];
  for(int i = 0; i < 4; ++i)
  {
    c0[i] = p * b0[i] + r * b1[i];
    c1[i] = r * b0[i] + q * b1[i];
    c2[i] = lt * b2[i];
    c3[i] = lf * b3[i];
  }
  for(int i = 0; i < 4; ++i)
    for(int j = i; j < 4; ++j)
      H(i, j) = H(j, i) = c0[i] * b0[j] + c1[i] * b1[j] + c2[i] * b2[j] + c3[i] * b3[j];
}

// The gradient and (projected) Hessian of an isotropic energy from its
// value(J) and its derivatives(s1, s2) with respect to the singular values:
// the part every model of DistortionEnergy here shares.
template <typename Derived>
class Isotropic_energy
{
public:
  double value_and_gradient(const Eigen::Matrix2d& J, Eigen::Matrix2d& dJ) const
  {
    const double psi = static_cast<const Derived&>(*this).value(J);
    if(psi == std::numeric_limits<double>::infinity()) { dJ.setZero(); return psi; }
    const Signed_svd_2 svd(J);
    isotropic_gradient(svd, static_cast<const Derived&>(*this).derivatives(svd.s1, svd.s2), dJ);
    return psi;
  }

  double value_gradient_and_hessian(const Eigen::Matrix2d& J, Eigen::Matrix2d& dJ,
                                    Eigen::Matrix4d& H, bool project = true) const
  {
    const double psi = static_cast<const Derived&>(*this).value(J);
    if(psi == std::numeric_limits<double>::infinity()) { dJ.setZero(); H.setZero(); return psi; }
    const Signed_svd_2 svd(J);
    const Isotropic_derivatives_2 d = static_cast<const Derived&>(*this).derivatives(svd.s1, svd.s2);
    isotropic_gradient(svd, d, dJ);
    isotropic_hessian(svd, d, project, H);
    return psi;
  }
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ISOTROPIC_ENERGY_EIGENSYSTEM_H
