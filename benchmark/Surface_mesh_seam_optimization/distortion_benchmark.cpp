// Times the distortion-only solve (seams fixed) on disk meshes and prints
// iterations, seconds per iteration and E_SD beside the paper's code.
// Usage: distortion_benchmark [repeats] [mesh.obj ...]   (default: 3, bimba and bunny)
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/initial_parameterization.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace SMSO_np = CGAL::Surface_mesh_seam_optimization::parameters;

struct Reference { const char* name; double e_sd; int iterations; double seconds; };
// The paper's code, distortion-only mode, on this kind of machine (issue 2).
const Reference references[] = { { "bimba_i_f10000", 7.644, 79, 5.1 }, { "bunny_i_f10000", 7.512, 297, 18.7 } };

static double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

int main(int argc, char** argv)
{
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  std::vector<std::string> files;
  for(int i = 2; i < argc; ++i) files.push_back(argv[i]);
  if(files.empty())
    files = { std::string(SMSO_DATA_DIR) + "/bimba_i_f10000.obj", std::string(SMSO_DATA_DIR) + "/bunny_i_f10000.obj" };

  std::printf("| mesh | faces | E_SD | E_SD ref | iterations | iterations ref | solve s (median of %d) | s/iteration | total s | ref s | speed-up |\n", repeats);
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const std::string& file : files)
  {
    Surface_mesh sm;
    if(!CGAL::IO::read_polygon_mesh(file, sm)) { std::cerr << "cannot read " << file << "\n"; return EXIT_FAILURE; }
    std::string name = file.substr(file.find_last_of('/') + 1);
    name = name.substr(0, name.find_last_of('.'));
    auto uv = sm.add_property_map<Surface_mesh::Halfedge_index, K::Point_2>("h:uv").first;
    auto initial = sm.add_property_map<Surface_mesh::Halfedge_index, K::Point_2>("h:initial").first;
    auto seams = sm.add_property_map<Surface_mesh::Edge_index, bool>("e:seam", false).first;

    std::vector<double> solve, total;
    SMSO::Optimization_result r;
    for(int k = 0; k < repeats; ++k)
    {
      // total: initial map (circle + Tutte through CGAL) + solve
      r = SMSO::minimize_distortion(sm, uv, SMSO_np::edge_is_seam_map(seams));
      if(r.status != SMSO::OK) { std::cerr << name << ": " << SMSO::get_error_message(r.status) << "\n"; return EXIT_FAILURE; }
      total.push_back(r.seconds);
      // solve only: from the same initial map
      if(SMSO::compute_initial_parameterization(sm, seams, initial) != SMSO::OK) return EXIT_FAILURE;
      r = SMSO::minimize_distortion(sm, initial, SMSO_np::combine(SMSO_np::use_uv_map_as_initial(true),
                                                                  SMSO_np::edge_is_seam_map(seams)));
      solve.push_back(r.seconds);
    }
    const std::size_t flips = SMSO::number_of_flipped_triangles(sm, initial);
    const Reference* ref = nullptr;
    for(const Reference& x : references) if(name == x.name) ref = &x;
    const double s = median(solve);
    std::printf("| %s | %zu | %.5f | %s | %zu | %s | %.3f | %.4f | %.3f | %s | %s |\n", name.c_str(), sm.number_of_faces(),
                r.distortion, ref ? std::to_string(ref->e_sd).substr(0, 5).c_str() : "-", r.iterations,
                ref ? std::to_string(ref->iterations).c_str() : "-", s, s / double(std::max<std::size_t>(1, r.iterations)),
                median(total), ref ? std::to_string(ref->seconds).substr(0, 4).c_str() : "-",
                ref ? (std::to_string(ref->seconds / median(total)).substr(0, 5) + "x").c_str() : "-");
    if(flips != 0) { std::cerr << name << ": " << flips << " flipped triangles\n"; return EXIT_FAILURE; }
  }
  return EXIT_SUCCESS;
}
