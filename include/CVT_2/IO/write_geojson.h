// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Writing the cells of a bounded Voronoi diagram as GeoJSON features whose geometries are valid.
#ifndef CVT_2_IO_WRITE_GEOJSON_H
#define CVT_2_IO_WRITE_GEOJSON_H

#include <CVT_2/IO/Metadata.h>
#include <CVT_2/IO/internal/write_number.h>

#include <cstddef>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// Writes the cells of `mesh` as a GeoJSON FeatureCollection (RFC 7946), one Feature per cell,
/// its `id` the cell's number. The geometry is `Bvd_mesh_2::polygons()`: a Polygon, or a
/// MultiPolygon for a cell that meets itself at its generator, counterclockwise, slits dropped,
/// valid for GEOS, shapely and QGIS; neighboring cells share their vertices' coordinates
/// exactly, so they neither overlap nor leave gaps. Properties: `cell` (its number),
/// `generator` ([x, y]), `constrained` (whether the generator is a constrained vertex), `area`,
/// `neighbors` (the numbers of the cells across its edges). Coordinates are written as the
/// shortest decimals that read back as the same doubles; no coordinate reference system is
/// implied.
/// `metadata`, if any, is a `"metadata"` object beside `"features"` (`Metadata`).
/// \tparam Mesh a `Bvd_mesh_2`.
template <class Mesh>
void write_geojson(std::ostream& os, const Mesh& mesh, const Metadata& metadata = {}) {
  using internal::write_number;
  const auto xy = [&os](const auto& p) {
    os << '[';
    write_number(os, p.x());
    os << ',';
    write_number(os, p.y());
    os << ']';
  };
  const auto ring = [&](const std::vector<typename Mesh::Index>& r) {
    os << '[';
    for (const auto i : r) xy(mesh.point(i)), os << ',';
    xy(mesh.point(r.front()));  // GeoJSON closes a ring by repeating its first position
    os << ']';
  };
  os << "{\"type\":\"FeatureCollection\",";
  if (!metadata.empty()) {
    os << "\"metadata\":{";
    for (std::size_t j = 0; j < metadata.size(); ++j) {
      os << (j ? "," : "");
      internal::write_json_string(os, metadata[j].first);
      os << ':';
      internal::write_json_string(os, metadata[j].second);
    }
    os << "},";
  }
  os << "\"features\":[";
  for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    os << (k == 0 ? "\n" : ",\n") << "{\"type\":\"Feature\",\"id\":" << k
       << ",\"properties\":{\"cell\":" << k << ",\"generator\":";
    xy(mesh.generator(k)->point());
    os << ",\"constrained\":" << (mesh.is_constrained(k) ? "true" : "false") << ",\"area\":";
    write_number(os, mesh.area(k));
    os << ",\"neighbors\":[";
    const auto neighbors = mesh.neighbors(k);
    for (std::size_t j = 0; j < neighbors.size(); ++j) os << (j ? "," : "") << neighbors[j];
    os << "]},\"geometry\":";
    const auto polygons = mesh.polygons(k);
    if (polygons.size() == 1) {
      os << "{\"type\":\"Polygon\",\"coordinates\":[";
      ring(polygons[0]);
      os << "]}}";
    } else {
      os << "{\"type\":\"MultiPolygon\",\"coordinates\":[";
      for (std::size_t j = 0; j < polygons.size(); ++j) {
        os << (j ? ",[" : "[");
        ring(polygons[j]);
        os << ']';
      }
      os << "]}}";
    }
  }
  os << "\n]}\n";
}

/// \ingroup PkgCvt2IO
/// Writes `mesh` to the GeoJSON file `filename`; returns false if the file could not be written.
template <class Mesh>
bool write_geojson(const std::string& filename, const Mesh& mesh, const Metadata& metadata = {}) {
  std::ofstream os(filename);
  if (!os) return false;
  write_geojson(os, mesh, metadata);
  return static_cast<bool>(os);
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_WRITE_GEOJSON_H
