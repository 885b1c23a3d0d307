// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The lips of a vertex on constraints: the wedges of the domain between its constrained edges.
#ifndef CVT_2_INTERNAL_LIPS_H
#define CVT_2_INTERNAL_LIPS_H

#include <CGAL/enum.h>

#include <cstddef>

namespace CVT_2 {
namespace internal {

// Calls visit(f, lip) for each face f around v, counterclockwise, with the number of its lip:
// the wedges between consecutive constrained edges of v that lie in the domain are lips 0, 1,
// ... counterclockwise from the constrained edge whose other end is the smallest point (so the
// numbers depend on the geometry only, not on which face v points to), -1 for a face of
// another wedge. Returns the number of lips: 0 or 1 for a free vertex, a crack's tip or a
// vertex of the domain's boundary, 2 along a crack, more at junctions. visit returns true to
// stop.
template <class CDT, class Visit>
int for_each_face_by_lip(const CDT& cdt, typename CDT::Vertex_handle v, const Visit& visit) {
  auto fc = cdt.incident_faces(v), done = fc;
  if (fc == nullptr) return 0;
  auto start = fc;
  bool found = false;
  do {  // the face after that edge, counterclockwise, if there is one
    const int i = fc->index(v);
    if (!fc->is_constrained(CDT::cw(i))) continue;
    const auto end = fc->vertex(CDT::ccw(i));
    if (!found || (!cdt.is_infinite(end) &&
                   (cdt.is_infinite(start->vertex(CDT::ccw(start->index(v)))) ||
                    end->point() < start->vertex(CDT::ccw(start->index(v)))->point())))
      start = fc, found = true;
  } while (++fc != done);
  fc = done = start;
  int lips = 0, lip = -1;
  bool first = true;
  do {
    if (first || fc->is_constrained(CDT::cw(fc->index(v)))) {  // a wedge begins
      const bool in_domain = !cdt.is_infinite(fc) && fc->is_inside_domain();
      lip = in_domain ? lips++ : -1;
      first = false;
    }
    if (visit(fc, lip)) return lips;
  } while (++fc != done);
  return lips;
}

// The number of lips of v (for_each_face_by_lip()).
template <class CDT>
int number_of_lips(const CDT& cdt, typename CDT::Vertex_handle v) {
  return for_each_face_by_lip(cdt, v, [](auto, int) { return false; });
}

// Calls out(lip) for each lip of v whose wedge, closed, holds the direction to q: one, or the
// two beside a constraint of v that q lies on the line of, beyond v (each once).
template <class CDT, class Out>
void lips_toward(const CDT& cdt, typename CDT::Vertex_handle v, const typename CDT::Point_2& q,
                 const Out& out) {
  const auto orientation = cdt.geom_traits().orientation_2_object();
  const auto& x = v->point();
  int last = -1;
  for_each_face_by_lip(cdt, v, [&](typename CDT::Face_handle f, int lip) {
    if (lip < 0 || lip == last || cdt.is_infinite(f)) return false;
    const int i = f->index(v);
    const auto& a = f->vertex(CDT::ccw(i))->point();
    const auto& b = f->vertex(CDT::cw(i))->point();
    if (orientation(x, a, q) != CGAL::RIGHT_TURN && orientation(x, b, q) != CGAL::LEFT_TURN)
      out(last = lip);
    return false;
  });
}

// The lip of v that q lies in, seen from v: that of the first face around v whose angle at v
// holds the direction to q (q on a constraint of v: one of the lips beside it; q at v: lip 0);
// -1 if none (q outside the domain). Exact orientation tests.
template <class CDT>
int lip_toward(const CDT& cdt, typename CDT::Vertex_handle v, const typename CDT::Point_2& q) {
  const auto orientation = cdt.geom_traits().orientation_2_object();
  const auto& x = v->point();
  int found = -1;
  for_each_face_by_lip(cdt, v, [&](typename CDT::Face_handle f, int lip) {
    if (lip < 0 || cdt.is_infinite(f)) return false;
    const int i = f->index(v);
    const auto& a = f->vertex(CDT::ccw(i))->point();
    const auto& b = f->vertex(CDT::cw(i))->point();
    if (orientation(x, a, q) == CGAL::RIGHT_TURN || orientation(x, b, q) == CGAL::LEFT_TURN)
      return false;
    found = lip;
    return true;
  });
  return found;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_LIPS_H
