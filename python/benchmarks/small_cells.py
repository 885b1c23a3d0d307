# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""The manual's table of small cells with `slide`: on the bundled real domains, the cells below
a quarter of the median cell, sorted by where their generator is (uniform density, L-BFGS to the
1% stop, `random_points(cells=N)`, the same bits as `cvt2 --boundary slide --cells N`).

    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/small_cells.py [DATA_DIR] [N ...]

A generator is, in this order: an input vertex (a feature, or a vertex kept for the bound or
the topology); a resampled vertex that did not slide (a run or ring shorter than three cell
sizes); within half a cell size h of an input vertex of the domain; on land narrower than a
cell (the domain covers less than 0.3 of the disk of radius h around it: peninsulas,
isthmuses, thin islands); or neither.
"""
import json
import pathlib
import sys

import numpy as np
import shapely.wkt
from shapely.geometry import Point, shape

import cvt2

DOMAINS = ["world_land_110m.wkt", "france_mainland.poly", "us_kentucky_counties.geojson",
           "us_massachusetts_counties.wkt", "earcut_dude.poly"]
KINDS = ["input vertex", "short run or ring", "within h/2 of an input vertex", "narrow land",
         "neither"]


def polygons(path):
    """The domain as shapely polygons, for the narrow-land test (None for .poly files)."""
    if path.suffix == ".wkt":
        return [shapely.wkt.loads(path.read_text())]
    if path.suffix == ".geojson":
        return [shape(f["geometry"]) for f in json.loads(path.read_text())["features"]]
    return None


def small_cells(path, n):
    domain = cvt2.Domain.from_file(path)
    input_vertices = np.asarray(domain.vertices)
    inputs = set(map(tuple, input_vertices))
    resampled = domain.resample(cells=n)
    placed = set(map(tuple, np.asarray(resampled.vertices)))
    h = resampled.resampling["size"]
    result = cvt2.optimize(resampled, cvt2.random_points(resampled, cells=n), boundary="slide")
    diagram = result.bounded_voronoi()
    areas = np.asarray(diagram.areas)
    points, constrained = np.asarray(diagram.points), np.asarray(diagram.constrained)
    kept = np.array([v for v in np.asarray(result.domain.vertices) if tuple(v) in inputs])
    land = polygons(path)
    count = dict.fromkeys(KINDS, 0)
    small = np.flatnonzero(areas < 0.25 * np.median(areas))
    for i in small:
        p = tuple(points[i])
        if p in inputs:
            kind = "input vertex"
        elif constrained[i] and p in placed:
            kind = "short run or ring"
        elif len(kept) and np.hypot(*(kept - np.asarray(p)).T).min() < h / 2:
            kind = "within h/2 of an input vertex"
        else:
            kind = "neither"
            if land is not None:
                disk = Point(p).buffer(h, 64)
                share = sum(g.intersection(disk).area for g in land if g.distance(Point(p)) < h)
                if share < 0.3 * disk.area:
                    kind = "narrow land"
        count[kind] += 1
    return len(areas), len(small), count, result.normalized_energy


def main():
    data = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else \
        pathlib.Path(__file__).resolve().parents[2] / "examples" / "data"
    sizes = [int(a) for a in sys.argv[2:]] or [2000, 20000]
    print("| domain | N | below ¼ median | " + " | ".join(KINDS) + " | normalized energy |")
    print("|---|--:|--:|" + "--:|" * len(KINDS) + "--:|")
    for name in DOMAINS:
        for n in sizes:
            cells, small, count, energy = small_cells(data / name, n)
            print(f"| {name} | {n} | {small} | " + " | ".join(str(count[k]) for k in KINDS) +
                  f" | {energy:.3f} |")


if __name__ == "__main__":
    main()
