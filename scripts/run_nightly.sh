#!/bin/sh
# The nightly property run: the random-domain tests (test/support/random_domain.h) on CASES
# domains (default 20000; the regular suite runs 400 for the diagram and 150 for Lloyd), in a
# Release build in build-nightly. Each domain is checked for the diagram's invariants (cells
# tile it, free cells convex and holding their generator, the nearest-visible-generator oracle)
# and 3 in 8 of them for Lloyd's (5 steps: no exception, energy never rises, generators stay).
set -e
cases=${1:-20000}
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_dependencies.sh"
cmake -S "$root" -B "$root/build-nightly" -DCMAKE_BUILD_TYPE=Release -DCVT_2_BUILD_EXAMPLES=OFF > /dev/null
cmake --build "$root/build-nightly" --target cvt_2_tests -j 2
start=$(date +%s)
CVT_2_RANDOM_CASES=$cases "$root/build-nightly/test/cvt_2_tests" "[random]"
echo "$cases random domains checked in $(( $(date +%s) - start )) s"
