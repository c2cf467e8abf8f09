// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Starts the distortion minimization from a map computed by a parameterizer
// of Surface_mesh_parameterization (ARAP_parameterizer_3) on a Seam_mesh.
// Such a map usually has a few flipped triangles: they are untangled first.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>
#include <CGAL/Surface_mesh_seam_optimization/seam_mesh.h>

#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>          Kernel;
typedef Kernel::Point_2                         Point_2;
typedef CGAL::Surface_mesh<Kernel::Point_3>     Mesh;
typedef Mesh::Halfedge_index                    halfedge_descriptor;
typedef Mesh::Edge_index                        edge_descriptor;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;

typedef SMSO::Seam_mesh_maker<Mesh>::Seam_mesh  Seam_mesh;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : SMSO_DATA_DIR "/cat_f1500.obj";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh))
  {
    std::cerr << "Cannot read a mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // The seams cut the mesh into the disk the parameterizer needs: none for
  // this mesh, which is a disk already; set them here for another mesh.
  auto seams = mesh.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  SMSO::Seam_mesh_maker<Mesh> maker(mesh, seams);
  Seam_mesh& smesh = maker.seam_mesh();

  // Seam_mesh UVs are keyed by the underlying halfedges (one per seam-mesh vertex).
  auto seam_uvmap = mesh.add_property_map<halfedge_descriptor, Point_2>("h:seam_uv").first;
  const auto bhd = maker.border_halfedge(*faces(mesh).begin());
  SMP::ARAP_parameterizer_3<Seam_mesh> parameterizer;
  if(bhd == boost::graph_traits<Seam_mesh>::null_halfedge() ||
     SMP::parameterize(smesh, parameterizer, bhd, seam_uvmap) != SMP::OK)
  {
    std::cerr << "ARAP parameterization failed (the chart must be a disk)" << std::endl;
    return EXIT_FAILURE;
  }

  // One UV per face corner, the package's convention.
  auto uvmap = mesh.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  SMSO::seam_mesh_uv_map_to_corner_uv_map(smesh, seam_uvmap, uvmap);

  const std::size_t flipped_before = SMSO::number_of_flipped_triangles(mesh, uvmap);

  // The map is validated, untangled where it folds (the message says so),
  // rescaled to the 3D size, and its distortion minimized with the same seams.
  SMSO::Optimization_result r = SMSO::minimize_distortion(
    mesh, uvmap,
    SMSO::parameters::use_uv_map_as_initial(true).edge_is_seam_map(seams));
  if(!r.has_result())
  {
    std::cerr << SMSO::get_error_message(r.status) << ": " << r.message << std::endl;
    return EXIT_FAILURE;
  }
  const std::size_t flipped = SMSO::number_of_flipped_triangles(mesh, uvmap);
  std::cout << "ARAP parameterizer: " << flipped_before << " flipped triangles; " << r.message << "\n"
            << "E_SD of the initial map (scaled): " << r.initial_distortion << "\n"
            << "E_SD after minimize_distortion: " << r.distortion << " in " << r.iterations
            << " iterations, " << flipped << " flipped triangles" << std::endl;
  return (flipped == 0 && r.distortion < r.initial_distortion) ? EXIT_SUCCESS : EXIT_FAILURE;
}
