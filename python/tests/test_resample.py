# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# Constraints resampled to a cell size (Domain.resample, cvt2 --boundary resample): the count
# asked for delivered, specks gone, the outputs valid, the same bits as the program.
import json
import re
import subprocess

import numpy as np
import pytest
from shapely.geometry import shape
from shapely.ops import unary_union

import cvt2
from conftest import run_program

REAL = ["france_mainland.poly", "world_land_110m.wkt", "us_kentucky_counties.geojson",
        "us_massachusetts_counties.wkt", "earcut_dude.poly"]


@pytest.mark.parametrize("name", REAL)
def test_program_delivers_the_cells_asked_for_valid_and_tiling(program, data, tmp_path, name):
    domain = cvt2.Domain.from_file(data / name)
    cells = 1500
    summary, points, files = run_program(program, data / name, tmp_path, "--boundary", "resample",
                                         "--cells", cells, outputs=("points", "geojson"))
    features = json.loads(files["geojson"].read_text())["features"]
    assert len(features) == cells == len(points) == int(summary["generators"])
    polygons = [shape(f["geometry"]) for f in features]
    assert all(p.is_valid and p.area > 0 for p in polygons)
    # The cells tile the resampled domain (no overlap: the union's area is the sum's), whose
    # area is within the deviation of the input's.
    resampled = domain.resample(cells=cells)
    assert unary_union(polygons).area == pytest.approx(resampled.area, rel=1e-9)
    assert sum(p.area for p in polygons) == pytest.approx(resampled.area, rel=1e-9)
    assert resampled.area == pytest.approx(domain.area, rel=0.02)


def test_resampling_removes_the_specks_of_a_fine_boundary(program, data, tmp_path):
    # France's 533 boundary vertices at 1 000 cells: kept, a tenth of the cells are specks.
    speck = {}
    for mode in ("keep", "resample"):
        _, _, files = run_program(program, data / "france_mainland.poly", tmp_path, "--boundary",
                                  mode, "--cells", 1000, outputs=("geojson",))
        areas = np.array([f["properties"]["area"]
                          for f in json.loads(files["geojson"].read_text())["features"]])
        speck[mode] = np.mean(areas < 0.1 * np.median(areas))
    assert speck["keep"] > 0.05
    assert speck["resample"] < speck["keep"] / 4


@pytest.mark.parametrize("mode", ["resample", "slide"])
def test_module_matches_the_program_bit_for_bit(program, data, tmp_path, mode):
    name = "us_massachusetts_counties.wkt"
    _, expected, files = run_program(program, data / name, tmp_path, "--boundary", mode,
                                     "--cells", 800, "--seed", 5, outputs=("points", "geojson"))
    d = cvt2.Domain.from_file(data / name).resample(cells=800)
    points = cvt2.random_points(d, cells=800, seed=5)
    assert len(points) + d.own_cells == 800
    r = cvt2.optimize(d, points, boundary=mode)
    assert np.array_equal(r.points, expected[:, :2])
    if mode == "resample":
        return
    kept = cvt2.optimize(d, points)
    assert not np.array_equal(r.points, kept.points)
    # The result's domain is the slid one: its ridges along the lines name its segments.
    metadata = dict(r.domain._impl.metadata)
    assert metadata["boundary"] == "slide"
    # with the slid lines' largest deviation, as the program's files say (above the resampling's)
    written = json.loads(files["geojson"].read_text())["metadata"]
    assert metadata["max_deviation"] == written["max_deviation"]
    assert float(metadata["max_deviation"]) > float(dict(d._impl.metadata)["max_deviation"])
    b = r.bounded_voronoi()
    assert r.domain.area == pytest.approx(b.areas.sum(), rel=1e-9)
    assert (np.asarray(b.ridge_constraint) >= 0).sum() > 0
    assert set(map(tuple, r.domain.vertices)) <= set(map(tuple, r.points))
    with pytest.raises(ValueError, match="made by Domain.resample"):
        cvt2.optimize(cvt2.Domain.from_file(data / name), points, boundary="slide")
    with pytest.raises(ValueError, match="boundary must be"):
        cvt2.optimize(d, points, boundary="slid")


def test_cells_count_what_the_program_counts(program, data, tmp_path):
    """optimize(cells=) draws as cvt2 --cells: after the points, the fixed points and the
    conforming lines' generators, which count among the cells; the same bits."""
    name = data / "square_inner_constraints.wkt"
    d = cvt2.Domain.from_file(name)
    fixed = np.array([[1.0, 1.0], [9.0, 2.0], [5.0, 8.0], [2.5, 4.0]])
    np.savetxt(tmp_path / "fixed.txt", fixed)
    given = cvt2.random_points(d, 20, seed=3)
    np.savetxt(tmp_path / "given.txt", given)
    cases = [
        (dict(fixed_points=fixed), ["--fixed-points", tmp_path / "fixed.txt"]),
        (dict(constraints="conforming"), ["--constraints", "conforming"]),
        (dict(points=given), ["--points-in", tmp_path / "given.txt"]),
        (dict(points=given, density="lipschitz", redistribute=True),
         ["--points-in", tmp_path / "given.txt", "--density", "lipschitz", "--redistribute",
          "always"]),
        (dict(size=0.5), ["--size", 0.5]),
    ]
    for kwargs, options in cases:
        points = kwargs.pop("points", None)
        count = {} if "size" in kwargs else dict(cells=300)
        r = cvt2.optimize(d, points, seed=4, max_iterations=3, **count, **kwargs)
        counted = [] if count == {} else ["--cells", 300]
        _, expected, _ = run_program(program, name, tmp_path, *counted, "--seed", 4,
                                     "--iterations", 3, *options)
        assert len(r.points) == len(expected), options
        assert count == {} or len(r.points) == 300, options
        assert np.array_equal(r.points, expected[:, :2]), options
    # The points given keep their rows; those drawn are -1.
    r = cvt2.optimize(d, given, cells=300, max_iterations=0)
    assert sorted(r.input_index[r.input_index >= 0]) == list(range(20))
    # What cells= and size= take.
    with pytest.raises(TypeError, match="size must be a number, not str"):
        cvt2.optimize(d, None, size="1")
    with pytest.raises(TypeError, match="size must be a number, not bool"):
        cvt2.optimize(d, None, size=True)
    with pytest.raises(TypeError, match="cells must be an integer"):
        cvt2.optimize(d, None, cells=1.5)
    with pytest.raises(ValueError, match=r"size=1e-300 \(inf cells\) asks for too many cells"):
        cvt2.optimize(d, None, size=1e-300)
    with pytest.raises(ValueError, match=r"cells=1000000000000000000 asks for too many cells"):
        cvt2.optimize(d, None, cells=10**18, constraints="conforming")
    # more than memory holds: refused before any is drawn, as cvt2 --cells refuses
    with pytest.raises(ValueError, match=r"^cells=100000000000: 9999999\d+ points need about "
                                         r"\d+ GB; this machine has \d+ GB$"):
        cvt2.optimize(d, None, cells=10**11)
    with pytest.raises(ValueError, match=r"size=1e\+300 \(0 cells\) asks for fewer cells than"):
        cvt2.optimize(d, None, size=1e300)
    with pytest.raises(ValueError, match="boundary='resample' resamples the domain"):
        cvt2.optimize(d, given, boundary="resample")


def test_cells_deal_the_points_to_the_regions_by_area(data):
    # Kentucky's counties are regions no generator leaves: with cells=, each gets the points its
    # area asks for, whatever the seed; with n=, independent draws leave a county of k cells
    # about sqrt(k) off, which the optimization cannot mend.
    from shapely.geometry import LineString
    from shapely.ops import polygonize
    from shapely.vectorized import contains
    d = cvt2.Domain.from_file(data / "us_kentucky_counties.geojson").resample(cells=2000)
    n = 2000 - d.own_cells
    v = np.asarray(d.vertices)
    regions = list(polygonize([LineString(v[list(s)]) for s in np.asarray(d.segments)]))
    assert sum(r.area for r in regions) == pytest.approx(d.area, rel=1e-9)  # 121: an exclave

    def counts(points):
        inside = np.array([contains(r, points[:, 0], points[:, 1]) for r in regions])
        assert (inside.sum(axis=0) == 1).all()  # each point in one county
        return inside.sum(axis=1)

    dealt = [counts(cvt2.random_points(d, cells=2000, seed=s)) for s in (1, 2)]
    drawn = [counts(cvt2.random_points(d, n, seed=s)) for s in (1, 2)]
    assert dealt[0].sum() == n
    assert np.array_equal(dealt[0], dealt[1])
    assert not np.array_equal(drawn[0], drawn[1])
    # A county's count: its area less a share for each vertex on its boundary, to rounding.
    vertices = [len(r.exterior.coords) - 1 + sum(len(i.coords) - 1 for i in r.interiors)
                for r in regions]
    x = np.c_[[r.area for r in regions], vertices]

    def residual(c):
        coefficients = np.linalg.lstsq(x, c, rcond=None)[0]
        return c - x @ coefficients, coefficients

    r, (per_area, per_vertex) = residual(dealt[0])
    assert np.abs(r).max() < 1 and per_area > 0 and per_vertex < 0
    for c in drawn:
        assert residual(c)[0].std() > 2  # about sqrt(k) off


@pytest.mark.parametrize("mode", ["resample", "slide"])
@pytest.mark.parametrize("ask", [("cells", 800), ("size", 0.05)])
def test_optimize_resamples_and_draws_as_the_program(program, data, tmp_path, mode, ask):
    # optimize(d, None, boundary=..., cells= or size=): the domain resampled, the points drawn,
    # the program's bits; the result's domain is the resampled (or slid) one.
    name = "us_massachusetts_counties.wkt"
    option, value = ask
    _, expected, _ = run_program(program, data / name, tmp_path, "--boundary", mode,
                                 f"--{option}", value, "--seed", 5)
    r = cvt2.optimize(cvt2.Domain.from_file(data / name), None, boundary=mode, seed=5,
                      **{option: value})
    assert np.array_equal(r.points, expected[:, :2])
    assert r.domain.resampling is not None or mode == "slide"
    with pytest.raises(TypeError, match="one of cells and size"):
        cvt2.optimize(r.domain, None, cells=800, size=0.05)
    with pytest.raises(TypeError, match="not None"):  # no points, and none asked for
        cvt2.optimize(r.domain, None)


def test_resample_report_and_arguments(data):
    d = cvt2.Domain.from_file(data / "france_mainland.poly")
    h = 0.2
    r = d.resample(size=h)
    rep = r.resampling
    assert rep["size"] == h
    assert rep["output_vertices"] < rep["input_vertices"] == 533
    assert 0 < rep["max_deviation"] <= h / 4
    assert rep["area_after"] == pytest.approx(r.area)
    assert len(r.segments) == rep["output_vertices"]  # rings: as many segments as vertices
    assert d.resampling is None
    # A tighter bound keeps more vertices; fixed points stay.
    tight = d.resample(size=h, deviation_bound=h / 40)
    assert tight.resampling["output_vertices"] > rep["output_vertices"]
    pinned = d.vertices[100:110]
    fixed = d.resample(size=h, fixed_points=pinned)
    assert all((fixed.vertices == p).all(axis=1).any() for p in pinned)
    # The points are spacing_ratio sizes apart, two by default: a wider spacing, fewer points.
    one = d.resample(size=h, spacing_ratio=1)
    assert rep["spacing_ratio"] == 2 and one.resampling["spacing_ratio"] == 1
    assert one.resampling["output_vertices"] > 1.3 * rep["output_vertices"]
    with pytest.raises(ValueError, match="spacing ratio must be a positive number"):
        d.resample(size=h, spacing_ratio=0)
    # The count and the size are inverses, at any spacing ratio.
    assert d.cells_for_size(d.resample(cells=3000).resampling["size"]) == pytest.approx(3000)
    big = d.resample(cells=3000, spacing_ratio=1).resampling["size"]
    assert d.cells_for_size(big, spacing_ratio=1) == pytest.approx(3000)
    with pytest.raises(TypeError, match="one of cells and size"):
        d.resample()
    with pytest.raises(TypeError, match="one of cells and size"):
        d.resample(cells=10, size=1.0)
    with pytest.raises(ValueError, match="size must be a positive number"):
        d.resample(size=-1.0)
    with pytest.raises(ValueError, match="fewer than the"):
        cvt2.random_points(d, cells=10)
    with pytest.raises(TypeError, match="one of n and cells"):
        cvt2.random_points(d, 5, cells=1000)


def test_program_size_and_errors(program, data, tmp_path):
    name = data / "france_mainland.poly"
    h = 0.3
    summary, _, _ = run_program(program, name, tmp_path, "--boundary", "resample", "--size", h)
    expected = cvt2.Domain.from_file(name).resample(size=h).cells_for_size(h)
    assert int(summary["generators"]) == round(expected)

    def fails(*options):
        p = subprocess.run([program, str(name), "--quiet", *map(str, options)],
                           capture_output=True, text=True)
        assert p.returncode != 0
        return p.stderr

    assert "expects 'keep', 'resample' or 'slide'" in fails("--boundary", "glide")
    assert "--size asks for inf cells: too many" in fails("--size", "1e-300")
    # checked before the conforming lines' sites are placed (at the spacing it asks for)
    p = subprocess.run([program, str(data / "square_inner_constraints.wkt"), "--quiet",
                        "--constraints", "conforming", "--cells", str(10**18)],
                       capture_output=True, text=True, timeout=60)
    assert p.returncode != 0 and "--cells asks for 1e+18 cells: too many" in p.stderr
    assert re.search(r"--cells: 9999999\d+ points need about \d+ GB; this machine has",
                     fails("--cells", 10**11))  # the option named, not --points
    assert "give one of -n, --cells and --size" in fails("--cells", 100, "-n", 5)
    assert "--deviation-bound needs --boundary resample" in fails("--deviation-bound", 1)
    assert "--boundary-spacing needs --boundary resample" in fails("--boundary-spacing", 1)
    assert "--boundary-spacing must be positive" in fails("--boundary", "resample",
                                                            "--boundary-spacing", 0)
    assert "fewer than the 533 vertices" in fails("--cells", 100)
    # keep says when the domain's vertices add many cells, and names the option.
    p = subprocess.run([program, str(name), "-n", "1000", "--iterations", "1"],
                       capture_output=True, text=True)
    assert "--boundary resample" in p.stderr


def test_outputs_say_which_boundary_made_them_and_match_the_program(program, data, tmp_path):
    import meshio
    name = data / "france_mainland.poly"
    _, _, files = run_program(program, name, tmp_path, "--boundary", "resample", "--cells", 700,
                              "--iterations", 5, outputs=("points", "geojson", "vtu", "disv"))
    metadata = json.loads(files["geojson"].read_text())["metadata"]
    assert metadata["boundary"] == "resample" and metadata["domain"] == str(name)
    assert float(metadata["max_deviation"]) <= float(metadata["deviation_bound"])
    assert "# boundary: resample\n" in files["disv"].read_text()
    assert "<!-- boundary: resample -->" in files["vtu"].read_text()
    assert sum(len(block.data) for block in meshio.read(files["vtu"]).cells) == 700
    # The module writes the same bytes for the same domain and points.
    d = cvt2.Domain.from_file(name).resample(cells=700)
    r = cvt2.optimize(d, cvt2.random_points(d, cells=700), max_iterations=5).bounded_voronoi()
    for kind, write in (("geojson", r.to_geojson), ("vtu", r.to_vtu), ("disv", r.to_disv)):
        write(tmp_path / f"ours.{kind}")
        assert (tmp_path / f"ours.{kind}").read_bytes() == files[kind].read_bytes(), kind
    # keep says so too.
    _, _, files = run_program(program, name, tmp_path, "-n", 100, "--iterations", 1,
                              outputs=("geojson",))
    assert json.loads(files["geojson"].read_text())["metadata"]["boundary"] == "keep"


def test_program_writes_the_resampled_domain_and_the_layer(program, data, tmp_path):
    name = data / "france_mainland.poly"
    poly, disv = tmp_path / "resampled.poly", tmp_path / "grid.disv"
    subprocess.run([program, str(name), "--quiet", "--boundary", "resample", "--cells", "600",
                    "--iterations", "2", "--domain-out", str(poly), "--disv", str(disv),
                    "--top", "12.5", "--bottom", "-3"], check=True, capture_output=True)
    back = cvt2.Domain.from_file(poly)
    ours = cvt2.Domain.from_file(name).resample(cells=600)
    assert np.array_equal(back.vertices, ours.vertices)
    assert np.array_equal(back.segments, ours.segments)
    assert back.area == ours.area
    text = disv.read_text()
    assert "TOP\n    CONSTANT 12.5\n" in text and "BOTM LAYERED\n    CONSTANT -3\n" in text
    p = subprocess.run([program, str(name), "--top", "1", "--bottom", "1"], capture_output=True,
                       text=True)
    assert p.returncode != 0 and "--bottom must be below --top" in p.stderr


def test_minimum_ring_area_drops_small_islands(program, data, tmp_path):
    world = cvt2.Domain.from_file(data / "world_land_110m.wkt")
    cell = 3**0.5 / 2 * world.resample(cells=2000).resampling["size"] ** 2
    kept, dropped = world.resample(cells=2000), world.resample(cells=2000, minimum_ring_area=cell)
    assert kept.resampling["rings_dropped"] == 0 < dropped.resampling["rings_dropped"]
    assert dropped.resampling["output_vertices"] < kept.resampling["output_vertices"]
    # What goes is small: at most the dropped rings' count times a cell.
    lost = kept.area - dropped.area
    assert 0 < lost < dropped.resampling["rings_dropped"] * cell
    p = subprocess.run([program, str(data / "world_land_110m.wkt"), "--minimum-ring-area", "1"],
                       capture_output=True, text=True)
    assert p.returncode != 0 and "--minimum-ring-area needs --boundary resample" in p.stderr


def _on_lines(points, domain):
    """The distance from each point to the nearest segment of `domain`'s description."""
    v, seg = domain.vertices, domain.segments
    a, b = v[seg[:, 0]], v[seg[:, 1]]
    d = b - a
    out = []
    for p in points:
        t = np.clip(np.einsum("ij,ij->i", p - a, d) / np.einsum("ij,ij->i", d, d), 0, 1)
        out.append(np.min(np.hypot(*(a + t[:, None] * d - p).T)))
    return np.array(out)


@pytest.mark.parametrize("name", ["france_mainland.poly", "us_massachusetts_counties.wkt"])
def test_program_slides_the_boundary_on_the_input_valid_and_tiling(program, data, tmp_path, name):
    domain = cvt2.Domain.from_file(data / name)
    cells = 1500
    summary, points, files = run_program(program, data / name, tmp_path, "--boundary", "slide",
                                         "--cells", cells, outputs=("points", "geojson", "disv"))
    assert summary["stop"] == "converged"
    features = json.loads(files["geojson"].read_text())["features"]
    assert len(features) == cells == len(points)
    polygons = [shape(f["geometry"]) for f in features]
    assert all(p.is_valid and p.area > 0 for p in polygons)
    union = unary_union(polygons)
    assert union.area == pytest.approx(sum(p.area for p in polygons), rel=1e-9)  # no overlap
    # The boundary slid (not the resampled one any more), along the input, within the bound.
    resampled = domain.resample(cells=cells)
    constrained = points[points[:, 2] == 1, :2]
    scale = np.ptp(domain.vertices, axis=0).max()
    assert np.max(_on_lines(constrained, domain)) <= 1e-12 * scale
    moved = [tuple(p) not in set(map(tuple, resampled.vertices)) for p in constrained]
    assert sum(moved) >= 10
    assert union.area == pytest.approx(domain.area, rel=0.02)
    metadata = json.loads(files["geojson"].read_text())["metadata"]
    assert metadata["boundary"] == "slide"
    assert "# boundary: slide\n" in files["disv"].read_text()
    # --domain-out writes the lines where the vertices slid to.
    poly = tmp_path / "slid.poly"
    subprocess.run([program, str(data / name), "--quiet", "--boundary", "slide", "--cells",
                    str(cells), "--domain-out", str(poly)], check=True, capture_output=True)
    back = cvt2.Domain.from_file(poly)
    on_lines = np.unique(back.segments)
    assert set(map(tuple, back.vertices[on_lines])) == set(map(tuple, constrained))
    assert back.area == pytest.approx(union.area, rel=1e-9)
    # The metadata's max_deviation is the slid lines' (no longer the resampling's): no input
    # vertex lies farther than it from the lines where the vertices slid, and it keeps the bound.
    deviation = float(metadata["max_deviation"])
    on_input = domain.vertices[np.unique(domain.segments)]
    assert np.max(_on_lines(on_input, back)) <= deviation * (1 + 1e-9)
    assert deviation <= float(metadata["deviation_bound"]) * (1 + 1e-9)


def item_lines(domain):
    """The input lines of each item of `domain`, as shapely geometry."""
    from shapely.geometry import MultiLineString

    ends = domain.vertices[domain.segments]
    return {item: MultiLineString(list(ends[domain.segment_items == item]))
            for item in np.unique(domain.segment_items)}


@pytest.mark.parametrize("name", ["us_kentucky_counties.geojson", "us_massachusetts_counties.wkt",
                                  "france_mainland.poly"])
def test_resampled_lines_keep_the_items_of_the_input(data, name):
    # Each chord of a resampled (and a slid) domain is named by the input line it replaces (a
    # feature, a WKT line, a .poly row: the one of its stretch nearest to its middle), and
    # lies on it: within the deviation bound of it (twice after sliding); a feature or WKT line
    # has the chord's ends and middle (a .poly row may hold neither end).
    from shapely.geometry import Point

    domain = cvt2.Domain.from_file(data / name)
    lines = item_lines(domain)
    resampled = domain.resample(cells=1500)
    slid = cvt2.optimize(resampled, cvt2.random_points(resampled, cells=1500),
                         boundary="slide").domain
    bound = resampled.resampling["deviation_bound"]
    for d, tolerance in ((resampled, bound), (slid, 2 * bound)):
        items = d.segment_items
        assert (items >= 0).all() and set(items) <= set(lines)
        ends = d.vertices[d.segments]
        for (a, b), item in zip(ends, items):
            middle = lines[item].distance(Point((a + b) / 2))
            if name.endswith(".poly"):  # a row, not a line: a slide moves the chord off it
                assert d is slid or middle <= bound * (1 + 1e-9)
                continue
            assert lines[item].distance(Point(a)) < 1e-9 * (1 + np.abs(a).max())
            assert middle <= tolerance * (1 + 1e-9)
    # With no resampling a segment is its own item.
    assert (resampled.segment_items != np.arange(len(resampled.segments))).any()


def test_program_names_resampled_lines_by_the_input_items(program, data, tmp_path):
    # --cells-on-constraints names the chords of --boundary resample and slide by the GeoJSON's
    # features, as keep does; and the features' kinds hold under resampling (the fault a
    # barrier, the river conforming).
    def constraints(file, *options):
        csv = tmp_path / "on.csv"
        run_program(program, data / file, tmp_path, "--cells", 2500, *options,
                    "--cells-on-constraints", csv)
        rows = np.loadtxt(csv, delimiter=",", skiprows=1, ndmin=2)
        return set(rows[:, 0].astype(int))

    keep = constraints("us_kentucky_counties.geojson")
    assert len(keep) > 100 and min(keep) >= 1
    for mode in ("resample", "slide"):
        assert constraints("us_kentucky_counties.geojson", "--boundary", mode) == keep
    assert constraints("aquifer.geojson", "--boundary", "resample") == constraints(
        "aquifer.geojson")


def test_a_slid_chord_split_by_a_fixed_point_keeps_its_item():
    # A fixed point on a chord splits it (its ends then stay): both pieces are still named by
    # the input segment they lie on.
    bottom = [[x, 0.0] for x in np.linspace(0, 2, 101)]
    vertices = bottom + [[2, 1], [0, 1]]
    n = len(vertices)
    strip = cvt2.Domain(vertices, [[i, (i + 1) % n] for i in range(n)])
    resampled = strip.resample(cells=300)
    ends = resampled.vertices[resampled.segments]
    on_bottom = [i for i, (a, b) in enumerate(ends) if a[1] == 0 and b[1] == 0]
    middle = ends[on_bottom[len(on_bottom) // 2]].mean(axis=0)
    result = cvt2.optimize(resampled, cvt2.random_points(resampled, cells=300, seed=2),
                           boundary="slide", fixed_points=[middle], max_iterations=20)
    items = result.domain.segment_items
    assert (items >= 0).all() and set(items) <= set(strip.segment_items)


def test_points_given_outside_the_resampled_domain_are_told_why(program, tmp_path):
    # Inside the input's 64-gon, outside the chords that resampling put across its corners.
    t = np.linspace(0, 2 * np.pi, 65)[:-1]
    circle = tmp_path / "circle.wkt"
    circle.write_text("POLYGON ((" + ", ".join(f"{np.cos(a):.17g} {np.sin(a):.17g}" for a in t)
                      + f", {np.cos(t[0]):.17g} {np.sin(t[0]):.17g}))\n")
    points = tmp_path / "p.txt"
    points.write_text("0.99 0\n")
    for option in ("--fixed-points", "--points-in"):
        p = subprocess.run([program, str(circle), "-n", "50", "--boundary", "resample", option,
                            str(points), "--quiet"], capture_output=True, text=True, timeout=60)
        assert p.returncode == 1
        assert "p.txt:1: generator (0.99, 0) lies outside the domain" in p.stderr
        assert "the domain as --boundary resample left it" in p.stderr


def test_resample_and_the_sizing_check_their_arguments():
    d = cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])
    for bad in ([[np.nan, 0]], [[1e301, 0]]):  # matched no vertex, and were ignored
        with pytest.raises(cvt2.DomainError, match=r"fixed_points\[0\]: point \(.*\) is not"):
            d.resample(size=0.3, fixed_points=bad)
    # ignored, where cvt2 --fixed-points refuses it
    with pytest.raises(cvt2.DomainError, match=r"fixed_points\[1\]: point \(2, 2\) lies outside"):
        d.resample(size=0.3, fixed_points=[[1, 1], [2, 2]])
    # was "RuntimeError: Unable to cast Python instance to C++ type"
    with pytest.raises(TypeError, match="boundary_size must be None or a number, not str"):
        cvt2.random_points(d, 10, density="lipschitz", boundary_size="x")


@pytest.mark.parametrize("algorithm", ["lbfgs", "lloyd"])
def test_a_slide_that_swings_between_two_places_dies_out(program, data, tmp_path, algorithm):
    # On a curved run a slide moves the chords its cell is measured against: one vertex of
    # earcut_eberly6 went back and forth between two places every step under L-BFGS (1000
    # iterations, largest move ratio 0.49); sent back where it came from, it goes halfway.
    summary, _, _ = run_program(program, data / "earcut_eberly6.wkt", tmp_path, "--boundary",
                                "slide", "--cells", 300, "--algorithm", algorithm)
    assert summary["stop"] == "converged" and int(summary["iterations"]) < 200
