"""Oscillators whose equation of motion is nonlinear: a rocking half-cylinder shell at large
amplitude, and a rod held by a torsion spring about an equilibrium found by a root find.

Pure functions on pint quantities returning an :class:`~dyncalc.physics.outcome.Outcome`.
scipy is imported inside the functions that need it, so importing this module stays cheap.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapters 4 and 5.
"""
from __future__ import annotations

import math

from ..errors import PhysicsError
from ..lazy import numpy as np
from ..units import Q_
from ..units import ACCELERATION, ANGLE, LENGTH, MASS, TORSIONAL_STIFFNESS
from .face import check_units, magnitude
from .columns import Columns, column_kernel
from .numerics import (HALF_TURN, PI_LO, UNIT_ROUNDOFF, finite_nonzero, monomial, sqrt_ratio,
                       sqrt_ratio_array)
from .numerics_arrays import elementwise, monomial_array
from .oscillators import _SHORT, _amplitude_parts
from .outcome import Outcome, periodic, periodic_arrays

__all__ = ["half_cylinder_shell", "rod_torsion_spring", "SHELL_METHODS", "WOUND_THRESHOLD"]

#: The methods the half-cylinder shell offers besides ``auto``.
SHELL_METHODS = ("linear", "quadrature", "ode")

#: pi - 2 rounded once (math.pi - 2 is exact by Sterbenz's lemma; PI_LO restores pi's tail).
PI_MINUS_2 = (math.pi - 2.0) + PI_LO

#: The smallest relative tolerance asked of the quadrature (a few rounding errors of the sum).
QUAD_FLOOR = 8.0 * 2.0 ** -52
#: The smallest relative tolerance solve_ivp's DOP853 accepts (100 eps).
ODE_FLOOR = 100.0 * 2.0 ** -52

#: Relative rounding bound of one quadrature node ``sqrt((1 + c x) / (1 - x))``,
#: ``x = k2 sin^2(i pi / n)``: the node's angle and sine (2u), the square and the product with
#: ``k2`` (2u), so ``x`` within 6u; ``c``, ``1 + c x``, ``1 - x`` (whose sensitivity to ``x`` is
#: ``x / (1 - x) <= 1`` below 90 degrees) and the quotient, 6u more; the square root halves
#: that and adds 1u. 16u leaves a margin over the 13u counted.
SHELL_NODE_ROUNDING = 16.0 * UNIT_ROUNDOFF
#: Relative rounding from the factor to the printed period: ``omega0`` by ``sqrt_ratio`` of
#: ``g`` and ``(pi - 2) r`` (5u with the product), the quotient by the factor (1u), and
#: ``T = 2 pi / omega`` (2u), counted with a margin.
SHELL_OUTPUT_ROUNDING = 10.0 * UNIT_ROUNDOFF

#: ``kt / (m g l)`` below which the rod-torsion-spring has equilibria past the vertical:
#: ``sin(psi)`` with ``psi`` in (pi/2, pi) the root of ``psi sin(psi) + cos(psi) = 0``
#: (mpmath.findroot at 40 digits: psi = 2.79838604578388713672..., threshold
#: 0.336508416918395291616...).
WOUND_THRESHOLD = 0.33650841691839529


# --- half-cylinder shell -----------------------------------------------------------------------

def _shell_small_error_bound(k2: float) -> float:
    """Upper bound of ``T/T0 - 1`` for the shell at ``k2 = sin^2(phi0/2)``, ``k2 <= 1/2``.

    With ``s = sin^2 u``, ``c = 4/(pi - 2)``, ``T/T0 = (2/pi) int_0^{pi/2} f(k2 s) du`` and
    ``f(x) = sqrt(1 + c x) / sqrt(1 - x)``. Since ``sqrt(1 + c x) <= 1 + c x/2`` and
    ``1/sqrt(1 - x) - 1 <= x / (2 (1 - x))``, ``f(x) - 1 <= c x/2 + x/(2(1 - x)) +
    c x^2/(4(1 - x))``; the means of ``s`` and ``s^2`` over the quarter period are 1/2 and
    3/8, and ``1 - x >= 1 - k2``. The bound is exact to first order in ``k2``:
    ``(1/(pi - 2) + 1/4) k2``.
    """
    c = 4.0 / PI_MINUS_2
    q = 1.0 - k2
    return 0.5 * k2 * (0.5 * c + 0.5 / q) + 0.375 * c * k2 * k2 / (4.0 * q)


def _shell_quadrature(k2: float, rtol: float) -> tuple[float, float]:
    """``(T/T0, relative error estimate)`` by the trapezoidal rule over a whole period.

    The integrand ``F(k2 sin^2 u)`` is analytic and pi-periodic in ``u``, so the mean of its
    values at ``N`` equally spaced points converges geometrically (its nearest complex
    singularity, ``sin^2 u = -(pi - 2)/4``, lies about 0.5 off the real axis: the error falls
    like ``exp(-N)``). ``N`` doubles from 16 until two estimates agree to ``rtol / 10`` (at
    most 1024 points); their difference, an overestimate of the finer one's truncation error,
    plus the rounding of the arithmetic (each node within :data:`SHELL_NODE_ROUNDING`, the
    mean by ``math.fsum`` exact to one rounding) is returned, so the estimate bounds the whole
    error of the computed mean. numpy only, in microseconds: no scipy import on this path.
    """
    import numpy as np

    c = 4.0 / PI_MINUS_2

    def mean(n: int) -> float:
        x = k2 * np.sin(np.arange(n) * (math.pi / n)) ** 2
        return math.fsum(np.sqrt((1.0 + c * x) / (1.0 - x)).tolist()) / n

    n, previous = 16, mean(8)
    while True:
        current = mean(n)
        error = abs(current - previous) / current
        if error <= 0.1 * max(rtol, QUAD_FLOOR) or n >= 1024:
            return current, error + SHELL_NODE_ROUNDING + UNIT_ROUNDOFF
        n, previous = 2 * n, current


def _shell_ode(phi0: float, rtol: float) -> float:
    """``T/T0`` from the equation of motion integrated over a quarter period.

    Time is scaled by ``sqrt(r/g)``: ``phi'' = -(phi'^2 + 1) sin(phi) / (pi - 2 cos(phi))``,
    with ``pi - 2 cos(phi) = (pi - 2) + 4 sin^2(phi/2)`` (no cancellation at small phi). The
    quarter period ends at the event ``phi = 0`` (crossed downward).
    """
    from scipy.integrate import solve_ivp

    def rhs(_t, y):
        phi, rate = y
        half = math.sin(0.5 * phi)
        return [rate, -(rate * rate + 1.0) * math.sin(phi) / (PI_MINUS_2 + 4.0 * half * half)]

    def upright(_t, y):
        return y[0]

    upright.terminal = True
    upright.direction = -1.0
    small_period = 2.0 * math.pi * math.sqrt(PI_MINUS_2)
    tol = max(0.1 * rtol, ODE_FLOOR)
    sol = solve_ivp(rhs, (0.0, 2.0 * small_period), [phi0, 0.0], method="DOP853",
                    rtol=tol, atol=1e-3 * tol * phi0, events=upright)
    if not sol.t_events[0].size:  # cannot happen below 90 degrees (T/T0 < 1.4 there)
        raise PhysicsError("the integration of the shell's equation of motion did not return "
                           "to the upright position; use --method quadrature")
    return 4.0 * float(sol.t_events[0][0]) / small_period


@check_units(r=LENGTH, g=ACCELERATION, amplitude=ANGLE)
def half_cylinder_shell(r, g, amplitude=None, method: str = "auto",
                        rtol: float = 1e-9) -> Outcome:
    """A thin half-cylinder shell rocking without slipping on flat ground.

    .. math:: \\ddot\\varphi (\\pi - 2\\cos\\varphi) + \\dot\\varphi^2 \\sin\\varphi
              + \\frac{g}{r}\\sin\\varphi = 0, \\qquad
              \\omega_0^2 = \\frac{g}{(\\pi - 2) r}

    At amplitude ``phi0`` energy conservation gives
    ``phi'^2 = 2 (g/r)(cos phi - cos phi0) / (pi - 2 cos phi)``; substituting
    ``sin(phi/2) = k sin(u)``, ``k = sin(phi0/2)``, removes the endpoint singularity:

    .. math:: T = 4\\sqrt{\\frac{r}{g}} \\int_0^{\\pi/2}
              \\frac{\\sqrt{\\pi - 2 + 4 k^2 \\sin^2 u}}{\\sqrt{1 - k^2 \\sin^2 u}}\\,du

    (``pi - 2 cos phi = pi - 2 + 4 k^2 sin^2 u``). Below 90 degrees ``k^2 <= 1/2``, so the
    integrand is smooth, bounded and pi-periodic, and the trapezoidal rule over a whole period
    converges geometrically.

    Parameters
    ----------
    r : Quantity
        Shell radius ``[length]``.
    g : Quantity
        Gravitational acceleration ``[length]/[time]^2``.
    amplitude : Quantity, optional
        Rocking amplitude ``[angle]``, 0 <= amplitude < 90 deg. ``None``: small oscillations.
    method : {"auto", "linear", "quadrature", "ode"}
        ``linear`` is the small-oscillation period; ``quadrature`` the integral above
        (periodic trapezoidal rule, numpy only, to ``rtol``); ``ode`` integrates the equation
        of motion
        (scipy.integrate.solve_ivp, DOP853) from rest at ``phi0`` to the upright position.
        ``auto`` takes ``linear`` when the rigorous bound on its period error
        ``(k^2/2)(c/2 + 1/(2(1-k^2))) + 3 c k^4/(32 (1-k^2))``, ``c = 4/(pi-2)``, meets
        ``rtol`` (it costs nothing and is exact to first order, ``(1/(pi-2) + 1/4) k^2``, so
        it is never more than slightly pessimistic where the choice matters), otherwise
        ``quadrature`` (16 to 128 integrand evaluations, vectorised). ``ode`` imports scipy
        (about a second on these machines); the other methods do not.
    rtol : float
        Relative tolerance on the period.

    Returns
    -------
    Outcome with ``omega`` (rad/s), ``f`` (Hz), ``T`` (s), and with an amplitude also
    ``omega_0``. ``error_estimate`` is the relative period error ``|T_model - T| / T``: for
    ``linear`` the bound (which also bounds ``T/T0 - 1``), or the quadrature's
    ``1 - T0/T`` when the bound misses ``rtol``; for ``quadrature`` the difference of its last
    two refinements; for ``ode`` its difference from the quadrature plus that estimate. The
    nonlinear methods' estimates include the rounding of the arithmetic (the quadrature's nodes
    and sum, and the steps from the factor to ``T``), so each is an upper bound of the true
    relative error, never an approximation of it.

    Notes
    -----
    The shell rolls without slipping and is thin (its mass on the arc). At 90 degrees the
    rim reaches the ground and the model ends, so larger amplitudes are refused.

    Examples
    --------
    The set-up of E4.18 of [1], with numbers of our own (checked against mpmath):

    >>> from dyncalc.units import Q_
    >>> out = half_cylinder_shell(Q_(0.5, "m"), Q_(9.80665, "m/s^2"))
    >>> round(out.values["omega"].magnitude, 12)  # sqrt(g / ((pi - 2) r)), rad/s
    4.144954360471
    >>> out = half_cylinder_shell(Q_(0.5, "m"), Q_(9.80665, "m/s^2"), Q_(60, "deg"))
    >>> out.method
    'quadrature'
    >>> round(out.values["T"].magnitude, 12)  # mpmath.quad at 30 digits: 1.949968530966157
    1.949968530966
    """
    omega0 = sqrt_ratio(magnitude(g, "m/s**2"), PI_MINUS_2 * magnitude(r, "m"))
    if amplitude is None:
        if method in ("quadrature", "ode"):
            raise PhysicsError(f"--method {method} needs an amplitude (--amplitude or "
                               "amplitude=); without one the shell's oscillation is linear")
        out = Outcome(periodic(omega0), model="linear", method="closed-form")
        out.assumptions.append("small oscillations; give --amplitude for the "
                               "amplitude-dependent period")
        return out
    amount, unit, phi0 = _amplitude_parts(amplitude)
    limit = 0.5 * HALF_TURN[unit] if unit in HALF_TURN else 0.5 * math.pi
    if amount >= limit:
        shown = f"{amount:g} {_SHORT.get(unit, unit)}"
        raise PhysicsError(f"the amplitude must be below 90 degrees; at {shown} the rim of "
                           "the half-cylinder shell touches the ground and the rocking model "
                           "ends")
    k2 = math.sin(0.5 * phi0) ** 2
    bound = _shell_small_error_bound(k2)
    if method == "auto":
        method = "linear" if bound <= rtol else "quadrature"
    shown = f"{amount:.6g} {_SHORT.get(unit, unit)}"
    omega_0 = periodic(omega0)["omega"]
    if method == "linear":
        error, size = bound, "at most "
        if bound > rtol:
            factor, quad_error = _shell_quadrature(k2, rtol)
            error, size = 1.0 - 1.0 / factor + quad_error, ""
        error += SHELL_OUTPUT_ROUNDING
        values = periodic(omega0)
        values["omega_0"] = omega_0
        out = Outcome(values, model="linear", method="linear", error_estimate=error,
                      assumptions=[f"small oscillations: the period is {size}"
                                   f"{100 * error:.3g}% short at an amplitude of {shown}"])
        if error > rtol:
            out.warnings.append(f"the linear model misses the requested tolerance {rtol:g}: "
                                f"its period is {100 * error:.3g}% short at {shown}; use "
                                "--method quadrature")
        return out
    factor, error = _shell_quadrature(k2, rtol)
    model_note = ("period of phi''(pi - 2 cos phi) + phi'^2 sin phi + (g/r) sin phi = 0 at "
                  f"an amplitude of {shown}")
    if method == "ode":
        ode_factor = _shell_ode(phi0, rtol) if phi0 > 0.0 else 1.0
        # triangle inequality; the quotient's own rounding is one more u
        error = abs(ode_factor / factor - 1.0) + error + UNIT_ROUNDOFF
        factor = ode_factor
        how = "integrated with DOP853 to the upright position (error: against the quadrature)"
    else:
        how = "by the periodic trapezoidal rule on the energy integral"
    error += SHELL_OUTPUT_ROUNDING
    values = periodic(omega0 / factor)
    values["omega_0"] = omega_0
    out = Outcome(values, model="nonlinear", method=method, error_estimate=error,
                  assumptions=[f"{model_note}, {how}; the small-oscillation period is "
                               f"{100 * (1.0 - 1.0 / factor):.3g}% short"])
    if error > rtol:
        out.warnings.append(f"the {method} method reached a relative error of {error:.2g}, "
                            f"more than the requested tolerance {rtol:g}")
    return out


@column_kernel(half_cylinder_shell)
def _half_cylinder_shell_columns(r, g, amplitude=None, method: str = "auto",
                                 rtol: float = 1e-9):
    """:func:`half_cylinder_shell` on columns (``r`` in m, ``g`` in m/s^2): small swings
    (``amplitude`` None, method ``auto`` or ``linear``: the closed form), or at an amplitude
    (a :class:`~dyncalc.physics.columns.TypedColumn`) the quadrature rows
    (:func:`~dyncalc.physics.shell_columns.shell_amplitude_columns`); ``None`` otherwise."""
    if amplitude is not None:
        from .shell_columns import shell_amplitude_columns

        return shell_amplitude_columns(r, g, amplitude, method, rtol, {
            "PI_MINUS_2": PI_MINUS_2, "QUAD_FLOOR": QUAD_FLOOR,
            "SHELL_NODE_ROUNDING": SHELL_NODE_ROUNDING,
            "SHELL_OUTPUT_ROUNDING": SHELL_OUTPUT_ROUNDING})
    if method not in ("auto", "linear"):
        return None
    with np.errstate(over="ignore", under="ignore", divide="ignore", invalid="ignore"):
        values = periodic_arrays(sqrt_ratio_array(g, PI_MINUS_2 * r))
    return Columns(values, exact=finite_nonzero(values), model="linear",
                   method="closed-form")


_half_cylinder_shell_columns.typed_params = ("amplitude",)


# --- rod on a torsion spring -------------------------------------------------------------------

def _rod_equilibrium(kappa: float) -> float:
    """The root ``phi`` in (0, pi/2) of ``F(phi) = cos(phi) - kappa phi = 0``, ``kappa > 0``.

    The bracket: ``F(0) = 1 > 0`` and ``F(pi/2) = -kappa pi/2 < 0``, and ``F`` is strictly
    decreasing there (``F' = -sin(phi) - kappa < 0``), so [0, pi/2] holds exactly one root.
    ``F`` is also concave (``F'' = -cos(phi) <= 0``), so every tangent lies above it: Newton
    started at the right end ``pi/2`` (where ``F < 0``) steps left but never past the root,
    and its iterates fall monotonically into it (quadratically at the end). The step is
    written ``phi - F/F' = (phi sin(phi) + cos(phi)) / (sin(phi) + kappa)``, a ratio of
    positive terms, so no rounding can throw an iterate out of the bracket (the form
    ``phi + F/|F'|`` cancels to 0 at the first step when kappa is 1e18). It stops when an
    iterate no longer decreases, which rounding makes happen within a few ulp of the root.
    At most 5 steps for ``kappa`` from 1e-300 to 1e300 (measured).

    Not scipy's brentq: importing scipy.optimize doubles the command's run time, and in
    floats ``F(fl(pi/2)) = 6.1e-17 - kappa pi/2`` is positive for kappa below 3.9e-17, so the
    float bracket fails there (Newton returns ``fl(pi/2)``, the root to the last bit).
    The tests compare the two where both apply.
    """
    phi = 0.5 * math.pi
    for _ in range(200):
        sin = math.sin(phi)
        following = (phi * sin + math.cos(phi)) / (sin + kappa)  # phi - F/F', all terms >= 0
        if not following < phi:
            break
        phi = following
    return phi


def _rod_equilibrium_array(kappa):
    """:func:`_rod_equilibrium` on an array of ``kappa``: the same monotone Newton iterates,
    row by row the same floats (``math.sin`` and ``math.cos`` per row, numpy's may differ by an
    ulp; the step's ``* + /`` are IEEE in both), each row stopping where the scalar loop
    stops. So the final float is the scalar solver's, bit for bit, whatever it converges to."""
    phi = np.full(np.shape(kappa), 0.5 * math.pi)
    live = np.arange(phi.size)
    with np.errstate(all="ignore"):
        for _ in range(200):
            if not live.size:
                break
            now = phi[live]
            sin, cos = elementwise(math.sin, now), elementwise(math.cos, now)
            following = (now * sin + cos) / (sin + kappa[live])
            going = following < now
            live = live[going]
            phi[live] = following[going]
    return phi


@check_units(m=MASS, l=LENGTH, kt=TORSIONAL_STIFFNESS, g=ACCELERATION)
def rod_torsion_spring(m, l, kt, g) -> Outcome:
    """A massless rod with a point mass at its tip, pivoted at the other end on a torsion spring
    that is unstretched with the rod horizontal; gravity bends it down to ``phi_0``.

    .. math:: \\frac{g}{l}\\cos\\varphi_0 = \\frac{k_t \\varphi_0}{m l^2}, \\qquad
              \\omega^2 = \\frac{g}{l}\\sin\\varphi_0 + \\frac{k_t}{m l^2}

    With ``kappa = kt / (m g l)`` the equilibrium solves ``cos(phi_0) = kappa phi_0``, a
    bracketed root find on [0, pi/2] (monotone Newton, see :func:`_rod_equilibrium`), and
    ``omega = sqrt(g/l) sqrt(sin(phi_0) + kappa)`` (a sum of positive terms).

    Parameters
    ----------
    m : Quantity
        Tip mass ``[mass]``.
    l : Quantity
        Rod length ``[length]``.
    kt : Quantity
        Torsional stiffness ``[force]*[length]/[angle]``, positive.
    g : Quantity
        ``[length]/[time]^2``.

    Returns
    -------
    Outcome with ``omega``, ``f``, ``T`` and ``phi_0`` (rad, below the horizontal).

    Notes
    -----
    ``cos(phi) = kappa phi`` has further roots with the rod wound past the vertical (phi
    below -90 degrees, or beyond 270 degrees) when ``kappa`` is at most
    :data:`WOUND_THRESHOLD` ``= 0.33650841691839529``: at that value the line ``kappa phi``
    touches ``cos(phi)`` at ``psi`` in (90, 180) degrees, i.e. ``kappa = -sin(phi)`` and
    ``cos(phi) = kappa phi`` give ``psi sin(psi) + cos(psi) = 0``, ``kappa = sin(psi)``
    (solved with mpmath.findroot at 40 digits). A warning says so.

    Examples
    --------
    The set-up of E5.20 of [1], with numbers of our own (checked against mpmath):

    >>> from dyncalc.units import Q_
    >>> out = rod_torsion_spring(Q_(2, "kg"), Q_(1, "m"), Q_(30, "N*m/rad"), Q_(9.81, "m/s^2"))
    >>> round(out.values["phi_0"].to("deg").magnitude, 9)  # mpmath: 31.83472856122
    31.834728561
    >>> round(out.values["omega"].magnitude, 12)  # mpmath: 4.491602048489267
    4.491602048489
    """
    m_, l_ = magnitude(m, "kg"), magnitude(l, "m")
    kt_, g_ = magnitude(kt, "N*m/rad"), magnitude(g, "m/s**2")
    if not kt_ > 0.0:
        raise PhysicsError(f"kt must be positive; got {kt_:g} N*m/rad")
    kappa = monomial(1.0, [(kt_, 1), (m_, -1), (g_, -1), (l_, -1)])
    phi0 = _rod_equilibrium(kappa)
    omega = sqrt_ratio(g_, l_) * math.sqrt(math.sin(phi0) + kappa)
    values = periodic(omega)
    values["phi_0"] = Q_(phi0, "rad")
    out = Outcome(values, model="linear", method="root-find",
                  assumptions=["small oscillations about the equilibrium phi_0 below the "
                               "horizontal; massless rod, point mass at the tip"])
    if kappa <= WOUND_THRESHOLD:
        out.warnings.append(f"kt = {kappa:.4g} m g l is at most {WOUND_THRESHOLD:.6f} m g l: "
                            "further equilibria exist with the rod wound past the vertical; "
                            "this result is the one between the horizontal and the downward "
                            "vertical")
    return out


@column_kernel(rod_torsion_spring)
def _rod_torsion_spring_columns(m, l, kt, g) -> Columns:
    """:func:`rod_torsion_spring` on columns (``m`` in kg, ``l`` in m, ``kt`` in N*m/rad,
    ``g`` in m/s^2): ``kappa`` by :func:`monomial_array`, the equilibrium by the scalar
    solver's own iterates (:func:`_rod_equilibrium_array`), so every row is bit for bit the
    one-off's. Rows with ``kappa`` at most :data:`WOUND_THRESHOLD` (a warning), ``kt <= 0``
    (refused) or a result zero or beyond float64 are not exact."""
    with np.errstate(all="ignore"):
        kappa = monomial_array(1.0, [(kt, 1), (m, -1), (g, -1), (l, -1)])
        phi0 = _rod_equilibrium_array(kappa)
        omega = sqrt_ratio_array(g, l) * np.sqrt(elementwise(math.sin, phi0) + kappa)
    values = periodic_arrays(omega)
    values["phi_0"] = phi0
    return Columns(values, exact=finite_nonzero(values) & (kt > 0.0) & (kappa > WOUND_THRESHOLD),
                   model="linear", method="root-find")
