// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Per-triangle energy in UV coordinates: the chain rule from the energy
// density of the Jacobian J = [u1-u0, u2-u0] Dm^-1 to the 6 UV unknowns.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ELEMENT_ENERGY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ELEMENT_ENERGY_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>

#include <Eigen/Dense>

#include <limits>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// dJ(r, j) / du_a(r) for the three corners a (same for both rows r).
struct Jacobian_coefficients
{
  double c[3][2];
  explicit Jacobian_coefficients(const double* B) // Dm^-1, column-major
  {
    for(int j = 0; j < 2; ++j)
    {
      c[1][j] = B[2*j];
      c[2][j] = B[2*j + 1];
      c[0][j] = -(c[1][j] + c[2][j]);
    }
  }
};

// J of the triangle (a, b, c) in UV with rest-frame inverse B (column-major).
inline void triangle_jacobian(const double* a, const double* b, const double* c, const double* B,
                              Eigen::Matrix2d& J)
{
  const double d1x = b[0]-a[0], d1y = b[1]-a[1], d2x = c[0]-a[0], d2y = c[1]-a[1];
  J(0,0) = d1x * B[0] + d2x * B[1];
  J(1,0) = d1y * B[0] + d2y * B[1];
  J(0,1) = d1x * B[2] + d2x * B[3];
  J(1,1) = d1y * B[2] + d2y * B[3];
}

// J of face f for the UV coordinates `uv` (indexed by UV vertex).
inline void face_jacobian(const Cut_mesh& cm, std::size_t f, const double* uv, Eigen::Matrix2d& J)
{
  triangle_jacobian(uv + 2 * cm.corner_uv[3*f], uv + 2 * cm.corner_uv[3*f+1], uv + 2 * cm.corner_uv[3*f+2],
                    &cm.rest_inverse[4*f], J);
}

// Gradient (6) wrt (u0x,u0y,u1x,u1y,u2x,u2y) from the J-space gradient,
// scaled by `w`.
inline void element_gradient(const Jacobian_coefficients& k, double w, const Eigen::Matrix2d& dJ, double* g)
{
  for(int a = 0; a < 3; ++a)
    for(int r = 0; r < 2; ++r)
      g[2*a + r] = w * (dJ(r, 0) * k.c[a][0] + dJ(r, 1) * k.c[a][1]);
}

// The same and the Hessian (6x6) from the J-space Hessian.
inline void element_derivatives(const Jacobian_coefficients& k, double w,
                                const Eigen::Matrix2d& dJ, const Eigen::Matrix4d& HJ,
                                double* g, Eigen::Matrix<double, 6, 6>* H)
{
  element_gradient(k, w, dJ, g);
  if(!H) return;
  // T(r + 2j, 2b + s) = sum_k HJ(r + 2j, s + 2k) c[b][k]
  Eigen::Matrix<double, 4, 6> T;
  for(int b = 0; b < 3; ++b)
    for(int s = 0; s < 2; ++s)
      T.col(2*b + s) = HJ.col(s) * k.c[b][0] + HJ.col(s + 2) * k.c[b][1];
  for(int a = 0; a < 3; ++a)
    for(int r = 0; r < 2; ++r)
      H->row(2*a + r) = w * (T.row(r) * k.c[a][0] + T.row(r + 2) * k.c[a][1]);
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
