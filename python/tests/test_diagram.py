# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# bounded_voronoi(): cells valid for GEOS that tile the domain, scipy-style arrays consistent with
# each other and with the cells, agreement with scipy where scipy is right (a convex domain),
# cells that respect constraints and visibility where it is not.
import numpy as np
import pytest
import shapely.validation
import shapely.wkt
from shapely.geometry import LineString, MultiPolygon, Point, Polygon, box
from shapely.ops import unary_union

import cvt2


def shapely_of_wkt_file(path):
    polygons, lines = [], []
    for text in path.read_text().splitlines():
        if text.strip():
            g = shapely.wkt.loads(text)
            if g.geom_type in ("Polygon", "MultiPolygon"):
                polygons.append(g)
            elif g.geom_type in ("LineString", "MultiLineString"):
                lines.append(g)
    return unary_union(polygons), lines


def holed_square():
    """A 4 x 3 rectangle with a square hole, a constraint from the boundary into the domain and
    one inside it."""
    polygon = Polygon([(0, 0), (4, 0), (4, 3), (0, 3)], holes=[[(1, 1), (2, 1), (2, 2), (1, 2)]])
    constraints = [LineString([(2.5, 0), (3, 1.5), (3.5, 2.5)]), LineString([(0.5, 2.5), (1.5, 2.5)])]
    return polygon, constraints


def shoelace(xy):
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)


def diagrams(data):
    polygon, constraints = holed_square()
    shapely_domain = cvt2.Domain.from_shapely(polygon, constraints)
    cases = [(shapely_domain, polygon, 1500)]
    for file in ("four_clusters.wkt", "us_massachusetts_counties.wkt", "earcut_eberly6.wkt"):
        geometry, _ = shapely_of_wkt_file(data / file)
        cases.append((cvt2.Domain.from_file(data / file), geometry, 2500))
    cases.append((cvt2.Domain.from_file(data / "earcut_logo.poly"), None, 2000))
    cases.append((cvt2.Domain.from_file(data / "us_kentucky_counties.geojson"), None, 3000))
    for domain, geometry, n in cases:
        yield domain, geometry, cvt2.bounded_voronoi(domain, cvt2.random_points(domain, n, seed=8))


def test_cells_are_valid_and_tile_the_domain(data):
    for domain, geometry, vd in diagrams(data):
        cells = vd.to_shapely()
        assert len(cells) == len(vd.points)
        assert all(c.is_valid for c in cells), domain
        assert all(isinstance(c, (Polygon, MultiPolygon)) for c in cells)
        area = domain.area
        assert sum(c.area for c in cells) == pytest.approx(area, rel=1e-10)
        union = unary_union(cells)
        assert union.area == pytest.approx(area, rel=1e-9)  # so no two cells overlap
        if geometry is not None:
            assert union.symmetric_difference(geometry).area < 1e-9 * area
        assert np.allclose([c.area for c in cells], vd.areas, rtol=1e-9, atol=1e-12 * area)


def test_a_grid_of_generators_gives_valid_cells():
    # Step 0.1 is no binary fraction: every four neighbours are cocircular in true numbers but
    # not in doubles, and their circumcenters lie a rounding apart.
    polygon, constraints = holed_square()
    domain = cvt2.Domain.from_shapely(polygon, constraints)
    xy = np.array([(i * 0.1, j * 0.1) for i in range(1, 40) for j in range(1, 30)])
    xy = xy[[polygon.contains(Point(p)) for p in xy]]
    cells = cvt2.bounded_voronoi(domain, xy).to_shapely()
    invalid = [c for c in cells if not c.is_valid]
    assert not invalid, shapely.validation.explain_validity(invalid[0])
    assert sum(c.area for c in cells) == pytest.approx(domain.area, rel=1e-10)
    assert unary_union(cells).area == pytest.approx(domain.area, rel=1e-9)


def test_cells_small_against_their_coordinates_are_valid(tmp_path):
    # A right triangle's circumcenter is its hypotenuse's midpoint: computed, the two are a unit
    # in the last place apart, which at coordinates about 40 and cells of 0.01 is more than
    # 2^-40 of the cells. One vertex still, or the cells cross themselves, and a DISV repeats
    # the point (the cells around it share no vertex: MODFLOW sees no connection).
    rng = np.random.default_rng(1)
    triangles = [[(39.258461862487614, 21.445305310597536), (39.248461862487616, 21.445305310597536),
                  (39.248461862487616, 21.455305310597538)]]
    for _ in range(300):
        x, y = rng.uniform(-100, 100, 2)
        h = 10 ** rng.uniform(-3, 2)
        triangles.append([(x, y), (x + h, y), (x, y + h)])
    for corners in triangles:
        d = cvt2.Domain.from_shapely(Polygon(corners))
        vd = cvt2.bounded_voronoi(d, np.zeros((0, 2)))
        cells = vd.to_shapely()
        invalid = [c for c in cells if not c.is_valid]
        assert not invalid, (corners, shapely.validation.explain_validity(invalid[0]))
    d = cvt2.Domain.from_shapely(Polygon(triangles[0]))
    cvt2.bounded_voronoi(d, np.zeros((0, 2))).to_disv(tmp_path / "t.disv")
    text = (tmp_path / "t.disv").read_text()
    rows = text[text.index("BEGIN VERTICES"):text.index("END VERTICES")].splitlines()[1:]
    xy = [tuple(map(float, r.split()[1:3])) for r in rows]
    assert len(set(xy)) == len(xy) == 6  # the corners, the legs' midpoints, the circumcenter


def test_scipy_style_arrays_are_consistent(data):
    for domain, _, vd in diagrams(data):
        n, nv = len(vd.points), len(vd.vertices)
        scale = np.ptp(vd.vertices, axis=0).max()
        assert vd.points.shape == (n, 2) and vd.vertices.shape == (nv, 2)
        assert vd.constrained.dtype == bool and vd.constrained.shape == (n,)
        # Every region is the cell of some row (test_input_order.py: of which).
        assert np.array_equal(np.unique(vd.point_region[vd.point_region >= 0]), np.arange(n))
        assert len(vd.regions) == n and len(vd.cycles) == n
        # No -1 anywhere but in ridge_constraint, which says "a bisector".
        for r in vd.regions + vd.cycles:
            assert len(r) >= 3 and min(r) >= 0 and max(r) < nv
        assert vd.ridge_points.min() >= 0 and vd.ridge_points.max() < n
        assert vd.ridge_vertices.min() >= 0 and vd.ridge_vertices.max() < nv
        assert vd.ridge_constraint.min() >= -1
        assert vd.ridge_constraint.max() < len(domain.segments)
        # Regions are the cells: their areas, counterclockwise.
        areas = np.array([shoelace(vd.vertices[r]) for r in vd.regions])
        assert np.allclose(areas, vd.areas, rtol=1e-9, atol=1e-12 * scale**2)
        assert vd.areas.sum() == pytest.approx(domain.area, rel=1e-10)
        # Every ridge is an edge of the cycles of its cells, walked in opposite directions; a
        # boundary ridge once, a slit (a ridge with its cell on both sides) both ways in one cycle.
        edges = {}
        for k, c in enumerate(vd.cycles):
            for a, b in zip(c, c[1:] + c[:1]):
                edges.setdefault((a, b), []).append(k)
        assert sum(len(c) for c in vd.cycles) == 2 * len(vd.ridge_points) - vd.ridge_boundary.sum()
        for (p, q), (a, b), boundary in zip(vd.ridge_vertices, vd.ridge_points, vd.ridge_boundary):
            assert edges[(p, q)] == [a]
            if boundary:
                assert a == b and (q, p) not in edges
            else:
                assert edges[(q, p)] == [b]
        # A bisector ridge is equidistant from its two generators; a constraint ridge lies on
        # the input segment it names; the boundary is all constraint.
        bisector = vd.ridge_constraint < 0
        assert not np.any(bisector & vd.ridge_boundary)
        for e in np.flatnonzero(bisector)[:2000]:
            a, b = vd.points[vd.ridge_points[e]]
            assert vd.ridge_points[e][0] != vd.ridge_points[e][1]
            for v in vd.vertices[vd.ridge_vertices[e]]:
                assert np.hypot(*(v - a)) == pytest.approx(np.hypot(*(v - b)), rel=1e-6, abs=1e-9 * scale)
        ends = domain.vertices[domain.segments]
        for e in np.flatnonzero(~bisector):
            s = LineString(ends[vd.ridge_constraint[e]])
            for v in vd.vertices[vd.ridge_vertices[e]]:
                assert s.distance(Point(v)) <= 1e-9 * scale
        # Centroids, and each generator in its own cell (on its boundary if constrained).
        cells = vd.to_shapely()
        for k in range(0, n, 7):
            c = cells[k]
            assert np.allclose(vd.centroids[k], c.centroid.coords[0], rtol=0, atol=1e-9 * scale)
            assert c.buffer(1e-9 * scale).contains(Point(vd.points[k]))


def test_the_constraint_under_a_ridge_names_the_input(data):
    polygon, constraints = holed_square()
    domain = cvt2.Domain.from_shapely(polygon, constraints)
    vd = cvt2.bounded_voronoi(domain, cvt2.random_points(domain, 800, seed=1))
    items = domain.segment_items[vd.ridge_constraint[vd.ridge_constraint >= 0]]
    assert set(items) == {0, 1, 2}  # the polygon, constraints[0], constraints[1]
    on_boundary = vd.ridge_constraint[vd.ridge_boundary]
    assert np.all(domain.segment_items[on_boundary] == 0)
    # Triangle's arrays: the segment's row. A square with a square hole and a diagonal inside.
    vertices = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [1, 1], [2, 1], [2, 2], [1, 2], [2.5, 0.5], [3.5, 3]])
    segments = np.array([[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 4], [8, 9]])
    domain = cvt2.Domain(vertices, segments, holes=[[1.5, 1.5]])
    assert domain.area == pytest.approx(15)
    assert np.array_equal(domain.segments, segments) and np.array_equal(domain.segment_items, np.arange(9))
    vd = cvt2.bounded_voronoi(domain, cvt2.random_points(domain, 500, seed=2))
    assert set(vd.ridge_constraint[vd.ridge_constraint >= 0]) == set(range(9))
    hole = box(1, 1, 2, 2)
    assert all(c.intersection(hole).area < 1e-12 for c in vd.to_shapely())


def test_convex_domain_agrees_with_scipy_and_shapely():
    # scipy is not among the project's dependencies (python3-scipy): compared where it is.
    Voronoi = pytest.importorskip("scipy.spatial").Voronoi

    domain = cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])
    vd = cvt2.bounded_voronoi(domain, cvt2.random_points(domain, 3000, seed=6))
    far = np.array([[-10, -10], [11, -10], [11, 11], [-10, 11]])
    v = Voronoi(np.vstack([vd.points, far]))
    square = box(0, 0, 1, 1)
    theirs = np.array([Polygon(v.vertices[v.regions[v.point_region[k]]]).intersection(square).area
                       for k in range(len(vd.points))])
    assert np.allclose(vd.areas, theirs, rtol=1e-9, atol=0)


def test_cells_respect_constraints_and_visibility():
    polygon, constraints = holed_square()
    domain = cvt2.Domain.from_shapely(polygon, constraints)
    vd = cvt2.bounded_voronoi(domain, cvt2.random_points(domain, 600, seed=3))
    lines = unary_union(constraints)
    region = polygon.buffer(1e-9)
    for k, cell in enumerate(vd.to_shapely()):
        if vd.constrained[k]:
            continue  # a constraint that ends at its generator passes through it (a slit)
        # No constraint through its inside (cells end on constraints up to rounding).
        assert not cell.buffer(-1e-9).intersects(lines), k
        g = vd.points[k]
        for y in vd.vertices[vd.regions[k]]:  # every point of the cell sees its generator
            d = np.hypot(*(y - g))
            sight = LineString([g, y - 1e-9 * (y - g) / d])  # short of a hair (rounding)
            assert region.contains(sight) and not sight.intersects(lines), k
