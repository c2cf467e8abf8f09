// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Validity of a UV map (no flipped, no numerically degenerate triangle) and
// local untangling of an initial map that is not valid: the flipped region,
// grown by a few rings, is mapped anew by Tutte's barycentric embedding with
// its border fixed; the region grows while the result is still not valid.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_UNTANGLE_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_UNTANGLE_H

#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Element_energy.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Face f's UV triangle has twice its signed area above `least_area2` and a
// finite E_SD.
inline bool uv_triangle_above(const Cut_mesh& cm, std::size_t f, double least_area2)
{
  if(!(cm.signed_uv_area2(f) > least_area2)) return false;
  Eigen::Matrix2d J;
  face_jacobian(cm, f, cm.uv.data(), J);
  return std::isfinite(Symmetric_Dirichlet_energy().value(J));
}

// Per face: flipped or numerically degenerate (twice the signed area <=
// 1e-12 times that of the face's chart, uvmetrics.py's test), or an E_SD
// that is not finite. Returns the count.
inline std::size_t mark_invalid_uv_triangles(const Cut_mesh& cm, std::vector<char>& invalid)
{
  std::vector<int> chart;
  const std::size_t nc = cm.compute_charts(chart);
  std::vector<double> chart_area2(nc, 0.);
  const std::size_t nf = cm.number_of_faces();
  for(std::size_t f = 0; f < nf; ++f) chart_area2[chart[f]] += std::abs(cm.signed_uv_area2(f));
  invalid.assign(nf, 0);
  std::size_t n = 0;
  for(std::size_t f = 0; f < nf; ++f)
    if(!uv_triangle_above(cm, f, 1e-12 * chart_area2[chart[f]])) { invalid[f] = 1; ++n; }
  return n;
}

// The same count; `first` (if given) says which face is the first invalid one.
inline std::size_t count_invalid_uv_triangles(const Cut_mesh& cm, std::string* first = nullptr)
{
  std::vector<char> invalid;
  const std::size_t n = mark_invalid_uv_triangles(cm, invalid);
  if(n > 0 && first)
  {
    const std::size_t f = std::size_t(std::find(invalid.begin(), invalid.end(), 1) - invalid.begin());
    *first = "UV triangle of face " + std::to_string(f) + (cm.signed_uv_area2(f) > 0 ? " is degenerate" : " is flipped");
  }
  return n;
}

// The first face whose UV triangle is flipped, of zero area or of an E_SD
// that is not finite (outside the domain of the barrier energies the descent
// minimizes), or the number of faces if there is none.
inline std::size_t first_face_outside_barrier_domain(const Cut_mesh& cm)
{
  for(std::size_t f = 0; f < cm.number_of_faces(); ++f)
    if(!uv_triangle_above(cm, f, 0.)) return f;
  return cm.number_of_faces();
}

// Untangles the invalid triangles of the map in place: the region of the
// invalid faces grown by r rings (r = 1, 2, 4, ... up to `max_rings`), its
// UV vertices that are neither on its border nor on a chart's boundary
// placed by Tutte's embedding (uniform weights) with all others fixed. By
// Tutte's theorem the result is valid when a region is a disk with a convex
// border; a region that is not is grown until the result checks valid.
// Returns false, the map unchanged, if no region did; `count` receives the
// number of invalid triangles of the input.
inline bool untangle_uv_map(Cut_mesh& cm, std::size_t& count, int max_rings = 64)
{
  std::vector<char> invalid;
  count = mark_invalid_uv_triangles(cm, invalid);
  if(count == 0) return true;
  const std::size_t nf = cm.number_of_faces(), nuv = cm.number_of_uv_vertices();

  // faces around each UV vertex, and the UV vertices on a chart's boundary
  std::vector<int> offset(nuv + 1, 0), faces_of(3 * nf);
  for(std::size_t c = 0; c < 3 * nf; ++c) ++offset[cm.corner_uv[c] + 1];
  for(std::size_t v = 0; v < nuv; ++v) offset[v + 1] += offset[v];
  {
    std::vector<int> fill(offset.begin(), offset.end() - 1);
    for(std::size_t c = 0; c < 3 * nf; ++c) faces_of[fill[cm.corner_uv[c]]++] = int(c / 3);
  }
  std::vector<char> on_boundary(nuv, 0);
  for(std::size_t h = 0; h < 3 * nf; ++h)
    if(cm.opposite[h] < 0 || cm.is_seam(int(h)))
      on_boundary[cm.corner_uv[h]] = on_boundary[cm.corner_uv[Cut_mesh::prev(int(h))]] = 1;

  std::vector<char> region = invalid;
  auto grow = [&]() {
    std::vector<char> next = region;
    for(std::size_t f = 0; f < nf; ++f)
      if(region[f])
        for(int k = 0; k < 3; ++k)
        {
          const int v = cm.corner_uv[3*f + k];
          for(int i = offset[v]; i < offset[v + 1]; ++i) next[faces_of[i]] = 1;
        }
    region.swap(next);
  };

  const std::vector<double> original = cm.uv;
  int rings = 0;
  for(int target = 1; target <= max_rings; target *= 2)
  {
    for(; rings < target; ++rings) grow();
    // the unknowns: UV vertices all of whose faces are in the region, off the boundary
    std::vector<int> unknown(nuv, -1);
    int n = 0;
    for(std::size_t v = 0; v < nuv; ++v)
    {
      if(on_boundary[v] || offset[v] == offset[v + 1]) continue;
      bool inside = true;
      for(int i = offset[v]; i < offset[v + 1] && inside; ++i) inside = region[faces_of[i]] != 0;
      if(inside) unknown[v] = n++;
    }
    if(n == 0) continue;
    // Tutte: each unknown at the mean of its neighbours (edges of its faces)
    std::vector<Eigen::Triplet<double> > triplets;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n, 2);
    std::vector<int> neighbours;
    for(std::size_t v = 0; v < nuv; ++v)
    {
      const int row = unknown[v];
      if(row < 0) continue;
      neighbours.clear();
      for(int i = offset[v]; i < offset[v + 1]; ++i)
        for(int k = 0; k < 3; ++k)
        {
          const int w = cm.corner_uv[3 * faces_of[i] + k];
          if(w != int(v)) neighbours.push_back(w);
        }
      std::sort(neighbours.begin(), neighbours.end());
      neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
      triplets.emplace_back(row, row, double(neighbours.size()));
      for(int w : neighbours)
      {
        if(unknown[w] >= 0) triplets.emplace_back(row, unknown[w], -1.);
        else { rhs(row, 0) += cm.uv[2*w]; rhs(row, 1) += cm.uv[2*w + 1]; }
      }
    }
    Eigen::SparseMatrix<double> L(n, n);
    L.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > solver(L);
    if(solver.info() != Eigen::Success) continue;
    const Eigen::MatrixXd x = solver.solve(rhs);
    if(solver.info() != Eigen::Success || !x.allFinite()) continue;
    for(std::size_t v = 0; v < nuv; ++v)
      if(unknown[v] >= 0) { cm.uv[2*v] = x(unknown[v], 0); cm.uv[2*v + 1] = x(unknown[v], 1); }
    std::vector<char> still;
    if(mark_invalid_uv_triangles(cm, still) == 0) return true;
    cm.uv = original;
    // (a region that covers whole charts cannot grow further)
    if(std::find(region.begin(), region.end(), 0) == region.end()) break;
  }
  return false;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_UNTANGLE_H
