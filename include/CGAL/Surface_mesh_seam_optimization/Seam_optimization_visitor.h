// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_OPTIMIZATION_VISITOR_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_OPTIMIZATION_VISITOR_H

#include <CGAL/Surface_mesh_seam_optimization/parameters.h>

#include <cstddef>
#include <functional>
#include <type_traits>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationVisitor
/// The state of a run of `optimize_seams()`, passed to every member of a
/// model of `SeamOptimizationVisitor`.
struct Seam_optimization_progress
{
  std::size_t iterations = 0;          ///< Newton iterations so far
  std::size_t topology_operations = 0; ///< splits and merges applied so far (fracture propagation included)
  double distortion = 0;               ///< current distortion energy of the descent (E_SD with the default energy)
  double seam_length_normalized = 0;   ///< current normalized seam length E_se (unweighted)
  double lambda = 0;                   ///< current seam weight of E_w = (1 - lambda) E_SD + lambda E_se
  double seconds = 0;                  ///< wall-clock seconds since the alternating optimization started
};

/// \ingroup PkgSurfaceMeshSeamOptimizationVisitor
/// The default model of `SeamOptimizationVisitor`: does nothing, never cancels.
/// In a model of the concept, each member returns `false` to stop the run
/// (the best result so far is kept).
///
/// \cgalModels `SeamOptimizationVisitor`
struct Default_seam_optimization_visitor
{
  /// after every Newton iteration; returns `true`
  bool on_iteration(const Seam_optimization_progress&) { return true; }
  /// after every split or merge; returns `true`
  bool on_topology_operation(const Seam_optimization_progress&) { return true; }
  /// after every dual update of lambda; returns `true`
  bool on_lambda_update(const Seam_optimization_progress&) { return true; }
};

namespace internal {

// The `visitor` named parameter as an object to call: a visitor passed by
// value is copied (into the returned holder), one passed as std::ref(v) is
// held by reference, none gives the default visitor. Call unwrap_visitor() on
// the holder, kept alive as long as the run.
template <typename NamedParameters>
auto visitor_parameter(const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::visitor),
                                      Default_seam_optimization_visitor());
}

template <typename Visitor>
Visitor& unwrap_visitor(Visitor& visitor) { return visitor; }

template <typename Visitor>
Visitor& unwrap_visitor(std::reference_wrapper<Visitor>& visitor)
{
  static_assert(!std::is_const<Visitor>::value,
                "the visitor is called through a const reference: pass it by value or as std::ref(v) "
                "to a non-const visitor (a visitor that cannot be copied must be passed as std::ref(v))");
  return visitor.get();
}

// Whether a visitor reads the progress it is given, so that a run can skip
// the figures nobody reads (the seam length is a pass over the mesh at every
// Newton iteration). The default visitor does not; an internal one says so by
// a member reads_progress(); any other does.
template <typename Visitor>
auto visitor_reads_progress(const Visitor& visitor, int) -> decltype(bool(visitor.reads_progress()))
{
  return visitor.reads_progress();
}
template <typename Visitor>
bool visitor_reads_progress(const Visitor&, long)
{
  return !std::is_same<Visitor, Default_seam_optimization_visitor>::value;
}
template <typename Visitor>
bool visitor_reads_progress(const Visitor& visitor) { return visitor_reads_progress(visitor, 0); }

} // namespace internal

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
