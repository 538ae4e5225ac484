"""The quick ``spring-series`` and ``spring-parallel``: plain stiffnesses, all typed in one
unit (or all bare numbers, N/m).

.. math:: \\frac{1}{k_{eq}} = \\sum_i \\frac{1}{k_i} \\quad \\text{(series)}, \\qquad
          k_{eq} = \\sum_i k_i \\quad \\text{(parallel)}

Each element ``k_i`` is a stiffness [force]/[length] or, where the unit is not one, a
torsional stiffness [force]*[length]/[angle]. As :func:`dyncalc.physics.springs.
series_stiffness` does, the elements are combined in the unit they were typed in (exactly:
200 and 300 lbf/in give 120 lbf/in), by :func:`dyncalc.physics.numerics.series_sum_finite`
or the correctly rounded sum (``math.fsum``, :func:`~dyncalc.physics.numerics.parallel_sum`),
then converted to SI by the table's factor.

>>> print(spring_network("series", ["200 N/m", "300 N/m", "--value", "k_eq"], None))
120.0

``None`` where the full path must answer (element functions, groups, shared values, mixed
units, an infinite or zero result). Reference: docs/commands.md (spring-series).
"""
from __future__ import annotations

import math

from ..physics.numerics import series_sum_finite
from . import forms
from .read import read_options, read_quantity

__all__ = ["spring_network"]

_DIMENSIONS = (("stiffness", "N/m"), ("torsional stiffness", "N*m/rad"))


def _element(name: str, text: str):
    """A stiffness as the full path reads an element: linear first, then torsional."""
    for dimension, si_unit in _DIMENSIONS:
        entry = read_quantity(name, text, dimension, si_unit)
        if entry is not None:
            return entry
    return None


def spring_network(how: str, args: list[str], human_form) -> str | None:
    """The stdout of ``dyncalc spring-HOW ARGS``, or ``None``."""
    options = read_options(args, (), ("k_eq",), words=True)
    if options is None:
        return None
    _texts, words, names, as_json, digits = options
    inputs = [_element(f"k{i}", word) for i, word in enumerate(words, 1)]
    if not inputs or None in inputs:
        return None
    units = {entry.unit for entry in inputs}
    assumed = {entry.assumed for entry in inputs}
    si_units = {entry.si_unit for entry in inputs}
    if len(units) != 1 or len(assumed) != 1 or len(si_units) != 1:
        return None  # mixed units: the full path converts to the first one's
    magnitudes = [entry.value for entry in inputs]
    if how == "series":
        in_unit = series_sum_finite(magnitudes)
    else:
        try:
            in_unit = math.fsum(magnitudes)
        except OverflowError:
            return None
    si_unit = si_units.pop()
    k_eq = in_unit * inputs[0].factor  # combined.to(SI): pint's factor, as read
    if not (0.0 < k_eq < math.inf and 0.0 < in_unit < math.inf):
        return None
    typed = not inputs[0].assumed
    shown = (in_unit, inputs[0].unit) if typed else (k_eq, si_unit)
    results = [("k_eq", "k_eq", k_eq, si_unit, *shown)]
    if names:
        return forms.values(results, names)
    if as_json:
        return forms.json_text(f"spring-{how}", None, how, inputs, results)
    form = None if human_form is None else human_form()
    if form is None:
        return None
    title = [f"spring-{how}", f"model: {how}", "method: closed-form"]
    return forms.human(form, title, results, inputs, digits)

