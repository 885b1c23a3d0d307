// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Lloyd iteration: energy descent, stopping rule, constraints respected, densities, sizing.
#include "support/invariants.h"
#include "support/optimization.h"
#include "support/random_domain.h"
#include "support/support.h"

#include <CVT_2/Boundary_lipschitz_sizing_2.h>
#include <CVT_2/internal/layout/sort_faces.h>
#include <CVT_2/internal/parallel/Chunked_list.h>
#include <CVT_2/internal/parallel/Face_chunks.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

using namespace support;

namespace {

// E N / A² over its lower bound for uniform density, the regular hexagonal tiling's 5/(18√3).
double normalized_energy(double energy, std::size_t n, double area) {
  return energy * double(n) / (area * area) / (5.0 / (18.0 * std::sqrt(3.0)));
}

std::vector<Segment> constraint_segments(const Cdt& cdt) {
  std::vector<Segment> s;
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e)
    if (cdt.is_constrained(*e)) s.push_back(cdt.segment(*e));
  return s;
}

}  // namespace

TEST_CASE("a chunked list reads as its chunks joined, empty chunks and all", "[lloyd]") {
  CVT_2::internal::Chunked_list<int> list;
  CHECK(list.empty());
  CHECK(list.begin() == list.end());
  const std::vector<std::size_t> sizes{0, 3, 0, 0, 2500, 1, 0, 1023, 1024, 0, 5000, 0};
  for (int round = 0; round < 2; ++round) {  // again after a reset, with other values
    list.reset(sizes.size());
    std::vector<int> joined;
    for (std::size_t c = 0; c < sizes.size(); ++c)
      for (std::size_t k = 0; k < sizes[c]; ++k) {
        const int v = int(joined.size()) * (round + 2) + 7;
        list.chunk(c).push_back(v);
        joined.push_back(v);
      }
    list.seal();
    REQUIRE(list.size() == joined.size());
    const std::vector<int> read(list.begin(), list.end());
    CHECK(read == joined);
    for (std::size_t i = 0; i < joined.size(); ++i)
      if (list[i] != joined[i]) FAIL("index " << i << ": " << list[i] << " != " << joined[i]);
    for (std::size_t c = 0; c < sizes.size(); ++c) CHECK(list.previous_size(c) == sizes[c]);
  }
  list.clear();
  CHECK(list.empty());
  CHECK(list.begin() == list.end());
  CHECK(list.previous_size(4) == 2500);  // kept as a guess for the next lists
}

TEST_CASE("energy never rises under Lloyd iteration with exact quadrature", "[lloyd]") {
  const char* file = GENERATE(from_range(std::begin(descent_domains), std::end(descent_domains)));
  CAPTURE(file);
  Domain d;
  load_domain(d, file);
  insert_random_points(d, 400, 1);
  const Domain_marks marks = snapshot_marks(d.cdt);
  CVT_2::Lloyd_optimizer_2<Cdt> lloyd(d.cdt);
  double previous = lloyd.evaluate(10).energy;
  for (int it = 0; it < 40; ++it) {
    lloyd.move();
    CAPTURE(it);
    check_invariants(d.cdt, marks, 20, it);
    const double e = lloyd.evaluate(10).energy;
    CAPTURE(previous, e);
    CHECK(e <= previous * (1 + 1e-12));
    previous = e;
  }
}

TEST_CASE("constrained vertices never move and free generators never cross a constraint",
          "[lloyd]") {
  const char* file = GENERATE("square_inner_constraints.poly", "us_massachusetts_counties.poly");
  CAPTURE(file);
  Domain d;
  load_domain(d, file);
  insert_random_points(d, 600, 2);
  const auto constraints = constraint_segments(d.cdt);
  const Domain_marks marks = snapshot_marks(d.cdt);
  CVT_2::Lloyd_optimizer_2<Cdt> lloyd(d.cdt);
  std::size_t crossings = 0, constrained_moved = 0, moved = 0;
  for (int it = 0; it < 20; ++it) {
    std::map<Cdt::Vertex_handle, Point> before;
    for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
      before[v] = v->point();
    lloyd.evaluate(10);
    lloyd.move();
    CAPTURE(it);
    check_invariants(d.cdt, marks, 20, it);
    for (const auto& [v, p] : before) {
      if (v->point() == p) continue;
      ++moved;
      if (d.cdt.are_there_incident_constraints(v)) ++constrained_moved;
      const Segment path(p, v->point());
      for (const auto& s : constraints) crossings += CGAL::do_intersect(path, s);
    }
  }
  CHECK(moved > 600);
  CHECK(constrained_moved == 0);
  CHECK(crossings == 0);
}

TEST_CASE("fixed points stay where they are, by both optimizers; the others converge around them",
          "[lloyd][lbfgs]") {
  const bool lbfgs = GENERATE(false, true);
  CAPTURE(lbfgs);
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  const std::vector<Point> wells{Point(2.5, 7.25), Point(7.125, 2.75), Point(5, 5)};
  CVT_2::insert_generators_2(d.cdt, wells);
  insert_random_points(d, 400, 5);
  const auto np = CVT_2::parameters::fixed_points(wells).number_of_iterations(300);
  const auto r = lbfgs ? CVT_2::lbfgs_optimize_2(d.cdt, np) : CVT_2::lloyd_optimize_2(d.cdt, np);
  CHECK(r.stop_reason == CVT_2::CONVERGED);
  for (const Point& w : wells) {
    CAPTURE(w);
    Cdt::Locate_type lt;
    int li;
    d.cdt.locate(w, lt, li);
    CHECK(lt == Cdt::VERTEX);
  }
  // The same run without fixed points moves the wells' generators, to about the same energy.
  Domain free;
  load_domain(free, "square_inner_constraints.poly");
  CVT_2::insert_generators_2(free.cdt, wells);
  insert_random_points(free, 400, 5);
  const auto free_np = CVT_2::parameters::number_of_iterations(300);
  const auto f = lbfgs ? CVT_2::lbfgs_optimize_2(free.cdt, free_np)
                       : CVT_2::lloyd_optimize_2(free.cdt, free_np);
  CHECK(std::abs(r.energy / f.energy - 1) < 0.05);
  std::size_t moved = 0;
  for (const Point& w : wells) {
    Cdt::Locate_type lt;
    int li;
    free.cdt.locate(w, lt, li);
    moved += lt != Cdt::VERTEX;
  }
  CHECK(moved == wells.size());
  // A fixed point that is not a generator is an error that names it.
  const std::vector<Point> outside{Point(0.5, 0.25)}, on_constraint{Point(2, 2)};
  CHECK_THROWS_WITH(CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::fixed_points(outside)),
                    "fixed_points: (0.5, 0.25) is not a generator (insert it first)");
  CHECK_NOTHROW(CVT_2::lbfgs_optimize_2(  // a constrained vertex, fixed anyway
      d.cdt, CVT_2::parameters::fixed_points(on_constraint).number_of_iterations(1)));
}

TEST_CASE("generators stay in the region of the domain they start in", "[lloyd]") {
  // Massachusetts' counties are regions closed by constraints.
  Domain d;
  load_domain(d, "us_massachusetts_counties.poly");
  insert_random_points(d, 800, 3);
  const auto start = regions(d.cdt);
  const Domain_marks marks = snapshot_marks(d.cdt);
  CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::number_of_iterations(30).move_ratio_bound(0));
  check_invariants(d.cdt, marks);
  const auto end = regions(d.cdt);
  REQUIRE(start.size() == end.size());
  std::size_t changed = 0;
  for (const auto& [v, r] : start) changed += end.at(v) != r;
  CHECK(changed == 0);
}

TEST_CASE("the stopping rule stops where it should, and the result describes the final points",
          "[lloyd]") {
  Domain d;
  load_domain(d, "four_clusters.poly");  // the paper's Fig. 7: 200 clustered generators
  const Domain_marks marks = snapshot_marks(d.cdt);
  const CVT_2::Optimization_result r = CVT_2::lloyd_optimize_2(d.cdt);
  check_invariants(d.cdt, marks);
  check_converged(r);
  // An independent evaluation of the final points finds the same figures.
  check_result_describes_points(d.cdt, r);

  // With the move-ratio stop off, exactly the iterations asked for.
  Domain d2;
  load_domain(d2, "four_clusters.poly");
  const Domain_marks marks2 = snapshot_marks(d2.cdt);
  const auto r2 = CVT_2::lloyd_optimize_2(
      d2.cdt, CVT_2::parameters::number_of_iterations(7).move_ratio_bound(0));
  check_invariants(d2.cdt, marks2);
  CHECK(r2.stop_reason == CVT_2::MAX_ITERATIONS_REACHED);
  CHECK(std::string(CVT_2::to_string(r2.stop_reason)) == "max_iterations");
  CHECK(r2.number_of_iterations == 7);
  CHECK(r2.energy_history.size() == 8);
  // A callback stops it.
  Domain d3;
  load_domain(d3, "four_clusters.poly");
  const Domain_marks marks3 = snapshot_marks(d3.cdt);
  const auto r3 = CVT_2::lloyd_optimize_2(
      d3.cdt, CVT_2::parameters::callback(
                  [](const CVT_2::Optimization_result& p) { return p.number_of_iterations < 3; }));
  check_invariants(d3.cdt, marks3);
  CHECK(r3.stop_reason == CVT_2::CALLBACK_REQUESTED_STOP);
  CHECK(std::string(CVT_2::to_string(r3.stop_reason)) == "callback");
  CHECK(r3.number_of_iterations == 3);
}

TEST_CASE(
    "a converged uniform CVT of 2000 points in the unit square is within 4% of the hexagonal bound",
    "[lloyd]") {
  Domain d;
  load_square(d);
  insert_random_points(d, 2000, 4);
  const Domain_marks marks = snapshot_marks(d.cdt);
  const auto r = CVT_2::lloyd_optimize_2(d.cdt);
  check_invariants(d.cdt, marks);
  CAPTURE(r.number_of_iterations, r.max_move_ratio);
  CHECK(r.stop_reason == CVT_2::CONVERGED);
  const double e0 = normalized_energy(r.energy_history.front(), 2004, 1.0);
  const double e = normalized_energy(r.energy, 2004, 1.0);
  CAPTURE(e0, e);
  CHECK(e0 > 1.5);  // random points are far from it
  CHECK(e <= 1.04);
}

TEST_CASE("a user density (a lambda) and a user sizing field shape the cells", "[lloyd]") {
  SECTION("density: more generators where it is larger") {
    Domain d;
    load_square(d);
    const auto rho = [](const Point& p) { return 1.0 + 20.0 * p.x(); };
    const auto sqrt_rho = [&rho](const Point& p) { return std::sqrt(rho(p)); };
    CVT_2::insert_generators_2(
        d.cdt, CVT_2::random_points_in_domain_2(
                   d.cdt, 600, CVT_2::parameters::random_seed(5).density(sqrt_rho)));
    const Domain_marks marks = snapshot_marks(d.cdt);
    const auto r =
        CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::density(rho).number_of_iterations(60));
    check_invariants(d.cdt, marks);
    CHECK(r.energy_history.back() < r.energy_history.front());
    // Cells of size ∝ ρ^(-1/4): counts ∝ ∫ρ^(1/2), (21^1.5 - 11^1.5) / (11^1.5 - 1) = 1.68.
    CHECK(right_to_left(d.cdt) == Approx(1.68).epsilon(0.1));
  }
  SECTION("sizing: cell size proportional to the sizing field") {
    Domain d;
    load_square(d);
    const auto mu = [](const Point& p) { return 0.5 + p.x(); };
    // Initial points at about the CVT's density, μ^-2: Lloyd moves points only locally.
    const auto start = [&mu](const Point& p) { return 1 / (mu(p) * mu(p)); };
    CVT_2::insert_generators_2(
        d.cdt, CVT_2::random_points_in_domain_2(d.cdt, 1500,
                                                CVT_2::parameters::random_seed(6).density(start)));
    const Domain_marks marks = snapshot_marks(d.cdt);
    CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::sizing_field(mu).number_of_iterations(150));
    check_invariants(d.cdt, marks);
    // Mean cell area in two strips: ∝ μ², so their ratio is about (1.3 / 0.7)² = 3.45.
    const Bvd bvd(d.cdt);
    double area[2] = {0, 0};
    std::size_t count[2] = {0, 0};
    bvd.for_each_cell([&](Cdt::Vertex_handle v, const Cell& c) {
      if (!bvd.is_free(v)) return;
      const double x = v->point().x();
      const int s = x > 0.1 && x < 0.3 ? 0 : x > 0.7 && x < 0.9 ? 1 : -1;
      if (s < 0) return;
      area[s] += signed_area(c);
      ++count[s];
    });
    const double ratio = (area[1] / double(count[1])) / (area[0] / double(count[0]));
    CAPTURE(ratio, count[0], count[1]);
    CHECK(ratio == Approx(3.45).epsilon(0.2));
  }
}

TEST_CASE("bad densities and parameters give errors that say what and where", "[lloyd]") {
  Domain d;
  load_square(d);
  insert_random_points(d, 100, 7);
  const Domain_marks marks = snapshot_marks(d.cdt);
  const auto negative = [](const Point& p) { return p.x() < 0.5 ? 1.0 : -1.0; };
  try {
    CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::density(negative));
    FAIL("no exception");
  } catch (const CVT_2::Domain_error& e) {
    CHECK_THAT(e.what(), Catch::Contains("the density is -1") && Catch::Contains(" at ("));
  }
  const auto nan_sizing = [](const Point&) { return std::nan(""); };
  CHECK_THROWS_AS(CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::sizing_field(nan_sizing)),
                  CVT_2::Domain_error);
  CHECK_THROWS_WITH(CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::move_ratio_bound(-1.0)),
                    Catch::Contains("move_ratio_bound"));
  CHECK_THROWS_WITH(CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::maximum_running_time(-1.0)),
                    Catch::Contains("maximum_running_time"));
  CHECK_THROWS_WITH(CVT_2::lloyd_optimize_2(
                        d.cdt, CVT_2::parameters::minimum_quadrature_resolution(std::size_t(50))
                                   .maximum_quadrature_resolution(std::size_t(10))),
                    Catch::Contains("quadrature resolutions"));
  check_invariants(d.cdt, marks);  // the errors left a valid triangulation
}

// Three unit squares apart (islands): one with 40 vertices on its boundary (0.1 apart), one
// with its 4 corners, one with 400 (0.01 apart, under half a cell size: a finely digitised
// line, whose vertices' cells are slivers).
TEST_CASE("random points by region: each region's count is its mass less its generators' cells",
          "[lloyd]") {
  CVT_2::IO::Poly_data<Point> poly;
  const auto square = [](double x0, int per_side) {
    std::vector<Point> ring;
    const Point corner[4] = {{x0, 0}, {x0 + 1, 0}, {x0 + 1, 1}, {x0, 1}};
    for (int c = 0; c < 4; ++c)
      for (int i = 0; i < per_side; ++i) {
        const double t = double(i) / per_side;
        const Point &a = corner[c], &b = corner[(c + 1) % 4];
        ring.emplace_back(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
      }
    return ring;
  };
  add_ring(poly, square(0, 10));
  add_ring(poly, square(2, 1));
  add_ring(poly, square(4, 100));
  const Cdt cdt = triangulate(poly);
  const std::size_t n = 100;
  // The documented rule: a cell's mass m = area / cells, 0.35 m a boundary vertex, less in
  // proportion where its edges are under half a cell size.
  const double m = 3.0 / double(n + 444), size = std::sqrt(m / (std::sqrt(3.0) / 2));
  const double weight[3] = {1 - 40 * 0.35 * m, 1 - 4 * 0.35 * m,
                            1 - 400 * 0.35 * m * (0.01 / (size / 2))};
  const double sum = weight[0] + weight[1] + weight[2];
  std::set<std::array<int, 3>> independent;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const auto draw = [&](bool by_region) {
      const auto points = CVT_2::random_points_in_domain_2(
          cdt, n, CVT_2::parameters::random_seed(seed).by_region(by_region));
      REQUIRE(points.size() == n);
      std::array<int, 3> count{0, 0, 0};
      for (const Point& p : points) {
        REQUIRE(CVT_2::is_in_domain_2(cdt, p));
        ++count[std::size_t(p.x() / 2)];
      }
      return count;
    };
    const std::array<int, 3> count = draw(true);
    for (int r = 0; r < 3; ++r) CHECK(std::abs(count[r] - double(n) * weight[r] / sum) < 1);
    // A constant density: the triangles cut into pieces, weighed and sorted by region, the same
    // quotas.
    std::array<int, 3> weighed{0, 0, 0};
    for (const Point& p : CVT_2::random_points_in_domain_2(
             cdt, n, CVT_2::parameters::random_seed(seed).by_region(true).density([](const Point&) {
               return 5.0;
             })))
      ++weighed[std::size_t(p.x() / 2)];
    CHECK(weighed == count);
    independent.insert(draw(false));
    CHECK(CVT_2::random_points_in_domain_2(cdt, n, CVT_2::parameters::random_seed(seed)) ==
          CVT_2::random_points_in_domain_2(cdt, n,
                                           CVT_2::parameters::random_seed(seed).by_region(false)));
  }
  CHECK(independent.size() > 1);  // independent draws: counts that vary with the seed
  // A generator inside a region holds a whole cell there: 30 in the corners' square.
  Cdt with = cdt;
  std::vector<Point> inside;
  for (int i = 0; i < 30; ++i) inside.emplace_back(2.1 + 0.16 * (i / 5), 0.1 + 0.2 * (i % 5));
  CVT_2::insert_generators_2(with, inside);
  const double m2 = 3.0 / double(n + 474), size2 = std::sqrt(m2 / (std::sqrt(3.0) / 2));
  const double weight2[3] = {1 - 40 * 0.35 * m2, 1 - 4 * 0.35 * m2 - 30 * m2,
                             1 - 400 * 0.35 * m2 * (0.01 / (size2 / 2))};
  std::array<int, 3> count{0, 0, 0};
  for (const Point& p :
       CVT_2::random_points_in_domain_2(with, n, CVT_2::parameters::random_seed(1).by_region(true)))
    ++count[std::size_t(p.x() / 2)];
  for (int r = 0; r < 3; ++r)
    CHECK(std::abs(count[r] - double(n) * weight2[r] / (weight2[0] + weight2[1] + weight2[2])) < 1);
  // In each region the points follow the density (in the triangulation with generators,
  // whose faces are not in the regions' order): 1 to 9 across the first square, 9 to 1
  // across the second, 1 on the third
  const auto rho = [](const Point& p) {
    const double t = p.x() - 2 * std::floor(p.x() / 2);
    return p.x() < 2 ? 1 + 8 * t : p.x() < 4 ? 9 - 8 * t : 1.0;
  };
  double half[3][2] = {{0, 0}, {0, 0}, {0, 0}};
  for (const Point& p : CVT_2::random_points_in_domain_2(
           with, 30000, CVT_2::parameters::random_seed(1).by_region(true).density(rho)))
    half[std::size_t(p.x() / 2)][p.x() - 2 * std::floor(p.x() / 2) > 0.5] += 1;
  CHECK(half[0][1] / half[0][0] == Approx(3.5 / 1.5).epsilon(0.05));  // the halves' masses
  CHECK(half[1][1] / half[1][0] == Approx(1.5 / 3.5).epsilon(0.05));
  CHECK(half[2][1] / half[2][0] == Approx(1.0).epsilon(0.05));
  // Eight equal squares, 3 points each and 3 more: the regions that get one more are drawn with
  // the seed (in the faces' order, the same three would, whatever the seed).
  CVT_2::IO::Poly_data<Point> equal;
  for (int k = 0; k < 8; ++k) add_ring(equal, square(2 * k, 1));
  const Cdt squares = triangulate(equal);
  std::array<int, 8> extra{};
  std::set<std::array<int, 8>> counts;
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    std::array<int, 8> c{};
    for (const Point& p : CVT_2::random_points_in_domain_2(
             squares, 27, CVT_2::parameters::random_seed(seed).by_region(true)))
      ++c[std::size_t(p.x() / 2)];
    for (int k = 0; k < 8; ++k) {
      CHECK((c[k] == 3 || c[k] == 4));
      extra[k] += c[k] == 4;
    }
    counts.insert(c);
  }
  CAPTURE(extra);
  CHECK(*std::min_element(extra.begin(), extra.end()) > 0);  // each square, some seeds
  CHECK(counts.size() > 10);
  // Squares equal but for their last bits, as digitised data are (sides 1 + (k - 3.5) 2^-40):
  // the remainders lie within 2^-34 on either side of 3/8, a multiple of 2^-30. Rounded down to
  // 2^-30, those below 3/8 would rank last and never get one more.
  CVT_2::IO::Poly_data<Point> near;
  for (int k = 0; k < 8; ++k) {
    const double side = 1 + (k - 3.5) * 0x1p-40;
    add_ring(near, {{2.0 * k, 0}, {2.0 * k + side, 0}, {2.0 * k + side, side}, {2.0 * k, side}});
  }
  const Cdt near_squares = triangulate(near);
  extra = {};
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    std::array<int, 8> c{};
    for (const Point& p : CVT_2::random_points_in_domain_2(
             near_squares, 27, CVT_2::parameters::random_seed(seed).by_region(true)))
      ++c[std::size_t(p.x() / 2)];
    for (int k = 0; k < 8; ++k) extra[k] += c[k] == 4;
  }
  CAPTURE(extra);
  CHECK(*std::min_element(extra.begin(), extra.end()) > 0);
}

TEST_CASE("random initial generators are reproducible, inside, and follow the density", "[lloyd]") {
  Domain d;
  load_domain(d, "earcut_dude.poly");
  const auto a = CVT_2::random_points_in_domain_2(d.cdt, 2000, CVT_2::parameters::random_seed(9));
  const auto b = CVT_2::random_points_in_domain_2(d.cdt, 2000, CVT_2::parameters::random_seed(9));
  const auto c = CVT_2::random_points_in_domain_2(d.cdt, 2000, CVT_2::parameters::random_seed(10));
  CHECK(a == b);
  CHECK(a != c);
  std::size_t outside = 0;
  for (const auto& p : a) outside += !CVT_2::is_in_domain_2(d.cdt, p);
  CHECK(outside == 0);
  const CGAL::Bbox_2 box = domain_bbox(d.cdt);
  const double mid = (box.xmin() + box.xmax()) / 2;
  // A smooth density, 1 to 9 across: followed face by face (the sampling's resolution).
  const auto rho = [&box](const Point& p) {
    return 1 + 8 * (p.x() - box.xmin()) / (box.xmax() - box.xmin());
  };
  const auto w = CVT_2::random_points_in_domain_2(d.cdt, 40000,
                                                  CVT_2::parameters::random_seed(9).density(rho));
  const auto u = CVT_2::random_points_in_domain_2(d.cdt, 40000, CVT_2::parameters::random_seed(9));
  double mass[2] = {0, 0}, area[2] = {0, 0}, count[2] = {0, 0};  // the halves', from u
  for (const auto& p : u) mass[p.x() < mid ? 0 : 1] += rho(p), area[p.x() < mid ? 0 : 1] += 1;
  for (const auto& p : w) count[p.x() < mid ? 0 : 1] += 1;
  CHECK(count[1] / count[0] == Approx(mass[1] / mass[0]).epsilon(0.05));
  CHECK(count[1] / count[0] > 1.5 * area[1] / area[0]);  // far from uniform

  // A refinement far steeper than a sampling piece (the cell size 0.0005 at a well, growing
  // with the distance; a piece is 0.01 across): the points within 0.01 of the well are as
  // many as the density's mass there says (the pieces' masses from their edges' midpoints gave
  // it a third of them, and the rest went elsewhere).
  Domain square;
  load_square(square);
  const Point well(0.4302, 0.5713);
  const auto mu = [&well](const Point& p) {
    return 0.0005 + std::sqrt(CGAL::squared_distance(p, well));
  };
  const auto near = [&well](const Point& p) { return CGAL::squared_distance(p, well) < 1e-4; };
  double near_mass = 0, all_mass = 0;  // of 1 / mu^2, on a grid of 4000 x 4000 cells
  for (int i = 0; i < 4000; ++i)
    for (int j = 0; j < 4000; ++j) {
      const Point p((i + 0.5) / 4000, (j + 0.5) / 4000);
      const double m = 1 / (mu(p) * mu(p));
      all_mass += m, near_mass += near(p) ? m : 0;
    }
  const auto drawn = CVT_2::random_points_in_domain_2(
      square.cdt, 20000, CVT_2::parameters::random_seed(9).sizing_field(mu));
  const auto in_near = double(std::count_if(drawn.begin(), drawn.end(), near));
  CHECK(in_near / 20000 == Approx(near_mass / all_mass).epsilon(0.05));
}

TEST_CASE("Lloyd with the automatic k-Lipschitz sizing refines near the boundary", "[lloyd]") {
  Domain d;
  load_domain(d, "earcut_dude.poly");
  insert_random_points(d, 800, 11);
  const Domain_marks marks = snapshot_marks(d.cdt);
  const CVT_2::Boundary_lipschitz_sizing_2<K> mu(d.cdt, 0.1);
  const auto r =
      CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::sizing_field(mu).number_of_iterations(40));
  CHECK(r.energy_history.back() < r.energy_history.front());
  check_invariants(d.cdt, marks);
}

TEST_CASE("a density restricted to each cell's disk gives Lloyd the same bits as the whole field",
          "[lloyd]") {
  // The optimizer keeps each cell's restriction from one evaluation to the next while the cell
  // stays in its disk: the bits stay those of the whole field over many moves.
  const std::string file =
      GENERATE(as<std::string>{}, "us_massachusetts_counties.poly", "bubble_with_hole.poly");
  CAPTURE(file);
  Domain a, b;
  load_domain(a, file);
  load_domain(b, file);
  insert_random_points(a, 600, 3);
  insert_random_points(b, 600, 3);
  const Domain_marks marks_a = snapshot_marks(a.cdt), marks_b = snapshot_marks(b.cdt);
  const CVT_2::Boundary_lipschitz_sizing_2<K> mu(a.cdt, 0.1);
  const auto rho = CVT_2::make_sizing_field_density_2<K>(mu);
  const auto whole = [&rho](const Point& p) { return rho(p); };  // hides restrict_to_disk
  STATIC_REQUIRE(CVT_2::has_restrict_to_disk_v<decltype(rho), K>);
  STATIC_REQUIRE(!CVT_2::has_restrict_to_disk_v<decltype(whole), K>);
  CVT_2::Lloyd_optimizer_2<Cdt, std::decay_t<decltype(rho)>> la(a.cdt, rho);
  CVT_2::Lloyd_optimizer_2<Cdt, std::decay_t<decltype(whole)>> lb(b.cdt, whole);
  for (const std::size_t resolution : {10, 10, 10, 10, 10, 10, 10, 10, 100, 100, 100}) {
    const auto ea = la.evaluate(resolution);
    const auto eb = lb.evaluate(resolution);
    CAPTURE(resolution);
    REQUIRE(ea.energy == eb.energy);
    REQUIRE(ea.max_move_ratio == eb.max_move_ratio);
    REQUIRE(la.free_generators().size() == lb.free_generators().size());
    for (std::size_t i = 0; i < la.free_generators().size(); ++i)
      REQUIRE(la.free_generators()[i].centroid == lb.free_generators()[i].centroid);
    la.move();
    lb.move();
    check_invariants(a.cdt, marks_a, 20);
    check_invariants(b.cdt, marks_b, 20);
  }
}

// A density whose restrictions count their calls: one by one, and by batches with their points.
struct Call_counts {
  std::atomic<std::size_t> single{0}, batches{0}, points{0};
};
template <class Rho>
struct Counted_density {
  template <class R>
  struct Restriction {
    R r;
    Call_counts* counts;
    double operator()(const Point& p) const {
      ++counts->single;
      return r(p);
    }
    void evaluate(const std::vector<Point>& points, std::vector<double>& values) const {
      ++counts->batches;
      counts->points += points.size();
      r.evaluate(points, values);
    }
  };
  Rho rho;
  Call_counts* counts;
  double operator()(const Point& p) const { return rho(p); }
  auto restrict_to_disk(const Point& c, double radius) const {
    using R = decltype(rho.restrict_to_disk(c, radius));
    return Restriction<R>{rho.restrict_to_disk(c, radius), counts};
  }
};

TEST_CASE("a restriction with a batch member is evaluated once a cell, for all its points",
          "[lloyd]") {
  Domain d;
  load_domain(d, "bubble_with_hole.poly");
  insert_random_points(d, 500, 6);
  Call_counts counts;
  const CVT_2::Boundary_lipschitz_sizing_2<K> mu(d.cdt, 0.1);
  const auto rho = CVT_2::make_sizing_field_density_2<K>(mu);
  const Counted_density<decltype(rho)> counted{rho, &counts};
  STATIC_REQUIRE(CVT_2::has_restrict_to_disk_v<decltype(counted), K>);
  STATIC_REQUIRE(!CVT_2::has_batch_evaluation_v<decltype(counted), K>);
  CVT_2::Lloyd_optimizer_2<Cdt, std::decay_t<decltype(counted)>> lloyd(d.cdt, counted);
  std::size_t cells = 0;
  const auto& e = lloyd.evaluate(10);
  lloyd.diagram().for_each_cell([&](Cdt::Vertex_handle, const auto&) { ++cells; });
  CHECK(counts.single == 0);
  CHECK(counts.batches == cells);
  CHECK(counts.points >= 7 * 3 * cells);  // Radon's 7 points on each of 3 fan triangles at least
  // the same moments as one point at a time: the whole field, without restrictions
  Domain same;
  load_domain(same, "bubble_with_hole.poly");
  insert_random_points(same, 500, 6);
  const auto whole = [&rho](const Point& p) { return rho(p); };
  CVT_2::Lloyd_optimizer_2<Cdt, decltype(whole)> reference(same.cdt, whole);
  CHECK(reference.evaluate(10).energy == e.energy);
}

TEST_CASE("Lloyd gives the same bits whatever the number of threads and from run to run",
          "[lloyd]") {
  // Enough generators for many chunks of cells, a domain with holes and inner constraints, and
  // a density evaluated at many points (midpoint quadrature).
  const auto rho = [](const Point& p) { return 1.0 + 4.0 * std::exp(-p.x() * p.x() / 4000); };
  std::vector<std::vector<double>> energies;
  std::vector<std::vector<Point>> finals;
  for (const unsigned threads : {1u, 2u, 3u, 2u}) {
    Domain d;
    load_domain(d, "us_massachusetts_counties.poly");
    insert_random_points(d, 30000, 4);
    const Domain_marks marks = snapshot_marks(d.cdt);
    CVT_2::Lloyd_optimizer_2<Cdt, decltype(rho)> lloyd(d.cdt, rho);
    lloyd.set_number_of_threads(threads);
    REQUIRE(CVT_2::internal::Face_chunks<Cdt>(d.cdt).size() >= 12);  // enough for 3 threads
    std::vector<double> e;
    for (int it = 0; it < 4; ++it) {
      const auto& ev = lloyd.evaluate(10);
      e.push_back(ev.energy);
      e.push_back(ev.max_move_ratio);
      e.push_back(ev.mean_move_ratio);
      lloyd.move();
      if (threads == 3) check_invariants(d.cdt, marks, 20, it);  // one of the four runs
    }
    energies.push_back(e);
    finals.push_back(vertex_points(d.cdt));
  }
  for (std::size_t i = 1; i < energies.size(); ++i) {
    CAPTURE(i);
    CHECK(energies[i] == energies[0]);
    CHECK(finals[i] == finals[0]);
  }
}

TEST_CASE("an adaptive Lloyd on a few thousand generators gives the same bits on 1 and 2 threads",
          "[lloyd]") {
  // Cells under a quadrature rule come in smaller chunks than under exact formulas: a few
  // thousand generators already make several, run on two threads.
  std::vector<std::vector<Point>> finals;
  std::vector<double> energies;
  for (const int threads : {1, 2}) {
    Domain d;
    load_domain(d, "bubble_with_hole.poly");
    insert_random_points(d, 2500, 6);
    using Chunks = CVT_2::internal::Face_chunks<Cdt>;
    REQUIRE(Chunks(d.cdt).size() < 4);  // not for exact formulas
    REQUIRE(Chunks(d.cdt, Chunks::quadrature_chunk_size).size() >= 4);
    const CVT_2::Boundary_lipschitz_sizing_2<K> mu(d.cdt, 0.1);
    const auto r = CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::sizing_field(mu)
                                                      .number_of_iterations(5)
                                                      .move_ratio_bound(0)
                                                      .number_of_threads(threads));
    energies.push_back(r.energy);
    finals.push_back(vertex_points(d.cdt));
  }
  CHECK(energies[1] == energies[0]);
  CHECK(finals[1] == finals[0]);
}

TEST_CASE("lloyd_optimize_2 takes number_of_threads and gives the same result with any",
          "[lloyd]") {
  std::vector<std::vector<double>> histories;
  for (const int threads : {1, 2, 0}) {
    Domain d;
    load_domain(d, "earcut_dude.poly");
    insert_random_points(d, 20000, 2);
    const Domain_marks marks = snapshot_marks(d.cdt);
    const auto r = CVT_2::lloyd_optimize_2(
        d.cdt,
        CVT_2::parameters::number_of_iterations(3).move_ratio_bound(0).number_of_threads(threads));
    histories.push_back(r.energy_history);
    if (threads == 0) check_invariants(d.cdt, marks, 50);
  }
  CHECK(histories[1] == histories[0]);
  CHECK(histories[2] == histories[0]);
  Domain d;
  load_square(d);
  CHECK_THROWS_AS(CVT_2::lloyd_optimize_2(d.cdt, CVT_2::parameters::number_of_threads(-1)),
                  std::invalid_argument);
}

namespace {

// A density with the batch member of DensityFunction_2, around a function of a point: counts
// its batches and their points (from several threads at once).
template <class F>
struct Batch_density {
  F f;
  std::atomic<std::size_t>* batches;
  std::atomic<std::size_t>* points;
  std::ptrdiff_t extra = 0;  // values added (> 0) or left out (< 0), to break the contract
  double operator()(const Point& p) const { return f(p); }
  void evaluate(const std::vector<Point>& at, std::vector<double>& values) const {
    ++*batches;
    *points += at.size();
    for (const Point& p : at) values.push_back(f(p));
    if (extra < 0) values.resize(values.size() - std::size_t(-extra));
    if (extra > 0) values.resize(values.size() + std::size_t(extra), 1.0);
  }
};

}  // namespace

TEST_CASE("a density evaluated in batches gives the same bits as point by point", "[lloyd]") {
  const auto rho = [](const Point& p) { return 1.0 + 4.0 * std::exp(-p.x() * p.x() / 4000); };
  std::atomic<std::size_t> batches{0}, points{0};
  using Batch = Batch_density<decltype(rho)>;
  const Batch batch{rho, &batches, &points};
  STATIC_REQUIRE(CVT_2::has_batch_evaluation_v<Batch, K>);
  STATIC_REQUIRE(!CVT_2::has_batch_evaluation_v<decltype(rho), K>);
  SECTION("random points") {
    Domain d;
    load_domain(d, "us_massachusetts_counties.poly");
    const auto np = CVT_2::parameters::random_seed(3);
    const auto a = CVT_2::random_points_in_domain_2(d.cdt, 5000, np.density(rho));
    const auto b = CVT_2::random_points_in_domain_2(d.cdt, 5000, np.density(batch));
    CHECK(a == b);
    CHECK(batches == 1);
    CHECK(points >= 3 * 10000);  // three midpoints of each of at least 10^4 sub-triangles
  }
  SECTION("Lloyd's and L-BFGS's evaluations, one batch a chunk of cells, any threads") {
    for (const bool lbfgs : {false, true}) {
      std::vector<std::vector<double>> histories;
      std::vector<std::vector<Point>> finals;
      for (const int threads : {1, 2, -1}) {  // -1: point by point
        CAPTURE(lbfgs, threads);
        Domain d;
        load_domain(d, "us_massachusetts_counties.poly");
        insert_random_points(d, 20000, 4);
        const Domain_marks marks = snapshot_marks(d.cdt);
        batches = 0;
        const auto np =
            CVT_2::parameters::number_of_iterations(4).move_ratio_bound(0).number_of_threads(
                threads < 0 ? 2 : threads);
        const auto run = [&](const auto& parameters) {
          return lbfgs ? CVT_2::lbfgs_optimize_2(d.cdt, parameters)
                       : CVT_2::lloyd_optimize_2(d.cdt, parameters);
        };
        const auto r = threads < 0 ? run(np.density(rho)) : run(np.density(batch));
        if (threads < 0) {
          CHECK(batches == 0);
        } else {
          // One batch a chunk of faces (of cells under a quadrature rule) an evaluation, and
          // two for the final density response: the cells', and the counties' masses.
          using Chunks = CVT_2::internal::Face_chunks<Cdt>;
          const std::size_t chunks = Chunks(d.cdt, Chunks::quadrature_chunk_size).size();
          CHECK(batches == chunks * r.number_of_evaluations + 2);
        }
        check_invariants(d.cdt, marks, 50);
        histories.push_back(r.energy_history);
        finals.push_back(vertex_points(d.cdt));
      }
      CHECK(histories[1] == histories[0]);
      CHECK(histories[2] == histories[0]);
      CHECK(finals[1] == finals[0]);
      CHECK(finals[2] == finals[0]);
    }
  }
}

namespace {

// A quadrature with the call operator only (no nodes()): a batch density runs it twice.
struct Call_only_quadrature {
  template <class Density, class PointRange>
  CVT_2::Cell_moments_2<K> operator()(const Point& x, const PointRange& cell, const Density& rho,
                                      std::size_t resolution) const {
    return CVT_2::Midpoint_quadrature_2<K>()(x, cell, rho, resolution);
  }
};

// A quadrature that asks for another point where the density is large: not for batches.
struct Adaptive_quadrature {
  template <class Density, class PointRange>
  CVT_2::Cell_moments_2<K> operator()(const Point& x, const PointRange& cell, const Density& rho,
                                      std::size_t resolution) const {
    if (rho(x) > 1.5) rho(*cell.begin());
    return CVT_2::Midpoint_quadrature_2<K>()(x, cell, rho, resolution);
  }
};

}  // namespace

TEST_CASE("a quadrature without nodes() runs twice on a batch density, to the same bits",
          "[lloyd]") {
  const auto rho = [](const Point& p) { return 1.0 + std::exp(-4 * p.x() * p.x()); };
  std::atomic<std::size_t> batches{0}, points{0};
  using Batch = Batch_density<decltype(rho)>;
  STATIC_REQUIRE(CVT_2::has_quadrature_nodes_v<CVT_2::Midpoint_quadrature_2<K>, K>);
  STATIC_REQUIRE(!CVT_2::has_quadrature_nodes_v<Call_only_quadrature, K>);
  STATIC_REQUIRE(!CVT_2::has_quadrature_nodes_v<CVT_2::Exact_quadrature_2<K>, K>);
  Domain a, b, c;
  for (Domain* d : {&a, &b, &c}) {
    load_domain(*d, "four_clusters.poly");
    insert_random_points(*d, 3000, 6);
  }
  CVT_2::Lloyd_optimizer_2<Cdt, decltype(rho), CVT_2::Midpoint_quadrature_2<K>> pointwise(a.cdt,
                                                                                          rho);
  CVT_2::Lloyd_optimizer_2<Cdt, Batch, Call_only_quadrature> twice(b.cdt,
                                                                   Batch{rho, &batches, &points});
  for (const std::size_t resolution : {10, 40, 100}) {
    CAPTURE(resolution);
    const auto e = pointwise.evaluate(resolution);
    const auto f = twice.evaluate(resolution);
    CHECK(e.energy == f.energy);
    CHECK(e.max_move_ratio == f.max_move_ratio);
    pointwise.move();
    twice.move();
  }
  CHECK(batches > 0);
  CVT_2::Lloyd_optimizer_2<Cdt, Batch, Adaptive_quadrature> adaptive(c.cdt,
                                                                     Batch{rho, &batches, &points});
  CHECK_THROWS_WITH(adaptive.evaluate(10), Catch::Contains("needs a quadrature that asks for the "
                                                           "same points"));
}

TEST_CASE("a batch density's values are checked: count, sign, finiteness, naming the point",
          "[lloyd]") {
  std::atomic<std::size_t> batches{0}, points{0};
  const auto message = [](auto&& f) -> std::string {
    try {
      f();
    } catch (const CVT_2::Domain_error& e) {
      return e.what();
    }
    return "no exception";
  };
  const auto evaluate = [&](const auto& rho) {
    return message([&] {
      Domain d;
      load_square(d);
      insert_random_points(d, 3000, 9);
      CVT_2::Lloyd_optimizer_2<Cdt, std::decay_t<decltype(rho)>> lloyd(d.cdt, rho);
      lloyd.evaluate(10);
    });
  };
  const auto negative = [](const Point& p) { return p.x() < 0.5 ? 1.0 : -1.0; };
  const auto one = [](const Point&) { return 1.0; };
  const std::string pointwise = evaluate(negative);
  CHECK_THAT(pointwise, Catch::Contains("the density is -1"));
  CHECK(evaluate(Batch_density<decltype(negative)>{negative, &batches, &points}) == pointwise);
  CHECK_THAT(evaluate(Batch_density<decltype(one)>{one, &batches, &points, -1}),
             Catch::Matches("the density's batch evaluation gave [0-9]+ values for [0-9]+ points"));
  CHECK_THAT(evaluate(Batch_density<decltype(one)>{one, &batches, &points, 2}),
             Catch::Contains("batch evaluation gave"));
  const auto nan = [](const Point& p) { return p.y() < 0.5 ? 1.0 : std::nan(""); };
  CHECK_THAT(evaluate(Batch_density<decltype(nan)>{nan, &batches, &points}),
             Catch::Contains("the density is nan at"));
}

TEST_CASE("a density error from a worker thread is the one a serial run reports", "[lloyd]") {
  const auto rho = [](const Point& p) { return p.x() < 0.5 || p.y() < 0.5 ? 1.0 : -1.0; };
  std::vector<std::string> messages;
  for (const unsigned threads : {1u, 2u}) {
    Domain d;
    load_square(d);
    insert_random_points(d, 30000, 9);
    CVT_2::Lloyd_optimizer_2<Cdt, decltype(rho)> lloyd(d.cdt, rho);
    lloyd.set_number_of_threads(threads);
    try {
      lloyd.evaluate(10);
      messages.push_back("no exception");
    } catch (const CVT_2::Domain_error& e) {
      messages.push_back(e.what());
    }
  }
  CHECK_THAT(messages[0], Catch::Contains("the density is -1"));
  CHECK(messages[1] == messages[0]);
}

TEST_CASE("extreme scales: random points work, Lloyd says clearly when moments leave double",
          "[lloyd][degenerate]") {
  // At 2^-1000 or 2^990 the BVD is still right (see the BVD tests), but a cell's moments,
  // which scale as its size to the fourth, underflow or overflow.
  const int exponent = GENERATE(-1000, 990);  // 10 · 2^990 stays below the 1e300 limit
  CAPTURE(exponent);
  Domain d;
  load_domain(d, "square_inner_constraints.poly", std::ldexp(1.0, exponent));
  const auto pts = CVT_2::random_points_in_domain_2(d.cdt, 200, CVT_2::parameters::random_seed(1));
  REQUIRE(pts.size() == 200);
  for (const auto& p : pts) CHECK(CVT_2::is_in_domain_2(d.cdt, p));
  CVT_2::insert_generators_2(d.cdt, pts);
  const Domain_marks marks = snapshot_marks(d.cdt);
  try {
    CVT_2::lloyd_optimize_2(d.cdt);
    FAIL("no exception");
  } catch (const CVT_2::Domain_error& e) {
    CHECK_THAT(e.what(), Catch::Contains("do not fit in double precision"));
  }
  // The triangulation's invariants only: the domain's area under- or overflows double here.
  check_triangulation(d.cdt, marks);
}

TEST_CASE("a cell whose mass underflows stays put; Lloyd and L-BFGS go on around it",
          "[lloyd][degenerate]") {
  // Two free generators one ulp apart, and two 1e-310 from a corner: their cells' masses are
  // subnormal or 0 (before, 0 / 0 centroids, or an error that blamed the domain's size).
  const std::vector<Point> extra =
      GENERATE(std::vector<Point>{{0.3, 0.3}, {0.3, std::nextafter(0.3, 1.0)}},
               std::vector<Point>{{1e-310, 1e-310}, {2e-310, 1e-310}},
               std::vector<Point>{{1e-323, 0}, {0.5, 4.9e-324}});
  const bool lbfgs = GENERATE(false, true);
  CAPTURE(extra, lbfgs);
  Domain d;
  load_domain(d, "four_clusters.poly");
  insert_random_points(d, 100, 3);
  CVT_2::insert_generators_2(d.cdt, extra);
  const Domain_marks marks = snapshot_marks(d.cdt);
  const auto np = CVT_2::parameters::number_of_iterations(40).move_ratio_bound(0);
  const CVT_2::Optimization_result r =
      lbfgs ? CVT_2::lbfgs_optimize_2(d.cdt, np) : CVT_2::lloyd_optimize_2(d.cdt, np);
  CHECK(r.number_of_iterations == 40);
  CHECK(std::isfinite(r.energy));
  CHECK(r.energy > 0);
  CHECK(r.energy < r.energy_history.front());
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
    CHECK(CVT_2::is_in_domain_2(d.cdt, v->point()));
  check_invariants(d.cdt, marks, 200, 1, true);  // the two cells may stay subnormal
}

TEST_CASE("Lloyd on a domain with 2500 holes lowers the energy and keeps every generator in",
          "[lloyd][degenerate]") {
  Cdt cdt = square_with_holes(50);
  CVT_2::insert_generators_2(cdt, random_points_in_domain(cdt, 5000, 73));
  const Domain_marks marks = snapshot_marks(cdt);
  CVT_2::Lloyd_optimizer_2<Cdt> lloyd(cdt);
  double previous = lloyd.evaluate(10).energy;
  for (int it = 0; it < 10; ++it) {
    lloyd.move();
    check_invariants(cdt, marks, 20, it);
    const double e = lloyd.evaluate(10).energy;
    CAPTURE(it, previous, e);
    CHECK(e <= previous * (1 + 1e-12));
    previous = e;
  }
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    CHECK(CVT_2::is_in_domain_2(cdt, v->point()));
}

TEST_CASE("random domains: Lloyd never raises the energy and keeps generators in the domain",
          "[lloyd][random]") {
  // The BVD's random domains (see random_domain.h), 5 iterations each: 150 cases here,
  // CVT_2_RANDOM_CASES=N runs N (scripts/run_nightly.sh runs thousands).
  const unsigned cases = random_cases(150, 3.0 / 8);
  for (unsigned seed = 1; seed <= cases; ++seed) {
    CAPTURE(seed);
    Cdt cdt = random_triangulation(seed, 150);
    const Domain_marks marks = snapshot_marks(cdt);
    CVT_2::Lloyd_optimizer_2<Cdt> lloyd(cdt);
    double previous = lloyd.evaluate(10).energy;
    REQUIRE(std::isfinite(previous));
    for (int it = 0; it < 5; ++it) {
      lloyd.move();
      REQUIRE(check_triangulation(cdt, marks));  // valid, constrained Delaunay, marks
      const double e = lloyd.evaluate(10).energy;
      CAPTURE(it, previous, e);
      REQUIRE(e <= previous * (1 + 1e-12));
      previous = e;
    }
    std::size_t outside = 0;  // free generators (constraint vertices may lie outside)
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      outside += !cdt.are_there_incident_constraints(v) && !CVT_2::is_in_domain_2(cdt, v->point());
    REQUIRE(outside == 0);
    check_diagram(Bvd(cdt), 20, seed);  // and the final diagram
  }
}

TEST_CASE("the optimizers lay out the faces that CGAL's own insertion scattered, for long runs",
          "[lloyd]") {
  // Built by CGAL's insertion, 2^16 faces and more: scattered in memory (insert_generators_2
  // lays out its own). A run of 16 iterations or more lays them out first; a shorter one does
  // not. Either way, the same result as from a triangulation laid out by hand.
  const auto build = [](bool laid_out) {
    Domain d;
    load_square(d);
    const std::vector<Point> points = random_points_in_domain(d.cdt, 40000, 3);
    d.cdt.insert(points.begin(), points.end());
    CVT_2::mark_domain_2(d.cdt, d.poly.holes);
    REQUIRE(d.cdt.number_of_faces() >= std::size_t(1) << 16);
    if (laid_out) CVT_2::internal::sort_faces(d.cdt);
    return d;
  };
  const auto points_of = [](const Cdt& cdt) {
    std::vector<Point> p;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      p.push_back(v->point());
    return p;
  };
  for (const bool lbfgs : {false, true}) {
    CAPTURE(lbfgs);
    const auto run = [lbfgs](Cdt& cdt, std::size_t iterations) {
      const auto np = CVT_2::parameters::number_of_iterations(iterations).move_ratio_bound(0);
      return lbfgs ? CVT_2::lbfgs_optimize_2(cdt, np) : CVT_2::lloyd_optimize_2(cdt, np);
    };
    Domain scattered = build(false), by_hand = build(true);
    REQUIRE(CVT_2::internal::faces_are_scattered(scattered.cdt));
    REQUIRE(!CVT_2::internal::faces_are_scattered(by_hand.cdt));
    const std::vector<Point> start = points_of(scattered.cdt);

    Domain short_run = build(false);
    run(short_run.cdt, 15);
    CHECK(CVT_2::internal::faces_are_scattered(short_run.cdt));

    const auto r = run(scattered.cdt, 16);
    const auto r_by_hand = run(by_hand.cdt, 16);
    CHECK(!CVT_2::internal::faces_are_scattered(scattered.cdt));
    CHECK(scattered.cdt.is_valid());
    CHECK(points_of(scattered.cdt) != start);
    CHECK(points_of(scattered.cdt) == points_of(by_hand.cdt));
    CHECK(r.energy_history == r_by_hand.energy_history);
  }
}

namespace {

// The points of the vertices of `cdt`, sorted.
std::vector<Point> sorted_points(const Cdt& cdt) {
  std::vector<Point> p;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    p.push_back(v->point());
  std::sort(p.begin(), p.end());
  return p;
}

// Whether every face has the tag a rebuild (Algorithm 1 on all faces) gives it.
bool tags_as_rebuilt(const Cdt& cdt) {
  std::vector<std::tuple<Cdt::Face_handle, bool, Cdt::Edge>> tags;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    tags.emplace_back(f, f->is_blinded(), f->is_blinded() ? f->blinding_edge() : Cdt::Edge());
  CVT_2::Bounded_voronoi_diagram_2<Cdt> rebuilt(cdt);
  std::size_t wrong = 0;
  for (const auto& [f, blinded, e] : tags)
    wrong += f->is_blinded() != blinded || (blinded && f->blinding_edge() != e);
  CHECK(wrong == 0);
  return wrong == 0;
}

}  // namespace

TEST_CASE(
    "a relaxation in a region moves its generators as a run with the others fixed does, "
    "and keeps the tags current",
    "[lloyd][lbfgs][region]") {
  const bool lbfgs = GENERATE(false, true);
  const std::string file =
      GENERATE(std::string("square_inner_constraints.poly"), "us_massachusetts_counties.poly");
  CAPTURE(lbfgs, file);
  Domain a, b;
  load_domain(a, file);
  load_domain(b, file);
  insert_random_points(a, 1500, 11);
  insert_random_points(b, 1500, 11);
  // near a CVT, as after an edit: every generator reaches its centroid, whatever the order
  for (Domain* d : {&a, &b})
    CVT_2::lloyd_optimize_2(d->cdt, CVT_2::parameters::number_of_iterations(40));
  CVT_2::Bounded_voronoi_diagram_2<Cdt> diagram(a.cdt);  // tags current before the run
  // the seeds: the free generators nearest to a constrained vertex, so that blind faces are near
  const CGAL::Bbox_2 box = domain_bbox(a.cdt);
  const Point middle((box.xmin() + box.xmax()) / 2, (box.ymin() + box.ymax()) / 2);
  Point center = middle;
  double nearest = std::numeric_limits<double>::infinity();
  for (auto v = a.cdt.finite_vertices_begin(); v != a.cdt.finite_vertices_end(); ++v)
    if (a.cdt.are_there_incident_constraints(v) &&
        CGAL::squared_distance(v->point(), middle) < nearest) {
      nearest = CGAL::squared_distance(v->point(), middle);
      center = v->point();
    }
  std::vector<std::pair<double, Point>> by_distance;
  for (auto v = a.cdt.finite_vertices_begin(); v != a.cdt.finite_vertices_end(); ++v)
    if (!a.cdt.are_there_incident_constraints(v))
      by_distance.emplace_back(CGAL::squared_distance(v->point(), center), v->point());
  std::sort(by_distance.begin(), by_distance.end());
  std::vector<Point> seeds;
  for (std::size_t k = 0; k < 6; ++k) seeds.push_back(by_distance[k].second);
  const auto np =
      CVT_2::parameters::region(seeds).region_rings(2).number_of_iterations(12).move_ratio_bound(0);
  const auto region = *CVT_2::internal::region_vertices(a.cdt, np);
  REQUIRE(region.size() > 20);
  std::set<Point> movable;
  for (const auto v : region) movable.insert(v->point());
  std::vector<Point> fixed;  // the free generators outside the region
  for (auto v = b.cdt.finite_vertices_begin(); v != b.cdt.finite_vertices_end(); ++v)
    if (!b.cdt.are_there_incident_constraints(v) && movable.count(v->point()) == 0)
      fixed.push_back(v->point());
  const auto before = sorted_points(a.cdt);
  const auto r = lbfgs ? CVT_2::lbfgs_optimize_2(a.cdt, np) : CVT_2::lloyd_optimize_2(a.cdt, np);
  CHECK(r.number_of_iterations == 12);
  const auto fixed_np =
      CVT_2::parameters::fixed_points(fixed).number_of_iterations(12).move_ratio_bound(0);
  const auto f =
      lbfgs ? CVT_2::lbfgs_optimize_2(b.cdt, fixed_np) : CVT_2::lloyd_optimize_2(b.cdt, fixed_np);
  // the same moves: the same points, to the bit (L-BFGS's line search compares the region's
  // energy, not the whole one's: the same decisions, to rounding)
  const auto after = sorted_points(a.cdt), expected = sorted_points(b.cdt);
  REQUIRE(after.size() == expected.size());
  double largest = 0;
  for (std::size_t k = 0; k < after.size(); ++k)
    largest = std::max(largest, std::sqrt(CGAL::squared_distance(after[k], expected[k])));
  CHECK(largest <= (lbfgs ? 1e-9 : 0.0));
  // only the region moved, and it did
  std::vector<Point> kept, moved_from;
  for (const Point& p : before) (movable.count(p) ? moved_from : kept).push_back(p);
  std::size_t lost = 0;
  for (const Point& p : kept) lost += !std::binary_search(after.begin(), after.end(), p);
  CHECK(lost == 0);
  std::size_t stayed = 0;
  for (const Point& p : moved_from) stayed += std::binary_search(after.begin(), after.end(), p);
  CHECK(stayed < moved_from.size() / 4);
  // the energy of the region is lower than it was, and the tags are those of a rebuild
  CHECK(r.energy_history.back() < r.energy_history.front());
  CHECK(f.energy_history.back() < f.energy_history.front());
  CHECK(tags_as_rebuilt(a.cdt));
  // from random points, where moves are long and flips many, beside every constraint
  Domain c;
  load_domain(c, file);
  insert_random_points(c, 1500, 12);
  CVT_2::Bounded_voronoi_diagram_2<Cdt> tagged(c.cdt);
  std::vector<Point> constrained;
  for (auto v = c.cdt.finite_vertices_begin(); v != c.cdt.finite_vertices_end(); ++v)
    if (c.cdt.are_there_incident_constraints(v)) constrained.push_back(v->point());
  const auto wide = CVT_2::parameters::region(constrained).region_rings(1).number_of_iterations(8);
  lbfgs ? CVT_2::lbfgs_optimize_2(c.cdt, wide) : CVT_2::lloyd_optimize_2(c.cdt, wide);
  CHECK(tags_as_rebuilt(c.cdt));
  // a region point that is not a generator is an error that names it
  CHECK_THROWS_WITH(
      CVT_2::lloyd_optimize_2(a.cdt, CVT_2::parameters::region(std::vector<Point>{Point(-7, -7)})),
      "region: (-7, -7) is not a generator (insert it first)");
}
