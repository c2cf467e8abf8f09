// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// optimize_seams' input: reads a mesh file with bounded work
// (read_polygon_soup_bounded.h), checks it (or repairs it with --repair) and
// builds the triangle mesh, or says in one line what is wrong. A header of its
// own so that test_io.cpp fuzzes the very code the program runs.

#ifndef SMSO_CLI_LOAD_MESH_H
#define SMSO_CLI_LOAD_MESH_H

#include "read_polygon_soup_bounded.h"
#include "repair_input.h"
#include "run_optimization.h"
#include "seam_weights.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/IO/OBJ.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace optimize_seams_cli {

struct Load_failure
{
  std::string status;   // Error_code name, or ERROR_INPUT when the file itself is the problem
  std::string line;     // the stderr message after "optimize_seams: error: "
};

inline std::string lowercase_extension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

inline Load_failure code_failure(SMSO::Error_code code, const std::string& line)
{
  return Load_failure{SMSO::get_error_code_name(code), line};
}

namespace internal {

// The file exists, is a regular file, can be opened and is not empty.
inline bool check_input_file(const std::string& path, Load_failure& failure)
{
  std::error_code ec;
  if(!std::filesystem::exists(path, ec))
  {
    failure = {"ERROR_INPUT", "cannot open input '" + path + "': No such file or directory"};
    return false;
  }
  if(!std::filesystem::is_regular_file(path, ec))
  {
    failure = {"ERROR_INPUT", "cannot open input '" + path + "': not a regular file"};
    return false;
  }
  {
    std::ifstream probe(path, std::ios::binary);
    if(!probe)
    {
      failure = {"ERROR_INPUT", "cannot open input '" + path + "': " + std::strerror(errno)};
      return false;
    }
  }
  if(std::filesystem::file_size(path, ec) == 0 && !ec)
  {
    failure = code_failure(SMSO::ERROR_EMPTY_MESH, "input mesh is empty (no face): '" + path + "'");
    return false;
  }
  return true;
}

} // namespace internal

// Reads a polygon soup (so that defects can be named, where read_polygon_mesh
// would only say "false"), checks it, and builds a triangle mesh. With
// `repair`, fixes what Polygon_mesh_processing can fix instead of refusing
// it, and counts the changes in `repair`. Faces are numbered from 1 in file
// order in every message. Returns true on success; otherwise `failure` says
// why. Without `repair`, `file_vertex` (if given) receives the mesh vertex
// index of each of the file's vertices (no_mesh_vertex: used by no face).
inline bool load_mesh(const std::string& path, Mesh& mesh, std::vector<std::string>& notes,
                      Load_failure& failure, Repair_summary* repair = nullptr,
                      std::vector<std::size_t>* file_vertex = nullptr)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  // What an error line adds when --repair would have fixed the defect.
  const std::string try_repair = repair ? "" : " (--repair fixes this)";
  if(!internal::check_input_file(path, failure))
    return false;
  const std::string ext = lowercase_extension(path);
  if(ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
  {
    failure = {"ERROR_INPUT", "cannot read '" + path + "': unsupported format '" + ext +
                              "' (expected .obj, .off, .ply or .stl)"};
    return false;
  }

  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::string error;
  if(!read_polygon_soup_bounded(path, ext, points, polygons, error))
  {
    failure = {"ERROR_INPUT", "cannot read '" + path + "': " + error};
    return false;
  }
  if(polygons.empty() || points.empty())
  {
    failure = code_failure(SMSO::ERROR_EMPTY_MESH, "input mesh is empty (no face): '" + path + "'");
    return false;
  }

  if(repair)
  {
    repair_polygon_soup(points, polygons, *repair);
    if(polygons.empty())
    {
      failure = code_failure(SMSO::ERROR_EMPTY_MESH, "input mesh has no valid face left after --repair ('" +
                                                       path + "')");
      return false;
    }
  }

  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const Point_3& p = points[i];
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
    {
      failure = code_failure(SMSO::ERROR_NON_FINITE_COORDINATES,
                             "input has a non-finite coordinate (vertex " + std::to_string(i + 1) + ")" +
                               try_repair);
      return false;
    }
  }

  bool has_polygons = false;
  std::vector<char> used(points.size(), 0);
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    const auto& poly = polygons[f];
    if(poly.size() < 3)
    {
      failure = code_failure(SMSO::ERROR_DEGENERATE_TRIANGLE,
                             "input face " + std::to_string(f + 1) + " has fewer than three corners" + try_repair);
      return false;
    }
    // (CGAL's soup functions need distinct corners: a face "0 1 0 2" made
    // orient_polygon_soup() loop forever)
    std::vector<std::size_t> sorted(poly.begin(), poly.end());
    std::sort(sorted.begin(), sorted.end());
    const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
    if(repeated != sorted.end())
    {
      failure = code_failure(SMSO::ERROR_DEGENERATE_TRIANGLE,
                             "input face " + std::to_string(f + 1) + " has vertex " + std::to_string(*repeated) +
                               " (numbered from 0) at two of its corners" + try_repair);
      return false;
    }
    has_polygons = has_polygons || poly.size() > 3;
    for(std::size_t v : poly)
      used[v] = 1;
  }

  // Zero-area triangles make the distortion energy infinite: refuse them here
  // with the face number, rather than deep inside the solver. (--repair
  // removes them from the mesh below.) Polygons are checked once triangulated.
  std::size_t degenerate = 0, first_degenerate = 0;
  for(std::size_t f = 0; f < polygons.size() && !repair; ++f)
  {
    const auto& poly = polygons[f];
    if(poly.size() == 3 && is_zero_area_triangle(points[poly[0]], points[poly[1]], points[poly[2]]) &&
       degenerate++ == 0)
      first_degenerate = f;
  }
  if(degenerate > 0)
  {
    failure = code_failure(SMSO::ERROR_DEGENERATE_TRIANGLE,
                           "input has " + std::to_string(degenerate) +
                           " zero-area (degenerate) triangle(s); the first is face " +
                           std::to_string(first_degenerate + 1) + try_repair);
    return false;
  }

  // Unreferenced points would become isolated vertices: drop them.
  const std::size_t unused = static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
  if(file_vertex)
  {
    // polygon_soup_to_polygon_mesh() adds the points as vertices in order
    file_vertex->assign(points.size(), no_mesh_vertex);
    for(std::size_t i = 0, kept = 0; i < points.size(); ++i)
      if(used[i]) (*file_vertex)[i] = kept++;
  }
  if(unused > 0)
  {
    std::vector<std::size_t> new_index(points.size());
    std::vector<Point_3> kept;
    kept.reserve(points.size() - unused);
    for(std::size_t i = 0; i < points.size(); ++i)
      if(used[i])
      {
        new_index[i] = kept.size();
        kept.push_back(points[i]);
      }
    for(auto& poly : polygons)
      for(std::size_t& v : poly)
        v = new_index[v];
    points.swap(kept);
    notes.push_back("ignored " + std::to_string(unused) + " vertices used by no face");
  }

  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    // Inconsistent orientation is fixable; a non-manifold edge or vertex is
    // not, unless --repair lets orient_polygon_soup duplicate points.
    std::vector<Point_3> oriented_points = points;
    std::vector<std::vector<std::size_t> > oriented = polygons;
    const bool no_duplication = PMP::orient_polygon_soup(oriented_points, oriented);
    if(no_duplication && oriented_points.size() == points.size() &&
       PMP::is_polygon_soup_a_polygon_mesh(oriented))
    {
      polygons.swap(oriented);
      notes.push_back("reoriented faces to a consistent orientation");
    }
    else if(repair && orient_polygon_soup_duplicating(points, polygons, *repair))
    {
    }
    else
    {
      std::map<std::pair<std::size_t, std::size_t>, int> edge_faces;
      for(const auto& poly : polygons)
        for(std::size_t i = 0; i < poly.size(); ++i)
        {
          std::size_t a = poly[i], b = poly[(i + 1) % poly.size()];
          ++edge_faces[std::make_pair((std::min)(a, b), (std::max)(a, b))];
        }
      std::size_t bad_edges = 0;
      for(const auto& e : edge_faces)
        bad_edges += e.second > 2 ? 1 : 0;
      std::string detail = "input is not a manifold mesh (non-manifold edge or vertex): ";
      if(bad_edges > 0)
        detail += std::to_string(bad_edges) + " edge(s) with more than two faces";
      else
        detail += "faces around a vertex do not form a single fan, or the surface is not orientable";
      failure = code_failure(SMSO::ERROR_NON_MANIFOLD_MESH,
                             detail + (repair ? " (--repair could not fix it)" : try_repair));
      return false;
    }
  }

  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  if(has_polygons)
  {
    const std::size_t before = num_faces(mesh);
    if(!PMP::triangulate_faces(mesh))
    {
      failure = code_failure(SMSO::ERROR_NON_TRIANGULAR_MESH,
                             "input has a polygon that could not be triangulated");
      return false;
    }
    notes.push_back("triangulated polygons: " + std::to_string(before) + " faces became " +
                    std::to_string(num_faces(mesh)) + " triangles");
  }
  std::size_t bad = 0;
  if(repair)
    bad = repair_degenerate_faces(mesh, *repair);
  else if(has_polygons)
    for(face_descriptor f : faces(mesh))
      bad += is_zero_area_face(f, mesh) ? 1 : 0;
  if(bad > 0)
  {
    failure = code_failure(SMSO::ERROR_DEGENERATE_TRIANGLE,
                           "input has " + std::to_string(bad) + " zero-area (degenerate) triangle(s) " +
                           (repair ? "that --repair could not remove" : "after triangulating its polygons" +
                                                                            try_repair));
    return false;
  }
  if(num_faces(mesh) == 0)
  {
    failure = code_failure(SMSO::ERROR_EMPTY_MESH, "input mesh has no face left after --repair");
    return false;
  }
  return true;
}

// --use-input-uv: reads an OBJ with its per-corner UVs into the empty `mesh`
// and `uvmap`. Returns true on success; otherwise `failure` says why.
template <typename UVMap>
bool load_mesh_with_uv_map(const std::string& path, Mesh& mesh, UVMap uvmap, Load_failure& failure)
{
  if(!internal::check_input_file(path, failure))
    return false;
  if(lowercase_extension(path) != ".obj")
  {
    failure = {"ERROR_INPUT", "option '--use-input-uv' needs an .obj input with texture coordinates, not '" +
                              path + "'"};
    return false;
  }
  std::string error;
  bool ok = false;
  try
  {
    ok = SMSO::IO::read_OBJ_with_uv_map(path, mesh, uvmap, error);
  }
  catch(const std::exception& e)
  {
    error = e.what();
  }
  if(!ok)
  {
    failure = {"ERROR_INPUT", "--use-input-uv: cannot read a UV map: " + error};
    return false;
  }
  // The reader adds faces in file order: face i is the file's face i + 1.
  std::size_t i = 0, degenerate = 0, first = 0;
  for(face_descriptor f : faces(mesh))
  {
    const auto vpm = get(CGAL::vertex_point, mesh);
    bool bad = false;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh))
      bad = bad || !std::isfinite(get(vpm, v).x()) || !std::isfinite(get(vpm, v).y()) ||
            !std::isfinite(get(vpm, v).z());
    if(bad)
    {
      failure = code_failure(SMSO::ERROR_NON_FINITE_COORDINATES,
                             "input has a non-finite coordinate (face " + std::to_string(i + 1) + ")");
      return false;
    }
    if(is_zero_area_face(f, mesh) && degenerate++ == 0)
      first = i;
    ++i;
  }
  if(degenerate > 0)
  {
    failure = code_failure(SMSO::ERROR_DEGENERATE_TRIANGLE,
                           "input has " + std::to_string(degenerate) +
                           " zero-area (degenerate) triangle(s); the first is face " + std::to_string(first + 1));
    return false;
  }
  return true;
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_LOAD_MESH_H
