// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A chart whose free stationary map overlaps itself is cut in two between
// two of its triangles that overlap (their geodesic Voronoi regions on the
// surface), each corner keeping its UV: the pieces are flip-free at once and
// keep what the descent gained, which going back to an initial map that is
// far from stationary (Tutte maps of cut-open high-genus charts: E_SD 1e6)
// and descending again with a scaffold would take thousands of iterations
// to regain.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SPLIT_SELF_OVERLAPPING_CHARTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SPLIT_SELF_OVERLAPPING_CHARTS_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Overlap.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Shortest_paths.h>

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

// Splits every chart that overlaps itself into two; returns how many were split.
inline std::size_t split_self_overlapping_charts(Cut_mesh& cm)
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
  std::vector<int> label(nf, -1);
  std::vector<char> cut(cm.corner_vertex.size(), 0);
  std::size_t split = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::vector<int>& fk = faces[k];
    if(fk.size() < 2) continue;
    std::vector<int> tri;
    tri.reserve(3 * fk.size());
    for(int f : fk) for(int i = 0; i < 3; ++i) tri.push_back(cm.corner_uv[3*f + i]);
    std::pair<int, int> pair(-1, -1);
    if(count_overlapping_pairs(tri, cm.uv.data(), 1, 1e-9, &pair) == 0) continue;
    const int a = fk[pair.first], b = fk[pair.second];
    for(int f : fk) dist[f] = inf;
    label[a] = 0; label[b] = 1;
    dijkstra(std::vector<int>{ a, b }, dist, for_each_arc, [&](int u, int w, int) { label[w] = label[u]; });
    for(int f : fk)
      for(int i = 0; i < 3; ++i)
      {
        const int h = 3*f + i, o = cm.opposite[h];
        if(o >= 0 && !cm.is_seam(h) && label[o / 3] != label[f]) cut[h] = 1;
      }
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

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
