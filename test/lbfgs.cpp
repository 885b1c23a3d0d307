// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// L-BFGS on the CVT energy: descent, gradient, stopping rule, determinism, speed, constraints.
#include "support/invariants.h"
#include "support/optimization.h"
#include "support/support.h"

#include <CVT_2/Cvt_energy_2.h>
#include <CVT_2/Exact_quadrature_2.h>
#include <CVT_2/Lbfgs_optimizer_2.h>
#include <CVT_2/internal/Lbfgs_history.h>
#include <CVT_2/internal/move_generators.h>
#include <CVT_2/internal/parallel/Face_chunks.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <vector>

using namespace support;

namespace {

std::size_t number_of_cells(const Cdt& cdt) {
  std::size_t n = 0;
  Bvd(cdt).for_each_cell([&n](Cdt::Vertex_handle, const Cell&) { ++n; });
  return n;
}

// The exact quadrature, counting the cells it integrates (on several threads): evaluations =
// count / cells.
struct Counting_quadrature {
  std::shared_ptr<std::atomic<std::size_t>> count = std::make_shared<std::atomic<std::size_t>>(0);
  template <class Density, class PointRange>
  CVT_2::Cell_moments_2<K> operator()(const Point& x, const PointRange& cell, const Density& rho,
                                      std::size_t resolution) const {
    ++*count;
    return CVT_2::Exact_quadrature_2<K>()(x, cell, rho, resolution);
  }
};

// The exact moments, but an energy that grows with every cell integrated: each evaluation finds
// more than the last, so every line search fails.
struct Rising_energy_quadrature {
  std::shared_ptr<std::atomic<std::size_t>> count = std::make_shared<std::atomic<std::size_t>>(0);
  template <class Density, class PointRange>
  CVT_2::Cell_moments_2<K> operator()(const Point& x, const PointRange& cell, const Density& rho,
                                      std::size_t resolution) const {
    CVT_2::Cell_moments_2<K> m = CVT_2::Exact_quadrature_2<K>()(x, cell, rho, resolution);
    m.energy += 1e-3 * double(++*count);
    return m;
  }
};

}  // namespace

TEST_CASE("L-BFGS never raises the energy with exact quadrature", "[lbfgs]") {
  const char* file = GENERATE(from_range(std::begin(descent_domains), std::end(descent_domains)));
  CAPTURE(file);
  Domain d;
  load_domain(d, file);
  CVT_2::insert_generators_2(d.cdt, random_points_in_domain(d.cdt, 400, 1));
  const Domain_marks marks = snapshot_marks(d.cdt);
  CVT_2::Lbfgs_optimizer_2<Cdt> lbfgs(d.cdt);
  double previous = lbfgs.evaluate(10).energy;
  const double first = previous;
  std::size_t with_memory = 0;
  for (int it = 0; it < 40; ++it) {
    with_memory += lbfgs.number_of_curvature_pairs() > 0;
    const double e = lbfgs.step(10).energy;
    CAPTURE(it, previous, e);
    check_invariants(d.cdt, marks, 20, it);
    CHECK(e <= previous);
    previous = e;
  }
  CHECK(with_memory >= 30);  // quasi-Newton steps, not only Lloyd steps
  // Every quasi-Newton direction went downhill: with exact quadrature the curvature pairs are
  // those of the true energy, and positive.
  CHECK(lbfgs.number_of_restarts() == 0);
  CHECK(previous < first);
  CHECK(lbfgs.number_of_steps() == 40);
  CHECK(lbfgs.number_of_evaluations() >= 41);
}

TEST_CASE("L-BFGS stops by Lloyd's rule: an independent Lloyd evaluation of the result agrees",
          "[lbfgs]") {
  const char* file = GENERATE("four_clusters.poly", "us_massachusetts_counties.poly");
  CAPTURE(file);
  Domain d;
  load_domain(d, file);
  if (std::string(file) != "four_clusters.poly")
    CVT_2::insert_generators_2(d.cdt, random_points_in_domain(d.cdt, 1000, 2));
  const Domain_marks marks = snapshot_marks(d.cdt);
  const CVT_2::Optimization_result r = CVT_2::lbfgs_optimize_2(d.cdt);
  check_invariants(d.cdt, marks);
  check_converged(r);
  CHECK(r.energy < r.energy_history.front());
  check_result_describes_points(d.cdt, r);
}

TEST_CASE("L-BFGS stops after the iterations asked for, or when the callback says so", "[lbfgs]") {
  Domain d;
  load_domain(d, "four_clusters.poly");
  const Domain_marks marks = snapshot_marks(d.cdt);
  const auto r = CVT_2::lbfgs_optimize_2(
      d.cdt, CVT_2::parameters::number_of_iterations(7).move_ratio_bound(0));
  check_invariants(d.cdt, marks);
  CHECK(r.stop_reason == CVT_2::MAX_ITERATIONS_REACHED);
  CHECK(r.number_of_iterations == 7);
  CHECK(r.energy_history.size() == 8);
  const auto r2 = CVT_2::lbfgs_optimize_2(
      d.cdt, CVT_2::parameters::callback(
                 [](const CVT_2::Optimization_result& p) { return p.number_of_iterations < 3; }));
  CHECK(r2.stop_reason == CVT_2::CALLBACK_REQUESTED_STOP);
  CHECK(r2.number_of_iterations == 3);
  check_invariants(d.cdt, marks);
}

TEST_CASE("the gradient 2 m (x - c) equals central differences of the energy", "[lbfgs]") {
  // Exact quadrature; each generator moves by h, far less than its distance to any constraint,
  // and the triangulation is built again from the points.
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  const std::vector<Point> points = random_points_in_domain(d.cdt, 200, 3);
  const auto energy = [&d](const std::vector<Point>& p) {
    Domain e;
    load_domain(e, "square_inner_constraints.poly");
    CVT_2::insert_generators_2(e.cdt, p);
    return CVT_2::Cvt_energy_2<Cdt>(e.cdt).evaluate(1).energy;
  };
  CVT_2::insert_generators_2(d.cdt, points);
  CVT_2::Cvt_energy_2<Cdt> energy_at_points(d.cdt);
  energy_at_points.evaluate(1);
  std::map<Point, CVT_2::Cvt_energy_2<Cdt>::Free_generator> by_point;
  for (const auto& g : energy_at_points.free_generators()) by_point.emplace(g.vertex->point(), g);
  const double h = 1e-6;
  double largest_error = 0, largest_gradient = 0;
  for (std::size_t j = 0; j < points.size(); j += 10) {
    const auto& g = by_point.at(points[j]);
    const double gradient[2] = {2 * g.mass * (points[j].x() - g.centroid.x()),
                                2 * g.mass * (points[j].y() - g.centroid.y())};
    for (int axis = 0; axis < 2; ++axis) {
      std::vector<Point> plus = points, minus = points;
      const double dx = axis == 0 ? h : 0, dy = axis == 1 ? h : 0;
      plus[j] = Point(points[j].x() + dx, points[j].y() + dy);
      minus[j] = Point(points[j].x() - dx, points[j].y() - dy);
      const double difference = (energy(plus) - energy(minus)) / (2 * h);
      CAPTURE(j, axis, gradient[axis], difference);
      CHECK(difference == Approx(gradient[axis]).epsilon(1e-5).margin(1e-9));
      largest_error = std::max(largest_error, std::abs(difference - gradient[axis]));
      largest_gradient = std::max(largest_gradient, std::abs(gradient[axis]));
    }
  }
  CAPTURE(largest_error, largest_gradient);
  CHECK(largest_gradient > 1e-5);  // the random points are far from a CVT
  CHECK(largest_error < 1e-6 * largest_gradient);
}

TEST_CASE("L-BFGS runs twice on the same input give the same bits", "[lbfgs]") {
  const auto run = [] {
    Domain d;
    load_domain(d, "square_inner_constraints.poly");
    CVT_2::insert_generators_2(d.cdt, random_points_in_domain(d.cdt, 1500, 4));
    const Domain_marks marks = snapshot_marks(d.cdt);
    const auto r = CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::number_of_iterations(40));
    check_invariants(d.cdt, marks, 100);
    return std::make_pair(r.energy_history, vertex_points(d.cdt));
  };
  const auto a = run();
  const auto b = run();
  CHECK(a.first == b.first);
  CHECK(a.second == b.second);
  // And on one thread or three (enough generators for the cells to be split among them).
  const auto steps = [](unsigned threads) {
    Domain d;
    load_domain(d, "square_inner_constraints.poly");
    CVT_2::insert_generators_2(d.cdt, random_points_in_domain(d.cdt, 30000, 4));
    const Domain_marks marks = snapshot_marks(d.cdt);
    CVT_2::Lbfgs_optimizer_2<Cdt> lbfgs(d.cdt);
    lbfgs.set_number_of_threads(threads);
    REQUIRE(CVT_2::internal::Face_chunks<Cdt>(d.cdt).size() >= 12);
    std::vector<double> energies{lbfgs.evaluate(10).energy};
    for (int it = 0; it < 6; ++it) {
      energies.push_back(lbfgs.step(10).energy);
      if (threads == 3) check_invariants(d.cdt, marks, 20, it);
    }
    return std::make_pair(energies, vertex_points(d.cdt));
  };
  CHECK(steps(1) == steps(3));
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  CVT_2::insert_generators_2(d.cdt, random_points_in_domain(d.cdt, 1500, 4));
  const auto one = CVT_2::lbfgs_optimize_2(
      d.cdt, CVT_2::parameters::number_of_iterations(40).number_of_threads(1));
  CHECK(one.energy_history == a.first);
  CHECK(vertex_points(d.cdt) == a.second);
}

TEST_CASE("L-BFGS reaches Lloyd's 1% stop in fewer evaluations than Lloyd", "[lbfgs]") {
  Domain d;
  load_square(d);
  const std::vector<Point> points = random_points_in_domain(d.cdt, 2000, 5);
  std::size_t evaluations[2];
  double energies[2];
  for (int algorithm = 0; algorithm < 2; ++algorithm) {
    Domain e;
    load_square(e);
    CVT_2::insert_generators_2(e.cdt, points);
    const Domain_marks marks = snapshot_marks(e.cdt);
    const Counting_quadrature q;
    const auto np = CVT_2::parameters::quadrature(q);
    const auto r =
        algorithm == 0 ? CVT_2::lloyd_optimize_2(e.cdt, np) : CVT_2::lbfgs_optimize_2(e.cdt, np);
    check_invariants(e.cdt, marks);
    CHECK(r.stop_reason == CVT_2::CONVERGED);
    const std::size_t cells = number_of_cells(e.cdt);
    REQUIRE(*q.count % cells == 0);
    evaluations[algorithm] = *q.count / cells;
    energies[algorithm] = r.energy;
  }
  CAPTURE(evaluations[0], evaluations[1], energies[0], energies[1]);
  CHECK(2 * evaluations[1] <= evaluations[0]);  // at least twice as few (measured: 3x)
  CHECK(energies[1] <= energies[0] * 1.001);
}

TEST_CASE("L-BFGS keeps constrained vertices and each generator in its region", "[lbfgs]") {
  Domain d;
  load_domain(d, "us_massachusetts_counties.poly");
  CVT_2::insert_generators_2(d.cdt, random_points_in_domain(d.cdt, 800, 6));
  std::map<Cdt::Vertex_handle, Point> constrained;
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
    if (d.cdt.are_there_incident_constraints(v)) constrained[v] = v->point();
  const auto start = regions(d.cdt);
  const Domain_marks marks = snapshot_marks(d.cdt);
  const auto r = CVT_2::lbfgs_optimize_2(
      d.cdt, CVT_2::parameters::number_of_iterations(30).move_ratio_bound(0));
  check_invariants(d.cdt, marks);
  CHECK(r.energy < r.energy_history.front());
  const auto end = regions(d.cdt);
  REQUIRE(start.size() == end.size());
  std::size_t changed = 0, moved = 0;
  for (const auto& [v, region] : start) changed += end.at(v) != region;
  for (const auto& [v, p] : constrained) moved += v->point() != p;
  CHECK(changed == 0);
  CHECK(moved == 0);
}

TEST_CASE("L-BFGS with a lambda density (midpoint quadrature) converges and shapes the cells",
          "[lbfgs]") {
  Domain d;
  load_square(d);
  const auto rho = [](const Point& p) { return 1.0 + 20.0 * p.x(); };
  const auto sqrt_rho = [&rho](const Point& p) { return std::sqrt(rho(p)); };
  CVT_2::insert_generators_2(
      d.cdt, CVT_2::random_points_in_domain_2(d.cdt, 600,
                                              CVT_2::parameters::random_seed(7).density(sqrt_rho)));
  const Domain_marks marks = snapshot_marks(d.cdt);
  const auto r = CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::density(rho));
  check_invariants(d.cdt, marks);
  CAPTURE(r.number_of_iterations, r.max_move_ratio);
  CHECK(r.stop_reason == CVT_2::CONVERGED);
  CHECK(r.energy < r.energy_history.front());
  // Cells of size ∝ ρ^(-1/4): counts ∝ ∫ρ^(1/2), (21^1.5 - 11^1.5) / (11^1.5 - 1) = 1.68.
  CHECK(right_to_left(d.cdt) == Approx(1.68).epsilon(0.1));
  // The final points pass an independent check at the highest resolution.
  CVT_2::Lloyd_optimizer_2<Cdt, decltype(rho)> check(d.cdt, rho);
  CHECK(check.evaluate(100).max_move_ratio < 0.01);
}

TEST_CASE("generators moved to targets beyond their stars and back come back to the bit",
          "[lbfgs]") {
  Domain d;
  load_square(d);
  CVT_2::insert_generators_2(d.cdt, random_points_in_domain(d.cdt, 500, 8));
  std::vector<Cdt::Vertex_handle> vertices;
  std::vector<Point> start, targets;
  // A smooth displacement, as a quasi-Newton step is: up to 0.04 (cells are about 0.045
  // wide), zero on the boundary, one-to-one.
  const double pi = std::acos(-1.0);
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v) {
    if (d.cdt.are_there_incident_constraints(v)) continue;
    const double x = v->point().x(), y = v->point().y();
    const double length = 0.04 * std::sin(pi * x) * std::sin(pi * y), angle = 2 * pi * (x + y);
    vertices.push_back(v);
    start.push_back(v->point());
    targets.emplace_back(x + length * std::cos(angle), y + length * std::sin(angle));
  }
  std::vector<std::size_t> order(vertices.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  CVT_2::internal::Move_buffers<Cdt> stack;
  const Domain_marks marks = snapshot_marks(d.cdt);
  std::size_t beyond = 0;  // targets outside the star: reached in later passes
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto f = d.cdt.locate(targets[i]);
    beyond +=
        f->vertex(0) != vertices[i] && f->vertex(1) != vertices[i] && f->vertex(2) != vertices[i];
  }
  CHECK(beyond > 50);
  const CVT_2::internal::Face_chunks<Cdt> chunks(d.cdt);
  CHECK(CVT_2::internal::move_free_vertices(d.cdt, chunks, 0, vertices, targets, order, 8, stack) ==
        0);
  check_invariants(d.cdt, marks);  // valid and constrained Delaunay, among the rest
  CHECK(CVT_2::internal::move_free_vertices(d.cdt, chunks, 0, vertices, start, order, 8, stack) ==
        0);
  check_invariants(d.cdt, marks);
  std::size_t different = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) different += vertices[i]->point() != start[i];
  CHECK(different == 0);
}

TEST_CASE(
    "a bulk move flips chunk by chunk: small chunks, the same valid constrained Delaunay "
    "triangulation, face by face, on 1 and 2 threads",
    "[lbfgs][threads]") {
  // Chunks of 64 faces: many flips after the move touch one chunk and run on its thread, many
  // touch two and wait for the serial flips after; the county borders, constrained edges with
  // domain faces on both sides, get flips of both kinds beside them.
  std::vector<std::vector<Point>> layouts;  // each face's vertices, in memory order
  for (const unsigned threads : {1u, 2u}) {
    Domain d;
    load_domain(d, "us_kentucky_counties.poly");
    CVT_2::insert_generators_2(d.cdt, random_points_in_domain(d.cdt, 4000, 11));
    const Domain_marks marks = snapshot_marks(d.cdt);
    const CVT_2::internal::Face_chunks<Cdt> chunks(d.cdt, 64);
    REQUIRE(chunks.size() > 50);
    // The runs of each chunk hold its faces and no other.
    std::vector<CVT_2::internal::Face_runs<Cdt::Face>> runs(chunks.size());
    std::map<const Cdt::Face*, std::size_t> chunk_of;
    chunks.for_each(
        [&](std::size_t c, auto first, auto last) {
          for (auto f = first; f != last; ++f) {
            runs[c].add(&*f);
            chunk_of[&*f] = c;
          }
          runs[c].finish();
        },
        1);
    std::size_t wrong = 0;
    for (auto f = d.cdt.all_faces_begin(); f != d.cdt.all_faces_end(); ++f)
      for (std::size_t c = 0; c < chunks.size(); ++c)
        wrong += runs[c].holds(&*f) != (chunk_of[&*f] == c);
    CHECK(wrong == 0);
    CHECK(chunk_of.size() == d.cdt.tds().number_of_faces());
    // The first Lloyd step from random points: most generators move by about a cell, and
    // thousands of edges flip.
    std::vector<Cdt::Vertex_handle> vertices;
    std::vector<Point> targets;
    {
      CVT_2::Lloyd_optimizer_2<Cdt> lloyd(d.cdt);
      lloyd.evaluate(10);
      for (const auto& g : lloyd.free_generators()) {
        vertices.push_back(g.vertex);
        targets.push_back(g.centroid);
      }
    }
    std::vector<std::size_t> order(vertices.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    CVT_2::internal::Move_buffers<Cdt> buffers;
    CVT_2::internal::move_free_vertices(d.cdt, chunks, threads, vertices, targets, order, 8,
                                        buffers);
    CHECK(buffers.chunk_flips > 200);     // by the chunks on their own
    CHECK(buffers.deferred_edges > 200);  // left for after
    check_invariants(d.cdt, marks);       // valid, constrained Delaunay, each vertex in its face
    std::vector<Point> layout;
    const auto point = [&](Cdt::Vertex_handle v) {  // the infinite vertex has no point
      return d.cdt.is_infinite(v) ? Point(-1, -1) : v->point();
    };
    for (auto f = d.cdt.all_faces_begin(); f != d.cdt.all_faces_end(); ++f)
      for (int i = 0; i < 3; ++i) layout.push_back(point(f->vertex(i)));
    for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
      for (int i = 0; i < 3; ++i) layout.push_back(point(v->face()->vertex(i)));
    layouts.push_back(layout);
  }
  CHECK(layouts[0] == layouts[1]);
}

TEST_CASE("when the line search fails, the step goes back and is a Lloyd step from there",
          "[lbfgs]") {
  Domain a, b;
  load_domain(a, "square_inner_constraints.poly");
  load_domain(b, "square_inner_constraints.poly");
  const auto points = random_points_in_domain(a.cdt, 800, 9);
  CVT_2::insert_generators_2(a.cdt, points);
  CVT_2::insert_generators_2(b.cdt, points);
  const Domain_marks marks_a = snapshot_marks(a.cdt), marks_b = snapshot_marks(b.cdt);
  using Density = CVT_2::Uniform_density_2<K>;
  CVT_2::Lbfgs_optimizer_2<Cdt, Density, Rising_energy_quadrature> failing(a.cdt);
  CVT_2::Lbfgs_optimizer_2<Cdt> lloyd_steps(b.cdt, {}, {}, 0);  // no memory: Lloyd steps
  failing.evaluate(10);
  lloyd_steps.evaluate(10);
  for (int it = 0; it < 10; ++it) {
    failing.step(10);
    lloyd_steps.step(10);
    CAPTURE(it);
    check_invariants(a.cdt, marks_a, 20, it);
    check_invariants(b.cdt, marks_b, 20, it);
  }
  CHECK(failing.number_of_fallbacks() == 9);             // every step but the first, a Lloyd step
  CHECK(failing.number_of_evaluations() == 11 + 9 * 3);  // and 3 failed trials each
  // The same points, but for rounding: the moves back returned each generator to the bit,
  // the centroids are summed from another vertex of their cells.
  const auto pa = vertex_points(a.cdt), pb = vertex_points(b.cdt);
  REQUIRE(pa.size() == pb.size());
  double largest = 0;
  for (std::size_t i = 0; i < pa.size(); ++i)
    largest = std::max(largest, std::sqrt(CGAL::squared_distance(pa[i], pb[i])));
  CHECK(largest < 1e-12);
}

TEST_CASE("lbfgs_memory: 0 makes Lloyd steps, a negative value is an error that names it",
          "[lbfgs]") {
  Domain d;
  load_domain(d, "four_clusters.poly");
  const Domain_marks marks = snapshot_marks(d.cdt);
  CVT_2::Lbfgs_optimizer_2<Cdt> lloyd_steps(d.cdt, {}, {}, 0);
  lloyd_steps.evaluate(10);
  for (int it = 0; it < 5; ++it) {
    lloyd_steps.step(10);
    check_invariants(d.cdt, marks, 20, it);
  }
  CHECK(lloyd_steps.number_of_curvature_pairs() == 0);
  CHECK(lloyd_steps.number_of_evaluations() == 6);
  const auto r =
      CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::lbfgs_memory(0).number_of_iterations(3));
  CHECK(r.number_of_iterations == 3);
  CHECK_THROWS_WITH(CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::lbfgs_memory(-1)),
                    Catch::Contains("lbfgs_memory"));
  CHECK_THROWS_WITH(CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::move_ratio_bound(-1.0)),
                    Catch::Contains("move_ratio_bound"));
  check_invariants(d.cdt, marks);
}

TEST_CASE(
    "degenerate input: two generators sent to the same point, or to each other, never coincide",
    "[lbfgs][degenerate]") {
  // Each move stays inside the vertex's star, whose link the other vertex is on: the second
  // one stops short of the first, in every pass. Two free generators, each other's nearest
  // (0.18 from the others), so neighbors. (The test used to take (0.3, 0.3), a vertex of an
  // inner polyline, and so moved a constrained vertex: the invariant check caught it.)
  Cdt cdt;
  CVT_2::IO::insert_poly(cdt, CVT_2::IO::read_poly<Point>(data_path("four_clusters.poly")));
  CVT_2::insert_generators_2(cdt, std::vector<Point>{{0.62, 0.71}, {0.6, 0.7}});
  std::vector<Cdt::Vertex_handle> vertices;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (v->point() == Point(0.62, 0.71) || v->point() == Point(0.6, 0.7)) vertices.push_back(v);
  REQUIRE(vertices.size() == 2);
  REQUIRE(!cdt.are_there_incident_constraints(vertices[0]));
  REQUIRE(!cdt.are_there_incident_constraints(vertices[1]));
  REQUIRE(cdt.is_edge(vertices[0], vertices[1]));
  const std::size_t n = cdt.number_of_vertices();
  const Domain_marks marks = snapshot_marks(cdt);
  const bool swap = GENERATE(false, true);
  const std::vector<Point> targets =
      swap ? std::vector<Point>{vertices[1]->point(), vertices[0]->point()}
           : std::vector<Point>{Point(0.45, 0.5), Point(0.45, 0.5)};
  CVT_2::internal::Move_buffers<Cdt> stack;
  const std::size_t missed = CVT_2::internal::move_free_vertices(
      cdt, CVT_2::internal::Face_chunks<Cdt>(cdt), 0, vertices, targets, {0, 1}, 20, stack);
  CHECK(missed >= 1);
  CHECK(cdt.number_of_vertices() == n);
  CHECK(vertices[0]->point() != vertices[1]->point());
  CHECK(cdt.is_valid());
  CHECK(CVT_2::is_in_domain_2(cdt, vertices[0]->point()));
  CHECK(CVT_2::is_in_domain_2(cdt, vertices[1]->point()));
  check_invariants(cdt, marks);
}

namespace {

// Dense linear algebra for the quadratic f(x) = x.A x / 2 - b.x, apart from Lbfgs_history.
using Vector = std::vector<double>;
using Matrix = std::vector<Vector>;

Vector times(const Matrix& a, const Vector& x) {
  Vector y(x.size(), 0);
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j) y[i] += a[i][j] * x[j];
  return y;
}
double dot(const Vector& a, const Vector& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}
double norm(const Vector& a) { return std::sqrt(dot(a, a)); }
Vector subtract(const Vector& a, const Vector& b) {
  Vector c(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) c[i] = a[i] - b[i];
  return c;
}
Vector random_vector(std::mt19937_64& rng, std::size_t n) {
  Vector v(n);
  for (double& x : v) x = uniform(rng, -1, 1);
  return v;
}
// A^-1 b by Gaussian elimination with partial pivoting.
Vector solve(Matrix a, Vector b) {
  const std::size_t n = b.size();
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t p = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (std::abs(a[i][k]) > std::abs(a[p][k])) p = i;
    std::swap(a[k], a[p]);
    std::swap(b[k], b[p]);
    for (std::size_t i = k + 1; i < n; ++i) {
      const double f = a[i][k] / a[k][k];
      for (std::size_t j = k; j < n; ++j) a[i][j] -= f * a[k][j];
      b[i] -= f * b[k];
    }
  }
  Vector x(n);
  for (std::size_t k = n; k-- > 0;) {
    double s = b[k];
    for (std::size_t j = k + 1; j < n; ++j) s -= a[k][j] * x[j];
    x[k] = s / a[k][k];
  }
  return x;
}
// A random symmetric positive definite matrix, B^T B + I, B uniform in [-1, 1].
Matrix random_spd(std::mt19937_64& rng, std::size_t n) {
  Matrix b(n), a(n, Vector(n, 0));
  for (Vector& row : b) row = random_vector(rng, n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t k = 0; k < n; ++k) a[i][j] += b[k][i] * b[k][j];
      a[i][j] += i == j ? 1 : 0;
    }
  return a;
}
// n A-conjugate directions: random vectors, Gram-Schmidt in the A inner product.
std::vector<Vector> conjugate_directions(std::mt19937_64& rng, const Matrix& a) {
  const std::size_t n = a.size();
  std::vector<Vector> s;
  while (s.size() < n) {
    Vector v = random_vector(rng, n);
    for (const Vector& u : s) {
      const double c = dot(v, times(a, u)) / dot(u, times(a, u));
      for (std::size_t i = 0; i < n; ++i) v[i] -= c * u[i];
    }
    s.push_back(v);
  }
  return s;
}
// The pair (s, A s) into the history: from x = 0, g = 0 to x = s, g = A s.
template <class History>
bool add_pair(History& history, const Vector& s, const Vector& y) {
  const Vector zero(s.size(), 0);
  return history.add(zero, s, zero, y);
}
Vector random_h(std::mt19937_64& rng, std::size_t points) {  // a positive H0, one value a point
  Vector h(points);
  for (double& x : h) x = uniform(rng, 0.1, 10);
  return h;
}
// The L-BFGS inverse Hessian written out as a matrix (Nocedal and Wright, (7.19) and (7.20)):
// H0 = gamma diag(h), h_i for both coordinates of point i, gamma = s.y / y.diag(h) y of the
// newest pair; then H <- (I - rho s y^T) H (I - rho y s^T) + rho s s^T, rho = 1 / s.y, for
// each pair from the oldest.
Matrix inverse_hessian(const std::vector<Vector>& s, const std::vector<Vector>& y,
                       const Vector& h) {
  const std::size_t n = 2 * h.size();
  const Vector& yn = y.back();
  double yhy = 0;
  for (std::size_t j = 0; j < n; ++j) yhy += h[j / 2] * yn[j] * yn[j];
  const double gamma = dot(s.back(), yn) / yhy;
  Matrix m(n, Vector(n, 0));
  for (std::size_t j = 0; j < n; ++j) m[j][j] = gamma * h[j / 2];
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double rho = 1 / dot(s[k], y[k]);
    Matrix v(n, Vector(n, 0)), vm(n, Vector(n, 0)), next(n, Vector(n, 0));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) v[i][j] = (i == j ? 1 : 0) - rho * s[k][i] * y[k][j];
    for (std::size_t i = 0; i < n; ++i)  // V H
      for (std::size_t j = 0; j < n; ++j)
        for (std::size_t l = 0; l < n; ++l) vm[i][j] += v[i][l] * m[l][j];
    for (std::size_t i = 0; i < n; ++i)  // V H V^T + rho s s^T
      for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t l = 0; l < n; ++l) next[i][j] += vm[i][l] * v[j][l];
        next[i][j] += rho * s[k][i] * s[k][j];
      }
    m = next;
  }
  return m;
}
// max |a + b| / |b|: how far a is from -b.
double off_opposite(const Vector& a, const Vector& b) {
  double largest = 0;
  for (std::size_t j = 0; j < a.size(); ++j) largest = std::max(largest, std::abs(a[j] + b[j]));
  return largest / norm(b);
}

}  // namespace

TEST_CASE(
    "Lbfgs_history: the two-loop recursion is the BFGS update of H0 written out, and pairs "
    "along n A-conjugate directions give the Newton direction -A^-1 g, whatever H0",
    "[lbfgs][lbfgs_history]") {
  const std::size_t k = GENERATE(3, 4);      // points; n = 2k variables
  const std::size_t extra = GENERATE(0, 3);  // capacity beyond n
  const unsigned seed = 17;
  CAPTURE(k, extra, seed);
  const std::size_t n = 2 * k;
  std::mt19937_64 rng(seed + k);
  const Matrix a = random_spd(rng, n);
  const std::vector<Vector> s = conjugate_directions(rng, a);
  std::vector<Vector> y;
  CVT_2::internal::Lbfgs_history<double> history(n + extra);
  CVT_2::internal::Lbfgs_history<float> small(n + extra);  // the optimizer's: pairs as floats
  Vector d, d_small;
  for (std::size_t i = 0; i < n; ++i) {
    CAPTURE(i);
    y.push_back(times(a, s[i]));
    REQUIRE(add_pair(history, s[i], y[i]));
    REQUIRE(add_pair(small, s[i], y[i]));
    CHECK(history.size() == i + 1);
    // At any number of pairs: -H g with H the matrix of the updates, and downhill. (Rounding:
    // measured 4e-16 here, 5e-16 for the Newton direction below.)
    const Vector g = random_vector(rng, n), h = random_h(rng, k);
    CHECK(history.direction(g, h, d));
    CHECK(dot(g, d) < 0);
    // With float pairs, the same direction to float's precision (measured 1e-6), downhill.
    CHECK(small.direction(g, h, d_small));
    CHECK(norm(subtract(d_small, d)) <= 1e-5 * norm(d));
    CHECK(off_opposite(d, times(inverse_hessian({s.begin(), s.begin() + i + 1}, y, h), g)) <=
          1e-12);
    if (i + 2 == n) CHECK(off_opposite(d, solve(a, g)) > 1e-3);  // a pair short: not Newton's
  }
  for (int trial = 0; trial < 5; ++trial) {
    const Vector g = random_vector(rng, n), h = random_h(rng, k);
    CAPTURE(trial);
    REQUIRE(history.direction(g, h, d));
    CHECK(off_opposite(d, solve(a, g)) <= 1e-10);
  }
}

TEST_CASE("Lbfgs_history: L-BFGS with exact line searches minimizes a quadratic in n steps",
          "[lbfgs][lbfgs_history]") {
  const std::size_t k = GENERATE(3, 4);
  const unsigned seed = 19;
  CAPTURE(k, seed);
  const std::size_t n = 2 * k;
  std::mt19937_64 rng(seed + k);
  const Matrix a = random_spd(rng, n);
  const Vector b = random_vector(rng, n), minimum = solve(a, b);
  const Vector h = random_h(rng, k);
  CVT_2::internal::Lbfgs_history<double> history(n);
  Vector x = random_vector(rng, n), g = subtract(times(a, x), b), d(n);
  const double g0 = norm(g);
  for (std::size_t step = 0; step < n; ++step) {
    CAPTURE(step);
    CHECK(norm(g) > 1e-6 * g0);  // not there before the n-th step
    if (step == 0) {
      for (std::size_t i = 0; i < n; ++i) d[i] = -h[i / 2] * g[i];  // H0 = diag(h): the first step
    } else {
      REQUIRE(history.direction(g, h, d));
    }
    const double alpha = -dot(g, d) / dot(d, times(a, d));  // the exact line search
    Vector x1 = x;
    for (std::size_t i = 0; i < n; ++i) x1[i] += alpha * d[i];
    const Vector g1 = subtract(times(a, x1), b);
    CHECK(history.add(x, x1, g, g1));
    x = x1;
    g = g1;
  }
  CAPTURE(norm(g), g0);
  CHECK(norm(g) <= 1e-9 * g0);  // measured 2e-16, and 5e-16 for x
  CHECK(norm(subtract(x, minimum)) <= 1e-9 * norm(minimum));
}

TEST_CASE("Lbfgs_history: its passes give the same bits on any number of threads",
          "[lbfgs][lbfgs_history]") {
  const std::size_t n = 2 * 50000;  // a dozen blocks: three threads share them
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.5, 2.0);
  std::vector<double> a(n), h(n / 2);  // a diagonal quadratic, and a preconditioner
  for (double& v : a) v = u(rng);
  for (double& v : h) v = u(rng);
  const auto run = [&](unsigned threads) {
    CVT_2::internal::Lbfgs_history<float> history(5);
    history.set_number_of_threads(threads);
    std::mt19937 r(9);
    std::vector<double> x(n), g(n), x1(n), g1(n), d;
    for (std::size_t j = 0; j < n; ++j) x[j] = u(r), g[j] = a[j] * x[j];
    std::vector<std::vector<double>> directions;
    for (int k = 0; k < 8; ++k) {  // the ring fills, then turns
      for (std::size_t j = 0; j < n; ++j) x1[j] = x[j] - 0.3 * u(r) * g[j], g1[j] = a[j] * x1[j];
      REQUIRE(history.add(x, x1, g, g1));
      x.swap(x1);
      g.swap(g1);
      REQUIRE(history.direction(g, h, d));
      directions.push_back(d);
    }
    return directions;
  };
  const auto one = run(1);
  const auto first_difference = [&](const std::vector<std::vector<double>>& other) {
    for (std::size_t k = 0; k < one.size(); ++k)
      for (std::size_t j = 0; j < n; ++j)
        if (other[k][j] != one[k][j])  // the same bits, not nearly
          return "step " + std::to_string(k) + ", entry " + std::to_string(j);
    return std::string("none");
  };
  CHECK(first_difference(run(3)) == "none");
  CHECK(first_difference(run(2)) == "none");
}

TEMPLATE_TEST_CASE(
    "Lbfgs_history: a pair without positive curvature is rejected and changes nothing, "
    "whether the ring is full or not",
    "[lbfgs][lbfgs_history]", float, double) {
  using History = CVT_2::internal::Lbfgs_history<TestType>;
  const std::size_t k = 3, n = 2 * k, capacity = 3;
  std::mt19937_64 rng(23);
  const Matrix a = random_spd(rng, n);
  const std::vector<Vector> s = conjugate_directions(rng, a);
  const Vector g = random_vector(rng, n), h = random_h(rng, k);
  History history(capacity);
  // Curvature s.y < 0 (y = -A s), and s.y = 0 (y orthogonal to s).
  const Vector bad_s = random_vector(rng, n);
  Vector negative = times(a, bad_s), orthogonal = random_vector(rng, n);
  for (double& v : negative) v = -v;
  const double c = dot(orthogonal, bad_s) / dot(bad_s, bad_s);
  for (std::size_t i = 0; i < n; ++i) orthogonal[i] -= c * bad_s[i];
  REQUIRE(std::abs(dot(orthogonal, bad_s)) < 1e-14);
  Vector before, after;
  for (std::size_t pairs = 1; pairs <= capacity + 1; ++pairs) {
    CAPTURE(pairs);
    REQUIRE(add_pair(history, s[pairs - 1], times(a, s[pairs - 1])));
    CHECK(history.size() == std::min(pairs, capacity));
    REQUIRE(history.direction(g, h, before));
    for (const Vector* y : {&negative, &orthogonal}) {
      CHECK_FALSE(add_pair(history, bad_s, *y));
      CHECK(history.size() == std::min(pairs, capacity));
      REQUIRE(history.direction(g, h, after));
      CHECK(after == before);  // to the bit: no pair's vectors were touched
    }
  }
  // Full, the oldest pair left: the same direction as a history of the last `capacity` pairs.
  History last(capacity);
  for (std::size_t i = 1; i <= capacity; ++i) REQUIRE(add_pair(last, s[i], times(a, s[i])));
  Vector expected;
  REQUIRE(last.direction(g, h, expected));
  CHECK(before == expected);
}
