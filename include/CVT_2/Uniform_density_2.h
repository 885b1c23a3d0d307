// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Uniform_density_2: the constant density, and is_uniform_density to recognize it.
#ifndef CVT_2_UNIFORM_DENSITY_2_H
#define CVT_2_UNIFORM_DENSITY_2_H

#include <CVT_2/internal/to_string.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CVT_2 {

/// \ingroup PkgCvt2Policies
/// The constant density \f$\rho = c\f$: the cells of the centroidal Voronoi tessellation get
/// about the same size everywhere. It is the default density of the Lloyd iteration;
/// `is_uniform_density` recognizes it, so that the optimizer integrates its cells with exact
/// formulas. The value scales the mass and the energy of every cell but moves no centroid.
///
/// \tparam K a CGAL kernel.
/// \cgalModels `DensityFunction_2`
/// \sa `Sizing_field_density_2`
template <class K>
class Uniform_density_2 {
 public:
  using Geom_traits = K;                ///< the kernel
  using FT = typename K::FT;            ///< the number type
  using Point_2 = typename K::Point_2;  ///< the point type

  Uniform_density_2() : m_value(1) {}  ///< the density 1 everywhere

  /// the density `value` everywhere.
  /// \throws std::invalid_argument if `value` is not positive and finite.
  explicit Uniform_density_2(const FT& value) : m_value(value) {
    if (!(value > 0) || !std::isfinite(CGAL::to_double(value))) {
      throw std::invalid_argument("Uniform_density_2: the density value " +
                                  internal::number_to_string(value) +
                                  " must be positive and finite");
    }
  }

  FT operator()(const Point_2&) const { return m_value; }  ///< \f$\rho(p) = c\f$
  FT value() const { return m_value; }                     ///< the constant \f$c\f$

 private:
  FT m_value;
};

/// \ingroup PkgCvt2Policies
/// Whether the density `D` is a `Uniform_density_2` (const and reference qualifiers aside), in
/// which case a quadrature may ignore its values: a `std::true_type` or `std::false_type`. A
/// lambda that returns a constant is not recognized.
template <class D>
struct is_uniform_density : std::false_type {};

/// \cond SKIP_IN_MANUAL
template <class K>
struct is_uniform_density<Uniform_density_2<K>> : std::true_type {};
template <class D>
struct is_uniform_density<const D> : is_uniform_density<D> {};
template <class D>
struct is_uniform_density<D&> : is_uniform_density<D> {};
/// \endcond

/// \ingroup PkgCvt2Policies
/// `is_uniform_density<D>::value`.
template <class D>
inline constexpr bool is_uniform_density_v = is_uniform_density<D>::value;

}  // namespace CVT_2

#endif  // CVT_2_UNIFORM_DENSITY_2_H
