// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Algorithm 2 of the paper, extended to every vertex of the domain: build one BVD cell.
#ifndef CVT_2_INTERNAL_CONSTRUCT_CELL_H
#define CVT_2_INTERNAL_CONSTRUCT_CELL_H

#include <CVT_2/internal/tag_blind_faces.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/number_utils.h>

#include <boost/container/small_vector.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// The cell of v, counterclockwise, into `out` (cleared first).
//
// Around v the incident faces f_1 ... f_k turn counterclockwise; f_j and f_j+1 share the edge
// (v, w_j), whose Voronoi edge lies on the bisector of v and w_j and joins the circumcenters of
// f_j and f_j+1. Algorithm 2 walks this chain: a face that sees its circumcenter contributes it;
// between a seeing and a blind face, or two faces blinded by different constraints, the chain
// leaves or re-enters the visible region, and the clip point (bisector ∩ blinding constraint)
// is inserted.
//
// The paper stops at free vertices. Here the constrained edges around v cut the faces into
// wedges; each wedge in the domain is a fan from a constrained edge (v, a) to a constrained
// edge (v, b), and its chain starts on (v, a) and ends on (v, b): at the midpoint, where the
// bisector of v and a crosses (v, a), unless the first face is itself blinded by (v, a), in
// which case that bisector stays beyond (v, a) and the chain starts at the first clip point.
// The wedge's cell part is v, then its chain. Wedges follow each other around v, so a vertex
// on inner constraints gets one polygon that goes back to v along each constraint: the
// constraints cross it as slits.
template <class CDT, class Traits, class Cell_vertex>
void construct_cell(const CDT& cdt, const Traits& traits, typename CDT::Vertex_handle v,
                    std::vector<Cell_vertex>& out) {
  using Face_handle = typename CDT::Face_handle;
  using Vertex_handle = typename CDT::Vertex_handle;
  using Edge = typename CDT::Edge;
  using Point_2 = typename CDT::Point_2;
  using Type = typename Cell_vertex::Type;

  out.clear();
  if (cdt.dimension() < 2 || cdt.is_infinite(v)) return;
  const auto circumcenter = traits.construct_circumcenter_2_object();
  const auto clip_point = traits.construct_clip_point_2_object();

  // A node of the chain: a circumcenter, the midpoint of a constrained edge, or, when hidden,
  // the constraint that hides it.
  struct Node {
    bool blind;
    Edge constraint;  // the blinding edge (blind) or the edge the midpoint lies on
    Face_handle face;
  };
  const auto face_node = [](Face_handle f) {
    return f->is_blinded() ? Node{true, f->blinding_edge(), f} : Node{false, Edge(), f};
  };
  const auto push = [&out](const Point_2& p, Type type, Face_handle f, const Edge& c,
                           Vertex_handle w) {
    if (!out.empty() && out.back().point == p) return;  // a circumcenter on a constraint
    out.push_back(Cell_vertex{p, type, f, c, w});
  };
  const auto push_clip = [&](Vertex_handle w, const Edge& c) {
    const Point_2& a = c.first->vertex(CDT::ccw(c.second))->point();
    const Point_2& b = c.first->vertex(CDT::cw(c.second))->point();
    push(clip_point(v->point(), w->point(), a, b), Cell_vertex::CLIP_POINT, Face_handle(), c, w);
  };
  // Node x to node y along the bisector of v and w.
  const auto transition = [&](const Node& x, const Node& y, Vertex_handle w) {
    if (!x.blind && y.blind) {
      push_clip(w, y.constraint);
    } else if (x.blind && !y.blind) {
      push_clip(w, x.constraint);
    } else if (x.blind && y.blind && !is_same_constraint<CDT>(x.constraint, y.constraint)) {
      push_clip(w, x.constraint);
      push_clip(w, y.constraint);
    }
  };
  const auto push_circumcenter = [&](const Node& n) {
    push(circumcenter(n.face->vertex(0)->point(), n.face->vertex(1)->point(),
                      n.face->vertex(2)->point()),
         Cell_vertex::CIRCUMCENTER, n.face, Edge(), Vertex_handle());
  };
  // The chain's end on the constrained edge e = (v, w) of face f.
  const auto end_node = [&](const Node& fn, const Edge& e) {
    return fn.blind && is_same_constraint<CDT>(fn.constraint, e) ? Node{true, e, Face_handle()}
                                                                 : Node{false, e, Face_handle()};
  };
  const auto push_midpoint = [&](const Node& n, Vertex_handle w) {
    push(CGAL::midpoint(v->point(), w->point()), Cell_vertex::CLIP_POINT, Face_handle(),
         n.constraint, w);
  };

  // One turn around v, recording the fan: each face with the index of v in it. A face that
  // follows a constrained edge, counterclockwise, starts a wedge.
  boost::container::small_vector<std::pair<Face_handle, int>, 16> fan;
  std::size_t first = 0;
  bool has_constraint = false;
  auto fc = cdt.incident_faces(v);
  const auto done = fc;
  do {
    const int i = fc->index(v);
    if (!has_constraint && fc->is_constrained(CDT::cw(i))) {
      has_constraint = true;
      first = fan.size();
    }
    fan.emplace_back(fc, i);
  } while (++fc != done);
  const std::size_t k = fan.size();
  const auto at = [&](std::size_t j) -> const std::pair<Face_handle, int>& {
    return fan[first + j < k ? first + j : first + j - k];  // j < 2k: no division
  };
  const auto face = [&](std::size_t j) { return at(j).first; };
  const auto index = [&](std::size_t j) { return at(j).second; };

  if (!has_constraint) {  // a free vertex: one cyclic chain (the paper's case)
    if (!face(0)->is_inside_domain()) return;
    const Node start = face_node(face(0));
    Node x = start;
    for (std::size_t j = 0; j < k; ++j) {
      if (!x.blind) push_circumcenter(x);
      const Node y = j + 1 == k ? start : face_node(face(j + 1));
      transition(x, y, face(j)->vertex(CDT::cw(index(j))));
      x = y;
    }
  } else {
    for (std::size_t j = 0; j < k;) {  // one wedge, from face j to the next constrained edge
      if (!face(j)->is_inside_domain()) {
        while (!face(j)->is_constrained(CDT::ccw(index(j)))) ++j;
        ++j;
        continue;
      }
      push(v->point(), Cell_vertex::GENERATOR, Face_handle(), Edge(), Vertex_handle());
      Vertex_handle w = face(j)->vertex(CDT::ccw(index(j)));
      Node x = end_node(face_node(face(j)), Edge(face(j), CDT::cw(index(j))));
      if (!x.blind) push_midpoint(x, w);
      for (;; ++j) {
        const Node y = face_node(face(j));
        transition(x, y, w);
        if (!y.blind) push_circumcenter(y);
        x = y;
        w = face(j)->vertex(CDT::cw(index(j)));
        const Edge after(face(j), CDT::ccw(index(j)));
        if (face(j)->is_constrained(after.second)) {
          const Node last = end_node(x, after);
          transition(x, last, w);
          if (!last.blind) push_midpoint(last, w);
          ++j;
          break;
        }
      }
    }
  }
  if (out.size() > 1 && out.back().point == out.front().point) out.pop_back();
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_CONSTRUCT_CELL_H
