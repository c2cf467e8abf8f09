// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Joining slits to the border of their chart: a seam tree that touches no
// border (an interior split's slit) is a hole of its chart; under a
// scaffold, the hole's scaffold and the thin bridge between hole and border
// keep it from opening.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_JOIN_SLITS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_JOIN_SLITS_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Shortest_paths.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Union_find.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Dynamic_property_map.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Joins every seam tree of `seam` that touches neither the border of `tm`
// nor a tree that does (on a closed component: its largest seam tree) to
// the nearest such one, along a shortest path (3D edge lengths) through
// vertices on no seam, whose edges become seams. Returns the number of
// paths added; a slit no such path reaches stays as it is.
// With `holes_too`, only the largest tree of border loops (and seams) of
// each component counts as its border: the other loops, the holes of
// its charts, are joined to it as slits are.
template <typename TriangleMesh, typename VertexPointMap, typename EdgeSeamMap>
std::size_t join_slits_to_border(const TriangleMesh& tm, VertexPointMap vpm, EdgeSeamMap seam,
                                 bool holes_too = false)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  std::vector<vertex_descriptor> vertex;
  auto index = get(CGAL::dynamic_vertex_property_t<int>(), tm);
  for(vertex_descriptor v : vertices(tm)) { put(index, v, int(vertex.size())); vertex.push_back(v); }
  const int n = int(vertex.size());
  auto is_cut = [&](halfedge_descriptor h) { return is_border_edge(h, tm) || get(seam, edge(h, tm)); };
  auto length = [&](halfedge_descriptor h) {
    const auto a = get(vpm, source(h, tm)), b = get(vpm, target(h, tm));
    return std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
  };

  Union_find cuts(n), parts(n); // seam trees (with the border), connected components
  std::vector<char> on_cut(n, 0), anchored(n, 0); // anchored: by the root of a seam tree
  std::vector<int> size(n, 0);
  for(auto e : edges(tm))
  {
    const halfedge_descriptor h = halfedge(e, tm);
    const int a = get(index, source(h, tm)), b = get(index, target(h, tm));
    parts.unite(a, b);
    if(!is_cut(h)) continue;
    on_cut[a] = on_cut[b] = 1;
    cuts.unite(a, b);
  }
  std::vector<char> touches_border(n, 0);
  for(auto e : edges(tm))
    if(is_border(e, tm)) touches_border[cuts.find(get(index, source(halfedge(e, tm), tm)))] = 1;
  for(int v = 0; v < n; ++v)
    if(on_cut[v]) ++size[cuts.find(v)];
  // per component, its largest seam tree, and its largest tree on the border
  std::vector<int> best(n, -1), best_border(n, -1);
  for(int v = 0; v < n; ++v)
  {
    if(!on_cut[v] || cuts.find(v) != v) continue;
    int& b = best[parts.find(v)];
    if(b < 0 || size[v] > size[b]) b = v;
    if(!touches_border[v]) continue;
    if(!holes_too) { anchored[v] = 1; continue; }
    int& bb = best_border[parts.find(v)];
    if(bb < 0 || size[v] > size[bb]) bb = v;
  }
  for(int p = 0; p < n; ++p)
    if(best_border[p] >= 0) anchored[best_border[p]] = 1;
  // a closed component: its largest seam tree stands for the border
  std::vector<char> part_anchored(n, 0);
  for(int v = 0; v < n; ++v)
    if(on_cut[v] && anchored[cuts.find(v)]) part_anchored[parts.find(v)] = 1;
  for(int p = 0; p < n; ++p)
    if(best[p] >= 0 && !part_anchored[p]) anchored[best[p]] = 1;

  auto is_slit = [&](int v) { return on_cut[v] && !anchored[cuts.find(v)]; };
  std::size_t joined = 0;
  std::vector<double> dist(n);
  std::vector<halfedge_descriptor> reached_by(n);
  for(;;)
  {
    std::vector<int> sources;
    bool any_slit = false;
    for(int v = 0; v < n; ++v)
    {
      if(on_cut[v] && anchored[cuts.find(v)]) sources.push_back(v);
      any_slit = any_slit || is_slit(v);
    }
    if(!any_slit || sources.empty()) break;
    std::fill(dist.begin(), dist.end(), std::numeric_limits<double>::infinity());
    std::vector<char> is_source(n, 0);
    for(int s : sources) is_source[s] = 1;
    int slit = -1;
    dijkstra(
      sources, dist,
      [&](int u, const auto& visit) {
        for(halfedge_descriptor h : CGAL::halfedges_around_source(vertex[u], tm))
        {
          if(is_cut(h)) continue;
          const int w = get(index, target(h, tm));
          if(!on_cut[w] || is_slit(w)) visit(w, length(h), 0);
        }
      },
      [&](int u, int w, int) {
        for(halfedge_descriptor h : CGAL::halfedges_around_source(vertex[u], tm))
          if(get(index, target(h, tm)) == w && !is_cut(h)) { reached_by[w] = h; break; }
      },
      [&](int u) {
        if(!is_slit(u)) return false;
        slit = u;
        return true;
      });
    if(slit < 0) break;
    const int root = cuts.find(slit);
    for(int w = slit; !is_source[w];)
    {
      const halfedge_descriptor h = reached_by[w];
      put(seam, edge(h, tm), true);
      const int u = get(index, source(h, tm));
      on_cut[u] = on_cut[w] = 1;
      cuts.unite(u, w);
      w = u;
    }
    anchored[cuts.find(root)] = 1;
    ++joined;
  }
  return joined;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
