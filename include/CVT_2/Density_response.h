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
/// take part). NaN where it cannot be measured.
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
  /// Whether the cells follow the density as a start for (or the result of) an optimization
  /// must: false only if, over `fewest_cells` or more, the slope is above `bound` by two
  /// standard errors. True where it cannot be measured.
  bool is_followed() const { return cells < fewest_cells || !(slope - 2 * standard_error > bound); }
};

}  // namespace CVT_2

#endif  // CVT_2_DENSITY_RESPONSE_H
