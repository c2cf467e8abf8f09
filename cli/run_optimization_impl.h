// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The body of run_<energy>(): the library call for one energy. Included only
// by the run_*.cpp files.

#ifndef SMSO_CLI_RUN_OPTIMIZATION_IMPL_H
#define SMSO_CLI_RUN_OPTIMIZATION_IMPL_H

#include "run_optimization.h"

#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>

#include <functional>
#include <limits>

namespace optimize_seams_cli {

// Forwards the library's visitor calls to the request's callback.
struct Function_visitor
{
  const std::function<bool(const SMSO::Seam_optimization_progress&)>* f;
  bool call(const SMSO::Seam_optimization_progress& p) { return !*f || (*f)(p); }
  bool on_iteration(const SMSO::Seam_optimization_progress& p) { return call(p); }
  bool on_topology_operation(const SMSO::Seam_optimization_progress& p) { return call(p); }
  bool on_lambda_update(const SMSO::Seam_optimization_progress& p) { return call(p); }
};

template <typename Energy>
SMSO::Optimization_result run_with_energy(Mesh& mesh, UV_map uvmap, Seam_map seams,
                                          const Optimization_request& request, const Energy& energy)
{
  namespace NP = SMSO::parameters;
  const auto common = NP::energy(energy)
                        .use_uv_map_as_initial(request.use_input_uv)
                        .edge_is_seam_map(seams)
                        .number_of_iterations(request.iteration_cap)
                        .time_limit(request.time_limit > 0 ? request.time_limit
                                                           : std::numeric_limits<double>::infinity());
  Function_visitor visitor{&request.progress};
  const auto with_visitor = common.bijective(request.bijective)
                              .visitor(std::ref(visitor))
                              .vertex_seam_cost_map(request.vertex_seam_cost)
                              .seam_cost_map(request.edge_seam_cost);

  switch(request.mode)
  {
    case Mode::KEEP_SEAMS:
      return SMSO::minimize_distortion(mesh, uvmap, common);
    case Mode::SEAM_WEIGHT:
      return SMSO::optimize_seams(mesh, uvmap, with_visitor.seam_weight(request.seam_weight));
    case Mode::DISTORTION_BOUND:
      break;
  }
  return SMSO::optimize_seams(mesh, uvmap,
                              with_visitor.distortion_bound(request.distortion_bound)
                                .number_of_recut_rounds(request.recut_rounds)
                                .cut_strategy(request.cut_strategy)
                                .number_of_starts(request.starts)
                                .proxy_number_of_faces(request.proxy_faces));
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_RUN_OPTIMIZATION_IMPL_H
