// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Regional seam preferences: a painted region of vertices where seams are
// unwanted gets a seam cost of 1000 (region_seam_costs(); the OptCuts paper
// uses 100, which near the bound the dual step's seam price can exceed),
// passed as vertex_seam_cost_map; the seams leave the region while
// the distortion bound still holds.
//
//   regional_seams [MESH SELECTED [COST]]
//
// SELECTED lists 0-based vertex indices of MESH (the OptCuts benchmark's
// NAME_selected.txt); without it, the region is where the plain run put its
// seams, so that the second run must find other ones. A COST below 1 draws
// seams into the region instead.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>
#include <CGAL/Surface_mesh_seam_optimization/seam_costs.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double>          Kernel;
typedef Kernel::Point_2                         Point_2;
typedef CGAL::Surface_mesh<Kernel::Point_3>     Mesh;
typedef Mesh::Vertex_index                      vertex_descriptor;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace NP = CGAL::Surface_mesh_seam_optimization::parameters;

// 3D length of the seam edges with both ends in the region
double length_inside(const Mesh& mesh, Mesh::Property_map<Mesh::Edge_index, bool> seams,
                     const std::set<vertex_descriptor>& region)
{
  double l = 0;
  for(Mesh::Edge_index e : edges(mesh))
    if(seams[e] && region.count(mesh.vertex(e, 0)) && region.count(mesh.vertex(e, 1)))
      l += std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)), mesh.point(mesh.vertex(e, 1))));
  return l;
}

int main(int argc, char** argv)
{
  const std::string filename = (argc > 1) ? argv[1] : SMSO_DATA_DIR "/cat_f1500.obj";
  const double cost = (argc > 3) ? std::atof(argv[3]) : 1000.;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh) || is_empty(mesh))
  {
    std::cerr << "Cannot read a mesh from " << filename << std::endl;
    return EXIT_FAILURE;
  }
  auto uvmap = mesh.add_property_map<Mesh::Halfedge_index, Point_2>("h:uv").first;
  auto seams = mesh.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;

  const SMSO::Optimization_result plain = SMSO::optimize_seams(mesh, uvmap, NP::edge_is_seam_map(seams));
  if(!plain.has_result())
  {
    std::cerr << SMSO::get_error_message(plain.status) << ": " << plain.message << std::endl;
    return EXIT_FAILURE;
  }

  std::set<vertex_descriptor> region;
  if(argc > 2)
  {
    // read_polygon_mesh() keeps the file's vertex order for an OBJ without unused vertices
    std::ifstream in(argv[2]);
    for(std::size_t i; in >> i;)
      if(i < num_vertices(mesh)) region.insert(vertex_descriptor(Mesh::size_type(i)));
  }
  else
    for(Mesh::Edge_index e : edges(mesh))
      if(seams[e])
      {
        region.insert(mesh.vertex(e, 0));
        region.insert(mesh.vertex(e, 1));
      }
  const double plain_inside = length_inside(mesh, seams, region);

  // edge_is_seam_map also gives initial seams: start the second run afresh, as the first
  for(Mesh::Edge_index e : edges(mesh)) seams[e] = false;
  auto vertex_cost = mesh.add_property_map<vertex_descriptor, double>("v:seam_cost", 1.).first;
  SMSO::region_seam_costs(mesh, region, cost, vertex_cost);
  const SMSO::Optimization_result r =
    SMSO::optimize_seams(mesh, uvmap, NP::edge_is_seam_map(seams).vertex_seam_cost_map(vertex_cost));
  if(!r.has_result())
  {
    std::cerr << SMSO::get_error_message(r.status) << ": " << r.message << std::endl;
    return EXIT_FAILURE;
  }
  const double inside = length_inside(mesh, seams, region);
  std::cout << region.size() << " region vertices, seam cost " << cost << " there\n"
            << "plain:    E_SD " << plain.distortion << ", E_se " << plain.seam_length_normalized
            << ", seam length in the region " << plain_inside << "\n"
            << "weighted: E_SD " << r.distortion << ", E_se " << r.seam_length_normalized << " (weighted "
            << r.weighted_seam_length_normalized << "), seam length in the region " << inside << std::endl;

  // a repelling cost must at least halve the seams in the region, within the bound
  const bool ok = r.bound_met && r.bijective && (cost <= 1 || inside <= 0.5 * plain_inside);
  if(!ok) std::cerr << "Unexpected result" << std::endl;
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
