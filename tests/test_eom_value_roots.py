"""Equilibria that depend on the values (``bead-on-rotating-ring``: 0, pi and
+-acos(g/(Omega^2 r)) when Omega^2 r > g; ``pendulum-spring-dashpot``: 0, pi and
+-acos(-m g/(2 a k))): the closed forms generated into dyncalc/scenes/eom_tables.py against
the numeric search they replace (a few ulp) and the textbook, the per-row canonical form
(physics.eom_columns.equilibria_rows) against the search's rules, and ``eom --scene --batch``
on them against the one-off byte for byte, rows it cannot take left to the one-off."""
from __future__ import annotations

import json
import math
import random
import subprocess
import sys

import numpy as np
import pytest

from dyncalc.commands.eom import eom, read
from dyncalc.commands.eom_columns import scene_columns
from dyncalc.commands.eom_results import _table_roots, derive_system
from dyncalc.physics import lagrange_equations as lagrange
from dyncalc.physics.eom_columns import equilibria_rows
from dyncalc.scenes.eom_tables import TABLES
from helpers import eom_batch as _run

G = 9.80665


def _ulps(a: float, b: float) -> int:
    return abs(int(np.float64(a).view(np.int64)) - int(np.float64(b).view(np.int64)))


def _words(values: dict) -> list[str]:
    units = {"r": "m", "Omega": "rad/s", "a": "m", "m": "kg", "k": "N/m", "d": "N*s/m"}
    return [f"{k}={v!r} {units[k]}" for k, v in values.items()]


def _random_values(scene, rng):
    if scene == "bead-on-rotating-ring":
        return {"r": 10 ** rng.uniform(-2, 1), "Omega": 10 ** rng.uniform(-0.5, 1.5)}
    return {"m": 10 ** rng.uniform(-1, 1), "a": 10 ** rng.uniform(-1, 0.5),
            "k": 10 ** rng.uniform(-1.5, 2), "d": rng.uniform(0, 3)}


def _mp_roots(scene, v, mpmath):
    """The equilibria in (-pi, pi] to 40 digits: sin(q) (c0 - cos(q)) = 0."""
    if scene == "bead-on-rotating-ring":
        c = mpmath.mpf(v["g"]) / (mpmath.mpf(v["Omega"]) ** 2 * mpmath.mpf(v["r"]))
    else:
        c = -mpmath.mpf(v["m"]) * mpmath.mpf(v["g"]) / (2 * mpmath.mpf(v["a"])
                                                         * mpmath.mpf(v["k"]))
    out = [0.0, math.pi]
    if abs(c) < 1:
        out += [float(mpmath.acos(c)), -float(mpmath.acos(c))]
    return out


@pytest.mark.parametrize("scene", ["bead-on-rotating-ring", "pendulum-spring-dashpot"])
def test_closed_forms_are_the_numeric_searchs_roots(scene):
    """The grid search (scipy's hybr from 13 starts, polished to 1e-13) finds the same
    equilibria; both against mpmath (40 digits) at the same float inputs: the closed form
    within 2 ulp plus acos's conditioning near the bifurcation (4 eps |cos/sin|: the
    rounding of its argument), the search within 1e-12."""
    import mpmath

    mpmath.mp.dps = 40
    assert TABLES[scene]["roots"] is None and TABLES[scene]["R"] is not None
    rng = random.Random(scene)
    compared = 0
    for _ in range(25):
        inputs = read({}, _words(_random_values(scene, rng)), scene=scene)
        s, _exprs, system = derive_system(inputs)
        values = {s.param(k): v for k, v in inputs.values.items()}
        found = sorted(p[0] for p in lagrange.numeric_equilibria(system, values, [True],
                                                                   [1.0]))
        mine = sorted(p[0] for p in _table_roots(inputs))
        assert len(mine) == len(found), (inputs.values, mine, found)
        exact = sorted(_mp_roots(scene, inputs.values, mpmath))
        assert len(exact) == len(mine)
        for a, b, e in zip(mine, found, exact):
            cond = 4 * 2.2e-16 * abs(math.cos(e) / math.sin(e)) if e not in (0, math.pi) \
                else 0.0
            assert abs(a - e) <= 2 * math.ulp(e) + cond, (a, e)
            assert abs(b - e) <= 1e-12, (b, e)
        compared += len(mine) == 4
    assert compared >= 5  # the riding branches were there in several draws


def test_the_bead_rides_up_at_the_textbook_angle():
    """cos(theta) = g / (Omega^2 r) (Gross et al. E6.11), stable there; the bottom unstable."""
    result = eom({}, ["r=0.2m", "Omega=10rad/s"], scene="bead-on-rotating-ring")
    eq = result.extra["equilibria"]
    theta = math.acos(G / (100 * 0.2))
    assert [e["theta"] for e in eq] == [0.0, theta, -theta, math.pi]
    assert [e["stable"] for e in eq] == [False, True, True, False]
    assert result.extra["about"] == {"theta": theta}
    # K = r^2 (Omega^2 sin^2 - Omega^2 cos^2) + g r cos at the riding angle, per unit mass
    k = 0.04 * 100 * (math.sin(theta) ** 2 - math.cos(theta) ** 2) + G * 0.2 * math.cos(theta)
    assert result.results["omega_1"].si == pytest.approx(math.sqrt(k / 0.04), rel=1e-14)
    assert result.results["omega_1"].si == pytest.approx(10 * math.sin(theta), rel=1e-14)


def test_below_the_critical_spin_only_bottom_and_top():
    result = eom({}, ["r=0.5m", "Omega=2rad/s"], scene="bead-on-rotating-ring")
    assert result.extra["equilibria"] == [{"theta": 0.0, "stable": True},
                                          {"theta": math.pi, "stable": False}]
    assert result.results["omega_1"].si == pytest.approx(math.sqrt(G / 0.5 - 4), rel=1e-14)


def test_equilibria_rows_follows_the_search_rules():
    x = np.array([[0.0, math.pi, 1.0, -1.0],          # sorted by size, positive first
                  [0.0, -math.pi, 5e-13, 3 * math.pi],  # -pi is pi; tiny is 0; wrapped
                  [0.0, math.pi, 1e-8, -1e-8],         # merged into 0 (within 1e-7)
                  [0.0, math.pi, np.nan, np.nan]])      # no riding branch
    roots, count = equilibria_rows(x, True)
    assert count.tolist() == [4, 2, 2, 2]
    assert roots[0].tolist() == [0.0, 1.0, -1.0, math.pi]
    for row in roots[1:]:
        assert row[:2].tolist() == [0.0, math.pi] and np.isnan(row[2:]).all()




@pytest.mark.parametrize("as_json", [False, True])
def test_bead_batch_is_the_one_offs_byte_for_byte(tmp_path, as_json):
    """Random rows over six decades on both sides of the critical spin, at the bifurcation,
    a huge spin, a tiny ring at a huge spin and refusals (Omega = 0, r = 0)."""
    rng = random.Random(11)
    lines = ["r [m],Omega [rad/s],theta [deg],theta_dot [rad/s]"]
    for _ in range(60):
        lines.append(f"{10 ** rng.uniform(-3, 3)!r},{10 ** rng.uniform(-2, 2)!r},"
                     f"{rng.uniform(-200, 200)!r},{rng.uniform(-3, 3)!r}")
    lines += ["1,3.1315571206669692,0,0", "1,0,0,0", "0,1,0,0", "1,1e150,10,0",
              "1e-300,1e10,5,0"]
    path = tmp_path / "bead.csv"
    path.write_text("\n".join(lines) + "\n")
    calls = []
    fast = _run(path, "bead-on-rotating-ring", as_json, True, calls)
    assert fast == _run(path, "bead-on-rotating-ring", as_json, False)
    assert fast[0] == 2
    assert len(calls) <= 4  # the refused rows and the extremes, not the 61 others
    assert fast[2].splitlines() == [
        "Error: line 63: Omega= must be positive; got 0 radian / second",
        "Error: line 64: r= must be positive; got 0 meter"]
    if as_json:
        first = json.loads(fast[1].splitlines()[0])
        r, spin = float(lines[1].split(",")[0]), float(lines[1].split(",")[1])
        riding = spin ** 2 * r > G
        assert len(first["extra"]["equilibria"]) == (4 if riding else 2)


@pytest.mark.parametrize("as_json", [False, True])
def test_dashpot_pendulum_batch_is_the_one_offs_byte_for_byte(tmp_path, as_json):
    """Springs soft enough for the top to be stable (no stable root at the bottom: the
    one-off warns, the batch leaves those rows to it) and stiff ones."""
    rng = random.Random(12)
    lines = ["m [kg],a [m],k [N/m],d [N*s/m]"]
    for _ in range(40):
        lines.append(f"{10 ** rng.uniform(-1, 1)!r},{10 ** rng.uniform(-1, 0.5)!r},"
                     f"{10 ** rng.uniform(-1.5, 2)!r},{rng.uniform(0, 3)!r}")
    path = tmp_path / "psd.csv"
    path.write_text("\n".join(lines) + "\n")
    fast = _run(path, "pendulum-spring-dashpot", as_json, True)
    assert fast == _run(path, "pendulum-spring-dashpot", as_json, False)
    assert fast[0] == 0


def test_rows_the_kernel_cannot_take_are_left_to_the_one_off():
    """Refused values (r = 0, Omega = 0: the one-off's constraints) and non-finite ones are not
    exact; the others carry their own equilibria text and JSON extra."""
    r = np.array([0.5, 0.5, 0.0, 0.5, np.inf])
    spin = np.array([10.0, 2.0, 3.0, 0.0, 3.0])
    cols = scene_columns({"r": r, "Omega": spin}, {"scene": "bead-on-rotating-ring"})
    assert cols.exact.tolist() == [True, True, False, False, False]
    assert cols.values["equilibria"][1] == "theta=0 (stable); theta=3.14159 (unstable)"
    theta = math.acos(G / 50)
    extra = json.loads(cols.extras(np.array([0]))[0][0])
    # numpy's arccos may differ from libm's acos in the last place (numpy 1.26 does here), so
    # the roots are compared to one unit in the last place; the structure exactly.
    root = extra["about"]["theta"]
    assert abs(root - theta) <= math.ulp(theta)
    assert extra == {"equilibria": [{"theta": 0.0, "stable": False},
                                    {"theta": root, "stable": True},
                                    {"theta": -root, "stable": True},
                                    {"theta": math.pi, "stable": False}],
                     "about": {"theta": root}}


def test_bead_batch_does_not_import_sympy(tmp_path):
    path = tmp_path / "b.csv"
    path.write_text("r [m],Omega [rad/s]\n0.2,10\n0.5,2\n")
    code = ("import sys\nfrom dyncalc.cli import cli\n"
            "try:\n    cli(['eom', '--scene', 'bead-on-rotating-ring', '--batch', sys.argv[1]])\n"
            "except SystemExit as e:\n    assert not e.code, e.code\n"
            "print('sympy' in sys.modules, file=sys.stderr)\n")
    done = subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stderr.strip().splitlines()[-1] == "False"
    rows = [line.split(",") for line in done.stdout.splitlines()[1:]]
    theta = math.acos(G / (100 * 0.2))
    assert rows[0][3] == (f"theta=0 (unstable); theta={theta:.6g} (stable); "
                          f"theta={-theta:.6g} (stable); theta=3.14159 (unstable)")
    assert float(rows[0][6]) == pytest.approx(10 * math.sin(theta), rel=1e-14)
    assert rows[1][3] == "theta=0 (stable); theta=3.14159 (unstable)"
    assert float(rows[1][6]) == pytest.approx(math.sqrt(G / 0.5 - 4), rel=1e-14)
