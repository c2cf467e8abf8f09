// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Chart packing: every chart of a UV map moved rigidly (and all scaled by one
// factor) into [0,1]^2 without overlap, as texture atlas tools do.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_PACK_CHARTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_PACK_CHARTS_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Face_graph_copy.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// What `pack_charts()` did.
struct Chart_packing_result
{
  Error_code status = OK;       ///< `OK`, or an `ERROR_*` code: then the UV map was left untouched
  std::string message;          ///< what was wrong, when `status` is not `OK`
  std::size_t charts = 0;       ///< number of charts packed
  /// the factor applied to all UVs (with `equal_texel_density`, the factor applied to the charts at UV area = 3D area)
  double scale = 0;
  /// sum of the charts' UV areas in [0,1]^2 (1 would fill the texture)
  double fill_rate = 0;
  /// texture_size * sqrt(UV area / 3D area) over all charts: texels per unit of 3D length
  double texels_per_unit_length = 0;
  bool has_result() const { return status == OK; }
};

namespace internal {

struct Packing_settings
{
  double texture_size = 1024;
  double margin = 4;
  bool allow_rotation = true;
  bool equal_texel_density = false;
};

template <typename NamedParameters>
Packing_settings packing_settings(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Packing_settings s;
  s.texture_size = double(choose_parameter(get_parameter(np, internal_np::texture_size), s.texture_size));
  s.margin = double(choose_parameter(get_parameter(np, internal_np::margin), s.margin));
  s.allow_rotation = choose_parameter(get_parameter(np, internal_np::allow_rotation), s.allow_rotation);
  s.equal_texel_density = choose_parameter(get_parameter(np, internal_np::equal_texel_density),
                                           s.equal_texel_density);
  return s;
}

inline Error_code check_packing_settings(const Packing_settings& s, std::string& message)
{
  if(!(s.texture_size >= 1) || !std::isfinite(s.texture_size))
  {
    message = "texture_size must be at least 1 texel";
    return ERROR_WRONG_PARAMETER;
  }
  if(!(s.margin >= 0) || !(2 * s.margin < s.texture_size))
  {
    message = "margin must be >= 0 and less than half of texture_size";
    return ERROR_WRONG_PARAMETER;
  }
  return OK;
}

struct Pack_rect { double x, y, w, h; };

// MaxRects (Jylanki, "A thousand ways to pack the bin", 2010): the free space
// is kept as the list of maximal empty rectangles, which may overlap.
class Max_rects
{
public:
  enum Rule { BEST_SHORT_SIDE_FIT, BOTTOM_LEFT };

  Max_rects(double x0, double y0, double w, double h) { m_free.push_back(Pack_rect{x0, y0, w, h}); }

  // Places a w x h rectangle (or h x w if `may_turn`): false if it fits nowhere.
  bool insert(double w, double h, bool may_turn, Rule rule, Pack_rect& placed, bool& turned)
  {
    double best1 = std::numeric_limits<double>::infinity(), best2 = best1;
    bool found = false;
    for(const Pack_rect& f : m_free)
      for(int t = 0; t < (may_turn ? 2 : 1); ++t)
      {
        const double rw = t ? h : w, rh = t ? w : h;
        if(rw > f.w || rh > f.h) continue;
        double s1, s2;
        if(rule == BEST_SHORT_SIDE_FIT)
        {
          s1 = (std::min)(f.w - rw, f.h - rh);
          s2 = (std::max)(f.w - rw, f.h - rh);
        }
        else { s1 = f.y + rh; s2 = f.x; }
        if(s1 < best1 || (s1 == best1 && s2 < best2))
        {
          best1 = s1; best2 = s2; found = true;
          placed = Pack_rect{f.x, f.y, rw, rh};
          turned = t == 1;
        }
      }
    if(found) split(placed);
    return found;
  }

private:
  static bool contains(const Pack_rect& b, const Pack_rect& a)
  {
    return a.x >= b.x && a.y >= b.y && a.x + a.w <= b.x + b.w && a.y + a.h <= b.y + b.h;
  }

  void split(const Pack_rect& p)
  {
    // Free rectangles away from p stay (none contains another); the pieces
    // of those it cuts are checked against all, so each step is linear.
    std::vector<Pack_rect> kept, pieces;
    kept.reserve(m_free.size());
    for(const Pack_rect& f : m_free)
    {
      if(!(p.x < f.x + f.w && p.x + p.w > f.x && p.y < f.y + f.h && p.y + p.h > f.y))
      {
        kept.push_back(f);
        continue;
      }
      if(p.x > f.x) pieces.push_back(Pack_rect{f.x, f.y, p.x - f.x, f.h});
      if(p.x + p.w < f.x + f.w) pieces.push_back(Pack_rect{p.x + p.w, f.y, f.x + f.w - (p.x + p.w), f.h});
      if(p.y > f.y) pieces.push_back(Pack_rect{f.x, f.y, f.w, p.y - f.y});
      if(p.y + p.h < f.y + f.h) pieces.push_back(Pack_rect{f.x, p.y + p.h, f.w, f.y + f.h - (p.y + p.h)});
    }
    // a piece inside a kept rectangle or inside another piece (of two equal, the first stays) is dropped
    std::vector<char> drop(pieces.size(), 0);
    for(std::size_t i = 0; i < pieces.size(); ++i)
    {
      for(const Pack_rect& k : kept)
        if(contains(k, pieces[i])) { drop[i] = 1; break; }
      for(std::size_t j = 0; j < pieces.size() && !drop[i]; ++j)
        if(j != i && contains(pieces[j], pieces[i]) && (!contains(pieces[i], pieces[j]) || j < i))
          drop[i] = 1;
    }
    m_free.clear();
    // a piece never contains a kept rectangle: both lie in the free space, the
    // kept one away from p, the piece beside p within a rectangle it cut
    for(const Pack_rect& k : kept) m_free.push_back(k);
    for(std::size_t i = 0; i < pieces.size(); ++i)
      if(!drop[i]) m_free.push_back(pieces[i]);
  }

  std::vector<Pack_rect> m_free;
};

// Convex hull (Andrew's monotone chain), counterclockwise, of points given as x, y pairs.
inline std::vector<std::pair<double, double> > convex_hull_2(std::vector<std::pair<double, double> > p)
{
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if(p.size() < 3) return p;
  auto cross = [](const std::pair<double, double>& o, const std::pair<double, double>& a,
                  const std::pair<double, double>& b) {
    return (a.first - o.first) * (b.second - o.second) - (a.second - o.second) * (b.first - o.first);
  };
  std::vector<std::pair<double, double> > h(2 * p.size());
  std::size_t k = 0;
  for(std::size_t i = 0; i < p.size(); ++i)
  {
    while(k >= 2 && cross(h[k-2], h[k-1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for(std::size_t i = p.size() - 1, t = k + 1; i-- > 0;)
  {
    while(k >= t && cross(h[k-2], h[k-1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

// One chart, rotated into its own frame: bounding rectangle [0, w] x [0, h].
struct Packed_chart
{
  std::vector<int> uv_vertices;
  double uv_area = 0, area_3d = 0;
  double factor = 1;          // per-chart scale before the common one (equal_texel_density)
  double c = 1, s = 0;        // rotation
  double x0 = 0, y0 = 0, w = 0, h = 0;
};

// Packs the charts of `cm` (UV vertices labelled) in place; `cm.uv` is
// changed only when the result is `OK`.
inline Error_code pack_cut_mesh(Cut_mesh& cm, const Packing_settings& settings,
                                Chart_packing_result& result, std::string& message)
{
  Error_code status = check_packing_settings(settings, message);
  if(status != OK) return status;
  const double N = settings.texture_size, m = settings.margin;

  std::vector<int> chart_of_face;
  const std::size_t nc = cm.compute_charts(chart_of_face);
  std::vector<Packed_chart> charts(nc);
  std::vector<int> chart_of_uv(cm.number_of_uv_vertices(), -1);
  for(std::size_t f = 0; f < cm.number_of_faces(); ++f)
  {
    Packed_chart& pc = charts[chart_of_face[f]];
    pc.uv_area += 0.5 * cm.signed_uv_area2(f);
    pc.area_3d += cm.face_area[f];
    for(int i = 0; i < 3; ++i)
    {
      const int u = cm.corner_uv[3*f + i];
      if(chart_of_uv[u] < 0) { chart_of_uv[u] = chart_of_face[f]; pc.uv_vertices.push_back(u); }
    }
  }

  // Each chart in the frame of its minimum-area bounding rectangle (one of
  // the hull's edge directions), or as it is.
  double sum_rect_area = 0;
  for(std::size_t k = 0; k < nc; ++k)
  {
    Packed_chart& pc = charts[k];
    if(settings.equal_texel_density)
    {
      if(!(pc.uv_area > 0))
      {
        message = "chart " + std::to_string(k) + " has no positive UV area: its texel density is undefined";
        return ERROR_FLIPPED_UV_TRIANGLE;
      }
      pc.factor = std::sqrt(pc.area_3d / pc.uv_area);
    }
    std::vector<std::pair<double, double> > pts;
    pts.reserve(pc.uv_vertices.size());
    for(int u : pc.uv_vertices) pts.emplace_back(cm.uv[2*u], cm.uv[2*u+1]);
    if(settings.allow_rotation)
    {
      const auto hull = convex_hull_2(pts);
      double best = std::numeric_limits<double>::infinity();
      for(std::size_t i = 0; i < hull.size() && hull.size() >= 3; ++i)
      {
        const auto& a = hull[i];
        const auto& b = hull[(i + 1) % hull.size()];
        const double dx = b.first - a.first, dy = b.second - a.second, len = std::hypot(dx, dy);
        if(!(len > 0)) continue;
        const double c = dx / len, s = dy / len;   // rotate by -angle(ab)
        double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
        for(const auto& q : hull)
        {
          const double x = c * q.first + s * q.second, y = -s * q.first + c * q.second;
          lo[0] = (std::min)(lo[0], x); hi[0] = (std::max)(hi[0], x);
          lo[1] = (std::min)(lo[1], y); hi[1] = (std::max)(hi[1], y);
        }
        const double area = (hi[0] - lo[0]) * (hi[1] - lo[1]);
        if(area < best) { best = area; pc.c = c; pc.s = s; }
      }
    }
    // the rectangle from all points, not the hull, whatever the hull's rounding
    double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
    for(const auto& q : pts)
    {
      const double x = pc.factor * (pc.c * q.first + pc.s * q.second);
      const double y = pc.factor * (-pc.s * q.first + pc.c * q.second);
      lo[0] = (std::min)(lo[0], x); hi[0] = (std::max)(hi[0], x);
      lo[1] = (std::min)(lo[1], y); hi[1] = (std::max)(hi[1], y);
    }
    pc.x0 = lo[0]; pc.y0 = lo[1]; pc.w = hi[0] - lo[0]; pc.h = hi[1] - lo[1];
    sum_rect_area += pc.w * pc.h;
  }
  if(!(sum_rect_area > 0) || !std::isfinite(sum_rect_area))
  {
    message = "the charts have no extent in UV space";
    return ERROR_INVALID_UV_MAP;
  }

  // Charts grown by the margin on their right and top sides, in the square
  // [m, N]^2: m texels to the border and between any two charts.
  struct Layout { std::vector<Pack_rect> at; std::vector<char> turned; };
  std::vector<std::vector<std::size_t> > orders;
  {
    std::vector<std::size_t> by_side(nc), by_area(nc);
    for(std::size_t k = 0; k < nc; ++k) by_side[k] = by_area[k] = k;
    std::stable_sort(by_side.begin(), by_side.end(), [&](std::size_t a, std::size_t b) {
      return (std::max)(charts[a].w, charts[a].h) > (std::max)(charts[b].w, charts[b].h); });
    std::stable_sort(by_area.begin(), by_area.end(), [&](std::size_t a, std::size_t b) {
      return charts[a].w * charts[a].h > charts[b].w * charts[b].h; });
    orders.push_back(by_side);
    orders.push_back(by_area);
  }
  auto try_pack = [&](double scale, Layout& layout) {
    for(const auto& order : orders)
      for(Max_rects::Rule rule : { Max_rects::BEST_SHORT_SIDE_FIT, Max_rects::BOTTOM_LEFT })
      {
        Max_rects bin(m, m, N - m, N - m);
        layout.at.assign(nc, Pack_rect{0, 0, 0, 0});
        layout.turned.assign(nc, 0);
        bool ok = true;
        for(std::size_t k : order)
        {
          bool turned = false;
          if(!bin.insert(scale * charts[k].w + m, scale * charts[k].h + m, settings.allow_rotation, rule,
                         layout.at[k], turned)) { ok = false; break; }
          layout.turned[k] = turned;
        }
        if(ok) return true;
      }
    return false;
  };

  Layout best;
  if(!try_pack(0., best))
  {
    message = std::to_string(nc) + " charts do not fit in a " + std::to_string(N) + " texel square with a margin of " +
              std::to_string(m) + " texels";
    return ERROR_WRONG_PARAMETER;
  }
  // The largest common scale the packer fits, by bisection (an upper bound: the charts' area).
  double lo = 0, hi = (N - m) / std::sqrt(sum_rect_area);
  Layout layout;
  if(try_pack(hi, layout)) { lo = hi; best = layout; }
  for(int it = 0; it < 60 && hi - lo > 1e-6 * hi; ++it)   // the fill rate to ~2e-6
  {
    const double mid = 0.5 * (lo + hi);
    if(try_pack(mid, layout)) { lo = mid; best = layout; }
    else hi = mid;
  }
  const double scale = lo;
  if(!(scale > 0))
  {
    message = "no positive scale fits the charts in the texture";
    return ERROR_WRONG_PARAMETER;
  }

  double uv_area = 0, area_3d = 0;
  for(std::size_t k = 0; k < nc; ++k)
  {
    const Packed_chart& pc = charts[k];
    const Pack_rect& r = best.at[k];
    const double f = scale * pc.factor;
    for(int u : pc.uv_vertices)
    {
      const double p = cm.uv[2*u], q = cm.uv[2*u+1];
      // texels from the chart's rectangle corner; a quarter turn maps (x, y) to (w - y, x)
      const double x = f * (pc.c * p + pc.s * q) - scale * pc.x0;
      const double y = f * (-pc.s * p + pc.c * q) - scale * pc.y0;
      const double tx = best.turned[k] ? r.x + scale * pc.h - y : r.x + x;
      const double ty = best.turned[k] ? r.y + x : r.y + y;
      cm.uv[2*u] = tx / N;
      cm.uv[2*u+1] = ty / N;
    }
    uv_area += f * f * pc.uv_area / (N * N);
    area_3d += pc.area_3d;
  }
  result.charts = nc;
  result.scale = scale / N;
  result.fill_rate = uv_area;
  result.texels_per_unit_length = N * std::sqrt(uv_area / area_3d);
  return OK;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// Lays all charts of a UV map out in the unit square [0,1]^2 without
/// overlap, as texture atlas tools do: each chart is moved rigidly (rotated
/// to its minimum-area bounding rectangle and by quarter turns when allowed,
/// and translated), all by one scale factor, the largest for which the
/// packer fits them in a `texture_size` x `texture_size` texture with
/// `margin` texels around each chart. Charts are never deformed: the seams,
/// flips, overlaps within a chart, and the E_SD at the optimal scale
/// (`equal_texel_density(false)`) are those of the input map.
///
/// The charts are the faces joined across edges whose two sides have the
/// same UVs. The packing is a MaxRects rectangle packing (best short side
/// fit and bottom-left, the charts sorted by longer side and by area) of the
/// charts' bounding rectangles grown by the margin, whose scale is found by
/// bisection: those rectangles are disjoint, so no two charts overlap and
/// any two are at least `margin` texels apart.
///
/// \tparam TriangleMesh a model of `FaceGraph` (triangles only)
/// \tparam UVMap a read-write property map `halfedge_descriptor -> Point_2`
///   (for every halfedge `h` with a face, the UV of `target(h)` in `face(h)`)
///
/// \param tm the mesh
/// \param uvmap the UV map, read and overwritten with the packed one; left
///   untouched unless the result's status is `OK`
/// \param np optional named parameters:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{texture_size}
///     \cgalParamDescription{the side of the square texture, in texels (>= 1)}
///     \cgalParamType{`double` (or an integer type)}
///     \cgalParamDefault{`1024`}
///   \cgalParamNEnd
///   \cgalParamNBegin{margin}
///     \cgalParamDescription{texels between two charts and between a chart and the border of the texture
///       (>= 0 and less than half of `texture_size`)}
///     \cgalParamType{`double` (or an integer type)}
///     \cgalParamDefault{`4`}
///   \cgalParamNEnd
///   \cgalParamNBegin{allow_rotation}
///     \cgalParamDescription{each chart may be rotated to its minimum-area bounding rectangle and by a
///       quarter turn; if `false`, charts are only translated (and scaled)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{equal_texel_density}
///     \cgalParamDescription{if `true`, each chart is first scaled so that its UV area equals its 3D area
///       (one texel density, as atlas tools' "scale to area"; the E_SD of the whole map may then change,
///       each chart's at its own optimal scale does not); if `false`, all charts get one scale factor,
///       which keeps their relative sizes and the map's E_SD at the optimal scale}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points (for the charts' 3D areas)}
///     \cgalParamType{a model of `ReadablePropertyMap` with `vertex_descriptor` as key type}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the status (`ERROR_EMPTY_MESH` and the other mesh errors, `ERROR_INVALID_UV_MAP` for a
///   non-finite UV or a map of zero extent, `ERROR_FLIPPED_UV_TRIANGLE` with `equal_texel_density` for a
///   chart without positive UV area, `ERROR_WRONG_PARAMETER` for a texture size below 1, a
///   negative margin or one so large that the charts do not fit), the number of charts, the scale
///   factor, the fill rate (the charts' share of the texture's area) and the texel density.
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Chart_packing_result pack_charts(const TriangleMesh& tm, UVMap uvmap,
                                 const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Chart_packing_result result;
  const internal::Packing_settings settings = internal::packing_settings(np);
  result.status = internal::check_packing_settings(settings, result.message);
  if(result.status != OK) return result;

  auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                              get_const_property_map(CGAL::vertex_point, tm));
  internal::Cut_mesh cm;
  internal::Face_graph_copy<TriangleMesh> copy;
  result.status = internal::copy_face_graph(tm, vpm, cm, copy, result.message);
  if(result.status != OK) return result;
  std::vector<double> corner_uvs;
  result.status = internal::read_uv_map(tm, uvmap, copy, corner_uvs, result.message);
  if(result.status != OK) return result;
  std::vector<char> seam;
  internal::seams_from_corner_uvs(cm, corner_uvs, seam);
  internal::label_uv_vertices(cm, seam);
  internal::set_uvs_from_corners(cm, corner_uvs);

  result.status = internal::pack_cut_mesh(cm, settings, result, result.message);
  if(result.status != OK) return result;
  internal::write_uv_map(cm, copy, uvmap);
  return result;
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_PACK_CHARTS_H
