"""Reading a whole column of cells at once (the vectorised path): a unit per group of cells."""
from __future__ import annotations

import functools
import json
import re

import numpy as np

from ..errors import InputError
from .floats import json_floats, parse_floats
from .header import _LITERAL

#: A unit the vectorised path may read once for a whole column: names, ``*``, ``/``, and
#: numbers only as exponents or as a leading ``1/`` (so ``X unit`` is ``X`` times the unit,
#: exactly, in floats: ``2 1/s``).
#: (Only spaces and tabs separate tokens, as in dyncalc's tokenizer, which refuses others.)
_NAME = (r"[A-Za-z_µμΩΩÅ°%][A-Za-z0-9_µμΩΩÅ°]*"
         r"(?:[ \t]*(?:\*\*|\^)[ \t]*[+-]?[0-9]+(?:\.[0-9]+)?|[²³])?")
_SIMPLE_UNIT = rf"(?:1[ \t]*/[ \t]*)?{_NAME}(?:[ \t]*[*/·×]?[ \t]*{_NAME})*"
_SIMPLE_UNIT_RE = re.compile(_SIMPLE_UNIT)
#: A cell the vectorised path reads: a plain number and perhaps a simple unit. The number is
#: an atomic group, so it is the literal dyncalc's tokenizer would read, never a shorter one.
_LITERAL_CELL = rf"[+-]?(?>{_LITERAL})"
_CELL_RE = re.compile(rf"[ \t]*([+-]?(?>{_LITERAL}))[ \t]*({_SIMPLE_UNIT})?[ \t]*")
#: Every line of a column joined by line breaks, split in one pass into the number and the
#: rest (which must then be a simple unit, checked once per distinct unit).
_CELL_LINE_RE = re.compile(rf"^[ \t]*([+-]?(?>{_LITERAL}))[ \t]*(.*)$", re.M)
#: Number literals, one a line, each whole (what ``_CELL_LINE_RE`` reads as a cell's number).
_LITERALS_RE = re.compile(rf"{_LITERAL_CELL}(?:\n{_LITERAL_CELL})*")
_PLAIN_COLUMN_CHARS_RE = re.compile(r"[0-9.eE+\- \t\n]*")
#: A number with a leading zero (``007``), which the one-off reader refuses; an exponent's
#: zero (``1e-05``) is not one.
_LEADING_ZERO_RE = re.compile(r"0(?<![0-9.eE]0)(?<![eE][+-]0)[0-9]")


def _plain_floats(cells) -> np.ndarray | None:
    """The values of a column whose every cell is a plain number, read at once; ``None``
    otherwise (a cell with a unit, an empty cell, anything the one-off reader would read
    differently from ``float``)."""
    joined = "\n".join(cells)
    if not joined or not _PLAIN_COLUMN_CHARS_RE.fullmatch(joined):
        return None
    # JSON refuses a leading zero: what orjson reads needs no search for one
    values = json_floats(joined.replace("\n", ","), len(cells), cells)
    if values is not None:
        return values
    if _LEADING_ZERO_RE.search(joined):
        return None
    try:  # (``+5``, ``.5``: ``float`` of each cell)
        return np.fromiter(map(float, cells), dtype=np.float64, count=len(cells))
    except ValueError:
        return None


class _UnitInfo:
    """What reading ``X unit`` gives for every plain number ``X``, found once by reading
    ``1 unit`` the one-off way: the pint unit, the SI unit, and how the input entry shows it."""

    __slots__ = ("units", "target", "typed", "unit_json", "back", "same")


def _unit_info(unit: str, dim, strict: bool, cache: dict) -> _UnitInfo | None:
    key = ("unit", unit, dim, strict)
    if key in cache:
        return cache[key]
    from ..units import parse_quantity, same_units

    info = None
    if not unit or _SIMPLE_UNIT_RE.fullmatch(unit):
        try:
            sample = parse_quantity(f"1 {unit}" if unit else "1", dim, label="batch",
                                    strict=strict)
        except InputError:
            sample = None
        # the reader keeps the unit as typed (``1 unit`` reads as 1 of it), so pint's
        # conversion of the whole array is the one-off's conversion of a cell; a rate it
        # normalises (rpm to rad/s, a cycle rate in turns to Hz) is converted from the unit
        # typed, where probes show that pint's array conversion is the reader's to the bit
        rate = None
        if sample is not None and float(sample.quantity.magnitude) != 1.0 and sample.unit_text:
            rate = _rate_units(unit, dim, strict, sample.unit_text)
        if sample is not None and (float(sample.quantity.magnitude) == 1.0 or rate):
            info = _UnitInfo()
            info.units = sample.quantity.units
            info.target = dim.si.replace("^", "**") if dim.si else ""
            info.back = None
            if rate:
                info.units, info.target, info.back = rate
            info.typed = bool(sample.unit_text)
            info.same = same_units(info.units, info.target)
            info.unit_json = (json.dumps(sample.unit_text or dim.si),
                              ', "assumed_si": true' if sample.assumed_si else "")
    cache[key] = info
    return info


#: Values whose reading the array conversion of a rate unit must reproduce to the bit.
_RATE_PROBES = (1.0, 3.0, 0.1, 7.25, 12345.678, 1e-7, 6.02e23, 2.5e-300, 1.5e300)


def _rate_units(unit: str, dim, strict: bool, shown_in: str):
    """``(pint unit as typed, target, back)`` converting an angular rate (``rpm``, ``deg/s``:
    to rad/s) or a cycle rate in turns (``rpm`` as f: to turn/s, then read as Hz) the way the
    one-off reader does, and back (``back(si)``: the value its input entry shows, converted
    from SI to ``shown_in``, the unit text the reader kept), bit for bit on every probe;
    ``None`` where no such pair is found."""
    from ..units import convert, parse_quantity, registry

    if dim.kind not in ("angular-rate", "cycle-rate"):
        return None
    ureg = registry()
    try:
        typed = ureg.parse_units(unit.replace("^", "**"))
    except Exception:  # pint's own errors: not a unit pint reads alone
        return None
    try:
        expected = [parse_quantity(f"{x!r} {unit}", dim, label="batch", strict=strict).si
                    for x in _RATE_PROBES]
    except InputError:
        return None
    for target in ("rad/s",) if dim.kind == "angular-rate" else ("Hz", "turn/s"):
        with np.errstate(over="ignore", under="ignore", invalid="ignore"):
            try:
                got = ureg.Quantity(np.array(_RATE_PROBES), typed).to(target).magnitude
            except Exception:  # pint: not convertible
                continue
        if not _same_bits(got, expected):
            continue
        back = functools.partial(_converted_to, dim=dim, unit=shown_in)
        try:
            same = _same_bits(back(expected), [convert(x, dim, shown_in) for x in expected])
        except InputError:
            return None
        return (typed, target, back) if same else None
    return None


def _converted_to(si, dim, unit: str) -> np.ndarray:
    """SI values converted to ``unit`` as an input entry shows them (the one-off's
    :func:`~dyncalc.units.convert`, on an array)."""
    from ..units import convert

    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        return np.asarray(convert(np.asarray(si, dtype=float), dim, unit), dtype=float)


def _same_bits(a, b) -> bool:
    return np.array_equal(np.asarray(a, dtype=float).view(np.int64),
                          np.asarray(b, dtype=float).view(np.int64))


class _ColumnValues:
    """A parameter column read for the vectorised path: which rows it can take (``ok``), their
    SI values, and for JSON the value each input entry shows and its unit text."""

    __slots__ = ("ok", "si", "shown", "unit_json")


def _read_column(cells, header_unit: str, param, strict: bool, cache: dict,
                 plain: np.ndarray | None = None) -> _ColumnValues:
    """Read the cells of one parameter column (rows known to give it): a unit is read once per
    group of cells that share it, and pint converts the group's values as one array."""
    n = len(cells)
    out = _ColumnValues()
    out.ok = np.zeros(n, dtype=bool)
    out.si = np.zeros(n)
    out.shown = np.zeros(n)
    out.unit_json = [("", "")] * n  # (unit JSON, assumed_si JSON) of each cell
    if plain is None:
        plain = _plain_floats(cells)
    groups: dict[str, tuple[list[int] | None, np.ndarray, list[str]]] = {}
    one_unit = _one_unit(cells) if plain is None else None
    if plain is not None:
        groups[header_unit] = (None, plain, cells)
    elif one_unit is not None:  # what the one pass below gives such a column, sooner
        literals, unit, values = one_unit
        groups[unit] = (None, values, literals)
    else:
        joined = "\n".join(cells)
        pairs = _CELL_LINE_RE.findall(joined) if n else []
        if len(pairs) == n and joined.count("\n") == n - 1:  # one pass over the column
            literals, raw_units = zip(*pairs)
            values = parse_floats(literals)
            # the unit each cell is in: its own (trailing blanks off), or the header's
            code_of = {raw: raw.rstrip(" \t") or header_unit for raw in set(raw_units)}
            distinct = sorted(set(code_of.values()))
            if len(distinct) == 1:
                unit = distinct[0]
                if not unit or _SIMPLE_UNIT_RE.fullmatch(unit):
                    groups[unit] = (None, values, literals)
            else:
                index = {unit: k for k, unit in enumerate(distinct)}
                codes = np.fromiter(map(index.__getitem__, map(code_of.__getitem__, raw_units)),
                                    dtype=np.intp, count=n)
                for k, unit in enumerate(distinct):
                    if unit and not _SIMPLE_UNIT_RE.fullmatch(unit):
                        continue  # not a plain unit: those cells go to the generic path
                    rows = np.flatnonzero(codes == k).tolist()
                    groups[unit] = (rows, values[rows], [literals[i] for i in rows])
        else:
            members: dict[str, list[int]] = {}
            literals = [""] * n
            for i, cell in enumerate(cells):
                m = _CELL_RE.fullmatch(cell)
                if m is None:
                    continue
                literals[i] = m.group(1)
                members.setdefault((m.group(2) or "").strip() or header_unit, []).append(i)
            for unit, rows in members.items():
                lits = [literals[i] for i in rows]
                groups[unit] = (rows, np.array(list(map(float, lits)), dtype=float), lits)
    return _converted(out, groups, param, strict, cache)


def _one_unit(cells) -> tuple[list[str], str, np.ndarray] | None:
    """``(literals, unit, values)`` of a column whose every cell is a plain number followed by
    the first cell's text after its number (the same blanks and simple unit: ``2.5 m``,
    ``-1e3 m``), split by replacing that text away in the joined column instead of a regex
    pass a cell; ``None`` otherwise. It is what :data:`_CELL_LINE_RE` gives such a column:
    every literal is a whole number literal (read as JSON numbers at once, a subset of them,
    else checked by :data:`_LITERALS_RE` in one pass), and a text after the number that starts
    with an exponent's letter (``e5m``) is left to the regex, which could read ``2e5m``
    otherwise.

    Example: ``["2 m", "0.5 m"]`` gives ``(["2", "0.5"], "m", array([2. , 0.5]))``."""
    first = _CELL_RE.fullmatch(cells[0]) if len(cells) else None
    if first is None or not first.group(2) or not cells[0].startswith(first.group(1)):
        return None
    suffix = cells[0][len(first.group(1)):]
    if suffix[0] in "eE" or suffix != suffix.rstrip(" \t"):
        return None
    # (no line break in the suffix: each of the n - 1 line breaks ends one "suffix\n")
    n, joined = len(cells), "\n".join(cells)
    if joined.count("\n") != n - 1 or joined.count(suffix + "\n") != n - 1 \
            or not joined.endswith(suffix):
        return None
    text = joined.replace(suffix + "\n", "\n")[:-len(suffix)]
    if " " in text or "\t" in text:
        return None
    literals = text.split("\n")
    values = json_floats(text.replace("\n", ","), n, literals) \
        if _PLAIN_COLUMN_CHARS_RE.fullmatch(text) else None
    if values is None:
        if not _LITERALS_RE.fullmatch(text):
            return None
        values = _plain_floats(literals)
    unit = first.group(2).strip(" \t")
    if values is None or not _SIMPLE_UNIT_RE.fullmatch(unit):
        return None
    return literals, unit, values


def read_literals(literals: list[str], unit: str, param, strict: bool, cache: dict,
                  values: np.ndarray | None = None) -> _ColumnValues:
    """:func:`_read_column` of the cells ``literal + unit`` (plain number literals, as
    ``_CELL_LINE_RE`` splits them, all in one ``unit``), from their literals alone: the
    values read at once (or given: ``values``, as :func:`parse_floats` reads them), the
    unit once.

    Example: the literals ``["2", "0.5"]`` with ``m`` read as the cells ``2 m`` and ``0.5 m``.
    """
    n = len(literals)
    out = _ColumnValues()
    out.ok = np.zeros(n, dtype=bool)
    out.si = np.zeros(n)
    out.shown = np.zeros(n)
    out.unit_json = [("", "")] * n
    groups = {}
    if n and (not unit or _SIMPLE_UNIT_RE.fullmatch(unit)):
        groups[unit] = (None, parse_floats(literals) if values is None else values, literals)
    return _converted(out, groups, param, strict, cache)


def _converted(out: _ColumnValues, groups: dict, param, strict: bool,
               cache: dict) -> _ColumnValues:
    """``out`` filled in from ``groups`` (unit -> (rows or ``None`` for all, values, their
    literals)): each group's values converted to SI by pint as one array."""
    from ..units import registry

    n = len(out.ok)
    ureg = registry()
    for unit, (rows, values, literals) in groups.items():
        info = _unit_info(unit, param.dim, strict, cache)
        if info is None:
            continue
        good = np.isfinite(values)  # a literal beyond float64 is refused by the one-off reader
        for j in np.flatnonzero(values == 0.0):  # ... and so is one that underflows to zero
            if re.search(r"[1-9]", re.split(r"[eE]", literals[j])[0]):
                good[j] = False
        if info.same:  # what pint's conversion gives: the values themselves
            converted = np.asarray(values, dtype=float)
        else:
            with np.errstate(over="ignore", under="ignore", invalid="ignore"):
                converted = np.asarray(
                    ureg.Quantity(values, info.units).to(info.target).magnitude, dtype=float)
        good &= np.isfinite(converted)
        if param.constraint == "positive":
            good &= converted > 0
        elif param.constraint == "nonnegative":
            good &= converted >= 0
        elif param.constraint == "nonzero":
            good &= converted != 0
        index = slice(None) if rows is None else np.asarray(rows, dtype=np.intp)
        out.ok[index] = good
        out.si[index] = converted
        out.shown[index] = converted if not info.typed else \
            values if info.back is None else info.back(converted)
        if rows is None:
            out.unit_json = [info.unit_json] * n
        else:
            for i in rows:
                out.unit_json[i] = info.unit_json
    return out
