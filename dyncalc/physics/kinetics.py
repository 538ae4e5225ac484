"""Kinetics of connected rigid bodies: drums and blocks on ropes, a wheel and a block, impacts.

Pure functions on pint quantities or SI floats returning an
:class:`~dyncalc.physics.outcome.Outcome` of SI floats (the ``rigid-body`` command's scenes,
../shared/SCENES.md "Rigid-body scenes"). Every formula comes from Newton-Euler applied to
each body (rope forces eliminated). Each is evaluated in exact rational arithmetic on the
float inputs (:class:`fractions.Fraction`) and rounded once at the end: every result is the
float nearest the formula's value at those inputs (``sin``/``cos`` of an incline aside, rounded
once each), with no overflow midway and no cancellation (``m2 r2 - m1 r1`` is exact, and zero
exactly at static balance); a result beyond float64 is ``inf`` (warned by the Result).

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapters 3 and 4.
"""
from __future__ import annotations

import math
from fractions import Fraction

from ..errors import InputError
from ..units import (ACCELERATION, ANGLE, IMPULSE, INERTIA, LENGTH, MASS, TORQUE,
                     VELOCITY)
from .face import check_units, magnitude
from .outcome import Outcome

__all__ = ["drum_two_blocks", "wheel_incline_block", "two_drums_rope_drive",
           "direct_central_impact", "double_pendulum_impulse"]

_ROPES = "massless inextensible ropes that do not slip; frictionless axles"


def _exact(*values: float) -> list[Fraction]:
    """The floats as exact fractions (a non-finite input is refused)."""
    try:
        return [Fraction(v) for v in values]
    except (OverflowError, ValueError):
        raise InputError("every input must be finite") from None


def _floats(**values: Fraction) -> dict[str, float]:
    """Each exact value rounded once to the nearest float (``±inf`` beyond float64)."""
    out = {}
    for name, value in values.items():
        try:
            out[name] = float(value)
        except OverflowError:
            out[name] = math.inf if value > 0 else -math.inf
    return out


@check_units(m1=MASS, m2=MASS, r1=LENGTH, r2=LENGTH, J_A=INERTIA, g=ACCELERATION)
def drum_two_blocks(m1, m2, r1, r2, J_A, g=9.80665) -> Outcome:
    """Two blocks hanging from a stepped drum on opposite sides of its axle (E4.10 of [1]).

    .. math:: \\alpha = \\frac{(m_2 r_2 - m_1 r_1) g}{J_A + m_1 r_1^2 + m_2 r_2^2},\\quad
              a_1 = r_1\\alpha,\\ a_2 = r_2\\alpha,\\quad S_1 = m_1 (g + a_1),\\
              S_2 = m_2 (g - a_2)

    Parameters
    ----------
    m1, m2 : Quantity
        Masses of the blocks on radius r1 and r2 ``[mass]``.
    r1, r2 : Quantity
        Groove radii ``[length]``.
    J_A : Quantity
        Moment of inertia of the drum about its axle ``[mass]*[length]^2``.
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``alpha`` (rad/s^2, positive when block 2 goes down), ``a1`` (m/s^2, block
    1 up), ``a2`` (m/s^2, block 2 down), ``S1``, ``S2`` (N, rope forces, always positive).

    Examples
    --------
    >>> out = drum_two_blocks(1.0, 2.0, 0.1, 0.2, 0.03, 10.0)
    >>> round(out.values["alpha"], 12), round(out.values["S1"], 12)
    (25.0, 12.5)
    """
    m1_, m2_, r1_, r2_, J, g_ = _exact(
        magnitude(m1, "kg"), magnitude(m2, "kg"), magnitude(r1, "m"), magnitude(r2, "m"),
        magnitude(J_A, "kg*m^2"), magnitude(g, "m/s^2"))
    D = J + m1_ * r1_ * r1_ + m2_ * r2_ * r2_
    top = m2_ * r2_ - m1_ * r1_
    alpha = top * g_ / D
    values = _floats(alpha=alpha, a1=r1_ * alpha, a2=r2_ * alpha, S1=m1_ * (g_ + r1_ * alpha),
                     S2=m2_ * (g_ - r2_ * alpha))
    return Outcome(values, assumptions=[_ROPES],
                   exact_zeros={"alpha", "a1", "a2"} if top == 0 else set())


@check_units(m1=MASS, m2=MASS, beta=ANGLE, J_A=INERTIA, r=LENGTH, g=ACCELERATION)
def wheel_incline_block(m1, m2, beta, J_A=None, r=None, kappa=None, g=9.80665) -> Outcome:
    """A wheel rolling on an incline, pulled up the slope by a rope over a pulley to a hanging
    block (E4.12 of [1]).

    .. math:: a = \\frac{g (m_2 - m_1 \\sin\\beta)}{m_1 + m_2 + J_A/r^2},\\quad
              S = m_2 (g - a),\\quad H = \\frac{J_A}{r^2} a,\\quad N = m_1 g\\cos\\beta,\\quad
              \\mu_{min} = |H|/N

    Parameters
    ----------
    m1, m2 : Quantity
        Masses of the wheel and the block ``[mass]``.
    beta : Quantity
        Incline ``[angle]``, ``|beta| < 90 deg``.
    J_A, r : Quantity
        The wheel's moment of inertia about its centre ``[mass]*[length]^2`` and its rolling
        radius ``[length]``; or instead
    kappa : float
        its shape factor ``J_A / (m1 r^2)`` (r then cancels).
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``a`` (m/s^2, block down), ``S`` (N), ``H`` (N, friction on the wheel, down
    the slope), ``N`` (N) and ``mu_min``.

    Examples
    --------
    A disk (kappa = 1/2) on a level floor pulled by a block of its own mass, g = 10 m/s^2:

    >>> out = wheel_incline_block(1.0, 1.0, 0.0, kappa=0.5, g=10.0)
    >>> out.values["a"], out.values["S"], out.values["mu_min"]
    (4.0, 6.0, 0.2)
    """
    b = magnitude(beta, "rad")
    m1_, m2_, g_, s, c = _exact(magnitude(m1, "kg"), magnitude(m2, "kg"),
                                magnitude(g, "m/s^2"), math.sin(b), math.cos(b))
    if J_A is not None:
        J, r_ = _exact(magnitude(J_A, "kg*m^2"), magnitude(r, "m"))
        q = J / (r_ * r_)
    else:
        q = _exact(kappa)[0] * m1_
    total = m1_ + m2_ + q
    top = m2_ - m1_ * s
    a = g_ * top / total
    H, N = q * a, m1_ * g_ * c
    values = _floats(a=a, S=m2_ * g_ * (m1_ + q + m1_ * s) / total, H=H, N=N,
                     mu_min=abs(H) / N)
    zeros = ({"a"} if top == 0 else set()) | ({"H", "mu_min"} if top == 0 or q == 0 else set())
    return Outcome(values, exact_zeros=zeros,
                   assumptions=["rolling without slipping (static friction at least "
                                "mu_min N); " + _ROPES + "; an ideal pulley"])


@check_units(m1=MASS, m2=MASS, r1=LENGTH, r2=LENGTH, J1=INERTIA, J2=INERTIA, M0=TORQUE,
             g=ACCELERATION)
def two_drums_rope_drive(m1, m2, r1, r2, J1, J2, M0, g=9.80665) -> Outcome:
    """Two drums coupled by a rope, drum 1 driven by a moment, a block hanging from each
    (E4.13 of [1]).

    .. math:: a_2 = \\frac{g (m_2 r_2^2 - m_1 r_1 r_2) + M_0 r_2}{m_2 r_2^2 + m_1 r_1^2 + J_1
              + J_2},\\quad a_1 = \\frac{r_1}{r_2} a_2,\\quad \\alpha = \\frac{a_2}{r_2},\\quad
              S_1 = m_1 (g + a_1),\\ S_2 = m_2 (g - a_2)

    Parameters
    ----------
    m1, m2 : Quantity
        Masses of block 1 (on drum 1, radius r1) and block 2 (on drum 2, radius r2)
        ``[mass]``.
    r1, r2 : Quantity
        Radii ``[length]`` (the coupling rope runs on r2 of both drums).
    J1, J2 : Quantity
        Moments of inertia of the driven drum and the other ``[mass]*[length]^2``.
    M0 : Quantity
        Driving moment on drum 1 ``[force]*[length]`` (signed).
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``a2`` (block 2 down), ``a1`` (block 1 up) in m/s^2, ``alpha`` (rad/s^2, in
    the sense of M0), ``S1``, ``S2`` (N); a warning when a hanging rope would go slack.

    Examples
    --------
    >>> out = two_drums_rope_drive(1.0, 1.0, 0.1, 0.1, 0.0, 0.0, 2.0, 10.0)
    >>> round(out.values["a2"], 12), round(out.values["S2"], 12)
    (10.0, 0.0)
    """
    m1_, m2_, r1_, r2_, J1_, J2_, M, g_ = _exact(
        magnitude(m1, "kg"), magnitude(m2, "kg"), magnitude(r1, "m"), magnitude(r2, "m"),
        magnitude(J1, "kg*m^2"), magnitude(J2, "kg*m^2"), magnitude(M0, "N*m"),
        magnitude(g, "m/s^2"))
    D = m2_ * r2_ * r2_ + m1_ * r1_ * r1_ + J1_ + J2_
    top = g_ * (m2_ * r2_ * r2_ - m1_ * r1_ * r2_) + M * r2_
    a2 = top / D
    a1 = r1_ / r2_ * a2
    S1, S2 = m1_ * (g_ + a1), m2_ * (g_ - a2)
    values = _floats(a2=a2, a1=a1, alpha=a2 / r2_, S1=S1, S2=S2)
    zeros = {"a2", "a1", "alpha"} if top == 0 else set()
    zeros |= {name for name, value in (("S1", S1), ("S2", S2)) if value == 0}
    warnings = []
    if S2 < 0:
        warnings.append(f"the rope of block 2 goes slack: a2 = {values['a2']:.6g} m/s^2 "
                        "exceeds g; block 2 falls freely and these results do not hold")
    if S1 < 0:
        warnings.append(f"the rope of block 1 goes slack: a1 = {values['a1']:.6g} m/s^2 is "
                        "below -g; block 1 falls freely and these results do not hold")
    return Outcome(values, warnings=warnings, exact_zeros=zeros,
                   assumptions=[_ROPES + "; the coupling rope taut"])


@check_units(m1=MASS, m2=MASS, v1=VELOCITY, v2=VELOCITY)
def direct_central_impact(m1, m2, v1, v2, e) -> Outcome:
    """Straight central impact of two bodies with a coefficient of restitution.

    .. math:: v_c = \\frac{m_1 v_1 + m_2 v_2}{m_1 + m_2},\\quad
              v_1' = v_c - \\frac{e m_2 (v_1 - v_2)}{m_1 + m_2},\\quad
              v_2' = v_c + \\frac{e m_1 (v_1 - v_2)}{m_1 + m_2},\\quad
              \\hat F = \\frac{(1 + e) m_1 m_2 (v_1 - v_2)}{m_1 + m_2},\\quad
              \\Delta E = \\frac{(1 - e^2) m_1 m_2 (v_1 - v_2)^2}{2 (m_1 + m_2)}

    Parameters
    ----------
    m1, m2 : Quantity
        Masses ``[mass]``.
    v1, v2 : Quantity
        Velocities before the impact ``[length]/[time]``, signed, ``v1 > v2``.
    e : float
        Coefficient of restitution, ``0 <= e <= 1``.

    Returns
    -------
    Outcome with ``v_c``, ``v1_post``, ``v2_post`` (m/s), ``F_hat`` (N*s) and ``dE`` (J).

    Examples
    --------
    Equal masses, elastic: the velocities are exchanged.

    >>> out = direct_central_impact(1.0, 1.0, 2.0, 0.0, 1.0)
    >>> out.values["v1_post"], out.values["v2_post"], out.values["dE"]
    (0.0, 2.0, 0.0)
    """
    m1_, m2_, v1_, v2_, e_ = _exact(magnitude(m1, "kg"), magnitude(m2, "kg"),
                                    magnitude(v1, "m/s"), magnitude(v2, "m/s"), float(e))
    if not v1_ > v2_:
        raise InputError("direct-central-impact needs v1 > v2: body 1 must catch body 2 "
                         "(otherwise there is no impact)")
    if not 0.0 <= e_ <= 1.0:
        raise InputError(f"direct-central-impact needs 0 <= e <= 1 (e = 0 plastic, 1 elastic); "
                         f"got e = {float(e_):g}")
    total, dv = m1_ + m2_, v1_ - v2_
    v_c = (m1_ * v1_ + m2_ * v2_) / total
    mu = m1_ * m2_ / total  # the reduced mass
    exact = {"v_c": v_c, "v1_post": v_c - e_ * m2_ * dv / total,
             "v2_post": v_c + e_ * m1_ * dv / total, "F_hat": (1 + e_) * mu * dv,
             "dE": (1 - e_ * e_) * mu * dv * dv / 2}
    zeros = {name for name, value in exact.items() if value == 0}  # zero by the physics
    return Outcome(_floats(**exact), exact_zeros=zeros,
                   assumptions=["a straight central impact of smooth bodies without "
                                "rotation; other forces are negligible during the impact"])


@check_units(m=MASS, l=LENGTH, F_hat=IMPULSE, d=LENGTH)
def double_pendulum_impulse(m, l, F_hat, d=None) -> Outcome:
    """Two equal uniform bars hanging in line (A pinned, B joining them), bar 2 struck by a
    horizontal impulse at ``d`` above its lower end (E3.46 of [1]).

    .. math:: \\omega_1 = \\frac{6\\hat F (3d - l)}{7 m l^2},\\quad
              \\omega_2 = \\frac{6\\hat F (5l - 8d)}{7 m l^2},\\quad
              v_2 = \\frac{3\\hat F (3l - 2d)}{7 m l},\\quad
              \\hat B = \\frac{2\\hat F (3d - l)}{7l},\\quad \\hat A = \\hat B/2

    Parameters
    ----------
    m, l : Quantity
        Mass ``[mass]`` and length ``[length]`` of each bar.
    F_hat : Quantity
        The impulse ``[force]*[time]``.
    d : Quantity, optional
        Height of the blow above the lower end ``[length]``, ``0 <= d <= l``; default
        ``d_0 = 5l/8`` (bar 2 only translates).

    Returns
    -------
    Outcome with ``omega_1``, ``omega_2`` (rad/s), ``v_2`` (m/s), ``A_hat``, ``B_hat``
    (N*s), ``d_0`` and ``d_A0 = l/3`` (m).

    Examples
    --------
    At d_0 (the book's case): omega_1 = 3 F/(4 m l), omega_2 = 0, B = F/4, A = F/8.

    >>> out = double_pendulum_impulse(1.0, 1.0, 8.0)
    >>> [round(out.values[k], 12) for k in ("omega_1", "omega_2", "B_hat", "A_hat")]
    [6.0, 0.0, 2.0, 1.0]
    """
    m_, l_, F = _exact(magnitude(m, "kg"), magnitude(l, "m"), magnitude(F_hat, "N*s"))
    d_0 = 5 * l_ / 8
    d_ = d_0 if d is None else _exact(magnitude(d, "m"))[0]
    if not 0 <= d_ <= l_:
        raise InputError("double-pendulum-impulse needs 0 <= d <= l (the blow strikes bar 2); "
                         f"got d = {float(d_):g} m with l = {float(l_):g} m")
    upper, lower = 3 * d_ - l_, 5 * l_ - 8 * d_
    B_hat = 2 * F * upper / (7 * l_)
    values = _floats(omega_1=6 * F * upper / (7 * m_ * l_ * l_),
                     omega_2=6 * F * lower / (7 * m_ * l_ * l_),
                     v_2=3 * F * (3 * l_ - 2 * d_) / (7 * m_ * l_), A_hat=B_hat / 2, B_hat=B_hat,
                     d_0=d_0, d_A0=l_ / 3)
    return Outcome(values,
                   exact_zeros=({"omega_2"} if lower == 0 else set())
                   | ({"omega_1", "A_hat", "B_hat"} if upper == 0 else set()),
                   assumptions=["uniform thin bars; the blow is short, so the bars do not "
                                "move during it and weight gives no impulse"])
