"""One :class:`~dyncalc.result.Explanation`, three renderings: plain text, Markdown (formulas
as ``$$...$$`` display math) and a LaTeX fragment (``align*`` and ``itemize``; needs amsmath).

Every piece of words (assumptions, references, commands, units) is escaped for the target;
the formula lines are LaTeX already and go in as they are.
"""
from __future__ import annotations

import re
import unicodedata

from ..result.explain import latex_escape
from ..result.entries import Explanation

__all__ = ["FORMATS", "render_explanation", "text_lines", "markdown", "latex",
           "variance_line", "md_text", "latex_text"]

FORMATS = ("text", "markdown", "latex")


def variance_line(result: str, shares: dict[str, float]) -> str:
    """``variance of omega: k 20.0 %, m 80.0 %`` (largest share first)."""
    ordered = sorted(shares.items(), key=lambda item: -item[1])
    return f"variance of {result}: " + ", ".join(f"{name} {100 * share:.1f} %"
                                                 for name, share in ordered)


def text_lines(ex: Explanation) -> list[str]:
    lines = ["formula:"] + [f"  {f}" for f in ex.formula]
    if ex.substituted:
        lines += ["values:"] + [f"  {s}" for s in ex.substituted]
    if ex.assumptions:
        lines += ["assumptions:"] + [f"  - {a}" for a in ex.assumptions]
    lines += [variance_line(name, shares) for name, shares in ex.variance.items() if shares]
    if ex.reference:
        lines.append(f"reference: {ex.reference}")
    if ex.example:
        lines.append(f"example: {ex.example}")
    return lines


# --- Markdown ---------------------------------------------------------------------------------

_MD_SPECIAL = re.compile(r"([\\`*_\[\]<>|#$])")


def _md(text: str) -> str:
    return _MD_SPECIAL.sub(r"\\\1", text)


def md_text(text: str) -> str:
    """Words for Markdown, its special characters (``* _ | [ ] ...``) backslash-escaped."""
    return _md(text)


def _md_code(text: str) -> str:
    fence = "``" if "`" in text else "`"
    return f"{fence} {text} {fence}" if fence == "``" else f"`{text}`"


def _formula_tex(ex: Explanation) -> tuple[list[str], list[str]]:
    """The LaTeX formula and substituted lines; words where no LaTeX was written."""
    formula = ex.latex or [r"\text{" + latex_escape(_ascii(f)) + "}" for f in ex.formula]
    values = ex.latex_substituted or [r"\text{" + latex_escape(_ascii(s)) + "}"
                                      for s in ex.substituted]
    return formula, values


def markdown(ex: Explanation) -> str:
    formula, values = _formula_tex(ex)
    parts = ["### Explanation", "", "**Formula**", ""]
    parts += [f"$$ {line} $$" for line in formula] + [""]
    if values:
        parts += ["**Values substituted**", ""] + [f"$$ {line} $$" for line in values] + [""]
    if ex.assumptions:
        parts += ["**Assumptions**", ""] + [f"- {_md(a)}" for a in ex.assumptions] + [""]
    variance = [(n, s) for n, s in ex.variance.items() if s]
    if variance:
        parts += ["**Shares of the variance**", ""]
        parts += [f"- {_md(variance_line(n, s))}" for n, s in variance] + [""]
    if ex.reference or ex.example:
        parts += ["**Textbook example**", ""]
        if ex.reference:
            parts.append(f"- reference: {_md(ex.reference)}")
        if ex.example:
            command, gives, what = ex.example.partition(" gives ")
            parts.append(f"- {_md_code(command)}" + (f" gives {_md(what)}" if gives else ""))
        parts.append("")
    return "\n".join(parts).rstrip() + "\n"


# --- LaTeX ------------------------------------------------------------------------------------

_TEXT_SYMBOLS = {"×": r"\ensuremath{\times}", "°": r"\ensuremath{^\circ}",
                 "±": r"\ensuremath{\pm}", "−": "-", "≈": r"\ensuremath{\approx}",
                 "≤": r"\ensuremath{\le}", "≥": r"\ensuremath{\ge}",
                 "·": r"\ensuremath{\cdot}",
                 "²": r"\ensuremath{^2}", "³": r"\ensuremath{^3}", "µ": r"\ensuremath{\mu}",
                 "—": "---", "–": "--", "’": "'", "“": "``", "”": "''"}


def _ascii(text: str) -> str:
    """Non-ASCII letters and signs of words spelled so that pdfLaTeX takes them."""
    out = []
    for ch in text:
        if ord(ch) < 128:
            out.append(ch)
        elif ch in _TEXT_SYMBOLS:
            out.append(ch)
        else:
            name = unicodedata.name(ch, "")
            m = re.match(r"GREEK (SMALL|CAPITAL) LETTER (\w+)$", name)
            if m:
                letter = m.group(2).lower()
                out.append("\x00" + (letter.capitalize() if m.group(1) == "CAPITAL"
                                     else letter) + "\x01")
            else:
                out.append("?")
    return "".join(out)


def latex_text(text: str) -> str:
    """Words for a LaTeX document: special characters escaped, signs and Greek letters as
    math (``\\ensuremath``)."""
    escaped = latex_escape(_ascii(text)).replace("--", "-{}-")  # no en dash for options
    for ch, tex in _TEXT_SYMBOLS.items():
        escaped = escaped.replace(ch, tex)
    return re.sub("\x00(\\w+)\x01", lambda m: r"\ensuremath{\%s}" % m.group(1), escaped)


def _top_equals(line: str) -> int:
    """Where the first `` = `` outside any braces is (-1: none)."""
    depth = 0
    for i, ch in enumerate(line):
        depth += (ch == "{") - (ch == "}")
        if depth == 0 and line.startswith(" = ", i):
            return i
    return -1


def _align(lines: list[str]) -> list[str]:
    body = []
    for i, line in enumerate(lines):
        at = _top_equals(line)
        row = f"  {line[:at]} &= {line[at + 3:]}" if at >= 0 else f"  &{line}"
        body.append(row + (r" \\" if i < len(lines) - 1 else ""))
    return [r"\begin{align*}", *body, r"\end{align*}"]


def latex(ex: Explanation) -> str:
    formula, values = _formula_tex(ex)
    parts = ["% dyncalc --explain=latex (needs \\usepackage{amsmath})",
             r"\noindent\textbf{Formula}", *_align(formula)]
    if values:
        parts += [r"\noindent\textbf{Values substituted}", *_align(values)]
    if ex.assumptions:
        parts += [r"\noindent\textbf{Assumptions}", r"\begin{itemize}"]
        parts += [rf"  \item {latex_text(a)}" for a in ex.assumptions] + [r"\end{itemize}"]
    variance = [(n, s) for n, s in ex.variance.items() if s]
    if variance:
        parts += [r"\noindent\textbf{Shares of the variance}", r"\begin{itemize}"]
        parts += [rf"  \item {latex_text(variance_line(n, s))}" for n, s in variance]
        parts.append(r"\end{itemize}")
    if ex.reference or ex.example:
        parts += [r"\noindent\textbf{Textbook example}", r"\begin{itemize}"]
        if ex.reference:
            parts.append(rf"  \item reference: {latex_text(ex.reference)}")
        if ex.example:
            command, gives, what = ex.example.partition(" gives ")
            parts.append(rf"  \item \texttt{{{latex_text(command)}}}"
                         + (f" gives {latex_text(what)}" if gives else ""))
        parts.append(r"\end{itemize}")
    return "\n".join(parts) + "\n"


def render_explanation(ex: Explanation, fmt: str) -> str:
    """``ex`` as ``text``, ``markdown`` or ``latex``."""
    if fmt == "markdown":
        return markdown(ex)
    if fmt == "latex":
        return latex(ex)
    return "\n".join(text_lines(ex))
