"""Damped oscillators with their own dampers: the damping scenes of docs/scenes.md.

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

from ..lazy import numpy as np
from ..units import Q_
from ..units import ACCELERATION, ANGULAR_RATE, DAMPING, LENGTH, LINEAR_DRAG, MASS, STIFFNESS
from .face import check_units, magnitude
from .columns import Columns, column_kernel
from .numerics import (Wide, finite_nonzero, monomial, root_monomial, sqrt_ratio,
                       sqrt_ratio_array, two_product)
from .numerics_arrays import hypot_array, monomial_array, root_monomial_array
from .outcome import (CRITICAL_BAND, Outcome, damped, damped_arrays, periodic,
                      periodic_arrays)

__all__ = ["pendulum_spring_dashpot", "rod_in_fluid", "frame_brace_damper",
           "small_damping_error", "FRAME_METHODS", "TWO_PI", "CRITICAL_BAND", "REGIMES",
           "zeta_from_decrement", "decrement_from_zeta", "decrement_from_ratio",
           "damping_from_coefficients", "damping_from_decrement", "damping_from_zeta",
           "free_response"]

#: The methods frame-brace-damper offers besides ``auto``.
FRAME_METHODS = ("exact", "small-damping")

#: Below this damping ratio the steady amplitude has a resonance peak (above it the largest
#: amplitude is the static one).
_PEAK_LIMIT = math.sqrt(0.5)




def _hypot(a: float, b: float) -> float:
    try:
        return math.hypot(a, b)
    except OverflowError:
        return math.inf


@check_units(m=MASS, a=LENGTH, k=STIFFNESS, d=DAMPING, g=ACCELERATION)
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
    m_, a_, k_ = magnitude(m, "kg"), magnitude(a, "m"), magnitude(k, "N/m")
    d_, g_ = magnitude(d, "N*s/m"), magnitude(g, "m/s**2")
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
    if notes:
        critical = 8.0 * _hypot(root_monomial(1.0, [(k_, 1), (m_, 1)]),
                                root_monomial(0.5, [(g_, 1), (m_, 2), (a_, -1)]))
        notes = [f"{note}; it oscillates only for d < 8 sqrt(k m + g m^2/(2a)) = "
                 f"{critical:.6g} N*s/m" for note in notes]
    return Outcome(values, warnings=notes)


def _damped_columns(values: dict, omega, zeta, extra: dict, damper) -> Columns:
    """The columns of a damped scene: ``values`` (``omega``, ``f``, ``T`` and the scene's
    ``extra`` results before ``zeta``) completed with :func:`damped_arrays`. Exact rows are
    underdamped (the one-off warns from ``zeta = 1`` on), with every result finite and non-zero
    but ``xi`` and ``zeta``, which are zero without a damper (``damper == 0``, no underflow)."""
    with np.errstate(all="ignore"):
        values.update(damped_arrays(omega, zeta))
    rates = {name: array for name, array in values.items()
             if name != "zeta" and name not in extra}
    extra_ok = True
    for array in extra.values():
        extra_ok = extra_ok & np.isfinite(array) & ((array != 0.0) | (damper == 0.0))
    exact = (finite_nonzero(rates) & (zeta < 1.0) & extra_ok
             & ((zeta != 0.0) | (damper == 0.0)))
    return Columns(values, exact=exact)


@column_kernel(pendulum_spring_dashpot)
def _pendulum_spring_dashpot_columns(m, a, k, d, g) -> Columns:
    """:func:`pendulum_spring_dashpot` on columns (``m`` in kg, ``a`` in m, ``k`` in N/m,
    ``d`` in N*s/m, ``g`` in m/s^2): the same monomials (:func:`root_monomial_array`) and
    ``math.hypot`` row by row."""
    damper = d != 0.0
    with np.errstate(all="ignore"):
        omega = hypot_array(root_monomial_array(1.0, [(k, 1), (m, -1)]),
                            root_monomial_array(0.5, [(g, 1), (a, -1)]))
        xi = np.where(damper, monomial_array(0.125, [(d, 1), (m, -1)]), 0.0)
        scaled = hypot_array(root_monomial_array(1.0, [(k, 1), (m, 1), (d, -2)]),
                             root_monomial_array(0.5, [(g, 1), (m, 2), (a, -1), (d, -2)]))
        zeta = np.where(damper, np.where(scaled > 0.0, 0.125 / np.where(scaled > 0.0, scaled,
                                                                        1.0), np.inf), 0.0)
    values = periodic_arrays(omega)
    values["xi"] = xi
    return _damped_columns(values, omega, zeta, {"xi": xi}, d)


@check_units(m=MASS, l=LENGTH, beta=LINEAR_DRAG, g=ACCELERATION)
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
    m_, l_ = magnitude(m, "kg"), magnitude(l, "m")
    beta_, g_ = magnitude(beta, "N*s/m**2"), magnitude(g, "m/s**2")
    omega = root_monomial(1.5, [(g_, 1), (l_, -1)])
    xi = monomial(0.5, [(beta_, 1), (l_, 1), (m_, -1)]) if beta_ else 0.0
    zeta = root_monomial(1.0 / 6.0, [(beta_, 2), (l_, 3), (g_, -1), (m_, -2)])
    beta_crit = Q_(root_monomial(6.0, [(g_, 1), (m_, 2), (l_, -3)]), "N*s/m**2")
    extra, notes = damped(omega, zeta)
    values = {**periodic(omega), "xi": Q_(xi, "1/s"), "zeta": extra.pop("zeta"),
              "beta_crit": beta_crit, **extra}
    if notes:
        notes = [f"{note}; it oscillates only for beta < beta_crit = "
                 f"{beta_crit.magnitude:.6g} N*s/m^2" for note in notes]
    return Outcome(values, warnings=notes)


@column_kernel(rod_in_fluid)
def _rod_in_fluid_columns(m, l, beta, g) -> Columns:
    """:func:`rod_in_fluid` on columns (``m`` in kg, ``l`` in m, ``beta`` in N*s/m^2, ``g`` in
    m/s^2), by the same monomials (:func:`monomial_array`, :func:`root_monomial_array`)."""
    with np.errstate(all="ignore"):
        omega = root_monomial_array(1.5, [(g, 1), (l, -1)])
        xi = np.where(beta != 0.0, monomial_array(0.5, [(beta, 1), (l, 1), (m, -1)]), 0.0)
        zeta = root_monomial_array(1.0 / 6.0, [(beta, 2), (l, 3), (g, -1), (m, -2)])
        beta_crit = root_monomial_array(6.0, [(g, 1), (m, 2), (l, -3)])
    values = periodic_arrays(omega)
    values["xi"] = xi
    columns = _damped_columns(values, omega, zeta, {"xi": xi}, beta)
    order = ("omega", "f", "T", "xi", "zeta", "beta_crit", "omega_d", "f_d", "T_d")
    values["beta_crit"] = beta_crit
    columns.values = {name: values[name] for name in order}
    columns.exact = columns.exact & np.isfinite(beta_crit) & (beta_crit != 0.0)
    return columns


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


def _small_damping_error_array(zeta):
    """:func:`small_damping_error` elementwise (the same operations)."""
    with np.errstate(all="ignore"):
        below = zeta * zeta / (1.0 + np.sqrt((1.0 - zeta) * (1.0 + zeta)))
        return np.where(zeta < _PEAK_LIMIT, below, (2.0 * zeta - 1.0) / (2.0 * zeta))


@check_units(m=MASS, k=STIFFNESS, d=DAMPING, b0=ACCELERATION)
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
    m_, k_ = magnitude(m, "kg"), magnitude(k, "N/m")
    d_, b0_ = magnitude(d, "N*s/m"), magnitude(b0, "m/s**2")
    omega = root_monomial(0.5, [(k_, 1), (m_, -1)])
    zeta = root_monomial(0.125, [(d_, 2), (k_, -1), (m_, -1)])
    extra, warnings = damped(omega, zeta)
    y0 = Q_(monomial(2.0, [(m_, 1), (b0_, 1), (k_, -1)]), "m")
    values = {**periodic(omega), **extra, "y0": y0}

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


@column_kernel(frame_brace_damper)
def _frame_brace_damper_columns(m, k, d, b0, method: str = "auto", rtol: float = 1e-9):
    """:func:`frame_brace_damper` on columns (``m`` in kg, ``k`` in N/m, ``d`` in N*s/m, ``b0``
    in m/s^2) for the ``exact`` peak; ``auto`` rows that the one-off gives the small-damping
    model (its error at most ``rtol``) are not exact. ``None`` for ``small-damping``: its
    error estimate differs from row to row, where a Columns carries one for all."""
    if method not in ("auto", "exact"):
        return None
    with np.errstate(all="ignore"):
        omega = root_monomial_array(0.5, [(k, 1), (m, -1)])
        zeta = root_monomial_array(0.125, [(d, 2), (k, -1), (m, -1)])
        y0 = monomial_array(2.0, [(m, 1), (b0, 1), (k, -1)])
        small = np.where(d != 0.0, root_monomial_array(8.0, [(m, 3), (b0, 2), (k, -1),
                                                              (d, -2)]), np.inf)
        y_max = np.where(zeta < _PEAK_LIMIT, small / np.sqrt((1.0 - zeta) * (1.0 + zeta)), y0)
    columns = _damped_columns(periodic_arrays(omega), omega, zeta, {}, d)
    columns.values.update(y0=y0, y_max=y_max)
    columns.exact = columns.exact & finite_nonzero({"y0": y0, "y_max": y_max})
    if method == "auto":
        columns.exact = columns.exact & (_small_damping_error_array(zeta) > rtol)
    columns.method = "exact"
    return columns


# --- the damping-ratio command: zeta from a measurement --------------------------------------

#: ``2 pi`` (the float nearest it; its relative error is 3.9e-17).
TWO_PI = 2.0 * math.pi

#: ``|1 - zeta^2|`` at or below ``CRITICAL_BAND`` counts as critical damping: defined with
#: :func:`dyncalc.physics.outcome.damped`, so that every command and scene names the regime
#: alike (issue 15: a scene called zeta = 1 "overdamped").

#: The regimes, in order of growing damping.
REGIMES = ("undamped", "underdamped", "critically damped", "overdamped")


def zeta_from_decrement(delta: float) -> float:
    """Damping ratio from the logarithmic decrement per cycle.

    .. math:: \\zeta = \\frac{\\delta}{\\sqrt{4\\pi^2 + \\delta^2}}
              = \\frac{\\delta}{\\operatorname{hypot}(2\\pi, \\delta)}

    ``hypot`` neither overflows for a huge decrement nor loses the small one: two roundings
    (within about 1.5 ulp) from 1e-300 to 1e300.

    >>> round(zeta_from_decrement(math.log(10) / 10), 9)  # E5.18: a tenth in ten cycles
    0.036622197
    >>> zeta_from_decrement(1e-12)  # delta / (2 pi)
    1.5915494309189534e-13
    """
    return delta / math.hypot(TWO_PI, delta)


def decrement_from_zeta(zeta: float) -> float:
    """Logarithmic decrement per cycle of an underdamped oscillator (``0 <= zeta < 1``).

    .. math:: \\delta = \\frac{2\\pi\\zeta}{\\sqrt{(1-\\zeta)(1+\\zeta)}}

    ``(1 - zeta)(1 + zeta)`` rather than ``1 - zeta^2``: for zeta a hair below 1 the
    difference ``1 - zeta`` is exact (Sterbenz) and the result keeps its digits.

    >>> round(decrement_from_zeta(0.036622197), 6)
    0.230259
    >>> decrement_from_zeta(0.0)
    0.0
    """
    return TWO_PI * zeta / math.sqrt((1.0 - zeta) * (1.0 + zeta))


def decrement_from_ratio(ratio: float, cycles: int) -> float:
    """Logarithmic decrement from the ratio ``x_i / x_(i+N)`` of two peaks ``N`` cycles apart.

    .. math:: \\delta = \\frac{\\ln R}{N}

    >>> decrement_from_ratio(math.e ** 2, 2)
    1.0
    """
    return math.log(ratio) / cycles


def _critical_wide(k: float, m: float) -> Wide:
    """``c_c = 2 sqrt(k m)`` as a :class:`Wide` (no overflow of ``k m``)."""
    return (Wide(4.0) * Wide(k) * Wide(m)).sqrt()


def _excess(c: float, k: float, m: float) -> tuple[float, int]:
    """``4 k m - c^2`` as ``(mantissa, exponent)``: the value is ``mantissa * 2**exponent``.

    Both products are formed exactly from the binary mantissas (:func:`two_product`) and the
    four exact parts are summed once (``math.fsum``): the sign is exact for the float inputs and
    the value is correctly rounded, however close ``c`` is to ``2 sqrt(k m)``. This is what keeps
    ``omega_d`` and ``delta`` accurate for zeta a hair below 1 (the naive ``1 - zeta^2`` from a
    rounded zeta loses ``log10(1/(1 - zeta))`` digits).
    """
    mk, ek = math.frexp(k)
    mm, em = math.frexp(m)
    mc, ec = math.frexp(c)
    p1, e1 = two_product(mk, mm)
    p2, e2 = two_product(mc, mc)
    a, b = ek + em + 2, 2 * ec  # 4 k m = (p1 + e1) 2**a, c^2 = (p2 + e2) 2**b
    top = max(a, b)
    parts = [math.ldexp(p1, a - top), math.ldexp(e1, a - top),
             -math.ldexp(p2, b - top), -math.ldexp(e2, b - top)]
    return math.fsum(parts), top


def _overdamped_note(zeta: float, regime: str) -> str:
    return (f"zeta = {zeta:.6g}: the system is {regime}; it does not oscillate, so there is no "
            "damped frequency, period or logarithmic decrement")


@check_units(c=DAMPING, k=STIFFNESS, m=MASS)
def damping_from_coefficients(c, k, m) -> Outcome:
    """Damping ratio and damped motion of a mass ``m`` on a spring ``k`` with a viscous
    damper ``c``: ``m x'' + c x' + k x = 0``.

    .. math::
        c_c = 2\\sqrt{k m}, \\quad \\zeta = \\frac{c}{c_c}, \\quad
        \\omega = \\sqrt{k/m}, \\quad \\omega_d = \\frac{\\sqrt{4 k m - c^2}}{2 m}, \\quad
        \\delta = \\frac{2\\pi c}{\\sqrt{4 k m - c^2}}, \\quad Q = \\frac{c_c}{2c},
        \\quad \\xi = \\frac{c}{2m}

    Parameters
    ----------
    c : Quantity
        Damping coefficient, ``>= 0`` ``[force]*[time]/[length]``.
    k : Quantity
        Stiffness, ``> 0`` ``[force]/[length]``.
    m : Quantity
        Mass, ``> 0`` ``[mass]``.

    Returns
    -------
    Outcome with ``zeta``, ``regime`` (a word), ``c_c`` and ``c`` (N s/m), ``omega`` (rad/s),
    ``xi`` (1/s), ``Q`` when ``c > 0``, and when underdamped ``delta``, ``omega_d``, ``f_d``,
    ``T_d``. A value beyond float64 is ``inf`` (the caller reports it).

    Notes
    -----
    Every product and root is formed from binary mantissas and exponents (:class:`Wide`), so
    inputs from 1e-300 to 1e300 neither overflow nor underflow on the way. ``4 k m - c^2`` is
    formed exactly (see :func:`_excess`), so ``omega_d`` and ``delta`` keep their digits for
    zeta a hair below 1. The regime follows from the sign of ``4 k m - c^2``; when
    ``|1 - zeta^2| <= CRITICAL_BAND`` (within the rounding of the inputs, for instance ``c``
    typed as the ``c_c`` printed for the same ``k`` and ``m``) the system is taken as
    critically damped, with ``zeta = 1`` exactly.

    Examples
    --------
    >>> from dyncalc.units import Q_
    >>> out = damping_from_coefficients(Q_(4, "N*s/m"), Q_(100, "N/m"), Q_(1, "kg"))
    >>> out.values["zeta"], out.values["regime"], out.values["c_c"]
    (0.2, 'underdamped', <Quantity(20.0, 'newton * second / meter')>)
    >>> damping_from_coefficients(Q_(20, "N*s/m"), Q_(100, "N/m"), Q_(1, "kg")).values["regime"]
    'critically damped'
    """
    c_, k_, m_ = magnitude(c, "N*s/m"), magnitude(k, "N/m"), magnitude(m, "kg")
    critical = _critical_wide(k_, m_)
    values: dict = {"c_c": Q_(float(critical), "N*s/m"), "c": Q_(c_, "N*s/m"),
                    "omega": Q_(sqrt_ratio(k_, m_), "rad/s")}
    notes: list[str] = []
    if c_ == 0.0:
        values.update(zeta=0.0, delta=0.0, regime="undamped", xi=Q_(0.0, "1/s"))
        values.update(periodic(values["omega"].magnitude, "_d"))
        notes.append("zeta = 0: undamped; Q is unbounded and not given")
        return _ordered(values, notes)
    excess, exponent = _excess(c_, k_, m_)
    # 1 - zeta^2 = (4 k m - c^2) / (4 k m), from the exact excess
    four_km = Wide(4.0) * Wide(k_) * Wide(m_)
    fraction = float(Wide(abs(excess), exponent) / four_km)
    values["xi"] = Q_(float(Wide(c_) / Wide(m_) * Wide(0.5)), "1/s")
    values["Q"] = float(critical / Wide(c_) * Wide(0.5))
    if fraction <= CRITICAL_BAND:
        values.update(zeta=1.0, regime="critically damped", Q=0.5)
        if excess != 0.0:
            notes.append(f"c differs from c_c = 2 sqrt(k m) by less than the rounding of the "
                         f"inputs (|1 - zeta^2| = {fraction:.2g} <= 2^-50): taken as critically "
                         "damped, zeta = 1")
        notes.append(_overdamped_note(1.0, "critically damped"))
        return _ordered(values, notes)
    zeta = float(Wide(c_) / critical)
    values["zeta"] = zeta
    if excess < 0.0:
        values["regime"] = "overdamped"
        notes.append(_overdamped_note(zeta, "overdamped"))
        return _ordered(values, notes)
    root = Wide(excess, exponent).sqrt()          # sqrt(4 k m - c^2)
    values["regime"] = "underdamped"
    values["delta"] = float(Wide(TWO_PI) * Wide(c_) / root)
    omega_d = root / Wide(m_) * Wide(0.5)
    values["omega_d"] = Q_(float(omega_d), "rad/s")
    values["f_d"] = Q_(float(omega_d / Wide(TWO_PI)), "Hz")
    values["T_d"] = Q_(float(Wide(TWO_PI) / omega_d), "s")
    return _ordered(values, notes)


def _excess_array(c, k, m):
    """The twin of :func:`_excess` on arrays (``numerics_arrays``): ``(mantissas, exponents)``
    of ``4 k m - c^2``, correctly rounded, bit for bit."""
    from ..lazy import numpy as np
    from .numerics_arrays import fsum_rows, ldexp_array, two_product_array

    mk, ek = np.frexp(k)
    mm, em = np.frexp(m)
    mc, ec = np.frexp(c)
    p1, e1 = two_product_array(mk, mm)
    p2, e2 = two_product_array(mc, mc)
    a = ek.astype(np.int64) + em + 2
    b = 2 * ec.astype(np.int64)
    top = np.maximum(a, b)
    parts = np.column_stack([ldexp_array(p1, a - top), ldexp_array(e1, a - top),
                             -ldexp_array(p2, b - top), -ldexp_array(e2, b - top)])
    total, _ok = fsum_rows(parts)  # the parts are finite: below 1 in magnitude
    return total, top


@column_kernel(damping_from_coefficients)
def _coefficients_columns(c, k, m) -> Columns:
    """:func:`damping_from_coefficients` on columns (N s/m, N/m, kg): the same
    :class:`~dyncalc.physics.numerics_arrays.WideArray` steps and the exact excess
    ``4 k m - c^2`` (:func:`_excess_array`), bit for bit. The values (names and order of the
    underdamped one-off) are exact on the underdamped rows; the undamped, critically damped
    and overdamped ones carry a note (and other values) and are left to the one-off."""
    from ..lazy import numpy as np
    from .numerics_arrays import WideArray as W

    c, k, m = (np.asarray(x, dtype=float) for x in (c, k, m))
    with np.errstate(all="ignore"):
        four_km = W(4.0) * W(k) * W(m)
        critical = four_km.sqrt()
        excess, exponent = _excess_array(c, k, m)
        fraction = (W(np.abs(excess), exponent) / four_km).to_float()
        root = W(np.abs(excess), exponent).sqrt()
        omega_d = root / W(m) * W(0.5)
        underdamped = (c > 0.0) & (excess > 0.0) & (fraction > CRITICAL_BAND)
        regime = np.where(c == 0.0, "undamped", np.where(
            fraction <= CRITICAL_BAND, "critically damped",
            np.where(excess < 0.0, "overdamped", "underdamped")))
        values = {"zeta": (W(c) / critical).to_float(),
                  "delta": (W(TWO_PI) * W(c) / root).to_float(),
                  "regime": regime,
                  "Q": (critical / W(c) * W(0.5)).to_float(),
                  "c_c": critical.to_float(), "c": c.copy(),
                  "omega": sqrt_ratio_array(k, m),
                  "xi": (W(c) / W(m) * W(0.5)).to_float(),
                  "omega_d": omega_d.to_float(),
                  "f_d": (omega_d / W(TWO_PI)).to_float(),
                  "T_d": (W(TWO_PI) / omega_d).to_float()}
    ordinary = np.isfinite(c) & np.isfinite(k) & np.isfinite(m) & (k > 0.0) & (m > 0.0)
    return Columns(values, exact=underdamped & ordinary)


@check_units(omega=ANGULAR_RATE, k=STIFFNESS, m=MASS)
def damping_from_decrement(delta: float, omega=None, k=None, m=None) -> Outcome:
    """Damping ratio and damped motion from a logarithmic decrement per cycle.

    .. math::
        h = \\sqrt{4\\pi^2 + \\delta^2}, \\quad \\zeta = \\frac{\\delta}{h}, \\quad
        \\sqrt{1-\\zeta^2} = \\frac{2\\pi}{h}, \\quad Q = \\frac{h}{2\\delta}, \\quad
        \\omega_d = \\frac{2\\pi\\omega}{h}, \\quad T_d = \\frac{h}{\\omega}

    Parameters
    ----------
    delta : float
        ``ln(x_i / x_(i+1))``, ``>= 0`` and finite.
    omega : Quantity, optional
        Undamped natural angular frequency ``[angle]/[time]``.
    k, m : Quantity, optional
        Stiffness and mass (both or neither; not with ``omega``): give ``omega = sqrt(k/m)``,
        ``c_c = 2 sqrt(k m)`` and ``c = zeta c_c``.

    Returns
    -------
    Outcome with ``zeta``, ``delta``, ``regime`` (``undamped`` for ``delta = 0``, else
    ``underdamped``: a decrement is only measured on an oscillation), ``Q`` when
    ``delta > 0``; with a natural frequency ``xi``, ``omega_d``, ``f_d``, ``T_d``; with k and m
    also ``omega``, ``c_c``, ``c``.

    Notes
    -----
    ``sqrt(1 - zeta^2)`` is taken as ``2 pi / h``, never from zeta, so the damped frequency of
    a huge decrement (zeta rounds to 1) is still right.

    Examples
    --------
    Example 5.18 of [1]: the amplitude falls to a tenth in ten cycles, zeta = 0.037:

    >>> out = damping_from_decrement(math.log(10) / 10)
    >>> round(out.values["zeta"], 6), out.values["regime"]
    (0.036622, 'underdamped')
    """
    h = math.hypot(TWO_PI, delta)
    values: dict = {"zeta": delta / h, "delta": float(delta),
                    "regime": "undamped" if delta == 0.0 else "underdamped"}
    notes: list[str] = []
    if delta > 0.0:
        values["Q"] = float(Wide(h) / Wide(delta) * Wide(0.5))
    else:
        notes.append("zeta = 0: undamped; Q is unbounded and not given")
    omega_si = None
    if omega is not None:
        omega_si = magnitude(omega, "rad/s")
    elif k is not None and m is not None:
        k_, m_ = magnitude(k, "N/m"), magnitude(m, "kg")
        omega_si = sqrt_ratio(k_, m_)
        critical = _critical_wide(k_, m_)
        values["omega"] = Q_(omega_si, "rad/s")
        values["c_c"] = Q_(float(critical), "N*s/m")
        values["c"] = Q_(float(critical * Wide(delta) / Wide(h)), "N*s/m")
    if omega_si is not None:
        values["xi"] = Q_(float(Wide(omega_si) * Wide(delta) / Wide(h)), "1/s")
        values["omega_d"] = Q_(float(Wide(omega_si) * Wide(TWO_PI) / Wide(h)), "rad/s")
        values["f_d"] = Q_(float(Wide(omega_si) / Wide(h)), "Hz")
        values["T_d"] = Q_(float(Wide(h) / Wide(omega_si)), "s")
    return _ordered(values, notes)


@column_kernel(damping_from_decrement)
def _decrement_columns(delta, omega=None, k=None, m=None) -> Columns:
    """:func:`damping_from_decrement` on columns: ``h = hypot(2 pi, delta)`` as
    ``math.hypot`` computes it (:func:`~dyncalc.physics.numerics_arrays.hypot_rows`) and the
    same :class:`~dyncalc.physics.numerics_arrays.WideArray` steps, bit for bit. Exact on
    rows with ``delta > 0`` (``delta = 0`` carries a note and no ``Q``)."""
    from ..lazy import numpy as np
    from .numerics_arrays import WideArray as W, hypot_rows

    delta = np.asarray(delta, dtype=float)
    with np.errstate(all="ignore"):
        h, ok = hypot_rows(np.full(delta.shape, TWO_PI), delta)
        values = {"zeta": delta / h, "delta": delta.copy(),
                  "regime": np.where(delta == 0.0, "undamped", "underdamped"),
                  "Q": (W(h) / W(delta) * W(0.5)).to_float()}
        omega_si = None
        if omega is not None:
            omega_si = np.asarray(omega, dtype=float)
        elif k is not None and m is not None:
            k, m = np.asarray(k, dtype=float), np.asarray(m, dtype=float)
            omega_si = sqrt_ratio_array(k, m)
            critical = (W(4.0) * W(k) * W(m)).sqrt()
            values["c_c"] = critical.to_float()
            values["c"] = (critical * W(delta) / W(h)).to_float()
            values["omega"] = omega_si
            ok &= np.isfinite(k) & np.isfinite(m) & (k > 0.0) & (m > 0.0)
        if omega_si is not None:
            values["xi"] = (W(omega_si) * W(delta) / W(h)).to_float()
            values["omega_d"] = (W(omega_si) * W(TWO_PI) / W(h)).to_float()
            values["f_d"] = (W(omega_si) / W(h)).to_float()
            values["T_d"] = (W(h) / W(omega_si)).to_float()
            ok &= np.isfinite(omega_si) & (omega_si > 0.0)
    return Columns(values, exact=ok & (delta > 0.0) & np.isfinite(delta))


def damping_from_zeta(zeta: float) -> Outcome:
    """Decrement, quality factor and regime of an oscillator of damping ratio ``zeta >= 0``.

    ``delta = 2 pi zeta / sqrt((1 - zeta)(1 + zeta))`` below critical damping,
    ``Q = 1/(2 zeta)`` for ``zeta > 0``. A zeta with ``|1 - zeta^2| <= CRITICAL_BAND`` is
    critical damping (``zeta`` is then returned as exactly 1).

    >>> out = damping_from_zeta(0.5)
    >>> round(out.values["delta"], 12), out.values["Q"], out.values["regime"]
    (3.627598728468, 1.0, 'underdamped')
    >>> damping_from_zeta(1.0 - 2.0 ** -52).values["regime"]
    'critically damped'
    """
    values: dict = {"zeta": float(zeta)}
    notes: list[str] = []
    if zeta == 0.0:
        values.update(delta=0.0, regime="undamped")
        notes.append("zeta = 0: undamped; Q is unbounded and not given")
        return Outcome(values, warnings=notes)
    fraction = abs((1.0 - zeta) * (1.0 + zeta))
    if fraction <= CRITICAL_BAND:
        values.update(zeta=1.0, regime="critically damped", Q=0.5)
        if zeta != 1.0:
            notes.append(f"zeta = {zeta!r} differs from 1 by less than the rounding of the "
                         f"inputs (|1 - zeta^2| = {fraction:.2g} <= 2^-50): taken as critically "
                         "damped, zeta = 1")
        return Outcome(values, warnings=notes)
    if zeta < 1.0:
        values.update(delta=decrement_from_zeta(zeta), regime="underdamped")
    else:
        values["regime"] = "overdamped"
    values["Q"] = 0.5 / zeta
    return Outcome(values, warnings=notes)


@column_kernel(damping_from_zeta)
def _zeta_columns(zeta) -> Columns:
    """:func:`damping_from_zeta` on columns: ``zeta``, ``delta``
    (:func:`decrement_from_zeta`, the same float steps), ``regime`` and ``Q``, the names of
    the underdamped one-off; exact on its rows (``0 < zeta < 1`` outside the critical band).
    Undamped, critical and overdamped rows give other names (or a note): not exact."""
    from ..lazy import numpy as np

    zeta = np.asarray(zeta, dtype=float)
    with np.errstate(all="ignore"):
        fraction = np.abs((1.0 - zeta) * (1.0 + zeta))
        values = {"zeta": zeta.copy(),
                  "delta": TWO_PI * zeta / np.sqrt((1.0 - zeta) * (1.0 + zeta)),
                  "regime": np.where(zeta == 0.0, "undamped", np.where(
                      fraction <= CRITICAL_BAND, "critically damped",
                      np.where(zeta < 1.0, "underdamped", "overdamped"))),
                  "Q": 0.5 / zeta}
    exact = (zeta > 0.0) & (zeta < 1.0) & (fraction > CRITICAL_BAND)
    return Columns(values, exact=exact)


_ORDER = ("zeta", "delta", "regime", "Q", "c_c", "c", "omega", "xi", "omega_d", "f_d", "T_d")


def _ordered(values: dict, notes: list[str]) -> Outcome:
    """The values in the order the damping-ratio command shows them."""
    ordered = {name: values[name] for name in _ORDER if name in values}
    return Outcome(ordered, model="linear", method="closed-form", warnings=notes)


def free_response(zeta: float, tau):
    """``x(tau) / x(0)`` of an oscillator released from rest: ``x(0) = 1``, ``x'(0) = 0``.

    ``tau = omega t`` is the dimensionless time (``omega`` the undamped natural frequency);
    ``x'' + 2 zeta x' + x = 0``. Underdamped, with ``s = sqrt((1 - zeta)(1 + zeta))``:
    ``x = exp(-zeta tau) (cos(s tau) + (zeta/s) sin(s tau))``; critical:
    ``x = (1 + tau) exp(-tau)``; overdamped, with the slow and fast rates
    ``a = 1/(zeta + r)``, ``b = zeta + r``, ``r = sqrt(zeta - 1) sqrt(zeta + 1)`` (no overflow
    of ``zeta^2``): ``x = (b exp(-a tau) - a exp(-b tau)) / (b - a)``.

    >>> float(free_response(0.0, math.pi))
    -1.0
    >>> float(free_response(1.0, 0.0)), float(free_response(3.0, 0.0))
    (1.0, 1.0)
    """
    import numpy as np

    tau = np.asarray(tau, dtype=float)
    if zeta < 1.0:
        s = math.sqrt((1.0 - zeta) * (1.0 + zeta))
        return np.exp(-zeta * tau) * (np.cos(s * tau) + (zeta / s) * np.sin(s * tau))
    if zeta == 1.0:
        return (1.0 + tau) * np.exp(-tau)
    r = math.sqrt(zeta - 1.0) * math.sqrt(zeta + 1.0)
    fast = zeta + r
    slow = 1.0 / fast
    with np.errstate(over="ignore", under="ignore"):  # exp(-fast tau) -> 0 is right
        return (fast * np.exp(-slow * tau) - slow * np.exp(-fast * tau)) / (fast - slow)
