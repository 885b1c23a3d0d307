// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Sizing_field_density_2: the density rho = 1/mu^4 whose CVT cells have the size mu of a sizing
// field.
#ifndef CVT_2_SIZING_FIELD_DENSITY_2_H
#define CVT_2_SIZING_FIELD_DENSITY_2_H

#include <CGAL/number_utils.h>
#include <CVT_2/Concepts/DensityFunction_2.h>
#include <CVT_2/Concepts/SizingField_2.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/valid_point.h>
#include <CVT_2/mark_domain_2.h>

#include <cmath>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Policies
/// The density \f$\rho = 1/\mu^4\f$ of a sizing field \f$\mu\f$: the cells of a centroidal
/// Voronoi tessellation under \f$\rho\f$ have a diameter proportional to \f$\mu\f$.
///
/// In dimension \f$d\f$ the cell size goes as \f$\rho^{-1/(d+2)}\f$ [DW03], so in 2D
/// \f$\mu \propto \rho^{-1/4}\f$ and \f$\rho = 1/\mu^4\f$. The paper (Section 3) prints the
/// relation inverted, \f$\mu = 1/\rho^4\f$; that would make cells largest where the density is
/// largest.
///
/// \tparam K a CGAL kernel.
/// \tparam Sizing a model of `SizingField_2` for `K`, for example `Boundary_lipschitz_sizing_2`
///         or a lambda.
/// \cgalModels `DensityFunction_2`
/// \sa `make_sizing_field_density_2()`
template <class K, class Sizing>
class Sizing_field_density_2 {
  static_assert(is_sizing_field_2<Sizing, K>::value,
                "Sizing must model SizingField_2: FT operator()(const Point_2&) const");

 public:
  using Geom_traits = K;                ///< the kernel
  using FT = typename K::FT;            ///< the number type
  using Point_2 = typename K::Point_2;  ///< the point type
  using Sizing_field = Sizing;          ///< the sizing field type

  /// the density of the sizing field `sizing`.
  explicit Sizing_field_density_2(Sizing sizing) : m_sizing(std::move(sizing)) {}

  /// \f$\rho(p) = 1/\mu(p)^4\f$.
  /// \throws Domain_error if \f$\mu(p)\f$ is not positive and finite, or so large or small that
  ///         \f$1/\mu^4\f$ leaves the range of `double`; the message gives `p` and \f$\mu(p)\f$.
  FT operator()(const Point_2& p) const { return density(p, m_sizing(p)); }

  /// \f$1/\mu^4\f$ at each of `points` into `values` (replaced), from the sizing field's own
  /// batch evaluation, bit for bit what the call operator gives; only if `Sizing` has one (a
  /// restriction of `Boundary_lipschitz_sizing_2` does). The same checks.
  template <class S = Sizing, std::enable_if_t<has_batch_evaluation_v<S, K>, int> = 0>
  void evaluate(const std::vector<Point_2>& points, std::vector<FT>& values) const {
    m_sizing.evaluate(points, values);
    if (values.size() != points.size())
      throw Domain_error("the sizing field's batch evaluation gave " +
                         std::to_string(values.size()) + " values for " +
                         std::to_string(points.size()) + " points");
    // 1/mu^4 in a loop the compiler vectorizes, beside the sizes, and the checks of density()
    // on all the values at once; on a bad value, density() on each size in turn, to say where
    thread_local std::vector<FT> densities;
    densities.resize(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
      const FT mu2 = values[i] * values[i];
      densities[i] = FT(1) / (mu2 * mu2);
    }
    if (!internal::all_positive_finite(values) || !internal::all_positive_finite(densities))
      for (std::size_t i = 0; i < points.size(); ++i) densities[i] = density(points[i], values[i]);
    values.swap(densities);
  }

  /// The density of the sizing field's restriction to the disk (see
  /// `DensityFunction_2::restrict_to_disk()`); only if `Sizing` has one.
  template <class S = Sizing, std::enable_if_t<has_restrict_to_disk_v<S, K>, int> = 0>
  auto restrict_to_disk(const Point_2& center, const FT& radius) const {
    using Restriction = decltype(m_sizing.restrict_to_disk(center, radius));
    return Sizing_field_density_2<K, Restriction>(m_sizing.restrict_to_disk(center, radius));
  }

  const Sizing& sizing() const { return m_sizing; }  ///< the sizing field \f$\mu\f$

 private:
  // 1/mu^4, mu the field at p, checked
  static FT density(const Point_2& p, const FT& mu) {
    if (!internal::is_positive_finite(mu)) throw error(p, mu, "it must be positive and finite");
    const FT mu2 = mu * mu;
    const FT rho = FT(1) / (mu2 * mu2);
    // 1/mu^4 under- or overflows for mu beyond about 1e77 or below 1e-77.
    if (!internal::is_positive_finite(CGAL::to_double(rho)))
      throw error(p, mu, "1/size^4 leaves the range of double");
    return rho;
  }

  static Domain_error error(const Point_2& p, const FT& mu, const char* why) {
    return Domain_error("the sizing field is " + internal::number_to_string(mu) + " at " +
                        internal::to_string(p) + ": " + why);
  }

  Sizing m_sizing;
};

/// \ingroup PkgCvt2Policies
/// The density \f$1/\mu^4\f$ of the sizing field `sizing`, its type deduced:
/// `make_sizing_field_density_2<K>([](const K::Point_2& p) { return 0.1 + p.x(); })`.
/// \tparam K a CGAL kernel.
/// \tparam Sizing a model of `SizingField_2` for `K`.
template <class K, class Sizing>
Sizing_field_density_2<K, Sizing> make_sizing_field_density_2(Sizing sizing) {
  return Sizing_field_density_2<K, Sizing>(std::move(sizing));
}

}  // namespace CVT_2

#endif  // CVT_2_SIZING_FIELD_DENSITY_2_H
