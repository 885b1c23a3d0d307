// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Which input points the library accepts, and the one message for those it does not; which
// values of a density or a sizing field.
#ifndef CVT_2_INTERNAL_VALID_POINT_H
#define CVT_2_INTERNAL_VALID_POINT_H

#include <CVT_2/internal/layout/double_pair.h>
#include <CVT_2/internal/to_string.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CVT_2 {
namespace internal {

// Coordinates beyond this magnitude make differences overflow in double.
constexpr double max_coordinate = 1e300;

// Whether both coordinates are finite and at most max_coordinate in magnitude.
template <class Point_2>
bool is_valid_point(const Point_2& p) {
  const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
  return std::isfinite(x) && std::isfinite(y) && std::abs(x) <= max_coordinate &&
         std::abs(y) <= max_coordinate;
}

// Why `what` (a name and the point, or the segment it is an end of) is refused.
inline std::string invalid_point_message(const std::string& what) {
  return what + " is not finite or exceeds 1e300 in magnitude";
}

// Whether a value of a density or a sizing field is positive and finite (in double precision):
// one test without branches, for loops over many values.
template <class FT>
bool is_positive_finite(const FT& v) {
  return bool(v > 0) & (CGAL::to_double(v) <= std::numeric_limits<double>::max());
}

// Whether all of `values` are, two at a time for doubles.
template <class FT>
bool all_positive_finite(const std::vector<FT>& values) {
  if constexpr (std::is_same<FT, double>::value) {
    return all_positive_finite(values.data(), values.size());
  } else {
    bool all = true;
    for (const FT& v : values) all &= is_positive_finite(v);
    return all;
  }
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_VALID_POINT_H
