// free run, then cut the overlapping charts apart (keeping every corner's UV)
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Initialize_cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Split_self_overlapping_charts.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Chart_layout.h>
#include <CGAL/Real_timer.h>
#include <fstream>
#include <iostream>
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace I = CGAL::Surface_mesh_seam_optimization::internal;
void write(const SM& sm, SM::Property_map<SM::Halfedge_index, K::Point_2> uv, const char* path)
{
  std::ofstream o(path); o.precision(17);
  for(auto v : sm.vertices()) o << "v " << sm.point(v) << "\n";
  std::vector<int> idx(sm.number_of_halfedges()); int k = 1;
  for(auto h : sm.halfedges()) if(!sm.is_border(h)) { o << "vt " << uv[h].x() << " " << uv[h].y() << "\n"; idx[h.idx()] = k++; }
  for(auto f : sm.faces()) { o << "f"; for(auto h : CGAL::halfedges_around_face(sm.halfedge(f), sm)) o << " " << sm.target(h).idx()+1 << "/" << idx[h.idx()]; o << "\n"; }
}
int main(int argc, char** argv)
{
  SM sm; CGAL::IO::read_polygon_mesh(argv[1], sm);
  auto uv = sm.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;
  auto seam = sm.add_property_map<SM::Edge_index, bool>("e:seam", false).first;
  const int starts = std::getenv("FB_STARTS") ? std::atoi(std::getenv("FB_STARTS")) : 1;
  CGAL::Real_timer t; t.start();
  auto r1 = SMSO::optimize_seams(sm, uv, SMSO::parameters::bijective(false).edge_is_seam_map(seam).number_of_starts(starts));
  const double t1 = t.time();
  std::cerr << "free: " << r1.status << " E_se " << r1.seam_length_normalized << " E_SD " << r1.distortion << " it " << r1.iterations << " " << t1 << " s\n";
  I::Cut_mesh cm; I::Face_graph_copy<SM> copy; std::string msg;
  auto ec = I::initialize_cut_mesh(sm, uv, SMSO::parameters::use_uv_map_as_initial(true), cm, copy, msg);
  const double R = cm.normalization_radius();
  std::cerr << "cm: " << ec << " " << msg << " seams " << cm.seam_length() / R << " overlaps " << I::count_overlapping_pairs(cm) << "\n";
  // the library's minimum cut (landed 2026-11-29 from this driver's first version), until nothing overlaps
  int rounds = 0;
  while(I::count_overlapping_pairs(cm, 1) > 0 && rounds < 200)
  {
    std::size_t n = I::split_self_overlapping_charts(cm);
    I::lay_out_uv_components(cm);
    ++rounds;
    std::cerr << "round " << rounds << " cuts " << n << " seams " << cm.seam_length() / R << " overlaps " << I::count_overlapping_pairs(cm) << "\n";
    if(n == 0) break;
  }
  std::vector<int> ch; std::size_t nch = cm.compute_charts(ch);
  std::cerr << "split: seams " << cm.seam_length() / R << " charts " << nch << " rounds " << rounds << "\n";
  I::write_uv_map(cm, copy, uv);
  write(sm, uv, argv[2]);
  if(argc > 3)
  {
    auto r2 = SMSO::optimize_seams(sm, uv, SMSO::parameters::use_uv_map_as_initial(true).number_of_starts(1));
    std::cerr << "bij: " << r2.status << " " << r2.message << " E_se " << r2.seam_length_normalized << " E_SD " << r2.distortion << " it " << r2.iterations << " total " << t.time() << " s (second " << t.time() - t1 << ")\n";
    write(sm, uv, argv[3]);
  }
}
