"""Column kernels: the SI kernel under a physics function, called on whole numpy columns.

Batch mode computes a chunk of rows at once: each parameter is a float64 array in its SI unit
(the ``si`` unit of its :class:`~dyncalc.units.Dim`; a choice such as ``body`` as the array of
the values its words stand for, ``kappa``), and the kernel returns a :class:`Columns`. A
kernel reproduces the one-off function *bit for bit* on the rows it marks ``exact``; every
other row (a warning, a refusal, another model or method, a value the arrays cannot give
exactly) is left to the one-off function, so batch output never differs from the one-off's.

A kernel is attached to its physics function with :func:`column_kernel`, and found as the
function's ``columns`` attribute::

    @column_kernel(mass_spring)
    def _mass_spring_columns(k, m):
        omega = sqrt_ratio_array(k, m)
        return Columns(periodic_arrays(omega), exact=np.isfinite(omega) & (omega > 0))
"""
from __future__ import annotations

from typing import Any

from ..records import Record

__all__ = ["Columns", "TypedColumn", "column_kernel", "kernel_of", "text_column",
           "warnings_of_rows"]


class Columns(Record):
    """What a column kernel returns.

    ``values`` maps result names to float64 arrays in the unit the one-off
    :class:`~dyncalc.physics.outcome.Outcome` gives them (SI), in its order; ``exact`` is a
    boolean array: the rows whose values are the one-off's to the bit, with no warning, no
    refusal and this ``model`` and ``method`` (the other rows' values are ignored);
    ``error_estimate`` is the one-off's (a float, the same for every row) or ``None``.
    With ``optional``, a result that some exact rows do not have is NaN there: the batch
    splits the block by the results each row has (every exact value is otherwise finite).
    ``warnings``: the one-off's warnings (the same texts on every row) of the exact rows that
    ``warned`` marks (a boolean array; ``None``: no row warns); the batch keeps together only
    rows that all warn so or all do not, and its probe checks the texts against the one-off.
    ``row_warnings``: where the texts differ from row to row (a value in them), a function of
    the rows kept (an index array) giving each row's warnings (a tuple of texts, in the
    one-off's order; ``None`` where none of the rows warns); the texts must come from the
    function the one-off formats them with (the probe checks a block's first row);
    ``None``: ``warnings`` and ``warned`` say.
    ``extras``: where the one-off's ``extra`` differs from row to row (``coriolis``' Earth
    directions), a function of the rows kept (an index array) giving the parts of their JSON
    ``extra`` objects (texts every line shares and lists of one text a row, as
    :func:`dyncalc.batch.assemble.lines` takes them); ``None``: no ``extra``.
    ``groups``: an integer a row where rows differ in their results' dimensions (a mode's
    modal mass in kg or kg*m^2): the batch keeps rows of one code together, each code
    probed on its own; ``None``: one group.
    """

    _FIELDS = ("values", "exact", "model", "method", "error_estimate", "optional",
               "warnings", "warned", "extras", "groups", "row_warnings")
    __slots__ = _FIELDS
    __hash__ = None

    def __init__(self, values: dict[str, Any], exact: Any, model: str = "linear",
                 method: str = "closed-form", error_estimate: float | None = None,
                 optional: bool = False, warnings: tuple[str, ...] = (), warned: Any = None,
                 extras: Any = None, groups: Any = None, row_warnings: Any = None):
        self.values, self.exact, self.model, self.method, self.error_estimate = (
            values, exact, model, method, error_estimate)
        self.optional, self.warnings, self.warned = optional, tuple(warnings), warned
        self.extras, self.groups, self.row_warnings = extras, groups, row_warnings


class TypedColumn(Record):
    """A parameter column as typed, for a kernel whose one-off computes in the unit typed (a
    pendulum's ``cos(theta0/2)`` in degrees, a track's ``R - r`` in R's unit): ``si`` (the SI
    values), ``typed`` (the magnitudes as typed) and ``unit`` (per row, pint's name of the unit
    typed as the one-off's quantity carries it, ``"radian"``, ``"millimeter"``; the SI unit
    for a bare number; ``""`` where unknown: such rows are not exact). A kernel asks for its
    parameters so with a ``typed_params`` attribute naming them."""

    __slots__ = ("si", "typed", "unit")
    __hash__ = None

    def __init__(self, si, typed, unit):
        self.si, self.typed, self.unit = si, typed, unit


def column_kernel(physics):
    """Attach the decorated kernel to the physics function ``physics`` as
    ``physics.columns`` (the decorated kernel is returned unchanged)."""
    def attach(kernel):
        physics.columns = kernel
        kernel.physics = physics
        return kernel
    return attach


def kernel_of(physics):
    """The column kernel of ``physics``, or ``None`` where it has none."""
    return getattr(physics, "columns", None)


def one_result(kernel, name: str) -> dict:
    """The keywords that ask ``kernel`` for the result ``name`` alone: ``{"only": name}``
    where the kernel takes them (marked ``takes_only``; it then computes that result alone,
    exact where that result is), else none. An inverse's probes and search read one result;
    its answer asks for all.

    Example: ``one_result(lambda **kw: None, "alpha") == {}``."""
    return {"only": name} if getattr(kernel, "takes_only", False) else {}


def warnings_of_rows(rows, warned, texts_of):
    """Each row's warnings for :attr:`Columns.row_warnings`: ``()`` for the rows of the index
    array ``rows`` that ``warned`` (a boolean array over the block) does not mark,
    ``texts_of(i)`` (a tuple of texts) for those it does; ``None`` where it marks none.

    Example: ``warnings_of_rows(np.array([0, 2]), np.array([False, True, True]),
    lambda i: (f"row {i}",)) == [(), ("row 2",)]``."""
    from ..lazy import numpy as np

    marks = warned[rows]
    if not marks.any():
        return None
    out: list = [()] * len(rows)
    for j in np.flatnonzero(marks).tolist():
        out[j] = texts_of(int(rows[j]))
    return out


def text_column(n: int, text: str):
    """A column (object array) of ``n`` cells, each the str ``text``: a result or label that
    is the same on every row (``eom``'s equations, an inverse's empty label).

    Filled in place: ``np.full(n, text, dtype=object)`` casts the text through a numpy string
    for every cell, 57 ms for 10^6 rows against 1 ms here (issue 17).

    Example: ``text_column(2, "x'' = -x").tolist() == ["x'' = -x", "x'' = -x"]``."""
    from ..lazy import numpy as np

    column = np.empty(n, dtype=object)
    column.fill(text)
    return column
