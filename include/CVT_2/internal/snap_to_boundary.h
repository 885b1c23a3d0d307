// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Generators a rounding outside the domain: the boundary nearest to them, and how one goes onto it.
#ifndef CVT_2_INTERNAL_SNAP_TO_BOUNDARY_H
#define CVT_2_INTERNAL_SNAP_TO_BOUNDARY_H

#include <CVT_2/exceptions.h>
#include <CVT_2/internal/to_string.h>

#include <CGAL/Kernel/global_functions.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

// A distance or a tolerance in messages: 3 digits say enough.
inline std::string short_number(double x) {
  std::ostringstream os;
  os.precision(3);
  os << x;
  return os.str();
}

// The default boundary tolerance: 2^-50 of the largest coordinate magnitude of the
// triangulation's vertices, 4 to 8 units in the last place of that coordinate. A boundary
// point computed in double (an edge's midpoint, a projection) is within about one of them.
template <class CDT>
double default_boundary_tolerance(const CDT& cdt) {
  double m = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    m = std::max(
        {m, std::abs(CGAL::to_double(v->point().x())), std::abs(CGAL::to_double(v->point().y()))});
  return std::ldexp(m, -50);
}

// How far a point lies outside the domain, in messages ("1.2e-16 outside", "a rounding
// outside": the distance in double is 0 when it is below the coordinates' resolution).
inline std::string distance_outside(double d) {
  return (d > 0 ? short_number(d) : std::string("a rounding")) + " outside the domain";
}

template <class Point_2>
double distance_to_segment(const Point_2& p, const Point_2& a, const Point_2& b) {
  using Segment_2 = typename CGAL::Kernel_traits<Point_2>::Kernel::Segment_2;
  return std::sqrt(CGAL::to_double(CGAL::squared_distance(p, Segment_2(a, b))));
}

template <class Point_2>
double distance_to_line(const Point_2& p, const Point_2& a, const Point_2& b) {
  const double dx = CGAL::to_double(b.x() - a.x()), dy = CGAL::to_double(b.y() - a.y());
  const double ex = CGAL::to_double(p.x() - a.x()), ey = CGAL::to_double(p.y() - a.y());
  return std::abs(dx * ey - dy * ex) / std::hypot(dx, dy);
}

// Whether the edge (f, i) separates the domain from the rest: one of its faces is in the
// domain, the other not (the infinite faces never are).
template <class CDT>
bool is_boundary_edge(const typename CDT::Face_handle f, int i) {
  return f->is_inside_domain() != f->neighbor(i)->is_inside_domain();
}

// The place of the domain's boundary nearest to a point outside it, within some radius: a
// boundary vertex, or a boundary edge (face, index) with `face` on the domain's side.
template <class CDT>
struct Boundary_place {
  typename CDT::Vertex_handle vertex;  // a boundary vertex nearly as near, if any (see below)
  typename CDT::Face_handle face;      // else the nearest boundary edge, if any
  int index = -1;
  double distance = HUGE_VAL;  // from the point to the domain (to the edge, not the vertex)
  bool found() const { return index >= 0; }
};

// The boundary of the domain nearest to `p` (outside the domain, in face `start` or on its
// boundary) if it lies within `radius`, and its vertex nearest to `p` if that lies within
// `tolerance` and at most twice as far as that boundary point, plus a `rounding`: a point goes
// to a vertex rather than make a cell thinner than its distance outside beside it, and a point
// farther along an edge goes onto the edge, however large the tolerance. The search crosses only
// edges within `radius` of `p`: a segment from `p` to the boundary point within `radius` runs
// through faces whose edges it crosses within `radius`, and around a vertex within `radius` all
// edges are. Outside the convex hull it follows the hull edges that `p` sees and whose lines pass
// within `radius` (those the segment crosses), so a point far from the domain costs a face or two.
template <class CDT>
Boundary_place<CDT> nearest_boundary(const CDT& cdt, const typename CDT::Point_2& p,
                                     typename CDT::Face_handle start, double radius,
                                     double tolerance, double rounding) {
  using Face_handle = typename CDT::Face_handle;
  using Vertex_handle = typename CDT::Vertex_handle;
  Boundary_place<CDT> best;
  double vertex_distance = HUGE_VAL;
  if (cdt.dimension() < 2) return best;
  std::vector<Face_handle> stack{start};
  std::unordered_set<Face_handle> seen{start};
  while (!stack.empty()) {
    const Face_handle f = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const Face_handle g = f->neighbor(i);
      const Vertex_handle u = f->vertex(CDT::ccw(i)), w = f->vertex(CDT::cw(i));
      if (is_boundary_edge<CDT>(f, i)) {
        const double d = distance_to_segment(p, u->point(), w->point());
        if (d <= radius && d < best.distance) {
          best.distance = d;
          best.face = f->is_inside_domain() ? f : g;
          best.index = f->is_inside_domain() ? i : cdt.mirror_index(f, i);
        }
        for (const Vertex_handle x : {u, w}) {
          const double dx = std::sqrt(CGAL::to_double(CGAL::squared_distance(p, x->point())));
          if (dx <= tolerance && dx < vertex_distance) vertex_distance = dx, best.vertex = x;
        }
      }
      if (seen.count(g)) continue;
      bool cross;
      if (cdt.is_infinite(u) || cdt.is_infinite(w)) {  // between two infinite faces
        const int k = g->index(cdt.infinite_vertex());
        const auto& s = g->vertex(CDT::ccw(k))->point();
        const auto& t = g->vertex(CDT::cw(k))->point();
        // g's hull edge st has the hull on its right: p sees it unless p lies to its right.
        cross =
            CGAL::orientation(s, t, p) != CGAL::RIGHT_TURN && distance_to_line(p, s, t) <= radius;
      } else {
        cross = distance_to_segment(p, u->point(), w->point()) <= radius;
      }
      if (!cross) continue;
      seen.insert(g);
      stack.push_back(g);
    }
  }
  if (best.found() && vertex_distance > 2 * best.distance + rounding) best.vertex = Vertex_handle();
  return best;
}

// The distance from `p` to the domain, by every boundary edge: for messages only.
template <class CDT>
double distance_to_domain(const CDT& cdt, const typename CDT::Point_2& p) {
  double d = HUGE_VAL;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    for (int i = 0; i < 3; ++i)
      if (f->is_inside_domain() && !f->neighbor(i)->is_inside_domain())
        d = std::min(d, distance_to_segment(p, f->vertex(CDT::ccw(i))->point(),
                                            f->vertex(CDT::cw(i))->point()));
  return d;
}

// Where on the boundary edge (f, i) (f on the domain's side) the point p may go, best first:
// its projection onto the edge, rounded. A rounding exactly on the edge, if there is one, is
// the only candidate (`second` true: it splits the constraint there); else the roundings within
// two units in the last place that lie strictly on the domain's side of the edge (`inside`) or
// strictly on the other, nearest to the edge first. Such a point replaces the edge in the
// boundary (replace_boundary_edge()), which then bends by a rounding.
template <class CDT>
std::vector<std::pair<typename CDT::Point_2, bool>> points_near_boundary_edge(
    const typename CDT::Point_2& p, typename CDT::Face_handle f, int i, bool inside) {
  using Point_2 = typename CDT::Point_2;
  const Point_2& a = f->vertex(CDT::ccw(i))->point();  // the domain lies left of ab
  const Point_2& b = f->vertex(CDT::cw(i))->point();
  const double ax = CGAL::to_double(a.x()), ay = CGAL::to_double(a.y());
  const double dx = CGAL::to_double(b.x()) - ax, dy = CGAL::to_double(b.y()) - ay;
  double t = ((CGAL::to_double(p.x()) - ax) * dx + (CGAL::to_double(p.y()) - ay) * dy) /
             (dx * dx + dy * dy);
  t = std::min(1.0, std::max(0.0, t));
  const double qx = ax + t * dx, qy = ay + t * dy;
  // The roundings around the projection, nearest to the edge's line first, then to the
  // projection.
  std::vector<std::pair<std::array<double, 2>, Point_2>> candidates;
  for (int sx = -2; sx <= 2; ++sx)
    for (int sy = -2; sy <= 2; ++sy) {
      double x = qx, y = qy;
      for (int s = 0; s < std::abs(sx); ++s) x = std::nextafter(x, sx > 0 ? HUGE_VAL : -HUGE_VAL);
      for (int s = 0; s < std::abs(sy); ++s) y = std::nextafter(y, sy > 0 ? HUGE_VAL : -HUGE_VAL);
      const Point_2 c(x, y);
      candidates.push_back({{distance_to_line(c, a, b), double(std::abs(sx) + std::abs(sy))}, c});
    }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& l, const auto& r) { return l.first < r.first; });
  std::vector<std::pair<Point_2, bool>> out;
  for (const auto& [key, c] : candidates)
    if (CGAL::orientation(a, b, c) == CGAL::COLLINEAR &&
        CGAL::collinear_are_strictly_ordered_along_line(a, c, b))
      return {{c, true}};
  const CGAL::Orientation side = inside ? CGAL::LEFT_TURN : CGAL::RIGHT_TURN;
  for (const auto& [key, c] : candidates)
    if (CGAL::orientation(a, b, c) == side) out.emplace_back(c, false);
  return out;
}

// Whether a point located at (lt, f, li) lands in a face, or on an edge that is no constraint,
// of the given domain flag (outside the convex hull: outside the domain).
template <class CDT>
bool lands_in(const CDT& cdt, typename CDT::Locate_type lt, typename CDT::Face_handle f, int li,
              bool inside) {
  switch (lt) {
    case CDT::FACE:
      return f->is_inside_domain() == inside;
    case CDT::EDGE:
      return !cdt.is_constrained(typename CDT::Edge(f, li)) && f->is_inside_domain() == inside;
    case CDT::OUTSIDE_CONVEX_HULL:
      return !inside;
    default:
      return false;
  }
}

// The boundary edge ab replaced by the constraints a-c and c-b through the vertex c, just
// inserted next to it on the side whose flag new faces are created with (that of a default
// face; see insert_generators_2()): CGAL's insertion of the constraints then makes faces of
// the right flag on that side, and its flips join faces of one flag. The faces between ab and
// a-c-b take the flag of the side across ab, and ab is no constraint any more (its flips, too,
// join faces of one flag). So the marks follow the boundary.
template <class CDT>
void replace_boundary_edge(CDT& cdt, typename CDT::Vertex_handle a, typename CDT::Vertex_handle b,
                           typename CDT::Vertex_handle c) {
  using Face_handle = typename CDT::Face_handle;
  cdt.insert_constraint(a, c);
  cdt.insert_constraint(c, b);
  Face_handle s;
  int i;
  if (!cdt.is_edge(a, b, s, i)) return;  // a constraint is never flipped: cannot happen
  const int j = cdt.mirror_index(s, i);
  const bool c_side = CGAL::orientation(a->point(), b->point(), c->point()) ==
                      CGAL::orientation(a->point(), b->point(), s->vertex(i)->point());
  if (cdt.is_infinite(s->vertex(i)) || !c_side) s = s->neighbor(i), i = j;
  const bool flag = s->neighbor(i)->is_inside_domain();
  std::vector<Face_handle> stack{s};
  while (!stack.empty()) {  // the faces of the triangle abc, closed by constraints
    const Face_handle g = stack.back();
    stack.pop_back();
    if (g->is_inside_domain() == flag) continue;
    g->set_inside_domain(flag);
    for (int k = 0; k < 3; ++k)
      if (!cdt.is_constrained(typename CDT::Edge(g, k))) stack.push_back(g->neighbor(k));
  }
  cdt.remove_constrained_edge(s, i);
}

// What insert_generators_2() throws for generators outside the domain beyond the tolerance:
// what is wrong with the first, and the next few by position and coordinates, so that a reader
// can name each by its line or row (message()).
class Generators_outside_error : public Domain_error {
 public:
  using Others = std::vector<std::pair<std::size_t, std::string>>;
  // `first`: the first offending generator's position and what is wrong with it; `others`: the
  // next few (position, coordinates); `count`: how many in all.
  Generators_outside_error(std::size_t index, const std::string& first, const Others& others,
                           std::size_t count)
      : Domain_error(compose(first, others, count,
                             [](std::size_t k) { return "[" + std::to_string(k) + "]"; }),
                     index),
        m_first(first),
        m_others(others),
        m_count(count) {}
  // The message, each of the others named by `name(position)`.
  template <class Name>
  std::string message(const Name& name) const {
    return compose(m_first, m_others, m_count, name);
  }
  std::size_t count() const { return m_count; }

 private:
  template <class Name>
  static std::string compose(const std::string& first, const Others& others, std::size_t count,
                             const Name& name) {
    std::string m = first;
    if (count < 2) return m;
    m += (count == 2 ? "; so does 1 more:" : "; so do " + std::to_string(count - 1) + " more:");
    for (std::size_t k = 0; k < others.size(); ++k)
      m += (k ? ", " : " ") + name(others[k].first) + " " + others[k].second;
    if (count - 1 > others.size())
      m += ", and " + std::to_string(count - 1 - others.size()) + " more";
    return m;
  }
  std::string m_first;
  Others m_others;
  std::size_t m_count;
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_SNAP_TO_BOUNDARY_H
