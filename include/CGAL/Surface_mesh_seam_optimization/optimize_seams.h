// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_OPTIMIZE_SEAMS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_OPTIMIZE_SEAMS_H

#include <CGAL/Surface_mesh_seam_optimization/Seam_optimization_visitor.h>
#include <CGAL/Surface_mesh_seam_optimization/Cut_strategy.h>
#include <CGAL/Surface_mesh_seam_optimization/Seam_optimizer.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Extremity_cuts.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/pack_charts.h>
#include <CGAL/Surface_mesh_seam_optimization/seam_costs.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Multiresolution.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Join_slits.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Parallel_starts.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

namespace internal {

// optimize_seams(), less the E_SD start it gives a non-barrier energy.
// (Nested: a start's run from its own seams, one start.)
template <typename TriangleMesh, typename UVMap, typename NamedParameters, bool Nested = false>
Optimization_result optimize_seams_impl(const TriangleMesh& tm, UVMap uvmap, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;

  CGAL::Real_timer timer;
  timer.start();
  Optimization_result result;
  typedef std::decay_t<decltype(choose_parameter(get_parameter(np, internal_np::energy),
                                                 Symmetric_Dirichlet_energy()))> Energy;
  typedef std::decay_t<decltype(choose_parameter(get_parameter(np, CGAL::internal_np::sparse_linear_solver),
                                                 Default_sparse_solver_traits()))> Solver;
  auto visitor_holder = internal::visitor_parameter(np); // a copy of a visitor passed by value
  auto& visitor = internal::unwrap_visitor(visitor_holder);

  constexpr bool pack = !parameters::is_default_parameter<NamedParameters, internal_np::texture_size_t>::value;
  const internal::Packing_settings packing = internal::packing_settings(np);
  if(pack)
  {
    result.status = internal::check_packing_settings(packing, result.message);
    if(result.status != OK) return result;
  }

  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::cut_strategy_t>::value)
  {
    if(get_parameter(np, internal_np::cut_strategy) == EBCUTS)
    {
      const Energy energy = choose_parameter(get_parameter(np, internal_np::energy), Symmetric_Dirichlet_energy());
      double bound = 0;
      if(!internal::read_distortion_bound(np, energy, bound, result.message))
        return result;
      if(pack || !parameters::is_default_parameter<NamedParameters, internal_np::seam_weight_t>::value)
      {
        result.message = "cut_strategy EBCUTS takes no seam_weight or texture_size";
        return result;
      }
      if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value)
        return internal::extremity_cuts(tm, uvmap, get_parameter(np, internal_np::edge_is_seam_map), np, energy, bound);
      else
        return internal::extremity_cuts(tm, uvmap, get(CGAL::dynamic_edge_property_t<bool>(), tm), np, energy, bound);
    }
  }

  const int starts = choose_parameter(get_parameter(np, internal_np::number_of_starts),
                                     internal::default_number_of_starts);
  if(starts < 1 || starts > 4)
  {
    result.status = ERROR_WRONG_PARAMETER;
    result.message = "number_of_starts must be 1, 2, 3 or 4";
    return result;
  }

  typedef internal::Start_visitor<std::remove_reference_t<decltype(visitor)> > Visitor;
  typedef Seam_optimizer<TriangleMesh, Energy, Solver, Visitor> Optimizer;
  typedef internal::Seam_optimizer_access Access;
  std::atomic<bool> stop(false);
  internal::Iteration_budget budget(internal::second_start_iteration_factor);
  Visitor first_visitor(&visitor, stop, &budget, true), second_visitor(nullptr, stop, &budget, false);
  // one place runs the optimization and fills the result: Seam_optimizer
  std::unique_ptr<Optimizer> first = Access::set_up<Optimizer>(tm, uvmap, first_visitor, np);
  // Bound mode: more starts, the shortest feasible result kept; each finds
  // shorter seams than the others on some meshes (issue 19). They are
  // numbered by kind (Optimization_result::start) and taken in the order of
  // their gain on the 40 benchmark meshes (notes/issue19): with the
  // scaffold, the relaxed start (2), then the first-cut start (3), then the
  // hold-price start (1); without it, the hold-price start, then the
  // first-cut start. With two starts and the scaffold, the second is the
  // first-cut start where the first start's charts never overlap (below).
  constexpr bool bound_mode = parameters::is_default_parameter<NamedParameters, internal_np::seam_weight_t>::value;
  // (the kinds of the starts after the first, in the order they run)
  std::vector<int> taken;
  // Where the first start's charts never overlap, the relaxed start has
  // nothing to relax: the second start is then the first-cut start, run
  // beside the first from the beginning and dropped (whatever it reached) if
  // the charts do overlap; it runs again, from its beginning, after a relaxed
  // start that finds nothing feasible. Which one counts depends on the first
  // start alone, so the result does not depend on the schedule (40 benchmark
  // meshes: 0.964 -> 0.957, shorter on 7 of the 16 whose charts never
  // overlap, those up to x1.6 slower: the two starts share the cores).
  bool first_cut_unless_overlap = false;
  if constexpr(bound_mode && !Nested)
  {
    if(first->status() == OK)
    {
      const bool bijective = choose_parameter(get_parameter(np, internal_np::bijective), true);
      const bool user_start = choose_parameter(get_parameter(np, internal_np::use_uv_map_as_initial), false);
      // (no relaxed start without the scaffold, no first cut from the user's map)
      for(const int kind : bijective ? std::vector<int>{2, 3, 1} : std::vector<int>{1, 3})
        if(!(kind == 3 && user_start) && int(taken.size()) < starts - 1) taken.push_back(kind);
      first_cut_unless_overlap = bijective && !user_start && taken.size() == 1;
    }
  }
  auto takes = [&](int kind) { return std::find(taken.begin(), taken.end(), kind) != taken.end(); };
  const bool has_second = takes(1), has_third = takes(2), has_fourth = takes(3) || first_cut_unless_overlap;
  // raised when the first-cut start must end: a stop, or the overlap that
  // makes it the relaxed start's turn (first_cut_unless_overlap), which
  // drops its run
  std::atomic<bool> fourth_stop(false);
  bool fourth_dropped = false;
  // The hold-price start: the first's setup, with a dual step that holds the
  // price of distortion while a cut pays at it (hand1: 13.67 -> 10.08).
  // Copies of solver traits share their solver (as CGAL's do): the second
  // start gets a solver of its own, but for a solver the user gave, a copy,
  // and then the starts take turns.
  constexpr bool shared_solver =
    !parameters::is_default_parameter<NamedParameters, CGAL::internal_np::sparse_linear_solver_t>::value;
  std::unique_ptr<Optimizer> second;
  if(has_second)
    second = Access::copy_setup(*first, second_visitor,
                                choose_parameter(get_parameter(np, CGAL::internal_np::sparse_linear_solver), Solver()),
                                internal::HOLD_PRICE_WHILE_PAYING);
  // The relaxed start (with the scaffold): the seams optimized without
  // the scaffold first, then the scaffold run from the default initial map of
  // those seams. The relaxed problem's cuts are kept; a run with the scaffold
  // from the start takes its cuts while the charts' parts press on each other
  // and buys many cheap ones instead (rgb_dragon_o_f8000: 28.6 against 21.4;
  // notes/issue19). The run without the scaffold is the first start's up to
  // the end of its lazy phase (no overlap yet): it forks from there (if that
  // phase never ends, there is nothing to relax and it ends). Both phases run
  // within an iteration budget, on their own maps (made only for this start).
  auto feasible = [](const Optimization_result& r) { return r.has_result() && r.bound_met; };
  typedef typename boost::property_traits<UVMap>::value_type Uv;
  std::optional<decltype(get(CGAL::dynamic_halfedge_property_t<Uv>(), tm))> third_uv_holder;
  std::optional<decltype(get(CGAL::dynamic_edge_property_t<bool>(), tm))> third_seam_holder;
  Optimization_result third;
  Visitor third_visitor(nullptr, stop, &budget, false);
  internal::Handoff<Optimizer> free_run;
  bool third_time_limited = false;
  if(has_third)
  {
    third_uv_holder.emplace(get(CGAL::dynamic_halfedge_property_t<Uv>(), tm));
    third_seam_holder.emplace(get(CGAL::dynamic_edge_property_t<bool>(), tm));
    Access::set_lazy_phase_end_hook(*first, [&] {
      std::unique_ptr<Optimizer> forked =
        Access::fork_free(*first, third_visitor,
                          choose_parameter(get_parameter(np, CGAL::internal_np::sparse_linear_solver), Solver()));
      // (before the hand-off: the relaxed start's lane reads it then)
      if(first_cut_unless_overlap)
      {
        fourth_dropped = true;
        fourth_stop.store(true);
      }
      free_run.give(std::move(forked));
    });
  }
  // The first-cut start: EBCuts' first cut (the shortest path from
  // the vertex of largest distortion of the map minimized with the initial
  // seams to the nearest seam or border), then one start from the default
  // initial map of those seams. The greedy growth from the uncut map can
  // wind its seams (torusOnPlane: a helix over the tube, 1.2 times the
  // paper's code's seams; from a straight first cut 0.78 times; notes/issue19).
  std::optional<decltype(get(CGAL::dynamic_halfedge_property_t<Uv>(), tm))> fourth_uv_holder;
  std::optional<decltype(get(CGAL::dynamic_edge_property_t<bool>(), tm))> fourth_seam_holder;
  Optimization_result fourth;
  // Beside the first start, on the lane the relaxed start leaves idle, the
  // first-cut start does at most the first's iterations (half its budget), so
  // that the call still takes about one start's time there (face_f10000:
  // 848 iterations against the first's 410, for longer seams).
  Visitor fourth_visitor(nullptr, fourth_stop, &budget, false,
                         first_cut_unless_overlap ? internal::first_cut_beside_first_share : 1.);
  bool fourth_time_limited = false;
  if(has_fourth)
  {
    fourth_uv_holder.emplace(get(CGAL::dynamic_halfedge_property_t<Uv>(), tm));
    fourth_seam_holder.emplace(get(CGAL::dynamic_edge_property_t<bool>(), tm));
  }
  auto run_first = [&] {
    // (even on an exception)
    struct Done
    {
      internal::Iteration_budget& b;
      internal::Handoff<Optimizer>& h;
      std::atomic<bool>& stop;
      std::atomic<bool>& fourth_stop;
      ~Done()
      {
        // (the stop the first start's visitor or exception raises ends them all)
        if(stop.load() || std::uncaught_exceptions() > 0) fourth_stop.store(true);
        b.first_done();
        h.settle();
      }
    } done{budget, free_run, stop, fourth_stop};
    Access::begin(*first);
    first->run();
  };
  auto run_second = [&] { Access::begin(*second); second->run(); };
  auto run_third = [&] {
    if constexpr(!Nested)
    {
      auto& third_uv = *third_uv_holder;
      auto& third_seam = *third_seam_holder;
      std::unique_ptr<Optimizer> forked = free_run.take();
      if(stop.load()) return;
      // Where the charts never overlapped, the first start's run was the
      // relaxed problem's and its result is already bijective: the scaffold
      // phase would only start over from the same seams (on the 40 benchmark
      // meshes it never found shorter ones there), so the relaxed start ends.
      if(!forked) return;
      third_visitor.add_iterations(Access::iterations(*forked));
      Access::resume(*forked);
      const Optimization_result relaxed = forked->run();
      if(feasible(relaxed)) forked->write_seam_map(third_seam);
      third_time_limited = relaxed.status == WARNING_TIME_LIMIT;
      if(!feasible(relaxed) || stop.load() || relaxed.status == WARNING_CANCELLED) return;
      // its slits join the border first: under the scaffold a hole opens little
      // (lucy_o_f8000: 9 slits, seams 13.05 -> 10.19)
      join_slits_to_border(tm, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tm)),
                           third_seam);
      double limit = std::numeric_limits<double>::infinity();
      internal::read_time_limit(np, limit);
      const auto scaffold_np = np.number_of_starts(1).bijective(true).use_uv_map_as_initial(false)
                                 .edge_is_seam_map(third_seam).visitor(std::ref(third_visitor))
                                 .time_limit((std::max)(limit - timer.time(), 1e-9));
      third = optimize_seams_impl<TriangleMesh, std::decay_t<decltype(third_uv)>, std::decay_t<decltype(scaffold_np)>,
                                  true>(tm, third_uv, scaffold_np);
      third_time_limited = third_time_limited || third.status == WARNING_TIME_LIMIT;
      third.iterations += relaxed.iterations;
      third.topology_operations += relaxed.topology_operations;
      third.scaffold_rebuilds += relaxed.scaffold_rebuilds;
      third.timings += relaxed.timings;
      third.initial_distortion = relaxed.initial_distortion;
    }
  };
  auto run_fourth = [&] {
    if constexpr(!Nested)
    {
      if(fourth_stop.load()) return;
      auto& fourth_uv = *fourth_uv_holder;
      auto& fourth_seam = *fourth_seam_holder;
      // (from its beginning, also when it runs again after a dropped run: the
      // initial seams, as the other starts read them)
      fourth = Optimization_result();
      fourth_visitor.restart();
      for(auto e : edges(tm))
      {
        bool seam = false;
        if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value)
          seam = get(get_parameter(np, internal_np::edge_is_seam_map), e);
        put(fourth_seam, e, seam);
      }
      const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                        get_const_property_map(CGAL::vertex_point, tm));
      const Energy energy = choose_parameter(get_parameter(np, internal_np::energy), Symmetric_Dirichlet_energy());
      double limit = std::numeric_limits<double>::infinity();
      internal::read_time_limit(np, limit);
      // (stopped with the other starts by a cancel)
      const Optimization_result minimized = internal::minimize_distortion_impl(
        tm, fourth_uv,
        parameters::energy(energy).vertex_point_map(vpm).edge_is_seam_map(fourth_seam)
          .time_limit((std::max)(limit - timer.time(), 1e-9)),
        &fourth_stop);
      if(fourth_stop.load()) return;
      fourth_time_limited = minimized.status == WARNING_TIME_LIMIT;
      // (a map within the bound needs no cut: the first start's run is this start's)
      if(!minimized.has_result() || minimized.bound_met || fourth_time_limited) return;
      if(!internal::cut_from_the_worst_vertex(tm, vpm, fourth_seam,
                                              internal::face_area_and_density(tm, vpm, fourth_uv, energy)))
        return;
      const auto start_np = np.number_of_starts(1).use_uv_map_as_initial(false).edge_is_seam_map(fourth_seam)
                              .visitor(std::ref(fourth_visitor)).time_limit((std::max)(limit - timer.time(), 1e-9));
      fourth = optimize_seams_impl<TriangleMesh, std::decay_t<decltype(fourth_uv)>, std::decay_t<decltype(start_np)>,
                                   true>(tm, fourth_uv, start_np);
      fourth_time_limited = fourth.status == WARNING_TIME_LIMIT;
      fourth.timings += minimized.timings;
    }
  };
  // The first start on the calling thread, the next beside it, the others
  // after that one (on two cores: after the first start).
  std::vector<std::function<void()>> others;
  for(const int kind : taken)
    others.push_back(kind == 1 ? std::function<void()>(run_second)
                               : kind == 2 ? std::function<void()>(run_third) : std::function<void()>(run_fourth));
  // (the first-cut start until the charts overlap, then the relaxed start;
  // where that finds nothing, the first-cut start again, from its beginning)
  if(first_cut_unless_overlap)
    others = { [&] {
      run_fourth();
      run_third();
      if(!fourth_dropped || feasible(third)) return;
      // (lowered before `stop` is read: a stop raises `stop` before it
      // raises `fourth_stop` again)
      fourth_stop.store(false);
      if(stop.load())
      {
        fourth_stop.store(true);
        return;
      }
      fourth_dropped = false;
      run_fourth();
    } };
  auto run_rest = [&] { for(std::size_t i = 1; i < others.size(); ++i) others[i](); };
  auto run_others = [&] {
    if(others.size() > 1) internal::run_side_by_side(others[0], run_rest, stop);
    else if(!others.empty()) others[0]();
  };
  if(!others.empty() && !shared_solver)
    internal::run_side_by_side(run_first, run_others, stop);
  else
  {
    run_first();
    for(auto& run : others) run();
  }

  // the first start's result, unless the second is feasible and cheaper; after
  // a stop asked by the user's visitor, the first's (the run the visitor watched)
  Optimizer* kept = first.get();
  result = first->result();
  if(second && !stop.load())
  {
    Optimization_result other = second->result();
    if(feasible(other) && (!feasible(result) || Access::seam_cost(*second) < Access::seam_cost(*first)))
    {
      kept = second.get();
      result = std::move(other);
      result.start = 1;
      // (its iteration budget stopped it, not the user)
      if(result.status == WARNING_CANCELLED) result.status = OK;
    }
  }
  // a nested start's result replaces the kept one if feasible and cheaper
  double kept_cost = Access::seam_cost(*kept);
  auto compete = [&](Optimization_result& candidate, std::size_t start) {
    if(!feasible(candidate) || (feasible(result) && !(candidate.weighted_seam_length_normalized < kept_cost)))
      return false;
    kept_cost = candidate.weighted_seam_length_normalized;
    result = std::move(candidate);
    result.start = start;
    // (its iteration budget stopped it, not the user)
    if(result.status == WARNING_CANCELLED) result.status = OK;
    return true;
  };
  bool third_kept = has_third && !stop.load() && compete(third, 2);
  // (a first-cut start dropped at the overlap competes with nothing)
  const bool fourth_counts = has_fourth && !fourth_dropped;
  const bool fourth_kept = fourth_counts && !stop.load() && compete(fourth, 3);
  if(fourth_kept) third_kept = false;
  // the time limit that cut any start short cut the call short: the kept
  // result is the best so far, not the one an unlimited call would give
  if(result.status == OK && (first->status() == WARNING_TIME_LIMIT ||
                             (second && second->status() == WARNING_TIME_LIMIT) || third_time_limited ||
                             (fourth_counts && fourth_time_limited)))
    result.status = WARNING_TIME_LIMIT;
  if(!has_result(result.status)) return result;
  if(third_kept || fourth_kept)
  {
    // (packed already, if asked: the nested run packs its own result)
    const auto& start_uv = third_kept ? *third_uv_holder : *fourth_uv_holder;
    const auto& start_seam = third_kept ? *third_seam_holder : *fourth_seam_holder;
    for(auto h : halfedges(tm))
      if(!is_border(h, tm)) put(uvmap, h, get(start_uv, h));
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value)
      for(auto e : edges(tm)) put(get_parameter(np, internal_np::edge_is_seam_map), e, get(start_seam, e));
    result.seconds = timer.time();
    return result;
  }
  if(pack)
  {
    Chart_packing_result packed;
    const Error_code ec = internal::pack_cut_mesh(Access::cut_mesh(*kept), packing, packed, result.message);
    if(ec != OK) { result.status = ec; return result; }
  }
  kept->write_uv_map(uvmap);
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value)
    kept->write_seam_map(get_parameter(np, internal_np::edge_is_seam_map));
  result.seconds = timer.time();
  return result;
}

// Whether the seam costs given are all 1 (maps of 1 change nothing).
template <typename TriangleMesh, typename NamedParameters>
bool unit_seam_costs(const TriangleMesh& tm, const NamedParameters& np)
{
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  auto all_one = [](const auto& range, const auto& map) {
    for(const auto x : range) if(!(double(get(map, x)) == 1.)) return false;
    return true;
  };
  if constexpr(!is_default_parameter<NamedParameters, internal_np::seam_cost_map_t>::value)
    if(!all_one(edges(tm), get_parameter(np, internal_np::seam_cost_map))) return false;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_seam_weight_map_t>::value)
    if(!all_one(edges(tm), get_parameter(np, internal_np::edge_seam_weight_map))) return false;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_seam_cost_map_t>::value)
    if(!all_one(vertices(tm), get_parameter(np, internal_np::vertex_seam_cost_map))) return false;
  return true;
}

// Whether a call may run from a start computed for it (a proxy's seams,
// holes joined): bound mode on E_SD, no fixed lambda, no user start, OptCuts'
// cuts and unit seam costs, the settings under which such a start is judged
// by the E_SD of its map alone. The compile-time part keeps the other
// energies from instantiating those paths.
template <typename NamedParameters>
constexpr bool may_substitute_start_v =
  std::is_same_v<std::decay_t<decltype(parameters::choose_parameter(
                   parameters::get_parameter(std::declval<const NamedParameters&>(), internal_np::energy),
                   Symmetric_Dirichlet_energy()))>, Symmetric_Dirichlet_energy> &&
  parameters::is_default_parameter<NamedParameters, internal_np::seam_weight_t>::value;

template <typename TriangleMesh, typename NamedParameters>
bool may_substitute_start(const TriangleMesh& tm, const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  if constexpr(!may_substitute_start_v<NamedParameters>) return false;
  else
    return !choose_parameter(get_parameter(np, internal_np::use_uv_map_as_initial), false) &&
           choose_parameter(get_parameter(np, internal_np::cut_strategy), OPTCUTS) == OPTCUTS &&
           unit_seam_costs(tm, np);
}

// A dense mesh: seams and map optimized on a proxy first, then carried to
// the mesh, whose own run (one start, no recut rounds: the proxy's run did the
// global search) has only local work left. Returns false (and leaves
// `result` alone) when the proxy does not apply: the caller runs the mesh.
template <typename TriangleMesh, typename UVMap, typename NamedParameters>
bool optimize_seams_through_proxy(const TriangleMesh& tm, UVMap uvmap, const NamedParameters& np,
                                  Optimization_result& result)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  typedef typename boost::property_traits<UVMap>::value_type Point_2;

  const std::size_t proxy_faces = choose_parameter(get_parameter(np, internal_np::proxy_number_of_faces),
                                                   default_proxy_number_of_faces);
  // the options the proxy has no counterpart for (maps on the input's
  // elements, a start given by the user, a fixed lambda) keep the direct run
  if constexpr(!may_substitute_start_v<NamedParameters>)
    return false;
  else
  {
    if(proxy_faces == 0 || num_faces(tm) <= 2 * proxy_faces) return false;
    if(!may_substitute_start(tm, np)) return false;
    if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value)
      for(auto e : edges(tm))
        if(get(get_parameter(np, internal_np::edge_is_seam_map), e)) return false; // initial seams given

    CGAL::Real_timer timer;
    timer.start();
    double bound = 0;
    if(!read_distortion_bound(np, Symmetric_Dirichlet_energy(), bound, result.message)) return true;
    double limit = std::numeric_limits<double>::infinity();
    if(!read_time_limit(np, limit))
    {
      result.status = ERROR_WRONG_PARAMETER;
      result.message = "time_limit must be positive";
      return true;
    }
    const std::size_t cap = number_of_iterations_parameter(np, default_number_of_iterations);

    Cut_mesh full;
    Face_graph_copy<TriangleMesh> copy;
    auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                get_const_property_map(CGAL::vertex_point, tm));
    result.status = copy_face_graph(tm, vpm, full, copy, result.message);
    if(result.status != OK) return true;
    Proxy proxy;
    if(!build_proxy(full, proxy_faces, proxy)) return false;

    auto visitor_holder = visitor_parameter(np);
    auto& visitor = unwrap_visitor(visitor_holder);
    Proxy_mesh& pm = proxy.mesh;
    auto proxy_uv = pm.add_property_map<Proxy_mesh::Halfedge_index, Proxy_kernel::Point_2>("h:uv").first;
    auto proxy_seam = pm.add_property_map<Proxy_mesh::Edge_index, bool>("e:seam", false).first;
    const Optimization_result coarse = optimize_seams_impl(
      pm, proxy_uv,
      parameters::distortion_bound(bound)
        .bijective(choose_parameter(get_parameter(np, internal_np::bijective), true))
        .number_of_starts(choose_parameter(get_parameter(np, internal_np::number_of_starts),
                                           default_number_of_starts))
        .number_of_recut_rounds(choose_parameter(get_parameter(np, internal_np::number_of_recut_rounds),
                                                 default_number_of_recut_rounds))
        .number_of_iterations(cap)
        .time_limit(limit)
        .edge_is_seam_map(proxy_seam)
        .visitor(std::ref(visitor)));
    if(!coarse.has_result())
    {
      result = coarse;
      result.proxy_faces = pm.number_of_faces();
      result.message = "on the proxy of " + std::to_string(pm.number_of_faces()) + " faces: " + result.message;
      return true;
    }
    // (a proxy run cut short by the visitor or the time limit goes on as far
    // as the mesh's run is allowed: the visitor and the limit stop it too)

    // the proxy's seams and map carried to the mesh
    std::vector<char> seam;
    std::vector<Carried_side> side;
    transfer_seams(proxy, proxy_seam, full, seam, side);
    label_uv_vertices(full, seam);
    transfer_uv_map(proxy, proxy_uv, side, full);
    const std::size_t left_iterations = cap > coarse.iterations ? cap - coarse.iterations : 0;
    // A carried map that cannot be used: the mesh is run as without a proxy,
    // in what is left. (The default map along the carried cut was a poor
    // start: on lucy_o_f24136, 58 to 77 charts and seams 2.9 to 3.5 times the
    // direct run's.)
    auto seconds_left = [&] { return (std::max)(limit - timer.time(), 1e-9); };
    auto run_directly = [&](const std::string& why) {
      result = optimize_seams_impl(tm, uvmap, np.number_of_iterations(left_iterations).time_limit(seconds_left()));
      result.iterations += coarse.iterations;
      result.seconds = timer.time();
      const std::string note = "the map carried from a proxy of " + std::to_string(pm.number_of_faces()) +
                               " faces " + why + ": optimized without it";
      result.message = result.message.empty() ? note : note + "; " + result.message;
      return true;
    };
    std::size_t folds = 0;
    if(!untangle_uv_map(full, folds)) return run_directly("kept " + std::to_string(folds) + " folded triangles");
    auto start_uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), tm);
    auto start_seam = get(CGAL::dynamic_edge_property_t<bool>(), tm);
    write_uv_map(full, copy, start_uv);
    for(auto e : edges(tm)) put(start_seam, e, false);
    for(std::size_t h = 0; h < seam.size(); ++h)
      if(seam[h]) put(start_seam, edge(copy.corner_halfedge[h], tm), true);

    Optimization_result fine = optimize_seams_impl(
      tm, start_uv, np.edge_is_seam_map(start_seam).number_of_starts(1).number_of_recut_rounds(0)
                      .number_of_iterations(left_iterations).time_limit(seconds_left()).use_uv_map_as_initial(true));
    if(!fine.has_result()) return run_directly("was not usable (" + fine.message + ")");
    result = fine;
    result.proxy_faces = pm.number_of_faces();
    result.iterations += coarse.iterations;
    result.topology_operations += coarse.topology_operations;
    result.scaffold_rebuilds += coarse.scaffold_rebuilds;
    result.seconds = timer.time();
    for(auto h : halfedges(tm))
      if(!is_border(h, tm)) put(uvmap, h, get(start_uv, h));
    if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value)
      for(auto e : edges(tm)) put(get_parameter(np, internal_np::edge_is_seam_map), e, get(start_seam, e));
    return true;
  }
}

// A chart with holes (several boundary loops) keeps them in the initial
// map. Where a hole is as large as the chart's other loop, as at the two
// ends of a tube, that map is far from isometric (CGAL's blade.off: E_SD 40,
// where the tube cut open from end to end unrolls at 4.00), and the greedy
// topology steps cannot find the cure: a cut pays only once it joins the two
// loops, so they buy hundreds of short ones (blade: E_SD still 42.9 after
// 540 s). So where the map with the holes kept misses the bound, the holes
// are also joined to their component's largest loop along shortest paths,
// and the run starts from those seams if their map is less distorted (else
// as before, in the time left). Returns false (and leaves `result` alone)
// when there is no hole to join: the caller runs the mesh.
template <typename TriangleMesh, typename UVMap, typename NamedParameters>
bool optimize_seams_with_joined_holes(const TriangleMesh& tm, UVMap uvmap, const NamedParameters& np,
                                      Optimization_result& result)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  typedef typename boost::property_traits<UVMap>::value_type Point_2;
  // (a fixed lambda, regional seam costs and the user's own start keep the direct run)
  if constexpr(!may_substitute_start_v<NamedParameters>)
    return false;
  else
  {
    if(!may_substitute_start(tm, np)) return false;
    if(faces(tm).empty() || !CGAL::is_triangle_mesh(tm)) return false; // (the run reports it)
    CGAL::Real_timer timer;
    timer.start();
    auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                get_const_property_map(CGAL::vertex_point, tm));
    auto kept_seam = get(CGAL::dynamic_edge_property_t<bool>(), tm);
    auto joined_seam = get(CGAL::dynamic_edge_property_t<bool>(), tm);
    for(auto e : edges(tm))
    {
      bool seam = false;
      if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value)
        seam = get(get_parameter(np, internal_np::edge_is_seam_map), e);
      put(kept_seam, e, seam);
      put(joined_seam, e, seam);
    }
    for(auto v : vertices(tm))
    {
      const auto p = get(vpm, v);
      for(int k = 0; k < 3; ++k) if(!std::isfinite(CGAL::to_double(p[k]))) return false; // (the run reports it)
    }
    // (cheap: most meshes have no hole to join)
    if(join_slits_to_border(tm, vpm, joined_seam, true) == 0) return false;
    double bound = 0;
    std::string ignored;
    if(!read_distortion_bound(np, Symmetric_Dirichlet_energy(), bound, ignored)) return false;
    double limit = std::numeric_limits<double>::infinity();
    if(!read_time_limit(np, limit)) return false;
    auto uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), tm);
    auto minimized = [&](auto seam) {
      return minimize_distortion_impl(tm, uv, parameters::vertex_point_map(vpm).edge_is_seam_map(seam)
                                                .distortion_bound(bound)
                                                .time_limit((std::max)(limit - timer.time(), 1e-9)), nullptr);
    };
    // (the run as without holes to join, in the time left)
    auto as_before = [&] {
      if(std::isfinite(limit))
      {
        const auto left = np.time_limit((std::max)(limit - timer.time(), 1e-9));
        if(!optimize_seams_through_proxy(tm, uvmap, left, result)) result = optimize_seams_impl(tm, uvmap, left);
      }
      else if(!optimize_seams_through_proxy(tm, uvmap, np, result))
        result = optimize_seams_impl(tm, uvmap, np);
      result.seconds = timer.time();
      return true;
    };
    const Optimization_result kept = minimized(kept_seam);
    if(kept.status != OK || kept.bound_met) return as_before();
    const Optimization_result joined = minimized(joined_seam);
    if(joined.status != OK || !(joined.distortion_at_optimal_scale < kept.distortion_at_optimal_scale))
      return as_before();
    result = optimize_seams_impl(tm, uvmap, np.edge_is_seam_map(joined_seam)
                                               .time_limit((std::max)(limit - timer.time(), 1e-9)));
    if(result.has_result())
      if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_is_seam_map_t>::value)
        for(auto e : edges(tm)) put(get_parameter(np, internal_np::edge_is_seam_map), e, get(joined_seam, e));
    result.seconds = timer.time();
    const std::string note = "holes joined to the border (their map with the holes kept: E_SD " +
                             std::to_string(kept.distortion_at_optimal_scale) + ", joined: " +
                             std::to_string(joined.distortion_at_optimal_scale) + ")";
    result.message = result.message.empty() ? note : note + "; " + result.message;
    return true;
  }
}

} // namespace internal

/// \ingroup PkgSurfaceMeshSeamOptimizationFunctions
/// Jointly optimizes the seams and the UV map of `tm` (OptCuts): the shortest
/// seams it finds whose map meets the distortion bound, or, with
/// `seam_weight`, a stationary point of E_w = (1 - lambda) E_SD + lambda E_se.
///
/// \tparam TriangleMesh a model of `FaceGraph` (triangles only)
/// \tparam UVMap a read-write property map `halfedge_descriptor -> Point_2`
///   (for every halfedge `h` with a face, the UV of `target(h)` in `face(h)`)
///
/// \param tm a triangle mesh of any genus, with any number of boundary loops and connected
///   components (see `compute_initial_parameterization()` for how it is cut into charts first;
///   in bound mode, where the map with a chart's holes kept misses the bound, the holes are
///   joined to the chart's largest loop by shortest paths if that map is less distorted, and
///   `Optimization_result::message` says so)
/// \param uvmap receives the UV map
/// \param np an optional sequence of \ref PkgSurfaceMeshSeamOptimizationNamedParameters "named parameters"
///   among the ones listed below, chained in any order
///   (`parameters::distortion_bound(4.1).bijective(false).vertex_point_map(vpm)`; a parameter given twice
///   takes its last value):
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{distortion_bound}
///     \cgalParamDescription{bound on the normalized `energy` (E_SD by default), above its minimum; the result
///       meets it with the shortest seams found}
///     \cgalParamType{`double` (any arithmetic type)}
///     \cgalParamDefault{the energy's `default_bound()`: `4.1` for `Symmetric_Dirichlet_energy` (minimum 4),
///       \f$2 + 0.025(1 + w)\f$ for `Conformal_energy` with area weight \f$w\f$ (minimum 2; 2.02525 by
///       default), `0.025` for `ARAP_energy` (minimum 0)}
///   \cgalParamNEnd
///   \cgalParamNBegin{seam_weight}
///     \cgalParamDescription{a fixed lambda in [0, 1): no bound, no dual step}
///     \cgalParamType{`double` (any arithmetic type)}
///     \cgalParamDefault{none (bound mode)}
///   \cgalParamNEnd
///   \cgalParamNBegin{bijective}
///     \cgalParamDescription{keep the charts from overlapping one another or themselves: the space between
///       them is meshed (a scaffold) and no triangle of charts or scaffold may flip.
///       With `use_uv_map_as_initial`, the given map must then be bijective (else `ERROR_OVERLAPPING_UV_MAP`)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`true`}
///   \cgalParamNEnd
///   \cgalParamNBegin{edge_is_seam_map}
///     \cgalParamDescription{read-write `edge_descriptor -> bool`: initial seams, and the result}
///     \cgalParamType{a model of `ReadWritePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///       as key type and `bool` as value type}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{seam_cost_map}
///     \cgalParamDescription{regional seam preferences: `edge_descriptor -> double` (>= 0) multiplying each edge's
///       length in the seam term E_se, which the topology steps and the dual step optimize (> 1 repels seams,
///       < 1 attracts them, 0 makes them free); `Optimization_result::weighted_seam_length_normalized` reports
///       the weighted term, `seam_length_normalized` the plain one. A negative or non-finite value gives
///       `ERROR_WRONG_PARAMETER`. `edge_seam_weight_map`, the package's former name, is a deprecated alias,
///       read when `seam_cost_map` is not given}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
///       as key type and a value type convertible to `double`}
///     \cgalParamDefault{all 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_seam_cost_map}
///     \cgalParamDescription{the per-vertex form of `seam_cost_map`: an edge's cost is the mean of its two
///       vertices' (multiplied by its `seam_cost_map` value when both are given); `region_seam_costs()` makes
///       one from a painted region of vertices}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a value type convertible to `double`}
///     \cgalParamDefault{all 1}
///   \cgalParamNEnd
///   \cgalParamNBegin{use_uv_map_as_initial}
///     \cgalParamDescription{start from the UVs of `uvmap` and the seams they imply; flipped or degenerate
///       triangles are untangled first, as in `minimize_distortion()`, and `Optimization_result::message`
///       says so}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{the 3D points}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///       as key type and a 3D point type as value type}
///     \cgalParamDefault{`get_const_property_map(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{a model of `Kernel`, passed on to `compute_initial_parameterization()` (the
///       types of the initial map); the optimization itself works in `double`}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{the kernel of the point type of `vertex_point_map`}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy}
///     \cgalParamDescription{a model of `DistortionEnergy`: the descent steps minimize it, the topology steps
///       price cuts by it and the bound is on it (`Optimization_result::energy_value`; E_SD is reported too)}
///     \cgalParamType{a model of `DistortionEnergy`}
///     \cgalParamDefault{`Symmetric_Dirichlet_energy`}
///   \cgalParamNEnd
///   \cgalParamNBegin{sparse_linear_solver}
///     \cgalParamDescription{a model of `SparseSolverTraits`}
///     \cgalParamType{a model of `SparseSolverTraits`}
///     \cgalParamDefault{`Default_sparse_solver_traits`}
///   \cgalParamNEnd
///   \cgalParamNBegin{visitor}
///     \cgalParamDescription{a model of `SeamOptimizationVisitor`. Passed by value (`visitor(v)`,
///       `visitor(My_visitor())`), it is copied and the copy is called, as in `Polygon_mesh_processing`;
///       pass `std::ref(v)` to have `v` itself called (to read its state afterwards)}
///     \cgalParamType{a model of `SeamOptimizationVisitor`, or `std::reference_wrapper` of one}
///     \cgalParamDefault{`Default_seam_optimization_visitor`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{cap on Newton iterations, in total (CGAL's parameter; `maximum_number_of_iterations`,
///       the package's former name for it, is a deprecated alias, read when `number_of_iterations` is not given)}
///     \cgalParamType{`std::size_t` (any integral type)}
///     \cgalParamDefault{`100000`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_recut_rounds}
///     \cgalParamDescription{bound mode: after the first result, rounds of unzipping a tenth of the seams where
///       they buy least and cutting again from there, each after straightening rounds (a winding seam path
///       replaced by its shortcut) while these find shorter seams; the shortest seams that meet the bound are
///       kept, and the rounds end at the first unzipping round that finds none shorter (more time for shorter
///       seams; 0 turns all of them off).
///       Reaching `number_of_iterations` during these rounds ends them with status `OK`}
///     \cgalParamType{`int` (any integral type)}
///     \cgalParamDefault{`6`}
///   \cgalParamNEnd
///   \cgalParamNBegin{cut_strategy}
///     \cgalParamDescription{`OPTCUTS`, or `EBCUTS`, the baseline of the OptCuts paper's comparison: cuts grown
///       one at a time from the vertex of largest distortion to the nearest seam or border along a shortest
///       path, the distortion minimized with the seams fixed in between (no scaffold), until the bound is met;
///       `topology_operations` counts the cuts. Not with `seam_weight` or `texture_size`}
///     \cgalParamType{`Cut_strategy`}
///     \cgalParamDefault{`OPTCUTS`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_starts}
///     \cgalParamDescription{bound mode: runs that many starts and keeps the result with the shorter
///       (weighted) seams among those that meet the bound (the lower-numbered start on a tie, the first when
///       none does). The first start (0) runs OptCuts from the initial map. The others, taken in this order
///       with `bijective` true: the relaxed start (2), which optimizes the seams without the scaffold first
///       (the first start's run, taken over where its charts first overlap; none where they never do), then
///       with the scaffold from the default initial map of those seams, their slits joined to the border
///       along shortest paths (shorter seams where parts of the mesh press on each other in UV, see the user
///       manual); the first-cut start (3), which minimizes the distortion with the initial seams, cuts the
///       shortest path from the vertex of largest distortion to the nearest seam or border (EBCuts' first
///       cut), then runs one start from the default initial map of those seams (not with
///       `use_uv_map_as_initial`; none when the minimized map already meets the bound or nothing can be
///       cut; shorter seams where the greedy growth from the uncut map winds them, e.g. a helix over a
///       tube); the hold-price start (1), the first start's setup with a dual step that holds the price of
///       distortion while some cut already pays at it. With `bijective` false: the hold-price start, then
///       the first-cut start. So 1 runs the first alone (half the work, seams longer on some meshes), and the
///       default 2 adds the relaxed start where the first start's charts overlap and the first-cut start
///       where they never do (the relaxed start has nothing to relax there); without the scaffold, the
///       hold-price start. That first-cut start runs beside the first from the beginning, does at most the
///       first's Newton iterations and is dropped, whatever it has reached, when the first start's charts
///       overlap: which start counts depends on the first start alone; where the relaxed start then finds
///       nothing that meets the bound, the first-cut start runs after it, from its beginning. The second start
///       runs beside the first, in parallel when TBB is linked, and the others after it; each start has
///       its own `number_of_iterations` and `time_limit`, and the result does not depend on the number of
///       threads (a `sparse_linear_solver` given here is shared by its copies, as CGAL's solver traits are:
///       the starts then run one after the other). Every start after the first does at most twice the
///       first's Newton iterations (then its best result so far competes), so that two starts take at
///       most about twice one start's time, whatever the schedule. The visitor is called by the first
///       start only, from the calling thread; when it stops the run, every start stops and the first's
///       result is kept (`Optimization_result::start` says which start the result comes from: 0, 1, 2 or 3)}
///     \cgalParamType{`int` (any integral type), 1, 2, 3 or 4}
///     \cgalParamDefault{`2`}
///   \cgalParamNEnd
///   \cgalParamNBegin{proxy_number_of_faces}
///     \cgalParamDescription{a mesh of more than twice this many faces is first simplified to a proxy of about
///       this many faces (edge collapses that keep input vertices), whose seams and map are optimized with the
///       settings above and carried to the mesh (seams along shortest paths, chart borders onto the proxy's,
///       the rest by harmonic interpolation); the mesh's own run then starts from there, with one start and no
///       recut rounds. Not with `seam_weight`, seam costs, `use_uv_map_as_initial`, initial seams in
///       `edge_is_seam_map`, `EBCUTS` or an energy other than `Symmetric_Dirichlet_energy` (the mesh is then
///       run directly). `Optimization_result::proxy_faces` gives the proxy's size; the iterations, operations,
///       `number_of_iterations` and `time_limit` count both runs. 0 never uses a proxy}
///     \cgalParamType{`std::size_t` (any integral type)}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{time_limit}
///     \cgalParamDescription{seconds (> 0) after which the run stops with the best result so far (in bound
///       mode the best one that met the bound, if any), status `WARNING_TIME_LIMIT`}
///     \cgalParamType{`double`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{texture_size}
///     \cgalParamDescription{when given, the result's charts are packed into [0,1]^2 for a texture of this
///       many texels (see `pack_charts()`, whose `margin`, `allow_rotation` and `equal_texel_density` are
///       read too); the figures of the result are those of the map before packing (same E_SD at the optimal
///       scale, same seams). Invalid packing parameters are refused before the optimization starts}
///     \cgalParamType{`double`}
///     \cgalParamDefault{none (not packed)}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// The bound is on the run's energy, in its own units: the defaults of the
/// three energies allow the same small strains (at \f$\sigma_i = 1 + \epsilon_i\f$,
/// E_SD - 4 is \f$4(\epsilon_1^2 + \epsilon_2^2)\f$, ARAP \f$\epsilon_1^2 + \epsilon_2^2\f$ and
/// the conformal energy minus 2 is \f$(\epsilon_1 - \epsilon_2)^2 + w(\epsilon_1 + \epsilon_2)^2\f$,
/// \f$(1 + w)/4\f$ of E_SD - 4 on average). The map of a scale-invariant energy
/// (`Conformal_energy` with `area_weight` 0) is written at the uniform scale that
/// minimizes its E_SD. An energy that is no barrier (`ARAP_energy`) gives squeezed
/// triangles a finite energy, so that from the initial map of a closed mesh no
/// split pays enough to cut into its squeezed parts: such a run starts from the
/// E_SD run at the E_SD bound allowing the same small strains (4.1 for ARAP's
/// 0.025) and goes on with its energy, unless `use_uv_map_as_initial` or
/// `seam_weight` is given; the result counts the iterations and operations of both.
/// A result with a flipped or degenerate UV triangle is never written
/// (`ERROR_DEGENERATE_UV_RESULT`).
template <typename TriangleMesh, typename UVMap,
          typename NamedParameters = parameters::Default_named_parameters>
Optimization_result optimize_seams(const TriangleMesh& tm, UVMap uvmap,
                                   const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;

  typedef std::decay_t<decltype(choose_parameter(get_parameter(np, internal_np::energy),
                                                 Symmetric_Dirichlet_energy()))> Energy;
  CGAL::Real_timer timer;
  timer.start();
  Optimization_result result;
  // An energy that is no barrier (ARAP) gives a squeezed triangle a finite
  // energy: from the initial map of a closed mesh (a short slit, the rest
  // squeezed) no split then pays enough to cut into the squeezed parts
  // (bunny_i_f10000 with ARAP stalled at 0.84 with lambda near 0, then 8094 of
  // its faces were detached). Such a run starts from the E_SD run at the E_SD
  // bound that allows the same small strains, and goes on with its energy.
  if constexpr(!std::is_same_v<Energy, Symmetric_Dirichlet_energy> &&
               parameters::is_default_parameter<NamedParameters, internal_np::seam_weight_t>::value)
  {
    const Energy energy = choose_parameter(get_parameter(np, internal_np::energy), Symmetric_Dirichlet_energy());
    const bool ebcuts = choose_parameter(get_parameter(np, internal_np::cut_strategy), OPTCUTS) == EBCUTS;
    if(!internal::is_barrier_energy(energy) && !ebcuts &&
       !choose_parameter(get_parameter(np, internal_np::use_uv_map_as_initial), false))
    {
      double bound = 0;
      if(!internal::read_distortion_bound(np, energy, bound, result.message))
        return result;
      Optimization_result warm = internal::optimize_seams_impl(
        tm, uvmap,
        np.energy(Symmetric_Dirichlet_energy())
          .distortion_bound(internal::symmetric_dirichlet_bound_with_same_strains(energy, bound)));
      // the iteration cap and the time limit are the call's: what is left goes on
      const std::size_t cap = internal::number_of_iterations_parameter(np, internal::default_number_of_iterations);
      double limit = std::numeric_limits<double>::infinity();
      internal::read_time_limit(np, limit);
      const double left = limit - timer.time();
      if(warm.status == OK || warm.status == WARNING_BOUND_NOT_MET)
      {
        if(warm.iterations >= cap) warm.status = WARNING_MAXIMUM_ITERATIONS;
        else if(!(left > 0)) warm.status = WARNING_TIME_LIMIT;
      }
      if(warm.status != OK && warm.status != WARNING_BOUND_NOT_MET)
      {
        if(warm.has_result()) // stopped: the E_SD map, judged on the run's energy
        {
          warm.energy_value = distortion(tm, uvmap, np);
          warm.bound_met = warm.energy_value <= bound;
        }
        return warm;
      }
      Optimization_result r = internal::optimize_seams_impl(
        tm, uvmap, np.use_uv_map_as_initial(true).number_of_iterations(cap - warm.iterations).time_limit(left));
      if(r.has_result())
      {
        r.initial_distortion = warm.initial_distortion;
        r.iterations += warm.iterations;
        r.topology_operations += warm.topology_operations;
        r.seconds = timer.time();
      }
      return r;
    }
  }

  if(internal::optimize_seams_with_joined_holes(tm, uvmap, np, result)) return result;
  if(internal::optimize_seams_through_proxy(tm, uvmap, np, result)) return result;
  return internal::optimize_seams_impl(tm, uvmap, np);
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
