// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Scoring a topology operation: a few projected Newton iterations on a small
// stencil (the faces around the split or merged vertices) with only the new
// vertices free. With a scaffold, the scaffold triangles around the free
// vertices come along (symmetric Dirichlet, with their own rest shapes and
// weights), so that a free vertex cannot cross into another chart.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_LOCAL_STENCIL_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_LOCAL_STENCIL_H

#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Element_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Flip_free_step.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

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
  // scaffold triangles: 3 local ids, 4 rest-inverse entries and a weight each
  std::vector<int> extra_local;
  std::vector<double> extra_rest_inverse, extra_weight;

  void clear()
  {
    faces.clear(); local.clear(); pos.clear(); n_free = 0;
    extra_local.clear(); extra_rest_inverse.clear(); extra_weight.clear();
  }
  int add_vertex(double u, double v) { pos.push_back(u); pos.push_back(v); return int(pos.size() / 2) - 1; }
};

// The charts' part of the stencil energy.
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

// The scaffold's part.
inline double stencil_scaffold_energy(const Local_stencil& s, const double* pos)
{
  const Symmetric_Dirichlet_energy sd;
  double e = 0;
  Eigen::Matrix2d J;
  for(std::size_t i = 0; i < s.extra_weight.size(); ++i)
  {
    triangle_jacobian(pos + 2 * s.extra_local[3*i], pos + 2 * s.extra_local[3*i+1], pos + 2 * s.extra_local[3*i+2],
                      &s.extra_rest_inverse[4*i], J);
    e += s.extra_weight[i] * sd.value(J);
  }
  return e;
}

// Minimizes the stencil energy (charts and scaffold) over the free vertices;
// returns the charts' part.
template <typename Energy>
double optimize_stencil(const Cut_mesh& cm, const Energy& energy, Local_stencil& s, int iterations)
{
  const int n = 2 * s.n_free;
  const Symmetric_Dirichlet_energy sd;
  auto objective = [&](const double* x) { return stencil_energy(cm, energy, s, x) + stencil_scaffold_energy(s, x); };
  double e = objective(s.pos.data());
  if(n == 0 || !(e < std::numeric_limits<double>::infinity())) return stencil_energy(cm, energy, s, s.pos.data());
  // (a large stencil, a region moved by reroute_seam(), is sparse)
  const bool sparse = n > 256;
  Eigen::MatrixXd H(sparse ? 0 : n, sparse ? 0 : n);
  std::vector<Eigen::Triplet<double> > triplets;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > sparse_solver;
  Eigen::VectorXd g(n), p(n);
  std::vector<double> trial(s.pos.size()), dir(s.pos.size(), 0.);
  Eigen::Matrix2d J, dJ;
  Eigen::Matrix4d HJ;
  Eigen::Matrix<double, 6, 6> He;
  double ge[6];
  for(int it = 0; it < iterations; ++it)
  {
    if(!sparse) H.setZero();
    triplets.clear();
    g.setZero();
    const std::size_t n_faces = s.faces.size();
    for(std::size_t i = 0; i < n_faces + s.extra_weight.size(); ++i)
    {
      const bool chart = i < n_faces;
      const int* l = chart ? &s.local[3*i] : &s.extra_local[3*(i - n_faces)];
      if(l[0] >= s.n_free && l[1] >= s.n_free && l[2] >= s.n_free) continue;
      const double* B = chart ? &cm.rest_inverse[4 * s.faces[i]] : &s.extra_rest_inverse[4*(i - n_faces)];
      triangle_jacobian(&s.pos[2*l[0]], &s.pos[2*l[1]], &s.pos[2*l[2]], B, J);
      if(chart) energy.value_gradient_and_hessian(J, dJ, HJ, true);
      else sd.value_gradient_and_hessian(J, dJ, HJ, true);
      element_derivatives(Jacobian_coefficients(B),
                          chart ? cm.face_area[s.faces[i]] / cm.total_area : s.extra_weight[i - n_faces],
                          dJ, HJ, ge, &He);
      for(int x = 0; x < 3; ++x)
      {
        if(l[x] >= s.n_free) continue;
        for(int r = 0; r < 2; ++r)
        {
          g[2*l[x] + r] += ge[2*x + r];
          for(int y = 0; y < 3; ++y)
            if(l[y] < s.n_free)
              for(int q = 0; q < 2; ++q)
              {
                if(sparse) triplets.emplace_back(2*l[x] + r, 2*l[y] + q, He(2*x + r, 2*y + q));
                else H(2*l[x] + r, 2*l[y] + q) += He(2*x + r, 2*y + q);
              }
        }
      }
    }
    if(sparse)
    {
      Eigen::SparseMatrix<double> Hs(n, n);
      Hs.setFromTriplets(triplets.begin(), triplets.end());
      const double shift = 1e-12 * (1. + Hs.diagonal().cwiseAbs().maxCoeff());
      for(int i = 0; i < n; ++i) Hs.coeffRef(i, i) += shift;
      // (every iteration assembles the same pattern: one ordering, as compute() would find each time)
      if(it == 0) sparse_solver.analyzePattern(Hs);
      sparse_solver.factorize(Hs);
      p = sparse_solver.info() == Eigen::Success ? Eigen::VectorXd(sparse_solver.solve(-g)) : Eigen::VectorXd(-g);
    }
    else
    {
      H.diagonal().array() += 1e-12 * (1. + H.diagonal().cwiseAbs().maxCoeff());
      p = H.ldlt().solve(-g);
    }
    double slope = g.dot(p);
    if(!(slope < 0)) { p = -g; slope = -g.squaredNorm(); }
    if(-slope < 1e-20) break;
    for(int i = 0; i < n; ++i) dir[i] = p[i];
    // flip-free bound over the stencil faces and scaffold triangles
    double t = 1.;
    for(std::size_t i = 0; i < n_faces + s.extra_weight.size(); ++i)
    {
      const int* l = i < n_faces ? &s.local[3*i] : &s.extra_local[3*(i - n_faces)];
      const double r = triangle_flip_free_step(&s.pos[2*l[0]], &s.pos[2*l[1]], &s.pos[2*l[2]],
                                               &dir[2*l[0]], &dir[2*l[1]], &dir[2*l[2]]);
      t = (std::min)(t, 0.99 * r);
    }
    double en = e;
    for(int k = 0; k < 30; ++k, t *= 0.5)
    {
      for(std::size_t i = 0; i < trial.size(); ++i) trial[i] = s.pos[i] + t * dir[i];
      en = objective(trial.data());
      if(en <= e + 1e-4 * t * slope) break;
    }
    if(!(en < e)) break;
    const double decrease = e - en;
    s.pos.swap(trial);
    e = en;
    if(decrease < 1e-10 * e) break;
  }
  return stencil_energy(cm, energy, s, s.pos.data());
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
