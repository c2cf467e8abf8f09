// Every mesh a user has: handles, several boundary loops, several components.
// The initial map cuts handles by a greedy system of loops and keeps inner
// boundary loops as holes; optimize_seams() then meets the bound with no flip
// and no overlap. The checks here recompute the figures from the written maps
// (E_SD, flips, UV topology of every chart) instead of trusting the result.
#define BOOST_TEST_MODULE topology
#include <boost/test/unit_test.hpp>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Surface_mesh_seam_optimization/initial_parameterization.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>
#include <CGAL/Surface_mesh_seam_optimization/seams_from_uv_map.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Halfedge_index halfedge_descriptor;
typedef Mesh::Edge_index edge_descriptor;
typedef Mesh::Face_index face_descriptor;
typedef Mesh::Vertex_index vertex_descriptor;

namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace SMSO_np = CGAL::Surface_mesh_seam_optimization::parameters;

namespace {

const std::string dir = std::string(SMSO_TEST_DATA_DIR) + "/general/";

Mesh load(const std::string& name)
{
  Mesh m;
  BOOST_REQUIRE_MESSAGE(CGAL::IO::read_polygon_mesh(dir + name, m), "cannot read " << name);
  if(!CGAL::is_triangle_mesh(m)) CGAL::Polygon_mesh_processing::triangulate_faces(m);
  return m;
}

struct Union_find
{
  std::vector<int> p;
  explicit Union_find(std::size_t n) : p(n) { std::iota(p.begin(), p.end(), 0); }
  int find(int i) { while(p[i] != i) i = p[i] = p[p[i]]; return i; }
  void unite(int a, int b) { p[find(a)] = find(b); }
};

// Genus and boundary loops of each connected component of a (cut) surface
// given as triangles over vertex ids.
struct Surface_topology
{
  int components = 0;
  std::vector<int> genus, loops;
};

Surface_topology topology(const std::vector<std::array<int, 3> >& tris, int n_vertices)
{
  Union_find comp(n_vertices);
  std::map<std::pair<int, int>, int> edge_faces;
  for(const auto& t : tris)
    for(int k = 0; k < 3; ++k)
    {
      comp.unite(t[k], t[(k + 1) % 3]);
      ++edge_faces[std::minmax(t[k], t[(k + 1) % 3])];
    }
  std::map<int, int> id;
  std::vector<char> used(n_vertices, 0);
  for(const auto& t : tris) for(int v : t) used[v] = 1;
  for(int v = 0; v < n_vertices; ++v)
    if(used[v] && !id.count(comp.find(v))) { const int n = int(id.size()); id[comp.find(v)] = n; }
  Surface_topology r;
  r.components = int(id.size());
  std::vector<long> chi(r.components, 0);
  for(int v = 0; v < n_vertices; ++v) if(used[v]) ++chi[id[comp.find(v)]];
  for(const auto& t : tris) ++chi[id[comp.find(t[0])]];
  Union_find border(n_vertices);
  std::set<int> border_vertices;
  for(const auto& e : edge_faces)
  {
    --chi[id[comp.find(e.first.first)]];
    if(e.second == 1)
    {
      border.unite(e.first.first, e.first.second);
      border_vertices.insert(e.first.first);
      border_vertices.insert(e.first.second);
    }
  }
  r.loops.assign(r.components, 0);
  std::set<int> roots;
  for(int v : border_vertices)
    if(roots.insert(border.find(v)).second) ++r.loops[id[comp.find(v)]];
  for(int k = 0; k < r.components; ++k) r.genus.push_back(int(2 - chi[k] - r.loops[k]) / 2);
  return r;
}

Surface_topology mesh_topology(const Mesh& m)
{
  std::vector<std::array<int, 3> > tris;
  for(face_descriptor f : faces(m))
  {
    const halfedge_descriptor h = halfedge(f, m);
    tris.push_back({{ int(target(h, m)), int(target(next(h, m), m)), int(source(h, m)) }});
  }
  return topology(tris, int(m.number_of_vertices()));
}

// The UV mesh: corners welded where the UVs are equal at a vertex.
template <class UVMap>
Surface_topology uv_topology(const Mesh& m, UVMap uv)
{
  std::map<std::pair<int, std::pair<double, double> >, int> id;
  std::vector<std::array<int, 3> > tris;
  auto uv_vertex = [&](halfedge_descriptor h) {
    const Point_2 p = get(uv, h);
    const auto key = std::make_pair(int(target(h, m)), std::make_pair(p.x(), p.y()));
    auto it = id.find(key);
    if(it == id.end()) it = id.emplace(key, int(id.size())).first;
    return it->second;
  };
  for(face_descriptor f : faces(m))
  {
    const halfedge_descriptor h = halfedge(f, m);
    tris.push_back({{ uv_vertex(h), uv_vertex(next(h, m)), uv_vertex(prev(h, m)) }});
  }
  return topology(tris, int(id.size()));
}

// Face f's 3D area, and |J|_F^2 = s1^2 + s2^2 and det J = s1 s2 of its map.
template <class UVMap>
void face_map(const Mesh& m, UVMap uv, face_descriptor f, double& area, double& frob, double& det)
{
  const halfedge_descriptor h0 = halfedge(f, m), h1 = next(h0, m), h2 = next(h1, m);
  const Point_3 &p0 = m.point(target(h0, m)), &p1 = m.point(target(h1, m)), &p2 = m.point(target(h2, m));
  const Point_2 u0 = get(uv, h0), u1 = get(uv, h1), u2 = get(uv, h2);
  // 3D triangle in its own plane: e1 along x
  const K::Vector_3 a = p1 - p0, b = p2 - p0;
  const double la = std::sqrt(a.squared_length());
  const double bx = (a * b) / la, by = std::sqrt((std::max)(0., b.squared_length() - bx * bx));
  area = 0.5 * la * by;
  const double ux = u1.x() - u0.x(), uy = u1.y() - u0.y(), vx = u2.x() - u0.x(), vy = u2.y() - u0.y();
  // J = [u v] * inverse([la bx; 0 by])
  const double j00 = ux / la, j10 = uy / la;
  const double j01 = (vx - j00 * bx) / by, j11 = (vy - j10 * bx) / by;
  frob = j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11;
  det = j00 * j11 - j01 * j10;
}

// E_SD recomputed from the written map, and the number of triangles whose UV
// area is not positive.
template <class UVMap>
double recomputed_distortion(const Mesh& m, UVMap uv, std::size_t& flipped)
{
  double e = 0, area = 0;
  flipped = 0;
  for(face_descriptor f : faces(m))
  {
    double A3, frob, det;
    face_map(m, uv, f, A3, frob, det);
    if(!(det > 0)) { ++flipped; continue; }
    e += A3 * frob * (1 + 1 / (det * det));
    area += A3;
  }
  return e / area;
}

// Seams are exactly the edges whose two sides have different UVs.
template <class UVMap, class SeamMap>
std::size_t seam_mismatches(const Mesh& m, UVMap uv, SeamMap seam)
{
  std::size_t bad = 0;
  for(edge_descriptor e : edges(m))
  {
    const halfedge_descriptor h = halfedge(e, m), o = opposite(h, m);
    if(is_border(h, m) || is_border(o, m)) { bad += get(seam, e) ? 1 : 0; continue; }
    const bool differ = get(uv, h) != get(uv, prev(o, m)) || get(uv, o) != get(uv, prev(h, m));
    bad += differ != get(seam, e) ? 1 : 0;
  }
  return bad;
}

struct Expectation
{
  std::string name;
  int components, genus_total, loops_total; // of the input
};

// optimize_seams() with the defaults on `name`: bound met, no flip, no
// overlap, seams = UV discontinuities, every chart planar (genus 0).
void check_optimized(const Expectation& x, int recut_rounds = 6)
{
  BOOST_TEST_CONTEXT(x.name)
  {
    Mesh m = load(x.name);
    const Surface_topology in = mesh_topology(m);
    BOOST_TEST(in.components == x.components);
    BOOST_TEST(std::accumulate(in.genus.begin(), in.genus.end(), 0) == x.genus_total);
    BOOST_TEST(std::accumulate(in.loops.begin(), in.loops.end(), 0) == x.loops_total);

    auto uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
    auto seam = m.add_property_map<edge_descriptor, bool>("e:seam", false).first;
    const SMSO::Optimization_result r =
      SMSO::optimize_seams(m, uv, SMSO_np::combine(SMSO_np::edge_is_seam_map(seam),
                                                     SMSO_np::number_of_recut_rounds(recut_rounds)));
    BOOST_TEST_MESSAGE(x.name << ": " << SMSO::get_error_code_name(r.status) << " " << r.message << ", E_SD "
                       << r.distortion << ", E_se " << r.seam_length_normalized << ", " << r.charts
                       << " charts, " << r.seconds << " s");
    BOOST_TEST_REQUIRE(r.status == SMSO::OK);
    std::size_t flipped = 0;
    const double e_sd = recomputed_distortion(m, uv, flipped);
    BOOST_TEST(flipped == 0u);
    BOOST_TEST(e_sd <= 4.1);
    BOOST_TEST(std::abs(e_sd - r.distortion) <= 1e-9 * e_sd);
    BOOST_TEST(seam_mismatches(m, uv, seam) == 0u);
    const SMSO::Uv_map_measures measures = SMSO::measure_uv_map(m, uv);
    BOOST_TEST(measures.overlapping_triangle_pairs == 0u);
    const Surface_topology out = uv_topology(m, uv);
    BOOST_TEST(out.components >= x.components);
    BOOST_TEST(std::size_t(out.components) == r.charts);
    for(int k = 0; k < out.components; ++k) BOOST_TEST(out.genus[k] == 0);
  }
}

// The initial map alone: OK, no flip, seams = UV discontinuities, every
// chart planar, no overlap. Returns the UV mesh's topology.
template <class UVMap, class SeamMap>
Surface_topology check_initial_map(const Mesh& m, UVMap uv, SeamMap seam)
{
  BOOST_TEST_REQUIRE(SMSO::compute_initial_parameterization(m, seam, uv) == SMSO::OK);
  std::size_t flipped = 0;
  recomputed_distortion(m, uv, flipped);
  BOOST_TEST(flipped == 0u);
  BOOST_TEST(seam_mismatches(m, uv, seam) == 0u);
  const Surface_topology out = uv_topology(m, uv);
  for(int k = 0; k < out.components; ++k) BOOST_TEST(out.genus[k] == 0);
  BOOST_TEST(SMSO::measure_uv_map(m, uv).overlapping_triangle_pairs == 0u);
  return out;
}

} // namespace

// The initial map alone: handles cut by loops through one point, holes kept
// as holes (no seam joins them), one chart per component, no flip.
BOOST_AUTO_TEST_CASE(initial_map_cuts_handles_and_keeps_holes)
{
  struct Case { std::string name; int charts, uv_loops; };
  // uv_loops: the outer loop (with both sides of the handle cuts) + one per other input loop
  for(const Case& c : { Case{ "torus_with_hole.obj", 1, 1 }, Case{ "torus_with_holes.obj", 1, 2 },
                        Case{ "holes.off", 1, 7 }, Case{ "pinion.off", 1, 1 },
                        Case{ "double-torus-3-holes.off", 1, 3 }, Case{ "horizons.off", 2, 2 },
                        Case{ "blobby_3cc.off", 3, 4 } })
    BOOST_TEST_CONTEXT(c.name)
    {
      Mesh m = load(c.name);
      const Surface_topology in = mesh_topology(m);
      auto uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
      auto seam = m.add_property_map<edge_descriptor, bool>("e:seam", false).first;
      const Surface_topology out = check_initial_map(m, uv, seam);
      BOOST_TEST(out.components == c.charts);
      BOOST_TEST(std::accumulate(out.loops.begin(), out.loops.end(), 0) == c.uv_loops);
      // genus-0 charts with boundary need no seam at all
      const int genus = std::accumulate(in.genus.begin(), in.genus.end(), 0);
      std::size_t seams = 0;
      for(edge_descriptor e : edges(m)) seams += get(seam, e) ? 1 : 0;
      if(genus == 0) BOOST_TEST(seams == 0u);
      else BOOST_TEST(seams > 0u);
    }
}

// seams_from_uv_map(): the seams of the initial map are its UV discontinuities;
// noise far below the tolerance adds none, one corner moved adds its two edges.
BOOST_AUTO_TEST_CASE(seams_from_uv_map_finds_the_uv_discontinuities)
{
  for(const std::string name : { "torus_with_holes.obj", "pinion.off", "double-torus-3-holes.off" })
    BOOST_TEST_CONTEXT(name)
    {
      Mesh m = load(name);
      auto uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
      auto seam = m.add_property_map<edge_descriptor, bool>("e:seam", false).first;
      check_initial_map(m, uv, seam);
      auto found = m.add_property_map<edge_descriptor, bool>("e:found", true).first;
      BOOST_TEST(SMSO::seams_from_uv_map(m, uv, found) == SMSO::OK);
      std::size_t differ = 0, seams = 0;
      for(edge_descriptor e : edges(m)) { differ += get(seam, e) != get(found, e); seams += get(seam, e); }
      BOOST_TEST(differ == 0u);
      BOOST_TEST(seams > 0u);

      CGAL::Bbox_2 box;
      for(halfedge_descriptor h : halfedges(m)) if(!is_border(h, m)) box += get(uv, h).bbox();
      const double diag = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
      unsigned seed = 1;
      for(halfedge_descriptor h : halfedges(m))
        if(!is_border(h, m))
        {
          seed = seed * 1103515245u + 12345u;
          const double d = 1e-11 * diag * (double(seed % 2001) / 1000. - 1.);
          put(uv, h, Point_2(get(uv, h).x() + d, get(uv, h).y() - d));
        }
      BOOST_TEST(SMSO::seams_from_uv_map(m, uv, found) == SMSO::OK);
      differ = 0;
      for(edge_descriptor e : edges(m)) differ += get(seam, e) != get(found, e);
      BOOST_TEST(differ == 0u);

      // a corner at a vertex on no seam and no border, moved: its two edges open
      for(halfedge_descriptor h : halfedges(m))
      {
        if(is_border(h, m) || is_border_edge(h, m)) continue;
        bool free = true;
        for(halfedge_descriptor g : halfedges_around_target(h, m))
          free = free && !is_border_edge(g, m) && !get(seam, edge(g, m));
        if(!free) continue;
        put(uv, h, Point_2(get(uv, h).x() + 1e-3 * diag, get(uv, h).y()));
        BOOST_TEST(SMSO::seams_from_uv_map(m, uv, found) == SMSO::OK);
        std::set<edge_descriptor> opened;
        for(edge_descriptor e : edges(m)) if(get(found, e) && !get(seam, e)) opened.insert(e);
        BOOST_TEST(opened.size() == 2u);
        BOOST_TEST(opened.count(edge(h, m)) == 1u);
        BOOST_TEST(opened.count(edge(next(h, m), m)) == 1u);
        break;
      }
    }
}

// A torus of revolution (R = 1, r = 0.4, n x m quads): the greedy system of
// loops through the best sampled root is one meridian and one parallel,
// meeting at one vertex (degree 4), and no longer than the outer parallel.
BOOST_AUTO_TEST_CASE(torus_is_cut_along_a_meridian_and_a_parallel)
{
  const int n = 24, m = 12;
  const double R = 1, r = 0.4, pi = std::acos(-1.);
  Mesh t;
  std::vector<vertex_descriptor> v;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const double a = 2 * pi * i / n, b = 2 * pi * j / m, rho = R + r * std::cos(b);
      v.push_back(t.add_vertex(Point_3(rho * std::cos(a), rho * std::sin(a), r * std::sin(b))));
    }
  auto id = [&](int i, int j) { return v[(i % n) * m + (j % m)]; };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      t.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      t.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  auto uv = t.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  auto seam = t.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  BOOST_TEST_REQUIRE(SMSO::compute_initial_parameterization(t, seam, uv) == SMSO::OK);

  std::map<vertex_descriptor, int> degree;
  double length = 0;
  for(edge_descriptor e : edges(t))
  {
    if(!get(seam, e)) continue;
    ++degree[source(halfedge(e, t), t)];
    ++degree[target(halfedge(e, t), t)];
    length += std::sqrt(CGAL::squared_distance(t.point(source(halfedge(e, t), t)), t.point(target(halfedge(e, t), t))));
  }
  int fours = 0, twos = 0;
  for(const auto& d : degree) { fours += d.second == 4; twos += d.second == 2; }
  BOOST_TEST(fours == 1);
  BOOST_TEST(twos == int(degree.size()) - 1);
  const double meridian = m * 2 * r * std::sin(pi / m);
  const double inner = n * 2 * (R - r) * std::sin(pi / n), outer = n * 2 * (R + r) * std::sin(pi / n);
  BOOST_TEST(length >= meridian + inner - 1e-9);
  BOOST_TEST(length <= meridian + outer + 1e-9);
  std::size_t flipped = 0;
  recomputed_distortion(t, uv, flipped);
  BOOST_TEST(flipped == 0u);
  const Surface_topology out = uv_topology(t, uv);
  BOOST_TEST(out.components == 1);
  BOOST_TEST(out.loops[0] == 1);
  BOOST_TEST(out.genus[0] == 0);
}

// Genus 3 with 106 holes: the handle loops cannot avoid the holes, and the
// single chart's maps shrink below double precision (UV vertices coincide).
// The chart is split into geodesic Voronoi regions until every piece maps:
// no flip, no overlap, no two vertices at one point, every chart planar, and
// a bijective optimization can start from it (its scaffold meshes).
BOOST_AUTO_TEST_CASE(a_chart_that_cannot_be_mapped_whole_is_split)
{
  Mesh m = load("elephant-with-holes.off");
  const Surface_topology in = mesh_topology(m);
  BOOST_TEST(in.genus[0] == 3);
  BOOST_TEST(in.loops[0] == 106);
  auto uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  auto seam = m.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  const Surface_topology out = check_initial_map(m, uv, seam);
  BOOST_TEST(out.components > 1);
  std::map<std::pair<double, double>, vertex_descriptor> at;
  std::size_t coincident = 0;
  for(halfedge_descriptor h : halfedges(m))
  {
    if(is_border(h, m)) continue;
    const auto it = at.emplace(std::make_pair(get(uv, h).x(), get(uv, h).y()), target(h, m)).first;
    coincident += it->second != target(h, m) ? 1 : 0;
  }
  BOOST_TEST(coincident == 0u);

  auto uv2 = m.add_property_map<halfedge_descriptor, Point_2>("h:uv2").first;
  const SMSO::Optimization_result r =
    SMSO::optimize_seams(m, uv2, SMSO_np::number_of_iterations(30));
  BOOST_TEST(r.status == SMSO::WARNING_MAXIMUM_ITERATIONS);
  BOOST_TEST(r.overlapping_triangle_pairs == 0u);
  std::size_t flipped = 0;
  recomputed_distortion(m, uv2, flipped);
  BOOST_TEST(flipped == 0u);
}

// The shared benchmark's high_genus/, multi_component/ and edge_cases/ meshes.
BOOST_AUTO_TEST_CASE(shared_meshes_meet_the_bound)
{
  check_optimized({ "torus_with_hole.obj", 1, 1, 1 });
  check_optimized({ "torus_with_holes.obj", 1, 1, 2 });
  check_optimized({ "multiComp.obj", 6, 3, 6 }, 0); // the slowest here: no recut round
  check_optimized({ "double_triangles.obj", 2, 0, 2 });
  check_optimized({ "cube.obj", 1, 0, 0 });
  check_optimized({ "plane.obj", 1, 0, 1 });
  check_optimized({ "triangle_clockwise.obj", 1, 0, 1 });
}

// CGAL's sample meshes of genus >= 1, with several boundary loops or several components.
BOOST_AUTO_TEST_CASE(cgal_sample_meshes_meet_the_bound)
{
  check_optimized({ "rotor.off", 1, 1, 0 });
  check_optimized({ "pinion.off", 1, 1, 0 });
  check_optimized({ "pipe.off", 1, 1, 0 });
  check_optimized({ "eight.off", 1, 2, 0 });
  check_optimized({ "joint.off", 1, 2, 0 });
  check_optimized({ "helmet.off", 1, 3, 0 });
  check_optimized({ "double-torus-example.off", 1, 2, 0 });
  check_optimized({ "double-torus-3-holes.off", 1, 2, 3 });
  check_optimized({ "pig.off", 1, 0, 7 });
  check_optimized({ "head.off", 1, 0, 3 });
  check_optimized({ "holes.off", 1, 0, 7 });
  check_optimized({ "horizons.off", 2, 0, 2 });
  check_optimized({ "blobby_3cc.off", 3, 0, 4 });
}

// Two components, packed by optimize_seams() itself (texture_size given):
// every UV in [margin, N - margin] texels, no overlap, and the map at its
// optimal scale is the one the result describes (packing only moves,
// rotates and scales the charts).
BOOST_AUTO_TEST_CASE(optimize_seams_packs_when_given_a_texture_size)
{
  Mesh m = load("horizons.off");
  auto uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  const SMSO::Optimization_result r =
    SMSO::optimize_seams(m, uv, SMSO_np::combine(SMSO_np::texture_size(256), SMSO_np::margin(4)));
  BOOST_TEST_REQUIRE(r.status == SMSO::OK);
  BOOST_TEST(r.charts == 2u);
  double lo = 1, hi = 0;
  for(halfedge_descriptor h : halfedges(m))
  {
    if(is_border(h, m)) continue;
    lo = (std::min)({ lo, get(uv, h).x(), get(uv, h).y() });
    hi = (std::max)({ hi, get(uv, h).x(), get(uv, h).y() });
  }
  BOOST_TEST(lo >= 4. / 256 - 1e-12);
  BOOST_TEST(hi <= 1 - 4. / 256 + 1e-12);
  BOOST_TEST(SMSO::measure_uv_map(m, uv).overlapping_triangle_pairs == 0u);
  // E_SD at the optimal uniform scale: min over s of s^2 A + B / s^2 = 2 sqrt(A B)
  double a = 0, b = 0, area = 0;
  for(face_descriptor f : faces(m))
  {
    double A3, frob, det;
    face_map(m, uv, f, A3, frob, det);
    BOOST_TEST_REQUIRE(det > 0);
    a += A3 * frob;
    b += A3 * frob / (det * det);
    area += A3;
  }
  const double optimal = 2 * std::sqrt(a / area * b / area);
  BOOST_TEST(std::abs(optimal - r.distortion_at_optimal_scale) <= 1e-9 * optimal);
  BOOST_TEST(r.distortion_at_optimal_scale <= 4.1);

  // a margin that leaves no room is refused before anything runs, the map untouched
  auto uv2 = m.add_property_map<halfedge_descriptor, Point_2>("h:uv2", Point_2(-7, 42)).first;
  const SMSO::Optimization_result bad =
    SMSO::optimize_seams(m, uv2, SMSO_np::combine(SMSO_np::texture_size(16), SMSO_np::margin(8)));
  BOOST_TEST(bad.status == SMSO::ERROR_WRONG_PARAMETER);
  BOOST_TEST(bad.iterations == 0u);
  for(halfedge_descriptor h : halfedges(m)) if(!is_border(h, m)) BOOST_TEST_REQUIRE(get(uv2, h) == Point_2(-7, 42));
}

// Very coarse meshes (46 and 180 triangles, genus 3 and 1): under the
// scaffold no split lowers E_SD above the bound; the worst triangles are
// detached into charts of their own (E_SD 4 each) until the bound is met.
BOOST_AUTO_TEST_CASE(coarse_meshes_meet_the_bound_by_detaching_triangles)
{
  check_optimized({ "3torus.off", 1, 3, 0 });
  check_optimized({ "mpi_triang.off", 1, 1, 0 });
}

// There, a run without the scaffold from the same start, cut where its
// charts overlap, is as feasible and replaces the detached triangles when
// its seams are shorter: CGAL's star.off (six spikes, 24 triangles) had 12
// detached, 13 charts and E_se 14.7, 2.5 times the free run's (overlapping)
// seams; 3torus 27.9, 3.5 times. Now within twice the free run's seams.
BOOST_AUTO_TEST_CASE(coarse_meshes_cut_the_free_map_where_it_overlaps)
{
  check_optimized({ "star.off", 1, 0, 0 });
  for(const std::string name : { "star.off", "3torus.off" })
  {
    BOOST_TEST_CONTEXT(name)
    {
      Mesh m = load(name);
      auto uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
      const SMSO::Optimization_result bijective = SMSO::optimize_seams(m, uv);
      const SMSO::Optimization_result free = SMSO::optimize_seams(m, uv, SMSO_np::bijective(false));
      BOOST_TEST_REQUIRE(bijective.status == SMSO::OK);
      BOOST_TEST_REQUIRE(free.status == SMSO::OK);
      BOOST_TEST_MESSAGE(name << ": E_se " << bijective.seam_length_normalized << " (" << bijective.charts
                         << " charts), without the scaffold " << free.seam_length_normalized);
      BOOST_TEST(bijective.message.find("detached triangles replaced") != std::string::npos);
      BOOST_TEST(bijective.bound_met);
      BOOST_TEST(bijective.seam_length_normalized < 2 * free.seam_length_normalized);
      BOOST_TEST(bijective.charts < num_faces(m) / 4);
      // the replacement is one start without the scaffold from the same cut;
      // its iterations are counted with the bijective run's
      const SMSO::Optimization_result free_one =
          SMSO::optimize_seams(m, uv, SMSO_np::bijective(false).number_of_starts(1));
      BOOST_TEST_REQUIRE(free_one.status == SMSO::OK);
      BOOST_TEST(bijective.iterations > free_one.iterations);
      BOOST_TEST(bijective.topology_operations > free_one.topology_operations);
    }
  }
}
