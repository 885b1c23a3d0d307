// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Moving many free generators to given targets: moves within stars and flips, in a few passes.
#ifndef CVT_2_INTERNAL_MOVE_GENERATORS_H
#define CVT_2_INTERNAL_MOVE_GENERATORS_H

#include <CVT_2/internal/move_vertex.h>
#include <CVT_2/internal/prefetch.h>

#include <cstddef>
#include <vector>

namespace CVT_2 {
namespace internal {

// Moves each free vertex vertices[i] toward targets[i], in the sequence `order` (a permutation
// of the numbers; the cells' visit order is kind to the cache), in at most `passes` passes. A pass moves
// every vertex that is not yet at its target as far as its star allows (move_free_vertex: no
// edge is crossed, so no constraint), then restores the constrained Delaunay property; the next
// pass goes on from the new stars. A vertex that reaches its target is at it to the bit. Returns
// how many did not reach it.
template <class CDT>
std::size_t move_free_vertices(CDT& cdt, const std::vector<typename CDT::Vertex_handle>& vertices,
                               const std::vector<typename CDT::Point_2>& targets,
                               const std::vector<std::size_t>& order, std::size_t passes,
                               std::vector<Flip_candidate<CDT>>& stack) {
  CGAL_precondition(vertices.size() == targets.size() && order.size() == vertices.size());
  std::vector<std::size_t> pending, moved;
  for (const std::size_t i : order)
    if (vertices[i]->point() != targets[i]) pending.push_back(i);
  for (std::size_t pass = 0; pass < passes && !pending.empty(); ++pass) {
    moved.clear();
    std::size_t kept = 0;
    // The stars are far apart in memory: each is prefetched in steps ahead of its move, as in
    // Lloyd_optimizer_2::move() (its vertex, the vertex's face, that face's neighbors, theirs).
    const std::size_t n = pending.size(), d = 6;
    for (std::size_t k = 0; k < n; ++k) {
      if (k + 4 * d < n) prefetch(&*vertices[pending[k + 4 * d]]);
      if (k + 3 * d < n) prefetch(&*vertices[pending[k + 3 * d]]->face());
      if (k + 2 * d < n) {
        const auto f = vertices[pending[k + 2 * d]]->face();
        for (int j = 0; j < 3; ++j) prefetch(&*f->neighbor(j));
      }
      if (k + d < n) {
        const auto f = vertices[pending[k + d]]->face();
        for (int j = 0; j < 3; ++j) {
          prefetch(&*f->vertex(j));
          for (int l = 0; l < 3; ++l) prefetch(&*f->neighbor(j)->neighbor(l));
        }
      }
      const std::size_t i = pending[k];
      const double done = move_free_vertex(cdt, vertices[i], targets[i]);
      if (done > 0) moved.push_back(i);
      if (done < 1) pending[kept++] = i;
    }
    pending.resize(kept);
    if (moved.empty()) break;  // every remaining vertex is stuck where it is
    if (moved.size() * 8 > vertices.size()) {
      restore_delaunay(cdt, stack);  // most vertices moved: each edge of the domain once
    } else {
      // Few moved: only edges of their stars and links can have lost the Delaunay property
      // (their in-circle tests involve a moved vertex); Lawson's flips go on from there.
      stack.clear();
      for (const std::size_t i : moved) {
        auto fc = cdt.incident_faces(vertices[i]), end = fc;
        do {
          const typename CDT::Face_handle f = fc;
          for (int j = 0; j < 3; ++j)
            stack.push_back({f, j, f->vertex(CDT::ccw(j)), f->vertex(CDT::cw(j))});
        } while (++fc != end);
      }
      lawson_flips(cdt, stack);
    }
  }
  return pending.size();
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_MOVE_GENERATORS_H
