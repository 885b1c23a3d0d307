// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Properties of the density and sizing policies: values, validation, brute-force oracles.
#include <CVT_2/Boundary_lipschitz_sizing_2.h>
#include <CVT_2/Concepts/DensityFunction_2.h>
#include <CVT_2/Concepts/SizingField_2.h>
#include <CVT_2/Sizing_field_density_2.h>
#include <CVT_2/Uniform_density_2.h>
#include <CVT_2/density_response_2.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>

#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "support/support.h"

using namespace support;

namespace {

using Uniform = CVT_2::Uniform_density_2<K>;
using Sizing = CVT_2::Boundary_lipschitz_sizing_2<K>;
const double not_a_number = std::numeric_limits<double>::quiet_NaN();
const double infinity = std::numeric_limits<double>::infinity();

// The boundary as the test sees it: every constrained edge with a domain face on a side, from
// its lexicographically smaller end (a distance to a segment rounds differently from the
// distance to its reverse; the sizing orients them so).
std::vector<Segment> boundary_segments(const Cdt& cdt) {
  std::vector<Segment> s;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    const Cdt::Face_handle f = e->first, g = f->neighbor(e->second);
    if (cdt.is_constrained(*e) && ((!cdt.is_infinite(f) && f->is_inside_domain()) ||
                                   (!cdt.is_infinite(g) && g->is_inside_domain()))) {
      const Segment t = cdt.segment(*e);
      s.push_back(t.source() < t.target() ? t : t.opposite());
    }
  }
  return s;
}

// The formula, over every segment.
double brute_force(const std::vector<Segment>& segments, double k, std::optional<double> size,
                   const Point& x) {
  double best = infinity;
  for (const Segment& s : segments)
    best = std::min(best, k * std::sqrt(CGAL::squared_distance(x, s)) +
                              (size ? *size : std::sqrt(s.squared_length())));
  return best;
}

// How far two correct evaluations of the formula at x may differ: a distance computed from
// coordinates rounds to a few ulps of the coordinates, not of the distance (the oracle and the
// field compute it in different ways), and k multiplies it; the sum rounds relative to itself.
double evaluation_slack(double k, const Point& x, double value) {
  return 1e-12 * value +
         8 * k * std::numeric_limits<double>::epsilon() * (std::abs(x.x()) + std::abs(x.y()));
}

// Points in the domain, and as many in its bounding box enlarged by half (outside too).
std::vector<Point> sample_points(const Cdt& cdt, std::size_t n, unsigned seed) {
  std::vector<Point> pts = random_points_in_domain(cdt, n, seed);
  const CGAL::Bbox_2 b = domain_bbox(cdt);
  const double w = b.xmax() - b.xmin(), h = b.ymax() - b.ymin();
  std::mt19937_64 rng(seed + 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = uniform(rng, b.xmin() - w / 4, b.xmax() + w / 4);
    pts.emplace_back(x, uniform(rng, b.ymin() - h / 4, b.ymax() + h / 4));
  }
  return pts;
}

double diagonal(const Cdt& cdt) {
  const CGAL::Bbox_2 b = domain_bbox(cdt);
  return std::hypot(b.xmax() - b.xmin(), b.ymax() - b.ymin());
}

template <class F>
std::string message_of(F f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no exception";
}

}  // namespace

TEST_CASE("a uniform density is its value everywhere; a value not positive and finite throws",
          "[density]") {
  const Point p(3, -7), q(1e6, 2e-6);
  CHECK(Uniform()(p) == 1);
  CHECK(Uniform(2.5)(p) == 2.5);
  CHECK(Uniform(2.5)(q) == 2.5);
  CHECK(Uniform(2.5).value() == 2.5);
  CHECK(Uniform(1e-300)(p) == 1e-300);
  for (const double bad : {0.0, -1.5, not_a_number, infinity, -infinity}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(Uniform(bad), std::invalid_argument);
  }
  CHECK_THAT(message_of([] { Uniform(-1.5); }), Catch::Contains("-1.5"));
  CHECK_THAT(message_of([] { (void)Uniform(not_a_number); }), Catch::Contains("nan"));
}

TEST_CASE("the traits recognize uniform densities, density functions and sizing fields",
          "[density]") {
  const auto constant = [](const Point&) { return 1.0; };
  using Lambda = decltype(constant);
  using Density_of_lambda = CVT_2::Sizing_field_density_2<K, Lambda>;
  STATIC_REQUIRE(CVT_2::is_uniform_density<Uniform>::value);
  STATIC_REQUIRE(CVT_2::is_uniform_density_v<const Uniform&>);
  STATIC_REQUIRE_FALSE(CVT_2::is_uniform_density<Lambda>::value);
  STATIC_REQUIRE_FALSE(CVT_2::is_uniform_density<Density_of_lambda>::value);

  STATIC_REQUIRE(CVT_2::is_density_function_2<Uniform, K>::value);
  STATIC_REQUIRE(CVT_2::is_density_function_2<Density_of_lambda, K>::value);
  STATIC_REQUIRE(CVT_2::is_density_function_2_v<Lambda, K>);
  STATIC_REQUIRE(CVT_2::is_density_function_2<CVT_2::Sizing_field_density_2<K, Sizing>, K>::value);
  STATIC_REQUIRE_FALSE(CVT_2::is_density_function_2<int, K>::value);
  STATIC_REQUIRE_FALSE(CVT_2::is_density_function_2<double (*)(const std::string&), K>::value);

  STATIC_REQUIRE(CVT_2::is_sizing_field_2<Sizing, K>::value);
  STATIC_REQUIRE(CVT_2::is_sizing_field_2_v<Lambda, K>);
  STATIC_REQUIRE_FALSE(CVT_2::is_sizing_field_2<Point, K>::value);
}

TEST_CASE("a sizing field density is 1/mu^4 of its sizing field, lambdas included", "[density]") {
  const auto mu = [](const Point& p) { return 0.05 + std::abs(p.x()) + p.y() * p.y(); };
  const auto rho = CVT_2::make_sizing_field_density_2<K>(mu);
  Domain d;
  load_domain(d, "earcut_dude.poly");
  const Sizing boundary(d.cdt, 0.1);
  const CVT_2::Sizing_field_density_2<K, Sizing> rho_boundary(boundary);
  const auto copy = rho_boundary;
  std::mt19937_64 rng(5);
  std::size_t wrong = 0;
  for (int i = 0; i < 2000; ++i) {
    const double x = uniform(rng, -3, 3);
    const Point p(x, uniform(rng, -3, 3));
    const double m = mu(p), b = boundary(p);
    if (std::abs(rho(p) - 1 / (m * m * m * m)) > 1e-14 / (m * m * m * m)) ++wrong;
    if (std::abs(rho_boundary(p) - 1 / (b * b * b * b)) > 1e-14 / (b * b * b * b)) ++wrong;
    if (copy(p) != rho_boundary(p)) ++wrong;
  }
  CHECK(wrong == 0);
  CHECK(rho(Point(0.95, 0)) == Approx(1.0).epsilon(1e-15));       // mu = 1
  CHECK(rho(Point(1.95, 0)) == Approx(1.0 / 16).epsilon(1e-15));  // mu = 2
}

TEST_CASE("a sizing field not positive and finite throws Domain_error naming point and value",
          "[density]") {
  const Point p(0.25, 3.5);
  const auto shifted = [](double v) {
    return CVT_2::make_sizing_field_density_2<K>([v](const Point& x) { return x.x() - 0.25 + v; });
  };
  for (const double bad : {0.0, -0.75, not_a_number, infinity, 1e-80, 1e80}) {
    CAPTURE(bad);
    CHECK_THROWS_AS(shifted(bad)(p), CVT_2::Domain_error);
    const std::string what = message_of([&] { shifted(bad)(p); });
    CHECK_THAT(what, Catch::Contains("(0.25, 3.5)"));
  }
  CHECK_THAT(message_of([&] { shifted(-0.75)(p); }), Catch::Contains("-0.75"));
  CHECK_THAT(message_of([&] { shifted(not_a_number)(p); }), Catch::Contains("nan"));
  CHECK_NOTHROW(shifted(1e-70)(p));
  CHECK_NOTHROW(shifted(1e70)(p));
}

// A sizing field with a batch member: 1 + x, but `bad` at one point.
struct Sizing_with_one_bad_value {
  double bad;
  Point where;
  double operator()(const Point& x) const { return x == where ? bad : 1 + x.x(); }
  void evaluate(const std::vector<Point>& points, std::vector<double>& values) const {
    values.clear();
    for (const Point& x : points) values.push_back((*this)(x));
  }
};

TEST_CASE("a sizing field's batch is checked as one point is, a bad value anywhere in it",
          "[density]") {
  STATIC_REQUIRE(CVT_2::has_batch_evaluation_v<Sizing_with_one_bad_value, K>);
  for (const std::size_t n : {1u, 6u, 7u}) {  // one, even, odd: the last pair half repeated
    std::vector<Point> points;
    for (std::size_t i = 0; i < n; ++i) points.emplace_back(0.125 * double(i), 2.0);
    std::vector<double> values;
    const auto good =
        CVT_2::make_sizing_field_density_2<K>(Sizing_with_one_bad_value{1, Point(-1, -1)});
    good.evaluate(points, values);
    REQUIRE(values.size() == n);
    for (std::size_t i = 0; i < n; ++i) CHECK(values[i] == good(points[i]));
    for (const double bad :
         {0.0, -0.0, -0.75, not_a_number, infinity, -infinity, 1e-80, 1e80, 1e-310}) {
      for (std::size_t i = 0; i < n; ++i) {
        CAPTURE(n, bad, i);
        const auto rho =
            CVT_2::make_sizing_field_density_2<K>(Sizing_with_one_bad_value{bad, points[i]});
        const std::string one = message_of([&] { rho(points[i]); });
        REQUIRE_THAT(one, Catch::Contains("(0"));
        CHECK(message_of([&] { rho.evaluate(points, values); }) == one);
      }
    }
  }
}

TEST_CASE("the boundary sizing equals a brute-force minimum over all boundary segments",
          "[density][sizing]") {
  const std::string file = GENERATE(as<std::string>{}, "earcut_dude.poly",
                                    "us_massachusetts_counties.poly", "world_land_110m.poly");
  const double k = GENERATE(0.1, 0.5, 2.0);
  const bool constant = GENERATE(false, true);
  const unsigned seed = 17;
  Domain d;
  load_domain(d, file);
  const std::vector<Segment> segments = boundary_segments(d.cdt);
  const std::optional<double> size =
      constant ? std::optional<double>(diagonal(d.cdt) / 200) : std::nullopt;
  CAPTURE(file, k, constant, seed, segments.size());
  const Sizing mu(d.cdt, k, size);
  REQUIRE(mu.segments().size() == segments.size());
  CHECK(mu.lipschitz_constant() == k);
  std::size_t wrong = 0;
  for (const Point& x : sample_points(d.cdt, 2000, seed)) {
    const double expected = brute_force(segments, k, size, x), got = mu(x);
    const double slack = evaluation_slack(k, x, expected);
    if (!(std::abs(got - expected) <= slack)) {
      if (++wrong <= 3) {
        CAPTURE(x, expected, got, slack);
        CHECK(got == Approx(expected).margin(slack));
      }
    }
  }
  CHECK(wrong == 0);
}

TEST_CASE("the boundary sizing restricted to a disk equals it bit for bit in the disk",
          "[density][sizing]") {
  // bubble_with_hole: a finely cut curve, where many segments nearly tie and the restriction
  // keeps only those whose slope lets them beat the nearest one somewhere in the disk
  const std::string file =
      GENERATE(as<std::string>{}, "earcut_dude.poly", "us_massachusetts_counties.poly",
               "world_land_110m.poly", "bubble_with_hole.poly");
  const double k = GENERATE(0.1, 2.0);
  Domain d;
  load_domain(d, file);
  const Sizing mu(d.cdt, k);
  const auto rho = CVT_2::make_sizing_field_density_2<K>(mu);
  STATIC_REQUIRE(CVT_2::has_restrict_to_disk_v<Sizing, K>);
  STATIC_REQUIRE(CVT_2::has_restrict_to_disk_v<decltype(rho), K>);
  STATIC_REQUIRE(!CVT_2::has_restrict_to_disk_v<Uniform, K>);
  // restrictions evaluate in batches (a cell's quadrature points); the whole field does not,
  // or the optimizers would evaluate it by chunks instead of restricting it
  STATIC_REQUIRE(CVT_2::has_batch_evaluation_v<decltype(mu.restrict_to_disk(Point(), 1.0)), K>);
  STATIC_REQUIRE(CVT_2::has_batch_evaluation_v<decltype(rho.restrict_to_disk(Point(), 1.0)), K>);
  STATIC_REQUIRE(!CVT_2::has_batch_evaluation_v<Sizing, K>);
  STATIC_REQUIRE(!CVT_2::has_batch_evaluation_v<decltype(rho), K>);
  std::mt19937_64 rng(5);
  const double diag = diagonal(d.cdt);
  std::size_t wrong = 0, kept = 0, disks = 0, batch_wrong = 0;
  std::vector<Point> ys;
  std::vector<double> values, rho_values;
  for (const Point& c : sample_points(d.cdt, 200, 23)) {
    // radii from far below to far above the local size, and 0
    for (const double r : {0.0, 1e-4 * diag, 1e-2 * diag, 0.2 * diag}) {
      const auto local = mu.restrict_to_disk(c, r);
      const auto local_rho = rho.restrict_to_disk(c, r);
      kept += local.number_of_segments();
      ++disks;
      ys.clear();
      for (std::size_t j = 0; j < 20 + disks % 2; ++j) {  // on the circle (worst) and inside
        const double a = uniform(rng, 0, 2 * CGAL_PI),
                     t = j < 5 ? 1.0 : std::sqrt(uniform(rng, 0, 1));
        const Point y(c.x() + t * r * std::cos(a), c.y() + t * r * std::sin(a));
        ys.push_back(y);
        if (local(y) != mu(y) || local_rho(y) != rho(y)) {
          if (++wrong <= 3) {
            CAPTURE(file, k, c, r, y, local.number_of_segments());
            CHECK(local(y) == mu(y));
          }
        }
      }
      // the batch, an odd or even number of points, gives the same bits
      local.evaluate(ys, values);
      local_rho.evaluate(ys, rho_values);
      REQUIRE(values.size() == ys.size());
      REQUIRE(rho_values.size() == ys.size());
      for (std::size_t j = 0; j < ys.size(); ++j)
        if (values[j] != mu(ys[j]) || rho_values[j] != rho(ys[j])) ++batch_wrong;
      // and a cluster inside the disk, as a cell's quadrature points are, where the batch
      // skips the segments that cannot give the least value at any of them
      const double a = uniform(rng, 0, 2 * CGAL_PI), t = 0.8 * uniform(rng, 0, 1);
      const Point q(c.x() + t * r * std::cos(a), c.y() + t * r * std::sin(a));
      ys.clear();
      for (std::size_t j = 0; j < 41 + disks % 2; ++j)
        ys.emplace_back(q.x() + uniform(rng, -r, r) / 8, q.y() + uniform(rng, -r, r) / 8);
      local.evaluate(ys, values);
      local_rho.evaluate(ys, rho_values);
      for (std::size_t j = 0; j < ys.size(); ++j)
        if (values[j] != mu(ys[j]) || rho_values[j] != rho(ys[j])) ++batch_wrong;
      // a point that is not finite among them changes no other point's value
      const std::size_t odd = disks % ys.size();
      ys[odd] = disks % 2 ? Point(not_a_number, q.y()) : Point(q.x(), infinity);
      local.evaluate(ys, values);
      for (std::size_t j = 0; j < ys.size(); ++j)
        if (j == odd ? std::isfinite(values[j]) : values[j] != mu(ys[j])) ++batch_wrong;
    }
  }
  CAPTURE(file, k, double(kept) / double(disks), mu.segments().size());
  CHECK(wrong == 0);
  CHECK(batch_wrong == 0);
  CHECK(kept < disks * mu.segments().size() / 4);  // it does restrict
}

TEST_CASE("the restricted sizing equals it bit for bit next to a segment far longer than the disk",
          "[density][sizing]") {
  // A segment 10^4 long and a short one on nearly the same line, with one size: near the short
  // one both tie to within the rounding of the long one's distance, which is relative to its
  // length, not to the distance. The restriction's margins must cover it.
  const std::vector<Segment> segments{Segment(Point(-1e4, -7e3), Point(3e3, 2.1e3)),
                                      Segment(Point(-1, -0.7), Point(1, 0.7))};
  const Sizing mu(segments, 0.1, 0.01);
  std::mt19937_64 rng(3);
  std::size_t wrong = 0, batch_wrong = 0;
  std::vector<Point> ys;
  std::vector<double> values;
  for (int disk = 0; disk < 10000; ++disk) {  // the old margins: about 15 points wrong
    const double cx = uniform(rng, -1e-2, 1e-2), cy = 0.7 * cx + uniform(rng, 2e-3, 1e-2);
    const double r = 1e-3;
    const auto local = mu.restrict_to_disk(Point(cx, cy), r);
    ys.clear();
    for (int j = 0; j < 100; ++j) {
      const Point y(cx + uniform(rng, -r, r) / 1.5, cy + uniform(rng, -r, r) / 1.5);
      ys.push_back(y);
      if (local(y) != mu(y) && ++wrong <= 3) {
        CAPTURE(cx, cy, y, local(y) - mu(y));
        CHECK(local(y) == mu(y));
      }
    }
    local.evaluate(ys, values);
    for (std::size_t j = 0; j < ys.size(); ++j) batch_wrong += values[j] != mu(ys[j]);
  }
  CHECK(wrong == 0);
  CHECK(batch_wrong == 0);
}

TEST_CASE("the boundary sizing is k-Lipschitz", "[density][sizing]") {
  const std::string file =
      GENERATE(as<std::string>{}, "us_massachusetts_counties.poly", "world_land_110m.poly");
  const double k = GENERATE(0.1, 2.0);
  const unsigned seed = 23;
  CAPTURE(file, k, seed);
  Domain d;
  load_domain(d, file);
  const Sizing mu(d.cdt, k);
  const std::vector<Point> a = sample_points(d.cdt, 1500, seed),
                           b = sample_points(d.cdt, 1500, seed + 7);
  const double h = diagonal(d.cdt) * 1e-4;
  std::mt19937_64 rng(seed);
  std::size_t violations = 0, compared = 0;
  const auto check = [&](const Point& x, const Point& y) {
    const double mx = mu(x), my = mu(y);
    const double bound = k * std::sqrt(CGAL::squared_distance(x, y)) * (1 + 1e-12) +
                         1e-15 * std::max(mx, my);  // rounding of the two values
    ++compared;
    if (std::abs(mx - my) > bound) ++violations;
  };
  for (std::size_t i = 0; i < a.size(); ++i) {
    check(a[i], b[i]);  // far apart
    const double dx = uniform(rng, -h, h), dy = uniform(rng, -h, h);
    check(a[i], Point(a[i].x() + dx, a[i].y() + dy));  // close
  }
  CHECK(compared == 2 * a.size());
  CHECK(violations == 0);
}

TEST_CASE("the boundary sizing is at most size(s) on each segment, exactly the size if constant",
          "[density][sizing]") {
  const std::string file =
      GENERATE(as<std::string>{}, "earcut_dude.poly", "us_massachusetts_counties.poly");
  const double k = GENERATE(0.1, 2.0);
  CAPTURE(file, k);
  Domain d;
  load_domain(d, file);
  const std::vector<Segment> segments = boundary_segments(d.cdt);
  const double size = diagonal(d.cdt) / 100;
  const Sizing by_length(d.cdt, k), constant(d.cdt, k, size);
  std::size_t above = 0, not_size = 0, not_min = 0;
  for (const Segment& s : segments) {
    const double length = std::sqrt(s.squared_length());
    for (const double t : {0.0, 0.3, 0.5, 1.0}) {
      const Point x = s.source() + t * (s.target() - s.source());
      // x is s(t) rounded: k d(x, s) is up to k times a few ulps of its coordinates.
      if (by_length(x) > evaluation_slack(k, x, length) + length) ++above;
      if (std::abs(constant(x) - size) > evaluation_slack(k, x, size)) ++not_size;
      if (std::abs(by_length(x) - brute_force(segments, k, std::nullopt, x)) >
          evaluation_slack(k, x, length))
        ++not_min;
    }
  }
  CHECK(above == 0);
  CHECK(not_size == 0);
  CHECK(not_min == 0);
}

TEST_CASE("the sizing of a triangulation uses its domain's boundary and inner constraints",
          "[density][sizing]") {
  // The square [0, 10]² with the hole [4, 6]², a slit from (1, 1) to (3, 1) in the domain and a
  // slit from (4.5, 5) to (5.5, 5) inside the hole, outside the domain.
  CVT_2::IO::Poly_data<Point> poly;
  poly.vertices = {Point(0, 0), Point(10, 0), Point(10, 10), Point(0, 10),
                   Point(4, 4), Point(6, 4),  Point(6, 6),   Point(4, 6),
                   Point(1, 1), Point(3, 1),  Point(4.5, 5), Point(5.5, 5)};
  poly.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5},
                   {5, 6}, {6, 7}, {7, 4}, {8, 9}, {10, 11}};
  poly.holes = {Point(5, 4.5)};
  poly.segment_lines.assign(poly.segments.size(), 0);
  poly.vertex_lines.assign(poly.vertices.size(), 0);
  Cdt cdt;
  CVT_2::IO::insert_poly(cdt, poly);
  const Sizing mu(cdt, 0.5, 1.0);
  CHECK(mu.segments().size() == 9);
  for (const Segment& s : mu.segments()) {
    CAPTURE(s);
    CHECK(s != Segment(Point(4.5, 5), Point(5.5, 5)));
    CHECK(s != Segment(Point(5.5, 5), Point(4.5, 5)));
  }
  CHECK(mu(Point(5, 5)) == Approx(1.5).epsilon(1e-15));   // 1 from the hole's sides, not 0
  CHECK(mu(Point(2, 2)) == Approx(1.5).epsilon(1e-15));   // 1 from the slit, 2 from the sides
  CHECK(mu(Point(2, 1)) == Approx(1.0).epsilon(1e-15));   // on the slit
  CHECK(mu(Point(-4, 5)) == Approx(3.0).epsilon(1e-15));  // outside: still defined
  // Default sizes: the boundary edges are 10, 2 and 2 long.
  const Sizing by_length(cdt, 0.5);
  CHECK(by_length(Point(2, 1)) == Approx(2.0).epsilon(1e-15));
  CHECK(by_length(Point(5, 5)) == Approx(2.5).epsilon(1e-15));
}

TEST_CASE(
    "regression: the sizing of a triangulation does not depend on where its faces lie in "
    "memory",
    "[density][sizing][regression]") {
  // The edge iterator visits an edge from the face of smaller address, and a segment's distance
  // rounds differently from its reverse's: the field of the same domain differed in the last
  // bits from one process to another (the Python module against the cvt2 program, say).
  // Triangulation b reuses the faces that 3000 vertices removed in random order freed: its faces
  // lie in memory in another order than a's.
  Domain a, b;
  std::mt19937_64 rng(3);
  std::vector<Cdt::Vertex_handle> scaffold;
  for (std::size_t i = 0; i < 3000; ++i)
    scaffold.push_back(b.cdt.insert(Point(uniform(rng, 0, 1), uniform(rng, 0, 1))));
  std::shuffle(scaffold.begin(), scaffold.end(), rng);
  for (const auto v : scaffold) b.cdt.remove(v);
  load_domain(a, "earcut_dude.poly");
  load_domain(b, "earcut_dude.poly");
  // Another layout indeed: the same triangles, visited (in the order of their addresses) in
  // another order.
  const auto triangles_in_memory_order = [](const Cdt& cdt) {
    std::vector<std::array<Point, 3>> triangles;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      std::array<Point, 3> t{f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()};
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      triangles.push_back(t);
    }
    return triangles;
  };
  const auto triangles_a = triangles_in_memory_order(a.cdt);
  const auto triangles_b = triangles_in_memory_order(b.cdt);
  REQUIRE(std::is_permutation(triangles_a.begin(), triangles_a.end(), triangles_b.begin(),
                              triangles_b.end()));
  REQUIRE(triangles_a != triangles_b);
  for (const std::optional<double> size : {std::optional<double>(), std::optional<double>(2.5)}) {
    const Sizing mu_a(a.cdt, 0.2, size), mu_b(b.cdt, 0.2, size);
    CHECK(mu_a.segments() == mu_b.segments());
    const std::vector<Point> points = random_points_in_domain(a.cdt, 2000, 5);
    std::size_t different = 0;
    for (const Point& p : points) different += mu_a(p) == mu_b(p) ? 0 : 1;
    CHECK(different == 0);
  }
}

TEST_CASE("the boundary sizing scales with the domain: mu(s x + o) = s mu(x)",
          "[density][sizing]") {
  const double scale = GENERATE(1e-6, 1e-3, 1e6);
  const double offset = GENERATE(0.0, 1e4);
  CAPTURE(scale, offset);
  Domain ref, moved;
  load_domain(ref, "us_massachusetts_counties.poly");
  load_domain(moved, "us_massachusetts_counties.poly", scale, offset * scale, -offset * scale);
  const Sizing a(ref.cdt, 0.5), b(moved.cdt, 0.5);
  const double tolerance = offset == 0 ? 1e-12 : 1e-6;  // an offset costs digits
  std::size_t differ = 0;
  for (const Point& x : sample_points(ref.cdt, 1000, 31)) {
    const Point y(scale * x.x() + offset * scale, scale * x.y() - offset * scale);
    if (std::abs(b(y) - scale * a(x)) > tolerance * scale * a(x)) ++differ;
  }
  CHECK(differ == 0);
}

TEST_CASE("copies of the boundary sizing share it, and concurrent calls from its first one agree",
          "[density][sizing]") {
  Domain d;
  load_domain(d, "world_land_110m.poly");
  const std::vector<Point> pts = sample_points(d.cdt, 2000, 41);
  const Sizing mu(d.cdt, 0.1);
  // No call before the threads start: a lazily built tree would be built by both at once.
  std::vector<double> first(pts.size()), second(pts.size());
  const Sizing copy = mu;
  std::thread t1([&] {
    for (std::size_t i = 0; i < pts.size(); ++i) first[i] = mu(pts[i]);
  });
  std::thread t2([&] {
    for (std::size_t i = pts.size(); i-- > 0;) second[i] = copy(pts[i]);
  });
  t1.join();
  t2.join();
  CHECK(&copy.segments() == &mu.segments());
  CHECK(first == second);
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) wrong += first[i] != mu(pts[i]);
  CHECK(wrong == 0);
}

TEST_CASE("the boundary sizing rejects a bad k or size, no segment, degenerate segments",
          "[density][sizing]") {
  const std::vector<Segment> square = {
      Segment(Point(0, 0), Point(1, 0)), Segment(Point(1, 0), Point(1, 1)),
      Segment(Point(1, 1), Point(0, 1)), Segment(Point(0, 1), Point(0, 0))};
  for (const double k : {0.0, -0.5, not_a_number, infinity}) {
    CAPTURE(k);
    CHECK_THROWS_AS(Sizing(square, k), std::invalid_argument);
    CHECK_THAT(message_of([&] { Sizing(square, k); }), Catch::Contains("k = "));
  }
  CHECK_THAT(message_of([&] { Sizing(square, -0.5); }), Catch::Contains("-0.5"));
  for (const double size : {0.0, -1.0, not_a_number, infinity}) {
    CAPTURE(size);
    CHECK_THROWS_AS(Sizing(square, 0.1, size), std::invalid_argument);
    CHECK_THAT(message_of([&] { Sizing(square, 0.1, size); }), Catch::Contains("size = "));
  }
  CHECK_THROWS_AS(Sizing(std::vector<Segment>(), 0.1), CVT_2::Domain_error);
  const Cdt empty;
  CHECK_THROWS_AS(Sizing(empty, 0.1), CVT_2::Domain_error);

  std::vector<Segment> degenerate = square;
  degenerate.emplace_back(Point(2, 3), Point(2, 3));
  try {
    Sizing(degenerate, 0.1);
    FAIL("a segment of length 0 without a size was accepted");
  } catch (const CVT_2::Domain_error& e) {
    CHECK(e.index() == 4);
    CHECK_THAT(std::string(e.what()), Catch::Contains("(2, 3)"));
  }
  const Sizing with_point(degenerate, 0.5, 0.25);  // with a size, a point source is fine
  CHECK(with_point(Point(2, 4)) == Approx(0.75).epsilon(1e-15));

  // A point that is not finite gets no size, so the density reports it.
  const Sizing unit(square, 0.1);
  CHECK(std::isnan(unit(Point(not_a_number, 0.5))));
  CHECK_FALSE(std::isfinite(unit(Point(infinity, 0.5))));
  CHECK_THAT(message_of([&] { CVT_2::make_sizing_field_density_2<K>(unit)(Point(0.5, infinity)); }),
             Catch::Contains("(0.5, inf)"));

  std::vector<Segment> not_finite = square;
  not_finite.emplace_back(Point(0, 0), Point(not_a_number, 1));
  CHECK_THROWS_AS(Sizing(not_finite, 0.1, 1.0), CVT_2::Domain_error);
}

namespace {

// Generators on grids of the unit square, whose free cells' areas are known: squares of side
// 1/m, and of side 1/(2m) on the right half if `finer_right`.
std::vector<Point> square_grid(int m, bool finer_right) {
  std::vector<Point> p;
  for (int i = 0; i < 2 * m; ++i)
    for (int j = 0; j < 2 * m; ++j) {
      const double x = (i + 0.5) / (2 * m), y = (j + 0.5) / (2 * m);
      if (x > 0.5 && finer_right)
        p.emplace_back(x, y);  // a fine cell
      else if (i % 2 == 0 && j % 2 == 0)
        p.emplace_back(x + 0.25 / m, y + 0.25 / m);  // a coarse one, of four fine ones' place
    }
  return p;
}

}  // namespace

TEST_CASE("the density response is the slope of log(area) on log(density): 0, -1/2, NaN, errors",
          "[density]") {
  const auto response = [](const std::vector<Point>& points, const auto& rho) {
    Domain d;
    load_square(d);
    CVT_2::insert_generators_2(d.cdt, points);
    return CVT_2::density_response_2(Bvd(d.cdt), rho).slope;
  };
  const auto step = [](const Point& p) { return p.x() > 0.5 ? 16.0 : 1.0; };
  // Cells of one size: no response, whatever the density.
  CHECK(std::abs(response(square_grid(10, false), step)) < 0.02);
  CHECK(std::abs(response(square_grid(10, false),
                          [](const Point& p) { return std::exp(3 * p.x()); })) < 0.02);
  // A quarter of the area where the density is 16 times larger: -1/2, a CVT's response (to
  // the cells along the seam, which are neither: about 1/m of them).
  CHECK(response(square_grid(20, true), step) == Approx(-0.5).margin(0.02));
  // The batch member is used, and gives the same.
  CHECK(response(square_grid(20, true), CVT_2::make_sizing_field_density_2<K>([](const Point& p) {
                   return p.x() > 0.5 ? 0.5 : 1.0;
                 })) == Approx(-0.5).margin(0.02));
  // Too little variation, or too few cells, to measure.
  CHECK(
      std::isnan(response(square_grid(10, true), [](const Point& p) { return 1 + 0.5 * p.x(); })));
  CHECK(std::isnan(response({Point(0.3, 0.3), Point(0.6, 0.6)}, step)));
  // A bump narrower than the cells, on a generator: the cells of one size are its optimum's
  // (the bump's mass sits at a generator), and only the cells over which the density is about
  // constant take part, so there is nothing to measure (counting the generator's cell gave 0).
  const auto bump = [](const Point& p) {
    return 1 + 1e4 * std::exp(-CGAL::squared_distance(p, Point(0.45, 0.45)) / 1e-4);
  };
  CHECK(std::isnan(response(square_grid(10, false), bump)));
  // A bad value names its point.
  CHECK_THROWS_WITH(
      response(square_grid(4, false), [](const Point& p) { return p.x() > 0.5 ? -1.0 : 1.0; }),
      Catch::Contains("the density is -1") && Catch::Contains("at ("));
  // Points follow the density for a start when the response is at most -1/4, or not defined.
  const auto follows = [](const std::vector<Point>& points, const auto& rho) {
    Domain d;
    load_square(d);
    CVT_2::insert_generators_2(d.cdt, points);
    return CVT_2::follows_density_2(Bvd(d.cdt), rho);
  };
  CHECK_FALSE(follows(square_grid(20, false), step));  // 324 cells unclipped
  CHECK(follows(square_grid(6, false), step));         // 16: too few to judge
  CHECK(follows(square_grid(20, true), step));
  CHECK(follows(square_grid(10, true), [](const Point& p) { return 1 + 0.5 * p.x(); }));
  CHECK(follows(square_grid(10, false), bump));
  // What a redistribution replaces: every free generator but the fixed ones, if they do not
  // follow the density or always; none if they do; a fixed point that is not a generator named.
  const auto to_redistribute = [&step](const std::vector<Point>& points,
                                       const std::vector<Point>& fixed, bool always) {
    Domain d;
    load_square(d);
    CVT_2::insert_generators_2(d.cdt, points);
    const auto given = CVT_2::generators_to_redistribute_2(d.cdt, step, fixed, always);
    std::set<Point> out;
    for (const auto v : given) out.insert(v->point());
    CHECK(out.size() == given.size());
    return out;
  };
  const std::vector<Point> uniform = square_grid(20, false), drawn = square_grid(20, true);
  const std::vector<Point> fixed{uniform[7], uniform[42]};
  const std::set<Point> replaced = to_redistribute(uniform, fixed, false);
  CHECK(replaced.size() == uniform.size() - 2);
  for (const Point& p : uniform)
    CHECK(replaced.count(p) == (p == fixed[0] || p == fixed[1] ? 0 : 1));
  CHECK(to_redistribute(drawn, {}, false).empty());
  CHECK(to_redistribute(drawn, {drawn[3]}, true).size() == drawn.size() - 1);
  CHECK(to_redistribute(uniform, {Point(0, 0)}, false).size() == uniform.size());  // a corner
  CHECK_THROWS_WITH(to_redistribute(uniform, {Point(0.123, 0.5)}, true),
                    Catch::Contains("fixed_points") && Catch::Contains("(0.123, 0.5)"));
  // The note speaks up only for a response above -1/4 by two standard errors.
  const auto note = [](double slope, double error) {
    CVT_2::Density_response r;
    r.slope = slope, r.standard_error = error, r.cells = 500;
    return CVT_2::internal::density_response_note(r, false);
  };
  CHECK(note(-0.3, 0.01).empty());
  CHECK(note(not_a_number, not_a_number).empty());
  CHECK(note(-0.03, 0.2).empty());
  CHECK_THAT(note(-0.03, 0.1), Catch::Contains("density^-0.03") &&
                                   Catch::Contains("do not follow the density") &&
                                   Catch::Contains("started far"));
  CVT_2::Density_response far;
  far.slope = -0.03, far.standard_error = 0.01, far.cells = 500;
  CHECK_THAT(CVT_2::internal::density_response_note(far, true),
             Catch::Contains("were drawn from the density") && !Catch::Contains("started far"));
  far.cells = 127;  // too few cells to judge
  CHECK(CVT_2::internal::density_response_note(far, true).empty());
}

// The step of the tests below as a batch density (DensityFunction_2::evaluate()) that records
// its calls.
struct Recorded_step {
  std::vector<std::size_t>* calls;  // the points of each call
  double operator()(const Point& p) const { return p.x() > 0.5 ? 16.0 : 1.0; }
  void evaluate(const std::vector<Point>& points, std::vector<double>& values) const {
    calls->push_back(points.size());
    values.clear();
    for (const Point& p : points) values.push_back((*this)(p));
  }
};

TEST_CASE("the density response calls a batch density with 2^18 points at most, to the same bits",
          "[density]") {
  // 56 250 square cells: a generator and four vertices each, some 292 000 points.
  Domain d;
  load_square(d);
  CVT_2::insert_generators_2(d.cdt, square_grid(150, true));
  std::vector<std::size_t> calls;
  const CVT_2::Density_response batched =
      CVT_2::density_response_2(Bvd(d.cdt), Recorded_step{&calls});
  const CVT_2::Density_response single = CVT_2::density_response_2(
      Bvd(d.cdt), [](const Point& p) { return p.x() > 0.5 ? 16.0 : 1.0; });
  REQUIRE(calls.size() >= 2);
  CHECK(*std::max_element(calls.begin(), calls.end()) <= (std::size_t(1) << 18));
  CHECK(batched.slope == single.slope);
  CHECK(batched.cells == single.cells);
  CHECK(batched.slope == Approx(-0.5).margin(0.02));
}

TEST_CASE("a stop whose cells do not follow the density is STALLED, not CONVERGED", "[density]") {
  // Cells of one size on the unit square under a step density (16 on the right half): every
  // move ratio is 0 from the start (each cell's density is constant, its centroid its centre),
  // and the cells have the sizes of the start, far from the optimum (4 times smaller on the
  // right). Cells 4 times smaller on the right follow it: CONVERGED.
  const auto step = [](const Point& p) { return p.x() > 0.5 ? 16.0 : 1.0; };
  const auto run = [](const std::vector<Point>& points, bool lbfgs, const auto& np) {
    Domain d;
    load_square(d);
    CVT_2::insert_generators_2(d.cdt, points);
    return lbfgs ? CVT_2::lbfgs_optimize_2(d.cdt, np) : CVT_2::lloyd_optimize_2(d.cdt, np);
  };
  for (const bool lbfgs : {false, true}) {
    INFO((lbfgs ? "L-BFGS" : "Lloyd"));
    const auto density = CVT_2::parameters::density(step).number_of_iterations(5);
    const auto stalled = run(square_grid(20, false), lbfgs, density);
    CHECK(stalled.stop_reason == CVT_2::STALLED);
    CHECK(std::string(CVT_2::to_string(stalled.stop_reason)) == "stalled");
    CHECK(stalled.density_response.slope == Approx(0).margin(0.02));
    const auto converged = run(square_grid(20, true), lbfgs, density.number_of_iterations(100));
    CHECK(converged.stop_reason == CVT_2::CONVERGED);
    CHECK(converged.density_response.slope == Approx(-0.5).margin(0.02));
    // Uniform density: nothing to measure. Another limit stays what it was.
    const auto uniform =
        run(square_grid(20, false), lbfgs, CVT_2::parameters::number_of_iterations(5));
    CHECK(uniform.stop_reason == CVT_2::CONVERGED);
    CHECK(uniform.density_response.cells == 0);  // not measured
    const auto limit = run(square_grid(20, false), lbfgs, density.move_ratio_bound(0));
    CHECK(limit.stop_reason == CVT_2::MAX_ITERATIONS_REACHED);
    CHECK(limit.density_response.slope == Approx(0).margin(0.02));
  }
}

namespace {

// Two unit squares, [0, 1] and [1 + gap, 2 + gap] wide: a 2 x 1 rectangle cut by a constraint
// at x = 1 (no gap), or two islands. The density grows 16-fold from either outer side toward the
// middle; `left` and `right` points are drawn from it (with density^(1/2), as
// random_points_in_domain_2() draws) in the two squares.
struct Two_squares {
  struct Density {
    double end;  // the right square's outer side
    double operator()(const Point& p) const {
      return std::pow(16.0, std::min({p.x(), end - p.x(), 1.0}));
    }
  };
  Domain d;
  Density rho;
  Two_squares(std::size_t left, std::size_t right, std::uint64_t seed, double gap = 0)
      : rho{2 + gap} {
    const double b = 1 + gap, c = 2 + gap;
    if (gap == 0) {
      d.poly.vertices = {Point(0, 0), Point(1, 0), Point(2, 0),
                         Point(2, 1), Point(1, 1), Point(0, 1)};
      d.poly.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 0}, {1, 4}};
    } else {
      add_ring(d.poly, {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
      add_ring(d.poly, {{b, 0}, {c, 0}, {c, 1}, {b, 1}});
    }
    d.cdt = triangulate(d.poly);
    std::mt19937_64 rng(seed);
    std::vector<Point> points;
    for (const auto& [count, offset] : {std::pair{left, 0.0}, std::pair{right, b}})
      for (std::size_t k = 0; k < count;) {
        const Point p(offset + CVT_2::internal::uniform01(rng), CVT_2::internal::uniform01(rng));
        if (CVT_2::internal::uniform01(rng) * 4 < std::sqrt(rho(p))) points.push_back(p), ++k;
      }
    CVT_2::insert_generators_2(d.cdt, points);
  }
};

}  // namespace

TEST_CASE("regions between constraints with the wrong point counts for the density: STALLED",
          "[density]") {
  // Each square's cells follow the density among themselves (slope -1/2), whatever the counts;
  // no generator crosses the constraint, so 150 and 450 stay so, against 300 and 300 for the
  // squares' equal masses: by Gersho's law, (1/150 + 1/450) / (2/300) - 1 = 1/3 more energy.
  for (const bool lbfgs : {false, true}) {
    INFO((lbfgs ? "L-BFGS" : "Lloyd"));
    const auto run = [lbfgs](Two_squares& s) {
      const auto np = CVT_2::parameters::density(s.rho).number_of_iterations(300);
      return lbfgs ? CVT_2::lbfgs_optimize_2(s.d.cdt, np) : CVT_2::lloyd_optimize_2(s.d.cdt, np);
    };
    Two_squares wrong(150, 450, 1), right(300, 300, 2);
    const auto stalled = run(wrong), converged = run(right);
    CHECK(stalled.stop_reason == CVT_2::STALLED);
    CHECK(stalled.density_response.is_followed_in_cells());
    CHECK(stalled.density_response.slope == Approx(-0.5).margin(0.1));
    CHECK(stalled.density_response.regions == 2);
    CHECK(stalled.density_response.count_excess == Approx(1.0 / 3).margin(0.05));
    CHECK(converged.stop_reason == CVT_2::CONVERGED);
    CHECK(converged.density_response.regions == 2);
    CHECK(std::abs(converged.density_response.count_excess) < 0.01);
    // the public measure says the same of the final diagram
    const CVT_2::Density_response again = CVT_2::density_response_2(Bvd(wrong.d.cdt), wrong.rho);
    CHECK(again.count_excess == stalled.density_response.count_excess);
    CHECK_FALSE(again.is_followed());
  }
  // Given to an optimization, the wrong counts are redistributed, the right ones kept; so are
  // islands' (two squares 0.5 apart: no constraint has the domain on both sides).
  for (const double gap : {0.0, 0.5}) {
    INFO("gap " << gap);
    Two_squares wrong(150, 450, 3, gap), right(300, 300, 4, gap);
    const std::vector<Point> none;
    CVT_2::Density_response why;
    CHECK(CVT_2::generators_to_redistribute_2(wrong.d.cdt, wrong.rho, none, false, &why).size() ==
          600);
    CHECK(why.regions == 2);
    CHECK(why.count_excess == Approx(1.0 / 3).margin(0.08));
    CHECK(why.is_followed_in_cells());
    CHECK(CVT_2::internal::density_response_reason(why) ==
          "the regions between constraints hold too many of them or too few");
    CHECK(CVT_2::generators_to_redistribute_2(right.d.cdt, right.rho, none).empty());
  }
  // The note names the regions and the cost, and how to deal points.
  CVT_2::Density_response r;
  r.slope = -0.5, r.standard_error = 0.01, r.cells = 600;
  r.regions = 2, r.count_excess = 0.33;
  CHECK_THAT(CVT_2::internal::density_response_note(r, false),
             Catch::Contains("of the 2 regions between constraints, some hold too many points") &&
                 Catch::Contains("at least about 33% more energy") &&
                 Catch::Contains("deals them to the regions") &&
                 !Catch::Contains("do not follow the density:"));
  CHECK_THAT(CVT_2::internal::density_response_note(r, true),
             Catch::Contains("were dealt to the regions by their masses"));
  // Counts that cost 2% or less are not judged wrong.
  r.count_excess = 0.019;
  CHECK(CVT_2::internal::density_response_note(r, false).empty());
  CHECK(r.is_followed());
}
