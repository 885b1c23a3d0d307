// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// lloyd_optimize_2(): Lloyd iteration with the paper's stopping rule, options as named parameters.
#ifndef CVT_2_LLOYD_OPTIMIZE_2_H
#define CVT_2_LLOYD_OPTIMIZE_2_H

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

template <class CDT, class Density, class NP>
Lloyd_result lloyd_run(CDT& cdt, const Density& rho, const NP& np) {
  using namespace internal_np;
  using K = typename CDT::Geom_traits;
  const auto start = std::chrono::steady_clock::now();
  const std::size_t max_iterations =
      choose_parameter(get_parameter(np, number_of_iterations_t()), std::size_t(1000));
  const double time_limit = choose_parameter(get_parameter(np, maximum_running_time_t()), 0.0);
  const double bound = choose_parameter(get_parameter(np, move_ratio_bound_t()), 0.01);
  const std::size_t lo =
      choose_parameter(get_parameter(np, minimum_quadrature_resolution_t()), std::size_t(10));
  const std::size_t hi =
      choose_parameter(get_parameter(np, maximum_quadrature_resolution_t()), std::size_t(100));
  const bool verbose = choose_parameter(get_parameter(np, verbose_t()), false);
  const std::function<bool(const Lloyd_result&)> callback =
      choose_parameter(get_parameter(np, callback_t()), std::function<bool(const Lloyd_result&)>());
  if (!(bound >= 0)) throw std::invalid_argument("move_ratio_bound must be >= 0, not " + std::to_string(bound));
  if (!(time_limit >= 0)) throw std::invalid_argument("maximum_running_time must be >= 0 seconds, not " + std::to_string(time_limit));
  if (lo == 0 || hi < lo)
    throw std::invalid_argument("quadrature resolutions must satisfy 1 <= minimum (" + std::to_string(lo) +
                                ") <= maximum (" + std::to_string(hi) + ")");

  const auto quadrature =
      choose_parameter(get_parameter(np, quadrature_t()), Default_quadrature<K, Density>());
  Lloyd_optimizer_2<CDT, Density, std::decay_t<decltype(quadrature)>> optimizer(cdt, rho, quadrature);
  Lloyd_result r;
  std::size_t resolution = lo;
  while (true) {
    const auto& e = optimizer.evaluate(resolution);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (bound > 0 && e.max_move_ratio < bound && resolution < hi && e.number_of_free_generators > 0) {
      resolution = hi;  // converged at a low resolution: confirm at the highest before stopping
      continue;
    }
    r.energy = e.energy;
    r.max_move_ratio = e.max_move_ratio;
    r.mean_move_ratio = e.mean_move_ratio;
    r.energy_history.push_back(e.energy);
    r.max_move_ratio_history.push_back(e.max_move_ratio);
    r.mean_move_ratio_history.push_back(e.mean_move_ratio);
    r.seconds = seconds;
    if (verbose)
      std::clog << "lloyd: iteration " << r.number_of_iterations << " energy " << e.energy
                << " max move ratio " << e.max_move_ratio << " resolution " << resolution << " "
                << seconds << " s\n";
    if (e.number_of_free_generators == 0) {
      r.stop_reason = NO_FREE_GENERATOR;
      break;
    }
    if (bound > 0 && e.max_move_ratio < bound) {
      r.stop_reason = CONVERGED;
      break;
    }
    if (r.number_of_iterations >= max_iterations) {
      r.stop_reason = MAX_ITERATIONS_REACHED;
      break;
    }
    if (time_limit > 0 && seconds >= time_limit) {
      r.stop_reason = TIME_LIMIT_REACHED;
      break;
    }
    if (callback && !callback(r)) {
      r.stop_reason = CALLBACK_REQUESTED_STOP;
      break;
    }
    optimizer.move();
    ++r.number_of_iterations;
    resolution = quadrature_resolution(e.max_move_ratio, bound, lo, hi);
  }
  return r;
}

}  // namespace internal

/// \ingroup PkgCvt2Ref
/// Lloyd iteration (paper, Section 3): moves every free generator of `cdt` to the centroid of
/// its bounded Voronoi cell under a density \f$\rho\f$, and again, until every move ratio
/// \f$mr(x) = \|x - x^*\|/\mathrm{diameter}(V)\f$ is below `move_ratio_bound`, or another
/// limit is met. Constrained vertices stay; a free generator never crosses a constraint.
/// The result describes the generators as they are at the end (`Lloyd_result`).
///
/// \param cdt a constrained Delaunay triangulation with its domain marked (see
///        `Bounded_voronoi_diagram_2`); its free vertices are moved in place.
/// \param np optional named parameters among:
///   - `density(rho)`: a model of `DensityFunction_2` (a lambda works); default uniform.
///   - `sizing_field(mu)`: a sizing field \f$\mu\f$ instead, used as \f$\rho = 1/\mu^4\f$ (cell
///     size scales as \f$\rho^{-1/4}\f$); not together with `density`.
///   - `quadrature(q)`: a model of `CellQuadrature_2`; default `Exact_quadrature_2` for a
///     `Uniform_density_2`, `Midpoint_quadrature_2` otherwise.
///   - `minimum_quadrature_resolution(n)`, `maximum_quadrature_resolution(n)`: sub-triangles a
///     cell, raised from the first to the second as moves shrink; default 10 and 100.
///   - `move_ratio_bound(p)`: stop when every move ratio is below `p`; default 0.01; 0 turns
///     this stop off.
///   - `number_of_iterations(n)`: at most `n` moves; default 1000.
///   - `maximum_running_time(s)`: stop after `s` seconds (checked between iterations); default
///     0, no limit.
///   - `callback(f)`: `bool f(const Lloyd_result&)`, called after each evaluation with the
///     figures so far; returning `false` stops.
///   - `verbose(b)`: a line a iteration on `std::clog`; default `false`.
/// \throws std::invalid_argument for a bad parameter value, naming it; Domain_error if the
///         density is not positive and finite at a point where it is evaluated.
template <class CDT, class NP = No_named_parameters>
Lloyd_result lloyd_optimize_2(CDT& cdt, const NP& np = parameters::default_values()) {
  using namespace internal_np;
  using K = typename CDT::Geom_traits;
  static_assert(!(has_parameter<NP, density_t> && has_parameter<NP, sizing_field_t>),
                "lloyd_optimize_2: give either density() or sizing_field(), not both");
  if constexpr (has_parameter<NP, sizing_field_t>) {
    return internal::lloyd_run(cdt, make_sizing_field_density_2<K>(get_parameter(np, sizing_field_t())), np);
  } else {
    return internal::lloyd_run(cdt, choose_parameter(get_parameter(np, density_t()), Uniform_density_2<K>()), np);
  }
}

}  // namespace CVT_2

#endif  // CVT_2_LLOYD_OPTIMIZE_2_H
