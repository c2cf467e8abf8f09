// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Meshing the scaffold (Scaffold::build()): a constrained Delaunay
// triangulation of the space between the chart boundaries and a box around
// them, refined for shape (Steiner points inside, none on the chart
// boundaries) so that thin triangles do not block the charts' motion.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SCAFFOLD_MESHER_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SCAFFOLD_MESHER_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Overlap.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Scaffold.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

inline bool Scaffold::build(const Cut_mesh& cm)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  struct Vertex_id { int id = 0; }; // > 0: UV vertex id + 1, < 0: -(own vertex + 1), 0: Steiner point
  typedef CGAL::Triangulation_vertex_base_with_info_2<Vertex_id, K> Vb;
  typedef CGAL::Delaunay_mesh_face_base_2<K> Fb0;
  typedef CGAL::Triangulation_face_base_with_info_2<int, K, Fb0> Fb;
  typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag> CDT;
  typedef CDT::Vertex_handle Vertex_handle;
  typedef CDT::Face_handle Face_handle;

  clear();
  n_uv = int(cm.number_of_uv_vertices());
  if(count_overlapping_pairs(cm, 1) > 0) return false;

  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  for(int i = 0; i < n_uv; ++i)
  {
    x0 = (std::min)(x0, cm.uv[2*i]); x1 = (std::max)(x1, cm.uv[2*i]);
    y0 = (std::min)(y0, cm.uv[2*i+1]); y1 = (std::max)(y1, cm.uv[2*i+1]);
  }
  const double margin = 0.5 * (std::max)(x1 - x0, y1 - y0);
  x0 -= margin; y0 -= margin; x1 += margin; y1 += margin;

  CDT cdt;
  std::vector<Vertex_handle> handle(n_uv);
  std::vector<int> boundary; // pairs of UV vertices
  std::size_t inserted = 0;
  for(std::size_t h = 0; h < cm.corner_vertex.size(); ++h)
  {
    if(cm.opposite[h] >= 0 && !cm.is_seam(int(h))) continue;
    const int a = cm.corner_uv[Cut_mesh::prev(int(h))], b = cm.corner_uv[h];
    for(int u : { a, b })
      if(handle[u] == Vertex_handle())
      {
        handle[u] = cdt.insert(K::Point_2(cm.uv[2*u], cm.uv[2*u+1]));
        if(cdt.number_of_vertices() != ++inserted) return fail(); // coincident vertices
        handle[u]->info().id = u + 1;
      }
    boundary.push_back(a); boundary.push_back(b);
  }
  // thinnest rest shape: a small fraction of the typical boundary edge
  {
    std::vector<double> length;
    for(std::size_t i = 0; i < boundary.size(); i += 2)
      length.push_back(std::hypot(cm.uv[2*boundary[i]] - cm.uv[2*boundary[i+1]],
                                  cm.uv[2*boundary[i]+1] - cm.uv[2*boundary[i+1]+1]));
    std::nth_element(length.begin(), length.begin() + length.size() / 2, length.end());
    min_height = length.empty() ? 0. : settings.min_height_ratio * length[length.size() / 2];
  }
  // the box, a few vertices per side so that its triangles stay reasonable
  const int per_side = 4;
  std::vector<Vertex_handle> box;
  for(int side = 0; side < 4; ++side)
    for(int k = 0; k < per_side; ++k)
    {
      const double t = double(k) / per_side;
      double x = 0, y = 0;
      switch(side)
      {
        case 0: x = x0 + t * (x1 - x0); y = y0; break;
        case 1: x = x1; y = y0 + t * (y1 - y0); break;
        case 2: x = x1 - t * (x1 - x0); y = y1; break;
        default: x = x0; y = y1 - t * (y1 - y0); break;
      }
      Vertex_handle v = cdt.insert(K::Point_2(x, y));
      if(cdt.number_of_vertices() != ++inserted) return fail();
      v->info().id = -int(pos.size() / 2) - 1;
      pos.push_back(x); pos.push_back(y);
      box.push_back(v);
    }
  for(std::size_t i = 0; i < box.size(); ++i) cdt.insert_constraint(box[i], box[(i + 1) % box.size()]);
  for(std::size_t i = 0; i < boundary.size(); i += 2)
    cdt.insert_constraint(handle[boundary[i]], handle[boundary[i+1]]);
  // a constraint crossing another (or through a vertex) adds a vertex
  if(cdt.number_of_vertices() != inserted) return fail();

  // shape refinement of the empty space (charts are the seeds not to mesh)
  {
    std::vector<int> chart;
    const std::size_t n_charts = cm.compute_charts(chart);
    std::vector<K::Point_2> seeds(n_charts);
    std::vector<char> seeded(n_charts, 0);
    for(std::size_t f = 0; f < chart.size(); ++f)
    {
      if(seeded[chart[f]]) continue;
      seeded[chart[f]] = 1;
      double c[2] = { 0, 0 };
      for(int k = 0; k < 3; ++k)
        for(int d = 0; d < 2; ++d) c[d] += cm.uv[2 * cm.corner_uv[3*f + k] + d] / 3.;
      seeds[chart[f]] = K::Point_2(c[0], c[1]);
    }
    CGAL::Delaunay_mesher_no_edge_refinement_2<CDT, CGAL::Delaunay_mesh_size_criteria_2<CDT> >
      mesher(cdt, CGAL::Delaunay_mesh_size_criteria_2<CDT>(0.125, 0.));
    mesher.set_seeds(seeds.begin(), seeds.end(), false);
    mesher.refine_mesh();
    for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      if(v->info().id == 0)
      {
        v->info().id = -int(pos.size() / 2) - 1;
        pos.push_back(v->point().x()); pos.push_back(v->point().y());
      }
  }

  // nesting depth: 0 outside the box, 1 in the scaffold, 2 in the charts,
  // 3 in holes of the charts (empty space too), ...
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::vector<Face_handle> stack, next_stack;
  cdt.infinite_face()->info() = 0;
  stack.push_back(cdt.infinite_face());
  for(int depth = 0; !stack.empty(); ++depth)
  {
    while(!stack.empty())
    {
      Face_handle f = stack.back(); stack.pop_back();
      for(int i = 0; i < 3; ++i)
      {
        Face_handle g = f->neighbor(i);
        if(g->info() != -1) continue;
        if(cdt.is_constrained(CDT::Edge(f, i))) { next_stack.push_back(g); continue; }
        g->info() = depth;
        stack.push_back(g);
      }
    }
    for(Face_handle g : next_stack) if(g->info() == -1) { g->info() = depth + 1; stack.push_back(g); }
    next_stack.clear();
  }

  auto unified = [&](Vertex_handle v) { return v->info().id > 0 ? v->info().id - 1 : n_uv + (-v->info().id - 1); };
  double total_area = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
  {
    if(f->info() % 2 != 1) continue;
    int t[3];
    for(int k = 0; k < 3; ++k) t[k] = unified(f->vertex(k));
    const double* p0 = t[0] < n_uv ? &cm.uv[2*t[0]] : &pos[2*(t[0]-n_uv)];
    const double* p1 = t[1] < n_uv ? &cm.uv[2*t[1]] : &pos[2*(t[1]-n_uv)];
    const double* p2 = t[2] < n_uv ? &cm.uv[2*t[2]] : &pos[2*(t[2]-n_uv)];
    const double det = (p1[0]-p0[0]) * (p2[1]-p0[1]) - (p2[0]-p0[0]) * (p1[1]-p0[1]);
    if(!(det > 0)) return fail(); // a triangle of (numerically) collinear vertices
    // The rest shape is the current one, but no thinner than min_height:
    // squeezing a thin gap further then costs energy, instead of the gap
    // shrinking geometrically from one rebuild to the next.
    double q[3][2] = { { p0[0], p0[1] }, { p1[0], p1[1] }, { p2[0], p2[1] } };
    int i = 0; double L2 = -1;
    for(int k = 0; k < 3; ++k)
    {
      const double dx = q[(k+1)%3][0] - q[k][0], dy = q[(k+1)%3][1] - q[k][1];
      if(dx*dx + dy*dy > L2) { L2 = dx*dx + dy*dy; i = k; }
    }
    const double L = std::sqrt(L2), height = det / L;
    if(height < min_height)
    {
      // push the vertex opposite the longest edge away from it
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const double nx = -(q[j][1] - q[i][1]) / L, ny = (q[j][0] - q[i][0]) / L; // left normal: towards k
      q[k][0] += (min_height - height) * nx;
      q[k][1] += (min_height - height) * ny;
    }
    const double ax = q[1][0]-q[0][0], ay = q[1][1]-q[0][1], bx = q[2][0]-q[0][0], by = q[2][1]-q[0][1];
    const double rest_det = ax * by - bx * ay;
    tri.insert(tri.end(), t, t + 3);
    const double B[4] = { by / rest_det, -ay / rest_det, -bx / rest_det, ax / rest_det };
    rest_inverse.insert(rest_inverse.end(), B, B + 4);
    weight.push_back(0.5 * rest_det);
    total_area += 0.5 * rest_det;
  }
  for(double& w : weight) w *= settings.total_weight / total_area;
  built_density.assign(weight.size(), 0.);
  std::vector<double> x(cm.uv);
  x.insert(x.end(), pos.begin(), pos.end());
  built_density = densities(x.data());
  vertex_offset.assign(n_uv + 1, 0);
  for(int id : tri) if(id < n_uv) ++vertex_offset[id + 1];
  for(int u = 0; u < n_uv; ++u) vertex_offset[u + 1] += vertex_offset[u];
  vertex_triangles.resize(vertex_offset[n_uv]);
  std::vector<int> fill(vertex_offset.begin(), vertex_offset.end() - 1);
  for(std::size_t k = 0; k < tri.size(); ++k) if(tri[k] < n_uv) vertex_triangles[fill[tri[k]]++] = int(k / 3);
  return true;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
