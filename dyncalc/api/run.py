"""One call of a command through the API: its arguments as texts, the one-off computation,
and the elementwise computation of arrays through batch mode's vectorised path.

An array is computed as batch mode computes the rows of a file (:mod:`dyncalc.batch`): each
argument is a column of cells under its unit (:mod:`.values`), a chunk of
:data:`~dyncalc.batch.CHUNK_ROWS` rows at a time goes through the command's vectorised path
(``RowSpec.fast``: the column kernels of :mod:`dyncalc.physics.columns`, a scene's
``compute.columns`` or the record's ``Command.columns`` adapter), which keeps only the rows its
kernel marks exact, and every other row (a warning, a refusal, an extreme the kernel leaves
alone) is the one-off computation of that row's texts. So every element is the one-off's to
the bit, and the same as the batch row with those cells.
"""
from __future__ import annotations

import math
from typing import Any

from ..errors import InputError, PhysicsError, one_line
from ..lazy import numpy as np
from .values import Given

__all__ = ["Request", "ApiError", "one_off", "evaluate"]


def ApiError(exc: InputError, prefix: str = "") -> InputError:
    """The error the API raises for ``exc``: its message as the CLI's ``Error:`` line shows
    it (one line), of the same class (:class:`PhysicsError` or :class:`InputError`)."""
    cls = PhysicsError if isinstance(exc, PhysicsError) else InputError
    return cls(prefix + one_line(exc))


class Request:
    """A command call: the ``record``, the ``settings`` (``scene``, ``method``: texts or
    ``None``), the parameters by name (``options``), the extra keywords (``words``: scene
    parameters or a spring network's shared values), the spring ``elements``, ``rtol`` and
    ``strict`` (``--strict-units``)."""

    __slots__ = ("record", "settings", "options", "words", "elements", "rtol", "strict")

    def __init__(self, record, settings: dict[str, str | None], options: dict[str, Given],
                 words: dict[str, Given], elements: list[Given], rtol: float | None,
                 strict: bool):
        self.record, self.settings, self.options = record, settings, options
        self.words, self.elements, self.rtol, self.strict = words, elements, rtol, strict

    def givens(self) -> list[tuple[str, str, Given]]:
        """Every argument as ``(kind, name, Given)``: ``option``, ``word`` or ``element``
        (named ``k1``, ``k2``, ... as batch mode's element columns)."""
        return ([("option", n, g) for n, g in self.options.items()]
                + [("word", n, g) for n, g in self.words.items()]
                + [("element", f"k{i}", g) for i, g in enumerate(self.elements, 1)])

    def shape(self) -> tuple[int, ...]:
        """The shape the arguments broadcast to (``()``: one computation)."""
        return np.broadcast_shapes(*(g.cells.shape for _, _, g in self.givens()))


def _text(cell: str, unit: str) -> str:
    from ..batch.header import with_header_unit

    return with_header_unit(cell.strip(), unit) if unit else cell


def one_off(request: Request, texts: list[tuple[str, str, str]]):
    """The one-off :class:`~dyncalc.result.Result` of ``texts`` (``(kind, name, text)``, as
    :meth:`Request.givens`), computed as the CLI computes it (uncertainties propagated)."""
    from ..result.propagate import propagate

    record = request.record
    values: dict[str, str | None] = {p.name: None for p in record.parameters}
    values.update(request.settings)
    words = [text for kind, _, text in texts if kind == "element"]
    for kind, name, text in texts:
        if kind == "option":
            values[name] = text
        elif kind == "word":
            words.append(f"{name}={text}")
    try:
        return propagate(lambda: record.compute(values, tuple(words), rtol=request.rtol,
                                                strict=request.strict))
    except InputError as exc:
        raise ApiError(exc) from None


def one_off_at(request: Request, columns: list[tuple[str, str, list, str]], i: int):
    """The one-off Result of row ``i`` of the flattened ``columns``."""
    return one_off(request, [(kind, name, _text(cells[i], unit))
                             for kind, name, cells, unit in columns])


def index_text(i: int, shape: tuple[int, ...], origin: tuple[int, ...] | None = None) -> str:
    """Row ``i`` of an array of ``shape`` as the index the caller knows (``3``, ``(1, 2)``),
    shifted by ``origin`` (where a Dask block starts)."""
    index = np.unravel_index(i, shape) if shape else ()
    if origin is not None:
        index = tuple(int(a) + int(b) for a, b in zip(index, origin))
    index = tuple(int(a) for a in index)
    return str(index[0]) if len(index) == 1 else str(index)


class Arrays:
    """The results of an array computation, flattened: name -> array (float64 NaN-filled, an
    extra last axis for vectors; object arrays for words), the dimension of each, and the
    warnings (``at index I: ...``)."""

    __slots__ = ("n", "values", "dims", "warnings", "columns")

    def __init__(self, n: int, columns: list):
        self.n = n
        self.values: dict[str, Any] = {}
        self.dims: dict[str, Any] = {}
        self.warnings: list[str] = []
        self.columns = columns  # (kind, name, cells, unit): each element's texts

    def put(self, name: str, rows: Any, value: Any, dim) -> None:
        if name not in self.values:
            sample = np.asarray(value)
            trailing = sample.shape[1:] if not np.isscalar(rows) else sample.shape
            if sample.dtype.kind in "USO":
                self.values[name] = np.full((self.n, *trailing), None, dtype=object)
            else:
                self.values[name] = np.full((self.n, *trailing), np.nan)
            self.dims[name] = dim
        self.values[name][rows] = value


def _spec(request: Request):
    """The batch :class:`~dyncalc.batch.RowSpec` of the call (its vectorised path)."""
    from ..batch import NaturalFrequencyRows, SpringRows
    from ..batch.rows import RecordRows

    record = request.record
    if record.name == "natural-frequency":
        from ..commands.natural_frequency import STANDARD

        return NaturalFrequencyRows({option: str(name) for option, name in STANDARD.items()},
                                    scene=request.settings.get("scene"),
                                    method=request.settings.get("method"), rtol=request.rtol,
                                    strict=request.strict)
    if record.words == "ELEMENT...":
        return SpringRows(record.name.removeprefix("spring-"), strict=request.strict)
    return RecordRows(record, request.settings, scene_words=tuple(request.words),
                      rtol=request.rtol, strict=request.strict)


def evaluate(request: Request, shape: tuple[int, ...],
             origin: tuple[int, ...] | None = None) -> Arrays:
    """The results of every element of arrays broadcast to ``shape``, flattened (C order).
    An element the one-off refuses raises its error, prefixed ``at index I:``; ``origin``
    places a Dask block in the whole array for that index."""
    from ..batch import CHUNK_ROWS
    from ..batch.header import Column

    n = math.prod(shape)
    columns = []
    for kind, name, g in request.givens():
        cells = np.broadcast_to(g.cells, shape).ravel().tolist() if shape else [g.cells.item()]
        columns.append((kind, name, cells, g.unit))
    out = Arrays(n, columns)

    def where(i: int) -> str:
        return index_text(i, shape, origin)

    def generic(i: int, result=None) -> None:
        if result is None:
            try:
                result = one_off_at(request, columns, i)
            except InputError as exc:
                raise ApiError(exc, f"at index {where(i)}: ") from None
        from ..result.encode import machine

        for name, entry in result.results.items():
            out.put(name, i, machine(entry, {})[0], entry.dim)
        warned.extend((i, w) for w in result.warnings)

    warned: list[tuple[int, str]] = []  # (element, warning): the vectorised rows' too
    if n == 0:
        return out
    # the first element on its own: the refusals of the call as a whole (a parameter given
    # twice, a scene that does not take one) are the one-off's, and its results come first
    generic(0)
    spec = _spec(request)
    keys = [spec.key(name) for _, name, _, _ in columns]
    fast = spec.fast is not None and None not in keys and len(set(keys)) == len(keys) \
        and n > 1
    cache: dict = {}
    for start in range(0, n, CHUNK_ROWS):
        stop = min(n, start + CHUNK_ROWS)
        covered = np.zeros(stop - start, dtype=bool)
        if fast:
            table = [cells[start:stop] for _, _, cells, _ in columns]
            heads = [Column(j, name, name, unit, key) for j, ((_, name, _, unit), key)
                     in enumerate(zip(columns, keys))]
            for block in spec.fast(spec, heads, table, False, cache):
                rows = block.rows + start
                covered[block.rows] = True
                for name, values in block.values.items():
                    out.put(name, rows, values, block.dims.get(name))
                warned.extend((start + i, w) for i, w in block.warned_rows() if start + i)
        for i in np.flatnonzero(~covered).tolist():
            if start + i:
                generic(start + i)
    warned.sort(key=lambda pair: pair[0])  # (stable: an element's in the one-off's order)
    out.warnings = [f"at index {where(i)}: {w}" for i, w in warned]
    return out
