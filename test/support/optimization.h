// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// What the Lloyd and L-BFGS tests share: the domains they descend on, the checks of a result
// stopped by the move-ratio rule, the count of generators on either side of a density's slope.
#ifndef CVT_2_TEST_SUPPORT_OPTIMIZATION_H
#define CVT_2_TEST_SUPPORT_OPTIMIZATION_H

#include "support.h"

#include <CVT_2/Lloyd_optimizer_2.h>
#include <CVT_2/Optimization_result.h>

#include <catch2/catch.hpp>

#include <cstddef>

namespace support {

// Shipped domains for the energy-descent tests: clusters and inner constraints, a square with
// inner polylines, county borders, a figure with a long boundary.
inline const char* const descent_domains[] = {"four_clusters.poly", "square_inner_constraints.poly",
                                              "us_massachusetts_counties.poly", "earcut_dude.poly"};

// A result stopped by the rule: every move ratio of the last evaluation below `bound`, not so
// one iteration before, and figures that are those of the last evaluation.
inline void check_converged(const CVT_2::Optimization_result& r, double bound = 0.01) {
  CHECK(r.stop_reason == CVT_2::CONVERGED);
  CHECK(r.max_move_ratio < bound);
  REQUIRE(r.max_move_ratio_history.size() == r.number_of_iterations + 1);
  REQUIRE(r.number_of_iterations >= 1);
  CHECK(r.max_move_ratio_history[r.number_of_iterations - 1] >= bound);
  CHECK(r.energy == r.energy_history.back());
}

// A new evaluation of the final points at the highest resolution finds the result's figures
// (uniform density: the same closed forms, so to rounding).
inline void check_result_describes_points(Cdt& cdt, const CVT_2::Optimization_result& r,
                                          double bound = 0.01) {
  CVT_2::Lloyd_optimizer_2<Cdt> check(cdt);
  const auto& e = check.evaluate(100);
  CHECK(e.max_move_ratio < bound);
  CHECK(e.energy == Approx(r.energy).epsilon(1e-12));
  CHECK(e.max_move_ratio == Approx(r.max_move_ratio).epsilon(1e-9));
}

// Generators with x >= 0.5 over those with x < 0.5.
inline double right_to_left(const Cdt& cdt) {
  std::size_t left = 0, right = 0;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    (v->point().x() < 0.5 ? left : right) += 1;
  return double(right) / double(left);
}

}  // namespace support

#endif  // CVT_2_TEST_SUPPORT_OPTIMIZATION_H
