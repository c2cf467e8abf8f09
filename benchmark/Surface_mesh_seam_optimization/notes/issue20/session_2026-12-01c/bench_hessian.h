// The Hessian-like matrix of the two benches of this folder: a projected
// 6x6 element Hessian (random, rank 4) per triangle of an n x n grid, in 2x2
// blocks, plus 1e-3 on the diagonal (as test_core's block LDL^T test).
#include <Eigen/Sparse>
#include <random>
#include <vector>
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
