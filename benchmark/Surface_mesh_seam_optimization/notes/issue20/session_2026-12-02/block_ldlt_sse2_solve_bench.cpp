#include <CGAL/Surface_mesh_seam_optimization/internal/Block_ldlt.h>
#include "Block_ldlt_new.h"
#include "bench_hessian.h"
#include <chrono>
#include <cstdio>
#include <cstring>
#include <algorithm>
int main() {
  for(int n : {35, 50, 71, 100, 160}) {
    Matrix A = hessian(n, 7);
    Eigen::VectorXd b = Eigen::VectorXd::Random(A.rows()), x0, x1;
    CGAL::Surface_mesh_seam_optimization::internal::Block_ldlt o; o.analyze(A); o.factorize(A);
    CGAL::Surface_mesh_seam_optimization::internal_new::Block_ldlt p; p.analyze(A); p.factorize(A);
    auto t = [&](auto& s, Eigen::VectorXd& x) { auto t0 = std::chrono::steady_clock::now(); s.solve(b, x); return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    std::vector<double> r;
    int reps = 401;
    for(int k = 0; k < reps; ++k) { double a, c; if(k % 2) { a = t(o, x0); c = t(p, x1); } else { c = t(p, x1); a = t(o, x0); } r.push_back(c / a); }
    std::sort(r.begin(), r.end());
    std::printf("unknowns %ld  solve new/old median x%.3f (q1 %.3f q3 %.3f) same bits %d\n", (long)A.rows(), r[reps/2], r[reps/4], r[3*reps/4], (int)(std::memcmp(x0.data(), x1.data(), sizeof(double) * x0.size()) == 0));
  }
}
