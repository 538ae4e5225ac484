"""Column kernels of the damping-ratio physics (dyncalc.physics.damping) against the one-off
functions, bit for bit; rows with a note are not exact."""
from __future__ import annotations

import math

import numpy as np

from dyncalc.physics.columns import kernel_of
from dyncalc.physics.damping import (damping_from_coefficients, damping_from_decrement,
                                     damping_from_zeta)
from dyncalc.units import Q_


def _si(value):
    return value.to_base_units().magnitude if hasattr(value, "to_base_units") else value


def _check(out, outcomes):
    for i, outcome in enumerate(outcomes):
        if outcome.warnings or list(outcome.values) != list(out.values):
            assert not out.exact[i], i
            continue
        if out.exact[i]:
            for name, value in outcome.values.items():
                got = out.values[name][i]
                if isinstance(value, str):
                    assert got == value
                else:
                    assert np.float64(_si(value)).view(np.int64) == np.float64(got).view(
                        np.int64), (i, name)


def test_coefficients_kernel():
    rng = np.random.default_rng(12)
    n = 800
    k, m = 10.0 ** rng.uniform(-6, 6, n), 10.0 ** rng.uniform(-6, 6, n)
    c = 2.0 * np.sqrt(k * m) * rng.uniform(0.0, 1.0, n)
    c[:80] = 10.0 ** rng.uniform(-300, 300, 80)
    k[80:120], m[80:120] = 10.0 ** rng.uniform(-300, 300, 40), 10.0 ** rng.uniform(-300, 300, 40)
    c[120:130] = 0.0
    c[130], k[130], m[130] = 20.0, 100.0, 1.0       # critical: zeta = 1 with a note
    c[131], k[131], m[131] = 4.0, 100.0, 1.0        # zeta = 0.2, omega = 10
    out = kernel_of(damping_from_coefficients)(c, k, m)
    _check(out, [damping_from_coefficients(Q_(x, "N*s/m"), Q_(y, "N/m"), Q_(z, "kg"))
                 for x, y, z in zip(c.tolist(), k.tolist(), m.tolist())])
    assert not out.exact[120:131].any() and out.exact[132:].mean() > 0.95
    assert out.values["zeta"][131] == 0.2 and out.values["omega"][131] == 10.0
    assert out.values["omega_d"][131] == math.sqrt(96.0)


def test_decrement_kernel():
    rng = np.random.default_rng(13)
    n = 600
    delta = 10.0 ** rng.uniform(-300, 300, n)
    delta[:200] = 10.0 ** rng.uniform(-6, 2, 200)
    delta[0] = 0.0
    omega = 10.0 ** rng.uniform(-5, 5, n)
    k, m = 10.0 ** rng.uniform(-5, 5, n), 10.0 ** rng.uniform(-5, 5, n)
    for kw, call in ((dict(), lambda i: {}),
                     (dict(omega=omega), lambda i: {"omega": Q_(omega[i], "rad/s")}),
                     (dict(k=k, m=m), lambda i: {"k": Q_(k[i], "N/m"), "m": Q_(m[i], "kg")})):
        out = kernel_of(damping_from_decrement)(delta, **kw)
        _check(out, [damping_from_decrement(float(delta[i]), **call(i)) for i in range(n)])
        assert not out.exact[0] and out.exact[1:200].mean() > 0.95   # the ordinary rows
    # E5.18 of Gross et al.: a tenth in ten cycles
    e518 = kernel_of(damping_from_decrement)(np.array([math.log(10) / 10]))
    assert round(e518.values["zeta"][0], 9) == 0.036622197


def test_zeta_kernel():
    rng = np.random.default_rng(14)
    zeta = np.concatenate([rng.uniform(0, 1, 500), 10.0 ** rng.uniform(-300, 0, 100),
                           [0.0, 1.0, 1.0 - 2.0 ** -52, 2.0, 0.5]])
    out = kernel_of(damping_from_zeta)(zeta)
    _check(out, [damping_from_zeta(z) for z in zeta.tolist()])
    assert out.exact[:600].mean() > 0.95 and not out.exact[600:604].any()
    assert out.values["Q"][604] == 1.0 and round(out.values["delta"][604], 12) == 3.627598728468
