// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The named parameters of the seam optimization read into its settings, and
// the core mesh built, shared by optimize_seams() and Seam_optimizer.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SETUP_SEAM_OPTIMIZATION_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SETUP_SEAM_OPTIMIZATION_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Alternating_optimization.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Defaults.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Initialize_cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Projected_newton.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Seam_costs.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Reads the named parameters of the seam optimization and builds the core
// mesh with its (rescaled) initial map; shared by optimize_seams() and
// Seam_optimizer.
template <typename TriangleMesh, typename UVMap, typename NamedParameters, typename Energy>
Error_code setup_seam_optimization(const TriangleMesh& tm, UVMap uvmap, const NamedParameters& np,
                                   const Energy& energy, Cut_mesh& cm, Face_graph_copy<TriangleMesh>& copy,
                                   std::vector<double>& weight, Alternating_settings& settings,
                                   std::string& message)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;

  if(!read_distortion_bound(np, energy, settings.distortion_bound, message))
    return ERROR_WRONG_PARAMETER;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::seam_weight_t>::value)
  {
    settings.fixed_lambda = true;
    settings.lambda = choose_parameter(get_parameter(np, internal_np::seam_weight), 0.);
    if(!(settings.lambda >= 0. && settings.lambda < 1.))
    {
      message = "seam_weight must be in [0, 1)";
      return ERROR_WRONG_PARAMETER;
    }
  }
  // Stationary points between topology steps need not be polished: a looser
  // decrease test saves Newton iterations at no cost in seam length.
  settings.newton.relative_decrease_tolerance = 3e-6;
  // Every step from a fresh factorization: reusing the last one changed the
  // time by x0.99 at up to 10k faces (x0.72-0.90 on the larger meshes,
  // x1.03-1.14 on the small ones: a pattern lives 2-3 iterations between
  // topology steps), and any change of the steps' rounding changes the
  // seams of the meshes whose topology decisions are near ties (hand1 1.34
  // -> 1.81 times the reference's; notes/issue20).
  settings.newton.stale_factor_iterations = 0;
  // Nor for the steps that only confirm convergence (measured: x0.95 time,
  // hand1 1.34 -> 1.50 times the reference's; notes/issue20).
  // Full steps are not extrapolated: on the 40 meshes it saved 10% of the
  // Newton iterations and redrew 14 of the seams (geometric mean 0.991 ->
  // 0.989, but hand_2_i_f10000 1.10 -> 1.24, hand1 1.34 -> 1.66; notes/issue20).
  settings.newton.extrapolation_limit = 1;
  settings.bijective = choose_parameter(get_parameter(np, internal_np::bijective), true);
  settings.max_iterations = number_of_iterations_parameter(np, default_number_of_iterations);
  const int rounds = choose_parameter(get_parameter(np, internal_np::number_of_recut_rounds),
                                     default_number_of_recut_rounds);
  if(rounds < 0)
  {
    message = "number_of_recut_rounds must be >= 0";
    return ERROR_WRONG_PARAMETER;
  }
  settings.recut_rounds = rounds;
  if(!read_time_limit(np, settings.time_limit))
  {
    message = "time_limit must be > 0 seconds";
    return ERROR_WRONG_PARAMETER;
  }

  Error_code ec = initialize_cut_mesh(tm, uvmap, np, cm, copy, message);
  if(ec != OK) return ec;

  if(!read_seam_costs(tm, copy, np, weight, message))
    return ERROR_WRONG_PARAMETER;
  rescale_to_optimal(cm, energy);
  return OK;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
