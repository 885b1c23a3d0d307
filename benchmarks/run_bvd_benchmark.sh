#!/bin/sh
# Configures and builds the benchmarks in build-bench (Release), runs them; the table comes last.
# Extra arguments go to Google Benchmark, e.g. --benchmark_filter=massachusetts
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$root/build-bench" -DCMAKE_BUILD_TYPE=Release -DCVT_2_BUILD_BENCHMARKS=ON \
      -DCVT_2_BUILD_TESTS=OFF -DCVT_2_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$root/build-bench" --target bvd_benchmark -j 1
"$root/build-bench/benchmarks/bvd_benchmark" "$@"
