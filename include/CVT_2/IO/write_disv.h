// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Writing the cells of a bounded Voronoi diagram as a MODFLOW 6 DISV grid.
#ifndef CVT_2_IO_WRITE_DISV_H
#define CVT_2_IO_WRITE_DISV_H

#include <CVT_2/IO/Metadata.h>
#include <CVT_2/IO/internal/mesh_outlines.h>
#include <CVT_2/IO/internal/write_number.h>

#include <cstddef>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// Writes the cells of `mesh` as the input file of MODFLOW 6's DISV package (discretization by
/// vertices), one layer from `bottom` to `top`: `DIMENSIONS` (NLAY 1, NCPL the cells, NVERT the
/// mesh's vertices), `GRIDDATA` (TOP and BOTM constant), `VERTICES` (`iv xv yv`, numbered from
/// 1, each shared by the cells it bounds) and `CELL2D` (`icell2d xc yc ncvert icvert...`: the
/// cell center is its generator, the vertices `Bvd_mesh_2::outline()` in clockwise order,
/// closed by repeating the first, as flopy writes them). This is the grid flopy's
/// `VoronoiGrid` builds by clipping unbounded Voronoi cells, here with the cells bounded by
/// inner constraints too. Cells are numbered as in the mesh, from 1.
/// `metadata`, if any, goes in comment lines after the first (`Metadata`).
/// \tparam Mesh a `Bvd_mesh_2`.
/// \pre `bottom < top`
template <class Mesh>
void write_disv(std::ostream& os, const Mesh& mesh, double top = 1, double bottom = 0,
                const Metadata& metadata = {}) {
  using internal::write_number;
  const internal::Mesh_outlines<Mesh> o(mesh);
  os << "# MODFLOW 6 DISV: a bounded Voronoi grid written by CVT_2\n";
  for (const auto& [key, value] : metadata)
    os << "# " << internal::comment_text(key) << ": " << internal::comment_text(value) << '\n';
  os << "BEGIN OPTIONS\nEND OPTIONS\n\nBEGIN DIMENSIONS\n  NLAY 1\n  NCPL "
     << mesh.number_of_cells() << "\n  NVERT " << o.vertices.size()
     << "\nEND DIMENSIONS\n\nBEGIN GRIDDATA\n  TOP\n    CONSTANT ";
  write_number(os, top);
  os << "\n  BOTM LAYERED\n    CONSTANT ";
  write_number(os, bottom);
  os << "\nEND GRIDDATA\n\nBEGIN VERTICES\n";
  for (std::size_t i = 0; i < o.vertices.size(); ++i) {
    os << "  " << i + 1 << ' ';
    write_number(os, mesh.point(o.vertices[i]).x());
    os << ' ';
    write_number(os, mesh.point(o.vertices[i]).y());
    os << '\n';
  }
  os << "END VERTICES\n\nBEGIN CELL2D\n";
  for (std::size_t k = 0; k < mesh.number_of_cells(); ++k) {
    const auto& outline = o.cells[k];
    os << "  " << k + 1 << ' ';
    write_number(os, mesh.generator(k)->point().x());
    os << ' ';
    write_number(os, mesh.generator(k)->point().y());
    os << ' ' << (outline.empty() ? 0 : outline.size() + 1);
    for (std::size_t j = outline.size(); j-- > 0;) os << ' ' << outline[j] + 1;
    if (!outline.empty()) os << ' ' << outline.back() + 1;
    os << '\n';
  }
  os << "END CELL2D\n";
}

/// \ingroup PkgCvt2IO
/// Writes `mesh` to the DISV file `filename`; returns false if the file could not be written.
template <class Mesh>
bool write_disv(const std::string& filename, const Mesh& mesh, double top = 1, double bottom = 0,
                const Metadata& metadata = {}) {
  std::ofstream os(filename);
  if (!os) return false;
  write_disv(os, mesh, top, bottom, metadata);
  return static_cast<bool>(os);
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_WRITE_DISV_H
