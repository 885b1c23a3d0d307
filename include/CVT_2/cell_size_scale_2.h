// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// cell_size_scale_2(): the size of the cells that a number of generators take under a density.
#ifndef CVT_2_CELL_SIZE_SCALE_2_H
#define CVT_2_CELL_SIZE_SCALE_2_H

#include <CVT_2/exceptions.h>
#include <CVT_2/internal/domain_pieces.h>
#include <CVT_2/internal/domain_regions.h>
#include <CVT_2/parameters.h>

#include <cmath>
#include <cstddef>
#include <string>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// The scale \f$\kappa\f$ of the cells that `n` generators take in the domain of `cdt` once
/// optimized under a density, with the point density of `np` as `random_points_in_domain_2()`
/// takes it: about a point \f$x\f$ a cell's size (the spacing of a hexagonal tiling, a cell of
/// area \f$\frac{\sqrt3}{2}h^2\f$) is \f$h(x) = \kappa\,\mu(x)\f$ with `sizing_field(mu)`
/// (\f$\rho = 1/\mu^4\f$), \f$\kappa / \sqrt{d(x)}\f$ with `density(d)` (the point density,
/// \f$d = \rho^{1/2}\f$ for a CVT of density \f$\rho\f$), and \f$\kappa\f$ itself without
/// either. Hexagons of those sizes number `n`: \f$\frac{2}{\sqrt3}\int d / \kappa^2 = n\f$, the
/// integral as `random_points_in_domain_2()` weighs the domain (uniform: the size of `n` equal
/// hexagons, \f$\sqrt{2A/(\sqrt3 n)}\f$). The steps of a conforming line that follow the
/// cells: `insert_conforming_sites_2()` with the spacing \f$h\f$.
/// \throws Domain_error if the domain is empty, `n` is 0, or the mass is not positive and
///         finite; the density's own errors.
template <class CDT, class NP = No_named_parameters>
double cell_size_scale_2(const CDT& cdt, std::size_t n,
                         const NP& np = parameters::default_values()) {
  const auto domain = internal::domain_triangles(cdt);
  if (domain.triangles.empty()) throw Domain_error("cell size: the domain is empty");
  if (n == 0) throw Domain_error("a cell size for 0 cells does not exist");
  double mass = 0;  // at the domain's scale: units of 2^(2e)
  for (const double m : internal::weigh_domain(domain, n, np).mass) mass += m;
  if (!(mass > 0) || !std::isfinite(mass))
    throw Domain_error("cell size: the domain's mass under the density is " + std::to_string(mass) +
                       " (at its scale), not positive and finite");
  return std::ldexp(std::sqrt(2 * mass / (std::sqrt(3.0) * double(n))), domain.e);
}

}  // namespace CVT_2

#endif  // CVT_2_CELL_SIZE_SCALE_2_H
