// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Defaults of the named parameters that several functions read.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DEFAULTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DEFAULTS_H

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// The bound on E_SD (4 is an isometry): the paper's default.
constexpr double default_distortion_bound = 4.1;

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
