// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Initial maps of charts that are neither disks nor closed genus-0 surfaces:
// handles are cut by a greedy system of loops (Erickson and Whittlesey,
// "Greedy optimal homotopy and homology generators", SODA 2005), inner
// boundary loops are kept as holes. Tutte's theorem needs one convex border,
// so the map is computed on the cut chart with every inner hole filled by a
// fan around a virtual vertex; dropping the fans leaves an embedded chart
// with its holes, and no seam was spent on joining them.
//
// Charts are read from the flat corner table of compute_initial_parameterization():
// corner c = 3 * face + k; its side is the edge that ends at its vertex
// (from the vertex of prev(c)); cls[c] is its UV vertex (a corner id).

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_CUT_TO_DISK_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_CUT_TO_DISK_H

#include <CGAL/Surface_mesh_seam_optimization/internal/Fixed_border_solver_traits.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Shortest_paths.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Union_find.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// One chart of the corner table, with what the cut needs.
struct Flat_chart
{
  const std::vector<int>* faces = nullptr;          // its faces
  const std::vector<int>* cls = nullptr;            // UV vertex of every corner of the mesh
  const std::vector<int>* copp = nullptr;           // opposite side, -1 on the input border
  const std::vector<char>* cut = nullptr;           // side on a chart boundary (seam or border)
  std::vector<std::vector<int> > loops;             // boundary loops, sides in walk order:
                                                    // loops[i][j + 1] ends where loops[i][j] starts
  int outer = -1;                                   // the loop mapped to the circle, -1: none
  std::function<double(int)> side_length;           // 3D length of a side
  std::function<std::array<double, 3>(int)> point;  // 3D point of a corner's vertex

  static int next(int c) { return c - c % 3 + (c + 1) % 3; }
  static int prev(int c) { return c - c % 3 + (c + 2) % 3; }
};

// A cut graph through the chart's handles: the sides (one per edge) whose
// edges cut the chart, with its holes filled, into a disk whose border is the
// outer loop (if any) and both sides of the cut. `border_sides` receives the
// inner-loop sides the cut runs along (a border already; rare).
class Handle_cut
{
  enum Kind { REAL, BORDER, VIRTUAL };
  struct Edge { int u, v, f1, f2; double length; int side; Kind kind; };

  const Flat_chart& m_chart;
  int m_genus;
  std::vector<Edge> m_edges;
  std::vector<int> m_adj_start, m_adj;  // node -> incident edges (CSR)
  int m_nodes = 0, m_dual_faces = 0;
  std::vector<int> m_candidates;        // roots to try, when no loop is collapsed into one

public:
  Handle_cut(const Flat_chart& chart, int genus) : m_chart(chart), m_genus(genus) { build(); }

  // The shortest cut graph found over the candidate roots; false if none
  // has the expected 2 * genus generators (cannot happen on a manifold chart).
  bool compute(std::vector<int>& real_sides, std::vector<int>& border_sides, double& length) const
  {
    bool found = false;
    length = std::numeric_limits<double>::infinity();
    for(int root : m_candidates)
    {
      std::vector<int> r, b;
      double l = 0;
      if(!cut_from(root, r, b, l) || !(l < length)) continue;
      found = true;
      length = l;
      real_sides.swap(r);
      border_sides.swap(b);
    }
    return found;
  }

private:
  void build()
  {
    const Flat_chart& ch = m_chart;
    const std::vector<int>& faces = *ch.faces;
    const std::vector<int>& cls = *ch.cls;
    const std::vector<int>& copp = *ch.copp;
    const std::vector<char>& cut = *ch.cut;
    const int F = static_cast<int>(faces.size());

    std::vector<int> local_face(cls.size() / 3, -1);
    for(int i = 0; i < F; ++i) local_face[faces[i]] = i;

    // Nodes: the outer loop collapsed into node 0, the other UV vertices, a
    // virtual node per inner loop.
    std::vector<int> node(cls.size(), -1);
    if(ch.outer >= 0)
    {
      for(int s : ch.loops[ch.outer]) node[cls[s]] = 0;
      m_nodes = 1;
    }
    double total = 0;
    for(int f : faces)
      for(int c = 3 * f; c < 3 * f + 3; ++c)
      {
        if(node[cls[c]] < 0) node[cls[c]] = m_nodes++;
        total += ch.side_length(c);
      }
    // Longer than any path of real edges: the cut avoids virtual and hole
    // edges (they still make the filled chart a closed surface).
    const double big = 4 * total + 1;

    // A cut through a vertex of an inner loop would pinch that hole onto the
    // chart's border (the two would touch there): such edges cost `big` too.
    std::vector<char> on_hole(m_nodes, 0);
    for(std::size_t i = 0; i < ch.loops.size(); ++i)
      if(int(i) != ch.outer)
        for(int s : ch.loops[i]) on_hole[node[cls[s]]] = 1;

    m_dual_faces = F;
    for(int f : faces)
      for(int c = 3 * f; c < 3 * f + 3; ++c)
        if(!cut[c] && c < copp[c])
        {
          const int u = node[cls[Flat_chart::prev(c)]], v = node[cls[c]];
          const double length = ch.side_length(c) + ((on_hole[u] || on_hole[v]) ? big : 0.);
          m_edges.push_back(Edge{ u, v, local_face[f], local_face[copp[c] / 3], length, c, REAL });
        }
    for(std::size_t i = 0; i < ch.loops.size(); ++i)
    {
      if(int(i) == ch.outer) continue;
      const std::vector<int>& loop = ch.loops[i];
      const int m = static_cast<int>(loop.size());
      const int v = m_nodes++, fan0 = m_dual_faces;
      m_dual_faces += m;
      for(int j = 0; j < m; ++j)
      {
        const int s = loop[j], s_next = loop[(j + 1) % m];
        m_edges.push_back(Edge{ node[cls[Flat_chart::prev(s)]], node[cls[s]], local_face[s / 3], fan0 + j,
                                big, s, BORDER });
        m_edges.push_back(Edge{ v, node[cls[s_next]], fan0 + j, fan0 + (j + 1) % m, big, -1, VIRTUAL });
      }
    }

    m_adj_start.assign(m_nodes + 1, 0);
    for(const Edge& e : m_edges) { ++m_adj_start[e.u + 1]; ++m_adj_start[e.v + 1]; }
    for(int i = 0; i < m_nodes; ++i) m_adj_start[i + 1] += m_adj_start[i];
    m_adj.resize(m_adj_start.back());
    std::vector<int> fill(m_adj_start.begin(), m_adj_start.end() - 1);
    for(int i = 0; i < int(m_edges.size()); ++i)
    {
      m_adj[fill[m_edges[i].u]++] = i;
      m_adj[fill[m_edges[i].v]++] = i;
    }

    if(ch.outer >= 0) { m_candidates.push_back(0); return; }
    // Closed: a few roots spread by farthest-point sampling (the greedy
    // loops are shortest through their root, which matters on a torus).
    const int n_roots = (std::min)(6, m_nodes);
    std::vector<double> nearest(m_nodes, std::numeric_limits<double>::infinity());
    int root = node[cls[3 * faces.front()]];
    for(int r = 0; r < n_roots; ++r)
    {
      m_candidates.push_back(root);
      std::vector<double> d;
      std::vector<int> pred;
      dijkstra(root, d, pred);
      int far = root;
      for(int i = 0; i < m_nodes; ++i)
      {
        nearest[i] = (std::min)(nearest[i], d[i]);
        if(nearest[i] > nearest[far] || (nearest[i] == nearest[far] && i < far)) far = i;
      }
      if(!(nearest[far] > 0)) break;
      root = far;
    }
  }

  void dijkstra(int root, std::vector<double>& dist, std::vector<int>& pred) const
  {
    dist.assign(m_nodes, std::numeric_limits<double>::infinity());
    pred.assign(m_nodes, -1);
    internal::dijkstra(std::vector<int>(1, root), dist,
      [this](int u, const auto& visit) {
        for(int i = m_adj_start[u]; i < m_adj_start[u + 1]; ++i)
        {
          const Edge& e = m_edges[m_adj[i]];
          visit(e.u == u ? e.v : e.u, e.length, m_adj[i]);
        }
      },
      [&pred](int, int w, int edge) { pred[w] = edge; });
  }

  bool cut_from(int root, std::vector<int>& real_sides, std::vector<int>& border_sides, double& length) const
  {
    std::vector<double> dist;
    std::vector<int> pred;
    dijkstra(root, dist, pred);
    const int ne = static_cast<int>(m_edges.size());
    std::vector<char> in_tree(ne, 0);
    for(int i = 0; i < m_nodes; ++i)
    {
      if(i == root) continue;
      if(pred[i] < 0) return false; // not connected
      in_tree[pred[i]] = 1;
    }
    // Dual spanning tree of the other edges, longest loops first: what is
    // left over are the 2g edges closing the shortest loops (greedy).
    std::vector<int> order;
    std::vector<double> weight(ne, 0);
    for(int i = 0; i < ne; ++i)
      if(!in_tree[i])
      {
        order.push_back(i);
        weight[i] = dist[m_edges[i].u] + dist[m_edges[i].v] + m_edges[i].length;
      }
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return weight[a] > weight[b]; });
    Union_find dual(m_dual_faces);
    std::vector<int> generators;
    for(int i : order)
    {
      const int a = dual.find(m_edges[i].f1), b = dual.find(m_edges[i].f2);
      if(a != b) dual.unite(a, b);
      else generators.push_back(i);
    }
    if(int(generators.size()) != 2 * m_genus) return false;

    std::vector<char> in_cut(ne, 0);
    for(int g : generators)
    {
      in_cut[g] = 1;
      for(int end : { m_edges[g].u, m_edges[g].v })
        for(int u = end; u != root && !in_cut[pred[u]]; )
        {
          in_cut[pred[u]] = 1;
          const Edge& e = m_edges[pred[u]];
          u = e.u == u ? e.v : e.u;
        }
    }
    length = 0;
    for(int i = 0; i < ne; ++i)
    {
      if(!in_cut[i]) continue;
      const Edge& e = m_edges[i];
      if(e.kind == VIRTUAL) return false; // would need a cut through a hole: never shorter
      (e.kind == REAL ? real_sides : border_sides).push_back(e.side);
      length += e.length; // `big` where the cut touches a hole: the last resort
    }
    return true;
  }
};

// Maps the chart cut along `slit` (sides, both of an edge marked) and
// `border_cut` to the plane: its holes filled with fans, the outer border
// (the only one left) on a circle by arc length, the rest by Tutte's
// uniform weights or Floater's mean value coordinates. Writes the UV of
// every corner of the chart's faces into `uv`; false if CGAL's
// parameterizer failed or the filled chart is not a disk.
inline bool map_filled_chart(const Flat_chart& ch, const std::vector<char>& slit,
                             const std::vector<int>& border_cut, bool mean_value,
                             std::vector<std::array<double, 2> >& uv)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  typedef CGAL::Simple_cartesian<double>                     K;
  typedef CGAL::Surface_mesh<K::Point_3>                     Disk;
  typedef boost::graph_traits<Disk>::vertex_descriptor       vertex_descriptor;
  typedef boost::graph_traits<Disk>::halfedge_descriptor     halfedge_descriptor;

  const std::vector<int>& faces = *ch.faces;
  const std::vector<int>& cls = *ch.cls;
  const std::vector<int>& copp = *ch.copp;
  const std::vector<char>& cut = *ch.cut;
  const int F = static_cast<int>(faces.size());

  // Filled corners: 3 per face of the chart, then 3 per fan face (one fan
  // face per inner-loop side s from a to b: corners at a, the hole's centre, b).
  std::vector<int> local(cls.size(), -1); // corner of the mesh -> filled corner
  for(int i = 0; i < F; ++i)
    for(int k = 0; k < 3; ++k) local[3 * faces[i] + k] = 3 * i + k;
  int n_fan = 0;
  for(std::size_t i = 0; i < ch.loops.size(); ++i)
    if(int(i) != ch.outer) n_fan += static_cast<int>(ch.loops[i].size());
  const int n = 3 * (F + n_fan);
  std::vector<int> fopp(n, -1), centre(n, -1); // centre: the hole of a fan corner at its centre
  std::vector<int> fan_side(F + n_fan, -1);     // the inner-loop side of a fan face
  std::vector<char> fcut(n, 0);
  std::vector<char> is_border_cut(cls.size(), 0);
  for(int s : border_cut) is_border_cut[s] = 1;

  for(int i = 0; i < F; ++i)
    for(int k = 0; k < 3; ++k)
    {
      const int c = 3 * faces[i] + k;
      if(!cut[c]) { fopp[3 * i + k] = local[copp[c]]; fcut[3 * i + k] = slit[c]; }
      else fcut[3 * i + k] = 1; // outer loop, unless an inner loop's fan takes it below
    }
  // Where the cut passes through a vertex of a hole, the hole opens onto the
  // border there: its fan is cut at that vertex too (else the two sides of
  // the cut would share one UV point). Twice on one hole would cut the fan
  // in two: left to the caller (split the chart).
  std::vector<char> on_cut(cls.size(), 0);
  for(int i = 0; i < F; ++i)
    for(int k = 0; k < 3; ++k)
    {
      const int c = 3 * faces[i] + k;
      if(slit[c] || is_border_cut[c]) on_cut[cls[c]] = on_cut[cls[Flat_chart::prev(c)]] = 1;
    }
  int fan = F;
  for(std::size_t i = 0; i < ch.loops.size(); ++i)
  {
    if(int(i) == ch.outer) continue;
    const std::vector<int>& loop = ch.loops[i];
    const int m = static_cast<int>(loop.size());
    int touched = 0;
    for(int j = 0; j < m; ++j)
    {
      if(on_cut[cls[loop[(j + 1) % m]]])
      {
        if(++touched > 1) return false;
        fcut[3 * (fan + j) + 1] = fcut[3 * (fan + (j + 1) % m) + 2] = 1;
      }
    }
    for(int j = 0; j < m; ++j)
    {
      const int s = loop[j], f = fan + j, f_next = fan + (j + 1) % m, f_prev = fan + (j + m - 1) % m;
      const int ls = local[s];
      fopp[ls] = 3 * f; fopp[3 * f] = ls;
      fcut[ls] = fcut[3 * f] = is_border_cut[s];
      fopp[3 * f + 1] = 3 * f_next + 2;   // side a -> centre, against the next fan's centre -> a
      fopp[3 * f + 2] = 3 * f_prev + 1;
      centre[3 * f + 1] = static_cast<int>(i);
      fan_side[f] = s;
    }
    fan += m;
  }

  // Filled vertices: corners joined across uncut sides.
  Union_find filled(n);
  for(int c = 0; c < n; ++c)
  {
    const int nx = Flat_chart::next(c);
    if(!fcut[nx] && fopp[nx] >= 0) filled.unite(c, fopp[nx]);
  }

  // Corner of the filled chart -> a point.
  std::vector<std::array<double, 3> > loop_centre(ch.loops.size(), std::array<double, 3>{{ 0, 0, 0 }});
  for(std::size_t i = 0; i < ch.loops.size(); ++i)
  {
    for(int s : ch.loops[i])
    {
      const std::array<double, 3> p = ch.point(s);
      for(int d = 0; d < 3; ++d) loop_centre[i][d] += p[d] / double(ch.loops[i].size());
    }
  }
  auto point_of = [&](int c) -> std::array<double, 3>
  {
    if(c < 3 * F) return ch.point(3 * faces[c / 3] + c % 3);
    if(centre[c] >= 0) return loop_centre[centre[c]];
    const int s = fan_side[c / 3];
    return ch.point(c % 3 == 0 ? Flat_chart::prev(s) : s);
  };
  Disk disk;
  std::vector<vertex_descriptor> vertex_of(n);
  std::vector<char> made(n, 0);
  for(int c = 0; c < n; ++c)
  {
    const int r = filled.find(c);
    if(made[r]) continue;
    made[r] = 1;
    const std::array<double, 3> p = point_of(c);
    vertex_of[r] = disk.add_vertex(K::Point_3(p[0], p[1], p[2]));
  }
  for(int f = 0; f < F + n_fan; ++f)
  {
    const vertex_descriptor a = vertex_of[filled.find(3 * f)], b = vertex_of[filled.find(3 * f + 1)],
                            c = vertex_of[filled.find(3 * f + 2)];
    if(disk.add_face(a, b, c) == Disk::null_face()) return false;
  }
  // One border, the circle's.
  halfedge_descriptor bhd;
  std::size_t borders = 0;
  std::vector<char> seen(num_halfedges(disk), 0);
  for(halfedge_descriptor h : halfedges(disk))
  {
    if(!is_border(h, disk) || seen[h.idx()]) continue;
    ++borders;
    bhd = h;
    for(halfedge_descriptor g : halfedges_around_face(h, disk)) seen[g.idx()] = 1;
  }
  if(borders != 1) return false;

  auto uvpm = disk.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  const SMP::Error_code status = mean_value
    ? SMP::parameterize(disk, SMP::Mean_value_coordinates_parameterizer_3<Disk>(), bhd, uvpm)
    : SMP::parameterize(disk, SMP::Barycentric_mapping_parameterizer_3<Disk, CGAL::Default, Fixed_border_solver_traits>(),
                        bhd, uvpm);
  if(status != SMP::OK) return false;
  for(int i = 0; i < F; ++i)
    for(int k = 0; k < 3; ++k)
    {
      const K::Point_2 p = get(uvpm, vertex_of[filled.find(3 * i + k)]);
      uv[3 * faces[i] + k] = {{ p.x(), p.y() }};
    }
  return true;
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_CUT_TO_DISK_H
