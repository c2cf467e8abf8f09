// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A chart whose free stationary map overlaps itself is cut in two where its
// overlapping layers join (a minimum cut), each corner keeping its UV: the
// pieces are flip-free at once and keep what the descent gained, which going
// back to an initial map that is far from stationary (Tutte maps of cut-open
// high-genus charts: E_SD 1e6) and descending again with a scaffold would
// take thousands of iterations to regain.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SPLIT_SELF_OVERLAPPING_CHARTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SPLIT_SELF_OVERLAPPING_CHARTS_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Overlap.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Shortest_paths.h>

#include <CGAL/Surface_mesh_seam_optimization/internal/Union_find.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Distance between the 3D centroids of two faces.
inline double face_centroid_distance(const Cut_mesh& cm, int f, int g)
{
  double d2 = 0;
  for(int k = 0; k < 3; ++k)
  {
    double a = 0, b = 0;
    for(int i = 0; i < 3; ++i)
    {
      a += cm.points[3 * cm.corner_vertex[3*f + i] + k];
      b += cm.points[3 * cm.corner_vertex[3*g + i] + k];
    }
    d2 += (a - b) * (a - b) / 9.;
  }
  return std::sqrt(d2);
}

// Minimum cut, by 3D seam cost, between the faces `source` and `sink` (both
// nonempty, disjoint) of a chart given by its faces `fk`; marks the chart's
// halfedges across the cut in `cut`. `local` maps a face to its index in `fk`.
inline void mark_minimum_cut(const Cut_mesh& cm, const std::vector<int>& fk, const std::vector<int>& local,
                             const std::vector<char>& source, const std::vector<char>& sink,
                             const std::vector<double>* halfedge_weight, std::vector<char>& cut)
{
  typedef boost::adjacency_list_traits<boost::vecS, boost::vecS, boost::directedS> Traits;
  typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::directedS,
    boost::property<boost::vertex_index_t, long,
      boost::property<boost::vertex_color_t, boost::default_color_type,
        boost::property<boost::vertex_distance_t, long,
          boost::property<boost::vertex_predecessor_t, Traits::edge_descriptor> > > >,
    boost::property<boost::edge_capacity_t, double,
      boost::property<boost::edge_residual_capacity_t, double,
        boost::property<boost::edge_reverse_t, Traits::edge_descriptor> > > > Graph;
  const int n = int(fk.size()), S = n, T = n + 1;
  Graph g(std::size_t(n) + 2);
  auto capacity = get(boost::edge_capacity, g);
  auto reverse = get(boost::edge_reverse, g);
  auto add = [&](int u, int v, double forward, double backward) {
    const auto e = add_edge(u, v, g).first, r = add_edge(v, u, g).first;
    capacity[e] = forward; capacity[r] = backward;
    reverse[e] = r; reverse[r] = e;
  };
  double total = 0;
  for(int a = 0; a < n; ++a)
    for(int i = 0; i < 3; ++i)
    {
      const int h = 3 * fk[a] + i, o = cm.opposite[h];
      if(o < h || cm.is_seam(h)) continue; // each interior edge once (o >= 0)
      const double c = cm.edge_length(h) * (halfedge_weight ? (std::max)(0., (*halfedge_weight)[h]) : 1.);
      add(a, local[o / 3], c, c);
      total += c;
    }
  const double seed = 2 * total + 1; // more than any cut
  for(int a = 0; a < n; ++a)
  {
    if(source[a]) add(S, a, seed, 0.);
    else if(sink[a]) add(a, T, seed, 0.);
  }
  boost::boykov_kolmogorov_max_flow(g, S, T);
  // the source's side: the vertices of the source's search tree
  auto color = get(boost::vertex_color, g);
  const auto source_color = get(color, S);
  for(int a = 0; a < n; ++a)
    for(int i = 0; i < 3; ++i)
    {
      const int h = 3 * fk[a] + i, o = cm.opposite[h];
      if(o >= 0 && !cm.is_seam(h) && (get(color, a) == source_color) != (get(color, local[o / 3]) == source_color))
        cut[h] = 1;
    }
}

// Cuts every chart that overlaps itself in two, each corner keeping its UV;
// returns how many were cut. The cut is the cheapest one (3D length times
// `halfedge_weight`) between two overlapping layers (connected regions of
// overlapping triangles) that overlap each other most: a limb folded over the
// body comes off where it joins it, not across geodesic Voronoi cells. A
// layer that overlaps only itself is cut between the triangles of its pairs
// on either side of the Voronoi boundary of its first pair.
inline std::size_t cut_self_overlapping_charts_once(Cut_mesh& cm, const std::vector<double>* halfedge_weight)
{
  std::vector<int> chart;
  const std::size_t n = cm.compute_charts(chart);
  std::vector<std::vector<int> > faces(n);
  for(std::size_t f = 0; f < chart.size(); ++f) faces[chart[f]].push_back(int(f));

  const std::size_t nf = cm.number_of_faces();
  // dual graph of a chart: faces joined across its interior, non-seam edges
  auto for_each_arc = [&](int f, const auto& visit) {
    for(int i = 0; i < 3; ++i)
    {
      const int h = 3*f + i, o = cm.opposite[h];
      if(o < 0 || cm.is_seam(h)) continue;
      visit(o / 3, face_centroid_distance(cm, f, o / 3), h);
    }
  };
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> dist(nf, inf);
  std::vector<int> label(nf, -1), local(nf, -1);
  std::vector<char> cut(cm.corner_vertex.size(), 0);
  std::size_t split = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::vector<int>& fk = faces[k];
    if(fk.size() < 2) continue;
    std::vector<int> tri;
    tri.reserve(3 * fk.size());
    for(int f : fk) for(int i = 0; i < 3; ++i) tri.push_back(cm.corner_uv[3*f + i]);
    std::vector<std::pair<int, int> > pairs;
    if(count_overlapping_pairs(tri, cm.uv.data(), std::size_t(-1), 1e-9, nullptr, &pairs) == 0) continue;
    const int m = int(fk.size());
    for(int a = 0; a < m; ++a) local[fk[a]] = a;
    // layers: the overlapping triangles joined across the chart's interior edges
    std::vector<char> involved(m, 0);
    for(const auto& p : pairs) involved[p.first] = involved[p.second] = 1;
    Union_find layers(m);
    for(int a = 0; a < m; ++a)
      if(involved[a])
        for(int i = 0; i < 3; ++i)
        {
          const int h = 3 * fk[a] + i, o = cm.opposite[h];
          if(o >= 0 && !cm.is_seam(h) && involved[local[o / 3]]) layers.unite(a, local[o / 3]);
        }
    // the two layers with most pairs between them
    std::vector<std::pair<int, int> > between;
    for(const auto& p : pairs)
    {
      const int x = layers.find(p.first), y = layers.find(p.second);
      if(x != y) between.emplace_back((std::min)(x, y), (std::max)(x, y));
    }
    std::sort(between.begin(), between.end());
    std::pair<int, int> best(-1, -1);
    for(std::size_t s = 0, most = 0; s < between.size();)
    {
      std::size_t e = s;
      while(e < between.size() && between[e] == between[s]) ++e;
      if(e - s > most) { most = e - s; best = between[s]; }
      s = e;
    }
    std::vector<char> source(m, 0), sink(m, 0);
    if(best.first >= 0)
      for(int a = 0; a < m; ++a)
      {
        if(!involved[a]) continue;
        const int r = layers.find(a);
        source[a] = r == best.first;
        sink[a] = r == best.second;
      }
    else
    {
      const int a = fk[pairs[0].first], b = fk[pairs[0].second];
      for(int f : fk) { dist[f] = inf; label[f] = -1; }
      label[a] = 0; label[b] = 1;
      dijkstra(std::vector<int>{ a, b }, dist, for_each_arc, [&](int u, int w, int) { label[w] = label[u]; });
      for(const auto& p : pairs)
      {
        const int x = label[fk[p.first]], y = label[fk[p.second]];
        if(x == y || x < 0 || y < 0) continue; // (faces joined to the chart by a vertex only: unreached)
        (x == 0 ? source : sink)[p.first] = 1;
        (y == 0 ? source : sink)[p.second] = 1;
      }
    }
    mark_minimum_cut(cm, fk, local, source, sink, halfedge_weight, cut);
    ++split;
  }
  if(split == 0) return 0;
  // new UV vertices along the cuts, each corner keeping its UV
  std::vector<double> corner_uv(2 * cm.corner_uv.size());
  std::vector<char> seam(cm.corner_vertex.size(), 0);
  for(std::size_t c = 0; c < cm.corner_uv.size(); ++c)
  {
    corner_uv[2*c] = cm.uv[2 * cm.corner_uv[c]];
    corner_uv[2*c+1] = cm.uv[2 * cm.corner_uv[c] + 1];
    seam[c] = cm.is_seam(int(c)) || cut[c];
  }
  label_uv_vertices(cm, seam);
  // (the corners of a UV vertex had one UV: copied, not averaged, to keep it bit for bit)
  for(std::size_t c = 0; c < cm.corner_uv.size(); ++c)
  {
    cm.uv[2 * cm.corner_uv[c]] = corner_uv[2*c];
    cm.uv[2 * cm.corner_uv[c] + 1] = corner_uv[2*c+1];
  }
  return split;
}

// Cuts the charts until none overlaps itself (each cut between the layers
// that overlap most); returns the number of cuts. All at once, not one cut
// per descent: b9_mesh 9.47 (8 splits over both starts), femur 14.67 (6),
// against 9.45 (21) and 15.71 (10), and 15.06 and 14.40 by geodesic Voronoi
// cells.
inline std::size_t split_self_overlapping_charts(Cut_mesh& cm, const std::vector<double>* halfedge_weight = nullptr)
{
  std::size_t cuts = 0;
  while(std::size_t k = cut_self_overlapping_charts_once(cm, halfedge_weight)) cuts += k;
  return cuts;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
