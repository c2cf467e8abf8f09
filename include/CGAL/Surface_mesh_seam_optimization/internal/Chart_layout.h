// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_CHART_LAYOUT_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_CHART_LAYOUT_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Union_find.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Component of each UV vertex in the UV mesh (faces joined through shared UV
// vertices, so charts touching at a vertex are one; -1 for a UV vertex no
// corner uses); returns the count.
inline std::size_t uv_components(const Cut_mesh& cm, std::vector<int>& component)
{
  const std::size_t nu = cm.number_of_uv_vertices();
  Union_find uf(nu);
  std::vector<char> used(nu, 0);
  for(std::size_t c = 0; c + 2 < cm.corner_uv.size(); c += 3)
  {
    uf.unite(cm.corner_uv[c], cm.corner_uv[c + 1]);
    uf.unite(cm.corner_uv[c], cm.corner_uv[c + 2]);
    used[cm.corner_uv[c]] = used[cm.corner_uv[c + 1]] = used[cm.corner_uv[c + 2]] = 1;
  }
  std::vector<int> id(nu, -1);
  component.assign(nu, -1);
  int n = 0;
  for(std::size_t u = 0; u < nu; ++u)
  {
    if(!used[u]) continue;
    const int r = uf.find(int(u));
    if(id[r] < 0) id[r] = n++;
    component[u] = id[r];
  }
  return std::size_t(n);
}

// Where the lower-left corner of each box [lo[k], hi[k]] goes on a grid of
// ceil(sqrt(n)) columns filled row by row, in order: a column as wide as its
// widest box, a row as high as its highest, gaps of 5% of the largest extent.
// The initial map lays out its charts with it and lay_out_uv_components() the
// UV components, so the two give the same grid.
inline std::vector<std::array<double, 2> > grid_layout(const std::vector<std::array<double, 2> >& lo,
                                                       const std::vector<std::array<double, 2> >& hi)
{
  const std::size_t n = lo.size();
  std::vector<std::array<double, 2> > corner(n);
  if(n == 0) return corner;
  const std::size_t n_cols = std::size_t(std::ceil(std::sqrt(double(n))));
  const std::size_t n_rows = (n + n_cols - 1) / n_cols;
  std::vector<double> col_w(n_cols, 0), row_h(n_rows, 0);
  double largest = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    const double w = hi[k][0] - lo[k][0], h = hi[k][1] - lo[k][1];
    col_w[k % n_cols] = (std::max)(col_w[k % n_cols], w);
    row_h[k / n_cols] = (std::max)(row_h[k / n_cols], h);
    largest = (std::max)({ largest, w, h });
  }
  const double gap = 0.05 * largest;
  std::vector<double> col_x(n_cols, 0), row_y(n_rows, 0);
  for(std::size_t i = 1; i < n_cols; ++i) col_x[i] = col_x[i - 1] + col_w[i - 1] + gap;
  for(std::size_t i = 1; i < n_rows; ++i) row_y[i] = row_y[i - 1] + row_h[i - 1] + gap;
  for(std::size_t k = 0; k < n; ++k) corner[k] = std::array<double, 2>{{ col_x[k % n_cols], row_y[k / n_cols] }};
  return corner;
}

// Translates the UV components onto the grid of grid_layout(), in the order
// of their first UV vertex. The energies do not see where a component lies,
// so this moves nothing but overlaps between components. Returns the number
// of components.
inline std::size_t lay_out_uv_components(Cut_mesh& cm)
{
  std::vector<int> component;
  const std::size_t n = uv_components(cm, component);
  if(n < 2) return n;
  std::vector<std::array<double, 2> > lo(n, std::array<double, 2>{{ HUGE_VAL, HUGE_VAL }}),
                                      hi(n, std::array<double, 2>{{ -HUGE_VAL, -HUGE_VAL }});
  for(std::size_t u = 0; u < component.size(); ++u)
    for(int d = 0; d < 2 && component[u] >= 0; ++d)
    {
      lo[component[u]][d] = (std::min)(lo[component[u]][d], cm.uv[2 * u + d]);
      hi[component[u]][d] = (std::max)(hi[component[u]][d], cm.uv[2 * u + d]);
    }
  const std::vector<std::array<double, 2> > corner = grid_layout(lo, hi);
  for(std::size_t u = 0; u < component.size(); ++u)
  {
    if(component[u] < 0) continue;
    const std::size_t k = std::size_t(component[u]);
    cm.uv[2 * u] += corner[k][0] - lo[k][0];
    cm.uv[2 * u + 1] += corner[k][1] - lo[k][1];
  }
  return n;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
