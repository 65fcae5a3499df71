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



# Smith et al. (2006): PIN made in proportion to auxin, P_i = P0 + P1 a_i, and the efflux saturating,
# T PIN_ij a_i^2 / (1 + s a_i^2).
SMITH_P1, SMITH_S = 0.6, 0.25


def smith_reference_rhs(t, y):
    a = y / MEASURE
    da = np.zeros_like(y)
    neighbours = [[] for _ in range(N)]
    for i, j, L in INTERFACES:
        neighbours[i].append((j, L))
        neighbours[j].append((i, L))
    f = PIN_BASE**a
    for i in range(N):
        denominator = PIN_KAPPA + sum(L * f[j] for j, L in neighbours[i])
        for j, L in neighbours[i]:
            pin = (PIN_TOTAL + SMITH_P1 * a[i]) * L * f[j] / denominator
            flux = PIN_RATE * pin * a[i] ** 2 / (1 + SMITH_S * a[i] ** 2)
            da[i] -= flux
            da[j] += flux
    return da


def test_smith_pin_options_match_the_equations_and_solve_ivp():
    pin = tessella.PinTransport("a", base=PIN_BASE, rate=PIN_RATE, total=PIN_TOTAL, saturation=PIN_KAPPA,
                                efflux="saturating", efflux_saturation=SMITH_S, total_per_concentration=SMITH_P1)
    assert pin.efflux == "saturating" and pin.total_per_concentration == SMITH_P1
    system = tessella.NetworkSystem(tessella.NetworkModel([tessella.NetworkSpecies("a")], pin=pin),
                                    tessella.NetworkGraph(list(MEASURE), INTERFACES))
    y0 = initial_amounts()[0::2]
    np.testing.assert_allclose(system.rhs(0.0, list(y0)), smith_reference_rhs(0.0, y0), rtol=1e-12, atol=1e-12)
    ours = np.array(system.integrate(list(y0), 0.0, 5.0, relative_tolerance=1e-8, absolute_tolerance=1e-11))
    ref = scipy_integrate.solve_ivp(smith_reference_rhs, (0.0, 5.0), y0, method="LSODA", rtol=1e-12, atol=1e-14)
    assert ref.success
    np.testing.assert_allclose(ours, ref.y[:, -1], rtol=2e-7, atol=1e-10)
    with pytest.raises(tessella.InputError):
        tessella.PinTransport("a", efflux="quadratic")


# --- PIN as a state: with_the_flux and expression -------------------------------------------------


def flux_pin(**kw):
    args = dict(model="with_the_flux", rate=2.0, basal=0.1, production=3.0, decay=0.5, flux_exponent=2.0,
                flux_saturation=0.2, total=2.0, initial=0.3)
    args.update(kw)
    return tessella.PinTransport("auxin", **args)


@pytest.mark.parametrize("bounded", [False, True])
def test_with_the_flux_two_cells_reach_the_closed_form_steady_state(bounded):
    # A source cell (p per unit measure) and a sink cell (-d c): the net flux density through the wall carries
    # all that is made, phi = p V0 / L; docs/networks.md, "PIN as a state".
    V0, V1, L, p, d, D = 1.0, 1.5, 0.8, 1.0, 0.5, 0.1
    pin = flux_pin(bounded=bounded)
    assert pin.dynamic and pin.model == "with_the_flux"
    model = tessella.NetworkModel([tessella.NetworkSpecies("auxin", "p * source - d * (1 - source) * auxin", D)],
                                  {"p": p, "d": d}, ["source"], pin)
    graph = tessella.NetworkGraph([V0, V1], [(0, 1, L)], properties={"source": [1.0, 0.0]})
    system = tessella.NetworkSystem(model, graph)
    assert system.size == 4 and system.num_pin_states == 2
    y = system.integrate([0.5 * V0, 0.5 * V1, 0.3, 0.3], 0.0, 400.0, relative_tolerance=1e-11,
                         absolute_tolerance=1e-13)
    phi = p * V0 / L
    a = pin.basal + pin.production * phi**2 / (1 + pin.flux_saturation * phi**2)
    p10 = pin.basal / (pin.decay + (pin.basal * L / pin.total if bounded else 0.0))
    p01 = a / (pin.decay + (a * L / pin.total if bounded else 0.0))
    c1 = p * V0 / (d * V1)
    c0 = (phi + (pin.rate * p10 + D) * c1) / (pin.rate * p01 + D)
    assert y[0] / V0 == pytest.approx(c0, rel=1e-8)
    assert y[1] / V1 == pytest.approx(c1, rel=1e-8)
    assert y[system.pin_index(0, 0)] == pytest.approx(p01, rel=1e-8)
    assert y[system.pin_index(0, 1)] == pytest.approx(p10, rel=1e-8)
    np.testing.assert_allclose(system.pin_density(y)[0], [p01, p10], rtol=1e-8)
    np.testing.assert_allclose(system.pin(y)[0], [L * p01, L * p10], rtol=1e-8)


def test_expression_pin_matches_with_the_flux_and_its_jacobian_matches_differences():
    species = [tessella.NetworkSpecies("auxin", "1 - 0.3 * auxin", 0.2)]
    expression = ("(0.1 + 3 * (flux > 0 ? flux^2 : 0) / (1 + 0.2 * (flux > 0 ? flux^2 : 0))) * (1 - pin_cell / 2)"
                  " - 0.5 * pin")
    graph = tessella.NetworkGraph(list(MEASURE), INTERFACES)
    flux = tessella.NetworkSystem(tessella.NetworkModel(species, pin=flux_pin(bounded=True)), graph)
    expr = tessella.NetworkSystem(
        tessella.NetworkModel(species, pin=flux_pin(model="expression", expression=expression)), graph)
    rng = np.random.default_rng(4)
    y = list(rng.uniform(0.2, 2.0, flux.size))
    np.testing.assert_allclose(expr.rhs(0.0, y), flux.rhs(0.0, y), rtol=1e-13, atol=1e-14)
    for system in (flux, expr):
        J = system.jacobian(0.0, y)
        fd = np.zeros_like(J)
        for k in range(system.size):
            h = 1e-6 * max(1.0, abs(y[k]))
            up, down = list(y), list(y)
            up[k] += h
            down[k] -= h
            fd[:, k] = (np.array(system.rhs(0.0, up)) - np.array(system.rhs(0.0, down))) / (2 * h)
        assert np.max(np.abs(J - fd)) <= 1e-6 * np.max(np.abs(J))


def test_with_the_flux_transport_conserves_the_amount():
    model = tessella.NetworkModel([tessella.NetworkSpecies("auxin", "", 0.05)], pin=flux_pin(bounded=True))
    system = tessella.NetworkSystem(model, tessella.NetworkGraph(list(MEASURE), INTERFACES))
    y0 = list(np.random.default_rng(2).uniform(0.2, 2.0, system.size))
    y = system.integrate(y0, 0.0, 20.0)
    assert abs(system.total_amount(y, 0) - system.total_amount(y0, 0)) <= 1e-12 * system.total_amount(y0, 0)
    with pytest.raises(tessella.InputError, match="PIN densities"):
        system.rhs(0.0, y0[:N])
    with pytest.raises(tessella.InputError, match="needs pin.expression"):
        tessella.NetworkModel([tessella.NetworkSpecies("auxin")], pin=flux_pin(model="expression"))


def test_neighbourhood_terms_relax_a_ring_mode_in_closed_form():
    # dc_i/dt = k (mean_a - a) on a ring of equal cells and walls: c_i = 2 + exp(-k (1 - cos th) t) cos(th i).
    n, mode, k, t1 = 12, 3, 0.7, 2.5
    th = 2 * math.pi * mode / n
    graph = tessella.NetworkGraph([1.0] * n, [(min(i, (i + 1) % n), max(i, (i + 1) % n), 1.0) for i in range(n)])
    system = tessella.NetworkSystem(
        tessella.NetworkModel([tessella.NetworkSpecies("a", "k * (mean_a - a)")], {"k": k}), graph)
    y = system.integrate([2 + math.cos(th * i) for i in range(n)], 0.0, t1, relative_tolerance=1e-10,
                         absolute_tolerance=1e-12)
    exact = [2 + math.exp(-k * (1 - math.cos(th)) * t1) * math.cos(th * i) for i in range(n)]
    np.testing.assert_allclose(y, exact, rtol=1e-7)
