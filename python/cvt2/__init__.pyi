# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# Type stubs of the cvt2 module; cvt2/__init__.py documents each name.
from os import PathLike
from typing import Any, Callable, Iterable, Literal, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

_Path = Union[str, PathLike]
_Points = npt.ArrayLike  # float (n, 2)
# None (uniform), "uniform", "lipschitz", or f(xy: float (m, 2)) -> m positive values
_Density = Union[None, Literal["uniform", "lipschitz"], Callable[[np.ndarray], npt.ArrayLike]]

class ParseError(ValueError):
    file: str
    line: int
    token: str

class DomainError(ValueError):
    index: Optional[int]

class Domain:
    def __init__(
        self, vertices: _Points, segments: npt.ArrayLike, holes: Optional[_Points] = ...
    ) -> None: ...
    @classmethod
    def from_file(cls, path: _Path) -> Domain: ...
    @classmethod
    def from_shapely(cls, geometry: Any, constraints: Optional[Iterable[Any]] = ...) -> Domain: ...
    @property
    def format(self) -> str: ...
    @property
    def source(self) -> str: ...
    @property
    def area(self) -> float: ...
    @property
    def bounds(self) -> tuple[float, float, float, float]: ...
    @property
    def notes(self) -> list[str]: ...
    @property
    def vertices(self) -> np.ndarray: ...  # float (V, 2)
    @property
    def segments(self) -> np.ndarray: ...  # int (S, 2)
    @property
    def segment_items(self) -> np.ndarray: ...  # int (S,)
    @property
    def holes(self) -> np.ndarray: ...  # float (H, 2)
    @property
    def generators(self) -> np.ndarray: ...  # float (G, 2)
    @property
    def own_cells(self) -> int: ...
    resampling: Optional[dict[str, Any]]
    def resample(
        self,
        *,
        cells: Optional[int] = ...,
        size: Optional[float] = ...,
        deviation_bound: Optional[float] = ...,
        corner_angle: float = ...,
        fixed_points: Optional[_Points] = ...,
        minimum_ring_area: float = ...,
        spacing_ratio: Optional[float] = ...,
    ) -> Domain: ...
    def cells_for_size(self, size: float, spacing_ratio: Optional[float] = ...) -> float: ...

def random_points(
    domain: Domain,
    n: Optional[int] = ...,
    seed: int = ...,
    density: _Density = ...,
    *,
    lipschitz_k: float = ...,
    boundary_size: Optional[float] = ...,
    cells: Optional[int] = ...,
) -> np.ndarray: ...  # float (n, 2)
def optimize(
    domain: Domain,
    points: _Points,
    algorithm: Literal["lbfgs", "lloyd"] = ...,
    density: _Density = ...,
    move_ratio: float = ...,
    max_iterations: int = ...,
    threads: int = ...,
    callback: Optional[Callable[[dict[str, Any]], Optional[bool]]] = ...,
    *,
    time_limit: float = ...,
    lipschitz_k: float = ...,
    boundary_size: Optional[float] = ...,
    boundary_tolerance: Optional[float] = ...,
    fixed_points: Optional[_Points] = ...,
    boundary: Optional[Literal["slide"]] = ...,
    constraints: Optional[Literal["conforming"]] = ...,
    redistribute: Union[Literal["auto"], bool] = ...,
    seed: int = ...,
) -> OptimizeResult: ...
def bounded_voronoi(
    domain: Domain, points: _Points, threads: int = ..., *, boundary_tolerance: Optional[float] = ...
) -> BoundedVoronoi: ...
# A scipy.sparse.csr_matrix if scipy is installed, else a CsrMatrix; both with .inside
def natural_neighbours(
    domain: Domain,
    nodes: _Points,
    queries: _Points,
    method: Literal["sibson", "laplace"] = ...,
    threads: int = ...,
    *,
    boundary_tolerance: Optional[float] = ...,
) -> Any: ...

class CsrMatrix:
    data: np.ndarray  # float (nnz,)
    indices: np.ndarray  # int (nnz,)
    indptr: np.ndarray  # int (rows + 1,)
    shape: tuple[int, int]
    inside: np.ndarray  # bool (rows,), set by natural_neighbours
    def __init__(
        self,
        data: npt.ArrayLike,
        indices: npt.ArrayLike,
        indptr: npt.ArrayLike,
        shape: tuple[int, int],
    ) -> None: ...
    @property
    def nnz(self) -> int: ...
    def __matmul__(self, values: npt.ArrayLike) -> np.ndarray: ...
    def dot(self, values: npt.ArrayLike) -> np.ndarray: ...
    def toarray(self) -> np.ndarray: ...

class OptimizeResult:
    domain: Domain
    points: np.ndarray  # float (N, 2), every generator, in cvt2 --points-out order
    constrained: np.ndarray  # bool (N,)
    fixed: np.ndarray  # bool (N,): fixed_points and conforming pairs
    energy: float
    iterations: int
    evaluations: int
    stop_reason: Literal[
        "converged", "stalled", "max_iterations", "time_limit", "callback", "no_free_generator"
    ]
    energy_history: np.ndarray
    max_move_ratio: float
    mean_move_ratio: float
    max_move_ratio_history: np.ndarray
    mean_move_ratio_history: np.ndarray
    seconds: float
    notes: list[str]
    density_response: float  # slope of log(area) on log(density): -0.5 at a CVT, NaN uniform
    density_response_error: float  # its standard error
    density_response_cells: int  # the cells measured
    density_count_excess: float  # energy the regions' point counts cost; NaN one region
    input_index: np.ndarray  # int (N,), the input row of each generator, -1 for the domain's
    redistributed: bool  # the points given were replaced by points drawn from the density
    @property
    def normalized_energy(self) -> float: ...
    def bounded_voronoi(self, threads: int = ...) -> BoundedVoronoi: ...

class BoundedVoronoi:
    domain: Domain
    points: np.ndarray  # float (n, 2)
    constrained: np.ndarray  # bool (n,)
    vertices: np.ndarray  # float (V, 2)
    vertex_kinds: np.ndarray  # uint8 (V,)
    regions: list[list[int]]
    cycles: list[list[int]]
    point_region: np.ndarray  # int: the region of each input row, then of each domain point
    input_index: np.ndarray  # int (n,), the first input row of each region, -1 for the domain's
    duplicates: np.ndarray  # int (D, 2), rows (i, j): row i merged into the earlier row j
    ridge_points: np.ndarray  # int (E, 2)
    ridge_vertices: np.ndarray  # int (E, 2)
    ridge_constraint: np.ndarray  # int (E,), -1 for a bisector ridge
    ridge_boundary: np.ndarray  # bool (E,)
    areas: np.ndarray  # float (n,)
    centroids: np.ndarray  # float (n, 2)
    notes: list[str]
    def polygons(self) -> list[list[np.ndarray]]: ...
    def to_shapely(self) -> list[Any]: ...
    def to_geojson(self, path: _Path) -> None: ...
    def to_vtu(self, path: _Path) -> None: ...
    def to_disv(self, path: _Path, top: float = ..., bottom: float = ...) -> None: ...
    def metadata(self) -> list[tuple[str, str]]: ...
    def __len__(self) -> int: ...
