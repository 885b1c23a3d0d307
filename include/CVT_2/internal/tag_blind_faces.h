// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Algorithm 1 of the paper: tag the blind faces of the domain with their first blinding edge.
#ifndef CVT_2_INTERNAL_TAG_BLIND_FACES_H
#define CVT_2_INTERNAL_TAG_BLIND_FACES_H

#include <CVT_2/internal/Handle_set.h>
#include <CVT_2/internal/parallel/Face_chunks.h>

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <unordered_set>
#include <utility>
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
// now, replaces the face's tag t. The first edge met is never met at a tie, so the tag does not
// depend on the order the edges are met in (a local update then gives a rebuild's tags): a
// vertex on the way from the centroid to the circumcenter lies inside the circumdisk, so a
// constraint hides it, and the way meets that constraint first, inside the edge.
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

// The side of the constrained edge e that a face blinded by it stores: the domain face on the
// side of e's line where most of f's vertices lie (the left of the edge's endpoints in
// lexicographic order on a tie). Which side a walk reached f from does not matter, so neither
// does the order of the walks.
template <class CDT>
typename CDT::Edge side_toward(const CDT& cdt, typename CDT::Face_handle f,
                               const typename CDT::Edge& e) {
  typename CDT::Edge left = e, right = cdt.mirror_edge(e);  // left.first is left of a -> b
  const auto* a = &e.first->vertex(CDT::ccw(e.second))->point();
  const auto* b = &e.first->vertex(CDT::cw(e.second))->point();
  if (*b < *a) std::swap(left, right), std::swap(a, b);
  const auto orientation = cdt.geom_traits().orientation_2_object();
  int sum = 0;
  for (int i = 0; i < 3; ++i) sum += int(orientation(*a, *b, f->vertex(i)->point()));
  typename CDT::Edge pick = sum >= 0 ? left : right, other = sum >= 0 ? right : left;
  if (cdt.is_infinite(pick.first) || !pick.first->is_inside_domain()) std::swap(pick, other);
  return pick;
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
    return f->is_blinded() && is_same_constraint<CDT>(f->blinding_edge(), e);
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
        f->set_blinding_edge(side_toward(cdt, f, e));
        ++count;
      } else if (blinds_first<CDT>(traits, f, e, f->blinding_edge())) {
        f->set_blinding_edge(side_toward(cdt, f, e));
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

// The faces of the domain that the constrained edge e blinds, into `out`: Algorithm 1's walk
// from each of its domain sides. `seen` and `stack` are scratch.
template <class CDT, class Traits, class Faces>
void faces_blinded_by(const CDT& cdt, const Traits& traits, const typename CDT::Edge& e, Faces& out,
                      Handle_set<typename CDT::Face_handle>& seen,
                      std::vector<typename CDT::Face_handle>& stack) {
  const auto is_blinded = traits.is_blinded_2_object();
  const auto& a = e.first->vertex(CDT::ccw(e.second))->point();
  const auto& b = e.first->vertex(CDT::cw(e.second))->point();
  seen.clear();
  stack.clear();
  for (const auto& side : {e, cdt.mirror_edge(e)})
    if (!cdt.is_infinite(side.first) && side.first->is_inside_domain()) stack.push_back(side.first);
  while (!stack.empty()) {
    const auto f = stack.back();
    stack.pop_back();
    if (!seen.insert(f)) continue;
    if (!is_blinded(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(), a, b))
      continue;
    out.insert(f);
    for (int i = 0; i < 3; ++i) {
      const auto n = f->neighbor(i);
      if (!f->is_constrained(i) && !cdt.is_infinite(n) && n->is_inside_domain()) stack.push_back(n);
    }
  }
}

// Whether the segment [a, b] passes within sqrt(tol2) of the segment [p, q], in floating point
// (the walk below widens by tol2 what it follows, the exact predicate decides).
inline bool segments_near(double px, double py, double qx, double qy, double ax, double ay,
                          double bx, double by, double tol2) {
  const auto cross = [](double ux, double uy, double vx, double vy) { return ux * vy - uy * vx; };
  const double d1 = cross(qx - px, qy - py, ax - px, ay - py);
  const double d2 = cross(qx - px, qy - py, bx - px, by - py);
  const double d3 = cross(bx - ax, by - ay, px - ax, py - ay);
  const double d4 = cross(bx - ax, by - ay, qx - ax, qy - ay);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;  // they cross
  const auto point_segment = [](double x, double y, double ux, double uy, double vx, double vy) {
    const double dx = vx - ux, dy = vy - uy, len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((x - ux) * dx + (y - uy) * dy) / len2 : 0;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    const double ex = ux + t * dx - x, ey = uy + t * dy - y;
    return ex * ex + ey * ey;
  };
  return std::min({point_segment(ax, ay, px, py, qx, qy), point_segment(bx, by, px, py, qx, qy),
                   point_segment(px, py, ax, ay, bx, by), point_segment(qx, qy, ax, ay, bx, by)}) <=
         tol2;
}

// The tag Algorithm 1 gives the domain face f, found from f alone: among the constrained edges
// that blind f, the first met (blinds_first), on the side side_toward() picks; false if none
// blinds f. The first edge met on the way from f's centroid g to its circumcenter c is reached
// from f through unconstrained edges that the way crosses: a walk through the faces whose
// edges pass near [g, c] (widened for the rounded g and c) finds it, in as many faces as the
// way crosses. That this is Algorithm 1's tag rests on what Algorithm 1 rests on: the faces an
// edge blinds are connected to it.
template <class CDT, class Traits>
bool first_blinding_edge(const CDT& cdt, const Traits& traits, typename CDT::Face_handle f,
                         typename CDT::Edge& first, Handle_set<typename CDT::Face_handle>& seen,
                         std::vector<typename CDT::Face_handle>& stack) {
  using Point_2 = typename CDT::Point_2;
  const auto is_blinded = traits.is_blinded_2_object();
  const Point_2 &p = f->vertex(0)->point(), &q = f->vertex(1)->point(), &r = f->vertex(2)->point();
  const Point_2 c = traits.construct_circumcenter_2_object()(p, q, r);
  const auto x = [](const Point_2& a) { return CGAL::to_double(a.x()); };
  const auto y = [](const Point_2& a) { return CGAL::to_double(a.y()); };
  const double gx = (x(p) + x(q) + x(r)) / 3, gy = (y(p) + y(q) + y(r)) / 3;
  const double cx = x(c), cy = y(c);
  const double size = std::abs(cx - gx) + std::abs(cy - gy) + std::abs(x(q) - x(p)) +
                      std::abs(y(q) - y(p)) + std::abs(x(r) - x(p)) + std::abs(y(r) - y(p));
  const double magnitude = std::max({std::abs(gx), std::abs(gy), std::abs(cx), std::abs(cy)});
  const double tol = 1e-7 * size + 1e-14 * magnitude, tol2 = tol * tol;
  bool found = false;
  seen.clear();
  stack.assign(1, f);
  seen.insert(f);
  while (!stack.empty()) {
    const auto h = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const auto va = h->vertex(CDT::ccw(i)), vb = h->vertex(CDT::cw(i));
      if (cdt.is_infinite(va) || cdt.is_infinite(vb)) continue;
      const Point_2 &a = va->point(), &b = vb->point();
      if (!segments_near(gx, gy, cx, cy, x(a), y(a), x(b), y(b), tol2)) continue;
      if (h->is_constrained(i)) {
        const typename CDT::Edge e(h, i);
        if (is_blinded(p, q, r, a, b) && (!found || blinds_first<CDT>(traits, f, e, first)))
          first = e, found = true;
        continue;
      }
      const auto n = h->neighbor(i);
      if (!cdt.is_infinite(n) && seen.insert(n)) stack.push_back(n);
    }
  }
  if (found) first = side_toward(cdt, f, first);
  return found;
}

// Tags the faces `faces` again, each from itself (first_blinding_edge()); the other faces keep
// their tags. Returns how many of them are blinded. `seen` and `stack` are scratch.
template <class CDT, class Traits, class Faces>
std::size_t retag_faces(const CDT& cdt, const Traits& traits, const Faces& faces,
                        Handle_set<typename CDT::Face_handle>& seen,
                        std::vector<typename CDT::Face_handle>& stack) {
  std::size_t count = 0;
  for (const auto f : faces) {
    typename CDT::Edge e;
    if (!cdt.is_infinite(f) && f->is_inside_domain() &&
        first_blinding_edge(cdt, traits, f, e, seen, stack)) {
      f->set_blinding_edge(e);
      ++count;
    } else if (f->is_blinded()) {
      f->clear_blinding();
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
