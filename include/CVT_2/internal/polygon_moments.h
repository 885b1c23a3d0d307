// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Fan walks and closed-form moments of triangles and polygons relative to a point.
#ifndef CVT_2_INTERNAL_POLYGON_MOMENTS_H
#define CVT_2_INTERNAL_POLYGON_MOMENTS_H

#include <CVT_2/Cell_moments_2.h>

#include <iterator>

namespace CVT_2 {
namespace internal {

// Calls visit(p, q) for every edge (p, q) of the closed polygon `polygon`, the last one back to
// the first vertex. Points are copied, so ranges that make their points on the fly work too.
template <class PointRange, class Visitor>
void for_each_polygon_edge(const PointRange& polygon, Visitor visit) {
  auto it = std::begin(polygon);
  const auto end = std::end(polygon);
  if (it == end) return;
  const auto first = *it;
  auto previous = first;
  for (++it; it != end; ++it) {
    const auto current = *it;
    visit(previous, current);
    previous = current;
  }
  visit(previous, first);
}

// The moments of the triangle (x, p, q) under the density 1, relative to x: with a = p - x,
// b = q - x and A = cross(a, b) / 2 (signed, so a fan of a ccw polygon sums to the polygon),
// ∫1 = A, ∫(y - x) = A (a + b) / 3, ∫|y - x|² = A / 6 (|a|² + |b|² + a·b).
template <class K>
Cell_moments_2<K> triangle_moments_2(const typename K::Point_2& x, const typename K::Point_2& p,
                                     const typename K::Point_2& q) {
  using FT = typename K::FT;
  const FT ax = p.x() - x.x(), ay = p.y() - x.y();
  const FT bx = q.x() - x.x(), by = q.y() - x.y();
  const FT area = (ax * by - ay * bx) / 2;
  Cell_moments_2<K> m;
  m.mass = area;
  m.first_moment = typename K::Vector_2(area * (ax + bx) / 3, area * (ay + by) / 3);
  m.energy = area * (ax * ax + ay * ay + bx * bx + by * by + ax * bx + ay * by) / 6;
  return m;
}

// The moments of a polygon under the density 1, relative to x, as the sum over its fan from x.
// Signed areas make this right for any simple ccw polygon; slits (x repeated) add nothing.
template <class K, class PointRange>
Cell_moments_2<K> fan_moments_2(const typename K::Point_2& x, const PointRange& polygon) {
  using Point_2 = typename K::Point_2;
  Cell_moments_2<K> m;
  for_each_polygon_edge(
      polygon, [&](const Point_2& p, const Point_2& q) { m += triangle_moments_2<K>(x, p, q); });
  return m;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_POLYGON_MOMENTS_H
