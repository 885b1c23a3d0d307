// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The cells of the vertices of a range of faces, in memory order: the pass that builds many cells.
#ifndef CVT_2_INTERNAL_FOR_EACH_CELL_IN_FACES_H
#define CVT_2_INTERNAL_FOR_EACH_CELL_IN_FACES_H

#include <CVT_2/internal/prefetch.h>

#include <vector>

namespace CVT_2 {
namespace internal {

// Calls visit(v, cell) for every vertex v with v->face() in [first, last) that has a cell, each
// once, with its cell (the vector is reused between calls). Going by the faces in memory order
// is much kinder to the cache than the vertices' own order: building all cells is bound by the
// first access to each vertex's faces. Ranges that cut the faces in pieces (Face_chunks) visit
// every cell once in all.
template <class Diagram, class Face_iterator, class Visit>
void for_each_cell_in_faces(const Diagram& diagram, Face_iterator first, Face_iterator last,
                            const Visit& visit) {
  using Vertex_handle = typename Diagram::Vertex_handle;
  const auto& cdt = diagram.triangulation();
  std::vector<typename Diagram::Cell_vertex> c;
  for_each_face_prefetched(first, last, [&](const auto& f) {
    for (int i = 0; i < 3; ++i) {
      const Vertex_handle v = f->vertex(i);
      if (v->face() != f || cdt.is_infinite(v)) continue;  // each vertex once, at its face
      diagram.cell(v, c);
      if (!c.empty()) visit(v, static_cast<const std::vector<typename Diagram::Cell_vertex>&>(c));
    }
  });
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_FOR_EACH_CELL_IN_FACES_H
