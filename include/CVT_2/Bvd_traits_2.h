// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Bvd_traits_2: a kernel plus the filtered exact blindness predicates and the cell constructions.
#ifndef CVT_2_BVD_TRAITS_2_H
#define CVT_2_BVD_TRAITS_2_H

#include <CVT_2/internal/blindness_predicates.h>

#include <CGAL/Cartesian_converter.h>
#include <CGAL/Exact_kernel_selector.h>
#include <CGAL/Filtered_predicate.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <type_traits>
#include <utility>

namespace CVT_2 {
namespace internal {

// For double: the exponent e of the largest magnitude, so that dividing by 2^e brings all the
// values near 1 exactly. Other number types do not overflow this way: e = 0.
template <class FT>
int scale_exponent(std::initializer_list<FT> values) {
  int e = 0;
  if constexpr (std::is_same_v<FT, double>) {
    double m = 0;
    for (const double x : values) m = std::max(m, std::abs(x));
    // Within these magnitudes the cubic terms neither overflow nor underflow, nor does the
    // error filter's product of squares: no rescaling, which costs as much as the rest of the
    // construction. Rescaling is exact, so either way gives the same bits.
    if (m > 0x1.0p-100 && m < 0x1.0p100) return 0;
    if (m > 0 && std::isfinite(m)) std::frexp(m, &e);
  }
  return e;
}
template <class FT>
FT scaled(const FT& x, int e) {  // x 2^e; ldexp is a library call, skipped in the common case
  if constexpr (std::is_same_v<FT, double>)
    return e == 0 ? x : std::ldexp(x, e);
  else
    return x;
}

// The double nearest to the exact number x (ties to the lower bound): to_interval is tight, so
// one exact comparison decides.
template <class ENT>
double nearest_double(const ENT& x) {
  const std::pair<double, double> i = CGAL::to_interval(x);
  if (i.first == i.second || !std::isfinite(i.first) || !std::isfinite(i.second))
    return std::isfinite(i.first) ? i.first : i.second;
  return x - ENT(i.first) <= ENT(i.second) - x ? i.first : i.second;
}

// Forward error filter of the constructions' quotients x = nx / den, y = ny / den, computed in
// double from rounded differences (relative error 2^-53 each) of magnitude about 1: sx, sy, sd
// are the sums of the absolute values of the terms of nx, ny and den. True when x and y are
// within 2^-30 of sqrt(length2), the feature size, of their exact values; NaN and infinities
// fail. A slack of 2^-1020 covers products that fall below the normal range.
inline bool accurate_quotients(double x, double y, double sx, double sy, double den, double sd,
                               double length2) {
  constexpr double u = 0x1.0p-53, slack = 0x1.0p-1020;
  const double dden = 8 * u * sd + slack;   // |den - exact den| <= dden
  const double low = std::abs(den) - dden;  // <= |exact den|
  const double m = std::max(std::abs(x), std::abs(y));
  // error * low, without dividing
  const double err = 16 * u * std::max(sx, sy) + slack + m * (dden + 2 * u * low);
  return low > 3 * dden && err * err <= 0x1.0p-60 * length2 * (low * low);
}

}  // namespace internal

/// \ingroup PkgCvt2Ref
/// Geometric traits of the bounded Voronoi diagram: the kernel `K` plus
/// - `Is_blinded_2`: `bool operator()(p, q, r, a, b)`, the paper's predicate \f$\mathcal{P}\f$:
///   does the closed segment ab meet the segment from the centroid of triangle pqr to its
///   circumcenter (the circumcenter itself on the line of ab does not count)?
/// - `Compare_blinding_distance_2`: `Comparison_result operator()(p, q, r, a1, b1, a2, b2)`:
///   which of two segments that blind pqr is met first on that way (`SMALLER`: a1b1).
/// - `Construct_clip_point_2`: `Point_2 operator()(v, w, a, b)`: the point of the line ab at
///   equal distance from v and w, that is where the Voronoi edge dual to vw meets ab.
/// - `Construct_circumcenter_2`: the kernel's, made safe from overflow and underflow.
///
/// Both predicates are exact: interval arithmetic first, then a ring number type (GMP) when the
/// intervals cannot decide. The circumcenter is never constructed in floating point.
/// \tparam K a CGAL kernel with Cartesian coordinates.
/// \cgalModels `BvdTraits_2`
template <class K>
struct Bvd_traits_2 : K {
  using Kernel = K;                     ///< the kernel
  using FT = typename K::FT;            ///< the number type
  using Point_2 = typename K::Point_2;  ///< the point type

 private:
  using Interval_kernel = CGAL::Simple_cartesian<CGAL::Interval_nt_advanced>;
  using Exact = CGAL::Exact_kernel_selector<K>;
  using Exact_kernel = typename Exact::Exact_kernel_rt;
  using C2E = typename Exact::C2E_rt;
  using C2A = CGAL::Cartesian_converter<K, Interval_kernel>;

 public:
  /// The predicate \f$\mathcal{P}\f$, filtered.
  using Is_blinded_2 = CGAL::Filtered_predicate<internal::Is_blinded_2<Exact_kernel>,
                                                internal::Is_blinded_2<Interval_kernel>, C2E, C2A>;
  /// Which of two blinding segments comes first, filtered.
  using Compare_blinding_distance_2 =
      CGAL::Filtered_predicate<internal::Compare_blinding_distance_2<Exact_kernel>,
                               internal::Compare_blinding_distance_2<Interval_kernel>, C2E, C2A>;
  /// The way from the centroid of a triangle to its circumcenter, for a walk along it (the
  /// natural-neighbour coordinates tag the faces of a virtual star so): made from p, q, r, it
  /// answers `side_of_point(x)`, the orientation of centroid, circumcenter and x, and
  /// `side_of_circumcenter(a, b)`, the orientation of a, b and the circumcenter, filtered, the
  /// circumcenter never constructed.
  using Dual_segment_2 =
      internal::Filtered_dual_segment_2<K, Interval_kernel, Exact_kernel, C2A, C2E>;

  /// The circumcenter of pqr, as CGAL computes it (relative to p), on differences rescaled by
  /// a power of two: exact, so the result is CGAL's to the bit whenever CGAL's does not
  /// overflow or underflow, and still right where it would (feature sizes from 1e-300 to 1e300).
  /// Where the formula's forward error bound exceeds 2^-30 of the triangle's shortest side (a
  /// sliver, or q and r far closer to each other than to p, where |q - p|² no longer holds
  /// their difference), the circumcenter is built exactly and rounded to the nearest.
  struct Construct_circumcenter_2 {
    /// \pre p, q, r are not collinear.
    Point_2 operator()(const Point_2& p, const Point_2& q, const Point_2& r) const {
      FT qx = q.x() - p.x(), qy = q.y() - p.y(), rx = r.x() - p.x(), ry = r.y() - p.y();
      const int e = internal::scale_exponent<FT>({qx, qy, rx, ry});
      qx = internal::scaled(qx, -e), qy = internal::scaled(qy, -e);
      rx = internal::scaled(rx, -e), ry = internal::scaled(ry, -e);
      const FT r2 = rx * rx + ry * ry, q2 = qx * qx + qy * qy;
      const FT den = FT(2) * (qx * ry - qy * rx);
      const FT cx = (ry * q2 - qy * r2) / den, cy = -(rx * q2 - qx * r2) / den;
      if constexpr (std::is_same_v<FT, double>) {
        const double sx = std::abs(ry) * q2 + std::abs(qy) * r2,
                     sy = std::abs(rx) * q2 + std::abs(qx) * r2,
                     sd = std::abs(qx * ry) + std::abs(qy * rx);
        const double dx = qx - rx, dy = qy - ry;
        const double shortest2 = std::min({q2, r2, dx * dx + dy * dy});
        if (!internal::accurate_quotients(cx, cy, sx, sy, den, sd, shortest2))
          return exact(p, q, r);
      }
      return Point_2(p.x() + internal::scaled(cx, e), p.y() + internal::scaled(cy, e));
    }

   private:
    [[gnu::noinline]] static Point_2 exact(const Point_2& p, const Point_2& q, const Point_2& r) {
      using EK = typename Exact::Exact_kernel;
      const typename Exact::C2E to_exact;
      const typename EK::Point_2 c =
          EK().construct_circumcenter_2_object()(to_exact(p), to_exact(q), to_exact(r));
      return Point_2(internal::nearest_double(c.x()), internal::nearest_double(c.y()));
    }
  };

  /// The point of the line ab at equal distance from v and w: where the Voronoi edge dual to vw
  /// meets ab. Relative to v and rescaled like the circumcenter:
  /// y = a + t (b - a) with 2 (y - v).(w - v) = |w - v|². Exact, like the circumcenter, where
  /// the error bound exceeds 2^-30 of |w - v| or |b - a|.
  struct Construct_clip_point_2 {
    /// \pre the bisector of v and w is not parallel to ab.
    Point_2 operator()(const Point_2& v, const Point_2& w, const Point_2& a,
                       const Point_2& b) const {
      FT wx = w.x() - v.x(), wy = w.y() - v.y(), ax = a.x() - v.x(), ay = a.y() - v.y();
      FT dx = b.x() - a.x(), dy = b.y() - a.y();
      const int e = internal::scale_exponent<FT>({wx, wy, ax, ay, dx, dy});
      wx = internal::scaled(wx, -e), wy = internal::scaled(wy, -e), ax = internal::scaled(ax, -e);
      ay = internal::scaled(ay, -e), dx = internal::scaled(dx, -e), dy = internal::scaled(dy, -e);
      const FT w2 = wx * wx + wy * wy, d2 = dx * dx + dy * dy;
      const FT denom = FT(2) * (dx * wx + dy * wy);
      const FT t = (w2 - FT(2) * (ax * wx + ay * wy)) / denom;
      if constexpr (std::is_same_v<FT, double>) {
        // t times |b - a| is the length to bound.
        const double st = w2 + 2 * (std::abs(ax * wx) + std::abs(ay * wy)),
                     sd = std::abs(dx * wx) + std::abs(dy * wy);
        const double scale = std::sqrt(d2);
        if (!internal::accurate_quotients(t * scale, 0.0, st * scale, 0.0, denom, sd,
                                          std::min(w2, d2)))
          return exact(v, w, a, b);
      } else if (denom == FT(0)) {
        return CGAL::midpoint(a, b);  // bisector parallel to ab: never asked
      }
      return Point_2(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
    }

   private:
    [[gnu::noinline]] static Point_2 exact(const Point_2& v, const Point_2& w, const Point_2& a,
                                           const Point_2& b) {
      using ENT = typename Exact::Exact_nt;
      const ENT vx(v.x()), vy(v.y()), wx = ENT(w.x()) - vx, wy = ENT(w.y()) - vy;
      const ENT ax = ENT(a.x()) - vx, ay = ENT(a.y()) - vy;
      const ENT dx = ENT(b.x()) - ENT(a.x()), dy = ENT(b.y()) - ENT(a.y());
      const ENT denom = ENT(2) * (dx * wx + dy * wy);
      if (CGAL::is_zero(denom)) return CGAL::midpoint(a, b);  // parallel: never asked
      const ENT t = (wx * wx + wy * wy - ENT(2) * (ax * wx + ay * wy)) / denom;
      return Point_2(internal::nearest_double(ENT(ENT(a.x()) + t * dx)),
                     internal::nearest_double(ENT(ENT(a.y()) + t * dy)));
    }
  };

  /// \name Functor accessors
  /// @{
  /// the circumcenter functor
  Construct_circumcenter_2 construct_circumcenter_2_object() const {
    return Construct_circumcenter_2();
  }
  Is_blinded_2 is_blinded_2_object() const { return Is_blinded_2(); }  ///< the predicate
  /// the comparison of blinding segments
  Compare_blinding_distance_2 compare_blinding_distance_2_object() const {
    return Compare_blinding_distance_2();
  }
  /// the clip point functor
  Construct_clip_point_2 construct_clip_point_2_object() const { return Construct_clip_point_2(); }
  /// a face's way from its centroid to its circumcenter
  struct Construct_dual_segment_2 {
    /// \pre p, q, r are not collinear.
    Dual_segment_2 operator()(const Point_2& p, const Point_2& q, const Point_2& r) const {
      return Dual_segment_2(p, q, r);
    }
  };
  /// the dual segment functor
  Construct_dual_segment_2 construct_dual_segment_2_object() const {
    return Construct_dual_segment_2();
  }

  /// @}

  Bvd_traits_2() = default;                    ///< default traits
  explicit Bvd_traits_2(const K& k) : K(k) {}  ///< traits over the kernel object `k`
};

}  // namespace CVT_2

#endif  // CVT_2_BVD_TRAITS_2_H
