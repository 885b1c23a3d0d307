// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Algorithm 1 of the paper: tag the blind faces of the domain with their first blinding edge.
#ifndef CVT_2_INTERNAL_TAG_BLIND_FACES_H
#define CVT_2_INTERNAL_TAG_BLIND_FACES_H

#include <CVT_2/internal/parallel/Face_chunks.h>

#include <CGAL/enum.h>

#include <cstddef>
#include <unordered_set>
#include <vector>

namespace CVT_2 {
namespace internal {

template <class CDT>
bool is_same_constraint(const typename CDT::Edge& e1, const typename CDT::Edge& e2) {
  const auto a1 = e1.first->vertex(CDT::ccw(e1.second)), b1 = e1.first->vertex(CDT::cw(e1.second));
  const auto a2 = e2.first->vertex(CDT::ccw(e2.second)), b2 = e2.first->vertex(CDT::cw(e2.second));
  return (a1 == a2 && b1 == b2) || (a1 == b2 && b1 == a2);
}

// Which of two blinding edges a face keeps: the first one met on the way to its circumcenter,
// where Algorithm 2 must clip (with nested constraints the farther one is not). True if e, met
// now, replaces the face's tag t.
template <class CDT, class Traits>
bool blinds_first(const Traits& traits, typename CDT::Face_handle f, const typename CDT::Edge& e,
                  const typename CDT::Edge& t) {
  if (is_same_constraint<CDT>(t, e)) return false;
  const auto& a = e.first->vertex(CDT::ccw(e.second))->point();
  const auto& b = e.first->vertex(CDT::cw(e.second))->point();
  const auto& ta = t.first->vertex(CDT::ccw(t.second))->point();
  const auto& tb = t.first->vertex(CDT::cw(t.second))->point();
  return traits.compare_blinding_distance_2_object()(f->vertex(0)->point(), f->vertex(1)->point(),
                                                     f->vertex(2)->point(), a, b, ta,
                                                     tb) == CGAL::SMALLER;
}

// Clears every tag of the faces [first, last) (writing only to the faces that have one) and
// appends to `sides` the sides of constrained edges that domain faces among them lie on:
// Algorithm 1's loop runs over them.
template <class CDT, class Face_iterator>
void clear_tags_and_list_constraint_sides(const CDT& cdt, Face_iterator first, Face_iterator last,
                                          std::vector<typename CDT::Edge>& sides) {
  const bool planar = cdt.dimension() == 2;
  for (auto f = first; f != last; ++f) {
    if (f->is_blinded()) f->clear_blinding();
    if (planar && f->is_inside_domain() && !cdt.is_infinite(f))
      for (int i = 0; i < 3; ++i)
        if (f->is_constrained(i)) sides.emplace_back(f, i);
  }
}

// Algorithm 1, from the constraint sides that clear_tags_and_list_constraint_sides() lists: tags
// every face of the domain that a constraint hides from its circumcenter with the first such
// constraint; returns the number of blinded faces.
//
// The faces blinded by a constrained edge e are connected through unconstrained edges and reach
// e (the Voronoi diagram of their vertices on one side of e is a tree rooted at the dual ray of
// e), so a stack walk from each side of e finds them all. A face can be blinded by several
// nested constraints; it keeps the first one met (blinds_first). The walk therefore goes on
// through faces tagged by another constraint, and remembers them in `elsewhere` so as to visit
// each face once per walk.
template <class CDT, class Traits>
std::size_t tag_blind_faces_from(const CDT& cdt, const Traits& traits,
                                 const std::vector<typename CDT::Edge>& sides) {
  using Face_handle = typename CDT::Face_handle;
  using Edge = typename CDT::Edge;
  const auto is_blinded = traits.is_blinded_2_object();
  const auto tagged_by = [](Face_handle f, const Edge& e) {
    if (!f->is_blinded()) return false;
    const Edge t = f->blinding_edge();
    return t.first == e.first && t.second == e.second;
  };
  std::size_t count = 0;
  std::vector<Face_handle> stack;
  std::unordered_set<Face_handle> elsewhere;  // blinded by e, but first by another constraint
  for (const Edge& e : sides) {
    const auto& a = e.first->vertex(CDT::ccw(e.second))->point();
    const auto& b = e.first->vertex(CDT::cw(e.second))->point();
    stack.assign(1, e.first);
    elsewhere.clear();
    while (!stack.empty()) {
      const Face_handle f = stack.back();
      stack.pop_back();
      if (tagged_by(f, e) || elsewhere.count(f) != 0) continue;
      if (!is_blinded(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(), a, b))
        continue;
      if (!f->is_blinded()) {
        f->set_blinding_edge(e);
        ++count;
      } else if (blinds_first<CDT>(traits, f, e, f->blinding_edge())) {
        f->set_blinding_edge(e);
      } else {
        elsewhere.insert(f);
      }
      for (int i = 0; i < 3; ++i) {
        const Face_handle n = f->neighbor(i);
        if (!f->is_constrained(i) && !cdt.is_infinite(n) && n->is_inside_domain())
          stack.push_back(n);
      }
    }
  }
  return count;
}

// Algorithm 1 on the whole triangulation, its tags cleared first.
template <class CDT, class Traits>
std::size_t tag_blind_faces(const CDT& cdt, const Traits& traits) {
  std::vector<typename CDT::Edge> sides;
  clear_tags_and_list_constraint_sides(cdt, cdt.all_faces_begin(), cdt.all_faces_end(), sides);
  return tag_blind_faces_from(cdt, traits, sides);
}

// The same, the pass over the faces on `threads` threads in the chunks of `chunks` (up to date
// with `cdt`): the sides come out in the same order, and so do the tags.
template <class CDT, class Traits>
std::size_t tag_blind_faces(const CDT& cdt, const Traits& traits, const Face_chunks<CDT>& chunks,
                            unsigned threads) {
  if (chunks.size() == 0) return tag_blind_faces(cdt, traits);  // no plane: no chunks
  std::vector<Chunk_vector<typename CDT::Edge>> parts(chunks.size());
  chunks.for_each(
      [&](std::size_t c, auto first, auto last) {
        clear_tags_and_list_constraint_sides(cdt, first, last, parts[c]);
      },
      threads);
  std::vector<typename CDT::Edge> sides;
  for (const auto& part : parts) sides.insert(sides.end(), part.begin(), part.end());
  return tag_blind_faces_from(cdt, traits, sides);
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_TAG_BLIND_FACES_H
