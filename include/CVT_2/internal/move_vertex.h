// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Moving a free vertex in place: within its star, then edge flips back to constrained Delaunay.
#ifndef CVT_2_INTERNAL_MOVE_VERTEX_H
#define CVT_2_INTERNAL_MOVE_VERTEX_H

#include <CVT_2/internal/prefetch.h>

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// An edge to examine: a face and an index, and the edge's vertices, which tell whether a flip
// since has made (face, index) another edge.
template <class CDT>
struct Flip_candidate {
  typename CDT::Face_handle f;
  int i;
  typename CDT::Vertex_handle a, b;

  // The edge i of f, as it is now.
  static Flip_candidate of(typename CDT::Face_handle f, int i) {
    return {f, i, f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i))};
  }
};

// Lawson's flips: an edge on the stack that is not constrained and fails the (symbolically
// perturbed) empty-circle test is flipped, and the four edges around it are examined in turn.
// From any valid constrained triangulation this ends at the constrained Delaunay one.
template <class CDT>
void lawson_flips(CDT& cdt, std::vector<Flip_candidate<CDT>>& stack) {
  using Face_handle = typename CDT::Face_handle;
  while (!stack.empty()) {
    Flip_candidate<CDT> e = stack.back();
    stack.pop_back();
    if (e.f->vertex(CDT::ccw(e.i)) != e.a || e.f->vertex(CDT::cw(e.i)) != e.b) {
      if (!cdt.is_edge(e.a, e.b, e.f, e.i)) continue;  // flipped away
    }
    if (!cdt.is_flipable(e.f, e.i)) continue;
    Face_handle f = e.f;
    const Face_handle g = f->neighbor(e.i);
    cdt.flip(f, e.i);
    // The two faces now share the new edge; their four other edges are examined.
    for (const Face_handle h : {f, g}) {
      const int k = h->index(h == f ? g : f);
      stack.push_back(Flip_candidate<CDT>::of(h, CDT::ccw(k)));
      stack.push_back(Flip_candidate<CDT>::of(h, CDT::cw(k)));
    }
  }
}

// Calls visit(f) for every face f of [first, last), in memory order. The vertices and neighbors
// of a face some steps ahead, then the neighbors' vertices opposite to it, are prefetched:
// orientation and in-circle tests read all of them.
template <class Face_iterator, class Visit>
void for_each_face_prefetched(Face_iterator first, Face_iterator last, const Visit& visit) {
  constexpr int distance = 8;
  auto ahead = first, ahead2 = first;
  for (int i = 0; i < 2 * distance && ahead != last; ++i) ++ahead;
  for (int i = 0; i < distance && ahead2 != last; ++i) ++ahead2;
  for (auto f = first; f != last; ++f) {
    if (ahead != last) {
      for (int i = 0; i < 3; ++i) {
        prefetch(&*ahead->vertex(i));
        prefetch(&*ahead->neighbor(i));
      }
      ++ahead;
    }
    if (ahead2 != last) {
      for (int i = 0; i < 3; ++i) {
        const auto g = ahead2->neighbor(i);
        prefetch(&*g->vertex(g->index(ahead2)));
      }
      ++ahead2;
    }
    visit(f);
  }
}

// Whether the domain face f is the one to test its unconstrained edge i, so that a pass over
// the domain faces tests each edge once: the edge's only domain face, or of its two the one
// that sees the edge's smaller endpoint in (x, y) order first, counterclockwise (the other sees
// the endpoints the other way round). Not by address: the flips, hence the faces' layout and all
// sums over them, must be the same from run to run.
template <class CDT, class Less_xy>
bool tests_edge(const CDT& cdt, typename CDT::Face_handle f, int i, const Less_xy& less_xy) {
  if (f->is_constrained(i)) return false;
  const auto g = f->neighbor(i);
  return !g->is_inside_domain() || cdt.is_infinite(g) ||
         !less_xy(f->vertex(CDT::cw(i))->point(), f->vertex(CDT::ccw(i))->point());
}

// Restores the constrained Delaunay property of the domain after its free vertices moved:
// every edge with a domain face on its side is tested in place, and Lawson's flips start from
// those that fail, so the stack holds only the few edges around flips.
template <class CDT>
void restore_delaunay(CDT& cdt, std::vector<Flip_candidate<CDT>>& stack) {
  const auto less_xy = cdt.geom_traits().less_xy_2_object();
  for_each_face_prefetched(cdt.finite_faces_begin(), cdt.finite_faces_end(),
                           [&](typename CDT::Face_handle f) {
    if (!f->is_inside_domain()) return;
    for (int i = 0; i < 3; ++i) {
      if (!tests_edge(cdt, f, i, less_xy) || !cdt.is_flipable(f, i)) continue;
      stack.assign(1, Flip_candidate<CDT>::of(f, i));
      lawson_flips(cdt, stack);
    }
  });
}

// Moves the free vertex v toward `target`, as far as its star stays valid: every face around v
// keeps its orientation, so the move changes no topology and crosses no edge, constrained or
// not. If the target lies beyond the star's link, v goes halfway to the link along the way
// (each later iteration, after the flips, goes on from there). The triangulation stays valid
// but may no longer be Delaunay: restore_delaunay() follows. Returns the fraction of the way
// done (0: v did not move).
template <class CDT>
double move_free_vertex(const CDT& cdt, typename CDT::Vertex_handle v,
                        const typename CDT::Point_2& target) {
  using Point_2 = typename CDT::Point_2;
  using FT = typename CDT::Geom_traits::FT;
  const Point_2 x = v->point();
  if (x == target) return 1;
  const auto orientation = cdt.geom_traits().orientation_2_object();
  boost::container::small_vector<std::pair<Point_2, Point_2>, 16> link;
  auto fc = cdt.incident_faces(v), done = fc;
  do {
    const int i = fc->index(v);
    link.emplace_back(fc->vertex(CDT::ccw(i))->point(), fc->vertex(CDT::cw(i))->point());
  } while (++fc != done);
  // orientation(a, b, x + t (target - x)) is affine in t, positive at t = 0: the largest t
  // that keeps every face positive, in floating point; exact tests decide below.
  FT t_max = 1;
  for (const auto& [a, b] : link) {
    const FT ux = b.x() - a.x(), uy = b.y() - a.y();
    const FT o0 = ux * (x.y() - a.y()) - uy * (x.x() - a.x());
    const FT o1 = ux * (target.y() - a.y()) - uy * (target.x() - a.x());
    if (o1 <= 0 && o0 > o1) t_max = std::min(t_max, o0 / (o0 - o1));
  }
  FT t = t_max >= 1 ? FT(1) : t_max / 2;
  for (int attempt = 0; attempt < 16; ++attempt, t /= 2) {
    const Point_2 p = t == 1 ? target
                             : Point_2(x.x() + t * (target.x() - x.x()),
                                       x.y() + t * (target.y() - x.y()));
    const bool valid = std::all_of(link.begin(), link.end(), [&](const auto& e) {
      return orientation(e.first, e.second, p) == CGAL::LEFT_TURN;
    });
    if (!valid) continue;
    v->set_point(p);
    return CGAL::to_double(t);
  }
  return 0;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_MOVE_VERTEX_H
