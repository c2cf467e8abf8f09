// first-cut prototype: minimize the distortion of the uncut mesh, cut the
// shortest path from its vertex of largest distortion to the border (as
// EBCuts' first cut), then optimize_seams from the initial map of that cut.
// Usage: first_cut IN OUT.obj ; prints: mesh,seconds,iterations,E_se,E_SD,bound_met,status,cut
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>
#include <CGAL/Surface_mesh_seam_optimization/initial_parameterization.h>
#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Extremity_cuts.h>
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
  CGAL::Real_timer t; t.start();
  bool has_border = false;
  for(auto h : sm.halfedges()) if(sm.is_border(h)) { has_border = true; break; }
  bool cut = false;
  if(has_border)
  {
    auto r0 = SMSO::minimize_distortion(sm, uv, SMSO::parameters::edge_is_seam_map(seam));
    if(r0.has_result())
    {
      const SMSO::Symmetric_Dirichlet_energy energy;
      auto vpm = get(CGAL::vertex_point, sm);
      auto density = [&](SM::Face_index f) {
        const auto h0 = sm.halfedge(f), h1 = sm.next(h0), h2 = sm.next(h1);
        const auto q0 = sm.point(sm.target(h0)), q1 = sm.point(sm.target(h1)), q2 = sm.point(sm.target(h2));
        const auto p0 = uv[h0], p1 = uv[h1], p2 = uv[h2];
        const auto e1 = q1 - q0, e2 = q2 - q0;
        const double l1 = std::sqrt(e1.squared_length());
        const double x2 = (e1 * e2) / l1;
        const double y2 = std::sqrt((std::max)(0., e2.squared_length() - x2 * x2));
        Eigen::Matrix2d J;
        J(0, 0) = (p1.x() - p0.x()) / l1; J(1, 0) = (p1.y() - p0.y()) / l1;
        J(0, 1) = (p2.x() - p0.x() - J(0, 0) * x2) / y2; J(1, 1) = (p2.y() - p0.y() - J(1, 0) * x2) / y2;
        return std::make_pair(0.5 * l1 * y2, energy.value(J));
      };
      if(!r0.bound_met) cut = SMSO::internal::cut_from_the_worst_vertex(sm, vpm, seam, density);
    }
  }
  int ncut = 0; for(auto e : sm.edges()) if(seam[e]) ++ncut;
  auto uv2 = sm.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv2").first;
  SMSO::Optimization_result r;
  if(cut)
  {
    auto s = SMSO::compute_initial_parameterization(sm, seam, uv2);
    r = SMSO::optimize_seams(sm, uv2, SMSO::parameters::use_uv_map_as_initial(true).edge_is_seam_map(seam));
  }
  else
    r = SMSO::optimize_seams(sm, uv2, SMSO::parameters::edge_is_seam_map(seam));
  std::cout << argv[1] << "," << t.time() << "," << r.iterations << "," << r.seam_length_normalized << "," << r.distortion
            << "," << r.bound_met << "," << r.status << "," << ncut << "\n";
  write(sm, uv2, argv[2]);
}
