// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The mesh types of the command-line program and the one call into the
// library's optimizers. The optimizers are instantiated once per energy, each
// in its own translation unit (run_*.cpp): three energies in one file would
// triple the compile time of optimize_seams.cpp, and pictures or options
// would then rebuild all of them.

#ifndef SMSO_CLI_RUN_OPTIMIZATION_H
#define SMSO_CLI_RUN_OPTIMIZATION_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/Optimization_result.h>
#include <CGAL/Surface_mesh_seam_optimization/Seam_optimization_visitor.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Defaults.h>

#include <CGAL/Surface_mesh_seam_optimization/Cut_strategy.h>

#include <cstddef>
#include <functional>

namespace optimize_seams_cli {

namespace SMSO = CGAL::Surface_mesh_seam_optimization;

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_2                                     Point_2;
typedef Kernel::Point_3                                     Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor        vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor      halfedge_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor          edge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor          face_descriptor;
typedef Mesh::Property_map<halfedge_descriptor, Point_2>    UV_map;
typedef Mesh::Property_map<edge_descriptor, bool>           Seam_map;
typedef Mesh::Property_map<vertex_descriptor, double>       Vertex_cost_map;
typedef Mesh::Property_map<edge_descriptor, double>         Edge_cost_map;

// What the run does: the bound mode (OptCuts, the default), a fixed seam
// weight (no dual step), or the distortion-only mode with the seams kept.
enum class Mode { DISTORTION_BOUND, SEAM_WEIGHT, KEEP_SEAMS };

// The energies of --energy. The bound always applies to E_SD.
enum class Energy_kind { SYMMETRIC_DIRICHLET, ARAP, MIPS };

struct Optimization_request
{
  Mode mode = Mode::DISTORTION_BOUND;
  Energy_kind energy = Energy_kind::SYMMETRIC_DIRICHLET;
  double area_weight = 0.01;       // Conformal_energy's area term (MIPS only)
  double distortion_bound = SMSO::internal::default_distortion_bound; // DISTORTION_BOUND only
  double seam_weight = 0;          // SEAM_WEIGHT only
  bool use_input_uv = false;       // start from `uvmap` and the seams in `seams`
  bool bijective = true;
  std::size_t iteration_cap = 0;
  int recut_rounds = SMSO::internal::default_number_of_recut_rounds;  // DISTORTION_BOUND only
  int starts = SMSO::internal::default_number_of_starts;              // DISTORTION_BOUND only
  std::size_t proxy_faces = SMSO::internal::default_proxy_number_of_faces; // DISTORTION_BOUND only
  double time_limit = 0;           // seconds (the time_limit named parameter); 0: none
  // Seam costs (vertex_seam_cost_map, seam_cost_map; all 1 without --seam-weights). Not in KEEP_SEAMS.
  SMSO::Cut_strategy cut_strategy = SMSO::OPTCUTS; // DISTORTION_BOUND only
  Vertex_cost_map vertex_seam_cost;
  Edge_cost_map edge_seam_cost;
  // Called by the library's visitor (not in KEEP_SEAMS); false cancels the run.
  std::function<bool(const SMSO::Seam_optimization_progress&)> progress;
};

// One per energy, defined in run_<energy>.cpp.
SMSO::Optimization_result run_symmetric_dirichlet(Mesh& mesh, UV_map uvmap, Seam_map seams,
                                                  const Optimization_request& request);
SMSO::Optimization_result run_arap(Mesh& mesh, UV_map uvmap, Seam_map seams,
                                   const Optimization_request& request);
SMSO::Optimization_result run_mips(Mesh& mesh, UV_map uvmap, Seam_map seams,
                                   const Optimization_request& request);

inline SMSO::Optimization_result run_optimization(Mesh& mesh, UV_map uvmap, Seam_map seams,
                                                  const Optimization_request& request)
{
  switch(request.energy)
  {
    case Energy_kind::ARAP: return run_arap(mesh, uvmap, seams, request);
    case Energy_kind::MIPS: return run_mips(mesh, uvmap, seams, request);
    case Energy_kind::SYMMETRIC_DIRICHLET: break;
  }
  return run_symmetric_dirichlet(mesh, uvmap, seams, request);
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_RUN_OPTIMIZATION_H
