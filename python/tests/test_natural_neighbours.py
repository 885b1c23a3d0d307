# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# natural_neighbours(): the C++ natural_neighbours example's numbers bit for bit, in rows of
# queries and columns of nodes (the rows given, then the domain's own points); the properties
# the C++ tests prove (partition of unity, linear precision, the Kronecker delta at the nodes,
# nothing across a crack, empty rows outside); scipy's matrix, or ours without scipy.
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import cvt2

SQUARE = ([[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1], [1, 2], [2, 3], [3, 0]])


def own_points(domain):
    if domain.format in ("wkt", "geojson"):
        return np.vstack([domain.vertices, domain.generators])
    return domain.vertices


def dense(m):
    return m.toarray()


@pytest.fixture
def example():
    build = os.environ.get("CVT2_BUILD_DIR")
    path = pathlib.Path(build or ".") / "examples" / "natural_neighbours"
    if not build or not path.exists():
        pytest.skip("the natural_neighbours example is not built (CVT2_BUILD_DIR)")
    return path


def write_points(path, xy):
    path.write_text("".join(f"{x!r} {y!r}\n" for x, y in np.asarray(xy, dtype=float).tolist()))


def run_example(example, domain_file, nodes_file, queries_file, method):
    """The example's lines as (query, [(x, y, w) sorted by x then y])."""
    command = [str(example), str(domain_file), str(nodes_file), str(queries_file)]
    if method == "laplace":
        command.append("--laplace")
    out = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        t = [float(x) for x in line.split()]
        m = int(t[2])
        assert len(t) == 3 + 3 * m
        rows.append(((t[0], t[1]), [tuple(t[3 + 3 * k: 6 + 3 * k]) for k in range(m)]))
    return rows


def hard_queries(domain, nodes, n, seed):
    """At random, at nodes and the domain's own points, on the segments (midpoints and
    partway), a hair beside nodes, outside."""
    rng = np.random.default_rng(seed)
    q = [cvt2.random_points(domain, n, seed=seed)]
    everything = np.vstack([nodes, own_points(domain)])
    q.append(everything[rng.integers(len(everything), size=n // 4)])
    ends = domain.vertices[domain.segments]
    t = rng.random((len(ends), 1))
    q += [ends.mean(axis=1), ends[:, 0] + t * (ends[:, 1] - ends[:, 0])]
    q.append(everything[rng.integers(len(everything), size=n // 4)] + rng.uniform(-1e-9, 1e-9, (n // 4, 2)))
    lo, hi = np.array(domain.bounds[:2]), np.array(domain.bounds[2:])
    q.append([lo - (hi - lo), hi + 0.5 * (hi - lo)])
    return np.vstack(q)


@pytest.mark.parametrize("method", ["sibson", "laplace"])
@pytest.mark.parametrize("file", ["four_clusters.poly", "square_inner_constraints.wkt", "earcut_eberly6.poly"])
def test_the_same_numbers_as_the_cpp_example(example, data, tmp_path, method, file):
    domain = cvt2.Domain.from_file(data / file)
    if file == "four_clusters.poly":  # the example's own data, queries outside included
        nodes = np.loadtxt(data / "four_clusters_points.txt", ndmin=2)
        queries = np.loadtxt(data / "four_clusters_queries.txt", ndmin=2)
    else:
        nodes = cvt2.random_points(domain, 300, seed=4)
        queries = hard_queries(domain, nodes, 200, seed=5)
    write_points(tmp_path / "nodes.txt", nodes)
    write_points(tmp_path / "queries.txt", queries)
    theirs = run_example(example, data / file, tmp_path / "nodes.txt", tmp_path / "queries.txt", method)
    m = cvt2.natural_neighbours(domain, nodes, queries, method=method)
    columns = np.vstack([nodes, own_points(domain)])
    assert m.shape == (len(queries), len(columns))
    assert len(theirs) == len(queries)
    outside = 0
    for k, (q, row) in enumerate(theirs):
        assert q == tuple(queries[k])
        a, b = m.indptr[k], m.indptr[k + 1]
        ours = sorted((*columns[j], w) for j, w in zip(m.indices[a:b], m.data[a:b]))
        assert ours == row, k  # exact: the example prints the shortest decimals of each double
        assert m.inside[k] == bool(row)
        outside += not m.inside[k]
    assert outside >= 2  # the two far away, and maybe some of those a hair beside the boundary


def check_properties(domain, nodes, queries, m):
    columns = np.vstack([nodes, own_points(domain)])
    assert m.shape == (len(queries), len(columns))
    assert np.all(m.data > 0)
    rows = np.diff(m.indptr)
    for k in range(len(queries)):  # columns increasing within a row
        assert np.all(np.diff(m.indices[m.indptr[k]:m.indptr[k + 1]]) > 0)
    assert np.array_equal(rows > 0, m.inside)
    ones = np.ones(len(columns))
    assert np.allclose((m @ ones)[m.inside], 1, rtol=0, atol=1e-13)  # partition of unity
    # The Kronecker delta: a query at a node has that node alone, weight 1, in the first column
    # of the rows at that point.
    first = {}
    for j, p in enumerate(map(tuple, columns)):
        first.setdefault(p, j)
    for k, q in enumerate(map(tuple, queries)):
        if q in first:
            a = m.indptr[k]
            assert rows[k] == 1 and m.indices[a] == first[q] and m.data[a] == 1.0


@pytest.mark.parametrize("method", ["sibson", "laplace"])
def test_partition_of_unity_kronecker_delta_and_linear_precision(method):
    domain = cvt2.Domain(*SQUARE)
    nodes = cvt2.random_points(domain, 2000, seed=3)
    rng = np.random.default_rng(1)
    inner = rng.uniform(0.2, 0.8, (500, 2))  # cells far from the boundary
    queries = np.vstack([inner, nodes[:50], domain.vertices, [[0.5, 0], [1, 0.25]], [[2, 2], [-1e-3, 0.5]]])
    m = cvt2.natural_neighbours(domain, nodes, queries, method=method)
    check_properties(domain, nodes, queries, m)
    assert list(m.inside[-2:]) == [False, False] and m.inside[:-2].all()
    # Linear precision where the query's cell meets no constraint: x = sum phi_i x_i.
    columns = np.vstack([nodes, domain.vertices])
    assert np.abs((m @ columns)[:500] - inner).max() <= 1e-12
    # A query at a domain vertex: that vertex's column, after the nodes.
    at_corner = m.indices[m.indptr[550]:m.indptr[551]]
    assert list(at_corner) == [2000]


def test_nothing_crosses_a_crack_and_a_jump_is_interpolated_on_each_side():
    # The unit square with a crack from (0.2, 0.5) to (0.8, 0.5): the value 1 above it, 0 below.
    vertices = [[0, 0], [1, 0], [1, 1], [0, 1], [0.2, 0.5], [0.5, 0.5], [0.8, 0.5]]
    segments = SQUARE[1] + [[4, 5], [5, 6]]
    cracked = cvt2.Domain(vertices, segments)
    plain = cvt2.Domain(*SQUARE)
    nodes = cvt2.random_points(plain, 600, seed=8)
    nodes = nodes[nodes[:, 1] != 0.5]
    rng = np.random.default_rng(3)
    side = np.where(np.arange(400) % 2, 1.0, -1.0)
    queries = np.column_stack([rng.uniform(0.25, 0.75, 400), 0.5 + side * rng.uniform(1e-9, 0.05, 400)])
    for method in ("sibson", "laplace"):
        m = cvt2.natural_neighbours(cracked, nodes, queries, method=method)
        check_properties(cracked, nodes, queries, m)
        columns = np.vstack([nodes, cracked.vertices])
        above = np.sign(columns[:, 1] - 0.5)
        weights = dense(m)
        across = (weights > 0) & (above[None, :] == -side[:, None])
        assert not across.any()  # no weight from across the crack
        on_crack = (weights[:, above == 0] > 0).any(axis=1)
        value = m @ (above > 0).astype(float)
        expected = (side > 0).astype(float)
        assert (~on_crack).sum() > 200
        assert np.abs(value - expected)[~on_crack].max() <= 1e-14
        # Without the crack, weights do leak: the test can tell.
        leaky = dense(cvt2.natural_neighbours(plain, nodes, queries, method=method))
        plain_columns = np.vstack([nodes, plain.vertices])
        assert ((leaky > 0) & (np.sign(plain_columns[:, 1] - 0.5)[None, :] == -side[:, None])).sum() > 100


def test_columns_follow_the_nodes_order_and_duplicates_go_to_the_first(data):
    domain = cvt2.Domain.from_file(data / "four_clusters.wkt")  # own points: vertices, points
    n = 300
    nodes = cvt2.random_points(domain, n, seed=2)
    queries = cvt2.random_points(domain, 300, seed=9)
    m = dense(cvt2.natural_neighbours(domain, nodes, queries))
    own = len(own_points(domain))
    assert m.shape == (300, n + own)
    assert m[:, n:].any() and m[:, n + len(domain.vertices):].any()
    # Shuffled nodes: the same weights, their columns shuffled alike.
    perm = np.random.default_rng(4).permutation(n)
    shuffled = dense(cvt2.natural_neighbours(domain, nodes[perm], queries))
    assert np.allclose(shuffled[:, :n], m[:, perm], rtol=0, atol=1e-14)
    assert np.allclose(shuffled[:, n:], m[:, n:], rtol=0, atol=1e-14)
    # Nodes given twice, and on the domain's first 3 points (corners): one generator each,
    # whose weight goes to the first column at its point, the node's; the others' columns are
    # empty.
    repeated = np.vstack([nodes, nodes[:20], own_points(domain)[:3]])
    k = len(repeated)
    r = dense(cvt2.natural_neighbours(domain, repeated, queries))
    assert r.shape == (300, k + own)
    close = dict(rtol=0, atol=1e-14)
    assert np.allclose(r[:, :n], m[:, :n], **close)
    assert not r[:, n:n + 20].any()
    assert np.allclose(r[:, n + 20:k], m[:, n:n + 3], **close) and m[:, n:n + 3].any()
    assert not r[:, k:k + 3].any()
    assert np.allclose(r[:, k + 3:], m[:, n + 3:], **close)


def test_scipy_matrix_and_ours_agree(monkeypatch):
    domain = cvt2.Domain(*SQUARE)
    nodes = cvt2.random_points(domain, 500, seed=1)
    queries = np.vstack([cvt2.random_points(domain, 300, seed=2), [[3, 3]]])
    values = np.random.default_rng(5).random((len(nodes) + 4, 3))
    monkeypatch.setitem(sys.modules, "scipy", None)
    monkeypatch.setitem(sys.modules, "scipy.sparse", None)
    ours = cvt2.natural_neighbours(domain, nodes, queries)
    monkeypatch.undo()
    assert isinstance(ours, cvt2.CsrMatrix)
    assert ours.shape == (301, 504) and ours.nnz == len(ours.data) == ours.indptr[-1]
    assert ours.inside.shape == (301,) and not ours.inside[-1] and ours.inside[:-1].all()
    # M @ values: one value a column (1-D), or columns of values (2-D), as the dense product
    full = ours.toarray()
    assert full.shape == ours.shape
    assert np.allclose(ours @ values[:, 0], full @ values[:, 0], rtol=0, atol=1e-15)
    assert np.allclose(ours @ values, full @ values, rtol=0, atol=1e-15)
    assert np.array_equal(ours.dot(values), ours @ values)
    assert (ours @ values)[-1].tolist() == [0, 0, 0]  # the query outside: an empty row
    assert np.allclose(ours @ (1j * values[:, 0]), 1j * (full @ values[:, 0]), rtol=0, atol=1e-15)
    for bad in (values[:-1, 0], values[None, :, 0], np.ones((504, 2, 2))):
        with pytest.raises(ValueError, match="the matrix has 504 columns"):
            ours @ bad
    sparse = pytest.importorskip("scipy.sparse")
    theirs = cvt2.natural_neighbours(domain, nodes, queries)
    assert isinstance(theirs, sparse.csr_matrix)
    assert np.array_equal(theirs.inside, ours.inside)
    for name in ("indptr", "indices", "data"):
        assert np.array_equal(getattr(theirs, name), getattr(ours, name)), name
    assert theirs.shape == ours.shape
    # the same sums, in the same order: the same bits
    assert np.array_equal(theirs @ values[:, 0], ours @ values[:, 0])
    assert np.array_equal(theirs @ values, ours @ values)


def test_bad_input():
    domain = cvt2.Domain(*SQUARE)
    nodes = [[0.5, 0.5], [0.2, 0.3]]
    with pytest.raises(cvt2.DomainError, match=r"queries\[1\]: query \(nan, 0.5\) is not finite") as e:
        cvt2.natural_neighbours(domain, nodes, [[0.1, 0.1], [np.nan, 0.5]])
    assert e.value.index == 1
    with pytest.raises(cvt2.DomainError, match=r"nodes\[1\]: generator \(2, 0\.3\) lies outside"):
        cvt2.natural_neighbours(domain, [[0.5, 0.5], [2, 0.3]], [[0.1, 0.1]])
    with pytest.raises(ValueError, match="method must be 'sibson' or 'laplace', not 'linear'"):
        cvt2.natural_neighbours(domain, nodes, [[0.1, 0.1]], method="linear")
    with pytest.raises(TypeError, match="queries must be an array of shape \\(n, 2\\) of numbers, not None"):
        cvt2.natural_neighbours(domain, nodes, None)
    with pytest.raises(TypeError, match="nodes must be an array .* not an array of bool"):
        cvt2.natural_neighbours(domain, np.ones((3, 2), dtype=bool), [[0.1, 0.1]])
    empty = cvt2.natural_neighbours(domain, [], np.empty((0, 2)))
    assert empty.shape == (0, 4) and empty.nnz == 0


@pytest.mark.parametrize("method", ["sibson", "laplace"])
def test_weights_double_precision_cannot_give_are_an_error_not_an_empty_row(method):
    # Nodes 2 ulps apart at 1e15 (Sibson's areas round to nothing), a square 1e160 wide (areas
    # and squared lengths overflow): an empty row or NaNs, which M @ values would take silently.
    off = -1e15
    square = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], dtype=float)
    ring = [[0, 1], [1, 2], [2, 3], [3, 0]]
    far = cvt2.Domain(square + off, ring)
    tight = np.array([[7.125, 4.625], [7.125, 4.875]]) + off
    if method == "sibson":
        with pytest.raises(cvt2.DomainError, match=r"query \(.*\): its natural-neighbour weights "
                                                   r"vanish or are not finite in double precision"):
            cvt2.natural_neighbours(far, tight, np.array([[7.125, 4.75]]) + off, method=method)
    s = 1e160
    huge = cvt2.Domain(square * s, ring)
    with pytest.raises(cvt2.DomainError, match="vanish or are not finite"):
        cvt2.natural_neighbours(huge, np.array([[3, 3], [6, 7]]) * s, [[5 * s, 5 * s]],
                                method=method)
    # the same nodes at a sane scale: a row summing to 1
    m = cvt2.natural_neighbours(cvt2.Domain(square, ring), [[3, 3], [6, 7]], [[5, 5]], method=method)
    assert m.toarray().sum() == pytest.approx(1)
