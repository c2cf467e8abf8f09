// free run, then cut the overlapping charts apart (keeping every corner's UV)
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Initialize_cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Split_self_overlapping_charts.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Chart_layout.h>
#include <CGAL/Real_timer.h>
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <numeric>
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
// Cuts each self-overlapping chart along the shortest edge set (3D length)
// that separates the two overlapping layers with most pairs between them.
std::size_t min_cut_split(I::Cut_mesh& cm)
{
  using namespace boost;
  std::vector<int> chart;
  const std::size_t n = cm.compute_charts(chart);
  std::vector<std::vector<int> > faces(n);
  for(std::size_t f = 0; f < chart.size(); ++f) faces[chart[f]].push_back(int(f));
  const std::size_t nf = cm.number_of_faces();
  std::vector<char> cut(cm.corner_vertex.size(), 0);
  std::vector<int> local(nf, -1), patch(nf, -1);
  std::size_t split = 0;
  for(std::size_t k = 0; k < n; ++k)
  {
    const std::vector<int>& fk = faces[k];
    if(fk.size() < 2) continue;
    std::vector<int> tri;
    for(int f : fk) for(int i = 0; i < 3; ++i) tri.push_back(cm.corner_uv[3*f + i]);
    std::vector<std::pair<int,int> > pairs;
    if(I::count_overlapping_pairs(tri, cm.uv.data(), std::size_t(-1), 1e-9, nullptr, &pairs) == 0) continue;
    for(std::size_t i = 0; i < fk.size(); ++i) local[fk[i]] = int(i);
    // patches: involved faces joined across the chart's interior edges
    std::vector<char> involved(fk.size(), 0);
    for(auto& p : pairs) { involved[p.first] = 1; involved[p.second] = 1; }
    std::vector<int> pl(fk.size(), -1);
    int np = 0;
    for(std::size_t s = 0; s < fk.size(); ++s)
    {
      if(!involved[s] || pl[s] >= 0) continue;
      std::vector<int> st{ int(s) }; pl[s] = np;
      while(!st.empty())
      {
        int a = st.back(); st.pop_back();
        int f = fk[a];
        for(int i = 0; i < 3; ++i)
        {
          int h = 3*f+i, o = cm.opposite[h];
          if(o < 0 || cm.is_seam(h)) continue;
          int b = local[o/3];
          if(involved[b] && pl[b] < 0) { pl[b] = np; st.push_back(b); }
        }
      }
      ++np;
    }
    std::map<std::pair<int,int>, int> conflicts;
    for(auto& p : pairs)
    {
      int a = pl[p.first], b = pl[p.second];
      if(a > b) std::swap(a, b);
      ++conflicts[{a, b}];
    }
    std::pair<int,int> best(-1,-1); int bc = 0;
    for(auto& c : conflicts) if(c.first.first != c.first.second && c.second > bc) { bc = c.second; best = c.first; }
    std::vector<char> src(fk.size(), 0), snk(fk.size(), 0);
    if(best.first < 0)
    {
      src[pairs[0].first] = 1; snk[pairs[0].second] = 1;
      std::cerr << "  self-patch\n";
    }
    else
      for(std::size_t i = 0; i < fk.size(); ++i) { src[i] = pl[i] == best.first; snk[i] = pl[i] == best.second; }
    const std::size_t bestsize = 2 * std::size_t(bc);
    typedef adjacency_list_traits<vecS, vecS, directedS> Tr;
    typedef adjacency_list<vecS, vecS, directedS,
      property<vertex_index_t, long, property<vertex_color_t, default_color_type,
        property<vertex_distance_t, long, property<vertex_predecessor_t, Tr::edge_descriptor> > > >,
      property<edge_capacity_t, double, property<edge_residual_capacity_t, double,
        property<edge_reverse_t, Tr::edge_descriptor> > > > G;
    G g(fk.size() + 2);
    auto cap = get(edge_capacity, g); auto rev = get(edge_reverse, g);
    auto add = [&](int u, int v, double c) {
      auto e1 = add_edge(u, v, g).first, e2 = add_edge(v, u, g).first;
      cap[e1] = c; cap[e2] = 0; rev[e1] = e2; rev[e2] = e1;
    };
    const int S = int(fk.size()), T = S + 1;
    const double inf = 1e30;
    for(std::size_t a = 0; a < fk.size(); ++a)
    {
      int f = fk[a];
      for(int i = 0; i < 3; ++i)
      {
        int h = 3*f+i, o = cm.opposite[h];
        if(o < 0 || cm.is_seam(h)) continue;
        add(int(a), local[o/3], cm.edge_length(h));
      }
      if(src[a]) add(S, int(a), inf);
      if(snk[a]) add(int(a), T, inf);
    }
    double flow = boykov_kolmogorov_max_flow(g, S, T);
    auto col = get(vertex_color, g);
    const auto sc = get(vertex_color, g, S);
    for(std::size_t a = 0; a < fk.size(); ++a)
    {
      int f = fk[a];
      for(int i = 0; i < 3; ++i)
      {
        int h = 3*f+i, o = cm.opposite[h];
        if(o < 0 || cm.is_seam(h)) continue;
        if((col[a] == sc) != (col[local[o/3]] == sc)) cut[h] = 1;
      }
    }
    std::cerr << "  chart " << k << " pairs " << pairs.size() << " components " << np << " largest " << bestsize / 2 << " cut " << flow / cm.normalization_radius() << "\n";
    ++split;
  }
  if(split == 0) return 0;
  std::vector<double> corner_uv(2 * cm.corner_uv.size());
  std::vector<char> seam(cm.corner_vertex.size(), 0);
  for(std::size_t c = 0; c < cm.corner_uv.size(); ++c)
  {
    corner_uv[2*c] = cm.uv[2 * cm.corner_uv[c]];
    corner_uv[2*c+1] = cm.uv[2 * cm.corner_uv[c] + 1];
    seam[c] = cm.is_seam(int(c)) || cut[c];
  }
  I::label_uv_vertices(cm, seam);
  for(std::size_t c = 0; c < cm.corner_uv.size(); ++c)
  {
    cm.uv[2 * cm.corner_uv[c]] = corner_uv[2*c];
    cm.uv[2 * cm.corner_uv[c] + 1] = corner_uv[2*c+1];
  }
  return split;
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
  int rounds = 0;
  while(I::count_overlapping_pairs(cm, 1) > 0 && rounds < 200)
  {
    std::size_t n = std::getenv("VORONOI") ? I::split_self_overlapping_charts(cm) : min_cut_split(cm);
    I::lay_out_uv_components(cm);
    ++rounds;
    std::cerr << "round " << rounds << " split " << n << " seams " << cm.seam_length() / R << " overlaps " << I::count_overlapping_pairs(cm) << "\n";
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
