// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Fans of UV vertices and the relabellings that split or merge them. The 3D
// connectivity never changes; only corner -> UV-vertex labels do.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_UV_TOPOLOGY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_UV_TOPOLOGY_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Corners of each 3D vertex (CSR), fixed for the life of a Cut_mesh.
struct Vertex_corners
{
  std::vector<int> offset, corners;
  explicit Vertex_corners(const Cut_mesh& cm)
  {
    const std::size_t nv = cm.number_of_vertices();
    offset.assign(nv + 1, 0);
    for(int v : cm.corner_vertex) ++offset[v + 1];
    for(std::size_t v = 0; v < nv; ++v) offset[v + 1] += offset[v];
    corners.resize(cm.corner_vertex.size());
    std::vector<int> fill(offset.begin(), offset.end() - 1);
    for(std::size_t c = 0; c < cm.corner_vertex.size(); ++c) corners[fill[cm.corner_vertex[c]]++] = int(c);
  }
};

// Rotation around the corner's vertex inside its UV fan: -1 where the fan
// ends (input boundary or seam).
inline int ccw_corner(const Cut_mesh& cm, int c)
{
  const int h = Cut_mesh::next(c);           // leaves the vertex
  const int o = cm.opposite[h];
  if(o < 0 || cm.is_seam(h)) return -1;
  return o;                                  // o ends at the vertex
}
inline int cw_corner(const Cut_mesh& cm, int c)
{
  const int o = cm.opposite[c];              // c ends at the vertex
  if(o < 0 || cm.is_seam(c)) return -1;
  return Cut_mesh::prev(o);
}

// The fan of the UV vertex of corner c, in ccw order; true if it is closed
// (an interior UV vertex). For an open fan, fan.front() has no cw neighbour.
inline bool uv_fan(const Cut_mesh& cm, int c, std::vector<int>& fan)
{
  fan.clear();
  int start = c;
  for(int k = cw_corner(cm, start); k >= 0; k = cw_corner(cm, start))
  {
    if(k == c) { start = c; break; } // closed
    start = k;
  }
  int x = start;
  do
  {
    fan.push_back(x);
    x = ccw_corner(cm, x);
  } while(x >= 0 && x != start);
  return x == start;
}

inline bool is_boundary_uv_corner(const Cut_mesh& cm, int c)
{
  int x = c;
  do
  {
    x = ccw_corner(cm, x);
    if(x < 0) return true;
  } while(x != c);
  return false;
}

// Gives `corners` a new UV vertex at the same position; returns its id.
inline int split_uv_vertex(Cut_mesh& cm, const std::vector<int>& corners)
{
  const int old = cm.corner_uv[corners.front()];
  const int u = int(cm.uv_vertex.size());
  cm.uv_vertex.push_back(cm.uv_vertex[old]);
  cm.uv.push_back(cm.uv[2*old]);
  cm.uv.push_back(cm.uv[2*old + 1]);
  for(int c : corners) cm.corner_uv[c] = u;
  return u;
}

// Relabels UV vertex b as a and removes b (the last UV vertex takes its id).
inline void merge_uv_vertices(Cut_mesh& cm, const Vertex_corners& vc, int a, int b)
{
  const int v = cm.uv_vertex[b];
  for(int k = vc.offset[v]; k < vc.offset[v + 1]; ++k)
    if(cm.corner_uv[vc.corners[k]] == b) cm.corner_uv[vc.corners[k]] = a;
  const int last = int(cm.uv_vertex.size()) - 1;
  if(b != last)
  {
    const int w = cm.uv_vertex[last];
    for(int k = vc.offset[w]; k < vc.offset[w + 1]; ++k)
      if(cm.corner_uv[vc.corners[k]] == last) cm.corner_uv[vc.corners[k]] = b;
    cm.uv_vertex[b] = w;
    cm.uv[2*b] = cm.uv[2*last];
    cm.uv[2*b + 1] = cm.uv[2*last + 1];
  }
  cm.uv_vertex.pop_back();
  cm.uv.resize(2 * cm.uv_vertex.size());
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
