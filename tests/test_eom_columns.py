"""dyncalc/physics/eom_columns.py: the numpy functions of a derivation against sympy's own
evaluation (mpmath, 30 digits), the frequency rule against lagrange_equations.frequencies,
and the equilibria taken from sympy's roots against the numeric search they replace."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest
import sympy

from dyncalc.commands.eom import read
from dyncalc.commands.eom_results import constant_roots, derive_system
from dyncalc.physics import lagrange_equations as lagrange
from dyncalc.physics.eom_columns import one_frequency, plan_of
from dyncalc.scenes.energies import energies, energy_scene_names

ONE = [name for name in energy_scene_names() if len(energies(name).coords) == 1]


def _derived(scene):
    """The scene read with its parameters without a default at 1, 1.5, 2, ... (SI), and
    derived."""
    words = [f"{p.name}={1 + 0.5 * i} {p.dim.si}".strip()
             for i, p in enumerate(energies(scene).params) if p.default is None]
    inputs = read({}, words, scene=scene)
    s, _exprs, system = derive_system(inputs)
    return inputs, s, system


@pytest.mark.parametrize("scene", ["pendulum", "physical-pendulum", "clock-pendulum",
                                   "rod-in-fluid", "mass-spring"])
def test_plan_matches_sympys_evaluation(scene):
    inputs, s, system = _derived(scene)
    plan = plan_of(system, list(inputs.values))
    assert plan is not None
    rng = random.Random(scene)
    for _ in range(20):
        values = {k: v * rng.uniform(0.5, 2.0) for k, v in inputs.values.items()}
        q, qd = rng.uniform(-3, 3), rng.uniform(-2, 2)
        subs = {s.param(k): sympy.Float(v, 30) for k, v in values.items()}
        subs.update({s.q[0]: sympy.Float(q, 30), s.qd[0]: sympy.Float(qd, 30), s.qdd[0]: 0})
        arrays = {k: np.array([v]) for k, v in values.items()}
        M, K = plan.matrices(np.array([q]), arrays)
        want_m = float(system.mass[0, 0].subs(subs).evalf(30))
        want_k = float(sympy.diff(system.static[0], s.q[0]).subs(subs).evalf(30))
        want_a = float(system.accelerations[0].subs(subs).evalf(30))
        acc = plan.accelerations(np.array([q]), np.array([qd]), np.array([0.0]), arrays)
        assert M[0] == pytest.approx(want_m, rel=1e-14)
        assert K[0] == pytest.approx(want_k, rel=1e-13, abs=1e-13 * abs(want_m))
        assert acc[0] == pytest.approx(want_a, rel=1e-13, abs=1e-13)


def test_one_frequency_follows_the_eigenvalue_rule():
    rng = random.Random(2)
    for _ in range(200):
        m, k = 10 ** rng.uniform(-5, 5), rng.choice([-1, 1, 0]) * 10 ** rng.uniform(-5, 5)
        omegas, stable = lagrange.frequencies(sympy.Matrix([[m]]), sympy.Matrix([[k]]))
        w, ok = one_frequency(np.array([m]), np.array([k]))
        assert bool(ok[0]) == stable
        assert w[0] == pytest.approx(omegas[0], rel=1e-14)
        if k > 0:
            assert w[0] == pytest.approx(math.sqrt(k / m), rel=1e-15)


@pytest.mark.parametrize("scene", ONE)
def test_sympys_roots_are_the_numeric_searchs(scene):
    """Where the roots do not depend on the values, they are the ones the grid search finds
    (the one-off used the search before; it now takes the roots, as batch does)."""
    inputs, s, system = _derived(scene)
    angle = inputs.coords[0] in inputs.angles
    if plan_of(system, list(inputs.values)) is None:
        return
    roots = constant_roots(system, angle)
    if roots is None:
        return
    values = {s.param(k): v for k, v in inputs.values.items()}
    found = lagrange.numeric_equilibria(system, values, [angle], [1.0])
    assert [r for r in roots] == pytest.approx([p[0] for p in found], abs=1e-12)


def test_the_pendulums_roots():
    _inputs, _s, system = _derived("pendulum")
    assert constant_roots(system, True) == [0.0, math.pi]
