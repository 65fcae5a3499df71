# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# The simulation loop from Python: YAML configurations, stages and callbacks
# written in Python, ParaView series output, errors.
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import tessella

UNIFORM_YAML = """
rng_seed: 3
tissue:
  generator: rectangular_grid
  rectangular_grid: {nx: 4, ny: 3, dx: 1.0, dy: 1.0}
growth:
  field: uniform
  scheme: heun
  uniform: {rate: 0.1, center: [2.0, 1.5, 0.0]}
time: {end: 1.0, dt: 0.05}
"""


def pvd_times(path):
    return [float(d.get("timestep")) for d in ET.parse(path).getroot().iter("DataSet")]


def test_yaml_simulation_grows_as_exp_2rt():
    sim = tessella.Simulation.from_yaml(UNIFORM_YAML)
    assert sim.num_steps == 20 and sim.stage_names == ["growth"]
    a0 = sim.tissue.total_measure()
    sim.run()
    assert sim.finished and sim.time == pytest.approx(1.0)
    assert sim.tissue.time == pytest.approx(1.0)
    assert sim.tissue.total_measure() == pytest.approx(a0 * math.exp(2 * 0.1 * 1.0), rel=1e-6)
    with pytest.raises(RuntimeError, match="already over"):
        sim.step()


def test_on_step_callback_sees_every_step_and_can_edit_properties():
    sim = tessella.Simulation.from_yaml(UNIFORM_YAML, overrides=["time.end=0.5"])
    sim.tissue.add_property("x_centroid", 0.0)
    seen = []

    def update(s):
        t = s.tissue
        t.set_property("x_centroid", t.cell_centroids()[:, 0])
        seen.append((s.steps_done, round(s.time, 12)))

    sim.on_step(update)
    sim.run_until(0.25)
    assert seen == [(k, round(0.05 * k, 12)) for k in range(1, 6)]
    sim.run()
    assert len(seen) == 10
    np.testing.assert_allclose(sim.tissue.property("x_centroid"), sim.tissue.cell_centroids()[:, 0])


def test_callback_exception_propagates():
    sim = tessella.Simulation.from_yaml(UNIFORM_YAML)

    def fail(s):
        raise KeyError("stop here")

    sim.on_step(fail)
    with pytest.raises(KeyError, match="stop here"):
        sim.step()


def test_simulation_from_code_with_python_stage(tmp_path):
    t = tessella.rectangular_grid(3, 3)
    t.add_property("signal", 0.0)
    sim = tessella.Simulation(t, start=0.0, end=1.0, dt=0.25, rng_seed=7)
    calls = []

    def produce(tissue, step, time, dt):
        calls.append((step, time, dt))
        tissue.property_view("signal")[:] += dt

    sim.add_stage(tessella.GrowthIntegrator(tessella.uniform_expansion(0.4)))
    sim.add_stage(tessella.DivisionScheduler(tessella.SizeThreshold.fixed(1.5), tessella.MainAxisRule()))
    sim.add_stage(produce, name="production")
    assert sim.stage_names == ["growth", "division", "production"]
    out = sim.attach_series(str(tmp_path / "series"), every=2, name="grid")
    sim.run()
    assert [c[0] for c in calls] == [0, 1, 2, 3]
    assert [c[1] for c in calls] == [0.0, 0.25, 0.5, 0.75]
    # The simulation owns a copy: the original tissue did not grow.
    assert t.num_cells == 9 and t.total_measure() == pytest.approx(9.0)
    # Areas grow as exp(2 r t) (to the scheme's error) and division conserves them.
    h = 0.4 * 0.25  # Heun multiplies lengths by 1 + h + h^2/2 per step
    assert sim.tissue.total_measure() == pytest.approx(9.0 * (1 + h + h * h / 2) ** 8, rel=1e-12)
    assert sim.tissue.num_cells > 9
    signal = sim.tissue.property("signal")
    np.testing.assert_allclose(signal[sim.tissue.cells()], 1.0)  # copy policy: daughters inherit
    # Snapshots at steps 0, 2 and 4 (the last).
    assert out.snapshots == 3
    assert pvd_times(out.pvd_path) == [0.0, 0.5, 1.0]
    assert len(list((tmp_path / "series").glob("grid_*.vtu"))) == 3


def test_stage_exception_is_a_simulation_error_naming_the_stage():
    sim = tessella.Simulation(tessella.rectangular_grid(2, 2), end=1.0, dt=0.5)

    def broken(tissue, step, time, dt):
        raise ValueError("bad concentration")

    sim.add_stage(broken, name="chemistry")
    with pytest.raises(tessella.SimulationError, match=r"step 1 .*stage 'chemistry'.*bad concentration"):
        sim.step()
    with pytest.raises(ValueError, match=r"add_stage: expected a GrowthIntegrator"):
        sim.add_stage(42)
    with pytest.raises(ValueError, match=r"dt must be > 0"):
        tessella.Simulation(tessella.rectangular_grid(1, 1), dt=0.0)


def test_bad_yaml_raises_value_error_naming_key_and_line():
    bad = UNIFORM_YAML.replace("rectangular_grid: {nx: 4", "rectangular_grid: {nx: -4")
    with pytest.raises(ValueError, match=r"tissue\.rectangular_grid\.nx"):
        tessella.Simulation.from_yaml(bad)
    with pytest.raises(tessella.InputError, match=r"tissu"):
        tessella.Simulation.from_yaml(UNIFORM_YAML.replace("tissue:", "tissu:"))
    with pytest.raises(ValueError, match=r"no_such_file\.yaml"):
        tessella.Simulation.from_file("no_such_file.yaml")


def test_from_file_and_run_config_write_a_series(source_dir, tmp_path):
    config = str(source_dir / "configs" / "figure17.yaml")
    sim = tessella.Simulation.from_file(config, overrides=["time.end=0.2"])
    assert sim.stage_names == ["growth", "division"]
    sim.run()
    assert sim.steps_done == 4 and sim.tissue.validate()[0]

    result = tessella.run_config(config, out=str(tmp_path / "fig17"), overrides=["time.end=0.2", "output.every=2"])
    assert result["steps"] == 4 and result["snapshots"] == 3
    assert (tmp_path / "fig17" / "run.yaml").exists()
    assert pvd_times(str(tmp_path / "fig17" / "tissue.pvd")) == pytest.approx([0.0, 0.1, 0.2])
    with pytest.raises(ValueError, match=r"already"):
        tessella.run_config(config, out=str(tmp_path / "fig17"), overrides=["time.end=0.2"])


def test_write_snapshot_restarts_diffusion_bit_for_bit(source_dir, tmp_path):
    config = str(source_dir / "configs" / "morphogen_gradient_2d.yaml")
    whole = tessella.Simulation.from_file(config)
    first = tessella.Simulation.from_file(config)
    for _ in range(6):
        first.step()
    snapshot = tmp_path / "step6.vtu"
    first.write_snapshot(str(snapshot))
    assert (tmp_path / "step6.fields.vtu").exists()
    rest = tessella.Simulation.from_file(
        config, overrides=["tissue.generator=snapshot", "tissue.snapshot.file=" + str(snapshot)])
    whole.run()
    rest.run()
    assert np.array_equal(whole.tissue.positions(), rest.tissue.positions())
    assert np.array_equal(whole.tissue.cell_measures(), rest.tissue.cell_measures())


def test_run_config_refuses_an_empty_out(source_dir, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # the default would be runs/figure17 here
    config = str(source_dir / "configs" / "figure17.yaml")
    with pytest.raises(tessella.InputError, match=r"output.directory: the output directory is empty"):
        tessella.run_config(config, out="", overrides=["time.end=0.2"])
    assert not (tmp_path / "runs").exists()


def test_vtu_round_trip(tmp_path):
    t = tessella.hexagonal_grid(3, 2)
    t.add_property("zone", 0, dtype="int32")
    t.set_property("zone", np.arange(6, dtype=np.int32))
    t.time = 2.5
    path = str(tmp_path / "hex.vtu")
    tessella.write_vtu(t, path)
    back = tessella.read_vtu(path)
    assert back.num_cells == 6 and back.time == 2.5
    np.testing.assert_array_equal(back.property("zone"), np.arange(6))
    np.testing.assert_allclose(back.cell_measures(), t.cell_measures(), rtol=1e-12)
    with pytest.raises(ValueError, match=r"missing\.vtu"):
        tessella.read_vtu(str(tmp_path / "missing.vtu"))
    writer = tessella.SeriesWriter(str(tmp_path / "s"), name="hex")
    writer.write(t)
    writer.write(t, time=3.0)
    assert writer.steps == 2 and pvd_times(writer.pvd_path) == [2.5, 3.0]
