// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Distortion energies: values at hand-computed Jacobians, barrier, finite
// difference checks of gradient and Hessian, PSD projection.

#define BOOST_TEST_MODULE test_energy
#include <boost/test/unit_test.hpp>

#include <CGAL/Surface_mesh_seam_optimization/ARAP_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/Conformal_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Isotropic_energy_eigensystem.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Mesh_energy.h>

#include <Eigen/Dense>

#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

namespace SMSO = CGAL::Surface_mesh_seam_optimization;

namespace {

const double inf = std::numeric_limits<double>::infinity();
const double pi = 3.14159265358979323846;

Eigen::Matrix2d rotation(double a)
{
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

Eigen::Matrix2d make_J(double a, double s1, double s2, double b)
{
  return rotation(a) * Eigen::Vector2d(s1, s2).asDiagonal() * rotation(b);
}

Eigen::Matrix2d mat(double a, double b, double c, double d)
{
  Eigen::Matrix2d J;
  J << a, b, c, d;
  return J;
}

// Random J = R(a) diag(s1, s2) R(b), singular values log-uniform in [lo, hi].
struct Random_J
{
  std::mt19937 gen;
  explicit Random_J(unsigned seed) : gen(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
  Eigen::Matrix2d operator()(double lo, double hi)
  {
    const double s1 = std::exp(uniform(std::log(lo), std::log(hi)));
    const double s2 = std::exp(uniform(std::log(lo), std::log(hi)));
    return make_J(uniform(-pi, pi), s1, s2, uniform(-pi, pi));
  }
};

Eigen::Vector4d vec(const Eigen::Matrix2d& M) { return Eigen::Map<const Eigen::Vector4d>(M.data()); }

// Relative errors of the analytic gradient (against central differences of
// value()) and of the unprojected Hessian (against central differences of the
// analytic gradient), relative to max(1, norm).
template <class Energy>
std::pair<double, double> fd_errors(const Energy& energy, const Eigen::Matrix2d& J)
{
  Eigen::Matrix2d g;
  Eigen::Matrix4d H;
  energy.value_gradient_and_hessian(J, g, H, false);

  const double h = 1e-5 * J.norm();
  Eigen::Vector4d g_fd;
  Eigen::Matrix4d H_fd;
  for(int k = 0; k < 4; ++k)
  {
    Eigen::Matrix2d Jp = J, Jm = J;
    Jp.data()[k] += h;
    Jm.data()[k] -= h;
    g_fd[k] = (energy.value(Jp) - energy.value(Jm)) / (2 * h);
    Eigen::Matrix2d gp, gm;
    energy.value_and_gradient(Jp, gp);
    energy.value_and_gradient(Jm, gm);
    H_fd.col(k) = (vec(gp) - vec(gm)) / (2 * h);
  }
  const double eg = (vec(g) - g_fd).norm() / (std::max)(1., g.norm());
  const double eh = (H - H_fd).norm() / (std::max)(1., H.norm());
  return {eg, eh};
}

template <class Energy>
void check_fd(const Energy& energy)
{
  Random_J rnd(12345);
  std::vector<Eigen::Matrix2d> Js;
  for(int i = 0; i < 200; ++i)
    Js.push_back(rnd(0.4, 2.5));
  // Near-isotropic: s1 - s2 from 0 to 1e-5 relative (limit branch of the flip mode).
  for(double rel : {0., 1e-14, 1e-11, 1e-9, 1e-8, 1e-7, 1e-5})
    for(double s : {0.5, 1., 1.7})
      Js.push_back(make_J(rnd.uniform(-pi, pi), s * (1 + rel), s, rnd.uniform(-pi, pi)));
  Js.push_back(Eigen::Matrix2d::Identity());
  Js.push_back(mat(1, 2, 0.5, 3));
  Js.push_back(mat(1, 1, 0, 1));

  double max_eg = 0, max_eh = 0;
  for(const Eigen::Matrix2d& J : Js)
  {
    const std::pair<double, double> e = fd_errors(energy, J);
    BOOST_CHECK_MESSAGE(e.first < 1e-6, energy.name() << " gradient error " << e.first << " at\n" << J);
    BOOST_CHECK_MESSAGE(e.second < 1e-6, energy.name() << " Hessian error " << e.second << " at\n" << J);
    max_eg = (std::max)(max_eg, e.first);
    max_eh = (std::max)(max_eh, e.second);
  }
  BOOST_TEST_MESSAGE(energy.name() << ": max FD error gradient " << max_eg << ", Hessian " << max_eh
                     << " over " << Js.size() << " Jacobians");
}

template <class Energy>
void check_barrier(const Energy& energy)
{
  for(const Eigen::Matrix2d& J : {mat(1, 0, 0, -1),          // reflection
                                  mat(1, 2, 2, 4),           // rank 1
                                  mat(0, 0, 0, 0),
                                  mat(-2, 0.1, 0.3, 1),      // flipped
                                  mat(std::nan(""), 0, 0, 1)})
  {
    Eigen::Matrix2d g = Eigen::Matrix2d::Constant(7);
    Eigen::Matrix4d H = Eigen::Matrix4d::Constant(7);
    BOOST_CHECK_EQUAL(energy.value(J), inf);
    BOOST_CHECK_EQUAL(energy.value_and_gradient(J, g), inf);
    BOOST_CHECK(g.isZero(0));
    g.setConstant(7);
    BOOST_CHECK_EQUAL(energy.value_gradient_and_hessian(J, g, H), inf);
    BOOST_CHECK(g.isZero(0));
    BOOST_CHECK(H.isZero(0));
  }
  // Tiny positive det: finite.
  BOOST_CHECK(std::isfinite(energy.value(mat(1, 0, 0, 1e-6))));
}

// At rotations (MIPS: similarities) the value is the minimum and the gradient vanishes.
template <class Energy>
void check_minimum(const Energy& energy, double scale)
{
  Random_J rnd(7);
  for(int i = 0; i < 50; ++i)
  {
    const Eigen::Matrix2d J = scale * rotation(rnd.uniform(-pi, pi));
    Eigen::Matrix2d g;
    Eigen::Matrix4d H;
    const double psi = energy.value_gradient_and_hessian(J, g, H);
    BOOST_CHECK_SMALL(psi - Energy::minimum_value(), 1e-14);
    BOOST_CHECK_SMALL(g.norm(), 1e-13);
  }
  for(int i = 0; i < 1000; ++i)
    BOOST_CHECK_GE(energy.value(rnd(0.05, 20)), Energy::minimum_value() - 1e-14);
}

struct Projection_counts { int indefinite = 0, psd = 0; };

// Over strongly distorted J: the projected Hessian is symmetric, PSD, equals
// the unprojected one with its negative eigenvalues clamped (compared with a
// numeric eigensolver), and equals the unprojected one when that is PSD.
template <class Energy>
Projection_counts check_projection(const Energy& energy)
{
  Random_J rnd(2024);
  Projection_counts counts;
  for(int i = 0; i < 20000; ++i)
  {
    const Eigen::Matrix2d J = (i % 2 == 0) ? rnd(0.01, 100.) : rnd(0.3, 3.);
    Eigen::Matrix2d gu, gp;
    Eigen::Matrix4d Hu, Hp;
    const double vu = energy.value_gradient_and_hessian(J, gu, Hu, false);
    const double vp = energy.value_gradient_and_hessian(J, gp, Hp, true);
    BOOST_REQUIRE_EQUAL(vu, vp);
    BOOST_REQUIRE(gu == gp);
    BOOST_REQUIRE(Hp == Hp.transpose());
    BOOST_REQUIRE(Hu == Hu.transpose());

    Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eu(Hu), ep(Hp);
    const double scale = eu.eigenvalues().cwiseAbs().maxCoeff();
    BOOST_REQUIRE_GE(ep.eigenvalues().minCoeff(), -1e-9 * scale);

    const Eigen::Matrix4d Hn = eu.eigenvectors()
                             * eu.eigenvalues().cwiseMax(0.).asDiagonal()
                             * eu.eigenvectors().transpose();
    BOOST_REQUIRE_SMALL((Hp - Hn).norm() / scale, 1e-9);

    if(eu.eigenvalues().minCoeff() < -1e-9 * scale)
      ++counts.indefinite;
    else if(eu.eigenvalues().minCoeff() > 1e-12 * scale)
    {
      ++counts.psd;
      BOOST_REQUIRE(Hp == Hu); // nothing clamped: the same figures
    }
  }
  BOOST_TEST_MESSAGE(energy.name() << ": " << counts.indefinite << " indefinite, "
                     << counts.psd << " positive definite Hessians out of 20000");
  BOOST_CHECK_GT(counts.indefinite, 1000);
  return counts;
}

template <class Energy>
void time_energy(const Energy& energy)
{
  Random_J rnd(99);
  std::vector<Eigen::Matrix2d> Js(1 << 14);
  for(Eigen::Matrix2d& J : Js)
    J = rnd(0.3, 3.);
  const int rounds = 64;
  double sink = 0;
  Eigen::Matrix2d g;
  Eigen::Matrix4d H;

  auto t0 = std::chrono::steady_clock::now();
  for(int r = 0; r < rounds; ++r)
    for(const Eigen::Matrix2d& J : Js)
      sink += energy.value(J);
  auto t1 = std::chrono::steady_clock::now();
  for(int r = 0; r < rounds; ++r)
    for(const Eigen::Matrix2d& J : Js)
      sink += energy.value_and_gradient(J, g) + g(1, 0);
  auto t2 = std::chrono::steady_clock::now();
  for(int r = 0; r < rounds; ++r)
    for(const Eigen::Matrix2d& J : Js)
      sink += energy.value_gradient_and_hessian(J, g, H, true) + g(1, 0) + H(2, 1);
  auto t3 = std::chrono::steady_clock::now();

  const double n = double(rounds) * Js.size();
  auto ns = [n](auto a, auto b) { return std::chrono::duration<double, std::nano>(b - a).count() / n; };
  std::cout << energy.name() << ": ns per call: value " << ns(t0, t1)
            << ", value_and_gradient " << ns(t1, t2)
            << ", value_gradient_and_hessian (projected) " << ns(t2, t3)
            << "  [" << (sink > 0 ? "" : " ") << "]" << std::endl;
}

} // namespace

BOOST_AUTO_TEST_CASE(signed_svd)
{
  Random_J rnd(1);
  std::vector<Eigen::Matrix2d> Js;
  for(int i = 0; i < 1000; ++i)
  {
    Eigen::Matrix2d J = Eigen::Matrix2d::Random();
    Js.push_back(J);
    Js.push_back(rnd(1e-3, 1e3));
  }
  for(const Eigen::Matrix2d& J : {mat(1, 0, 0, 1), mat(2, 0, 0, -2), mat(0, 0, 0, 0), mat(0, -3, 3, 0),
                                  mat(0, 1, 1, 0), mat(1, 2, 2, 4), mat(-1, 0, 0, -1), mat(-1, 0, 0, 1)})
    Js.push_back(J);

  for(const Eigen::Matrix2d& J : Js)
  {
    const SMSO::internal::Signed_svd_2 svd(J);
    const double scale = (std::max)(J.norm(), 1e-300);
    BOOST_CHECK_SMALL((svd.U * Eigen::Vector2d(svd.s1, svd.s2).asDiagonal() * svd.V.transpose() - J).norm() / scale, 1e-14);
    BOOST_CHECK_SMALL(svd.U.determinant() - 1, 1e-14);
    BOOST_CHECK_SMALL(svd.V.determinant() - 1, 1e-14);
    BOOST_CHECK_SMALL((svd.U.transpose() * svd.U - Eigen::Matrix2d::Identity()).norm(), 1e-14);
    BOOST_CHECK_SMALL((svd.V.transpose() * svd.V - Eigen::Matrix2d::Identity()).norm(), 1e-14);
    BOOST_CHECK_GE(svd.s1, std::abs(svd.s2));
    BOOST_CHECK_EQUAL(svd.s2 < 0, J.determinant() < 0);
    // Against Eigen's SVD (unsigned singular values).
    const Eigen::Vector2d sv = Eigen::JacobiSVD<Eigen::Matrix2d>(J).singularValues();
    BOOST_CHECK_SMALL(svd.s1 - sv[0], 1e-14 * scale);
    BOOST_CHECK_SMALL(std::abs(svd.s2) - sv[1], 1e-14 * scale);
  }
  // Smallest singular value to full relative accuracy near det = 0.
  const SMSO::internal::Signed_svd_2 thin(mat(1, 0, 0, 1e-12));
  BOOST_CHECK_CLOSE(thin.s2, 1e-12, 1e-10);
  BOOST_CHECK_EQUAL(SMSO::internal::Signed_svd_2(mat(2, 0, 0, -0.5)).s2, -0.5);
}

BOOST_AUTO_TEST_CASE(symmetric_dirichlet_values)
{
  const SMSO::Symmetric_Dirichlet_energy sd;
  BOOST_CHECK_EQUAL(sd.value(Eigen::Matrix2d::Identity()), 4.);
  BOOST_CHECK_CLOSE(sd.value(rotation(0.7)), 4., 1e-13);
  BOOST_CHECK_EQUAL(sd.value(mat(2, 0, 0, 0.5)), 8.5);          // 4 + 1/4 + 1/4 + 4
  BOOST_CHECK_EQUAL(sd.value(mat(1, 2, 0.5, 3)), 17.8125);      // 14.25 (1 + 1/2^2)
  BOOST_CHECK_EQUAL(sd.value(mat(1, 1, 0, 1)), 6.);             // 3 (1 + 1)
  BOOST_CHECK_CLOSE(sd.value(2 * rotation(-1.1)), 8.5, 1e-13);  // 4 + 4 + 1/4 + 1/4
  BOOST_CHECK_CLOSE(sd.value(make_J(0.3, 3, 0.25, 2.)), 9 + 1. / 16 + 1. / 9 + 16, 1e-13);
  BOOST_CHECK_EQUAL(SMSO::Symmetric_Dirichlet_energy::minimum_value(), 4.);
  BOOST_CHECK_EQUAL(std::string(sd.name()), "symmetric_dirichlet");

  // The returned value is the same figure from all three functions.
  Eigen::Matrix2d g;
  Eigen::Matrix4d H;
  const Eigen::Matrix2d J = mat(1, 2, 0.5, 3);
  BOOST_CHECK_EQUAL(sd.value_and_gradient(J, g), 17.8125);
  BOOST_CHECK_EQUAL(sd.value_gradient_and_hessian(J, g, H), 17.8125);
  // Gradient from the invariant form: 2 J (1 + 1/det^2) - 2 |J|^2 / det^3 cof(J).
  const Eigen::Matrix2d cof = mat(3, -0.5, -2, 1);
  BOOST_CHECK_SMALL((g - (2 * J * 1.25 - 2 * 14.25 / 8 * cof)).norm(), 1e-13);
}

BOOST_AUTO_TEST_CASE(arap_values)
{
  const SMSO::ARAP_energy arap;
  BOOST_CHECK_EQUAL(arap.value(Eigen::Matrix2d::Identity()), 0.);
  BOOST_CHECK_SMALL(arap.value(rotation(0.7)), 1e-14);
  BOOST_CHECK_EQUAL(arap.value(mat(2, 0, 0, 0.5)), 1.25);       // 1 + 1/4
  BOOST_CHECK_CLOSE(arap.value(3 * rotation(2.)), 8., 1e-13);   // 2 * 2^2
  BOOST_CHECK_CLOSE(arap.value(mat(1, 1, 0, 1)), 5 - 2 * std::sqrt(5.), 1e-12); // golden-ratio shear
  // s1^2 + s2^2 = 14.25, s1 s2 = 2, so s1 + s2 = sqrt(18.25).
  BOOST_CHECK_CLOSE(arap.value(mat(1, 2, 0.5, 3)), 16.25 - 2 * std::sqrt(18.25), 1e-13);
  BOOST_CHECK_EQUAL(SMSO::ARAP_energy::minimum_value(), 0.);
  BOOST_CHECK_EQUAL(std::string(arap.name()), "arap");
}

BOOST_AUTO_TEST_CASE(mips_values)
{
  const SMSO::Conformal_energy mips(0.); // pure MIPS
  BOOST_CHECK_EQUAL(mips.value(Eigen::Matrix2d::Identity()), 2.);
  BOOST_CHECK_CLOSE(mips.value(3 * rotation(0.7)), 2., 1e-13);  // scale invariant
  BOOST_CHECK_EQUAL(mips.value(mat(2, 0, 0, 0.5)), 4.25);       // 4 + 1/4
  BOOST_CHECK_EQUAL(mips.value(mat(1, 1, 0, 1)), 3.);
  BOOST_CHECK_EQUAL(mips.value(mat(1, 2, 0.5, 3)), 7.125);      // 14.25 / 2
  const Eigen::Matrix2d J = make_J(0.4, 2.5, 0.7, -1.3);
  BOOST_CHECK_CLOSE(mips.value(5 * J), mips.value(J), 1e-13);
  BOOST_CHECK_CLOSE(mips.value(J), 2.5 / 0.7 + 0.7 / 2.5, 1e-13);
  BOOST_CHECK_EQUAL(SMSO::Conformal_energy::minimum_value(), 2.);
  BOOST_CHECK_EQUAL(std::string(mips.name()), "conformal");
  BOOST_TEST(mips.is_scale_invariant());

  // the default adds 0.01 (det + 1/det - 2): zero at unit area, whatever the angles
  const SMSO::Conformal_energy conformal;
  BOOST_CHECK_EQUAL(conformal.area_weight(), 0.01);
  BOOST_TEST(!conformal.is_scale_invariant());
  BOOST_CHECK_EQUAL(conformal.value(Eigen::Matrix2d::Identity()), 2.);
  BOOST_CHECK_EQUAL(conformal.value(mat(2, 0, 0, 0.5)), 4.25);                        // det 1
  BOOST_CHECK_CLOSE(conformal.value(3 * rotation(0.7)), 2 + 0.01 * (9 + 1. / 9 - 2), 1e-13); // det 9
  BOOST_CHECK_CLOSE(conformal.value(mat(1, 2, 0.5, 3)), 7.125 + 0.01 * 0.5, 1e-13);  // det 2: 2 + 1/2 - 2
  BOOST_CHECK_CLOSE(SMSO::Conformal_energy(2.).value(J), 2.5 / 0.7 + 0.7 / 2.5 + 2 * (1.75 + 1 / 1.75 - 2), 1e-13);
}

BOOST_AUTO_TEST_CASE(barrier)
{
  check_barrier(SMSO::Symmetric_Dirichlet_energy());
  check_barrier(SMSO::ARAP_energy());
  check_barrier(SMSO::Conformal_energy());
  // Symmetric Dirichlet blows up as the triangle degenerates.
  BOOST_CHECK_GT(SMSO::Symmetric_Dirichlet_energy().value(mat(1, 0, 0, 1e-6)), 1e12);
}

BOOST_AUTO_TEST_CASE(minimum_at_rotations)
{
  check_minimum(SMSO::Symmetric_Dirichlet_energy(), 1.);
  check_minimum(SMSO::ARAP_energy(), 1.);
  check_minimum(SMSO::Conformal_energy(), 1.);
  check_minimum(SMSO::Conformal_energy(2.), 1.);
  check_minimum(SMSO::Conformal_energy(0.), 0.3); // every similarity without the area term
  check_minimum(SMSO::Conformal_energy(0.), 4.);
}

// The default bounds allow the same small strains: at singular values
// 1 + e1, 1 + e2, E_SD - 4 ~ 4(e1^2 + e2^2), ARAP ~ e1^2 + e2^2 and the
// conformal energy minus 2 ~ (e1 - e2)^2 + w (e1 + e2)^2, whose means over
// independent strains of equal spread are 1/4 and (1 + w)/4 of E_SD - 4:
// hence 4.1, 0.025 and 2 + 0.025 (1 + w).
BOOST_AUTO_TEST_CASE(default_bounds_allow_the_same_small_strains)
{
  const double e1 = 1e-4, e2 = -3e-4, w = SMSO::Conformal_energy().area_weight();
  const Eigen::Matrix2d J = mat(1 + e1, 0, 0, 1 + e2);
  const double sd = SMSO::Symmetric_Dirichlet_energy().value(J) - 4;
  BOOST_TEST(sd == 4 * (e1 * e1 + e2 * e2), boost::test_tools::tolerance(1e-3));
  BOOST_TEST(SMSO::ARAP_energy().value(J) == e1 * e1 + e2 * e2, boost::test_tools::tolerance(1e-3));
  BOOST_TEST(SMSO::Conformal_energy(0.).value(J) - 2 == (e1 - e2) * (e1 - e2), boost::test_tools::tolerance(1e-3));
  BOOST_TEST(SMSO::Conformal_energy().value(J) - 2 == (e1 - e2) * (e1 - e2) + w * (e1 + e2) * (e1 + e2),
             boost::test_tools::tolerance(1e-3));
  const double sd_excess = SMSO::Symmetric_Dirichlet_energy::default_bound() - 4;
  BOOST_TEST(SMSO::ARAP_energy::default_bound() == sd_excess / 4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(SMSO::Conformal_energy(0.).default_bound() - 2 == sd_excess / 4, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(SMSO::Conformal_energy().default_bound() - 2 == (1 + w) * sd_excess / 4,
             boost::test_tools::tolerance(1e-12));
  BOOST_TEST(SMSO::Symmetric_Dirichlet_energy::default_bound() == 4.1);
  // the E_SD start of a non-barrier energy: the E_SD bound of the same strains
  BOOST_TEST(SMSO::internal::symmetric_dirichlet_bound_with_same_strains(SMSO::ARAP_energy(), 0.025) == 4.1,
             boost::test_tools::tolerance(1e-3));
  BOOST_TEST(SMSO::internal::symmetric_dirichlet_bound_with_same_strains(SMSO::ARAP_energy(), 0.1) == 4.4,
             boost::test_tools::tolerance(1e-3));
  BOOST_TEST(!SMSO::internal::is_barrier_energy(SMSO::ARAP_energy()));
  BOOST_TEST(SMSO::internal::is_barrier_energy(SMSO::Conformal_energy()));
  BOOST_TEST(SMSO::internal::is_barrier_energy(SMSO::Symmetric_Dirichlet_energy()));
}

BOOST_AUTO_TEST_CASE(finite_differences)
{
  check_fd(SMSO::Symmetric_Dirichlet_energy());
  check_fd(SMSO::ARAP_energy());
  check_fd(SMSO::Conformal_energy());
  check_fd(SMSO::Conformal_energy(0.));
  check_fd(SMSO::Conformal_energy(2.)); // the area term's derivatives, weighted up
}

// The generic quotients (for energies without a closed form) agree with the
// closed forms, also across the switch to the limit at s1 = s2.
BOOST_AUTO_TEST_CASE(generic_quotients)
{
  using SMSO::internal::Isotropic_derivatives_2;
  double max_err = 0;
  for(double s : {0.3, 1., 2.})
    for(double rel : {0., 1e-15, 1e-12, 1e-9, 3e-8, 1e-7, 1e-5, 1e-2, 0.5})
    {
      const double s1 = s * (1 + rel), s2 = s;
      for(const Isotropic_derivatives_2& d : {SMSO::Symmetric_Dirichlet_energy::derivatives(s1, s2),
                                              SMSO::ARAP_energy::derivatives(s1, s2),
                                              SMSO::Conformal_energy().derivatives(s1, s2),
                                              SMSO::Conformal_energy(0.).derivatives(s1, s2),
                                              SMSO::Conformal_energy(2.).derivatives(s1, s2)})
      {
        const double scale = (std::max)({1., std::abs(d.d11), std::abs(d.d12)});
        const double ef = std::abs(SMSO::internal::flip_eigenvalue(s1, s2, d) - d.flip) / scale;
        const double et = std::abs(SMSO::internal::twist_eigenvalue(s1, s2, d) - d.twist) / scale;
        BOOST_CHECK_SMALL(ef, 1e-6);
        BOOST_CHECK_SMALL(et, 1e-12);
        max_err = (std::max)({max_err, ef, et});
      }
    }
  BOOST_TEST_MESSAGE("generic twist/flip quotients: max relative error " << max_err);

  // Twist limit d11 + d12 as s2 -> -s1 (det < 0, outside the barrier energies'
  // domain), for psi = s1^2 + s2^2 + (s1 s2)^2 = |J|^2 + det^2, smooth there:
  // (d1 + d2) / (s1 + s2) = 2 + 2 s1 s2.
  for(double rel : {0., 1e-12, 1e-9, 1e-6, 1e-2})
  {
    const double s1 = 1.5, s2 = -1.5 * (1 - rel);
    Isotropic_derivatives_2 d;
    d.d1 = 2 * s1 + 2 * s1 * s2 * s2;
    d.d2 = 2 * s2 + 2 * s1 * s1 * s2;
    d.d11 = 2 + 2 * s2 * s2;
    d.d22 = 2 + 2 * s1 * s1;
    d.d12 = 4 * s1 * s2;
    BOOST_CHECK_CLOSE(SMSO::internal::twist_eigenvalue(s1, s2, d), 2 + 2 * s1 * s2, 1e-6);
  }
}

BOOST_AUTO_TEST_CASE(projection)
{
  const Projection_counts sd = check_projection(SMSO::Symmetric_Dirichlet_energy());
  const Projection_counts arap = check_projection(SMSO::ARAP_energy());
  check_projection(SMSO::Conformal_energy());
  check_projection(SMSO::Conformal_energy(2.));
  // Both branches happen for the energies whose Hessian can be definite.
  BOOST_CHECK_GT(sd.psd, 1000);
  BOOST_CHECK_GT(arap.psd, 1000);

  // Hand-computed: SD at s1 = s2 = 1/2 has twist eigenvalue
  // 2 - 2 (s^2)/(s^6) = 2 - 32 < 0, clamped; flip 2 + 6/s^4 = 98.
  Eigen::Matrix2d g;
  Eigen::Matrix4d Hu, Hp;
  const Eigen::Matrix2d J = 0.5 * Eigen::Matrix2d::Identity();
  SMSO::Symmetric_Dirichlet_energy().value_gradient_and_hessian(J, g, Hu, false);
  SMSO::Symmetric_Dirichlet_energy().value_gradient_and_hessian(J, g, Hp, true);
  Eigen::Vector4d eu = Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(Hu).eigenvalues();
  Eigen::Vector4d ep = Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(Hp).eigenvalues();
  // Scaling modes: d11 = d22 = 2 + 6 * 16 = 98, d12 = 0.
  BOOST_CHECK_CLOSE(eu[0], -30., 1e-12);
  BOOST_CHECK_CLOSE(eu[1], 98., 1e-12);
  BOOST_CHECK_CLOSE(eu[3], 98., 1e-12);
  BOOST_CHECK_SMALL(ep[0], 1e-12);
  BOOST_CHECK_CLOSE(ep[1], 98., 1e-12);
}

BOOST_AUTO_TEST_CASE(timing)
{
  time_energy(SMSO::Symmetric_Dirichlet_energy());
  time_energy(SMSO::ARAP_energy());
  time_energy(SMSO::Conformal_energy());
}
