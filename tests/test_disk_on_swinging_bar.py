"""disk-on-swinging-bar (E4.17, ../shared/SCENES.md "Lagrange scenes"): a catalog scene that
natural-frequency and modes refuse on purpose (no equilibrium), whose eom accelerations match
SCENES.md's closed forms, and whose derived equations conserve the energy along a trajectory
integrated with scipy's solve_ivp (the energy written independently from SCENES.md's T and V)."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest
from click.testing import CliRunner
from scipy.integrate import solve_ivp

from dyncalc.cli import cli
from dyncalc.commands.eom import eom
from dyncalc.physics.symbolic import Symbols, to_sympy
from dyncalc.scenes import catalog, computed_scenes, get_scene
from dyncalc.scenes.energies import energies
from dyncalc.units.expression import parse_expression

G = 9.80665
WORDS = ["m1=2kg", "l=1m", "m2=1kg", "J2=0.01kg*m^2"]
REASON = ("disk-on-swinging-bar has no equilibrium with the disk free to slide: at rest the "
          "disk accelerates outward along the bar at g cos(phi), so there is no oscillation "
          "about a rest position and no natural frequency; dyncalc eom --scene "
          "disk-on-swinging-bar derives its equations of motion")


def _closed_form(m1, l, m2, J2, phi, x, phi_dot, x_dot, g=G):
    """SCENES.md: phi_ddot and x_ddot at a state."""
    phi_ddot = -(2 * m2 * x * x_dot * phi_dot + (m1 * l / 2 + m2 * x) * g * math.sin(phi)) \
        / (m1 * l * l / 3 + m2 * x * x + J2)
    return phi_ddot, x * phi_dot ** 2 + g * math.cos(phi)


@pytest.mark.parametrize("command", ["natural-frequency", "modes"])
def test_refused_with_the_reason(command):
    result = CliRunner().invoke(cli, [command, "--scene", "disk-on-swinging-bar", *WORDS])
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr == f"Error: {REASON}\n"


def test_the_scene_declares_its_refusal():
    scene = get_scene("disk-on-swinging-bar")
    assert scene.no_frequency == REASON
    assert scene.example.startswith("dyncalc eom --scene disk-on-swinging-bar ")
    assert "disk-on-swinging-bar" in catalog()
    assert "disk-on-swinging-bar" not in computed_scenes()
    assert [s.name for s in catalog().values() if s.no_frequency] == ["disk-on-swinging-bar"]


def test_card_shows_the_eom_example_and_the_refusal():
    result = CliRunner().invoke(cli, ["scenes", "disk-on-swinging-bar"])
    assert result.exit_code == 0
    lines = result.stdout.splitlines()
    assert "example: " + get_scene("disk-on-swinging-bar").example in lines
    assert f"natural-frequency and modes refuse it: {REASON}" in lines


def test_example_gives_its_reference_values():
    """The card's example run through the CLI gives SCENES.md's closed forms."""
    import json
    import shlex

    scene = get_scene("disk-on-swinging-bar")
    result = CliRunner().invoke(cli, [*shlex.split(scene.example)[1:], "--json"])
    assert result.exit_code == 0, result.stderr
    data = json.loads(result.stdout)["results"]
    expected = _closed_form(2.0, 1.0, 1.0, 0.01, 0.3, 0.5, 1.0, 0.2)
    assert data["phi_ddot"]["value"] == pytest.approx(expected[0], rel=1e-14)
    assert data["x_ddot"]["value"] == pytest.approx(expected[1], rel=1e-14)
    for name, text in scene.example_result.items():
        assert data[name]["value"] == pytest.approx(float(text.split()[0]), rel=1e-14)


def test_accelerations_at_random_states_are_the_closed_forms():
    rng = random.Random("disk-on-swinging-bar")
    for _ in range(4):
        m1, l, m2 = rng.uniform(0.5, 5), rng.uniform(0.3, 2), rng.uniform(0.1, 3)
        J2 = rng.uniform(1e-3, 0.1)
        phi, x = rng.uniform(-2, 2), rng.uniform(0, l)
        phi_dot, x_dot = rng.uniform(-3, 3), rng.uniform(-2, 2)
        words = [f"m1={m1!r}kg", f"l={l!r}m", f"m2={m2!r}kg", f"J2={J2!r}kg*m^2",
                 f"phi={phi!r}rad", f"x={x!r}m", f"phi_dot={phi_dot!r}rad/s",
                 f"x_dot={x_dot!r}m/s"]
        r = eom({}, words, scene="disk-on-swinging-bar")
        expected = _closed_form(m1, l, m2, J2, phi, x, phi_dot, x_dot)
        assert r.results["phi_ddot"].si == pytest.approx(expected[0], rel=1e-12, abs=1e-12)
        assert r.results["x_ddot"].si == pytest.approx(expected[1], rel=1e-12, abs=1e-12)


def test_derived_equations_conserve_the_energy():
    """eom's two equations (read back through the grammar), integrated by solve_ivp from a
    state with the disk near the pin, keep T + V (SCENES.md's) constant while 0 <= x <= l."""
    import sympy

    m1, l, m2, J2 = 2.0, 1.0, 1.0, 0.01
    record = energies("disk-on-swinging-bar")
    s = Symbols(record.coords)
    result = eom({}, [], scene="disk-on-swinging-bar")
    rhs = []
    for i, c in enumerate(record.coords, start=1):
        lhs, _, text = result.results[f"eom_{i}"].si.partition(" = ")
        assert lhs == f"{c}''"
        tree = parse_expression(text, coordinates=record.coords,
                                names={p.name for p in record.params}, free_names=False)
        rhs.append(to_sympy(tree, s))
    values = {s.param("m1"): m1, s.param("l"): l, s.param("m2"): m2, s.param("J2"): J2,
              s.param("g"): G}
    f = sympy.lambdify([*s.q, *s.qd], [e.subs(values) for e in rhs], "math")

    def energy(y):
        phi, x, phi_dot, x_dot = y
        T = (m1 * l * l / 3 + m2 * x * x + J2) * phi_dot ** 2 / 2 + m2 * x_dot ** 2 / 2
        V = -(m1 * l / 2 + m2 * x) * G * math.cos(phi)
        return T + V

    def leaves(t, y):  # the disk reaches the end of the bar
        return y[1] - l
    leaves.terminal = True
    y0 = [1.2, 0.1, 0.0, 0.0]
    sol = solve_ivp(lambda t, y: [y[2], y[3], *f(*y)], (0.0, 2.0), y0, rtol=1e-11,
                    atol=1e-12, events=leaves, dense_output=True)
    assert sol.status in (0, 1)
    assert sol.t[-1] > 0.2  # the disk moved a fair way
    e0 = energy(y0)
    drift = max(abs(energy(y) - e0) for y in sol.y.T)
    assert drift < 1e-8 * max(1.0, abs(e0))
    # a wrong sign in the Coriolis term would show: the drift with it flipped is large
    flipped = [rhs[0].subs(values) - 4 * m2 * s.q[1] * s.qd[1] * s.qd[0]
               / (m1 * l * l / 3 + m2 * s.q[1] ** 2 + J2), rhs[1].subs(values)]
    g_wrong = sympy.lambdify([*s.q, *s.qd], flipped, "math")
    bad = solve_ivp(lambda t, y: [y[2], y[3], *g_wrong(*y)], (0.0, sol.t[-1]), y0,
                    rtol=1e-11, atol=1e-12)
    assert max(abs(energy(y) - e0) for y in bad.y.T) > 1e-3 * abs(e0)
    assert np.all(sol.y[1] <= l + 1e-9)
