// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The faces of a triangulation laid out in memory along a Hilbert curve.
#ifndef CVT_2_INTERNAL_LAYOUT_SORT_FACES_H
#define CVT_2_INTERNAL_LAYOUT_SORT_FACES_H

#include <CVT_2/internal/layout/prefetch.h>
#include <CVT_2/internal/parallel/Interrupt_scope.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// Moves the faces of `cdt` within their container (the same slots of the same container) so
// that memory order follows CGAL's Hilbert sort of their centroids (the median policy: the
// middle one stops at a cluster that falls in one quadrant of its box, and would leave a domain
// with a far island in shuffled order), the infinite faces last. The centroids are sorted in
// single precision, relative to the first vertex and scaled by a power of two into [-1, 1] (any
// extent of double coordinates fits; floats relative to the origin would be 0.25 apart at 4e6):
// the order is only a layout, and a float pair with its slot takes 12 bytes. The faces' neighbors
// and the vertices' faces follow their faces; nothing else does (a face base's own face handles,
// such as a blinding edge's face), and blind tags are cleared. The passes of the optimizers read
// faces in memory order and, from each, the faces around its vertices. CGAL's spatially sorted
// insertion makes faces in rounds over the whole domain, and the later rounds split and flip them
// where they lie: half the neighbors of a face then lie more than 64 faces away in memory, a tenth
// after this. Face handles held before the call then refer to other faces. Extra memory: 16 bytes a
// face, no second container; everything is allocated, and may throw, before the first face changes.
template <class CDT>
void sort_faces(CDT& cdt) {
  using Face_handle = typename CDT::Face_handle;
  using Index = std::uint32_t;
  using Float_point = CGAL::Simple_cartesian<float>::Point_2;
  using Item = std::pair<Float_point, Index>;  // a finite face's centroid and slot
  auto& faces = cdt.tds().faces();
  if (cdt.dimension() < 2 || faces.size() > std::numeric_limits<Index>::max()) return;
  const std::size_t n = faces.size();
  // where[k]: the slot of the face of rank k, the infinite faces ranked last, slots counted in
  // memory order
  std::vector<Index> where;
  {
    const auto x = [](typename CDT::Vertex_handle v) { return CGAL::to_double(v->point().x()); };
    const auto y = [](typename CDT::Vertex_handle v) { return CGAL::to_double(v->point().y()); };
    const double ox = x(cdt.finite_vertices_begin()), oy = y(cdt.finite_vertices_begin());
    double extent = 0;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      extent = std::max({extent, std::abs(x(v) - ox), std::abs(y(v) - oy)});
    if (!std::isfinite(extent)) return;  // coordinates beyond what insert_generators_2() takes
    int exponent = 0;
    std::frexp(extent, &exponent);  // extent < 2^exponent
    const double scale = std::ldexp(1.0, -exponent);
    std::vector<Item> finite;
    std::vector<Index> infinite;
    finite.reserve(n);
    Index j = 0;
    for (auto f = faces.begin(); f != faces.end(); ++f, ++j) {
      poll_interrupt_sometimes();
      if (cdt.is_infinite(f)) {
        infinite.push_back(j);
        continue;
      }
      const auto a = f->vertex(0), b = f->vertex(1), c = f->vertex(2);
      finite.emplace_back(Float_point(float(((x(a) + x(b) + x(c)) / 3 - ox) * scale),
                                      float(((y(a) + y(b) + y(c)) / 3 - oy) * scale)),
                          j);
    }
    CGAL::hilbert_sort(
        finite.begin(), finite.end(),
        Interruptible_sort_traits_2<CGAL::Spatial_sort_traits_adapter_2<
            CGAL::Simple_cartesian<float>, CGAL::First_of_pair_property_map<Item>>>(),
        CGAL::Hilbert_sort_median_policy());
    where.reserve(n);
    for (const Item& i : finite) where.push_back(i.second);
    where.insert(where.end(), infinite.begin(), infinite.end());
  }
  // slot[j]: the j-th face of the container; rank[j]: the rank of the face in slot j
  std::vector<Face_handle> slot;
  std::vector<Index> rank(n);
  slot.reserve(n);
  for (auto f = faces.begin(); f != faces.end(); ++f) {
    poll_interrupt_sometimes();
    slot.push_back(f);
  }
  for (std::size_t k = 0; k < n; ++k) {
    poll_interrupt_sometimes();  // the last poll: from here on the faces change
    rank[where[k]] = Index(k);
  }
  // The face in slot i goes to slot rank[i]. After the moves, the face that sits in slot j came
  // from the slot i with rank[i] = j; it carries, in its blinding edge's face (a handle free
  // here: blind tags are stale after an insertion, and cleared below), the new place of the
  // face that was in slot j, slot[rank[j]] = slot[rank[rank[i]]]. So an old neighbor handle
  // gives its face's new place, and the neighbors are set once no face is its own neighbor.
  for (std::size_t i = 0; i < n; ++i) slot[i]->set_blinding_edge({slot[rank[rank[i]]], 0});
  // Slot by slot, the face of its rank is swapped in; the face it held takes the other slot.
  // The other slots are known ahead, so they are fetched ahead.
  constexpr std::size_t distance = 8;
  for (std::size_t k = 0; k < n; ++k) {
    if (k + distance < n) prefetch(&*slot[where[k + distance]]);
    const Index j = where[k];
    if (j == k) continue;
    std::swap(*slot[k], *slot[j]);
    const Index r = rank[k];  // the face that was in slot k is now in slot j
    rank[j] = r;
    where[r] = j;
  }
  const auto place = [](Face_handle old) { return old->blinding_edge().first; };
  for (const Face_handle f : slot)
    f->set_neighbors(place(f->neighbor(0)), place(f->neighbor(1)), place(f->neighbor(2)));
  for (auto v = cdt.tds().vertices().begin(); v != cdt.tds().vertices().end(); ++v)
    if (v->face() != Face_handle()) v->set_face(place(v->face()));
  for (const Face_handle f : slot) f->clear_blinding();
}

// Whether the faces of `cdt` lie scattered in memory, as CGAL's own insertion leaves them:
// fewer than 3 in 4 of the neighbors of `sample` finite faces, in memory order, lie within 64
// faces of them (about 1 in 2 after CGAL's insertion, 9 in 10 after sort_faces()). Distances are
// taken between addresses, which count faces within a block of the container; the first
// `sample` faces are skipped when there are enough, as they lie in the container's first, small
// blocks, whose neighbors across blocks are near or far as the allocator placed the blocks.
template <class CDT>
bool faces_are_scattered(const CDT& cdt, std::size_t sample = std::size_t(1) << 14) {
  if (cdt.dimension() < 2) return false;
  const auto address = [](typename CDT::Face_handle f) {
    return reinterpret_cast<std::uintptr_t>(&*f);
  };
  constexpr std::uintptr_t near = 64 * sizeof(typename CDT::Face);
  auto f = cdt.finite_faces_begin();
  if (cdt.number_of_faces() >= 2 * sample)
    for (std::size_t k = 0; k < sample; ++k) ++f;
  std::size_t close = 0, all = 0, seen = 0;
  for (; f != cdt.finite_faces_end() && seen < sample; ++f, ++seen)
    for (int i = 0; i < 3; ++i) {
      const auto g = f->neighbor(i);
      if (cdt.is_infinite(g)) continue;
      const std::uintptr_t a = address(f), b = address(g);
      ++all;
      close += (a < b ? b - a : a - b) <= near;
    }
  return close * 4 < all * 3;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_LAYOUT_SORT_FACES_H
