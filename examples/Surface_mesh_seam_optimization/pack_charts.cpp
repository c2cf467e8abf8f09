// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Two models in one texture: their seams and UV maps are optimized together
// (each connected component gets its own charts), then pack_charts() lays
// all charts out in [0,1]^2 without overlap, one scale factor for all, with a
// margin of 4 texels in a 1024 x 1024 texture.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>
#include <CGAL/Surface_mesh_seam_optimization/pack_charts.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>          Kernel;
typedef Kernel::Point_2                         Point_2;
typedef CGAL::Surface_mesh<Kernel::Point_3>     Mesh;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace NP = CGAL::Surface_mesh_seam_optimization::parameters;

int main(int argc, char** argv)
{
  const std::string first = (argc > 1) ? argv[1] : SMSO_DATA_DIR "/cat_f1500.obj";
  const std::string second = (argc > 2) ? argv[2] : SMSO_DATA_DIR "/bishop_part_f1000.obj";
  Mesh mesh, other;
  if(!CGAL::IO::read_polygon_mesh(first, mesh) || !CGAL::IO::read_polygon_mesh(second, other))
  {
    std::cerr << "Cannot read " << first << " and " << second << std::endl;
    return EXIT_FAILURE;
  }
  mesh += other;   // one mesh, two connected components
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;

  const SMSO::Optimization_result r = SMSO::optimize_seams(mesh, uvmap, NP::number_of_recut_rounds(0));
  if(!r.has_result())
  {
    std::cerr << SMSO::get_error_message(r.status) << ": " << r.message << std::endl;
    return EXIT_FAILURE;
  }
  const double e_sd = SMSO::distortion(mesh, uvmap);

  const double texture_size = 1024, margin = 4;
  const SMSO::Chart_packing_result p =
    SMSO::pack_charts(mesh, uvmap, NP::texture_size(texture_size).margin(margin));
  if(!p.has_result())
  {
    std::cerr << SMSO::get_error_message(p.status) << ": " << p.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << p.charts << " charts packed in a " << texture_size << " texel square: fill rate " << p.fill_rate
            << ", " << p.texels_per_unit_length << " texels per unit length" << std::endl;

  // All UVs at least `margin` texels inside the square, no overlap, and the
  // same E_SD once the common factor is undone (a rigid motion per chart).
  double lo = 1, hi = 0;
  for(Mesh::Halfedge_index h : halfedges(mesh))
  {
    if(is_border(h, mesh)) continue;
    const Point_2 q = get(uvmap, h);
    lo = (std::min)(lo, (std::min)(q.x(), q.y()));
    hi = (std::max)(hi, (std::max)(q.x(), q.y()));
  }
  auto unscaled = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:unscaled").first;
  for(Mesh::Halfedge_index h : halfedges(mesh))
    put(unscaled, h, Point_2(get(uvmap, h).x() / p.scale, get(uvmap, h).y() / p.scale));
  const double e_sd_unscaled = SMSO::distortion(mesh, unscaled);
  std::cout << "UVs in [" << lo << ", " << hi << "], E_SD " << e_sd << " before, " << e_sd_unscaled
            << " after packing (at the same scale)" << std::endl;
  const bool ok = p.charts == r.charts && p.charts >= 2 && lo >= margin / texture_size - 1e-12 &&
                  hi <= 1 - margin / texture_size + 1e-12 &&
                  SMSO::number_of_overlapping_triangle_pairs(mesh, uvmap) == 0 &&
                  std::abs(e_sd_unscaled - e_sd) <= 1e-9 * e_sd;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
