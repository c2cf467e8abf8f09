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

#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
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
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Relative threshold below which a 3D triangle counts as degenerate:
// twice its area against its longest edge squared (the sine of its largest
// angle, up to a factor <= 2). Below this, distortion energies overflow.
inline double degenerate_triangle_threshold() { return 1e-12; }

struct Union_find
{
  std::vector<int> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i)
  {
    while(parent[i] != i)
    {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  }
  // The smaller index becomes the root, so roots do not depend on the merge order.
  void unite(int a, int b)
  {
    a = find(a);
    b = find(b);
    if(a < b) parent[b] = a;
    else if(b < a) parent[a] = b;
  }
};

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

inline double signed_area_2(const std::array<double, 2>& a,
                            const std::array<double, 2>& b,
                            const std::array<double, 2>& c)
{
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
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
/// triangle. A closed genus-0 chart is first cut by a slit of two edges
/// sharing a vertex (the shortest such pair whose edges are not on one
/// triangle); those edges are set in `seam_map`. Every chart is then scaled so
/// that its UV area equals its 3D area (the optimizer works at the 3D scale),
/// and the charts are laid out on a grid, with gaps, so that no two overlap.
///
/// \tparam TriangleMesh a model of `FaceListGraph` with an internal vertex
///         point map (required by `Surface_mesh_parameterization`)
/// \tparam EdgeSeamMap a model of `ReadWritePropertyMap`, `edge_descriptor -> bool`
/// \tparam UVMap a model of `WritablePropertyMap`, `halfedge_descriptor -> Point_2`
///         (`Point_2` of the geometric traits)
///
/// \param tm the mesh; not modified
/// \param seam_map the seams; border edges of `tm` are never seams and are
///        ignored. Written only to add the slits of closed charts.
/// \param uvmap receives, for every halfedge `h` with a face, the UV of
///        `target(h)` in `face(h)`
/// \param np optional: `vertex_point_map`, `geom_traits`
///
/// \return `OK`, or `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
/// `ERROR_NON_FINITE_COORDINATES`, `ERROR_DEGENERATE_TRIANGLE` (twice the
/// area below 1e-12 times the longest edge squared), `ERROR_NON_MANIFOLD_MESH`
/// (a vertex whose faces form several fans), `ERROR_NOT_A_DISK` (a chart of
/// higher genus or with several boundary loops: cut it to a disk first),
/// `ERROR_INITIAL_PARAMETERIZATION` (CGAL's parameterizer failed or gave a
/// flipped triangle). On any error neither `uvmap` nor `seam_map` is modified.
template <class TriangleMesh, class EdgeSeamMap, class UVMap,
          class NamedParameters = parameters::Default_named_parameters>
Error_code compute_initial_parameterization(const TriangleMesh& tm,
                                            EdgeSeamMap seam_map,
                                            UVMap uvmap,
                                            const NamedParameters& np = parameters::default_values())
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;

  typedef boost::graph_traits<TriangleMesh>                           GT;
  typedef typename GT::vertex_descriptor                              vertex_descriptor;
  typedef typename GT::halfedge_descriptor                            halfedge_descriptor;
  typedef typename GT::edge_descriptor                                edge_descriptor;
  typedef typename GT::face_descriptor                                face_descriptor;

  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type           Geom_traits;
  typedef typename Geom_traits::Point_2                                        Point_2;
  typedef std::array<double, 2>                                                UV;
  typedef std::array<double, 3>                                                XYZ;

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));

  // ---- flat copy: corner c = 3 * face + k is halfedge H[c], the UV of target(H[c]) in that face
  const auto himap = get_initialized_halfedge_index_map(tm);
  const auto vimap = get_initialized_vertex_index_map(tm);
  std::size_t nh = 0, nv = 0;
  for(halfedge_descriptor h : halfedges(tm)) nh = (std::max)(nh, std::size_t(get(himap, h)) + 1);
  for(vertex_descriptor v : vertices(tm)) nv = (std::max)(nv, std::size_t(get(vimap, v)) + 1);

  std::vector<halfedge_descriptor> H;
  H.reserve(3 * num_faces(tm));
  for(face_descriptor f : faces(tm))
  {
    const halfedge_descriptor h0 = halfedge(f, tm), h1 = next(h0, tm), h2 = next(h1, tm);
    if(next(h2, tm) != h0 || h1 == h0 || h2 == h0)
      return ERROR_NON_TRIANGULAR_MESH;
    H.push_back(h0); H.push_back(h1); H.push_back(h2);
  }
  const int nc = static_cast<int>(H.size());
  const int nf = nc / 3;
  if(nf == 0)
    return ERROR_EMPTY_MESH;

  std::vector<XYZ> P(nv);
  for(vertex_descriptor v : vertices(tm))
  {
    const auto& p = get(vpm, v);
    const XYZ q = {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()) }};
    if(!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
      return ERROR_NON_FINITE_COORDINATES;
    P[get(vimap, v)] = q;
  }

  std::vector<int> corner_of(nh, -1), cv(nc), copp(nc);
  for(int c = 0; c < nc; ++c)
    corner_of[get(himap, H[c])] = c;
  std::vector<char> cut(nc, 0); // the edge of H[c] separates charts (or is a border)
  for(int c = 0; c < nc; ++c)
  {
    cv[c] = static_cast<int>(get(vimap, target(H[c], tm)));
    const halfedge_descriptor o = opposite(H[c], tm);
    copp[c] = corner_of[get(himap, o)];
    cut[c] = (copp[c] < 0 || get(seam_map, edge(H[c], tm))) ? 1 : 0;
  }
  auto next_c = [](int c) { return c - c % 3 + (c + 1) % 3; };
  auto prev_c = [](int c) { return c - c % 3 + (c + 2) % 3; };

  // ---- 3D areas; degenerate triangles
  std::vector<double> area3(nf);
  for(int f = 0; f < nf; ++f)
  {
    const XYZ& a = P[cv[3 * f]];
    const XYZ& b = P[cv[3 * f + 1]];
    const XYZ& c = P[cv[3 * f + 2]];
    const XYZ u = {{ b[0] - a[0], b[1] - a[1], b[2] - a[2] }};
    const XYZ w = {{ c[0] - a[0], c[1] - a[1], c[2] - a[2] }};
    const XYZ n = {{ u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] }};
    const double twice_area = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    auto sq = [](const XYZ& p, const XYZ& q)
    { return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]); };
    const double lmax2 = (std::max)({ sq(a, b), sq(b, c), sq(c, a) });
    if(!(twice_area > internal::degenerate_triangle_threshold() * lmax2))
      return ERROR_DEGENERATE_TRIANGLE;
    area3[f] = 0.5 * twice_area;
  }

  // ---- manifold vertices: the corners at a vertex form one fan (ignoring seams)
  {
    internal::Union_find fans(nc);
    for(int c = 0; c < nc; ++c)
    {
      const int o = copp[next_c(c)]; // corner at the same vertex across the edge of next(H[c])
      if(o >= 0) fans.unite(c, o);
    }
    std::vector<int> fan_of(nv, -1);
    for(int c = 0; c < nc; ++c)
    {
      const int r = fans.find(c);
      if(fan_of[cv[c]] < 0) fan_of[cv[c]] = r;
      else if(fan_of[cv[c]] != r) return ERROR_NON_MANIFOLD_MESH;
    }
  }

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
  std::vector<long> chi(n_charts, 0), border_sides(n_charts, 0);
  std::vector<int> loops(n_charts, 0);
  for(int f = 0; f < nf; ++f) chi[chart_of_face[f]] += 1;
  for(int c = 0; c < nc; ++c)
  {
    if(uv_uf.find(c) == c) chi[chart_of_face[c / 3]] += 1;
    if(cut[c]) border_sides[chart_of_face[c / 3]] += 1;
  }
  {
    // E: every face has 3 sides, an uncut edge two of them, a cut side is an edge alone.
    std::vector<long> faces_in(n_charts, 0);
    for(int f = 0; f < nf; ++f) faces_in[chart_of_face[f]] += 1;
    for(int k = 0; k < n_charts; ++k)
      chi[k] -= (3 * faces_in[k] + border_sides[k]) / 2;
  }
  {
    // The boundary of the cut surface runs against the cut sides: after the
    // side of H[c], continue at the first cut side met turning around source(H[c]).
    std::vector<char> seen(nc, 0);
    for(int c0 = 0; c0 < nc; ++c0)
    {
      if(!cut[c0] || seen[c0]) continue;
      ++loops[chart_of_face[c0 / 3]];
      int c = c0;
      while(!seen[c])
      {
        seen[c] = 1;
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

  // ---- closed genus-0 charts get a slit; anything else but a disk is refused
  std::vector<char> slit(nc, 0); // corner sides cut by a new slit
  std::vector<edge_descriptor> slit_edges;
  for(int k = 0; k < n_charts; ++k)
  {
    if(loops[k] == 1 && chi[k] == 1)
      continue;
    if(!(loops[k] == 0 && chi[k] == 2))
      return ERROR_NOT_A_DISK;

    // Shortest pair of edges at one vertex not on a common triangle (consecutive
    // in the ring); a tetrahedron-like ring has none, then any pair will do.
    double best = std::numeric_limits<double>::infinity();
    int best_a = -1, best_b = -1;
    for(int pass = 0; pass < 2 && best_a < 0; ++pass)
    {
      std::vector<char> vdone(nv, 0);
      for(int c = 0; c < nc; ++c)
      {
        if(chart_of_face[c / 3] != k || vdone[cv[c]]) continue;
        vdone[cv[c]] = 1;
        // ring of corner sides ending at this vertex: H[r] for r = c, prev(copp(c)), ...
        std::vector<int> ring;
        int r = c;
        do { ring.push_back(r); r = prev_c(copp[r]); } while(r != c && ring.size() <= std::size_t(nc));
        const std::size_t d = ring.size();
        std::vector<double> len(d);
        for(std::size_t i = 0; i < d; ++i)
        {
          const XYZ& p = P[cv[ring[i]]];
          const XYZ& q = P[cv[prev_c(ring[i])]];
          len[i] = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                             (p[2] - q[2]) * (p[2] - q[2]));
        }
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
      return ERROR_INITIAL_PARAMETERIZATION;
    for(int s : { best_a, best_b })
    {
      slit[s] = slit[copp[s]] = 1;
      slit_edges.push_back(edge(H[s], tm));
    }
  }

  // ---- Tutte on a Seam_mesh of the charts
  const auto is_cut_edge = [&](edge_descriptor e) -> bool
  {
    const int c = corner_of[get(himap, halfedge(e, tm))];
    const int c2 = corner_of[get(himap, opposite(halfedge(e, tm), tm))];
    const int s = c >= 0 ? c : c2;
    return s >= 0 && (cut[s] || slit[s]);
  };
  Seam_mesh_maker<TriangleMesh> maker(
    tm, boost::make_function_property_map<edge_descriptor, bool>(is_cut_edge));
  typedef typename Seam_mesh_maker<TriangleMesh>::Seam_mesh Seam_mesh;
  typedef typename SMP::internal::Kernel_traits<Seam_mesh>::Kernel::Point_2 SMP_point_2;
  typedef internal::Circular_border_arc_length_with_point_map<Seam_mesh, VPM>  Border;
  typedef SMP::Barycentric_mapping_parameterizer_3<Seam_mesh, Border>          Parameterizer;

  std::vector<SMP_point_2> seam_uv_data(nh);
  const auto seam_uv = boost::make_iterator_property_map(seam_uv_data.begin(), himap);
  Seam_mesh& smesh = maker.seam_mesh();
  for(int k = 0; k < n_charts; ++k)
  {
    const auto bhd = maker.border_halfedge(face(H[3 * first_face[k]], tm));
    if(bhd == typename boost::graph_traits<Seam_mesh>::halfedge_descriptor())
      return ERROR_INITIAL_PARAMETERIZATION;
    const SMP::Error_code status = SMP::parameterize(smesh, Parameterizer(Border(vpm)), bhd, seam_uv);
    if(status != SMP::OK)
      return ERROR_INITIAL_PARAMETERIZATION;
  }

  std::vector<UV> uv(nc);
  for(int c = 0; c < nc; ++c)
  {
    const SMP_point_2 p = get(seam_uv, seam_mesh_corner_vertex(smesh, H[c]));
    uv[c] = {{ CGAL::to_double(p.x()), CGAL::to_double(p.y()) }};
    if(!std::isfinite(uv[c][0]) || !std::isfinite(uv[c][1]))
      return ERROR_INITIAL_PARAMETERIZATION;
  }

  // ---- orientation, scale to the 3D area, layout
  std::vector<double> area_uv(n_charts, 0), area_3d(n_charts, 0);
  for(int f = 0; f < nf; ++f)
  {
    area_uv[chart_of_face[f]] += internal::signed_area_2(uv[3 * f], uv[3 * f + 1], uv[3 * f + 2]);
    area_3d[chart_of_face[f]] += area3[f];
  }
  // The circle is walked along the border loop, which may give a mirrored
  // chart: mirror it back so that faces keep their 3D orientation.
  std::vector<double> sx(n_charts), sy(n_charts);
  for(int k = 0; k < n_charts; ++k)
  {
    if(!(area_uv[k] != 0) || !std::isfinite(area_uv[k]))
      return ERROR_INITIAL_PARAMETERIZATION;
    const double s = std::sqrt(area_3d[k] / std::abs(area_uv[k]));
    sx[k] = area_uv[k] < 0 ? -s : s;
    sy[k] = s;
  }
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<UV> lo(n_charts, UV{{ inf, inf }}), hi(n_charts, UV{{ -inf, -inf }});
  for(int c = 0; c < nc; ++c)
  {
    const int k = chart_of_face[c / 3];
    uv[c][0] *= sx[k];
    uv[c][1] *= sy[k];
    for(int i = 0; i < 2; ++i)
    {
      lo[k][i] = (std::min)(lo[k][i], uv[c][i]);
      hi[k][i] = (std::max)(hi[k][i], uv[c][i]);
    }
  }
  for(int f = 0; f < nf; ++f)
    if(!(internal::signed_area_2(uv[3 * f], uv[3 * f + 1], uv[3 * f + 2]) > 0))
      return ERROR_INITIAL_PARAMETERIZATION;

  // Grid of charts in face order; a column is as wide as its widest chart.
  const int n_cols = static_cast<int>(std::ceil(std::sqrt(double(n_charts))));
  const int n_rows = (n_charts + n_cols - 1) / n_cols;
  std::vector<double> col_w(n_cols, 0), row_h(n_rows, 0);
  double largest = 0;
  for(int k = 0; k < n_charts; ++k)
  {
    const double w = hi[k][0] - lo[k][0], h = hi[k][1] - lo[k][1];
    col_w[k % n_cols] = (std::max)(col_w[k % n_cols], w);
    row_h[k / n_cols] = (std::max)(row_h[k / n_cols], h);
    largest = (std::max)({ largest, w, h });
  }
  const double gap = 0.05 * largest;
  std::vector<double> col_x(n_cols, 0), row_y(n_rows, 0);
  for(int i = 1; i < n_cols; ++i) col_x[i] = col_x[i - 1] + col_w[i - 1] + gap;
  for(int i = 1; i < n_rows; ++i) row_y[i] = row_y[i - 1] + row_h[i - 1] + gap;

  // ---- write (nothing was written before this point)
  for(int c = 0; c < nc; ++c)
  {
    const int k = chart_of_face[c / 3];
    put(uvmap, H[c], Point_2(uv[c][0] - lo[k][0] + col_x[k % n_cols],
                             uv[c][1] - lo[k][1] + row_y[k / n_cols]));
  }
  for(edge_descriptor e : slit_edges)
    put(seam_map, e, true);
  return OK;
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INITIAL_PARAMETERIZATION_H
