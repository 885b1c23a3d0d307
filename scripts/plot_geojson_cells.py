#!/usr/bin/env python3
# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Draws cvt2's GeoJSON cells as a GIS would: each cell filled with the colour of the region
(county) that holds its generator, cell edges thin and white, region borders dark.

    plot_geojson_cells.py CELLS.geojson REGIONS.geojson OUT.png [TITLE]

REGIONS.geojson: one Polygon or MultiPolygon feature per region (us_kentucky_counties.geojson).
"{cells}" in TITLE becomes the number of cells. The PNG has 128 colours (a fifth of the bytes,
as the README shows it). Needs matplotlib and shapely (Debian: python3-matplotlib
python3-shapely)."""
import io
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PatchCollection
from matplotlib.patches import Polygon as Patch
from PIL import Image
from shapely.geometry import Point, shape
from shapely.prepared import prep

cells_file, regions_file, out = sys.argv[1:4]
cells = json.load(open(cells_file))["features"]
title = sys.argv[4].replace("{cells}", str(len(cells))) if len(sys.argv) > 4 else ""
regions = [shape(f["geometry"]) for f in json.load(open(regions_file))["features"]]
prepared = [(g.bounds, prep(g)) for g in regions]
palette = plt.get_cmap("tab20").colors + plt.get_cmap("tab20b").colors


def region_of(point):
    """The first region that holds the point (on a border, either)."""
    for i, ((x0, y0, x1, y1), g) in enumerate(prepared):
        if x0 <= point.x <= x1 and y0 <= point.y <= y1 and g.intersects(point):
            return i
    return 0


patches, colours = [], []
for f in cells:
    g = shape(f["geometry"])
    r = region_of(Point(*f["properties"]["generator"]))
    for p in getattr(g, "geoms", [g]):
        patches.append(Patch(list(p.exterior.coords), closed=True))
        colours.append(palette[(7 * r) % len(palette)])
fig, ax = plt.subplots(figsize=(12, 5.2), dpi=110)
ax.add_collection(PatchCollection(patches, facecolor=colours, edgecolor="white", linewidth=0.25))
for g in regions:
    for p in getattr(g, "geoms", [g]):
        x, y = p.exterior.xy
        ax.plot(x, y, color="#202020", linewidth=0.6)
ax.set_aspect("equal")
ax.autoscale_view()
ax.set_axis_off()
if title:
    ax.set_title(title, fontsize=10)
fig.tight_layout()
png = io.BytesIO()
fig.savefig(png, format="png")
image = Image.open(png).convert("RGB")
image.quantize(128, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE).save(out, optimize=True)
print(f"{out}: {len(cells)} cells in {len(regions)} regions")
