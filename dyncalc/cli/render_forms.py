"""Results as a document to paste or a table to load: Markdown (``--format markdown`` or
``--explain=markdown``), LaTeX (``--explain=latex``), CSV and TSV (``--format csv|tsv``).

Markdown and LaTeX are the whole human output (title, results table, inputs, warnings,
checks, explanation) with the human table's numbers: ``--digits`` figures, the display unit.
CSV and TSV are the results table alone, for a spreadsheet: ``name,value,unit`` (with
``uncertainty`` before ``unit`` when a result has one), every number full precision as
``--value`` prints it (``repr``), in the canonical unit unless ``--unit`` names another, as
the machine forms (``--json``, ``--value``, batch) give it. CSV lines end in CRLF as batch's
CSV does (RFC 4180); TSV lines in LF.
"""
from __future__ import annotations

import csv
import io
from typing import TYPE_CHECKING

from ..errors import one_line
from ..result.encode import full_number, machine
from ..result.explain_render import latex_text, md_text as _md, render_explanation
from ..result.entries import Result
from .render_parts import check_line, header_parts, input_phrases, rows

if TYPE_CHECKING:
    from ..result.checks import Check

__all__ = ["markdown", "latex", "delimited"]


def _explanation(result: Result, fmt: str) -> str:
    if result.explanation is None:
        return "(no explanation for this result)\n"
    return render_explanation(result.explanation, fmt)


def markdown(result: Result, units: dict[str, str], digits: int, checks: list[Check],
             explain: bool | str) -> str:
    """The whole output as Markdown: a heading, the scene line, a pipe table, the inputs as a
    paragraph, warnings and checks as a list, then the explanation (``### Explanation``)."""
    title, *meta = header_parts(result)
    parts = [f"## {_md(title)}", ""]
    if meta:
        parts += ["; ".join(_md(m) for m in meta), ""]
    parts += ["| result | symbol | value | unit |", "| --- | --- | ---: | --- |"]
    parts += ["| " + " | ".join(_md(cell) for cell in row) + " |"
              for row in rows(result, units, digits)]
    parts.append("")
    if (inputs := input_phrases(result, digits)):
        parts += ["**Inputs:** " + _md(", ".join(inputs)), ""]
    notes = ([f"- **warning:** {_md(one_line(w))}" for w in result.warnings]
             + [f"- {_md(check_line(c, digits))}" for c in checks])
    if notes:
        parts += notes + [""]
    if explain:
        parts.append(_explanation(result, "markdown"))
    return "\n".join(parts).rstrip("\n") + "\n"


def latex(result: Result, units: dict[str, str], digits: int, checks: list[Check],
          explain: bool | str) -> str:
    """The whole output as a LaTeX fragment: the title, a ``tabular`` of the results (``\\hline``
    rules, no package needed), the inputs, warnings and checks, then the explanation (which
    needs amsmath)."""
    title, *meta = header_parts(result)
    head = rf"\noindent\textbf{{{latex_text(title)}}}"
    if meta:
        head += " (" + "; ".join(latex_text(m) for m in meta) + ")"
    parts = [f"% dyncalc {latex_text(result.command)}", head, "",
             r"\begin{tabular}{llrl}", r"\hline", r"result & symbol & value & unit \\",
             r"\hline"]
    parts += [" & ".join(latex_text(cell) for cell in row) + r" \\"
              for row in rows(result, units, digits)]
    parts += [r"\hline", r"\end{tabular}", ""]
    if (inputs := input_phrases(result, digits)):
        parts += [r"\noindent Inputs: " + latex_text(", ".join(inputs)), ""]
    for w in result.warnings:
        parts += [r"\noindent Warning: " + latex_text(one_line(w)), ""]
    for c in checks:
        parts += [r"\noindent " + latex_text(check_line(c, digits)), ""]
    if explain:
        parts.append(_explanation(result, "latex"))
    return "\n".join(parts).rstrip("\n") + "\n"


def delimited(result: Result, units: dict[str, str], fmt: str) -> str:
    """The results table as CSV (``fmt="csv"``) or TSV (``"tsv"``): full precision, canonical
    units (see the module's docstring); an overflowed result's cell is empty."""
    sigma_column = any(e.uncertainty is not None for e in result.results.values())
    rows = [["name", "value", "uncertainty", "unit"] if sigma_column
            else ["name", "value", "unit"]]
    for entry in result.results.values():
        value, unit = machine(entry, units)
        cell = "" if entry.overflowed else value if isinstance(value, str) else \
            full_number(value)
        row = [entry.name, cell]
        if sigma_column:
            sigma = entry.uncertainty_in(unit) if entry.uncertainty is not None else None
            row.append("" if sigma is None or entry.overflowed else full_number(sigma))
        rows.append(row + [unit])
    out = io.StringIO()
    if fmt == "csv":
        csv.writer(out, lineterminator="\r\n").writerows(rows)
    else:
        csv.writer(out, delimiter="\t", lineterminator="\n",
                   quoting=csv.QUOTE_MINIMAL).writerows(rows)
    return out.getvalue()
