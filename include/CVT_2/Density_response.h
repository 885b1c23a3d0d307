// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Density_response: how the cells of a diagram follow a density (density_response_2()).
#ifndef CVT_2_DENSITY_RESPONSE_H
#define CVT_2_DENSITY_RESPONSE_H

#include <cstddef>
#include <limits>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// How cells follow a density (`density_response_2()`): the least-squares slope of log(cell
/// area) against log(density), about -1/2 for a centroidal tessellation, 0 for cells of one
/// size, and its standard error (from the cells' scatter about the line; large where few cells
/// take part), NaN where it cannot be measured; and, on a domain that constraints cut into
/// regions, the energy that the regions' point counts cost.
struct Density_response {
  double slope = std::numeric_limits<double>::quiet_NaN();           ///< the slope
  double standard_error = std::numeric_limits<double>::quiet_NaN();  ///< the slope's
  std::size_t cells = 0;                                             ///< the cells measured
  /// Half way from cells of one size (0) to a centroidal tessellation's (-1/2).
  static constexpr double bound = -0.25;
  /// The fewest cells judged: the law is asymptotic, and a few large cells follow the domain's
  /// shape as much as the density (optimal tessellations of 60 to 120 cells on a figure-shaped
  /// domain, earcut_dude, have slopes up to 0; of 140, -0.3 and below).
  static constexpr std::size_t fewest_cells = 128;
  /// The regions between constraints whose point counts were compared with those the density
  /// asks for; 0 where the domain is one region (or fewer than `fewest_cells` points count).
  std::size_t regions = 0;
  /// The energy that the regions' point counts cost over counts that follow the density, as a
  /// fraction: by Gersho's law a region of mass M (the integral of the density's square root)
  /// in c cells has an energy of about M^2 / c, least when the counts follow M. The reference
  /// is the counts `random_points_in_domain_2()` deals by region: 0 for them, below 0 for
  /// counts the law prefers (it may, by a point or two a region, where regions hold few);
  /// NaN where not measured. A lower bound where a region keeps few cells: its boundary
  /// generators' cells
  /// are strips, not the compact cells of the law (a county emptied of its 59 points costs 117%,
  /// not the 33% predicted).
  double count_excess = std::numeric_limits<double>::quiet_NaN();
  /// The largest `count_excess` that counts may cost: 2% of the energy.
  static constexpr double count_bound = 0.02;
  /// Whether the cells follow the density as a start for (or the result of) an optimization
  /// must: false only if, over `fewest_cells` or more, the slope is above `bound` by two
  /// standard errors, or if the regions' counts cost more than `count_bound`. True where
  /// neither can be measured.
  bool is_followed() const { return is_followed_in_cells() && is_followed_by_counts(); }
  /// the slope's half of `is_followed()`
  bool is_followed_in_cells() const {
    return cells < fewest_cells || !(slope - 2 * standard_error > bound);
  }
  /// the counts' half of `is_followed()`
  bool is_followed_by_counts() const { return regions < 2 || !(count_excess > count_bound); }
};

}  // namespace CVT_2

#endif  // CVT_2_DENSITY_RESPONSE_H
