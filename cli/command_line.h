// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// optimize_seams' command line: the options, their defaults (the library's),
// the help, and the parser (Boost.Program_options for the syntax, the checks
// of each value here).

#ifndef SMSO_CLI_COMMAND_LINE_H
#define SMSO_CLI_COMMAND_LINE_H

#include "pictures.h"
#include "run_optimization.h"
#include "seam_weights.h"

#include <CGAL/Surface_mesh_seam_optimization/ARAP_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/Conformal_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/Symmetric_Dirichlet_energy.h>
#include <CGAL/Surface_mesh_seam_optimization/internal/Defaults.h>
#include <CGAL/Surface_mesh_seam_optimization/pack_charts.h>

#include <boost/program_options.hpp>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace optimize_seams_cli {

const char* const program_name = "optimize_seams";

// The option that collects INPUT (not to be typed: reported as unknown).
const char* const positional_name = "INPUT";

// The library's defaults (internal/Defaults.h, Packing_settings), so that
// --help states them and the cap in force is always passed to the library.
const std::size_t default_max_iterations_seams = SMSO::internal::default_number_of_iterations;       // optimize_seams()
const std::size_t default_max_iterations_keep =
  SMSO::internal::default_number_of_iterations_distortion_only;                                     // minimize_distortion()
const std::size_t default_recut_rounds = std::size_t(SMSO::internal::default_number_of_recut_rounds);
const std::size_t default_starts = std::size_t(SMSO::internal::default_number_of_starts);
const double default_distortion_bound = SMSO::internal::default_distortion_bound;
const double default_texture_size = SMSO::internal::Packing_settings().texture_size;
const double default_margin = SMSO::internal::Packing_settings().margin;

inline const char* mode_name(Mode m)
{
  switch(m)
  {
    case Mode::DISTORTION_BOUND: return "distortion-bound";
    case Mode::SEAM_WEIGHT: return "seam-weight";
    case Mode::KEEP_SEAMS: return "keep-seams";
  }
  return "unknown";
}

// --energy names, in the order of Energy_kind.
const char* const energy_names[] = {"symmetric_dirichlet", "arap", "conformal"};
// Each energy's minimum and default bound (the library's default_bound()).
const double energy_minimum[] = {SMSO::Symmetric_Dirichlet_energy::minimum_value(), SMSO::ARAP_energy::minimum_value(),
                                 SMSO::Conformal_energy::minimum_value()};
inline double energy_default_bound(Energy_kind e, double area_weight)
{
  switch(e)
  {
    case Energy_kind::ARAP: return SMSO::ARAP_energy::default_bound();
    case Energy_kind::MIPS: return SMSO::Conformal_energy(area_weight).default_bound();
    case Energy_kind::SYMMETRIC_DIRICHLET: break;
  }
  return SMSO::Symmetric_Dirichlet_energy::default_bound();
}

inline const char* energy_name(Energy_kind e) { return energy_names[static_cast<int>(e)]; }

inline bool parse_energy(const std::string& s, Energy_kind& e)
{
  for(int i = 0; i < 3; ++i)
    if(s == energy_names[i] || (i == 2 && s == "mips")) // "mips": the former name
    {
      e = static_cast<Energy_kind>(i);
      return true;
    }
  return false;
}


// ---------------------------------------------------------------------------
// Options

struct Options
{
  std::string input;
  std::string output;          // empty: INPUT stem + "_uv.obj" in the current directory
  std::string report;          // empty: no JSON report
  bool keep_seams = false;
  bool quiet = false;
  bool no_bijectivity = false;            // bijective(false): no scaffold, charts may overlap
  bool has_distortion_bound = false;
  double distortion_bound = default_distortion_bound;
  bool has_seam_weight = false;
  double seam_weight = 0;
  bool has_max_iterations = false;
  std::size_t max_iterations = 0;         // meaningful only with has_max_iterations
  bool has_recut_rounds = false;
  std::size_t recut_rounds = default_recut_rounds; // bound mode only
  bool has_starts = false;
  std::size_t starts = default_starts;    // bound mode only
  bool has_proxy_faces = false;
  std::size_t proxy_faces = std::size_t(SMSO::internal::default_proxy_number_of_faces); // bound mode only
  bool normalize = false;                 // written UVs scaled uniformly into [0,1]^2
  bool pack = false;                      // charts packed into [0,1]^2 (SMSO::pack_charts)
  double texture_size = default_texture_size; // --pack, --normalize with several charts: texels
  double margin = default_margin;         // texels between charts and to the border
  bool has_packing_option = false;        // --texture-size or --margin given
  bool use_input_uv = false;              // start from the input OBJ's own per-corner UVs
  double time_limit = 0;                  // seconds; 0: none
  Energy_kind energy = Energy_kind::SYMMETRIC_DIRICHLET;
  double area_weight = SMSO::Conformal_energy().area_weight(); // --area-weight (conformal only)
  bool has_area_weight = false;
  std::size_t threads = 0;                // 0: TBB's default (all cores)
  bool repair = false;                    // repair the input instead of refusing it
  std::string svg;                        // empty: no UV layout picture
  std::string png;                        // empty: no rendering
  std::string seam_weights;               // --seam-weights FILE; empty: every edge costs 1
  double region_seam_cost = default_region_seam_cost; // the W of FILE:W (a region's cost)
  bool has_region_seam_cost = false;
  SMSO::Cut_strategy cut_strategy = SMSO::OPTCUTS; // --cut-strategy
  bool hide_seams = false;                // seam costs from visibility (SMSO::visibility_seam_costs)
  bool measure_visibility = false;        // report the seams' share on the most visible edges

  // --distortion-bound, or the energy's default
  double bound() const
  {
    return has_distortion_bound ? distortion_bound : energy_default_bound(energy, area_weight);
  }
  Mode mode() const
  {
    return keep_seams ? Mode::KEEP_SEAMS : has_seam_weight ? Mode::SEAM_WEIGHT : Mode::DISTORTION_BOUND;
  }
  std::size_t iteration_cap() const
  {
    return has_max_iterations ? max_iterations
                              : keep_seams ? default_max_iterations_keep : default_max_iterations_seams;
  }
};

enum class Parse_status { RUN, HELP, ERROR };

inline void print_help(std::ostream& os)
{
  os << "Usage: " << program_name << " INPUT [options]\n"
     << "\n"
     << "Cuts a triangle mesh open along short seams and computes its UV map (texture\n"
     << "coordinates) so that the symmetric Dirichlet distortion E_SD stays below a bound\n"
     << "(OptCuts; 4 is an isometry), and writes it as an OBJ with per-corner texture\n"
     << "coordinates. Progress goes to stderr (one updating line on a terminal).\n"
     << "\n"
     << "  INPUT                   triangle mesh: .obj, .off, .ply or .stl (ASCII or binary;\n"
     << "                          an STL's equal points are merged). Polygons with more than\n"
     << "                          three corners are triangulated (a note says so); a\n"
     << "                          non-manifold mesh or a zero-area triangle (twice its area\n"
     << "                          below 1e-12 times its longest edge squared) is an error\n"
     << "                          (see --repair). Faces are numbered from 1 in messages.\n"
     << "                          Any genus, holes and several connected components: each\n"
     << "                          component is first cut to disks (through its handles; its\n"
     << "                          holes stay holes, or are cut to its largest boundary loop\n"
     << "                          where the map with them misses the bound) and the charts\n"
     << "                          are laid side by side.\n"
     << "\n"
     << "Options:\n"
     << "  -o, --output OUT.obj    output OBJ, must end in .obj (default: INPUT's name\n"
     << "                          without extension + \"_uv.obj\", in the current directory)\n"
     << "  --repair                repair the input first (CGAL Polygon_mesh_processing):\n"
     << "                          merge duplicate points, drop repeated corners, faces with\n"
     << "                          fewer than 3 corners, duplicate faces and unused points,\n"
     << "                          orient the faces (duplicating points at non-manifold edges\n"
     << "                          and vertices), collapse or flip away zero-area triangles;\n"
     << "                          what changed is\n"
     << "                          one stderr line and \"repair\" in the report (default: off)\n"
     << "  --use-input-uv          start from the input's own UV map (an OBJ with a vt for\n"
     << "                          every face corner, no flipped triangle) instead of\n"
     << "                          computing one; its seams are those of the map\n"
     << "                          (default: off)\n"
     << "  --normalize             write the UVs scaled uniformly (one factor for all charts)\n"
     << "                          and packed as with --pack when there are several charts;\n"
     << "                          one chart is scaled\n"
     << "                          and translated into [0,1]^2; the report's e_sd is that of\n"
     << "                          the unnormalized map (default: off)\n"
     << "  --pack                  lay all charts out in [0,1]^2 without overlap, each moved\n"
     << "                          rigidly (rotated to its smallest bounding rectangle) and\n"
     << "                          all scaled by one factor, as large as fits in a square\n"
     << "                          texture of --texture-size texels with --margin texels\n"
     << "                          around each chart; the report gives the fill rate\n"
     << "                          (default: off)\n"
     << "  --texture-size N        texture side in texels for --pack, an integer >= 1\n"
     << "                          (default: " << default_texture_size << ")\n"
     << "  --margin M              texels between charts and to the border for --pack,\n"
     << "                          >= 0 and < N / 2 (default: " << default_margin << ")\n"
     << "  --distortion-bound B    bound on the energy (E_SD: a number > 4); the seams are made\n"
     << "                          as short as found while it is <= B (default: "
     << default_distortion_bound << ", or the --energy's)\n"
     << "  --seam-weight L         a fixed seam weight lambda in [0, 1) instead of the bound:\n"
     << "                          minimize (1 - L) E_SD + L E_seam, no bound (default: off;\n"
     << "                          not with --distortion-bound)\n"
     << "  --no-bijectivity        do not keep charts from overlapping each other or\n"
     << "                          themselves in UV space (no scaffold): faster, and seams\n"
     << "                          may be shorter, but the map may not be usable as a\n"
     << "                          texture; the report says whether it overlaps (default:\n"
     << "                          off: the result is globally bijective)\n"
     << "  --keep-seams            keep the input's seams (none for a disk; a closed genus-0\n"
     << "                          mesh is cut by a two-edge slit) and only minimize\n"
     << "                          distortion: the previous distortion-only mode (default: off)\n"
     << "  --energy NAME           distortion energy the run minimizes and bounds, each with its\n"
     << "                          minimum and default bound: symmetric_dirichlet (E_SD; 4,\n"
     << "                          4.1), conformal (alias mips: MIPS, angles, plus an area\n"
     << "                          term weighted --area-weight; 2, 2.025 + 0.025 w) or arap\n"
     << "                          (0, 0.025); the defaults allow the same small strains. The\n"
     << "                          report gives energy_value (the bounded figure) and e_sd\n"
     << "                          (default: symmetric_dirichlet)\n"
     << "  --area-weight W         weight of the conformal energy's area term, >= 0; 0 leaves\n"
     << "                          areas free (pure MIPS, written at the scale minimizing E_SD)\n"
     << "                          (default: 0.01)\n"
     << "  --seam-weights FILE[:W] regional seam preferences: seams cost W times their length\n"
     << "                          on a region of vertices (W > 1 keeps them out, W < 1 draws\n"
     << "                          them in; default W: 1000) or what FILE gives per vertex or\n"
     << "                          edge; one form per file, vertices 0-based in file order:\n"
     << "                          'i' a region vertex (OptCuts' *_selected.txt), 'i w' vertex\n"
     << "                          i costs w (an edge the mean of its two), 'i j w' edge ij\n"
     << "                          costs w; '#' comments; others cost 1. The report gives the\n"
     << "                          weighted seam length too (default: none; not with\n"
     << "                          --keep-seams or --repair)\n"
     << "  --cut-strategy NAME     optcuts, or ebcuts: the baseline of the OptCuts paper's\n"
     << "                          comparison, cuts grown one by one from the vertex of largest\n"
     << "                          distortion to the nearest seam or border, the distortion\n"
     << "                          minimized in between (no scaffold: may overlap), until the\n"
     << "                          bound is met (default: optcuts; ebcuts not with --keep-seams\n"
     << "                          or --seam-weight)\n"
     << "  --hide-seams            move seams to where they show least: each edge's seam cost\n"
     << "                          grows with its visibility (ambient occlusion by ray\n"
     << "                          casting, and concave creases), from 1 for the least visible\n"
     << "                          edge to 4 for the most visible (by rank); multiplies\n"
     << "                          --seam-weights' costs. The report gives visible_seam_share\n"
     << "                          (default: off; not with --keep-seams)\n"
     << "  --measure-visibility    report visible_seam_share, the share of the seam length on\n"
     << "                          the most visible quarter of the edges, without hiding\n"
     << "                          (default: off)\n"
     << "  --max-iterations N      cap on Newton iterations (default: "
     << default_max_iterations_seams << ", or " << default_max_iterations_keep
     << " with --keep-seams)\n"
     << "  --recut-rounds N        after the first result at the bound, at most N rounds of\n"
     << "                          unzipping a tenth of the seams and cutting again (and N\n"
     << "                          of straightening a winding seam path), while that finds\n"
     << "                          shorter seams; 0 for the first result alone (faster);\n"
     << "                          not with --seam-weight or --keep-seams\n"
     << "                          (default: " << default_recut_rounds << ")\n"
     << "  --starts N              1, 2, 3 or 4: with 2, a second start that cuts without the\n"
     << "                          scaffold first, then goes on with it from those seams\n"
     << "                          (where the charts never overlap: one from a first straight\n"
     << "                          cut, from the point of largest distortion to the border;\n"
     << "                          a second dual step without --no-bijectivity), runs beside\n"
     << "                          the first (in parallel), and the shorter seams that meet\n"
     << "                          the bound are kept; 1 for the first alone (half the work);\n"
     << "                          3 runs both of these; 4 adds one whose dual\n"
     << "                          step holds the price of distortion while a cut pays; not with\n"
     << "                          --seam-weight or --keep-seams (default: " << default_starts << ")\n"
     << "  --proxy-faces N         a mesh of more than 2N faces: seams and map optimized first\n"
     << "                          on a proxy of about N faces (the mesh simplified), then\n"
     << "                          carried to the mesh, whose own run has only local work left\n"
     << "                          (0: never); not with --seam-weight, --keep-seams,\n"
     << "                          --use-input-uv, --seam-weights, --hide-seams or another\n"
     << "                          energy, where the mesh runs directly (default: "
     << SMSO::internal::default_proxy_number_of_faces << ")\n"
     << "  --time-limit S          stop the optimization after about S seconds (S > 0) and\n"
     << "                          write the best result so far (status WARNING_TIME_LIMIT,\n"
     << "                          exit 0); also with --keep-seams (default: none)\n"
     << "  --threads N             use at most N threads (N >= 1; the result does not depend\n"
     << "                          on it)"
#ifdef CGAL_LINKED_WITH_TBB
     << " (default: all cores)\n"
#else
     << "; built without TBB: always one thread (default: 1)\n"
#endif
     << "  --svg OUT.svg           draw the UV layout: triangles colored by their distortion,\n"
     << "                          seams, legend and figures (default: none)\n"
     << "  --png OUT.png           render the 3D model with a checkerboard through the UV map\n"
     << "                          and the seams drawn on it, 600x600"
     << (png_supported() ? "" : "; NOT AVAILABLE: built without libpng") << " (default: none)\n"
     << "  --report OUT.json       write a JSON report: status, message, mode, e_sd,\n"
     << "                          e_sd_optimal_scale, initial_e_sd, distortion_bound,\n"
     << "                          bound_met, seam_weight,\n"
     << "                          lambda, seam_length, seam_length_normalized,\n"
     << "                          weighted_seam_length_normalized, seam_weights,\n"
     << "                          hide_seams, visible_seam_share, charts,\n"
     << "                          normalized, packed, texture_size, margin, fill_rate,\n"
     << "                          iterations, topology_operations, bijective,\n"
     << "                          overlapping_triangle_pairs, scaffold_rebuilds, energy,\n"
     << "                          threads, repair, notes, seconds, faces, vertices, input,\n"
     << "                          output, svg, png (default: no report)\n"
     << "  --quiet                 no progress, summary or notes on stderr; errors are still\n"
     << "                          printed (default: off)\n"
     << "  -h, --help              print this help and exit\n"
     << "\n"
     << "Exit status: 0 success (also when the iteration cap was reached or the bound could\n"
     << "not be met: see the warning and the report), 1 invalid input or failed run,\n"
     << "2 invalid options, or an output that cannot be written (checked before the run;\n"
     << "outputs go to a temporary file renamed over the target: never half-written).\n";
}

// A whole-string finite number ("4.1", "1e-2"); false for anything else.
inline bool parse_double(const std::string& s, double& value)
{
  if(s.empty() || std::isspace(static_cast<unsigned char>(s[0])))
    return false;
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(s.c_str(), &end);
  if(end != s.c_str() + s.size() || errno == ERANGE || !std::isfinite(x))
    return false;
  value = x;
  return true;
}

inline bool parse_size(const std::string& s, std::size_t& value)
{
  if(s.empty() || s.find_first_not_of("0123456789") != std::string::npos || s.size() > 18)
    return false;
  value = static_cast<std::size_t>(std::stoull(s));
  return true;
}

inline bool parse_number(const std::string& s, double& value) { return parse_double(s, value); }
inline bool parse_number(const std::string& s, std::size_t& value) { return parse_size(s, value); }

// An option's name as typed, for the messages: "-o", or "--name" without "=value".
inline std::string typed_option_name(const std::string& arg)
{
  return arg.compare(0, 2, "--") == 0 ? arg.substr(0, arg.find('=')) : arg.substr(0, 2);
}

// The options Boost.Program_options recognizes: names only (no abbreviation),
// "--name=value", "--name value" and "-o value"; "--" ends the options. The
// values are checked below, in command-line order, with the messages of the
// help (Program_options' typed values would give its own).
inline Parse_status parse_options(int argc, char* argv[], Options& options, std::string& error)
{
  namespace po = boost::program_options;
  po::options_description recognized;
  recognized.add_options()("help,h", "")("output,o", po::value<std::string>(), "");
  for(const char* name : {"repair", "keep-seams", "use-input-uv", "normalize", "pack", "quiet", "no-bijectivity",
                          "hide-seams", "measure-visibility"})
    recognized.add_options()(name, "");
  for(const char* name : {"report", "svg", "png", "energy", "threads", "time-limit", "texture-size", "margin",
                          "distortion-bound", "seam-weight", "max-iterations", "recut-rounds", "seam-weights",
                          "cut-strategy", "starts", "area-weight", "proxy-faces"})
    recognized.add_options()(name, po::value<std::string>(), "");
  recognized.add_options()(positional_name, po::value<std::vector<std::string> >(), "");
  po::positional_options_description positional;
  positional.add(positional_name, -1);

  po::parsed_options parsed(&recognized);
  try
  {
    parsed = po::command_line_parser(argc, argv)
               .options(recognized)
               .positional(positional)
               .style(po::command_line_style::default_style & ~po::command_line_style::allow_guessing)
               .allow_unregistered() // reported below, in order, as "unknown option"
               .run();
  }
  catch(const po::invalid_command_line_syntax& e)
  {
    // Program_options names the long form; an option missing its value is
    // the last argument, named here as typed ("-o").
    const std::string name = e.kind() == po::invalid_command_line_syntax::missing_parameter && argc > 1
                               ? typed_option_name(argv[argc - 1]) : e.get_option_name();
    switch(e.kind())
    {
      case po::invalid_command_line_syntax::missing_parameter: error = "option '" + name + "' needs a value"; break;
      case po::invalid_command_line_syntax::empty_adjacent_parameter:
        error = "option '" + name + "' needs a non-empty value"; break;
      case po::invalid_command_line_syntax::extra_parameter: error = "option '" + name + "' takes no value"; break;
      default: error = e.what();
    }
    return Parse_status::ERROR;
  }
  catch(const po::error& e)
  {
    error = e.what();
    return Parse_status::ERROR;
  }

  for(const po::option& o : parsed.options)
  {
    if(o.position_key >= 0)
    {
      const std::string& arg = o.value.front();
      if(!options.input.empty())
      {
        error = "unexpected argument '" + arg + "' (only one INPUT)";
        return Parse_status::ERROR;
      }
      options.input = arg;
      continue;
    }
    const std::string& arg = o.original_tokens.front();
    if(o.unregistered || o.string_key == positional_name)
    {
      error = "unknown option '" + arg + "'";
      return Parse_status::ERROR;
    }
    const std::string key = "--" + o.string_key; // "--output" for -o too
    const std::string name = typed_option_name(arg);
    auto take_value = [&](std::string& out) {
      out = o.value.empty() ? std::string() : o.value.front();
      if(out.empty())
      {
        error = "option '" + name + "' needs a non-empty value";
        return false;
      }
      // "--report --quiet": the next option is no value (a file of that name
      // is still "--report=--quiet")
      if(o.original_tokens.size() > 1 && out.size() > 1 && out[0] == '-' && !std::isdigit(static_cast<unsigned char>(out[1])) && out[1] != '.')
      {
        error = "option '" + name + "' needs a value, not the option '" + out + "'";
        return false;
      }
      return true;
    };
    // A number option: its value parsed, in range, and the flag that says it was given.
    auto number = [&](auto& value, auto in_range, const std::string& needs, bool* given = nullptr) {
      std::string s;
      if(!take_value(s))
        return false;
      if(!parse_number(s, value) || !in_range(value))
      {
        error = "option '" + key + "' needs " + needs + ", not '" + s + "'";
        return false;
      }
      if(given) *given = true;
      return true;
    };

    // Switches, and options whose value is a file name.
    const std::pair<const char*, bool*> switches[] = {
      {"--repair", &options.repair}, {"--keep-seams", &options.keep_seams},
      {"--use-input-uv", &options.use_input_uv}, {"--normalize", &options.normalize}, {"--pack", &options.pack},
      {"--quiet", &options.quiet}, {"--no-bijectivity", &options.no_bijectivity},
      {"--hide-seams", &options.hide_seams}, {"--measure-visibility", &options.measure_visibility}};
    const std::pair<const char*, std::string*> paths[] = {
      {"--output", &options.output}, {"--report", &options.report},
      {"--svg", &options.svg}, {"--png", &options.png}};
    bool* switch_option = nullptr;
    std::string* path_option = nullptr;
    for(const auto& o : switches) if(key == o.first) switch_option = o.second;
    for(const auto& o : paths) if(key == o.first) path_option = o.second;

    if(switch_option)
    {
      *switch_option = true;
    }
    else if(path_option)
    {
      if(!take_value(*path_option))
        return Parse_status::ERROR;
      if(path_option == &options.png && !png_supported())
      {
        error = "option '--png' is not available: optimize_seams was built without libpng";
        return Parse_status::ERROR;
      }
    }
    else if(key == "--help")
      return Parse_status::HELP;
    else if(key == "--energy")
    {
      std::string s;
      if(!take_value(s))
        return Parse_status::ERROR;
      if(!parse_energy(s, options.energy))
      {
        error = "option '--energy' needs symmetric_dirichlet, conformal (or mips) or arap, not '" + s + "'";
        return Parse_status::ERROR;
      }
    }
    else if(key == "--threads")
    {
      if(!number(options.threads, [](std::size_t n) { return n >= 1 && n <= 4096; }, "an integer from 1 to 4096"))
        return Parse_status::ERROR;
    }
    else if(key == "--time-limit")
    {
      if(!number(options.time_limit, [](double t) { return t > 0.; }, "a number of seconds > 0"))
        return Parse_status::ERROR;
    }
    else if(key == "--texture-size")
    {
      std::size_t n = 0;
      if(!number(n, [](std::size_t t) { return t >= 1 && t <= 65536; }, "an integer from 1 to 65536",
                 &options.has_packing_option))
        return Parse_status::ERROR;
      options.texture_size = double(n);
    }
    else if(key == "--margin")
    {
      if(!number(options.margin, [](double m) { return m >= 0.; }, "a number of texels >= 0", &options.has_packing_option))
        return Parse_status::ERROR;
    }
    else if(key == "--distortion-bound")
    {
      // (checked against the energy's minimum below, once --energy is known)
      if(!number(options.distortion_bound, [](double) { return true; },
                 "a number above the energy's minimum (> 4 for E_SD, 4 is an isometry)", &options.has_distortion_bound))
        return Parse_status::ERROR;
    }
    else if(key == "--area-weight")
    {
      if(!number(options.area_weight, [](double w) { return w >= 0. && std::isfinite(w); }, "a number >= 0",
                 &options.has_area_weight))
        return Parse_status::ERROR;
    }
    else if(key == "--seam-weight")
    {
      if(!number(options.seam_weight, [](double w) { return w >= 0. && w < 1.; }, "a number in [0, 1)",
                 &options.has_seam_weight))
        return Parse_status::ERROR;
    }
    else if(key == "--cut-strategy")
    {
      std::string s;
      if(!take_value(s))
        return Parse_status::ERROR;
      if(s != "optcuts" && s != "ebcuts")
      {
        error = "option '--cut-strategy' needs optcuts or ebcuts, not '" + s + "'";
        return Parse_status::ERROR;
      }
      options.cut_strategy = s == "ebcuts" ? SMSO::EBCUTS : SMSO::OPTCUTS;
    }
    else if(key == "--seam-weights")
    {
      std::string s;
      if(!take_value(s))
        return Parse_status::ERROR;
      if(!split_seam_weights_argument(s, options.seam_weights, options.region_seam_cost,
                                      options.has_region_seam_cost))
      {
        error = "option '--seam-weights' needs FILE or FILE:W with a cost W >= 0, not '" + s + "'";
        return Parse_status::ERROR;
      }
    }
    else if(key == "--max-iterations")
    {
      if(!number(options.max_iterations, [](std::size_t) { return true; }, "a non-negative integer",
                 &options.has_max_iterations))
        return Parse_status::ERROR;
    }
    else if(key == "--recut-rounds")
    {
      if(!number(options.recut_rounds, [](std::size_t n) { return n <= 1000; }, "an integer in [0, 1000]",
                 &options.has_recut_rounds))
        return Parse_status::ERROR;
    }
    else if(key == "--starts")
    {
      if(!number(options.starts, [](std::size_t n) { return n >= 1 && n <= 4; }, "1, 2, 3 or 4", &options.has_starts))
        return Parse_status::ERROR;
    }
    else if(key == "--proxy-faces")
    {
      if(!number(options.proxy_faces, [](std::size_t) { return true; }, "a non-negative integer",
                 &options.has_proxy_faces))
        return Parse_status::ERROR;
    }
    else
    {
      error = "unknown option '" + arg + "'";
      return Parse_status::ERROR;
    }
  }
  if(options.has_distortion_bound && !(options.distortion_bound > energy_minimum[static_cast<int>(options.energy)]))
  {
    std::ostringstream s;
    s << "option '--distortion-bound' needs a number > " << energy_minimum[static_cast<int>(options.energy)]
      << " (the minimum of " << energy_name(options.energy)
      << (options.energy == Energy_kind::SYMMETRIC_DIRICHLET ? ": 4 is an isometry" : "") << "), not "
      << options.distortion_bound;
    error = s.str();
    return Parse_status::ERROR;
  }
  if(options.has_area_weight && options.energy != Energy_kind::MIPS)
  {
    error = "option '--area-weight' weights the area term of '--energy conformal' only";
    return Parse_status::ERROR;
  }
  if(options.has_distortion_bound && options.has_seam_weight)
  {
    error = "options '--distortion-bound' and '--seam-weight' are exclusive (a bound, or a fixed seam weight)";
    return Parse_status::ERROR;
  }
  if(options.keep_seams && (options.has_distortion_bound || options.has_seam_weight))
  {
    error = std::string("option '--keep-seams' does not optimize seams: it takes no '") +
            (options.has_distortion_bound ? "--distortion-bound" : "--seam-weight") + "'";
    return Parse_status::ERROR;
  }
  if(options.has_recut_rounds && (options.keep_seams || options.has_seam_weight))
  {
    error = std::string("option '--recut-rounds' applies to the distortion bound, not to '") +
            (options.keep_seams ? "--keep-seams" : "--seam-weight") + "'";
    return Parse_status::ERROR;
  }
  if(options.has_starts && (options.keep_seams || options.has_seam_weight))
  {
    error = std::string("option '--starts' applies to the distortion bound, not to '") +
            (options.keep_seams ? "--keep-seams" : "--seam-weight") + "'";
    return Parse_status::ERROR;
  }
  if(options.has_proxy_faces && (options.keep_seams || options.has_seam_weight))
  {
    error = std::string("option '--proxy-faces' applies to the distortion bound, not to '") +
            (options.keep_seams ? "--keep-seams" : "--seam-weight") + "'";
    return Parse_status::ERROR;
  }
  if(options.has_packing_option && !options.pack && !options.normalize)
  {
    error = "options '--texture-size' and '--margin' apply to '--pack' (or '--normalize')";
    return Parse_status::ERROR;
  }
  if(!(2 * options.margin < options.texture_size))
  {
    error = "option '--margin' must be less than half of the texture size";
    return Parse_status::ERROR;
  }
  if(options.cut_strategy == SMSO::EBCUTS && (options.keep_seams || options.has_seam_weight))
  {
    error = std::string("option '--cut-strategy ebcuts' cuts to the bound: not with '") +
            (options.keep_seams ? "--keep-seams" : "--seam-weight") + "'";
    return Parse_status::ERROR;
  }
  if(options.hide_seams && options.keep_seams)
  {
    error = "option '--hide-seams' prices seams, which '--keep-seams' does not optimize";
    return Parse_status::ERROR;
  }
  if(!options.seam_weights.empty() && (options.keep_seams || options.repair))
  {
    error = std::string("option '--seam-weights' ") +
            (options.keep_seams ? "prices seams, which '--keep-seams' does not optimize"
                                : "numbers the input's vertices, which '--repair' may renumber");
    return Parse_status::ERROR;
  }
  if(options.use_input_uv && options.repair)
  {
    error = "options '--use-input-uv' and '--repair' are exclusive (a repair would not keep the input's UVs)";
    return Parse_status::ERROR;
  }
  if(options.input.empty())
  {
    error = "missing INPUT";
    return Parse_status::ERROR;
  }
  return Parse_status::RUN;
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_COMMAND_LINE_H
