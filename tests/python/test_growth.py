# SPDX-FileCopyrightText: 2026 The Tessella developers
# SPDX-License-Identifier: AGPL-3.0-or-later
# Growth and division from Python: analytic growth laws, Python fields equal
# to the built-in ones, Python division rules, conservation at division.
import math

import numpy as np
import pytest

import tessella


def grow(t, field, steps, dt, scheme="heun", **options):
    g = tessella.GrowthIntegrator(field, scheme=scheme, **options)
    for _ in range(steps):
        g.step(t, dt)
    return g


def test_uniform_growth_area_follows_exp_2rt():
    r, dt, steps = 0.1, 0.05, 40
    t = tessella.hexagonal_grid(6, 5)
    a0 = t.total_measure()
    grow(t, tessella.uniform_expansion(r), steps, dt, scheme="heun")
    T = steps * dt
    assert t.time == pytest.approx(T)
    # Heun on x' = r x multiplies lengths by 1 + h + h^2/2 per step (h = r dt)
    # exactly, and the area is quadratic in lengths ...
    h = r * dt
    assert t.total_measure() == pytest.approx(a0 * (1 + h + h * h / 2) ** (2 * steps), rel=1e-12)
    # ... which is exp(2 r T) to the scheme's O(h^3) per-step error.
    assert t.total_measure() == pytest.approx(a0 * math.exp(2 * r * T), rel=1e-5)


def test_python_field_equals_builtin_field():
    r = 0.2
    builtin = tessella.hexagonal_grid(4, 4)
    python = builtin.copy()
    grow(builtin, tessella.uniform_expansion(r, center=[1.0, 2.0, 0.0]), 10, 0.1)
    center = np.array([1.0, 2.0, 0.0])
    grow(python, tessella.PythonField(lambda x, t: r * (x - center)), 10, 0.1)
    np.testing.assert_allclose(python.positions(), builtin.positions(), rtol=0, atol=1e-13)


def test_python_meristem_field_equals_builtin_on_the_dome():
    # The meristem law v = k(rho) (x - apex), k = kc + (kp - kc)(1 + tanh((rho - R)/w))/2,
    # written in NumPy, against MeristemField.
    apex, R, w, kc, kp = np.array([0.0, 0.0, 1.0]), 0.8, 0.2, 0.02, 0.15
    builtin = tessella.MeristemField(apex=apex, axis=[0, 0, 1], central_radius=R, transition_width=w,
                                     central_rate=kc, peripheral_rate=kp)

    def meristem(x, t):
        d = x - apex
        rho = np.hypot(d[:, 0], d[:, 1])
        k = kc + (kp - kc) * 0.5 * (1.0 + np.tanh((rho - R) / w))
        return k[:, None] * d

    points = tessella.random_seeds(tessella.Disk(radius=2.0), 200, rng_seed=4)
    np.testing.assert_allclose(tessella.PythonField(meristem).velocities(points), builtin.velocities(points),
                               rtol=1e-13, atol=1e-15)
    for rho in (0.0, R, 1.5):
        assert builtin.rate_at(rho) == pytest.approx(kc + (kp - kc) * 0.5 * (1 + math.tanh((rho - R) / w)))

    dome = tessella.Dome("spherical_cap", base_radius=2.0, height=1.0)
    a = tessella.dome_tissue(tessella.random_seeds(tessella.Disk(radius=2.0), 30, rng_seed=2), dome)
    b = a.copy()
    grow(a, builtin, 5, 0.1, projection=tessella.dome_projection(dome))
    grow(b, tessella.PythonField(meristem), 5, 0.1, projection=tessella.dome_projection(dome))
    np.testing.assert_allclose(b.positions(), a.positions(), rtol=0, atol=1e-12)


def test_python_field_is_called_once_per_stage_with_every_vertex():
    t = tessella.rectangular_grid(3, 3)
    calls = []

    def field(x, time):
        calls.append((x.shape, time, x.flags.writeable))
        return np.zeros_like(x)

    grow(t, tessella.PythonField(field), 2, 0.5, scheme="euler")
    assert [c[0] for c in calls] == [(16, 3)] * 2
    assert [c[1] for c in calls] == [0.0, 0.5]
    assert not calls[0][2]  # points are read-only
    calls.clear()
    grow(t, tessella.PythonField(field), 1, 0.5, scheme="heun")
    assert len(calls) == 2  # Heun: two stages per step


def test_python_field_errors():
    t = tessella.rectangular_grid(2, 2)
    before = t.positions()
    with pytest.raises(ValueError, match=r"must return an \(n, 3\) array .* for 9 points"):
        grow(t, tessella.PythonField(lambda x, time: x[:, :2], "flat"), 1, 0.1)

    class Boom(Exception):
        pass

    def raising(x, time):
        raise Boom("field failed")

    with pytest.raises(Boom, match="field failed"):
        grow(t, tessella.PythonField(raising), 1, 0.1)
    with pytest.raises(ValueError, match=r"non-finite velocity"):
        grow(t, tessella.PythonField(lambda x, time: np.full_like(x, np.nan)), 1, 0.1)
    np.testing.assert_array_equal(t.positions(), before)

    # A failure in Heun's second stage, after the predictor moved the
    # vertices: positions and clock are restored too.
    calls = []

    def second_stage_fails(x, time):
        calls.append(time)
        if len(calls) == 2:
            raise Boom("corrector failed")
        return 0.5 * x

    with pytest.raises(Boom, match="corrector failed"):
        grow(t, tessella.PythonField(second_stage_fails), 1, 0.1, scheme="heun")
    assert len(calls) == 2
    np.testing.assert_array_equal(t.positions(), before)
    assert t.time == 0.0


def test_expression_field_matches_builtin_and_reports_errors():
    e = tessella.ExpressionField("r*(x-1)", "r*y", "0", {"r": 0.3})
    points = np.random.default_rng(0).uniform(-1, 1, size=(50, 3))
    points[:, 2] = 0
    np.testing.assert_allclose(e.velocities(points, 0.0),
                               tessella.uniform_expansion(0.3, center=[1, 0, 0]).velocities(points), atol=1e-14)
    with pytest.raises(ValueError, match=r"vx"):
        tessella.ExpressionField("r*(x-", "0", "0", {"r": 1.0})
    with pytest.raises(ValueError, match=r"euler"):
        tessella.GrowthIntegrator(tessella.uniform_expansion(1.0), scheme="rk45")


def test_main_axis_division_conserves_area_and_amounts():
    t = tessella.voronoi_tissue(tessella.random_seeds(tessella.Rectangle(min=[0, 0, 0], max=[4, 3, 0]), 30, 9),
                                tessella.Rectangle(min=[0, 0, 0], max=[4, 3, 0]))
    t.add_property("amount", 1.0, policy="split_by_measure")
    grow(t, tessella.uniform_expansion(0.2), 10, 0.1)
    area, total = t.total_measure(), t.property("amount").sum()
    scheduler = tessella.DivisionScheduler(tessella.SizeThreshold.fixed(0.5), tessella.MainAxisRule())
    due = int((t.cell_measures() > 0.5).sum())
    report = scheduler.step(t)
    assert due > 0 and len(report["divided"]) + len(report["skipped"]) == due
    assert t.num_cells == 30 + len(report["divided"])
    assert t.total_measure() == pytest.approx(area, rel=1e-12)
    assert t.property("amount").sum() == pytest.approx(total, rel=1e-12)
    assert t.validate()[0]


def test_main_axis_rule_cuts_an_elongated_cell_across():
    t = tessella.rectangular_grid(1, 1, dx=2.0, dy=1.0)
    point, normal = tessella.MainAxisRule().plane(t, 0)
    np.testing.assert_allclose(point, [1.0, 0.5, 0.0], atol=1e-14)
    assert abs(normal[0]) == pytest.approx(np.linalg.norm(normal))
    record = tessella.DivisionScheduler(tessella.SizeThreshold.fixed(1.0), tessella.MainAxisRule()).divide(t, 0)
    np.testing.assert_allclose(t.cell_measures(), [1.0, 1.0], atol=1e-12)
    assert record["daughter"] == 1 and record["mother_lineage"] == 0


def test_python_division_rule_is_called_for_every_due_cell():
    t = tessella.rectangular_grid(3, 2, dx=1.0, dy=2.0)
    calls = []

    def across_y(tissue, cell):
        calls.append(cell)
        assert tissue.num_cells == t.num_cells  # the dividing tissue itself
        return tissue.cell_centroid(cell), [0.0, 1.0, 0.0]

    rule = tessella.PythonRule(across_y, "across_y")
    assert rule.name == "across_y"
    report = tessella.DivisionScheduler(tessella.SizeThreshold.fixed(1.5), rule).step(t)
    assert sorted(calls) == [0, 1, 2, 3, 4, 5]
    assert len(report["divided"]) == 6 and t.num_cells == 12
    np.testing.assert_allclose(t.cell_measures(), 1.0, atol=1e-12)
    assert t.validate()[0]


def test_python_division_rule_bad_answer():
    t = tessella.rectangular_grid(1, 1)
    rule = tessella.PythonRule(lambda tissue, cell: (tissue.cell_centroid(cell),), "short")
    with pytest.raises(ValueError, match=r"division rule 'short': expected \(point, normal\) for cell 0"):
        tessella.DivisionScheduler(tessella.SizeThreshold.fixed(0.5), rule).step(t)
    assert t.num_cells == 1


def test_named_rules_and_thresholds():
    for name in ("main_axis", "shortest_wall", "random", "besson_dumais", "perpendicular_to_mother_wall"):
        assert tessella.make_division_rule(name).name == name
    with pytest.raises(ValueError, match=r"mainaxis"):
        tessella.make_division_rule("mainaxis")
    with pytest.raises(ValueError):
        tessella.SizeThreshold.fixed(-1.0)
    t = tessella.hexagonal_grid(4, 4)
    grow(t, tessella.uniform_expansion(0.3), 10, 0.1)
    s = tessella.DivisionScheduler(tessella.SizeThreshold.noisy(3.0, 0.3), tessella.ShortestWallRule(), rng_seed=5)
    report = s.step(t)
    assert report["divided"] and t.has_property("division_threshold")
    assert t.validate()[0]
