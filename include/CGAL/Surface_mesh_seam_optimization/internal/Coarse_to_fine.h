// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// A start for distortion only on large meshes: Tutte's map of a dense chart
// squeezes its inner triangles by orders of magnitude, and the flip-free
// Newton descent then needs ~100 short steps, each a factorization, before
// it converges. Instead the UV mesh is simplified by edge collapses that
// flip no triangle of that map (which so stays a valid map of every level),
// the coarsest level's map minimized, and the collapses undone in reverse,
// each level's map minimized in turn. A returning vertex only changes its
// own faces, which were valid with the kept vertex in its place: a point
// close to the kept vertex, inside the wedge of the two faces on the
// collapsed edge, makes them valid. The vertex goes to the mean of its ring
// where that is valid, else toward it from that wedge point, and is then
// relaxed alone (Newton on its two unknowns, flip-free).

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_COARSE_TO_FINE_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_COARSE_TO_FINE_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Element_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Flip_free_step.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Multiresolution.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Projected_newton.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Meshes from this many faces start coarse; each level has a quarter of the
// faces of the one above (lucy at 96544 faces through 23976: valid; through
// 11982 the placements failed, notes/issue20).
constexpr std::size_t coarse_to_fine_minimum_faces = 16000;
constexpr double coarse_to_fine_ratio = 4;

// One edge collapse, to undo: the removed UV vertex, the one it was merged
// into, and the removed vertex's faces just before (UV vertices, in order).
struct Collapse_record
{
  int removed, kept;
  std::size_t first_face, number_of_faces;
};

struct Coarse_level
{
  Proxy_mesh mesh;                    // the coarse UV mesh (its charts are components)
  std::vector<int> fine_vertex;       // the fine UV vertex of each coarse vertex
  std::vector<Collapse_record> records;
  std::vector<std::array<int, 3> > faces;
};

struct Record_collapses
  : CGAL::Surface_mesh_simplification::Edge_collapse_visitor_base<Proxy_mesh>
{
  Proxy_mesh::Property_map<Proxy_mesh::Vertex_index, int> fine;
  Coarse_level* level = nullptr;
  int pending = -1;

  template <typename Profile, typename OptionalPoint>
  void OnCollapsing(const Profile& profile, const OptionalPoint&)
  {
    const bool at0 = placed_at_v0(profile);
    const auto removed = at0 ? profile.v1() : profile.v0();
    pending = fine[at0 ? profile.v0() : profile.v1()];
    const Proxy_mesh& m = profile.surface_mesh();
    Collapse_record r{ fine[removed], pending, level->faces.size(), 0 };
    for(const auto h : CGAL::halfedges_around_target(removed, m))
    {
      if(CGAL::is_border(h, m)) continue;
      level->faces.push_back({ fine[m.target(h)], fine[m.target(m.next(h))], fine[m.target(m.next(m.next(h)))] });
      ++r.number_of_faces;
    }
    level->records.push_back(r);
  }
  template <typename Profile, typename Vertex>
  void OnCollapsed(const Profile&, const Vertex& v) { fine[v] = pending; }
};

// Shape_preserving_filter, and no collapse that would flip a UV triangle of
// the current map: the coarse mesh keeps the fine map at its vertices as a
// valid start (its own Tutte map can degenerate where the fine one did not).
struct Uv_preserving_filter
{
  Proxy_mesh::Property_map<Proxy_mesh::Vertex_index, int> fine;
  const std::vector<double>* uv = nullptr;

  template <typename Profile>
  boost::optional<typename Profile::Point> operator()(const Profile& profile,
                                                      boost::optional<typename Profile::Point> op) const
  {
    op = Shape_preserving_filter()(profile, op);
    if(!op) return op;
    const Proxy_mesh& m = profile.surface_mesh();
    const bool at0 = placed_at_v0(profile);
    const auto removed = at0 ? profile.v1() : profile.v0();
    const auto kept = at0 ? profile.v0() : profile.v1();
    for(const auto h : CGAL::halfedges_around_target(removed, m))
    {
      if(CGAL::is_border(h, m)) continue;
      const Proxy_mesh::Vertex_index w[3] = { m.target(h), m.target(m.next(h)), m.target(m.next(m.next(h))) };
      if(w[1] == kept || w[2] == kept) continue; // removed by the collapse
      const double* q[3];
      for(int i = 0; i < 3; ++i) q[i] = &(*uv)[2 * fine[w[i] == removed ? kept : w[i]]];
      if(!(signed_area2(q[0], q[1], q[2]) > 0)) return boost::none;
    }
    return op;
  }
};

// The UV mesh of `cm` (charts as components, seams as borders) simplified to
// about `target_faces` faces, no UV triangle flipped; false if it is no
// manifold surface.
inline bool simplify_uv_mesh(const Cut_mesh& cm, std::size_t target_faces, Coarse_level& level)
{
  namespace SMS = CGAL::Surface_mesh_simplification;
  Proxy_mesh m;
  Record_collapses visitor;
  visitor.level = &level;
  visitor.fine = m.add_property_map<Proxy_mesh::Vertex_index, int>("v:fine", -1).first;
  const std::size_t nu = cm.number_of_uv_vertices();
  std::vector<Proxy_mesh::Vertex_index> vertex(nu);
  for(std::size_t u = 0; u < nu; ++u)
  {
    const double* p = &cm.points[3 * cm.uv_vertex[u]];
    vertex[u] = m.add_vertex(Proxy_kernel::Point_3(p[0], p[1], p[2]));
    visitor.fine[vertex[u]] = int(u);
  }
  for(std::size_t f = 0; f < cm.number_of_faces(); ++f)
    if(m.add_face(vertex[cm.corner_uv[3*f]], vertex[cm.corner_uv[3*f+1]], vertex[cm.corner_uv[3*f+2]]) ==
       Proxy_mesh::null_face())
      return false;
  const double edges_per_face = double(m.number_of_edges()) / double(m.number_of_faces());
  SMS::Count_stop_predicate<Proxy_mesh> stop(std::size_t(edges_per_face * double(target_faces)));
  SMS::edge_collapse(m, stop,
                     CGAL::parameters::get_cost(SMS::Edge_length_cost<Proxy_mesh>())
                       .get_placement(Endpoint_placement())
                       .filter(Uv_preserving_filter{ visitor.fine, &cm.uv })
                       .visitor(visitor));
  std::vector<Proxy_mesh::Vertex_index> coarse(m.number_of_vertices() + m.number_of_removed_vertices());
  for(const auto v : m.vertices())
  {
    coarse[v.idx()] = level.mesh.add_vertex(m.point(v));
    level.fine_vertex.push_back(visitor.fine[v]);
  }
  for(const auto f : m.faces())
  {
    const auto h = m.halfedge(f);
    level.mesh.add_face(coarse[m.target(h).idx()], coarse[m.target(m.next(h)).idx()],
                        coarse[m.target(m.prev(h)).idx()]);
  }
  return level.mesh.number_of_faces() == m.number_of_faces();
}

// The faces of one returning vertex r, with their rest frames.
template <typename Energy>
class Vertex_fan
{
public:
  Vertex_fan(const Cut_mesh& cm, const Energy& energy, std::vector<double>& uv, int r,
             const std::array<int, 3>* faces, std::size_t n)
    : m_energy(energy), m_uv(uv), m_r(r), m_faces(faces), m_n(n), m_rest(4 * n), m_area(n)
  {
    for(std::size_t i = 0; i < n; ++i)
      triangle_rest_frame(point(cm, faces[i][0]), point(cm, faces[i][1]), point(cm, faces[i][2]),
                          &m_rest[4*i], m_area[i]);
  }

  // The corners of face i with r at p.
  void corners(std::size_t i, const double* p, const double* q[3]) const
  {
    for(int k = 0; k < 3; ++k) q[k] = m_faces[i][k] == m_r ? p : &m_uv[2 * m_faces[i][k]];
  }

  bool valid_at(const double* p) const
  {
    const double* q[3];
    for(std::size_t i = 0; i < m_n; ++i)
    {
      corners(i, p, q);
      if(!(signed_area2(q[0], q[1], q[2]) > 0)) return false;
    }
    return true;
  }

  double energy_at(const double* p) const
  {
    Eigen::Matrix2d J;
    const double* q[3];
    double e = 0;
    for(std::size_t i = 0; i < m_n; ++i)
    {
      corners(i, p, q);
      triangle_jacobian(q[0], q[1], q[2], &m_rest[4*i], J);
      e += m_area[i] * m_energy.value(J);
    }
    return e;
  }

  // Projected Newton on r's two unknowns, flip-free; r must be valid.
  void relax(int iterations)
  {
    double* p = &m_uv[2 * m_r];
    double e = energy_at(p);
    Eigen::Matrix2d J, dJ;
    Eigen::Matrix4d HJ;
    Eigen::Matrix<double, 6, 6> H;
    double g6[6];
    const double* q[3];
    const double zero[2] = { 0, 0 };
    for(int it = 0; it < iterations && std::isfinite(e); ++it)
    {
      Eigen::Vector2d g = Eigen::Vector2d::Zero();
      Eigen::Matrix2d h = Eigen::Matrix2d::Zero();
      for(std::size_t i = 0; i < m_n; ++i)
      {
        corners(i, p, q);
        triangle_jacobian(q[0], q[1], q[2], &m_rest[4*i], J);
        m_energy.value_gradient_and_hessian(J, dJ, HJ, true);
        element_derivatives(Jacobian_coefficients(&m_rest[4*i]), m_area[i], dJ, HJ, g6, &H);
        for(int a = 0; a < 3; ++a)
          if(m_faces[i][a] == m_r)
          {
            g += Eigen::Vector2d(g6[2*a], g6[2*a+1]);
            h += H.block<2, 2>(2*a, 2*a);
          }
      }
      h.diagonal().array() += 1e-12 * h.trace();
      Eigen::Vector2d d = -h.ldlt().solve(g);
      if(!(d.dot(g) < 0)) d = -g;
      double t_max = std::numeric_limits<double>::infinity();
      for(std::size_t i = 0; i < m_n; ++i)
      {
        corners(i, p, q);
        const double* dq[3];
        for(int k = 0; k < 3; ++k) dq[k] = m_faces[i][k] == m_r ? d.data() : zero;
        t_max = (std::min)(t_max, triangle_flip_free_step(q[0], q[1], q[2], dq[0], dq[1], dq[2]));
      }
      double t = (std::min)(1., 0.9 * t_max);
      bool moved = false;
      for(int k = 0; k < 30; ++k, t *= 0.5)
      {
        const double x[2] = { p[0] + t * d[0], p[1] + t * d[1] };
        const double ex = energy_at(x);
        if(ex <= e + 1e-4 * t * d.dot(g))
        {
          moved = e - ex > 1e-10 * e; // else converged
          p[0] = x[0]; p[1] = x[1];
          e = ex;
          break;
        }
      }
      if(!moved) break;
    }
  }

private:
  static const double* point(const Cut_mesh& cm, int u) { return &cm.points[3 * cm.uv_vertex[u]]; }

  const Energy& m_energy;
  std::vector<double>& m_uv;
  int m_r;
  const std::array<int, 3>* m_faces;
  std::size_t m_n;
  std::vector<double> m_rest, m_area;
};

// Undoes the collapses of `level`: `uv` has the coarse vertices' UVs (per
// fine UV vertex) and gets the others'. False if a vertex found no valid
// place (then `uv` is not a map).
template <typename Energy>
bool prolong_uv_map(const Cut_mesh& cm, const Coarse_level& level, const Energy& energy, std::vector<double>& uv)
{
  const int relax_iterations = 8;
  for(auto it = level.records.rbegin(); it != level.records.rend(); ++it)
  {
    const int r = it->removed, kept = it->kept;
    const std::array<int, 3>* faces = &level.faces[it->first_face];
    const std::size_t n = it->number_of_faces;
    if(n == 0) return false;
    Vertex_fan<Energy> fan(cm, energy, uv, r, faces, n);
    double* p = &uv[2 * r];
    double target[2] = { 0, 0 };
    if(n == 1)
    {
      // a border ear: the mean of its ring lies on its UV edge; place the
      // triangle similar to its 3D shape on that edge instead
      int i = 0;
      while(faces[0][i] != r) ++i;
      const int a = faces[0][(i + 1) % 3], b = faces[0][(i + 2) % 3]; // (r, a, b) counterclockwise
      double l, x, y; // r in the plane of (a, b, r), a at the origin, b on the x axis
      triangle_local_frame(&cm.points[3 * cm.uv_vertex[a]], &cm.points[3 * cm.uv_vertex[b]],
                           &cm.points[3 * cm.uv_vertex[r]], l, x, y);
      const double ux = uv[2*b] - uv[2*a], uy = uv[2*b+1] - uv[2*a+1];
      const double s = 1. / l; // (x, y) in units of |ab|, rotated and scaled onto a -> b in UV
      target[0] = uv[2*a] + s * (x * ux - y * uy);
      target[1] = uv[2*a+1] + s * (x * uy + y * ux);
    }
    else
    {
      int count = 0;
      for(std::size_t i = 0; i < n; ++i)
        for(int k = 0; k < 3; ++k)
          if(faces[i][k] != r) { target[0] += uv[2 * faces[i][k]]; target[1] += uv[2 * faces[i][k] + 1]; ++count; }
      target[0] /= count; target[1] /= count;
    }
    if(fan.valid_at(target))
    {
      p[0] = target[0]; p[1] = target[1];
      fan.relax(relax_iterations);
      continue;
    }
    // the wedge at the kept vertex between the two faces on the collapsed edge
    const double* pk = &uv[2 * kept];
    double d[2] = { 0, 0 };
    double shortest = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < n; ++i)
    {
      int k = 0;
      while(faces[i][k] != r) ++k;
      const int a = faces[i][(k + 1) % 3], b = faces[i][(k + 2) % 3];
      auto inward = [&](int w, double sign) {
        const double ux = uv[2*w] - pk[0], uy = uv[2*w+1] - pk[1], l = std::hypot(ux, uy);
        if(l > 0) { d[0] += sign * -uy / l; d[1] += sign * ux / l; }
      };
      if(a == kept) inward(b, 1.);   // (r, kept, b): r left of kept -> b
      if(b == kept) inward(a, -1.);  // (r, a, kept): r right of kept -> a
      shortest = (std::min)(shortest, std::hypot(uv[2*a] - uv[2*b], uv[2*a+1] - uv[2*b+1]));
    }
    const double dl = std::hypot(d[0], d[1]);
    if(!(dl > 0) || !(shortest > 0)) return false;
    d[0] /= dl; d[1] /= dl;
    bool placed = false;
    for(double eps = 0.3 * shortest; eps > 1e-12 * shortest && !placed; eps *= 0.3)
    {
      const double q0[2] = { pk[0] + eps * d[0], pk[1] + eps * d[1] };
      if(!fan.valid_at(q0)) continue;
      // halfway along the valid part of the segment from there to the target
      double lo = 0, hi = 1;
      for(int b = 0; b < 30; ++b)
      {
        const double mid = 0.5 * (lo + hi);
        const double x[2] = { q0[0] + mid * (target[0] - q0[0]), q0[1] + mid * (target[1] - q0[1]) };
        (fan.valid_at(x) ? lo : hi) = mid;
      }
      p[0] = q0[0] + 0.5 * lo * (target[0] - q0[0]);
      p[1] = q0[1] + 0.5 * lo * (target[1] - q0[1]);
      placed = fan.valid_at(p);
    }
    if(!placed) return false;
    fan.relax(relax_iterations);
  }
  return true;
}

// Gauss-Seidel sweeps of single-vertex relaxations over the UV vertices of
// `cm`: a vertex placed during prolongation was relaxed before its later
// neighbours came back; a sweep after all are back expands the triangles
// left squeezed (mannequin-devil, 25888 faces: start E_SD 2371 -> 9.4 in 3
// sweeps, 84 -> 22 Newton iterations; notes/issue20).
template <typename Energy>
void relax_uv_vertices(Cut_mesh& cm, const Energy& energy, int sweeps)
{
  const std::size_t nu = cm.number_of_uv_vertices(), nf = cm.number_of_faces();
  std::vector<std::size_t> start(nu + 1, 0);
  for(int u : cm.corner_uv) ++start[u + 1];
  for(std::size_t u = 0; u < nu; ++u) start[u + 1] += start[u];
  std::vector<std::array<int, 3> > fan(start[nu]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for(std::size_t f = 0; f < nf; ++f)
    for(int i = 0; i < 3; ++i)
      fan[fill[cm.corner_uv[3*f + i]]++] = { cm.corner_uv[3*f], cm.corner_uv[3*f + 1], cm.corner_uv[3*f + 2] };
  for(int s = 0; s < sweeps; ++s)
    for(std::size_t u = 0; u < nu; ++u)
      Vertex_fan<Energy>(cm, energy, cm.uv, int(u), &fan[start[u]], start[u + 1] - start[u]).relax(8);
}

// A Cut_mesh of the surface `m` (no garbage; its borders bound the charts),
// every vertex its own UV vertex, UVs zero.
inline void cut_mesh_of(const Proxy_mesh& m, Cut_mesh& cm)
{
  const std::size_t nv = m.number_of_vertices(), nf = m.number_of_faces();
  cm.points.resize(3 * nv);
  for(const auto v : m.vertices())
    for(int k = 0; k < 3; ++k) cm.points[3 * v.idx() + k] = m.point(v)[k];
  cm.corner_vertex.resize(3 * nf);
  cm.opposite.assign(3 * nf, -1);
  std::vector<int> corner_of(m.number_of_halfedges(), -1); // the corner a halfedge ends at
  for(const auto f : m.faces())
  {
    int i = 0;
    for(const auto h : CGAL::halfedges_around_face(m.halfedge(f), m))
    {
      cm.corner_vertex[3 * f.idx() + i] = int(m.target(h).idx());
      corner_of[h.idx()] = int(3 * f.idx() + i);
      ++i;
    }
  }
  // (halfedge c ends at corner c: its opposite ends at the corner before c)
  for(const auto h : m.halfedges())
    if(!m.is_border(h) && !m.is_border(m.opposite(h)))
      cm.opposite[corner_of[h.idx()]] = corner_of[m.opposite(h).idx()];
  cm.corner_uv = cm.corner_vertex;
  cm.uv_vertex.resize(nv);
  for(std::size_t v = 0; v < nv; ++v) cm.uv_vertex[v] = int(v);
  cm.uv.assign(2 * nv, 0.);
  cm.compute_rest_shape();
}

// Replaces the (valid) UVs of `cm` by a coarse-to-fine map: the UV mesh
// simplified to a quarter of its faces, that mesh's map (the UVs of `cm` at
// its vertices; coarse-to-fine in turn while it has at least
// `minimum_faces` faces) minimized, the collapses undone.
// `level_faces` gets the faces of each level, finest first. False, `cm`
// unchanged, if any part fails.
template <typename Energy, typename SolverTraits>
bool coarse_to_fine_start(Cut_mesh& cm, const Energy& energy, const SolverTraits& solver,
                          const Newton_settings& settings, const Deadline& deadline,
                          std::vector<std::size_t>& level_faces,
                          std::size_t minimum_faces = coarse_to_fine_minimum_faces)
{
  Coarse_level level;
  const std::size_t target = std::size_t(double(cm.number_of_faces()) / coarse_to_fine_ratio);
  if(!simplify_uv_mesh(cm, target, level)) return false;
  // (a mesh that hardly simplifies gains nothing)
  const std::size_t nf = level.mesh.number_of_faces();
  if(2 * nf > cm.number_of_faces()) return false;
  Cut_mesh coarse;
  cut_mesh_of(level.mesh, coarse);
  for(std::size_t v = 0; v < level.fine_vertex.size(); ++v)
    for(int k = 0; k < 2; ++k) coarse.uv[2 * v + k] = cm.uv[2 * level.fine_vertex[v] + k];
  if(first_face_outside_barrier_domain(coarse) < nf) return false;
  level_faces.push_back(nf);
  const std::size_t depth = level_faces.size();
  if(nf >= minimum_faces && // (else, or if that fails, from the fine map's UVs)
     !coarse_to_fine_start(coarse, energy, solver, settings, deadline, level_faces, minimum_faces))
    level_faces.resize(depth);
  rescale_to_optimal(coarse, energy);
  std::size_t iterations = 0;
  Optimization_timings timings;
  std::string message;
  if(descend(coarse, energy, solver, settings, std::size_t(10000), deadline, iterations, timings, message) != OK)
    return false;
  std::vector<double> uv(cm.uv.size(), std::numeric_limits<double>::quiet_NaN());
  for(std::size_t v = 0; v < level.fine_vertex.size(); ++v)
    for(int k = 0; k < 2; ++k) uv[2 * level.fine_vertex[v] + k] = coarse.uv[2 * v + k];
  if(!prolong_uv_map(cm, level, energy, uv)) return false;
  for(double x : uv)
    if(!std::isfinite(x)) return false;
  uv.swap(cm.uv);
  if(first_face_outside_barrier_domain(cm) < cm.number_of_faces())
  {
    uv.swap(cm.uv);
    return false;
  }
  relax_uv_vertices(cm, energy, 3);
  return true;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
