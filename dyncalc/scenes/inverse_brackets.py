"""Inverse problems on columns whose root needs a bracket: an angle solved from a result that
is monotone in it (a pendulum's amplitude from its period), row for row the one-off's root.

The one-off (:meth:`dyncalc.scenes.inverse._Problem._bracketed`) samples the scene on its
grid of the angle (every 2 degrees, a tail toward 180), refines every interval where
``y - goal`` changes sign with 7 points, and refines each sign change between neighbouring
samples to full precision with Brent's method
(:func:`~dyncalc.physics.brent_arrays.brent_roots`, ``xtol = 1e-300``, four machine epsilons
relative, 200 iterations). Here the same grid, the same refinement points
(``x + (x' - x) j / 8``) and the same Brent iteration run on arrays through the scene's column
kernel (exact, by the kernel's own contract, on the rows it marks): the bracket is the
one-off's, and since :func:`brent_roots` treats each row on its own, so is every root, bit for
bit (tests/test_batch_inverse_brackets.py).

A row is taken only where the one-off provably finds that one bracket and no other root: the
kernel exact at every sample from the second grid point on, finite up to a last sample and
refused after it, ``y`` strictly monotone over those samples and over the refinement, the
sign change strictly inside them (not in the first interval, whose left end the one-off
computes on the small-angle model, nor next to where the scene stops answering), no sample
exactly at the goal, and Brent converged with every evaluation exact. Every other row is left
to the one-off's search.
"""
from __future__ import annotations

from types import SimpleNamespace

from ..lazy import numpy as np
from ..physics.brent_arrays import RTOL_MIN, brent_roots
from ..physics.columns import TypedColumn, text_column
from ..units import ANGLE
from .inverse_columns import ClosedForm

__all__ = ["bracketed_columns", "FINE_POINTS"]

#: Points the one-off adds inside an interval with a sign change (FINE_ANGLE - 1).
FINE_POINTS = 7
#: Rows sampled on the whole grid at a time (about 100 samples each: flat memory).
SLICE = 256


def _grid(unknown) -> list[float]:
    """The one-off's coarse grid of the unknown (radians)."""
    from .inverse import _Problem

    return _Problem.grid(SimpleNamespace(param=unknown))


def bracketed_columns(scene, kernel, unknown, target: str, arguments: dict, goal,
                      settings: dict) -> ClosedForm | None:
    """Solve ``target = goal`` for the angle ``unknown`` row by row (see the module). The
    arguments are those of :func:`~dyncalc.scenes.inverse_columns.closed_form_columns`;
    ``None`` where no row can be solved here (not an angle, a method other than ``auto``, a
    kernel that does not take the angle as typed)."""
    from .inverse import FINE_ANGLE

    if unknown.dim is not ANGLE or settings.get("method", "auto") != "auto" \
            or unknown.name not in getattr(kernel, "typed_params", ()):
        return None
    goal = np.asarray(goal, dtype=float)
    n = len(goal)

    def y(x, rows):
        """``(y at x, exact)`` for the rows ``rows`` (index array), x per row (radians)."""
        args = {k: (v[rows] if isinstance(v, np.ndarray) else v) for k, v in arguments.items()}
        args[unknown.name] = TypedColumn(x, x, np.full(len(rows), "radian"))
        ok = np.ones(len(rows), dtype=bool)
        for constraint in scene.constraints:
            ok &= np.asarray(constraint.holds(args), dtype=bool)
        out = kernel(**args, **settings)
        if out is None or target not in out.values:
            return np.full(len(rows), np.nan), np.zeros(len(rows), dtype=bool), None
        ok &= out.exact
        return np.where(ok, out.values[target], np.nan), ok, out

    xs = np.array(_grid(unknown)[1:])   # the first (0) is on the small-angle model
    every = np.arange(n)
    exact = np.zeros(n, dtype=bool)
    a, b = np.ones(n), np.ones(n)
    with np.errstate(all="ignore"):
        for start in range(0, n, SLICE):  # a slice of rows at a time: flat memory
            part = every[start:start + SLICE]
            exact[part], a[part], b[part] = _bracket(y, xs, part, goal[part], FINE_ANGLE)
        rows = np.flatnonzero(exact)
        a, b = a[rows], b[rows]
        missed = np.zeros(n, dtype=bool)

        def f(x, which):
            at = rows[which]
            value, fine_here, _ = y(x, at)
            missed[at[~fine_here]] = True
            return value - goal[at]

        x = np.ones(n)
        if len(rows):
            found = brent_roots(f, a, b, xtol=1e-300, rtol=RTOL_MIN, maxiter=200)
            exact[rows] &= found.converged & ~found.nan
            x[rows] = np.where(exact[rows], found.x, 1.0)
        exact &= ~missed
        value, fine, out = y(x, every)
        if out is None:
            return None
        exact &= fine & np.isfinite(value)
    return ClosedForm(x, out, exact, text_column(n, ""))


def _bracket(y, xs, part, goal, fine: int):
    """``(exact, a, b)`` of the rows ``part``: whether the one-off's samples give exactly one
    sign change, provably (see the module), and its refined bracket ``[a, b]``."""
    n, m = len(part), len(xs)
    flat, ok, _ = y(np.tile(xs, n), np.repeat(part, m))
    Y = flat.reshape(n, m)
    answered = (ok & np.isfinite(flat)).reshape(n, m)
    last = answered.sum(axis=1) - 1                    # the last sample answered ...
    exact = answered[:, 0] & (last >= 1)
    exact &= (answered == (np.arange(m)[None, :] <= last[:, None])).all(axis=1)  # a prefix
    inside = np.arange(m - 1)[None, :] < last[:, None]
    steps = np.diff(Y, axis=1)
    rising = ((steps > 0) | ~inside).all(axis=1)
    exact &= rising | ((steps < 0) | ~inside).all(axis=1)
    g = Y - goal[:, None]
    exact &= ~((g == 0) & (np.arange(m)[None, :] <= last[:, None])).any(axis=1)
    change = ((g[:, :-1] > 0) != (g[:, 1:] > 0)) & inside
    exact &= change.sum(axis=1) == 1
    i = np.argmax(change, axis=1)
    exact &= i + 1 < last                              # not next to the scene's end
    a, b = np.ones(n), np.ones(n)
    rows = np.flatnonzero(exact)
    if not len(rows):
        return exact, a, b
    lo_x, hi_x = xs[i[rows]], xs[i[rows] + 1]
    # the one-off's refinement of the interval: x + (x' - x) j / fine
    X = np.column_stack([lo_x] + [lo_x + (hi_x - lo_x) * j / fine
                                  for j in range(1, FINE_POINTS + 1)] + [hi_x])
    inner, ok, _ = y(X[:, 1:-1].ravel(), np.repeat(part[rows], FINE_POINTS))
    V = np.column_stack([Y[rows, i[rows]], inner.reshape(len(rows), FINE_POINTS),
                         Y[rows, i[rows] + 1]])
    good = ok.reshape(len(rows), FINE_POINTS).all(axis=1) & np.isfinite(V).all(axis=1)
    step = np.diff(V, axis=1)
    good &= np.where(rising[rows], (step > 0).all(axis=1), (step < 0).all(axis=1))
    G = V - goal[rows, None]
    good &= ~(G == 0).any(axis=1)
    sub = np.argmax((G[:, :-1] > 0) != (G[:, 1:] > 0), axis=1)
    pick = np.arange(len(rows))
    exact[rows] = good
    a[rows], b[rows] = X[pick, sub], X[pick, sub + 1]
    return exact, a, b
