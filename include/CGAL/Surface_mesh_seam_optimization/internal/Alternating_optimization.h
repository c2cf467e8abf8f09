// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// OptCuts with what follows its loop (Alternation.h): at the bound, the
// seams of the best configuration are zipped where the bound still holds;
// then rounds that perturb the best result (a winding seam path replaced by
// its shortcut, or a tenth of the seams unzipped) and alternate again,
// while that finds shorter seams; and, in bound mode, the last resort of
// detaching the worst triangles.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ALTERNATING_OPTIMIZATION_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_ALTERNATING_OPTIMIZATION_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Alternation.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Detach_faces.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Overlap.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Seam_paths.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Seam_reroute.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

template <typename Energy, typename SolverTraits, typename Visitor>
class Alternating_optimization : public Alternation<Energy, SolverTraits, Visitor>
{
  typedef Alternation<Energy, SolverTraits, Visitor> Base;

public:
  using Base::Base;
  using Base::bound_met;
  using Base::distortion;
  using Base::seam_cost;
  using Base::start;
  using Base::step;

  // triangles detached into charts of their own to meet the bound (see finish())
  std::size_t detached_faces() const { return m_detached_faces; }

  Error_code run()
  {
    Error_code status = start();
    while(status == OK && step(status)) {}
    return finish(status);
  }

  // Keeps the best feasible configuration (bound mode).
  Error_code finish(Error_code status)
  {
    // (a lazy phase that lasted to here: the run's result stands for the free one)
    this->drop_lazy_phase_end_hook();
    // whatever stopped a run without its scaffold, what it leaves does not overlap
    m_guard.restore_if_overlapping(m_cm);
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
          // no split left lowers the energy: the worst triangles go alone (at its minimum)
          m_detached_faces = detach_faces_until_bound(m_cm, m_settings.distortion_bound, m_energy);
          if(!bound_met()) status = WARNING_BOUND_NOT_MET;
        }
      }
    }
    return status;
  }


private:
  using Base::m_best_polished;
  using Base::m_best_se;
  using Base::m_cancelled;
  using Base::m_cm;
  using Base::m_energy;
  using Base::m_defer_pattern;
  using Base::m_guard;
  using Base::m_has_best;
  using Base::m_newton;
  using Base::m_operations;
  using Base::m_seen;
  using Base::m_settings;
  using Base::m_stationary_points;
  using Base::m_best_at;
  using Base::m_timings;
  using Base::m_tips;
  using Base::m_topology;
  using Base::m_visitor;
  using Base::apply;
  using Base::build_scaffold;
  using Base::descend;
  using Base::polish_seams;
  using Base::progress;
  using Base::rebuild_scaffold;
  using Base::record;
  using Base::restore_best;
  using Base::scaffold_on;

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
  // cannot be opened yet), and the alternation goes on from there; where it
  // cannot be replaced, the next largest (replace_largest_detour()).
  // `applied` is false if there was no such detour or none could be replaced
  // (the seams did not change then).
  Error_code straighten(bool& applied)
  {
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
    return replace_largest_detour(detours, m_settings.detour_min_saving * seam_cost(), m_straightened, ends,
                                  [this](const Seam_detour& d, bool& done) {
                                    return d.reroute ? reroute(d, done) : replace_detour(d, done);
                                  }, applied);
  }

  // Cuts the shortcut of a leaf detour and zips the detour, then alternates
  // again from there; `applied` is false if nothing could be done.
  Error_code replace_detour(const Seam_detour& d, bool& applied)
  {
    const std::vector<int>& cut = d.shortcut;
    std::size_t cuts = 0, zips = 0;
    {
      // one pattern analysis for the whole batch of operations
      struct Defer { bool& flag; explicit Defer(bool& f) : flag(f) { flag = true; } ~Defer() { flag = false; } };
      Defer defer(m_defer_pattern);
      if(split_along(cut[0]))
        // the shortcut but its last edge, whose end is still on the detour
        for(cuts = 1; cuts + 1 < cut.size() && split_along(cut[cuts]); ++cuts) {}
      const Error_code status = zip(d.seam, zips);
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
      if(ring == 0 && scaffold_on()) m_topology.set_scaffold(&m_guard.scaffold());
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

  // Zips the seam path (halfedges towards its tip) from the tip, with
  // Newton iterations where a merge cannot be placed; `zipped` merges done.
  Error_code zip(const std::vector<int>& seam, std::size_t& zipped)
  {
    zipped = 0;
    for(std::size_t i = seam.size(); i-- > 0; ++zipped)
    {
      Operation op;
      bool merged = false;
      for(int attempt = 0; attempt < 2 && !merged && !m_cancelled; ++attempt)
      {
        bool can = false;
        auto place = [&] {
          Phase_timer timer(m_timings.topology);
          return can = m_topology.merge_at(seam[i], op);
        };
        if(attempt == 1)
        {
          m_tips.clear();
          if(!m_newton.rebuild_pattern()) return ERROR_LINEAR_SOLVER;
          // only until the merge can be placed (not to a stationary point:
          // the alternation descends after the zip); a descent that ends
          // otherwise ended at a stationary point, after its last try
          const Error_code status = descend(place);
          if(status != OK) return status;
        }
        else place();
        merged = can && apply(op);
      }
      if(m_cancelled) return WARNING_CANCELLED;
      if(!merged) break;
    }
    return OK;
  }

  std::size_t m_detached_faces = 0;
  std::vector<std::pair<int, int> > m_straightened; // (start, tip) of the detours tried from the best
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
