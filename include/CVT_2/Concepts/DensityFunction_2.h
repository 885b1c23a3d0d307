// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The DensityFunction_2 concept: the density that weighs the Lloyd centroids, and its check.
#ifndef CVT_2_CONCEPTS_DENSITYFUNCTION_2_H
#define CVT_2_CONCEPTS_DENSITYFUNCTION_2_H

#include <type_traits>
#include <utility>
#include <vector>

#ifdef DOXYGEN_RUNNING
// A concept is not a C++ type; as in CGAL, Doxygen sees it as a class that lists the
// requirements. The compiler never sees this class.

/// \ingroup PkgCvt2Concepts
/// A density \f$\rho\f$ over the plane, which weighs the centroids of the Lloyd iteration: each
/// generator moves to the centroid of its cell under \f$\rho\f$, so cells shrink where
/// \f$\rho\f$ is large. In 2D the cell size \f$\mu\f$ goes as \f$\rho^{-1/4}\f$.
///
/// A model is any copyable function object with this call operator, lambdas included. The
/// quadratures call it from several points of each cell, possibly from several threads at once,
/// so it must not change state.
///
/// \pre \f$\rho(p) > 0\f$ and finite at every point `p` of the domain.
/// \cgalHasModel `CVT_2::Uniform_density_2<K>`
/// \cgalHasModel `CVT_2::Sizing_field_density_2<K, Sizing>`
/// \cgalHasModel any lambda `[](const K::Point_2& p) -> K::FT { ... }`
/// \sa `CVT_2::is_density_function_2`
/// \sa `SizingField_2`
class DensityFunction_2 {
 public:
  /// the density \f$\rho(p)\f$, positive and finite.
  FT operator()(const Point_2& p) const;

  /// Optional: a model of `DensityFunction_2` equal to this one (bit for bit) at every point
  /// within distance `radius` of `center`, and cheaper to evaluate there. The Lloyd optimizer
  /// asks for it once a cell, with the disk around the generator that holds the cell, when
  /// `CVT_2::has_restrict_to_disk` says it exists; the quadrature then evaluates the
  /// restriction. `CVT_2::Boundary_lipschitz_sizing_2` (through
  /// `CVT_2::Sizing_field_density_2`) provides one: near a point only a few boundary segments
  /// can be the nearest. If the restriction has the batch member `evaluate()` and the
  /// quadrature has `nodes()`, the optimizer asks it for all the cell's quadrature points in
  /// one call (the same bits).
  Restriction restrict_to_disk(const Point_2& center, const FT& radius) const;

  /// Optional: the densities at many points at once, `values[i]` = \f$\rho\f$(`points[i]`), for
  /// a density that is cheaper by the batch than point by point (one that calls an
  /// interpreter, say: the Python module's callables). When `CVT_2::has_batch_evaluation` says
  /// it exists, `Lloyd_optimizer_2` (and so both optimizers) evaluates each chunk of cells in two
  /// passes: the quadrature first runs with a density that records the points it asks for, then
  /// this member is called once for the whole chunk, then the quadrature runs again on the
  /// recorded values, which it asks for in the same order. `random_points_in_domain_2()` calls it
  /// once for all its sub-triangles. The result is the same, bit for bit, as with `operator()`
  /// at each point; the quadrature must ask for the same points whatever the values (the
  /// library's quadratures do). It is called from several threads at once, each with its own
  /// chunk, and must leave `values` with exactly one value a point (the optimizer checks the
  /// count, and that each value is positive and finite, naming the point). `restrict_to_disk()`
  /// is not used then.
  void evaluate(const std::vector<Point_2>& points, std::vector<FT>& values) const;
};
#endif  // DOXYGEN_RUNNING

namespace CVT_2 {
namespace internal {

template <class D, class K>
using Density_function_2_result_t =
    decltype(std::declval<const D&>()(std::declval<const typename K::Point_2&>()));

}  // namespace internal

/// \ingroup PkgCvt2Concepts
/// Whether `D` provides what `DensityFunction_2` requires for the kernel `K`: a const call
/// operator that takes a `K::Point_2` and returns something convertible to `K::FT`. A
/// `std::true_type` or `std::false_type`. It checks the signature only, not that
/// \f$\rho > 0\f$.
template <class D, class K, class = void>
struct is_density_function_2 : std::false_type {};

/// \cond SKIP_IN_MANUAL
template <class D, class K>
struct is_density_function_2<D, K, std::void_t<internal::Density_function_2_result_t<D, K>>>
    : std::is_convertible<internal::Density_function_2_result_t<D, K>, typename K::FT> {};
/// \endcond

/// \ingroup PkgCvt2Concepts
/// `is_density_function_2<D, K>::value`.
template <class D, class K>
inline constexpr bool is_density_function_2_v = is_density_function_2<D, K>::value;

/// \ingroup PkgCvt2Concepts
/// Whether the density function or sizing field `F` has the optional member of
/// `DensityFunction_2` and `SizingField_2`:
/// `restrict_to_disk(const K::Point_2& center, const K::FT& radius) const`. A
/// `std::true_type` or `std::false_type`.
template <class F, class K, class = void>
struct has_restrict_to_disk : std::false_type {};

/// \cond SKIP_IN_MANUAL
template <class F, class K>
struct has_restrict_to_disk<
    F, K,
    std::void_t<decltype(std::declval<const F&>().restrict_to_disk(
        std::declval<const typename K::Point_2&>(), std::declval<const typename K::FT&>()))>>
    : std::true_type {};
/// \endcond

/// \ingroup PkgCvt2Concepts
/// `has_restrict_to_disk<F, K>::value`.
template <class F, class K>
inline constexpr bool has_restrict_to_disk_v = has_restrict_to_disk<F, K>::value;

/// \ingroup PkgCvt2Concepts
/// Whether the density function `D` has the optional batch member of `DensityFunction_2`:
/// `evaluate(const std::vector<K::Point_2>& points, std::vector<K::FT>& values) const`. A
/// `std::true_type` or `std::false_type`.
template <class D, class K, class = void>
struct has_batch_evaluation : std::false_type {};

/// \cond SKIP_IN_MANUAL
template <class D, class K>
struct has_batch_evaluation<D, K,
                            std::void_t<decltype(std::declval<const D&>().evaluate(
                                std::declval<const std::vector<typename K::Point_2>&>(),
                                std::declval<std::vector<typename K::FT>&>()))>> : std::true_type {
};
/// \endcond

/// \ingroup PkgCvt2Concepts
/// `has_batch_evaluation<D, K>::value`.
template <class D, class K>
inline constexpr bool has_batch_evaluation_v = has_batch_evaluation<D, K>::value;

}  // namespace CVT_2

#endif  // CVT_2_CONCEPTS_DENSITYFUNCTION_2_H
