"""``eom --scene disk-on-swinging-bar`` (Gross et al. E4.17) through the generated
two-coordinate table: its equilibria as closed forms (phi = +-pi/2, x = -m1 l / (2 m2)) with
the scene's domain 0 <= x <= l, so the disk free on the bar is never at rest; the equations
against a derivation by hand, the one-off's answers, and ``--batch`` on columns byte for byte
the one-off's rows (those with an equilibrium in the domain, refused or overflowing left to
the one-off), without sympy."""
from __future__ import annotations

import csv
import io
import json
import math
import random

import numpy as np
import pytest
from click.testing import CliRunner

from dyncalc.cli import cli
from dyncalc.physics.eom_pairs import PairPlan
from dyncalc.scenes.eom_tables2 import TABLES2
from helpers import eom_batch, eom_batch_without_sympy

SCENE = "disk-on-swinging-bar"
NONE = "no equilibrium: the system is never at rest at these values"


def _by_hand(m1, l, m2, J2, g, phi, x, phi_dot, x_dot):
    """Lagrange by hand: T = (m1 l^2/3 + m2 x^2 + J2) phi'^2/2 + m2 x'^2/2,
    V = -(m1 l/2 + m2 x) g cos(phi)."""
    inertia = m1 * l * l / 3 + m2 * x * x + J2
    phi_ddot = -(g * (m1 * l / 2 + m2 * x) * np.sin(phi) + 2 * m2 * x * x_dot * phi_dot) / inertia
    x_ddot = x * phi_dot ** 2 + g * np.cos(phi)
    return phi_ddot, x_ddot


def test_table_accelerations_and_roots_are_the_hand_derivations():
    rng = np.random.default_rng(17)
    n = 500
    m1, l, m2, J2, g = (10 ** rng.uniform(-3, 3, n) for _ in range(5))
    phi, x, phi_dot, x_dot = (rng.uniform(-3, 3, n) for _ in range(4))
    plan = PairPlan(TABLES2[SCENE])
    values = {"m1": m1, "l": l, "m2": m2, "J2": J2, "g": g}
    got = plan.accelerations(phi, x, phi_dot, x_dot, np.zeros(n), values)
    want = _by_hand(m1, l, m2, J2, g, phi, x, phi_dot, x_dot)
    for a, b in zip(got, want):
        assert np.allclose(a, b, rtol=1e-12, atol=1e-12 * np.abs(b).max())
    roots, distinct, covered = plan.root_rows(values, n)
    assert distinct.all() and covered.all() and len(roots) == 2
    assert (roots[0][0] == math.pi / 2).all() and (roots[1][0] == -math.pi / 2).all()
    for root in roots:
        assert np.allclose(root[1], -m1 * l / (2 * m2), rtol=1e-15, atol=0)
    lo, hi = plan.bound_rows(values, n)[1]
    assert (lo == 0).all() and (hi == l).all()


def test_the_one_off_says_the_disk_is_never_at_rest():
    """E4.17: with the disk free on the bar there is no equilibrium (x = -m1 l / (2 m2) < 0
    lies off the bar); the accelerations at a state still follow."""
    done = CliRunner().invoke(cli, ["eom", "--scene", SCENE, "m1=2kg", "l=1m", "m2=1kg",
                                    "J2=0.01kg*m^2", "phi=0.1", "x=0.5", "phi_dot=0",
                                    "x_dot=1", "--json"])
    assert done.exit_code == 0, done.output
    data = json.loads(done.output)
    assert data["warnings"] == [NONE] and data["extra"] == {"equilibria": []}
    assert data["method"] == "symbolic" and data["results"]["equilibria"]["value"] == "none"
    want = _by_hand(2.0, 1.0, 1.0, 0.01, 9.80665, 0.1, 0.5, 0.0, 1.0)
    assert data["results"]["phi_ddot"]["value"] == pytest.approx(want[0], rel=1e-14)
    assert data["results"]["x_ddot"]["value"] == pytest.approx(want[1], rel=1e-14)


def test_a_vanishing_bar_puts_two_unstable_equilibria_on_the_pivot():
    """m1 = 1e-20 kg: x = -5e-21 m, at the pivot to 1e-12; there phi = +-pi/2 is a saddle
    (K = [[~0, g m2], [g m2, 0]], det K < 0), so unstable and no frequency."""
    done = CliRunner().invoke(cli, ["eom", "--scene", SCENE, "m1=1e-20kg", "l=1m", "m2=1kg",
                                    "J2=0.01kg*m^2", "--json"])
    assert done.exit_code == 0, done.output
    data = json.loads(done.output)
    assert data["extra"]["equilibria"] == [{"phi": math.pi / 2, "x": 0.0, "stable": False},
                                           {"phi": -math.pi / 2, "x": 0.0, "stable": False}]
    assert "omega_1" not in data["results"]
    assert data["warnings"] == ["the equilibrium linearised about is unstable: no natural "
                                "frequency (a small disturbance grows)"]


def test_a_huge_disk_is_unstable_not_a_zero_frequency():
    """m2 = 1e300 kg: the matrices are finite but M^-1 K's eigenvalues (+-2.2e148) overflowed
    scipy's unscaled solver, which read as stable with omega = 0; scaled by M's diagonal
    they are a saddle, so unstable."""
    done = CliRunner().invoke(cli, ["eom", "--scene", SCENE, "m1=72kg", "l=90m", "m2=1e300kg",
                                    "J2=68kg*m^2", "--json"])
    assert done.exit_code == 0, done.output
    data = json.loads(done.output)
    assert [e["stable"] for e in data["extra"]["equilibria"]] == [False, False]
    assert "omega_1" not in data["results"]


def _file(tmp_path, rng, count, state=True):
    def value():
        return rng.choice([rng.uniform(0.01, 100.0)] * 8 + [10 ** rng.uniform(-100, 100),
                                                            1e-300, 1e300])
    head = "m1 [kg],l [m],m2 [kg],J2 [kg*m^2]"
    lines = [head + (",phi [rad],x [m],phi_dot [rad/s],x_dot [m/s]" if state else "")]
    for _ in range(count):
        cells = [repr(value()) for _ in range(4)]
        if state:
            cells += [repr(rng.uniform(-2, 2)) for _ in range(4)]
        lines.append(",".join(cells))
    extra = ["1e-20,1,1,0.01", "0,1,1,0.01", "2 lb,20 in,1 kg,0.1 kg*m^2", "-1,1,1,0.01"]
    lines += [e + (",0.1,0.2,0,0" if state else "") for e in extra]
    if state:
        lines.append("1,1,1,0.01,0.1,,0,0")  # no x: the one-off asks for it
    path = tmp_path / "disk.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def _run(path, as_json, fast):
    """``((status, stdout, stderr), rows the one-off answered)``."""
    calls: list = []
    return eom_batch(path, SCENE, as_json, fast, calls), len(calls)


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # (the one-off's search at 1e300)
@pytest.mark.parametrize("state", [True, False])
@pytest.mark.parametrize("as_json", [False, True])
def test_batch_rows_are_the_one_offs_byte_for_byte(tmp_path, as_json, state):
    rng = random.Random(41 + state)
    path = _file(tmp_path, rng, 60, state)
    (fast, calls) = _run(path, as_json, True)
    generic, every = _run(path, as_json, False)
    assert fast == generic
    # rows of parameters in [0.01, 100] on columns: the one-off takes only the others
    # (an extreme value, a pivot on the bar, overflows) and the five refused or odd ones
    lines = path.read_text().splitlines()[1:61]
    extreme = sum(any(not 0.01 <= float(c) <= 100 for c in line.split(",")[:4])
                  for line in lines)
    assert fast[0] == 2 and calls <= extreme + 5 < every, (calls, extreme, every)
    errors = fast[2].splitlines()
    assert sum(e.startswith("Error: line 63: m1=") for e in errors) == 1
    assert sum(e.startswith("Error: line 65: m1=") for e in errors) == 1
    said = fast[1].count(NONE) if as_json else sum(
        e.startswith("warning:") and e.endswith(NONE) for e in errors)
    assert said >= 60 - extreme  # (x = -m1 l / (2 m2) <= -5e-7 m: off the bar)


def test_batch_on_columns_without_sympy(tmp_path):
    path = tmp_path / "d.csv"
    path.write_text("m1,l,m2,J2,phi,x,phi_dot,x_dot\n" + "".join(
        f"{1 + i / 7!r},{0.5 + i / 11!r},{2 + i / 3!r},0.01,0.1,0.25,0.5,-1\n"
        for i in range(300)))
    (status, out, err), calls = _run(path, False, True)
    assert status == 0 and calls == 0 and out.count("\n") == 301
    assert err.count(NONE) == 300
    rows = list(csv.DictReader(io.StringIO(eom_batch_without_sympy(SCENE, path))))
    assert len(rows) == 300 and all(r["equilibria"] == "none" for r in rows)
    want = _by_hand(1.0, 0.5, 2.0, 0.01, 9.80665, 0.1, 0.25, 0.5, -1.0)
    assert float(rows[0]["phi_ddot [rad/s^2]"]) == pytest.approx(want[0], rel=1e-14)
    assert float(rows[0]["x_ddot [m/s^2]"]) == pytest.approx(want[1], rel=1e-14)


def test_symbolic_path_frequencies_scaled_and_overflow_refused():
    """lagrange.frequencies (the one-off's symbolic path): masses far apart give mpmath's
    eigenvalues (here a saddle, +-sqrt(c^2 / (a b))), and an eigenvalue beyond double
    (K/M = 1e310) is refused in one line rather than read as stable with omega = 0."""
    import sympy

    from dyncalc.errors import PhysicsError
    from dyncalc.physics import lagrange_equations as lagrange

    a, b, c = 195514.74770406017, 1e300, 9.80665e300
    M = sympy.Matrix([[a, 0], [0, b]])
    omegas, stable = lagrange.frequencies(M, sympy.Matrix([[1.95e-12, c], [c, 0]]))
    assert not stable
    assert omegas[1] == pytest.approx(math.sqrt(c / math.sqrt(a * b)), rel=1e-9)
    omegas, stable = lagrange.frequencies(M, sympy.Matrix([[4 * a, 0], [0, 9 * b]]))
    assert stable and omegas == pytest.approx([2.0, 3.0], rel=1e-14)
    with pytest.raises(PhysicsError) as caught:
        lagrange.frequencies(sympy.Matrix([[1e-300, 0], [0, 1]]),
                             sympy.Matrix([[1e10, 0], [0, 1]]))
    assert str(caught.value) == ("the natural frequencies overflow at these values (an "
                                 "eigenvalue of M^-1 K beyond 1.8e308 in SI units)")
