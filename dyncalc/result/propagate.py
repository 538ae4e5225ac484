"""First-order propagation of standard uncertainties through any command.

A quantity typed with an uncertainty (``"2.0+/-0.1 kg"``, ``"(100 ± 5) N/m"``) is read by
:func:`dyncalc.units.parse_quantity`, which hands it to :func:`traced_input` while
:func:`propagate` runs (through the hook ``dyncalc.units.grammar.UNCERTAIN_INPUT_HOOK``).
:func:`propagate` runs a computation once as typed, then twice more per uncertain input with
that input nudged by ``±h``; the central difference gives each result's sensitivity, and

.. math::

    u(y)^2 = \\sum_i \\left(\\frac{\\partial y}{\\partial x_i}\\right)^2 u(x_i)^2

(independent inputs: the law of propagation of uncertainty of the GUM, first order). Each
input's share of a result's variance is its term over the sum.

Why finite differences and not the ``uncertainties`` package (pint's ``Measurement``): the
results come out of numerically careful kernels (the AGM, bracketed root finds, ``solve_ivp``,
exact fractions) that an object carrying derivatives cannot pass through; re-running the
computation works for every command, scene and method alike. The step is
``h = 1e-6 |x|`` (``1e-6 u(x)`` for ``x = 0``): the truncation error of the central difference
is about ``h^2``, the rounding error about ``eps / h``, both far below the two significant
digits an uncertainty is quoted to. Where ``x + h`` or ``x - h`` is refused (a mass of
``0 ± 1 g``), the one-sided difference is used.

Example
-------
>>> from dyncalc.scenes.runner import run_scene
>>> r = propagate(lambda: run_scene("mass-spring", {"k": "100+/-5 N/m", "m": "2 kg"}))
>>> round(r.results["omega"].uncertainty, 6)   # omega/2 * u(k)/k = 7.0711 * 0.025
0.176777
"""
from __future__ import annotations

import contextvars
import math
from typing import Any, Callable

import numpy as np

from ..errors import InputError

__all__ = ["traced_input", "propagate", "nudged_hint", "store_hint", "RELATIVE_STEP",
           "UncertainInput", "Sensitivity", "central_differences"]

#: The finite-difference step relative to the input's magnitude.
RELATIVE_STEP = 1e-6
#: A propagated uncertainty below this fraction of its result is rounding noise of the
#: differences (about eps / RELATIVE_STEP = 2e-10 of the result, times the input's share):
#: it is given as zero (a result that does not depend on the uncertain inputs at all).
NOISE_FLOOR = 1e-9


class _Input:
    """One uncertain input as first read: where, its SI value, uncertainty and unit scale."""

    __slots__ = ("label", "si", "sigma", "scale")

    def __init__(self, label: str, si: float, sigma: float, scale: float):
        self.label, self.si, self.sigma, self.scale = label, si, sigma, scale

    @property
    def name(self) -> str:
        return self.label.lstrip("-").rstrip("=").split(" (")[0]


class _Tape:
    """The uncertain inputs of one run, in the order they were read, and the nudge to apply."""

    def __init__(self):
        self.inputs: list[_Input] = []
        self.keys: dict[tuple[str, str], int] = {}  # (label, text) -> index in inputs
        self.nudge: tuple[int, float] | None = None  # (input index, SI offset)
        self.hints: dict[Any, Any] = {}


_TAPE: contextvars.ContextVar[_Tape | None] = contextvars.ContextVar("dyncalc_tape",
                                                                     default=None)


def traced_input(parsed, dim, label: str, allow_inf: bool, constraint: str | None,
                 source: str | None = None):
    """Record an uncertain input of the run in progress, or return it nudged (called by
    :func:`dyncalc.units.parse_quantity` for every quantity typed with ``±``). ``source``
    names a value read in several places (a network's shared ``EI=``): one input."""
    tape = _TAPE.get()
    if tape is None:
        return parsed
    key = (source or label, parsed.text)
    if tape.nudge is None:
        if key not in tape.keys:
            scale = _unit_scale(parsed.quantity, dim)
            tape.keys[key] = len(tape.inputs)
            tape.inputs.append(_Input(source or label, parsed.si, parsed.uncertainty, scale))
        return parsed
    index = tape.keys.get(key)
    which, offset = tape.nudge
    if which != index:
        return parsed
    from ..units.grammar import _check_value

    item = tape.inputs[index]
    si = parsed.si + offset
    _check_value(si, dim, label, allow_inf, constraint, parsed.quantity)
    quantity = parsed.quantity + type(parsed.quantity)(offset / item.scale,
                                                       parsed.quantity.units)
    return type(parsed)(quantity, si, parsed.assumed_si, parsed.unit_text, parsed.text,
                        uncertainty=parsed.uncertainty)


def nudged_hint(key) -> Any:
    """What the run as typed stored under ``key`` (:func:`store_hint`), when this run is one
    of the nudged re-runs of :func:`propagate`; otherwise ``None``. A solver uses it to look
    for its answer next to the one it found before (the inputs moved by 1e-6)."""
    tape = _TAPE.get()
    if tape is None or tape.nudge is None:
        return None
    return tape.hints.get(key)


def store_hint(key, value) -> None:
    """Keep ``value`` for the nudged re-runs of the run as typed (no-op otherwise)."""
    tape = _TAPE.get()
    if tape is not None and tape.nudge is None:
        tape.hints[key] = value


def _unit_scale(quantity, dim) -> float:
    """SI magnitude of one of ``quantity``'s units (a nudge in SI over it is the nudge in the
    unit typed; not ``si / magnitude``, which is 0 when the value underflowed in SI)."""
    from ..units import to_si

    return float(to_si(type(quantity)(1.0, quantity.units), dim, "unit"))


def _numbers(result) -> dict[str, Any]:
    """The numeric results (floats and vectors) by name, in SI."""
    out = {}
    for name, entry in result.results.items():
        if entry.dim is None or isinstance(entry.si, str):
            continue
        out[name] = np.asarray(entry.si, dtype=float)
    return out


def _run_nudged(compute: Callable, tape: _Tape, index: int, offset: float):
    tape.nudge = (index, offset)
    try:
        return _numbers(compute())
    except InputError:
        return None


def propagate(compute: Callable[[], Any]):
    """Run ``compute`` (no arguments, returns a :class:`~dyncalc.result.Result`) and give its
    results the standard uncertainty propagated from the uncertain inputs it read.

    Each result entry gets ``uncertainty`` (SI, float or array; ``None`` where it could not be
    propagated), each uncertain input entry its own, and the explanation (if any) ``variance``:
    result name -> {input name: share of the result's variance}. Without uncertain inputs
    ``compute`` runs once and its result is returned unchanged.
    """
    from ..units.grammar import UNCERTAIN_INPUT_HOOK

    tape = _Tape()
    token = _TAPE.set(tape)
    hook = UNCERTAIN_INPUT_HOOK.set(traced_input)
    try:
        result = compute()
        if not tape.inputs:  # no quantity was typed with an uncertainty
            return result
        if result.sensitivity is not None:  # the command read, then computed: no re-runs
            return _propagate_read(result, result.sensitivity())
        _name_inputs(result, tape)
        nominal = _numbers(result)
        terms: dict[str, dict[int, np.ndarray]] = {name: {} for name in nominal}
        failed: set[str] = set()
        for index, item in enumerate(tape.inputs):
            if item.sigma == 0:
                continue
            h = RELATIVE_STEP * (abs(item.si) if item.si != 0 else item.sigma)
            up = _run_nudged(compute, tape, index, h)
            down = _run_nudged(compute, tape, index, -h)
            for name, y0 in nominal.items():
                slope = _slope(y0, h, up, down, name)
                if slope is None:
                    failed.add(name)
                    continue
                with np.errstate(all="ignore"):  # an overflow is caught in _attach
                    terms[name][index] = (slope * item.sigma) ** 2
    finally:
        UNCERTAIN_INPUT_HOOK.reset(hook)
        _TAPE.reset(token)
    _attach(result, [item.name for item in tape.inputs], nominal, terms, failed)
    return result


class UncertainInput:
    """One uncertain input of a command that reads, then computes: the name its share of a
    variance is listed under, its SI value and standard uncertainty."""

    __slots__ = ("name", "si", "sigma")

    def __init__(self, name: str, si: float, sigma: float):
        self.name, self.si, self.sigma = name, si, sigma

    def __repr__(self) -> str:
        return f"UncertainInput({self.name!r}, {self.si!r}, {self.sigma!r})"


class Sensitivity:
    """The derivatives of a result's numbers with respect to its uncertain inputs, as the
    command worked them out on its parsed inputs: ``slopes[result][i]`` is
    ``d result / d inputs[i]`` in SI (a float or an array shaped like the result), exact
    where the formula is closed; a result in ``failed`` could not be differentiated."""

    __slots__ = ("inputs", "slopes", "failed")

    def __init__(self, inputs: list[UncertainInput], slopes: dict[str, dict[int, Any]],
                 failed: set[str] | None = None):
        self.inputs, self.slopes = inputs, slopes
        self.failed = set() if failed is None else failed


def central_differences(inputs: list[UncertainInput], nominal: dict[str, Any],
                        rerun: Callable[[int, float], dict[str, Any] | None]) -> Sensitivity:
    """Slopes by central differences on parsed inputs: ``rerun(i, offset)`` computes again
    with input ``i`` moved by ``offset`` (SI) and returns the numbers by name (``None`` where
    that value is refused); nothing is parsed again, so the cost is two computations per
    uncertain input. For results behind a root find or an ODE, where no closed derivative
    exists."""
    slopes: dict[str, dict[int, Any]] = {name: {} for name in nominal}
    failed: set[str] = set()
    for index, item in enumerate(inputs):
        if item.sigma == 0:
            continue
        h = RELATIVE_STEP * (abs(item.si) if item.si != 0 else item.sigma)
        up, down = rerun(index, h), rerun(index, -h)
        for name, y0 in nominal.items():
            slope = _slope(np.asarray(y0, dtype=float), h, up, down, name)
            if slope is None:
                failed.add(name)
            else:
                slopes[name][index] = slope
    return Sensitivity(inputs, slopes, failed)


def _propagate_read(result, sensitivity: Sensitivity):
    """Attach the uncertainties a command's own :class:`Sensitivity` gives."""
    if not sensitivity.inputs:
        return result
    nominal = _numbers(result)
    terms: dict[str, dict[int, np.ndarray]] = {name: {} for name in nominal}
    failed = set(sensitivity.failed)
    for name in nominal:
        if name in failed:
            continue
        for index, slope in sensitivity.slopes.get(name, {}).items():
            sigma = sensitivity.inputs[index].sigma
            with np.errstate(all="ignore"):  # an overflow is caught in _attach
                term = (np.asarray(slope, dtype=float) * sigma) ** 2
            if not np.all(np.isfinite(slope)):
                failed.add(name)
                break
            terms[name][index] = term
    _attach(result, [item.name for item in sensitivity.inputs], nominal, terms, failed)
    return result


def _slope(y0, h, up, down, name):
    """The derivative by the central difference, or one-sided where one side was refused."""
    y_up = None if up is None else up.get(name)
    y_down = None if down is None else down.get(name)
    with np.errstate(all="ignore"):
        if y_up is not None and y_down is not None and y_up.shape == y0.shape == y_down.shape:
            slope = (y_up - y_down) / (2 * h)
        elif y_up is not None and y_up.shape == y0.shape:
            slope = (y_up - y0) / h
        elif y_down is not None and y_down.shape == y0.shape:
            slope = (y0 - y_down) / h
        else:
            return None
    return slope if np.all(np.isfinite(slope)) else None


def _name_inputs(result, tape: _Tape) -> None:
    """Name each uncertain input as the result's inputs do (``--inertia`` is ``J``).

    The result lists its uncertain inputs in the order they were read, as the tape does; when
    the two lists match one to one, the names are paired in order. Otherwise (a shared network
    value read once and used by several elements) the name comes from the option's label."""
    entries = [e for e in result.inputs.values() if e.uncertainty is not None]
    if len(entries) == len(tape.inputs):
        for item, entry in zip(tape.inputs, entries):
            item.label = entry.name


def _attach(result, names: list[str], nominal, terms, failed) -> None:
    shares: dict[str, dict[str, float]] = {}
    for name, parts in terms.items():
        entry = result.results[name]
        if name in failed:
            entry.uncertainty = None
            result.warnings.append(f"the uncertainty of {name} could not be propagated (a "
                                   "nudged input was refused or gave no finite result)")
            continue
        total = sum(parts.values()) if parts else np.zeros_like(nominal[name])
        sigma = np.sqrt(total)
        with np.errstate(all="ignore"):  # below what the differences resolve: zero
            sigma = np.where(sigma <= NOISE_FLOOR * np.abs(nominal[name]), 0.0, sigma)
        if not np.all(np.isfinite(sigma)):
            entry.uncertainty = None
            result.warnings.append(f"the uncertainty of {name} overflows float64")
            continue
        entry.uncertainty = float(sigma) if sigma.ndim == 0 else sigma
        grand = float(np.sum(total))
        if grand > 0 and math.isfinite(grand):
            share: dict[str, float] = {}
            for index, part in parts.items():
                fraction = float(np.sum(part)) / grand
                key = names[index]
                share[key] = share.get(key, 0.0) + (fraction if fraction > 1e-12 else 0.0)
            shares[name] = share
    if not result.amend_explanation(lambda explanation: setattr(explanation, "variance",
                                                                shares)):
        result.extra["variance"] = shares
