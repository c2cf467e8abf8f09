// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// --svg: the UV layout as an SVG picture. Every triangle is one <polygon>
// filled by its symmetric Dirichlet distortion on a viridis color map, seams
// and the input's boundary are drawn as lines over it, with a legend and a
// caption (E_SD, normalized seam length, charts).
//
// Size matters (10k faces should stay in a few hundred KB): coordinates are
// integers on a 1000-unit canvas (shared corners round alike, so no gap
// opens), and the faces are grouped by color level so that each <polygon>
// carries only its points; its fill is inherited from its group.

#ifndef SMSO_CLI_UV_LAYOUT_SVG_H
#define SMSO_CLI_UV_LAYOUT_SVG_H

#include "picture_common.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace optimize_seams_cli {

// Viridis (matplotlib), sampled at 9 evenly spaced points; t in [0, 1].
inline std::array<int, 3> viridis(double t)
{
  static const int table[9][3] = {{68, 1, 84},    {72, 40, 120},  {62, 73, 137},
                                  {49, 104, 142}, {38, 130, 142}, {31, 158, 137},
                                  {53, 183, 121}, {110, 206, 88}, {253, 231, 37}};
  t = std::min(1., std::max(0., std::isfinite(t) ? t : 1.));
  const double x = t * 8;
  const int i = std::min(7, static_cast<int>(x));
  const double a = x - i;
  std::array<int, 3> c;
  for(int k = 0; k < 3; ++k)
    c[k] = static_cast<int>(std::lround((1 - a) * table[i][k] + a * table[i + 1][k]));
  return c;
}

inline std::string hex_color(const std::array<int, 3>& c)
{
  char buf[8];
  std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", c[0], c[1], c[2]);
  return buf;
}

// The color scale: log of the excess E - 4 over [0.01, 4], i.e. E in
// [4.01, 8] (clamped). A bound of 4.1 leaves most triangles within a few
// percent of 4: a linear scale would paint them all the same dark blue.
struct Distortion_scale
{
  static constexpr double low = 4.01, high = 8.0;
  static double position(double e)   // in [0, 1]
  {
    if(!std::isfinite(e) || e >= high)
      return 1;
    if(e <= low)
      return 0;
    return std::log((e - 4) / (low - 4)) / std::log((high - 4) / (low - 4));
  }
};

inline void append_xml_text(std::string& out, const std::string& s)
{
  for(char c : s)
  {
    switch(c)
    {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
}

// Writes the SVG; false if the file cannot be written or the map is empty.
template <typename TriangleMesh, typename UVMap, typename SeamMap>
bool write_uv_layout_svg(const std::string& path, const TriangleMesh& mesh, UVMap uvmap, SeamMap seams,
                         const Picture_caption& caption)
{
  const auto vpm = get(CGAL::vertex_point, mesh);

  // UV bounding box.
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for(auto f : faces(mesh))
    for(auto h : face_corners(f, mesh))
    {
      const auto q = get(uvmap, h);
      lo[0] = std::min(lo[0], q.x()); hi[0] = std::max(hi[0], q.x());
      lo[1] = std::min(lo[1], q.y()); hi[1] = std::max(hi[1], q.y());
    }
  const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if(!(extent > 0) || !std::isfinite(extent))
    return false;

  // Canvas: the layout fills `side` units along its longer extent; the
  // caption is above it, the legend below.
  const int side = 1000, margin = 20, caption_height = 88, legend_height = 80;
  const int layout_w = static_cast<int>(std::ceil(side * (hi[0] - lo[0]) / extent));
  const int layout_h = static_cast<int>(std::ceil(side * (hi[1] - lo[1]) / extent));
  const int width = std::max(layout_w, side) + 2 * margin;   // room for the caption
  const int x0 = margin + (width - 2 * margin - layout_w) / 2;   // centered
  const int y0 = margin + caption_height;
  const int height = y0 + layout_h + margin + legend_height;
  const double scale = side / extent;
  // v grows upwards in UV space, y downwards in SVG.
  auto px = [&](double u) { return static_cast<long>(std::lround(x0 + (u - lo[0]) * scale)); };
  auto py = [&](double v) { return static_cast<long>(std::lround(y0 + (hi[1] - v) * scale)); };

  // Faces by color level.
  const int levels = 64;
  std::vector<std::string> level_points(levels);
  std::size_t flipped = 0;
  char buf[512];
  for(auto f : faces(mesh))
  {
    const auto c = face_corners(f, mesh);
    const double e = triangle_symmetric_dirichlet(
      get(vpm, target(c[0], mesh)), get(vpm, target(c[1], mesh)), get(vpm, target(c[2], mesh)),
      get(uvmap, c[0]), get(uvmap, c[1]), get(uvmap, c[2]));
    flipped += std::isfinite(e) ? 0 : 1;
    const int level = std::min(levels - 1, static_cast<int>(Distortion_scale::position(e) * levels));
    std::string& out = level_points[level];
    out += "<polygon points=\"";
    for(int i = 0; i < 3; ++i)
    {
      const auto q = get(uvmap, c[i]);
      std::snprintf(buf, sizeof(buf), i ? " %ld %ld" : "%ld %ld", px(q.x()), py(q.y()));
      out += buf;
    }
    out += "\"/>\n";
  }

  // Seams (each side of a seam is on a chart boundary: both are drawn) and
  // the input's boundary, as one path each.
  std::string seam_path, boundary_path;
  std::size_t seam_edges = 0;
  for(auto e : edges(mesh))
  {
    const Edge_kind kind = edge_kind(e, mesh, seams);
    if(kind == Edge_kind::INTERIOR)
      continue;
    seam_edges += kind == Edge_kind::SEAM ? 1 : 0;
    std::string& out = kind == Edge_kind::SEAM ? seam_path : boundary_path;
    for(auto h : {halfedge(e, mesh), opposite(halfedge(e, mesh), mesh)})
    {
      if(is_border(h, mesh))
        continue;
      const auto a = get(uvmap, prev(h, mesh)), b = get(uvmap, h);   // source(h), target(h) in face(h)
      std::snprintf(buf, sizeof(buf), "M%ld %ldL%ld %ld", px(a.x()), py(a.y()), px(b.x()), py(b.y()));
      out += buf;
    }
  }

  std::string svg;
  svg.reserve(64 * num_faces(mesh) + 8192);
  std::snprintf(buf, sizeof(buf), "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" ", width,
                height);
  svg += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  svg += buf;
  std::snprintf(buf, sizeof(buf), "viewBox=\"0 0 %d %d\" font-family=\"sans-serif\">\n", width, height);
  svg += buf;
  svg += "<title>UV layout";
  if(!caption.title.empty())
  {
    svg += " of ";
    append_xml_text(svg, caption.title);
  }
  svg += "</title>\n";
  std::snprintf(buf, sizeof(buf), "<rect width=\"%d\" height=\"%d\" fill=\"#ffffff\"/>\n", width, height);
  svg += buf;

  // Caption.
  {
    const std::string line1 = caption.title.empty() ? std::string("UV layout") : caption.title;
    std::string line2 = "E_SD " + picture_number(caption.e_sd, 5);
    if(std::isfinite(caption.distortion_bound))
      line2 += " (bound " + picture_number(caption.distortion_bound, 6) + ")";
    line2 += ", normalized seam length " + picture_number(caption.seam_length_normalized, 4) + ", " +
             std::to_string(caption.charts) + (caption.charts == 1 ? " chart" : " charts") + ", " +
             std::to_string(num_faces(mesh)) + " faces";
    std::string line3 = "red: seams (" + std::to_string(seam_edges) + " edges, drawn on both sides)";
    if(!boundary_path.empty())
      line3 += "; black: boundary of the input";
    if(!caption.energy.empty())
      line3 += "; energy minimized: " + caption.energy;
    if(flipped > 0)
      line3 += "; " + std::to_string(flipped) + " flipped or degenerate triangles (top color)";
    const struct { const std::string* text; int y, size; const char* color; } lines[] = {
      {&line1, margin + 20, 20, "#000000"}, {&line2, margin + 46, 17, "#000000"}, {&line3, margin + 70, 14, "#444444"}};
    for(const auto& l : lines)
    {
      std::snprintf(buf, sizeof(buf), "<text x=\"%d\" y=\"%d\" font-size=\"%d\" fill=\"%s\">", margin, l.y, l.size,
                    l.color);
      svg += buf;
      append_xml_text(svg, *l.text);
      svg += "</text>\n";
    }
  }

  // Faces: a thin stroke of the fill color closes the anti-aliasing cracks
  // between neighbors.
  svg += "<g id=\"faces\" stroke-width=\"0.6\" stroke-linejoin=\"round\">\n";
  for(int level = 0; level < levels; ++level)
  {
    if(level_points[level].empty())
      continue;
    const std::string color = hex_color(viridis((level + 0.5) / levels));
    svg += "<g fill=\"" + color + "\" stroke=\"" + color + "\">\n";
    svg += level_points[level];
    svg += "</g>\n";
  }
  svg += "</g>\n";
  if(!boundary_path.empty())
    svg += "<path id=\"boundary\" fill=\"none\" stroke=\"#000000\" stroke-width=\"1.6\" stroke-linecap=\"round\" d=\"" +
           boundary_path + "\"/>\n";
  if(!seam_path.empty())
    svg += "<path id=\"seams\" fill=\"none\" stroke=\"#e8112d\" stroke-width=\"1.6\" stroke-linecap=\"round\" d=\"" +
           seam_path + "\"/>\n";

  // Legend: a gradient bar on the same scale, with ticks.
  {
    const int bar_x = margin, bar_y = y0 + layout_h + margin + 26, bar_w = std::min(600, width - 2 * margin),
              bar_h = 16;
    svg += "<g id=\"legend\">\n<defs><linearGradient id=\"viridis\" x1=\"0\" x2=\"1\" y1=\"0\" y2=\"0\">";
    for(int i = 0; i <= 8; ++i)
    {
      std::snprintf(buf, sizeof(buf), "<stop offset=\"%g\" stop-color=\"%s\"/>", i / 8.,
                    hex_color(viridis(i / 8.)).c_str());
      svg += buf;
    }
    svg += "</linearGradient></defs>\n";
    std::snprintf(buf, sizeof(buf), "<text x=\"%d\" y=\"%d\" font-size=\"15\" fill=\"#000000\">", bar_x, bar_y - 8);
    svg += buf;
    svg += "per-triangle E_SD = s1\xc2\xb2 + s2\xc2\xb2 + s1\xe2\x81\xbb\xc2\xb2 + s2\xe2\x81\xbb\xc2\xb2 "
           "(4 = isometric; log scale of E_SD \xe2\x88\x92 4)</text>\n";
    std::snprintf(buf, sizeof(buf),
                  "<rect x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\" fill=\"url(#viridis)\" stroke=\"#000000\" "
                  "stroke-width=\"0.5\"/>\n",
                  bar_x, bar_y, bar_w, bar_h);
    svg += buf;
    const double ticks[] = {4.01, 4.03, 4.1, 4.3, 5, 6, 8};
    for(double t : ticks)
    {
      const double x = bar_x + bar_w * Distortion_scale::position(t);
      std::snprintf(buf, sizeof(buf),
                    "<line x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\" stroke=\"#000000\" stroke-width=\"1\"/>"
                    "<text x=\"%.1f\" y=\"%d\" font-size=\"13\" text-anchor=\"middle\">%s%s</text>\n",
                    x, bar_y + bar_h, x, bar_y + bar_h + 5, x, bar_y + bar_h + 19, t == 4.01 ? "\xe2\x89\xa4" : t == 8 ? "\xe2\x89\xa5" : "",
                    picture_number(t, 3).c_str());
      svg += buf;
    }
    svg += "</g>\n";
  }
  svg += "</svg>\n";
  return write_text_file(path, svg);
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_UV_LAYOUT_SVG_H
