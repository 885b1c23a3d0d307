# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""The picture of constraints that change: a crack grown in 40 steps of one cell through a CVT
of 2000 generators in the unit square (cvt2.ConstraintEditor), the cells within two rings of
each step's changes relaxed by five Lloyd iterations (ConstraintEditor.relax). Left, each cell
coloured by the last step that changed or moved it; middle, the tip's last step close up;
right, the crack-opening displacement sqrt(r) sin(theta / 2) interpolated near the crack from
the nodes with one value per lip (natural_neighbours(..., lips=True)). Needs the cvt2 module
(scripts/make_figures.sh runs it):

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
ring = [[0, 1], [1, 2], [2, 3], [3, 0]]
square = cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], ring)
result = cvt2.optimize(square, cvt2.random_points(square, 2000, seed=1))
editor = cvt2.ConstraintEditor(square, result.points)
h = 1 / np.sqrt(2000)
start, direction = np.array([0, 0.35]), np.array([1, 0.3]) / np.hypot(1, 0.3)
crack = editor.insert_constraint([start, start + h * direction])
last_change, sizes, moved = {}, [], []
for step in range(1, 41):
    report = editor.extend_constraint(crack, start + (step + 1) * h * direction)
    sizes.append(len(report["changed_cells"]))
    for p in map(tuple, report["changed_cells"]):
        last_change[p] = step
    relaxed = editor.relax(rings=2, iterations=5)
    moved.append(len(relaxed["moved_from"]))
    for a, b in zip(map(tuple, relaxed["moved_from"]), map(tuple, relaxed["moved_to"])):
        last_change.pop(a, None)
        last_change[b] = step
diagram = editor.bounded_voronoi()
line = editor.constraint_vertices(crack)
tip = line[-1]
polygons = [diagram.vertices[r] for r in diagram.regions]
steps = np.array([last_change.get(tuple(p), 0) for p in diagram.points], dtype=float)

# The opening displacement around the tip, the crack's faces at theta = +-pi.
def opening(p):
    d = p - tip
    across = direction[0] * d[..., 1] - direction[1] * d[..., 0]
    return np.sqrt(np.hypot(d[..., 0], d[..., 1])) * np.sin(np.arctan2(across, d @ direction) / 2)


domain = cvt2.Domain(
    np.vstack([[[0, 0], [1, 0], [1, 1], [0, 1]], line]),
    np.vstack([ring, np.column_stack([np.arange(4, 3 + len(line)), np.arange(5, 4 + len(line))])]),
)
free = np.array([p for p in diagram.points if not (domain.vertices == p).all(axis=1).any()])
xs, ys = np.meshgrid(np.linspace(0, 1, 200), np.linspace(0.2, 0.8, 120))
queries = np.column_stack([xs.ravel(), ys.ravel()])
m = cvt2.natural_neighbours(domain, free, queries, lips=True)
nodes = np.vstack([free, domain.vertices])
values = opening(nodes)
left = np.array([-direction[1], direction[0]])
on_crack = np.arange(len(free) + 4, len(nodes))
values[on_crack] = 0  # the mean of the two faces, for the matrix without lips
row_of = np.repeat(np.arange(len(queries)), np.diff(m.indptr))
lip_values = np.empty(len(m.lip_columns))
for k, c in enumerate(m.lip_columns):  # a lip faces the side where the queries that use it lie
    users = row_of[m.indices == len(nodes) + k]
    side = np.sign(np.median((queries[users] - nodes[c]) @ left)) if len(users) else 1.0
    lip_values[k] = side * np.sqrt(np.hypot(*(nodes[c] - tip)))
field = (m @ np.concatenate([values, lip_values])).reshape(xs.shape)
exact = opening(queries).reshape(xs.shape)
error_lips = np.max(np.abs(field - exact))
error_plain = np.max(np.abs((cvt2.natural_neighbours(domain, free, queries) @ values).reshape(xs.shape) - exact))

fig, axes = plt.subplots(1, 3, figsize=(18, 5.6), gridspec_kw={"width_ratios": [1, 1, 1.25]})
plt.rcParams["axes.titlesize"] = 10
colours = plt.get_cmap("viridis")
for ax, zoom in zip(axes[:2], (False, True)):
    shown = steps if not zoom else np.where(steps == 40, 40.0, 0.0)
    face = [colours(s / 40) if s > 0 else (0.95, 0.95, 0.95, 1) for s in shown]
    ax.add_collection(PolyCollection(polygons, facecolors=face, edgecolors="0.35", linewidths=0.4))
    ax.plot(line[:, 0], line[:, 1], color="crimson", linewidth=2)
    ax.set_aspect("equal")
    if zoom:
        ax.set_xlim(tip[0] - 5 * h, tip[0] + 5 * h)
        ax.set_ylim(tip[1] - 5 * h, tip[1] + 5 * h)
        ax.plot(*tip, "o", color="crimson")
        ax.set_title(f"the last step: {sizes[-1]} cells changed, {moved[-1]} relaxed")
    else:
        ax.set_xlim(0, 1)
        ax.set_ylim(0, 1)
        ax.set_title(f"40 steps; a step: {int(np.median(sizes))} cells changed, {int(np.median(moved))} relaxed (median)")
    ax.set_xticks([])
    ax.set_yticks([])
sm = plt.cm.ScalarMappable(cmap=colours, norm=plt.Normalize(1, 40))
fig.colorbar(sm, ax=axes[:2], shrink=0.8, label="last step that changed the cell")
ax = axes[2]
image = ax.contourf(xs, ys, field, levels=24, cmap="RdBu_r")
ax.plot(line[:, 0], line[:, 1], color="k", linewidth=1.5)
ax.set_aspect("equal")
ax.set_xticks([])
ax.set_yticks([])
ax.set_title(f"the opening, interpolated with lips\nlargest error {error_lips:.0e} (without lips: {error_plain:.1f})")
fig.colorbar(image, ax=ax, shrink=0.8, label=r"$\sqrt{r}\,\sin(\theta/2)$")
fig.savefig(out, dpi=110, bbox_inches="tight")
