// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The EBCuts baseline of the OptCuts paper's comparison (extremity-based
// cuts, after Geometry Images, Gu et al. 2002): minimize the distortion with
// the seams fixed; while the bound is not met, cut the shortest path from the
// vertex of largest distortion to the nearest seam or border, and again.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_EXTREMITY_CUTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_EXTREMITY_CUTS_H

#include <CGAL/Surface_mesh_seam_optimization/Optimization_result.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Shortest_paths.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// The next cut: the shortest path (3D lengths) from the vertex whose incident
// faces have the largest area-weighted mean `density` to the nearest vertex
// on a seam or the border; its edges go into `seams`. False if no vertex is
// off the seams and the border.
template <typename TriangleMesh, typename VPM, typename SeamMap, typename FaceDensity>
bool cut_from_the_worst_vertex(const TriangleMesh& tm, VPM vpm, SeamMap seams, const FaceDensity& density)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  auto index = get(CGAL::dynamic_vertex_property_t<int>(), tm);
  std::vector<vertex_descriptor> vs;
  for(vertex_descriptor v : vertices(tm)) { put(index, v, int(vs.size())); vs.push_back(v); }
  const std::size_t n = vs.size();

  // each face's (area, density) once, though three of its corners use it
  auto face_density = get(CGAL::dynamic_face_property_t<std::pair<double, double> >(), tm);
  for(auto f : faces(tm)) put(face_density, f, density(f));
  std::vector<char> on_boundary(n, 0);
  std::vector<double> sum(n, 0.), area(n, 0.);
  for(halfedge_descriptor h : halfedges(tm))
  {
    const int t = get(index, target(h, tm));
    if(is_border_edge(h, tm) || get(seams, edge(h, tm))) on_boundary[t] = 1;
    if(is_border(h, tm)) continue;
    const std::pair<double, double> d = get(face_density, face(h, tm));
    sum[t] += d.first * d.second;
    area[t] += d.first;
  }
  int worst = -1;
  double worst_value = -1;
  for(std::size_t i = 0; i < n; ++i)
    if(!on_boundary[i] && area[i] > 0 && sum[i] / area[i] > worst_value)
    {
      worst_value = sum[i] / area[i];
      worst = int(i);
    }
  if(worst < 0) return false;

  // shortest paths from the worst vertex; the cut ends at the nearest seam or
  // border vertex (ties: the smallest index), whose path meets no other
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> pred(n, -1);
  dijkstra(std::vector<int>(1, worst), dist,
           [&](int u, const auto& visit) {
             for(halfedge_descriptor h : halfedges_around_source(vs[u], tm))
               visit(get(index, target(h, tm)),
                     std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, vs[u]), get(vpm, target(h, tm))))), u);
           },
           [&](int u, int w, int) { pred[w] = u; });
  int reached = -1;
  for(std::size_t i = 0; i < n; ++i)
    if(on_boundary[i] && dist[i] < std::numeric_limits<double>::infinity() && (reached < 0 || dist[i] < dist[reached]))
      reached = int(i);
  if(reached < 0) return false;
  for(int v = reached; v != worst; v = pred[v])
    put(seams, edge(halfedge(vs[pred[v]], vs[v], tm).first, tm), true);
  return true;
}

// (area, energy density) of a face of `tm` under the per-corner map `uv`:
// what cut_from_the_worst_vertex() ranks vertices by.
template <typename TriangleMesh, typename VPM, typename UVMap, typename Energy>
auto face_area_and_density(const TriangleMesh& tm, VPM vpm, UVMap uv, const Energy& energy)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  return [&tm, vpm, uv, &energy](face_descriptor f) {
    const halfedge_descriptor h0 = halfedge(f, tm), h1 = next(h0, tm), h2 = next(h1, tm);
    const auto q0 = get(vpm, target(h0, tm)), q1 = get(vpm, target(h1, tm)), q2 = get(vpm, target(h2, tm));
    const auto p0 = get(uv, h0), p1 = get(uv, h1), p2 = get(uv, h2);
    const auto e1 = q1 - q0, e2 = q2 - q0;
    const double l1 = std::sqrt(CGAL::to_double(e1.squared_length()));
    const double x2 = CGAL::to_double(e1 * e2) / l1;
    const double y2 = std::sqrt((std::max)(0., CGAL::to_double(e2.squared_length()) - x2 * x2));
    Eigen::Matrix2d J;
    const double d1x = CGAL::to_double(p1.x() - p0.x()), d1y = CGAL::to_double(p1.y() - p0.y());
    const double d2x = CGAL::to_double(p2.x() - p0.x()), d2y = CGAL::to_double(p2.y() - p0.y());
    J(0, 0) = d1x / l1;
    J(1, 0) = d1y / l1;
    J(0, 1) = (d2x - J(0, 0) * x2) / y2;
    J(1, 1) = (d2y - J(1, 0) * x2) / y2;
    return std::make_pair(0.5 * l1 * y2, energy.value(J));
  };
}

// EBCuts: the distortion-only descent (minimize_distortion(), no scaffold)
// between cuts; the bound, energy, vertex_point_map, number_of_iterations
// (in total) and time_limit of `np` apply. Writes `uvmap` and `seams` (every
// edge) only with a result.
template <typename TriangleMesh, typename UVMap, typename SeamMap, typename NamedParameters, typename Energy>
Optimization_result extremity_cuts(const TriangleMesh& tm, UVMap uvmap, SeamMap seams, const NamedParameters& np,
                                   const Energy& energy, double bound)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  CGAL::Real_timer timer;
  timer.start();
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const std::size_t max_iterations = number_of_iterations_parameter(np, default_number_of_iterations);
  double time_limit = std::numeric_limits<double>::infinity();
  read_time_limit(np, time_limit);

  typedef typename boost::property_traits<UVMap>::value_type Point_2;
  auto uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), tm);
  auto cut = get(CGAL::dynamic_edge_property_t<bool>(), tm);
  for(auto e : edges(tm)) put(cut, e, false);

  const auto density = face_area_and_density(tm, vpm, uv, energy);

  Optimization_result result, r;
  std::size_t iterations = 0, cuts = 0;
  for(;;)
  {
    const double left = time_limit - timer.time();
    r = minimize_distortion(tm, uv,
                            parameters::energy(energy)
                              .vertex_point_map(vpm)
                              .edge_is_seam_map(cut)
                              .distortion_bound(bound)
                              .number_of_iterations(max_iterations > iterations ? max_iterations - iterations : 1)
                              .time_limit(left > 0 ? left : 1e-9));
    if(!r.has_result()) return cuts == 0 ? r : result; // (the previous map is written)
    iterations += r.iterations;
    r.iterations = iterations;
    r.topology_operations = cuts;
    result = r;
    for(auto h : halfedges(tm)) if(!is_border(h, tm)) put(uvmap, h, get(uv, h));
    for(auto e : edges(tm)) put(seams, e, get(cut, e));
    if(r.bound_met) break;
    if(r.status != OK || iterations >= max_iterations || !(timer.time() < time_limit)) break;
    if(!cut_from_the_worst_vertex(tm, vpm, cut, density)) break;
    ++cuts;
  }
  if(result.status == OK && !result.bound_met) result.status = WARNING_BOUND_NOT_MET;
  result.seconds = timer.time();
  return result;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
