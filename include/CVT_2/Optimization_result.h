// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// Optimization_result: what lloyd_optimize_2() and lbfgs_optimize_2() return, and why they stop.
#ifndef CVT_2_OPTIMIZATION_RESULT_H
#define CVT_2_OPTIMIZATION_RESULT_H

#include <CVT_2/Density_response.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace CVT_2 {

/// \ingroup PkgCvt2Ref
/// Why an optimization stopped.
enum Stop_reason {
  CONVERGED,  ///< every free (or sliding) generator's move ratio is below the bound, and not
              ///< `STALLED`
  MAX_ITERATIONS_REACHED,   ///< `number_of_iterations` moves were done
  TIME_LIMIT_REACHED,       ///< `maximum_running_time` passed
  CALLBACK_REQUESTED_STOP,  ///< the callback returned `false`
  NO_FREE_GENERATOR,        ///< nothing can move
  /// every move ratio is below the bound, but the cells do not follow the density
  /// (`Density_response::is_followed()` false): the generators are still on their way across
  /// the domain, or the regions between constraints hold too many of them or too few, which no
  /// move mends; far from the optimum either way (points that do not follow the density, given
  /// under one, stop so; `random_points_in_domain_2()` draws points that do, dealt by region)
  STALLED
};

/// \ingroup PkgCvt2Ref
/// The name `Stop_reason` had before L-BFGS shared it.
using Lloyd_stop_reason = Stop_reason;

/// \ingroup PkgCvt2Ref
/// A short name of `reason` for messages and logs: `converged`, `stalled`, `max_iterations`,
/// `time_limit`, `callback` or `no_free_generator`.
inline const char* to_string(Stop_reason reason) {
  switch (reason) {
    case CONVERGED:
      return "converged";
    case STALLED:
      return "stalled";
    case MAX_ITERATIONS_REACHED:
      return "max_iterations";
    case TIME_LIMIT_REACHED:
      return "time_limit";
    case CALLBACK_REQUESTED_STOP:
      return "callback";
    case NO_FREE_GENERATOR:
      return "no_free_generator";
  }
  return "unknown";
}

/// \ingroup PkgCvt2Ref
/// What an optimization (`lloyd_optimize_2()`, `lbfgs_optimize_2()`) did. The figures describe
/// the generators as they are at the end: an independent evaluation of the final points finds
/// the same energy and move ratios.
struct Optimization_result {
  std::size_t number_of_iterations = 0;  ///< moves of all free generators done
  /// evaluations of the diagram, energy and centroids done (one per Lloyd iteration, plus the
  /// first and a confirmation at the highest quadrature resolution; L-BFGS adds its line
  /// searches)
  std::size_t number_of_evaluations = 0;
  Stop_reason stop_reason = MAX_ITERATIONS_REACHED;  ///< why it stopped
  double energy = 0;  ///< \f$E = \sum_i \int_{V_i} \rho(y)\|y - x_i\|^2 dy\f$, all cells
  /// \f$\max_i mr(x_i)\f$ over the free generators and the sliding ones (`sliding_runs`), whose
  /// move is along their run
  double max_move_ratio = 0;
  double mean_move_ratio = 0;  ///< the mean of \f$mr(x_i)\f$ over the same
  /// how the final cells follow a density that is not uniform (`density_response_2()`); not
  /// measured (NaN) with a uniform density or in a `region`
  Density_response density_response;
  std::vector<double> energy_history;           ///< one per evaluation, the first before any move
  std::vector<double> max_move_ratio_history;   ///< likewise
  std::vector<double> mean_move_ratio_history;  ///< likewise
  double seconds = 0;                           ///< running time
};

/// \ingroup PkgCvt2Ref
/// The name `Optimization_result` had before L-BFGS shared it.
using Lloyd_result = Optimization_result;

}  // namespace CVT_2

#endif  // CVT_2_OPTIMIZATION_RESULT_H
