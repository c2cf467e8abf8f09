// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Two charts that share seam edges, glued back along them. A corner merge
// zips a seam only from its tip; seams that cut a chart through (the cuts
// where a free map overlapped itself, Split_self_overlapping_charts.h) have
// no tip, so their charts could never be joined again however far the
// distortion stays below the bound.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_JOIN_CHARTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_JOIN_CHARTS_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Union_find.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Untangle.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Uv_topology.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

struct Chart_join
{
  int a = -1, b = -1;  // charts, a < b
  double saving = 0;   // seam cost the join removes (weighted length)
};

// Pairs of distinct charts with seam edges between them, the largest saving first.
inline std::vector<Chart_join> chart_joins(const Cut_mesh& cm, const std::vector<double>* halfedge_weight)
{
  std::vector<int> chart;
  if(cm.compute_charts(chart) < 2) return {};
  std::vector<std::pair<std::pair<int, int>, double> > shared;
  for(std::size_t h = 0; h < cm.opposite.size(); ++h)
  {
    const int o = cm.opposite[h];
    if(o < int(h) || !cm.is_seam(int(h))) continue;
    const int a = chart[h / 3], b = chart[std::size_t(o) / 3];
    if(a == b) continue;
    shared.emplace_back(std::make_pair((std::min)(a, b), (std::max)(a, b)),
                        cm.edge_length(int(h)) * (halfedge_weight ? (*halfedge_weight)[h] : 1.));
  }
  std::sort(shared.begin(), shared.end());
  std::vector<Chart_join> joins;
  for(const auto& s : shared)
  {
    if(joins.empty() || joins.back().a != s.first.first || joins.back().b != s.first.second)
      joins.push_back(Chart_join{s.first.first, s.first.second, 0.});
    joins.back().saving += s.second;
  }
  // (ties in saving keep the chart order: deterministic)
  std::stable_sort(joins.begin(), joins.end(),
                   [](const Chart_join& x, const Chart_join& y) { return x.saving > y.saving; });
  return joins;
}

// Glues chart b of `join` onto chart a along all their shared seam edges:
// b moved rigidly onto a (least squares over the shared vertices), each pair
// of copies merged at its midpoint, triangles flipped by the gluing
// untangled. False, with `cm` unchanged, where the result would not be a
// valid chart: a pinched vertex, a handle, or flips that cannot be undone.
inline bool join_two_charts(Cut_mesh& cm, const Vertex_corners& vc, const Chart_join& join)
{
  std::vector<int> chart;
  cm.compute_charts(chart);
  // the corner pairs to merge (corners are stable under relabelling; UV ids are not)
  std::vector<std::pair<int, int> > pairs;
  for(std::size_t h = 0; h < cm.opposite.size(); ++h)
  {
    const int o = cm.opposite[h];
    if(o < 0 || chart[h / 3] != join.a || chart[std::size_t(o) / 3] != join.b || !cm.is_seam(int(h))) continue;
    // halfedge h (in a) ends at corner h and starts at prev(h); o runs the other way
    pairs.emplace_back(int(h), Cut_mesh::prev(o));
    pairs.emplace_back(Cut_mesh::prev(int(h)), o);
  }
  if(pairs.empty()) return false;
  // each UV vertex of b meets one of a (else a's fans would merge too)
  std::vector<std::pair<int, int> > uv_pairs;
  for(const auto& p : pairs) uv_pairs.emplace_back(cm.corner_uv[p.second], cm.corner_uv[p.first]);
  std::sort(uv_pairs.begin(), uv_pairs.end());
  uv_pairs.erase(std::unique(uv_pairs.begin(), uv_pairs.end()), uv_pairs.end());
  for(std::size_t k = 1; k < uv_pairs.size(); ++k)
    if(uv_pairs[k].first == uv_pairs[k - 1].first) return false;
  {
    std::vector<int> of_a;
    for(const auto& p : uv_pairs) of_a.push_back(p.second);
    std::sort(of_a.begin(), of_a.end());
    if(std::adjacent_find(of_a.begin(), of_a.end()) != of_a.end()) return false;
  }
  auto border = [&cm](int h) { return cm.opposite[h] < 0 || cm.is_seam(h); };
  // rigid motion of b onto a: centroids, then the rotation of the cross-covariance
  const double n = double(uv_pairs.size());
  double qc[2] = {0, 0}, pc[2] = {0, 0};
  for(const auto& p : uv_pairs)
    for(int d = 0; d < 2; ++d) { qc[d] += cm.uv[2 * p.first + d] / n; pc[d] += cm.uv[2 * p.second + d] / n; }
  double sxx = 0, sxy = 0;
  for(const auto& p : uv_pairs)
  {
    const double qx = cm.uv[2 * p.first] - qc[0], qy = cm.uv[2 * p.first + 1] - qc[1];
    const double px = cm.uv[2 * p.second] - pc[0], py = cm.uv[2 * p.second + 1] - pc[1];
    sxx += qx * px + qy * py;
    sxy += qx * py - qy * px;
  }
  const double angle = std::atan2(sxy, sxx), c = std::cos(angle), s = std::sin(angle);
  Uv_snapshot before;
  before.save(cm);
  std::vector<char> in_b(cm.number_of_uv_vertices(), 0);
  for(std::size_t f = 0; f < chart.size(); ++f)
    if(chart[f] == join.b)
      for(int i = 0; i < 3; ++i) in_b[cm.corner_uv[3 * f + i]] = 1;
  for(std::size_t u = 0; u < in_b.size(); ++u)
  {
    if(!in_b[u]) continue;
    const double x = cm.uv[2 * u] - qc[0], y = cm.uv[2 * u + 1] - qc[1];
    cm.uv[2 * u] = pc[0] + c * x - s * y;
    cm.uv[2 * u + 1] = pc[1] + s * x + c * y;
  }
  for(const auto& p : pairs)
  {
    const int ua = cm.corner_uv[p.first], ub = cm.corner_uv[p.second];
    if(ua == ub) continue;
    for(int d = 0; d < 2; ++d) cm.uv[2 * ua + d] = 0.5 * (cm.uv[2 * ua + d] + cm.uv[2 * ub + d]);
    merge_uv_vertices(cm, vc, ua, ub);
  }
  // the union must be planar (glued along several paths it has holes, but
  // no handle: V - E + F plus its boundary loops is 2), and valid: the
  // gluing moved the two sides' copies, so triangles beside the seam may
  // have flipped; they are untangled with the borders fixed
  std::vector<int> joined_chart;
  const std::size_t n_joined = cm.compute_charts(joined_chart);
  const std::vector<long> chi = chart_euler_characteristics(joined_chart, n_joined, cm.corner_uv,
                                                            cm.number_of_uv_vertices(), cm.opposite, border);
  const int j = joined_chart[std::size_t(std::find(chart.begin(), chart.end(), join.a) - chart.begin())];
  Union_find loops(cm.number_of_uv_vertices());
  std::vector<char> on_border(cm.number_of_uv_vertices(), 0);
  for(std::size_t h = 0; h < cm.opposite.size(); ++h)
    if(joined_chart[h / 3] == j && border(int(h)))
    {
      const int u = cm.corner_uv[h], w = cm.corner_uv[Cut_mesh::prev(int(h))];
      on_border[u] = on_border[w] = 1;
      loops.unite(u, w);
    }
  long n_loops = 0;
  for(std::size_t u = 0; u < on_border.size(); ++u)
    if(on_border[u] && loops.find(int(u)) == int(u)) ++n_loops;
  std::size_t invalid = 0;
  bool valid = chi[j] + n_loops == 2 && untangle_uv_map(cm, invalid);
  if(!valid) before.restore(cm);
  return valid;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
