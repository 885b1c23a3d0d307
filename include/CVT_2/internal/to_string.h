// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Numbers and points in error messages: 17 significant digits, so a message names the exact
// double that caused it.
#ifndef CVT_2_INTERNAL_TO_STRING_H
#define CVT_2_INTERNAL_TO_STRING_H

#include <CGAL/number_utils.h>

#include <sstream>
#include <string>

namespace CVT_2 {
namespace internal {

template <class NT>
std::string number_to_string(const NT& x) {
  std::ostringstream os;
  os.precision(17);
  os << CGAL::to_double(x);
  return os.str();
}

template <class Point_2>
std::string to_string(const Point_2& p) {
  return '(' + number_to_string(p.x()) + ", " + number_to_string(p.y()) + ')';
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_TO_STRING_H
