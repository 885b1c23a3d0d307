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

// Algorithm 2 on a fan: the faces around a generator v, counterclockwise. `Fan` provides
//   size(); starts_wedges(): whether the fan begins after a constrained edge (a constrained v;
//   else it is the whole cycle of a free v); for face j: inside(j), blind(j), blinding(j) (a
//   Constraint), circumcenter(j); after(j), the vertex face j shares with face j + 1 (w_j),
//   before(j), the one it shares with face j - 1, and the edges (v, after(j)) and (v, before(j))
//   as edge_after(j), edge_before(j), constrained_after(j); same(c1, c2) for two Constraints;
//   clip_point(w, c), where the bisector of v and w meets c; midpoint(w) of v and w; generator().
// emit(point, type, j, constraint, w) is called for each cell vertex in turn, as the chain makes
// it: a point may come twice in a row (a circumcenter on a constraint is also a clip point
// there; cocircular faces share their circumcenter), and the last may equal the first. j is the
// fan index of a circumcenter's face (else the size of the fan); w the generator across the
// cell edge that leaves a circumcenter, or the other generator of a clip point's bisector.
//
// Around v the faces f_1 ... f_k turn counterclockwise; f_j and f_j+1 share the edge (v, w_j),
// whose Voronoi edge lies on the bisector of v and w_j and joins the circumcenters of f_j and
// f_j+1. Algorithm 2 walks this chain: a face that sees its circumcenter contributes it;
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
template <class Fan, class Emit>
void fan_chain(const Fan& fan, const Emit& emit) {
  using Constraint = typename Fan::Constraint;
  using Vertex = typename Fan::Vertex;
  using Type = typename Fan::Type;
  const std::size_t k = fan.size(), none = k;

  // A node of the chain: a circumcenter, the midpoint of a constrained edge, or, when hidden,
  // the constraint that hides it.
  struct Node {
    bool blind;
    Constraint constraint;  // the blinding edge (blind) or the edge the midpoint lies on
    std::size_t face;       // in the fan, or none
  };
  const auto face_node = [&](std::size_t j) {
    return fan.blind(j) ? Node{true, fan.blinding(j), j} : Node{false, Constraint(), j};
  };
  const auto push_clip = [&](const Vertex& w, const Constraint& c) {
    emit(fan.clip_point(w, c), Type::CLIP_POINT, none, c, w);
  };
  // Node x to node y along the bisector of v and w.
  const auto transition = [&](const Node& x, const Node& y, const Vertex& w) {
    if (!x.blind && y.blind) {
      push_clip(w, y.constraint);
    } else if (x.blind && !y.blind) {
      push_clip(w, x.constraint);
    } else if (x.blind && y.blind && !fan.same(x.constraint, y.constraint)) {
      push_clip(w, x.constraint);
      push_clip(w, y.constraint);
    }
  };
  const auto push_circumcenter = [&](const Node& n, const Vertex& w) {
    emit(fan.circumcenter(n.face), Type::CIRCUMCENTER, n.face, Constraint(), w);
  };
  // The chain's end on the constrained edge e = (v, w) of a face whose node is fn.
  const auto end_node = [&](const Node& fn, const Constraint& e) {
    return fn.blind && fan.same(fn.constraint, e) ? Node{true, e, none} : Node{false, e, none};
  };
  const auto push_midpoint = [&](const Node& n, const Vertex& w) {
    emit(fan.midpoint(w), Type::CLIP_POINT, none, n.constraint, w);
  };

  if (!fan.starts_wedges()) {  // a free vertex: one cyclic chain (the paper's case)
    if (!fan.inside(0)) return;
    const Node start = face_node(0);
    Node x = start;
    for (std::size_t j = 0; j < k; ++j) {
      const Vertex w = fan.after(j);
      if (!x.blind) push_circumcenter(x, w);
      const Node y = j + 1 == k ? start : face_node(j + 1);
      transition(x, y, w);
      x = y;
    }
    return;
  }
  for (std::size_t j = 0; j < k;) {  // one wedge, from face j to the next constrained edge
    if (!fan.inside(j)) {
      while (!fan.constrained_after(j)) ++j;
      ++j;
      continue;
    }
    emit(fan.generator(), Type::GENERATOR, none, Constraint(), Vertex());
    Vertex w = fan.before(j);
    Node x = end_node(face_node(j), fan.edge_before(j));
    if (!x.blind) push_midpoint(x, w);
    for (;; ++j) {
      const Node y = face_node(j);
      transition(x, y, w);
      x = y;
      w = fan.after(j);
      if (!y.blind) push_circumcenter(y, w);
      if (fan.constrained_after(j)) {
        const Node last = end_node(x, fan.edge_after(j));
        transition(x, last, w);
        if (!last.blind) push_midpoint(last, w);
        ++j;
        break;
      }
    }
  }
}

// The faces around a vertex of a triangulation as fan_chain() reads them: each face with the
// index of v in it, from a face that follows a constrained edge if v has one.
template <class CDT, class Traits, class Cell_vertex>
class Cdt_fan {
 public:
  using Face_handle = typename CDT::Face_handle;
  using Vertex = typename CDT::Vertex_handle;
  using Constraint = typename CDT::Edge;
  using Point_2 = typename CDT::Point_2;
  using Type = typename Cell_vertex::Type;

  Cdt_fan(const CDT& cdt, const Traits& traits, Vertex v)
      : m_circumcenter(traits.construct_circumcenter_2_object()),
        m_clip_point(traits.construct_clip_point_2_object()),
        m_v(v) {
    auto fc = cdt.incident_faces(v);
    const auto done = fc;
    do {
      const int i = fc->index(v);
      if (!m_wedges && fc->is_constrained(CDT::cw(i))) {
        m_wedges = true;
        m_first = m_faces.size();
      }
      m_faces.emplace_back(fc, i);
    } while (++fc != done);
  }

  std::size_t size() const { return m_faces.size(); }
  bool starts_wedges() const { return m_wedges; }
  Face_handle face(std::size_t j) const { return at(j).first; }
  bool inside(std::size_t j) const { return face(j)->is_inside_domain(); }
  bool blind(std::size_t j) const { return face(j)->is_blinded(); }
  Constraint blinding(std::size_t j) const { return face(j)->blinding_edge(); }
  Point_2 circumcenter(std::size_t j) const {
    const Face_handle f = face(j);
    return m_circumcenter(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
  }
  Vertex after(std::size_t j) const { return face(j)->vertex(CDT::cw(at(j).second)); }
  Vertex before(std::size_t j) const { return face(j)->vertex(CDT::ccw(at(j).second)); }
  Constraint edge_after(std::size_t j) const { return Constraint(face(j), CDT::ccw(at(j).second)); }
  Constraint edge_before(std::size_t j) const { return Constraint(face(j), CDT::cw(at(j).second)); }
  bool constrained_after(std::size_t j) const {
    return face(j)->is_constrained(CDT::ccw(at(j).second));
  }
  bool same(const Constraint& a, const Constraint& b) const {
    return is_same_constraint<CDT>(a, b);
  }
  Point_2 clip_point(Vertex w, const Constraint& c) const {
    return m_clip_point(m_v->point(), w->point(), c.first->vertex(CDT::ccw(c.second))->point(),
                        c.first->vertex(CDT::cw(c.second))->point());
  }
  Point_2 midpoint(Vertex w) const { return CGAL::midpoint(m_v->point(), w->point()); }
  const Point_2& generator() const { return m_v->point(); }

 private:
  const std::pair<Face_handle, int>& at(std::size_t j) const {
    const std::size_t k = m_faces.size();
    return m_faces[m_first + j < k ? m_first + j : m_first + j - k];  // j < 2k: no division
  }

  decltype(std::declval<const Traits&>().construct_circumcenter_2_object()) m_circumcenter;
  decltype(std::declval<const Traits&>().construct_clip_point_2_object()) m_clip_point;
  Vertex m_v;
  boost::container::small_vector<std::pair<Face_handle, int>, 16> m_faces;
  std::size_t m_first = 0;
  bool m_wedges = false;
};

// fan_chain() on a Cdt_fan (or a class derived from one), each cell vertex as a `Cell_vertex`.
template <class Cell_vertex, class Fan, class Emit>
void fan_cell_chain(const Fan& fan, const Emit& emit) {
  fan_chain(fan, [&](const typename Fan::Point_2& p, typename Fan::Type type, std::size_t j,
                     const typename Fan::Constraint& c, typename Fan::Vertex w) {
    emit(Cell_vertex{p, type, j < fan.size() ? fan.face(j) : typename Fan::Face_handle(), c, w});
  });
}

// The cell of v, counterclockwise: emit(c) for each of its vertices c in turn, a `Cell_vertex`,
// as fan_chain() makes it (a point may come twice in a row; nothing for a vertex without a cell).
template <class Cell_vertex, class CDT, class Traits, class Emit>
void construct_cell_chain(const CDT& cdt, const Traits& traits, typename CDT::Vertex_handle v,
                          const Emit& emit) {
  if (cdt.dimension() < 2 || cdt.is_infinite(v)) return;
  fan_cell_chain<Cell_vertex>(Cdt_fan<CDT, Traits, Cell_vertex>(cdt, traits, v), emit);
}

// The cell of v, counterclockwise, into `out` (cleared first), without repeated points.
template <class CDT, class Traits, class Cell_vertex>
void construct_cell(const CDT& cdt, const Traits& traits, typename CDT::Vertex_handle v,
                    std::vector<Cell_vertex>& out) {
  out.clear();
  construct_cell_chain<Cell_vertex>(cdt, traits, v, [&out](const Cell_vertex& c) {
    if (out.empty() || out.back().point != c.point) out.push_back(c);
  });
  if (out.size() > 1 && out.back().point == out.front().point) out.pop_back();
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_CONSTRUCT_CELL_H
