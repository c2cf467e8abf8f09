// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_OPTIMIZER_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_OPTIMIZER_H

#include <CGAL/Surface_mesh_seam_optimization/Seam_optimization_visitor.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Alternating_optimization.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Chart_layout.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Measure_result.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Overlap.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Setup_seam_optimization.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Split_self_overlapping_charts.h>

#include <CGAL/Real_timer.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Tag of the constructor that sets nothing up (see Seam_optimizer_access).
struct Not_set_up {};

// What optimize_seams() needs of a Seam_optimizer beyond its public interface.
struct Seam_optimizer_access
{
  template <typename Optimizer>
  static Cut_mesh& cut_mesh(Optimizer& o) { return o.m_cm; }

  // the (weighted) seam cost that bound mode minimizes
  template <typename Optimizer>
  static double seam_cost(const Optimizer& o)
  {
    return o.m_core ? o.m_core->seam_cost() : std::numeric_limits<double>::infinity();
  }

  // The input checked and the initial map computed, but the first descent
  // not run (begin() runs it): several starts then share this setup.
  template <typename Optimizer, typename TriangleMesh, typename UVMap, typename Visitor, typename NamedParameters>
  static std::unique_ptr<Optimizer> set_up(const TriangleMesh& tm, UVMap uvmap, Visitor& visitor,
                                           const NamedParameters& np)
  {
    std::unique_ptr<Optimizer> o(new Optimizer(Not_set_up(), tm, visitor));
    o->set_up(uvmap, np);
    return o;
  }

  // Another start from the setup of `o` (not begun): its own copy of the
  // data, its own visitor, solver and dual-step rule. (Copies of solver
  // traits share their solver, as CGAL's do: `solver` is a fresh one.)
  template <typename Optimizer, typename Visitor, typename SolverTraits>
  static std::unique_ptr<Optimizer> copy_setup(const Optimizer& o, Visitor& visitor, const SolverTraits& solver,
                                               Dual_step_rule rule)
  {
    std::unique_ptr<Optimizer> c(new Optimizer(Not_set_up(), o.m_tm, visitor));
    c->m_timer.start();
    c->m_energy = o.m_energy;
    c->m_solver.emplace(solver);
    c->m_status = o.m_status;
    c->m_message = o.m_message;
    c->m_cm = o.m_cm;
    c->m_initial_cm = o.m_initial_cm;
    c->m_copy = o.m_copy;
    c->m_weight = o.m_weight;
    c->m_settings = o.m_settings;
    c->m_settings.dual_step_rule = rule;
    c->m_initial_distortion = o.m_initial_distortion;
    return c;
  }

  template <typename Optimizer>
  static void begin(Optimizer& o) { o.begin(); }

  // `f` is called on the run's thread where its lazy phase (bijective, no
  // scaffold yet) ends; set before begin().
  template <typename Optimizer>
  static void set_lazy_phase_end_hook(Optimizer& o, std::function<void()> f) { o.m_lazy_phase_end_hook = std::move(f); }

  // A run without bijectivity that takes over `o` where it stands (called
  // from the lazy phase end hook of `o`): a copy of its charts and of its
  // loop. Its own visitor and solver; resume() before its first step.
  template <typename Optimizer, typename Visitor, typename SolverTraits>
  static std::unique_ptr<Optimizer> fork_free(const Optimizer& o, Visitor& visitor, const SolverTraits& solver)
  {
    // (its charts as they stand: copy_setup() copies the current cut mesh)
    std::unique_ptr<Optimizer> c = copy_setup(o, visitor, solver, o.m_settings.dual_step_rule);
    c->m_settings.bijective = false;
    c->m_core.reset(new typename Optimizer::Core(c->m_cm, c->m_energy, *c->m_solver, c->m_weight, c->m_settings,
                                                 *c->m_visitor));
    c->m_core->resume(*o.m_core);
    return c;
  }

  template <typename Optimizer>
  static std::size_t iterations(const Optimizer& o) { return o.m_core ? o.m_core->iterations() : 0; }

  // The pattern of a forked run analysed (not in the hook: a solver the
  // user gave is shared, and the first run goes on with it).
  template <typename Optimizer>
  static void resume(Optimizer& o)
  {
    o.m_running = o.m_core->resume_pattern();
    if(!o.m_running) o.end(ERROR_LINEAR_SOLVER);
  }
};

} // namespace internal

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// The class behind `optimize_seams()`, for users who want to step the
/// optimization, look at it between steps, or stop it: the constructor
/// validates the input and computes the initial map (nothing is written to
/// the user's maps), `step()` performs one alternation (descent to a
/// stationary point, dual update, topology operation), `run()` goes to the
/// end, and `write_uv_map()` / `write_seam_map()` write the current result.
/// It runs one start, with OptCuts' dual step: the result of
/// `optimize_seams()` with `number_of_starts(1)`.
///
/// \tparam TriangleMesh a model of `FaceGraph`
/// \tparam Energy a model of `DistortionEnergy`
/// \tparam SolverTraits a model of `SparseSolverTraits`
/// \tparam Visitor a model of `SeamOptimizationVisitor`
template <typename TriangleMesh,
          typename Energy = Symmetric_Dirichlet_energy,
          typename SolverTraits = Default_sparse_solver_traits,
          typename Visitor = Default_seam_optimization_visitor>
class Seam_optimizer
{
  typedef internal::Alternating_optimization<Energy, SolverTraits, Visitor> Core;
  friend struct internal::Seam_optimizer_access;

public:
  /// Takes the same named parameters as `optimize_seams()` (but `visitor`;
  /// `time_limit` counts from the construction, which runs the first descent);
  /// `uvmap` is read only with `use_uv_map_as_initial(true)`.
  template <typename UVMap, typename NamedParameters = parameters::Default_named_parameters>
  Seam_optimizer(const TriangleMesh& tm, UVMap uvmap, const NamedParameters& np = parameters::default_values())
    : m_tm(tm)
  {
    m_own_visitor.emplace();
    m_visitor = &*m_own_visitor;
    initialize(uvmap, np);
  }

  /// Same, with `visitor` called during the optimization (it must outlive
  /// this object).
  template <typename UVMap, typename NamedParameters = parameters::Default_named_parameters>
  Seam_optimizer(const TriangleMesh& tm, UVMap uvmap, Visitor& visitor,
                 const NamedParameters& np = parameters::default_values())
    : m_tm(tm), m_visitor(&visitor)
  {
    initialize(uvmap, np);
  }

private:
  Seam_optimizer(internal::Not_set_up, const TriangleMesh& tm, Visitor& visitor) : m_tm(tm), m_visitor(&visitor) {}

  template <typename UVMap, typename NamedParameters>
  void initialize(UVMap uvmap, const NamedParameters& np)
  {
    set_up(uvmap, np);
    begin();
  }

  template <typename UVMap, typename NamedParameters>
  void set_up(UVMap uvmap, const NamedParameters& np)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    m_timer.start();
    m_energy = choose_parameter(get_parameter(np, internal_np::energy), Energy());
    m_solver.emplace(choose_parameter(get_parameter(np, CGAL::internal_np::sparse_linear_solver), SolverTraits()));
    m_status = internal::setup_seam_optimization(m_tm, uvmap, np, m_energy, m_cm, m_copy, m_weight, m_settings, m_message);
    if(m_status != OK) return;
    m_initial_distortion = internal::total_energy(m_cm, Symmetric_Dirichlet_energy(), m_cm.uv.data());
    if(m_settings.bijective && !m_settings.fixed_lambda) m_initial_cm = m_cm; // (see split_free_result())
  }

  // the first descent
  void begin()
  {
    if(m_status != OK) return;
    m_core.reset(new Core(m_cm, m_energy, *m_solver, m_weight, m_settings, *m_visitor));
    if(m_lazy_phase_end_hook) m_core->set_lazy_phase_end_hook(m_lazy_phase_end_hook);
    m_status = m_core->start();
    m_running = (m_status == OK);
    // (the first descent already hit the iteration cap or the time limit)
    if(!m_running) end(m_status);
  }

public:

  Seam_optimizer(const Seam_optimizer&) = delete;
  Seam_optimizer& operator=(const Seam_optimizer&) = delete;

  /// `OK` while running and after a converged run; an error code if the
  /// input was refused (then nothing else may be called but `message()`).
  Error_code status() const { return m_status; }
  const std::string& message() const { return m_message; }
  bool is_running() const { return m_running; }

  /// One alternation; returns `false` when the optimization is over (then
  /// the best feasible configuration has been restored, in bound mode). In
  /// bound mode the step that ends the run also runs the recut rounds
  /// (`number_of_recut_rounds`), which may take as long as the run so far.
  bool step()
  {
    if(!m_running) return false;
    if(!m_core->step(m_status)) end(m_status);
    return m_running;
  }

  /// Steps to the end; returns the figures of the result.
  Optimization_result run()
  {
    while(step()) {}
    return result();
  }

  /// Figures of the current configuration.
  Optimization_result result() const
  {
    Optimization_result r;
    r.status = m_status;
    r.message = m_message;
    if(!m_core) return r;
    if(!has_result(m_status)) return r;
    internal::measure_result(m_cm, m_energy, m_settings.distortion_bound, r, &m_weight);
    r.initial_distortion = m_initial_distortion;
    r.lambda = m_core->lambda();
    r.iterations = m_core->iterations() + m_replacement_iterations;
    r.topology_operations = m_core->topology_operations() + m_replacement_operations;
    r.scaffold_rebuilds = m_core->scaffold_rebuilds();
    r.timings = m_core->timings();
    r.seconds = m_timer.time();
    return r;
  }

  /// E_SD of the current map as the bound judges it (at the optimal uniform scale for a scale-invariant energy)
  double distortion() const { return internal::judged_distortion(m_cm, m_energy, m_cm.uv.data()); }
  double seam_length_normalized() const { return m_cm.seam_length() / m_cm.normalization_radius(); }
  double lambda() const { return m_core ? m_core->lambda() : 0.; }

  /// Writes the current UV map (every halfedge with a face); nothing after
  /// the run ended with `ERROR_DEGENERATE_UV_RESULT`.
  template <typename UVMap>
  void write_uv_map(UVMap uvmap) const
  {
    if(m_core && m_status != ERROR_DEGENERATE_UV_RESULT) internal::write_uv_map(m_cm, m_copy, uvmap);
  }
  /// Writes the current seams (every edge).
  template <typename EdgeSeamMap>
  void write_seam_map(EdgeSeamMap seam_map) const
  {
    if(m_core) internal::write_seam_map(m_tm, m_cm, m_copy, seam_map);
  }

private:
  // The run is over: the best result restored, and checked as optimize_seams() checks it.
  void end(Error_code status)
  {
    m_status = m_core->finish(status);
    m_running = false;
    if(m_status == OK && m_core->detached_faces() > 0) split_free_result();
    if(has_result(m_status)) internal::scale_for_output(m_cm, m_energy);
    if(!has_result(m_status))
      m_message = m_status == ERROR_OVERLAPPING_UV_MAP ? internal::overlapping_initial_map_message()
                                                       : "the optimization failed";
    else if(internal::count_invalid_uv_triangles(m_cm, &m_message) > 0)
      m_status = ERROR_DEGENERATE_UV_RESULT;
  }

  // The bijective run met the bound only by detaching its worst triangles
  // (its splits could not open under the scaffold: coarse meshes). A run
  // without the scaffold from the same start, its charts then cut where they
  // overlap until nothing does, is as feasible (each corner keeps its UV: the
  // same distortion) and is kept if its seams cost less (CGAL's star.off:
  // 14.7 with 12 detached faces; the free run's map split in pieces: 7.7).
  void split_free_result()
  {
    if(m_initial_cm.corner_uv.empty()) return;
    internal::Cut_mesh cm = m_initial_cm;
    internal::Alternating_settings settings = m_settings;
    settings.bijective = false;
    if(m_core->iterations() >= m_settings.max_iterations) return;
    settings.max_iterations = m_settings.max_iterations - m_core->iterations(); // (the call's cap holds)
    Core free(cm, m_energy, *m_solver, m_weight, settings, *m_visitor);
    Error_code status = free.start();
    while(status == OK && free.step(status)) {}
    status = free.finish(status);
    if(status != OK || free.detached_faces() > 0 || !free.bound_met()) return;
    internal::lay_out_uv_components(cm);
    // (every split leaves pieces that overlap less; a bounded number of rounds all the same)
    for(int round = 0; round < 64 && internal::count_overlapping_pairs(cm, 1) > 0; ++round)
    {
      if(internal::split_self_overlapping_charts(cm, &m_weight) == 0) return;
      internal::lay_out_uv_components(cm);
    }
    if(internal::count_overlapping_pairs(cm, 1) > 0 || !free.bound_met()) return;
    if(!(free.seam_cost() < m_core->seam_cost())) return;
    m_cm = std::move(cm);
    m_replacement_iterations = free.iterations();
    m_replacement_operations = free.topology_operations();
    if(m_message.empty()) m_message = "the bijective run's detached triangles replaced by a run without the "
                                      "scaffold, cut where its charts overlapped";
  }

  const TriangleMesh& m_tm;
  Energy m_energy;
  internal::Cut_mesh m_cm;
  internal::Cut_mesh m_initial_cm; // bijective bound mode: the start, for split_free_result()
  internal::Face_graph_copy<TriangleMesh> m_copy;
  std::vector<double> m_weight;
  std::optional<SolverTraits> m_solver; // (a model need not be default constructible)
  internal::Alternating_settings m_settings;
  std::optional<Visitor> m_own_visitor; // (none when the user gave one)
  Visitor* m_visitor;
  std::unique_ptr<Core> m_core;
  std::function<void()> m_lazy_phase_end_hook;
  Error_code m_status = OK;
  std::string m_message;
  bool m_running = false;
  double m_initial_distortion = 0;
  // (the run without the scaffold of split_free_result(), counted with the rest)
  std::size_t m_replacement_iterations = 0, m_replacement_operations = 0;
  CGAL::Real_timer m_timer;
};

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
