"""Forced set-ups of the catalog (../shared/SCENES.md): each one's own parameters turned into the
single-degree-of-freedom oscillator of :mod:`dyncalc.physics.forced`, or its own closed form.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Examples 5.21-5.24.
"""
from __future__ import annotations

import math
from fractions import Fraction

from ..errors import PhysicsError
from ..units import (ACCELERATION, ANGULAR_RATE, CYCLE_RATE, DAMPING, DIMENSIONLESS, LENGTH,
                     MASS, STIFFNESS, TIME, VELOCITY)
from .face import check_units, magnitude
from .forced import SQRT_HALF, forced_response
from .numerics import sqrt_ratio
from .outcome import Outcome

__all__ = ["quarter_car_forced", "frame_brace_forced", "mass_spring_given_response",
           "rolling_wheel_moving_ground"]


@check_units(k=STIFFNESS, m=MASS, L=LENGTH, U0=LENGTH, v0=VELOCITY, c=DAMPING)
def quarter_car_forced(k, m, L, U0, v0, zeta=None, c=None, Q=None) -> Outcome:
    """A quarter-car on a wavy road, with damping: base motion ``u0 = U0`` at
    ``Omega = 2 pi v0 / L``.

    .. math:: m x'' + c x' + k x = k u + c u', \\quad u = U_0\\cos\\Omega t, \\quad
              \\Omega = \\frac{2\\pi v_0}{L}, \\quad v_{crit} = \\frac{L}{2\\pi}\\sqrt{k/m}

    Parameters
    ----------
    k : Quantity
        Suspension stiffness ``[force]/[length]``.
    m : Quantity
        Body mass ``[mass]``.
    L, U0 : Quantity
        Road wavelength and amplitude ``[length]``.
    v0 : Quantity
        Speed ``[length]/[time]``.
    zeta, c, Q : optional
        Damping ratio, damper ``[force]*[time]/[length]`` or quality factor (default none).

    Returns
    -------
    The :func:`~dyncalc.physics.forced.forced_response` results for base motion, with
    ``Omega`` (rad/s), ``x_amp = X`` (m) and ``v_crit`` (m/s).

    Examples
    --------
    E5.23 of [1] set up with numbers of our own; undamped it is the quarter-car scene:

    >>> from dyncalc.units import Q_
    >>> out = quarter_car_forced(Q_(40, "kN/m"), Q_(400, "kg"), Q_(10, "m"), Q_(2, "cm"),
    ...                          Q_(20, "m/s"))
    >>> round(out.values["x_amp"], 15)
    0.034534160684074
    """
    L_, v_ = magnitude(L, "m"), magnitude(v0, "m/s")
    W = 2.0 * math.pi * v_ / L_
    out = forced_response(k=k, m=m, zeta=zeta, c=c, Q=Q, base=U0, Omega=W)
    values = {"omega": out.values["omega"], "Omega": W}
    values.update((n, v) for n, v in out.values.items() if n != "omega")
    values["x_amp"] = out.values["X"]
    values["v_crit"] = L_ * out.values["omega"] / (2.0 * math.pi)
    return Outcome(values, warnings=out.warnings, assumptions=out.assumptions)


@check_units(m=MASS, k=STIFFNESS, d=DAMPING, b0=ACCELERATION, Omega=ANGULAR_RATE,
             f_exc=CYCLE_RATE)
def frame_brace_forced(m, k, d, b0, Omega=None, f_exc=None) -> Outcome:
    """The braced frame of E5.21 driven at one frequency: the brace at 45 degrees gives the
    oscillator ``m y'' + (d/2) y' + (k/2) y = -m b0 cos(Omega t)``, base acceleration ``b0``
    on ``k/2`` and ``d/2``.

    .. math:: y_0 = \\frac{2 m b_0}{k}, \\quad
              y_{max} = \\frac{y_0}{2\\zeta\\sqrt{1 - \\zeta^2}}\\ (\\zeta < 1/\\sqrt 2)

    Parameters
    ----------
    m : Quantity
        Mass of the beam ``[mass]``.
    k, d : Quantity
        Brace spring ``[force]/[length]`` and dashpot ``[force]*[time]/[length]``.
    b0 : Quantity
        Ground acceleration amplitude ``[length]/[time]^2``.
    Omega, f_exc : Quantity, one of them
        Excitation frequency.

    Returns
    -------
    The base-acceleration results of :func:`~dyncalc.physics.forced.forced_response`, with
    ``y0`` (m) and ``y_max`` (m), the largest amplitude over every frequency.

    Examples
    --------
    E5.21 of [1]: 500 kg, 200 kN/m, 2 kN s/m, 1 m/s^2:

    >>> from dyncalc.units import Q_
    >>> out = frame_brace_forced(Q_(500, "kg"), Q_(200, "kN/m"), Q_(2, "kN*s/m"),
    ...                          Q_(1, "m/s^2"), Omega=Q_(10, "rad/s"))
    >>> round(out.values["y_max"], 12)
    0.03544406025
    """
    k_, d_ = magnitude(k, "N/m"), magnitude(d, "N*s/m")
    out = forced_response(k=0.5 * k_, m=m, c=0.5 * d_, base_accel=b0, Omega=Omega,
                          f_exc=f_exc)
    values = dict(out.values)
    y0 = 2.0 * magnitude(m, "kg") * magnitude(b0, "m/s**2") / k_
    values["y0"] = y0
    if "X_peak" in values:
        values["y_max"] = values["X_peak"]
    elif values["zeta"] >= SQRT_HALF:
        values["y_max"] = y0
    return Outcome(values, warnings=out.warnings, assumptions=out.assumptions)


@check_units(m=MASS, k=STIFFNESS, x0=LENGTH, t0=TIME, T=TIME, c=DIMENSIONLESS, t=TIME)
def mass_spring_given_response(m, k, x0, t0, T, c, t) -> Outcome:
    """The force that makes an undamped mass-spring follow a prescribed motion (E5.22).

    .. math:: x = x_0\\left[\\cos\\frac{t}{2t_0} + c\\left(1 - \\cos\\frac{t - T}{2t_0}\\right)
              H(t - T)\\right], \\quad F = m x'' + k x, \\quad q = k - \\frac{m}{4t_0^2}

    so ``F = q x0 cos(t/(2 t0))`` before ``T`` and ``F = q x0 cos(t/(2 t0)) + c x0 (k - q
    cos((t - T)/(2 t0)))`` from ``T`` on (the value after the jump at ``T``). ``q`` is formed
    exactly from the float inputs (``k = m/(4 t0^2)`` gives exactly 0).

    Parameters
    ----------
    m : Quantity
        Mass ``[mass]``.
    k : Quantity
        Stiffness ``[force]/[length]``.
    x0 : Quantity
        Amplitude of the prescribed motion ``[length]``.
    t0, T, t : Quantity
        Time scale, time of the step and time asked for ``[time]``.
    c : float
        Step factor.

    Returns
    -------
    Outcome with ``omega`` (rad/s, the block's natural frequency ``sqrt(k/m)``), ``F`` (N)
    and ``x`` (m).

    Examples
    --------
    E5.22 of [1]: m = 4 kg, k = 1 N/m, t0 = 1 s: no force before T, then c k x0:

    >>> out = mass_spring_given_response(4.0, 1.0, 1.0, 1.0, 2.0, 20.0, 1.0)
    >>> out.values["F"]
    0.0
    >>> mass_spring_given_response(4.0, 1.0, 1.0, 1.0, 2.0, 20.0, 5.0).values["F"]
    20.0
    """
    m_, k_, x_ = magnitude(m, "kg"), magnitude(k, "N/m"), magnitude(x0, "m")
    t0_, T_, t_ = magnitude(t0, "s"), magnitude(T, "s"), magnitude(t, "s")
    c_ = magnitude(c, "")
    q = float(Fraction(k_) - Fraction(m_) / (4 * Fraction(t0_) ** 2))
    first = math.cos(t_ / (2.0 * t0_))
    x = x_ * first
    F = q * x_ * first
    if t_ >= T_:
        later = math.cos((t_ - T_) / (2.0 * t0_))
        x += x_ * c_ * (1.0 - later)
        F += c_ * x_ * (k_ - q * later)
    return Outcome({"omega": sqrt_ratio(k_, m_), "F": F, "x": x},
                   assumptions=["undamped linear spring; x is prescribed and F computed "
                                "from m x'' + k x"])


@check_units(m=MASS, k=STIFFNESS, u0=LENGTH, Omega=ANGULAR_RATE, g=ACCELERATION)
def rolling_wheel_moving_ground(m, k, u0, Omega, kappa=0.5, g=9.80665) -> Outcome:
    """A wheel rolling on ground that moves as ``u0 cos(Omega t)``, held by a spring to a wall
    (E5.24).

    .. math:: (1 + \\kappa) m x'' + k x = -\\kappa m u_0 \\Omega^2 \\cos\\Omega t, \\quad
              x_0 = \\frac{\\kappa m u_0 \\Omega^2}{(1 + \\kappa) m \\Omega^2 - k}, \\quad
              H_{max} = |k - m\\Omega^2|\\,|x_0|, \\quad \\mu_0 = \\frac{H_{max}}{m g}

    Both differences are formed exactly from the float inputs.

    Parameters
    ----------
    m : Quantity
        Mass of the wheel ``[mass]``.
    k : Quantity
        Spring stiffness ``[force]/[length]``.
    u0 : Quantity
        Ground amplitude ``[length]``.
    Omega : Quantity
        Ground angular frequency ``[angle]/[time]``.
    kappa : float
        Shape factor ``J_C/(m r^2)`` (a disk 1/2).
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``x_amp`` (m), ``phi`` (0: in phase with the ground, pi:
    against it), ``H_max`` (N), ``mu0``.

    Raises
    ------
    PhysicsError
        At resonance, ``Omega^2 = k/((1 + kappa) m)``.

    Examples
    --------
    A 2 kg disk, 300 N/m, ground 1 cm at 20 rad/s; the book's form for a disk
    ``|x0| = u0 / (3 |2k/(3 m Omega^2) - 1|)``:

    >>> out = rolling_wheel_moving_ground(2.0, 300.0, 0.01, 20.0)
    >>> round(out.values["x_amp"], 15), round(0.01 / (3 * abs(2 * 300 / (3 * 2 * 400) - 1)), 15)
    (0.004444444444444, 0.004444444444444)
    """
    m_, k_, u_ = magnitude(m, "kg"), magnitude(k, "N/m"), magnitude(u0, "m")
    W, g_, kap = magnitude(Omega, "rad/s"), magnitude(g, "m/s**2"), float(kappa)
    W2 = Fraction(W) ** 2
    den = (1 + Fraction(kap)) * Fraction(m_) * W2 - Fraction(k_)
    omega = sqrt_ratio(k_, (1.0 + kap) * m_)
    if den == 0 or abs(den) <= Fraction(8.0 * 2.0 ** -52) * Fraction(k_):  # exact: no overflow
        raise PhysicsError(f"Omega = {W:.6g} rad/s is the natural frequency sqrt(k/((1 + kappa) "
                           "m)): the undamped amplitude is unbounded; choose another Omega")
    x0 = float(Fraction(kap) * Fraction(m_) * Fraction(u_) * W2 / den)
    try:  # the product in fractions: |k - m Omega^2| alone may exceed float64 (Omega ~ 1e161)
        h_max = float(abs(Fraction(k_) - Fraction(m_) * W2) * abs(Fraction(x0)))
    except OverflowError:
        h_max = math.inf
    return Outcome({"omega": omega, "x_amp": abs(x0), "phi": 0.0 if x0 >= 0 else math.pi,
                    "H_max": h_max, "mu0": h_max / (m_ * g_)},
                   assumptions=["rolling without slipping; linear spring; steady state "
                                "(undamped)"])
