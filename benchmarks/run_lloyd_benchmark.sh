#!/bin/sh
# Configures and builds the benchmarks in build-bench (Release), runs the Lloyd one; the tables
# come last. CVT_2_BENCH_LARGE=1 adds N = 1e6; CVT_2_BENCH_MEMORY=4000000 adds the peak memory at
# that N (no timing). Extra arguments go to Google Benchmark, e.g.
# --benchmark_filter=unit_square
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$root/build-bench" -DCMAKE_BUILD_TYPE=Release -DCVT_2_BUILD_BENCHMARKS=ON \
      -DCVT_2_BUILD_TESTS=OFF -DCVT_2_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$root/build-bench" --target lloyd_benchmark -j 1
"$root/build-bench/benchmarks/lloyd_benchmark" "$@"
