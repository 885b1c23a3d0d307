// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Segments of an input that cross: which, for the readers' and the conforming lines' errors.
#ifndef CVT_2_INTERNAL_CROSSING_SEGMENTS_H
#define CVT_2_INTERNAL_CROSSING_SEGMENTS_H

#include <CVT_2/internal/to_string.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Kernel/global_functions.h>
#include <CGAL/enum.h>

#include <array>
#include <cstddef>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

namespace CVT_2 {
namespace internal {

// A ring's or a line's points, without repeats (nor a ring's closing point).
template <class Range>
auto polyline_points(const Range& points, bool closed) {
  std::vector<std::decay_t<decltype(*std::begin(points))>> p;
  for (const auto& q : points)
    if (p.empty() || q != p.back()) p.push_back(q);
  if (closed && p.size() > 1 && p.front() == p.back()) p.pop_back();
  return p;
}

// p's segments into `out`, a ring's closing one too.
template <class Point_2>
void add_segments(const std::vector<Point_2>& p, bool closed,
                  std::vector<std::array<Point_2, 2>>& out) {
  for (std::size_t k = 0; k + 1 < p.size(); ++k) out.push_back({p[k], p[k + 1]});
  if (closed && p.size() > 2) out.push_back({p.back(), p.front()});
}

// Whether the interiors of ab and cd cross at one point, an end of neither: what a
// triangulation that does not compute intersections refuses (exact orientations).
template <class Point_2>
bool cross_properly(const Point_2& a, const Point_2& b, const Point_2& c, const Point_2& d) {
  const auto s = [](const Point_2& p, const Point_2& q, const Point_2& r) {
    return int(CGAL::orientation(p, q, r));
  };
  return s(a, b, c) * s(a, b, d) < 0 && s(c, d, a) * s(c, d, b) < 0;
}

// ": its segment (a) - (b) crosses (c) - (d)", the first segment of the polyline p that
// crosses an earlier one of p or one of `segments`; empty if none does. For error messages:
// those of `segments` that p's box meets are compared with each of p's.
template <class Point_2>
std::string first_crossing(const std::vector<std::array<Point_2, 2>>& segments,
                           const std::vector<Point_2>& p, bool closed) {
  std::vector<std::array<Point_2, 2>> own;
  add_segments(p, closed, own);
  CGAL::Bbox_2 all;
  for (const Point_2& q : p) all += q.bbox();
  std::vector<std::array<Point_2, 2>> earlier;
  for (const auto& t : segments)
    if (CGAL::do_overlap(all, t[0].bbox() + t[1].bbox())) earlier.push_back(t);
  for (const auto& s : own) {
    const CGAL::Bbox_2 box = s[0].bbox() + s[1].bbox();
    for (const auto& t : earlier)
      if (CGAL::do_overlap(box, t[0].bbox() + t[1].bbox()) &&
          cross_properly(s[0], s[1], t[0], t[1]))
        return ": its segment " + to_string(s[0]) + " - " + to_string(s[1]) + " crosses " +
               to_string(t[0]) + " - " + to_string(t[1]);
    earlier.push_back(s);
  }
  return "";
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_CROSSING_SEGMENTS_H
