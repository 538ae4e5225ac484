"""Oscillators on moving supports and in rotating frames: a pendulum on an accelerating
support, a pendulum on a spinning disk, a bead on a spinning ring, and a quarter-car driven by
a wavy road.

Pure functions on pint quantities returning an :class:`~dyncalc.physics.outcome.Outcome`.
Where a result hangs on a difference of nearly equal terms (near the bead's bifurcation, near
the car's critical speed) the difference is formed exactly in rational arithmetic from the
float inputs (:class:`fractions.Fraction`), then rounded once.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapters 5 and 6.
"""
from __future__ import annotations

import math
from fractions import Fraction

from ..errors import PhysicsError
from ..lazy import numpy as np
from ..units import Q_
from ..units import ACCELERATION, ANGULAR_RATE, LENGTH, MASS, STIFFNESS, VELOCITY
from .face import check_units, magnitude
from .columns import Columns, column_kernel
from .numerics import PI_LO, finite_nonzero, sqrt_ratio, sqrt_ratio_array
from .numerics_arrays import (dd_div, dd_mul, dd_one_minus, elementwise, hypot_array,
                              round_certified, two_product_array)
from .outcome import Outcome, periodic, periodic_arrays

__all__ = ["pendulum_accelerating_support", "pendulum_on_rotating_disk",
           "bead_on_rotating_ring", "quarter_car", "BIFURCATION_ULPS", "NEAR_BIFURCATION",
           "RESONANCE_GAP", "LARGE_AMPLIFICATION"]

EPS = 2.0 ** -52
#: ``|1 - g/(r Omega^2)|`` at or below which the bead is taken to sit at its bifurcation.
BIFURCATION_ULPS = 4.0 * EPS
#: ``|1 - g/(r Omega^2)|`` below which a warning says the bead is near its bifurcation
#: (about 1% in Omega).
NEAR_BIFURCATION = 0.02
#: ``|1 - (v0/v_crit)^2|`` at or below which the quarter-car is refused as resonant: v0 equals
#: v_crit to within the rounding of the inputs.
RESONANCE_GAP = 8.0 * EPS
#: Amplification ``x_amp / U0`` above which the quarter-car warns that it is near resonance.
LARGE_AMPLIFICATION = 1e6

#: pi^2 as an exact fraction good to about 32 digits ((PI_HI + PI_LO)^2).
_PI2 = (Fraction(math.pi) + Fraction(PI_LO)) ** 2


@check_units(l=LENGTH, a0=ACCELERATION, g=ACCELERATION)
def pendulum_accelerating_support(l, a0, g) -> Outcome:
    """A simple pendulum whose support moves horizontally with constant acceleration ``a0``.

    .. math:: l\\ddot\\varphi + g \\sin\\varphi + a_0 \\cos\\varphi = 0, \\qquad
              \\varphi_0 = -\\arctan\\frac{a_0}{g}, \\qquad
              \\omega^2 = \\frac{\\sqrt{g^2 + a_0^2}}{l}

    ``phi`` is measured from the downward vertical, positive toward the direction of ``a0``;
    the bob trails behind (``phi_0 < 0`` for ``a0 > 0``) and swings about the direction of
    the apparent gravity ``hypot(g, a0)``.

    Parameters
    ----------
    l : Quantity
        Length ``[length]``.
    a0 : Quantity
        Support acceleration ``[length]/[time]^2``, any sign, zero allowed.
    g : Quantity
        ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega``, ``f``, ``T`` and ``phi_0`` (rad).

    Notes
    -----
    ``phi_0 = -atan2(a0, g)`` and ``hypot(g, a0)`` keep full accuracy for any ratio of
    ``a0`` to ``g`` (no overflow of ``a0^2``).

    Examples
    --------
    The set-up of E6.5 of [1]: a support accelerating at g tilts the pendulum by 45 degrees
    and raises ``omega^2`` by ``sqrt(2)``:

    >>> from dyncalc.units import Q_
    >>> g = Q_(9.81, "m/s^2")
    >>> out = pendulum_accelerating_support(Q_(1, "m"), g, g)
    >>> out.values["phi_0"].to("deg").magnitude
    -45.0
    >>> round(out.values["omega"].magnitude ** 2 / 9.81, 15)  # sqrt(2)
    1.414213562373095
    """
    l_, a_, g_ = magnitude(l, "m"), magnitude(a0, "m/s**2"), magnitude(g, "m/s**2")
    phi0 = 0.0 - math.atan2(a_, g_)  # 0.0 - ... : no negative zero for a0 = 0
    values = periodic(sqrt_ratio(math.hypot(g_, a_), l_))
    values["phi_0"] = Q_(phi0, "rad")
    return Outcome(values, model="linear", method="closed-form",
                   assumptions=["small oscillations about the tilted equilibrium phi_0; "
                                "constant support acceleration"])


@column_kernel(pendulum_accelerating_support)
def _pendulum_accelerating_support_columns(l, a0, g) -> Columns:
    """:func:`pendulum_accelerating_support` on columns (``l`` in m, ``a0`` and ``g`` in
    m/s^2). ``atan2`` and ``hypot`` are taken row by row from ``math`` (numpy's round
    differently), the rest as the one-off does. Rows with a result zero or beyond float64 are
    not exact (``phi_0 = 0`` only counts where ``a0 = 0``: elsewhere it is an underflow)."""
    values = periodic_arrays(sqrt_ratio_array(hypot_array(g, a0), l))
    exact = finite_nonzero(values)
    values["phi_0"] = 0.0 - elementwise(math.atan2, a0, g)
    return Columns(values, exact=exact & ((values["phi_0"] != 0.0) | (a0 == 0.0)))


@check_units(r=LENGTH, l=LENGTH, Omega=ANGULAR_RATE)
def pendulum_on_rotating_disk(r, l, Omega) -> Outcome:
    """A pendulum pivoted on a disk spinning at ``Omega`` about a vertical axis, swinging in
    the horizontal plane (weight neglected): the centrifugal field holds it radially outward.

    .. math:: \\omega = \\sqrt{\\frac{r}{l}}\\,|\\Omega|

    Parameters
    ----------
    r : Quantity
        Disk centre to pivot ``[length]``.
    l : Quantity
        Pendulum length ``[length]``.
    Omega : Quantity
        Spin of the disk ``[angle]/[time]`` (rpm allowed), not zero; its sense does not
        matter.

    Returns
    -------
    Outcome with ``omega``, ``f``, ``T``.

    Examples
    --------
    The set-up of E6.8 of [1], with numbers of our own:

    >>> from dyncalc.units import Q_
    >>> out = pendulum_on_rotating_disk(Q_(0.4, "m"), Q_(0.1, "m"), Q_(3, "rad/s"))
    >>> out.values["omega"].magnitude  # 2 Omega
    6.0
    """
    r_, l_, spin = magnitude(r, "m"), magnitude(l, "m"), abs(magnitude(Omega, "rad/s"))
    if spin == 0.0:
        raise PhysicsError("Omega must not be zero: a pendulum on a disk at rest has no "
                           "restoring force in the horizontal plane")
    return Outcome(periodic(sqrt_ratio(r_, l_) * spin), model="linear", method="closed-form",
                   assumptions=["small oscillations in the horizontal plane, weight "
                                "neglected, constant spin"])


@column_kernel(pendulum_on_rotating_disk)
def _pendulum_on_rotating_disk_columns(r, l, Omega) -> Columns:
    """:func:`pendulum_on_rotating_disk` on columns (``r``, ``l`` in m, ``Omega`` in rad/s);
    a zero spin (refused) or a result zero or beyond float64 is not exact."""
    with np.errstate(over="ignore"):
        values = periodic_arrays(sqrt_ratio_array(r, l) * np.abs(Omega))
    return Columns(values, exact=finite_nonzero(values))


@check_units(r=LENGTH, Omega=ANGULAR_RATE, g=ACCELERATION)
def bead_on_rotating_ring(r, Omega, g) -> Outcome:
    """A bead sliding without friction on a circular ring of radius ``r`` that spins at
    ``Omega`` about its vertical diameter; ``theta`` is measured from the bottom.

    .. math:: \\ddot\\theta = \\sin\\theta\\,(\\Omega^2 \\cos\\theta - g/r)

    With ``c = g/(r Omega^2)``:

    * ``Omega^2 < g/r`` (``c > 1``): stable at the bottom, ``theta_eq = 0``,
      ``omega^2 = g/r - Omega^2``;
    * ``Omega^2 > g/r`` (``c < 1``): the bottom is unstable and the bead rides up to
      ``theta_eq = acos(c)`` (and ``-theta_eq``), ``omega^2 = Omega^2 - (g/(r Omega))^2``.

    The difference ``r Omega^2 - g`` is formed exactly (fractions) from the float inputs, so
    near the bifurcation ``1 - c`` keeps its digits; then
    ``theta_eq = 2 asin(sqrt((1 - c)/2))`` (the same angle as ``acos(c)``, well conditioned
    near ``c = 1`` where ``acos`` loses half the digits), ``omega = |Omega| sqrt((1 - c)(1 +
    c))`` above and ``omega = sqrt(g/r) sqrt(1 - r Omega^2/g)`` below the bifurcation: each
    within a few ulp.

    Parameters
    ----------
    r : Quantity
        Ring radius ``[length]``.
    Omega : Quantity
        Spin ``[angle]/[time]`` (rpm allowed); any sign, zero allowed.
    g : Quantity
        ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega``, ``f``, ``T`` about the stable equilibrium and ``theta_eq`` (rad).

    Notes
    -----
    At the bifurcation (``|1 - c|`` within :data:`BIFURCATION_ULPS`) the linear stiffness
    vanishes: ``omega = 0``, the period is infinite and a warning says the oscillation is
    governed by the cubic term. Within :data:`NEAR_BIFURCATION` of it a warning says the
    linear frequency holds only for tiny amplitudes.

    Examples
    --------
    The set-up of E6.11 of [1], with numbers of our own (checked against mpmath):

    >>> from dyncalc.units import Q_
    >>> out = bead_on_rotating_ring(Q_(0.2, "m"), Q_(10, "rad/s"), Q_(9.81, "m/s^2"))
    >>> round(out.values["theta_eq"].to("deg").magnitude, 12)  # acos(0.4905)
    60.626549578274
    >>> round(out.values["omega"].magnitude, 12)  # 10 sqrt(1 - 0.4905^2)
    8.714411913606
    """
    r_, spin, g_ = magnitude(r, "m"), abs(magnitude(Omega, "rad/s")), magnitude(g, "m/s**2")
    critical = sqrt_ratio(g_, r_)
    pull = Fraction(r_) * Fraction(spin) ** 2   # r Omega^2, exact
    excess = pull - Fraction(g_)                # r Omega^2 - g, exact; its sign is the regime
    warnings = []
    if abs(excess) <= Fraction(BIFURCATION_ULPS) * pull:  # a float * Fraction may overflow
        values = periodic(0.0)
        values["theta_eq"] = Q_(0.0, "rad")
        warnings.append(f"Omega is at the bifurcation Omega^2 = g/r (Omega = {critical:.6g} "
                        "rad/s): the linear stiffness vanishes, so omega = 0 and the period "
                        "is infinite; the real oscillation is governed by the cubic term and "
                        "depends on its amplitude")
        return Outcome(values, model="linear", method="closed-form", warnings=warnings,
                       assumptions=["small oscillations about the stable equilibrium"],
                       exact_zeros={"omega", "f", "theta_eq"})
    if excess > 0:                        # above the bifurcation: the bead rides up
        gap = excess / pull               # 1 - c, exact
        theta = 2.0 * math.asin(math.sqrt(0.5 * float(gap)))
        omega = spin * math.sqrt(float(gap * (2 - gap)))
    else:                                 # below: stable at the bottom
        theta = 0.0
        omega = critical * math.sqrt(float(-excess / Fraction(g_)))  # 1 - r Omega^2/g
    values = periodic(omega)
    values["theta_eq"] = Q_(theta, "rad")
    if abs(excess) < Fraction(NEAR_BIFURCATION) * pull:
        side = "above" if excess > 0 else "below"
        warnings.append(f"Omega is {100 * abs(spin / critical - 1):.2g}% {side} the "
                        f"bifurcation speed sqrt(g/r) = {critical:.6g} rad/s: the stiffness "
                        "about the equilibrium is small, so this frequency holds only for "
                        "very small amplitudes and changes fast with Omega")
    regime = ("above the bifurcation: equilibria at +-theta_eq" if excess > 0
              else "below the bifurcation: equilibrium at the bottom")
    return Outcome(values, model="linear", method="closed-form", warnings=warnings,
                   assumptions=[f"small oscillations about the stable equilibrium ({regime}); "
                                "frictionless bead, constant spin"],
                   exact_zeros=set() if excess > 0 else {"theta_eq"})


#: ``rho = r Omega^2 / g`` at or beyond which (at or below :data:`_BEAD_BELOW`) the bead is
#: certainly farther than :data:`NEAR_BIFURCATION` from its bifurcation (a margin of 2^-40 over
#: ``1/(1 -+ 0.02)`` covers the rounding of the bound and of ``rho``).
_BEAD_ABOVE = 1.0 / (1.0 - NEAR_BIFURCATION) * (1.0 + 2.0 ** -40)
_BEAD_BELOW = 1.0 / (1.0 + NEAR_BIFURCATION) * (1.0 - 2.0 ** -40)
#: Relative error bound of the double-double values the columns round: a few 2^-104 per step,
#: amplified at most 50 times by ``1 - x`` (``x <= 0.98`` away from the bifurcation).
_DD_BOUND = 2.0 ** -90


@column_kernel(bead_on_rotating_ring)
def _bead_on_rotating_ring_columns(r, Omega, g) -> Columns:
    """:func:`bead_on_rotating_ring` on columns (``r`` in m, ``Omega`` in rad/s, ``g`` in
    m/s^2), both regimes.

    The one-off rounds exact rationals once: ``1 - rho`` below the bifurcation, ``1 - 1/rho``
    and ``1 - 1/rho^2`` above (``rho = r Omega^2 / g``, via fractions). Here ``rho`` is formed
    from the binary mantissas in double-double arithmetic (relative error below 2^-100), each
    rational to within :data:`_DD_BOUND`, and rounded with :func:`round_certified`: a row is
    exact only where that rounding is certainly the correctly rounded one (all but about one
    row in 2^37). ``asin`` is math's, row by row. Rows within :data:`NEAR_BIFURCATION` (plus a
    margin) of the bifurcation (the one-off warns) and rows with a result zero or beyond
    float64 are not exact.
    """
    spin = np.abs(Omega)
    mr, er = np.frexp(r)
    ms, es = np.frexp(spin)
    mg, eg = np.frexp(g)
    with np.errstate(all="ignore"):
        sh, sl = two_product_array(ms, ms)
        rho_h, rho_l = dd_div(*dd_mul(sh, sl, mr, 0.0), mg, 0.0)       # rho 2^-E
        shift = er.astype(np.int64) + 2 * es - eg
        # beyond 2^+-200 rho's part in 1 - rho (1 - 1/rho) is far below an ulp of 1
        shift = np.clip(np.where(spin == 0.0, 0, shift), -200, 200).astype(np.int32)
        rho_h, rho_l = np.ldexp(rho_h, shift), np.ldexp(rho_l, shift)
        above, below = rho_h >= _BEAD_ABOVE, rho_h <= _BEAD_BELOW
        th, tl = dd_div(1.0, 0.0, np.where(above, rho_h, 2.0), np.where(above, rho_l, 0.0))
        gap, sure_gap = round_certified(*dd_one_minus(th, tl), _DD_BOUND)        # 1 - 1/rho
        stiff, sure_stiff = round_certified(*dd_one_minus(*dd_mul(th, tl, th, tl)),
                                            _DD_BOUND)                            # 1 - 1/rho^2
        rest, sure_rest = round_certified(*dd_one_minus(np.where(below, rho_h, 0.0),
                                                        np.where(below, rho_l, 0.0)),
                                          _DD_BOUND)                              # 1 - rho
        omega = np.where(above, spin * np.sqrt(stiff), sqrt_ratio_array(g, r) * np.sqrt(rest))
        theta = np.where(above, 2.0 * elementwise(math.asin, np.sqrt(0.5 * gap)), 0.0)
    values = periodic_arrays(omega)
    exact = finite_nonzero(values) & np.where(above, sure_gap & sure_stiff, below & sure_rest)
    values["theta_eq"] = theta
    return Columns(values, exact=exact)


@check_units(k=STIFFNESS, m=MASS, L=LENGTH, U0=LENGTH, v0=VELOCITY)
def quarter_car(k, m, L, U0, v0) -> Outcome:
    """A quarter-car: body mass ``m`` on a suspension spring ``k`` whose lower end follows a
    sinusoidal road ``u = U0 cos(2 pi x / L)`` at speed ``v0`` (undamped).

    .. math:: m\\ddot x + k x = k U_0 \\cos\\Omega t, \\quad \\omega^2 = \\frac{k}{m}, \\quad
              \\Omega = \\frac{2\\pi v_0}{L}, \\quad
              x_{amp} = \\frac{U_0}{|1 - \\Omega^2/\\omega^2|}, \\quad
              v_{crit} = \\frac{L}{2\\pi}\\sqrt{\\frac{k}{m}}

    The denominator ``1 - Omega^2/omega^2 = (k L^2 - 4 pi^2 m v0^2)/(k L^2)`` is formed
    exactly from the float inputs (fractions, with pi^2 to 32 digits) and rounded once, so
    ``x_amp`` is within about 1 ulp even a hair from resonance (the usual
    ``(omega - Omega)(omega + Omega)`` form still inherits the rounding of ``omega`` and
    ``Omega``, amplified by ``1/|1 - (v0/v_crit)^2|``).

    Parameters
    ----------
    k : Quantity
        Suspension stiffness ``[force]/[length]``.
    m : Quantity
        Body mass ``[mass]``.
    L : Quantity
        Road wavelength ``[length]``.
    U0 : Quantity
        Road amplitude ``[length]``.
    v0 : Quantity
        Speed ``[length]/[time]``.

    Returns
    -------
    Outcome with ``omega``, ``f``, ``T``, ``Omega`` (rad/s), ``x_amp`` (m, the absolute
    amplitude of the body) and ``v_crit`` (m/s).

    Raises
    ------
    PhysicsError
        At resonance: ``v0`` equal to ``v_crit`` to within the rounding of the inputs
        (:data:`RESONANCE_GAP`), where the undamped amplitude is unbounded.

    Notes
    -----
    Without damping; above :data:`LARGE_AMPLIFICATION` a warning says the real amplitude is
    set by the damping this model leaves out.

    Examples
    --------
    The set-up of E5.23 of [1], with numbers of our own (checked against mpmath):

    >>> from dyncalc.units import Q_
    >>> out = quarter_car(Q_(40, "kN/m"), Q_(400, "kg"), Q_(10, "m"), Q_(2, "cm"),
    ...                   Q_(20, "m/s"))
    >>> round(out.values["x_amp"].magnitude, 15)  # 0.02 / |1 - (4 pi)^2 / 100|
    0.034534160684074
    >>> round(out.values["v_crit"].magnitude, 12)  # 10 * 10 / (2 pi)
    15.91549430919
    """
    k_, m_, L_ = magnitude(k, "N/m"), magnitude(m, "kg"), magnitude(L, "m")
    U_, v_ = magnitude(U0, "m"), magnitude(v0, "m/s")
    omega = sqrt_ratio(k_, m_)
    v_crit = L_ * omega / (2.0 * math.pi)
    forcing = 2.0 * math.pi * v_ / L_
    stiff = Fraction(k_) * Fraction(L_) ** 2
    gap = (stiff - 4 * _PI2 * Fraction(m_) * Fraction(v_) ** 2) / stiff  # 1 - (v0/v_crit)^2
    if abs(gap) <= RESONANCE_GAP:
        raise PhysicsError(f"v0 = {v_:.6g} m/s is the critical speed v_crit = L sqrt(k/m) / "
                           f"(2 pi) = {v_crit:.6g} m/s: the road excites the body at "
                           "resonance and the undamped amplitude is unbounded; choose another "
                           "speed")
    try:
        amplitude = float(Fraction(U_) / abs(gap))
    except OverflowError:
        amplitude = math.inf
    if not math.isfinite(amplitude):
        raise PhysicsError(f"x_amp overflows float64: the speed is too close to v_crit = "
                           f"{v_crit:.6g} m/s for U0 = {U_:.6g} m")
    values = periodic(omega)
    values["Omega"] = Q_(forcing, "rad/s")
    values["x_amp"] = Q_(amplitude, "m")
    values["v_crit"] = Q_(v_crit, "m/s")
    out = Outcome(values, model="linear", method="closed-form",
                  assumptions=["undamped linear suspension; the wheel follows the road "
                               "(no tyre stiffness, no loss of contact); steady state"])
    gain = float(1 / abs(gap))  # |gap| may be beyond float64; its inverse is not
    if gain > LARGE_AMPLIFICATION:
        out.warnings.append(f"v0 = {v_:.6g} m/s is within {100 * abs(v_ / v_crit - 1):.2g}% "
                            f"of the critical speed v_crit = {v_crit:.6g} m/s: the undamped "
                            f"amplitude is {gain:.3g} times the road amplitude; a real "
                            "suspension is limited by the damping this model leaves out")
    return out


#: ``_PI2`` as a double-double (relative error about 1e-33).
_PI2_HI = float(_PI2)
_PI2_LO = float(_PI2 - Fraction(_PI2_HI))
#: ``|gap|`` at or above which the amplification ``1/|gap|`` is certainly at most
#: :data:`LARGE_AMPLIFICATION` (no warning).
_GAP_FLOOR = (1.0 / LARGE_AMPLIFICATION) * (1.0 + 2.0 ** -30)
#: Relative error bound of the double-double ``x_amp``: ``rho`` within a few 2^-104,
#: amplified at most 2^20 times by ``1 - rho`` (``|gap| >= 1e-6``), and the quotient.
_CAR_BOUND = 2.0 ** -78


@column_kernel(quarter_car)
def _quarter_car_columns(k, m, L, U0, v0) -> Columns:
    """:func:`quarter_car` on columns (``k`` in N/m, ``m`` in kg, ``L`` and ``U0`` in m,
    ``v0`` in m/s).

    ``x_amp`` is the one-off's exact rational ``U0 / |1 - rho|``, ``rho = 4 pi^2 m v0^2 /
    (k L^2)``, rounded once; here ``rho`` is formed from the binary mantissas in double-double
    arithmetic (pi^2 to 1e-33) and the quotient rounded with :func:`round_certified`: a row is
    exact only where that rounding is certainly the correct one (all but about one row in
    2^25). Rows near resonance (amplification above :data:`LARGE_AMPLIFICATION`: the one-off
    warns or refuses), with ``x_amp`` subnormal or a result zero or beyond float64 are not
    exact (``Omega = 0`` counts where ``v0 = 0``).
    """
    omega = sqrt_ratio_array(k, m)
    with np.errstate(all="ignore"):
        v_crit = L * omega / (2.0 * math.pi)
        forcing = 2.0 * math.pi * v0 / L
        mm, em = np.frexp(m)
        mv, ev = np.frexp(v0)
        mk, ek = np.frexp(k)
        ml, el = np.frexp(L)
        mu, eu = np.frexp(U0)
        num = dd_mul(*dd_mul(_PI2_HI, _PI2_LO, mm, 0.0), *two_product_array(mv, mv))
        den = dd_mul(*two_product_array(ml, ml), mk, 0.0)
        rho_h, rho_l = dd_div(*num, *den)                     # rho 2^-(shift)
        shift = 2 + em.astype(np.int64) + 2 * ev - ek - 2 * el
        shift = np.where(rho_h == 0.0, 0, shift)
        big = shift > 200       # |gap| = rho (1 - 1/rho): 1/rho is far below an ulp
        near = np.clip(shift, -200, 200).astype(np.int32)   # below 2^-200: gap = 1 - 0
        gap_h, gap_l = dd_one_minus(np.ldexp(rho_h, near), np.ldexp(rho_l, near))
        sign = np.where(gap_h < 0.0, -1.0, 1.0)
        gap_h, gap_l = np.where(big, rho_h, sign * gap_h), np.where(big, rho_l, sign * gap_l)
        amp, sure = round_certified(*dd_div(mu, 0.0, gap_h, gap_l), _CAR_BOUND)
        amp = np.ldexp(amp, np.clip(eu - np.where(big, shift, 0), -3000, 3000).astype(np.int32))
    values = periodic_arrays(omega)
    exact = (finite_nonzero(values) & np.isfinite(v_crit) & (v_crit != 0.0) & sure
             & (big | (gap_h >= _GAP_FLOOR)) & np.isfinite(amp) & (amp >= 2.0 ** -1022)
             & np.isfinite(forcing) & ((forcing != 0.0) | (v0 == 0.0)))
    values.update(Omega=forcing, x_amp=amp, v_crit=v_crit)
    return Columns(values, exact=exact)
