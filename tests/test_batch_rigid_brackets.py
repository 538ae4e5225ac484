"""``rigid-body --scene S --batch`` inverse rows that the one-off solves by a bracketed search
(``J_A=?`` from ``alpha``, a signed ``M0=?``): on columns (dyncalc/scenes/inverse_monotone.py
through dyncalc/batch/fast_rigid.py), byte for byte what the generic path (the one-off's
search row by row) writes, CSV and JSON lines, stderr and exit status, on random rows and
extremes; rows the columns cannot prove go to the one-off with its messages."""
from __future__ import annotations

import json

import numpy as np
import pytest
from helpers import batch_run, fast_same_as_generic

SEED = 20261125


def _bracketed_rows(monkeypatch) -> list:
    """The number of rows each call of monotone_columns proved (solved on columns)."""
    from dyncalc.scenes import inverse_monotone

    solved = []
    original = inverse_monotone.monotone_columns

    def counting(*args):
        out = original(*args)
        solved.append(0 if out is None else int(out.exact.sum()))
        return out

    monkeypatch.setattr(inverse_monotone, "monotone_columns", counting)
    return solved


G = 9.80665


def _drum(m1, m2, r1, r2, J_A, g=G):
    return (m2 * r2 - m1 * r1) * g / (J_A + m1 * r1 ** 2 + m2 * r2 ** 2)


def _two_drums(m1, m2, r1, r2, J1, J2, M0):
    return (G * (m2 * r2 ** 2 - m1 * r1 * r2) + M0 * r2) / (m2 * r2 ** 2 + m1 * r1 ** 2 + J1
                                                           + J2)


#: scene, header, unknown, the target from the other values (a second derivation, so that
#: most rows have a root), the least share of the rows solved on columns
CASES = [
    ("drum-two-blocks", "m1 [kg],m2 [kg],r1 [m],r2 [m],J_A [kg*m^2],alpha [rad/s^2]", "J_A",
     lambda v: _drum(*v[:5]), 0.4),
    ("drum-two-blocks", "m1,m2,r1,r2,J_A,g [m/s^2],S2 [N]", "J_A",
     lambda v: v[1] * (v[5] - v[3] * _drum(*v[:6])), 0.4),
    ("beam-spun-up", "m [kg],l [m],M0 [N*m],alpha [rad/s^2]", "M0",
     lambda v: 3 * v[2] / (v[0] * v[1] ** 2), 0.8),
    ("beam-spun-up", "m [kg],l [m],M0 [N*m],x [m],M [N*m]", "M0",
     lambda v: -v[2] * (1 - v[3] / v[1]) ** 2 * (1 + v[3] / (2 * v[1])), 0.6),
    ("angled-bar-on-shaft", "m [kg],l [m],M0 [N*m],omega [rad/s],A_eta [N]", "M0",
     lambda v: 27 * v[2] / (80 * v[1]), 0.8),
    ("two-drums-rope-drive", "m1,m2,r1,r2,J1,J2,M0 [N*m],a2 [m/s^2]", "M0",
     lambda v: _two_drums(*v[:7]), 0.2),
    ("two-drums-rope-drive", "m1,m2,r1,r2,J1,J2,M0 [N*m],alpha [rad/s^2]", "J2",
     lambda v: _two_drums(*v[:7]) / v[3], 0.1),
]


def _random_values(rng, names: list[str], target, decades: float, noise: float):
    """A row's values: each 10^U(-decades, decades) (a signed M0, a section x inside the
    beam, g at its standard value), the last (the goal) from the others by ``target`` times
    1 + U(-noise, noise)."""
    values = 10.0 ** rng.uniform(-decades, decades, len(names))
    if "x" in names:   # a section on the beam
        values[names.index("x")] = values[names.index("l")] * rng.uniform(0, 0.99)
    if "M0" in names:
        values[names.index("M0")] *= rng.choice([-1.0, 1.0])
    if "g" in names:
        values[names.index("g")] = G
    values[-1] = target(values.tolist()) * (1 + rng.uniform(-noise, noise))
    return values


@pytest.mark.parametrize("as_json", [False, True])
@pytest.mark.parametrize("scene, header, unknown, target, share", CASES)
def test_bracketed_rows_on_columns_are_the_one_off(monkeypatch, scene, header, unknown, target,
                                                   share, as_json):
    rng = np.random.default_rng(SEED + len(header))
    names = [h.split(" ")[0] for h in header.split(",")]
    rows = []
    for i in range(60):
        values = _random_values(rng, names, target, 2, 1e-3)
        cells = [f"{float(x)!r}" for x in values]
        cells[names.index(unknown)] = "?" if i % 3 else ""   # asked, or left out
        rows.append(",".join(cells))
    extremes = ["0", "-2", "1e308", "1e-320", "5e-324", "1.7976931348623157e308", "?", "",
                "x", "inf", "nan"]
    given = 0
    for bad in extremes:   # in a parameter, then in the target
        for column in (given, len(names) - 1):
            cells = ["3.0"] * len(names)
            cells[names.index(unknown)] = "?"
            cells[column] = bad
            rows.append(",".join(cells))
    solved = _bracketed_rows(monkeypatch)
    args = ["rigid-body", "--scene", scene, "--batch", "-", "--on-error", "skip"] + (
        ["--json"] if as_json else [])
    fast = fast_same_as_generic(monkeypatch, args, "\n".join([header, *rows]) + "\n")
    assert sum(solved) >= share * 60
    assert fast.exit_code == 2 and "Error: line" in fast.stderr


def test_bracketed_numbers_and_method():
    """drum-two-blocks: J_A = (m2 r2 - m1 r1) g / alpha - m1 r1^2 - m2 r2^2 (the formula turned
    around: a second derivation); beam-spun-up: M0 = alpha m l^2 / 3, of either sign."""
    out = batch_run(["rigid-body", "--scene", "drum-two-blocks", "--batch", "-", "--json"],
                    "m1 [kg],m2 [kg],r1 [m],r2 [m],J_A [kg*m^2],alpha [rad/s^2]\n"
                    "20,15,0.2,0.4,?,3\n20,15,0.2,0.4,,2\n")
    assert out.exit_code == 0, out.stderr
    lines = [json.loads(line) for line in out.stdout.splitlines()]
    for line, alpha in zip(lines, (3.0, 2.0)):
        J_A = (15 * 0.4 - 20 * 0.2) * 9.80665 / alpha - 20 * 0.04 - 15 * 0.16
        assert line["results"]["J_A"]["value"] == pytest.approx(J_A, rel=1e-14)
        assert line["extra"]["inverse"] == {
            "unknown": "J_A", "method": "bracketed-root",
            "detail": "a sign change on a grid of J_A, refined by Brent's method"}
    out = batch_run(["rigid-body", "--scene", "beam-spun-up", "--batch", "-"],
                    "m [kg],l [m],M0 [N*m],alpha [rad/s^2]\n6,2,?,1.5\n6,2,?,-0.75\n")
    assert out.exit_code == 0, out.stderr
    found = [float(line.split(",")[4]) for line in out.stdout.splitlines()[1:]]
    assert found == [pytest.approx(12.0, rel=1e-15), pytest.approx(-6.0, rel=1e-15)]


def test_rows_the_columns_cannot_prove_take_the_one_off(monkeypatch):
    """No root (alpha of the wrong sign: the one-off's message with the range it takes) and
    a flat result (omega at t = 0 whatever M0) go row by row with the one-off's messages; the
    good row after each is solved on columns."""
    solved = _bracketed_rows(monkeypatch)
    text = ("m1,m2,r1,r2,J_A,alpha\n20,15,0.2,0.4,?,-2\n20,15,0.2,0.4,?,3\n")
    fast = fast_same_as_generic(monkeypatch, ["rigid-body", "--scene", "drum-two-blocks",
                                "--batch", "-", "--on-error", "skip"], text)
    assert sum(solved) == 1
    assert fast.exit_code == 2
    assert fast.stderr == (
        "Error: line 2: no value of J_A gives alpha = -2 rad/s^2 in drum-two-blocks with the "
        "other parameters given; over the values of J_A tried it ranges from 1.09103e-307 to "
        "6.12916 rad/s^2\n")
    solved.clear()
    text = "m,l,M0,t,omega\n6,2,?,0,1\n6,2,?,2,3\n"
    fast = fast_same_as_generic(monkeypatch, ["rigid-body", "--scene", "beam-spun-up", "--batch",
                                "-", "--on-error", "skip"], text)
    assert sum(solved) == 1 and fast.exit_code == 2
    assert fast.stderr.startswith("Error: line 2: ")


def test_seed_is_the_root_of_a_linear_fractional_result():
    """The cross-ratio seed inverts y = (p x + q)/(r x + s) (and a line, r = 0) through any
    three of its points: the root x = (s goal - q)/(p - r goal), to rounding."""
    from dyncalc.scenes.inverse_monotone import _seed

    rng = np.random.default_rng(SEED)
    for _ in range(500):
        p, q, r, s = rng.uniform(-5, 5, 4) * 10.0 ** rng.uniform(-3, 3, 4)
        r = 0.0 if rng.uniform() < 0.2 else r
        xs = tuple(sorted(rng.uniform(-10, 10, 3)))
        root = rng.uniform(-10, 10)
        goal = (p * root + q) / (r * root + s)
        ys = [(p * x + q) / (r * x + s) for x in xs]
        spread = max(abs(v) for v in ys) + abs(goal)
        if min(abs(a - b) for a, b in ((ys[0], ys[1]), (ys[1], ys[2]), (goal, ys[2]))) \
                < 1e-3 * spread:
            continue   # points too close together to fix the map
        assert _seed(xs, ys, goal) == pytest.approx(root, rel=1e-6, abs=1e-6)


@pytest.mark.parametrize("case", [0, 2, 5])
def test_the_seeded_step_is_proven_without_bisection(monkeypatch, case):
    """On random rows of drum-two-blocks (J_A), beam-spun-up and two-drums-rope-drive (M0,
    signed), the step the seed picks is the proven one on every row solved, coarse and fine:
    the bisection (which a wrong seed would need) proves no row."""
    from dyncalc.scenes import inverse_monotone

    scene, header, unknown, target, _ = CASES[case]
    proofs = []
    original = inverse_monotone._proven
    locate = inverse_monotone._locate

    def proving(*args):
        out = original(*args)
        proofs[-1].append(int(out[2].sum()))
        return out

    def locating(*args):
        proofs.append([])
        return locate(*args)

    monkeypatch.setattr(inverse_monotone, "_proven", proving)
    monkeypatch.setattr(inverse_monotone, "_locate", locating)
    solved = _bracketed_rows(monkeypatch)
    rng = np.random.default_rng(SEED)
    names = [h.split(" ")[0] for h in header.split(",")]
    rows = []
    for _ in range(40):
        values = _random_values(rng, names, target, 1, 0.0)
        rows.append(",".join("?" if n == unknown else repr(float(v))
                             for n, v in zip(names, values)))
    out = batch_run(["rigid-body", "--scene", scene, "--batch", "-"],
                    "\n".join([header, *rows]) + "\n")
    assert out.exit_code in (0, 2)
    assert sum(solved) >= 15
    assert len(proofs) == 2 * len(solved)   # a coarse and a fine step each call
    assert all(sum(redo) == 0 for first, *redo in proofs), proofs


def test_the_drum_kernel_narrowed_to_one_result_is_that_result():
    """``only=NAME``: the one result, bit for bit the full kernel's, exact on the rows where
    the full kernel's is certain (a superset of its exact rows, which need every result)."""
    from dyncalc.physics.kinetics import drum_two_blocks
    from dyncalc.physics.kinetics_columns import KERNELS

    kernel = KERNELS[drum_two_blocks]
    rng = np.random.default_rng(SEED)
    m1, m2, r1, r2, J_A = 10.0 ** rng.uniform(-3, 3, (5, 2000))
    m2[:50] = m1[:50] * r1[:50] / r2[:50]   # alpha near zero: rows the kernel cannot prove
    # r2 alpha = g (J_A = -m1 r1 (r1 + r2), a kernel test): S2 = m2 (g - r2 alpha) cancels
    J_A[50:100] = -m1[50:100] * r1[50:100] * (r1[50:100] + r2[50:100])
    full = kernel(m1, m2, r1, r2, J_A, np.full(2000, G))
    for name in ("alpha", "a1", "a2", "S1", "S2"):
        one = kernel(m1, m2, r1, r2, J_A, np.full(2000, G), only=name)
        assert list(one.values) == [name]
        assert np.array_equal(one.values[name], full.values[name], equal_nan=True)
        assert not (full.exact & ~one.exact).any()
    alpha = kernel(m1, m2, r1, r2, J_A, np.full(2000, G), only="alpha")
    assert (alpha.exact & ~full.exact)[50:100].any()   # S2 uncertain, alpha certain
    assert not alpha.exact[:50].all()


def test_the_search_asks_the_drum_kernel_for_the_target_alone(monkeypatch):
    """Every evaluation of the power-law probes and the bracketed search but the last (the
    answer) reads ``alpha`` alone; the rows written are the one-off's (the byte-for-byte
    test above)."""
    from dyncalc.physics.kinetics import drum_two_blocks
    from dyncalc.physics.kinetics_columns import KERNELS

    kernel = KERNELS[drum_two_blocks]
    asked = []

    def spy(*args, **kwargs):
        asked.append(kwargs.get("only"))
        return kernel(*args, **kwargs)

    spy.takes_only = True
    monkeypatch.setitem(KERNELS, drum_two_blocks, spy)
    rng = np.random.default_rng(SEED)
    scene, header, unknown, target, _ = CASES[0]
    names = [h.split(" ")[0] for h in header.split(",")]
    rows = [",".join("?" if n == unknown else repr(float(v)) for n, v in
                     zip(names, _random_values(rng, names, target, 1, 0.0))) for _ in range(30)]
    solved = _bracketed_rows(monkeypatch)
    out = batch_run(["rigid-body", "--scene", scene, "--batch", "-"],
                    "\n".join([header, *rows]) + "\n")
    assert out.exit_code == 0 and sum(solved) >= 15
    # the power-law probes and their root (none a power law), the bracketed search, then
    # the answer: every result
    assert len(asked) > 5 and set(asked[:-1]) == {"alpha"} and asked[-1] is None
