# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""A finely digitised boundary with and without resampling: France's mainland (533 boundary
vertices) with 2 000 cells in all, L-BFGS to the 1% stop, every vertex of the input a generator
(``keep``), the boundary resampled to the cell size first (``Domain.resample``), and resampled
with its new vertices sliding along the input (``boundary="slide"``); cells coloured by area on
one scale, the specks of the input's vertices dark, the input's coast a thin red line; the
north-west (Brittany and Normandy) enlarged.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/resample.py [DATA_DIR] [OUT.png]
"""
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import LineCollection, PolyCollection
from matplotlib.colors import LogNorm

import cvt2

data = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "examples/data")
out = sys.argv[2] if len(sys.argv) > 2 else "resample.png"
cells = 2000
france = cvt2.Domain.from_file(data / "france_mainland.poly")
resampled = france.resample(cells=cells)
runs = {"keep": france, "resample": resampled, "slide": resampled}
fig, axes = plt.subplots(1, 3, figsize=(15, 5.2))
norm = LogNorm(3e-4, 3e-2)
coast = france.vertices[france.segments]
for ax, (mode, domain) in zip(axes, runs.items()):
    points = cvt2.random_points(domain, cells=cells, seed=1)
    result = cvt2.optimize(domain, points, boundary=mode if mode == "slide" else None)
    d = result.bounded_voronoi()
    areas = np.asarray(d.areas)
    specks = np.mean(areas < 0.1 * np.median(areas))
    ax.add_collection(PolyCollection([d.vertices[r] for r in d.regions], array=areas, norm=norm,
                                     cmap="viridis", edgecolor="w", linewidth=0.3))
    ax.plot(*d.points.T, "k.", ms=1)
    ax.plot(*result.points[result.constrained].T, "o", ms=2.5, mfc="tab:red", mec="k", mew=0.3)
    ax.add_collection(LineCollection(coast, colors="tab:red", linewidths=0.5))
    ax.set_xlim(-3.3, 0.9), ax.set_ylim(47.2, 49.9), ax.set_aspect("equal"), ax.set_axis_off()
    title = (f"{mode}: {len(areas)} cells, normalized energy {result.normalized_energy:.3f}\n"
             f"{specks:.1%} below a tenth of the median cell\n")
    if mode == "slide":
        title += "the resampled vertices slid along the input coast"
    elif mode == "resample":
        r = domain.resampling
        title += (f"{r['input_vertices']} boundary vertices -> {r['output_vertices']}, "
                  f"deviation <= {r['max_deviation']:.3g}")
    else:
        title += f"{france.own_cells} boundary vertices, each a generator"
    ax.set_title(title, fontsize=9)
fig.colorbar(axes[2].collections[0], ax=axes, shrink=0.7, label="cell area")
fig.savefig(out, dpi=110, bbox_inches="tight")
