"""Column kernels of the rigid-body load scenes of :mod:`dyncalc.physics.kinetics_loads`
(``--batch``).

The one-off's float formulas are evaluated here on whole float64 columns, the same operations
in the same order (``+ - * /`` are correctly rounded in numpy as in Python), so every value is
the one-off's to the bit; the beam's normal force, which the one-off forms exactly and rounds
once, goes through the double-double kernel of :mod:`~dyncalc.physics.kinetics_columns`. A row
is exact where every value is finite and not zero (a zero only where the one-off calls it
exact: the free end of the beam, the axis end of the arm) and its section lies on the bar;
the others are left to the one-off, which gives its message.
"""
from __future__ import annotations

import math

from ..lazy import numpy as np
from .columns import Columns
from .euler_bearing import precessing_shaft
from .kinetics_columns import Exact, in_range, rigid_kernel, rounded
from .numerics_arrays import elementwise
from .kinetics_loads import angled_bar_on_shaft, beam_spun_up, rotating_angled_arm

__all__ = []


def _exact(values: dict, ok, zero_ok=None) -> Columns:
    """Columns of float results, exact where ``ok``, every value finite and non-zero (or
    zero where ``zero_ok`` allows it; ``zero_ok`` maps a name to a boolean array)."""
    exact = np.asarray(ok, dtype=bool)
    for name, value in values.items():
        allowed = zero_ok.get(name, False) if zero_ok else False
        exact = exact & np.isfinite(value) & ((value != 0.0) | allowed)
    return Columns(values, exact=exact)


@rigid_kernel(angled_bar_on_shaft)
def _angled_bar_on_shaft_columns(m, l, M0, omega) -> Columns:
    """:func:`angled_bar_on_shaft` on columns, bit for bit."""
    centripetal = m * l * omega * omega
    values = {"alpha": 9.0 * M0 / (20.0 * m * l * l), "A_xi": 0.0 - 0.75 * centripetal,
              "A_eta": 27.0 * M0 / (80.0 * l), "B_xi": 0.0 - 7.0 * centripetal / 12.0,
              "B_eta": 21.0 * M0 / (80.0 * l)}
    return _exact(values, True)


@rigid_kernel(beam_spun_up)
def _beam_spun_up_columns(m, l, M0, x=None, t=None) -> Columns:
    """:func:`beam_spun_up` on columns: the float formulas bit for bit, ``N`` formed in
    double-double and certified (:func:`~dyncalc.physics.kinetics_columns.rounded`)."""
    ok = np.ones(len(m), dtype=bool)
    alpha = 3.0 * M0 / (m * l * l)
    values = {"alpha": alpha}
    if t is not None:
        ok &= t >= 0.0
        values["omega"] = alpha * t
    zero_ok = {}
    if x is not None:
        ok &= (x >= 0.0) & (x <= l)
        end = x == l
        zero_ok = {"N": end, "V": end, "M": end}
        inner, outer = (l - x) / l, (l + x) / l
        if t is not None:
            L = Exact(l)
            exact = (Exact(M0) * Exact(t)) * (Exact(M0) * Exact(t)) * 4.5 * (L - Exact(x)) \
                * (L + Exact(x)) / (Exact(m) * L * L * L * L * L)
            normal = rounded({"N": exact}, ok & in_range(m, l, M0, x, t), zeros=("N",))
            ok &= normal.exact
            values["N"] = normal.values["N"]
        values["V"] = 1.5 * M0 / l * (inner * outer)
        values["M"] = 0.0 - M0 * (inner * inner) * ((l + l + x) / (l + l))
    return _exact(values, ok, zero_ok)


def _leg_a(mu_W2, a, b, x2):
    return (mu_W2 * (a * b + x2 * (a - 0.5 * x2)), -0.5 * mu_W2 * b * b,
            0.5 * mu_W2 * b * b * (a - x2))


@rigid_kernel(rotating_angled_arm)
def _rotating_angled_arm_columns(m, a, b, Omega, x1=None, x2=None) -> Columns:
    """:func:`rotating_angled_arm` on columns, bit for bit (exactly one of ``x1``, ``x2``)."""
    if (x1 is None) == (x2 is None):
        return Columns({}, exact=np.zeros(len(m), dtype=bool))
    mu_W2 = m / (a + b) * Omega * Omega
    zero_ok = {}
    if x1 is not None:
        ok = (x1 >= 0.0) & (x1 <= b)
        N, V, M = mu_W2 * x1 * (b - 0.5 * x1), mu_W2 * a * x1, 0.5 * mu_W2 * a * x1 * x1
    else:
        ok = (x2 >= 0.0) & (x2 <= a)
        N, V, M = _leg_a(mu_W2, a, b, x2)
        zero_ok = {"M": x2 == a}
    N0, V0, M0 = _leg_a(mu_W2, a, b, 0.0)
    return _exact({"N": N, "V": V, "M": M, "N0": N0, "V0": V0, "M0": M0}, ok, zero_ok)


def _sin_cos(x):
    """libm's ``sin`` and ``cos`` row by row, as the one-off calls them (0 and 1 at zero;
    NaN where ``x`` is not finite, a row the one-off refuses)."""
    if not np.any(x) and not np.signbit(x).any():
        return np.zeros(len(x)), np.ones(len(x))
    finite = np.isfinite(x)
    x = np.where(finite, x, 0.0)
    return (np.where(finite, elementwise(math.sin, x), math.nan),
            np.where(finite, elementwise(math.cos, x), math.nan))


@rigid_kernel(precessing_shaft)
def _precessing_shaft_columns(J1, J3, omega0, Omega, J2=None, alpha0=None, t=None,
                              psi=None) -> Columns:
    """:func:`precessing_shaft` on columns, bit for bit (its ``sin``/``cos`` by libm)."""
    n = len(J1)
    J2 = J3 if J2 is None else J2
    psi = np.zeros(n) if psi is None else psi
    if (alpha0 is None) != (t is None):
        return Columns({}, exact=np.zeros(n, dtype=bool))  # the one-off refuses: t goes with alpha0
    if alpha0 is None:
        ok, rate, accel = np.ones(n, dtype=bool), Omega, np.zeros(n)
    else:
        ok = t >= 0.0
        sin, cos = _sin_cos(Omega * t)
        rate, accel = alpha0 * Omega * cos, 0.0 - alpha0 * Omega * Omega * sin
    d = J2 - J3
    s2, c2 = _sin_cos(2.0 * psi)
    s, c = _sin_cos(psi)
    values = {"M1": 0.0 - d * s2 * rate * rate / 2.0,
              "M2": J1 * omega0 * rate + d * (omega0 * rate * c2 + accel * s2 / 2.0),
              "M3": (J2 * s * s + J3 * c * c) * accel + d * omega0 * rate * s2,
              "alpha_dot": rate, "alpha_ddot": accel}
    uniform = alpha0 is None
    zero_ok = {"M1": J2 == J3, "alpha_ddot": np.full(n, uniform),
               "M3": (J2 == J3) & uniform}
    return _exact(values, ok, zero_ok)
