// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// L-BFGS on the CVT energy: descent, gradient, stopping rule, determinism, speed, constraints.
#include "support/support.h"

#include <CVT_2/Exact_quadrature_2.h>
#include <CVT_2/Lbfgs_optimizer_2.h>
#include <CVT_2/internal/Face_chunks.h>
#include <CVT_2/internal/move_generators.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <map>
#include <memory>

using namespace support;

namespace {

void load_square(Domain& d) {
  d.poly = CVT_2::IO::Poly_data<Point>();
  d.poly.vertices = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
  d.poly.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  d.poly.vertex_lines.assign(4, 0);
  d.poly.segment_lines.assign(4, 0);
  CVT_2::IO::insert_poly(d.cdt, d.poly);
}

std::vector<Point> random_generators(const Domain& d, std::size_t n, unsigned seed) {
  return CVT_2::random_points_in_domain_2(d.cdt, n, CVT_2::parameters::random_seed(seed));
}

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

// The region of each free vertex: faces connected without crossing a constraint.
std::map<Cdt::Vertex_handle, int> regions(const Cdt& cdt) {
  std::map<Cdt::Face_handle, int> id;
  int next = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain() || id.count(f)) continue;
    std::vector<Cdt::Face_handle> stack{f};
    id[f] = next;
    while (!stack.empty()) {
      const auto g = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i)
        if (!g->is_constrained(i) && !id.count(g->neighbor(i))) {
          id[g->neighbor(i)] = next;
          stack.push_back(g->neighbor(i));
        }
    }
    ++next;
  }
  std::map<Cdt::Vertex_handle, int> region;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (!cdt.are_there_incident_constraints(v)) region[v] = id.at(v->face());
  return region;
}

std::vector<Point> vertex_points(const Cdt& cdt) {
  std::vector<Point> p;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) p.push_back(v->point());
  return p;
}

}  // namespace

TEST_CASE("L-BFGS never raises the energy with exact quadrature", "[lbfgs]") {
  const char* file = GENERATE("four_clusters.poly", "square_inner_constraints.poly",
                              "us_massachusetts_counties.poly", "earcut_dude.poly");
  CAPTURE(file);
  Domain d;
  load_domain(d, file);
  CVT_2::insert_generators_2(d.cdt, random_generators(d, 400, 1));
  CVT_2::Lbfgs_optimizer_2<Cdt> lbfgs(d.cdt);
  double previous = lbfgs.evaluate(10).energy;
  const double first = previous;
  std::size_t with_memory = 0;
  for (int it = 0; it < 40; ++it) {
    with_memory += lbfgs.number_of_curvature_pairs() > 0;
    const double e = lbfgs.step(10).energy;
    CAPTURE(it, previous, e);
    CHECK(e <= previous);
    previous = e;
  }
  CHECK(with_memory >= 30);  // quasi-Newton steps, not only Lloyd steps
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
    CVT_2::insert_generators_2(d.cdt, random_generators(d, 1000, 2));
  const CVT_2::Optimization_result r = CVT_2::lbfgs_optimize_2(d.cdt);
  CHECK(r.stop_reason == CVT_2::CONVERGED);
  CHECK(r.max_move_ratio < 0.01);
  REQUIRE(r.max_move_ratio_history.size() == r.number_of_iterations + 1);
  REQUIRE(r.number_of_iterations >= 1);
  CHECK(r.max_move_ratio_history[r.number_of_iterations - 1] >= 0.01);
  CHECK(r.energy == r.energy_history.back());
  CHECK(r.energy < r.energy_history.front());
  CVT_2::Lloyd_optimizer_2<Cdt> check(d.cdt);
  const auto& e = check.evaluate(100);
  CHECK(e.max_move_ratio < 0.01);
  CHECK(e.max_move_ratio == Approx(r.max_move_ratio).epsilon(1e-9));
  CHECK(e.energy == Approx(r.energy).epsilon(1e-12));
}

TEST_CASE("L-BFGS stops after the iterations asked for, or when the callback says so", "[lbfgs]") {
  Domain d;
  load_domain(d, "four_clusters.poly");
  const auto r = CVT_2::lbfgs_optimize_2(
      d.cdt, CVT_2::parameters::number_of_iterations(7).move_ratio_bound(0));
  CHECK(r.stop_reason == CVT_2::MAX_ITERATIONS_REACHED);
  CHECK(r.number_of_iterations == 7);
  CHECK(r.energy_history.size() == 8);
  const auto r2 = CVT_2::lbfgs_optimize_2(
      d.cdt, CVT_2::parameters::callback(
                 [](const CVT_2::Optimization_result& p) { return p.number_of_iterations < 3; }));
  CHECK(r2.stop_reason == CVT_2::CALLBACK_REQUESTED_STOP);
  CHECK(r2.number_of_iterations == 3);
}

TEST_CASE("the gradient 2 m (x - c) equals central differences of the energy", "[lbfgs]") {
  // Exact quadrature; each generator moves by h, far less than its distance to any constraint,
  // and the triangulation is built again from the points.
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  const std::vector<Point> points = random_generators(d, 200, 3);
  const auto energy = [&d](const std::vector<Point>& p) {
    Domain e;
    load_domain(e, "square_inner_constraints.poly");
    CVT_2::insert_generators_2(e.cdt, p);
    return CVT_2::Lloyd_optimizer_2<Cdt>(e.cdt).evaluate(1).energy;
  };
  CVT_2::insert_generators_2(d.cdt, points);
  CVT_2::Lloyd_optimizer_2<Cdt> lloyd(d.cdt);
  lloyd.evaluate(1);
  std::map<Point, CVT_2::Lloyd_optimizer_2<Cdt>::Free_generator> by_point;
  for (const auto& g : lloyd.free_generators()) by_point.emplace(g.vertex->point(), g);
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
    CVT_2::insert_generators_2(d.cdt, random_generators(d, 1500, 4));
    const auto r = CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::number_of_iterations(40));
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
    CVT_2::insert_generators_2(d.cdt, random_generators(d, 30000, 4));
    CVT_2::Lbfgs_optimizer_2<Cdt> lbfgs(d.cdt);
    lbfgs.set_number_of_threads(threads);
    REQUIRE(CVT_2::internal::Face_chunks<Cdt>(d.cdt).size() >= 12);
    std::vector<double> energies{lbfgs.evaluate(10).energy};
    for (int it = 0; it < 6; ++it) energies.push_back(lbfgs.step(10).energy);
    return std::make_pair(energies, vertex_points(d.cdt));
  };
  CHECK(steps(1) == steps(3));
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  CVT_2::insert_generators_2(d.cdt, random_generators(d, 1500, 4));
  const auto one = CVT_2::lbfgs_optimize_2(
      d.cdt, CVT_2::parameters::number_of_iterations(40).number_of_threads(1));
  CHECK(one.energy_history == a.first);
  CHECK(vertex_points(d.cdt) == a.second);
}

TEST_CASE("L-BFGS reaches Lloyd's 1% stop in fewer evaluations than Lloyd", "[lbfgs]") {
  Domain d;
  load_square(d);
  const std::vector<Point> points = random_generators(d, 2000, 5);
  std::size_t evaluations[2];
  double energies[2];
  for (int algorithm = 0; algorithm < 2; ++algorithm) {
    Domain e;
    load_square(e);
    CVT_2::insert_generators_2(e.cdt, points);
    const Counting_quadrature q;
    const auto np = CVT_2::parameters::quadrature(q);
    const auto r = algorithm == 0 ? CVT_2::lloyd_optimize_2(e.cdt, np) : CVT_2::lbfgs_optimize_2(e.cdt, np);
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
  CVT_2::insert_generators_2(d.cdt, random_generators(d, 800, 6));
  std::map<Cdt::Vertex_handle, Point> constrained;
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
    if (d.cdt.are_there_incident_constraints(v)) constrained[v] = v->point();
  const auto start = regions(d.cdt);
  const auto r =
      CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::number_of_iterations(30).move_ratio_bound(0));
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
      d.cdt, CVT_2::random_points_in_domain_2(d.cdt, 600, CVT_2::parameters::random_seed(7).density(sqrt_rho)));
  const auto r = CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::density(rho));
  CAPTURE(r.number_of_iterations, r.max_move_ratio);
  CHECK(r.stop_reason == CVT_2::CONVERGED);
  CHECK(r.energy < r.energy_history.front());
  std::size_t left = 0, right = 0;
  for (auto v = d.cdt.finite_vertices_begin(); v != d.cdt.finite_vertices_end(); ++v)
    (v->point().x() < 0.5 ? left : right) += 1;
  // Cells of size ∝ ρ^(-1/4): counts ∝ ∫ρ^(1/2), (21^1.5 - 11^1.5) / (11^1.5 - 1) = 1.68.
  CHECK(double(right) / double(left) == Approx(1.68).epsilon(0.1));
  // The final points pass an independent check at the highest resolution.
  CVT_2::Lloyd_optimizer_2<Cdt, decltype(rho)> check(d.cdt, rho);
  CHECK(check.evaluate(100).max_move_ratio < 0.01);
}

TEST_CASE("generators moved to targets beyond their stars and back come back to the bit", "[lbfgs]") {
  Domain d;
  load_square(d);
  CVT_2::insert_generators_2(d.cdt, random_generators(d, 500, 8));
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
  const auto delaunay = [&d] {
    for (auto f = d.cdt.finite_faces_begin(); f != d.cdt.finite_faces_end(); ++f)
      for (int i = 0; i < 3; ++i)
        if (d.cdt.is_flipable(f, i)) return false;
    return d.cdt.is_valid();
  };
  std::size_t beyond = 0;  // targets outside the star: reached in later passes
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto f = d.cdt.locate(targets[i]);
    beyond += f->vertex(0) != vertices[i] && f->vertex(1) != vertices[i] && f->vertex(2) != vertices[i];
  }
  CHECK(beyond > 50);
  const CVT_2::internal::Face_chunks<Cdt> chunks(d.cdt);
  CHECK(CVT_2::internal::move_free_vertices(d.cdt, chunks, 0, vertices, targets, order, 8, stack) == 0);
  CHECK(delaunay());
  CHECK(CVT_2::internal::move_free_vertices(d.cdt, chunks, 0, vertices, start, order, 8, stack) == 0);
  CHECK(delaunay());
  std::size_t different = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) different += vertices[i]->point() != start[i];
  CHECK(different == 0);
}

TEST_CASE("when the line search fails, the step goes back and is a Lloyd step from there",
          "[lbfgs]") {
  Domain a, b;
  load_domain(a, "square_inner_constraints.poly");
  load_domain(b, "square_inner_constraints.poly");
  const auto points = random_generators(a, 800, 9);
  CVT_2::insert_generators_2(a.cdt, points);
  CVT_2::insert_generators_2(b.cdt, points);
  using Density = CVT_2::Uniform_density_2<K>;
  CVT_2::Lbfgs_optimizer_2<Cdt, Density, Rising_energy_quadrature> failing(a.cdt);
  CVT_2::Lbfgs_optimizer_2<Cdt> lloyd_steps(b.cdt, {}, {}, 0);  // no memory: Lloyd steps
  failing.evaluate(10);
  lloyd_steps.evaluate(10);
  for (int it = 0; it < 10; ++it) {
    failing.step(10);
    lloyd_steps.step(10);
  }
  CHECK(failing.number_of_fallbacks() == 9);  // every step but the first, a Lloyd step
  CHECK(failing.number_of_evaluations() == 11 + 9 * 3);  // and 3 failed trials each
  // The same points, but for rounding: the moves back returned each generator to the bit,
  // the centroids are summed from another vertex of their cells.
  const auto pa = vertex_points(a.cdt), pb = vertex_points(b.cdt);
  REQUIRE(pa.size() == pb.size());
  double largest = 0;
  for (std::size_t i = 0; i < pa.size(); ++i) largest = std::max(largest, std::sqrt(CGAL::squared_distance(pa[i], pb[i])));
  CHECK(largest < 1e-12);
}

TEST_CASE("lbfgs_memory: 0 makes Lloyd steps, a negative value is an error that names it",
          "[lbfgs]") {
  Domain d;
  load_domain(d, "four_clusters.poly");
  CVT_2::Lbfgs_optimizer_2<Cdt> lloyd_steps(d.cdt, {}, {}, 0);
  lloyd_steps.evaluate(10);
  for (int it = 0; it < 5; ++it) lloyd_steps.step(10);
  CHECK(lloyd_steps.number_of_curvature_pairs() == 0);
  CHECK(lloyd_steps.number_of_evaluations() == 6);
  const auto r = CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::lbfgs_memory(0).number_of_iterations(3));
  CHECK(r.number_of_iterations == 3);
  CHECK_THROWS_WITH(CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::lbfgs_memory(-1)),
                    Catch::Contains("lbfgs_memory"));
  CHECK_THROWS_WITH(CVT_2::lbfgs_optimize_2(d.cdt, CVT_2::parameters::move_ratio_bound(-1.0)),
                    Catch::Contains("move_ratio_bound"));
}

TEST_CASE("degenerate input: two generators sent to the same point, or to each other, never coincide",
          "[lbfgs][degenerate]") {
  // Each move stays inside the vertex's star, whose link the other vertex is on: the second
  // one stops short of the first, in every pass.
  Cdt cdt;
  CVT_2::IO::insert_poly(cdt, CVT_2::IO::read_poly<Point>(data_path("four_clusters.poly")));
  CVT_2::insert_generators_2(cdt, std::vector<Point>{{0.3, 0.3}, {0.6, 0.7}});
  std::vector<Cdt::Vertex_handle> vertices;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (v->point() == Point(0.3, 0.3) || v->point() == Point(0.6, 0.7)) vertices.push_back(v);
  REQUIRE(vertices.size() == 2);
  const std::size_t n = cdt.number_of_vertices();
  const bool swap = GENERATE(false, true);
  const std::vector<Point> targets =
      swap ? std::vector<Point>{vertices[1]->point(), vertices[0]->point()}
           : std::vector<Point>{Point(0.45, 0.5), Point(0.45, 0.5)};
  CVT_2::internal::Move_buffers<Cdt> stack;
  const std::size_t missed =
      CVT_2::internal::move_free_vertices(cdt, CVT_2::internal::Face_chunks<Cdt>(cdt), 0,
                                          vertices, targets, {0, 1}, 20, stack);
  CHECK(missed >= 1);
  CHECK(cdt.number_of_vertices() == n);
  CHECK(vertices[0]->point() != vertices[1]->point());
  CHECK(cdt.is_valid());
  CHECK(CVT_2::is_in_domain_2(cdt, vertices[0]->point()));
  CHECK(CVT_2::is_in_domain_2(cdt, vertices[1]->point()));
}
