// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Writing the cells of a bounded Voronoi diagram as a VTK XML unstructured grid (.vtu).
#ifndef CVT_2_IO_WRITE_VTU_H
#define CVT_2_IO_WRITE_VTU_H

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
/// Writes the cells of `mesh` as a VTK XML unstructured grid (ASCII), for ParaView, VTK and
/// meshio: the vertices of the cells as shared points (z = 0; those of slits only, which the
/// outlines drop, left out), one `VTK_POLYGON` cell per Voronoi
/// cell in the order of the mesh, its vertices `Bvd_mesh_2::outline()` (counterclockwise, slits
/// dropped; a cell that meets itself at its generator goes through it once per lobe), and the
/// cell data `cell` (its number), `constrained` (1 if its generator is a constrained vertex),
/// `area` and `generator` (x, y, 0).
/// `metadata`, if any, goes in XML comments before the `VTKFile` element (`Metadata`).
/// \tparam Mesh a `Bvd_mesh_2`.
template <class Mesh>
void write_vtu(std::ostream& os, const Mesh& mesh, const Metadata& metadata = {}) {
  using internal::write_number;
  const internal::Mesh_outlines<Mesh> o(mesh);
  const auto& outlines = o.cells;
  os << "<?xml version=\"1.0\"?>\n";
  for (const auto& [key, value] : metadata)
    os << "<!-- " << internal::comment_text(key) << ": " << internal::comment_text(value)
       << " -->\n";
  os << "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\""
     << o.vertices.size() << "\" NumberOfCells=\"" << outlines.size() << "\">\n"
     << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto i : o.vertices) {
    write_number(os, mesh.point(i).x());
    os << ' ';
    write_number(os, mesh.point(i).y());
    os << " 0\n";
  }
  os << "</DataArray>\n</Points>\n<Cells>\n"
        "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& o : outlines) {
    for (std::size_t j = 0; j < o.size(); ++j) os << (j ? " " : "") << o[j];
    os << '\n';
  }
  os << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t offset = 0;
  for (const auto& o : outlines) os << (offset += o.size()) << '\n';
  os << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < outlines.size(); ++k) os << "7\n";  // VTK_POLYGON
  os << "</DataArray>\n</Cells>\n<CellData Scalars=\"cell\">\n"
        "<DataArray type=\"Int64\" Name=\"cell\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < outlines.size(); ++k) os << k << '\n';
  os << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"constrained\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < outlines.size(); ++k) os << (mesh.is_constrained(k) ? 1 : 0) << '\n';
  os << "</DataArray>\n<DataArray type=\"Float64\" Name=\"area\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < outlines.size(); ++k) write_number(os, mesh.area(k)), os << '\n';
  os << "</DataArray>\n<DataArray type=\"Float64\" Name=\"generator\" NumberOfComponents=\"3\" "
        "format=\"ascii\">\n";
  for (std::size_t k = 0; k < outlines.size(); ++k) {
    write_number(os, mesh.generator(k)->point().x());
    os << ' ';
    write_number(os, mesh.generator(k)->point().y());
    os << " 0\n";
  }
  os << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

/// \ingroup PkgCvt2IO
/// Writes `mesh` to the VTU file `filename`; returns false if the file could not be written.
template <class Mesh>
bool write_vtu(const std::string& filename, const Mesh& mesh, const Metadata& metadata = {}) {
  std::ofstream os(filename);
  if (!os) return false;
  write_vtu(os, mesh, metadata);
  return static_cast<bool>(os);
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_WRITE_VTU_H
