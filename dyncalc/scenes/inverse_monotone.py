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
bracket is found on the grid and then on its refinement, and proven by the kernel's exact
values at the bracket's two ends alone. The step tried first holds a seed, the root of the
linear-fractional map through three of the kernel's values (:func:`_seed`: exact for every
pair here up to rounding), so a row costs two evaluations a stage; a row the seed's step does
not prove is bisected over the steps and proven the same way. No turning
point exists, so no extremum is added; an edge where the scene stops answering (an overflow at
the grid's ends) adds samples only inside its own interval, never inside the bracket. A row is
taken only where the kernel's target is exact at the power-law probes of a positive unknown
(which must show no power law, else the one-off inverts in closed form), at the bracket's ends
and at every Brent iterate, every result is exact at the root, and the result is not flat over
the grid to 1e-12 (the one-off refuses that) with a margin; every other row is left to the
one-off's search. The search asks a kernel that can for the target alone
(:func:`~dyncalc.physics.columns.one_result`).
"""
from __future__ import annotations

import math
from types import SimpleNamespace

from ..lazy import numpy as np
from ..physics.brent_arrays import RTOL_MIN, brent_roots
from ..physics.columns import one_result, text_column
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
#: Where a signed unknown's result is sampled for :func:`_seed` (a positive or nonnegative
#: unknown's seed reads the power-law probes).
SIGNED_PROBES = (-1.0, 0.0, 1.0)
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

    narrow = one_result(kernel, target)

    def y(x, rows, every_result: bool = False):
        """``(y at x, exact, the kernel's Columns)`` of the rows ``rows``; NaN where the
        kernel has no value. The search reads the target alone; the answer,
        ``every_result``, all."""
        args = {k: (v[rows] if isinstance(v, np.ndarray) else v) for k, v in arguments.items()}
        args[unknown.name] = np.asarray(x, dtype=float)
        ok = np.ones(len(rows), dtype=bool)
        for constraint in scene.constraints:
            ok &= np.asarray(constraint.holds(args), dtype=bool)
        out = kernel(**args, **({} if every_result else narrow))
        if out is None or target not in out.values:
            return np.full(len(rows), np.nan), np.zeros(len(rows), dtype=bool), None
        value = np.where(ok, out.values[target], np.nan)
        return value, ok & out.exact & np.isfinite(value), out

    xs = np.array(_grid(unknown))
    every = np.arange(n)
    with np.errstate(all="ignore"):
        exact, probe_x, probe_y = _no_power_law(y, unknown, every, n)
        seed = _seed(probe_x, probe_y, goal)
        rising, exact = _direction(y, xs, every, exact)
        a, b, exact = _coarse(y, xs, every, goal, rising, exact, seed)
        a, b, exact = _fine(y, a, b, every, goal, rising, exact, seed)
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
        value, fine, out = y(x, every, every_result=True)
        if out is None:
            return None
        exact &= fine
    return ClosedForm(x, out, exact, text_column(n, ""))


def _no_power_law(y, unknown, every, n):
    """``(exact, xs, ys)``: the rows where the one-off's power-law probe (a positive or
    nonnegative unknown) surely finds none: the kernel exact at the probes, and a probe not
    positive or the log-slopes (libm's log, as the one-off) apart by more than the tolerance or
    flat; and the three points ``(x, y)`` probed (:data:`SIGNED_PROBES` for a signed unknown,
    which the one-off does not probe), which :func:`_seed` reads."""
    if unknown.constraint not in ("positive", "nonnegative"):
        return np.ones(n, dtype=bool), SIGNED_PROBES, \
            [y(np.full(n, p), every)[0] for p in SIGNED_PROBES]
    probes = [y(np.full(n, p), every) for p in PROBES]
    exact = probes[0][1] & probes[1][1] & probes[2][1]
    ys = [p[0] for p in probes]
    positive = (ys[0] > 0) & (ys[1] > 0) & (ys[2] > 0)
    logs = [elementwise(_log, np.where(positive, v, 1.0)) for v in ys]
    slopes = [(logs[i + 1] - logs[i]) / math.log(PROBES[i + 1] / PROBES[i]) for i in (0, 1)]
    power = positive & ~(np.abs(slopes[0] - slopes[1]) > SLOPE_TOL) \
        & ~(np.abs(slopes[0]) < SLOPE_TOL)
    return exact & ~power, PROBES, ys


def _seed(xs, ys, goal):
    """Where the result reaches ``goal``, read off the linear-fractional map
    ``y = (p x + q)/(r x + s)`` through the three points ``(xs[i], ys[i])`` by the
    invariance of the cross-ratio: ``S = R (x2 - x1)/(x2 - x3)`` with
    ``R = (goal - y1)(y2 - y3) / ((goal - y3)(y2 - y1))``, and ``x = (x1 - S x3)/(1 - S)``.
    Every result in :data:`MONOTONE` is linear or linear-fractional in its unknown, so the
    seed is the root up to rounding; it only chooses the step tried first (NaN where the
    points do not fix one), never the answer.

    >>> round(float(_seed((1e-3, 1.0, 1e3), [6 / (x + 2) for x in (1e-3, 1.0, 1e3)], 1.5)), 12)
    2.0
    """
    x1, x2, x3 = xs
    y1, y2, y3 = ys
    R = (goal - y1) * (y2 - y3) / ((goal - y3) * (y2 - y1))
    S = R * (x2 - x1) / (x2 - x3)
    return (x1 - S * x3) / (1.0 - S)


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


def _coarse(y, xs, every, goal, rising, exact, seed):
    """The coarse interval ``[a, b]`` of the sign change: the grid step holding the seed, or
    else bisected on the kernel's values, proven by its exact values at both ends."""
    def point(j, at):
        return xs[j]

    start = np.searchsorted(xs, np.where(np.isfinite(seed), seed, 0.0), side="right") - 1
    return _locate(y, point, len(xs) - 1, start, every, goal, rising, exact)


def _fine(y, a, b, every, goal, rising, exact, seed):
    """The one-off's refinement of ``[a, b]`` (49 points; geometric where ``a b > 0``, with
    C's ``pow`` as the one-off's ``**``): its step holding the seed, or else bisected, proven
    as the coarse interval."""
    geometric = a * b > 0
    safe_a = np.where(exact, a, 1.0)
    ratio = np.where(geometric & exact, b / safe_a, 1.0)

    def point(j, at):
        e = j / FINE
        a_, b_, geometric_ = a[at], b[at], geometric[at]
        power = elementwise(lambda r, k: r ** k, ratio[at], e)
        return np.where(j == 0, a_, np.where(j == FINE, b_, np.where(
            geometric_, a_ * power, a_ + (b_ - a_) * j / FINE)))

    # the seed's place in the step, read with numpy's log (a guess only: the ends prove it)
    where = np.where(geometric, np.log(np.abs(seed / safe_a)) / np.log(np.abs(ratio)),
                     (seed - a) / np.where(b > a, b - a, 1.0))
    start = np.floor(np.where(np.isfinite(where), where, 0.0) * FINE)
    return _locate(y, point, FINE, start, every, goal, rising, exact)


def _locate(y, point, last, start, every, goal, rising, exact):
    """The step ``[point(j), point(j + 1)]`` (``0 <= j < last``) where ``y - goal`` changes
    sign, proven by the kernel's exact values at its two ends (nonzero, of opposite signs):
    first the step ``start`` (the seed's), then, for the rows it does not prove, bisection
    over the steps. ``point(j, at)`` is the ``j``-th point of the rows ``at`` (positions in
    ``every``). The function being monotone, the proven step is the one-off's either way."""
    n = len(every)
    sense = np.where(rising, 1.0, -1.0)
    j = np.clip(start, 0, last - 1).astype(int)
    here = np.arange(n)
    a, b, proven = _proven(y, point(j, here), point(j + 1, here), every, goal, sense, exact)
    redo = np.flatnonzero(exact & ~proven)
    if len(redo):
        lo, hi = np.zeros(len(redo), dtype=int), np.full(len(redo), last)
        while np.any(hi - lo > 1):
            mid = (lo + hi) // 2
            value, _, _ = y(point(mid, redo), every[redo])
            above = (value - goal[redo]) * sense[redo] > 0
            hi, lo = np.where(above, mid, hi), np.where(above, lo, mid)
        a[redo], b[redo], proven[redo] = _proven(
            y, point(lo, redo), point(hi, redo), every[redo], goal[redo], sense[redo],
            exact[redo])
    return a, b, proven


def _proven(y, a, b, every, goal, sense, exact):
    va, fa, _ = y(a, every)
    vb, fb, _ = y(b, every)
    exact = exact & fa & fb & ((va - goal) * sense < 0) & ((vb - goal) * sense > 0)
    return np.array(a, dtype=float), np.array(b, dtype=float), exact
