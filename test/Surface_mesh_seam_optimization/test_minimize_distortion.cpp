// Distortion-only mode (fixed seams) on real meshes: the figures of the
// paper's code, no flipped triangle, nothing but the UVs changed.
#define BOOST_TEST_MODULE minimize_distortion
#include <boost/test/unit_test.hpp>

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>

#include <boost/property_map/property_map.hpp>

#include <map>
#include <string>

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2 Point_2;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef Surface_mesh::Halfedge_index halfedge_descriptor;
typedef Surface_mesh::Edge_index edge_descriptor;

namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace SMSO_np = CGAL::Surface_mesh_seam_optimization::parameters;

namespace {

template <typename Mesh>
Mesh read_mesh(const std::string& name)
{
  Mesh m;
  BOOST_REQUIRE(CGAL::IO::read_polygon_mesh(std::string(SMSO_DATA_DIR) + "/" + name, m));
  return m;
}

// The paper's code, distortion-only mode, on this kind of machine (issue 2).
void check_reference(const std::string& name, double reference_e_sd)
{
  Surface_mesh sm = read_mesh<Surface_mesh>(name);
  auto uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  auto seam = sm.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  const SMSO::Optimization_result r = SMSO::minimize_distortion(sm, uv, SMSO_np::edge_is_seam_map(seam));
  BOOST_TEST_MESSAGE(name << ": E_SD " << r.distortion << " (reference " << reference_e_sd << "), "
                     << r.iterations << " iterations, " << r.seconds << " s");
  BOOST_TEST(r.status == SMSO::OK);
  BOOST_TEST(r.initial_distortion > r.distortion);
  BOOST_TEST(std::abs(r.distortion - reference_e_sd) <= 0.005 * reference_e_sd);
  BOOST_TEST(r.charts == 1u);
  BOOST_TEST(r.seam_length == 0.); // a disk keeps its (empty) seams
  BOOST_TEST(!r.bound_met);         // a disk without cuts cannot reach 4.1

  // An independent measure of the written map agrees with the result.
  const SMSO::Uv_map_measures m = SMSO::measure_uv_map(sm, uv);
  BOOST_TEST(m.status == SMSO::OK);
  BOOST_TEST(m.flipped_triangles == 0u);
  BOOST_TEST(std::abs(m.distortion - r.distortion) <= 1e-9 * r.distortion);
  BOOST_TEST(m.charts == 1u);
  for(auto e : sm.edges()) BOOST_REQUIRE(!seam[e]);
}

} // namespace

BOOST_AUTO_TEST_CASE(bimba_reaches_the_reference_distortion)
{
  check_reference("bimba_i_f10000.obj", 7.644);
}

BOOST_AUTO_TEST_CASE(bunny_reaches_the_reference_distortion)
{
  check_reference("bunny_i_f10000.obj", 7.512);
}

BOOST_AUTO_TEST_CASE(polyhedron_and_surface_mesh_give_the_same_map)
{
  Surface_mesh sm = read_mesh<Surface_mesh>("bishop_part_f1000.obj");
  Polyhedron poly = read_mesh<Polyhedron>("bishop_part_f1000.obj");
  auto uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  typedef boost::graph_traits<Polyhedron>::halfedge_descriptor P_halfedge;
  std::map<P_halfedge, Point_2> storage;
  boost::associative_property_map<std::map<P_halfedge, Point_2> > puv(storage);
  const auto a = SMSO::minimize_distortion(sm, uv);
  const auto b = SMSO::minimize_distortion(poly, puv);
  BOOST_TEST(a.status == SMSO::OK);
  BOOST_TEST(b.status == SMSO::OK);
  BOOST_TEST(std::abs(a.distortion - b.distortion) <= 1e-9 * a.distortion);
  BOOST_TEST(a.iterations == b.iterations);
  BOOST_TEST(SMSO::number_of_flipped_triangles(poly, puv) == 0u);
  BOOST_TEST(storage.size() == 3 * num_faces(poly));
}

BOOST_AUTO_TEST_CASE(restarting_from_the_result_changes_nothing_and_the_cap_is_honoured)
{
  Surface_mesh sm = read_mesh<Surface_mesh>("bishop_part_f1000.obj");
  auto uv = sm.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  const auto first = SMSO::minimize_distortion(sm, uv);
  BOOST_REQUIRE(first.status == SMSO::OK);
  // Starting from the optimum (use_uv_map_as_initial): already stationary.
  const auto again = SMSO::minimize_distortion(sm, uv, SMSO_np::use_uv_map_as_initial(true));
  BOOST_TEST(again.status == SMSO::OK);
  BOOST_TEST(again.distortion <= first.distortion * (1 + 1e-9));
  BOOST_TEST(again.iterations <= 3u);

  Surface_mesh sm2 = read_mesh<Surface_mesh>("bishop_part_f1000.obj");
  auto uv2 = sm2.add_property_map<halfedge_descriptor, Point_2>("h:uv").first;
  const auto capped = SMSO::minimize_distortion(sm2, uv2, SMSO_np::maximum_number_of_iterations(std::size_t(2)));
  BOOST_TEST(capped.status == SMSO::WARNING_MAXIMUM_ITERATIONS);
  BOOST_TEST(capped.has_result());
  BOOST_TEST(capped.iterations == 2u);
  BOOST_TEST(capped.distortion > first.distortion);
  BOOST_TEST(SMSO::number_of_flipped_triangles(sm2, uv2) == 0u);
}
