// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Polyhedron_3 with UV and seam maps kept outside the mesh, in associative
// containers, on a disk and on a closed sphere (opened by a two-edge slit).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>

#include <boost/property_map/property_map.hpp>

#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <unordered_map>

typedef CGAL::Exact_predicates_inexact_constructions_kernel   Kernel;
typedef Kernel::Point_2                                       Point_2;
typedef CGAL::Polyhedron_3<Kernel>                            Polyhedron;
typedef boost::graph_traits<Polyhedron>::halfedge_descriptor  halfedge_descriptor;
typedef boost::graph_traits<Polyhedron>::edge_descriptor      edge_descriptor;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;

// Returns false unless the map is valid: a smoke test must fail when the library breaks.
bool parameterize(const std::string& filename)
{
  Polyhedron mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh))
  {
    std::cerr << "Cannot read a mesh from " << filename << std::endl;
    return false;
  }

  // Any associative container works. std::map needs operator<, which
  // halfedge handles have; edge descriptors of Polyhedron_3 only hash
  // consistently (both halfedges of an edge give one key), hence unordered_map.
  std::map<halfedge_descriptor, Point_2> uv_storage;
  std::unordered_map<edge_descriptor, bool> seam_storage;
  for(edge_descriptor e : edges(mesh))
    seam_storage[e] = false;
  boost::associative_property_map<std::map<halfedge_descriptor, Point_2> > uvmap(uv_storage);
  boost::associative_property_map<std::unordered_map<edge_descriptor, bool> > seams(seam_storage);

  SMSO::Optimization_result r =
    SMSO::minimize_distortion(mesh, uvmap, SMSO::parameters::edge_is_seam_map(seams));
  if(!r.has_result())
  {
    std::cerr << filename << ": " << SMSO::get_error_message(r.status) << ": " << r.message << std::endl;
    return false;
  }

  std::size_t seam_edges = 0;
  for(edge_descriptor e : edges(mesh))
    if(get(seams, e)) ++seam_edges;
  const std::size_t flipped = SMSO::number_of_flipped_triangles(mesh, uvmap);
  std::cout << filename.substr(filename.find_last_of("/\\") + 1) << ": " << num_faces(mesh)
            << " faces, " << seam_edges << " seam edges, E_SD " << r.distortion << " in "
            << r.iterations << " iterations, " << flipped << " flipped triangles" << std::endl;
  return flipped == 0 && r.distortion >= 4;
}

int main(int argc, char** argv)
{
  if(argc > 1)
    return parameterize(argv[1]) ? EXIT_SUCCESS : EXIT_FAILURE;
  // A disk needs no seam; the closed sphere is opened by a slit of two edges,
  // which minimize_distortion() writes into the seam map.
  const bool disk = parameterize(SMSO_DATA_DIR "/cat_f1500.obj");
  const bool sphere = parameterize(SMSO_DATA_DIR "/sphere_f1522.obj");
  return (disk && sphere) ? EXIT_SUCCESS : EXIT_FAILURE;
}
