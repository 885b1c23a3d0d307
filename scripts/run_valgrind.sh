#!/bin/sh
# Runs the whole pipeline once under valgrind's memcheck on small cases (the examples of the
# Release build that scripts/run_tests.sh makes, built here if missing): any error or leak
# fails the run.
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_dependencies.sh" valgrind
if [ ! -x "$root/build/tools/cvt2/cvt2" ] || [ ! -x "$root/build/examples/bvd_cells" ] ||
   [ ! -x "$root/build/examples/bvd_edit" ]; then
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release > /dev/null
  cmake --build "$root/build" --target cvt2 bvd_cells bvd_edit -j 2
fi
data="$root/examples/data"
out=$(mktemp -d)
check() {
  valgrind --quiet --error-exitcode=1 --leak-check=full --errors-for-leak-kinds=definite,indirect "$@"
}
check "$root/build/examples/bvd_cells" "$data/four_clusters.poly" "$data/four_clusters_points.txt" \
  "$out/bvd.svg" > /dev/null
check "$root/build/examples/bvd_edit" "$data/square_inner_constraints.poly" "$data/square_points.txt" \
  "$data/square_edits.txt" --verify --relax-rings 2 --relax-iterations 3 --cells-out "$out/edit.txt" \
  > /dev/null
check "$root/build/tools/cvt2/cvt2" "$data/four_clusters.poly" --iterations 10 --quiet \
  --svg "$out/a.svg" --geojson "$out/a.geojson" --vtu "$out/a.vtu" --disv "$out/a.disv" \
  --cells-out "$out/a.txt" --mesh-out "$out/a"
check "$root/build/tools/cvt2/cvt2" "$data/earcut_dude.poly" -n 300 --density lipschitz \
  --iterations 5 --quiet --algorithm lloyd
check "$root/build/tools/cvt2/cvt2" "$data/four_clusters.wkt" -n 20000 --iterations 3 --quiet \
  --geojson "$out/b.geojson"  # threads
check "$root/build/tools/cvt2/cvt2" "$data/us_kentucky_counties.geojson" -n 3000 --iterations 3 --quiet \
  --geojson "$out/c.geojson" --disv "$out/c.disv"
check "$root/build/tools/cvt2/cvt2" "$data/world_land_110m.wkt" --boundary resample --cells 1500 \
  --minimum-ring-area 10 --iterations 2 --quiet --vtu "$out/d.vtu" --domain-out "$out/d.poly"
printf '2.5 7.25\n7.125 2.75\n' > "$out/wells.txt"
check "$root/build/tools/cvt2/cvt2" "$data/square_inner_constraints.wkt" -n 400 --iterations 5 --quiet \
  --constraints barrier --fixed-points "$out/wells.txt" --refine 2.5 7.25 0.1 2 --disv "$out/e.disv" \
  --geojson "$out/e.geojson" --vtu "$out/e.vtu" --cells-on-constraints "$out/e.csv"
check "$root/build/tools/cvt2/cvt2" "$data/aquifer.geojson" --cells 600 --iterations 5 --quiet \
  --fixed-points "$data/aquifer_wells.txt" --refine 480 640 12 300 --disv "$out/f.disv" \
  --geojson "$out/f.geojson" --cells-on-constraints "$out/f.csv"  # a barrier and a river
rm -r "$out"
echo "valgrind: no error, no leak"
