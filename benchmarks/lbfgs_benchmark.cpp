// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lbfgs_benchmark: L-BFGS against Lloyd iteration from the same random points: evaluations and
// time to the 1% stop, evaluations L-BFGS needs to reach the energy of K Lloyd iterations,
// serial against two threads; with CVT_2_CONVERGENCE_CSV=path, the energy against time of
// both and of CGAL's optimizer, for scripts/plot_convergence.py; with CVT_2_BENCH_LARGE=1, the
// time CGAL's optimizer takes to the 1% stop at N = 1e5.
#include "benchmark_support.h"

#include <CVT_2/Boundary_lipschitz_sizing_2.h>
#include <CVT_2/Midpoint_quadrature_2.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>

#include <CGAL/Mesh_2/Uniform_sizing_field_2.h>
#include <CGAL/lloyd_optimize_mesh_2.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

using support::CDT;
using support::CDT2;
using support::Clock;
using support::Domain;
using support::domain;
using support::fmt;
using support::hexagon;
using support::K;
using support::lipschitz_k;
using support::load_average;
using support::massachusetts;
using support::Point;
using support::since;
using support::Sizing;
using support::sizing;
using support::square;
using Shipped_move = CGAL::Mesh_2::Lloyd_move_2<CDT2, CGAL::Mesh_2::Mesh_sizing_field<CDT2>>;
using Uniform_move = CGAL::Mesh_2::Lloyd_move_2<CDT2, CGAL::Mesh_2::Uniform_sizing_field_2<CDT2>>;

namespace {

using support::nan;  // hides ::nan of <cmath>

const std::size_t lloyd_iterations[] = {20, 50, 100, 200};  // K
constexpr int number_of_ks = 4;
const std::size_t convergence_n = 10000;  // the convergence plot's cases

// A domain with a uniform density, or with the automatic k-Lipschitz sizing of its boundary.
struct Case {
  std::string domain;
  bool adaptive = false;
  std::string label() const { return adaptive ? domain + "_adaptive" : domain; }
};

// f(np) with the case's density as named parameters: none (uniform) or sizing_field(mu).
template <class F>
CVT_2::Optimization_result with_density(const Case& c, F f) {
  if (c.adaptive) return f(CVT_2::parameters::sizing_field(sizing(c.domain)));
  return f(CVT_2::parameters::default_values());
}

// (∫√ρ)², which takes the place of A² in E_norm: for large n the least energy of n generators
// is about (5/(18√3)) (∫√ρ)² / n (Fejes Tóth; Gersho). ρ = 1/μ⁴ in the adaptive cases, so
// √ρ = 1/μ², integrated by the midpoint rule on 1000 sub-triangles a domain triangle.
double squared_root_mass(const Case& c) {
  static std::map<std::string, double> cache;
  const Domain& d = domain(c.domain);
  if (!c.adaptive) return d.area * d.area;
  auto it = cache.find(c.domain);
  if (it != cache.end()) return it->second;
  const Sizing mu = sizing(c.domain);
  const auto root_density = [&mu](const Point& p) { return 1 / (mu(p) * mu(p)); };
  double mass = 0;
  for (auto f = d.cdt.finite_faces_begin(); f != d.cdt.finite_faces_end(); ++f) {
    if (!f->is_inside_domain()) continue;
    const std::array<Point, 3> t{f->vertex(0)->point(), f->vertex(1)->point(),
                                 f->vertex(2)->point()};
    mass +=
        CVT_2::Midpoint_quadrature_2<K>()(CGAL::centroid(t[0], t[1], t[2]), t, root_density, 1000)
            .mass;
  }
  return cache[c.domain] = mass * mass;
}

// The case's random points (seed 1): uniform, or with density 1/μ² in the adaptive cases,
// about the final spacing of a CVT of density 1/μ⁴ (as lloyd_adaptive starts).
std::vector<Point> initial_points(const Case& c, std::size_t n) {
  if (!c.adaptive) return support::initial_points(domain(c.domain), n);
  return support::adaptive_initial_points(c.domain, n);
}

// One point of an energy history: after `evaluation` evaluations (CGAL: iterations), `seconds`
// since the start, the raw energy of `cells` generators with a cell.
struct Sample {
  std::size_t evaluation = 0;
  double seconds = nan, energy = nan;
  std::size_t cells = 0;
  double max_move_ratio = nan;  // CGAL's samples only
};

struct Run {
  std::size_t iterations = 0, evaluations = 0;
  double seconds = nan, energy = nan;
  std::string stop;
  std::vector<Sample>
      history;                // one sample a step, the first before any move, the last at the stop
  std::vector<Point> points;  // the final vertices, in the triangulation's order
};

struct Row {
  std::size_t cells = 0;
  Run lloyd, lbfgs;                                                // to the 1% stop
  double lloyd_energy_after[number_of_ks] = {nan, nan, nan, nan};  // E after K Lloyd iterations
  std::size_t lbfgs_evaluations_to[number_of_ks] = {};  // to reach it; 0: not within the cap
  std::vector<Sample> cgal, cgal_uniform;               // CGAL's histories, for the plot
};
std::map<std::pair<std::string, std::size_t>, Row> rows;

// L-BFGS at N = 1e5 on the unit square, to the 1% stop, with one thread and with two.
struct Threads {
  std::size_t n = 0;
  Run serial, parallel;
  bool same_bits = false;
} threads;

using Callback = std::function<bool(const CVT_2::Optimization_result&)>;

// Runs `optimize` on the case's points to the 1% stop (1000 iterations at most) with
// `number_of_threads` threads (0: one per core), recording the energy after each step.
template <class Optimize>
Run run_to_stop(const Case& c, std::size_t n, Optimize optimize, std::size_t& cells,
                unsigned number_of_threads = 0) {
  CDT cdt;
  support::build_ours(cdt, domain(c.domain), initial_points(c, n));
  Run run;
  const Callback record = [&run](const CVT_2::Optimization_result& r) {
    run.history.push_back({r.number_of_evaluations, r.seconds, r.energy, 0});
    return true;
  };
  const CVT_2::Optimization_result r = with_density(c, [&](const auto& np) {
    return optimize(cdt, np.number_of_threads(number_of_threads).callback(record));
  });
  run.history.push_back({r.number_of_evaluations, r.seconds, r.energy, 0});  // the callback
  run.iterations = r.number_of_iterations;  // is not called at the stop
  run.evaluations = r.number_of_evaluations;
  run.seconds = r.seconds;
  run.energy = r.energy;
  run.stop = CVT_2::to_string(r.stop_reason);
  cells = 0;
  CVT_2::Bounded_voronoi_diagram_2<CDT>(cdt).for_each_cell(
      [&cells](auto, const auto&) { ++cells; });
  for (Sample& s : run.history) s.cells = cells;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    run.points.push_back(v->point());
  return run;
}

const auto lloyd = [](CDT& cdt, const auto& np) { return CVT_2::lloyd_optimize_2(cdt, np); };
const auto lbfgs = [](CDT& cdt, const auto& np) { return CVT_2::lbfgs_optimize_2(cdt, np); };

// Both to the 1% stop.
void bm_stop(benchmark::State& state, const Case& c) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  Row& row = rows[{c.label(), n}];
  try {
    for (auto _ : state) {
      row.lloyd = run_to_stop(c, n, lloyd, row.cells);
      row.lbfgs = run_to_stop(c, n, lbfgs, row.cells);
      state.SetIterationTime(row.lloyd.seconds + row.lbfgs.seconds);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  auto& counters = state.counters;
  counters["lloyd_evaluations"] = double(row.lloyd.evaluations);
  counters["lbfgs_evaluations"] = double(row.lbfgs.evaluations);
  counters["lloyd_s"] = row.lloyd.seconds;
  counters["lbfgs_s"] = row.lbfgs.seconds;
}

// Lloyd's energy after K = 20, 50, 100, 200 iterations; the evaluations L-BFGS needs to reach it
// (move-ratio stop off, 4 K evaluations at most).
void bm_energy(benchmark::State& state, const Case& c) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  Row& row = rows[{c.label(), n}];
  double seconds = 0;
  try {
    const Domain& d = domain(c.domain);
    const std::vector<Point> points = initial_points(c, n);
    for (auto _ : state) {
      {
        CDT cdt;
        support::build_ours(cdt, d, points);
        const auto r = with_density(c, [&](const auto& np) {
          const std::size_t k = lloyd_iterations[number_of_ks - 1];
          return CVT_2::lloyd_optimize_2(cdt, np.number_of_iterations(k).move_ratio_bound(0));
        });
        for (int k = 0; k < number_of_ks; ++k)
          row.lloyd_energy_after[k] = r.energy_history[lloyd_iterations[k]];
        seconds += r.seconds;
      }
      CDT cdt;
      support::build_ours(cdt, d, points);
      std::size_t* reached = row.lbfgs_evaluations_to;
      const double* targets = row.lloyd_energy_after;
      const auto record = [&](const CVT_2::Optimization_result& r) {
        for (int k = 0; k < number_of_ks; ++k)
          if (reached[k] == 0 && r.energy <= targets[k]) reached[k] = r.number_of_evaluations;
        const int last = number_of_ks - 1;
        return reached[last] == 0 && r.number_of_evaluations < 4 * lloyd_iterations[last];
      };
      const auto r = with_density(c, [&](const auto& np) {
        return CVT_2::lbfgs_optimize_2(cdt, np.move_ratio_bound(0).callback(Callback(record)));
      });
      record(r);  // the last evaluation, if a limit stopped it before the callback saw it
      seconds += r.seconds;
      state.SetIterationTime(seconds);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  for (int k = 0; k < number_of_ks; ++k)
    state.counters["lbfgs_evaluations_to_lloyd_" + std::to_string(lloyd_iterations[k])] =
        double(row.lbfgs_evaluations_to[k]);
}

// L-BFGS to the 1% stop on one thread and on two, from the same points: times, and whether
// the histories and the final points agree bit for bit.
void bm_threads(benchmark::State& state) {
  const Case c{square};
  threads.n = static_cast<std::size_t>(state.range(0));
  std::size_t cells = 0;
  try {
    for (auto _ : state) {
      threads.serial = run_to_stop(c, threads.n, lbfgs, cells, 1);
      threads.parallel = run_to_stop(c, threads.n, lbfgs, cells, 2);
      state.SetIterationTime(threads.serial.seconds + threads.parallel.seconds);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  const auto& h1 = threads.serial.history;
  const auto& h2 = threads.parallel.history;
  threads.same_bits = threads.serial.points == threads.parallel.points && h1.size() == h2.size();
  for (std::size_t i = 0; threads.same_bits && i < h1.size(); ++i)
    threads.same_bits = h1[i].energy == h2[i].energy && h1[i].evaluation == h2[i].evaluation;
  state.counters["serial_s"] = threads.serial.seconds;
  state.counters["two_threads_s"] = threads.parallel.seconds;
  state.counters["speed_up"] = threads.serial.seconds / threads.parallel.seconds;
}

// CGAL's optimizer from the same points, one iteration a call (so no vertex stays frozen),
// the energy and move ratios measured by our evaluator between calls and outside the time;
// until it has run `budget` seconds or 1000 iterations, or until every move ratio of its points
// is below `move_ratio_bound`.
template <class Move>
std::vector<Sample> cgal_history(const Domain& d, const std::vector<Point>& points, double budget,
                                 double move_ratio_bound = 0) {
  CDT2 cdt2;
  support::build_cdt2(cdt2, d, points);
  std::vector<Sample> history;
  const auto sample = [&](std::size_t iterations, double seconds) {
    const support::Energy e = support::measure(cdt2, d);
    history.push_back({iterations, seconds, e.energy, e.cells, e.max_move_ratio});
    return e.max_move_ratio >= move_ratio_bound;  // go on
  };
  sample(0, 0);
  auto t = Clock::now();
  CGAL::Mesh_2::Mesh_global_optimizer_2<CDT2, Move> optimizer(cdt2, 0, 0);
  optimizer.set_time_limit(0);
  optimizer.set_seeds(d.poly.holes.begin(), d.poly.holes.end(), false);
  double seconds = since(t);
  for (std::size_t i = 1; i <= 1000 && seconds < budget; ++i) {
    t = Clock::now();
    optimizer(1);
    seconds += since(t);
    if (!sample(i, seconds)) break;
  }
  return history;
}

// CGAL's optimizer with a uniform sizing (as shipped, it does not converge: see the Lloyd
// benchmark) to the paper's 1% stop at N = 1e5 on the unit square, against L-BFGS's time in
// the same run (lbfgs_stop). Its iterations cost about 0.5 s: 600 s of them at most.
struct Cgal_stop {
  std::size_t n = 100000;
  std::vector<Sample> history;
} cgal_stop;

void bm_cgal_stop(benchmark::State& state) {
  const Case c{square};
  try {
    const std::vector<Point> points = initial_points(c, cgal_stop.n);
    for (auto _ : state) {
      cgal_stop.history = cgal_history<Uniform_move>(domain(c.domain), points, 600, 0.01);
      state.SetIterationTime(cgal_stop.history.back().seconds);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  state.counters["cgal_iterations"] = double(cgal_stop.history.back().evaluation);
  state.counters["cgal_max_move_ratio"] = cgal_stop.history.back().max_move_ratio;
}

void bm_cgal_history(benchmark::State& state, const Case& c) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  Row& row = rows[{c.label(), n}];
  const double budget =
      row.lloyd.stop.empty() ? 1.0 : std::max(row.lloyd.seconds, row.lbfgs.seconds);
  try {
    const std::vector<Point> points = initial_points(c, n);
    for (auto _ : state) {
      row.cgal = cgal_history<Shipped_move>(domain(c.domain), points, budget);
      row.cgal_uniform = cgal_history<Uniform_move>(domain(c.domain), points, budget);
      state.SetIterationTime(row.cgal.back().seconds + row.cgal_uniform.back().seconds);
    }
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
  }
}

// case,method,evaluation,seconds,normalized_energy: a line a sample of each history.
bool write_convergence(const std::string& path, const std::vector<Case>& cases) {
  std::ofstream out(path);
  out << "case,method,evaluation,seconds,normalized_energy\n";
  char line[256];
  for (const Case& c : cases) {
    const auto it = rows.find({c.label(), convergence_n});
    if (it == rows.end()) continue;
    const std::string name = c.label() + "/" + std::to_string(convergence_n);
    const auto write = [&](const char* method, const std::vector<Sample>& history) {
      for (const Sample& s : history) {
        std::snprintf(line, sizeof line, "%s,%s,%zu,%.6f,%.9g\n", name.c_str(), method,
                      s.evaluation, s.seconds,
                      s.energy * double(s.cells) / squared_root_mass(c) / hexagon);
        out << line;
      }
    };
    write("lloyd", it->second.lloyd.history);
    write("lbfgs", it->second.lbfgs.history);
    write("cgal_lloyd_optimize_mesh_2", it->second.cgal);
    write("cgal_uniform_sizing", it->second.cgal_uniform);
  }
  return bool(out);
}

}  // namespace

int main(int argc, char* argv[]) {
  const std::vector<long> sizes{2000, 10000, 100000}, adaptive_sizes{2000, 10000};
  const std::vector<Case> cases{{square}, {massachusetts}, {"earcut_dude", true}};
  const std::vector<Case> convergence_cases{{square}, {massachusetts}};
  const char* csv = std::getenv("CVT_2_CONVERGENCE_CSV");
  const char* large = std::getenv("CVT_2_BENCH_LARGE");
  const bool cgal_to_stop = large && std::string(large) != "0";
  const std::string load_before = load_average();

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (const Case& c : cases)
    for (const long n : c.adaptive ? adaptive_sizes : sizes) {
      benchmark::RegisterBenchmark(("lbfgs_stop/" + c.label()).c_str(), bm_stop, c)
          ->Arg(n)
          ->Iterations(1)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark(("lbfgs_energy/" + c.label()).c_str(), bm_energy, c)
          ->Arg(n)
          ->Iterations(1)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
  benchmark::RegisterBenchmark("lbfgs_threads/unit_square", bm_threads)
      ->Arg(100000)
      ->Iterations(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond);
  if (csv)
    for (const Case& c : convergence_cases)
      benchmark::RegisterBenchmark(("lbfgs_convergence_cgal/" + c.label()).c_str(), bm_cgal_history,
                                   c)
          ->Arg(long(convergence_n))
          ->Iterations(1)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
  if (cgal_to_stop)
    benchmark::RegisterBenchmark("lbfgs_cgal_to_stop/unit_square", bm_cgal_stop)
        ->Arg(long(cgal_stop.n))
        ->Iterations(1)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  std::printf(
      "\nRandom points (seed 1), one run each, the cells on one thread per core (2 here). "
      "Uniform density: exact quadrature. Adaptive: sizing_field(mu), mu the k-Lipschitz sizing "
      "of the boundary (k = %.1f), density 1/mu^4 by the default Gauss rule (energies too), points "
      "drawn with density 1/mu^2. Evaluations: of the diagram, energy and centroids (the "
      "confirmation at the highest resolution and L-BFGS's line-search trials included). "
      "E_norm = E n / A² / (5/(18√3)), n cells; adaptive: (∫√ρ)² for A². Lloyd's energy after "
      "K iterations: E_K; L-BFGS evaluations to reach it (target: K/4 or fewer). Load average "
      "before the run: %s; after: %s.\n\n"
      "| domain | N | Lloyd to 1%%: it, evaluations, s | L-BFGS to 1%%: it, evaluations, s | "
      "evaluations Lloyd / L-BFGS | time Lloyd / L-BFGS | E_norm at 1%%: Lloyd / L-BFGS | "
      "L-BFGS evaluations to E_20 / E_50 / E_100 / E_200 |\n"
      "|---|--:|--:|--:|--:|--:|--:|--:|\n",
      lipschitz_k, load_before.c_str(), load_average().c_str());
  for (const Case& c : cases)
    for (const long n : c.adaptive ? adaptive_sizes : sizes) {
      const auto it = rows.find({c.label(), std::size_t(n)});
      if (it == rows.end()) continue;
      const Row& r = it->second;
      const auto run = [](const Run& x) {
        return x.stop.empty() ? std::string("–")
                              : std::to_string(x.iterations) + ", " +
                                    std::to_string(x.evaluations) + ", " + fmt("%.2f", x.seconds) +
                                    (x.stop == "converged" ? "" : " (" + x.stop + ")");
      };
      const auto reached = [&r](int k) {
        const std::string cap = ">" + std::to_string(4 * lloyd_iterations[number_of_ks - 1]);
        return std::isnan(r.lloyd_energy_after[k]) ? std::string("–")
               : r.lbfgs_evaluations_to[k] == 0    ? cap
                                                   : std::to_string(r.lbfgs_evaluations_to[k]);
      };
      const double norm = double(r.cells) / squared_root_mass(c) / hexagon;
      std::printf("| %s | %ld | %s | %s | %s | %s | %s / %s | %s / %s / %s / %s |\n",
                  c.label().c_str(), n, run(r.lloyd).c_str(), run(r.lbfgs).c_str(),
                  fmt("%.2f", double(r.lloyd.evaluations) / double(r.lbfgs.evaluations)).c_str(),
                  fmt("%.2f", r.lloyd.seconds / r.lbfgs.seconds).c_str(),
                  fmt("%.4f", r.lloyd.energy * norm).c_str(),
                  fmt("%.4f", r.lbfgs.energy * norm).c_str(), reached(0).c_str(),
                  reached(1).c_str(), reached(2).c_str(), reached(3).c_str());
    }
  if (threads.n > 0)
    std::printf(
        "\nL-BFGS to 1%%, unit square, N = %zu, number_of_threads 1 and 2 (same points):\n\n"
        "| N | evaluations | serial s | 2 threads s | serial / 2 threads | same bits |\n"
        "|--:|--:|--:|--:|--:|---|\n"
        "| %zu | %zu, %zu | %.2f | %.2f | %.2f | %s |\n",
        threads.n, threads.n, threads.serial.evaluations, threads.parallel.evaluations,
        threads.serial.seconds, threads.parallel.seconds,
        threads.serial.seconds / threads.parallel.seconds, threads.same_bits ? "yes" : "no");
  if (!cgal_stop.history.empty()) {
    const Sample& last = cgal_stop.history.back();
    const auto it = rows.find({Case{square}.label(), cgal_stop.n});
    const Run lbfgs = it == rows.end() ? Run() : it->second.lbfgs;
    const Run lloyd = it == rows.end() ? Run() : it->second.lloyd;
    const bool reached = last.max_move_ratio < 0.01;
    std::printf(
        "\nTo the 1%% stop, unit square, N = %zu (CGAL: uniform sizing, one iteration a call, "
        "move ratios by our evaluator outside its time, 600 s at most):\n\n"
        "| | iterations | s | / L-BFGS time |\n|---|--:|--:|--:|\n"
        "| L-BFGS | %zu | %s | 1 |\n| Lloyd | %zu | %s | %s |\n"
        "| CGAL uniform sizing | %zu%s | %s%.2f | %s%s |\n",
        cgal_stop.n, lbfgs.iterations, fmt("%.2f", lbfgs.seconds).c_str(), lloyd.iterations,
        fmt("%.2f", lloyd.seconds).c_str(), fmt("%.1f", lloyd.seconds / lbfgs.seconds).c_str(),
        last.evaluation,
        reached ? "" : (" (largest move ratio " + fmt("%.3f", last.max_move_ratio) + ")").c_str(),
        reached ? "" : "> ", last.seconds, reached ? "" : "> ",
        fmt("%.0f", last.seconds / lbfgs.seconds).c_str());
  }
  if (csv) {
    if (!write_convergence(csv, convergence_cases)) {
      std::fprintf(stderr, "lbfgs_benchmark: cannot write %s\n", csv);
      return 1;
    }
    std::printf("\nConvergence histories (N = %zu) in %s\n", convergence_n, csv);
  }
  return 0;
}
