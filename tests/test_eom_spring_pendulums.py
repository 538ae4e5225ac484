"""``eom --scene spring-coupled-pendulums`` (Gross et al. E4.16) through the generated
two-coordinate table: its equilibria in the domain 0 <= phi2 <= pi/2 from the hand-written
roots of dyncalc/physics/pendulum_pair_roots.py where the spring's free length b is 0
(phi1 = +-pi/2 at phi2 = pi/2; phi1 = 0 or pi at phi2 = 0; phi1 = pi at phi2 = acos(g m /
(2 k l))), the textbook's two frequencies, and ``--batch`` on columns byte for byte the
one-off's rows (b > 0, extremes and refused rows left to the one-off), without sympy."""
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
from dyncalc.physics.pendulum_pair_roots import spring_pendulum_roots
from helpers import eom_batch, eom_batch_without_sympy

SCENE = "spring-coupled-pendulums"
G = 9.80665


def _static(phi1, phi2, b, g, k, l, m):
    """dV/dphi1, dV/dphi2 of V = -2 m g l cos(phi1) cos(phi2) + k (2 l sin(phi2) - b)^2 / 2,
    by hand."""
    return (2 * m * g * l * np.sin(phi1) * np.cos(phi2),
            2 * m * g * l * np.cos(phi1) * np.sin(phi2)
            + 2 * k * l * (2 * l * np.sin(phi2) - b) * np.cos(phi2))


def test_hand_roots_are_equilibria_and_cover_only_b_zero():
    rng = np.random.default_rng(16)
    n = 2000
    g = np.full(n, G)
    k, l, m = 10 ** rng.uniform(-2, 3, n), 10 ** rng.uniform(-2, 1, n), 10 ** rng.uniform(-2, 2, n)
    b = np.where(rng.uniform(size=n) < 0.2, rng.uniform(0, 0.5, n), 0.0)
    flat, covered = spring_pendulum_roots(b, g, k, l, m)
    assert (covered == (b == 0)).all()
    r = g * m / (2 * k * l)
    for i in range(0, len(flat), 2):
        phi1, phi2 = flat[i], flat[i + 1]
        there = ~np.isnan(phi1) & covered
        assert ((phi2[there] >= 0) & (phi2[there] <= math.pi / 2)).all()
        for residual, scale in zip(_static(phi1, phi2, 0.0, g, k, l, m),
                                   (m * g * l, m * g * l + k * l * l)):
            assert (np.abs(residual[there]) <= 1e-12 * scale[there]).all()
    # the fifth, upside down and held apart, exists exactly where r <= 1
    assert (np.isnan(flat[8]) == (r > 1)).all()
    assert np.allclose(np.cos(flat[9][r <= 1]), r[r <= 1], rtol=1e-13, atol=1e-15)


def test_the_one_off_against_the_textbook():
    """E4.16 with b = 0: about phi1 = phi2 = 0 the bisector swings at omega_1^2 = g/l, the
    opening at omega_2^2 = g/l + 2 k/m; five equilibria in the domain, the first stable."""
    done = CliRunner().invoke(cli, ["eom", "--scene", SCENE, "m=1.5kg", "l=0.8m",
                                    "k=120N/m", "--json"])
    assert done.exit_code == 0, done.output
    data = json.loads(done.output)
    assert data["results"]["omega_1"]["value"] == pytest.approx(math.sqrt(G / 0.8), rel=1e-14)
    assert data["results"]["omega_2"]["value"] == pytest.approx(
        math.sqrt(G / 0.8 + 2 * 120 / 1.5), rel=1e-14)
    apart = math.acos(G * 1.5 / (2 * 120 * 0.8))
    assert data["extra"]["equilibria"] == [
        {"phi1": 0.0, "phi2": 0.0, "stable": True},
        {"phi1": math.pi, "phi2": 0.0, "stable": False},
        {"phi1": math.pi / 2, "phi2": math.pi / 2, "stable": False},
        {"phi1": -math.pi / 2, "phi2": math.pi / 2, "stable": False},
        {"phi1": math.pi, "phi2": pytest.approx(apart, rel=1e-15), "stable": False}]


def test_a_spring_too_weak_to_hold_them_apart_has_four():
    """r = g m / (2 k l) > 1: no equilibrium upside down with the pendulums apart."""
    done = CliRunner().invoke(cli, ["eom", "--scene", SCENE, "m=10kg", "l=0.5m", "k=20N/m",
                                    "--json"])
    assert done.exit_code == 0, done.output
    points = json.loads(done.output)["extra"]["equilibria"]
    assert [(p["phi1"], p["phi2"]) for p in points] == [
        (0.0, 0.0), (math.pi, 0.0), (math.pi / 2, math.pi / 2), (-math.pi / 2, math.pi / 2)]


def _file(tmp_path, rng, count, state):
    def value(lo, hi):
        return rng.choice([rng.uniform(lo, hi)] * 8 + [10 ** rng.uniform(-100, 100), 1e-300,
                                                        1e300])
    lines = ["m [kg],l [m],k [N/m],b [m]"
             + (",phi1 [rad],phi2 [rad],phi1_dot [rad/s],phi2_dot [rad/s]" if state else "")]
    moderate = 0
    for i in range(count):
        cells = [value(0.1, 10), value(0.1, 3), value(100, 1000)]
        b = 0.0 if i % 4 else rng.uniform(0.01, 0.5)
        moderate += b == 0 and 0.1 <= cells[0] <= 10 and 0.1 <= cells[1] <= 3 \
            and 100 <= cells[2] <= 1000
        cells.append(b)
        if state:
            cells += [rng.uniform(-2, 2) for _ in range(4)]
        lines.append(",".join(map(repr, cells)))
    extra = ["2 lb,20 in,10 lbf/in,0", "0,1,1,0", "1,1,100,-1"]
    lines += [e + (",0.1,0.2,0,0" if state else "") for e in extra]
    if state:
        lines.append("1,1,100,0,0.1,,0,0")  # no phi2: the one-off asks for it
    path = tmp_path / "pendulums.csv"
    path.write_text("\n".join(lines) + "\n")
    return path, moderate


@pytest.mark.filterwarnings("ignore::RuntimeWarning")  # (the one-off's search at 1e300)
@pytest.mark.parametrize("state", [True, False])
@pytest.mark.parametrize("as_json", [False, True])
def test_batch_rows_are_the_one_offs_byte_for_byte(tmp_path, as_json, state):
    path, moderate = _file(tmp_path, random.Random(60 + state), 80, state)
    calls: list = []
    fast = eom_batch(path, SCENE, as_json, True, calls)
    assert fast == eom_batch(path, SCENE, as_json, False)
    # b = 0 with m in [0.1, 10] kg, l in [0.1, 3] m, k in [100, 1000] N/m on columns (r
    # <= 1 and r > 1 two groups); the rest (b > 0, extremes) and the odd rows the one-off's
    assert fast[0] == 2 and len(calls) <= 80 + 4 - moderate, (len(calls), moderate)
    assert moderate >= 15
    errors = fast[2].splitlines()
    assert sum(e.startswith("Error: line 83: m=") for e in errors) == 1
    assert sum(e.startswith("Error: line 84: b=") for e in errors) == 1


def test_batch_on_columns_without_sympy(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text("m,l,k,phi1,phi2,phi1_dot,phi2_dot\n" + "".join(
        f"{1 + i / 7!r},{0.5 + i / 110!r},{200 + i!r},0.1,0.25,0.5,-1\n" for i in range(300)))
    calls: list = []
    status, out, _err = eom_batch(path, SCENE, False, True, calls)
    assert status == 0 and not calls and out.count("\n") == 301
    rows = list(csv.DictReader(io.StringIO(eom_batch_without_sympy(SCENE, path))))
    assert len(rows) == 300
    m, l, k = 1.0, 0.5, 200.0
    assert float(rows[0]["omega_1 [rad/s]"]) == pytest.approx(math.sqrt(G / l), rel=1e-14)
    assert float(rows[0]["omega_2 [rad/s]"]) == pytest.approx(math.sqrt(G / l + 2 * k / m),
                                                              rel=1e-14)
    phi1, phi2 = 0.1, 0.25  # the accelerations by hand: T = m l^2 (phi1'^2 + phi2'^2)
    want1 = -G * math.sin(phi1) * math.cos(phi2) / l
    want2 = (-G * m * math.sin(phi2) * math.cos(phi1)
             - k * 2 * l * math.sin(phi2) * math.cos(phi2)) / (l * m)
    assert float(rows[0]["phi1_ddot [rad/s^2]"]) == pytest.approx(want1, rel=1e-14)
    assert float(rows[0]["phi2_ddot [rad/s^2]"]) == pytest.approx(want2, rel=1e-14)


@pytest.mark.parametrize("as_json", [False, True])
def test_rows_with_four_and_five_equilibria_on_columns_together(tmp_path, as_json):
    """r = g m / (2 k l) on both sides of 1 in one file: two patterns of equilibria, each a
    group of its own, every row on columns, byte for byte the one-off's."""
    rng = random.Random(9)
    lines = ["m,l,k"]
    for i in range(120):
        m, l = rng.uniform(0.5, 5), rng.uniform(0.2, 2)
        r = rng.uniform(0.2, 0.9) if i % 3 else rng.uniform(1.1, 3)
        lines.append(f"{m!r},{l!r},{G * m / (2 * r * l)!r}")
    path = tmp_path / "mixed.csv"
    path.write_text("\n".join(lines) + "\n")
    calls: list = []
    fast = eom_batch(path, SCENE, as_json, True, calls)
    assert fast == eom_batch(path, SCENE, as_json, False)
    assert fast[0] == 0 and not calls
    four = "phi1=-1.5708, phi2=1.5708 (unstable)"
    texts = fast[1].splitlines()[0 if as_json else 1:]
    assert sum(t.count(four + ";") for t in texts) == 80  # (a fifth follows: r <= 1)
    assert sum(t.count(four + '"') for t in texts) == 40  # (the text ends: r > 1)
