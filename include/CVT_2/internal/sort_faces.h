// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The faces of a triangulation laid out in memory along a Hilbert curve.
#ifndef CVT_2_INTERNAL_SORT_FACES_H
#define CVT_2_INTERNAL_SORT_FACES_H

#include <CVT_2/internal/prefetch.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <array>
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
// with a far island in shuffled order), the infinite faces last. The faces' neighbors and the
// vertices' faces follow their faces; nothing else does (a face base's own face handles, such
// as a blinding edge's face), and blind tags are cleared. The passes of the optimizers read
// faces in memory order and, from each, the faces around its vertices. CGAL's spatially sorted
// insertion makes faces in rounds over the whole domain, and the later rounds split and flip
// them where they lie: half the neighbors of a face then lie more than 64 faces away in memory,
// a tenth after this. Face handles held before the call then refer to other faces. Extra
// memory: 40 bytes a face (double coordinates), no second container; everything is allocated,
// and may throw, before the first face changes.
template <class CDT>
void sort_faces(CDT& cdt) {
  using Face_handle = typename CDT::Face_handle;
  using Point_2 = typename CDT::Point_2;
  using Index = std::uint32_t;
  using Item = std::pair<Point_2, Index>;  // a finite face's centroid and slot
  auto& faces = cdt.tds().faces();
  if (cdt.dimension() < 2 || faces.size() > std::numeric_limits<Index>::max()) return;
  const std::size_t n = faces.size();
  // slot[j]: the j-th face of the container, in memory order; where[k]: the slot of the face of
  // rank k, the infinite faces ranked last; rank[j]: the rank of the face in slot j
  std::vector<Face_handle> slot;
  std::vector<Index> where, infinite, rank(n);
  slot.reserve(n);
  where.reserve(n);
  {
    std::vector<Item> finite;
    finite.reserve(n);
    for (auto f = faces.begin(); f != faces.end(); ++f) {
      const Index j = Index(slot.size());
      slot.push_back(f);
      if (cdt.is_infinite(f))
        infinite.push_back(j);
      else
        finite.emplace_back(
            CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()), j);
    }
    CGAL::hilbert_sort(finite.begin(), finite.end(),
                       CGAL::Spatial_sort_traits_adapter_2<typename CDT::Geom_traits,
                                                           CGAL::First_of_pair_property_map<Item>>(
                           CGAL::First_of_pair_property_map<Item>(), cdt.geom_traits()),
                       CGAL::Hilbert_sort_median_policy());
    for (const Item& i : finite) where.push_back(i.second);
  }
  where.insert(where.end(), infinite.begin(), infinite.end());
  for (std::size_t k = 0; k < n; ++k) rank[where[k]] = Index(k);
  // Each face's new place goes into its neighbor(0) for the time of the move (any face's new
  // place in one read; none for a face that stays, as a face may not be its own neighbor), and
  // its new neighbors, by rank, into `neighbors`: they are set once all faces are in place.
  std::vector<std::array<Face_handle, 3>> neighbors(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Face_handle f = slot[j];
    neighbors[rank[j]] = {f->neighbor(0), f->neighbor(1), f->neighbor(2)};
    f->set_neighbors(rank[j] == j ? Face_handle() : slot[rank[j]], f->neighbor(1), f->neighbor(2));
  }
  const auto place = [](Face_handle f) {
    const Face_handle p = f->neighbor(0);
    return p == Face_handle() ? f : p;
  };
  for (auto& a : neighbors)
    for (Face_handle& g : a) g = place(g);
  for (auto v = cdt.tds().vertices().begin(); v != cdt.tds().vertices().end(); ++v)
    if (v->face() != Face_handle()) v->set_face(place(v->face()));
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
  for (std::size_t k = 0; k < n; ++k) {
    const Face_handle f = slot[k];
    f->set_neighbors(neighbors[k][0], neighbors[k][1], neighbors[k][2]);
    if (f->is_blinded()) f->clear_blinding();  // stale after an insertion, if not dangling
  }
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

#endif  // CVT_2_INTERNAL_SORT_FACES_H
