// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The scaffold ("air mesh") for global bijectivity: a triangulation of the
// space between the chart boundaries and a box around them (meshed by
// Scaffold_mesher.h). Its triangles enter the energy with a tiny symmetric
// Dirichlet weight, their rest shape being their shape when built; since no
// triangle of charts or scaffold may flip, no chart can cross another or
// itself.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SCAFFOLD_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SCAFFOLD_H

#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Element_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Flip_free_step.h>

#include <Eigen/Core>


#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

struct Scaffold
{
  // Unified vertex ids: [0, n_uv) are the charts' UV vertices, n_uv + k the
  // scaffold's own vertex k (box and Steiner points).
  int n_uv = 0;
  std::vector<double> pos;          // 2 per own vertex
  std::vector<int> tri;             // 3 per triangle, unified ids, ccw
  std::vector<double> rest_inverse; // 4 per triangle
  std::vector<double> weight;       // per triangle: weight * area / total scaffold area
  std::vector<double> built_density; // per triangle: energy density when built (4 unless its rest was thickened)
  // triangles around each chart UV vertex: vertex_triangles[vertex_offset[u] .. vertex_offset[u+1])
  std::vector<int> vertex_offset, vertex_triangles;
  struct Settings
  {
    // Total weight of the scaffold energy, relative to the charts' mean energy.
    double total_weight = 1e-2;
    // A scaffold triangle whose energy density grew by more than this since
    // it was built is too squeezed: rebuild. Rebuilding sooner (36) cost
    // time and, on statue_1_i_f8000, seams 4 times the reference's: the
    // charts were pushed around by ever new thickened slivers.
    double rebuild_threshold = 200.;
    // Rest shapes are no thinner than this times the median boundary edge.
    double min_height_ratio = 0.05;
  };
  Settings settings;
  double min_height = 0;

  std::size_t number_of_vertices() const { return pos.size() / 2; }
  std::size_t number_of_triangles() const { return weight.size(); }
  bool empty() const { return weight.empty(); }
  void clear()
  {
    n_uv = 0; pos.clear(); tri.clear(); rest_inverse.clear(); weight.clear(); built_density.clear();
    vertex_offset.clear(); vertex_triangles.clear();
  }

  // Position of a vertex by unified id.
  const double* position(const Cut_mesh& cm, int id) const
  {
    return id < n_uv ? &cm.uv[2*id] : &pos[2*(id - n_uv)];
  }


  // Meshes the space around the charts of `cm`; false (and empty) if the
  // chart boundaries cross or touch, i.e. the map is not bijective.
  // Defined in Scaffold_mesher.h (include it to call this), so that the
  // solver, which only evaluates a scaffold, does not pull in the mesher.
  bool build(const Cut_mesh& cm);

  // Energy (weighted symmetric Dirichlet) of the scaffold at unified positions x.
  double energy(const double* x) const
  {
    const Symmetric_Dirichlet_energy sd;
    Eigen::Matrix2d J;
    double e = 0;
    for(std::size_t t = 0; t < weight.size(); ++t)
    {
      triangle_jacobian(x + 2*tri[3*t], x + 2*tri[3*t+1], x + 2*tri[3*t+2], &rest_inverse[4*t], J);
      e += weight[t] * sd.value(J);
    }
    return e;
  }

  std::vector<double> densities(const double* x) const
  {
    const Symmetric_Dirichlet_energy sd;
    Eigen::Matrix2d J;
    std::vector<double> d(weight.size());
    for(std::size_t t = 0; t < weight.size(); ++t)
    {
      triangle_jacobian(x + 2*tri[3*t], x + 2*tri[3*t+1], x + 2*tri[3*t+2], &rest_inverse[4*t], J);
      d[t] = sd.value(J);
    }
    return d;
  }

  // Largest growth of a triangle's energy density since the scaffold was built.
  double max_density_growth(const double* x) const
  {
    const std::vector<double> d = densities(x);
    double m = 0;
    for(std::size_t t = 0; t < d.size(); ++t) m = (std::max)(m, d[t] - built_density[t]);
    return m;
  }

  // Largest t such that x + s * dir flips no scaffold triangle for s in [0, t).
  double max_flip_free_step(const double* x, const double* dir) const
  {
    double t = std::numeric_limits<double>::infinity();
    for(std::size_t k = 0; k < weight.size(); ++k)
    {
      const int i0 = 2 * tri[3*k], i1 = 2 * tri[3*k+1], i2 = 2 * tri[3*k+2];
      t = (std::min)(t, triangle_flip_free_step(x + i0, x + i1, x + i2, dir + i0, dir + i1, dir + i2));
    }
    return t;
  }

private:
  bool fail() { clear(); return false; }
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
