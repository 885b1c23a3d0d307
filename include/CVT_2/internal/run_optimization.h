// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// What lloyd_optimize_2() and lbfgs_optimize_2() share: options, policies, schedule, stopping rule.
#ifndef CVT_2_INTERNAL_RUN_OPTIMIZATION_H
#define CVT_2_INTERNAL_RUN_OPTIMIZATION_H

#include <CVT_2/Optimization_result.h>
#include <CVT_2/internal/layout/sort_faces.h>
#include <CVT_2/internal/parallel/run_chunks.h>
#include <CVT_2/internal/to_string.h>
#include <CVT_2/internal/vertices_at.h>
#include <CVT_2/parameters.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <iostream>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <utility>
#include <vector>

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
  return std::clamp(
      static_cast<std::size_t>(std::lround(double(lo) * std::pow(double(hi) / double(lo), s))), lo,
      hi);
}

// A count option: an integer >= 0, or std::invalid_argument naming the option.
template <class T>
std::size_t checked_count(const T& value, const char* name) {
  static_assert(std::is_integral_v<T>, "a count option takes an integer");
  if constexpr (std::is_signed_v<T>)
    if (value < 0)
      throw std::invalid_argument(std::string(name) + " must be >= 0, not " +
                                  std::to_string(value));
  return static_cast<std::size_t>(value);
}

// The options both optimizers read; the defaults are written here only.
struct Run_options {
  std::chrono::steady_clock::time_point start;
  std::size_t max_iterations = 1000;
  double time_limit = 0;          // seconds; 0: none
  double bound = 0.01;            // on the move ratios; 0: no such stop
  std::size_t lo = 10, hi = 100;  // quadrature resolutions
  bool verbose = false;
  unsigned threads = 0;  // 0: one per core
  std::size_t lbfgs_memory = 7;
  std::function<bool(const Optimization_result&)> callback;
};

template <class NP>
Run_options read_run_options(const NP& np) {
  using namespace internal_np;
  Run_options o;
  o.start = std::chrono::steady_clock::now();
  o.max_iterations =
      checked_count(choose_parameter(get_parameter(np, number_of_iterations_t()), o.max_iterations),
                    "number_of_iterations");
  o.time_limit = choose_parameter(get_parameter(np, maximum_running_time_t()), o.time_limit);
  o.bound = choose_parameter(get_parameter(np, move_ratio_bound_t()), o.bound);
  o.lo = checked_count(choose_parameter(get_parameter(np, minimum_quadrature_resolution_t()), o.lo),
                       "minimum_quadrature_resolution");
  o.hi = checked_count(choose_parameter(get_parameter(np, maximum_quadrature_resolution_t()), o.hi),
                       "maximum_quadrature_resolution");
  o.verbose = choose_parameter(get_parameter(np, verbose_t()), o.verbose);
  o.threads = static_cast<unsigned>(checked_count(
      choose_parameter(get_parameter(np, number_of_threads_t()), o.threads), "number_of_threads"));
  o.lbfgs_memory = checked_count(
      choose_parameter(get_parameter(np, lbfgs_memory_t()), o.lbfgs_memory), "lbfgs_memory");
  o.callback = choose_parameter(get_parameter(np, callback_t()), o.callback);
  if (!(o.bound >= 0))
    throw std::invalid_argument("move_ratio_bound must be >= 0, not " + std::to_string(o.bound));
  if (!(o.time_limit >= 0))
    throw std::invalid_argument("maximum_running_time must be >= 0 seconds, not " +
                                std::to_string(o.time_limit));
  if (o.lo == 0 || o.hi < o.lo)
    throw std::invalid_argument("quadrature resolutions must satisfy 1 <= minimum (" +
                                std::to_string(o.lo) + ") <= maximum (" + std::to_string(o.hi) +
                                ")");
  return o;
}

// The vertices at the points of the named parameter `fixed_points` (none without it; one on a
// constraint never moves anyway, unless it would slide).
// \throws std::invalid_argument naming a point that is not a vertex of `cdt`.
template <class CDT, class NP>
std::vector<typename CDT::Vertex_handle> fixed_vertices(const CDT& cdt, const NP& np) {
  std::vector<typename CDT::Vertex_handle> vertices;
  if constexpr (internal_np::has_parameter<NP, internal_np::fixed_points_t>)
    for (const auto v :
         vertices_at(cdt, get_parameter(np, internal_np::fixed_points_t()), "fixed_points"))
      vertices.push_back(v);
  return vertices;
}

// With the named parameter `region` (a range of points, vertices of `cdt`): the free vertices
// among them and within `region_rings` (default 0) rings of them, the only ones to move. The
// rings grow from the points and from free vertices only: a constrained vertex reached on the
// way (the end of a long boundary edge) would take them far away.
// \throws std::invalid_argument naming a point that is not a vertex of `cdt`.
template <class CDT, class NP>
std::optional<std::vector<typename CDT::Vertex_handle>> region_vertices(const CDT& cdt,
                                                                        const NP& np) {
  using Vertex_handle = typename CDT::Vertex_handle;
  if constexpr (internal_np::has_parameter<NP, internal_np::region_t>) {
    const std::size_t rings = checked_count(
        internal_np::choose_parameter(get_parameter(np, internal_np::region_rings_t()), 0),
        "region_rings");
    std::vector<Vertex_handle> reached;
    std::unordered_set<Vertex_handle> seen;
    for (const Vertex_handle v :
         vertices_at(cdt, get_parameter(np, internal_np::region_t()), "region"))
      if (seen.insert(v).second) reached.push_back(v);
    for (std::size_t ring = 0, first = 0; ring < rings && cdt.dimension() == 2; ++ring) {
      const std::size_t last = reached.size();
      if (first == last) break;  // no vertex reached by the last ring
      for (std::size_t k = first; k < last; ++k) {
        if (ring > 0 && cdt.are_there_incident_constraints(reached[k])) continue;
        auto vc = cdt.incident_vertices(reached[k]), done = vc;
        do
          if (!cdt.is_infinite(vc) && seen.insert(vc).second) reached.push_back(vc);
        while (++vc != done);
      }
      first = last;
    }
    std::vector<Vertex_handle> free;
    for (const Vertex_handle v : reached)
      if (!cdt.are_there_incident_constraints(v)) free.push_back(v);
    return free;
  } else {
    return std::nullopt;
  }
}

// The named parameter `keep_out` (an object with `empty()` and `outside(from, to)`, as
// Conforming_disks), if given and not empty, to the optimizer's moves.
template <class Optimizer, class NP>
void set_keep_out(Optimizer& optimizer, const NP& np) {
  if constexpr (internal_np::has_parameter<NP, internal_np::keep_out_t>) {
    const auto& keep_out = get_parameter(np, internal_np::keep_out_t());
    using Point_2 = typename Optimizer::Point_2;
    if (!keep_out.empty())
      optimizer.set_keep_out([&keep_out](const Point_2& from, const Point_2& to) {
        return keep_out.outside(from, to);
      });
  }
}

// The named parameter `sliding_runs` (a pointer to a Sliding_runs_2, or nullptr), if given, to
// the optimizer. \throws std::invalid_argument if a region is given too.
template <class Optimizer, class NP>
void set_sliding_runs(Optimizer& optimizer, const NP& np) {
  if constexpr (internal_np::has_parameter<NP, internal_np::sliding_runs_t>) {
    if constexpr (internal_np::has_parameter<NP, internal_np::region_t>)
      throw std::invalid_argument(
          "sliding_runs and region do not go together: a region moves free generators only");
    optimizer.set_sliding_runs(get_parameter(np, internal_np::sliding_runs_t()));
  }
}

// Lays out the faces of a big triangulation that CGAL's own insertion left scattered in
// memory (insert_generators_2() lays out its own), before a run that may repay it: at 10^6
// generators an iteration then takes about 3/4 of the time, and the layout costs about three
// iterations. Skipped for a run of fewer than 16 iterations, and if its memory cannot be had.
template <class CDT>
void lay_out_faces(CDT& cdt, const Run_options& o) {
  constexpr std::size_t big = std::size_t(1) << 16, iterations = 16;
  if (o.max_iterations < iterations || cdt.number_of_faces() < big || !faces_are_scattered(cdt))
    return;
  try {
    sort_faces(cdt);
  } catch (const std::bad_alloc&) {
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

// Why to stop after evaluation `e`, if at all; `r` holds the figures so far.
template <class Evaluation>
std::optional<Stop_reason> stop_reason(const Evaluation& e, const Optimization_result& r,
                                       const Run_options& o) {
  if (e.number_of_free_generators + e.number_of_sliding_generators == 0) return NO_FREE_GENERATOR;
  if (o.bound > 0 && e.max_move_ratio < o.bound) return CONVERGED;
  if (r.number_of_iterations >= o.max_iterations) return MAX_ITERATIONS_REACHED;
  if (o.time_limit > 0 && r.seconds >= o.time_limit) return TIME_LIMIT_REACHED;
  if (o.callback && !o.callback(r)) return CALLBACK_REQUESTED_STOP;
  return std::nullopt;
}

// The figures of evaluation `e` into `r`, and a line on std::clog if verbose.
template <class Evaluation>
void record(const Evaluation& e, std::size_t evaluations, const Run_options& o, const char* name,
            Optimization_result& r) {
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - o.start).count();
  r.energy = e.energy;
  r.max_move_ratio = e.max_move_ratio;
  r.mean_move_ratio = e.mean_move_ratio;
  r.energy_history.push_back(e.energy);
  r.max_move_ratio_history.push_back(e.max_move_ratio);
  r.mean_move_ratio_history.push_back(e.mean_move_ratio);
  r.number_of_evaluations = evaluations;
  if (o.verbose)
    std::clog << name << ": iteration " << r.number_of_iterations << " energy " << e.energy
              << " max move ratio " << e.max_move_ratio << " resolution " << e.resolution << " "
              << r.seconds << " s\n";
}

// The loop both optimizers run. `Optimizer` has evaluate(resolution), which evaluates the
// generators where they are, and step(resolution), which moves them and evaluates them there;
// both return a Cvt_energy_2 Evaluation; number_of_evaluations() counts them. It stops by
// the paper's rule (every move ratio of the last evaluation below the bound, confirmed at the
// highest resolution) or a limit, and returns the figures of the final points.
template <class Optimizer>
Optimization_result run_optimization(Optimizer&& optimizer, const Run_options& o,
                                     const char* name) {
  const Worker_pool::Scope threads;  // the same threads for every pass of the run
  Optimization_result r;
  auto e = optimizer.evaluate(o.lo);
  while (true) {
    if (o.bound > 0 && e.max_move_ratio < o.bound && e.resolution < o.hi &&
        e.number_of_free_generators + e.number_of_sliding_generators > 0) {
      e = optimizer.evaluate(o.hi);  // converged at a low resolution: confirm at the highest
      continue;
    }
    record(e, optimizer.number_of_evaluations(), o, name, r);
    if (const auto reason = stop_reason(e, r, o)) {
      r.stop_reason = *reason;
      return r;
    }
    e = optimizer.step(quadrature_resolution(e.max_move_ratio, o.bound, o.lo, o.hi));
    ++r.number_of_iterations;
  }
}

}  // namespace internal
}  // namespace CVT_2

#endif  // CVT_2_INTERNAL_RUN_OPTIMIZATION_H
