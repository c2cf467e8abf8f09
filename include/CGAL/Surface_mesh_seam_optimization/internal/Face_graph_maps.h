// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Scratch property maps over any FaceGraph (vector-backed through an index
// map), so results are computed aside and written to the user's maps only on
// success.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_FACE_GRAPH_MAPS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_FACE_GRAPH_MAPS_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <deque>
#include <memory>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// A read-write property map `Key -> Value` owning its storage (shared on copy).
template <typename IndexMap, typename Value>
class Indexed_vector_map
{
public:
  typedef typename boost::property_traits<IndexMap>::key_type key_type;
  typedef Value value_type;
  typedef Value& reference;
  typedef boost::lvalue_property_map_tag category;

  // std::vector<bool> has no bool&: a deque does.
  typedef typename std::conditional<std::is_same<Value, bool>::value,
                                    std::deque<bool>, std::vector<Value> >::type Storage;

  Indexed_vector_map() {}
  Indexed_vector_map(IndexMap index, std::size_t n, const Value& init = Value())
    : m_index(index), m_data(std::make_shared<Storage>(n, init)) {}

  reference operator[](const key_type& k) const { return (*m_data)[get(m_index, k)]; }
  friend reference get(const Indexed_vector_map& m, const key_type& k) { return m[k]; }
  friend void put(const Indexed_vector_map& m, const key_type& k, const Value& v) { m[k] = v; }

private:
  IndexMap m_index;
  std::shared_ptr<Storage> m_data;
};

template <typename Value, typename TriangleMesh>
auto make_halfedge_vector_map(const TriangleMesh& tm, const Value& init = Value())
{
  auto him = CGAL::get_initialized_halfedge_index_map(tm);
  return Indexed_vector_map<decltype(him), Value>(him, num_halfedges(tm), init);
}

// Keyed by edge through the index of its canonical halfedge: edge index maps
// are not available for every FaceGraph (Polyhedron_3 without ids).
template <typename TriangleMesh, typename HalfedgeIndexMap, typename Value>
class Edge_vector_map
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor key_type;
  typedef Value value_type;
  typedef Value& reference;
  typedef boost::lvalue_property_map_tag category;

  Edge_vector_map() {}
  Edge_vector_map(const TriangleMesh& tm, HalfedgeIndexMap him, const Value& init)
    : m_tm(&tm), m_index(him), m_map(him, num_halfedges(tm), init) {}

  // An edge descriptor may wrap either of its halfedges (Surface_mesh does):
  // key by the one with the smaller index.
  reference operator[](const key_type& e) const
  {
    const auto h = halfedge(e, *m_tm), o = opposite(h, *m_tm);
    return m_map[get(m_index, h) < get(m_index, o) ? h : o];
  }
  friend reference get(const Edge_vector_map& m, const key_type& e) { return m[e]; }
  friend void put(const Edge_vector_map& m, const key_type& e, const Value& v) { m[e] = v; }

private:
  const TriangleMesh* m_tm = nullptr;
  HalfedgeIndexMap m_index;
  Indexed_vector_map<HalfedgeIndexMap, Value> m_map;
};

template <typename Value, typename TriangleMesh>
auto make_edge_vector_map(const TriangleMesh& tm, const Value& init = Value())
{
  auto him = CGAL::get_initialized_halfedge_index_map(tm);
  return Edge_vector_map<TriangleMesh, decltype(him), Value>(tm, him, init);
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
