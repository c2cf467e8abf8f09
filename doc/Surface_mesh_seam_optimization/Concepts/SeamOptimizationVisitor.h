// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

/*!
\ingroup PkgSurfaceMeshSeamOptimizationConcepts
\cgalConcept

The concept `SeamOptimizationVisitor` describes the observer that
`CGAL::Surface_mesh_seam_optimization::optimize_seams()` calls while it runs
(named parameter `visitor`): after every Newton iteration, after every
topology operation (split or merge) it applies, and after every update of the
seam weight \f$ \lambda \f$ by the dual step. Each call receives a
`CGAL::Surface_mesh_seam_optimization::Seam_optimization_progress`, the
current state of the run:

<table>
<tr><th>Field</th><th>Meaning</th></tr>
<tr><td>`iterations`</td><td>Newton iterations so far (at the end, the `iterations` of the result)</td></tr>
<tr><td>`topology_operations`</td><td>splits and merges applied so far, those of fracture propagation included</td></tr>
<tr><td>`distortion`</td><td>the current value of the distortion energy of the descent: \f$ E_{SD} \f$ with the default `energy`</td></tr>
<tr><td>`seam_length_normalized`</td><td>the current normalized seam length \f$ E_{seam} \f$ (3D lengths, without the seam costs of `seam_cost_map` and `vertex_seam_cost_map`)</td></tr>
<tr><td>`lambda`</td><td>the current seam weight \f$ \lambda \f$ of \f$ E_w = (1 - \lambda) E_{SD} + \lambda E_{seam} \f$</td></tr>
<tr><td>`seconds`</td><td>wall-clock seconds since the alternating optimization started (after the copy of the mesh and the initial map)</td></tr>
</table>

Each member returns `true` to go on and `false` to stop the run. A stopped
run still writes a valid, flip-free result into the user's maps: in bound
mode the best configuration met so far that satisfies the bound (if there is
one), otherwise the current one. A run stopped from `on_iteration()` or
`on_topology_operation()` returns the status `WARNING_CANCELLED`.

The calls are made from the thread that called `optimize_seams()`, one at a
time; they should be cheap, since `on_iteration()` is called once per
Newton iteration. A visitor passed by value (`visitor(v)`,
`visitor(My_visitor())`) is copied and the copy is called, as in
`Polygon_mesh_processing`; pass `std::ref(v)` so that the function calls
the user's object itself, and the state it accumulates is visible after the
call.

\cgalHasModel `CGAL::Surface_mesh_seam_optimization::Default_seam_optimization_visitor` (does nothing, never stops the run)

\sa `CGAL::Surface_mesh_seam_optimization::optimize_seams()`
*/
class SeamOptimizationVisitor
{
public:
  /// \name Operations
  /// @{

  /// Called after every Newton iteration of the descent (before the seams
  /// created by the last split are extended from their tips).
  /// Returns `false` to stop the run.
  bool on_iteration(const CGAL::Surface_mesh_seam_optimization::Seam_optimization_progress& progress);

  /// Called after every topology operation applied to the UV mesh: a
  /// boundary split, an interior split or a corner merge chosen by a topology
  /// step, or the extension of a seam by fracture propagation.
  /// Returns `false` to stop the run.
  bool on_topology_operation(const CGAL::Surface_mesh_seam_optimization::Seam_optimization_progress& progress);

  /// Called after every dual update of \f$ \lambda \f$ (bound mode only:
  /// never with a fixed `seam_weight`); `progress.lambda` is the new value.
  /// Returns `false` to stop the run.
  bool on_lambda_update(const CGAL::Surface_mesh_seam_optimization::Seam_optimization_progress& progress);

  /// @}
};
