// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// optimize_seams: command-line front end of Surface_mesh_seam_optimization.
// A thin shell: parse options (command_line.h), load, check (or repair) the mesh, call the
// library (run_optimization.h), write the OBJ, the pictures and the JSON
// report. Every failure is one line on stderr and a non-zero exit code
// (1: input or run failed, 2: bad options).

#include "command_line.h"
#include "load_mesh.h"
#include "output_files.h"
#include "picture_common.h"
#include "pictures.h"
#include "repair_input.h"
#include "run_optimization.h"

#include <CGAL/Surface_mesh_seam_optimization/Error_code.h>
#include <CGAL/Surface_mesh_seam_optimization/IO/OBJ.h>
#include <CGAL/Surface_mesh_seam_optimization/Optimization_result.h>
#include <CGAL/Surface_mesh_seam_optimization/pack_charts.h>
#include <CGAL/Surface_mesh_seam_optimization/Seam_optimization_visitor.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Defaults.h>
#include <CGAL/Surface_mesh_seam_optimization/seam_visibility.h>
#include <CGAL/Surface_mesh_seam_optimization/seams_from_uv_map.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <memory>
#endif

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>   // isatty

namespace {

using namespace optimize_seams_cli;
namespace PMP = CGAL::Polygon_mesh_processing;

enum Exit_status { EXIT_OK = 0, EXIT_RUN_FAILED = 1, EXIT_USAGE = 2 };


// ---------------------------------------------------------------------------
// Everything the run learns, for the summary line and the JSON report.

struct Run_report
{
  std::string status = "ERROR_INPUT";   // Error_code name, or a CLI-level ERROR_*
  std::string message;
  SMSO::Optimization_result result;
  Mode mode = Mode::DISTORTION_BOUND;
  double distortion_bound = default_distortion_bound;   // bound mode only
  double seam_weight = 0;                               // seam-weight mode only
  std::string seam_weights;                             // --seam-weights FILE
  bool hide_seams = false;
  SMSO::Cut_strategy cut_strategy = SMSO::OPTCUTS;
  double visible_seam_share = std::numeric_limits<double>::quiet_NaN(); // measured: null otherwise
  std::vector<std::string> notes;                       // also printed on stderr (unless --quiet)
  bool normalized = false;                              // --normalize applied to the written UVs
  bool packed = false;                                  // charts packed (--pack, or --normalize with several)
  double texture_size = 0, margin = 0, fill_rate = 0;   // of the packing
  Energy_kind energy = Energy_kind::SYMMETRIC_DIRICHLET;
  double area_weight = 0;  // the conformal energy's
  std::size_t threads = 0;                              // --threads; 0: default
  bool repair = false;                                  // --repair asked
  bool repair_done = false;                             // and reached (the file was read)
  Repair_summary repair_summary;
  std::string input, output, svg, png;                  // svg, png: written pictures
  std::size_t faces = 0, vertices = 0;
  double seconds = 0;                    // the optimization call
  double total_seconds = 0;              // reading + optimization + writing
};

void append_json_string(std::string& out, const std::string& s)
{
  out += '"';
  for(unsigned char c : s)
  {
    switch(c)
    {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if(c < 0x20)
        {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", c);
          out += buf;
        }
        else
          out += static_cast<char>(c);
    }
  }
  out += '"';
}

// JSON has no inf/nan: a figure that was never computed is null.
std::string json_number(double x, int digits = 17)
{
  if(!std::isfinite(x))
    return "null";
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.*g", digits, x);
  return buf;
}

bool write_json_report(const std::string& path, const Run_report& r)
{
  const SMSO::Optimization_result& res = r.result;
  std::vector<std::pair<std::string, std::string> > fields;
  auto str = [](const std::string& s) { std::string o; append_json_string(o, s); return o; };
  fields.emplace_back("status", str(r.status));
  fields.emplace_back("message", str(r.message));
  fields.emplace_back("input", str(r.input));
  fields.emplace_back("output", r.output.empty() ? "null" : str(r.output));
  const bool ran = res.has_result();
  fields.emplace_back("mode", str(mode_name(r.mode)));
  fields.emplace_back("faces", std::to_string(r.faces));
  fields.emplace_back("vertices", std::to_string(r.vertices));
  fields.emplace_back("e_sd", json_number(res.distortion));
  fields.emplace_back("initial_e_sd", json_number(res.initial_distortion));
  fields.emplace_back("e_sd_optimal_scale", json_number(res.distortion_at_optimal_scale));
  fields.emplace_back("energy_value", json_number(res.energy_value));
  fields.emplace_back("distortion_bound",
                      r.mode == Mode::DISTORTION_BOUND ? json_number(r.distortion_bound, 15) : "null");
  // The library's flag (on the run's energy); null where
  // there is no bound (it refers to its default bound in the other modes).
  fields.emplace_back("bound_met", r.mode != Mode::DISTORTION_BOUND || !ran
                                     ? "null"
                                     : (res.bound_met ? "true" : "false"));
  fields.emplace_back("seam_weight", r.mode == Mode::SEAM_WEIGHT ? json_number(r.seam_weight, 15) : "null");
  fields.emplace_back("lambda", r.mode == Mode::KEEP_SEAMS || !ran ? "null" : json_number(res.lambda));
  fields.emplace_back("seam_length", json_number(res.seam_length));
  fields.emplace_back("seam_length_normalized", json_number(res.seam_length_normalized));
  fields.emplace_back("weighted_seam_length_normalized", json_number(res.weighted_seam_length_normalized));
  fields.emplace_back("seam_weights", r.seam_weights.empty() ? "null" : str(r.seam_weights));
  fields.emplace_back("hide_seams", r.hide_seams ? "true" : "false");
  fields.emplace_back("cut_strategy", str(r.cut_strategy == SMSO::EBCUTS ? "ebcuts" : "optcuts"));
  fields.emplace_back("visible_seam_share", ran ? json_number(r.visible_seam_share) : "null");
  fields.emplace_back("charts", std::to_string(res.charts));
  fields.emplace_back("iterations", std::to_string(res.iterations));
  fields.emplace_back("topology_operations", std::to_string(res.topology_operations));
  // which start of optimize_seams() the result comes from (see --starts)
  fields.emplace_back("start", r.mode != Mode::DISTORTION_BOUND || !ran ? "null" : std::to_string(res.start));
  // faces of the proxy the seams were first optimized on (0: none; see --proxy-faces)
  fields.emplace_back("proxy_faces", !ran ? "null" : std::to_string(res.proxy_faces));
  fields.emplace_back("normalized", r.normalized ? "true" : "false");
  fields.emplace_back("packed", r.packed ? "true" : "false");
  fields.emplace_back("texture_size", r.packed ? json_number(r.texture_size) : "null");
  fields.emplace_back("margin", r.packed ? json_number(r.margin) : "null");
  fields.emplace_back("fill_rate", r.packed ? json_number(r.fill_rate) : "null");
  // Checked on the result (no flip, no overlapping pair), not assumed from the option.
  fields.emplace_back("bijective", !ran ? "null" : (res.bijective ? "true" : "false"));
  fields.emplace_back("overlapping_triangle_pairs", !ran ? "null" : std::to_string(res.overlapping_triangle_pairs));
  fields.emplace_back("scaffold_rebuilds", std::to_string(res.scaffold_rebuilds));
  fields.emplace_back("energy", str(energy_name(r.energy)));
  fields.emplace_back("area_weight", r.energy == Energy_kind::MIPS ? json_number(r.area_weight) : "null");
  fields.emplace_back("threads", r.threads > 0 ? std::to_string(r.threads) : "null");
  if(!r.repair)
    fields.emplace_back("repair", "null");
  else
  {
    // What the repair changed, kind by kind (null when the file could not be read).
    std::string o = "null";
    if(r.repair_done)
    {
      o = "{";
      const auto items = r.repair_summary.items();
      for(std::size_t i = 0; i < items.size(); ++i)
        o += (i ? ", " : "") + str(items[i].first) + ": " +
             (items[i].first == "reoriented" ? (items[i].second ? "true" : "false")
                                             : std::to_string(items[i].second));
      o += ", " + str("description") + ": " + str(r.repair_summary.description()) + "}";
    }
    fields.emplace_back("repair", o);
  }
  fields.emplace_back("svg", r.svg.empty() ? "null" : str(r.svg));
  fields.emplace_back("png", r.png.empty() ? "null" : str(r.png));
  {
    std::string notes = "[";
    for(std::size_t i = 0; i < r.notes.size(); ++i)
      notes += (i ? ", " : "") + str(r.notes[i]);
    fields.emplace_back("notes", notes + "]");
  }
  fields.emplace_back("seconds", json_number(r.seconds, 6));
  fields.emplace_back("total_seconds", json_number(r.total_seconds, 6));

  std::string out = "{\n";
  for(std::size_t i = 0; i < fields.size(); ++i)
  {
    out += "  ";
    append_json_string(out, fields[i].first);
    out += ": " + fields[i].second + (i + 1 < fields.size() ? ",\n" : "\n");
  }
  out += "}\n";
  return write_atomically(path, [&out](const std::string& tmp) { return write_text_file(tmp, out); });
}

// ---------------------------------------------------------------------------
// Input: load_mesh.h

// ---------------------------------------------------------------------------
// Outputs, checked before the run: a bad path is a usage error found in
// milliseconds, not after minutes of optimization.

std::string output_path(const Options& options)
{
  return options.output.empty() ? std::filesystem::path(options.input).stem().string() + "_uv.obj"
                                : options.output;
}

bool check_output_paths(const Options& options, std::string& error)
{
  const std::string output = output_path(options);
  if(lowercase_extension(output) != ".obj")
  {
    error = "option '-o' writes an OBJ (the format with per-corner UVs): '" + output +
            "' does not end in .obj";
    return false;
  }
  const std::pair<const char*, const std::string*> outputs[] = {
    {"-o", &output}, {"--report", &options.report}, {"--svg", &options.svg}, {"--png", &options.png}};
  for(std::size_t i = 0; i < 4; ++i)
  {
    const std::string& path = *outputs[i].second;
    if(path.empty())
      continue;
    if(same_file(path, options.input))
    {
      error = std::string("option '") + outputs[i].first + "' would overwrite the input '" + options.input + "'";
      return false;
    }
    for(std::size_t j = 0; j < i; ++j)
      if(!outputs[j].second->empty() && same_file(path, *outputs[j].second))
      {
        error = std::string("options '") + outputs[j].first + "' and '" + outputs[i].first +
                "' name the same file '" + path + "'";
        return false;
      }
    std::string why;
    if(!check_writable(path, why))
    {
      error = std::string("cannot write '") + path + "' (option '" + outputs[i].first + "'): " + why;
      return false;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------
// Run

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string format_double(double x, int digits)
{
  if(!std::isfinite(x))
    return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*g", digits, x);
  return buf;
}

void print_error(const std::string& line)
{
  std::cerr << program_name << ": error: " << line << std::endl;
}

// ---------------------------------------------------------------------------
// Progress on stderr, fed by the library's visitor. Each call only copies the
// library's progress figures and reads the clock; a line is printed at most
// every `interval` (about 5 a second), and `finish()` prints the last state
// if it was held back. On a terminal the line is rewritten in place ('\r');
// otherwise each state is a plain line.
class Progress_printer
{
public:
  // `label` names the energy of the descent (the figure the library reports).
  // (--time-limit is the library's time_limit named parameter, not a cancel here.)
  explicit Progress_printer(bool enabled, const char* label = "E_SD")
    : m_label(label), m_enabled(enabled), m_tty(enabled && ::isatty(STDERR_FILENO) == 1),
      m_last(std::chrono::steady_clock::now())
  {}

  // The last state (if held back), and the newline that ends the updating line.
  void finish()
  {
    if(!m_enabled)
      return;
    if(m_pending)
      print(m_state);
    if(m_tty && m_width > 0)
      std::fputc('\n', stderr);
    std::fflush(stderr);
    m_width = 0;
  }

  // Called by the library's visitor (through the request's callback); never
  // cancels the run.
  bool update(const SMSO::Seam_optimization_progress& p)
  {
    if(!m_enabled)
      return true;
    m_state = p;
    m_pending = true;
    const auto now = std::chrono::steady_clock::now();
    if(now - m_last >= interval)
    {
      m_last = now;
      print(p);
    }
    return true;
  }

private:
  void print(const SMSO::Seam_optimization_progress& p)
  {
    char line[160];
    int n = std::snprintf(line, sizeof(line), "it %zu  ops %zu  %s %.6g  E_se %.4g  lambda %.4g  t %.1f s",
                          p.iterations, p.topology_operations, m_label, p.distortion, p.seam_length_normalized,
                          p.lambda, p.seconds);
    n = std::max(0, std::min(n, int(sizeof(line)) - 1));
    if(m_tty)
    {
      // Blank out what is left of a longer previous line.
      std::fprintf(stderr, "\r%s%*s", line, m_width > n ? m_width - n : 0, "");
      m_width = std::max(m_width, n);
    }
    else
      std::fprintf(stderr, "%s\n", line);
    std::fflush(stderr);
    m_pending = false;
  }

  static constexpr std::chrono::milliseconds interval{200};
  const char* m_label;
  bool m_enabled;
  bool m_tty;
  std::chrono::steady_clock::time_point m_last;
  SMSO::Seam_optimization_progress m_state;
  bool m_pending = false;
  int m_width = 0;   // of the longest line written on the current terminal line
};

// --normalize: one scale factor for all charts and a translation, so that the
// UVs fill [0,1]^2 along their longer extent (the other starts at 0).
template <typename UVMap>
void normalize_uv_map(const Mesh& mesh, UVMap uvmap)
{
  double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  double hi[2] = {-lo[0], -lo[1]};
  for(halfedge_descriptor h : halfedges(mesh))
  {
    if(is_border(h, mesh))
      continue;
    const Point_2 p = get(uvmap, h);
    lo[0] = std::min(lo[0], p.x()); hi[0] = std::max(hi[0], p.x());
    lo[1] = std::min(lo[1], p.y()); hi[1] = std::max(hi[1], p.y());
  }
  const double extent = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  if(!(extent > 0) || !std::isfinite(extent))
    return;
  auto unit = [](double x) { return std::min(1., std::max(0., x)); };
  for(halfedge_descriptor h : halfedges(mesh))
  {
    if(is_border(h, mesh))
      continue;
    const Point_2 p = get(uvmap, h);
    // The extreme corners land exactly on 0 and 1 (x - lo is exact there).
    put(uvmap, h, Point_2(unit((p.x() - lo[0]) / extent), unit((p.y() - lo[1]) / extent)));
  }
}

// Writes the report if one was asked for; a failure to do so is an error only
// when nothing else failed (one error line per run).
int finish(const Options& options, Run_report& report, std::chrono::steady_clock::time_point t0,
           int exit_status)
{
  report.total_seconds = seconds_since(t0);
  if(!options.report.empty() && !write_json_report(options.report, report))
  {
    if(exit_status == EXIT_OK)
    {
      print_error("cannot write report '" + options.report + "'");
      return EXIT_RUN_FAILED;
    }
  }
  return exit_status;
}

int run(const Options& options)
{
  const auto t0 = std::chrono::steady_clock::now();
  Run_report report;
  report.input = options.input;
  report.mode = options.mode();
  report.distortion_bound = options.bound();
  report.seam_weight = options.seam_weight;
  report.energy = options.energy;
  report.area_weight = options.area_weight;
  report.threads = options.threads;
  report.repair = options.repair;
  report.seam_weights = options.seam_weights;
  report.hide_seams = options.hide_seams;
  report.cut_strategy = options.cut_strategy;

#ifdef CGAL_LINKED_WITH_TBB
  // Caps TBB's workers for the whole run (the parallel candidate scoring).
  std::unique_ptr<tbb::global_control> thread_cap;
  if(options.threads > 0)
    thread_cap = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                       options.threads);
#endif

  // Notes are printed only with the summary, so that a failure is exactly one line.
  std::vector<std::string> notes;

  Mesh mesh;
  UV_map uvmap;
  Load_failure failure;
  bool loaded = false;
  std::vector<std::size_t> file_vertex; // --seam-weights: file vertex -> mesh vertex
  if(options.use_input_uv)
  {
    uvmap = mesh.add_property_map<halfedge_descriptor, Point_2>("h:smso_uv", Point_2(0, 0)).first;
    loaded = load_mesh_with_uv_map(options.input, mesh, uvmap, failure);
  }
  else
    loaded = load_mesh(options.input, mesh, notes, failure, options.repair ? &report.repair_summary : nullptr,
                       &file_vertex);
  if(loaded && options.use_input_uv)
    for(std::size_t i = 0; i < num_vertices(mesh); ++i) // the OBJ reader keeps every vertex, in order
      file_vertex.push_back(i);
  if(!loaded)
  {
    report.status = failure.status;
    report.message = failure.line;
    print_error(failure.line);
    return finish(options, report, t0, EXIT_RUN_FAILED);
  }
  report.repair_done = options.repair;
  for(const std::string& n : notes)
    report.notes.push_back(n);
  report.faces = num_faces(mesh);
  report.vertices = num_vertices(mesh);
  // What the repair did is worth seeing before a long run: printed now.
  if(options.repair && !options.quiet)
    std::cerr << program_name << ": repair: " << report.repair_summary.description() << std::endl;

  if(!options.use_input_uv)
    uvmap = mesh.add_property_map<halfedge_descriptor, Point_2>("h:smso_uv", Point_2(0, 0)).first;
  Seam_map seams = mesh.add_property_map<edge_descriptor, bool>("e:smso_seam", false).first;
  // (the library's tolerance: a UV written with a few digits is not a seam)
  if(options.use_input_uv)
    SMSO::seams_from_uv_map(mesh, uvmap, seams);

  const char* const progress_label[] = {"E_SD", "E_arap", "E_conf"};
  Progress_printer progress(!options.quiet, progress_label[static_cast<int>(options.energy)]);
  Optimization_request request;
  request.mode = report.mode;
  request.energy = options.energy;
  request.area_weight = options.area_weight;
  request.distortion_bound = options.bound();
  request.seam_weight = options.seam_weight;
  request.use_input_uv = options.use_input_uv;
  request.bijective = !options.no_bijectivity;
  request.iteration_cap = options.iteration_cap();
  request.recut_rounds = int(options.recut_rounds);
  request.cut_strategy = options.cut_strategy;
  request.starts = int(options.starts);
  request.proxy_faces = options.proxy_faces;
  request.time_limit = options.time_limit;
  request.vertex_seam_cost = mesh.add_property_map<vertex_descriptor, double>("v:smso_seam_cost", 1.).first;
  request.edge_seam_cost = mesh.add_property_map<edge_descriptor, double>("e:smso_seam_cost", 1.).first;
  if(!options.seam_weights.empty())
  {
    Seam_weights_form form;
    std::string error;
    if(!read_seam_weights(options.seam_weights, mesh, file_vertex, options.region_seam_cost,
                          options.has_region_seam_cost, request.vertex_seam_cost, request.edge_seam_cost, form,
                          error))
    {
      report.status = "ERROR_INPUT";
      report.message = error;
      print_error(error);
      return finish(options, report, t0, EXIT_RUN_FAILED);
    }
  }
  // Visibility of each edge, for --hide-seams' costs and the visible share.
  Edge_cost_map visibility;
  if(options.hide_seams || options.measure_visibility)
  {
    visibility = mesh.add_property_map<edge_descriptor, double>("e:smso_visibility", 1.).first;
    SMSO::edge_visibility(mesh, visibility);
  }
  if(options.hide_seams)
  {
    Edge_cost_map hiding = mesh.add_property_map<edge_descriptor, double>("e:smso_hiding_cost", 1.).first;
    SMSO::internal::seam_costs_from_visibility_ranks(mesh, visibility, hiding, default_visibility_cost_ratio);
    for(edge_descriptor e : edges(mesh))
      put(request.edge_seam_cost, e, get(request.edge_seam_cost, e) * get(hiding, e));
  }
  request.progress = [&progress](const SMSO::Seam_optimization_progress& p) { return progress.update(p); };

  const auto t_opt = std::chrono::steady_clock::now();
  report.result = run_optimization(mesh, uvmap, seams, request);
  report.seconds = seconds_since(t_opt);
  progress.finish();
  const SMSO::Optimization_result& res = report.result;
  report.status = SMSO::get_error_code_name(res.status);
  report.message = res.message;
  if(res.status == SMSO::WARNING_TIME_LIMIT)
  {
    const std::string n = "time limit of " + format_double(options.time_limit, 6) +
                          " s reached: best result so far (after " + std::to_string(res.iterations) +
                          " iterations)";
    notes.push_back(n);
    report.notes.push_back(n);
  }
  // (an untangled --use-input-uv map; a warning prints its message anyway)
  if(res.status == SMSO::OK && !res.message.empty())
  {
    notes.push_back(res.message);
    report.notes.push_back(res.message);
  }

  if(res.has_result() && (options.hide_seams || options.measure_visibility))
    report.visible_seam_share = SMSO::seam_share_on_most_visible_edges(mesh, visibility, seams, 0.25);
  if(!res.has_result())
  {
    std::string line = SMSO::get_error_message(res.status);
    if(!res.message.empty())
      line += ": " + res.message;
    print_error(line);
    return finish(options, report, t0, EXIT_RUN_FAILED);
  }
  if(!res.bijective)
  {
    const std::string n = "the UV map is not bijective: " + std::to_string(res.overlapping_triangle_pairs) +
                          " overlapping triangle pairs" +
                          (report.mode == Mode::KEEP_SEAMS ? " (--keep-seams has no scaffold)"
                           : options.no_bijectivity ? " (--no-bijectivity)" : "");
    notes.push_back(n);
    report.notes.push_back(n);
  }

  // The pictures use the map at its own scale (per-triangle distortion): keep
  // a copy when --normalize rescales it for the OBJ.
  UV_map picture_uvmap = uvmap;
  if(options.normalize || options.pack)
  {
    if(!options.svg.empty() || !options.png.empty())
    {
      picture_uvmap = mesh.add_property_map<halfedge_descriptor, Point_2>("h:smso_picture_uv").first;
      for(halfedge_descriptor h : halfedges(mesh))
        put(picture_uvmap, h, get(uvmap, h));
    }
    // several charts: packed, or a uniform scale could leave them overlapping
    if(options.pack || res.charts > 1)
    {
      namespace SMSO_np = SMSO::parameters;
      const SMSO::Chart_packing_result packing = SMSO::pack_charts(
        mesh, uvmap, SMSO_np::combine(SMSO_np::texture_size(options.texture_size), SMSO_np::margin(options.margin)));
      if(!packing.has_result())
      {
        report.status = SMSO::get_error_code_name(packing.status);
        report.message = "cannot pack the charts: " + packing.message;
        print_error(report.message);
        return finish(options, report, t0, EXIT_RUN_FAILED);
      }
      report.packed = true;
      report.texture_size = options.texture_size;
      report.margin = options.margin;
      report.fill_rate = packing.fill_rate;
    }
    else
      normalize_uv_map(mesh, uvmap);
    report.normalized = options.normalize;
  }

  report.output = output_path(options);
  if(!write_atomically(report.output, [&](const std::string& tmp) {
       return SMSO::IO::write_OBJ_with_uv_map(tmp, mesh, uvmap);
     }))
  {
    const std::string out = report.output;
    report.output.clear();
    report.status = "ERROR_OUTPUT";
    report.message = "cannot write '" + out + "'";
    print_error(report.message);
    return finish(options, report, t0, EXIT_RUN_FAILED);
  }

  Picture_caption caption;
  caption.title = std::filesystem::path(options.input).filename().string();
  caption.e_sd = res.distortion;
  if(report.mode == Mode::DISTORTION_BOUND)
    caption.distortion_bound = options.bound();
  caption.seam_length_normalized = res.seam_length_normalized;
  caption.charts = res.charts;
  if(options.energy != Energy_kind::SYMMETRIC_DIRICHLET)
    caption.energy = energy_name(options.energy);
  if(!options.svg.empty())
  {
    if(!write_atomically(options.svg, [&](const std::string& tmp) {
         return write_uv_layout_svg_file(tmp, mesh, picture_uvmap, seams, caption);
       }))
    {
      report.status = "ERROR_OUTPUT";
      report.message = "cannot write '" + options.svg + "'";
      print_error(report.message);
      return finish(options, report, t0, EXIT_RUN_FAILED);
    }
    report.svg = options.svg;
  }
  if(!options.png.empty())
  {
    std::string error;
    if(!write_atomically(options.png, [&](const std::string& tmp) {
         return render_png_file(tmp, mesh, picture_uvmap, seams, error);
       }))
    {
      if(error.empty() || error.find(".tmp-") != std::string::npos)
        error = "cannot write '" + options.png + "'";
      report.status = "ERROR_OUTPUT";
      report.message = error;
      print_error(error);
      return finish(options, report, t0, EXIT_RUN_FAILED);
    }
    report.png = options.png;
  }

  if(!options.quiet)
  {
    for(const std::string& n : notes)
      std::cerr << program_name << ": note: " << n << std::endl;
    if(res.status != SMSO::OK)
      std::cerr << program_name << ": warning: " << SMSO::get_error_message(res.status)
                << (res.message.empty() ? "" : ": " + res.message) << std::endl;
    std::ostringstream what;
    what << "E_SD " << format_double(res.initial_distortion, 6) << " -> " << format_double(res.distortion, 6);
    if(std::abs(res.distortion_at_optimal_scale - res.distortion) > 1e-6 * res.distortion)
      what << " (" << format_double(res.distortion_at_optimal_scale, 6) << " at the optimal scale)";
    // the bound is on the run's energy
    if(options.energy != Energy_kind::SYMMETRIC_DIRICHLET)
      what << ", energy " << energy_name(options.energy) << " " << format_double(res.energy_value, 6);
    if(report.mode == Mode::DISTORTION_BOUND)
      what << " (bound " << format_double(options.bound(), 6) << (res.bound_met ? ", met)" : ", NOT met)");
    if(report.mode != Mode::KEEP_SEAMS)
      what << ", lambda " << format_double(res.lambda, 4) << ", " << res.topology_operations
           << " topology operations";
    what << ", " << res.iterations << " iterations (" << format_double(report.seconds, 3)
         << " s), normalized seam length " << format_double(res.seam_length_normalized, 4);
    std::string written = report.output;
    for(const std::string* extra : {&report.svg, &report.png})
      if(!extra->empty())
        written += ", " + *extra;
    std::cerr << program_name << ": "
              << std::filesystem::path(options.input).filename().string() << ": "
              << report.faces << " faces, " << res.charts << (res.charts == 1 ? " chart" : " charts")
              << ", " << what.str() << "; wrote " << written << std::endl;
  }
  return finish(options, report, t0, EXIT_OK);
}

} // namespace

int main(int argc, char* argv[])
{
  // Nothing may escape as an uncaught exception: a crash is never an answer.
  try
  {
    Options options;
    std::string error;
    switch(parse_options(argc, argv, options, error))
    {
      case Parse_status::HELP:
        print_help(std::cout);
        return EXIT_OK;
      case Parse_status::ERROR:
        print_error(error + " (see --help)");
        return EXIT_USAGE;
      case Parse_status::RUN:
        break;
    }
    if(!check_output_paths(options, error))
    {
      print_error(error);
      return EXIT_USAGE;
    }
    return run(options);
  }
  catch(const std::bad_alloc&)
  {
    print_error("out of memory");
  }
  catch(const std::exception& e)
  {
    std::string what = e.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    print_error("internal error: " + what);
  }
  catch(...)
  {
    print_error("internal error: unknown exception");
  }
  return EXIT_RUN_FAILED;
}
