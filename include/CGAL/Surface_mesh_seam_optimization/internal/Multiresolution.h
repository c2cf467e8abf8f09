// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Dense meshes through a proxy. The mesh is simplified by edge collapses that
// place each collapsed edge's vertex at one of its endpoints, so that every
// proxy vertex is an input vertex. The seams optimized on the proxy are carried
// to the input along shortest paths between the input vertices of each proxy
// seam edge that do not touch each other, and the proxy's UV map with the
// chart borders on the proxy's and the rest interpolated; the input's
// optimization starts from there, where only local work is left.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_MULTIRESOLUTION_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_MULTIRESOLUTION_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Shortest_paths.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Untangle.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Edge_collapse_visitor_base.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <boost/optional.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

typedef CGAL::Simple_cartesian<double> Proxy_kernel;
typedef CGAL::Surface_mesh<Proxy_kernel::Point_3> Proxy_mesh;

struct Proxy
{
  Proxy_mesh mesh;
  std::vector<int> full_vertex;  // the input (core) vertex of each proxy vertex
  std::vector<int> proxy_vertex; // the proxy vertex of each input vertex, -1 for none
};

// Keep a border endpoint where there is one: the proxy's border then runs
// through input border vertices.
template <typename Profile>
bool placed_at_v0(const Profile& profile)
{
  return bool(CGAL::is_border(profile.v0(), profile.surface_mesh())) &&
         !bool(CGAL::is_border(profile.v1(), profile.surface_mesh()));
}

struct Endpoint_placement
{
  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile) const
  {
    return placed_at_v0(profile) ? profile.p0() : profile.p1();
  }
};

// 4 sqrt(3) area / (sum of squared edge lengths): 1 for an equilateral
// triangle, 0 for a degenerate one; `n` gets the unnormalized normal.
inline double triangle_quality(const Proxy_kernel::Point_3& a, const Proxy_kernel::Point_3& b,
                               const Proxy_kernel::Point_3& c, Proxy_kernel::Vector_3& n)
{
  n = CGAL::cross_product(b - a, c - a);
  const double l2 = (b - a).squared_length() + (c - b).squared_length() + (a - c).squared_length();
  return l2 > 0 ? 2 * std::sqrt(3.) * std::sqrt(n.squared_length()) / l2 : 0.;
}

// A collapse may neither turn a triangle over (normal change beyond 90
// degrees) nor leave one worse shaped than the worst it replaces and than a
// fixed floor: the proxy's triangles must pass the input validation.
struct Shape_preserving_filter
{
  double least_quality = 0.05;

  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile,
                                                      boost::optional<typename Profile::Point> op) const
  {
    if(!op) return op;
    const auto& tm = profile.surface_mesh();
    const auto v0 = profile.v0(), v1 = profile.v1();
    const typename Profile::Point& q = *op;
    double worst_before = 1, worst_after = 1;
    for(const auto v : { v0, v1 })
      for(const auto h : CGAL::halfedges_around_target(v, tm))
      {
        if(CGAL::is_border(h, tm)) continue;
        std::array<typename Profile::vertex_descriptor, 3> w = { target(h, tm), target(next(h, tm), tm),
                                                                 target(next(next(h, tm), tm), tm) };
        bool both = false;
        for(int i = 0; i < 3; ++i) if(w[i] == (v == v0 ? v1 : v0)) both = true;
        if(both) continue; // removed by the collapse
        std::array<Proxy_kernel::Point_3, 3> p, r;
        for(int i = 0; i < 3; ++i)
        {
          p[i] = tm.point(w[i]);
          r[i] = (w[i] == v) ? q : p[i];
        }
        Proxy_kernel::Vector_3 n_before, n_after;
        worst_before = (std::min)(worst_before, triangle_quality(p[0], p[1], p[2], n_before));
        worst_after = (std::min)(worst_after, triangle_quality(r[0], r[1], r[2], n_after));
        if(!(n_before * n_after > 0)) return boost::none;
      }
    if(worst_after < (std::min)(worst_before, least_quality)) return boost::none;
    return op;
  }
};

struct Track_full_vertex
  : CGAL::Surface_mesh_simplification::Edge_collapse_visitor_base<Proxy_mesh>
{
  Proxy_mesh::Property_map<Proxy_mesh::Vertex_index, int> full;
  int pending = -1;

  template <typename Profile, typename OptionalPoint>
  void OnCollapsing(const Profile& profile, const OptionalPoint& placement)
  {
    (void)placement; // Endpoint_placement's choice, made again
    pending = placed_at_v0(profile) ? full[profile.v0()] : full[profile.v1()];
  }
  template <typename Profile, typename Vertex>
  void OnCollapsed(const Profile&, const Vertex& v) { full[v] = pending; }
};

// The proxy of about `target_faces` faces (fewer collapses where they would
// spoil the shape). False if the input could not be copied as a manifold mesh.
inline bool build_proxy(const Cut_mesh& full, std::size_t target_faces, Proxy& proxy)
{
  namespace SMS = CGAL::Surface_mesh_simplification;
  Proxy_mesh& m = proxy.mesh;
  m.clear();
  Track_full_vertex visitor;
  visitor.full = m.add_property_map<Proxy_mesh::Vertex_index, int>("v:full_vertex", -1).first;
  const std::size_t nv = full.number_of_vertices(), nf = full.number_of_faces();
  std::vector<Proxy_mesh::Vertex_index> vertex(nv);
  for(std::size_t v = 0; v < nv; ++v)
  {
    vertex[v] = m.add_vertex(Proxy_kernel::Point_3(full.points[3*v], full.points[3*v+1], full.points[3*v+2]));
    visitor.full[vertex[v]] = int(v);
  }
  for(std::size_t f = 0; f < nf; ++f)
    if(m.add_face(vertex[full.corner_vertex[3*f]], vertex[full.corner_vertex[3*f+1]],
                  vertex[full.corner_vertex[3*f+2]]) == Proxy_mesh::null_face())
      return false;
  // edges ~ 3/2 faces on a closed surface, more with borders: scale by the input's ratio
  const double edges_per_face = double(m.number_of_edges()) / double(nf);
  SMS::Count_stop_predicate<Proxy_mesh> stop(std::size_t(edges_per_face * double(target_faces)));
  SMS::edge_collapse(m, stop,
                     CGAL::parameters::get_cost(SMS::Edge_length_cost<Proxy_mesh>())
                       .get_placement(Endpoint_placement())
                       .filter(Shape_preserving_filter())
                       .visitor(visitor));
  m.collect_garbage();
  proxy.full_vertex.assign(m.number_of_vertices(), -1);
  proxy.proxy_vertex.assign(nv, -1);
  for(const auto v : m.vertices())
  {
    proxy.full_vertex[v.idx()] = visitor.full[v];
    proxy.proxy_vertex[visitor.full[v]] = int(v.idx());
  }
  return true;
}

// Where an input halfedge on a chart border lies in the proxy: along the
// proxy halfedge `proxy_halfedge` (whose face is on its side), its source and
// target at these fractions of it (by arc length).
struct Carried_side
{
  int proxy_halfedge = -1;
  double t_source = 0, t_target = 0;
};

// Per input halfedge (both sides): the proxy's seam edges carried to the
// input, each along the shortest input path between the input vertices of
// its ends that keeps off the paths found before, the input border and the
// other proxy seam vertices (the plain shortest path where there is none);
// `side` gets where each halfedge of these paths and of the input border
// lies in the proxy.
template <typename ProxySeamMap>
void transfer_seams(const Proxy& proxy, ProxySeamMap proxy_seam, const Cut_mesh& full, std::vector<char>& seam,
                    std::vector<Carried_side>& side)
{
  const Proxy_mesh& m = proxy.mesh;
  const std::size_t nv = full.number_of_vertices(), nh = full.corner_vertex.size();
  auto source_of = [&](int h) { return full.corner_vertex[Cut_mesh::prev(h)]; };
  // vertex -> (neighbour, halfedge), both directions of every edge
  std::vector<int> start(nv + 1, 0), arc_to, arc_halfedge;
  auto for_each_edge = [&](auto&& f) {
    for(std::size_t h = 0; h < nh; ++h)
    {
      const int a = source_of(int(h)), b = full.corner_vertex[h];
      f(a, b, int(h));
      if(full.opposite[h] < 0) f(b, a, int(h));
    }
  };
  for_each_edge([&](int a, int, int) { ++start[a + 1]; });
  for(std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  arc_to.resize(start[nv]);
  arc_halfedge.resize(start[nv]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for_each_edge([&](int a, int b, int h) { arc_to[fill[a]] = b; arc_halfedge[fill[a]++] = h; });

  seam.assign(nh, 0);
  side.assign(nh, Carried_side());
  // h on the proxy halfedge hp, from fraction ts to tt
  auto set_side = [&](int h, Proxy_mesh::Halfedge_index hp, double ts, double tt) {
    if(h < 0 || side[h].proxy_halfedge >= 0 || m.is_border(hp)) return;
    side[h].proxy_halfedge = int(hp.idx());
    side[h].t_source = ts;
    side[h].t_target = tt;
  };
  // Paths may not touch each other, the input border or a proxy seam vertex
  // but at their own ends: two paths that share a stretch would pinch the
  // chart between them (a branch where the proxy has none).
  std::vector<char> blocked(nv, 0);
  std::vector<Proxy_mesh::Edge_index> seam_edges;
  for(const auto e : m.edges())
    if(get(proxy_seam, e))
    {
      seam_edges.push_back(e);
      blocked[proxy.full_vertex[m.vertex(e, 0).idx()]] = blocked[proxy.full_vertex[m.vertex(e, 1).idx()]] = 1;
    }
  for(std::size_t h = 0; h < nh; ++h)
    if(full.opposite[h] < 0) blocked[full.corner_vertex[h]] = blocked[source_of(int(h))] = 1;
  // short edges first: they have the fewest ways around what is blocked
  auto chord2 = [&](Proxy_mesh::Edge_index e) {
    return CGAL::squared_distance(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1)));
  };
  std::stable_sort(seam_edges.begin(), seam_edges.end(),
                   [&](auto x, auto y) { return chord2(x) < chord2(y); });

  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> dist(nv, inf);
  std::vector<int> reached_by(nv, -1), touched;
  for(const auto e : seam_edges)
  {
    const auto hp = m.halfedge(e), op = m.opposite(hp);
    const int a = proxy.full_vertex[m.source(hp).idx()];
    const int b = proxy.full_vertex[m.target(hp).idx()];
    // (a path blocked everywhere takes the shortest way regardless)
    for(const bool avoid : {true, false})
    {
      for(int v : touched) { dist[v] = inf; reached_by[v] = -1; }
      touched.assign(1, a);
      dijkstra(std::vector<int>(1, a), dist,
               [&](int u, const auto& visit) {
                 for(int k = start[u]; k < start[u + 1]; ++k)
                   if(!avoid || !blocked[arc_to[k]] || arc_to[k] == b)
                     visit(arc_to[k], full.edge_length(arc_halfedge[k]), k);
               },
               [&](int, int w, int k) { reached_by[w] = k; touched.push_back(w); },
               [&](int u) { return u == b; });
      if(dist[b] < inf) break;
    }
    const double length = dist[b];
    if(length < inf && length > 0)
      for(int v = b; v != a;)
      {
        blocked[v] = 1;
        const int h = arc_halfedge[reached_by[v]];
        const int o = full.opposite[h];
        seam[h] = 1;
        if(o >= 0) seam[o] = 1;
        // faces are on the left: a halfedge running along a -> b is on the
        // side of hp's face, one running against it on the side of op's
        const bool along = full.corner_vertex[h] == v;
        const int u = along ? source_of(h) : full.corner_vertex[h];
        const double tu = dist[u] / length, tv = dist[v] / length;
        if(along) { set_side(h, hp, tu, tv); set_side(o, op, 1 - tv, 1 - tu); }
        else { set_side(h, op, 1 - tv, 1 - tu); set_side(o, hp, tu, tv); }
        v = u;
      }
  }
  for(int v : touched) { dist[v] = inf; reached_by[v] = -1; }

  // the input border: chains between consecutive proxy vertices, along the
  // proxy border halfedge between them (same orientation: faces on the left)
  const std::vector<int>& proxy_vertex = proxy.proxy_vertex;
  std::vector<int> border_out(nv, -1);
  for(std::size_t h = 0; h < nh; ++h)
    if(full.opposite[h] < 0) border_out[source_of(int(h))] = int(h);
  std::vector<int> chain;
  for(std::size_t h0 = 0; h0 < nh; ++h0)
  {
    if(full.opposite[h0] >= 0 || proxy_vertex[source_of(int(h0))] < 0) continue;
    chain.clear();
    double length = 0;
    int h = int(h0);
    for(std::size_t steps = 0; steps < nh; ++steps)
    {
      chain.push_back(h);
      length += full.edge_length(h);
      if(proxy_vertex[full.corner_vertex[h]] >= 0 || border_out[full.corner_vertex[h]] < 0) break;
      h = border_out[full.corner_vertex[h]];
    }
    const int b = full.corner_vertex[chain.back()];
    if(proxy_vertex[b] < 0 || !(length > 0)) continue;
    const auto found = CGAL::halfedge(Proxy_mesh::Vertex_index(proxy_vertex[source_of(int(h0))]),
                                      Proxy_mesh::Vertex_index(proxy_vertex[b]), m);
    if(!found.second) continue;
    double along = 0;
    for(int g : chain)
    {
      const double l = full.edge_length(g);
      set_side(g, found.first, along / length, (along + l) / length);
      along += l;
    }
  }
}

// UVs of the UV vertices not `fixed` (0) as the harmonic interpolation of the
// fixed ones, with mean value weights (Floater), which reproduce a linear map
// on a planar neighbourhood. False if the system could not be solved.
inline bool harmonic_interpolation(Cut_mesh& full, const std::vector<char>& fixed)
{
  const std::size_t nu = full.number_of_uv_vertices(), nc = full.corner_uv.size();
  std::vector<int> index(nu, -1);
  int n = 0;
  for(std::size_t u = 0; u < nu; ++u) if(!fixed[u]) index[u] = n++;
  if(n == 0) return true;
  std::vector<Eigen::Triplet<double> > triplets;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
  for(std::size_t c = 0; c < nc; ++c)
  {
    const int i = index[full.corner_uv[c]];
    if(i < 0) continue;
    // tan(theta/2) / |x_i - x_j| per face around vertex i
    const int cj = Cut_mesh::next(int(c)), ck = Cut_mesh::prev(int(c));
    const double* x = &full.points[3 * full.corner_vertex[c]];
    const double* xj = &full.points[3 * full.corner_vertex[cj]];
    const double* xk = &full.points[3 * full.corner_vertex[ck]];
    double dj[3], dk[3];
    for(int t = 0; t < 3; ++t) { dj[t] = xj[t] - x[t]; dk[t] = xk[t] - x[t]; }
    const double lj = std::sqrt(dj[0]*dj[0] + dj[1]*dj[1] + dj[2]*dj[2]);
    const double lk = std::sqrt(dk[0]*dk[0] + dk[1]*dk[1] + dk[2]*dk[2]);
    const double cosine = (dj[0]*dk[0] + dj[1]*dk[1] + dj[2]*dk[2]) / (lj * lk);
    const double half_tan = std::sqrt((std::max)(0., 1. - cosine) / (std::max)(1e-300, 1. + cosine));
    for(const auto& jl : { std::make_pair(full.corner_uv[cj], lj), std::make_pair(full.corner_uv[ck], lk) })
    {
      const double w = half_tan / jl.second;
      triplets.emplace_back(i, i, w);
      const int j = index[jl.first];
      if(j >= 0) triplets.emplace_back(i, j, -w);
      else { rhs(i, 0) += w * full.uv[2*jl.first]; rhs(i, 1) += w * full.uv[2*jl.first+1]; }
    }
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(triplets.begin(), triplets.end());
  L.makeCompressed();
  Eigen::SparseLU<Eigen::SparseMatrix<double> > solver;
  solver.compute(L);
  if(solver.info() != Eigen::Success) return false;
  const Eigen::MatrixXd x = solver.solve(rhs);
  if(solver.info() != Eigen::Success || !x.allFinite()) return false;
  for(std::size_t u = 0; u < nu; ++u)
    if(index[u] >= 0) { full.uv[2*u] = x(index[u], 0); full.uv[2*u+1] = x(index[u], 1); }
  return true;
}

// The UVs of `full` (UV vertices labelled by its seams) from the proxy's map.
// Each chart's border is put on the proxy's chart border (`side`): a border
// vertex between two proxy vertices at its fraction of arc length on the UV
// segment between theirs, so that the charts' borders are the proxy's, which
// do not overlap. An input vertex that is a proxy vertex inside a chart gets
// its UV there. The other UV vertices are the harmonic interpolation of these
// (mean value weights, which reproduce a linear map).
template <typename ProxyUVMap>
void transfer_uv_map(const Proxy& proxy, ProxyUVMap proxy_uv, const std::vector<Carried_side>& side, Cut_mesh& full)
{
  typedef Proxy_mesh::Halfedge_index Halfedge;
  const Proxy_mesh& m = proxy.mesh;
  const std::size_t nu = full.number_of_uv_vertices(), nv = full.number_of_vertices(), nc = full.corner_uv.size();
  const std::vector<int>& proxy_vertex = proxy.proxy_vertex;
  std::vector<int> wedges_at(nv, 0);
  for(std::size_t u = 0; u < nu; ++u) ++wedges_at[full.uv_vertex[u]];

  full.uv.assign(2 * nu, 0.);
  std::vector<char> fixed(nu, 0);
  auto put_uv = [&](int u, Halfedge hp, double t) {
    const auto a = get(proxy_uv, m.prev(hp)), b = get(proxy_uv, hp); // UVs of source(hp), target(hp)
    full.uv[2*u] = (1 - t) * a.x() + t * b.x();
    full.uv[2*u+1] = (1 - t) * a.y() + t * b.y();
    fixed[u] = 1;
  };
  // a chart border vertex: from a halfedge of one of its corners' faces that
  // ends or starts at it
  for(std::size_t c = 0; c < nc; ++c)
  {
    const int u = full.corner_uv[c];
    if(fixed[u]) continue;
    const int ending = int(c), starting = Cut_mesh::next(int(c));
    if(side[ending].proxy_halfedge >= 0)
      put_uv(u, Halfedge(side[ending].proxy_halfedge), side[ending].t_target);
    else if(side[starting].proxy_halfedge >= 0)
      put_uv(u, Halfedge(side[starting].proxy_halfedge), side[starting].t_source);
  }
  // a proxy vertex inside a chart: its one UV there
  for(std::size_t u = 0; u < nu; ++u)
  {
    const int v = full.uv_vertex[u];
    if(fixed[u] || wedges_at[v] != 1 || proxy_vertex[v] < 0) continue;
    for(const Halfedge h : CGAL::halfedges_around_target(Proxy_mesh::Vertex_index(proxy_vertex[v]), m))
      if(!m.is_border(h)) { put_uv(int(u), h, 1.); fixed[u] = 2; break; }
  }

  // harmonic interpolation of the rest: L_ff x_f = -L_fc x_c, per coordinate.
  // A fixed inner vertex near a flipped triangle is set free and the rest
  // solved again (a point constraint the mesh around it cannot follow); from
  // the third pass, a chart border vertex between proxy vertices too (a
  // reflex corner of the border the mesh cannot follow: such a vertex, free,
  // moves into its chart).
  const std::size_t nf = full.number_of_faces();
  // A border vertex of one triangle (an ear) between two vertices on the same
  // border segment would make that triangle flat: it is placed instead so
  // that its triangle has its 3D shape, inside the chart.
  std::vector<int> corners(nu, 0), ear_corner(nu, -1);
  for(std::size_t c = 0; c < nc; ++c) { ++corners[full.corner_uv[c]]; ear_corner[full.corner_uv[c]] = int(c); }
  for(std::size_t u = 0; u < nu; ++u)
    if(corners[u] == 1 && fixed[u] == 1 && proxy_vertex[full.uv_vertex[u]] < 0) fixed[u] = 3;
    else ear_corner[u] = -1;
  auto place_ears = [&] {
    for(std::size_t u = 0; u < nu; ++u)
    {
      const int c = ear_corner[u];
      if(c < 0) continue;
      const int x = full.corner_uv[Cut_mesh::next(c)], z = full.corner_uv[Cut_mesh::prev(c)];
      const double* py = &full.points[3 * full.corner_vertex[c]];
      const double* px = &full.points[3 * full.corner_vertex[Cut_mesh::next(c)]];
      const double* pz = &full.points[3 * full.corner_vertex[Cut_mesh::prev(c)]];
      double a[3], b[3];
      for(int k = 0; k < 3; ++k) { a[k] = py[k] - px[k]; b[k] = pz[k] - px[k]; }
      const double bb = b[0]*b[0] + b[1]*b[1] + b[2]*b[2];
      const double cr[3] = { a[1]*b[2] - a[2]*b[1], a[2]*b[0] - a[0]*b[2], a[0]*b[1] - a[1]*b[0] };
      const double along = (a[0]*b[0] + a[1]*b[1] + a[2]*b[2]) / bb;
      const double height = std::sqrt(cr[0]*cr[0] + cr[1]*cr[1] + cr[2]*cr[2]) / bb;
      const double dx = full.uv[2*z] - full.uv[2*x], dy = full.uv[2*z+1] - full.uv[2*x+1];
      // (y, x, z) counterclockwise: y on the left of x -> z
      full.uv[2*u] = full.uv[2*x] + along * dx - height * dy;
      full.uv[2*u+1] = full.uv[2*x+1] + along * dy + height * dx;
    }
  };
  std::vector<char> invalid;
  for(int pass = 0; pass < 6; ++pass)
  {
    place_ears();
    if(!harmonic_interpolation(full, fixed)) return;
    place_ears();
    std::vector<char> near(nu, 0);
    if(mark_invalid_uv_triangles(full, invalid) == 0) return;
    for(std::size_t f = 0; f < nf; ++f)
      if(invalid[f])
        for(int i = 0; i < 3; ++i) near[full.corner_uv[3*f + i]] = 1;
    for(int ring = 0; ring <= pass / 2; ++ring)
    {
      std::vector<char> grown(near);
      for(std::size_t f = 0; f < nf; ++f)
        if(near[full.corner_uv[3*f]] || near[full.corner_uv[3*f+1]] || near[full.corner_uv[3*f+2]])
          for(int i = 0; i < 3; ++i) grown[full.corner_uv[3*f + i]] = 1;
      near.swap(grown);
    }
    bool freed = false;
    for(std::size_t u = 0; u < nu; ++u)
      if(near[u] && (fixed[u] == 2 || (pass >= 2 && fixed[u] == 1 && proxy_vertex[full.uv_vertex[u]] < 0)))
      {
        fixed[u] = 0;
        freed = true;
      }
    if(!freed && pass >= 2) return; // (solved with these fixed vertices already)
  }
  harmonic_interpolation(full, fixed);
  place_ears();
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
