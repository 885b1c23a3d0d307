// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Prefetching walks: the passes over large triangulations are bound by memory latency, so the
// records a step will read are fetched some steps ahead.
#ifndef CVT_2_INTERNAL_LAYOUT_PREFETCH_H
#define CVT_2_INTERNAL_LAYOUT_PREFETCH_H

#include <cstddef>

namespace CVT_2 {
namespace internal {

// A hint that memory will be read soon; a no-op where the compiler has no builtin.
inline void prefetch(const void* p) {
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

// Calls visit(f) for every face f of [first, last), in memory order. The neighbors of the face
// `distance` ahead are fetched, then, halfway there, their neighbors and vertices: all that a
// cell around a vertex of f (the faces and vertices around it) and the orientation and
// in-circle tests of f's edges (its vertices, its neighbors' opposite vertices) read.
template <class Face_iterator, class Visit>
void for_each_face_prefetched(Face_iterator first, Face_iterator last, const Visit& visit) {
  constexpr int distance = 16;
  auto ahead = first, halfway = first;
  for (int i = 0; i < distance && ahead != last; ++i) ++ahead;
  for (int i = 0; i < distance / 2 && halfway != last; ++i) ++halfway;
  for (auto f = first; f != last; ++f) {
    if (ahead != last) {
      for (int i = 0; i < 3; ++i) prefetch(&*ahead->neighbor(i));
      ++ahead;
    }
    if (halfway != last) {
      for (int i = 0; i < 3; ++i) {
        const auto g = halfway->neighbor(i);
        for (int j = 0; j < 3; ++j) {
          prefetch(&*g->neighbor(j));
          prefetch(&*g->vertex(j));
        }
      }
      ++halfway;
    }
    visit(f);
  }
}

// Calls visit(k) for k = 0 ... n - 1, where vertex(k) is the vertex visit(k) works around. The
// stars are far apart in memory: each is fetched in steps ahead of its visit (the vertex, its
// face, that face's neighbors, then their vertices and neighbors).
template <class VertexAt, class Visit>
void for_each_star_prefetched(std::size_t n, const VertexAt& vertex, const Visit& visit) {
  constexpr std::size_t d = 6;
  for (std::size_t k = 0; k < n; ++k) {
    if (k + 4 * d < n) prefetch(&*vertex(k + 4 * d));
    if (k + 3 * d < n) prefetch(&*vertex(k + 3 * d)->face());
    if (k + 2 * d < n) {
      const auto f = vertex(k + 2 * d)->face();
      for (int j = 0; j < 3; ++j) prefetch(&*f->neighbor(j));
    }
    if (k + d < n) {
      const auto f = vertex(k + d)->face();
      for (int j = 0; j < 3; ++j) {
        prefetch(&*f->vertex(j));
        for (int l = 0; l < 3; ++l) prefetch(&*f->neighbor(j)->neighbor(l));
      }
    }
    visit(k);
  }
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_LAYOUT_PREFETCH_H
