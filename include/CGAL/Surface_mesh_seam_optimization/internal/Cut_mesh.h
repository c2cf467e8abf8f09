// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The core's data: the 3D mesh in flat arrays (never changed) and a mutable
// corner -> UV-vertex labelling. Cutting and merging only relabel corners.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_CUT_MESH_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_CUT_MESH_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Twice the signed area of the 2D triangle (a, b, c): > 0 if counterclockwise.
inline double signed_area2(const double* a, const double* b, const double* c)
{
  return (b[0]-a[0]) * (c[1]-a[1]) - (b[1]-a[1]) * (c[0]-a[0]);
}

// The 3D triangle (p0, p1, p2) in its own plane: p0 at the origin, p1 at
// (l1, 0), p2 at (x2, y2) with y2 >= 0.
inline void triangle_local_frame(const double* p0, const double* p1, const double* p2,
                                 double& l1, double& x2, double& y2)
{
  double e1[3], e2[3];
  for(int k = 0; k < 3; ++k) { e1[k] = p1[k] - p0[k]; e2[k] = p2[k] - p0[k]; }
  l1 = std::sqrt(e1[0]*e1[0] + e1[1]*e1[1] + e1[2]*e1[2]);
  x2 = (e1[0]*e2[0] + e1[1]*e2[1] + e1[2]*e2[2]) / l1;
  y2 = std::sqrt((std::max)(0., e2[0]*e2[0] + e2[1]*e2[1] + e2[2]*e2[2] - x2*x2));
}

// The rest frame of the 3D triangle (p0, p1, p2): Dm^-1 (column-major) of
// its local 2D frame, and its area.
inline void triangle_rest_frame(const double* p0, const double* p1, const double* p2, double* B, double& area)
{
  double l1, x2, y2;
  triangle_local_frame(p0, p1, p2, l1, x2, y2);
  // Dm = [[l1, x2], [0, y2]]
  B[0] = 1. / l1; B[1] = 0.; B[2] = -x2 / (l1 * y2); B[3] = 1. / y2;
  area = 0.5 * l1 * y2;
}

// Corner c = 3*f + i is corner i of face f. Halfedge c is the halfedge of
// face f that ENDS at corner c (it starts at prev(c)), as CGAL's per-halfedge
// UV convention: get(uvmap, h) is the UV of target(h) in face(h).
struct Cut_mesh
{
  // --- 3D surface (fixed) ---
  std::vector<double> points;        // 3 per vertex
  std::vector<int> corner_vertex;    // 3 per face
  std::vector<int> opposite;         // 3 per face: opposite halfedge, -1 on the input boundary
  std::vector<double> face_area;     // 3D area per face
  std::vector<double> rest_inverse;  // 4 per face: Dm^-1 (column-major) of the local 2D rest frame
  double total_area = 0;

  // --- UV mesh (mutable) ---
  std::vector<int> corner_uv;        // 3 per face
  std::vector<double> uv;            // 2 per UV vertex
  std::vector<int> uv_vertex;        // 3D vertex of each UV vertex

  std::size_t number_of_faces() const { return corner_vertex.size() / 3; }
  std::size_t number_of_vertices() const { return points.size() / 3; }
  std::size_t number_of_uv_vertices() const { return uv_vertex.size(); }

  static int next(int c) { return c % 3 == 2 ? c - 2 : c + 1; }
  static int prev(int c) { return c % 3 == 0 ? c + 2 : c - 1; }

  // The UV corners of both sides of an interior halfedge differ: a seam.
  bool is_seam(int h) const
  {
    const int o = opposite[h];
    if(o < 0) return false;
    return corner_uv[h] != corner_uv[prev(o)] || corner_uv[prev(h)] != corner_uv[o];
  }

  double edge_length(int h) const
  {
    const double* a = &points[3 * corner_vertex[h]];
    const double* b = &points[3 * corner_vertex[prev(h)]];
    return std::sqrt((a[0]-b[0])*(a[0]-b[0]) + (a[1]-b[1])*(a[1]-b[1]) + (a[2]-b[2])*(a[2]-b[2]));
  }

  // Twice the signed UV area of face f.
  double signed_uv_area2(std::size_t f) const
  {
    return signed_area2(&uv[2 * corner_uv[3*f]], &uv[2 * corner_uv[3*f+1]], &uv[2 * corner_uv[3*f+2]]);
  }

  // Fills face_area / rest_inverse / total_area from the 3D points.
  void compute_rest_shape()
  {
    const std::size_t nf = number_of_faces();
    face_area.assign(nf, 0.);
    rest_inverse.assign(4 * nf, 0.);
    total_area = 0;
    for(std::size_t f = 0; f < nf; ++f)
    {
      triangle_rest_frame(&points[3 * corner_vertex[3*f]], &points[3 * corner_vertex[3*f+1]],
                          &points[3 * corner_vertex[3*f+2]], &rest_inverse[4*f], face_area[f]);
      total_area += face_area[f];
    }
  }

  // Chart id per face (faces joined across non-seam interior edges); returns the count.
  std::size_t compute_charts(std::vector<int>& chart) const
  {
    const std::size_t nf = number_of_faces();
    chart.assign(nf, -1);
    std::vector<int> stack;
    int n = 0;
    for(std::size_t s = 0; s < nf; ++s)
    {
      if(chart[s] >= 0) continue;
      chart[s] = n;
      stack.push_back(int(s));
      while(!stack.empty())
      {
        const int f = stack.back(); stack.pop_back();
        for(int i = 0; i < 3; ++i)
        {
          const int h = 3*f + i;
          const int o = opposite[h];
          if(o < 0 || is_seam(h)) continue;
          if(chart[o / 3] < 0) { chart[o / 3] = n; stack.push_back(o / 3); }
        }
      }
      ++n;
    }
    return std::size_t(n);
  }

  // Sum of 3D lengths of the seam edges, each edge once, optionally weighted per halfedge.
  double seam_length(const std::vector<double>* halfedge_weight = nullptr) const
  {
    double l = 0;
    for(std::size_t h = 0; h < corner_vertex.size(); ++h)
    {
      const int o = opposite[h];
      if(o < int(h) || !is_seam(int(h))) continue;
      l += edge_length(int(h)) * (halfedge_weight ? (*halfedge_weight)[h] : 1.);
    }
    return l;
  }

  double normalization_radius() const { return std::sqrt(total_area / 3.14159265358979323846); }
};

// V - E + F of each chart of a cut surface. `chart`: the chart of each face
// (ids below `n_charts`); `uv_of`: the UV vertex of each corner (ids below
// `n_uv`); `border(h)`: the side of halfedge h bounds its chart, an edge of
// its own (an interior edge is counted once from its two sides).
template <class BorderSide>
std::vector<long> chart_euler_characteristics(const std::vector<int>& chart, std::size_t n_charts,
                                              const std::vector<int>& uv_of, std::size_t n_uv,
                                              const std::vector<int>& opposite, BorderSide border)
{
  std::vector<long> chi(n_charts, 0);
  for(int k : chart) ++chi[k];
  std::vector<char> counted(n_uv, 0);
  for(std::size_t c = 0; c < uv_of.size(); ++c)
    if(!counted[uv_of[c]]) { counted[uv_of[c]] = 1; ++chi[chart[c / 3]]; }
  for(std::size_t h = 0; h < opposite.size(); ++h)
    if(border(int(h)) || opposite[h] > int(h)) --chi[chart[h / 3]];
  return chi;
}

// A copy of the mutable part of a cut mesh (the UV mesh), to come back to.
struct Uv_snapshot
{
  std::vector<int> corner_uv, uv_vertex;
  std::vector<double> uv;

  void save(const Cut_mesh& cm) { corner_uv = cm.corner_uv; uv_vertex = cm.uv_vertex; uv = cm.uv; }
  void restore(Cut_mesh& cm) const { cm.corner_uv = corner_uv; cm.uv_vertex = uv_vertex; cm.uv = uv; }
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
