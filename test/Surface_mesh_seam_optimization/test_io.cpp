// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// OBJ with per-corner UVs: write then read back, vt deduplication, reader errors.

#define BOOST_TEST_MODULE io
#include <boost/test/unit_test.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/IO/OBJ.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace SMSO = CGAL::Surface_mesh_seam_optimization;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;
typedef K::Point_3 Point_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
typedef Mesh::Property_map<halfedge_descriptor, Point_2> UV_map;

namespace {

const int n_columns = 6;

// An open cylinder (2 rings of n_columns vertices) unrolled into a rectangle:
// the column at angle 0 is cut, so its 2 vertices have two UVs each.
struct Cylinder
{
  std::vector<Point_3> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::array<Point_2, 3> > corner_uvs;   // per triangle, per corner

  Cylinder()
  {
    const double pi = std::acos(-1.0);
    for(int r = 0; r < 2; ++r)
      for(int j = 0; j < n_columns; ++j)
      {
        // Awkward values, so a lossy writer would show.
        const double a = 2 * pi * j / n_columns + 0.1;
        points.emplace_back(std::cos(a) / 3, std::sin(a) / 7, r * 0.7 + 1e-9);
      }
    for(int j = 0; j < n_columns; ++j)
    {
      const int j1 = (j + 1) % n_columns;
      // Column j spans u in [j, j+1] / n: vertex j1 of the last column is at u = 1.
      auto uv = [&](int r, bool right) {
        return Point_2((right ? j + 1 : j) / double(n_columns), r * 0.7);
      };
      const std::size_t a = j, b = j1, c = n_columns + j1, d = n_columns + j;
      triangles.push_back({a, b, c});
      corner_uvs.push_back({uv(0, false), uv(0, true), uv(1, true)});
      triangles.push_back({a, c, d});
      corner_uvs.push_back({uv(0, false), uv(1, true), uv(1, false)});
    }
  }

  // n_columns distinct UVs per ring + one extra for the cut vertex of each ring
  std::size_t expected_vt() const { return 2 * n_columns + 2; }
};

template <typename PolygonMesh, typename UVMap>
void build(const Cylinder& c, PolygonMesh& pm, UVMap uvmap)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> vds;
  for(const Point_3& p : c.points)
  {
    vertex_descriptor v = add_vertex(pm);
    put(get(CGAL::vertex_point, pm), v, p);
    vds.push_back(v);
  }
  for(std::size_t t = 0; t < c.triangles.size(); ++t)
  {
    std::vector<vertex_descriptor> fv = {vds[c.triangles[t][0]], vds[c.triangles[t][1]],
                                         vds[c.triangles[t][2]]};
    auto f = CGAL::Euler::add_face(fv, pm);
    BOOST_REQUIRE(f != boost::graph_traits<PolygonMesh>::null_face());
    for(auto h : halfedges_around_face(halfedge(f, pm), pm))
      for(int k = 0; k < 3; ++k)
        if(target(h, pm) == fv[k])
          put(uvmap, h, c.corner_uvs[t][k]);
  }
}

std::size_t count_lines(const std::string& text, const std::string& prefix)
{
  std::istringstream is(text);
  std::string line;
  std::size_t n = 0;
  while(std::getline(is, line))
    n += line.compare(0, prefix.size(), prefix) == 0 ? 1 : 0;
  return n;
}

// Every face of `read` (in order) has the same corners, positions and UVs as
// the cylinder's triangle of the same index.
void check_against(const Cylinder& c, const Mesh& read, UV_map uv)
{
  BOOST_REQUIRE_EQUAL(num_vertices(read), c.points.size());
  BOOST_REQUIRE_EQUAL(num_faces(read), c.triangles.size());
  std::size_t i = 0;
  for(auto v : vertices(read))
  {
    BOOST_CHECK_EQUAL(std::size_t(v), i);
    BOOST_CHECK(read.point(v) == c.points[i]); // exact: 17 digits round-trip
    ++i;
  }
  std::size_t t = 0, corners = 0;
  for(face_descriptor f : faces(read))
  {
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, read), read))
      for(int k = 0; k < 3; ++k)
        if(std::size_t(target(h, read)) == c.triangles[t][k])
        {
          BOOST_CHECK(get(uv, h) == c.corner_uvs[t][k]);
          ++corners;
        }
    ++t;
  }
  BOOST_CHECK_EQUAL(corners, 3 * c.triangles.size());
}

} // namespace

BOOST_AUTO_TEST_CASE(surface_mesh_round_trip_and_vt_dedup)
{
  Cylinder c;
  Mesh mesh;
  UV_map uv = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  build(c, mesh, uv);

  std::ostringstream os;
  BOOST_REQUIRE(SMSO::IO::write_OBJ_with_uv_map(os, mesh, uv));
  const std::string text = os.str();
  BOOST_CHECK_EQUAL(count_lines(text, "v "), c.points.size());
  BOOST_CHECK_EQUAL(count_lines(text, "vt "), c.expected_vt());
  BOOST_CHECK_EQUAL(count_lines(text, "f "), c.triangles.size());

  Mesh back;
  UV_map back_uv = back.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  std::istringstream is(text);
  std::string error;
  BOOST_REQUIRE_MESSAGE(SMSO::IO::read_OBJ_with_uv_map(is, back, back_uv, error), error);
  check_against(c, back, back_uv);

  // Writing what was read gives the same file: nothing drifts.
  std::ostringstream os2;
  BOOST_REQUIRE(SMSO::IO::write_OBJ_with_uv_map(os2, back, back_uv));
  BOOST_CHECK(os2.str() == text);
}

BOOST_AUTO_TEST_CASE(polyhedron_with_associative_uv_map)
{
  typedef CGAL::Polyhedron_3<K> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::halfedge_descriptor P_halfedge;
  Cylinder c;
  Polyhedron poly;
  std::map<P_halfedge, Point_2> uv_storage;
  boost::associative_property_map<std::map<P_halfedge, Point_2> > uv(uv_storage);
  build(c, poly, uv);

  std::ostringstream os;
  BOOST_REQUIRE(SMSO::IO::write_OBJ_with_uv_map(os, poly, uv));
  BOOST_CHECK_EQUAL(count_lines(os.str(), "vt "), c.expected_vt());

  Mesh back;
  UV_map back_uv = back.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  std::istringstream is(os.str());
  std::string error;
  BOOST_REQUIRE_MESSAGE(SMSO::IO::read_OBJ_with_uv_map(is, back, back_uv, error), error);
  check_against(c, back, back_uv);
}

BOOST_AUTO_TEST_CASE(reader_accepts_obj_variants)
{
  // v/vt/vn corners, negative (relative) indices, comments and other lines.
  const std::string text =
    "# comment\n"
    "mtllib x.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
    "vt 0.5 0.25\nvt 1 0\nvt 0 1\n"
    "vn 0 0 1\n"
    "usemtl m\n"
    "f -3/-3/1 2/-2/1 3/3/1\n";
  Mesh m;
  UV_map uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  std::istringstream is(text);
  std::string error;
  BOOST_REQUIRE_MESSAGE(SMSO::IO::read_OBJ_with_uv_map(is, m, uv, error), error);
  BOOST_REQUIRE_EQUAL(num_faces(m), 1u);
  for(halfedge_descriptor h : halfedges_around_face(halfedge(*faces(m).begin(), m), m))
  {
    const Point_3& p = m.point(target(h, m));
    const Point_2 expected = p == Point_3(0, 0, 0) ? Point_2(0.5, 0.25)
                           : p == Point_3(1, 0, 0) ? Point_2(1, 0) : Point_2(0, 1);
    BOOST_CHECK(get(uv, h) == expected);
  }
}

BOOST_AUTO_TEST_CASE(reader_rejects_bad_input_with_a_reason)
{
  const std::vector<std::pair<std::string, std::string> > cases = {
    {"no vt", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"},
    {"no vt index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1//1 2//1 3//1\n"},
    {"vertex index out of range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 4/1\n"},
    {"vt index out of range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/2\n"},
    {"bad vertex", "v 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n"},
    {"no face", "v 0 0 0\nvt 0 0\n"},
    {"two-corner face", "v 0 0 0\nv 1 0 0\nvt 0 0\nf 1/1 2/1\n"},
    // three triangles on one edge
    {"non-manifold edge",
     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nvt 0 0\n"
     "f 1/1 2/1 3/1\nf 2/1 1/1 4/1\nf 1/1 2/1 5/1\n"},
  };
  for(const auto& c : cases)
  {
    Mesh m;
    UV_map uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
    std::istringstream is(c.second);
    std::string error;
    BOOST_CHECK_MESSAGE(!SMSO::IO::read_OBJ_with_uv_map(is, m, uv, error),
                        "accepted invalid input: " << c.first);
    BOOST_CHECK_MESSAGE(!error.empty(), "no reason given for: " << c.first);
  }

  Mesh m;
  UV_map uv = m.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  std::string error;
  BOOST_CHECK(!SMSO::IO::read_OBJ_with_uv_map(std::string("/nonexistent/dir/x.obj"), m, uv, error));
  BOOST_CHECK(error.find("cannot open") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(write_to_unwritable_file_fails)
{
  Cylinder c;
  Mesh mesh;
  UV_map uv = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  build(c, mesh, uv);
  BOOST_CHECK(!SMSO::IO::write_OBJ_with_uv_map(std::string("/nonexistent/dir/x.obj"), mesh, uv));
}
