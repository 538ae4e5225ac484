"""Inverse problems on columns whose root needs a bracket on the decade grid: a parameter
(``J_A``, a signed moment ``M0``) solved from a result that is monotone in it, row for row the
one-off's root.

The one-off (:meth:`dyncalc.scenes.inverse._Problem._bracketed`) samples the scene on every
fifth decade of the unknown (both signs and zero for a signed one, zero too for a nonnegative
one), refines the interval where ``y - goal`` changes sign with 49 points
(``x (x'/x)^(j/50)``, or ``x + (x' - x) j / 50`` across zero or on underflow), and refines the
sign change between neighbouring samples by Brent's method
(:func:`~dyncalc.physics.brent_arrays.brent_roots`, ``xtol = 1e-300``, four machine epsilons).

Here the result is monotone in the unknown by construction (:data:`MONOTONE`: an exact
rational rounded once, or float operations each monotone, in a quantity the unknown enters
linearly or as one term of a positive denominator), so two neighbouring samples with
``y - goal`` of opposite signs, both nonzero, fix every other sample's sign: the one-off's
bracket is found by bisecting the grid and then its refinement (a guess from the kernel's
values), and proven by the kernel's exact values at the bracket's two ends alone. No turning
point exists, so no extremum is added; an edge where the scene stops answering (an overflow at
the grid's ends) adds samples only inside its own interval, never inside the bracket. A row is
taken only where the kernel is exact at the power-law probes of a positive unknown (which must
show no power law, else the one-off inverts in closed form), at the bracket's ends, at every
Brent iterate and at the root, and where the result is not flat over the grid to 1e-12 (the
one-off refuses that) with a margin; every other row is left to the one-off's search.
"""
from __future__ import annotations

import math
from types import SimpleNamespace

from ..lazy import numpy as np
from ..physics.brent_arrays import RTOL_MIN, brent_roots
from ..physics.columns import text_column
from ..physics.numerics_arrays import elementwise
from ..units import ANGLE
from .inverse_columns import PROBES, SLOPE_TOL, ClosedForm, _log

__all__ = ["MONOTONE", "monotone_columns", "DETAIL"]

#: (scene, unknown) -> the results monotone in that unknown over its whole domain.
MONOTONE = {
    ("drum-two-blocks", "J_A"): frozenset({"alpha", "a1", "a2", "S1", "S2"}),
    ("two-drums-rope-drive", "M0"): frozenset({"a2", "a1", "alpha", "S1", "S2"}),
    ("two-drums-rope-drive", "J1"): frozenset({"a2", "a1", "alpha", "S1", "S2"}),
    ("two-drums-rope-drive", "J2"): frozenset({"a2", "a1", "alpha", "S1", "S2"}),
    ("angled-bar-on-shaft", "M0"): frozenset({"alpha", "A_eta", "B_eta"}),
    ("beam-spun-up", "M0"): frozenset({"alpha", "omega", "V", "M"}),
}
#: The one-off's ``extra.inverse.detail`` of a bracketed root (``{}``: the unknown).
DETAIL = "a sign change on a grid of {}, refined by Brent's method"
#: Points of the one-off's refinement of an interval (``FINE``).
FINE = 50
#: The flatness test of the one-off (1e-12 relative) with a margin for the kernel's rounding
#: at the grid's ends (values there need not be exact).
FLAT = 2e-12


def _grid(unknown) -> list[float]:
    from .inverse import _Problem

    return _Problem.grid(SimpleNamespace(param=unknown))


def monotone_columns(scene, kernel, unknown, target: str, arguments: dict,
                     goal) -> ClosedForm | None:
    """Solve ``target = goal`` for ``unknown`` row by row as the one-off's bracketed search
    does (see the module); ``None`` where the pair is not in :data:`MONOTONE`. Rows not
    ``exact`` in the answer are the one-off's to solve.

    Example: drum-two-blocks, ``alpha = (m2 r2 - m1 r1) g / (J_A + m1 r1^2 + m2 r2^2) = 3``
    at ``m1 = 20, m2 = 15, r1 = 0.2, r2 = 0.4`` gives ``J_A = 3.33777 kg m^2``
    (tests/test_batch_rigid_brackets.py compares every row with the one-off).
    """
    if target not in MONOTONE.get((scene.name, unknown.name), ()) or unknown.dim is ANGLE:
        return None
    goal = np.asarray(goal, dtype=float)
    n = len(goal)

    def y(x, rows):
        """``(y at x, exact, the kernel's Columns)`` of the rows ``rows``; NaN where the
        kernel has no value."""
        args = {k: (v[rows] if isinstance(v, np.ndarray) else v) for k, v in arguments.items()}
        args[unknown.name] = np.asarray(x, dtype=float)
        ok = np.ones(len(rows), dtype=bool)
        for constraint in scene.constraints:
            ok &= np.asarray(constraint.holds(args), dtype=bool)
        out = kernel(**args)
        if out is None or target not in out.values:
            return np.full(len(rows), np.nan), np.zeros(len(rows), dtype=bool), None
        value = np.where(ok, out.values[target], np.nan)
        return value, ok & out.exact & np.isfinite(value), out

    xs = np.array(_grid(unknown))
    every = np.arange(n)
    with np.errstate(all="ignore"):
        exact = _no_power_law(y, unknown, every, n)
        rising, exact = _direction(y, xs, every, exact)
        a, b, exact = _coarse(y, xs, every, goal, rising, exact)
        a, b, exact = _fine(y, a, b, every, goal, rising, exact)
        rows = np.flatnonzero(exact)
        missed = np.zeros(n, dtype=bool)

        def f(x, which):
            at = rows[which]
            value, fine, _ = y(x, at)
            missed[at[~fine]] = True
            return value - goal[at]

        x = np.ones(n)
        if len(rows):
            found = brent_roots(f, a[rows], b[rows], xtol=1e-300, rtol=RTOL_MIN, maxiter=200)
            exact[rows] &= found.converged & ~found.nan
            x[rows] = np.where(exact[rows], found.x, 1.0)
        exact &= ~missed
        value, fine, out = y(x, every)
        if out is None:
            return None
        exact &= fine
    return ClosedForm(x, out, exact, text_column(n, ""))


def _no_power_law(y, unknown, every, n):
    """Rows where the one-off's power-law probe (a positive or nonnegative unknown) surely
    finds none: the kernel exact at the probes, and a probe not positive or the log-slopes
    (libm's log, as the one-off) apart by more than the tolerance or flat."""
    if unknown.constraint not in ("positive", "nonnegative"):
        return np.ones(n, dtype=bool)
    probes = [y(np.full(n, p), every) for p in PROBES]
    exact = probes[0][1] & probes[1][1] & probes[2][1]
    ys = [p[0] for p in probes]
    positive = (ys[0] > 0) & (ys[1] > 0) & (ys[2] > 0)
    logs = [elementwise(_log, np.where(positive, v, 1.0)) for v in ys]
    slopes = [(logs[i + 1] - logs[i]) / math.log(PROBES[i + 1] / PROBES[i]) for i in (0, 1)]
    power = positive & ~(np.abs(slopes[0] - slopes[1]) > SLOPE_TOL) \
        & ~(np.abs(slopes[0]) < SLOPE_TOL)
    return exact & ~power


def _direction(y, xs, every, exact):
    """``(rising, exact)``: the sense of ``y`` from its values at the first and the last
    finite grid samples (inward from the grid's ends), and the rows whose result is not flat
    over the grid (the one-off's refusal) with a margin."""
    n = len(every)
    ends = []
    for order in (range(len(xs)), range(len(xs) - 1, -1, -1)):
        end = np.full(n, np.nan)
        for i in order:
            open_ = np.flatnonzero(~np.isfinite(end) & exact)
            if not len(open_):
                break
            value, _, _ = y(np.full(len(open_), xs[i]), every[open_])
            end[open_] = value
        ends.append(end)
    first, last = ends
    exact = exact & np.isfinite(first) & np.isfinite(last)
    size = np.maximum(np.abs(first), np.abs(last))
    exact &= np.abs(last - first) > FLAT * size
    return last > first, exact


def _coarse(y, xs, every, goal, rising, exact):
    """The coarse interval ``[a, b]`` of the sign change: bisected on the kernel's values,
    then proven by its exact values at both ends (nonzero and of opposite signs)."""
    n = len(every)
    sense = np.where(rising, 1.0, -1.0)
    lo, hi = np.zeros(n, dtype=int), np.full(n, len(xs) - 1)
    while np.any(hi - lo > 1):
        mid = (lo + hi) // 2
        value, _, _ = y(xs[mid], every)
        above = (value - goal) * sense > 0
        hi, lo = np.where(above, mid, hi), np.where(above, lo, mid)
    return _proven(y, xs[lo], xs[hi], every, goal, sense, exact)


def _proven(y, a, b, every, goal, sense, exact):
    va, fa, _ = y(a, every)
    vb, fb, _ = y(b, every)
    exact = exact & fa & fb & ((va - goal) * sense < 0) & ((vb - goal) * sense > 0)
    return a, b, exact


def _fine(y, a, b, every, goal, rising, exact):
    """The one-off's refinement of ``[a, b]`` (49 points; geometric where ``a b > 0``, with
    C's ``pow`` as the one-off's ``**``), bisected and proven as the coarse interval."""
    n = len(every)
    sense = np.where(rising, 1.0, -1.0)
    geometric = a * b > 0
    safe_a = np.where(exact, a, 1.0)
    ratio = np.where(geometric & exact, b / safe_a, 1.0)

    def point(j):
        e = j / FINE
        power = elementwise(lambda r, k: r ** k, ratio, e)
        return np.where(j == 0, a, np.where(j == FINE, b, np.where(
            geometric, a * power, a + (b - a) * j / FINE)))

    lo, hi = np.zeros(n, dtype=int), np.full(n, FINE)
    while np.any(hi - lo > 1):
        mid = (lo + hi) // 2
        value, _, _ = y(point(mid), every)
        above = (value - goal) * sense > 0
        hi, lo = np.where(above, mid, hi), np.where(above, lo, mid)
    return _proven(y, point(lo), point(hi), every, goal, sense, exact)
