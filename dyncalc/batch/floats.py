"""Floats to text and text to floats a column at a time, to the byte what ``repr`` and ``float``
give one at a time.

Writing: ``repr`` of a float is the shortest decimal string that reads back to the same float
(the closest such string when several are shortest), positional from 1e-4 to 1e16 and
``d.ddde±XX`` outside. orjson (the ``fast`` extra, version 3.12 or later) writes the same
shortest digits for a whole numpy array in one call, five times faster, in the same notation
except between 1e-9 and 1e-4 (``0.00001`` and ``1e-7`` for ``1e-05`` and ``1e-07``) and for
``inf``/``nan`` (``null``): those few are written by ``repr``. Without orjson, or with one that
fails the check of :func:`_writer` (an older release writes ``1e16`` for ``1e+16``), every
float is written by ``repr``. ``tests/test_batch_floats.py`` proves the identity over float64
bit patterns with hypothesis.

Reading: ``orjson.loads`` reads a column of plain numbers, joined as a JSON list, twice as fast
as ``float`` one cell at a time and correctly rounded like it; JSON's number grammar is part of
``float``'s, so a cell it refuses (``+5``, ``.5``, ``5.``, a number beyond float64) is read
again by ``float``, which gives what the one-off gives or refuses it. Its one difference, an
integer ``-0`` read as ``0``, is read again by ``float`` too; cells that could hold a JSON value
other than a number (``null``, ``true``, ``"5"``, ``[1]``) are all read by ``float``.

Example::

    >>> import numpy as np
    >>> reprs(np.array([1e-05, 0.25, 1e16, -0.0, float("inf")]))
    ['1e-05', '0.25', '1e+16', '-0.0', 'inf']
    >>> parse_floats(["1.5", " 2e3", "-0"]).tolist()
    [1.5, 2000.0, -0.0]
"""
from __future__ import annotations

import functools
import re

import numpy as np

#: Floats whose ``repr`` orjson must write to the byte before it is trusted: every notation
#: and each boundary between notations that orjson writes as ``repr`` does.
_PROBES = (0.0, -0.0, 1.0, -2.0, 0.1, 1 / 3, 123456.789, 0.0001, 0.00012345, 9e15,
           9999999999999998.0, 1e16, -1.2345678901234568e+17, 1e21, 1e22, 1e100, 1e300,
           1.7976931348623157e308, 9.99e-10, 1e-10, 1.5e-100, 2.2250738585072014e-308,
           5e-324, -1.5e-320)


def _reprs_python(values: list[float]) -> list[str]:
    """``list(map(repr, values))``, a third faster: the list's repr writes every float's repr
    in C (no float repr holds ``", "``)."""
    return str(values)[1:-1].split(", ") if values else []


@functools.cache
def _orjson():
    """The orjson module, or ``None`` when it is absent or not :func:`_trusted`."""
    try:
        import orjson
    except ImportError:
        return None
    return orjson if _trusted(orjson) else None


def _trusted(orjson) -> bool:
    """Whether ``orjson`` writes the floats of :data:`_PROBES` as ``repr`` writes them."""
    try:
        written = orjson.dumps(np.array(_PROBES), option=orjson.OPT_SERIALIZE_NUMPY)
        return written.decode()[1:-1].split(",") == list(map(repr, _PROBES))
    except Exception:  # noqa: BLE001 (a release without numpy arrays, or any other failure)
        return False


def reprs(array) -> list[str]:
    """``repr`` of each float of a one-dimensional float64 array (or sequence of floats)."""
    orjson = _orjson()
    array = np.ascontiguousarray(array, dtype=np.float64)
    if orjson is None or array.ndim != 1:
        return _reprs_python(array.tolist())
    if not len(array):
        return []
    texts = orjson.dumps(array, option=orjson.OPT_SERIALIZE_NUMPY).decode()[1:-1].split(",")
    size = np.abs(array)
    # repr's own: 1e-9 <= |x| < 1e-4 (other notation), inf and nan (``null``: not below inf)
    other = ((size < 1e-4) & (size >= 1e-9)) | ~(size < np.inf)
    if other.any():
        where = np.flatnonzero(other)
        for i, text in zip(where.tolist(), _reprs_python(array[where].tolist())):
            texts[i] = text
    return texts


def int_texts(array) -> list[str]:
    """``str`` of each integer of a one-dimensional integer array (line numbers)."""
    orjson = _orjson()
    array = np.ascontiguousarray(array, dtype=np.int64)
    if orjson is None or not len(array):
        return list(map(str, array.tolist()))
    return orjson.dumps(array, option=orjson.OPT_SERIALIZE_NUMPY).decode()[1:-1].split(",")


def reprs_rows(array) -> list[str]:
    """The rows of a two-dimensional float64 array, each its floats' ``repr`` joined by
    commas (vectors in a CSV cell)."""
    array = np.asarray(array, dtype=np.float64)
    rows, width = array.shape
    if not width:
        return [""] * rows
    flat = reprs(array.ravel())
    return list(map(",".join, zip(*[iter(flat)] * width)))


def parse_floats(cells) -> np.ndarray:
    """``float`` of each cell (strings of the characters ``0-9 . e E + -``, spaces and tabs),
    as a float64 array; ``ValueError`` where ``float`` refuses a cell."""
    values = json_floats(",".join(cells), len(cells), cells)
    if values is not None:
        return values
    return np.fromiter(map(float, cells), dtype=np.float64, count=len(cells))


#: An integer ``-0`` (which orjson reads as 0, ``float`` as -0.0): a minus, a zero, no
#: digit, point or exponent after it.
_MINUS_ZERO_RE = re.compile(r"-0(?![0-9.eE])")


def json_floats(joined: str, n: int, cells=None) -> np.ndarray | None:
    """The ``n`` numbers of ``joined`` (numbers separated by commas, perhaps spaces and tabs
    around them) read at once as JSON numbers, each as ``float`` reads it; ``None`` where
    orjson is absent or refuses them (JSON's number grammar is part of ``float``'s: no ``+``,
    no leading zero, no ``.5`` or ``5.``), or where they are not ``n``. ``cells``: the
    numbers as a list, if the caller has it (else ``joined`` is split where needed)."""
    orjson = _orjson()
    # JSON values other than numbers (a string, list, object, true, false, null) need one of
    # these characters; without them, a list of ``n`` values is ``n`` numbers, one a cell
    if orjson is None or not n or any(map(joined.__contains__, '"[{tfn')):
        return None
    try:
        values = np.array(orjson.loads("[" + joined + "]"), dtype=np.float64)
    except (orjson.JSONDecodeError, OverflowError, TypeError, ValueError):
        return None
    if values.shape != (n,):
        return None
    if _MINUS_ZERO_RE.search(joined):  # ``-0``, an integer: read as 0, not -0.0
        cells = joined.split(",") if cells is None else cells
        zeros = np.flatnonzero((values == 0.0) & ~np.signbit(values)).tolist()
        for i in [i for i in zeros if "-" in cells[i]]:
            values[i] = float(cells[i])
    return values
