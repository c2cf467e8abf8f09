// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_CUT_STRATEGY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_CUT_STRATEGY_H

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// How `optimize_seams()` places the seams (named parameter `cut_strategy`).
enum Cut_strategy
{
  OPTCUTS, ///< OptCuts: topology steps and dual step, the shortest seams found under the bound (the default)
  EBCUTS   ///< the baseline of the OptCuts paper's comparison: extremity-based cuts, each the shortest path from
           ///< the vertex of largest distortion to the nearest seam or border, the distortion minimized with the
           ///< seams fixed in between, until the bound is met (no scaffold: the map may overlap itself)
};

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
