// Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
// natural_neighbors_benchmark: natural-neighbour coordinates per query on our bounded Voronoi
// diagram against CGAL's natural_neighbor_coordinates_2() on a Delaunay triangulation of the
// same nodes, with the same Hilbert-sorted queries each started from the previous one's face;
// and our batch natural_neighbor_matrix_2() on one thread and on two.
// CVT_2_NN_NODES=10000,100000 keeps those node counts (default 1e4, 1e5, 1e6);
// CVT_2_NN_QUERIES=n sets the number of queries (default 1e6); CVT_2_NN_REPETITIONS=r the
// repetitions (default 3). Times are wall-clock medians over the repetitions; ours/CGAL the
// median of the ratios of blocks of queries timed in turn, and the speed-up of the batch the
// median over the repetitions of 1 thread's time over 2 threads'. On a loaded machine two
// figures say how much to trust them: ours/CGAL by thread CPU time, and the cores the batch on
// two threads got (its process CPU time over its wall time).
#include "benchmark_support.h"

#include <CVT_2/Bounded_voronoi_diagram_2.h>
#include <CVT_2/natural_neighbor_coordinates_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/function_objects.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/natural_neighbor_coordinates_2.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using support::CDT;
using support::Clock;
using support::domain;
using support::fmt;
using support::K;
using support::load_average;
using support::massachusetts;
using support::Point;
using support::square;
using Bvd = CVT_2::Bounded_voronoi_diagram_2<CDT>;
using Dt = CGAL::Delaunay_triangulation_2<K>;

namespace {

using support::nan;  // hides ::nan of <cmath>

struct Row {
  std::string domain;
  std::size_t nodes = 0, vertices = 0, queries = 0, outside = 0;
  // µs per query, medians: the hinted walk alone on each triangulation, the single-query
  // functions (ours Sibson and Laplace, CGAL's Sibson), the batch on 1 and 2 threads.
  double walk_ours = nan, walk_cgal = nan, sibson = nan, cgal = nan, laplace = nan;
  double sibson1 = nan, sibson2 = nan, laplace1 = nan, laplace2 = nan;
  // Medians of ratios: ours/CGAL over the blocks, by wall and by thread CPU time; the speed-ups
  // over the repetitions.
  double ratio = nan, ratio_cpu = nan, sibson_speedup = nan, laplace_speedup = nan;
  double sibson_cores = nan, laplace_cores = nan;       // of the batch on 2 threads
  double neighbours_ours = nan, neighbours_cgal = nan;  // per query
  bool same_bits = true;                                // the batch on 2 threads as on 1
  double numbering = nan;  // µs per query: the batch's pass over every cell, on one thread
};
std::vector<Row> rows;  // for the table printed after the run

double cpu_seconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// Wall, thread CPU and process CPU time since construction.
struct Stopwatch {
  Clock::time_point start = Clock::now();
  double thread = cpu_seconds(CLOCK_THREAD_CPUTIME_ID);
  double process = cpu_seconds(CLOCK_PROCESS_CPUTIME_ID);
  double wall_s() const { return std::chrono::duration<double>(Clock::now() - start).count(); }
  double thread_s() const { return cpu_seconds(CLOCK_THREAD_CPUTIME_ID) - thread; }
  double process_s() const { return cpu_seconds(CLOCK_PROCESS_CPUTIME_ID) - process; }
};

double median(std::vector<double> v) {
  if (v.empty()) return nan;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

std::size_t env_size(const char* name, std::size_t fallback) {
  const char* s = std::getenv(name);
  return s && *s ? std::stoul(s) : fallback;
}

template <class Matrix>
bool same(const Matrix& a, const Matrix& b) {
  return a.row_offsets == b.row_offsets && a.columns == b.columns && a.values == b.values &&
         a.inside == b.inside;
}

void bm_natural_neighbors(benchmark::State& state, const std::string& name) {
  const std::size_t n = static_cast<std::size_t>(state.range(0));
  const std::size_t number_of_queries = env_size("CVT_2_NN_QUERIES", 1000000);
  Row r;
  r.domain = name;
  r.nodes = n;
  CDT cdt;
  Dt dt;
  std::vector<Point> queries;
  try {
    const support::Domain& d = domain(name);
    support::build_ours(cdt, d, support::initial_points(d, n));
    // CGAL's nodes: every vertex of ours, the domain's included; no constraints.
    std::vector<Point> nodes;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      nodes.push_back(v->point());
    dt.insert(nodes.begin(), nodes.end());
    queries = CVT_2::random_points_in_domain_2(d.cdt, number_of_queries,
                                               CVT_2::parameters::random_seed(2));
    CGAL::hilbert_sort(queries.begin(), queries.end());
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  const Bvd bvd(cdt);
  r.vertices = cdt.number_of_vertices();
  r.queries = queries.size();
  const double per_query = 1e6 / double(queries.size());  // seconds to µs per query

  std::vector<double> walk_ours, walk_cgal, sibson, cgal, laplace, sibson1, sibson2, laplace1,
      laplace2, ratio, ratio_cpu, sibson_speedup, laplace_speedup, sibson_cores, laplace_cores,
      numbering;
  std::vector<std::pair<Bvd::Vertex_handle, double>> out;
  std::vector<std::pair<Dt::Vertex_handle, double>> cgal_out;  // vertices too, not points
  out.reserve(64);
  cgal_out.reserve(64);
  double checksum = 0;
  std::size_t count_ours = 0, count_cgal = 0;
  // Neither function gives back the face it located: each query is located here from the
  // previous one's face, timed with the function, which then starts in q's own face.
  CDT::Face_handle f_walk, f_sibson, f_laplace;
  Dt::Face_handle g_walk, g_sibson;
  const auto walk_ours_block = [&](auto first, auto last) {
    for (; first != last; ++first) f_walk = cdt.locate(*first, f_walk);
  };
  const auto walk_cgal_block = [&](auto first, auto last) {
    for (; first != last; ++first) g_walk = dt.locate(*first, g_walk);
  };
  const auto ours_block = [&](auto first, auto last, CVT_2::Natural_neighbor_method method) {
    CDT::Face_handle& h = method == CVT_2::SIBSON ? f_sibson : f_laplace;
    for (; first != last; ++first) {
      h = cdt.locate(*first, h);
      out.clear();
      const auto result = CVT_2::natural_neighbor_coordinates_2(
          bvd, *first, std::back_inserter(out),
          CVT_2::parameters::hint(h).natural_neighbor_method(method));
      checksum += result.second;
      if (method == CVT_2::SIBSON) count_ours += out.size(), r.outside += !result.third;
    }
  };
  const auto cgal_block = [&](auto first, auto last) {
    for (; first != last; ++first) {
      g_sibson = dt.locate(*first, g_sibson);
      cgal_out.clear();
      const auto result = CGAL::natural_neighbor_coordinates_2(
          dt, *first, std::back_inserter(cgal_out),
          CGAL::Identity<std::pair<Dt::Vertex_handle, double>>(), g_sibson);
      checksum += result.second;
      count_cgal += cgal_out.size();
    }
  };
  // Load on a shared machine comes and goes within seconds: ours and CGAL alternate by blocks
  // of queries, each block timed, and the ratio is the median of the blocks' ratios.
  constexpr std::size_t block = 10000;
  for (auto _ : state) {
    double times[5] = {};  // walk ours, walk CGAL, ours, CGAL, Laplace: seconds
    count_ours = count_cgal = r.outside = 0;
    f_walk = f_sibson = f_laplace = CDT::Face_handle();
    g_walk = g_sibson = Dt::Face_handle();
    for (std::size_t b = 0; b < queries.size(); b += block) {
      const auto first = queries.begin() + std::ptrdiff_t(b);
      const auto last = queries.begin() + std::ptrdiff_t(std::min(queries.size(), b + block));
      Stopwatch t;
      walk_ours_block(first, last);
      times[0] += t.wall_s();
      t = Stopwatch();
      walk_cgal_block(first, last);
      times[1] += t.wall_s();
      t = Stopwatch();
      ours_block(first, last, CVT_2::SIBSON);
      const double ours_wall = t.wall_s(), ours_cpu = t.thread_s();
      t = Stopwatch();
      cgal_block(first, last);
      const double cgal_wall = t.wall_s(), cgal_cpu = t.thread_s();
      t = Stopwatch();
      ours_block(first, last, CVT_2::LAPLACE);
      times[4] += t.wall_s();
      times[2] += ours_wall;
      times[3] += cgal_wall;
      ratio.push_back(ours_wall / cgal_wall);
      ratio_cpu.push_back(ours_cpu / cgal_cpu);
    }
    benchmark::DoNotOptimize(&*f_walk);
    benchmark::DoNotOptimize(&*g_walk);
    walk_ours.push_back(times[0] * per_query);
    walk_cgal.push_back(times[1] * per_query);
    sibson.push_back(times[2] * per_query);
    cgal.push_back(times[3] * per_query);
    laplace.push_back(times[4] * per_query);

    // The batch numbers the nodes in a hash map, serial whatever the threads.
    Stopwatch t;
    std::size_t cells = 0;
    {
      CGAL::Unique_hash_map<Bvd::Vertex_handle, std::size_t> column(std::size_t(-1),
                                                                    cdt.number_of_vertices());
      for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
        if (bvd.has_cell(v)) column[v] = cells++;
    }
    numbering.push_back(t.wall_s() * per_query);
    benchmark::DoNotOptimize(cells);

    // The batch, its result freed outside the time.
    for (const auto method : {CVT_2::SIBSON, CVT_2::LAPLACE}) {
      const auto np = CVT_2::parameters::natural_neighbor_method(method);
      t = Stopwatch();
      const auto m1 = CVT_2::natural_neighbor_matrix_2(bvd, queries, np.number_of_threads(1u));
      const double s1 = t.wall_s() * per_query;
      t = Stopwatch();
      const auto m2 = CVT_2::natural_neighbor_matrix_2(bvd, queries, np.number_of_threads(2u));
      const double s2 = t.wall_s() * per_query;
      (method == CVT_2::SIBSON ? sibson_cores : laplace_cores)
          .push_back(t.process_s() / t.wall_s());
      r.same_bits = r.same_bits && same(m1, m2);
      (method == CVT_2::SIBSON ? sibson1 : laplace1).push_back(s1);
      (method == CVT_2::SIBSON ? sibson2 : laplace2).push_back(s2);
      (method == CVT_2::SIBSON ? sibson_speedup : laplace_speedup).push_back(s1 / s2);
    }
    state.SetIterationTime((walk_ours.back() + walk_cgal.back() + sibson.back() + cgal.back() +
                            laplace.back() + sibson1.back() + sibson2.back() + laplace1.back() +
                            laplace2.back()) /
                           per_query);
  }
  benchmark::DoNotOptimize(checksum);

  r.walk_ours = median(walk_ours);
  r.walk_cgal = median(walk_cgal);
  r.sibson = median(sibson);
  r.cgal = median(cgal);
  r.laplace = median(laplace);
  r.sibson1 = median(sibson1);
  r.sibson2 = median(sibson2);
  r.laplace1 = median(laplace1);
  r.laplace2 = median(laplace2);
  r.ratio = median(ratio);
  r.numbering = median(numbering);
  r.ratio_cpu = median(ratio_cpu);
  r.sibson_cores = median(sibson_cores);
  r.laplace_cores = median(laplace_cores);
  r.sibson_speedup = median(sibson_speedup);
  r.laplace_speedup = median(laplace_speedup);
  r.neighbours_ours = double(count_ours) / double(queries.size());
  r.neighbours_cgal = double(count_cgal) / double(queries.size());
  auto& c = state.counters;
  c["vertices"] = double(r.vertices);
  c["ours_us"] = r.sibson;
  c["cgal_us"] = r.cgal;
  c["ours/cgal"] = r.ratio;
  c["laplace_us"] = r.laplace;
  c["batch_1_thread_us"] = r.sibson1;
  c["batch_2_threads_us"] = r.sibson2;
  c["speedup"] = r.sibson_speedup;
  c["cores_2_threads"] = r.sibson_cores;
  const auto it = std::find_if(rows.begin(), rows.end(), [&r](const Row& x) {
    return x.domain == r.domain && x.nodes == r.nodes;
  });
  if (it == rows.end())
    rows.push_back(r);
  else
    *it = r;
}

}  // namespace

int main(int argc, char* argv[]) {
  std::vector<long> sizes{10000, 100000, 1000000};
  if (const char* s = std::getenv("CVT_2_NN_NODES"); s && *s) {
    sizes.clear();
    std::istringstream in(s);
    for (std::string item; std::getline(in, item, ',');) sizes.push_back(std::stol(item));
  }
  const std::size_t repetitions = env_size("CVT_2_NN_REPETITIONS", 3);
  const std::string load_before = load_average();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (const std::string& name : {square, massachusetts})
    for (const long n : sizes) {
      benchmark::RegisterBenchmark(("natural_neighbors/" + name).c_str(), bm_natural_neighbors,
                                   name)
          ->Arg(n)
          ->Iterations(static_cast<benchmark::IterationCount>(repetitions))
          ->UseManualTime()
          ->Unit(benchmark::kMillisecond);
    }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();

  const std::size_t queries = rows.empty() ? 0 : rows.front().queries;
  std::printf(
      "\nµs per query (wall-clock medians), %zu Hilbert-sorted queries in the domain, each "
      "located from the previous one's face (that walk is in the single-query columns; alone in "
      "'walk'). CGAL: natural_neighbor_coordinates_2() on a Delaunay_triangulation_2 of the same "
      "nodes. In brackets: ours/CGAL by thread CPU time; the cores the batch on 2 threads got.\n"
      "\n| domain | nodes | method | walk ours / CGAL | ours | CGAL | ours/CGAL (CPU) | "
      "batch 1 thread | batch 2 threads | 2 vs 1 (cores) |\n"
      "|---|--:|---|--:|--:|--:|--:|--:|--:|--:|\n",
      queries);
  for (const Row& r : rows) {
    const std::string walk = fmt("%.3f", r.walk_ours) + " / " + fmt("%.3f", r.walk_cgal);
    std::printf("| %s | %zu | Sibson | %s | %s | %s | %s (%s) | %s | %s | %sx (%s) |\n",
                r.domain.c_str(), r.nodes, walk.c_str(), fmt("%.3f", r.sibson).c_str(),
                fmt("%.3f", r.cgal).c_str(), fmt("%.2f", r.ratio).c_str(),
                fmt("%.2f", r.ratio_cpu).c_str(), fmt("%.3f", r.sibson1).c_str(),
                fmt("%.3f", r.sibson2).c_str(), fmt("%.2f", r.sibson_speedup).c_str(),
                fmt("%.2f", r.sibson_cores).c_str());
    std::printf("| %s | %zu | Laplace | %s | %s | – | – | %s | %s | %sx (%s) |\n", r.domain.c_str(),
                r.nodes, walk.c_str(), fmt("%.3f", r.laplace).c_str(),
                fmt("%.3f", r.laplace1).c_str(), fmt("%.3f", r.laplace2).c_str(),
                fmt("%.2f", r.laplace_speedup).c_str(), fmt("%.2f", r.laplace_cores).c_str());
  }
  std::printf(
      "\nChecks (natural neighbours per query, Sibson, ours / CGAL; queries ours found outside "
      "the domain; batch on 2 threads bit for bit as on 1; µs per query of the batch's serial pass "
      "numbering the nodes):\n");
  for (const Row& r : rows)
    std::printf("  %s/%zu (%zu vertices): %.3f / %.3f neighbours, %zu outside, %s, %.3f µs\n",
                r.domain.c_str(), r.nodes, r.vertices, r.neighbours_ours, r.neighbours_cgal,
                r.outside, r.same_bits ? "same bits" : "BITS DIFFER", r.numbering);
  std::printf("Load average: %s before, %s after.\n", load_before.c_str(), load_average().c_str());
  return 0;
}
