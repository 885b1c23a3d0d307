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
