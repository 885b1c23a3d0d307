// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// What lloyd_optimize_2() and lbfgs_optimize_2() share: options, policies, schedule, stopping rule.
#ifndef CVT_2_INTERNAL_RUN_OPTIMIZATION_H
#define CVT_2_INTERNAL_RUN_OPTIMIZATION_H

#include <CVT_2/Lloyd_optimizer_2.h>
#include <CVT_2/Sizing_field_density_2.h>
#include <CVT_2/Uniform_density_2.h>
#include <CVT_2/parameters.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CVT_2 {
namespace internal {

// The paper's practice: few quadrature triangles while generators move a lot, many at the end.
// Geometric from `lo` at a largest move ratio of 10 p down to `hi` at 2 p.
inline std::size_t quadrature_resolution(double max_move_ratio, double p, std::size_t lo,
                                         std::size_t hi) {
  if (p <= 0) p = 0.01;
  if (max_move_ratio >= 10 * p) return lo;
  if (max_move_ratio <= 2 * p) return hi;
  const double s = std::log(10 * p / max_move_ratio) / std::log(5.0);
  return std::clamp(static_cast<std::size_t>(std::lround(double(lo) * std::pow(double(hi) / double(lo), s))), lo, hi);
}

// The options both optimizers read, with their defaults, checked.
struct Run_options {
  std::chrono::steady_clock::time_point start;
  std::size_t max_iterations = 1000;
  double time_limit = 0;
  double bound = 0.01;
  std::size_t lo = 10, hi = 100;
  bool verbose = false;
  unsigned threads = 0;  // 0: one per core
  std::function<bool(const Lloyd_result&)> callback;
};

template <class NP>
Run_options read_run_options(const NP& np) {
  using namespace internal_np;
  Run_options o;
  o.start = std::chrono::steady_clock::now();
  o.max_iterations = choose_parameter(get_parameter(np, number_of_iterations_t()), std::size_t(1000));
  o.time_limit = choose_parameter(get_parameter(np, maximum_running_time_t()), 0.0);
  o.bound = choose_parameter(get_parameter(np, move_ratio_bound_t()), 0.01);
  o.lo = choose_parameter(get_parameter(np, minimum_quadrature_resolution_t()), std::size_t(10));
  o.hi = choose_parameter(get_parameter(np, maximum_quadrature_resolution_t()), std::size_t(100));
  o.verbose = choose_parameter(get_parameter(np, verbose_t()), false);
  const auto threads = choose_parameter(get_parameter(np, number_of_threads_t()), 0);
  if constexpr (std::is_signed_v<std::decay_t<decltype(threads)>>)
    if (threads < 0) throw std::invalid_argument("number_of_threads must be >= 0, not " + std::to_string(threads));
  o.threads = static_cast<unsigned>(threads);
  o.callback =
      choose_parameter(get_parameter(np, callback_t()), std::function<bool(const Lloyd_result&)>());
  if (!(o.bound >= 0)) throw std::invalid_argument("move_ratio_bound must be >= 0, not " + std::to_string(o.bound));
  if (!(o.time_limit >= 0)) throw std::invalid_argument("maximum_running_time must be >= 0 seconds, not " + std::to_string(o.time_limit));
  if (o.lo == 0 || o.hi < o.lo)
    throw std::invalid_argument("quadrature resolutions must satisfy 1 <= minimum (" + std::to_string(o.lo) +
                                ") <= maximum (" + std::to_string(o.hi) + ")");
  return o;
}

// Calls run(rho, quadrature) with the density (`density`, or `sizing_field` as 1/mu^4, or
// uniform) and the quadrature (`quadrature`, or the default for that density) of `np`.
template <class K, class NP, class Run>
decltype(auto) with_density_and_quadrature(const NP& np, Run&& run) {
  using namespace internal_np;
  const auto go = [&](const auto& rho) -> decltype(auto) {
    using Density = std::decay_t<decltype(rho)>;
    const auto quadrature =
        choose_parameter(get_parameter(np, quadrature_t()), Default_quadrature<K, Density>());
    return run(rho, quadrature);
  };
  if constexpr (has_parameter<NP, sizing_field_t>) {
    return go(make_sizing_field_density_2<K>(get_parameter(np, sizing_field_t())));
  } else {
    return go(choose_parameter(get_parameter(np, density_t()), Uniform_density_2<K>()));
  }
}

// Lloyd iteration as run_optimization() drives it: a step moves to the centroids, evaluates.
template <class Optimizer>
struct Lloyd_steps {
  Optimizer& lloyd;
  const auto& evaluate(std::size_t resolution) { return lloyd.evaluate(resolution); }
  const auto& step(std::size_t resolution) {
    lloyd.move();
    return lloyd.evaluate(resolution);
  }
  std::size_t number_of_evaluations() const { return lloyd.number_of_evaluations(); }
};

// The loop both optimizers run. `Optimizer` has evaluate(resolution), which evaluates the
// generators where they are, and step(resolution), which moves them and evaluates them there;
// both return a Lloyd_optimizer_2 Evaluation; number_of_evaluations() counts them. It stops by the paper's rule (every move ratio of
// the last evaluation below the bound, confirmed at the highest resolution) or a limit, and
// returns the figures of the final points.
template <class Optimizer>
Lloyd_result run_optimization(Optimizer& optimizer, const Run_options& o, const char* name) {
  Lloyd_result r;
  std::size_t resolution = o.lo;
  auto e = optimizer.evaluate(resolution);
  while (true) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - o.start).count();
    if (o.bound > 0 && e.max_move_ratio < o.bound && resolution < o.hi && e.number_of_free_generators > 0) {
      resolution = o.hi;  // converged at a low resolution: confirm at the highest before stopping
      e = optimizer.evaluate(resolution);
      continue;
    }
    r.energy = e.energy;
    r.max_move_ratio = e.max_move_ratio;
    r.mean_move_ratio = e.mean_move_ratio;
    r.energy_history.push_back(e.energy);
    r.max_move_ratio_history.push_back(e.max_move_ratio);
    r.mean_move_ratio_history.push_back(e.mean_move_ratio);
    r.seconds = seconds;
    r.number_of_evaluations = optimizer.number_of_evaluations();
    if (o.verbose)
      std::clog << name << ": iteration " << r.number_of_iterations << " energy " << e.energy
                << " max move ratio " << e.max_move_ratio << " resolution " << resolution << " "
                << seconds << " s\n";
    if (e.number_of_free_generators == 0) {
      r.stop_reason = NO_FREE_GENERATOR;
      break;
    }
    if (o.bound > 0 && e.max_move_ratio < o.bound) {
      r.stop_reason = CONVERGED;
      break;
    }
    if (r.number_of_iterations >= o.max_iterations) {
      r.stop_reason = MAX_ITERATIONS_REACHED;
      break;
    }
    if (o.time_limit > 0 && seconds >= o.time_limit) {
      r.stop_reason = TIME_LIMIT_REACHED;
      break;
    }
    if (o.callback && !o.callback(r)) {
      r.stop_reason = CALLBACK_REQUESTED_STOP;
      break;
    }
    resolution = quadrature_resolution(e.max_move_ratio, o.bound, o.lo, o.hi);
    e = optimizer.step(resolution);
    ++r.number_of_iterations;
  }
  return r;
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_RUN_OPTIMIZATION_H
