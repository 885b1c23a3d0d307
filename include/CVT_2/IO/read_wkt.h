// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Reading a domain from WKT, one geometry a line, with errors that name the line.
#ifndef CVT_2_IO_READ_WKT_H
#define CVT_2_IO_READ_WKT_H

#include <CVT_2/IO/internal/line_reader.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/internal/crossing_segments.h>
#include <CVT_2/internal/snap_to_boundary.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/valid_point.h>
#include <CVT_2/mark_domain_2.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/IO/WKT.h>
#include <CGAL/Polygon_with_holes_2.h>

#include <array>
#include <cctype>
#include <cstddef>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// A domain read from WKT (or GeoJSON): polygons with holes (their union is the domain),
/// linestrings (inner constraints) and points (generators), each with the line it was on (for
/// GeoJSON, the number of its feature).
/// \tparam K a CGAL kernel.
template <class K>
struct Wkt_data {
  using Point_2 = typename K::Point_2;                         ///< the point type
  using Polygon_with_holes_2 = CGAL::Polygon_with_holes_2<K>;  ///< a polygon
  std::string source;                                          ///< file name, for messages
  std::vector<Polygon_with_holes_2> polygons;                  ///< from POLYGON and MULTIPOLYGON
  std::vector<std::size_t> polygon_lines;                      ///< the line of each polygon
  std::vector<std::vector<Point_2>> polylines;                 ///< from LINESTRING, MULTILINESTRING
  std::vector<std::size_t> polyline_lines;                     ///< the line of each polyline
  std::vector<Point_2> points;                                 ///< from POINT and MULTIPOINT
  std::vector<std::size_t> point_lines;                        ///< the line of each point
  /// each point equal to an earlier one, as (its line, the earlier one's line): inserting
  /// them merges them
  std::vector<std::array<std::size_t, 2>> repeated_points;
  /// for GeoJSON, what to call each feature in messages, by its number from 1
  std::vector<std::string> item_names;
  /// for GeoJSON, each feature's `"kind"` property, by its number from 1: what its lines are to
  /// a simulation grid (`slit`, `barrier`, `conforming`), or empty if it has none
  std::vector<std::string> item_kinds;

  /// how messages name line or feature `n`: `file:n: `, or `file: feature n ('name'): `
  std::string where(std::size_t n) const {
    if (n >= 1 && n <= item_names.size()) return source + ": " + item_names[n - 1] + ": ";
    return source + ":" + std::to_string(n) + ": ";
  }
};

}  // namespace IO

namespace internal {

// Silences std::cerr: CGAL's WKT reader prints "error." on some malformed lines.
class Silenced_cerr {
 public:
  Silenced_cerr() : m_old(std::cerr.rdbuf(nullptr)) {}
  ~Silenced_cerr() { std::cerr.rdbuf(m_old); }
  Silenced_cerr(const Silenced_cerr&) = delete;
  Silenced_cerr& operator=(const Silenced_cerr&) = delete;

 private:
  std::streambuf* m_old;
};

// t without leading and trailing blanks.
inline std::string trimmed(std::string t) {
  t.erase(0, t.find_first_not_of(" \t\r"));
  t.erase(t.find_last_not_of(" \t\r") + 1);
  return t;
}

// t in upper case (WKT keywords are case-insensitive; CGAL's reader wants upper case).
inline std::string upper_case(std::string t) {
  for (char& c : t) c = char(std::toupper(static_cast<unsigned char>(c)));
  return t;
}

// Calls f(list) for the text of each innermost parenthesized list of a WKT geometry: a ring,
// a linestring or a point.
template <class F>
void for_each_innermost_list(const std::string& text, F f) {
  std::size_t open = std::string::npos;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '(') {
      open = i;
    } else if (text[i] == ')' && open != std::string::npos) {
      f(text.substr(open + 1, i - open - 1));
      open = std::string::npos;
    }
  }
}

// WKT rings repeat their first point last; CGAL's reader accepts a ring that does not and
// closes it silently, so the text is checked first: each innermost parenthesized list of a
// POLYGON or MULTIPOLYGON is a ring of two points or more (CGAL's reader reads before the
// start of an empty one) whose first and last coordinates are equal.
inline void check_rings_closed(const std::string& text, const std::string& source,
                               std::size_t line) {
  for_each_innermost_list(text, [&](const std::string& ring) {
    const std::size_t first_comma = ring.find(','), last_comma = ring.rfind(',');
    if (first_comma == std::string::npos)  // and CGAL's reader steps before an empty ring
      throw IO::Parse_error(source, line,
                            "a ring has fewer than 2 points: (" + ring +
                                "); a WKT ring has 3 distinct points or more, and repeats its "
                                "first point last");
    const std::string first = ring.substr(0, first_comma), last = ring.substr(last_comma + 1);
    double x0, y0, x1, y1;
    std::istringstream a(first), b(last);
    if (!(a >> x0 >> y0) || !(b >> x1 >> y1)) return;  // malformed: CGAL's reader says so
    if (x0 != x1 || y0 != y1)
      throw IO::Parse_error(source, line,
                            "a ring is not closed: it starts at (" + trimmed(first) +
                                ") and ends at (" + trimmed(last) +
                                "); a WKT ring repeats its first point last");
  });
}

// CGAL's WKT reader reads 3D coordinates into 2D points silently: each innermost
// parenthesized list must hold pairs 'x y' separated by commas.
inline void check_coordinate_pairs(const std::string& text, const std::string& source,
                                   std::size_t line) {
  for_each_innermost_list(text, [&](const std::string& list) {
    std::istringstream items(list);
    for (std::string item; std::getline(items, item, ',');) {
      std::istringstream fields(item);
      std::size_t n = 0;
      for (std::string f; fields >> f;) ++n;
      if (n > 2)
        throw IO::Parse_error(source, line,
                              "a point has " + std::to_string(n) + " coordinates (" + item +
                                  "): only 2D WKT is read");
    }
  });
}

}  // namespace internal

namespace IO {

/// \ingroup PkgCvt2IO
/// Reads WKT, one geometry a line: `POLYGON` and `MULTIPOLYGON` (the domain),
/// `LINESTRING` and `MULTILINESTRING` (inner constraints), `POINT` and `MULTIPOINT` (initial
/// generators); keywords in any case, blank lines and `EMPTY` geometries skipped. CGAL's WKT
/// reader parses each line.
/// \throws Parse_error naming the line: an unknown or malformed geometry, a point with more
///         than 2 coordinates, a ring that is not closed or has fewer than 3 distinct points, a
///         linestring of fewer than 2 points, a coordinate that is not finite or exceeds 1e300
///         in magnitude, or no polygon at all.
template <class K>
Wkt_data<K> read_wkt(std::istream& is, const std::string& source = "<wkt>") {
  using Point_2 = typename K::Point_2;
  Wkt_data<K> w;
  w.source = source;
  std::string line;
  for (std::size_t number = 1; std::getline(is, line); ++number) {
    const std::size_t b = line.find_first_not_of(" \t\r");
    if (b == std::string::npos) continue;
    std::size_t e = b;
    while (e < line.size() && std::isalpha(static_cast<unsigned char>(line[e]))) ++e;
    const std::string type = internal::upper_case(line.substr(b, e - b));
    if (type != "POINT" && type != "MULTIPOINT" && type != "LINESTRING" &&
        type != "MULTILINESTRING" && type != "POLYGON" && type != "MULTIPOLYGON")
      throw Parse_error(source, number,
                        "expected a WKT POLYGON, MULTIPOLYGON, LINESTRING, MULTILINESTRING, "
                        "POINT or MULTIPOINT",
                        type.empty() ? line.substr(b, 20) : type);
    const std::string rest = internal::trimmed(line.substr(e));
    const std::string upper_rest = internal::upper_case(rest);
    if (upper_rest == "EMPTY") continue;  // adds nothing (CGAL's reader would crash on it)
    if (upper_rest.find("EMPTY") != std::string::npos)
      throw Parse_error(source, number, "an EMPTY part inside a geometry is not supported",
                        "EMPTY");
    if (rest.empty() || rest[0] != '(')
      throw Parse_error(source, number, "malformed " + type + ": expected '(' or EMPTY after it",
                        rest.empty() ? type : rest.substr(0, 20));
    internal::check_coordinate_pairs(rest, source, number);
    std::vector<Point_2> points;
    std::vector<std::vector<Point_2>> polylines;
    std::vector<CGAL::Polygon_with_holes_2<K>> polygons;
    // CGAL reads upper-case keywords only, and takes a CR or a tab at the end for more text
    std::istringstream iss(type + " " + rest);
    bool ok = false;
    {
      const internal::Silenced_cerr silence;
      if (type == "POINT") {
        Point_2 p;
        ok = CGAL::IO::read_point_WKT(iss, p);
        points.push_back(p);
      } else if (type == "MULTIPOINT") {
        ok = CGAL::IO::read_multi_point_WKT(iss, points);
      } else if (type == "LINESTRING") {
        polylines.emplace_back();
        ok = CGAL::IO::read_linestring_WKT(iss, polylines.back());
      } else if (type == "MULTILINESTRING") {
        ok = CGAL::IO::read_multi_linestring_WKT(iss, polylines);
      } else if (type == "POLYGON" || type == "MULTIPOLYGON") {
        internal::check_rings_closed(line, source, number);
        if (type == "POLYGON") {
          polygons.emplace_back();
          ok = CGAL::IO::read_polygon_WKT(iss, polygons.back());
        } else {
          ok = CGAL::IO::read_multi_polygon_WKT(iss, polygons);
        }
      }
    }
    if (!ok) throw Parse_error(source, number, "malformed " + type, type);
    const auto check = [&](const Point_2& p) {
      if (!CVT_2::internal::is_valid_point(p))
        throw Parse_error(
            source, number,
            CVT_2::internal::invalid_point_message("point " + CVT_2::internal::to_string(p)));
    };
    for (const Point_2& p : points) {
      check(p);
      w.points.push_back(p);
      w.point_lines.push_back(number);
    }
    for (auto& l : polylines) {
      for (const Point_2& p : l) check(p);
      if (l.size() < 2) throw Parse_error(source, number, "a LINESTRING needs 2 points");
      w.polylines.push_back(std::move(l));
      w.polyline_lines.push_back(number);
    }
    for (auto& pwh : polygons) {
      std::vector<const CGAL::Polygon_2<K>*> rings{&pwh.outer_boundary()};
      for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) rings.push_back(&*h);
      for (const auto* r : rings) {
        for (const Point_2& p : *r) check(p);
        std::size_t distinct = 0;
        for (std::size_t i = 0; i < r->size(); ++i)
          distinct += (*r)[i] != (*r)[(i + 1) % r->size()] ? 1 : 0;
        if (distinct < 3) throw Parse_error(source, number, "a ring needs 3 distinct points");
      }
      w.polygons.push_back(std::move(pwh));
      w.polygon_lines.push_back(number);
    }
  }
  if (w.polygons.empty()) throw Parse_error(source, 0, "no POLYGON or MULTIPOLYGON");
  w.repeated_points = internal::repeated_points(w.points, w.point_lines);
  return w;
}

/// \ingroup PkgCvt2IO
/// Reads the WKT file `filename`. \throws Parse_error, also when it cannot be opened.
template <class K>
Wkt_data<K> read_wkt(const std::string& filename) {
  std::ifstream is = internal::open_input(filename);
  return read_wkt<K>(is, filename);
}

/// \ingroup PkgCvt2IO
/// Inserts a WKT domain into `cdt`: the rings of the polygons and the linestrings as
/// constraints (a point repeated in a row counts once), the domain marked from the polygons
/// (`mark_domain_from_polygons_2()`: the union of the polygons minus their holes), then the
/// points as generators (`insert_generators_2()`; a point on a constraint becomes a constrained
/// vertex, one outside by no more than the default boundary tolerance goes onto the boundary).
/// A linestring that runs out of the domain (through a boundary vertex: it may not cross the
/// boundary) constrains the cells with its part in the closed domain; the rest has no effect.
/// \throws Domain_error naming the file and line, and a polygon's ring as `polygon k, ring r`
///         (from 0 within the line or feature, ring 0 the exterior): a geometry that crosses
///         itself or an earlier one, with the two segments (with a triangulation that does
///         not compute intersections), a hole not inside its polygon's exterior or inside another
///         hole (as GEOS finds the polygon invalid), an empty domain, a linestring of no length
///         (its points all the same; GEOS finds it invalid), a linestring wholly outside
///         the domain (in another coordinate system, or with x and y swapped?), or a point outside
///         the domain (the first few named, with how many).
template <class CDT>
void insert_wkt(CDT& cdt, const Wkt_data<typename CDT::Geom_traits>& w) {
  using Point_2 = typename CDT::Point_2;
  const auto where = [&w](std::size_t line) { return w.where(line); };
  // Ring r of polygon i: `polygon k, ring r` after its line or feature, k counting the polygons
  // of that line or feature, r the rings (0 the exterior), from 0 as GeoJSON's arrays and
  // shapely's geometries count. Shapely's domain, one item named `polygon`, is named by them.
  const auto where_ring = [&w](std::size_t i, std::size_t r) {
    const std::size_t n = w.polygon_lines[i];
    std::size_t k = 0;
    while (k < i && w.polygon_lines[i - k - 1] == n) ++k;
    const std::string ring = "polygon " + std::to_string(k) + ", ring " + std::to_string(r) + ": ";
    if (n >= 1 && n <= w.item_names.size() && w.item_names[n - 1] == "polygon")
      return w.source + ": " + ring;
    return w.where(n) + ring;
  };
  // Each ring and line, in the order they are inserted: visit(points, closed, line).
  const auto for_each_geometry = [&w](const auto& visit) {
    for (std::size_t i = 0; i < w.polygons.size(); ++i) {
      const auto& pwh = w.polygons[i];
      visit(pwh.outer_boundary(), true, w.polygon_lines[i]);
      for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h)
        visit(*h, true, w.polygon_lines[i]);
    }
    for (std::size_t i = 0; i < w.polylines.size(); ++i)
      visit(w.polylines[i], false, w.polyline_lines[i]);
  };
  std::size_t inserted = 0;
  for_each_geometry([&](const auto& points, bool closed, std::size_t line) {
    const std::vector<Point_2> p = internal::polyline_points(points, closed);
    if (!closed && p.size() < 2)  // a point, not a line (GEOS finds it invalid)
      throw Domain_error(where(line) + "the line at " + internal::to_string(p.front()) +
                         " has no length: its points are all the same");
    try {
      cdt.insert_constraint(p.begin(), p.end(), closed);
    } catch (const typename CDT::Intersection_of_constraints_exception&) {
      // Which segments cross, found again from the input (the triangulation refused one).
      std::vector<std::array<Point_2, 2>> earlier;
      std::size_t g = 0;
      for_each_geometry([&](const auto& q, bool q_closed, std::size_t) {
        if (g++ < inserted)
          internal::add_segments(internal::polyline_points(q, q_closed), q_closed, earlier);
      });
      throw Domain_error(where(line) + "this geometry crosses itself or an earlier one" +
                         internal::first_crossing(earlier, p, closed));
    }
    ++inserted;
  });
  internal::check_holes_inside(cdt, w.polygons, where_ring);
  mark_domain_from_polygons_2(cdt, w.polygons);
  if (!internal::has_domain_face(cdt))
    throw Domain_error(w.source + ": the domain is empty: no polygon has an area");
  typename CDT::Face_handle hint;
  for (std::size_t i = 0; i < w.polylines.size(); ++i) {
    if (internal::polyline_meets_domain(cdt, w.polylines[i], hint)) continue;
    CGAL::Bbox_2 box;
    for (const auto& pwh : w.polygons) box += pwh.outer_boundary().bbox();
    throw Domain_error(where(w.polyline_lines[i]) + "the line from " +
                       internal::to_string(w.polylines[i].front()) + " to " +
                       internal::to_string(w.polylines[i].back()) +
                       " lies outside the domain, which spans " +
                       internal::to_string(Point_2(box.xmin(), box.ymin())) + " to " +
                       internal::to_string(Point_2(box.xmax(), box.ymax())) +
                       ": it would constrain nothing (coordinates in another system, or x and y "
                       "swapped?)");
  }
  try {
    insert_generators_2(cdt, w.points);
  } catch (const internal::Generators_outside_error& e) {
    if (e.index() >= w.point_lines.size()) throw;
    throw Domain_error(where(w.point_lines[e.index()]) + e.message([&](std::size_t k) {
      const std::size_t n = w.point_lines[k];
      return n >= 1 && n <= w.item_names.size() ? w.item_names[n - 1] : "line " + std::to_string(n);
    }),
                       e.index());
  } catch (const Domain_error& e) {
    if (e.index() >= w.point_lines.size()) throw;
    throw Domain_error(where(w.point_lines[e.index()]) + e.what(), e.index());
  }
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_READ_WKT_H
