# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""The manual's picture of conforming lines that meet: a river with tributaries (one joining at
53 degrees, one ending on the river's segment, two streams at a Y), a canal crossing the river
at a vertex of both, and a pond's shore, made conforming together, as `cvt2` writes them
(scripts/make_figures.sh runs):

    cvt2 examples/data/river_network.wkt --cells 3000 --constraints conforming \\
         --geojson network.geojson --cells-on-constraints network.csv

    python3 scripts/plot_conforming_network.py network.geojson network.csv \\
            examples/data/river_network.wkt OUT.png

The cells beside each line (the rows of the CSV) are tinted by line, the lines drawn over them:
each runs along faces, through the junctions too.
"""
import json
import pathlib
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

cells_file, csv_file, wkt_file, out = sys.argv[1:5]
features = json.loads(pathlib.Path(cells_file).read_text())["features"]
rings = [np.array(f["geometry"]["coordinates"][0]) for f in features]
rows = np.loadtxt(csv_file, delimiter=",", skiprows=1, ndmin=2)
lines = [np.array([p.split() for p in m.split(",")], dtype=float)
         for m in re.findall(r"LINESTRING \(([^)]*)\)", pathlib.Path(wkt_file).read_text())]
tints = ["#ffd6a5", "#caffbf", "#9bf6ff", "#bdb2ff", "#ffc6ff", "#fdffb6", "#a0c4ff"]
colors = np.full(len(rings), "#f1f3f5", dtype=object)
for item, cell in rows[rows[:, 0] >= 2][:, :2].astype(int):
    colors[cell - 1] = tints[(item - 2) % len(tints)]
covered = [rows[rows[:, 0] == i + 2, 2].sum() / 2 for i in range(len(lines))]
length = [np.hypot(*np.diff(line, axis=0).T).sum() for line in lines]

views = [((-40, 3040, -40, 2240), f"{len(features)} cells; {len(lines)} conforming lines"),
         ((1420, 1780, 880, 1220), "a tributary joins at 53 degrees"),
         ((920, 1280, 780, 1120), "a canal crosses the river at a vertex of both")]
fig, axes = plt.subplots(1, 3, figsize=(15, 5.2), gridspec_kw={"width_ratios": [1.4, 1, 1]})
for ax, ((x0, x1, y0, y1), title) in zip(axes, views):
    ax.add_collection(PolyCollection(rings, facecolors=colors, edgecolor="#4a5a6a", linewidth=0.3))
    for line in lines:
        ax.plot(*line.T, color="#1f4e8c", lw=1.4)
    ax.set_xlim(x0, x1), ax.set_ylim(y0, y1), ax.set_aspect("equal"), ax.set_axis_off()
    ax.set_title(title, fontsize=10)
axes[0].set_title(f"{views[0][1]}: faces along all of their {sum(length):.0f} m "
                  f"({sum(covered):.0f} m of faces)", fontsize=10)
fig.tight_layout()
fig.savefig(out, dpi=100)
print(f"{out}: {len(features)} cells, lines {sum(length):.1f} m, "
      f"faces along them {sum(covered):.1f} m")
