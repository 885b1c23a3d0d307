#!/bin/sh
# Feeds each file of test/hostile/expected.txt to cvt2 and bvd_cells: each must fail with exit
# status 1 and the expected message and write no output file (or, for 'ok:' lines, succeed),
# within 60 s. Usage: run_hostile.sh CVT2 BVD_CELLS HOSTILE_DIR
cvt2=$1 bvd_cells=$2 dir=$3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
failed=0 tried=0
check() {  # check NAME EXPECTED PROGRAM ARGS...
  name=$1 expected=$2
  shift 2
  rm -f "$out"/*
  timeout 60 "$@" > "$out/stdout" 2> "$out/stderr"
  status=$?
  tried=$((tried + 1))
  case $expected in
    ok:*) want=0 text=${expected#ok:} ;;
    *) want=1 text=$expected ;;
  esac
  problem=""
  [ "$status" -eq "$want" ] || problem="exit status $status, expected $want"
  grep -qF -- "$text" "$out/stderr" || problem="$problem; stderr lacks '$text'"
  if [ "$want" -eq 1 ] && ls "$out"/out.* > /dev/null 2>&1; then problem="$problem; wrote an output file"; fi
  if [ -n "$problem" ]; then
    failed=$((failed + 1))
    echo "FAIL $name ($(basename "$1")): $problem"
    sed 's/^/  | /' "$out/stderr" | head -n 5
  fi
}
while IFS='|' read -r file expected; do
  file=$(echo "$file" | sed 's/ *$//') expected=$(echo "$expected" | sed 's/^ *//')
  case $file in ''|'#'*) continue ;; esac
  case $file in
    *.txt)
      check "$file" "$expected" "$cvt2" "$dir/square.poly" --points-in "$dir/$file" -n 0 \
        --svg "$out/out.svg" --points-out "$out/out.txt" --iterations 20
      check "$file" "$expected" "$bvd_cells" "$dir/square.poly" "$dir/$file" "$out/out.svg" ;;
    *)
      check "$file" "$expected" "$cvt2" "$dir/$file" -n 20 --svg "$out/out.svg" \
        --points-out "$out/out.txt" --iterations 20
      check "$file" "$expected" "$bvd_cells" "$dir/$file" "/dev/null" "$out/out.svg" ;;
  esac
done < "$dir/expected.txt"
echo "$tried runs on hostile input, $failed failed"
[ "$failed" -eq 0 ]
