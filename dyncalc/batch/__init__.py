"""Batch mode (``--batch FILE``): one command over every row of a CSV file, in one process.

The file's header names the parameters: a command's option names without the dashes
(``k``, ``m``, ``length``, ``v0``) or, for the scene commands, scene parameter names (``l``,
``J``, ``M``). A header cell may carry a unit, ``k [N/m]``: it applies to every cell of the
column that has no unit of its own. A cell may carry its own unit (``2 kN/m``), so a column may
mix units; an empty cell means "not given", exactly as an option left out. Each row is the
one-off command with those parameters, so a row's numbers are exactly the one-off's.

Output: the input columns as read, then one column per result, ``omega [rad/s]`` (CSV, full
precision, as ``--value`` prints it); or, with ``--json``, one JSON object per line, the
one-off ``--json`` object with the row's line number (``"line"``) in front. Results are in
their canonical unit (:attr:`~dyncalc.result.entries.Entry.canonical_unit`: ``k_eq [N/m]``
for springs typed in kN/m), unless ``--unit NAME=UNIT`` names another. Cells may carry
uncertainties (``2.0+/-0.1``, ``(100 ± 5) N/m``): such rows take the generic path, and when the
first chunk has any, each result column is followed by ``u(NAME) [unit]``, its standard
uncertainty (empty for rows without one).

Two paths give the same numbers:

* the generic path evaluates each row through the same library call as the one-off command
  (:class:`NaturalFrequencyRows` calls
  :func:`dyncalc.commands.natural_frequency.compute_scene`,
  :class:`SpringRows` :func:`dyncalc.commands.springs.network_stiffness`, ...);
* a vectorised path (:func:`.fast._natural_frequency_fast`) computes whole chunks of
  ``natural-frequency`` rows at once with numpy, through the column kernel of the scene's
  physics function (:mod:`dyncalc.physics.columns`: the same formulas written for arrays,
  bit for bit the one-off's, e.g. :func:`~dyncalc.physics.numerics.sqrt_ratio_array` splits
  the binary exponents off with ``np.frexp`` as :func:`~dyncalc.physics.numerics.sqrt_ratio`
  does with ``math.frexp``). A unit is read once per chunk and column (pint converts the whole
  array), not once per cell. Any row it cannot take exactly as the one-off would (a cell that
  is not a plain number with a plain unit, a value out of range, a constraint broken, a
  result that is zero, infinite or needs a warning: every row the kernel does not mark exact)
  goes to the generic path, so refusals and warnings are the one-off's own
  (tests/test_batch_kernels.py holds the two paths byte-identical for every scene and
  command). The other commands take the same path through their record's column adapter
  (:attr:`dyncalc.commands.record.Command.columns`, :mod:`.fast_commands`), block by block
  of rows that give the same columns, words and typed units; the first row of each block is
  also computed by the one-off, whose inputs the JSON lines show and whose results must be
  the adapter's to the bit, or the block takes the generic path.

Rows are read, computed and written in chunks of :data:`CHUNK_ROWS` (JSON lines: sized by
their width, :func:`chunk_rows`), so memory stays flat however long the file. A bad row is reported on stderr as ``Error: line N: ...`` (its line in
the file, the header being line 1); with ``--on-error stop`` (the default) the rows before it
have been written and nothing after it is; with ``--on-error skip`` every bad row gets its own
line and every good row is written. The exit status is 2 when any row failed.

Malformed files: a column the command does not read is refused at the header (not passed
through, so a mistyped optional parameter is never ignored silently); a line longer than
:data:`MAX_LINE` characters, a line that is not UTF-8 and a row with the wrong number of cells
are bad rows; a quote left open, text after a closing quote and an I/O error while reading end
the run at their line, after the rows before it are written.

The modules, in the order the data flows: :mod:`.source` opens the file and hands out its
records a chunk at a time; :mod:`.header` reads the header and a cell's text under its header
unit; :mod:`.rows` says what each command reads from a row (the generic path); :mod:`.fast`
and :mod:`.fast_commands` compute whole chunks, reading their columns with :mod:`.columns`;
:mod:`.write` writes CSV rows (:mod:`.csvlines`) or JSON lines; this module's
:func:`run_batch` runs them in turn.
"""
from __future__ import annotations

import gc
import os
import sys

import numpy as np

from ..errors import EXIT_BAD_INPUT, EXIT_OK, InputError, one_line
from ..result.propagate import propagate
from .fast import FastBlock
from .header import Column, has_own_unit, read_header, with_header_unit
from .rows import (CoriolisRows, CoriolisTimeRows, DampingRows, EomRows, ForcedRows, ModesRows,
                   NaturalFrequencyRows, RigidRows,
                   RollingRows, RowSpec, SpringRows)
from .source import MAX_LINE, _Reader, open_source
from .write import _BLANK, _FAST, _Writer

__all__ = ["run_batch", "RowSpec", "NaturalFrequencyRows", "SpringRows", "DampingRows",
           "RollingRows", "CoriolisRows", "CoriolisTimeRows", "ForcedRows", "ModesRows", "EomRows",
           "RigidRows", "CHUNK_ROWS",
           "ON_ERROR", "GENERIC_ENV", "MAX_LINE",
           "open_source", "Column", "read_header", "has_own_unit", "with_header_unit",
           "FastBlock"]

#: Rows read, computed and written at a time; the result columns of CSV output are those of
#: the first chunk's rows.
CHUNK_ROWS = 16384
#: JSON lines: the rows of the first chunk, and the cells (input and result columns times
#: rows) a later chunk holds at most. A JSON line carries every input and result with its
#: unit and text (forced-response's run to 1.3 kB), so a wide command takes fewer rows a
#: chunk and memory stays flat (issue 17: <= 100 MB at 10^7 rows).
FIRST_JSON_ROWS = 1024
CHUNK_CELLS = 16384 * 4


def chunk_rows(as_json: bool, inputs: int, results: list | None, csv_rows: int = CHUNK_ROWS
               ) -> int:
    """Rows in the next chunk. CSV: the command's ``csv_rows`` (:attr:`RowSpec.csv_rows`),
    at most :data:`CHUNK_ROWS`. JSON lines: :data:`FIRST_JSON_ROWS` until the results are
    known, then :data:`CHUNK_CELLS` over the columns (between FIRST_JSON_ROWS and
    CHUNK_ROWS, and at most ``csv_rows``)."""
    if not as_json:
        return min(CHUNK_ROWS, csv_rows)
    if not results:
        return min(CHUNK_ROWS, FIRST_JSON_ROWS)
    return min(CHUNK_ROWS, csv_rows,
               max(FIRST_JSON_ROWS, CHUNK_CELLS // (inputs + len(results))))


ON_ERROR = ("stop", "skip")
#: Set to "1" to send every row through the generic (one-off) path: for tests and benchmarks.
GENERIC_ENV = "DYNCALC_BATCH_GENERIC"


def run_batch(spec: RowSpec, source: str, *, as_json: bool = False,
              units: dict[str, str] | None = None, on_error: str = "stop",
              debug: bool = False, out=None, err=None, fast: bool | None = None) -> int:
    """Run ``spec``'s command on every row of the CSV ``source`` (a path, ``-`` for standard
    input, or an open text stream); the exit status.

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
    stream = open_source(source) if isinstance(source, str) else source
    collecting = gc.isenabled()
    gc.enable()  # the rows stream for long: the collector is on (dyncalc.cli.main pauses it)
    try:
        return _run(spec, stream, as_json, dict(units or {}), on_error, debug, out, err,
                    fast and spec.fast is not None)
    finally:
        if not collecting:
            gc.disable()
        if isinstance(source, str) and source != "-":
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
    rows = chunk_rows(as_json, len(columns), None, spec.csv_rows)
    writer = _Writer([c.raw for c in columns], as_json, units, on_error, out, err, rows)
    failed = False
    cache: dict = {}
    while (chunk := reader.chunk(rows)) is not None:
        row_failed, stopped = _compute(spec, columns, chunk, on_error, debug, fast, writer,
                                       cache)
        rows = chunk_rows(as_json, len(columns), writer.columns, spec.csv_rows)
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
