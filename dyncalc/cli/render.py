"""Results -> human text: a rich table on a terminal, plain aligned text when piped (the
machine forms, JSON, ``--value`` and batch cells, are :mod:`dyncalc.result.encode`).

Nothing here computes physics; it converts units for display (``--unit``) and formats numbers.
rich is imported only when a table is drawn on a terminal.
"""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..errors import one_line
from ..result.encode import explain_format, shown
from ..result.entries import Entry, Result, format_number
from .streams import fit

if TYPE_CHECKING:
    from ..result.checks import Check

__all__ = ["plain_text", "rich_text", "format_number"]


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
    shown_sigma = format_number(sigma, 2)
    if "e+" in shown_sigma and not hasattr(sigma, "__len__") and abs(float(sigma)) < 1e15:
        shown_sigma = str(int(float(shown_sigma)))  # 100, not 1e+02
    return f"{text} ± {shown_sigma}"


def _rows(result: Result, units: dict[str, str], digits: int) -> list[tuple[str, ...]]:
    rows = []
    for entry in result.results.values():
        value, unit = shown(entry, units)
        rows.append(tuple(map(fit, (entry.name, entry.symbol or entry.name,
                                    _with_uncertainty(entry, value, unit, digits), unit))))
    return rows


def _same_unit(a: str, b: str) -> bool:
    """Whether two unit texts name the same unit (``m/s**2`` and ``m/s^2``)."""
    if a == b:
        return True
    from ..units import parse_unit

    try:
        return parse_unit(a) == parse_unit(b)
    except Exception:  # not a unit dyncalc reads: shown as it is
        return False


def _input_part(entry: Entry, digits: int) -> str:
    """How one input was read: ``k = 2 kN/m = 2000 N/m``, ``k = 1500 N / (7 mm) = 214286
    N/m``, ``k = 200 N/m (assumed SI)``; the value in the unit typed and, where that is not
    the canonical unit, in it too."""
    value, unit = shown(entry, {})
    number = _with_uncertainty(entry, value, unit, digits)
    if entry.reading:  # typed as an expression: the reading, then its value
        number, unit = entry.reading, ""
    text = f"{entry.name} = {number}{' ' + unit if unit else ''}"
    if entry.assumed_si:
        return text + " (assumed SI)"
    canonical = entry.canonical_unit
    if (entry.dim is not None and not isinstance(entry.si, str)
            and (entry.reading or not _same_unit(unit, canonical))):
        si = _with_uncertainty(entry, entry.si, canonical, digits)
        text += f" = {si}{' ' + canonical if canonical else ''}"
    return text


def _inputs_line(result: Result, digits: int) -> str:
    parts = [_input_part(entry, digits) for entry in result.inputs.values()]
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
    from ..result.explain_render import render_explanation

    if result.explanation is None:
        return ["(no explanation for this result)"]
    return render_explanation(result.explanation, explain_format(explain)).splitlines()


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
    from rich.measure import Measurement
    from rich.table import Table
    from rich.text import Text

    table = Table(title=Text(_header(result)), title_justify="left")
    for column, justify in (("result", "left"), ("symbol", "left"), ("value", "right"),
                            ("unit", "left")):
        table.add_column(column, justify=justify, no_wrap=True)
    for row in _rows(result, units, digits):
        table.add_row(*(Text(cell) for cell in row))
    natural = Measurement.get(console, console.options.update_width(1 << 20), table).maximum
    if natural > console.width:
        # a terminal narrower than the table: rich would cut the numbers ("5.7006…"); the
        # plain table instead, its lines left whole for the terminal to wrap
        console.print(Text(plain_text(result, units, digits, checks, explain)),
                      soft_wrap=True)
        return
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
