// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Loops over the elements (triangles) of a map that run in parallel with TBB
// and still give the serial loop's bits whatever the number of threads: the
// terms are computed in parallel into a buffer of a bounded block and added
// in element order, so floating-point sums are the same as one thread's.

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_PARALLEL_ELEMENTS_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_PARALLEL_ELEMENTS_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#endif

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// Below this many elements a loop stays serial: the fork and join would cost
// more than the work (an element's energy is tens of nanoseconds).
constexpr std::size_t parallel_elements_minimum = 8192;
// Elements computed per block before their terms are added (so the buffer
// stays in the cache and its size does not grow with the mesh).
constexpr std::size_t parallel_elements_block = 4096;
// Elements per task inside a block.
constexpr std::size_t parallel_elements_grain = 512;

// Calls compute(k, terms + k' * stride) for every k in [0, n) (k' = k within
// its block), in parallel, then add(k, that pointer) in increasing k.
// `buffer` is the caller's, kept between calls.
template <typename Compute, typename Add>
void for_each_element_in_order(std::size_t n, std::size_t stride, std::vector<double>& buffer,
                               const Compute& compute, const Add& add)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(n >= parallel_elements_minimum)
  {
    buffer.resize(stride * (std::min)(n, parallel_elements_block));
    for(std::size_t first = 0; first < n; first += parallel_elements_block)
    {
      const std::size_t last = (std::min)(n, first + parallel_elements_block);
      tbb::parallel_for(tbb::blocked_range<std::size_t>(first, last, parallel_elements_grain),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for(std::size_t k = r.begin(); k != r.end(); ++k)
                            compute(k, &buffer[stride * (k - first)]);
                        });
      for(std::size_t k = first; k < last; ++k) add(k, &buffer[stride * (k - first)]);
    }
    return;
  }
#endif
  buffer.resize(stride);
  for(std::size_t k = 0; k < n; ++k)
  {
    compute(k, buffer.data());
    add(k, buffer.data());
  }
}

// sum over k in [0, n) of term(k), added in increasing k (the serial loop's bits).
template <typename Term>
double ordered_sum(std::size_t n, const Term& term)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(n >= parallel_elements_minimum)
  {
    // (one buffer per calling thread: the starts of optimize_seams() run side by side)
    thread_local std::vector<double> buffer;
    double sum = 0;
    for_each_element_in_order(n, 1, buffer, [&](std::size_t k, double* t) { *t = term(k); },
                              [&](std::size_t, const double* t) { sum += *t; });
    return sum;
  }
#endif
  double sum = 0;
  for(std::size_t k = 0; k < n; ++k) sum += term(k);
  return sum;
}

// min over k in [0, n) of term(k), +inf if n = 0; a NaN term is ignored, as
// std::min(t, NaN) = t does in the serial loop (min is exact: any order).
template <typename Term>
double parallel_min(std::size_t n, const Term& term)
{
  const double inf = std::numeric_limits<double>::infinity();
  auto serial = [&](std::size_t first, std::size_t last, double t) {
    for(std::size_t k = first; k < last; ++k) t = (std::min)(t, term(k));
    return t;
  };
#ifdef CGAL_LINKED_WITH_TBB
  if(n >= parallel_elements_minimum)
    return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, parallel_elements_grain), inf,
      [&](const tbb::blocked_range<std::size_t>& r, double t) { return serial(r.begin(), r.end(), t); },
      [](double a, double b) { return (std::min)(a, b); });
#endif
  return serial(0, n, inf);
}

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
