// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The core mesh and its initial UV map, the user's or a computed one, shared
// by minimize_distortion() and the seam optimization.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_INITIALIZE_CUT_MESH_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_INITIALIZE_CUT_MESH_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/initial_parameterization.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Untangle.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Builds the core mesh with its initial UVs: the user's map, or a computed
// one (cut to disks along the given seams, Tutte per chart).
template <typename TriangleMesh, typename UVMap, typename NamedParameters>
Error_code initialize_cut_mesh(const TriangleMesh& tm, UVMap uvmap, const NamedParameters& np,
                               Cut_mesh& cm, Face_graph_copy<TriangleMesh>& copy, std::string& message)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, tm));
  Error_code ec = copy_face_graph(tm, vpm, cm, copy, message);
  if(ec != OK) return ec;

  const bool use_input = choose_parameter(get_parameter(np, internal_np::use_uv_map_as_initial), false);
  constexpr bool has_seam_map =
    !parameters::is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value;

  std::vector<char> seam;
  std::vector<double> corner_uvs;

  // the default initial map, cut along `seams` (per core halfedge) and more if needed
  auto compute_default = [&](std::vector<char> seams) -> Error_code {
    ec = initial_uv_map(tm, vpm, cm, copy, seams, corner_uvs, message);
    if(ec != OK) { message = "could not compute the initial map: " + message; return ec; }
    seam.swap(seams);
    label_uv_vertices(cm, seam);
    set_uvs_from_corners(cm, corner_uvs);
    return OK;
  };

  if(!use_input)
  {
    if constexpr(has_seam_map)
      read_seam_map(tm, get_parameter(np, internal_np::edge_is_seam_map), copy, cm, seam);
    else
      seam.assign(cm.corner_vertex.size(), 0);
    ec = compute_default(seam);
    if(ec != OK) return ec;
    const std::size_t f = first_face_outside_barrier_domain(cm);
    if(f < cm.number_of_faces())
    {
      message = "UV triangle of face " + std::to_string(f) + " is flipped or degenerate";
      return ERROR_FLIPPED_UV_TRIANGLE;
    }
    return OK;
  }

  ec = read_uv_map(tm, uvmap, copy, corner_uvs, message);
  if(ec != OK) return ec;
  if constexpr(has_seam_map)
    read_seam_map(tm, get_parameter(np, internal_np::edge_is_seam_map), copy, cm, seam);
  else
    seams_from_corner_uvs(cm, corner_uvs, seam);
  label_uv_vertices(cm, seam);
  set_uvs_from_corners(cm, corner_uvs);

  // A map the descent can start from is kept as it is, tiny triangles
  // included (Tutte's maps of long protrusions, compute_initial_parameterization()'s
  // own too: the descent expands them as it does in the default map). Maps of
  // Surface_mesh_parameterization's LSCM and ARAP parameterizers usually fold
  // a little: untangled locally, or replaced by the default map.
  if(first_face_outside_barrier_domain(cm) == cm.number_of_faces()) return OK;
  std::string which;
  count_invalid_uv_triangles(cm, &which);
  std::size_t count = 0;
  if(untangle_uv_map(cm, count))
  {
    message = std::to_string(count) + " flipped or degenerate triangles of the initial UV map untangled";
    return OK;
  }
  std::string default_message;
  std::swap(default_message, message);
  if(compute_default(seam) != OK || first_face_outside_barrier_domain(cm) < cm.number_of_faces())
  {
    message = which + " (and neither untangling it nor the default initial map with its seams worked)";
    return ERROR_FLIPPED_UV_TRIANGLE;
  }
  message = std::to_string(count) + " flipped or degenerate triangles of the initial UV map could not be "
            "untangled: fell back to the default initial map";
  return OK;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
