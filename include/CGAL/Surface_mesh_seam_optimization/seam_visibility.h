// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Hidden seams: how visible each edge is (ambient occlusion by ray casting
// in CGAL's AABB tree, and concave creases), and seam costs from it, so that
// seams move to where a texture discontinuity shows least.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_VISIBILITY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_VISIBILITY_H

#include <CGAL/Surface_mesh_seam_optimization/parameters.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

namespace internal {

// `n` directions spread evenly over the unit sphere (a Fibonacci lattice):
// deterministic, no clustering at the poles.
inline std::vector<std::array<double, 3> > sphere_directions(std::size_t n)
{
  std::vector<std::array<double, 3> > d(n);
  const double golden = CGAL_PI * (3. - std::sqrt(5.));
  for(std::size_t i = 0; i < n; ++i)
  {
    const double z = 1. - (2. * double(i) + 1.) / double(n);
    const double r = std::sqrt((std::max)(0., 1. - z * z));
    d[i] = {{r * std::cos(golden * double(i)), r * std::sin(golden * double(i)), z}};
  }
  return d;
}

// The edges in increasing order of `key` (ties: in the order of edges(tm)).
template <typename TriangleMesh, typename EdgeKeyMap>
std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor>
edges_sorted_by(const TriangleMesh& tm, EdgeKeyMap key)
{
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  std::vector<std::pair<double, std::size_t> > order;
  std::vector<edge_descriptor> es;
  for(edge_descriptor e : edges(tm))
  {
    order.emplace_back(double(get(key, e)), es.size());
    es.push_back(e);
  }
  std::sort(order.begin(), order.end());
  std::vector<edge_descriptor> sorted;
  sorted.reserve(es.size());
  for(const auto& o : order) sorted.push_back(es[o.second]);
  return sorted;
}

// cost = ratio^q, q the rank of the edge's visibility in [0, 1]
template <typename TriangleMesh, typename EdgeVisibilityMap, typename EdgeCostMap>
void seam_costs_from_visibility_ranks(const TriangleMesh& tm, EdgeVisibilityMap visibility, EdgeCostMap cost,
                                      double ratio)
{
  const auto sorted = edges_sorted_by(tm, visibility);
  const double last = sorted.size() > 1 ? double(sorted.size() - 1) : 1.;
  for(std::size_t i = 0; i < sorted.size(); ++i)
    put(cost, sorted[i], std::pow(ratio, double(i) / last));
}

} // namespace internal

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Writes into `visibility` how visible each edge is, in [0, 1]: the mean
/// openness of its two vertices times a crease factor. A vertex's openness
/// is the share of the directions in front of it (a fixed, even set of
/// `number_of_rays` directions over the sphere, those with a positive dot
/// product with the vertex normal) along which a ray leaves the surface
/// without hitting it (ambient occlusion; rays cast in an `AABB_tree` of the
/// faces): 1 on a convex part, lower in crevices and between limbs. The
/// crease factor is 1 but on a concave (valley) edge, where it is
/// \f$ 1 - \theta / \pi \f$ for the angle \f$ \theta \f$ between the two face
/// normals: a discontinuity along a fold shows less than one across a flat
/// or convex part.
///
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam EdgeVisibilityMap a model of `WritablePropertyMap` with
///   `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `double` as value type
/// \param np `vertex_point_map` (as usual) and `number_of_rays` (default 64)
template <typename TriangleMesh, typename EdgeVisibilityMap,
          typename NamedParameters = parameters::Default_named_parameters>
void edge_visibility(const TriangleMesh& tm, EdgeVisibilityMap visibility,
                     const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::edge_descriptor edge_descriptor;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point_3;
  typedef typename Kernel_traits<Point_3>::Kernel K;
  typedef typename K::Vector_3 Vector_3;
  typedef CGAL::AABB_face_graph_triangle_primitive<TriangleMesh, VPM> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive> > Tree;

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const std::size_t rays = choose_parameter(get_parameter(np, internal_np::number_of_rays), std::size_t(64));
  if(faces(tm).first == faces(tm).second) return;

  Tree tree(faces(tm).first, faces(tm).second, tm, vpm);
  const auto box = tree.bbox();
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  // off the surface by a hair, so that a ray does not hit the faces it starts on
  const double offset = 1e-5 * diagonal;
  const std::vector<std::array<double, 3> > directions = internal::sphere_directions((std::max)(rays, std::size_t(1)));

  auto openness = get(CGAL::dynamic_vertex_property_t<double>(), tm);
  for(vertex_descriptor v : vertices(tm))
  {
    double open = 1.;
    if(halfedge(v, tm) != GT::null_halfedge())
    {
      const Vector_3 n = PMP::compute_vertex_normal(v, tm, CGAL::parameters::vertex_point_map(vpm));
      const Point_3 origin = get(vpm, v) + offset * n;
      std::size_t front = 0, escaped = 0;
      for(const auto& d : directions)
      {
        const Vector_3 dir(d[0], d[1], d[2]);
        if(!(n * dir > 0)) continue;
        ++front;
        if(!tree.do_intersect(typename K::Ray_3(origin, dir))) ++escaped;
      }
      open = front == 0 ? 1. : double(escaped) / double(front);
    }
    put(openness, v, open);
  }

  for(edge_descriptor e : edges(tm))
  {
    const halfedge_descriptor h = halfedge(e, tm), o = opposite(h, tm);
    double crease = 1.;
    if(!is_border(h, tm) && !is_border(o, tm))
    {
      const Vector_3 n1 = PMP::compute_face_normal(face(h, tm), tm, CGAL::parameters::vertex_point_map(vpm));
      const Vector_3 n2 = PMP::compute_face_normal(face(o, tm), tm, CGAL::parameters::vertex_point_map(vpm));
      // valley: the far corner of the second face is on the front side of the first
      const Vector_3 across = get(vpm, target(next(o, tm), tm)) - get(vpm, source(h, tm));
      if(across * n1 > 0)
        crease = 1. - std::acos((std::max)(-1., (std::min)(1., double(n1 * n2)))) / CGAL_PI;
    }
    put(visibility, e,
        0.5 * (get(openness, source(h, tm)) + get(openness, target(h, tm))) * crease);
  }
}

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Seam costs that hide seams: writes into `cost` the value
/// \f$ r^{q_e} \f$, where \f$ q_e \in [0, 1] \f$ is the rank of the edge's
/// `edge_visibility()` among all edges (0 the least visible, 1 the most) and
/// \f$ r \f$ is `visibility_cost_ratio` (default 4): the most visible edges
/// cost \f$ r \f$ times the least visible ones, which bounds how much longer
/// a hidden route may be than a visible one. Ranks rather than raw values
/// make the costs the same whatever the mesh's overall exposure. Pass `cost`
/// as `seam_cost_map` to `optimize_seams()`.
///
/// \tparam EdgeCostMap a model of `WritablePropertyMap` with
///   `boost::graph_traits<TriangleMesh>::%edge_descriptor` as key type and `double` as value type
/// \param np `vertex_point_map`, `number_of_rays` (see `edge_visibility()`) and
///   `visibility_cost_ratio` (>= 1; default 4)
template <typename TriangleMesh, typename EdgeCostMap,
          typename NamedParameters = parameters::Default_named_parameters>
void visibility_seam_costs(const TriangleMesh& tm, EdgeCostMap cost,
                           const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const double ratio = (std::max)(1., double(choose_parameter(get_parameter(np, internal_np::visibility_cost_ratio), 4.)));

  auto visibility = get(CGAL::dynamic_edge_property_t<double>(), tm);
  edge_visibility(tm, visibility, np);
  internal::seam_costs_from_visibility_ranks(tm, visibility, cost, ratio);
}

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// The share of the seam length (3D) that lies on the most visible
/// `fraction` of the edges by `visibility` (e.g. from `edge_visibility()`):
/// the figure that hidden seams lower. 0 without seams.
template <typename TriangleMesh, typename EdgeVisibilityMap, typename EdgeIsSeamMap,
          typename NamedParameters = parameters::Default_named_parameters>
double seam_share_on_most_visible_edges(const TriangleMesh& tm, EdgeVisibilityMap visibility, EdgeIsSeamMap seams,
                                        double fraction = 0.25,
                                        const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  // most visible first (ties: in the order of edges(tm))
  const auto sorted = internal::edges_sorted_by(
    tm, boost::make_function_property_map<edge_descriptor>([&](edge_descriptor e) { return -double(get(visibility, e)); }));
  const std::size_t top = std::size_t(std::ceil(fraction * double(sorted.size())));
  double all = 0, visible = 0;
  for(std::size_t i = 0; i < sorted.size(); ++i)
  {
    const edge_descriptor e = sorted[i];
    if(!get(seams, e)) continue;
    const double l = std::sqrt(CGAL::to_double(
      CGAL::squared_distance(get(vpm, source(e, tm)), get(vpm, target(e, tm)))));
    all += l;
    if(i < top) visible += l;
  }
  return all > 0 ? visible / all : 0.;
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
