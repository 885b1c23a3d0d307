#!/bin/sh
# Installs what is missing, builds the examples, and runs bvd_cells on bundled data:
# the bounded Voronoi diagram of 500 generators in a square with inner constraints.
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_dependencies.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$root/build" --target bvd_cells -j 2
"$root/build/examples/bvd_cells" "$root/examples/data/four_clusters.poly" \
  "$root/examples/data/four_clusters_points.txt" "$root/bvd_cells.svg" > "$root/bvd_cells.txt"
echo "cells: $root/bvd_cells.txt (x y c k x1 y1 ... xk yk per vertex)  picture: $root/bvd_cells.svg"
head -n 3 "$root/bvd_cells.txt"
