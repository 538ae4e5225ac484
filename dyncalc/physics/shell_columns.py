"""The rocking half-cylinder shell at an amplitude, on columns: the twin of
:func:`~dyncalc.physics.nonlinear.half_cylinder_shell`'s ``quadrature`` rows.

.. math:: \\frac{T}{T_0} = \\frac{1}{N} \\sum_{i=0}^{N-1}
          \\sqrt{\\frac{1 + c\\,x_i}{1 - x_i}}, \\qquad x_i = k^2 \\sin^2\\frac{i\\pi}{N},
          \\quad c = \\frac{4}{\\pi - 2}, \\quad k = \\sin\\frac{\\varphi_0}{2}

The one-off's periodic trapezoidal rule, ``N`` doubling from 8 until two means agree to
``rtol / 10`` (at most 1024 nodes), is repeated on a stack of rows: the same nodes (one
``numpy.sin`` of the same grid), the same IEEE operations per node, and each row stops at the
``N`` where the scalar loop stops. The one-off sums the nodes with ``math.fsum`` (the
correctly rounded exact sum); here every node lies in ``[1, 4)`` (``0 <= x <= 1/2`` below 90
degrees), so it is an integer multiple of ``2^-52`` below ``2^54``, and up to 1024 of them sum
exactly in ``uint64`` (below ``2.35 * 2^62``); the one conversion to float64 rounds to
nearest, which is the correctly rounded sum: fsum's float, bit for bit
(tests/test_shell_columns.py).

Rows on the ``linear`` model (tiny amplitudes, the bound meets ``rtol``), rows with a warning
(the quadrature misses ``rtol``), refused rows (90 degrees and beyond) and rows whose amplitude
unit is not one in which half a turn is exact are left to the one-off. The error estimate
differs from row to row: it is returned as an array.

Reference: L. N. Trefethen and J. A. C. Weideman, *The exponentially convergent trapezoidal
rule*, SIAM Review 56 (2014) 385-458.
"""
from __future__ import annotations

import math

from ..lazy import numpy as np
from .columns import Columns, TypedColumn
from .numerics import HALF_TURN, UNIT_ROUNDOFF, finite_nonzero, sqrt_ratio_array
from .numerics_arrays import elementwise
from .outcome import periodic_arrays

__all__ = ["shell_amplitude_columns"]

#: The largest node count (the one-off's cap).
MAX_NODES = 1024
#: Nodes (rows times nodes) evaluated at a time.
NODES_AT_ONCE = 1 << 18


def _k2(phi0: float) -> float:
    """``sin(phi0 / 2)^2`` as the one-off writes it (libm's sine, Python's power)."""
    return math.sin(0.5 * phi0) ** 2


def exact_mean(k2, n: int, c: float):
    """``(the mean of the n nodes of each row, ok)``: ``math.fsum`` of the nodes over ``n``,
    bit for bit; ``ok`` False where a node falls outside ``[1, 4)`` (then the integer sum
    would not be exact).

    >>> m, ok = exact_mean(np.array([0.25]), 8, 4.0 / (math.pi - 2.0))
    >>> ok.tolist(), m.tolist() == [math.fsum(
    ...     np.sqrt((1.0 + 4.0 / (math.pi - 2.0) * 0.25 * np.sin(np.arange(8) * (math.pi / 8))
    ...              ** 2) / (1.0 - 0.25 * np.sin(np.arange(8) * (math.pi / 8)) ** 2)).tolist()) / 8]
    ([True], True)
    """
    s2 = np.sin(np.arange(n) * (math.pi / n)) ** 2   # the one-off's grid, the same call
    mean, ok = np.empty(len(k2)), np.empty(len(k2), dtype=bool)
    step = max(1, NODES_AT_ONCE // n)
    for start in range(0, len(k2), step):            # flat memory however many nodes
        part = slice(start, start + step)
        x = k2[part, None] * s2[None, :]
        nodes = np.sqrt((1.0 + c * x) / (1.0 - x))
        ok[part] = good = ((nodes >= 1.0) & (nodes < 4.0)).all(axis=1)
        nodes = np.where(good[:, None], nodes, 1.0)
        scaled = np.ldexp(nodes, 52).astype(np.uint64)   # exact: integers below 2^54
        total = scaled.sum(axis=1, dtype=np.uint64)      # exact: below 2^64
        mean[part] = np.ldexp(total.astype(np.float64), -52) / n
    return mean, ok


def _quadrature(k2, rtol: float, c: float, floor: float, node_rounding: float):
    """``(T/T0, error estimate, ok)`` of each row: the one-off's doubling loop."""
    rows = len(k2)
    factor, error = np.ones(rows), np.zeros(rows)
    ok = np.ones(rows, dtype=bool)
    previous, good = exact_mean(k2, 8, c)
    ok &= good
    live = np.arange(rows)
    n = 16
    stop = 0.1 * max(rtol, floor)
    while live.size:
        current, good = exact_mean(k2[live], n, c)
        ok[live] &= good
        change = np.abs(current - previous) / current
        done = (change <= stop) | (n >= MAX_NODES)
        finished = live[done]
        factor[finished] = current[done]
        error[finished] = change[done] + node_rounding + UNIT_ROUNDOFF
        live, previous = live[~done], current[~done]
        n *= 2
    return factor, error, ok


def shell_amplitude_columns(r, g, amplitude: TypedColumn, method: str, rtol: float,
                            constants: dict) -> Columns | None:
    """The quadrature rows of the shell at an amplitude: ``r`` (m), ``g`` (m/s^2), the
    amplitude as typed; ``constants`` the one-off's (:mod:`~dyncalc.physics.nonlinear`'s
    ``PI_MINUS_2``, ``QUAD_FLOOR``, ``SHELL_NODE_ROUNDING``, ``SHELL_OUTPUT_ROUNDING``, by
    those names). ``None`` for the methods the kernel does not take (linear, ode)."""
    PI_MINUS_2, QUAD_FLOOR = constants["PI_MINUS_2"], constants["QUAD_FLOOR"]
    SHELL_NODE_ROUNDING = constants["SHELL_NODE_ROUNDING"]
    SHELL_OUTPUT_ROUNDING = constants["SHELL_OUTPUT_ROUNDING"]
    if method not in ("auto", "quadrature"):
        return None
    unit = np.asarray(amplitude.unit)
    radians = np.asarray(amplitude.si, dtype=float)
    own = np.isin(unit, ["radian", *HALF_TURN])      # the one-off's _amplitude_parts
    amount = np.where(own, amplitude.typed, radians)
    limit = np.full(len(radians), 0.5 * math.pi)
    for name, half in HALF_TURN.items():
        limit = np.where(unit == name, 0.5 * half, limit)
    c = 4.0 / PI_MINUS_2
    with np.errstate(all="ignore"):
        exact = (amount < limit) & np.isfinite(radians) & (unit != "")
        k2 = elementwise(_k2, np.where(exact, radians, 0.0))
        if method == "auto":   # the bound (_shell_small_error_bound) meets rtol: linear
            bound = 0.5 * k2 * (0.5 * c + 0.5 / (1.0 - k2)) \
                + 0.375 * c * k2 * k2 / (4.0 * (1.0 - k2))
            exact &= ~(bound <= rtol)
        factor, error, ok = _quadrature(np.where(exact, k2, 0.25), rtol, c, QUAD_FLOOR,
                                        SHELL_NODE_ROUNDING)
        exact &= ok
        error = error + SHELL_OUTPUT_ROUNDING
        exact &= ~(error > rtol)                      # a warning: the one-off's
        omega0 = sqrt_ratio_array(g, PI_MINUS_2 * r)
        values = periodic_arrays(omega0 / factor)
        values["omega_0"] = omega0
        exact &= finite_nonzero(values)
    return Columns(values, exact=exact, model="nonlinear", method="quadrature",
                   error_estimate=error)
