#!/bin/sh
# The cost of a uniform Lloyd iteration per generator from 10^4 to 4*10^6 generators, read by
# `cvt2 --points-in` from files of uniform random points in the unit square, in random order
# (as a user's file comes, not spatially sorted). Builds cvt2 in build-bench (Release), then, for
# each N, runs it with 1 and with 1 + K iterations, in alternating pairs, and takes the median of
# the pairs' differences of optimization time (cvt2's seconds=): reading, inserting and the first
# evaluation cancel out. Prints one table row per N, its cost per generator as a ratio to that at
# 10^5 last. About 3 minutes; the 4*10^6 runs peak near 1 GB.
#   CVT_2_SCALING_SIZES   the N (default "10000 100000 1000000 4000000")
#   CVT_2_SCALING_K       iterations timed a run (default 10)
#   CVT_2_SCALING_THREADS cvt2 --threads (default 0: all cores)
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
sizes=${CVT_2_SCALING_SIZES:-"10000 100000 1000000 4000000"}
k=${CVT_2_SCALING_K:-10}
threads=${CVT_2_SCALING_THREADS:-0}
cmake -S "$root" -B "$root/build-bench" -DCMAKE_BUILD_TYPE=Release -DCVT_2_BUILD_BENCHMARKS=ON \
      -DCVT_2_BUILD_TESTS=OFF -DCVT_2_BUILD_EXAMPLES=OFF -DCVT_2_BUILD_PYTHON=OFF > /dev/null
cmake --build "$root/build-bench" --target cvt2 -j 2
cvt2="$root/build-bench/tools/cvt2/cvt2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# seconds= of one run of cvt2 on the points with $1 iterations
seconds() {
  "$cvt2" "$root/test/hostile/square.poly" --points-in "$work/points.txt" --algorithm lloyd \
    --iterations "$1" --move-ratio 0 --threads "$threads" --quiet |
    sed -n 's/.* seconds=\([0-9.e+-]*\).*/\1/p'
}
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

base=""
for n in $sizes; do
  # points strictly inside the square, seeded, in the order drawn
  awk -v n="$n" 'BEGIN { srand(7); for (i = 0; i < n; ++i)
    printf "%.17g %.17g\n", 1e-9 + rand() * (1 - 2e-9), 1e-9 + rand() * (1 - 2e-9) }' \
    > "$work/points.txt"
  pairs=$((n >= 4000000 ? 3 : n >= 1000000 ? 5 : 9))
  : > "$work/diffs"
  i=0
  while [ "$i" -lt "$pairs" ]; do
    t1=$(seconds 1)
    tk=$(seconds $((k + 1)))
    [ -n "$t1" ] && [ -n "$tk" ] || { echo "run_scaling: cvt2 failed at N = $n" >&2; exit 1; }
    echo "$t1 $tk" | awk -v k="$k" '{ printf "%.9g\n", ($2 - $1) / k }' >> "$work/diffs"
    i=$((i + 1))
  done
  it=$(median < "$work/diffs")
  ns=$(awk -v t="$it" -v n="$n" 'BEGIN { printf "%.0f", t / n * 1e9 }')
  [ "$n" = 100000 ] && base=$ns
  echo "$n $pairs $it $ns" >> "$work/rows"
done
echo "| N | pairs | s/iteration | ns/generator | / at 10^5 |"
echo "|--:|--:|--:|--:|--:|"
while read -r n pairs it ns; do
  ratio=$( [ -n "$base" ] && awk -v a="$ns" -v b="$base" 'BEGIN { printf "%.2f", a / b }' || echo "-")
  echo "| $n | $pairs | $it | $ns | $ratio |"
done < "$work/rows"
