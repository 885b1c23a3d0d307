# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""The tables of the manual's redistribution paragraph: what `optimize(..., redistribute=)` does
with points that do not follow the density, to the 1% stop.

    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/redistribution_table.py [DATA_DIR]

First the issue's 16:1 step density in a 2 x 1 rectangle, 2 000 uniform points kept or
redistributed against 2 000 points drawn from the density: the mean cell area on the left over
that on the right (4 at a centroidal tessellation) and the energy over the drawn start's; then
the automatic sizing (density="lipschitz") on bundled domains, from 2 000 uniform points.
"""
import pathlib
import sys

import numpy as np

import cvt2


def step(xy):
    return np.where(xy[:, 0] > 1.0, 16.0, 1.0)


def area_ratio(result):
    free = ~result.constrained
    areas, x = result.bounded_voronoi().areas[free], result.points[free, 0]
    return areas[x < 1].mean() / areas[x >= 1].mean()


def main():
    data = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "examples/data")
    rectangle = cvt2.Domain([[0, 0], [2, 0], [2, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])
    uniform = cvt2.random_points(rectangle, 2000, seed=4)
    drawn = cvt2.random_points(rectangle, 2000, seed=1, density=step)
    print("| start | algorithm | left/right area | energy / drawn start's | iterations |")
    print("|---|---|--:|--:|--:|")
    for algorithm in ("lbfgs", "lloyd"):
        options = dict(algorithm=algorithm, density=step, max_iterations=3000)
        reference = cvt2.optimize(rectangle, drawn, redistribute=False, **options)
        for name, points, redistribute in (("uniform, kept", uniform, False),
                                           ("uniform, redistributed", uniform, "auto"),
                                           ("drawn from the density", drawn, False)):
            r = cvt2.optimize(rectangle, points, redistribute=redistribute, **options)
            print(f"| {name} | {algorithm} | {area_ratio(r):.2f} | "
                  f"{r.energy / reference.energy:.3f} | {r.iterations} |")
    print()
    print("| domain | kept: energy / drawn start's | redistributed |")
    print("|---|--:|--:|")
    for file in ("bubble_with_hole.poly", "four_clusters.poly", "us_massachusetts_counties.poly",
                 "earcut_dude.poly"):
        domain = cvt2.Domain.from_file(data / file)
        uniform = cvt2.random_points(domain, 2000, seed=1)
        drawn = cvt2.random_points(domain, 2000, seed=1, density="lipschitz")
        options = dict(density="lipschitz", max_iterations=3000)
        reference = cvt2.optimize(domain, drawn, redistribute=False, **options).energy
        kept = cvt2.optimize(domain, uniform, redistribute=False, **options).energy
        auto = cvt2.optimize(domain, uniform, **options).energy
        print(f"| {file} | {kept / reference:.3f} | {auto / reference:.3f} |")


if __name__ == "__main__":
    main()
