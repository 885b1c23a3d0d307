# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# Generators a hair apart beside a constraint: the cell nearer the constraint is a strip some
# 1e-14 wide. It keeps its area and at least three vertices in every output (the arrays, GeoJSON,
# VTU, DISV), and the cells still tile the domain.
import json

import meshio
import numpy as np
import pytest
import shapely.geometry
from shapely.ops import unary_union

import cvt2

SQUARE = cvt2.Domain([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])


def shoelace(xy):
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)


def disv_cells(path):
    """CELL2D rows of a DISV file: {cell number: vertex coordinates}."""
    vertices, cells, block = {}, {}, None
    for line in path.read_text().splitlines():
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        if words[0] == "BEGIN":
            block = words[1]
        elif words[0] == "END":
            block = None
        elif block == "VERTICES":
            vertices[int(words[0])] = (float(words[1]), float(words[2]))
        elif block == "CELL2D":
            n = int(words[3])
            cells[int(words[0])] = np.array([vertices[int(i)] for i in words[4 : 4 + n]])
    return cells


@pytest.mark.parametrize(
    "points",
    [
        [[0.5, 1e-14], [0.5, 3e-14]],  # the lower cell: (0.75, 0) (0.75, 2e-14) (0.25, 2e-14) (0.25, 0)
        [[1 - 2e-15, 0.4], [1 - 5e-15, 0.4], [0.3, 0.5]],  # beside the right side, at one y
        [[0.2, 1 - 1e-13], [0.2, 1 - 3.5e-13], [0.7, 1 - 2e-16], [0.7, 1 - 7e-16]],
    ],
)
def test_a_thin_cell_keeps_its_area_in_every_output(points, tmp_path):
    vd = cvt2.bounded_voronoi(SQUARE, points)
    assert all(len(r) >= 3 for r in vd.regions)
    assert (vd.areas > 0).all()
    assert vd.areas.sum() == pytest.approx(1, rel=1e-12)
    for region, area in zip(vd.regions, vd.areas):
        assert shoelace(vd.vertices[region]) == pytest.approx(area, rel=1e-6)

    vd.to_geojson(tmp_path / "cells.geojson")
    features = json.loads((tmp_path / "cells.geojson").read_text())["features"]
    shapes = [shapely.geometry.shape(f["geometry"]) for f in features]
    assert len(shapes) == len(vd.points)
    assert all(s.is_valid and not s.is_empty and s.area > 0 for s in shapes)
    assert unary_union(shapes).area == pytest.approx(1, rel=1e-12)

    vd.to_vtu(tmp_path / "cells.vtu")
    mesh = meshio.read(tmp_path / "cells.vtu")
    polygons = [np.asarray(c) for block in mesh.cells for c in block.data]
    assert len(polygons) == len(vd.points)
    assert all(len(c) >= 3 and shoelace(mesh.points[c, :2]) > 0 for c in polygons)

    vd.to_disv(tmp_path / "cells.disv")
    cells = disv_cells(tmp_path / "cells.disv")
    assert len(cells) == len(vd.points)
    for ring in cells.values():
        assert len(ring) >= 4 and (ring[0] == ring[-1]).all()  # closed, three vertices or more
        assert shoelace(ring[:-1]) < 0  # clockwise, with area
