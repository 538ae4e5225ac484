"""Results -> text: a rich table on a terminal, plain aligned text when piped, JSON, a bare value,
the cells of a batch CSV row.

Nothing here computes physics; it converts units for display (``--unit``) and formats numbers.
rich is imported only when a table is drawn on a terminal.
"""
from __future__ import annotations

import json
import math
from typing import TYPE_CHECKING

from ..errors import InputError, one_line
from ..result.entries import Entry, Result, format_number

if TYPE_CHECKING:
    from ..result.checks import Check

__all__ = ["to_json", "json_data", "bare_value", "batch_cell", "plain_text", "rich_text",
           "format_number"]


def _shown(entry: Entry, units: dict[str, str]):
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
        value, unit = _shown(entry, units)
        item = {"value": _json_value(value), "unit": unit}
        if entry.uncertainty is not None:
            item = {"value": item["value"],
                    "uncertainty": _json_value(entry.uncertainty_in(unit)), "unit": unit}
        if entry.assumed_si:
            item["assumed_si"] = True
        out[name] = item
    return out


def _explain_format(explain) -> str | None:
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
        fmt = _explain_format(explain)
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
    value, _unit = _shown(entry, units)
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


def _header(result: Result) -> str:
    parts = [result.command]
    if result.scene:
        parts.append(f"scene: {result.scene}")
    if result.model:
        parts.append(f"model: {result.model}")
    if result.method:
        parts.append(f"method: {result.method}")
    inverse = result.extra.get("inverse")
    if inverse:
        parts.append(f"solved for {inverse['unknown']}: {inverse['method']}")
    return "   ".join(parts)


def _with_uncertainty(entry: Entry, value, unit: str, digits: int) -> str:
    """``7.07107 ± 0.18``: the value to ``digits`` figures, its uncertainty to two."""
    text = format_number(value, digits)
    sigma = entry.uncertainty_in(unit) if entry.uncertainty is not None else None
    if sigma is None or isinstance(value, str):
        return text
    return f"{text} ± {format_number(sigma, 2)}"


def _rows(result: Result, units: dict[str, str], digits: int) -> list[tuple[str, ...]]:
    rows = []
    for entry in result.results.values():
        value, unit = _shown(entry, units)
        rows.append((entry.name, entry.symbol or entry.name,
                     _with_uncertainty(entry, value, unit, digits), unit))
    return rows


def _inputs_line(result: Result, digits: int) -> str:
    parts = []
    for entry in result.inputs.values():
        value, unit = _shown(entry, {})
        shown = _with_uncertainty(entry, value, unit, digits)
        text = f"{entry.name} = {shown}{' ' + unit if unit else ''}"
        if entry.assumed_si:
            text += " (assumed SI)"
        parts.append(text)
    return "inputs: " + ", ".join(parts) if parts else ""


def _check_line(check: Check, digits: int) -> str:
    verdict = "pass" if check.passed else "FAIL"
    unit = f" {check.unit}" if check.unit else ""
    return (f"check {check.name}: expected {format_number(check.expected, digits)}{unit}, "
            f"given {format_number(check.given, digits)}{unit}, relative difference "
            f"{check.rel_diff:.2g} (tolerance {check.rtol:g}): {verdict}"
            + (f"; likely slip: {check.diagnosis}" if check.diagnosis else ""))


def _explanation_lines(result: Result, explain: bool | str = True) -> list[str]:
    """The explanation as lines: plain text, or the Markdown or LaTeX to copy."""
    from .explain_render import render_explanation

    if result.explanation is None:
        return ["(no explanation for this result)"]
    return render_explanation(result.explanation, _explain_format(explain)).splitlines()


def plain_text(result: Result, units: dict[str, str], digits: int, checks: list[Check],
               explain: bool | str) -> str:
    """Human output without colour or box drawing (stdout is not a terminal)."""
    rows = [("result", "symbol", "value", "unit")] + _rows(result, units, digits)
    widths = [max(len(r[i]) for r in rows) for i in range(4)]
    lines = [_header(result)]
    for row in rows:
        lines.append("  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip())
    if (inputs := _inputs_line(result, digits)):
        lines.append(inputs)
    lines += [f"warning: {one_line(w)}" for w in result.warnings]
    lines += [_check_line(c, digits) for c in checks]
    if explain:
        lines += _explanation_lines(result, explain)
    return "\n".join(lines)


def rich_text(result: Result, units: dict[str, str], digits: int, checks: list[Check],
              explain: bool | str, console) -> None:
    """Human output on a terminal: a rich table; user text is never read as markup."""
    from rich.table import Table
    from rich.text import Text

    table = Table(title=Text(_header(result)), title_justify="left")
    for column, justify in (("result", "left"), ("symbol", "left"), ("value", "right"),
                            ("unit", "left")):
        table.add_column(column, justify=justify)
    for row in _rows(result, units, digits):
        table.add_row(*(Text(cell) for cell in row))
    console.print(table)
    if (inputs := _inputs_line(result, digits)):
        console.print(Text(inputs, style="dim"))
    for w in result.warnings:
        console.print(Text(f"warning: {one_line(w)}", style="yellow"))
    for c in checks:
        console.print(Text(_check_line(c, digits), style="green" if c.passed else "bold red"))
    if explain:
        for line in _explanation_lines(result, explain):
            console.print(Text(line))
