#!/usr/bin/env python3
# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Checks the natural_neighbours example against references built independently with
shapely/GEOS.

    check_natural_neighbours.py NATURAL_NEIGHBOURS WORK_DIR

Writes its own small domains (.poly), nodes and queries into WORK_DIR, runs the program (Sibson
and --laplace) and checks, query by query:
  * convex domains (a square, a heptagon) without inner constraints: the weights equal, to
    1e-9, those of GEOS's Voronoi cells (shapely.ops.voronoi_diagram) clipped to the domain,
    before and after q is added: Sibson |C_q ∩ C_i| / |C_q|, Laplace s_i / h_i normalised (s_i
    the length of q's cell's boundary on the bisector of q and x_i);
  * domains with constraints (cracks, one from the boundary; a hole; a reflex corner with a
    crack): the same, against the bounded Voronoi diagram built from its definition: the cell
    of x_i is the part of the domain x_i sees that is no nearer to another node seen from there
    (visibility regions, shadows and bisector half-planes overlaid by GEOS on a 2^-42 grid);
    Laplace ignores the edges on constraints;
  * the natural neighbours themselves: a node whose reference weight exceeds 1e-12 has a
    weight, a node the reference gives none (no common area, no bisector edge) has none;
  * everywhere: one line per query in input order, printed back exactly; `qx qy 0` exactly
    when the domain excludes q (GEOS's exact point-in-polygon); weights positive, summing to 1
    within 1e-13; none for a node hidden from q by a constraint; the Kronecker delta at the
    nodes; nodes sorted by (x, y). Queries: random, at every node, on every segment's midpoint
    and 1e-12 off it, 1e-9 from nodes and around the ends of the cracks, outside;
  * errors: a malformed query, point or .poly line, a point outside the domain and a missing
    file: exit status 1, nothing on standard output, the file (and line) named on stderr.
Exit status 0 if all hold, 1 otherwise (each failure printed), 77 (skipped) without numpy or
shapely.
"""
import math
import os
import subprocess
import sys
import time
from fractions import Fraction

try:
    import numpy as np
    from shapely.geometry import MultiPoint, MultiPolygon, Point, Polygon, box
    from shapely.ops import voronoi_diagram
except ImportError as e:  # CTest reports the test as skipped (SKIP_RETURN_CODE 77)
    print(f"skipped: {e}")
    sys.exit(77)

TOL = 1e-9          # on weights
SHARE = 1e-12       # a reference weight above this is a natural neighbour
SUM_TOL = 1e-13     # on the sum of the printed weights

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)
    return condition


# ---------------------------------------------------------------------------------------------
# Input files

class Domain:
    """A domain as written to the .poly file: vertices, segments (0-based, with Triangle's
    markers 1 outer, 2 hole, 3 inner constraint), hole seeds; and as shapely sees it."""

    def __init__(self, name, outer, holes=(), cracks=()):
        self.name = name
        self.vertices, self.segments, self.hole_points = [], [], []
        index = {}

        def vertex(p):
            p = (float(p[0]), float(p[1]))
            if p not in index:
                index[p] = len(self.vertices)
                self.vertices.append(p)
            return index[p]

        def ring(points, marker):
            ids = [vertex(p) for p in points]
            for k in range(len(ids)):
                self.segments.append((ids[k], ids[(k + 1) % len(ids)], marker))

        ring(outer, 1)
        for hole in holes:
            ring(hole, 2)
            self.hole_points.append(Polygon(hole).representative_point().coords[0])
        for a, b in cracks:
            self.segments.append((vertex(a), vertex(b), 3))
        self.shape = Polygon(outer, list(holes))
        assert self.shape.is_valid
        self.constraints = [(np.array(self.vertices[i]), np.array(self.vertices[j]))
                            for i, j, _ in self.segments]
        # The side of each segment's line the whole domain lies on (0 if on both): from there
        # the segment hides nothing of the domain.
        self.domain_side = []
        for a, b in self.constraints:
            sides = {orient(a, b, v) for v in self.vertices} - {0}
            self.domain_side.append(sides.pop() if len(sides) == 1 else 0)
        x0, y0, x1, y1 = self.shape.bounds
        self.scale = math.hypot(x1 - x0, y1 - y0)

    def write(self, path):
        with open(path, "w") as f:
            f.write(f"# {self.name}, written by check_natural_neighbours.py\n")
            f.write(f"{len(self.vertices)} 2 0 0\n")
            for k, (x, y) in enumerate(self.vertices):
                f.write(f"{k + 1} {x!r} {y!r}\n")
            f.write(f"{len(self.segments)} 1\n")
            for k, (i, j, marker) in enumerate(self.segments):
                f.write(f"{k + 1} {i + 1} {j + 1} {marker}\n")
            f.write(f"{len(self.hole_points)}\n")
            for k, (x, y) in enumerate(self.hole_points):
                f.write(f"{k + 1} {x!r} {y!r}\n")


def write_points(path, points):
    with open(path, "w") as f:
        f.write("# x y\n")
        for x, y in points:
            f.write(f"{float(x)!r} {float(y)!r}\n")


def random_points(rng, domain, n, spacing, clearance):
    """n points inside the domain, `spacing` apart and from its vertices, `clearance` from
    every constraint."""
    x0, y0, x1, y1 = domain.shape.bounds
    pts = [np.array(v) for v in domain.vertices]
    out = []
    while len(out) < n:
        p = np.array([rng.uniform(x0, x1), rng.uniform(y0, y1)])
        if not domain.shape.contains(Point(p)):
            continue
        if min(np.hypot(*(p - q)) for q in pts) < spacing:
            continue
        if min(segment_distance(p, a, b) for a, b in domain.constraints) < clearance:
            continue
        pts.append(p)
        out.append((float(p[0]), float(p[1])))
    return out


# ---------------------------------------------------------------------------------------------
# Running the program and reading its output

def run(program, *args):
    return subprocess.run([program, *args], capture_output=True, text=True)


def parse_output(label, text, queries, node_index):
    """The program's lines as a list of (status, {node: weight}) per query; status is
    'outside', 'inside' or None when the line is malformed."""
    lines = text.splitlines()
    if not check(len(lines) == len(queries),
                 f"{label}: {len(lines)} output lines for {len(queries)} queries"):
        return None
    rows = []
    for k, (line, q) in enumerate(zip(lines, queries)):
        t = line.split()
        where = f"{label}: query {k + 1} {q}"
        try:
            qx, qy, m = float(t[0]), float(t[1]), int(t[2])
            ok = len(t) == 3 + 3 * m and m >= 0
        except (ValueError, IndexError):
            ok = False
        if not check(ok, f"{where}: malformed line {line!r}"):
            rows.append((None, {}))
            continue
        check((qx, qy) == tuple(q), f"{where}: printed as ({t[0]}, {t[1]})")
        if m == 0:
            check(t == [t[0], t[1], "0"], f"{where}: malformed empty row {line!r}")
            rows.append(("outside", {}))
            continue
        row, keys = {}, []
        for e in range(m):
            x, y, w = float(t[3 + 3 * e]), float(t[4 + 3 * e]), float(t[5 + 3 * e])
            keys.append((x, y))
            i = node_index.get((x, y))
            if not check(i is not None, f"{where}: ({x}, {y}) is not a node"):
                continue
            check(i not in row, f"{where}: node ({x}, {y}) twice")
            check(w > 0 and math.isfinite(w), f"{where}: node ({x}, {y}) has weight {w}")
            row[i] = w
        check(keys == sorted(keys), f"{where}: nodes not sorted by (x, y)")
        total = math.fsum(row.values())
        check(abs(total - 1) <= SUM_TOL, f"{where}: weights sum to 1{total - 1:+.3e}")
        rows.append(("inside", row))
    return rows


# ---------------------------------------------------------------------------------------------
# Exact-enough predicates

def orient(a, b, c):
    """The sign of the orientation of (a, b, c), exact (floating-point filter, then
    rationals)."""
    det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    bound = 1e-12 * (abs((b[0] - a[0]) * (c[1] - a[1])) + abs((b[1] - a[1]) * (c[0] - a[0])))
    if abs(det) > bound:
        return 1 if det > 0 else -1
    A = [Fraction(float(v)) for v in a]
    B = [Fraction(float(v)) for v in b]
    C = [Fraction(float(v)) for v in c]
    det = (B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0])
    return (det > 0) - (det < 0)


def properly_cross(p, q, a, b):
    """Segments pq and ab cross at one point interior to both."""
    return (orient(a, b, p) * orient(a, b, q) < 0) and (orient(p, q, a) * orient(p, q, b) < 0)


def segment_distance(p, a, b):
    px, py, ax, ay, bx, by = float(p[0]), float(p[1]), float(a[0]), float(a[1]), float(b[0]), \
        float(b[1])
    dx, dy = bx - ax, by - ay
    t = min(1.0, max(0.0, ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy)))
    return math.hypot(px - ax - t * dx, py - ay - t * dy)


def on_segment(p, a, b):
    """p lies on the closed segment ab, exactly."""
    return orient(a, b, p) == 0 and min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and \
        min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def visible(p, x, constraints):
    """x is seen from p: the segment p-x properly crosses no constraint."""
    return not any(properly_cross(p, x, a, b) for a, b in constraints)


def overlap(b1, b2):
    """Two bounding boxes overlap."""
    return b1[0] <= b2[2] and b2[0] <= b1[2] and b1[1] <= b2[3] and b2[1] <= b1[3]


def polygons(g):
    """The polygons of a GEOS result, without the points and lines of degenerate contacts."""
    if g.geom_type in ("Polygon", "MultiPolygon"):
        return g
    parts = [p for p in getattr(g, "geoms", []) if p.geom_type == "Polygon"]
    parts += [q for p in getattr(g, "geoms", []) if p.geom_type == "MultiPolygon" for q in p.geoms]
    return MultiPolygon(parts) if len(parts) > 1 else parts[0] if parts else Polygon()


# GEOS's overlay on a fixed grid (snap rounding: robust by construction), which shapely 1.8 does
# not offer: in floating point, GEOS 3.11 gets edges that coincide to an ulp wrong (a visibility
# region minus a shadow that only touches it came out empty). The grid, 2^-42 (about 2e-13),
# moves vertices by less than that: areas by about 1e-12.
GRID = 2.0 ** -42
_prec = {}
try:
    import ctypes
    from shapely.geometry.base import geom_factory
    from shapely.geos import lgeos

    for how, name in (("intersection", "GEOSIntersectionPrec_r"),
                      ("difference", "GEOSDifferencePrec_r")):
        fn = getattr(lgeos._lgeos, name)
        fn.restype = ctypes.c_void_p
        fn.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_double]
        _prec[how] = fn
except (AttributeError, ImportError):  # shapely 2 has grid_size; GEOS before 3.9 has no grid
    _prec = {}


def overlay(a, b, how):
    """a.intersection(b) or a.difference(b), its polygons only, on the grid."""
    if how in _prec:
        ptr = _prec[how](lgeos.geos_handle, a._geom, b._geom, GRID)
        if not ptr:
            raise RuntimeError(f"GEOS {how} on the grid failed")
        return polygons(geom_factory(ptr))
    try:
        return polygons(getattr(a, how)(b, grid_size=GRID))  # shapely 2
    except TypeError:
        return polygons(getattr(a, how)(b))


# ---------------------------------------------------------------------------------------------
# Reference 1: GEOS's Voronoi diagram clipped to a convex domain

def voronoi_cell_of(sites, site, domain):
    """Each cell of the Voronoi diagram of `sites` that contains one of `site` (a list of
    points), clipped to the domain."""
    x0, y0, x1, y1 = domain.shape.bounds
    d = domain.scale
    envelope = box(x0 - 2 * d, y0 - 2 * d, x1 + 2 * d, y1 + 2 * d)
    cells = list(voronoi_diagram(MultiPoint([tuple(s) for s in sites]), envelope=envelope).geoms)
    out = []
    for s in site:
        p = Point(s)
        found = [c for c in cells if c.contains(p)]
        assert len(found) == 1, f"no single Voronoi cell contains {s}"
        out.append(overlay(found[0], domain.shape, "intersection"))
    return out


class VoronoiReference:
    def __init__(self, domain, nodes):
        self.domain, self.nodes = domain, np.array(nodes)
        self.query_cells = {}
        self.old = voronoi_cell_of(self.nodes, self.nodes, domain)
        total = sum(c.area for c in self.old)
        assert abs(total - domain.shape.area) <= 1e-12 * domain.shape.area, "cells do not tile"

    def cell_of_query(self, q):
        return voronoi_cell_of(np.vstack([self.nodes, [q]]), [q], self.domain)[0]

    def visible(self, p, i):
        return True


# ---------------------------------------------------------------------------------------------
# Reference 2: the bounded Voronoi diagram from its definition

class DefinitionReference:
    """cell(x_i) = V(x_i) minus the union over j of V(x_j) ∩ {p nearer to x_j than to x_i},
    V(x) the part of the domain seen from x (the domain minus the shadows the constraints
    cast from x). Every set is a GEOS polygon, every operation overlay(); every half-plane a
    rectangle larger than the domain."""

    def __init__(self, domain, nodes):
        self.domain, self.nodes = domain, np.array(nodes)
        self.query_cells = {}
        self.R = 4 * domain.scale
        x0, y0, x1, y1 = domain.shape.bounds
        pad = 0.01 * domain.scale
        self.frame = box(x0 - pad, y0 - pad, x1 + pad, y1 + pad)  # holds the domain
        self.seen = [self.visibility(x) for x in self.nodes]
        self.old = [self.cell(x, self.seen[i], skip=i) for i, x in enumerate(self.nodes)]
        total = sum(c.area for c in self.old)
        assert abs(total - domain.shape.area) <= 1e-11 * domain.shape.area, \
            f"{domain.name}: reference cells do not tile ({total} vs {domain.shape.area})"

    def halfplane(self, p, n, q=None):
        """{y : (y - p).n >= 0} within R of p, n of any length, as a rectangle with p (and q,
        a second point of the line) among its vertices, exactly."""
        n = np.asarray(n, float) / math.hypot(*n)
        d = np.array([-n[1], n[0]])
        p, R = np.asarray(p, float), self.R
        on_line = [p] if q is None else ([p, q] if np.dot(q - p, d) > 0 else [q, p])
        return Polygon([p - R * d] + on_line + [p + R * d, p + R * d + R * n, p - R * d + R * n])

    def shadow(self, x, a, b):
        """What the segment ab hides from x, or None: the part of the frame beyond ab and
        between the rays from x through a and through b."""
        side = orient(a, b, x)
        if side == 0:
            return None  # x on the segment's line: it hides no area
        ab, xa, xb = b - a, a - x, b - x
        beyond = np.array([ab[1], -ab[0]]) * side        # away from x
        toward_b = np.array([-xa[1], xa[0]]) * side       # the side of ray x->a holding b
        toward_a = np.array([xb[1], -xb[0]]) * side       # the side of ray x->b holding a
        s = self.frame
        for h in (self.halfplane(a, beyond, b), self.halfplane(x, toward_b),
                  self.halfplane(x, toward_a)):
            s = overlay(s, h, "intersection")
        return s

    def visibility(self, x):
        v = self.domain.shape
        for (a, b), side in zip(self.domain.constraints, self.domain.domain_side):
            if side and orient(a, b, x) == side:
                continue  # everything beyond ab is outside the domain
            s = self.shadow(x, a, b)
            if s is not None and not s.is_empty and overlap(s.bounds, v.bounds):
                v = overlay(v, s, "difference")
        return v

    def cell(self, x, seen, skip=None):
        c = seen
        distance = np.hypot(*(self.nodes - x).T)
        coords = None
        for j in np.argsort(distance):
            if j == skip or distance[j] == 0:
                continue
            if coords is None:
                coords = np.vstack(list(rings(c)))
                reach = np.hypot(*(coords - x).T).max()
            if distance[j] > 2 * reach * (1 + 1e-12):
                break  # this node's bisector, and those of all farther, miss the cell
            xj = self.nodes[j]
            n = xj - x
            mid = (x + xj) / 2
            if ((coords - mid) @ n).max() <= 0:
                continue  # the cell is all on x's side of the bisector
            coords = None
            nearer = overlay(self.seen[j], self.halfplane(mid, n), "intersection")
            c = overlay(c, nearer, "difference")
            if c.is_empty:
                break
        return c

    def cell_of_query(self, q):
        return self.cell(np.asarray(q, float), self.visibility(np.asarray(q, float)))

    def visible(self, p, i):
        return visible(p, self.nodes[i], self.domain.constraints)


# ---------------------------------------------------------------------------------------------
# Coordinates from the reference cells

def rings(geom):
    polys = [geom] if geom.geom_type == "Polygon" else \
        [g for g in getattr(geom, "geoms", []) if g.geom_type == "Polygon"]
    for p in polys:
        yield np.array(p.exterior.coords)
        for r in p.interiors:
            yield np.array(r.coords)


def reference_weights(ref, q, method):
    """{node: weight} of every node with a positive share, and q's cell."""
    key = (float(q[0]), float(q[1]))
    if key not in ref.query_cells:
        ref.query_cells[key] = ref.cell_of_query(np.asarray(q, float))
    q = np.asarray(q, float)
    cq = ref.query_cells[key]
    area = cq.area
    out = {}
    if method == "sibson":
        if not hasattr(ref, "old_bounds"):
            ref.old_bounds = np.array([c.bounds if not c.is_empty else (np.inf,) * 4
                                       for c in ref.old])
        b, qb = ref.old_bounds, cq.bounds
        near = (b[:, 0] <= qb[2]) & (qb[0] <= b[:, 2]) & (b[:, 1] <= qb[3]) & (qb[1] <= b[:, 3])
        for i in np.nonzero(near)[0]:
            share = overlay(ref.old[i], cq, "intersection").area / area
            if share > 0:
                out[i] = share
        # The old cells tile the domain, so the shares sum to 1: else the reference is wrong.
        assert abs(math.fsum(out.values()) - 1) <= 1e-10, f"reference shares at {q} do not sum to 1"
        return out, cq
    # Laplace: the edges of q's cell on the bisector of q and a node seen from the edge, not
    # on a constraint, each over the distance from q to that node.
    tol, on_tol = 1e-10 * ref.domain.scale, 1e-12 * ref.domain.scale
    hq = np.hypot(*(ref.nodes - q).T)
    normal = (ref.nodes - q) / np.where(hq > 0, hq, 1.0)[:, None]  # of each bisector
    middle = (ref.nodes + q) / 2
    lengths = {}
    for r in rings(cq):
        for u, v in zip(r[:-1], r[1:]):
            length = math.hypot(*(v - u))
            if length == 0:
                continue
            m = (u + v) / 2
            if min(segment_distance(m, a, b) for a, b in ref.domain.constraints) <= on_tol:
                continue  # on a constraint (to the grid: a bisector may run 1e-10 from one)
            # the distances of u and v to each bisector (not the difference of the distances to
            # q and the node: that is at most |q - x_i|, small for a query near a node)
            du = np.abs(np.einsum("ij,ij->i", u - middle, normal))
            dv = np.abs(np.einsum("ij,ij->i", v - middle, normal))
            for i in np.nonzero((du <= tol) & (dv <= tol) & (hq > 0))[0]:
                if ref.visible(m, i):
                    lengths[i] = lengths.get(i, 0.0) + length
    total = sum(s / hq[i] for i, s in lengths.items())
    return {i: s / hq[i] / total for i, s in lengths.items()}, cq


def compare(where, got, ref, nodes):
    """Failure messages for one query: the same natural neighbours, the same weights. A node
    whose reference weight exceeds SHARE must have a weight; a node the reference gives no
    weight at all (its cell and q's share no area, or no bisector edge) must have none; in
    between, the weight is optional (too small to demand)."""
    msgs = []
    name = lambda i: f"({nodes[i][0]!r}, {nodes[i][1]!r})"
    for i in sorted(i for i, w in ref.items() if w > SHARE and i not in got):
        msgs.append(f"{where}: node {name(i)} missing, expected weight {ref[i]!r}")
    for i in sorted(set(got) - set(ref)):
        msgs.append(f"{where}: node {name(i)} has weight {got[i]!r}, expected 0 (not a "
                    f"natural neighbour)")
    for i in sorted(set(got) | set(ref)):
        g, e = got.get(i, 0.0), ref.get(i, 0.0)
        if abs(g - e) > TOL and i in got and i in ref:
            msgs.append(f"{where}: node {name(i)} weight {g!r}, expected {e!r} "
                        f"(difference {g - e:+.3e})")
    return msgs


# ---------------------------------------------------------------------------------------------
# The cases

def node_list(domain, points):
    nodes = list(domain.vertices) + list(points)
    assert len(set(nodes)) == len(nodes)
    return nodes


def special_queries(domain, nodes):
    """Queries exactly at every node, at the midpoints of the segments (exactly on them: the
    coordinates are dyadic) and just off them on either side, 1e-9 from a few nodes and
    around the ends of the inner constraints."""
    out = [tuple(p) for p in nodes]
    for i, j, _ in domain.segments:
        a, b = np.array(domain.vertices[i]), np.array(domain.vertices[j])
        m = (a + b) / 2
        n = np.array([b[1] - a[1], a[0] - b[0]]) / math.hypot(*(b - a))
        out += [tuple(m), tuple(m + 1e-12 * n), tuple(m - 1e-12 * n)]
    points = nodes[len(domain.vertices):]
    near = [(x + 1e-9, y - 0.5e-9) for x, y in points[:: max(1, len(points) // 6)]]
    for i in sorted({k for i, j, marker in domain.segments if marker == 3 for k in (i, j)}):
        x, y = domain.vertices[i]
        near += [(x + 1e-9, y), (x - 1e-9, y), (x, y + 1e-9), (x, y - 1e-9)]
    out += [p for p in near if domain.shape.covers(Point(p))]
    return [(float(x), float(y)) for x, y in out]


def random_queries(rng, domain, n):
    x0, y0, x1, y1 = domain.shape.bounds
    out = []
    while len(out) < n:
        p = (rng.uniform(x0, x1), rng.uniform(y0, y1))
        if domain.shape.covers(Point(p)):
            out.append(p)
    return out


def run_case(program, work, domain, points, queries, ref):
    """Runs Sibson and Laplace on the case and checks every query. Returns the count of rows
    compared with the reference and their largest difference."""
    base = os.path.join(work, domain.name)
    domain.write(base + ".poly")
    write_points(base + "_points.txt", points)
    write_points(base + "_queries.txt", queries)
    nodes = node_list(domain, points)
    node_index = {p: i for i, p in enumerate(nodes)}
    compared, largest = 0, 0.0
    for method in ("sibson", "laplace"):
        label = f"{domain.name} {method}"
        args = [base + ".poly", base + "_points.txt", base + "_queries.txt"]
        r = run(program, *args, *(["--laplace"] if method == "laplace" else []))
        if not check(r.returncode == 0, f"{label}: exit status {r.returncode}: {r.stderr}"):
            continue
        rows = parse_output(label, r.stdout, queries, node_index)
        if rows is None:
            continue
        for k, (q, (status, got)) in enumerate(zip(queries, rows)):
            where = f"{label}: query {k + 1} ({q[0]!r}, {q[1]!r})"
            inside = domain.shape.covers(Point(q))
            if status is None:
                continue
            verb = "covers" if inside else "excludes"
            if not check((status == "inside") == inside,
                         f"{where}: {status}, but the domain {verb} it"):
                continue
            if not inside:
                continue
            if q in node_index:
                i = node_index[q]
                check(got == {i: 1.0}, f"{where}: at a node, weights {got} instead of delta")
                continue
            for i in got:  # no weight across a constraint
                check(visible(np.array(q), np.array(nodes[i]), domain.constraints),
                      f"{where}: node {nodes[i]} hidden by a constraint has weight {got[i]!r}")
            expected, _ = reference_weights(ref, q, method)
            on = [f"({a[0]:g}, {a[1]:g})-({b[0]:g}, {b[1]:g})" for a, b in domain.constraints
                  if on_segment(q, a, b)]
            where += f" (on the segment {on[0]})" if on else ""
            for msg in compare(where, got, expected, nodes):
                check(False, msg)
            compared += 1
            largest = max([largest] + [abs(got.get(i, 0.0) - expected.get(i, 0.0))
                                       for i in set(got) | set(expected)])
    return compared, largest


def check_errors(program, work, domain_path):
    """Malformed and missing files: exit status 1 and a message naming file and line."""
    def expect_error(label, args, needle):
        r = run(program, *args)
        check(r.returncode == 1, f"{label}: exit status {r.returncode}, expected 1")
        check(needle in r.stderr, f"{label}: stderr {r.stderr.strip()!r} does not name {needle!r}")
        check(r.stdout == "", f"{label}: output {r.stdout[:80]!r} despite the error")

    bad_queries = os.path.join(work, "bad_queries.txt")
    with open(bad_queries, "w") as f:
        f.write("# queries\n1 1\n2.5 3\n4 seven\n5 5\n")
    expect_error("malformed query", [domain_path, "-", bad_queries], f"{bad_queries}:4")
    with open(bad_queries, "w") as f:
        f.write("1 1\n\n2 2 2\n")
    expect_error("query of three numbers", [domain_path, "-", bad_queries], f"{bad_queries}:3")
    bad_points = os.path.join(work, "bad_points.txt")
    with open(bad_points, "w") as f:
        f.write("1 1\n2 nan\n")
    good_queries = os.path.join(work, "good_queries.txt")
    write_points(good_queries, [(1.0, 1.0)])
    expect_error("malformed point", [domain_path, bad_points, good_queries], f"{bad_points}:2")
    with open(bad_points, "w") as f:
        f.write("1 1\n# outside\n\n20 20\n")
    expect_error("point outside the domain", [domain_path, bad_points, good_queries],
                 f"{bad_points}:4")
    bad_poly = os.path.join(work, "bad.poly")
    with open(bad_poly, "w") as f:
        f.write("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 1\n1 1 2 1\n2 2 3 1\n3 3 9 1\n0\n")
    expect_error("malformed .poly", [bad_poly, "-", good_queries], f"{bad_poly}:8")
    missing = os.path.join(work, "no_such_queries.txt")
    expect_error("missing query file", [domain_path, "-", missing], missing)
    missing = os.path.join(work, "no_such_domain.poly")
    expect_error("missing domain", [missing, "-", good_queries], missing)
    r = run(program, domain_path, "-")
    check(r.returncode != 0 and "usage" in r.stderr, "two arguments: no usage message")


def report(before, what):
    """`ok what` if no check failed since `before` failures, else how many did."""
    if len(failures) == before:
        print("ok", what)
    else:
        print(f"FAILED ({len(failures) - before} checks above) {what.split(':')[0]}; measured: "
              f"{what.split(': ', 1)[-1]}")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: check_natural_neighbours.py NATURAL_NEIGHBOURS WORK_DIR")
    program, work = sys.argv[1:3]
    os.makedirs(work, exist_ok=True)
    start = time.time()
    rng = np.random.default_rng(20260213)

    # The comparison itself must see a wrong weight.
    check(compare("self-test", {0: 0.5 + 2 * TOL, 1: 0.5 - 2 * TOL}, {0: 0.5, 1: 0.5}, [(0, 0)] * 2)
          and compare("self-test", {0: 1.0}, {0: 0.9, 1: 0.1}, [(0, 0)] * 2)
          and compare("self-test", {0: 0.9, 1: 0.1}, {0: 1.0, 1: 1e-13}, [(0, 0)] * 2),
          "the comparison does not catch a perturbed weight")

    # 1. Convex domains, no constraints: GEOS's Voronoi diagram, clipped.
    convex = [
        (Domain("square", [(0, 0), (10, 0), (10, 10), (0, 10)]), 120, 0.25),
        (Domain("convex_heptagon", [(0, 0), (6, -1), (11, 2), (12.5, 7), (8, 11), (2, 10.25),
                                    (-1, 5)]), 60, 0.4),
    ]
    for domain, n, spacing in convex:
        points = random_points(rng, domain, n, spacing, 0.05)
        nodes = node_list(domain, points)
        queries = random_queries(rng, domain, 200) + special_queries(domain, nodes) + \
            [(-1.0, 5.0), (5.0, 13.0), (20.0, 20.0), (-1e-9, 1e-9)]
        ref = VoronoiReference(domain, nodes)
        # The two references agree where both apply.
        definition = DefinitionReference(domain, nodes)
        worst = 0.0
        for q in queries[:15]:
            for method in ("sibson", "laplace"):
                a, _ = reference_weights(ref, q, method)
                b, _ = reference_weights(definition, q, method)
                worst = max([worst] + [abs(a.get(i, 0) - b.get(i, 0)) for i in set(a) | set(b)])
        check(worst <= 1e-11, f"{domain.name}: the two references differ by {worst:.3e}")
        before = len(failures)
        compared, largest = run_case(program, work, domain, points, queries, ref)
        report(before, f"{domain.name}: {len(nodes)} nodes, {len(queries)} queries; {compared} "
               f"Sibson and Laplace rows equal GEOS's clipped Voronoi cells (largest difference "
               f"{largest:.1e}; the two references agree to {worst:.1e})")

    # 2. Constraints: a crack from the boundary and two inside, a hole, a reflex corner.
    constrained = [
        Domain("cracks", [(0, 0), (10, 0), (10, 10), (0, 10), (0, 5)],
               cracks=[((0, 5), (6, 5)), ((3, 7.25), (7.5, 8.5)), ((7.5, 1), (8.25, 3.5))]),
        Domain("hole", [(0, 0), (10, 0), (10, 10), (0, 10)],
               holes=[[(3, 3), (6.5, 2.5), (7, 6), (3.5, 6.5)]]),
        Domain("l_shape", [(0, 0), (10, 0), (10, 4), (4, 4), (4, 10), (0, 10)],
               cracks=[((1.5, 6), (2.75, 2.25))]),
    ]
    for domain in constrained:
        points = random_points(rng, domain, 40, 0.5, 0.1)
        nodes = node_list(domain, points)
        queries = random_queries(rng, domain, 120) + special_queries(domain, nodes) + \
            [(-1.0, 5.0), (5.0, 13.0), (5.0, -1e-300)]
        if domain.name == "hole":
            queries += [(5.0, 4.5), (4.0, 4.0)]  # inside the hole
        if domain.name == "l_shape":
            queries += [(7.0, 7.0), (4.0 + 1e-12, 7.0)]  # in the missing quadrant
        ref = DefinitionReference(domain, nodes)
        before = len(failures)
        compared, largest = run_case(program, work, domain, points, queries, ref)
        report(before, f"{domain.name}: {len(nodes)} nodes, {len(queries)} queries; {compared} "
               f"Sibson and Laplace rows equal the bounded Voronoi diagram's definition (largest "
               f"difference {largest:.1e}); weights positive, summing to 1, none across a "
               f"constraint, delta at the nodes")

    # 3. Errors.
    before = len(failures)
    check_errors(program, work, os.path.join(work, "square.poly"))
    report(before, "errors: malformed and missing files name the file and line, exit status 1")

    if failures:
        print(f"{len(failures)} failures")
        sys.exit(1)
    print(f"ok all in {time.time() - start:.1f} s")


if __name__ == "__main__":
    main()
