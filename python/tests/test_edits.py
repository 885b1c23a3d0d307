# Copyright (c) 2026 CVT_2 contributors. SPDX-License-Identifier: GPL-3.0-or-later
# cvt2.ConstraintEditor: after a sequence of edits, the diagram is the one built from scratch on
# the equivalent domain (the remaining polylines as inner constraints, a removed polyline's
# vertices as free points); a refused edit changes nothing; the reports are numpy arrays.
import numpy as np
import pytest

import cvt2

SQUARE = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], dtype=float)
RING = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])


def cells_by_generator(diagram):
    """Area and centroid of each cell, rows sorted by generator."""
    order = np.lexsort((diagram.points[:, 1], diagram.points[:, 0]))
    return diagram.points[order], diagram.areas[order], diagram.centroids[order]


def scratch(editor, points, removed_points):
    vertices, segments = [SQUARE], [RING]
    n = len(SQUARE)
    for i in range(editor.number_of_constraints):
        if editor.is_removed(i):
            continue
        line = editor.constraint_vertices(i)
        vertices.append(line)
        segments.append(np.column_stack([np.arange(n, n + len(line) - 1), np.arange(n + 1, n + len(line))]))
        n += len(line)
    domain = cvt2.Domain(np.vstack(vertices), np.vstack(segments))
    return cvt2.bounded_voronoi(domain, np.vstack([points] + removed_points))


def test_edits_match_a_rebuild():
    rng = np.random.default_rng(3)
    points = rng.uniform(0, 10, (800, 2))
    editor = cvt2.ConstraintEditor(cvt2.Domain(SQUARE, RING), points)
    crack = editor.insert_constraint([[0, 3.05], [0.7, 3.2]])
    assert crack == 0
    for k in range(1, 12):
        report = editor.extend_constraint(crack, [0.7 + 0.35 * k, 3.2 + 0.1 * np.sin(k)], spacing=0.2)
        assert report["changed_cells"].shape[1] == 2 and len(report["changed_cells"]) > 0
        assert report["new_vertices"].shape == (len(report["new_vertices"]), 2)
        assert report["retagged_faces"] > 0
        indptr, nodes, weights = report["weights_indptr"], report["weights_nodes"], report["weights"]
        assert len(indptr) == len(report["new_vertices"]) + 1 and len(nodes) == len(weights)
        for k, q in enumerate(report["new_vertices"]):  # Sibson before the edit: sums to 1
            w, x = weights[indptr[k]:indptr[k + 1]], nodes[indptr[k]:indptr[k + 1]]
            assert abs(w.sum() - 1) < 1e-12 and (w >= 0).all()
            assert np.linalg.norm(w @ x - q) < 1.0  # the nodes around it
    slit = editor.insert_constraint([[5, 8], [6, 8.6], [7, 8.1]])
    editor.move_constrained_vertex([6, 8.6], [6.1, 8.2])  # sweeps over free generators
    assert np.allclose(editor.constraint_vertices(slit)[1], [6.1, 8.2])
    other = editor.insert_constraint([[2, 7], [3, 6]])
    removed = [editor.constraint_vertices(other)]
    editor.remove_constraint(other)
    assert editor.is_removed(other)
    got = cells_by_generator(editor.bounded_voronoi())
    want = cells_by_generator(scratch(editor, points, removed))
    assert len(got[0]) == len(want[0])
    assert np.array_equal(got[0], want[0])
    assert np.allclose(got[1], want[1], rtol=1e-9, atol=1e-12)
    assert np.allclose(got[2], want[2], rtol=1e-9, atol=1e-12)
    assert abs(got[1].sum() - 100) < 1e-9


def test_refused_edits_change_nothing():
    rng = np.random.default_rng(4)
    editor = cvt2.ConstraintEditor(cvt2.Domain(SQUARE, RING), rng.uniform(0, 10, (300, 2)))
    editor.insert_constraint([[1, 1], [3, 3]])
    before = cells_by_generator(editor.bounded_voronoi())
    with pytest.raises(cvt2.DomainError, match=r"crosses constraint 0"):
        editor.insert_constraint([[1, 3], [3, 1]])
    with pytest.raises(cvt2.DomainError, match=r"outside the domain"):
        editor.extend_constraint(0, [12, 3])
    with pytest.raises(cvt2.DomainError, match=r"crosses itself"):
        editor.insert_constraint([[5, 5], [6, 6], [6, 5], [5, 6]])
    with pytest.raises(cvt2.DomainError, match=r"no constraint 7"):
        editor.remove_constraint(7)
    with pytest.raises(cvt2.DomainError, match=r"no vertex"):
        editor.move_constrained_vertex([4.5, 4.5], [4.6, 4.6])
    after = cells_by_generator(editor.bounded_voronoi())
    assert all(np.array_equal(a, b) for a, b in zip(before, after))
    assert editor.number_of_constraints == 1  # the refused insertions took no id


def test_bad_input_is_an_error():
    editor = cvt2.ConstraintEditor(cvt2.Domain(SQUARE, RING), np.random.default_rng(5).uniform(0, 10, (100, 2)))
    editor.insert_constraint([[1, 1], [2, 2]])
    with pytest.raises(cvt2.DomainError, match="not finite"):
        editor.insert_constraint([[np.nan, 5], [5, 5]])
    with pytest.raises(cvt2.DomainError):
        editor.extend_constraint(0, [np.inf, 3])
    with pytest.raises(ValueError):
        editor.extend_constraint(0, "ab")
    with pytest.raises(ValueError):
        editor.move_constrained_vertex([[1, 1, 1]], [2, 2])
    with pytest.raises(cvt2.DomainError, match="million"):
        editor.extend_constraint(0, [3, 3], spacing=1e-300)
    # Ids that name no constraint (was libstdc++'s "vector::_M_range_check" for these two)
    for call in (editor.constraint_vertices, editor.is_removed, editor.remove_constraint):
        for bad in (1, 99):
            with pytest.raises(cvt2.DomainError, match=f"there is no constraint {bad}$"):
                call(bad)
    before = editor.report
    assert editor.extend_constraint(0, [2, 2])["changed_cells"].shape == (0, 2)  # no change
    assert len(before["changed_cells"]) > 0


def test_a_move_next_to_a_hole_keeps_the_hole():
    # the crack's end at the hole's corner: moving its other end sweeps over generators, so the
    # vertex is removed and inserted again, and the hole's face is among those around it
    hole = [[4, 4], [6, 4], [5, 6]]
    domain = cvt2.Domain(np.vstack([SQUARE, hole]), np.vstack([RING, [[4, 5], [5, 6], [6, 4]]]), holes=[[5, 4.5]])
    points = cvt2.random_points(domain, 400, seed=2)
    editor = cvt2.ConstraintEditor(domain, points)
    editor.insert_constraint([[4, 4], [3, 2]])
    editor.move_constrained_vertex([3, 2], [3.6, 1.0])
    got = cells_by_generator(editor.bounded_voronoi())
    assert abs(got[1].sum() - (100 - 2)) < 1e-9  # the hole is still out
    moved = cvt2.Domain(
        np.vstack([SQUARE, hole, [[4, 4], [3.6, 1.0]]]),
        np.vstack([RING, [[4, 5], [5, 6], [6, 4], [7, 8]]]),
        holes=[[5, 4.5]],
    )
    want = cells_by_generator(cvt2.bounded_voronoi(moved, points))
    assert np.array_equal(got[0], want[0])
    assert np.allclose(got[1], want[1], rtol=1e-9, atol=1e-12)


def test_lips_carry_and_interpolate_each_side():
    """A crack along y = 5: each lip of its new vertices is fed from its side only, and the
    natural-neighbour matrix with lips interpolates a field that jumps across it exactly, off
    its tips."""
    rng = np.random.default_rng(8)
    points = rng.uniform(0, 10, (1500, 2))
    points = points[np.abs(points[:, 1] - 5) > 1e-9]
    editor = cvt2.ConstraintEditor(cvt2.Domain(SQUARE, RING), points)
    crack = editor.insert_constraint([[0, 5], [1, 5]])
    report = editor.extend_constraint(crack, [6, 5], spacing=0.25)
    assert len(report["lips"]) == 2 * (len(report["new_vertices"]) - 1)  # the tip has one lip
    for k in range(len(report["lips"])):
        rows = slice(report["lip_weights_indptr"][k], report["lip_weights_indptr"][k + 1])
        dy = report["lip_weights_nodes"][rows][:, 1] - 5
        assert np.all(dy >= 0) or np.all(dy <= 0)
        assert report["lip_weights"][rows].sum() == pytest.approx(1, abs=1e-12)

    # the diagram of the cracked square, and queries on both sides
    line = editor.constraint_vertices(crack)
    n = len(SQUARE)
    domain = cvt2.Domain(
        np.vstack([SQUARE, line]),
        np.vstack([RING, np.column_stack([np.arange(n, n + len(line) - 1), np.arange(n + 1, n + len(line))])]),
    )
    queries = np.column_stack([rng.uniform(0.5, 5.5, 2000), 5 + rng.choice([-1, 1], 2000) * rng.uniform(1e-9, 0.5, 2000)])
    plain = cvt2.natural_neighbours(domain, points, queries)
    m = cvt2.natural_neighbours(domain, points, queries, lips=True)
    d = plain.shape[1]
    lips = m.lip_columns
    assert m.shape == (len(queries), d + len(lips))
    assert len(lips) == 2 * (len(line) - 2) + 2  # inner crack vertices; the end on the boundary
    fold = np.zeros((d + len(lips), d))
    fold[np.arange(d), np.arange(d)] = 1
    fold[d + np.arange(len(lips)), lips] = 1
    dense = np.asarray(m @ fold) if hasattr(m, "toarray") else None
    if dense is not None:
        assert np.array_equal(dense, plain.toarray())
    # the field: 1 above, 0 below; each lip's value from the queries that use it
    all_points = np.vstack([points, domain.vertices])
    above = (all_points[:, 1] > 5).astype(float)
    value = np.concatenate([above, np.zeros(len(lips))])
    mm = m.toarray() if hasattr(m, "toarray") else None
    if mm is None:
        return
    used_lips = 0
    for k in range(len(lips)):
        used = mm[:, d + k] > 0
        if not used.any():  # a lip far from the queries
            continue
        used_lips += 1
        sides = np.sign(queries[used, 1] - 5)
        assert np.all(sides == sides[0])  # a lip is seen from one side
        value[d + k] = 1.0 if sides[0] > 0 else 0.0
    assert used_lips >= len(lips) - 6
    on_crack = np.isclose(all_points[:, 1], 5) & (all_points[:, 0] > 0)
    tip = np.flatnonzero(on_crack & (all_points[:, 0] == line[-1][0]))
    clear = mm[:, tip].sum(axis=1) == 0
    assert clear.sum() > 1000
    expected = (queries[:, 1] > 5).astype(float)
    assert np.allclose((mm @ value)[clear], expected[clear], atol=1e-12, rtol=0)


def test_relax_moves_only_near_the_tip_and_matches_a_rebuild():
    rng = np.random.default_rng(4)
    points = cvt2.optimize(cvt2.Domain(SQUARE, RING), rng.uniform(0, 10, (1500, 2))).points
    editor = cvt2.ConstraintEditor(cvt2.Domain(SQUARE, RING), points)
    crack = editor.insert_constraint([[0, 4.1], [0.5, 4.2]])
    for k in range(1, 8):
        editor.extend_constraint(crack, [0.5 + 0.3 * k, 4.2 + 0.05 * k])
        line = editor.constraint_vertices(crack)
        moved = editor.relax(rings=2, iterations=4)
        assert 0 < len(moved["moved_from"]) < 100
        # near the crack only: within a few cell sizes (0.26) of its vertices
        near = np.min(np.hypot(*(moved["moved_from"][:, None, :] - line[None, :, :]).T), axis=0)
        assert np.max(near) < 1.5
    now = editor.bounded_voronoi()
    # the diagram kept current is the one built from scratch on the points as they are
    fixed = np.vstack([SQUARE, editor.constraint_vertices(crack)])
    free = np.array([p for p in now.points if not (fixed == p).all(axis=1).any()])
    assert len(free) == 1500
    rebuilt = scratch(editor, free, [])
    a, b = cells_by_generator(now), cells_by_generator(rebuilt)
    assert np.array_equal(a[0], b[0])
    assert np.allclose(a[1], b[1], rtol=0, atol=1e-12)
    assert np.allclose(a[2], b[2], rtol=0, atol=1e-12)


def test_ridges_name_the_constraints_the_editor_inserted_and_moved():
    # A domain with an inner wall (segments 4 and 5), a crack grown by the editor, a slit moved,
    # one removed: each ridge on a line names it, by the editor's id or the domain's segment.
    vertices = np.vstack([SQUARE, [[2, 2], [4, 2.5], [6, 2]]])
    segments = np.vstack([RING, [[4, 5], [5, 6]]])
    rng = np.random.default_rng(5)
    editor = cvt2.ConstraintEditor(cvt2.Domain(vertices, segments), rng.uniform(0, 10, (600, 2)))
    crack = editor.insert_constraint([[0, 6.05], [1.1, 6.2]])
    editor.extend_constraint(crack, [3.3, 6.6], spacing=0.3)
    slit = editor.insert_constraint([[5, 8], [6, 8.6], [7, 8.1]])
    editor.move_constrained_vertex([6, 8.6], [6.1, 8.2])
    gone = editor.insert_constraint([[7, 4], [8, 5]])
    editor.remove_constraint(gone)
    editor.move_constrained_vertex([4, 2.5], [4.1, 2.9])  # the domain's wall, bent
    d = editor.bounded_voronoi()
    ids, rows = d.ridge_edit_constraint, d.ridge_constraint
    assert ids is not None and len(ids) == len(rows)
    assert set(ids) == {-1, crack, slit}
    assert ((ids < 0) | (rows < 0)).all()  # never both
    ends = d.vertices[d.ridge_vertices]
    length = np.hypot(*(ends[:, 1] - ends[:, 0]).T)
    for c in (crack, slit):  # a ridge a pair of cells, whole along the line
        line = editor.constraint_vertices(c)
        assert length[ids == c].sum() == pytest.approx(np.hypot(*np.diff(line, axis=0).T).sum())
    wall = np.hypot(4.1 - 2, 2.9 - 2) + np.hypot(6 - 4.1, 2 - 2.9)
    assert length[(rows == 4) | (rows == 5)].sum() == pytest.approx(wall)
    assert cvt2.bounded_voronoi(cvt2.Domain(vertices, segments), [[1, 1]]).ridge_edit_constraint is None


def test_a_domain_segment_split_then_bent_keeps_its_name():
    # A crack ending on a hole's edge splits it at (6, 5); the hole's corner (6, 6) then moves:
    # the edge runs (6, 4) - (6, 5) - (6.1, 6.1), and its ridges still name segment 5 (the walk
    # from one end to the other along the segment stopped at the bend: none named it). A wall
    # through a free generator that a move made a vertex of it, then its other end moved, too.
    v = np.array([[0, 0], [10, 0], [10, 10], [0, 10], [4, 4], [6, 4], [6, 6], [4, 6]], float)
    s = np.vstack([RING, [[4, 5], [5, 6], [6, 7], [7, 4]]])
    editor = cvt2.ConstraintEditor(cvt2.Domain(v, s, holes=[[5, 5]]),
                                   [[1, 1], [9, 9], [1, 9], [9, 1]])
    editor.insert_constraint([[6, 5], [8, 5]])
    editor.move_constrained_vertex([6, 6], [6.1, 6.1])
    d = editor.bounded_voronoi()
    ends = d.vertices[d.ridge_vertices]
    length = np.hypot(*(ends[:, 1] - ends[:, 0]).T)
    assert length[d.ridge_constraint == 5].sum() == pytest.approx(1 + np.hypot(0.1, 1.1))
    assert length[d.ridge_constraint == 6].sum() == pytest.approx(np.hypot(2.1, 0.1))
    wall = cvt2.ConstraintEditor(
        cvt2.Domain(np.vstack([SQUARE, [[1.5, 5.5], [3, 8.5]]]), np.vstack([RING, [[4, 5]]])),
        [[2, 7], [8, 8], [8, 2]])
    wall.move_constrained_vertex([3, 8.5], [2.5, 8.5])  # now through the generator at (2, 7)
    wall.move_constrained_vertex([1.5, 5.5], [1, 5.5])
    d = wall.bounded_voronoi()
    ends = d.vertices[d.ridge_vertices]
    length = np.hypot(*(ends[:, 1] - ends[:, 0]).T)
    expected = np.hypot(1, 1.5) + np.hypot(0.5, 1.5)
    assert length[d.ridge_constraint == 4].sum() == pytest.approx(expected)


def test_a_move_reports_no_new_vertex_and_weights_rows_match():
    # A move that removes the vertex and inserts it again reported it as a new vertex with no
    # row of weights (indptr [0] for one vertex); a move inserts none, whichever way it goes.
    editor = cvt2.ConstraintEditor(cvt2.Domain(SQUARE, RING),
                                   [[5, 5], [2, 2], [8, 8], [2, 8], [8, 2]])
    editor.insert_constraint([[3, 4], [4, 4]])
    for to in ([6, 6], [6.2, 6.1]):  # over the generator at (5, 5): reinserted; then a slide
        report = editor.move_constrained_vertex(editor.constraint_vertices(0)[1], to)
        assert len(report["new_vertices"]) == 0
        assert len(report["weights_indptr"]) == len(report["new_vertices"]) + 1
        assert len(report["changed_cells"]) > 0


def test_a_closed_polyline_is_inserted_as_extend_closes_one():
    ring = [[7, 1], [9, 1], [9, 3], [7, 1]]
    points = np.random.default_rng(2).uniform(0, 10, (300, 2))
    closed = cvt2.ConstraintEditor(cvt2.Domain(SQUARE, RING), points)
    c = closed.insert_constraint(ring)
    assert len(closed.constraint_vertices(c)) == 4
    grown = cvt2.ConstraintEditor(cvt2.Domain(SQUARE, RING), points)
    g = grown.insert_constraint(ring[:3])
    grown.extend_constraint(g, ring[3])
    for x, y in zip(cells_by_generator(closed.bounded_voronoi()),
                    cells_by_generator(grown.bounded_voronoi())):
        assert np.array_equal(x, y)
    # Folding back at the closing point, or through the ring, is still refused.
    for bad in ([[7, 5], [9, 5], [8, 5], [7, 5]], [[7, 6], [9, 6], [9, 8], [8, 6], [7, 6]]):
        with pytest.raises(cvt2.DomainError, match="crosses itself"):
            closed.insert_constraint(bad)


def test_points_moved_onto_the_boundary_are_noted():
    editor = cvt2.ConstraintEditor(cvt2.Domain(SQUARE, RING), [[1, 1], [10.5, 2]],
                                   boundary_tolerance=1.0)
    assert any("(10, 2)" in note for note in editor.notes)
    assert editor.bounded_voronoi().notes == editor.notes
