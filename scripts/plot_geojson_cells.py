#!/usr/bin/env python3
# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""Draws cvt2's GeoJSON cells as a GIS would: each cell filled with the colour of the region
(county) that holds its generator, cell edges thin and white, region borders dark.

    plot_geojson_cells.py CELLS.geojson REGIONS.geojson OUT.png

REGIONS.geojson: one Polygon or MultiPolygon feature per region (us_kentucky_counties.geojson).
The picture is 1320 pixels wide, drawn at twice that and scaled down (smooth edges), in 128
colours. Needs only Pillow (Debian: python3-pil), so that the README's first command installs
little."""
import json
import sys

from PIL import Image, ImageDraw

cells_file, regions_file, out = sys.argv[1:4]
width, margin, supersample = 1320, 20, 2
# matplotlib's tab20 and tab20b, as the GIS pictures of this project have them.
palette = """1f77b4 aec7e8 ff7f0e ffbb78 2ca02c 98df8a d62728 ff9896 9467bd c5b0d5 8c564b c49c94
e377c2 f7b6d2 7f7f7f c7c7c7 bcbd22 dbdb8d 17becf 9edae5 393b79 5254a3 6b6ecf 9c9ede 637939 8ca252
b5cf6b cedb9c 8c6d31 bd9e39 e7ba52 e7cb94 843c39 ad494a d6616b e7969c 7b4173 a55194 ce6dbd
de9ed6""".split()


def polygons(geometry):
    """The rings of each polygon of a Polygon or MultiPolygon, exterior first."""
    if geometry["type"] == "Polygon":
        return [geometry["coordinates"]]
    return geometry["coordinates"]


def contains(rings, x, y):
    """Whether (x, y) is inside the polygon with these rings (even-odd rule, so holes count)."""
    inside = False
    for ring in rings:
        for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]):
            if (y0 > y) != (y1 > y) and x < x0 + (y - y0) * (x1 - x0) / (y1 - y0):
                inside = not inside
    return inside


cells = json.load(open(cells_file))["features"]
regions = []  # (bounding box, polygons) of each region
for f in json.load(open(regions_file))["features"]:
    ps = polygons(f["geometry"])
    xs = [p[0] for poly in ps for p in poly[0]]
    ys = [p[1] for poly in ps for p in poly[0]]
    regions.append(((min(xs), min(ys), max(xs), max(ys)), ps))


def distance(rings, x, y):
    """The distance from (x, y) to the rings' edges."""
    d = float("inf")
    for ring in rings:
        for (x0, y0), (x1, y1) in zip(ring, ring[1:] + ring[:1]):
            dx, dy = x1 - x0, y1 - y0
            t = max(0.0, min(1.0, ((x - x0) * dx + (y - y0) * dy) / (dx * dx + dy * dy or 1.0)))
            d = min(d, ((x0 + t * dx - x) ** 2 + (y0 + t * dy - y) ** 2) ** 0.5)
    return d


def region_of(x, y):
    """The first region that holds (x, y); for a point on borders (the even-odd rule may put it
    in none), the nearest."""
    near = []
    for i, ((x0, y0, x1, y1), ps) in enumerate(regions):
        if x0 <= x <= x1 and y0 <= y <= y1:
            if any(contains(rings, x, y) for rings in ps):
                return i
            near.append((min(distance(rings, x, y) for rings in ps), i))
    return min(near)[1] if near else 0


x0 = min(b[0] for b, _ in regions)
y0 = min(b[1] for b, _ in regions)
x1 = max(b[2] for b, _ in regions)
y1 = max(b[3] for b, _ in regions)
scale = supersample * (width - 2 * margin) / (x1 - x0)
height = round((y1 - y0) * scale / supersample) + 2 * margin


def pixels(ring):
    m = supersample * margin
    return [(m + (x - x0) * scale, m + (y1 - y) * scale) for x, y, *_ in ring]


image = Image.new("RGB", (width * supersample, height * supersample), "white")
draw = ImageDraw.Draw(image)
for f in cells:
    colour = "#" + palette[(7 * region_of(*f["properties"]["generator"])) % len(palette)]
    for rings in polygons(f["geometry"]):
        draw.polygon(pixels(rings[0]), fill=colour, outline="white", width=1)
for _, ps in regions:
    for rings in ps:
        for ring in rings:
            draw.line(pixels(ring + ring[:1]), fill="#202020", width=2 * supersample - 1)
image = image.resize((width, height), Image.Resampling.LANCZOS)
image.quantize(128, method=Image.Quantize.FASTOCTREE, dither=Image.Dither.NONE).save(out, optimize=True)
print(f"{out}: {len(cells)} cells in {len(regions)} regions")
