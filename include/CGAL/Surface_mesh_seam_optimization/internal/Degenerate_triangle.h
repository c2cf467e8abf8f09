// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The one definition of a (numerically) zero-area 3D triangle, used by the
// initial map, the flat copy of the mesh and the command-line reader alike.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DEGENERATE_TRIANGLE_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DEGENERATE_TRIANGLE_H

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Relative threshold below which a 3D triangle counts as degenerate:
// twice its area against its longest edge squared (the sine of its largest
// angle, up to a factor <= 2). Below this, distortion energies overflow.
inline double degenerate_triangle_threshold() { return 1e-12; }

// Twice the area of the 3D triangle (a, b, c), each 3 coordinates.
inline double twice_triangle_area(const double* a, const double* b, const double* c)
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double w[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double n[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] };
  return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// Twice the area of a triangle and whether it is degenerate, for callers
// that need both (one cross product).
struct Triangle_area_test
{
  double twice_area;
  bool is_degenerate;
};

// Degenerate: twice its area at most degenerate_triangle_threshold() times its
// longest edge squared (or not a number): scale- and position-free.
inline Triangle_area_test test_triangle_area(const double* a, const double* b, const double* c)
{
  auto sq = [](const double* p, const double* q) {
    return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
  };
  const double lmax2 = (std::max)({ sq(a, b), sq(b, c), sq(c, a) });
  const double twice_area = twice_triangle_area(a, b, c);
  return Triangle_area_test{ twice_area, !(twice_area > degenerate_triangle_threshold() * lmax2) };
}

inline bool is_degenerate_triangle(const double* a, const double* b, const double* c)
{
  return test_triangle_area(a, b, c).is_degenerate;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
