#!/bin/sh
# Compares two cvt2 programs' outputs, for a change that must not change results (a refactor):
# on five bundled real domains, L-BFGS and Lloyd, uniform and Lipschitz densities, 1000 random
# generators, the --points-out and --cells-out files must be byte-identical.
#   sh scripts/compare_outputs.sh OLD_CVT2 NEW_CVT2
set -e
old=$1 new=$2
data=$(cd "$(dirname "$0")/../examples/data" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
for domain in france_mainland.poly us_massachusetts_counties.poly earcut_dude.wkt \
              world_land_110m.poly us_kentucky_counties.geojson; do
  for algorithm in lbfgs lloyd; do
    for density in uniform lipschitz; do
      for which in old new; do
        eval program=\$$which
        "$program" "$data/$domain" -n 1000 --algorithm $algorithm --density $density --quiet \
          --points-out "$tmp/$which.points" --cells-out "$tmp/$which.cells" > "$tmp/$which.out"
      done
      if cmp -s "$tmp/old.points" "$tmp/new.points" && cmp -s "$tmp/old.cells" "$tmp/new.cells"
      then verdict=same; else verdict=DIFFERENT; status=1; fi
      echo "$domain $algorithm $density: $verdict ($(cut -d' ' -f2-4 "$tmp/new.out"))"
    done
  done
done
exit $status
