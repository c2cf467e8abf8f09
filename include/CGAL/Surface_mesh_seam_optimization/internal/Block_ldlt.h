// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Sparse LDL^T by 2x2 blocks: the unknowns (2i, 2i+1) of one UV vertex are
// eliminated together. The Hessians of the package couple the two
// coordinates of every vertex with the two of each neighbour, so the factor
// has the same fill by blocks as by scalars, and the block version does one
// index lookup per four entries (and SSE2 arithmetic): 2.5-4 times faster
// numeric factorizations than Eigen's SimplicialLDLT at 10k-48k unknowns
// (notes/issue20/session_2026-12-01).

#ifndef CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_BLOCK_LDLT_H
#define CGAL_SURFACE_MESH_SEAM_OPTIMIZATION_INTERNAL_BLOCK_LDLT_H

#include <Eigen/Sparse>
#include <Eigen/OrderingMethods>

#ifdef __SSE2__
#include <emmintrin.h>
#endif

// The update of the factorization by 256-bit operations where the CPU has
// AVX, chosen at run time (a build for any x86-64 runs everywhere): the same
// operations in the same order, so the same bits (notes/issue20/session_2026-12-02).
#if defined(__SSE2__) && (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__)) && \
    !defined(CGAL_SMSO_NO_AVX_DISPATCH)
#define CGAL_SMSO_BLOCK_LDLT_AVX 1
#include <immintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_seam_optimization {
namespace internal {

// A = P^T L D L^T P with L unit lower triangular by 2x2 blocks and D block
// diagonal (2x2 symmetric blocks), P an AMD ordering of the vertices (of the
// graph of blocks). Up-looking, as Eigen's SimplicialLDLT, by blocks.
class Block_ldlt
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;

  // The graph of blocks of A (compressed; its lower triangle is read): the
  // block rows R >= C of each block column C, sorted. False if A is not made
  // of full 2x2 blocks: even size, and every block with an entry in the lower
  // triangle has all its entries of the lower triangle stored.
  static bool block_graph(const Matrix& A, std::vector<int>& graph_outer, std::vector<int>& graph_inner)
  {
    if(!A.isCompressed() || A.rows() != A.cols() || A.rows() % 2 != 0 || A.rows() == 0) return false;
    const int n = int(A.rows() / 2);
    std::vector<int> mark(std::size_t(n), -1), count(std::size_t(n), 0), rows;
    graph_outer.assign(std::size_t(n) + 1, 0);
    graph_inner.clear();
    graph_inner.reserve(std::size_t(A.nonZeros()) / 3 + std::size_t(n));
    for(int C = 0; C < n; ++C)
    {
      block_column(A, C, mark, count, rows);
      for(const int R : rows)
        if(count[std::size_t(R)] != (R == C ? 3 : 4)) return false;
      std::sort(rows.begin(), rows.end());
      graph_inner.insert(graph_inner.end(), rows.begin(), rows.end());
      graph_outer[std::size_t(C) + 1] = int(graph_inner.size());
    }
    return true;
  }

  static bool made_of_blocks(const Matrix& A)
  {
    std::vector<int> graph_outer, graph_inner;
    return block_graph(A, graph_outer, graph_inner);
  }

  // false if A is not made of full 2x2 blocks (see block_graph())
  bool analyze(const Matrix& A)
  {
    m_n = 0;
    std::vector<int> graph_outer, graph_inner;
    return block_graph(A, graph_outer, graph_inner) && analyze_blocks(A, graph_outer, graph_inner);
  }

  // analyze() of an A whose graph of blocks the caller has (block_graph()
  // scans the whole pattern: the caller that chose the solver by it passes
  // it on rather than scanning again). `ordering`: the new index of each
  // vertex (a permutation of them) instead of AMD's.
  bool analyze_blocks(const Matrix& A, const std::vector<int>& graph_outer, const std::vector<int>& graph_inner,
                      const std::vector<int>* ordering = nullptr)
  {
    m_n = 0;
    const int n = int(A.rows() / 2);
    const int* outer = A.outerIndexPtr();
    const int* inner = A.innerIndexPtr();
    if(ordering)
    {
      if(ordering->size() != std::size_t(n)) return false;
      m_perm = *ordering;
    }
    else
    {
      // (the graph as a matrix only for Eigen's AMD)
      Matrix G(n, n);
      G.resizeNonZeros(Eigen::Index(graph_inner.size()));
      std::copy(graph_outer.begin(), graph_outer.end(), G.outerIndexPtr());
      std::copy(graph_inner.begin(), graph_inner.end(), G.innerIndexPtr());
      std::fill(G.valuePtr(), G.valuePtr() + graph_inner.size(), 1.);
      Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
      Eigen::AMDOrdering<int>()(G.selfadjointView<Eigen::Lower>(), inverse);
      m_perm.resize(std::size_t(n));
      for(int k = 0; k < n; ++k) m_perm[std::size_t(inverse.indices()[k])] = k;
    }
    // the upper triangle of the permuted graph, by column; the slot of each
    // stored entry of A in its block (4 values per block, row-major)
    const int* Gouter = graph_outer.data();
    const int* Ginner = graph_inner.data();
    m_up.assign(std::size_t(n) + 1, 0);
    for(int C = 0; C < n; ++C)
      for(int q = Gouter[C]; q < Gouter[C + 1]; ++q)
        ++m_up[std::size_t((std::max)(m_perm[std::size_t(Ginner[q])], m_perm[std::size_t(C)])) + 1];
    for(int k = 0; k < n; ++k) m_up[std::size_t(k) + 1] += m_up[std::size_t(k)];
    m_ui.resize(std::size_t(m_up[std::size_t(n)]));
    std::vector<int> fill(m_up.begin(), m_up.end() - 1), block_of(std::size_t(n), -1);
    m_slot.assign(std::size_t(A.nonZeros()), -1);
    for(int C = 0; C < n; ++C)
    {
      const int pC = m_perm[std::size_t(C)];
      for(int q = Gouter[C]; q < Gouter[C + 1]; ++q)
      {
        const int R = Ginner[q], pR = m_perm[std::size_t(R)];
        const int b = fill[std::size_t((std::max)(pR, pC))]++;
        m_ui[std::size_t(b)] = (std::min)(pR, pC);
        block_of[std::size_t(R)] = b;
      }
      for(int c = 2 * C; c < 2 * C + 2; ++c)
        for(int p = outer[c]; p < outer[c + 1]; ++p)
        {
          const int r = inner[p];
          if(r < c) continue;
          const int R = r / 2, pR = m_perm[std::size_t(R)];
          // (rows of the block's row vertex, columns of its column vertex; a
          // diagonal block's (0, 1) entry is read from its (1, 0) one)
          const int at = pR <= pC ? 2 * (r % 2) + c % 2 : 2 * (c % 2) + r % 2;
          m_slot[std::size_t(p)] = 4 * block_of[std::size_t(R)] + at;
        }
    }
    m_values.assign(4 * m_ui.size(), 0.);
    // Elimination tree, the number of blocks of each column of L, and each
    // row of L in the order the factorization eliminates it (the tree's
    // topological order, whose sums give the bits) with the slot of each of
    // its blocks in its column: the numeric factorization has no symbolic
    // work left.
    std::vector<int> parent(std::size_t(n), -1), flag(std::size_t(n), -1);
    std::vector<int> nz(std::size_t(n), 0), pattern(static_cast<std::size_t>(n));
    m_rp.assign(std::size_t(n) + 1, 0);
    m_ri.clear();
    m_ri.reserve(4 * m_ui.size());
    for(int k = 0; k < n; ++k)
    {
      flag[std::size_t(k)] = k;
      int top = n;
      for(int p = m_up[std::size_t(k)]; p < m_up[std::size_t(k) + 1]; ++p)
      {
        int i = m_ui[std::size_t(p)], len = 0;
        for(; i < k && flag[std::size_t(i)] != k; i = parent[std::size_t(i)])
        {
          if(parent[std::size_t(i)] == -1) parent[std::size_t(i)] = k;
          ++nz[std::size_t(i)];
          flag[std::size_t(i)] = k;
          pattern[std::size_t(len++)] = i;
        }
        while(len > 0) pattern[std::size_t(--top)] = pattern[std::size_t(--len)];
      }
      m_ri.insert(m_ri.end(), pattern.begin() + top, pattern.end());
      m_rp[std::size_t(k) + 1] = int(m_ri.size());
    }
    m_lp.assign(std::size_t(n) + 1, 0);
    for(int k = 0; k < n; ++k) m_lp[std::size_t(k) + 1] = m_lp[std::size_t(k)] + nz[std::size_t(k)];
    const std::size_t nnz = m_ri.size();
    m_li.resize(nnz);
    m_rslot.resize(nnz);
    std::vector<int>& next = nz; // (the next free slot of each column)
    std::copy(m_lp.begin(), m_lp.end() - 1, next.begin());
    for(int k = 0; k < n; ++k)
      for(int t = m_rp[std::size_t(k)]; t < m_rp[std::size_t(k) + 1]; ++t)
      {
        const int i = m_ri[std::size_t(t)];
        m_rslot[std::size_t(t)] = next[std::size_t(i)];
        m_li[std::size_t(next[std::size_t(i)]++)] = k;
      }
    m_lx.resize(4 * nnz);
    m_dinv.resize(4 * std::size_t(n));
    m_y.assign(4 * std::size_t(n), 0.);
    m_n = n;
    return true;
  }

  // false on a singular (or non-finite) diagonal block; `avx`: the AVX
  // update where the CPU has it (false: SSE2, the same bits)
  bool factorize(const Matrix& A, bool avx = true)
  {
    if(m_n == 0 || !A.isCompressed() || std::size_t(A.nonZeros()) != m_slot.size()) return false;
    const double* a = A.valuePtr();
    for(std::size_t p = 0; p < m_slot.size(); ++p)
      if(m_slot[p] >= 0) m_values[std::size_t(m_slot[p])] = a[p];
    const int n = m_n;
#ifdef CGAL_SMSO_BLOCK_LDLT_AVX
    static const bool cpu_has_avx = __builtin_cpu_supports("avx");
    avx = avx && cpu_has_avx;
#else
    (void)avx;
#endif
    for(int k = 0; k < n; ++k)
    {
      // scatter column k of the upper triangle
      double d[4] = { 0., 0., 0., 0. };
      for(int p = m_up[std::size_t(k)]; p < m_up[std::size_t(k) + 1]; ++p)
      {
        const int i = m_ui[std::size_t(p)];
        const double* v = &m_values[4 * std::size_t(p)];
        if(i == k)
        {
          d[0] = v[0]; d[1] = v[2]; d[2] = v[2]; d[3] = v[3];
          continue;
        }
        double* y = &m_y[4 * std::size_t(i)];
        for(int q = 0; q < 4; ++q) y[q] += v[q];
      }
      // row k of L by a sparse triangular solve, and D_k
#ifdef CGAL_SMSO_BLOCK_LDLT_AVX
      if(avx) eliminate_row_avx(k, d);
      else
#endif
      for(int t = m_rp[std::size_t(k)]; t < m_rp[std::size_t(k) + 1]; ++t)
      {
        const int i = m_ri[std::size_t(t)], end = m_rslot[std::size_t(t)];
        double* yi = &m_y[4 * std::size_t(i)];
        const double y0 = yi[0], y1 = yi[1], y2 = yi[2], y3 = yi[3];
        yi[0] = yi[1] = yi[2] = yi[3] = 0.;
        // Y_r -= L_ri Y_i (the loop of the factorization's time; SSE2 does
        // each row of the 2x2 product at once, the same operations in the
        // same order as the scalar code: x0.70 time at 10k-20k unknowns)
#ifdef __SSE2__
        const __m128d ya = _mm_set_pd(y1, y0), yb = _mm_set_pd(y3, y2);
        for(int p = m_lp[std::size_t(i)]; p < end; ++p)
        {
          const double* l = &m_lx[4 * std::size_t(p)];
          double* r = &m_y[4 * std::size_t(m_li[std::size_t(p)])];
          const __m128d l01 = _mm_loadu_pd(l), l23 = _mm_loadu_pd(l + 2);
          const __m128d top = _mm_add_pd(_mm_mul_pd(_mm_unpacklo_pd(l01, l01), ya), _mm_mul_pd(_mm_unpackhi_pd(l01, l01), yb));
          const __m128d bottom = _mm_add_pd(_mm_mul_pd(_mm_unpacklo_pd(l23, l23), ya), _mm_mul_pd(_mm_unpackhi_pd(l23, l23), yb));
          _mm_storeu_pd(r, _mm_sub_pd(_mm_loadu_pd(r), top));
          _mm_storeu_pd(r + 2, _mm_sub_pd(_mm_loadu_pd(r + 2), bottom));
        }
#else
        for(int p = m_lp[std::size_t(i)]; p < end; ++p)
        {
          const double* l = &m_lx[4 * std::size_t(p)];
          double* r = &m_y[4 * std::size_t(m_li[std::size_t(p)])];
          r[0] -= l[0] * y0 + l[1] * y2;
          r[1] -= l[0] * y1 + l[1] * y3;
          r[2] -= l[2] * y0 + l[3] * y2;
          r[3] -= l[2] * y1 + l[3] * y3;
        }
#endif
        store_row_block(i, end, y0, y1, y2, y3, d);
      }
      // (symmetric up to rounding)
      const double off = 0.5 * (d[1] + d[2]);
      const double det = d[0] * d[3] - off * off;
      if(!(det != 0.) || !std::isfinite(det)) return false;
      double* e = &m_dinv[4 * std::size_t(k)];
      e[0] = d[3] / det; e[1] = -off / det; e[2] = e[1]; e[3] = d[0] / det;
    }
    return true;
  }

  // x = A^-1 b with the last factorization; false if x is not finite
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x)
  {
    const int n = m_n;
    if(n == 0 || b.size() != 2 * Eigen::Index(n)) return false;
    m_x.resize(2 * std::size_t(n));
    double* z = m_x.data();
    for(int i = 0; i < n; ++i)
    {
      z[2 * m_perm[std::size_t(i)]] = b[2 * i];
      z[2 * m_perm[std::size_t(i)] + 1] = b[2 * i + 1];
    }
    for(int j = 0; j < n; ++j)
    {
      const double u = z[2 * j], v = z[2 * j + 1];
      for(int p = m_lp[std::size_t(j)]; p < m_lp[std::size_t(j) + 1]; ++p)
      {
        const double* l = &m_lx[4 * std::size_t(p)];
        double* r = z + 2 * m_li[std::size_t(p)];
        r[0] -= l[0] * u + l[1] * v;
        r[1] -= l[2] * u + l[3] * v;
      }
    }
    for(int j = 0; j < n; ++j)
    {
      const double* e = &m_dinv[4 * std::size_t(j)];
      const double u = z[2 * j], v = z[2 * j + 1];
      z[2 * j] = e[0] * u + e[1] * v;
      z[2 * j + 1] = e[2] * u + e[3] * v;
    }
    for(int j = n - 1; j >= 0; --j)
    {
      double u = z[2 * j], v = z[2 * j + 1];
      for(int p = m_lp[std::size_t(j)]; p < m_lp[std::size_t(j) + 1]; ++p)
      {
        const double* l = &m_lx[4 * std::size_t(p)];
        const double* r = z + 2 * m_li[std::size_t(p)];
        u -= l[0] * r[0] + l[2] * r[1];
        v -= l[1] * r[0] + l[3] * r[1];
      }
      z[2 * j] = u;
      z[2 * j + 1] = v;
    }
    x.resize(b.size());
    for(int i = 0; i < n; ++i)
    {
      x[2 * i] = z[2 * m_perm[std::size_t(i)]];
      x[2 * i + 1] = z[2 * m_perm[std::size_t(i)] + 1];
    }
    return x.allFinite();
  }

  // blocks of L below the diagonal (each 4 entries)
  std::size_t factor_blocks() const { return m_li.size(); }
  // the new index of each vertex in the last analysis (see analyze_blocks())
  const std::vector<int>& ordering() const { return m_perm; }

private:
  // L_ki = Y_i^T D_i^-1 into its slot `end` of column i, D_k -= L_ki Y_i
  void store_row_block(int i, int end, double y0, double y1, double y2, double y3, double* d)
  {
    const double* e = &m_dinv[4 * std::size_t(i)];
    const double l0 = y0 * e[0] + y2 * e[2], l1 = y0 * e[1] + y2 * e[3];
    const double l2 = y1 * e[0] + y3 * e[2], l3 = y1 * e[1] + y3 * e[3];
    d[0] -= l0 * y0 + l1 * y2;
    d[1] -= l0 * y1 + l1 * y3;
    d[2] -= l2 * y0 + l3 * y2;
    d[3] -= l2 * y1 + l3 * y3;
    double* out = &m_lx[4 * std::size_t(end)];
    out[0] = l0; out[1] = l1; out[2] = l2; out[3] = l3;
  }

#ifdef CGAL_SMSO_BLOCK_LDLT_AVX
  // The row loop of factorize() with Y_r -= L_ri Y_i as one 256-bit
  // operation per block: L's block (l0, l1, l2, l3) duplicated against
  // (y0, y1, y0, y1) and swapped against (y2, y3, y2, y3), the SSE2 code's
  // products and sums in its order (no FMA). The whole loop, not the update
  // alone: a call per column costs what AVX gains on short columns.
  __attribute__((target("avx"))) void eliminate_row_avx(int k, double* d)
  {
    for(int t = m_rp[std::size_t(k)]; t < m_rp[std::size_t(k) + 1]; ++t)
    {
      const int i = m_ri[std::size_t(t)], end = m_rslot[std::size_t(t)];
      double* yi = &m_y[4 * std::size_t(i)];
      const double y0 = yi[0], y1 = yi[1], y2 = yi[2], y3 = yi[3];
      yi[0] = yi[1] = yi[2] = yi[3] = 0.;
      const __m256d ya = _mm256_set_pd(y1, y0, y1, y0), yb = _mm256_set_pd(y3, y2, y3, y2);
      for(int p = m_lp[std::size_t(i)]; p < end; ++p)
      {
        const __m256d l = _mm256_loadu_pd(&m_lx[4 * std::size_t(p)]);
        double* r = &m_y[4 * std::size_t(m_li[std::size_t(p)])];
        const __m256d u = _mm256_add_pd(_mm256_mul_pd(_mm256_movedup_pd(l), ya), _mm256_mul_pd(_mm256_permute_pd(l, 0xF), yb));
        _mm256_storeu_pd(r, _mm256_sub_pd(_mm256_loadu_pd(r), u));
      }
      store_row_block(i, end, y0, y1, y2, y3, d);
    }
  }
#endif

  // the block rows R >= C of block column C, each once, and how many entries
  // of the lower triangle each has stored (in count)
  static void block_column(const Matrix& A, int C, std::vector<int>& mark, std::vector<int>& count,
                           std::vector<int>& rows)
  {
    const int* outer = A.outerIndexPtr();
    const int* inner = A.innerIndexPtr();
    rows.clear();
    for(int c = 2 * C; c < 2 * C + 2; ++c)
      for(int p = outer[c]; p < outer[c + 1]; ++p)
      {
        if(inner[p] < c) continue;
        const int R = inner[p] / 2;
        if(mark[std::size_t(R)] != C) { mark[std::size_t(R)] = C; count[std::size_t(R)] = 0; rows.push_back(R); }
        ++count[std::size_t(R)];
      }
  }

  int m_n = 0; // vertices (blocks per side); 0: nothing analysed
  std::vector<int> m_perm; // new index of each vertex
  std::vector<int> m_up, m_ui; // upper triangle of the permuted graph (column starts, rows)
  std::vector<int> m_slot; // entry of A -> value in m_values (-1: upper triangle, not read)
  std::vector<double> m_values; // blocks of m_ui, 4 values each
  std::vector<int> m_lp, m_li;
  std::vector<int> m_rp, m_ri, m_rslot; // rows of L: starts, columns, slots in their columns
  std::vector<double> m_lx, m_dinv, m_y, m_x;
};

} // namespace internal
} // namespace Surface_mesh_seam_optimization
} // namespace CGAL

#endif
