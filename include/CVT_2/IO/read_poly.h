// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Reading Triangle's .poly files, and turning one into a constrained triangulation and domain.
#ifndef CVT_2_IO_READ_POLY_H
#define CVT_2_IO_READ_POLY_H

#include <CVT_2/IO/internal/line_reader.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/crossing_segments.h>
#include <CVT_2/internal/valid_point.h>
#include <CVT_2/mark_domain_2.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// What a `.poly` file holds: a planar straight-line graph and hole points, each item with the
/// line it was read from, so that later errors can say where.
template <class Point_2>
struct Poly_data {
  std::string source;                                ///< file name, for messages
  std::vector<Point_2> vertices;                     ///< in file order
  std::vector<std::size_t> vertex_lines;             ///< the line of each vertex
  std::vector<std::array<std::size_t, 2>> segments;  ///< 0-based indices into `vertices`
  std::vector<std::size_t> segment_lines;            ///< the line of each segment
  std::vector<Point_2> holes;                        ///< one seed point inside each hole
  std::vector<std::size_t> hole_lines;               ///< the line of each hole point
  /// each vertex at the same point as an earlier one, as (its line, the earlier one's line):
  /// `insert_poly()` merges them
  std::vector<std::array<std::size_t, 2>> repeated_vertices;
};

/// \ingroup PkgCvt2IO
/// Reads Triangle's `.poly` format: vertices (2D, any attributes and markers, numbered from 0
/// or from 1 as the first vertex says), segments (optional marker), holes, and an optional
/// regional-attributes section. Attributes, markers and regions are checked and ignored. `#`
/// starts a comment anywhere.
/// \throws Parse_error with the file, line and token on any malformed entry: wrong counts,
///         indices out of range, numbers that are not finite, an index or marker that is not
///         an integer, a segment of one vertex, content after the last section.
template <class Point_2>
Poly_data<Point_2> read_poly(std::istream& is, const std::string& source = "<poly>") {
  internal::Line_reader in(is, source);
  Poly_data<Point_2> data;
  data.source = source;
  std::vector<std::string> t;

  in.expect(t, "the vertex header '<#vertices> 2 <#attributes> <#markers>'");
  const std::size_t nv = in.count(t[0], "vertex count");
  if (nv == 0) in.fail("no vertices (reading them from a .node file is not supported)", t[0]);
  if (t.size() > 1 && in.integer(t[1]) != 2) in.fail("only dimension 2 is supported", t[1]);
  const std::size_t nattr = t.size() > 2 ? in.count(t[2], "attribute count") : 0;
  const std::size_t nmark = t.size() > 3 ? in.count(t[3], "marker count") : 0;
  if (nmark > 1) in.fail("at most one boundary marker", t[3]);
  if (t.size() > 4) in.fail("too many fields in the vertex header", t[4]);
  long long first = 0;
  for (std::size_t i = 0; i < nv; ++i) {
    in.expect(t, "vertex " + std::to_string(i + 1) + " of " + std::to_string(nv));
    if (t.size() != 3 + nattr + nmark)
      in.fail("expected '<index> <x> <y>' with " + std::to_string(nattr) + " attribute(s) and " +
                  std::to_string(nmark) + " marker(s)",
              t.back());
    const long long index = in.integer(t[0]);
    if (i == 0) {
      if (index != 0 && index != 1) in.fail("the first vertex must be numbered 0 or 1", t[0]);
      first = index;
    } else if (index != first + static_cast<long long>(i)) {
      in.fail("vertex numbers must be consecutive: expected " +
                  std::to_string(first + static_cast<long long>(i)),
              t[0]);
    }
    data.vertices.emplace_back(in.real(t[1]), in.real(t[2]));
    for (std::size_t f = 3; f < 3 + nattr; ++f) in.real(t[f]);
    if (nmark) in.integer(t[3 + nattr]);
    data.vertex_lines.push_back(in.line());
  }

  data.repeated_vertices = internal::repeated_points(data.vertices, data.vertex_lines);

  in.expect(t, "the segment header '<#segments> <#markers>'");
  const std::size_t ns = in.count(t[0], "segment count");
  const std::size_t smark = t.size() > 1 ? in.count(t[1], "marker count") : 0;
  if (smark > 1) in.fail("at most one boundary marker", t[1]);
  if (t.size() > 2) in.fail("too many fields in the segment header", t[2]);
  for (std::size_t j = 0; j < ns; ++j) {
    in.expect(t, "segment " + std::to_string(j + 1) + " of " + std::to_string(ns));
    if (t.size() != 3 + smark)
      in.fail("expected '<index> <vertex> <vertex>'" + std::string(smark ? " <marker>" : ""),
              t.back());
    in.integer(t[0]);
    std::array<std::size_t, 2> s{};
    for (int k = 0; k < 2; ++k) {
      const long long v = in.integer(t[1 + k]);
      if (v < first || v >= first + static_cast<long long>(nv))
        in.fail("vertex number out of range [" + std::to_string(first) + ", " +
                    std::to_string(first + static_cast<long long>(nv) - 1) + "]",
                t[1 + k]);
      s[k] = static_cast<std::size_t>(v - first);
    }
    if (s[0] == s[1]) in.fail("a segment needs two different vertices", t[2]);
    if (smark) in.integer(t[3]);
    data.segments.push_back(s);
    data.segment_lines.push_back(in.line());
  }

  if (!in.next(t)) return data;  // Triangle allows the hole section to be missing
  const std::size_t nh = in.count(t[0], "hole count");
  if (t.size() > 1) in.fail("too many fields in the hole header", t[1]);
  for (std::size_t k = 0; k < nh; ++k) {
    in.expect(t, "hole " + std::to_string(k + 1) + " of " + std::to_string(nh));
    if (t.size() != 3) in.fail("expected '<index> <x> <y>'", t.back());
    in.integer(t[0]);
    data.holes.emplace_back(in.real(t[1]), in.real(t[2]));
    data.hole_lines.push_back(in.line());
  }

  if (!in.next(t)) return data;
  const std::size_t nr = in.count(t[0], "region count");
  if (t.size() > 1) in.fail("too many fields in the region header", t[1]);
  for (std::size_t k = 0; k < nr; ++k) {
    in.expect(t, "region " + std::to_string(k + 1) + " of " + std::to_string(nr));
    if (t.size() < 4 || t.size() > 5)
      in.fail("expected '<index> <x> <y> <attribute> [<area>]'", t.back());
    for (std::size_t f = 1; f < t.size(); ++f) in.real(t[f]);
  }
  if (in.next(t)) in.fail("unexpected content after the last section", t[0]);
  return data;
}

/// \ingroup PkgCvt2IO
/// Reads the `.poly` file `filename`. \throws Parse_error, also when it cannot be opened.
template <class Point_2>
Poly_data<Point_2> read_poly(const std::string& filename) {
  std::ifstream is = internal::open_input(filename);
  return read_poly<Point_2>(is, filename);
}

/// \ingroup PkgCvt2IO
/// Inserts a `.poly` graph into `cdt` and marks its domain by Triangle's rule: vertices, then
/// segments as constraints, then the faces reachable from outside or from a hole point without
/// crossing a segment are left out. Vertices on no segment are free generators, as in Triangle.
/// \throws Domain_error naming the file and line of the offending item: a segment whose two
///         vertices lie at the same point, two segments that cross (with a triangulation that
///         does not compute intersections), a free vertex outside the domain, a hole point on a
///         segment or outside the domain (it would remove nothing), or an empty domain. As in
///         Triangle, a hole removes the segments inside it with the rest.
template <class CDT>
void insert_poly(CDT& cdt, const Poly_data<typename CDT::Point_2>& data) {
  const auto where = [&data](std::size_t line) {
    return data.source + ":" + std::to_string(line) + ": ";
  };
  for (std::size_t i = 0; i < data.vertices.size(); ++i)
    if (!internal::is_valid_point(data.vertices[i]))
      throw Domain_error(internal::invalid_point_message(where(data.vertex_lines[i]) + "vertex " +
                                                         internal::to_string(data.vertices[i])));
  std::vector<typename CDT::Vertex_handle> vertices;
  vertices.reserve(data.vertices.size());
  typename CDT::Face_handle hint;
  for (const auto& p : data.vertices) {
    vertices.push_back(cdt.insert(p, hint));
    hint = vertices.back()->face();
  }
  for (std::size_t j = 0; j < data.segments.size(); ++j) {
    const auto& s = data.segments[j];
    if (vertices[s[0]] == vertices[s[1]])  // two vertices of the file at the same point
      throw Domain_error(where(data.segment_lines[j]) + "segment " +
                         internal::to_string(data.vertices[s[0]]) + " - " +
                         internal::to_string(data.vertices[s[1]]) +
                         " has zero length: its vertices coincide");
    try {
      cdt.insert_constraint(vertices[s[0]], vertices[s[1]]);
    } catch (const typename CDT::Intersection_of_constraints_exception&) {
      // Name the first earlier segment it crosses properly (interiors meet at one point that is
      // no vertex: CGAL would have to construct it); searched only now, on the error path.
      const auto& a = data.vertices[s[0]];
      const auto& b = data.vertices[s[1]];
      std::string which = "an earlier segment";
      for (std::size_t k = 0; k < j; ++k) {
        const auto& c = data.vertices[data.segments[k][0]];
        const auto& d = data.vertices[data.segments[k][1]];
        if (internal::cross_properly(a, b, c, d)) {
          which = "segment " + internal::to_string(c) + " - " + internal::to_string(d) +
                  " of line " + std::to_string(data.segment_lines[k]);
          break;
        }
      }
      throw Domain_error(where(data.segment_lines[j]) + "segment " + internal::to_string(a) +
                         " - " + internal::to_string(b) + " crosses " + which);
    }
  }
  try {
    mark_domain_2(cdt, data.holes);
  } catch (const Domain_error& e) {
    if (e.index() >= data.hole_lines.size()) throw Domain_error(data.source + ": " + e.what());
    throw Domain_error(where(data.hole_lines[e.index()]) + e.what(), e.index());
  }
  if (!internal::has_domain_face(cdt))
    throw Domain_error(data.source + ": the domain is empty: no region is enclosed by segments");
  std::vector<bool> on_segment(data.vertices.size(), false);
  for (const auto& s : data.segments) on_segment[s[0]] = on_segment[s[1]] = true;
  for (std::size_t i = 0; i < data.vertices.size(); ++i) {
    if (on_segment[i]) continue;
    if (!internal::has_domain_face(cdt, vertices[i]))
      throw Domain_error(where(data.vertex_lines[i]) + "free vertex " +
                         internal::to_string(data.vertices[i]) + " lies outside the domain");
  }
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_READ_POLY_H
