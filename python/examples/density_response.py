# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Why a density wants points drawn from it, and dealt to the regions between constraints. The
same points kept (redistribute=False) and replaced by points drawn from the density (the
default, redistribute="auto", since they do not follow it), L-BFGS to the 1% stop, cells
coloured by area (one scale a row):

- top: a 2 x 1 rectangle whose density is 16 on the right half and 1 on the left, from 600
  uniform points: kept, the cells keep one size (density response 0, not -0.5);
- bottom: two unit squares split by a wall, under a density that grows 16-fold toward it from
  either side (equal masses), from 150 points drawn from it on the left and 450 on the right:
  kept, each square's cells follow the density, but no generator crosses the wall, and the
  counts cost a third more energy.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/density_response.py [OUT.png]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection
from matplotlib.colors import LogNorm

import cvt2


def step(xy):
    return np.where(xy[:, 0] > 1.0, 16.0, 1.0)


def toward_the_wall(xy):
    return 16.0 ** np.minimum(xy[:, 0], 2 - xy[:, 0])


rectangle = cvt2.Domain([[0, 0], [2, 0], [2, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])
squares = cvt2.Domain([[0, 0], [2, 0], [2, 1], [0, 1], [1, 0], [1, 1]],
                      [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]])
rng = np.random.default_rng(5)
drawn = []
for count, offset in ((150, 0.0), (450, 1.0)):
    xy = rng.random((8 * count, 2)) + [offset, 0]
    drawn.append(xy[rng.random(len(xy)) * 4 < np.sqrt(toward_the_wall(xy))][:count])
rows = [(rectangle, step, cvt2.random_points(rectangle, 600, seed=4), "uniform points",
         LogNorm(2e-3, 1e-2)),
        (squares, toward_the_wall, np.vstack(drawn), "150 | 450 points", LogNorm(6e-4, 2e-2))]
fig, axes = plt.subplots(2, 2, figsize=(11, 7))
for row, (domain, density, points, start, norm) in zip(axes, rows):
    for ax, redistribute in zip(row, (False, "auto")):
        result = cvt2.optimize(domain, points, density=density, redistribute=redistribute)
        cells = result.bounded_voronoi()
        free = ~result.constrained
        left = np.count_nonzero(free & (result.points[:, 0] < 1))
        ax.add_collection(PolyCollection([cells.vertices[r] for r in cells.regions],
                                         array=cells.areas, norm=norm, cmap="viridis",
                                         edgecolor="w", linewidth=0.3))
        ax.axvline(1.0, color="r", lw=2 if domain is squares else 1)
        ax.set_xlim(0, 2), ax.set_ylim(0, 1), ax.set_aspect("equal")
        ax.set_xticks([]), ax.set_yticks([])
        counts = ("" if np.isnan(result.density_count_excess)
                  else f", count excess {100 * result.density_count_excess:.0f}%")
        ax.set_title(f"from {start}, {'redistributed (default)' if redistribute else 'kept'}: "
                     f"{result.stop_reason}\n{left} | {np.count_nonzero(free) - left} points, "
                     f"energy {result.energy:.4g}, density response "
                     f"{result.density_response:.2f}{counts}", fontsize=9)
fig.tight_layout()
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "density_response.png", dpi=100)
