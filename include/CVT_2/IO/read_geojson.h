// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Reading a domain from GeoJSON: polygons, inner constraints and generators (needs nlohmann/json).
#ifndef CVT_2_IO_READ_GEOJSON_H
#define CVT_2_IO_READ_GEOJSON_H

#include <CVT_2/IO/internal/line_reader.h>
#include <CVT_2/IO/read_wkt.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/valid_point.h>

#include <CGAL/Polygon_with_holes_2.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// What a GeoJSON reader knows while it walks the geometries of one feature.
template <class K>
struct Geojson_reader {
  using Point_2 = typename K::Point_2;
  using json = nlohmann::json;
  IO::Wkt_data<K>& out;
  std::size_t feature;  // from 1

  [[noreturn]] void fail(const std::string& what) const {
    throw IO::Parse_error(out.source, 0, out.item_names[feature - 1] + ": " + what);
  }

  // [x, y] or [x, y, z] (the altitude is not used).
  Point_2 position(const json& p) const {
    if (!p.is_array() || p.size() < 2 || p.size() > 3 || !p[0].is_number() || !p[1].is_number())
      fail("a position must be [x, y] with numbers, not " + p.dump().substr(0, 60));
    const Point_2 q(p[0].get<double>(), p[1].get<double>());
    if (!is_valid_point(q)) fail(invalid_point_message("point " + to_string(q)));
    return q;
  }
  std::vector<Point_2> positions(const json& a, std::size_t at_least, const char* what) const {
    if (!a.is_array() || a.size() < at_least)
      fail(std::string(what) + " needs an array of " + std::to_string(at_least) +
           " positions or more");
    std::vector<Point_2> p;
    for (const json& x : a) p.push_back(position(x));
    return p;
  }
  // A linear ring: closed (its last position repeats its first), 3 distinct positions or more.
  CGAL::Polygon_2<K> ring(const json& a) const {
    std::vector<Point_2> p = positions(a, 4, "a linear ring");
    if (p.front() != p.back())
      fail("a linear ring is not closed: it starts at " + to_string(p.front()) + " and ends at " +
           to_string(p.back()) + "; GeoJSON repeats the first position last");
    p.pop_back();
    std::vector<Point_2> distinct = p;
    std::sort(distinct.begin(), distinct.end());
    if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() < 3)
      fail("a linear ring needs 3 distinct positions");
    return CGAL::Polygon_2<K>(p.begin(), p.end());
  }
  void polygon(const json& rings) {
    if (!rings.is_array() || rings.empty()) fail("a Polygon needs an array of linear rings");
    CGAL::Polygon_with_holes_2<K> pwh(ring(rings[0]));
    for (std::size_t i = 1; i < rings.size(); ++i) pwh.add_hole(ring(rings[i]));
    out.polygons.push_back(std::move(pwh));
    out.polygon_lines.push_back(feature);
  }
  void linestring(const json& a) {
    out.polylines.push_back(positions(a, 2, "a LineString"));
    out.polyline_lines.push_back(feature);
  }
  void point(const json& p) {
    out.points.push_back(position(p));
    out.point_lines.push_back(feature);
  }
  template <class F>
  void each(const json& a, const char* what, const F& f) {
    if (!a.is_array()) fail(std::string(what) + " needs an array of coordinates");
    for (const json& x : a) f(x);
  }
  // Polygon and MultiPolygon: the domain; LineString and MultiLineString: inner constraints;
  // Point and MultiPoint: generators; GeometryCollection: each of its geometries.
  void geometry(const json& g) {
    if (g.is_null()) return;  // a feature without geometry adds nothing
    if (!g.is_object() || !g.contains("type") || !g["type"].is_string())
      fail("a geometry must be an object with a \"type\"");
    const std::string type = g["type"];
    if (type == "GeometryCollection") {
      if (!g.contains("geometries") || !g["geometries"].is_array())
        fail("a GeometryCollection needs \"geometries\"");
      for (const json& x : g["geometries"]) geometry(x);
      return;
    }
    if (!g.contains("coordinates")) fail("a " + type + " needs \"coordinates\"");
    const json& c = g["coordinates"];
    if (type == "Polygon")
      polygon(c);
    else if (type == "MultiPolygon")
      each(c, "a MultiPolygon", [&](const json& x) { polygon(x); });
    else if (type == "LineString")
      linestring(c);
    else if (type == "MultiLineString")
      each(c, "a MultiLineString", [&](const json& x) { linestring(x); });
    else if (type == "Point")
      point(c);
    else if (type == "MultiPoint")
      each(c, "a MultiPoint", [&](const json& x) { point(x); });
    else
      fail("unknown geometry type \"" + type.substr(0, 40) + "\"");
  }
};

// The line and column (from 1) of byte `byte` of `text` (from 1, as nlohmann counts).
inline std::pair<std::size_t, std::size_t> line_and_column(const std::string& text,
                                                           std::size_t byte) {
  const std::size_t at = std::min(byte == 0 ? 0 : byte - 1, text.size());
  const std::size_t line = 1 + std::size_t(std::count(text.begin(), text.begin() + at, '\n'));
  const std::size_t start = at == 0 ? 0 : text.rfind('\n', at - 1);
  return {line, start == std::string::npos || at == 0 ? at + 1 : at - start};
}

}  // namespace internal

namespace IO {

/// \ingroup PkgCvt2IO
/// Reads a domain from GeoJSON (RFC 7946): a FeatureCollection, a Feature or a bare geometry.
/// Polygon and MultiPolygon geometries are the domain (their union, minus their holes),
/// LineString and MultiLineString inner constraints, Point and MultiPoint generators;
/// GeometryCollections are read through. A third coordinate (altitude) is not used. Coordinates
/// are taken as they are, planar (project geographic data first). nlohmann/json
/// (`nlohmann-json3-dev` on Debian) parses the text.
///
/// The data's "lines" number the features from 1 (a bare geometry is feature 1), and messages
/// name a feature by its number and, if it has one, its `name` property or `id`. A feature's
/// `kind` property (`slit`, `barrier` or `conforming`) says what its lines are to a simulation
/// grid (`Wkt_data::item_kinds`; `cvt2 --constraints` for the others).
/// \throws Parse_error: text that is not JSON (with the line and column), or not GeoJSON (with
///         the feature): an unknown geometry type, a position that is not 2 or 3 numbers, a
///         linear ring not closed or with fewer than 3 distinct positions, a LineString of one
///         position, a coordinate that is not finite or exceeds 1e300 in magnitude, a `kind`
///         property of another value, or no polygon at all.
template <class K>
Wkt_data<K> read_geojson(std::istream& is, const std::string& source = "<geojson>") {
  using json = nlohmann::json;
  const std::string text((std::istreambuf_iterator<char>(is)), std::istreambuf_iterator<char>());
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    const std::string what = e.what();
    const std::size_t colon = what.rfind(": ");
    const auto [line, column] = internal::line_and_column(text, e.byte);
    throw Parse_error(source, line,
                      "column " + std::to_string(column) + ": not JSON: " +
                          (colon == std::string::npos ? what : what.substr(colon + 2)));
  } catch (const json::exception& e) {  // a number beyond double's range, say
    const std::string what = e.what();
    const std::size_t bracket = what.find("] ");
    throw Parse_error(
        source, 0, "not JSON: " + (bracket == std::string::npos ? what : what.substr(bracket + 2)));
  }
  Wkt_data<K> w;
  w.source = source;
  const auto name = [](const json& feature, std::size_t n) {
    std::string s = "feature " + std::to_string(n);
    const json* label = nullptr;
    if (feature.contains("properties") && feature["properties"].is_object() &&
        feature["properties"].contains("name"))
      label = &feature["properties"]["name"];
    else if (feature.contains("id"))
      label = &feature["id"];
    if (label) s += " (" + (label->is_string() ? label->get<std::string>() : label->dump()) + ")";
    return s;
  };
  const auto read_feature = [&](const json& f, bool is_feature) {
    w.item_names.push_back(is_feature ? name(f, w.item_names.size() + 1)
                                      : "geometry " + std::to_string(w.item_names.size() + 1));
    w.item_kinds.emplace_back();
    internal::Geojson_reader<K> r{w, w.item_names.size()};
    if (!is_feature) return r.geometry(f);
    if (!f.contains("geometry")) r.fail("a Feature needs a \"geometry\" (null for none)");
    if (f.contains("properties") && f["properties"].is_object() &&
        f["properties"].contains("kind")) {
      const json& kind = f["properties"]["kind"];
      if (!kind.is_string() || (kind != "slit" && kind != "barrier" && kind != "conforming"))
        r.fail("the property \"kind\" must be \"slit\", \"barrier\" or \"conforming\", not " +
               kind.dump().substr(0, 40));
      w.item_kinds.back() = kind.get<std::string>();
    }
    r.geometry(f["geometry"]);
  };
  if (!root.is_object() || !root.contains("type") || !root["type"].is_string())
    throw Parse_error(source, 0, "not GeoJSON: expected an object with a \"type\"");
  const std::string type = root["type"];
  if (type == "FeatureCollection") {
    if (!root.contains("features") || !root["features"].is_array())
      throw Parse_error(source, 0, "a FeatureCollection needs an array \"features\"");
    for (const json& f : root["features"]) {
      if (!f.is_object() || f.value("type", "") != "Feature")
        throw Parse_error(source, 0,
                          "feature " + std::to_string(w.item_names.size() + 1) +
                              ": a FeatureCollection holds Feature objects only");
      read_feature(f, true);
    }
  } else {
    read_feature(root, type == "Feature");
  }
  if (w.polygons.empty()) throw Parse_error(source, 0, "no Polygon or MultiPolygon");
  w.repeated_points = internal::repeated_points(w.points, w.point_lines);
  return w;
}

/// \ingroup PkgCvt2IO
/// Reads the GeoJSON file `filename`. \throws Parse_error, also when it cannot be opened.
template <class K>
Wkt_data<K> read_geojson(const std::string& filename) {
  std::ifstream is = internal::open_input(filename);
  return read_geojson<K>(is, filename);
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_READ_GEOJSON_H
