// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Oracles that share no code with what they check (support/cell_quadrature.h): the move ratios
// and centroids of converged Lloyd and L-BFGS runs recomputed from the cell polygons by an
// independent quadrature, the stop confirmed at the highest resolution, and cell sizes against
// the sizing field.
#include "support/cell_quadrature.h"
#include "support/invariants.h"
#include "support/support.h"

#include <CVT_2/Boundary_lipschitz_sizing_2.h>
#include <CVT_2/Midpoint_quadrature_2.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <vector>

using namespace support;

namespace {

constexpr double bound = 0.01;  // the default move_ratio_bound

// Lloyd or L-BFGS with the named parameters np.
template <class NP>
CVT_2::Optimization_result optimize(Cdt& cdt, bool lbfgs, const NP& np) {
  return lbfgs ? CVT_2::lbfgs_optimize_2(cdt, np) : CVT_2::lloyd_optimize_2(cdt, np);
}

}  // namespace

TEST_CASE(
    "converged runs: move ratios recomputed from the cells by an independent quadrature "
    "are below the bound, and the largest and the mean are the result's",
    "[lloyd][lbfgs][oracle]") {
  const bool lbfgs = GENERATE(false, true);
  const bool graded = GENERATE(false, true);  // uniform, or the k-Lipschitz sizing's 1/mu^4
  CAPTURE(lbfgs, graded);
  Domain d;
  load_domain(d, "earcut_dude.poly");
  const CVT_2::Boundary_lipschitz_sizing_2<K> mu(d.cdt, 0.1);
  // Initial points at about the CVT's density: 1/mu^2 generators per unit area.
  const auto start = [&mu, graded](const Point& p) { return graded ? 1 / (mu(p) * mu(p)) : 1.0; };
  CVT_2::insert_generators_2(
      d.cdt, CVT_2::random_points_in_domain_2(d.cdt, 300,
                                              CVT_2::parameters::random_seed(12).density(start)));
  const Domain_marks marks = snapshot_marks(d.cdt);
  const CVT_2::Optimization_result r =
      graded ? optimize(d.cdt, lbfgs, CVT_2::parameters::sizing_field(mu))
             : optimize(d.cdt, lbfgs, CVT_2::parameters::default_values());
  CAPTURE(r.number_of_iterations, r.max_move_ratio);
  REQUIRE(r.stop_reason == CVT_2::CONVERGED);
  check_invariants(d.cdt, marks);
  // The density written out again, 1/mu^4, and integrated by Gauss (8 x 8 points) on 16
  // sub-triangles of each fan triangle, for the sizing field's kinks (its medial axis).
  const auto rho = [&mu, graded](const Point& p) {
    const double m = graded ? mu(p) : 1.0;
    return 1 / (m * m * m * m);
  };
  const std::vector<Free_cell> cells = free_cells(d.cdt, rho, 8, graded ? 4 : 1);
  REQUIRE(cells.size() >= 300);
  double largest = 0, mean = 0;
  std::size_t above = 0;
  // Absolute, on ratios below 0.01. Uniform density: the library's closed forms, so rounding
  // (measured: equal to 8 digits). Otherwise the default Gauss rule against an oracle accurate
  // to about 5e-7 (its ratios move by 4.4e-7 with 4 times the sub-triangles and 12 x 12
  // points): measured |max - result's| <= 4e-9, |mean - result's| <= 2.9e-7 (the midpoint rule
  // at resolution 100: 2.7e-7 and 9e-8); the tolerance leaves a margin of 7 to the oracle.
  const double tolerance = graded ? 2e-6 : 1e-10;
  for (const Free_cell& c : cells) {
    largest = std::max(largest, c.move_ratio);
    mean += c.move_ratio / double(cells.size());
    above += c.move_ratio >= bound + tolerance;
  }
  CAPTURE(largest, mean, r.mean_move_ratio);
  CHECK(above == 0);
  CHECK(largest == Approx(r.max_move_ratio).margin(tolerance));
  CHECK(mean == Approx(r.mean_move_ratio).margin(tolerance));
}

TEST_CASE(
    "a Lloyd step moves each generator to the centroid of its cell as an independent "
    "quadrature finds it",
    "[lloyd][oracle]") {
  const bool graded = GENERATE(false, true);
  CAPTURE(graded);
  Domain d;
  load_domain(d, "square_inner_constraints.poly");
  const CVT_2::Boundary_lipschitz_sizing_2<K> mu(d.cdt, 0.1);
  insert_random_points(d, 400, 14);
  const Domain_marks marks = snapshot_marks(d.cdt);
  const auto rho = [&mu, graded](const Point& p) {
    const double m = graded ? mu(p) : 1.0;
    return 1 / (m * m * m * m);
  };
  // A few Lloyd steps first, so that the generators' targets are within their stars.
  const auto np = CVT_2::parameters::number_of_iterations(5).move_ratio_bound(0);
  graded ? CVT_2::lloyd_optimize_2(d.cdt, np.sizing_field(mu)) : CVT_2::lloyd_optimize_2(d.cdt, np);
  const std::vector<Free_cell> cells = free_cells(d.cdt, rho, 8, graded ? 4 : 1);
  const auto step = [&](auto& lloyd) {
    lloyd.evaluate(100);
    return lloyd.move();
  };
  std::size_t reached = 0;
  if (graded) {
    CVT_2::Lloyd_optimizer_2<
        Cdt, CVT_2::Sizing_field_density_2<K, CVT_2::Boundary_lipschitz_sizing_2<K>>>
        lloyd(d.cdt, CVT_2::make_sizing_field_density_2<K>(mu));
    reached = step(lloyd);
  } else {
    CVT_2::Lloyd_optimizer_2<Cdt> lloyd(d.cdt);
    reached = step(lloyd);
  }
  check_invariants(d.cdt, marks, 100);
  // Distances to the oracle's centroid, in cell diameters: rounding for the exact quadrature
  // (measured 3e-15); for the default Gauss rule, its error: 5.6e-5 at most, in a cell across
  // a kink of the sizing field (where its nearest segment changes), below 1e-8 in 286 of the
  // 397 cells (the midpoint rule at resolution 100: 3.4e-5 at most).
  const double tolerance = graded ? 3e-4 : 1e-12;
  std::size_t at_centroid = 0;
  double worst = 0;
  for (const Free_cell& c : cells) {
    const double off =
        std::sqrt(CGAL::squared_distance(c.vertex->point(), c.centroid)) / c.diameter;
    at_centroid += off <= tolerance;
    if (off <= 10 * tolerance) worst = std::max(worst, off);
  }
  CAPTURE(reached, at_centroid, cells.size(), worst);
  CHECK(reached > cells.size() * 9 / 10);
  CHECK(at_centroid >= reached);
}

TEST_CASE(
    "the stop is confirmed at the highest resolution: 70 small runs with a non-uniform "
    "density, and again from where they stopped, end with every move ratio below the bound",
    "[lloyd][lbfgs][oracle]") {
  // A run starts at the lowest resolution (10); a second run from converged points finds every
  // ratio below the bound there at once, and must confirm it at the highest (100) before it
  // stops: its figures are then the accurate ones.
  std::size_t restarts_at_once = 0;
  double worst = 0;
  for (unsigned seed = 1; seed <= 70; ++seed) {
    const bool lbfgs = seed % 2 == 0;  // for the second run; the first is L-BFGS, the faster
    CAPTURE(seed, lbfgs);
    Domain d;
    if (seed % 3 == 0)
      load_square(d);
    else
      load_domain(d, seed % 3 == 1 ? "square_inner_constraints.poly" : "earcut_dude.poly");
    const CGAL::Bbox_2 box = domain_bbox(d.cdt);
    const double w = box.xmax() - box.xmin(), h = box.ymax() - box.ymin();
    // Smooth, 1 to 30 across the domain, in a different direction for each seed.
    const double angle = 0.7 * seed;
    const auto rho = [box, w, h, angle](const Point& p) {
      const double u = 2 * (p.x() - box.xmin()) / w - 1, v = 2 * (p.y() - box.ymin()) / h - 1;
      const double t = 0.5 + 0.5 * (std::cos(angle) * u + std::sin(angle) * v) / std::sqrt(2.0);
      return std::exp(3.4 * t * t);
    };
    const auto sqrt_rho = [&rho](const Point& p) { return std::sqrt(rho(p)); };
    CVT_2::insert_generators_2(d.cdt, CVT_2::random_points_in_domain_2(
                                          d.cdt, 60 + 20 * (seed % 5),
                                          CVT_2::parameters::random_seed(seed).density(sqrt_rho)));
    for (int run = 0; run < 2; ++run) {
      CAPTURE(run);
      // The midpoint rule, whose resolution the schedule raises (the default rule has none).
      const auto r =
          optimize(d.cdt, run == 0 || lbfgs,
                   CVT_2::parameters::density(rho).quadrature(CVT_2::Midpoint_quadrature_2<K>()));
      REQUIRE(r.stop_reason == CVT_2::CONVERGED);
      restarts_at_once += run == 1 && r.number_of_iterations == 0;
      // The oracle: Gauss 8 x 8 on each fan triangle, exact to rounding for this smooth density
      // (16 x 16 points on 4 sub-triangles give the same ratios).
      // The midpoint rule agrees with it to 2.8e-7 at resolution 100 (measured, 140 runs), to
      // 3e-5 at resolution 10 (a stop without the confirmation): the tolerance, on ratios
      // below 0.01, leaves a margin of 18 to the first and is 6 times below the second.
      const double largest = max_move_ratio(free_cells(d.cdt, rho, 8, 1));
      const double tolerance = 5e-6;
      CAPTURE(largest, r.max_move_ratio, r.number_of_iterations);
      worst = std::max(worst, std::abs(largest - r.max_move_ratio));
      CHECK(largest < bound + tolerance);
      CHECK(largest == Approx(r.max_move_ratio).margin(tolerance));
    }
  }
  CAPTURE(worst);
  CHECK(restarts_at_once > 35);  // the path under test was taken
}

TEST_CASE(
    "under a sizing field, converged cells have its size: log diameter against log mu has "
    "slope 1",
    "[lloyd][lbfgs][sizing][oracle]") {
  const bool lbfgs = GENERATE(false, true);
  CAPTURE(lbfgs);
  Domain d;
  load_square(d);
  const auto mu = [](const Point& p) { return std::exp(std::log(10.0) * p.x()); };  // 1 to 10
  const auto start = [&mu](const Point& p) { return 1 / (mu(p) * mu(p)); };
  CVT_2::insert_generators_2(
      d.cdt, CVT_2::random_points_in_domain_2(d.cdt, 1000,
                                              CVT_2::parameters::random_seed(15).density(start)));
  const Domain_marks marks = snapshot_marks(d.cdt);
  const auto r = optimize(d.cdt, lbfgs, CVT_2::parameters::sizing_field(mu));
  CAPTURE(r.number_of_iterations);
  REQUIRE(r.stop_reason == CVT_2::CONVERGED);
  check_invariants(d.cdt, marks);
  // Least squares over the cells away from the boundary: log diameter = a + slope log mu.
  const Bvd bvd(d.cdt);
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  bvd.for_each_cell([&](Cdt::Vertex_handle v, const Cell& c) {
    if (!bvd.is_free(v)) return;
    std::vector<Point> points;
    for (const auto& cv : c) {
      if (cv.type != Bvd::Cell_vertex::CIRCUMCENTER) return;
      points.push_back(cv.point);
    }
    const double x = std::log(mu(v->point())), y = std::log(polygon_diameter(points));
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  });
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  CAPTURE(n, slope);
  // Measured 0.963 (Lloyd) and 0.972 (L-BFGS) on 884 cells; rho = 1/mu^2 gives about 0.5.
  CHECK(n > 500);
  CHECK(slope > 0.85);
  CHECK(slope < 1.15);
}
