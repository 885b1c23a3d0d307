# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# Errors arrive as Python exceptions with the library's message and where; none crashes the
# interpreter, and the interpreter is fine afterwards.
import numpy as np
import pytest
from shapely.geometry import LineString, Point, Polygon

import cvt2


@pytest.fixture
def square():
    return cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])


@pytest.mark.parametrize(
    "points, error, message",
    [
        (np.zeros((3, 3)), ValueError, r"points must have shape \(n, 2\), not \(3, 3\)"),
        (np.zeros(4), ValueError, r"points must have shape \(n, 2\), not \(4,\)"),
        ("abc", TypeError, "points must be an array"),
        ([[0.5, 0.5], [0.2]], TypeError, "points must be an array"),
        ([[0.5, 0.5], [np.nan, 0.2]], cvt2.DomainError, r"points\[1\]: generator \(nan, 0.2\d*\) is not finite"),
        ([[0.5, 0.5], [0.1, np.inf]], cvt2.DomainError, r"points\[1\]: generator"),
        ([[0.5, 0.5], [0.3, 0.3], [1.5, 0.5]], cvt2.DomainError,
         r"points\[2\]: generator \(1.5, 0.5\) lies outside the domain"),
    ],
)
def test_bad_points(square, points, error, message):
    for call in (lambda: cvt2.optimize(square, points), lambda: cvt2.bounded_voronoi(square, points)):
        with pytest.raises(error, match=message) as e:
            call()
        if error is cvt2.DomainError:
            assert isinstance(e.value, ValueError)
            assert e.value.index == int(message.split("[")[1].split("\\]")[0])


def test_no_points_is_fine(square):
    r = cvt2.optimize(square, np.empty((0, 2)))
    assert r.stop_reason == "no_free_generator" and len(r.points) == 4 and r.constrained.all()
    assert len(cvt2.bounded_voronoi(square, []).points) == 4
    assert cvt2.random_points(square, 0).shape == (0, 2)


def test_bad_densities(square):
    points = cvt2.random_points(square, 200, seed=1)
    with pytest.raises(ValueError, match=r"the density returned shape \(\d+, 2\) for \d+ points"):
        cvt2.optimize(square, points, density=lambda xy: xy)
    with pytest.raises(ValueError, match=r"returned shape \(\d+,\) for \d+ points"):
        cvt2.optimize(square, points, density=lambda xy: np.ones(len(xy) - 1))
    with pytest.raises(ValueError, match=r"returned shape \(\) "):
        cvt2.optimize(square, points, density=lambda xy: 1.0)
    with pytest.raises(TypeError, match="the density must return an array of numbers, not str"):
        cvt2.optimize(square, points, density=lambda xy: "abc")
    negative = lambda xy: np.where(xy[:, 0] < 0.5, 1.0, -2.0)  # noqa: E731
    with pytest.raises(cvt2.DomainError, match=r"the density is -2(.0*)? at \(0\.[5-9]"):
        cvt2.optimize(square, points, density=negative)
    with pytest.raises(cvt2.DomainError, match=r"the density is -1e-10 at"):  # not -0.000000
        cvt2.optimize(square, points, density=lambda xy: np.full(len(xy), -1e-10))
    with pytest.raises(cvt2.DomainError, match=r"the density is nan at"):
        cvt2.optimize(square, points, density=lambda xy: np.full(len(xy), np.nan))
    with pytest.raises(cvt2.DomainError, match=r"the density is -2(.0*)? at"):
        cvt2.random_points(square, 10, density=negative)

    class Mine(Exception):
        pass

    def raising(xy):
        raise Mine("from the density")

    for threads in (1, 2):
        with pytest.raises(Mine, match="from the density"):
            cvt2.optimize(square, cvt2.random_points(square, 20000, seed=2), density=raising,
                          threads=threads)
    with pytest.raises(Mine):
        cvt2.random_points(square, 10, density=raising)
    with pytest.raises(ZeroDivisionError):
        cvt2.optimize(square, points, callback=lambda info: 1 / 0)
    with pytest.raises(TypeError, match="density must be None, 'uniform', 'lipschitz' or a callable"):
        cvt2.optimize(square, points, density=3)
    with pytest.raises(ValueError, match="density must be None, 'uniform', 'lipschitz' or a callable, not 'x'"):
        cvt2.optimize(square, points, density="x")
    with pytest.raises(ValueError, match="boundary_size needs density='lipschitz'"):
        cvt2.optimize(square, points, boundary_size=1.0)
    with pytest.raises(ValueError, match="lipschitz_k must be positive"):
        cvt2.random_points(square, 5, density="lipschitz", lipschitz_k=-1)
    # The interpreter and the module are fine afterwards.
    assert cvt2.optimize(square, points, density=lambda xy: np.ones(len(xy)), max_iterations=2).iterations == 2


def test_bad_options(square):
    points = cvt2.random_points(square, 50, seed=1)
    with pytest.raises(ValueError, match="algorithm must be 'lbfgs' or 'lloyd', not 'newton'"):
        cvt2.optimize(square, points, algorithm="newton")
    with pytest.raises(ValueError, match="move_ratio must be a finite number >= 0, not -1"):
        cvt2.optimize(square, points, move_ratio=-1)
    with pytest.raises(ValueError, match="move_ratio must be a finite number >= 0, not inf"):
        cvt2.optimize(square, points, move_ratio=np.inf)  # said ">= 0, not inf"
    for name in ("move_ratio", "time_limit", "lipschitz_k"):  # float() took "1" and True
        for bad in ("1", True):
            with pytest.raises(TypeError, match=f"{name} must be a number, not"):
                cvt2.optimize(square, points, **{name: bad})
    with pytest.raises(ValueError, match="max_iterations must be >= 0"):
        cvt2.optimize(square, points, max_iterations=-5)
    with pytest.raises(TypeError, match="max_iterations must be an integer"):
        cvt2.optimize(square, points, max_iterations=2.5)
    with pytest.raises(ValueError, match="n must be >= 0"):
        cvt2.random_points(square, -1)
    with pytest.raises(ValueError, match="seed must be below 2\\*\\*64"):
        cvt2.random_points(square, 3, seed=2**64)
    with pytest.raises(TypeError, match="domain must be a cvt2.Domain"):
        cvt2.random_points("square.poly", 3)
    with pytest.raises(TypeError, match="callback must be None or a callable"):
        cvt2.optimize(square, points, callback=3)


def test_bad_domains(tmp_path):
    with pytest.raises(FileNotFoundError):
        cvt2.Domain.from_file(tmp_path / "missing.poly")
    (tmp_path / "folder.wkt").mkdir()
    with pytest.raises(IsADirectoryError, match="a directory"):  # was "no such domain file"
        cvt2.Domain.from_file(tmp_path / "folder.wkt")
    bad = tmp_path / "bad.poly"
    bad.write_text("4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\nx 0\n")
    with pytest.raises(cvt2.ParseError) as e:
        cvt2.Domain.from_file(bad)
    assert e.value.file == str(bad) and e.value.line == 6 and str(e.value).startswith(f"{bad}:6: ")
    unknown = tmp_path / "domain.txt"
    unknown.write_text("x")
    with pytest.raises(cvt2.ParseError, match="unknown domain format"):
        cvt2.Domain.from_file(unknown)
    crossing = tmp_path / "crossing.wkt"
    crossing.write_text("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))\nLINESTRING (0.1 0.1, 0.9 0.9)\n"
                        "LINESTRING (0.1 0.9, 0.9 0.1)\n")
    with pytest.raises(cvt2.DomainError, match=rf"{crossing}:3: this geometry crosses itself or an earlier one: "
                       r"its segment \(0.1, 0.9\) - \(0.9, 0.1\) crosses \(0.1, 0.1\) - \(0.9, 0.9\)"):
        cvt2.Domain.from_file(crossing)
    # Arrays: rows named in messages.
    with pytest.raises(cvt2.DomainError, match=r"<arrays>:3: segment .* crosses segment"):
        cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [0, 2], [1, 3]])
    with pytest.raises(IndexError, match=r"segments\[1\] = \(1, 4\): no such vertex among 4"):
        cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 4]])
    with pytest.raises(TypeError, match="segments must hold integers"):
        cvt2.Domain([[0, 0], [1, 0], [1, 1]], [[0.0, 1.0], [1.0, 2.0], [2.0, 0.0]])
    with pytest.raises(cvt2.DomainError, match="the domain is empty"):
        cvt2.Domain([[0, 0], [1, 0], [1, 1]], [[0, 1], [1, 2]])
    with pytest.raises(cvt2.DomainError, match="is not finite"):
        cvt2.Domain([[0, 0], [1, 0], [1, np.nan]], [[0, 1], [1, 2], [2, 0]])
    # Shapely: geometries named in messages.
    square = Polygon([(0, 0), (1, 0), (1, 1), (0, 1)])
    with pytest.raises(cvt2.DomainError, match=r"<shapely>: constraints\[1\]: this geometry crosses"):
        cvt2.Domain.from_shapely(square, [LineString([(0.1, 0.1), (0.9, 0.9)]),
                                          LineString([(0.1, 0.9), (0.9, 0.1)])])
    with pytest.raises(TypeError, match="must be a shapely Polygon or MultiPolygon, not Point"):
        cvt2.Domain.from_shapely(Point(0, 0))
    with pytest.raises(TypeError, match=r"constraints\[0\] must be a shapely LineString"):
        cvt2.Domain.from_shapely(square, [square])
    with pytest.raises(cvt2.DomainError, match="the domain is empty"):
        cvt2.Domain.from_shapely(Polygon())
    bowtie = Polygon([(0, 0), (1, 1), (1, 0), (0, 1)])
    with pytest.raises(cvt2.DomainError, match="<shapely>: polygon: this geometry crosses itself"):
        cvt2.Domain.from_shapely(bowtie)


@pytest.mark.parametrize(
    "points, kind",
    [
        (None, "None"),
        (np.ones((3, 2), dtype=bool), "an array of bool"),
        (np.array([["0.5", "0.5"]]), "an array of <U3"),
        (np.array([[0.5 + 0j, 0.5]]), "an array of complex128"),
        (np.array([[0.5, 0.5]], dtype=object), "an array of object"),
    ],
)
def test_points_that_are_no_numbers_are_not_cast(square, points, kind):
    # numpy would take each of them as doubles without a word: True as 1, "0.5" as 0.5, 0.5+0j
    # as 0.5 with a warning.
    message = r"^points must be an array of shape \(n, 2\) of numbers, not " + kind + "$"
    for call in (cvt2.optimize, cvt2.bounded_voronoi):
        with pytest.raises(TypeError, match=message):
            call(square, points)


def test_other_arrays_of_no_numbers_are_not_cast(square):
    with pytest.raises(TypeError, match=r"^vertices must be an array of shape \(n, 2\) of numbers, not an array of bool$"):
        cvt2.Domain(np.ones((3, 2), dtype=bool), [[0, 1], [1, 2], [2, 0]])
    with pytest.raises(TypeError, match="^the density must return an array of numbers, not an array of bool$"):
        cvt2.optimize(square, [[0.5, 0.5]], density=lambda xy: np.ones(len(xy), dtype=bool))


def test_counts_out_of_range_get_one_message(square):
    for n in (-1, 2**63, 2**64, np.uint64(2**63)):
        with pytest.raises(ValueError, match=rf"^n must be >= 0 and below 2\*\*63, not {n}$"):
            cvt2.random_points(square, n)
    with pytest.raises(ValueError, match=r"^max_iterations must be >= 0 and below 2\*\*63, not 9223372036854775808$"):
        cvt2.optimize(square, [[0.5, 0.5]], max_iterations=2**63)
    with pytest.raises(ValueError, match=r"^threads must be >= 0 and below 2\*\*63, not 9223372036854775808$"):
        cvt2.bounded_voronoi(square, [], threads=2**63)
    # A count the int64 takes, but memory not: a MemoryError of ours, nothing allocated.
    with pytest.raises(MemoryError, match=r"^not enough memory for n = 4611686018427387904 points$"):
        cvt2.random_points(square, 2**62)
    assert cvt2.random_points(square, 2**0).shape == (1, 2)


@pytest.mark.parametrize("algorithm", ["lloyd", "lbfgs"])
def test_the_callback_sees_every_state_once_the_final_one_last(square, algorithm):
    points = cvt2.random_points(square, 200, seed=3)
    for options, reason in [
        (dict(max_iterations=4, move_ratio=0), "max_iterations"),
        (dict(max_iterations=1000), "converged"),
        (dict(max_iterations=0), "max_iterations"),
    ]:
        seen = []
        r = cvt2.optimize(square, points, algorithm=algorithm, callback=lambda info: seen.append(info), **options)
        assert r.stop_reason == reason
        assert [s["iteration"] for s in seen] == list(range(r.iterations + 1))
        assert [s["energy"] for s in seen] == list(r.energy_history)
        last = seen[-1]
        assert (last["energy"], last["evaluations"], last["max_move_ratio"], last["mean_move_ratio"]) == (
            r.energy, r.evaluations, r.max_move_ratio, r.mean_move_ratio)
    # Returning False stops at the state the callback saw: the result, not seen twice.
    for stop in (lambda info: info["iteration"] < 2, lambda info: np.bool_(info["iteration"] < 2)):
        seen = []
        r = cvt2.optimize(square, points, algorithm=algorithm, move_ratio=0,
                          callback=lambda info: seen.append(info["iteration"]) or stop(info))
        assert r.stop_reason == "callback" and r.iterations == 2 and seen == [0, 1, 2]
    for answer in (1, "stop", [False]):
        with pytest.raises(TypeError, match=rf"^the callback must return None, True or False, not {type(answer).__name__}$"):
            cvt2.optimize(square, points, algorithm=algorithm, callback=lambda info: answer)


def test_cells_too_small_for_double_precision_are_an_error():
    # A 1 x 1 square at 1e15 (an ulp is 0.125) with 40 cells: cells round to fewer than three
    # vertices, which every output wrote as an empty polygon (a DISV row MODFLOW rejects).
    far = cvt2.Domain(np.array([[0, 0], [1, 0], [1, 1], [0, 1]]) + 1e15,
                      [[0, 1], [1, 2], [2, 3], [3, 0]])
    with pytest.raises(cvt2.DomainError, match=r"the cell of generator \(.*\) rounds to [0-2] "
                                               r"vertices: double precision cannot hold the "
                                               r"cells at their coordinates \(cells a few ulps"):
        cvt2.bounded_voronoi(far, cvt2.random_points(far, 40, seed=1))
    # the same square at 1e6 is fine
    near = cvt2.Domain(np.array([[0, 0], [1, 0], [1, 1], [0, 1]]) + 1e6,
                       [[0, 1], [1, 2], [2, 3], [3, 0]])
    d = cvt2.bounded_voronoi(near, cvt2.random_points(near, 40, seed=1))
    assert d.areas.sum() == pytest.approx(1, rel=1e-9)


def test_cells_that_lose_a_lobe_to_rounding_are_an_error():
    # At 1e15 (doubles 0.125 apart) a polyline's vertices one unit in the last place apart have
    # cells of two lobes each a few units wide; the lobes of the one at (2.375, 3.5) rounded to
    # one, its polygon 0.3125 of its area 1.5625: a gap in the tiling, without a word. Now the
    # diagram says that double precision cannot hold the cells, naming the generator.
    off = 1e15
    square = np.array([[0, 0], [10, 0], [10, 10], [0, 10]]) + off
    line = np.array([[0.0, 3.0], [2.25, 3.5], [2.375, 3.5], [2.5, 3.5], [5.25, 2.875]]) + off
    domain = cvt2.Domain(np.vstack([square, line]),
                         [[0, 1], [1, 2], [2, 3], [3, 0], [4, 5], [5, 6], [6, 7], [7, 8]])
    with pytest.raises(cvt2.DomainError, match="loses a part to rounding: double precision"):
        cvt2.bounded_voronoi(domain, np.zeros((0, 2)))
