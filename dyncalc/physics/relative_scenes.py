"""The relative-motion scenes of ``coriolis --scene`` (../shared/SCENES.md, "Relative-motion
scenes"): a block released in a radial slot of a turning platform (E6.7) and the pin of a drum
sliding in a slotted link (E6.9).

Pure functions on pint quantities returning an :class:`~dyncalc.physics.outcome.Outcome`.
Differences of nearly equal squares are formed as products (``r^2 - a^2 = (r - a)(r + a)``,
``rho`` as a hypot), and ``acosh`` near 1 through ``log1p``.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapter 6.
"""
from __future__ import annotations

import math

from ..errors import PhysicsError
from ..units import ANGLE, ANGULAR_RATE, LENGTH, MASS, Q_, TIME
from .face import check_units, magnitude
from .outcome import Outcome

__all__ = ["radial_slot_release", "slotted_link"]


def _acosh_ratio(r: float, a: float) -> float:
    """``acosh(r/a)`` for ``r >= a > 0``, accurate near 1: ``log1p(u + sqrt(u (u + 2)))``
    with ``u = (r - a)/a``."""
    u = (r - a) / a
    return math.log1p(u + math.sqrt(u * (u + 2.0)))


@check_units(Omega=ANGULAR_RATE, a=LENGTH, r=LENGTH, m=MASS, t=TIME)
def radial_slot_release(Omega, a, r, m=None, t=None) -> Outcome:
    """A block released from rest relative to a platform turning at constant ``Omega``, in a
    frictionless radial slot through the centre (E6.7 of [1]).

    .. math:: x(t) = a\\cosh\\Omega t,\\quad v_r = \\Omega\\sqrt{r^2 - a^2},\\quad
              t_R = \\frac{\\operatorname{acosh}(r/a)}{\\Omega},\\quad
              v_{abs} = \\Omega\\sqrt{2r^2 - a^2},\\quad F_{slot} = 2 m\\Omega v_r

    Parameters
    ----------
    Omega : Quantity
        Rate of the platform ``[angle]/[time]``, positive.
    a : Quantity
        Release radius ``[length]``, ``0 < a < r``.
    r : Quantity
        Radius reached (the rim, say) ``[length]``.
    m : Quantity, optional
        Mass of the block ``[mass]``: gives the side forces ``F_slot`` (and ``F_t``).
    t : Quantity, optional
        A time ``[time]`` with ``0 <= t <= t_R``: gives ``x_t``, ``v_t`` (and ``F_t``).

    Returns
    -------
    Outcome with ``v_r``, ``t_R``, ``v_abs`` (m/s, s, m/s), ``F_slot`` (N, with ``m``) and
    ``x_t``, ``v_t``, ``F_t`` (with ``t``).

    Examples
    --------
    >>> from dyncalc.units import Q_
    >>> out = radial_slot_release(Q_(2, "rad/s"), Q_(3, "m"), Q_(5, "m"))
    >>> out.values["v_r"].magnitude, out.values["v_abs"].magnitude  # 2*4, 2*sqrt(41)
    (8.0, 12.806248474865697)
    """
    W, a_, r_ = magnitude(Omega, "rad/s"), magnitude(a, "m"), magnitude(r, "m")
    if not a_ < r_:
        raise PhysicsError(f"a must be below r (the block is released inside the radius it "
                           f"reaches); got a = {a_:.6g} m, r = {r_:.6g} m")
    product = (r_ - a_) * (r_ + a_)
    if math.isfinite(product) and product >= 2.2250738585072014e-308:
        gap = math.sqrt(product)  # one rounding fewer
    else:  # the product leaves float64: its factors' roots do not
        gap = math.sqrt(r_ - a_) * math.sqrt(r_ + a_)
    v_r = W * gap
    t_R = _acosh_ratio(r_, a_) / W
    values = {"v_r": Q_(v_r, "m/s"), "t_R": Q_(t_R, "s"),
              "v_abs": Q_(W * math.hypot(r_, gap), "m/s")}
    m_ = None if m is None else magnitude(m, "kg")
    if m_ is not None:
        values["F_slot"] = Q_(2.0 * m_ * W * v_r, "N")
    if t is not None:
        t_ = magnitude(t, "s")
        if t_ < 0.0:
            raise PhysicsError(f"t must not be negative (the block is released at t = 0); got "
                               f"t = {t_:.6g} s")
        if t_ > t_R:
            raise PhysicsError(f"t = {t_:.6g} s is after t_R = {t_R:.6g} s, when the block "
                               f"reaches r = {r_:.6g} m: x(t) = a cosh(Omega t) holds only "
                               "inside the slot")
        v_t = a_ * W * math.sinh(W * t_)
        values.update(x_t=Q_(a_ * math.cosh(W * t_), "m"), v_t=Q_(v_t, "m/s"))
        if m_ is not None:
            values["F_t"] = Q_(2.0 * m_ * W * v_t, "N")
    return Outcome(values, model="rigid platform at constant rate", method="closed-form",
                   assumptions=["frictionless slot, constant Omega; the floor carries the "
                                "weight; F_slot is the side push of the slot wall, forward in "
                                "the sense of the rotation"])


@check_units(d=LENGTH, c=LENGTH, theta=ANGLE, omega=ANGULAR_RATE)
def slotted_link(d, c, theta, omega) -> Outcome:
    """The pin C of a drum (centre B, turning at ``omega``) sliding in the slot of a link
    turning about A, ``AB = d``, ``BC = c``, ``theta`` the angle of BC from the direction A to
    B (E6.9 of [1]).

    .. math:: \\rho = \\sqrt{d^2 + c^2 + 2cd\\cos\\theta},\\quad
              \\omega_{AD} = \\frac{\\omega c (c + d\\cos\\theta)}{\\rho^2},\\quad
              v_r = -\\frac{\\omega c d \\sin\\theta}{\\rho},\\quad v_C = c|\\omega|

    Parameters
    ----------
    d : Quantity
        Pivot A to drum centre B ``[length]``.
    c : Quantity
        Pin radius BC ``[length]``.
    theta : Quantity
        Angle of BC from the direction A to B ``[angle]``, counterclockwise.
    omega : Quantity
        Angular velocity of the drum ``[angle]/[time]``, counterclockwise positive.

    Returns
    -------
    Outcome with ``rho`` (m), ``omega_AD`` (rad/s), ``v_r``, ``v_C`` (m/s).

    Examples
    --------
    The book's instant, ``d = 4 l``, ``c = 3 l``, ``theta = 90 deg``, ``omega = -w``
    (l = 1 m, w = 1 rad/s): ``omega_AD = -9/25``, ``v_r = 12/5``:

    >>> from dyncalc.units import Q_
    >>> out = slotted_link(Q_(4, "m"), Q_(3, "m"), Q_(90, "deg"), Q_(-1, "rad/s"))
    >>> [out.values[n].magnitude for n in ("rho", "omega_AD", "v_r", "v_C")]
    [5.0, -0.36, 2.4, 3.0]
    """
    from .frames import _degrees, cos_sin_degrees

    d_, c_, w = magnitude(d, "m"), magnitude(c, "m"), magnitude(omega, "rad/s")
    cos, sin = cos_sin_degrees(_degrees(theta))
    along, across = d_ + c_ * cos, c_ * sin  # AC in the axes of AB
    rho = math.hypot(along, across)
    if rho <= 1e-12 * (d_ + c_):
        raise PhysicsError("rho = AC is zero: the pin C reaches the pivot A (c = d, theta = "
                           "180 deg) and the link's angle is undefined there")
    return Outcome({"rho": Q_(rho, "m"),
                    "omega_AD": Q_(w * c_ * ((c_ + d_ * cos) / rho) / rho, "rad/s"),
                    "v_r": Q_(-w * c_ * d_ * sin / rho, "m/s"),
                    "v_C": Q_(c_ * abs(w), "m/s")},
                   model="rigid links, pin in a straight slot through A", method="closed-form",
                   assumptions=["angles and angular velocities counterclockwise positive; v_r "
                                "positive away from A"])
