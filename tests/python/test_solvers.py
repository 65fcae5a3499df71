# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# Meshing and the finite-element / compartment solvers from Python, checked
# against exact solutions: P1 elements reproduce linear fields exactly, the
# zero-flux and compartment schemes conserve amounts, two compartments relax
# exponentially, and a uniaxial stretch has stress E * strain.
import math
import pathlib

import numpy as np
import pytest

import tessella


def boundary_facets_at(mesh, axis, value, tol=1e-9):
    """Boundary wall facets whose nodes all lie on the plane x[axis] = value."""
    nodes, facets = mesh.nodes, mesh.wall_facets
    on_plane = np.all(np.abs(nodes[facets][:, :, axis] - value) < tol, axis=1)
    return np.flatnonzero(on_plane & mesh.facet_on_boundary).tolist()


@pytest.fixture
def grid():
    return tessella.rectangular_grid(4, 2, 1.0, 1.0)  # [0, 4] x [0, 2], 8 cells


@pytest.fixture
def grid_mesh(grid):
    return tessella.mesh_tissue(grid, tessella.MeshOptions(max_edge_length=0.3))


def test_mesh_arrays_and_cell_measures_match_the_tissue():
    domain = tessella.Rectangle(min=[0, 0, 0], max=[5, 4, 0])
    t = tessella.voronoi_tissue(tessella.random_seeds(domain, 25, rng_seed=3), domain)
    mesh = tessella.mesh_tissue(t, tessella.MeshOptions(min_angle_degrees=25, max_edge_length=0.4))
    assert mesh.dim == 2
    assert mesh.nodes.shape == (mesh.num_nodes, 3) and mesh.elements.shape == (mesh.num_elements, 3)
    assert mesh.element_cell.shape == (mesh.num_elements,)
    assert mesh.wall_facets.shape == (mesh.num_wall_facets, 2) and mesh.facet_wall.shape == (mesh.num_wall_facets,)
    assert mesh.facet_on_boundary.dtype == bool
    # Every tissue vertex is a node at the same place.
    nv = mesh.node_vertex
    pos = t.positions()
    assert sorted(nv[nv >= 0].tolist()) == sorted(t.vertices().tolist())
    np.testing.assert_allclose(mesh.nodes[nv >= 0], pos[nv[nv >= 0]], atol=1e-12)
    # Per-cell mesh measures are the cell areas.
    np.testing.assert_allclose(mesh.cell_measures(t.cell_slots), t.cell_measures(), rtol=1e-9)
    assert mesh.total_measure() == pytest.approx(20.0, rel=1e-9)
    assert mesh.element_measures().sum() == pytest.approx(20.0, rel=1e-9)
    # Wall facets of a wall add up to the wall's length.
    lengths = mesh.wall_facet_measures()
    for w in t.walls()[:10]:
        assert lengths[mesh.facet_wall == w].sum() == pytest.approx(t.wall_measure(w), rel=1e-9)


@pytest.mark.parametrize("method", [tessella.VolumeMethod.CELL_BY_CELL, tessella.VolumeMethod.WHOLE_TISSUE])
def test_mesh_of_a_box_tissue_has_tetrahedra_filling_each_cell(method):
    t = tessella.box_grid(2, 2, 1, 1.0, 1.0, 1.5)
    options = tessella.MeshOptions(max_volume=0.05, volume_method=method)
    assert options.volume_method == method
    mesh = tessella.mesh_tissue(t, options)
    assert mesh.dim == 3 and mesh.elements.shape[1] == 4
    np.testing.assert_allclose(mesh.cell_measures(t.cell_slots), t.cell_measures(), rtol=1e-9)
    assert mesh.radius_edge_ratios().max() <= 1.5 * (1 + 1e-6)


def test_a_mesh_estimated_above_max_elements_is_refused_before_meshing(grid):
    assert tessella.MeshOptions().max_elements == 20_000_000
    # Area 8 with edges <= 1e-6: at least 1.8e13 triangles, refused at once.
    with pytest.raises(tessella.InputError, match=r"max_edge_length = 1e-06.*1\.84752e\+13 triangles.*max_elements = 2e\+07"):
        tessella.mesh_tissue(grid, tessella.MeshOptions(max_edge_length=1e-6))
    with pytest.raises(tessella.InputError, match=r"max_elements = 50"):
        tessella.mesh_tissue(grid, tessella.MeshOptions(max_edge_length=0.3, max_elements=50))
    options = tessella.MeshOptions(max_edge_length=0.3)
    options.max_elements = 0  # no limit
    assert tessella.mesh_tissue(grid, options).num_elements > 50


def test_steady_diffusion_between_two_dirichlet_ends_is_linear(grid_mesh):
    mesh = grid_mesh
    left, right = boundary_facets_at(mesh, 0, 0.0), boundary_facets_at(mesh, 0, 4.0)
    assert left and right
    assert mesh.min_angles().min() >= 20.0 - 1e-9  # the default bound; the grid has no sharp input corners
    sp = tessella.Species(diffusivity=[2.0], dirichlet=[tessella.DirichletCondition(left, 1.0),
                                                        tessella.DirichletCondition(right, 0.0)])
    d = tessella.DiffusionReaction(mesh, [sp], tessella.DiffusionOptions(linear=tessella.LinearSolverOptions(method="direct")))
    u = d.solve_steady()
    assert u.shape == (mesh.num_nodes, 1)
    np.testing.assert_allclose(u[:, 0], 1.0 - mesh.nodes[:, 0] / 4.0, atol=1e-10)
    np.testing.assert_allclose(d.values(0), u[:, 0])
    rep = d.last_report
    assert rep.method == tessella.SolverMethod.Direct and rep.unknowns > 0 and rep.relative_residual < 1e-10


def test_per_cell_diffusivity_gives_the_piecewise_linear_profile(grid, grid_mesh):
    # D = 1 for x < 2 and 3 for x > 2: equal flux, so the left slope is 3 times
    # the right one: u(0) = 1, u(2) = 1/4, u(4) = 0.
    mesh = grid_mesh
    cx = grid.cell_centroids()[:, 0]
    D = np.where(cx < 2.0, 1.0, 3.0)
    sp = tessella.Species(diffusivity=D, dirichlet=[tessella.DirichletCondition(boundary_facets_at(mesh, 0, 0.0), 1.0),
                                                    tessella.DirichletCondition(boundary_facets_at(mesh, 0, 4.0), 0.0)])
    x = mesh.nodes[:, 0]
    exact = np.where(x < 2.0, 1.0 - 3.0 * x / 8.0, 0.25 * (4.0 - x) / 2.0)
    u = tessella.DiffusionReaction(mesh, [sp]).solve_steady()[:, 0]
    np.testing.assert_allclose(u, exact, atol=1e-10)


@pytest.mark.parametrize("scheme", ["implicit_euler", "crank_nicolson"])
def test_zero_flux_transient_conserves_the_total_amount(grid_mesh, scheme):
    sp = tessella.Species(diffusivity=[0.5])
    d = tessella.DiffusionReaction(grid_mesh, [sp], tessella.DiffusionOptions(scheme=scheme))
    d.set_state(0, lambda x, t: x[0] ** 2 + 2.0 * x[1])
    amount0 = d.total_amount(0)
    spread0 = np.ptp(d.values(0))
    d.advance(2.0, 0.1)
    assert d.time == pytest.approx(2.0)
    assert d.total_amount(0) == pytest.approx(amount0, rel=1e-10)
    assert np.ptp(d.values(0)) < 0.5 * spread0  # it did diffuse


def test_decay_and_explicit_reaction_converge_to_the_ode_of_a_uniform_state(grid_mesh):
    # A uniform state stays uniform under zero flux: du/dt = -k u - u (the
    # reaction, explicit in time), u = exp(-(k + 1) t). Crank-Nicolson with the
    # reaction extrapolated to the half step is second order (docs/solvers.md):
    # halving dt quarters the error.
    def error(dt):
        sp = tessella.Species(diffusivity=[1.0], decay=[0.5])
        d = tessella.DiffusionReaction(grid_mesh, [sp], tessella.DiffusionOptions(scheme="crank_nicolson"))
        d.set_reaction(lambda u: -u)
        d.set_state(np.ones((grid_mesh.num_nodes, 1)))
        d.advance(1.0, dt)
        u = d.values(0)
        assert np.ptp(u) < 1e-12
        return abs(u[0] - math.exp(-1.5))

    e1, e2 = error(0.02), error(0.01)
    assert e2 < 1e-2 * math.exp(-1.5)
    assert 3.3 < e1 / e2 < 4.7


@pytest.mark.parametrize("scheme,dt,rtol", [("crank_nicolson", 1e-3, 1e-6), ("implicit_euler", 1e-4, 1e-3)])
def test_two_compartments_relax_exponentially(scheme, dt, rtol):
    V1, V2, A, P = 1.0, 2.0, 0.5, 0.3
    net = tessella.CompartmentNetwork(volume=[V1, V2], walls=[tessella.CompartmentWall(0, 1, area=A, permeability=P)])
    ct = tessella.CompartmentTransport(net, scheme)
    c0 = np.array([3.0, 0.0])
    c = ct.advance(c0, 2.0, dt)
    lam = P * A * (1 / V1 + 1 / V2)
    c_inf = (V1 * c0[0] + V2 * c0[1]) / (V1 + V2)
    d = (c0[0] - c0[1]) * math.exp(-lam * 2.0)
    np.testing.assert_allclose(c, [c_inf + V2 / (V1 + V2) * d, c_inf - V1 / (V1 + V2) * d], rtol=rtol)
    assert ct.total_amount(c) == pytest.approx(ct.total_amount(c0), rel=1e-10)  # 20000 steps of round-off
    np.testing.assert_allclose(c0, [3.0, 0.0])  # the input array is not modified
    np.testing.assert_allclose(ct.rate(c0), [-P * A * 3.0 / V1, P * A * 3.0 / V2])


@pytest.mark.parametrize("model", ["plane_stress", "plane_strain"])
def test_uniaxial_stretch_gives_stress_e_times_strain(grid_mesh, model):
    mesh = grid_mesh
    E, nu, L, delta = 7.0, 0.3, 4.0, 0.01
    origin = int(np.flatnonzero(np.linalg.norm(mesh.nodes, axis=1) < 1e-12)[0])
    problem = tessella.ElasticityProblem(
        model=model, young=[E], poisson=[nu],
        displacement=[tessella.DisplacementCondition(facets=boundary_facets_at(mesh, 0, 0.0), fixed=(True, False, False)),
                      tessella.DisplacementCondition(facets=boundary_facets_at(mesh, 0, L), fixed=(True, False, False),
                                                     value=(delta, 0.0, 0.0)),
                      tessella.DisplacementCondition(nodes=[origin], fixed=(True, True, False))])
    r = tessella.solve_elasticity(mesh, problem)
    strain = delta / L
    modulus = E if model == "plane_stress" else E / (1 - nu * nu)  # eps_zz = 0 stiffens plane strain
    assert r.displacement.shape == (mesh.num_nodes, 3) and r.cell_stress.shape == (8, 6)
    np.testing.assert_allclose(r.cell_stress[:, 0], modulus * strain, rtol=1e-9)
    np.testing.assert_allclose(r.cell_stress[:, [1, 3, 4, 5]], 0.0, atol=1e-9 * E * strain)
    np.testing.assert_allclose(r.displacement[:, 0], strain * mesh.nodes[:, 0], atol=1e-12)
    np.testing.assert_allclose(r.principal_stress[:, 2], modulus * strain, rtol=1e-9)
    assert r.principal_directions.shape == (8, 3, 3)
    assert abs(r.principal_directions[0][:, 2] @ [1.0, 0.0, 0.0]) == pytest.approx(1.0)
    np.testing.assert_allclose(tessella.voigt_to_tensor(r.cell_stress[0]), np.diag([modulus * strain, 0, r.cell_stress[0, 2]]),
                               atol=1e-12)


def test_field_transfer_after_a_division_is_exact_for_linear_fields(grid, grid_mesh):
    old, old_mesh = grid, grid_mesh
    new = old.copy()
    new.split_cell(0, new.cell_centroid(0), (1.0, 0.3, 0.0))
    new_mesh = tessella.mesh_tissue(new, tessella.MeshOptions(max_edge_length=0.25))
    anc = tessella.ancestor_cells(old, new)
    assert anc[0] == 0 and anc[new.cell_slots - 1] == 0 and anc[3] == 3
    f = lambda x: 1.0 + 2.0 * x[:, 0] - 0.5 * x[:, 1]
    g = tessella.interpolate_nodal_field(old, old_mesh, f(old_mesh.nodes), new, new_mesh)
    np.testing.assert_allclose(g, f(new_mesh.nodes), atol=1e-10)
    c = tessella.transfer_concentration(old, old_mesh, f(old_mesh.nodes), new, new_mesh)
    assert tessella.cell_integrals(new_mesh, c).sum() == pytest.approx(tessella.cell_integrals(old_mesh, f(old_mesh.nodes)).sum(), rel=1e-12)
    amounts, lost = tessella.transfer_cell_amounts(old, np.arange(8.0) + 1, new)
    assert lost == 0.0 and amounts.sum() == pytest.approx(36.0) and amounts[3] == pytest.approx(4.0)


def test_linear_solver_choices(grid_mesh):
    assert tessella.solver_available("auto") and tessella.solver_available(tessella.SolverMethod.Direct)
    assert tessella.solver_available("conjugate_gradient")
    sp = tessella.Species(dirichlet=[tessella.DirichletCondition(boundary_facets_at(grid_mesh, 0, 0.0), 1.0)], decay=[1.0])
    opts = tessella.DiffusionOptions(linear=tessella.LinearSolverOptions(method="conjugate_gradient", tolerance=1e-12))
    d = tessella.DiffusionReaction(grid_mesh, [sp], opts)
    d.solve_steady()
    rep = d.last_report
    assert rep.method == tessella.SolverMethod.ConjugateGradient and rep.iterations > 0 and rep.relative_residual <= 1e-12
    for method in ("cholmod", "amg_cg"):
        if not tessella.solver_available(method):
            with pytest.raises(ValueError, match="TESSELLA_WITH"):
                tessella.DiffusionReaction(grid_mesh, [sp], tessella.DiffusionOptions(
                    linear=tessella.LinearSolverOptions(method=method))).solve_steady()


def test_write_mesh_vtu_with_fields(tmp_path, grid_mesh):
    u = grid_mesh.nodes[:, 0].copy()
    path, walls = tmp_path / "mesh.vtu", tmp_path / "walls.vtu"
    tessella.write_mesh_vtu(grid_mesh, str(path), point_data={"u": u},
                            element_data={"measure": grid_mesh.element_measures()}, walls_path=str(walls),
                            compression="none")
    text = path.read_text(errors="replace")
    assert 'Name="u"' in text and 'Name="cell_id"' in text and 'Name="measure"' in text
    assert 'Name="wall_id"' in walls.read_text(errors="replace")
    with pytest.raises(ValueError, match="u"):
        tessella.write_mesh_vtu(grid_mesh, str(path), point_data={"u": u[:-1]})


def test_bad_input_raises_value_error_with_a_clear_message(grid_mesh):
    mesh = grid_mesh
    with pytest.raises(ValueError, match="[Dd]iffusivity"):
        tessella.DiffusionReaction(mesh, [tessella.Species(diffusivity=[-1.0])])
    with pytest.raises(ValueError, match=str(mesh.num_wall_facets + 5)):
        tessella.DiffusionReaction(mesh, [tessella.Species(dirichlet=[tessella.DirichletCondition([mesh.num_wall_facets + 5])])])
    with pytest.raises(ValueError, match="min_angle"):
        tessella.MeshOptions(min_angle_degrees=-3.0)
    with pytest.raises(ValueError, match="crank_nicolson"):
        tessella.TimeScheme("crank-nicholson")
    with pytest.raises(ValueError, match="species 2"):
        tessella.DiffusionReaction(mesh, [tessella.Species()]).total_amount(2)
    with pytest.raises(ValueError, match="3 concentrations for 2 cells"):
        tessella.CompartmentTransport(tessella.CompartmentNetwork([1.0, 1.0], [])).step(np.zeros(3), 0.1)
    with pytest.raises(ValueError, match="dt"):
        tessella.CompartmentTransport(tessella.CompartmentNetwork([1.0, 1.0], [])).step(np.zeros(2), -0.1)
    with pytest.raises(ValueError, match="rigid-body modes"):
        tessella.solve_elasticity(mesh, tessella.ElasticityProblem(model="plane_stress"))
    fixed = [tessella.DisplacementCondition(facets=boundary_facets_at(mesh, 0, 0.0))]
    with pytest.raises(ValueError, match=r"Poisson's ratio of cell \d+ must be in \(-1, 0.5\)"):
        tessella.solve_elasticity(mesh, tessella.ElasticityProblem(model="plane_stress", poisson=[0.5], displacement=fixed))
    with pytest.raises(tessella.InputError):
        tessella.FeMesh(2, np.zeros((3, 3)), np.array([[0, 1, 7]]), np.array([0]))
