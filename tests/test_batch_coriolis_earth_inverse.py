"""``coriolis --batch`` Earth inverse rows (a result column, ``?`` in the speed, rate, mass or
latitude column) solved on columns (dyncalc/batch/fast_coriolis_earth.py): byte for byte what
the generic path (the one-off's solver row by row) writes, CSV and JSON lines, stderr and exit
status, on random rows and extremes; the rows it leaves (a heading to solve for, refusals,
warnings) are the one-off's."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from dyncalc.constants import EARTH_RATE
from helpers import batch_run, count_block_rows, fast_same_as_generic

SEED = 1124


def _solved_rows(monkeypatch) -> list:
    from dyncalc.batch import fast_coriolis_earth

    return count_block_rows(monkeypatch, fast_coriolis_earth)


def _cell(rng, name: str) -> str:
    if name == "latitude":
        return f"{float(rng.uniform(-90, 90))!r}"
    if name == "heading":
        return f"{float(rng.uniform(-720, 720))!r}"
    if name == "omega":
        return f"{float(EARTH_RATE * 10.0 ** rng.uniform(-2, 2))!r}"
    return f"{float(10.0 ** rng.uniform(-3, 4))!r}"


#: header, unknown, the least share of the random rows solved on columns
CASES = [
    ("a_c_mag [m/s^2],latitude [deg],vr [m/s]", "vr", 0.95),
    ("F_c_mag [N],latitude [deg],speed [km/h],heading [deg],mass [g]", "mass", 0.95),
    ("F_c_horizontal_mag [kN],latitude [deg],vr [km/h],mass [kg]", "vr", 0.95),
    ("a_c_mag [m/s^2],latitude [deg],vr [m/s],heading [deg],omega [rad/s]", "omega", 0.95),
    ("a_c_horizontal_mag [m/s^2],vr [m/s],latitude", "latitude", 0.8),
    ("a_c_mag [m/s^2],latitude,vr [m/s],heading [deg]", "latitude", 0.5),
    ("a_c_mag [m/s^2],latitude [deg],vr [m/s],heading", "heading", 0.0),   # the one-off's
]


@pytest.mark.parametrize("as_json", [False, True])
@pytest.mark.parametrize("header, unknown, share", CASES)
def test_earth_inverse_rows_on_columns_are_the_one_off(monkeypatch, header, unknown, share,
                                                       as_json):
    """The goal of each random row is the result at a latitude between 3 and 87 degrees and
    the row's speed and heading (where the latitude is solved for, a root exists); extremes
    run the one-off."""
    rng = np.random.default_rng(SEED + len(header))
    names = [h.split(" ")[0] for h in header.split(",")]
    rows = []
    for _ in range(100):
        cells = [_cell(rng, name) for name in names]
        phi = math.radians(rng.uniform(3, 87))
        v = float(cells[names.index("vr")]) if "vr" in names else 1.0
        psi = math.radians(float(cells[names.index("heading")])) if "heading" in names else 0.0
        # the result at phi (the speed typed in m/s where the latitude is solved for)
        horizontal = names[0].startswith("a_c_horizontal")
        ratio = abs(math.sin(phi)) if horizontal else math.sqrt(
            math.sin(phi) ** 2 + (math.cos(phi) * math.sin(psi)) ** 2)
        cells[0] = f"{2 * EARTH_RATE * v * ratio!r}"
        cells[names.index(unknown)] = "?"
        rows.append(",".join(cells))
    given = 1 if names[1] != unknown else 2
    for bad in ("0", "-2", "1e308", "1e-320", "?", "", "x", "95", "nan"):
        cells = ["3.0"] * len(names)
        cells[0] = "1e-4"
        cells[names.index(unknown)] = "?"
        cells[given] = bad
        rows.append(",".join(cells))
    for goal in ("0", "-1e-4", "1e300", "5e-324"):
        cells = ["3.0"] * len(names)
        cells[0] = goal
        cells[names.index(unknown)] = "?"
        rows.append(",".join(cells))
    solved = _solved_rows(monkeypatch)
    args = ["coriolis", "--batch", "-", "--on-error", "skip"] + (["--json"] if as_json else [])
    fast = fast_same_as_generic(monkeypatch, args, "\n".join([header, *rows]) + "\n")
    assert sum(solved) >= share * 100
    assert fast.exit_code == 2 and "Error: line" in fast.stderr


def test_earth_inverse_numbers():
    """|a_c,h| = 2 Omega_E v |sin phi|: v = 1e-4 / (2 Omega_E sin 45 deg) at 45 deg, and the
    latitude asin(1e-4 / (2 Omega_E 10 m/s)) at 10 m/s, in radians (bracketed: the one-off's grid and
    Brent's method, to the last bits of asin)."""
    out = batch_run(["coriolis", "--batch", "-", "--json"],
                    "a_c_horizontal_mag [m/s^2],latitude [deg],vr\n1e-4,45,?\n"
                    "a_c_horizontal_mag [m/s^2],latitude,vr [m/s]\n")
    line = json.loads(out.stdout.splitlines()[0])
    assert line["results"]["vr"]["value"] == pytest.approx(
        1e-4 / (2 * EARTH_RATE * math.sqrt(0.5)), rel=1e-14)
    assert line["extra"]["inverse"]["method"] == "closed-form"
    out = batch_run(["coriolis", "--batch", "-", "--json"],
                    "a_c_horizontal_mag [m/s^2],vr [m/s],latitude\n0.0001,10,?\n")
    line = json.loads(out.stdout)
    assert line["results"]["latitude"] == {
        "value": pytest.approx(math.asin(1e-4 / (2 * EARTH_RATE * 10)), rel=1e-12),
        "unit": "rad"}
    assert line["extra"]["inverse"] == {
        "unknown": "latitude", "method": "bracketed-root",
        "detail": "a sign change on a grid of latitude, refined by Brent's method"}
