"""Output lines assembled a column at a time: each line is the same *parts* in order, a part
being a text every line shares, a column of floats (written as ``repr`` writes them, through
:func:`~dyncalc.batch.floats.reprs`), a column of integers or a column of texts.

polars' ``concat_str`` was tried for the joining (issue 17): no faster than joining the columns
with ``map("".join, zip(...))`` here (1.14 s against 1.13 s for 10^6 mass-spring rows) and 40 MB
more memory for its import, so dyncalc does not use it (the limit scripts of ``benchmarks/limit``
do). Joining the pieces of all lines in one ``str.join`` is faster still (below).

Example::

    >>> lines(["k=", np.array([1.5, 1e-05]), ", ", ["a", "b"]], 2)
    ['k=1.5, a', 'k=1e-05, b']
"""
from __future__ import annotations

from itertools import chain, repeat

import numpy as np

from .floats import int_texts, reprs


def lines(parts: list, n: int, joined: bool = False):
    """The ``n`` lines made of ``parts`` (each a ``str``, a 1-D float64 numpy array, a 1-D
    integer array or a list of ``n`` texts): a list of str, or with ``joined`` one str of
    the lines each ending in a line break.

    Joined, the pieces of every line are joined in one ``str.join`` (no text per line is
    made): three times faster than joining each line, then the lines."""
    merged = _merged([_constant(p) for p in parts] + (["\n"] if joined else []))
    columns: list = []
    written: list = []  # (float column, its texts): a column equal to one written is not again
    for part in merged:
        if isinstance(part, str):
            columns.append(repeat(part))
        elif isinstance(part, np.ndarray):
            columns.append(int_texts(part) if part.dtype.kind == "i" else
                           _float_texts(part, written))
        else:
            columns.append(part)
    if all(isinstance(c, repeat) for c in columns):  # texts only: every line the same
        line = "".join(next(c) for c in columns)
        return line * n if joined else [line] * n
    if joined:
        return "".join(chain.from_iterable(zip(*columns)))
    return list(map("".join, zip(*columns)))


#: Lines assembled at a time by :func:`write_lines` (flat memory) ...
STEP = 4096
#: ... and at most this many column cells (a wide result, ``coriolis`` over times' 60-odd
#: columns, would hold 4096 rows' texts at once: 19 MB of a 100 MB budget), at least
#: :data:`MIN_STEP` lines.
STEP_CELLS, MIN_STEP = 32768, 256


def write_lines(out, parts: list, n: int) -> None:
    """Write the ``n`` lines of ``parts`` to the text stream ``out``, :data:`STEP` lines (or
    :data:`STEP_CELLS` cells) at a time, each ending in a line break."""
    columns = sum(1 for p in parts if not isinstance(p, str))
    step = max(MIN_STEP, min(STEP, STEP_CELLS // max(1, columns)))
    for start in range(0, n, step):
        stop = min(n, start + step)
        piece = parts if (start, stop) == (0, n) else [
            p if isinstance(p, str) else p[start:stop] for p in parts]
        out.write(lines(piece, stop - start, joined=True))


def _float_texts(column: np.ndarray, written: list) -> list[str]:
    """``repr`` of each float of ``column``, or the texts of a column of ``written`` equal to
    it bit for bit (``inertia``'s moments appear in ``J_O``, ``J_C`` and ``J_1..J_3``: ten
    columns of three distinct ones a disk); ``written`` gets the column's texts."""
    bits = np.ascontiguousarray(column, dtype=np.float64).view(np.int64)
    for other, texts in written:
        if len(other) == len(bits) and (not len(bits) or other[0] == bits[0]) \
                and np.array_equal(other, bits):
            return texts
    texts = reprs(column)
    written.append((bits, texts))
    return texts


def _constant(part):
    """A float column of one bit pattern as its one text (a shared text, joined with the texts
    around it: fewer pieces a line; ``modes``' rigid-body mode writes 0.0 in three columns);
    any other part as it is."""
    if isinstance(part, np.ndarray) and part.dtype.kind == "f" and part.ndim == 1 \
            and len(part) > 1:
        bits = np.ascontiguousarray(part, dtype=np.float64).view(np.int64)
        if bits[0] == bits[-1] and (bits == bits[0]).all():
            return reprs(part[:1])[0]
    return part


def _merged(parts: list) -> list:
    """Consecutive texts joined into one (fewer, longer literals)."""
    out: list = []
    for part in parts:
        if isinstance(part, str) and out and isinstance(out[-1], str):
            out[-1] += part
        elif not (isinstance(part, str) and not part):
            out.append(part)
    return out
