// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Moving a vertex in place, within its star: no edge, hence no constraint, is crossed.
#ifndef CVT_2_INTERNAL_MOVE_VERTEX_H
#define CVT_2_INTERNAL_MOVE_VERTEX_H

#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <utility>
#include <vector>

namespace CVT_2 {
namespace internal {

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
    const Point_2 p =
        t == 1 ? target
               : Point_2(x.x() + t * (target.x() - x.x()), x.y() + t * (target.y() - x.y()));
    const bool valid = std::all_of(link.begin(), link.end(), [&](const auto& e) {
      return orientation(e.first, e.second, p) == CGAL::LEFT_TURN;
    });
    if (!valid) continue;
    v->set_point(p);
    return CGAL::to_double(t);
  }
  return 0;
}

// The faces around v into `out`.
template <class CDT>
void push_star(const CDT& cdt, typename CDT::Vertex_handle v,
               std::vector<typename CDT::Face_handle>& out) {
  auto fc = cdt.incident_faces(v), done = fc;
  do out.push_back(fc);
  while (++fc != done);
}

// Whether the triangulation stays valid with the vertex v (constrained or not, on the convex
// hull or not) at p instead: every finite face around v positive, and, on the hull, the hull
// convex (collinear allowed) at v and at its two neighbours on it. Exact orientations. The faces
// around v then tile its old star, so its edges cross nothing, constrained or not.
template <class CDT>
bool stays_valid_at(const CDT& cdt, typename CDT::Vertex_handle v, const typename CDT::Point_2& p) {
  using Vertex_handle = typename CDT::Vertex_handle;
  const auto orientation = cdt.geom_traits().orientation_2_object();
  const auto at = [&](Vertex_handle w) -> const typename CDT::Point_2& {
    return w == v ? p : w->point();
  };
  auto fc = cdt.incident_faces(v), done = fc;
  do {
    if (!cdt.is_infinite(fc)) {
      if (orientation(at(fc->vertex(0)), at(fc->vertex(1)), at(fc->vertex(2))) != CGAL::LEFT_TURN)
        return false;
      continue;
    }
    // The hull edge a b of the infinite face (inf, a, b), counterclockwise, and its neighbours
    // on the hull, a' before a and b' after b: the hull turns right or goes straight at a and b.
    const int i = fc->index(cdt.infinite_vertex());
    const Vertex_handle a = fc->vertex(CDT::ccw(i)), b = fc->vertex(CDT::cw(i));
    const auto before = fc->neighbor(CDT::cw(i)), after = fc->neighbor(CDT::ccw(i));
    const Vertex_handle a0 = before->vertex(CDT::ccw(before->index(cdt.infinite_vertex())));
    const Vertex_handle b1 = after->vertex(CDT::cw(after->index(cdt.infinite_vertex())));
    if (orientation(at(a0), at(a), at(b)) == CGAL::LEFT_TURN ||
        orientation(at(a), at(b), at(b1)) == CGAL::LEFT_TURN)
      return false;
  } while (++fc != done);
  return true;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_MOVE_VERTEX_H
