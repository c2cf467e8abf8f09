// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// The OptCuts loop on the core arrays: descent (projected Newton, with
// fracture propagation), topology steps at stationary points, and the dual
// update of lambda for a distortion bound; the best feasible configuration
// is kept. What follows the loop (polish, straighten, recut) is in
// Alternating_optimization.h, the scaffold's lazy state in Bijectivity_guard.h.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ALTERNATION_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ALTERNATION_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/Seam_optimization_visitor.h>
#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Bijectivity_guard.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Candidate_ranking.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Defaults.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Dual_step.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Invariants.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Join_charts.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Projected_newton.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Topology_step.h>

#include <CGAL/Real_timer.h>
#include <CGAL/assertions.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <functional>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

inline const char* overlapping_initial_map_message()
{
  return "the initial UV map is not bijective (charts overlap or touch): give a bijective map, "
         "or pass bijective(false)";
}

struct Alternating_settings
{
  double distortion_bound = default_distortion_bound;
  bool fixed_lambda = false;
  double lambda = 0.999;            // initial (bound mode) or fixed value
  double kappa = 1.;                // dual step size on rho = (1 - lambda) / lambda
  std::size_t max_iterations = default_number_of_iterations;
  double time_limit = std::numeric_limits<double>::infinity(); // seconds from construction
  // bound mode: after the first result, unzip this fraction of the seams
  // where they buy least and alternate again, until a round finds nothing
  // shorter
  int recut_rounds = default_number_of_recut_rounds;
  double recut_fraction = 0.1;
  // and straighten a leaf seam path whose shortcut is this much cheaper and
  // saves at least this fraction of the seams
  double detour_ratio = 1.1;
  double detour_min_saving = 0.01;
  // bound mode: an interior split (a new slit) must cost this many times less
  // seam per unit of distortion than the best boundary split
  double slit_ratio = 1.5;
  Dual_step_rule dual_step_rule = RAISE_PRICE; // see Dual_step.h
  bool bijective = false;           // scaffold around the charts
  Newton_settings newton;
};

template <typename Energy, typename SolverTraits, typename Visitor>
class Alternation
{
public:

  Alternation(Cut_mesh& cm, const Energy& energy, const SolverTraits& solver,
                           const std::vector<double>& halfedge_weight, const Alternating_settings& settings,
                           Visitor& visitor)
    : m_cm(cm), m_energy(energy), m_weight(halfedge_weight), m_settings(settings), m_visitor(visitor),
      m_newton(cm, energy, solver, settings.newton), m_topology(cm, energy, halfedge_weight),
      m_lambda(settings.lambda), m_guard(settings.bijective, &halfedge_weight), m_deadline(settings.time_limit)
  {
    m_timer.start();
  }

  double lambda() const { return m_lambda; }
  std::size_t iterations() const { return m_newton.iterations(); }
  std::size_t topology_operations() const { return m_operations; }
  bool bound_met() const { return distortion() <= m_settings.distortion_bound; }

  // E_SD as the bound judges it (at the optimal scale for a scale-invariant energy)
  double distortion() const { return judged_distortion(m_cm, m_energy, m_cm.uv.data()); }
  double seam_cost() const { return m_cm.seam_length(&m_weight) / m_cm.normalization_radius(); }

  // Pattern analysis and descent to the first stationary point.
  Error_code start()
  {
    if(m_settings.bijective)
    {
      // the scaffold waits until it is needed (see check_overlaps())
      Phase_timer timer(m_timings.scaffold);
      if(!m_guard.begin(m_cm, m_lambda, chart_distortion())) return ERROR_OVERLAPPING_UV_MAP;
    }
    if(!m_newton.rebuild_pattern()) return ERROR_LINEAR_SOLVER;
    return descend();
  }

  std::size_t scaffold_rebuilds() const { return m_scaffold_rebuilds; }

  // Called (once, on the thread of this run) at the stationary point where
  // the lazy phase ends, before the scaffold changes anything: the state then
  // is that of a run without bijectivity. Dropped once the alternation ends.
  void set_lazy_phase_end_hook(std::function<void()> f) { m_on_lazy_phase_end = std::move(f); }
  void drop_lazy_phase_end_hook() { m_on_lazy_phase_end = nullptr; }

  // Takes over the loop of `o` (another run on a copy of its cut mesh, at a
  // stationary point): lambda, the best record, the configurations seen and
  // the counts, Newton's iterations and the deadline included.
  // resume_pattern() before the first step.
  void resume(const Alternation& o)
  {
    m_lambda = o.m_lambda;
    m_operations = o.m_operations;
    m_tips = o.m_tips;
    m_seen = o.m_seen;
    m_stationary_points = o.m_stationary_points;
    m_best_at = o.m_best_at;
    m_has_best = o.m_has_best;
    m_best_polished = o.m_best_polished;
    m_best_se = o.m_best_se;
    m_best_lambda = o.m_best_lambda;
    m_best = o.m_best;
    m_deadline = o.m_deadline;
    m_newton.continue_count(o.m_newton.iterations());
  }
  bool resume_pattern() { return m_newton.rebuild_pattern(); }

  Optimization_timings timings() const
  {
    Optimization_timings t = m_newton.timings();
    t.topology = m_timings.topology;
    t.scaffold = m_timings.scaffold;
    return t;
  }

  // One alternation from a stationary point: stopping tests, dual update,
  // topology operation, descent. False when the optimization is over;
  // `status` then says why (OK: converged).
  bool step(Error_code& status)
  {
    if(m_deadline.reached()) { status = WARNING_TIME_LIMIT; return false; }
    if(!check_overlaps(status)) return false;
    const double e_sd = distortion();
    const double e_se = seam_cost();
    record(e_sd, e_se);
    if(!m_settings.fixed_lambda)
    {
      const double b = m_settings.distortion_bound;
      if(e_sd <= b && e_sd >= b - 1e-4) { status = polish_seams(); return false; }
      // A stationary (E_se, E_SD) seen before: the dual step only cycles
      // split/merge pairs from here (lambda drifts in its last digits).
      const auto key = std::make_pair(std::llround(e_se * 1e6), std::llround(e_sd * 1e5));
      if(!m_seen.insert(key).second) return false;
      // nor does it pay to go on long after the best feasible stopped improving
      if(m_has_best && m_stationary_points++ > m_best_at + 50) return false;
    }
    std::vector<Operation> ops;
    {
      Phase_timer timer(m_timings.topology);
      gather_candidates(e_sd, ops);
    }
    if(!m_settings.fixed_lambda)
    {
      // above the bound only cuts, below only merges (the dual step makes them pay)
      const bool above = e_sd > m_settings.distortion_bound;
      ops.erase(std::remove_if(ops.begin(), ops.end(), [above](const Operation& op) {
                  return above == (op.type == CORNER_MERGE); }), ops.end());
      // and a new slit only where it clearly beats cutting from a boundary
      drop_costly_slits(ops, m_settings.slit_ratio);
    }
    if(!m_settings.fixed_lambda && !dual_update(e_sd, ops))
    {
      if(m_cancelled) { status = WARNING_CANCELLED; return false; }
      // below the bound with no merge left, charts cut apart may still be glued back
      return e_sd <= m_settings.distortion_bound && join_charts(status, false);
    }
    // the most profitable operation that keeps the map bijective
    std::vector<std::pair<double, std::size_t> > order;
    for(std::size_t i = 0; i < ops.size(); ++i)
      if(ops[i].weighted(m_lambda) < 0) order.emplace_back(ops[i].weighted(m_lambda), i);
    std::sort(order.begin(), order.end());
    bool applied = false;
    for(const auto& o : order)
      if((applied = apply(ops[o.second]))) break;
    if(!applied)
    {
      // (as above)
      if(!m_settings.fixed_lambda && e_sd <= m_settings.distortion_bound && join_charts(status, false)) return true;
      if(m_cancelled) status = WARNING_CANCELLED;
      return false; // stationary in topology too
    }
    if(m_cancelled) { status = WARNING_CANCELLED; return false; }
    status = descend();
    return status == OK;
  }

  Seam_optimization_progress progress() const
  {
    Seam_optimization_progress p;
    p.iterations = m_newton.iterations();
    p.topology_operations = m_operations;
    p.distortion = m_newton.energy();
    if(visitor_reads_progress(m_visitor))
    {
      // (a pass over the mesh: once per labelling, not at every iteration)
      if(!m_progress_seam_valid || m_progress_seam_pattern != m_newton.patterns())
      {
        m_progress_seam = m_cm.seam_length() / m_cm.normalization_radius();
        m_progress_seam_pattern = m_newton.patterns();
        m_progress_seam_valid = true;
      }
      p.seam_length_normalized = m_progress_seam;
    }
    p.lambda = m_lambda;
    p.seconds = m_timer.time();
    return p;
  }

private:

protected:

  // At a stationary point: on with the scaffold if the charts overlap (see
  // Bijectivity_guard). False (status set) if the run must end.
  bool check_overlaps(Error_code& status)
  {
    auto e_sd = [this] { return chart_distortion(); };
    auto fork = [this] {
      if(!m_on_lazy_phase_end) return;
      std::function<void()> f;
      f.swap(m_on_lazy_phase_end);
      f();
    };
    Bijectivity_guard::Verdict verdict = m_guard.check(m_cm, m_lambda, e_sd, fork);
    while(verdict == Bijectivity_guard::SPLIT)
    {
      m_tips.clear();
      if(!m_newton.rebuild_pattern()) { status = ERROR_LINEAR_SOLVER; return false; }
      status = descend();
      if(status != OK) return false;
      verdict = m_guard.check(m_cm, m_lambda, e_sd, fork);
    }
    if(verdict == Bijectivity_guard::NO_OVERLAP) return true;
    if(verdict == Bijectivity_guard::RESTARTED)
    {
      m_lambda = m_settings.lambda;
      m_best_at = m_stationary_points; // the second start has its patience
    }
    m_tips.clear();
    m_seen.clear();
    ++m_scaffold_rebuilds;
    // (a scaffold that cannot be meshed ends the run at its best feasible configuration)
    if(!build_scaffold()) { m_guard.scaffold_failed(); status = OK; return false; }
    m_topology.set_scaffold(&m_guard.scaffold());
    if(!m_newton.rebuild_pattern()) { status = ERROR_LINEAR_SOLVER; return false; }
    status = descend();
    return status == OK;
  }

  bool scaffold_on() const { return m_guard.scaffold_on(); }

  // E_SD of the charts as they are (the guard compares configurations)
  double chart_distortion() const { return total_energy(m_cm, Symmetric_Dirichlet_energy(), m_cm.uv.data()); }

  // Newton to a stationary point; between iterations, the seams created by
  // the last split are extended from their tips while that beats Newton.
  Error_code descend() { return descend([] { return false; }); }

  // The same, ended early (OK) after the first iteration that leaves `enough()`.
  template <typename Enough>
  Error_code descend(const Enough& enough)
  {
    for(;;)
    {
      if(m_newton.iterations() >= m_settings.max_iterations) return WARNING_MAXIMUM_ITERATIONS;
      if(m_deadline.reached()) return WARNING_TIME_LIMIT;
      const Newton_status s = m_newton.step();
      if(s == NEWTON_SOLVER_FAILED) return ERROR_LINEAR_SOLVER;
      // a squeezed scaffold blocks the charts' motion: mesh the space anew
      if(m_newton.has_scaffold() && m_guard.squeezed(scaffold_positions()))
      {
        if(!rebuild_scaffold()) return ERROR_LINEAR_SOLVER;
        if(s == NEWTON_CONVERGED && !m_rebuilt_at_convergence) { m_rebuilt_at_convergence = true; continue; }
      }
      m_rebuilt_at_convergence = false;
      if(!m_visitor.on_iteration(progress())) return WARNING_CANCELLED;
      if(enough()) { m_tips.clear(); return OK; }
      const bool propagated = propagate(s == NEWTON_CONVERGED ? 0. : (1 - m_lambda) * m_newton.last_decrease());
      if(m_cancelled) return WARNING_CANCELLED;
      if(s == NEWTON_CONVERGED && !propagated) { m_tips.clear(); return OK; }
    }
  }

  bool propagate(double newton_gain)
  {
    if(m_tips.empty()) return false;
    bool any = false;
    std::vector<int> tips;
    tips.swap(m_tips);
    for(int tip : tips)
    {
      if(m_cancelled) break;
      std::vector<Operation> ops;
      {
        Phase_timer timer(m_timings.topology);
        m_topology.boundary_splits(tip, ops);
      }
      const Operation* best = nullptr;
      for(const Operation& op : ops)
        if(!best || op.weighted(m_lambda) < best->weighted(m_lambda)) best = &op;
      if(best && best->weighted(m_lambda) < 0 && -best->weighted(m_lambda) > newton_gain)
      {
        const int next_tip = best->tips.front();
        if(!apply(*best)) continue;
        m_tips.push_back(next_tip);
        any = true;
      }
    }
    return any;
  }

  // At the bound: zip seams back, or move seam ears across (shorter seams
  // through the same vertices but one), while the bound still holds after
  // descent (a failed try is undone; five end the polish).
  Error_code polish_seams()
  {
    // whatever ends the polish, the best configuration it leaves is polished
    struct Mark { bool& polished; ~Mark() { polished = true; } };
    Mark mark{m_best_polished};
    const double b = m_settings.distortion_bound;
    int failures = 0;
    std::vector<std::pair<int, int> > failed; // (uv_a, uv_b) tried in vain at this configuration
    while(failures < 5)
    {
      std::vector<Operation> ops;
      {
        Phase_timer timer(m_timings.topology);
        m_topology.merges(ops);
        m_topology.shifts(ops);
      }
      const Operation* best = cheapest_per_seam_length(ops, failed);
      if(!best)
      {
        Error_code status = OK;
        if(join_charts(status, true)) { record(distortion(), seam_cost()); failed.clear(); continue; }
        return m_cancelled ? WARNING_CANCELLED : status;
      }
      Uv_snapshot before;
      before.save(m_cm);
      const std::pair<int, int> tried(best->uv_a, best->uv_b);
      if(!apply(*best)) { failed.push_back(tried); ++failures; continue; }
      if(m_cancelled) return WARNING_CANCELLED;
      const Error_code status = descend();
      if(status != OK) return status;
      const double e_sd = distortion();
      if(e_sd <= b) { record(e_sd, seam_cost()); failed.clear(); continue; }
      before.restore(m_cm);
      if(!rebuild_scaffold()) return ERROR_LINEAR_SOLVER;
      failed.push_back(tried);
      ++failures;
    }
    return OK;
  }

  // Glues two charts back along the seams between them (Join_charts.h), the
  // largest saving first, and keeps the first join that can be placed
  // without overlap, descended. `within_bound`: only if the descent stays
  // within the bound (the polish); else the alternation goes on from it, its
  // dual step buying cuts back where they cost less than the join saved,
  // the best feasible configuration kept as always (femur: 13.06 -> 11.88).
  // Joins only ever lower the number of charts, so they end. False, the
  // configuration as it was, when none is kept (five failures end the tries,
  // as in the polish), or with `status` set when the descent ends the run.
  bool join_charts(Error_code& status, bool within_bound)
  {
    const double b = m_settings.distortion_bound;
    std::vector<Chart_join> joins;
    {
      Phase_timer timer(m_timings.topology);
      joins = chart_joins(m_cm, &m_weight);
    }
    int failures = 0;
    for(std::size_t k = 0; k < joins.size() && failures < 5; ++k)
    {
      Uv_snapshot before;
      before.save(m_cm);
      {
        Phase_timer timer(m_timings.topology);
        if(!join_two_charts(m_cm, m_topology.vertex_corners(), joins[k])) { ++failures; continue; }
      }
      m_progress_seam_valid = false;
      lay_out_uv_components(m_cm); // (the glued chart may now lie on another)
      const bool placed = scaffold_on() ? build_scaffold() : !(m_settings.bijective && count_overlapping_pairs(m_cm, 1) > 0);
      if(!placed)
      {
        before.restore(m_cm);
        if(scaffold_on()) build_scaffold();
        if(!m_newton.rebuild_pattern()) { status = ERROR_LINEAR_SOLVER; return false; }
        ++failures;
        continue;
      }
      if(!m_newton.rebuild_pattern()) { status = ERROR_LINEAR_SOLVER; return false; }
      m_tips.clear();
      status = descend();
      if(status != OK) return false;
      if(!within_bound || distortion() <= b)
      {
        ++m_operations;
        if(!m_visitor.on_topology_operation(progress())) { m_cancelled = true; status = WARNING_CANCELLED; return false; }
        return true;
      }
      before.restore(m_cm);
      if(!rebuild_scaffold()) { status = ERROR_LINEAR_SOLVER; return false; }
      ++failures;
    }
    return false;
  }

  // Applies op; with a scaffold, an op whose result would overlap is undone
  // (false).
  bool apply(const Operation& op)
  {
    // (the seams change before the pattern is rebuilt, which a batch defers)
    m_progress_seam_valid = false;
    Uv_snapshot before;
    if(scaffold_on()) before.save(m_cm);
    {
      Phase_timer timer(m_timings.topology);
      Topology_step<Energy>::apply(m_cm, m_topology.vertex_corners(), op);
    }
    CGAL_assertion_msg(check_invariants(m_cm).empty(), check_invariants(m_cm).c_str());
    if(scaffold_on() && !build_scaffold())
    {
      before.restore(m_cm);
      build_scaffold();
      if(!m_defer_pattern) m_newton.rebuild_pattern();
      ++m_rejected;
      return false;
    }
    ++m_operations;
    if(op.type != CORNER_MERGE)
      for(int t : op.tips) m_tips.push_back(t);
    if(!m_defer_pattern) m_newton.rebuild_pattern();
    if(!m_visitor.on_topology_operation(progress())) m_cancelled = true;
    return true;
  }

  // On failure (a numerically degenerate triangle, say) the previous
  // scaffold stays: its triangles are still unflipped, so it still bounds
  // the charts where they are.
  bool build_scaffold()
  {
    Phase_timer timer(m_timings.scaffold);
    if(!m_guard.build(m_cm)) return false;
    // (again, if a mismatched scaffold had to be dropped: see rebuild_scaffold())
    if(scaffold_on()) m_newton.set_scaffold(&m_guard.scaffold());
    return true;
  }

  // Scaffold positions live in the scaffold; Newton's unified vector is
  // charts' UVs then scaffold vertices.
  const double* scaffold_positions()
  {
    const std::vector<double>& pos = m_guard.scaffold().pos;
    m_x.resize(m_cm.uv.size() + pos.size());
    std::copy(m_cm.uv.begin(), m_cm.uv.end(), m_x.begin());
    std::copy(pos.begin(), pos.end(), m_x.begin() + m_cm.uv.size());
    return m_x.data();
  }

  bool rebuild_scaffold()
  {
    if(scaffold_on())
    {
      ++m_scaffold_rebuilds;
      // a kept scaffold must still match the UV vertices (it does unless a
      // topology edit was undone under it)
      if(!build_scaffold() && m_guard.scaffold().n_uv != int(m_cm.number_of_uv_vertices())) m_newton.set_scaffold(nullptr);
    }
    return m_newton.rebuild_pattern();
  }

  void gather_candidates(double e_sd, std::vector<Operation>& ops)
  {
    std::vector<std::pair<double, int> > boundary, interior;
    rank_split_candidates(m_cm, m_energy, boundary, interior);
    const std::size_t nb = number_of_boundary_candidates(boundary.size());
    // Independent stencil solves: in parallel where TBB is linked, gathered in
    // candidate order so that results do not depend on the schedule.
    std::vector<std::vector<Operation> > per_vertex(nb);
#ifdef CGAL_LINKED_WITH_TBB
    if(nb >= 16)
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nb), [&](const tbb::blocked_range<std::size_t>& range) {
        std::unique_ptr<Topology_step<Energy> >& local = m_thread_topology.local();
        if(!local) local.reset(new Topology_step<Energy>(m_cm, m_energy, m_weight));
        local->set_scaffold(scaffold_on() ? &m_guard.scaffold() : nullptr);
        for(std::size_t i = range.begin(); i != range.end(); ++i)
          local->boundary_splits(boundary[i].second, per_vertex[i]);
      });
    }
    else
#endif
    for(std::size_t i = 0; i < nb; ++i) m_topology.boundary_splits(boundary[i].second, per_vertex[i]);
    for(const std::vector<Operation>& v : per_vertex) ops.insert(ops.end(), v.begin(), v.end());
    m_topology.merges(ops);
    // Only what the step may apply counts: above the bound, splits; below, merges.
    const bool above = e_sd > m_settings.distortion_bound;
    auto usable = [&](const Operation& op) {
      return m_settings.fixed_lambda || above == (op.type != CORNER_MERGE);
    };
    bool profitable = false;
    for(const Operation& op : ops) profitable = profitable || (usable(op) && op.weighted(m_lambda) < 0);
    if(boundary.empty() || (!profitable && (m_settings.fixed_lambda || above)))
    {
      const std::size_t ni = number_of_interior_candidates(interior.size());
      for(std::size_t i = 0; i < ni; ++i) m_topology.interior_splits(interior[i].second, ops);
    }
    // Nothing usable among the best ranked vertices (their splits would
    // overlap, say): widen the filter to every vertex rather than stop.
    if(above && std::none_of(ops.begin(), ops.end(), usable))
    {
      for(std::size_t i = nb; i < boundary.size(); ++i) m_topology.boundary_splits(boundary[i].second, ops);
      if(std::none_of(ops.begin(), ops.end(), usable))
        for(const std::pair<double, int>& v : interior) m_topology.interior_splits(v.second, ops);
    }
  }

  // The dual step (see dual_step()), then the visitor; false: nothing can pay, or cancelled.
  bool dual_update(double e_sd, const std::vector<Operation>& ops)
  {
    if(!dual_step(e_sd, m_settings.distortion_bound, m_settings.kappa, ops, m_lambda, m_settings.dual_step_rule)) return false;
    if(!m_visitor.on_lambda_update(progress())) { m_cancelled = true; return false; }
    return true;
  }

  void record(double e_sd, double e_se)
  {
    if(m_settings.fixed_lambda || e_sd > m_settings.distortion_bound) return;
    if(m_has_best && e_se >= m_best_se) return;
    if(!m_guard.is_result(m_cm)) return;
    m_has_best = true;
    m_best_polished = false;
    m_best_se = e_se;
    m_best_at = m_stationary_points;
    m_best.save(m_cm);
    m_best_lambda = m_lambda;
  }

  void restore_best()
  {
    m_best.restore(m_cm);
    m_lambda = m_best_lambda;
  }

  Cut_mesh& m_cm;
  const Energy& m_energy;
  const std::vector<double>& m_weight;
  Alternating_settings m_settings;
  Visitor& m_visitor;
  Projected_newton<Energy, SolverTraits> m_newton;
  Topology_step<Energy> m_topology;
  double m_lambda;
  std::size_t m_operations = 0;
  bool m_cancelled = false;
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<std::unique_ptr<Topology_step<Energy> > > m_thread_topology;
#endif
  Bijectivity_guard m_guard;
  Optimization_timings m_timings; // topology and scaffold; Newton keeps its own
  Deadline m_deadline;
  std::vector<double> m_x;
  std::size_t m_scaffold_rebuilds = 0, m_rejected = 0;
  bool m_rebuilt_at_convergence = false;
  std::vector<int> m_tips;
  std::function<void()> m_on_lazy_phase_end;
  std::set<std::pair<long long, long long> > m_seen;
  std::size_t m_stationary_points = 0, m_best_at = 0;
  bool m_defer_pattern = false; // a batch of operations: the Newton pattern is analysed after it
  bool m_has_best = false;
  bool m_best_polished = false;
  double m_best_se = 0, m_best_lambda = 0;
  Uv_snapshot m_best;
  CGAL::Real_timer m_timer;
  // progress()'s seam length and the Newton pattern it was computed for: the
  // seams change only with the labelling, after which the pattern is rebuilt
  mutable double m_progress_seam = 0;
  mutable std::size_t m_progress_seam_pattern = 0;
  mutable bool m_progress_seam_valid = false;
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
