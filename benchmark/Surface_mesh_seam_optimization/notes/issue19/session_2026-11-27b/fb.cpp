// free-then-bijective prototype: optimize_seams without a scaffold, then a
// bijective run from the initial map of those seams; keeps the better of it
// and (optionally) the default bijective run.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>
#include <CGAL/Surface_mesh_seam_optimization/initial_parameterization.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Real_timer.h>
#include <fstream>
#include <iostream>
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;
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
  const int starts = std::getenv("FB_STARTS") ? std::atoi(std::getenv("FB_STARTS")) : 2;
  CGAL::Real_timer t; t.start();
  auto r1 = SMSO::optimize_seams(sm, uv, SMSO::parameters::bijective(false).edge_is_seam_map(seam).number_of_starts(starts));
  const double t1 = t.time();
  std::cerr << "free: " << r1.status << " " << r1.message << " E_se " << r1.seam_length_normalized << " it " << r1.iterations << " " << t1 << " s\n";
  if(argc > 3) write(sm, uv, argv[3]);
  auto uv2 = sm.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv2").first;
  auto s = SMSO::compute_initial_parameterization(sm, seam, uv2);
  std::cerr << "initial: " << s << "\n";
  auto r2 = SMSO::optimize_seams(sm, uv2, SMSO::parameters::use_uv_map_as_initial(true).edge_is_seam_map(seam).number_of_starts(starts));
  std::cerr << "bij: " << r2.status << " " << r2.message << " E_se " << r2.seam_length_normalized << " it " << r2.iterations << " total " << t.time() << " s (second " << t.time() - t1 << ")\n";
  std::cout << r1.iterations + r2.iterations << " " << t.time() << "\n";
  write(sm, uv2, argv[2]);
}
