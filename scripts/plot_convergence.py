#!/usr/bin/env python3
# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""plot_convergence.py CSV [OUT.svg]: the energy against time of each method, one panel a case.

Reads the CSV that benchmarks/lbfgs_benchmark writes with CVT_2_CONVERGENCE_CSV=path (columns
case,method,evaluation,seconds,normalized_energy) and writes an SVG (default convergence.svg):
E_norm - 1 on a log scale against seconds, where E_norm = E n / A^2 / (5/(18 sqrt 3)) is 1 for
the hexagonal tiling, so E_norm - 1 is the gap to that bound. Python's standard library only.
"""
import csv
import math
import sys
from collections import OrderedDict
from xml.sax.saxutils import escape

METHODS = {  # name in the CSV: (legend, colour, dash pattern)
    "lloyd": ("Lloyd (lloyd_optimize_2)", "#1f77b4", ""),
    "lbfgs": ("L-BFGS (lbfgs_optimize_2)", "#d62728", ""),
    "cgal_lloyd_optimize_mesh_2": ("CGAL lloyd_optimize_mesh_2 (its sizing)", "#7f7f7f", "6,3"),
    "cgal_uniform_sizing": ("CGAL optimizer, uniform sizing", "#2ca02c", "2,2"),
}
OTHER_COLOURS = ["#9467bd", "#8c564b", "#e377c2", "#bcbd22", "#17becf"]
DOMAINS = {"unit_square": "unit square", "us_massachusetts_counties": "Massachusetts counties"}
SUPERSCRIPT = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")

PANEL_W, PANEL_H = 470, 330  # one case
LEFT, RIGHT, TOP, BOTTOM = 62, 14, 30, 46  # plot margins inside a panel
LEGEND_H = 26
FONT = 'font-family="DejaVu Sans, Arial, Helvetica, sans-serif"'


def read(path):
    """{case: {method: [(seconds, normalized_energy), ...]}} in the file's order."""
    cases = OrderedDict()
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            series = cases.setdefault(row["case"], OrderedDict()).setdefault(row["method"], [])
            series.append((float(row["seconds"]), float(row["normalized_energy"])))
    return cases


def case_title(case):
    """'unit_square/10000' -> 'unit square, N = 10⁴'."""
    domain, _, n = case.partition("/")
    title = DOMAINS.get(domain, domain.replace("_", " "))
    if n.isdigit():
        k = int(n)
        exponent = round(math.log10(k)) if k > 0 else 0
        title += ", N = " + ("10" + str(exponent).translate(SUPERSCRIPT) if 10**exponent == k else n)
    return title


def nice_step(span, ticks=5):
    """A step of 1, 2 or 5 times a power of ten giving about `ticks` intervals over `span`."""
    raw = span / ticks
    power = 10 ** math.floor(math.log10(raw))
    return next(m * power for m in (1, 2, 5, 10) if m * power >= raw)


def round_125(x, down):
    """The nearest of 1, 2, 5 times a power of ten below (down) or above x."""
    power = 10 ** math.floor(math.log10(x))
    marks = [m * power for m in (1, 2, 5, 10)]
    return max(v for v in marks if v <= x * (1 + 1e-9)) if down else min(v for v in marks if v >= x * (1 - 1e-9))


def number(x):
    return f"{x:g}"


def panel(x0, case, methods, style):
    """SVG elements of one case's panel with its top-left corner at (x0, 0)."""
    points = {m: [(t, e - 1) for t, e in s if e > 1] for m, s in methods.items()}
    dropped = sum(len(s) for s in methods.values()) - sum(len(p) for p in points.values())
    if dropped:
        print(f"plot_convergence: {case}: {dropped} samples with E_norm <= 1 left out", file=sys.stderr)
    gaps = [g for p in points.values() for _, g in p]
    times = [t for p in points.values() for t, _ in p]
    if not gaps:
        return []
    t_max = max(times) or 1
    step = nice_step(t_max)
    t_max = math.ceil(t_max / step - 1e-9) * step
    lo, hi = math.log10(round_125(min(gaps), down=True)), math.log10(round_125(max(gaps), down=False))
    hi = max(hi, lo + 1)
    w, h = PANEL_W - LEFT - RIGHT, PANEL_H - TOP - BOTTOM
    px = lambda t: x0 + LEFT + w * t / t_max
    py = lambda g: TOP + h * (hi - math.log10(g)) / (hi - lo)
    out = [f'<text x="{x0 + LEFT + w / 2}" y="{TOP - 10}" text-anchor="middle" font-size="14" '
           f'font-weight="bold">{escape(case_title(case))}</text>']
    # Grid and ticks at 1..9 times the powers of ten: 1, 2 and 5 labelled (1 only over many decades).
    for d in range(math.floor(lo), math.ceil(hi) + 1):
        for m in range(1, 10):
            g = m * 10.0**d
            if not lo - 1e-9 <= math.log10(g) <= hi + 1e-9:
                continue
            y = py(g)
            major = m == 1
            label = major or (hi - lo <= 2.5 and m in (2, 5))
            out.append(f'<line x1="{x0 + LEFT}" x2="{x0 + LEFT + w}" y1="{y:.1f}" y2="{y:.1f}" '
                       f'stroke="{"#cccccc" if major else "#eeeeee"}"/>')
            out.append(f'<line x1="{x0 + LEFT - (6 if major else 3)}" x2="{x0 + LEFT}" y1="{y:.1f}" '
                       f'y2="{y:.1f}" stroke="black"/>')
            if label:
                out.append(f'<text x="{x0 + LEFT - 8}" y="{y + 4:.1f}" text-anchor="end" '
                           f'font-size="11">{number(g)}</text>')
    k = 0
    while k * step <= t_max + 1e-9:
        x = px(k * step)
        out.append(f'<line x1="{x:.1f}" x2="{x:.1f}" y1="{TOP}" y2="{TOP + h}" stroke="#eeeeee"/>')
        out.append(f'<line x1="{x:.1f}" x2="{x:.1f}" y1="{TOP + h}" y2="{TOP + h + 5}" stroke="black"/>')
        out.append(f'<text x="{x:.1f}" y="{TOP + h + 18}" text-anchor="middle" font-size="11">'
                   f'{number(round(k * step, 10))}</text>')
        k += 1
    out.append(f'<rect x="{x0 + LEFT}" y="{TOP}" width="{w}" height="{h}" fill="none" stroke="black"/>')
    out.append(f'<text x="{x0 + LEFT + w / 2}" y="{PANEL_H - 8}" text-anchor="middle" '
               f'font-size="12">time (s)</text>')
    cy = TOP + h / 2
    out.append(f'<text x="{x0 + 14}" y="{cy}" text-anchor="middle" font-size="12" '
               f'transform="rotate(-90 {x0 + 14} {cy})">E_norm − 1 (log scale)</text>')
    # The series, each ending in a dot where the method stopped.
    for m, p in points.items():
        if not p:
            continue
        _, colour, dash = style[m]
        coords = " ".join(f"{px(t):.1f},{py(g):.1f}" for t, g in p)
        dash_attr = f' stroke-dasharray="{dash}"' if dash else ""
        out.append(f'<polyline points="{coords}" fill="none" stroke="{colour}" stroke-width="1.8"'
                   f'{dash_attr} stroke-linejoin="round"/>')
        t, g = p[-1]
        out.append(f'<circle cx="{px(t):.1f}" cy="{py(g):.1f}" r="3" fill="{colour}"/>')
    return out


def main(argv):
    if len(argv) not in (2, 3) or argv[1] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    cases = read(argv[1])
    if not cases:
        print(f"plot_convergence: no rows in {argv[1]}", file=sys.stderr)
        return 1
    out_path = argv[2] if len(argv) == 3 else "convergence.svg"
    methods = list(OrderedDict((m, None) for c in cases.values() for m in c))
    style, others = {}, iter(OTHER_COLOURS * 4)
    for m in methods:
        style[m] = METHODS.get(m, (m, next(others), ""))
    width, height = PANEL_W * len(cases), PANEL_H + LEGEND_H + 6
    body = []
    for i, (case, series) in enumerate(cases.items()):
        body += panel(i * PANEL_W, case, series, style)
    # The legend: one row under the panels.
    x, y = LEFT, PANEL_H + 14
    for m in methods:
        label, colour, dash = style[m]
        dash_attr = f' stroke-dasharray="{dash}"' if dash else ""
        body.append(f'<line x1="{x}" x2="{x + 28}" y1="{y}" y2="{y}" stroke="{colour}" '
                    f'stroke-width="2"{dash_attr}/>')
        body.append(f'<text x="{x + 34}" y="{y + 4}" font-size="12">{escape(label)}</text>')
        x += 34 + 7 * len(label) + 24
    width = max(width, x)
    svg = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'viewBox="0 0 {width} {height}" {FONT}>\n'
           f'<rect width="100%" height="100%" fill="white"/>\n' + "\n".join(body) + "\n</svg>\n")
    with open(out_path, "w", encoding="utf-8") as f:
        f.write(svg)
    print(f"plot_convergence: {out_path} ({len(cases)} cases, {len(methods)} methods)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
