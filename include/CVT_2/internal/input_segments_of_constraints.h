// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The input segment each constraint of a mesh lies on: how outputs name the user's lines.
#ifndef CVT_2_INTERNAL_INPUT_SEGMENTS_OF_CONSTRAINTS_H
#define CVT_2_INTERNAL_INPUT_SEGMENTS_OF_CONSTRAINTS_H

#include <CVT_2/internal/snap_to_boundary.h>
#include <CVT_2/mark_domain_2.h>

#include <CGAL/Kernel/global_functions_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CVT_2 {
namespace internal {

// Whether w, a neighbour of u on the way from a to b, is a point that insert_generators_2()
// moved onto the boundary next to the segment ab, bending it through w by a few units in the
// last place: strictly between u and b along ab, and within 2^-44 of its largest coordinate
// from the line.
template <class Point_2>
bool is_bent_onto(const Point_2& w, const Point_2& u, const Point_2& a, const Point_2& b) {
  const double dx = b.x() - a.x(), dy = b.y() - a.y();
  const double m = std::max({std::abs(a.x()), std::abs(a.y()), std::abs(b.x()), std::abs(b.y())});
  return (w.x() - u.x()) * dx + (w.y() - u.y()) * dy > 0 &&
         (b.x() - w.x()) * dx + (b.y() - w.y()) * dy > 0 &&
         distance_to_line(w, a, b) <= std::ldexp(m, -44);
}

// Walks each input segment i (from ends[2i] to ends[2i + 1]) from one end to the other along
// the constrained edges of `cdt` that lie on it (they meet it exactly: the triangulation
// constructs no intersection), calling f(u, w, i) for each such edge uw.
template <class CDT, class F>
void for_each_edge_on_input_segments(const CDT& cdt, const std::vector<typename CDT::Point>& ends,
                                     F f) {
  using Vertex_handle = typename CDT::Vertex_handle;
  using Face_handle = typename CDT::Face_handle;
  Face_handle hint;
  const auto vertex_at = [&](const typename CDT::Point& p) {
    typename CDT::Locate_type lt;
    int li;
    const Face_handle face = cdt.locate(p, lt, li, hint);
    if (face != Face_handle()) hint = face;
    return lt == CDT::VERTEX ? face->vertex(li) : Vertex_handle();
  };
  for (std::size_t i = 0; i < ends.size() / 2; ++i) {
    const auto &a = ends[2 * i], &b = ends[2 * i + 1];
    Vertex_handle u = vertex_at(a);
    const Vertex_handle target = vertex_at(b);
    if (u == Vertex_handle() || target == Vertex_handle()) continue;
    while (u != target) {
      Vertex_handle next, bent;
      auto e = cdt.incident_edges(u), done = e;
      do {
        if (!cdt.is_constrained(*e)) continue;
        const Vertex_handle p = e->first->vertex(CDT::ccw(e->second));
        const Vertex_handle w = p == u ? e->first->vertex(CDT::cw(e->second)) : p;
        if (cdt.is_infinite(w)) continue;
        if (w == target ||
            (CGAL::orientation(a, b, w->point()) == CGAL::COLLINEAR &&
             CGAL::collinear_are_strictly_ordered_along_line(u->point(), w->point(), b))) {
          next = w;
          break;
        }
        if (is_bent_onto(w->point(), u->point(), a, b)) bent = w;
      } while (++e != done);
      if (next == Vertex_handle()) next = bent;
      if (next == Vertex_handle()) break;
      f(u, next, i);
      u = next;
    }
  }
}

// For each constraint of `mesh` (a constrained edge of the triangulation, by the cells of its
// ends), the first input segment it lies on (segment i from ends[2i] to ends[2i + 1]), or -1.
template <class CDT, class Mesh>
std::vector<std::int64_t> input_segments_of_constraints(
    const CDT& cdt, const Mesh& mesh, const std::vector<typename CDT::Point>& ends) {
  using Index = typename Mesh::Index;
  std::unordered_map<std::uint64_t, std::int64_t> of_edge;
  const auto key = [](Index a, Index b) {
    return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
  };
  for_each_edge_on_input_segments(cdt, ends, [&](auto u, auto next, std::size_t i) {
    if (has_domain_face(cdt, u) && has_domain_face(cdt, next))
      of_edge.emplace(key(Index(mesh.cell_of(u)), Index(mesh.cell_of(next))), std::int64_t(i));
  });
  std::vector<std::int64_t> input;
  for (const auto& c : mesh.constraints()) {
    const auto it = of_edge.find(key(c[0], c[1]));
    input.push_back(it == of_edge.end() ? -1 : it->second);
  }
  return input;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_INPUT_SEGMENTS_OF_CONSTRAINTS_H
