#!/bin/sh
# Builds the libFuzzer targets with clang in build-fuzz and runs each in turn for
# SECONDS_PER_TARGET (default 60). The corpus grows in build-fuzz/corpus/<target> (seeded from
# examples/data; for GeoJSON also test/hostile and Kentucky's counties, alone and in fours),
# findings land in build-fuzz/findings/<target>, logs in build-fuzz/logs.
# Replay a finding with: build-fuzz/fuzz/<target> FILE
set -e
seconds=${1:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-fuzz"
data="$root/examples/data"

"$root/scripts/install_dependencies.sh" clang
# libFuzzer's runtime ships separately on some Debian releases (libclang-rt-N-dev).
probe=$(mktemp -d)
printf 'extern "C" int LLVMFuzzerTestOneInput(const char*, unsigned long) { return 0; }\n' > "$probe/p.cpp"
if ! clang++ -fsanitize=fuzzer "$probe/p.cpp" -o "$probe/p" > /dev/null 2>&1; then
  "$root/scripts/install_dependencies.sh" "libclang-rt-$(clang++ -dumpversion | cut -d. -f1)-dev"
fi
rm -rf "$probe"

CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCVT_2_BUILD_FUZZERS=ON \
  -DCVT_2_BUILD_TESTS=OFF -DCVT_2_BUILD_EXAMPLES=OFF -DCVT_2_BUILD_PYTHON=OFF > /dev/null
mkdir -p "$build/logs"
if ! cmake --build "$build" -j 2 > "$build/logs/build.log" 2>&1; then
  tail -n 40 "$build/logs/build.log"
  exit 1
fi

# Seeds: copied at run time, never committed twice. The pipeline only takes inputs <= 8 KB.
seed() {  # seed TARGET MAX_BYTES FILE...
  target=$1 max=$2
  shift 2
  mkdir -p "$build/corpus/$target" "$build/findings/$target"
  for f in "$@"; do
    [ -f "$f" ] && [ "$(wc -c < "$f")" -le "$max" ] || continue
    [ -e "$build/corpus/$target/$(basename "$f")" ] || cp "$f" "$build/corpus/$target/"
  done
}
seed fuzz_read_poly 1000000 "$data"/*.poly
seed fuzz_read_wkt 1000000 "$data"/*.wkt
seed fuzz_read_points 1000000 "$data"/four_clusters_points.txt
# Small GeoJSON seeds: each county of Kentucky alone, and in fours (shared borders become inner
# constraints); the whole state exceeds the inputs' length.
mkdir -p "$build/seeds"
/usr/bin/python3 - "$data/us_kentucky_counties.geojson" "$build/seeds" <<'PY'
import json, sys
features = json.load(open(sys.argv[1]))["features"]
groups = [[f] for f in features] + [features[i:i + 4] for i in range(0, len(features), 4)]
for i, parts in enumerate(groups):
    with open(f"{sys.argv[2]}/kentucky_{i:03d}.geojson", "w") as f:
        json.dump({"type": "FeatureCollection", "features": parts}, f)
PY
seed fuzz_read_geojson 1000000 "$data"/*.geojson "$root"/test/hostile/*.geojson "$build"/seeds/*.geojson
seed fuzz_pipeline 8192 "$data"/*.poly "$data"/*.wkt "$build"/seeds/*.geojson

status=0
summary=""
# The WKT and GeoJSON targets' dictionaries add the format's keywords to the number spellings;
# the pipeline's has all three formats'.
cat "$root/fuzz/numbers.dict" "$root/fuzz/wkt.dict" > "$build/wkt_and_numbers.dict"
cat "$root/fuzz/numbers.dict" "$root/fuzz/json.dict" > "$build/json_and_numbers.dict"
cat "$root/fuzz/numbers.dict" "$root/fuzz/wkt.dict" "$root/fuzz/json.dict" > "$build/all.dict"
for spec in fuzz_read_poly:16384 fuzz_read_wkt:16384 fuzz_read_geojson:16384 \
            fuzz_read_points:8192 fuzz_pipeline:8192; do
  target=${spec%%:*} max_len=${spec#*:}
  echo "running $target for $seconds s"
  log="$build/logs/$target.log"
  case $target in
    fuzz_read_wkt) dict="$build/wkt_and_numbers.dict" ;;
    fuzz_read_geojson) dict="$build/json_and_numbers.dict" ;;
    fuzz_pipeline) dict="$build/all.dict" ;;
    *) dict="$root/fuzz/numbers.dict" ;;
  esac
  start=$(date +%s)
  # One process at a time; a hang is an input that takes over 10 s.
  if "$build/fuzz/$target" "$build/corpus/$target" -max_total_time="$seconds" -max_len="$max_len" \
       -timeout=10 -dict="$dict" -print_final_stats=1 \
       -artifact_prefix="$build/findings/$target/" > "$log" 2>&1; then
    result="no finding"
  else
    what=$(grep -m 1 -E 'ORACLE VIOLATED|ERROR: |runtime error|CGAL ERROR' "$log" || true)
    result="FINDING: $what (see $log and $build/findings/$target/)"
    status=1
  fi
  elapsed=$(( $(date +%s) - start ))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  corpus=$(find "$build/corpus/$target" -type f | wc -l)
  summary="$summary$target: ${runs:-?} executions in $elapsed s, corpus $corpus files, $result
"
done
printf '%s' "$summary"
exit $status
