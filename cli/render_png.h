// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// --png: the 3D model with a checkerboard texture through its UV map (so
// that stretch and shear show), Lambert shading, and the seams drawn on the
// surface. A small software rasterizer: perspective camera fitted to the
// model (a 3/4 view, y up), z-buffer, perspective-correct UVs, 3x3
// supersampling; written with libpng.

#ifndef SMSO_CLI_RENDER_PNG_H
#define SMSO_CLI_RENDER_PNG_H

#include "picture_common.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#ifdef SMSO_CLI_HAS_PNG
#include <png.h>
#endif

namespace optimize_seams_cli {

#ifdef SMSO_CLI_HAS_PNG
constexpr bool png_available = true;
#else
constexpr bool png_available = false;
#endif

struct Png_render_options
{
  int width = 600, height = 600;
  int supersampling = 3;                  // samples per pixel along each axis
  double checker_cells = 1600;            // about this many cells cover the whole UV area
};

namespace render_internal {

struct Vec3
{
  double x = 0, y = 0, z = 0;
  Vec3() {}
  Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  double dot(const Vec3& o) const { return x * o.x + y * o.y + z * o.z; }
  Vec3 cross(const Vec3& o) const { return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x}; }
  double norm() const { return std::sqrt(dot(*this)); }
  Vec3 normalized() const { const double n = norm(); return n > 0 ? *this * (1 / n) : *this; }
};

// A point in the supersampled image: pixel coordinates, and w = 1 / depth
// (linear in screen space, so it and attribute / depth interpolate exactly).
struct Screen_point
{
  double x, y, w;
};

#ifdef SMSO_CLI_HAS_PNG
// libpng's classic API (for the compression level); no C++ object lives
// across setjmp.
inline bool write_png_rgb(const char* path, int width, int height, const std::uint8_t* rgb)
{
  std::FILE* fp = std::fopen(path, "wb");
  if(!fp)
    return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if(!png || !info || setjmp(png_jmpbuf(png)))
  {
    png_destroy_write_struct(&png, &info);
    std::fclose(fp);
    return false;
  }
  png_init_io(png, fp);
  png_set_compression_level(png, 9);
  png_set_IHDR(png, info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for(int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(rgb + 3 * std::size_t(width) * y));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return std::fclose(fp) == 0;
}
#endif

} // namespace render_internal

// Renders and writes the PNG. Returns false with `error` set on failure
// (also when the program was built without libpng).
template <typename TriangleMesh, typename UVMap, typename SeamMap>
bool render_png(const std::string& path, const TriangleMesh& mesh, UVMap uvmap, SeamMap seams,
                const Png_render_options& options, std::string& error)
{
  using namespace render_internal;
  if(!png_available)
  {
    error = "cannot write PNG: optimize_seams was built without libpng";
    return false;
  }
  if(num_faces(mesh) == 0)
  {
    error = "cannot render an empty mesh";
    return false;
  }
  const auto vpm = get(CGAL::vertex_point, mesh);
  auto position = [&](typename boost::graph_traits<TriangleMesh>::vertex_descriptor v) {
    const auto& p = get(vpm, v);
    return Vec3(p.x(), p.y(), p.z());
  };

  // Bounding box, and the sphere around its center.
  Vec3 lo(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity());
  Vec3 hi = lo * -1.;
  for(auto v : vertices(mesh))
  {
    const Vec3 p = position(v);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const Vec3 center = (lo + hi) * 0.5;
  double radius = 0;
  for(auto v : vertices(mesh))
    radius = std::max(radius, (position(v) - center).norm());
  if(!(radius > 0) || !std::isfinite(radius))
  {
    error = "cannot render a mesh without extent";
    return false;
  }

  // Camera: y is up (the OBJ convention); a 3/4 view from the front (+z)
  // right and a little above; 30 degree field of view.
  const double pi = 3.14159265358979323846;
  const double azimuth = 35 * pi / 180, elevation = 20 * pi / 180, fov = 30 * pi / 180;
  const Vec3 to_eye(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                    std::cos(azimuth) * std::cos(elevation));
  const double distance = radius / std::sin(fov / 2);
  const Vec3 eye = center + to_eye * distance;
  const Vec3 forward = to_eye * -1.;
  const Vec3 right = forward.cross(Vec3(0, 1, 0)).normalized();
  const Vec3 up = right.cross(forward);

  // Project (x / depth, y / depth), then fit the projected box into the image.
  const int ss = std::max(1, options.supersampling);
  const int W = options.width * ss, H = options.height * ss;
  std::vector<double> cam_x(num_vertices(mesh)), cam_y(num_vertices(mesh)), cam_z(num_vertices(mesh));
  double pmin[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double pmax[2] = {-pmin[0], -pmin[1]};
  for(auto v : vertices(mesh))
  {
    const Vec3 d = position(v) - eye;
    const double z = std::max(d.dot(forward), 1e-9 * distance);
    cam_x[v] = d.dot(right) / z;
    cam_y[v] = d.dot(up) / z;
    cam_z[v] = z;
    pmin[0] = std::min(pmin[0], cam_x[v]); pmax[0] = std::max(pmax[0], cam_x[v]);
    pmin[1] = std::min(pmin[1], cam_y[v]); pmax[1] = std::max(pmax[1], cam_y[v]);
  }
  const double fill = 0.92;
  const double s = fill * std::min(W / std::max(pmax[0] - pmin[0], 1e-12), H / std::max(pmax[1] - pmin[1], 1e-12));
  const double cx = 0.5 * (pmin[0] + pmax[0]), cy = 0.5 * (pmin[1] + pmax[1]);
  auto screen = [&](typename boost::graph_traits<TriangleMesh>::vertex_descriptor v) {
    return Screen_point{W * 0.5 + (cam_x[v] - cx) * s, H * 0.5 - (cam_y[v] - cy) * s, 1 / cam_z[v]};
  };

  // Smooth normals (area-weighted), continuous across seams.
  std::vector<Vec3> normal(num_vertices(mesh));
  for(auto f : faces(mesh))
  {
    const auto c = face_corners(f, mesh);
    const Vec3 p0 = position(target(c[0], mesh)), p1 = position(target(c[1], mesh)),
               p2 = position(target(c[2], mesh));
    const Vec3 n = (p1 - p0).cross(p2 - p0);
    for(auto h : c)
      normal[target(h, mesh)] = normal[target(h, mesh)] + n;
  }
  for(Vec3& n : normal)
    n = n.normalized();

  // Checker cell size from the UV area (scale free: --normalize changes nothing).
  double uv_area = 0;
  for(auto f : faces(mesh))
  {
    const auto c = face_corners(f, mesh);
    const auto q0 = get(uvmap, c[0]), q1 = get(uvmap, c[1]), q2 = get(uvmap, c[2]);
    uv_area += 0.5 * std::abs((q1.x() - q0.x()) * (q2.y() - q0.y()) - (q2.x() - q0.x()) * (q1.y() - q0.y()));
  }
  const double cell = std::sqrt(std::max(uv_area, 1e-300) / std::max(1., options.checker_cells));

  // Light from the upper left of the viewer.
  const Vec3 light = (right * -0.45 + up * 0.6 + to_eye).normalized();
  const double light_rgb[2][3] = {{238, 232, 220}, {58, 104, 178}};   // checker: warm white, blue
  const std::array<double, 3> background = {255, 255, 255};

  std::vector<float> depth(std::size_t(W) * H, 0.f);   // w = 1 / depth; 0 is "nothing"
  std::vector<float> color(std::size_t(W) * H * 3);
  for(std::size_t i = 0; i < depth.size(); ++i)
    for(int k = 0; k < 3; ++k)
      color[3 * i + k] = static_cast<float>(background[k]);

  for(auto f : faces(mesh))
  {
    const auto c = face_corners(f, mesh);
    Screen_point sp[3];
    double uw[3], vw[3];
    Vec3 nw[3];
    for(int i = 0; i < 3; ++i)
    {
      const auto v = target(c[i], mesh);
      sp[i] = screen(v);
      const auto q = get(uvmap, c[i]);
      uw[i] = q.x() * sp[i].w;
      vw[i] = q.y() * sp[i].w;
      nw[i] = normal[v] * sp[i].w;
    }
    // Two-sided: the inside of an open surface is lit like its outside.
    const Vec3 p0 = position(target(c[0], mesh));
    const Vec3 face_normal = (position(target(c[1], mesh)) - p0).cross(position(target(c[2], mesh)) - p0);
    const bool back_facing = face_normal.dot(p0 - eye) > 0;
    const double area = (sp[1].x - sp[0].x) * (sp[2].y - sp[0].y) - (sp[2].x - sp[0].x) * (sp[1].y - sp[0].y);
    if(!(std::abs(area) > 1e-12))
      continue;
    const int x_min = std::max(0, static_cast<int>(std::floor(std::min({sp[0].x, sp[1].x, sp[2].x}))));
    const int x_max = std::min(W - 1, static_cast<int>(std::ceil(std::max({sp[0].x, sp[1].x, sp[2].x}))));
    const int y_min = std::max(0, static_cast<int>(std::floor(std::min({sp[0].y, sp[1].y, sp[2].y}))));
    const int y_max = std::min(H - 1, static_cast<int>(std::ceil(std::max({sp[0].y, sp[1].y, sp[2].y}))));
    for(int y = y_min; y <= y_max; ++y)
      for(int x = x_min; x <= x_max; ++x)
      {
        const double X = x + 0.5, Y = y + 0.5;
        // Barycentric coordinates from edge functions (either orientation).
        const double b0 = ((sp[1].x - X) * (sp[2].y - Y) - (sp[2].x - X) * (sp[1].y - Y)) / area;
        const double b1 = ((sp[2].x - X) * (sp[0].y - Y) - (sp[0].x - X) * (sp[2].y - Y)) / area;
        const double b2 = 1 - b0 - b1;
        if(b0 < 0 || b1 < 0 || b2 < 0)
          continue;
        const double w = b0 * sp[0].w + b1 * sp[1].w + b2 * sp[2].w;
        const std::size_t pix = std::size_t(y) * W + x;
        if(!(w > depth[pix]))
          continue;
        depth[pix] = static_cast<float>(w);
        const double u = (b0 * uw[0] + b1 * uw[1] + b2 * uw[2]) / w;
        const double v = (b0 * vw[0] + b1 * vw[1] + b2 * vw[2]) / w;
        Vec3 n = ((nw[0] * b0 + nw[1] * b1 + nw[2] * b2) * (1 / w)).normalized();
        if(back_facing)
          n = n * -1.;
        const double shade = 0.28 + 0.72 * std::max(0., n.dot(light));
        const int parity = static_cast<int>((static_cast<long long>(std::floor(u / cell)) +
                                             static_cast<long long>(std::floor(v / cell))) & 1);
        for(int k = 0; k < 3; ++k)
          color[3 * pix + k] = static_cast<float>(light_rgb[parity][k] * shade);
      }
  }

  // Seams (and the input's boundary) drawn over the surface where they are
  // not hidden: each edge is sampled in screen space, and a disk is stamped
  // at every sample on the pixels whose surface is not in front of it.
  const double tolerance = 0.01 * radius;   // in depth: the edge lies on the surface it is tested against
  const double line_radius = 1.4 * ss;
  const std::array<float, 3> seam_rgb = {230, 20, 40}, boundary_rgb = {20, 20, 20};
  for(auto e : edges(mesh))
  {
    const Edge_kind kind = edge_kind(e, mesh, seams);
    if(kind == Edge_kind::INTERIOR)
      continue;
    const auto& rgb = kind == Edge_kind::SEAM ? seam_rgb : boundary_rgb;
    const auto h = halfedge(e, mesh);
    const Screen_point a = screen(source(h, mesh)), b = screen(target(h, mesh));
    const double length = std::hypot(b.x - a.x, b.y - a.y);
    const int steps = std::max(1, static_cast<int>(std::ceil(length / (0.5 * ss))));
    const int r = static_cast<int>(std::ceil(line_radius));
    for(int i = 0; i <= steps; ++i)
    {
      const double t = double(i) / steps;
      const double X = a.x + t * (b.x - a.x), Y = a.y + t * (b.y - a.y);
      const double w = a.w + t * (b.w - a.w);
      const double z = 1 / w;
      for(int dy = -r; dy <= r; ++dy)
        for(int dx = -r; dx <= r; ++dx)
        {
          const int x = static_cast<int>(std::floor(X)) + dx, y = static_cast<int>(std::floor(Y)) + dy;
          if(x < 0 || y < 0 || x >= W || y >= H)
            continue;
          if(std::hypot(x + 0.5 - X, y + 0.5 - Y) > line_radius)
            continue;
          const std::size_t pix = std::size_t(y) * W + x;
          // Only on the surface (not the background), and hidden where the
          // surface at that pixel is in front by more than the tolerance.
          if(depth[pix] == 0 || 1 / double(depth[pix]) < z - tolerance)
            continue;
          for(int k = 0; k < 3; ++k)
            color[3 * pix + k] = rgb[k];
        }
    }
  }

  // Box filter down to the output size.
  std::vector<std::uint8_t> image(std::size_t(options.width) * options.height * 3);
  for(int y = 0; y < options.height; ++y)
    for(int x = 0; x < options.width; ++x)
      for(int k = 0; k < 3; ++k)
      {
        double sum = 0;
        for(int j = 0; j < ss; ++j)
          for(int i = 0; i < ss; ++i)
            sum += color[3 * ((std::size_t(y) * ss + j) * W + std::size_t(x) * ss + i) + k];
        image[3 * (std::size_t(y) * options.width + x) + k] =
          static_cast<std::uint8_t>(std::min(255., std::max(0., std::round(sum / (ss * ss)))));
      }

#ifdef SMSO_CLI_HAS_PNG
  if(!write_png_rgb(path.c_str(), options.width, options.height, image.data()))
  {
    error = "cannot write '" + path + "'";
    return false;
  }
  return true;
#else
  (void)path;
  return false;
#endif
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_RENDER_PNG_H
