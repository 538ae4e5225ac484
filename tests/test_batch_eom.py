"""``eom --scene --batch`` on its vectorised path (dyncalc/commands/eom_columns.py: the scene
derived once, the numbers on columns) against the one-off row by row, byte for byte, on
random rows with extremes, refusals and rows left to the one-off; and the numbers against the
textbook pendulum (omega^2 = g/l, phi'' = -g sin(phi)/l, M = l^2, K = g l per unit mass)."""
from __future__ import annotations

import json
import math
import random

import pytest

from helpers import eom_batch as _run

G = 9.80665




def _pendulum_file(tmp_path, seed: int, count: int = 40, extremes: bool = True):
    rng = random.Random(seed)
    lines = ["l,phi,phi_dot"]
    for _ in range(count):
        l = rng.choice([rng.uniform(0.01, 10.0), 10 ** rng.uniform(-150, 150), 1e-300, 1e300]
                       if extremes else [rng.uniform(0.01, 10.0)])
        phi = rng.choice([rng.uniform(-math.pi, math.pi), 0.0, -0.0, math.pi, 1e-200])
        lines.append(f"{l!r},{phi!r},{rng.uniform(-5, 5)!r}")
    lines += ["0,0.1,0",            # l = 0: refused by the one-off
              "-1,0.1,0",           # negative: refused
              "2 ft,30 deg,1 rpm",  # units: read by the batch, the same numbers
              "1,0.1,",             # no rate: the one-off asks for it
              "1e400,0.1,0"]        # beyond float64: refused
    path = tmp_path / "pendulum.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("as_json", [False, True])
def test_pendulum_rows_are_the_one_offs_byte_for_byte(tmp_path, as_json):
    path = _pendulum_file(tmp_path, 17)
    fast = _run(path, "pendulum", as_json, True)
    slow = _run(path, "pendulum", as_json, False)
    assert fast == slow
    assert fast[0] == 2  # some rows refused (SPEC "Exit status": a row failed)
    assert "l=" in fast[2]


def test_the_vectorised_path_computes_the_rows(tmp_path):
    path = _pendulum_file(tmp_path, 3, count=200, extremes=False)
    calls: list = []
    status, out, _err = _run(path, "pendulum", False, True, calls)
    # the probes of each block and the rows left to the one-off; not the 200 rows
    assert len(calls) < 20
    assert out.count("\n") == 1 + 200 + 2  # the header, the rows, two rows with units/no rate


def test_pendulum_numbers_against_the_textbook(tmp_path):
    rng = random.Random(5)
    rows = [(rng.uniform(0.05, 20.0), rng.uniform(-3.0, 3.0), rng.uniform(-4, 4))
            for _ in range(300)]
    path = tmp_path / "p.csv"
    path.write_text("l,phi,phi_dot\n" + "".join(f"{l!r},{p!r},{v!r}\n" for l, p, v in rows))
    status, out, err = _run(path, "pendulum", True, True)
    assert status == 0 and err == ""
    for line, (l, phi, _v) in zip(out.splitlines(), rows):
        data = json.loads(line)
        res = data["results"]
        assert res["eom_1"]["value"] == "phi'' = -g*sin(phi)/l"
        assert res["equilibria"]["value"] == "phi=0 (stable); phi=3.14159 (unstable)"
        assert res["mass_matrix"]["value"] == [[pytest.approx(l * l, rel=1e-15)]]
        assert res["stiffness_matrix"]["value"] == [[pytest.approx(G * l, rel=1e-15)]]
        assert res["omega_1"]["value"] == pytest.approx(math.sqrt(G / l), rel=1e-15)
        assert res["f_1"]["value"] == pytest.approx(math.sqrt(G / l) / (2 * math.pi),
                                                    rel=1e-15)
        assert res["phi_ddot"]["value"] == pytest.approx(-G * math.sin(phi) / l, rel=1e-14,
                                                         abs=1e-300)
        assert data["extra"] == {"equilibria": [{"phi": 0.0, "stable": True},
                                                {"phi": math.pi, "stable": False}],
                                 "about": {"phi": 0.0}}


@pytest.mark.parametrize("scene, header, make", [
    ("mass-spring", "m,k,x,x_dot",
     lambda r: f"{r.uniform(0.1, 10)!r},{10 ** r.uniform(-3, 6)!r},{r.uniform(-1, 1)!r},0"),
    ("rod-in-fluid", "m,l,beta",   # a dissipation D: the one-off's warning on every row
     lambda r: f"{r.uniform(0.1, 10)!r},{r.uniform(0.1, 3)!r},{r.uniform(0.0, 5)!r}"),
    ("physical-pendulum", "m,a,J",
     lambda r: f"{r.uniform(0.1, 10)!r},{r.uniform(0.01, 3)!r},{r.uniform(0.01, 5)!r}"),
    ("bead-on-rotating-ring", "r,Omega",  # equilibria that depend on Omega: closed forms
     lambda r: f"{r.uniform(0.1, 1)!r},{r.uniform(0.5, 20)!r}"),
])
@pytest.mark.parametrize("as_json", [False, True])
def test_other_scenes_match_the_one_off(tmp_path, scene, header, make, as_json):
    rng = random.Random(hash(scene) % 1000)
    path = tmp_path / "s.csv"
    path.write_text(header + "\n" + "".join(make(rng) + "\n" for _ in range(12)))
    fast = _run(path, scene, as_json, True)
    assert fast == _run(path, scene, as_json, False)
    assert fast[0] == 0


UNSTABLE = ("the equilibrium linearised about is unstable: no natural frequency (a small "
            "disturbance grows)")


@pytest.mark.parametrize("about", ["phi=0", "phi=pi", "phi = 180 deg", "phi=-pi",
                                   "phi=3.1415926", "phi=1", "x=0", "phi=", "phi=l"])
@pytest.mark.parametrize("as_json", [False, True])
def test_about_rows_are_the_one_offs_byte_for_byte(tmp_path, about, as_json):
    """--about in batch (round 10): the equilibrium named (within the one-off's 1e-6, an
    angle modulo 2 pi) linearised on columns, stable or not; one that is no equilibrium, or
    a text the one-off refuses, leaves every row to the one-off and its message."""
    path = _pendulum_file(tmp_path, 23)
    fast = _run(path, "pendulum", as_json, True, about=about)
    slow = _run(path, "pendulum", as_json, False, about=about)
    assert fast == slow


@pytest.mark.parametrize("about", ["phi=pi", "phi=0"])
def test_about_takes_the_rows_on_columns(tmp_path, about):
    path = _pendulum_file(tmp_path, 3, count=200, extremes=False)
    calls: list = []
    status, out, err = _run(path, "pendulum", False, True, calls, about=about)
    assert len(calls) < 20  # the probes and the rows left to the one-off, not 200 rows
    assert out.count("\n") == 1 + 200 + 2
    assert err.count(UNSTABLE) == (202 if about == "phi=pi" else 0)


def test_about_an_unstable_equilibrium_against_the_textbook(tmp_path):
    """Linearised about phi = pi: K = g l cos(pi) = -g l < 0 per unit mass, so no omega; the
    one-off's warning and method; phi'' = -g sin(phi)/l at the state all the same."""
    path = tmp_path / "up.csv"
    path.write_text("l [m],phi [deg],phi_dot [rad/s]\n2,30,0\n0.5,-90,1\n")
    status, out, err = _run(path, "pendulum", True, True, about="phi=pi")
    assert (status, err) == (0, "")
    lines = [json.loads(line) for line in out.splitlines()]
    for line, (l_, phi) in zip(lines, [(2.0, math.radians(30)), (0.5, math.radians(-90))]):
        r = {name: entry["value"] for name, entry in line["results"].items()}
        assert "omega_1" not in r and "f_1" not in r
        assert (line["method"], line["warnings"]) == ("symbolic", [UNSTABLE])
        assert line["extra"]["about"] == {"phi": math.pi}
        assert r["mass_matrix"] == [[l_ * l_]]
        assert math.isclose(r["stiffness_matrix"][0][0], -G * l_, rel_tol=1e-15)
        assert math.isclose(r["phi_ddot"], -G * math.sin(phi) / l_, rel_tol=1e-15)
