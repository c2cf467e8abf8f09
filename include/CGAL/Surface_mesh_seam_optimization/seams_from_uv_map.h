// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The seams a per-corner UV map implies.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAMS_FROM_UV_MAP_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAMS_FROM_UV_MAP_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// Marks as seams the edges of `tm` whose two sides disagree on the UV of a
/// vertex, and the other edges (border edges too) as no seams: the seams
/// `optimize_seams()` reads from `uvmap` with `use_uv_map_as_initial(true)`.
/// Two UVs agree when they differ by at most 1e-9 times the diagonal of the
/// map's bounding box in each coordinate (a map written with a few digits,
/// or computed, rarely repeats a UV bit for bit).
///
/// \tparam TriangleMesh a model of `FaceGraph` (triangles only)
/// \tparam UVMap a readable property map, `halfedge_descriptor` to a 2D point:
///   the UV of `target(h)` in `face(h)`
/// \tparam EdgeSeamMap a writable property map, `edge_descriptor` to `bool`
/// \tparam NamedParameters a sequence of named parameters
///
/// \param tm the mesh
/// \param uvmap its UV map
/// \param seam_map receives the seams
/// \param np an optional sequence of named parameters among those below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D positions of the vertices (only checked: the mesh must be valid)}
///     \cgalParamType{a readable property map, `vertex_descriptor` to a 3D point}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns `OK`, or why the mesh (not a manifold triangle mesh, or with a
///   zero-area triangle) or the map (a non-finite UV) cannot be read;
///   `seam_map` is then left untouched.
template <typename TriangleMesh, typename UVMap, typename EdgeSeamMap,
          typename NamedParameters = parameters::Default_named_parameters>
Error_code seams_from_uv_map(const TriangleMesh& tm, UVMap uvmap, EdgeSeamMap seam_map,
                             const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, tm));
  internal::Cut_mesh cm;
  internal::Face_graph_copy<TriangleMesh> copy;
  std::string message;
  Error_code ec = internal::copy_face_graph(tm, vpm, cm, copy, message);
  if(ec != OK) return ec;
  std::vector<double> corner_uvs;
  ec = internal::read_uv_map(tm, uvmap, copy, corner_uvs, message);
  if(ec != OK) return ec;
  std::vector<char> seam;
  internal::seams_from_corner_uvs(cm, corner_uvs, seam);
  for(auto e : edges(tm)) put(seam_map, e, false);
  for(std::size_t h = 0; h < seam.size(); ++h)
    if(seam[h]) put(seam_map, edge(copy.corner_halfedge[h], tm), true);
  return OK;
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
