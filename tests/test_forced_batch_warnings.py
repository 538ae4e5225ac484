"""forced-response rows that warn with a value in the text (issue 17: every row vectorised).

Damped rows beyond the resonance peak's limit (``zeta >= 1/sqrt 2``: no peak) or the
half-power bandwidth's (``0.38268 < zeta < 1/sqrt 2``, or a heavily damped base motion: one
half-power frequency only) used to leave the vectorised path for the one-off, row by row.
They are now the kernel's, each row with the one-off's own warning text
(``Columns.row_warnings``). Checked here: the kernel against the one-off bit for bit with the
warnings; whole files against the row-by-row run byte for byte (CSV, JSON lines, stderr);
the texts against a hand derivation; the Python API's warnings at every index.
"""
import math
import random
import struct
import sys
from pathlib import Path

import numpy as np
import pytest

import dyncalc
from dyncalc import batch
from dyncalc.batch.fast_commands import _command_fast
from dyncalc.errors import InputError, PhysicsError
from dyncalc.physics.forced import forced_response
from dyncalc.physics.forced_columns import forced_columns

sys.path.insert(0, str(Path(__file__).parent))
from test_batch_kernels import _same_both_ways  # noqa: E402

#: The two limits, and damping ratios a few ulps either side of each.
EDGE_LOW = math.sqrt((2.0 - math.sqrt(2.0)) / 4.0)   # 0.38268...: the product 1 - 8z^2 + 8z^4
EDGE_HIGH = math.sqrt(0.5)                           # 1/sqrt 2: 1 - 2 z^2


def _ulps(x: float, n: int) -> list[float]:
    out = [x]
    up = down = x
    for _ in range(n):
        up, down = math.nextafter(up, math.inf), math.nextafter(down, 0.0)
        out += [up, down]
    return out


def bits(x: float) -> int:
    return struct.unpack("<q", struct.pack("<d", x))[0]


def _zetas(rng: random.Random, n: int) -> list[float]:
    """Damping ratios over every regime: light, between the limits, heavy, critical, huge,
    and at the limits to the ulp."""
    edges = _ulps(EDGE_LOW, 4) + _ulps(EDGE_HIGH, 4) + [1.0, 0.9999999999, 1.0000000001]
    out = []
    for _ in range(n):
        r = rng.random()
        if r < 0.15:
            out.append(rng.choice(edges))
        elif r < 0.4:
            out.append(rng.uniform(0.3827, 0.7071))
        elif r < 0.8:
            out.append(rng.uniform(0.7071, 3.0))
        elif r < 0.9:
            out.append(math.exp(rng.uniform(math.log(3.0), math.log(1e30))))
        else:
            out.append(rng.uniform(0.01, 0.3827))
    return out


KINDS = ["F0", "base", "base_accel", "unbalance"]


def _rows(rng, kind, n, damping="zeta"):
    rows = []
    for zeta in _zetas(rng, n):
        k, m = math.exp(rng.uniform(-5, 20)), math.exp(rng.uniform(-8, 10))
        row = {"k": k, "m": m, kind: math.exp(rng.uniform(-10, 10)),
               "Omega": math.sqrt(k / m) * math.exp(rng.uniform(-5, 5))}
        if damping == "zeta":
            row["zeta"] = zeta
        elif damping == "Q":
            row["Q"] = 0.5 / zeta
        else:
            row["c"] = 2.0 * zeta * math.sqrt(k * m)
        rows.append(row)
    return rows


def _one_off(row):
    try:
        out = forced_response(**row)
    except (InputError, PhysicsError, ArithmeticError, ValueError):
        return None
    if not all(math.isfinite(v) and v != 0.0 for v in out.values.values()):
        return None
    return out


@pytest.mark.parametrize("damping", ["zeta", "Q", "c"])
@pytest.mark.parametrize("kind", KINDS)
def test_the_kernel_gives_the_one_offs_values_and_warnings(kind, damping):
    rng = random.Random(f"{kind}-{damping}")
    rows = _rows(rng, kind, 500, damping)
    given = {name: np.array([r[name] for r in rows]) for name in rows[0]}
    values, exact, notes = forced_columns(given, with_warnings=True)
    texts = notes(np.arange(len(rows))) or [()] * len(rows)
    warned = answered = 0
    for i, row in enumerate(rows):
        ref = _one_off(row)
        if not exact[i]:
            continue
        answered += 1
        assert ref is not None, row
        got = {n: float(v[i]) for n, v in values.items() if not math.isnan(v[i])}
        assert set(got) == set(ref.values), (row, set(got) ^ set(ref.values))
        for name, value in ref.values.items():
            assert bits(got[name]) == bits(value), (name, row)
        assert list(texts[i]) == list(ref.warnings), row
        warned += bool(ref.warnings)
    # every row the one-off answers is the kernel's (the limits decided to the ulp)
    assert answered == sum(_one_off(r) is not None for r in rows)
    assert warned > (100 if kind != "base" else 0)
    # without the flag, the kernel keeps to the rows that do not warn
    plain, exact_plain = forced_columns(given)
    assert not any(_one_off(r).warnings for r, e in zip(rows, exact_plain.tolist()) if e)


def test_base_motion_loses_its_lower_half_power_frequency_when_heavily_damped():
    """Base motion keeps its peak for every zeta, and loses the lower half-power frequency
    above a damping ratio between 0.5 and 1: the kernel's rows there warn as the one-off."""
    zetas = np.linspace(0.3, 1.2, 901)
    n = len(zetas)
    given = {"k": np.full(n, 100.0), "m": np.ones(n), "zeta": zetas, "base": np.full(n, 1e-3),
             "Omega": np.full(n, 7.0)}
    values, exact, notes = forced_columns(given, with_warnings=True)
    assert exact.all() and np.isfinite(values["V_peak"]).all()
    lost = np.isnan(values["bandwidth"])
    assert lost.any() and not lost.all() and not lost[0] and lost[-1]
    texts = notes(np.arange(n))
    assert all(bool(t) == bool(lose) for t, lose in zip(texts, lost.tolist()))
    assert texts[-1][0].startswith("no lower half-power frequency at zeta = 1.2:")


@pytest.mark.parametrize("zeta, kind", [(0.5, "F0"), (0.6, "base_accel"), (0.45, "unbalance")])
def test_a_half_power_warning_states_the_frequency_derived_by_hand(zeta, kind):
    """The one half-power frequency the text gives: ``eta^2 = 1 - 2 zeta^2 + 2 zeta
    sqrt(1 - zeta^2)`` (its reciprocal for unbalance), from the quartic the peak over sqrt 2
    makes, here in plain floats."""
    k, m = 400.0, 4.0
    omega = math.sqrt(k / m)
    s = 1 - 2 * zeta ** 2 + 2 * zeta * math.sqrt(1 - zeta ** 2)
    eta = math.sqrt(s) if kind != "unbalance" else 1 / math.sqrt(s)
    given = {"k": np.array([k]), "m": np.array([m]), "zeta": np.array([zeta]),
             kind: np.array([1.0]), "Omega": np.array([3.0])}
    _values, exact, notes = forced_columns(given, with_warnings=True)
    assert exact.tolist() == [True]
    (text,) = notes(np.array([0]))[0]
    which, other = ("upper", "lower") if kind != "unbalance" else ("lower", "upper")
    assert text.startswith(f"no {other} half-power frequency at zeta = {zeta:g}: ")
    stated = float(text.split(f"(the {which} one is ")[1].split(" rad/s")[0])
    assert stated == pytest.approx(eta * omega, rel=1e-5)  # %.6g


@pytest.mark.parametrize("header", ["k,m,zeta,F0,Omega", "k [kN/m],m,Q,unbalance,Omega [rpm]",
                                    "omega,m,c,base,f_exc", "k,m,zeta,base_accel,Omega,x0,v0,t"])
def test_files_that_warn_write_the_row_by_row_bytes(tmp_path, header):
    """Whole files, damping over every regime: CSV, JSON lines, stderr (a warning line a
    row) and the exit status as row by row; the rows that warn are vectorised."""
    rng = random.Random(header)
    names = [h.split("[")[0].strip() for h in header.split(",")]
    lines = []
    for zeta in _zetas(rng, 300):
        v = {name: rng.uniform(0.5, 3.0) * 10.0 ** rng.randint(-1, 2) for name in names}
        v["x0"], v["v0"] = rng.uniform(-1, 1), rng.uniform(-1, 1)
        omega = v["omega"] if "omega" in v else math.sqrt(v["k"] / v["m"])  # (k as typed)
        v.update(zeta=zeta, Q=0.5 / zeta, c=2.0 * zeta * v["m"] * omega)
        lines.append(",".join(repr(v[name]) for name in names))
    lines += ["100,1,-0.5,1,3" + ",1" * (len(names) - 5), ",".join(["x"] * len(names))]
    path = tmp_path / "rows.csv"
    path.write_text(header + "\n" + "\n".join(lines) + "\n")
    spec = batch.ForcedRows()
    code, _out, stderr = _same_both_ways(spec, path)
    assert code == 2  # the bad rows, as row by row
    assert stderr.count("warning: line") > 100
    cols = batch.read_header(1, header.split(","), spec)
    table = [[line.split(",")[c.index] for line in lines[:300]] for c in cols]
    blocks = _command_fast(spec, cols, table, True, {})
    covered = sum(len(b.rows) for b in blocks)
    warned = sum(len(b.rows) for b in blocks if b.warns())
    assert covered >= 290 and warned > 100


def test_a_whole_chunk_of_rows_without_a_peak(tmp_path):
    """Every row of the chunk heavily damped (one block, each row's own text): the warning
    lines are the ones written by hand."""
    zetas = [0.75 + 0.01 * i for i in range(40)]
    path = tmp_path / "heavy.csv"
    path.write_text("k,m,zeta,F0,Omega\n" + "".join(f"100,1,{z!r},1,3\n" for z in zetas))
    spec = batch.ForcedRows()
    code, _out, err = _same_both_ways(spec, path)
    assert code == 0
    assert err.splitlines() == [
        f"warning: line {n + 2}: zeta = {z:.6g} >= 1/sqrt(2): the amplitude has no resonance "
        "peak; it is largest at Omega = 0" for n, z in enumerate(zetas)]
    table = [["100"] * 40, ["1"] * 40, [repr(z) for z in zetas], ["1"] * 40, ["3"] * 40]
    cols = batch.read_header(1, ["k", "m", "zeta", "F0", "Omega"], spec)
    (block,) = _command_fast(spec, cols, table, True, {})
    assert len(block.rows) == 40 and block.row_warnings[3] == (
        "zeta = 0.78 >= 1/sqrt(2): the amplitude has no resonance peak; it is largest at "
        "Omega = 0",)


def test_the_api_gives_every_elements_warnings():
    """Arrays through the vectorised path: the warnings of every element (they were the
    first element's only where a block warned), as element-by-element one-offs give them."""
    zeta = np.array([0.1, 0.5, 0.9, 0.6, 0.2, 2.0])
    k = np.linspace(100.0, 600.0, 6)
    r = dyncalc.forced_response(k=k, m="2 kg", F0="1 N", Omega="3 rad/s", zeta=zeta)
    expected = []
    for i in range(6):
        one = dyncalc.forced_response(k=f"{float(k[i])!r} N/m", m="2 kg", F0="1 N",
                                      Omega="3 rad/s", zeta=repr(float(zeta[i])))
        expected += [f"at index {i}: {w}" for w in one.warnings]
    assert r.warnings == expected and len(expected) == 4
    undamped = dyncalc.forced_response(k=k, m="2 kg", F0="1 N", Omega="3 rad/s")
    assert [w.split(":")[0] for w in undamped.warnings] == [f"at index {i}" for i in range(6)]
