// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// read_domain(): a domain from a .poly, .wkt or .geojson file into a triangulation, at once or
// in two steps (read_domain_data(), insert_domain()).
#ifndef CVT_2_IO_READ_DOMAIN_H
#define CVT_2_IO_READ_DOMAIN_H

#include <CVT_2/IO/read_geojson.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/IO/read_wkt.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/input_segments_of_constraints.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// What `read_domain()` found besides the triangulation.
struct Domain_file {
  std::string source;                    ///< the file
  std::string format;                    ///< `poly`, `wkt` or `geojson`
  std::size_t number_of_generators = 0;  ///< the free vertices or points the file gave
  /// one note per input point equal to an earlier one (the triangulation merges them), in file
  /// order: `file:12: this point repeats the one on line 3`
  std::vector<std::string> repeated;
};

/// \ingroup PkgCvt2IO
/// A domain as a file describes it, before it is inserted into a triangulation: what
/// `read_domain()` reads, kept for callers that build several triangulations of one domain
/// (`insert_domain()` inserts it). The Python module builds these from arrays and shapely
/// geometries too.
template <class K>
struct Domain_data {
  Domain_file file;  ///< the file, its format, its generators and repeated points
  /// the `.poly` graph, or the polygons, lines and points of a `.wkt` or `.geojson` file
  std::variant<Poly_data<typename K::Point_2>, Wkt_data<K>> description;
};

/// \ingroup PkgCvt2IO
/// The segments of a domain's description, as outputs name the lines of the input: segment `i`
/// from `ends[2i]` to `ends[2i + 1]`, and its `items[i]`: its row in a `.poly` file (from 0),
/// the line of its geometry in a `.wkt` file, its feature in a `.geojson` file (from 1). The
/// order is the file's: a `.poly` file's segments; each polygon's exterior and hole rings, then
/// each line, segment after segment, points repeated in a row counting once (as
/// `insert_wkt()` constrains them).
template <class K>
struct Domain_segments {
  std::vector<typename K::Point_2> ends;  ///< two a segment
  std::vector<std::int64_t> items;        ///< one a segment
  /// how many come first from polygons' rings (.wkt, .geojson); where two polygons share a
  /// border, the later one's edges lie on the earlier one's
  std::size_t rings = 0;
};

/// \ingroup PkgCvt2IO
/// The segments of `d` (`Domain_segments`).
template <class K>
Domain_segments<K> domain_segments(const Domain_data<K>& d) {
  using Point_2 = typename K::Point_2;
  Domain_segments<K> s;
  if (const auto* poly = std::get_if<0>(&d.description)) {
    for (std::size_t j = 0; j < poly->segments.size(); ++j) {
      s.ends.push_back(poly->vertices[poly->segments[j][0]]);
      s.ends.push_back(poly->vertices[poly->segments[j][1]]);
      s.items.push_back(std::int64_t(j));
    }
    return s;
  }
  const Wkt_data<K>& w = std::get<1>(d.description);
  const auto add = [&](const auto& points, bool closed, std::size_t item) {
    std::vector<Point_2> p;
    for (const Point_2& q : points)
      if (p.empty() || q != p.back()) p.push_back(q);
    if (closed && p.size() > 1 && p.front() == p.back()) p.pop_back();
    const std::size_t n = closed ? p.size() : p.size() - 1;
    for (std::size_t i = 0; i < n && p.size() > 1; ++i) {
      s.ends.push_back(p[i]);
      s.ends.push_back(p[(i + 1) % p.size()]);
      s.items.push_back(std::int64_t(item));
    }
  };
  for (std::size_t i = 0; i < w.polygons.size(); ++i) {
    add(w.polygons[i].outer_boundary(), true, w.polygon_lines[i]);
    for (auto h = w.polygons[i].holes_begin(); h != w.polygons[i].holes_end(); ++h)
      add(*h, true, w.polygon_lines[i]);
  }
  s.rings = s.items.size();
  for (std::size_t i = 0; i < w.polylines.size(); ++i)
    add(w.polylines[i], false, w.polyline_lines[i]);
  return s;
}

/// \ingroup PkgCvt2IO
/// The item of each constrained edge of `cdt` that lies on a segment of `segments` (as
/// `Domain_segments`): the input line it belongs to, keyed by its two points (the smaller
/// first). Taken before `resample_constraints_2()`, for `resampled_segments()`.
template <class CDT, class Segments>
std::map<std::pair<typename CDT::Point, typename CDT::Point>, std::int64_t> constrained_edge_items(
    const CDT& cdt, const Segments& segments) {
  std::map<std::pair<typename CDT::Point, typename CDT::Point>, std::int64_t> items;
  internal::for_each_edge_on_input_segments(cdt, segments.ends, [&](auto u, auto w, std::size_t i) {
    items.emplace(std::minmax(u->point(), w->point()), segments.items[i]);
  });
  return items;
}

/// \ingroup PkgCvt2IO
/// The segments of a resampled domain named as the input's lines: each of `chords`
/// (`resample_constraints_2()`'s `resampled_chords`) from `a` to `b`, with the item that
/// `edge_items` (`constrained_edge_items()` before the resampling) gives its source edge, or -1.
/// So `--cells-on-constraints`, the kinds of a GeoJSON's features and Python's `segment_items`
/// name a chord by the line the user gave.
template <class K, class Chords, class EdgeItems>
Domain_segments<K> resampled_segments(const Chords& chords, const EdgeItems& edge_items) {
  Domain_segments<K> s;
  for (const auto& c : chords) {
    s.ends.push_back(c.a);
    s.ends.push_back(c.b);
    const auto it = edge_items.find(std::minmax(c.source_a, c.source_b));
    s.items.push_back(it == edge_items.end() ? -1 : it->second);
  }
  return s;
}

/// \ingroup PkgCvt2IO
/// Reads the domain in `filename`, by the file's extension: Triangle's `.poly` (`read_poly()`),
/// `.wkt` (`read_wkt()`) or `.geojson` and `.json` (`read_geojson()`).
/// \throws Parse_error naming the file and the place, also for a file that cannot be opened or
///         an unknown extension.
template <class K>
Domain_data<K> read_domain_data(const std::string& filename) {
  const auto ends_with = [&filename](const std::string& suffix) {
    return filename.size() >= suffix.size() &&
           filename.compare(filename.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  Domain_data<K> d;
  Domain_file& f = d.file;
  f.source = filename;
  if (ends_with(".poly")) {
    const auto& poly = d.description.template emplace<0>(read_poly<typename K::Point_2>(filename));
    std::vector<bool> on_segment(poly.vertices.size(), false);
    for (const auto& s : poly.segments) on_segment[s[0]] = on_segment[s[1]] = true;
    for (const bool b : on_segment) f.number_of_generators += b ? 0 : 1;
    f.format = "poly";
    for (const auto& [line, earlier] : poly.repeated_vertices)
      f.repeated.push_back(filename + ":" + std::to_string(line) +
                           ": this vertex repeats the one on line " + std::to_string(earlier));
    return d;
  }
  Wkt_data<K>& w = d.description.template emplace<1>();
  if (ends_with(".wkt")) {
    w = read_wkt<K>(filename);
    f.format = "wkt";
  } else if (ends_with(".geojson") || ends_with(".json")) {
    w = read_geojson<K>(filename);
    f.format = "geojson";
  } else {
    internal::open_input(filename);  // a missing file says so first
    throw Parse_error(filename, 0,
                      "unknown domain format: expected a Triangle .poly, a .wkt or a .geojson "
                      "file");
  }
  f.number_of_generators = w.points.size();
  for (const auto& [item, earlier] : w.repeated_points)
    f.repeated.push_back(
        w.where(item) + "this point repeats the one of " +
        (w.item_names.empty() ? "line " + std::to_string(earlier) : w.item_names[earlier - 1]));
  return d;
}

/// \ingroup PkgCvt2IO
/// Inserts the domain `d` into `cdt` (`insert_poly()` or `insert_wkt()`): constraints, the
/// domain marked, and the description's free vertices or points inserted as generators.
/// \throws Domain_error naming the file and the place.
template <class CDT>
void insert_domain(CDT& cdt, const Domain_data<typename CDT::Geom_traits>& d) {
  if (const auto* poly = std::get_if<0>(&d.description))
    insert_poly(cdt, *poly);
  else
    insert_wkt(cdt, std::get<1>(d.description));
}

/// \ingroup PkgCvt2IO
/// Reads the domain in `filename` into `cdt`, by the file's extension: Triangle's `.poly`
/// (`read_poly()`, `insert_poly()`), `.wkt` (`read_wkt()`, `insert_wkt()`) or `.geojson` and
/// `.json` (`read_geojson()`, `insert_wkt()`): constraints, the domain marked, and the file's
/// free vertices or points inserted as generators. `read_domain_data()` then `insert_domain()`.
/// \throws Parse_error or Domain_error naming the file and the place; Parse_error for a file
///         that cannot be opened or an unknown extension.
template <class CDT>
Domain_file read_domain(const std::string& filename, CDT& cdt) {
  const auto d = read_domain_data<typename CDT::Geom_traits>(filename);
  insert_domain(cdt, d);
  return d.file;
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_READ_DOMAIN_H
