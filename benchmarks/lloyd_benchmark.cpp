// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lloyd_benchmark: our Lloyd iteration against CGAL's (lloyd_optimize_mesh_2, and its optimizer
// with a uniform sizing field) and against a plain CGAL constrained Delaunay build, on the same
// domain and the same initial points. N = 1e6 only with CVT_2_BENCH_LARGE=1.
#include "benchmark_support.h"

#include <CVT_2/Boundary_lipschitz_sizing_2.h>
#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/Gauss_quadrature_2.h>
#include <CVT_2/Sizing_field_density_2.h>
#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>

#include <CGAL/Mesh_2/Uniform_sizing_field_2.h>
#include <CGAL/lloyd_optimize_mesh_2.h>

#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

using support::build_cdt2;
using support::build_ours;
using support::CDT;
using support::CDT2;
using support::Clock;
using support::Domain;
using support::domain;
using support::Energy;
using support::fmt;
using support::Itag;
using support::K;
using support::massachusetts;
using support::measure;
using support::Point;
using support::Poly;
using support::since;
using support::square;
using support::Vb;
// The baseline: CGAL's constrained Delaunay triangulation with its default face base.
using Tds0 =
    CGAL::Triangulation_data_structure_2<Vb,
                                         CGAL::Constrained_Delaunay_triangulation_face_base_2<K>>;
using CDT0 = CGAL::Constrained_Delaunay_triangulation_2<K, Tds0, Itag>;
using Shipped_move = CGAL::Mesh_2::Lloyd_move_2<CDT2, CGAL::Mesh_2::Mesh_sizing_field<CDT2>>;
using Uniform_move = CGAL::Mesh_2::Lloyd_move_2<CDT2, CGAL::Mesh_2::Uniform_sizing_field_2<CDT2>>;
using Uniform_optimizer = CGAL::Mesh_2::Mesh_global_optimizer_2<CDT2, Uniform_move>;

namespace {

using support::nan;  // hides ::nan of <cmath>

double median(std::vector<double> v) {
  if (v.empty()) return nan;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

std::size_t iterations_for(std::size_t n) { return n >= 1000000 ? 5 : 20; }

// What a user of plain CGAL builds: vertices, constraints, points.
void build_cdt0(CDT0& cdt, const Poly& poly, const std::vector<Point>& points) {
  std::vector<CDT0::Vertex_handle> vh;
  for (const auto& p : poly.vertices) vh.push_back(cdt.insert(p));
  for (const auto& s : poly.segments) cdt.insert_constraint(vh[s[0]], vh[s[1]]);
  cdt.insert(points.begin(), points.end());
}

// Faces whose CGAL domain mark differs from our domain (0 if both rules agree).
std::size_t domain_mismatches(const CDT2& cdt, const Domain& d) {
  std::size_t m = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    m += f->is_in_domain() != CVT_2::is_in_domain_2(d.cdt, CGAL::centroid(cdt.triangle(f)));
  return m;
}

// Counts the passes of CGAL's optimizer over its moving vertices: a pass visits them in the
// order of its std::set, so a handle not after the previous one starts a new pass.
template <class Move>
struct Counting_move {
  using Sizing_field = typename Move::Sizing_field;
  Move move;
  std::size_t* passes;
  mutable CDT2::Vertex_handle last;
  typename K::Vector_2 operator()(CDT2::Vertex_handle v, const CDT2& cdt,
                                  const Sizing_field& sizing) const {
    if (last == CDT2::Vertex_handle() || !(last < v)) ++*passes;
    last = v;
    return move(v, cdt, sizing);
  }
};

const char* to_string(CGAL::Mesh_optimization_return_code c) {
  switch (c) {
    case CGAL::BOUND_REACHED:
      return "bound";
    case CGAL::TIME_LIMIT_REACHED:
      return "time";
    case CGAL::CANT_IMPROVE_ANYMORE:
      return "cant_improve";
    case CGAL::CONVERGENCE_REACHED:
      return "converged";
    case CGAL::MAX_ITERATION_NUMBER_REACHED:
      return "max_iterations";
    case CGAL::ALL_VERTICES_FROZEN:
      return "all_frozen";
    default:
      return "error";
  }
}

struct Row {
  std::size_t k = 0, cells = 0;
  double build = nan, ours = nan, cgal = nan, cgal_uniform = nan;
  Energy e0, ours_k, cgal_k, cgal_uniform_k;
  std::size_t domain_mismatch = 0;
  std::size_t ours_rises = 0, cgal_rises = 0;  // energy rises over the K iterations (N <= 1e4)
  double ours_max_rise = 0, cgal_max_rise = 0;
  std::size_t ours_conv_it = 0, cgal_conv_it = 0;
  double ours_conv_s = nan, cgal_conv_s = nan;
  std::string ours_stop, cgal_stop;
  Energy ours_conv, cgal_conv;
  double rss_cdt = nan, rss_ours = nan, rss_cgal = nan, rss_lbfgs = nan;
};
std::map<std::pair<std::string, std::size_t>, Row> rows;  // for the tables printed at the end

// Relative rises of an energy sequence: how many, and the largest.
void rises(const std::vector<double>& e, std::size_t& count, double& largest) {
  count = 0;
  largest = 0;
  for (std::size_t i = 1; i < e.size(); ++i)
    if (e[i] > e[i - 1]) ++count, largest = std::max(largest, e[i] / e[i - 1] - 1);
}

// The initial points of a case, or false after telling the benchmark why there are none.
bool load_points(benchmark::State& state, const std::string& name, std::size_t n,
                 std::vector<Point>& points) {
  try {
    points = support::initial_points(domain(name), n);
    return true;
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return false;
  }
}

// Per-iteration times: K iterations of each optimizer from the same points; a CDT build.
void bm_iteration(benchmark::State& state, const std::string& name) {
  const std::size_t n = static_cast<std::size_t>(state.range(0)), k = iterations_for(n);
  const bool uniform = n <= 100000;
  std::vector<Point> points;
  if (!load_points(state, name, n, points)) return;
  const Domain& d = domain(name);
  Row& r = rows[{name, n}];
  r.k = k;
  std::vector<double> build, ours, cgal, cgal_uniform;
  for (auto _ : state) {
    for (int rep = 0; rep < 3; ++rep) {
      const auto t = Clock::now();
      CDT0 cdt0;
      build_cdt0(cdt0, d.poly, points);
      build.push_back(since(t));
    }
    {
      CDT cdt;
      build_ours(cdt, d, points);
      const CVT_2::Optimization_result res = CVT_2::lloyd_optimize_2(
          cdt, CVT_2::parameters::number_of_iterations(k).move_ratio_bound(0));
      ours.push_back(res.seconds / double(res.number_of_iterations + 1));
      r.ours_k = measure(cdt, d);
      rises(res.energy_history, r.ours_rises, r.ours_max_rise);
    }
    {
      CDT2 cdt2;
      build_cdt2(cdt2, d, points);
      const auto t = Clock::now();
      CGAL::lloyd_optimize_mesh_2(
          cdt2, CGAL::parameters::max_iteration_number = int(k), CGAL::parameters::convergence = 0,
          CGAL::parameters::freeze_bound = 0, CGAL::parameters::seeds_begin = d.poly.holes.begin(),
          CGAL::parameters::seeds_end = d.poly.holes.end());
      cgal.push_back(since(t) / double(k));
      r.cgal_k = measure(cdt2, d);
      r.domain_mismatch = domain_mismatches(cdt2, d);
    }
    if (uniform) {
      CDT2 cdt2;
      build_cdt2(cdt2, d, points);
      const auto t = Clock::now();
      Uniform_optimizer optimizer(cdt2, 0, 0);
      optimizer.set_time_limit(0);
      optimizer.set_seeds(d.poly.holes.begin(), d.poly.holes.end(), false);
      optimizer(int(k));
      cgal_uniform.push_back(since(t) / double(k));
      r.cgal_uniform_k = measure(cdt2, d);
    }
    state.SetIterationTime(build.back() + (ours.back() + cgal.back()) * double(k) +
                           (uniform ? cgal_uniform.back() * double(k) : 0));
  }
  r.build = median(build);
  r.ours = median(ours);
  r.cgal = median(cgal);
  r.cgal_uniform = median(cgal_uniform);
  {
    CDT cdt;
    build_ours(cdt, d, points);
    r.e0 = measure(cdt, d);
    r.cells = r.e0.cells;
  }
  if (n <= 10000) {  // CGAL's energy after each iteration: one call per iteration, same moves
    CDT2 cdt2;
    build_cdt2(cdt2, d, points);
    CGAL::Mesh_2::Mesh_global_optimizer_2<CDT2, Shipped_move> optimizer(cdt2, 0, 0);
    optimizer.set_time_limit(0);
    optimizer.set_seeds(d.poly.holes.begin(), d.poly.holes.end(), false);
    std::vector<double> history{measure(cdt2, d).energy};
    for (std::size_t i = 0; i < k; ++i) {
      optimizer(1);
      history.push_back(measure(cdt2, d).energy);
    }
    rises(history, r.cgal_rises, r.cgal_max_rise);
  }
  auto& c = state.counters;
  c["N"] = double(n);
  c["K"] = double(k);
  c["cdt_build_s"] = r.build;
  c["ours_s/it"] = r.ours;
  c["cgal_s/it"] = r.cgal;
  c["cgal_uniform_s/it"] = r.cgal_uniform;
  c["ours/cdt"] = r.ours / r.build;
  c["cgal/ours"] = r.cgal / r.ours;
  c["E0_norm"] = r.e0.normalized;
  c["ours_EK_norm"] = r.ours_k.normalized;
  c["cgal_EK_norm"] = r.cgal_k.normalized;
  c["cgal_uniform_EK_norm"] = r.cgal_uniform_k.normalized;
}

// Time to converge: ours with its defaults (300 iterations at most from 1e5), CGAL's as shipped.
void bm_converge(benchmark::State& state, const std::string& name) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  std::vector<Point> points;
  if (!load_points(state, name, n, points)) return;
  const Domain& d = domain(name);
  Row& r = rows[{name, n}];
  for (auto _ : state) {
    double seconds = 0;
    {
      CDT cdt;
      build_ours(cdt, d, points);
      const CVT_2::Optimization_result res =
          n >= 100000 ? CVT_2::lloyd_optimize_2(cdt, CVT_2::parameters::number_of_iterations(300))
                      : CVT_2::lloyd_optimize_2(cdt);
      r.ours_conv_it = res.number_of_iterations;
      r.ours_conv_s = res.seconds;
      r.ours_stop = CVT_2::to_string(res.stop_reason);
      seconds += res.seconds;
      r.ours_conv = measure(cdt, d);
    }
    if (n <= 10000) {
      // lloyd_optimize_mesh_2() with its defaults, spelled out to count its passes.
      CDT2 cdt2;
      build_cdt2(cdt2, d, points);
      std::size_t passes = 0;
      const auto t = Clock::now();
      CGAL::Mesh_2::Mesh_global_optimizer_2<CDT2, Counting_move<Shipped_move>> optimizer(
          cdt2, 0.001, 0.001, Counting_move<Shipped_move>{Shipped_move(), &passes, {}});
      optimizer.set_time_limit(0);
      optimizer.set_seeds(d.poly.holes.begin(), d.poly.holes.end(), false);
      const CGAL::Mesh_optimization_return_code code = optimizer(1000);
      r.cgal_conv_s = since(t);
      seconds += r.cgal_conv_s;
      // The last pass only found the moves small (or the vertices frozen): no move followed.
      r.cgal_conv_it = code == CGAL::MAX_ITERATION_NUMBER_REACHED ? passes : passes - 1;
      r.cgal_stop = to_string(code);
      r.cgal_conv = measure(cdt2, d);
    }
    state.SetIterationTime(seconds);
  }
  auto& c = state.counters;
  c["N"] = double(n);
  c["ours_iterations"] = double(r.ours_conv_it);
  c["ours_s"] = r.ours_conv_s;
  c["ours_E_norm"] = r.ours_conv.normalized;
  if (n <= 10000) {
    c["cgal_iterations"] = double(r.cgal_conv_it);
    c["cgal_s"] = r.cgal_conv_s;
    c["cgal_E_norm"] = r.cgal_conv.normalized;
  }
}

// The paper's Fig. 10 case: a curved domain with a hole, 2000 points, uniform and adaptive
// (k-Lipschitz sizing, k = 0.1) density, each run to the 1% stop; CGAL's optimizer as shipped
// from the same points. The paper reports 7 s uniform and 80 s adaptive.
struct Figure10 {
  double lloyd_uniform = nan, lloyd_adaptive = nan, lbfgs_uniform = nan, lbfgs_adaptive = nan;
  double cgal = nan, per_it_uniform = nan, per_it_adaptive = nan;
  std::size_t it_uniform = 0, it_adaptive = 0, it_lbfgs_uniform = 0, it_lbfgs_adaptive = 0;
  std::string stops;
} figure10;

void bm_figure10(benchmark::State& state) {
  const std::string name = "bubble_with_hole";
  std::vector<Point> points;
  if (!load_points(state, name, 2000, points)) return;
  const Domain& d = domain(name);
  const support::Sizing& mu = support::sizing(name);
  Figure10& f = figure10;
  for (auto _ : state) {
    double seconds = 0;
    const auto run = [&](auto optimize, const auto& np, double& time, std::size_t& iterations) {
      CDT cdt;
      build_ours(cdt, d, points);
      const CVT_2::Optimization_result r = optimize(cdt, np);
      time = r.seconds;
      iterations = r.number_of_iterations;
      seconds += r.seconds;
      f.stops += std::string(f.stops.empty() ? "" : ", ") + CVT_2::to_string(r.stop_reason);
    };
    const auto lloyd = [](CDT& cdt, const auto& np) { return CVT_2::lloyd_optimize_2(cdt, np); };
    const auto lbfgs = [](CDT& cdt, const auto& np) { return CVT_2::lbfgs_optimize_2(cdt, np); };
    f.stops.clear();
    run(lloyd, CVT_2::parameters::default_values(), f.lloyd_uniform, f.it_uniform);
    run(lloyd, CVT_2::parameters::sizing_field(mu), f.lloyd_adaptive, f.it_adaptive);
    run(lbfgs, CVT_2::parameters::default_values(), f.lbfgs_uniform, f.it_lbfgs_uniform);
    run(lbfgs, CVT_2::parameters::sizing_field(mu), f.lbfgs_adaptive, f.it_lbfgs_adaptive);
    f.per_it_uniform = f.lloyd_uniform / double(f.it_uniform + 2);
    f.per_it_adaptive = f.lloyd_adaptive / double(f.it_adaptive + 2);
    CDT2 cdt2;  // lloyd_optimize_mesh_2() with its defaults
    build_cdt2(cdt2, d, points);
    const auto t = Clock::now();
    CGAL::lloyd_optimize_mesh_2(cdt2, CGAL::parameters::max_iteration_number = 1000,
                                CGAL::parameters::seeds_begin = d.poly.holes.begin(),
                                CGAL::parameters::seeds_end = d.poly.holes.end());
    f.cgal = since(t);
    seconds += f.cgal;
    state.SetIterationTime(seconds);
  }
  state.counters["lloyd_uniform_s"] = f.lloyd_uniform;
  state.counters["lloyd_adaptive_s"] = f.lloyd_adaptive;
  state.counters["cgal_s"] = f.cgal;
}

// An adaptive Lloyd iteration against a uniform one on the same domain and points, at equal
// accuracy: the adaptive run goes to the 1% stop, then each free cell's move ratio is computed
// again with an accurate quadrature of the same density.
struct Adaptive_row {
  std::string name;
  std::size_t n = 0, adaptive_iterations = 0, cells = 0, over = 0;
  std::size_t runs = 0;                      // of each, interleaved
  double uniform_s = nan, adaptive_s = nan;  // per evaluation, medians, all cores
  double uniform_1 = nan, adaptive_1 = nan;  // the same on one thread
  double max_ratio = nan, accurate_max_ratio = nan, max_error = nan;
  std::string stop;
};
std::vector<Adaptive_row> adaptive_rows;

struct Fan_moments {
  double mass = 0, mx = 0, my = 0;
  void operator+=(const Fan_moments& o) { mass += o.mass, mx += o.mx, my += o.my; }
};
// Radon's rule on triangle t (coordinates relative to x): the default rule, whose fan from a
// corner of t is t itself, its first moment moved from that corner to x.
template <class Rho>
Fan_moments radon(const std::array<double, 6>& t, const Point& x, const Rho& rho) {
  const Point a(x.x() + t[0], x.y() + t[1]);
  const std::array<Point, 3> corners{a, Point(x.x() + t[2], x.y() + t[3]),
                                     Point(x.x() + t[4], x.y() + t[5])};
  const auto m = CVT_2::Gauss_quadrature_2<K>()(a, corners, rho, 0);
  return {m.mass, m.first_moment.x() + m.mass * t[0], m.first_moment.y() + m.mass * t[1]};
}
// The moments of t under rho: Radon's rule on t and on its four halves, recursively where the
// two differ by more than the tolerances (shared out by area), to depth 10.
template <class Rho>
Fan_moments accurate(const std::array<double, 6>& t, const Point& x, const Rho& rho,
                     const Fan_moments& whole, double mass_tol, double moment_tol, int depth) {
  const auto mid = [&](int i, int j) {
    return std::array<double, 2>{(t[i] + t[j]) / 2, (t[i + 1] + t[j + 1]) / 2};
  };
  const auto ab = mid(0, 2), bc = mid(2, 4), ca = mid(4, 0);
  const std::array<std::array<double, 6>, 4> parts{{{t[0], t[1], ab[0], ab[1], ca[0], ca[1]},
                                                    {ab[0], ab[1], t[2], t[3], bc[0], bc[1]},
                                                    {ca[0], ca[1], bc[0], bc[1], t[4], t[5]},
                                                    {ab[0], ab[1], bc[0], bc[1], ca[0], ca[1]}}};
  std::array<Fan_moments, 4> m;
  Fan_moments sum;
  for (int i = 0; i < 4; ++i) sum += m[i] = radon(parts[i], x, rho);
  if (depth == 10 ||
      (std::abs(sum.mass - whole.mass) <= mass_tol && std::abs(sum.mx - whole.mx) <= moment_tol &&
       std::abs(sum.my - whole.my) <= moment_tol))
    return sum;
  Fan_moments out;
  for (int i = 0; i < 4; ++i)
    out += accurate(parts[i], x, rho, m[i], mass_tol / 4, moment_tol / 4, depth + 1);
  return out;
}

// Adaptive against uniform Lloyd, both to the 1% stop from the same points (uniform ones for
// the Fig. 10 case, density 1/μ² on earcut_dude), then the accuracy check.
void bm_adaptive(benchmark::State& state, const std::string& name) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const bool fig10 = name == "bubble_with_hole";
  std::vector<Point> points;
  try {
    points = fig10 ? support::initial_points(domain(name), n)
                   : support::adaptive_initial_points(name, n);
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  const Domain& d = domain(name);
  const support::Sizing& mu = support::sizing(name);
  Adaptive_row row;
  row.name = name;
  row.n = n;
  // Runs of a few seconds are timed several times, uniform and adaptive in turn, on all cores
  // and on one thread; the medians of seconds per evaluation.
  row.runs = n <= 10000 ? 5 : 1;
  std::vector<double> uniform_s, adaptive_s, uniform_1, adaptive_1;
  for (auto _ : state) {
    CDT adaptive;
    CVT_2::Optimization_result a;
    double seconds = 0;
    try {
      for (std::size_t run = 0; run < 2 * row.runs; ++run) {
        const unsigned threads = run < row.runs ? 0 : 1;
        CDT uniform;
        build_ours(uniform, d, points);
        const auto u = CVT_2::lloyd_optimize_2(
            uniform, CVT_2::parameters::default_values().number_of_threads(threads));
        CDT fresh;
        build_ours(fresh, d, points);
        a = CVT_2::lloyd_optimize_2(fresh,
                                    CVT_2::parameters::sizing_field(mu).number_of_threads(threads));
        adaptive.swap(fresh);  // the last run's result is checked below
        seconds += u.seconds + a.seconds;
        (threads == 0 ? uniform_s : uniform_1)
            .push_back(u.seconds / double(u.number_of_evaluations));
        (threads == 0 ? adaptive_s : adaptive_1)
            .push_back(a.seconds / double(a.number_of_evaluations));
      }
    } catch (const std::exception& e) {
      state.SkipWithError(e.what());
      return;
    }
    state.SetIterationTime(seconds);
    row.uniform_s = median(uniform_s);
    row.adaptive_s = median(adaptive_s);
    row.uniform_1 = median(uniform_1);
    row.adaptive_1 = median(adaptive_1);
    row.adaptive_iterations = a.number_of_iterations;
    row.stop = CVT_2::to_string(a.stop_reason);
    row.max_ratio = a.max_move_ratio;
    // each free cell again, with Radon's rule refined until the mass and first moment change
    // by less than 1e-8 of the cell's (the same density, restricted to the cell's disk)
    row.accurate_max_ratio = row.max_error = 0;
    const CVT_2::Bounded_voronoi_diagram_2<CDT> bvd(adaptive);
    const auto density = CVT_2::make_sizing_field_density_2<K>(mu);
    bvd.for_each_cell([&](CDT::Vertex_handle v, const auto& cell) {
      std::vector<Point> q;
      for (const auto& c : cell) {
        if (c.type == std::decay_t<decltype(c)>::GENERATOR) return;  // not free
        q.push_back(c.point);
      }
      const Point& x = v->point();
      double r2 = 0, diameter2 = 0;
      for (const Point& p : q) {
        r2 = std::max(r2, CGAL::squared_distance(x, p));
        for (const Point& o : q) diameter2 = std::max(diameter2, CGAL::squared_distance(p, o));
      }
      const auto rho = density.restrict_to_disk(x, std::sqrt(r2) * (1 + 1e-9));
      std::vector<std::array<double, 6>> fan;
      Fan_moments coarse, fine;
      for (std::size_t i = 0; i < q.size(); ++i) {
        const Point &p = q[i], &o = q[(i + 1) % q.size()];
        fan.push_back({0, 0, p.x() - x.x(), p.y() - x.y(), o.x() - x.x(), o.y() - x.y()});
        coarse += radon(fan.back(), x, rho);
      }
      double area = 0;
      for (const auto& t : fan) area += std::abs(t[2] * t[5] - t[3] * t[4]) / 2;
      for (const auto& t : fan) {
        const double share = 1e-8 * std::abs(t[2] * t[5] - t[3] * t[4]) / 2 / area;
        fine += accurate(t, x, rho, radon(t, x, rho), share * coarse.mass,
                         share * coarse.mass * std::sqrt(r2), 0);
      }
      const double diameter = std::sqrt(diameter2);
      const double ratio = std::hypot(fine.mx, fine.my) / fine.mass / diameter;
      const double error = std::hypot(fine.mx / fine.mass - coarse.mx / coarse.mass,
                                      fine.my / fine.mass - coarse.my / coarse.mass) /
                           diameter;
      row.accurate_max_ratio = std::max(row.accurate_max_ratio, ratio);
      row.max_error = std::max(row.max_error, error);
      row.over += ratio >= 0.01;
      ++row.cells;
    });
  }
  state.counters["adaptive_over_uniform"] = row.adaptive_s / row.uniform_s;
  adaptive_rows.push_back(row);
}

// Peak resident memory of `work`, run in a child forked while this process is still small
// (a child starts from its parent's resident size, so this comes before any benchmark).
double peak_rss_mb(const std::function<void()>& work) {
  int fd[2];
  if (pipe(fd) != 0) return nan;
  const pid_t pid = fork();
  if (pid < 0) return nan;
  if (pid == 0) {
    close(fd[0]);
    double mb = nan;
    try {
      work();
      rusage ru{};
      getrusage(RUSAGE_SELF, &ru);
      mb = double(ru.ru_maxrss) / 1024;
    } catch (...) {
    }
    if (write(fd[1], &mb, sizeof mb) != sizeof mb) _exit(1);
    _exit(0);
  }
  close(fd[1]);
  double mb = nan;
  if (read(fd[0], &mb, sizeof mb) != sizeof mb) mb = nan;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  return mb;
}

void measure_memory(const std::string& name, std::size_t n, bool with_cgal = true) {
  Row& r = rows[{name, n}];
  r.rss_cdt = peak_rss_mb([&] {
    const Domain& d = domain(name);
    const std::vector<Point> points = support::initial_points(d, n);
    CDT0 cdt0;
    build_cdt0(cdt0, d.poly, points);
  });
  // our build, then optimize(cdt)
  const auto ours = [&](const auto& optimize) {
    return peak_rss_mb([&] {
      const Domain& d = domain(name);
      std::vector<Point> points = support::initial_points(d, n);
      CDT cdt;
      build_ours(cdt, d, points);
      std::vector<Point>().swap(points);  // the harness's input, not the optimizer's memory
      optimize(cdt);
    });
  };
  r.rss_ours = ours([](CDT& cdt) {
    CVT_2::lloyd_optimize_2(cdt, CVT_2::parameters::number_of_iterations(5).move_ratio_bound(0));
  });
  r.rss_lbfgs = ours([](CDT& cdt) {  // 12 steps: the ring of 7 curvature pairs is full from step 8
    CVT_2::lbfgs_optimize_2(cdt, CVT_2::parameters::number_of_iterations(12).move_ratio_bound(0));
  });
  if (with_cgal)
    r.rss_cgal = peak_rss_mb([&] {
      const Domain& d = domain(name);
      const std::vector<Point> points = support::initial_points(d, n);
      CDT2 cdt2;
      build_cdt2(cdt2, d, points);
      CGAL::lloyd_optimize_mesh_2(
          cdt2, CGAL::parameters::max_iteration_number = 5, CGAL::parameters::convergence = 0,
          CGAL::parameters::freeze_bound = 0, CGAL::parameters::seeds_begin = d.poly.holes.begin(),
          CGAL::parameters::seeds_end = d.poly.holes.end());
    });
}

// One thread against two: K Lloyd iterations or L-BFGS steps on the unit square from the same
// points, in pairs (1 then 2 threads), the time an evaluation; both must give the same bits.
struct Threads_row {
  std::size_t k = 0, evaluations = 0;
  std::vector<double> one, two;  // seconds an evaluation, pair by pair
  bool same_bits = true;
};
std::map<std::pair<std::string, std::size_t>, Threads_row> threads_rows;

void bm_threads(benchmark::State& state, const std::string& algorithm) {
  const std::size_t n = static_cast<std::size_t>(state.range(0)), k = n >= 1000000 ? 9 : 40;
  std::vector<Point> points;
  if (!load_points(state, square, n, points)) return;
  const Domain& d = domain(square);
  Threads_row& r = threads_rows[{algorithm, n}];
  r.k = k;
  for (auto _ : state) {
    double seconds = 0;
    std::vector<Point> first_points;
    std::vector<double> first_energies;
    for (const unsigned threads : {1u, 2u}) {
      CDT cdt;
      build_ours(cdt, d, points);
      const auto np =
          CVT_2::parameters::number_of_iterations(k).move_ratio_bound(0).number_of_threads(threads);
      const CVT_2::Optimization_result res = algorithm == "lloyd"
                                                 ? CVT_2::lloyd_optimize_2(cdt, np)
                                                 : CVT_2::lbfgs_optimize_2(cdt, np);
      seconds += res.seconds;
      r.evaluations = res.number_of_evaluations;
      (threads == 1 ? r.one : r.two).push_back(res.seconds / double(res.number_of_evaluations));
      std::vector<Point> final_points;
      for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
        final_points.push_back(v->point());
      if (threads == 1) {
        first_points = std::move(final_points);
        first_energies = res.energy_history;
      } else {
        r.same_bits =
            r.same_bits && final_points == first_points && res.energy_history == first_energies;
      }
    }
    state.SetIterationTime(seconds);
  }
  state.counters["speed_up"] = median(r.one) / median(r.two);
}

}  // namespace

int main(int argc, char* argv[]) {
  const char* large_env = std::getenv("CVT_2_BENCH_LARGE");
  const bool large = large_env && std::string(large_env) == "1";
  // CVT_2_BENCH_MEMORY=N adds the memory of N generators on the unit square (no timing)
  const char* memory_env = std::getenv("CVT_2_BENCH_MEMORY");
  const std::size_t memory_n = memory_env ? std::size_t(std::strtoull(memory_env, nullptr, 10)) : 0;
  std::vector<long> sizes{2000, 10000, 100000};
  if (large) sizes.push_back(1000000);
  const std::vector<std::string> names{square, massachusetts};

  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  rusage ru{};
  getrusage(RUSAGE_SELF, &ru);
  const double baseline_mb = double(ru.ru_maxrss) / 1024;
  for (const auto& name : names)
    for (const long n : sizes)
      if (n >= 100000) measure_memory(name, std::size_t(n));
  if (memory_n > 0) measure_memory(square, memory_n, false);  // CGAL's would take an hour

  for (const auto& name : names)
    for (const long n : sizes)
      benchmark::RegisterBenchmark(("lloyd_iteration/" + name).c_str(), bm_iteration, name)
          ->Arg(n)
          ->Iterations(n <= 10000    ? 5
                       : n <= 100000 ? 3
                                     : 1)
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
  for (const auto& name : names)
    for (const long n : sizes)
      if (n < 1000000)
        benchmark::RegisterBenchmark(("lloyd_converge/" + name).c_str(), bm_converge, name)
            ->Arg(n)
            ->Iterations(1)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
  for (const char* algorithm : {"lloyd", "lbfgs"})
    for (const long n : sizes)
      if (n >= 100000)
        benchmark::RegisterBenchmark((std::string("threads_") + algorithm + "/unit_square").c_str(),
                                     bm_threads, std::string(algorithm))
            ->Arg(n)
            ->Iterations(n >= 1000000 ? 3 : 5)
            ->UseManualTime()
            ->Unit(benchmark::kMillisecond);
  for (const auto& [name, n] : std::vector<std::pair<std::string, long>>{
           {"bubble_with_hole", 2000}, {"earcut_dude", 10000}, {"earcut_dude", 100000}})
    benchmark::RegisterBenchmark(("lloyd_adaptive/" + name).c_str(), bm_adaptive, name)
        ->Arg(n)
        ->UseManualTime()
        ->Iterations(1)
        ->Unit(benchmark::kSecond);
  benchmark::RegisterBenchmark("lloyd_figure10/bubble_with_hole", bm_figure10)
      ->Iterations(1)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  std::printf(
      "\nK = 20 iterations (5 at N = 1e6) from the same random points (seed 1). ours s/it = "
      "seconds / (K+1) evaluations; CGAL s/it = seconds / K. E_norm = E n / A² / (5/(18√3)), "
      "n = generators with a cell incl. constrained vertices, energies by our evaluator; for "
      "Massachusetts E_norm is indicative only, compare raw E via CGAL E / ours E. "
      "Convergence: ours mr < 0.01 (300 iterations at most at 1e5); CGAL as shipped "
      "(convergence 0.001, freeze 0.001). RSS: peak of a child process (baseline %.1f MB) "
      "running the build, or the build and 5 iterations.\n\n",
      baseline_mb);
  std::printf(
      "| domain | N | n cells | cdt build s | ours s/it | ours/cdt | CGAL s/it | CGAL/ours | "
      "CGAL uniform s/it | ours to mr<0.01: it, s, stop | E_norm initial | ours E_norm K / conv "
      "| CGAL E_norm K / uniform K | CGAL E / ours E (K) | CGAL conv: it, s, stop, E_norm | "
      "peak RSS MB cdt / ours / CGAL |\n"
      "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
  for (const auto& name : names)
    for (const long n : sizes) {
      const auto it = rows.find({name, std::size_t(n)});
      if (it == rows.end()) continue;
      const Row& r = it->second;
      const std::string ours_conv = r.ours_stop.empty()
                                        ? "–"
                                        : std::to_string(r.ours_conv_it) + ", " +
                                              fmt("%.3f", r.ours_conv_s) + ", " + r.ours_stop;
      const std::string cgal_conv =
          r.cgal_stop.empty() ? "–"
                              : std::to_string(r.cgal_conv_it) + ", " + fmt("%.3f", r.cgal_conv_s) +
                                    ", " + r.cgal_stop + ", " + fmt("%.4f", r.cgal_conv.normalized);
      std::printf(
          "| %s | %ld | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s / %s | %s / %s | %s | "
          "%s | %s / %s / %s |\n",
          name.c_str(), n, r.cells, fmt("%.4f", r.build).c_str(), fmt("%.4f", r.ours).c_str(),
          fmt("%.2f", r.ours / r.build).c_str(), fmt("%.4f", r.cgal).c_str(),
          fmt("%.1f", r.cgal / r.ours).c_str(), fmt("%.4f", r.cgal_uniform).c_str(),
          ours_conv.c_str(), fmt("%.4f", r.e0.normalized).c_str(),
          fmt("%.4f", r.ours_k.normalized).c_str(), fmt("%.4f", r.ours_conv.normalized).c_str(),
          fmt("%.4f", r.cgal_k.normalized).c_str(),
          fmt("%.4f", r.cgal_uniform_k.normalized).c_str(),
          fmt("%.4f", r.cgal_k.energy / r.ours_k.energy).c_str(), cgal_conv.c_str(),
          fmt("%.0f", r.rss_cdt).c_str(), fmt("%.0f", r.rss_ours).c_str(),
          fmt("%.0f", r.rss_cgal).c_str());
    }
  std::printf(
      "\nPeak memory (RSS of a child process, baseline %.1f MB): a plain CGAL CDT build of the "
      "points; ours: the build and 5 Lloyd iterations, or 12 L-BFGS steps (its 7 curvature "
      "pairs kept from step 8); CGAL's lloyd_optimize_mesh_2, 5 iterations. Bytes a generator "
      "and the ratio to the CDT build.\n\n"
      "| domain | N | CDT MB | CDT B/gen | Lloyd B/gen | Lloyd / CDT | L-BFGS B/gen | "
      "L-BFGS / CDT | CGAL / CDT |\n|---|--:|--:|--:|--:|--:|--:|--:|--:|\n",
      baseline_mb);
  for (const auto& [key, r] : rows) {
    if (!(r.rss_cdt > 0)) continue;
    const double per = 1048576.0 / double(key.second);  // MB to bytes a generator
    std::printf("| %s | %zu | %.0f | %.0f | %.0f | %.2f | %.0f | %.2f | %s |\n", key.first.c_str(),
                key.second, r.rss_cdt, r.rss_cdt * per, r.rss_ours * per, r.rss_ours / r.rss_cdt,
                r.rss_lbfgs * per, r.rss_lbfgs / r.rss_cdt,
                fmt("%.2f", r.rss_cgal / r.rss_cdt).c_str());
  }
  if (!threads_rows.empty()) {
    std::printf(
        "\nOne thread against two (number_of_threads 1 and 2), unit square, K Lloyd iterations "
        "or L-BFGS steps from the same points, in pairs: seconds an evaluation (medians), the "
        "median of the pairs' ratios and their range; the same final points and energies?\n\n"
        "| algorithm | N | K | evaluations | 1 thread s | 2 threads s | 1 / 2 threads | range "
        "| same bits |\n|---|--:|--:|--:|--:|--:|--:|--:|---|\n");
    for (const auto& [key, r] : threads_rows) {
      std::vector<double> ratios;
      for (std::size_t i = 0; i < std::min(r.one.size(), r.two.size()); ++i)
        ratios.push_back(r.one[i] / r.two[i]);
      if (ratios.empty()) continue;
      std::printf("| %s | %zu | %zu | %zu | %.4f | %.4f | %.2f | %.2f–%.2f | %s |\n",
                  key.first.c_str(), key.second, r.k, r.evaluations, median(r.one), median(r.two),
                  median(ratios), *std::min_element(ratios.begin(), ratios.end()),
                  *std::max_element(ratios.begin(), ratios.end()), r.same_bits ? "yes" : "no");
    }
  }
  std::printf(
      "\nChecks (faces whose CGAL domain mark differs from ours after K; CGAL free "
      "points outside the domain; energy rises over the K iterations):");
  for (const auto& [key, r] : rows) {
    if (r.k == 0) continue;
    std::printf("\n- %s N=%zu: marks differ %zu; outside after K %zu, uniform %zu",
                key.first.c_str(), key.second, r.domain_mismatch, r.cgal_k.outside,
                r.cgal_uniform_k.outside);
    if (!r.cgal_stop.empty()) std::printf(", at convergence %zu", r.cgal_conv.outside);
    std::printf("; rises: ours %zu", r.ours_rises);
    if (key.second <= 10000)
      std::printf(", CGAL shipped %zu of %zu (largest +%.2g%%)", r.cgal_rises, r.k,
                  100 * r.cgal_max_rise);
  }
  std::printf("\n");
  if (!adaptive_rows.empty()) {
    std::printf(
        "\nAdaptive (k = 0.1, default quadrature) against uniform Lloyd, each to mr < 0.01 from "
        "the same points, on all cores and on one thread (medians of the runs, uniform and "
        "adaptive in turn); the adaptive result's move ratios again by Radon's rule refined to "
        "1e-8\n\n"
        "| domain | N | runs | uniform s/evaluation | adaptive s/evaluation | adaptive / uniform | "
        "on one thread: uniform, adaptive, ratio | adaptive iterations, stop | max mr: ours / "
        "accurate | cells at mr >= 1%% (accurate) | largest centroid error / diameter |\n"
        "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    for (const Adaptive_row& r : adaptive_rows)
      std::printf(
          "| %s | %zu | %zu | %.5f | %.5f | **%.2f** | %.5f, %.5f, %.2f | %zu, %s | %.5f / %.5f | "
          "%zu of %zu | %.1e |\n",
          r.name.c_str(), r.n, r.runs, r.uniform_s, r.adaptive_s, r.adaptive_s / r.uniform_s,
          r.uniform_1, r.adaptive_1, r.adaptive_1 / r.uniform_1, r.adaptive_iterations,
          r.stop.c_str(), r.max_ratio, r.accurate_max_ratio, r.over, r.cells, r.max_error);
  }
  const Figure10& f = figure10;
  if (f.it_uniform > 0) {
    std::printf(
        "\nFig. 10 case (bubble_with_hole, 2000 points, to mr < 0.01; paper: 7 s uniform, 80 s "
        "adaptive; CGAL's lloyd_optimize_mesh_2 as shipped, its defaults, 1000 iterations at "
        "most): stops %s\n\n"
        "| | Lloyd uniform | Lloyd adaptive (k = 0.1) | L-BFGS uniform | L-BFGS adaptive | CGAL "
        "shipped |\n|---|--:|--:|--:|--:|--:|\n"
        "| s | %.3f | %.3f | %.3f | %.3f | %.3f |\n"
        "| iterations | %zu | %zu | %zu | %zu | |\n"
        "| / CGAL time | %.3f | %.3f | %.3f | %.3f | 1 |\n"
        "| s per evaluation | %.5f | %.5f (%.1fx uniform) | | | |\n",
        f.stops.c_str(), f.lloyd_uniform, f.lloyd_adaptive, f.lbfgs_uniform, f.lbfgs_adaptive,
        f.cgal, f.it_uniform, f.it_adaptive, f.it_lbfgs_uniform, f.it_lbfgs_adaptive,
        f.lloyd_uniform / f.cgal, f.lloyd_adaptive / f.cgal, f.lbfgs_uniform / f.cgal,
        f.lbfgs_adaptive / f.cgal, f.per_it_uniform, f.per_it_adaptive,
        f.per_it_adaptive / f.per_it_uniform);
  }
  return 0;
}
