#!/bin/sh
# Configures and builds the benchmarks (Release) in build-bench, or in $CVT_2_BENCH_BUILD, and runs
# the L-BFGS one (about 2 minutes); the tables come last. CVT_2_CONVERGENCE_CSV=path also writes
# the energy histories of the convergence plot (scripts/plot_convergence.py); CVT_2_BENCH_LARGE=1
# adds CGAL's optimizer to the 1% stop at N = 1e5 (up to 12 more minutes). Extra arguments go
# to Google Benchmark, e.g. --benchmark_filter=unit_square
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CVT_2_BENCH_BUILD:-$root/build-bench}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCVT_2_BUILD_BENCHMARKS=ON \
      -DCVT_2_BUILD_TESTS=OFF -DCVT_2_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$build" --target lbfgs_benchmark -j 1
"$build/benchmarks/lbfgs_benchmark" "$@"
