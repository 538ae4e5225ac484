"""Running a scene: texts -> checked quantities -> the scene's physics -> a Result.

The rules (docs/scenes.md): every parameter the scene needs must be given or have a
default; a parameter the scene does not have, or one given twice, is refused with the list of
the scene's parameters; groups of alternatives (``J`` or ``J_A``, ``body`` or ``kappa``) take
exactly one; relations between parameters (``R > r``) are checked before any physics runs.
"""
from __future__ import annotations

import math
from typing import Any

from ..errors import InputError
from ..result.entries import Entry, Explanation, Result, entry_from_parsed, format_number
from ..units import DIMENSIONLESS, parse_quantity, to_si
from . import Scene, get_scene
from ..result.kinds import result_kind
from ..lazy import numpy as np  # for vector results only

__all__ = ["run_scene", "is_inverse", "is_result_name", "scene_kind", "read_inputs",
           "compute_values",
           "make_result", "DEFAULT_RTOL"]

DEFAULT_RTOL = 1e-9

def _parameter_list(scene: Scene) -> str:
    return f"the parameters of {scene.name} are: {scene.signature()}"


def _resolve_groups(scene: Scene, texts: dict[str, str], unknown: tuple[str, ...] = ()
                    ) -> set[str]:
    """Check the one-of groups; return the names left out on purpose (the other alternative).
    A name in ``unknown`` (solved for) counts as given."""
    skipped = set()
    for group in scene.one_of:
        given = [n for n in group if n in texts or n in unknown]
        if len(given) > 1:
            raise InputError(f"{scene.name}: give {' or '.join(group)}, not both; "
                             f"{_parameter_list(scene)}")
        if not given and not any(scene.param(n).default is not None for n in group):
            raise InputError(f"{scene.name} needs {' or '.join(group)}; "
                             f"{_parameter_list(scene)}")
        chosen = given[0] if given else next(n for n in group
                                             if scene.param(n).default is not None)
        skipped.update(n for n in group if n != chosen)
    return skipped


def run_scene(scene: Scene | str, texts: dict[str, str], *, labels: dict[str, str] | None = None,
              method: str | None = None, rtol: float | None = None, strict: bool = False,
              command: str = "natural-frequency") -> Result:
    """Compute ``scene`` from the parameter texts the user gave (every parameter it needs
    given or defaulted; an inverse problem, a result given as an input, is
    :func:`dyncalc.scenes.inverse.solve`'s, and the command decides which to call).

    Parameters
    ----------
    scene : Scene or str
    texts : dict
        Parameter name -> text as typed (``{"k": "2 kN/m", "m": "4kg"}``).
    labels : dict, optional
        How the user named each parameter in messages (``{"k": "--k"}``); default ``k=``.
    method : str, optional
        ``auto`` (default) or one of ``scene.methods``.
    rtol : float, optional
        Relative tolerance the model must meet (default 1e-9).
    strict : bool
        ``--strict-units``.
    """
    if isinstance(scene, str):
        scene = get_scene(scene)
    prepared = read_inputs(scene, texts, labels or {}, strict)
    if prepared.missing:
        raise InputError(f"{scene.name} needs {', '.join(prepared.missing)}; "
                         f"{_parameter_list(scene)}")
    check_constraints(scene, prepared.si)
    outcome, values, warnings = compute_values(scene, prepared.kwargs, prepared.zeta,
                                               method, rtol)
    result = make_result(scene, prepared.inputs, outcome, values, warnings, command)
    result.sensitivity = lambda: scene_sensitivity(scene, prepared, method, rtol, result)
    return result


def scene_sensitivity(scene: Scene, prepared: Prepared, method, rtol, result):
    """The derivatives of a scene's results with respect to its uncertain parameters, by
    central differences on the parameters as read (:func:`dyncalc.result.propagate.
    central_differences`): each nudged computation calls the scene's physics with one value
    moved, nothing is parsed again, so the cost is two computations per uncertain input."""
    from ..result.propagate import UncertainInput, _numbers, central_differences

    names = [name for name, entry in prepared.inputs.items()
             if entry.uncertainty is not None and name in prepared.si]
    inputs = [UncertainInput(name, float(prepared.si[name]),
                             float(prepared.inputs[name].uncertainty)) for name in names]
    if not inputs:
        return central_differences([], {}, lambda i, h: None)

    def rerun(index: int, offset: float):
        name = names[index]
        nudged = _nudged(scene, prepared, name, offset)
        if nudged is None:
            return None
        try:
            check_constraints(scene, nudged.si)
            outcome, values, warnings = compute_values(scene, nudged.kwargs, nudged.zeta,
                                                       method, rtol)
            return _numbers(make_result(scene, nudged.inputs, outcome, values, warnings,
                                        result.command))
        except InputError:
            return None

    return central_differences(inputs, _numbers(result), rerun)


def _nudged(scene: Scene, prepared: Prepared, name: str, offset: float) -> Prepared | None:
    """A copy of ``prepared`` with parameter ``name`` moved by ``offset`` (SI), or ``None``
    where the moved value breaks the parameter's own constraint (a mass of ``0 ± 1 g``)."""
    param = scene.param(name)
    si = prepared.si[name] + offset
    if ((param.constraint == "positive" and not si > 0)
            or (param.constraint == "nonnegative" and not si >= 0)):
        return None
    copy = Prepared()
    copy.kwargs, copy.inputs = dict(prepared.kwargs), prepared.inputs
    copy.si, copy.zeta, copy.missing = dict(prepared.si), prepared.zeta, prepared.missing
    quantity = prepared.kwargs.get(name)
    if hasattr(quantity, "units"):
        scale = to_si(type(quantity)(1.0, quantity.units), param.dim, name)
        quantity = quantity + type(quantity)(offset / scale, quantity.units)
    else:
        quantity = si
    set_parameter(scene, copy, name, si, quantity)
    return copy


def is_inverse(scene: Scene, texts: dict[str, str]) -> bool:
    """Whether ``texts`` pose an inverse problem: a result of the scene given as an input
    (``f=5Hz``), which is not also the name of one of its parameters."""
    return any(scene.param(name) is None and is_result_name(name, scene) for name in texts)


def is_result_name(name: str, scene: Scene | None = None) -> bool:
    """Whether ``name`` names a result some scene gives (``f``, ``omega_d``, ``zeta``), or
    one of ``scene``'s own results."""
    if scene is not None and name in scene.kinds:
        return True
    try:
        result_kind(name)
    except KeyError:
        return False
    return not name.startswith("mode_")


def scene_kind(scene: Scene | None, name: str):
    """The kind of result ``name`` of ``scene``: its own (``Scene.kinds``), else the shared
    table's (``KeyError`` for a name no scene gives)."""
    if scene is not None and name in scene.kinds:
        return scene.kinds[name]
    return result_kind(name)


class Prepared:
    """The parameters read: the physics function's keyword arguments, the input entries, the
    SI values by name, the damping ratio given as ``zeta``, and the required names missing."""

    __slots__ = ("kwargs", "inputs", "si", "zeta", "missing")

    def __init__(self):
        self.kwargs: dict[str, Any] = {}
        self.inputs: dict[str, Entry] = {}
        self.si: dict[str, Any] = {}
        self.zeta: float | None = None
        self.missing: list[str] = []


def read_inputs(scene: Scene, texts: dict[str, str], labels: dict[str, str],
                strict: bool, unknown: tuple[str, ...] = ()) -> Prepared:
    """Check the names in ``texts`` against the scene and read every parameter it gives
    (or its default); parameters required but not given are listed in ``missing``, and the
    ``unknown`` ones (to be solved for) are left out altogether."""
    names = {p.name for p in scene.params}
    for name in texts:
        if name == "zeta" and not scene.accepts_zeta and scene.param("zeta") is None:
            raise InputError(f"{scene.name} takes no zeta: {scene.no_zeta_because}; "
                             f"{_parameter_list(scene)}")
        if name not in names:
            raise InputError(f"{scene.name} has no parameter {name!r}; {_parameter_list(scene)}")
    skipped = _resolve_groups(scene, texts, unknown)
    prepared = Prepared()
    for param in scene.params:
        if param.name in unknown:
            continue
        text = texts.get(param.name)
        if text is None and param.name not in skipped:
            text = param.default
        if text is None:
            if not param.optional and param.name not in skipped:
                prepared.missing.append(param.name)
            continue
        label = labels.get(param.name, f"{param.name}=")
        label = label[:-1] if label.endswith("=") else label
        if param.choices is not None:
            word = text.strip()
            if word not in param.choices:
                raise InputError(f"{label} must be one of {', '.join(param.choices)}; got "
                                 f"{word[:40]!r}")
            prepared.kwargs["kappa" if param.name == "body" else param.name] = \
                param.choices[word]
            prepared.inputs[param.name] = Entry(param.name, word, None, text=text)
            continue
        parsed = parse_quantity(text, param.dim, label=label, strict=strict,
                                constraint=param.constraint)
        prepared.inputs[param.name] = entry_from_parsed(param.name, parsed, param.dim,
                                                        description=param.description)
        set_parameter(scene, prepared, param.name, parsed.si, parsed.quantity)
    return prepared


def set_parameter(scene: Scene, prepared: Prepared, name: str, si: float, quantity) -> None:
    """Hand one parameter's value to the physics (``quantity`` in any unit of its dimension)."""
    param = scene.param(name)
    prepared.si[name] = si
    if name == "zeta" and scene.accepts_zeta:
        prepared.zeta = si
    elif param.dim is DIMENSIONLESS:
        prepared.kwargs[name] = si
    else:
        prepared.kwargs[name] = quantity


def check_constraints(scene: Scene, si: dict[str, Any]) -> None:
    for constraint in scene.constraints:
        if not constraint.holds(si):
            raise InputError(f"{scene.name} needs {constraint.text}{constraint.why}")


def compute_values(scene: Scene, kwargs: dict[str, Any], zeta: float | None,
                   method: str | None, rtol: float | None):
    """Run the scene's physics: ``(outcome, values by name, warnings)``."""
    allowed = ("auto", *scene.methods)
    if method not in (None, "auto") and method not in scene.methods:
        offered = ", ".join(allowed) if scene.methods else "auto (a closed form only)"
        raise InputError(f"--method {method} is not offered by {scene.name}; it offers "
                         f"{offered}")
    kwargs = dict(kwargs)
    if scene.methods:
        kwargs["method"] = method or "auto"
        kwargs["rtol"] = DEFAULT_RTOL if rtol is None else rtol

    outcome = scene.compute(**kwargs)
    values = dict(outcome.values)
    warnings = list(outcome.warnings)
    if zeta is not None:
        from ..physics.outcome import damped

        omega = values["omega"].to("rad/s").magnitude
        extra, notes = damped(float(omega), zeta)
        values.update(extra)
        warnings += notes
    return outcome, values, warnings


def make_result(scene: Scene, inputs: dict[str, Entry], outcome, values: dict[str, Any],
                warnings: list[str], command: str,
                solved: dict[str, Entry] | None = None) -> Result:
    """The Result of a scene: ``solved`` entries (an inverse problem) come first."""
    results = dict(solved or {})
    results.update((name, _entry(name, value, scene)) for name, value in values.items()
                   if name not in results)
    result = Result(command=command, results=results, inputs=inputs, scene=scene.name,
                    model=outcome.model, method=outcome.method, warnings=warnings,
                    explanation=lambda: _explain(scene, inputs, results, outcome))
    result.add_overflow_warnings()
    if outcome.error_estimate is not None:
        result.extra["error_estimate"] = outcome.error_estimate
    result.add_underflow_warnings(outcome.exact_zeros)
    return result


def _entry(name: str, value, scene: Scene | None = None) -> Entry:
    kind = scene_kind(scene, name)
    if hasattr(value, "units"):
        magnitude = to_si(value, kind.dim, name)
        if type(magnitude) is float:  # a plain scalar: no need to ask numpy (np.ndim is 0)
            si = magnitude
        else:
            si = np.asarray(magnitude, dtype=float) if np.ndim(magnitude) else float(magnitude)
    elif type(value) is float:
        si = value
    elif np.ndim(value):
        si = np.asarray(value, dtype=float)
    else:
        si = float(value)
    return Entry(name, si, kind.dim, unit=kind.unit, symbol=kind.symbol,
                 description=kind.description)


#: Lines every scene gets for the results it has and does not derive itself.
FAMILY_LATEX = (r"$f = \frac{$omega}{2\pi}", r"$T = \frac{1}{$f}",
                r"$omega_d = $omega\,\sqrt{1 - $zeta^2}", r"$f_d = \frac{$omega_d}{2\pi}",
                r"$T_d = \frac{1}{$f_d}")


def _explain(scene: Scene, inputs: dict[str, Entry], results: dict[str, Entry],
             outcome) -> Explanation:
    """The formula of ``scene`` in symbols and with these values (plain text and LaTeX), its
    assumptions with their size at these inputs, and its textbook example."""
    from ..result.explain import Term, render_formulas, symbol_latex, template_terms

    symbols = {p.name: p.symbol for p in scene.params if p.symbol}
    terms = template_terms([*inputs.values(), *results.values()], symbols)
    values = {name: entry.si for name, entry in [*inputs.items(), *results.items()]
              if not isinstance(entry.si, str)}
    body = inputs.get("body")
    if body is not None and scene.param("body") is not None:
        kappa = float(scene.param("body").choices[body.si])
        terms["kappa"] = Term(symbol_latex("kappa"), kappa)
        values["kappa"] = kappa
    values["method"] = outcome.method
    latex, latex_substituted, substituted = render_formulas([*scene.latex, *FAMILY_LATEX],
                                                            terms, values)
    if not substituted:
        substituted = [f"{e.name} = {format_number(e.value_in(), 6)}"
                       + (f" {e.unit}" if e.unit else "") for e in results.values()]

    assumptions = [*scene.assumptions, *outcome.assumptions]
    assumptions += [text for size in scene.sizes if (text := _sized(size, values))]
    zeta, omega, omega_d = (values.get(n) for n in ("zeta", "omega", "omega_d"))
    if zeta and omega and omega_d and zeta < 1:
        # 1 - sqrt(1 - zeta^2) from zeta alone, without cancellation: finite where omega and
        # omega_d overflow (their quotient inf / inf would read nan)
        drop = zeta * zeta / (1.0 + math.sqrt((1.0 - zeta) * (1.0 + zeta)))
        assumptions.append(f"damping lowers the frequency: omega_d = omega sqrt(1 - zeta^2) is "
                           f"{100 * drop:.3g}% below omega at zeta = {zeta:.3g}")
    example = scene.example
    if scene.example_result:
        example += " gives " + ", ".join(f"{name} = {value}"
                                         for name, value in scene.example_result.items())
    return Explanation(formula=[f"equation of motion: {scene.equation}", scene.formula],
                       substituted=substituted, assumptions=assumptions,
                       reference=scene.reference, latex=latex,
                       latex_substituted=latex_substituted, example=example)


def _sized(size, values: dict) -> str | None:
    """A scene's sentence on an assumption's size at these values; none where it cannot be
    worked out in float64 (an input near 1e308)."""
    try:
        return size(values)
    except (ArithmeticError, ValueError):
        return None
