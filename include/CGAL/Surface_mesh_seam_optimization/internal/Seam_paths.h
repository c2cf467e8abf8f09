// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Seams as a graph on the 3D mesh: the leaf paths (from a seam tip to the
// first junction or input boundary vertex) and, for each, the cheapest path
// through uncut vertices from one of its vertices to its tip; the paths
// between two junctions and, for each, the cheapest such path between two
// of its vertices. Local operations grow seams one edge at a time along the
// distortion's pull, so a seam may wind far from the shortest route between
// its ends; these are the detours.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SEAM_PATHS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SEAM_PATHS_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Union_find.h>

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
  bool reroute = false; // no tip: both paths from the part's first vertex to its last
  bool to_border = false; // a reroute whose part and shortcut end on the input boundary, at two vertices
};

// The interior edges around each vertex and how many of them are seams.
struct Seam_graph
{
  const Cut_mesh& cm;
  std::vector<int> offset, out;  // outgoing interior halfedges of each vertex
  std::vector<int> seam_degree;
  std::vector<int> border_loop;  // a representative vertex of the input boundary loop through each vertex, or -1

  explicit Seam_graph(const Cut_mesh& mesh)
    : cm(mesh), offset(mesh.number_of_vertices() + 1, 0), out(mesh.corner_vertex.size()),
      seam_degree(mesh.number_of_vertices(), 0), border_loop(mesh.number_of_vertices(), -1)
  {
    const int nv = int(cm.number_of_vertices()), nh = int(cm.corner_vertex.size());
    Union_find loops(nv);
    for(int h = 0; h < nh; ++h)
    {
      if(cm.opposite[h] < 0)
      {
        border_loop[source(h)] = border_loop[target(h)] = 0; // (on the boundary; its loop below)
        loops.unite(source(h), target(h));
        continue;
      }
      ++offset[source(h) + 1];
      if(cm.is_seam(h)) ++seam_degree[source(h)];
    }
    for(int v = 0; v < nv; ++v)
      if(border_loop[v] >= 0) border_loop[v] = loops.find(v);
    for(int v = 0; v < nv; ++v) offset[v + 1] += offset[v];
    std::vector<int> fill(offset.begin(), offset.end() - 1);
    for(int h = 0; h < nh; ++h)
      if(cm.opposite[h] >= 0) out[fill[source(h)]++] = h;
  }

  bool on_border(int v) const { return border_loop[v] >= 0; } // on the input boundary
  int source(int h) const { return cm.corner_vertex[Cut_mesh::prev(h)]; }
  int target(int h) const { return cm.corner_vertex[h]; }
  // the seam halfedge out of v that does not lead back to `from`, or -1
  int next_seam(int v, int from) const
  {
    for(int k = offset[v]; k < offset[v + 1]; ++k)
      if(cm.is_seam(out[k]) && target(out[k]) != from) return out[k];
    return -1;
  }
};

// Cheapest paths from one vertex through uncut vertices (on no seam and not
// on the input boundary; a seam or boundary vertex ends a path), no longer
// than a bound: the candidate shortcuts. Reset by each run.
struct Uncut_paths
{
  std::vector<double> dist;
  std::vector<int> reached_by; // last halfedge of the cheapest path
  std::vector<int> touched;

  explicit Uncut_paths(std::size_t nv) : dist(nv, std::numeric_limits<double>::infinity()), reached_by(nv, -1) {}

  template <typename Cost>
  void run(const Seam_graph& g, const Cost& cost, int start, double bound)
  {
    for(int w : touched) { dist[w] = std::numeric_limits<double>::infinity(); reached_by[w] = -1; }
    touched.clear();
    typedef std::pair<double, int> Item;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
    dist[start] = 0; touched.push_back(start);
    queue.emplace(0., start);
    while(!queue.empty())
    {
      const Item item = queue.top(); queue.pop();
      const int u = item.first > dist[item.second] ? -1 : item.second;
      if(u < 0 || (u != start && (g.seam_degree[u] != 0 || g.on_border(u)))) continue;
      for(int k = g.offset[u]; k < g.offset[u + 1]; ++k)
      {
        const int h = g.out[k], w = g.target(h);
        const double dw = item.first + cost(h);
        if(dw >= dist[w] || dw > bound) continue;
        if(dist[w] == std::numeric_limits<double>::infinity()) touched.push_back(w);
        dist[w] = dw;
        reached_by[w] = h;
        queue.emplace(dw, w);
      }
    }
  }

  // the halfedges of the cheapest path from the last run's start to w
  std::vector<int> path_to(const Seam_graph& g, int w) const
  {
    std::vector<int> path;
    for(int x = w; reached_by[x] >= 0; x = g.source(reached_by[x])) path.push_back(reached_by[x]);
    std::reverse(path.begin(), path.end());
    return path;
  }
};

// For each leaf seam path, the part from one of its vertices to its tip
// whose cheapest alternative (on interior edges, through vertices on no seam
// and not on the input boundary, cost per halfedge `cost`) saves most, if
// that is at least `min_ratio` times cheaper.
template <typename Cost>
std::vector<Seam_detour> seam_detours(const Cut_mesh& cm, const Cost& cost, double min_ratio, bool plain_start = false)
{
  const Seam_graph g(cm);
  const int nv = int(cm.number_of_vertices());
  const int nh = int(cm.corner_vertex.size());
  std::vector<Seam_detour> detours;
  Uncut_paths paths(nv);
  for(int tip = 0; tip < nv; ++tip)
  {
    if(g.seam_degree[tip] != 1 || g.on_border(tip)) continue;
    // walk from the tip to the first vertex that is not a plain seam vertex
    std::vector<int> walk;      // halfedges, each towards the tip
    std::vector<double> length; // seam cost from the tip to the source of walk[i]
    int v = tip, from = -1;
    double l = 0;
    for(std::size_t guard = 0; guard < std::size_t(nh); ++guard)
    {
      const int next = g.next_seam(v, from);
      if(next < 0) break;
      walk.push_back(cm.opposite[next]);
      l += cost(next);
      length.push_back(l);
      from = v;
      v = g.target(next);
      if(g.seam_degree[v] != 2 || g.on_border(v) || v == tip) break;
    }
    if(walk.size() < 2 || v == tip) continue;

    // a shortcut from any vertex of the seam to its tip
    paths.run(g, cost, tip, l);
    const std::vector<double>& dist = paths.dist;
    std::size_t best = 0;
    double saving = 0;
    for(std::size_t i = 1; i < walk.size() - (plain_start ? 1 : 0); ++i)
    {
      const int start = g.source(walk[i]);
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
      d.shortcut_cost = dist[g.source(walk[best])];
      for(int w = g.source(walk[best]); w != tip; w = g.source(paths.reached_by[w]))
        d.shortcut.push_back(cm.opposite[paths.reached_by[w]]);
      detours.push_back(std::move(d));
    }
  }
  return detours;
}

// Where a seam path from a junction or a tip ends on the input boundary (and
// nothing else does there), that end is free to move along the boundary: the part from one of the
// path's inner vertices to it, against the cheapest path from that vertex to
// another vertex on no seam of the same boundary loop, if at least
// `min_ratio` times cheaper (the best saving). (A path to another loop is no
// slide: it bounds no region with the part, and would change which loops the
// cut joins.)
template <typename Cost>
void border_slides(const Seam_graph& g, const Cost& cost, double min_ratio, const std::vector<int>& path,
                   Uncut_paths& paths, std::vector<Seam_detour>& out)
{
  for(int direction = 0; direction < 2; ++direction)
  {
    const int end = direction == 0 ? g.target(path.back()) : g.source(path.front());
    const int other = direction == 0 ? g.source(path.front()) : g.target(path.back());
    // (a path from boundary to boundary divides charts: its ends stay)
    if(!g.on_border(end) || g.on_border(other) || g.seam_degree[end] != 1 || path.size() < 2) continue;
    std::vector<int> p(path); // towards `end`
    if(direction == 1)
    {
      std::reverse(p.begin(), p.end());
      for(int& h : p) h = g.cm.opposite[h];
    }
    std::vector<double> length(p.size() + 1, 0.);
    for(std::size_t i = 0; i < p.size(); ++i) length[i + 1] = length[i] + cost(p[i]);
    double saving = 0;
    std::size_t best_i = 0;
    std::vector<int> best_shortcut;
    for(std::size_t i = 1; i < p.size(); ++i)
    {
      const int start = g.target(p[i - 1]);
      const double along = length[p.size()] - length[i];
      paths.run(g, cost, start, along);
      for(int w : paths.touched)
      {
        const double dw = paths.dist[w];
        // (on the loop of `end`, so on the boundary)
        if(w == end || g.border_loop[w] != g.border_loop[end] || g.seam_degree[w] != 0 ||
           !(dw * min_ratio <= along) || !(along - dw > saving))
          continue;
        saving = along - dw;
        best_i = i;
        best_shortcut = paths.path_to(g, w);
      }
    }
    if(saving > 0)
    {
      Seam_detour d;
      d.seam.assign(p.begin() + best_i, p.end());
      d.seam_cost = length[p.size()] - length[best_i];
      d.shortcut = best_shortcut;
      d.shortcut_cost = d.seam_cost - saving;
      d.reroute = true;
      d.to_border = true;
      out.push_back(std::move(d));
    }
  }
}

// For each seam path between two junctions (or input boundary vertices),
// the part between two of its inner vertices whose cheapest alternative
// (through vertices on no seam and not on the input boundary) saves most, if
// that is at least `min_ratio` times cheaper. Such a part has no tip to be
// zipped from: `seam` and `shortcut` both go from its first vertex to its
// last. And, where such a path ends on the input boundary, its border
// slides (border_slides()).
template <typename Cost>
std::vector<Seam_detour> seam_reroutes(const Cut_mesh& cm, const Cost& cost, double min_ratio)
{
  const Seam_graph g(cm);
  const int nh = int(cm.corner_vertex.size());
  auto plain = [&](int v) { return g.seam_degree[v] == 2 && !g.on_border(v); };
  auto tip = [&](int v) { return g.seam_degree[v] == 1 && !g.on_border(v); };

  std::vector<Seam_detour> reroutes;
  std::vector<char> walked(nh, 0);
  Uncut_paths paths(cm.number_of_vertices());
  for(int h0 = 0; h0 < nh; ++h0)
  {
    if(cm.opposite[h0] < 0 || !cm.is_seam(h0) || walked[h0] || plain(g.source(h0))) continue;
    // the path from a node along h0 to the next node
    std::vector<int> path{ h0 };
    walked[h0] = walked[cm.opposite[h0]] = 1;
    for(std::size_t guard = 0; plain(g.target(path.back())) && guard < std::size_t(nh); ++guard)
    {
      const int next = g.next_seam(g.target(path.back()), g.source(path.back()));
      if(next < 0 || walked[next]) break;
      path.push_back(next);
      walked[next] = walked[cm.opposite[next]] = 1;
    }
    const int end = g.target(path.back());
    if(plain(end)) continue; // a loop
    border_slides(g, cost, min_ratio, path, paths, reroutes);
    if(tip(end) || tip(g.source(h0)) || path.size() < 3)
      continue; // a leaf path (seam_detours())
    // length[i]: seam cost from the start to vertex i (target of path[i-1])
    std::vector<double> length(path.size() + 1, 0.);
    for(std::size_t i = 0; i < path.size(); ++i) length[i + 1] = length[i] + cost(path[i]);
    double saving = 0;
    std::size_t best_i = 0, best_j = 0;
    std::vector<int> best_shortcut;
    for(std::size_t i = 1; i + 2 < path.size(); ++i)
    {
      const int start = g.target(path[i - 1]);
      paths.run(g, cost, start, length[path.size() - 1] - length[i]);
      const std::vector<double>& dist = paths.dist;
      for(std::size_t j = i + 2; j < path.size(); ++j)
      {
        const int w = g.target(path[j - 1]);
        const double along = length[j] - length[i];
        if(dist[w] * min_ratio <= along && along - dist[w] > saving)
        {
          saving = along - dist[w];
          best_i = i; best_j = j;
          best_shortcut = paths.path_to(g, w);
        }
      }
    }
    if(saving > 0)
    {
      Seam_detour d;
      d.seam.assign(path.begin() + best_i, path.begin() + best_j);
      d.seam_cost = length[best_j] - length[best_i];
      d.shortcut = best_shortcut;
      d.shortcut_cost = d.seam_cost - saving;
      d.reroute = true;
      reroutes.push_back(std::move(d));
    }
  }
  return reroutes;
}

// Replaces one detour by its shortcut: `attempt(d, applied)` on the detours
// that save at least `min_saving`, largest saving first (among equal
// savings, the first found), skipping those whose ends (`ends(d)`, a pair)
// are in `tried` and adding the ends of each attempted one, until one is
// applied or an attempt returns an error. A detour that cannot be replaced
// (its result would overlap, say) changes nothing, so the next is tried.
template <typename Ends, typename Attempt>
Error_code replace_largest_detour(const std::vector<Seam_detour>& detours, double min_saving,
                                  std::vector<std::pair<int, int> >& tried, const Ends& ends,
                                  const Attempt& attempt, bool& applied)
{
  applied = false;
  std::vector<const Seam_detour*> order;
  for(const Seam_detour& d : detours)
    if(d.seam_cost - d.shortcut_cost >= min_saving) order.push_back(&d);
  std::stable_sort(order.begin(), order.end(), [](const Seam_detour* a, const Seam_detour* b) {
    return a->seam_cost - a->shortcut_cost > b->seam_cost - b->shortcut_cost;
  });
  for(const Seam_detour* d : order)
  {
    const std::pair<int, int> e = ends(*d);
    if(std::find(tried.begin(), tried.end(), e) != tried.end()) continue;
    tried.push_back(e);
    const Error_code status = attempt(*d, applied);
    if(status != OK || applied) return status;
  }
  return OK;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
