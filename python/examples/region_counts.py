# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Why the regions between constraints need the counts the density asks for: two unit squares
split by a wall, under a density that grows 16-fold toward the wall from either side (equal
masses), from 150 points drawn from it on the left and 450 on the right, kept (redistribute=
False) and redistributed (the default); L-BFGS to the 1% stop, cells coloured by area (one
scale). Within each square the cells follow the density either way; no generator crosses the
wall, so only redistribution mends the counts.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/region_counts.py [OUT.png]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import LogNorm

import cvt2


def density(xy):
    return 16.0 ** np.minimum(xy[:, 0], 2 - xy[:, 0])


squares = cvt2.Domain([[0, 0], [2, 0], [2, 1], [0, 1], [1, 0], [1, 1]],
                      [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]])
rng = np.random.default_rng(5)
points = []
for count, offset in ((150, 0.0), (450, 1.0)):
    xy = rng.random((8 * count, 2)) + [offset, 0]
    points.append(xy[rng.random(len(xy)) * 4 < np.sqrt(density(xy))][:count])
points = np.vstack(points)
fig, axes = plt.subplots(1, 2, figsize=(11, 3.6))
norm = LogNorm(6e-4, 2e-2)
results = {}
for ax, (name, redistribute) in zip(axes, {"kept": False, "redistributed (default)": "auto"}.items()):
    result = results[name] = cvt2.optimize(squares, points, density=density,
                                           redistribute=redistribute)
    cells = result.bounded_voronoi()
    free = ~result.constrained
    left = np.count_nonzero(free & (result.points[:, 0] < 1))
    ax.add_collection(PolyCollection([cells.vertices[r] for r in cells.regions], array=cells.areas,
                                     norm=norm, cmap="viridis", edgecolor="w", linewidth=0.3))
    ax.plot([1, 1], [0, 1], color="r", lw=2)
    ax.set_xlim(0, 2), ax.set_ylim(0, 1), ax.set_aspect("equal"), ax.set_xticks([]), ax.set_yticks([])
    ax.set_title(f"{name}: {result.stop_reason}, {left} | {np.count_nonzero(free) - left} points, "
                 f"energy {result.energy:.4g}\ndensity response {result.density_response:.2f}, "
                 f"count excess {100 * result.density_count_excess:.0f}%", fontsize=9)
fig.tight_layout()
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "region_counts.png", dpi=100)
