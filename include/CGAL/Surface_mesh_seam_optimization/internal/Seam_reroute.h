// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Rerouting a seam part that has no tip (between two vertices of a path
// from junction to junction, or from a vertex of a path to its end on the
// input boundary): cutting its shortcut and zipping the part cannot be done
// by local operations, since the zip would start nowhere. The region
// between the part and its shortcut changes sides instead.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SEAM_REROUTE_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_SEAM_REROUTE_H

#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Local_stencil.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Seam_paths.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Uv_topology.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Replaces a seam part without tips (d.seam, inner vertices on no other
// seam; see seam_reroutes()) by its shortcut (same ends): the region
// between the two comes off along the shortcut and is glued along the part,
// moved rigidly across it; since the two sides of an open seam differ in
// shape, its side of the part then goes over to the other side in steps,
// the region relaxing without flips after each. False, nothing changed, if
// that region is not bounded by the two paths alone (and, for a part and a
// shortcut that end on the input boundary, the boundary between their ends)
// or cannot be laid out without flips. Overlaps are the caller's: if
// true, `before` holds the configuration to restore.
inline bool reroute_seam(Cut_mesh& cm, const Vertex_corners& vc, const Seam_detour& d, Uv_snapshot& before)
{
  const int nf = int(cm.number_of_faces());
  const std::size_t nh = cm.corner_vertex.size();
  auto source = [&](int h) { return cm.corner_vertex[Cut_mesh::prev(h)]; };
  std::vector<char> on_part(nh, 0), on_cut(nh, 0);
  for(int h : d.seam) on_part[h] = on_part[cm.opposite[h]] = 1;
  for(int h : d.shortcut) on_cut[h] = on_cut[cm.opposite[h]] = 1;

  // the region: faces on one side of the shortcut, reached without crossing
  // a seam or the shortcut; its seams other than the part are inside it
  std::vector<char> in_r(nf, 0);
  bool found = false;
  for(int side : { d.shortcut.front(), cm.opposite[d.shortcut.front()] })
  {
    std::fill(in_r.begin(), in_r.end(), 0);
    std::vector<int> stack(1, side / 3);
    in_r[side / 3] = 1;
    int count = 1;
    bool valid = true;
    while(!stack.empty() && valid)
    {
      const int f = stack.back(); stack.pop_back();
      for(int k = 0; k < 3 && valid; ++k)
      {
        const int h = 3*f + k, o = cm.opposite[h];
        if(o < 0) valid = d.to_border; // (between the two ends on the boundary)
        else if(!on_cut[h] && !cm.is_seam(h) && !in_r[o / 3]) { in_r[o / 3] = 1; ++count; stack.push_back(o / 3); }
      }
    }
    if(!valid || 2 * count >= nf) continue;
    for(int f = 0; f < nf && valid; ++f)
      for(int k = 0; k < 3 && valid && in_r[f]; ++k)
      {
        const int h = 3*f + k, o = cm.opposite[h];
        if(o < 0) continue;
        if(on_cut[h] || on_part[h]) valid = !in_r[o / 3];
        else if(cm.is_seam(h)) valid = in_r[o / 3] != 0;
      }
    for(int h : d.seam) valid = valid && (in_r[h / 3] != in_r[cm.opposite[h] / 3]);
    if(valid) { found = true; break; }
  }
  if(!found) return false;

  // per vertex of the part: a corner in the region, one outside
  std::vector<int> part_vertices, inside, outside;
  for(std::size_t i = 0; i < d.seam.size(); ++i)
  {
    const int h = d.seam[i], o = cm.opposite[h];
    const int r = in_r[h / 3] ? h : o, w = in_r[h / 3] ? o : h;
    // corner of face(r) at the source of d.seam[i], and at its target
    const int r_src = r == h ? Cut_mesh::prev(r) : r, r_dst = r == h ? r : Cut_mesh::prev(r);
    const int w_src = w == h ? Cut_mesh::prev(w) : w, w_dst = w == h ? w : Cut_mesh::prev(w);
    if(i == 0) { part_vertices.push_back(source(h)); inside.push_back(r_src); outside.push_back(w_src); }
    part_vertices.push_back(cm.corner_vertex[h]); inside.push_back(r_dst); outside.push_back(w_dst);
  }

  // (a border slide's end on the boundary closes; the other ends stay on the seam)
  auto stays = [&](std::size_t i) { return i == 0 || (i + 1 == part_vertices.size() && !d.to_border); };
  // An end that stays on the seam keeps corners of the region's copy outside
  // the region (else the region went around the seam's other side, past a
  // tip, say, and its end would leave the seam: not this move)
  for(std::size_t i : { std::size_t(0), part_vertices.size() - 1 })
  {
    if(!stays(i)) continue;
    const int v = part_vertices[i], u = cm.corner_uv[inside[i]];
    bool kept = false;
    for(int k = vc.offset[v]; k < vc.offset[v + 1] && !kept; ++k)
      kept = cm.corner_uv[vc.corners[k]] == u && !in_r[vc.corners[k] / 3];
    if(!kept) return false;
  }

  // rigid motion of the region's side of the part onto the other side (2D Procrustes)
  double cx[2] = { 0, 0 }, cy[2] = { 0, 0 };
  const double n = double(part_vertices.size());
  for(std::size_t i = 0; i < part_vertices.size(); ++i)
    for(int k = 0; k < 2; ++k)
    {
      cx[k] += cm.uv[2 * cm.corner_uv[inside[i]] + k] / n;
      cy[k] += cm.uv[2 * cm.corner_uv[outside[i]] + k] / n;
    }
  double dot = 0, cross = 0;
  for(std::size_t i = 0; i < part_vertices.size(); ++i)
  {
    const double* x = &cm.uv[2 * cm.corner_uv[inside[i]]];
    const double* y = &cm.uv[2 * cm.corner_uv[outside[i]]];
    const double ax = x[0] - cx[0], ay = x[1] - cx[1], bx = y[0] - cy[0], by = y[1] - cy[1];
    dot += ax * bx + ay * by;
    cross += ax * by - ay * bx;
  }
  const double norm = std::sqrt(dot * dot + cross * cross);
  if(!(norm > 0)) return false;
  const double c = dot / norm, s = cross / norm;
  auto move = [&](double* p) {
    const double x = p[0] - cx[0], y = p[1] - cx[1];
    p[0] = cy[0] + c * x - s * y;
    p[1] = cy[1] + s * x + c * y;
  };

  std::vector<double> from, to;
  for(std::size_t i = 0; i < part_vertices.size(); ++i)
  {
    double x[2] = { cm.uv[2 * cm.corner_uv[inside[i]]], cm.uv[2 * cm.corner_uv[inside[i]] + 1] };
    move(x);
    from.push_back(x[0]); from.push_back(x[1]);
    to.push_back(cm.uv[2 * cm.corner_uv[outside[i]]]); to.push_back(cm.uv[2 * cm.corner_uv[outside[i]] + 1]);
  }
  before.save(cm);
  std::vector<char> on_loop(cm.number_of_vertices(), 0);
  for(int v : part_vertices) on_loop[v] = 1;
  for(int h : d.shortcut) on_loop[cm.corner_vertex[h]] = 1;
  // the region's own UV vertices move
  {
    std::vector<char> moved(cm.number_of_uv_vertices(), 0);
    for(int f = 0; f < nf; ++f)
      for(int k = 0; k < 3 && in_r[f]; ++k)
      {
        const int u = cm.corner_uv[3*f + k];
        if(!on_loop[cm.uv_vertex[u]] && !moved[u]) { moved[u] = 1; move(&cm.uv[2*u]); }
      }
  }
  // the region comes off along the shortcut (up to its boundary end, if it has one)
  for(std::size_t i = 0; i + (d.to_border ? 0 : 1) < d.shortcut.size(); ++i)
  {
    const int v = cm.corner_vertex[d.shortcut[i]];
    std::vector<int> corners;
    for(int k = vc.offset[v]; k < vc.offset[v + 1]; ++k)
      if(in_r[vc.corners[k] / 3]) corners.push_back(vc.corners[k]);
    const int u = split_uv_vertex(cm, corners);
    move(&cm.uv[2*u]);
  }
  // and is glued along the part (ids are read from corners: merges renumber)
  for(std::size_t i = 0; i < part_vertices.size(); ++i)
  {
    const int v = part_vertices[i];
    const int keep = cm.corner_uv[outside[i]], drop = cm.corner_uv[inside[i]];
    if(stays(i))
    {
      // the ends stay on the seam: only the region's corners change sides
      for(int k = vc.offset[v]; k < vc.offset[v + 1]; ++k)
        if(in_r[vc.corners[k] / 3] && cm.corner_uv[vc.corners[k]] == drop) cm.corner_uv[vc.corners[k]] = keep;
    }
    else
      merge_uv_vertices(cm, vc, keep, drop);
  }
  // The two sides of a seam that opened wide differ in shape: the region's
  // side of the part goes over to the other side step by step, the region
  // relaxing (flip-free) after each.
  {
    Local_stencil st;
    std::vector<int> local(cm.number_of_uv_vertices(), -1);
    std::vector<char> fixed(cm.number_of_uv_vertices(), 0);
    for(std::size_t i = 0; i < part_vertices.size(); ++i) fixed[cm.corner_uv[outside[i]]] = 1;
    for(int f = 0; f < nf; ++f)
      for(int k = 0; k < 3 && in_r[f]; ++k)
      {
        const int u = cm.corner_uv[3*f + k];
        if(!fixed[u] && local[u] < 0) local[u] = st.add_vertex(cm.uv[2*u], cm.uv[2*u + 1]);
      }
    st.n_free = int(st.pos.size() / 2);
    std::vector<int> fixed_local;
    for(std::size_t i = 0; i < part_vertices.size(); ++i)
    {
      const int u = cm.corner_uv[outside[i]];
      if(local[u] < 0) local[u] = st.add_vertex(from[2*i], from[2*i + 1]);
      fixed_local.push_back(local[u]);
    }
    for(int f = 0; f < nf; ++f)
    {
      if(!in_r[f]) continue;
      st.faces.push_back(f);
      for(int k = 0; k < 3; ++k) st.local.push_back(local[cm.corner_uv[3*f + k]]);
    }
    auto place = [&](double t) {
      for(std::size_t i = 0; i < fixed_local.size(); ++i)
        for(int k = 0; k < 2; ++k)
          st.pos[2 * fixed_local[i] + k] = (1 - t) * from[2*i + k] + t * to[2*i + k];
    };
    auto valid = [&] {
      for(std::size_t q = 0; q < st.faces.size(); ++q)
        if(!(signed_area2(&st.pos[2 * st.local[3*q]], &st.pos[2 * st.local[3*q + 1]], &st.pos[2 * st.local[3*q + 2]]) > 0))
          return false;
      return true;
    };
    const Symmetric_Dirichlet_energy sd;
    double t = 0, step = 0.125;
    bool ok = valid();
    while(ok && t < 1)
    {
      const double next = (std::min)(1., t + step);
      place(next);
      if(!valid())
      {
        place(t);
        step *= 0.5;
        ok = step > 1. / 4096;
        continue;
      }
      t = next;
      optimize_stencil(cm, sd, st, 6);
      step = (std::min)(0.25, 2 * step);
    }
    if(!ok) { before.restore(cm); return false; }
    optimize_stencil(cm, sd, st, 20);
    for(std::size_t u = 0; u < local.size(); ++u)
      if(local[u] >= 0 && local[u] < st.n_free) { cm.uv[2*u] = st.pos[2 * local[u]]; cm.uv[2*u + 1] = st.pos[2 * local[u] + 1]; }
  }
  for(int f = 0; f < nf; ++f)
    if(!(cm.signed_uv_area2(std::size_t(f)) > 0)) { before.restore(cm); return false; }
  return true;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
