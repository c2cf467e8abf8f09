// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_OPTIMIZATION_VISITOR_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_OPTIMIZATION_VISITOR_H

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// The state passed to a visitor.
struct Seam_optimization_progress
{
  std::size_t iterations = 0;          ///< Newton iterations so far
  std::size_t topology_operations = 0; ///< splits and merges applied so far
  double distortion = 0;               ///< current E_SD
  double seam_length_normalized = 0;   ///< current E_se
  double lambda = 0;                   ///< current seam weight of E_w
  double seconds = 0;                  ///< since the start
};

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// The default model of `SeamOptimizationVisitor`: does nothing, never cancels.
/// Each member returns `false` to stop the run (the best result so far is kept).
struct Default_seam_optimization_visitor
{
  bool on_iteration(const Seam_optimization_progress&) { return true; }
  bool on_topology_operation(const Seam_optimization_progress&) { return true; }
  bool on_lambda_update(const Seam_optimization_progress&) { return true; }
};

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
