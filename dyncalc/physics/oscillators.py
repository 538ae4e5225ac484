"""Natural frequencies of the basic oscillators: mass on a spring, torsional, pendulums.

Pure functions on pint quantities returning an :class:`~dyncalc.physics.outcome.Outcome`.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapter 5.
"""
from __future__ import annotations

import math

from ..errors import PhysicsError
from .numerics import HALF_TURN, half_complement_sin, monomial, pendulum_period_factor, sqrt_ratio
from .outcome import Outcome, periodic

__all__ = ["mass_spring", "torsional", "pendulum", "physical_pendulum", "large_amplitude",
           "SMALL_ANGLE_METHODS"]

#: The methods a pendulum-like scene offers besides ``auto``.
SMALL_ANGLE_METHODS = ("small-angle", "elliptic")
#: Relative accuracy claimed for the elliptic (AGM) period: a few ulp (tests/test_pendulum.py).
ELLIPTIC_ERROR = 1e-15
_SHORT = {"degree": "deg", "radian": "rad", "grade": "grad", "arcminute": "arcmin",
          "arcsecond": "arcsec"}


def _si(quantity, unit: str) -> float:
    return float(quantity.to(unit).magnitude)


def mass_spring(k, m) -> Outcome:
    """Mass on a linear spring.

    .. math:: \\omega^2 = k / m

    Parameters
    ----------
    k : Quantity
        Stiffness ``[force]/[length]``.
    m : Quantity
        Mass ``[mass]``.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s).

    Examples
    --------
    E5.11, E5.19 and E5.26 of [1] reduce to this after the springs are combined:

    >>> from dyncalc.units import Q_
    >>> mass_spring(Q_(100, "N/m"), Q_(2, "kg")).values["omega"].magnitude  # rad/s
    7.0710678118654755
    """
    return Outcome(periodic(sqrt_ratio(_si(k, "N/m"), _si(m, "kg"))))


def torsional(kt, J) -> Outcome:
    """Rotor on a torsional spring.

    .. math:: \\omega^2 = k_t / J

    Parameters
    ----------
    kt : Quantity
        Torsional stiffness ``[force]*[length]/[angle]``.
    J : Quantity
        Mass moment of inertia about the axis ``[mass]*[length]^2``.

    >>> from dyncalc.units import Q_
    >>> torsional(Q_(3, "kN*m/rad"), Q_(1.2, "kg*m^2")).values["f"].magnitude  # Hz
    7.957747154594767
    """
    return Outcome(periodic(sqrt_ratio(_si(kt, "N*m/rad"), _si(J, "kg*m**2"))))


def _amplitude_parts(amplitude) -> tuple[float, str, float]:
    """(magnitude, unit name, radians) of an amplitude: in the unit typed where half a turn is
    exact in it (degree, grade, ...) or it is the radian; otherwise converted to radians."""
    units = list(amplitude.units._units.items())
    radians = _si(amplitude, "rad")
    if len(units) == 1 and units[0][1] == 1 and (units[0][0] in HALF_TURN
                                                 or units[0][0] == "radian"):
        return float(amplitude.magnitude), units[0][0], radians
    return radians, "radian", radians


def large_amplitude(omega0: float, amplitude, method: str = "auto", rtol: float = 1e-9,
                    what: str = "pendulum") -> Outcome:
    """Period of a pendulum-like oscillator ``theta'' + omega0^2 sin(theta) = 0`` at amplitude
    ``amplitude``, by the model the method (or, for ``auto``, the tolerance) chooses.

    .. math:: T = \\frac{2\\pi}{\\omega_0\\,\\mathrm{AGM}(1, \\cos(\\theta_0/2))}
              = \\frac{4 K(\\sin(\\theta_0/2))}{\\omega_0}

    ``cos(theta0/2)`` is taken as ``sin`` of half the complement, in the unit typed
    (:func:`~dyncalc.physics.numerics.half_complement_sin`), so the period is within a few ulp
    up to a hair below 180 degrees.

    Parameters
    ----------
    omega0 : float
        Small-oscillation angular frequency, rad/s.
    amplitude : Quantity or None
        Angle ``[angle]``, 0 <= amplitude < 180 deg. ``None``: small oscillations.
    method : {"auto", "small-angle", "elliptic"}
        ``auto`` takes the small-angle model when its true relative period error
        ``1 - AGM(1, cos(theta0/2))`` (about ``theta0^2/16``) meets ``rtol``, otherwise the
        elliptic period; the AGM costs a handful of float operations, so the choice is made on
        the exact error rather than on a bound.
    rtol : float
        Relative tolerance on the period.

    Returns
    -------
    Outcome with ``omega``, ``f``, ``T`` at the amplitude and ``omega_0``; ``error_estimate``
    is the relative period error of the model chosen, ``(T_model - T) / T`` in magnitude.
    """
    if amplitude is None:
        if method == "elliptic":
            raise PhysicsError(f"--method elliptic needs an amplitude (--amplitude or "
                               f"amplitude=); without one the {what} is linear")
        out = Outcome(periodic(omega0), model="linear", method="closed-form")
        out.assumptions.append("small oscillations (sin theta = theta); give --amplitude for "
                               "the exact large-amplitude period")
        return out
    magnitude, unit, radians = _amplitude_parts(amplitude)
    shown = f"{magnitude:.6g} {_SHORT.get(unit, unit)}"
    if radians >= math.pi:
        raise PhysicsError(f"the amplitude must be below 180 degrees; at {shown} the {what} "
                           "goes over the top and does not swing back")
    cos_half = half_complement_sin(magnitude, unit)
    factor = pendulum_period_factor(cos_half)        # T / T0 = 1 / AGM(1, cos(theta0/2))
    small_error = 1.0 - 1.0 / factor                  # (T - T0) / T: the small-angle error
    if method == "auto":  # the AGM is cheaper than any bound, so decide on the true error
        method = "small-angle" if small_error <= rtol else "elliptic"
    assumption = (f"the small-angle period is {100 * small_error:.3g}% short at an amplitude "
                  f"of {shown}")
    if method == "small-angle":
        values = periodic(omega0)
        values["omega_0"] = values["omega"]
        out = Outcome(values, model="linear", method="small-angle", error_estimate=small_error,
                      assumptions=[assumption])
        if small_error > rtol:
            out.warnings.append(f"the small-angle model misses the requested tolerance "
                                f"{rtol:g}: its period is {100 * small_error:.3g}% short at "
                                f"{shown}; use --method elliptic")
        return out
    values = periodic(omega0 / factor)
    values["omega_0"] = periodic(omega0)["omega"]
    out = Outcome(values, model="nonlinear", method="elliptic", error_estimate=ELLIPTIC_ERROR,
                  assumptions=[f"exact period of theta'' + omega_0^2 sin(theta) = 0 (complete "
                               f"elliptic integral by the AGM); {assumption}"])
    return out


def pendulum(l, g, amplitude=None, method: str = "auto", rtol: float = 1e-9) -> Outcome:
    """Simple pendulum: a point mass on a massless rod or string.

    .. math:: \\omega_0^2 = g / l

    with the exact period at amplitude ``theta0`` from :func:`large_amplitude`.

    Parameters
    ----------
    l : Quantity
        Length ``[length]``.
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.
    amplitude : Quantity, optional
        ``[angle]``, 0 <= amplitude < 180 deg.
    method, rtol
        See :func:`large_amplitude`.

    Examples
    --------
    >>> from dyncalc.units import Q_
    >>> out = pendulum(Q_(1, "m"), Q_(9.80665, "m/s^2"))
    >>> round(out.values["T"].magnitude, 6)
    2.006409
    >>> out = pendulum(Q_(1, "m"), Q_(9.80665, "m/s^2"), Q_(90, "deg"))
    >>> round(out.values["T"].magnitude / 2.006409, 4)  # 1.18034 = 2K(1/sqrt 2)/pi
    1.1803
    """
    return large_amplitude(sqrt_ratio(_si(g, "m/s**2"), _si(l, "m")), amplitude, method, rtol)


def physical_pendulum(m, a, g, J=None, J_A=None, amplitude=None, method: str = "auto",
                      rtol: float = 1e-9) -> Outcome:
    """Rigid body swinging about a fixed pivot.

    .. math:: \\omega_0^2 = \\frac{m g a}{J_A}, \\qquad J_A = J + m a^2

    Parameters
    ----------
    m : Quantity
        Mass ``[mass]``.
    a : Quantity
        Distance from the pivot to the centre of mass ``[length]``.
    g : Quantity
        ``[length]/[time]^2``.
    J : Quantity, optional
        Moment of inertia about the centre of mass ``[mass]*[length]^2``; or give
    J_A : Quantity, optional
        the moment of inertia about the pivot.
    amplitude, method, rtol
        See :func:`large_amplitude`.

    Returns
    -------
    Outcome with ``omega``, ``f``, ``T`` (and ``omega_0``), ``J_A``.

    Examples
    --------
    A uniform rod of length L about one end (J_A = m L^2/3, a = L/2) swings like a simple
    pendulum of length 2L/3 (E3.44 and E5.15 of [1] build on this):

    >>> from dyncalc.units import Q_
    >>> rod = physical_pendulum(Q_(3, "kg"), Q_(0.5, "m"), Q_(9.81, "m/s^2"), J_A=Q_(1, "kg*m^2"))
    >>> round(rod.values["omega"].magnitude ** 2, 12)  # g / (2/3)
    14.715
    """
    m_, a_, g_ = _si(m, "kg"), _si(a, "m"), _si(g, "m/s**2")
    steiner = monomial(1.0, [(m_, 1), (a_, 2)])                  # m a^2, no overflow midway
    ja = _si(J_A, "kg*m**2") if J_A is not None else _si(J, "kg*m**2") + steiner
    if J_A is not None and ja < steiner * (1 - 1e-12):
        raise PhysicsError(f"J_A = {ja:.6g} kg*m^2 is less than m a^2 = {steiner:.6g} "
                           "kg*m^2, which no body can have (J_A = J + m a^2 with J >= 0)")
    if not math.isfinite(ja):
        raise PhysicsError("J_A = J + m a^2 overflows float64")
    omega0 = math.sqrt(monomial(1.0, [(m_, 1), (g_, 1), (a_, 1), (ja, -1)]))
    out = large_amplitude(omega0, amplitude, method, rtol, what="physical pendulum")
    from ..units import Q_

    out.values["J_A"] = Q_(ja, "kg*m**2")
    return out
