// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The figures of an Optimization_result read off the core mesh, shared by
// minimize_distortion(), optimize_seams() and Seam_optimizer.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_MEASURE_RESULT_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_MEASURE_RESULT_H

#include <CGAL/Surface_mesh_seam_optimization/Optimization_result.h>
#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Overlap.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Projected_newton.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Fills the figures of `r` (E_SD, seams, charts) from the core mesh; the
// bound is judged as judged_distortion() says for `energy`. `seam_cost`: the
// per-corner seam costs, if any.
template <typename Energy>
void measure_result(const Cut_mesh& cm, const Energy& energy, double bound, Optimization_result& r,
                    const std::vector<double>* seam_cost = nullptr)
{
  r.distortion = total_energy(cm, Symmetric_Dirichlet_energy(), cm.uv.data());
  r.distortion_at_optimal_scale = symmetric_dirichlet_at_optimal_scale(cm, cm.uv.data(), &r.optimal_scale);
  r.energy_value = judged_distortion(cm, energy, cm.uv.data());
  r.bound_met = r.energy_value <= bound;
  r.seam_length = cm.seam_length();
  r.seam_length_normalized = r.seam_length / cm.normalization_radius();
  r.weighted_seam_length_normalized =
    seam_cost ? cm.seam_length(seam_cost) / cm.normalization_radius() : r.seam_length_normalized;
  std::vector<int> chart;
  r.charts = cm.compute_charts(chart);
  r.overlapping_triangle_pairs = count_overlapping_pairs(cm);
  std::size_t flipped = 0;
  for(std::size_t f = 0; f < cm.number_of_faces(); ++f)
    if(!(cm.signed_uv_area2(f) > 0)) ++flipped;
  r.bijective = flipped == 0 && r.overlapping_triangle_pairs == 0;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
