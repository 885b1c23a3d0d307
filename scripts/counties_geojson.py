#!/usr/bin/env python3
"""counties_geojson.py - one state's counties as a GeoJSON FeatureCollection in the
projected coordinates of the .poly/.wkt that to_poly.py made from the same state.

  counties_geojson.py COUNTIES.geojson STATE.geojson OUT.geojson [--poly BASE.poly] [--check]

COUNTIES.geojson: `node topojson_to_geojson.cjs counties-10m.json counties OUT` (us-atlas).
STATE.geojson:    `node topojson_to_geojson.cjs counties-10m.json --us-state NAME OUT`, the
                  file given to `to_poly.py --project`; the state's FIPS code (its feature id)
                  selects the counties, and phi_m is computed from it exactly as to_poly.py
                  does (middle of the latitude range of its polygons and lines).
Projection and cleaning repeat to_poly.py: x = lon * cos(phi_m), y = lat, rounded to 6
decimals (+0.0), then per ring: closing point and consecutive duplicates removed, spikes
(a, b, a) removed, degenerate rings dropped, outer rings counter-clockwise, holes clockwise
(RFC 7946).  The conversion uses the standard library only.

--poly: compare with the .poly (projection line, vertex set, edge set).
--check: shapely checks (validity, union vs the .wkt domain next to --poly); needs shapely.
"""
import json
import math
import sys

DIGITS = 6


def ring_area(r):
    n = len(r)
    return 0.5 * sum(r[i][0] * r[(i + 1) % n][1] - r[(i + 1) % n][0] * r[i][1] for i in range(n))


def clean_ring(r, stats):
    """As to_poly.clean_ring: open ring without repeats or spikes, or None."""
    r = list(r)
    if len(r) > 1 and r[0] == r[-1]:
        r.pop()
    out = []
    for p in r:
        if not out or out[-1] != p:
            out.append(p)
        else:
            stats["repeated consecutive points removed"] = stats.get("repeated consecutive points removed", 0) + 1
    while len(out) > 1 and out[0] == out[-1]:
        out.pop()
        stats["repeated consecutive points removed"] = stats.get("repeated consecutive points removed", 0) + 1
    changed = True
    while changed and len(out) >= 3:
        changed = False
        n = len(out)
        for i in range(n):
            if out[(i - 1) % n] == out[(i + 1) % n]:
                for idx in sorted((i, (i + 1) % n), reverse=True):
                    del out[idx]
                stats["spikes removed"] = stats.get("spikes removed", 0) + 1
                changed = True
                break
    if len(out) < 3 or ring_area(out) == 0.0:
        stats["degenerate rings dropped"] = stats.get("degenerate rings dropped", 0) + 1
        return None
    return out


def polygons_of(g):
    if g is None:
        return []
    if g["type"] == "Polygon":
        return [g["coordinates"]]
    if g["type"] == "MultiPolygon":
        return g["coordinates"]
    raise ValueError("unexpected geometry " + g["type"])


def state_lat0(state):
    """phi_m as to_poly.py --project computes it: polygons, lines and points of the file."""
    lats = []

    def walk(g):
        t, c = g["type"], g.get("coordinates")
        if t == "Polygon":
            lats.extend(float(q[1]) for r in c for q in r)
        elif t == "MultiPolygon":
            lats.extend(float(q[1]) for p in c for r in p for q in r)
        elif t == "LineString":
            lats.extend(float(q[1]) for q in c)
        elif t == "MultiLineString":
            lats.extend(float(q[1]) for l in c for q in l)
        elif t == "Point":
            lats.append(float(c[1]))
        elif t == "MultiPoint":
            lats.extend(float(q[1]) for q in c)
        elif t == "GeometryCollection":
            for h in g["geometries"]:
                walk(h)
    for f in state["features"]:
        if f["geometry"]:
            walk(f["geometry"])
    return 0.5 * (min(lats) + max(lats))


def convert(counties, state):
    st = next(f for f in state["features"] if f["geometry"]["type"] in ("Polygon", "MultiPolygon"))
    fips = str(st["id"])
    lat0 = state_lat0(state)
    c = math.cos(math.radians(lat0))
    rd = lambda q: (round(float(q[0]) * c, DIGITS) + 0.0, round(float(q[1]), DIGITS) + 0.0)
    stats, feats = {}, []
    for f in counties["features"]:
        cid = str(f.get("id"))
        if cid[:2] != fips:
            continue
        polys = []
        for p in polygons_of(f["geometry"]):
            outer = clean_ring([rd(q) for q in p[0]], stats)
            if outer is None:
                continue
            if ring_area(outer) < 0:
                outer = outer[:1] + outer[:0:-1]
            rings = [outer]
            for h in p[1:]:
                h = clean_ring([rd(q) for q in h], stats)
                if h is None:
                    continue
                if ring_area(h) > 0:
                    h = h[:1] + h[:0:-1]
                rings.append(h)
            polys.append([[list(q) for q in r + r[:1]] for r in rings])
        if not polys:
            stats["counties without a polygon left"] = stats.get("counties without a polygon left", 0) + 1
            continue
        geom = ({"type": "Polygon", "coordinates": polys[0]} if len(polys) == 1
                else {"type": "MultiPolygon", "coordinates": polys})
        props = {}
        name = (f.get("properties") or {}).get("name")
        if name is not None:
            props["name"] = name
        feats.append({"type": "Feature", "id": cid, "properties": props, "geometry": geom})
    feats.sort(key=lambda f: f["id"])
    fc = {"type": "FeatureCollection",
          "description": "%s counties (FIPS %s), projected: x = lon * cos(%s deg), y = lat (degrees),"
                         " rounded to %d decimals, as the .poly/.wkt of the same name"
                         % (st["properties"].get("name"), fips, round(lat0, 6), DIGITS),
          "features": feats}
    return fc, lat0, stats


def read_poly(path):
    toks, comments = [], []
    for raw in open(path):
        if raw.startswith("#"):
            comments.append(raw)
        s = raw.split("#", 1)[0].split()
        if s:
            toks.append(s)
    nv = int(toks[0][0])
    verts = [(float(t[1]), float(t[2])) for t in toks[1:1 + nv]]
    ns = int(toks[1 + nv][0])
    segs = [(int(t[1]) - 1, int(t[2]) - 1, int(t[3])) for t in toks[2 + nv:2 + nv + ns]]
    return verts, segs, comments


def compare_poly(fc, lat0, path):
    verts, segs, comments = read_poly(path)
    proj = [l for l in comments if "projection" in l]
    hdr = proj[0].split("cos(")[1].split(" deg")[0] if proj else None
    print("phi_m: computed %r, .poly header %s, match %s" % (lat0, hdr, hdr is not None and float(hdr) == round(lat0, 6)))
    cverts, cedges = set(), {}
    for f in fc["features"]:
        for p in polygons_of(f["geometry"]):
            for r in p:
                for a, b in zip(r, r[1:]):
                    a, b = tuple(a), tuple(b)
                    cverts.add(a)
                    k = (min(a, b), max(a, b))
                    cedges[k] = cedges.get(k, 0) + 1
    pverts = set(verts)
    pedges = {}
    for a, b, m in segs:
        k = (min(verts[a], verts[b]), max(verts[a], verts[b]))
        pedges[k] = m
    print("vertices: counties %d distinct, .poly %d; only in counties %d, only in .poly %d"
          % (len(cverts), len(pverts), len(cverts - pverts), len(pverts - cverts)))
    once = {k for k, n in cedges.items() if n == 1}
    twice = {k for k, n in cedges.items() if n == 2}
    more = {k for k, n in cedges.items() if n > 2}
    pb = {k for k, m in pedges.items() if m in (1, 2)}
    pc = {k for k, m in pedges.items() if m == 3}
    print("edges used by 1 county: %d (.poly boundary segments %d, equal sets: %s)" % (len(once), len(pb), once == pb))
    print("edges shared by 2 counties: %d (.poly inner constraint segments %d, equal sets: %s)" % (len(twice), len(pc), twice == pc))
    if more:
        print("edges used by more than 2 counties: %d" % len(more))


def shapely_check(fc, wkt_path):
    from shapely.geometry import shape
    from shapely.ops import unary_union
    from shapely import wkt as swkt
    from shapely.validation import explain_validity
    geoms, bad = [], []
    for f in fc["features"]:
        g = shape(f["geometry"])
        if not g.is_valid:
            bad.append((f["properties"].get("name"), explain_validity(g)))
        geoms.append(g)
    print("counties: %d (%s)" % (len(geoms), ", ".join("%s %d" % (t, sum(1 for f in fc["features"] if f["geometry"]["type"] == t)) for t in ("Polygon", "MultiPolygon"))))
    print("invalid county geometries: %d %s" % (len(bad), bad if bad else ""))
    # overlaps between counties (area of pairwise intersections)
    ov = 0.0
    boxes = [g.bounds for g in geoms]
    for i, g in enumerate(geoms):
        for j in range(i + 1, len(geoms)):
            a, b = boxes[i], boxes[j]
            if a[0] <= b[2] and b[0] <= a[2] and a[1] <= b[3] and b[1] <= a[3]:
                ov += g.intersection(geoms[j]).area
    print("total area of pairwise county overlaps: %.3g" % ov)
    u = unary_union(geoms)
    parts = list(u.geoms) if u.geom_type == "MultiPolygon" else [u]
    print("union: %s, %d polygons, %d holes, valid %s" % (u.geom_type, len(parts), sum(len(p.interiors) for p in parts), u.is_valid))
    dom = swkt.loads(open(wkt_path).read().split("\n")[0])
    print("domain (.wkt line 1): %s, %d polygons, valid %s" % (dom.geom_type, len(getattr(dom, "geoms", [dom])), dom.is_valid))
    print("area: union %.12f, domain %.12f, difference %.3g (relative %.3g); sum of county areas %.12f"
          % (u.area, dom.area, u.area - dom.area, (u.area - dom.area) / dom.area, sum(g.area for g in geoms)))
    print("symmetric difference area: %.3g; union equals domain exactly (topologically): %s"
          % (u.symmetric_difference(dom).area, u.equals(dom)))


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    poly = None
    if "--poly" in argv:
        poly = argv[argv.index("--poly") + 1]
        args.remove(poly)
    counties_path, state_path, out = args
    fc, lat0, stats = convert(json.load(open(counties_path)), json.load(open(state_path)))
    with open(out, "w") as f:
        json.dump(fc, f, separators=(",", ":"))
        f.write("\n")
    print("%s: %d features, phi_m %r, cleaning %s" % (out, len(fc["features"]), lat0, stats or "none"))
    if poly:
        compare_poly(fc, lat0, poly)
    if "--check" in argv:
        shapely_check(fc, poly[:-len(".poly")] + ".wkt")


if __name__ == "__main__":
    main(sys.argv[1:])
