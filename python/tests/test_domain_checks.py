# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# Issue 38: holes outside their polygon, constraints outside the domain, and points on the
# boundary computed in floating point, through every reader and the functions that take points.
import re
import subprocess

import numpy as np
import pytest
from shapely.geometry import LineString, MultiPolygon, Point, Polygon
from shapely.ops import unary_union

import cvt2

from conftest import write_geojson, write_wkt

SQUARE = Polygon([(0, 0), (1, 0), (1, 1), (0, 1)], [[(5, 5), (6, 5), (6, 6), (5, 6)]])


def test_a_hole_outside_its_shell_is_an_error_in_every_reader(tmp_path):
    wkt = tmp_path / "hole.wkt"
    wkt.write_text("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0), (5 5, 6 5, 6 6, 5 6, 5 5))\n")
    with pytest.raises(cvt2.DomainError, match=rf"{wkt}:1: polygon 0, ring 1: the hole through "
                                               r"\(5, 5\) lies outside the polygon's exterior"):
        cvt2.Domain.from_file(wkt)
    geojson = tmp_path / "hole.geojson"
    write_geojson(geojson, [SQUARE], [])
    with pytest.raises(cvt2.DomainError, match=rf"{geojson}: feature 1: polygon 0, ring 1: the "
                                               r"hole through \(5, 5\) lies outside"):
        cvt2.Domain.from_file(geojson)
    with pytest.raises(cvt2.DomainError, match=r"^<shapely>: polygon 0, ring 1: the hole through "
                                               r"\(5, 5\) lies outside"):
        cvt2.Domain.from_shapely(SQUARE)
    # In a MultiPolygon, a hole belongs to its own polygon: the second one's, here, lies in the
    # first one's hole.
    lake = Polygon([(0, 0), (10, 0), (10, 10), (0, 10)], [[(2, 2), (8, 2), (8, 8), (2, 8)]])
    other = Polygon([(20, 0), (30, 0), (30, 10), (20, 10)], [[(3, 3), (4, 3), (4, 4), (3, 4)]])
    with pytest.raises(cvt2.DomainError, match=r"<shapely>: polygon 1, ring 1: the hole through "
                                               r"\(3, 3\) lies outside"):
        cvt2.Domain.from_shapely(MultiPolygon([lake, other]))
    nested = Polygon(lake.exterior, [lake.interiors[0], [(3, 3), (4, 3), (4, 4), (3, 4)]])
    with pytest.raises(cvt2.DomainError, match=r"<shapely>: polygon 0, ring 2: the hole through "
                                               r"\(3, 3\) overlaps the hole of ring 1"):
        cvt2.Domain.from_shapely(nested)
    # A hole that is the exterior again leaves no area (it was read as the bare square).
    empty = Polygon(lake.exterior, [lake.exterior])
    with pytest.raises(cvt2.DomainError, match=r"<shapely>: polygon 0, ring 1: the hole through "
                                               r"\(0, 0\) covers the polygon's exterior"):
        cvt2.Domain.from_shapely(empty)
    assert empty.area == 0
    # GEOS agrees that these are invalid, and accepts the valid ones we accept.
    assert not SQUARE.is_valid and not MultiPolygon([lake, other]).is_valid and not nested.is_valid
    island = Polygon([(3, 3), (7, 3), (7, 7), (3, 7)])
    touching = Polygon(lake.exterior, [[(0, 0), (2, 1), (1, 2)]])
    for valid in (MultiPolygon([lake, island]), touching):
        assert valid.is_valid
        assert cvt2.Domain.from_shapely(valid).area == pytest.approx(valid.area, rel=1e-12)


@pytest.mark.parametrize("hole", [[(2, 0), (8, 0), (5, 3)], [(2, 0), (8, 0), (6.5, 1.5), (5, 3)],
                                  [(0, 0), (10, 0), (10, 3), (0, 3)]])
def test_a_hole_along_its_exterior_is_a_notch_in_every_reader(tmp_path, hole):
    # GEOS calls it invalid; read as its buffer(0) reads it. A hole whose faces all touched the
    # shared edge was kept (a triangle: 100), one with another face cut out (the same with a
    # vertex more: 91).
    polygon = Polygon([(0, 0), (10, 0), (10, 10), (0, 10)], [hole])
    assert not polygon.is_valid
    wkt, geojson = tmp_path / "notch.wkt", tmp_path / "notch.geojson"
    write_wkt(wkt, [polygon], [])
    write_geojson(geojson, [polygon], [])
    for domain in (cvt2.Domain.from_shapely(polygon, [LineString()]), cvt2.Domain.from_file(wkt),
                   cvt2.Domain.from_file(geojson)):
        assert domain.area == pytest.approx(polygon.buffer(0).area, rel=1e-12)


def _error_in_every_reader(tmp_path, polygon, lines, shapely_message, file_message):
    """The same DomainError from shapely (the lines as constraints[i]) and from a WKT and a
    GeoJSON file with the last line (on the file's line 2, its feature 2)."""
    with pytest.raises(cvt2.DomainError, match="^<shapely>: " + shapely_message):
        cvt2.Domain.from_shapely(polygon, lines)
    for write, where in ((write_wkt, ":2: "), (write_geojson, ": feature 2: ")):
        path = tmp_path / ("domain.wkt" if write is write_wkt else "domain.geojson")
        write(path, [polygon], lines[-1:])
        with pytest.raises(cvt2.DomainError, match=re.escape(f"{path}{where}") + file_message):
            cvt2.Domain.from_file(path)


def test_a_constraint_outside_the_domain_is_an_error_naming_it(tmp_path):
    square = Polygon([(10, 50), (11, 50), (11, 51), (10, 51)])
    swapped = LineString([(50.5, 10.2), (50.5, 10.8)])  # x and y swapped
    _error_in_every_reader(tmp_path, square, [LineString([(10.2, 50.5), (10.8, 50.5)]), swapped],
                           r"constraints\[1\]: the line from \(50.5, 10.2\) to \(50.5, 10.8\) "
                           r"lies outside the domain, which spans \(10, 50\) to \(11, 51\)",
                           r"the line from \(50.5, 10.2\)")


def test_a_line_of_no_length_is_an_error_naming_it(tmp_path):
    # All its points one: GEOS finds it invalid; it was taken as a point, a vertex of the cells.
    dot = LineString([(0.5, 0.25), (0.5, 0.25)])
    assert not dot.is_valid
    _error_in_every_reader(tmp_path, Polygon([(0, 0), (1, 0), (1, 1), (0, 1)]), [dot],
                           r"constraints\[0\]: the line at \(0.5, 0.25\) has no length",
                           r"the line at \(0.5, 0.25\) has no length")


def test_a_line_partly_outside_constrains_the_cells_with_its_part_inside():
    square = Polygon([(0, 0), (1, 0), (1, 0.5), (1, 1), (0, 1)])
    line = LineString([(0.5, 0.5), (1, 0.5), (2, 0.5)])  # out through the vertex (1, 0.5)
    domain = cvt2.Domain.from_shapely(square, [line])
    assert domain.area == pytest.approx(1, rel=1e-15)
    # The description keeps the whole line: its two segments, constraint 0.
    ends = {tuple(map(tuple, domain.vertices[s])) for s, item in
            zip(domain.segments, domain.segment_items) if item == 1}
    assert ends == {((0.5, 0.5), (1.0, 0.5)), ((1.0, 0.5), (2.0, 0.5))}
    d = cvt2.bounded_voronoi(domain, [[0.75, 0.45], [0.75, 0.55], [0.25, 0.5]])
    rows = [r for r in d.ridge_constraint if r >= 0 and domain.segment_items[r] == 1]
    on_line = {tuple(map(tuple, domain.vertices[domain.segments[r]])) for r in rows}
    assert on_line == {((0.5, 0.5), (1.0, 0.5))}  # the ridges lie on the part inside only
    assert sum(d.areas) == pytest.approx(1, rel=1e-12)
    below = d.to_shapely()[list(map(tuple, d.points)).index((0.75, 0.45))]
    assert below.bounds[3] <= 0.5 or below.intersection(Polygon([(0.5, 0.5), (1, 0.5), (1, 1), (0.5, 1)])).area == 0


def _slanted():
    polygon = Polygon([(0, 0), (1, 0.3), (0.7, 1), (0.2, 0.9), (0, 1)], [[(0.3, 0.3), (0.3, 0.5), (0.5, 0.4)]])
    return polygon, cvt2.Domain.from_shapely(polygon)


def _boundary_points(polygon, n, seed):
    """Midpoints of the boundary's edges and projections onto them, computed in double."""
    rng = np.random.default_rng(seed)
    rings = [np.asarray(r.coords) for r in [polygon.exterior, *polygon.interiors]]
    edges = [(r[i], r[i + 1]) for r in rings for i in range(len(r) - 1)]
    points = []
    for k in range(n):
        a, b = edges[rng.integers(len(edges))]
        if k % 2 == 0:
            points.append((a + b) / 2)
        else:
            d = b - a
            q = a + rng.random() * d + (rng.random() - 0.5) * np.array([-d[1], d[0]])
            points.append(a + np.dot(q - a, d) / np.dot(d, d) * d)
    return np.array(points)


@pytest.mark.parametrize("scale, offset", [(1.0, 0.0), (1000.0, 4.5e6)])
def test_points_on_the_boundary_computed_in_double_are_taken(scale, offset):
    polygon, _ = _slanted()
    polygon = Polygon(np.asarray(polygon.exterior.coords) * scale + offset,
                      [np.asarray(r.coords) * scale + offset for r in polygon.interiors])
    domain = cvt2.Domain.from_shapely(polygon)
    points = _boundary_points(polygon, 200, 1)
    # As before: many of them lie outside (by a rounding); all are taken now.
    with pytest.raises(cvt2.DomainError, match=r"lies outside the domain, at .* \(boundary tolerance 0\); so do"):
        cvt2.bounded_voronoi(domain, points, boundary_tolerance=0)
    d = cvt2.bounded_voronoi(domain, points)
    assert len(d.notes) == 1 and "moved onto the boundary at" in d.notes[0]
    moved = int(d.notes[0].split("; so were ")[1].split()[0]) + 1 if "so were" in d.notes[0] else 1
    assert 20 < moved < 180
    # Every point is a generator at most a rounding from where it was given, a constrained one if
    # it was not inside the domain (one inside by a rounding stays a free generator, as given).
    tree = {tuple(p): c for p, c in zip(d.points, d.constrained)}
    for p in points:
        nearest = min(tree, key=lambda q: np.hypot(*(np.asarray(q) - p)))
        assert np.hypot(*(np.asarray(nearest) - p)) <= 1e-14 * (scale + offset)
        assert tree[nearest] or polygon.contains(Point(p))
    # The cells are valid and tile the domain; every boundary ridge lies on an input segment.
    cells = d.to_shapely()
    assert all(c.is_valid and c.area > 0 for c in cells)
    assert unary_union(cells).symmetric_difference(polygon).area <= 1e-9 * polygon.area
    assert sum(d.areas) == pytest.approx(polygon.area, rel=1e-12)
    assert (d.ridge_constraint[d.ridge_boundary] >= 0).all()
    r = cvt2.optimize(domain, points, max_iterations=3)
    assert r.notes == d.notes
    assert r.constrained.sum() == d.constrained.sum()


def test_points_outside_beyond_the_tolerance_are_named_with_how_many():
    _, domain = _slanted()
    points = [[0.1, 0.1], [3, 3], [0.2, 0.2], [0.5, 0.15 - 1e-9], [4, 4], [0.25, 0.1], [0.5, 2]]
    for call in (cvt2.bounded_voronoi, cvt2.optimize):
        with pytest.raises(cvt2.DomainError, match=r"^points\[1\]: generator \(3, 3\) lies outside the "
                                                   r"domain, at 3.05 from it \(boundary tolerance "
                                                   r"8.88e-16\); so do 3 more: points\[3\] \(0.5, "
                                                   r"0.149999999\), points\[4\] \(4, 4\), "
                                                   r"points\[6\] \(0.5, 2\)$") as e:
            call(domain, points)
        assert e.value.index == 1
    # A tolerance in the coordinates' unit takes the near miss.
    d = cvt2.bounded_voronoi(domain, [[0.5, 0.15 - 1e-9]], boundary_tolerance=1e-8)
    assert "points[0]: generator (0.5, 0.149999999) lies 9.58e-10 outside" in d.notes[0]
    moved = [p for p, c in zip(d.points, d.constrained) if c and np.hypot(*(p - [0.5, 0.15])) < 1e-9]
    assert len(moved) == 1 and abs(0.3 * moved[0][0] - moved[0][1]) < 1e-15  # onto y = 0.3 x
    with pytest.raises(ValueError, match="boundary_tolerance must be >= 0 and finite, not -1"):
        cvt2.bounded_voronoi(domain, [[0.5, 0.5]], boundary_tolerance=-1)
    with pytest.raises(ValueError, match="boundary_tolerance must be >= 0 and finite, not nan"):
        cvt2.optimize(domain, [[0.5, 0.5]], boundary_tolerance=float("nan"))
    with pytest.raises(TypeError, match="boundary_tolerance must be None or a number, not str"):
        cvt2.bounded_voronoi(domain, [[0.5, 0.5]], boundary_tolerance="1e-9")
    assert cvt2.bounded_voronoi(domain, [[0.5, 0.5]]).notes == []


def test_natural_neighbours_take_nodes_a_rounding_outside():
    polygon, domain = _slanted()
    nodes = _boundary_points(polygon, 40, 2)
    with pytest.raises(cvt2.DomainError, match=r"^nodes\[\d+\]: generator .* lies outside the domain"):
        cvt2.natural_neighbours(domain, nodes, [[0.4, 0.5]], boundary_tolerance=0)
    m = cvt2.natural_neighbours(domain, nodes, [[0.4, 0.5], [0.6, 0.7]])
    assert m.inside.all()
    assert np.allclose(np.add.reduceat(m.data, m.indptr[:-1]), 1)  # rows sum to 1


def test_the_program_takes_points_a_rounding_outside_and_says_so(program, tmp_path):
    domain = tmp_path / "slanted.wkt"
    polygon, _ = _slanted()
    write_wkt(domain, [polygon], [])
    points = tmp_path / "points.txt"
    np.savetxt(points, _boundary_points(polygon, 60, 1), fmt="%.17g")
    run = subprocess.run([program, str(domain), "--points-in", str(points), "-n", "0",
                          "--iterations", "3", "--quiet"], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert f"cvt2: note: {points}:" in run.stderr and "moved onto the boundary at" in run.stderr
    run = subprocess.run([program, str(domain), "--points-in", str(points), "-n", "0",
                          "--boundary-tolerance", "0"], capture_output=True, text=True)
    assert run.returncode == 1 and "(boundary tolerance 0); so do" in run.stderr


def test_the_program_says_when_refine_asks_for_no_finer_cells(program, data, tmp_path):
    # --refine's SIZE at or above the background size (that of -n's uniform cells) refines
    # nothing: a note names it. A size below it says nothing.
    domain = data / "square_inner_constraints.wkt"
    for size, said in ((100, True), (0.05, False)):
        run = subprocess.run([program, str(domain), "-n", "200", "--iterations", "2", "--refine",
                              "5", "5", str(size), "1", "--points-out",
                              str(tmp_path / "points.txt")], capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        assert ("cvt2: note: --refine 5 5 " in run.stderr
                and "not below the background cells'" in run.stderr) == said, run.stderr


def test_a_segment_on_an_earlier_one_is_noted(program, data, tmp_path):
    # A constrained edge is named by the first input segment it lies on: a segment along an
    # earlier one (row 5 within row 4; row 6 partly along it) gives the shared part's cells to
    # the earlier row. It was silent: row 5 was missing from the list of cells on constraints.
    poly = tmp_path / "on.poly"
    poly.write_text("8 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n5 2 5\n6 6 5\n7 8 5\n8 9 5\n"
                    "7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 7\n6 6 7\n7 6 8\n0\n")
    within = f"{poly}: item 5: the segment from (6, 5) to (8, 5) lies on item 4's: its pieces are named 4"
    partly = (f"{poly}: item 6: the segment from (6, 5) to (9, 5) lies partly on item 4's: the "
              "pieces along it are named 4")
    domain = cvt2.Domain.from_file(poly)
    assert domain.notes == [within, partly]
    named = set(cvt2.bounded_voronoi(domain, [[5, 3], [5, 7], [3, 3], [7.5, 7]]).ridge_constraint)
    assert named == {-1, 0, 1, 2, 3, 4, 6}
    run = subprocess.run([program, str(poly), "-n", "10", "--iterations", "2", "--quiet",
                          "--cells-on-constraints", str(tmp_path / "on.csv")],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert f"cvt2: note: {within} (and 1 more lie on others)" in run.stderr
    # The bundled domains have none, counties sharing their borders included.
    for name in ("square_inner_constraints.poly", "us_kentucky_counties.poly", "four_clusters.poly"):
        assert cvt2.Domain.from_file(data / name).notes == []
