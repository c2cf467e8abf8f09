// Block LDL^T: the loop over rows (Block_ldlt_old.h: 9f15788's header with
// namespace internal renamed internal_old and its include guard renamed)
// against subtrees eliminated in parallel (<repo>/include with
// block_ldlt_subtree_parallel.patch applied), speed and bits. Build:
// g++ -O2 -std=c++17 -DCGAL_LINKED_WITH_TBB -I<repo>/include -I/usr/include/eigen3 block_ldlt_subtree_parallel_bench.cpp -ltbb
#include <CGAL/Surface_mesh_seam_optimization/internal/Block_ldlt.h>
#include "Block_ldlt_old.h"
#include "bench_hessian.h"
#include <tbb/global_control.h>
#include <random>
#include <chrono>
#include <cstdio>
#include <cstring>
int main(int argc, char** argv) {
  for(int n : {30, 71, 100, 160}) {
    Matrix A = hessian(n, 7);
    Eigen::VectorXd b = Eigen::VectorXd::Random(A.rows()), x_old, x1, x2;
    CGAL::Surface_mesh_seam_optimization::internal_old::Block_ldlt o;
    o.analyze(A);
    auto time = [&](auto&& f) { double best = 1e9; for(int r = 0; r < 7; ++r) { auto t0 = std::chrono::steady_clock::now(); f(); best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()); } return best; };
    double t_old = time([&]{ o.factorize(A); });
    o.solve(b, x_old);
    CGAL::Surface_mesh_seam_optimization::internal::Block_ldlt p;
    p.analyze(A);
    double t1, t2;
    { tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1); t1 = time([&]{ p.factorize(A); }); p.solve(b, x1); }
    { tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2); t2 = time([&]{ p.factorize(A); }); p.solve(b, x2); }
    bool same1 = std::memcmp(x1.data(), x_old.data(), sizeof(double) * x1.size()) == 0;
    bool same2 = std::memcmp(x2.data(), x_old.data(), sizeof(double) * x1.size()) == 0;
    std::printf("unknowns %ld parallel %d critical share %.3f  old %.4f s  new 1 thread %.4f  2 threads %.4f (x%.2f)  same bits %d %d\n",
      (long)A.rows(), (int)p.eliminates_subtrees_in_parallel(), p.critical_share(), t_old, t1, t2, t_old / t2, same1, same2);
  }
}
