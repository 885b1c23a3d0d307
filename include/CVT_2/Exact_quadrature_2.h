// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Exact_quadrature_2: closed-form cell moments for a uniform density.
#ifndef CVT_2_EXACT_QUADRATURE_2_H
#define CVT_2_EXACT_QUADRATURE_2_H

#include <CVT_2/Cell_moments_2.h>
#include <CVT_2/internal/polygon_moments.h>

#include <cstddef>
#include <type_traits>

namespace CVT_2 {

/// \ingroup PkgCvt2Policies
/// A model of `CellQuadrature_2` for a uniform density: the moments of the cell in closed form
/// (sum over the fan triangles \f$(x, c_i, c_{i+1})\f$ of their area, first and second moments),
/// times \f$\rho(x)\f$.
///
/// It evaluates \f$\rho\f$ once, at the generator \f$x\f$, and takes it for constant: with a
/// variable density it returns the moments of the constant density \f$\rho(x)\f$, not those of
/// \f$\rho\f$. The Lloyd optimizer selects it only for uniform densities; use
/// `Gauss_quadrature_2` otherwise. Exact up to rounding (exact with an exact kernel); it
/// ignores `resolution`.
///
/// \tparam K a CGAL kernel with Cartesian coordinates.
/// \sa `Gauss_quadrature_2`, `Midpoint_quadrature_2`, `Cell_moments_2`
template <class K>
class Exact_quadrature_2 {
 public:
  using Geom_traits = K;                   ///< the kernel
  using FT = typename K::FT;               ///< the number type
  using Point_2 = typename K::Point_2;     ///< the point type
  using Cell_moments = Cell_moments_2<K>;  ///< the result type

  /// The moments of `cell` relative to `x` under the constant density `rho(x)`.
  /// \tparam Density a model of `DensityFunction_2`: `FT operator()(const Point_2&) const`.
  /// \tparam PointRange a range of `Point_2`, the cell's vertices.
  /// \pre `cell` is a counterclockwise polygon, star-shaped from `x` (it may pass through `x`,
  ///      several times for a generator on constraints); `rho` is constant on the cell.
  template <class Density, class PointRange>
  Cell_moments operator()(const Point_2& x, const PointRange& cell, const Density& rho,
                          std::size_t /*resolution*/) const {
    static_assert(std::is_invocable_r_v<FT, const Density&, const Point_2&>,
                  "Density must model DensityFunction_2: FT operator()(const Point_2&) const");
    Cell_moments m = internal::fan_moments_2<K>(x, cell);
    const FT r = rho(x);
    m.mass *= r;
    m.first_moment = m.first_moment * r;
    m.energy *= r;
    return m;
  }
};

}  // namespace CVT_2

#endif  // CVT_2_EXACT_QUADRATURE_2_H
