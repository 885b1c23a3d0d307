#!/usr/bin/env python3
# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Writes examples/data/bubble_with_hole.poly, the synthetic curved domain of the paper's
Fig. 10-like example (examples/lloyd_curved_hole.cpp): a smooth blob with an off-centre circular
hole, both polygonised finely (the sea horse of the paper is not available). Standard library
only. Usage: make_bubble_poly.py [OUT.poly]
"""

import math
import os
import sys

OUTER_VERTICES = 240
HOLE_VERTICES = 64
HOLE_CENTRE = (0.42, 0.18)
HOLE_RADIUS = 0.3


def outer(t):
    """The blob: a star-shaped curve, r(t) > 0, stretched along x."""
    r = 1 + 0.12 * math.cos(3 * t) + 0.06 * math.sin(5 * t + 0.4)
    return (1.25 * r * math.cos(t), r * math.sin(t))


def ring(n, point):
    return [tuple(round(c, 6) + 0.0 for c in point(2 * math.pi * i / n)) for i in range(n)]  # no -0


def main(out):
    rim = ring(OUTER_VERTICES, outer)  # counter-clockwise
    hole = ring(HOLE_VERTICES, lambda t: (HOLE_CENTRE[0] + HOLE_RADIUS * math.cos(-t),
                                          HOLE_CENTRE[1] + HOLE_RADIUS * math.sin(-t)))  # clockwise
    # The hole keeps clear of the rim (no crossing, no touching).
    gap = min(math.dist(p, HOLE_CENTRE) for p in rim) - HOLE_RADIUS
    assert gap > 0.1, gap
    lines = [
        "# Synthetic: a smooth blob with an off-centre circular hole (after the paper's Fig. 10)",
        "# Written by scripts/make_bubble_poly.py; public domain (CC0-1.0)",
        "# 1 polygons, 1 holes, 0 inner constraint polylines, 0 free vertices",
        "# format: Triangle .poly subset described in examples/data/README.md;"
        " segment markers 1 outer, 2 hole",
        f"{len(rim) + len(hole)} 2 0 0",
    ]
    lines += [f"{i + 1} {x:.6f} {y:.6f}" for i, (x, y) in enumerate(rim + hole)]
    n, m = len(rim), len(hole)
    lines.append(f"{n + m} 1")
    lines.append(f"# ring 1: outer of polygon 1, segments 1-{n}")
    lines += [f"{i + 1} {i + 1} {(i + 1) % n + 1} 1" for i in range(n)]
    lines.append(f"# ring 2: hole of polygon 1, segments {n + 1}-{n + m}")
    lines += [f"{n + i + 1} {n + i + 1} {n + (i + 1) % m + 1} 2" for i in range(m)]
    lines += ["1", f"1 {HOLE_CENTRE[0]:.6f} {HOLE_CENTRE[1]:.6f}"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    default = os.path.join(root, "examples", "data", "bubble_with_hole.poly")
    main(sys.argv[1] if len(sys.argv) > 1 else default)
