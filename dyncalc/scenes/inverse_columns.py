"""Inverse problems on columns: the closed-form inversion of :mod:`dyncalc.scenes.inverse`
over whole batch columns, row for row the one-off's numbers.

The one-off (:meth:`dyncalc.scenes.inverse._Problem.roots`) inverts a result that is a power of
the unknown, ``y = C x^a``: it computes the scene at ``x = 1e-3, 1, 1e3``, reads the exponent
off the log-slopes (they must agree to 1e-9, and ``a`` must be a fraction ``p/q`` with
``q <= 4`` within 1e-9), takes ``x = x1 exp((ln y - ln y1) / a)`` and checks
``|y(x) - y| <= 1e-12 |y|``. Here the same steps run on arrays through the scene's column
kernel, with libm's ``log`` and ``exp`` row by row (numpy's may round differently), so every
row marked exact is the one-off's to the bit. Rows the kernel does not mark exact at a probe
or at the root, rows whose result is no power law, and rows whose check fails are left to the
one-off (which then searches for brackets).
"""
from __future__ import annotations

import math
from fractions import Fraction

from ..lazy import numpy as np
from ..physics.columns import one_result, text_column
from ..physics.numerics_arrays import elementwise
from ..records import Record
from ..units import ANGLE

__all__ = ["ClosedForm", "closed_form_columns", "PROBES"]

#: The values of the unknown (SI) at which the one-off reads the exponent off the scene.
PROBES = (1e-3, 1.0, 1e3)
#: The log-slopes must agree, and be a simple fraction, to this.
SLOPE_TOL = 1e-9
#: The check of the root: ``|y(x) - goal| <= CHECK_TOL |goal|``.
CHECK_TOL = 1e-12


class ClosedForm(Record):
    """What :func:`closed_form_columns` gives: the roots ``x``, the kernel's
    :class:`~dyncalc.physics.columns.Columns` at them, the rows that are the one-off's
    (``exact``), and each row's exponent ``a`` as the one-off writes it (``"1/2"``)."""

    __slots__ = ("x", "out", "exact", "exponent")
    __hash__ = None

    def __init__(self, x, out, exact, exponent):
        self.x, self.out, self.exact, self.exponent = x, out, exact, exponent


def _exp(value: float) -> float:
    try:
        return math.exp(value)
    except OverflowError:
        return math.inf


def _log(value: float) -> float:
    return math.log(value) if value > 0 else math.nan


def closed_form_columns(scene, kernel, unknown, target: str, arguments: dict, goal,
                        settings: dict) -> ClosedForm | None:
    """Solve ``target = goal`` for the parameter ``unknown`` row by row in closed form.

    Parameters
    ----------
    scene, kernel
        The scene and the column kernel of its physics function.
    unknown : Param
        The parameter solved for (positive or nonnegative, not an angle).
    target : str
        The result given (``f``, ``omega``, ``T``, ...).
    arguments : dict
        The kernel's other arguments, SI arrays of ``n`` rows (words as the kernel takes them).
    goal : ndarray
        The target's values, SI, finite.
    settings : dict
        The kernel's keyword settings (``method``, ``rtol``).

    Returns ``None`` where no row can be solved here (an angle, a signed unknown, no kernel
    values); rows not ``exact`` are the one-off's to solve.

    Example: ``f = sqrt(k/m)/(2 pi)`` solved for ``k`` at ``f = 5 Hz``, ``m = 2 kg`` gives
    ``k = (2 pi 5)^2 2 = 1973.92 N/m`` (tests/test_batch_inverse.py compares every row with the
    one-off).
    """
    if unknown.dim is ANGLE or unknown.constraint not in ("positive", "nonnegative"):
        return None
    goal = np.asarray(goal, dtype=float)
    n = len(goal)

    narrow = one_result(kernel, target)

    def y(x, every_result: bool = False):
        """The target at ``x`` (the probes read nothing else), every result with
        ``every_result`` (the root)."""
        args = {**arguments, unknown.name: np.broadcast_to(np.asarray(x, dtype=float), (n,))}
        ok = np.ones(n, dtype=bool)
        for constraint in scene.constraints:
            ok &= np.asarray(constraint.holds(args), dtype=bool)
        out = kernel(**args, **settings, **({} if every_result else narrow))
        if out is None or target not in out.values:
            return None
        return np.where(ok & out.exact, out.values[target], np.nan), ok & out.exact, out

    with np.errstate(all="ignore"):
        probes = [y(x) for x in PROBES]
        if any(p is None for p in probes):
            return None
        ys = [p[0] for p in probes]
        exact = probes[0][1] & probes[1][1] & probes[2][1]
        exact &= np.isfinite(ys[0]) & np.isfinite(ys[1]) & np.isfinite(ys[2])
        exact &= (ys[0] > 0) & (ys[1] > 0) & (ys[2] > 0)
        logs = [elementwise(_log, np.where(exact, v, 1.0)) for v in ys]
        slopes = [(logs[i + 1] - logs[i]) / math.log(PROBES[i + 1] / PROBES[i]) for i in (0, 1)]
        exact &= ~(np.abs(slopes[0] - slopes[1]) > SLOPE_TOL) & ~(np.abs(slopes[0]) < SLOPE_TOL)
        a, labels = _simple_fractions(np.where(exact, slopes[0], 1.0))
        exact &= np.isfinite(a) & (goal > 0)
        ratio = (elementwise(_log, np.where(exact, goal, 1.0)) - logs[1]) / np.where(exact, a,
                                                                                  1.0)
        x = PROBES[1] * elementwise(_exp, ratio)
        exact &= np.isfinite(x) & (x > 0)
        # every result where a row is taken (none: drum-two-blocks' J_A, never a power law)
        at_root = y(np.where(exact, x, 1.0), every_result=bool(exact.any()))
        if at_root is None:
            return None
        value, fine, out = at_root
        exact &= fine & np.isfinite(value) & (np.abs(value - goal) <= CHECK_TOL * np.abs(goal))
    return ClosedForm(x, out, exact, labels)


def _simple_fractions(slope):
    """``(a as a float, a as the one-off writes it)`` per row: the fraction ``p/q``, ``q <= 4``,
    within :data:`SLOPE_TOL` of the slope (``Fraction(slope).limit_denominator(4)``: fractions
    with ``q <= 4`` lie at least 1/12 apart, so the one within the tolerance is the nearest);
    ``nan`` and ``""`` where there is none."""
    a = np.full(len(slope), np.nan)
    for q in (4.0, 3.0, 2.0, 1.0):  # the smallest denominator last: it wins
        p = np.rint(slope * q)
        close = np.abs(p / q - slope) <= SLOPE_TOL
        a = np.where(close, p / q, a)
    labels = text_column(len(slope), "")
    for value in set(a[np.isfinite(a)].tolist()):
        fraction = Fraction(value).limit_denominator(4)
        if float(fraction) != value:  # not the float of a simple fraction: the one-off's
            a[a == value] = np.nan
            continue
        labels[a == value] = str(fraction)
    return a, labels
