# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""A river 0.5 from a well: the cells refined around the well without the river (left) and with
the river made conforming (right), whose steps follow the refinement, as `cvt2` writes them
(scripts/make_figures.sh runs, in a 10 x 10 square with the river from (0, 5.2) to (10, 4.8)):

    cvt2 river.wkt --cells 3000 --refine 5 5.5 0.05 2 --geojson alone.geojson
    cvt2 river.wkt --cells 3000 --refine 5 5.5 0.05 2 --constraints conforming \\
         --geojson river.geojson

    python3 scripts/plot_conforming_refined.py alone.geojson river.geojson OUT.png
"""
import json
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import LogNorm

fig, axes = plt.subplots(1, 2, figsize=(12, 6.2))
norm = LogNorm(2e-3, 5e-2)
titles = ("without the river", "with the river, conforming")
for ax, path, title in zip(axes, sys.argv[1:3], titles):
    rings = [np.array(f["geometry"]["coordinates"][0])
             for f in json.loads(pathlib.Path(path).read_text())["features"]
             if f["geometry"]["type"] == "Polygon"]
    areas = [abs(np.dot(r[:-1, 0], r[1:, 1]) - np.dot(r[1:, 0], r[:-1, 1])) / 2 for r in rings]
    ax.add_collection(PolyCollection(rings, array=np.array(areas), norm=norm, cmap="viridis",
                                     edgecolor="w", linewidth=0.4))
    if ax is axes[1]:
        ax.plot([0, 10], [5.2, 4.8], color="tab:blue", linewidth=1.5)
    ax.plot([5], [5.5], "o", color="tab:red", markersize=4)
    ax.set_xlim(3.5, 6.5), ax.set_ylim(4.0, 7.0), ax.set_aspect("equal"), ax.set_title(title)
    ax.set_xticks([]), ax.set_yticks([])
fig.tight_layout()
fig.savefig(sys.argv[3], dpi=90)
