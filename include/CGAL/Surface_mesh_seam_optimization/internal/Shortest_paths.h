// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SHORTEST_PATHS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SHORTEST_PATHS_H

#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Dijkstra from `sources` over a graph given by its arcs: for_each_arc(u,
// visit) calls visit(w, length, arc) for each arc u -> w. `dist` (one per
// vertex, set by the caller: infinity where not yet reached) gets the
// distances; on_relax(u, w, arc) is called whenever w is reached more
// cheaply, through `arc` from u. Ties are broken by vertex index, so the
// result does not depend on anything but the graph.
// The search stops early once on_settle(u) returns true for a vertex u whose
// distance is final (a target reached).
template <typename ForEachArc, typename OnRelax, typename OnSettle>
void dijkstra(const std::vector<int>& sources, std::vector<double>& dist,
              const ForEachArc& for_each_arc, const OnRelax& on_relax, const OnSettle& on_settle)
{
  typedef std::pair<double, int> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
  for(int s : sources)
  {
    dist[s] = 0;
    queue.push(Item(0., s));
  }
  while(!queue.empty())
  {
    const Item top = queue.top();
    queue.pop();
    const int u = top.second;
    if(top.first > dist[u]) continue;
    if(on_settle(u)) return;
    for_each_arc(u, [&](int w, double length, int arc) {
      const double d = top.first + length;
      if(d < dist[w])
      {
        dist[w] = d;
        on_relax(u, w, arc);
        queue.push(Item(d, w));
      }
    });
  }
}

template <typename ForEachArc, typename OnRelax>
void dijkstra(const std::vector<int>& sources, std::vector<double>& dist,
              const ForEachArc& for_each_arc, const OnRelax& on_relax)
{
  dijkstra(sources, dist, for_each_arc, on_relax, [](int) { return false; });
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
