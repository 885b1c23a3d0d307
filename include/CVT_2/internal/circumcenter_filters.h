// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Floating-point filters of the questions on a triangle's circumcenter that the virtual star asks
// most: each gives the exact sign or says it is unsure, never a wrong sign.
#ifndef CVT_2_INTERNAL_CIRCUMCENTER_FILTERS_H
#define CVT_2_INTERNAL_CIRCUMCENTER_FILTERS_H

#include <CGAL/double.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>

namespace CVT_2 {
namespace internal {

// Why filters of our own: the questions are those of Triangle_dual_segment_2
// (blindness_predicates.h) and of the kernel's angle(), which Epick filters with intervals only,
// switching the rounding mode for each; with those alone (the traits' Dual_segment_2 for the
// walk) natural-neighbour queries take 15% longer. Here a plain sum with a forward error bound
// (relative 2^-53 a rounding, plus 2^-1000 a term below the normal range) decides, and the exact
// predicate behind it the few it leaves. test/predicates.cpp checks every filter against the
// exact predicate on random and degenerate input.

// The sign of x if it exceeds its bound; false if it does not (an infinite or NaN bound never
// is exceeded: where the sum overflowed, so did the bound).
inline bool sure_sign(double x, double bound, CGAL::Sign& sign) {
  if (!(std::abs(x) > bound)) return false;
  sign = x > 0 ? CGAL::POSITIVE : CGAL::NEGATIVE;
  return true;
}

// The signs of the angles of triangle pqr at p, q and r, if sure: CGAL::angle(q, p, r),
// angle(p, q, r) and angle(p, r, q) as signs (a right angle is unsure). An angle is obtuse
// (negative) where the circumcenter lies strictly beyond the opposite edge. From u = q - p and
// v = r - p: the dot products u.v, |u|² - u.v and |v|² - u.v.
template <class Point_2>
bool angle_signs(const Point_2& p, const Point_2& q, const Point_2& r, CGAL::Sign sign[3]) {
  const double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y());
  const double ux = CGAL::to_double(q.x()) - px, uy = CGAL::to_double(q.y()) - py;
  const double vx = CGAL::to_double(r.x()) - px, vy = CGAL::to_double(r.y()) - py;
  const double xx = ux * vx, yy = uy * vy, uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
  const double dot = xx + yy, cross = std::abs(xx) + std::abs(yy);
  const double value[3] = {dot, uu - dot, vv - dot};
  const double bound[3] = {0x1.0p-50 * cross + 0x1.0p-1000, 0x1.0p-50 * (uu + cross) + 0x1.0p-1000,
                           0x1.0p-50 * (vv + cross) + 0x1.0p-1000};
  for (int i = 0; i < 3; ++i)
    if (!sure_sign(value[i], bound[i], sign[i])) return false;
  return true;
}

// Whether the circumcenter c of the triangle (a, b, w) lies surely on the left of the line
// a -> x when (a, b, w) is counterclockwise (on its right when clockwise): the sign of
// |v|² (e.u) - |u|² (e.v), u = b - a, v = w - a, e = x - a, which is
// Triangle_dual_segment_2(a, b, w).side_of_circumcenter(a, x) times orientation(a, b, w),
// with no circumcenter built. False where floating point cannot tell.
template <class Point_2>
bool is_circumcenter_surely_left(const Point_2& a, const Point_2& b, const Point_2& w,
                                 const Point_2& x) {
  const double ox = CGAL::to_double(a.x()), oy = CGAL::to_double(a.y());
  const double ux = CGAL::to_double(b.x()) - ox, uy = CGAL::to_double(b.y()) - oy;
  const double vx = CGAL::to_double(w.x()) - ox, vy = CGAL::to_double(w.y()) - oy;
  const double ex = CGAL::to_double(x.x()) - ox, ey = CGAL::to_double(x.y()) - oy;
  const double uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
  const double value = vv * (ex * ux + ey * uy) - uu * (ex * vx + ey * vy);
  // Products below the normal range err by 2^-1075 each, then scaled by |u|², |v|²: at most
  // 2^-1000 unless these exceed 2^70 (the term is built only then, as a subnormal product
  // would be slow).
  const double spread = vv + uu;
  const double bound = 0x1.0p-48 * (vv * (std::abs(ex * ux) + std::abs(ey * uy)) +
                                    uu * (std::abs(ex * vx) + std::abs(ey * vy))) +
                       (spread > 0x1.0p70 ? 0x1.0p-1070 * spread : 0x1.0p-1000) + 0x1.0p-1000;
  return value > bound;
}

// The way [g, c) of triangle pqr, from its centroid to its circumcenter, in floating point: the
// questions of Triangle_dual_segment_2, side_of_circumcenter() and side_of_point(), answered
// from c as Bvd_traits_2::Construct_circumcenter_2 builds it (off by at most 2^-30 of pqr's
// shortest side, then rounded) with a bound on the error of each orientation.
template <class Point_2>
class Approximate_dual_segment_2 {
 public:
  // \pre c is construct_circumcenter_2_object()(p, q, r) of Bvd_traits_2 on doubles.
  Approximate_dual_segment_2(const Point_2& p, const Point_2& q, const Point_2& r, const Point_2& c)
      : m_cx(CGAL::to_double(c.x())), m_cy(CGAL::to_double(c.y())) {
    const double x[3] = {CGAL::to_double(p.x()), CGAL::to_double(q.x()), CGAL::to_double(r.x())};
    const double y[3] = {CGAL::to_double(p.y()), CGAL::to_double(q.y()), CGAL::to_double(r.y())};
    m_gx = (x[0] + x[1] + x[2]) / 3, m_gy = (y[0] + y[1] + y[2]) / 3;
    double shortest = HUGE_VAL, size = 0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      shortest = std::min(shortest, std::abs(x[j] - x[i]) + std::abs(y[j] - y[i]));
      size += std::abs(x[i]) + std::abs(y[i]);
    }
    m_ec = 0x1.0p-29 * shortest + 0x1.0p-51 * (std::abs(m_cx) + std::abs(m_cy));
    m_eg = 0x1.0p-50 * size;
  }
  // The sign of orientation(a, b, c), if sure.
  bool side_of_circumcenter(const Point_2& a, const Point_2& b, CGAL::Sign& sign) const {
    const double ax = CGAL::to_double(a.x()), ay = CGAL::to_double(a.y());
    const double ux = CGAL::to_double(b.x()) - ax, uy = CGAL::to_double(b.y()) - ay;
    const double wx = m_cx - ax, wy = m_cy - ay;
    const double o = ux * wy - uy * wx;
    const double bound = 2 * (std::abs(ux) + std::abs(uy)) * m_ec +
                         0x1.0p-50 * (std::abs(ux * wy) + std::abs(uy * wx)) + tiny;
    return sure_sign(o, bound, sign);
  }
  // The sign of orientation(g, c, x), if sure.
  bool side_of_point(const Point_2& x, CGAL::Sign& sign) const {
    const double dx = m_cx - m_gx, dy = m_cy - m_gy;
    const double ex = CGAL::to_double(x.x()) - m_gx, ey = CGAL::to_double(x.y()) - m_gy;
    const double o = dx * ey - dy * ex;
    const double bound =
        2 * ((std::abs(ex) + std::abs(ey)) * (m_ec + m_eg) + (std::abs(dx) + std::abs(dy)) * m_eg) +
        0x1.0p-50 * (std::abs(dx * ey) + std::abs(dy * ex)) + tiny;
    return sure_sign(o, bound, sign);
  }

 private:
  static constexpr double tiny = 0x1.0p-1000;  // rounding below the normal range
  double m_cx, m_cy, m_gx, m_gy, m_ec, m_eg;
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_CIRCUMCENTER_FILTERS_H
