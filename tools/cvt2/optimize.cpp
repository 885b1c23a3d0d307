// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// cvt2's optimization: L-BFGS or Lloyd iteration with the sizing field chosen, progress on
// standard error, Ctrl-C.
#include "cvt2.h"

#include <CVT_2/lbfgs_optimize_2.h>
#include <CVT_2/lloyd_optimize_2.h>

#include <csignal>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace {

volatile std::sig_atomic_t interrupted = 0;
// The first Ctrl-C ends the iteration early and keeps its result; a second one kills.
extern "C" void on_interrupt(int) {
  interrupted = 1;
  std::signal(SIGINT, SIG_DFL);
}

bool stderr_is_terminal() {
#ifdef CVT2_POSIX
  return isatty(2) != 0;
#else
  return false;
#endif
}

// Progress on standard error: one updating line on a terminal, a line every 10 iterations else.
class Progress {
 public:
  explicit Progress(bool quiet) : m_quiet(quiet), m_terminal(stderr_is_terminal()) {}
  bool operator()(const CVT_2::Optimization_result& r) {
    if (!m_quiet && (m_terminal || r.number_of_iterations % 10 == 0)) {
      std::ostringstream line;
      line << "cvt2: iteration " << r.number_of_iterations << "  energy " << std::setprecision(8)
           << r.energy << "  max move ratio " << std::setprecision(4) << r.max_move_ratio << "  "
           << std::fixed << std::setprecision(2) << r.seconds << " s";
      if (m_terminal)
        std::cerr << '\r' << line.str() << "\033[K" << std::flush, m_line_open = true;
      else
        std::cerr << line.str() << '\n';
    }
    return !interrupted;
  }
  void finish() {
    if (m_line_open) std::cerr << '\n';
    m_line_open = false;
  }

 private:
  bool m_quiet, m_terminal, m_line_open = false;
};

}  // namespace

namespace cvt2_program {

CVT_2::Optimization_result optimize(CDT& cdt, const Options& o, const Sizing_choice& sizing,
                                    const std::vector<Point_2>& fixed,
                                    const CVT_2::Conforming_disks<Point_2>& keep_out,
                                    CVT_2::Sliding_runs_2<CDT>* sliding) {
  Progress progress(o.quiet);
  const std::function<bool(const CVT_2::Optimization_result&)> callback = std::ref(progress);
  const auto np = CVT_2::parameters::number_of_iterations(o.iterations)
                      .move_ratio_bound(o.move_ratio)
                      .maximum_running_time(o.time_limit)
                      .number_of_threads(o.threads)
                      .callback(callback)
                      .fixed_points(fixed)
                      .keep_out(keep_out)
                      .sliding_runs(sliding);
  const auto run = [&o](CDT& t, const auto& parameters) {
    return o.lbfgs ? CVT_2::lbfgs_optimize_2(t, parameters)
                   : CVT_2::lloyd_optimize_2(t, parameters);
  };
  std::signal(SIGINT, on_interrupt);
  try {
    const CVT_2::Optimization_result r =
        sizing.apply(np, [&](const auto& parameters) { return run(cdt, parameters); });
    progress.finish();
    std::signal(SIGINT, SIG_DFL);
    return r;
  } catch (...) {
    progress.finish();
    throw;
  }
}

}  // namespace cvt2_program
