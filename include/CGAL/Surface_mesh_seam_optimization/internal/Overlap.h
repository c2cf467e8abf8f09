// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Pairs of UV triangles whose interiors overlap (global bijectivity): a
// uniform grid over the triangles' boxes and a separating-axis test with a
// tolerance relative to the UV extent, so that triangles which only share or
// touch a vertex or an edge do not count. Before the pairs, a linear-time
// proof that there are none (is_certainly_overlap_free()).

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_OVERLAP_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_OVERLAP_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Counts overlapping pairs of the triangles `tri` (3 indices into `uv` per
// triangle), stopping at `cap`. Degenerate triangles are skipped. The first
// pair found goes to `first` (triangle indices), if given, and every pair
// counted to `all`.
inline std::size_t count_overlapping_pairs(const std::vector<int>& tri, const double* uv,
                                           std::size_t cap = std::size_t(-1),
                                           double relative_tolerance = 1e-9,
                                           std::pair<int, int>* first = nullptr,
                                           std::vector<std::pair<int, int> >* all = nullptr)
{
  const std::size_t n = tri.size() / 3;
  struct Box { double x0, y0, x1, y1; };
  std::vector<Box> box;
  std::vector<double> line;   // 9 per triangle: inward unit edge lines
  std::vector<int> id;        // triangles kept
  box.reserve(n); line.reserve(9 * n); id.reserve(n);
  double gx0 = HUGE_VAL, gy0 = HUGE_VAL, gx1 = -HUGE_VAL, gy1 = -HUGE_VAL;
  std::vector<double> extent;
  for(std::size_t t = 0; t < n; ++t)
  {
    const double* p[3] = { uv + 2 * tri[3*t], uv + 2 * tri[3*t+1], uv + 2 * tri[3*t+2] };
    const double a2 = (p[1][0]-p[0][0]) * (p[2][1]-p[0][1]) - (p[1][1]-p[0][1]) * (p[2][0]-p[0][0]);
    if(!(a2 != 0) || !std::isfinite(a2)) continue;
    const double s = a2 > 0 ? 1. : -1.;
    Box b{ p[0][0], p[0][1], p[0][0], p[0][1] };
    for(int k = 1; k < 3; ++k)
    {
      b.x0 = (std::min)(b.x0, p[k][0]); b.x1 = (std::max)(b.x1, p[k][0]);
      b.y0 = (std::min)(b.y0, p[k][1]); b.y1 = (std::max)(b.y1, p[k][1]);
    }
    for(int k = 0; k < 3; ++k)
    {
      const double* a = p[k];
      const double* c = p[(k + 1) % 3];
      const double dx = c[0] - a[0], dy = c[1] - a[1], l = std::sqrt(dx*dx + dy*dy);
      const double nx = l > 0 ? -dy * s / l : 0., ny = l > 0 ? dx * s / l : 0.;
      line.push_back(nx); line.push_back(ny); line.push_back(-(nx * a[0] + ny * a[1]));
    }
    gx0 = (std::min)(gx0, b.x0); gy0 = (std::min)(gy0, b.y0);
    gx1 = (std::max)(gx1, b.x1); gy1 = (std::max)(gy1, b.y1);
    extent.push_back((std::max)(b.x1 - b.x0, b.y1 - b.y0));
    box.push_back(b);
    id.push_back(int(t));
  }
  const std::size_t m = box.size();
  if(m < 2) return 0;
  const double span = (std::max)(gx1 - gx0, gy1 - gy0);
  const double tol = relative_tolerance * std::sqrt((gx1-gx0)*(gx1-gx0) + (gy1-gy0)*(gy1-gy0));
  std::nth_element(extent.begin(), extent.begin() + m / 2, extent.end());
  double h = (std::max)(1.5 * extent[m / 2], span * 1e-7);
  if(!(h > 0)) h = 1.;
  // coarser cells while boxes would be inserted into too many of them
  for(;;)
  {
    std::size_t insertions = 0;
    for(const Box& b : box)
    {
      insertions += std::size_t((std::floor((b.x1 - gx0) / h) - std::floor((b.x0 - gx0) / h) + 1) *
                                (std::floor((b.y1 - gy0) / h) - std::floor((b.y0 - gy0) / h) + 1));
      if(insertions > 12 * m + 1000) break;
    }
    if(insertions <= 12 * m + 1000 || h >= span) break;
    h *= 2;
  }
  const long long ny = (long long)((gy1 - gy0) / h) + 3;
  auto cell = [&](double x, double y) { return (long long)((x - gx0) / h) * ny + (long long)((y - gy0) / h); };
  std::vector<std::pair<long long, int> > entries;
  for(std::size_t i = 0; i < m; ++i)
  {
    const Box& b = box[i];
    const long long cx0 = (long long)((b.x0 - gx0) / h), cx1 = (long long)((b.x1 - gx0) / h);
    const long long cy0 = (long long)((b.y0 - gy0) / h), cy1 = (long long)((b.y1 - gy0) / h);
    for(long long cx = cx0; cx <= cx1; ++cx)
      for(long long cy = cy0; cy <= cy1; ++cy) entries.emplace_back(cx * ny + cy, int(i));
  }
  std::sort(entries.begin(), entries.end());

  // true if the edge lines of triangle i separate triangle j from it
  auto separated = [&](std::size_t i, std::size_t j) {
    const double* L = &line[9 * i];
    const int* t = &tri[3 * id[j]];
    for(int k = 0; k < 3; ++k)
    {
      bool all_out = true;
      for(int v = 0; v < 3 && all_out; ++v)
        all_out = L[3*k] * uv[2*t[v]] + L[3*k+1] * uv[2*t[v]+1] + L[3*k+2] <= tol;
      if(all_out) return true;
    }
    return false;
  };
  std::size_t count = 0;
  for(std::size_t s = 0; s < entries.size();)
  {
    std::size_t e = s;
    while(e < entries.size() && entries[e].first == entries[s].first) ++e;
    for(std::size_t a = s; a + 1 < e; ++a)
      for(std::size_t b = a + 1; b < e; ++b)
      {
        const std::size_t i = std::size_t(entries[a].second), j = std::size_t(entries[b].second);
        const Box &bi = box[i], &bj = box[j];
        if(bj.x0 >= bi.x1 || bi.x0 >= bj.x1 || bj.y0 >= bi.y1 || bi.y0 >= bj.y1) continue;
        // each pair once: in the cell of the lower corner of the boxes' intersection
        if(cell((std::max)(bi.x0, bj.x0), (std::max)(bi.y0, bj.y0)) != entries[s].first) continue;
        if(separated(i, j) || separated(j, i)) continue;
        if(count == 0 && first) *first = std::make_pair(id[i], id[j]);
        if(all) all->emplace_back(id[i], id[j]);
        if(++count >= cap) return count;
      }
    s = e;
  }
  return count;
}

// True only if no two UV triangles of `cm` overlap, by a degree argument:
// with every triangle counterclockwise, the number of triangles over a point
// is the winding number of the UV border around it. So if the border loops
// are simple and pairwise disjoint, that number is constant between loops
// and drops by one across each, and it is at most one everywhere iff it is
// one just left of (on the charts' side of) every loop. Exact predicates;
// linear in the faces plus the border's pairs of nearby edges and loops x
// border edges. False (no proof) on any clockwise or degenerate triangle,
// touching or crossing border edges, a pinched border or too many loops:
// count_overlapping_pairs() decides then. The scaffold is rebuilt hundreds
// of times per run, each time checked: the pairs' count was 8-10% of a run.
inline bool is_certainly_overlap_free(const Cut_mesh& cm, std::size_t max_loop_work = 50000000)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
  typedef Kernel::Point_2 Point;
  const std::size_t nf = cm.number_of_faces(), nuv = cm.number_of_uv_vertices();
  auto point = [&](int i) { return Point(cm.uv[2*i], cm.uv[2*i+1]); };
  for(std::size_t f = 0; f < nf; ++f)
    if(CGAL::orientation(point(cm.corner_uv[3*f]), point(cm.corner_uv[3*f+1]), point(cm.corner_uv[3*f+2])) !=
       CGAL::LEFT_TURN)
      return false;

  // border edges src -> dst, the charts on their left
  std::vector<int> src, dst, next(nuv, -1), prev(nuv, -1);
  for(std::size_t h = 0; h < cm.corner_uv.size(); ++h)
  {
    if(cm.opposite[h] >= 0 && !cm.is_seam(int(h))) continue;
    const int u = cm.corner_uv[Cut_mesh::prev(int(h))], w = cm.corner_uv[h];
    if(next[u] >= 0 || prev[w] >= 0) return false; // a pinch
    next[u] = w;
    prev[w] = u;
    src.push_back(u);
    dst.push_back(w);
  }
  const std::size_t ne = src.size();
  std::vector<int> loop_of(nuv, -1), first_of_loop;
  for(std::size_t e = 0; e < ne; ++e)
  {
    if(loop_of[src[e]] >= 0) continue;
    const int id = int(first_of_loop.size());
    first_of_loop.push_back(src[e]);
    for(int v = src[e]; loop_of[v] < 0; v = next[v])
    {
      if(next[v] < 0) return false; // an open border: not a cut mesh
      loop_of[v] = id;
    }
  }
  const std::size_t nloops = first_of_loop.size();
  if(nloops * ne > max_loop_work) return false;

  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
  std::vector<Box> boxes;
  boxes.reserve(ne);
  for(std::size_t e = 0; e < ne; ++e)
  {
    const double* a = &cm.uv[2 * src[e]];
    const double* b = &cm.uv[2 * dst[e]];
    boxes.push_back(Box(CGAL::Bbox_2((std::min)(a[0], b[0]), (std::min)(a[1], b[1]),
                                     (std::max)(a[0], b[0]), (std::max)(a[1], b[1])), e));
  }
  bool simple = true;
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& x, const Box& y) {
    if(!simple) return;
    const std::size_t i = x.info(), j = y.info();
    const int a = src[i], b = dst[i], c = src[j], d = dst[j];
    if(a == d && b == c) { simple = false; return; }
    if(b == c || a == d)
    {
      // consecutive edges p -> q -> r: they may only meet at q
      const int p = b == c ? a : c, q = b == c ? b : a, r = b == c ? d : b;
      const Point P = point(p), Q = point(q), R = point(r);
      simple = !(CGAL::orientation(P, Q, R) == CGAL::COLLINEAR &&
                 (P.x() - Q.x()) * (R.x() - Q.x()) + (P.y() - Q.y()) * (R.y() - Q.y()) > 0);
      return;
    }
    simple = !CGAL::do_intersect(Kernel::Segment_2(point(a), point(b)), Kernel::Segment_2(point(c), point(d)));
  });
  if(!simple) return false;

  // 1 if a loop turns counterclockwise (left of it: inside it), else 0;
  // decided at its lowest-leftmost vertex, which is convex
  std::vector<int> own(nloops, 0), lowest(nloops, -1);
  for(std::size_t e = 0; e < ne; ++e)
  {
    int& l = lowest[loop_of[src[e]]];
    if(l < 0 || CGAL::compare_xy(point(src[e]), point(l)) == CGAL::SMALLER) l = src[e];
  }
  for(std::size_t k = 0; k < nloops; ++k)
  {
    const int v = lowest[k];
    const CGAL::Orientation o = CGAL::orientation(point(prev[v]), point(v), point(next[v]));
    if(o == CGAL::COLLINEAR) return false;
    own[k] = o == CGAL::LEFT_TURN ? 1 : 0;
  }
  // winding number of the other loops around a vertex of each loop
  for(std::size_t k = 0; k < nloops; ++k)
  {
    const Point p = point(first_of_loop[k]);
    int winding = own[k];
    for(std::size_t e = 0; e < ne; ++e)
    {
      if(loop_of[src[e]] == int(k)) continue;
      const Point a = point(src[e]), b = point(dst[e]);
      if(a.y() <= p.y())
      {
        if(b.y() > p.y() && CGAL::orientation(a, b, p) == CGAL::LEFT_TURN) ++winding;
      }
      else if(b.y() <= p.y() && CGAL::orientation(a, b, p) == CGAL::RIGHT_TURN) --winding;
    }
    if(winding != 1) return false;
  }
  return true;
}

inline std::size_t count_overlapping_pairs(const Cut_mesh& cm, std::size_t cap = std::size_t(-1))
{
  if(is_certainly_overlap_free(cm)) return 0;
  return count_overlapping_pairs(cm.corner_uv, cm.uv.data(), cap);
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
