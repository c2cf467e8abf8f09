// Block LDL^T: the SSE2 update against the AVX one (block_ldlt_avx_update.patch),
// speed and bits. Block_ldlt_avx.h: the patched header with namespace
// internal renamed internal_avx and its include guard renamed. Build:
// g++ -O2 -std=c++17 -I<repo>/include -I/usr/include/eigen3 block_ldlt_avx_bench.cpp
#include <CGAL/Surface_mesh_seam_optimization/internal/Block_ldlt.h>
#include "Block_ldlt_avx.h"
#include "bench_hessian.h"
#include <random>
#include <chrono>
#include <cstdio>
#include <cstring>
int main() {
  for(int n : {50, 71, 100, 160}) {
    Matrix A = hessian(n, 7);
    Eigen::VectorXd b = Eigen::VectorXd::Random(A.rows()), x0, x1;
    CGAL::Surface_mesh_seam_optimization::internal::Block_ldlt o; o.analyze(A);
    CGAL::Surface_mesh_seam_optimization::internal_avx::Block_ldlt p; p.analyze(A);
    auto time = [&](auto&& f) { double best = 1e9; for(int r = 0; r < 9; ++r) { auto t0 = std::chrono::steady_clock::now(); f(); best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()); } return best; };
    double ts = 0, ta = 0;
    for(int round = 0; round < 3; ++round) { ts += time([&]{ o.factorize(A); }); ta += time([&]{ p.factorize(A); }); }
    o.solve(b, x0); p.solve(b, x1);
    std::printf("unknowns %ld  sse2 %.4f s  avx %.4f s  (x%.3f)  same bits %d\n", (long)A.rows(), ts/3, ta/3, ta/ts,
                (int)(std::memcmp(x0.data(), x1.data(), sizeof(double) * x0.size()) == 0));
  }
}
