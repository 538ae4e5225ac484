"""Velocities and accelerations of a point moving in a moving, rotating frame.

.. math:: \\mathbf v_t = \\mathbf v_0 + \\boldsymbol\\Omega\\times\\mathbf r, \\qquad
          \\mathbf v = \\mathbf v_t + \\mathbf v_r

.. math:: \\mathbf a_t = \\mathbf a_0 + \\boldsymbol\\alpha\\times\\mathbf r
          + \\boldsymbol\\Omega\\times(\\boldsymbol\\Omega\\times\\mathbf r), \\qquad
          \\mathbf a = \\mathbf a_t + 2\\,\\boldsymbol\\Omega\\times\\mathbf v_r + \\mathbf a_r

:func:`relative_motion` is the one entry point for every vector path of ``coriolis``: the
vectors typed as components (``--r``, ``--v0``, ...) and the motion given in time (which
differentiates ``r(t)``, ``Omega(t)``, ``R0(t)`` and calls it with the values at ``--t``).
The accelerations come from :func:`~dyncalc.physics.frames.relative_acceleration` (the
power-of-two scaled cross products). The velocities are summed without cancellation: each
component of ``v0 + Omega x r`` (and of ``v``) is the correctly rounded value of the exact sum
of ``v0``, ``v_r`` and the two products of the cross product, each product split exactly
into two floats (Dekker) on the scaled mantissas, the whole added by ``math.fsum``; so
``v0 = -1e12 m/s`` against ``Omega x r = 1e12 m/s + 1 mm/s`` gives the 1 mm/s exactly.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapter 6 (relative motion), eqs. (6.9) and (6.15).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..errors import PhysicsError
from ..lazy import numpy as np
from .columns import Columns, column_kernel
from . import frames
from .frames import FrameAcceleration, _Scaled, _ScaledRows, _exponents, _si_vector, magnitude
from .numerics import two_product

__all__ = ["relative_motion", "RelativeMotion", "transport_velocity"]

_PAIRS = ((1, 2), (2, 0), (0, 1))  # component i of a x b is a[j] b[k] - a[k] b[j]


def _scaled_sum(Om: _Scaled, rr: _Scaled, addends) -> np.ndarray | None:
    """``sum(addends) + Omega x r`` correctly rounded per component, or ``None`` when an
    addend is not exactly representable at the scale of the cross product (then it and the
    cross product differ by some 1e300 and a plain sum is exact enough)."""
    shift = Om.e + rr.e
    scaled = []
    for x in addends:
        with np.errstate(over="ignore", under="ignore"):
            y = np.ldexp(x, -shift) if shift else x
            if not np.array_equal(np.ldexp(y, shift), x):
                return None
        scaled.append(y)
    a, b = Om.m, rr.m
    out = np.empty(3)
    for i, (j, k) in enumerate(_PAIRS):
        p1, e1 = two_product(float(a[j]), float(b[k]))
        p2, e2 = two_product(float(a[k]), float(b[j]))
        out[i] = math.fsum([p1, e1, -p2, -e2, *(float(y[i]) for y in scaled)])
    with np.errstate(over="ignore", under="ignore"):
        return np.ldexp(out, shift) + 0.0


def transport_velocity(Omega, r, v0=None, v_r=None) -> np.ndarray:
    """``v0 + Omega x r (+ v_r)`` in m/s, each component the correctly rounded exact sum.

    Parameters
    ----------
    Omega : array
        Angular velocity of the frame, rad/s (3 components).
    r : array
        Position in the frame, m.
    v0, v_r : array, optional
        Velocity of the frame's origin and velocity relative to the frame, m/s (default 0).

    Examples
    --------
    Large opposing terms keep their small difference (``1e6 * 2^-30 m/s``):

    >>> transport_velocity([0, 0, 1e6], [1e6 + 2**-30, 0, 0], v0=[0, -1e12, 0]).tolist()
    [0.0, 0.0009313225746154785, 0.0]
    """
    Om_v = _si_vector(Omega, "rad/s", "Omega")
    r_v = _si_vector(r, "m", "r")
    addends = [np.asarray(x, dtype=float) + 0.0 for x in (v0, v_r) if x is not None]
    finite = all(np.all(np.isfinite(x)) for x in (Om_v, r_v, *addends))
    if not finite:
        raise PhysicsError("v: a non-finite input (inf or nan) in v0 + Omega x r")
    Om, rr = _Scaled.of(Om_v), _Scaled.of(r_v)
    value = _scaled_sum(Om, rr, addends)
    if value is None:
        with np.errstate(over="ignore", invalid="ignore"):
            value = Om.cross(rr).value()
            for x in addends:
                value = value + x
            value = value + 0.0
    if not np.all(np.isfinite(value)):
        raise PhysicsError("v overflows float64 at these inputs (a component beyond 1.8e308 "
                           "m/s)")
    return value


@dataclass
class RelativeMotion:
    """Every velocity and acceleration of a point moving in a moving, rotating frame, SI
    numpy arrays (m/s, m/s^2; ``F_c`` in N) and their magnitudes (``mags``: name -> float).

    ``v``, ``a_c``, ``a`` and ``F_c`` are ``None`` without ``v_r`` (the point's motion in the
    frame is then not known); ``accel`` holds every term as
    :class:`~dyncalc.physics.frames.FrameAcceleration` (``v_r = 0`` where none was given).
    """

    v_transport: np.ndarray
    v: np.ndarray | None
    a_transport: np.ndarray
    a_c: np.ndarray | None
    a: np.ndarray | None
    F_c: np.ndarray | None
    accel: FrameAcceleration
    mags: dict[str, float] = field(default_factory=dict)
    warnings: list[str] = field(default_factory=list)


def relative_motion(Omega, r=None, v_r=None, v0=None, alpha=None, a0=None, a_r=None,
                    m=None) -> RelativeMotion:
    """Velocities and accelerations of a point at ``r`` in a frame turning with ``Omega``.

    The vector path of ``coriolis`` calls this with the vectors as typed; the path of motion
    given in time calls it with ``r``, ``v_r = r'``, ``a_r = r''``, ``Omega``,
    ``alpha = Omega'``, ``v0 = R0'``, ``a0 = R0''`` evaluated at ``--t``. Do not rename it.

    .. math:: \\mathbf v_t = \\mathbf v_0 + \\boldsymbol\\Omega\\times\\mathbf r,\\quad
              \\mathbf v = \\mathbf v_t + \\mathbf v_r,\\quad
              \\mathbf a_t = \\mathbf a_0 + \\boldsymbol\\alpha\\times\\mathbf r
              + \\boldsymbol\\Omega\\times(\\boldsymbol\\Omega\\times\\mathbf r),\\quad
              \\mathbf a = \\mathbf a_t + 2\\,\\boldsymbol\\Omega\\times\\mathbf v_r
              + \\mathbf a_r

    Parameters
    ----------
    Omega : array
        Angular velocity of the frame ``[angle]/[time]`` (SI: rad/s, 3 components).
    r : array, optional
        Position of the point from the frame's origin ``[length]`` (m; default 0: the point
        is at the origin).
    v_r : array, optional
        Velocity relative to the frame ``[length]/[time]``; without it ``v``, ``a_c``, ``a``
        and ``F_c`` are ``None``.
    v0, a0 : array, optional
        Velocity and acceleration of the frame's origin (m/s, m/s^2; default 0).
    alpha : array, optional
        Angular acceleration of the frame (rad/s^2; default 0).
    a_r : array, optional
        Acceleration relative to the frame (m/s^2; default 0).
    m : float, optional
        Mass (kg): the Coriolis force ``F_c = -m a_c``.

    Returns
    -------
    RelativeMotion
        All vectors in the frame's axes, with ``mags`` (``v_transport_mag``, ``v_mag``,
        ``a_transport_mag``, ``a_c_mag``, ``a_mag``, ``F_c_mag``).

    Examples
    --------
    A point 0.2 m out on a turntable at 30 rpm moving outward at 0.5 m/s:

    >>> out = relative_motion([0, 0, math.pi], [0.2, 0, 0], v_r=[0.5, 0, 0])
    >>> out.v.tolist(), round(out.mags["a_mag"], 6)
    ([0.5, 0.6283185307179586, 0.0], 3.710252)

    Reference: [1], eqs. (6.9) (velocity) and (6.15) (acceleration).
    """
    Om_v = _si_vector(Omega, "rad/s", "Omega")
    r_v = np.zeros(3) if r is None else _si_vector(r, "m", "r")
    v0_v = None if v0 is None else _si_vector(v0, "m/s", "v0")
    vr_v = None if v_r is None else _si_vector(v_r, "m/s", "v_r")
    accel = frames.relative_acceleration(Om_v, np.zeros(3) if vr_v is None else vr_v,
                                  r=None if r is None else r_v,
                                  alpha=alpha, a0=a0, a_r=a_r, m=None if vr_v is None else m)
    v_t = transport_velocity(Om_v, r_v, v0=v0_v)
    v = None if vr_v is None else transport_velocity(Om_v, r_v, v0=v0_v, v_r=vr_v)
    known = vr_v is not None
    out = RelativeMotion(v_transport=v_t, v=v, a_transport=accel.a_transport,
                         a_c=accel.a_c if known else None, a=accel.a if known else None,
                         F_c=accel.F_c if known else None, accel=accel,
                         warnings=list(accel.warnings))
    for name in ("v_transport", "v", "a_transport", "a_c", "a", "F_c"):
        value = getattr(out, name)
        if value is not None:
            out.mags[name + "_mag"] = magnitude(value)
    return out


# --------------------------------------------------------------------------------------------
# Whole columns at once (batch): the same sums, row by row, bit for bit


def _transport_rows(Om: _ScaledRows, rr: _ScaledRows, addends):
    """The twin of :func:`transport_velocity` for ``(n, 3)`` arrays: ``(value, ok)``, ``ok``
    False where the one-off would take its plain-sum branch (a different rounding) or where
    the value is not finite."""
    from .numerics_arrays import fsum_rows, two_product_array

    shift = Om.e + rr.e
    down, up = _exponents(-shift), _exponents(shift)
    ok = np.ones(len(shift), dtype=bool)
    scaled = []
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        for x in addends:
            y = np.ldexp(x, down[:, None])
            ok &= np.all(np.ldexp(y, up[:, None]) == x, axis=1)
            scaled.append(y)
        out = np.empty((len(shift), 3))
        for i, (j, k) in enumerate(_PAIRS):
            p1, e1 = two_product_array(Om.c[j], rr.c[k])
            p2, e2 = two_product_array(Om.c[k], rr.c[j])
            terms = np.stack([p1, e1, -p2, -e2, *(y[:, i] for y in scaled)], axis=1)
            total, fine = fsum_rows(terms)
            ok &= fine
            out[:, i] = np.ldexp(total, up)
        out += 0.0
    ok &= np.all(np.isfinite(out), axis=1)
    return out, ok


@column_kernel(transport_velocity)
def _transport_velocity_columns(Omega, r, v0=None, v_r=None) -> Columns:
    """:func:`transport_velocity` on ``(n, 3)`` SI arrays; ``values["v"]``. Exact where the
    one-off sums exactly (every row unless an addend and the cross product are some 1e300
    apart) and the value is finite."""
    addends = [np.asarray(x, dtype=float) + 0.0 for x in (v0, v_r) if x is not None]
    Omega, r = np.asarray(Omega, dtype=float) + 0.0, np.asarray(r, dtype=float) + 0.0
    value, ok = _transport_rows(_ScaledRows.of(Omega), _ScaledRows.of(r), addends)
    for x in (Omega, r, *addends):
        ok &= np.all(np.isfinite(x), axis=1)
    return Columns({"v": value}, exact=ok, model="vectors")


# --------------------------------------------------------------------------------------------
# Scalar set-ups for inverse problems (dyncalc.scenes.coriolis)


def coriolis_perpendicular(omega, vr, mass=None):
    """Magnitudes of the Coriolis term for a velocity perpendicular to the rotation axis.

    .. math:: a_c = 2\\,\\Omega\\,v_r, \\qquad F_c = m\\,a_c

    Parameters
    ----------
    omega : Quantity or float
        Angular velocity of the frame ``[angle]/[time]`` (SI: rad/s).
    vr : Quantity or float
        Speed relative to the frame ``[length]/[time]`` (m/s), perpendicular to the axis.
    mass : Quantity or float, optional
        Mass ``[mass]`` (kg): adds ``F_c``.

    Returns
    -------
    Outcome with ``a_c`` (m/s^2) and, with a mass, ``F_c`` (N).

    Examples
    --------
    >>> coriolis_perpendicular(2.0, 3.0).values["a_c"].magnitude
    12.0

    Reference: [1], eq. (6.15), the Coriolis term.
    """
    from ..units import Q_
    from .face import magnitude as value_in
    from .outcome import Outcome

    a_c = _finite_term("a_c", 2.0 * value_in(omega, "rad/s") * value_in(vr, "m/s"))
    values = {"a_c": Q_(a_c, "m/s^2")}
    if mass is not None:
        values["F_c"] = Q_(_finite_term("F_c", value_in(mass, "kg") * a_c), "N")
    return Outcome(values, model="magnitudes (perpendicular vectors)")


def coriolis_earth(latitude, vr, heading=0.0, omega=None, mass=None):
    """The Coriolis term of horizontal motion over the rotating Earth, by magnitude.

    .. math:: \\mathbf a_c = 2\\,\\boldsymbol\\Omega\\times\\mathbf v_r,\\quad
              \\boldsymbol\\Omega = \\Omega_E(0, \\cos\\varphi, \\sin\\varphi),\\quad
              \\mathbf v_r = v(\\sin\\psi, \\cos\\psi, 0)

    so ``|a_c| = 2 Omega_E v sqrt(sin^2 phi + cos^2 phi sin^2 psi)`` and the horizontal part
    ``|a_c,h| = 2 Omega_E v |sin phi|`` whatever the heading.

    Parameters
    ----------
    latitude : Quantity or float
        Latitude ``[angle]`` (a float: radians), positive north.
    vr : Quantity or float
        Horizontal speed over the ground ``[length]/[time]`` (m/s).
    heading : Quantity or float, optional
        Compass heading ``[angle]`` (0 north, 90 deg east); default north, where
        ``|a_c| = 2 Omega_E v sin(phi)``, the textbook's ``f v``.
    omega : Quantity or float, optional
        The Earth's rotation rate ``[angle]/[time]`` (default the sidereal 7.2921159e-5 rad/s).
    mass : Quantity or float, optional
        Mass ``[mass]``: adds ``F_c_mag`` and ``F_c_horizontal_mag``.

    Returns
    -------
    Outcome with ``a_c_mag``, ``a_c_horizontal_mag`` (m/s^2) and with a mass ``F_c_mag``,
    ``F_c_horizontal_mag`` (N).

    Examples
    --------
    >>> out = coriolis_earth(math.radians(90), 10.0)
    >>> out.values["a_c_mag"].magnitude
    0.00145842318

    Reference: [1], Chapter 6 (relative motion), the rotating Earth.
    """
    from ..units import Q_
    from .frames import EARTH_RATE, coriolis_acceleration, earth_angular_velocity, enu_velocity
    from .face import magnitude as value_in
    from .outcome import Outcome

    Omega = earth_angular_velocity(latitude, EARTH_RATE if omega is None else omega)
    a_c = coriolis_acceleration(Omega, enu_velocity(vr, heading))
    flat = np.array([a_c[0], a_c[1], 0.0]) + 0.0
    values = {"a_c_mag": Q_(_finite_term("a_c_mag", magnitude(a_c)), "m/s^2"),
              "a_c_horizontal_mag": Q_(magnitude(flat), "m/s^2")}
    if mass is not None:
        m = value_in(mass, "kg")
        values["F_c_mag"] = Q_(_finite_term("F_c_mag", m * magnitude(a_c)), "N")
        values["F_c_horizontal_mag"] = Q_(_finite_term("F_c_horizontal_mag",
                                                       m * magnitude(flat)), "N")
    return Outcome(values, model="Earth, horizontal motion")


def _finite_term(name: str, value: float) -> float:
    if not math.isfinite(value):
        raise PhysicsError(f"{name} overflows float64 at these inputs")
    return value


@column_kernel(coriolis_perpendicular)
def _coriolis_perpendicular_columns(omega, vr, mass=None):
    """:func:`coriolis_perpendicular` on columns (SI arrays), bit for bit: ``a_c = 2 Omega v_r``
    and ``F_c = m a_c`` in the one-off's order of operations; exact where finite."""
    with np.errstate(over="ignore", invalid="ignore"):
        a_c = 2.0 * np.asarray(omega, dtype=float) * np.asarray(vr, dtype=float)
        values = {"a_c": a_c}
        exact = np.isfinite(a_c)
        if mass is not None:
            values["F_c"] = np.asarray(mass, dtype=float) * a_c
            exact = exact & np.isfinite(values["F_c"])
    return Columns(values, exact=exact, model="magnitudes (perpendicular vectors)")
