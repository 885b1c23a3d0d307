# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""The picture of the README's modeller's example: an aquifer 2 km across with a fault that
ends inside it (a barrier: the cells on it are split, one per side, and no face crosses it), a
river (a conforming line: faces lie on it) and two pumping wells (fixed generators, cells
refined to 12 m around them), as `cvt2` writes it (scripts/make_figures.sh runs):

    cvt2 examples/data/aquifer.geojson --cells 2500 \\
         --fixed-points examples/data/aquifer_wells.txt \\
         --refine 480 640 12 300 --refine 1560 520 12 300 \\
         --disv aquifer.disv --cells-on-constraints aquifer.csv --geojson aquifer_cells.geojson

    python3 scripts/plot_modflow_grid.py aquifer_cells.geojson examples/data OUT.png
"""
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

cells_file, data, out = sys.argv[1], pathlib.Path(sys.argv[2]), sys.argv[3]
features = json.loads(pathlib.Path(cells_file).read_text())["features"]
lines = {f["properties"]["name"]: np.array(f["geometry"]["coordinates"], dtype=float)
         for f in json.loads((data / "aquifer.geojson").read_text())["features"]
         if f["geometry"]["type"] == "LineString"}
wells = np.loadtxt(data / "aquifer_wells.txt")
fault, river = lines["fault"], lines["river"]
rings = [np.array(f["geometry"]["coordinates"][0]) for f in features]
centers = np.array([f["properties"]["generator"] for f in features])
split = np.array([(centers == c).all(axis=1).sum() > 1 for c in centers])
at_well = np.array([any((c == w).all() for w in wells) for c in centers])


def side(ring, line):  # of a line: -1 left, 1 right, 0 away from it (no vertex on it)
    a, b = line[:-1], line[1:]
    on = [np.any((np.abs(np.cross(b - a, p - a)) <= 1e-6 * np.hypot(*(b - a).T))
                 & (np.einsum("ij,ij->i", p - a, b - a) >= 0) & (np.einsum("ij,ij->i", p - b, a - b) >= 0))
          for p in ring]
    if sum(on) < 2:
        return 0
    c = ring[:-1].mean(axis=0)
    k = np.argmin(np.hypot(*((a + b) / 2 - c).T))
    return 1 if np.cross(b[k] - a[k], c - a[k]) < 0 else -1


by_fault = np.array([side(r, fault) for r in rings])
by_river = np.array([side(r, river) for r in rings])
colors = np.full(len(rings), "#eef2f6", dtype=object)
colors[by_river != 0] = "#ffd6a5"
colors[by_fault < 0], colors[by_fault > 0] = "#8ecae6", "#b7e4a0"
colors[at_well] = "#d62728"
fig, axes = plt.subplots(1, 2, figsize=(12, 5.4), gridspec_kw={"width_ratios": [1.45, 1]})
for ax, (x0, x1, y0, y1) in zip(axes, [(-150, 2180, -30, 1350), (1000, 1300, 520, 860)]):
    ax.add_collection(PolyCollection(rings, facecolors=colors, edgecolor="#4a5a6a", linewidth=0.25))
    ax.plot(*fault.T, color="k", lw=1.6)
    ax.plot(*river.T, color="#1f6fb4", lw=1.6)
    ax.plot(*wells.T, "k^", ms=6)
    ax.set_xlim(x0, x1), ax.set_ylim(y0, y1), ax.set_aspect("equal"), ax.set_axis_off()
axes[1].plot(*centers[split].T, "o", color="k", ms=3)
axes[0].set_title(f"{len(features)} cells: a fault as a barrier (cells beside it blue and green by side: none\n"
                  "crosses it), a river as a conforming line (faces on it: cells beside it orange), two wells",
                  fontsize=9.5)
axes[1].set_title(f"the fault's tip: {split.sum()} halves of cells split at its vertices (dots: the\n"
                  "generator both halves share); the tip's cell goes round the tip", fontsize=9.5)
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"{out}: {len(features)} cells, {split.sum()} halves")
