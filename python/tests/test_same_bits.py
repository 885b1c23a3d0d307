# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# The module gives the same bits as the cvt2 program of the same build: random points,
# optimization by both algorithms and both built-in densities, the generators' order, the files
# it writes; and a shapely domain gives what the same geometry gives as a .wkt or .geojson file.
import numpy as np
import pytest
import shapely.wkt

import cvt2
from conftest import run_program, write_geojson, write_wkt


def same(a, b):
    return a.shape == b.shape and np.array_equal(a, b)


@pytest.mark.parametrize(
    "file, n, seed",
    [("four_clusters.poly", 300, 1), ("us_massachusetts_counties.wkt", 2000, 7),
     ("us_kentucky_counties.geojson", 1500, 3), ("earcut_logo.poly", 500, 12345678901234)],
)
def test_random_points_are_the_programs_draw(program, data, tmp_path, file, n, seed):
    # With no iteration, the program's generators are the domain's and its draw, in the order of
    # the cells of the triangulation they make: the diagram's order.
    domain = cvt2.Domain.from_file(data / file)
    points = cvt2.random_points(domain, n, seed=seed)
    assert points.shape == (n, 2) and points.dtype == np.float64
    _, theirs, _ = run_program(program, data / file, tmp_path, "-n", n, "--seed", seed,
                               "--iterations", 0, "--move-ratio", 0)
    diagram = cvt2.bounded_voronoi(domain, points)
    assert same(diagram.points, theirs[:, :2])
    assert same(diagram.constrained, theirs[:, 2] == 1)
    drawn = {tuple(p) for p in points}
    assert drawn <= {tuple(p) for p in theirs[:, :2]}
    assert same(cvt2.random_points(domain, n, seed=seed), points)  # the domain is reusable


@pytest.mark.parametrize("algorithm", ["lloyd", "lbfgs"])
@pytest.mark.parametrize(
    "file, n, iterations",
    [("four_clusters.poly", 400, 1000), ("square_inner_constraints.wkt", 800, 30),
     ("us_kentucky_counties.geojson", 3000, 8)],
)
def test_optimize_gives_the_programs_bits(program, data, tmp_path, algorithm, file, n, iterations):
    domain = cvt2.Domain.from_file(data / file)
    result = cvt2.optimize(domain, cvt2.random_points(domain, n, seed=5), algorithm=algorithm,
                           max_iterations=iterations)
    summary, theirs, files = run_program(
        program, data / file, tmp_path, "-n", n, "--seed", 5, "--algorithm", algorithm,
        "--iterations", iterations, outputs=("points", "geojson", "vtu", "disv"))
    assert same(result.points, theirs[:, :2])
    assert same(result.constrained, theirs[:, 2] == 1)
    assert result.iterations == int(summary["iterations"])
    assert result.evaluations == int(summary["evaluations"])
    assert result.stop_reason == summary["stop"]
    assert result.energy == pytest.approx(float(summary["energy"]), rel=1e-7)
    assert result.normalized_energy == pytest.approx(float(summary["normalized_energy"]), rel=1e-7)
    assert len(result.energy_history) == result.iterations + 1
    assert result.energy_history[-1] == result.energy
    # The diagram of the optimized triangulation: the program's files, byte for byte.
    diagram = result.bounded_voronoi()
    assert same(diagram.points, result.points)
    diagram.to_geojson(tmp_path / "ours.geojson")
    diagram.to_vtu(tmp_path / "ours.vtu")
    diagram.to_disv(tmp_path / "ours.disv")
    for kind in ("geojson", "vtu", "disv"):
        assert (tmp_path / f"ours.{kind}").read_bytes() == files[kind].read_bytes(), kind


@pytest.mark.parametrize("algorithm", ["lloyd", "lbfgs"])
def test_lipschitz_density_gives_the_programs_bits(program, data, tmp_path, algorithm):
    file = data / "earcut_dude.poly"
    domain = cvt2.Domain.from_file(file)
    for size in (None, 2.5):
        options = ["--density", "lipschitz", "--lipschitz-k", 0.2]
        if size is not None:
            options += ["--boundary-size", size]
        points = cvt2.random_points(domain, 400, seed=2, density="lipschitz", lipschitz_k=0.2,
                                    boundary_size=size)
        result = cvt2.optimize(domain, points, algorithm=algorithm, density="lipschitz",
                               lipschitz_k=0.2, boundary_size=size, max_iterations=15)
        summary, theirs, _ = run_program(program, file, tmp_path, "-n", 400, "--seed", 2,
                                         "--algorithm", algorithm, "--iterations", 15, *options)
        assert same(result.points, theirs[:, :2])
        assert result.evaluations == int(summary["evaluations"])


def test_points_given_are_the_programs_points_in(program, data, tmp_path):
    file = data / "us_massachusetts_counties.poly"
    domain = cvt2.Domain.from_file(file)
    points = cvt2.random_points(domain, 1000, seed=9)
    np.savetxt(tmp_path / "in.txt", points, fmt="%.17g")
    assert same(np.loadtxt(tmp_path / "in.txt"), points)
    result = cvt2.optimize(domain, points, algorithm="lloyd", max_iterations=10, move_ratio=0)
    _, theirs, _ = run_program(program, file, tmp_path, "--points-in", tmp_path / "in.txt",
                               "--algorithm", "lloyd", "--iterations", 10, "--move-ratio", 0)
    assert same(result.points, theirs[:, :2])


@pytest.mark.parametrize("redistribute, option", [("auto", "auto"), (True, "always"),
                                                 (False, "never")])
def test_redistributed_points_are_the_programs(program, data, tmp_path, redistribute, option):
    # Uniform points under the automatic sizing: cvt2 --redistribute and optimize(redistribute=)
    # replace them (auto: they do not follow it) by the same draw, or keep them.
    file = data / "earcut_dude.poly"
    domain = cvt2.Domain.from_file(file)
    points = cvt2.random_points(domain, 600, seed=9)
    np.savetxt(tmp_path / "in.txt", points, fmt="%.17g")
    result = cvt2.optimize(domain, points, density="lipschitz", max_iterations=5,
                           redistribute=redistribute, seed=3)
    _, theirs, _ = run_program(program, file, tmp_path, "--points-in", tmp_path / "in.txt",
                               "--density", "lipschitz", "--iterations", 5, "--seed", 3,
                               "--redistribute", option)
    assert same(result.points, theirs[:, :2])
    assert result.redistributed == (redistribute is not False)


def test_redistributed_points_keep_out_of_conforming_circles_as_the_programs(program, data,
                                                                           tmp_path):
    # The river of aquifer.geojson is conforming: points drawn in place of the given ones keep
    # out of its circles, drawn again as cvt2 draws them.
    file = data / "aquifer.geojson"
    domain = cvt2.Domain.from_file(file)
    points = cvt2.random_points(domain, 800, seed=9)
    np.savetxt(tmp_path / "in.txt", points, fmt="%.17g")
    result = cvt2.optimize(domain, points, density="lipschitz", max_iterations=0, seed=3)
    _, theirs, _ = run_program(program, file, tmp_path, "--points-in", tmp_path / "in.txt",
                               "--density", "lipschitz", "--iterations", 0, "--seed", 3)
    assert result.redistributed
    assert same(result.points, theirs[:, :2])


def test_threads_do_not_change_the_bits(data):
    domain = cvt2.Domain.from_file(data / "us_massachusetts_counties.poly")
    points = cvt2.random_points(domain, 30000, seed=4)
    results = [cvt2.optimize(domain, points, max_iterations=5, threads=t) for t in (1, 2, 0)]
    for r in results[1:]:
        assert same(r.points, results[0].points)
        assert same(r.energy_history, results[0].energy_history)


@pytest.mark.parametrize("file", ["four_clusters.wkt", "us_massachusetts_counties.wkt",
                                  "square_inner_constraints.wkt"])
def test_a_shapely_domain_is_the_same_geometry_read_from_a_file(program, data, tmp_path, file):
    polygons, lines = [], []
    for text in (data / file).read_text().splitlines():
        if not text.strip():
            continue
        g = shapely.wkt.loads(text)
        if g.geom_type == "Polygon":
            polygons.append(g)
        elif g.geom_type == "MultiPolygon":
            polygons.extend(g.geoms)
        elif g.geom_type == "LineString":
            lines.append(g)
        elif g.geom_type == "MultiLineString":
            lines.extend(g.geoms)
    geometry = polygons[0] if len(polygons) == 1 else shapely.geometry.MultiPolygon(polygons)
    domain = cvt2.Domain.from_shapely(geometry, constraints=lines)
    assert domain.format == "shapely"
    points = cvt2.random_points(domain, 700, seed=11)
    result = cvt2.optimize(domain, points, max_iterations=20)
    write_wkt(tmp_path / "d.wkt", polygons, lines)
    write_geojson(tmp_path / "d.geojson", polygons, lines)
    for written in ("d.wkt", "d.geojson"):
        _, theirs, _ = run_program(program, tmp_path / written, tmp_path, "-n", 700, "--seed", 11,
                                   "--iterations", 20)
        assert same(result.points, theirs[:, :2]), written
        from_file = cvt2.Domain.from_file(tmp_path / written)
        assert same(cvt2.random_points(from_file, 700, seed=11), points)
        assert same(from_file.segments, domain.segments)
        assert same(from_file.vertices, domain.vertices)


@pytest.mark.parametrize("file", ["four_clusters.poly", "square_inner_constraints.wkt", "us_kentucky_counties.geojson"])
def test_barrier_grids_and_cells_on_constraints_are_the_programs(program, data, tmp_path, file):
    domain = cvt2.Domain.from_file(data / file)
    diagram = cvt2.bounded_voronoi(domain, cvt2.random_points(domain, 400, seed=3))
    csv = tmp_path / "theirs.csv"
    _, _, files = run_program(program, data / file, tmp_path, "-n", 400, "--seed", 3, "--iterations", 0,
                              "--move-ratio", 0, "--constraints", "barrier", "--cells-on-constraints", csv,
                              outputs=("geojson", "vtu", "disv"))
    diagram.to_geojson(tmp_path / "ours.geojson", constraints="barrier")
    diagram.to_vtu(tmp_path / "ours.vtu", constraints="barrier")
    diagram.to_disv(tmp_path / "ours.disv", constraints="barrier")
    diagram.to_cells_on_constraints(tmp_path / "ours.csv", constraints="barrier")
    for kind in ("geojson", "vtu", "disv"):
        assert (tmp_path / f"ours.{kind}").read_bytes() == files[kind].read_bytes(), kind
    assert (tmp_path / "ours.csv").read_bytes() == csv.read_bytes()
    with pytest.raises(ValueError, match="optimize\\(..., constraints='conforming'\\)"):
        diagram.to_disv(tmp_path / "x.disv", constraints="conforming")
    with pytest.raises(ValueError, match="'slit', 'barrier' or 'conforming'"):
        diagram.to_disv(tmp_path / "x.disv", constraints="wall")
