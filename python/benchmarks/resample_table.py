# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""The table of the manual's "Resampling the boundary": `cvt2` on the bundled real domains,
every input vertex a generator (`--boundary keep -n N`) against the boundary resampled to the
cell size (`--boundary resample --cells N`) and resampled with vertices that slide along the
input (`--boundary slide --cells N`), uniform density, L-BFGS to the 1% stop.

    python3 python/benchmarks/resample_table.py build/tools/cvt2/cvt2 [DATA_DIR] [N ...]

Columns: the cells delivered; the share of them that are cells of the domain's vertices; specks
(below a tenth of the median cell) and cells below a quarter of it (and of those, how many
have an input vertex as generator: a feature, or a vertex the bound or the topology kept); the smallest over the median;
the normalized energy (1 for hexagons); for resample, the boundary vertices before and after and
the largest deviation from the input, relative to the cell size.
"""
import json
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile
import time

DOMAINS = ["world_land_110m.wkt", "france_mainland.poly", "us_kentucky_counties.geojson",
           "us_massachusetts_counties.wkt", "earcut_dude.poly", "four_clusters.poly",
           "square_inner_constraints.poly"]


def input_vertices(cvt2, domain, tmp):
    """The domain's own vertices on constraints (junctions, corners, every vertex kept)."""
    out = pathlib.Path(tmp) / "own.txt"
    subprocess.run([cvt2, str(domain), "-n", "0", "--iterations", "0", "--quiet", "--points-out",
                    str(out)], check=True, capture_output=True)
    return {(x, y) for x, y, c in (map(float, line.split()) for line in out.read_text().splitlines())
            if c == 1}


def run(cvt2, domain, mode, n, tmp):
    out = pathlib.Path(tmp) / "cells.geojson"
    count = ["-n", str(n)] if mode == "keep" else ["--cells", str(n)]
    start = time.perf_counter()
    p = subprocess.run([cvt2, str(domain), "--boundary", mode, *count, "--geojson", str(out)],
                       capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if p.returncode:
        return {"error": p.stderr.strip().splitlines()[0]}
    summary = dict(kv.split("=", 1) for kv in p.stdout.split())
    features = json.loads(out.read_text())["features"]
    areas = [f["properties"]["area"] for f in features]
    constrained = sum(f["properties"]["constrained"] for f in features)
    median = statistics.median(areas)
    own = input_vertices(cvt2, domain, tmp)
    row = {"cells": len(areas), "constrained": constrained / len(areas),
           "specks": sum(a < 0.1 * median for a in areas) / len(areas),
           "quarter": sum(a < 0.25 * median for a in areas),
           "quarter_at_input": sum(a < 0.25 * median and tuple(f["properties"]["generator"]) in own
                                   for a, f in zip(areas, features)),
           "smallest": min(areas) / median, "energy": float(summary["normalized_energy"]),
           "iterations": int(summary["iterations"]), "seconds": seconds}
    m = re.search(r"cell size (\S+): (\d+) vertices on constraints -> (\d+) .*largest deviation (\S+),",
                  p.stderr)
    if m:
        row["boundary"] = f"{m.group(2)} → {m.group(3)}"
        row["deviation"] = float(m.group(4)) / float(m.group(1))
    return row


def main():
    cvt2 = sys.argv[1]
    data = pathlib.Path(sys.argv[2] if len(sys.argv) > 2 else "examples/data")
    sizes = [int(a) for a in sys.argv[3:]] or [2000, 20000]
    print("| domain | N | mode | cells | of vertices | specks | < ¼ median (at input vertices) | smallest / median "
          "| normalized energy | boundary vertices | deviation / size | iterations | ms an iteration |")
    print("|---|--:|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
    with tempfile.TemporaryDirectory() as tmp:
        for name in DOMAINS:
            for n in sizes:
                for mode in ("keep", "resample", "slide"):
                    r = run(cvt2, data / name, mode, n, tmp)
                    if "error" in r:
                        print(f"| {name} | {n} | {mode} | {r['error']} |||||||")
                        continue
                    deviation = f"{r['deviation']:.3f}" if "deviation" in r else ""
                    print(f"| {name} | {n} | {mode} | {r['cells']} | {r['constrained']:.1%} | "
                          f"{r['specks']:.1%} | {r['quarter']} ({r['quarter_at_input']}) | {r['smallest']:.1e} | "
                          f"{r['energy']:.3f} | {r.get('boundary', '')} | {deviation} | "
                          f"{r['iterations']} | {1000 * r['seconds'] / max(r['iterations'], 1):.2f} |",
                          flush=True)

if __name__ == "__main__":
    main()
