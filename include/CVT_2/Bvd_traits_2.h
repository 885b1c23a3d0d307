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

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// Geometric traits of the bounded Voronoi diagram: the kernel `K` plus
/// - `Is_blinded_2`: `bool operator()(p, q, r, a, b)`, the paper's predicate \f$\mathcal{P}\f$:
///   does the closed segment ab meet the segment from the centroid of triangle pqr to its
///   circumcenter (the circumcenter itself on the line of ab does not count)?
/// - `Compare_blinding_distance_2`: `Comparison_result operator()(p, q, r, a1, b1, a2, b2)`:
///   which of two segments that blind pqr is met first on that way (`SMALLER`: a1b1).
/// - `Construct_clip_point_2`: `Point_2 operator()(v, w, a, b)`: the point of the line ab at
///   equal distance from v and w, that is where the Voronoi edge dual to vw meets ab.
///
/// Both predicates are exact: interval arithmetic first, then a ring number type (GMP) when the
/// intervals cannot decide. The circumcenter is never constructed in floating point.
/// \tparam K a CGAL kernel with Cartesian coordinates.
/// \cgalModels `BvdTraits_2`
template <class K>
struct Bvd_traits_2 : K {
  using Kernel = K;
  using FT = typename K::FT;
  using Point_2 = typename K::Point_2;

 private:
  using Interval_kernel = CGAL::Simple_cartesian<CGAL::Interval_nt_advanced>;
  using Exact = CGAL::Exact_kernel_selector<K>;
  using Exact_kernel = typename Exact::Exact_kernel_rt;
  using C2E = typename Exact::C2E_rt;
  using C2A = CGAL::Cartesian_converter<K, Interval_kernel>;

 public:
  using Is_blinded_2 =
      CGAL::Filtered_predicate<internal::Is_blinded_2<Exact_kernel>,
                               internal::Is_blinded_2<Interval_kernel>, C2E, C2A>;
  using Compare_blinding_distance_2 =
      CGAL::Filtered_predicate<internal::Compare_blinding_distance_2<Exact_kernel>,
                               internal::Compare_blinding_distance_2<Interval_kernel>, C2E, C2A>;

  struct Construct_clip_point_2 {
    // Relative to v, so that coordinates far from the origin do not cancel:
    // y = a + t (b - a) with 2 (y - v).(w - v) = |w - v|².
    Point_2 operator()(const Point_2& v, const Point_2& w, const Point_2& a,
                       const Point_2& b) const {
      const FT wx = w.x() - v.x(), wy = w.y() - v.y();
      const FT ax = a.x() - v.x(), ay = a.y() - v.y();
      const FT dx = b.x() - a.x(), dy = b.y() - a.y();
      const FT denom = FT(2) * (dx * wx + dy * wy);
      if (denom == FT(0)) return CGAL::midpoint(a, b);  // bisector parallel to ab: never asked
      const FT t = (wx * wx + wy * wy - FT(2) * (ax * wx + ay * wy)) / denom;
      return Point_2(a.x() + t * dx, a.y() + t * dy);
    }
  };

  Is_blinded_2 is_blinded_2_object() const { return Is_blinded_2(); }
  Compare_blinding_distance_2 compare_blinding_distance_2_object() const {
    return Compare_blinding_distance_2();
  }
  Construct_clip_point_2 construct_clip_point_2_object() const { return Construct_clip_point_2(); }

  Bvd_traits_2() = default;
  explicit Bvd_traits_2(const K& k) : K(k) {}
};

}  // namespace CVT_2

#endif  // CVT_2_BVD_TRAITS_2_H
