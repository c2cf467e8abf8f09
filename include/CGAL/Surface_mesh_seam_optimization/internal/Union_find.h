// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_UNION_FIND_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_UNION_FIND_H

#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Flat union-find over 0..n-1 (CGAL::Union_find hands out handles instead).
struct Union_find
{
  std::vector<int> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i)
  {
    while(parent[i] != i)
    {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  }
  // The smaller index becomes the root, so roots do not depend on the merge order.
  void unite(int a, int b)
  {
    a = find(a);
    b = find(b);
    if(a < b) parent[b] = a;
    else if(b < a) parent[a] = b;
  }
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
