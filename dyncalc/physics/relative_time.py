"""Relative motion given in time: exact derivatives of component expressions (sympy) and the
rotation of the frame, for ``coriolis --t`` (../shared/SPEC.md, "Motion given in time").

The point's position ``r(t)`` and the frame's angular velocity ``Omega(t)`` are components in
the rotating frame, the origin's position ``R0(t)`` in the fixed frame; the frames coincide at
``t = 0``. Then

.. math:: v_r = \\dot r,\\quad a_r = \\ddot r,\\quad \\alpha = \\dot\\Omega,\\quad
          v_0 = \\dot R_0,\\quad a_0 = \\ddot R_0,\\qquad
          \\dot Q = Q\\,[\\Omega]_\\times,\\ Q(0) = I,

where ``Q(t)`` takes rotating-frame components to fixed-frame ones (``alpha``'s components are
the same in both readings of the derivative, since ``Omega x Omega = 0``). For an axis fixed in
the frame (``Omega(t) = w(t) n``, ``n`` constant) ``Q`` is the rotation by
``theta(t) = int_0^t w dt`` about ``n`` (Rodrigues), the integral exact through sympy where it
has a closed form and by adaptive quadrature otherwise; for an axis that turns in time ``Q`` is
integrated numerically (DOP853, rtol 1e-12), and the result says so.

This module and :mod:`dyncalc.physics.symbolic` are the only ones of ``coriolis`` that import
sympy, and only the time path reaches them (tests/test_architecture.py).

Reference: Gross, Hauger, Schröder, Wall, Engineering Mechanics 3, Chapter 6.
"""
from __future__ import annotations

import math

import sympy

from ..errors import InputError, PhysicsError
from ..lazy import numpy as np
from ..units.timevector import TimeVector
from .budget import OverBudget, time_budget
from .symbolic import Symbols, to_sympy, text_of

#: Seconds sympy may spend on the closed-form integral of the frame's rate before the
#: rotation angle falls back to adaptive quadrature (exact to rtol 1e-13 either way).
INTEGRAL_BUDGET = 2.0
#: Evaluations of the frame's rate one numerical integration of ``Q`` may make (DOP853 makes
#: 12 a step; at rtol 1e-12 a turn takes tens of steps, so about a hundred turns; about 1 s).
#: A time that needs more is refused instead of integrated for minutes (t = 1e150 s would run
#: for hours).
RATE_EVALUATIONS = 50_000

__all__ = ["TimeMotion", "FrameState", "motion_in_time"]

#: How the rotation of the frame was found (``TimeMotion.rotation``).
ROTATIONS = ("none", "closed form", "quadrature", "numerical")


#: What evaluating a compiled expression raises where it is not defined.
_UNDEFINED = (ZeroDivisionError, ValueError, OverflowError, TypeError)

class FrameState:
    """Every vector at one time ``t`` (SI, numpy arrays of 3): ``r``, ``v_r``, ``a_r``,
    ``Omega``, ``alpha`` in rotating-frame components; ``R0``, ``v0``, ``a0`` in fixed-frame
    components; ``Q`` the 3x3 rotation taking rotating to fixed components; ``theta`` the angle
    turned (rad; ``None`` when the axis turns in time)."""

    __slots__ = ("t", "r", "v_r", "a_r", "Omega", "alpha", "R0", "v0", "a0", "Q", "theta")

    def __init__(self, **values):
        for name in self.__slots__:
            setattr(self, name, values[name])

    def rotating(self, fixed_vector):
        """A fixed-frame vector in rotating-frame components: ``Q^T v``."""
        return self.Q.T @ np.asarray(fixed_vector, dtype=float)


def _cross_matrix(w) -> "np.ndarray":
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


class TimeMotion:
    """The derived motion: sympy expressions of every vector (parameters substituted) and
    their numeric functions of ``t``. ``rotation`` is one of :data:`ROTATIONS`; ``derived``
    maps a name (``v_r``, ``a_r``, ``alpha``, ``v0``, ``a0``, ``theta``) to the text of its
    components (for the explanation)."""

    def __init__(self, exprs: dict, t: sympy.Symbol, values: dict):
        self.t = t
        self.exprs = {name: [e.subs(values) for e in comps] for name, comps in exprs.items()}
        self._f = {name: [sympy.lambdify([t], e, modules=["math"]) for e in comps]
                   for name, comps in self.exprs.items()}
        self.rotation = "none"
        self.axis = None
        self.theta_expr = None
        self._theta = None
        self.derived = {name: [text_of(e) for e in comps] for name, comps in exprs.items()}

    def vector(self, name: str, t: float):
        """``name`` (``r``, ``v_r``, ``Omega`` ...) at ``t`` seconds, SI."""
        try:
            values = [float(f(t)) for f in self._f[name]]
        except _UNDEFINED as exc:
            raise PhysicsError(f"{name} cannot be evaluated at t = {t:g} s ({exc}): the "
                               "expression is not defined there") from None
        if not all(math.isfinite(v) for v in values):
            raise PhysicsError(f"{name} is not finite at t = {t:g} s")
        return np.array(values) + 0.0

    def vectors_at(self, names, times):
        """``({name: (n, 3) array}, ok)``: the vectors ``names`` at each of ``times`` (SI), bit
        for bit :meth:`vector` at each time (the same compiled expressions, all of them in one
        call a time); ``ok`` is False at a time where :meth:`vector` would refuse (not
        defined or not finite there), whose values are then NaN."""
        key = tuple(names)
        f = self._together.get(key) if hasattr(self, "_together") else None
        if f is None:
            self._together = getattr(self, "_together", {})
            f = self._together[key] = sympy.lambdify(
                [self.t], [e for name in key for e in self.exprs[name]], modules=["math"])
        times = np.asarray(times, dtype=float)
        try:  # every time at once (the same calls, one list); a time that raises: one by one
            out = np.array([f(s) for s in times.tolist()])
            if out.dtype.kind not in "fi" or out.shape != (len(times), 3 * len(key)):
                raise TypeError
        except _UNDEFINED:
            pass
        else:
            out = out.astype(float) + 0.0
            ok = np.isfinite(out).all(axis=1)
            return {name: out[:, 3 * j:3 * j + 3] for j, name in enumerate(key)}, ok
        out = np.full((len(times), 3 * len(key)), np.nan)
        ok = np.zeros(len(times), dtype=bool)
        for i, s in enumerate(times.tolist()):
            try:
                out[i] = [float(v) for v in f(s)]
            except _UNDEFINED:
                continue
            ok[i] = True
        ok &= np.isfinite(out).all(axis=1)
        out += 0.0
        return {name: out[:, 3 * j:3 * j + 3] for j, name in enumerate(key)}, ok

    def rotations_at(self, times):
        """``(Q, theta, ok)`` at each of ``times``: :meth:`rotation_matrix` on a stack, bit for
        bit (the angle and its sine and cosine by the same calls a time, Rodrigues' sums on
        the stack); a frame whose axis turns in time is not taken (``None``)."""
        times = np.asarray(times, dtype=float)
        n = len(times)
        if self.rotation == "none":
            return np.broadcast_to(np.eye(3), (n, 3, 3)), np.zeros(n), np.ones(n, dtype=bool)
        if self.rotation != "closed form":
            return None
        try:  # every time at once (the same calls); a time that raises: one by one below
            angles = [self._theta(s) for s in times.tolist()]
            theta = np.array(angles, dtype=float)
            sin = np.array(list(map(math.sin, angles)), dtype=float)
            cos = np.array(list(map(math.cos, angles)), dtype=float)
            ok = np.ones(n, dtype=bool)
        except _UNDEFINED:
            theta, sin, cos = np.full(n, np.nan), np.full(n, np.nan), np.full(n, np.nan)
            ok = np.zeros(n, dtype=bool)
        for i, s in enumerate(times.tolist() if not ok.all() else ()):
            try:
                value = self._theta(s)
                theta[i], sin[i], cos[i] = value, math.sin(value), math.cos(value)
            except _UNDEFINED:
                continue
            ok[i] = True
        K = _cross_matrix(self.axis)
        Q = np.eye(3) + sin[:, None, None] * K + (1.0 - cos)[:, None, None] * (K @ K)
        return Q, theta, ok & np.isfinite(theta)

    def rotation_matrix(self, t: float):
        """``Q(t)`` (rotating -> fixed components) and the angle turned (``None`` when the axis
        turns in time)."""
        if self.rotation == "none":
            return np.eye(3), 0.0
        if self.rotation in ("closed form", "quadrature"):
            theta = self._theta(t)
            return _rodrigues(self.axis, theta), theta
        return self._integrate(t), None

    def _rate_equation(self, t: float):
        """``Q' = Q [Omega(s)]x`` as ``solve_ivp`` takes it, which raises once it has been
        called :data:`RATE_EVALUATIONS` times (see :func:`_bounded`)."""
        calls = [0]

        def rhs(s, y):
            calls[0] += 1
            if calls[0] > RATE_EVALUATIONS:
                raise _TooManyTurns()
            return (y.reshape(3, 3) @ _cross_matrix(self.vector("Omega", s))).ravel()

        return rhs

    def _integrate(self, t: float):
        from scipy.integrate import solve_ivp

        if t == 0.0:
            return np.eye(3)

        rhs = self._rate_equation(t)
        sol = _bounded(lambda: solve_ivp(rhs, (0.0, t), np.eye(3).ravel(), method="DOP853",
                                         rtol=1e-12, atol=1e-14), t)
        if not sol.success:
            raise PhysicsError(f"the frame's rotation could not be integrated to t = {t:g} s "
                               f"({sol.message})")
        Q = sol.y[:, -1].reshape(3, 3)
        u, _, vt = np.linalg.svd(Q)  # the nearest rotation (removes the drift of the solver)
        return u @ vt

    def state(self, t: float) -> FrameState:
        """Every vector at ``t`` (:class:`FrameState`)."""
        Q, theta = self.rotation_matrix(t)
        return FrameState(t=t, Q=Q, theta=theta,
                          **{name: self.vector(name, t) for name in
                             ("r", "v_r", "a_r", "Omega", "alpha", "R0", "v0", "a0")})

    def positions(self, times) -> "np.ndarray":
        """The point's position in the fixed frame, ``R0 + Q r``, at each of ``times`` (n, 3);
        NaN at a time where an expression is not defined. A numerically integrated rotation is
        integrated once each way from ``t = 0`` through every time asked."""
        times = np.asarray(times, dtype=float)
        out = np.full((len(times), 3), np.nan)
        rotations = self._rotations(times) if self.rotation == "numerical" else None
        for i, s in enumerate(times):
            try:
                Q = rotations[i] if rotations is not None else self.rotation_matrix(s)[0]
                out[i] = self.vector("R0", s) + Q @ self.vector("r", s)
            except PhysicsError:
                continue
        return out

    def _rotations(self, times):
        """``Q`` at each of ``times`` from one integration forward and one backward."""
        from scipy.integrate import solve_ivp

        out = [np.eye(3)] * len(times)
        for side in (times > 0, times < 0):
            chosen = np.flatnonzero(side)
            if not len(chosen):
                continue
            order = chosen[np.argsort(np.abs(times[chosen]))]
            end = float(times[order[-1]])
            rhs = self._rate_equation(end)
            sol = _bounded(lambda: solve_ivp(rhs, (0.0, end), np.eye(3).ravel(),
                                             method="DOP853", rtol=1e-12, atol=1e-14,
                                             t_eval=times[order]), end)
            if not sol.success:
                raise PhysicsError(f"the frame's rotation could not be integrated to t = "
                                   f"{end:g} s ({sol.message})")
            for k, index in enumerate(order):
                u, _, vt = np.linalg.svd(sol.y[:, k].reshape(3, 3))
                out[index] = u @ vt
        return out


class _TooManyTurns(Exception):
    """The rate was evaluated :data:`RATE_EVALUATIONS` times in one integration."""


def _bounded(integrate, t: float):
    """``integrate()`` (a ``solve_ivp`` call whose rate counts its calls), refused with a
    :class:`~dyncalc.errors.PhysicsError` once it would need more than
    :data:`RATE_EVALUATIONS` evaluations of the rate to reach ``t``."""
    try:
        return integrate()
    except _TooManyTurns:
        raise PhysicsError(f"the frame's rotation could not be integrated to t = {t:g} s: "
                           f"the axis turns in time and reaching t needs more than "
                           f"{RATE_EVALUATIONS:,} evaluations of the rate (too many turns); "
                           f"ask for a time nearer 0") from None


def _rodrigues(n, theta: float):
    K = _cross_matrix(n)
    return np.eye(3) + math.sin(theta) * K + (1.0 - math.cos(theta)) * (K @ K)


def _component_exprs(vector: TimeVector | None, symbols: Symbols) -> list:
    if vector is None:
        return [sympy.Integer(0)] * 3
    out = []
    for c in vector.components:
        e = to_sympy(c.node, symbols)
        if c.scale != 1.0:
            e = sympy.Float(c.scale, 17) * e
        out.append(e)
    return out


def _fixed_axis(Omega: list, t: sympy.Symbol):
    """``(n, w)`` when ``Omega(t) = w(t) n`` with a constant unit ``n``, else ``None``;
    ``(None, 0)`` for a frame that never turns."""
    nonzero = [e for e in Omega if not (e.is_zero is True)]
    if not nonzero:
        return None, sympy.Integer(0)
    f = nonzero[0]
    ratios = []
    for e in Omega:
        ratio = sympy.simplify(e / f)
        if ratio.has(t) or not ratio.is_number:
            return None
        ratios.append(float(ratio))
    size = math.sqrt(sum(k * k for k in ratios))
    return np.array(ratios) / size, f * sympy.Float(size, 17)


#: The motions derived so far (:func:`motion_in_time`), by what they are derived from; a
#: batch over times derives once. Bounded: the oldest goes first.
_DERIVED: dict = {}
_DERIVED_MAX = 32


def _node_key(node) -> tuple:
    """What an expression tree is, as a hashable tuple (the numbers by their SI values)."""
    return (node.kind, node.name, node.order, node.value if node.kind == "num" else None,
            tuple(_node_key(a) for a in node.args))


def _vector_key(vector: TimeVector | None):
    if vector is None:
        return None
    return tuple((_node_key(c.node), c.scale) for c in vector.components)


def motion_in_time(r: TimeVector | None, omega: TimeVector | None, R0: TimeVector | None,
                   params: dict[str, float]) -> TimeMotion:
    """Derive the motion: ``v_r = r'``, ``a_r = r''``, ``alpha = Omega'``, ``v0 = R0'``,
    ``a0 = R0''`` exactly, and the rotation of the frame.

    The derivation (sympy, and the numeric functions compiled from it) is done once for the
    same expressions and parameter values and kept (:data:`_DERIVED`): every row of a batch
    over times, and every call of the one-off, evaluates the same compiled functions.

    Parameters
    ----------
    r, omega, R0 : TimeVector or None
        Position in the frame ``[length]``, its angular velocity ``[angle]/[time]`` (rotating
        components), the origin's position ``[length]`` (fixed components); ``None`` is zero.
    params : dict
        Parameter values in SI by name.

    Examples
    --------
    A slider at ``s0 - b t^2/2`` in a slot turning at 2 rad/s (E6.6-like numbers of our own):

    >>> from dyncalc.units.timevector import read_time_vector
    >>> from dyncalc.units.expression import Dimension
    >>> L, T = Dimension({"[length]": 1}), Dimension({"[time]": 1})
    >>> P = {"s0": L, "b": L / T**2}
    >>> r = read_time_vector("s0 - b*t^2/2, 0, 0 m", L, label="--r", params=P,
    ...                      dim_words="a length", unit_hint="m")
    >>> w = read_time_vector("0, 0, 2 rad/s", T**-1, label="--omega", params=P,
    ...                      dim_words="an angular rate", unit_hint="rad/s")
    >>> s = motion_in_time(r, w, None, {"s0": 4.0, "b": 0.5}).state(2.0)
    >>> s.r.tolist(), s.v_r.tolist(), s.a_r.tolist(), round(s.theta, 12)
    ([3.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [-0.5, 0.0, 0.0], 4.0)
    """
    key = (_vector_key(r), _vector_key(omega), _vector_key(R0),
           tuple(sorted((name, float(value)) for name, value in params.items())))
    motion = _DERIVED.get(key)
    if motion is None:
        motion = _derive(r, omega, R0, params)
        if len(_DERIVED) >= _DERIVED_MAX:
            del _DERIVED[next(iter(_DERIVED))]
        _DERIVED[key] = motion
    return motion


def _derive(r: TimeVector | None, omega: TimeVector | None, R0: TimeVector | None,
            params: dict[str, float]) -> TimeMotion:
    """:func:`motion_in_time` without the memory: sympy every time."""
    symbols = Symbols([], params, signed=params)
    t = symbols.t
    values = {symbols.param(name): sympy.Float(value, 17) for name, value in params.items()}
    rr = _component_exprs(r, symbols)
    Om = _component_exprs(omega, symbols)
    R = _component_exprs(R0, symbols)
    try:
        exprs = {"r": rr, "v_r": [sympy.diff(e, t) for e in rr],
                 "Omega": Om, "R0": R, "v0": [sympy.diff(e, t) for e in R]}
        exprs["a_r"] = [sympy.diff(e, t) for e in exprs["v_r"]]
        exprs["alpha"] = [sympy.diff(e, t) for e in Om]
        exprs["a0"] = [sympy.diff(e, t) for e in exprs["v0"]]
    except (TypeError, ValueError) as exc:  # pragma: no cover - the grammar is differentiable
        raise InputError(f"the motion cannot be differentiated: {exc}") from None
    motion = TimeMotion(exprs, t, values)
    axis = _fixed_axis(motion.exprs["Omega"], t)
    if axis is None:
        motion.rotation = "numerical"
        return motion
    n, w = axis
    if n is None:
        return motion
    motion.axis = n
    tau = sympy.Symbol("tau", real=True)
    try:  # sympy may take long over an integral it cannot do: quadrature instead
        with time_budget(INTEGRAL_BUDGET):
            integral = sympy.integrate(w.subs(t, tau), (tau, 0, t))
    except OverBudget:
        integral = None
    theta = None
    if integral is not None and not (integral.has(sympy.Integral)
                                     or integral.has(sympy.Piecewise)):
        try:  # a closed form the math module cannot evaluate (hyper, ...) is not one here
            theta = sympy.lambdify([t], integral, modules=["math"])
            float(theta(0.5))
        except Exception:  # noqa: BLE001 - any failure: fall back to quadrature
            theta = None
    if theta is None:
        from scipy.integrate import quad

        rate = sympy.lambdify([t], w, modules=["math"])
        motion.rotation = "quadrature"
        motion._theta = lambda s: quad(rate, 0.0, s, epsabs=0.0, epsrel=1e-13, limit=200)[0]
    else:
        motion.rotation = "closed form"
        motion.theta_expr = integral
        motion.derived["theta"] = [text_of(sympy.nsimplify(integral, rational=False))]
        motion._theta = lambda s: float(theta(s))
    return motion
