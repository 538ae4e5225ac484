"""The matrix grammar (SPEC v2, "Quantities on the command line", Matrices): text -> a square
matrix of quantities, each entry read by the quantity grammar (:mod:`.grammar`).

Forms::

    "2, -1; -1, 2 kN/m"                      rows by ';', entries by ',', one trailing unit
    "[[2, -1], [-1, 2]] kN/m"                nested brackets, one trailing unit
    "[[2 kg, 0.2 kg*m], [0.2 kg*m, 0.05 kg*m^2]]"   a unit on each entry
    "1.0,0.0;0.0,2.0"                        bare entries: SI (what ``--value`` prints)
    "@stiffness.csv"                         a file: one row a line, entries by ','

A trailing unit (after the closing bracket, or on the last entry of the ``;`` form when no
other entry carries one) applies to every entry typed without a unit; an entry with its own
unit keeps it. A bare entry otherwise means the SI unit its place in the matrix calls for
(``--strict-units`` refuses it, except a plain ``0``, which is zero in every unit).

The dimension of an entry is not known while reading: ``modes`` infers each coordinate's kind
from the diagonal of the mass matrix first (:meth:`MatrixText.diagonal_kinds`) and then asks
for every entry's SI value in the dimension of its pair of coordinates (:meth:`MatrixText.si`).
Every refusal names the entry: ``--K row 2, column 1: ...``.
"""
from __future__ import annotations

import math
import os
import re
from typing import Any, Callable

from ..errors import InputError
from .dimensions import Dim
from .grammar import _check_characters, _evaluate, _finish, _show
from .split import split_top

__all__ = ["MatrixText", "MatrixValue", "parse_matrix", "MAX_ORDER", "MAX_MATRIX_TEXT",
           "MAX_MATRIX_FILE"]

MAX_ORDER = 500                  #: rows (degrees of freedom) of one matrix
MAX_MATRIX_TEXT = 20_000         #: characters of a matrix typed inline (larger: @FILE)
MAX_MATRIX_FILE = 16_000_000     #: bytes of a matrix file

_PLAIN = re.compile(r"\s*[+-]?(?:(?:0|[1-9]\d*)(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?\s*")
_WITH_UNIT = re.compile(r"\s*([+-]?(?:(?:0|[1-9]\d*)(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)"
                        r"\s*([A-Za-z_µμΩÅ°][^,;\[\]]*?)\s*")


_NUM = r"[ \t]*[+-]?(?:(?:0|[1-9]\d*)(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?[ \t]*"
#: A file of plain numbers only: read at once (numpy), not entry by entry.
_PLAIN_FILE = re.compile(rf"{_NUM}(?:,{_NUM})*(?:\n{_NUM}(?:,{_NUM})*)*")
#: What :func:`_plain_file` checks instead of ``_PLAIN_FILE`` (the same files pass).
_NUMBER_CHARACTERS = re.compile(r"[0-9eE+\-., \t\n]*")
_LEADING_ZERO = re.compile(r"(?:^|[,\n])[ \t]*[+\-]?0\d")  # at a cell's start only


class _Cell:
    """One entry as read: a plain number (``reading`` None, ``unit`` ""), a number with a
    unit (``unit`` its text), or an expression (``reading`` from the grammar)."""

    __slots__ = ("text", "mag", "unit", "reading")

    def __init__(self, text: str, mag: float | None, unit: str = "", reading: Any = None):
        self.text, self.mag, self.unit, self.reading = text, mag, unit, reading

    @property
    def bare(self) -> bool:
        return not self.unit and (self.reading is None or not self.reading.named)


def _entry_label(label: str, i: int, j: int) -> str:
    return f"{label} row {i + 1}, column {j + 1}"


def _read_cell(text: str, label: str) -> _Cell:
    if not text.strip():
        raise InputError(f"{label} is empty")
    if _PLAIN.fullmatch(text):
        value = float(text)
        if math.isfinite(value):
            return _Cell(text, value)
    m = _WITH_UNIT.fullmatch(text)
    if m and math.isfinite(float(m.group(1))) and "+/-" not in text and "±" not in text:
        return _Cell(text, float(m.group(1)), m.group(2))
    reading = _evaluate(text, label)
    return _Cell(text, None, reading=reading)


def _closing(text: str, start: int, label: str) -> int:
    """The index of the bracket closing the one at ``start``."""
    depth = 0
    for k in range(start, len(text)):
        if text[k] == "[":
            depth += 1
        elif text[k] == "]":
            depth -= 1
            if depth == 0:
                return k
    raise InputError(f"{label}: a '[' is never closed in {_show(text)}")


def _rows_of_brackets(inner: str, label: str) -> list[list[str]]:
    """The rows inside the outer brackets: ``[a, b], [c, d]`` or ``a, b; c, d``."""
    if "[" not in inner:
        return [split_top(row, ",") for row in split_top(inner, ";")]
    rows = []
    for k, part in enumerate(split_top(inner, ",")):
        part = part.strip()
        if not (part.startswith("[") and part.endswith("]")) \
                or _closing(part, 0, label) != len(part) - 1:
            raise InputError(f"{label}: row {k + 1} must be written [a, b, ...]; got "
                             f"{_show(part)}")
        rows.append(split_top(part[1:-1], ","))
    return rows


def _read_file(path: str, label: str) -> str:
    if not path:
        raise InputError(f"{label}: @ needs a file name: @FILE.csv")
    try:
        size = os.path.getsize(path)
        if size > MAX_MATRIX_FILE:
            raise InputError(f"{label}: {_show(path)} is {size} bytes; a matrix file may "
                             f"hold at most {MAX_MATRIX_FILE} bytes")
        with open(path, "rb") as handle:
            data = handle.read(MAX_MATRIX_FILE + 1)
    except OSError as exc:
        raise InputError(f"{label}: cannot read {_show(path)}: "
                         f"{exc.strerror or exc.__class__.__name__}") from None
    if b"\0" in data:
        raise InputError(f"{label}: {_show(path)} is not a text file")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise InputError(f"{label}: {_show(path)} is not UTF-8 text") from None


class MatrixValue(str):
    """A matrix the Python API was given as numbers (a numpy array, a pint Quantity array):
    the text is what a user would have typed (shortened for a large one), ``array`` the
    magnitudes (an ``(n, n)`` float array) and ``unit`` the unit they are in (``""``: SI).
    :func:`parse_matrix` reads it as a ``@FILE.csv`` of plain numbers followed by that unit,
    with no limit on the text's length. ``array`` None: the text itself is to be read (a
    nested list of quantities written out by the API), without the length limit."""

    array: Any
    unit: str

    def __new__(cls, text: str, array: Any = None, unit: str = "") -> MatrixValue:
        value = super().__new__(cls, text)
        value.array, value.unit = array, unit
        return value

    @classmethod
    def of_numbers(cls, array: Any, unit: str) -> MatrixValue:
        """The value of an array of numbers in ``unit``; its text lists the entries when the
        matrix is small (what ``--json``'s inputs show), else its size."""
        rows = array.tolist() if getattr(array, "ndim", 0) == 2 else []
        if rows and len(rows) <= 8:
            text = "; ".join(", ".join(repr(float(v)) for v in row) for row in rows)
        else:
            text = f"[{'x'.join(str(n) for n in getattr(array, 'shape', ()))} array]"
        return cls(f"{text} {unit}".strip(), array, unit)


def _numbers_matrix(value: MatrixValue, label: str, max_order: int) -> MatrixText:
    """A :class:`MatrixValue` of numbers as a :class:`MatrixText` (checked: square, finite,
    at most ``max_order`` rows, its unit readable)."""
    from ..lazy import numpy as np

    array = np.asarray(value.array, dtype=float)
    if array.ndim != 2:
        raise InputError(f"{label} must be a square matrix (2 dimensions); got an array of "
                         f"shape {array.shape}")
    if array.shape[0] > max_order:
        raise InputError(f"{label} has {array.shape[0]} rows; dyncalc takes at most "
                         f"{max_order} degrees of freedom")
    if array.shape[0] != array.shape[1] or array.shape[0] == 0:
        raise InputError(f"{label} must be square: it has shape {array.shape}")
    bad = np.argwhere(~np.isfinite(array))
    if len(bad):
        i, j = (int(x) for x in bad[0])
        raise InputError(f"{_entry_label(label, i, j)} must be finite; got {float(array[i, j])!r}")
    if value.unit:
        _trailing_unit(value.unit, label)
    return MatrixText([], value.unit, str(value), label, plain=array)


def _trailing_unit(unit: str, label: str) -> None:
    from .grammar import _read_unit

    try:
        _read_unit(unit, label)
    except InputError as exc:
        raise InputError(f"{label}: cannot read the unit {_show(unit)} after the "
                         f"matrix: {getattr(exc, 'why', exc)}") from None


class MatrixText:
    """A square matrix as read, before its entries' dimensions are known.

    ``cells[i][j]`` is entry (i, j); ``trailing`` the unit every bare entry takes (``""``:
    none, bare entries are SI); ``text`` what the user typed; ``label`` the option (``--K``).
    """

    __slots__ = ("cells", "trailing", "text", "label", "plain")

    def __init__(self, cells: list[list[_Cell]], trailing: str, text: str, label: str,
                 plain=None):
        self.cells, self.trailing, self.text, self.label = cells, trailing, text, label
        self.plain = plain  # a file of plain numbers: its array (``cells`` then unused)

    @property
    def order(self) -> int:
        return len(self.cells) if self.plain is None else len(self.plain)

    def unit_of(self, i: int, j: int) -> str:
        """The unit entry (i, j) is in as typed: its own, the trailing one, or ``""``."""
        cell = self.cells[i][j]
        if cell.unit:
            return cell.unit
        if cell.reading is not None and cell.reading.named:
            return cell.reading.unit_text or cell.text.strip()
        return self.trailing

    def quantity_of(self, i: int, j: int):
        """Entry (i, j)'s unit as a pint quantity (1 of the unit it was typed in, or the
        expression as read); ``None`` when the entry is bare and there is no trailing unit."""
        if self.plain is not None:
            if not self.trailing:
                return None
            return _evaluate(f"1 {self.trailing}", _entry_label(self.label, i, j)).quantity
        cell = self.cells[i][j]
        if cell.reading is not None and cell.reading.named:
            return cell.reading.quantity
        unit = cell.unit or (self.trailing if cell.bare else "")
        if not unit:
            return None
        return _evaluate(f"1 {unit}", _entry_label(self.label, i, j)).quantity

    def si(self, dim_of: Callable[[int, int], tuple[Dim, str]], *, strict: bool = False):
        """The SI magnitudes (an ``(n, n)`` float array), each entry checked against
        ``dim_of(i, j) -> (Dim, why)``; ``why`` ends the message of a refused entry (which
        coordinates ask for that dimension). Returns ``(array, assumed_si)``: whether some
        non-zero entry was bare and read in SI."""
        from ..lazy import numpy as np

        n = self.order
        if self.plain is not None and self.trailing:
            return self._plain_in_unit(dim_of), False
        if self.plain is not None:
            nonzero = np.argwhere(self.plain != 0.0)
            if strict and len(nonzero):
                i, j = (int(x) for x in nonzero[0])
                dim = dim_of(i, j)[0]
                if dim.kind != "dimensionless":
                    raise InputError(f"{_entry_label(self.label, i, j)}: {float(self.plain[i, j])!r} "
                                     f"has no unit and --strict-units is on; write it with a "
                                     f"unit, e.g. {float(self.plain[i, j])!r} {dim.si}")
            return self.plain.copy(), bool(len(nonzero))
        if not strict and not self.trailing and all(
                c.reading is None and not c.unit for row in self.cells for c in row):
            # plain numbers only (a large @FILE.csv): SI as they are, no per-entry checks left
            out = np.array([[c.mag for c in row] for row in self.cells], dtype=float)
            return out, bool(np.any(out != 0.0))
        out = np.empty((n, n), dtype=float)
        factors: dict[tuple[str, str], float] = {}
        assumed = False
        for i in range(n):
            for j in range(n):
                cell = self.cells[i][j]
                dim, why = dim_of(i, j)
                label = _entry_label(self.label, i, j)
                try:
                    value = self._entry_si(cell, dim, label, strict, factors)
                except InputError as exc:
                    if why:
                        raise InputError(f"{exc} ({why})") from None
                    raise
                if cell.bare and not self.trailing and value != 0.0:
                    assumed = True
                out[i, j] = value
        return out, assumed

    def _plain_in_unit(self, dim_of: Callable[[int, int], tuple[Dim, str]]):
        """The plain array in the trailing unit, in SI. An entry's dimension depends only on
        the kinds of its two coordinates, so the first row and the diagonal meet every
        dimension the matrix asks for; each is checked once against the unit."""
        n = self.order
        factors: dict[str, float] = {}
        for i, j in [(0, j) for j in range(n)] + [(i, i) for i in range(n)]:
            dim, why = dim_of(i, j)
            if dim.name in factors:
                continue
            label = _entry_label(self.label, i, j)
            text = f"{float(self.plain[i, j])!r} {self.trailing}"
            try:
                reading = _evaluate(f"1 {self.trailing}", label)
                factors[dim.name] = float(_finish(reading, f"1 {self.trailing}", dim, label,
                                                  False, False, None).si)
            except InputError:
                try:
                    _finish(_evaluate(text, label), text, dim, label, False, False, None)
                except InputError as exc:
                    raise InputError(f"{exc} ({why})" if why else str(exc)) from None
                raise
        if len(factors) != 1:  # pragma: no cover - one unit has one dimension
            raise InputError(f"{self.label}: one unit cannot serve entries of several "
                             "dimensions")
        from ..lazy import numpy as np

        out = self.plain * next(iter(factors.values()))
        bad = np.argwhere(~np.isfinite(out))
        if len(bad):
            i, j = (int(x) for x in bad[0])
            raise InputError(f"{_entry_label(self.label, i, j)} overflows float64 in SI "
                             f"({float(self.plain[i, j])!r} {self.trailing})")
        return out

    def _entry_si(self, cell: _Cell, dim: Dim, label: str, strict: bool,
                  factors: dict) -> float:
        unit = cell.unit or (self.trailing if cell.bare else "")
        if cell.reading is not None and cell.reading.named:
            return float(_finish(cell.reading, cell.text, dim, label, False, False, None).si)
        if cell.reading is not None:        # a bare expression: (2/12)
            mag = float(cell.reading.quantity.magnitude)
        else:
            mag = cell.mag
        if not unit:
            if strict and mag != 0.0 and dim.kind != "dimensionless":
                raise InputError(f"{label}: {_show(cell.text.strip())} has no unit and "
                                 f"--strict-units is on; write it with a unit, e.g. "
                                 f"{cell.text.strip()} {dim.si}")
            if not math.isfinite(mag):
                raise InputError(f"{label} must be finite; got {cell.text.strip()}")
            return mag
        key = (unit, dim.name)
        factor = factors.get(key)
        if factor is None:
            try:
                reading = _evaluate(f"1 {unit}", label)
                factor = float(_finish(reading, f"1 {unit}", dim, label, False, False,
                                       None).si)
            except InputError:
                text = f"{cell.text.strip()} {self.trailing}" if cell.bare else cell.text
                _finish(_evaluate(text, label), text, dim, label, False, False, None)
                raise
            factors[key] = factor
        value = mag * factor
        if not math.isfinite(value):
            raise InputError(f"{label} overflows float64 in SI ({cell.text.strip()} {unit})")
        return value


def _plain_file(lines: list[str], label: str, max_order: int):
    """The array of a file holding plain numbers only (square, finite), else ``None`` (the
    entry-by-entry reader then gives the exact message)."""
    from ..lazy import numpy as np

    if not lines or len(lines) > max_order:
        return None
    body = "\n".join(lines)
    # _PLAIN_FILE's language, checked faster (a 500 x 500 file: 0.2 s less): the characters
    # of numbers only, no leading zero (007), and every cell a float (else ValueError)
    if not _NUMBER_CHARACTERS.fullmatch(body) or _LEADING_ZERO.search(body):
        return None
    rows = [line.split(",") for line in lines]
    if any(len(row) != len(rows) for row in rows):
        return None
    try:
        values = np.array(rows, dtype=float)
    except ValueError:
        return None
    return values if bool(np.all(np.isfinite(values))) else None


def parse_matrix(text: str, *, label: str = "matrix", max_order: int = MAX_ORDER) -> MatrixText:
    """Read a square matrix (see the module docstring for the forms).

    >>> m = parse_matrix("2, -1; -1, 2 kN/m", label="--K")
    >>> m.order, m.trailing, [[c.mag for c in row] for row in m.cells]
    (2, 'kN/m', [[2.0, -1.0], [-1.0, 2.0]])
    """
    if not isinstance(text, str):
        raise InputError(f"{label}: expected text, got {type(text).__name__}")
    if isinstance(text, MatrixValue) and text.array is not None:
        return _numbers_matrix(text, label, max_order)
    stripped = text.strip()
    if stripped.startswith("@"):
        body = _read_file(stripped[1:], label)
        lines = [line for line in body.splitlines() if line.strip()]
        plain = _plain_file(lines, label, max_order)
        if plain is not None:
            return MatrixText([], "", stripped, label, plain=plain)
        rows = [split_top(line, ",") for line in lines]
        trailing = ""
        source = stripped
    else:
        if len(text) > MAX_MATRIX_TEXT and not isinstance(text, MatrixValue):
            raise InputError(f"{label}: the matrix is {len(text)} characters long; dyncalc "
                             f"reads at most {MAX_MATRIX_TEXT} on the command line (give a "
                             f"larger one as @FILE.csv)")
        _check_characters(text, label)
        source = text
        if stripped.startswith("["):
            end = _closing(stripped, 0, label)
            trailing = stripped[end + 1:].strip()
            rows = _rows_of_brackets(stripped[1:end], label)
        else:
            trailing = ""
            rows = [split_top(row, ",") for row in split_top(stripped, ";")]
    if not rows or rows == [[""]] or not any(c.strip() for row in rows for c in row):
        raise InputError(f"{label} is empty; give a square matrix, e.g. '2, -1; -1, 2 kN/m'")
    if len(rows) > max_order:
        raise InputError(f"{label} has {len(rows)} rows; dyncalc takes at most {max_order} "
                         f"degrees of freedom")
    width = len(rows[0])
    for k, row in enumerate(rows[1:], 2):
        if len(row) != width:
            raise InputError(f"{label}: row {k} has {len(row)} entr{'y' if len(row) == 1 else 'ies'}"
                             f" but row 1 has {width}; "
                             f"every row needs the same number")
    if width != len(rows):
        raise InputError(f"{label} must be square: it has {len(rows)} row"
                         f"{'s' if len(rows) != 1 else ''} of {width} entries")
    cells = [[_read_cell(entry, _entry_label(label, i, j)) for j, entry in enumerate(row)]
             for i, row in enumerate(rows)]
    if trailing:
        _trailing_unit(trailing, label)
    elif not stripped.startswith("@"):
        last = cells[-1][-1]
        others = [c for row in cells for c in row if c is not last]
        if last.unit and all(c.bare for c in others):
            trailing = last.unit
    return MatrixText(cells, trailing, source, label)
