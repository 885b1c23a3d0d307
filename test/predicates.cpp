// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// The filtered blindness predicates, and the floating-point filters of the virtual star, against
// an exact rational construct-then-test reference.
#include "support/random.h"

#include <CVT_2/Bvd_traits_2.h>
#include <CVT_2/internal/circumcenter_filters.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

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

// The floating-point filters of internal/circumcenter_filters.h: where a filter answers, its sign
// is the exact one; on generic input it answers almost always.
namespace {

// The input of a filter, drawn around the unit square and then moved to a scale:
// p -> (p + offset) 2^exponent.
struct Scale {
  int exponent;
  double offset;
};
// Products of coordinates 2^k apart from 1 leave the normal range first at k = ±511 (squares)
// and ±255 (the fourth-degree terms of is_circumcenter_surely_left()); 2^-1000 and 2^990 are
// the coordinates near 1e-300 and 1e300; the offset makes large coordinates with small
// differences.
const Scale scales[] = {{0, 0},   {0, 0x1.0p24}, {-1000, 0}, {990, 0}, {-530, 0},      {-540, 0},
                        {510, 0}, {-264, 0},     {-270, 0},  {260, 0}, {-40, 0x1.0p30}};

P scaled(const P& p, const Scale& s) {
  return P(std::ldexp(p.x() + s.offset, s.exponent), std::ldexp(p.y() + s.offset, s.exponent));
}
double rounded(const EK::FT& x) { return CGAL::to_double(x); }
P rounded(const EK::Point_2& p) { return P(rounded(p.x()), rounded(p.y())); }
// x moved by up to 2 units in the last place, either way.
double nudged(std::mt19937_64& rng, double x) {
  for (int k = support::uniform_int(rng, -2, 2); k != 0; k += k > 0 ? -1 : 1)
    x = std::nextafter(x, k > 0 ? HUGE_VAL : -HUGE_VAL);
  return x;
}
P nudged(std::mt19937_64& rng, const P& p) { return P(nudged(rng, p.x()), nudged(rng, p.y())); }
// A point of the exact line a + t (b - a), t in [-2, 2], rounded and nudged.
P near_line(std::mt19937_64& rng, const EK::Point_2& a, const EK::Point_2& b) {
  const EK::FT t(support::uniform(rng, -2, 2));
  // on it, or off it by 2^-10 to 2^-60 of |b - a|: across every level of error
  const EK::FT off(
      rng() % 2 ? 0.0
                : std::ldexp(support::uniform(rng, -1, 1), -support::uniform_int(rng, 10, 60)));
  return nudged(rng, rounded(a + t * (b - a) + off * (b - a).perpendicular(CGAL::LEFT_TURN)));
}
// Lattice points of the circle x² + y² = 65², which has many: cocircular quadruples, right
// angles, diameters.
const std::vector<P>& circle_points() {
  static const std::vector<P> points = [] {
    std::vector<P> v;
    for (int x = -65; x <= 65; ++x)
      for (int y = -65; y <= 65; ++y)
        if (x * x + y * y == 65 * 65) v.emplace_back(x / 65.0 * 64, y / 65.0 * 64);
    return v;
  }();
  return points;
}

// The kinds of input each filter is tried on. NEAR_DEGENERATE and MIXED_SCALES build the points
// that make a question degenerate, from points at the scale or, for MIXED_SCALES, half of them
// near 1.
enum Kind { RANDOM, GRID, COCIRCULAR, NEAR_DEGENERATE, MIXED_SCALES };
const char* kind_name(Kind k) {
  const char* names[] = {"random", "grid", "cocircular", "near-degenerate", "mixed scales"};
  return names[k];
}
bool near_degenerate(Kind k) { return k == NEAR_DEGENERATE || k == MIXED_SCALES; }

// A random point of the kind, at the scale (before any dependent point is built).
P draw(std::mt19937_64& rng, Kind kind, const Scale& s) {
  if (kind == GRID) return scaled(random_point(rng, 4), s);
  if (kind == COCIRCULAR) {
    const std::vector<P>& c = circle_points();
    return scaled(c[rng() % c.size()], s);
  }
  if (kind == MIXED_SCALES && rng() % 2) return random_point(rng, 0);
  return scaled(random_point(rng, 0), s);
}

// Runs `trial` (which checks the filter's answer, and returns whether it answered where it
// could) on every kind and scale; checks that it answers on most random input at moderate
// scales, so that a filter that never answers does not pass.
struct Tally {
  std::size_t trials = 0, sure = 0;
};
void over_kinds_and_scales(const std::function<bool(std::mt19937_64&, Kind, const Scale&)>& trial,
                           int per_case = 2000) {
  for (const Kind kind : {RANDOM, GRID, COCIRCULAR, NEAR_DEGENERATE, MIXED_SCALES})
    for (const Scale& s : scales) {
      CAPTURE(kind_name(kind), s.exponent, s.offset);
      std::mt19937_64 rng(1000 * unsigned(kind) + unsigned(s.exponent + 2000));
      Tally t;
      for (int i = 0; i < per_case; ++i, ++t.trials) t.sure += trial(rng, kind, s);
      if (kind == RANDOM && std::abs(s.exponent) <= 40) CHECK(t.sure > t.trials * 95 / 100);
    }
}

CGAL::Sign exact_angle(const P& a, const P& vertex, const P& b) {  // sign of (a - v).(b - v)
  switch (CGAL::angle(to_exact(a), to_exact(vertex), to_exact(b))) {
    case CGAL::ACUTE:
      return CGAL::POSITIVE;
    case CGAL::OBTUSE:
      return CGAL::NEGATIVE;
    default:
      return CGAL::ZERO;
  }
}
EK::Point_2 exact_circumcenter(const P& p, const P& q, const P& r) {
  return CGAL::circumcenter(to_exact(p), to_exact(q), to_exact(r));
}

}  // namespace

TEST_CASE("angle_signs() gives the exact signs of the angles or none", "[predicates]") {
  std::size_t wrong = 0;
  over_kinds_and_scales([&](std::mt19937_64& rng, Kind kind, const Scale& s) {
    const P p = draw(rng, kind, s), q = draw(rng, kind, s);
    P r = draw(rng, kind, s);
    if (near_degenerate(kind)) {  // a right angle at r (Thales), at p, or a straight one
      const EK::Point_2 ep = to_exact(p), eq = to_exact(q);
      const EK::Vector_2 normal(-(eq.y() - ep.y()), eq.x() - ep.x());
      const double angle = support::uniform(rng, 0, 6.283185307179586);
      switch (rng() % 3) {
        case 0:
          r = nudged(rng, rounded(CGAL::midpoint(ep, eq) + (ep - eq) * std::cos(angle) / 2 +
                                  normal * std::sin(angle) / 2));
          break;
        case 1:
          r = nudged(rng, rounded(ep + normal * support::uniform(rng, -2, 2)));
          break;
        default:
          r = near_line(rng, ep, eq);
      }
    }
    CGAL::Sign sign[3];
    if (!CVT_2::internal::angle_signs(p, q, r, sign)) return false;
    const CGAL::Sign expected[3] = {exact_angle(q, p, r), exact_angle(p, q, r),
                                    exact_angle(p, r, q)};
    for (int i = 0; i < 3; ++i)
      if (sign[i] != expected[i]) {
        ++wrong;
        CAPTURE(p, q, r, i, sign[i], expected[i]);
        CHECK(sign[i] == expected[i]);
      }
    return true;
  });
  CHECK(wrong == 0);
}

TEST_CASE("is_circumcenter_surely_left() is true only where the circumcenter is left",
          "[predicates]") {
  std::size_t wrong = 0;
  over_kinds_and_scales([&](std::mt19937_64& rng, Kind kind, const Scale& s) {
    const P a = draw(rng, kind, s), b = draw(rng, kind, s), w = draw(rng, kind, s);
    if (CGAL::collinear(a, b, w)) return true;  // not a triangle: no question (counted sure)
    const EK::Point_2 c = exact_circumcenter(a, b, w);
    // x on the line from a through c, where the answer changes
    const P x = near_degenerate(kind) ? near_line(rng, to_exact(a), c) : draw(rng, kind, s);
    // on the left of a -> x for (a, b, w) counterclockwise, on the right for clockwise
    const CGAL::Sign expected = CGAL::orientation(to_exact(a), to_exact(x), c) *
                                CGAL::orientation(to_exact(a), to_exact(b), to_exact(w));
    // a one-sided filter: it answers where c is left, else says nothing
    if (!CVT_2::internal::is_circumcenter_surely_left(a, b, w, x))
      return expected != CGAL::POSITIVE;
    if (expected != CGAL::POSITIVE) {
      ++wrong;
      CAPTURE(a, b, w, x, expected);
      CHECK(expected == CGAL::POSITIVE);
    }
    return true;
  });
  CHECK(wrong == 0);
}

TEST_CASE("Approximate_dual_segment_2 gives the exact sides of the way or none", "[predicates]") {
  const Traits::Construct_circumcenter_2 circumcenter = Traits().construct_circumcenter_2_object();
  std::size_t wrong = 0;
  over_kinds_and_scales([&](std::mt19937_64& rng, Kind kind, const Scale& s) {
    P p = draw(rng, kind, s), q = draw(rng, kind, s), r = draw(rng, kind, s);
    if (near_degenerate(kind)) {
      // A needle (r near q), a sliver (r near the line pq) or a small triangle near the origin
      // (the lines asked far from it): where the error of the built circumcenter, of the
      // orientation's products or of the centroid leads the bound in turn.
      const double k = std::ldexp(1.0, -support::uniform_int(rng, 0, 40));
      const EK::Point_2 ep = to_exact(p), eq = to_exact(q), er = to_exact(r);
      const EK::Vector_2 normal(-(eq.y() - ep.y()), eq.x() - ep.x());
      switch (rng() % 3) {
        case 0:
          r = rounded(eq + (er - ep) * k);
          break;
        case 1:
          r = rounded(ep + (eq - ep) * support::uniform(rng, -0.5, 1.5) + normal * k);
          break;
        default:
          for (P* v : {&p, &q, &r}) *v = P(v->x() * k, v->y() * k);
      }
    }
    if (CGAL::collinear(p, q, r)) return true;  // not a triangle: no question (counted sure)
    const CVT_2::internal::Approximate_dual_segment_2<P> way(p, q, r, circumcenter(p, q, r));
    const EK::Point_2 c = exact_circumcenter(p, q, r);
    const EK::Point_2 g = CGAL::centroid(to_exact(p), to_exact(q), to_exact(r));
    // the sides of the circumcenter from an edge of the face (right triangles: c on it), from a
    // line through c, or from a line of the kind
    P a = draw(rng, kind, s), b = draw(rng, kind, s);
    if (rng() % 3 == 0) a = p, b = r;
    if (near_degenerate(kind)) b = near_line(rng, to_exact(a), c);
    // the side of a vertex (an isosceles triangle's apex lies on its way), a point near the
    // way, or a point of the kind
    const P x = rng() % 3 == 0          ? q
                : near_degenerate(kind) ? near_line(rng, g, c)
                                        : draw(rng, kind, s);
    bool sure = true;
    CGAL::Sign sign;
    if (a != b && way.side_of_circumcenter(a, b, sign)) {
      const CGAL::Sign expected = CGAL::orientation(to_exact(a), to_exact(b), c);
      if (sign != expected) {
        ++wrong;
        CAPTURE(p, q, r, a, b, sign, expected);
        CHECK(sign == expected);
      }
    } else {
      sure = a == b;
    }
    if (way.side_of_point(x, sign)) {
      const CGAL::Sign expected = CGAL::orientation(g, c, to_exact(x));
      if (sign != expected) {
        ++wrong;
        CAPTURE(p, q, r, x, sign, expected);
        CHECK(sign == expected);
      }
    } else {
      sure = false;
    }
    return sure;
  });
  CHECK(wrong == 0);
}
