#!/usr/bin/env python3
# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Draws the speed of a uniform Lloyd iteration from the benchmarks' printed tables.

    plot_speed.py LLOYD.txt SCALING.txt [SCALING_ONE_THREAD.txt] OUT.png

LLOYD.txt: the output of `run_lloyd_benchmark.sh --benchmark_filter=lloyd_iteration/unit_square`
(its unit-square rows: a CGAL constrained Delaunay build, our iteration and CGAL's optimizer's,
from the same points in one run). SCALING.txt: the output of `run_scaling.sh` (our iteration per
generator from a file in random order), on all cores; SCALING_ONE_THREAD.txt the same with
CVT_2_SCALING_THREADS=1. Left: seconds against N, log-log, each ratio to the CDT build written
and CGAL's optimizer's to ours written beside their points. Right: nanoseconds a generator against N, with the issue's line, 1.2 times the
cost at 10^5. Needs matplotlib (Debian: python3-matplotlib)."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def tables(path):
    """Every markdown table of the file: a list of rows, each a {header: cell} dict."""
    found, header = [], None
    for line in open(path, encoding="utf-8"):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if not line.startswith("|"):
            header = None
        elif header is None:
            header = cells
            found.append([])
        elif not set(line) <= set("|-: \n"):
            found[-1].append(dict(zip(header, cells)))
    return found


def column(path, key, value, wanted_header, where=None):
    """(N, value) pairs of the first table with `wanted_header`, rows kept by `where`."""
    for table in tables(path):
        if table and wanted_header in table[0]:
            rows = [r for r in table if where is None or where(r)]
            return [(float(r[key]), float(r[value].split()[0])) for r in rows if r[value] not in ("", "–")]
    sys.exit(f"plot_speed: no table with a '{wanted_header}' column in {path}")


def main(argv):
    if len(argv) not in (4, 5) or argv[1] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    lloyd, scaling, out = argv[1], argv[2], argv[-1]
    one_thread = argv[3] if len(argv) == 5 else None
    square = lambda r: r.get("domain") == "unit_square"
    cdt = column(lloyd, "N", "cdt build s", "cdt build s", square)
    ours = column(lloyd, "N", "ours s/it", "cdt build s", square)
    cgal = column(lloyd, "N", "CGAL s/it", "cdt build s", square)

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.3), constrained_layout=True)
    for series, label, style in ((cgal, "CGAL's optimizer (lloyd_optimize_mesh_2), an iteration", "s-"),
                                 (cdt, "CGAL constrained Delaunay build of the points", "^--"),
                                 (ours, "CVT_2 Lloyd iteration (lloyd_optimize_2), both cores", "o-")):
        left.loglog(*zip(*series), style, label=label)
    # the ratios as the benchmark printed them, from its unrounded times, below right of each point
    for series, ratios, text in ((ours, column(lloyd, "N", "ours/cdt", "cdt build s", square), "{}× the build"),
                                 (cgal, column(lloyd, "N", "CGAL/ours", "cdt build s", square), "{}× ours")):
        ratio = dict(ratios)
        for n, s in series:
            left.annotate(text.format(f"{ratio[n]:g}"), (n, s), textcoords="offset points",
                          xytext=(7, -13), fontsize=9)
    low = min(s for _, s in ours)
    left.set_ylim(low / 3, max(s for _, s in cgal) * 30)  # room for the legend
    left.set_xlim(min(n for n, _ in ours) / 2, max(n for n, _ in ours) * 4)
    left.set_xlabel("generators N (unit square, uniform random points)")
    left.set_ylabel("seconds")
    left.set_title("An iteration against a CDT build and CGAL's optimizer (one run)", fontsize=11)
    left.grid(True, which="both", alpha=0.3)
    left.legend(fontsize=9, loc="upper left")

    runs = [(scaling, "both cores", "o-")] + ([(one_thread, "one thread", "s--")] if one_thread else [])
    top = 0
    for path, label, style in runs:
        points = column(path, "N", "ns/generator", "ns/generator")
        right.semilogx(*zip(*points), style, label=f"CVT_2 Lloyd iteration, {label}")
        top = max(top, max(ns for _, ns in points))
        base = dict(points).get(1e5)
        if base and label == "both cores":
            right.axhline(1.2 * base, color="gray", linestyle=":", label="1.2 × the cost at 10⁵, both cores")
    right.set_ylim(0, top * 1.3)
    right.set_xlabel("generators N (cvt2 --points-in, a file in random order)")
    right.set_ylabel("nanoseconds a generator and iteration")
    right.set_title("Cost per generator (run_scaling.sh)", fontsize=11)
    right.grid(True, which="both", alpha=0.3)
    right.legend(fontsize=9, loc="lower right")
    fig.savefig(out, dpi=100)
    print(f"plot_speed: {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
