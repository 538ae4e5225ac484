"""The quick ``natural-frequency``: mass-spring, torsional and the pendulum at small swings.

.. math:: \\omega = \\sqrt{k / m}, \\quad \\sqrt{k_t / J}, \\quad \\sqrt{g / l};
          \\qquad f = \\omega / 2\\pi, \\quad T = 2\\pi / \\omega

Parameters (by scene): ``--k`` stiffness [force]/[length] and ``--m`` mass [mass]; ``--kt``
torsional stiffness [force]*[length]/[angle] and ``--inertia`` [mass]*[length]^2; ``--length``
[length] and ``--g`` [length]/[time]^2 (default 9.80665 m/s^2). omega is
:func:`dyncalc.physics.numerics.sqrt_ratio` of the SI values, as in
:func:`dyncalc.physics.oscillators.mass_spring` and :func:`~dyncalc.physics.outcome.periodic`.

>>> print(natural_frequency(["--k", "100 N/m", "--m", "2 kg", "--value", "omega"], None))
7.0710678118654755

``None`` where the full path must answer (:mod:`dyncalc.quick`). Reference: the scenes
``mass-spring``, ``torsional`` and ``pendulum`` (docs/scenes.md; Gross et al., Chapter 5).
"""
from __future__ import annotations

import math

from ..constants import STANDARD_GRAVITY_TEXT
from ..physics.numerics import sqrt_ratio
from . import forms
from .read import read_options, read_quantity

__all__ = ["natural_frequency"]

#: option -> scene parameter, its dimension (the table's name) and SI unit
PARAMETERS = {
    "--k": ("k", "stiffness", "N/m"), "--m": ("m", "mass", "kg"),
    "--kt": ("kt", "torsional stiffness", "N*m/rad"),
    "--inertia": ("J", "mass moment of inertia", "kg*m^2"),
    "--length": ("l", "length", "m"), "--g": ("g", "acceleration", "m/s^2"),
}
#: the parameters given -> the scene, and its parameters in the order it lists them
_SCENES = {
    frozenset({"k", "m"}): ("mass-spring", ("k", "m")),
    frozenset({"kt", "J"}): ("torsional", ("kt", "J")),
    frozenset({"l"}): ("pendulum", ("l", "g")),
    frozenset({"l", "g"}): ("pendulum", ("l", "g")),
}
#: result -> symbol and unit (shown and canonical alike)
RESULTS = {"omega": ("ω", "rad/s"), "f": ("f", "Hz"), "T": ("T", "s")}


def natural_frequency(args: list[str], human_form) -> str | None:
    """The stdout of ``dyncalc natural-frequency ARGS`` (``human_form()``: the human form
    it may print, :func:`dyncalc.quick.forms.human`), or ``None``."""
    options = read_options(args, PARAMETERS, RESULTS)
    if options is None:
        return None
    texts, _words, names, as_json, digits = options
    inputs = {}
    for flag, text in texts.items():
        name, dimension, si_unit = PARAMETERS[flag]
        inputs[name] = read_quantity(name, text, dimension, si_unit)
        if inputs[name] is None:
            return None
    found = _SCENES.get(frozenset(inputs))
    if found is None:
        return None
    scene, order = found
    if "g" in order and "g" not in inputs:
        inputs["g"] = read_quantity("g", STANDARD_GRAVITY_TEXT, "acceleration", "m/s^2")
    inputs = {name: inputs[name] for name in order}
    top, bottom = (inputs["g"], inputs["l"]) if scene == "pendulum" else inputs.values()
    omega = sqrt_ratio(top.si, bottom.si)
    values = {"omega": omega, "f": omega / (2.0 * math.pi),
              "T": 2.0 * math.pi / omega if omega > 0 else math.inf}
    if not all(0.0 < v < math.inf for v in values.values()):
        return None  # the full path warns
    results = [(name, RESULTS[name][0], v, RESULTS[name][1], v, RESULTS[name][1])
               for name, v in values.items()]
    if names:
        return forms.values(results, names)
    if as_json:
        return forms.json_text("natural-frequency", scene, "linear", inputs.values(), results)
    form = None if human_form is None else human_form()
    if form is None:
        return None
    title = ["natural-frequency", f"scene: {scene}", "model: linear", "method: closed-form"]
    return forms.human(form, title, results, inputs.values(), digits)
