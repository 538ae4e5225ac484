"""Results -> human output: a rich table on a terminal, plain aligned text when piped, both
fitted to the width; Markdown, LaTeX, CSV and TSV (:mod:`.render_forms`). The machine forms,
JSON, ``--value`` and batch cells, are :mod:`dyncalc.result.encode`.

Fitting (a terminal's width, or ``COLUMNS`` when piped; no limit otherwise): a line breaks
only between phrases (the title's ``scene: ...``, an input's ``k = 100 N/m``) or words, never
inside a number; a table too wide is drawn plain, then without its symbol column, then as one
``name (symbol) = value unit`` a line.

Nothing here computes physics; it converts units for display (``--unit``) and formats numbers.
rich is imported only when a table is drawn on a terminal.
"""
from __future__ import annotations

import os
import textwrap
from typing import TYPE_CHECKING

import click

from ..errors import one_line
from ..result.encode import explain_format
from ..result.entries import Result, format_number
from .render_parts import check_line, header_parts, input_phrases, rows
from .streams import fit

if TYPE_CHECKING:
    from ..result.checks import Check

__all__ = ["human", "plain_text", "rich_text", "format_number", "pack", "plain_width"]

_GAP = "   "  # between the title's phrases
_HEAD = ("result", "symbol", "value", "unit")


def pack(phrases: list[str], width: int | None, sep: str = _GAP, first: str = "",
         indent: str = "") -> list[str]:
    """``phrases`` joined by ``sep`` into lines of at most ``width`` characters, broken only
    between phrases (a phrase wider than the line keeps a line of its own, whole).

    >>> pack(["natural-frequency", "scene: mass-spring", "model: linear"], 40)
    ['natural-frequency   scene: mass-spring', 'model: linear']
    """
    lines: list[str] = []
    tail = sep.rstrip()  # what ends a line that goes on (", " -> ",")
    line, empty = first, True
    for i, phrase in enumerate(phrases):
        candidate = line + phrase if empty else line + sep + phrase
        room = len(candidate) + (len(tail) if i < len(phrases) - 1 else 0)
        if empty or width is None or room <= width:
            line, empty = candidate, False
        else:
            lines.append(line + tail)
            line = indent + phrase
    lines.append(line.rstrip())
    return lines


def _wrap(text: str, width: int | None) -> list[str]:
    """One line of words broken at spaces only (a number is never split), continued indented."""
    if width is None or len(text) <= width:
        return [text]
    lead = text[:len(text) - len(text.lstrip())]
    return textwrap.wrap(text.strip(), width, initial_indent=lead, subsequent_indent=lead + "  ",
                         break_long_words=False, break_on_hyphens=False)


def _inputs_lines(result: Result, digits: int, width: int | None) -> list[str]:
    phrases = [fit(p) for p in input_phrases(result, digits)]
    lines = pack(phrases, width, sep=", ", first="inputs: ", indent="  ") if phrases else []
    # a phrase wider than the line (a vector read in rpm, then in rad/s) breaks at its spaces
    return [part for line in lines for part in _wrap(line, width)]


def _explanation_lines(result: Result, explain: bool | str = True) -> list[str]:
    """The explanation as lines: plain text, or the Markdown or LaTeX to copy."""
    from ..result.explain_render import render_explanation

    if result.explanation is None:
        return ["(no explanation for this result)"]
    return render_explanation(result.explanation, explain_format(explain)).splitlines()


def _aligned(lines: list[tuple[str, ...]]) -> list[str]:
    widths = [max(len(r[i]) for r in lines) for i in range(len(lines[0]))]
    return ["  ".join(cell.ljust(w) for cell, w in zip(row, widths)).rstrip() for row in lines]


def _listed(cells: list[tuple[str, ...]], width: int) -> list[str]:
    """One result a line, ``name (symbol) = value unit``; the value on a line of its own,
    indented, when the line would be too wide (and whole even then)."""
    lines = []
    for name, symbol, value, unit in cells:
        label = name if symbol == name else f"{name} ({symbol})"
        shown_value = f"{value} {unit}".rstrip()
        line = f"{label} = {shown_value}"
        lines += [line] if len(line) <= width else [f"{label} =", f"  {shown_value}"]
    return lines


def table_lines(result: Result, units: dict[str, str], digits: int,
                width: int | None) -> list[str]:
    """The results as plain aligned lines that fit ``width``: the full table, the table
    without its symbol column, or one result a line (:func:`_listed`)."""
    cells = rows(result, units, digits)
    full = _aligned([_HEAD, *cells])
    if width is None or max(map(len, full)) <= width:
        return full
    slim = _aligned([(r[0], r[2], r[3]) for r in [_HEAD, *cells]])
    if max(map(len, slim)) <= width:
        return slim
    return _listed(cells, width)


def plain_text(result: Result, units: dict[str, str], digits: int, checks: list[Check],
               explain: bool | str, width: int | None = None) -> str:
    """Human output without colour or box drawing, its lines at most ``width`` wide (None:
    no limit) wherever they can break between phrases or words."""
    lines = pack([fit(p) for p in header_parts(result)], width)
    lines += table_lines(result, units, digits, width)
    lines += _inputs_lines(result, digits, width)
    for text in ([f"warning: {one_line(w)}" for w in result.warnings]
                 + [check_line(c, digits) for c in checks]):
        lines += _wrap(text, width)
    if explain:
        for line in _explanation_lines(result, explain):
            lines += _wrap(line, width)
    return "\n".join(lines)


def rich_text(result: Result, units: dict[str, str], digits: int, checks: list[Check],
              explain: bool | str, console) -> None:
    """Human output on a terminal: a rich table; user text is never read as markup. A table
    wider than the terminal (rich would cut its numbers, ``5.7006…``) is drawn plain."""
    from rich.measure import Measurement
    from rich.table import Table
    from rich.text import Text

    width = console.width
    table = Table()
    for column, justify in (("result", "left"), ("symbol", "left"), ("value", "right"),
                            ("unit", "left")):
        table.add_column(column, justify=justify, no_wrap=True)
    for row in rows(result, units, digits):
        table.add_row(*(Text(cell) for cell in row))
    natural = Measurement.get(console, console.options.update_width(1 << 20), table).maximum

    def say(line: str, style: str = "") -> None:
        console.print(Text(line, style=style), soft_wrap=True)

    for line in pack([fit(p) for p in header_parts(result)], width):
        say(line, "bold")
    if natural > width:
        for line in table_lines(result, units, digits, width):
            say(line)
    else:
        console.print(table)
    for line in _inputs_lines(result, digits, width):
        say(line, "dim")
    for w in result.warnings:
        for line in _wrap(f"warning: {one_line(w)}", width):
            say(line, "yellow")
    for c in checks:
        for line in _wrap(check_line(c, digits), width):
            say(line, "green" if c.passed else "bold red")
    if explain:
        for text in _explanation_lines(result, explain):
            for line in _wrap(text, width):
                say(line)


def plain_width() -> int | None:
    """The width of plain output: ``COLUMNS`` when it is a positive whole number, else no
    limit (a pipe has no width; a terminal's own is not consulted for it)."""
    text = os.environ.get("COLUMNS", "").strip()
    return int(text) if text.isdigit() and int(text) > 0 else None


def _console():
    """A rich console as wide as the terminal (``COLUMNS``, else the terminal's own width;
    ``COLUMNS=0`` or nonsense, which rich would take as zero columns, falls back to it, then
    to 80). It is a terminal to rich when stdout is one or ``FORCE_COLOR`` is set (not
    empty); rich itself leaves the colour off under ``NO_COLOR``."""
    import shutil

    from rich.console import Console

    width = shutil.get_terminal_size((80, 24)).columns
    forced = True if os.environ.get("FORCE_COLOR") else None
    return Console(width=width if width > 0 else 80, force_terminal=forced)


def human(result: Result, units: dict[str, str], digits: int, checks: list[Check],
          explain: bool | str, fmt: str | None, terminal: bool) -> None:
    """Print ``result`` in a human form: ``fmt`` (``--format``: ``table``, ``markdown``,
    ``csv``, ``tsv``; None when not given) or ``--explain``'s document format (Markdown,
    LaTeX) decides; else the table, with colour on a terminal (``terminal``)."""
    from . import render_forms

    document = explain_format(explain)
    if fmt in ("csv", "tsv"):
        for w in result.warnings:
            click.echo(f"warning: {one_line(w)}", err=True)
        for c in checks:
            if not c.passed:
                click.echo(check_line(c, digits), err=True)
        click.echo(render_forms.delimited(result, units, fmt), nl=False)
    elif fmt == "markdown" or document == "markdown":
        click.echo(render_forms.markdown(result, units, digits, checks, explain), nl=False)
    elif document == "latex":
        click.echo(render_forms.latex(result, units, digits, checks, explain), nl=False)
    elif terminal:
        rich_text(result, units, digits, checks, explain, _console())
    else:
        click.echo(plain_text(result, units, digits, checks, explain, plain_width()))
