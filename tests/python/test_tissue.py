# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# tessella.Tissue from Python: generators against exact measures, NumPy
# copies and views, properties and their division policies, lineage,
# neighbourhood, and errors for bad input.
import gc
import math

import numpy as np
import pytest

import tessella


def test_rectangular_grid_measures_are_exact():
    t = tessella.rectangular_grid(4, 3, dx=2.0, dy=0.5)
    assert (t.dim, t.embedding) == (2, "planar")
    assert t.num_cells == 12 and t.num_vertices == 20
    np.testing.assert_allclose(t.cell_measures(), 1.0, rtol=0, atol=1e-14)
    assert t.total_measure() == pytest.approx(12.0, abs=1e-12)
    # Cell centroids are the rectangle centres.
    c = t.cell_centroids()
    assert c.shape == (12, 3)
    xs = sorted(set(np.round(c[:, 0], 12)))
    assert xs == [1.0, 3.0, 5.0, 7.0]
    ok, message = t.validate()
    assert ok, message


def test_hexagonal_and_box_grids():
    r = 0.7
    hexes = tessella.hexagonal_grid(5, 4, radius=r)
    np.testing.assert_allclose(hexes.cell_measures(), 1.5 * math.sqrt(3) * r * r, rtol=1e-13)
    boxes = tessella.box_grid(2, 3, 4, dx=0.5, dy=1.0, dz=2.0)
    assert boxes.dim == 3 and boxes.num_cells == 24
    np.testing.assert_allclose(boxes.cell_measures(), 1.0, rtol=1e-13)
    assert boxes.total_measure() == pytest.approx(24.0, rel=1e-13)


def test_positions_copy_is_independent_and_view_shares_memory():
    t = tessella.rectangular_grid(3, 2)
    copy = t.positions()
    version = t.geometry_version
    view = t.positions_view()  # a writable view counts as a geometry change
    assert t.geometry_version > version
    assert view.shape == (t.vertex_slots, 3) and view.dtype == np.float64
    view[:, 0] *= 2.0  # stretch along x through the view: areas double
    np.testing.assert_allclose(t.cell_measures(), 2.0, rtol=1e-14)
    np.testing.assert_allclose(t.positions()[:, 0], 2.0 * copy[:, 0])
    # The copy taken before the edit did not change.
    assert copy[:, 0].max() == pytest.approx(3.0)
    # A read-only view refuses writes.
    ro = t.positions_view(writable=False)
    with pytest.raises(ValueError):
        ro[0, 0] = 1.0


def test_view_keeps_the_tissue_alive():
    view = tessella.rectangular_grid(2, 2, dx=3.0).positions_view()
    gc.collect()
    assert view.base is not None
    assert view[:, 0].max() == pytest.approx(6.0)


def test_set_positions_checks_shape():
    t = tessella.rectangular_grid(2, 1)
    p = t.positions()
    t.set_positions(p * 3.0)
    assert t.total_measure() == pytest.approx(18.0)
    with pytest.raises(ValueError, match=r"set_positions: expected 6 rows"):
        t.set_positions(p[:4])
    with pytest.raises(ValueError, match=r"\(n, 3\)"):
        t.set_positions(np.zeros((6, 2)))


def test_neighbours_of_a_grid():
    t = tessella.rectangular_grid(3, 3)
    counts = sorted(len(t.cell_neighbors(c)) for c in t.cells())
    assert counts == [2, 2, 2, 2, 3, 3, 3, 3, 4]
    for c in t.cells():
        for n in t.cell_neighbors(c):
            assert c in t.cell_neighbors(n)
    # Every wall bounds one (boundary) or two cells.
    boundary = [w for w in t.walls() if t.is_boundary_wall(w)]
    assert len(boundary) == 12
    assert all(len(t.wall_cells(w)) == 2 for w in t.walls() if not t.is_boundary_wall(w))


def test_split_cell_halves_area_and_records_lineage():
    t = tessella.rectangular_grid(2, 1, dx=2.0, dy=1.0)
    t.time = 3.5
    mother = 0
    lineage = t.lineage_id(mother)
    cut = t.split_cell(mother, point=t.cell_centroid(mother), normal=[1, 0, 0])
    daughter = cut["daughter"]
    assert t.num_cells == 3
    assert t.cell_measure(mother) == pytest.approx(1.0, abs=1e-12)
    assert t.cell_measure(daughter) == pytest.approx(1.0, abs=1e-12)
    assert t.total_measure() == pytest.approx(4.0, abs=1e-12)
    assert t.parent_id(daughter) == lineage and t.parent_id(mother) == lineage
    assert t.lineage_id(daughter) != lineage and t.lineage_id(mother) != lineage
    assert t.birth_time(daughter) == 3.5
    ids = [t.lineage_id(c) for c in t.cells()]
    assert len(set(ids)) == len(ids)
    # The cut vertex at x = 1 is shared with the neighbouring cell's walls.
    assert t.validate()[0]


def test_refused_split_leaves_the_tissue_unchanged():
    t = tessella.rectangular_grid(2, 2)
    before = (t.num_cells, t.num_vertices, t.positions().tobytes())
    with pytest.raises(tessella.GeometryError, match="cell"):
        t.split_cell(0, point=[10.0, 10.0, 0.0], normal=[1, 0, 0])  # misses the cell
    assert (t.num_cells, t.num_vertices, t.positions().tobytes()) == before
    assert t.validate()[0]


@pytest.mark.parametrize(
    "options, message",
    [
        ({"snap_tolerance": -1.0}, r"snap_tolerance = -1 is out of range"),
        ({"snap_tolerance": float("nan")}, r"snap_tolerance = nan is out of range"),
        ({"min_fraction": -1.0}, r"min_fraction = -1 is out of range"),
        ({"min_fraction": 0.7}, r"min_fraction = 0.7 is out of range"),
    ],
)
def test_split_cell_refuses_bad_options(options, message):
    t = tessella.rectangular_grid(2, 1)
    before = (t.num_cells, t.positions().tobytes())
    with pytest.raises(tessella.InputError, match=message):
        t.split_cell(0, point=[0.5, 0.5, 0.0], normal=[1, 0, 0], **options)
    assert (t.num_cells, t.positions().tobytes()) == before


def test_property_policies_on_division():
    t = tessella.rectangular_grid(1, 1, dx=4.0, dy=1.0)
    t.add_property("auxin", 8.0, policy="split_by_measure")
    t.add_property("kind", 3, policy="copy", dtype="int32")
    t.add_property("age", 2.5, policy="reset")
    t.set_property("age", [7.0])
    calls = []

    def halve_and_tag(value, fraction):
        calls.append((value, fraction))
        return value * fraction, -1.0

    t.add_property("custom", 10.0, policy="custom", divide=halve_and_tag)
    # Cut at x = 1: the mother keeps the negative side, a quarter of the area.
    cut = t.split_cell(0, point=[1.0, 0.5, 0.0], normal=[1, 0, 0])
    m, d = 0, cut["daughter"]
    auxin = t.property("auxin")
    assert auxin[m] == pytest.approx(2.0) and auxin[d] == pytest.approx(6.0)
    assert auxin[m] + auxin[d] == 8.0  # the parts add up exactly
    assert list(t.property("kind")) == [3, 3]
    assert t.property("kind").dtype == np.int32
    assert list(t.property("age")) == [2.5, 2.5]
    assert len(calls) == 1 and calls[0][0] == 10.0 and calls[0][1] == pytest.approx(0.25)
    np.testing.assert_allclose(t.property("custom"), [2.5, -1.0])
    assert t.property_info("auxin") == ("float64", "split_by_measure")
    assert {"auxin", "kind", "age", "custom", "lineage_id"} <= set(t.property_names())


def test_failing_custom_division_is_raised_after_a_complete_split():
    t = tessella.rectangular_grid(2, 1)
    t.add_property("marker", 4.0, policy="custom", divide=lambda value, fraction: 1 / 0)
    with pytest.raises(ZeroDivisionError):
        t.split_cell(0, point=[0.5, 0.5, 0.0], normal=[1, 0, 0])
    # The split happened and the tissue is whole: lineage updated, values copied.
    assert t.num_cells == 3 and t.validate()[0]
    ids = [t.lineage_id(c) for c in t.cells()]
    assert len(set(ids)) == 3 and t.parent_id(2) == 0
    assert list(t.property("marker")) == [4.0, 4.0, 4.0]
    t.remove_property("marker")
    t.add_property("bad_shape", 1.0, policy="custom", divide=lambda value, fraction: value)
    with pytest.raises(ValueError, match=r"property 'bad_shape': the division function must return \(stays, part\)"):
        t.split_cell(1, point=t.cell_centroid(1), normal=[1, 0, 0])
    assert t.num_cells == 4 and t.validate()[0]


def test_property_view_reflects_edits_both_ways():
    t = tessella.hexagonal_grid(3, 3)
    t.add_property("signal", 0.0)
    view = t.property_view("signal")
    view[:] = np.arange(t.cell_slots)
    np.testing.assert_array_equal(t.property("signal"), np.arange(t.cell_slots))
    t.set_property("signal", np.full(t.cell_slots, 2.0))
    assert (view == 2.0).all()
    t.add_property("direction", [1.0, 0.0, 0.0])
    assert t.property("direction").shape == (t.cell_slots, 3)
    t.property_view("direction")[:, 2] = 5.0
    assert (t.property("direction")[:, 2] == 5.0).all()


def test_vertex_and_wall_properties():
    t = tessella.rectangular_grid(2, 2)
    t.add_property("height", 0.0, degree="vertex")
    assert t.property("height", degree="vertex").shape == (9,)
    t.add_property("stiffness", 1.0, degree="wall")
    assert t.property("stiffness", degree="wall").shape == (t.slots(1),)


def test_bad_input_raises_value_error_with_a_clear_message():
    t = tessella.rectangular_grid(2, 2)
    with pytest.raises(ValueError, match=r"cell 99 is not a live cell"):
        t.cell_measure(99)
    with pytest.raises(ValueError, match=r"cell -1 is not a live cell"):
        t.cell_neighbors(-1)
    with pytest.raises(tessella.InputError, match=r"no property named 'nope'.*known: .*lineage_id"):
        t.property("nope")
    t.add_property("a", 1.0)
    with pytest.raises(ValueError, match=r"property 'a' is already registered"):
        t.add_property("a", 1.0)
    with pytest.raises(ValueError, match=r"policy: expected .* got 'halve'"):
        t.add_property("b", 1.0, policy="halve")
    with pytest.raises(ValueError, match=r"set_property\('a'\): expected a 1-D array of 4 values"):
        t.set_property("a", [1.0, 2.0])
    with pytest.raises(ValueError, match=r"Custom policy needs a division function"):
        t.add_property("c", 1.0, policy="custom")
    assert issubclass(tessella.InputError, tessella.Error)


def test_voronoi_tissue_tiles_its_domain():
    domain = tessella.Rectangle(min=[0, 0, 0], max=[3, 2, 0])
    seeds = tessella.random_seeds(domain, 50, rng_seed=3)
    assert seeds.shape == (50, 3)
    t = tessella.voronoi_tissue(seeds, domain, lloyd_iterations=1)
    assert t.num_cells == 50
    assert t.total_measure() == pytest.approx(6.0, rel=1e-12)
    assert t.validate()[0]
    # Same seed, same seeds: reproducible.
    np.testing.assert_array_equal(seeds, tessella.random_seeds(domain, 50, rng_seed=3))
    dup = np.vstack([seeds[:5], seeds[:1]])
    with pytest.raises(ValueError, match=r"seed"):
        tessella.voronoi_tissue(dup, domain)


def test_dome_vertices_lie_on_the_dome():
    dome = tessella.Dome("spherical_cap", base_radius=2.0, height=1.0)
    seeds = tessella.random_seeds(tessella.Disk(radius=2.0), 40, rng_seed=1)
    t = tessella.dome_tissue(seeds, dome, lloyd_iterations=1)
    assert t.embedding == "surface" and t.num_cells == 40
    p = t.positions()
    rho = np.hypot(p[:, 0], p[:, 1])
    # Sphere through the base circle and the summit: R = (a^2 + h^2) / 2h.
    R = (2.0**2 + 1.0**2) / 2.0
    np.testing.assert_allclose(p[:, 2], np.sqrt(R * R - rho * rho) - (R - 1.0), atol=1e-9)
    np.testing.assert_allclose(dome.summit, [0, 0, 1.0])


def test_generate_makes_any_generator_of_the_table_by_name():
    # The generators of a configuration's tissue.generator, with its keys.
    for name in ("rectangular_grid", "hexagonal_grid", "box_grid", "cylinder", "voronoi", "dome"):
        assert name in tessella.generate.__doc__
    # The cylinder: around x along quad cells, every vertex at the radius from the z axis.
    c = tessella.generate("cylinder", {"around": 12, "along": 3, "radius": 1.5, "length": 4.0})
    assert c.dim == 2 and c.num_cells == 36
    q = c.positions()
    np.testing.assert_allclose(np.hypot(q[:, 0], q[:, 1]), 1.5, rtol=1e-12)
    np.testing.assert_allclose([q[:, 2].min(), q[:, 2].max()], [0.0, 4.0], atol=1e-12)
    t = tessella.generate("hexagonal_grid", {"nx": 3, "ny": 2, "radius": 0.5})
    np.testing.assert_array_equal(t.positions(), tessella.hexagonal_grid(3, 2, radius=0.5).positions())
    # The same random seeds as random_seeds with the same rng_seed.
    v = tessella.generate("voronoi", {"domain": "disk", "count": 30, "disk.radius": 2.0}, rng_seed=3)
    disk = tessella.Disk(radius=2.0)
    expected = tessella.voronoi_tissue(tessella.random_seeds(disk, 30, rng_seed=3), disk)
    np.testing.assert_array_equal(v.positions(), expected.positions())
    d = tessella.generate("dome", {"shape": "paraboloid", "height": 6.0, "count": 20}, rng_seed=1)
    assert d.embedding == "surface" and d.num_cells == 20
    with pytest.raises(ValueError, match=r"unknown generator 'hexagon'.*hexagonal_grid"):
        tessella.generate("hexagon")
    with pytest.raises(ValueError, match=r"parameter 'radius' must be a number > 0"):
        tessella.generate("hexagonal_grid", {"radius": -1.0})
    with pytest.raises(ValueError, match=r"spherical cap cannot be higher"):
        tessella.generate("dome", {"height": 6.0})


def test_copy_is_deep():
    t = tessella.rectangular_grid(2, 2)
    t.add_property("x", 1.0)
    u = t.copy()
    u.set_property("x", [5.0] * 4)
    u.split_cell(0, point=u.cell_centroid(0), normal=[1, 0, 0])
    assert t.num_cells == 4 and (t.property("x") == 1.0).all()
    assert u.num_cells == 5


def test_remove_cell_leaves_tombstones_until_compact():
    t = tessella.rectangular_grid(3, 1)
    lineage = [t.lineage_id(c) for c in (0, 2)]
    t.remove_cell(1)
    assert t.num_cells == 2 and t.cell_slots == 3
    assert list(t.cells()) == [0, 2]
    assert t.cell_measures()[1] == 0.0  # dead slot
    with pytest.raises(ValueError, match=r"cell 1 is not a live cell"):
        t.cell_measure(1)
    maps = t.compact()
    assert list(maps[2]) == [0, -1, 1]
    assert t.cell_slots == 2 and [t.lineage_id(c) for c in t.cells()] == lineage
    assert t.validate()[0]
