"""The full path's output forms for a quick result: ``--value``, ``--json`` and the plain
table (:mod:`dyncalc.result.encode`, :func:`dyncalc.cli.render.plain_text` with no width
limit), written again without click, pint or numpy.

A result is ``(name, symbol, SI value, SI unit, value shown, unit shown)``; the inputs are
:class:`dyncalc.quick.read.Input`.

>>> print(table(["spring-series", "model: series"], [("k_eq", "k_eq", 120.0, "N/m", 120.0,
...             "N/m")], [], 6))
spring-series   model: series
result  symbol  value  unit
k_eq    k_eq    120    N/m
"""
from __future__ import annotations

__all__ = ["values", "json_text", "table", "terminal", "human"]

_BOLD, _DIM, _RESET = "\x1b[1m", "\x1b[2m", "\x1b[0m"


def values(results, names: list[str]) -> str:
    """``--value NAME ...``: the SI value of each, ``repr``, one a line."""
    by_name = {result[0]: result[2] for result in results}
    return "\n".join(repr(by_name[name]) for name in names)


def json_text(command: str, scene, model: str, inputs, results) -> str:
    """The ``--json`` object of docs/json.md (schema dyncalc/2), indented as the full path
    indents it."""
    import json

    shown = {}
    for entry in inputs:
        item = {"value": entry.value, "unit": entry.unit, "text": entry.text}
        if entry.assumed:
            item["assumed_si"] = True
        shown[entry.name] = item
    return json.dumps({
        "schema": "dyncalc/2", "command": command, "scene": scene, "model": model,
        "method": "closed-form", "inputs": shown,
        "results": {r[0]: {"value": r[2], "unit": r[3]} for r in results},
        "warnings": [], "extra": {}}, indent=2, allow_nan=False)


def human(form, title: list[str], results, inputs, digits: int) -> str | None:
    """The human output in ``form``: ``"plain"`` (:func:`table`) or a terminal's width
    (:func:`terminal`; ``None`` where it does not fit)."""
    if form == "plain":
        return table(title, results, inputs, digits)
    return terminal(title, results, inputs, digits, form)


def _cells(results, digits: int) -> list[tuple[str, str, str, str]]:
    return [("result", "symbol", "value", "unit")] + [
        (r[0], r[1], f"{r[4]:.{digits}g}", r[5]) for r in results]


def _inputs_line(inputs, digits: int) -> str:
    """``inputs: k = 2 kN/m = 2000 N/m, m = 4 kg`` (empty without inputs)."""
    phrases = []
    for entry in inputs:
        phrase = f"{entry.name} = {entry.value:.{digits}g} {entry.unit}"
        if entry.assumed:
            phrase += " (assumed SI)"
        elif not entry.canonical:
            phrase += f" = {entry.si:.{digits}g} {entry.si_unit}"
        phrases.append(phrase)
    return "inputs: " + ", ".join(phrases) if phrases else ""


def table(title: list[str], results, inputs, digits: int) -> str:
    """The plain human output: the title's phrases, the aligned results table, the inputs as
    read (``k = 2 kN/m = 2000 N/m``, ``m = 4 kg (assumed SI)``)."""
    rows = _cells(results, digits)
    widths = [max(len(row[i]) for row in rows) for i in range(4)]
    lines = ["   ".join(title)]
    lines += ["  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip() for row in rows]
    inputs_line = _inputs_line(inputs, digits)
    if inputs_line:
        lines.append(inputs_line)
    return "\n".join(lines)


def terminal(title: list[str], results, inputs, digits: int, width: int) -> str | None:
    """The human output as the full path draws it on a terminal ``width`` columns wide with
    rich (:func:`dyncalc.cli.render.rich_text`): the title in bold, the table in rich's
    default box (heavy head, its header cells bold, the value column right-aligned, a space
    of padding each side), the inputs dim. ``None`` where rich would lay it out otherwise
    (the title, the table or the inputs wider than the terminal) or a character might not be
    one column wide.

    >>> text = terminal(["spring-series"], [("k_eq", "k_eq", 120.0, "N/m", 120.0, "N/m")],
    ...                 [], 6, 80)
    >>> print(text.replace(_BOLD, "").replace(_RESET, ""))
    spring-series
    ┏━━━━━━━━┳━━━━━━━━┳━━━━━━━┳━━━━━━┓
    ┃ result ┃ symbol ┃ value ┃ unit ┃
    ┡━━━━━━━━╇━━━━━━━━╇━━━━━━━╇━━━━━━┩
    │ k_eq   │ k_eq   │   120 │ N/m  │
    └────────┴────────┴───────┴──────┘
    """
    rows = _cells(results, digits)
    head = "   ".join(title)
    inputs_line = _inputs_line(inputs, digits)
    text = head + inputs_line + "".join(cell for row in rows for cell in row)
    if not all(" " <= c <= "~" or "\u0391" <= c <= "\u03c9" for c in text):
        return None  # ASCII and the Greek letters: one column each
    widths = [max(len(row[i]) for row in rows) for i in range(4)]
    if max(len(head), len(inputs_line), sum(widths) + 13) > width:
        return None  # 4 columns: 2 of padding each, 5 rules

    def cell(text: str, i: int) -> str:
        return text.rjust(widths[i]) if i == 2 else text.ljust(widths[i])

    def rule(left: str, line: str, cross: str, right: str) -> str:
        return left + cross.join(line * (w + 2) for w in widths) + right

    lines = [_BOLD + head + _RESET, rule("┏", "━", "┳", "┓"),
             "┃" + "┃".join(f"{_BOLD} {_RESET}{_BOLD}{cell(text, i)}{_RESET}{_BOLD} {_RESET}"
                            for i, text in enumerate(rows[0])) + "┃",
             rule("┡", "━", "╇", "┩")]
    lines += ["│" + "│".join(f" {cell(text, i)} " for i, text in enumerate(row)) + "│"
              for row in rows[1:]]
    lines.append(rule("└", "─", "┴", "┘"))
    if inputs_line:
        lines.append(_DIM + inputs_line + _RESET)
    return "\n".join(lines)
