# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Why a density wants points drawn from it: L-BFGS to the 1% stop in a 2 x 1 rectangle whose
density is 16 on the right half and 1 on the left, from the same 600 uniform points, kept
(redistribute=False) and replaced by points drawn from the density (the default,
redistribute="auto", since they do not follow it); cells coloured by area (one scale), with each
result's density response (-0.5 for a centroidal tessellation of the density).

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


rectangle = cvt2.Domain([[0, 0], [2, 0], [2, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])
uniform = cvt2.random_points(rectangle, 600, seed=4)
starts = {"uniform points, kept": False, "uniform points, redistributed (default)": "auto"}
fig, axes = plt.subplots(1, 2, figsize=(11, 3.4))
norm = LogNorm(2e-3, 1e-2)
for ax, (name, redistribute) in zip(axes, starts.items()):
    result = cvt2.optimize(rectangle, uniform, density=step, redistribute=redistribute)
    cells = result.bounded_voronoi()
    right = np.count_nonzero(cells.points[:, 0] > 1.0)
    ax.add_collection(PolyCollection([cells.vertices[r] for r in cells.regions], array=cells.areas,
                                     norm=norm, cmap="viridis", edgecolor="w", linewidth=0.3))
    ax.axvline(1.0, color="r", lw=1)
    ax.set_xlim(0, 2), ax.set_ylim(0, 1), ax.set_aspect("equal"), ax.set_xticks([]), ax.set_yticks([])
    ax.set_title(f"from {name}: {result.stop_reason} after {result.iterations} iterations\n"
                 f"{len(cells.points) - right} cells left, {right} right; "
                 f"density response {result.density_response:.2f}", fontsize=9)
fig.tight_layout()
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "density_response.png", dpi=100)
