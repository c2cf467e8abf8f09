// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The largest step along a direction that flips no triangle: the smallest
// positive root of each triangle's signed-area quadratic.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_FLIP_FREE_STEP_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_FLIP_FREE_STEP_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>

#include <cmath>
#include <limits>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Smallest root > 0 of a t^2 + b t + c with c > 0; +inf if none.
inline double smallest_positive_root(double a, double b, double c)
{
  const double inf = std::numeric_limits<double>::infinity();
  const double scale = std::abs(a) + std::abs(b) + std::abs(c);
  if(std::abs(a) <= 1e-14 * scale)
    return b < 0 ? -c / b : inf;
  const double disc = b * b - 4 * a * c;
  if(disc < 0) return inf;
  // stable roots: q = -(b + sign(b) sqrt(disc)) / 2, roots q/a and c/q
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double r = inf;
  const double r1 = q / a, r2 = (q != 0) ? c / q : inf;
  if(r1 > 0) r = r1;
  if(r2 > 0 && r2 < r) r = r2;
  return r;
}

// Largest t such that the triangle (a, b, c) moved by t * (pa, pb, pc) keeps
// a positive signed area on [0, t).
inline double triangle_flip_free_step(const double* a, const double* b, const double* c,
                                      const double* pa, const double* pb, const double* pc)
{
  const double d1x = b[0] - a[0], d1y = b[1] - a[1], d2x = c[0] - a[0], d2y = c[1] - a[1];
  const double q1x = pb[0] - pa[0], q1y = pb[1] - pa[1], q2x = pc[0] - pa[0], q2y = pc[1] - pa[1];
  return smallest_positive_root(q1x * q2y - q1y * q2x,
                                d1x * q2y - d1y * q2x + q1x * d2y - q1y * d2x,
                                d1x * d2y - d1y * d2x);
}

// Largest t such that uv + s * dir flips no face for all s in [0, t).
inline double max_flip_free_step(const Cut_mesh& cm, const double* uv, const double* dir)
{
  double t = std::numeric_limits<double>::infinity();
  const std::size_t nf = cm.number_of_faces();
  for(std::size_t f = 0; f < nf; ++f)
  {
    const int i0 = 2 * cm.corner_uv[3*f], i1 = 2 * cm.corner_uv[3*f+1], i2 = 2 * cm.corner_uv[3*f+2];
    const double r = triangle_flip_free_step(uv + i0, uv + i1, uv + i2, dir + i0, dir + i1, dir + i2);
    if(r < t) t = r;
  }
  return t;
}

// Largest t such that the triangle keeps twice its signed area >= `floor2`
// on [0, t); 0 if it is already at or below the floor and the direction
// shrinks it (a triangle may then only grow).
inline double triangle_area_floor_step(const double* a, const double* b, const double* c,
                                       const double* pa, const double* pb, const double* pc, double floor2)
{
  const double inf = std::numeric_limits<double>::infinity();
  const double d1x = b[0] - a[0], d1y = b[1] - a[1], d2x = c[0] - a[0], d2y = c[1] - a[1];
  const double q1x = pb[0] - pa[0], q1y = pb[1] - pa[1], q2x = pc[0] - pa[0], q2y = pc[1] - pa[1];
  const double qa = q1x * q2y - q1y * q2x;
  const double qb = d1x * q2y - d1y * q2x + q1x * d2y - q1y * d2x;
  const double area2 = d1x * d2y - d1y * d2x;
  if(area2 > floor2) return smallest_positive_root(qa, qb, area2 - floor2);
  if(qb < 0 || (qb == 0 && qa < 0)) return 0.;
  return qa < 0 ? -qb / qa : inf;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
