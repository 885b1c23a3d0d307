// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The CellQuadrature_2 concept: how Lloyd iteration integrates a density over a cell; its check.
#ifndef CVT_2_CONCEPTS_CELLQUADRATURE_2_H
#define CVT_2_CONCEPTS_CELLQUADRATURE_2_H

#include <CVT_2/Cell_moments_2.h>

#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef DOXYGEN_RUNNING
// A concept is not a C++ type; as in CGAL, Doxygen sees it as a class that lists the
// requirements. The compiler never sees this class.

/// \ingroup PkgCvt2Concepts
/// A quadrature that integrates a density \f$\rho\f$ over a cell of a bounded Voronoi diagram:
/// its mass, first moment and energy, relative to the generator \f$x\f$ so that coordinates
/// far from the origin do not cancel (see `CVT_2::Cell_moments_2`).
///
/// The cell is integrated as the fan of triangles \f$(x, c_i, c_{i+1})\f$. A model is a small
/// copyable functor without state that changes between calls: the Lloyd optimizer owns the
/// resolution schedule (the paper's \f$n = 10\f$ to \f$100\f$ sub-triangles as moves shrink)
/// and passes it on every call. Exact models ignore it.
///
/// \cgalHasModel `CVT_2::Gauss_quadrature_2<K>` (any density; with the batch members)
/// \cgalHasModel `CVT_2::Midpoint_quadrature_2<K>` (any density; with the batch members)
/// \cgalHasModel `CVT_2::Exact_quadrature_2<K>` (uniform density only: evaluates \f$\rho(x)\f$)
/// \sa `CVT_2::is_cell_quadrature_2`
class CellQuadrature_2 {
 public:
  /// The moments of `cell` relative to `x` under `rho`, with `resolution` sub-triangles (a
  /// hint for approximate models; the cost of a call grows with it).
  /// \tparam Density a model of `DensityFunction_2`: `FT operator()(const Point_2&) const`,
  ///         lambdas included.
  /// \tparam PointRange a range of `K::Point_2`, the cell's vertices.
  /// \pre `cell` is a counterclockwise polygon, star-shaped from `x`. It may pass through `x`,
  ///      several times for a generator on constraints (slits), so some fan triangles have
  ///      zero area.
  template <class Density, class PointRange>
  CVT_2::Cell_moments_2<K> operator()(const Point_2& x, const PointRange& cell, const Density& rho,
                                      std::size_t resolution) const;

  /// Optional, for densities evaluated in batches (`DensityFunction_2::evaluate()`): appends to
  /// `points` the points at which `operator()` evaluates the density on `cell`, in the order it
  /// does, and to `nodes` what `moments()` needs to finish its sums from the values there.
  /// Returns the number of points appended. Without these two members, the optimizer records
  /// the points by running `operator()` once with a density that notes them, and again on the
  /// values; with them, the cell is subdivided once. `CVT_2::has_quadrature_nodes` tells.
  template <class PointRange>
  std::size_t nodes(const Point_2& x, const PointRange& cell, std::size_t resolution,
                    std::vector<Point_2>& points, std::vector<FT>& nodes) const;

  /// What `operator()` returns, bit for bit, for the cell whose `nodes()` begin at `nodes`,
  /// given the density's values at its `number_of_points` points, in order.
  CVT_2::Cell_moments_2<K> moments(const FT* nodes, const FT* values,
                                   std::size_t number_of_points) const;
};
#endif  // DOXYGEN_RUNNING

namespace CVT_2 {
namespace internal {

template <class Q, class K, class Density, class PointRange>
using Cell_quadrature_2_result_t = decltype(std::declval<const Q&>()(
    std::declval<const typename K::Point_2&>(), std::declval<const PointRange&>(),
    std::declval<const Density&>(), std::declval<std::size_t>()));

}  // namespace internal

/// \ingroup PkgCvt2Concepts
/// Whether `Q` provides what `CellQuadrature_2` requires for the kernel `K`, the density type
/// `Density` and cells given as `PointRange`: a const call operator taking
/// `(const K::Point_2&, const PointRange&, const Density&, std::size_t)` and returning something
/// convertible to `Cell_moments_2<K>`, with `Density` callable as
/// `K::FT operator()(const K::Point_2&) const`. A `std::true_type` or `std::false_type`. It
/// checks signatures only, not the accuracy of the quadrature.
template <class Q, class K, class Density, class PointRange = std::vector<typename K::Point_2>,
          class = void>
struct is_cell_quadrature_2 : std::false_type {};

/// \cond SKIP_IN_MANUAL
template <class Q, class K, class Density, class PointRange>
struct is_cell_quadrature_2<
    Q, K, Density, PointRange,
    std::void_t<internal::Cell_quadrature_2_result_t<Q, K, Density, PointRange>>>
    : std::bool_constant<
          std::is_convertible<internal::Cell_quadrature_2_result_t<Q, K, Density, PointRange>,
                              Cell_moments_2<K>>::value &&
          std::is_invocable_r<typename K::FT, const Density&, const typename K::Point_2&>::value> {
};
/// \endcond

/// \ingroup PkgCvt2Concepts
/// `is_cell_quadrature_2<Q, K, Density>::value`.
template <class Q, class K, class Density, class PointRange = std::vector<typename K::Point_2>>
inline constexpr bool is_cell_quadrature_2_v =
    is_cell_quadrature_2<Q, K, Density, PointRange>::value;

/// \ingroup PkgCvt2Concepts
/// Whether the quadrature `Q` has the optional members of `CellQuadrature_2` for densities
/// evaluated in batches, `nodes()` and `moments()`, for the kernel `K`. A `std::true_type` or
/// `std::false_type`.
template <class Q, class K, class = void>
struct has_quadrature_nodes : std::false_type {};

/// \cond SKIP_IN_MANUAL
template <class Q, class K>
struct has_quadrature_nodes<
    Q, K,
    std::void_t<decltype(std::declval<const Q&>().nodes(
                    std::declval<const typename K::Point_2&>(),
                    std::declval<const std::vector<typename K::Point_2>&>(),
                    std::declval<std::size_t>(), std::declval<std::vector<typename K::Point_2>&>(),
                    std::declval<std::vector<typename K::FT>&>())),
                decltype(std::declval<const Q&>().moments(
                    std::declval<const typename K::FT*>(), std::declval<const typename K::FT*>(),
                    std::declval<std::size_t>()))>> : std::true_type {};
/// \endcond

/// \ingroup PkgCvt2Concepts
/// `has_quadrature_nodes<Q, K>::value`.
template <class Q, class K>
inline constexpr bool has_quadrature_nodes_v = has_quadrature_nodes<Q, K>::value;

}  // namespace CVT_2

#endif  // CVT_2_CONCEPTS_CELLQUADRATURE_2_H
