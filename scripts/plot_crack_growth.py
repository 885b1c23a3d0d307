# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""The picture of the README's constraints that change: a crack grown in 40 steps of one cell
through a CVT of 2000 generators in the unit square (cvt2.ConstraintEditor), each cell coloured
by the last step that changed it (the rows a solver assembles again), and the tip's last step
close up. Needs the cvt2 module (scripts/make_figures.sh runs it):

    python3 scripts/plot_crack_growth.py OUT.png
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from matplotlib.collections import PolyCollection

import cvt2

out = sys.argv[1]
square = cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])
result = cvt2.optimize(square, cvt2.random_points(square, 2000, seed=1))
editor = cvt2.ConstraintEditor(square, result.points)
h = 1 / np.sqrt(2000)
crack = editor.insert_constraint([[0, 0.45], [h, 0.45]])
last_change, sizes = {}, []
for step in range(1, 41):
    t = step * h
    report = editor.extend_constraint(crack, [h + t, 0.45 + 0.25 * t * t])
    sizes.append(len(report["changed_cells"]))
    for p in map(tuple, report["changed_cells"]):
        last_change[p] = step
diagram = editor.bounded_voronoi()
line = editor.constraint_vertices(crack)
polygons = [diagram.vertices[r] for r in diagram.regions]
steps = np.array([last_change.get(tuple(p), 0) for p in diagram.points], dtype=float)

fig, axes = plt.subplots(1, 2, figsize=(11, 5.4))
colours = plt.get_cmap("viridis")
for ax, zoom in zip(axes, (False, True)):
    shown = steps if not zoom else np.where(steps == 40, 40.0, 0.0)
    face = [colours(s / 40) if s > 0 else (0.95, 0.95, 0.95, 1) for s in shown]
    ax.add_collection(PolyCollection(polygons, facecolors=face, edgecolors="0.35", linewidths=0.4))
    ax.plot(line[:, 0], line[:, 1], color="crimson", linewidth=2)
    ax.set_aspect("equal")
    if zoom:
        tip = line[-1]
        ax.set_xlim(tip[0] - 5 * h, tip[0] + 5 * h)
        ax.set_ylim(tip[1] - 5 * h, tip[1] + 5 * h)
        ax.plot(*tip, "o", color="crimson")
        ax.set_title(f"the last step: {sizes[-1]} cells changed")
    else:
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.set_title(f"40 steps, {int(np.median(sizes))} cells changed each (median)")
    ax.set_xticks([])
    ax.set_yticks([])
sm = plt.cm.ScalarMappable(cmap=colours, norm=plt.Normalize(1, 40))
fig.colorbar(sm, ax=axes, shrink=0.8, label="last step that changed the cell")
fig.savefig(out, dpi=110, bbox_inches="tight")
