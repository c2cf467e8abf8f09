// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Candidate topology operations (boundary split, interior split, corner
// merge, seam shift), each scored by a local stencil solve, and their
// application as corner relabellings.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_TOPOLOGY_STEP_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_TOPOLOGY_STEP_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Local_stencil.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Overlap.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Scaffold.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Uv_topology.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

enum Operation_type { BOUNDARY_SPLIT, INTERIOR_SPLIT, CORNER_MERGE, SEAM_SHIFT };

struct Operation
{
  Operation_type type = BOUNDARY_SPLIT;
  std::vector<int> corners;    // split: corners that get the new UV vertex; shift: the ear's corners
  int uv_a = -1, uv_b = -1;    // split: the UV vertex split; merge, shift: b is merged into a
  std::vector<int> labels;     // shift: the ear corners' new UV vertices
  std::vector<int> moved;      // shift: UV vertices moved by the local solve ...
  std::vector<double> moved_uv; // ... and where to
  std::vector<int> tips;       // corners at the new seam tips (fracture propagation)
  double d_sd = 0;             // change of E_SD (local solve)
  double d_se = 0;             // change of the normalized (weighted) seam length
  double new_u[4] = { 0, 0, 0, 0 }; // optimized positions: split a, new; merge a
  double weighted(double lambda) const { return (1 - lambda) * d_sd + lambda * d_se; }
};

// Drops the interior splits from `ops` unless the cheapest of them costs
// `ratio` times less seam per unit of E_SD removed than the cheapest boundary
// split. A cut from a chart boundary keeps opening as it grows; a slit inside
// a chart opens much less, which a stencil's score does not see (bunny: a
// chin slit chosen at 1.3 times cheaper left seams 4.22 long, 3.41 without).
inline void drop_costly_slits(std::vector<Operation>& ops, double ratio)
{
  double boundary = std::numeric_limits<double>::infinity(), interior = boundary;
  for(const Operation& op : ops)
  {
    if(!(op.d_sd < 0 && op.d_se > 0)) continue;
    const double price = op.d_se / -op.d_sd;
    if(op.type == BOUNDARY_SPLIT) boundary = (std::min)(boundary, price);
    else if(op.type == INTERIOR_SPLIT) interior = (std::min)(interior, price);
  }
  if(std::isfinite(boundary) && interior * ratio > boundary)
    ops.erase(std::remove_if(ops.begin(), ops.end(), [](const Operation& op) { return op.type == INTERIOR_SPLIT; }),
              ops.end());
}

template <typename Energy>
class Topology_step
{
public:
  Topology_step(const Cut_mesh& cm, const Energy& energy, const std::vector<double>& halfedge_weight)
    : m_cm(cm), m_energy(energy), m_vc(cm), m_weight(halfedge_weight)
  {}

  const Vertex_corners& vertex_corners() const { return m_vc; }

  // Boundary splits are then scored with the scaffold around the vertex.
  void set_scaffold(const Scaffold* scaffold) { m_scaffold = scaffold; }

  double seam_cost(int h) const { return m_cm.edge_length(h) * m_weight[h] / m_cm.normalization_radius(); }

  // Splits of the UV vertex of `corner` (on a chart boundary) along each
  // interior edge of its fan whose far end is not on a chart boundary
  // (so that every chart stays a disk).
  void boundary_splits(int corner, std::vector<Operation>& out)
  {
    if(uv_fan(m_cm, corner, m_fan)) return; // interior vertex
    const std::vector<int> fan = m_fan;
    for(std::size_t i = 0; i + 1 < fan.size(); ++i)
    {
      const int h = Cut_mesh::next(fan[i]); // from the vertex to w
      const int w_corner = h;               // corner of w in fan[i]'s face
      if(is_boundary_uv_corner(m_cm, w_corner)) continue;
      Operation op;
      op.type = BOUNDARY_SPLIT;
      op.uv_a = m_cm.corner_uv[fan[i]];
      op.corners.assign(fan.begin() + i + 1, fan.end());
      op.tips.push_back(w_corner);
      op.d_se = seam_cost(h);
      if(evaluate_split(op, fan)) out.push_back(op);
    }
  }

  // Splits of an interior UV vertex along two of its edges (a slit).
  void interior_splits(int corner, std::vector<Operation>& out)
  {
    if(!uv_fan(m_cm, corner, m_fan)) return;
    const std::vector<int> fan = m_fan;
    const std::size_t n = fan.size();
    for(std::size_t i = 0; i < n; ++i)
    {
      const int hi = Cut_mesh::next(fan[i]);
      if(is_boundary_uv_corner(m_cm, hi)) continue;
      for(std::size_t j = i + 2; j < n && j + 1 < n + i; ++j)
      {
        const int hj = Cut_mesh::next(fan[j]);
        if(is_boundary_uv_corner(m_cm, hj)) continue;
        Operation op;
        op.type = INTERIOR_SPLIT;
        op.uv_a = m_cm.corner_uv[fan[i]];
        op.corners.assign(fan.begin() + i + 1, fan.begin() + j + 1);
        op.tips.push_back(hi);
        op.tips.push_back(hj);
        op.d_se = seam_cost(hi) + seam_cost(hj);
        if(evaluate_split(op, fan)) out.push_back(op);
      }
    }
  }

  // Zipping the seam at a tip: h is a seam halfedge whose target is the tip
  // (both sides share its UV vertex) and whose source sides differ.
  bool merge_at(int h, Operation& op)
  {
    const int o = m_cm.opposite[h];
    if(o < 0 || !m_cm.is_seam(h)) return false;
    if(m_cm.corner_uv[h] != m_cm.corner_uv[Cut_mesh::prev(o)]) return false;
    const int a = m_cm.corner_uv[Cut_mesh::prev(h)], b = m_cm.corner_uv[o];
    if(a == b) return false;
    op = Operation();
    op.type = CORNER_MERGE;
    op.uv_a = a; op.uv_b = b;
    op.d_se = -seam_cost(h);
    op.tips.push_back(Cut_mesh::prev(h));
    return evaluate_merge(op);
  }

  void merges(std::vector<Operation>& out)
  {
    Operation op;
    for(std::size_t h = 0; h < m_cm.corner_vertex.size(); ++h)
      if(merge_at(int(h), op)) out.push_back(op);
  }

  // Moving an ear of a seam across it: where a face has two seam edges at
  // corner c (its UV vertex there has no other face) and the other side of
  // the seam is one UV vertex, the face joins the other side and the seam
  // runs along its third edge instead (shorter, by the triangle inequality).
  bool shift_at(int c, Operation& op)
  {
    const int h1 = c, h2 = Cut_mesh::next(c), h0 = Cut_mesh::prev(c); // v0->v1, v1->v2, v2->v0
    if(!m_cm.is_seam(h1) || !m_cm.is_seam(h2) || m_cm.opposite[h0] < 0 || m_cm.is_seam(h0)) return false;
    const int o1 = m_cm.opposite[h1], o2 = m_cm.opposite[h2];
    const int b1 = m_cm.corner_uv[o2];
    if(m_cm.corner_uv[Cut_mesh::prev(o1)] != b1) return false;
    const int l0 = m_cm.corner_uv[o1], l2 = m_cm.corner_uv[Cut_mesh::prev(o2)];
    const bool tip0 = l0 == m_cm.corner_uv[h0], tip2 = l2 == m_cm.corner_uv[h2];
    if(tip0 && tip2) return false; // a two-edge slit: a merge's business
    op = Operation();
    op.type = SEAM_SHIFT;
    op.uv_a = b1; op.uv_b = m_cm.corner_uv[c];
    op.corners = { h0, c, h2 };  // corners at v0, v1, v2
    op.labels = { l0, b1, l2 };
    op.d_se = seam_cost(h0) - seam_cost(h1) - seam_cost(h2);
    if(!(op.d_se < 0)) return false;
    return evaluate_shift(op);
  }

  void shifts(std::vector<Operation>& out)
  {
    Operation op;
    for(std::size_t c = 0; c < m_cm.corner_vertex.size(); ++c)
      if(shift_at(int(c), op)) out.push_back(op);
  }

  // Applies `op` to `cm` (which must be the mesh this step reads).
  static void apply(Cut_mesh& cm, const Vertex_corners& vc, const Operation& op)
  {
    if(op.type == SEAM_SHIFT)
    {
      for(std::size_t k = 0; k < op.moved.size(); ++k)
      {
        cm.uv[2*op.moved[k]] = op.moved_uv[2*k];
        cm.uv[2*op.moved[k] + 1] = op.moved_uv[2*k + 1];
      }
      for(int k = 0; k < 3; ++k) cm.corner_uv[op.corners[k]] = op.labels[k];
      merge_uv_vertices(cm, vc, op.uv_a, op.uv_b); // b has no corner left: removes it
      return;
    }
    if(op.type == CORNER_MERGE)
    {
      cm.uv[2*op.uv_a] = op.new_u[0];
      cm.uv[2*op.uv_a + 1] = op.new_u[1];
      merge_uv_vertices(cm, vc, op.uv_a, op.uv_b);
      return;
    }
    const int u = split_uv_vertex(cm, op.corners);
    cm.uv[2*op.uv_a] = op.new_u[0];
    cm.uv[2*op.uv_a + 1] = op.new_u[1];
    cm.uv[2*u] = op.new_u[2];
    cm.uv[2*u + 1] = op.new_u[3];
  }

private:
  int local_id(int uv)
  {
    for(std::size_t k = 0; k < m_ids.size(); ++k) if(m_ids[k] == uv) return int(k);
    m_ids.push_back(uv);
    m_stencil.add_vertex(m_cm.uv[2*uv], m_cm.uv[2*uv + 1]);
    return int(m_ids.size()) - 1;
  }

  // Stencil = faces of the fan; free: the old vertex (0) and its copy (1).
  bool evaluate_split(Operation& op, const std::vector<int>& fan)
  {
    m_stencil.clear(); m_ids.clear();
    m_ids.push_back(op.uv_a); m_ids.push_back(-2);
    m_stencil.add_vertex(m_cm.uv[2*op.uv_a], m_cm.uv[2*op.uv_a + 1]);
    m_stencil.add_vertex(m_cm.uv[2*op.uv_a], m_cm.uv[2*op.uv_a + 1]);
    m_stencil.n_free = 2;
    for(int c : fan)
    {
      const bool moved = std::find(op.corners.begin(), op.corners.end(), c) != op.corners.end();
      const int f = c / 3;
      m_stencil.faces.push_back(f);
      for(int k = 0; k < 3; ++k)
      {
        const int ck = 3*f + k;
        m_stencil.local.push_back(ck == c ? (moved ? 1 : 0) : local_id(m_cm.corner_uv[ck]));
      }
    }
    if(op.type == BOUNDARY_SPLIT && m_scaffold && !m_scaffold->empty()) add_scaffold_ring(op);
    const double before = stencil_energy(m_cm, m_energy, m_stencil, m_stencil.pos.data());
    const std::vector<double> start(m_stencil.pos);
    double after = optimize_stencil(m_cm, m_energy, m_stencil, 12);
    if(!(after < std::numeric_limits<double>::infinity())) return false;
    if(m_scaffold && !m_scaffold->empty() && !opened_without_overlap(start, after)) return false;
    op.d_sd = after - before;
    std::copy(m_stencil.pos.begin(), m_stencil.pos.begin() + 4, op.new_u);
    return true;
  }

  // The two sides of the new seam may not cross each other: back off towards
  // the start while the stencil's faces overlap (nothing else can be
  // crossed: the faces and the scaffold ring do not flip).
  bool opened_without_overlap(const std::vector<double>& start, double& after)
  {
    const std::vector<double> end(m_stencil.pos);
    for(double t = 1.; t > 1e-3; t *= 0.5)
    {
      for(std::size_t i = 0; i < 4; ++i) m_stencil.pos[i] = start[i] + t * (end[i] - start[i]);
      if(count_overlapping_pairs(m_stencil.local, m_stencil.pos.data(), 1) == 0)
      {
        if(t < 1.) after = stencil_energy(m_cm, m_energy, m_stencil, m_stencil.pos.data());
        return true;
      }
    }
    return false;
  }

  int local_scaffold_id(int id)
  {
    if(id < m_scaffold->n_uv) return local_id(id);
    const int key = -3 - (id - m_scaffold->n_uv); // apart from UV ids and the new vertex (-2)
    for(std::size_t k = 0; k < m_ids.size(); ++k) if(m_ids[k] == key) return int(k);
    m_ids.push_back(key);
    const double* p = m_scaffold->position(m_cm, id);
    m_stencil.add_vertex(p[0], p[1]);
    return int(m_ids.size()) - 1;
  }

  // The scaffold triangles around the split vertex (the empty wedge between
  // its two boundary edges) bound both copies: each gets its own copy of
  // them, at half weight, so that neither can cross into another chart.
  void add_scaffold_ring(const Operation& op)
  {
    const Scaffold& sc = *m_scaffold;
    const int a = op.uv_a;
    if(a >= sc.n_uv) return;
    for(int copy = 0; copy < 2; ++copy)
      for(int k = sc.vertex_offset[a]; k < sc.vertex_offset[a + 1]; ++k)
      {
        const int t = sc.vertex_triangles[k];
        for(int j = 0; j < 3; ++j)
        {
          const int id = sc.tri[3*t + j];
          m_stencil.extra_local.push_back(id == a ? copy : local_scaffold_id(id));
        }
        m_stencil.extra_rest_inverse.insert(m_stencil.extra_rest_inverse.end(),
                                            &sc.rest_inverse[4*t], &sc.rest_inverse[4*t] + 4);
        m_stencil.extra_weight.push_back(0.5 * sc.weight[t]);
      }
  }

  // Stencil = faces of both fans; free: the merged vertex, started at the
  // midpoint (or nearer either copy) where that flips nothing.
  bool evaluate_merge(Operation& op)
  {
    const int v = m_cm.uv_vertex[op.uv_a];
    m_stencil.clear(); m_ids.clear();
    m_ids.push_back(op.uv_a);
    m_stencil.add_vertex(0, 0);
    m_stencil.n_free = 1;
    for(int k = m_vc.offset[v]; k < m_vc.offset[v + 1]; ++k)
    {
      const int c = m_vc.corners[k];
      const int uvc = m_cm.corner_uv[c];
      if(uvc != op.uv_a && uvc != op.uv_b) continue;
      const int f = c / 3;
      m_stencil.faces.push_back(f);
      for(int j = 0; j < 3; ++j)
      {
        const int cj = 3*f + j;
        const int uj = m_cm.corner_uv[cj];
        m_stencil.local.push_back(cj == c ? 0 : local_id(uj));
      }
    }
    const double* pa = &m_cm.uv[2*op.uv_a];
    const double* pb = &m_cm.uv[2*op.uv_b];
    double before = 0;
    {
      // energy of the same faces with the two copies where they are
      Local_stencil s = m_stencil;
      s.pos.push_back(pb[0]); s.pos.push_back(pb[1]);
      const int lb = int(s.pos.size() / 2) - 1;
      s.pos[0] = pa[0]; s.pos[1] = pa[1];
      for(std::size_t i = 0; i < s.faces.size(); ++i)
        for(int j = 0; j < 3; ++j)
          if(s.local[3*i + j] == 0 && m_cm.corner_uv[3*s.faces[i] + j] == op.uv_b) s.local[3*i + j] = lb;
      before = stencil_energy(m_cm, m_energy, s, s.pos.data());
    }
    static const double ts[] = { 0.5, 0.25, 0.75, 0., 1. };
    double start = std::numeric_limits<double>::infinity();
    for(double t : ts)
    {
      m_stencil.pos[0] = (1 - t) * pa[0] + t * pb[0];
      m_stencil.pos[1] = (1 - t) * pa[1] + t * pb[1];
      start = stencil_energy(m_cm, m_energy, m_stencil, m_stencil.pos.data());
      if(start < std::numeric_limits<double>::infinity()) break;
    }
    if(!(start < std::numeric_limits<double>::infinity())) return false;
    const double after = optimize_stencil(m_cm, m_energy, m_stencil, 12);
    op.d_sd = after - before;
    op.new_u[0] = m_stencil.pos[0]; op.new_u[1] = m_stencil.pos[1];
    return true;
  }

  // Stencil = every face at the UV vertices the shift touches; free: those
  // vertices (the ear's, on both sides). The ear's apex starts where its
  // whole ring is unflipped.
  bool evaluate_shift(Operation& op)
  {
    const int* ear = op.corners.data();
    int touched[6] = { m_cm.corner_uv[ear[0]], m_cm.corner_uv[ear[1]], m_cm.corner_uv[ear[2]],
                       op.labels[0], op.labels[1], op.labels[2] };
    // faces, from the corners of the three 3D vertices
    m_faces.clear();
    for(int k = 0; k < 3; ++k)
    {
      const int v = m_cm.corner_vertex[ear[k]];
      for(int i = m_vc.offset[v]; i < m_vc.offset[v + 1]; ++i)
      {
        const int cc = m_vc.corners[i];
        if(std::find(touched, touched + 6, m_cm.corner_uv[cc]) == touched + 6) continue;
        if(std::find(m_faces.begin(), m_faces.end(), cc / 3) == m_faces.end()) m_faces.push_back(cc / 3);
      }
    }
    auto label = [&](int cc) {
      for(int k = 0; k < 3; ++k) if(cc == ear[k]) return op.labels[k];
      return m_cm.corner_uv[cc];
    };
    auto build = [&](bool after) {
      m_stencil.clear(); m_ids.clear();
      if(after) // the ear's new corners first (the apex is local 1), then its old sides
        for(int u : { op.labels[0], op.labels[1], op.labels[2], m_cm.corner_uv[ear[0]], m_cm.corner_uv[ear[2]] })
          local_id(u);
      m_stencil.n_free = int(m_ids.size());
      for(int f : m_faces)
      {
        m_stencil.faces.push_back(f);
        for(int j = 0; j < 3; ++j) m_stencil.local.push_back(local_id(after ? label(3*f + j) : m_cm.corner_uv[3*f + j]));
      }
    };
    build(false);
    const double before = stencil_energy(m_cm, m_energy, m_stencil, m_stencil.pos.data());
    build(true);
    // the apex (local 1) starts at its far-side copy, else nearer its new ring's centre
    const int apex = 1;
    double cx = 0, cy = 0; int n = 0;
    for(std::size_t i = 0; i < m_stencil.faces.size(); ++i)
      for(int j = 0; j < 3; ++j)
        if(m_stencil.local[3*i + j] == apex)
          for(int q = 1; q < 3; ++q)
          {
            const int l = m_stencil.local[3*i + (j + q) % 3];
            cx += m_stencil.pos[2*l]; cy += m_stencil.pos[2*l + 1]; ++n;
          }
    cx /= n; cy /= n;
    const double px = m_stencil.pos[2*apex], py = m_stencil.pos[2*apex + 1];
    double start = std::numeric_limits<double>::infinity();
    for(double t : { 0., 0.5, 1. })
    {
      m_stencil.pos[2*apex] = (1 - t) * px + t * cx;
      m_stencil.pos[2*apex + 1] = (1 - t) * py + t * cy;
      start = stencil_energy(m_cm, m_energy, m_stencil, m_stencil.pos.data());
      if(start < std::numeric_limits<double>::infinity()) break;
    }
    if(!(start < std::numeric_limits<double>::infinity())) return false;
    const double after = optimize_stencil(m_cm, m_energy, m_stencil, 12);
    op.d_sd = after - before;
    op.moved.assign(m_ids.begin(), m_ids.begin() + m_stencil.n_free);
    op.moved_uv.assign(m_stencil.pos.begin(), m_stencil.pos.begin() + 2 * m_stencil.n_free);
    return true;
  }

  const Cut_mesh& m_cm;
  const Energy& m_energy;
  Vertex_corners m_vc;
  const std::vector<double>& m_weight;
  const Scaffold* m_scaffold = nullptr;
  Local_stencil m_stencil;
  std::vector<int> m_ids, m_fan, m_faces;
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
