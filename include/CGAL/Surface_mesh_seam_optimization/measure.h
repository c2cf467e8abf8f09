// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Measures of any per-corner UV map: distortion, seam length, flips, charts.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_MEASURE_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_MEASURE_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Overlap.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Mesh_energy.h>

#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// Figures of a UV map, as computed by `measure_uv_map()`.
struct Uv_map_measures
{
  Error_code status = OK;          ///< not `OK` if the mesh or the map is invalid
  std::string message;
  double distortion = std::numeric_limits<double>::infinity(); ///< area-weighted mean energy (E_SD by default); +inf with a flipped triangle
  double seam_length = 0;          ///< 3D length of the seam edges, each once (input boundary excluded)
  double seam_length_normalized = 0; ///< seam_length / sqrt(area / pi)
  std::size_t flipped_triangles = 0; ///< UV triangles with non-positive signed area
  std::size_t charts = 0;          ///< faces joined across non-seam edges
  /// pairs of UV triangles (of any charts) whose interiors overlap by more
  /// than 1e-9 times the UV bounding box diagonal; sharing or touching a
  /// vertex or an edge is not an overlap
  std::size_t overlapping_triangle_pairs = 0;
  /// no flipped triangle and no overlapping pair: the map is globally injective
  bool is_bijective() const { return status == OK && flipped_triangles == 0 && overlapping_triangle_pairs == 0; }
};

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// Measures a per-corner UV map: seams are the edges whose two sides have
/// different UVs (or those of `edge_is_seam_map` if given). The functions
/// below (`distortion()`, `seam_length()`, ...) take the same named parameters.
///
/// \tparam TriangleMesh a model of `FaceGraph` (triangles only)
/// \tparam UVMap a readable property map `halfedge_descriptor -> Point_2`
///   (for every halfedge `h` with a face, the UV of `target(h)` in `face(h)`)
///
/// \param tm the mesh
/// \param uvmap the UV map to measure
/// \param np an optional sequence of named parameters among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_seam_map}
///     \cgalParamDescription{the seams, instead of the edges whose two sides have different UVs}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///       as key type and `bool` as value type}
///     \cgalParamDefault{the UV discontinuities}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy}
///     \cgalParamDescription{the distortion energy measured}
///     \cgalParamType{a model of `DistortionEnergy`}
///     \cgalParamDefault{`Symmetric_Dirichlet_energy`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Uv_map_measures measure_uv_map(const TriangleMesh& tm, UVMap uvmap,
                               const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Uv_map_measures m;
  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, tm));
  const auto energy = choose_parameter(get_parameter(np, internal_np::energy), Symmetric_Dirichlet_energy());

  internal::Cut_mesh cm;
  internal::Face_graph_copy<TriangleMesh> copy;
  m.status = internal::copy_face_graph(tm, vpm, cm, copy, m.message);
  if(m.status != OK) return m;
  std::vector<double> corner_uvs;
  m.status = internal::read_uv_map(tm, uvmap, copy, corner_uvs, m.message);
  if(m.status != OK) return m;
  std::vector<char> seam;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value)
  {
    internal::read_seam_map(tm, get_parameter(np, internal_np::edge_is_seam_map), copy, cm, seam);
  }
  else
    internal::seams_from_corner_uvs(cm, corner_uvs, seam);
  internal::label_uv_vertices(cm, seam);
  internal::set_uvs_from_corners(cm, corner_uvs);

  for(std::size_t f = 0; f < cm.number_of_faces(); ++f)
    if(!(cm.signed_uv_area2(f) > 0)) ++m.flipped_triangles;
  m.distortion = internal::total_energy(cm, energy, cm.uv.data());
  m.seam_length = cm.seam_length();
  m.seam_length_normalized = m.seam_length / cm.normalization_radius();
  std::vector<int> chart;
  m.charts = cm.compute_charts(chart);
  m.overlapping_triangle_pairs = internal::count_overlapping_pairs(cm);
  return m;
}

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// E_SD (or the energy of the `energy` named parameter) of a UV map; +inf if a triangle is flipped.
///
/// \param np an optional sequence of named parameters among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_seam_map}
///     \cgalParamDescription{the seams, instead of the edges whose two sides have different UVs}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///       as key type and `bool` as value type}
///     \cgalParamDefault{the UV discontinuities}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy}
///     \cgalParamDescription{the distortion energy measured}
///     \cgalParamType{a model of `DistortionEnergy`}
///     \cgalParamDefault{`Symmetric_Dirichlet_energy`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
double distortion(const TriangleMesh& tm, UVMap uvmap, const NamedParameters& np = parameters::default_values())
{
  return measure_uv_map(tm, uvmap, np).distortion;
}

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// Seam length; normalized by sqrt(area / pi) if `normalized`.
///
/// \param np an optional sequence of named parameters among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_seam_map}
///     \cgalParamDescription{the seams, instead of the edges whose two sides have different UVs}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///       as key type and `bool` as value type}
///     \cgalParamDefault{the UV discontinuities}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy}
///     \cgalParamDescription{the distortion energy measured}
///     \cgalParamType{a model of `DistortionEnergy`}
///     \cgalParamDefault{`Symmetric_Dirichlet_energy`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
double seam_length(const TriangleMesh& tm, UVMap uvmap, bool normalized = false,
                   const NamedParameters& np = parameters::default_values())
{
  const Uv_map_measures m = measure_uv_map(tm, uvmap, np);
  return normalized ? m.seam_length_normalized : m.seam_length;
}

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// Number of UV triangles with non-positive signed area.
///
/// \param np an optional sequence of named parameters among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_seam_map}
///     \cgalParamDescription{the seams, instead of the edges whose two sides have different UVs}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///       as key type and `bool` as value type}
///     \cgalParamDefault{the UV discontinuities}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy}
///     \cgalParamDescription{the distortion energy measured}
///     \cgalParamType{a model of `DistortionEnergy`}
///     \cgalParamDefault{`Symmetric_Dirichlet_energy`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t number_of_flipped_triangles(const TriangleMesh& tm, UVMap uvmap,
                                        const NamedParameters& np = parameters::default_values())
{
  return measure_uv_map(tm, uvmap, np).flipped_triangles;
}

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// Number of pairs of UV triangles whose interiors overlap (see
/// `Uv_map_measures::overlapping_triangle_pairs`), any two charts or within one.
///
/// \param np an optional sequence of named parameters among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_seam_map}
///     \cgalParamDescription{the seams, instead of the edges whose two sides have different UVs}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///       as key type and `bool` as value type}
///     \cgalParamDefault{the UV discontinuities}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy}
///     \cgalParamDescription{the distortion energy measured}
///     \cgalParamType{a model of `DistortionEnergy`}
///     \cgalParamDefault{`Symmetric_Dirichlet_energy`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t number_of_overlapping_triangle_pairs(const TriangleMesh& tm, UVMap uvmap,
                                                 const NamedParameters& np = parameters::default_values())
{
  return measure_uv_map(tm, uvmap, np).overlapping_triangle_pairs;
}

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// Whether a UV map is globally injective: valid, no flipped triangle and no
/// overlapping pair of triangles. Use it, e.g., to validate an initial map
/// before `optimize_seams()` with `use_uv_map_as_initial(true)`.
///
/// \param np an optional sequence of named parameters among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points of the vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_seam_map}
///     \cgalParamDescription{the seams, instead of the edges whose two sides have different UVs}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///       as key type and `bool` as value type}
///     \cgalParamDefault{the UV discontinuities}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy}
///     \cgalParamDescription{the distortion energy measured}
///     \cgalParamType{a model of `DistortionEnergy`}
///     \cgalParamDefault{`Symmetric_Dirichlet_energy`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
bool is_bijective(const TriangleMesh& tm, UVMap uvmap, const NamedParameters& np = parameters::default_values())
{
  return measure_uv_map(tm, uvmap, np).is_bijective();
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
