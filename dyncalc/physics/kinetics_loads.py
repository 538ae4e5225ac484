"""Loads inside and on rotating rigid bodies: bearing forces of an angled bar driven on a shaft,
and the stress resultants ``N``, ``V``, ``M`` of a beam spun up from rest and of an L-shaped
arm turning steadily (../shared/SCENES.md "Rigid-body scenes", E3.41, E3.43, E4.11).

Pure functions on pint quantities or SI floats returning an
:class:`~dyncalc.physics.outcome.Outcome` of SI floats. The stress resultants come from the
distributed d'Alembert loads ``dm (r Omega^2)`` (centrifugal) and ``dm (r alpha)``
(tangential) on the outer part of the bar; the ``*_diagram`` functions give them along the
whole bar (what ``--plot`` draws and ``--batch`` tabulates).

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Examples 3.41, 3.43 and 4.11.
"""
from __future__ import annotations

import math
from fractions import Fraction

from ..errors import InputError
from ..units import ANGULAR_RATE, LENGTH, MASS, TIME, TORQUE
from .face import check_units, magnitude
from .outcome import Outcome

__all__ = ["angled_bar_on_shaft", "beam_spun_up", "beam_loads", "rotating_angled_arm",
           "arm_leg_a", "arm_leg_b"]

_NO_WEIGHT = "weight neglected (as in the book)"


@check_units(m=MASS, l=LENGTH, M0=TORQUE, omega=ANGULAR_RATE)
def angled_bar_on_shaft(m, l, M0, omega=0.0) -> Outcome:
    """A bent bar (legs ``2l`` across and ``l`` along the shaft) driven by ``M0`` on a shaft in
    two bearings ``4l`` apart (E3.41 of [1]).

    .. math:: \\alpha = \\frac{9 M_0}{20 m l^2},\\quad A_\\xi = -\\tfrac34 m l\\omega^2,\\
              A_\\eta = \\frac{27 M_0}{80 l},\\quad B_\\xi = -\\tfrac{7}{12} m l\\omega^2,\\
              B_\\eta = \\frac{21 M_0}{80 l}

    from ``J_zeta = 20 m l^2/9``, ``J_xizeta = -m l^2/3``, ``xi_C = 4l/3``: Newton for the
    centre of mass and Euler's equations about O, ``M_xi = J_xizeta alpha``,
    ``M_eta = J_xizeta omega^2``, with the bearings at ``zeta = +-2l``.

    Parameters
    ----------
    m : Quantity
        Mass of the bent bar ``[mass]``.
    l : Quantity
        Length of the short leg (the bar is ``3l`` long) ``[length]``.
    M0 : Quantity
        Driving moment about the shaft ``[force]*[length]``.
    omega : Quantity
        Angular velocity at the instant, in the sense of ``M0`` ``[angle]/[time]``.

    Returns
    -------
    Outcome with ``alpha`` (rad/s^2) and the bearing forces on the shaft ``A_xi``, ``A_eta``,
    ``B_xi``, ``B_eta`` (N; ``xi`` along the long leg, ``eta`` the direction of motion).

    Examples
    --------
    >>> out = angled_bar_on_shaft(3.0, 0.5, 10.0, 2.0)
    >>> round(out.values["alpha"], 12), out.values["A_xi"], out.values["B_eta"]
    (6.0, -4.5, 5.25)
    """
    m_, l_ = magnitude(m, "kg"), magnitude(l, "m")
    M, w = magnitude(M0, "N*m"), magnitude(omega, "rad/s")
    centripetal = m_ * l_ * w * w
    return Outcome({"alpha": 9.0 * M / (20.0 * m_ * l_ * l_),
                    "A_xi": 0.0 - 0.75 * centripetal, "A_eta": 27.0 * M / (80.0 * l_),
                    "B_xi": 0.0 - 7.0 * centripetal / 12.0, "B_eta": 21.0 * M / (80.0 * l_)},
                   assumptions=[_NO_WEIGHT, "massless shaft; radial bearings (no axial "
                                "force arises)"])


def _position(x: float | None, length: float, name: str, of: str) -> None:
    if x is not None and not 0.0 <= x <= length:
        raise InputError(f"{name} must lie on the bar: 0 <= {name} <= {of}; got {name} = "
                         f"{x:g} m with {of} = {length:g} m")


def beam_loads(m: float, l: float, M0: float, x: float, t: float | None):
    """``(N, V, M)`` at ``x`` (SI floats) of the beam spun up from rest (``N`` is ``None``
    without ``t``):
    ``V = (3 M0/(2 l)) (1 - (x/l)^2)``, ``M = -M0 (1 - x/l)^2 (1 + x/(2 l))``,
    ``N = (9 M0^2 t^2/(2 m l^3)) (1 - (x/l)^2)``.

    >>> beam_loads(1.0, 1.0, 1.0, 0.0, 1.0)
    (4.5, 1.5, -1.0)
    """
    # l - x is exact for x >= l/2 (Sterbenz), so 1 - (x/l)^2 keeps its digits near the end
    inner, outer = (l - x) / l, (l + x) / l
    V = 1.5 * M0 / l * (inner * outer)
    M = 0.0 - M0 * (inner * inner) * ((l + l + x) / (l + l))  # 0, not -0, at the free end
    N = None if t is None else _exact_normal_force(m, l, M0, x, t)
    return N, V, M


def _exact_normal_force(m: float, l: float, M0: float, x: float, t: float) -> float:
    """``9 (M0 t)^2 (l - x)(l + x) / (2 m l^5)`` formed exactly from the float inputs and
    rounded once (nine roundings of the float form reach 4.4 ulp); ``inf`` beyond float64."""
    exact = (Fraction(9, 2) * (Fraction(M0) * Fraction(t)) ** 2 * (Fraction(l) - Fraction(x))
             * (Fraction(l) + Fraction(x)) / (Fraction(m) * Fraction(l) ** 5))
    try:
        return float(exact)
    except OverflowError:
        return math.inf


@check_units(m=MASS, l=LENGTH, M0=TORQUE, x=LENGTH, t=TIME)
def beam_spun_up(m, l, M0, x=None, t=None) -> Outcome:
    """A uniform beam pinned at one end, spun up from rest by a constant moment ``M0`` in a
    horizontal plane: its stress resultants at ``x`` and time ``t`` (E3.43 of [1]).

    .. math:: \\alpha = \\frac{3 M_0}{m l^2},\\ \\omega = \\alpha t,\\quad
              N = \\frac{9 M_0^2 t^2}{2 m l^3}\\Bigl(1 - \\frac{x^2}{l^2}\\Bigr),\\
              V = \\frac{3 M_0}{2 l}\\Bigl(1 - \\frac{x^2}{l^2}\\Bigr),\\
              M = -M_0\\Bigl(1 - \\frac{x}{l}\\Bigr)^2\\Bigl(1 + \\frac{x}{2l}\\Bigr)

    ``N`` (tension positive), ``V`` (in the direction of motion) and ``M`` (positive against
    the rotation) act from the inner part on the outer part; ``dM/dx = V``.

    Parameters
    ----------
    m : Quantity
        Mass of the beam ``[mass]``.
    l : Quantity
        Length ``[length]``.
    M0 : Quantity
        Driving moment about the pin ``[force]*[length]``.
    x : Quantity, optional
        Distance of the section from the pin, ``0 <= x <= l`` ``[length]``.
    t : Quantity, optional
        Time since the start, ``t >= 0`` ``[time]``.

    Returns
    -------
    Outcome with ``alpha`` (rad/s^2), with ``t`` ``omega`` (rad/s), with ``x`` ``V`` (N) and
    ``M`` (N m), with both ``N`` (N).

    Examples
    --------
    >>> out = beam_spun_up(2.0, 1.0, 4.0, 0.5, 1.0)
    >>> out.values["alpha"], out.values["V"], out.values["M"], out.values["N"]
    (6.0, 4.5, -1.25, 27.0)
    """
    m_, l_, M = magnitude(m, "kg"), magnitude(l, "m"), magnitude(M0, "N*m")
    x_ = None if x is None else magnitude(x, "m")
    t_ = None if t is None else magnitude(t, "s")
    _position(x_, l_, "x", "l")
    if t_ is not None and not t_ >= 0.0:
        raise InputError(f"t is the time since the start: t >= 0; got t = {t_:g} s")
    alpha = 3.0 * M / (m_ * l_ * l_)
    values = {"alpha": alpha}
    if t_ is not None:
        values["omega"] = alpha * t_
    if x_ is not None:
        N, V, Mx = beam_loads(m_, l_, M, x_, t_)
        if N is not None:
            values["N"] = N
        values["V"] = V
        values["M"] = Mx
    return Outcome(values, assumptions=[_NO_WEIGHT, "the beam starts from rest at t = 0"],
                   exact_zeros={"N", "V", "M"} if x_ == l_ else set())  # the free end


def arm_leg_b(mu_W2: float, a: float, b: float, x1: float):
    """``(N, V, M)`` on leg ``b`` at ``x1`` from the free end (SI; ``mu_W2 = mu Omega^2``):
    ``N = mu Omega^2 (b x1 - x1^2/2)``, ``V = mu Omega^2 a x1``, ``M = mu Omega^2 a x1^2/2``.

    >>> arm_leg_b(1.0, 2.0, 1.0, 1.0)
    (0.5, 2.0, 1.0)
    """
    return mu_W2 * x1 * (b - 0.5 * x1), mu_W2 * a * x1, 0.5 * mu_W2 * a * x1 * x1


def arm_leg_a(mu_W2: float, a: float, b: float, x2: float):
    """``(N, V, M)`` on leg ``a`` at ``x2`` from the corner (SI; ``mu_W2 = mu Omega^2``):
    ``N = mu Omega^2 (a b + a x2 - x2^2/2)``, ``V = -mu Omega^2 b^2/2``,
    ``M = mu Omega^2 b^2 (a - x2)/2``.

    >>> arm_leg_a(1.0, 2.0, 1.0, 2.0)
    (4.0, -0.5, 0.0)
    """
    return (mu_W2 * (a * b + x2 * (a - 0.5 * x2)), -0.5 * mu_W2 * b * b,
            0.5 * mu_W2 * b * b * (a - x2))


@check_units(m=MASS, a=LENGTH, b=LENGTH, Omega=ANGULAR_RATE, x1=LENGTH, x2=LENGTH)
def rotating_angled_arm(m, a, b, Omega, x1=None, x2=None) -> Outcome:
    """An L-shaped arm (legs ``a`` and ``b``, mass ``m``) turning steadily at ``Omega`` about an
    axis through the free end of leg ``a``: stress resultants at a section and at the corner
    (E4.11 of [1]).

    .. math:: \\mu = \\frac{m}{a + b};\\ \\text{leg } b:\\ N = \\mu\\Omega^2 (b x_1 -
              x_1^2/2),\\ V = \\mu\\Omega^2 a x_1,\\ M = \\mu\\Omega^2 a x_1^2/2;\\
              \\text{leg } a:\\ N = \\mu\\Omega^2 (ab + a x_2 - x_2^2/2),\\
              V = -\\mu\\Omega^2 b^2/2,\\ M = \\mu\\Omega^2 b^2 (a - x_2)/2

    ``x1`` runs from the free end E along leg ``b``, ``x2`` from the corner K along leg ``a``;
    ``N`` is tension, ``V`` points to the inside of the L, ``M`` stretches the inside fibres.

    Parameters
    ----------
    m : Quantity
        Mass of the whole arm ``[mass]``.
    a, b : Quantity
        Leg lengths (``a`` from the axis to the corner) ``[length]``.
    Omega : Quantity
        Angular velocity ``[angle]/[time]``.
    x1, x2 : Quantity
        The section: exactly one, ``0 <= x1 <= b`` or ``0 <= x2 <= a`` ``[length]``.

    Returns
    -------
    Outcome with ``N``, ``V`` (N), ``M`` (N m) at the section and the corner values ``N0``,
    ``V0`` (N), ``M0`` (N m).

    Examples
    --------
    >>> out = rotating_angled_arm(3.0, 2.0, 1.0, 1.0, x2=2.0)
    >>> out.values["N"], out.values["M"], out.values["M0"]
    (4.0, 0.0, 1.0)
    """
    m_, a_, b_, W = (magnitude(m, "kg"), magnitude(a, "m"), magnitude(b, "m"),
                     magnitude(Omega, "rad/s"))
    if (x1 is None) == (x2 is None):
        raise InputError("rotating-angled-arm needs exactly one section: x1 (on leg b, from "
                         "its free end) or x2 (on leg a, from the corner)")
    mu_W2 = m_ / (a_ + b_) * W * W
    if x1 is not None:
        x = magnitude(x1, "m")
        _position(x, b_, "x1", "b")
        N, V, M = arm_leg_b(mu_W2, a_, b_, x)
    else:
        x = magnitude(x2, "m")
        _position(x, a_, "x2", "a")
        N, V, M = arm_leg_a(mu_W2, a_, b_, x)
    N0, V0, M0 = arm_leg_a(mu_W2, a_, b_, 0.0)
    return Outcome({"N": N, "V": V, "M": M, "N0": N0, "V0": V0, "M0": M0},
                   assumptions=[_NO_WEIGHT + ": the arm turns in a horizontal plane",
                                "constant Omega: only the centrifugal loads act"],
                   exact_zeros={"M"} if x2 is not None and x == a_ else set())  # the axis
