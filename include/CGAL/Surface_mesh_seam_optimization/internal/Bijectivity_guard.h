// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Global bijectivity, lazily: the charts run free while their stationary
// points do not overlap (a scaffold resists the charts' motion and changes
// which cuts pay); at the first that does, back to the last that did not,
// and on with the scaffold from there. The guard owns the scaffold and the
// configurations to go back to; the alternation asks it at each stationary
// point.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_BIJECTIVITY_GUARD_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_BIJECTIVITY_GUARD_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Chart_layout.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Overlap.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Scaffold.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Scaffold_mesher.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Split_self_overlapping_charts.h>

#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

class Bijectivity_guard
{
public:
  // What a stationary point of the lazy phase led to.
  enum Verdict
  {
    NO_OVERLAP,   // kept as the safe configuration (charts perhaps laid apart)
    SPLIT,        // charts that overlapped themselves were cut in two: descend again, still free
    RESTORED,     // overlap: back to the last safe configuration, scaffold on
    RESTARTED     // overlap: back to the initial map, scaffold on
  };

  // `halfedge_weight` (seam cost per unit length; null: 1) prices the cuts of split charts.
  Bijectivity_guard(bool bijective, const std::vector<double>* halfedge_weight)
    : m_bijective(bijective), m_weight(halfedge_weight) {}

  bool bijective() const { return m_bijective; }
  // bijective and the scaffold in use (after the lazy phase)
  bool scaffold_on() const { return m_bijective && !m_lazy; }
  bool lazy() const { return m_lazy; }
  Scaffold& scaffold() { return m_scaffold; }
  const Scaffold& scaffold() const { return m_scaffold; }

  // Starts the lazy phase at the initial map, of E_SD `e_sd`; false if that
  // map is not bijective (meshing a scaffold once checks it).
  bool begin(const Cut_mesh& cm, double lambda, double e_sd)
  {
    m_lazy = true;
    if(!build(cm)) return false;
    m_scaffold.clear();
    keep_as_safe(cm, lambda);
    m_safe_is_initial = true;
    m_initial_e_sd = e_sd;
    // The input's own disks keep about their initial layout; charts that
    // were cut free settle where the scaffold later cramps them: at the
    // first overlap, start over from the initial map (as the reference
    // does for disks).
    if(cm.seam_length() == 0)
    {
      m_initial.save(cm);
      m_restart_at_overlap = true;
    }
    return true;
  }

  // Meshes the scaffold around the charts anew; false (the previous one
  // kept) if the charts overlap or the space cannot be meshed.
  bool build(const Cut_mesh& cm)
  {
    Scaffold fresh;
    fresh.settings = m_scaffold.settings;
    if(!fresh.build(cm)) return false;
    m_scaffold = std::move(fresh);
    return true;
  }

  // A squeezed scaffold blocks the charts' motion (x: unified positions).
  bool squeezed(const double* x) const
  {
    return m_scaffold.max_density_growth(x) > m_scaffold.settings.rebuild_threshold;
  }

  // At a stationary point with lambda `lambda`: see Verdict. `e_sd()` gives
  // the charts' E_SD (asked only when a split is considered). On RESTORED,
  // `lambda` becomes the safe configuration's. The caller then builds the
  // scaffold (see scaffold_failed()).
  // `before_scaffold()` is called once the lazy phase is found over, before
  // anything is changed for it (the relaxed start of optimize_seams() forks there).
  template <typename Distortion, typename Before>
  Verdict check(Cut_mesh& cm, double& lambda, const Distortion& e_sd, const Before& before_scaffold)
  {
    if(!m_lazy) return NO_OVERLAP;
    if(count_overlapping_pairs(cm, 1) == 0) { keep_as_safe(cm, lambda); return NO_OVERLAP; }
    // where a chart lies is free: only a chart that overlaps itself needs the scaffold
    if(lay_out_uv_components(cm) > 1 && count_overlapping_pairs(cm, 1) == 0)
    {
      keep_as_safe(cm, lambda);
      return NO_OVERLAP;
    }
    before_scaffold();
    // Back to an initial map (no stationary point was free of overlaps yet)
    // that is orders of magnitude from stationary (Tutte maps of cut-open
    // high-genus charts: E_SD 1e6, triangles squeezed 100-fold and more),
    // the scaffolded descent would have to redo all of the free one while
    // the charts grow many times over their scaffold: thousands of slow
    // iterations. Cut the charts that overlap themselves instead. (Closer to
    // stationary, going back costs little and the seams are shorter:
    // couplingdown 12.0 against 23.1, elephant-with-holes 13.2 against 19.3,
    // whose initial maps are 90 and 245 times their stationary E_SD.)
    if(m_safe_is_initial && !m_restart_at_overlap && m_initial_e_sd > far_from_stationary * e_sd() &&
       split_self_overlapping_charts(cm, m_weight) > 0)
    {
      lay_out_uv_components(cm);
      return SPLIT;
    }
    Verdict verdict = RESTORED;
    if(m_restart_at_overlap)
    {
      m_initial.restore(cm);
      m_restart_at_overlap = false;
      verdict = RESTARTED;
    }
    else
    {
      m_safe.restore(cm);
      lambda = m_safe_lambda;
    }
    m_lazy = false;
    return verdict;
  }

  // The scaffold could not be meshed after check(): the run ends lazily, at
  // its best feasible configuration.
  void scaffold_failed() { m_lazy = true; }

  // Whatever stopped a run without its scaffold, what it leaves must not overlap.
  void restore_if_overlapping(Cut_mesh& cm)
  {
    if(m_lazy && count_overlapping_pairs(cm, 1) > 0) m_safe.restore(cm);
  }

  // False for an overlapping configuration of the lazy phase (not a result).
  bool is_result(const Cut_mesh& cm) const
  {
    return !(m_lazy && count_overlapping_pairs(cm, 1) > 0);
  }

private:
  void keep_as_safe(const Cut_mesh& cm, double lambda)
  {
    m_safe.save(cm);
    m_safe_lambda = lambda;
    m_safe_is_initial = false;
  }

  bool m_bijective;
  const std::vector<double>* m_weight;
  bool m_lazy = false; // bijective, but no scaffold yet
  Scaffold m_scaffold;
  double m_safe_lambda = 0;
  Uv_snapshot m_safe;
  Uv_snapshot m_initial;
  bool m_restart_at_overlap = false;
  bool m_safe_is_initial = false;
  double m_initial_e_sd = 0;
  // initial E_SD / stationary E_SD beyond which going back does not pay
  static constexpr double far_from_stationary = 1e4;
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
