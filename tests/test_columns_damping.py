"""Column kernels of the damped scenes (dyncalc/physics/damping.py) against the one-off
functions, bit for bit (see tests/kernel_rows.py): ordinary and extreme rows, undamped rows
(a zero damper), over- and critically damped rows (warned by the one-off) and the textbook
set-ups.
"""
import math

import numpy as np
import pytest

from dyncalc.physics.columns import kernel_of
from dyncalc.physics.damping import (_small_damping_error_array, frame_brace_damper,
                                     pendulum_spring_dashpot, rod_in_fluid,
                                     small_damping_error)
from kernel_rows import check_kernel, log_uniform, mixed, ordinary_rows

N = 500


def _mix(rng, ordinary, n=N):
    return mixed(rng, ordinary, n)


def _ordinary(extra=0):
    return ordinary_rows(N, extra)


def test_pendulum_spring_dashpot_columns():
    rng = np.random.default_rng(21)
    m, a, k = _mix(rng, (-1, 2)), _mix(rng, (-2, 1)), _mix(rng, (0, 4))
    d, g = _mix(rng, (-2, 2)), _mix(rng, (0, 1.5))
    d[:10] = 0.0
    rows = {"m": np.append(m, 2.0), "a": np.append(a, 0.5), "k": np.append(k, 200.0),
            "d": np.append(d, 6.0), "g": np.append(g, 9.80665)}
    counts = check_kernel(pendulum_spring_dashpot, rows,
                          {"m": "kg", "a": "m", "k": "N/m", "d": "N*s/m", "g": "m/s^2"},
                          ordinary=_ordinary(1))
    out = kernel_of(pendulum_spring_dashpot)(**{n: v[-1:] for n, v in rows.items()})
    assert out.exact[0] and out.values["xi"][0] == 0.375          # d / (8 m)
    # zeta = d / (8 sqrt(k m + g m^2 / (2a))), E5.18's set-up: 0.035786312218054468319
    assert abs(out.values["zeta"][0] - 0.035786312218054468319) < 1e-17
    assert counts["missed"] <= 0.1 * counts["clean"]


def test_rod_in_fluid_columns():
    rng = np.random.default_rng(22)
    m, l = _mix(rng, (-1, 2)), _mix(rng, (-2, 1))
    beta, g = _mix(rng, (-1, 2)), _mix(rng, (0, 1.5))
    beta[:10] = 0.0
    rows = {"m": np.append(m, 1.5), "l": np.append(l, 0.8), "beta": np.append(beta, 2.0),
            "g": np.append(g, 9.80665)}
    counts = check_kernel(rod_in_fluid, rows,
                          {"m": "kg", "l": "m", "beta": "N*s/m^2", "g": "m/s^2"},
                          ordinary=_ordinary(1))
    out = kernel_of(rod_in_fluid)(**{n: v[-1:] for n, v in rows.items()})
    assert out.exact[0]
    # E5.14: beta_crit = (m/l) sqrt(6 g/l) (mpmath: 16.080229454111499089 N s/m^2)
    assert abs(out.values["beta_crit"][0] - 16.080229454111499089) < 4e-15
    assert list(out.values) == ["omega", "f", "T", "xi", "zeta", "beta_crit", "omega_d", "f_d",
                                "T_d"]
    assert counts["missed"] <= 0.1 * counts["clean"]


@pytest.mark.parametrize("method, rtol", [("auto", 1e-9), ("exact", 1e-9), ("auto", 1e-3)])
def test_frame_brace_damper_columns(method, rtol):
    rng = np.random.default_rng(23)
    m, k = _mix(rng, (1, 4)), _mix(rng, (3, 6))
    d, b0 = _mix(rng, (0, 5)), _mix(rng, (-1, 1))
    d[:10] = 0.0
    d[10:40] = 2.0 * np.sqrt(2.0 * k[10:40] * m[10:40]) * 10.0 ** rng.uniform(-6, -1, 30)
    rows = {"m": np.append(m, 500.0), "k": np.append(k, 200e3), "d": np.append(d, 2e3),
            "b0": np.append(b0, 1.0)}
    counts = check_kernel(frame_brace_damper, rows,
                          {"m": "kg", "k": "N/m", "d": "N*s/m", "b0": "m/s^2"},
                          {"method": method, "rtol": rtol}, ordinary=_ordinary(1))
    out = kernel_of(frame_brace_damper)(**{n: v[-1:] for n, v in rows.items()},
                                        method=method, rtol=rtol)
    assert out.exact[0] and out.method == "exact"
    # E5.21: y_max = y0 / (2 zeta sqrt(1 - zeta^2)), mpmath 0.035444060250416795038 m
    assert abs(out.values["y_max"][0] - 0.035444060250416795038) < 1e-17
    assert counts["missed"] <= 0.1 * counts["clean"]


def test_frame_brace_damper_small_damping_is_not_vectorised():
    ones = np.ones(3)
    assert kernel_of(frame_brace_damper)(ones, ones, ones, ones, method="small-damping") is None


def test_small_damping_error_twin():
    rng = np.random.default_rng(24)
    zeta = np.concatenate([rng.uniform(0, 2, 2000), log_uniform(rng, -300, 300, 2000),
                           [0.0, math.sqrt(0.5), np.nextafter(math.sqrt(0.5), 0), 1.0]])
    mine = _small_damping_error_array(zeta)
    theirs = np.array([small_damping_error(z) for z in zeta.tolist()])
    assert np.array_equal(mine.view(np.int64), theirs.view(np.int64))
