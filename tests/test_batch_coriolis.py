"""``coriolis --batch`` on the vectorised paths against the one-off, byte for byte: the Earth
form (``--latitude``) on whole columns, with the array twins it stands on
(:mod:`dyncalc.physics.earth_columns`) checked against the one-off functions."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest

from dyncalc.commands import coriolis_earth_columns
from dyncalc.constants import EARTH_RATE
from dyncalc.physics.earth_columns import compass_sectors, cos_sin_degrees_rows
from dyncalc.physics.frames import cos_sin_degrees
from helpers import batch_run, fast_same_as_generic

RNG_SEED = 20261124


def _bits(a) -> np.ndarray:
    return np.asarray(a, dtype=float).view(np.int64)


def test_cos_sin_degrees_rows_is_the_one_off_bit_for_bit():
    rng = np.random.default_rng(RNG_SEED)
    degrees = np.concatenate([
        rng.uniform(-90, 90, 4000), rng.uniform(-1e6, 1e6, 2000),
        np.arange(-720.0, 720.5, 7.5),                      # multiples of 90, 45, 30, 22.5
        [0.0, -0.0, 45.0, -45.0, 135.0, 1e300, -1e300, 5e-324, 89.99999999999999]])
    c, s = cos_sin_degrees_rows(degrees)
    expected = np.array([cos_sin_degrees(float(d)) for d in degrees])
    assert (_bits(c) == _bits(expected[:, 0])).all()
    assert (_bits(s) == _bits(expected[:, 1])).all()
    # the exact values at the quarter turns and 30 degrees, as the one-off's doctest
    c, s = cos_sin_degrees_rows(np.array([90.0, 180.0, 30.0]))
    assert c.tolist()[:2] == [0.0, -1.0] and s.tolist()[2] == 0.5


def _one_off_sector(east: float, north: float) -> int:
    bearing = math.degrees(math.atan2(east, north)) % 360.0
    return round(bearing / 22.5) % 16


def test_compass_sectors_match_the_one_off_also_at_the_boundaries():
    rng = np.random.default_rng(RNG_SEED + 1)
    n = 20000
    east = rng.normal(size=n) * 10.0 ** rng.integers(-300, 300, n)
    north = rng.normal(size=n) * 10.0 ** rng.integers(-300, 300, n)
    east[:500], north[500:1000] = 0.0, 0.0
    north[1000:1200] = -0.0
    # on and next to the boundaries between compass points (11.25 + 22.5 k degrees)
    angles = np.radians(11.25 + 22.5 * np.arange(16))
    edge_e = np.concatenate([np.sin(angles), np.nextafter(np.sin(angles), 2.0),
                             np.nextafter(np.sin(angles), -2.0)])
    edge_n = np.concatenate([np.cos(angles)] * 3)
    east, north = np.concatenate([east, edge_e]), np.concatenate([north, edge_n])
    expected = [_one_off_sector(e, n_) for e, n_ in zip(east.tolist(), north.tolist())]
    assert compass_sectors(east, north).tolist() == expected


def _fast_and_generic(monkeypatch, args, text):
    """The output of ``args`` with the file ``text`` on the vectorised path and on the
    generic one, and the number of rows the Earth adapter marked exact."""
    exact = []
    adapter = coriolis_earth_columns.earth_columns

    def counting(given, settings):
        out = adapter(given, settings)
        if out is not None:
            exact.append(int(np.count_nonzero(out.exact)))
        return out

    monkeypatch.setattr(coriolis_earth_columns, "earth_columns", counting)
    return fast_same_as_generic(monkeypatch, args, text), sum(exact)


def _random_rows(rng, n: int, form: str) -> list[str]:
    rows = []
    for i in range(n):
        lat = float(rng.uniform(-90, 90))
        lat_text = (f"{lat!r}deg" if i % 5 else f"{math.radians(lat)!r} rad")
        if form == "speed":
            speed, heading, vertical, mass = (float(x) for x in (
                10.0 ** rng.uniform(-3, 4), rng.uniform(-720, 720), rng.uniform(-5, 5),
                10.0 ** rng.uniform(-2, 3)))
            rows.append(f"{lat_text},{speed!r} km/h,{heading!r}deg,{vertical!r},{mass!r}kg")
        else:
            v = (rng.normal(size=3) * 10.0 ** rng.uniform(-3, 3) * (rng.random(3) > 0.2)).tolist()
            rows.append(f'{lat_text},"{v[0]!r},{v[1]!r},{v[2]!r}",'
                        f"{float(abs(rng.normal())) * 1e-4!r}")
    return rows


_EXTREMES = {
    "speed": ["90deg,10m/s,0deg,0,1kg", "-90deg,10m/s,90deg,0,1kg", "0deg,0m/s,0deg,0,1kg",
              "0,3m/s,0,0,1kg",                     # bare zeros: no warning, vectorised
              "0.5,3m/s,10deg,0,1kg",               # a bare latitude warns: vectorised
              "45deg,3m/s,1,0,1kg",                 # a bare heading warns: vectorised
              "91deg,3m/s,0deg,0,1kg",              # refused: beyond the pole
              "45deg,-3m/s,0deg,0,1kg",             # refused: a negative speed
              "45deg,1e300m/s,45deg,1e300,1e300kg", # F_c overflows: refused as the one-off does
              "45deg,1e-320m/s,45deg,0,1kg",        # underflows: the one-off's warning
              "30deg,20m/s,90deg,0,-1kg"],          # refused: a negative mass
    "vr": ['90deg,"10,0,0",7.2921159e-5', '-33deg,"0,0,0",7.2921159e-5',
           '45deg,"0,0,5",0', '45deg,"1e-320,0,0",1e-4', '45deg,"1,2,3",-1e-4',
           '1.5707963267948966 rad,"0,20,0",1e-4'],
}
_HEADERS = {"speed": "latitude,speed,heading,vertical [m/s],mass",
            "vr": "latitude,vr [m/s],omega [rad/s]"}


@pytest.mark.parametrize("form", ["speed", "vr"])
@pytest.mark.parametrize("as_json", [False, True])
def test_earth_batch_is_the_one_off_byte_for_byte(monkeypatch, form, as_json):
    rng = np.random.default_rng(RNG_SEED + (form == "vr"))
    rows = _random_rows(rng, 300, form) + _EXTREMES[form]
    text = "\n".join([_HEADERS[form], *rows]) + "\n"
    args = ["coriolis", "--batch", "-", "--on-error", "skip"] + (["--json"] if as_json else [])
    fast, exact = _fast_and_generic(monkeypatch, args, text)
    assert fast.exit_code == 2 and exact >= 300  # the random rows went through the columns
    assert "Error: line" in fast.stderr       # the refused rows, as the one-off refuses them


def test_earth_batch_rows_that_warn_keep_the_one_offs_warning(monkeypatch):
    """A bare latitude (radians) warns, each row its own text: on columns since session 13
    (a block of its own: the unit typed differs from the next row's)."""
    text = "latitude,vr [m/s]\n0.5,\"0,20,0\"\n45deg,\"0,20,0\"\n"
    fast, exact = _fast_and_generic(monkeypatch, ["coriolis", "--batch", "-", "--json"], text)
    lines = [json.loads(line) for line in fast.stdout.splitlines()]
    assert exact == 2
    assert lines[0]["warnings"] == ["--latitude 0.5 has no unit and is read in radians "
                                    "(28.6479 deg); write 0.5deg for degrees"]
    assert lines[1]["warnings"] == []


def test_earth_batch_numbers_and_directions():
    """At 45 deg N a northward 20 m/s: a_c = 2 Omega x v_r = (-2 W sin45 v, 0, 0), to the
    west; the Coriolis force pushes east (to the right of the motion). At the pole an
    eastward 10 m/s: a_c = (0, 2 W v, 0), north; the force south."""
    text = "latitude,vr [m/s],mass [kg]\n45deg,\"0,20,0\",2\n90deg,\"10,0,0\",1\n"
    out = batch_run(["coriolis", "--batch", "-", "--json"], text)
    assert out.exit_code == 0, out.stderr
    first, pole = (json.loads(line) for line in out.stdout.splitlines())
    a_c = first["results"]["a_c"]["value"]
    assert a_c[0] == pytest.approx(-2 * EARTH_RATE * math.sqrt(0.5) * 20, rel=1e-15)
    assert a_c[1:] == [0.0, 0.0]
    assert first["results"]["F_c_horizontal"]["value"] == [-2 * a_c[0], 0.0, 0.0]
    assert first["extra"] == {"frame": "east-north-up",
                              "directions": {"a_c": "west", "F_c": "east"}}
    assert pole["results"]["a_c"]["value"] == [0.0, 2 * EARTH_RATE * 10, 0.0]
    assert pole["results"]["coriolis_parameter"]["value"] == 2 * EARTH_RATE
    assert pole["extra"]["directions"] == {"a_c": "north", "F_c": "south"}


# --- a motion given in time: derived once per batch ------------------------------------------

_TIME_ARGS = ["coriolis", "--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "--omega", "0, 0, c*t",
              "c=0.5rad/s^2", "--mass", "2kg", "b=0.5m/s^2"]


def _counting_derivations(monkeypatch) -> list:
    from dyncalc.physics import relative_time

    calls = []
    derive = relative_time._derive

    def counting(*args):
        calls.append(1)
        return derive(*args)

    monkeypatch.setattr(relative_time, "_derive", counting)
    monkeypatch.setattr(relative_time, "_DERIVED", {})
    return calls


@pytest.mark.parametrize("as_json", [False, True])
def test_a_batch_over_times_derives_once_and_is_the_one_off(monkeypatch, as_json):
    """Each row's output equals a one-off run that derives afresh (sympy, no memory), while
    the batch derives once; a parameter column derives once per distinct value."""
    from dyncalc.physics import relative_time

    rng = np.random.default_rng(RNG_SEED + 7)
    times = [float(x) for x in rng.uniform(-3, 6, 40)] + [0.0, 1e-300]
    flag = ["--json"] if as_json else []
    calls = _counting_derivations(monkeypatch)
    batch = batch_run(_TIME_ARGS + ["--batch", "-", *flag],
                 "t [s]\n" + "".join(f"{t!r}\n" for t in times))
    assert batch.exit_code == 0, batch.stderr
    assert len(calls) == 1
    lines = batch.stdout.splitlines()
    if not as_json:
        lines = lines[1:]
    for t, line in zip(times, lines):
        relative_time._DERIVED.clear()
        if as_json:
            one = batch_run(_TIME_ARGS + ["--t", f"{t!r} s", "--json"], "")
            assert one.exit_code == 0, one.stderr
            mine = json.loads(line)
            del mine["line"], mine["inputs"]["t"]
            theirs = json.loads(one.stdout)
            del theirs["inputs"]["t"]
            assert json.dumps(mine) == json.dumps(theirs)
        else:  # the same row alone, derived afresh
            alone = batch_run(_TIME_ARGS + ["--batch", "-"], f"t [s]\n{t!r}\n")
            assert alone.stdout.splitlines() == [batch.stdout.splitlines()[0], line]
    assert len(calls) == 1 + len(times)
    calls.clear()
    relative_time._DERIVED.clear()
    text = "t [s],b [m/s^2]\n" + "".join(f"{t!r},{0.5 + (i % 3)}\n" for i, t in enumerate(times))
    assert batch_run(_TIME_ARGS + ["--batch", "-"], text).exit_code == 0
    assert len(calls) == 3


# --- inverse rows: a result column and a ? cell, row by row through the one-off --------------

@pytest.mark.parametrize("header, cells, one_off", [
    ("a_c [m/s^2],omega [rad/s],vr", "12,2,?", ["a_c=12 m/s^2", "--omega", "2 rad/s", "vr=?"]),
    ("F_c [N],vr [m/s],mass [kg],omega", "6,3,2,?",
     ["F_c=6 N", "--vr", "3 m/s", "--mass", "2 kg", "omega=?"]),
    ("a_c_mag [m/s^2],latitude [deg],vr", "0.01,45,?",
     ["a_c_mag=0.01 m/s^2", "--latitude", "45 deg", "vr=?"]),
    ("a_c_horizontal_mag [m/s^2],vr [m/s],latitude", "0.0001,10,?",
     ["a_c_horizontal_mag=0.0001 m/s^2", "--vr", "10 m/s", "latitude=?"]),
])
def test_inverse_rows_are_the_one_offs(header, cells, one_off):
    """Before round 6 a result column was refused ("unknown column"); now each such row is
    the one-off's inverse problem, its JSON line the one-off's JSON (line number aside)."""
    batch = batch_run(["coriolis", "--batch", "-", "--json"], f"{header}\n{cells}\n")
    one = batch_run(["coriolis", *one_off, "--json"], "")
    assert batch.exit_code == 0 and one.exit_code == 0, batch.stderr + one.stderr
    mine, theirs = json.loads(batch.stdout), json.loads(one.stdout)
    del mine["line"]
    assert mine == theirs
    assert theirs["extra"]["inverse"]["unknown"] == one_off[-1][:-2]


def test_inverse_rows_numbers_and_an_unknown_column():
    """a_c = 2 Omega v_r: 12 m/s^2 at 2 rad/s is 3 m/s; on the Earth the horizontal part
    2 Omega_E v |sin phi| = 1e-4 m/s^2 at 10 m/s gives sin phi = 1e-4 / (2 Omega_E 10)."""
    out = batch_run(["coriolis", "--batch", "-"], "a_c [m/s^2],omega [rad/s],vr\n12,2,?\n")
    assert float(out.stdout.splitlines()[1].split(",")[3]) == pytest.approx(3.0, rel=1e-15)
    out = batch_run(["coriolis", "--batch", "-"],
               "a_c_horizontal_mag [m/s^2],vr [m/s],latitude\n0.0001,10,?\n")
    latitude = float(out.stdout.splitlines()[1].split(",")[3])
    assert latitude == pytest.approx(math.asin(1e-4 / (2 * EARTH_RATE * 10)), rel=1e-12)
    bad = batch_run(["coriolis", "--batch", "-"], "a_x,vr\n1,2\n")
    assert bad.exit_code == 2
    assert bad.stderr == ("Error: line 1: unknown column 'a_x'; coriolis reads omega, vr, r, "
                          "alpha, v0, a0, ar, mass, latitude, speed, heading, vertical, R0, t\n")


def _solved_rows(monkeypatch) -> list:
    from dyncalc.batch import fast_coriolis

    solved = []
    original = fast_coriolis._solved

    def counting(*args):
        blocks = original(*args)
        solved.extend(len(block.rows) for block in blocks)
        return blocks

    monkeypatch.setattr(fast_coriolis, "_solved", counting)
    return solved


@pytest.mark.parametrize("as_json", [False, True])
@pytest.mark.parametrize("header, unknown", [
    ("a_c [m/s^2],omega [rad/s],vr [m/s]", "vr"), ("a_c [m/s^2],omega [rad/s],vr [m/s]", "omega"),
    ("F_c [N],omega [rad/s],vr [m/s],mass [kg]", "mass"),
    ("F_c [kN],omega [rpm],vr [km/h],mass [g]", "vr")])
def test_perpendicular_inverse_rows_on_columns_are_the_one_off(monkeypatch, header, unknown,
                                                                as_json):
    """Closed-form inverse rows on columns against every row through the one-off's solver,
    byte for byte; extremes (zero, negative, overflowing, two unknowns, a missing cell) run
    the one-off (refused or solved its way)."""
    rng = np.random.default_rng(RNG_SEED + 11)
    names = [h.split(" ")[0] for h in header.split(",")]
    rows = []
    for _ in range(200):
        cells = [f"{float(x)!r}" for x in 10.0 ** rng.uniform(-4, 4, len(names))]
        cells[names.index(unknown)] = "?"
        rows.append(",".join(cells))
    for bad in ("0", "-2", "1e308", "?", ""):
        cells = ["3.0"] * len(names)
        cells[names.index(unknown)] = "?"
        cells[0 if unknown != names[0] else 1] = bad
        rows.append(",".join(cells))
    solved = _solved_rows(monkeypatch)
    args = ["coriolis", "--batch", "-", "--on-error", "skip"] + (["--json"] if as_json else [])
    fast, _exact = _fast_and_generic(monkeypatch, args, "\n".join([header, *rows]) + "\n")
    assert sum(solved) >= 190
    assert "Error: line" in fast.stderr


@pytest.mark.parametrize("as_json", [False, True])
def test_bare_latitudes_and_headings_on_columns_are_the_one_off(monkeypatch, as_json):
    """Columns of bare numbers (radians, as the one-off reads them): every row on columns,
    each non-zero cell with the one-off's warning naming the cell as typed (spaces, exponents,
    signs) and its degrees; zeros warn nothing; beyond the pole refused as the one-off does."""
    rng = np.random.default_rng(RNG_SEED + 7)
    rows = []
    for i in range(300):
        lat, heading = float(rng.uniform(-1.57, 1.57)), float(rng.uniform(-7, 7))
        lat_text = [repr(lat), f" {lat:.3e} ", "0", f"{lat:.4f}"][i % 4]
        heading_text = [repr(heading), "0", f"{heading:.2E}", " 1 "][i % 4 if i % 3 else 0]
        rows.append(f"{lat_text},{float(rng.uniform(0, 40))!r},{heading_text}")
    rows += ["2,3,1", "-0.0,3,-0.0", "1e-300,3,1e-300"]
    text = "latitude,speed [m/s],heading\n" + "\n".join(rows) + "\n"
    args = ["coriolis", "--batch", "-", "--on-error", "skip"] + (["--json"] if as_json else [])
    from dyncalc.batch import fast_commands

    finish, written = fast_commands._finish, []

    def counting(*a, **kw):  # the rows of the blocks the probe let through
        block = finish(*a, **kw)
        written.append(0 if block is None else len(block.rows))
        return block
    monkeypatch.setattr(fast_commands, "_finish", counting)
    fast, exact = _fast_and_generic(monkeypatch, args, text)
    assert exact >= 300 and sum(written) >= 300
    assert fast.exit_code == 2  # 2 rad is beyond the pole: refused, as the one-off refuses it
    if not as_json:
        warned = [line for line in fast.stderr.splitlines() if line.startswith("warning:")]
        assert len(warned) > 300
        lat = float(rows[0].split(",")[0])
        assert warned[0] == (f"warning: line 2: --latitude {rows[0].split(',')[0]} has no "
                             f"unit and is read in radians ({math.degrees(lat):.6g} deg); "
                             f"write {rows[0].split(',')[0]}deg for degrees")
