"""Damped oscillators with their own dampers: the damping scenes of SCENES.md.

Pure functions on pint quantities returning an :class:`~dyncalc.physics.outcome.Outcome`. Every
product or quotient of inputs is formed from binary mantissas and exponents
(:func:`~dyncalc.physics.numerics.monomial` and :func:`_root`), so nothing overflows or
underflows on the way unless the result itself does; the damping ratio is formed directly from
the inputs, never as a quotient of two results that may have overflowed.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapter 5.
"""
from __future__ import annotations

import math

from ..errors import PhysicsError
from ..units import Q_
from .numerics import monomial, root_monomial
from .outcome import Outcome, damped, periodic

__all__ = ["pendulum_spring_dashpot", "rod_in_fluid", "frame_brace_damper",
           "small_damping_error", "FRAME_METHODS"]

#: The methods frame-brace-damper offers besides ``auto``.
FRAME_METHODS = ("exact", "small-damping")

#: Below this damping ratio the steady amplitude has a resonance peak (above it the largest
#: amplitude is the static one).
_PEAK_LIMIT = math.sqrt(0.5)


def _si(quantity, unit: str) -> float:
    """The magnitude of ``quantity`` in ``unit`` (pint refuses a wrong dimension here)."""
    return float(quantity.to(unit).magnitude)


def _hypot(a: float, b: float) -> float:
    try:
        return math.hypot(a, b)
    except OverflowError:
        return math.inf


def _refuse_overflow(values: dict, scene: str) -> None:
    """A result that overflows float64 is refused (SPEC.md), naming the results."""
    bad = [name for name, v in values.items()
           if math.isinf(float(v.magnitude if hasattr(v, "magnitude") else v))]
    if bad:
        verb = "overflows" if len(bad) == 1 else "overflow"
        raise PhysicsError(f"{scene}: {', '.join(bad)} {verb} float64 for these inputs "
                           "(above 1.8e308 in SI units)")


def pendulum_spring_dashpot(m, a, k, d, g) -> Outcome:
    """Pendulum with a point mass at 2a, a spring at 2a and a dashpot at a from the pivot.

    .. math::
        \\omega^2 = \\frac{k}{m} + \\frac{g}{2a}, \\qquad \\xi = \\frac{d}{8m}, \\qquad
        \\zeta = \\frac{\\xi}{\\omega} = \\frac{d}{8\\sqrt{k m + g m^2/(2a)}}

    from ``4 m a^2 phi'' + d a^2 phi' + (4 k a^2 + 2 m g a) phi = 0`` (moments about the
    pivot, small angles).

    Parameters
    ----------
    m : Quantity
        Point mass at distance ``2a`` below the pivot ``[mass]``.
    a : Quantity
        Pivot to the dashpot; the mass and the spring sit at ``2a`` ``[length]``.
    k : Quantity
        Stiffness of the horizontal spring ``[force]/[length]``.
    d : Quantity
        Dashpot coefficient, ``>= 0`` ``[force]*[time]/[length]``.
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s), ``xi`` (1/s), ``zeta`` and, when
    underdamped, ``omega_d``, ``f_d``, ``T_d``.

    Notes
    -----
    The rod is massless and the angles small. The pendulum oscillates iff
    ``d < 8 sqrt(k m + g m^2/(2a))``; at or above that a warning says it is over- (or
    critically) damped and no damped frequency is given.

    Examples
    --------
    Example 5.18 of [1] asks for the damping ratio at which the amplitude falls to a tenth in
    ten cycles (zeta = 0.037); here a dashpot of 6 N s/m on a 2 kg bob:

    >>> from dyncalc.units import Q_
    >>> out = pendulum_spring_dashpot(Q_(2, "kg"), Q_(0.5, "m"), Q_(200, "N/m"),
    ...                               Q_(6, "N*s/m"), Q_(9.80665, "m/s^2"))
    >>> out.values["xi"].magnitude  # 1/s
    0.375
    >>> round(out.values["zeta"], 6)
    0.035786
    """
    m_, a_, k_ = _si(m, "kg"), _si(a, "m"), _si(k, "N/m")
    d_, g_ = _si(d, "N*s/m"), _si(g, "m/s**2")
    omega = _hypot(root_monomial(1.0, [(k_, 1), (m_, -1)]), root_monomial(0.5, [(g_, 1), (a_, -1)]))
    if d_ == 0.0:
        xi = zeta = 0.0
    else:
        xi = monomial(0.125, [(d_, 1), (m_, -1)])
        # 1 / zeta = 8 sqrt(k m + g m^2 / (2a)) / d, each term scaled by d before it is squared
        scaled = _hypot(root_monomial(1.0, [(k_, 1), (m_, 1), (d_, -2)]),
                        root_monomial(0.5, [(g_, 1), (m_, 2), (a_, -1), (d_, -2)]))
        zeta = 0.125 / scaled if scaled > 0.0 else math.inf
    values = periodic(omega)
    values["xi"] = Q_(xi, "1/s")
    extra, notes = damped(omega, zeta)
    values.update(extra)
    _refuse_overflow(values, "pendulum-spring-dashpot")
    if notes:
        critical = 8.0 * _hypot(root_monomial(1.0, [(k_, 1), (m_, 1)]),
                                root_monomial(0.5, [(g_, 1), (m_, 2), (a_, -1)]))
        notes = [f"{note}; it oscillates only for d < 8 sqrt(k m + g m^2/(2a)) = "
                 f"{critical:.6g} N*s/m" for note in notes]
    return Outcome(values, warnings=notes)


def rod_in_fluid(m, l, beta, g) -> Outcome:
    """Uniform rod pivoted at its upper end, swinging in a fluid with linear drag.

    .. math::
        \\omega^2 = \\frac{3g}{2l}, \\qquad \\xi = \\frac{\\beta l}{2m}, \\qquad
        \\zeta = \\frac{\\xi}{\\omega} = \\frac{\\beta}{\\beta_{crit}}, \\qquad
        \\beta_{crit} = \\frac{m}{l}\\sqrt{\\frac{6g}{l}}

    from ``(m l^2/3) phi'' + (beta l^3/3) phi' + (m g l/2) phi = 0``: the drag on an element
    ``dx`` at distance ``x`` is ``beta x phi' dx``, its moment ``beta x^2 phi' dx``.

    Parameters
    ----------
    m : Quantity
        Mass of the rod ``[mass]``.
    l : Quantity
        Length of the rod ``[length]``.
    beta : Quantity
        Drag force per unit length per unit velocity, ``>= 0`` ``[force]*[time]/[length]^2``.
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega``, ``f``, ``T``, ``xi`` (1/s), ``zeta``, ``beta_crit`` (N s/m^2)
    and, when underdamped, ``omega_d``, ``f_d``, ``T_d``.

    Notes
    -----
    Small angles; buoyancy and the fluid's added mass are neglected; the drag is linear in the
    local velocity. The rod oscillates iff ``beta < beta_crit``.

    Examples
    --------
    Example 5.14 of [1] asks for the critical drag coefficient (m/l) sqrt(6 g/l):

    >>> from dyncalc.units import Q_
    >>> out = rod_in_fluid(Q_(1.5, "kg"), Q_(0.8, "m"), Q_(2, "N*s/m^2"),
    ...                    Q_(9.80665, "m/s^2"))
    >>> round(out.values["beta_crit"].magnitude, 9)  # N s/m^2
    16.080229454
    >>> round(out.values["zeta"], 9)
    0.124376335
    """
    m_, l_, beta_, g_ = _si(m, "kg"), _si(l, "m"), _si(beta, "N*s/m**2"), _si(g, "m/s**2")
    omega = root_monomial(1.5, [(g_, 1), (l_, -1)])
    xi = monomial(0.5, [(beta_, 1), (l_, 1), (m_, -1)]) if beta_ else 0.0
    zeta = root_monomial(1.0 / 6.0, [(beta_, 2), (l_, 3), (g_, -1), (m_, -2)])
    beta_crit = Q_(root_monomial(6.0, [(g_, 1), (m_, 2), (l_, -3)]), "N*s/m**2")
    extra, notes = damped(omega, zeta)
    values = {**periodic(omega), "xi": Q_(xi, "1/s"), "zeta": extra.pop("zeta"),
              "beta_crit": beta_crit, **extra}
    _refuse_overflow(values, "rod-in-fluid")
    if notes:
        notes = [f"{note}; it oscillates only for beta < beta_crit = "
                 f"{beta_crit.magnitude:.6g} N*s/m^2" for note in notes]
    return Outcome(values, warnings=notes)


def small_damping_error(zeta: float) -> float:
    """Relative error of the small-damping peak ``y0/(2 zeta)`` against the exact one.

    Below ``zeta = 1/sqrt(2)`` the exact peak is ``y0 / (2 zeta sqrt(1 - zeta^2))``, so the
    error is ``1 - sqrt(1 - zeta^2) = zeta^2 / (1 + sqrt((1 - zeta)(1 + zeta)))`` (the form
    without cancellation); above, the exact peak is ``y0`` and the error ``1 - 1/(2 zeta)``.
    The small-damping value is always the lower one.

    >>> small_damping_error(0.0)
    0.0
    >>> round(small_damping_error(0.1), 12)  # 1 - sqrt(0.99)
    0.005012562893
    """
    if zeta < _PEAK_LIMIT:
        return zeta * zeta / (1.0 + math.sqrt((1.0 - zeta) * (1.0 + zeta)))
    return (2.0 * zeta - 1.0) / (2.0 * zeta)


def frame_brace_damper(m, k, d, b0, method: str = "auto", rtol: float = 1e-9) -> Outcome:
    """Frame (a beam on massless columns) braced by a diagonal spring and dashpot at 45 degrees,
    its ground shaken with acceleration amplitude ``b0``.

    .. math::
        \\omega^2 = \\frac{k}{2m}, \\qquad \\zeta = \\frac{d}{2}\\sqrt{\\frac{1}{2 k m}},
        \\qquad y_0 = \\frac{2 m b_0}{k}, \\qquad
        y_{max} = \\frac{y_0}{2\\zeta\\sqrt{1-\\zeta^2}} \\;(\\zeta < 1/\\sqrt 2),
        \\quad y_0 \\;\\text{otherwise}

    from ``m y'' + (d/2) y' + (k/2) y = -m b0 cos(Omega t)``, ``y`` the beam's displacement
    relative to the ground (a brace at 45 degrees stretches by ``y/sqrt 2`` and pulls
    horizontally with ``1/sqrt 2`` of its force). The steady amplitude is
    ``y0 / sqrt((1 - eta^2)^2 + (2 zeta eta)^2)``, ``eta = Omega/omega``; ``y_max`` is its
    largest value over all forcing frequencies.

    Parameters
    ----------
    m : Quantity
        Mass of the beam ``[mass]``.
    k : Quantity
        Stiffness of the brace spring ``[force]/[length]``.
    d : Quantity
        Coefficient of the brace dashpot, ``>= 0`` ``[force]*[time]/[length]``.
    b0 : Quantity
        Amplitude of the ground acceleration ``[length]/[time]^2``.
    method : {"auto", "exact", "small-damping"}
        ``small-damping`` takes the cheaper ``y_max = y0/(2 zeta)``; ``auto`` takes it only when
        its relative error (:func:`small_damping_error`) meets ``rtol``, else ``exact``.
    rtol : float
        Relative tolerance on ``y_max``.

    Returns
    -------
    Outcome with ``omega``, ``f``, ``T``, ``zeta``, (underdamped) ``omega_d``, ``f_d``,
    ``T_d``, ``y0`` (m), ``y_max`` (m); ``error_estimate`` is the relative error of the
    small-damping ``y_max`` when that model is used.

    Notes
    -----
    Small deflections, massless columns. Without damping (``d = 0``) the steady amplitude is
    unbounded at resonance: ``y_max`` is then left out with a warning.

    Examples
    --------
    Example 5.21 of [1]; a 500 kg beam, a 200 kN/m brace with a 2 kN s/m dashpot and a ground
    acceleration amplitude of 1 m/s^2:

    >>> from dyncalc.units import Q_
    >>> out = frame_brace_damper(Q_(500, "kg"), Q_(200, "kN/m"), Q_(2, "kN*s/m"),
    ...                          Q_(1, "m/s^2"))
    >>> out.values["y0"].magnitude  # m
    0.005
    >>> round(out.values["y_max"].magnitude, 12)  # m
    0.03544406025
    >>> out.method
    'exact'
    """
    m_, k_, d_, b0_ = _si(m, "kg"), _si(k, "N/m"), _si(d, "N*s/m"), _si(b0, "m/s**2")
    omega = root_monomial(0.5, [(k_, 1), (m_, -1)])
    zeta = root_monomial(0.125, [(d_, 2), (k_, -1), (m_, -1)])
    extra, warnings = damped(omega, zeta)
    y0 = Q_(monomial(2.0, [(m_, 1), (b0_, 1), (k_, -1)]), "m")
    values = {**periodic(omega), **extra, "y0": y0}
    _refuse_overflow(values, "frame-brace-damper")

    error = small_damping_error(zeta)
    if method == "auto":
        method = "small-damping" if error <= rtol else "exact"
    # y0 / (2 zeta) = sqrt(8 m^3 b0^2 / (k d^2)), straight from the inputs
    small = root_monomial(8.0, [(m_, 3), (b0_, 2), (k_, -1), (d_, -2)]) if d_ else math.inf
    where = f"at zeta = {zeta:.6g}"
    if method == "small-damping":
        y_max = small
        estimate = error
        assumptions = [f"small damping: y_max = y0/(2 zeta), {100 * error:.3g}% low {where}"]
        if error > rtol:
            warnings.append(f"the small-damping model misses the requested tolerance {rtol:g}: "
                            f"its y_max is {100 * error:.3g}% low {where}; use --method exact")
    else:
        if zeta < _PEAK_LIMIT:
            y_max = small / math.sqrt((1.0 - zeta) * (1.0 + zeta))
            peak = "the peak of the steady amplitude, at Omega = omega sqrt(1 - 2 zeta^2)"
        else:
            y_max = y0.magnitude
            peak = ("zeta >= 1/sqrt(2): no resonance peak, the largest steady amplitude is the "
                    "static one (Omega -> 0)")
        estimate = None
        assumptions = [f"y_max is {peak}"]
    if math.isinf(y_max):
        why = ("without damping (d = 0) the steady amplitude grows without bound at resonance "
               "(Omega = omega)" if d_ == 0.0 else
               f"the resonance peak overflows float64 {where}")
        warnings.append(f"{why}; y_max is not given")
    else:
        values["y_max"] = Q_(y_max, "m")
    return Outcome(values, model="linear", method=method, error_estimate=estimate,
                   warnings=warnings, assumptions=assumptions)
