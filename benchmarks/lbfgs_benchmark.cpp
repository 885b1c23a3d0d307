// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lbfgs_benchmark: L-BFGS against Lloyd iteration from the same random points: evaluations and
// time to the 1% stop, and evaluations L-BFGS needs to reach the energy of K Lloyd iterations.
#include <CVT_2/IO/read_poly.h>
#include <CVT_2/insert_generators_2.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>
#include <CVT_2/random_points_in_domain_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Tds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<K>,
                                                 CVT_2::Bvd_face_base_2<K>>;
using CDT = CGAL::Constrained_Delaunay_triangulation_2<
    K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag>;
using Poly = CVT_2::IO::Poly_data<Point>;

namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();
const double hexagon = 5.0 / (18.0 * std::sqrt(3.0));  // E N / A² of the hexagonal tiling
const std::string square = "unit_square", massachusetts = "us_massachusetts_counties";
const std::size_t lloyd_iterations[] = {20, 50, 100};  // K

struct Domain {
  Poly poly;
  CDT cdt;  // the domain alone, marked: for sampling and the area
  double area = 0;
};

const Domain& domain(const std::string& name) {
  static std::map<std::string, Domain> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Domain& d = cache[name];
  if (name == square) {
    d.poly.source = name;
    d.poly.vertices = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
    d.poly.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    d.poly.vertex_lines.assign(4, 0);
    d.poly.segment_lines.assign(4, 0);
  } else {
    d.poly = CVT_2::IO::read_poly<Point>(CVT_2_DATA_DIR "/" + name + ".poly");
  }
  CVT_2::IO::insert_poly(d.cdt, d.poly);
  for (auto f = d.cdt.finite_faces_begin(); f != d.cdt.finite_faces_end(); ++f)
    if (f->is_inside_domain()) d.area += d.cdt.triangle(f).area();
  return d;
}

// The domain's CDT with the random points of the case (seed 1).
void build(CDT& cdt, const Domain& d, std::size_t n) {
  CVT_2::IO::insert_poly(cdt, d.poly);
  CVT_2::insert_generators_2(cdt, CVT_2::random_points_in_domain_2(d.cdt, n, CVT_2::parameters::random_seed(1)));
}

struct Run {
  std::size_t iterations = 0, evaluations = 0;
  double seconds = nan, energy = nan;
  std::string stop;
};

struct Row {
  std::size_t cells = 0;
  Run lloyd, lbfgs;                              // to the 1% stop
  double lloyd_energy_after[3] = {nan, nan, nan};  // E after K Lloyd iterations
  std::size_t lbfgs_evaluations_to[3] = {0, 0, 0};  // to reach it; 0: not within the cap
};
std::map<std::pair<std::string, std::size_t>, Row> rows;

template <class Optimize>
Run run_to_stop(const Domain& d, std::size_t n, Optimize optimize, std::size_t& cells) {
  CDT cdt;
  build(cdt, d, n);
  const CVT_2::Lloyd_result r = optimize(cdt, CVT_2::parameters::default_values());
  Run run;
  run.iterations = r.number_of_iterations;
  run.evaluations = r.number_of_evaluations;
  run.seconds = r.seconds;
  run.energy = r.energy;
  run.stop = CVT_2::to_string(r.stop_reason);
  cells = 0;
  CVT_2::Bounded_voronoi_diagram_2<CDT>(cdt).for_each_cell([&cells](auto, const auto&) { ++cells; });
  return run;
}

// Both to the 1% stop (1000 iterations at most).
void bm_stop(benchmark::State& state, const std::string& name) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  Row& row = rows[{name, n}];
  try {
    const Domain& d = domain(name);
    for (auto _ : state) {
      row.lloyd = run_to_stop(d, n, [](CDT& cdt, const auto& np) { return CVT_2::lloyd_optimize_2(cdt, np); }, row.cells);
      row.lbfgs = run_to_stop(d, n, [](CDT& cdt, const auto& np) { return CVT_2::lbfgs_optimize_2(cdt, np); }, row.cells);
      state.SetIterationTime(row.lloyd.seconds + row.lbfgs.seconds);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  auto& c = state.counters;
  c["lloyd_evaluations"] = double(row.lloyd.evaluations);
  c["lbfgs_evaluations"] = double(row.lbfgs.evaluations);
  c["lloyd_s"] = row.lloyd.seconds;
  c["lbfgs_s"] = row.lbfgs.seconds;
}

// Lloyd's energy after K = 20, 50, 100 iterations; the evaluations L-BFGS needs to reach it
// (move-ratio stop off, 4 K evaluations at most).
void bm_energy(benchmark::State& state, const std::string& name) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  Row& row = rows[{name, n}];
  double seconds = 0;
  try {
    const Domain& d = domain(name);
    for (auto _ : state) {
      {
        CDT cdt;
        build(cdt, d, n);
        const auto r = CVT_2::lloyd_optimize_2(cdt, CVT_2::parameters::number_of_iterations(100).move_ratio_bound(0));
        for (int k = 0; k < 3; ++k) row.lloyd_energy_after[k] = r.energy_history[lloyd_iterations[k]];
        seconds += r.seconds;
      }
      CDT cdt;
      build(cdt, d, n);
      std::size_t* reached = row.lbfgs_evaluations_to;
      const double* targets = row.lloyd_energy_after;
      const auto record = [&](const CVT_2::Lloyd_result& r) {
        for (int k = 0; k < 3; ++k)
          if (reached[k] == 0 && r.energy <= targets[k]) reached[k] = r.number_of_evaluations;
        return reached[2] == 0 && r.number_of_evaluations < 4 * lloyd_iterations[2];
      };
      const auto r = CVT_2::lbfgs_optimize_2(
          cdt, CVT_2::parameters::move_ratio_bound(0).callback(
                   std::function<bool(const CVT_2::Lloyd_result&)>(record)));
      record(r);  // the last evaluation, if a limit stopped it before the callback saw it
      seconds += r.seconds;
      state.SetIterationTime(seconds);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  auto& c = state.counters;
  for (int k = 0; k < 3; ++k)
    c["lbfgs_evaluations_to_lloyd_" + std::to_string(lloyd_iterations[k])] = double(row.lbfgs_evaluations_to[k]);
}

std::string fmt(const char* f, double x) {
  if (std::isnan(x)) return "–";
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

}  // namespace

int main(int argc, char* argv[]) {
  const std::vector<long> sizes{2000, 10000, 100000};
  const std::vector<std::string> names{square, massachusetts};
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (const auto& name : names)
    for (const long n : sizes) {
      benchmark::RegisterBenchmark(("lbfgs_stop/" + name).c_str(), bm_stop, name)
          ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("lbfgs_energy/" + name).c_str(), bm_energy, name)
          ->Arg(n)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
    }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  std::printf(
      "\nUniform density, exact quadrature, random points (seed 1), one run each. Evaluations: "
      "of the diagram, energy and centroids (the confirmation at the highest resolution and "
      "L-BFGS's line-search trials included). E_norm = E n / A² / (5/(18√3)), n cells. Lloyd's "
      "energy after K iterations: E_K; L-BFGS evaluations to reach it (target: K/4 or fewer).\n\n"
      "| domain | N | Lloyd to 1%%: it, evaluations, s | L-BFGS to 1%%: it, evaluations, s | "
      "evaluations Lloyd / L-BFGS | time Lloyd / L-BFGS | E_norm at 1%%: Lloyd / L-BFGS | "
      "L-BFGS evaluations to E_20 / E_50 / E_100 |\n"
      "|---|--:|--:|--:|--:|--:|--:|--:|\n");
  for (const auto& name : names)
    for (const long n : sizes) {
      const auto it = rows.find({name, std::size_t(n)});
      if (it == rows.end()) continue;
      const Row& r = it->second;
      const auto run = [](const Run& x) {
        return x.stop.empty() ? std::string("–")
                              : std::to_string(x.iterations) + ", " + std::to_string(x.evaluations) +
                                    ", " + fmt("%.2f", x.seconds) +
                                    (x.stop == "converged" ? "" : " (" + x.stop + ")");
      };
      const auto reached = [](std::size_t e) { return e == 0 ? std::string(">400") : std::to_string(e); };
      const double norm = double(r.cells) / (domain(name).area * domain(name).area) / hexagon;
      std::printf("| %s | %ld | %s | %s | %s | %s | %s / %s | %s / %s / %s |\n", name.c_str(), n,
                  run(r.lloyd).c_str(), run(r.lbfgs).c_str(),
                  fmt("%.2f", double(r.lloyd.evaluations) / double(r.lbfgs.evaluations)).c_str(),
                  fmt("%.2f", r.lloyd.seconds / r.lbfgs.seconds).c_str(),
                  fmt("%.4f", r.lloyd.energy * norm).c_str(), fmt("%.4f", r.lbfgs.energy * norm).c_str(),
                  reached(r.lbfgs_evaluations_to[0]).c_str(), reached(r.lbfgs_evaluations_to[1]).c_str(),
                  reached(r.lbfgs_evaluations_to[2]).c_str());
    }
  return 0;
}
