// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Numbers in output files: the shortest decimal that reads back as the same double.
#ifndef CVT_2_IO_INTERNAL_WRITE_NUMBER_H
#define CVT_2_IO_INTERNAL_WRITE_NUMBER_H

#include <CGAL/number_utils.h>

#include <charconv>
#include <ostream>
#include <string>

namespace CVT_2 {
namespace internal {

// Writes x (a double or a CGAL number) as the shortest decimal that reads back as the same
// double, whatever the stream's precision: files round-trip exactly.
template <class NT>
void write_number(std::ostream& os, const NT& value) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof(buffer), CGAL::to_double(value));
  os.write(buffer, r.ptr - buffer);
}

// The same as a string (metadata values).
template <class NT>
std::string number_text(const NT& value) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof(buffer), CGAL::to_double(value));
  return std::string(buffer, r.ptr);
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_IO_INTERNAL_WRITE_NUMBER_H
