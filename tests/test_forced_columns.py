"""The forced-response column kernel (dyncalc.physics.forced_columns) against the one-off
(dyncalc.physics.forced.forced_response) bit for bit, row by row: every form (k and m, or
omega with m; zeta, c or Q; the four excitations; Omega or f_exc) over random rows spanning
many decades, rows a hair from resonance (eta = 1 +- 1e-12 and closer, zeta down to 1e-12),
near the peak's and the bandwidth's limits (zeta about 1/sqrt 2 and 0.38268), and rows outside
the kernel's domain (left to the one-off)."""
import math
import random
import struct

import numpy as np
import pytest

from dyncalc.errors import InputError, PhysicsError
from dyncalc.physics.forced import forced_response, resonance_gap
from dyncalc.physics.forced_columns import (forced_columns, half_power_product_columns,
                                            one_minus_two_z2_columns, resonance_gap_columns)


def bits(x: float) -> int:
    return struct.unpack("<q", struct.pack("<d", x))[0]


def one_off(row: dict):
    """The one-off's values for the row, or None where it refuses, warns, or gives a value
    that is not finite and non-zero (what the batch adapter takes from it)."""
    try:
        out = forced_response(**row)
    except (InputError, PhysicsError, ArithmeticError, ValueError):
        return None
    if out.warnings or not all(math.isfinite(v) and v != 0.0 for v in out.values.values()):
        return None
    return out.values


def _log(rng, lo, hi):
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


FORMS = [(nat, damp, exc, freq) for nat in ("km", "omega-m") for damp in ("zeta", "c", "Q")
         for exc in ("F0", "base", "base_accel", "unbalance") for freq in ("Omega", "f_exc")]


def rows_for(form, rng, n, near=False):
    nat, damp, exc, freq = form
    rows = []
    for _ in range(n):
        k, m = _log(rng, 1e-3, 1e9), _log(rng, 1e-4, 1e5)
        omega = math.sqrt(k / m)
        zeta = _log(rng, 1e-12, 0.38) if rng.random() < 0.8 else rng.uniform(0.36, 0.72)
        if near:
            eta = 1.0 + rng.choice([-1, 1]) * _log(rng, 1e-16, 1e-9)
            zeta = _log(rng, 1e-12, 1e-6)
        else:
            eta = _log(rng, 1e-3, 1e3)
        W = eta * omega
        row = {"k": k, "m": m} if nat == "km" else {"omega": omega, "m": m}
        if damp == "zeta":
            row["zeta"] = zeta
        elif damp == "c":
            row["c"] = 2.0 * zeta * math.sqrt(k * m)
        else:
            row["Q"] = 0.5 / zeta
        row[exc] = _log(rng, 1e-6, 1e6)
        if freq == "Omega":
            row["Omega"] = W
        else:
            row["f_exc"] = W / (2 * math.pi)
        rows.append(row)
    return rows


def check(rows):
    """Kernel against the one-off row by row; returns how many rows the kernel answered."""
    given = {name: np.array([r[name] for r in rows]) for name in rows[0]}
    values, exact = forced_columns(given)
    answered = 0
    for i, row in enumerate(rows):
        ref = one_off(row)
        if exact[i]:
            answered += 1
            assert ref is not None, row
            got = {n: float(v[i]) for n, v in values.items() if not math.isnan(v[i])}
            assert set(got) == set(ref), row
            for name, value in ref.items():
                assert bits(got[name]) == bits(value), (name, row, got[name], value)
    return answered


@pytest.mark.parametrize("form", FORMS, ids=["-".join(f) for f in FORMS])
def test_random_rows_bit_for_bit(form):
    rng = random.Random("-".join(form))
    rows = rows_for(form, rng, 400)
    answered = check(rows)
    expected = sum(one_off(r) is not None for r in rows)
    assert answered == expected     # every row the one-off answers, the kernel answers
    assert answered > 250


@pytest.mark.parametrize("form", FORMS[::5], ids=["-".join(f) for f in FORMS[::5]])
def test_near_resonance_rows_bit_for_bit(form):
    rng = random.Random("near" + "-".join(form))
    rows = rows_for(form, rng, 300, near=True)
    answered = check(rows)
    assert answered == sum(one_off(r) is not None for r in rows) and answered > 200


def test_resonance_gap_is_the_exact_rational_rounded():
    """The gap on 20000 rows around resonance, against Fraction (resonance_gap) bit for bit."""
    rng = random.Random(7)
    W, k, m, om = [], [], [], []
    for _ in range(20000):
        kk, mm = _log(rng, 1e-30, 1e30), _log(rng, 1e-30, 1e30)
        w = math.sqrt(kk / mm)
        W.append(w * (1 + rng.choice([-1, 1]) * _log(rng, 1e-17, 1e-1)))
        k.append(kk), m.append(mm), om.append(w)
    W, k, m, om = map(np.array, (W, k, m, om))
    gap, ok = resonance_gap_columns(W, k=k, m=m)
    gap2, ok2 = resonance_gap_columns(W, omega=om)
    assert ok.mean() > 0.999 and ok2.mean() > 0.999
    for i in range(len(W)):
        if ok[i]:
            assert bits(gap[i]) == bits(resonance_gap(W[i], k=k[i], m=m[i]))
        if ok2[i]:
            assert bits(gap2[i]) == bits(resonance_gap(W[i], omega=om[i]))


def test_exact_polynomials_of_zeta():
    from fractions import Fraction

    rng = random.Random(11)
    z = np.array([_log(rng, 1e-40, 1e40) for _ in range(5000)]
                 + [math.sqrt(0.5) * (1 + d * 1e-15) for d in range(-20, 21)]
                 + [0.3826834323650898 * (1 + d * 1e-15) for d in range(-20, 21)])
    s, ok = one_minus_two_z2_columns(z)
    p, ok2 = half_power_product_columns(z)
    assert ok.all() and ok2.all()
    for i, x in enumerate(z.tolist()):
        f = Fraction(x) ** 2
        assert bits(s[i]) == bits(float(1 - 2 * f))
        assert bits(p[i]) == bits(float(1 - 8 * f + 8 * f * f))


def test_outside_the_domain_is_left_to_the_one_off():
    rows = [{"k": 1e200, "m": 1.0, "zeta": 0.1, "F0": 1.0, "Omega": 1.0},
            {"k": 100.0, "m": 1.0, "zeta": 0.1, "F0": 1.0, "Omega": 3.0}]
    given = {n: np.array([r[n] for r in rows]) for n in rows[0]}
    values, exact = forced_columns(given)
    assert exact.tolist() == [False, True]
    assert math.isnan(values["X"][0])


def test_forms_the_kernel_does_not_take():
    base = {"k": np.array([1.0]), "m": np.array([1.0]), "F0": np.array([1.0]),
            "Omega": np.array([2.0])}
    assert forced_columns({**base, "base": np.array([1.0])}) is None     # two excitations
    assert forced_columns({**base, "zeta": np.array([0.1]), "x0": np.array([1.0])}) is None


def with_start(rows, rng):
    """The rows with an initial state and a time (x0, v0 of either sign, zero now and then;
    t over many decades, some exactly on whole periods of the excitation)."""
    out = []
    for row in rows:
        row = dict(row)
        row["x0"] = rng.choice([0.0, rng.uniform(-1, 1), -_log(rng, 1e-9, 1e3)])
        row["v0"] = rng.choice([0.0, rng.uniform(-10, 10), _log(rng, 1e-9, 1e3)])
        W = row["Omega"] if "Omega" in row else 2 * math.pi * row["f_exc"]
        row["t"] = rng.choice([_log(rng, 1e-9, 1e3), 2 * math.pi / W * rng.randint(1, 50)])
        out.append(row)
    return out


@pytest.mark.parametrize("form", FORMS, ids=["-".join(f) for f in FORMS])
def test_total_response_rows_bit_for_bit(form):
    """With x0, v0 and t, the total response x as the one-off gives it, to the bit, and
    every row the one-off answers without a warning is answered."""
    rng = random.Random("t-" + "-".join(form))
    rows = with_start(rows_for(form, rng, 200), rng)
    answered = check(rows)
    assert answered == sum(one_off(r) is not None for r in rows) and answered > 120
    given = {name: np.array([r[name] for r in rows]) for name in rows[0]}
    values, exact = forced_columns(given)
    assert "x" in values and np.isfinite(values["x"][exact]).all()


def test_total_response_without_x0_or_v0():
    rng = random.Random(5)
    rows = with_start(rows_for(FORMS[0], rng, 100), rng)
    for drop in ("x0", "v0"):
        part = [{n: v for n, v in r.items() if n != drop} for r in rows]
        assert check(part) == sum(one_off(r) is not None for r in part) > 60


def test_x0_without_t_is_left_to_the_one_off():
    """The one-off refuses x0 without t: the kernel takes no such block."""
    given = {"k": np.ones(1), "m": np.ones(1), "zeta": np.array([0.1]), "F0": np.ones(1),
             "Omega": np.array([2.0]), "x0": np.ones(1)}
    assert forced_columns(given) is None


def test_transient_branches_bit_for_bit():
    """transient_columns against transient on every branch: under-, critically (within the
    band) and overdamped, t = 0, and zeta = 0."""
    from dyncalc.physics.forced import transient
    from dyncalc.physics.forced_columns import transient_columns
    from dyncalc.physics.outcome import CRITICAL_BAND

    rng = random.Random(11)
    rows = []
    for _ in range(3000):
        zeta = rng.choice([0.0, _log(rng, 1e-9, 0.999), 1.0, 1.0 + CRITICAL_BAND / 4,
                           1.0 - CRITICAL_BAND / 4, _log(rng, 1.001, 1e4)])
        t = rng.choice([0.0, _log(rng, 1e-6, 1e2)])
        rows.append((_log(rng, 1e-2, 1e3), zeta, rng.uniform(-2, 2), rng.uniform(-50, 50), t))
    cols = [np.array(c) for c in zip(*rows)]
    got = transient_columns(*cols)
    branches = set()
    for i, (w, zeta, x0, v0, t) in enumerate(rows):
        assert bits(float(got[i])) == bits(transient(w, zeta, x0, v0, t)), rows[i]
        band = abs((1 - zeta) * (1 + zeta)) <= CRITICAL_BAND
        branches.add("t0" if t == 0 else "critical" if band else "under" if zeta < 1 else "over")
    assert branches == {"t0", "critical", "under", "over"}


def one_off_undamped(row: dict):
    """The one-off's values where its only warning is that the undamped resonance results
    are unbounded (what the kernel answers for an undamped block), else None."""
    from dyncalc.physics.forced import UNDAMPED_WARNING

    try:
        out = forced_response(**row)
    except (InputError, PhysicsError, ArithmeticError, ValueError):
        return None
    if out.warnings != [UNDAMPED_WARNING] or not all(
            math.isfinite(v) and (v != 0.0 or n in ("zeta", "phi"))
            for n, v in out.values.items()):
        return None
    return out.values


@pytest.mark.parametrize("form", FORMS[::3], ids=["-".join(f) for f in FORMS[::3]])
@pytest.mark.parametrize("timed", [False, True])
def test_undamped_rows_bit_for_bit(form, timed):
    """No damping given: the one-off's values (zeta 0, phi 0 or pi, no resonance results)
    to the bit, rows a hair from resonance (refused there) among them."""
    rng = random.Random(f"undamped-{timed}-" + "-".join(form))
    rows = rows_for(form, rng, 150) + rows_for(form, rng, 50, near=True)
    for row in rows:
        for name in ("zeta", "c", "Q"):
            row.pop(name, None)
    if timed:
        rows = with_start(rows, rng)
    given = {name: np.array([r[name] for r in rows]) for name in rows[0]}
    values, exact = forced_columns(given)
    assert "X_res" not in values and "Q" not in values
    phis = set()
    for i, row in enumerate(rows):
        ref = one_off_undamped(row)
        assert bool(exact[i]) == (ref is not None), row
        if ref is None:
            continue
        got = {n: float(v[i]) for n, v in values.items() if not math.isnan(v[i])}
        assert set(got) == set(ref), row
        for name, value in ref.items():
            assert bits(got[name]) == bits(value), (name, row, got[name], value)
        phis.add(got["phi"])
    assert sum(exact) > 120 and phis >= {0.0, math.pi}
