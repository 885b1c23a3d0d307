# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# The rows given keep their identity: scipy's regions[point_region[i]] is row i's cell whatever
# the diagram's order, duplicates and points on the domain's vertices share a cell and are
# listed, the domain's own points come after the rows given; optimize() says where each row went.
import numpy as np
import pytest
from shapely.geometry import LineString, Point, Polygon

import cvt2


def own_points(domain):
    """The domain's own points in point_region's numbering: its vertices, then a WKT or
    GeoJSON domain's generators (a .poly's are among its vertices)."""
    if domain.format in ("wkt", "geojson"):
        return np.vstack([domain.vertices, domain.generators])
    return domain.vertices


def holed_domain():
    polygon = Polygon([(0, 0), (4, 0), (4, 3), (0, 3)], holes=[[(1, 1), (2, 1), (2, 2), (1, 2)]])
    wall = LineString([(2.5, 0), (3, 1.5), (3.5, 2.5)])
    return cvt2.Domain.from_shapely(polygon, [wall])


def hostile_rows(domain, n, seed):
    """Random rows, shuffled, with duplicates of some, copies of some of the domain's own points
    (vertices on the boundary, on a constraint) and a point on a constraint."""
    rng = np.random.default_rng(seed)
    points = cvt2.random_points(domain, n, seed=seed)
    own = own_points(domain)
    extra = [points[rng.integers(n, size=n // 10)], own[rng.integers(len(own), size=5)]]
    rows = np.vstack([points] + extra)
    return rows[rng.permutation(len(rows))]


CASES = [
    ("square", lambda data: cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])),
    ("shapely", lambda data: holed_domain()),
    ("poly", lambda data: cvt2.Domain.from_file(data / "four_clusters.poly")),
    ("wkt", lambda data: cvt2.Domain.from_file(data / "four_clusters.wkt")),
]


@pytest.mark.parametrize("name, make", CASES, ids=[c[0] for c in CASES])
def test_point_region_names_each_rows_cell(data, name, make):
    domain = make(data)
    rows = hostile_rows(domain, 400, seed=5)
    own = own_points(domain)
    vd = cvt2.bounded_voronoi(domain, rows)
    n, regions = len(rows), len(vd.points)
    assert vd.point_region.shape == (n + len(own),)
    everything = np.vstack([rows, own])
    named = vd.point_region >= 0
    # Every row given has a cell, whose generator is the row itself, exactly; the domain's own
    # points likewise, but for one with no cell (none in these domains).
    assert named.all()
    assert np.array_equal(vd.points[vd.point_region], everything)
    assert set(vd.point_region) == set(range(regions))
    # scipy's habit: the region of row i, as a polygon, holds row i.
    for i in range(0, n, 3):
        cell = Polygon(vd.vertices[vd.regions[vd.point_region[i]]])
        assert cell.buffer(1e-9).contains(Point(rows[i])), i
    # Rows at one place: one region, and listed once each, with the first row there.
    first = {}
    expected = []
    for i, p in enumerate(map(tuple, everything)):
        if p in first:
            expected.append((i, first[p]))
        else:
            first[p] = i
    assert len(expected) > 40
    assert vd.duplicates.shape == (len(expected), 2)
    assert sorted(map(tuple, vd.duplicates)) == expected
    assert np.array_equal(vd.point_region[vd.duplicates[:, 0]], vd.point_region[vd.duplicates[:, 1]])
    # input_index goes back: the first row given in each region, -1 for a region of the domain's
    # own points alone.
    assert vd.input_index.shape == (regions,)
    for k, i in enumerate(vd.input_index):
        if i >= 0:
            assert vd.point_region[i] == k and first[tuple(rows[i])] == i
        else:
            assert tuple(vd.points[k]) not in set(map(tuple, rows))
            assert tuple(vd.points[k]) in set(map(tuple, own))


def test_the_diagrams_order_is_not_the_rows_order():
    # The property above is not empty: the regions are in another order than the rows.
    domain = cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])
    rows = cvt2.random_points(domain, 200, seed=2)
    vd = cvt2.bounded_voronoi(domain, rows)
    assert not np.array_equal(vd.point_region[:200], np.arange(200))
    assert not np.array_equal(vd.points[:200], rows)


@pytest.mark.parametrize("algorithm", ["lloyd", "lbfgs"])
def test_optimize_says_which_row_each_generator_started_from(algorithm):
    domain = holed_domain()
    rows = hostile_rows(domain, 300, seed=7)
    own = own_points(domain)
    first = {}
    for i, p in enumerate(map(tuple, rows)):
        first.setdefault(p, i)
    # No move: each generator is where its row is.
    still = cvt2.optimize(domain, rows, algorithm=algorithm, max_iterations=0)
    index = still.input_index
    assert index.shape == (len(still.points),)
    given = index >= 0
    assert np.array_equal(still.points[given], rows[index[given]])
    assert sorted(index[given]) == sorted(first.values())  # each row's first once, no other
    assert set(map(tuple, still.points[~given])) <= set(map(tuple, own))
    # After moves: the same rows; the constrained ones (on the boundary, on the wall) where
    # they were, and after one Lloyd iteration, each free one at the centroid of its row's
    # first cell, or on the way there (a move stops short of leaving its star).
    moved = cvt2.optimize(domain, rows, algorithm=algorithm, max_iterations=1, move_ratio=0)
    assert moved.iterations == 1
    index = moved.input_index
    assert np.array_equal(np.sort(index), np.sort(still.input_index))
    given = index >= 0
    starts = rows[index[given]]
    fixed = moved.constrained[given]
    assert fixed.any() and np.array_equal(moved.points[given][fixed], starts[fixed])
    assert not np.array_equal(moved.points[given][~fixed], starts[~fixed])
    if algorithm == "lloyd":
        before = cvt2.bounded_voronoi(domain, rows)
        targets = before.centroids[before.point_region[index[given]]]
        scale = np.ptp(rows, axis=0).max()
        full = 0
        for p, s, c in zip(moved.points[given][~fixed], starts[~fixed], targets[~fixed]):
            t = np.dot(p - s, c - s) / np.dot(c - s, c - s)
            assert 0 < t <= 1 + 1e-9 and np.hypot(*(s + t * (c - s) - p)) <= 1e-9 * scale
            full += np.hypot(*(p - c)) <= 1e-9 * scale
        assert full > 0.9 * (~fixed).sum()
    # The optimized diagram: its rows are the result's points.
    vd = moved.bounded_voronoi()
    assert np.array_equal(vd.point_region, np.arange(len(moved.points)))
    assert np.array_equal(vd.input_index, moved.input_index)
    assert vd.duplicates.shape == (0, 2)


def test_points_a_rounding_off_a_slanted_edge_keep_their_own_cells():
    # Points along the triangle's slanted edge, computed in floating point: about half lie
    # outside it by a rounding and go onto it. Each row must name its own cell (found by the
    # nearest vertex around where the row was, rows 3 and 8 named rows 0 and 6's).
    tri = cvt2.Domain([[0, 0], [1, 0], [0.3, 0.7]], [[0, 1], [1, 2], [2, 0]])
    rows = np.array([1, 0]) + (np.arange(1, 40) / 40)[:, None] * np.array([-0.7, 0.7])
    d = cvt2.bounded_voronoi(tri, rows)
    assert len(d.duplicates) == 0
    assert sorted(d.point_region[:len(rows)]) == sorted(set(d.point_region[:len(rows)]))
    assert np.max(np.hypot(*(d.points[d.point_region[:len(rows)]] - rows).T)) < 1e-15
    r = cvt2.optimize(tri, rows, max_iterations=1)
    assert sorted(r.input_index[r.input_index >= 0]) == list(range(len(rows)))
    # "a generator that is no node" (an internal error) when rows went to other rows' vertices
    m = cvt2.natural_neighbours(tri, rows, [[0.3, 0.2], [0.5, 0.45]])
    assert np.allclose(m.toarray().sum(axis=1), 1)


def test_editor_snapshots_follow_the_points_relax_moved():
    square = cvt2.Domain([[0, 0], [10, 0], [10, 10], [0, 10]], [[0, 1], [1, 2], [2, 3], [3, 0]])
    rows = np.random.default_rng(4).uniform(0, 10, (500, 2))
    editor = cvt2.ConstraintEditor(square, rows)
    editor.insert_constraint([[0, 4.1], [3, 4.3]])
    moved = editor.relax(2, 5)
    assert len(moved["moved_from"]) > 10
    d = editor.bounded_voronoi()
    assert len(d.duplicates) == 0  # 40 when the snapshot looked for the rows where they started
    cells = d.point_region[:len(rows)]
    assert len(set(cells)) == len(rows)
    where = rows.copy()
    for a, b in zip(moved["moved_from"], moved["moved_to"]):
        where[(rows == a).all(axis=1)] = b
    assert np.array_equal(d.points[cells], where)
