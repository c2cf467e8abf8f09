// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Seams as a graph on the 3D mesh: the leaf paths (from a seam tip to the
// first junction or input boundary vertex) and, for each, the cheapest path
// through uncut vertices from one of its vertices to its tip. Local
// operations grow seams one edge at a time along the distortion's pull, so a
// seam may wind far from the shortest route between its ends; these are the
// detours.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SEAM_PATHS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SEAM_PATHS_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

struct Seam_detour
{
  // halfedges along the two paths, both from the same seam vertex to the tip
  std::vector<int> seam, shortcut;
  double seam_cost = 0, shortcut_cost = 0;
};

// For each leaf seam path, the part from one of its vertices to its tip
// whose cheapest alternative (on interior edges, through vertices on no seam
// and not on the input boundary, cost per halfedge `cost`) saves most, if
// that is at least `min_ratio` times cheaper.
template <typename Cost>
std::vector<Seam_detour> seam_detours(const Cut_mesh& cm, const Cost& cost, double min_ratio, bool plain_start = false)
{
  const int nv = int(cm.number_of_vertices());
  const int nh = int(cm.corner_vertex.size());
  auto source = [&](int h) { return cm.corner_vertex[Cut_mesh::prev(h)]; };
  auto target = [&](int h) { return cm.corner_vertex[h]; };

  // outgoing interior halfedges of each vertex, and which of them are seams
  std::vector<int> offset(nv + 1, 0), out(nh);
  std::vector<int> seam_degree(nv, 0);
  std::vector<char> on_border(nv, 0);
  for(int h = 0; h < nh; ++h)
  {
    if(cm.opposite[h] < 0) { on_border[source(h)] = on_border[target(h)] = 1; continue; }
    ++offset[source(h) + 1];
    if(cm.is_seam(h)) ++seam_degree[source(h)];
  }
  for(int v = 0; v < nv; ++v) offset[v + 1] += offset[v];
  {
    std::vector<int> fill(offset.begin(), offset.end() - 1);
    for(int h = 0; h < nh; ++h)
      if(cm.opposite[h] >= 0) out[fill[source(h)]++] = h;
  }

  std::vector<Seam_detour> detours;
  std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
  std::vector<int> reached_by(nv, -1), touched;
  for(int tip = 0; tip < nv; ++tip)
  {
    if(seam_degree[tip] != 1 || on_border[tip]) continue;
    // walk from the tip to the first vertex that is not a plain seam vertex
    std::vector<int> walk;      // halfedges, each towards the tip
    std::vector<double> length; // seam cost from the tip to the source of walk[i]
    int v = tip, from = -1;
    double l = 0;
    for(std::size_t guard = 0; guard < std::size_t(nh); ++guard)
    {
      int next = -1;
      for(int k = offset[v]; k < offset[v + 1]; ++k)
        if(cm.is_seam(out[k]) && target(out[k]) != from) { next = out[k]; break; }
      if(next < 0) break;
      walk.push_back(cm.opposite[next]);
      l += cost(next);
      length.push_back(l);
      from = v;
      v = target(next);
      if(seam_degree[v] != 2 || on_border[v] || v == tip) break;
    }
    if(walk.size() < 2 || v == tip) continue;

    // cheapest paths from the tip through uncut vertices (the seam's own
    // vertices end them): a shortcut from any vertex of the seam to its tip
    typedef std::pair<double, int> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
    dist[tip] = 0; touched.push_back(tip);
    queue.emplace(0., tip);
    while(!queue.empty())
    {
      const Item item = queue.top(); queue.pop();
      const int u = item.first > dist[item.second] ? -1 : item.second;
      if(u < 0 || (u != tip && (seam_degree[u] != 0 || on_border[u]))) continue;
      for(int k = offset[u]; k < offset[u + 1]; ++k)
      {
        const int h = out[k], w = target(h);
        const double dw = item.first + cost(h);
        if(dw >= dist[w] || dw > l) continue;
        if(dist[w] == std::numeric_limits<double>::infinity()) touched.push_back(w);
        dist[w] = dw;
        reached_by[w] = h;
        queue.emplace(dw, w);
      }
    }
    std::size_t best = 0;
    double saving = 0;
    for(std::size_t i = 1; i < walk.size() - (plain_start ? 1 : 0); ++i)
    {
      const int start = source(walk[i]);
      if(dist[start] * min_ratio <= length[i] && length[i] - dist[start] > saving)
      {
        best = i;
        saving = length[i] - dist[start];
      }
    }
    if(saving > 0)
    {
      Seam_detour d;
      d.seam.assign(walk.rend() - best - 1, walk.rend());
      d.seam_cost = length[best];
      d.shortcut_cost = dist[source(walk[best])];
      for(int w = source(walk[best]); w != tip; w = source(reached_by[w])) d.shortcut.push_back(cm.opposite[reached_by[w]]);
      detours.push_back(std::move(d));
    }
    for(int w : touched) { dist[w] = std::numeric_limits<double>::infinity(); reached_by[w] = -1; }
    touched.clear();
  }
  return detours;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
