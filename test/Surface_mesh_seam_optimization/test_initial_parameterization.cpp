// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Initial parameterization (Tutte on a circle per chart, slit for closed
// genus-0 charts) and the Seam_mesh bridge, on Surface_mesh and Polyhedron_3.

#define BOOST_TEST_MODULE test_initial_parameterization
#include <boost/test/unit_test.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <boost/property_map/function_property_map.hpp>

// After the mesh headers: CGAL::Seam_mesh calls CGAL::target(h, tm) & co. by
// qualified name, so the mesh's graph traits must be declared first.
#include <CGAL/Surface_mesh_seam_optimization/initial_parameterization.h>
#include <CGAL/Surface_mesh_seam_optimization/seam_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef CGAL::Simple_cartesian<double>                          SC;
typedef CGAL::Exact_predicates_inexact_constructions_kernel     EPICK;
typedef CGAL::Surface_mesh<SC::Point_3>                         Surface_mesh;
typedef CGAL::Polyhedron_3<EPICK>                               Polyhedron;

namespace {

const std::string data_dir = SMSO_DATA_DIR;
const std::string test_data_dir = SMSO_TEST_DATA_DIR;

template <class Mesh>
Mesh load(const std::string& path)
{
  Mesh m;
  const bool ok = CGAL::IO::read_polygon_mesh(path, m);
  BOOST_REQUIRE_MESSAGE(ok && num_faces(m) > 0, "cannot read " << path);
  return m;
}

// Per-mesh-type maps: dynamic property maps work for both mesh types.
template <class Mesh>
struct Maps
{
  typedef typename CGAL::Kernel_traits<
    typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type
  >::Kernel                                                                    K;
  typedef typename K::Point_2                                                  Point_2;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor              halfedge_descriptor;
  typedef typename boost::graph_traits<Mesh>::edge_descriptor                  edge_descriptor;
  typedef typename boost::graph_traits<Mesh>::face_descriptor                  face_descriptor;
  typedef typename boost::property_map<Mesh, CGAL::dynamic_halfedge_property_t<Point_2> >::type UV_map;
  typedef typename boost::property_map<Mesh, CGAL::dynamic_edge_property_t<bool> >::type       Seam_map;

  UV_map uv;
  Seam_map seam;
  explicit Maps(Mesh& m)
    : uv(get(CGAL::dynamic_halfedge_property_t<Point_2>(), m)),
      seam(get(CGAL::dynamic_edge_property_t<bool>(), m))
  {
    for(halfedge_descriptor h : halfedges(m)) put(uv, h, Point_2(-7, 42)); // sentinel
    for(edge_descriptor e : edges(m)) put(seam, e, false);
  }
};

template <class Mesh, class UVMap>
double signed_area(const Mesh& m, UVMap uv, typename boost::graph_traits<Mesh>::face_descriptor f)
{
  const auto h0 = halfedge(f, m), h1 = next(h0, m), h2 = next(h1, m);
  const auto a = get(uv, h0), b = get(uv, h1), c = get(uv, h2);
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
}

struct UV_stats
{
  std::size_t non_finite = 0, flipped = 0;
  double min_area = std::numeric_limits<double>::infinity(), total_area = 0;
};

template <class Mesh, class UVMap>
UV_stats uv_stats(const Mesh& m, UVMap uv)
{
  UV_stats s;
  for(auto h : halfedges(m))
    if(!is_border(h, m) && !(std::isfinite(get(uv, h).x()) && std::isfinite(get(uv, h).y())))
      ++s.non_finite;
  for(auto f : faces(m))
  {
    const double a = signed_area(m, uv, f);
    if(!(a > 0)) ++s.flipped;
    s.min_area = (std::min)(s.min_area, a);
    s.total_area += a;
  }
  return s;
}

// Interior edges whose two sides have different UVs at either end.
template <class Mesh, class UVMap>
std::set<std::size_t> uv_discontinuities(const Mesh& m, UVMap uv)
{
  std::set<std::size_t> out;
  std::size_t i = 0;
  for(auto e : edges(m))
  {
    const auto h = halfedge(e, m), o = opposite(h, m);
    if(!is_border(e, m) && (get(uv, h) != get(uv, prev(o, m)) || get(uv, o) != get(uv, prev(h, m))))
      out.insert(i);
    ++i;
  }
  return out;
}

template <class Mesh, class SeamMap>
std::set<std::size_t> seam_edges(const Mesh& m, SeamMap seam)
{
  std::set<std::size_t> out;
  std::size_t i = 0;
  for(auto e : edges(m))
  {
    if(get(seam, e)) out.insert(i);
    ++i;
  }
  return out;
}

template <class Mesh, class SeamMap>
std::size_t number_of_charts(const Mesh& m, SeamMap seam)
{
  auto fcc = get(CGAL::dynamic_face_property_t<std::size_t>(), m);
  return PMP::connected_components(m, fcc, CGAL::parameters::edge_is_constrained_map(seam));
}

template <class Mesh>
double area_3d(const Mesh& m)
{
  return CGAL::to_double(PMP::area(m));
}

// Circle through three points.
std::array<double, 2> circumcenter(std::array<double, 2> a, std::array<double, 2> b, std::array<double, 2> c)
{
  const double d = 2 * (a[0] * (b[1] - c[1]) + b[0] * (c[1] - a[1]) + c[0] * (a[1] - b[1]));
  const double a2 = a[0] * a[0] + a[1] * a[1], b2 = b[0] * b[0] + b[1] * b[1], c2 = c[0] * c[0] + c[1] * c[1];
  return {{ (a2 * (b[1] - c[1]) + b2 * (c[1] - a[1]) + c2 * (a[1] - b[1])) / d,
            (a2 * (c[0] - b[0]) + b2 * (a[0] - c[0]) + c2 * (b[0] - a[0])) / d }};
}

template <class Mesh>
void check_disk(const std::string& name)
{
  Mesh m = load<Mesh>(data_dir + "/" + name);
  Maps<Mesh> maps(m);
  BOOST_REQUIRE_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv), SMSO::OK);

  const UV_stats s = uv_stats(m, maps.uv);
  BOOST_CHECK_EQUAL(s.non_finite, 0u);
  BOOST_CHECK_EQUAL(s.flipped, 0u);
  std::size_t sentinels = 0;
  for(auto h : halfedges(m))
    if(!is_border(h, m) && get(maps.uv, h) == typename Maps<Mesh>::Point_2(-7, 42)) ++sentinels;
  BOOST_CHECK_EQUAL(sentinels, 0u);

  const double a3 = area_3d(m);
  BOOST_CHECK_LT(std::abs(s.total_area - a3) / a3, 1e-9);
  BOOST_CHECK(seam_edges(m, maps.seam).empty());
  BOOST_CHECK(uv_discontinuities(m, maps.uv).empty());

  // Border vertices on one circle: the UV of a border vertex is taken in the face beside it.
  std::vector<std::array<double, 2> > border;
  for(auto h : halfedges(m))
    if(is_border(h, m))
    {
      const auto p = get(maps.uv, opposite(h, m));
      border.push_back({{ p.x(), p.y() }});
    }
  BOOST_REQUIRE_GE(border.size(), 3u);
  const std::size_t n = border.size();
  const std::array<double, 2> c = circumcenter(border[0], border[n / 3], border[2 * n / 3]);
  auto dist = [&](const std::array<double, 2>& p) { return std::hypot(p[0] - c[0], p[1] - c[1]); };
  const double r = dist(border[0]);
  double worst = 0;
  for(const auto& p : border) worst = (std::max)(worst, std::abs(dist(p) - r) / r);
  BOOST_CHECK_LT(worst, 1e-9);
  // The border is the circle of area a3 / (interior share): at least it encloses the map.
  BOOST_CHECK_GT(CGAL_PI * r * r, s.total_area);

  BOOST_TEST_MESSAGE(name << ": " << num_faces(m) << " faces, " << n << " border vertices, radius "
                     << r << ", circle deviation " << worst << ", UV/3D area - 1 = "
                     << (s.total_area - a3) / a3 << ", smallest UV triangle area " << s.min_area);
}

// A path of `length` interior edges from a border vertex inward, marked as seams.
template <class Mesh, class SeamMap>
void mark_seam_path_from_border(const Mesh& m, SeamMap seam, int length)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  auto vpm = get(CGAL::vertex_point, m);
  halfedge_descriptor b;
  for(auto h : halfedges(m)) if(is_border(h, m)) { b = h; break; }
  const vertex_descriptor start = target(b, m);
  std::set<vertex_descriptor> visited;
  visited.insert(start);
  vertex_descriptor v = start;
  for(int i = 0; i < length; ++i)
  {
    halfedge_descriptor best;
    double best_d = -1;
    for(halfedge_descriptor h : CGAL::halfedges_around_source(v, m))
    {
      const vertex_descriptor w = target(h, m);
      if(visited.count(w) || is_border(w, m) || is_border(edge(h, m), m)) continue;
      const double d = CGAL::to_double(CGAL::squared_distance(get(vpm, w), get(vpm, start)));
      if(d > best_d) { best_d = d; best = h; }
    }
    BOOST_REQUIRE(best_d >= 0);
    put(seam, edge(best, m), true);
    v = target(best, m);
    visited.insert(v);
  }
}

} // namespace

BOOST_AUTO_TEST_CASE(disk_surface_mesh)
{
  check_disk<Surface_mesh>("bimba_i_f10000.obj");
}

BOOST_AUTO_TEST_CASE(disk_polyhedron)
{
  check_disk<Polyhedron>("bimba_i_f10000.obj");
}

BOOST_AUTO_TEST_CASE(closed_genus_0_gets_a_two_edge_slit)
{
  Surface_mesh m = load<Surface_mesh>(data_dir + "/sphere_f1522.obj");
  Maps<Surface_mesh> maps(m);
  BOOST_REQUIRE_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv), SMSO::OK);

  std::vector<Surface_mesh::Edge_index> seams;
  for(auto e : edges(m)) if(get(maps.seam, e)) seams.push_back(e);
  BOOST_REQUIRE_EQUAL(seams.size(), 2u);
  std::set<Surface_mesh::Vertex_index> ends;
  for(auto e : seams) { ends.insert(source(e, m)); ends.insert(target(e, m)); }
  BOOST_CHECK_EQUAL(ends.size(), 3u); // a path: the two edges share exactly one vertex
  // not two sides of one triangle
  const auto h0 = halfedge(seams[0], m), h1 = halfedge(seams[1], m);
  BOOST_CHECK(face(h0, m) != face(h1, m) && face(h0, m) != face(opposite(h1, m), m) &&
              face(opposite(h0, m), m) != face(h1, m) &&
              face(opposite(h0, m), m) != face(opposite(h1, m), m));

  BOOST_CHECK_EQUAL(number_of_charts(m, maps.seam), 1u);
  const UV_stats s = uv_stats(m, maps.uv);
  BOOST_CHECK_EQUAL(s.non_finite, 0u);
  BOOST_CHECK_EQUAL(s.flipped, 0u);
  const double a3 = area_3d(m);
  BOOST_CHECK_LT(std::abs(s.total_area - a3) / a3, 1e-9);
  BOOST_CHECK(uv_discontinuities(m, maps.uv) == seam_edges(m, maps.seam));

  // The slit's middle vertex is the farthest from the centroid of the
  // triangles' corners, and its two edges are the straightest admissible pair there.
  typedef Surface_mesh::Point Point;
  double c[3] = { 0, 0, 0 }, n = 0;
  for(auto f : faces(m))
    for(auto h : halfedges_around_face(halfedge(f, m), m))
    {
      const Point& p = m.point(target(h, m));
      c[0] += p.x(); c[1] += p.y(); c[2] += p.z(); n += 1;
    }
  const Point centroid(c[0] / n, c[1] / n, c[2] / n);
  Surface_mesh::Vertex_index tip;
  for(auto v : vertices(m))
    if(tip == Surface_mesh::null_vertex() ||
       CGAL::squared_distance(m.point(v), centroid) > CGAL::squared_distance(m.point(tip), centroid))
      tip = v;
  Surface_mesh::Vertex_index middle;
  for(auto v : ends)
    if(std::count_if(seams.begin(), seams.end(), [&](Surface_mesh::Edge_index e) {
         return source(e, m) == v || target(e, m) == v; }) == 2)
      middle = v;
  BOOST_CHECK(middle == tip);
  auto other_end = [&](Surface_mesh::Edge_index e) { return source(e, m) == middle ? target(e, m) : source(e, m); };
  auto cosine = [&](Surface_mesh::Vertex_index a, Surface_mesh::Vertex_index b) {
    const auto u = m.point(a) - m.point(middle), w = m.point(b) - m.point(middle);
    return u * w / std::sqrt(u.squared_length() * w.squared_length());
  };
  const double slit_cosine = cosine(other_end(seams[0]), other_end(seams[1]));
  std::vector<Surface_mesh::Vertex_index> ring;
  for(auto v : vertices_around_target(halfedge(middle, m), m)) ring.push_back(v);
  for(std::size_t i = 0; i < ring.size(); ++i)
    for(std::size_t j = i + 2; j < ring.size(); ++j)
      if(!(i == 0 && j + 1 == ring.size()))
        BOOST_CHECK_GE(cosine(ring[i], ring[j]), slit_cosine - 1e-12);
  BOOST_CHECK_LT(slit_cosine, -0.8); // nearly a straight line on a fine sphere

  BOOST_TEST_MESSAGE("sphere: slit at the farthest vertex, cosine " << slit_cosine
                     << ", smallest UV triangle area " << s.min_area);
}

BOOST_AUTO_TEST_CASE(closed_genus_0_with_protrusions_gets_a_path_slit)
{
  // The octopus is closed, genus 0, with eight long tentacles: Tutte's map of
  // the two-edge slit squeezes the tentacle tips to zero area in double
  // precision; the retry slits it along a shortest path between two
  // approximately farthest vertices.
  Surface_mesh m = load<Surface_mesh>(test_data_dir + "/octopus_mainComp_f6000.obj");
  BOOST_REQUIRE(CGAL::is_closed(m));
  Maps<Surface_mesh> maps(m);
  BOOST_REQUIRE_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv), SMSO::OK);

  BOOST_CHECK_EQUAL(number_of_charts(m, maps.seam), 1u);
  const UV_stats s = uv_stats(m, maps.uv);
  BOOST_CHECK_EQUAL(s.non_finite, 0u);
  BOOST_CHECK_EQUAL(s.flipped, 0u); // signed area > 0 everywhere: none flipped or degenerate
  BOOST_CHECK_GT(s.min_area, 0.);
  const double a3 = area_3d(m);
  BOOST_CHECK_LT(std::abs(s.total_area - a3) / a3, 1e-9);

  // The slit is a simple path: seam degree 2 at its interior vertices, 1 at its two ends, connected.
  std::vector<Surface_mesh::Edge_index> seams;
  for(auto e : edges(m)) if(get(maps.seam, e)) seams.push_back(e);
  BOOST_REQUIRE_GT(seams.size(), 2u);
  std::map<Surface_mesh::Vertex_index, int> degree;
  for(auto e : seams) { ++degree[source(e, m)]; ++degree[target(e, m)]; }
  std::vector<Surface_mesh::Vertex_index> ends;
  std::size_t interior = 0;
  for(const auto& vd : degree)
  {
    if(vd.second == 1) ends.push_back(vd.first);
    else if(vd.second == 2) ++interior;
  }
  BOOST_CHECK_EQUAL(ends.size(), 2u);
  BOOST_CHECK_EQUAL(interior, degree.size() - 2);
  BOOST_CHECK_EQUAL(degree.size(), seams.size() + 1); // a tree: connected and no cycle
  if(ends.size() == 2)
  {
    // walk from one end along the seams: it reaches the other end through every seam edge
    std::set<Surface_mesh::Edge_index> walked;
    Surface_mesh::Vertex_index v = ends[0];
    for(bool moved = true; moved; )
    {
      moved = false;
      for(auto h : CGAL::halfedges_around_source(v, m))
        if(get(maps.seam, edge(h, m)) && walked.insert(edge(h, m)).second)
        {
          v = target(h, m);
          moved = true;
          break;
        }
    }
    BOOST_CHECK(v == ends[1]);
    BOOST_CHECK_EQUAL(walked.size(), seams.size());
  }
  // The UVs differ across exactly those edges.
  BOOST_CHECK(uv_discontinuities(m, maps.uv) == seam_edges(m, maps.seam));

  double slit_length = 0;
  for(auto e : seams) slit_length += std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
  BOOST_TEST_MESSAGE("octopus: path slit of " << seams.size() << " edges, length " << slit_length
                     << " (3D area " << a3 << "), smallest UV triangle area " << s.min_area);
}

BOOST_AUTO_TEST_CASE(two_components_are_laid_out_apart)
{
  // two triangles
  {
    Surface_mesh m = load<Surface_mesh>(test_data_dir + "/double_triangles.obj");
    Maps<Surface_mesh> maps(m);
    BOOST_REQUIRE_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv), SMSO::OK);
    BOOST_CHECK_EQUAL(uv_stats(m, maps.uv).flipped, 0u);
  }
  // two real disks in one mesh: cat and bishop
  Surface_mesh m;
  CGAL::copy_face_graph(load<Surface_mesh>(data_dir + "/cat_f1500.obj"), m);
  const std::size_t cat_faces = num_faces(m);
  CGAL::copy_face_graph(load<Surface_mesh>(data_dir + "/bishop_part_f1000.obj"), m);
  Maps<Surface_mesh> maps(m);
  BOOST_REQUIRE_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv), SMSO::OK);
  BOOST_CHECK_EQUAL(number_of_charts(m, maps.seam), 2u);
  BOOST_CHECK(seam_edges(m, maps.seam).empty());
  const UV_stats s = uv_stats(m, maps.uv);
  BOOST_CHECK_EQUAL(s.flipped, 0u);

  // per chart: UV area = 3D area, and the bounding boxes are disjoint
  double lo[2][2], hi[2][2], uv_area[2] = { 0, 0 }, a3[2] = { 0, 0 };
  for(int k = 0; k < 2; ++k) for(int i = 0; i < 2; ++i) { lo[k][i] = 1e300; hi[k][i] = -1e300; }
  for(auto f : faces(m))
  {
    const int k = std::size_t(f) < cat_faces ? 0 : 1;
    uv_area[k] += signed_area(m, maps.uv, f);
    a3[k] += PMP::face_area(f, m);
    for(auto h : halfedges_around_face(halfedge(f, m), m))
    {
      const auto p = get(maps.uv, h);
      lo[k][0] = (std::min)(lo[k][0], p.x()); hi[k][0] = (std::max)(hi[k][0], p.x());
      lo[k][1] = (std::min)(lo[k][1], p.y()); hi[k][1] = (std::max)(hi[k][1], p.y());
    }
  }
  for(int k = 0; k < 2; ++k)
    BOOST_CHECK_LT(std::abs(uv_area[k] - a3[k]) / a3[k], 1e-9);
  const bool disjoint = hi[0][0] < lo[1][0] || hi[1][0] < lo[0][0] || hi[0][1] < lo[1][1] || hi[1][1] < lo[0][1];
  BOOST_CHECK(disjoint);
  BOOST_TEST_MESSAGE("cat box [" << lo[0][0] << "," << hi[0][0] << "]x[" << lo[0][1] << "," << hi[0][1]
                     << "], bishop box [" << lo[1][0] << "," << hi[1][0] << "]x[" << lo[1][1] << ","
                     << hi[1][1] << "]");
}

BOOST_AUTO_TEST_CASE(vertex_point_map_is_honoured)
{
  // Stretch x by 3 through the named parameter: areas and the border's arc
  // lengths must follow the stretched points, not the mesh's own.
  Surface_mesh m = load<Surface_mesh>(data_dir + "/cat_f1500.obj");
  Maps<Surface_mesh> maps(m);
  const auto vpm = boost::make_function_property_map<Surface_mesh::Vertex_index, SC::Point_3>(
    [&m](Surface_mesh::Vertex_index v) { const SC::Point_3& p = m.point(v); return SC::Point_3(3 * p.x(), p.y(), p.z()); });
  BOOST_REQUIRE_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv,
                                                             CGAL::parameters::vertex_point_map(vpm)),
                      SMSO::OK);
  const UV_stats s = uv_stats(m, maps.uv);
  BOOST_CHECK_EQUAL(s.flipped, 0u);
  const double a3 = CGAL::to_double(PMP::area(m, CGAL::parameters::vertex_point_map(vpm)));
  BOOST_CHECK_LT(std::abs(s.total_area - a3) / a3, 1e-9);

  // Walk the border loop: angle steps on the circle = stretched edge length / border length.
  Surface_mesh::Halfedge_index b;
  for(auto h : halfedges(m)) if(is_border(h, m)) { b = h; break; }
  std::vector<std::array<double, 2> > pts;
  std::vector<double> len;
  for(auto h : halfedges_around_face(b, m))
  {
    const auto p = get(maps.uv, opposite(h, m)); // UV of source(h)
    pts.push_back({{ p.x(), p.y() }});
    len.push_back(std::sqrt(CGAL::squared_distance(get(vpm, source(h, m)), get(vpm, target(h, m)))));
  }
  const std::size_t n = pts.size();
  const std::array<double, 2> c = circumcenter(pts[0], pts[n / 3], pts[2 * n / 3]);
  double total = 0;
  for(double l : len) total += l;
  double worst = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const auto& p = pts[i];
    const auto& q = pts[(i + 1) % n];
    double step = std::atan2(q[1] - c[1], q[0] - c[0]) - std::atan2(p[1] - c[1], p[0] - c[0]);
    step = std::abs(std::remainder(step, 2 * CGAL_PI));
    worst = (std::max)(worst, std::abs(step / (2 * CGAL_PI) - len[i] / total));
  }
  BOOST_CHECK_LT(worst, 1e-9);
  BOOST_TEST_MESSAGE("stretched cat: " << n << " border vertices, worst arc-length share error " << worst);
}

BOOST_AUTO_TEST_CASE(user_seams_are_honoured)
{
  // A seam path from the border into a disk keeps it a disk; the UVs must split along it.
  Polyhedron m = load<Polyhedron>(data_dir + "/cat_f1500.obj");
  Maps<Polyhedron> maps(m);
  mark_seam_path_from_border(m, maps.seam, 8);
  const std::set<std::size_t> seams = seam_edges(m, maps.seam);
  BOOST_REQUIRE_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv), SMSO::OK);
  BOOST_CHECK(seam_edges(m, maps.seam) == seams);
  BOOST_CHECK(uv_discontinuities(m, maps.uv) == seams);
  BOOST_CHECK_EQUAL(uv_stats(m, maps.uv).flipped, 0u);
}

BOOST_AUTO_TEST_CASE(errors_leave_the_maps_untouched)
{
  typedef Maps<Surface_mesh>::Point_2 Point_2;
  auto untouched = [](const Surface_mesh& m, const Maps<Surface_mesh>& maps)
  {
    for(auto h : halfedges(m)) if(get(maps.uv, h) != Point_2(-7, 42)) return false;
    for(auto e : edges(m)) if(get(maps.seam, e)) return false;
    return true;
  };

  {
    // sphere (its slit is chosen first) + torus (its handles cut) + a
    // zero-area triangle: still nothing written
    Surface_mesh m;
    CGAL::copy_face_graph(load<Surface_mesh>(data_dir + "/sphere_f1522.obj"), m);
    CGAL::copy_face_graph(load<Surface_mesh>(test_data_dir + "/torus.obj"), m);
    m.add_face(m.add_vertex(SC::Point_3(0, 0, 9)), m.add_vertex(SC::Point_3(1, 0, 9)),
               m.add_vertex(SC::Point_3(2, 0, 9)));
    Maps<Surface_mesh> maps(m);
    std::string message;
    BOOST_CHECK_EQUAL(SMSO::internal::initial_parameterization(m, maps.seam, maps.uv, SMSO::parameters::default_values(),
                                                               message),
                      SMSO::ERROR_DEGENERATE_TRIANGLE);
    BOOST_CHECK_MESSAGE(message.find("face 5345 (numbered from 1)") != std::string::npos, message);
    BOOST_CHECK(untouched(m, maps));
  }
  {
    // a zero-area triangle: (0,0,0), (1,0,0), (2,0,0)
    Surface_mesh m;
    const auto a = m.add_vertex(SC::Point_3(0, 0, 0)), b = m.add_vertex(SC::Point_3(1, 0, 0)),
               c = m.add_vertex(SC::Point_3(2, 0, 0)), d = m.add_vertex(SC::Point_3(1, 1, 0));
    m.add_face(a, b, d);
    m.add_face(b, c, d);
    BOOST_REQUIRE(m.add_face(a, c, b) != Surface_mesh::null_face());
    Maps<Surface_mesh> maps(m);
    BOOST_CHECK_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv),
                      SMSO::ERROR_DEGENERATE_TRIANGLE);
    BOOST_CHECK(untouched(m, maps));
  }
  {
    Surface_mesh m;
    Maps<Surface_mesh> maps(m);
    BOOST_CHECK_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv), SMSO::ERROR_EMPTY_MESH);
  }
  {
    Surface_mesh m;
    const auto a = m.add_vertex(SC::Point_3(0, 0, 0)), b = m.add_vertex(SC::Point_3(1, 0, 0)),
               c = m.add_vertex(SC::Point_3(1, 1, 0)), d = m.add_vertex(SC::Point_3(0, 1, 0));
    m.add_face(a, b, c, d);
    Maps<Surface_mesh> maps(m);
    BOOST_CHECK_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv),
                      SMSO::ERROR_NON_TRIANGULAR_MESH);
    BOOST_CHECK(untouched(m, maps));
  }
  {
    Surface_mesh m;
    const auto a = m.add_vertex(SC::Point_3(0, 0, 0)), b = m.add_vertex(SC::Point_3(1, 0, 0)),
               c = m.add_vertex(SC::Point_3(std::numeric_limits<double>::quiet_NaN(), 1, 0));
    m.add_face(a, b, c);
    Maps<Surface_mesh> maps(m);
    BOOST_CHECK_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv),
                      SMSO::ERROR_NON_FINITE_COORDINATES);
    BOOST_CHECK(untouched(m, maps));
  }
}

BOOST_AUTO_TEST_CASE(seam_mesh_round_trip)
{
  Surface_mesh m = load<Surface_mesh>(data_dir + "/sphere_f1522.obj");
  Maps<Surface_mesh> maps(m);
  BOOST_REQUIRE_EQUAL(SMSO::compute_initial_parameterization(m, maps.seam, maps.uv), SMSO::OK);

  SMSO::Seam_mesh_maker<Surface_mesh> maker(m, maps.seam);
  BOOST_CHECK_EQUAL(maker.number_of_seam_edges(), 2u);
  typedef SMSO::Seam_mesh_maker<Surface_mesh>::Seam_mesh Seam_mesh;
  const Seam_mesh& smesh = maker.seam_mesh();
  // the slit of two edges splits its middle vertex in two
  BOOST_CHECK_EQUAL(num_vertices(smesh), num_vertices(m) + 1);

  auto seam_uv = m.add_property_map<Surface_mesh::Halfedge_index, SC::Point_2>("h:seam_uv").first;
  BOOST_REQUIRE_EQUAL(SMSO::corner_uv_map_to_seam_mesh_uv_map(smesh, maps.uv, seam_uv), SMSO::OK);
  auto back = m.add_property_map<Surface_mesh::Halfedge_index, SC::Point_2>("h:back", SC::Point_2(-1, -1)).first;
  SMSO::seam_mesh_uv_map_to_corner_uv_map(smesh, seam_uv, back);
  std::size_t differ = 0;
  for(auto h : halfedges(m))
    if(!is_border(h, m) && get(back, h) != get(maps.uv, h)) ++differ;
  BOOST_CHECK_EQUAL(differ, 0u);

  // A per-corner map with a jump the seams do not explain is refused, untouched.
  const auto h = *halfedges(m).begin();
  const Surface_mesh::Halfedge_index hf = is_border(h, m) ? opposite(h, m) : h;
  const SC::Point_2 saved = get(maps.uv, hf);
  put(maps.uv, hf, SC::Point_2(saved.x() + 1, saved.y()));
  auto fresh = m.add_property_map<Surface_mesh::Halfedge_index, SC::Point_2>("h:fresh", SC::Point_2(5, 5)).first;
  BOOST_CHECK_EQUAL(SMSO::corner_uv_map_to_seam_mesh_uv_map(smesh, maps.uv, fresh), SMSO::ERROR_INVALID_UV_MAP);
  std::size_t written = 0;
  for(auto g : halfedges(m)) if(get(fresh, g) != SC::Point_2(5, 5)) ++written;
  BOOST_CHECK_EQUAL(written, 0u);
}

template <class Mesh>
void check_cgal_parameterizer_through_bridge()
{
  // Discrete conformal map on a disk with a seam path: CGAL's map, read back per corner.
  Mesh m = load<Mesh>(data_dir + "/bimba_i_f10000.obj");
  Maps<Mesh> maps(m);
  mark_seam_path_from_border(m, maps.seam, 12);

  SMSO::Seam_mesh_maker<Mesh> maker(m, maps.seam);
  typedef typename SMSO::Seam_mesh_maker<Mesh>::Seam_mesh Seam_mesh;
  Seam_mesh& smesh = maker.seam_mesh();
  BOOST_CHECK_EQUAL(maker.number_of_seam_edges(), 12u);

  typedef typename Maps<Mesh>::Point_2 Point_2;
  auto seam_uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), m);
  const auto bhd = maker.border_halfedge(*faces(m).begin());
  BOOST_REQUIRE(bhd != typename boost::graph_traits<Seam_mesh>::halfedge_descriptor());
  SMP::Discrete_conformal_map_parameterizer_3<Seam_mesh> dcm;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(smesh, dcm, bhd, seam_uv), SMP::OK);

  SMSO::seam_mesh_uv_map_to_corner_uv_map(smesh, seam_uv, maps.uv);
  const UV_stats s = uv_stats(m, maps.uv);
  BOOST_CHECK_EQUAL(s.non_finite, 0u);
  BOOST_CHECK_EQUAL(s.flipped, 0u);
  BOOST_CHECK(uv_discontinuities(m, maps.uv) == seam_edges(m, maps.seam));
  BOOST_TEST_MESSAGE("DCM through the bridge: " << s.flipped << " flipped, smallest UV area "
                     << s.min_area << ", UV area " << s.total_area);
}

BOOST_AUTO_TEST_CASE(cgal_parameterizer_through_the_bridge_surface_mesh)
{
  check_cgal_parameterizer_through_bridge<Surface_mesh>();
}

BOOST_AUTO_TEST_CASE(cgal_parameterizer_through_the_bridge_polyhedron)
{
  check_cgal_parameterizer_through_bridge<Polyhedron>();
}

// Tutte's map of a large chart: the border rows eliminated, one sparse
// Cholesky factorization for u and v (Fixed_border_solver_traits) gives
// CGAL's map (BiCGSTAB with incomplete LU, per coordinate) up to the
// iterative solver's tolerance; below the size limit, and for a system that is
// not symmetric (mean value coordinates), CGAL's solver runs, to the last bit.
BOOST_AUTO_TEST_CASE(tutte_by_one_factorization_gives_cgal_map)
{
  Surface_mesh m = load<Surface_mesh>(data_dir + "/bimba_i_f10000.obj");
  Maps<Surface_mesh> maps(m);
  mark_seam_path_from_border(m, maps.seam, 12);
  SMSO::Seam_mesh_maker<Surface_mesh> maker(m, maps.seam);
  typedef SMSO::Seam_mesh_maker<Surface_mesh>::Seam_mesh Seam_mesh;
  Seam_mesh& smesh = maker.seam_mesh();
  const auto bhd = maker.border_halfedge(*faces(m).begin());
  BOOST_REQUIRE(bhd != boost::graph_traits<Seam_mesh>::halfedge_descriptor());
  typedef SMP::Circular_border_arc_length_parameterizer_3<Seam_mesh> Border;
  typedef SMSO::internal::Fixed_border_solver_traits Traits;
  typedef Surface_mesh::Halfedge_index H;

  auto cgal = m.add_property_map<H, SC::Point_2>("h:cgal").first;
  auto direct = m.add_property_map<H, SC::Point_2>("h:direct").first;
  auto small = m.add_property_map<H, SC::Point_2>("h:small").first;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(smesh, SMP::Barycentric_mapping_parameterizer_3<Seam_mesh, Border>(), bhd, cgal),
                      SMP::OK);
  const Traits by_factor(0), by_default;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(smesh, SMP::Barycentric_mapping_parameterizer_3<Seam_mesh, Border, Traits>(
                                                 Border(), by_factor), bhd, direct), SMP::OK);
  BOOST_CHECK(by_factor.used_factorization());
  BOOST_REQUIRE_EQUAL(SMP::parameterize(smesh, SMP::Barycentric_mapping_parameterizer_3<Seam_mesh, Border, Traits>(
                                                 Border(), by_default), bhd, small), SMP::OK);
  BOOST_CHECK(!by_default.used_factorization());

  double largest = 0;
  std::size_t differ = 0, corners = 0;
  for(H h : halfedges(m))
  {
    if(is_border(h, m)) continue;
    ++corners;
    const SC::Point_2 a = get(cgal, h), b = get(direct, h);
    largest = (std::max)(largest, (std::max)(std::abs(a.x() - b.x()), std::abs(a.y() - b.y())));
    if(get(small, h) != a) ++differ;
  }
  BOOST_TEST_MESSAGE("Tutte by one factorization against CGAL's solver: largest UV difference " << largest
                     << " on the unit circle's map, " << corners << " corners");
  BOOST_CHECK_LT(largest, 1e-11);
  BOOST_CHECK_EQUAL(differ, 0u);

  // Tutte's equations: every interior vertex at the mean of its neighbours
  double residual = 0;
  for(auto v : vertices(smesh))
  {
    bool border = false;
    double sx = 0, sy = 0;
    int n = 0;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, smesh), smesh))
    {
      if(is_border(h, smesh) || is_border(opposite(h, smesh), smesh)) border = true;
      const SC::Point_2 q = get(direct, source(h, smesh));
      sx += q.x(); sy += q.y(); ++n;
    }
    if(border) continue;
    const SC::Point_2 p = get(direct, v);
    residual = (std::max)(residual, std::hypot(p.x() - sx / n, p.y() - sy / n));
  }
  BOOST_CHECK_LT(residual, 1e-12);

  // not symmetric: CGAL's solver, the same map
  auto mvc = m.add_property_map<H, SC::Point_2>("h:mvc").first;
  auto mvc_traits = m.add_property_map<H, SC::Point_2>("h:mvc_traits").first;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(smesh, SMP::Mean_value_coordinates_parameterizer_3<Seam_mesh, Border>(), bhd, mvc),
                      SMP::OK);
  const Traits mvc_factor(0);
  BOOST_REQUIRE_EQUAL(SMP::parameterize(smesh, SMP::Mean_value_coordinates_parameterizer_3<Seam_mesh, Border, Traits>(
                                                 Border(), mvc_factor), bhd, mvc_traits), SMP::OK);
  BOOST_CHECK(!mvc_factor.used_factorization());
  differ = 0;
  for(H h : halfedges(m))
    if(!is_border(h, m) && get(mvc, h) != get(mvc_traits, h)) ++differ;
  BOOST_CHECK_EQUAL(differ, 0u);
}
