"""The bearing moment on a spinning shaft whose bearings are swung about a perpendicular axis
(../shared/SCENES.md "precessing-shaft", E3.42 with the book's erratum corrected).

Pure functions on pint quantities or SI floats returning an
:class:`~dyncalc.physics.outcome.Outcome` of SI floats.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Example 3.42.
"""
from __future__ import annotations

import math

from ..errors import InputError
from ..units import ANGLE, ANGULAR_RATE, INERTIA, TIME
from .face import check_units, magnitude
from .outcome import Outcome

__all__ = ["precessing_shaft", "turning_rates", "bearing_moment"]


def turning_rates(Omega: float, alpha0: float | None = None, t: float | None = None):
    """``(a', a'')``, the first two time derivatives of the turning angle ``alpha(t)``: uniform
    turning ``alpha = Omega t`` without ``alpha0`` (``(Omega, 0)``), harmonic turning
    ``alpha = alpha0 sin(Omega t)`` with it (``(alpha0 Omega cos(Omega t),
    -alpha0 Omega^2 sin(Omega t))``, needing ``t``). SI floats.

    >>> turning_rates(2.0)
    (2.0, 0.0)
    >>> turning_rates(2.0, 0.5, 0.0)
    (1.0, 0.0)
    """
    if alpha0 is None:
        if t is not None:
            raise InputError("precessing-shaft: t goes with alpha0 (harmonic turning alpha = "
                             "alpha0 sin(Omega t)); uniform turning (alpha = Omega t, no alpha0) "
                             "is the same at every instant")
        return Omega, 0.0
    if t is None:
        raise InputError("precessing-shaft: harmonic turning (alpha0 given) needs t, the "
                         "instant asked for")
    if not t >= 0.0:
        raise InputError(f"t is the time since the start: t >= 0; got t = {t:g} s")
    phase = Omega * t
    return alpha0 * Omega * math.cos(phase), 0.0 - alpha0 * Omega * Omega * math.sin(phase)


def bearing_moment(J1: float, J2: float, J3: float, omega0: float, rate: float, accel: float,
                   psi: float = 0.0):
    """``(M1, M2, M3)`` in the turning frame (SI floats), with ``a' = rate``, ``a'' = accel``:

    ``M1 = -(J2 - J3) sin(2 psi) a'^2/2``,
    ``M2 = J1 omega0 a' + (J2 - J3) (omega0 a' cos(2 psi) + a'' sin(2 psi)/2)``,
    ``M3 = (J2 sin(psi)^2 + J3 cos(psi)^2) a'' + (J2 - J3) omega0 a' sin(2 psi)``.

    >>> bearing_moment(0.02, 0.5, 0.5, 100.0, 2.0, 0.0)
    (0.0, 4.0, 0.0)
    """
    d = J2 - J3
    s2, c2 = math.sin(2.0 * psi), math.cos(2.0 * psi)
    s, c = math.sin(psi), math.cos(psi)
    M1 = 0.0 - d * s2 * rate * rate / 2.0  # no -0.0 when J2 = J3
    M2 = J1 * omega0 * rate + d * (omega0 * rate * c2 + accel * s2 / 2.0)
    M3 = (J2 * s * s + J3 * c * c) * accel + d * omega0 * rate * s2
    return M1, M2, M3


@check_units(J1=INERTIA, J3=INERTIA, J2=INERTIA, omega0=ANGULAR_RATE, Omega=ANGULAR_RATE,
             alpha0=ANGLE, t=TIME, psi=ANGLE)
def precessing_shaft(J1, J3, omega0, Omega, J2=None, alpha0=None, t=None, psi=0.0) -> Outcome:
    """A shaft spinning at ``omega0`` in bearings that turn about a perpendicular fixed axis by
    ``alpha(t)``: the moment the bearings exert on it (E3.42 of [1], erratum corrected).

    .. math:: M_1 = -\\tfrac12 (J_2 - J_3)\\sin 2\\psi\\,\\alpha'^2,\\quad
              M_2 = J_1\\omega_0\\alpha' + (J_2 - J_3)(\\omega_0\\alpha'\\cos 2\\psi +
              \\tfrac12\\alpha''\\sin 2\\psi),\\quad
              M_3 = (J_2\\sin^2\\psi + J_3\\cos^2\\psi)\\alpha'' +
              (J_2 - J_3)\\omega_0\\alpha'\\sin 2\\psi

    from ``dH/dt`` in the fixed frame. The book prints ``M2 = (J1 - J3) omega0 alpha'``; the
    derived value is ``J1 omega0 alpha'`` for a symmetric shaft (a thin rod gives none).

    Parameters
    ----------
    J1 : Quantity
        Moment of inertia about the shaft axis ``[mass]*[length]^2``.
    J3, J2 : Quantity
        Transverse principal moments (``J2`` defaults to ``J3``) ``[mass]*[length]^2``.
    omega0 : Quantity
        Spin relative to the turning frame ``[angle]/[time]``.
    Omega : Quantity
        Turning rate (uniform) or angular frequency (harmonic) ``[angle]/[time]``.
    alpha0 : Quantity, optional
        Amplitude of harmonic turning ``alpha = alpha0 sin(Omega t)`` ``[angle]``.
    t : Quantity, optional
        The instant, with ``alpha0`` ``[time]``.
    psi : Quantity
        Spin angle at the instant, from ``z`` to the principal axis of ``J3`` ``[angle]``.

    Returns
    -------
    Outcome with ``M1``, ``M2``, ``M3`` (N m) along the shaft, the horizontal transverse axis
    and the fixed axis, and the turning rates ``alpha_dot`` (rad/s), ``alpha_ddot`` (rad/s^2).

    Examples
    --------
    >>> out = precessing_shaft(0.02, 0.5, 100.0, 2.0)
    >>> out.values["M2"]  # the book's form gives -96 N m
    4.0
    """
    J1_, J3_ = magnitude(J1, "kg*m^2"), magnitude(J3, "kg*m^2")
    J2_ = J3_ if J2 is None else magnitude(J2, "kg*m^2")
    w0, W = magnitude(omega0, "rad/s"), magnitude(Omega, "rad/s")
    a0 = None if alpha0 is None else magnitude(alpha0, "rad")
    rate, accel = turning_rates(W, a0, None if t is None else magnitude(t, "s"))
    M1, M2, M3 = bearing_moment(J1_, J2_, J3_, w0, rate, accel, magnitude(psi, "rad"))
    law = "uniform turning alpha = Omega t" if a0 is None else \
        "harmonic turning alpha = alpha0 sin(Omega t)"
    zeros = set() if J2_ != J3_ else {"M1"}          # zero by the physics, not underflow
    if a0 is None:
        zeros.update({"alpha_ddot"} if J2_ != J3_ else {"alpha_ddot", "M3"})
    return Outcome({"M1": M1, "M2": M2, "M3": M3, "alpha_dot": rate, "alpha_ddot": accel},
                   exact_zeros=zeros,
                   assumptions=[law, "constant spin omega0 relative to the turning frame "
                                "(the drive supplies M1)"])
