// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Reading generator points: one 'x y' per line, '#' comments.
#ifndef CVT_2_IO_READ_POINTS_H
#define CVT_2_IO_READ_POINTS_H

#include <CVT_2/IO/internal/line_reader.h>
#include <CVT_2/exceptions.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/internal/snap_to_boundary.h>
#include <CVT_2/parameters.h>

#include <array>
#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace CVT_2 {
namespace IO {

/// \ingroup PkgCvt2IO
/// Points read from a text file, each with its line.
template <class Point_2>
struct Point_data {
  std::string source;              ///< file name, for messages
  std::vector<Point_2> points;     ///< in file order
  std::vector<std::size_t> lines;  ///< the line of each point
  /// each point equal to an earlier one, as (its line, the earlier one's line): inserting them
  /// merges them
  std::vector<std::array<std::size_t, 2>> repeated_points;
  /// the lines `x y 1` skipped: constrained generators of a file `cvt2 --points-out` wrote,
  /// which the domain gives
  std::size_t constrained_skipped = 0;
};

/// \ingroup PkgCvt2IO
/// Reads one point `x y` per line; blank lines and `#` comments are skipped. A line `x y c`, as
/// `cvt2 --points-out` writes them (`c` = 1 for a constrained generator), is read as `x y` if
/// `c` is 0 and skipped if it is 1 (the domain gives its constrained generators), so that a
/// run continues from another's generators.
/// \throws Parse_error on a line that is not two finite numbers, or those and a 0 or a 1.
template <class Point_2>
Point_data<Point_2> read_points(std::istream& is, const std::string& source = "<points>") {
  internal::Line_reader in(is, source);
  Point_data<Point_2> data;
  data.source = source;
  for (std::vector<std::string> t; in.next(t);) {
    if (t.size() != 2 && (t.size() != 3 || (t[2] != "0" && t[2] != "1")))
      in.fail("expected 'x y' (or 'x y c', c 0 or 1, as cvt2 --points-out writes)",
              t.size() > 2 ? t[2] : t[0]);
    const Point_2 p(in.real(t[0]), in.real(t[1]));
    if (t.size() == 3 && t[2] == "1") {
      ++data.constrained_skipped;
      continue;
    }
    data.points.push_back(p);
    data.lines.push_back(in.line());
  }
  data.repeated_points = internal::repeated_points(data.points, data.lines);
  return data;
}

/// \ingroup PkgCvt2IO
/// Reads the points of file `filename`. \throws Parse_error, also when it cannot be opened.
template <class Point_2>
Point_data<Point_2> read_points(const std::string& filename) {
  std::ifstream is = internal::open_input(filename);
  return read_points<Point_2>(is, filename);
}

/// \ingroup PkgCvt2IO
/// Reads numbers, one or more a line, in order (a value per cell, say); blank lines and `#`
/// comments are skipped. \throws Parse_error on a word that is not a finite number, also when
/// the file cannot be opened.
inline std::vector<double> read_values(const std::string& filename) {
  std::ifstream is = internal::open_input(filename);
  internal::Line_reader in(is, filename);
  std::vector<double> values;
  for (std::vector<std::string> t; in.next(t);)
    for (const std::string& word : t) values.push_back(in.real(word));
  return values;
}

/// \ingroup PkgCvt2IO
/// Inserts the points as generators (`insert_generators_2()`, which keeps the domain's marking,
/// and takes its named parameter `boundary_tolerance`).
/// \returns the points moved onto the boundary (`moved_points_note()` says which).
/// \throws Domain_error naming the file and line of the points outside the domain (the first
///         few, with how many).
template <class CDT, class NP = No_named_parameters>
Generator_insertion_result<typename CDT::Point_2> insert_points(
    CDT& cdt, const Point_data<typename CDT::Point_2>& data,
    const NP& np = parameters::default_values()) {
  const auto where = [&data](std::size_t k) {
    return data.source + ":" + std::to_string(data.lines[k]);
  };
  try {
    return insert_generators_2(cdt, data.points, np);
  } catch (const internal::Generators_outside_error& e) {
    if (e.index() >= data.lines.size()) throw;
    throw Domain_error(where(e.index()) + ": " + e.message([&](std::size_t k) {
      return "line " + std::to_string(data.lines[k]);
    }),
                       e.index());
  } catch (const Domain_error& e) {
    if (e.index() >= data.lines.size()) throw;
    throw Domain_error(where(e.index()) + ": " + e.what(), e.index());
  }
}

/// \ingroup PkgCvt2IO
/// The note on the points `insert_points()` moved onto the boundary, naming each by its file and
/// line (the first in full, how many, the next few); empty if none was.
template <class Point_2>
std::string moved_points_note(const Point_data<Point_2>& data,
                              const Generator_insertion_result<Point_2>& r) {
  return internal::moved_points_note(
      r, data.points,
      [&data](std::size_t k) { return data.source + ":" + std::to_string(data.lines[k]); },
      [&data](std::size_t k) { return "line " + std::to_string(data.lines[k]); });
}

}  // namespace IO
}  // namespace CVT_2

#endif  // CVT_2_IO_READ_POINTS_H
