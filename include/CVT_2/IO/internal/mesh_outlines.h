// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The outlines of all cells of a mesh, with the vertices they use numbered anew: what the
// writers of one-vertex-list-per-cell formats (VTU, DISV) write.
#ifndef CVT_2_IO_INTERNAL_MESH_OUTLINES_H
#define CVT_2_IO_INTERNAL_MESH_OUTLINES_H

#include <cstddef>
#include <vector>

namespace CVT_2 {
namespace internal {

template <class Mesh>
struct Mesh_outlines {
  using Index = typename Mesh::Index;
  std::vector<std::vector<Index>> cells;  // each cell's outline, in the new numbers
  std::vector<Index> vertices;            // the mesh vertex of each new number

  // Vertices are numbered in the order of the mesh; those no outline uses (the generator at the
  // tip of slits only) are left out.
  explicit Mesh_outlines(const Mesh& mesh) : cells(mesh.number_of_cells()) {
    for (std::size_t k = 0; k < cells.size(); ++k) cells[k] = mesh.outline(k);
    std::vector<Index> renumber(mesh.number_of_vertices(), Mesh::none);
    for (const auto& c : cells)
      for (const Index i : c) renumber[i] = 0;
    for (std::size_t i = 0; i < renumber.size(); ++i)
      if (renumber[i] == 0) renumber[i] = Index(vertices.size()), vertices.push_back(Index(i));
    for (auto& c : cells)
      for (Index& i : c) i = renumber[i];
  }
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_IO_INTERNAL_MESH_OUTLINES_H
