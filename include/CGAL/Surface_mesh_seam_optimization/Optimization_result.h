// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_OPTIMIZATION_RESULT_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_OPTIMIZATION_RESULT_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>

#include <cstddef>
#include <limits>
#include <string>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Wall seconds spent in each phase of an optimization (the rest: setup,
/// measures, copying in and out).
struct Optimization_timings
{
  double assembly = 0;          ///< energies, gradients and projected Hessians of the Newton iterations
  double factorization = 0;     ///< numeric factorizations and solves
  double symbolic_analysis = 0; ///< sparsity pattern and its analysis, after a topology operation or a new scaffold
  double line_search = 0;       ///< flip-free step bound and backtracking
  double topology = 0;          ///< candidate operations: ranking, stencil solves, application
  double scaffold = 0;          ///< meshing the scaffold

  double total() const
  {
    return assembly + factorization + symbolic_analysis + line_search + topology + scaffold;
  }

  /// adds the seconds of another optimization, phase by phase
  Optimization_timings& operator+=(const Optimization_timings& other)
  {
    assembly += other.assembly;
    factorization += other.factorization;
    symbolic_analysis += other.symbolic_analysis;
    line_search += other.line_search;
    topology += other.topology;
    scaffold += other.scaffold;
    return *this;
  }
};

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// What `minimize_distortion()` and `optimize_seams()` return.
struct Optimization_result
{
  Error_code status = ERROR_WRONG_PARAMETER;
  std::string message;              ///< details of an error (which face, which parameter), or a note on the input (an untangled initial map)
  double distortion = std::numeric_limits<double>::infinity(); ///< E_SD of the result as written (>= 4)
  /// the normalized (area-weighted mean) value of the run's `energy`, the figure the distortion bound is
  /// on (equal to `distortion` for `Symmetric_Dirichlet_energy`)
  double energy_value = std::numeric_limits<double>::infinity();
  /// E_SD of the result scaled uniformly by `optimal_scale`, the factor that
  /// minimizes it (closed form: with \f$a = \sum A_t(\sigma_1^2+\sigma_2^2)\f$ and
  /// \f$b = \sum A_t(\sigma_1^{-2}+\sigma_2^{-2})\f$, \f$s^4 = b/a\f$ and the value is
  /// \f$2\sqrt{ab}/A\f$). The map of a scale-invariant energy (`Conformal_energy`) is written at this
  /// scale, so that its `distortion` equals this figure
  double distortion_at_optimal_scale = std::numeric_limits<double>::infinity();
  double optimal_scale = 1;         ///< see `distortion_at_optimal_scale`
  double initial_distortion = std::numeric_limits<double>::infinity();
  double seam_length = 0;           ///< 3D length of the seam edges, each once
  double seam_length_normalized = 0;///< seam_length / sqrt(area / pi)
  /// the seam term \f$ E_{seam} \f$ as optimized: each seam edge's length times its seam cost
  /// (`seam_cost_map`, `vertex_seam_cost_map`), over sqrt(area / pi); equal to
  /// `seam_length_normalized` without seam costs
  double weighted_seam_length_normalized = 0;
  double lambda = 0;                ///< final seam weight of E_w
  std::size_t charts = 0;
  std::size_t iterations = 0;       ///< Newton iterations
  std::size_t topology_operations = 0;
  bool bound_met = false;           ///< `energy_value` <= the bound
  std::size_t overlapping_triangle_pairs = 0; ///< checked on the result, whether `bijective` was asked for or not
  bool bijective = false;           ///< no flipped triangle and no overlap (checked, not assumed)
  std::size_t scaffold_rebuilds = 0; ///< times the scaffold was meshed anew
  /// `optimize_seams()`: the start whose result this is (see `number_of_starts`): 0 the first (OptCuts from
  /// the initial map), 1 the hold-price start (a dual step that holds the price of distortion while a cut
  /// pays), 2 the relaxed start (seams without the scaffold first; its iterations, operations, scaffold
  /// rebuilds and timings count both phases), 3 the first-cut start (from EBCuts' first cut; its timings
  /// count the distortion minimization it cuts from); the other figures are those of that start
  std::size_t start = 0;
  /// faces of the simplified proxy the seams were optimized on before the mesh
  /// itself (`proxy_number_of_faces`), 0 if none; the iterations and operations count both
  std::size_t proxy_faces = 0;
  double seconds = 0;
  Optimization_timings timings;     ///< where the seconds of the kept start went (`seconds` also counts
                                    ///< the time it waited for the others, which ran beside it)

  bool has_result() const { return Surface_mesh_seam_optimization::has_result(status); }
};

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
