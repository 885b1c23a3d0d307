// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// edit_benchmark: a crack grown through a relaxed CVT of the unit square, one cell size a step:
// our local update (Constraint_editor_2::extend_constraint, then the changed cells built)
// against CGAL's own insertion of the same vertex and constraint edge into a plain constrained
// Delaunay triangulation of the same points, and against a rebuild of the diagram (the
// triangulation and the tags from scratch). A crack that reaches x = 0.95 stops and the next
// starts 7 cells higher (that insertion is not a step).
// CVT_2_EDIT_SIZES=10000,100000 keeps those sizes (default 1e4, 1e5, 1e6); CVT_2_EDIT_STEPS
// the steps (default 1000). Times are medians over the steps, rebuilds the median of three.
#include "benchmark_support.h"

#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Constraint_editor_2.h>
#include <CVT_2/lloyd_optimize_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

using support::CDT;
using support::Clock;
using support::K;
using support::Point;
using Bvd = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using Editor = CVT_2::Constraint_editor_2<CDT>;
using Plain = CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, support::Itag>;

namespace {

double median(std::vector<double> x) {
  if (x.empty()) return std::nan("");
  std::nth_element(x.begin(), x.begin() + std::ptrdiff_t(x.size() / 2), x.end());
  return x[x.size() / 2];
}
double quantile(std::vector<double> x, double q) {
  std::sort(x.begin(), x.end());
  return x.empty() ? std::nan("") : x[std::size_t(q * double(x.size() - 1))];
}

// The cracks: polylines of `steps` steps in all, each a list of tips after its first point.
std::vector<std::vector<Point>> cracks(double h, std::size_t steps) {
  std::vector<std::vector<Point>> out;
  double y0 = 0.05;
  for (std::size_t done = 0; done < steps; y0 += 7 * h) {
    std::vector<Point> line{Point(0.05, y0)};
    for (int k = 1; 0.05 + k * h < 0.95 && done < steps; ++k, ++done)
      line.emplace_back(0.05 + k * h, y0 + 0.2 * h * std::sin(k / 7.0));
    out.push_back(line);
  }
  return out;
}

}  // namespace

int main() {
  std::vector<std::size_t> sizes{10000, 100000, 1000000};
  if (const char* s = std::getenv("CVT_2_EDIT_SIZES")) {
    sizes.clear();
    std::stringstream in(s);
    for (std::string x; std::getline(in, x, ',');) sizes.push_back(std::size_t(std::stod(x)));
  }
  const std::size_t steps = std::getenv("CVT_2_EDIT_STEPS")
                                ? std::size_t(std::atol(std::getenv("CVT_2_EDIT_STEPS")))
                                : 1000;
  std::printf("load average: %s\n", support::load_average().c_str());
  std::printf("%9s %10s %10s %8s %11s %14s %9s %9s %9s\n", "N", "step µs", "CGAL µs", "ours/CGAL",
              "rebuild s", "rebuild/step", "changed", "p90", "max");
  const auto& square = support::domain(support::square);
  for (const std::size_t n : sizes) {
    const std::vector<Point> points = support::initial_points(square, n);
    CDT cdt;
    support::build_ours(cdt, square, points);
    CVT_2::lloyd_optimize_2(cdt, CVT_2::parameters::number_of_iterations(20));
    std::vector<Point> relaxed;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      if (!cdt.are_there_incident_constraints(v)) relaxed.push_back(v->point());
    const double h = 1 / std::sqrt(double(n));
    const auto lines = cracks(h, steps);

    // ours
    Bvd bvd(cdt);
    Editor editor(cdt, bvd);
    std::vector<double> ours, changed;
    std::vector<Bvd::Cell_vertex> cell;
    std::size_t sink = 0;
    for (const auto& line : lines) {
      const auto id = editor.insert_constraint(std::vector<Point>{line[0], line[1]});
      for (std::size_t k = 2; k < line.size(); ++k) {
        const auto start = Clock::now();
        editor.extend_constraint(id, line[k]);
        for (const auto v : editor.report().changed_cells) bvd.cell(v, cell), sink += cell.size();
        ours.push_back(1e6 * support::since(start));
        changed.push_back(double(editor.report().changed_cells.size()));
      }
    }
    // CGAL's own insertion, the same points
    Plain plain;
    plain.insert_constraint(Point(0, 0), Point(1, 0));
    plain.insert_constraint(Point(1, 0), Point(1, 1));
    plain.insert_constraint(Point(1, 1), Point(0, 1));
    plain.insert_constraint(Point(0, 1), Point(0, 0));
    plain.insert(relaxed.begin(), relaxed.end());
    std::vector<double> cgal;
    for (const auto& line : lines) {
      auto last = plain.insert(line[0]);
      const auto second = plain.insert(line[1], last->face());
      plain.insert_constraint(last, second);
      last = second;
      for (std::size_t k = 2; k < line.size(); ++k) {
        const auto start = Clock::now();
        const auto v = plain.insert(line[k], last->face());
        plain.insert_constraint(last, v);
        cgal.push_back(1e6 * support::since(start));
        last = v;
      }
    }
    // rebuilds: the triangulation of the points and cracks, its domain and its tags
    std::vector<double> rebuild;
    for (int r = 0; r < 3; ++r) {
      const auto start = Clock::now();
      CDT fresh;
      support::build_ours(fresh, square, relaxed);
      for (const auto& line : lines) fresh.insert_constraint(line.begin(), line.end());
      CVT_2::mark_domain_2(fresh, std::vector<Point>());
      const Bvd b(fresh);
      sink += b.number_of_blinded_faces();
      rebuild.push_back(support::since(start));
    }
    const double step = median(ours), base = median(cgal), again = median(rebuild);
    std::printf("%9zu %10.2f %10.2f %8.2f %11.3f %14.0f %9.0f %9.0f %9.0f\n", n, step, base,
                step / base, again, 1e6 * again / step, median(changed), quantile(changed, 0.9),
                quantile(changed, 1.0));
    if (sink == 0) std::printf("?\n");
  }
  return 0;
}
