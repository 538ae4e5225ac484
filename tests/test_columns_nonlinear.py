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


def test_half_cylinder_shell_amplitude_and_quadrature_are_not_vectorised():
    kernel, ones = kernel_of(half_cylinder_shell), np.ones(2)
    assert kernel(ones, ones, amplitude=0.5 * ones) is None
    assert kernel(ones, ones, method="quadrature") is None


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
