# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# Shared fixtures of the Python module's tests: the bundled data, the cvt2 program of the same
# build (CTest sets CVT2_PROGRAM; tests that need it are skipped without it), and writers of the
# files the program reads.
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

HERE = pathlib.Path(__file__).resolve().parent
DATA = pathlib.Path(os.environ.get("CVT2_DATA_DIR", HERE.parents[1] / "examples" / "data"))


@pytest.fixture
def data():
    return DATA


@pytest.fixture
def program():
    path = os.environ.get("CVT2_PROGRAM")
    if not path or not os.path.exists(path):
        pytest.skip("the cvt2 program is not built (CVT2_PROGRAM)")
    return path


def run_program(program, domain, tmp_path, *options, outputs=("points",)):
    """Runs `cvt2 DOMAIN OPTIONS --points-out ...`; returns the summary line's fields and the
    generators file as an array (x, y, c) and the paths of the other outputs asked for."""
    files = {name: tmp_path / f"cvt2_out.{name}" for name in outputs}
    flags = {"points": "--points-out", "geojson": "--geojson", "vtu": "--vtu", "disv": "--disv"}
    command = [program, str(domain), "--quiet", *map(str, options)]
    for name, path in files.items():
        command += [flags[name], str(path)]
    out = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    summary = dict(field.split("=", 1) for field in out.split())
    points = np.loadtxt(files["points"], ndmin=2) if "points" in files else None
    return summary, points, files


def wkt_number(x):
    return repr(float(x))


def write_wkt(path, polygons, lines):
    """A WKT file with the exact doubles of shapely geometries: a MULTIPOLYGON line and a
    LINESTRING line per line."""

    def ring(coords):
        return "(" + ", ".join(f"{wkt_number(x)} {wkt_number(y)}" for x, y, *_ in coords) + ")"

    text = ["MULTIPOLYGON (" + ", ".join(
        "(" + ", ".join(ring(r.coords) for r in [p.exterior, *p.interiors]) + ")" for p in polygons
    ) + ")"]
    text += ["LINESTRING " + ring(line.coords) for line in lines]
    pathlib.Path(path).write_text("\n".join(text) + "\n")


def write_geojson(path, polygons, lines):
    """The same as GeoJSON features (Python's json writes the shortest exact decimals)."""
    from shapely.geometry import mapping

    features = [{"type": "Feature", "properties": {}, "geometry": mapping(g)} for g in [*polygons, *lines]]
    pathlib.Path(path).write_text(json.dumps({"type": "FeatureCollection", "features": features}))
