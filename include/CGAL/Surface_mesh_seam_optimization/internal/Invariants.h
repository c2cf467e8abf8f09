// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The invariants of a Cut_mesh, checked after every topology edit in debug
// builds and by the tests.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_INVARIANTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_INVARIANTS_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Uv_topology.h>

#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Empty string if all hold, else the first violation:
// - every corner has a UV vertex of its own 3D vertex, every UV vertex is used;
// - the corners of a UV vertex form one fan (the UV mesh is manifold);
// - no UV triangle has non-positive signed area;
// - every chart is a disk, or (after interior splits) a disk with holes.
inline std::string check_invariants(const Cut_mesh& cm)
{
  const std::size_t nuv = cm.number_of_uv_vertices();
  if(cm.uv.size() != 2 * nuv) return "uv array size";
  std::vector<int> count(nuv, 0);
  for(std::size_t c = 0; c < cm.corner_uv.size(); ++c)
  {
    const int u = cm.corner_uv[c];
    if(u < 0 || std::size_t(u) >= nuv) return "corner " + std::to_string(c) + " has no UV vertex";
    if(cm.uv_vertex[u] != cm.corner_vertex[c]) return "UV vertex " + std::to_string(u) + " on two 3D vertices";
    ++count[u];
  }
  std::vector<int> fan;
  std::vector<char> done(nuv, 0);
  for(std::size_t c = 0; c < cm.corner_uv.size(); ++c)
  {
    const int u = cm.corner_uv[c];
    if(count[u] == 0) return "unused UV vertex";
    if(done[u]) continue;
    done[u] = 1;
    uv_fan(cm, int(c), fan);
    if(int(fan.size()) != count[u]) return "UV vertex " + std::to_string(u) + " is not manifold";
  }
  for(std::size_t u = 0; u < nuv; ++u)
    if(count[u] == 0) return "unused UV vertex " + std::to_string(u);
  for(std::size_t f = 0; f < cm.number_of_faces(); ++f)
    if(!(cm.signed_uv_area2(f) > 0)) return "face " + std::to_string(f) + " is flipped";

  std::vector<int> chart;
  const std::size_t nc = cm.compute_charts(chart);
  const std::vector<long> chi = chart_euler_characteristics(
    chart, nc, cm.corner_uv, nuv, cm.opposite, [&](int h) { return cm.opposite[h] < 0 || cm.is_seam(h); });
  std::vector<char> open(nc, 0);
  for(std::size_t h = 0; h < cm.corner_vertex.size(); ++h)
    if(cm.opposite[h] < 0 || cm.is_seam(int(h))) open[chart[h / 3]] = 1;
  for(std::size_t k = 0; k < nc; ++k)
    if(!open[k] || chi[k] > 1) return "chart " + std::to_string(k) + " is closed";
  return std::string();
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
