// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Named parameters of the package. They chain with each other and with CGAL's
// own parameters, in any order:
//
//   namespace NP = CGAL::Surface_mesh_seam_optimization::parameters;
//   NP::distortion_bound(4.1).bijective(true).number_of_recut_rounds(2).visitor(v)
//   NP::vertex_point_map(vpm).distortion_bound(4.2)
//
// CGAL 5.5's chainable members come from a list inside CGAL, which a package
// outside CGAL cannot extend, so a pack is a `Seam_optimization_named_parameters`:
// a `CGAL::Named_function_parameters` (CGAL's `get_parameter()`,
// `choose_parameter()` and `is_default_parameter` read it as usual) whose
// members add the package's parameters and re-declare CGAL's, each returning
// the package's class again. `NP` has a free function for every parameter of
// both lists; the helpers (`choose_parameter()`, `get_parameter()`, ...) are
// CGAL's.
//
// A parameter given twice takes its LAST value, as in CGAL (the outermost
// link of a pack is found first): `distortion_bound(5.).distortion_bound(4.2)`
// and `combine(distortion_bound(5.), distortion_bound(4.2))` both read 4.2.
//
// The values of the package's parameters are type-checked at compile time:
// a flag takes a `bool`, a number an arithmetic type, a count an integral
// type, an energy an object (`bijective("no")` does not compile).

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_PARAMETERS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <type_traits>

// The package's parameters and the kind of value each takes (checked at
// compile time): `flag` a bool, `number` an arithmetic type, `count` an
// integral type, `object` a class, `map` anything (a property map),
// `enumerator` an enum value.
#define CGAL_SMSO_FOR_EACH_NAMED_PARAMETER(X) \
  X(distortion_bound, number)                 \
  X(seam_weight, number)                      \
  X(bijective, flag)                          \
  X(edge_is_seam_map, map)                    \
  X(use_uv_map_as_initial, flag)              \
  X(energy, object)                           \
  X(maximum_number_of_iterations, count)      \
  X(edge_seam_weight_map, map)                \
  X(seam_cost_map, map)                       \
  X(vertex_seam_cost_map, map)                \
  X(number_of_rays, count)                    \
  X(visibility_cost_ratio, number)            \
  X(cut_strategy, enumerator)                 \
  X(gradient_tolerance, number)               \
  X(number_of_recut_rounds, count)            \
  X(number_of_starts, count)                  \
  X(time_limit, number)                       \
  X(texture_size, number)                     \
  X(margin, number)                           \
  X(allow_rotation, flag)                     \
  X(equal_texel_density, flag)               \
  X(proxy_number_of_faces, count)

namespace CGAL {
namespace Surface_mesh_seam_optimization {

namespace internal_np {
#define CGAL_SMSO_NAMED_PARAMETER_TAG(NAME, KIND) enum NAME##_t { NAME };
CGAL_SMSO_FOR_EACH_NAMED_PARAMETER(CGAL_SMSO_NAMED_PARAMETER_TAG)
#undef CGAL_SMSO_NAMED_PARAMETER_TAG
} // namespace internal_np

namespace internal {

template <typename T>
struct Accepts_flag : std::is_same<T, bool> {};
template <typename T>
struct Accepts_number : std::bool_constant<std::is_arithmetic<T>::value && !std::is_same<T, bool>::value> {};
template <typename T>
struct Accepts_count : std::bool_constant<std::is_integral<T>::value && !std::is_same<T, bool>::value> {};
template <typename T>
struct Accepts_object : std::is_class<T> {};
template <typename T>
struct Accepts_map : std::true_type {};
template <typename T>
struct Accepts_enumerator : std::is_enum<T> {};

#define CGAL_SMSO_EXPECTS_flag "the value must be a bool"
#define CGAL_SMSO_EXPECTS_number "the value must be a number (an arithmetic type other than bool)"
#define CGAL_SMSO_EXPECTS_count "the value must be an integer (an integral type other than bool)"
#define CGAL_SMSO_EXPECTS_object "the value must be an object (a model of DistortionEnergy)"
#define CGAL_SMSO_EXPECTS_map ""
#define CGAL_SMSO_EXPECTS_enumerator "the value must be an enumerator (Cut_strategy)"

// Value_check<Tag, T>: true, or a static_assert naming the parameter. CGAL's
// own parameters are not checked (CGAL does not either).
template <typename Tag, typename T>
struct Value_check : std::true_type {};

#define CGAL_SMSO_VALUE_CHECK(NAME, KIND)                                              \
  template <typename T>                                                                \
  struct Value_check<internal_np::NAME##_t, T> : std::true_type                        \
  {                                                                                    \
    static_assert(Accepts_##KIND<T>::value,                                            \
                  "Surface_mesh_seam_optimization::parameters::" #NAME "(): "          \
                  CGAL_SMSO_EXPECTS_##KIND);                                           \
  };
CGAL_SMSO_FOR_EACH_NAMED_PARAMETER(CGAL_SMSO_VALUE_CHECK)
#undef CGAL_SMSO_VALUE_CHECK
#undef CGAL_SMSO_EXPECTS_flag
#undef CGAL_SMSO_EXPECTS_number
#undef CGAL_SMSO_EXPECTS_count
#undef CGAL_SMSO_EXPECTS_object
#undef CGAL_SMSO_EXPECTS_map
#undef CGAL_SMSO_EXPECTS_enumerator

} // namespace internal

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// A pack of named parameters: a `CGAL::Named_function_parameters` whose
/// member functions chain the package's parameters and CGAL's in any order
/// (`distortion_bound(4.1).bijective(true).visitor(v)`), each returning a
/// `Seam_optimization_named_parameters` again. CGAL's
/// `parameters::get_parameter()`, `parameters::choose_parameter()` and
/// `parameters::is_default_parameter` read it as any CGAL pack. A parameter
/// given twice takes its last value. Users do not name this class: they
/// start a pack with a free function of
/// `CGAL::Surface_mesh_seam_optimization::parameters`.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Seam_optimization_named_parameters
  : CGAL::Named_function_parameters<T, Tag, Base>
{
  static_assert(internal::Value_check<Tag, std::remove_cv_t<T> >::value, "(see the message above)");

  typedef CGAL::Named_function_parameters<T, Tag, Base> Cgal_pack;
  typedef Seam_optimization_named_parameters<T, Tag, Base> self;

  using Cgal_pack::Cgal_pack;

#ifndef DOXYGEN_RUNNING
  // CGAL's parameters (the list CGAL's own class is made of)
#define CGAL_add_named_parameter(X, Y, Z)                                     \
  template <typename K>                                                       \
  Seam_optimization_named_parameters<K, CGAL::internal_np::X, self>           \
  Z(const K& k) const                                                         \
  {                                                                           \
    return Seam_optimization_named_parameters<K, CGAL::internal_np::X, self>(k, *this); \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

  // the package's
#define CGAL_SMSO_NAMED_PARAMETER_MEMBER(NAME, KIND)                          \
  template <typename K>                                                       \
  Seam_optimization_named_parameters<K, internal_np::NAME##_t, self>          \
  NAME(const K& k) const                                                      \
  {                                                                           \
    return Seam_optimization_named_parameters<K, internal_np::NAME##_t, self>(k, *this); \
  }
CGAL_SMSO_FOR_EACH_NAMED_PARAMETER(CGAL_SMSO_NAMED_PARAMETER_MEMBER)
#undef CGAL_SMSO_NAMED_PARAMETER_MEMBER
#endif
};

namespace parameters {

// CGAL's helpers, by name (not `using namespace CGAL::parameters`: its free
// functions would be ambiguous with the ones below).
using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;
using CGAL::parameters::is_default_parameter;
using CGAL::parameters::no_parameters;

/// the type of `default_values()`
typedef Seam_optimization_named_parameters<bool, CGAL::internal_np::all_default_t> Default_named_parameters;

/// an empty pack, to start a chain with: `default_values().distortion_bound(4.2)`
inline Default_named_parameters default_values() { return Default_named_parameters(); }

#ifndef DOXYGEN_RUNNING
// One free function per parameter, CGAL's and the package's, each starting a
// chainable pack.
#define CGAL_add_named_parameter(X, Y, Z)                                     \
  template <typename K>                                                       \
  Seam_optimization_named_parameters<K, CGAL::internal_np::X> Z(const K& k)   \
  {                                                                           \
    return Seam_optimization_named_parameters<K, CGAL::internal_np::X>(k);    \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter

#define CGAL_SMSO_NAMED_PARAMETER_FUNCTION(NAME, KIND)                        \
  template <typename K>                                                       \
  Seam_optimization_named_parameters<K, internal_np::NAME##_t> NAME(const K& k) \
  {                                                                           \
    return Seam_optimization_named_parameters<K, internal_np::NAME##_t>(k);   \
  }
CGAL_SMSO_FOR_EACH_NAMED_PARAMETER(CGAL_SMSO_NAMED_PARAMETER_FUNCTION)
#undef CGAL_SMSO_NAMED_PARAMETER_FUNCTION
#endif

namespace internal {

struct Empty_pack {};

// One link of `Tag` and value `v` on top of `below`; `all_default` links are
// dropped (they carry nothing).
template <typename T, typename Tag, typename Below>
auto make_link(const T& v, const Below& below)
{
  if constexpr(std::is_same<Tag, CGAL::internal_np::all_default_t>::value)
    return below;
  else if constexpr(std::is_same<Below, Empty_pack>::value)
    return Seam_optimization_named_parameters<T, Tag>(v);
  else
    return Seam_optimization_named_parameters<T, Tag, Below>(v, below);
}

// The links of `link` and of its bases, rebuilt in order on top of `below`.
// The links are `Named_params_impl`, the classes a pack is made of: a pack
// derives from all of its links, so a pack itself would make deduction ambiguous.
template <typename T, typename Tag, typename Base, typename Below>
auto rebase(const CGAL::internal_np::Named_params_impl<T, Tag, Base>& link, const Below& below)
{
  if constexpr(std::is_same<Base, CGAL::internal_np::No_property>::value)
    return make_link<T, Tag>(link.v, below);
  else
    return make_link<T, Tag>(link.v, rebase(static_cast<const typename Base::base&>(link), below));
}

template <typename Below>
const Below& stack(const Below& below) { return below; }

template <typename Below, typename NP, typename... NPs>
auto stack(const Below& below, const NP& np, const NPs&... rest)
{
  return stack(rebase(static_cast<const typename NP::base&>(np), below), rest...);
}

template <typename NP>
NP finish(const NP& np) { return np; }

inline Default_named_parameters finish(const Empty_pack&) { return Default_named_parameters(); }

} // namespace internal

/// Joins packs of named parameters, the package's or CGAL's, into one
/// chainable pack: `combine(distortion_bound(4.2), seam_weight(0.1),
/// CGAL::parameters::vertex_point_map(vpm))`. Order does not matter but for
/// a parameter given more than once, which takes its LAST value (as in a
/// chain, where the last call wins). Packs made by chaining
/// (`distortion_bound(4.2).seam_weight(0.1)`) need no `combine()`.
template <typename... NPs>
auto combine(const NPs&... nps)
{
  return internal::finish(internal::stack(internal::Empty_pack(), nps...));
}

} // namespace parameters

namespace internal {

// The cap on Newton iterations: CGAL's `number_of_iterations`, else the
// package's former name for it, `maximum_number_of_iterations` (a deprecated
// alias, still read); CGAL's wins if both are given.
template <typename NamedParameters>
std::size_t number_of_iterations_parameter(const NamedParameters& np, std::size_t default_value)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto cap = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                    choose_parameter(get_parameter(np, internal_np::maximum_number_of_iterations),
                                                     default_value));
  // CGAL does not check the type of its own parameters: this one must count.
  static_assert(Accepts_count<std::decay_t<decltype(cap)> >::value,
                "parameters::number_of_iterations(): the value must be an integer (an integral type other than bool)");
  return std::size_t(cap);
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_PARAMETERS_H
