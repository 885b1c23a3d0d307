// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The BvdTraits_2 concept: what the bounded Voronoi diagram asks of its traits, and its check.
#ifndef CVT_2_CONCEPTS_BVDTRAITS_2_H
#define CVT_2_CONCEPTS_BVDTRAITS_2_H

#include <CGAL/enum.h>

#include <type_traits>
#include <utility>

#ifdef DOXYGEN_RUNNING
// A concept is not a C++ type; as in CGAL, Doxygen sees it as a class that lists the
// requirements. The compiler never sees this class.

/// \ingroup PkgCvt2Concepts
/// The geometric traits of `CVT_2::Bounded_voronoi_diagram_2`: the point and number types, the
/// blindness predicates of Algorithm 1 and the two constructions of Algorithm 2. This is all the
/// diagram calls.
///
/// The two predicates decide the topology of the diagram, so a model should evaluate them
/// exactly (`CVT_2::Bvd_traits_2` filters them: interval arithmetic, then an exact ring type).
/// The two constructions only place cell vertices and may round.
///
/// In the signatures, `p`, `q`, `r` are the vertices of a finite face of the triangulation, in
/// any order, and `a`, `b` are the endpoints of a constrained edge.
///
/// \pre `Point_2` is the triangulation's `Point_2`: the diagram passes the triangulation's
///      points to the functors and stores what the constructions return.
/// \cgalHasModel `CVT_2::Bvd_traits_2<K>` for a CGAL kernel `K` with Cartesian coordinates.
/// \sa `CVT_2::is_bvd_traits_2`
class BvdTraits_2 {
 public:
  /// The number type of the coordinates.
  using FT = unspecified_type;
  /// The point type; the triangulation's `Point_2`.
  using Point_2 = unspecified_type;

  /// A predicate object: does `ab` blind triangle `pqr` (paper, Definition 2.1)?
  struct Is_blinded_2 {
    /// whether the segment from the centroid of triangle `pqr` to its circumcenter meets the
    /// closed segment `ab`; a circumcenter on the line of `ab` does not count.
    /// \pre `p`, `q`, `r` are not collinear; `a != b`.
    bool operator()(const Point_2& p, const Point_2& q, const Point_2& r, const Point_2& a,
                    const Point_2& b) const;
  };

  /// A predicate object: which of two blinding constraints of a face is met first?
  struct Compare_blinding_distance_2 {
    /// which of the segments `a1b1` and `a2b2` the way from the centroid of `pqr` to its
    /// circumcenter meets first: `CGAL::SMALLER` if `a1b1`, `CGAL::LARGER` if `a2b2`,
    /// `CGAL::EQUAL` if both at the same point (segments that share an endpoint).
    /// \pre both segments blind `pqr` (`Is_blinded_2` returns `true` for each).
    CGAL::Comparison_result operator()(const Point_2& p, const Point_2& q, const Point_2& r,
                                       const Point_2& a1, const Point_2& b1, const Point_2& a2,
                                       const Point_2& b2) const;
  };

  /// A construction object: where a Voronoi edge is clipped by a constraint.
  struct Construct_clip_point_2 {
    /// the point of the line `ab` at equal distance from `v` and `w`, that is where the Voronoi
    /// edge dual to `vw` crosses the constraint `ab`.
    /// \pre `v != w`, `a != b`, and the bisector of `v` and `w` is not parallel to `ab`.
    Point_2 operator()(const Point_2& v, const Point_2& w, const Point_2& a,
                       const Point_2& b) const;
  };

  /// A construction object, as CGAL's `Kernel::ConstructCircumcenter_2`.
  struct Construct_circumcenter_2 {
    /// the circumcenter of triangle `pqr`.
    /// \pre `p`, `q`, `r` are not collinear.
    Point_2 operator()(const Point_2& p, const Point_2& q, const Point_2& r) const;
  };

  /// \name Operations
  /// The diagram fetches each functor once, before the loop that uses it.
  /// @{

  /// the blindness predicate.
  Is_blinded_2 is_blinded_2_object() const;
  /// the comparison of blinding constraints.
  Compare_blinding_distance_2 compare_blinding_distance_2_object() const;
  /// the clip point construction.
  Construct_clip_point_2 construct_clip_point_2_object() const;
  /// the circumcenter construction.
  Construct_circumcenter_2 construct_circumcenter_2_object() const;
  /// @}
};
#endif  // DOXYGEN_RUNNING

namespace CVT_2 {
namespace internal {

template <class T>
using Bvd_traits_point_t = const typename T::Point_2&;

template <class T>
using Is_blinded_2_result_t = decltype(std::declval<const T&>().is_blinded_2_object()(
    std::declval<Bvd_traits_point_t<T>>(), std::declval<Bvd_traits_point_t<T>>(),
    std::declval<Bvd_traits_point_t<T>>(), std::declval<Bvd_traits_point_t<T>>(),
    std::declval<Bvd_traits_point_t<T>>()));

template <class T>
using Compare_blinding_distance_2_result_t =
    decltype(std::declval<const T&>().compare_blinding_distance_2_object()(
        std::declval<Bvd_traits_point_t<T>>(), std::declval<Bvd_traits_point_t<T>>(),
        std::declval<Bvd_traits_point_t<T>>(), std::declval<Bvd_traits_point_t<T>>(),
        std::declval<Bvd_traits_point_t<T>>(), std::declval<Bvd_traits_point_t<T>>(),
        std::declval<Bvd_traits_point_t<T>>()));

template <class T>
using Construct_clip_point_2_result_t =
    decltype(std::declval<const T&>().construct_clip_point_2_object()(
        std::declval<Bvd_traits_point_t<T>>(), std::declval<Bvd_traits_point_t<T>>(),
        std::declval<Bvd_traits_point_t<T>>(), std::declval<Bvd_traits_point_t<T>>()));

template <class T>
using Construct_circumcenter_2_result_t =
    decltype(std::declval<const T&>().construct_circumcenter_2_object()(
        std::declval<Bvd_traits_point_t<T>>(), std::declval<Bvd_traits_point_t<T>>(),
        std::declval<Bvd_traits_point_t<T>>()));

}  // namespace internal

/// \ingroup PkgCvt2Concepts
/// Whether `T` provides what `BvdTraits_2` requires: the types `FT` and `Point_2` and the four
/// `_object()` accessors, whose functors are callable with the arguments of the concept and
/// return something convertible to `bool`, `CGAL::Comparison_result`, `Point_2` and `Point_2`.
/// A `std::true_type` or `std::false_type`. It checks signatures only, not the exactness the
/// concept asks of the predicates.
template <class T, class = void>
struct is_bvd_traits_2 : std::false_type {};

/// \cond SKIP_IN_MANUAL
template <class T>
struct is_bvd_traits_2<
    T, std::void_t<typename T::FT, typename T::Point_2, internal::Is_blinded_2_result_t<T>,
                   internal::Compare_blinding_distance_2_result_t<T>,
                   internal::Construct_clip_point_2_result_t<T>,
                   internal::Construct_circumcenter_2_result_t<T>>>
    : std::bool_constant<std::is_convertible<internal::Is_blinded_2_result_t<T>, bool>::value &&
                         std::is_convertible<internal::Compare_blinding_distance_2_result_t<T>,
                                             CGAL::Comparison_result>::value &&
                         std::is_convertible<internal::Construct_clip_point_2_result_t<T>,
                                             typename T::Point_2>::value &&
                         std::is_convertible<internal::Construct_circumcenter_2_result_t<T>,
                                             typename T::Point_2>::value> {};
/// \endcond

/// \ingroup PkgCvt2Concepts
/// `is_bvd_traits_2<T>::value`.
template <class T>
inline constexpr bool is_bvd_traits_2_v = is_bvd_traits_2<T>::value;

}  // namespace CVT_2

#endif  // CVT_2_CONCEPTS_BVDTRAITS_2_H
