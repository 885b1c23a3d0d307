// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// What cvt2's two translation units share: cvt2.cpp reads the command line and the domain and
// writes the outputs, optimize.cpp runs the optimizers; each compiles in about a minute, side by
// side (one unit took a minute and a half).
#ifndef CVT2_TOOL_CVT2_H
#define CVT2_TOOL_CVT2_H

#include <CVT_2/Boundary_lipschitz_sizing_2.h>
#include <CVT_2/Cvt_triangulation_2.h>
#include <CVT_2/Optimization_result.h>
#include <CVT_2/Point_refinement_sizing_2.h>
#include <CVT_2/Sliding_runs_2.h>
#include <CVT_2/conforming_sites_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

// getpid() and isatty(), where there are
#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#define CVT2_POSIX 1
#endif

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using CDT = CVT_2::Cvt_triangulation_2<K>;
using Point_2 = K::Point_2;
using Sizing = CVT_2::Boundary_lipschitz_sizing_2<K>;

namespace cvt2_program {

// The command line, parsed.
struct Options {
  std::string domain;
  std::optional<std::size_t> points;  // -n; by default from the domain file
  std::optional<std::size_t> cells;   // --cells: in all, the domain's vertices included
  std::optional<double> size;         // --size: the spacing of a hexagonal tiling
  bool resample = false;              // --boundary resample or slide
  bool slide = false;                 // --boundary slide
  std::optional<double> deviation_bound;
  std::optional<double> spacing_ratio;  // --boundary-spacing
  double corner_angle = 30;
  double minimum_ring_area = 0;
  std::string points_in;
  std::string fixed_points;                   // --fixed-points FILE
  std::vector<std::array<double, 4>> refine;  // --refine X Y SIZE RADIUS, each
  std::optional<double> boundary_tolerance;   // default: insert_generators_2()'s
  std::uint64_t seed = 1;
  std::size_t iterations = 1000;
  double move_ratio = 0.01;
  bool lbfgs = true;
  bool lipschitz = false;
  std::optional<double> lipschitz_k;    // --lipschitz-k; default 0.1
  std::optional<double> boundary_size;  // default: each boundary edge's length
  std::string redistribute = "auto";    // --redistribute: auto | always | never
  double time_limit = 0;
  unsigned threads = 0;  // 0: all cores
  std::string svg, points_out, cells_out, geojson, vtu, disv, mesh_out, domain_out;
  std::string cells_on_constraints;
  std::string top = "1", bottom = "0";  // of the DISV's layer: a number or a file of them
  bool barriers = false;                // --constraints barrier
  bool conforming = false;              // --constraints conforming
  bool quiet = false;
  bool help = false;
  bool version = false;
};

// The sizing field of --density lipschitz or of --refine, if any.
struct Sizing_choice {
  std::optional<Sizing> lipschitz;
  std::optional<CVT_2::Point_refinement_sizing_2<K>> refinement;
  bool is_uniform() const { return !lipschitz && !refinement; }
  // run(np) with the sizing field among the named parameters np.
  template <class NP, class Run>
  auto apply(const NP& np, Run run) const {
    if (lipschitz) return run(np.sizing_field(*lipschitz));
    if (refinement) return run(np.sizing_field(*refinement));
    return run(np);
  }
};

// The optimization (--algorithm), with progress on standard error; Ctrl-C ends it early.
CVT_2::Optimization_result optimize(CDT& cdt, const Options& o, const Sizing_choice& sizing,
                                    const std::vector<Point_2>& fixed,
                                    const CVT_2::Conforming_disks<Point_2>& keep_out,
                                    CVT_2::Sliding_runs_2<CDT>* sliding);

}  // namespace cvt2_program

#endif  // CVT2_TOOL_CVT2_H
