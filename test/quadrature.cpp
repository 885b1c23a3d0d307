// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Properties of the cell quadratures: closed forms, exactness, convergence, counts, slits.
#include "support/cell_quadrature.h"
#include "support/support.h"

#include <CVT_2/Concepts/CellQuadrature_2.h>
#include <CVT_2/Exact_quadrature_2.h>
#include <CVT_2/Gauss_quadrature_2.h>
#include <CVT_2/Midpoint_quadrature_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/convex_hull_2.h>

#include <boost/range/adaptor/transformed.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <random>
#include <vector>

using namespace support;

namespace {

using Points = std::vector<Point>;
using Moments = CVT_2::Cell_moments_2<K>;
using Exact = CVT_2::Exact_quadrature_2<K>;
using Midpoint = CVT_2::Midpoint_quadrature_2<K>;
using Gauss = CVT_2::Gauss_quadrature_2<K>;

struct Star_cell {
  Point x;
  Points cell;  // ccw, star-shaped from x
  double diameter;
};

// A random convex cell of size `scale` (the hull of 3 to 12 points in a disk) around a random
// interior generator, everything moved by `offset` along a random direction.
Star_cell random_convex_cell(std::mt19937_64& rng, double scale, double offset) {
  const auto unit = [](std::mt19937_64& r) { return uniform(r, 0, 1); };
  const double pi = std::acos(-1.0);
  Points local;
  const std::size_t n = 3 + static_cast<std::size_t>(unit(rng) * 10);
  while (local.size() < n) {
    const double r = scale * std::sqrt(unit(rng)), t = 2 * pi * unit(rng);
    local.push_back(Point(r * std::cos(t), r * std::sin(t)));
  }
  Points hull;
  CGAL::convex_hull_2(local.begin(), local.end(), std::back_inserter(hull));
  double wx = 0, wy = 0, wsum = 0;  // x: a convex combination, sometimes close to an edge
  for (const Point& p : hull) {
    const double w = std::pow(unit(rng), 3) + 1e-3;
    wx += w * p.x();
    wy += w * p.y();
    wsum += w;
  }
  const double t = 2 * pi * unit(rng), ox = offset * std::cos(t), oy = offset * std::sin(t);
  Star_cell c{Point(wx / wsum + ox, wy / wsum + oy), {}, 0};
  for (const Point& p : hull) c.cell.push_back(Point(p.x() + ox, p.y() + oy));
  for (const Point& p : c.cell)
    for (const Point& q : c.cell)
      c.diameter = std::max(c.diameter, std::sqrt(CGAL::squared_distance(p, q)));
  return c;
}

// Independent closed forms: Green's theorem relative to the first vertex c0 (the polygon area,
// centroid and second-moment formulas), moved to x by the parallel axis theorem.
Moments polygon_moments_oracle(const Point& x, const Points& cell) {
  const Point& c0 = cell.front();
  double a = 0, sx = 0, sy = 0, j = 0;
  for (std::size_t i = 0; i < cell.size(); ++i) {
    const auto u = cell[i] - c0, v = cell[(i + 1) % cell.size()] - c0;
    const double cross = u.x() * v.y() - v.x() * u.y();
    a += cross / 2;
    sx += cross * (u.x() + v.x()) / 6;
    sy += cross * (u.y() + v.y()) / 6;
    j += cross *
         (u.x() * u.x() + u.x() * v.x() + v.x() * v.x() + u.y() * u.y() + u.y() * v.y() +
          v.y() * v.y()) /
         12;
  }
  const auto d = x - c0;
  Moments m;
  m.mass = a;
  m.first_moment = K::Vector_2(sx - d.x() * a, sy - d.y() * a);
  m.energy = j - 2 * (d.x() * sx + d.y() * sy) + (d.x() * d.x() + d.y() * d.y()) * a;
  return m;
}

// The largest of the three relative errors: mass, first moment (against mass × diameter),
// energy.
double relative_error(const Moments& m, const Moments& ref, double diameter) {
  const double fm = std::sqrt((m.first_moment - ref.first_moment).squared_length());
  return std::max({std::abs(m.mass - ref.mass) / std::abs(ref.mass),
                   fm / (std::abs(ref.mass) * diameter),
                   std::abs(m.energy - ref.energy) / std::abs(ref.energy)});
}

// A density that counts its evaluations.
struct Counting_density {
  std::size_t* calls;
  double operator()(const Point&) const {
    ++*calls;
    return 1;
  }
};

// Checks that the nodes() and moments() of `rule` give its call operator's points, in its order,
// and its bits, on cell c; returns the number of points.
template <class Rule>
std::size_t check_nodes(const Rule& rule, const Star_cell& c, std::size_t resolution) {
  const auto rho = [](const Point& p) { return 1 + 0.5 * std::sin(p.x()) * std::cos(3 * p.y()); };
  std::vector<Point> asked;
  const auto recording = [&](const Point& p) {
    asked.push_back(p);
    return rho(p);
  };
  const Moments direct = rule(c.x, c.cell, recording, resolution);
  std::vector<Point> points;
  std::vector<double> nodes, values;
  const std::size_t count = rule.nodes(c.x, c.cell, resolution, points, nodes);
  REQUIRE(count == points.size());
  CHECK(points == asked);
  for (const Point& p : points) values.push_back(rho(p));
  const Moments m = rule.moments(nodes.data(), values.data(), count);
  CHECK(m.mass == direct.mass);
  CHECK(m.first_moment == direct.first_moment);
  CHECK(m.energy == direct.energy);
  return count;
}

// [-1, 1]² around x = (0, 0) with slits along the positive and negative x axes: the polygon
// goes out to the boundary along each slit and back, so x appears twice.
const Point origin(0, 0);
const Points two_slit_square = {origin, Point(1, 0),  Point(1, 1),   Point(-1, 1), Point(-1, 0),
                                origin, Point(-1, 0), Point(-1, -1), Point(1, -1), Point(1, 0)};

}  // namespace

static_assert(CVT_2::is_cell_quadrature_2_v<Exact, K, double (*)(const Point&)>);
static_assert(CVT_2::is_cell_quadrature_2_v<Midpoint, K, Counting_density>);
static_assert(!CVT_2::is_cell_quadrature_2_v<Midpoint, K, int>, "int is no density");
static_assert(!CVT_2::is_cell_quadrature_2_v<Midpoint, K, Point (*)(const Point&)>,
              "a density returns a number");
static_assert(!CVT_2::is_cell_quadrature_2_v<int, K, Counting_density>);
static_assert(!CVT_2::is_cell_quadrature_2_v<Counting_density, K, Counting_density>);

TEST_CASE("exact quadrature equals polygon closed forms on random convex cells, also far away",
          "[quadrature]") {
  const double scale = GENERATE(1e-6, 1.0, 1e6);
  const double offset = GENERATE(0.0, 1e6);
  const unsigned seed = 11;
  CAPTURE(scale, offset, seed);
  std::mt19937_64 rng(seed);
  double worst = 0;
  for (int i = 0; i < 300; ++i) {
    const Star_cell c = random_convex_cell(rng, scale, offset * std::max(scale, 1.0));
    const Moments m = Exact()(
        c.x, c.cell, [](const Point&) { return 1.0; }, 0);
    worst = std::max(worst, relative_error(m, polygon_moments_oracle(c.x, c.cell), c.diameter));
    if (offset == 0) {
      const CGAL::Polygon_2<K> polygon(c.cell.begin(), c.cell.end());
      CHECK(m.mass == Approx(polygon.area()).epsilon(1e-12));
    }
  }
  CHECK(worst < 1e-11);
}

TEST_CASE("exact quadrature's moments relative to the generator survive translation by 1e6",
          "[quadrature]") {
  const unsigned seed = 12;
  CAPTURE(seed);
  std::mt19937_64 rng(seed), same(seed);
  double worst = 0;
  for (int i = 0; i < 300; ++i) {
    const Star_cell near = random_convex_cell(rng, 10, 0), far = random_convex_cell(same, 10, 1e6);
    const Moments m0 = Exact()(
        near.x, near.cell, [](const Point&) { return 1.0; }, 0);
    const Moments m1 = Exact()(
        far.x, far.cell, [](const Point&) { return 1.0; }, 0);
    worst = std::max(worst, relative_error(m1, m0, near.diameter));
  }
  CHECK(worst < 1e-8);  // the input points themselves are rounded to ~1e-10 at 1e6
  CHECK(worst > 0);     // the translation did happen
}

TEST_CASE("exact quadrature scales the uniform moments by rho(x) and evaluates rho once",
          "[quadrature]") {
  std::mt19937_64 rng(13);
  const Star_cell c = random_convex_cell(rng, 1, 0);
  std::size_t calls = 0;
  const Moments one = Exact()(c.x, c.cell, Counting_density{&calls}, 100);
  CHECK(calls == 1);
  const Moments m = Exact()(
      c.x, c.cell, [](const Point&) { return 2.5; }, 7);
  CHECK(m.mass == Approx(2.5 * one.mass).epsilon(1e-15));
  CHECK(m.energy == Approx(2.5 * one.energy).epsilon(1e-15));
  CHECK(m.first_moment.x() == Approx(2.5 * one.first_moment.x()).epsilon(1e-15));
}

TEST_CASE("midpoint rule with a constant density equals exact quadrature at resolutions 1 to 200",
          "[quadrature]") {
  const double offset = GENERATE(0.0, 1e6);
  const unsigned seed = 21;
  CAPTURE(offset, seed);
  std::mt19937_64 rng(seed);
  const auto rho = [](const Point&) { return 2.5; };
  double worst = 0;
  for (int i = 0; i < 20; ++i) {
    const Star_cell c = random_convex_cell(rng, 3, offset);
    const Moments exact = Exact()(c.x, c.cell, rho, 0);
    for (std::size_t n = 1; n <= 200; ++n)
      worst = std::max(worst, relative_error(Midpoint()(c.x, c.cell, rho, n), exact, c.diameter));
  }
  CHECK(worst < 1e-12);
}

TEST_CASE("midpoint rule's nodes() and moments() give operator()'s points and bits",
          "[quadrature]") {
  STATIC_REQUIRE(CVT_2::has_quadrature_nodes_v<Midpoint, K>);
  std::mt19937_64 rng(5);
  for (int i = 0; i < 30; ++i) {
    const Star_cell c = random_convex_cell(rng, 3, i % 2 == 0 ? 0.0 : 1e6);
    for (const std::size_t n : {1, 7, 10, 33, 100, 150}) {
      CAPTURE(i, n);
      check_nodes(Midpoint(), c, n);
    }
  }
  // A cell of zero area: no point, the moments of operator().
  std::vector<Point> points;
  std::vector<double> nodes;
  CHECK(Midpoint().nodes(origin, Points{origin, Point(1, 0), Point(2, 0)}, 10, points, nodes) == 0);
  CHECK(Midpoint().moments(nodes.data(), nullptr, 0).mass == 0);
}

TEST_CASE("midpoint rule with a constant density is exact in exact arithmetic", "[quadrature]") {
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  std::mt19937_64 rng(22);
  for (int i = 0; i < 3; ++i) {
    const Star_cell c = random_convex_cell(rng, 1, 0);
    const EK::Point_2 x(c.x.x(), c.x.y());
    std::vector<EK::Point_2> cell;
    for (const Point& p : c.cell) cell.push_back(EK::Point_2(p.x(), p.y()));
    const auto rho = [](const EK::Point_2&) { return EK::FT(3); };
    const CVT_2::Cell_moments_2<EK> exact = CVT_2::Exact_quadrature_2<EK>()(x, cell, rho, 0);
    for (const std::size_t n : {1, 7, 30}) {
      CAPTURE(i, n);
      const CVT_2::Cell_moments_2<EK> m = CVT_2::Midpoint_quadrature_2<EK>()(x, cell, rho, n);
      CHECK(m.mass == exact.mass);
      CHECK(m.first_moment == exact.first_moment);
      CHECK(m.energy == exact.energy);
    }
  }
}

TEST_CASE("midpoint rule converges at least as O(1/n) for non-polynomial densities",
          "[quadrature]") {
  const int density = GENERATE(0, 1);
  const double offset = GENERATE(0.0, 1e6);
  const unsigned seed = 31;
  CAPTURE(density, offset, seed);
  std::mt19937_64 rng(seed);
  double error_25 = 0, error_100 = 0, error_400 = 0, reference_gap = 0;
  for (int i = 0; i < 20; ++i) {
    const Star_cell c = random_convex_cell(rng, 1, offset);
    // The density's features sit near the cell, wherever the cell is.
    const Point o(c.x.x() + 0.3, c.x.y() - 0.2);
    const auto smooth = [o](const Point& p) {
      const double u = p.x() - o.x(), v = p.y() - o.y();
      return std::exp(2 * u) * (1 + 4 * v * v);
    };
    const auto graded = [o](const Point& p) {  // rho = 1 / mu^4, mu = |p - o| + 0.1: a kink at o
      const double mu = std::sqrt(CGAL::squared_distance(p, o)) + 0.1;
      return 1 / (mu * mu * mu * mu);
    };
    const auto error = [&](std::size_t n) {
      const auto run = [&](const auto& rho) {
        return relative_error(Midpoint()(c.x, c.cell, rho, n), Midpoint()(c.x, c.cell, rho, 20000),
                              c.diameter);
      };
      return density == 0 ? run(smooth) : run(graded);
    };
    error_25 += error(25);
    error_100 += error(100);
    error_400 += error(400);
    if (density == 0)
      reference_gap = std::max(reference_gap,
                               relative_error(Midpoint()(c.x, c.cell, smooth, 20000),
                                              gauss_moments(c.x, c.cell, smooth, 24), c.diameter));
  }
  CAPTURE(error_25, error_100, error_400, reference_gap);
  // Pre-asymptotic for the graded density (rho varies 10^4-fold over a cell): the ratios at 4×
  // the resolution are about 3 and 7 there, 16 to 19 for the smooth one.
  CHECK(error_100 < error_25 / 2);
  CHECK(error_400 < error_100 / 2);
  CHECK(error_400 < error_25 / 8);
  CHECK(reference_gap < 1e-5);  // the reference agrees with an independent Gauss rule
}

TEST_CASE("the Gauss rule is exact for cubic densities, at any subdivision, also far away",
          "[quadrature][gauss]") {
  const double offset = GENERATE(0.0, 1e6);
  CAPTURE(offset);
  std::mt19937_64 rng(23);
  double worst = 0, worst_constant = 0;
  for (int i = 0; i < 20; ++i) {
    const Star_cell c = random_convex_cell(rng, 3, offset);
    // A cubic in coordinates relative to the cell, so that the moments (degree 5 at most) are
    // integrated exactly; the oracle is Gauss-Legendre on the collapsed square, 24 x 24 points.
    const Point o = c.x;
    const auto cubic = [o](const Point& p) {
      const double u = p.x() - o.x(), v = p.y() - o.y();
      return 40 + 3 * u - 2 * v + u * v + 0.5 * u * u * u - 0.25 * u * v * v + v * v * v / 3;
    };
    const Moments reference = gauss_moments(c.x, c.cell, cubic, 24);
    for (const std::size_t m : {1, 2, 3, 5}) {
      worst =
          std::max(worst, relative_error(Gauss(m)(c.x, c.cell, cubic, 0), reference, c.diameter));
      const auto constant = [](const Point&) { return 2.5; };
      worst_constant =
          std::max(worst_constant, relative_error(Gauss(m)(c.x, c.cell, constant, 0),
                                                  Exact()(c.x, c.cell, constant, 0), c.diameter));
    }
  }
  CAPTURE(worst, worst_constant);
  // Far away, the density's own argument p - o loses 10 digits (measured 5e-12; 5e-15 at 0).
  CHECK(worst < (offset == 0 ? 1e-13 : 1e-10));
  CHECK(worst_constant < 1e-12);
  CHECK_THROWS_AS(Gauss(0), std::invalid_argument);
}

TEST_CASE(
    "the Gauss rule converges as O(h^6) on smooth densities, and beats the midpoint rule "
    "at resolution 100",
    "[quadrature][gauss]") {
  std::mt19937_64 rng(32);
  double error_1 = 0, error_2 = 0, midpoint_100 = 0, graded_1 = 0, graded_midpoint_100 = 0;
  for (int i = 0; i < 20; ++i) {
    const Star_cell c = random_convex_cell(rng, 1, 0);
    const Point o(c.x.x() + 0.3, c.x.y() - 0.2);
    const auto smooth = [o](const Point& p) {
      const double u = p.x() - o.x(), v = p.y() - o.y();
      return std::exp(2 * u) * (1 + 4 * v * v);
    };
    // A sizing field's density as in the paper: mu = 0.1 |p - o'| + size, the cell about mu.
    const Point far(c.x.x() + 6, c.x.y() + 2);
    const auto graded = [far](const Point& p) {
      const double mu = 0.1 * std::sqrt(CGAL::squared_distance(p, far)) + 0.5;
      return 1 / (mu * mu * mu * mu);
    };
    const Moments reference = gauss_moments(c.x, c.cell, smooth, 24, 4);
    const Moments graded_reference = gauss_moments(c.x, c.cell, graded, 24, 4);
    error_1 += relative_error(Gauss(1)(c.x, c.cell, smooth, 0), reference, c.diameter);
    error_2 += relative_error(Gauss(2)(c.x, c.cell, smooth, 0), reference, c.diameter);
    midpoint_100 += relative_error(Midpoint()(c.x, c.cell, smooth, 100), reference, c.diameter);
    graded_1 += relative_error(Gauss(1)(c.x, c.cell, graded, 0), graded_reference, c.diameter);
    graded_midpoint_100 +=
        relative_error(Midpoint()(c.x, c.cell, graded, 100), graded_reference, c.diameter);
  }
  CAPTURE(error_1, error_2, midpoint_100, graded_1, graded_midpoint_100);
  // Measured: error_1 / error_2 = 54 (2^6 = 64 asymptotically); with 28 points a fan triangle
  // against the midpoint rule's 300 a cell, 6 times more accurate on this density, which
  // varies 50-fold over a cell; with 7 points, 13 times on the sizing field's.
  CHECK(error_2 < error_1 / 20);
  CHECK(error_2 < midpoint_100 / 3);
  CHECK(graded_1 < graded_midpoint_100 / 5);
  CHECK(graded_1 / 20 < 1e-5);  // a centroid within 1e-5 of the diameter, on average
}

TEST_CASE("the Gauss rule's nodes() and moments() give operator()'s points and bits",
          "[quadrature][gauss]") {
  STATIC_REQUIRE(CVT_2::has_quadrature_nodes_v<Gauss, K>);
  std::mt19937_64 rng(6);
  for (int i = 0; i < 30; ++i) {
    const Star_cell c = random_convex_cell(rng, 3, i % 2 == 0 ? 0.0 : 1e6);
    for (const std::size_t m : {1, 2, 4}) {
      CAPTURE(i, m);
      // x is inside: no fan triangle is flat
      CHECK(check_nodes(Gauss(m), c, 0) == 7 * m * m * c.cell.size());
    }
  }
  std::vector<Point> points;
  std::vector<double> nodes;
  CHECK(Gauss().nodes(origin, Points{origin, Point(1, 0), Point(2, 0)}, 10, points, nodes) == 0);
  CHECK(Gauss().moments(nodes.data(), nullptr, 0).mass == 0);
}

TEST_CASE("midpoint rule makes max(resolution, fan triangles) sub-triangles, 3 evaluations each",
          "[quadrature]") {
  const double pi = std::acos(-1.0);
  Points hexagon, polygon_150;
  for (int i = 0; i < 6; ++i) hexagon.push_back(Point(std::cos(i * pi / 3), std::sin(i * pi / 3)));
  for (int i = 0; i < 150; ++i)
    polygon_150.push_back(Point(std::cos(i * pi / 75), std::sin(i * pi / 75)));
  struct Case {
    const Points* cell;
    std::size_t fan;  // fan triangles of nonzero area
  };
  for (const Case& c : {Case{&hexagon, 6}, Case{&two_slit_square, 6}, Case{&polygon_150, 150}})
    for (const std::size_t n : {0, 1, 5, 6, 7, 10, 100, 127, 128, 129, 149, 150, 151, 300}) {
      CAPTURE(c.fan, n);
      std::size_t calls = 0;
      Midpoint()(origin, *c.cell, Counting_density{&calls}, n);
      CHECK(calls == 3 * std::max(n, c.fan));
    }
}

namespace {

// The sub-triangles of a midpoint run, each known by its three (sorted) evaluation points, the
// midpoints of its edges; all sorted, so that runs compare as sets.
using Midpoint_triple = std::array<Point, 3>;
std::vector<Midpoint_triple> sub_triangles(const Point& x, const Points& cell, std::size_t n) {
  std::vector<Point> points;
  Midpoint()(
      x, cell,
      [&points](const Point& p) {
        points.push_back(p);
        return 1.0;
      },
      n);
  std::vector<Midpoint_triple> triangles;
  for (std::size_t i = 0; i + 2 < points.size(); i += 3) {
    Midpoint_triple t = {points[i], points[i + 1], points[i + 2]};
    std::sort(t.begin(), t.end());
    triangles.push_back(t);
  }
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}
// The midpoint triangle has half the sides of the triangle: this is its longest side, squared.
double squared_longest_edge(const Midpoint_triple& m) {
  return 4 * std::max({CGAL::squared_distance(m[0], m[1]), CGAL::squared_distance(m[1], m[2]),
                       CGAL::squared_distance(m[2], m[0])});
}
// The vertices, m_i + m_j - m_k, and the area, 4 × the midpoint triangle's.
std::array<Point, 3> triangle_vertices(const Midpoint_triple& m) {
  const auto corner = [](const Point& p, const Point& q, const Point& r) { return p + (q - r); };
  return {corner(m[0], m[1], m[2]), corner(m[1], m[2], m[0]), corner(m[2], m[0], m[1])};
}
double triangle_area(const Midpoint_triple& m) {
  return 4 * std::abs(CGAL::area(m[0], m[1], m[2]));
}

}  // namespace

TEST_CASE("midpoint rule bisects, at each step, the longest edge of all sub-triangles",
          "[quadrature]") {
  std::mt19937_64 rng(51);
  for (int i = 0; i < 5; ++i) {
    const double offset = i % 2 == 0 ? 0 : 1e6;
    const Star_cell c = random_convex_cell(rng, 1, offset);
    // The evaluation points are rounded to ~1e-10 at 1e6, and the reconstructed vertices too.
    const double relative = offset == 0 ? 1e-12 : 1e-7, tolerance = 1e-9 * c.diameter;
    std::vector<Midpoint_triple> before = sub_triangles(c.x, c.cell, c.cell.size());
    for (std::size_t n = c.cell.size(); n < 150; ++n) {
      CAPTURE(i, n);
      const std::vector<Midpoint_triple> after = sub_triangles(c.x, c.cell, n + 1);
      std::vector<Midpoint_triple> bisected, halves;
      std::set_difference(before.begin(), before.end(), after.begin(), after.end(),
                          std::back_inserter(bisected));
      std::set_difference(after.begin(), after.end(), before.begin(), before.end(),
                          std::back_inserter(halves));
      REQUIRE(bisected.size() == 1);
      REQUIRE(halves.size() == 2);
      const Midpoint_triple& t = bisected[0];
      double longest = 0;
      for (const Midpoint_triple& s : before) longest = std::max(longest, squared_longest_edge(s));
      CHECK(squared_longest_edge(t) >= longest * (1 - relative));
      // The new vertex is the midpoint of the longest edge of t, a vertex of both halves.
      const std::array<Point, 3> v = triangle_vertices(t);
      Point split = v[0];
      for (int j = 0; j < 3; ++j) {
        const Point m = CGAL::midpoint(v[j], v[(j + 1) % 3]);
        const double edge = CGAL::squared_distance(v[j], v[(j + 1) % 3]);
        if (edge >= squared_longest_edge(t) * (1 - relative)) split = m;
      }
      for (const Midpoint_triple& h : halves) {
        CHECK(triangle_area(h) == Approx(triangle_area(t) / 2).epsilon(relative));
        const std::array<Point, 3> w = triangle_vertices(h);
        CHECK(std::any_of(w.begin(), w.end(), [&](const Point& p) {
          return CGAL::squared_distance(p, split) < tolerance * tolerance;
        }));
      }
      before = after;
    }
  }
}

TEST_CASE("a generator on its cell's boundary or on slits integrates to the right moments",
          "[quadrature]") {
  // x on the boundary of [-1, 1] × [0, 1]: area 2, first moment (0, 1), energy 2/3 + 2/3.
  const Points half_square = {origin, Point(1, 0), Point(1, 1), Point(-1, 1), Point(-1, 0)};
  // [-1, 1]² with one slit from x to (1, 0): area 4, first moment 0, energy 8/3.
  const Points one_slit_square = {origin,        Point(1, 0),  Point(1, 1), Point(-1, 1),
                                  Point(-1, -1), Point(1, -1), Point(1, 0)};
  struct Case {
    const Points* cell;
    double mass, first_y, energy;
  };
  const auto rho = [](const Point&) { return 1.0; };
  for (const Case& c : {Case{&half_square, 2, 1, 4.0 / 3}, Case{&one_slit_square, 4, 0, 8.0 / 3},
                        Case{&two_slit_square, 4, 0, 8.0 / 3}})
    for (const std::size_t n : {1, 10, 100}) {
      CAPTURE(c.mass, n);
      for (const Moments& m :
           {Exact()(origin, *c.cell, rho, n), Midpoint()(origin, *c.cell, rho, n),
            Gauss(n == 100 ? 3 : 1)(origin, *c.cell, rho, n)}) {
        CHECK(m.mass == Approx(c.mass).epsilon(1e-14));
        CHECK(m.first_moment.x() == Approx(0).margin(1e-14));
        CHECK(m.first_moment.y() == Approx(c.first_y).margin(1e-14));
        CHECK(m.energy == Approx(c.energy).epsilon(1e-14));
      }
    }
}

TEST_CASE("quadratures of the cells of a constrained domain sum to its area, slits included",
          "[quadrature]") {
  const std::string file =
      GENERATE(as<std::string>{}, "square_inner_constraints.poly", "four_clusters.poly");
  const unsigned seed = 41;
  CAPTURE(file, seed);
  Domain d;
  load_domain(d, file);
  insert_random_points(d, 300, seed);
  const Bvd bvd(d.cdt);
  const auto rho = [](const Point&) { return 1.0; };
  double exact_sum = 0, midpoint_sum = 0, worst = 0;
  std::size_t constrained = 0, with_slits = 0, not_the_same = 0;
  Points points;
  bvd.for_each_cell([&](Cdt::Vertex_handle v, const Cell& c) {
    points.clear();
    for (const auto& cv : c) points.push_back(cv.point);
    const Moments exact = Exact()(v->point(), points, rho, 0);
    const Moments midpoint = Midpoint()(v->point(), points, rho, 10);
    // A range that makes the points on the fly, instead of a copy, gives the same moments.
    const auto on_the_fly =
        c | boost::adaptors::transformed([](const Bvd::Cell_vertex& cv) { return cv.point; });
    if (Midpoint()(v->point(), on_the_fly, rho, 10).energy != midpoint.energy) ++not_the_same;
    worst = std::max(worst, std::abs(exact.mass - signed_area(c)) / signed_area(c));
    worst = std::max(worst, std::abs(midpoint.mass - signed_area(c)) / signed_area(c));
    exact_sum += exact.mass;
    midpoint_sum += midpoint.mass;
    constrained += bvd.is_free(v) ? 0 : 1;
    with_slits += std::count(points.begin(), points.end(), v->point()) > 1 ? 1 : 0;
  });
  REQUIRE(constrained > 0);
  CHECK(not_the_same == 0);
  CHECK(worst < 1e-12);
  CHECK(exact_sum == Approx(domain_area(d.cdt)).epsilon(1e-10));
  CHECK(midpoint_sum == Approx(domain_area(d.cdt)).epsilon(1e-10));
  if (file == "square_inner_constraints.poly") CHECK(with_slits > 0);
}

TEST_CASE("quadratures of an empty or flat cell return zero moments", "[quadrature]") {
  const auto rho = [](const Point&) { return 1.0; };
  const Points empty, flat = {Point(0, 0), Point(1, 1), Point(2, 2)}, single = {origin};
  for (const Points* cell : {&empty, &flat, &single})
    for (const Moments& m : {Exact()(origin, *cell, rho, 10), Midpoint()(origin, *cell, rho, 10),
                             Gauss()(origin, *cell, rho, 10)}) {
      CHECK(m.mass == 0);
      CHECK(m.first_moment == K::Vector_2(0, 0));
      CHECK(m.energy == 0);
    }
}

TEST_CASE("a fan triangle that rounding makes negative counts nothing under a steep density",
          "[quadrature]") {
  // x a rounding below the cell's bottom edge (as a centroid in a steep sizing field's thin
  // boundary layer puts a generator): the fan triangle on that edge has area -2.5e-18, and a
  // density of 1e30 there made the mass -2.5e12 (cvt2 stopped with "a bug in CVT_2").
  const Point x(0.5, -5e-18);
  const Points cell = {Point(0, 0), Point(1, 0), Point(0.5, 1)};
  const auto rho = [](const Point& p) { return 1e30 * std::exp(-1e4 * std::abs(p.y())); };
  for (const Moments& m :
       {Midpoint()(x, cell, rho, 100), Gauss()(x, cell, rho, 10), Gauss(3)(x, cell, rho, 10)}) {
    CHECK(m.mass >= 0);
    CHECK(m.energy >= 0);
  }
}

TEST_CASE("a lambda density works, capturing state or not", "[quadrature]") {
  const Points square = {Point(-1, -1), Point(1, -1), Point(1, 1), Point(-1, 1)};
  const double a = 0.5;
  const auto linear = [a](const Point& p) { return 1 + a * p.x(); };
  static_assert(CVT_2::is_cell_quadrature_2_v<Midpoint, K, decltype(linear)>);
  const Moments m = Midpoint()(origin, square, linear, 10);
  // Mass and first moment have degree <= 2, so the rule is exact; the energy has degree 3.
  CHECK(m.mass == Approx(4).epsilon(1e-14));
  CHECK(m.first_moment.x() == Approx(a * 4.0 / 3).epsilon(1e-14));  // ∫ a u² over the square
  CHECK(m.first_moment.y() == Approx(0).margin(1e-14));
  CHECK(m.energy == Approx(8.0 / 3).epsilon(1e-2));
  CHECK(Exact()(
            origin, square, [](const Point&) { return 2.0; }, 0)
            .mass == Approx(8));
}
