#include <CGAL/Surface_mesh_seam_optimization/internal/Block_ldlt.h>
#include "Block_ldlt_sse2.h"
#include "bench_hessian.h"
#include <chrono>
#include <cstdio>
#include <cstring>
#include <algorithm>
int main() {
  for(int n : {35, 50, 71, 100, 160}) {
    Matrix A = hessian(n, 7);
    CGAL::Surface_mesh_seam_optimization::internal_sse2::Block_ldlt o; o.analyze(A);
    CGAL::Surface_mesh_seam_optimization::internal::Block_ldlt p; p.analyze(A);
    auto t = [&](auto& s) { auto t0 = std::chrono::steady_clock::now(); s.factorize(A); return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    std::vector<double> r, ts, ta;
    int reps = n < 100 ? 201 : 41;
    for(int k = 0; k < reps; ++k) {
      double a, b;
      if(k % 2) { a = t(o); b = t(p); } else { b = t(p); a = t(o); }
      r.push_back(b / a); ts.push_back(a); ta.push_back(b);
    }
    std::sort(r.begin(), r.end()); std::sort(ts.begin(), ts.end()); std::sort(ta.begin(), ta.end());
    std::printf("unknowns %ld  median sse2 %.5f avx %.5f  median ratio x%.3f (q1 %.3f q3 %.3f)\n", (long)A.rows(), ts[reps/2], ta[reps/2], r[reps/2], r[reps/4], r[3*reps/4]);
  }
}
