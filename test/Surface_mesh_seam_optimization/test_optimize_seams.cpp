// optimize_seams (OptCuts) on small shared meshes: bound met, no flip, one
// chart, seams = UV discontinuities, deterministic, monotone in the bound.
// Assertions on in this test: the core checks its invariants (manifold UV
// mesh, one UV vertex per corner, no flip, open charts) after every topology
// operation.
#undef NDEBUG
#define BOOST_TEST_MODULE optimize_seams
#include <boost/test/unit_test.hpp>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <CGAL/Surface_mesh_seam_optimization/ARAP_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/Conformal_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/Seam_optimizer.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>
#include <CGAL/Surface_mesh_seam_optimization/seam_visibility.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Invariants.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Join_slits.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Scaffold.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Topology_step.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>
#include <set>
#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef Surface_mesh::Halfedge_index halfedge_descriptor;
typedef Surface_mesh::Edge_index edge_descriptor;
typedef Surface_mesh::Property_map<halfedge_descriptor, Point_2> UV_map;
typedef Surface_mesh::Property_map<edge_descriptor, bool> Seam_map;

namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace SMSO_np = CGAL::Surface_mesh_seam_optimization::parameters;

namespace {

struct Run
{
  Surface_mesh sm;
  UV_map uv;
  Seam_map seam;
  SMSO::Optimization_result result;
};

template <typename NP>
void run(const std::string& name, Run& r, const NP& np, const std::string& dir = SMSO_DATA_DIR)
{
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(dir + "/" + name, r.sm));
  r.uv = r.sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  r.seam = r.sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  r.result = SMSO::optimize_seams(r.sm, r.uv, SMSO_np::combine(SMSO_np::edge_is_seam_map(r.seam), np));
  BOOST_TEST_MESSAGE(name << ": status " << SMSO::get_error_message(r.result.status) << ", E_SD "
                     << r.result.distortion << ", E_se " << r.result.seam_length_normalized << ", lambda "
                     << r.result.lambda << ", " << r.result.iterations << " iterations, "
                     << r.result.topology_operations << " operations, " << r.result.seconds << " s");
}

// The written maps are a valid cut: seam map == UV discontinuities, no flip,
// one chart, and the reported figures are those of the written map.
void check_valid(const Run& r)
{
  BOOST_TEST(r.result.has_result());
  const SMSO::Uv_map_measures implied = SMSO::measure_uv_map(r.sm, r.uv);
  const SMSO::Uv_map_measures declared = SMSO::measure_uv_map(r.sm, r.uv, SMSO_np::edge_is_seam_map(r.seam));
  BOOST_TEST(implied.status == SMSO::OK);
  BOOST_TEST(implied.flipped_triangles == 0u);
  BOOST_TEST(implied.charts == 1u);
  // bijective by default: no chart crosses another or itself
  BOOST_TEST(implied.overlapping_triangle_pairs == 0u);
  BOOST_TEST(r.result.overlapping_triangle_pairs == 0u);
  BOOST_TEST(r.result.bijective);
  BOOST_TEST(declared.charts == 1u);
  BOOST_TEST(std::abs(implied.seam_length - declared.seam_length) <= 1e-12 * (1 + declared.seam_length));
  BOOST_TEST(std::abs(implied.distortion - r.result.distortion) <= 1e-9 * r.result.distortion);
  BOOST_TEST(std::abs(implied.seam_length_normalized - r.result.seam_length_normalized) <= 1e-9);
  // every seam edge really separates UV corners
  std::size_t seam_edges = 0;
  for(edge_descriptor e : r.sm.edges())
  {
    if(!r.seam[e]) continue;
    ++seam_edges;
    const halfedge_descriptor h = r.sm.halfedge(e), o = r.sm.opposite(h);
    BOOST_REQUIRE(!r.sm.is_border(h) && !r.sm.is_border(o));
    const bool differ = r.uv[h] != r.uv[r.sm.prev(o)] || r.uv[r.sm.prev(h)] != r.uv[o];
    BOOST_REQUIRE(differ);
  }
  BOOST_TEST(seam_edges > 0u);
}

} // namespace

BOOST_AUTO_TEST_CASE(the_bound_is_met_on_small_meshes)
{
  for(const std::string name : { "cat_f1500.obj", "bishop_part_f1000.obj", "pyramid_f3000.obj", "sphere_f1522.obj" })
  {
    Run r;
    run(name, r, SMSO_np::distortion_bound(4.1));
    BOOST_TEST(r.result.status == SMSO::OK);
    BOOST_TEST(r.result.bound_met);
    BOOST_TEST(r.result.distortion <= 4.1);
    BOOST_TEST(r.result.distortion < r.result.initial_distortion);
    BOOST_TEST(r.result.topology_operations > 0u);
    // each phase was timed (the timings are the kept start's, the seconds
    // those of the call, which waits for both starts)
    const SMSO::Optimization_timings& t = r.result.timings;
    BOOST_TEST(t.assembly > 0); BOOST_TEST(t.factorization > 0); BOOST_TEST(t.symbolic_analysis > 0);
    BOOST_TEST(t.line_search > 0); BOOST_TEST(t.topology > 0); BOOST_TEST(t.scaffold > 0);
    BOOST_TEST(t.total() <= r.result.seconds);
    check_valid(r);
  }
  // with one start, the phases add up to most of the wall time
  Run one;
  run("cat_f1500.obj", one, SMSO_np::number_of_starts(1));
  BOOST_TEST(one.result.timings.total() <= one.result.seconds);
  BOOST_TEST(one.result.timings.total() >= 0.5 * one.result.seconds);
}

// The library's flat cut mesh of a run's result: seams where the UVs disagree.
static void cut_mesh_of(const Run& r, SMSO::internal::Cut_mesh& cm)
{
  SMSO::internal::Face_graph_copy<Surface_mesh> copy;
  std::string msg;
  BOOST_REQUIRE(SMSO::internal::copy_face_graph(r.sm, get(CGAL::vertex_point, r.sm), cm, copy, msg) == SMSO::OK);
  std::vector<double> corner_uvs;
  BOOST_REQUIRE(SMSO::internal::read_uv_map(r.sm, r.uv, copy, corner_uvs, msg) == SMSO::OK);
  std::vector<char> seam;
  SMSO::internal::seams_from_corner_uvs(cm, corner_uvs, seam);
  SMSO::internal::label_uv_vertices(cm, seam);
  SMSO::internal::set_uvs_from_corners(cm, corner_uvs);
}

BOOST_AUTO_TEST_CASE(invariant_check_detects_broken_labellings)
{
  // The check itself must be able to fail: break a valid cut mesh in three ways.
  Run r;
  run("cat_f1500.obj", r, SMSO_np::distortion_bound(4.1));
  SMSO::internal::Cut_mesh cm;
  cut_mesh_of(r, cm);
  BOOST_TEST(SMSO::internal::check_invariants(cm) == "");

  SMSO::internal::Cut_mesh flipped = cm;
  std::swap(flipped.corner_uv[0], flipped.corner_uv[1]); // also moves UV vertices between 3D vertices
  BOOST_TEST(SMSO::internal::check_invariants(flipped) != "");
  // two non-adjacent corners of one fan share a new UV vertex: a pinched vertex
  SMSO::internal::Cut_mesh pinched = cm;
  std::vector<int> fan;
  int c = 0;
  while(SMSO::internal::uv_fan(cm, c, fan), fan.size() < 5) ++c;
  const int u = pinched.corner_uv[fan[0]];
  pinched.uv_vertex.push_back(pinched.uv_vertex[u]);
  pinched.uv.push_back(pinched.uv[2*u]); pinched.uv.push_back(pinched.uv[2*u+1]);
  pinched.corner_uv[fan[0]] = pinched.corner_uv[fan[2]] = int(pinched.uv_vertex.size()) - 1;
  BOOST_TEST(SMSO::internal::check_invariants(pinched).find("not manifold") != std::string::npos);
  SMSO::internal::Cut_mesh moved = cm;
  moved.uv[2 * moved.corner_uv[0]] += 1e3; // drags triangles over each other
  BOOST_TEST(SMSO::internal::check_invariants(moved) != "");
}

// two runs with the same result, to the last bit
void check_same_result(const Run& a, const Run& b)
{
  BOOST_TEST(a.result.seam_length == b.result.seam_length);
  BOOST_TEST(a.result.distortion == b.result.distortion);
  BOOST_TEST(a.result.iterations == b.result.iterations);
}

BOOST_AUTO_TEST_CASE(results_are_deterministic)
{
  Run a, b;
  run("sphere_f1522.obj", a, SMSO_np::distortion_bound(4.1));
  run("sphere_f1522.obj", b, SMSO_np::distortion_bound(4.1));
  check_same_result(a, b);
  bool same = true;
  for(halfedge_descriptor h : a.sm.halfedges())
    if(!a.sm.is_border(h)) same = same && a.uv[h] == b.uv[h];
  BOOST_TEST(same);
}

BOOST_AUTO_TEST_CASE(a_lower_bound_gives_longer_seams)
{
  Run loose, tight;
  run("cat_f1500.obj", loose, SMSO_np::distortion_bound(4.4));
  run("cat_f1500.obj", tight, SMSO_np::distortion_bound(4.05));
  BOOST_TEST(loose.result.distortion <= 4.4);
  BOOST_TEST(tight.result.distortion <= 4.05);
  BOOST_TEST(tight.result.seam_length > loose.result.seam_length);
  check_valid(tight);
}

BOOST_AUTO_TEST_CASE(recut_rounds_keep_the_bound_and_never_lengthen_the_seams)
{
  // Each round starts from the best result so far and only a shorter one
  // that meets the bound replaces it; on the cat the first round finds one
  // (one start: the rounds of a start, not the choice between starts).
  Run once, recut;
  run("cat_f1500.obj", once, SMSO_np::number_of_recut_rounds(0).number_of_starts(1));
  run("cat_f1500.obj", recut, SMSO_np::number_of_recut_rounds(6).number_of_starts(1));
  BOOST_TEST(once.result.status == SMSO::OK);
  BOOST_TEST(recut.result.status == SMSO::OK);
  BOOST_TEST(recut.result.distortion <= 4.1);
  BOOST_TEST(recut.result.iterations > once.result.iterations);
  BOOST_TEST(recut.result.seam_length < once.result.seam_length);
  check_valid(recut);
  // a cap reached during the rounds ends them, not the run: OK, the best so far
  Run capped;
  run("cat_f1500.obj", capped, SMSO_np::number_of_iterations(once.result.iterations + 5).number_of_starts(1));
  BOOST_TEST(capped.result.status == SMSO::OK);
  BOOST_TEST(capped.result.distortion <= 4.1);
  BOOST_TEST(capped.result.seam_length <= once.result.seam_length);
  check_valid(capped);
}

BOOST_AUTO_TEST_CASE(an_explicit_kernel_gives_the_default_run)
{
  Run plain, explicit_np;
  run("bishop_part_f1000.obj", plain, SMSO_np::bijective(false));
  run("bishop_part_f1000.obj", explicit_np, SMSO_np::combine(SMSO_np::bijective(false), CGAL::parameters::geom_traits(K())));
  BOOST_TEST(explicit_np.result.status == SMSO::OK);
  BOOST_TEST(explicit_np.result.seam_length == plain.result.seam_length);
  BOOST_TEST(explicit_np.result.distortion == plain.result.distortion);
}

BOOST_AUTO_TEST_CASE(fixed_lambda_stops_at_a_stationary_point)
{
  Run r;
  run("bishop_part_f1000.obj", r, SMSO_np::seam_weight(0.025));
  BOOST_TEST(r.result.status == SMSO::OK);
  BOOST_TEST(r.result.lambda == 0.025);
  BOOST_TEST(r.result.start == 0u); // one start: no bound to compare results by
  check_valid(r);
  // Restarting from the result with the same lambda: no operation pays and
  // Newton is already converged.
  SMSO::Optimization_result again = SMSO::optimize_seams(
    r.sm, r.uv, SMSO_np::combine(SMSO_np::seam_weight(0.025), SMSO_np::use_uv_map_as_initial(true),
                                 SMSO_np::edge_is_seam_map(r.seam)));
  BOOST_TEST(again.status == SMSO::OK);
  BOOST_TEST(again.topology_operations == 0u);
  BOOST_TEST(again.iterations <= 3u);
  BOOST_TEST(std::abs(again.seam_length - r.result.seam_length) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(bad_parameters_are_refused_and_nothing_is_written)
{
  Surface_mesh sm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/cat_f1500.obj", sm));
  UV_map uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(-1, -1)).first;
  BOOST_TEST(SMSO::optimize_seams(sm, uv, SMSO_np::distortion_bound(3.9)).status == SMSO::ERROR_WRONG_PARAMETER);
  BOOST_TEST(SMSO::optimize_seams(sm, uv, SMSO_np::seam_weight(1.0)).status == SMSO::ERROR_WRONG_PARAMETER);
  BOOST_TEST(SMSO::optimize_seams(sm, uv, SMSO_np::seam_weight(-0.1)).status == SMSO::ERROR_WRONG_PARAMETER);
  BOOST_TEST(SMSO::optimize_seams(sm, uv, SMSO_np::number_of_recut_rounds(-1)).status == SMSO::ERROR_WRONG_PARAMETER);
  BOOST_TEST(SMSO::optimize_seams(sm, uv, SMSO_np::number_of_starts(0)).status == SMSO::ERROR_WRONG_PARAMETER);
  BOOST_TEST(SMSO::optimize_seams(sm, uv, SMSO_np::number_of_starts(5)).status == SMSO::ERROR_WRONG_PARAMETER);
  bool untouched = true;
  for(halfedge_descriptor h : sm.halfedges()) untouched = untouched && uv[h] == Point_2(-1, -1);
  BOOST_TEST(untouched);
}

BOOST_AUTO_TEST_CASE(the_visitor_sees_progress_and_can_cancel)
{
  struct Counting_visitor
  {
    std::size_t iterations = 0, operations = 0, updates = 0;
    bool on_iteration(const SMSO::Seam_optimization_progress& p) { ++iterations; return p.topology_operations < 5; }
    bool on_topology_operation(const SMSO::Seam_optimization_progress&) { ++operations; return true; }
    bool on_lambda_update(const SMSO::Seam_optimization_progress&) { ++updates; return true; }
  } visitor;
  Run r;
  run("cat_f1500.obj", r, CGAL::parameters::visitor(std::ref(visitor)));
  BOOST_TEST(r.result.status == SMSO::WARNING_CANCELLED);
  BOOST_TEST(visitor.iterations > 0u);
  BOOST_TEST(visitor.updates > 0u);
  BOOST_TEST(visitor.operations >= 5u);
  BOOST_TEST(r.result.iterations == visitor.iterations);
  BOOST_TEST(SMSO::number_of_flipped_triangles(r.sm, r.uv) == 0u);

  // cancelling from the lambda update is a cancel too
  struct Lambda_visitor : SMSO::Default_seam_optimization_visitor
  {
    bool on_lambda_update(const SMSO::Seam_optimization_progress&) { return false; }
  } stop_at_lambda;
  Run s;
  run("cat_f1500.obj", s, CGAL::parameters::visitor(std::ref(stop_at_lambda)));
  BOOST_TEST(s.result.status == SMSO::WARNING_CANCELLED);
  BOOST_TEST(s.result.has_result());
}

// time_limit: a distinct status, the best result so far written and valid
// (bunny_i_f10000 needs several seconds in bound mode: 15 s with two starts,
// 2026-12-01; the cat_f1500 it ran on before now takes 0.3 s).
BOOST_AUTO_TEST_CASE(the_time_limit_stops_with_the_best_result_so_far)
{
  Run r;
  run("bunny_i_f10000.obj", r, SMSO_np::time_limit(0.3));
  BOOST_TEST(r.result.status == SMSO::WARNING_TIME_LIMIT);
  BOOST_TEST(r.result.has_result());
  BOOST_TEST(r.result.seconds < 3.);
  const SMSO::Uv_map_measures m = SMSO::measure_uv_map(r.sm, r.uv);
  BOOST_TEST(m.flipped_triangles == 0u);
  BOOST_TEST(m.overlapping_triangle_pairs == 0u);
  BOOST_TEST(std::abs(m.distortion - r.result.distortion) <= 1e-9 * r.result.distortion);
  BOOST_TEST(r.result.bound_met == (r.result.distortion <= 4.1));

  Surface_mesh sm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/bunny_i_f10000.obj", sm));
  UV_map uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  SMSO::Seam_optimizer<Surface_mesh> optimizer(sm, uv, SMSO_np::time_limit(0.3));
  std::size_t steps = 0;
  while(optimizer.step()) ++steps;
  const SMSO::Optimization_result o = optimizer.result();
  BOOST_TEST_MESSAGE("Seam_optimizer, 0.3 s: " << steps << " steps, " << SMSO::get_error_code_name(o.status));
  BOOST_TEST(o.status == SMSO::WARNING_TIME_LIMIT);
  optimizer.write_uv_map(uv);
  BOOST_TEST(SMSO::number_of_flipped_triangles(sm, uv) == 0u);
  BOOST_TEST(o.bound_met == (o.distortion <= 4.1));

  Run bad;
  run("cat_f1500.obj", bad, SMSO_np::time_limit(-1.));
  BOOST_TEST(bad.result.status == SMSO::ERROR_WRONG_PARAMETER);
}

BOOST_AUTO_TEST_CASE(stepping_the_class_gives_the_free_function_result)
{
  // (the class runs one start, OptCuts' dual step)
  Run reference;
  run("bishop_part_f1000.obj", reference, SMSO_np::distortion_bound(4.1).number_of_starts(1));

  Surface_mesh sm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/bishop_part_f1000.obj", sm));
  UV_map uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(-1, -1)).first;
  Seam_map seam = sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  SMSO::Seam_optimizer<Surface_mesh> optimizer(sm, uv, SMSO_np::distortion_bound(4.1));
  BOOST_REQUIRE(optimizer.status() == SMSO::OK);
  BOOST_TEST(uv[*sm.halfedges().begin()] == Point_2(-1, -1)); // nothing written yet
  std::size_t steps = 0;
  double previous_se = optimizer.seam_length_normalized();
  bool seams_grew = false;
  while(optimizer.step())
  {
    ++steps;
    seams_grew = seams_grew || optimizer.seam_length_normalized() > previous_se;
    previous_se = optimizer.seam_length_normalized();
    if(steps == 3)
    {
      // a snapshot mid-way is a valid cut too
      Run mid;
      mid.sm = sm;
      mid.uv = mid.sm.property_map<halfedge_descriptor, Point_2>("h:uv").first;
      mid.seam = mid.sm.property_map<edge_descriptor, bool>("e:seam").first;
      optimizer.write_uv_map(mid.uv);
      optimizer.write_seam_map(mid.seam);
      mid.result = optimizer.result();
      check_valid(mid);
    }
  }
  BOOST_TEST(steps > 3u);
  BOOST_TEST(seams_grew);
  const SMSO::Optimization_result r = optimizer.result();
  BOOST_TEST(r.status == SMSO::OK);
  BOOST_TEST(r.distortion == reference.result.distortion);
  BOOST_TEST(r.seam_length == reference.result.seam_length);
  BOOST_TEST(r.topology_operations == reference.result.topology_operations);
  optimizer.write_uv_map(uv);
  optimizer.write_seam_map(seam);
  bool same = true;
  for(halfedge_descriptor h : sm.halfedges())
    if(!sm.is_border(h)) same = same && uv[h] == reference.uv[h];
  BOOST_TEST(same);
  BOOST_TEST(!optimizer.step());

  Surface_mesh bad;
  UV_map buv = bad.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  SMSO::Seam_optimizer<Surface_mesh> refused(bad, buv);
  BOOST_TEST(refused.status() == SMSO::ERROR_EMPTY_MESH);
  BOOST_TEST(!refused.step());
}

BOOST_AUTO_TEST_CASE(the_scaffold_prevents_overlaps)
{
  // The octopus' flattening folds its tentacles over each other unless the
  // space around the chart is meshed (146 overlapping pairs at the fixed
  // lambda 0.7, which keeps the runs short).
  const std::string dir = SMSO_TEST_DATA_DIR, name = "octopus_mainComp_f6000.obj";
  Run free_run, bijective_run;
  run(name, free_run, SMSO_np::combine(SMSO_np::seam_weight(0.7), SMSO_np::bijective(false)), dir);
  BOOST_TEST(free_run.result.status == SMSO::OK);
  BOOST_TEST(free_run.result.overlapping_triangle_pairs > 0u);
  BOOST_TEST(!free_run.result.bijective);
  BOOST_TEST(SMSO::number_of_overlapping_triangle_pairs(free_run.sm, free_run.uv) ==
             free_run.result.overlapping_triangle_pairs);
  BOOST_TEST(!SMSO::is_bijective(free_run.sm, free_run.uv));
  BOOST_TEST(SMSO::number_of_flipped_triangles(free_run.sm, free_run.uv) == 0u);

  run(name, bijective_run, SMSO_np::seam_weight(0.7), dir);
  BOOST_TEST(bijective_run.result.status == SMSO::OK);
  BOOST_TEST(bijective_run.result.scaffold_rebuilds > 0u);
  BOOST_TEST(SMSO::is_bijective(bijective_run.sm, bijective_run.uv));
  check_valid(bijective_run);

  // An overlapping map given as the initial one is refused in bijective
  // mode, and left as it was; without bijectivity it is a fine start.
  std::vector<Point_2> before;
  for(halfedge_descriptor h : free_run.sm.halfedges()) before.push_back(free_run.uv[h]);
  const SMSO::Optimization_result refused = SMSO::optimize_seams(
    free_run.sm, free_run.uv, SMSO_np::combine(SMSO_np::use_uv_map_as_initial(true),
                                               SMSO_np::edge_is_seam_map(free_run.seam)));
  BOOST_TEST(refused.status == SMSO::ERROR_OVERLAPPING_UV_MAP);
  BOOST_TEST(refused.message.find("bijective(false)") != std::string::npos);
  BOOST_TEST(!refused.has_result());
  std::size_t i = 0;
  bool untouched = true;
  for(halfedge_descriptor h : free_run.sm.halfedges()) untouched = untouched && free_run.uv[h] == before[i++];
  BOOST_TEST(untouched);
  const SMSO::Optimization_result accepted = SMSO::optimize_seams(
    free_run.sm, free_run.uv, SMSO_np::combine(SMSO_np::use_uv_map_as_initial(true), SMSO_np::bijective(false),
                                               SMSO_np::edge_is_seam_map(free_run.seam), SMSO_np::seam_weight(0.7)));
  BOOST_TEST(accepted.status == SMSO::OK);
}

BOOST_AUTO_TEST_CASE(the_scaffold_waits_until_charts_overlap)
{
  // The cat's stationary points never overlap: the bijective run is the free
  // run, and never meshes a scaffold (one start: the default second start
  // differs with and without the scaffold).
  Run free_run, bijective_run;
  run("cat_f1500.obj", free_run, SMSO_np::bijective(false).number_of_starts(1));
  run("cat_f1500.obj", bijective_run, SMSO_np::bijective(true).number_of_starts(1));
  BOOST_TEST(free_run.result.overlapping_triangle_pairs == 0u);
  BOOST_TEST(bijective_run.result.scaffold_rebuilds == 0u);
  check_same_result(bijective_run, free_run);
  check_valid(bijective_run);
}

BOOST_AUTO_TEST_CASE(a_disk_starts_over_with_its_scaffold_at_the_first_overlap)
{
  // planck_s1 is a disk whose free run overlaps: the bijective run goes back
  // to the initial map (no seam) once, and on with the scaffold from there
  // (one start: the result of another start would be kept).
  const auto one = SMSO_np::number_of_starts(1);
  struct Seam_visitor : SMSO::Default_seam_optimization_visitor
  {
    std::size_t restarts = 0;
    double last = 0;
    bool on_iteration(const SMSO::Seam_optimization_progress& p)
    {
      if(last > 0 && p.seam_length_normalized == 0) ++restarts;
      last = p.seam_length_normalized;
      return true;
    }
  } free_visitor, bijective_visitor;
  Run free_run, bijective_run;
  run("planck_s1.obj", free_run,
      SMSO_np::combine(one, SMSO_np::bijective(false), CGAL::parameters::visitor(std::ref(free_visitor))),
      SMSO_TEST_DATA_DIR);
  run("planck_s1.obj", bijective_run, SMSO_np::combine(one, CGAL::parameters::visitor(std::ref(bijective_visitor))),
      SMSO_TEST_DATA_DIR);
  BOOST_TEST(free_run.result.overlapping_triangle_pairs > 0u);
  BOOST_TEST(free_visitor.restarts == 0u);
  BOOST_TEST(bijective_visitor.restarts == 1u);
  BOOST_TEST(bijective_run.result.scaffold_rebuilds > 0u);
  BOOST_TEST(bijective_run.result.distortion <= 4.1);
  check_valid(bijective_run);
}

BOOST_AUTO_TEST_CASE(is_bijective_on_hand_made_maps)
{
  // Two triangles sharing an edge; the second folded back over the first
  // overlaps it without flipping if its UVs are given separately.
  Surface_mesh sm;
  const auto v0 = sm.add_vertex(K::Point_3(0, 0, 0)), v1 = sm.add_vertex(K::Point_3(1, 0, 0)),
             v2 = sm.add_vertex(K::Point_3(0, 1, 0)), v3 = sm.add_vertex(K::Point_3(1, 1, 0));
  sm.add_face(v0, v1, v2);
  sm.add_face(v1, v3, v2);
  UV_map uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  for(halfedge_descriptor h : sm.halfedges())
    if(!sm.is_border(h)) { const K::Point_3& p = sm.point(sm.target(h)); uv[h] = Point_2(p.x(), p.y()); }
  BOOST_TEST(SMSO::is_bijective(sm, uv));
  BOOST_TEST(SMSO::number_of_overlapping_triangle_pairs(sm, uv) == 0u);
  // cut the shared edge in UV: move the second triangle onto the first
  for(halfedge_descriptor h : CGAL::halfedges_around_face(sm.halfedge(Surface_mesh::Face_index(1)), sm))
    uv[h] = Point_2(uv[h].x() - 0.5, uv[h].y() - 0.5);
  BOOST_TEST(SMSO::number_of_flipped_triangles(sm, uv) == 0u);
  BOOST_TEST(SMSO::number_of_overlapping_triangle_pairs(sm, uv) == 1u);
  BOOST_TEST(!SMSO::is_bijective(sm, uv));
  // apart: bijective again
  for(halfedge_descriptor h : CGAL::halfedges_around_face(sm.halfedge(Surface_mesh::Face_index(1)), sm))
    uv[h] = Point_2(uv[h].x() + 3, uv[h].y());
  BOOST_TEST(SMSO::is_bijective(sm, uv));
}

BOOST_AUTO_TEST_CASE(the_scaffold_fills_the_box_around_the_charts)
{
  // Charts and scaffold tile the box: every scaffold triangle is ccw, and
  // the areas add up to the box's.
  Run r;
  run("cat_f1500.obj", r, SMSO_np::distortion_bound(4.1));
  SMSO::internal::Cut_mesh cm;
  cut_mesh_of(r, cm);
  SMSO::internal::Scaffold scaffold;
  BOOST_REQUIRE(scaffold.build(cm));
  BOOST_TEST(scaffold.number_of_triangles() > 0u);
  double scaffold_area = 0, chart_area = 0;
  double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
  std::size_t clockwise = 0;
  for(std::size_t t = 0; t < scaffold.number_of_triangles(); ++t)
  {
    const double* p[3];
    for(int k = 0; k < 3; ++k) p[k] = scaffold.position(cm, scaffold.tri[3*t + k]);
    const double a2 = (p[1][0]-p[0][0]) * (p[2][1]-p[0][1]) - (p[2][0]-p[0][0]) * (p[1][1]-p[0][1]);
    if(!(a2 > 0)) ++clockwise;
    scaffold_area += 0.5 * a2;
    for(int k = 0; k < 3; ++k)
    {
      x0 = (std::min)(x0, p[k][0]); x1 = (std::max)(x1, p[k][0]);
      y0 = (std::min)(y0, p[k][1]); y1 = (std::max)(y1, p[k][1]);
    }
  }
  for(std::size_t f = 0; f < cm.number_of_faces(); ++f) chart_area += 0.5 * cm.signed_uv_area2(f);
  BOOST_TEST(clockwise == 0u);
  BOOST_TEST(std::abs(scaffold_area + chart_area - (x1 - x0) * (y1 - y0)) <= 1e-9 * (x1 - x0) * (y1 - y0));
  // the scaffold vertex incidence lists every triangle at each chart vertex
  std::size_t incidences = 0;
  for(int id : scaffold.tri) if(id < scaffold.n_uv) ++incidences;
  BOOST_TEST(scaffold.vertex_triangles.size() == incidences);

  // a map whose charts overlap has no scaffold
  cm.uv[2 * cm.corner_uv[0]] += 1e3;
  BOOST_TEST(!scaffold.build(cm));
  BOOST_TEST(scaffold.empty());
}

BOOST_AUTO_TEST_CASE(moving_an_ear_across_a_seam_shortens_it_by_the_stencils_figures)
{
  // Every seam ear of a few results: the shift keeps the cut valid, shortens
  // the seams by exactly the two ear edges minus the third, and changes E_SD
  // by exactly what its stencil solve predicted (the stencil holds every
  // face whose corners move).
  std::size_t ears = 0;
  for(const std::string name : { "cat_f1500.obj", "sphere_f1522.obj" })
  {
    Run r;
    run(name, r, SMSO_np::combine(SMSO_np::seam_weight(0.025), SMSO_np::bijective(false)));
    SMSO::internal::Cut_mesh cm;
    cut_mesh_of(r, cm);
    const std::vector<double> no_weight(cm.corner_vertex.size(), 1.);
    const SMSO::Symmetric_Dirichlet_energy sd;
    SMSO::internal::Topology_step<SMSO::Symmetric_Dirichlet_energy> step(cm, sd, no_weight);
    std::vector<SMSO::internal::Operation> shifts;
    step.shifts(shifts);
    BOOST_TEST_MESSAGE(name << ": " << shifts.size() << " seam ears");
    ears += shifts.size();
    for(const SMSO::internal::Operation& op : shifts)
    {
      SMSO::internal::Cut_mesh shifted = cm;
      SMSO::internal::Topology_step<SMSO::Symmetric_Dirichlet_energy>::apply(shifted, step.vertex_corners(), op);
      BOOST_TEST(SMSO::internal::check_invariants(shifted) == "");
      BOOST_TEST(shifted.number_of_uv_vertices() == cm.number_of_uv_vertices() - 1);
      const int c0 = op.corners[0], c1 = op.corners[1], c2 = op.corners[2];
      // the halfedges ending at the ear's corners: v2->v0 (new seam), v0->v1 and v1->v2 (closed)
      const double expected = cm.edge_length(c0) - cm.edge_length(c1) - cm.edge_length(c2);
      BOOST_TEST(expected < 0);
      BOOST_TEST(std::abs(shifted.seam_length() - cm.seam_length() - expected) <= 1e-12 * cm.seam_length());
      BOOST_TEST(std::abs(op.d_se * cm.normalization_radius() - expected) <= 1e-12 * cm.seam_length());
      BOOST_TEST(!shifted.is_seam(c1));
      BOOST_TEST(!shifted.is_seam(c2));
      BOOST_TEST(shifted.is_seam(c0));
      const double d_sd = SMSO::internal::total_energy(shifted, sd, shifted.uv.data()) -
                          SMSO::internal::total_energy(cm, sd, cm.uv.data());
      BOOST_TEST(std::abs(d_sd - op.d_sd) <= 1e-9);
    }
  }
  BOOST_TEST(ears > 0u);
}

namespace {

// A test mesh set up for the core loop as optimize_seams() does (default parameters).
struct Core_setup
{
  Surface_mesh sm;
  SMSO::internal::Cut_mesh cm;
  SMSO::internal::Face_graph_copy<Surface_mesh> copy;
  std::vector<double> weight;
  SMSO::internal::Alternating_settings settings;

  explicit Core_setup(const std::string& file)
  {
    BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_TEST_DATA_DIR) + "/" + file, sm));
    UV_map uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
    std::string message;
    BOOST_REQUIRE(SMSO::internal::setup_seam_optimization(sm, uv, SMSO::parameters::default_values(),
                                                          SMSO::Symmetric_Dirichlet_energy(), cm, copy, weight,
                                                          settings, message) == SMSO::OK);
  }
};

} // namespace

BOOST_AUTO_TEST_CASE(straightening_detours_shortens_the_seams_within_the_bound)
{
  // planck_s1 (775 faces, OptCuts data): its seams grown edge by edge wind;
  // the rounds that replace a detour by its shortcut find shorter ones.
  typedef SMSO::Symmetric_Dirichlet_energy Energy;
  auto solve = [](double detour_ratio, double& e_sd, double& e_se, std::size_t& overlaps, std::string& invariants) {
    Core_setup setup("planck_s1.obj");
    SMSO::internal::Cut_mesh& cm = setup.cm;
    const std::vector<double>& weight = setup.weight;
    SMSO::internal::Alternating_settings settings = setup.settings;
    settings.detour_ratio = detour_ratio;
    SMSO::Default_seam_optimization_visitor visitor;
    SMSO::internal::Alternating_optimization<Energy, SMSO::Eigen_simplicial_ldlt_traits,
                                             SMSO::Default_seam_optimization_visitor>
      optimizer(cm, Energy(), SMSO::Eigen_simplicial_ldlt_traits(), weight, settings, visitor);
    BOOST_TEST(optimizer.run() == SMSO::OK);
    e_sd = optimizer.distortion();
    e_se = optimizer.seam_cost();
    overlaps = SMSO::internal::count_overlapping_pairs(cm);
    invariants = SMSO::internal::check_invariants(cm);
  };
  double sd_off, se_off, sd_on, se_on;
  std::size_t ov_off, ov_on;
  std::string inv_off, inv_on;
  solve(std::numeric_limits<double>::infinity(), sd_off, se_off, ov_off, inv_off); // no path is a detour
  solve(1.1, sd_on, se_on, ov_on, inv_on);
  BOOST_TEST_MESSAGE("planck_s1: E_se " << se_off << " without straightening, " << se_on << " with");
  BOOST_TEST(sd_off <= 4.1);
  BOOST_TEST(sd_on <= 4.1);
  BOOST_TEST(ov_on == 0u);
  BOOST_TEST(inv_on.empty());
  BOOST_TEST(se_on < 0.97 * se_off);
}

BOOST_AUTO_TEST_CASE(the_progress_reports_the_seams_as_they_are)
{
  // progress() computes the seam length once per labelling (it keys it on the
  // Newton pattern, and a topology operation drops it): whatever the path
  // (planck_s1 bijective: a restart at the first overlap, the scaffold, the
  // straightening's deferred batches, the polish's undone tries), every
  // figure a visitor gets must be that of the seams at that moment.
  typedef SMSO::Symmetric_Dirichlet_energy Energy;
  Core_setup setup("planck_s1.obj");
  SMSO::internal::Cut_mesh& cm = setup.cm;
  BOOST_REQUIRE(setup.settings.bijective);
  struct Checking_visitor
  {
    const SMSO::internal::Cut_mesh* cm;
    std::size_t calls = 0, operations = 0, wrong = 0;
    double worst = 0;
    bool check(const SMSO::Seam_optimization_progress& p)
    {
      ++calls;
      const double now = cm->seam_length() / cm->normalization_radius();
      if(p.seam_length_normalized != now) { ++wrong; worst = (std::max)(worst, std::abs(p.seam_length_normalized - now)); }
      return true;
    }
    bool on_iteration(const SMSO::Seam_optimization_progress& p) { return check(p); }
    bool on_topology_operation(const SMSO::Seam_optimization_progress& p) { ++operations; return check(p); }
    bool on_lambda_update(const SMSO::Seam_optimization_progress& p) { return check(p); }
  } visitor{&cm};
  SMSO::internal::Alternating_optimization<Energy, SMSO::Eigen_simplicial_ldlt_traits, Checking_visitor>
    optimizer(cm, Energy(), SMSO::Eigen_simplicial_ldlt_traits(), setup.weight, setup.settings, visitor);
  BOOST_TEST(optimizer.run() == SMSO::OK);
  BOOST_TEST_MESSAGE("planck_s1: " << visitor.calls << " progress reports, " << visitor.operations
                     << " topology operations, " << optimizer.scaffold_rebuilds() << " scaffold meshings");
  BOOST_TEST(visitor.operations > 50u);
  BOOST_TEST(optimizer.scaffold_rebuilds() > 0u);
  BOOST_TEST(visitor.wrong == 0u, visitor.wrong << " reports off by up to " << visitor.worst);
}

namespace {

// The alternation with its descent open to the test.
template <typename Energy, typename SolverTraits, typename Visitor>
struct Open_alternation : SMSO::internal::Alternation<Energy, SolverTraits, Visitor>
{
  typedef SMSO::internal::Alternation<Energy, SolverTraits, Visitor> Base;
  using Base::Base;
  template <typename Enough>
  SMSO::Error_code descend_from_start(const Enough& enough)
  {
    if(!this->m_newton.rebuild_pattern()) return SMSO::ERROR_LINEAR_SOLVER;
    return this->descend(enough);
  }
  SMSO::Error_code descend_on() { return this->descend(); }
};

} // namespace

BOOST_AUTO_TEST_CASE(a_descent_ended_early_resumes_to_the_same_stationary_point)
{
  // The zip of a straightening round descends only until its next merge can
  // be placed: descend(enough) must stop right after the iteration that
  // satisfies it, and going on from there must be the full descent.
  typedef SMSO::Symmetric_Dirichlet_energy Energy;
  typedef Open_alternation<Energy, SMSO::Eigen_simplicial_ldlt_traits, SMSO::Default_seam_optimization_visitor> Open;
  Core_setup setup("planck_s1.obj");
  const std::vector<double>& weight = setup.weight;
  SMSO::internal::Alternating_settings settings = setup.settings;
  settings.bijective = false;
  SMSO::Default_seam_optimization_visitor visitor;
  SMSO::internal::Cut_mesh full_cm = setup.cm, early_cm = setup.cm;
  Open full(full_cm, Energy(), SMSO::Eigen_simplicial_ldlt_traits(), weight, settings, visitor);
  Open early(early_cm, Energy(), SMSO::Eigen_simplicial_ldlt_traits(), weight, settings, visitor);
  const double e0 = full.distortion();

  BOOST_TEST(full.descend_from_start([] { return false; }) == SMSO::OK);
  BOOST_TEST_MESSAGE("planck_s1 initial map: E_SD " << e0 << ", stationary " << full.distortion() << " after "
                     << full.iterations() << " Newton iterations");
  BOOST_REQUIRE(full.iterations() > 3u);

  int calls = 0;
  BOOST_TEST(early.descend_from_start([&calls] { return ++calls == 3; }) == SMSO::OK);
  BOOST_TEST(calls == 3);
  BOOST_TEST(early.iterations() == 3u);
  const double e3 = early.distortion();
  BOOST_TEST(e3 < e0);
  BOOST_TEST(e3 > full.distortion());
  BOOST_TEST(early.descend_on() == SMSO::OK);
  BOOST_TEST(early.iterations() == full.iterations());
  BOOST_TEST(early.distortion() == full.distortion());
  BOOST_TEST((early_cm.uv == full_cm.uv));
}

// ---------------------------------------------------------------------------
// Regional seam preferences (seam_cost_map, vertex_seam_cost_map)

namespace {

typedef Surface_mesh::Vertex_index vertex_descriptor;

std::set<vertex_descriptor> seam_vertices(const Run& r)
{
  std::set<vertex_descriptor> s;
  for(edge_descriptor e : r.sm.edges())
    if(r.seam[e])
    {
      s.insert(r.sm.vertex(e, 0));
      s.insert(r.sm.vertex(e, 1));
    }
  return s;
}

// 3D length of the seams with both ends in `region`
double seam_length_inside(const Run& r, const std::set<vertex_descriptor>& region)
{
  double l = 0;
  for(edge_descriptor e : r.sm.edges())
    if(r.seam[e] && region.count(r.sm.vertex(e, 0)) && region.count(r.sm.vertex(e, 1)))
      l += std::sqrt(CGAL::squared_distance(r.sm.point(r.sm.vertex(e, 0)), r.sm.point(r.sm.vertex(e, 1))));
  return l;
}

double surface_area(const Surface_mesh& sm)
{
  double a = 0;
  for(auto f : sm.faces())
  {
    const halfedge_descriptor h = sm.halfedge(f);
    a += std::sqrt(K::Triangle_3(sm.point(sm.source(h)), sm.point(sm.target(h)),
                                 sm.point(sm.target(sm.next(h)))).squared_area());
  }
  return a;
}

} // namespace

BOOST_AUTO_TEST_CASE(region_seam_costs_average_over_the_one_ring)
{
  // a fan of six triangles: centre c, rim r0..r5
  Surface_mesh sm;
  const vertex_descriptor c = sm.add_vertex(K::Point_3(0, 0, 0));
  std::vector<vertex_descriptor> rim;
  for(int i = 0; i < 6; ++i)
    rim.push_back(sm.add_vertex(K::Point_3(std::cos(i * CGAL_PI / 3), std::sin(i * CGAL_PI / 3), 0)));
  for(int i = 0; i < 6; ++i) sm.add_face(c, rim[i], rim[(i + 1) % 6]);
  auto cost = sm.add_property_map<vertex_descriptor, double>("v:cost", 0.).first;
  SMSO::region_seam_costs(sm, std::vector<vertex_descriptor>{c}, 100., cost);
  BOOST_TEST(cost[c] == 106. / 7, boost::test_tools::tolerance(1e-15));       // itself and six rim vertices of 1
  for(vertex_descriptor r : rim)
    BOOST_TEST(cost[r] == 103. / 4, boost::test_tools::tolerance(1e-15));     // itself, c and two rim neighbours
  SMSO::region_seam_costs(sm, rim, 0., cost);
  BOOST_TEST(cost[c] == 1. / 7, boost::test_tools::tolerance(1e-15));
  for(vertex_descriptor r : rim)
    BOOST_TEST(cost[r] == 1. / 4, boost::test_tools::tolerance(1e-15));
}

// A region over the plain run's seams pushes them out (region seam length at
// most half the plain run's); a cheap region along a route the plain run did
// not take draws seams in. Both meet the bound, and the reported weighted
// seam term is the costs times the lengths.
BOOST_AUTO_TEST_CASE(seam_costs_repel_and_attract_seams)
{
  Run plain;
  run("cat_f1500.obj", plain, SMSO_np::distortion_bound(4.1));
  BOOST_REQUIRE(plain.result.status == SMSO::OK);
  BOOST_TEST(plain.result.weighted_seam_length_normalized == plain.result.seam_length_normalized);
  const std::set<vertex_descriptor> route_a = seam_vertices(plain);
  const double plain_in_a = seam_length_inside(plain, route_a);
  BOOST_REQUIRE(plain_in_a > 0);

  auto run_with_region = [](Run& r, const std::set<vertex_descriptor>& region, double region_cost) {
    BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/cat_f1500.obj", r.sm));
    auto cost = r.sm.add_property_map<vertex_descriptor, double>("v:seam_cost", 1.).first;
    std::vector<vertex_descriptor> vs(region.begin(), region.end());
    SMSO::region_seam_costs(r.sm, vs, region_cost, cost);
    r.uv = r.sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
    r.seam = r.sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;
    r.result = SMSO::optimize_seams(r.sm, r.uv, SMSO_np::edge_is_seam_map(r.seam).vertex_seam_cost_map(cost));
    BOOST_REQUIRE(r.result.status == SMSO::OK);
    BOOST_TEST(r.result.bound_met);
    check_valid(r);
    // the weighted term by hand: each seam edge's length times the mean of its vertices' costs
    double weighted = 0;
    for(edge_descriptor e : r.sm.edges())
      if(r.seam[e])
        weighted += std::sqrt(CGAL::squared_distance(r.sm.point(r.sm.vertex(e, 0)), r.sm.point(r.sm.vertex(e, 1)))) *
                    0.5 * (cost[r.sm.vertex(e, 0)] + cost[r.sm.vertex(e, 1)]);
    weighted /= std::sqrt(surface_area(r.sm) / CGAL_PI);
    BOOST_TEST(r.result.weighted_seam_length_normalized == weighted, boost::test_tools::tolerance(1e-9));
  };

  Run repelled;
  run_with_region(repelled, route_a, 100.);
  BOOST_TEST_MESSAGE("cat: seams on the plain route " << plain_in_a << " -> " << seam_length_inside(repelled, route_a)
                     << " with cost 100 there");
  BOOST_TEST(seam_length_inside(repelled, route_a) <= 0.5 * plain_in_a);

  // the repelled run's own route, less the plain one's vertices: a route the plain run did not take
  std::set<vertex_descriptor> route_b;
  for(vertex_descriptor v : seam_vertices(repelled))
    if(!route_a.count(v)) route_b.insert(v);
  BOOST_REQUIRE(!route_b.empty());
  const double plain_in_b = seam_length_inside(plain, route_b);
  Run attracted;
  run_with_region(attracted, route_b, 0.1);
  const double attracted_in_b = seam_length_inside(attracted, route_b);
  BOOST_TEST_MESSAGE("cat: seams on the other route " << plain_in_b << " -> " << attracted_in_b
                     << " with cost 0.1 there; weighted E_se " << attracted.result.weighted_seam_length_normalized
                     << ", plain " << attracted.result.seam_length_normalized);
  BOOST_TEST(attracted_in_b > plain_in_b + 0.25 * plain.result.seam_length);
  BOOST_TEST(attracted.result.weighted_seam_length_normalized < attracted.result.seam_length_normalized);
}

// Costs of 1 everywhere change nothing, to the last bit; invalid costs are
// refused before anything is written.
BOOST_AUTO_TEST_CASE(unit_seam_costs_change_nothing_and_invalid_ones_are_refused)
{
  Run plain, ones;
  run("bishop_part_f1000.obj", plain, SMSO_np::distortion_bound(4.1));
  {
    BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/bishop_part_f1000.obj", ones.sm));
    auto vcost = ones.sm.add_property_map<vertex_descriptor, double>("v:c", 1.).first;
    auto ecost = ones.sm.add_property_map<edge_descriptor, float>("e:c", 1.f).first;
    ones.uv = ones.sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
    ones.seam = ones.sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;
    ones.result = SMSO::optimize_seams(
      ones.sm, ones.uv, SMSO_np::edge_is_seam_map(ones.seam).seam_cost_map(ecost).vertex_seam_cost_map(vcost));
  }
  BOOST_REQUIRE(ones.result.status == SMSO::OK);
  BOOST_TEST(ones.result.iterations == plain.result.iterations);
  // the same seams, and the same map up to rounding. Under the sanitizers the
  // two instantiations' -O1 code rounds differently, and on one CI machine
  // that difference grew over the Newton iterations into another placement
  // of the same cut (UVs 0.32 apart, same seams and iteration count): there,
  // the map is compared by its distortion.
  bool same_seams = true;
  for(edge_descriptor e : plain.sm.edges()) same_seams = same_seams && plain.seam[e] == ones.seam[e];
  BOOST_TEST(same_seams);
  double largest = 0, extent = 0;
  for(halfedge_descriptor h : plain.sm.halfedges())
  {
    largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(plain.uv[h], ones.uv[h])));
    extent = (std::max)(extent, std::abs(plain.uv[h].x()) + std::abs(plain.uv[h].y()));
  }
#if defined(__SANITIZE_ADDRESS__)
  BOOST_TEST_MESSAGE("unit costs: largest UV difference " << largest << " of extent " << extent);
  BOOST_TEST(ones.result.distortion == plain.result.distortion, boost::test_tools::tolerance(1e-3));
  BOOST_TEST(ones.result.distortion <= 4.1);
  check_valid(ones);
#else
  BOOST_TEST(largest <= 1e-9 * extent);
#endif
  BOOST_TEST(ones.result.seam_length_normalized == plain.result.seam_length_normalized,
             boost::test_tools::tolerance(1e-12));

  for(double bad : {-1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    Surface_mesh sm;
    BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/bishop_part_f1000.obj", sm));
    auto uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(7, 7)).first;
    auto vcost = sm.add_property_map<vertex_descriptor, double>("v:c", 1.).first;
    auto ecost = sm.add_property_map<edge_descriptor, double>("e:c", 1.).first;
    vcost[*std::next(sm.vertices().begin(), 10)] = bad;
    ecost[*std::next(sm.edges().begin(), 10)] = bad;
    const SMSO::Optimization_result rv = SMSO::optimize_seams(sm, uv, SMSO_np::vertex_seam_cost_map(vcost));
    BOOST_TEST(rv.status == SMSO::ERROR_WRONG_PARAMETER);
    BOOST_TEST(rv.message.find("vertex_seam_cost_map") != std::string::npos);
    const SMSO::Optimization_result re = SMSO::optimize_seams(sm, uv, SMSO_np::seam_cost_map(ecost));
    BOOST_TEST(re.status == SMSO::ERROR_WRONG_PARAMETER);
    BOOST_TEST(re.message.find("seam_cost_map") != std::string::npos);
    // the former name still reads the same map
    BOOST_TEST(SMSO::optimize_seams(sm, uv, SMSO_np::edge_seam_weight_map(ecost)).status == SMSO::ERROR_WRONG_PARAMETER);
    bool untouched = true;
    for(halfedge_descriptor h : sm.halfedges())
      untouched = untouched && uv[h] == Point_2(7, 7);
    BOOST_TEST(untouched);
  }
}

// ---------------------------------------------------------------------------
// Hidden seams (edge_visibility, visibility_seam_costs)

BOOST_AUTO_TEST_CASE(edge_visibility_on_hand_made_surfaces)
{
  // a flat square of two triangles: every direction in front escapes, no crease
  Surface_mesh flat;
  const vertex_descriptor a = flat.add_vertex(K::Point_3(0, 0, 0)), b = flat.add_vertex(K::Point_3(1, 0, 0)),
                          c = flat.add_vertex(K::Point_3(1, 1, 0)), d = flat.add_vertex(K::Point_3(0, 1, 0));
  flat.add_face(a, b, c);
  flat.add_face(a, c, d);
  auto vis = flat.add_property_map<edge_descriptor, double>("e:vis", -1.).first;
  SMSO::edge_visibility(flat, vis);
  for(edge_descriptor e : flat.edges()) BOOST_TEST(vis[e] == 1.);

  // folded along x = 1 by 90 degrees, up (a valley) and down (a ridge); the
  // valley's fold edge has crease factor 1 - (pi/2)/pi = 1/2 times an openness <= 1
  for(double up : {1., -1.})
  {
    Surface_mesh fold;
    const vertex_descriptor p0 = fold.add_vertex(K::Point_3(0, 0, 0)), p1 = fold.add_vertex(K::Point_3(1, 0, 0)),
                            p2 = fold.add_vertex(K::Point_3(1, 1, 0)), p3 = fold.add_vertex(K::Point_3(0, 1, 0)),
                            q1 = fold.add_vertex(K::Point_3(1, 0, up)), q2 = fold.add_vertex(K::Point_3(1, 1, up));
    fold.add_face(p0, p1, p2);
    fold.add_face(p0, p2, p3);
    fold.add_face(p1, q1, q2);
    fold.add_face(p1, q2, p2);
    auto v = fold.add_property_map<edge_descriptor, double>("e:vis", -1.).first;
    SMSO::edge_visibility(fold, v, SMSO_np::number_of_rays(256));
    const edge_descriptor hinge = fold.edge(fold.halfedge(p1, p2));
    const edge_descriptor far_edge = fold.edge(fold.halfedge(p0, p3));
    if(up > 0)
    {
      BOOST_TEST(v[hinge] <= 0.5);
      BOOST_TEST(v[hinge] > 0.2);       // half of the front is open
      BOOST_TEST(v[far_edge] < 1.);     // the wall hides part of the sky
    }
    else
    {
      BOOST_TEST(v[hinge] == 1.);       // a ridge: nothing in front, no crease factor
      BOOST_TEST(v[far_edge] == 1.);
    }
  }
}

// Costs from visibility ranks span [1, ratio] in the order of visibility; the
// visible share is the seam length on the most visible quarter over all of it.
BOOST_AUTO_TEST_CASE(visibility_costs_and_visible_share)
{
  Surface_mesh sm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/cat_f1500.obj", sm));
  auto vis = sm.add_property_map<edge_descriptor, double>("e:vis", -1.).first;
  auto cost = sm.add_property_map<edge_descriptor, double>("e:cost", -1.).first;
  SMSO::edge_visibility(sm, vis);
  SMSO::visibility_seam_costs(sm, cost, SMSO_np::visibility_cost_ratio(4.));
  double lo = 1e9, hi = -1e9;
  std::vector<std::pair<double, double> > vc;
  for(edge_descriptor e : sm.edges())
  {
    BOOST_REQUIRE(vis[e] >= 0.);
    BOOST_REQUIRE(vis[e] <= 1.);
    lo = (std::min)(lo, cost[e]);
    hi = (std::max)(hi, cost[e]);
    vc.emplace_back(vis[e], cost[e]);
  }
  BOOST_TEST(lo == 1., boost::test_tools::tolerance(1e-12));
  BOOST_TEST(hi == 4., boost::test_tools::tolerance(1e-12));
  std::sort(vc.begin(), vc.end());
  bool monotone = true;
  for(std::size_t i = 1; i < vc.size(); ++i) monotone = monotone && vc[i].second >= vc[i - 1].second;
  BOOST_TEST(monotone);
  BOOST_TEST(vc.front().first < 0.9 * vc.back().first); // the cat has hidden parts

  // hand-made visibilities: edge i has visibility i; seams on the top edge and on edge 0
  auto hand = sm.add_property_map<edge_descriptor, double>("e:hand", 0.).first;
  auto seam = sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  std::vector<edge_descriptor> es(sm.edges().begin(), sm.edges().end());
  for(std::size_t i = 0; i < es.size(); ++i) hand[es[i]] = double(i);
  seam[es.front()] = seam[es.back()] = true;
  auto length = [&](edge_descriptor e) {
    return std::sqrt(CGAL::squared_distance(sm.point(sm.vertex(e, 0)), sm.point(sm.vertex(e, 1))));
  };
  const double expected = length(es.back()) / (length(es.back()) + length(es.front()));
  BOOST_TEST(SMSO::seam_share_on_most_visible_edges(sm, hand, seam, 0.25) == expected,
             boost::test_tools::tolerance(1e-12));
  seam[es.back()] = false;
  BOOST_TEST(SMSO::seam_share_on_most_visible_edges(sm, hand, seam, 0.25) == 0.);
}

// The seams move off the most visible quarter of the edges (share at most
// half the default run's) for at most 1.3 times the seam length, within the bound.
BOOST_AUTO_TEST_CASE(visibility_costs_hide_the_seams)
{
  Run plain, hidden;
  run("cat_f1500.obj", plain, SMSO_np::distortion_bound(4.1));
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/cat_f1500.obj", hidden.sm));
  auto cost = hidden.sm.add_property_map<edge_descriptor, double>("e:cost", 1.).first;
  SMSO::visibility_seam_costs(hidden.sm, cost);
  hidden.uv = hidden.sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  hidden.seam = hidden.sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  hidden.result = SMSO::optimize_seams(hidden.sm, hidden.uv, SMSO_np::edge_is_seam_map(hidden.seam).seam_cost_map(cost));
  BOOST_REQUIRE(hidden.result.status == SMSO::OK);
  BOOST_TEST(hidden.result.bound_met);
  check_valid(hidden);

  auto vis = hidden.sm.add_property_map<edge_descriptor, double>("e:vis", 0.).first;
  SMSO::edge_visibility(hidden.sm, vis);
  // same mesh file, same edge order: the plain run's seams measured with the same visibility
  auto plain_seam = hidden.sm.add_property_map<edge_descriptor, bool>("e:plain_seam", false).first;
  for(edge_descriptor e : plain.sm.edges()) plain_seam[e] = plain.seam[e];
  const double share_plain = SMSO::seam_share_on_most_visible_edges(hidden.sm, vis, plain_seam);
  const double share_hidden = SMSO::seam_share_on_most_visible_edges(hidden.sm, vis, hidden.seam);
  BOOST_TEST_MESSAGE("cat: visible share " << share_plain << " -> " << share_hidden << ", E_se "
                     << plain.result.seam_length_normalized << " -> " << hidden.result.seam_length_normalized);
  BOOST_TEST(share_plain > 0.);
  BOOST_TEST(share_hidden <= 0.5 * share_plain);
  BOOST_TEST(hidden.result.seam_length_normalized <= 1.3 * plain.result.seam_length_normalized);
}

// ---------------------------------------------------------------------------
// The EBCuts baseline (cut_strategy(EBCUTS))

// Cuts grown from the worst vertex to the boundary until the bound holds: a
// valid cut (one disk chart, seams = UV discontinuities) meeting the bound,
// with longer seams than OptCuts' on cat_f1500, as the paper reports.
BOOST_AUTO_TEST_CASE(ebcuts_meets_the_bound_with_longer_seams)
{
  Run optcuts, ebcuts;
  run("cat_f1500.obj", optcuts, SMSO_np::distortion_bound(4.1));
  run("cat_f1500.obj", ebcuts, SMSO_np::cut_strategy(SMSO::EBCUTS));
  BOOST_REQUIRE(ebcuts.result.status == SMSO::OK);
  BOOST_TEST(ebcuts.result.bound_met);
  BOOST_TEST(ebcuts.result.distortion <= 4.1);
  BOOST_TEST(ebcuts.result.topology_operations >= 1u); // the cuts
  check_valid(ebcuts);
  BOOST_TEST(ebcuts.result.seam_length_normalized > optcuts.result.seam_length_normalized);

  Surface_mesh sm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/cat_f1500.obj", sm));
  auto uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv", Point_2(7, 7)).first;
  const auto with_weight = SMSO::optimize_seams(sm, uv, SMSO_np::cut_strategy(SMSO::EBCUTS).seam_weight(0.1));
  BOOST_TEST(with_weight.status == SMSO::ERROR_WRONG_PARAMETER);
  BOOST_TEST(with_weight.message.find("EBCUTS") != std::string::npos);
  BOOST_TEST(SMSO::optimize_seams(sm, uv, SMSO_np::cut_strategy(SMSO::EBCUTS).distortion_bound(3.)).status ==
             SMSO::ERROR_WRONG_PARAMETER);
  bool untouched = true;
  for(halfedge_descriptor h : sm.halfedges()) untouched = untouched && uv[h] == Point_2(7, 7);
  BOOST_TEST(untouched);
}

// a run that met the bound with a valid map
void check_met(const Run& r)
{
  BOOST_TEST(r.result.status == SMSO::OK);
  BOOST_TEST(r.result.bound_met);
  BOOST_TEST(r.result.distortion <= 4.1);
  check_valid(r);
}

// A run with several starts: it met the bound with a valid map, and the
// same call on one thread (`again`) gives the same result.
template <typename NP>
void check_starts(const std::string& name, const Run& r, Run& again, const NP& np, const std::string& dir)
{
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
#endif
    run(name, again, np, dir);
  }
  check_met(r);
  check_met(again);
  BOOST_TEST(again.result.start == r.result.start);
  BOOST_TEST(again.result.seam_length == r.result.seam_length);
  BOOST_TEST(again.result.iterations == r.result.iterations);
}

// A start added by more starts: the run with more starts (`more`) keeps
// start `kept`, the one with fewer (`fewer`) does not, and its seams are
// below `ratio` times theirs; both meet the bound, and `again`, the run with
// more starts on one thread, gives the same result.
template <typename Fewer, typename More>
void check_added_start(const std::string& name, const std::string& dir, const Fewer& fewer_np, const More& more_np,
                       std::size_t kept, double ratio, Run& fewer, Run& more, Run& again)
{
  run(name, fewer, fewer_np, dir);
  run(name, more, more_np, dir);
  check_starts(name, more, again, more_np, dir);
  check_met(fewer);
  BOOST_TEST(fewer.result.start != kept);
  BOOST_TEST(more.result.start == kept);
  BOOST_TEST(more.result.seam_length_normalized < ratio * fewer.result.seam_length_normalized);
}

// planck_s1 (775 faces): the hold-price start (start 1, the fourth taken
// with the scaffold), whose dual step holds the price of distortion while a
// cut pays, finds shorter seams under the bound than the first three starts
// (3.49 against 3.67); four starts keep them.
BOOST_AUTO_TEST_CASE(the_hold_price_start_shortens_the_seams)
{
  Run three, four, again;
  check_added_start("planck_s1.obj", SMSO_TEST_DATA_DIR, SMSO_np::number_of_starts(3), SMSO_np::number_of_starts(4), 1u,
                    0.97, three, four, again);
}

// Two starts in parallel give the same result run after run, whatever the
// number of threads, and with a solver given by the user (the starts then
// take turns, as copies of the traits share their solver).
BOOST_AUTO_TEST_CASE(two_starts_are_deterministic)
{
  Run a, b, c, d;
  run("planck_s1.obj", a, SMSO_np::number_of_starts(2), SMSO_TEST_DATA_DIR);
  run("planck_s1.obj", b, SMSO_np::number_of_starts(2), SMSO_TEST_DATA_DIR);
  run("planck_s1.obj", c, SMSO_np::number_of_starts(2).sparse_linear_solver(SMSO::Default_sparse_solver_traits()),
      SMSO_TEST_DATA_DIR);
  {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
#endif
    run("planck_s1.obj", d, SMSO_np::number_of_starts(2), SMSO_TEST_DATA_DIR);
  }
  for(const Run* r : { &b, &c, &d })
  {
    BOOST_TEST(r->result.start == a.result.start);
    BOOST_TEST(r->result.distortion == a.result.distortion);
    BOOST_TEST(r->result.seam_length == a.result.seam_length);
    BOOST_TEST(r->result.iterations == a.result.iterations);
    bool same = true;
    for(halfedge_descriptor h : a.sm.halfedges())
      if(!a.sm.is_border(h)) same = same && a.uv[h] == r->uv[h] && a.seam[edge(h, a.sm)] == r->seam[edge(h, r->sm)];
    BOOST_TEST(same);
  }
}

// The cat's charts never overlap (see the_scaffold_waits_until_charts_overlap):
// there is nothing to relax, and the second start is the first-cut start,
// whose seams are longer here (1.80 against 1.76). The call gives the first
// start's result, to the last bit: the second start changes nothing of it.
BOOST_AUTO_TEST_CASE(a_second_start_that_loses_leaves_the_first_result_unchanged)
{
  Run one, two;
  run("cat_f1500.obj", one, SMSO_np::number_of_starts(1));
  run("cat_f1500.obj", two, SMSO_np::number_of_starts(2));
  BOOST_TEST(two.result.status == SMSO::OK);
  BOOST_TEST(two.result.start == 0u);
  BOOST_TEST(two.result.scaffold_rebuilds == 0u);
  check_same_result(two, one);
  check_valid(two);
}

// hand1 (413 faces): with the scaffold from the start, the cutting phase
// takes many cheap cuts once the fingers press on the palm (seams 10.08, the
// reference's 7.52); the relaxed start (start 2, the second by default)
// cuts without the scaffold first (6.79, overlapping) and goes on with it
// from those seams: 8.92, bijective. The result is the same run after run
// and with one thread.
BOOST_AUTO_TEST_CASE(the_relaxed_start_cutting_without_the_scaffold_first_shortens_the_seams)
{
  Run one, two, again;
  check_added_start("hand1.obj", SMSO_TEST_DATA_DIR, SMSO_np::number_of_starts(1), SMSO_np::number_of_starts(2), 2u, 0.95,
                    one, two, again);
  BOOST_TEST(one.result.start == 0u);
  bool same = true;
  for(halfedge_descriptor h : two.sm.halfedges())
    if(!two.sm.is_border(h))
      same = same && two.uv[h] == again.uv[h] && two.seam[edge(h, two.sm)] == again.seam[edge(h, again.sm)];
  BOOST_TEST(same);
}

// bishop_part_f1000 (1000 faces): the first-cut start (start 3) cuts first
// from the vertex of largest distortion of the uncut map to the border
// (EBCuts' first cut), then optimizes from that cut: seams 2.659 (the paper's
// code's 2.659), against 2.781 for the first start. The charts never
// overlap, so by default the second start is the first-cut start, not the
// relaxed one. Deterministic whatever the number of threads (on one thread
// the first-cut start runs after the first, not beside it).
BOOST_AUTO_TEST_CASE(the_first_cut_start_shortens_the_seams)
{
  Run one, two, again;
  check_added_start("bishop_part_f1000.obj", SMSO_DATA_DIR, SMSO_np::number_of_starts(1), SMSO_np::number_of_starts(2), 3u,
                    0.98, one, two, again);
  BOOST_TEST(one.result.start == 0u);
  BOOST_TEST(two.result.scaffold_rebuilds == 0u);
}

// Where the charts overlap, the first-cut start (run beside the first one
// from the beginning) is dropped there, whatever it has reached, and the
// second start is the relaxed start. planck_s1: the first-cut start's seams
// are the shortest (3.669, kept with three starts), but two starts keep the
// relaxed start's (3.686), also on one thread, where the first-cut start
// never begins.
BOOST_AUTO_TEST_CASE(the_first_cut_start_is_dropped_where_the_charts_overlap)
{
  Run two, three, again;
  run("planck_s1.obj", two, SMSO_np::number_of_starts(2), SMSO_TEST_DATA_DIR);
  run("planck_s1.obj", three, SMSO_np::number_of_starts(3), SMSO_TEST_DATA_DIR);
  check_starts("planck_s1.obj", two, again, SMSO_np::number_of_starts(2), SMSO_TEST_DATA_DIR);
  check_met(three);
  BOOST_TEST(two.result.start == 2u);
  BOOST_TEST(two.result.scaffold_rebuilds > 0u);
  BOOST_TEST(three.result.start == 3u);
  BOOST_TEST(three.result.seam_length_normalized < two.result.seam_length_normalized);
}

// torusOnPlane remeshed (1763 faces: CGAL's isotropic_remeshing of the OptCuts
// benchmark mesh, edge length 9, 5 iterations): the first start's charts
// overlap, so the second start is the relaxed start, but its run without the
// scaffold winds the seams as the first start does and is still cutting when
// its iteration budget ends: nothing feasible. The first-cut start then runs
// after it, from its beginning: seams 2.77 against the first start's 3.38
// (0.82), also on one thread.
BOOST_AUTO_TEST_CASE(the_first_cut_start_runs_after_a_relaxed_start_that_finds_nothing)
{
  Run one, two, again;
  check_added_start("torusOnPlane_remeshed_f1763.obj", SMSO_TEST_DATA_DIR, SMSO_np::number_of_starts(1),
                    SMSO_np::number_of_starts(2), 3u, 0.9, one, two, again);
  BOOST_TEST(one.result.start == 0u);
  BOOST_TEST(one.result.scaffold_rebuilds > 0u); // the charts overlapped: a relaxed start was due
}

// The relaxed start takes over the first start's run where its lazy phase ends
// (the charts first overlap) and goes on without the scaffold: that run is
// the one without bijectivity (hand1: the same seams and iterations as
// bijective(false)), and the first start goes on unchanged with its scaffold.
BOOST_AUTO_TEST_CASE(the_free_run_forks_from_the_first_start_where_its_lazy_phase_ends)
{
  typedef SMSO::Seam_optimizer<Surface_mesh> Optimizer;
  typedef SMSO::internal::Seam_optimizer_access Access;
  Run free_run, bijective_run;
  run("hand1.obj", free_run, SMSO_np::number_of_starts(1).bijective(false), SMSO_TEST_DATA_DIR);
  run("hand1.obj", bijective_run, SMSO_np::number_of_starts(1), SMSO_TEST_DATA_DIR);
  BOOST_REQUIRE(free_run.result.has_result());
  BOOST_TEST(free_run.result.overlapping_triangle_pairs > 0u); // else the lazy phase would not end

  Run r;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_TEST_DATA_DIR) + "/hand1.obj", r.sm));
  r.uv = r.sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  r.seam = r.sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  SMSO::Default_seam_optimization_visitor visitor, fork_visitor;
  std::unique_ptr<Optimizer> first = Access::set_up<Optimizer>(r.sm, r.uv, visitor, SMSO_np::default_values());
  std::unique_ptr<Optimizer> forked;
  std::size_t calls = 0, at = 0;
  Access::set_lazy_phase_end_hook(*first, [&] {
    ++calls;
    at = Access::iterations(*first);
    forked = Access::fork_free(*first, fork_visitor, SMSO::Default_sparse_solver_traits());
  });
  Access::begin(*first);
  const SMSO::Optimization_result first_result = first->run();
  BOOST_TEST(calls == 1u);
  BOOST_REQUIRE(forked);
  BOOST_TEST(at > 0u);
  BOOST_TEST(at < first_result.iterations);
  // the first start as without the hook
  BOOST_TEST(first_result.seam_length == bijective_run.result.seam_length);
  BOOST_TEST(first_result.iterations == bijective_run.result.iterations);

  Access::resume(*forked);
  const SMSO::Optimization_result f = forked->run();
  BOOST_TEST(f.status == SMSO::OK);
  BOOST_TEST(f.seam_length == free_run.result.seam_length);
  BOOST_TEST(f.distortion == free_run.result.distortion);
  BOOST_TEST(f.iterations == free_run.result.iterations);
  forked->write_uv_map(r.uv);
  forked->write_seam_map(r.seam);
  bool same = true;
  for(halfedge_descriptor h : r.sm.halfedges())
    if(!r.sm.is_border(h)) same = same && r.seam[edge(h, r.sm)] == free_run.seam[edge(h, free_run.sm)];
  BOOST_TEST(same);
}

// A slit of two edges in the middle of a 6 x 6 grid joins the border along a
// shortest path (2 edges from either end of the slit); nothing is left to join then.
BOOST_AUTO_TEST_CASE(a_slit_joins_the_border_along_a_shortest_path)
{
  Surface_mesh sm;
  CGAL::make_grid(6, 6, sm, [](std::size_t i, std::size_t j) { return K::Point_3(double(i), double(j), 0.); }, true);
  Seam_map seam = sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  auto at = [&](double x, double y) {
    for(auto v : sm.vertices()) if(sm.point(v) == K::Point_3(x, y, 0.)) return v;
    return Surface_mesh::null_vertex();
  };
  auto seam_between = [&](double x0, double y0, double x1, double y1) {
    const auto e = CGAL::edge(at(x0, y0), at(x1, y1), sm);
    BOOST_REQUIRE(e.second);
    seam[e.first] = true;
  };
  seam_between(2, 3, 3, 3);
  seam_between(3, 3, 4, 3);
  auto seam_length = [&] {
    double l = 0;
    for(edge_descriptor e : sm.edges())
      if(seam[e]) l += std::sqrt(CGAL::squared_distance(sm.point(sm.source(sm.halfedge(e))), sm.point(sm.target(sm.halfedge(e)))));
    return l;
  };
  BOOST_TEST(SMSO::internal::join_slits_to_border(sm, get(CGAL::vertex_point, sm), seam) == 1u);
  BOOST_TEST(std::abs(seam_length() - 4.) < 1e-12);
  // the slit and the new path reach the border: one tree with it
  std::size_t on_border = 0;
  for(edge_descriptor e : sm.edges())
    if(seam[e])
      for(auto v : { sm.source(sm.halfedge(e)), sm.target(sm.halfedge(e)) })
        on_border += sm.is_border(v) ? 1 : 0;
  BOOST_TEST(on_border == 1u);
  BOOST_TEST(SMSO::internal::join_slits_to_border(sm, get(CGAL::vertex_point, sm), seam) == 0u);
  BOOST_TEST(std::abs(seam_length() - 4.) < 1e-12);
}

// An open tube (two boundary loops at its ends): with the holes kept its
// map is an annulus, far from isometric, and no single boundary split pays
// until a cut joins the two loops. The holes are joined first: the tube
// unrolls along one shortest path from end to end (3D length 10), at E_SD 4.
BOOST_AUTO_TEST_CASE(a_tube_is_cut_open_from_end_to_end)
{
  const int around = 16, along = 40;
  const double length = 10;
  Surface_mesh sm;
  std::vector<Surface_mesh::Vertex_index> v;
  for(int j = 0; j <= along; ++j)
    for(int i = 0; i < around; ++i)
    {
      const double a = 2 * CGAL_PI * i / around;
      v.push_back(sm.add_vertex(K::Point_3(std::cos(a), std::sin(a), length * j / along)));
    }
  auto at = [&](int i, int j) { return v[std::size_t(j * around + (i % around))]; };
  for(int j = 0; j < along; ++j)
    for(int i = 0; i < around; ++i)
    {
      sm.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      sm.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  BOOST_REQUIRE(sm.number_of_faces() == std::size_t(2 * around * along));
  UV_map uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  Seam_map seam = sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;

  // its map with the holes kept is far above the bound
  {
    UV_map kept_uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:kept_uv").first;
    Seam_map kept_seam = sm.add_property_map<edge_descriptor, bool>("e:kept_seam", false).first;
    const SMSO::Optimization_result kept =
      SMSO::minimize_distortion(sm, kept_uv, SMSO_np::edge_is_seam_map(kept_seam));
    BOOST_TEST_REQUIRE(kept.status == SMSO::OK);
    BOOST_TEST(kept.distortion_at_optimal_scale > 5.);
  }

  const SMSO::Optimization_result r = SMSO::optimize_seams(sm, uv, SMSO_np::edge_is_seam_map(seam));
  BOOST_TEST_MESSAGE("tube: " << r.message << ", E_SD " << r.distortion << ", seams " << r.seam_length);
  BOOST_TEST_REQUIRE(r.status == SMSO::OK);
  BOOST_TEST(r.message.find("holes joined") != std::string::npos);
  BOOST_TEST(r.bound_met);
  BOOST_TEST(r.distortion_at_optimal_scale < 4.01);
  BOOST_TEST(r.charts == 1u);
  BOOST_TEST(r.bijective);
  // one path from end to end: as long as the tube, and it joins the two loops
  BOOST_TEST(r.seam_length >= length * (1 - 1e-9));
  BOOST_TEST(r.seam_length <= length * 1.05);
  std::set<double> seam_heights;
  for(edge_descriptor e : sm.edges())
    if(seam[e])
      for(auto w : { sm.source(sm.halfedge(e)), sm.target(sm.halfedge(e)) }) seam_heights.insert(sm.point(w).z());
  BOOST_TEST(seam_heights.size() == std::size_t(along + 1));
  const SMSO::Uv_map_measures m = SMSO::measure_uv_map(sm, uv, SMSO_np::edge_is_seam_map(seam));
  BOOST_TEST(m.status == SMSO::OK);
  BOOST_TEST(m.flipped_triangles == 0u);
  BOOST_TEST(m.overlapping_triangle_pairs == 0u);
  BOOST_TEST(std::abs(m.seam_length - r.seam_length) <= 1e-9 * length);
}

// A planar square with a square hole: its map with the hole kept meets the
// bound, so nothing is joined (no seam at all).
BOOST_AUTO_TEST_CASE(a_hole_whose_map_meets_the_bound_is_not_joined)
{
  Surface_mesh sm;
  CGAL::make_grid(8, 8, sm, [](std::size_t i, std::size_t j) { return K::Point_3(double(i), double(j), 0.); }, true);
  std::vector<Surface_mesh::Face_index> hole;
  for(auto f : sm.faces())
  {
    double x = 0, y = 0;
    for(auto w : CGAL::vertices_around_face(sm.halfedge(f), sm)) { x += sm.point(w).x() / 3; y += sm.point(w).y() / 3; }
    if(x > 3 && x < 5 && y > 3 && y < 5) hole.push_back(f);
  }
  BOOST_REQUIRE(hole.size() == 8u);
  for(auto f : hole) CGAL::Euler::remove_face(sm.halfedge(f), sm);
  sm.collect_garbage();
  UV_map uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  Seam_map seam = sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  const SMSO::Optimization_result r = SMSO::optimize_seams(sm, uv, SMSO_np::edge_is_seam_map(seam));
  BOOST_TEST_REQUIRE(r.status == SMSO::OK);
  BOOST_TEST(r.message.find("holes joined") == std::string::npos);
  BOOST_TEST(r.bound_met);
  BOOST_TEST(r.seam_length == 0.);
  BOOST_TEST(r.charts == 1u);
}

// A stop asked by the user's visitor (called by the first start only) stops
// both starts, and the first start's result is kept. On the octopus a whole
// run of either start takes about a minute.
BOOST_AUTO_TEST_CASE(a_cancel_stops_both_starts)
{
  struct Stop_visitor : SMSO::Default_seam_optimization_visitor
  {
    std::size_t iterations = 0, operations = 0;
    double cancelled_at = 0;
    bool on_iteration(const SMSO::Seam_optimization_progress&) { ++iterations; return true; }
    bool on_topology_operation(const SMSO::Seam_optimization_progress& p)
    {
      cancelled_at = p.seconds;
      return ++operations < 3;
    }
  } visitor;
  Run r;
  run("octopus_mainComp_f6000.obj", r, SMSO_np::number_of_starts(2).visitor(std::ref(visitor)), SMSO_TEST_DATA_DIR);
  BOOST_TEST_MESSAGE("octopus: cancelled at " << visitor.cancelled_at << " s, returned at " << r.result.seconds << " s");
  BOOST_TEST(r.result.status == SMSO::WARNING_CANCELLED);
  BOOST_TEST(r.result.start == 0u);
  BOOST_TEST(r.result.iterations == visitor.iterations);
  // the other start stopped too: had it run on, the call would have lasted a
  // whole run (~8 times the part before the cancel); relative, as the speed of
  // the machine (and of sanitizer builds) scales both parts
  BOOST_TEST(r.result.seconds - visitor.cancelled_at < visitor.cancelled_at);
  BOOST_TEST(SMSO::number_of_flipped_triangles(r.sm, r.uv) == 0u);
}

// ---------------------------------------------------------------------------
// Energies with their own bound

// The bound is on the run's energy, in its own units, with a default per
// energy. The conformal run meets 2.02525 with lower angle distortion (pure
// MIPS) than the E_SD run and no collapsed area; the ARAP run, started from
// the E_SD run at the bound of the same strains (ARAP is no barrier), meets 0.025.
BOOST_AUTO_TEST_CASE(each_energy_meets_its_own_default_bound)
{
  Run sd, conformal, arap;
  run("cat_f1500.obj", sd, SMSO_np::distortion_bound(4.1));
  run("cat_f1500.obj", conformal, SMSO_np::energy(SMSO::Conformal_energy()));
  run("cat_f1500.obj", arap, SMSO_np::energy(SMSO::ARAP_energy()));
  const SMSO::Conformal_energy mips(0.);
  const double sd_angles = SMSO::distortion(sd.sm, sd.uv, SMSO_np::energy(mips));
  const double conformal_angles = SMSO::distortion(conformal.sm, conformal.uv, SMSO_np::energy(mips));
  const double conformal_value = SMSO::distortion(conformal.sm, conformal.uv, SMSO_np::energy(SMSO::Conformal_energy()));
  const double arap_value = SMSO::distortion(arap.sm, arap.uv, SMSO_np::energy(SMSO::ARAP_energy()));
  BOOST_TEST_MESSAGE("cat: MIPS " << sd_angles << " (E_SD run) vs " << conformal_angles << " (conformal run, E_se "
                     << conformal.result.seam_length_normalized << ", E_SD " << conformal.result.distortion
                     << "); ARAP " << arap_value << " (E_SD " << arap.result.distortion << ", E_se "
                     << arap.result.seam_length_normalized << ")");
  BOOST_TEST(sd.result.energy_value == sd.result.distortion);
  for(const Run* r : {&conformal, &arap})
  {
    BOOST_TEST(r->result.status == SMSO::OK);
    BOOST_TEST(r->result.bound_met);
    BOOST_TEST(SMSO::number_of_flipped_triangles(r->sm, r->uv) == 0u);
    BOOST_TEST(SMSO::number_of_overlapping_triangle_pairs(r->sm, r->uv) == 0u);
    check_valid(*r);
  }
  BOOST_TEST(std::abs(conformal.result.energy_value - conformal_value) <= 1e-9 * conformal_value);
  BOOST_TEST(conformal_value <= SMSO::Conformal_energy().default_bound());
  BOOST_TEST(conformal_angles < sd_angles);
  BOOST_TEST(conformal.result.distortion < 10.); // the area term keeps areas within a bounded factor
  BOOST_TEST(std::abs(arap.result.energy_value - arap_value) <= 1e-9 + 1e-9 * arap_value);
  BOOST_TEST(arap_value <= SMSO::ARAP_energy::default_bound());
  BOOST_TEST(arap.result.distortion < 4.5);
  BOOST_TEST(arap.result.charts < 5u); // no detached faces

  Surface_mesh sm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/bishop_part_f1000.obj", sm));
  auto uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  const auto low_conformal =
    SMSO::optimize_seams(sm, uv, SMSO_np::energy(SMSO::Conformal_energy()).distortion_bound(2.));
  BOOST_TEST(low_conformal.status == SMSO::ERROR_WRONG_PARAMETER);
  BOOST_TEST(low_conformal.message.find("> 2") != std::string::npos);
  BOOST_TEST(SMSO::optimize_seams(sm, uv, SMSO_np::energy(SMSO::ARAP_energy()).distortion_bound(0.)).status ==
             SMSO::ERROR_WRONG_PARAMETER);
  for(halfedge_descriptor h : sm.halfedges()) put(uv, h, Point_2(7, 7));
  const auto negative = SMSO::optimize_seams(sm, uv, SMSO_np::energy(SMSO::Conformal_energy(-0.5)));
  BOOST_TEST(negative.status == SMSO::ERROR_WRONG_PARAMETER);
  BOOST_TEST(negative.message.find("below its minimum_value()") != std::string::npos);
  bool untouched = true;
  for(halfedge_descriptor h : sm.halfedges()) untouched = untouched && get(uv, h) == Point_2(7, 7);
  BOOST_TEST(untouched);
  BOOST_TEST(SMSO::optimize_seams(sm, uv, SMSO_np::energy(SMSO::ARAP_energy()).distortion_bound(0.01)).bound_met);
}

// The E_SD start of an ARAP run shares the call's iteration cap: stopped
// within it (in the E_SD start, or after it), with a valid map whose
// energy_value is ARAP's.
BOOST_AUTO_TEST_CASE(the_e_sd_start_of_arap_counts_in_the_iteration_cap)
{
  for(std::size_t cap : {30u, 140u})
  {
    Run r;
    run("cat_f1500.obj", r, SMSO_np::energy(SMSO::ARAP_energy()).number_of_iterations(cap));
    BOOST_TEST_MESSAGE("cat, ARAP, cap " << cap << ": " << SMSO::get_error_code_name(r.result.status) << ", "
                       << r.result.iterations << " iterations, ARAP " << r.result.energy_value);
    BOOST_TEST(r.result.has_result());
    BOOST_TEST(r.result.iterations <= cap);
    BOOST_TEST(SMSO::number_of_flipped_triangles(r.sm, r.uv) == 0u);
    const double arap = SMSO::distortion(r.sm, r.uv, SMSO_np::energy(SMSO::ARAP_energy()));
    BOOST_TEST(std::abs(r.result.energy_value - arap) <= 1e-9 + 1e-9 * arap);
    if(cap == 30u) BOOST_TEST(r.result.status == SMSO::WARNING_MAXIMUM_ITERATIONS); // the E_SD start takes ~110
  }
}

// ---------------------------------------------------------------------------
// Dense meshes through a proxy (proxy_number_of_faces)
// ---------------------------------------------------------------------------

BOOST_AUTO_TEST_CASE(the_proxy_keeps_input_vertices_and_carries_a_valid_cut_and_map)
{
  namespace I = SMSO::internal;
  Surface_mesh sm;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/cat_f1500.obj", sm));
  I::Cut_mesh full;
  I::Face_graph_copy<Surface_mesh> copy;
  std::string message;
  BOOST_REQUIRE(I::copy_face_graph(sm, sm.points(), full, copy, message) == SMSO::OK);
  I::Proxy proxy;
  BOOST_REQUIRE(I::build_proxy(full, 400, proxy));
  const I::Proxy_mesh& pm = proxy.mesh;
  BOOST_TEST(pm.number_of_faces() <= 440u);
  BOOST_TEST(pm.number_of_faces() >= 300u);
  // same topology (Euler characteristic and border loops), every proxy vertex
  // an input vertex at its place
  long full_edges = 0, full_borders = 0, proxy_borders = 0;
  for(std::size_t h = 0; h < full.opposite.size(); ++h)
  {
    full_edges += full.opposite[h] < 0 || full.opposite[h] > int(h);
    full_borders += full.opposite[h] < 0;
  }
  for(auto h : pm.halfedges()) proxy_borders += pm.is_border(h);
  BOOST_TEST(long(pm.number_of_vertices()) - long(pm.number_of_edges()) + long(pm.number_of_faces()) ==
             long(full.number_of_vertices()) - full_edges + long(full.number_of_faces()));
  BOOST_TEST(proxy_borders > 0);
  BOOST_TEST(proxy_borders < full_borders);
  std::set<int> used;
  for(auto v : pm.vertices())
  {
    const int w = proxy.full_vertex[v.idx()];
    BOOST_REQUIRE(w >= 0);
    BOOST_TEST(used.insert(w).second);
    BOOST_TEST(pm.point(v).x() == full.points[3*w]);
    BOOST_TEST(pm.point(v).y() == full.points[3*w+1]);
    BOOST_TEST(pm.point(v).z() == full.points[3*w+2]);
  }

  // seams and map on the proxy, carried to the mesh
  auto puv = proxy.mesh.add_property_map<I::Proxy_mesh::Halfedge_index, I::Proxy_kernel::Point_2>("h:uv").first;
  auto pseam = proxy.mesh.add_property_map<I::Proxy_mesh::Edge_index, bool>("e:seam", false).first;
  const SMSO::Optimization_result coarse =
    SMSO::optimize_seams(proxy.mesh, puv, SMSO_np::edge_is_seam_map(pseam).number_of_starts(1));
  BOOST_REQUIRE(coarse.status == SMSO::OK);
  double proxy_seam_length = 0;
  for(auto e : pm.edges())
    if(pseam[e]) proxy_seam_length += std::sqrt(CGAL::squared_distance(pm.point(pm.vertex(e, 0)), pm.point(pm.vertex(e, 1))));
  BOOST_REQUIRE(proxy_seam_length > 0);

  std::vector<char> seam;
  std::vector<I::Carried_side> side;
  I::transfer_seams(proxy, pseam, full, seam, side);
  I::label_uv_vertices(full, seam);
  // a path on the surface is no shorter than the chord it follows, and not much longer
  const double carried = full.seam_length();
  BOOST_TEST(carried >= proxy_seam_length * (1 - 1e-12));
  BOOST_TEST(carried <= 1.5 * proxy_seam_length);
  // the carried paths neither touch nor share a stretch: each proxy seam
  // vertex has its seam degree in the proxy, every other seam vertex 2
  std::vector<int> degree(full.number_of_vertices(), 0), proxy_degree(pm.number_of_vertices(), 0);
  for(std::size_t h = 0; h < seam.size(); ++h)
    if(seam[h] && (full.opposite[h] < 0 || full.opposite[h] > int(h)))
    {
      ++degree[full.corner_vertex[h]];
      ++degree[full.corner_vertex[I::Cut_mesh::prev(int(h))]];
    }
  for(auto e : pm.edges())
    if(pseam[e]) { ++proxy_degree[pm.vertex(e, 0).idx()]; ++proxy_degree[pm.vertex(e, 1).idx()]; }
  std::size_t wrong_degree = 0;
  for(std::size_t v = 0; v < degree.size(); ++v)
  {
    const int p = proxy.proxy_vertex[v];
    if(p >= 0 && proxy_degree[p] > 0) wrong_degree += degree[v] != proxy_degree[p];
    else wrong_degree += degree[v] != 0 && degree[v] != 2;
  }
  BOOST_TEST(wrong_degree == 0u);
  // the cut gives as many charts as the proxy's, each a disk
  std::vector<int> chart;
  const std::size_t charts = full.compute_charts(chart);
  BOOST_TEST(charts == coarse.charts);
  const std::vector<long> chi = I::chart_euler_characteristics(chart, charts, full.corner_uv, full.number_of_uv_vertices(),
    full.opposite, [&](int h) { return full.opposite[h] < 0 || full.is_seam(h); });
  for(long x : chi) BOOST_TEST(x == 1);

  // the carried map: no flip, its border on the proxy's, and far less
  // distortion than the default initial map of the same mesh
  I::transfer_uv_map(proxy, puv, side, full);
  for(std::size_t f = 0; f < full.number_of_faces(); ++f) BOOST_REQUIRE(full.signed_uv_area2(f) > 0);
  auto uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  I::write_uv_map(full, copy, uv);
  const SMSO::Uv_map_measures carried_map = SMSO::measure_uv_map(sm, uv);
  BOOST_TEST(carried_map.overlapping_triangle_pairs == 0u);
  BOOST_TEST(std::abs(carried_map.seam_length - carried) <= 1e-9 * carried);
  auto default_seam = sm.add_property_map<edge_descriptor, bool>("e:default_seam", false).first;
  BOOST_REQUIRE(SMSO::compute_initial_parameterization(sm, default_seam, uv) == SMSO::OK);
  const SMSO::Uv_map_measures default_map = SMSO::measure_uv_map(sm, uv);
  BOOST_TEST_MESSAGE("carried map E_SD " << carried_map.distortion << ", default initial map " << default_map.distortion
                     << ", proxy result " << coarse.distortion);
  BOOST_TEST(carried_map.distortion < 0.5 * default_map.distortion);
}

BOOST_AUTO_TEST_CASE(a_mesh_above_twice_the_proxy_size_goes_through_the_proxy)
{
  Run r;
  run("cat_f1500.obj", r, SMSO_np::proxy_number_of_faces(400));
  BOOST_TEST(r.result.status == SMSO::OK);
  BOOST_TEST(r.result.proxy_faces > 0u);
  BOOST_TEST(r.result.proxy_faces <= 440u);
  BOOST_TEST(r.result.bound_met);
  BOOST_TEST(r.result.distortion <= 4.1);
  check_valid(r);
  // not for a mesh at most twice as large, nor with options the proxy cannot carry
  Run small;
  run("cat_f1500.obj", small, SMSO_np::proxy_number_of_faces(750).number_of_starts(1));
  BOOST_TEST(small.result.proxy_faces == 0u);
  Run fixed;
  run("cat_f1500.obj", fixed, SMSO_np::proxy_number_of_faces(400).seam_weight(0.1).number_of_starts(1));
  BOOST_TEST(fixed.result.proxy_faces == 0u);
}

// The fallback: bunny through a proxy of about 3333 faces (one start) comes
// back with one folded triangle that untangling cannot remove; the mesh is
// then optimized as without a proxy. (When carried maps become valid by
// construction, this case needs another way to reach the fallback.)
BOOST_AUTO_TEST_CASE(a_carried_map_that_keeps_a_fold_gives_way_to_the_direct_run)
{
  Run r;
  run("bunny_i_f10000.obj", r, SMSO_np::proxy_number_of_faces(3333).number_of_starts(1));
  BOOST_TEST(r.result.status == SMSO::OK);
  BOOST_TEST(r.result.proxy_faces == 0u);
  BOOST_TEST_MESSAGE("message: " << r.result.message);
  BOOST_TEST(r.result.message.find("folded triangles: optimized without it") != std::string::npos);
  BOOST_TEST(r.result.bound_met);
  BOOST_TEST(r.result.distortion <= 4.1);
  check_valid(r);
}
