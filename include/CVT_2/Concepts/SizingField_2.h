// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The SizingField_2 concept: the desired cell size at each point, and its check.
#ifndef CVT_2_CONCEPTS_SIZINGFIELD_2_H
#define CVT_2_CONCEPTS_SIZINGFIELD_2_H

#include <type_traits>
#include <utility>

#ifdef DOXYGEN_RUNNING
// A concept is not a C++ type; as in CGAL, Doxygen sees it as a class that lists the
// requirements. The compiler never sees this class.

/// \ingroup PkgCvt2Concepts
/// A sizing field \f$\mu\f$ over the plane: the desired distance between neighboring
/// generators at each point. `CVT_2::Sizing_field_density_2` turns it into the density
/// \f$\rho = 1/\mu^4\f$ that the Lloyd iteration uses.
///
/// A model is any copyable function object with this call operator, lambdas included. It may be
/// called from several threads at once, so it must not change state.
///
/// \pre \f$\mu(p) > 0\f$ and finite at every point `p` of the domain.
/// \cgalHasModel `CVT_2::Boundary_lipschitz_sizing_2<K>`
/// \cgalHasModel any lambda `[](const K::Point_2& p) -> K::FT { ... }`
/// \sa `CVT_2::is_sizing_field_2`
/// \sa `DensityFunction_2`
class SizingField_2 {
 public:
  /// the size \f$\mu(p)\f$, positive and finite.
  FT operator()(const Point_2& p) const;

  /// Optional: a model of `SizingField_2` equal to this one (bit for bit) within distance
  /// `radius` of `center`, and cheaper there; `CVT_2::Sizing_field_density_2` then offers the
  /// same for its density (see `DensityFunction_2::restrict_to_disk()`).
  Restriction restrict_to_disk(const Point_2& center, const FT& radius) const;

  /// Optional: the sizes at many points at once, `values[i]` = \f$\mu\f$(`points[i]`), bit for
  /// bit; `CVT_2::Sizing_field_density_2` then offers the same for its density (see
  /// `DensityFunction_2::evaluate()`). The restrictions of `CVT_2::Boundary_lipschitz_sizing_2`
  /// have it: the optimizers call it once a cell, for all its quadrature points. A sizing field
  /// with this member makes its density a batch density, evaluated by chunks of cells, whose
  /// `restrict_to_disk()` the optimizers then do not use.
  void evaluate(const std::vector<Point_2>& points, std::vector<FT>& values) const;
};
#endif  // DOXYGEN_RUNNING

namespace CVT_2 {
namespace internal {

template <class S, class K>
using Sizing_field_2_result_t =
    decltype(std::declval<const S&>()(std::declval<const typename K::Point_2&>()));

}  // namespace internal

/// \ingroup PkgCvt2Concepts
/// Whether `S` provides what `SizingField_2` requires for the kernel `K`: a const call operator
/// that takes a `K::Point_2` and returns something convertible to `K::FT`. A `std::true_type`
/// or `std::false_type`. It checks the signature only, not that \f$\mu > 0\f$.
template <class S, class K, class = void>
struct is_sizing_field_2 : std::false_type {};

/// \cond SKIP_IN_MANUAL
template <class S, class K>
struct is_sizing_field_2<S, K, std::void_t<internal::Sizing_field_2_result_t<S, K>>>
    : std::is_convertible<internal::Sizing_field_2_result_t<S, K>, typename K::FT> {};
/// \endcond

/// \ingroup PkgCvt2Concepts
/// `is_sizing_field_2<S, K>::value`.
template <class S, class K>
inline constexpr bool is_sizing_field_2_v = is_sizing_field_2<S, K>::value;

}  // namespace CVT_2

#endif  // CVT_2_CONCEPTS_SIZINGFIELD_2_H
