# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
"""cvt2: centroidal Voronoi tessellations of 2D domains with constraints.

The Python face of the CVT_2 C++ library and its ``cvt2`` program: the same algorithms, called
the same way, so that the same domain, points and options give the same bits.

A *domain* is a polygon with holes and inner constraints (lines that cells do not cross),
read from a file (:meth:`Domain.from_file`), from shapely geometries
(:meth:`Domain.from_shapely`) or from Triangle's arrays (:class:`Domain`). Its *generators* are
the points given, plus the domain's own vertices (constrained generators, which never move).

- :func:`random_points` draws initial generators, as ``cvt2 DOMAIN -n N --seed S`` does;
- :func:`optimize` moves them to a centroidal Voronoi tessellation by L-BFGS or Lloyd
  iteration, as ``cvt2`` does, under a uniform, automatic (``"lipschitz"``) or Python density;
- :func:`bounded_voronoi` gives the bounded Voronoi diagram of a domain and points with the
  names of ``scipy.spatial.Voronoi`` (``points``, ``vertices``, ``regions``, ``point_region``,
  ``ridge_points``, ``ridge_vertices``), no -1 anywhere, and what scipy lacks: the constraint
  under each ridge, cell areas and centroids, valid shapely geometries, GeoJSON, VTU and
  MODFLOW 6 DISV files;
- :func:`natural_neighbours` gives the natural-neighbour (Sibson or Laplace) coordinates of
  query points on that diagram as a sparse matrix: ``M @ values`` interpolates values given at
  the generators, never across a constraint.

Errors in the input raise :class:`ParseError` or :class:`DomainError` (both ValueError) with the
library's message, which names the file and line or the row of the offending item.

Example::

    import cvt2
    from shapely.geometry import Polygon
    domain = cvt2.Domain.from_shapely(Polygon([(0, 0), (1, 0), (1, 1), (0, 1)]))
    result = cvt2.optimize(domain, cvt2.random_points(domain, 500))
    diagram = result.bounded_voronoi()
    cells = diagram.to_shapely()
"""

from __future__ import annotations

import errno
import functools
import math
import os

import numpy as np

from . import _cvt2
from ._cvt2 import DomainError, ParseError, __version__

__all__ = [
    "BoundedVoronoi",
    "ConstraintEditor",
    "CsrMatrix",
    "Domain",
    "DomainError",
    "OptimizeResult",
    "ParseError",
    "__version__",
    "bounded_voronoi",
    "conforming_sites",
    "natural_neighbours",
    "optimize",
    "random_points",
]

ParseError.__doc__ = (
    "A domain file that cannot be read: the message says file:line: what (near 'token'); "
    "attributes file, line (0: none) and token. A ValueError."
)
DomainError.__doc__ = (
    "Input that does not make a valid domain or valid generators: crossing segments, a point "
    "outside the domain or not finite, a density not positive; the message says where. "
    "Attribute index: the row of the offending point, or None. A ValueError."
)

_HEXAGON_ENERGY = 5 / (18 * 3**0.5)  # E N / A^2 of the regular hexagonal tiling (Gersho)


class Domain:
    """A planar domain: polygons with holes, inner constraints (segments that cells do not
    cross), and possibly generators of its own. It holds the description only: each call
    (:func:`random_points`, :func:`optimize`, :func:`bounded_voronoi`) builds its own
    triangulation from it, so a domain can be used any number of times.

    ``Domain(vertices, segments, holes=None)`` takes the arrays of Triangle's ``.poly`` format,
    as the ``triangle`` package does:

    - ``vertices``: float array (V, 2); a vertex on no segment is a generator;
    - ``segments``: integer array (S, 2), rows of vertex indices; the domain is what they
      enclose (Triangle's rule: a face is in the domain unless it can be reached from outside or
      from a hole point without crossing a segment), and segments inside it are inner
      constraints;
    - ``holes``: float array (H, 2), or None: one point inside each hole.

    Errors name the row: ``<arrays>:ROW: segment (0, 0) - (1, 1) crosses ...`` (rows from 0).

    Attributes: ``format`` (``"arrays"``, ``"poly"``, ``"wkt"``, ``"geojson"``, ``"shapely"``),
    ``source``, ``area``, ``bounds`` (xmin, ymin, xmax, ymax), and the description as arrays:
    ``vertices``, ``segments`` (what :attr:`BoundedVoronoi.ridge_constraint` indexes),
    ``segment_items``, ``holes``, ``generators``.
    """

    def __init__(self, vertices, segments, holes=None):
        self._impl = _cvt2.Domain.from_arrays(vertices, segments, holes)

    @classmethod
    def _wrap(cls, impl):
        d = cls.__new__(cls)
        d._impl = impl
        return d

    @classmethod
    def from_file(cls, path) -> "Domain":
        """The domain of a file, by its extension, as the ``cvt2`` program reads it:

        - ``.poly``: Triangle's format (vertices, segments, holes; vertices on no segment are
          generators);
        - ``.wkt``: one geometry a line: POLYGON and MULTIPOLYGON are the domain (their union
          minus their holes), LINESTRING and MULTILINESTRING inner constraints, POINT and
          MULTIPOINT generators;
        - ``.geojson`` (or ``.json``): the same by geometry type, in features.

        Raises FileNotFoundError (IsADirectoryError for a directory), or ParseError /
        DomainError naming the file and line or feature.
        """
        path = os.fspath(path)
        if os.path.isdir(path):
            raise IsADirectoryError(errno.EISDIR, "a directory, not a domain file", path)
        if not os.path.isfile(path):
            raise FileNotFoundError(errno.ENOENT, "no such domain file", path)
        return cls._wrap(_cvt2.Domain.from_file(path))

    @classmethod
    def from_shapely(cls, geometry, constraints=None) -> "Domain":
        """The domain of a shapely geometry, as ``cvt2`` reads the same geometry from a WKT or
        GeoJSON file (the same doubles give the same bits).

        - ``geometry``: a Polygon or MultiPolygon (the union of its polygons minus their holes);
          coordinates are taken as planar (project geographic data first); a third coordinate
          is ignored.
        - ``constraints``: None, or a list of LineString, LinearRing or MultiLineString: inner
          constraints, which cells do not cross (county borders, faults, rivers). They may end
          inside the domain, meet each other at their ends or run along the boundary, but not
          cross each other or the boundary. Empty geometries are skipped.

        Errors name the geometry: ``<shapely>: constraints[2]: this geometry crosses itself or an
        earlier one``. In :attr:`segment_items`, 0 is the polygon, k + 1 is ``constraints[k]``.
        """
        polygons = []
        kind = getattr(geometry, "geom_type", None)
        if kind is not None and geometry.is_empty:
            raise DomainError("<shapely>: the domain is empty")
        if kind == "Polygon":
            parts = [geometry]
        elif kind == "MultiPolygon":
            parts = list(geometry.geoms)
        else:
            raise TypeError(
                f"the domain must be a shapely Polygon or MultiPolygon, not {type(geometry).__name__}"
            )
        for p in parts:
            if p.is_empty:
                continue
            rings = [p.exterior] + list(p.interiors)
            polygons.append([np.asarray(r.coords, dtype=float)[:, :2] for r in rings])
        if not polygons:
            raise DomainError("<shapely>: the domain is empty")
        if constraints is None:
            constraints = []
        elif getattr(constraints, "geom_type", None) is not None:
            constraints = [constraints]
        lines, items = [], []
        for k, c in enumerate(constraints):
            kind = getattr(c, "geom_type", None)
            if kind is not None and c.is_empty:
                continue  # no line (shapely 1.8 calls an empty LineString a GeometryCollection)
            if kind in ("LineString", "LinearRing"):
                parts = [c]
            elif kind == "MultiLineString":
                parts = list(c.geoms)
            else:
                raise TypeError(
                    f"constraints[{k}] must be a shapely LineString, LinearRing or "
                    f"MultiLineString, not {type(c).__name__}"
                )
            for part in parts:
                if not part.is_empty:
                    lines.append(np.asarray(part.coords, dtype=float)[:, :2])
                    items.append(k)
        return cls._wrap(_cvt2.Domain.from_shapely(polygons, lines, items))

    @property
    def format(self) -> str:
        """Where the description came from: ``arrays``, ``poly``, ``wkt``, ``geojson``, ``shapely``."""
        return self._impl.format

    @property
    def source(self) -> str:
        """The file, or ``<arrays>``, ``<shapely>``: how messages name it."""
        return self._impl.source

    @property
    def area(self) -> float:
        """The domain's area."""
        return self._impl.area

    @property
    def bounds(self) -> tuple:
        """(xmin, ymin, xmax, ymax) of the domain."""
        return self._impl.bounds

    @property
    def notes(self) -> list:
        """Points of the file that repeat earlier ones (they are merged), and segments that lie on
        earlier ones (``ridge_constraint`` names the shared part by the earlier one's item), as
        ``cvt2`` notes them."""
        return self._impl.notes

    @functools.cached_property
    def _arrays(self):
        return self._impl.arrays()

    @property
    def vertices(self) -> np.ndarray:
        """(V, 2) float: the vertices of the description (for a WKT, GeoJSON or shapely domain,
        the points of its rings and lines, each once)."""
        return self._arrays["vertices"]

    @property
    def segments(self) -> np.ndarray:
        """(S, 2) int: the input segments, as rows of :attr:`vertices`: a ``.poly`` file's or the
        arrays' segments in order; for WKT, GeoJSON and shapely domains each polygon's exterior
        and hole rings, then each line, segment after segment. :attr:`BoundedVoronoi.ridge_constraint`
        gives rows of this array."""
        return self._arrays["segments"]

    @property
    def segment_items(self) -> np.ndarray:
        """(S,) int: the input item each segment comes from: its own row (``.poly``, arrays), the
        line of its geometry (``.wkt``), its feature from 1 (``.geojson``), or 0 for the polygon
        and k + 1 for ``constraints[k]`` (shapely). A domain made by :meth:`resample` (or slid
        by ``optimize(..., boundary="slide")``) gives each chord the item of the input line it
        replaces (for a ``.poly`` file, the segment of its stretch nearest to its middle)."""
        return self._arrays["segment_items"]

    @property
    def holes(self) -> np.ndarray:
        """(H, 2) float: the hole points of a ``.poly`` or arrays domain."""
        return self._arrays["holes"]

    @property
    def generators(self) -> np.ndarray:
        """(G, 2) float: the description's own generators (``.poly`` vertices on no segment,
        WKT and GeoJSON points), which every call inserts before the points it is given."""
        return self._arrays["generators"]

    @property
    def own_cells(self) -> int:
        """How many cells the domain's own vertices and generators have (those on or in the
        domain): what :func:`random_points` subtracts from ``cells``."""
        return self._impl.own_cells

    #: What :meth:`resample` did (a dict), or None for a domain it did not make.
    resampling = None

    def resample(
        self,
        *,
        cells=None,
        size=None,
        deviation_bound=None,
        corner_angle=30.0,
        fixed_points=None,
        minimum_ring_area=0.0,
        spacing_ratio=None,
    ) -> "Domain":
        """A new domain, its polylines resampled to a cell size, so that a finely digitised
        boundary does not give a speck of a cell at each of its vertices (``cvt2 --boundary
        resample``). Each polyline (rings, holes, inner constraints) is cut at its features,
        which stay: junctions, ends of open lines, ``fixed_points``, and corners (a turn of more
        than ``corner_angle`` degrees seen a cell size away on either side); between them its
        vertices are replaced by points on it about ``spacing_ratio`` cell sizes apart (default
        2: a generator on the domain's boundary has half a cell, which then has an inner cell's
        area; ``cvt2 --boundary-spacing``), never more points than it had. An input vertex is
        kept where a chord would leave the input by more than ``deviation_bound`` (default a
        quarter of the size) or change the topology (cross a
        line, cut off a point or a generator). Generators and the domain's marks stay. A ring
        (a closed line meeting no other, with no fixed point) enclosing less than
        ``minimum_ring_area`` goes, with the lines and generators inside it: an island is
        dropped, a hole filled (``cvt2 --minimum-ring-area``; default 0: none).

        - ``size``: the cell size ``H``, the spacing of a hexagonal tiling (a cell of area
          ``sqrt(3)/2 H**2``); or
        - ``cells``: how many cells in all: the size ``H`` that solves
          ``area / (sqrt(3)/2 H**2) + boundary_length (2 - s) / (2 s H) = cells`` for the
          spacing ratio ``s`` (at the default 2, ``area / (sqrt(3)/2 H**2) = cells``); then
          ``random_points(d, cells=cells)`` fills the domain up to that count.

        The new domain is described by arrays (:attr:`vertices`, :attr:`segments`,
        :attr:`holes`); its ``resampling`` is a dict: ``size``, ``spacing_ratio``,
        ``deviation_bound``, ``input_vertices``,
        ``output_vertices``, ``features``, ``corners``, ``runs``, ``kept_for_deviation``,
        ``kept_for_topology``, ``rings_dropped``, ``generators_dropped``, ``max_deviation``
        (the largest distance from an input vertex to
        the new polylines), ``area_before``, ``area_after``.
        """
        if (cells is None) == (size is None):
            raise TypeError("give one of cells and size")
        impl, report = self._impl.resample(
            None if cells is None else _count(cells, "cells"),
            None if size is None else float(size),
            None if deviation_bound is None else float(deviation_bound),
            float(corner_angle),
            fixed_points,
            float(minimum_ring_area),
            None if spacing_ratio is None else float(spacing_ratio),
        )
        d = Domain._wrap(impl)
        d.resampling = report
        return d

    def cells_for_size(self, size, spacing_ratio=None) -> float:
        """How many cells the cell size ``size`` gives this domain once resampled to it with
        ``spacing_ratio`` ``s`` (default 2): ``area / (sqrt(3)/2 size**2) + boundary_length (2 -
        s) / (2 s size)``, not rounded."""
        return self._impl.cells_for_size(
            float(size), None if spacing_ratio is None else float(spacing_ratio))

    def __repr__(self):
        return (
            f"<cvt2.Domain {self.format} {self.source!r}: area {self.area:.6g}, "
            f"{len(self.segments)} segments>"
        )


def _impl(domain):
    if not isinstance(domain, Domain):
        raise TypeError(f"domain must be a cvt2.Domain, not {type(domain).__name__}")
    return domain._impl


def _count(value, name, below=2**63):
    """An integer count: >= 0 and below ``below`` (None: no bound), what the module's int64 takes."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer, not {type(value).__name__}")
    if below is None and value < 0:
        raise ValueError(f"{name} must be >= 0, not {value}")
    if below is not None and not 0 <= value < below:
        raise ValueError(f"{name} must be >= 0 and below 2**{below.bit_length() - 1}, not {value}")
    return int(value)


def random_points(
    domain, n=None, seed=1, density=None, *, lipschitz_k=0.1, boundary_size=None, cells=None
):
    """``n`` random points in ``domain``: the same bits as ``cvt2 DOMAIN -n N --seed S`` draws
    them (``cvt2 --cells`` for ``cells=``; with ``--density lipschitz`` for
    ``density="lipschitz"``).

    - ``domain``: a :class:`Domain`;
    - ``n``: how many points (an integer >= 0); or
    - ``cells``: how many cells in all, the domain's own vertices' included: ``n`` is
      ``cells - domain.own_cells`` (``cvt2 --cells``; with :meth:`Domain.resample`, cells of
      the size asked for). The points are then dealt to the regions that constraints
      separate (counties, islands) by their area (their mass, with a density) less the cells
      of the generators on their boundary and in them, and drawn in each, so that each region
      has the cells its area asks for: no generator crosses a constraint, so the optimization
      cannot move cells between regions. ``n=`` points are dealt so too under a density (as
      ``cvt2 -n`` deals them; before December 2026 they were drawn independently, and a
      county network's counties got 7-13% more energy), and drawn independently without;
    - ``seed``: the seed (an integer, 0 to 2**64 - 1): the same seed gives the same points on
      every platform;
    - ``density``: the density the points will be optimized under (:func:`optimize`'s
      ``density``): None (uniform: by area), ``"lipschitz"`` (the automatic sizing, with
      ``lipschitz_k`` and ``boundary_size``), or a callable as in :func:`optimize`, called once
      with every point it needs. The points follow sqrt(density), the point density of a
      centroidal tessellation of that density in 2D, so that the optimization starts close to
      its result.

    Returns a float64 array (n, 2).
    """
    if (n is None) == (cells is None):
        raise TypeError("give one of n and cells")
    if cells is not None:
        cells = _count(cells, "cells")
        if cells < domain.own_cells:
            raise ValueError(
                f"cells={cells} is fewer than the {domain.own_cells} cells of the domain's own "
                "vertices (Domain.resample spaces them to a cell size)"
            )
        n = cells - domain.own_cells
    n = _count(n, "n")
    return _cvt2.random_points(
        _impl(domain),
        n,
        _seed(seed),
        density,
        _number(lipschitz_k, "lipschitz_k"),
        _optional_number(boundary_size, "boundary_size"),
        by_region=cells is not None,
    )


def optimize(
    domain,
    points,
    algorithm="lbfgs",
    density=None,
    move_ratio=0.01,
    max_iterations=1000,
    threads=0,
    callback=None,
    *,
    time_limit=0.0,
    lipschitz_k=0.1,
    boundary_size=None,
    boundary_tolerance=None,
    fixed_points=None,
    boundary=None,
    constraints=None,
    redistribute="auto",
    seed=1,
    cells=None,
    size=None,
) -> "OptimizeResult":
    """Moves ``points`` to a centroidal Voronoi tessellation of ``domain``: each free generator
    to the centroid of its bounded Voronoi cell (under the density), again and again. The same
    domain, points and options give the same bits as ``cvt2 DOMAIN --points-in POINTS`` with
    the same options, whatever the number of threads.

    - ``domain``: a :class:`Domain`; its own vertices (and generators) are generators too;
      constrained ones never move, and no generator crosses a constraint;
    - ``points``: float array (n, 2), the initial free generators (:func:`random_points`, say),
      in the domain (its boundary included: a point on a constraint becomes constrained; one
      outside by no more than ``boundary_tolerance`` goes onto the boundary, see
      :func:`bounded_voronoi`); or None with ``cells`` or ``size`` (below);
    - ``algorithm``: ``"lbfgs"`` (L-BFGS on the CVT energy; fewer evaluations) or ``"lloyd"``;
    - ``density``: None (uniform, integrated exactly), ``"lipschitz"`` (the automatic sizing
      of the paper's Section 4: cell size ``lipschitz_k`` * distance to the boundary +
      ``boundary_size``, by default each boundary edge's length; ``cvt2 --density lipschitz``),
      or a callable ``f(xy) -> values``: ``xy`` a float array (m, 2), the result m positive
      finite values. It is called with many points at once (every quadrature point of a chunk
      of about 500 cells), with the GIL held only while it runs; cells get small where it is
      large (cell size ~ density**-1/4);
    - ``move_ratio``: stop when every free generator's move ratio ``|x - centroid| /
      diameter(cell)`` is below it (0: never);
    - ``max_iterations``: at most that many iterations;
    - ``threads``: threads for the cells (0: one per core); the result does not depend on it;
    - ``callback``: None, or ``f(info)`` called once with each state the run goes through,
      with its figures in a dict (``iteration``, ``evaluations``, ``energy``,
      ``max_move_ratio``, ``mean_move_ratio``, ``seconds``): first the points given
      (``iteration`` 0, before any move), then the state after each iteration, the last call
      with the final state, the one returned (``energy`` is then the result's ``energy``).
      Returning False stops there (the result is that state, ``stop_reason`` ``"callback"``);
      None or True goes on, and the last call's answer is not used when the run stopped for
      another reason. Anything else it returns raises TypeError;
    - ``time_limit``: stop after that many seconds (0: no limit);
    - ``boundary_tolerance``: as in :func:`bounded_voronoi`;
    - ``fixed_points``: None, or a float array (k, 2) of generators that never move (wells,
      observation points; ``cvt2 --fixed-points``), inserted after ``points``, in the domain.
      For finer cells around them, pass a density (``cvt2 --refine`` uses
      ``size + (background - size) * min(1, distance / radius)`` as the cell size);
    - ``boundary``: None (the domain's vertices stay), or ``"slide"`` for a domain made by
      :meth:`Domain.resample`: its new vertices slide along the polylines it was resampled from,
      each to the point nearest to its cell's centroid, never past its neighbours, its chords
      within the deviation bound, the features fixed (``cvt2 --boundary slide``). The result's
      points, diagram and ``domain`` (described by arrays, metadata ``boundary`` ``slide``) have
      them where they slid to;
    - ``constraints``: None, or ``"conforming"`` (``cvt2 --constraints conforming``) for a domain
      with lines (WKT, GeoJSON or shapely LineStrings): the lines are no constraints, but rivers
      or borders that water crosses. Generators mirrored across each step of a line
      (:func:`conforming_sites`, at the spacing of the cells where they lie, under a density
      too) are inserted and fixed, and no other generator enters their circles, so that the
      faces between the cells lie on the line, each perpendicular to the line between the two
      cells' centres. The result's ``domain`` is the
      domain without its lines; its writers take ``constraints="conforming"``, and
      ``to_cells_on_constraints`` lists the pairs of cells along each line. A GeoJSON
      feature's ``"kind"`` property (``"slit"``, ``"barrier"``, ``"conforming"``) says it for its
      own lines, as for ``cvt2``: its conforming lines are made so whatever ``constraints``, and
      the writers split the cells on its barriers whatever theirs;
    - ``redistribute``: with a density, whether to replace the free generators given (``points``
      and the domain's own, not ``fixed_points``) by as many drawn from the density
      (:func:`random_points` with ``seed``): ``"auto"`` (the default) if their cells do not
      follow it (``density_response`` above -1/4 by two standard errors, over 128 cells or
      more: uniform points under a density that varies, from which the iteration would stop
      with every move ratio small, far from the optimum), or if the regions that constraints
      separate hold too many of them or too few (``density_count_excess``),
      ``True`` always, ``False`` never (``cvt2 --redistribute auto|always|never``). The result's
      ``redistributed`` says whether it did, and its ``input_index`` is then -1 for them;
    - ``seed``: the seed of those points (an integer, 0 to 2**64 - 1);
    - ``cells`` or ``size``: how many cells in all (``cvt2 --cells``), or their size ``H`` (a
      hexagon of area ``sqrt(3)/2 H**2``, ``cvt2 --size``): with ``boundary`` ``"resample"`` or
      ``"slide"``, a domain not made by :meth:`Domain.resample` is first resampled to that size
      (``domain.resample(cells=cells, size=size)``). Free generators are then drawn, as many as
      make that many cells with the domain's own, ``points``, ``fixed_points`` and the
      conforming lines' generators (None for ``points``: none given), dealt to the regions that
      constraints separate as :func:`random_points` deals them (``seed``), none in the
      conforming lines' circles; ``size`` gives ``domain.cells_for_size(size,
      spacing_ratio=1)`` cells with ``boundary="keep"`` (the boundary's generators counted as if
      ``size`` apart, however few its vertices), the resampled domain's
      ``cells_for_size(size)`` otherwise, rounded half away from 0. Their ``input_index`` is
      -1. ``optimize(d, None, boundary="slide", cells=N, seed=S)`` gives the bits of ``cvt2 D --boundary slide --cells N --seed S``, and
      so with ``fixed_points``, ``constraints`` and a density as with their options.

    Ctrl-C raises KeyboardInterrupt. Returns an :class:`OptimizeResult`.
    """
    if threads is None:
        threads = 0
    if cells is not None and size is not None:
        raise TypeError("give one of cells and size")
    if cells is not None:
        cells = _count(cells, "cells")
    if size is not None:
        size = _size(size)
    if boundary == "resample" and domain.resampling is None:
        if cells is None and size is None:
            raise ValueError(
                "boundary='resample' resamples the domain to the size of the cells: give cells= "
                "or size=, or a domain made by Domain.resample()"
            )
    counted = cells is not None or size is not None
    if boundary in ("resample", "slide") and constraints == "conforming" and domain.resampling is None:
        # Domain.resample() would make the lines constraints ("this domain has none")
        raise ValueError(
            f"boundary={boundary!r} with constraints='conforming' is not in the module yet "
            "(Domain.resample() makes the lines constraints; cvt2 --boundary resample "
            "--constraints conforming keeps them conforming)"
        )
    if boundary in ("resample", "slide") and domain.resampling is None and counted:
        domain = domain.resample(cells=cells, size=size)
    if points is None and counted:
        points = np.empty((0, 2))
    # as cvt2: a domain not resampled keeps its vertices (ratio 1)
    ratio = domain.resampling["spacing_ratio"] if domain.resampling else 1.0
    result = _cvt2.optimize(
        _impl(domain),
        points,
        str(algorithm),
        density,
        _number(move_ratio, "move_ratio"),
        _count(max_iterations, "max_iterations"),
        _number(time_limit, "time_limit"),
        _count(threads, "threads"),
        callback,
        _number(lipschitz_k, "lipschitz_k"),
        _optional_number(boundary_size, "boundary_size"),
        _optional_number(boundary_tolerance, "boundary_tolerance"),
        fixed_points,
        _slide(boundary),
        _conforming(constraints),
        _redistribute(redistribute),
        _seed(seed),
        cells=cells,
        size=size,
        spacing_ratio=float(ratio),
    )
    if _slide(boundary) or _conforming(constraints):  # the domain the cells are of
        domain = Domain._wrap(result.domain)
    return OptimizeResult(result, domain)


def _size(size):
    """A cell size: a positive finite number."""
    if isinstance(size, (bool, np.bool_)) or not isinstance(size, (int, float, np.integer, np.floating)):
        raise TypeError(f"size must be a number, not {type(size).__name__}")
    if not (size > 0 and math.isfinite(size)):
        raise ValueError(f"size must be a positive number, not {size}")
    return float(size)


def _redistribute(redistribute):
    if isinstance(redistribute, (bool, np.bool_)):
        return "always" if redistribute else "never"
    if isinstance(redistribute, str) and redistribute == "auto":
        return "auto"
    raise ValueError(f"redistribute must be 'auto', True or False, not {redistribute!r}")


def _seed(seed):
    seed = _count(seed, "seed", below=None)
    if seed >= 2**64:
        raise ValueError(f"seed must be below 2**64, not {seed}")
    return seed


def _conforming(constraints):
    if constraints not in (None, "conforming"):
        raise ValueError(f"optimize's constraints must be None or 'conforming', not {constraints!r} "
                         "('slit' and 'barrier' are the writers' choice)")
    return constraints == "conforming"


def _slide(boundary):
    if boundary not in (None, "keep", "resample", "slide"):
        raise ValueError(f"boundary must be None, 'keep', 'resample' or 'slide', not {boundary!r}")
    return boundary == "slide"


def _barriers(constraints):
    if constraints not in ("slit", "barrier", "conforming"):
        raise ValueError(f"constraints must be 'slit', 'barrier' or 'conforming', not {constraints!r}")
    return constraints == "barrier"


def _number(value, name, or_none=False):
    """A number as a float (bool and strings refused); None too with ``or_none``."""
    if value is None and or_none:
        return None
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.number)):
        what = "None or a number" if or_none else "a number"
        raise TypeError(f"{name} must be {what}, not {type(value).__name__}")
    return float(value)


def _optional_number(value, name):
    """None, or a number as a float (bool and strings refused)."""
    return _number(value, name, or_none=True)


def conforming_sites(line, spacing) -> dict:
    """The generators that make ``line`` (float array (m, 2), a polyline) a *conforming* line of
    the Voronoi diagram (``cvt2 --constraints conforming``): pairs mirrored across it, about
    ``spacing`` apart along it, so that each step of the line is the face between its pair,
    perpendicular to the line between them, while no other generator lies inside the circles
    around the nodes. Returns a dict: ``sites`` (2k, 2), the pair of step k at rows 2k (left)
    and 2k + 1 (right); ``nodes`` (k + 1, 2), the line's vertices and points between, the
    Voronoi vertices between the pairs; ``radii`` (k + 1,), the circles' radii. A river in
    Python: the domain without the line, the sites inside the domain as ``fixed_points`` of
    :func:`optimize`, random points drawn outside the circles. One line: lines that meet (a
    tributary, a crossing at a shared vertex) are placed together by ``optimize(...,
    constraints="conforming")``, which gives them shared nodes at their junctions; placed one
    by one, their pairs would fall out of order or into each other's circles there."""
    return _cvt2.conforming_sites(line, float(spacing))


def bounded_voronoi(domain, points, threads=0, *, boundary_tolerance=None) -> "BoundedVoronoi":
    """The bounded Voronoi diagram of the domain's vertices (and generators) and ``points``
    (float array (n, 2) in the domain): each generator's cell is the part of the domain that is
    closer to it than to any other generator it can see (constraints block the view, and cells
    stop at them). Returns a :class:`BoundedVoronoi`; its regions, and its ``points`` (their
    generators), are in the diagram's order, which is not the order given: as in scipy,
    ``regions[point_region[i]]`` is the cell of ``points`` row i, and ``point_region[n + j]``
    that of the domain's own point j; ``input_index`` goes back from regions to rows, and
    ``duplicates`` says which rows were merged.

    A point on the boundary is a constrained generator. One that lies outside the domain by no
    more than ``boundary_tolerance`` (a boundary point computed in floating point: an edge's
    midpoint, a projection) goes onto the boundary as a constrained generator: merged with a
    boundary vertex within the tolerance and at most twice as far as the boundary, else at its
    projection onto the nearest boundary edge (rounded; the edge bends through it by a rounding
    if no rounding lies on it); the result's ``notes`` say which. ``boundary_tolerance`` is a
    distance >= 0 (0: none), by default 2**-50 of the largest coordinate magnitude of the domain
    (4 to 8 units in the last place). Points farther out raise DomainError naming how many and the first few rows.
    """
    return BoundedVoronoi(
        _cvt2.bounded_voronoi(
            _impl(domain),
            points,
            _count(threads, "threads"),
            _optional_number(boundary_tolerance, "boundary_tolerance"),
        ),
        domain,
    )


def natural_neighbours(domain, nodes, queries, method="sibson", threads=0, *, boundary_tolerance=None, lips=False):
    """The natural-neighbour coordinates of ``queries`` on the bounded Voronoi diagram of
    ``domain`` and ``nodes``, as a sparse matrix ``M``: the shape functions of the constrained
    natural element method, in which a node that a constraint hides from a query gets no
    weight, so that ``M @ values`` interpolates values given at the nodes without mixing the
    two sides of a constraint (a crack, a fault, a wall).

    - ``domain``: a :class:`Domain`; its own points are nodes too;
    - ``nodes``: float array (n, 2) in the domain, as :func:`bounded_voronoi` takes its points;
    - ``queries``: float array (q, 2), finite;
    - ``method``: ``"sibson"`` (the share of the query's cell that each node's cell gives up;
      reproduces linear functions) or ``"laplace"`` (the length of the edge between the two
      cells over the distance between the two points);
    - ``threads``: threads (0: one per core); the result does not depend on it;
    - ``boundary_tolerance``: as in :func:`bounded_voronoi`, for the nodes.

    Returns a (q, n + d) matrix with ``indptr``, ``indices``, ``data`` and ``shape``: a
    ``scipy.sparse.csr_matrix`` if scipy can be imported, a :class:`CsrMatrix` otherwise.
    Row k holds the coordinates of ``queries[k]``, positive and summing to 1, in increasing
    columns: column i < n is ``nodes[i]``, column n + j the domain's own point j
    (:attr:`Domain.vertices`, then a WKT or GeoJSON domain's :attr:`Domain.generators`): the
    rows of :attr:`BoundedVoronoi.point_region`, so ``values`` has one value a column. Rows at
    one place (a node given twice, or on a vertex of the domain) are one generator, whose
    weight goes to the first of their columns. A query at a node has that node alone, weight
    1. A query outside the closed domain gets an empty row, so ``M @ values`` is 0 there:
    ``M.inside``, bool (q,), says which queries lie in it. The numbers are those of the
    library's ``natural_neighbor_matrix_2()`` (the ``natural_neighbours`` example prints
    them), bit for bit.

    With ``lips=True``, a node along a crack (two lips or more: the wedges of the domain
    between its constraints) gets a column for each lip after all the others, and its own
    column stays empty: a query's weight goes to the lip it sees the node from, so that a field
    that jumps across the crack has a value on each lip. ``M.lip_columns``, int (L,), gives the
    node column that each of the last L columns splits (lips of a node counterclockwise).

    Errors: DomainError for a node outside the domain or a query that is not finite, naming
    its row.
    """
    if method not in ("sibson", "laplace"):
        raise ValueError(f"method must be 'sibson' or 'laplace', not {method!r}")
    m = _cvt2.natural_neighbours(
        _impl(domain),
        nodes,
        queries,
        method,
        _count(threads, "threads"),
        _optional_number(boundary_tolerance, "boundary_tolerance"),
        bool(lips),
    )
    try:
        import scipy.sparse
    except ImportError:
        matrix = CsrMatrix(m["data"], m["indices"], m["indptr"], m["shape"])
    else:
        matrix = scipy.sparse.csr_matrix((m["data"], m["indices"], m["indptr"]), shape=m["shape"])
    matrix.inside = m["inside"]
    matrix.lip_columns = m["lip_columns"]
    return matrix


class ConstraintEditor:
    """A bounded Voronoi diagram whose constraints change: cracks that grow, slits inserted,
    moved and removed, with work local to each edit (``CVT_2::Constraint_editor_2``). Built from
    a domain and ``points`` (float (n, 2)) as :func:`bounded_voronoi` is.

    Each edit returns its report, a dict: ``changed_cells`` float (k, 2), the generators whose
    cells changed (the rows a solver assembles again, named by their coordinates, since a
    snapshot's numbering changes with each edit); ``new_vertices`` float (m, 2), the vertices
    it inserted; ``retagged_faces``, how many faces were tagged again; and the weights that
    carry a field over to the new vertices (their Sibson coordinates in the diagram before the
    edit, each row summing to 1), in compressed rows: new vertex k's nodes are
    ``weights_nodes[weights_indptr[k]:weights_indptr[k + 1]]`` (float (., 2), by coordinates)
    with ``weights`` (empty outside the domain), from both sides of the new constraint; and
    the same for each lip of the new vertices along a crack, from its side only:
    ``lip_vertices`` float (L, 2), ``lips`` int (L,) (numbered as ``natural_neighbours(...,
    lips=True)`` numbers them), ``lip_weights_indptr``, ``lip_weights_nodes``,
    ``lip_weights``. Polylines inserted here
    get ids 0, 1, ... in order; the domain's own constraints have none (their vertices can
    move). A point outside the domain, or an edge that would cross another constraint off a
    vertex, raises DomainError naming both, and changes nothing.

    :meth:`bounded_voronoi` takes a snapshot (a :class:`BoundedVoronoi`) that later edits
    leave alone.
    """

    def __init__(self, domain, points, *, boundary_tolerance=None):
        self._domain = domain
        self._impl = _cvt2.ConstraintEditor(
            _impl(domain), points, _optional_number(boundary_tolerance, "boundary_tolerance")
        )

    def insert_constraint(self, points) -> int:
        """Inserts the polyline through ``points`` (float (k, 2), k >= 2); returns its id."""
        return self._impl.insert_constraint(points)

    def extend_constraint(self, id, tip, spacing=0.0) -> dict:
        """Grows constraint ``id`` from its last vertex to ``tip``, with vertices at most
        ``spacing`` apart on the way if it is positive; a tip on another constraint is inserted
        on it. Returns the report."""
        return self._impl.extend_constraint(_count(id, "id"), tip, float(spacing))

    def move_constrained_vertex(self, vertex, to) -> dict:
        """Moves the constrained vertex at ``vertex`` (x, y) to ``to``; its constraints follow,
        free generators stay. Returns the report."""
        return self._impl.move_constrained_vertex(vertex, to)

    def remove_constraint(self, id) -> dict:
        """Removes constraint ``id``; its vertices stay, as free generators where no other
        constraint holds them. Returns the report."""
        return self._impl.remove_constraint(_count(id, "id"))

    def relax(self, rings=2, iterations=5) -> dict:
        """``iterations`` Lloyd iterations on the free generators within ``rings`` rings of the
        last edit's changed cells, evaluated around them only (``lloyd_optimize_2`` with
        ``region``): the cells around a crack's tip made centroidal again, at a cost that does
        not grow with the diagram. Returns ``moved_from`` and ``moved_to``, float (k, 2): the
        generators that moved (their cells and their neighbours' changed)."""
        return self._impl.relax(_count(rings, "rings"), _count(iterations, "iterations"))

    @property
    def report(self) -> dict:
        """The last edit's report."""
        return self._impl.report()

    def constraint_vertices(self, id) -> np.ndarray:
        """Float (k, 2): the vertices of constraint ``id`` in order (a removed one's: the
        vertices it had, where they are now, as later moves and ``relax`` left them)."""
        return self._impl.constraint_vertices(_count(id, "id"))

    @property
    def number_of_constraints(self) -> int:
        """The constraints inserted here, removed ones included (the next id)."""
        return self._impl.number_of_constraints()

    def is_removed(self, id) -> bool:
        return self._impl.is_removed(_count(id, "id"))

    @property
    def notes(self) -> list:
        """The points given that went onto the boundary (``boundary_tolerance``), as
        :func:`bounded_voronoi` notes them; its snapshots' ``notes`` say them too."""
        return list(self._impl.notes)

    def bounded_voronoi(self, threads=0) -> "BoundedVoronoi":
        """The diagram as it is now, as :func:`bounded_voronoi` returns it."""
        return BoundedVoronoi(self._impl.diagram(_count(threads, "threads")), self._domain)


class CsrMatrix:
    """A sparse matrix in compressed rows, as :func:`natural_neighbours` returns it when scipy
    is not installed: scipy's ``indptr``, ``indices``, ``data``, ``shape`` and ``nnz`` (row k's
    columns ``indices[indptr[k]:indptr[k + 1]]``, its values likewise in ``data``), ``M @
    values`` and ``M.dot(values)`` for ``values`` of shape (columns,) or (columns, m), summed in
    the order scipy sums them, and ``toarray()``. ``scipy.sparse.csr_matrix((M.data, M.indices,
    M.indptr), shape=M.shape)`` is the same matrix in scipy."""

    def __init__(self, data, indices, indptr, shape):
        self.data = np.asarray(data)
        self.indices = np.asarray(indices)
        self.indptr = np.asarray(indptr)
        self.shape = tuple(int(s) for s in shape)

    @property
    def nnz(self) -> int:
        return len(self.data)

    def _rows(self):
        return np.repeat(np.arange(self.shape[0]), np.diff(self.indptr))

    def __matmul__(self, values):
        values = np.asarray(values)
        if values.ndim not in (1, 2) or values.shape[0] != self.shape[1]:
            raise ValueError(
                f"the matrix has {self.shape[1]} columns: values must have shape "
                f"({self.shape[1]},) or ({self.shape[1]}, m), not {values.shape}"
            )
        rows = self._rows()
        terms = (self.data if values.ndim == 1 else self.data[:, None]) * values[self.indices]
        out = np.zeros((self.shape[0],) + values.shape[1:], dtype=terms.dtype)
        columns = out.reshape(self.shape[0], int(np.prod(values.shape[1:])))  # a view of out
        if terms.dtype == np.float64:  # bincount adds in order from 0, as scipy, and fast
            for c, t in enumerate(terms.reshape(len(terms), columns.shape[1]).T):
                columns[:, c] = np.bincount(rows, weights=t, minlength=self.shape[0])
        else:
            np.add.at(out, rows, terms)
        return out

    dot = __matmul__

    def toarray(self) -> np.ndarray:
        out = np.zeros(self.shape, dtype=self.data.dtype)
        out[self._rows(), self.indices] = self.data
        return out

    def __repr__(self):
        return f"<cvt2.CsrMatrix {self.shape[0]} x {self.shape[1]}, {self.nnz} stored values>"


class OptimizeResult:
    """What :func:`optimize` found, for the generators as they are at the end.

    - ``points``: float (N, 2), every generator, constrained ones included, in the order
      ``cvt2 --points-out`` writes them (the cells' order of :meth:`bounded_voronoi`);
    - ``constrained``: bool (N,), whether each is a constrained vertex (which never moves);
    - ``fixed``: bool (N,), whether each is a free generator held where it is: one of
      ``fixed_points``, or of a conforming line's pairs;
    - ``energy``: the CVT energy, sum over cells of the integral of density * |y - x|^2;
    - ``normalized_energy``: energy * N / area^2 over the hexagonal tiling's (uniform density:
      1 is the optimum for large N), as ``cvt2`` prints it;
    - ``iterations``, ``evaluations``: moves done, and diagrams evaluated;
    - ``stop_reason``: ``"converged"``, ``"stalled"`` (every move ratio below the stop, but
      the cells do not follow the density, far from the optimum: ``density_response`` above
      -0.25 by two of its standard errors, ``density_response_error``, over 128 cells or more;
      or the regions between constraints hold too many points or too few, by
      ``density_count_excess``),
      ``"max_iterations"``, ``"time_limit"``, ``"callback"`` or ``"no_free_generator"``;
    - ``energy_history``, ``max_move_ratio_history``, ``mean_move_ratio_history``: one value an
      iteration, the first before any move; ``max_move_ratio``, ``mean_move_ratio``: the last
      (over the free generators and, with ``boundary="slide"``, the sliding ones);
    - ``seconds``: the optimization's time, measured as ``cvt2`` prints ``seconds=``;
    - ``notes``: the points moved onto the boundary (``boundary_tolerance``), as ``cvt2`` notes
      them, and, with a density, a note if the cells do not follow it (as for ``"stalled"``):
      a list of strings, empty if none;
    - ``density_response``: with a density, the least-squares slope of log(cell area) against
      log(density at the generator) over the free generators that move (not ``fixed``), the
      density varying over their cells by a factor 8 at most, ``density_response_cells`` of
      them: about -0.5 for a centroidal tessellation of the
      density (cell size ~ density**-1/4), 0 for cells of one size, as a uniform start keeps
      them long after every move ratio is below 1%; NaN without a density, or where it varies
      by less than a factor 2 over those cells (or within most cells: a feature smaller than
      them);
    - ``density_count_excess``: with a density, on a domain that constraints cut into regions
      (counties, islands), the energy that the regions' counts of those generators cost over
      counts that follow the density, as a fraction (Gersho's law: a region of mass M, the
      integral of the density's square root, in c cells has an energy of about M**2 / c). No
      generator crosses a constraint, so no iteration mends wrong counts; above 0.02 the stop
      is ``"stalled"``. A lower bound where a region keeps few cells. NaN with one region, or
      fewer than 128 generators;
    - ``input_index``: int (N,), for each generator, the row of the ``points`` given that it
      started from (the first of rows merged as duplicates), or -1 for a generator of the
      domain's own or one drawn in their place: ``points[input_index == i]`` is where input row
      i went;
    - ``redistributed``: whether the points given were replaced by points drawn from the density
      (``optimize``'s ``redistribute``; a note says why).
    """

    def __init__(self, impl, domain):
        self._impl = impl
        self.domain = domain
        self.points = impl.points
        self.constrained = impl.constrained
        self.fixed = impl.fixed
        self.energy = impl.energy
        self.iterations = impl.iterations
        self.evaluations = impl.evaluations
        self.stop_reason = impl.stop_reason
        self.energy_history = impl.energy_history
        self.max_move_ratio = impl.max_move_ratio
        self.mean_move_ratio = impl.mean_move_ratio
        self.max_move_ratio_history = impl.max_move_ratio_history
        self.mean_move_ratio_history = impl.mean_move_ratio_history
        self.seconds = impl.seconds
        self.notes = impl.notes
        self.density_response = impl.density_response
        self.density_response_error = impl.density_response_error
        self.density_response_cells = impl.density_response_cells
        self.density_count_excess = impl.density_count_excess
        self.input_index = impl.input_index
        self.redistributed = impl.redistributed

    @property
    def normalized_energy(self) -> float:
        area = self.domain.area
        return self.energy * len(self.points) / (area * area) / _HEXAGON_ENERGY

    def bounded_voronoi(self, threads=0) -> "BoundedVoronoi":
        """The diagram of the optimized triangulation itself: its ``points`` are this result's,
        in the same order (``point_region`` is ``arange(N)``, ``input_index`` this result's),
        and its files are those ``cvt2 --geojson/--vtu/--disv`` writes."""
        n = len(self.points)
        rows = {
            "point_region": np.arange(n, dtype=np.int64),
            "input_index": self.input_index,
            "duplicates": np.empty((0, 2), dtype=np.int64),
        }
        return BoundedVoronoi(self._impl.diagram(_count(threads, "threads")), self.domain, rows)

    def __repr__(self):
        return (
            f"<cvt2.OptimizeResult {len(self.points)} generators, {self.iterations} iterations, "
            f"stop {self.stop_reason}, energy {self.energy:.9g}>"
        )


class BoundedVoronoi:
    """A bounded Voronoi diagram as a conforming polygon mesh, with the names of
    ``scipy.spatial.Voronoi`` and no -1 in them (every region is finite, inside the domain):

    - ``points``: float (n, 2), every generator (the domain's vertices included), in the
      regions' order: ``points[k]`` is region k's generator (for the rows given, see
      ``point_region``); ``constrained``: bool (n,), whether each is a constrained vertex;
    - ``vertices``: float (V, 2), the cell vertices: circumcenters, points where bisectors meet
      constraints, and constrained generators (a vertex of its own cell); each is shared by the
      cells it bounds, found from the triangulation, not by comparing coordinates;
    - ``regions``: list of n lists of vertex indices, counterclockwise: cell k as one ring, what
      plotting wants (``vertices[regions[k]]``); a constraint that ends inside a cell (a slit)
      is left out, and a cell of several pieces meeting at its generator (where two holes
      touch) is one ring through the generator; ``cycles`` is the exact boundary, slits walked
      there and back;
    - ``point_region``: int, scipy's: the region of each point given to
      :func:`bounded_voronoi`, in the order given (``regions[point_region[i]]`` is input row
      i's cell), then of each of the domain's own points (:attr:`Domain.vertices`, then a WKT
      or GeoJSON domain's :attr:`Domain.generators`; -1 for one with no cell). Rows at one
      place (duplicates, or a point on a vertex of the domain) were merged into one generator
      and name its region; ``duplicates``, int (D, 2), lists them as pairs (i, j): row i
      shares the generator of the earlier row j, the first there.
      For :meth:`OptimizeResult.bounded_voronoi`, the rows are the result's ``points``:
      ``point_region`` is ``arange(n)``;
    - ``input_index``: int (n,), for each region, the first row given that is its generator,
      -1 for a generator of the domain's own (``OptimizeResult.input_index`` for an optimized
      diagram);
    - ``ridge_points``: int (E, 2), the cells on the two sides of each ridge (mesh edge), the
      left one first; a ridge on the domain's boundary, with no cell beyond, names its cell
      twice (``ridge_boundary`` is True for those), as does a slit;
    - ``ridge_vertices``: int (E, 2), the ends of each ridge (rows of ``vertices``);
    - ``ridge_constraint``: int (E,), the input segment each ridge lies on (a row of
      :attr:`Domain.segments`; :attr:`Domain.segment_items` gives its line, feature or
      shapely geometry, as a :class:`ConstraintEditor`'s moves left it), or -1 for a bisector
      ridge or one on a constraint the editor inserted;
    - ``ridge_edit_constraint``: for a :class:`ConstraintEditor`'s snapshot, int (E,), the id
      of the constraint the editor inserted that each ridge lies on, or -1; None otherwise;
    - ``areas``: float (n,), ``centroids``: float (n, 2) (of the cells as uniform polygons);
    - ``notes``: the points moved onto the boundary (``boundary_tolerance``), a list of
      strings, empty if none was.

    :meth:`to_shapely` gives one valid geometry per generator; :meth:`to_geojson`,
    :meth:`to_vtu`, :meth:`to_disv` write the library's files.
    """

    def __init__(self, impl, domain, rows=None):
        self._impl = impl
        self.domain = domain
        self._given_rows = rows  # point_region, input_index, duplicates; else found when asked

    @functools.cached_property
    def _rows(self):
        return self._impl.rows() if self._given_rows is None else self._given_rows

    @functools.cached_property
    def points(self) -> np.ndarray:
        return self._impl.points

    @functools.cached_property
    def constrained(self) -> np.ndarray:
        return self._impl.constrained

    @functools.cached_property
    def vertices(self) -> np.ndarray:
        return self._impl.vertices

    @functools.cached_property
    def vertex_kinds(self) -> np.ndarray:
        """uint8 (V,): 0 a circumcenter, 1 a point on a constraint, 2 a constrained generator."""
        return self._impl.vertex_kinds

    @functools.cached_property
    def regions(self) -> list:
        return self._impl.outlines()

    @functools.cached_property
    def cycles(self) -> list:
        """Cell k's exact boundary, counterclockwise: a slit (a constraint ending inside the
        cell, or crossing it at its constrained generator) is walked there and back."""
        return self._impl.cycles()

    @functools.cached_property
    def point_region(self) -> np.ndarray:
        return self._rows["point_region"]

    @functools.cached_property
    def input_index(self) -> np.ndarray:
        return self._rows["input_index"]

    @functools.cached_property
    def duplicates(self) -> np.ndarray:
        return self._rows["duplicates"]

    @functools.cached_property
    def ridge_points(self) -> np.ndarray:
        return self._impl.ridge_points

    @functools.cached_property
    def ridge_vertices(self) -> np.ndarray:
        return self._impl.ridge_vertices

    @functools.cached_property
    def ridge_constraint(self) -> np.ndarray:
        return self._impl.ridge_constraint

    @functools.cached_property
    def ridge_edit_constraint(self):
        ids = self._impl.ridge_edit_constraint
        return ids if len(ids) == len(self._impl.ridge_constraint) else None

    @functools.cached_property
    def ridge_boundary(self) -> np.ndarray:
        """bool (E,): the ridge has no cell beyond it (the domain's boundary)."""
        return self._impl.ridge_boundary

    @functools.cached_property
    def areas(self) -> np.ndarray:
        return self._impl.areas

    @functools.cached_property
    def centroids(self) -> np.ndarray:
        return self._impl.centroids

    @property
    def notes(self) -> list:
        return self._impl.notes

    def polygons(self) -> list:
        """Cell k as valid rings: a list (one ring per piece, usually one) of int arrays of
        vertex indices, counterclockwise, not closed; slits dropped. What :meth:`to_shapely`
        and the GeoJSON writer use."""
        return self._impl.polygons()

    def to_shapely(self) -> list:
        """One shapely geometry per generator, in the order of ``points``: a Polygon, or a
        MultiPolygon for a cell of several pieces that meet at its generator. Every one is
        valid; neighbouring cells share their vertices' coordinates exactly, so they neither
        overlap nor leave gaps, and their union is the domain."""
        import shapely.wkb

        return list(shapely.wkb.loads(self._impl.wkb()).geoms)

    def to_geojson(self, path, constraints="slit") -> None:
        """Writes the cells as a GeoJSON FeatureCollection (``cvt2 --geojson``): one valid
        Polygon or MultiPolygon per cell; properties cell, generator, constrained, area,
        neighbors; what made it in a ``metadata`` object (see :meth:`metadata`).
        ``constraints``: what inner constraints are to the cells, ``"slit"`` or ``"barrier"``
        (``cvt2 --constraints``; see :meth:`to_disv`)."""
        self._impl.write_geojson(os.fspath(path), _barriers(constraints), self.metadata(constraints))

    def to_vtu(self, path, constraints="slit") -> None:
        """Writes the cells as a VTK XML unstructured grid (``cvt2 --vtu``; ParaView, meshio),
        :meth:`metadata` in XML comments; ``constraints`` as for :meth:`to_disv`."""
        self._impl.write_vtu(os.fspath(path), _barriers(constraints), self.metadata(constraints))

    def to_disv(self, path, top=1.0, bottom=0.0, constraints="slit") -> None:
        """Writes the cells as a MODFLOW 6 DISV grid of one layer between ``bottom`` and
        ``top`` (``cvt2 --disv``; flopy), :meth:`metadata` in comment lines. Each pair of cells
        shares one edge, the whole face between them, but across a slit. ``top`` and ``bottom``: a number, or one
        a cell of the grid (``cvt2 --top FILE``), each bottom below its top (else ValueError).

        ``constraints``: ``"slit"`` (the cells of this diagram: a constrained generator's cell
        lies on both sides of an inner constraint) or ``"barrier"`` (a wall: the cell of a
        generator on one is split into one cell per side, each centered at the generator, and
        no edge is shared across, so that MODFLOW connects no cells through it; cells are then
        more than :attr:`points`, numbered as the diagram's, the parts of a split cell one after
        the other); ``"conforming"`` for the cells of ``optimize(..., constraints="conforming")``,
        whose lines are no constraints (the same cells as ``"slit"``, said in the metadata)."""
        def values(v):
            return [float(x) for x in np.ravel(np.asarray(v, dtype=float))]

        self._impl.write_disv(os.fspath(path), values(top), values(bottom), _barriers(constraints),
                              self.metadata(constraints))

    def to_cells_on_constraints(self, path, constraints="slit") -> None:
        """Writes which cells lie on each input line (``cvt2 --cells-on-constraints``): a CSV
        with the header ``constraint,cell,length,other_cell``, one row per piece of a segment
        along a cell: the input item it comes from (:attr:`Domain.segment_items`), the cell of
        :meth:`to_disv` with the same ``constraints`` (from 1), the piece's length, the cell on
        the other side (from 1; -1 on the boundary; the cell itself for a slit inside it)."""
        self.metadata(constraints)  # checks "conforming"
        self._impl.write_cells_on_constraints(os.fspath(path), _barriers(constraints))

    def metadata(self, constraints="slit") -> list:
        """What the writers put in their headers, as (key, value) strings: the program, the
        domain's source and its boundary mode (``keep``, or ``resample`` with the cell size,
        the deviation bound and the largest deviation), and ``constraints`` if ``"barrier"``,
        as ``cvt2`` writes them."""
        barriers = _barriers(constraints)
        metadata = list(self.domain._impl.metadata)
        if constraints == "conforming" and ("constraints", "conforming") not in metadata:
            raise ValueError("constraints='conforming' writes the cells of "
                             "optimize(..., constraints='conforming'), which made the lines conforming")
        kinds = [("constraint_kinds", "by feature")] if self.domain._impl.has_kinds else []
        return metadata + ([("constraints", "barrier")] if barriers else []) + kinds

    def __len__(self):
        return len(self.points)

    def __repr__(self):
        return (
            f"<cvt2.BoundedVoronoi {len(self.points)} cells, {len(self.vertices)} vertices, "
            f"{len(self.ridge_points)} ridges>"
        )
