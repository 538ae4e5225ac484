"""``rolling-onset``: the texts the user typed -> checked quantities -> the physics -> a Result.

The command line stays thin: it hands the option texts to :func:`rolling_onset_result`, which
is :func:`read` (every quantity parsed once and checked: dimension, sign, the rules between
options) then :func:`compute` (calls :mod:`dyncalc.physics.rolling` and builds the
:class:`~dyncalc.result.Result` with its explanation and warnings). With ``method="ode"`` it
also integrates the equations of motion, compares them with the closed form and times both.
The Result's ``sensitivity`` gives the derivatives for the propagation of uncertainties,
worked out on the parsed inputs: exact for the closed form, by central differences for the
ODE (:func:`_sensitivity`).
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, replace
from fractions import Fraction

from ..constants import STANDARD_GRAVITY_TEXT
from ..errors import InputError, PhysicsError
from ..lazy import numpy as np
from ..result.explain import Formula
from .record import Command, Parameter, results_from_kinds
from ..result.entries import Entry, Explanation, Result, entry_from_parsed, format_number
from ..units import (ACCELERATION, ANGLE, ANGULAR_RATE, DIMENSIONLESS, LENGTH, TIME, VELOCITY,
                    Parsed, format_quantity, parse_quantity, to_si)

__all__ = ["COMMAND", "rolling_onset_result", "read", "compute", "RollingInputs", "METHODS",
           "DEFAULT_RTOL", "DEFAULT_BODY"]

#: ``--method`` choices: ``auto`` is the closed form (exact to rounding, and the cheapest).
METHODS = ("auto", "closed-form", "ode")
DEFAULT_RTOL = 1e-9
DEFAULT_BODY = "solid-sphere"
DEFAULT_G = STANDARD_GRAVITY_TEXT

#: name -> (dimension, display unit, symbol, description)
_KINDS = {
    "t_roll": (TIME, "s", "t_roll", "time until it rolls without slipping"),
    "x_roll": (LENGTH, "m", "x_roll", "displacement along the surface until then"),
    "v_roll": (VELOCITY, "m/s", "v_roll", "speed of the centre when it starts to roll"),
    "omega_roll": (ANGULAR_RATE, "rad/s", "ω_roll", "spin when it starts to roll"),
    "path_roll": (LENGTH, "m", "ℓ_roll", "path length until then (out and back)"),
    "mu_min": (DIMENSIONLESS, "", "μ_min", "static friction that keeps it rolling on the slope"),
}
_REFERENCE = ("Gross et al., Engineering Mechanics 3, Example 3.45 (bowling ball: v0 = 5 m/s, "
              "mu = 0.3 gives 0.49 s, 2.08 m, 3.57 m/s)")


def _num(value: float) -> str:
    return format_number(value, 6)


def _term(value: float, unit: str = "") -> str:
    """A value inside a substituted formula: negative ones in parentheses."""
    text = f"{_num(value)} {unit}".rstrip()
    return f"({text})" if value < 0 else text


def _bodies() -> dict[str, float]:
    from ..physics.bodies import KAPPA

    return KAPPA


def _read(texts: dict, name: str, dim, strict: bool, **kw):
    return parse_quantity(texts[name], dim, label=COMMAND.parameter(name).flag, strict=strict, **kw)


def _method(method: str | None) -> str:
    method = "auto" if method is None else method
    if method not in METHODS:
        raise InputError(f"--method must be one of {', '.join(METHODS)}; got {method!r}")
    return method


@dataclass(frozen=True)
class RollingInputs:
    """``rolling-onset``'s quantities as :func:`read` parsed and checked them, in SI: all that
    :func:`compute` needs (nothing typed is read again after this).

    ``v0`` initial speed (m/s, >= 0), ``mu`` kinetic friction (> 0), ``kappa`` shape factor
    J_C/(m r^2) (>= 0), ``g`` (m/s^2, > 0), ``radius`` (m, or ``None``), ``omega0`` initial
    spin (rad/s), ``sin_b``, ``cos_b`` of the slope (``cos_b > 0``); ``incline`` the slope as
    read (or ``None``), ``body`` the named body (``None`` with ``--kappa``); ``parsed`` every
    quantity read, by input name (with its uncertainty); ``entries`` the Result's inputs.
    """

    v0: float
    mu: float
    kappa: float
    g: float
    radius: float | None
    omega0: float
    sin_b: float
    cos_b: float
    incline: Parsed | None
    body: str | None
    parsed: dict[str, Parsed]
    entries: dict[str, Entry]

    def args(self) -> tuple:
        """The arguments of the physics kernels (``onset_closed_form``, ``onset_ode``)."""
        return (self.v0, self.mu, self.kappa, self.g, self.radius, self.omega0, self.sin_b,
                self.cos_b)


_SPIN_NEEDS_RADIUS = ("--omega0 needs --radius: the contact point slips with v0 - r omega0, so "
                      "the spin counts only with the radius; give --radius (e.g. --radius "
                      "0.11m)")


def read(texts: dict[str, str | None], strict: bool = False) -> RollingInputs:
    """The option texts (``{"v0": "5 m/s", "mu": "0.3"}``) -> :class:`RollingInputs`: every
    quantity parsed once and checked (dimension, sign, the rules between options).

    Keys: ``v0``, ``mu`` (required), ``body`` or ``kappa``, ``radius``, ``omega0``, ``g``,
    ``incline``; ``None`` or a missing key means not given. ``strict`` is ``--strict-units``.
    """
    from ..physics.rolling import slope_sin_cos

    texts = {k: v for k, v in texts.items() if v is not None}
    for name in ("v0", "mu"):
        if name not in texts:
            example = {"v0": "--v0 '5 m/s'", "mu": "--mu 0.3"}[name]
            raise InputError(f"rolling-onset needs {COMMAND.parameter(name).flag} (e.g. {example}); see "
                             "'dyncalc rolling-onset --help'")

    inputs: dict[str, Entry] = {}
    parsed: dict[str, Parsed] = {}
    v0 = parsed["v0"] = _read(texts, "v0", VELOCITY, strict)
    if v0.si < 0:
        raise InputError(f"--v0 must not be negative: it is the speed, and its direction is "
                         f"the positive one (spin against it is a negative --omega0, moving "
                         f"downhill a negative --incline); got {format_quantity(v0.quantity)}")
    inputs["v0"] = entry_from_parsed("v0", v0, VELOCITY, description="initial speed")
    mu = parsed["mu"] = _read(texts, "mu", DIMENSIONLESS, strict, constraint="positive")
    inputs["mu"] = entry_from_parsed("mu", mu, DIMENSIONLESS, description="kinetic friction")

    body = texts.get("body")
    if body is not None and "kappa" in texts:
        raise InputError("give --body or --kappa, not both (--kappa is the shape factor "
                         "J_C/(m r^2) of any body)")
    if "kappa" in texts:
        one = parsed["kappa"] = _read(texts, "kappa", DIMENSIONLESS, strict,
                                      constraint="nonnegative")
        kappa = one.si
        inputs["kappa"] = entry_from_parsed("kappa", one, DIMENSIONLESS,
                                            description="shape factor J_C/(m r^2)")
        body_name = None
    else:
        body_name = DEFAULT_BODY if body is None else body.strip()
        bodies = _bodies()
        if body_name not in bodies:
            raise InputError(f"--body must be one of {', '.join(bodies)}; got "
                             f"{body_name[:40]!r} (or give the shape factor J_C/(m r^2) with "
                             "--kappa)")
        kappa = bodies[body_name]
        inputs["body"] = Entry("body", body_name, None,
                               text=DEFAULT_BODY if body is None else body)

    radius = None
    if "radius" in texts:
        one = parsed["radius"] = _read(texts, "radius", LENGTH, strict, constraint="positive")
        radius = one.si
        inputs["radius"] = entry_from_parsed("radius", one, LENGTH, description="radius")
    omega0 = 0.0
    if "omega0" in texts:
        one = parsed["omega0"] = _read(texts, "omega0", ANGULAR_RATE, strict)
        omega0 = one.si
        if omega0 != 0.0 and radius is None:
            raise InputError(_SPIN_NEEDS_RADIUS)
        inputs["omega0"] = entry_from_parsed("omega0", one, ANGULAR_RATE,
                                             description="initial spin")
    g = parsed["g"] = _read({"g": texts.get("g", DEFAULT_G)}, "g", ACCELERATION, strict,
                            constraint="positive")
    inputs["g"] = entry_from_parsed("g", g, ACCELERATION, description="gravity")

    sin_b, cos_b = 0.0, 1.0
    incline = None
    if "incline" in texts:
        incline = parsed["incline"] = _read(texts, "incline", ANGLE, strict)
        sin_b, cos_b = slope_sin_cos(incline.quantity)
        if not cos_b > 0.0:
            hint = (f"; a bare number is in radians: write {texts['incline'].strip()}deg for "
                    "degrees" if incline.assumed_si else "")
            raise InputError("--incline must be between -90 and 90 degrees (a slope, not a "
                             f"wall); got {format_quantity(incline.quantity)}{hint}")
        inputs["incline"] = entry_from_parsed("incline", incline, ANGLE,
                                              description="slope, positive uphill")
    return RollingInputs(v0=v0.si + 0.0, mu=mu.si, kappa=kappa, g=g.si, radius=radius,
                         omega0=omega0, sin_b=sin_b, cos_b=cos_b, incline=incline,
                         body=body_name, parsed=parsed, entries=inputs)


def rolling_onset_result(texts: dict[str, str | None], *, method: str | None = None,
                         rtol: float | None = None, strict: bool = False) -> Result:
    """Compute ``rolling-onset`` from the option texts (``{"v0": "5 m/s", "mu": "0.3"}``):
    :func:`read`, then :func:`compute`.

    Keys: ``v0``, ``mu`` (required), ``body`` or ``kappa``, ``radius``, ``omega0``, ``g``,
    ``incline``; ``None`` or a missing key means not given. ``method`` is one of
    :data:`METHODS` (``None``: auto, the closed form); ``rtol`` the ODE's tolerance (default
    1e-9); ``strict`` is ``--strict-units``.

    >>> r = rolling_onset_result({"v0": "5 m/s", "mu": "0.3"})
    >>> [(n, round(e.si, 4)) for n, e in r.results.items()]
    [('t_roll', 0.4856), ('x_roll', 2.0811), ('v_roll', 3.5714)]
    """
    method = _method(method)
    return compute(read(texts, strict), method, rtol)


def compute(inputs: RollingInputs, method: str | None = None,
            rtol: float | None = None) -> Result:
    """The Result of the quantities :func:`read` gave: the closed form (and with
    ``method="ode"`` the integrated equations of motion, compared and timed), its
    explanation and warnings, and ``sensitivity`` for the propagation of uncertainties
    (:func:`_sensitivity`)."""
    method = _method(method)
    closed_form_s, onset, values, used, extra, ode_notes = _evaluate(inputs, method, rtol)
    warnings = list(onset.warnings) + ode_notes
    results = {}
    for name, value in values.items():
        dim, unit, symbol, words = _KINDS[name]
        results[name] = Entry(name, float(value), dim, unit=unit, symbol=symbol,
                              description=words)
    on_slope = inputs.incline is not None
    warnings += _physics_warnings(onset, inputs.kappa, inputs.mu, on_slope)
    result = Result(command="rolling-onset", results=results, inputs=inputs.entries,
                    scene=None, model="coulomb-friction", method=used, warnings=warnings,
                    explanation=_explain(onset, inputs.kappa, inputs.body, inputs.mu,
                                         inputs.g, inputs.v0, inputs.radius, inputs.omega0,
                                         inputs.incline, inputs.sin_b, inputs.cos_b, used,
                                         extra),
                    extra=extra)
    result.add_overflow_warnings()
    result.sensitivity = lambda: _sensitivity(inputs, onset, rtol, used, result)
    return result


#: How often the run as typed times each kernel (the best of these runs is reported).
TIMING_RUNS = 3


def _evaluate(inputs: RollingInputs, method: str, rtol: float | None,
              repeat: int = TIMING_RUNS):
    """``(closed_form_s, onset, values, used, extra, notes)``: the closed form (timed, the
    best of ``repeat`` runs) and with ``method="ode"`` the ODE (:func:`_run_ode`)."""
    from ..physics.rolling import onset_closed_form

    args = inputs.args()
    closed_form_s, onset = _timed(lambda: onset_closed_form(*args), repeat)
    values = onset.values()
    if inputs.incline is not None:
        values["mu_min"] = onset.mu_min
    if method != "ode":
        return closed_form_s, onset, values, "closed-form", {}, []
    values, used, extra, notes = _run_ode(args, onset, values, rtol, closed_form_s, repeat)
    return closed_form_s, onset, values, used, extra, notes


# --- derivatives for the propagation of uncertainties ----------------------------------------

def _sensitivity(inputs: RollingInputs, onset, rtol: float | None, used: str,
                 result: Result):
    """The derivatives of the results with respect to the uncertain inputs (SI), worked out
    on the parsed inputs (:class:`dyncalc.result.propagate.Sensitivity`).

    Exact (:func:`_exact_slopes`) for the closed form while the body slips (``s0 != 0``).
    By central differences on the parsed values (:func:`_nudged`; two computations per
    uncertain input, nothing parsed again) where the closed form has no derivative or the
    results are not the closed form's: ``--method ode`` (each nudge integrates once, untimed),
    a body set down already rolling (``s0 = 0``: ``t_roll ~ |s0|`` has a kink, the central
    difference averages its two sides), an uncertain ``--omega0 0`` without ``--radius`` (a
    spin other than 0 is refused: the results get no uncertainty).
    """
    from ..result.propagate import Sensitivity, UncertainInput, _numbers, central_differences

    names = [name for name, one in inputs.parsed.items() if one.uncertainty is not None]
    uncertain = [UncertainInput(name, float(inputs.parsed[name].si),
                                float(inputs.parsed[name].uncertainty)) for name in names]
    nominal = _numbers(result)
    if used == "ode" or onset.sigma == 0 or (inputs.radius is None and "omega0" in names):
        how = "ode" if used == "ode" else "closed-form"

        def rerun(index: int, offset: float):
            nudged = _nudged(inputs, names[index], offset)
            if nudged is None:
                return None
            try:
                values = _evaluate(nudged, how, rtol, repeat=1)[2]
            except InputError:
                return None
            return {name: np.asarray(float(value)) for name, value in values.items()}

        return central_differences(uncertain, nominal, rerun)
    exact = _exact_slopes(inputs, onset)
    slopes = {name: {i: exact[name][item.name] for i, item in enumerate(uncertain)
                     if item.sigma != 0} for name in nominal}
    return Sensitivity(uncertain, slopes)


def _nudged(inputs: RollingInputs, name: str, offset: float) -> RollingInputs | None:
    """``inputs`` with input ``name`` moved by ``offset`` (SI; an incline is moved in the unit
    it was typed in, as :func:`read` takes its sine and cosine), or ``None`` where
    :func:`read` would refuse the moved value."""
    from ..physics.rolling import slope_sin_cos

    if name == "incline":
        quantity = inputs.incline.quantity
        scale = to_si(type(quantity)(1.0, quantity.units), ANGLE, "incline")
        sin_b, cos_b = slope_sin_cos(quantity + type(quantity)(offset / scale, quantity.units))
        if not cos_b > 0.0:
            return None
        return replace(inputs, sin_b=sin_b, cos_b=cos_b)
    si = float(inputs.parsed[name].si) + offset
    refused = (not math.isfinite(si)
               or (name in ("mu", "g", "radius") and not si > 0.0)
               or (name in ("v0", "kappa") and not si >= 0.0)
               or (name == "omega0" and si != 0.0 and inputs.radius is None))
    return None if refused else replace(inputs, **{name: si + 0.0})


def _exact_slopes(inputs: RollingInputs, onset) -> dict[str, dict[str, float]]:
    """``d result / d input`` of the closed form, exactly (in float64), while the body slips
    (``sigma = sign(s0) != 0``), for every input (v0, mu, kappa, radius, omega0, g, incline).

    With ``N = sigma sin(beta) + mu cos(beta)`` (``|a| = g |N|``, the deceleration while it
    slips), ``D = mu cos(beta) + kappa N`` and ``s0 = v0 - r omega0``::

        t = kappa |s0| / (g D)       v = v0 - q s0,  q = kappa N / D,  1 - q = mu cos / D
        x = t (v0 + v) / 2           omega = v / r     path = (v0^2 + v^2) / (2 g |N|)
        mu_min = kappa |tan(beta)| / (1 + kappa)

    whence ``dt/ds0 = sigma kappa/(g D)``, ``dt/dkappa = |s0| mu cos/(g D^2)``,
    ``dt/dmu = -t (1 + kappa) cos/D``, ``dt/dg = -t/g``, ``dt/dbeta = -t D'/D`` with
    ``D' = sigma kappa cos - mu (1 + kappa) sin``; ``dv/dv0 = 1 - q``, ``dv/dr = q omega0``,
    ``dv/domega0 = q r``, ``dv/dkappa = -s0 N mu cos/D^2``, ``dv/dmu = sigma s0 kappa sin
    cos/D^2``, ``dv/dbeta = -sigma s0 kappa mu/D^2``, ``dv/dg = 0``; x, omega, path by the
    product and quotient rules, cancellation-free where the terms are large:
    ``x = sigma kappa s0 (2 v0 - q s0) / (2 g D)`` gives ``dx/dv0 = t + v dt/ds0`` and
    ``dx/ds0 = v dt/ds0``, ``omega = (1 - q) v0 / r + q omega0`` gives
    ``domega/dr = -(1 - q) v0 / r^2``; ``dmu_min/dkappa = |tan(beta)|/(1 + kappa)^2``,
    ``dmu_min/dbeta = sign(beta) kappa/((1 + kappa) cos^2)`` (0 at ``beta = 0``, the mean of
    its two sides). ``beta`` in radians. At ``kappa = 0`` these are the derivatives from
    above (a negative kappa is refused).
    """
    from ..physics.rolling import decimal_value

    f = np.float64
    sigma = onset.sigma
    with np.errstate(all="ignore"):  # a slope beyond float64 is caught by the propagation
        K, mu, g, w = f(inputs.kappa), f(inputs.mu), f(inputs.g), f(inputs.omega0)
        S, C = f(inputs.sin_b), f(inputs.cos_b)
        r = f(inputs.radius) if inputs.radius is not None else f(0.0)
        v0, s0, t, v, D = f(inputs.v0), f(onset.s0), f(onset.t), f(onset.v), f(onset.drive)
        N = f(float(sigma * Fraction(inputs.sin_b)
                    + decimal_value(inputs.mu) * Fraction(inputs.cos_b)))
        q, e = K * N / D, mu * C / D                      # q + e = 1
        dts = sigma * K / D / g
        dt = {"v0": dts, "radius": -w * dts, "omega0": -r * dts,
              "mu": -t * (1 + K) * C / D, "kappa": abs(s0) / D * e / g, "g": -t / g,
              "incline": -t * (sigma * K * C - mu * (1 + K) * S) / D}
        dv = {"v0": e, "radius": q * w, "omega0": q * r,
              "mu": sigma * s0 * (K * S / D) * (C / D), "kappa": -s0 * (N / D) * e,
              "g": f(0.0), "incline": -sigma * s0 * (K / D) * (mu / D)}
        d_v0 = {name: f(1.0 if name == "v0" else 0.0) for name in dt}
        dx = {n: dt[n] * ((v0 + v) / 2) + t * (dv[n] / 2) for n in dt}
        dx.update(v0=t + v * dts, radius=-w * v * dts, omega0=-r * v * dts)
        out = {"t_roll": dt, "v_roll": dv, "x_roll": dx}
        if onset.omega is not None:
            out["omega_roll"] = {n: dv[n] / r for n in dt}
            out["omega_roll"]["radius"] = -e * v0 / r / r
        if onset.path is not None:
            A, sign_n = g * abs(N), np.sign(N)
            dA = {"g": abs(N), "mu": g * sign_n * C, "incline": g * sign_n * (sigma * C - mu * S)}
            out["path_roll"] = {n: (v0 * d_v0[n] + v * dv[n]) / A
                                - f(onset.path) * (dA.get(n, 0.0) / A) for n in dt}
        if inputs.incline is not None:
            out["mu_min"] = {n: f(0.0) for n in dt}
            out["mu_min"]["kappa"] = abs(S) / C / (1 + K) / (1 + K)
            out["mu_min"]["incline"] = np.sign(S) * K / (1 + K) / C / C
    return {name: {n: float(slope) for n, slope in row.items()} for name, row in out.items()}


def _timed(call, repeat: int = TIMING_RUNS):
    """``(seconds, result)``: the best of ``repeat`` runs of ``call()`` (the first run pays
    for warming caches up; the best is the cost of the computation itself)."""
    best, result = math.inf, None
    for _ in range(repeat):
        start = time.perf_counter()
        result = call()
        best = min(best, time.perf_counter() - start)
    return best, result


def _run_ode(args, onset, values, rtol, closed_form_s, repeat: int = TIMING_RUNS):
    """Integrate the equations of motion (timed: the best of ``repeat`` runs); their results,
    the method, the JSON extras, notes."""
    from ..physics.rolling import ODE_FLOOR, onset_ode

    tol = DEFAULT_RTOL if rtol is None else rtol
    v0, mu, kappa, g, radius, omega0, sin_b, cos_b = args
    if onset.sigma == 0 or kappa == 0.0:
        why = ("the body is set down already rolling, s0 = 0" if onset.sigma == 0 else
               "kappa = 0 rolls at once")
        return values, "closed-form", {}, [
            f"--method ode: there is no sliding phase to integrate ({why}); the closed form "
            "is given, exact"]
    import scipy.integrate  # noqa: F401  (imported before the clock starts)

    try:
        ode_s, ode = _timed(lambda: onset_ode(*args, rtol=tol, horizon=onset.t), repeat)
    except PhysicsError as exc:
        return values, "closed-form", {}, [f"--method ode: {exc}; the closed form is given"]
    speed_scale = max(abs(v0), abs(onset.rim0))
    scales = {"t_roll": onset.t, "x_roll": speed_scale * onset.t, "v_roll": speed_scale,
              "omega_roll": speed_scale / radius if radius else 0.0}
    got = {"t_roll": ode.t, "x_roll": ode.x, "v_roll": ode.v, "omega_roll": ode.omega}
    errors = {}
    new = dict(values)
    for name in ("t_roll", "x_roll", "v_roll", "omega_roll"):
        if name not in values:
            continue
        new[name] = got[name]
        if not (math.isfinite(values[name]) and math.isfinite(got[name])):
            continue  # an overflowed result (null, with its warning) has no error estimate
        denominator = max(abs(values[name]), scales[name])
        errors[name] = abs(got[name] - values[name]) / denominator if denominator else 0.0
    worst = max(errors.values(), default=0.0)
    extra = {"error_estimate": worst, "ode_error": errors,
             "timing": {"closed_form_s": closed_form_s, "ode_s": ode_s},
             "ode": {"solver": ode.solver, "rtol": ode.rtol, "atol": ode.atol,
                     "steps": ode.steps, "nfev": ode.nfev}}
    notes = []
    if tol < ODE_FLOOR:
        notes.append(f"--rtol {tol:g} is below what solve_ivp accepts; the ODE ran at "
                     f"{ODE_FLOOR:.3g}")
    if worst > tol:
        notes.append(f"the ODE result differs from the closed form by {worst:.2g} (relative), "
                     f"more than --rtol {tol:g}; the closed form is exact to rounding")
    return new, "ode", extra, notes


def _physics_warnings(onset, kappa: float, mu: float, on_slope: bool) -> list[str]:
    notes = []
    if onset.sigma == 0:
        notes.append("v0 = r omega0: the body is set down already rolling (no slip), so "
                     "t_roll = 0 and x_roll = 0")
    if kappa == 0.0:
        notes.append("kappa = 0: a body with no moment of inertia about its centre rolls at "
                     "once (t_roll = 0, v_roll = v0) whatever its spin; a body that cannot "
                     "turn (a block) never rolls, it slides until it stops")
    if on_slope and mu < onset.mu_min:
        notes.append(f"rolling on this slope needs static friction mu_s >= mu_min = "
                     f"{_num(onset.mu_min)}; unless the static coefficient reaches it (mu = "
                     f"{_num(mu)} is below), the slip reverses at t_roll and the body "
                     "slides on")
    return notes


#: The formulas of rolling-onset in LaTeX (:mod:`dyncalc.result.explain`), all values in SI.
ROLLING_LATEX = (
    r"$s0 = $v0 - $r\,$omega0",
    Formula(r"$t_roll = \frac{$kappa\,\lvert $s0\rvert}{$mu\,$g\,(1 + $kappa)}",
            lambda v: not v["slope"]),
    Formula(r"$t_roll = \frac{$kappa\,\lvert $s0\rvert}{$g\,\left($mu\,(1 + $kappa)\,"
            r"\cos $beta + $sigma\,$kappa\,\sin $beta\right)}", lambda v: v["slope"]),
    Formula(r"$v_roll = \frac{$v0 + $kappa\,$r\,$omega0}{1 + $kappa}", lambda v: not v["slope"]),
    Formula(r"$v_roll = \frac{$v0}{1 + $kappa}", lambda v: not v["slope"]),
    Formula(r"$v_roll = $v0 - $g\,\left(\sin $beta + $sigma\,$mu\,\cos $beta\right)\,$t_roll",
            lambda v: v["slope"]),
    r"$x_roll = \frac{($v0 + $v_roll)\,$t_roll}{2}",
    r"$omega_roll = \frac{$v_roll}{$r}",
    r"$mu_min = \frac{$kappa\,\lvert\tan $beta\rvert}{1 + $kappa}",
)


def _latex_lines(onset, kappa, mu, g, v0, radius, omega0, incline, slope):
    """(LaTeX formula, LaTeX substituted) of ``ROLLING_LATEX`` at these values."""
    from ..result.explain import Term, render_formulas, symbol_latex

    given = {"kappa": (kappa, ""), "mu": (mu, ""), "g": (g, "m/s^2"), "v0": (v0, "m/s"),
             "s0": (onset.s0, "m/s"), "sigma": (float(onset.sigma), ""),
             "t_roll": (onset.t, "s"), "v_roll": (onset.v, "m/s"), "x_roll": (onset.x, "m")}
    if radius is not None:
        given.update(r=(radius, "m"), omega0=(omega0, "rad/s"), omega_roll=(onset.omega, "rad/s"))
    if incline is not None:
        given.update(beta=(incline.quantity.magnitude, incline.unit_text or "rad"),
                     mu_min=(onset.mu_min, ""))
    terms = {name: Term(symbol_latex(name), float(value), unit)
             for name, (value, unit) in given.items() if value is not None}
    latex, latex_substituted, _text = render_formulas(ROLLING_LATEX, terms, {"slope": slope})
    return latex, latex_substituted


def _explain(onset, kappa, body_name, mu, g, v0, radius, omega0, incline, sin_b, cos_b,
             method, extra) -> Explanation:
    sigma = {1: "+1", -1: "-1", 0: "0"}[onset.sigma]
    kappa_text = (f"kappa = {_num(kappa)} ({body_name})" if body_name else
                  f"kappa = {_num(kappa)}")
    slope = incline is not None and sin_b != 0.0
    formula = ["slip of the contact point s = v - r omega; while it slips, kinetic friction "
               "mu m g cos(beta) opposes it (sigma = sign(s0)); the mass cancels"]
    if slope:
        formula += [
            "v' = -g (sin(beta) + sigma mu cos(beta)),  r omega' = sigma mu g cos(beta) / kappa",
            "t_roll = kappa |s0| / (g (mu (1 + kappa) cos(beta) + sigma kappa sin(beta)))",
            "v_roll = v0 - g (sin(beta) + sigma mu cos(beta)) t_roll",
        ]
    else:
        formula += [
            "v' = -sigma mu g,  r omega' = sigma mu g / kappa",
            "t_roll = kappa |s0| / (mu g (1 + kappa))",
            "v_roll = (v0 + kappa r omega0) / (1 + kappa)  (angular momentum about the contact "
            "point is conserved)",
        ]
    formula.append("x_roll = (v0 + v_roll) t_roll / 2 = v0 t_roll - a t_roll^2 / 2  (a = -v')")
    if body_name == "solid-sphere" and omega0 == 0.0 and not slope:
        formula.append("solid sphere without spin (kappa = 2/5): t_roll = 2 v0 / (7 mu g), "
                       "x_roll = 12 v0^2 / (49 mu g), v_roll = 5 v0 / 7")
    if radius is not None:
        formula.append("omega_roll = v_roll / r")
    if incline is not None:
        formula.append("mu_min = kappa |tan(beta)| / (1 + kappa)")

    rim = f"{_num(radius)} m × {_term(omega0, 'rad/s')}" if radius is not None else "0"
    sub = [f"{kappa_text}, mu = {_num(mu)}, g = {_num(g)} m/s^2"]
    if incline is not None:
        sub.append(f"beta = {_num(incline.quantity.magnitude)} {incline.unit_text or 'rad'}: "
                   f"sin(beta) = {_num(sin_b)}, cos(beta) = {_num(cos_b)}")
    sub.append(f"s0 = {_num(v0)} m/s - {rim} = {_num(onset.s0)} m/s, sigma = {sigma}")
    if onset.sigma == 0:
        sub.append("s0 = 0: set down already rolling, so t_roll = 0, x_roll = 0, v_roll = v0")
    elif kappa == 0.0:
        sub.append("kappa = 0: t_roll = 0, x_roll = 0, v_roll = v0")
    elif slope:
        sub.append(f"t_roll = {_num(kappa)} × {_num(abs(onset.s0))} m/s / ({_num(g)} m/s^2 × "
                   f"{_num(onset.drive)}) = {_num(onset.t)} s")
        sub.append(f"v_roll = {_num(v0)} m/s - {_term(onset.accel, 'm/s^2')} × "
                   f"{_num(onset.t)} s = {_num(onset.v)} m/s")
    else:
        sub.append(f"t_roll = {_num(kappa)} × {_num(abs(onset.s0))} m/s / ({_num(mu)} × "
                   f"{_num(g)} m/s^2 × {_num(1 + kappa)}) = {_num(onset.t)} s")
        sub.append(f"v_roll = ({_num(v0)} m/s + {_num(kappa)} × {_term(onset.rim0, 'm/s')}) / "
                   f"{_num(1 + kappa)} = {_num(onset.v)} m/s")
    if onset.sigma != 0 and kappa != 0.0:
        sub.append(f"x_roll = ({_num(v0)} m/s + {_term(onset.v, 'm/s')}) × {_num(onset.t)} s "
                   f"/ 2 = {_num(onset.x)} m")
    if radius is not None:
        sub.append(f"omega_roll = {_term(onset.v, 'm/s')} / {_num(radius)} m = "
                   f"{_num(onset.omega)} rad/s")
    if incline is not None:
        sub.append(f"mu_min = {_num(onset.mu_min)}")

    assumptions = ["rigid round body on a rigid surface, one contact point; Coulomb friction "
                   "(kinetic mu while it slips); no rolling resistance, no air drag",
                   "x_roll is the displacement along the surface from the start to where "
                   "rolling begins (positive in the direction of v0), not the path length"]
    if onset.reverses:
        assumptions.append(
            f"the backspin brings it back: it stops at t = {_num(onset.t_turn)} s, "
            f"{_num(onset.x_turn)} m from the start, and returns; the path length is "
            f"path_roll = {_num(onset.path)} m, and v_roll < 0 is motion back toward the start")
    if incline is not None:
        assumptions.append("after t_roll it keeps rolling while the static friction "
                           "coefficient is at least mu_min")
    else:
        assumptions.append("after t_roll it rolls on at v_roll (friction then does no work)")
    if method == "ode":
        timing = extra["timing"]
        ode = extra["ode"]
        assumptions.append(
            f"method ode: solve_ivp ({ode['solver']}, rtol {ode['rtol']:g}, {ode['steps']} "
            f"steps) with an event at zero slip; it differs from the closed form by "
            f"{extra['error_estimate']:.2g} (relative); time {timing['ode_s'] * 1e3:.3g} ms "
            f"against {timing['closed_form_s'] * 1e3:.3g} ms for the closed form")
    latex, latex_substituted = _latex_lines(onset, float(kappa), mu, g, v0, radius, omega0,
                                            incline, slope)
    return Explanation(formula=formula, substituted=sub, assumptions=assumptions,
                       reference=_REFERENCE, latex=latex, latex_substituted=latex_substituted)


# --- whole columns at once (batch) -------------------------------------------------------------

def columns(given: dict, settings: dict):
    """The results of a block of batch rows at once, or ``None`` when not vectorised here.

    ``given`` maps the columns the block gives (``v0``, ``mu``, ``body`` or ``kappa``,
    ``radius``, ``omega0``, ``g``, ``incline``: the record's input names) to SI arrays
    (``body`` a str array); ``settings`` holds ``method`` and, with an ``incline`` column,
    ``units["incline"]`` (the unit it was typed in; ``""`` for a bare number). The closed form runs through the kernel of
    :func:`~dyncalc.physics.rolling.rolling_onset` (row by row: its arithmetic is exact
    rational, see there); ``--method ode``, an incline typed in another unit than radians
    (its sine is taken in the unit typed) and ``body`` with ``kappa`` give ``None``. Exact
    where the one-off gives these values with no warning (set down rolling, ``kappa = 0``,
    ``mu < mu_min``, an underflow or overflow, a reversal) and no refusal.
    """
    from ..physics.bodies import KAPPA
    from ..physics.columns import Columns
    from ..physics.rolling import rolling_onset
    from .columns import typed_in_si

    keys = set(given)
    if (settings.get("method") not in (None, "auto", "closed-form")
            or not {"v0", "mu"} <= keys or {"body", "kappa"} <= keys
            or keys - {"v0", "mu", "body", "kappa", "radius", "omega0", "g", "incline"}
            or ("incline" in keys and not typed_in_si(settings, "incline", "rad"))):
        return None
    arrays = {name: np.asarray(value, dtype=float) for name, value in given.items()
              if name != "body"}
    n = len(arrays["v0"])
    ok = np.ones(n, dtype=bool)
    for value in arrays.values():
        ok &= np.isfinite(value)
    if "kappa" in keys:
        kappa = arrays["kappa"]
    else:
        words = np.asarray(given.get("body", np.full(n, DEFAULT_BODY)), dtype=str)
        kappa = np.array([KAPPA.get(word.strip(), math.nan) for word in words.tolist()])
        ok &= np.isfinite(kappa)
    omega0 = arrays.get("omega0")
    if omega0 is not None and "radius" not in keys:
        ok &= omega0 == 0.0
        omega0 = None
    for name in ("mu", "g", "radius"):
        if name in arrays:
            ok &= arrays[name] > 0.0
    ok &= (arrays["v0"] >= 0.0) & (kappa >= 0.0)
    v0 = np.where(ok, arrays["v0"], 1.0)
    out = rolling_onset.columns(v0 + 0.0, arrays["mu"], np.where(ok, kappa, 0.4),
                                g=arrays.get("g"), r=arrays.get("radius"), omega0=omega0,
                                incline=arrays.get("incline"))
    values = out.values
    for value in values.values():
        ok &= np.isfinite(value)
    ok &= values["t_roll"] != 0.0          # set down rolling, or kappa = 0: a note
    if "mu_min" in values:
        with np.errstate(invalid="ignore"):
            ok &= ~(arrays["mu"] < values["mu_min"])
    return Columns(values, exact=out.exact & ok, model="coulomb-friction",
                   method="closed-form")


# --- the command record ----------------------------------------------------------------------

def _run(values: dict[str, str | None], words=(), *, rtol=None, strict=False) -> Result:
    texts = {p.name: values.get(p.name) for p in COMMAND.inputs}
    return rolling_onset_result(texts, method=values.get("method"), rtol=rtol, strict=strict)


COMMAND = Command(
    "rolling-onset",
    "When a sliding ball, cylinder or hoop starts to roll.",
    """When a ball, cylinder or hoop set down sliding starts to roll without slipping.

    Kinetic friction opposes the slip of the contact point, v0 - r omega0, until it vanishes.
    Results: t_roll (s), x_roll (m, displacement along the surface), v_roll (m/s), with
    --radius omega_roll (rad/s), with backspin that brings the body back path_roll (m), on a
    slope mu_min (the static friction that keeps it rolling). The mass cancels; bare numbers
    are SI.

    \b
    Examples:
      dyncalc rolling-onset --v0 "5 m/s" --mu 0.3 --explain       # E3.45, a bowling ball
      dyncalc rolling-onset --v0 "2 m/s" --mu 0.2 --radius 28.5mm --omega0 "-300 rad/s"
      dyncalc rolling-onset --v0 "3 m/s" --mu 0.25 --body hoop --incline -10deg
      dyncalc rolling-onset --v0 15mph --mu 0.2 --method ode --json
    """,
    (
        Parameter("v0", VELOCITY, "Initial sliding speed of the centre, e.g. '5 m/s' or 12mph "
                  "(>= 0; its direction is the positive one).", "V0"),
        Parameter("mu", DIMENSIONLESS, "Kinetic friction coefficient at the contact (> 0).",
                  "MU"),
        Parameter("body", None, "solid-sphere (default), hollow-sphere, solid-cylinder, "
                  "hollow-cylinder or hoop.", "BODY", kind="text",
                  choices=lambda: tuple(_bodies())),
        Parameter("kappa", DIMENSIONLESS, "Shape factor J_C/(m r^2) of any body, instead of "
                  "--body (>= 0).", "KAPPA"),
        Parameter("radius", LENGTH, "Radius: needed with --omega0, and gives omega_roll.", "R"),
        Parameter("omega0", ANGULAR_RATE, "Initial spin, e.g. '30 rad/s' or '-600 rpm': "
                  "positive is the sense of rolling forward, negative is backspin (default 0; "
                  "needs --radius).", "OMEGA0"),
        Parameter("g", ACCELERATION, "Gravitational acceleration (default 9.80665 m/s^2).",
                  "G"),
        Parameter("incline", ANGLE, "Slope angle, e.g. 10deg: positive when the body moves "
                  "uphill, negative downhill (between -90 and 90 deg).", "ANGLE"),
        Parameter("method", None, "auto or closed-form (the default: exact to rounding), or "
                  "ode: integrate the equations of motion with scipy's solve_ivp to --rtol, "
                  "and report the difference from the closed form and both timings (JSON "
                  "error_estimate, timing; --explain).", "METHOD", default="auto",
                  kind="setting", choices=METHODS),
    ),
    results_from_kinds(_KINDS),
    _run,
    columns=columns,
)
