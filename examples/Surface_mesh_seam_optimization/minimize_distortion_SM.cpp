// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Minimal use: minimize the symmetric Dirichlet distortion of the UV map of a
// disk-topology Surface_mesh (seams fixed), then write it as OBJ with UVs.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/IO/OBJ.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>

#include <cstdlib>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>          Kernel;
typedef Kernel::Point_2                         Point_2;
typedef CGAL::Surface_mesh<Kernel::Point_3>     Mesh;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : SMSO_DATA_DIR "/bimba_i_f10000.obj";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh))
  {
    std::cerr << "Cannot read a mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }

  // One UV per face corner: get(uvmap, h) is the UV of target(h) in face(h).
  Mesh::Property_map<Mesh::Halfedge_index, Point_2> uvmap =
    mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;
  // Seams are fixed by minimize_distortion(); a disk needs none, a closed
  // genus-0 mesh gets a slit, and the map tells which edges ended up as seams.
  Mesh::Property_map<Mesh::Edge_index, bool> seams =
    mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;

  SMSO::Optimization_result r =
    SMSO::minimize_distortion(mesh, uvmap, SMSO::parameters::edge_is_seam_map(seams));
  if(!r.has_result())
  {
    std::cerr << SMSO::get_error_message(r.status) << ": " << r.message << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << num_faces(mesh) << " faces: E_SD " << r.initial_distortion << " (initial map) -> "
            << r.distortion << " in " << r.iterations << " Newton iterations, "
            << r.seconds << " s" << std::endl;

  // The descent never flips a triangle; a smoke test checks it anyway.
  const std::size_t flipped = SMSO::number_of_flipped_triangles(mesh, uvmap);
  if(flipped != 0 || !(r.distortion >= 4))
  {
    std::cerr << "Invalid result: " << flipped << " flipped triangles" << std::endl;
    return EXIT_FAILURE;
  }
  if(r.status != SMSO::OK)
    std::cout << "Warning: " << SMSO::get_error_message(r.status) << std::endl;

  const std::string out = "minimize_distortion_SM.obj";
  if(!SMSO::IO::write_OBJ_with_uv_map(out, mesh, uvmap))
  {
    std::cerr << "Cannot write " << out << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "UV map written to " << out << std::endl;
  return EXIT_SUCCESS;
}
