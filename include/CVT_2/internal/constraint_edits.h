// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Helpers of Constraint_editor_2: the checks before an edit, and the domain flags of new faces.
#ifndef CVT_2_INTERNAL_CONSTRAINT_EDITS_H
#define CVT_2_INTERNAL_CONSTRAINT_EDITS_H

#include <CVT_2/exceptions.h>
#include <CVT_2/internal/Handle_set.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/mark_domain_2.h>

#include <CGAL/Kernel/global_functions_2.h>
#include <CGAL/enum.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// Whether the point of locate(p) -> (f, lt, li) lies in the closed domain.
template <class CDT>
bool located_in_domain(const CDT& cdt, typename CDT::Face_handle f, typename CDT::Locate_type lt,
                       int li) {
  const auto inside = [&](typename CDT::Face_handle h) {
    return !cdt.is_infinite(h) && h->is_inside_domain();
  };
  switch (lt) {
    case CDT::VERTEX:
      return has_domain_face(cdt, f->vertex(li));
    case CDT::EDGE:
      return inside(f) || inside(f->neighbor(li));
    case CDT::FACE:
      return inside(f);
    default:
      return false;
  }
}

// Checks that the segment [p, q] can become a constraint: it lies in the closed domain and
// meets the constrained edges only at vertices or at p or q (which then split them). Throws a
// Domain_error that starts with `what()` and names the edge with `name(a, b)` otherwise (the
// messages are made only then).
// Exact: orientation tests, and the triangles that meet [p, q]; only the domain test of each
// piece between the vertices on the segment locates a constructed midpoint.
// The constrained edges of `ignored` (a vertex about to move) do not count; with `domain`
// false, neither does the domain.
// Whether the closed triangle abc (counterclockwise) and the closed segment [p, q] meet: no
// line through a side of either separates them (exact orientation tests).
template <class Orientation, class Point_2>
bool triangle_meets_segment(const Orientation& orientation, const Point_2& a, const Point_2& b,
                            const Point_2& c, const Point_2& p, const Point_2& q) {
  for (const Point_2* v : {&a, &b, &c})  // an end of the segment: no degenerate test
    if (*v == p || *v == q) return true;
  const int oa = orientation(p, q, a), ob = orientation(p, q, b), oc = orientation(p, q, c);
  if ((oa > 0 && ob > 0 && oc > 0) || (oa < 0 && ob < 0 && oc < 0)) return false;
  const Point_2* v[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const Point_2 &u = *v[i], &w = *v[(i + 1) % 3];
    if (orientation(u, w, p) < 0 && orientation(u, w, q) < 0) return false;
  }
  return true;
}

template <class CDT, class Name, class What>
void check_segment(const CDT& cdt, const typename CDT::Point_2& p, const typename CDT::Point_2& q,
                   const Name& name, const What& what,
                   typename CDT::Vertex_handle ignored = typename CDT::Vertex_handle(),
                   bool domain = true,
                   typename CDT::Face_handle hint = typename CDT::Face_handle()) {
  using Point_2 = typename CDT::Point_2;
  using Face_handle = typename CDT::Face_handle;
  const auto orientation = cdt.geom_traits().orientation_2_object();
  const auto segment = [&] { return to_string(p) + " - " + to_string(q); };
  typename CDT::Locate_type lt;
  int li;
  const Face_handle start = cdt.locate(p, lt, li, hint);
  if (cdt.dimension() < 2 || cdt.is_infinite(start))
    throw Domain_error(what() + ": " + to_string(p) + " is outside the triangulation");
  if (domain && !located_in_domain(cdt, start, lt, li))
    throw Domain_error(what() + ": " + to_string(p) + " is outside the domain");
  const Face_handle end = cdt.locate(q, lt, li, start);
  if (domain && !located_in_domain(cdt, end, lt, li))
    throw Domain_error(what() + ": " + to_string(q) + " is outside the domain");
  // scratch kept from call to call: a crack's step checks one short segment
  thread_local std::vector<Face_handle> stack;
  thread_local Handle_set<Face_handle> seen;
  thread_local std::vector<Point_2> on_segment;
  stack.assign(1, start);
  seen.clear();
  seen.insert(start);
  on_segment.clear();
  while (!stack.empty()) {
    const Face_handle h = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const auto& x = h->vertex(i)->point();
      if (x != p && x != q && orientation(p, q, x) == CGAL::COLLINEAR &&
          CGAL::collinear_are_strictly_ordered_along_line(p, x, q))
        on_segment.push_back(x);
      if (!h->is_constrained(i) || h->vertex(CDT::ccw(i)) == ignored ||
          h->vertex(CDT::cw(i)) == ignored)
        continue;
      const auto& a = h->vertex(CDT::ccw(i))->point();
      const auto& b = h->vertex(CDT::cw(i))->point();
      const bool a_end = a == p || a == q, b_end = b == p || b == q;
      if (a_end || b_end) {  // an edge at an end of [p, q]: only running along it is wrong
        const Point_2& shared = a_end ? a : b;
        const Point_2& other = a_end ? b : a;
        const Point_2& far = shared == p ? q : p;
        if ((a_end && b_end) || (orientation(shared, far, other) == CGAL::COLLINEAR &&
                                 !CGAL::collinear_are_ordered_along_line(other, shared, far)))
          throw Domain_error(what() + ": " + segment() + " runs along " +
                             name(h->vertex(CDT::ccw(i)), h->vertex(CDT::cw(i))));
        continue;
      }
      const int o1 = orientation(p, q, a), o2 = orientation(p, q, b);
      const int o3 = orientation(a, b, p), o4 = orientation(a, b, q);
      if (o1 * o2 < 0 && o3 * o4 < 0)
        throw Domain_error(what() + ": " + segment() + " crosses " +
                           name(h->vertex(CDT::ccw(i)), h->vertex(CDT::cw(i))) + " at no vertex");
      if (o1 == 0 && o2 == 0) {
        const Point_2 lo = std::max(std::min(p, q), std::min(a, b));
        const Point_2 hi = std::min(std::max(p, q), std::max(a, b));
        if (lo < hi)
          throw Domain_error(what() + ": " + segment() + " runs along " +
                             name(h->vertex(CDT::ccw(i)), h->vertex(CDT::cw(i))));
      }
    }
    for (int i = 0; i < 3; ++i) {
      const Face_handle n = h->neighbor(i);
      if (!cdt.is_infinite(n) && !seen.contains(n) &&
          triangle_meets_segment(orientation, n->vertex(0)->point(), n->vertex(1)->point(),
                                 n->vertex(2)->point(), p, q)) {
        seen.insert(n);
        stack.push_back(n);
      }
    }
  }
  // each piece between the vertices on the segment lies in one region: its midpoint's
  std::sort(on_segment.begin(), on_segment.end(), [&](const Point_2& x, const Point_2& y) {
    return CGAL::compare_distance_to_point(p, x, y) == CGAL::SMALLER;
  });
  on_segment.erase(std::unique(on_segment.begin(), on_segment.end()), on_segment.end());
  on_segment.insert(on_segment.begin(), p);
  on_segment.push_back(q);
  for (std::size_t k = 0; domain && k + 1 < on_segment.size(); ++k) {
    const Point_2 m = CGAL::midpoint(on_segment[k], on_segment[k + 1]);
    const Face_handle f = cdt.locate(m, lt, li, start);
    if (!located_in_domain(cdt, f, lt, li))
      throw Domain_error(what() + ": " + segment() + " leaves the domain near " + to_string(m));
  }
}

// Whether two pieces of one polyline meet where they must not: anywhere if they are not
// consecutive, beyond their shared end (folding back) if they are.
template <class Point_2>
bool pieces_meet(const Point_2& a, const Point_2& b, const Point_2& c, const Point_2& d,
                 bool consecutive) {
  if (consecutive)  // b == c
    return CGAL::collinear(a, b, d) && !CGAL::collinear_are_ordered_along_line(a, b, d);
  using K = typename CGAL::Kernel_traits<Point_2>::Kernel;
  return CGAL::do_intersect(typename K::Segment_2(a, b), typename K::Segment_2(c, d));
}

// The next vertex from u toward w along a constrained edge: w, or a vertex strictly between.
template <class CDT>
typename CDT::Vertex_handle next_along(const CDT& cdt, typename CDT::Vertex_handle u,
                                       typename CDT::Vertex_handle w) {
  auto ec = cdt.incident_edges(u), done = ec;
  do {
    if (!ec->first->is_constrained(ec->second)) continue;
    auto x = ec->first->vertex(CDT::ccw(ec->second));
    if (x == u) x = ec->first->vertex(CDT::cw(ec->second));
    if (x == w ||
        (!cdt.is_infinite(x) && CGAL::collinear(u->point(), x->point(), w->point()) &&
         CGAL::collinear_are_strictly_ordered_along_line(u->point(), x->point(), w->point())))
      return x;
  } while (++ec != done);
  throw std::logic_error("Constraint_editor_2: a constraint inserted is not in the triangulation");
}

// The domain flags of the faces `fresh` that a constraint insertion created: those of the old
// faces beside them across unconstrained edges, then across the new constraint (whose two
// sides lie in one region, being in the domain), flooding within the new faces.
// A face that neither reaches (`keep(f)`, an old face unchanged) keeps its mark; any other is
// in the domain, enclosed by the new constraint and others.
template <class CDT, class Inner, class Keep = bool (*)(typename CDT::Face_handle)>
void flood_domain_marks(
    const CDT& cdt, const Handle_set<typename CDT::Face_handle>& fresh,
    const Inner& is_new_constraint,
    const Keep& keep = [](typename CDT::Face_handle) { return false; }) {
  std::vector<typename CDT::Face_handle> stack;
  Handle_set<typename CDT::Face_handle> done;
  for (const auto f : fresh)
    for (int i = 0; i < 3; ++i) {
      const auto n = f->neighbor(i);
      if (!fresh.contains(n) && !f->is_constrained(i)) {
        f->set_inside_domain(!cdt.is_infinite(n) && n->is_inside_domain() && !cdt.is_infinite(f));
        done.insert(f);
        stack.push_back(f);
        break;
      }
    }
  for (int pass = 0; pass < 2; ++pass) {
    while (!stack.empty()) {
      const auto f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const auto n = f->neighbor(i);
        if (!fresh.contains(n) || done.contains(n)) continue;
        if (f->is_constrained(i) && (pass == 0 || !is_new_constraint(f, i))) continue;
        n->set_inside_domain(f->is_inside_domain() && !cdt.is_infinite(n));
        done.insert(n);
        stack.push_back(n);
      }
    }
    for (const auto f : done) stack.push_back(f);  // second pass: across the new constraint
  }
  for (const auto f : fresh)
    if (!done.contains(f) && !keep(f)) f->set_inside_domain(!cdt.is_infinite(f));
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_CONSTRAINT_EDITS_H
