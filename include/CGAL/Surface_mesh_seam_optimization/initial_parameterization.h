// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The initial UV map OptCuts starts from: every chart (faces connected across
// non-seam edges) mapped to a disk by Tutte's embedding with a circular
// border, through Surface_mesh_parameterization on a CGAL::Seam_mesh.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INITIAL_PARAMETERIZATION_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INITIAL_PARAMETERIZATION_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/seam_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Chart_layout.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_to_disk.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Degenerate_triangle.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Fixed_border_solver_traits.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Shortest_paths.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Union_find.h>

#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Kernel_traits.h>

#include <boost/property_map/function_property_map.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// CGAL's circular arc-length border, measured with the user's vertex point map
// (the stock one reads the mesh's internal point map).
template <class SeamMesh, class VertexPointMap>
class Circular_border_arc_length_with_point_map
  : public CGAL::Surface_mesh_parameterization::Circular_border_parameterizer_3<SeamMesh>
{
  typedef CGAL::Surface_mesh_parameterization::Circular_border_parameterizer_3<SeamMesh> Base;
  typedef typename Base::NT                                                  NT;
  typedef typename boost::graph_traits<SeamMesh>::vertex_descriptor           vertex_descriptor;
  typedef typename SeamMesh::TM_halfedge_descriptor                           TM_halfedge_descriptor;

  VertexPointMap m_vpm;

public:
  explicit Circular_border_arc_length_with_point_map(VertexPointMap vpm = VertexPointMap())
    : m_vpm(vpm) { }

protected:
  virtual NT compute_edge_length(const SeamMesh& mesh,
                                 vertex_descriptor s,
                                 vertex_descriptor t) const
  {
    const TM_halfedge_descriptor hs = s, ht = t;
    const auto& ps = get(m_vpm, target(hs, mesh.mesh()));
    const auto& pt = get(m_vpm, target(ht, mesh.mesh()));
    const double dx = CGAL::to_double(pt.x()) - CGAL::to_double(ps.x());
    const double dy = CGAL::to_double(pt.y()) - CGAL::to_double(ps.y());
    const double dz = CGAL::to_double(pt.z()) - CGAL::to_double(ps.z());
    return NT(std::sqrt(dx * dx + dy * dy + dz * dz));
  }
};

// Floater's mean value coordinates (positive weights: with a convex border the
// map is an embedding, like Tutte's, but it follows the 3D geometry), measured
// with the user's vertex point map (the stock one reads the mesh's own).
template <class SeamMesh, class VertexPointMap, class BorderParameterizer>
class Mean_value_coordinates_with_point_map
  : public CGAL::Surface_mesh_parameterization::Mean_value_coordinates_parameterizer_3<SeamMesh, BorderParameterizer>
{
  typedef CGAL::Surface_mesh_parameterization::Mean_value_coordinates_parameterizer_3<SeamMesh, BorderParameterizer> Base;
  typedef typename CGAL::Surface_mesh_parameterization::internal::Kernel_traits<SeamMesh>::Kernel::FT NT;
  typedef typename boost::graph_traits<SeamMesh>::vertex_descriptor           vertex_descriptor;
  typedef typename SeamMesh::TM_halfedge_descriptor                           TM_halfedge_descriptor;
  typedef std::array<double, 3>                                               XYZ;

  VertexPointMap m_vpm;

  XYZ point(const SeamMesh& mesh, vertex_descriptor v) const
  {
    const TM_halfedge_descriptor h = v;
    const auto& p = get(m_vpm, target(h, mesh.mesh()));
    return {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }};
  }

  // tan(a / 2) for the angle a between u and w: |u x w| / (|u| |w| + u . w)
  static double tan_half_angle(const XYZ& u, const XYZ& w)
  {
    const XYZ n = {{ u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] }};
    const double cross = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    const double lw = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    return cross / (lu * lw + u[0] * w[0] + u[1] * w[1] + u[2] * w[2]);
  }

public:
  Mean_value_coordinates_with_point_map(VertexPointMap vpm, BorderParameterizer border)
    : Base(border), m_vpm(vpm) { }

protected:
  virtual NT compute_w_ij(const SeamMesh& mesh,
                          vertex_descriptor v_i,
                          CGAL::Vertex_around_target_circulator<SeamMesh> v_j) const override
  {
    CGAL::Vertex_around_target_circulator<SeamMesh> v_k = v_j, v_l = v_j;
    --v_k;
    ++v_l;
    const XYZ pi = point(mesh, v_i), pj = point(mesh, *v_j), pk = point(mesh, *v_k), pl = point(mesh, *v_l);
    const XYZ eij = {{ pj[0] - pi[0], pj[1] - pi[1], pj[2] - pi[2] }};
    const XYZ eik = {{ pk[0] - pi[0], pk[1] - pi[1], pk[2] - pi[2] }};
    const XYZ eil = {{ pl[0] - pi[0], pl[1] - pi[1], pl[2] - pi[2] }};
    const double r = std::sqrt(eij[0] * eij[0] + eij[1] * eij[1] + eij[2] * eij[2]);
    return NT((tan_half_angle(eij, eik) + tan_half_angle(eij, eil)) / r);
  }
};

inline double signed_area_2(const std::array<double, 2>& a,
                            const std::array<double, 2>& b,
                            const std::array<double, 2>& c)
{
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

// The initial map of `cm`, the flat copy of `tm` made by copy_face_graph()
// (which validated it): `seam` (per core halfedge, both sides) gains the
// slits and the cuts through handles, `corner_uvs` receives the UV of every
// corner (2 values each). A message says which chart failed and why on
// ERROR_INITIAL_PARAMETERIZATION and ERROR_NOT_A_DISK; on any error `seam`
// and `corner_uvs` are unchanged.
template <class TriangleMesh, class VertexPointMap>
Error_code initial_uv_map(const TriangleMesh& tm,
                          VertexPointMap vpm,
                          const Cut_mesh& cm,
                          const Face_graph_copy<TriangleMesh>& copy,
                          std::vector<char>& seam,
                          std::vector<double>& corner_uvs,
                          std::string& message)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;

  typedef boost::graph_traits<TriangleMesh>                           GT;
  typedef typename GT::halfedge_descriptor                            halfedge_descriptor;
  typedef typename GT::edge_descriptor                                edge_descriptor;
  typedef VertexPointMap                                              VPM;
  typedef std::array<double, 2>                                       UV;
  typedef std::array<double, 3>                                       XYZ;

  // corner c = 3 * face + k is halfedge H[c], the UV of target(H[c]) in that face
  const std::vector<halfedge_descriptor>& H = copy.corner_halfedge;
  const std::vector<int>& cv = cm.corner_vertex;
  const std::vector<int>& copp = cm.opposite;
  const int nc = static_cast<int>(cv.size());
  const int nf = nc / 3;
  const std::size_t nv = cm.number_of_vertices();
  struct Points
  {
    const double* p;
    XYZ operator[](int v) const { return {{ p[3 * v], p[3 * v + 1], p[3 * v + 2] }}; }
  } const P{ cm.points.data() };

  const auto himap = get_initialized_halfedge_index_map(tm);
  std::size_t nh = 0;
  for(halfedge_descriptor h : halfedges(tm)) nh = (std::max)(nh, std::size_t(get(himap, h)) + 1);
  std::vector<int> corner_of(nh, -1);
  for(int c = 0; c < nc; ++c)
    corner_of[get(himap, H[c])] = c;
  std::vector<char> base_cut(nc, 0); // the edge of H[c] separates charts (or is a border)
  for(int c = 0; c < nc; ++c)
    base_cut[c] = (copp[c] < 0 || seam[c]) ? 1 : 0;
  auto next_c = [](int c) { return c - c % 3 + (c + 1) % 3; };
  auto prev_c = [](int c) { return c - c % 3 + (c + 2) % 3; };

  std::vector<double> area3(nf);
  for(int f = 0; f < nf; ++f)
    area3[f] = 0.5 * internal::twice_triangle_area(&cm.points[3 * cv[3 * f]], &cm.points[3 * cv[3 * f + 1]],
                                                   &cm.points[3 * cv[3 * f + 2]]);

  auto side_length = [&](int c) -> double
  {
    const XYZ& p = P[cv[c]];
    const XYZ& q = P[cv[prev_c(c)]];
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                     (p[2] - q[2]) * (p[2] - q[2]));
  };

  // Everything from the seams on, with `extra` seams beside the user's. On
  // ERROR_INITIAL_PARAMETERIZATION, `failed` receives the faces of the chart
  // that could not be mapped.
  auto solve = [&](const std::vector<char>& extra, std::vector<int>& failed) -> Error_code
  {
    std::vector<char> cut(base_cut);
    for(int c = 0; c < nc; ++c) cut[c] = cut[c] || extra[c];
    // ---- charts (faces across non-cut edges) and UV vertices (corners across non-cut edges)
    internal::Union_find chart_uf(nf), uv_uf(nc);
    for(int c = 0; c < nc; ++c)
    {
      if(!cut[c]) chart_uf.unite(c / 3, copp[c] / 3);
      const int n = next_c(c);
      if(!cut[n]) uv_uf.unite(c, copp[n]);
    }
    std::vector<int> chart_of_face(nf), chart_face(nf, -1);
    int n_charts = 0;
    for(int f = 0; f < nf; ++f)
    {
      const int r = chart_uf.find(f);
      if(chart_face[r] < 0) chart_face[r] = n_charts++;
      chart_of_face[f] = chart_face[r];
    }
    std::vector<int> first_face(n_charts, -1);
    for(int f = nf - 1; f >= 0; --f) first_face[chart_of_face[f]] = f;

    // Euler characteristic V - E + F of each chart's cut surface, and its boundary loops.
    std::vector<int> uv_class(nc); // the UV vertex of each corner, named by a corner
    for(int c = 0; c < nc; ++c) uv_class[c] = uv_uf.find(c);
    const std::vector<long> chi = internal::chart_euler_characteristics(
      chart_of_face, n_charts, uv_class, nc, copp, [&](int c) { return cut[c] != 0; });
    std::vector<int> loops(n_charts, 0);
    std::vector<std::vector<int> > loop_sides;  // every boundary loop, sides in walk order
    std::vector<int> loop_chart;
    {
      // The boundary of the cut surface runs against the cut sides: after the
      // side of H[c], continue at the first cut side met turning around source(H[c]).
      std::vector<char> seen(nc, 0);
      for(int c0 = 0; c0 < nc; ++c0)
      {
        if(!cut[c0] || seen[c0]) continue;
        ++loops[chart_of_face[c0 / 3]];
        loop_sides.emplace_back();
        loop_chart.push_back(chart_of_face[c0 / 3]);
        int c = c0;
        while(!seen[c])
        {
          seen[c] = 1;
          loop_sides.back().push_back(c);
          int g = prev_c(c);
          for(int guard = 0; !cut[g]; ++guard)
          {
            if(guard > nc) return ERROR_NON_MANIFOLD_MESH;
            g = prev_c(copp[g]);
          }
          c = g;
        }
      }
    }

    // ---- faces of each chart, in face order
    std::vector<int> chart_face_start(n_charts + 1, 0), chart_faces(nf);
    for(int f = 0; f < nf; ++f) ++chart_face_start[chart_of_face[f] + 1];
    for(int k = 0; k < n_charts; ++k) chart_face_start[k + 1] += chart_face_start[k];
    {
      std::vector<int> fill(chart_face_start.begin(), chart_face_start.end() - 1);
      for(int f = 0; f < nf; ++f) chart_faces[fill[chart_of_face[f]]++] = f;
    }

    // ---- closed genus-0 charts get a slit; other charts that are not disks
    // (handles, several boundary loops) a cut graph through their handles
    std::vector<char> closed(n_charts, 0), general(n_charts, 0);
    for(int k = 0; k < n_charts; ++k)
    {
      if(loops[k] == 1 && chi[k] == 1)
        continue;
      if(loops[k] == 0 && chi[k] == 2)
        closed[k] = 1;
      else if((2 - chi[k] - loops[k]) % 2 != 0 || 2 - chi[k] - loops[k] < 0)
      {
        message = "chart " + std::to_string(k) + " has an impossible Euler characteristic " +
                  std::to_string(chi[k]) + " with " + std::to_string(loops[k]) + " boundary loops";
        return ERROR_NOT_A_DISK;
      }
      else
        general[k] = 1;
    }
    auto describe_chart = [&](int k) -> std::string
    {
      return "chart " + std::to_string(k) + " (faces connected across non-seam edges, " +
             std::to_string(chart_face_start[k + 1] - chart_face_start[k]) + " faces, genus " +
             std::to_string((2 - chi[k] - loops[k]) / 2) + ", " + std::to_string(loops[k]) + " boundary loops)";
    };
    auto fail_chart = [&](int k, const std::string& why) -> Error_code
    {
      message = describe_chart(k) + why;
      failed.assign(chart_faces.begin() + chart_face_start[k], chart_faces.begin() + chart_face_start[k + 1]);
      return ERROR_INITIAL_PARAMETERIZATION;
    };


    // Ring of corner sides ending at the vertex of corner c: H[r] for
    // r = c, prev(copp(c)), ...
    auto ring_of = [&](int c) -> std::vector<int>
    {
      std::vector<int> ring;
      int r = c;
      do { ring.push_back(r); r = prev_c(copp[r]); } while(r != c && ring.size() <= std::size_t(nc));
      return ring;
    };

    // The first choice: two edges at one vertex not on a common triangle
    // (consecutive in the ring). Returns one corner side per edge.
    auto two_edge_slit = [&](int k) -> std::vector<int>
    {
      double best = std::numeric_limits<double>::infinity();
      int best_a = -1, best_b = -1;
      // The vertex farthest from the chart's centroid, a protrusion's tip
      // where a seam is likely to end anyway; its straightest pair of edges.
      {
        const int* faces_begin = chart_faces.data() + chart_face_start[k];
        const int* faces_end = chart_faces.data() + chart_face_start[k + 1];
        double centroid[3] = { 0, 0, 0 };
        for(const int* f = faces_begin; f != faces_end; ++f)
          for(int j = 0; j < 3; ++j)
            for(int d = 0; d < 3; ++d) centroid[d] += P[cv[3 * *f + j]][d];
        for(int d = 0; d < 3; ++d) centroid[d] /= 3. * double(faces_end - faces_begin);
        int tip = -1;
        double farthest = -1;
        for(const int* f = faces_begin; f != faces_end; ++f)
          for(int j = 0; j < 3; ++j)
          {
            const int c = 3 * *f + j;
            double d2 = 0;
            for(int d = 0; d < 3; ++d) d2 += (P[cv[c]][d] - centroid[d]) * (P[cv[c]][d] - centroid[d]);
            if(d2 > farthest) { farthest = d2; tip = c; }
          }
        const std::vector<int> ring = ring_of(tip);
        const std::size_t d = ring.size();
        const XYZ& o = P[cv[tip]];
        double straightest = 2; // cosine of the angle between the two edges
        for(std::size_t i = 0; i < d; ++i)
          for(std::size_t j = i + 2; j < d; ++j)
          {
            if(i == 0 && j == d - 1) continue; // consecutive: on one triangle
            const XYZ& a = P[cv[prev_c(ring[i])]];
            const XYZ& b = P[cv[prev_c(ring[j])]];
            double aa = 0, bb = 0, ab = 0;
            for(int q = 0; q < 3; ++q)
            {
              aa += (a[q] - o[q]) * (a[q] - o[q]);
              bb += (b[q] - o[q]) * (b[q] - o[q]);
              ab += (a[q] - o[q]) * (b[q] - o[q]);
            }
            const double cosine = ab / std::sqrt(aa * bb);
            if(cosine < straightest) { straightest = cosine; best_a = ring[i]; best_b = ring[j]; }
          }
        if(best_a >= 0) return std::vector<int>{ best_a, best_b };
      }
      // else (a tetrahedron-like ring) the shortest such pair anywhere, or any pair
      for(int pass = 0; pass < 2 && best_a < 0; ++pass)
      {
        std::vector<char> vdone(nv, 0);
        for(int c = 0; c < nc; ++c)
        {
          if(chart_of_face[c / 3] != k || vdone[cv[c]]) continue;
          vdone[cv[c]] = 1;
          const std::vector<int> ring = ring_of(c);
          const std::size_t d = ring.size();
          std::vector<double> len(d);
          for(std::size_t i = 0; i < d; ++i)
            len[i] = side_length(ring[i]);
          for(std::size_t i = 0; i < d; ++i)
            for(std::size_t j = i + 1; j < d; ++j)
            {
              const bool adjacent = (j == i + 1) || (i == 0 && j == d - 1);
              if(pass == 0 && adjacent) continue;
              if(len[i] + len[j] < best)
              {
                best = len[i] + len[j];
                best_a = ring[i];
                best_b = ring[j];
              }
            }
        }
      }
      if(best_a < 0)
        return std::vector<int>();
      return std::vector<int>{ best_a, best_b };
    };

    // The fallbacks: shortest paths on the 3D edge lengths (Dijkstra). A closed
    // chart is a whole connected component, so the search stays in it.
    // H[c] runs from cv[prev_c(c)] to cv[c].
    std::vector<int> out_start, out_side;
    std::vector<double> dist;
    std::vector<int> pred; // the side by which a vertex was reached, -1 at the sources
    auto dijkstra = [&](const std::vector<int>& sources)
    {
      if(out_start.empty())
      {
        out_start.assign(nv + 1, 0);
        out_side.resize(nc);
        for(int c = 0; c < nc; ++c) ++out_start[cv[prev_c(c)] + 1];
        for(std::size_t v = 0; v < nv; ++v) out_start[v + 1] += out_start[v];
        std::vector<int> fill(out_start.begin(), out_start.end() - 1);
        for(int c = 0; c < nc; ++c) out_side[fill[cv[prev_c(c)]]++] = c;
      }
      dist.assign(nv, std::numeric_limits<double>::infinity());
      pred.assign(nv, -1);
      internal::dijkstra(sources, dist,
        [&](int u, const auto& visit) {
          for(int i = out_start[u]; i < out_start[u + 1]; ++i) visit(cv[out_side[i]], side_length(out_side[i]), out_side[i]);
        },
        [&](int, int w, int c) { pred[w] = c; });
    };
    auto chart_vertices = [&](int k) -> std::vector<int>
    {
      std::vector<int> vs;
      for(int i = chart_face_start[k]; i < chart_face_start[k + 1]; ++i)
        for(int j = 0; j < 3; ++j) vs.push_back(cv[3 * chart_faces[i] + j]);
      std::sort(vs.begin(), vs.end());
      vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
      return vs;
    };
    auto farthest = [&](const std::vector<int>& vs) -> int
    {
      int best = vs.front();
      for(int v : vs)
        if(dist[v] > dist[best]) best = v;
      return best;
    };
    // A shortest path between two approximately farthest vertices (double
    // sweep: the farthest vertex b from the farthest vertex a from an arbitrary
    // one): a simple path, so the slit chart is a disk.
    auto path_slit = [&](int k) -> std::vector<int>
    {
      const std::vector<int> vs = chart_vertices(k);
      dijkstra(std::vector<int>(1, cv[3 * first_face[k]]));
      const int a = farthest(vs);
      dijkstra(std::vector<int>(1, a));
      std::vector<int> sides;
      for(int v = farthest(vs); pred[v] >= 0; v = cv[prev_c(pred[v])])
        sides.push_back(pred[v]);
      if(sides.size() < 2) // a single edge is no slit a circle can be put on
        sides.clear();
      return sides;
    };

    // Attempts, in order, until the chart's map has no flipped or degenerate triangle:
    // closed charts: two-edge slit + Tutte, path + Tutte, path + mean value coordinates;
    // disks: Tutte, mean value coordinates.
    auto n_attempts = [&](int k) { return closed[k] ? 3 : 2; };
    auto uses_mean_value = [&](int k, int a) { return closed[k] ? a == 2 : a == 1; };
    std::vector<int> attempt(n_charts, 0);
    std::vector<std::vector<int> > slit_sides(n_charts);
    // Sets the slit of attempt[k], skipping attempts whose slit does not exist.
    auto prepare = [&](int k) -> bool
    {
      for(; attempt[k] < n_attempts(k); ++attempt[k])
      {
        if(!closed[k]) return true;
        if(attempt[k] == 0) slit_sides[k] = two_edge_slit(k);
        else if(attempt[k] == 1) slit_sides[k] = path_slit(k);
        else if(slit_sides[k].empty()) continue; // no path for mean value coordinates either
        if(!slit_sides[k].empty()) return true;
      }
      return false;
    };

    // ---- Tutte (or mean value coordinates) on a Seam_mesh of the charts
    std::vector<char> slit(nc, 0); // corner sides cut by a slit
    const auto is_cut_edge = [&](edge_descriptor e) -> bool
    {
      const int c = corner_of[get(himap, halfedge(e, tm))];
      const int c2 = corner_of[get(himap, opposite(halfedge(e, tm), tm))];
      const int s = c >= 0 ? c : c2;
      return s >= 0 && (cut[s] || slit[s]);
    };
    typedef Seam_mesh_maker<TriangleMesh>                                        Maker;
    typedef typename Maker::Seam_mesh                                            Seam_mesh;
    typedef typename SMP::internal::Kernel_traits<Seam_mesh>::Kernel::Point_2   SMP_point_2;
    typedef internal::Circular_border_arc_length_with_point_map<Seam_mesh, VPM>  Border;
    typedef SMP::Barycentric_mapping_parameterizer_3<Seam_mesh, Border,
                                                     internal::Fixed_border_solver_traits> Tutte;
    typedef internal::Mean_value_coordinates_with_point_map<Seam_mesh, VPM, Border> Mean_value;

    std::vector<SMP_point_2> seam_uv_data(nh);
    const auto seam_uv = boost::make_iterator_property_map(seam_uv_data.begin(), himap);
    std::vector<UV> uv(nc);
    std::vector<UV> lo(n_charts), hi(n_charts);

    // Reads chart k back from the seam mesh, mirrors it if needed (the circle is
    // walked along the border loop) so that faces keep their 3D orientation,
    // scales it so that its UV area equals its 3D area, and checks that every
    // triangle has a positive area.
    auto finish_chart = [&](int k, bool strict) -> bool
    {
      const double inf = std::numeric_limits<double>::infinity();
      for(int i = chart_face_start[k]; i < chart_face_start[k + 1]; ++i)
        for(int c = 3 * chart_faces[i]; c < 3 * chart_faces[i] + 3; ++c)
          if(!std::isfinite(uv[c][0]) || !std::isfinite(uv[c][1]))
            return false;
      double area_uv = 0, area_3d = 0;
      for(int i = chart_face_start[k]; i < chart_face_start[k + 1]; ++i)
      {
        const int f = chart_faces[i];
        area_uv += internal::signed_area_2(uv[3 * f], uv[3 * f + 1], uv[3 * f + 2]);
        area_3d += area3[f];
      }
      if(!(area_uv != 0) || !std::isfinite(area_uv))
        return false;
      const double s = std::sqrt(area_3d / std::abs(area_uv));
      const double sx = area_uv < 0 ? -s : s, sy = s;
      lo[k] = UV{{ inf, inf }};
      hi[k] = UV{{ -inf, -inf }};
      for(int i = chart_face_start[k]; i < chart_face_start[k + 1]; ++i)
        for(int c = 3 * chart_faces[i]; c < 3 * chart_faces[i] + 3; ++c)
        {
          uv[c][0] *= sx;
          uv[c][1] *= sy;
          for(int j = 0; j < 2; ++j)
          {
            lo[k][j] = (std::min)(lo[k][j], uv[c][j]);
            hi[k][j] = (std::max)(hi[k][j], uv[c][j]);
          }
        }
      // `strict`: not even numerically degenerate as the optimizers (and
      // uvmetrics.py) judge it, an area below 1e-12 of the chart's (the
      // descent expands such triangles of disks and slit spheres, but on cut
      // handles and holes it can take hours)
      const double least = strict ? 1e-12 * area_3d : 0.;
      for(int i = chart_face_start[k]; i < chart_face_start[k + 1]; ++i)
      {
        const int f = chart_faces[i];
        if(!(internal::signed_area_2(uv[3 * f], uv[3 * f + 1], uv[3 * f + 2]) > least))
          return false;
      }
      // two vertices at (about) one point: a map shrunk to the precision of
      // doubles, around which no scaffold can be meshed
      const double cell = 1e-12 * (std::max)(hi[k][0] - lo[k][0], hi[k][1] - lo[k][1]);
      std::vector<std::pair<std::pair<long long, long long>, int> > at;
      for(int i = chart_face_start[k]; i < chart_face_start[k + 1]; ++i)
        for(int c = 3 * chart_faces[i]; c < 3 * chart_faces[i] + 3; ++c)
          at.emplace_back(std::make_pair(std::llround((uv[c][0] - lo[k][0]) / cell),
                                         std::llround((uv[c][1] - lo[k][1]) / cell)), cv[c]);
      std::sort(at.begin(), at.end());
      for(std::size_t i = 1; i < at.size(); ++i)
        if(at[i].first == at[i - 1].first && at[i].second != at[i - 1].second) return false;
      return true;
    };
    auto accept_chart = [&](Seam_mesh& smesh, int k) -> bool
    {
      for(int i = chart_face_start[k]; i < chart_face_start[k + 1]; ++i)
        for(int c = 3 * chart_faces[i]; c < 3 * chart_faces[i] + 3; ++c)
        {
          const SMP_point_2 p = get(seam_uv, seam_mesh_corner_vertex(smesh, H[c]));
          uv[c] = {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()) }};
        }
      return finish_chart(k, false);
    };

    // ---- charts with handles or several boundary loops: cut graph, filled-hole Tutte
    std::vector<int> slit_sides_all; // a corner side of every slit and cut edge
    std::vector<char> pending(n_charts, 1);
    {
      std::vector<char> handle_slit(nc, 0);
      for(int k = 0; k < n_charts; ++k)
      {
        if(!general[k]) continue;
        pending[k] = 0;
        const std::vector<int> faces_k(chart_faces.begin() + chart_face_start[k],
                                       chart_faces.begin() + chart_face_start[k + 1]);
        internal::Flat_chart ch;
        ch.faces = &faces_k;
        ch.cls = &uv_class;
        ch.copp = &copp;
        ch.cut = &cut;
        ch.side_length = side_length;
        ch.point = [&](int c) { return P[cv[c]]; };
        double longest = -1;
        for(std::size_t i = 0; i < loop_sides.size(); ++i)
        {
          if(loop_chart[i] != k) continue;
          double length = 0;
          for(int s : loop_sides[i]) length += side_length(s);
          if(length > longest) { longest = length; ch.outer = static_cast<int>(ch.loops.size()); }
          ch.loops.push_back(loop_sides[i]);
        }
        const int genus = (2 - chi[k] - loops[k]) / 2;
        std::vector<int> real_sides, border_sides;
        if(genus > 0)
        {
          double length = 0;
          if(!internal::Handle_cut(ch, genus).compute(real_sides, border_sides, length))
          {
            return fail_chart(k, ": no cut graph through its handles was found");
          }
        }
        for(int s : real_sides) handle_slit[s] = handle_slit[copp[s]] = 1;
        bool ok = false;
        for(int attempt = 0; attempt < 2 && !ok; ++attempt)
          ok = internal::map_filled_chart(ch, handle_slit, border_sides, attempt == 1, uv) && finish_chart(k, true);
        if(!ok)
        {
          return fail_chart(k, ": its Tutte and mean value maps, cut to a disk through " +
                               std::to_string(real_sides.size()) + " edges, have flipped, degenerate or coincident triangles");
        }
        for(int s : real_sides) slit_sides_all.push_back(s);
      }
    }

    for(int k = 0; k < n_charts; ++k)
      if(pending[k] && !prepare(k))
      {
        return fail_chart(k, ": no slit was found");
      }
    for(bool any = std::find(pending.begin(), pending.end(), 1) != pending.end(); any; )
    {
      std::fill(slit.begin(), slit.end(), 0);
      for(int k = 0; k < n_charts; ++k)
        for(int s : slit_sides[k])
          slit[s] = slit[copp[s]] = 1;
      Maker maker(tm, boost::make_function_property_map<edge_descriptor, bool>(is_cut_edge));
      Seam_mesh& smesh = maker.seam_mesh();
      any = false;
      for(int k = 0; k < n_charts; ++k)
      {
        if(!pending[k]) continue;
        const auto bhd = maker.border_halfedge(face(H[3 * first_face[k]], tm));
        if(bhd == typename boost::graph_traits<Seam_mesh>::halfedge_descriptor())
        {
          return fail_chart(k, ": no border was found");
        }
        const SMP::Error_code status = uses_mean_value(k, attempt[k])
          ? SMP::parameterize(smesh, Mean_value(vpm, Border(vpm)), bhd, seam_uv)
          : SMP::parameterize(smesh, Tutte(Border(vpm)), bhd, seam_uv);
        if(status == SMP::OK && accept_chart(smesh, k))
        {
          pending[k] = 0;
          continue;
        }
        ++attempt[k];
        if(!prepare(k))
        {
          return fail_chart(k, ": its Tutte and mean value maps have flipped, degenerate or coincident triangles");
        }
        any = true;
      }
    }
    for(int k = 0; k < n_charts; ++k)
      for(int s : slit_sides[k])
        slit_sides_all.push_back(s);
    for(int c = 0; c < nc; ++c)
      if(extra[c] && c < copp[c]) slit_sides_all.push_back(c);

    // Grid of charts in face order.
    const std::vector<UV> corner = internal::grid_layout(lo, hi);

    // ---- write (nothing was written before this point)
    corner_uvs.resize(2 * std::size_t(nc));
    for(int c = 0; c < nc; ++c)
    {
      const int k = chart_of_face[c / 3];
      corner_uvs[2 * c] = uv[c][0] - lo[k][0] + corner[k][0];
      corner_uvs[2 * c + 1] = uv[c][1] - lo[k][1] + corner[k][1];
    }
    for(int s : slit_sides_all)
      if(copp[s] >= 0) seam[s] = seam[copp[s]] = 1;
    return OK;
  };

  // A chart whose maps all degenerate (long protrusions, many holes: Tutte's
  // map shrinks them below double precision) is split into geodesic Voronoi
  // regions around 2, 4, ... farthest-point seeds, and everything is tried again.
  auto split = [&](const std::vector<int>& fs, int n_seeds, std::vector<char>& extra)
  {
    std::vector<char> in_set(nf, 0);
    for(int f : fs) in_set[f] = 1;
    std::vector<double> d(nv, std::numeric_limits<double>::infinity());
    std::vector<int> label(nv, -1);
    std::vector<std::vector<std::pair<int, double> > > adj(nv);
    for(int f : fs)
      for(int c = 3 * f; c < 3 * f + 3; ++c)
      {
        adj[cv[prev_c(c)]].emplace_back(cv[c], side_length(c));
        adj[cv[c]].emplace_back(cv[prev_c(c)], side_length(c));
      }
    auto grow = [&](const std::vector<int>& seeds)
    {
      for(std::size_t i = 0; i < seeds.size(); ++i) label[seeds[i]] = static_cast<int>(i);
      internal::dijkstra(seeds, d,
        [&](int u, const auto& visit) { for(const auto& e : adj[u]) visit(e.first, e.second, -1); },
        [&](int u, int w, int) { label[w] = label[u]; });
    };
    std::vector<int> seeds(1, cv[3 * fs.front()]);
    while(int(seeds.size()) < n_seeds)
    {
      std::fill(d.begin(), d.end(), std::numeric_limits<double>::infinity());
      grow(seeds);
      int far = seeds.front();
      for(int f : fs)
        for(int c = 3 * f; c < 3 * f + 3; ++c)
          if(d[cv[c]] > d[far]) far = cv[c];
      if(!(d[far] > 0)) break;
      seeds.push_back(far);
    }
    std::fill(d.begin(), d.end(), std::numeric_limits<double>::infinity());
    grow(seeds);
    auto face_label = [&](int f)
    {
      int best = cv[3 * f];
      for(int c = 3 * f + 1; c < 3 * f + 3; ++c)
        if(d[cv[c]] < d[best]) best = cv[c];
      return label[best];
    };
    for(int f : fs)
      for(int c = 3 * f; c < 3 * f + 3; ++c)
        if(copp[c] >= 0 && in_set[copp[c] / 3] && face_label(f) != face_label(copp[c] / 3))
          extra[c] = extra[copp[c]] = 1;
  };

  // Each round splits the first chart that failed, into more regions the
  // more rounds have failed (up to 64); a surface with many small handles
  // (CGAL's cheese: genus 133) has many such charts, so the rounds go on
  // while they cut something new.
  std::vector<char> extra(nc, 0);
  std::vector<int> failed;
  for(int round = 0; ; ++round)
  {
    failed.clear();
    const Error_code ec = solve(extra, failed);
    if(ec == OK) message.clear(); // (the charts that had to be split said why)
    if(ec != ERROR_INITIAL_PARAMETERIZATION || failed.empty()) return ec;
    const std::ptrdiff_t cuts = std::count(extra.begin(), extra.end(), char(1));
    split(failed, 2 << (std::min)(round, 5), extra);
    if(round >= 5 && std::count(extra.begin(), extra.end(), char(1)) == cuts) return ec;
  }
}

// compute_initial_parameterization(), with a message saying what failed.
template <class TriangleMesh, class EdgeSeamMap, class UVMap, class NamedParameters>
Error_code initial_parameterization(const TriangleMesh& tm,
                                    EdgeSeamMap seam_map,
                                    UVMap uvmap,
                                    const NamedParameters& np,
                                    std::string& message)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type Geom_traits;
  typedef typename Geom_traits::Point_2                              Point_2;

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  Cut_mesh cm;
  Face_graph_copy<TriangleMesh> copy;
  Error_code ec = copy_face_graph(tm, vpm, cm, copy, message);
  if(ec != OK) return ec;
  std::vector<char> seam;
  read_seam_map(tm, seam_map, copy, cm, seam);
  std::vector<double> corner_uvs;
  ec = initial_uv_map(tm, vpm, cm, copy, seam, corner_uvs, message);
  if(ec != OK) return ec;
  for(std::size_t c = 0; c < copy.corner_halfedge.size(); ++c)
    put(uvmap, copy.corner_halfedge[c], Point_2(corner_uvs[2 * c], corner_uvs[2 * c + 1]));
  for(std::size_t h = 0; h < seam.size(); ++h)
    if(seam[h] && cm.opposite[h] > int(h)) put(seam_map, edge(copy.corner_halfedge[h], tm), true);
  return OK;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
///
/// Computes the initial UV map OptCuts starts from.
///
/// The seams read from `seam_map` cut `tm` into charts (faces connected
/// across non-seam edges). Each chart that is a topological disk has its
/// boundary mapped to a circle by arc length and its interior by Tutte's
/// embedding (uniform weights), with CGAL's
/// `Circular_border_parameterizer_3` and `Barycentric_mapping_parameterizer_3`
/// on a `CGAL::Seam_mesh` (see `Seam_mesh_maker`); such a map has no flipped
/// triangle in exact arithmetic. On charts of 20000 interior vertices or
/// more, Tutte's system, its border rows eliminated (symmetric positive
/// definite), is solved for both coordinates with one factorization of
/// `Default_sparse_solver_traits` instead of CGAL's default iterative solver
/// (the same map up to that solver's tolerance; 96544 faces: 1.7 -> 0.8 s,
/// 386176 faces: 12.6 -> 3.7 s). A closed genus-0 chart is first cut by a slit
/// of two edges sharing a vertex: at the vertex farthest from the centroid of
/// the chart's triangle corners (the tip of a protrusion, where seams tend to
/// end), the two edges not on one triangle that make the straightest line. On
/// a surface with long protrusions (an octopus' tentacles), Tutte's map of that
/// slit squeezes the protrusions until triangles have zero area in double
/// precision: the chart is then slit along a shortest path
/// (Dijkstra on the 3D edge lengths) between two approximately farthest
/// vertices instead, and if that map still has a flipped or degenerate
/// triangle, mapped with Floater's mean value coordinates on the same path. A
/// disk whose Tutte map fails also gets mean value coordinates.
///
/// Any other chart (handles, several boundary loops) is cut through its
/// handles by a greedy system of loops (Erickson and Whittlesey 2005: a
/// shortest-path tree from a root, the dual spanning tree of the other edges
/// taking the longest loops first, and the 2g loops closed by the edges left
/// over). The root is the chart's longest boundary loop, collapsed to a point,
/// or on a closed chart the best of a few vertices spread over it. Inner
/// boundary loops stay holes: no seam joins them; the map (Tutte, else mean
/// value coordinates) is computed with each hole filled by a fan around a
/// virtual vertex, whose faces are then dropped, and the loops avoid the
/// holes' vertices so that no hole touches the chart's border.
///
/// The slit and cut edges are set in `seam_map`. Every chart is then scaled so that its UV area equals
/// its 3D area (the optimizer works at the 3D scale), and the charts are laid
/// out on a grid, with gaps, so that no two overlap.
///
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal vertex
///         point map (required by `Surface_mesh_parameterization`)
/// \tparam EdgeSeamMap a model of `ReadWritePropertyMap`, `edge_descriptor -> bool`
/// \tparam UVMap a model of `WritablePropertyMap`, `halfedge_descriptor -> Point_2`
///         (`Point_2` of the geometric traits)
///
/// \param tm the mesh; not modified
/// \param seam_map the seams; border edges of `tm` are never seams and are
///        ignored. Written only to add the slits of closed charts and the cuts through handles.
/// \param uvmap receives, for every halfedge `h` with a face, the UV of
///        `target(h)` in `face(h)`
/// \param np an optional sequence of named parameters among those below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D positions of the vertices}
///     \cgalParamType{a readable property map, `vertex_descriptor` to a 3D point}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{the kernel whose `Point_2` the UVs are}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of the points of `vertex_point_map`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return `OK`, or `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
/// `ERROR_NON_FINITE_COORDINATES`, `ERROR_DEGENERATE_TRIANGLE` (twice the
/// area below 1e-12 times the longest edge squared), `ERROR_NON_MANIFOLD_MESH`
/// (a vertex whose faces form several fans), `ERROR_NOT_A_DISK` (a chart
/// whose Euler characteristic and boundary loops fit no orientable surface),
/// `ERROR_INITIAL_PARAMETERIZATION` (CGAL's parameterizers failed or gave a
/// flipped or zero-area triangle with every slit and weighting tried; the
/// optimizers' message names the chart, its genus and its boundary loops). On any error neither `uvmap` nor `seam_map` is modified.
template <class TriangleMesh, class EdgeSeamMap, class UVMap,
          class NamedParameters = parameters::Default_named_parameters>
Error_code compute_initial_parameterization(const TriangleMesh& tm,
                                            EdgeSeamMap seam_map,
                                            UVMap uvmap,
                                            const NamedParameters& np = parameters::default_values())
{
  std::string message;
  return internal::initial_parameterization(tm, seam_map, uvmap, np, message);
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INITIAL_PARAMETERIZATION_H
