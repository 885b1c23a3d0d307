#!/usr/bin/env python3
# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Draws crack_interpolation's samples: the field, its Sibson interpolation on the bounded
Voronoi diagram, and CGAL's on the Delaunay triangulation of the same nodes, side by side.

    plot_crack_interpolation.py SAMPLES.txt OUT.png

Needs matplotlib and numpy (Debian: python3-matplotlib python3-numpy)."""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

samples, out = sys.argv[1:3]
x, y, exact, ours, cgal = np.loadtxt(samples, unpack=True)
n = int(round(np.sqrt(len(x))))
extent = (x.min() - 0.5 / n, x.max() + 0.5 / n, y.min() - 0.5 / n, y.max() + 0.5 / n)
panels = [
    (ours, "CVT_2: Sibson on the bounded Voronoi diagram"),
    (cgal, "CGAL: Sibson on the Delaunay triangulation"),
]
fig, axes = plt.subplots(2, 2, figsize=(9, 6.8), constrained_layout=True)
window = (0.0, 0.8, 0.2, 0.8)  # around the crack


def frame(ax, title, width):
    ax.plot([0, 0.5], [0.5, 0.5], color="k", linewidth=width)  # the crack
    ax.set_title(title, fontsize=10)
    ax.set_xlim(window[0], window[1])
    ax.set_ylim(window[2], window[3])
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_aspect("equal")


for ax, (values, title) in zip(axes[0], panels):
    image = ax.imshow(values.reshape(n, n), origin="lower", extent=extent, cmap="RdBu_r",
                      vmin=exact.min(), vmax=exact.max(), interpolation="nearest")
    ax.contour(values.reshape(n, n), levels=np.linspace(exact.min(), exact.max(), 21),
               extent=extent, colors="k", linewidths=0.4)
    frame(ax, title, 2.5)
fig.colorbar(image, ax=axes[0], shrink=0.8, label="sqrt(r) sin(theta/2), a jump across the crack")
top = abs(cgal - exact).max()
for ax, (values, title) in zip(axes[1], panels):
    error = abs(values - exact)
    image = ax.imshow(error.reshape(n, n), origin="lower", extent=extent, cmap="magma_r",
                      vmin=0, vmax=top, interpolation="nearest")
    frame(ax, "its error: largest %.3f" % error.max(), 0.6)
fig.colorbar(image, ax=axes[1], shrink=0.8, label="|interpolated - field|")
fig.savefig(out, dpi=80)
