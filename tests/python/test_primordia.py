# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# Primordium detection from Python (tessella.find_primordia, axial_position,
# divergence_deg) on a hand-made ring of cells whose maxima, angles and
# divergence angles are known: the angles are recomputed here with atan2.
import math

import numpy as np
import pytest

import tessella

R = 2.0
RING = 12  # cells 0..11 at angles 30 k degrees on a circle of radius R; cell 12 at the centre


def ring_graph():
    centroid = [(R * math.cos(math.radians(30 * k)), R * math.sin(math.radians(30 * k)), 0.0) for k in range(RING)]
    centroid.append((0.0, 0.0, 0.0))
    # The ring's cells are neighbours in turn; the centre cell has no walls with them (it would be every
    # ring cell's highest neighbour).
    interfaces = [(k, (k + 1) % RING, 1.0) for k in range(RING)]
    interfaces = [(min(i, j), max(i, j), L) for i, j, L in interfaces]
    return tessella.NetworkGraph([1.0] * (RING + 1), interfaces, centroid=np.array(centroid)), centroid


def concentration():
    c = [1.0] * (RING + 1)
    c[0], c[5], c[9] = 5.0, 4.0, 3.0  # angles 0, 150, 270
    c[RING] = 10.0  # the summit: inside min_radius
    return c


def test_maxima_in_the_annulus_by_decreasing_concentration():
    graph, centroid = ring_graph()
    found = tessella.find_primordia(graph, concentration(), threshold=2.0, min_radius=1.0, max_radius=3.0)
    assert found == [0, 5, 9]
    angles = [math.degrees(math.atan2(centroid[k][1], centroid[k][0])) % 360 for k in found]
    for k, a in zip(found, angles):
        angle, radius, distance = tessella.axial_position(centroid[k])
        assert angle == pytest.approx(a, abs=1e-9)
        assert radius == pytest.approx(R)
        assert distance == pytest.approx(R)
    assert angles == pytest.approx([0.0, 150.0, 270.0], abs=1e-9)
    divergences = [tessella.divergence_deg(angles[i - 1], angles[i]) for i in range(1, len(angles))]
    assert divergences == pytest.approx([150.0, 120.0])


def test_separation_and_existing_primordia():
    graph, _ = ring_graph()
    # Cells 0 and 9 are 2 sqrt(2) = 2.83 apart, 0 and 5 3.86, 5 and 9 3.46: with 3, cell 9 is left out.
    assert tessella.find_primordia(graph, concentration(), threshold=2.0, min_radius=1.0, min_separation=3.0) == [0, 5]
    near_zero = [(R, 0.5, 0.0)]
    assert tessella.find_primordia(graph, concentration(), threshold=2.0, min_radius=1.0, min_separation=1.0,
                                   existing=near_zero) == [5, 9]


def test_bad_options_are_errors():
    graph, _ = ring_graph()
    with pytest.raises(tessella.InputError, match="max_radius"):
        tessella.find_primordia(graph, concentration(), threshold=2.0, min_radius=3.0, max_radius=1.0)
    with pytest.raises(tessella.InputError, match="13 cells"):
        tessella.find_primordia(graph, [1.0, 2.0], threshold=2.0)
