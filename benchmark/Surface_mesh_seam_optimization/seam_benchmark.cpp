// Runs optimize_seams() (OptCuts: seams + UV map under a distortion bound) on
// each mesh given, writes DIR/<name>.obj with the UVs, and prints one CSV line
// per mesh:
//   mesh,faces,seconds,iterations,topology_operations,e_sd,seam_length_normalized,
//   charts,flipped_triangles,peak_mb,status,bound_met,lambda,initial_map_seconds,
//   overlapping_pairs,scaffold_rebuilds,t_assembly,t_factorization,t_symbolic,
//   t_line_search,t_topology,t_scaffold,start
// (t_*: Optimization_result::timings, seconds by phase; start: the start whose
// result was kept, Optimization_result::start).
// seconds: wall time of the optimize_seams() call (reading and writing excluded).
// peak_mb: getrusage(RUSAGE_SELF).ru_maxrss of the whole process so far, so run
// one mesh per process to get a per-mesh figure (run_benchmark.sh does).
// A mesh that cannot be read or that optimize_seams() rejects (not a disk,
// not manifold, ...) gives a line with its status, not a failure; the exit
// code is non-zero only for a wrong command line.
// --time-limit S: a visitor cancels the run past S seconds; the best result so
// far is written and the status is WARNING_CANCELLED.
// --distortion-only: minimize_distortion() with the seams of the initial map
// (none for a disk) instead of optimize_seams(): the descent step alone, from
// its default start (the initial map, or from 16000 faces coarser meshes'
// maps); seconds is the whole call, initial map included, and
// initial_map_seconds the initial map (compute_initial_parameterization())
// alone, timed before it.
// --no-bijectivity: bijective(false) (no scaffold; charts may overlap).
// --solver ldlt|cholmod: Eigen_simplicial_ldlt_traits or Cholmod_traits (when the
// package is built with CHOLMOD) instead of the default Default_sparse_solver_traits.
//
// Usage: seam_benchmark [--bound B] [--out-dir DIR] [--max-iterations N] [--recut-rounds N] [--starts N] [--proxy-faces N] [--time-limit S]
//                       [--distortion-only] [--no-bijectivity] [--solver default|ldlt|cholmod] [--no-header] mesh.obj ...
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_seam_optimization/IO/OBJ.h>
#include <CGAL/Surface_mesh_seam_optimization/initial_parameterization.h>
#include <CGAL/Surface_mesh_seam_optimization/measure.h>
#include <CGAL/Surface_mesh_seam_optimization/minimize_distortion.h>
#include <CGAL/Surface_mesh_seam_optimization/optimize_seams.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <new>
#include <string>
#include <type_traits>
#include <vector>

#include <sys/resource.h>

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Surface_mesh;
namespace SMSO = CGAL::Surface_mesh_seam_optimization;
namespace SMSO_np = CGAL::Surface_mesh_seam_optimization::parameters;

static double peak_mb()
{
  struct rusage ru;
  if(getrusage(RUSAGE_SELF, &ru) != 0) return -1;
  return double(ru.ru_maxrss) / 1024.; // kilobytes on Linux
}

// Cancels the run once `limit` seconds have passed since `start`.
struct Time_limit_visitor : public SMSO::Default_seam_optimization_visitor
{
  std::chrono::steady_clock::time_point start;
  double limit;

  Time_limit_visitor(std::chrono::steady_clock::time_point start, double limit) : start(start), limit(limit) {}
  bool in_time() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < limit;
  }
  bool on_iteration(const SMSO::Seam_optimization_progress&) { return in_time(); }
  bool on_topology_operation(const SMSO::Seam_optimization_progress&) { return in_time(); }
  bool on_lambda_update(const SMSO::Seam_optimization_progress&) { return in_time(); }
};

struct Settings
{
  double bound = 4.1;
  std::size_t max_iterations = 100000;
  int recut_rounds = 6;
  int starts = 2;
  std::size_t proxy_faces = SMSO::internal::default_proxy_number_of_faces;
  double time_limit = 0; // seconds; 0: none
  bool distortion_only = false;
  bool bijective = true;
  std::string solver = "default"; // default (Default_sparse_solver_traits), ldlt or cholmod
  std::string out_dir = ".";
};

struct Row
{
  std::string name;
  std::size_t faces = 0;
  double seconds = 0, initial_map_seconds = -1; // -1: not timed apart
  std::size_t iterations = 0, topology_operations = 0, charts = 0, flips = 0;
  double e_sd = 0, seam = 0, lambda = 0;
  bool bound_met = false, has_result = false, timed_only = false;
  std::size_t overlaps = 0, scaffold_rebuilds = 0;
  int start = -1; // Optimization_result::start (-1: no result)
  SMSO::Optimization_timings timings;
  std::string status = "ERROR_UNKNOWN";
};

static void print(const Row& r)
{
  if(!r.has_result) // rejected or unreadable: the figures are left empty
  {
    if(r.timed_only) // iterations and times only
    {
      const SMSO::Optimization_timings& t = r.timings;
      std::printf("%s,%zu,%.3f,%zu,,,,,,%.1f,%s,,,", r.name.c_str(), r.faces, r.seconds, r.iterations, peak_mb(),
                  r.status.c_str());
      if(r.initial_map_seconds >= 0) std::printf("%.3f", r.initial_map_seconds);
      std::printf(",,,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f\n", t.assembly, t.factorization, t.symbolic_analysis, t.line_search,
                  t.topology, t.scaffold);
    }
    else
      std::printf("%s,%zu,%.3f,,,,,,,%.1f,%s,,,,,,,,,,,\n", r.name.c_str(), r.faces, r.seconds, peak_mb(), r.status.c_str());
    std::fflush(stdout);
    return;
  }
  std::printf("%s,%zu,%.3f,%zu,%zu,%.6f,%.6f,%zu,%zu,%.1f,%s,%d,%.6g,", r.name.c_str(), r.faces, r.seconds,
              r.iterations, r.topology_operations, r.e_sd, r.seam, r.charts, r.flips, peak_mb(), r.status.c_str(),
              int(r.bound_met), r.lambda);
  if(r.initial_map_seconds >= 0) std::printf("%.3f", r.initial_map_seconds);
  const SMSO::Optimization_timings& t = r.timings;
  std::printf(",%zu,%zu,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,", r.overlaps, r.scaffold_rebuilds, t.assembly, t.factorization,
              t.symbolic_analysis, t.line_search, t.topology, t.scaffold);
  if(r.start >= 0) std::printf("%d", r.start);
  std::printf("\n");
  std::fflush(stdout);
}

template <typename SolverTraits>
static SMSO::Optimization_result optimize(const Surface_mesh& sm,
                                          Surface_mesh::Property_map<Surface_mesh::Halfedge_index, K::Point_2> uv,
                                          Surface_mesh::Property_map<Surface_mesh::Edge_index, bool> seams,
                                          const Settings& settings, Time_limit_visitor& visitor)
{
  const auto common = SMSO_np::combine(SMSO_np::distortion_bound(settings.bound),
                                       SMSO_np::number_of_iterations(settings.max_iterations),
                                       SMSO_np::number_of_recut_rounds(settings.recut_rounds),
                                       SMSO_np::proxy_number_of_faces(settings.proxy_faces),
                                       SMSO_np::edge_is_seam_map(seams));
  auto run = [&](const auto& np) {
    if(settings.distortion_only)
      return SMSO::minimize_distortion(sm, uv, np);
    return SMSO::optimize_seams(sm, uv, SMSO_np::combine(np, SMSO_np::bijective(settings.bijective),
                                                         SMSO_np::number_of_starts(settings.starts),
                                                         SMSO_np::visitor(std::ref(visitor))));
  };
  // The default solver is not passed: the two starts then get a solver each
  // and run side by side, as for a user who does not choose one (copies of a
  // given solver share its factorization, so its starts take turns).
  if constexpr(std::is_same_v<SolverTraits, SMSO::Default_sparse_solver_traits>)
    return run(common);
  else
    return run(SMSO_np::combine(common, SMSO_np::sparse_linear_solver(SolverTraits())));
}

static Row run(const std::string& file, const Settings& settings)
{
  Row row;
  row.name = std::filesystem::path(file).stem().string();
  Surface_mesh sm;
  if(!CGAL::IO::read_polygon_mesh(file, sm) || is_empty(sm))
  {
    row.status = "ERROR_READ";
    return row;
  }
  row.faces = sm.number_of_faces();
  auto uv = sm.add_property_map<Surface_mesh::Halfedge_index, K::Point_2>("h:uv").first;
  auto seams = sm.add_property_map<Surface_mesh::Edge_index, bool>("e:seam", false).first;

  if(settings.distortion_only)
  {
    const auto start = std::chrono::steady_clock::now();
    const SMSO::Error_code ec = SMSO::compute_initial_parameterization(sm, seams, uv);
    row.initial_map_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(ec != SMSO::OK)
    {
      row.status = SMSO::get_error_code_name(ec);
      return row;
    }
  }
  const auto start = std::chrono::steady_clock::now();
  Time_limit_visitor visitor(start, settings.time_limit > 0 ? settings.time_limit : 1e300);
#ifdef CGAL_SMSO_HAS_CHOLMOD
  const SMSO::Optimization_result r = settings.solver == "cholmod"
    ? optimize<SMSO::Cholmod_traits>(sm, uv, seams, settings, visitor)
    : settings.solver == "ldlt" ? optimize<SMSO::Eigen_simplicial_ldlt_traits>(sm, uv, seams, settings, visitor)
                                : optimize<SMSO::Default_sparse_solver_traits>(sm, uv, seams, settings, visitor);
#else
  const SMSO::Optimization_result r = settings.solver == "ldlt"
    ? optimize<SMSO::Eigen_simplicial_ldlt_traits>(sm, uv, seams, settings, visitor)
    : optimize<SMSO::Default_sparse_solver_traits>(sm, uv, seams, settings, visitor);
#endif
  row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  row.status = SMSO::get_error_code_name(r.status);
  if(!r.message.empty()) std::cerr << row.name << ": " << r.message << "\n";
  if(!r.has_result())
  {
    // a capped descent whose map still has a tiny triangle: no result, but its
    // iterations were timed (the scaling benchmark's seconds per iteration)
    if(r.status == SMSO::ERROR_DEGENERATE_UV_RESULT && r.iterations > 0)
    {
      row.timed_only = true;
      row.iterations = r.iterations;
      row.timings = r.timings;
    }
    return row;
  }
  row.has_result = true;
  row.iterations = r.iterations;
  row.topology_operations = r.topology_operations;
  row.e_sd = r.distortion;
  row.seam = r.seam_length_normalized;
  row.charts = r.charts;
  row.lambda = r.lambda;
  row.bound_met = r.bound_met;
  row.overlaps = r.overlapping_triangle_pairs;
  row.scaffold_rebuilds = r.scaffold_rebuilds;
  row.start = int(r.start);
  row.timings = r.timings;
  const SMSO::Uv_map_measures m = SMSO::measure_uv_map(sm, uv);
  row.flips = m.flipped_triangles;
  if(!settings.out_dir.empty())
  {
    const std::string out = (std::filesystem::path(settings.out_dir) / (row.name + ".obj")).string();
    if(!SMSO::IO::write_OBJ_with_uv_map(out, sm, uv))
    {
      std::cerr << row.name << ": cannot write " << out << "\n";
      row.status = "ERROR_WRITE";
    }
  }
  return row;
}

static int usage(const char* argv0)
{
  std::cerr << "usage: " << argv0
            << " [--bound B] [--out-dir DIR] [--max-iterations N] [--recut-rounds N] [--starts N] [--proxy-faces N] [--time-limit S] [--distortion-only]"
               " [--solver S]"
               " [--no-bijectivity] [--no-header] mesh.obj ...\n"
               "  --bound B           distortion bound on E_SD (default 4.1)\n"
               "  --out-dir DIR       write DIR/<name>.obj with UVs (default: current directory)\n"
               "  --max-iterations N  cap on Newton iterations (default 100000)\n"
               "  --recut-rounds N    number_of_recut_rounds(N) (default 6; 0: none)\n"
               "  --starts N          number_of_starts(N): 1, 2 (default), 3 or 4\n"
               "  --proxy-faces N     proxy_number_of_faces(N): seams of meshes above 2N faces first on a proxy\n"
               "  --time-limit S      cancel optimize_seams() past S seconds (status WARNING_CANCELLED)\n"
               "  --distortion-only   minimize_distortion() with the initial seams instead of optimize_seams()\n"
               "  --no-bijectivity    no scaffold: charts may overlap\n"
               "  --solver S          default (Default_sparse_solver_traits: SimplicialLDLT, CHOLMOD supernodal from 40000 unknowns),\n"
               "                      ldlt (Eigen SimplicialLDLT) or cholmod (Cholmod_traits, if built with it)\n"
               "  --no-header         do not print the CSV header line\n";
  return EXIT_FAILURE;
}

int main(int argc, char** argv)
{
  Settings settings;
  bool header = true;
  std::vector<std::string> files;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--bound" && i + 1 < argc) settings.bound = std::atof(argv[++i]);
    else if(a == "--out-dir" && i + 1 < argc) settings.out_dir = argv[++i];
    else if(a == "--max-iterations" && i + 1 < argc) settings.max_iterations = std::strtoull(argv[++i], nullptr, 10);
    else if(a == "--recut-rounds" && i + 1 < argc) settings.recut_rounds = std::atoi(argv[++i]);
    else if(a == "--starts" && i + 1 < argc) settings.starts = std::atoi(argv[++i]);
    else if(a == "--proxy-faces" && i + 1 < argc) settings.proxy_faces = std::size_t(std::atol(argv[++i]));
    else if(a == "--time-limit" && i + 1 < argc)
    {
      settings.time_limit = std::atof(argv[++i]);
      if(!(settings.time_limit > 0)) return usage(argv[0]);
    }
    else if(a == "--distortion-only") settings.distortion_only = true;
    else if(a == "--no-bijectivity") settings.bijective = false;
    else if(a == "--solver" && i + 1 < argc)
    {
      settings.solver = argv[++i];
#ifndef CGAL_SMSO_HAS_CHOLMOD
      if(settings.solver == "cholmod") { std::cerr << "built without CHOLMOD\n"; return EXIT_FAILURE; }
#endif
      if(settings.solver != "cholmod" && settings.solver != "ldlt" && settings.solver != "default") return usage(argv[0]);
    }
    else if(a == "--no-header") header = false;
    else if(a == "-h" || a == "--help") { usage(argv[0]); return EXIT_SUCCESS; }
    else if(!a.empty() && a[0] == '-') return usage(argv[0]);
    else files.push_back(a);
  }
  if(files.empty()) return usage(argv[0]);
  if(!settings.out_dir.empty())
  {
    std::error_code ec;
    std::filesystem::create_directories(settings.out_dir, ec);
  }

  if(header)
    std::printf("mesh,faces,seconds,iterations,topology_operations,e_sd,seam_length_normalized,charts,"
                "flipped_triangles,peak_mb,status,bound_met,lambda,initial_map_seconds,overlapping_pairs,scaffold_rebuilds,"
                "t_assembly,t_factorization,t_symbolic,t_line_search,t_topology,t_scaffold,start\n");
  for(const std::string& file : files)
  {
    Row row;
    try
    {
      row = run(file, settings);
    }
    catch(const std::bad_alloc&)
    {
      row.name = std::filesystem::path(file).stem().string();
      row.status = "ERROR_OUT_OF_MEMORY";
    }
    catch(const std::exception& e)
    {
      row.name = std::filesystem::path(file).stem().string();
      row.status = "ERROR_EXCEPTION";
      std::cerr << row.name << ": " << e.what() << "\n";
    }
    print(row);
  }
  return EXIT_SUCCESS;
}
