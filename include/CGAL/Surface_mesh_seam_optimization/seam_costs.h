// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Regional seam preferences from a painted region of vertices, for
// `vertex_seam_cost_map`.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_COSTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_COSTS_H

#include <boost/graph/graph_traits.hpp>

#include <CGAL/boost/graph/iterator.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// The paper's regional seam preference: writes into `vcm` a seam cost of 1
/// for every vertex and `region_cost` for the vertices of `region`, then
/// replaces each value by the mean over the vertex and its one-ring, so that
/// the cost changes over a band of edges rather than at one edge. Pass `vcm`
/// as `vertex_seam_cost_map` to `optimize_seams()`: a cost above 1 (the paper
/// uses 100) keeps seams out of the region, below 1 draws them in.
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam VertexRange a range of `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
/// \tparam VertexCostMap a model of `ReadWritePropertyMap` with the vertex descriptor as key type and
///   `double` as value type
/// \pre `region_cost >= 0`
template <typename TriangleMesh, typename VertexRange, typename VertexCostMap>
void region_seam_costs(const TriangleMesh& tm, const VertexRange& region, double region_cost, VertexCostMap vcm)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  for(vertex_descriptor v : vertices(tm)) put(vcm, v, 1.);
  for(vertex_descriptor v : region) put(vcm, v, region_cost);

  // smoothed values in the order of vertices(tm), written back after
  std::vector<double> smoothed;
  smoothed.reserve(num_vertices(tm));
  for(vertex_descriptor v : vertices(tm))
  {
    double sum = get(vcm, v);
    std::size_t n = 1;
    if(halfedge(v, tm) != boost::graph_traits<TriangleMesh>::null_halfedge())
      for(halfedge_descriptor h : halfedges_around_target(halfedge(v, tm), tm))
      {
        sum += get(vcm, source(h, tm));
        ++n;
      }
    smoothed.push_back(sum / double(n));
  }
  std::size_t i = 0;
  for(vertex_descriptor v : vertices(tm)) put(vcm, v, smoothed[i++]);
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
