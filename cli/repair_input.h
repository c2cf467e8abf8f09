// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// --repair: fixes what CGAL::Polygon_mesh_processing can fix in an input
// soup or mesh, and counts each change so that the user is told what was
// altered (one stderr line, and the JSON report).

#ifndef SMSO_CLI_REPAIR_INPUT_H
#define SMSO_CLI_REPAIR_INPUT_H

#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>

#include <CGAL/Surface_mesh_seam_optimization/internal/Degenerate_triangle.h>

#include <algorithm>
#include <limits>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace optimize_seams_cli {

struct Repair_summary
{
  std::size_t nonfinite_faces_removed = 0;      // faces using a non-finite coordinate
  std::size_t duplicate_points_merged = 0;      // points at the same position
  std::size_t polygons_simplified = 0;          // a corner repeated consecutively, still >= 3 corners
  std::size_t pinched_faces_split = 0;          // a corner repeated apart: one face per loop
  std::size_t invalid_faces_removed = 0;        // fewer than three distinct corners
  std::size_t duplicate_faces_removed = 0;      // same corners as another face
  std::size_t isolated_points_removed = 0;      // used by no face
  std::size_t points_duplicated = 0;            // to make edges and vertices manifold (orient_polygon_soup)
  bool reoriented = false;                      // faces flipped to a consistent orientation
  std::size_t degenerate_faces_removed = 0;     // zero-area triangles (removed, collapsed or flipped away)
  std::size_t non_manifold_vertices_split = 0;  // after the degenerate faces went

  // (JSON key, count) of every kind of change, in the order they are made.
  std::vector<std::pair<std::string, std::size_t> > items() const
  {
    return {{"nonfinite_faces_removed", nonfinite_faces_removed},
            {"duplicate_points_merged", duplicate_points_merged},
            {"polygons_simplified", polygons_simplified},
            {"pinched_faces_split", pinched_faces_split},
            {"invalid_faces_removed", invalid_faces_removed},
            {"duplicate_faces_removed", duplicate_faces_removed},
            {"isolated_points_removed", isolated_points_removed},
            {"points_duplicated_for_manifoldness", points_duplicated},
            {"reoriented", reoriented ? 1u : 0u},
            {"degenerate_faces_removed", degenerate_faces_removed},
            {"non_manifold_vertices_split", non_manifold_vertices_split}};
  }

  // "merged 1 duplicate point, removed 2 zero-area faces", or "nothing to repair".
  std::string description() const
  {
    std::string s;
    auto add = [&s](std::size_t n, const char* singular, const char* plural) {
      if(n == 0)
        return;
      s += (s.empty() ? "" : ", ");
      s += std::to_string(n) + " " + (n == 1 ? singular : plural);
    };
    add(nonfinite_faces_removed, "face with a non-finite coordinate removed",
        "faces with a non-finite coordinate removed");
    add(duplicate_points_merged, "duplicate point merged", "duplicate points merged");
    add(polygons_simplified, "face with a repeated corner simplified", "faces with a repeated corner simplified");
    add(pinched_faces_split, "face with a corner repeated apart split into its loops",
        "faces with a corner repeated apart split into their loops");
    add(invalid_faces_removed, "face with fewer than 3 corners removed", "faces with fewer than 3 corners removed");
    add(duplicate_faces_removed, "duplicate face removed", "duplicate faces removed");
    add(isolated_points_removed, "unused point removed", "unused points removed");
    add(points_duplicated, "point duplicated to make the mesh manifold",
        "points duplicated to make the mesh manifold");
    if(reoriented)
      s += std::string(s.empty() ? "" : ", ") + "faces reoriented consistently";
    add(degenerate_faces_removed, "zero-area face removed", "zero-area faces removed");
    add(non_manifold_vertices_split, "non-manifold vertex split", "non-manifold vertices split");
    return s.empty() ? "nothing to repair" : s;
  }
};

// Soup stage: drops faces on non-finite points, merges duplicate points,
// removes repeated corners, faces with fewer than three corners, duplicate
// faces and unused points. Every index must be < points.size().
template <typename Point, typename Polygon>
void repair_polygon_soup(std::vector<Point>& points, std::vector<Polygon>& polygons, Repair_summary& summary)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  {
    std::vector<Polygon> kept;
    kept.reserve(polygons.size());
    for(Polygon& poly : polygons)
    {
      bool finite = true;
      for(std::size_t v : poly)
        finite = finite && std::isfinite(points[v].x()) && std::isfinite(points[v].y()) &&
                 std::isfinite(points[v].z());
      if(finite)
        kept.push_back(std::move(poly));
    }
    summary.nonfinite_faces_removed = polygons.size() - kept.size();
    polygons.swap(kept);
  }
  // The steps of PMP::repair_polygon_soup(), one by one to count each.
  // Non-finite points are all unused now; they must go before the merge
  // (NaN breaks its ordering).
  summary.isolated_points_removed = PMP::remove_isolated_points_in_polygon_soup(points, polygons);
  summary.duplicate_points_merged = PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  // Repeated corners and faces left with fewer than three (PMP's own versions
  // of these two steps are internal in CGAL 5.5).
  std::vector<Polygon> kept;
  kept.reserve(polygons.size());
  std::vector<std::size_t> position(points.size(), std::size_t(-1));
  for(Polygon& poly : polygons)
  {
    Polygon simple;
    for(std::size_t i = 0; i < poly.size(); ++i)
      if(poly[i] != poly[(i + 1) % poly.size()])
        simple.push_back(poly[i]);
    if(simple.size() < 3)
    {
      ++summary.invalid_faces_removed;
      continue;
    }
    if(simple.size() != poly.size())
      ++summary.polygons_simplified;
    // A corner repeated apart pinches the face into loops (CGAL's soup steps
    // need distinct corners): each loop of three corners or more is a face.
    Polygon rest;
    std::size_t loops = 0;
    for(std::size_t v : simple)
    {
      if(position[v] != std::size_t(-1))
      {
        Polygon loop(rest.begin() + std::ptrdiff_t(position[v]), rest.end());
        for(std::size_t k = position[v] + 1; k < rest.size(); ++k)
          position[rest[k]] = std::size_t(-1);
        rest.resize(position[v] + 1);
        ++loops;
        if(loop.size() >= 3)
          kept.push_back(std::move(loop));
        continue;
      }
      position[v] = rest.size();
      rest.push_back(v);
    }
    for(std::size_t v : rest)
      position[v] = std::size_t(-1);
    summary.pinched_faces_split += loops > 0 ? 1 : 0;
    if(rest.size() >= 3)
      kept.push_back(std::move(rest));
  }
  polygons.swap(kept);
  summary.duplicate_faces_removed = PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
  summary.isolated_points_removed += PMP::remove_isolated_points_in_polygon_soup(points, polygons);
}

// Orients the soup consistently, duplicating points where an edge or a
// vertex is not manifold. Returns whether the soup is now a polygon mesh.
template <typename Point, typename Polygon>
bool orient_polygon_soup_duplicating(std::vector<Point>& points, std::vector<Polygon>& polygons,
                                     Repair_summary& summary)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const std::size_t before = points.size();
  const std::vector<Polygon> original = polygons;
  PMP::orient_polygon_soup(points, polygons);
  summary.points_duplicated = points.size() - before;
  // A face whose corners changed without a new point was flipped.
  for(std::size_t f = 0; f < polygons.size() && !summary.reoriented; ++f)
    if(polygons[f] != original[f])
    {
      bool uses_new_point = false;
      for(std::size_t v : polygons[f])
        uses_new_point = uses_new_point || v >= before;
      summary.reoriented = !uses_new_point;
    }
  return PMP::is_polygon_soup_a_polygon_mesh(polygons);
}

// The library's definition of a zero-area triangle (is_degenerate_triangle()):
// scale- and position-free, so that --repair removes what the library refuses.
template <typename Point>
bool is_zero_area_triangle(const Point& a, const Point& b, const Point& c)
{
  const double p[3][3] = { { a.x(), a.y(), a.z() }, { b.x(), b.y(), b.z() }, { c.x(), c.y(), c.z() } };
  return CGAL::Surface_mesh_seam_optimization::internal::is_degenerate_triangle(p[0], p[1], p[2]);
}

template <typename TriangleMesh>
bool is_zero_area_face(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& mesh)
{
  const auto h = halfedge(f, mesh);
  const auto vpm = get(CGAL::vertex_point, mesh);
  return is_zero_area_triangle(get(vpm, source(h, mesh)), get(vpm, target(h, mesh)),
                               get(vpm, target(next(h, mesh), mesh)));
}

// Mesh stage: removes the zero-area triangles (is_zero_area_triangle()):
// exact ones by PMP::remove_degenerate_faces(), the others as needles (their
// shortest edge collapsed) or caps (their longest edge flipped), then splits
// the non-manifold vertices that this may leave. Returns the number of
// zero-area faces left (0 when everything was repaired).
template <typename TriangleMesh>
std::size_t repair_degenerate_faces(TriangleMesh& mesh, Repair_summary& summary)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  auto zero_area_faces = [&mesh]() {
    std::vector<face_descriptor> bad;
    for(face_descriptor f : faces(mesh))
      if(is_zero_area_face(f, mesh))
        bad.push_back(f);
    return bad;
  };
  const std::size_t before = zero_area_faces().size();
  if(before == 0)
    return 0;
  PMP::remove_degenerate_faces(mesh);
  std::vector<face_descriptor> bad = zero_area_faces();
  if(!bad.empty())
  {
    // Thresholds that take in every zero-area triangle: one that is not a
    // needle at a length ratio of 1e6 has angles below 1e-6 at its longest
    // edge, hence a cosine below -1 + 2e-12 at the opposite corner.
    PMP::experimental::remove_almost_degenerate_faces(bad, mesh, -1 + 4e-12, 1e6,
                                                      (std::numeric_limits<double>::max)());
    PMP::remove_degenerate_faces(mesh);
  }
  PMP::remove_isolated_vertices(mesh);
  mesh.collect_garbage();
  summary.non_manifold_vertices_split = PMP::duplicate_non_manifold_vertices(mesh);
  const std::size_t after = zero_area_faces().size();
  summary.degenerate_faces_removed = before > after ? before - after : 0;
  return after;
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_REPAIR_INPUT_H
