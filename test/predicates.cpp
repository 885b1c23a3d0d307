// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The filtered blindness predicates against an exact rational construct-then-test reference.
#include "support/random.h"

#include <CVT_2/Bvd_traits_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <catch2/catch.hpp>

#include <random>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using EK = CGAL::Exact_predicates_exact_constructions_kernel;
using P = K::Point_2;
using Traits = CVT_2::Bvd_traits_2<K>;
const CGAL::Cartesian_converter<K, EK> to_exact;

// The reference: build the centroid g and circumcenter c exactly, then test the segment
// [g, c] against ab; c on the line of ab does not count.
bool reference_blinded(const P& p, const P& q, const P& r, const P& a, const P& b) {
  const EK::Point_2 ep = to_exact(p), eq = to_exact(q), er = to_exact(r);
  const EK::Point_2 g = CGAL::centroid(ep, eq, er), c = CGAL::circumcenter(ep, eq, er);
  const EK::Point_2 ea = to_exact(a), eb = to_exact(b);
  if (CGAL::collinear(ea, eb, c)) return false;
  return CGAL::do_intersect(EK::Segment_2(g, c), EK::Segment_2(ea, eb));
}
// g on ab does not happen in a triangulation (ab would cross the face); such draws are skipped.
bool centroid_on_segment(const P& p, const P& q, const P& r, const P& a, const P& b) {
  const EK::Point_2 g = CGAL::centroid(to_exact(p), to_exact(q), to_exact(r));
  return EK::Segment_2(to_exact(a), to_exact(b)).has_on(g);
}
CGAL::Comparison_result reference_compare(const P& p, const P& q, const P& r, const P& a1,
                                          const P& b1, const P& a2, const P& b2) {
  const EK::Point_2 ep = to_exact(p), eq = to_exact(q), er = to_exact(r);
  const EK::Line_2 dual(CGAL::centroid(ep, eq, er), CGAL::circumcenter(ep, eq, er));
  const auto x1 = CGAL::intersection(dual, EK::Line_2(to_exact(a1), to_exact(b1)));
  const auto x2 = CGAL::intersection(dual, EK::Line_2(to_exact(a2), to_exact(b2)));
  const EK::Point_2 g = CGAL::centroid(ep, eq, er);
  return CGAL::compare(CGAL::squared_distance(g, *boost::get<EK::Point_2>(&*x1)),
                       CGAL::squared_distance(g, *boost::get<EK::Point_2>(&*x2)));
}

// A point of the integer grid [-grid, grid]², or for grid = 0 a point uniform in [-1, 1]².
P random_point(std::mt19937_64& rng, int grid) {
  const double x = grid ? support::uniform_int(rng, -grid, grid) : support::uniform(rng, -1, 1);
  const double y = grid ? support::uniform_int(rng, -grid, grid) : support::uniform(rng, -1, 1);
  return P(x, y);
}

}  // namespace

TEST_CASE("the blindness predicate equals the exact reference on random input", "[predicates]") {
  const Traits::Is_blinded_2 blinded = Traits().is_blinded_2_object();
  // Small integer grids give many exact degeneracies (c on the line of ab, a or b on [g, c],
  // right triangles); uniform reals give the generic case.
  const int grid = GENERATE(4, 8, 0);
  CAPTURE(grid);
  std::mt19937_64 rng(42 + grid);
  const auto draw = [&] { return random_point(rng, grid); };
  std::size_t tested = 0, blind = 0, mismatches = 0;
  for (int i = 0; i < 200000 && tested < 50000; ++i) {
    const P p = draw(), q = draw(), r = draw(), a = draw(), b = draw();
    if (CGAL::collinear(p, q, r) || a == b || centroid_on_segment(p, q, r, a, b)) continue;
    ++tested;
    const bool expected = reference_blinded(p, q, r, a, b);
    blind += expected;
    if (blinded(p, q, r, a, b) != expected) {
      ++mismatches;
      CAPTURE(p, q, r, a, b, expected);
      CHECK(blinded(p, q, r, a, b) == expected);
    }
  }
  CHECK(tested > 10000);
  CHECK(blind > tested / 20);
  CHECK(mismatches == 0);
}

TEST_CASE("the blindness predicate on named degenerate cases", "[predicates][degenerate]") {
  const Traits::Is_blinded_2 blinded = Traits().is_blinded_2_object();
  // Obtuse triangle, circumcenter (2, -3.75).
  const P p(0, 0), q(4, 0), r(2, 0.5);
  SECTION("circumcenter beyond the line of the segment but beside it: not blind") {
    // CGAL's supporting-line test calls this blind; the paper's definition does not.
    CHECK_FALSE(blinded(p, q, r, P(10, -1), P(12, -1)));
    CHECK(reference_blinded(p, q, r, P(10, -1), P(12, -1)) == false);
  }
  SECTION("segment across the way to the circumcenter: blind") {
    CHECK(blinded(p, q, r, P(0, -1), P(4, -1)));
  }
  SECTION("circumcenter exactly on the segment's line: not blind") {
    CHECK_FALSE(blinded(p, q, r, P(0, -3.75), P(4, -3.75)));
  }
  SECTION("the way to the circumcenter passes exactly through an endpoint: blind") {
    // g = (2, 1/6), c = (2, -3.75): the vertical line x = 2.
    CHECK(blinded(p, q, r, P(2, -1), P(5, -1)));
    CHECK(blinded(p, q, r, P(-3, -1), P(2, -1)));
  }
  SECTION("the face's own edge, opposite the obtuse angle: blind") {
    CHECK(blinded(p, q, r, p, q));
    CHECK(blinded(q, r, p, q, p));  // whatever the vertex order
  }
  SECTION("right triangle: circumcenter at the hypotenuse's midpoint, on the constraint") {
    CHECK_FALSE(blinded(P(0, 0), P(2, 0), P(0, 2), P(2, 0), P(0, 2)));
  }
  SECTION("cocircular: the four corners of a square") {
    CHECK_FALSE(blinded(P(0, 0), P(1, 0), P(1, 1), P(0, 0), P(1, 1)));
    CHECK_FALSE(blinded(P(0, 0), P(1, 0), P(1, 1), P(0, 1), P(1, 0)));
  }
  SECTION("near-degenerate: interval arithmetic cannot decide, the exact fallback does") {
    const double e = std::ldexp(1.0, -52);
    const P a(0, -3.75 * (1 + e)), b(4, -3.75 * (1 + e));  // just below c: c stays above
    CHECK(blinded(p, q, r, a, b) == reference_blinded(p, q, r, a, b));
    CHECK_FALSE(blinded(p, q, r, a, b));
    const P a2(0, -3.75 * (1 - e)), b2(4, -3.75 * (1 - e));  // just above c: crossed
    CHECK(blinded(p, q, r, a2, b2));
  }
}

TEST_CASE("the first-constraint comparison equals the exact reference", "[predicates]") {
  const Traits::Is_blinded_2 blinded = Traits().is_blinded_2_object();
  const Traits::Compare_blinding_distance_2 compare = Traits().compare_blinding_distance_2_object();
  const int grid = GENERATE(6, 0);
  CAPTURE(grid);
  std::mt19937_64 rng(7 + grid);
  const auto draw = [&] { return random_point(rng, grid); };
  std::size_t tested = 0, mismatches = 0;
  for (int i = 0; i < 2000000 && tested < 5000; ++i) {
    const P p = draw(), q = draw(), r = draw(), a1 = draw(), b1 = draw(), a2 = draw(), b2 = draw();
    if (CGAL::collinear(p, q, r) || a1 == b1 || a2 == b2) continue;
    if (!blinded(p, q, r, a1, b1) || !blinded(p, q, r, a2, b2)) continue;
    ++tested;
    const auto expected = reference_compare(p, q, r, a1, b1, a2, b2);
    if (compare(p, q, r, a1, b1, a2, b2) != expected) {
      ++mismatches;
      CAPTURE(p, q, r, a1, b1, a2, b2);
      CHECK(compare(p, q, r, a1, b1, a2, b2) == expected);
    }
  }
  CHECK(tested > 1000);
  CHECK(mismatches == 0);
}

TEST_CASE("clip points lie on the constraint's line at equal distance from both generators",
          "[predicates]") {
  const Traits::Construct_clip_point_2 clip = Traits().construct_clip_point_2_object();
  std::mt19937_64 rng(3);
  // the coordinates in the order written, since the order of a call's arguments is unspecified
  const auto u = [&rng](double offset) { return offset + support::uniform(rng, -1, 1); };
  const auto draw = [&u](double offset) {
    const double x = u(offset);
    return P(x, u(0));
  };
  for (const double offset : {0.0, 1e6}) {
    for (int i = 0; i < 1000; ++i) {
      const P v = draw(offset), w = draw(offset), a = draw(offset), b = draw(offset);
      const P x = clip(v, w, a, b);
      const double scale = 1 + std::sqrt(CGAL::squared_distance(x, v));
      CHECK(std::sqrt(CGAL::squared_distance(K::Line_2(a, b), x)) <=
            1e-9 * scale * (1 + offset * 1e-6));
      CHECK(std::sqrt(CGAL::squared_distance(x, v)) ==
            Approx(std::sqrt(CGAL::squared_distance(x, w))).epsilon(1e-6).margin(1e-9));
    }
  }
}
