// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Random valid domains on a grid: star-shaped or notched outer rings, rectangular and
// triangular holes, inner polylines that meet and touch, degenerate points.
#ifndef CVT_2_TEST_RANDOM_DOMAIN_H
#define CVT_2_TEST_RANDOM_DOMAIN_H

#include "support.h"

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <vector>

namespace support {

// On a grid of step 1/8 in [0, 10]², so that the input is exactly representable and full of
// degeneracies: collinear and cocircular points, a polyline ending inside another segment,
// segments that overlap, points on constraints. No two segments cross.
inline CVT_2::IO::Poly_data<Point> random_domain(unsigned seed, std::vector<Point>& generators,
                                                 std::size_t n_points) {
  std::mt19937_64 rng(seed);
  const auto grid = [&](int lo, int hi) { return uniform_int(rng, lo, hi) / 8.0; };
  CVT_2::IO::Poly_data<Point> poly;
  std::vector<Segment> segments;
  const auto add_vertex = [&](const Point& p) {
    for (std::size_t i = 0; i < poly.vertices.size(); ++i)
      if (poly.vertices[i] == p) return i;
    poly.vertices.push_back(p);
    poly.vertex_lines.push_back(poly.vertices.size());
    return poly.vertices.size() - 1;
  };
  // A segment may touch others (endpoint on them, overlap) but not cross them.
  const auto crosses = [&](const Segment& s) {
    for (const Segment& t : segments) {
      if (!CGAL::do_intersect(s, t)) continue;
      const auto o1 = CGAL::orientation(s.source(), s.target(), t.source());
      const auto o2 = CGAL::orientation(s.source(), s.target(), t.target());
      const auto o3 = CGAL::orientation(t.source(), t.target(), s.source());
      const auto o4 = CGAL::orientation(t.source(), t.target(), s.target());
      if (o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o3 != CGAL::COLLINEAR &&
          o4 != CGAL::COLLINEAR)
        return true;  // a proper crossing
    }
    return false;
  };
  const auto add_segment = [&](const Point& a, const Point& b) {
    if (a == b || crosses(Segment(a, b))) return false;
    for (const Point& seed : poly.holes)
      if (Segment(a, b).has_on(seed)) return false;
    segments.emplace_back(a, b);
    poly.segments.push_back({add_vertex(a), add_vertex(b)});
    poly.segment_lines.push_back(poly.segments.size());
    return true;
  };
  // The outer ring: a square with some extra collinear vertices, a notched square, or a random
  // star-shaped polygon of 5 to 16 grid vertices around (5, 5).
  std::vector<Point> ring{Point(0, 0), Point(5, 0), Point(10, 0), Point(10, 10), Point(0, 10)};
  const auto shape = rng() % 3;
  if (shape == 1)
    ring = {Point(0, 0), Point(10, 0), Point(10, 10), Point(6, 10),
            Point(5, 4), Point(4, 10), Point(0, 10)};
  if (shape == 2) {
    std::vector<double> angles(5 + rng() % 12);
    for (double& a : angles) a = uniform(rng, 0, 2 * CGAL_PI);
    std::sort(angles.begin(), angles.end());
    std::vector<Point> star;
    for (const double a : angles) {
      const double r = uniform(rng, 2, 5);
      const Point p(std::round((5 + r * std::cos(a)) * 8) / 8,
                    std::round((5 + r * std::sin(a)) * 8) / 8);
      if (star.empty() || (p != star.back() && p != star.front())) star.push_back(p);
    }
    if (star.size() >= 3 && CGAL::is_simple_2(star.begin(), star.end(), K())) ring = star;
  }
  for (std::size_t i = 0; i < ring.size(); ++i) add_segment(ring[i], ring[(i + 1) % ring.size()]);
  // Rectangular holes, each with its seed at its center.
  const int holes = static_cast<int>(rng() % 4);
  std::vector<CGAL::Bbox_2> boxes;
  for (int h = 0; h < holes; ++h) {
    const double x = grid(4, 64), y = grid(4, 24), w = grid(2, 10), t = grid(2, 10);
    const Point c[4] = {Point(x, y), Point(x, y + t), Point(x + w, y + t), Point(x + w, y)};
    const CGAL::Bbox_2 box(x, y, x + w, y + t);
    bool ok = true;
    for (const auto& b : boxes) ok = ok && !CGAL::do_overlap(b, box);  // nor in another hole
    for (int i = 0; i < 4 && ok; ++i) ok = !crosses(Segment(c[i], c[(i + 1) % 4]));
    for (const Point& p : poly.vertices)  // nothing inside the hole
      ok = ok && !(p.x() > x && p.x() < x + w && p.y() > y && p.y() < y + t);
    if (!ok) continue;
    for (int i = 0; i < 4; ++i) add_segment(c[i], c[(i + 1) % 4]);
    boxes.push_back(box);
    poly.holes.emplace_back(x + w / 2, y + t / 2);
    poly.hole_lines.push_back(0);
  }
  // Triangular holes of area 1/2 or more, seeded at their centroid.
  const int triangles = static_cast<int>(rng() % 3);
  for (int h = 0; h < triangles; ++h) {
    const Point c[3] = {Point(grid(4, 76), grid(4, 76)), Point(grid(4, 76), grid(4, 76)),
                        Point(grid(4, 76), grid(4, 76))};
    const K::Triangle_2 t(c[0], c[1], c[2]);
    bool ok = std::abs(t.area()) >= 0.5;
    for (const auto& b : boxes) ok = ok && !CGAL::do_overlap(b, t.bbox());
    for (int i = 0; i < 3 && ok; ++i) ok = !crosses(Segment(c[i], c[(i + 1) % 3]));
    for (const Point& p : poly.vertices) ok = ok && t.has_on_unbounded_side(p);
    if (!ok) continue;
    for (int i = 0; i < 3; ++i) add_segment(c[i], c[(i + 1) % 3]);
    boxes.push_back(t.bbox());
    poly.holes.push_back(CGAL::centroid(t));
    poly.hole_lines.push_back(0);
  }
  // Inner polylines: random walks, some starting at an existing vertex or on a segment.
  const int polylines = static_cast<int>(rng() % 6);
  for (int l = 0; l < polylines; ++l) {
    Point p(grid(8, 72), grid(8, 72));
    if (rng() % 3 == 0) p = poly.vertices[rng() % poly.vertices.size()];
    const int steps = 1 + static_cast<int>(rng() % 4);
    for (int s = 0; s < steps; ++s) {
      const Point q(std::clamp(p.x() + grid(-24, 24), 0.0, 10.0),
                    std::clamp(p.y() + grid(-24, 24), 0.0, 10.0));
      bool in_hole = false;
      for (std::size_t h = 0; h < poly.holes.size(); ++h)
        in_hole = in_hole || CGAL::squared_distance(q, poly.holes[h]) < 0.01;
      if (!in_hole && add_segment(p, q)) p = q;
    }
  }
  // Generators: random reals, grid points (cocircular), and points on constraints.
  Cdt cdt;
  CVT_2::IO::insert_poly(cdt, poly);
  generators = random_points_in_domain(cdt, n_points / 2, seed + 1);
  while (generators.size() < n_points) {
    const Segment& s = segments[rng() % segments.size()];
    const Point p =
        rng() % 4 ? Point(grid(1, 79), grid(1, 79)) : CGAL::midpoint(s.source(), s.target());
    if (CVT_2::is_in_domain_2(cdt, p)) generators.push_back(p);
  }
  return poly;
}

// How many random cases to run: `suite` in the regular suite, or `share` of CVT_2_RANDOM_CASES
// when it is set (scripts/run_nightly.sh sets thousands).
inline unsigned random_cases(unsigned suite, double share = 1) {
  const char* env = std::getenv("CVT_2_RANDOM_CASES");
  return env ? static_cast<unsigned>(share * double(std::strtoul(env, nullptr, 10))) : suite;
}

// The triangulation of random_domain(seed) with its n generators inserted.
inline Cdt random_triangulation(unsigned seed, std::size_t n) {
  std::vector<Point> generators;
  const auto poly = random_domain(seed, generators, n);
  Cdt cdt;
  CVT_2::IO::insert_poly(cdt, poly);
  CVT_2::insert_generators_2(cdt, generators);
  return cdt;
}

}  // namespace support

#endif  // CVT_2_TEST_RANDOM_DOMAIN_H
