// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The blindness predicates P of the paper, written once over a kernel, division-free.
#ifndef CVT_2_INTERNAL_BLINDNESS_PREDICATES_H
#define CVT_2_INTERNAL_BLINDNESS_PREDICATES_H

#include <CGAL/FPU.h>
#include <CGAL/Uncertain.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <optional>

namespace CVT_2 {
namespace internal {

// Both predicates look along the segment [g, c] from the centroid g of triangle pqr to its
// circumcenter c. Everything is computed relative to p, with g = G / 3 and c = N / den:
//   u = q - p, w = r - p, den = 2 cross(u, w), N = (w.y|u|² - u.y|w|², u.x|w|² - w.x|u|²),
//   G = u + w.
// Only +, - and * of K::RT are used, so an interval kernel filters them and a ring kernel
// (GMP integers or floats) decides exactly. The circumcenter is never constructed.
template <class K>
struct Triangle_dual_segment_2 {
  using RT = typename K::RT;
  RT den, nx, ny, gx, gy;  // homogeneous c = (nx, ny) / den and 3g = (gx, gy), relative to p
  RT px, py;

  Triangle_dual_segment_2(const typename K::Point_2& p, const typename K::Point_2& q,
                          const typename K::Point_2& r)
      : px(p.x()), py(p.y()) {
    const RT ux = q.x() - px, uy = q.y() - py, wx = r.x() - px, wy = r.y() - py;
    const RT u2 = ux * ux + uy * uy, w2 = wx * wx + wy * wy;
    den = RT(2) * (ux * wy - uy * wx);
    nx = wy * u2 - uy * w2;
    ny = ux * w2 - wx * u2;
    gx = ux + wx;
    gy = uy + wy;
  }

  // The sign of orientation(a, b, g).
  CGAL::Sign side_of_centroid(const typename K::Point_2& a, const typename K::Point_2& b) const {
    const RT ax = a.x() - px, ay = a.y() - py, dx = b.x() - a.x(), dy = b.y() - a.y();
    return CGAL::sign(dx * (gy - RT(3) * ay) - dy * (gx - RT(3) * ax));
  }
  // The sign of orientation(a, b, c).
  CGAL::Sign side_of_circumcenter(const typename K::Point_2& a,
                                  const typename K::Point_2& b) const {
    return side_of_circumcenter_uncertain(a, b);
  }
  auto side_of_circumcenter_uncertain(const typename K::Point_2& a,
                                      const typename K::Point_2& b) const {
    const RT ax = a.x() - px, ay = a.y() - py, dx = b.x() - a.x(), dy = b.y() - a.y();
    return CGAL::sign(dx * (ny - den * ay) - dy * (nx - den * ax)) * CGAL::sign(den);
  }
  // The sign of orientation(g, c, x).
  CGAL::Sign side_of_point(const typename K::Point_2& x) const {
    return side_of_point_uncertain(x);
  }
  auto side_of_point_uncertain(const typename K::Point_2& x) const {
    const RT ux = RT(3) * nx - den * gx, uy = RT(3) * ny - den * gy;          // 3 den (c - g)
    const RT xx = RT(3) * (x.x() - px) - gx, xy = RT(3) * (x.y() - py) - gy;  // 3 (x - g)
    return CGAL::sign(ux * xy - uy * xx) * CGAL::sign(den);
  }
  // Where [g, c] meets the line (a, b), as the parameter t = num / denom along g -> c, up to
  // the factor den common to all lines: t * den = num / denom.
  void crossing_parameter(const typename K::Point_2& a, const typename K::Point_2& b, RT& num,
                          RT& denom) const {
    const RT ax = a.x() - px, ay = a.y() - py, dx = b.x() - a.x(), dy = b.y() - a.y();
    num = dx * (RT(3) * ay - gy) - dy * (RT(3) * ax - gx);                // cross(d, 3a - G)
    denom = dx * (RT(3) * ny - den * gy) - dy * (RT(3) * nx - den * gx);  // cross(d, 3N - den G)
  }
};

// P(pqr, ab): is triangle pqr blinded by segment ab? True iff the segment [g, c) from the
// triangle's centroid to its circumcenter meets the closed segment ab, where c itself on the
// line of ab does not count (the circumcenter is then on the barrier, and still seen).
// This is the paper's Definition 2.1 with the segment, not CGAL's test of the supporting line:
// a circumcenter beyond the line of ab but beside the segment is not hidden by ab.
// g rather than a vertex of pqr: a vertex may be an endpoint of ab, which the definition excludes.
template <class K>
struct Is_blinded_2 {
  using result_type = bool;
  using Point_2 = typename K::Point_2;

  bool operator()(const Point_2& p, const Point_2& q, const Point_2& r, const Point_2& a,
                  const Point_2& b) const {
    const Triangle_dual_segment_2<K> s(p, q, r);
    const CGAL::Sign side_c = s.side_of_circumcenter(a, b);
    if (side_c == CGAL::ZERO) return false;
    const CGAL::Sign side_g = s.side_of_centroid(a, b);
    if (side_g != CGAL::opposite(side_c))
      return false;  // same side, or g on the line (then ab is beside g)
    // [g, c] crosses the line of ab; the crossing lies on ab unless a and b are strictly on
    // the same side of the line (g, c).
    const CGAL::Sign side_a = s.side_of_point(a);
    const CGAL::Sign side_b = s.side_of_point(b);
    return side_a == CGAL::ZERO || side_a != side_b;
  }
};

// Which of two segments, both blinding triangle pqr, does [g, c] meet first? SMALLER if a1b1.
// Algorithm 2 clips on the first constraint: with nested constraints between a triangle and its
// circumcenter, the farther one is not where the visible part of the Voronoi edges ends.
template <class K>
struct Compare_blinding_distance_2 {
  using result_type = CGAL::Comparison_result;
  using Point_2 = typename K::Point_2;
  using RT = typename K::RT;

  CGAL::Comparison_result operator()(const Point_2& p, const Point_2& q, const Point_2& r,
                                     const Point_2& a1, const Point_2& b1, const Point_2& a2,
                                     const Point_2& b2) const {
    const Triangle_dual_segment_2<K> s(p, q, r);
    RT n1, d1, n2, d2;
    s.crossing_parameter(a1, b1, n1, d1);
    s.crossing_parameter(a2, b2, n2, d2);
    // t_i = den * n_i / d_i; sign(t1 - t2) = sign(den) sign(d1) sign(d2) sign(n1 d2 - n2 d1)
    const CGAL::Sign s12 = CGAL::sign(n1 * d2 - n2 * d1);
    const CGAL::Sign sd = CGAL::sign(s.den) * CGAL::sign(d1) * CGAL::sign(d2);
    return CGAL::Comparison_result(s12 * sd);
  }
};

// The way [g, c) of one triangle pqr, from its centroid to its circumcenter, for a walk along
// it that asks many questions of it: built once in intervals; each question answered by them
// or, when they cannot tell, exactly (the exact form built then, once).
template <class K, class Interval_kernel, class Exact_kernel, class C2A, class C2E>
class Filtered_dual_segment_2 {
 public:
  using Point_2 = typename K::Point_2;

  Filtered_dual_segment_2(const Point_2& p, const Point_2& q, const Point_2& r) : m_p{p, q, r} {
    CGAL::Protect_FPU_rounding<true> rounding;
    m_interval.emplace(C2A()(p), C2A()(q), C2A()(r));
  }
  // The sign of orientation(g, c, x): where x lies from the way.
  CGAL::Sign side_of_point(const Point_2& x) const {
    {
      CGAL::Protect_FPU_rounding<true> rounding;
      const auto s = m_interval->side_of_point_uncertain(C2A()(x));
      if (CGAL::is_certain(s)) return CGAL::get_certain(s);
    }
    return exact().side_of_point(C2E()(x));
  }
  // The sign of orientation(a, b, c): where the circumcenter lies from the line ab.
  CGAL::Sign side_of_circumcenter(const Point_2& a, const Point_2& b) const {
    {
      CGAL::Protect_FPU_rounding<true> rounding;
      const auto s = m_interval->side_of_circumcenter_uncertain(C2A()(a), C2A()(b));
      if (CGAL::is_certain(s)) return CGAL::get_certain(s);
    }
    return exact().side_of_circumcenter(C2E()(a), C2E()(b));
  }

 private:
  const Triangle_dual_segment_2<Exact_kernel>& exact() const {
    if (!m_exact) m_exact.emplace(C2E()(m_p[0]), C2E()(m_p[1]), C2E()(m_p[2]));
    return *m_exact;
  }
  Point_2 m_p[3];
  std::optional<Triangle_dual_segment_2<Interval_kernel>> m_interval;
  mutable std::optional<Triangle_dual_segment_2<Exact_kernel>> m_exact;
};

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_BLINDNESS_PREDICATES_H
