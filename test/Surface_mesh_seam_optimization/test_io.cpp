// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// OBJ with per-corner UVs: write then read back, vt deduplication, reader
// errors; optimize_seams' input loading (cli/load_mesh.h) under a few hundred
// deterministic mutations of small OBJ, OFF, PLY and STL files.

#define BOOST_TEST_MODULE io
#include <boost/test/unit_test.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/IO/OBJ.h>

#include "../../cli/load_mesh.h"

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <unistd.h>

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
    {"float vertex index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1.5/1 2/1 3/1\n"},
    {"trailing junk", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1 junk\n"},
    {"absurd index", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 99999999999999999999/1\n"},
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

// ---------------------------------------------------------------------------
// Fuzzing optimize_seams' loader (the code the program runs: cli/load_mesh.h).

namespace {

namespace CLI = optimize_seams_cli;

// A 3x3 grid (a disk) in each format: quads and triangles in the OBJ.
std::vector<std::array<double, 3> > grid_points()
{
  std::vector<std::array<double, 3> > p;
  for(int j = 0; j < 4; ++j)
    for(int i = 0; i < 4; ++i)
      p.push_back({i / 3.0, j / 3.0, 0.1 * ((i * j) % 2)});
  return p;
}
std::vector<std::array<int, 3> > grid_triangles()
{
  std::vector<std::array<int, 3> > t;
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i)
    {
      const int a = 4 * j + i;
      t.push_back({a, a + 1, a + 5});
      t.push_back({a, a + 5, a + 4});
    }
  return t;
}

std::string seed_obj()
{
  std::ostringstream os;
  os << "# grid\no grid\n";
  for(const auto& p : grid_points())
    os << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
  os << "vt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n";
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i)
    {
      const int a = 4 * j + i + 1;
      if((i + j) % 2)
        os << "f " << a << "/1/1 " << a + 1 << "/2/1 " << a + 5 << "/3/1 " << a + 4 << "/1/1\n";
      else
        os << "f " << a << "/1 " << a + 1 << "/2 " << a + 5 << "/3\nf " << a - 17 << "/-3/1 " << a + 5 - 17
           << "/3/1 " << a + 4 - 17 << "/1/1\n";   // relative vertex and vt numbers
    }
  return os.str();
}

std::string seed_off()
{
  std::ostringstream os;
  os << "OFF\n# grid\n16 18 0\n";
  for(const auto& p : grid_points())
    os << p[0] << " " << p[1] << " " << p[2] << "\n";
  for(const auto& t : grid_triangles())
    os << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  return os.str();
}

std::string seed_ply_ascii()
{
  std::ostringstream os;
  os << "ply\nformat ascii 1.0\ncomment grid\nelement vertex 16\nproperty float x\nproperty float y\n"
        "property float z\nelement face 18\nproperty list uchar int vertex_indices\nend_header\n";
  for(const auto& p : grid_points())
    os << p[0] << " " << p[1] << " " << p[2] << "\n";
  for(const auto& t : grid_triangles())
    os << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  return os.str();
}

// Binary, with a color per vertex and an element that is read past.
std::string seed_ply_binary()
{
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex 16\nproperty double x\n"
                  "property double y\nproperty double z\nproperty uchar red\nelement face 18\n"
                  "property list uchar int vertex_indices\nelement edge 1\nproperty int vertex1\n"
                  "property int vertex2\nend_header\n";
  auto put = [&s](const void* p, std::size_t n) {
    // little endian on the machines the suite runs on (x86-64, aarch64)
    s.append(static_cast<const char*>(p), n);
  };
  for(const auto& p : grid_points())
  {
    put(p.data(), 24);
    const unsigned char red = 200;
    put(&red, 1);
  }
  for(const auto& t : grid_triangles())
  {
    const unsigned char n = 3;
    put(&n, 1);
    for(int v : t)
    {
      const std::int32_t i = v;
      put(&i, 4);
    }
  }
  const std::int32_t e[2] = {0, 1};
  put(e, 8);
  return s;
}

// The grid as an STL triangle soup: three points per facet, shared points
// written again each time (the reader merges them).
std::string seed_stl_ascii()
{
  std::ostringstream os;
  os << "solid grid\n";
  const auto p = grid_points();
  for(const auto& t : grid_triangles())
  {
    os << "  facet normal 0 0 1\n    outer loop\n";
    for(int v : t)
      os << "      vertex " << p[v][0] << " " << p[v][1] << " " << p[v][2] << "\n";
    os << "    endloop\n  endfacet\n";
  }
  os << "endsolid grid\n";
  return os.str();
}

// Binary: its 80-byte header begins with "solid", as some writers' do.
std::string seed_stl_binary()
{
  std::string s = "solid grid (binary)";
  s.resize(80, ' ');
  const auto p = grid_points();
  const std::uint32_t n = static_cast<std::uint32_t>(grid_triangles().size());
  s.append(reinterpret_cast<const char*>(&n), 4);   // little endian (x86-64, aarch64)
  for(const auto& t : grid_triangles())
  {
    const float normal[3] = {0.f, 0.f, 1.f};
    s.append(reinterpret_cast<const char*>(normal), 12);
    for(int v : t)
      for(int k = 0; k < 3; ++k)
      {
        const float x = static_cast<float>(p[v][k]);
        s.append(reinterpret_cast<const char*>(&x), 4);
      }
    s.append(2, '\0');
  }
  return s;
}

// One deterministic mutation of `s` (the generator's raw output only: the
// standard distributions are not the same on every library).
std::string mutate(const std::string& s, std::mt19937& rng, bool binary)
{
  static const char* const hostile[] = {"2000000000", "-1", "0", "99999999999999999999", "1.5", "nan", "inf",
                                        "-inf", "1e308", "-2147483648", "4294967295", "", "1/", "//", "x"};
  std::string t = s;
  const auto pick = [&rng](std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng() % n); };
  const std::size_t kind = pick(binary ? 8 : 7);
  switch(kind)
  {
    case 0:   // truncation
      t.resize(pick(t.size()));
      break;
    case 1:   // byte flips
      for(std::size_t k = 0, n = 1 + pick(4); k < n && !t.empty(); ++k)
        t[pick(t.size())] ^= static_cast<char>(1 + pick(255));
      break;
    case 2: case 3:   // a number replaced by a hostile one (in the header half the time)
    {
      std::vector<std::pair<std::size_t, std::size_t> > numbers;
      for(std::size_t i = 0; i < t.size();)
        if(std::isdigit(static_cast<unsigned char>(t[i])) || t[i] == '-')
        {
          std::size_t j = i;
          while(j < t.size() && (std::isdigit(static_cast<unsigned char>(t[j])) || t[j] == '.' || t[j] == '-' ||
                                 t[j] == 'e'))
            ++j;
          numbers.emplace_back(i, j - i);
          i = j;
        }
        else
          ++i;
      if(numbers.empty())
        break;
      const std::size_t limit = kind == 2 ? (std::min<std::size_t>)(numbers.size(), 6) : numbers.size();
      const auto n = numbers[pick(limit)];
      t.replace(n.first, n.second, hostile[pick(sizeof(hostile) / sizeof(hostile[0]))]);
      break;
    }
    case 4:   // binary garbage
    {
      std::string g;
      for(std::size_t k = 0, n = 1 + pick(32); k < n; ++k)
        g += static_cast<char>(rng() & 0xff);
      t.insert(pick(t.size() + 1), g);
      break;
    }
    case 5:   // a line deleted or repeated (a field or a count goes missing)
    {
      std::vector<std::size_t> starts{0};
      for(std::size_t i = 0; i < t.size(); ++i)
        if(t[i] == '\n')
          starts.push_back(i + 1);
      const std::size_t l = pick(starts.size());
      const std::size_t b = starts[l], e = l + 1 < starts.size() ? starts[l + 1] : t.size();
      const std::string line = t.substr(b, e - b);
      if(rng() % 2)
        t.erase(b, e - b);
      else
        t.insert(b, line);
      break;
    }
    case 6:   // a token deleted
    {
      const std::size_t i = pick(t.size());
      std::size_t j = i;
      while(j < t.size() && t[j] != ' ' && t[j] != '\n')
        ++j;
      t.erase(i, j - i);
      break;
    }
    default:  // binary: a 32-bit field after the header set to a huge or negative value
    {
      const std::size_t body = t.find("end_header\n");
      if(body == std::string::npos || t.size() < body + 16)
        break;
      const std::size_t at = body + 11 + pick(t.size() - body - 15);
      const std::uint32_t v = rng() % 2 ? 0x7fffffffu : 0xffffffffu;
      std::memcpy(&t[at], &v, 4);
      break;
    }
  }
  return t;
}

// Caps the address space (a runaway allocation then fails as bad_alloc
// instead of taking the machine's memory) for the lifetime of the object;
// not under AddressSanitizer, which reserves terabytes of address space.
struct Address_space_cap
{
  struct rlimit old;
  bool set = false;
  explicit Address_space_cap(std::size_t extra_bytes)
  {
#if defined(__SANITIZE_ADDRESS__)
    (void)extra_bytes;
#else
    std::size_t pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    if(pages > 0 && getrlimit(RLIMIT_AS, &old) == 0)
    {
      struct rlimit cap = old;
      cap.rlim_cur = static_cast<rlim_t>(pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE)) + extra_bytes);
      if(old.rlim_cur == RLIM_INFINITY || cap.rlim_cur < old.rlim_cur)
        set = setrlimit(RLIMIT_AS, &cap) == 0;
    }
#endif
  }
  ~Address_space_cap()
  {
    if(set)
      setrlimit(RLIMIT_AS, &old);
  }
};

std::size_t max_rss_kb()
{
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  return static_cast<std::size_t>(ru.ru_maxrss);
}

} // namespace

// An STL soup becomes the mesh its OFF describes: equal points merged (the
// grid's 54 corners are its 16 vertices), numbered in order of first
// appearance, facets connected; a broken file names what is wrong.
BOOST_AUTO_TEST_CASE(stl_soups_load_as_connected_meshes)
{
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("smso_stl_" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(dir);
  auto load = [&](const std::string& name, const std::string& text, CLI::Mesh& mesh, CLI::Load_failure& failure) {
    const std::string path = dir + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    std::vector<std::string> notes;
    return CLI::load_mesh(path, mesh, notes, failure);
  };
  const auto p = grid_points();
  for(const std::string& text : {seed_stl_ascii(), seed_stl_binary()})
  {
    CLI::Mesh mesh;
    CLI::Load_failure failure;
    BOOST_REQUIRE_MESSAGE(load("grid.stl", text, mesh, failure), failure.line);
    BOOST_CHECK_EQUAL(num_vertices(mesh), 16u);
    BOOST_CHECK_EQUAL(num_faces(mesh), 18u);
    BOOST_CHECK_EQUAL(num_edges(mesh), 33u);   // 16 - 33 + 18 = 1: one disk, not 18 loose triangles
    // first appearance: the first facet (0, 1, 5) gives vertices 0, 1, 2
    const int first[3] = {0, 1, 5};
    for(int k = 0; k < 3; ++k)
      BOOST_CHECK_CLOSE(mesh.point(CLI::Mesh::Vertex_index(k)).x() + 1., p[first[k]][0] + 1., 1e-3);
  }
  CLI::Mesh mesh;
  CLI::Load_failure failure;
  std::string broken = seed_stl_ascii();
  broken.resize(broken.rfind("endsolid"));
  BOOST_CHECK(!load("no_end.stl", broken, mesh, failure));
  BOOST_CHECK_MESSAGE(failure.line.find("without 'endsolid'") != std::string::npos, failure.line);
  std::string bad_vertex = seed_stl_ascii();
  bad_vertex.replace(bad_vertex.find("vertex"), 6, "vortex");
  BOOST_CHECK(!load("vortex.stl", bad_vertex, mesh, failure));
  BOOST_CHECK_MESSAGE(failure.line.find("line 4: 'vertex' expected") != std::string::npos, failure.line);
  std::string short_binary = seed_stl_binary();
  short_binary.pop_back();   // 84 + 50 n + 49 bytes: neither binary nor ASCII
  BOOST_CHECK(!load("short.stl", short_binary, mesh, failure));
  BOOST_CHECK_MESSAGE(failure.line.find("not an STL file") != std::string::npos, failure.line);
  std::string nan_point = seed_stl_ascii();
  nan_point.replace(nan_point.find("vertex ") + 7, 1, "nan");
  BOOST_CHECK(!load("nan.stl", nan_point, mesh, failure));
  BOOST_CHECK_EQUAL(failure.status, "ERROR_NON_FINITE_COORDINATES");
  std::filesystem::remove_all(dir);
}

// Every mutation is refused with one clean line (no control character) or
// gives a valid triangle mesh, within 0.5 s each and without a memory spike
// (the unfixed readers took 15.6 GB for a 98-byte OFF). Under a sanitizer
// the bound is ASan's.
BOOST_AUTO_TEST_CASE(loader_survives_mutated_files)
{
  const std::pair<std::string, std::string> seeds[] = {
    {".obj", seed_obj()}, {".off", seed_off()}, {".ply", seed_ply_ascii()}, {".ply", seed_ply_binary()},
    {".stl", seed_stl_ascii()}, {".stl", seed_stl_binary()}};
  const int n_seeds = int(sizeof(seeds) / sizeof(seeds[0]));
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("smso_fuzz_" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(dir);

  // The seeds themselves load, as the 18 triangles of the grid.
  for(const auto& seed : seeds)
  {
    const std::string path = dir + "/seed" + seed.first;
    std::ofstream(path, std::ios::binary) << seed.second;
    CLI::Mesh mesh;
    std::vector<std::string> notes;
    CLI::Load_failure failure;
    BOOST_REQUIRE_MESSAGE(CLI::load_mesh(path, mesh, notes, failure), path << ": " << failure.line);
    BOOST_CHECK_EQUAL(num_faces(mesh), 18u);
    BOOST_CHECK_EQUAL(num_vertices(mesh), 16u);
  }

  const std::set<std::string> statuses = {"ERROR_INPUT", "ERROR_EMPTY_MESH", "ERROR_NON_FINITE_COORDINATES",
                                          "ERROR_DEGENERATE_TRIANGLE", "ERROR_NON_MANIFOLD_MESH",
                                          "ERROR_NON_TRIANGULAR_MESH"};
  std::mt19937 rng(20261125);
  const Address_space_cap cap(std::size_t(1) << 30);
  const std::size_t rss_before = max_rss_kb();
  std::size_t accepted = 0, refused = 0, repaired = 0, with_uv = 0;
  double slowest = 0;
  const int per_seed = 250;
  for(int k = 0; k < n_seeds * per_seed; ++k)
  {
    const auto& seed = seeds[k % n_seeds];
    const std::string text = mutate(seed.second, rng, k % n_seeds == 3 || k % n_seeds == 5);
    const std::string path = dir + "/m" + std::to_string(k) + seed.first;
    std::ofstream(path, std::ios::binary) << text;
    for(int repair = 0; repair < 2; ++repair)
    {
      CLI::Mesh mesh;
      std::vector<std::string> notes;
      CLI::Load_failure failure;
      CLI::Repair_summary summary;
      const auto t0 = std::chrono::steady_clock::now();
      bool ok = false;
      try
      {
        ok = CLI::load_mesh(path, mesh, notes, failure, repair ? &summary : nullptr);
      }
      catch(const std::exception& e)
      {
        BOOST_ERROR("mutation " << k << " (" << path << "): exception " << e.what());
        continue;
      }
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      slowest = (std::max)(slowest, s);
      BOOST_CHECK_MESSAGE(s < 0.5, "mutation " << k << " took " << s << " s");
      if(ok)
      {
        bool finite = true, zero_area = false;
        for(auto v : vertices(mesh))
          finite = finite && std::isfinite(mesh.point(v).x()) && std::isfinite(mesh.point(v).y()) &&
                   std::isfinite(mesh.point(v).z());
        for(auto f : faces(mesh))
          zero_area = zero_area || CLI::is_zero_area_face(f, mesh);
        BOOST_CHECK_MESSAGE(CGAL::is_valid_polygon_mesh(mesh) && CGAL::is_triangle_mesh(mesh) &&
                              num_faces(mesh) > 0 && finite && !zero_area,
                            "mutation " << k << " (" << path << ") loaded an invalid mesh");
        ++(repair ? repaired : accepted);
      }
      else
      {
        const bool printable = std::none_of(failure.line.begin(), failure.line.end(), [](char c) {
          return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
        });
        BOOST_CHECK_MESSAGE(!failure.line.empty() && printable && statuses.count(failure.status) == 1,
                            "mutation " << k << ": bad failure '" << failure.status << "' '" << failure.line
                                        << "'");
        refused += repair ? 0 : 1;
      }
    }
    if(seed.first == ".obj")
    {
      // --use-input-uv's reader on the same text
      CLI::Mesh mesh;
      auto uv = mesh.add_property_map<CLI::halfedge_descriptor, CLI::Point_2>("h:uv").first;
      CLI::Load_failure failure;
      if(CLI::load_mesh_with_uv_map(path, mesh, uv, failure))
        ++with_uv;
      else
        BOOST_CHECK(!failure.line.empty() && failure.line.find('\n') == std::string::npos);
    }
    std::filesystem::remove(path);
  }
  std::filesystem::remove_all(dir);
  const std::size_t grown_mb = (max_rss_kb() - rss_before) / 1024;
  BOOST_TEST_MESSAGE("fuzz: " << n_seeds * per_seed << " mutations, " << accepted << " accepted, " << refused
                     << " refused, " << repaired << " accepted with --repair, " << with_uv
                     << " read with their UVs; slowest " << slowest << " s; peak memory grew by " << grown_mb
                     << " MB");
  // The mutations are varied enough to exercise both outcomes.
  BOOST_CHECK(accepted > 100 && refused > 500 && with_uv > 20);
  BOOST_CHECK_GE(repaired, accepted);
  BOOST_CHECK_LT(grown_mb, 200u);
}
