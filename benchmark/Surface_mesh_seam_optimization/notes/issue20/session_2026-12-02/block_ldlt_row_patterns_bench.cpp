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
    Eigen::VectorXd b = Eigen::VectorXd::Random(A.rows()), x0, x1, x2;
    CGAL::Surface_mesh_seam_optimization::internal_sse2::Block_ldlt o; o.analyze(A);
    CGAL::Surface_mesh_seam_optimization::internal::Block_ldlt p; p.analyze(A);
    for(bool avx : {true, false}) {
      auto t = [&](auto& s) { auto t0 = std::chrono::steady_clock::now(); s.factorize(A, avx); return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
      std::vector<double> r;
      int reps = n < 100 ? 201 : 41;
      for(int k = 0; k < reps; ++k) { double a, c; if(k % 2) { a = t(o); c = t(p); } else { c = t(p); a = t(o); } r.push_back(c / a); }
      std::sort(r.begin(), r.end());
      o.solve(b, x0); p.solve(b, x1);
      std::printf("unknowns %ld avx %d new/old x%.3f (q1 %.3f q3 %.3f) same bits %d\n", (long)A.rows(), (int)avx, r[reps/2], r[reps/4], r[3*reps/4],
        (int)(std::memcmp(x0.data(), x1.data(), sizeof(double) * x0.size()) == 0));
    }
    // analysis time
    auto t0 = std::chrono::steady_clock::now(); for(int k=0;k<5;++k) o.analyze(A); auto t1 = std::chrono::steady_clock::now(); for(int k=0;k<5;++k) p.analyze(A); auto t2 = std::chrono::steady_clock::now();
    std::printf("   analysis old %.5f new %.5f s\n", std::chrono::duration<double>(t1-t0).count()/5, std::chrono::duration<double>(t2-t1).count()/5);
  }
}
