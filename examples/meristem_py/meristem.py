#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
"""A shoot apical meristem in Python with the tessella module.

The same model as examples/meristem_cpp/meristem.cpp, written against the
Python bindings and run by tessella.Simulation: the L1 layer is a Voronoi
tissue lifted onto a spherical-cap dome; a meristem velocity field makes a
slowly growing central zone around the summit and a fast periphery, and a
projection keeps every vertex on the dome, so cells flow from the summit
down the flanks. After every step a Python callback recomputes each cell's
identity from its distance to the summit (central zone or periphery); cells
above a size threshold divide across their main axis, and a ParaView series
records every property.

    python3 meristem.py [output-directory]      (default: meristem_out)
"""
import sys
from dataclasses import dataclass

import numpy as np

import tessella

CENTRAL, PERIPHERAL = 0, 1


@dataclass(frozen=True)
class Model:
    """The model's parameters, in the dome's length and time units."""
    base_radius: float = 5.0
    height: float = 2.5
    initial_cells: int = 80
    central_radius: float = 1.5   # central zone: distance to the summit below this
    central_rate: float = 0.02    # relative growth rate of the central zone
    peripheral_rate: float = 0.15  # ... and of the periphery
    division_area: float = 1.6    # mean cell area at division
    division_noise: float = 0.15  # its standard deviation between cells
    dt: float = 0.1
    end: float = 6.0
    output_every: int = 5         # steps between snapshots


def build(m: Model, out_dir: str):
    """The simulation, its series output and the identity update."""
    # --- the tissue: Voronoi cells of the footprint disk, lifted onto the dome
    dome = tessella.Dome("spherical_cap", base_radius=m.base_radius, height=m.height)
    seeds = tessella.random_seeds(tessella.Disk(radius=m.base_radius), m.initial_cells, rng_seed=7)
    tissue = tessella.dome_tissue(seeds, dome, lloyd_iterations=2)
    summit = np.asarray(dome.summit)

    # --- cell properties, each with the policy division applies to it.
    # Identity is recomputed every step, so daughters only need the mother's
    # value until the next update: copy.
    tissue.add_property("zone", PERIPHERAL, policy="copy", dtype="int32")
    tissue.add_property("summit_distance", 0.0, policy="copy")
    # The founder cell each cell descends from: clonal sectors in ParaView.
    tissue.add_property("clone", -1, policy="copy", dtype="int64")
    tissue.set_property("clone", tissue.property("lineage_id"))

    sim = tessella.Simulation(tissue, start=0.0, end=m.end, dt=m.dt, rng_seed=7)

    # --- growth: slow centre, fast periphery, vertices kept on the dome
    field = tessella.MeristemField(apex=summit, axis=[0, 0, 1], central_radius=m.central_radius,
                                   transition_width=0.3, central_rate=m.central_rate,
                                   peripheral_rate=m.peripheral_rate)
    sim.add_stage(tessella.GrowthIntegrator(field, projection=tessella.dome_projection(dome)))

    # --- division: noisy size threshold, plane across the main axis
    sim.add_stage(tessella.DivisionScheduler(tessella.SizeThreshold.noisy(m.division_area, m.division_noise),
                                             tessella.MainAxisRule()))

    def update_identity(s) -> int:
        """Zone and distance to the summit of every cell, from the centroids (vectorised)."""
        t = s.tissue
        distance = np.linalg.norm(t.cell_centroids() - summit, axis=1)
        zone = np.where(distance < m.central_radius, CENTRAL, PERIPHERAL).astype(np.int32)
        # Views are re-fetched each call: divisions may have reallocated the columns.
        t.property_view("summit_distance")[:] = distance
        t.property_view("zone")[:] = zone
        return int((zone[t.cells()] == CENTRAL).sum())

    update_identity(sim)
    return sim, update_identity


def main(argv) -> int:
    out_dir = argv[1] if len(argv) > 1 else "meristem_out"
    m = Model()
    try:
        sim, update_identity = build(m, out_dir)
        central = update_identity(sim)
        print(f"{'time':>6} {'cells':>6} {'central':>8} {'area':>10} {'snapshot':>9}")

        def report(s):
            nonlocal central
            # Registered before the series output: the snapshot holds this step's identity.
            central = update_identity(s)
            if s.steps_done % m.output_every == 0 or s.finished:
                s.tissue.validate_or_throw()  # the complex's invariants, before anything is written
                print(f"{s.time:6.2f} {s.tissue.num_cells:6d} {central:8d} {s.tissue.total_measure():10.4f} "
                      f"{series.snapshots + 1:9d}")

        sim.on_step(report)
        series = sim.attach_series(out_dir, every=m.output_every, name="meristem")  # writes the initial state
        print(f"{sim.time:6.2f} {sim.tissue.num_cells:6d} {central:8d} {sim.tissue.total_measure():10.4f} "
              f"{series.snapshots:9d}")
        sim.run()
        print(f"{sim.tissue.num_cells - m.initial_cells} divisions, series: {series.pvd_path}")
    except (tessella.Error, ValueError) as e:
        print(f"meristem: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
