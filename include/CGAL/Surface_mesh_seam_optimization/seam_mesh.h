// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Bridge to CGAL::Seam_mesh, the cut surface of Surface_mesh_parameterization:
// build one from the package's edge seam map, and convert UV maps between
// the Seam_mesh convention (one UV per seam-mesh vertex, stored at that
// vertex's canonical halfedge of the underlying mesh) and the package's
// convention (one UV per face corner, stored at every halfedge with a face).
//
// CGAL/boost/graph/Seam_mesh.h calls CGAL::target(h, tm) & co. by qualified
// name, so the graph traits of the underlying mesh must be declared before it.
// Those of Surface_mesh and Polyhedron_3 are included here, so the package's
// headers may come first; for another FaceGraph (OpenMesh, a
// Linear_cell_complex, a HalfedgeDS), include its graph traits header before
// any header of this package.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_MESH_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_MESH_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>

#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h> // before Seam_mesh.h, see above
#include <CGAL/boost/graph/graph_traits_Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Unique_hash_map.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// A border halfedge of `smesh` on the chart (connected component of the seam
/// mesh) of face `f`, for `SMP::parameterize()`; a default constructed
/// halfedge if that chart is closed. Works with any `CGAL::Seam_mesh`.
template <class TM, class SEM, class SVM>
typename boost::graph_traits<CGAL::Seam_mesh<TM, SEM, SVM> >::halfedge_descriptor
seam_mesh_border_halfedge(const CGAL::Seam_mesh<TM, SEM, SVM>& smesh,
                          typename boost::graph_traits<TM>::face_descriptor f)
{
  typedef CGAL::Seam_mesh<TM, SEM, SVM>                                 SM;
  typedef typename boost::graph_traits<SM>::halfedge_descriptor        halfedge_descriptor;
  typedef typename boost::graph_traits<TM>::face_descriptor            face_descriptor;

  CGAL::Unique_hash_map<face_descriptor, bool> seen(false);
  std::vector<face_descriptor> stack(1, f);
  seen[f] = true;
  while(!stack.empty())
  {
    const face_descriptor g = stack.back();
    stack.pop_back();
    for(halfedge_descriptor h : halfedges_around_face(halfedge(g, smesh), smesh))
    {
      const halfedge_descriptor o = opposite(h, smesh);
      if(is_border(o, smesh))
        return o;
      const face_descriptor n = face(o, smesh);
      if(!seen[n])
      {
        seen[n] = true;
        stack.push_back(n);
      }
    }
  }
  return halfedge_descriptor();
}

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
///
/// Owns the two property maps a `CGAL::Seam_mesh` needs (seam edges and seam
/// vertices) and the `Seam_mesh` itself, built from the package's edge seam
/// map. This is how a result of the package is handed to
/// `Surface_mesh_parameterization`, and how an initial UV map computed by any
/// CGAL parameterizer is brought back:
///
/// \code
/// Seam_mesh_maker<Mesh> maker(tm, seam_map);
/// auto& smesh = maker.seam_mesh();
/// SMP::parameterize(smesh, parameterizer, maker.border_halfedge(f), seam_uvmap);
/// seam_mesh_uv_map_to_corner_uv_map(smesh, seam_uvmap, uvmap);
/// \endcode
///
/// The seams are read once, at construction: later changes of `seam_map` are
/// not seen. Border edges of `tm` are never seams (a `Seam_mesh` cannot cut
/// them), whatever `seam_map` says. The maker keeps references to `tm` and to
/// its own maps, so it is neither copyable nor movable and must outlive the
/// `Seam_mesh` reference it hands out.
///
/// \tparam TriangleMesh a model of `FaceGraph`
template <class TriangleMesh>
class Seam_mesh_maker
{
  typedef boost::graph_traits<TriangleMesh>                         GT;
public:
  typedef typename GT::vertex_descriptor                            TM_vertex_descriptor;
  typedef typename GT::halfedge_descriptor                          TM_halfedge_descriptor;
  typedef typename GT::edge_descriptor                              TM_edge_descriptor;
  typedef typename GT::face_descriptor                              TM_face_descriptor;

  typedef CGAL::Unique_hash_map<TM_edge_descriptor, bool>           Seam_edge_container;
  typedef CGAL::Unique_hash_map<TM_vertex_descriptor, bool>         Seam_vertex_container;
  /// `edge_descriptor -> bool`, true on the seam edges
  typedef boost::associative_property_map<Seam_edge_container>      Seam_edge_map;
  /// `vertex_descriptor -> bool`, true on the vertices of seam edges
  typedef boost::associative_property_map<Seam_vertex_container>    Seam_vertex_map;
  /// the seam mesh type
  typedef CGAL::Seam_mesh<TriangleMesh, Seam_edge_map, Seam_vertex_map> Seam_mesh;
  typedef typename boost::graph_traits<Seam_mesh>::halfedge_descriptor halfedge_descriptor;

  /// builds the seam mesh of `tm` whose seams are the non-border edges `e`
  /// with `get(seam_map, e) == true`.
  /// \tparam EdgeSeamMap a model of `ReadablePropertyMap`, `edge_descriptor -> bool`
  template <class EdgeSeamMap>
  Seam_mesh_maker(const TriangleMesh& tm, EdgeSeamMap seam_map)
    : m_edges(false), m_vertices(false),
      m_seam_mesh(tm, Seam_edge_map(m_edges), Seam_vertex_map(m_vertices))
  {
    std::size_t n = 0;
    for(TM_edge_descriptor e : edges(tm))
    {
      if(!get(seam_map, e) || is_border(e, tm))
        continue;
      m_edges[e] = true;
      m_vertices[source(e, tm)] = true;
      m_vertices[target(e, tm)] = true;
      ++n;
    }
    // The maps were filled directly (add_seam() would look every edge up again).
    m_seam_mesh.set_seam_edges_number(n);
  }

  Seam_mesh_maker(const Seam_mesh_maker&) = delete;
  Seam_mesh_maker& operator=(const Seam_mesh_maker&) = delete;

  /// the seam mesh (non-const: `SMP::parameterize()` takes it by reference)
  Seam_mesh& seam_mesh() { return m_seam_mesh; }
  const Seam_mesh& seam_mesh() const { return m_seam_mesh; }

  /// true if `e` is a seam edge of the seam mesh
  bool is_seam(TM_edge_descriptor e) const { return m_edges.is_defined(e) && m_edges[e]; }

  /// number of seam edges
  std::size_t number_of_seam_edges() const
  {
    return static_cast<std::size_t>(m_seam_mesh.number_of_seam_edges());
  }

  /// A border halfedge of the seam mesh on the chart (connected component of
  /// the seam mesh) of face `f`, as `SMP::parameterize()` wants it; a default
  /// constructed halfedge if that chart is closed.
  halfedge_descriptor border_halfedge(TM_face_descriptor f) const
  {
    return CGAL::Surface_mesh_seam_optimization::seam_mesh_border_halfedge(m_seam_mesh, f);
  }

private:
  // Declared before m_seam_mesh: it is built from property maps pointing at them.
  Seam_edge_container m_edges;
  Seam_vertex_container m_vertices;
  Seam_mesh m_seam_mesh;
};

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// The key under which a seam-mesh UV map (as `SMP::parameterize()` writes
/// it) stores the UV of the corner `h` (a halfedge of the underlying mesh with
/// a face): the seam-mesh vertex at `target(h)` in `face(h)`. It converts to
/// the underlying mesh's halfedge, so maps keyed by either type accept it.
template <class TM, class SEM, class SVM>
typename boost::graph_traits<CGAL::Seam_mesh<TM, SEM, SVM> >::vertex_descriptor
seam_mesh_corner_vertex(const CGAL::Seam_mesh<TM, SEM, SVM>& smesh,
                        typename boost::graph_traits<TM>::halfedge_descriptor h)
{
  typedef typename boost::graph_traits<CGAL::Seam_mesh<TM, SEM, SVM> >::halfedge_descriptor
    halfedge_descriptor;
  return target(halfedge_descriptor(h), smesh);
}

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Copies a UV map of a seam mesh (one UV per seam-mesh vertex, as
/// `SMP::parameterize()` writes it) into the package's per-corner UV map:
/// every halfedge `h` of the underlying mesh with a face gets the UV of the
/// seam-mesh vertex at `target(h)` in `face(h)`.
///
/// \tparam SeamMeshUVMap a model of `ReadablePropertyMap` keyed by the
///         underlying mesh's `halfedge_descriptor` (as in CGAL's
///         `seam_Surface_mesh.cpp` example) or by the seam mesh's
///         `vertex_descriptor`
/// \tparam UVMap a model of `WritablePropertyMap`, underlying mesh's
///         `halfedge_descriptor -> Point_2`
///
/// Only the charts `SMP::parameterize()` was run on have UVs in
/// `seam_uvmap`; the caller decides which charts that is.
template <class TM, class SEM, class SVM, class SeamMeshUVMap, class UVMap>
void seam_mesh_uv_map_to_corner_uv_map(const CGAL::Seam_mesh<TM, SEM, SVM>& smesh,
                                       SeamMeshUVMap seam_uvmap,
                                       UVMap uvmap)
{
  const TM& tm = smesh.mesh();
  for(typename boost::graph_traits<TM>::halfedge_descriptor h : halfedges(tm))
  {
    if(is_border(h, tm))
      continue;
    put(uvmap, h, get(seam_uvmap, seam_mesh_corner_vertex(smesh, h)));
  }
}

/// \ingroup PkgSurfaceMeshSeamOptimizationRef
/// Copies the package's per-corner UV map into a UV map of the seam mesh (one
/// UV per seam-mesh vertex), e.g. to start a CGAL parameterizer or a
/// post-processor from it, or to use CGAL's distortion measures.
///
/// The corners of one seam-mesh vertex must have equal UVs (that is, the seams
/// of `smesh` must contain every UV discontinuity of `uvmap`), and every UV
/// must be finite; otherwise `ERROR_INVALID_UV_MAP` is returned and
/// `seam_uvmap` is not modified.
///
/// \tparam UVMap a model of `ReadablePropertyMap`, underlying mesh's
///         `halfedge_descriptor -> Point_2`
/// \tparam SeamMeshUVMap a model of `WritablePropertyMap` keyed by the
///         underlying mesh's `halfedge_descriptor` or by the seam mesh's
///         `vertex_descriptor`
template <class TM, class SEM, class SVM, class UVMap, class SeamMeshUVMap>
Error_code corner_uv_map_to_seam_mesh_uv_map(const CGAL::Seam_mesh<TM, SEM, SVM>& smesh,
                                             UVMap uvmap,
                                             SeamMeshUVMap seam_uvmap)
{
  typedef CGAL::Seam_mesh<TM, SEM, SVM>                                SM;
  typedef typename boost::graph_traits<SM>::vertex_descriptor         vertex_descriptor;
  typedef typename boost::graph_traits<TM>::halfedge_descriptor       TM_halfedge_descriptor;
  typedef typename boost::property_traits<UVMap>::value_type          Point_2;

  const TM& tm = smesh.mesh();
  // One entry per seam-mesh vertex; keyed by its canonical halfedge, which
  // hashes for every FaceGraph (a seam-mesh vertex_descriptor may not).
  CGAL::Unique_hash_map<TM_halfedge_descriptor, std::size_t> slot(std::size_t(-1));
  std::vector<std::pair<vertex_descriptor, Point_2> > values;
  for(TM_halfedge_descriptor h : halfedges(tm))
  {
    if(is_border(h, tm))
      continue;
    const Point_2 uv = get(uvmap, h);
    if(!std::isfinite(CGAL::to_double(uv.x())) || !std::isfinite(CGAL::to_double(uv.y())))
      return ERROR_INVALID_UV_MAP;
    const vertex_descriptor v = seam_mesh_corner_vertex(smesh, h);
    const TM_halfedge_descriptor key = v;
    std::size_t& s = slot[key];
    if(s == std::size_t(-1))
    {
      s = values.size();
      values.push_back(std::make_pair(v, uv));
    }
    else if(values[s].second != uv)
      return ERROR_INVALID_UV_MAP;
  }
  for(const std::pair<vertex_descriptor, Point_2>& p : values)
    put(seam_uvmap, p.first, p.second);
  return OK;
}

} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_SEAM_MESH_H
