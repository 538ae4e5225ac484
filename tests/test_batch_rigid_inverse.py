"""``rigid-body --scene S --batch`` inverse rows (a result column and a parameter left out or
``?``): those whose result is a power of the unknown are solved in closed form on columns
(dyncalc/batch/fast_rigid.py), byte for byte what the generic path (the one-off's solver row
by row) writes, CSV and JSON lines, stderr and exit status, on random rows and extremes; the
others (a bracketed search, a refusal) run the one-off."""
from __future__ import annotations

import json

import numpy as np
import pytest
from helpers import batch_run, count_block_rows, fast_same_as_generic

SEED = 20261124


def _solved_rows(monkeypatch) -> list:
    from dyncalc.batch import fast_rigid

    return count_block_rows(monkeypatch, fast_rigid)


#: scene, header, unknown, the least share of the random rows solved on columns
CASES = [
    ("beam-spun-up", "m [kg],l [m],M0 [N*m],alpha [rad/s^2]", "m", 0.95),
    ("beam-spun-up", "m [kg],l [m],M0 [N*m],M [N*m],x [m]", "M0", 0.0),   # signed: one-off
    ("beam-spun-up", "m [kg],l [m],M0 [N*m],alpha [rad/s^2]", "l", 0.95),
    ("drum-two-blocks", "m1,m2,r1,r2,J_A,g [m/s^2],alpha [rad/s^2]", "g", 0.3),
    ("double-pendulum-impulse", "m [kg],l [m],F_hat [N*s],omega_1 [rad/s]", "F_hat", 0.95),
    ("double-pendulum-impulse", "m [g],l [cm],F_hat [N*s],omega_1 [rpm]", "m", 0.5),
]


@pytest.mark.parametrize("as_json", [False, True])
@pytest.mark.parametrize("scene, header, unknown, share", CASES)
def test_inverse_rows_on_columns_are_the_one_off(monkeypatch, scene, header, unknown, share,
                                                 as_json):
    rng = np.random.default_rng(SEED + len(header))
    names = [h.split(" ")[0] for h in header.split(",")]
    rows = []
    for i in range(120):
        cells = [f"{float(x)!r}" for x in 10.0 ** rng.uniform(-3, 3, len(names))]
        cells[names.index(unknown)] = "?" if i % 3 else ""   # asked, or left out
        rows.append(",".join(cells))
    given = 0 if unknown != names[0] else 1
    for bad in ("0", "-2", "1e308", "1e-320", "?", "", "x", "inf"):
        cells = ["3.0"] * len(names)
        cells[names.index(unknown)] = "?"
        cells[given] = bad
        rows.append(",".join(cells))
    cells = ["3.0"] * len(names)
    cells[names.index(unknown)] = "3.0"                     # every parameter given
    rows.append(",".join(cells))
    solved = _solved_rows(monkeypatch)
    args = ["rigid-body", "--scene", scene, "--batch", "-", "--on-error", "skip"] + (
        ["--json"] if as_json else [])
    fast = fast_same_as_generic(monkeypatch, args, "\n".join([header, *rows]) + "\n")
    assert sum(solved) >= share * 120
    assert fast.exit_code == 2 and "Error: line" in fast.stderr


def test_inverse_numbers_and_method():
    """beam-spun-up: alpha = M0 / (m l^2 / 3), so m = 3 M0 / (alpha l^2): 3 * 12 / (1.5 * 4)
    = 6 kg; drum-two-blocks' alpha is proportional to g; J_A enters a sum: the one-off's
    bracketed search (row by row), the same root, alpha = (m2 r2 - m1 r1) g / (J_A + ...)."""
    out = batch_run(["rigid-body", "--scene", "beam-spun-up", "--batch", "-", "--json"],
                    "m [kg],l [m],M0 [N*m],alpha [rad/s^2]\n?,2,12,1.5\n,0.5,3,4\n")
    lines = [json.loads(line) for line in out.stdout.splitlines()]
    assert out.exit_code == 0
    assert lines[0]["results"]["m"]["value"] == pytest.approx(6.0, rel=1e-15)
    assert lines[1]["results"]["m"]["value"] == pytest.approx(3 * 3 / (4 * 0.25), rel=1e-15)
    assert lines[0]["extra"]["inverse"] == {
        "unknown": "m", "method": "closed-form",
        "detail": "alpha is proportional to m^(-1): inverted exactly"}
    out = batch_run(["rigid-body", "--scene", "drum-two-blocks", "--batch", "-", "--json"],
                    "m1 [kg],m2 [kg],r1 [m],r2 [m],J_A [kg*m^2],alpha [rad/s^2]\n"
                    "20,15,0.2,0.4,?,3\n")
    line = json.loads(out.stdout)
    J_A = (15 * 0.4 - 20 * 0.2) * 9.80665 / 3 - 20 * 0.04 - 15 * 0.16
    assert line["results"]["J_A"]["value"] == pytest.approx(J_A, rel=1e-12)
    assert line["extra"]["inverse"]["method"] == "bracketed-root"


def test_bracketed_rows_take_the_one_off(monkeypatch):
    """A row whose unknown is no power law and not monotone (m1 enters both the numerator and
    the denominator of drum-two-blocks' alpha) is not solved on columns; the monotone ones
    (J_A) are, tests/test_batch_rigid_brackets.py."""
    solved = _solved_rows(monkeypatch)
    text = "m1,m2,r1,r2,J_A,alpha\n?,15,0.2,0.4,2,3\n?,15,0.2,0.4,2,2\n"
    fast = fast_same_as_generic(monkeypatch, ["rigid-body", "--scene", "drum-two-blocks",
                                "--batch", "-"], text)
    assert fast.exit_code == 0 and sum(solved) == 0
    assert fast.stdout.count("\n") == 3
