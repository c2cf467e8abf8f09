#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Multiresolution.h>
#include <CGAL/Real_timer.h>
#include <iostream>
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace SMS = CGAL::Surface_mesh_simplification;
using namespace SMSO::internal;

struct Record { int removed, kept; std::vector<std::array<int,3> > faces; };
struct Recorder : SMS::Edge_collapse_visitor_base<Proxy_mesh>
{
  Proxy_mesh::Property_map<Proxy_mesh::Vertex_index, int> full;
  std::vector<Record>* records;
  int pending = -1;
  template <typename Profile, typename OptionalPoint>
  void OnCollapsing(const Profile& profile, const OptionalPoint&)
  {
    const bool at0 = placed_at_v0(profile);
    pending = at0 ? full[profile.v0()] : full[profile.v1()];
    const auto r = at0 ? profile.v1() : profile.v0();
    const Proxy_mesh& m = profile.surface_mesh();
    Record rec; rec.removed = full[r]; rec.kept = pending;
    for(auto h : CGAL::halfedges_around_target(r, m))
    {
      if(CGAL::is_border(h, m)) continue;
      rec.faces.push_back({ full[m.target(h)], full[m.target(m.next(h))], full[m.target(m.next(m.next(h)))] });
    }
    records->push_back(std::move(rec));
  }
  template <typename Profile, typename Vertex>
  void OnCollapsed(const Profile&, const Vertex& v) { full[v] = pending; }
};

static double orient(const double* a, const double* b, const double* c)
{ return (b[0]-a[0])*(c[1]-a[1]) - (b[1]-a[1])*(c[0]-a[0]); }

int main(int argc, char** argv)
{
  SM sm; CGAL::IO::read_polygon_mesh(argv[1], sm);
  const std::size_t target = argc > 2 ? std::atoi(argv[2]) : 6000;
  CGAL::Real_timer t; t.start();
  // fine vertices 0..n-1 are sm's indices (fresh read: no garbage)
  Proxy_mesh m;
  Recorder vis; std::vector<Record> records; vis.records = &records;
  vis.full = m.add_property_map<Proxy_mesh::Vertex_index, int>("v:full", -1).first;
  const std::size_t nv = sm.number_of_vertices();
  std::vector<Proxy_mesh::Vertex_index> vx(nv);
  for(auto v : sm.vertices()) { vx[v.idx()] = m.add_vertex(sm.point(v)); vis.full[vx[v.idx()]] = int(v.idx()); }
  for(auto f : sm.faces()) { std::vector<Proxy_mesh::Vertex_index> w; for(auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) w.push_back(vx[v.idx()]); m.add_face(w); }
  const double epf = double(m.number_of_edges()) / double(m.number_of_faces());
  SMS::Count_stop_predicate<Proxy_mesh> stop(std::size_t(epf * double(target)));
  SMS::edge_collapse(m, stop, CGAL::parameters::get_cost(SMS::Edge_length_cost<Proxy_mesh>()).get_placement(Endpoint_placement()).filter(Shape_preserving_filter()).visitor(vis));
  const double t_simplify = t.time();
  // coarse mesh as a clean SM
  SM coarse; std::vector<int> coarse_full; std::vector<SM::Vertex_index> cv(m.number_of_vertices() + m.number_of_removed_vertices());
  for(auto v : m.vertices()) { cv[v.idx()] = coarse.add_vertex(m.point(v)); coarse_full.push_back(vis.full[v]); }
  for(auto f : m.faces()) { std::vector<SM::Vertex_index> w; for(auto v : CGAL::vertices_around_face(m.halfedge(f), m)) w.push_back(cv[v.idx()]); coarse.add_face(w); }
  auto cuv = coarse.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;
  auto rc = SMSO::minimize_distortion(coarse, cuv);
  const double t_coarse = t.time();
  std::cerr << "coarse faces " << coarse.number_of_faces() << " status " << rc.status << " it " << rc.iterations << " E " << rc.distortion << " simplify " << t_simplify << " s, coarse solve " << t_coarse - t_simplify << " s\n";
  std::vector<double> uv(2 * nv, std::numeric_limits<double>::quiet_NaN());
  for(auto h : coarse.halfedges()) if(!coarse.is_border(h)) { int fv = coarse_full[coarse.target(h).idx()]; uv[2*fv] = cuv[h].x(); uv[2*fv+1] = cuv[h].y(); }
  // undo the collapses
  std::size_t fallback = 0, failed = 0;
  for(auto it = records.rbegin(); it != records.rend(); ++it)
  {
    const Record& rec = *it; const int r = rec.removed;
    auto valid_at = [&](const double* p) {
      for(const auto& f : rec.faces) {
        const double* q[3]; for(int i = 0; i < 3; ++i) q[i] = f[i] == r ? p : &uv[2*f[i]];
        if(!(orient(q[0], q[1], q[2]) > 0)) return false; }
      return true; };
    auto fan_energy = [&](const double* p) {
      double e = 0;
      for(const auto& f : rec.faces) {
        const double* q[3]; for(int i = 0; i < 3; ++i) q[i] = f[i] == r ? p : &uv[2*f[i]];
        const double a2 = orient(q[0], q[1], q[2]); if(!(a2 > 0)) return std::numeric_limits<double>::infinity();
        // rest frame of the 3D triangle
        const auto& P0 = sm.point(SM::Vertex_index(f[0])); const auto& P1 = sm.point(SM::Vertex_index(f[1])); const auto& P2 = sm.point(SM::Vertex_index(f[2]));
        K::Vector_3 e1 = P1 - P0, e2 = P2 - P0; const double l1 = std::sqrt(e1.squared_length());
        const double x2 = (e1 * e2) / l1; const double y2 = std::sqrt((std::max)(0., e2.squared_length() - x2 * x2));
        // Dm = [[l1, x2],[0, y2]], Ds = [q1-q0, q2-q0]
        const double d00 = q[1][0]-q[0][0], d10 = q[1][1]-q[0][1], d01 = q[2][0]-q[0][0], d11 = q[2][1]-q[0][1];
        // J = Ds Dm^-1; Dm^-1 = [[1/l1, -x2/(l1 y2)],[0, 1/y2]]
        const double i00 = 1/l1, i01 = -x2/(l1*y2), i11 = 1/y2;
        const double j00 = d00*i00, j01 = d00*i01 + d01*i11, j10 = d10*i00, j11 = d10*i01 + d11*i11;
        const double det = j00*j11 - j01*j10; const double fro = j00*j00+j01*j01+j10*j10+j11*j11;
        e += 0.5 * l1 * y2 * (fro + fro / (det*det)); }
      return e; };
    auto relax = [&]() {
      double p[2] = { uv[2*r], uv[2*r+1] }; double e = fan_energy(p);
      double lm = std::numeric_limits<double>::infinity(); for(const auto& f : rec.faces) for(int i = 0; i < 3; ++i) if(f[i] != r) lm = std::min(lm, std::hypot(uv[2*f[i]]-p[0], uv[2*f[i]+1]-p[1]));
      for(int it = 0; it < 30; ++it) {
        double h = 1e-7 * lm; for(int c = 0; c < 12; ++c, h *= 0.1) { double a0[2] = {p[0]+h, p[1]}, a1[2] = {p[0]-h, p[1]}, a2[2] = {p[0], p[1]+h}, a3[2] = {p[0], p[1]-h}; if(std::isfinite(fan_energy(a0)) && std::isfinite(fan_energy(a1)) && std::isfinite(fan_energy(a2)) && std::isfinite(fan_energy(a3))) break; } double g[2];
        for(int k = 0; k < 2; ++k) { double pp[2] = {p[0], p[1]}, pm[2] = {p[0], p[1]}; pp[k] += h; pm[k] -= h; double ep = fan_energy(pp), em = fan_energy(pm); if(!std::isfinite(ep) || !std::isfinite(em)) { g[k] = 0; } else g[k] = (ep - em) / (2*h); }
        const double gl = std::hypot(g[0], g[1]); if(!(gl > 0)) break;
        double step = 0.5 * lm / gl; bool moved = false;
        for(int b = 0; b < 40; ++b, step *= 0.5) { double q[2] = { p[0] - step * g[0], p[1] - step * g[1] }; double eq = fan_energy(q); if(eq < e) { p[0] = q[0]; p[1] = q[1]; e = eq; moved = true; break; } }
        if(!moved) break; }
      uv[2*r] = p[0]; uv[2*r+1] = p[1]; };
    // candidate: mean of the ring
    double c[2] = {0, 0}; int n = 0; double lmin = std::numeric_limits<double>::infinity();
    for(const auto& f : rec.faces) for(int i = 0; i < 3; ++i) if(f[i] != r) { c[0] += uv[2*f[i]]; c[1] += uv[2*f[i]+1]; ++n; }
    c[0] /= n; c[1] /= n;
    if(rec.faces.size() == 1)
    { // an ear on the border: the triangle as in 3D on its UV edge (the mean would be on the edge)
      const auto& f = rec.faces[0]; int i = 0; while(f[i] != r) ++i;
      const int a = f[(i+1)%3], b = f[(i+2)%3]; // (r, a, b) counterclockwise
      const auto& R = sm.point(SM::Vertex_index(r)); const auto& A = sm.point(SM::Vertex_index(a)); const auto& B = sm.point(SM::Vertex_index(b));
      const K::Vector_3 ab = B - A, ar = R - A; const double l = std::sqrt(ab.squared_length());
      const double x = (ar * ab) / l, y = std::sqrt((std::max)(0., ar.squared_length() - x * x));
      const double ux = uv[2*b] - uv[2*a], uy = uv[2*b+1] - uv[2*a+1], ul = std::hypot(ux, uy), s = ul / l;
      // r left of a->b? (r, a, b) ccw <=> r on the left of a->b
      c[0] = uv[2*a] + s * (x * ux / ul - y * uy / ul); c[1] = uv[2*a+1] + s * (x * uy / ul + y * ux / ul);
    }
    if(valid_at(c)) { uv[2*r] = c[0]; uv[2*r+1] = c[1]; relax(); continue; }
    ++fallback;
    bool done = false;
    { const int k = rec.kept; const double* pk = &uv[2*k]; double d[2] = {0, 0};
      for(const auto& f : rec.faces) for(int i = 0; i < 3; ++i) if(f[i] == r) {
        const int a = f[(i+1)%3], b = f[(i+2)%3];
        if(a == k) { double ux = uv[2*b]-pk[0], uy = uv[2*b+1]-pk[1], l = std::hypot(ux, uy); d[0] += -uy/l; d[1] += ux/l; }   // (r, k, x): left of x-k
        if(b == k) { double ux = uv[2*a]-pk[0], uy = uv[2*a+1]-pk[1], l = std::hypot(ux, uy); d[0] += uy/l; d[1] += -ux/l; }   // (r, x, k): right of x-k
        double l = std::hypot(uv[2*a]-uv[2*b], uv[2*a+1]-uv[2*b+1]); lmin = std::min(lmin, l); }
      const double dl = std::hypot(d[0], d[1]);
      if(dl > 0) { d[0] /= dl; d[1] /= dl;
        for(double eps = 0.3 * lmin; eps > 1e-12 * lmin && !done; eps *= 0.3) {
          double q0[2] = { pk[0] + eps * d[0], pk[1] + eps * d[1] };
          if(!valid_at(q0)) continue;
          double lo = 0, hi = 1; for(int b = 0; b < 30; ++b) { double mid = 0.5 * (lo + hi); double p[2] = { q0[0] + mid * (c[0]-q0[0]), q0[1] + mid * (c[1]-q0[1]) }; if(valid_at(p)) lo = mid; else hi = mid; }
          const double s = 0.5 * lo; uv[2*r] = q0[0] + s * (c[0]-q0[0]); uv[2*r+1] = q0[1] + s * (c[1]-q0[1]); done = true; relax(); } } }
    if(!done) { int nk = 0; for(const auto& f : rec.faces) for(int i = 0; i < 3; ++i) nk += f[i] == rec.kept;
      // validity before: faces with r replaced by kept
      int bad_before = 0; for(const auto& f : rec.faces) { bool hasK = false; for(int i=0;i<3;++i) hasK |= f[i]==rec.kept; if(hasK) continue; const double* q[3]; for(int i = 0; i < 3; ++i) q[i] = f[i] == r ? &uv[2*rec.kept] : &uv[2*f[i]]; if(!(orient(q[0],q[1],q[2]) > 0)) ++bad_before; }
      std::cerr << "fail: faces " << rec.faces.size() << " with kept " << nk << " bad before " << bad_before << "\n"; }
    if(!done) { ++failed; uv[2*r] = c[0]; uv[2*r+1] = c[1]; }
  }
  const double t_prolong = t.time();
  { std::vector<char> isc(nv, 0); for(int v : coarse_full) isc[v] = 1;
    for(auto f : sm.faces()) { int w[3], i = 0; for(auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) w[i++] = v.idx();
      const double a = orient(&uv[2*w[0]], &uv[2*w[1]], &uv[2*w[2]]);
      if(!(a > 0)) std::cerr << "bad face " << f.idx() << " area2 " << a << " coarse " << int(isc[w[0]]) << int(isc[w[1]]) << int(isc[w[2]]) << "\n"; } }
  auto fuv = sm.add_property_map<SM::Halfedge_index, K::Point_2>("h:uv").first;
  for(auto h : sm.halfedges()) if(!sm.is_border(h)) { int v = sm.target(h).idx(); fuv[h] = K::Point_2(uv[2*v], uv[2*v+1]); }
  { auto mr = SMSO::measure_uv_map(sm, fuv); std::cerr << "measure: status " << mr.status << " flipped " << mr.flipped_triangles << "\n";
    double worst = 1e300; for(auto f : sm.faces()) { auto h = sm.halfedge(f); auto a = fuv[h], b = fuv[sm.next(h)], c = fuv[sm.next(sm.next(h))];
      double o = (b.x()-a.x())*(c.y()-a.y()) - (b.y()-a.y())*(c.x()-a.x()); auto P = sm.point(sm.target(h)), Q = sm.point(sm.target(sm.next(h))), R = sm.point(sm.target(sm.next(sm.next(h))));
      double A = std::sqrt(CGAL::cross_product(Q-P, R-P).squared_length()); if(o / A < worst) { worst = o / A; std::cerr << "  face " << f.idx() << " ratio " << o/A << " o " << o << " A " << A << " verts " << sm.target(h).idx() << " " << sm.target(sm.next(h)).idx() << " " << sm.target(sm.next(sm.next(h))).idx() << "\n"; } }
    std::cerr << "worst uv/3d area ratio " << worst << "\n"; }
  { std::vector<char> isc(nv, 0); for(int v : coarse_full) isc[v] = 1; for(int v : {5863, 6103, 5860}) { std::cerr << v << " coarse " << int(isc[v]); for(std::size_t i = 0; i < records.size(); ++i) if(records[i].removed == v) std::cerr << " removed at " << i << " kept " << records[i].kept << " faces " << records[i].faces.size(); std::cerr << "\n"; } }
  std::cerr << "prolonged: " << records.size() << " splits, " << fallback << " off the mean, " << failed << " failed; flips " << SMSO::number_of_flipped_triangles(sm, fuv) << " prolong " << t_prolong - t_coarse << " s\n";
  auto r = SMSO::minimize_distortion(sm, fuv, SMSO::parameters::use_uv_map_as_initial(true));
  std::cerr << "fine: status " << r.status << " " << r.message << " it " << r.iterations << " E " << r.distortion << " init E " << r.initial_distortion << " solve " << r.seconds << " s; total " << t.time() << " s\n";
}
