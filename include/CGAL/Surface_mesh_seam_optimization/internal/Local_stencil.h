// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Scoring a topology operation: a few projected Newton iterations on a small
// stencil (the faces around the split or merged vertices) with only the new
// vertices free.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_LOCAL_STENCIL_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_LOCAL_STENCIL_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Element_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Flip_free_step.h>

#include <Eigen/Dense>

#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

struct Local_stencil
{
  std::vector<int> faces;      // face ids
  std::vector<int> local;      // 3 per face: local vertex ids
  std::vector<double> pos;     // 2 per local vertex; [0, n_free) are free
  int n_free = 0;

  void clear() { faces.clear(); local.clear(); pos.clear(); n_free = 0; }
  int add_vertex(double u, double v) { pos.push_back(u); pos.push_back(v); return int(pos.size() / 2) - 1; }
};

template <typename Energy>
double stencil_energy(const Cut_mesh& cm, const Energy& energy, const Local_stencil& s, const double* pos)
{
  double e = 0;
  Eigen::Matrix2d J;
  for(std::size_t i = 0; i < s.faces.size(); ++i)
  {
    triangle_jacobian(pos + 2 * s.local[3*i], pos + 2 * s.local[3*i+1], pos + 2 * s.local[3*i+2],
                      &cm.rest_inverse[4 * s.faces[i]], J);
    e += cm.face_area[s.faces[i]] * energy.value(J);
  }
  return e / cm.total_area;
}

// Minimizes the stencil energy over the free vertices; returns the energy.
template <typename Energy>
double optimize_stencil(const Cut_mesh& cm, const Energy& energy, Local_stencil& s, int iterations)
{
  const int n = 2 * s.n_free;
  double e = stencil_energy(cm, energy, s, s.pos.data());
  if(n == 0 || !(e < std::numeric_limits<double>::infinity())) return e;
  Eigen::MatrixXd H(n, n);
  Eigen::VectorXd g(n), p(n);
  std::vector<double> trial(s.pos.size()), dir(s.pos.size(), 0.);
  Eigen::Matrix2d J, dJ;
  Eigen::Matrix4d HJ;
  Eigen::Matrix<double, 6, 6> He;
  double ge[6];
  for(int it = 0; it < iterations; ++it)
  {
    H.setZero(); g.setZero();
    for(std::size_t i = 0; i < s.faces.size(); ++i)
    {
      const int* l = &s.local[3*i];
      if(l[0] >= s.n_free && l[1] >= s.n_free && l[2] >= s.n_free) continue;
      const double* B = &cm.rest_inverse[4 * s.faces[i]];
      triangle_jacobian(&s.pos[2*l[0]], &s.pos[2*l[1]], &s.pos[2*l[2]], B, J);
      energy.value_gradient_and_hessian(J, dJ, HJ, true);
      element_derivatives(Jacobian_coefficients(B), cm.face_area[s.faces[i]] / cm.total_area, dJ, HJ, ge, &He);
      for(int x = 0; x < 3; ++x)
      {
        if(l[x] >= s.n_free) continue;
        for(int r = 0; r < 2; ++r)
        {
          g[2*l[x] + r] += ge[2*x + r];
          for(int y = 0; y < 3; ++y)
            if(l[y] < s.n_free)
              for(int q = 0; q < 2; ++q) H(2*l[x] + r, 2*l[y] + q) += He(2*x + r, 2*y + q);
        }
      }
    }
    H.diagonal().array() += 1e-12 * (1. + H.diagonal().cwiseAbs().maxCoeff());
    p = H.ldlt().solve(-g);
    double slope = g.dot(p);
    if(!(slope < 0)) { p = -g; slope = -g.squaredNorm(); }
    if(-slope < 1e-20) break;
    for(int i = 0; i < n; ++i) dir[i] = p[i];
    // flip-free bound over the stencil faces
    double t = 1.;
    for(std::size_t i = 0; i < s.faces.size(); ++i)
    {
      const int* l = &s.local[3*i];
      const double r = triangle_flip_free_step(&s.pos[2*l[0]], &s.pos[2*l[1]], &s.pos[2*l[2]],
                                               &dir[2*l[0]], &dir[2*l[1]], &dir[2*l[2]]);
      t = (std::min)(t, 0.99 * r);
    }
    double en = e;
    for(int k = 0; k < 30; ++k, t *= 0.5)
    {
      for(std::size_t i = 0; i < trial.size(); ++i) trial[i] = s.pos[i] + t * dir[i];
      en = stencil_energy(cm, energy, s, trial.data());
      if(en <= e + 1e-4 * t * slope) break;
    }
    if(!(en < e)) break;
    const double decrease = e - en;
    s.pos.swap(trial);
    e = en;
    if(decrease < 1e-10 * e) break;
  }
  return e;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
