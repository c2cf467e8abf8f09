#include <CGAL/Surface_mesh_seam_optimization/internal/Block_ldlt.h>
#include "Block_ldlt_avx.h"
#include <random>
#include <chrono>
#include <cstdio>
#include <cstring>
typedef Eigen::SparseMatrix<double> Matrix;
Matrix hessian(int n, unsigned seed) {
  std::mt19937 rng(seed); std::normal_distribution<double> g(0., 1.);
  std::vector<Eigen::Triplet<double> > t;
  auto element = [&](const int v[3]) {
    Eigen::Matrix<double, 6, 4> G; for(int i = 0; i < 6; ++i) for(int j = 0; j < 4; ++j) G(i, j) = g(rng);
    const Eigen::Matrix<double, 6, 6> M = G * G.transpose();
    for(int a = 0; a < 3; ++a) for(int b = 0; b < 3; ++b) for(int c = 0; c < 2; ++c) for(int d = 0; d < 2; ++d)
      if(2 * v[a] + c >= 2 * v[b] + d) t.emplace_back(2 * v[a] + c, 2 * v[b] + d, M(2 * a + c, 2 * b + d));
  };
  for(int i = 0; i + 1 < n; ++i) for(int j = 0; j + 1 < n; ++j) {
    const int v0 = i * n + j, v1 = v0 + 1, v2 = v0 + n, v3 = v2 + 1;
    const int f0[3] = { v0, v1, v3 }, f1[3] = { v0, v3, v2 }; element(f0); element(f1); }
  for(int k = 0; k < 2 * n * n; ++k) t.emplace_back(k, k, 1e-3);
  Matrix A(2 * n * n, 2 * n * n); A.setFromTriplets(t.begin(), t.end()); A.makeCompressed(); return A;
}
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
