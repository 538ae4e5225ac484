"""The pieces every human form of a result shares (the terminal and plain tables of
:mod:`.render`, the Markdown and LaTeX of :mod:`.render_forms`): the title's phrases, the
table's rows as text, the inputs as read, a check's verdict."""
from __future__ import annotations

from typing import TYPE_CHECKING

from ..result.encode import shown
from ..result.entries import Entry, Result, format_number, matrix_with_units
from .streams import fit

if TYPE_CHECKING:
    from ..result.checks import Check

__all__ = ["header_parts", "rows", "input_phrases", "check_line"]


def header_parts(result: Result) -> list[str]:
    """The title's phrases: the command, ``scene: ...``, ``model: ...``, ``method: ...``."""
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
    return parts


#: A vector with more components than this is shown by its ends in the human table (a
#: 500-mass chain's mode shapes would print 250,000 numbers); --json and --value give all.
LONG_VECTOR = 12
#: A matrix input of a larger order is shown as typed (``@stiffness.csv``) or by its size.
LONG_MATRIX = 8


def _long(value) -> str | None:
    """The human table's short form of a long vector or large matrix, else None."""
    ndim = getattr(value, "ndim", 0)
    if ndim == 1 and len(value) > LONG_VECTOR:
        head = ", ".join(format_number(float(v), 6) for v in value[:3])
        tail = ", ".join(format_number(float(v), 6) for v in value[-3:])
        return f"({head}, ..., {tail}) [{len(value)} components; --json for all]"
    if ndim == 2 and len(value) > LONG_MATRIX:
        return f"[{value.shape[0]}x{value.shape[1]} matrix]"
    return None


def _with_uncertainty(entry: Entry, value, unit: str, digits: int) -> str:
    """``7.07107 ± 0.18``: the value to ``digits`` figures, its uncertainty to two."""
    short = _long(value)
    if short is not None:
        return short
    text = format_number(value, digits)
    sigma = entry.uncertainty_in(unit) if entry.uncertainty is not None else None
    if sigma is None or isinstance(value, str):
        return text
    shown_sigma = format_number(sigma, 2)
    if "e+" in shown_sigma and not hasattr(sigma, "__len__") and abs(float(sigma)) < 1e15:
        shown_sigma = str(int(float(shown_sigma)))  # 100, not 1e+02
    return f"{text} ± {shown_sigma}"


def rows(result: Result, units: dict[str, str], digits: int) -> list[tuple[str, ...]]:
    rows = []
    for entry in result.results.values():
        value, unit = shown(entry, units)
        if entry.units is not None and entry.name not in units:
            text = matrix_with_units(value, entry.units, lambda v: format_number(v, digits))
        else:
            text = _with_uncertainty(entry, value, unit, digits)
        rows.append(tuple(map(fit, (entry.name, entry.symbol or entry.name, text, unit))))
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


def _input_phrase(entry: Entry, digits: int) -> str:
    """How one input was read: ``k = 2 kN/m = 2000 N/m``, ``k = 1500 N / (7 mm) = 214286
    N/m``, ``k = 200 N/m (assumed SI)``; the value in the unit typed and, where that is not
    the canonical unit, in it too."""
    value, unit = shown(entry, {})
    if getattr(value, "ndim", 0) == 2 and len(value) > LONG_MATRIX and entry.text:
        return f"{entry.name} = {entry.text.strip()}"  # a large matrix: as typed (@FILE)
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


def input_phrases(result: Result, digits: int) -> list[str]:
    """Each input as read, one phrase each (the ``inputs:`` line)."""
    return [_input_phrase(entry, digits) for entry in result.inputs.values()]


def check_line(check: Check, digits: int) -> str:
    verdict = "pass" if check.passed else "FAIL"
    unit = f" {check.unit}" if check.unit else ""
    return (f"check {check.name}: expected {format_number(check.expected, digits)}{unit}, "
            f"given {format_number(check.given, digits)}{unit}, relative difference "
            f"{check.rel_diff:.2g} (tolerance {check.rtol:g}): {verdict}"
            + (f"; likely slip: {check.diagnosis}" if check.diagnosis else ""))
