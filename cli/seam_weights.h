// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// --seam-weights FILE[:W]: regional seam preferences read into the seam cost
// maps of the library (vertex_seam_cost_map, seam_cost_map). A file holds one
// of three forms, one entry per line ('#' starts a comment; vertices are
// 0-based indices in the input file's vertex order):
//
//   a region    "i"        the vertices of a painted region (the OptCuts
//                          benchmark's *_selected.txt): cost W (default 1000;
//                          the paper uses 100; W < 1 attracts seams), smoothed
//                          over the one-ring (region_seam_costs())
//   vertices    "i w"      vertex i costs w (an edge: the mean of its two)
//   edges       "i j w"    the edge between vertices i and j costs w
//
// Unlisted vertices and edges cost 1.

#ifndef SMSO_CLI_SEAM_WEIGHTS_H
#define SMSO_CLI_SEAM_WEIGHTS_H

#include "run_optimization.h"

#include <CGAL/Surface_mesh_seam_optimization/seam_costs.h>

#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace optimize_seams_cli {

// Above the seam price the dual step reaches near the bound (100-300 on hard
// meshes), so that the region is not cut when nothing else pays; the paper's
// 100 left a third of the region's seams on dilo_o_f10000, 1000 none.
constexpr double default_region_seam_cost = 1000.;
constexpr double default_visibility_cost_ratio = 4.;
constexpr std::size_t no_mesh_vertex = std::numeric_limits<std::size_t>::max();

enum class Seam_weights_form { NONE, REGION, VERTICES, EDGES };

// "FILE" or "FILE:W" (W a number >= 0 after the last ':'; a ':' followed by
// anything else belongs to the file name). False when W is a number < 0.
inline bool split_seam_weights_argument(const std::string& arg, std::string& file, double& cost, bool& has_cost)
{
  file = arg;
  has_cost = false;
  const std::size_t colon = arg.rfind(':');
  if(colon == std::string::npos || colon == 0)
    return true;
  const std::string tail = arg.substr(colon + 1);
  char* end = nullptr;
  const double w = std::strtod(tail.c_str(), &end);
  if(tail.empty() || end != tail.c_str() + tail.size())
    return true;
  if(!(w >= 0) || !std::isfinite(w))
    return false;
  file = arg.substr(0, colon);
  cost = w;
  has_cost = true;
  return true;
}

// Reads `path` into `vcost` and `ecost` (all 1 elsewhere). `file_vertex[i]` is
// the mesh vertex of the file's vertex i (no_mesh_vertex: used by no face).
// Returns false with a one-line `error` naming the line at fault.
inline bool read_seam_weights(const std::string& path, const Mesh& mesh,
                              const std::vector<std::size_t>& file_vertex, double region_cost,
                              bool has_region_cost, Vertex_cost_map vcost, Edge_cost_map ecost,
                              Seam_weights_form& form, std::string& error)
{
  std::ifstream in(path);
  if(!in)
  {
    error = "cannot open seam weights '" + path + "'";
    return false;
  }
  for(vertex_descriptor v : vertices(mesh)) put(vcost, v, 1.);
  for(edge_descriptor e : edges(mesh)) put(ecost, e, 1.);
  form = Seam_weights_form::NONE;
  std::vector<vertex_descriptor> region;
  std::string line;
  std::size_t line_number = 0;
  auto fail = [&](const std::string& what) {
    error = "seam weights '" + path + "', line " + std::to_string(line_number) + ": " + what;
    return false;
  };
  auto vertex = [&](double x, vertex_descriptor& v) {
    if(!(x >= 0) || x != std::floor(x) || x >= double(file_vertex.size()))
    {
      std::ostringstream s;
      s << "no vertex " << x << " (indices are 0-based integers below " << file_vertex.size() << ")";
      return fail(s.str());
    }
    const std::size_t i = file_vertex[std::size_t(x)];
    if(i == no_mesh_vertex)
      return fail("vertex " + std::to_string(std::size_t(x)) + " is used by no face");
    v = vertex_descriptor(static_cast<Mesh::size_type>(i));
    return true;
  };
  while(std::getline(in, line))
  {
    ++line_number;
    const std::string data = line.substr(0, line.find('#'));
    std::istringstream fields(data);
    std::vector<double> x;
    std::string token;
    while(fields >> token)
    {
      char* end = nullptr;
      const double value = std::strtod(token.c_str(), &end);
      if(end != token.c_str() + token.size())
        return fail("'" + token + "' is not a number");
      x.push_back(value);
    }
    if(x.empty())
      continue;
    if(x.size() > 3)
      return fail("expected 'i', 'i w' or 'i j w'");
    const Seam_weights_form f = Seam_weights_form(x.size());
    if(form == Seam_weights_form::NONE)
      form = f;
    else if(f != form)
      return fail("mixes forms: the file started with " +
                  std::string(form == Seam_weights_form::REGION ? "a region ('i')"
                              : form == Seam_weights_form::VERTICES ? "vertex costs ('i w')"
                                                                    : "edge costs ('i j w')"));
    const double w = x.back();
    if(f != Seam_weights_form::REGION && (!(w >= 0) || !std::isfinite(w)))
      return fail("a cost must be a number >= 0");
    vertex_descriptor a, b;
    if(!vertex(x[0], a))
      return false;
    if(f == Seam_weights_form::REGION)
      region.push_back(a);
    else if(f == Seam_weights_form::VERTICES)
      put(vcost, a, w);
    else
    {
      if(!vertex(x[1], b))
        return false;
      const auto h = halfedge(a, b, mesh);
      if(!h.second)
        return fail("vertices " + std::to_string(std::size_t(x[0])) + " and " + std::to_string(std::size_t(x[1])) +
                    " share no edge");
      put(ecost, edge(h.first, mesh), w);
    }
  }
  if(form == Seam_weights_form::NONE)
  {
    error = "seam weights '" + path + "' lists nothing";
    return false;
  }
  if(has_region_cost && form != Seam_weights_form::REGION)
  {
    error = "seam weights '" + path + "': ':W' applies to a region (a list of vertices), not to costs given per " +
            (form == Seam_weights_form::VERTICES ? "vertex" : "edge");
    return false;
  }
  if(form == Seam_weights_form::REGION)
    SMSO::region_seam_costs(mesh, region, region_cost, vcost);
  return true;
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_SEAM_WEIGHTS_H
