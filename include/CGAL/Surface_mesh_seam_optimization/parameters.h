// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Named parameters of the package. CGAL 5.5's chainable members come from a
// list inside CGAL, so the package's own parameters are free functions here;
// `combine()` joins any number of parameter packs in any order.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_PARAMETERS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <type_traits>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

namespace internal_np {
#define CGAL_SMSO_NAMED_PARAMETER(NAME) enum NAME##_t { NAME };
CGAL_SMSO_NAMED_PARAMETER(distortion_bound)
CGAL_SMSO_NAMED_PARAMETER(seam_weight)
CGAL_SMSO_NAMED_PARAMETER(bijective)
CGAL_SMSO_NAMED_PARAMETER(edge_is_seam_map)
CGAL_SMSO_NAMED_PARAMETER(use_uv_map_as_initial)
CGAL_SMSO_NAMED_PARAMETER(energy)
CGAL_SMSO_NAMED_PARAMETER(maximum_number_of_iterations)
CGAL_SMSO_NAMED_PARAMETER(edge_seam_weight_map)
CGAL_SMSO_NAMED_PARAMETER(gradient_tolerance)
CGAL_SMSO_NAMED_PARAMETER(number_of_recut_rounds)
CGAL_SMSO_NAMED_PARAMETER(time_limit)
CGAL_SMSO_NAMED_PARAMETER(texture_size)
CGAL_SMSO_NAMED_PARAMETER(margin)
CGAL_SMSO_NAMED_PARAMETER(allow_rotation)
CGAL_SMSO_NAMED_PARAMETER(equal_texel_density)
#undef CGAL_SMSO_NAMED_PARAMETER
} // namespace internal_np

namespace parameters {

using namespace CGAL::parameters;

#define CGAL_SMSO_NAMED_PARAMETER(NAME)                                        \
  template <typename T>                                                        \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t>                    \
  NAME(const T& t)                                                             \
  {                                                                            \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t>(t);       \
  }
/// bound on E_SD (default 4.1)
CGAL_SMSO_NAMED_PARAMETER(distortion_bound)
/// fixed lambda in [0,1): no dual step
CGAL_SMSO_NAMED_PARAMETER(seam_weight)
/// prevent overlaps between charts (default true)
CGAL_SMSO_NAMED_PARAMETER(bijective)
/// property map `edge_descriptor -> bool`, read as the initial seams and written with the result
CGAL_SMSO_NAMED_PARAMETER(edge_is_seam_map)
/// start from the UV map given by the user (and the seams it implies)
CGAL_SMSO_NAMED_PARAMETER(use_uv_map_as_initial)
/// a model of `DistortionEnergy` (default `Symmetric_Dirichlet_energy`)
CGAL_SMSO_NAMED_PARAMETER(energy)
/// cap on Newton iterations
CGAL_SMSO_NAMED_PARAMETER(maximum_number_of_iterations)
/// property map `edge_descriptor -> double`: regional seam preference (> 1 repels, < 1 attracts)
CGAL_SMSO_NAMED_PARAMETER(edge_seam_weight_map)
/// stop when the squared gradient norm falls below this (default 1e-12)
CGAL_SMSO_NAMED_PARAMETER(gradient_tolerance)
/// rounds of unzipping part of the seams (and of straightening winding ones) and cutting again after the first result (default 6; 0: none)
CGAL_SMSO_NAMED_PARAMETER(number_of_recut_rounds)
/// seconds (> 0) after which the run stops with the best result so far (status `WARNING_TIME_LIMIT`; default: none)
CGAL_SMSO_NAMED_PARAMETER(time_limit)
/// `pack_charts()`: side of the square texture in texels (default 1024)
CGAL_SMSO_NAMED_PARAMETER(texture_size)
/// `pack_charts()`: texels between two charts and between a chart and the border (default 4)
CGAL_SMSO_NAMED_PARAMETER(margin)
/// `pack_charts()`: charts may be rotated to their minimum-area bounding rectangle and by quarter turns (default true)
CGAL_SMSO_NAMED_PARAMETER(allow_rotation)
/// `pack_charts()`: each chart scaled to one UV area / 3D area ratio, instead of one factor for all charts (default false)
CGAL_SMSO_NAMED_PARAMETER(equal_texel_density)
#undef CGAL_SMSO_NAMED_PARAMETER

namespace internal {

template <typename NP>
struct Is_default_pack : std::false_type {};
template <typename T, typename Base>
struct Is_default_pack<CGAL::Named_function_parameters<T, CGAL::internal_np::all_default_t, Base> >
  : std::true_type {};

// `a` with its terminal `No_property` replaced by `b`. A class template, not
// overloaded functions: a function's trailing return type cannot see its own
// overload, and the call then slices a longer pack down to its last link.
template <typename NP1, typename NP2>
struct Append;

template <typename T, typename Tag, typename NP2>
struct Append<CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>, NP2>
{
  typedef CGAL::Named_function_parameters<T, Tag, NP2> type;
  static type run(const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& a, const NP2& b)
  {
    return type(a.v, b);
  }
};

template <typename T, typename Tag, typename Base, typename NP2>
struct Append<CGAL::Named_function_parameters<T, Tag, Base>, NP2>
{
  typedef Append<Base, NP2> Inner;
  typedef CGAL::Named_function_parameters<T, Tag, typename Inner::type> type;
  static type run(const CGAL::Named_function_parameters<T, Tag, Base>& a, const NP2& b)
  {
    return type(a.v, Inner::run(static_cast<const Base&>(a), b));
  }
};

template <typename NP1, typename NP2>
typename Append<NP1, NP2>::type append(const NP1& a, const NP2& b)
{
  return Append<NP1, NP2>::run(a, b);
}

} // namespace internal

/// Joins parameter packs: `combine(distortion_bound(4.2), seam_weight(0.1),
/// CGAL::parameters::vertex_point_map(vpm))`. Order does not matter; a
/// parameter given twice takes its first value.
template <typename NP>
const NP& combine(const NP& np) { return np; }

template <typename NP1, typename NP2, typename... NPs>
auto combine(const NP1& np1, const NP2& np2, const NPs&... rest)
{
  if constexpr(internal::Is_default_pack<NP1>::value)
    return combine(np2, rest...);
  else if constexpr(internal::Is_default_pack<NP2>::value)
    return combine(np1, rest...);
  else
    return combine(internal::append(np1, np2), rest...);
}

} // namespace parameters
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_PARAMETERS_H
