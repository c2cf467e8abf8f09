// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// What both pictures of the command-line program (--svg, --png) need: the
// corners of a face with their UVs, and which edges to draw as seams or as
// the mesh's own boundary.

#ifndef SMSO_CLI_PICTURE_COMMON_H
#define SMSO_CLI_PICTURE_COMMON_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <string>

namespace optimize_seams_cli {

// Figures printed on the pictures.
struct Picture_caption
{
  std::string title;                                           // usually the input's file name
  double e_sd = std::numeric_limits<double>::quiet_NaN();
  double distortion_bound = std::numeric_limits<double>::quiet_NaN();   // NaN: no bound
  double seam_length_normalized = std::numeric_limits<double>::quiet_NaN();
  std::size_t charts = 0;
  std::size_t faces = 0;
  std::string energy;                                          // empty, or the energy minimized if not E_SD
};

// The three halfedges of a triangle face: corner i is target(h[i]), with UV
// get(uvmap, h[i]) (the package's convention).
template <typename TriangleMesh>
std::array<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor, 3>
face_corners(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& mesh)
{
  const auto h = halfedge(f, mesh);
  return {h, next(h, mesh), next(next(h, mesh), mesh)};
}

// Per-triangle symmetric Dirichlet energy s1^2 + s2^2 + s1^-2 + s2^-2 of the
// map from the 3D triangle (p0, p1, p2) to the UV triangle (q0, q1, q2);
// infinity for a flipped or degenerate triangle. 4 is an isometry.
// With J the 2x2 Jacobian: s1^2 + s2^2 = |J|_F^2 and s1^-2 + s2^-2 = |J|_F^2 / det(J)^2.
template <typename Point_3, typename Point_2>
double triangle_symmetric_dirichlet(const Point_3& p0, const Point_3& p1, const Point_3& p2,
                                    const Point_2& q0, const Point_2& q1, const Point_2& q2)
{
  // The 3D triangle in an orthonormal frame of its plane: e1 along p0p1.
  const double ax = p1.x() - p0.x(), ay = p1.y() - p0.y(), az = p1.z() - p0.z();
  const double bx = p2.x() - p0.x(), by = p2.y() - p0.y(), bz = p2.z() - p0.z();
  const double la = std::sqrt(ax * ax + ay * ay + az * az);
  if(!(la > 0))
    return std::numeric_limits<double>::infinity();
  const double b1 = (ax * bx + ay * by + az * bz) / la;            // b along e1
  const double cx = ay * bz - az * by, cy = az * bx - ax * bz, cz = ax * by - ay * bx;
  const double b2 = std::sqrt(cx * cx + cy * cy + cz * cz) / la;   // b along e2 (>= 0)
  if(!(b2 > 0))
    return std::numeric_limits<double>::infinity();
  // J maps (la, 0) -> u1 and (b1, b2) -> u2.
  const double u1x = q1.x() - q0.x(), u1y = q1.y() - q0.y();
  const double u2x = q2.x() - q0.x(), u2y = q2.y() - q0.y();
  const double j00 = u1x / la, j10 = u1y / la;
  const double j01 = (u2x - b1 * j00) / b2, j11 = (u2y - b1 * j10) / b2;
  const double det = j00 * j11 - j01 * j10;
  if(!(det > 0))
    return std::numeric_limits<double>::infinity();
  const double f2 = j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11;
  return f2 + f2 / (det * det);
}

// How an edge is drawn: a seam (both sides carry different UVs), an edge
// of the input's boundary, or not at all.
enum class Edge_kind { INTERIOR, SEAM, BOUNDARY };

template <typename TriangleMesh, typename SeamMap>
Edge_kind edge_kind(typename boost::graph_traits<TriangleMesh>::edge_descriptor e, const TriangleMesh& mesh,
                    SeamMap seams)
{
  if(is_border(e, mesh))
    return Edge_kind::BOUNDARY;
  return get(seams, e) ? Edge_kind::SEAM : Edge_kind::INTERIOR;
}

// "4.0998" for a figure, "n/a" when it was not computed.
inline std::string picture_number(double x, int digits)
{
  if(!std::isfinite(x))
    return "n/a";
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.*g", digits, x);
  return buf;
}

// Writes `text` to `path`; false if the file cannot be written whole.
inline bool write_text_file(const std::string& path, const std::string& text)
{
  std::ofstream os(path, std::ios::binary);
  if(!os)
    return false;
  os << text;
  os.close();
  return static_cast<bool>(os);
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_PICTURE_COMMON_H
