// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// read_domain(): a domain from a .poly, .wkt or .geojson file into a triangulation.
#ifndef CVT_2_IO_READ_DOMAIN_H
#define CVT_2_IO_READ_DOMAIN_H

#include <CVT_2/IO/read_geojson.h>
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/IO/read_wkt.h>
#include <CVT_2/exceptions.h>

#include <cstddef>
#include <string>
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
/// Reads the domain in `filename` into `cdt`, by the file's extension: Triangle's `.poly`
/// (`read_poly()`, `insert_poly()`), `.wkt` (`read_wkt()`, `insert_wkt()`) or `.geojson` and
/// `.json` (`read_geojson()`, `insert_wkt()`): constraints, the domain marked, and the file's
/// free vertices or points inserted as generators.
/// \throws Parse_error or Domain_error naming the file and the place; Parse_error for a file
///         that cannot be opened or an unknown extension.
template <class CDT>
Domain_file read_domain(const std::string& filename, CDT& cdt) {
  using K = typename CDT::Geom_traits;
  const auto ends_with = [&filename](const std::string& suffix) {
    return filename.size() >= suffix.size() &&
           filename.compare(filename.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  Domain_file d;
  d.source = filename;
  if (ends_with(".poly")) {
    const auto poly = read_poly<typename CDT::Point_2>(filename);
    insert_poly(cdt, poly);
    std::vector<bool> on_segment(poly.vertices.size(), false);
    for (const auto& s : poly.segments) on_segment[s[0]] = on_segment[s[1]] = true;
    for (const bool b : on_segment) d.number_of_generators += b ? 0 : 1;
    d.format = "poly";
    for (const auto& [line, earlier] : poly.repeated_vertices)
      d.repeated.push_back(filename + ":" + std::to_string(line) +
                           ": this vertex repeats the one on line " + std::to_string(earlier));
    return d;
  }
  Wkt_data<K> w;
  if (ends_with(".wkt")) {
    w = read_wkt<K>(filename);
    d.format = "wkt";
  } else if (ends_with(".geojson") || ends_with(".json")) {
    w = read_geojson<K>(filename);
    d.format = "geojson";
  } else {
    internal::open_input(filename);  // a missing file says so first
    throw Parse_error(filename, 0,
                      "unknown domain format: expected a Triangle .poly, a .wkt or a .geojson "
                      "file");
  }
  insert_wkt(cdt, w);
  d.number_of_generators = w.points.size();
  for (const auto& [item, earlier] : w.repeated_points)
    d.repeated.push_back(
        w.where(item) + "this point repeats the one of " +
        (w.item_names.empty() ? "line " + std::to_string(earlier) : w.item_names[earlier - 1]));
  return d;
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_READ_DOMAIN_H
