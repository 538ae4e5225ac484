"""Column kernels of dyncalc/physics/rotating.py against the one-off functions, bit for bit.

Rows are drawn log-uniformly over ordinary ranges and over 1e-300..1e300, plus each scene's
textbook set-up and rows at the edges the one-off warns about (the bead's bifurcation, the
car's resonance); see tests/kernel_rows.py for what is compared.
"""
import math

import numpy as np

from dyncalc.physics.columns import kernel_of
from dyncalc.physics.rotating import (bead_on_rotating_ring, pendulum_accelerating_support,
                                      pendulum_on_rotating_disk, quarter_car)
from kernel_rows import check_kernel, mixed, ordinary_rows

N = 600


def _mix(rng, ordinary, n=N):
    return mixed(rng, ordinary, n)


def _ordinary(n=N):
    return ordinary_rows(n)


def test_pendulum_accelerating_support_columns():
    rng = np.random.default_rng(11)
    l = np.append(_mix(rng, (-2, 2)), [1.0, 1.0, 2.0])
    a0 = np.append(_mix(rng, (-2, 2)) * rng.choice([-1.0, 1.0], N), [9.81, 0.0, -3.0])
    g = np.append(_mix(rng, (-1, 2)), [9.81, 9.80665, 9.80665])
    a0[:20] = 0.0                                        # at rest: phi_0 = 0 is no underflow
    ordinary = np.append(_ordinary(), [True] * 3)
    counts = check_kernel(pendulum_accelerating_support, {"l": l, "a0": a0, "g": g},
                          {"l": "m", "a0": "m/s^2", "g": "m/s^2"}, ordinary=ordinary)
    # E6.5: a support accelerating at g tilts the pendulum by 45 degrees
    out = kernel_of(pendulum_accelerating_support)(l[-3:], a0[-3:], g[-3:])
    assert out.values["phi_0"][0] == -math.pi / 4 and out.exact[0]
    assert abs(out.values["omega"][0] ** 2 / 9.81 - math.sqrt(2)) < 4e-16
    assert counts["missed"] <= 0.1 * counts["clean"]


def test_pendulum_on_rotating_disk_columns():
    rng = np.random.default_rng(12)
    r, l = _mix(rng, (-2, 1)), _mix(rng, (-2, 1))
    spin = _mix(rng, (-1, 3)) * rng.choice([-1.0, 1.0], N)
    spin[:5] = 0.0                                     # refused by the one-off
    r, l, spin = np.append(r, 0.4), np.append(l, 0.1), np.append(spin, 3.0)
    check_kernel(pendulum_on_rotating_disk, {"r": r, "l": l, "Omega": spin},
                 {"r": "m", "l": "m", "Omega": "rad/s"}, ordinary=np.append(_ordinary(), True))
    out = kernel_of(pendulum_on_rotating_disk)(r[-1:], l[-1:], spin[-1:])
    assert out.values["omega"][0] == 6.0 and out.exact[0]          # 2 Omega (E6.8)
    assert not kernel_of(pendulum_on_rotating_disk)(r[:5], l[:5], spin[:5]).exact.any()


def test_bead_on_rotating_ring_columns():
    rng = np.random.default_rng(13)
    r = _mix(rng, (-2, 1))
    g = _mix(rng, (0, 1.5))
    spin = _mix(rng, (-1, 2.5)) * rng.choice([-1.0, 1.0], N)
    # both sides of the bifurcation, some within 2 % (warned), some a hair from it
    near = np.sqrt(g[:60] / r[:60]) * (1.0 + rng.choice([-1, 1], 60)
                                       * 10.0 ** rng.uniform(-17, -0.5, 60))
    spin[:60] = near
    spin[60:65] = 0.0                                 # at rest: omega = sqrt(g/r)
    r, spin, g = (np.append(r, [0.2, 0.2]), np.append(spin, [10.0, 4 * math.pi]),
                  np.append(g, [9.81, 9.80665]))
    counts = check_kernel(bead_on_rotating_ring, {"r": r, "Omega": spin, "g": g},
                          {"r": "m", "Omega": "rad/s", "g": "m/s^2"},
                          ordinary=np.append(_ordinary(), [True, True]))
    kernel = kernel_of(bead_on_rotating_ring)
    out = kernel(r[-2:], spin[-2:], g[-2:])
    # E6.11 with our numbers: theta_eq = acos(0.4905), omega = 10 sqrt(1 - 0.4905^2)
    assert out.exact.all()
    assert abs(out.values["theta_eq"][0] - math.acos(0.4905)) < 1e-15
    assert abs(out.values["omega"][0] - 10 * math.sqrt(1 - 0.4905 ** 2)) < 1e-14
    rest = kernel(r[60:65], spin[60:65], g[60:65])
    assert rest.exact.all() and (rest.values["theta_eq"] == 0.0).all()
    assert not kernel(r[:60], spin[:60], g[:60]).exact[
        np.abs(spin[:60] / np.sqrt(g[:60] / r[:60]) - 1.0) < 0.009].any()
    assert counts["missed"] <= 0.15 * counts["clean"]


def test_quarter_car_columns():
    rng = np.random.default_rng(14)
    k, m, L = _mix(rng, (2, 6)), _mix(rng, (1, 3)), _mix(rng, (-1, 2))
    U0, v0 = _mix(rng, (-3, -1)), _mix(rng, (-1, 2))
    with np.errstate(all="ignore"):
        v_crit = L * np.sqrt(k / m) / (2 * math.pi)
    v0[:60] = v_crit[:60] * (1.0 + rng.choice([-1, 1], 60) * 10.0 ** rng.uniform(-16, -2, 60))
    v0[60:65] = 0.0
    rows = {"k": np.append(k, 40e3), "m": np.append(m, 400.0), "L": np.append(L, 10.0),
            "U0": np.append(U0, 0.02), "v0": np.append(v0, 20.0)}
    counts = check_kernel(quarter_car, rows,
                          {"k": "N/m", "m": "kg", "L": "m", "U0": "m", "v0": "m/s"},
                          ordinary=np.append(_ordinary(), True))
    out = kernel_of(quarter_car)(**{name: a[-1:] for name, a in rows.items()})
    assert out.exact[0]
    # E5.23 with our numbers: 0.02 / |1 - (4 pi)^2 / 100|
    assert abs(out.values["x_amp"][0] / (0.02 / abs(1 - (4 * math.pi) ** 2 / 100)) - 1) < 1e-14
    assert counts["missed"] <= 0.15 * counts["clean"]
