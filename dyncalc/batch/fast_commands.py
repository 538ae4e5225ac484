"""The vectorised path of the commands other than ``natural-frequency``: whole chunks of rows
through the command's column adapter (``Command.columns``: SI arrays in, a
:class:`~dyncalc.physics.columns.Columns` out).

The first row of each block is also computed by the one-off (a *probe*): it gives the order
and the text of the inputs the JSON lines show (defaults such as ``g`` included) and the
dimensions of the results, and the block is left to the generic path unless the probe's
results, model and method are the adapter's own, bit for bit.
"""
from __future__ import annotations

import itertools
import json
import re
from typing import Any

import numpy as np

from ..errors import InputError
from .cells import Table
from .columns import (_LEADING_ZERO_RE, _LITERAL_CELL, _converted_to, _plain_floats,
                      _read_column, _unit_info)
from .fast import FastBlock, _by_columns_given, _input_texts, json_head
from .floats import json_floats, parse_floats
from .header import Column, with_header_unit

#: A vector cell the vectorised path reads: three plain numbers, comma-separated, no unit.
_VECTOR_RE = re.compile(rf"[ \t]*({_LITERAL_CELL})[ \t]*,[ \t]*({_LITERAL_CELL})[ \t]*,"
                        rf"[ \t]*({_LITERAL_CELL})[ \t]*")


#: The characters of a column of such cells, joined by commas.
_VECTOR_CHARS_RE = re.compile(r"[0-9.eE+\- \t,]*")
#: A column of cells of three numbers each (the characters of numbers, two commas a cell),
#: joined by line breaks.
_NUMBER_CHARS = r"[0-9.eE+\- \t]*+"
_VECTOR_COLUMN_RE = re.compile(rf"(?:{_NUMBER_CHARS},{_NUMBER_CHARS},{_NUMBER_CHARS}\n)*+"
                               rf"{_NUMBER_CHARS},{_NUMBER_CHARS},{_NUMBER_CHARS}")


def _vectors(column: list[str]) -> tuple[np.ndarray, np.ndarray]:
    """``(values (n, 3), ok)`` of a column of vector cells: a column whose every cell is three
    plain numbers (two commas a cell, the characters of numbers, no leading zero, every
    component one ``float`` reads: what :data:`_VECTOR_RE` matches) is read at once (its
    components as JSON numbers, or by one :func:`parse_floats`); any other is read a cell at a
    time (``ok`` False where a cell is not one)."""
    n = len(column)
    lined = "\n".join(column)
    if n and _VECTOR_COLUMN_RE.fullmatch(lined):
        # JSON refuses a leading zero: what orjson reads needs no search for one
        flat = json_floats(lined.replace("\n", ","), 3 * n)
        if flat is not None:
            return flat.reshape(n, 3), np.ones(n, dtype=bool)
    joined = ",".join(column)
    if (n and _VECTOR_CHARS_RE.fullmatch(joined) and not _LEADING_ZERO_RE.search(joined)
            and list(map(str.count, column, itertools.repeat(","))).count(2) == n):
        try:
            flat = parse_floats(joined.split(","))
        except ValueError:
            flat = None
        if flat is not None and flat.shape == (3 * n,):
            return flat.reshape(n, 3), np.ones(n, dtype=bool)
    typed = np.zeros((n, 3))
    ok = np.zeros(n, dtype=bool)
    for i, cell in enumerate(column):
        m = _VECTOR_RE.fullmatch(cell)
        if m is not None:
            typed[i] = [float(x) for x in m.groups()]
            ok[i] = True
    return typed, ok


class _Param:
    """What :func:`~dyncalc.batch.columns._read_column` needs of a parameter: its dimension
    (the command checks signs and ranges itself: its adapter marks such rows not exact)."""

    __slots__ = ("name", "dim", "constraint")

    def __init__(self, name: str, dim):
        self.name, self.dim, self.constraint = name, dim, None


def _command_fast(spec, columns: list[Column], table, want_json: bool,
                  cache: dict) -> list[FastBlock]:
    """The rows of this chunk the command's adapter computes, as blocks (one per set of
    columns given); every other row is left to the generic path."""
    if not table or len(columns) > 62:
        return []
    n = table.n if isinstance(table, Table) else len(table[0])
    # every cell a plain number: the values at once, the texts made only if needed (JSON)
    numbers = table.numbers() if isinstance(table, Table) else None
    plain: dict[str, np.ndarray] = {}
    if numbers is not None:
        cells = {col.key: _stripped(table[col.index]) if want_json
                 else table.later(col.index, _stripped, str.strip) for col in columns}
        plain = {col.key: np.ascontiguousarray(numbers[:, col.index]) for col in columns}
        present = [np.ones(n, dtype=bool) for _col in columns]
    else:
        cells = {col.key: _stripped(table[col.index]) for col in columns}
        present = [np.ones(n, dtype=bool) if "" not in cells[col.key]
                   else np.fromiter((c != "" for c in cells[col.key]), dtype=bool, count=n)
                   for col in columns]
    blocks = []
    for given, rows in _by_columns_given(columns, present):
        if not given:
            continue
        for subset in _by_words(spec, given, rows, cells):
            blocks += _blocks(spec, given, subset, cells, want_json, cache,
                              plain if len(subset) == n else {})
    return blocks


def _stripped(column) -> list[str]:
    """The cells without their surrounding white space (a column with none kept as it is)."""
    joined = "".join(column)
    if (any(map(joined.__contains__, _ASCII_SPACES)) if joined.isascii()
            else _SPACE_RE.search(joined)):  # what str.strip strips (str.isspace)
        return [c.strip() for c in column]
    return list(column)


_SPACE_RE = re.compile(r"\s")
#: The ASCII characters ``str.isspace`` knows (a search for each is faster than the regex).
_ASCII_SPACES = tuple(c for c in map(chr, range(128)) if c.isspace())


#: The most distinct word combinations (``body``, ``cycles``) a block is split into; beyond,
#: its rows take the generic path.
MAX_WORD_GROUPS = 32


def _is_word(param) -> bool:
    return param is not None and (param.kind == "choice"
                                  or (param.kind == "text" and param.dim is None))


def _by_words(spec, given: list[Column], rows: np.ndarray, cells):
    """The rows split by the texts of their word columns (the one-off reads a word its own
    way, ``cycles`` 4 as 4.0: each group's probe shows how, for every row of the group)."""
    keys = [col.key for col in given if _is_word(spec.parameter(col.key))]
    if not keys:
        yield rows
        return
    groups: dict[tuple, list[int]] = {}
    for i in rows.tolist():
        groups.setdefault(tuple(cells[key][i] for key in keys), []).append(i)
    if len(groups) <= MAX_WORD_GROUPS:
        for members in groups.values():
            yield np.asarray(members, dtype=np.intp)


def _read(spec, col: Column, column: list[str], cache: dict, plain=None):
    """``(ok, SI values, shown values, unit JSON, kind)`` of one column of a block, or
    ``None`` where the column cannot be read here (the generic path reads it). For a number
    column the fourth item is whether every cell is a plain number instead."""
    param = spec.parameter(col.key)
    if param is None:
        return None
    # a vector is read for a parameter whose record says it takes one (metavar VEC); any
    # other cell with a comma is not a plain number, so _read_column leaves it alone
    if _is_word(param):
        if col.unit:
            return None
        words = np.array(column, dtype=object)
        if param.kind == "choice":  # (free text is the adapter's to check, as the one-off's)
            ok = np.fromiter((w in param.choices for w in column), dtype=bool,
                             count=len(column))
        else:
            ok = np.ones(len(column), dtype=bool)
        return ok, words, None, None, "word"
    if param.dim is None:
        return None
    if param.metavar == "MATRIX":  # a 3x3 matrix a cell (rigid-body's inertia_tensor)
        from .fast_matrices import read_matrices

        return read_matrices(column, col.unit, param.dim, spec.strict)
    if param.kind == "quantity" and (plain is not None or param.metavar != "VEC"
                                     or not any("," in cell for cell in column)):
        plain = _plain_floats(column) if plain is None else plain
        read = _read_column(column, col.unit, _Param(param.name, param.dim), spec.strict,
                            cache, plain)
        # (for a number, the fourth item says every cell is a plain number: its JSON input
        # text is the cell and the header's unit, assembled a column at a time)
        return read.ok, read.si, read, plain is not None, "number"
    info = _unit_info(col.unit, param.dim, spec.strict, cache)
    if info is None:
        return None
    typed, ok = _vectors(column)
    from ..units import registry

    with np.errstate(over="ignore", under="ignore", invalid="ignore"):
        si = np.asarray(registry().Quantity(typed, info.units).to(info.target).magnitude,
                        dtype=float)
    ok &= np.isfinite(typed).all(axis=1) & np.isfinite(si).all(axis=1)
    # a vector's input entry shows its SI value converted back to the unit typed
    shown = _converted_to(si, param.dim, json.loads(info.unit_json[0])) if info.typed else si
    shown = shown + 0.0  # the one-off shows a component typed -0 as 0.0 (its entries add 0.0)
    return ok, si, shown, info, "vector"


def _blocks(spec, given: list[Column], rows: np.ndarray, cells, want_json: bool,
            cache: dict, plain: dict | None = None) -> list[FastBlock]:
    """The blocks of these rows: one, or one per combination of the units their number
    cells were typed in (an adapter may compute in the unit typed; it is told one per
    column). ``plain``: the values of columns of plain numbers, where ``rows`` are all."""
    read = _read_rows(spec, given, rows, cells, cache, plain)
    if read is None:
        return []
    reads, _arrays, good = read
    typed = [r[2].unit_json for r, _column in reads.values() if r[4] == "number"]
    groups: dict[tuple, list[int]] = {}
    if all(units.count(units[0]) == len(units) for units in typed if units):
        pass  # every column in one unit (checked at C speed): one group, no row loop
    else:
        for i in np.flatnonzero(good).tolist():
            groups.setdefault(tuple(units[i] for units in typed), []).append(int(rows[i]))
        if len(groups) > MAX_WORD_GROUPS:
            return []
    if len(groups) <= 1:  # the common case: the columns as read serve the block
        return _as_list(_block(spec, given, rows, cells, want_json, read))
    found = []
    for members in groups.values():
        subset = np.asarray(members, dtype=np.intp)
        read = _read_rows(spec, given, subset, cells, cache)
        if read is not None:
            found += _as_list(_block(spec, given, subset, cells, want_json, read))
    return found


def _as_list(block) -> list[FastBlock]:
    """:func:`_block`'s answer (none, one block, or a list of them) as a list."""
    if block is None:
        return []
    return block if isinstance(block, list) else [block]


def _read_rows(spec, given: list[Column], rows: np.ndarray, cells, cache: dict,
               plain: dict | None = None):
    """``(reads by key: (read, cells), SI arrays by key, good rows)`` of these rows' columns,
    or ``None`` where a column cannot be read here. ``plain``: the values of columns of
    plain numbers, where ``rows`` are all."""
    good = np.ones(len(rows), dtype=bool)
    arrays: dict[str, Any] = {}
    reads = {}
    row_list = rows.tolist()
    plain = plain or {}
    for col in given:
        whole = col.key in plain or (len(rows) == len(cells[col.key])
                                     and (not len(rows) or row_list[-1] == len(rows) - 1))
        column = cells[col.key] if whole else [cells[col.key][i] for i in row_list]
        read = _read(spec, col, column, cache, plain.get(col.key))
        if read is None:
            return None
        good &= read[0]
        arrays[col.key] = read[1]
        reads[col.key] = (read, column)
    return reads, arrays, good


def _block(spec, given: list[Column], rows: np.ndarray, cells, want_json: bool,
           read) -> FastBlock | None:
    """One block: the adapter on the columns as read (:func:`_read_rows`), its exact rows
    kept where the probe agrees."""
    reads, arrays, good = read
    if not good.any():
        return None
    settings = {**spec.settings, "units": _typed_units(reads, good), "json": want_json,
                "typed": {key: read[2].shown for key, (read, _column) in reads.items()
                          if read[4] == "number"},
                "cells": {key: column for key, (_read, column) in reads.items()}}
    try:
        with np.errstate(all="ignore"):
            out = spec.adapter(arrays, settings)
    except (ArithmeticError, ValueError, TypeError, IndexError, KeyError):
        out = None  # an adapter that cannot take these columns: the generic path answers
    if out is None:
        return None
    good = good & np.asarray(out.exact, dtype=bool)
    if not good.any():
        return None
    if getattr(out, "optional", False):
        return _split_by_results(spec, given, rows, cells, want_json, reads, good, out)
    if getattr(out, "groups", None) is not None:  # results of other dimensions: apart
        codes = np.asarray(out.groups)
        return [block for code in np.unique(codes[good]).tolist()
                if (block := _finish(spec, given, rows, cells, want_json, reads,
                                     good & (codes == code), out, code)) is not None]
    return _finish(spec, given, rows, cells, want_json, reads, good, out)


def _split_by_results(spec, given, rows, cells, want_json, reads, good, out):
    """The blocks of an adapter whose rows have different results (``Columns.optional``:
    NaN where a row has no such result), one per set of results, each with its own probe."""
    from ..physics.columns import Columns

    names = list(out.values)
    present = np.stack([np.isfinite(out.values[name]) for name in names]) if names else None
    if present is None:
        return None
    blocks = []
    for pattern, members in _patterns(present, np.flatnonzero(good)):
        mask = np.zeros(len(rows), dtype=bool)
        mask[members] = True
        part = Columns({name: out.values[name] for name, has in zip(names, pattern) if has},
                       exact=mask, model=out.model, method=out.method,
                       error_estimate=out.error_estimate, warnings=out.warnings,
                       warned=out.warned, extras=out.extras, row_warnings=out.row_warnings)
        block = _finish(spec, given, rows, cells, want_json, reads, mask, part)
        if block is not None:
            blocks.append(block)
    return blocks


def _patterns(present, index):
    """``(pattern, rows)`` of the rows ``index``, grouped by their column of ``present`` (which
    results each has), in the order each pattern first appears, the rows ascending: the
    patterns coded as integers and grouped by one ``np.unique`` (no loop over rows)."""
    if len(present) > 62:
        groups: dict[tuple, list[int]] = {}
        for i in index.tolist():
            groups.setdefault(tuple(present[:, i].tolist()), []).append(i)
        return list(groups.items())
    weights = np.left_shift(np.int64(1), np.arange(len(present), dtype=np.int64))
    codes = weights @ present[:, index].astype(np.int64)
    unique, first, inverse = np.unique(codes, return_index=True, return_inverse=True)
    out = []
    for u in np.argsort(first, kind="stable").tolist():
        members = index[inverse.ravel() == u]
        out.append((tuple(present[:, members[0]].tolist()), members.tolist()))
    return out


def _finish(spec, given, rows, cells, want_json, reads, good, out,
            group=None) -> FastBlock | None:
    """The block of the ``good`` rows of ``out``, where the probe agrees (the rows that warn,
    ``out.warned``, or those that do not, whichever the first good row is); ``group``: the
    rows' code of ``out.groups`` (each code probed on its own)."""
    warnings = ()
    per_row = getattr(out, "row_warnings", None)
    if per_row is None and out.warned is not None and out.warned[good].any():
        first = bool(out.warned[int(np.argmax(good))])
        good = good & (out.warned if first else ~out.warned)
        warnings = out.warnings if first else ()
    first = int(np.argmax(good))
    if per_row is not None:  # the probe checks the first row's own texts
        warnings = tuple((per_row(np.array([first])) or [()])[0])
    first_extra = None if out.extras is None else _joined(out.extras(np.array([first])))
    # a spec with ``probed`` (a dict) probes each kind of block once a run (eom: a probe is
    # a whole one-off, with its explanation; springs: one per chunk was a quarter of a run);
    # the others probe every block. A kind: the columns, the units typed, the results.
    probed = getattr(spec, "probed", None)
    # (texts a row: the kind of block is whether its first row warns and how often; the
    # texts come from the one-off's own formatting, its results say which warning it is)
    said = warnings if per_row is None else ("per row", len(warnings))
    key = (tuple(col.key for col in given), out.model, out.method, first_extra, said,
           tuple(out.values), tuple(_unit_at(reads[col.key][0], first) for col in given),
           group)
    probe = probed.get(key) if probed is not None else None
    light = getattr(spec, "light_probe", None)  # eom: the generated table stands in for it
    if probe is None and light is not None and all(reads[col.key][0][4] == "number"
                                                   for col in given):
        probe = light(spec, set(spec.input_names([col.key for col in given]).values()), out)
    if probe is None:
        probe = _probe(spec, given, cells, int(rows[first]), out,
                       {name: array[first] for name, array in out.values.items()}, warnings,
                       first_extra)
        if probe is None:
            return None
        if probed is not None:
            probed[key] = probe
    keep = np.flatnonzero(good)
    values = {name: array[keep] for name, array in out.values.items()}
    dims = {name: entry.dim for name, entry in probe.results.items()}
    head = texts = None
    if want_json:
        head = json_head(spec.command, probe.scene, out.model, out.method)
        texts = _input_texts(_inputs(spec, given, reads, probe), keep, {})
    extra = "{}" if out.error_estimate is None else json.dumps(
        {"error_estimate": out.error_estimate})
    if out.extras is not None:
        extra = out.extras(keep) if want_json else "{}"
    each = per_row(keep) if per_row is not None else None
    if each is not None:
        return FastBlock(rows[keep], values, dims, head, texts, extra,
                         row_warnings=[tuple(w) for w in each])
    return FastBlock(rows[keep], values, dims, head, texts, extra, warnings)


def _unit_at(read, row: int):
    """The unit (JSON) a number or vector column of a block was typed in at ``row``."""
    _ok, _si, shown, info, kind = read
    if kind == "number":
        return shown.unit_json[row] if shown.unit_json else None
    return info.unit_json if kind == "vector" else None


def _joined(parts: list) -> str:
    """The one line of :func:`~dyncalc.batch.assemble.lines` parts made for one row."""
    return "".join(part if isinstance(part, str) else part[0] for part in parts)


def _typed_units(reads: dict, good: np.ndarray) -> dict[str, str]:
    """The unit each number or vector column of a block was typed in (``""``: bare numbers,
    read as SI), for the adapters whose one-off computes in the unit typed (a spring network
    adds in its first element's unit); a column whose good cells mix units is left out (the
    adapter then leaves the block to the generic path)."""
    units = {}
    for key, ((_ok, _si, shown, info, kind), _column) in reads.items():
        if kind == "number":
            typed = shown.unit_json
            pairs = {typed[0]} if typed and typed.count(typed[0]) == len(typed) else {
                typed[i] for i in np.flatnonzero(good).tolist()}
        elif kind == "vector":
            pairs = {info.unit_json}
        else:
            continue
        if len(pairs) == 1:
            unit, assumed = pairs.pop()
            units[key] = "" if assumed else json.loads(unit)
    return units


def _probe(spec, given, cells, row: int, out, values: dict, warnings: tuple = (),
           extra: str | None = None):
    """The one-off Result of ``row``, or ``None`` where it is not the adapter's to the bit,
    warnings and the JSON text of a row's own ``extra`` (``out.extras``) included (then the
    whole block takes the generic path)."""
    texts = {col.key: with_header_unit(cells[col.key][row], col.unit) for col in given}
    try:
        result = spec.compute(texts, {col.key: col.name for col in given})
    except InputError:
        return None
    if (tuple(result.warnings) != warnings or result.model != out.model or result.method != out.method
            or list(result.results) != list(values)
            or result.extra.get("error_estimate") != out.error_estimate
            or (set(result.extra) - {"error_estimate"} if extra is None
                else json.dumps(result.extra) != extra)):
        return None
    rtol = getattr(spec, "probe_rtol", None)  # modes: within the documented tolerance
    for name, entry in result.results.items():
        mine = values[name]
        if entry.uncertainty is not None or not (
                _same(entry.si, mine) if rtol is None else _close(entry.si, mine, rtol)):
            return None
    return result


def _close(theirs, mine, rtol: float) -> bool:
    """Equal within ``rtol`` relative (a number or a vector, of the same shape)."""
    a = np.asarray(theirs, dtype=float)
    b = np.asarray(mine, dtype=float)
    return a.shape == b.shape and bool(np.allclose(a, b, rtol=rtol, atol=0.0))


def _same(theirs, mine) -> bool:
    """Equal to the bit (a word, a number or a vector)."""
    if isinstance(theirs, str) or isinstance(mine, str):
        return theirs == mine
    a = np.asarray(theirs, dtype=float)
    b = np.asarray(mine, dtype=float)
    if a.size == b.size == 1:  # a 1 x 1 matrix: one number in a CSV cell
        a, b = a.reshape(1), b.reshape(1)
    return a.shape == b.shape and bool((a.view(np.int64) == b.view(np.int64)).all())


def _inputs(spec, given, reads, probe) -> list[tuple]:
    """The inputs of the JSON lines in the one-off's order: a column given (templated per row)
    or an input the one-off adds (a default such as ``g``: the same text on every row)."""
    from ..result.encode import _json_inputs

    by_name = spec.input_names([col.key for col in given])
    columns = {by_name[col.key]: col for col in given}
    items = []
    for name, entry in probe.inputs.items():
        col = columns.get(name)
        if col is None:
            items.append((name, json.dumps(_json_inputs({name: entry}))[1:-1], None, None,
                          False, None))
            continue
        (ok, _si, shown, info, kind), column = reads[col.key]
        if kind == "number":
            items.append((name, shown, column, col.unit, info, None))
        elif kind == "matrix":  # (dyncalc.batch.fast_matrices.Matrices)
            items.append((name, shown, None, None, False, None))
        elif kind == "word":  # the same word on every row of the block: the probe's entry
            items.append((name, json.dumps(_json_inputs({name: entry}))[1:-1], None, None,
                          False, None))
        else:
            items.append((name, _Vectors(shown, info, column, col.unit), None, None, False,
                          None))
    return items


class _Vectors:
    """A column of vectors as JSON input entries, each shown in the unit typed."""

    def __init__(self, shown, info, column, header_unit):
        self.shown, self.info, self.column, self.header_unit = shown, info, column, header_unit

    def parts(self, name: str, keep) -> list:
        """The parts (:func:`dyncalc.batch.assemble.lines`) of the kept rows' entries."""
        key = json.dumps(name)
        unit, assumed = self.info.unit_json
        rows = keep.tolist()
        shown = np.asarray(self.shown, dtype=np.float64)[keep]
        cells = list(self.column) if len(rows) == len(self.column) else [
            self.column[i] for i in rows]  # (keep: sorted rows, all of them or fewer)
        if np.isfinite(shown).all() and "\t" not in "".join(cells):
            suffix = json.dumps(" " + self.header_unit)[1:-1] if self.header_unit else ""
            text = ['"', cells, suffix + '"']  # with_header_unit: "cell unit", nothing to escape
        else:
            text = [[json.dumps(with_header_unit(c, self.header_unit)) for c in cells]]
            shown = None
        if shown is None:
            values = [json.dumps(self.shown[i].tolist()) for i in rows]
            return [f"{key}: {{\"value\": ", values, f', "unit": {unit}, "text": ', *text,
                    assumed + "}"]
        return [f"{key}: {{\"value\": [", shown[:, 0], ", ", shown[:, 1], ", ", shown[:, 2],
                f'], "unit": {unit}, "text": ', *text, assumed + "}"]
