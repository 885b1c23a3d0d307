#!/bin/sh
# Rebuilds the figures of the README, the manual and benchmarks/README.md (doc/fig/*.png) from
# the examples, each run with its defaults; needs rsvg-convert (Debian: librsvg2-bin), pngquant
# and python3. Takes about 2 minutes once built. CVT_2_BUILD_DIR: the build directory (default
# build); JOBS: parallel compile jobs (2). CVT_2_CONVERGENCE_CSV: the CSV the L-BFGS benchmark
# writes (see benchmarks/README.md), drawn as doc/fig/convergence.png by
# scripts/plot_convergence.py; `make_figures.sh convergence` draws only that one.
# CVT_2_SPEED_DIR: a directory holding the printed outputs of the speed runs that
# benchmarks/README.md lists (lloyd.txt, scaling.txt, scaling_1_thread.txt), drawn as
# doc/fig/speed.png by scripts/plot_speed.py; `make_figures.sh speed` draws only that one.
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
build=${CVT_2_BUILD_DIR:-$root/build}
csv=${CVT_2_CONVERGENCE_CSV:-}
[ -z "$csv" ] || csv=$(cd "$(dirname "$csv")" && pwd)/$(basename "$csv")
if [ "$1" = convergence ] && [ -z "$csv" ]; then
  echo "make_figures.sh convergence: set CVT_2_CONVERGENCE_CSV to the benchmark's CSV" >&2
  exit 1
fi
speed=${CVT_2_SPEED_DIR:-}
[ -z "$speed" ] || speed=$(cd "$speed" && pwd)
if [ "$1" = speed ] && [ -z "$speed" ]; then
  echo "make_figures.sh speed: set CVT_2_SPEED_DIR to the directory of the speed runs' outputs" >&2
  exit 1
fi
"$root/scripts/install_dependencies.sh" librsvg2-bin pngquant python3-matplotlib
ex="$build/examples"
data="$root/examples/data"
fig="$root/doc/fig"
tmp=$(mktemp -d)

# png WIDTH IN.svg OUT.png: rendered WIDTH pixels wide, in 64 colours (a third of the bytes).
png() {
  rsvg-convert -w "$1" "$2" -o "$tmp/render.png"
  pngquant --force --output "$3" 64 "$tmp/render.png"
}
# combine row|column OUT.svg IN.svg...: the pictures side by side or one above the other.
combine() {
  python3 - "$@" <<'PY'
import re, sys
layout, out, inputs = sys.argv[1], sys.argv[2], sys.argv[3:]
parts, x, y, w, h = [], 0, 0, 0, 0
for name in inputs:
    s = open(name).read()
    pw = float(re.search(r'width="([0-9.]+)"', s).group(1))
    ph = float(re.search(r'height="([0-9.]+)"', s).group(1))
    parts.append(re.sub(r"<svg ", f'<svg x="{x}" y="{y}" ', s, count=1))
    w, h = max(w, x + pw), max(h, y + ph)
    if layout == "row":
        x += pw + 20
    else:
        y += ph + 20
open(out, "w").write(
    f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}">'
    '<rect width="100%" height="100%" fill="white"/>' + "".join(parts) + "</svg>")
PY
}

cd "$tmp"
if [ "$1" != convergence ] && [ "$1" != speed ]; then
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" -j "${JOBS:-2}" --target bvd_cells lloyd_four_clusters lloyd_uniform \
  custom_density lloyd_adaptive lloyd_france lloyd_world lloyd_curved_hole cvt2 \
  crack_interpolation

"$ex/bvd_cells" "$data/four_clusters.poly" "$data/four_clusters_points.txt" bvd.svg > /dev/null
png 700 bvd.svg "$fig/bvd_four_clusters.png"

"$ex/lloyd_four_clusters" "$data/four_clusters.poly" lloyd
combine row fig.svg lloyd_0.svg lloyd_10.svg lloyd_converged.svg
png 1200 fig.svg "$fig/lloyd_four_clusters.png"

"$ex/lloyd_uniform"
"$ex/custom_density"
combine row fig.svg lloyd_uniform.svg custom_density.svg
png 1200 fig.svg "$fig/lloyd_uniform_custom_density.png"

"$ex/lloyd_adaptive"
png 1200 lloyd_adaptive.svg "$fig/lloyd_adaptive.png"

"$ex/lloyd_france" | grep -v '^ '
png 1000 lloyd_france.svg "$fig/lloyd_france.png"

"$ex/lloyd_world"
combine column fig.svg lloyd_world_uniform.svg lloyd_world_adaptive.svg
png 1200 fig.svg "$fig/lloyd_world.png"

"$ex/lloyd_curved_hole"
combine row fig.svg lloyd_curved_hole_uniform.svg lloyd_curved_hole_adaptive.svg
png 1200 fig.svg "$fig/lloyd_curved_hole.png"

# What scripts/run_main_job.sh makes (the README's first picture), with this build's cvt2.
"$build/tools/cvt2/cvt2" "$data/us_kentucky_counties.geojson" -n 6000 --quiet \
  --geojson kentucky.geojson > /dev/null
/usr/bin/python3 "$root/scripts/plot_geojson_cells.py" kentucky.geojson \
  "$data/us_kentucky_counties.geojson" "$fig/kentucky_counties.png"

PYTHONPATH="$build/python" /usr/bin/python3 "$root/python/examples/density_response.py" \
  density_response.png
pngquant --force --output "$fig/density_response.png" 64 density_response.png

PYTHONPATH="$build/python" /usr/bin/python3 "$root/python/examples/resample.py" "$data" \
  resample.png
pngquant --force --output "$fig/resample.png" 64 resample.png

# A river past a well (the manual's conforming lines): without it, and made conforming.
printf 'POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0))\n' > square.wkt
{ cat square.wkt; printf 'LINESTRING (0 5.2, 10 4.8)\n'; } > river.wkt
"$build/tools/cvt2/cvt2" square.wkt --cells 3000 --refine 5 5.5 0.05 2 --quiet \
  --geojson alone.geojson > /dev/null
"$build/tools/cvt2/cvt2" river.wkt --cells 3000 --refine 5 5.5 0.05 2 --quiet \
  --constraints conforming --geojson river.geojson > /dev/null
/usr/bin/python3 "$root/scripts/plot_conforming_refined.py" alone.geojson river.geojson \
  conforming_refined.png
pngquant --force --output "$fig/conforming_refined.png" 64 conforming_refined.png

"$build/tools/cvt2/cvt2" "$data/aquifer.geojson" --cells 2500 --quiet \
  --fixed-points "$data/aquifer_wells.txt" --refine 480 640 12 300 --refine 1560 520 12 300 \
  --geojson aquifer_cells.geojson > /dev/null
/usr/bin/python3 "$root/scripts/plot_modflow_grid.py" aquifer_cells.geojson "$data" modflow_grid.png
pngquant --force --output "$fig/modflow_grid.png" 64 modflow_grid.png

"$build/tools/cvt2/cvt2" "$data/river_network.wkt" --cells 3000 --constraints conforming --quiet \
  --geojson network.geojson --cells-on-constraints network.csv > /dev/null
/usr/bin/python3 "$root/scripts/plot_conforming_network.py" network.geojson network.csv \
  "$data/river_network.wkt" network.png
pngquant --force --output "$fig/conforming_network.png" 64 network.png

"$ex/crack_interpolation" crack.txt
/usr/bin/python3 "$root/scripts/plot_crack_interpolation.py" crack.txt crack.png
pngquant --force --output "$fig/crack_interpolation.png" 64 crack.png

PYTHONPATH="$build/python" /usr/bin/python3 "$root/scripts/plot_crack_growth.py" crack_growth.png
pngquant --force --output "$fig/crack_growth.png" 64 crack_growth.png
fi

if [ -n "$csv" ] && [ "$1" != speed ]; then
  python3 "$root/scripts/plot_convergence.py" "$csv" convergence.svg
  png 1000 convergence.svg "$fig/convergence.png"
fi

if [ -n "$speed" ] && [ "$1" != convergence ]; then
  one_thread=""
  [ ! -f "$speed/scaling_1_thread.txt" ] || one_thread="$speed/scaling_1_thread.txt"
  /usr/bin/python3 "$root/scripts/plot_speed.py" "$speed/lloyd.txt" "$speed/scaling.txt" \
    $one_thread speed.png
  pngquant --force --output "$fig/speed.png" 64 speed.png
fi

cd "$root"
rm -r "$tmp"
ls -l "$fig"
