// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The cells of the vertices of a range of faces, in memory order: the pass that builds many cells.
#ifndef CVT_2_INTERNAL_FOR_EACH_CELL_IN_FACES_H
#define CVT_2_INTERNAL_FOR_EACH_CELL_IN_FACES_H

#include <CVT_2/internal/layout/prefetch.h>

#include <vector>

namespace CVT_2 {
namespace internal {

// Calls visit(v) for every finite vertex v with v->face() in [first, last), each once, in the
// order of the faces in memory: much kinder to the cache than the vertices' own order, as what
// follows reads the faces around v. Ranges that cut the faces in pieces (Face_chunks) visit
// every vertex once in all.
template <class CDT, class Face_iterator, class Visit>
void for_each_vertex_at_its_face(const CDT& cdt, Face_iterator first, Face_iterator last,
                                 const Visit& visit) {
  for_each_face_prefetched(first, last, [&](const auto& f) {
    for (int i = 0; i < 3; ++i) {
      const typename CDT::Vertex_handle v = f->vertex(i);
      if (v->face() == f && !cdt.is_infinite(v)) visit(v);
    }
  });
}

// Calls visit(v, cell) for every vertex v with v->face() in [first, last) that has a cell, each
// once, with its cell (the vector is reused between calls), in the order of
// for_each_vertex_at_its_face(): building all cells is bound by the first access to each
// vertex's faces.
template <class Diagram, class Face_iterator, class Visit>
void for_each_cell_in_faces(const Diagram& diagram, Face_iterator first, Face_iterator last,
                            const Visit& visit) {
  using Vertex_handle = typename Diagram::Vertex_handle;
  std::vector<typename Diagram::Cell_vertex> c;
  for_each_vertex_at_its_face(diagram.triangulation(), first, last, [&](Vertex_handle v) {
    diagram.cell(v, c);
    if (!c.empty()) visit(v, static_cast<const std::vector<typename Diagram::Cell_vertex>&>(c));
  });
}

// The cell of v as its points: into `points` (a container of Point_2 with clear() and
// push_back()) the cell's vertices counterclockwise without repeats, as cell() lists them;
// false if v has no cell. `is_free` tells that v is not one of them; `c` is scratch. Most cells
// are those of a free vertex whose faces are all in the domain and see their circumcenters:
// such a cell is the circumcenters of the faces in the order of the circulation, and it is read
// straight from the faces, without a Cell_vertex; the same points, to the bit, as cell() gives.
// Any other vertex takes cell().
template <class Diagram, class Points>
bool cell_points(const Diagram& diagram, typename Diagram::Vertex_handle v, Points& points,
                 bool& is_free, std::vector<typename Diagram::Cell_vertex>& c) {
  using CDT = typename Diagram::Triangulation;
  const auto& cdt = diagram.triangulation();
  if (cdt.dimension() < 2) return false;  // no cell
  const auto circumcenter = diagram.geom_traits().construct_circumcenter_2_object();
  // The circumcenters of the faces around v, if v is free and its faces are all in the domain
  // and see them.
  const auto read_plain_cell = [&] {
    points.clear();
    auto fc = cdt.incident_faces(v);
    const auto done = fc;
    do {
      if (!fc->is_inside_domain() || fc->is_blinded() || fc->is_constrained(CDT::cw(fc->index(v))))
        return false;
      const auto p =
          circumcenter(fc->vertex(0)->point(), fc->vertex(1)->point(), fc->vertex(2)->point());
      if (points.empty() || points.back() != p) points.push_back(p);  // as construct_cell()
    } while (++fc != done);
    if (points.size() > 1 && points.back() == points.front()) points.pop_back();
    return true;
  };
  is_free = true;
  if (read_plain_cell()) return true;
  diagram.cell(v, c);
  if (c.empty()) return false;
  points.clear();
  for (const auto& x : c) {
    points.push_back(x.point);
    is_free = is_free && x.type != Diagram::Cell_vertex::GENERATOR;
  }
  return true;
}

// The same visit as for_each_cell_in_faces(), with each cell as its points (cell_points()):
// visit(v, points, is_free), `points` reused between calls.
template <class Diagram, class Face_iterator, class Points, class Visit>
void for_each_cell_points_in_faces(const Diagram& diagram, Face_iterator first, Face_iterator last,
                                   Points& points, const Visit& visit) {
  using Vertex_handle = typename Diagram::Vertex_handle;
  if (diagram.triangulation().dimension() < 2) return;  // no cell
  std::vector<typename Diagram::Cell_vertex> c;
  for_each_vertex_at_its_face(diagram.triangulation(), first, last, [&](Vertex_handle v) {
    bool is_free = true;
    if (cell_points(diagram, v, points, is_free, c))
      visit(v, static_cast<const Points&>(points), is_free);
  });
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_FOR_EACH_CELL_IN_FACES_H
