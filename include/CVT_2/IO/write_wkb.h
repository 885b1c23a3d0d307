// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Writing the cells of a bounded Voronoi diagram as one WKB geometry collection.
#ifndef CVT_2_IO_WRITE_WKB_H
#define CVT_2_IO_WRITE_WKB_H

#include <CGAL/number_utils.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// Writes the cells of `mesh` as one well-known-binary (OGC WKB, little-endian)
/// GeometryCollection, cell k its k-th geometry: `Bvd_mesh_2::polygons()` as a Polygon, or a
/// MultiPolygon for a cell that meets itself at its generator, each ring closed by its first
/// point, the same doubles as the mesh's. What shapely (`shapely.wkb.loads`) and GDAL read in one
/// call, far faster than text. `os` should be opened in binary mode.
/// \tparam Mesh a `Bvd_mesh_2`.
template <class Mesh>
void write_wkb(std::ostream& os, const Mesh& mesh) {
  const auto u32 = [&os](std::uint32_t x) {
    char b[4];
    for (int i = 0; i < 4; ++i) b[i] = char((x >> (8 * i)) & 0xff);
    os.write(b, 4);
  };
  const auto f64 = [&os](double x) {
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    char b[8];
    for (int i = 0; i < 8; ++i) b[i] = char((bits >> (8 * i)) & 0xff);
    os.write(b, 8);
  };
  const auto header = [&](std::uint32_t type, std::size_t count) {
    os.put(1);  // little-endian
    u32(type), u32(std::uint32_t(count));
  };
  const auto polygon = [&](const std::vector<typename Mesh::Index>& ring) {
    header(3, 1);  // a Polygon of one ring
    u32(std::uint32_t(ring.size() + 1));
    for (std::size_t j = 0; j <= ring.size(); ++j) {
      const auto& p = mesh.point(ring[j % ring.size()]);
      f64(CGAL::to_double(p.x())), f64(CGAL::to_double(p.y()));
    }
  };
  header(7, mesh.number_of_cells());  // a GeometryCollection
  for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    const auto rings = mesh.polygons(k);
    if (rings.size() == 1) {
      polygon(rings[0]);
      continue;
    }
    header(6, rings.size());  // a MultiPolygon
    for (const auto& ring : rings) polygon(ring);
  }
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_WRITE_WKB_H
