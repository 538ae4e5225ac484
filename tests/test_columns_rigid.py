"""Column kernels of dyncalc.physics.rigid against the one-off functions, row by row: the same
SI values to the bit on every row marked exact (their Wide arithmetic redone on WideArray), no
exact row that the one-off refuses or warns about, and most ordinary rows exact; the textbook
examples of each scene (Gross et al., Engineering Mechanics 3) from the formula in floats."""
from __future__ import annotations

import math

import numpy as np
import pytest

from dyncalc.physics import rigid
from dyncalc.physics.columns import kernel_of
from dyncalc.units import Q_
from kernel_check import check_kernel, log_uniform

N = 800
SEED = 17
G = 9.80665

#: parameter -> (unit, log10 range of its ordinary values)
UNITS = {"k": ("N/m", (0, 5)), "m": ("kg", (-2, 3)), "M": ("kg", (-2, 3)),
         "l": ("m", (-2, 1)), "r": ("m", (-3, 0)), "a": ("m", (-3, 1)), "R": ("m", (-2, 1)),
         "kt": ("N*m/rad", (-1, 4)), "g": ("m/s^2", (0, 1.5))}

#: scene function, its quantity parameters, its textbook row and that row's omega^2 and J_A
CASES = [
    (rigid.rolling_disk_spring, ("k", "m"), dict(k=300.0, m=2.0, kappa=0.5),
     lambda p: p["k"] / (1.5 * p["m"]), None),
    (rigid.drum_block_spring, ("k", "m", "M"), dict(k=2000.0, m=4.0, M=10.0),
     lambda p: 2 * p["k"] / (p["M"] + 2 * p["m"]), None),
    (rigid.pulley_block_spring, ("k", "m", "M"), dict(k=1000.0, m=3.0, M=4.0),
     lambda p: p["k"] / (4 * p["m"] + 1.5 * p["M"]), None),
    (rigid.wheel_on_moving_beam, ("k", "m", "M"), dict(k=500.0, m=5.0, M=20.0, kappa=0.5),
     lambda p: p["k"] / (p["m"] + p["M"] / (1 + p["M"] / (0.5 * p["m"]))), None),
    (rigid.clock_pendulum, ("m", "l", "M", "r", "a", "g"),
     dict(m=0.5, l=1.0, M=2.0, r=0.1, a=0.9, g=G),
     lambda p: (0.5 + 2 * 2.0 * 0.9) * G / (2 * (0.5 / 3 + 2.0 * (0.01 + 2 * 0.81) / 2)),
     0.5 / 3 + 2.0 * (0.01 + 2 * 0.81) / 2),
    (rigid.disk_torsion_offset_mass, ("M", "R", "m", "r", "a", "kt", "g"),
     dict(M=20.0, R=0.3, m=2.0, r=0.05, a=0.2, kt=50.0, g=G),
     lambda p: (50.0 + 2.0 * G * 0.2) / (20.0 * 0.09 / 2 + 2.0 * (0.0025 / 2 + 0.04)),
     20.0 * 0.09 / 2 + 2.0 * (0.0025 / 2 + 0.04)),
    (rigid.angled_member, ("l", "g"), dict(l=0.5, g=G),
     lambda p: math.sqrt(65) / 14 * G / 0.5, None),
]


def _draw(rng, names, n=N):
    """Half the rows over 1e-300..1e300 (sums and products far outside float64), half in the
    parameter's ordinary range."""
    half = n // 2
    return {name: np.concatenate([log_uniform(rng, half, -300, 300),
                                  log_uniform(rng, n - half, *UNITS[name][1])])
            for name in names}


def _one_off(function, columns, plain=()):
    def call(i):
        kwargs = {name: Q_(values[i], UNITS[name][0]) for name, values in columns.items()}
        kwargs.update({name: float(values[i]) for name, values in plain})
        return function(**kwargs)
    return call


@pytest.mark.parametrize("function, names, textbook, omega_squared, inertia", CASES,
                         ids=[case[0].__name__ for case in CASES])
def test_rigid_kernel_is_the_one_off_bit_for_bit(function, names, textbook, omega_squared,
                                                 inertia):
    rng = np.random.default_rng(SEED + len(names))
    columns = _draw(rng, names)
    for name in names:
        columns[name][0] = textbook[name]
    plain = []
    if "kappa" in textbook:
        kappa = np.concatenate([[0.5, -0.1, 0.0, 2 / 3, 1.0], rng.uniform(0.0, 2.0, N - 5)])
        plain = [("kappa", kappa)]
    out = kernel_of(function)(**columns, **dict(plain))
    exact, refused, clean = check_kernel(out, _one_off(function, columns, plain), N)
    assert np.array_equal(exact, clean)     # every row the one-off computes cleanly is exact
    assert exact[0]
    assert math.isclose(out.values["omega"][0] ** 2, omega_squared(textbook), rel_tol=1e-15)
    if inertia is not None:
        assert math.isclose(out.values["J_A"][0], inertia, rel_tol=1e-15)
    if plain:
        assert refused[1] and not exact[1]                # kappa < 0
    assert exact[N // 2:].mean() >= 0.97
    assert exact[:N // 2].mean() >= 0.25                  # Wide: no overflow midway


def test_disk_torsion_kernel_leaves_the_neutral_disk_to_the_one_off():
    """kt = 0 and a = 0: nothing pulls back; the one-off refuses, the kernel is not exact."""
    rng = np.random.default_rng(SEED)
    names = ("M", "R", "m", "r", "a", "kt", "g")
    columns = _draw(rng, names, 40)
    columns["kt"][:20] = 0.0
    columns["a"][:10] = 0.0
    out = kernel_of(rigid.disk_torsion_offset_mass)(**columns)
    exact, refused, clean = check_kernel(out, _one_off(rigid.disk_torsion_offset_mass, columns),
                                         40)
    assert np.array_equal(exact, clean)
    assert refused[:10].all() and not refused[10:].any()
    assert exact[30:].all()


def test_board_on_drums_kernel():
    rng = np.random.default_rng(SEED)
    columns = _draw(rng, ("a", "g"))
    mu = np.concatenate([[0.4, 0.0, -0.2], log_uniform(rng, N - 3, -3, 0)])
    columns["a"][0], columns["g"][0] = 0.8, G
    out = kernel_of(rigid.board_on_drums)(mu, **columns)
    exact, refused, clean = check_kernel(out, _one_off(rigid.board_on_drums, columns,
                                                       [("mu", mu)]), N)
    assert np.array_equal(exact, clean)
    assert exact[0] and refused[1:3].all()
    assert math.isclose(out.values["omega"][0] ** 2, 2 * 0.4 * G / 0.8, rel_tol=1e-15)
    assert exact[N // 2:].mean() >= 0.97
    assert kernel_of(rigid.board_on_drums)(mu, **columns, sense="outward") is None


def test_rolling_in_track_kernel_with_R_in_metres():
    rng = np.random.default_rng(SEED)
    columns = _draw(rng, ("R", "g"))
    r = columns["R"] * rng.uniform(0.0, 1.2, N)      # about one row in six: r > R, refused
    columns["R"][0], r[0], columns["g"][0] = 1.0, 0.2, G
    kappa = np.concatenate([[0.4], rng.uniform(0.0, 1.0, N - 1)])
    kernel = kernel_of(rigid.rolling_in_track)
    out = kernel(columns["R"], r, columns["g"], kappa, R_in_metres=True)
    exact, refused, clean = check_kernel(out, _one_off(rigid.rolling_in_track,
                                                       {**columns, "r": r},
                                                       [("kappa", kappa)]), N)
    assert np.array_equal(exact, clean)
    assert exact[0]
    assert math.isclose(out.values["omega"][0] ** 2, G / (1.4 * 0.8), rel_tol=1e-15)
    assert 0.05 < refused.mean() < 0.3
    assert exact[N // 2:][~refused[N // 2:]].mean() >= 0.97
    assert kernel(columns["R"], r, columns["g"], kappa) is None     # R's unit not known


def test_rolling_in_track_in_millimetres_is_not_the_kernels():
    """Why the kernel needs R in metres: the one-off takes R - r in mm, then converts."""
    rng = np.random.default_rng(SEED)
    R_mm = rng.uniform(100.0, 1000.0, 200)
    r_mm = R_mm * rng.uniform(0.1, 0.9, 200)
    R_si = np.array([Q_(x, "mm").to("m").magnitude for x in R_mm])
    r_si = np.array([Q_(x, "mm").to("m").magnitude for x in r_mm])
    out = kernel_of(rigid.rolling_in_track)(R_si, r_si, np.full(200, G), 0.5, R_in_metres=True)
    one_off = [rigid.rolling_in_track(Q_(a, "mm"), Q_(b, "mm"), Q_(G, "m/s^2"))
               .values["omega"].magnitude for a, b in zip(R_mm, r_mm)]
    assert (out.values["omega"] != np.array(one_off)).any()
