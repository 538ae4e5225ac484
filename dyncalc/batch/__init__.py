"""Batch mode (``--batch FILE``): one command over every row of a CSV file, in one process.

The file's header names the parameters: a command's option names without the dashes
(``k``, ``m``, ``length``, ``v0``) or, for the scene commands, scene parameter names (``l``,
``J``, ``M``). A header cell may carry a unit, ``k [N/m]``: it applies to every cell of the
column that has no unit of its own. A cell may carry its own unit (``2 kN/m``), so a column may
mix units; an empty cell means "not given", exactly as an option left out. Each row is the
one-off command with those parameters, so a row's numbers are exactly the one-off's.

Output: the input columns as read, then one column per result, ``omega [rad/s]`` (CSV, full
precision, the number ``--value`` would print); or, with ``--json``, one JSON object per line,
the one-off ``--json`` object with the row's line number (``"line"``) in front. Cells may carry
uncertainties (``2.0+/-0.1``, ``(100 ± 5) N/m``): such rows take the generic path, and when the
first chunk has any, each result column is followed by ``u(NAME) [unit]``, its standard
uncertainty (empty for rows without one).

Two paths give the same numbers:

* the generic path evaluates each row through the same library call as the one-off command
  (:class:`NaturalFrequencyRows` calls
  :func:`dyncalc.commands.natural_frequency.compute_scene`,
  :class:`SpringRows` :func:`dyncalc.commands.springs.network_stiffness`, ...);
* a vectorised path (:func:`_natural_frequency_fast`) computes whole chunks of
  ``natural-frequency`` rows of the closed-form linear scenes (mass-spring, torsional, the
  pendulum without an amplitude) at once with numpy, with the same kernels written for arrays
  (:func:`~dyncalc.physics.numerics.sqrt_ratio_array`: the binary exponents split off with
  ``np.frexp``, as :func:`~dyncalc.physics.numerics.sqrt_ratio` does with ``math.frexp``).
  A unit is read once per chunk and column (pint converts the whole array), not once per cell. Any row it cannot
  take exactly as the one-off would (a cell that is not a plain number with a plain unit, a
  value out of range, a result that is zero, infinite or needs a warning) goes to the generic
  path, so refusals and warnings are the one-off's own.

Rows are read, computed and written in chunks of :data:`CHUNK_ROWS`, so memory stays flat
however long the file. A bad row is reported on stderr as ``Error: line N: ...`` (its line in
the file, the header being line 1); with ``--on-error stop`` (the default) the rows before it
have been written and nothing after it is; with ``--on-error skip`` every bad row gets its own
line and every good row is written. The exit status is 2 when any row failed.

Malformed files: a column the command does not read is refused at the header (not passed
through, so a mistyped optional parameter is never ignored silently); a line longer than
:data:`MAX_LINE` characters, a line that is not UTF-8 and a row with the wrong number of cells
are bad rows; a quote left open, text after a closing quote and an I/O error while reading end
the run at their line, after the rows before it are written.
"""
from __future__ import annotations

import csv
import gc
import io
import itertools
import json
import math
import os
import re
import sys
from typing import Any

import numpy as np

from ..errors import EXIT_BAD_INPUT, EXIT_OK, InputError, one_line
from ..physics.numerics import sqrt_ratio_array
from ..physics.outcome import damped_arrays, periodic_arrays
from ..result.propagate import propagate

__all__ = ["run_batch", "NaturalFrequencyRows", "SpringRows", "DampingRows", "RollingRows",
           "CoriolisRows", "CHUNK_ROWS", "ON_ERROR"]

#: Rows read, computed and written at a time; the result columns of CSV output are those of
#: the first chunk's rows.
CHUNK_ROWS = 16384
ON_ERROR = ("stop", "skip")
#: Set to "1" to send every row through the generic (one-off) path: for tests and benchmarks.
GENERIC_ENV = "DYNCALC_BATCH_GENERIC"

# --------------------------------------------------------------------------------------------
# Reading the header and the cells

_HEADER_RE = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\[([^\[\]]*)\])?\s*$")
_LITERAL = r"(?:(?:0|[1-9][0-9]*)(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?"
_NUMBER_WORDS_RE = re.compile(r"(?<![A-Za-z_])(?:infinity|inf|nan)(?![A-Za-z0-9_])", re.I)
_ANY_LITERAL_RE = re.compile(r"(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
_UNIT_CHAR_RE = re.compile(r"[^\W\d]|[%°]")
#: A plain number, as dyncalc's quantity reader reads it (no leading zeros, ASCII digits).
_PLAIN_RE = re.compile(rf"[+-]?{_LITERAL}")
#: A unit the vectorised path may read once for a whole column: names, ``*``, ``/``, and
#: numbers only as exponents (so ``X unit`` is ``X`` times the unit, exactly, in floats).
#: (Only spaces and tabs separate tokens, as in dyncalc's tokenizer, which refuses others.)
_NAME = (r"[A-Za-z_µμΩΩÅ°%][A-Za-z0-9_µμΩΩÅ°]*"
         r"(?:[ \t]*(?:\*\*|\^)[ \t]*[+-]?[0-9]+(?:\.[0-9]+)?|[²³])?")
_SIMPLE_UNIT = rf"{_NAME}(?:[ \t]*[*/·×]?[ \t]*{_NAME})*"
_SIMPLE_UNIT_RE = re.compile(_SIMPLE_UNIT)
#: A cell the vectorised path reads: a plain number and perhaps a simple unit. The number is
#: an atomic group, so it is the literal dyncalc's tokenizer would read, never a shorter one.
_CELL_RE = re.compile(rf"[ \t]*([+-]?(?>{_LITERAL}))[ \t]*({_SIMPLE_UNIT})?[ \t]*")
#: Every line of a column joined by line breaks, split in one pass into the number and the
#: rest (which must then be a simple unit, checked once per distinct unit).
_CELL_LINE_RE = re.compile(rf"^[ \t]*([+-]?(?>{_LITERAL}))[ \t]*(.*)$", re.M)


def has_own_unit(cell: str) -> bool:
    """Whether a cell names a unit of its own (``2 kN/m``, ``5%``), not only numbers
    (``2``, ``-1.5e3``, ``inf``, ``0,0,2``, ``2*3``)."""
    rest = _NUMBER_WORDS_RE.sub(" ", _ANY_LITERAL_RE.sub(" ", cell))
    return _UNIT_CHAR_RE.search(rest) is not None


def with_header_unit(cell: str, unit: str) -> str:
    """The text a cell stands for under a header unit: ``2`` under ``[kN/m]`` is ``2 kN/m``,
    ``2*3`` is ``(2*3) kN/m``, ``0,0,2`` is ``0,0,2 kN/m``; a cell with its own unit is kept."""
    if not unit or has_own_unit(cell):
        return cell
    if "," in cell or _PLAIN_RE.fullmatch(cell) or _NUMBER_WORDS_RE.fullmatch(cell.lstrip("+-")):
        return f"{cell} {unit}"
    return f"({cell}) {unit}"


class Column:
    """One column of the input: where it is, its header cell, name, unit and parameter key."""

    __slots__ = ("index", "raw", "name", "unit", "key")

    def __init__(self, index: int, raw: str, name: str, unit: str, key: str):
        self.index, self.raw, self.name, self.unit, self.key = index, raw, name, unit, key


def read_header(line: int, cells: list[str], spec) -> list[Column]:
    """The header's columns, checked: names the command reads, each parameter once, units
    that are units."""
    from ..units import parse_unit

    columns: list[Column] = []
    by_key: dict[str, str] = {}
    for index, raw in enumerate(cells):
        text = raw.strip()
        if not text:
            raise InputError(f"line {line}: column {index + 1} has no name; the header names the "
                             f"parameters, e.g. {spec.example_header}")
        m = _HEADER_RE.match(text)
        if not m:
            raise InputError(f"line {line}: cannot read the column name {text[:60]!r}; write NAME "
                             "or NAME [UNIT], e.g. k [N/m]")
        name, unit = m.group(1), (m.group(2) or "").strip()
        key = spec.key(name)
        if key is None:
            raise InputError(f"line {line}: unknown column {name!r}; {spec.known()}")
        if key in by_key:
            first = by_key[key]
            if first == name:
                raise InputError(f"line {line}: column {name!r} is given twice")
            raise InputError(f"line {line}: columns {first!r} and {name!r} both give {key}")
        by_key[key] = name
        if unit:
            parse_unit(unit, label=f"line {line}: column {name}")
        columns.append(Column(index, text, name, unit, key))
    return columns



# --------------------------------------------------------------------------------------------
# What each command reads from a row (the generic path calls the one-off's library function)


class RowSpec:
    """How one command turns a row's cells into its library call.

    ``key(name)`` maps a column name to the parameter it gives (``None``: not a column this
    command reads); ``compute(texts, labels)`` runs the one-off computation on the cells given
    (texts by parameter key, header units applied) and returns its
    :class:`~dyncalc.result.Result`; ``fast`` is the vectorised path, if the command has one.
    """

    command = ""
    example_header = "k [N/m],m [kg]"
    fast = None

    def key(self, name: str) -> str | None:
        raise NotImplementedError

    def known(self) -> str:
        raise NotImplementedError

    def compute(self, texts: dict[str, str], labels: dict[str, str]):
        raise NotImplementedError


class NaturalFrequencyRows(RowSpec):
    """``natural-frequency``: columns are the standard options (``k``, ``length``, ...) and
    scene parameter names; ``--scene``, ``--method`` and ``--rtol`` apply to every row, and
    without ``--scene`` each row's columns choose its scene, as for a one-off."""

    command = "natural-frequency"

    def __init__(self, standard: dict[str, str], *, scene: str | None = None,
                 method: str | None = None, rtol: float | None = None, strict: bool = False):
        from ..scenes import catalog, get_scene

        self.standard = dict(standard)
        self.scene = get_scene(scene) if scene is not None else None
        self.method, self.rtol, self.strict = method, rtol, strict
        if self.scene is not None:
            self.params = [p.name for p in self.scene.params]
        else:
            self.params = list(dict.fromkeys(p.name for s in catalog().values()
                                             for p in s.params))
        self.fast = _natural_frequency_fast

    def key(self, name):
        param = self.standard.get(name, name)
        return param if param in self.params else None

    def known(self):
        options = [o for o, p in self.standard.items() if p in self.params]
        if self.scene is not None:
            names = list(dict.fromkeys([*self.params, *options]))
            return (f"natural-frequency --scene {self.scene.name} reads "
                    f"{', '.join(names)}")
        return (f"natural-frequency reads {', '.join(options)} and the parameters of the "
                "scenes (dyncalc scenes lists them)")

    def scene_for(self, keys) -> str:
        from ..commands.natural_frequency import infer_scene

        return self.scene.name if self.scene is not None else infer_scene(set(keys))

    def compute(self, texts, labels):
        from ..commands.natural_frequency import compute_scene

        return compute_scene(self.scene_for(texts), texts, labels=labels, method=self.method,
                             rtol=self.rtol, strict=self.strict)


class SpringRows(RowSpec):
    """``spring-series`` / ``spring-parallel``: element columns ``k1``, ``k2``, ... (each cell
    one element as on the command line: ``200 N/m``, ``cantilever(l=2m)``; the non-empty ones
    of a row, in column order) and shared-value columns named for an element parameter
    (``EI``, ``E``, ``l``, ...), as the command line's ``NAME=QUANTITY`` words."""

    example_header = "k1 [N/m],k2 [N/m]"
    _ELEMENT_RE = re.compile(r"^k[0-9]+$")

    def __init__(self, how: str, *, strict: bool = False):
        from ..commands.springs import ELEMENTS

        self.how, self.strict = how, strict
        self.command = f"spring-{how}"
        self.shared = list(dict.fromkeys(p for kind in ELEMENTS.values() for p in kind.params))

    def key(self, name):
        if self._ELEMENT_RE.match(name) or name in self.shared:
            return name
        return None

    def known(self):
        return (f"{self.command} reads elements k1, k2, ... and shared values "
                f"{', '.join(self.shared)}")

    def compute(self, texts, labels):
        from ..commands.springs import network_stiffness

        words = [text for key, text in texts.items() if self._ELEMENT_RE.match(key)]
        words += [f"{key}={text}" for key, text in texts.items()
                  if not self._ELEMENT_RE.match(key)]
        return network_stiffness(self.how, words, strict=self.strict)


class DampingRows(RowSpec):
    """``damping-ratio``: columns ``c``, ``k``, ``m``, ``decrement``, ``ratio``, ``cycles``,
    ``amplitudes``, ``omega``, ``g``; with ``--scene``, also that scene's parameters."""

    command = "damping-ratio"
    example_header = "decrement,omega [rad/s]"
    OPTIONS = ("c", "k", "m", "decrement", "ratio", "cycles", "amplitudes", "omega", "g")

    def __init__(self, *, scene: str | None = None, method: str | None = None,
                 rtol: float | None = None, strict: bool = False):
        self.scene, self.method, self.rtol, self.strict = scene, method, rtol, strict
        self.scene_params: list[str] = []
        if scene is not None:
            from ..scenes import get_scene

            self.scene_params = [p.name for p in get_scene(scene).params
                                 if p.name not in self.OPTIONS]

    def key(self, name):
        return name if name in self.OPTIONS or name in self.scene_params else None

    def known(self):
        names = [*self.OPTIONS, *self.scene_params]
        return f"damping-ratio reads {', '.join(names)}"

    def compute(self, texts, labels):
        from ..commands.damping_ratio import damping_ratio

        options = {name: texts.get(name) for name in self.OPTIONS}
        params = tuple(f"{k}={v}" for k, v in texts.items() if k not in self.OPTIONS)
        return damping_ratio(**options, scene=self.scene, params=params, method=self.method,
                             rtol=self.rtol, strict=self.strict)


class RollingRows(RowSpec):
    """``rolling-onset``: columns ``v0``, ``mu``, ``body``, ``kappa``, ``radius``, ``omega0``,
    ``g``, ``incline``."""

    command = "rolling-onset"
    example_header = "v0 [m/s],mu"
    OPTIONS = ("v0", "mu", "body", "kappa", "radius", "omega0", "g", "incline")

    def __init__(self, *, method: str | None = None, rtol: float | None = None,
                 strict: bool = False):
        self.method, self.rtol, self.strict = method, rtol, strict

    def key(self, name):
        return name if name in self.OPTIONS else None

    def known(self):
        return f"rolling-onset reads {', '.join(self.OPTIONS)}"

    def compute(self, texts, labels):
        from ..commands.rolling_onset import rolling_onset_result

        return rolling_onset_result(dict(texts), method=self.method, rtol=self.rtol,
                                    strict=self.strict)


class CoriolisRows(RowSpec):
    """``coriolis``: columns named for its options (``omega``, ``vr``, ``r``, ``alpha``,
    ``a0``, ``ar``, ``mass``, ``latitude``, ``speed``, ``heading``, ``vertical``)."""

    command = "coriolis"
    example_header = "omega [rad/s],vr [m/s]"

    def __init__(self, *, strict: bool = False):
        from ..commands.coriolis import OPTIONS

        self.options = tuple(OPTIONS)
        self.strict = strict

    def key(self, name):
        return name if name in self.options else None

    def known(self):
        return f"coriolis reads {', '.join(self.options)}"

    def compute(self, texts, labels):
        from ..commands.coriolis import coriolis_result

        return coriolis_result(dict(texts), strict=self.strict)


# --------------------------------------------------------------------------------------------
# The vectorised kernels (the careful scalar kernels of physics/numerics.py, for arrays)



#: The natural-frequency scenes the vectorised path computes: scene -> (the two parameters of
#: omega = sqrt(a / b), the parameters the row must not give (they need another model)).
FAST_SCENES = {
    "mass-spring": (("k", "m"), ()),
    "torsional": (("kt", "J"), ()),
    "pendulum": (("g", "l"), ("amplitude",)),
}



# --------------------------------------------------------------------------------------------
# Reading a column of cells at once

_PLAIN_COLUMN_CHARS_RE = re.compile(r"[0-9.eE+\- \t\n]*")
#: A number with a leading zero (``007``), which the one-off reader refuses; an exponent's
#: zero (``1e-05``) is not one.
_LEADING_ZERO_RE = re.compile(r"0(?<![0-9.eE]0)(?<![eE][+-]0)[0-9]")


def _plain_floats(cells) -> np.ndarray | None:
    """The values of a column whose every cell is a plain number, read at once; ``None``
    otherwise (a cell with a unit, an empty cell, anything the one-off reader would read
    differently from ``float``)."""
    joined = "\n".join(cells)
    if not joined or not _PLAIN_COLUMN_CHARS_RE.fullmatch(joined) \
            or _LEADING_ZERO_RE.search(joined):
        return None
    try:
        return np.fromiter(map(float, cells), dtype=float, count=len(cells))
    except ValueError:
        return None


def _reprs(values: list[float]) -> list[str]:
    """``list(map(repr, values))``, a third faster: the list's repr writes every float's repr
    in C (no float repr holds ``", "``)."""
    return str(values)[1:-1].split(", ") if values else []


class _UnitInfo:
    """What reading ``X unit`` gives for every plain number ``X``, found once by reading
    ``1 unit`` the one-off way: the pint unit, the SI unit, and how the input entry shows it."""

    __slots__ = ("units", "target", "typed", "unit_json")


def _unit_info(unit: str, dim, strict: bool, cache: dict) -> _UnitInfo | None:
    key = ("unit", unit, dim, strict)
    if key in cache:
        return cache[key]
    from ..units import parse_quantity

    info = None
    if not unit or _SIMPLE_UNIT_RE.fullmatch(unit):
        try:
            sample = parse_quantity(f"1 {unit}" if unit else "1", dim, label="batch",
                                    strict=strict)
        except InputError:
            sample = None
        if sample is not None and dim.kind in ("plain", "dimensionless") \
                and float(sample.quantity.magnitude) == 1.0:
            info = _UnitInfo()
            info.units = sample.quantity.units
            info.target = dim.si.replace("^", "**") if dim.si else ""
            info.typed = bool(sample.unit_text)
            info.unit_json = (json.dumps(sample.unit_text or dim.si)
                              + (', "assumed_si": true' if sample.assumed_si else ""))
    cache[key] = info
    return info


class _ColumnValues:
    """A parameter column read for the vectorised path: which rows it can take (``ok``), their
    SI values, and for JSON the value each input entry shows and its unit text."""

    __slots__ = ("ok", "si", "shown", "unit_json")


def _read_column(cells, header_unit: str, param, strict: bool, cache: dict,
                 plain: np.ndarray | None = None) -> _ColumnValues:
    """Read the cells of one parameter column (rows known to give it): a unit is read once per
    group of cells that share it, and pint converts the group's values as one array."""
    from ..units import registry

    n = len(cells)
    out = _ColumnValues()
    out.ok = np.zeros(n, dtype=bool)
    out.si = np.zeros(n)
    out.shown = np.zeros(n)
    out.unit_json = [""] * n
    if plain is None:
        plain = _plain_floats(cells)
    groups: dict[str, tuple[list[int] | None, np.ndarray, list[str]]] = {}
    if plain is not None:
        groups[header_unit] = (None, plain, cells)
    else:
        joined = "\n".join(cells)
        pairs = _CELL_LINE_RE.findall(joined) if n else []
        if len(pairs) == n and joined.count("\n") == n - 1:  # one pass over the column
            literals, raw_units = zip(*pairs)
            values = np.fromiter(map(float, literals), dtype=float, count=n)
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
    ureg = registry()
    for unit, (rows, values, literals) in groups.items():
        info = _unit_info(unit, param.dim, strict, cache)
        if info is None:
            continue
        good = np.isfinite(values)  # a literal beyond float64 is refused by the one-off reader
        for j in np.flatnonzero(values == 0.0):  # ... and so is one that underflows to zero
            if re.search(r"[1-9]", re.split(r"[eE]", literals[j])[0]):
                good[j] = False
        with np.errstate(over="ignore", under="ignore", invalid="ignore"):
            converted = np.asarray(ureg.Quantity(values, info.units).to(info.target).magnitude,
                                   dtype=float)
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
        out.shown[index] = values if info.typed else converted
        if rows is None:
            out.unit_json = [info.unit_json] * n
        else:
            for i in rows:
                out.unit_json[i] = info.unit_json
    return out


# --------------------------------------------------------------------------------------------
# The vectorised natural-frequency path


class FastBlock:
    """Rows of a chunk computed together: their positions in the chunk, the result arrays (SI,
    in the order the one-off gives them) and kinds, and for JSON the constant part of each
    line (``head``) and each row's ``inputs`` object text."""

    __slots__ = ("rows", "values", "kinds", "head", "inputs")

    def __init__(self, rows, values, kinds, head, inputs):
        self.rows, self.values, self.kinds, self.head, self.inputs = (
            rows, values, kinds, head, inputs)


def _default_input(p, strict: bool, cache: dict):
    """(SI value, JSON text of the input entry) of a scene parameter's default."""
    key = ("default", p.name, p.default, strict)
    if key not in cache:
        from ..units import parse_quantity

        parsed = parse_quantity(p.default, p.dim, label=p.name, strict=strict,
                                constraint=p.constraint)
        shown = float(parsed.quantity.magnitude) if parsed.unit_text else parsed.si
        text = json.dumps({p.name: {"value": shown, "unit": parsed.unit_text or p.dim.si}})
        cache[key] = (parsed.si, text[1:-1])
    return cache[key]


def _natural_frequency_fast(spec: NaturalFrequencyRows, columns: list[Column], table,
                            want_json: bool, cache: dict) -> list[FastBlock]:
    """The rows of this chunk the vectorised path computes, as blocks (one per scene and set
    of parameters given); every other row is left to the generic path. ``table`` holds the
    chunk's cells column by column."""
    from ..scenes import get_scene
    from ..result.kinds import result_kind

    if spec.method not in (None, "auto") or not table or len(columns) > 62:
        return []
    n = len(table[0])
    present: dict[str, np.ndarray] = {}
    cells: dict[str, Any] = {}
    plain: dict[str, np.ndarray | None] = {}
    for col in columns:
        column = table[col.index]
        values = _plain_floats(column)
        plain[col.key] = values
        if values is not None:
            present[col.key] = np.ones(n, dtype=bool)
            cells[col.key] = column
            continue
        column = [c.strip() for c in column]
        cells[col.key] = column
        present[col.key] = np.fromiter((c != "" for c in column), dtype=bool, count=n)
    keys = [col.key for col in columns]
    units = {col.key: col.unit for col in columns}
    signature = np.zeros(n, dtype=np.int64)
    for bit, key in enumerate(keys):
        signature |= present[key].astype(np.int64) << bit
    blocks = []
    # the distinct signatures, in order (np.unique would import numpy.ma: 6 ms)
    for sig in sorted(set(signature.tolist())):
        given = [key for bit, key in enumerate(keys) if (sig >> bit) & 1]
        if not given:
            continue
        try:
            scene_name = spec.scene_for(given)
        except InputError:
            continue
        if scene_name not in FAST_SCENES:
            continue
        (a_name, b_name), excluded = FAST_SCENES[scene_name]
        scene = get_scene(scene_name)
        names = {p.name for p in scene.params}
        if any(k not in names or k in excluded for k in given):
            continue
        params = [p for p in scene.params if p.name not in excluded
                  and (p.name in given or p.default is not None)]
        if any(p.default is None and not p.optional and p.name not in given
               for p in scene.params if p.name not in excluded):
            continue
        rows = np.arange(n) if sig == int(signature[0]) and (signature == sig).all() \
            else np.flatnonzero(signature == sig)
        whole = len(rows) == n
        good = np.ones(len(rows), dtype=bool)
        si: dict[str, Any] = {}
        inputs = []
        for p in params:
            if p.name in given:
                column = cells[p.name] if whole else [cells[p.name][i] for i in rows]
                read = _read_column(column, units[p.name], p, spec.strict, cache,
                                    plain[p.name] if whole else None)
                good &= read.ok
                si[p.name] = read.si
                inputs.append((p.name, read))
            else:
                value, text = _default_input(p, spec.strict, cache)
                si[p.name] = np.full(len(rows), value)
                inputs.append((p.name, text))
        if not good.any():
            continue
        with np.errstate(all="ignore"):
            omega = sqrt_ratio_array(np.where(good, si[a_name], 1.0),
                                     np.where(good, si[b_name], 1.0))
            values = periodic_arrays(omega)
            if "zeta" in si:
                good &= si["zeta"] < 1.0   # at or above critical: a warning, generic path
                values.update(damped_arrays(omega, np.where(good, si["zeta"], 0.0)))
            for array in values.values():  # zero or beyond float64: warnings, generic path
                good &= np.isfinite(array) & (array != 0.0)
        if not good.any():
            continue
        keep = np.flatnonzero(good)
        if len(keep) != len(rows):
            rows = rows[keep]
            values = {name: array[keep] for name, array in values.items()}
        kinds = {name: result_kind(name) for name in values}
        head = texts = None
        if want_json:
            head = (f'"command": "natural-frequency", "scene": {json.dumps(scene_name)}, '
                    '"model": "linear", "method": "closed-form"')
            parts = []
            for name, read in inputs:
                if isinstance(read, str):
                    parts.append([read] * len(keep))
                    continue
                shown = read.shown if len(keep) == len(read.shown) else read.shown[keep]
                unit_json = read.unit_json if len(keep) == len(read.shown) \
                    else [read.unit_json[i] for i in keep.tolist()]
                prefix = (json.dumps(name) + ': {"value": ').replace("%", "%%")
                if unit_json and unit_json.count(unit_json[0]) == len(unit_json):
                    template = prefix + '%r, "unit": ' + unit_json[0].replace("%", "%%") + "}"
                    parts.append(list(map(template.__mod__, shown.tolist())))
                else:
                    parts.append([f"{prefix}{v!r}, \"unit\": {u}}}"
                                  for v, u in zip(shown.tolist(), unit_json)])
            texts = list(map(", ".join, zip(*parts)))
        blocks.append(FastBlock(rows, values, kinds, head, texts))
    return blocks


# --------------------------------------------------------------------------------------------
# Writing


class _Sink:
    """A file-like object collecting what a ``csv.writer`` writes, one string per row."""

    __slots__ = ("write",)

    def __init__(self, collect):
        self.write = collect


def _csv_lines(rows) -> list[str]:
    """Each row as one CSV line (without the line end), quoted as ``csv.writer`` quotes (the
    writer quotes a cell holding a line break only if the line end has that character)."""
    lines: list[str] = []
    csv.writer(_Sink(lambda line: lines.append(line[:-2])),
               lineterminator="\r\n").writerows(rows)
    return lines


class _Failure(Exception):
    """A row that cannot be written (its message, without the line number)."""


class _Writer:
    """Turns each chunk's outcomes into text, in order: CSV (the input columns, then a column
    per result) or JSON lines. The result columns are fixed by the first chunk's rows."""

    def __init__(self, header: list[str], as_json: bool, units: dict[str, str], on_error: str,
                 out, err):
        self.header, self.as_json, self.units, self.on_error = header, as_json, units, on_error
        self.out, self.err = out, err
        self.columns: list[str] | None = None  # result names, in order of first appearance
        self.col_units: dict[str, str] = {}
        self.checked_units: set[str] = set()
        self.uncertain: set[str] = set()  # results given a u(NAME) column after their own

    # -- the result columns, from the first chunk's rows
    def fix_columns(self, outcomes, blocks, upto: int) -> None:
        names: dict[str, Any] = {}
        first: list[tuple[int, list]] = []
        for block in blocks:
            position = int(block.rows[0])
            if position < upto:
                first.append((position, [(name, block.kinds[name].unit, block.kinds[name].dim)
                                         for name in block.values]))
        for i in range(upto):
            kind, item = outcomes[i]
            if kind == "ok":
                first.append((i, [(name, e.unit, e.dim) for name, e in item.results.items()]))
                self.uncertain.update(name for name, e in item.results.items()
                                      if e.uncertainty is not None)
        first.sort(key=lambda pair: pair[0])
        for _position, pairs in first:
            for name, unit, dim in pairs:
                if name not in names:
                    names[name] = dim
                    self.col_units[name] = self.units.get(name, unit)
        if not names:
            return
        for name in self.units:
            if name not in names:
                raise InputError(f"--unit {name}: there is no result named {name!r}; the "
                                 f"results are {', '.join(names)}")
        for name, dim in names.items():
            self.check_unit(name, dim)
        self.columns = list(names)
        if not self.as_json:
            header = list(self.header)
            inputs = {_HEADER_RE.match(h).group(1) for h in self.header}
            for name in self.columns:
                unit = self.col_units[name]
                shown = f"{name}_result" if name in inputs else name  # k1 in, k1 out
                header.append(f"{shown} [{unit}]" if unit else shown)
                if name in self.uncertain:
                    header.append(f"u({shown}) [{unit}]" if unit else f"u({shown})")
            self.out.write(_csv_lines([header])[0] + "\n")

    def check_unit(self, name: str, dim) -> None:
        """``--unit NAME=UNIT`` refused, as the one-off refuses it, when the unit cannot show
        the result (the whole run stops: the option is wrong, not a row)."""
        if name in self.units and name not in self.checked_units and dim is not None:
            from ..units import convert

            convert(1.0, dim, self.units[name], label=f"--unit {name}", name=name)
            self.checked_units.add(name)

    # -- one chunk
    def write(self, chunk, outcomes, blocks, upto: int) -> tuple[bool, bool]:
        """Write the first ``upto`` rows of a chunk in order; (a row failed, stopped)."""
        if self.columns is None:
            self.fix_columns(outcomes, blocks, upto)
        n = len(chunk.numbers)
        lines = chunk.numbers
        texts: list = [None] * n
        for block in blocks:
            self._fast_texts(block, chunk, texts)
        messages: list[tuple[int, str]] = []
        failed = stopped = False
        slow = range(upto)
        if not any(isinstance(texts[int(b.rows[0])], _Failure) for b in blocks if len(b.rows)):
            fast_count = sum(len(b.rows) for b in blocks)
            if fast_count == upto == n:
                slow = ()  # every row computed by the vectorised path: nothing to check
            elif fast_count:
                slow = [i for i in range(upto) if outcomes[i] is not _FAST]
        for i in slow:
            kind, item = outcomes[i]
            try:
                if kind == "fast":
                    if isinstance(texts[i], _Failure):
                        raise texts[i]
                elif kind == "ok":
                    texts[i] = self._result_text(lines[i], chunk.row(i), item)
                    if not self.as_json and item.warnings:
                        messages += [(i, f"warning: line {lines[i]}: {w}")
                                     for w in item.warnings]
                elif kind == "error":
                    raise _Failure(item)
            except _Failure as exc:
                texts[i] = None
                messages.append((i, f"Error: line {lines[i]}: {exc}"))
                failed = True
                if self.on_error == "stop":
                    stopped = True
                    upto = i
                    break
        shown = texts[:upto] if upto < n else texts
        if None in shown:
            shown = [t for t in shown if t is not None and not isinstance(t, _Failure)]
        if shown:
            self.out.write("\n".join(shown) + "\n")
        if messages:
            self.out.flush()
            self.err.write("\n".join(one_line(m) for _i, m in sorted(messages,
                                                                      key=lambda p: p[0]))
                           + "\n")
            self.err.flush()
        return failed, stopped

    def _fast_texts(self, block, chunk, texts) -> None:
        """Fill ``texts`` at the block's rows: CSV lines or JSON lines."""
        from ..units import convert

        rows = block.rows.tolist()
        if not self.as_json:
            missing = [name for name in block.values if name not in self.col_units]
            if missing:
                failure = _Failure(self._not_a_column(missing[0]))
                for i in rows:
                    texts[i] = failure
                return
        shown = {}
        for name, array in block.values.items():
            dim, unit = block.kinds[name].dim, block.kinds[name].unit
            if name in self.units:
                self.check_unit(name, dim)
            target = self.units.get(name, unit) if self.as_json else self.col_units[name]
            if target != unit and target != dim.si:
                with np.errstate(over="ignore", under="ignore"):
                    array = np.asarray(convert(array, dim, target, label=f"--unit {name}",
                                               name=name), dtype=float)
            numbers = _reprs(array.tolist())
            if self.as_json and not np.isfinite(array).all():  # JSON has no infinity
                numbers = [t if math.isfinite(v) else "null"
                           for t, v in zip(numbers, array.tolist())]
            shown[name] = (numbers, target)
        whole = len(rows) == len(texts)
        line_numbers = chunk.numbers if whole else [chunk.numbers[i] for i in rows]
        if self.as_json:
            parts = []
            for name, (numbers, unit) in shown.items():
                entry = (json.dumps(name).replace("%", "%%") + ': {"value": %s, "unit": '
                         + json.dumps(unit).replace("%", "%%") + "}")
                parts.append(list(map(entry.__mod__, numbers)))
            template = '{"line": %d, ' + block.head.replace("%", "%%") + \
                ', "inputs": {%s}, "results": {%s}, "warnings": []}'
            made = list(map(template.__mod__, zip(line_numbers, block.inputs,
                                                  map(", ".join, zip(*parts)))))
        else:
            empty = [""] * len(rows)
            cells = []
            for name in self.columns:
                cells.append(shown[name][0] if name in shown else empty)
                if name in self.uncertain:  # no uncertainty on this path: an empty u(NAME)
                    cells.append(empty)
            echo = chunk.echo(None if whole else rows)
            made = list(map(",".join, zip(echo, *cells)))
        if whole:
            texts[:] = made
        else:
            for i, text in zip(rows, made):
                texts[i] = text

    def _not_a_column(self, name: str) -> str:
        return (f"its result {name} is not a column of the output (the columns come from the "
                f"first {CHUNK_ROWS} rows); use --json, whose lines carry every result, or put "
                f"such a row first")

    def _result_text(self, line, cells, result) -> str:
        from ..result import encode

        if self.as_json:
            units = {}
            for name, unit in self.units.items():
                entry = result.results.get(name)
                if entry is not None:
                    self.check_unit(name, entry.dim)
                    units[name] = unit
            data: dict[str, Any] = {"line": line}
            data.update(encode.json_data(result, units, [], False))
            return json.dumps(data, allow_nan=False)
        for name in result.results:
            if name not in self.col_units:
                raise _Failure(self._not_a_column(name))
        row = list(cells)
        for name in self.columns:
            entry = result.results.get(name)
            if entry is None:
                row.append("")
                if name in self.uncertain:
                    row.append("")
                continue
            try:
                row.append(encode.batch_cell(entry, self.col_units[name]))
                if name in self.uncertain:
                    sigma = entry.uncertainty_in(self.col_units[name])
                    row.append("" if sigma is None else encode.full_number(sigma))
            except InputError:
                raise _Failure(f"its {name} cannot be shown in the column's unit "
                               f"{self.col_units[name]} (it is a "
                               f"{entry.dim.name if entry.dim else 'word'}); give such rows a "
                               "file of their own") from None
        return _csv_lines([row])[0]


# --------------------------------------------------------------------------------------------
# The driver


def open_source(source: str):
    """The CSV text stream of ``--batch SOURCE`` (``-``: standard input): UTF-8, with or
    without a byte-order mark, any line ending."""
    if source == "-":
        raw = getattr(sys.stdin, "buffer", sys.stdin)
    else:
        try:
            raw = open(source, "rb")  # noqa: SIM115 (closed by run_batch)
        except OSError as exc:
            raise InputError(f"--batch: cannot read {source!r}: "
                             f"{exc.strerror or exc}") from None
    # bytes that are not UTF-8 are kept as lone surrogates, so that the row holding them is
    # refused with its line number and the other rows go on
    return io.TextIOWrapper(raw, encoding="utf-8-sig", newline="", errors="surrogateescape")


#: Characters that make a chunk need the csv module: quotes, and line breaks that
#: ``str.splitlines`` knows but CSV does not.
_NEEDS_CSV_RE = re.compile('["\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029]')
_NEEDS_CSV_ASCII = ('"', "\x0b", "\x0c", "\x1c", "\x1d", "\x1e")
#: Bytes that were not UTF-8, kept by the ``surrogateescape`` decoding; and ``_TOO_LONG``, the
#: line that stands for a line longer than :data:`MAX_LINE` (a lone surrogate that decoding
#: never produces).
_NOT_UTF8_RE = re.compile("[\udc00\udc80-\udcff]")
_TOO_LONG = "\udc00"
#: Characters a line may hold; a longer one is refused without being held in memory.
MAX_LINE = 100_000


def _bounded_lines(stream, limit: int = MAX_LINE):
    """The lines of ``stream``, each read ``limit + 1`` characters at most: a longer line is
    skipped to its end and yields ``_TOO_LONG`` in its place (so the line numbers hold)."""
    while line := stream.readline(limit + 1):
        if len(line) <= limit or line.endswith(("\n", "\r")):
            yield line
            continue
        while (rest := stream.readline(limit)) and not rest.endswith(("\n", "\r")):
            pass
        yield _TOO_LONG + "\n"


class _Chunk:
    """Consecutive records of the CSV: the line each starts on (``numbers``), and either the
    text lines of a chunk without quotes (``lines``: each is one record, split at commas) or
    the records the csv module read (``rows``)."""

    __slots__ = ("numbers", "lines", "rows", "not_utf8")

    def __init__(self, numbers, *, lines=None, rows=None, suspect: bool = False):
        self.numbers, self.lines, self.rows = numbers, lines, rows
        #: rows refused before reading their cells: index -> why
        self.not_utf8: dict[int, str] = {}
        if suspect:
            records = lines if lines is not None else map(",".join, rows)
            self.not_utf8 = {
                i: (f"the line is longer than {MAX_LINE} characters" if _TOO_LONG in text
                    else "the line is not UTF-8 text")
                for i, text in enumerate(records) if _NOT_UTF8_RE.search(text)}

    def __len__(self) -> int:
        return len(self.numbers)

    def row(self, i: int) -> list[str]:
        return self.lines[i].split(",") if self.rows is None else self.rows[i]

    def widths(self) -> list[int]:
        """The number of cells of each row (in a chunk without quotes, one more than its
        commas)."""
        if self.rows is not None:
            return list(map(len, self.rows))
        return list(map(str.count, self.lines, itertools.repeat(",")))

    def table(self, width: int, keep: list[int] | None):
        """The cells column by column, of all rows (``keep`` None) or of the rows ``keep``;
        they all have ``width`` cells."""
        if self.rows is not None:
            return list(zip(*(self.rows if keep is None else [self.rows[i] for i in keep])))
        lines = self.lines if keep is None else [self.lines[i] for i in keep]
        flat = ",".join(lines).split(",")
        return [flat[j::width] for j in range(width)]

    def echo(self, keep: list[int] | None) -> list[str]:
        """The rows (all, or ``keep``) as CSV lines, as ``csv.writer`` writes them."""
        if self.rows is None:  # no quotes, no line breaks in a cell: the line is its CSV
            return self.lines if keep is None else [self.lines[i] for i in keep]
        return _csv_lines(self.rows if keep is None else [self.rows[i] for i in keep])


class _Reader:
    """The CSV's records a chunk at a time, with the line each starts on (the header is line
    1). A chunk without quotes is split at commas directly (what the csv module does, faster);
    one with quotes goes through the csv module, which reads on past the chunk's lines to
    finish a quoted cell that holds line breaks. A record the csv module cannot read, or an
    I/O error (a failing disk, a broken pipe), ends the reading, with ``fatal`` set to its
    message; the records read before it are still handed out. Lines longer than
    :data:`MAX_LINE` are refused one by one (:func:`_bounded_lines`)."""

    def __init__(self, stream):
        self.stream = _bounded_lines(stream)
        self.last = 0      # lines read so far
        self.fatal: str | None = None
        self.done = False

    def chunk(self, size: int) -> _Chunk | None:
        if self.done:
            return None
        raw: list[str] = []
        try:
            raw.extend(itertools.islice(self.stream, size))  # keeps the lines read before
        except OSError as exc:  # a disk or pipe error: the lines before it are computed
            self._failed(self.last + len(raw) + 1, exc)
        if len(raw) < size:
            self.done = True
        if not raw:
            return None
        text = "".join(raw)
        ascii_only = text.isascii()
        suspect = not ascii_only and _NOT_UTF8_RE.search(text) is not None
        start = self.last + 1
        if not (any(c in text for c in _NEEDS_CSV_ASCII) if ascii_only
                else _NEEDS_CSV_RE.search(text)):
            lines = text.splitlines()
            self.last += len(lines)
            return _Chunk(list(range(start, start + len(lines))), lines=lines, suspect=suspect)
        # strict: a quote left open at the end, or text after a closing quote, is refused
        reader = csv.reader(itertools.chain(raw, self.stream), strict=True)
        rows, numbers = [], []
        try:
            while reader.line_num < len(raw):
                row = next(reader, None)
                if row is None:
                    break
                rows.append(row)
                numbers.append(start)
                start = self.last + reader.line_num + 1
        except csv.Error as exc:
            self.fatal = f"line {self.last + reader.line_num}: cannot read the CSV: {exc}"
            self.done = True
        except OSError as exc:
            self._failed(self.last + reader.line_num + 1, exc)
        if reader.line_num > len(raw) and not self.fatal:
            self.done = False  # a quoted cell ran on past the chunk's lines: more may follow
        self.last += reader.line_num
        return _Chunk(numbers, rows=rows, suspect=suspect) if rows else None

    def _failed(self, line: int, exc: OSError) -> None:
        self.fatal = f"line {line}: reading the file failed: {exc.strerror or exc}"
        self.done = True


def run_batch(spec: RowSpec, source: str, *, as_json: bool = False,
              units: dict[str, str] | None = None, on_error: str = "stop",
              debug: bool = False, out=None, err=None, fast: bool | None = None) -> int:
    """Run ``spec``'s command on every row of the CSV ``source``; the exit status.

    ``units`` is ``--unit`` (result name -> unit); ``on_error`` ``stop`` or ``skip``;
    ``fast=False`` sends every row through the generic path (default: the vectorised path
    where the command has one, unless the environment sets ``DYNCALC_BATCH_GENERIC=1``).
    """
    if on_error not in ON_ERROR:
        raise InputError(f"--on-error must be one of {', '.join(ON_ERROR)}; got {on_error!r}")
    out = sys.stdout if out is None else out
    err = sys.stderr if err is None else err
    if fast is None:
        fast = os.environ.get(GENERIC_ENV, "") in ("", "0")
    stream = open_source(source)
    collecting = gc.isenabled()
    gc.enable()  # the rows stream for long: the collector is on (dyncalc.cli.main pauses it)
    try:
        return _run(spec, stream, as_json, dict(units or {}), on_error, debug, out, err,
                    fast and spec.fast is not None)
    finally:
        if not collecting:
            gc.disable()
        if source != "-":
            stream.close()


def _run(spec, stream, as_json, units, on_error, debug, out, err, fast) -> int:
    reader = _Reader(stream)
    header = None
    while header is None:  # blank lines before the header are skipped
        chunk = reader.chunk(1)
        if chunk is None:
            if reader.fatal:
                raise InputError(reader.fatal)
            return EXIT_OK  # no header: nothing to do, nothing printed
        row = chunk.row(0)
        if chunk.not_utf8:  # a header line that is not UTF-8 or too long
            raise InputError(f"line {chunk.numbers[0]}: {chunk.not_utf8[0]}")
        if "".join(row).strip():
            header = (chunk.numbers[0], row)
    columns = read_header(header[0], header[1], spec)
    writer = _Writer([c.raw for c in columns], as_json, units, on_error, out, err)
    failed = False
    cache: dict = {}
    while (chunk := reader.chunk(CHUNK_ROWS)) is not None:
        row_failed, stopped = _compute(spec, columns, chunk, on_error, debug, fast, writer,
                                       cache)
        failed |= row_failed
        if stopped:
            return EXIT_BAD_INPUT
    if reader.fatal:
        out.flush()
        err.write(f"Error: {one_line(reader.fatal)}\n")
        return EXIT_BAD_INPUT
    return EXIT_BAD_INPUT if failed else EXIT_OK


def _compute(spec, columns, chunk, on_error, debug, fast, writer, cache) -> tuple[bool, bool]:
    """Compute and write one chunk; (a row failed, stopped at a failed row)."""
    n = len(chunk)
    width = len(columns)
    widths = chunk.widths()
    if chunk.rows is None:
        widths = [w + 1 for w in widths] if widths.count(width - 1) != n else [width] * n
    bad = chunk.not_utf8
    blocks = []
    covered = np.zeros(n, dtype=bool)
    if fast:
        shaped = None if widths.count(width) == n and not bad else \
            [i for i in range(n) if widths[i] == width and i not in bad]
        if shaped is None or shaped:
            blocks = spec.fast(spec, columns, chunk.table(width, shaped), writer.as_json,
                               cache)
        for block in blocks:
            if shaped is not None:
                block.rows = np.asarray(shaped, dtype=np.intp)[block.rows]
            covered[block.rows] = True
    outcomes: list = [_FAST] * n if covered.all() else \
        [_FAST if c else None for c in covered.tolist()]
    upto = n
    for i in np.flatnonzero(~covered).tolist():
        row = chunk.row(i)
        if not "".join(row).strip():
            outcomes[i] = _BLANK
            continue
        if i in bad:
            outcomes[i] = ("error", bad[i])
        elif widths[i] != width:
            outcomes[i] = ("error", (f"{widths[i]} cell{'s' if widths[i] != 1 else ''} where "
                                     f"the header has {width} "
                                     f"column{'s' if width != 1 else ''}"))
        else:
            outcomes[i] = _generic(spec, columns, row, debug)
        if outcomes[i][0] == "error" and on_error == "stop":
            upto = i + 1
            break
    return writer.write(chunk, outcomes, blocks, upto)


_FAST = ("fast", None)
_BLANK = ("blank", None)


def _generic(spec, columns, row, debug):
    texts: dict[str, str] = {}
    labels: dict[str, str] = {}
    for col in columns:
        cell = row[col.index].strip()
        if cell:
            texts[col.key] = with_header_unit(cell, col.unit)
            labels[col.key] = col.name
    try:
        return ("ok", propagate(lambda: spec.compute(texts, labels)))
    except InputError as exc:
        return ("error", " ".join(str(exc).split()))
    except Exception as exc:  # a bug: reported for this row, the others go on
        if debug:
            raise
        text = " ".join(str(exc).split())[:200]
        return ("error", (f"internal error ({type(exc).__name__}: {text}); please report "
                          "it, with --debug for the traceback"))
