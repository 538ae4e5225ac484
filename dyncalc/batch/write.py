"""Writing each chunk's outcomes in order: CSV rows (the result columns) or JSON lines."""
from __future__ import annotations

import json
import math
import re
from typing import Any

import numpy as np

from ..errors import InputError, one_line
from .csvlines import _csv_lines
from . import assemble
from .floats import reprs
from .header import _HEADER_RE

#: What makes csv.writer quote a cell (its delimiter, quote character or a line break).
_QUOTED = re.compile(r'[,"\r\n]')
#: What ``json.dumps`` escapes in a text (quotes, backslashes, controls, beyond ASCII).
_ESCAPED = re.compile(r'["\\\x00-\x1f\x7f-\U0010ffff]')

#: The outcome of a row the vectorised path computed, and of a blank row.
_FAST = ("fast", None)
_BLANK = ("blank", None)


class _Failure(Exception):
    """A row that cannot be written (its message, without the line number)."""


class _Writer:
    """Turns each chunk's outcomes into text, in order: CSV (the input columns, then a column
    per result) or JSON lines. The result columns are fixed by the first chunk's rows (a chunk
    is ``chunk_rows`` rows). Results are given in their canonical unit (docs/json.md,
    "Canonical units": ``omega [rad/s]`` whatever units the inputs were typed in), unless
    ``--unit`` (``units``) names another."""

    def __init__(self, header: list[str], as_json: bool, units: dict[str, str], on_error: str,
                 out, err, chunk_rows: int):
        self.header, self.as_json, self.units, self.on_error = header, as_json, units, on_error
        self.out, self.err, self.chunk_rows = out, err, chunk_rows
        self.columns: list[str] | None = None  # result names, in order of first appearance
        self.col_units: dict[str, str] = {}
        self.checked_units: set[str] = set()
        self.uncertain: set[str] = set()  # results given a u(NAME) column after their own

    # -- the result columns, from the first chunk's rows
    def fix_columns(self, outcomes, blocks, upto: int) -> None:
        names: dict[str, Any] = {}
        first: list[tuple[int, list]] = []
        for block in blocks:  # (a block's dims: the canonical unit is the SI unit)
            position = int(block.rows[0])
            if position < upto:
                first.append((position, [(name, dim.si if dim is not None else "", dim)
                                         for name, dim in block.dims.items()]))
        for i in range(upto):
            kind, item = outcomes[i]
            if kind == "ok":
                first.append((i, [(name, e.canonical_unit, e.dim)
                                  for name, e in item.results.items()]))
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
        if name in self.units and name not in self.checked_units and dim is not None \
                and getattr(dim, "entry_units", None) is None:
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
        if len(blocks) == 1 and upto == n and len(blocks[0].rows) == n:
            parts = self._fast_parts(blocks[0], chunk, True)  # the common case: one block
            if not isinstance(parts, _Failure):
                assemble.write_lines(self.out, parts, n)
                self._block_warnings(blocks, lines)
                return False, False
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
                        messages += [(i, f"warning: line {lines[i]}{_tail(w)}")
                                     for w in item.warnings]
                elif kind == "error":
                    raise _Failure(item)
            except _Failure as exc:
                texts[i] = None
                messages.append((i, one_line(f"Error: line {lines[i]}: {exc}")))
                failed = True
                if self.on_error == "stop":
                    stopped = True
                    upto = i
                    break
        shown = texts[:upto] if upto < n else texts
        if None in shown:
            shown = [t for t in shown if t is not None and not isinstance(t, _Failure)]
        if shown:
            shown.append("")  # the last line's break, without copying the chunk's text again
            self.out.write("\n".join(shown))
        if not self.as_json:  # the warnings of the vectorised rows written
            for block in blocks:
                tails: dict = {}  # (a block's rows share few texts: each made once)
                messages += [(i, f"warning: line {lines[i]}"
                                  f"{tails.get(w) or tails.setdefault(w, _tail(w))}")
                             for i, w in block.warned_rows()
                             if i < upto and texts[i] is not None
                             and not isinstance(texts[i], _Failure)]
        if messages:  # each message already one line (errors.one_line)
            self.out.flush()
            self.err.write("\n".join(m for _i, m in sorted(messages, key=_first)) + "\n")
            self.err.flush()
        return failed, stopped

    def _block_warnings(self, blocks, lines) -> None:
        """The CSV run's ``warning:`` lines of vectorised blocks (the same texts each row, or
        each row's own: ``row_warnings``), in row order."""
        if self.as_json or not any(block.warns() for block in blocks):
            return
        if len(blocks) == 1 and len(blocks[0].rows) == len(lines) and \
                blocks[0].row_warnings is None:
            # one block over the whole chunk: every row has the same warnings, so each is made
            # one line once and the line numbers are joined around it in one call (one_line of
            # the whole message a row was half of a 10^6-row undamped forced-response run)
            text = _same_warnings(lines, sorted(blocks[0].warnings))
        else:
            rows = sorted((pair for block in blocks for pair in block.warned_rows()),
                          key=_first)  # (stable: a row's warnings in the one-off's order)
            text = "\n".join(one_line(f"warning: line {lines[i]}: {w}") for i, w in rows)
        self.out.flush()
        self.err.write(text)  # then the break apart: the chunk's warnings are not copied again
        self.err.write("\n")
        self.err.flush()

    def _fast_texts(self, block, chunk, texts) -> None:
        """Fill ``texts`` at the block's rows: CSV lines or JSON lines."""
        rows = block.rows.tolist()
        whole = len(rows) == len(texts)
        parts = self._fast_parts(block, chunk, whole)
        if isinstance(parts, _Failure):
            for i in rows:
                texts[i] = parts
            return
        made = assemble.lines(parts, len(rows))
        if whole:
            texts[:] = made
        else:
            for i, text in zip(rows, made):
                texts[i] = text

    def _fast_parts(self, block, chunk, whole: bool):
        """The parts (:func:`dyncalc.batch.assemble.lines`) of the block's lines, or the
        :class:`_Failure` of every row of it."""
        from ..units import convert

        rows = block.rows.tolist()
        if not self.as_json:
            missing = [name for name in block.values if name not in self.col_units]
            if missing:
                return _Failure(self._not_a_column(missing[0]))
        shown = {}
        for name, array in block.values.items():
            dim = block.dims[name]
            if dim is None:  # words (a regime): the same text as the one-off's
                words = array.tolist()
                unique = list(set(words))  # (one writer for all: a text a row is common)
                # no text to quote or escape: one search, not one a word
                if self.as_json and not _ESCAPED.search("".join(unique)):
                    shown[name] = (['"', words, '"'], "")
                    continue
                if not self.as_json and all(unique) and not _QUOTED.search("\0".join(unique)):
                    shown[name] = ([words], "")
                    continue
                if self.as_json:
                    text = dict(zip(unique, map(json.dumps, unique)))
                else:  # csv.writer leaves a text without , " or a line break as it is
                    odd = [w for w in unique if not w or _QUOTED.search(w)]
                    text = dict(zip(unique, unique))
                    text.update(zip(odd, _csv_lines([[w] for w in odd])))
                shown[name] = ([list(map(text.__getitem__, words))], "")
                continue
            mixed = getattr(dim, "entry_units", None)  # a matrix, a unit on each entry
            if mixed is not None:
                shown[name] = (_mixed_parts(array, mixed) if not self.as_json and name not in
                               self.units else _number_parts(array, self.as_json),
                               self.units.get(name, ""))
                continue
            if name in self.units:
                self.check_unit(name, dim)
            target = self.units.get(name, dim.si) if self.as_json else self.col_units[name]
            if target != dim.si:  # the arrays are SI
                try:
                    with np.errstate(over="ignore", under="ignore"):
                        array = np.asarray(convert(array, dim, target, label=f"--unit {name}",
                                                   name=name), dtype=float)
                except InputError:
                    if self.as_json:
                        raise
                    # (a modal mass in kg under a kg*m^2 column: the one-off's row message)
                    return _Failure(self._not_shown(name, target, dim))
            shown[name] = (_number_parts(array, self.as_json), target)
        if self.as_json:
            parts: list = []
            for name, (numbers, unit) in shown.items():
                parts += [", " if parts else "", json.dumps(name) + ': {"value": ', *numbers,
                          ', "unit": ' + json.dumps(unit) + "}"]
            numbers = chunk.numbers if whole else [chunk.numbers[i] for i in rows]
            return ['{"line": ', np.asarray(numbers, dtype=np.int64),
                    ", " + block.head + ', "inputs": {', *block.inputs, '}, "results": {',
                    *parts, *_warning_parts(block), *_extra_parts(block.extra), "}"]
        parts = [chunk.echo(None if whole else rows)]
        for name in self.columns:
            parts += [","] if name not in shown else [",", *shown[name][0]]
            if name in self.uncertain:  # no uncertainty on this path: an empty u(NAME)
                parts.append(",")
        return parts

    @staticmethod
    def _not_shown(name: str, unit: str, dim) -> str:
        return (f"its {name} cannot be shown in the column's unit {unit} (it is a "
                f"{dim.name if dim else 'word'}); give such rows a file of their own")

    def _not_a_column(self, name: str) -> str:
        return (f"its result {name} is not a column of the output (the columns come from the "
                f"first {self.chunk_rows} rows); use --json, whose lines carry every result, or "
                f"put such a row first")

    def _result_text(self, line, cells, result) -> str:
        from ..result import encode

        if self.as_json:
            for name in self.units:
                entry = result.results.get(name)
                if entry is not None:
                    self.check_unit(name, entry.dim)
            # every result named, so that none is shown in the units its inputs were typed in
            units = {name: self.units.get(name, entry.canonical_unit)
                     for name, entry in result.results.items()}
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
                raise _Failure(self._not_shown(name, self.col_units[name], entry.dim)) from None
        return _csv_lines([row])[0]


def _warning_parts(block) -> list:
    """A block's JSON ``warnings`` member and the start of ``extra``: one text every line
    shares, or each row's list (``row_warnings``), made once a distinct list."""
    if block.row_warnings is None:
        return ['}, "warnings": ' + json.dumps(list(block.warnings)) + ', "extra": ']
    made: dict = {}
    texts = [made.get(w) or made.setdefault(w, json.dumps(list(w)))
             for w in block.row_warnings]
    return ['}, "warnings": ', texts, ', "extra": ']


def _extra_parts(extra) -> list:
    """A block's ``extra``: one text every line shares, or parts (texts and a list of one text
    a row: :attr:`dyncalc.physics.columns.Columns.extras`)."""
    return [extra] if isinstance(extra, str) else list(extra)


def _number_parts(array, as_json: bool) -> list:
    """The parts of a result column: floats (``null`` in JSON where not finite, as
    ``json.dumps`` refuses them), or vectors (a JSON list, or quoted components comma
    separated)."""
    if array.ndim == 1:
        if as_json and not np.isfinite(array).all():
            return [[t if math.isfinite(v) else "null" for t, v in zip(reprs(array),
                                                                         array.tolist())]]
        return [array]
    if as_json and not np.isfinite(array).all():
        return [[json.dumps(v) for v in array.tolist()]]
    if array.ndim == 3:  # matrices: rows of components ("a,b;c,d" in CSV, as --value)
        if as_json:
            rows = [_number_parts(array[:, i, :], True) for i in range(array.shape[1])]
            return ["[", *[p for i, row in enumerate(rows) for p in ([", "] if i else []) + row],
                    "]"]
        parts = ['"']
        for i in range(array.shape[1]):
            parts += [";"] if i else []
            for j in range(array.shape[2]):
                parts += [","] if j else []
                parts.append(_component(array[:, i, j]))
        return parts + ['"']
    width = array.shape[1]
    opening, between, closing = ("[", ", ", "]") if as_json else ('"', ",", '"')
    if not width:
        return ["[]" if as_json else '""']
    parts: list = [opening]
    for j in range(width):
        parts += [between] if j else []
        parts.append(_component(array[:, j]))
    return parts + [closing]


def _mixed_parts(array, units) -> list:
    """The CSV parts of ``(n, r, c)`` matrices whose entries have units of their own, as
    :func:`dyncalc.result.entries.matrix_with_units` writes one: ``"[[3.0 kg, 0.5 kg*m],
    ...]"``."""
    parts: list = ['"[']
    for i, row in enumerate(units):
        parts.append(", [" if i else "[")
        for j, unit in enumerate(row):
            parts += [", "] if j else []
            parts += [_component(array[:, i, j]), f" {unit}".rstrip()]
        parts.append("]")
    return parts + [']"']


def _component(column):
    """A component column of vectors or matrices: one text when every row holds the same
    float, bit for bit (the zeros off a diagonal, an axis), else the column."""
    column = np.ascontiguousarray(column, dtype=np.float64)
    bits = column.view(np.int64)
    if len(bits) and (bits == bits[0]).all():
        return repr(float(column[0]))
    return column


def _same_warnings(lines, warnings: list[str]) -> str:
    """The ``warning:`` lines of rows that all carry ``warnings`` (already in order), without
    the trailing line break: ``one_line`` of each whole message, made once a warning.

    ``one_line("warning: line 7: " + w)`` is ``"warning: line 7: " + one_line(w)`` (a line
    number holds no blank or character to escape), or ``"warning: line 7:"`` when ``w`` is
    blank."""
    tails = list(map(_tail, warnings))
    numbers = list(map(str, lines))
    if len(tails) == 1:
        tail = tails[0]
        return "warning: line " + (tail + "\nwarning: line ").join(numbers) + tail
    return "\n".join(f"warning: line {number}{tail}" for number in numbers for tail in tails)


def _tail(warning: str) -> str:
    """What follows ``warning: line N`` for ``warning``, so that the whole message is
    ``one_line`` of ``f"warning: line {N}: {warning}"``: a line number holds no blank or
    character to escape, so only the warning needs making one line (once, not once a row)."""
    text = one_line(warning)
    return ": " + text if text else ":"


def _first(pair: tuple) -> Any:
    return pair[0]
