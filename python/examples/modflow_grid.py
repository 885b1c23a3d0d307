# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""A groundwater modeller's grid: an aquifer 2 km across with a fault that ends inside it (a
barrier: the cells on it are split, one per side, and no face crosses it) and two pumping
wells (fixed generators, cells refined to 12 m around them, growing to the background size at
300 m); 2 500 cells, L-BFGS to the 1% stop. It writes what ``cvt2`` writes for

    cvt2 examples/data/aquifer.wkt --cells 2500 --constraints barrier \\
         --fixed-points examples/data/aquifer_wells.txt \\
         --refine 480 640 12 300 --refine 1560 520 12 300 \\
         --disv aquifer.disv --cells-on-constraints aquifer.csv

and draws the grid: the split cells along the fault, the wells' cells, the whole and the
fault's tip enlarged.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/modflow_grid.py [DATA_DIR] [OUT.png]
"""
import json
import pathlib
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

import cvt2

data = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "examples/data")
out = sys.argv[2] if len(sys.argv) > 2 else "modflow_grid.png"
domain = cvt2.Domain.from_file(data / "aquifer.wkt")
wells = np.loadtxt(data / "aquifer_wells.txt")
cells = 2500
background = np.sqrt(2 * domain.area / (np.sqrt(3) * cells))  # as cvt2 --refine takes it


def density(xy):  # cvt2 --refine X Y 12 300 at each well: the size, and 1 / size^4
    size = np.full(len(xy), background)
    for w in wells:
        t = np.minimum(1, np.hypot(*(xy - w).T) / 300)
        size = np.minimum(size, 12 + (background - 12) * t)
    return size**-4.0


points = cvt2.random_points(domain, cells=cells - len(wells), seed=1)
diagram = cvt2.optimize(domain, points, density=density, fixed_points=wells).bounded_voronoi()
with tempfile.TemporaryDirectory() as tmp:
    diagram.to_geojson(pathlib.Path(tmp) / "grid.geojson", constraints="barrier")
    diagram.to_disv(pathlib.Path(tmp) / "grid.disv", top=10, bottom=-40, constraints="barrier")
    features = json.loads((pathlib.Path(tmp) / "grid.geojson").read_text())["features"]
rings = [np.array(f["geometry"]["coordinates"][0]) for f in features]
centers = np.array([f["properties"]["generator"] for f in features])
split = np.array([(centers == c).all(axis=1).sum() > 1 for c in centers])
at_well = np.array([any((c == w).all() for w in wells) for c in centers])
ends = domain.vertices[domain.segments[domain.segment_items == 2]]  # the fault: line 2 of the file
fault = np.vstack([ends[:, 0], ends[-1:, 1]])


def side(ring):  # of the fault: -1 west, 1 east, 0 away from it (no vertex on it)
    a, b = ends[:, 0], ends[:, 1]
    on = [np.any(np.abs(np.cross(b - a, p - a)) <= 1e-6 * np.hypot(*(b - a).T)
                 * (np.einsum("ij,ij->i", p - a, b - a) >= 0) * (np.einsum("ij,ij->i", p - b, a - b) >= 0))
          for p in ring]
    if sum(on) < 2:
        return 0
    c = ring[:-1].mean(axis=0)
    k = np.argmin(np.hypot(*((a + b) / 2 - c).T))
    return 1 if np.cross(b[k] - a[k], c - a[k]) < 0 else -1


sides = np.array([side(r) for r in rings])
colors = np.where(at_well, "#d62728", np.where(sides < 0, "#8ecae6", np.where(sides > 0, "#b7e4a0", "#eef2f6")))
fig, axes = plt.subplots(1, 2, figsize=(12, 5.4), gridspec_kw={"width_ratios": [1.45, 1]})
for ax, (x0, x1, y0, y1) in zip(axes, [(-150, 2180, -30, 1350), (1000, 1300, 520, 860)]):
    ax.add_collection(PolyCollection(rings, facecolors=colors, edgecolor="#4a5a6a", linewidth=0.25))
    ax.plot(*fault.T, color="k", lw=1.6)
    ax.plot(*wells.T, "k^", ms=6)
    ax.set_xlim(x0, x1), ax.set_ylim(y0, y1), ax.set_aspect("equal"), ax.set_axis_off()
axes[1].plot(*centers[split].T, "o", color="k", ms=3)
axes[0].set_title(f"{len(features)} cells: a fault as a barrier (the cells along it blue and green by\n"
                  "side: none crosses it) and two wells (fixed generators, cells refined around them)",
                  fontsize=9.5)
axes[1].set_title(f"the fault's tip: {split.sum()} halves of cells split at its vertices (dots: the\n"
                  "generator both halves share); the tip's cell goes round the tip", fontsize=9.5)
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"{out}: {len(features)} cells, {split.sum()} halves, well cells {np.array([f['properties']['area'] for f in features])[at_well].round(1)} m2")
