#!/usr/bin/env python3
# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Runs cvt2 on domains with every output at once and reads each output back with the
readers its users use: GeoJSON with shapely/GEOS, VTU with meshio, the MODFLOW 6 DISV grid
and Triangle's .node/.ele/.edge with parsers that check their formats' contracts.

    check_outputs.py CVT2 DATA_DIR WORK_DIR

Fails (exit 1) on any invalid geometry, overlap, gap, unreadable file or broken contract.
"""
import json
import math
import os
import subprocess
import sys

import meshio
import numpy as np
from shapely import wkt as shapely_wkt
from shapely.geometry import Point, Polygon, shape
from shapely.ops import unary_union
from shapely.validation import explain_validity, make_valid

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)


def domain_geometry(path):
    """The domain as shapely reads it: the union of the polygons of a .wkt or .geojson file
    (made valid as GEOS makes them)."""
    if path.endswith(".wkt"):
        geoms = [shapely_wkt.loads(line) for line in open(path) if line.strip()]
    else:
        fc = json.load(open(path))
        geoms = [shape(f["geometry"]) for f in fc["features"]]
    return unary_union([make_valid(g) for g in geoms if g.geom_type in ("Polygon", "MultiPolygon")])


def check_geojson(path, domain, cells):
    fc = json.load(open(path))
    features = fc["features"]
    check(len(features) == cells, f"{path}: {len(features)} features, {cells} generators")
    geoms = [shape(f["geometry"]) for f in features]
    invalid = [(i, explain_validity(g)) for i, g in enumerate(geoms) if not g.is_valid]
    check(not invalid, f"{path}: invalid geometries {invalid[:3]}")
    empty = [i for i, g in enumerate(geoms) if g.is_empty or g.area <= 0]
    check(not empty, f"{path}: empty cells {empty[:5]}")
    total = sum(g.area for g in geoms)
    union = unary_union(geoms)
    scale = domain.area
    check(abs(total - scale) <= 1e-9 * scale, f"{path}: cells' areas {total} != domain {scale}")
    check(abs(union.area - total) <= 1e-9 * scale, f"{path}: cells overlap ({union.area} < {total})")
    check(union.symmetric_difference(domain).area <= 1e-9 * scale,
          f"{path}: the union of the cells differs from the domain")
    for f, g in zip(features, geoms):
        p = f["properties"]
        check(abs(p["area"] - g.area) <= 1e-9 * max(g.area, 1e-300) + 1e-12 * scale,
              f"{path}: cell {p['cell']} area property {p['area']} != {g.area}")
        x, y = p["generator"]
        check(g.distance(Point(x, y)) <= 1e-9 * math.sqrt(scale),
              f"{path}: cell {p['cell']} does not hold its generator")
    # Neighbors are mutual and share a boundary.
    for f in features:
        k = f["properties"]["cell"]
        for n in f["properties"]["neighbors"]:
            check(k in features[n]["properties"]["neighbors"], f"{path}: {k} -> {n} not mutual")
    return geoms


def check_vtu(path, geoms, scale):
    mesh = meshio.read(path)
    cells = [c for block in mesh.cells for c in block.data]
    check(len(cells) == len(geoms), f"{path}: {len(cells)} cells, {len(geoms)} expected")
    used = set(i for c in cells for i in c)
    check(used == set(range(len(mesh.points))), f"{path}: points not all used, or missing")
    areas = np.concatenate(mesh.cell_data["area"])
    for k, c in enumerate(cells):
        xy = mesh.points[c][:, :2] - mesh.points[c][0, :2]
        shoelace = 0.5 * np.sum(xy[:, 0] * np.roll(xy[:, 1], -1) - np.roll(xy[:, 0], -1) * xy[:, 1])
        check(abs(shoelace - geoms[k].area) <= 1e-9 * max(geoms[k].area, 1e-12) + 1e-15 * scale,
              f"{path}: cell {k} has area {shoelace}, GeoJSON {geoms[k].area}")
        check(abs(areas[k] - geoms[k].area) <= 1e-9 * max(geoms[k].area, 1e-12) + 1e-15 * scale,
              f"{path}: cell {k} area data {areas[k]}")
    check(len(np.concatenate(mesh.cell_data["cell"])) == len(cells), f"{path}: cell data")


def read_blocks(path):
    """The blocks of an MF6 input file: name -> list of token lists."""
    blocks, name = {}, None
    for raw in open(path):
        line = raw.split("#")[0].strip()
        if not line:
            continue
        t = line.split()
        if t[0].upper() == "BEGIN":
            name = t[1].upper()
            blocks[name] = []
        elif t[0].upper() == "END":
            name = None
        elif name:
            blocks[name].append(t)
    return blocks


def check_disv(path, geoms, scale):
    """The MODFLOW 6 DISV contract: counts, 1-based shared vertices, clockwise closed cells,
    cell centers inside their cells, conforming neighbours."""
    b = read_blocks(path)
    dims = {t[0].upper(): int(t[1]) for t in b["DIMENSIONS"]}
    check(dims.get("NLAY") == 1, f"{path}: NLAY")
    ncpl, nvert = dims["NCPL"], dims["NVERT"]
    check(ncpl == len(geoms), f"{path}: NCPL {ncpl}, {len(geoms)} cells")
    verts = {}
    for t in b["VERTICES"]:
        verts[int(t[0])] = (float(t[1]), float(t[2]))
    check(sorted(verts) == list(range(1, nvert + 1)), f"{path}: vertices not numbered 1..NVERT")
    check("TOP" in [t[0].upper() for t in b["GRIDDATA"]], f"{path}: no TOP")
    check(len(b["CELL2D"]) == ncpl, f"{path}: {len(b['CELL2D'])} CELL2D lines")
    used = set()
    edges = {}
    total = 0.0
    for t in b["CELL2D"]:
        icell, xc, yc, nc = int(t[0]), float(t[1]), float(t[2]), int(t[3])
        iv = [int(v) for v in t[4:]]
        check(len(iv) == nc, f"{path}: cell {icell} lists {len(iv)} vertices, says {nc}")
        check(iv[0] == iv[-1], f"{path}: cell {icell} not closed")
        x0, y0 = verts[iv[0]]
        ring = [(verts[v][0] - x0, verts[v][1] - y0) for v in iv[:-1]]
        used.update(iv)
        a = 0.5 * sum(ring[i][0] * ring[i - 1][1] - ring[i - 1][0] * ring[i][1] for i in range(len(ring)))
        check(a > 0, f"{path}: cell {icell} is not clockwise (area {a})")
        total += a
        g = geoms[icell - 1]
        check(abs(a - g.area) <= 1e-9 * max(g.area, 1e-12) + 1e-15 * scale,
              f"{path}: cell {icell} area {a} != {g.area}")
        check(g.distance(Point(xc, yc)) <= 1e-9 * math.sqrt(max(g.area, 1e-300)),
              f"{path}: center of cell {icell} not in it")
        for i in range(len(iv) - 1):
            e = (min(iv[i], iv[i + 1]), max(iv[i], iv[i + 1]))
            edges.setdefault(e, []).append(icell)
    check(used == set(range(1, nvert + 1)), f"{path}: vertices not all used")
    check(all(len(c) <= 2 for c in edges.values()), f"{path}: an edge shared by more than 2 cells")
    return total


def check_triangle(prefix, domain):
    """Triangle's .node/.ele/.edge: counts, 1-based indices, counterclockwise triangles tiling
    the domain, every edge of the triangles listed once, markers on the boundary."""
    node = [l.split() for l in open(prefix + ".node") if l.strip() and not l.startswith("#")]
    ele = [l.split() for l in open(prefix + ".ele") if l.strip() and not l.startswith("#")]
    edge = [l.split() for l in open(prefix + ".edge") if l.strip() and not l.startswith("#")]
    n, dim, nattr, nmark = map(int, node[0])
    check(dim == 2 and len(node) == n + 1, f"{prefix}.node: header or count")
    pts = {int(t[0]): (float(t[1]), float(t[2])) for t in node[1:]}
    nt = int(ele[0][0])
    check(len(ele) == nt + 1 and int(ele[0][1]) == 3, f"{prefix}.ele: header or count")
    area, tri_edges = 0.0, {}
    for t in ele[1:]:
        a, b, c = (pts[int(v)] for v in t[1:4])
        s = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
        check(s > 0, f"{prefix}.ele: triangle {t[0]} not counterclockwise")
        area += s
        v = [int(x) for x in t[1:4]]
        for i in range(3):
            e = (min(v[i], v[(i + 1) % 3]), max(v[i], v[(i + 1) % 3]))
            tri_edges[e] = tri_edges.get(e, 0) + 1
    check(abs(area - domain.area) <= 1e-9 * domain.area, f"{prefix}.ele: area {area} != {domain.area}")
    ne = int(edge[0][0])
    listed = {}
    for t in edge[1:]:
        e = (min(int(t[1]), int(t[2])), max(int(t[1]), int(t[2])))
        listed[e] = int(t[3])
    check(len(edge) == ne + 1 and len(listed) == ne, f"{prefix}.edge: count or repeated edges")
    check(set(listed) == set(tri_edges), f"{prefix}.edge: not the triangles' edges")
    boundary = [e for e, k in tri_edges.items() if k == 1]
    check(all(listed[e] == 1 for e in boundary), f"{prefix}.edge: a boundary edge without marker 1")


def main():
    cvt2, data, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    # Each domain as cvt2 reads it, and as shapely reads it (the same coordinates).
    cases = [("four_clusters.poly", "four_clusters.wkt", 2000),
             ("us_massachusetts_counties.wkt", "us_massachusetts_counties.wkt", 3000),
             ("us_kentucky_counties.geojson", "us_kentucky_counties.geojson", 3000),
             ("earcut_eberly6.poly", "earcut_eberly6.wkt", 2000),
             ("world_land_110m.poly", "world_land_110m.wkt", 3000),
             ("square_inner_constraints.wkt", "square_inner_constraints.wkt", 1500)]
    for name, reference, n in cases:
        src = os.path.join(data, name)
        out = os.path.join(work, name)
        cmd = [cvt2, src, "-n", str(n), "--iterations", "30", "--quiet", "--geojson", out + ".geojson",
               "--vtu", out + ".vtu", "--disv", out + ".disv", "--mesh-out", out,
               "--points-out", out + ".pts"]
        r = subprocess.run(cmd, capture_output=True, text=True)
        check(r.returncode == 0, f"{' '.join(cmd)} failed: {r.stderr}")
        if r.returncode:
            continue
        cells = sum(1 for l in open(out + ".pts") if l.strip())
        domain = domain_geometry(os.path.join(data, reference))
        geoms = check_geojson(out + ".geojson", domain, cells)
        check_vtu(out + ".vtu", geoms, domain.area)
        total = check_disv(out + ".disv", geoms, domain.area)
        check(abs(total - domain.area) <= 1e-9 * domain.area, f"{name}: DISV areas {total}")
        check_triangle(out, domain)
        print(f"{name}: {cells} cells read back by shapely, meshio and the DISV and Triangle readers")
    # Rings that touch themselves (ESRI-style inverted holes, a hole around an island): the
    # domain is what GEOS's make_valid makes of them.
    here = os.path.dirname(os.path.abspath(__file__))
    for name in ("pocket_outer.wkt", "pocket_hole.wkt", "island_in_lake.wkt"):
        src, out = os.path.join(here, name), os.path.join(work, name)
        r = subprocess.run([cvt2, src, "-n", "200", "--iterations", "5", "--quiet", "--geojson",
                            out + ".geojson"], capture_output=True, text=True)
        check(r.returncode == 0, f"cvt2 {name} failed: {r.stderr}")
        if r.returncode:
            continue
        domain = domain_geometry(src)
        check_geojson(out + ".geojson", domain, len(json.load(open(out + ".geojson"))["features"]))
        print(f"{name}: the cells cover GEOS's reading of the rings, area {domain.area}")
    # A square grid of generators, step 0.1 (not a binary fraction): every four of them are
    # cocircular in true numbers, not quite in doubles, their circumcenters a rounding apart.
    name = "square_inner_constraints.wkt"
    src, out = os.path.join(data, name), os.path.join(work, "grid")
    with open(out + ".txt", "w") as f:
        for i in range(1, 100):
            for j in range(1, 100):
                f.write(f"{i * 0.1!r} {j * 0.1!r}\n")
    r = subprocess.run([cvt2, src, "--points-in", out + ".txt", "--iterations", "0", "--quiet",
                        "--geojson", out + ".geojson", "--vtu", out + ".vtu", "--disv",
                        out + ".disv", "--points-out", out + ".pts"], capture_output=True, text=True)
    check(r.returncode == 0, f"cvt2 {name} on a grid failed: {r.stderr}")
    if r.returncode == 0:
        domain = domain_geometry(src)
        cells = sum(1 for l in open(out + ".pts") if l.strip())  # the domain's vertices too
        geoms = check_geojson(out + ".geojson", domain, cells)
        check_vtu(out + ".vtu", geoms, domain.area)
        check_disv(out + ".disv", geoms, domain.area)
        print(f"a grid of {99 * 99} generators on {name}: {cells} valid cells, read back")
    if failures:
        print(f"{len(failures)} failures")
        sys.exit(1)


if __name__ == "__main__":
    main()
