# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# The mechanics section from Python: a turgor-driven run from its YAML file,
# the walls' state as wall properties, and per-cell pressures set by a model.
import math

import numpy as np
import pytest

import tessella

HEXAGON_YAML = """
tissue:
  generator: hexagonal_grid
  hexagonal_grid: {nx: 1, ny: 1, radius: 0.8}
mechanics:
  model: wall_springs
  pressure: 0.1
  young: 2.0
  thickness: 0.5
  tolerance: 1.0e-13
time: {end: 1.0, dt: 0.1}
"""


def ring_strain(n, pressure, stiffness, rest_length):
    """The closed form of a regular N-gon of wall springs (docs/mechanics.md): a / (1 - a)."""
    a = pressure * rest_length / (2 * stiffness * math.tan(math.pi / n))
    return a / (1 - a)


def test_turgor_config_runs_from_python_and_grows(source_dir):
    sim = tessella.Simulation.from_file(str(source_dir / "configs" / "turgor_tissue_2d.yaml"),
                                        overrides=["time.end=1.0"])
    assert "mechanics" in sim.stage_names
    a0 = sim.tissue.total_measure()
    sim.run()
    assert sim.tissue.total_measure() > a0
    rest = np.asarray(sim.tissue.property("rest_length", "wall"))
    strain = np.asarray(sim.tissue.property("wall_strain", "wall"))
    tension = np.asarray(sim.tissue.property("wall_tension", "wall"))
    live = rest > 0
    assert live.sum() == sim.tissue.num_walls
    # The tension is the stiffness E t = 10 * 0.1 times the strain.
    np.testing.assert_allclose(tension[live], 1.0 * strain[live], rtol=1e-12, atol=1e-15)


def test_pressures_set_per_cell_by_a_model():
    # One hexagon of side 0.8 (its circumradius), stiffness E t = 1: the ring's closed form.
    sim = tessella.Simulation.from_yaml(HEXAGON_YAML)
    sim.step()
    strain = np.asarray(sim.tissue.property("wall_strain", "wall"))
    assert len(strain) == 6
    np.testing.assert_allclose(strain, ring_strain(6, 0.1, 1.0, 0.8), rtol=1e-9)
    # A model sets the cell's pressure between steps; the next equilibrium follows it.
    sim.tissue.set_property("turgor_pressure", np.array([0.3]))
    sim.step()
    strain = np.asarray(sim.tissue.property("wall_strain", "wall"))
    np.testing.assert_allclose(strain, ring_strain(6, 0.3, 1.0, 0.8), rtol=1e-9)


def test_membrane_configs_run_from_python(source_dir):
    # The dome sheet, the hypocotyl cylinder and the 3D tissue (docs/mechanics.md,
    # "Membranes from a tissue"), a few steps each: the tissue grows, volumes stay positive.
    for name, end in (("turgor_dome_2p5d", "0.3"), ("hypocotyl_cylinder", "0.5"), ("turgor_tissue_3d", "0.2")):
        sim = tessella.Simulation.from_file(str(source_dir / "configs" / f"{name}.yaml"), overrides=[f"time.end={end}"])
        assert "mechanics" in sim.stage_names
        m0 = sim.tissue.total_measure()
        sim.run()
        assert sim.tissue.total_measure() > m0, name
        young = np.asarray(sim.tissue.property("young_scale", "cell"))
        assert len(young) == sim.tissue.num_cells and (young > 0).all()


def test_membrane_pressure_set_by_a_model_inflates_the_dome(source_dir):
    # Doubling every cell's turgor between steps inflates the dome further than the same step at the old pressure.
    def height_after(factor):
        sim = tessella.Simulation.from_file(str(source_dir / "configs" / "turgor_dome_2p5d.yaml"),
                                            overrides=["time.end=0.2", "mechanics.extensibility=0"])
        sim.step()
        p = np.asarray(sim.tissue.property("turgor_pressure", "cell"))
        sim.tissue.set_property("turgor_pressure", factor * p)
        sim.step()
        return np.asarray(sim.tissue.positions())[:, 2].max()

    assert height_after(2.0) > height_after(1.0)


NEO_HOOKEAN_CYLINDER_YAML = """
tissue:
  generator: cylinder
  cylinder: {around: 24, along: 24, radius: 1.0, length: 8.0}
mechanics:
  model: membranes
  material: neo_hookean
  pressure: 0.01
  young: 10.0
  thickness: 0.1
  fibres: circumferential
  fibre_vector: [0.0, 0.0, 1.0]
time: {end: 0.1, dt: 0.1}
"""


def test_fibre_ratio_per_cell_set_by_a_model():
    # A neo-Hookean cylinder with hoop fibres; a model makes the upper half's fibres ten times stiffer
    # (cell property fibre_ratio): there the hoop strain is about a thirteenth of the isotropic half's
    # (the small-strain laws' compliances: docs/mechanics.md, "Membrane materials").
    sim = tessella.Simulation.from_yaml(NEO_HOOKEAN_CYLINDER_YAML)
    tissue = sim.tissue
    z = np.asarray(tissue.cell_centroids())[:, 2]
    tissue.add_property("fibre_ratio", 1.0, policy="copy")
    tissue.set_property("fibre_ratio", np.where(z > 4.0, 10.0, 1.0))
    before = np.asarray(tissue.positions()).copy()
    sim.step()
    after = np.asarray(sim.tissue.positions())

    def hoop_strain(z0):
        ring = np.abs(before[:, 2] - z0) < 1e-9
        stretch = np.hypot(after[ring, 0], after[ring, 1]).mean()
        return 0.5 * (stretch ** 2 - 1)

    def predicted(ratio):
        # Green strains D(0)^-1 (P r / t, P r / (2 t)), D(0) = mu [[4 + kappa / mu, 2], [2, 4]] (normal part),
        # mu = E / 3, kappa = 4 mu (ratio - 1), r = 1 to first order.
        mu = 10.0 / 3
        d = mu * np.array([[4 + 4 * (ratio - 1), 2], [2, 4]])
        sigma = 0.01 * 1.0 / 0.1
        return np.linalg.solve(d, [sigma, sigma / 2])[0]

    lower, upper = hoop_strain(2.0), hoop_strain(6.0)
    assert lower == pytest.approx(predicted(1.0), rel=0.05)
    assert upper == pytest.approx(predicted(10.0), rel=0.05)
    assert upper < 0.1 * lower

def test_extensibility_set_per_cell_by_a_model():
    # The hexagon ring: its strain is the closed form a / (1 - a) at its rest length; the step's growth multiplies
    # the rest lengths by exp(phi max(strain - threshold, 0) dt) with the cell's phi (docs/mechanics.md).
    sim = tessella.Simulation.from_yaml(HEXAGON_YAML)
    phi = np.asarray(sim.tissue.property("extensibility", "cell"))
    np.testing.assert_array_equal(phi, [0.0])  # the section's extensibility (0 here): no growth
    sim.step()
    np.testing.assert_allclose(np.asarray(sim.tissue.property("rest_length", "wall")), 0.8, rtol=1e-14)
    # A model sets phi = 0.5 between steps: the next step grows the ring at that rate.
    sim.tissue.set_property("extensibility", np.array([0.5]))
    sim.step()
    strain = ring_strain(6, 0.1, 1.0, 0.8)
    grown = math.exp(0.5 * strain * 0.1)
    np.testing.assert_allclose(np.asarray(sim.tissue.property("rest_length", "wall")), 0.8 * grown, rtol=1e-9)
    np.testing.assert_allclose(np.asarray(sim.tissue.property("growth_rate", "wall")), (grown - 1) / 0.1,
                               rtol=1e-9)


def test_wall_stresses_of_a_3d_tissue_as_numpy_arrays(source_dir, tmp_path):
    # Per wall of a 3D tissue under turgor: the mean tension tensor (n, 3, 3), its principal values in the wall's
    # plane and their unit directions, as NumPy arrays; the walls file beside a snapshot holds the same numbers.
    sim = tessella.Simulation.from_file(str(source_dir / "configs" / "turgor_tissue_3d.yaml"),
                                        overrides=["time.end=0.1"])
    sim.step()
    t = sim.tissue
    walls = np.asarray(t.walls())
    tension = np.asarray(t.property("wall_stress", "wall"))[walls]
    assert tension.shape == (len(walls), 3, 3)
    np.testing.assert_array_equal(tension, np.transpose(tension, (0, 2, 1)))
    high = np.asarray(t.property("stress_max", "wall"))[walls]
    low = np.asarray(t.property("stress_min", "wall"))[walls]
    d_high = np.asarray(t.property("stress_direction", "wall"))[walls]
    d_low = np.asarray(t.property("stress_min_direction", "wall"))[walls]
    # Unit directions at right angles, and the tensor's values along them are the principal values.
    np.testing.assert_allclose(np.linalg.norm(d_high, axis=1), 1.0, rtol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(d_low, axis=1), 1.0, rtol=1e-12)
    assert np.abs(np.einsum("ni,ni->n", d_high, d_low)).max() < 1e-12
    scale = np.abs(tension).max()
    np.testing.assert_allclose(np.einsum("ni,nij,nj->n", d_high, tension, d_high), high, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(np.einsum("ni,nij,nj->n", d_low, tension, d_low), low, rtol=0, atol=1e-12 * scale)
    assert (high >= low).all()
    # The outer walls carry the turgor 0.05 and are stretched (those held on the base, all vertices fixed, carry
    # no tension); walls between two cells of equal pressure carry none.
    load = np.asarray(t.property("pressure_load", "wall"))[walls]
    outer = np.array([t.is_boundary_wall(int(w)) for w in walls])
    np.testing.assert_allclose(load[outer], 0.05, rtol=1e-14)
    np.testing.assert_array_equal(load[~outer], 0.0)
    stretched = high[outer] > 1e-6
    assert stretched.mean() > 0.8
    assert np.abs(high[outer][~stretched]).max() < 1e-12
    # The walls file beside a snapshot, read back.
    sim.write_snapshot(str(tmp_path / "tissue_000001.vtu"))
    f = tessella.read_walls(str(tmp_path / "tissue_000001.walls.vtu"))
    np.testing.assert_array_equal(f["wall_id"], walls)
    np.testing.assert_array_equal(f["wall_stress"], tension)
    np.testing.assert_array_equal(f["stress_max"], high)
    np.testing.assert_array_equal(f["stress_direction"], d_high)


def test_membrane_extensibility_set_per_cell(source_dir):
    # phi = 0 in the cells with x < 3: their walls (both cells, or the one cell of an outer wall, at phi = 0) keep
    # their rest area (the growth tensor is the identity up to round-off); the rest grow.
    sim = tessella.Simulation.from_file(str(source_dir / "configs" / "turgor_tissue_3d.yaml"),
                                        overrides=["time.end=0.2"])
    t = sim.tissue
    cells = np.asarray(t.cells())
    phi = np.asarray(t.property("extensibility", "cell"))
    np.testing.assert_array_equal(phi[cells], 1.0)  # the config's extensibility
    left = np.zeros(t.cell_slots, dtype=bool)
    left[cells] = np.asarray(t.cell_centroids())[cells, 0] < 3.0
    phi[left] = 0.0
    t.set_property("extensibility", phi)
    sim.step()
    walls = np.asarray(t.walls())
    rate = np.asarray(t.property("growth_rate", "wall"))[walls]
    still = np.array([all(left[c] for c in t.wall_cells(int(w))) for w in walls])
    assert still.sum() > 50 and (~still).sum() > 50
    np.testing.assert_allclose(rate[still], 0.0, rtol=0, atol=1e-12)
    assert (rate[~still] > 1e-3).sum() > 50
    # A cell whose walls all keep their rest area keeps its own (the sum of its walls').
    kept = set(int(w) for w in walls[still])
    inner = [int(c) for c in cells if all(w in kept for w in t.cell_walls(int(c)))]
    assert len(inner) > 5
    np.testing.assert_allclose(np.asarray(t.property("growth_rate", "cell"))[inner], 0.0, rtol=0, atol=1e-12)
