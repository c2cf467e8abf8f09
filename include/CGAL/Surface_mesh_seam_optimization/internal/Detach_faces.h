// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The last resort of bound mode: a triangle alone is mapped isometrically
// (E_SD = 4), so the bound can always be met by detaching the triangles of
// highest distortion into charts of their own. Used when the alternation
// ends above the bound with no split left that lowers E_SD (very coarse
// meshes, where a scaffold leaves a split no room to open).

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DETACH_FACES_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DETACH_FACES_H

#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Element_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Mesh_energy.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// True if taking face f out of its chart would leave some UV vertex of it
// with two fans that only touch there (f in the middle of an open fan).
inline bool detaching_pinches(const Cut_mesh& cm, std::size_t f)
{
  auto joined = [&](int h) { return cm.opposite[h] >= 0 && !cm.is_seam(h); };
  for(int c = int(3 * f); c < int(3 * f) + 3; ++c)
  {
    if(!joined(c) || !joined(Cut_mesh::next(c))) continue; // f ends its fan there
    int cur = c;
    for(std::size_t steps = 0; steps <= cm.corner_vertex.size(); ++steps)
    {
      const int h = Cut_mesh::next(cur);
      if(!joined(h)) return true; // open fan, f inside it
      cur = cm.opposite[h];
      if(cur == c) break;         // a ring: f leaves an open fan
    }
  }
  return false;
}

// Detaches the faces of highest density, one at a time, until the
// area-weighted mean of `energy` is at most `bound` (a detached face is at
// its 3D shape, the energy's minimum): first those that leave their chart
// whole, then (if that is not enough) any. Each gets UV vertices of its own
// (reusing those it alone had) at its 3D shape, in rows below every chart;
// charts that then touch another at a single vertex are moved into the rows
// too, so that nothing overlaps or touches. Returns the number of faces detached.
template <typename Energy>
std::size_t detach_faces_until_bound(Cut_mesh& cm, double bound, const Energy& energy)
{
  const double minimum = Energy::minimum_value();
  const std::size_t nf = cm.number_of_faces();
  std::vector<std::pair<double, std::size_t> > order(nf);
  double total = 0;
  for(std::size_t f = 0; f < nf; ++f)
  {
    order[f] = std::make_pair(-face_energy_density(cm, f, cm.uv.data(), energy), f);
    total += cm.face_area[f] * -order[f].first;
  }
  total /= cm.total_area;
  if(!(total > bound)) return 0;
  std::sort(order.begin(), order.end());

  std::vector<int> corners(cm.number_of_uv_vertices(), 0);
  for(int u : cm.corner_uv) ++corners[u];
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL;
  for(std::size_t i = 0; i < cm.number_of_uv_vertices(); ++i)
  {
    x0 = (std::min)(x0, cm.uv[2 * i]);
    x1 = (std::max)(x1, cm.uv[2 * i]);
    y0 = (std::min)(y0, cm.uv[2 * i + 1]);
  }
  double longest = 0;
  for(std::size_t h = 0; h < cm.corner_vertex.size(); ++h) longest = (std::max)(longest, cm.edge_length(int(h)));
  const double gap = 0.25 * longest;
  // rows below the charts, each as high as its highest piece
  double x = x0, row_top = y0 - gap, row_height = 0;
  auto place = [&](double width, double height) -> std::pair<double, double>
  {
    if(x + width > x1 && x > x0) { x = x0; row_top -= row_height + gap; row_height = 0; }
    const std::pair<double, double> at(x, row_top - height);
    x += width + gap;
    row_height = (std::max)(row_height, height);
    return at;
  };
  auto new_uv_vertex = [&](int c)
  {
    const int u = cm.corner_uv[c];
    --corners[u];
    cm.corner_uv[c] = int(cm.number_of_uv_vertices());
    cm.uv_vertex.push_back(cm.uv_vertex[u]);
    cm.uv.push_back(cm.uv[2 * u]);
    cm.uv.push_back(cm.uv[2 * u + 1]);
    corners.push_back(1);
  };

  std::size_t detached = 0;
  std::vector<char> done(nf, 0);
  for(int pass = 0; pass < 2 && total > bound; ++pass)
    for(const auto& o : order)
    {
      const double density = -o.first;
      if(!(total > bound) || !(density > minimum)) break;
      const std::size_t f = o.second;
      if(done[f] || (pass == 0 && detaching_pinches(cm, f))) continue;
      done[f] = 1;
      const double* B = &cm.rest_inverse[4 * f];
      // rest frame Dm = B^-1 = [[l1, x2], [0, y2]]
      const double l1 = 1 / B[0], y2 = 1 / B[3], x2 = -B[2] * l1 * y2;
      const double local[3][2] = { { 0, 0 }, { l1, 0 }, { x2, y2 } };
      const double left = (std::min)(0., x2), width = (std::max)(l1, x2) - left;
      const std::pair<double, double> at = place(width, y2);
      for(int k = 0; k < 3; ++k)
      {
        const int c = int(3 * f) + k;
        if(corners[cm.corner_uv[c]] > 1) new_uv_vertex(c);
        const int u = cm.corner_uv[c];
        cm.uv[2 * u] = at.first - left + local[k][0];
        cm.uv[2 * u + 1] = at.second + local[k][1];
      }
      total += cm.face_area[f] * (minimum - density) / cm.total_area;
      ++detached;
    }

  // Charts that now share a UV vertex (they touch there): all but the
  // largest get their own copies of it, and move into the rows.
  std::vector<int> chart;
  const std::size_t n_charts = cm.compute_charts(chart);
  std::vector<std::size_t> size(n_charts, 0);
  for(std::size_t f = 0; f < nf; ++f) ++size[chart[f]];
  std::vector<int> owner(cm.number_of_uv_vertices(), -1);
  std::vector<char> moved(n_charts, 0);
  for(std::size_t c = 0; c < cm.corner_uv.size(); ++c)
  {
    const int u = cm.corner_uv[c], k = chart[c / 3];
    if(owner[u] < 0 || owner[u] == k) { owner[u] = k; continue; }
    const int keep = size[owner[u]] >= size[k] ? owner[u] : k;
    moved[keep == k ? owner[u] : k] = 1;
  }
  for(std::size_t k = 0; k < n_charts; ++k)
  {
    if(!moved[k]) continue;
    std::vector<int> map(cm.number_of_uv_vertices(), -1);
    double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
    for(std::size_t c = 0; c < cm.corner_uv.size(); ++c)
    {
      if(chart[c / 3] != int(k)) continue;
      const int u = cm.corner_uv[c];
      if(map[u] < 0)
      {
        new_uv_vertex(int(c));
        map[u] = cm.corner_uv[c];
      }
      else { --corners[u]; ++corners[map[u]]; cm.corner_uv[c] = map[u]; }
      for(int d = 0; d < 2; ++d)
      {
        lo[d] = (std::min)(lo[d], cm.uv[2 * u + d]);
        hi[d] = (std::max)(hi[d], cm.uv[2 * u + d]);
      }
    }
    const std::pair<double, double> at = place(hi[0] - lo[0], hi[1] - lo[1]);
    for(std::size_t u = 0; u < map.size(); ++u)
      if(map[u] >= 0)
      {
        cm.uv[2 * map[u]] += at.first - lo[0];
        cm.uv[2 * map[u] + 1] += at.second - lo[1];
      }
  }
  // UV vertices left without a corner: renumbered away
  std::vector<int> renumber(cm.number_of_uv_vertices(), -1);
  int n = 0;
  for(std::size_t u = 0; u < renumber.size(); ++u)
    if(corners[u] > 0)
    {
      renumber[u] = n;
      cm.uv[2 * n] = cm.uv[2 * u];
      cm.uv[2 * n + 1] = cm.uv[2 * u + 1];
      cm.uv_vertex[n] = cm.uv_vertex[u];
      ++n;
    }
  cm.uv.resize(2 * n);
  cm.uv_vertex.resize(n);
  for(int& u : cm.corner_uv) u = renumber[u];
  return detached;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DETACH_FACES_H
