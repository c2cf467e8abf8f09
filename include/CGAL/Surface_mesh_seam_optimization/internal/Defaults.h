// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Defaults of the named parameters that several functions read.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DEFAULTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_DEFAULTS_H

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// The bound on E_SD (4 is an isometry): the paper's default.
constexpr double default_distortion_bound = 4.1;

// Caps on Newton iterations (named parameter number_of_iterations): in total
// for optimize_seams() and Seam_optimizer, and for minimize_distortion().
constexpr std::size_t default_number_of_iterations = 100000;
constexpr std::size_t default_number_of_iterations_distortion_only = 10000;

// Rounds of unzipping and cutting again after the first result at the bound
// (named parameter number_of_recut_rounds).
constexpr int default_number_of_recut_rounds = 6;

// Starts of optimize_seams() in bound mode, the shortest feasible result
// kept (named parameter number_of_starts): the first and, with the scaffold,
// the relaxed start where the first's charts overlap, else (or after a
// relaxed start that found nothing feasible) the first-cut start (without
// the scaffold, the hold-price start).
constexpr int default_number_of_starts = 2;
// Every start after the first does at most this many times the first's
// Newton iterations: two starts take at most about twice one start. (On the
// 19 meshes where it was measured, the hold-price start's result was kept
// only when it took at most 2.04 times the first's iterations (sphere_f1522);
// it took 2.1-2.7 times on six meshes, and lost on all six.)
constexpr double second_start_iteration_factor = 2.;
// (the share of it the first-cut start has when it is the second start: at
// most the first start's iterations)
constexpr double first_cut_beside_first_share = 0.5;
// Seams of a mesh of more than twice this many faces are optimized on a proxy
// of this many faces first (parameters::proxy_number_of_faces(); 0: never).
constexpr std::size_t default_proxy_number_of_faces = 0;

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
