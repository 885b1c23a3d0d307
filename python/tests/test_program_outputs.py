# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# cvt2's output files: none replaces an input or another output, a bad path fails before any
# work, and a temporary name never takes a user's file.
import os
import shutil
import subprocess
import time

import numpy as np
import pytest


def run(program, *arguments, cwd):
    return subprocess.run([os.path.abspath(program), *map(str, arguments), "--quiet"],
                          capture_output=True, text=True, cwd=cwd, timeout=120)


def test_an_output_never_replaces_an_input(program, data, tmp_path):
    shutil.copy(data / "four_clusters.poly", tmp_path / "in.poly")
    (tmp_path / "p.txt").write_text("0.5 0.5\n")
    kept = {name: (tmp_path / name).read_bytes() for name in ("in.poly", "p.txt")}
    cases = [
        (["--geojson", "in.poly"], "--geojson 'in.poly' would replace the domain file 'in.poly'"),
        (["--vtu", "./sub/../in.poly"], "would replace the domain file"),  # the same file
        (["--points-in", "p.txt", "--points-out", "p.txt"],
         "--points-out 'p.txt' would replace --points-in 'p.txt'"),
        (["--fixed-points", "p.txt", "--svg", "p.txt"], "would replace --fixed-points 'p.txt'"),
        (["--top", "p.txt", "--disv", "p.txt"], "would replace --top 'p.txt'"),
    ]
    (tmp_path / "sub").mkdir()
    for options, message in cases:
        p = run(program, "in.poly", "-n", 50, *options, cwd=tmp_path)
        assert p.returncode == 1 and message in p.stderr, (options, p.stderr)
    assert kept == {name: (tmp_path / name).read_bytes() for name in kept}


def test_outputs_are_checked_before_any_work(program, data, tmp_path):
    shutil.copy(data / "four_clusters.poly", tmp_path / "in.poly")
    (tmp_path / "a").write_text("ORIG")
    (tmp_path / "d").mkdir()
    cases = [
        (["--geojson", "a", "--vtu", "a"], "--vtu and --geojson name the same file 'a'"),
        (["--svg", "ok.svg", "--geojson", "d"], "--geojson 'd' is a directory"),
        (["--geojson", "nodir/x.geojson"], "--geojson 'nodir/x.geojson': there is no directory"),
        (["--mesh-out", "m", "--svg", "m.ele"], "--mesh-out and --svg name the same file 'm.ele'"),
    ]
    for options, message in cases:
        start = time.monotonic()
        # a million points: the check comes first, in far less than the run would take
        p = run(program, "in.poly", "-n", 1000000, *options, cwd=tmp_path)
        assert p.returncode == 1 and message in p.stderr, (options, p.stderr)
        assert time.monotonic() - start < 5
    assert (tmp_path / "a").read_text() == "ORIG"
    assert not (tmp_path / "ok.svg").exists()
    assert sorted(os.listdir(tmp_path)) == ["a", "d", "in.poly"]  # no temporary left


def test_temporary_names_take_no_file_and_links_are_written_through(program, data, tmp_path):
    shutil.copy(data / "four_clusters.poly", tmp_path / "in.poly")
    (tmp_path / "b.tmp").write_text("MINE")
    (tmp_path / "real.geojson").write_text("OLD")
    os.symlink("real.geojson", tmp_path / "link.geojson")
    p = run(program, "in.poly", "-n", 50, "--geojson", "a", "--svg", "a.tmp", "--points-out",
            "b", "--vtu", "link.geojson", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert (tmp_path / "a").read_text().startswith("{")  # the GeoJSON, not the SVG
    assert (tmp_path / "a.tmp").read_text().startswith("<")
    assert (tmp_path / "b.tmp").read_text() == "MINE"
    assert os.path.islink(tmp_path / "link.geojson")
    assert (tmp_path / "real.geojson").read_text().startswith("<?xml")  # the VTU, through it
    assert not [f for f in os.listdir(tmp_path) if "cvt2-" in f]
    # /dev/stdout a pipe (a link to /proc/self/fd/1, whose target is no path): written to
    p = run(program, "in.poly", "-n", 50, "--geojson", "/dev/stdout", cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert p.stdout.startswith('{"type":"FeatureCollection"') and "algorithm=" in p.stdout
    assert not [f for f in os.listdir(tmp_path) if "cvt2-" in f]


def test_points_out_reads_back_as_points_in(program, data, tmp_path):
    # 'x y c' lines: a run continues from another's generators, the domain's own (c = 1) given
    # by the domain again (a domain with no free points of its own, which it would give again
    # where they started). Converged already: no iteration, the same energy and generators.
    domain = data / "square_inner_constraints.poly"
    first = run(program, domain, "-n", 300, "--points-out", "a.txt", cwd=tmp_path)
    assert first.returncode == 0, first.stderr
    again = run(program, domain, "--points-in", "a.txt", "--points-out", "b.txt", cwd=tmp_path)
    assert again.returncode == 0, again.stderr
    a = dict(f.split("=", 1) for f in first.stdout.split())
    b = dict(f.split("=", 1) for f in again.stdout.split())
    assert a["stop"] == b["stop"] == "converged" and b["iterations"] == "0"
    assert a["generators"] == b["generators"] and a["energy"] == b["energy"]
    rows = [sorted(map(tuple, np.loadtxt(tmp_path / f))) for f in ("a.txt", "b.txt")]
    assert rows[0] == rows[1]


def test_a_top_a_cell_counts_the_cells_barriers_split(program, data, tmp_path):
    # With barriers a cell they cross is two cells of the DISV: a --top of one value a DISV cell
    # is taken (no length was: the count of --cells was asked for first, write_disv's after).
    domain = data / "square_inner_constraints.wkt"
    first = run(program, domain, "--cells", 200, "--constraints", "barrier", "--disv", "a.disv",
                cwd=tmp_path)
    assert first.returncode == 0, first.stderr
    text = (tmp_path / "a.disv").read_text()
    cells = int(text.split("NCPL")[1].split()[0])
    assert cells > 200
    for count in (cells, 200):
        (tmp_path / "top.txt").write_text("\n".join(["2"] * count) + "\n")
        p = run(program, domain, "--cells", 200, "--constraints", "barrier", "--disv",
                f"b{count}.disv", "--top", "top.txt", cwd=tmp_path)
        if count == cells:
            assert p.returncode == 0, p.stderr
        else:
            assert p.returncode == 1 and not (tmp_path / "b200.disv").exists()
            assert f"--top has 200 values, the DISV {cells} cells" in p.stderr, p.stderr
    # Without barriers the count is --cells', checked before the work.
    (tmp_path / "top.txt").write_text("2\n" * cells)
    p = run(program, domain, "--cells", 200, "--disv", "c.disv", "--top", "top.txt", cwd=tmp_path)
    assert p.returncode == 1 and f"--top has {cells} values for --cells 200" in p.stderr


def test_the_lipschitz_options_need_the_lipschitz_density(program, data, tmp_path):
    # (--lipschitz-k alone was taken and did nothing)
    for option, value in (("--lipschitz-k", 0.5), ("--boundary-size", 0.1)):
        p = run(program, data / "four_clusters.poly", option, value, cwd=tmp_path)
        assert p.returncode == 1 and f"{option} needs --density lipschitz" in p.stderr, p.stderr
    p = run(program, data / "four_clusters.poly", "--density", "lipschitz", "--lipschitz-k", 0.5,
            "--iterations", 2, cwd=tmp_path)
    assert p.returncode == 0, p.stderr


def test_random_points_merged_where_coordinates_are_coarse_are_counted(program, tmp_path):
    # A 10 x 10 square at (1e15, 1e15), where a double is an eighth: of 296 points drawn, some
    # round onto others and merge; --cells 300 then gives fewer cells, and says how many.
    c = 1e15
    (tmp_path / "far.wkt").write_text(
        f"POLYGON (({c} {c}, {c + 10} {c}, {c + 10} {c + 10}, {c} {c + 10}, {c} {c}))\n")
    p = run(program, "far.wkt", "--cells", 300, "--iterations", 0, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    merged = int(p.stderr.split("cvt2: note: ")[1].split(" of the 296 random points fell on")[0])
    generators = int(dict(f.split("=", 1) for f in p.stdout.split())["generators"])
    assert merged > 0 and generators + merged == 300, (p.stderr, generators)


def test_repeated_points_given_are_noted_and_merged(program, data, tmp_path):
    # (a repeated --fixed-points line was merged silently; --points-in's were noted)
    (tmp_path / "points.txt").write_text("0.25 0.25\n0.5 0.5\n0.25 0.25\n")
    (tmp_path / "wells.txt").write_text("0.75 0.75\n# a comment\n0.75 0.75\n")
    p = run(program, data / "four_clusters.poly", "--points-in", "points.txt", "--fixed-points",
            "wells.txt", "--iterations", 0, cwd=tmp_path)
    assert p.returncode == 0, p.stderr
    assert "points.txt:3: this point repeats the one on line 1" in p.stderr, p.stderr
    assert "wells.txt:3: this point repeats the one on line 1" in p.stderr, p.stderr
    assert int(dict(f.split("=", 1) for f in p.stdout.split())["generators"]) == 213 + 2 + 1


def test_redistribute_always_without_a_density_says_the_points_are_kept(program, data, tmp_path):
    # (it was taken silently: with a uniform density there is nothing to redistribute by)
    p = subprocess.run([os.path.abspath(program), str(data / "four_clusters.poly"),
                        "--redistribute", "always", "--iterations", "2"],
                       capture_output=True, text=True, cwd=tmp_path)
    assert p.returncode == 0
    assert "--redistribute always: the density is uniform (no --density lipschitz, no --refine): " \
           "the generators given are kept" in p.stderr, p.stderr
