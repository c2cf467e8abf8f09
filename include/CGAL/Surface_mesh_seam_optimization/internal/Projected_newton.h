// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Projected Newton on the distortion energy of a Cut_mesh with a flip-free
// backtracking line search. The sparsity pattern is analysed once per UV
// topology; every iteration only refills the values, and refactorizes
// unless the last factorization still solves the step (Stale_factor_cg.h).
// With a scaffold, its triangles join the energy (symmetric Dirichlet, tiny
// weight) and its own vertices the unknowns, after the charts' UV vertices.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_PROJECTED_NEWTON_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_PROJECTED_NEWTON_H

#include <CGAL/Surface_mesh_seam_optimization/Optimization_result.h>
#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/parameters.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Element_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Flip_free_step.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Mesh_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Scaffold.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Stale_factor_cg.h>

#include <CGAL/assertions.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <type_traits>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Adds the wall seconds from construction to stop() (or destruction) to `sum`.
class Phase_timer
{
public:
  explicit Phase_timer(double& sum) : m_sum(&sum), m_start(std::chrono::steady_clock::now()) {}
  ~Phase_timer() { stop(); }
  void stop()
  {
    if(!m_sum) return;
    *m_sum += std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
    m_sum = nullptr;
  }
private:
  double* m_sum;
  std::chrono::steady_clock::time_point m_start;
};

// The `time_limit` named parameter: reached once that many seconds have
// passed since construction; never with no limit (+inf). Also reached once
// `stop` is raised (a start of optimize_seams() cancelled with the others).
class Deadline
{
public:
  explicit Deadline(double seconds = std::numeric_limits<double>::infinity(),
                    const std::atomic<bool>* stop = nullptr)
    : m_seconds(seconds), m_start(std::chrono::steady_clock::now()), m_stop(stop) {}
  bool reached() const
  {
    if(m_stop && m_stop->load()) return true;
    return m_seconds < std::numeric_limits<double>::infinity() &&
           std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count() >= m_seconds;
  }
private:
  double m_seconds;
  std::chrono::steady_clock::time_point m_start;
  const std::atomic<bool>* m_stop;
};

// Reads `time_limit` (seconds > 0; default none); false if it is not valid.
template <typename NamedParameters>
bool read_time_limit(const NamedParameters& np, double& seconds)
{
  seconds = parameters::choose_parameter(parameters::get_parameter(np, internal_np::time_limit),
                                         std::numeric_limits<double>::infinity());
  return seconds > 0; // (NaN is not)
}

struct Newton_settings
{
  // Stop when |g|^2 * A (scale-free) falls below this.
  double gradient_tolerance = 1e-12;
  // Stop when the relative energy decrease of an iteration falls below this.
  double relative_decrease_tolerance = 1e-6;
  double armijo = 1e-4;
  // Fraction of the largest flip-free step taken at most.
  double flip_free_fraction = 0.99;
  // An energy that is no barrier (ARAP) lets the flip-free bound squeeze a
  // triangle that would rather flip closer to zero area every iteration, at
  // a vanishing energy gain (cat_f1500: area ratio 5e-16, E_SD 6e27): its
  // triangles keep at least this fraction of their area relative to the
  // map's mean area ratio (or half their first area, if smaller).
  double area_floor = 1e-3;
  // The Newton step is solved by conjugate gradients preconditioned by the
  // last factorization of the same pattern, to this relative residual (an
  // inexact Newton step; the line search keeps it a descent), when that
  // takes at most this many iterations; else the Hessian is factorized
  // anew. 0: factorize every iteration. minimize_distortion() on
  // lucy_o_f48275 (one pattern): 57.6 -> 52.0 s, the same iterations.
  int stale_factor_iterations = 8;
  double stale_factor_tolerance = 1e-4;
  // After a failed try, the next steps factorize without trying the stale
  // factor (see Projected_newton::back_off_stale_factor()); false: try at every step.
  bool stale_factor_backoff = true;
  // The projected Hessian drops the negative curvature of compressed
  // triangles: its model is too curved, a full step falls short, and a
  // descent creeps on by full steps that each gain little. A full step that
  // lowers the energy is doubled while that lowers it further, up to this
  // factor and the flip-free bound (energy evaluations only). 1: never
  // (the seam loop's setting, see Setup_seam_optimization.h).
  double extrapolation_limit = 1;
  // The projected Hessian's missing curvature also makes the tail linear
  // (full steps that each gain 1e-5). After a full step, the next one
  // minimizes the exact Hessian's quadratic model by conjugate gradients
  // preconditioned by the last factor of a projected Hessian, truncated at
  // negative curvature, at this many iterations, or at a radius (the exact
  // Hessian is indefinite away from the minimum, and nearly flat directions
  // would blow the step up): at first 4 times the length of the step the
  // factor alone gives, doubled after a full step that reached it, halved
  // (down to 1) after one the line search shortened, as a trust region's.
  // No solver ever factorizes an indefinite matrix. 0: never (the seam
  // loop's setting: its stationary points would move, and its topology
  // decisions with them).
  int exact_curvature_iterations = 0;
};

// minimize_distortion()'s settings (the seam loop's are in Setup_seam_optimization.h).
inline Newton_settings distortion_only_newton_settings()
{
  Newton_settings settings;
  // Extrapolated full steps: Newton iterations 20 -> 15 on bimba_i_f10000,
  // 136 -> 65 on hand_1_i_f5000, 251 -> 153 on lucy_o_f12067 (notes/issue20).
  settings.extrapolation_limit = 16;
  // Steps along the exact curvature after full steps: lucy at 96544 faces
  // 98 -> 65 Newton iterations, 34 -> 22 s (notes/issue20).
  settings.exact_curvature_iterations = 10;
  return settings;
}

// the first radius (see Newton_settings::exact_curvature_iterations)
constexpr double exact_curvature_radius = 4;

// Analyses after an AMD one that keep its elimination order (see
// Projected_newton::analyze()): 4 skips AMD in 4 of 5 analyses for 2-5%
// more fill (10 meshes, 10k faces: the same iterations and seams, wall
// time x0.94; 16: 5-8% more fill, no faster; notes/issue20/session_2026-12-02b).
constexpr int inherited_ordering_analyses = 4;

// Solver traits that take an elimination order of the 2x2 blocks (as
// Default_sparse_solver_traits does)
template <typename Solver, typename = void>
struct Takes_block_ordering : std::false_type {};
template <typename Solver>
struct Takes_block_ordering<Solver, std::void_t<decltype(std::declval<Solver&>().block_ordering()),
                                                decltype(std::declval<Solver&>().analyze_pattern(
                                                  std::declval<const Eigen::SparseMatrix<double>&>(),
                                                  std::declval<const std::vector<int>&>()))> >
  : std::true_type {};

enum Newton_status { NEWTON_PROGRESS, NEWTON_CONVERGED, NEWTON_SOLVER_FAILED };

template <typename Energy, typename SolverTraits>
class Projected_newton
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;

  Projected_newton(Cut_mesh& cm, const Energy& energy, const SolverTraits& solver,
                   const Newton_settings& settings = Newton_settings())
    : m_cm(cm), m_energy(energy), m_solver(solver), m_settings(settings), m_barrier(is_barrier_energy(energy))
  {}

  // The scaffold (or null); call rebuild_pattern() after it changed.
  void set_scaffold(Scaffold* scaffold) { m_scaffold = scaffold; }
  bool has_scaffold() const { return m_scaffold && !m_scaffold->empty(); }

  const Optimization_timings& timings() const { return m_timings; }

  // Call after any change of the corner -> UV labelling or of the scaffold.
  bool rebuild_pattern()
  {
    ++m_patterns;
    Phase_timer timer(m_timings.symbolic_analysis);
    const std::size_t ne = number_of_elements();
    const int ndof = int(2 * m_cm.number_of_uv_vertices() + (has_scaffold() ? m_scaffold->pos.size() : 0));
    build_lower_pattern(ne, ndof);
    int dof[6];
    m_entry.resize(21 * ne);
    const int* outer = m_H.outerIndexPtr();
    const int* inner = m_H.innerIndexPtr();
    for(std::size_t f = 0; f < ne; ++f)
    {
      local_dofs(f, dof);
      // where the rows of vertex a start in the two columns of vertex b (a
      // not before b): one search per pair of vertices, not per entry
      int base[3][3][2];
      for(int a = 0; a < 3; ++a)
        for(int b = 0; b < 3; ++b)
        {
          const int R = dof[2*a] / 2, C = dof[2*b] / 2;
          if(R < C) continue;
          int* at = base[a][b];
          if(R == C) { at[0] = outer[2*C]; at[1] = outer[2*C + 1] - 1; continue; }
          // (a column holds a few blocks: a scan beats a binary search)
          at[1] = outer[2*C + 1];
          while(inner[at[1]] < 2 * R) ++at[1];
          at[0] = at[1] - outer[2*C + 1] + outer[2*C] + 1; // (column 2C has row 2C more)
        }
      int k = 0;
      for(int p = 0; p < 6; ++p)
        for(int q = 0; q <= p; ++q)
        {
          const int row = (std::max)(dof[p], dof[q]), col = (std::min)(dof[p], dof[q]);
          const int a = dof[p] >= dof[q] ? p / 2 : q / 2, b = dof[p] >= dof[q] ? q / 2 : p / 2;
          m_entry[21*f + k++] = base[a][b][col % 2] + row % 2;
          CGAL_assertion(m_entry[21*f + k - 1] == entry_index(row, col));
        }
    }
    m_diagonal.resize(ndof);
    for(int d = 0; d < ndof; ++d) m_diagonal[d] = outer[d]; // (each column starts at its diagonal)
    m_gradient.resize(ndof);
    load();
    m_energy_value = total_energy(m_cm, m_energy, m_x.data());
    m_objective = m_energy_value + (has_scaffold() ? m_scaffold->energy(m_x.data()) : 0.);
    m_reuse_factor = false;
    back_off_stale_factor(true); // (a new pattern: a fresh record)
    return analyze();
  }

  // The lower triangle of the last assembled Hessian.
  const Matrix& hessian() const { return m_H; }

  // Energy of the charts (without the scaffold's).
  double energy() const { return m_energy_value; }
  double last_step() const { return m_last_step; }
  double last_decrease() const { return m_last_decrease; }
  double gradient_norm2() const { return m_gradient_norm2; }
  std::size_t iterations() const { return m_iterations; }
  // calls of rebuild_pattern() so far (each follows a change of the labelling)
  std::size_t patterns() const { return m_patterns; }
  // (a run taking over another's counts on from its iterations)
  void continue_count(std::size_t iterations) { m_iterations = iterations; }
  // iterations whose step needed a new factorization (the others reused the last one)
  std::size_t factorizations() const { return m_factorizations; }
  // steps that tried the last factor as a preconditioner (Newton_settings::stale_factor_iterations), and those it failed
  std::size_t stale_factor_tries() const { return m_stale_tries; }
  std::size_t stale_factor_failures() const { return m_stale_failures; }
  // iterations whose step came from the exact Hessian's model (see Newton_settings::exact_curvature_iterations)
  std::size_t exact_curvature_steps() const { return m_exact_steps; }

  // One projected Newton iteration.
  Newton_status step()
  {
    load();
    Phase_timer assembly(m_timings.assembly);
    bool exact = m_full_step && m_reuse_factor && m_settings.exact_curvature_iterations > 0, on_radius = false;
    const double e0 = assemble(!exact);
    assembly.stop();
    const double A = m_cm.total_area;
    m_gradient_norm2 = m_gradient.squaredNorm() * A;
    if(m_gradient_norm2 < m_settings.gradient_tolerance) return NEWTON_CONVERGED;
    regularize();

    const Eigen::VectorXd rhs = -m_gradient;
    if(exact)
    {
      Phase_timer solve(m_timings.factorization);
      const Stale_factor_cg_result r =
        stale_factor_cg(m_H, m_solver, rhs, m_direction, m_settings.stale_factor_tolerance,
                        m_settings.exact_curvature_iterations, true, m_radius_factor);
      exact = r.converged && m_direction.allFinite() && rhs.dot(m_direction) > 0;
      on_radius = r.on_radius;
      solve.stop();
      if(exact) ++m_exact_steps;
      else
      {
        Phase_timer assembly_again(m_timings.assembly);
        assemble(true);
        assembly_again.stop();
        regularize();
      }
    }
    Phase_timer factorization(m_timings.factorization);
    bool inexact = exact;
    if(!exact && m_reuse_factor && m_settings.stale_factor_iterations > 0)
    {
      if(m_stale_skips > 0) --m_stale_skips;
      else
      {
        inexact = stale_factor_cg(m_H, m_solver, rhs, m_direction, m_settings.stale_factor_tolerance,
                                  m_settings.stale_factor_iterations).converged;
        ++m_stale_tries;
        if(!inexact) ++m_stale_failures;
        if(m_settings.stale_factor_backoff) back_off_stale_factor(inexact);
      }
    }
    if(!inexact)
    {
      if(!m_solver.factorize(m_H)) return NEWTON_SOLVER_FAILED;
      m_reuse_factor = true;
      ++m_factorizations;
      if(!m_solver.solve(rhs, m_direction)) return NEWTON_SOLVER_FAILED;
    }
    factorization.stop();
    Phase_timer line_search(m_timings.line_search);

    double slope = m_gradient.dot(m_direction);
    if(!(slope < 0)) { m_direction = -m_gradient; slope = -m_gradient.squaredNorm(); }

    double t_max = m_barrier ? max_flip_free_step(m_cm, m_x.data(), m_direction.data())
                             : max_area_floor_step(m_direction.data());
    if(has_scaffold()) t_max = (std::min)(t_max, m_scaffold->max_flip_free_step(m_x.data(), m_direction.data()));
    double t = (std::min)(1., m_settings.flip_free_fraction * t_max);
    // A triangle at its floor cuts every step short: judge the decrease as
    // is, not per unit step, or the iterations creep on (ARAP on the cat in
    // bound mode: 100000 of them).
    const bool at_floor = !m_barrier && t < 1.;
    double e = std::numeric_limits<double>::infinity(), e_charts = e;
    for(int k = 0; k < 60; ++k, t *= 0.5)
    {
      e = objective_along_direction(t, m_trial, e_charts);
      if(e <= e0 + m_settings.armijo * t * slope) break;
    }
    if(t == 1. && e < e0)
    {
      const double t_limit = (std::min)(m_settings.extrapolation_limit, m_settings.flip_free_fraction * t_max);
      for(double t2 = 2; t2 <= t_limit; t2 *= 2)
      {
        double e2_charts;
        const double e2 = objective_along_direction(t2, m_extrapolated, e2_charts);
        if(!(e2 < e)) break;
        e = e2; e_charts = e2_charts; t = t2;
        m_trial.swap(m_extrapolated);
      }
    }
    ++m_iterations;
    m_full_step = t >= 1. && e < e0;
    // (a trust-region update of the radius)
    if(exact && on_radius) m_radius_factor = t >= 1. ? 2 * m_radius_factor : (std::max)(1., 0.5 * m_radius_factor);
    // Only an exact step decides that the iterate is stationary: a stalled
    // inexact one would stop the descent short of the stationary point
    // (higher E_SD at the topology step: more cuts, measured).
    auto stalled = [this] { m_reuse_factor = false; return NEWTON_PROGRESS; };
    if(!(e < e0))
    {
      m_last_step = 0; m_last_decrease = 0;
      return inexact ? stalled() : NEWTON_CONVERGED; // the step vanished
    }
    m_x.swap(m_trial);
    store();
    m_last_step = t;
    m_last_decrease = e0 - e;
    m_energy_value = e_charts;
    m_objective = e;
    // (per unit step: an extrapolated step judged as a full one)
    if(m_last_decrease < m_settings.relative_decrease_tolerance * (at_floor ? 1. : (std::min)(t, 1.)) * e0)
      return inexact ? stalled() : NEWTON_CONVERGED;
    return NEWTON_PROGRESS;
  }

private:
  // A failed try of the stale factor costs a third of a factorization and
  // more, and predicts the next: after a step the line search shortened it
  // fails in 98% of the tries (minimize_distortion() on lucy at 96544
  // faces, 133 of 135). Each failure doubles the number of the next steps
  // that factorize without trying it (up to 32); a success resets it.
  void back_off_stale_factor(bool success)
  {
    if(success) { m_stale_backoff = 0; m_stale_skips = 0; return; }
    m_stale_backoff = m_stale_backoff == 0 ? 1 : (std::min)(2 * m_stale_backoff, 32);
    m_stale_skips = m_stale_backoff;
  }

  // The objective at m_x + t m_direction, written to `x`; `e_charts` gets the charts' part.
  double objective_along_direction(double t, std::vector<double>& x, double& e_charts)
  {
    x.resize(m_x.size());
    for(std::size_t i = 0; i < x.size(); ++i) x[i] = m_x[i] + t * m_direction[i];
    double e = e_charts = total_energy(m_cm, m_energy, x.data());
    if(has_scaffold()) e += m_scaffold->energy(x.data());
    return e;
  }

  std::size_t number_of_elements() const
  {
    return m_cm.number_of_faces() + (has_scaffold() ? m_scaffold->number_of_triangles() : 0);
  }

  // Unknowns of element e: a face of the charts, then the scaffold's triangles.
  void local_dofs(std::size_t e, int* dof) const
  {
    const std::size_t nf = m_cm.number_of_faces();
    const int* v = e < nf ? &m_cm.corner_uv[3*e] : &m_scaffold->tri[3*(e - nf)];
    for(int a = 0; a < 3; ++a)
    {
      dof[2*a] = 2 * v[a];
      dof[2*a + 1] = dof[2*a] + 1;
    }
  }

  // The flip-free step of a non-barrier energy: no triangle below its area
  // floor (set at the first call, see Newton_settings::area_floor).
  double max_area_floor_step(const double* dir)
  {
    const std::size_t nf = m_cm.number_of_faces();
    const double* uv = m_x.data();
    if(m_floor2.size() != nf)
    {
      const double ratio = area_floor_ratio2(m_cm, m_settings.area_floor);
      m_floor2.resize(nf);
      for(std::size_t f = 0; f < nf; ++f)
        m_floor2[f] = (std::min)(ratio * m_cm.face_area[f], 0.5 * m_cm.signed_uv_area2(f));
    }
    double t = std::numeric_limits<double>::infinity();
    for(std::size_t f = 0; f < nf; ++f)
    {
      const int i0 = 2 * m_cm.corner_uv[3*f], i1 = 2 * m_cm.corner_uv[3*f+1], i2 = 2 * m_cm.corner_uv[3*f+2];
      t = (std::min)(t, triangle_area_floor_step(uv + i0, uv + i1, uv + i2, dir + i0, dir + i1, dir + i2, m_floor2[f]));
    }
    return t;
  }

  // m_x = charts' UVs followed by the scaffold's own vertices.
  void load()
  {
    const std::size_t n = m_cm.uv.size();
    m_x.resize(n + (has_scaffold() ? m_scaffold->pos.size() : 0));
    std::copy(m_cm.uv.begin(), m_cm.uv.end(), m_x.begin());
    if(has_scaffold()) std::copy(m_scaffold->pos.begin(), m_scaffold->pos.end(), m_x.begin() + n);
  }
  void store()
  {
    const std::size_t n = m_cm.uv.size();
    std::copy(m_x.begin(), m_x.begin() + n, m_cm.uv.begin());
    if(has_scaffold()) std::copy(m_x.begin() + n, m_x.end(), m_scaffold->pos.begin());
  }

  // The analysis of the new pattern. Without a scaffold, a topology
  // operation changes the graph only around it: for the next few analyses
  // after an AMD one, each UV vertex is eliminated where the earliest of its
  // corners was in that one (a split's copies side by side, a merged vertex
  // where its first part was), which spares AMD's pass over the whole graph.
  bool analyze()
  {
    if constexpr(Takes_block_ordering<SolverTraits>::value)
    {
      if(has_scaffold())
      {
        m_corner_rank.clear();
        return m_solver.analyze_pattern(m_H);
      }
      const std::size_t nc = m_cm.corner_uv.size(), nu = m_cm.number_of_uv_vertices();
      if(m_corner_rank.size() == nc && m_inherited < inherited_ordering_analyses)
      {
        std::vector<int> key(nu, (std::numeric_limits<int>::max)());
        for(std::size_t c = 0; c < nc; ++c)
        {
          int& k = key[std::size_t(m_cm.corner_uv[c])];
          k = (std::min)(k, m_corner_rank[c]);
        }
        std::vector<int> order(nu);
        for(std::size_t u = 0; u < nu; ++u) order[u] = int(u);
        std::sort(order.begin(), order.end(), [&key](int a, int b) {
          return key[std::size_t(a)] != key[std::size_t(b)] ? key[std::size_t(a)] < key[std::size_t(b)] : a < b;
        });
        m_ordering.resize(nu);
        for(std::size_t k = 0; k < nu; ++k) m_ordering[std::size_t(order[k])] = int(k);
        ++m_inherited;
        return m_solver.analyze_pattern(m_H, m_ordering);
      }
      const bool ok = m_solver.analyze_pattern(m_H);
      const std::vector<int>& amd = m_solver.block_ordering();
      m_corner_rank.clear();
      if(amd.size() == nu)
      {
        m_corner_rank.resize(nc);
        for(std::size_t c = 0; c < nc; ++c) m_corner_rank[c] = amd[std::size_t(m_cm.corner_uv[c])];
        m_inherited = 0;
      }
      return ok;
    }
    else
      return m_solver.analyze_pattern(m_H);
  }

  // The lower triangle's pattern, column by column: the 2x2 blocks of the
  // vertices that share an element (no triplets to sort: the pattern is
  // built anew after every topology change).
  void build_lower_pattern(std::size_t ne, int ndof)
  {
    const int nv = ndof / 2;
    std::vector<int> start(nv + 1, 0);
    int dof[6];
    for(std::size_t e = 0; e < ne; ++e)
    {
      local_dofs(e, dof);
      for(int a = 0; a < 3; ++a) start[dof[2*a] / 2 + 1] += 2;
    }
    for(int v = 0; v < nv; ++v) start[v + 1] += start[v];
    std::vector<int> adjacent(start[nv]);
    std::vector<int> fill(start.begin(), start.end() - 1);
    for(std::size_t e = 0; e < ne; ++e)
    {
      local_dofs(e, dof);
      for(int a = 0; a < 3; ++a)
        for(int b = 1; b < 3; ++b) adjacent[fill[dof[2*a] / 2]++] = dof[2 * ((a + b) % 3)] / 2;
    }
    // per vertex: itself, then its neighbours of higher index, sorted (each
    // kept once before the sort: an interior edge is listed by both its faces)
    std::vector<int> outer(ndof + 1, 0), inner, seen(nv, -1);
    inner.reserve(std::size_t(2 * ndof + 4 * start[nv]));
    for(int v = 0; v < nv; ++v)
    {
      int* first = adjacent.data() + start[v];
      int* last = first;
      for(const int* w = first; w != adjacent.data() + start[v + 1]; ++w)
        if(*w > v && seen[*w] != v) { seen[*w] = v; *last++ = *w; }
      std::sort(first, last);
      for(int c = 0; c < 2; ++c)
      {
        if(c == 0) inner.push_back(2 * v);
        inner.push_back(2 * v + 1);
        for(const int* w = first; w != last; ++w) { inner.push_back(2 * *w); inner.push_back(2 * *w + 1); }
        outer[2 * v + c + 1] = int(inner.size());
      }
    }
    m_H.resize(ndof, ndof);
    m_H.resizeNonZeros(Eigen::Index(inner.size()));
    std::copy(outer.begin(), outer.end(), m_H.outerIndexPtr());
    std::copy(inner.begin(), inner.end(), m_H.innerIndexPtr());
    std::fill(m_H.valuePtr(), m_H.valuePtr() + inner.size(), 0.);
  }

  int entry_index(int row, int col) const
  {
    const int* begin = m_H.innerIndexPtr() + m_H.outerIndexPtr()[col];
    const int* end = m_H.innerIndexPtr() + m_H.outerIndexPtr()[col + 1];
    return int(std::lower_bound(begin, end, row) - m_H.innerIndexPtr());
  }

  // Regularize the rigid-motion null space of a free-boundary chart.
  void regularize()
  {
    double mean_diag = 0;
    double* values = m_H.valuePtr();
    for(int i : m_diagonal) mean_diag += values[i];
    mean_diag /= double(m_diagonal.size());
    for(int i : m_diagonal) values[i] += 1e-10 * mean_diag;
  }

  // Gradient and Hessian at the current UVs (the charts' exact one unless
  // `project`; the scaffold's always projected); returns the energy.
  double assemble(bool project = true)
  {
    const std::size_t nf = m_cm.number_of_faces();
    std::fill(m_H.valuePtr(), m_H.valuePtr() + m_H.nonZeros(), 0.);
    m_gradient.setZero();
    const double inv_area = 1. / m_cm.total_area;
    double e = 0;
    Eigen::Matrix2d J, dJ;
    Eigen::Matrix4d HJ;
    Eigen::Matrix<double, 6, 6> H;
    double g[6];
    int dof[6];
    double* values = m_H.valuePtr();
    auto add = [&](std::size_t element) {
      local_dofs(element, dof);
      for(int p = 0; p < 6; ++p) m_gradient[dof[p]] += g[p];
      const int* entry = &m_entry[21*element];
      int n = 0;
      for(int p = 0; p < 6; ++p)
        for(int q = 0; q <= p; ++q)
          values[entry[n++]] += H(p, q);
    };
    for(std::size_t f = 0; f < nf; ++f)
    {
      face_jacobian(m_cm, f, m_x.data(), J);
      const double w = m_cm.face_area[f] * inv_area;
      e += w * m_energy.value_gradient_and_hessian(J, dJ, HJ, project);
      element_derivatives(Jacobian_coefficients(&m_cm.rest_inverse[4*f]), w, dJ, HJ, g, &H);
      add(f);
    }
    m_energy_value = e;
    if(has_scaffold())
    {
      const Symmetric_Dirichlet_energy sd;
      const Scaffold& s = *m_scaffold;
      for(std::size_t t = 0; t < s.number_of_triangles(); ++t)
      {
        const int* v = &s.tri[3*t];
        triangle_jacobian(&m_x[2*v[0]], &m_x[2*v[1]], &m_x[2*v[2]], &s.rest_inverse[4*t], J);
        e += s.weight[t] * sd.value_gradient_and_hessian(J, dJ, HJ, true);
        element_derivatives(Jacobian_coefficients(&s.rest_inverse[4*t]), s.weight[t], dJ, HJ, g, &H);
        add(nf + t);
      }
    }
    m_objective = e;
    return e;
  }

  Cut_mesh& m_cm;
  const Energy& m_energy;
  SolverTraits m_solver;
  Newton_settings m_settings;
  Scaffold* m_scaffold = nullptr;
  bool m_barrier;
  std::vector<double> m_floor2; // twice the smallest UV area of each face (non-barrier energies)
  std::vector<double> m_x;
  double m_objective = 0;

  Matrix m_H;
  std::vector<int> m_entry, m_diagonal;
  std::vector<int> m_corner_rank; // position of each corner's UV vertex in the last AMD analysis (see analyze())
  std::vector<int> m_ordering;
  int m_inherited = 0; // analyses since then
  Eigen::VectorXd m_gradient, m_direction;
  std::vector<double> m_trial, m_extrapolated;
  double m_energy_value = 0, m_last_step = 0, m_last_decrease = 0, m_gradient_norm2 = 0;
  std::size_t m_iterations = 0;
  std::size_t m_patterns = 0;
  bool m_reuse_factor = false; // the last factorization may precondition the next step (same pattern, no stall since)
  int m_stale_backoff = 0, m_stale_skips = 0; // (see back_off_stale_factor())
  std::size_t m_stale_tries = 0, m_stale_failures = 0;
  std::size_t m_factorizations = 0, m_exact_steps = 0;
  bool m_full_step = false; // the last step was full: the next may try the exact curvature
  double m_radius_factor = exact_curvature_radius; // of exact-curvature steps, times the factor's step
  Optimization_timings m_timings;
};

// Newton iterations on the charts of `cm` from their UVs until convergence, `max_iterations` or `deadline`:
// OK, WARNING_MAXIMUM_ITERATIONS, WARNING_TIME_LIMIT or ERROR_LINEAR_SOLVER
// (with `message`).
template <typename Energy, typename SolverTraits>
Error_code descend(Cut_mesh& cm, const Energy& energy, const SolverTraits& solver, const Newton_settings& settings,
                   std::size_t max_iterations, const Deadline& deadline, std::size_t& iterations,
                   Optimization_timings& timings, std::string& message)
{
  Projected_newton<Energy, SolverTraits> newton(cm, energy, solver, settings);
  Error_code status = WARNING_MAXIMUM_ITERATIONS;
  if(!newton.rebuild_pattern())
  {
    message = "symbolic factorization failed";
    status = ERROR_LINEAR_SOLVER;
  }
  else
    while(newton.iterations() < max_iterations)
    {
      if(deadline.reached()) { status = WARNING_TIME_LIMIT; break; }
      const Newton_status s = newton.step();
      if(s == NEWTON_CONVERGED) { status = OK; break; }
      if(s == NEWTON_SOLVER_FAILED)
      {
        message = "numeric factorization failed";
        status = ERROR_LINEAR_SOLVER;
        break;
      }
    }
  iterations = newton.iterations();
  timings = newton.timings();
  return status;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
