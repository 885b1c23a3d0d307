#!/bin/sh
# Configures and builds the benchmarks in build-bench (Release), runs the natural-neighbour one
# on both domains at 1e4, 1e5 and 1e6 nodes, 1e6 queries each (about 5 minutes on 2 idle cores);
# the table comes last. CVT_2_NN_NODES=10000,100000 keeps those node counts, CVT_2_NN_QUERIES and
# CVT_2_NN_REPETITIONS set the queries and repetitions. Extra arguments go to Google Benchmark,
# e.g. --benchmark_filter=unit_square
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$root/build-bench" -DCMAKE_BUILD_TYPE=Release -DCVT_2_BUILD_BENCHMARKS=ON \
      -DCVT_2_BUILD_TESTS=OFF -DCVT_2_BUILD_EXAMPLES=OFF -DCVT_2_BUILD_TOOLS=OFF \
      -DCVT_2_BUILD_PYTHON=OFF > /dev/null
cmake --build "$root/build-bench" --target natural_neighbors_benchmark -j 1
"$root/build-bench/benchmarks/natural_neighbors_benchmark" "$@"
