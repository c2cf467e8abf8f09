// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// FaceGraph <-> core arrays: the only place that knows the user's mesh type.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_FACE_GRAPH_COPY_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_FACE_GRAPH_COPY_H

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Cut_mesh.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Degenerate_triangle.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Union_find.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

template <typename TriangleMesh>
struct Face_graph_copy
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef typename GT::face_descriptor face_descriptor;

  std::vector<halfedge_descriptor> corner_halfedge; // halfedge of each core corner
};

// Copies the 3D mesh into `cm` (no UV yet) and validates it.
template <typename TriangleMesh, typename VertexPointMap>
Error_code copy_face_graph(const TriangleMesh& tm, VertexPointMap vpm, Cut_mesh& cm,
                           Face_graph_copy<TriangleMesh>& copy, std::string& message)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;

  cm = Cut_mesh();
  copy.corner_halfedge.clear();
  if(faces(tm).empty()) { message = "no face"; return ERROR_EMPTY_MESH; }

  auto vim = CGAL::get_initialized_vertex_index_map(tm);
  auto him = CGAL::get_initialized_halfedge_index_map(tm);

  const std::size_t nv = num_vertices(tm);
  cm.points.assign(3 * nv, 0.);
  for(auto v : vertices(tm))
  {
    const auto& p = get(vpm, v);
    const std::size_t i = get(vim, v);
    for(int k = 0; k < 3; ++k)
    {
      const double x = CGAL::to_double(p[k]);
      if(!std::isfinite(x))
      {
        message = "vertex " + std::to_string(i) + " has a non-finite coordinate";
        return ERROR_NON_FINITE_COORDINATES;
      }
      cm.points[3*i + k] = x;
    }
  }

  const std::size_t nf = num_faces(tm);
  cm.corner_vertex.reserve(3 * nf);
  copy.corner_halfedge.reserve(3 * nf);
  std::vector<int> halfedge_corner(num_halfedges(tm), -1);
  std::size_t fi = 0;
  for(auto f : faces(tm))
  {
    halfedge_descriptor h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
    {
      message = "face " + std::to_string(fi) + " is not a triangle";
      return ERROR_NON_TRIANGULAR_MESH;
    }
    for(int i = 0; i < 3; ++i, h = next(h, tm))
    {
      halfedge_corner[get(him, h)] = int(cm.corner_vertex.size());
      cm.corner_vertex.push_back(int(get(vim, target(h, tm))));
      copy.corner_halfedge.push_back(h);
    }
    ++fi;
  }
  cm.opposite.assign(cm.corner_vertex.size(), -1);
  for(std::size_t c = 0; c < copy.corner_halfedge.size(); ++c)
  {
    const halfedge_descriptor o = opposite(copy.corner_halfedge[c], tm);
    if(!is_border(o, tm)) cm.opposite[c] = halfedge_corner[get(him, o)];
  }

  // A vertex whose corners do not form one fan is pinched (non-manifold).
  std::vector<int> corners_at(nv, 0);
  for(int v : cm.corner_vertex) ++corners_at[v];
  for(auto v : vertices(tm))
  {
    if(halfedge(v, tm) == GT::null_halfedge()) continue;
    int fan = 0, borders = 0;
    for(halfedge_descriptor h : halfedges_around_target(halfedge(v, tm), tm))
      is_border(h, tm) ? ++borders : ++fan;
    if(fan != corners_at[get(vim, v)] || borders > 1)
    {
      message = "vertex " + std::to_string(get(vim, v)) + " is not manifold";
      return ERROR_NON_MANIFOLD_MESH;
    }
  }

  cm.compute_rest_shape();
  // Relative to each face's longest edge, not to the bounding box: a far
  // vertex must not condemn small faces.
  for(std::size_t f = 0; f < cm.number_of_faces(); ++f)
  {
    const double* p[3];
    for(int k = 0; k < 3; ++k) p[k] = &cm.points[3 * cm.corner_vertex[3*f + k]];
    if(is_degenerate_triangle(p[0], p[1], p[2]) ||
       !std::isfinite(cm.rest_inverse[4*f+2]))
    {
      message = "face " + std::to_string(f + 1) + " (numbered from 1) has zero area";
      return ERROR_DEGENERATE_TRIANGLE;
    }
  }
  return OK;
}

// Corners joined across non-seam edges share a UV vertex (union-find);
// `seam` is per core halfedge (both sides set). Each UV vertex's corners
// form one fan, so the UV mesh is manifold by construction.
inline void label_uv_vertices(Cut_mesh& cm, const std::vector<char>& seam)
{
  const std::size_t nc = cm.corner_vertex.size();
  Union_find uf(nc);
  for(std::size_t h = 0; h < nc; ++h)
  {
    const int o = cm.opposite[h];
    if(o < int(h) || seam[h]) continue;
    uf.unite(int(h), Cut_mesh::prev(o));         // target of h == source of o
    uf.unite(Cut_mesh::prev(int(h)), o);         // source of h == target of o
  }
  cm.corner_uv.assign(nc, -1);
  cm.uv_vertex.clear();
  std::vector<int> id(nc, -1);
  for(std::size_t c = 0; c < nc; ++c)
  {
    const int r = uf.find(int(c));
    if(id[r] < 0) { id[r] = int(cm.uv_vertex.size()); cm.uv_vertex.push_back(cm.corner_vertex[c]); }
    cm.corner_uv[c] = id[r];
  }
  cm.uv.assign(2 * cm.uv_vertex.size(), 0.);
}

// Seams given per edge, as per core halfedge (both sides; never on the input boundary).
template <typename TriangleMesh, typename EdgeSeamMap>
void read_seam_map(const TriangleMesh& tm, EdgeSeamMap seam_map, const Face_graph_copy<TriangleMesh>& copy,
                   const Cut_mesh& cm, std::vector<char>& seam)
{
  seam.assign(cm.corner_vertex.size(), 0);
  for(std::size_t h = 0; h < seam.size(); ++h)
    seam[h] = cm.opposite[h] >= 0 && bool(get(seam_map, edge(copy.corner_halfedge[h], tm)));
}

// Seams implied by a per-corner UV map: an interior edge whose two sides
// disagree (beyond `tolerance`) at either endpoint.
template <typename UVMap, typename TriangleMesh>
Error_code read_uv_map(const TriangleMesh& tm, UVMap uvmap, const Face_graph_copy<TriangleMesh>& copy,
                       std::vector<double>& corner_uv_values, std::string& message)
{
  (void)tm;
  const std::size_t nc = copy.corner_halfedge.size();
  corner_uv_values.resize(2 * nc);
  for(std::size_t c = 0; c < nc; ++c)
  {
    const auto& p = get(uvmap, copy.corner_halfedge[c]);
    const double u = CGAL::to_double(p[0]), v = CGAL::to_double(p[1]);
    if(!std::isfinite(u) || !std::isfinite(v))
    {
      message = "corner " + std::to_string(c) + " (face " + std::to_string(c / 3) + ") has a non-finite UV";
      return ERROR_INVALID_UV_MAP;
    }
    corner_uv_values[2*c] = u; corner_uv_values[2*c+1] = v;
  }
  return OK;
}

inline void seams_from_corner_uvs(const Cut_mesh& cm, const std::vector<double>& cuv, std::vector<char>& seam)
{
  double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
  for(std::size_t c = 0; c < cuv.size() / 2; ++c)
    for(int k = 0; k < 2; ++k) { lo[k] = (std::min)(lo[k], cuv[2*c+k]); hi[k] = (std::max)(hi[k], cuv[2*c+k]); }
  const double tol = 1e-9 * std::sqrt((hi[0]-lo[0])*(hi[0]-lo[0]) + (hi[1]-lo[1])*(hi[1]-lo[1]));
  auto differ = [&](int a, int b) {
    return std::abs(cuv[2*a] - cuv[2*b]) > tol || std::abs(cuv[2*a+1] - cuv[2*b+1]) > tol;
  };
  seam.assign(cm.corner_vertex.size(), 0);
  for(std::size_t h = 0; h < seam.size(); ++h)
  {
    const int o = cm.opposite[h];
    if(o < 0) continue;
    seam[h] = differ(int(h), Cut_mesh::prev(o)) || differ(Cut_mesh::prev(int(h)), o);
  }
}

// UV of each UV vertex = mean of its corners' values (they agree up to the tolerance).
inline void set_uvs_from_corners(Cut_mesh& cm, const std::vector<double>& cuv)
{
  std::vector<int> count(cm.number_of_uv_vertices(), 0);
  std::fill(cm.uv.begin(), cm.uv.end(), 0.);
  for(std::size_t c = 0; c < cm.corner_uv.size(); ++c)
  {
    const int u = cm.corner_uv[c];
    cm.uv[2*u] += cuv[2*c]; cm.uv[2*u+1] += cuv[2*c+1]; ++count[u];
  }
  for(std::size_t u = 0; u < count.size(); ++u)
    if(count[u] > 0) { cm.uv[2*u] /= count[u]; cm.uv[2*u+1] /= count[u]; }
}

template <typename TriangleMesh, typename UVMap>
void write_uv_map(const Cut_mesh& cm, const Face_graph_copy<TriangleMesh>& copy, UVMap uvmap)
{
  typedef typename boost::property_traits<UVMap>::value_type Point_2;
  for(std::size_t c = 0; c < copy.corner_halfedge.size(); ++c)
  {
    const int u = cm.corner_uv[c];
    put(uvmap, copy.corner_halfedge[c], Point_2(cm.uv[2*u], cm.uv[2*u+1]));
  }
}

template <typename TriangleMesh, typename EdgeSeamMap>
void write_seam_map(const TriangleMesh& tm, const Cut_mesh& cm, const Face_graph_copy<TriangleMesh>& copy,
                    EdgeSeamMap seam_map)
{
  for(std::size_t h = 0; h < copy.corner_halfedge.size(); ++h)
  {
    const int o = cm.opposite[h];
    if(o >= 0 && o < int(h)) continue;
    put(seam_map, edge(copy.corner_halfedge[h], tm), cm.is_seam(int(h)));
  }
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
