# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# 3D tissues from arrays: tessella.Tissue.from_polyhedra against closed forms
# (cube volumes, a shared wall, centroids), automatic and given face
# orientation, the errors naming the cell, face or edge at fault, and
# add_polygon refused on a 3D tissue.
import numpy as np
import pytest

import tessella


def cube_corners(x0=0.0, size=1.0):
    """The 8 corners of a cube [x0, x0+size] x [0, size] x [0, size]; corner (i, j, k) is 4i + 2j + k."""
    return [(x0 + size * i, size * j, size * k) for i in (0, 1) for j in (0, 1) for k in (0, 1)]


# The six faces of the cube of cube_corners, each loop with its normal pointing out (right-hand rule).
CUBE_FACES = [
    [0, 1, 3, 2],  # x = 0, normal -x
    [4, 6, 7, 5],  # x = 1, normal +x
    [0, 4, 5, 1],  # y = 0, normal -y
    [2, 3, 7, 6],  # y = 1, normal +y
    [0, 2, 6, 4],  # z = 0, normal -z
    [1, 5, 7, 3],  # z = 1, normal +z
]


def outward_normal_is_right_hand(positions, loop, centre):
    p = np.asarray([positions[v] for v in loop])
    n = np.cross(p[1] - p[0], p[2] - p[0])
    return np.dot(n, p.mean(axis=0) - centre) > 0


def test_the_cube_faces_fixture_points_out():
    pos = cube_corners()
    assert all(outward_normal_is_right_hand(pos, f, np.array([0.5, 0.5, 0.5])) for f in CUBE_FACES)


def test_unit_cube_has_volume_one_and_validates():
    t = tessella.Tissue.from_polyhedra(np.array(cube_corners()), CUBE_FACES, [list(range(6))])
    assert (t.dim, t.embedding, t.num_cells) == (3, "volume", 1)
    assert (t.num_vertices, t.num_edges, t.num_faces) == (8, 12, 6)
    assert t.cell_measure(0) == pytest.approx(1.0, abs=1e-14)
    np.testing.assert_allclose(t.cell_centroid(0), [0.5, 0.5, 0.5], atol=1e-14)
    ok, message = t.validate()
    assert ok, message
    assert t.is_boundary_wall(0)


def test_faces_given_inward_are_turned_out():
    # Every loop reversed: the automatic orientation turns them all back out.
    faces = [list(reversed(f)) for f in CUBE_FACES]
    t = tessella.Tissue.from_polyhedra(cube_corners(size=2.0), faces, [[5, 3, 1, 0, 2, 4]])
    assert t.cell_measure(0) == pytest.approx(8.0, rel=1e-14)
    assert t.validate()[0]


def test_two_cubes_share_one_wall():
    # Cube A on [0,1], cube B on [1,2] in x: B's corners 0..3 are A's corners 4..7.
    positions = cube_corners(0.0) + cube_corners(1.0)[4:]  # 12 vertices
    b = {0: 4, 1: 5, 2: 6, 3: 7, 4: 8, 5: 9, 6: 10, 7: 11}
    faces = [list(f) for f in CUBE_FACES]  # A's six faces; face 1 (x = 1) is the shared wall
    b_faces = [[b[v] for v in f] for f in CUBE_FACES]
    faces += [b_faces[k] for k in (1, 2, 3, 4, 5)]  # B's faces but its x = 1 face, which is face 1
    cells = [[0, 1, 2, 3, 4, 5], [1, 6, 7, 8, 9, 10]]
    t = tessella.Tissue.from_polyhedra(positions, faces, cells)
    assert t.num_cells == 2 and t.num_walls == 11 and t.num_vertices == 12
    np.testing.assert_allclose(t.cell_measures(), [1.0, 1.0], atol=1e-14)
    assert t.total_measure() == pytest.approx(2.0, abs=1e-14)
    np.testing.assert_allclose(t.cell_centroid(1), [1.5, 0.5, 0.5], atol=1e-14)
    assert t.cell_neighbors(0) == [1] and t.cell_neighbors(1) == [0]
    assert sorted(t.wall_cells(1)) == [0, 1] and not t.is_boundary_wall(1)
    ok, message = t.validate()
    assert ok, message
    # The same with the orientation given: face 1's normal (+x) points out of A, into B.
    reversed_flags = [[False] * 6, [True] + [False] * 5]
    t2 = tessella.Tissue.from_polyhedra(positions, faces, cells, reversed=reversed_flags)
    np.testing.assert_allclose(t2.cell_measures(), [1.0, 1.0], atol=1e-14)
    assert t2.validate()[0]


def test_a_tetrahedron_and_a_division():
    positions = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
    faces = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]]  # orientations mixed on purpose
    t = tessella.Tissue.from_polyhedra(positions, faces, [[0, 1, 2, 3]])
    assert t.cell_measure(0) == pytest.approx(1.0 / 6.0, rel=1e-14)
    np.testing.assert_allclose(t.cell_centroid(0), [0.25, 0.25, 0.25], atol=1e-15)
    t.split_cell(0, (0.2, 0.0, 0.0), (1.0, 0.0, 0.0))
    assert t.num_cells == 2
    assert t.total_measure() == pytest.approx(1.0 / 6.0, rel=1e-13)
    assert t.validate()[0]


def error(positions, faces, cells, **kw):
    with pytest.raises(tessella.InputError) as info:
        tessella.Tissue.from_polyhedra(positions, faces, cells, **kw)
    return str(info.value)


def test_errors_name_the_cell_face_and_edge():
    pos = cube_corners()
    six = list(range(6))
    assert "face 2: vertex index 8 is out of range (there are 8 vertices)" in error(
        pos, CUBE_FACES[:2] + [[0, 4, 8, 1]] + CUBE_FACES[3:], [six])
    assert "face 0: vertex index -1 is out of range" in error(pos, [[0, 1, -1]] + CUBE_FACES[1:], [six])
    assert "cell 0: face index 6 is out of range (there are 6 faces)" in error(pos, CUBE_FACES, [[0, 1, 2, 3, 4, 6]])
    assert "cell 0 is open: edge 0-1 of its face 2 is in no other face of the cell" in error(
        pos, CUBE_FACES, [[1, 2, 3, 4, 5]])
    assert "cell 1 has 3 faces, a closed cell needs at least 4" in error(pos, CUBE_FACES, [six, [0, 1, 2]])
    assert "cell 0 lists face 4 twice" in error(pos, CUBE_FACES, [[0, 1, 2, 3, 4, 5, 4]])
    assert "face 1 has 2 vertices" in error(pos, [CUBE_FACES[0], [4, 6]] + CUBE_FACES[2:], [six])
    assert "face 3 passes twice through vertex 2" in error(pos, CUBE_FACES[:3] + [[2, 3, 2, 6]] + CUBE_FACES[4:],
                                                           [six])
    assert "faces 0 and 6 have the same vertices" in error(pos, CUBE_FACES + [[2, 3, 1, 0]], [six])
    assert "face 0 is listed by cells 0, 1 and 2" in error(pos, CUBE_FACES, [six, six, six])
    assert "vertex 3: position (nan, 1, 1) is not finite" in error(
        [p if i != 3 else (float("nan"), 1, 1) for i, p in enumerate(pos)], CUBE_FACES, [six])
    # Two separate cubes listed as one cell.
    positions = cube_corners(0.0) + cube_corners(2.0)
    faces = CUBE_FACES + [[v + 8 for v in f] for f in CUBE_FACES]
    assert "cell 0 is made of separate closed surfaces: its face 6 is not connected to its face 0" in error(
        positions, faces, [list(range(12))])
    # A flat 'cell': a square pyramid squashed into its base plane encloses nothing.
    flat = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, 0)]
    assert "cell 0 encloses no volume" in error(flat, [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
                                                [[0, 1, 2, 3, 4]])
    # An edge in three faces of one cell: two tetrahedra glued along edge 0-1, as one cell.
    p = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (0, -1, 0), (0, 0, -1)]
    f = [[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3], [0, 1, 4], [0, 1, 5], [0, 4, 5], [1, 4, 5]]
    assert "cell 0: edge 0-1 is in 4 of its faces" in error(p, f, [list(range(8))])


def test_given_orientation_errors():
    pos = cube_corners()
    six = list(range(6))
    flags = [False] * 6
    assert "cell 0: with the orientations given its faces point into it" in error(
        pos, CUBE_FACES, [six], reversed=[[True] * 6])
    assert "run the same way along edge" in error(pos, CUBE_FACES, [six], reversed=[[True] + flags[1:]])
    assert "reversed[0] has 5 flags for the 6 faces of cell 0" in error(pos, CUBE_FACES, [six], reversed=[flags[1:]])
    assert "reversed has 2 lists for 1 cells" in error(pos, CUBE_FACES, [six], reversed=[flags, flags])


def test_add_polygon_is_refused_on_a_3d_tissue_and_kept_in_2d():
    t3 = tessella.Tissue(3, "volume")
    for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0)]:
        t3.add_vertex(p)
    with pytest.raises(tessella.InputError, match=r"add_polygon builds the cells of a 2D tissue.*from_polyhedra"):
        t3.add_polygon([0, 1, 2])
    assert t3.num_faces == 0
    t2 = tessella.Tissue(2, "planar")
    for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0)]:
        t2.add_vertex(p)
    assert t2.add_polygon([0, 1, 2]) == 0
    assert t2.num_cells == 1 and t2.cell_measure(0) == pytest.approx(0.5)
