// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Regional seam preferences: the per-corner seam cost factors of the core mesh
// read from `seam_cost_map` (its deprecated alias `edge_seam_weight_map`) and
// `vertex_seam_cost_map`.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SEAM_COSTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SEAM_COSTS_H

#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

inline bool is_valid_seam_cost(double w) { return w >= 0 && std::isfinite(w); }

// `cost[h]` for every corner halfedge h of the copy: the edge's factor times
// the mean of its two vertices' factors (1 where a map is not given). Returns
// false, with `message`, at the first negative or non-finite factor.
template <typename TriangleMesh, typename NamedParameters>
bool read_seam_costs(const TriangleMesh& tm, const Face_graph_copy<TriangleMesh>& copy,
                     const NamedParameters& np, std::vector<double>& cost, std::string& message)
{
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  constexpr bool has_edge_map = !is_default_parameter<NamedParameters, internal_np::seam_cost_map_t>::value;
  constexpr bool has_alias = !is_default_parameter<NamedParameters, internal_np::edge_seam_weight_map_t>::value;
  constexpr bool has_vertex_map =
    !is_default_parameter<NamedParameters, internal_np::vertex_seam_cost_map_t>::value;

  cost.assign(copy.corner_halfedge.size(), 1.);
  for(std::size_t h = 0; h < cost.size(); ++h)
  {
    const auto th = copy.corner_halfedge[h];
    double w = 1.;
    if constexpr(has_edge_map)
      w = double(get(get_parameter(np, internal_np::seam_cost_map), edge(th, tm)));
    else if constexpr(has_alias)
      w = double(get(get_parameter(np, internal_np::edge_seam_weight_map), edge(th, tm)));
    if(!is_valid_seam_cost(w))
    {
      message = std::string(has_edge_map ? "seam_cost_map" : "edge_seam_weight_map") +
                " has a negative or non-finite value";
      return false;
    }
    if constexpr(has_vertex_map)
    {
      const auto vmap = get_parameter(np, internal_np::vertex_seam_cost_map);
      const double a = double(get(vmap, source(th, tm))), b = double(get(vmap, target(th, tm)));
      if(!is_valid_seam_cost(a) || !is_valid_seam_cost(b))
      {
        message = "vertex_seam_cost_map has a negative or non-finite value";
        return false;
      }
      w *= 0.5 * (a + b);
    }
    cost[h] = w;
  }
  return true;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
