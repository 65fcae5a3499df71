# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# examples/meristem_py/meristem.py, run as a user runs it: a fresh
# interpreter, the series it writes read back and checked.
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np

import tessella


def test_meristem_example_writes_a_paraview_series(source_dir, tmp_path):
    out = tmp_path / "meristem"
    script = source_dir / "examples" / "meristem_py" / "meristem.py"
    run = subprocess.run([sys.executable, str(script), str(out)], capture_output=True, text=True,
                         env=dict(os.environ), timeout=600)
    assert run.returncode == 0, run.stderr
    assert "series:" in run.stdout

    # 60 steps of 0.1, a snapshot every 5 steps and the initial state: 13.
    datasets = list(ET.parse(out / "meristem.pvd").getroot().iter("DataSet"))
    assert len(datasets) == 13
    times = [float(d.get("timestep")) for d in datasets]
    np.testing.assert_allclose(times, np.arange(13) * 0.5, atol=1e-9)
    for d in datasets:
        assert (out / d.get("file")).exists()

    first = tessella.read_vtu(str(out / datasets[0].get("file")))
    last = tessella.read_vtu(str(out / datasets[-1].get("file")))
    assert first.num_cells == 80 and last.num_cells > first.num_cells
    assert last.validate()[0]
    # The identity written is the one of the written geometry: zone follows
    # summit_distance, which is the centroid's distance to the summit (0, 0, 2.5).
    cells = last.cells()
    distance = last.property("summit_distance")[cells]
    np.testing.assert_allclose(distance, np.linalg.norm(last.cell_centroids()[cells] - [0, 0, 2.5], axis=1),
                               rtol=1e-9)
    np.testing.assert_array_equal(last.property("zone")[cells], np.where(distance < 1.5, 0, 1))
    assert 0 < (last.property("zone")[cells] == 0).sum() < len(cells)
    # Clones are founder lineage ids, each cell's lineage descends from one.
    clones = last.property("clone")[cells]
    assert set(clones) <= set(first.property("lineage_id")[first.cells()])
