"""Results -> the machine-readable forms: the JSON object of ``--json`` (and of a batch JSON
line), the bare number of ``--value``, and a batch CSV cell. No terminal, no physics.

The object follows the contract, version 2 (``docs/json.md``; its JSON Schema is
``dyncalc/result/schema/dyncalc-2.schema.json``): the keys of :data:`TOP_KEYS`, results in
their canonical unit unless ``--unit`` names another, everything else under ``"extra"``."""
from __future__ import annotations

import json
import math
from typing import TYPE_CHECKING

from ..errors import InputError
from .entries import Entry, Result, matrix_with_units

if TYPE_CHECKING:
    from .checks import Check

__all__ = ["SCHEMA", "SCHEMA_FILE", "TOP_KEYS", "json_schema", "shown", "machine",
           "explain_format", "to_json", "json_data", "bare_value", "full_number", "batch_cell"]

#: The value of the JSON object's ``"schema"`` key.
SCHEMA = "dyncalc/2"
#: The JSON Schema (draft 2020-12) of the object, relative to this package (package data).
SCHEMA_FILE = "schema/dyncalc-2.schema.json"
#: The JSON object's top-level keys, in order; nothing else is at the top level.
TOP_KEYS = ("schema", "command", "scene", "model", "method", "inputs", "results", "warnings",
            "extra")


def json_schema() -> dict:
    """The JSON Schema of the ``--json`` object, as shipped inside the installed package."""
    from importlib.resources import files

    return json.loads(files(__package__).joinpath(SCHEMA_FILE).read_text(encoding="utf-8"))


def shown(entry: Entry, units: dict[str, str]):
    """(value, unit) of an entry as displayed, honouring ``--unit NAME=UNIT``."""
    unit = units.get(entry.name)
    if unit is None:
        return entry.value_in(), entry.unit
    return entry.value_in(unit), unit


def machine(entry: Entry, units: dict[str, str]):
    """(value, unit) of a result in ``--json`` and ``--value``: in the unit ``--unit NAME=UNIT``
    names, else in the entry's canonical unit (docs/json.md, "Canonical units")."""
    unit = units.get(entry.name)
    if unit is None:
        unit = entry.canonical_unit
    return entry.value_in(unit), unit


def _json_value(value):
    if isinstance(value, str):
        return value
    if getattr(value, "ndim", 1) == 2:
        return [_json_value(row) for row in value]
    if hasattr(value, "__len__"):
        return [_json_value(float(v)) for v in value]
    value = float(value)
    return None if not math.isfinite(value) else value


def _json_item(value, sigma, unit: str) -> dict:
    if sigma is None:
        return {"value": _json_value(value), "unit": unit}
    return {"value": _json_value(value), "uncertainty": _json_value(sigma), "unit": unit}


def _json_inputs(entries: dict[str, Entry]) -> dict:
    """Inputs as typed: the value in the unit typed, that unit, and the text itself."""
    out = {}
    for name, entry in entries.items():
        sigma = entry.uncertainty_in() if entry.uncertainty is not None else None
        item = _json_item(entry.value_in(), sigma, entry.unit)
        if entry.text is not None:
            item["text"] = entry.text
        if entry.assumed_si:
            item["assumed_si"] = True
        out[name] = item
    return out


def _json_results(entries: dict[str, Entry], units: dict[str, str]) -> dict:
    """Results in their canonical unit, or the one ``--unit`` names."""
    out = {}
    for name, entry in entries.items():
        value, unit = machine(entry, units)
        sigma = entry.uncertainty_in(unit) if entry.uncertainty is not None else None
        out[name] = _json_item(value, sigma, unit)
    return out


def explain_format(explain) -> str | None:
    """``--explain``'s format (``text``, ``markdown``, ``latex``), None when not asked for."""
    if not explain:
        return None
    return explain if isinstance(explain, str) else "text"


def to_json(result: Result, units: dict[str, str], checks: list[Check],
            explain: bool | str) -> str:
    """The JSON object of docs/json.md, indented (:func:`json_data`)."""
    return json.dumps(json_data(result, units, checks, explain), indent=2, allow_nan=False)


def json_data(result: Result, units: dict[str, str], checks: list[Check],
              explain: bool | str) -> dict:
    """The object :func:`to_json` prints, as a dict (a batch JSON line is this object).

    ``extra`` holds :attr:`Result.extra` (error estimates, ``inverse``, ``variance``, a fit,
    timings, ``plot``), then ``checks`` and ``explanation`` when asked for."""
    extra = _finite(result.extra)
    if checks:
        extra["checks"] = _finite([c.as_dict() for c in checks])
    if explain and result.explanation is not None:
        extra["explanation"] = _finite(result.explanation.as_dict())
        fmt = explain_format(explain)
        if fmt != "text":
            from .explain_render import render_explanation

            extra["explanation"]["rendered"] = render_explanation(result.explanation, fmt)
    return {
        "schema": SCHEMA,
        "command": result.command,
        "scene": result.scene,
        "model": result.model,
        "method": result.method,
        "inputs": _json_inputs(result.inputs),
        "results": _json_results(result.results, units),
        "warnings": list(result.warnings),
        "extra": extra,
    }


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
    """``--value NAME``: the full-precision number (``repr``) in the canonical unit (or the one
    ``--unit`` names), vectors comma-separated; ``--value 'u(NAME)'`` its standard uncertainty
    in the same unit (when an input carried one)."""
    if name.startswith("u(") and name.endswith(")") and name[2:-1] in result.results:
        entry = result.results[name[2:-1]]
        sigma = entry.uncertainty_in(machine(entry, units)[1])
        if sigma is None:
            raise InputError(f"--value {name}: {entry.name} has no uncertainty (give one on "
                             "an input: 2.0+/-0.1 kg)")
        return full_number(sigma)
    entry = result.results.get(name)
    if entry is None and name in result.unavailable:
        raise InputError(f"--value {name}: {result.unavailable[name]}")
    if entry is None:
        raise InputError(f"--value {name}: there is no result named {name!r}; the results are "
                         f"{', '.join(result.results)}")
    if entry.overflowed:
        raise InputError(f"--value {name}: {name} overflows float64 at these inputs")
    value, _unit = machine(entry, units)
    if isinstance(value, str):
        return value
    if entry.units is not None and name not in units:
        return matrix_with_units(value, entry.units, repr)
    return full_number(value)


def full_number(value) -> str:
    """A number as ``--value`` and a batch CSV cell print it: ``repr`` of the float (full
    precision), a vector's components comma-separated, a matrix's rows separated by ``;``
    (``1.0,0.0;0.0,2.0``: the matrix grammar reads it back)."""
    if getattr(value, "ndim", 1) == 2:
        return ";".join(full_number(row) for row in value)
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
    if entry.units is not None and not unit:
        return matrix_with_units(value, entry.units, repr)
    return full_number(value)
