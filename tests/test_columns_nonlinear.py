"""Column kernels of dyncalc/physics/nonlinear.py against the one-off functions, bit for bit
(see tests/kernel_rows.py): the half-cylinder shell's small swings and the rod on a torsion
spring, whose equilibrium comes from a root find replicated iterate for iterate.
"""
import math

import numpy as np
import pytest

from dyncalc.physics.columns import kernel_of
from dyncalc.physics.nonlinear import (WOUND_THRESHOLD, _rod_equilibrium,
                                       _rod_equilibrium_array, half_cylinder_shell,
                                       rod_torsion_spring)
from kernel_rows import check_kernel, log_uniform, mixed, ordinary_rows

N = 600


def _mix(rng, ordinary, n=N):
    return mixed(rng, ordinary, n)


def _ordinary(extra=0):
    return ordinary_rows(N, extra)


@pytest.mark.parametrize("method", ["auto", "linear"])
def test_half_cylinder_shell_columns(method):
    rng = np.random.default_rng(31)
    rows = {"r": np.append(_mix(rng, (-2, 2)), 0.5), "g": np.append(_mix(rng, (0, 1.5)),
                                                                     9.80665)}
    check_kernel(half_cylinder_shell, rows, {"r": "m", "g": "m/s^2"}, {"method": method},
                 ordinary=_ordinary(1))
    out = kernel_of(half_cylinder_shell)(rows["r"][-1:], rows["g"][-1:], method=method)
    # E4.18 with our numbers: sqrt(g / ((pi - 2) r)), mpmath 4.14495436047052202 rad/s
    assert out.exact[0] and abs(out.values["omega"][0] - 4.14495436047052202) < 1e-15


def test_half_cylinder_shell_amplitude_rows_are_the_quadrature_others_are_not_vectorised():
    """With an amplitude (as typed) the quadrature rows are the kernel's
    (tests/test_shell_columns.py holds them to the one-off's bits); ``ode``, and
    ``quadrature`` without an amplitude (the one-off refuses it), are not vectorised."""
    from dyncalc.physics.columns import TypedColumn

    kernel, ones = kernel_of(half_cylinder_shell), np.ones(2)
    amplitude = TypedColumn(0.5 * ones, 0.5 * ones, np.array(["radian"] * 2))
    out = kernel(ones, 9.80665 * ones, amplitude=amplitude)
    assert out.method == "quadrature" and out.exact.all()
    # T/T0 at 0.5 rad from the energy integral (mpmath.quad at 30 digits)
    assert out.values["omega_0"][0] / out.values["omega"][0] == pytest.approx(
        float(_shell_factor(0.5)), rel=1e-14)
    assert kernel(ones, ones, amplitude=amplitude, method="ode") is None
    assert kernel(ones, ones, method="quadrature") is None


def _shell_factor(phi0: float):
    """T/T0 of the shell at ``phi0`` by mpmath: (2/pi) int_0^{pi/2} sqrt((1 + c k^2 sin^2 u) /
    (1 - k^2 sin^2 u)) du, c = 4/(pi - 2), k = sin(phi0/2)."""
    import mpmath

    with mpmath.workdps(30):
        c = 4 / (mpmath.pi - 2)
        k2 = mpmath.sin(mpmath.mpf(phi0) / 2) ** 2
        return 2 / mpmath.pi * mpmath.quad(
            lambda u: mpmath.sqrt((1 + c * k2 * mpmath.sin(u) ** 2)
                                  / (1 - k2 * mpmath.sin(u) ** 2)), [0, mpmath.pi / 2])


def test_rod_equilibrium_twin():
    rng = np.random.default_rng(32)
    kappa = np.concatenate([log_uniform(rng, -300, 300, 3000), log_uniform(rng, -2, 2, 3000),
                            [WOUND_THRESHOLD, 3e-17, 4e-17, 1.0, 1e18]])
    mine = _rod_equilibrium_array(kappa)
    theirs = np.array([_rod_equilibrium(k) for k in kappa.tolist()])
    assert np.array_equal(mine.view(np.int64), theirs.view(np.int64))
    # and it is the root: cos(phi) = kappa phi to a few ulp (independent check)
    ordinary = (kappa > 1e-3) & (kappa < 1e3)
    phi = mine[ordinary]
    assert np.all(np.abs(np.cos(phi) - kappa[ordinary] * phi) < 1e-14 * (1 + kappa[ordinary]))


def test_rod_torsion_spring_columns():
    rng = np.random.default_rng(33)
    m, l = _mix(rng, (-1, 2)), _mix(rng, (-2, 1))
    kt, g = _mix(rng, (-1, 3)), _mix(rng, (0, 1.5))
    rows = {"m": np.append(m, 2.0), "l": np.append(l, 1.0), "kt": np.append(kt, 30.0),
            "g": np.append(g, 9.81)}
    counts = check_kernel(rod_torsion_spring, rows,
                          {"m": "kg", "l": "m", "kt": "N*m/rad", "g": "m/s^2"},
                          ordinary=_ordinary(1))
    out = kernel_of(rod_torsion_spring)(**{n: v[-1:] for n, v in rows.items()})
    # E5.20 with our numbers (mpmath): phi_0 = 31.83472856122 deg, omega = 4.491602048489267
    assert out.exact[0] and out.method == "root-find"
    assert abs(math.degrees(out.values["phi_0"][0]) - 31.83472856122) < 1e-10
    assert abs(out.values["omega"][0] - 4.491602048489267) < 4e-15
    assert counts["missed"] == 0
