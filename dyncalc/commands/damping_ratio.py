"""``damping-ratio``: the damping ratio, decrement, regime and damped period from a measurement.

:func:`damping_ratio` takes the texts the user typed; :func:`read` parses and checks each of them
once (``dyncalc.units``) into :class:`DampingInputs`, and :func:`compute` calls the physics
(``dyncalc.physics.damping``, ``dyncalc.physics.decay_fit``, or a damping scene through the
scene runner) and returns a :class:`~dyncalc.result.Result`. ``--plot`` draws its free decay
(:func:`dyncalc.cli.plot.plot_decay`).

The input forms, exactly one of them:

* ``c, k, m``            a viscous damper, a spring and a mass;
* ``decrement``          the logarithmic decrement per cycle;
* ``ratio, cycles``      the ratio ``x_i / x_(i+N)`` of two peaks ``N`` whole cycles apart
  (``cycles`` defaults to 1: successive peaks);
* ``amplitudes``         successive peaks, one per cycle, fitted;
* ``scene, params``      a scene with a damper (rod-in-fluid, pendulum-spring-dashpot,
  frame-brace-damper), with ``NAME=QUANTITY`` words.

``omega`` (the undamped natural angular frequency), or ``k`` and ``m``, add the damped
quantities to the decrement, ratio and amplitude forms.
"""
from __future__ import annotations

import math
import re

from ..errors import InputError, PhysicsError
from ..lazy import numpy as np
from ..result.explain import Formula
from ..result.entries import Entry, Explanation, Result, entry_from_parsed, format_number
from ..result.kinds import DECAY_RATE
from ..units import (ACCELERATION, ANGULAR_RATE, CYCLE_RATE, DAMPING, DIMENSIONLESS, MASS,
                     STIFFNESS, TIME, Dim, parse_quantity, parse_unit)
from .record import Command, Parameter, results_from_kinds
from .words import gather_texts

__all__ = ["COMMAND", "damping_ratio", "read", "compute", "DampingInputs", "SceneTexts",
           "parse_amplitudes", "parse_cycles", "damping_scene_names", "MAX_PEAKS"]

#: ``2 pi`` (as :data:`dyncalc.physics.damping.TWO_PI`).
_TWO_PI = 2.0 * math.pi

#: The most peaks ``--amplitudes`` reads.
MAX_PEAKS = 100_000

#: name -> (dimension, display unit, symbol, description) of every result this command adds.
_KINDS = {
    "zeta": (DIMENSIONLESS, "", "ζ", "damping ratio"),
    "delta": (DIMENSIONLESS, "", "δ", "logarithmic decrement per cycle"),
    "regime": (None, "", "regime", "undamped / underdamped / critically damped / overdamped"),
    "Q": (DIMENSIONLESS, "", "Q", "quality factor 1/(2 zeta)"),
    "c_c": (DAMPING, "N*s/m", "c_c", "critical damping coefficient 2 sqrt(k m)"),
    "c": (DAMPING, "N*s/m", "c", "damping coefficient"),
    "omega": (ANGULAR_RATE, "rad/s", "ω", "undamped natural angular frequency"),
    "xi": (DECAY_RATE, "1/s", "ξ", "decay rate zeta omega (envelope exp(-xi t))"),
    "omega_d": (ANGULAR_RATE, "rad/s", "ωd", "damped angular frequency"),
    "f_d": (CYCLE_RATE, "Hz", "fd", "damped frequency"),
    "T_d": (TIME, "s", "Td", "damped period"),
    "residual": (DIMENSIONLESS, "", "s_fit", "rms scatter of ln(peaks) about the fitted envelope"),
    "delta_se": (DIMENSIONLESS, "", "σδ", "standard error of delta from the fit"),
}

_FORMS = ("--c --k --m", "--decrement", "--ratio --cycles", "--amplitudes", "--scene")
_USAGE = ('--c C --k K --m M, --decrement DELTA, --ratio R --cycles N, --amplitudes '
          '"x0,x1,...", or --scene NAME NAME=QUANTITY ...')


def method_names(scene: str | None = None) -> list[str]:
    """The words ``--method`` takes: the fits of ``--amplitudes``, or with a damping scene
    ``auto`` and that scene's methods: for completion."""
    if scene is not None:
        from ..scenes import get_scene

        try:
            return ["auto", *get_scene(scene).methods]
        except InputError:
            pass
    from ..physics.decay_fit import FIT_METHODS

    return list(FIT_METHODS)


def damping_scene_names() -> list[str]:
    """The scenes with a damper: those whose physics lives in ``dyncalc.physics.damping``."""
    from ..scenes import catalog

    return [name for name, scene in catalog().items()
            if scene.compute.__module__ == "dyncalc.physics.damping"]


# --- reading the inputs ----------------------------------------------------------------------

_NUMBER = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?"
_PEAK_RE = re.compile(_NUMBER)
_BRACKETS_RE = re.compile(r"^\s*[\(\[](.*)[\)\]]\s*(.*)$", re.S)


def parse_amplitudes(text: str, label: str = "--amplitudes") -> tuple[np.ndarray, str]:
    """Successive peaks ``"x0, x1, ..."`` with an optional unit after the last one
    (``"12.1, 8.3, 5.9 mV"``, ``"[12.1, 8.3, 5.9] mm"``) -> (peaks, unit text).

    Commas separate the peaks (so a comma is never a decimal point here). The unit may be any
    unit (a length, a voltage from an oscilloscope, a percentage): only ratios of the peaks
    matter. Every peak must be a positive finite plain number.

    >>> parse_amplitudes("12.1, 8.3, 5.9 mV")
    (array([12.1,  8.3,  5.9]), 'mV')
    """
    if not isinstance(text, str) or not text.strip():
        raise InputError(f'{label} needs the peaks separated by commas, e.g. {label} '
                         '"12.1, 8.3, 5.9 mm"')
    m = _BRACKETS_RE.match(text)
    if m:
        body, unit = m.group(1), m.group(2).strip()
        parts = body.split(",")
    else:
        parts = text.split(",")
        last = parts[-1].strip()
        num = _PEAK_RE.match(last)
        unit = last[num.end():].strip() if num else ""
        if num:
            parts[-1] = num.group(0)
    if len(parts) > MAX_PEAKS:
        raise InputError(f"{label}: {len(parts)} peaks; dyncalc fits at most {MAX_PEAKS}")
    if len(parts) < 2:
        raise InputError(f"{label} needs at least 2 peaks (one per cycle) to measure a "
                         f"decrement; got 1")
    values = []
    for index, part in enumerate(parts):
        part = part.strip()
        if not part:
            raise InputError(f"{label}: x{index} is empty; separate the peaks by single "
                             "commas")
        if not _PEAK_RE.fullmatch(part):
            raise InputError(f"{label}: x{index} ({part[:40]!r}) is not a plain number; "
                             f'give the peaks as numbers with one unit at the end, e.g. '
                             f'"12.1, 8.3, 5.9 mm"')
        value = float(part)
        if math.isinf(value):
            raise InputError(f"{label}: x{index} ({part[:40]}) overflows float64")
        if value <= 0.0:
            raise InputError(f"{label}: every peak must be positive (give the peak magnitudes "
                             f"|x|); x{index} is {part}")
        values.append(value)
    if unit:
        parse_unit(unit, label=label)  # a real unit, or a clear refusal
    return np.array(values), unit


def parse_cycles(text: str, label: str = "--cycles") -> int:
    """A whole number of cycles, at least 1.

    >>> parse_cycles("10"), parse_cycles("1e2")
    (10, 100)
    """
    return _read_cycles(text, label)[0]


def _read_cycles(text: str, label: str = "--cycles") -> tuple[int, float | None]:
    """:func:`parse_cycles` and the uncertainty typed with the count (``None`` without)."""
    parsed = parse_quantity(text, DIMENSIONLESS, label=label)
    value = parsed.si
    if not float(value).is_integer():
        raise InputError(f"{label} must be a whole number of cycles (1, 2, 3, ...); got "
                         f"{value:.15g}")
    if value < 1:
        raise InputError(f"{label} must be at least 1 (a whole number of cycles); got "
                         f"{value:.15g}")
    return int(value), parsed.uncertainty


# --- the command -----------------------------------------------------------------------------

class SceneTexts:
    """A damping scene as checked by :func:`read`: the scene, its parameter texts and labels
    (a ``delta=`` or ``Q=`` given to solve from already turned into ``zeta=``; ``given`` is
    then its name and the value read), and the settings
    :func:`~dyncalc.commands.natural_frequency.compute_scene` takes. The scene's texts are
    read once, by the scene runner, when :func:`compute` runs it."""

    __slots__ = ("scene", "texts", "labels", "method", "rtol", "strict", "given")

    def __init__(self, scene, texts: dict[str, str], labels: dict[str, str], method, rtol,
                 strict: bool, given=None):
        self.scene, self.texts, self.labels = scene, texts, labels
        self.method, self.rtol, self.strict = method, rtol, strict
        self.given = given


class DampingInputs:
    """A damping measurement as read by :func:`read`: what :func:`compute` needs, and nothing
    typed is read again after it.

    ``form`` is the option that gave the damping (``--c``, ``--decrement``, ``--ratio``,
    ``--amplitudes``, ``--scene``); ``inputs`` the input entries in the order read; ``parsed``
    the quantities read, by name (``c``, ``k``, ``m``, ``omega``, ``decrement``, ``ratio``);
    ``cycles`` the whole cycles of ``--ratio`` and ``cycles_sigma`` an uncertainty typed with
    them; ``fit`` the decay fitted to ``--amplitudes`` (how the peaks are read into a
    decrement: it refuses peaks that grow) and ``method`` its method; ``scene`` a scene's
    checked texts (:class:`SceneTexts`).
    """

    __slots__ = ("form", "inputs", "parsed", "cycles", "cycles_sigma", "fit", "method",
                 "scene")

    def __init__(self, form: str):
        self.form = form
        self.inputs: dict[str, Entry] = {}
        self.parsed: dict = {}
        self.cycles: int | None = None
        self.cycles_sigma: float | None = None
        self.fit = None
        self.method: str | None = None
        self.scene: SceneTexts | None = None

    def __repr__(self) -> str:
        return f"DampingInputs({self.form!r}, {list(self.inputs)!r})"


def damping_ratio(*, c: str | None = None, k: str | None = None, m: str | None = None,
                  omega: str | None = None, decrement: str | None = None,
                  ratio: str | None = None, cycles: str | None = None,
                  amplitudes: str | None = None, scene: str | None = None,
                  params: tuple[str, ...] | list[str] = (), g: str | None = None,
                  method: str | None = None, rtol: float | None = None,
                  strict: bool = False) -> Result:
    """The damping ratio and everything that follows from it, from one measurement
    (:func:`read`, then :func:`compute`).

    Every argument is the text the user typed (``None`` when not given); see the module's
    docstring for the forms. Returns a :class:`Result` with ``zeta``, ``delta``, ``regime``,
    ``Q`` and, as the inputs allow, ``c_c``, ``c``, ``omega``, ``xi``, ``omega_d``, ``f_d``,
    ``T_d`` (and ``residual``, ``delta_se`` for a fit; the scene's own results for a scene).

    >>> r = damping_ratio(ratio="10", cycles="10")  # E5.18
    >>> round(r.results["zeta"].si, 6), r.results["regime"].si
    (0.036622, 'underdamped')
    """
    return compute(read(c=c, k=k, m=m, omega=omega, decrement=decrement, ratio=ratio,
                        cycles=cycles, amplitudes=amplitudes, scene=scene, params=params, g=g,
                        method=method, rtol=rtol, strict=strict))


def read(*, c: str | None = None, k: str | None = None, m: str | None = None,
         omega: str | None = None, decrement: str | None = None, ratio: str | None = None,
         cycles: str | None = None, amplitudes: str | None = None, scene: str | None = None,
         params: tuple[str, ...] | list[str] = (), g: str | None = None,
         method: str | None = None, rtol: float | None = None,
         strict: bool = False) -> DampingInputs:
    """The texts of :func:`damping_ratio` -> :class:`DampingInputs`: the form chosen, every
    quantity parsed and checked once (the peaks fitted), a scene's texts checked."""
    forms = []
    if c is not None:
        forms.append("--c")
    if decrement is not None:
        forms.append("--decrement")
    if ratio is not None or cycles is not None:
        forms.append("--ratio" if ratio is not None else "--cycles")
    if amplitudes is not None:
        forms.append("--amplitudes")
    if scene is not None or params:
        forms.append("--scene")
    if not forms:
        raise InputError(f"damping-ratio needs one measurement of the damping: {_USAGE}")
    if len(forms) > 1:
        raise InputError(f"damping-ratio takes one measurement of the damping, not "
                         f"{len(forms)}: got {' and '.join(forms)}; give one of {_USAGE}")
    form = forms[0]
    if form == "--scene":
        if scene is None:
            raise InputError("NAME=QUANTITY parameters need --scene NAME (a scene with a "
                             f"damper: {', '.join(damping_scene_names())})")
        if omega is not None:
            raise InputError("--omega is not used with --scene: the scene gives its own "
                             "natural frequency")
        read_in = DampingInputs(form)
        read_in.scene = _read_scene(scene, params, k, m, g, method, rtol, strict)
        return read_in
    if g is not None:
        raise InputError("--g is a scene parameter: use it with --scene")
    if form == "--cycles":
        raise InputError("--cycles goes with --ratio R (the ratio x_i / x_(i+N) of two peaks "
                         "N cycles apart)")
    if form == "--c" and omega is not None:
        need = " and ".join(f"--{n}" for n, v in (("k", k), ("m", m)) if v is None)
        raise InputError("--c goes with --k and --m (zeta = c / (2 sqrt(k m))), not with "
                         f"--omega: give {need or '--k and --m'} instead of --omega")
    if omega is not None and k is not None and m is not None:
        raise InputError("give the natural frequency as --omega or as --k and --m, not both")
    if omega is not None and (k is not None or m is not None):
        given = "--k" if k is not None else "--m"
        raise InputError(f"{given} does not go with --omega: give the natural frequency as "
                         "--omega, or as --k and --m")
    if form == "--c":
        if k is None or m is None:
            need = " and ".join(f"--{n}" for n, v in (("k", k), ("m", m)) if v is None)
            raise InputError(f"--c needs {need} too: zeta = c / (2 sqrt(k m))")
    elif (k is None) != (m is None):
        given, other = ("--k", "--m") if m is None else ("--m", "--k")
        raise InputError(f"{given} needs {other}: together they give the natural frequency "
                         "sqrt(k/m) and c_c = 2 sqrt(k m)")
    read_in = DampingInputs(form)
    read_in.method = _check_method(form, method)

    def quantity(name: str, text: str, dim: Dim, label: str, constraint: str | None):
        parsed = parse_quantity(text, dim, label=label, strict=strict, constraint=constraint)
        read_in.inputs[name] = entry_from_parsed(name, parsed, dim)
        read_in.parsed[name] = parsed
        return parsed

    if form == "--c":
        quantity("c", c, DAMPING, "--c", "nonnegative")
        quantity("k", k, STIFFNESS, "--k", "positive")
        quantity("m", m, MASS, "--m", "positive")
        return read_in
    if form == "--decrement":
        quantity("decrement", decrement, DIMENSIONLESS, "--decrement", "nonnegative")
    elif form == "--ratio":
        pr = quantity("ratio", ratio, DIMENSIONLESS, "--ratio", None)
        read_in.cycles, read_in.cycles_sigma = _read_cycles(cycles if cycles is not None
                                                            else "1")
        read_in.inputs["cycles"] = Entry("cycles", float(read_in.cycles), DIMENSIONLESS,
                                         description="whole cycles between the two peaks",
                                         text="1" if cycles is None else cycles)
        if pr.si < 1.0:
            raise InputError(f"--ratio must be at least 1: it is x_i / x_(i+N), the "
                             f"earlier peak over the later one; got {pr.si:.15g} (for "
                             f"decaying peaks, did you mean {1.0 / pr.si:.6g}?)"
                             if pr.si > 0 else
                             f"--ratio must be at least 1: it is x_i / x_(i+N), the "
                             f"earlier peak over the later one; got {pr.si:.15g}")
    else:
        peaks, unit = parse_amplitudes(amplitudes)
        read_in.inputs["amplitudes"] = Entry("amplitudes", peaks, None, unit=unit,
                                             description="successive peaks, one per cycle",
                                             text=amplitudes)
        read_in.fit = _fit(peaks, read_in.method, rtol)
    if omega is not None:
        quantity("omega", omega, ANGULAR_RATE, "--omega", "positive")
    if k is not None:
        quantity("k", k, STIFFNESS, "--k", "positive")
        quantity("m", m, MASS, "--m", "positive")
    return read_in


def compute(inputs: DampingInputs) -> Result:
    """The Result of a measurement read by :func:`read`, with its ``sensitivity``: exact
    derivatives for the closed forms (:func:`_sensitivity`), a scene's own carried through
    zeta to the results added here (:func:`_from_scene`)."""
    if inputs.form == "--scene":
        return _from_scene(inputs.scene)
    from ..physics import damping as phys

    form, parsed = inputs.form, inputs.parsed
    extra: dict = {}
    formula: list[str] = []
    reference = ""
    fit = inputs.fit
    exact_zeros: set[str] = set()
    c_unit = None
    if form == "--c":
        pc, pk, pm = parsed["c"], parsed["k"], parsed["m"]
        outcome = phys.damping_from_coefficients(pc.quantity, pk.quantity, pm.quantity)
        c_unit = inputs.inputs["c"].unit if pc.unit_text else None
        if pc.si == 0.0:
            exact_zeros |= {"zeta", "delta", "xi"}
        formula = ["c_c = 2 sqrt(k m), zeta = c / c_c, omega = sqrt(k/m), xi = c / (2 m)",
                   "underdamped: omega_d = sqrt(4 k m - c^2) / (2 m), T_d = 2 pi / omega_d, "
                   "delta = 2 pi c / sqrt(4 k m - c^2)", "Q = c_c / (2 c) = 1/(2 zeta)"]
    else:
        delta = _decrement(inputs)
        if form == "--ratio":
            formula = ["delta = ln(R) / N"]
            reference = "E5.18"
        elif form == "--amplitudes":
            extra["fit"] = fit.as_dict()
            formula = (["ln x_i = ln x0 - delta i, least squares over the peaks i = 0 .. n-1"]
                       if inputs.method == "log-linear" else
                       ["x_i = x0 exp(-delta i), least squares over the peaks i = 0 .. n-1"])
        if delta == 0.0:
            exact_zeros |= {"zeta", "delta", "xi", "c"}
        kw = {name: parsed[name].quantity for name in ("omega", "k", "m") if name in parsed}
        outcome = phys.damping_from_decrement(delta, **kw)
        formula += ["zeta = delta / sqrt(4 pi^2 + delta^2), Q = 1/(2 zeta)"]
        if kw:
            formula.append("omega_d = omega sqrt(1 - zeta^2) = 2 pi omega / sqrt(4 pi^2 + "
                           "delta^2), T_d = 2 pi / omega_d, xi = zeta omega")
        if "k" in kw:
            formula.append("omega = sqrt(k/m), c_c = 2 sqrt(k m), c = zeta c_c")

    results = {name: _entry(name, value) for name, value in outcome.values.items()}
    if c_unit is not None:
        for name in ("c", "c_c"):
            results[name].unit = c_unit
        results["c"].exact = inputs.inputs["c"].exact
    if fit is not None:
        results["residual"] = _entry("residual", fit.residual)
        exact_zeros |= {"residual", "delta_se"}  # 0 for exact peaks, never an underflow
        if fit.delta_se is not None:
            results["delta_se"] = _entry("delta_se", fit.delta_se)
    warnings = list(outcome.warnings) + (fit.warnings if fit is not None else [])
    result = Result(command="damping-ratio", results=results, inputs=inputs.inputs,
                    scene=None, model="linear", method=inputs.method or "closed-form",
                    warnings=warnings, extra=extra)
    result.add_overflow_warnings()
    result.explanation = _explain(formula, inputs.inputs, results, reference, fit, form)
    result.add_underflow_warnings(exact_zeros)
    result.sensitivity = lambda: _sensitivity(inputs, results)
    return result


def _decrement(inputs: DampingInputs) -> float:
    """The logarithmic decrement per cycle the measurement gives (not for ``--c``)."""
    from ..physics.damping import decrement_from_ratio

    if inputs.form == "--decrement":
        return inputs.parsed["decrement"].si
    if inputs.form == "--ratio":
        return decrement_from_ratio(inputs.parsed["ratio"].si, inputs.cycles)
    return inputs.fit.delta


# --- derivatives, for the propagation of uncertainties ---------------------------------------

def _grad(*terms) -> dict:
    """``sum a * g`` over the ``(a, g)`` pairs: the chain rule on gradients, a gradient being
    {input name: derivative in SI}."""
    out: dict = {}
    for coefficient, gradient in terms:
        for name, derivative in gradient.items():
            out[name] = out.get(name, 0.0) + coefficient * derivative
    return out


def _gradients(inputs: DampingInputs, values: dict[str, float]) -> dict[str, dict]:
    """The gradient of every result of a closed form with respect to the inputs read, by
    the chain rule (in numpy floats: an overflow is ``inf``, never an exception).

    ``--c``: ``c_c = 2 sqrt(k m)``, ``omega = sqrt(k/m)``, ``xi = c/(2m)``,
    ``zeta = c/c_c``, ``Q = c_c/(2c)``, ``s = sqrt(1 - zeta^2) = omega_d/omega``
    (``ds = -(zeta/s) d zeta``), ``delta = 2 pi zeta/s`` (``d delta = (2 pi/s^3) d zeta``),
    ``omega_d = omega s``. The decrement forms: ``delta`` (``--decrement``),
    ``ln(R)/N`` (``--ratio``) or the fit (no uncertain input); ``h = hypot(2 pi, delta)``,
    ``zeta = delta/h`` (``d zeta = (2 pi)^2/h^3 d delta``), ``Q = h/(2 delta)``,
    ``s = 2 pi/h``, ``omega`` typed or ``sqrt(k/m)``, ``xi = zeta omega``,
    ``omega_d = omega s``, ``c = zeta c_c``. Always ``f_d = omega_d/(2 pi)``,
    ``T_d = 2 pi/omega_d``.

    Parameters
    ----------
    inputs : DampingInputs
        The measurement as read (not a scene).
    values : dict
        The numeric results in SI, by name (``omega_d`` of ``--c`` gives ``s``).
    """
    f64 = np.float64
    x = {name: f64(parsed.si) for name, parsed in inputs.parsed.items()}
    two_pi, one = f64(_TWO_PI), f64(1.0)
    g: dict[str, dict] = {}
    omega = None
    if "k" in x:
        k, m = x["k"], x["m"]
        c_c, omega = 2.0 * np.sqrt(k) * np.sqrt(m), np.sqrt(k) / np.sqrt(m)
        g["c_c"] = _grad((c_c / (2.0 * k), {"k": one}), (c_c / (2.0 * m), {"m": one}))
        g["omega"] = _grad((omega / (2.0 * k), {"k": one}), (-omega / (2.0 * m), {"m": one}))
    if inputs.form == "--c":
        c = x["c"]
        zeta, q = c / c_c, c_c / (2.0 * c)
        g["c"] = {"c": one}
        g["xi"] = _grad((1.0 / (2.0 * m), {"c": one}), (-c / (2.0 * m) / m, {"m": one}))
        g["zeta"] = _grad((1.0 / c_c, {"c": one}), (-zeta / c_c, g["c_c"]))
        g["Q"] = _grad((1.0 / (2.0 * c), g["c_c"]), (-q / c, {"c": one}))
        s = f64(values["omega_d"]) / omega if "omega_d" in values else f64(np.nan)
        g["delta"] = _grad((two_pi / s ** 3, g["zeta"]))
        g_s = _grad((-zeta / s, g["zeta"]))
    else:
        if inputs.form == "--decrement":
            delta, g_delta = x["decrement"], {"decrement": one}
        elif inputs.form == "--ratio":
            n = f64(inputs.cycles)
            delta = np.log(x["ratio"]) / n
            g_delta = {"ratio": 1.0 / (x["ratio"] * n), "cycles": -delta / n}
        else:  # the fit: the peaks carry no uncertainty
            delta, g_delta = f64(inputs.fit.delta), {}
        h = np.hypot(two_pi, delta)
        zeta, s = delta / h, two_pi / h
        g["delta"] = g_delta
        g["zeta"] = _grad((s * s / h, g_delta))
        g["Q"] = _grad((-(two_pi / delta) ** 2 / (2.0 * h), g_delta))
        g_s = _grad((-s * delta / (h * h), g_delta))
        if "omega" in x:
            omega = x["omega"]
            g["omega"] = {"omega": one}
        if "k" in x:
            g["c"] = _grad((c_c, g["zeta"]), (zeta, g["c_c"]))
        if omega is not None:
            g["xi"] = _grad((zeta, g["omega"]), (omega, g["zeta"]))
    if omega is not None:
        omega_d = omega * s
        g["omega_d"] = _grad((s, g["omega"]), (omega, g_s))
        g["f_d"] = _grad((1.0 / two_pi, g["omega_d"]))
        g["T_d"] = _grad((-two_pi / omega_d / omega_d, g["omega_d"]))
    return g


def _sensitivity(inputs: DampingInputs, results: dict[str, Entry]):
    """Exact derivatives of the results of a closed form (:func:`_gradients`) with respect
    to the uncertain inputs, named as the inputs are. The fit of ``--amplitudes`` is never
    run again: its peaks are plain numbers, so zeta, delta, Q, ``residual`` and ``delta_se``
    carry no uncertainty, and the rest depends on ``--omega`` or ``--k``, ``--m`` in closed
    form. A whole number of ``--cycles`` has no derivative: a ``±`` typed with it leaves the
    results that go through the decrement unpropagated."""
    from ..result.propagate import Sensitivity, UncertainInput

    uncertain: list[UncertainInput] = []
    for name in inputs.inputs:
        if name == "cycles":
            si, sigma = inputs.cycles, inputs.cycles_sigma
        elif name in inputs.parsed:
            si, sigma = inputs.parsed[name].si, inputs.parsed[name].uncertainty
        else:
            continue
        if sigma is not None:
            uncertain.append(UncertainInput(name, float(si), float(sigma)))
    values = {name: e.si for name, e in results.items()
              if e.dim is not None and not isinstance(e.si, str)}
    with np.errstate(all="ignore"):
        gradients = _gradients(inputs, values)
    count_uncertain = inputs.cycles_sigma is not None
    slopes: dict[str, dict[int, float]] = {}
    failed: set[str] = set()
    for name in values:
        gradient = gradients.get(name, {})
        if count_uncertain and "cycles" in gradient:
            failed.add(name)
        slopes[name] = {i: float(gradient.get(item.name, 0.0))
                        for i, item in enumerate(uncertain) if item.name != "cycles"}
    return Sensitivity(uncertain, slopes, failed)


def _scene_sensitivity(scene_sensitivity, results: dict[str, Entry], given=None):
    """A damping scene's own sensitivity (central differences on its parameters as read,
    :func:`dyncalc.scenes.runner.scene_sensitivity`, or on the values of an inverse problem,
    :func:`dyncalc.scenes.inverse.solve`) carried through zeta to the results added here:
    ``d delta / d zeta = 2 pi / (1 - zeta^2)^(3/2)``, ``d Q / d zeta = -1 / (2 zeta^2)``.
    A ``delta=`` or ``Q=`` solved from (``given``) is the input, not the zeta it became
    (:func:`_as_given`)."""
    sensitivity = scene_sensitivity()
    if given is not None and given[1].uncertainty is not None:
        _as_given(sensitivity, given, results)
    zeta = np.float64(results["zeta"].si)
    factors = {}
    with np.errstate(all="ignore"):
        if "delta" in results:
            factors["delta"] = _TWO_PI / np.sqrt((1.0 - zeta) * (1.0 + zeta)) ** 3
        if "Q" in results:
            factors["Q"] = -0.5 / (zeta * zeta)
        by_zeta = sensitivity.slopes.get("zeta", {})
        for name, factor in factors.items():
            if "zeta" in sensitivity.failed:
                sensitivity.failed.add(name)
                continue
            sensitivity.failed.discard(name)
            sensitivity.slopes[name] = {i: factor * np.asarray(slope, dtype=float)
                                        for i, slope in by_zeta.items()}
    return sensitivity


def _as_given(sensitivity, given, results: dict[str, Entry]) -> None:
    """The target ``zeta`` of an inverse scene, solved from ``delta=`` or ``Q=``, as the
    value typed: named as typed, its slopes times ``d zeta / d delta`` (or ``d Q``)."""
    from ..result.propagate import UncertainInput

    name, parsed = given
    typed = UncertainInput(name, float(parsed.si), float(parsed.uncertainty))
    index = next((i for i, item in enumerate(sensitivity.inputs) if item.name == "zeta"),
                 None)
    if index is None:  # u(zeta) was beyond float64 and not passed on
        sensitivity.inputs.append(typed)
        sensitivity.failed |= {n for n, e in results.items()
                               if e.dim is not None and not isinstance(e.si, str)}
        return
    sensitivity.inputs[index] = typed
    slope = _zeta_slope(name, parsed.si)
    with np.errstate(all="ignore"):
        for row in sensitivity.slopes.values():
            if index in row:
                row[index] = slope * np.asarray(row[index], dtype=float)


def _check_method(form: str, method: str | None) -> str | None:
    """The fitting method for ``--amplitudes`` (``None`` for the closed forms)."""
    from ..physics.decay_fit import FIT_METHODS

    if form == "--amplitudes":
        if method in (None, "auto"):
            return FIT_METHODS[0]
        if method not in FIT_METHODS:
            raise InputError(f"--method {method} is not offered for --amplitudes; it offers "
                             f"{FIT_METHODS[0]} (the default) and {FIT_METHODS[1]}")
        return method
    if method not in (None, "auto", "closed-form"):
        raise InputError(f"--method {method} does not apply to {form}, which has a closed form; "
                         "--method log-linear or nonlinear chooses the fit of --amplitudes")
    return None


def _fit(peaks: np.ndarray, method: str, rtol: float | None):
    """Fit the peaks; refuse peaks that grow, take non-significant growth as no decay."""
    from ..physics.decay_fit import fit_decrement

    fit = fit_decrement(peaks, method=method, rtol=1e-9 if rtol is None else rtol)
    if fit.delta < 0.0:
        se = fit.delta_se
        if se is None or fit.delta + 2.0 * se < 0.0:
            spread = f" +/- {se:.2g}" if se is not None else ""
            raise PhysicsError(f"--amplitudes: the peaks grow (fitted delta = {fit.delta:.4g}"
                               f"{spread} per cycle): that is not a free decay; list the peaks "
                               "in time order, the first peak first")
        fit.warnings.append(f"the peaks do not decay measurably: the fitted delta = "
                            f"{fit.delta:.3g} +/- {se:.2g} per cycle is not distinguishable "
                            "from zero; taken as 0 (undamped)")
        fit.x0 = float(np.exp(np.mean(np.log(peaks))))
        fit.delta = 0.0
    return fit


def _entry(name: str, value) -> Entry:
    dim, unit, symbol, description = _KINDS[name]
    if isinstance(value, str):
        return Entry(name, value, None, unit="", symbol=symbol, description=description)
    if hasattr(value, "units"):
        value = value.to(dim.si.replace("^", "**")).magnitude
    return Entry(name, float(value), dim, unit=unit, symbol=symbol, description=description)


def _shown(entry: Entry) -> str:
    value = entry.value_in()
    unit = f" {entry.unit}" if entry.unit else ""
    return f"{entry.name} = {format_number(value, 6)}{unit}"


#: The formulas of damping-ratio in LaTeX (:mod:`dyncalc.result.explain`); ``form`` is the option
#: that gave the damping (``--c``, ``--decrement``, ``--ratio``, ``--amplitudes``).
DAMPING_LATEX = (
    r"$delta = \frac{\ln $ratio}{$cycles}",
    r"$omega = \sqrt{\frac{$k}{$m}}",
    r"$c_c = 2\,\sqrt{$k\,$m}",
    Formula(r"$zeta = \frac{$c}{$c_c}", lambda v: v["form"] == "--c"),
    Formula(r"$xi = \frac{$c}{2\,$m}", lambda v: v["form"] == "--c"),
    Formula(r"$delta = \frac{2\pi\,$zeta}{\sqrt{1 - $zeta^2}}",
            lambda v: v["form"] in ("--c", "--scene")),
    r"$zeta = \frac{$delta}{\sqrt{4\pi^2 + $delta^2}}",
    Formula(r"$c = $zeta\,$c_c", lambda v: v["form"] != "--c"),
    r"$omega_d = $omega\,\sqrt{1 - $zeta^2}",
    r"$T_d = \frac{2\pi}{$omega_d}",
    r"$xi = $zeta\,$omega",
    r"$Q = \frac{1}{2\,$zeta}",
)


def _formula_lines(inputs, results, form: str):
    """(LaTeX formula, LaTeX substituted, text substituted) of ``DAMPING_LATEX``."""
    from ..result.explain import render_formulas, template_terms

    terms = template_terms([*inputs.values(), *results.values()])
    if "decrement" in terms:  # --decrement is delta itself
        terms.setdefault("delta", terms.pop("decrement"))
    values = {name: e.si for name, e in [*inputs.items(), *results.items()]}
    values["form"] = form
    return render_formulas(DAMPING_LATEX, terms, values)


def _explain(formula, inputs, results, reference, fit, form="") -> Explanation:
    from ..physics.damping import CRITICAL_BAND

    assumptions = ["linear viscous damping: the peaks fall geometrically, one factor "
                   "exp(delta) per cycle",
                   "regime from zeta: critically damped when |1 - zeta^2| <= 2^-50 "
                   f"({CRITICAL_BAND:.2g}), the rounding of the inputs"]
    if fit is not None:
        from ..physics.decay_fit import CURVATURE_LIMIT, R2_LIMIT

        assumptions.append(
            "peaks one full cycle apart, in time order; not exponential when ln(x) bends "
            "(quadratic term significant at 0.1% and changing the decrement by more than "
            f"{100 * CURVATURE_LIMIT:.0f}%) or scatters (R^2 < {R2_LIMIT})")
    latex, latex_substituted, substituted = _formula_lines(inputs, results, form)
    listed = [_shown(e) for e in inputs.values() if e.dim is None]  # the peaks
    return Explanation(formula=formula, substituted=listed + substituted,
                       assumptions=assumptions, reference=reference, latex=latex,
                       latex_substituted=latex_substituted)


# --- scenes with a damper --------------------------------------------------------------------

def _decrement_as_zeta(scene, texts: dict[str, str], labels: dict[str, str],
                       strict: bool):
    """``delta=`` or ``Q=`` given to solve a damping scene for one of its parameters: the
    damping ratio they mean (``zeta = delta / sqrt(4 pi^2 + delta^2)``, ``zeta = 1/(2Q)``)
    becomes the ``zeta=`` target the scene solves from (:mod:`dyncalc.scenes.inverse`), with
    the uncertainty that follows (``u(zeta) = |d zeta / d delta| u(delta)``) when one was
    typed. Returns ``(name, parsed)`` of the value given, or ``None``."""
    from ..physics.damping import zeta_from_decrement

    given = [n for n in ("delta", "Q") if n in texts and scene.param(n) is None]
    if not given:
        return None
    if len(given) > 1 or "zeta" in texts:
        raise InputError("give one of zeta=, delta= and Q= to solve from")
    name = given[0]
    text = texts.pop(name)
    label = labels.pop(name, f"{name}=").rstrip("=")
    parsed = parse_quantity(text, DIMENSIONLESS, label=label, strict=strict,
                            constraint="positive")
    value = parsed.si
    zeta = zeta_from_decrement(value) if name == "delta" else 0.5 / value
    texts["zeta"], labels["zeta"] = repr(zeta), f"zeta (from {name})="
    if parsed.uncertainty is not None:
        with np.errstate(all="ignore"):
            sigma = float(abs(_zeta_slope(name, value)) * parsed.uncertainty
                          if parsed.uncertainty else 0.0)
        if math.isfinite(zeta) and math.isfinite(sigma):
            texts["zeta"] = f"{zeta!r} +/- {sigma!r}"
    return name, parsed


def _zeta_slope(name: str, value: float):
    """``d zeta / d delta = (2 pi)^2 / h^3`` (``h = hypot(2 pi, delta)``) at ``value`` of
    ``delta``, or ``d zeta / d Q = -1 / (2 Q^2)`` at ``value`` of ``Q``."""
    value = np.float64(value)
    with np.errstate(all="ignore"):
        if name == "delta":
            h = np.hypot(_TWO_PI, value)
            return (_TWO_PI / h) ** 2 / h
        return -0.5 / value / value


def _read_scene(name, params, k, m, g, method, rtol, strict) -> SceneTexts:
    """Check a damping scene and gather its texts (``--k``, ``--m``, ``--g`` and the
    ``NAME=QUANTITY`` words) for :func:`_from_scene`."""
    from ..scenes import get_scene

    scene = get_scene(name)
    damped = damping_scene_names()
    if scene.name not in damped:
        from ..scenes import refuse_kinetics

        refuse_kinetics(scene.name, "damping-ratio")
        raise InputError(f"damping-ratio --scene takes a scene with a damper: "
                         f"{', '.join(damped)}; {scene.name} has none (natural-frequency "
                         "computes it)")
    texts, labels = gather_texts({"k": (k, "--k"), "m": (m, "--m"), "g": (g, "--g")}, params,
                                 "a scene parameter")
    given = _decrement_as_zeta(scene, texts, labels, strict)
    return SceneTexts(scene, texts, labels, method, rtol, strict, given)


def _from_scene(read_in: SceneTexts) -> Result:
    """The scene's Result with the decrement, Q and regime its zeta gives added; the
    scene's sensitivity carried through zeta to them (:func:`_scene_sensitivity`)."""
    from ..physics.damping import damping_from_zeta
    from .natural_frequency import compute_scene

    result = compute_scene(read_in.scene, read_in.texts, labels=read_in.labels,
                           method=read_in.method, rtol=read_in.rtol, strict=read_in.strict,
                           command="damping-ratio")
    scene_sensitivity = result.sensitivity
    given = read_in.given
    if given is not None and given[1].uncertainty is not None:
        # zeta (from delta), the target (no damping scene takes zeta), is shown plain as
        # before: its uncertainty is delta's, propagated under delta's name
        result.inputs["zeta"].uncertainty = None
    if "zeta" not in result.results:  # an inverse problem with several roots
        if "zeta" not in result.inputs:
            raise PhysicsError(f"{read_in.scene.name}: several values of the unknown fit and "
                               "each has its own damping ratio; natural-frequency lists them")
        # solved from zeta: every root has the zeta given, so it stays a result
        result.results["zeta"] = _entry("zeta", result.inputs["zeta"].si)
    zeta = result.results["zeta"].si
    added = damping_from_zeta(zeta)
    results: dict[str, Entry] = {}
    for key, entry in result.results.items():
        results[key] = entry
        if key == "zeta":
            for extra_name, value in added.values.items():
                if extra_name != "zeta":
                    results[extra_name] = _entry(extra_name, value)
    warnings = list(result.warnings)
    if added.values["zeta"] != zeta:  # within rounding of critical: exactly critical
        results["zeta"].si = added.values["zeta"]
        for key in ("omega_d", "f_d", "T_d"):
            results.pop(key, None)
        # the scene's own words on the regime were about the unrounded zeta
        warnings = [w for w in warnings if not w.startswith("zeta = ")]
        warnings += added.warnings
        warnings.append("zeta = 1: the system is critically damped; it does not oscillate, "
                        "so there is no damped frequency, period or logarithmic decrement")
    else:
        warnings += [w for w in added.warnings if w not in warnings]
    result.results = results
    result.warnings = warnings
    result.add_overflow_warnings()  # the results added here (Q = 1/(2 zeta) at a tiny zeta)
    if scene_sensitivity is not None:
        result.sensitivity = lambda: _scene_sensitivity(scene_sensitivity, results, given)
    if result.explanation is not None:
        result.explanation.formula.append(
            "delta = 2 pi zeta / sqrt((1 - zeta)(1 + zeta)) (underdamped), Q = 1/(2 zeta)")
        latex, latex_sub, text_sub = _formula_lines(result.inputs, {
            n: e for n, e in results.items() if n in added.values or n == "zeta"}, "--scene")
        ex = result.explanation
        ex.substituted += [line for line in text_sub if not line.startswith("zeta =")]
        ex.latex += [line for line in latex if not line.startswith(r"\zeta =")]
        ex.latex_substituted += [line for line in latex_sub if not line.startswith(r"\zeta =")]
    return result


_CYCLES_RE = re.compile(r"\s*[1-9][0-9]{0,14}\s*")


def _cycles_column(cycles, n: int):
    """Whole cycles of each row as floats (NaN where the text is no plain whole number: the
    one-off reads those, or refuses them)."""
    if cycles is None:
        return np.ones(n)
    cycles = np.asarray(cycles)
    if cycles.dtype.kind in "fiu":
        out = cycles.astype(float)
        return np.where((out >= 1.0) & (out == np.floor(out)) & (out < 2.0 ** 53), out, np.nan)
    return np.array([float(t) if _CYCLES_RE.fullmatch(str(t)) else np.nan for t in cycles],
                    dtype=float)


def columns(given: dict, settings: dict):
    """The results of a block of batch rows at once, or ``None`` when not vectorised here.

    ``given`` maps the columns the block gives (``c``, ``k``, ``m``, ``omega``,
    ``decrement``, ``ratio``, ``cycles``: the record's input names) to float64 SI arrays
    (``cycles`` may be the cell texts); ``settings`` holds ``scene`` and ``method``. The
    forms ``c, k, m`` and ``decrement`` or ``ratio`` (with ``cycles``; with ``omega`` or
    ``k`` and ``m``) are vectorised through the kernels of :mod:`dyncalc.physics.damping`;
    ``--amplitudes``, a scene, a fit method and any combination the one-off refuses give
    ``None``. ``ln(ratio)`` is taken with ``math.log`` per row (numpy's log may round
    otherwise). Exact on rows whose one-off result is underdamped with every value finite and
    non-zero (no note, no overflow or underflow warning).
    """
    from ..physics.columns import Columns
    from ..physics.damping import damping_from_coefficients, damping_from_decrement

    keys = set(given)
    if (settings.get("scene") is not None or settings.get("method") not in (None, "auto",
                                                                              "closed-form")
            or not keys or keys - {"c", "k", "m", "omega", "decrement", "ratio", "cycles"}
            or ("k" in keys) != ("m" in keys) or ("omega" in keys and "k" in keys)):
        return None
    arrays = {name: np.asarray(value, dtype=float) for name, value in given.items()
              if name != "cycles"}
    forms = [f for f in ("c", "decrement", "ratio") if f in keys]
    if len(forms) != 1 or ("cycles" in keys and forms != ["ratio"]):
        return None
    ok = np.ones(len(next(iter(given.values()))), dtype=bool)
    for value in arrays.values():
        ok &= np.isfinite(value)
    if forms == ["c"]:
        if "k" not in keys or "omega" in keys:
            return None
        out = damping_from_coefficients.columns(arrays["c"], arrays["k"], arrays["m"])
    else:
        if forms == ["decrement"]:
            delta = arrays["decrement"]
        else:
            ratio = arrays["ratio"]
            cycles = _cycles_column(given.get("cycles"), len(ratio))
            ok &= (ratio > 1.0) & np.isfinite(cycles)
            logs = np.array([math.log(r) if r > 0.0 and math.isfinite(r) else math.nan
                             for r in ratio.tolist()])
            with np.errstate(invalid="ignore"):
                delta = logs / cycles
        out = damping_from_decrement.columns(delta, omega=arrays.get("omega"),
                                             k=arrays.get("k"), m=arrays.get("m"))
    numbers = [v for v in out.values.values() if v.dtype.kind == "f"]
    for value in numbers:
        ok &= np.isfinite(value) & (value != 0.0)
    return Columns(out.values, exact=out.exact & ok, model="linear", method="closed-form")


# --- the command record ----------------------------------------------------------------------

def _run(values: dict[str, str | None], words=(), *, rtol=None, strict=False) -> Result:
    return damping_ratio(**{p.name: values.get(p.name) for p in COMMAND.inputs},
                         scene=values.get("scene"), params=tuple(words),
                         method=values.get("method"), rtol=rtol, strict=strict)


COMMAND = Command(
    "damping-ratio",
    "Damping ratio, decrement, Q and regime from a measurement.",
    """Damping ratio zeta, log decrement delta, Q, regime and damped period from a
    measurement: a damper rating, a decrement, two peaks, a list of peaks or a scene.

    Give exactly one of --c/--k/--m, --decrement, --ratio (with --cycles), --amplitudes or
    --scene. --omega (or --k and --m) adds the damped frequency and period; k and m add the
    critical damping coefficient c_c and c. Regime: undamped, underdamped, critically damped
    (also when c equals c_c to within the rounding of the inputs), overdamped. Peaks that are
    not exponential (Coulomb friction, noise larger than the decay) come with a warning.

    \b
    Examples:
      dyncalc damping-ratio --ratio 10 --cycles 10          # E5.18: zeta = 0.0366
      dyncalc damping-ratio --c "4 N*s/m" --k 100N/m --m 1kg
      dyncalc damping-ratio --decrement 0.23 --omega "12 rad/s"
      dyncalc damping-ratio --amplitudes "12.1, 9.0, 6.8, 5.1, 3.8 mV" --omega 25rad/s \\
          --plot decay.png
      dyncalc damping-ratio --scene rod-in-fluid m=1.5kg l=0.8m "beta=2 N*s/m^2"  # E5.14
    """,
    (
        Parameter("c", DAMPING, "Viscous damping coefficient, e.g. '4 N*s/m' (with --k and "
                  "--m).", "C"),
        Parameter("k", STIFFNESS, "Stiffness, e.g. '100 N/m': with --c, or with another form "
                  "for c_c, c and the damped period.", "K"),
        Parameter("m", MASS, "Mass, e.g. 1kg (goes with --k).", "M"),
        Parameter("decrement", DIMENSIONLESS, "Logarithmic decrement per cycle, "
                  "ln(x_i / x_(i+1)).", "DELTA"),
        Parameter("ratio", DIMENSIONLESS, "Amplitude ratio x_i / x_(i+N) of two peaks N cycles "
                  "apart (R >= 1).", "R"),
        Parameter("cycles", None, "Whole cycles between the two peaks of --ratio (default 1).",
                  "N", kind="text"),
        Parameter("amplitudes", None, "Successive peaks, one per cycle, one optional unit at "
                  "the end, e.g. \"12.1, 8.3, 5.9 mV\": the decrement is fitted to all of "
                  "them.", '"x0,x1,..."', kind="text"),
        Parameter("scene", None, "A scene with a damper (rod-in-fluid, "
                  "pendulum-spring-dashpot, frame-brace-damper), its parameters as "
                  "NAME=QUANTITY words.", "NAME", kind="setting", choices=damping_scene_names),
        Parameter("omega", ANGULAR_RATE, "Undamped natural angular frequency, e.g. '12 rad/s' "
                  "or 115rpm: adds omega_d, f_d, T_d.", "OMEGA"),
        Parameter("g", ACCELERATION, "Gravitational acceleration of a scene (default 9.80665 "
                  "m/s^2).", "G"),
        Parameter("method", None, "Fit of --amplitudes: log-linear (default; least squares of "
                  "ln x) or nonlinear (least squares of x, scipy); a scene's own methods with "
                  "--scene.", "METHOD", kind="setting", choices=method_names),
        Parameter("plot", None, "Draw the free decay (the peaks and the fitted envelope for "
                  "--amplitudes) into FILE (.png, .svg or .pdf); needs matplotlib (the plot "
                  "extra).", "FILE.png", kind="after"),
    ),
    results_from_kinds(_KINDS),
    _run,
    words="[NAME=QUANTITY]...",
    columns=columns,
)
