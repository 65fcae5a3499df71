# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# Cell networks (tessella.NetworkSystem, CVODE) against an independent
# integration of the same equations written here with NumPy and SciPy's
# solve_ivp, and against their conservation law.
import math

import numpy as np
import pytest

import tessella

scipy_integrate = pytest.importorskip("scipy.integrate")

N = 10
MEASURE = np.array([1.0 + 0.15 * i for i in range(N)])
# A ring of 10 cells plus two chords; interface measures vary.
INTERFACES = [(i, (i + 1) % N, 0.5 + 0.1 * i) for i in range(N)] + [(0, 5, 0.3), (2, 7, 0.8)]
INTERFACES = [(min(i, j), max(i, j), L) for i, j, L in INTERFACES]
P = {"v": 2.0, "K": 0.8, "p": 0.2, "d": 0.6, "e": 0.3}
PERM_A, PERM_H = 0.4, 1.5
PIN_RATE, PIN_TOTAL, PIN_BASE, PIN_KAPPA = 0.7, 1.2, 2.0, 0.1


def reference_rhs(t, y):
    """The same model written out by hand: amounts -> d amounts / dt."""
    a = y[0::2] / MEASURE
    h = y[1::2] / MEASURE
    ra = P["v"] * a**2 / ((P["K"] ** 2 + a**2) * (1 + h)) + P["p"] - P["d"] * a
    rh = a**2 - P["e"] * h
    da = MEASURE * ra
    dh = MEASURE * rh
    neighbours = [[] for _ in range(N)]
    for i, j, L in INTERFACES:
        neighbours[i].append((j, L))
        neighbours[j].append((i, L))
        ja = PERM_A * L * (a[i] - a[j])
        jh = PERM_H * L * (h[i] - h[j])
        da[i] -= ja
        da[j] += ja
        dh[i] -= jh
        dh[j] += jh
    f = PIN_BASE**a
    for i in range(N):
        denominator = PIN_KAPPA + sum(L * f[j] for j, L in neighbours[i])
        for j, L in neighbours[i]:
            flux = PIN_RATE * PIN_TOTAL * L * f[j] / denominator * a[i]
            da[i] -= flux
            da[j] += flux
    out = np.empty_like(y)
    out[0::2] = da
    out[1::2] = dh
    return out


def make_system(jacobian="exact"):
    model = tessella.NetworkModel(
        [
            tessella.NetworkSpecies("a", "v * a^2 / ((K^2 + a^2) * (1 + h)) + p - d * a", PERM_A),
            tessella.NetworkSpecies("h", "a^2 - e * h", PERM_H),
        ],
        parameters=P,
        pin=tessella.PinTransport("a", base=PIN_BASE, rate=PIN_RATE, total=PIN_TOTAL, saturation=PIN_KAPPA),
    )
    graph = tessella.NetworkGraph(list(MEASURE), INTERFACES)
    return tessella.NetworkSystem(model, graph, jacobian)


def initial_amounts():
    rng = np.random.default_rng(11)
    c = rng.uniform(0.2, 2.0, size=2 * N)
    c[0::2] *= MEASURE
    c[1::2] *= MEASURE
    return c


def test_rhs_matches_the_equations_written_out():
    system = make_system()
    y = initial_amounts()
    np.testing.assert_allclose(system.rhs(0.0, list(y)), reference_rhs(0.0, y), rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("linear_solver", ["klu", "gmres"])
@pytest.mark.parametrize("jacobian", ["exact", "neighbours"])
@pytest.mark.parametrize("rtol", [1e-6, 1e-9])
def test_ten_cell_nonlinear_network_matches_solve_ivp(rtol, jacobian, linear_solver):
    system = make_system(jacobian)
    y0 = initial_amounts()
    T = 8.0
    ours = np.array(system.integrate(list(y0), 0.0, T, relative_tolerance=rtol, absolute_tolerance=rtol * 1e-3,
                                     linear_solver=linear_solver))
    ref = scipy_integrate.solve_ivp(reference_rhs, (0.0, T), y0, method="LSODA", rtol=1e-12, atol=1e-14)
    assert ref.success
    # Both solutions within the requested tolerance of each other (with a safety factor for
    # the accumulation of local errors over the run).
    np.testing.assert_allclose(ours, ref.y[:, -1], rtol=20 * rtol, atol=20 * rtol * 1e-3)


@pytest.mark.parametrize("linear_solver", ["klu", "gmres"])
def test_transport_alone_conserves_each_species(linear_solver):
    model = tessella.NetworkModel(
        [tessella.NetworkSpecies("a", "", PERM_A), tessella.NetworkSpecies("h", "", PERM_H)],
        pin=tessella.PinTransport("a", base=PIN_BASE, rate=PIN_RATE),
    )
    system = tessella.NetworkSystem(model, tessella.NetworkGraph(list(MEASURE), INTERFACES))
    y0 = initial_amounts()
    y = system.integrate(list(y0), 0.0, 20.0, linear_solver=linear_solver)
    for s in range(2):
        assert abs(system.total_amount(y, s) - system.total_amount(list(y0), s)) <= 1e-12 * system.total_amount(
            list(y0), s
        )


def test_graph_of_a_tissue_and_bad_input():
    tissue = tessella.rectangular_grid(3, 2, 1.0, 1.0)
    graph, cells = tessella.network_graph(tissue)
    assert graph.num_cells == 6 and len(cells) == 6
    assert len(graph.interfaces) == 7
    np.testing.assert_allclose(graph.measure, np.ones(6))
    c = tessella.initial_concentrations("1 + x", graph)
    assert min(c) == pytest.approx(1.5) and max(c) == pytest.approx(3.5)
    with pytest.raises(tessella.InputError, match="species 'a'"):
        tessella.NetworkSystem(tessella.NetworkModel([tessella.NetworkSpecies("a", "a * nope")]), graph)
    with pytest.raises(tessella.InputError, match="not a species"):
        tessella.NetworkModel([tessella.NetworkSpecies("a")], pin=tessella.PinTransport("b"))
