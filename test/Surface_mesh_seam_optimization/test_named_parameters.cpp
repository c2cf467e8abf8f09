// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Named parameters as a CGAL user writes them: the package's header first,
// chains of the package's and CGAL's parameters in any order, a visitor
// passed by value or by std::ref, the last duplicate winning, and CGAL's
// vertex_point_map on a Polyhedron_3.

// The package's header before any CGAL mesh header: each header includes what it uses.
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#define BOOST_TEST_MODULE named_parameters
#include <boost/test/unit_test.hpp>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <type_traits>
#include <unordered_map>

namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace SMSO_np = CGAL::Surface_mesh_seam_optimization::parameters;

namespace {

const std::string cube = std::string(SMSO_TEST_DATA_DIR) + "/general/cube.obj"; // 12 triangles, closed

// Counts its callbacks in a counter shared by all of its copies: a visitor
// passed by value is copied before it is called.
struct Counting_visitor
{
  std::shared_ptr<std::size_t> calls = std::make_shared<std::size_t>(0);
  bool on_iteration(const SMSO::Seam_optimization_progress&) { ++*calls; return true; }
  bool on_topology_operation(const SMSO::Seam_optimization_progress&) { ++*calls; return true; }
  bool on_lambda_update(const SMSO::Seam_optimization_progress&) { ++*calls; return true; }
};

// Counts in itself: only std::ref(v) lets the caller see the count.
struct Plain_counting_visitor
{
  std::size_t calls = 0;
  bool on_iteration(const SMSO::Seam_optimization_progress&) { ++calls; return true; }
  bool on_topology_operation(const SMSO::Seam_optimization_progress&) { ++calls; return true; }
  bool on_lambda_update(const SMSO::Seam_optimization_progress&) { ++calls; return true; }
};

// ---- Concept archetypes: exactly the members that the concepts of the manual
// (doc/Surface_mesh_seam_optimization/Concepts) require, nothing the package's
// own models add (no internal::Isotropic_energy base, no eigen_solver()), so
// that code relying on an undocumented member fails to compile here.

// DistortionEnergy: psi(J) = |J|_F^2 + det(J)^-2, a barrier whose minimum, 3,
// is reached at rotations; gradient and Hessian by hand, projected by an
// eigendecomposition.
class Distortion_energy_archetype
{
public:
  double value(const Eigen::Matrix2d& J) const
  {
    const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
    if(!(det > 0)) return std::numeric_limits<double>::infinity();
    return J.squaredNorm() + 1 / (det * det);
  }
  double value_and_gradient(const Eigen::Matrix2d& J, Eigen::Matrix2d& dJ) const
  {
    const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
    dJ = 2 * J - 2 / (det * det * det) * d_det(J);
    return value(J);
  }
  double value_gradient_and_hessian(const Eigen::Matrix2d& J, Eigen::Matrix2d& dJ, Eigen::Matrix4d& H,
                                    bool project = true) const
  {
    const double v = value_and_gradient(J, dJ);
    const double det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
    const Eigen::Matrix2d C = d_det(J);
    const Eigen::Vector4d c(C(0, 0), C(1, 0), C(0, 1), C(1, 1)); // vec(d det / dJ), column-major
    Eigen::Matrix4d dc = Eigen::Matrix4d::Zero();                  // d vec(C) / d vec(J)
    dc(0, 3) = dc(3, 0) = 1;
    dc(1, 2) = dc(2, 1) = -1;
    H = 2 * Eigen::Matrix4d::Identity() + 6 / (det * det * det * det) * c * c.transpose() - 2 / (det * det * det) * dc;
    if(project)
    {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(H);
      H = es.eigenvectors() * es.eigenvalues().cwiseMax(0.).asDiagonal() * es.eigenvectors().transpose();
    }
    return v;
  }
  static constexpr double minimum_value() { return 3.0; }
  const char* name() const { return "archetype"; }

private:
  static Eigen::Matrix2d d_det(const Eigen::Matrix2d& J)
  {
    Eigen::Matrix2d C;
    C << J(1, 1), -J(1, 0),
         -J(0, 1), J(0, 0);
    return C;
  }
};

// SparseSolverTraits: Eigen's LDL^T behind the three documented operations;
// copies share the solver and a count of factorizations.
class Sparse_solver_traits_archetype
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;

  Sparse_solver_traits_archetype()
    : m_solver(std::make_shared<Eigen::SimplicialLDLT<Matrix, Eigen::Lower> >()),
      m_factorizations(std::make_shared<std::size_t>(0))
  {}
  bool analyze_pattern(const Matrix& A)
  {
    m_solver->analyzePattern(A);
    return m_solver->info() == Eigen::Success;
  }
  bool factorize(const Matrix& A)
  {
    ++*m_factorizations;
    m_solver->factorize(A);
    return m_solver->info() == Eigen::Success;
  }
  bool solve(const Eigen::VectorXd& b, Eigen::VectorXd& x)
  {
    x = m_solver->solve(b);
    return m_solver->info() == Eigen::Success && x.allFinite();
  }

  std::size_t factorizations() const { return *m_factorizations; } // for the test, not part of the concept

private:
  std::shared_ptr<Eigen::SimplicialLDLT<Matrix, Eigen::Lower> > m_solver;
  std::shared_ptr<std::size_t> m_factorizations;
};

// SeamOptimizationVisitor: the three callbacks, counted.
class Seam_optimization_visitor_archetype
{
public:
  bool on_iteration(const SMSO::Seam_optimization_progress&) { ++iterations; return true; }
  bool on_topology_operation(const SMSO::Seam_optimization_progress&) { ++topology_operations; return true; }
  bool on_lambda_update(const SMSO::Seam_optimization_progress&) { ++lambda_updates; return true; }

  std::size_t iterations = 0, topology_operations = 0, lambda_updates = 0;
};

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef Surface_mesh::Halfedge_index SM_halfedge;

template <typename NP>
SMSO::Optimization_result run_on_cube(const NP& np, double& recomputed)
{
  Surface_mesh sm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(cube, sm));
  auto uv = sm.add_property_map<SM_halfedge, K::Point_2>("h:uv").first;
  const SMSO::Optimization_result r = SMSO::optimize_seams(sm, uv, np);
  recomputed = r.has_result() ? SMSO::distortion(sm, uv) : -1;
  BOOST_TEST_MESSAGE(SMSO::get_error_code_name(r.status) << " " << r.message << ", E_SD " << r.distortion
                     << " (recomputed " << recomputed << "), " << r.iterations << " iterations, "
                     << r.charts << " charts");
  return r;
}

template <typename NP, typename Tag>
double read(const NP& np, Tag tag)
{
  return SMSO_np::choose_parameter(SMSO_np::get_parameter(np, tag), -1.);
}

} // namespace

BOOST_AUTO_TEST_CASE(a_chain_with_a_visitor_passed_by_value)
{
  Counting_visitor visitor;
  const auto np = SMSO_np::distortion_bound(4.1).bijective(true).number_of_recut_rounds(2).visitor(visitor);
  typedef std::decay_t<decltype(np)> NP;
  static_assert(!SMSO_np::is_default_parameter<NP, CGAL::internal_np::visitor_t>::value, "");
  static_assert(SMSO_np::is_default_parameter<NP, CGAL::internal_np::vertex_point_t>::value, "");
  BOOST_TEST(read(np, SMSO::internal_np::distortion_bound) == 4.1);
  BOOST_TEST(read(np, SMSO::internal_np::number_of_recut_rounds) == 2.);

  double recomputed = 0;
  const SMSO::Optimization_result r = run_on_cube(np, recomputed);
  BOOST_TEST_REQUIRE(r.status == SMSO::OK);
  BOOST_TEST(r.bound_met);
  BOOST_TEST(r.distortion <= 4.1 + 1e-9);
  BOOST_TEST(recomputed <= 4.1 + 1e-9);
  BOOST_TEST(recomputed == r.distortion, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(r.bijective);
  BOOST_TEST(*visitor.calls > 0u); // the copy counted in the shared counter
  BOOST_TEST(*visitor.calls >= r.iterations);

  // a temporary, and a chain starting with CGAL's parameter
  Counting_visitor temporary_counter;
  const SMSO::Optimization_result t =
    run_on_cube(SMSO_np::visitor(Counting_visitor(temporary_counter)).distortion_bound(4.1), recomputed);
  BOOST_TEST(t.status == SMSO::OK);
  BOOST_TEST(*temporary_counter.calls > 0u);
}

BOOST_AUTO_TEST_CASE(a_visitor_passed_by_std_ref_is_called_itself)
{
  Plain_counting_visitor by_ref, by_value;
  double recomputed = 0;
  const SMSO::Optimization_result r =
    run_on_cube(SMSO_np::number_of_recut_rounds(0).visitor(std::ref(by_ref)), recomputed);
  BOOST_TEST_REQUIRE(r.status == SMSO::OK);
  BOOST_TEST(by_ref.calls >= r.iterations);
  BOOST_TEST(by_ref.calls > 0u);
  // by value: the copy is called, the caller's object is left alone
  const SMSO::Optimization_result s = run_on_cube(SMSO_np::number_of_recut_rounds(0).visitor(by_value), recomputed);
  BOOST_TEST(s.status == SMSO::OK);
  BOOST_TEST(by_value.calls == 0u);
  BOOST_TEST(s.iterations == r.iterations); // the visitor does not change the run
}

BOOST_AUTO_TEST_CASE(the_last_duplicate_wins)
{
  BOOST_TEST(read(SMSO_np::combine(SMSO_np::distortion_bound(5.0), SMSO_np::distortion_bound(4.2)),
                  SMSO::internal_np::distortion_bound) == 4.2);
  BOOST_TEST(read(SMSO_np::distortion_bound(5.0).distortion_bound(4.2), SMSO::internal_np::distortion_bound) == 4.2);
  // across packs of CGAL's class and the package's, and packs of several links
  const auto np = SMSO_np::combine(CGAL::parameters::number_of_iterations(1).geom_traits(7.),
                                   SMSO_np::seam_weight(0.1).number_of_iterations(2),
                                   SMSO_np::default_values(), SMSO_np::margin(3).seam_weight(0.2));
  BOOST_TEST(read(np, CGAL::internal_np::number_of_iterations) == 2.);
  BOOST_TEST(read(np, SMSO::internal_np::seam_weight) == 0.2);
  BOOST_TEST(read(np, CGAL::internal_np::geom_traits) == 7.);
  BOOST_TEST(read(np, SMSO::internal_np::margin) == 3.);
  BOOST_TEST(read(np, SMSO::internal_np::bijective) == -1.);
  // ... and in what the function reads: the last bound, 4.05, is the one met
  double recomputed = 0;
  const SMSO::Optimization_result r =
    run_on_cube(SMSO_np::combine(SMSO_np::distortion_bound(4.4), SMSO_np::distortion_bound(4.05)), recomputed);
  BOOST_TEST_REQUIRE(r.status == SMSO::OK);
  BOOST_TEST(recomputed <= 4.05 + 1e-9);
}

BOOST_AUTO_TEST_CASE(cgal_vertex_point_map_chains_on_a_Polyhedron_3)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel EPICK;
  typedef CGAL::Polyhedron_3<EPICK> Polyhedron;
  typedef boost::graph_traits<Polyhedron>::vertex_descriptor vertex_descriptor;
  typedef boost::graph_traits<Polyhedron>::halfedge_descriptor halfedge_descriptor;
  typedef boost::graph_traits<Polyhedron>::edge_descriptor edge_descriptor;

  Polyhedron mesh;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(cube, mesh));
  // The points only in the user's map: the mesh's own points all collapse to
  // one, so a run that ignored vertex_point_map would find zero-area faces.
  std::map<vertex_descriptor, EPICK::Point_3> points;
  for(vertex_descriptor v : vertices(mesh))
  {
    points[v] = v->point();
    v->point() = CGAL::ORIGIN;
  }
  boost::associative_property_map<std::map<vertex_descriptor, EPICK::Point_3> > vpm(points);
  std::map<halfedge_descriptor, EPICK::Point_2> uv_storage;
  boost::associative_property_map<std::map<halfedge_descriptor, EPICK::Point_2> > uv(uv_storage);
  std::unordered_map<edge_descriptor, bool> seam_storage;
  for(edge_descriptor e : edges(mesh)) seam_storage[e] = false;
  boost::associative_property_map<std::unordered_map<edge_descriptor, bool> > seams(seam_storage);

  const SMSO::Optimization_result ignored = SMSO::optimize_seams(mesh, uv, SMSO_np::distortion_bound(4.2));
  BOOST_TEST(!ignored.has_result());

  const SMSO::Optimization_result r = SMSO::optimize_seams(
    mesh, uv, SMSO_np::vertex_point_map(vpm).distortion_bound(4.2).edge_is_seam_map(seams).geom_traits(EPICK()));
  BOOST_TEST_MESSAGE("Polyhedron_3: " << SMSO::get_error_code_name(r.status) << " " << r.message << ", E_SD "
                     << r.distortion << ", " << r.charts << " charts");
  BOOST_TEST_REQUIRE(r.status == SMSO::OK);
  const double recomputed = SMSO::distortion(mesh, uv, SMSO_np::vertex_point_map(vpm));
  BOOST_TEST(recomputed <= 4.2 + 1e-9);
  BOOST_TEST(recomputed == r.distortion, boost::test_tools::tolerance(1e-6));
  std::size_t seam_edges = 0;
  for(edge_descriptor e : edges(mesh)) seam_edges += get(seams, e) ? 1 : 0;
  BOOST_TEST(seam_edges > 0u); // a closed cube is cut
}

BOOST_AUTO_TEST_CASE(concept_archetypes)
{
  // One right triangle, legs 1, with UVs stretching it by 2 along u:
  // J = diag(2, 1) in any orthonormal frame, psi = 4 + 1 + 1 / 2^2 = 5.25.
  Surface_mesh tri;
  const Surface_mesh::Vertex_index a = tri.add_vertex(K::Point_3(0, 0, 0)), b = tri.add_vertex(K::Point_3(1, 0, 0)),
                                   c = tri.add_vertex(K::Point_3(0, 1, 0));
  tri.add_face(a, b, c);
  auto uv = tri.add_property_map<SM_halfedge, K::Point_2>("h:uv").first;
  for(SM_halfedge h : halfedges_around_face(halfedge(*faces(tri).begin(), tri), tri))
  {
    const K::Point_3& p = tri.point(target(h, tri));
    put(uv, h, K::Point_2(2 * p.x(), p.y()));
  }
  BOOST_TEST(SMSO::distortion(tri, uv, SMSO_np::energy(Distortion_energy_archetype())) == 5.25,
             boost::test_tools::tolerance(1e-12));

  // minimize_distortion() with the energy and the solver archetypes: the
  // triangle ends up a rotation of itself, psi = 3 and E_SD = 4.
  Sparse_solver_traits_archetype solver;
  const SMSO::Optimization_result m = SMSO::minimize_distortion(
    tri, uv, SMSO_np::energy(Distortion_energy_archetype()).sparse_linear_solver(solver));
  BOOST_TEST_MESSAGE("archetypes, minimize_distortion: " << SMSO::get_error_code_name(m.status) << " " << m.message
                     << ", E_SD " << m.distortion << ", " << m.iterations << " iterations, "
                     << solver.factorizations() << " factorizations");
  BOOST_TEST_REQUIRE(m.status == SMSO::OK);
  BOOST_TEST(solver.factorizations() > 0u);
  BOOST_TEST(SMSO::distortion(tri, uv, SMSO_np::energy(Distortion_energy_archetype())) == 3.,
             boost::test_tools::tolerance(1e-6));
  BOOST_TEST(m.distortion == 4., boost::test_tools::tolerance(1e-6));

  // optimize_seams() with all three on the closed cube. The archetype has no
  // default_bound() (optional in the concept): the bound must then be given.
  Sparse_solver_traits_archetype seam_solver;
  Seam_optimization_visitor_archetype visitor;
  double recomputed = 0;
  const SMSO::Optimization_result no_bound =
    run_on_cube(SMSO_np::energy(Distortion_energy_archetype()).sparse_linear_solver(seam_solver), recomputed);
  BOOST_TEST(no_bound.status == SMSO::ERROR_WRONG_PARAMETER);
  BOOST_TEST(no_bound.message.find("default_bound") != std::string::npos);
  BOOST_TEST(seam_solver.factorizations() == 0u);
  const SMSO::Optimization_result r = run_on_cube(SMSO_np::energy(Distortion_energy_archetype())
                                                    .distortion_bound(3.1)
                                                    .sparse_linear_solver(seam_solver)
                                                    .visitor(std::ref(visitor)),
                                                  recomputed);
  BOOST_TEST_MESSAGE("archetypes, optimize_seams: " << visitor.iterations << " iterations, "
                     << visitor.topology_operations << " topology operations, " << visitor.lambda_updates
                     << " lambda updates, " << seam_solver.factorizations() << " factorizations");
  BOOST_TEST_REQUIRE(r.has_result());
  BOOST_TEST(visitor.iterations > 0u);
  BOOST_TEST(visitor.iterations == r.iterations); // one call per Newton iteration, as the concept says
  BOOST_TEST(seam_solver.factorizations() > 0u);
  BOOST_TEST(r.charts > 0u);
}

BOOST_AUTO_TEST_CASE(number_of_iterations_is_cgal_s_and_the_old_name_still_works)
{
  double recomputed = 0;
  const SMSO::Optimization_result free_run = run_on_cube(SMSO_np::number_of_recut_rounds(0), recomputed);
  BOOST_TEST_REQUIRE(free_run.status == SMSO::OK);
  const std::size_t cap = free_run.iterations / 2;
  BOOST_TEST_REQUIRE(cap > 0u);

  // CGAL's parameter, chained or from CGAL's own namespace, and the deprecated alias: the same cap
  const SMSO::Optimization_result cgal = run_on_cube(SMSO_np::number_of_recut_rounds(0).number_of_iterations(cap),
                                                     recomputed);
  BOOST_TEST(cgal.status == SMSO::WARNING_MAXIMUM_ITERATIONS);
  BOOST_TEST(cgal.iterations <= cap);
  const SMSO::Optimization_result from_cgal =
    run_on_cube(SMSO_np::combine(CGAL::parameters::number_of_iterations(cap), SMSO_np::number_of_recut_rounds(0)),
                recomputed);
  BOOST_TEST(from_cgal.iterations == cgal.iterations);
  const SMSO::Optimization_result old =
    run_on_cube(SMSO_np::number_of_recut_rounds(0).maximum_number_of_iterations(cap), recomputed);
  BOOST_TEST(old.status == SMSO::WARNING_MAXIMUM_ITERATIONS);
  BOOST_TEST(old.iterations == cgal.iterations);
  // both given: CGAL's name wins, whichever comes last
  const SMSO::Optimization_result both = run_on_cube(
    SMSO_np::number_of_iterations(cap).maximum_number_of_iterations(std::size_t(100000)).number_of_recut_rounds(0),
    recomputed);
  BOOST_TEST(both.iterations == cgal.iterations);

  // minimize_distortion() reads it too
  Surface_mesh sm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(cube, sm));
  auto uv = sm.add_property_map<SM_halfedge, K::Point_2>("h:uv").first;
  const SMSO::Optimization_result m = SMSO::minimize_distortion(sm, uv, SMSO_np::number_of_iterations(1));
  BOOST_TEST(m.iterations <= 1u);
  const SMSO::Optimization_result m_old = SMSO::minimize_distortion(sm, uv, SMSO_np::maximum_number_of_iterations(1));
  BOOST_TEST(m_old.iterations == m.iterations);
  BOOST_TEST(m_old.distortion == m.distortion);
}
