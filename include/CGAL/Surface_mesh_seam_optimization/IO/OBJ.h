// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Wavefront OBJ with a per-corner UV map (`v`, `vt`, `f v/vt`). CGAL's own OBJ
// IO drops texture coordinates, hence this small reader and writer.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_IO_OBJ_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_IO_OBJ_H

#include <CGAL/Surface_mesh_seam_optimization/parameters.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace IO {

namespace internal {

inline void append_double(std::string& out, double x)
{
  // %.17g round-trips every double exactly.
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", x);
  out += buf;
}

// Parses one OBJ index ("12", "-3"); relative indices count back from `count`.
// Returns false on junk or when the index is out of [1, count].
inline bool parse_obj_index(const std::string& s, std::size_t count, std::size_t& index)
{
  if(s.empty())
    return false;
  char* end = nullptr;
  long long i = std::strtoll(s.c_str(), &end, 10);
  if(*end != '\0')
    return false;
  if(i < 0)
    i += static_cast<long long>(count) + 1;
  if(i < 1 || i > static_cast<long long>(count))
    return false;
  index = static_cast<std::size_t>(i - 1);
  return true;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshSeamOptimizationIO
/// Writes `tm` with its per-corner UV map as OBJ: one `v` per vertex, one
/// `vt` per distinct UV of a vertex (corners of the same vertex with equal
/// UVs share it, so seams show as split `vt`), and `f v/vt v/vt v/vt` in the
/// orientation of `tm`. Coordinates are written with 17 significant digits.
///
/// `uvmap`: `halfedge_descriptor -> Point_2`, `get(uvmap, h)` the UV of
/// `target(h)` in `face(h)`.
/// \param np an optional sequence of named parameters among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points written}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return `false` when the stream fails.
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
bool write_OBJ_with_uv_map(std::ostream& os, const TriangleMesh& tm, UVMap uvmap,
                           const NamedParameters& np = parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh>              GT;
  typedef typename GT::vertex_descriptor                 vertex_descriptor;
  typedef typename GT::halfedge_descriptor               halfedge_descriptor;
  typedef typename GT::face_descriptor                   face_descriptor;
  typedef typename boost::property_traits<UVMap>::value_type Point_2;

  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, tm));

  // Dense 0-based vertex numbers in iteration order (works for any FaceGraph).
  auto vindex = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::string out;
  out.reserve(64 * (num_vertices(tm) + 2 * num_faces(tm)));
  out += "# OBJ with per-corner texture coordinates (Surface_mesh_seam_optimization)\n";
  std::size_t nv = 0;
  for(vertex_descriptor v : vertices(tm))
  {
    put(vindex, v, nv++);
    const auto& p = get(vpm, v);
    out += "v ";
    internal::append_double(out, CGAL::to_double(p.x()));
    out += ' ';
    internal::append_double(out, CGAL::to_double(p.y()));
    out += ' ';
    internal::append_double(out, CGAL::to_double(p.z()));
    out += '\n';
  }

  // Per vertex, the distinct UVs seen so far with their vt number; a vertex
  // has one UV per incident chart, so a linear scan is enough.
  std::vector<std::vector<std::pair<Point_2, std::size_t> > > uvs_of_vertex(nv);
  std::vector<Point_2> vts;
  std::vector<std::size_t> face_corners; // (v, vt) pairs, faces separated by sizes
  std::vector<std::size_t> face_sizes;
  face_sizes.reserve(num_faces(tm));
  face_corners.reserve(6 * num_faces(tm));
  for(face_descriptor f : faces(tm))
  {
    std::size_t n = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
    {
      const std::size_t vi = get(vindex, target(h, tm));
      const Point_2 uv = get(uvmap, h);
      std::size_t t = vts.size();
      for(const auto& known : uvs_of_vertex[vi])
        if(known.first.x() == uv.x() && known.first.y() == uv.y())
        {
          t = known.second;
          break;
        }
      if(t == vts.size())
      {
        uvs_of_vertex[vi].emplace_back(uv, t);
        vts.push_back(uv);
      }
      face_corners.push_back(vi);
      face_corners.push_back(t);
      ++n;
    }
    face_sizes.push_back(n);
  }

  for(const Point_2& uv : vts)
  {
    out += "vt ";
    internal::append_double(out, CGAL::to_double(uv.x()));
    out += ' ';
    internal::append_double(out, CGAL::to_double(uv.y()));
    out += '\n';
  }
  std::size_t k = 0;
  for(std::size_t n : face_sizes)
  {
    out += 'f';
    for(std::size_t i = 0; i < n; ++i, k += 2)
    {
      out += ' ';
      out += std::to_string(face_corners[k] + 1);
      out += '/';
      out += std::to_string(face_corners[k + 1] + 1);
    }
    out += '\n';
  }
  os.write(out.data(), static_cast<std::streamsize>(out.size()));
  os.flush();
  return static_cast<bool>(os);
}

/// \ingroup PkgSurfaceMeshSeamOptimizationIO
/// Same as above, to the file `fname`.
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
bool write_OBJ_with_uv_map(const std::string& fname, const TriangleMesh& tm, UVMap uvmap,
                           const NamedParameters& np = parameters::default_values())
{
  std::ofstream os(fname, std::ios::binary);
  if(!os)
    return false;
  return write_OBJ_with_uv_map(os, tm, uvmap, np) && static_cast<bool>(os);
}

/// \ingroup PkgSurfaceMeshSeamOptimizationIO
/// Reads an OBJ with `v`, `vt` and `f v/vt ...` (also `v/vt/vn`, negative
/// indices; other lines ignored) into the empty mesh `tm` and writes the UV
/// of every face corner into `uvmap`. Every face corner must have a `vt`,
/// and the faces must form a combinatorial manifold (as CGAL requires).
/// Faces are added in file order and vertices in `v` order.
/// \param np an optional sequence of named parameters among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{where the points read are put}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \return `false`, with the reason in `error`, on any problem; `tm` is then
/// left in an unspecified state.
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
bool read_OBJ_with_uv_map(std::istream& is, TriangleMesh& tm, UVMap uvmap, std::string& error,
                          const NamedParameters& np = parameters::default_values())
{
  typedef boost::graph_traits<TriangleMesh>              GT;
  typedef typename GT::vertex_descriptor                 vertex_descriptor;
  typedef typename GT::halfedge_descriptor               halfedge_descriptor;
  typedef typename GT::face_descriptor                   face_descriptor;
  typedef typename boost::property_traits<UVMap>::value_type Point_2;

  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_property_map(CGAL::vertex_point, tm));
  typedef typename boost::property_traits<decltype(vpm)>::value_type Point_3;

  std::vector<std::array<double, 3> > points;
  std::vector<std::array<double, 2> > uvs;
  std::vector<std::vector<std::size_t> > polygons, polygon_uvs;

  std::string line, tag, corner;
  std::size_t line_number = 0;
  auto fail = [&](const std::string& what) {
    error = "line " + std::to_string(line_number) + ": " + what;
    return false;
  };
  while(std::getline(is, line))
  {
    ++line_number;
    std::istringstream ls(line);
    if(!(ls >> tag))
      continue;
    if(tag == "v")
    {
      std::array<double, 3> p;
      if(!(ls >> p[0] >> p[1] >> p[2]))
        return fail("bad vertex");
      points.push_back(p);
    }
    else if(tag == "vt")
    {
      std::array<double, 2> t;
      if(!(ls >> t[0] >> t[1]))
        return fail("bad texture coordinate");
      uvs.push_back(t);
    }
    else if(tag == "f")
    {
      std::vector<std::size_t> poly, poly_uv;
      while(ls >> corner)
      {
        const std::size_t s1 = corner.find('/');
        if(s1 == std::string::npos)
          return fail("face corner without texture coordinate: '" + corner + "'");
        const std::size_t s2 = corner.find('/', s1 + 1);
        std::size_t vi, ti;
        if(!internal::parse_obj_index(corner.substr(0, s1), points.size(), vi))
          return fail("bad vertex index in '" + corner + "'");
        const std::string t = corner.substr(s1 + 1, s2 == std::string::npos ? std::string::npos
                                                                             : s2 - s1 - 1);
        if(t.empty())
          return fail("face corner without texture coordinate: '" + corner + "'");
        if(!internal::parse_obj_index(t, uvs.size(), ti))
          return fail("bad texture coordinate index in '" + corner + "'");
        poly.push_back(vi);
        poly_uv.push_back(ti);
      }
      if(poly.size() < 3)
        return fail("face with fewer than three corners");
      polygons.push_back(std::move(poly));
      polygon_uvs.push_back(std::move(poly_uv));
    }
  }
  if(is.bad())
  {
    error = "read error";
    return false;
  }
  if(polygons.empty())
  {
    error = "no face";
    return false;
  }
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
  {
    error = "the faces do not form a manifold mesh (non-manifold edge or vertex, or "
            "inconsistent orientation)";
    return false;
  }

  std::vector<vertex_descriptor> vds;
  vds.reserve(points.size());
  for(const auto& p : points)
  {
    vertex_descriptor v = add_vertex(tm);
    put(vpm, v, Point_3(p[0], p[1], p[2]));
    vds.push_back(v);
  }
  std::vector<vertex_descriptor> fv;
  for(std::size_t i = 0; i < polygons.size(); ++i)
  {
    fv.clear();
    for(std::size_t vi : polygons[i])
      fv.push_back(vds[vi]);
    face_descriptor f = CGAL::Euler::add_face(fv, tm);
    if(f == GT::null_face())
    {
      error = "face " + std::to_string(i + 1) + " cannot be added (non-manifold)";
      return false;
    }
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
    {
      const vertex_descriptor t = target(h, tm);
      for(std::size_t j = 0; j < fv.size(); ++j)
        if(fv[j] == t)
        {
          const auto& uv = uvs[polygon_uvs[i][j]];
          put(uvmap, h, Point_2(uv[0], uv[1]));
          break;
        }
    }
  }
  return true;
}

/// \ingroup PkgSurfaceMeshSeamOptimizationIO
/// Same as above, from the file `fname`.
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
bool read_OBJ_with_uv_map(const std::string& fname, TriangleMesh& tm, UVMap uvmap,
                          std::string& error,
                          const NamedParameters& np = parameters::default_values())
{
  std::ifstream is(fname, std::ios::binary);
  if(!is)
  {
    error = "cannot open '" + fname + "'";
    return false;
  }
  if(!read_OBJ_with_uv_map(is, tm, uvmap, error, np))
  {
    error = fname + ": " + error;
    return false;
  }
  return true;
}

} // namespace IO
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_IO_OBJ_H
