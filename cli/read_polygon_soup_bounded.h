// Copyright (c) 2026 The Surface_mesh_seam_optimization authors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// OBJ, OFF, PLY and STL (ASCII and binary) polygon soups read with bounded work:
// a count written in a file is checked against the bytes left before
// anything is allocated for it (CGAL 5.5's readers trust them: a 98-byte OFF
// announcing 2e9 corners allocated 15.6 GB), and every malformed or
// out-of-range token is an error naming its line (or byte offset).

#ifndef SMSO_CLI_READ_POLYGON_SOUP_BOUNDED_H
#define SMSO_CLI_READ_POLYGON_SOUP_BOUNDED_H

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace optimize_seams_cli {
namespace internal {

inline bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// A whole token as a finite or non-finite double ("nan" and "inf" are read:
// the caller decides about them).
inline bool parse_number_token(const std::string& t, double& x)
{
  if(t.empty())
    return false;
  char* end = nullptr;
  x = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size();
}

// A whole token as a signed integer; false on junk ("1.5", "1x") or overflow.
inline bool parse_integer_token(const std::string& t, long long& i)
{
  if(t.empty() || !(std::isdigit(static_cast<unsigned char>(t[0])) || t[0] == '-' || t[0] == '+'))
    return false;
  char* end = nullptr;
  errno = 0;
  i = std::strtoll(t.c_str(), &end, 10);
  return end == t.c_str() + t.size() && errno != ERANGE;
}

inline std::string format_count(double x)
{
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.17g", x);
  return buf;
}

// A token for a message: at most 40 characters, control bytes as '?' (a
// binary file must not write escape sequences to the terminal).
inline std::string quote_token(const std::string& t)
{
  std::string s = t.size() > 40 ? t.substr(0, 40) + "..." : t;
  for(char& c : s)
    if(static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      c = '?';
  return "'" + s + "'";
}

// Splits [b, e) into whitespace-separated tokens, stopping at '#' if `comments`.
inline void split_tokens(const char* b, const char* e, std::vector<std::string>& tokens, bool comments)
{
  tokens.clear();
  while(b < e)
  {
    while(b < e && is_space(*b))
      ++b;
    if(b == e || (comments && *b == '#'))
      break;
    const char* s = b;
    while(b < e && !is_space(*b) && !(comments && *b == '#'))
      ++b;
    tokens.emplace_back(s, b);
  }
}

// Lines of an in-memory file ('\n' ends a line, a final '\r' is whitespace).
struct Line_cursor
{
  const char* p;
  const char* end;
  std::size_t line = 0;
  Line_cursor(const char* b, const char* e) : p(b), end(e) {}
  bool next(const char*& b, const char*& e)
  {
    if(p >= end)
      return false;
    b = p;
    const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
    e = nl ? static_cast<const char*>(nl) : end;
    p = nl ? e + 1 : end;
    ++line;
    return true;
  }
  std::size_t bytes_left() const { return static_cast<std::size_t>(end - p); }
};

template <typename Point>
bool read_obj_soup(const std::string& data, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons, std::string& error)
{
  Line_cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string> tok;
  std::vector<long long> face;
  std::vector<std::size_t> face_lines;   // to name the line of a face whose index is out of range
  std::vector<std::vector<long long> > raw;
  const char* b; const char* e;
  auto fail = [&](const std::string& what) {
    error = "line " + std::to_string(cur.line) + ": " + what;
    return false;
  };
  while(cur.next(b, e))
  {
    split_tokens(b, e, tok, true);
    if(tok.empty())
      continue;
    if(tok[0] == "v")
    {
      // x y z, optionally w or a color (r g b [a]): numbers only
      if(tok.size() < 4 || tok.size() > 8)
        return fail("a vertex has 3 coordinates, optionally w or a color (" + std::to_string(tok.size() - 1) +
                    " values)");
      double c[3];
      for(std::size_t i = 1; i < tok.size(); ++i)
      {
        double x;
        if(!parse_number_token(tok[i], x))
          return fail("bad vertex coordinate " + quote_token(tok[i]));
        if(i <= 3)
          c[i - 1] = x;
      }
      points.emplace_back(c[0], c[1], c[2]);
    }
    else if(tok[0] == "f")
    {
      face.clear();
      for(std::size_t i = 1; i < tok.size(); ++i)
      {
        // v, v/vt, v/vt/vn or v//vn: each part an integer (or an empty vt)
        const std::string& t = tok[i];
        const std::size_t s1 = t.find('/');
        long long v, dummy;
        if(!parse_integer_token(t.substr(0, s1), v))
          return fail("bad face corner " + quote_token(t) + " (expected a vertex number)");
        if(s1 != std::string::npos)
        {
          const std::size_t s2 = t.find('/', s1 + 1);
          const std::string vt = t.substr(s1 + 1, s2 == std::string::npos ? std::string::npos : s2 - s1 - 1);
          const std::string vn = s2 == std::string::npos ? std::string() : t.substr(s2 + 1);
          if((!vt.empty() && !parse_integer_token(vt, dummy)) ||
             (s2 != std::string::npos && !parse_integer_token(vn, dummy)) ||
             (s2 == std::string::npos && vt.empty()))
            return fail("bad face corner " + quote_token(t));
        }
        if(v == 0)
          return fail("bad face corner " + quote_token(t) + " (vertex numbers start at 1)");
        if(v < 0)
        {
          // relative to the vertices read so far
          if(-v > static_cast<long long>(points.size()))
            return fail("face corner " + quote_token(t) + " refers to a vertex before the first");
          v += static_cast<long long>(points.size()) + 1;
        }
        face.push_back(v - 1);
      }
      raw.push_back(face);
      face_lines.push_back(cur.line);
    }
    // other statements (vt, vn, o, g, s, usemtl, l, ...) do not make the soup
  }
  polygons.clear();
  polygons.reserve(raw.size());
  for(std::size_t f = 0; f < raw.size(); ++f)
  {
    std::vector<std::size_t> poly;
    poly.reserve(raw[f].size());
    for(long long v : raw[f])
    {
      if(v >= static_cast<long long>(points.size()))
      {
        error = "line " + std::to_string(face_lines[f]) + ": face " + std::to_string(f + 1) +
                " refers to vertex " + std::to_string(v + 1) + ", but the file has " +
                std::to_string(points.size()) + " vertices";
        return false;
      }
      poly.push_back(static_cast<std::size_t>(v));
    }
    polygons.push_back(std::move(poly));
  }
  return true;
}

// OFF, COFF, NOFF, STOFF, CNOFF ... (extra per-vertex values and a face
// color after the indices are read and ignored); 4OFF, nOFF and binary OFF
// are refused.
template <typename Point>
bool read_off_soup(const std::string& data, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons, std::string& error)
{
  Line_cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string> tok;
  const char* b; const char* e;
  auto fail = [&](const std::string& what) {
    error = "line " + std::to_string(cur.line) + ": " + what;
    return false;
  };
  // The next line with a token; false at the end of the file.
  auto next_tokens = [&]() {
    while(cur.next(b, e))
    {
      split_tokens(b, e, tok, true);
      if(!tok.empty())
        return true;
    }
    return false;
  };
  if(!next_tokens())
  {
    error = "no OFF header";
    return false;
  }
  const std::string key = tok[0];
  if(key.size() < 3 || key.compare(key.size() - 3, 3, "OFF") != 0 ||
     key.find_first_not_of("STCN", 0) != key.size() - 3)
    return fail("not an OFF header: " + quote_token(key) + (key.find("OFF") != std::string::npos
                                                         ? " (4OFF and nOFF are not supported)" : ""));
  std::vector<std::string> counts(tok.begin() + 1, tok.end());
  if(counts.empty())
  {
    if(!next_tokens())
      return fail("missing vertex and face counts");
    counts = tok;
  }
  if(!counts.empty() && counts[0] == "BINARY")
    return fail("binary OFF is not supported");
  long long nv = -1, nf = -1, ne = 0;
  if(counts.size() < 2 || counts.size() > 3 || !parse_integer_token(counts[0], nv) ||
     !parse_integer_token(counts[1], nf) || (counts.size() == 3 && !parse_integer_token(counts[2], ne)) ||
     nv < 0 || nf < 0 || ne < 0)
    return fail("bad counts line (expected: vertices faces [edges], non-negative integers)");
  // Every vertex takes at least 3 numbers and every face 4 (each a character
  // and a separator): counts the rest of the file cannot hold are lies.
  const long double needed = 6.0L * nv + 8.0L * nf;
  if(needed > static_cast<long double>(cur.bytes_left()) + 1)
    return fail("the header announces " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                " faces, more than the " + std::to_string(cur.bytes_left()) + " bytes after it can hold");
  const bool has_texture = key.find("ST") != std::string::npos;
  points.clear();
  points.reserve(static_cast<std::size_t>(nv));
  for(long long i = 0; i < nv; ++i)
  {
    if(!next_tokens())
      return fail("the file ends after " + std::to_string(i) + " of the " + std::to_string(nv) +
                  " vertices its header announces");
    double c[3];
    if(tok.size() < 3)
      return fail("a vertex needs 3 coordinates");
    for(std::size_t k = 0; k < tok.size(); ++k)
    {
      double x;
      if(!parse_number_token(tok[k], x))
        return fail("bad vertex value " + quote_token(tok[k]) +
                    (i > 0 ? " (does the header announce too many vertices?)" : ""));
      if(k < 3)
        c[k] = x;
    }
    if(tok.size() > 3 + 3 + 4 + (has_texture ? 2 : 0))
      return fail("too many values for a vertex");
    points.emplace_back(c[0], c[1], c[2]);
  }
  polygons.clear();
  polygons.reserve(static_cast<std::size_t>(nf));
  for(long long f = 0; f < nf; ++f)
  {
    if(!next_tokens())
      return fail("the file ends after " + std::to_string(f) + " of the " + std::to_string(nf) +
                  " faces its header announces");
    long long n;
    if(!parse_integer_token(tok[0], n) || n < 1)
      return fail("bad face: " + quote_token(tok[0]) + " is not a corner count" +
                  " (does the header announce too few vertices?)");
    if(n > static_cast<long long>(tok.size()) - 1)
      return fail("face " + std::to_string(f + 1) + " announces " + std::to_string(n) + " corners but lists " +
                  std::to_string(tok.size() - 1) + " values");
    const std::size_t extra = tok.size() - 1 - static_cast<std::size_t>(n);
    if(extra > 4)
      return fail("face " + std::to_string(f + 1) + " has " + std::to_string(extra) +
                  " values after its corners (at most a color)");
    std::vector<std::size_t> poly;
    poly.reserve(static_cast<std::size_t>(n));
    for(long long k = 1; k <= n; ++k)
    {
      long long v;
      if(!parse_integer_token(tok[k], v))
        return fail("face " + std::to_string(f + 1) + ": bad vertex index " + quote_token(tok[k]));
      if(v < 0 || v >= nv)
        return fail("face " + std::to_string(f + 1) + " refers to vertex " + std::to_string(v) +
                    " (numbered from 0), but the header announces " + std::to_string(nv) + " vertices");
      poly.push_back(static_cast<std::size_t>(v));
    }
    for(std::size_t k = static_cast<std::size_t>(n) + 1; k < tok.size(); ++k)
    {
      double x;
      if(!parse_number_token(tok[k], x))
        return fail("face " + std::to_string(f + 1) + ": bad color value " + quote_token(tok[k]));
    }
    polygons.push_back(std::move(poly));
  }
  if(next_tokens())
    return fail("data after the " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                " faces the header announces (wrong counts?)");
  return true;
}

// PLY, ASCII or binary (either byte order): the vertex element's x, y, z and
// the face element's vertex_indices (or vertex_index) list; other elements
// and properties are read past.
struct Ply_property
{
  std::string name;
  bool is_list = false;
  int count_type = 0;   // size in bytes (list only)
  bool count_signed = false;
  int type = 0;         // size in bytes of the value (or of a list item)
  bool is_float = false, is_signed = false;
};

struct Ply_element
{
  std::string name;
  std::size_t count = 0;
  std::vector<Ply_property> properties;
};

inline bool ply_type(const std::string& t, int& size, bool& is_float, bool& is_signed)
{
  static const struct { const char* name; int size; bool f, s; } types[] = {
    {"char", 1, false, true}, {"int8", 1, false, true}, {"uchar", 1, false, false}, {"uint8", 1, false, false},
    {"short", 2, false, true}, {"int16", 2, false, true}, {"ushort", 2, false, false}, {"uint16", 2, false, false},
    {"int", 4, false, true}, {"int32", 4, false, true}, {"uint", 4, false, false}, {"uint32", 4, false, false},
    {"float", 4, true, true}, {"float32", 4, true, true}, {"double", 8, true, true}, {"float64", 8, true, true}};
  for(const auto& x : types)
    if(t == x.name)
    {
      size = x.size; is_float = x.f; is_signed = x.s;
      return true;
    }
  return false;
}

// Reads one binary scalar at `p` (bounds checked by the caller).
inline double ply_binary_value(const unsigned char* p, int size, bool is_float, bool is_signed, bool big_endian)
{
  unsigned char b[8];
  for(int i = 0; i < size; ++i)
    b[i] = p[big_endian ? size - 1 - i : i];
  const bool host_big = [] { const std::uint16_t x = 1; unsigned char c; std::memcpy(&c, &x, 1); return c == 0; }();
  if(host_big)
    std::reverse(b, b + size);
  switch(size)
  {
    case 1: return is_signed ? double(static_cast<std::int8_t>(b[0])) : double(b[0]);
    case 2: { std::int16_t s; std::uint16_t u; std::memcpy(&s, b, 2); std::memcpy(&u, b, 2);
              return is_signed ? double(s) : double(u); }
    case 4: { if(is_float) { float x; std::memcpy(&x, b, 4); return double(x); }
              std::int32_t s; std::uint32_t u; std::memcpy(&s, b, 4); std::memcpy(&u, b, 4);
              return is_signed ? double(s) : double(u); }
    default: { double x; std::memcpy(&x, b, 8); return x; }
  }
}

template <typename Point>
bool read_ply_soup(const std::string& data, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons, std::string& error)
{
  Line_cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string> tok;
  const char* b; const char* e;
  auto fail_line = [&](const std::string& what) {
    error = "line " + std::to_string(cur.line) + ": " + what;
    return false;
  };
  if(!cur.next(b, e) || (split_tokens(b, e, tok, false), tok.size() != 1) || tok[0] != "ply")
    return fail_line("not a PLY file (no 'ply' on the first line)");
  int format = -1;   // 0 ascii, 1 little endian, 2 big endian
  std::vector<Ply_element> elements;
  bool ended = false;
  while(!ended && cur.next(b, e))
  {
    split_tokens(b, e, tok, false);
    if(tok.empty() || tok[0] == "comment" || tok[0] == "obj_info")
      continue;
    if(tok[0] == "format")
    {
      if(tok.size() != 3 || tok[2] != "1.0")
        return fail_line("bad format line");
      format = tok[1] == "ascii" ? 0 : tok[1] == "binary_little_endian" ? 1 : tok[1] == "binary_big_endian" ? 2 : -1;
      if(format < 0)
        return fail_line("unknown format " + quote_token(tok[1]));
    }
    else if(tok[0] == "element")
    {
      long long n;
      if(tok.size() != 3 || !parse_integer_token(tok[2], n) || n < 0)
        return fail_line("bad element line (expected: element NAME COUNT)");
      elements.push_back(Ply_element{tok[1], static_cast<std::size_t>(n), {}});
    }
    else if(tok[0] == "property")
    {
      if(elements.empty())
        return fail_line("property before any element");
      Ply_property p;
      bool ok = false;
      if(tok.size() == 3)
        ok = ply_type(tok[1], p.type, p.is_float, p.is_signed);
      else if(tok.size() == 5 && tok[1] == "list")
      {
        bool count_float = false;
        p.is_list = true;
        ok = ply_type(tok[2], p.count_type, count_float, p.count_signed) && !count_float &&
             ply_type(tok[3], p.type, p.is_float, p.is_signed);
      }
      if(!ok)
        return fail_line("bad property line");
      p.name = tok.back();
      elements.back().properties.push_back(p);
    }
    else if(tok[0] == "end_header")
      ended = true;
    else
      return fail_line("unexpected header line starting with " + quote_token(tok[0]));
  }
  if(!ended)
  {
    error = "the PLY header has no end_header";
    return false;
  }
  if(format < 0)
  {
    error = "the PLY header has no format line";
    return false;
  }

  // Minimum bytes per record (ASCII: a character and a separator per value).
  long double needed = 0;
  for(const Ply_element& el : elements)
  {
    long double record = 0;
    for(const Ply_property& p : el.properties)
      record += format == 0 ? 2 : (p.is_list ? p.count_type : p.type);
    needed += record * static_cast<long double>(el.count);
  }
  const std::size_t data_begin = data.size() - cur.bytes_left();
  if(needed > static_cast<long double>(cur.bytes_left()) + 1)
  {
    error = "the PLY header announces more elements than the " + std::to_string(cur.bytes_left()) +
            " bytes after it can hold";
    return false;
  }

  std::size_t pos = data_begin;           // binary read position
  Line_cursor ascii(data.data() + data_begin, data.data() + data.size());
  std::vector<std::string> line_tokens;
  std::size_t line_token = 0;
  auto where = [&]() {
    return format == 0 ? "line " + std::to_string(cur.line + ascii.line)
                       : "byte " + std::to_string(pos);
  };
  // The next value (ASCII token or binary scalar); `integral` requires an integer.
  auto next_value = [&](int size, bool is_float, bool is_signed, bool integral, double& x) {
    if(format == 0)
    {
      while(line_token >= line_tokens.size())
      {
        if(!ascii.next(b, e))
        {
          error = "the file ends before the data its header announces";
          return false;
        }
        split_tokens(b, e, line_tokens, false);
        line_token = 0;
      }
      const std::string& t = line_tokens[line_token++];
      long long i;
      if(integral || !is_float)
      {
        if(!parse_integer_token(t, i))
        {
          error = where() + ": bad integer " + quote_token(t);
          return false;
        }
        x = double(i);
      }
      else if(!parse_number_token(t, x))
      {
        error = where() + ": bad number " + quote_token(t);
        return false;
      }
      return true;
    }
    if(data.size() - pos < static_cast<std::size_t>(size))
    {
      error = "the file ends before the data its header announces";
      return false;
    }
    x = ply_binary_value(reinterpret_cast<const unsigned char*>(data.data()) + pos, size, is_float, is_signed,
                         format == 2);
    pos += static_cast<std::size_t>(size);
    if(integral && is_float)
    {
      error = where() + ": a float where an index is expected";
      return false;
    }
    return true;
  };
  auto bytes_left = [&]() {
    return format == 0 ? ascii.bytes_left() + static_cast<std::size_t>(e - b) : data.size() - pos;
  };

  bool has_vertices = false, has_faces = false;
  points.clear();
  polygons.clear();
  for(const Ply_element& el : elements)
  {
    const bool is_vertex = el.name == "vertex" && !has_vertices;
    const bool is_face = el.name == "face" && !has_faces;
    int xyz[3] = {-1, -1, -1};
    int indices = -1;
    for(std::size_t k = 0; k < el.properties.size(); ++k)
    {
      const Ply_property& p = el.properties[k];
      if(is_vertex && !p.is_list && (p.name == "x" || p.name == "y" || p.name == "z"))
        xyz[p.name[0] - 'x'] = int(k);
      if(is_face && p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index"))
        indices = int(k);
    }
    if(is_vertex)
    {
      if(xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0)
      {
        error = "the PLY vertex element has no x, y and z";
        return false;
      }
      points.reserve(el.count);
      has_vertices = true;
    }
    if(is_face)
    {
      if(!has_vertices)
      {
        error = "the PLY face element comes before the vertex element";
        return false;
      }
      if(indices < 0)
      {
        error = "the PLY face element has no vertex_indices list";
        return false;
      }
      if(el.properties[indices].is_float)
      {
        error = "the PLY face indices are floating-point numbers";
        return false;
      }
      polygons.reserve(el.count);
      has_faces = true;
    }
    for(std::size_t r = 0; r < el.count; ++r)
    {
      double c[3] = {0, 0, 0};
      std::vector<std::size_t> poly;
      for(std::size_t k = 0; k < el.properties.size(); ++k)
      {
        const Ply_property& p = el.properties[k];
        double x;
        if(!p.is_list)
        {
          if(!next_value(p.type, p.is_float, p.is_signed, false, x))
            return false;
          for(int d = 0; d < 3; ++d)
            if(int(k) == xyz[d])
              c[d] = x;
          continue;
        }
        if(!next_value(p.count_type, false, p.count_signed, true, x))
          return false;
        const std::size_t item_bytes = format == 0 ? 2 : static_cast<std::size_t>(p.type);
        if(x < 0 || x * item_bytes > static_cast<double>(bytes_left()) + 1)
        {
          error = where() + ": a list of " + format_count(x) + " values, more than the rest of the file holds";
          return false;
        }
        const std::size_t n = static_cast<std::size_t>(x);
        const bool keep = is_face && int(k) == indices;
        if(keep)
          poly.reserve(n);
        for(std::size_t i = 0; i < n; ++i)
        {
          if(!next_value(p.type, p.is_float, p.is_signed, keep, x))
            return false;
          if(keep)
          {
            if(x < 0 || x >= static_cast<double>(points.size()))
            {
              error = where() + ": face " + std::to_string(r + 1) + " refers to vertex " + format_count(x) +
                      " (numbered from 0), but the file has " + std::to_string(points.size()) + " vertices";
              return false;
            }
            poly.push_back(static_cast<std::size_t>(x));
          }
        }
      }
      if(is_vertex)
        points.emplace_back(c[0], c[1], c[2]);
      if(is_face)
        polygons.push_back(std::move(poly));
    }
  }
  // Left-over data means the counts do not describe the file.
  if(format == 0)
  {
    bool extra = line_token < line_tokens.size();
    while(!extra && ascii.next(b, e))
    {
      split_tokens(b, e, line_tokens, false);
      extra = !line_tokens.empty();
    }
    if(extra)
    {
      error = where() + ": data after the elements the header announces (wrong counts?)";
      return false;
    }
  }
  else if(pos != data.size())
  {
    error = "byte " + std::to_string(pos) + ": " + std::to_string(data.size() - pos) +
            " bytes after the elements the header announces (wrong counts?)";
    return false;
  }
  return true;
}

// STL is a triangle soup with three points per facet: the points shared by
// facets (equal coordinates, bit for bit up to the sign of zero) become one
// vertex, numbered in order of first appearance, so that the facets are
// connected. Non-finite points are kept apart (the caller names them).
template <typename Point>
void merge_stl_corners(const std::vector<std::array<double, 3> >& corner, std::vector<Point>& points,
                       std::vector<std::vector<std::size_t> >& polygons)
{
  const std::size_t n = corner.size();
  std::vector<std::size_t> order;
  order.reserve(n);
  for(std::size_t c = 0; c < n; ++c)
    if(std::isfinite(corner[c][0]) && std::isfinite(corner[c][1]) && std::isfinite(corner[c][2]))
      order.push_back(c);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return corner[a] < corner[b] || (corner[a] == corner[b] && a < b);
  });
  std::vector<std::size_t> first(n);
  for(std::size_t c = 0; c < n; ++c)
    first[c] = c;
  for(std::size_t k = 1; k < order.size(); ++k)
    if(corner[order[k]] == corner[order[k - 1]])
      first[order[k]] = first[order[k - 1]];
  std::vector<std::size_t> id(n);
  points.clear();
  for(std::size_t c = 0; c < n; ++c)
  {
    if(first[c] == c)
    {
      id[c] = points.size();
      points.emplace_back(corner[c][0], corner[c][1], corner[c][2]);
    }
    else
      id[c] = id[first[c]];
  }
  polygons.assign(n / 3, std::vector<std::size_t>(3));
  for(std::size_t f = 0; f < n / 3; ++f)
    for(int k = 0; k < 3; ++k)
      polygons[f][k] = id[3 * f + k];
}

// STL, binary (80-byte header, a facet count, 50 bytes per facet, little
// endian; recognized by its size, since some begin with "solid" too) or
// ASCII ("solid ... facet normal ... outer loop vertex x y z (x3) endloop
// endfacet ... endsolid", several solids allowed). Normals are ignored: the
// corners' order orients a facet.
template <typename Point>
bool read_stl_soup(const std::string& data, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons, std::string& error)
{
  std::vector<std::array<double, 3> > corner;
  if(data.size() >= 84)
  {
    const unsigned char* u = reinterpret_cast<const unsigned char*>(data.data());
    const std::uint64_t nf = std::uint64_t(u[80]) | std::uint64_t(u[81]) << 8 | std::uint64_t(u[82]) << 16 |
                             std::uint64_t(u[83]) << 24;
    if(84 + 50 * nf == data.size())
    {
      corner.reserve(3 * nf);
      for(std::uint64_t f = 0; f < nf; ++f)
        for(int k = 0; k < 3; ++k)
        {
          std::array<double, 3> p;
          for(int j = 0; j < 3; ++j)
            p[j] = ply_binary_value(u + 84 + 50 * f + 12 + 12 * k + 4 * j, 4, true, true, false);
          corner.push_back(p);
        }
      merge_stl_corners(corner, points, polygons);
      return true;
    }
  }
  // (text has no NUL byte; a binary facet nearly always has one)
  if(std::memchr(data.data(), 0, data.size()) != nullptr)
  {
    error = "not an STL file: binary, but " + std::to_string(data.size()) +
            " bytes is not 84 plus 50 per facet of the count it gives" +
            (data.size() >= 84 ? std::string() : " (shorter than its 84-byte header)");
    return false;
  }
  // ASCII: a stream of keywords and numbers, line numbers for messages
  Line_cursor cur(data.data(), data.data() + data.size());
  std::vector<std::string> tok;
  std::size_t next_tok = 0;
  const char* b; const char* e;
  auto next = [&](std::string& t) {
    while(next_tok == tok.size())
    {
      if(!cur.next(b, e))
        return false;
      split_tokens(b, e, tok, false);
      next_tok = 0;
    }
    t = tok[next_tok++];
    return true;
  };
  auto fail = [&](const std::string& what) {
    error = "line " + std::to_string(cur.line) + ": " + what;
    return false;
  };
  std::string t;
  if(!next(t) || t != "solid")
  {
    if(data.size() >= 84)
      error = "not an STL file: neither ASCII (it does not begin with 'solid') nor binary (" +
              std::to_string(data.size()) + " bytes is not 84 plus 50 per facet of the count it gives)";
    else
      error = "not an STL file (" + std::to_string(data.size()) + " bytes, no 'solid')";
    return false;
  }
  auto expect = [&](const char* word) {
    if(!next(t))
      return fail(std::string("the file ends where '") + word + "' is expected");
    if(t != word)
      return fail(std::string("'") + word + "' expected, not " + quote_token(t));
    return true;
  };
  bool in_solid = true;
  // (a solid's name runs to the end of its line)
  next_tok = tok.size();
  while(next(t))
  {
    if(!in_solid)
    {
      if(t != "solid")
        return fail("data after 'endsolid': " + quote_token(t));
      in_solid = true;
      next_tok = tok.size();
      continue;
    }
    if(t == "endsolid")
    {
      in_solid = false;
      next_tok = tok.size();
      continue;
    }
    if(t != "facet")
      return fail("'facet' or 'endsolid' expected, not " + quote_token(t));
    if(!expect("normal"))
      return false;
    for(int j = 0; j < 3; ++j)
    {
      double x;
      if(!next(t) || !parse_number_token(t, x))
        return fail("a facet normal needs 3 numbers");
    }
    if(!expect("outer") || !expect("loop"))
      return false;
    for(int k = 0; k < 3; ++k)
    {
      if(!expect("vertex"))
        return false;
      std::array<double, 3> p;
      for(int j = 0; j < 3; ++j)
        if(!next(t) || !parse_number_token(t, p[j]))
          return fail("a vertex needs 3 numbers");
      corner.push_back(p);
    }
    if(!expect("endloop") || !expect("endfacet"))
      return false;
  }
  if(in_solid)
    return fail("the file ends without 'endsolid'");
  merge_stl_corners(corner, points, polygons);
  return true;
}

} // namespace internal

// Reads `path` (.obj, .off, .ply or .stl, by `extension`, lowercase with the dot)
// into a soup. False with a one-line reason in `error` (no file name).
template <typename Point>
bool read_polygon_soup_bounded(const std::string& path, const std::string& extension, std::vector<Point>& points,
                               std::vector<std::vector<std::size_t> >& polygons, std::string& error)
{
  std::ifstream is(path, std::ios::binary);
  if(!is)
  {
    error = "cannot open the file";
    return false;
  }
  // The whole file in memory: every count is then checked against its size.
  std::string data((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
  if(is.bad())
  {
    error = "read error";
    return false;
  }
  points.clear();
  polygons.clear();
  if(extension == ".obj")
    return internal::read_obj_soup(data, points, polygons, error);
  if(extension == ".off")
    return internal::read_off_soup(data, points, polygons, error);
  if(extension == ".ply")
    return internal::read_ply_soup(data, points, polygons, error);
  if(extension == ".stl")
    return internal::read_stl_soup(data, points, polygons, error);
  error = "unsupported format";
  return false;
}

} // namespace optimize_seams_cli

#endif // SMSO_CLI_READ_POLYGON_SOUP_BOUNDED_H
