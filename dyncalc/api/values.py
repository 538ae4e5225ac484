"""A Python argument -> the text the command line would have been given.

Every argument becomes *cells* and a *unit*, as a column of a batch file: ``cells`` an object
array of texts (shape ``()`` for one value), ``unit`` the text of the unit they are in (``""``:
none, a bare number read in SI). The text of one element is
:func:`~dyncalc.batch.header.with_header_unit` of its cell and the unit, exactly as batch mode
reads a cell under its header's unit, so an element of an array and a one-off read the same
text.

* a pint Quantity, of any registry: its magnitude's cells and ``format(units, "~D")`` (pint's
  default format with symbols, ``kN / m``, whatever format the caller's registry prefers);
* a ``str``: the text as typed on the command line (``"2 kN/m"``, ``"2.0+/-0.1 kg"``);
* a number: its shortest round-trip text (``repr`` of the float), read in SI;
* a numpy array (or a list) of those: one cell per element; a vector parameter (``VEC``)
  takes its last axis of length 3 as the vector; a list parameter (``"x0,x1,..."``) joins a
  sequence into one cell;
* a matrix parameter (``MATRIX``) takes the whole array as one value
  (:class:`~dyncalc.units.matrix.MatrixValue`): a numpy array or nested lists of numbers (in
  SI), a Quantity array (its unit), or nested lists of Quantities (each in its own unit,
  written out as the command line's ``[[2 kg, 0.1 kg*m], ...]``).
"""
from __future__ import annotations

import numbers
import sys
from typing import Any

from ..lazy import numpy as np

__all__ = ["Given", "is_quantity", "dask_array_type", "xarray_type", "given", "matrix_value"]


class Given:
    """One argument as cells (an object array of texts) and the unit they are in."""

    __slots__ = ("cells", "unit")

    def __init__(self, cells: Any, unit: str):
        self.cells, self.unit = cells, unit

    def __repr__(self) -> str:
        return f"Given({self.cells!r}, {self.unit!r})"


def is_quantity(value: object) -> bool:
    """Whether ``value`` is a pint Quantity of any registry (duck-typed: pint not imported)."""
    return (hasattr(value, "_REGISTRY") and hasattr(value, "magnitude")
            and hasattr(value, "units"))


def dask_array_type():
    """``dask.array.Array`` when dask is loaded (never imported here), else ``None``."""
    module = sys.modules.get("dask.array")
    return getattr(module, "Array", None)


def xarray_type():
    """``xarray.DataArray`` when xarray is loaded (never imported here), else ``None``."""
    module = sys.modules.get("xarray")
    return getattr(module, "DataArray", None)


def unit_text(units: Any) -> str:
    """The text of a pint unit of any registry, as dyncalc's grammar reads it."""
    return format(units, "~D")


def _cell(value: Any, name: str) -> str:
    """The text of one plain element."""
    if isinstance(value, str):
        return value
    if isinstance(value, (bool, np.bool_)):
        raise TypeError(f"{name}: a bool is not a quantity")
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))
    raise TypeError(f"{name}: cannot read a {type(value).__name__} as a quantity (give a pint "
                    "Quantity, a str as typed on the command line, or a number in SI)")


def _cells(magnitude: Any, name: str, vector: bool, listed: bool) -> Any:
    """The object array of texts of a plain magnitude (a number, a str, a list, an array)."""
    if isinstance(magnitude, str) or (not hasattr(magnitude, "__len__")
                                      and not hasattr(magnitude, "shape")):
        return np.array(_cell(magnitude, name), dtype=object)
    # a list keeps its elements' own types (an int is written as one: 10, not 10.0)
    array = np.asarray(magnitude, dtype=object if isinstance(magnitude, (list, tuple))
                       else None)
    if array.dtype.kind in "bcV" or (array.dtype.kind == "O" and array.ndim == 0):
        raise TypeError(f"{name}: cannot read an array of {array.dtype} as quantities")
    if array.ndim == 0:
        return np.array(_cell(array.item(), name), dtype=object)
    if vector or listed:
        if vector and array.shape[-1] != 3:
            raise TypeError(f"{name}: a vector has 3 components (the last axis); got shape "
                            f"{array.shape}")
        rows = array.reshape(-1, array.shape[-1]).tolist()
        cells = np.empty(len(rows), dtype=object)
        cells[:] = [",".join(_cell(v, name) for v in row) for row in rows]
        return cells.reshape(array.shape[:-1])
    flat = array.ravel().tolist()
    cells = np.empty(len(flat), dtype=object)
    cells[:] = [_cell(v, name) for v in flat]
    return cells.reshape(array.shape)


def _entry_text(value: Any, name: str) -> str:
    """One entry of a nested list given for a matrix: a Quantity as ``2.0 kg``."""
    if is_quantity(value):
        return f"{_cell(value.magnitude, name)} {unit_text(value.units)}"
    return _cell(value, name)


def matrix_value(value: object, name: str) -> str:
    """A matrix argument as the one text (or :class:`~dyncalc.units.matrix.MatrixValue`)
    the command reads."""
    from ..units.matrix import MatrixValue

    if isinstance(value, str):
        return value
    if is_quantity(value):
        magnitude = value.magnitude  # type: ignore[attr-defined]
        array = np.asarray(magnitude, dtype=float)
        if array.ndim != 2:
            raise TypeError(f"{name}: a matrix is a 2-D array; got shape {array.shape}")
        return MatrixValue.of_numbers(array, unit_text(value.units))  # type: ignore
    rows = value.tolist() if hasattr(value, "tolist") else value
    if not isinstance(rows, (list, tuple)) or not all(isinstance(r, (list, tuple))
                                                      for r in rows):
        raise TypeError(f"{name}: a matrix is a 2-D array, nested lists, a Quantity array "
                        f"or a str; got {type(value).__name__}")
    entries = [v for row in rows for v in row]
    if any(is_quantity(v) or isinstance(v, str) for v in entries):
        text = "[" + ", ".join("[" + ", ".join(_entry_text(v, name) for v in row) + "]"
                               for row in rows) + "]"
        return MatrixValue(text)
    for v in entries:
        _cell(v, name)  # a bool or an object that is no number is refused
    if len({len(row) for row in rows}) > 1:
        raise TypeError(f"{name}: the rows of a matrix need the same length")
    return MatrixValue.of_numbers(np.asarray(rows, dtype=float).reshape(len(rows), -1), "")


def given(value: object, name: str, *, vector: bool = False, listed: bool = False,
          matrix: bool = False) -> Given:
    """``value`` (a Quantity, a str, a number, an array of them) as a :class:`Given`.

    ``vector``: the parameter takes a 3-vector (its last axis); ``listed``: it takes a list
    of numbers in one text (``x0,x1,...``), so a 1-D sequence is one value; ``matrix``: the
    whole value is one matrix (:func:`matrix_value`)."""
    if matrix:
        cell = np.empty((), dtype=object)
        cell[()] = matrix_value(value, name)
        return Given(cell, "")
    if is_quantity(value):
        magnitude = value.magnitude  # type: ignore[attr-defined]
        unit = unit_text(value.units)  # type: ignore[attr-defined]
        if isinstance(magnitude, str):
            raise TypeError(f"{name}: a Quantity whose magnitude is a str; give the str")
        return Given(_cells(magnitude, name, vector, listed), unit)
    return Given(_cells(value, name, vector, listed), "")
