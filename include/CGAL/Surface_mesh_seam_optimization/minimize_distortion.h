// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_MINIMIZE_DISTORTION_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_MINIMIZE_DISTORTION_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/Optimization_result.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Minimizes the distortion energy of a UV map whose seams are fixed
/// (work in progress: the real body lands with the core).
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Optimization_result minimize_distortion(const TriangleMesh& tm, UVMap uvmap,
                                        const NamedParameters& np = parameters::default_values())
{
  (void)tm; (void)uvmap; (void)np;
  Optimization_result r;
  r.status = ERROR_WRONG_PARAMETER;
  r.message = "not implemented yet";
  return r;
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
