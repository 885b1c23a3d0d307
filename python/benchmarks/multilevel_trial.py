# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Why there is no multilevel optimization (the manual's "Converged for real"): a coarse-to-fine
start against one level, to the 1% stop, as iterations of the finest level and energies.

A level solves with about a quarter of the next one's points; the next starts from its
generators and the midpoint of each Delaunay edge between them (a hexagonal tiling refines so
exactly), less a few spread midpoints or plus a few random points to make the count.

    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/multilevel_trial.py [N]

Uniform density in the unit square from N random points (default 100 000), then the step
density (16 on the right half of a 2 x 1 rectangle) from 2 000.
"""
import sys
import time

import numpy as np

import cvt2


def refine(result, domain, target, density=None):
    """The generators of `result` and the midpoints of the ridges between them: `target`
    points, free ones only."""
    d = result.bounded_voronoi()
    points, constrained, pairs = d.points, d.constrained, d.ridge_points
    pairs = pairs[(pairs[:, 0] >= 0) & (pairs[:, 1] >= 0)]
    pairs = pairs[~(constrained[pairs[:, 0]] & constrained[pairs[:, 1]])]
    pairs = np.unique(np.sort(pairs, axis=1), axis=0)
    midpoints = 0.5 * (points[pairs[:, 0]] + points[pairs[:, 1]])
    free = points[~constrained]
    start = np.vstack([free, midpoints])
    if len(start) > target:  # drop midpoints spread through the list
        extra = len(start) - target
        start = np.delete(start, len(free) + np.arange(extra) * len(midpoints) // extra, axis=0)
    elif len(start) < target:
        start = np.vstack([start, cvt2.random_points(domain, target - len(start), seed=7,
                                                     density=density)])
    return start


def multilevel(domain, n, density=None, coarsest=1000, ratio=3.9, coarse_stop=0.03):
    counts = [n]
    while counts[-1] / ratio > coarsest:
        counts.append(int(counts[-1] / ratio))
    counts.reverse()
    points = cvt2.random_points(domain, counts[0], seed=1, density=density)
    iterations = []
    for level, count in enumerate(counts):
        if level > 0:
            points = refine(result, domain, count, density)
        last = level == len(counts) - 1
        result = cvt2.optimize(domain, points, density=density, max_iterations=3000,
                               move_ratio=0.01 if last else coarse_stop, redistribute=False)
        iterations.append(result.iterations)
    return result, counts, iterations


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    square = cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])
    start = time.perf_counter()
    one = cvt2.optimize(square, cvt2.random_points(square, n, seed=1))
    print(f"uniform, {n} points, one level: {one.iterations} iterations, "
          f"{time.perf_counter() - start:.2f} s, energy {one.energy:.6g}")
    start = time.perf_counter()
    result, counts, iterations = multilevel(square, n)
    print(f"uniform, multilevel {counts}: iterations {iterations}, "
          f"{time.perf_counter() - start:.2f} s, energy {result.energy:.6g}")

    rectangle = cvt2.Domain([[0, 0], [2, 0], [2, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])

    def step(xy):
        return np.where(xy[:, 0] > 1.0, 16.0, 1.0)

    def left(r):
        return int((r.points[~r.constrained][:, 0] < 1).sum())

    drawn = cvt2.optimize(rectangle, cvt2.random_points(rectangle, 2000, seed=1, density=step),
                          density=step, max_iterations=3000, redistribute=False)
    print(f"step density, 2000 points drawn from it: {drawn.iterations} iterations, "
          f"{left(drawn)} cells on the left, energy {drawn.energy:.6g}")
    result, counts, iterations = multilevel(rectangle, 2000, density=step, coarsest=300)
    print(f"step density, multilevel {counts}: iterations {iterations}, {left(result)} cells on "
          f"the left, energy {result.energy:.6g} ({result.energy / drawn.energy:.3f} of drawn)")


if __name__ == "__main__":
    main()
