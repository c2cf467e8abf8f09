// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// OptCuts on the core arrays: descent (projected Newton, with fracture
// propagation), topology steps at stationary points, and the dual update of
// lambda for a distortion bound; the best feasible configuration is kept.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ALTERNATING_OPTIMIZATION_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ALTERNATING_OPTIMIZATION_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/Seam_optimization_visitor.h>
#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Candidate_ranking.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Chart_layout.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Defaults.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Detach_faces.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Dual_step.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Invariants.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Projected_newton.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Scaffold.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Seam_paths.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Seam_reroute.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Topology_step.h>

#include <CGAL/Real_timer.h>
#include <CGAL/assertions.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
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
  std::size_t max_iterations = 100000;
  double time_limit = std::numeric_limits<double>::infinity(); // seconds from construction
  // bound mode: after the first result, unzip this fraction of the seams
  // where they buy least and alternate again, until a round finds nothing
  // shorter
  int recut_rounds = 6;
  double recut_fraction = 0.1;
  // and straighten a leaf seam path whose shortcut is this much cheaper and
  // saves at least this fraction of the seams
  double detour_ratio = 1.1;
  double detour_min_saving = 0.01;
  // bound mode: an interior split (a new slit) must cost this many times less
  // seam per unit of distortion than the best boundary split
  double slit_ratio = 1.5;
  bool bijective = false;           // scaffold around the charts
  Newton_settings newton;
};

template <typename Energy, typename SolverTraits, typename Visitor>
class Alternating_optimization
{
public:
  Alternating_optimization(Cut_mesh& cm, const Energy& energy, const SolverTraits& solver,
                           const std::vector<double>& halfedge_weight, const Alternating_settings& settings,
                           Visitor& visitor)
    : m_cm(cm), m_energy(energy), m_weight(halfedge_weight), m_settings(settings), m_visitor(visitor),
      m_newton(cm, energy, solver, settings.newton), m_topology(cm, energy, halfedge_weight),
      m_lambda(settings.lambda), m_deadline(settings.time_limit)
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

  Error_code run()
  {
    Error_code status = start();
    while(status == OK && step(status)) {}
    return finish(status);
  }

  // Pattern analysis and descent to the first stationary point.
  Error_code start()
  {
    if(m_settings.bijective)
    {
      // The scaffold waits until it is needed (see check_overlaps());
      // meshing it once checks that the initial map is bijective.
      m_lazy = true;
      if(!build_scaffold()) return ERROR_OVERLAPPING_UV_MAP;
      m_scaffold.clear();
      keep_as_safe();
      // (the input's own disks: see check_overlaps())
      if(m_cm.seam_length() == 0)
      {
        m_initial.save(m_cm);
        m_restart_at_overlap = true;
      }
    }
    if(!m_newton.rebuild_pattern()) return ERROR_LINEAR_SOLVER;
    return descend();
  }

  std::size_t scaffold_rebuilds() const { return m_scaffold_rebuilds; }
  // triangles detached into charts of their own to meet the bound (see finish())
  std::size_t detached_faces() const { return m_detached_faces; }

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
      if(m_cancelled) status = WARNING_CANCELLED;
      return false;
    }
    // the most profitable operation that keeps the map bijective
    std::vector<std::pair<double, std::size_t> > order;
    for(std::size_t i = 0; i < ops.size(); ++i)
      if(ops[i].weighted(m_lambda) < 0) order.emplace_back(ops[i].weighted(m_lambda), i);
    std::sort(order.begin(), order.end());
    bool applied = false;
    for(const auto& o : order)
      if((applied = apply(ops[o.second]))) break;
    if(!applied) return false; // stationary in topology too
    if(m_cancelled) { status = WARNING_CANCELLED; return false; }
    status = descend();
    return status == OK;
  }

  // Keeps the best feasible configuration (bound mode).
  Error_code finish(Error_code status)
  {
    // whatever stopped a run without its scaffold, what it leaves does not overlap
    if(m_lazy && count_overlapping_pairs(m_cm, 1) > 0) restore_safe();
    if(status == OK || status == WARNING_CANCELLED || status == WARNING_MAXIMUM_ITERATIONS ||
       status == WARNING_TIME_LIMIT)
    {
      record(distortion(), seam_cost());
      // Whatever stopped the alternation, the seams of the best feasible
      // configuration may still zip shut within the bound.
      if(status == OK && !m_settings.fixed_lambda && m_has_best && !m_best_polished)
      {
        status = polish_best();
        if(status != OK && status != WARNING_CANCELLED && status != WARNING_MAXIMUM_ITERATIONS &&
           status != WARNING_TIME_LIMIT) return status;
      }
      // Rounds from the best result: straighten its largest detour while
      // that finds shorter seams, else unzip; they end at the first
      // unzipping round that finds nothing shorter (the next would start
      // from the same configuration and, deterministic, do about the same).
      bool straighten_next = true;
      for(int unzips = 0, straightens = 0;
          unzips < m_settings.recut_rounds && status == OK && !m_settings.fixed_lambda && m_has_best; )
      {
        const double before = m_best_se;
        restore_best();
        if(!rebuild_scaffold()) return ERROR_LINEAR_SOLVER;
        bool straightened = false;
        if(straighten_next && straightens < m_settings.recut_rounds) status = straighten(straightened);
        if(straightened) ++straightens;
        else if(status == OK) { status = recut(m_settings.recut_fraction); ++unzips; }
        if(status == OK && !m_best_polished) status = polish_best();
        // the iteration cap ends the rounds, not the converged run they improve
        if(status == WARNING_MAXIMUM_ITERATIONS) { status = OK; break; }
        if(status != OK && status != WARNING_CANCELLED && status != WARNING_TIME_LIMIT) return status;
        const bool shorter = m_best_se < before;
        if(shorter) m_straightened.clear();
        if(!straightened && !shorter) break;
        straighten_next = !straightened || shorter;
      }
      if(!m_settings.fixed_lambda)
      {
        if(m_has_best) restore_best();
        else if(status == OK)
        {
          // no split left lowers E_SD: the worst triangles go alone (E_SD 4 each)
          m_detached_faces = detach_faces_until_bound(m_cm, m_settings.distortion_bound);
          if(!bound_met()) status = WARNING_BOUND_NOT_MET;
        }
      }
    }
    return status;
  }

  Seam_optimization_progress progress() const
  {
    Seam_optimization_progress p;
    p.iterations = m_newton.iterations();
    p.topology_operations = m_operations;
    p.distortion = m_newton.energy();
    p.seam_length_normalized = m_cm.seam_length() / m_cm.normalization_radius();
    p.lambda = m_lambda;
    p.seconds = m_timer.time();
    return p;
  }

private:
  // Bijectivity, lazily: the charts run free while the stationary points do
  // not overlap (a scaffold resists the charts' motion and changes which cuts
  // pay); at the first that does, back to the last that did not, and on with
  // the scaffold from there. False (status set) if the run must end.
  bool check_overlaps(Error_code& status)
  {
    if(!m_lazy) return true;
    if(count_overlapping_pairs(m_cm, 1) == 0) { keep_as_safe(); return true; }
    // where a chart lies is free: only a chart that overlaps itself needs the scaffold
    if(lay_out_uv_components(m_cm) > 1 && count_overlapping_pairs(m_cm, 1) == 0)
    {
      keep_as_safe();
      return true;
    }
    if(m_restart_at_overlap)
    {
      // The input's own disks keep about their initial layout; charts that
      // were cut free settle where the scaffold later cramps them: start
      // over, with the scaffold (as the reference does for disks).
      m_initial.restore(m_cm);
      m_lambda = m_settings.lambda;
      m_best_at = m_stationary_points; // the second start has its patience
      m_restart_at_overlap = false;
    }
    else
    {
      restore_safe();
      m_lambda = m_safe_lambda;
    }
    m_tips.clear();
    m_seen.clear();
    m_lazy = false;
    ++m_scaffold_rebuilds;
    // (a scaffold that cannot be meshed ends the run at its best feasible configuration)
    if(!build_scaffold()) { m_lazy = true; status = OK; return false; }
    m_topology.set_scaffold(&m_scaffold);
    if(!m_newton.rebuild_pattern()) { status = ERROR_LINEAR_SOLVER; return false; }
    status = descend();
    return status == OK;
  }

  bool scaffold_on() const { return m_settings.bijective && !m_lazy; }

  void restore_safe()
  {
    m_safe.restore(m_cm);
  }

  void keep_as_safe()
  {
    m_safe.save(m_cm);
    m_safe_lambda = m_lambda;
  }

  // Newton to a stationary point; between iterations, the seams created by
  // the last split are extended from their tips while that beats Newton.
  Error_code descend()
  {
    for(;;)
    {
      if(m_newton.iterations() >= m_settings.max_iterations) return WARNING_MAXIMUM_ITERATIONS;
      if(m_deadline.reached()) return WARNING_TIME_LIMIT;
      const Newton_status s = m_newton.step();
      if(s == NEWTON_SOLVER_FAILED) return ERROR_LINEAR_SOLVER;
      // a squeezed scaffold blocks the charts' motion: mesh the space anew
      if(m_newton.has_scaffold() && m_scaffold.max_density_growth(scaffold_positions()) > m_scaffold.settings.rebuild_threshold)
      {
        if(!rebuild_scaffold()) return ERROR_LINEAR_SOLVER;
        if(s == NEWTON_CONVERGED && !m_rebuilt_at_convergence) { m_rebuilt_at_convergence = true; continue; }
      }
      m_rebuilt_at_convergence = false;
      if(!m_visitor.on_iteration(progress())) return WARNING_CANCELLED;
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
      if(!best) return OK;
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

  // The best feasible configuration, polished (its scaffold meshed anew).
  Error_code polish_best()
  {
    restore_best();
    if(!rebuild_scaffold()) return ERROR_LINEAR_SOLVER;
    return polish_seams();
  }

  // A perturbation of the result (iterated local search): unzip the seams
  // where they buy least (merges by distortion per seam length) until they
  // are `fraction` shorter, and alternate from there (at the result's
  // lambda, not at the smaller one the dual step had on its way down).
  Error_code recut(double fraction)
  {
    const double target = seam_cost() * (1 - fraction);
    std::vector<Operation> ops;
    std::vector<std::pair<int, int> > failed; // (uv_a, uv_b) of merges whose result would overlap
    while(seam_cost() > target)
    {
      ops.clear();
      {
        Phase_timer timer(m_timings.topology);
        m_topology.merges(ops);
      }
      ops.erase(std::remove_if(ops.begin(), ops.end(), [](const Operation& op) { return !(op.d_se < 0); }), ops.end());
      const Operation* best = cheapest_per_seam_length(ops, failed);
      if(!best) break;
      if(!apply(*best)) failed.emplace_back(best->uv_a, best->uv_b);
      if(m_cancelled) return WARNING_CANCELLED;
    }
    return alternate_again();
  }

  // From a perturbed configuration, alternate again to the bound.
  Error_code alternate_again()
  {
    m_tips.clear();
    m_seen.clear();
    m_best_at = m_stationary_points; // patience starts anew
    Error_code status = descend();
    while(status == OK && step(status)) {}
    return status;
  }

  // A perturbation of the result: the largest detour of a leaf seam path
  // not yet tried from this result is replaced by its shortcut (cut, then
  // the detour zipped from its tip; or zipped first where the shortcut
  // cannot be opened yet), and the alternation goes on from there.
  // `applied` is false if there was no such detour or nothing could be done
  // (nothing changed then).
  Error_code straighten(bool& applied)
  {
    applied = false;
    // (with a scaffold, a shortcut starts beside the junction: a junction's
    // wedges are narrow, and splits there overlap)
    std::vector<Seam_detour> detours = seam_detours(
      m_cm, [this](int h) { return m_topology.seam_cost(h); }, m_settings.detour_ratio, scaffold_on());
    // and parts of junction-to-junction paths, which have no tip to zip from
    for(Seam_detour& d : seam_reroutes(m_cm, [this](int h) { return m_topology.seam_cost(h); }, m_settings.detour_ratio))
      detours.push_back(std::move(d));
    auto ends = [this](const Seam_detour& d) {
      return std::make_pair(m_cm.corner_vertex[Cut_mesh::prev(d.seam.front())], m_cm.corner_vertex[d.seam.back()]);
    };
    const double min_saving = m_settings.detour_min_saving * seam_cost();
    const Seam_detour* best = nullptr;
    for(const Seam_detour& d : detours)
    {
      const double saving = d.seam_cost - d.shortcut_cost;
      if(saving >= min_saving && (!best || saving > best->seam_cost - best->shortcut_cost) &&
         std::find(m_straightened.begin(), m_straightened.end(), ends(d)) == m_straightened.end())
        best = &d;
    }
    if(!best) return OK;
    m_straightened.push_back(ends(*best));
    if(best->reroute) return reroute(*best, applied);
    const std::vector<int>& cut = best->shortcut;
    std::size_t cuts = 0, zips = 0;
    {
      // one pattern analysis for the whole batch of operations
      struct Defer { bool& flag; explicit Defer(bool& f) : flag(f) { flag = true; } ~Defer() { flag = false; } };
      Defer defer(m_defer_pattern);
      if(split_along(cut[0]))
        // the shortcut but its last edge, whose end is still on the detour
        for(cuts = 1; cuts + 1 < cut.size() && split_along(cut[cuts]); ++cuts) {}
      const Error_code status = zip(best->seam, zips);
      if(status != OK) return status;
      for(; cuts < cut.size() && split_along(cut[cuts]); ++cuts) {}
    }
    if(m_cancelled) return WARNING_CANCELLED;
    if(!m_newton.rebuild_pattern()) return ERROR_LINEAR_SOLVER;
    if(cuts + zips == 0) return OK;
    applied = true;
    return alternate_again();
  }

  // Replaces a seam part without tips by its shortcut (reroute_seam()), if
  // the result does not overlap, and alternates again from there.
  Error_code reroute(const Seam_detour& d, bool& applied)
  {
    Uv_snapshot before;
    bool done = false;
    {
      Phase_timer timer(m_timings.topology);
      done = reroute_seam(m_cm, m_topology.vertex_corners(), d, before);
    }
    if(!done) return OK;
    // (the region moved across the seam may land on another part of the chart)
    if((m_settings.bijective && count_overlapping_pairs(m_cm, 1) > 0) || (scaffold_on() && !build_scaffold()))
    {
      before.restore(m_cm);
      if(scaffold_on()) build_scaffold();
      return m_newton.rebuild_pattern() ? OK : ERROR_LINEAR_SOLVER;
    }
    CGAL_assertion_msg(check_invariants(m_cm).empty(), check_invariants(m_cm).c_str());
    ++m_operations;
    if(!m_newton.rebuild_pattern()) return ERROR_LINEAR_SOLVER;
    applied = true;
    if(!m_visitor.on_topology_operation(progress())) { m_cancelled = true; return WARNING_CANCELLED; }
    return alternate_again();
  }

  // Splits the source of halfedge h along it; false if that is not possible
  // (the seam would reach another, or the result would overlap).
  bool split_along(int h)
  {
    const int to = m_cm.corner_vertex[h];
    std::vector<Operation> ops;
    const Operation* split = nullptr;
    for(int ring = scaffold_on() ? 1 : 0; ring >= 0 && !split; --ring)
    {
      // (the scaffold ring may leave no room to open it; apply() still checks the result)
      Phase_timer timer(m_timings.topology);
      if(ring == 0) m_topology.set_scaffold(nullptr);
      m_topology.boundary_splits(Cut_mesh::prev(h), ops);
      if(ring == 0 && scaffold_on()) m_topology.set_scaffold(&m_scaffold);
      for(const Operation& op : ops) if(m_cm.corner_vertex[op.tips.front()] == to) split = &op;
    }
    if(!split) return false;
    if(apply(*split)) return true;
    if(!scaffold_on()) return false;
    // Where the distortion would rather close the shortcut than open it,
    // its sides cross in the stencil solve: open it a little instead (each
    // copy towards its own faces), for the descent to settle with the scaffold.
    Operation op = *split;
    if(!open_slightly(op)) return false;
    return apply(op);
  }

  // New positions of a split's two copies: a step from where the vertex is
  // towards the centroid of each copy's faces, flipping none of them.
  bool open_slightly(Operation& op) const
  {
    const Vertex_corners& vc = m_topology.vertex_corners();
    const int v = m_cm.uv_vertex[op.uv_a];
    const double* p = &m_cm.uv[2*op.uv_a];
    double c[2][2] = { { 0, 0 }, { 0, 0 } };
    int n[2] = { 0, 0 };
    std::vector<std::pair<int, int> > faces; // (corner, copy)
    for(int k = vc.offset[v]; k < vc.offset[v + 1]; ++k)
    {
      const int corner = vc.corners[k];
      if(m_cm.corner_uv[corner] != op.uv_a) continue;
      const int copy = std::find(op.corners.begin(), op.corners.end(), corner) != op.corners.end() ? 1 : 0;
      faces.emplace_back(corner, copy);
      for(int j : { Cut_mesh::next(corner), Cut_mesh::prev(corner) })
        for(int d = 0; d < 2; ++d) c[copy][d] += m_cm.uv[2 * m_cm.corner_uv[j] + d] / 2;
      ++n[copy];
    }
    if(n[0] == 0 || n[1] == 0) return false;
    for(double eps = 0.1; eps > 1e-4; eps *= 0.5)
    {
      double q[2][2];
      for(int copy = 0; copy < 2; ++copy)
        for(int d = 0; d < 2; ++d) q[copy][d] = p[d] + eps * (c[copy][d] / n[copy] - p[d]);
      bool flipped = false;
      for(const std::pair<int, int>& fc : faces)
        flipped = flipped || !(signed_area2(q[fc.second], &m_cm.uv[2 * m_cm.corner_uv[Cut_mesh::next(fc.first)]],
                                            &m_cm.uv[2 * m_cm.corner_uv[Cut_mesh::prev(fc.first)]]) > 0);
      if(flipped) continue;
      op.new_u[0] = q[0][0]; op.new_u[1] = q[0][1];
      op.new_u[2] = q[1][0]; op.new_u[3] = q[1][1];
      return true;
    }
    return false;
  }

  // Zips the seam path (halfedges towards its tip) from the tip, with a
  // descent where a merge cannot be placed; `zipped` merges done.
  Error_code zip(const std::vector<int>& seam, std::size_t& zipped)
  {
    zipped = 0;
    for(std::size_t i = seam.size(); i-- > 0; ++zipped)
    {
      Operation op;
      bool merged = false;
      for(int attempt = 0; attempt < 2 && !merged && !m_cancelled; ++attempt)
      {
        if(attempt == 1)
        {
          m_tips.clear();
          if(!m_newton.rebuild_pattern()) return ERROR_LINEAR_SOLVER;
          const Error_code status = descend();
          if(status != OK) return status;
        }
        bool can = false;
        {
          Phase_timer timer(m_timings.topology);
          can = m_topology.merge_at(seam[i], op);
        }
        merged = can && apply(op);
      }
      if(m_cancelled) return WARNING_CANCELLED;
      if(!merged) break;
    }
    return OK;
  }

  // Applies op; with a scaffold, an op whose result would overlap is undone
  // (false).
  bool apply(const Operation& op)
  {
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
    Scaffold fresh;
    fresh.settings = m_scaffold.settings;
    if(!fresh.build(m_cm)) return false;
    m_scaffold = std::move(fresh);
    // (again, if a mismatched scaffold had to be dropped: see rebuild_scaffold())
    if(scaffold_on()) m_newton.set_scaffold(&m_scaffold);
    return true;
  }

  // Scaffold positions live in the scaffold; Newton's unified vector is
  // charts' UVs then scaffold vertices.
  const double* scaffold_positions()
  {
    m_x.resize(m_cm.uv.size() + m_scaffold.pos.size());
    std::copy(m_cm.uv.begin(), m_cm.uv.end(), m_x.begin());
    std::copy(m_scaffold.pos.begin(), m_scaffold.pos.end(), m_x.begin() + m_cm.uv.size());
    return m_x.data();
  }

  bool rebuild_scaffold()
  {
    if(scaffold_on())
    {
      ++m_scaffold_rebuilds;
      // a kept scaffold must still match the UV vertices (it does unless a
      // topology edit was undone under it)
      if(!build_scaffold() && m_scaffold.n_uv != int(m_cm.number_of_uv_vertices())) m_newton.set_scaffold(nullptr);
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
        local->set_scaffold(scaffold_on() ? &m_scaffold : nullptr);
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
    if(!dual_step(e_sd, m_settings.distortion_bound, m_settings.kappa, ops, m_lambda)) return false;
    if(!m_visitor.on_lambda_update(progress())) { m_cancelled = true; return false; }
    return true;
  }

  void record(double e_sd, double e_se)
  {
    if(m_settings.fixed_lambda || e_sd > m_settings.distortion_bound) return;
    if(m_has_best && e_se >= m_best_se) return;
    if(m_lazy && count_overlapping_pairs(m_cm, 1) > 0) return; // not a result
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
  Scaffold m_scaffold;
  Optimization_timings m_timings; // topology and scaffold; Newton keeps its own
  Deadline m_deadline;
  std::vector<double> m_x;
  std::size_t m_scaffold_rebuilds = 0, m_rejected = 0;
  std::size_t m_detached_faces = 0;
  bool m_rebuilt_at_convergence = false;
  std::vector<int> m_tips;
  std::set<std::pair<long long, long long> > m_seen;
  std::size_t m_stationary_points = 0, m_best_at = 0;
  bool m_lazy = false; // bijective, but no scaffold yet
  bool m_defer_pattern = false; // a batch of operations: the Newton pattern is analysed after it
  std::vector<std::pair<int, int> > m_straightened; // (start, tip) of the detours tried from the best

  double m_safe_lambda = 0;
  Uv_snapshot m_safe;
  Uv_snapshot m_initial; // restart_at_overlap
  bool m_restart_at_overlap = false; // (initial map without seams)
  bool m_has_best = false;
  bool m_best_polished = false;
  double m_best_se = 0, m_best_lambda = 0;
  Uv_snapshot m_best;
  CGAL::Real_timer m_timer;
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
