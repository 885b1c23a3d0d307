#!/bin/sh
# Rebuilds the README's figures (doc/fig/*.png) from the examples; needs rsvg-convert
# (Debian: librsvg2-bin) and python3.
set -e
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_dependencies.sh" librsvg2-bin
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$root/build" --target bvd_cells lloyd_four_clusters -j 2
tmp=$(mktemp -d)
"$root/build/examples/bvd_cells" "$root/examples/data/four_clusters.poly" \
  "$root/examples/data/four_clusters_points.txt" "$tmp/bvd.svg" > /dev/null
rsvg-convert -w 700 "$tmp/bvd.svg" -o "$root/doc/fig/bvd_four_clusters.png"
(cd "$tmp" && "$root/build/examples/lloyd_four_clusters" "$root/examples/data/four_clusters.poly" lloyd)
python3 - "$tmp" <<'PY'
import re, sys
d = sys.argv[1]
out, x, h = [], 0, 0
for name in ("lloyd_0.svg", "lloyd_10.svg", "lloyd_converged.svg"):  # side by side
    s = open(f"{d}/{name}").read()
    w = float(re.search(r'width="([0-9.]+)"', s).group(1))
    h = float(re.search(r'height="([0-9.]+)"', s).group(1))
    out.append(re.sub(r"<svg ", f'<svg x="{x}" y="0" ', s, count=1))
    x += w + 20
open(f"{d}/fig.svg", "w").write(
    f'<svg xmlns="http://www.w3.org/2000/svg" width="{x - 20}" height="{h}">'
    '<rect width="100%" height="100%" fill="white"/>' + "".join(out) + "</svg>")
PY
rsvg-convert -w 1200 "$tmp/fig.svg" -o "$root/doc/fig/lloyd_four_clusters.png"
rm -r "$tmp"
echo "figures in $root/doc/fig"
