// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Numbers and points in error messages: the shortest decimal that reads back as the same double,
// so a message names the exact double that caused it without rounding noise (-84.2, not
// -84.200000000000003).
#ifndef CVT_2_INTERNAL_TO_STRING_H
#define CVT_2_INTERNAL_TO_STRING_H

#include <CGAL/number_utils.h>

#include <charconv>
#include <cmath>
#include <string>

namespace CVT_2 {
namespace internal {

// Positional notation from 1e-5 to 1e16 (100000, not 1e+05), the shortest form beyond (1e-17).
template <class NT>
std::string number_to_string(const NT& value) {
  const double x = CGAL::to_double(value);
  const double m = std::abs(x);
  const bool positional = m == 0 || (m >= 1e-5 && m < 1e16);
  char buffer[64];
  const auto r = positional
                     ? std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::fixed)
                     : std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, r.ptr);
}

template <class Point_2>
std::string to_string(const Point_2& p) {
  return '(' + number_to_string(p.x()) + ", " + number_to_string(p.y()) + ')';
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_TO_STRING_H
