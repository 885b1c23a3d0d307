#!/bin/sh
# The main job, on a fresh Debian machine: installs what it needs if missing, builds the cvt2
# program in build-main, installs it into ./install, and runs it:
# 6000 random generators in Kentucky, whose 120 county borders are inner constraints, optimized
# to a centroidal Voronoi tessellation (L-BFGS to the 1% stop). Writes results/kentucky.geojson
# (the cells), results/kentucky.svg and results/kentucky.png (the README's first picture: the
# cells coloured by the county of their generator, by scripts/plot_geojson_cells.py).
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
# ccache keeps what it compiles: the test command (scripts/run_tests.sh) compiles it with the
# same flags and takes it from the cache.
"$root/scripts/install_dependencies.sh" --only cmake g++ make ccache libcgal-dev \
  nlohmann-json3-dev python3-pil
# cvt2 alone (no tests, examples or Python module): two translation units, a minute each.
# Beside them, in a tree of its own (make builds one target at a time), the example of a crack
# that grows (build-examples/examples/crack_growth, to try): two cores kept busy, and the test
# command 40 s of a core less.
options="-DCMAKE_BUILD_TYPE=Release -DCVT_2_BUILD_TESTS=OFF -DCVT_2_BUILD_PYTHON=OFF"
cmake -S "$root" -B "$root/build-main" $options -DCVT_2_BUILD_EXAMPLES=OFF > /dev/null
cmake -S "$root" -B "$root/build-examples" $options -DCVT_2_BUILD_TOOLS=OFF > /dev/null
cmake --build "$root/build-examples" --target crack_growth > /dev/null &
example=$!
cmake --build "$root/build-main" --target cvt2 -j 2
wait $example
cmake --install "$root/build-main" --prefix "$root/install" > /dev/null
data="$root/examples/data"
out="$root/results"
mkdir -p "$out"
"$root/install/bin/cvt2" "$data/us_kentucky_counties.geojson" -n 6000 --quiet \
  --geojson "$out/kentucky.geojson" --svg "$out/kentucky.svg"
/usr/bin/python3 "$root/scripts/plot_geojson_cells.py" "$out/kentucky.geojson" \
  "$data/us_kentucky_counties.geojson" "$out/kentucky.png"
echo "cells: $out/kentucky.geojson  pictures: $out/kentucky.png, $out/kentucky.svg"
