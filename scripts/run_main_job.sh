#!/bin/sh
# The main job, on a fresh Debian machine: installs what it needs if missing, builds only the
# cvt2 program (one translation unit) in build-main, installs it into ./install, and runs it:
# 6000 random generators in Kentucky, whose 120 county borders are inner constraints, optimized
# to a centroidal Voronoi tessellation (L-BFGS to the 1% stop). Writes results/kentucky.geojson
# (the cells), results/kentucky.svg and results/kentucky.png (the README's first picture: the
# cells coloured by the county of their generator, by scripts/plot_geojson_cells.py).
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
# ccache keeps the compiled cvt2: the test command (scripts/run_tests.sh) compiles it with the
# same flags and takes it from the cache, a minute and a half of a core.
"$root/scripts/install_dependencies.sh" --only cmake g++ make ccache libcgal-dev \
  nlohmann-json3-dev python3-pil
# No tests, examples or Python module: cvt2 alone, so the configuration finds only what it uses.
cmake -S "$root" -B "$root/build-main" -DCMAKE_BUILD_TYPE=Release -DCVT_2_BUILD_TESTS=OFF \
  -DCVT_2_BUILD_EXAMPLES=OFF -DCVT_2_BUILD_PYTHON=OFF > /dev/null
cmake --build "$root/build-main" --target cvt2 -j 2
cmake --install "$root/build-main" --prefix "$root/install" > /dev/null
data="$root/examples/data"
out="$root/results"
mkdir -p "$out"
"$root/install/bin/cvt2" "$data/us_kentucky_counties.geojson" -n 6000 --quiet \
  --geojson "$out/kentucky.geojson" --svg "$out/kentucky.svg"
/usr/bin/python3 "$root/scripts/plot_geojson_cells.py" "$out/kentucky.geojson" \
  "$data/us_kentucky_counties.geojson" "$out/kentucky.png"
echo "cells: $out/kentucky.geojson  pictures: $out/kentucky.png, $out/kentucky.svg"
