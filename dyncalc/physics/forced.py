"""Harmonically forced single-degree-of-freedom oscillator: steady amplitude, phase,
magnification, transmissibility, resonance peak, half-power bandwidth, isolation, and the
total response from initial conditions.

The equation of motion is ``m x'' + c x' + k x = F(t)`` with ``omega^2 = k/m``,
``zeta = c/(2 sqrt(k m))``, ``eta = Omega/omega`` and, for the four excitations:

========== ================================ ==========================================
excitation F(t)                             x
========== ================================ ==========================================
force      ``F0 cos(Omega t)``              absolute displacement of the mass
base       ``k u + c u'``, ``u = u0 cos``   absolute displacement of the mass
base-accel ``-m B0 cos(Omega t)``           displacement relative to the ground
unbalance  ``m_u e Omega^2 cos(Omega t)``   absolute displacement (``m`` the whole machine)
========== ================================ ==========================================

Numerical care: ``1 - eta^2`` (:func:`resonance_gap`) is formed exactly in rational arithmetic
from the float inputs and rounded once, so the amplitude and the phase keep their digits a
hair from resonance (``eta = 1 +- 1e-12``) with tiny damping (``zeta = 1e-9``); the
denominator ``sqrt((1 - eta^2)^2 + (2 zeta eta)^2)`` is a ``hypot`` (no overflow of the
squares); ``1 - 2 zeta^2`` and ``1 - 8 zeta^2 + 8 zeta^4`` are exact too.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Section 5.3 (forced vibrations).
.. [2] Rao, *Mechanical Vibrations*, 6th ed., Pearson 2017, Sections 3.4-3.7 (harmonic
   excitation, base excitation, rotating unbalance).
"""
from __future__ import annotations

import math
from fractions import Fraction

from ..errors import InputError, PhysicsError
from ..units import (ACCELERATION, ANGULAR_RATE, CYCLE_RATE, DAMPING, DIMENSIONLESS, FORCE,
                     LENGTH, MASS, STIFFNESS, TIME, UNBALANCE, VELOCITY)
from .face import check_units, magnitude
from .numerics import sqrt_ratio
from .outcome import CRITICAL_BAND, Outcome

__all__ = ["EXCITATIONS", "resonance_gap", "phase", "magnification", "transmissibility",
           "peak", "half_power", "no_peak_warning", "half_power_warning", "transient",
           "total_response", "forced_response",
           "RESONANCE_GAP", "SQRT_HALF", "UNDAMPED_WARNING"]

#: The excitation kinds, as the option names say them.
EXCITATIONS = ("force", "base", "base-accel", "unbalance")
#: ``|1 - eta^2|`` at or below which an undamped oscillator is at resonance (the rounding of
#: the inputs: Omega, k and m each carry half an ulp).
RESONANCE_GAP = 8.0 * 2.0 ** -52
#: The warning of every undamped response away from resonance.
UNDAMPED_WARNING = "undamped: X_res, the peak and the bandwidth are unbounded; not given"
#: ``1/sqrt(2)``: above this damping ratio the force response has no peak.
SQRT_HALF = math.sqrt(0.5)


def resonance_gap(Omega: float, *, k: float | None = None, m: float | None = None,
                  omega: float | None = None) -> float:
    """``1 - eta^2 = 1 - Omega^2 m / k`` (or ``1 - Omega^2/omega^2``), formed exactly from the
    float inputs and rounded once.

    .. math:: 1 - \\eta^2 = \\frac{k - m\\Omega^2}{k}

    Parameters
    ----------
    Omega : float
        Excitation angular frequency ``[angle]/[time]`` (rad/s).
    k, m : float, optional
        Stiffness ``[force]/[length]`` (N/m) and mass ``[mass]`` (kg); or
    omega : float, optional
        Natural angular frequency (rad/s).

    Returns
    -------
    float, within half an ulp of the exact value for these floats (``-inf`` beyond float64).

    Examples
    --------
    ``eta`` a hair above 1 keeps every digit of the gap (``(1 - eta)(1 + eta)`` would keep
    only those of ``eta``):

    >>> resonance_gap(1.000000000001, omega=1.0)
    -2.000177801165682e-12
    """
    W2 = Fraction(Omega) ** 2
    if k is not None and m is not None:
        exact = (Fraction(k) - Fraction(m) * W2) / Fraction(k)
    else:
        exact = 1 - W2 / Fraction(omega) ** 2
    try:
        return float(exact)
    except OverflowError:
        return -math.inf


def phase(kind: str, gap: float, zeta: float, eta: float) -> float:
    """Phase lag of the steady response behind the excitation, 0 to pi (rad).

    .. math:: \\varphi = \\operatorname{atan2}(2\\zeta\\eta,\\; 1 - \\eta^2)
              \\quad\\text{(force, unbalance, base acceleration)}

    .. math:: \\varphi = \\operatorname{atan2}(2\\zeta\\eta^3,\\; 1 - \\eta^2 + (2\\zeta\\eta)^2)
              \\quad\\text{(base motion: } x/u = (1 + 2i\\zeta\\eta)/(1 - \\eta^2 + 2i\\zeta\\eta))

    For base acceleration the lag is of the relative motion behind the inertial force
    ``-m B0 cos(Omega t)``.

    >>> round(phase("force", 0.0, 0.1, 1.0), 15)  # at resonance: a quarter cycle
    1.570796326794897
    """
    two_ze = 2.0 * zeta * eta
    if kind == "base":
        return math.atan2(two_ze * eta * eta, gap + two_ze * two_ze)
    return math.atan2(two_ze, gap)


def transmissibility(gap: float, zeta: float, eta: float) -> float:
    """Force (or motion) transmissibility, the same for the four excitations.

    .. math:: TR = \\frac{\\sqrt{1 + (2\\zeta\\eta)^2}}{\\sqrt{(1-\\eta^2)^2 + (2\\zeta\\eta)^2}}

    >>> transmissibility(-1.0, 0.0, math.sqrt(2.0))  # eta = sqrt 2: TR = 1 at any zeta
    1.0
    """
    two_ze = 2.0 * zeta * eta
    if gap == -math.inf:  # eta^2 beyond float64: both roots over eta^2
        return _far_ratio(zeta, eta) / eta
    return math.hypot(1.0, two_ze) / math.hypot(gap, two_ze)


def _far_ratio(zeta: float, eta: float) -> float:
    """``eta TR`` where ``eta^2`` is beyond float64:
    ``sqrt(1/eta^2 + 4 zeta^2) / sqrt((1/eta^2 - 1)^2 + (2 zeta/eta)^2)``."""
    inv = 1.0 / eta
    return math.hypot(inv, 2.0 * zeta) / math.hypot(inv * inv - 1.0, 2.0 * zeta * inv)


def magnification(kind: str, gap: float, zeta: float, eta: float) -> float:
    """The magnification ``V``: the steady amplitude over its static reference.

    .. math:: V = \\frac{1}{D}\\ \\text{(force: } X k/F_0\\text{; base acceleration: }
              X k/(m B_0)), \\quad V = \\frac{\\eta^2}{D}\\ \\text{(unbalance: } m X/(m_u e)),
              \\quad V = TR\\ \\text{(base: } X/u_0)

    with ``D = sqrt((1 - eta^2)^2 + (2 zeta eta)^2)`` (a ``hypot``).

    >>> magnification("force", 0.0, 0.05, 1.0)  # 1/(2 zeta) at resonance
    10.0
    """
    if kind == "base":
        return transmissibility(gap, zeta, eta)
    d = math.hypot(gap, 2.0 * zeta * eta)
    if kind == "unbalance":
        if d == math.inf:  # eta^2 beyond float64: V = 1/sqrt((1/eta^2 - 1)^2 + (2 zeta/eta)^2)
            return 1.0 / math.hypot(1.0 / eta / eta - 1.0, 2.0 * zeta / eta)
        if eta == 0.0:  # at rest (Omega = 0): no unbalance force, no motion
            return 0.0
        return eta / (d / eta) if d != 0.0 else math.inf
    return 1.0 / d


def _one_minus_two_z2(zeta: float) -> float:
    """``1 - 2 zeta^2`` exactly rounded (``-inf`` beyond float64, zeta above about 1e154)."""
    try:
        return float(1 - 2 * Fraction(zeta) ** 2)
    except OverflowError:
        return -math.inf


def peak(kind: str, zeta: float) -> tuple[float, float] | None:
    """``(eta_peak, V_peak)``: where the steady amplitude is largest over the excitation
    frequency (``Omega_peak = eta_peak omega``), or ``None`` when it has no maximum at a finite
    ``Omega > 0`` (undamped: unbounded at resonance; heavily damped: largest at 0 or at
    infinity).

    Derivation, with ``s = eta^2`` and ``D^2 = (1 - s)^2 + 4 zeta^2 s``:

    * force, base acceleration: ``V^2 = 1/D^2``; ``d(D^2)/ds = -2(1 - s) + 4 zeta^2 = 0`` gives
      ``s = 1 - 2 zeta^2``: a peak for ``zeta < 1/sqrt 2``, ``V_peak = 1/(2 zeta sqrt(1 -
      zeta^2))``; above, ``V`` falls from 1 at ``Omega = 0``.
    * unbalance: ``V^2 = s^2/D^2 = 1/((u - 1)^2 + 4 zeta^2 u)``, ``u = 1/s``: the same
      function of ``u``, so ``s = 1/(1 - 2 zeta^2)`` and the same ``V_peak``; above
      ``1/sqrt 2`` ``V`` rises to 1 as ``Omega -> inf``.
    * base motion: ``TR^2 = (1 + a s)/((1 - s)^2 + a s)``, ``a = 4 zeta^2``; setting the
      derivative's numerator to zero, ``a((1 - s)^2 + a s) - (1 + a s)(a - 2(1 - s)) = 0``
      simplifies to ``a s^2 + 2 s - 2 = 0``, so ``s = 2/(1 + sqrt(1 + 8 zeta^2))``, always in
      (0, 1): a peak below ``omega`` for every ``zeta > 0``; there
      ``1 - s = 8 zeta^2/(1 + sqrt(1 + 8 zeta^2))^2`` (no cancellation).

    >>> eta, v = peak("force", 0.1)
    >>> round(eta, 15), round(v, 12)  # sqrt(0.98), 1/(0.2 sqrt(0.99))
    (0.989949493661167, 5.025189076296)
    """
    if not zeta > 0.0:
        return None
    if kind == "base":
        r = math.hypot(1.0, math.sqrt(8.0) * zeta)
        s = 2.0 / (1.0 + r)
        w = (math.sqrt(8.0) * zeta / (1.0 + r)) ** 2
        eta = math.sqrt(s)
        two_ze = 2.0 * zeta * eta
        return eta, math.hypot(1.0, two_ze) / math.hypot(w, two_ze)
    s = _one_minus_two_z2(zeta)
    if not s > 0.0:
        return None
    v = 1.0 / (2.0 * zeta * math.sqrt((1.0 - zeta) * (1.0 + zeta)))
    return (math.sqrt(s) if kind != "unbalance" else 1.0 / math.sqrt(s)), v


def half_power(kind: str, zeta: float) -> tuple[float | None, float | None, float | None]:
    """The half-power frequencies ``(eta_low, eta_high, bandwidth/omega)``, where the steady
    amplitude is its peak over ``sqrt 2``: each ``None`` where it does not exist.

    Force and base acceleration: ``(1 - s)^2 + 4 zeta^2 s = 8 zeta^2 (1 - zeta^2)`` (a quartic in
    ``eta``, a quadratic in ``s = eta^2``) gives
    ``s = 1 - 2 zeta^2 +- 2 zeta sqrt(1 - zeta^2)``. The product of the two roots is
    ``P = 1 - 8 zeta^2 + 8 zeta^4`` (exact), so the lower one is ``P/s_+``: it exists only while
    ``P > 0``, ``zeta < sqrt((2 - sqrt 2)/4) = 0.38268``; above, the amplitude stays over
    ``X_peak/sqrt 2`` all the way down to ``Omega = 0`` and the bandwidth is not defined.
    ``eta_+ - eta_- = 4 zeta sqrt(1 - zeta^2)/(eta_+ + eta_-)`` (no cancellation; it tends to
    ``2 zeta`` for small damping). Unbalance: the same roots in ``u = 1/s``; there the
    *upper* frequency is lost above 0.38268. Base motion: with ``w = 1 - s`` and
    ``P = TR_peak^2``, ``P w^2 - a (P - 2) w - N/den = 0`` with ``den = w_p^2 + a s_p`` and
    ``N = 2(1 + a) w_p^2 + a(1 - 2 w_p) + a^2 s_p > 0`` at the peak ``s_p`` (the constant term
    ``P a - 2 - 2a`` written without cancellation); one root each side of 0, the lower
    frequency only while ``1 - w > 0``.

    >>> low, high, width = half_power("force", 0.01)
    >>> round(width, 9)  # close to 2 zeta
    0.020002001
    """
    if not zeta > 0.0:
        return None, None, None
    if kind == "base":
        return _half_power_base(zeta)
    if not _one_minus_two_z2(zeta) > 0.0:
        return None, None, None
    root = math.sqrt((1.0 - zeta) * (1.0 + zeta))
    plus = _one_minus_two_z2(zeta) + 2.0 * zeta * root
    z2 = Fraction(zeta) ** 2
    product = float(1 - 8 * z2 + 8 * z2 * z2)
    minus = product / plus if product > 0.0 else None
    spread = 4.0 * zeta * root
    if kind != "unbalance":
        low = math.sqrt(minus) if minus is not None else None
        width = spread / (math.sqrt(plus) + low) if low is not None else None
        return low, math.sqrt(plus), width
    low = 1.0 / math.sqrt(plus)
    if minus is None:
        return low, None, None
    high = 1.0 / math.sqrt(minus)
    return low, high, spread / ((math.sqrt(plus) + math.sqrt(minus)) * math.sqrt(product))


def _half_power_base(zeta: float):
    if zeta < 1e-100:
        # 4 zeta^2 < 1e-199 (it may underflow): the base-motion TR^2 = (1 + a s)/D^2 is the
        # force's 1/D^2 to far below an ulp, and so are its half-power frequencies
        return half_power("force", zeta)
    a = 4.0 * zeta * zeta
    r = math.hypot(1.0, math.sqrt(8.0) * zeta)
    s = 2.0 / (1.0 + r)
    w = (math.sqrt(8.0) * zeta / (1.0 + r)) ** 2
    den = w * w + a * s
    p = (1.0 + a * s) / den
    n = 2.0 * (1.0 + a) * w * w + a * (1.0 - 2.0 * w) + a * a * s
    lin = a * (p - 2.0)
    disc = math.sqrt(lin * lin + 4.0 * p * n / den)
    q = lin + math.copysign(disc, lin)
    w1 = q / (2.0 * p)
    w2 = -n / (den * p * w1)
    w_pos, w_neg = max(w1, w2), min(w1, w2)
    high = math.sqrt(1.0 - w_neg)
    if not 1.0 - w_pos > 0.0:
        return None, high, None
    low = math.sqrt(1.0 - w_pos)
    return low, high, (disc / p) / (high + low)


def no_peak_warning(kind: str, zeta: float) -> str:
    """The warning of a damped response without a resonance peak (``zeta >= 1/sqrt 2``; not
    for base motion, which always has one): where the amplitude is largest instead. One text
    for the one-off and the batch's rows (:mod:`~dyncalc.physics.forced_columns`).

    >>> no_peak_warning("force", 0.9)
    'zeta = 0.9 >= 1/sqrt(2): the amplitude has no resonance peak; it is largest at Omega = 0'
    """
    where = "at Omega = 0" if kind != "unbalance" else "as Omega -> inf"
    return (f"zeta = {zeta:.6g} >= 1/sqrt(2): the amplitude has no resonance peak; it is "
            f"largest {where}")


def half_power_warning(zeta: float, low: float | None, high: float | None,
                       omega: float) -> str | None:
    """The warning where one half-power frequency exists and the other does not (``low`` and
    ``high`` as :func:`half_power` gives them, ``eta``; ``omega`` [rad/s]): the bandwidth is
    not defined. ``None`` where both exist or neither does.

    >>> half_power_warning(0.5, None, 1.5, 2.0)[:48]
    'no lower half-power frequency at zeta = 0.5: X s'
    """
    if low is None and high is not None:
        return (f"no lower half-power frequency at zeta = {zeta:.6g}: X stays above "
                f"X_peak/sqrt(2) down to Omega = 0 (the upper one is {high * omega:.6g} "
                "rad/s); the bandwidth is not defined")
    if high is None and low is not None:
        return (f"no upper half-power frequency at zeta = {zeta:.6g}: X stays above "
                f"X_peak/sqrt(2) as Omega -> inf (the lower one is {low * omega:.6g} "
                "rad/s); the bandwidth is not defined")
    return None


def transient(omega: float, zeta: float, x0: float, v0: float, t: float) -> float:
    """Free response at ``t`` from ``x(0) = x0``, ``x'(0) = v0``.

    .. math:: x = e^{-\\zeta\\omega t}\\left(x_0\\cos\\omega_d t + \\frac{v_0 + \\zeta\\omega
              x_0}{\\omega_d}\\sin\\omega_d t\\right)

    (underdamped, ``omega_d = omega sqrt((1 - zeta)(1 + zeta))``); critically damped
    ``x = e^{-omega t}(x0 + (v0 + omega x0) t)``; overdamped the same with ``cosh``, ``sinh``
    and ``omega* = omega sqrt(zeta - 1) sqrt(zeta + 1)``.

    >>> round(transient(1.0, 0.0, 1.0, 0.0, math.pi), 15)
    -1.0
    """
    if t == 0.0:
        return x0
    decay = math.exp(-zeta * omega * t)
    if abs((1.0 - zeta) * (1.0 + zeta)) <= CRITICAL_BAND:
        return decay * (x0 + (v0 + omega * x0) * t)
    b = v0 + zeta * omega * x0
    if zeta < 1.0:
        wd = omega * math.sqrt((1.0 - zeta) * (1.0 + zeta))
        return decay * (x0 * math.cos(wd * t) + b * math.sin(wd * t) / wd)
    root = math.sqrt(zeta - 1.0) * math.sqrt(zeta + 1.0)
    ws = omega * root
    # e^{-zeta omega t} cosh(ws t) = (e^{-(zeta omega - ws) t} + e^{-(zeta omega + ws) t})/2,
    # the slow rate zeta omega - ws = omega/(zeta + sqrt(zeta^2 - 1)) without the cancellation
    # (which made it negative, and exp overflow, at large zeta)
    slow = math.exp(-(omega / (zeta + root)) * t)
    fast = math.exp(-(zeta * omega + ws) * t)
    return 0.5 * x0 * (slow + fast) + 0.5 * b * (slow - fast) / ws


def total_response(omega: float, zeta: float, Omega: float, X: float, phi: float,
                   sign: float, x0: float, v0: float, t: float) -> float:
    """``x(t)``: the steady state ``sign X cos(Omega t - phi)`` plus the transient that meets
    ``x(0) = x0``, ``x'(0) = v0`` (:func:`transient` from ``x0 - sign X cos phi`` and
    ``v0 - sign X Omega sin phi``). ``sign`` is -1 for base acceleration (the relative motion
    answers ``-m B0 cos(Omega t)``), else 1.

    >>> total_response(1.0, 0.0, 2.0, 1/3, math.pi, 1.0, -1/3, 0.0, 0.0)  # starts steady
    -0.3333333333333333
    """
    steady = sign * X * math.cos(Omega * t - phi)
    h0 = x0 - sign * X * math.cos(phi)
    hv = v0 - sign * X * Omega * math.sin(phi)
    return steady + transient(omega, zeta, h0, hv, t)


def resonant_response(omega: float, x_static: float, x0: float, v0: float, t: float) -> float:
    """Undamped at resonance: ``x = x0 cos(omega t) + (v0/omega) sin(omega t)
    + (x_st omega t / 2) sin(omega t)``, growing linearly (``x_st`` the forcing amplitude
    over ``k``: ``m x'' + k x = k x_st cos(omega t)``).

    >>> round(resonant_response(2.0, 1.0, 0.0, 0.0, math.pi / 4), 15)  # (2 pi/4 / 2) sin(pi/2)
    0.785398163397448
    """
    wt = omega * t
    return x0 * math.cos(wt) + (v0 / omega + 0.5 * x_static * wt) * math.sin(wt)


# --- the face: quantities in, an Outcome out ------------------------------------------------

def _si(value, unit: str) -> float | None:
    return None if value is None else magnitude(value, unit)


@check_units(k=STIFFNESS, m=MASS, omega=ANGULAR_RATE, zeta=DIMENSIONLESS, c=DAMPING,
             Q=DIMENSIONLESS, F0=FORCE, base=LENGTH, base_accel=ACCELERATION,
             unbalance=UNBALANCE, Omega=ANGULAR_RATE, f_exc=CYCLE_RATE, x0=LENGTH,
             v0=VELOCITY, t=TIME)
def forced_response(k=None, m=None, omega=None, zeta=None, c=None, Q=None, F0=None, base=None,
                    base_accel=None, unbalance=None, Omega=None, f_exc=None, x0=None, v0=None,
                    t=None) -> Outcome:
    """Steady and total response of ``m x'' + c x' + k x = F(t)`` to one harmonic excitation.

    .. math:: X = X_{st}\\,V,\\quad
              V = \\frac{1}{\\sqrt{(1-\\eta^2)^2 + (2\\zeta\\eta)^2}},\\quad
              TR = V\\sqrt{1 + (2\\zeta\\eta)^2}

    with the static reference ``X_st = F0/k`` (force), ``m B0/k`` (base acceleration),
    ``m_u e/m`` (unbalance, ``V = eta^2/D``), and ``X = u0 TR`` (base motion); see the
    module's table and :func:`magnification`, :func:`phase`, :func:`peak`,
    :func:`half_power`.

    Parameters
    ----------
    k : Quantity, optional
        Stiffness ``[force]/[length]`` (with ``m``); or ``omega`` ``[angle]/[time]``.
    m : Quantity, optional
        Mass ``[mass]`` (the whole machine's for unbalance).
    zeta, c, Q : optional
        Damping: ratio (``>= 0``), coefficient ``[force]*[time]/[length]``, or quality factor
        ``Q = 1/(2 zeta)``; default undamped.
    F0, base, base_accel, unbalance : Quantity, at most one
        Without one, only ``TR``, ``Omega_iso``, ``isolation`` and ``Q`` (which do not
        depend on it). Force amplitude ``[force]``, base displacement amplitude ``[length]``, ground
        acceleration amplitude ``[length]/[time]^2``, unbalance ``m_u e`` ``[mass]*[length]``.
    Omega, f_exc : Quantity, exactly one
        Excitation angular frequency ``[angle]/[time]`` or frequency ``[cycles]/[time]``.
    x0, v0, t : Quantity, optional
        Initial displacement ``[length]``, velocity ``[length]/[time]`` and the time
        ``[time]`` of the total response ``x``.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``zeta``, ``eta``, ``X`` (m), ``phi`` (rad), ``V``,
    ``TR``, ``F_T`` (N), ``Z`` (m, base excitations), ``X_res``, ``V_res``, ``Omega_peak``,
    ``X_peak``, ``V_peak``, ``Omega_iso``, ``isolation`` (when ``TR < 1``), ``bandwidth``
    (rad/s), ``Q`` and, with ``t``, ``x`` (m) -- each where it exists and the inputs allow.

    Raises
    ------
    PhysicsError
        Undamped at resonance without ``t``: the steady state does not exist.

    Examples
    --------
    A 40 kg machine with a 1500 rpm unbalance of 0.01 kg m on a 0.5 MN/m mount, 5 % damping:

    >>> from dyncalc.units import Q_
    >>> out = forced_response(k=Q_(0.5, "MN/m"), m=Q_(40, "kg"), zeta=0.05,
    ...                       unbalance=Q_(0.01, "kg*m"), Omega=Q_(1500, "rpm"))
    >>> round(out.values["eta"], 12), round(out.values["TR"], 9)
    (1.404962946208, 1.026238537)
    """
    k_, m_, w_ = _si(k, "N/m"), _si(m, "kg"), _si(omega, "rad/s")
    if k_ is not None:
        if m_ is None:
            raise InputError("k needs m too: omega = sqrt(k/m)")
        w_ = sqrt_ratio(k_, m_)
    elif w_ is None:
        raise InputError("give the natural frequency as k and m, or as omega")
    elif m_ is not None:
        k_ = m_ * w_ * w_
    zeta_ = _damping_ratio(zeta, c, Q, k_, m_, w_)
    if Omega is not None:
        W = magnitude(Omega, "rad/s")
    elif f_exc is not None:
        W = 2.0 * math.pi * magnitude(f_exc, "Hz")
    else:
        raise InputError("give the excitation frequency as Omega or f_exc")
    kind, amplitude = _excitation(F0, base, base_accel, unbalance)
    gap = (resonance_gap(W, k=_si(k, "N/m"), m=m_) if k is not None
           else resonance_gap(W, omega=w_))
    eta = W / w_
    at_resonance = zeta_ == 0.0 and abs(gap) <= RESONANCE_GAP
    time = _si(t, "s")
    if time is None and (x0 is not None or v0 is not None):
        raise InputError("x0 and v0 give the total response at a time: give t too")
    values: dict = {"omega": w_, "zeta": zeta_, "eta": eta}
    warnings: list[str] = []
    assumptions = ["linear spring and viscous damping; one degree of freedom"]
    if kind is None:  # the results that do not depend on the excitation
        return _unforced(values, gap, zeta_, eta, w_, assumptions)
    static = _static(kind, amplitude, k_, m_, w_, W)
    if at_resonance:
        if time is None:
            raise PhysicsError(
                f"undamped at resonance (Omega = omega = {w_:.6g} rad/s): the steady state "
                "does not exist, the amplitude grows without bound; give damping (zeta, c or "
                "Q), another excitation frequency, or a time t for the growing response")
        if static is None:
            raise InputError(f"the {kind} response needs the mass m")
        sign = -1.0 if kind == "base-accel" else 1.0
        at_omega = static * (eta * eta if kind == "unbalance" else 1.0)
        values["x"] = resonant_response(w_, sign * at_omega, _si(x0, "m") or 0.0,
                                        _si(v0, "m/s") or 0.0, time)
        warnings.append("undamped at resonance: no steady state; x grows linearly in time "
                        "(x_st omega t / 2) sin(omega t)")
        return Outcome(values, warnings=warnings, assumptions=assumptions)
    _steady(values, kind, amplitude, gap, zeta_, eta, w_, W, k_, m_, static, warnings)
    if time is not None:
        sign = -1.0 if kind == "base-accel" else 1.0
        if "X" in values:
            values["x"] = total_response(w_, zeta_, W, values["X"], values["phi"], sign,
                                         _si(x0, "m") or 0.0, _si(v0, "m/s") or 0.0, time)
    if zeta_ > 0.0:
        assumptions.append(f"steady state after the transient has died out: about "
                           f"4/(zeta omega) = {4.0 / (zeta_ * w_):.3g} s")
    else:
        assumptions.append("undamped: the free vibration started with the motion never dies "
                           "out; the steady state is the part at the excitation frequency")
    if kind == "base-accel":
        assumptions.append("X is the motion relative to the ground; phi its lag behind the "
                           "inertial force -m B0 cos(Omega t)")
    return Outcome(values, warnings=warnings, assumptions=assumptions)


def _unforced(values, gap, zeta, eta, w, assumptions) -> Outcome:
    """Without an excitation: ``TR``, ``Omega_iso``, ``isolation`` and ``Q``, which do not
    depend on it (an inverse problem such as ``TR=0.1 k=?``)."""
    if zeta == 0.0 and abs(gap) <= RESONANCE_GAP:
        raise PhysicsError(f"undamped at resonance (Omega = omega = {w:.6g} rad/s): TR is "
                           "unbounded")
    TR = transmissibility(gap, zeta, eta)
    values.update({"TR": TR, "Omega_iso": math.sqrt(2.0) * w})
    if TR < 1.0:
        values["isolation"] = 1.0 - TR
    if zeta > 0.0:
        values["Q"] = 0.5 / zeta
    return Outcome(values, assumptions=assumptions)


def _damping_ratio(zeta, c, Q, k_, m_, w_) -> float:
    if c is not None:
        if m_ is None:
            raise InputError("c needs the mass m: zeta = c / (2 m omega)")
        c_ = magnitude(c, "N*s/m")
        return c_ / (2.0 * math.sqrt(k_) * math.sqrt(m_)) if k_ is not None else \
            c_ / (2.0 * m_ * w_)
    if Q is not None:
        return 0.5 / magnitude(Q, "")
    return 0.0 if zeta is None else magnitude(zeta, "")


def _excitation(F0, base, base_accel, unbalance) -> tuple[str, float]:
    given = [(kind, value, unit) for kind, value, unit in
             (("force", F0, "N"), ("base", base, "m"), ("base-accel", base_accel, "m/s**2"),
              ("unbalance", unbalance, "kg*m")) if value is not None]
    if len(given) > 1:
        raise InputError("give exactly one excitation: F0, base, base_accel or unbalance")
    if not given:
        return None, None
    kind, value, unit = given[0]
    return kind, magnitude(value, unit)


def _static(kind, amplitude, k_, m_, w_, W) -> float | None:
    """The reference amplitude ``X/V``: ``F0/k``, ``u0``, ``B0/omega^2``, ``m_u e/m``."""
    if kind == "force":
        return amplitude / k_ if k_ is not None else None
    if kind == "base":
        return amplitude
    if kind == "base-accel":
        return amplitude / w_ / w_
    return amplitude / m_ if m_ is not None else None


def _steady(values, kind, amplitude, gap, zeta, eta, w, W, k, m, static, warnings) -> None:
    """The steady-state results, into ``values``."""
    V = magnification(kind, gap, zeta, eta)
    TR = transmissibility(gap, zeta, eta)
    if static is not None:
        values["X"] = static * V
    values["phi"] = phase(kind, gap, zeta, eta)
    values["V"] = V
    values["TR"] = TR
    if kind == "force":
        values["F_T"] = amplitude * TR
    elif kind == "unbalance":
        values["F_T"] = amplitude * W * W * TR
        if gap == -math.inf:
            # Omega^2 beyond float64 while TR -> 0: m_u e Omega^2 TR = m_u e Omega omega (eta TR)
            values["F_T"] = amplitude * W * (w * _far_ratio(zeta, eta))
    elif m is not None:
        values["F_T"] = m * W * W * values["X"] if kind == "base" else m * amplitude * TR
    if kind == "base":
        values["Z"] = amplitude * eta * (eta / math.hypot(gap, 2.0 * zeta * eta))
    elif kind == "base-accel":
        values["Z"] = values["X"]
    missing = [n for n in ("X", "F_T") if n not in values]
    if missing:
        warnings.append(f"{' and '.join(missing)} need the mass: give m (with omega, or k "
                        "and m)")
    if zeta > 0.0:
        V_res = magnification(kind, 0.0, zeta, 1.0)
        if static is not None:
            values["X_res"] = static * V_res
        values["V_res"] = V_res
        top = peak(kind, zeta)
        if top is not None:
            values["Omega_peak"] = top[0] * w
            if static is not None:
                values["X_peak"] = static * top[1]
            values["V_peak"] = top[1]
        else:
            warnings.append(no_peak_warning(kind, zeta))
    else:
        warnings.append(UNDAMPED_WARNING)
    values["Omega_iso"] = math.sqrt(2.0) * w
    if TR < 1.0:
        values["isolation"] = 1.0 - TR
    if zeta > 0.0:
        low, high, width = half_power(kind, zeta)
        if width is not None:
            values["bandwidth"] = width * w
        elif (text := half_power_warning(zeta, low, high, w)) is not None:
            warnings.append(text)
        values["Q"] = 0.5 / zeta
