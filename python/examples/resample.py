# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""A finely digitised boundary with and without resampling: France's mainland (533 boundary
vertices) with 2 000 cells in all, L-BFGS to the 1% stop, every vertex of the input a generator
(``keep``) and the boundary resampled to the cell size first (``Domain.resample``); cells
coloured by area on one scale, the specks of the input's vertices dark; the north-west
(Brittany and Normandy) enlarged.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/resample.py [DATA_DIR] [OUT.png]
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import LogNorm

import cvt2

data = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "examples/data")
out = sys.argv[2] if len(sys.argv) > 2 else "resample.png"
cells = 2000
france = cvt2.Domain.from_file(data / "france_mainland.poly")
resampled = france.resample(cells=cells)
runs = {"keep": france, "resample": resampled}
fig, axes = plt.subplots(1, 2, figsize=(12, 5.2))
norm = LogNorm(3e-4, 3e-2)
for ax, (mode, domain) in zip(axes, runs.items()):
    points = cvt2.random_points(domain, cells=cells, seed=1)
    d = cvt2.optimize(domain, points).bounded_voronoi()
    areas = np.asarray(d.areas)
    specks = np.mean(areas < 0.1 * np.median(areas))
    ax.add_collection(PolyCollection([d.vertices[r] for r in d.regions], array=areas, norm=norm,
                                     cmap="viridis", edgecolor="w", linewidth=0.3))
    ax.plot(*d.points.T, "k.", ms=1)
    ax.set_xlim(-3.3, 0.9), ax.set_ylim(47.2, 49.9), ax.set_aspect("equal"), ax.set_axis_off()
    title = f"{mode}: {len(areas)} cells, {specks:.1%} below a tenth of the median"
    if mode == "resample":
        r = domain.resampling
        title += (f"\n{r['input_vertices']} boundary vertices -> {r['output_vertices']}, "
                  f"deviation <= {r['max_deviation']:.3g}")
    else:
        title += f"\n{france.own_cells} boundary vertices, each a generator"
    ax.set_title(title, fontsize=9)
fig.colorbar(axes[1].collections[0], ax=axes, shrink=0.7, label="cell area")
fig.savefig(out, dpi=90, bbox_inches="tight")
