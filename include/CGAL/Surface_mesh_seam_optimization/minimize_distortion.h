// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_MINIMIZE_DISTORTION_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_MINIMIZE_DISTORTION_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/Optimization_result.h>
#include <CGAL/Surface_mesh_seam_optimization/Sparse_solver_traits.h>
#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/initial_parameterization.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Coarse_to_fine.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Defaults.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_maps.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Initialize_cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Measure_result.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Projected_newton.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Untangle.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <atomic>
#include <chrono>
#include <limits>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// minimize_distortion(); `stop`, when raised, ends the descent as the time
// limit does (a start of optimize_seams() cancelled with the others).
template <typename TriangleMesh, typename UVMap, typename NamedParameters>
Optimization_result minimize_distortion_impl(const TriangleMesh& tm, UVMap uvmap, const NamedParameters& np,
                                             const std::atomic<bool>* stop)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;

  CGAL::Real_timer timer;
  timer.start();
  Optimization_result result;

  const auto energy = choose_parameter(get_parameter(np, internal_np::energy), Symmetric_Dirichlet_energy());
  if(!internal::check_energy(energy, result.message))
  {
    result.status = ERROR_WRONG_PARAMETER;
    return result;
  }
  // (one pattern per level: nested dissection pays)
  auto solver = choose_parameter(get_parameter(np, CGAL::internal_np::sparse_linear_solver),
                                 Default_sparse_solver_traits(Default_sparse_solver_traits::default_threshold, true));
  const std::size_t max_iterations =
    internal::number_of_iterations_parameter(np, internal::default_number_of_iterations_distortion_only);
  internal::Newton_settings settings = internal::distortion_only_newton_settings();
  settings.gradient_tolerance =
    choose_parameter(get_parameter(np, internal_np::gradient_tolerance), settings.gradient_tolerance);
  if(!(settings.gradient_tolerance >= 0))
  {
    result.status = ERROR_WRONG_PARAMETER;
    result.message = "gradient_tolerance must be >= 0";
    return result;
  }
  double time_limit = 0;
  if(!internal::read_time_limit(np, time_limit))
  {
    result.status = ERROR_WRONG_PARAMETER;
    result.message = "time_limit must be > 0 seconds";
    return result;
  }
  const internal::Deadline deadline(time_limit, stop);

  internal::Cut_mesh cm;
  internal::Face_graph_copy<TriangleMesh> copy;
  result.status = internal::initialize_cut_mesh(tm, uvmap, np, cm, copy, result.message);
  if(result.status != OK) return result;

  const bool use_input = choose_parameter(get_parameter(np, internal_np::use_uv_map_as_initial), false);
  // An energy with no barrier (ARAP) keeps the triangles squeezed below its
  // area floor squeezed, to a degenerate result (from Tutte's map, the
  // default, with ARAP_energy on 7 of 10 meshes of the benchmark; from
  // Mean_value_coordinates_parameterizer_3's on 3 of 5): from such a map it
  // descends from E_SD's minimum.
  const bool barrier = internal::is_barrier_energy(energy);
  const std::size_t squeezed =
    !barrier && use_input ? internal::number_of_faces_below_area_floor(cm, settings.area_floor) : 0;
  const bool distortion_first = !barrier && (!use_input || squeezed > 0);
  if(squeezed > 0)
    result.message += std::string(result.message.empty() ? "" : "; ") + "E_SD minimized first: " +
                      std::to_string(squeezed) + " triangles of the initial map are squeezed below the area floor";
  const Symmetric_Dirichlet_energy sd;

  // Large meshes start from a coarser one's map (Coarse_to_fine.h); the
  // initial map stays if that fails.
  std::vector<std::size_t> levels;
  if(!use_input && cm.number_of_faces() >= internal::coarse_to_fine_minimum_faces &&
     (distortion_first ? internal::coarse_to_fine_start(cm, sd, solver, settings, deadline, levels)
                       : internal::coarse_to_fine_start(cm, energy, solver, settings, deadline, levels)))
  {
    result.message = "started from coarser meshes of";
    for(std::size_t n : levels) result.message += " " + std::to_string(n);
    result.message += " faces";
  }

  std::size_t sd_iterations = 0;
  Optimization_timings sd_timings;
  if(distortion_first)
  {
    internal::rescale_to_optimal(cm, sd);
    result.initial_distortion = internal::total_energy(cm, sd, cm.uv.data());
    result.status = internal::descend(cm, sd, solver, settings, max_iterations, deadline, sd_iterations, sd_timings,
                                      result.message);
    if(result.status == ERROR_LINEAR_SOLVER) return result;
  }
  internal::rescale_to_optimal(cm, energy);
  if(!distortion_first)
    result.initial_distortion = internal::total_energy(cm, sd, cm.uv.data());
  if(!distortion_first || result.status == OK)
    result.status = internal::descend(cm, energy, solver, settings, max_iterations - sd_iterations, deadline,
                                      result.iterations, result.timings, result.message);
  result.iterations += sd_iterations;
  result.timings += sd_timings;
  if(result.status == ERROR_LINEAR_SOLVER) return result;
  // (the line search never allows it: a last check before anything is written)
  std::string first_invalid;
  if(const std::size_t invalid = internal::count_invalid_uv_triangles(cm, &first_invalid))
  {
    // Valid but still squeezed triangles of the initial map (Tutte's maps of
    // long protrusions): the descent was stopped before it opened them.
    const bool stopped = result.status == WARNING_MAXIMUM_ITERATIONS || result.status == WARNING_TIME_LIMIT;
    if(stopped && internal::first_face_outside_barrier_domain(cm) == cm.number_of_faces())
      result.message = "the descent stopped after " + std::to_string(result.iterations) + " iterations (" +
                       get_error_code_name(result.status) + ") with " + std::to_string(invalid) +
                       " triangles still squeezed below 1e-12 of their chart's area (" + first_invalid +
                       "; initial maps squeeze long protrusions so): allow more iterations or time";
    else
      result.message = first_invalid;
    result.status = ERROR_DEGENERATE_UV_RESULT;
    return result;
  }

  internal::scale_for_output(cm, energy);
  internal::write_uv_map(cm, copy, uvmap);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value)
    internal::write_seam_map(tm, cm, copy, get_parameter(np, internal_np::edge_is_seam_map));
  // no bound is enforced here; say whether the result meets the one given (default: the energy's)
  double bound = std::numeric_limits<double>::infinity();
  std::string ignored;
  if(!internal::read_distortion_bound(np, energy, bound, ignored)) bound = -1; // none: not met
  internal::measure_result(cm, energy, bound, result);
  result.seconds = timer.time();
  return result;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// Minimizes the distortion energy (symmetric Dirichlet by default) of a UV
/// map whose seams are fixed: projected Newton with a flip-free line search,
/// the boundary of every chart free.
///
/// An energy with no barrier (`ARAP_energy`) cannot expand the triangles
/// that Tutte's map squeezes (the result was degenerate on most meshes of the
/// benchmark): from the default initial map, E_SD is minimized first and the
/// energy from there (`Optimization_result::iterations` counts both).
///
/// A mesh of 16000 faces or more starts from coarser ones: the charts are
/// simplified by edge collapses that flip no triangle of the initial map, to
/// a quarter of the faces (and again while the result has 16000 faces or
/// more); the coarsest mesh is minimized from the initial map at its
/// vertices, and each level's minimum is carried to the next finer one by
/// undoing the collapses, every returning vertex placed where its triangles
/// are valid and relaxed alone, then all relaxed again in three sweeps. This
/// spares the long first phase of the descent from Tutte's map, whose
/// squeezed triangles cut every step short (lucy_o_f24136: 4.8 s instead of
/// 7.5 s; lucy at 96544 faces: 43 s instead of 110 s; CGAL's man.off, 34986
/// faces: 9 s instead of 37 s; slower on a few meshes, as CGAL's blade.off:
/// 35 s instead of 25 s). The energy is not convex: the result is a minimum
/// too, not always the same one (E_SD within 0.9% on 20 meshes of 16000 to
/// 97000 faces, 1.1% apart on the octopus).
/// `Optimization_result::message` names the coarser levels; if any part of
/// the coarse start fails, the descent starts from the initial map. A map
/// given with `use_uv_map_as_initial` is always the start.
///
/// \tparam TriangleMesh a model of `FaceGraph` (triangles only)
/// \tparam UVMap a read-write property map `halfedge_descriptor -> Point_2`;
///   for every halfedge `h` with a face, `get(uvmap, h)` is the UV of
///   `target(h)` in `face(h)`.
///
/// \param tm the mesh, of any genus, with any number of boundary loops and
///   connected components: it is cut into charts as
///   `compute_initial_parameterization()` says (closed genus-0 charts slit
///   open, handles cut by loops, holes kept), after the seams of
///   `edge_is_seam_map`; with `use_uv_map_as_initial`, the given charts.
/// \param uvmap receives the result; read as the initial map with `use_uv_map_as_initial(true)`
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points of the vertices}
///     \cgalParamType{a readable property map, `vertex_descriptor` to a 3D point}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel, passed on to `compute_initial_parameterization()` (the
///       types of the initial map); the optimization itself works in `double`}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type of `vertex_point_map`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_seam_map}
///     \cgalParamDescription{the fixed seams
///       (read unless the seams come from the input UV map), written with the final seams}
///     \cgalParamType{a read-write property map, `edge_descriptor` to `bool`}
///     \cgalParamDefault{no seam map: seams implied by the UV map, or none}
///   \cgalParamNEnd
///   \cgalParamNBegin{use_uv_map_as_initial}
///     \cgalParamDescription{start from the UVs in `uvmap` (validated: finite). Flipped or degenerate
///       triangles (as in maps of `ARAP_parameterizer_3` or `LSCM_parameterizer_3`) are untangled
///       first: the region around them, grown ring by ring, is re-mapped by Tutte's embedding with its
///       border fixed; if no region works, the default initial map with the same seams is used.
///       `Optimization_result::message` says which ("k flipped or degenerate triangles of the initial
///       UV map untangled", or "... fell back to the default initial map")}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`: circle boundary + Tutte per chart}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy}
///     \cgalParamDescription{the distortion energy minimized}
///     \cgalParamType{a model of `DistortionEnergy`}
///     \cgalParamDefault{`Symmetric_Dirichlet_energy`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{the sparse solver of the Newton steps}
///     \cgalParamType{a model of `SparseSolverTraits`}
///     \cgalParamDefault{`Default_sparse_solver_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{cap on Newton iterations on `tm` (those of the coarser meshes not counted; CGAL's parameter; `maximum_number_of_iterations`, the
///       package's former name for it, is a deprecated alias, read when `number_of_iterations` is not given)}
///     \cgalParamType{an integral type (`std::size_t`)}
///     \cgalParamDefault{`10000`}
///   \cgalParamNEnd
///   \cgalParamNBegin{gradient_tolerance}
///     \cgalParamDescription{stop when the scale-free squared gradient norm falls below it}
///     \cgalParamType{`double`}
///     \cgalParamDefault{`1e-12`}
///   \cgalParamNEnd
///   \cgalParamNBegin{time_limit}
///     \cgalParamDescription{seconds (> 0) after which the descent stops with the map it has reached,
///       status `WARNING_TIME_LIMIT` (a result is written)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{distortion_bound}
///     \cgalParamDescription{not enforced here: `Optimization_result::bound_met` says whether the result
///       meets it (the bound is on `energy`, in its own units)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{the energy's `default_bound()` (4.1 for `Symmetric_Dirichlet_energy`)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the status (the user's maps are untouched unless `has_result()`;
///   a result with a flipped or degenerate triangle is never written:
///   `ERROR_DEGENERATE_UV_RESULT`; a run stopped by `number_of_iterations` or
///   `time_limit` before it opened the initial map's squeezed triangles ends so, and
///   `message` says how many are left), E_SD of the result (as written and at its
///   optimal uniform scale), seam length, charts, iterations.
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Optimization_result minimize_distortion(const TriangleMesh& tm, UVMap uvmap,
                                        const NamedParameters& np = parameters::default_values())
{
  return internal::minimize_distortion_impl(tm, uvmap, np, nullptr);
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
