# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Benchmark of the Python module cvt2 (not a test): prints the figures of the Python
section of benchmarks/README.md, each a median of --runs runs, ratios within one run.

1. optimize() against the cvt2 program on the same run: 10^5 generators, uniform density, Lloyd,
   20 iterations; the optimization's time as the program prints it (seconds=) and as
   OptimizeResult.seconds measures it the same way, and the whole call against the whole program.
2. A numpy density callback against the same formula as a C++ lambda, in the same optimization
   (the lambda is in the module of a build configured with -DCVT_2_BUILD_BENCHMARKS=ON).
3. What Python users do today, side by side: scipy.spatial.Voronoi of the same generators (four
   far points added, so that every region is finite) and shapely's intersection of each region
   with the domain, as flopy and pyvista-gridder do, against bounded_voronoi(); cell areas in a
   convex domain, and in domains with inner constraints and with holes, the cells that are
   invalid, empty, MultiPolygons or see past a constraint (a point of the cell hidden from its
   generator), theirs and ours.

    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/benchmark.py \\
        --program build/tools/cvt2/cvt2
"""

import argparse
import os
import pathlib
import statistics
import subprocess
import tempfile
import time

import numpy as np

import cvt2

ROOT = pathlib.Path(__file__).resolve().parents[2]


def median(xs):
    return statistics.median(xs)


def run_program(program, domain_file, points_out, *options):
    t = time.perf_counter()
    out = subprocess.run([program, str(domain_file), "--quiet", "--points-out", str(points_out),
                          *map(str, options)], check=True, capture_output=True, text=True).stdout
    wall = time.perf_counter() - t
    return dict(f.split("=", 1) for f in out.split()), wall


def square_poly(path):
    path.write_text("4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n")


def bench_optimize(program, n, runs, tmp):
    domain_file = tmp / "square.poly"
    square_poly(domain_file)
    domain = cvt2.Domain.from_file(domain_file)
    points = cvt2.random_points(domain, n, seed=1)
    opts = dict(algorithm="lloyd", max_iterations=20, move_ratio=0)
    theirs_s, theirs_wall, ours_s, ours_wall, ratios, wall_ratios = [], [], [], [], [], []
    same = None
    for _ in range(runs):
        summary, wall = run_program(program, domain_file, tmp / "p.txt", "-n", n, "--seed", 1,
                                    "--algorithm", "lloyd", "--iterations", 20, "--move-ratio", 0)
        t = time.perf_counter()
        r = cvt2.optimize(domain, points, **opts)
        ours = time.perf_counter() - t
        if same is None:
            same = np.array_equal(np.loadtxt(tmp / "p.txt")[:, :2], r.points)
        theirs_s.append(float(summary["seconds"]))
        theirs_wall.append(wall)
        ours_s.append(r.seconds)
        ours_wall.append(ours)
        ratios.append(r.seconds / float(summary["seconds"]))
        wall_ratios.append(ours / wall)
    print(f"## 1. optimize() against the cvt2 program: unit square, N = {n}, uniform, Lloyd, 20 "
          f"iterations, {runs} runs, same bits: {'yes' if same else 'NO'}")
    print("| | cvt2 program | optimize() | optimize / program (median of the runs' ratios) |")
    print("|---|--:|--:|--:|")
    print(f"| optimization s (seconds=, OptimizeResult.seconds) | {median(theirs_s):.3f} | "
          f"{median(ours_s):.3f} | {median(ratios):.3f} |")
    print(f"| whole s (process; call with insertion and results) | {median(theirs_wall):.3f} | "
          f"{median(ours_wall):.3f} | {median(wall_ratios):.3f} |")
    print()


def bench_density(n, runs):
    if not hasattr(cvt2._cvt2, "_optimize_lambda_density"):
        print("## 2. A numpy density against a C++ lambda: skipped, the module has no C++ lambda "
              "(configure with -DCVT_2_BUILD_BENCHMARKS=ON)\n")
        return
    domain = cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])
    points = cvt2.random_points(domain, n, seed=2)
    a, cx, cy, w = 20.0, 0.5, 0.5, 0.05

    def rho(xy):
        dx = xy[:, 0] - cx
        dy = xy[:, 1] - cy
        return 1.0 + a * np.exp(-(dx * dx + dy * dy) / w)

    numpy_s, lambda_s, ratios, energies = [], [], [], []
    for _ in range(runs):
        r = cvt2.optimize(domain, points, algorithm="lloyd", density=rho, max_iterations=20,
                          move_ratio=0)
        q = cvt2._cvt2._optimize_lambda_density(domain._impl, points, 20, 0.0, 0, a, cx, cy, w)
        numpy_s.append(r.seconds)
        lambda_s.append(q.seconds)
        ratios.append(r.seconds / q.seconds)
        energies.append(abs(r.energy - q.energy) / q.energy)
    print(f"## 2. A numpy density against a C++ lambda: unit square, N = {n}, "
          f"rho = 1 + {a:g} exp(-|p - (0.5, 0.5)|^2 / {w:g}), Lloyd, 20 iterations, {runs} runs")
    print("| C++ lambda s | numpy callback s | numpy / lambda (median of ratios) | energy rel. diff |")
    print("|--:|--:|--:|--:|")
    print(f"| {median(lambda_s):.3f} | {median(numpy_s):.3f} | {median(ratios):.3f} | "
          f"{max(energies):.1e} |")
    print()


def scipy_shapely_cells(points, domain_geometry):
    """scipy's Voronoi of the points (four far points close every region) and each region cut by
    the domain with shapely, as flopy and pyvista-gridder do."""
    from scipy.spatial import Voronoi
    from shapely.geometry import Polygon

    lo, hi = points.min(axis=0), points.max(axis=0)
    c, r = (lo + hi) / 2, 10 * (hi - lo).max()
    far = c + r * np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]])
    v = Voronoi(np.vstack([points, far]))
    cells = []
    for k in range(len(points)):
        region = v.regions[v.point_region[k]]
        cells.append(Polygon(v.vertices[region]).intersection(domain_geometry))
    return cells


def defects(cells, points, constrained, domain_geometry, lines):
    """Counts invalid, empty and multi-part cells, and free generators' cells with a vertex that
    the generator does not see (the sight line leaves the domain or meets an inner constraint)."""
    from shapely.geometry import LineString
    from shapely.prepared import prep

    xmin, ymin, xmax, ymax = domain_geometry.bounds
    eps = 1e-9 * max(xmax - xmin, ymax - ymin)  # rounding: points on a constraint, up to it
    inside = prep(domain_geometry.buffer(eps))
    walls = prep(lines) if lines is not None else None
    invalid = empty = multi = hidden = 0
    for k, cell in enumerate(cells):
        invalid += not cell.is_valid
        empty += cell.is_empty
        multi += cell.geom_type not in ("Polygon",)
        if cell.is_empty or constrained[k]:
            continue
        parts = getattr(cell, "geoms", [cell])
        g = points[k]
        for part in parts:
            rings = [part.exterior, *part.interiors] if part.geom_type == "Polygon" else [part]
            ok = True
            for ring in rings:
                for y in np.asarray(ring.coords)[:-1]:
                    d = np.hypot(*(y - g))
                    if d <= eps:
                        continue
                    sight = LineString([g, y - eps * (y - g) / d])  # stops short of y
                    if not inside.contains(sight) or (walls is not None and walls.intersects(sight)):
                        ok = False
                        break
                if not ok:
                    break
            if not ok:
                hidden += 1
                break
    return invalid, empty, multi, hidden


def shapely_domain(file):
    import shapely.wkt
    from shapely.ops import unary_union

    polygons, lines = [], []
    for text in file.read_text().splitlines():
        if text.strip():
            g = shapely.wkt.loads(text)
            (polygons if g.geom_type in ("Polygon", "MultiPolygon") else lines).append(g)
    return unary_union(polygons), (unary_union(lines) if lines else None)


def with_lakes(geometry, lines, count):
    """The domain with `count` holes, octagons that keep clear of its boundary, of the lines and
    of each other (seeded)."""
    from shapely.geometry import Point
    from shapely.ops import unary_union

    rng = np.random.default_rng(5)
    xmin, ymin, xmax, ymax = geometry.bounds
    lakes = []
    while len(lakes) < count:
        r = 0.015 * (xmax - xmin) * rng.uniform(0.5, 1.5)
        lake = Point(rng.uniform(xmin, xmax), rng.uniform(ymin, ymax)).buffer(r, 2)
        margin = lake.buffer(0.3 * r)
        if geometry.contains(margin) and not margin.intersects(lines) and \
                not any(margin.intersects(other) for other in lakes):
            lakes.append(lake)
    return geometry.difference(unary_union(lakes)), lines


def bench_scipy(n, runs, data):
    from shapely.geometry import box

    print(f"## 3. scipy.spatial.Voronoi + shapely clipping against bounded_voronoi(): N = {n} "
          f"random points, {runs} runs")
    print("| domain | scipy + shapely s | bounded_voronoi() s | ratio | with .to_shapely() s | "
          "ratio | cells | areas: max rel. diff | theirs: invalid / empty / MultiPolygon / hidden "
          "| ours |")
    print("|---|--:|--:|--:|--:|--:|--:|--:|--|--|")
    cases = [("unit square (convex)", cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]],
                                                  [[0, 1], [1, 2], [2, 3], [3, 0]]), box(0, 0, 1, 1), None)]
    for file, name in (("us_massachusetts_counties.wkt", "Massachusetts, 14 county borders inside"),
                       ("earcut_eberly6.wkt", "eberly6, 15 holes")):
        geometry, lines = shapely_domain(data / file)
        cases.append((name, cvt2.Domain.from_file(data / file), geometry, lines))
    geometry, lines = with_lakes(*shapely_domain(data / "us_massachusetts_counties.wkt"), 20)
    cases.append(("Massachusetts with 20 lakes (holes) and its county borders",
                  cvt2.Domain.from_shapely(geometry, list(lines.geoms)), geometry, lines))
    for name, domain, geometry, lines in cases:
        points = cvt2.random_points(domain, n, seed=3)
        theirs_s, ours_s, ours_shapely_s, ratios, ratios_shapely = [], [], [], [], []
        for _ in range(runs):
            t = time.perf_counter()
            vd = cvt2.bounded_voronoi(domain, points)
            areas = vd.areas
            ours = time.perf_counter() - t
            ours_cells = vd.to_shapely()
            with_shapely = time.perf_counter() - t
            t = time.perf_counter()
            cells = scipy_shapely_cells(vd.points, geometry)
            theirs = time.perf_counter() - t
            theirs_s.append(theirs)
            ours_s.append(ours)
            ours_shapely_s.append(with_shapely)
            ratios.append(theirs / ours)
            ratios_shapely.append(theirs / with_shapely)
        their_areas = np.array([c.area for c in cells])
        rel = np.max(np.abs(their_areas - areas) / areas)
        theirs_defects = defects(cells, vd.points, vd.constrained, geometry, lines)
        ours_defects = defects(ours_cells, vd.points, vd.constrained, geometry, lines)
        fmt = lambda d: " / ".join(map(str, d))  # noqa: E731
        print(f"| {name} | {median(theirs_s):.3f} | {median(ours_s):.3f} | {median(ratios):.1f} | "
              f"{median(ours_shapely_s):.3f} | {median(ratios_shapely):.1f} | {len(areas)} | "
              f"{rel:.1e} | {fmt(theirs_defects)} | {fmt(ours_defects)} |")
    print()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--program", default=os.environ.get("CVT2_PROGRAM",
                                                            str(ROOT / "build/tools/cvt2/cvt2")))
    parser.add_argument("--data", default=str(ROOT / "examples/data"))
    parser.add_argument("--n", type=int, default=100000)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--only", choices=["optimize", "density", "scipy"])
    args = parser.parse_args()
    print(f"cvt2 {cvt2.__version__}, {os.cpu_count()} cores\n")
    with tempfile.TemporaryDirectory() as tmp:
        if args.only in (None, "optimize"):
            bench_optimize(args.program, args.n, args.runs, pathlib.Path(tmp))
    if args.only in (None, "density"):
        bench_density(args.n, args.runs)
    if args.only in (None, "scipy"):
        bench_scipy(args.n, args.runs, pathlib.Path(args.data))


if __name__ == "__main__":
    main()
