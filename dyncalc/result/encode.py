"""Results -> the machine-readable forms: the JSON object of ``--json`` (and of a batch JSON
line), the bare number of ``--value``, and a batch CSV cell. No terminal, no physics."""
from __future__ import annotations

import json
import math
from typing import TYPE_CHECKING

from ..errors import InputError
from .entries import Entry, Result

if TYPE_CHECKING:
    from .checks import Check

__all__ = ["shown", "explain_format", "to_json", "json_data", "bare_value", "full_number",
           "batch_cell"]


def shown(entry: Entry, units: dict[str, str]):
    """(value, unit) of an entry as displayed, honouring ``--unit NAME=UNIT``."""
    unit = units.get(entry.name)
    if unit is None:
        return entry.value_in(), entry.unit
    return entry.value_in(unit), unit


def _json_value(value):
    if isinstance(value, str):
        return value
    if hasattr(value, "__len__"):
        return [_json_value(float(v)) for v in value]
    value = float(value)
    return None if not math.isfinite(value) else value


def _json_entries(entries: dict[str, Entry], units: dict[str, str]) -> dict:
    out = {}
    for name, entry in entries.items():
        value, unit = shown(entry, units)
        item = {"value": _json_value(value), "unit": unit}
        if entry.uncertainty is not None:
            item = {"value": item["value"],
                    "uncertainty": _json_value(entry.uncertainty_in(unit)), "unit": unit}
        if entry.assumed_si:
            item["assumed_si"] = True
        out[name] = item
    return out


def explain_format(explain) -> str | None:
    """``--explain``'s format (``text``, ``markdown``, ``latex``), None when not asked for."""
    if not explain:
        return None
    return explain if isinstance(explain, str) else "text"


def to_json(result: Result, units: dict[str, str], checks: list[Check],
            explain: bool | str) -> str:
    """The JSON object of SPEC.md (extra keys: ``checks``, ``explanation``, ``extra``)."""
    return json.dumps(json_data(result, units, checks, explain), indent=2, allow_nan=False)


def json_data(result: Result, units: dict[str, str], checks: list[Check],
              explain: bool | str) -> dict:
    """The object :func:`to_json` prints, as a dict (a batch JSON line is this object)."""
    data = {
        "command": result.command,
        "scene": result.scene,
        "model": result.model,
        "method": result.method,
        "inputs": _json_entries(result.inputs, {}),
        "results": _json_entries(result.results, units),
        "warnings": list(result.warnings),
    }
    data.update(_finite(result.extra))
    if checks:
        data["checks"] = _finite([c.as_dict() for c in checks])
    if explain and result.explanation is not None:
        data["explanation"] = result.explanation.as_dict()
        fmt = explain_format(explain)
        if fmt != "text":
            from .explain_render import render_explanation

            data["explanation"]["rendered"] = render_explanation(result.explanation, fmt)
    return data


def _finite(value):
    """``value`` with every NaN or infinite float, in lists and dicts too, as ``None`` (JSON
    null): a check's relative difference beyond float64, an overflowed estimate."""
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if isinstance(value, dict):
        return {key: _finite(item) for key, item in value.items()}
    if isinstance(value, (list, tuple)):
        return [_finite(item) for item in value]
    return value


def bare_value(result: Result, name: str, units: dict[str, str]) -> str:
    """``--value NAME``: the full-precision number (``repr``), vectors comma-separated;
    ``--value 'u(NAME)'`` its standard uncertainty (when an input carried one)."""
    if name.startswith("u(") and name.endswith(")") and name[2:-1] in result.results:
        entry = result.results[name[2:-1]]
        sigma = entry.uncertainty_in(units.get(entry.name))
        if sigma is None:
            raise InputError(f"--value {name}: {entry.name} has no uncertainty (give one on "
                             "an input: 2.0+/-0.1 kg)")
        return full_number(sigma)
    entry = result.results.get(name)
    if entry is None:
        raise InputError(f"--value {name}: there is no result named {name!r}; the results are "
                         f"{', '.join(result.results)}")
    if entry.overflowed:
        raise InputError(f"--value {name}: {name} overflows float64 at these inputs")
    value, _unit = shown(entry, units)
    if isinstance(value, str):
        return value
    return full_number(value)


def full_number(value) -> str:
    """A number as ``--value`` and a batch CSV cell print it: ``repr`` of the float (full
    precision), a vector's components comma-separated."""
    if hasattr(value, "__len__"):
        return ",".join(repr(float(v)) for v in value)
    return repr(float(value))


def batch_cell(entry: Entry, unit: str) -> str:
    """A result in a batch CSV cell, in the column's ``unit``: what ``--value`` prints
    (``repr`` of the float, ``inf``, vectors comma-separated); empty when it overflowed."""
    if entry.overflowed:
        return ""
    value = entry.value_in(unit)
    if isinstance(value, str):
        return value
    return full_number(value)
