"""The pieces of a call: where each argument goes (:class:`Slot`), the
:class:`~.run.Request` made of them, the caller's registry, and the :class:`ArrayResult` of
an elementwise computation."""
from __future__ import annotations

from typing import Any

from ..errors import InputError
from .results import ArrayResult, Result
from .run import ApiError, Request
from .values import given, is_quantity, xarray_type

__all__ = ["Slot", "caller_registry", "choice_error", "request_of", "array_result"]


class Slot:
    """Where an argument goes: ``kind`` (``option``, ``word``, ``element``), its ``name``,
    and whether it is a vector (``VEC``), a list of numbers in one text, or a matrix
    (``MATRIX``: a numpy array, nested lists, a Quantity array, one value)."""

    __slots__ = ("kind", "name", "vector", "listed", "matrix")

    def __init__(self, kind: str, name: str, vector: bool = False, listed: bool = False,
                 matrix: bool = False):
        self.kind, self.name, self.vector, self.listed = kind, name, vector, listed
        self.matrix = matrix


def caller_registry(values: list[object]) -> Any:
    """The registry of the first Quantity argument (inside a DataArray too), else dyncalc's."""
    xr_type = xarray_type()
    for value in values:
        if xr_type is not None and isinstance(value, xr_type):
            value = value.data
        if is_quantity(value):
            return value._REGISTRY  # type: ignore[attr-defined]
    from ..units import registry

    return registry()


def choice_error(record, parameter, value: str) -> InputError:
    """The CLI's message for a word that is not among a parameter's fixed choices (click's
    ``Invalid value for '--method': ...`` and the hint)."""
    import click

    try:
        click.Choice(parameter.choices).convert(value, click.Option([parameter.flag]), None)
    except click.BadParameter as exc:
        shown = exc.format_message().rstrip(".")
        return ApiError(InputError(f"{shown}; see 'dyncalc {record.name} --help'"))
    raise AssertionError("a valid choice")  # pragma: no cover


def _check_choices(record, request: Request) -> None:
    """Words of a ``choice`` parameter that are not among its choices: the CLI's refusal."""
    for name, g in request.options.items():
        p = record.parameter(name)
        if p.kind == "choice" and isinstance(p.choices, tuple):
            for word in sorted(set(g.cells.ravel().tolist())):
                if word not in p.choices:
                    raise choice_error(record, p, word)


def request_of(record, settings, slots: list[Slot], values: list[object], rtol, strict,
               ) -> Request:
    options, words, elements = {}, {}, []
    for slot, value in zip(slots, values):
        label = slot.name if slot.kind != "element" else f"element {slot.name[1:]}"
        g = given(value, label, vector=slot.vector, listed=slot.listed, matrix=slot.matrix)
        if slot.kind == "option":
            options[slot.name] = g
        elif slot.kind == "word":
            words[slot.name] = g
        else:
            elements.append(g)
    request = Request(record, settings, options, words, elements, rtol, strict)
    _check_choices(record, request)
    return request


def array_result(record, request: Request | None, arrays, shape, registry) -> ArrayResult:
    """The :class:`ArrayResult` of flattened ``arrays`` (:class:`~.run.Arrays`)."""
    values = {}
    for name, flat in arrays.values.items():
        array = flat.reshape(*shape, *flat.shape[1:])
        dim = arrays.dims.get(name)
        values[name] = array if flat.dtype == object else registry.Quantity(
            array, dim.si if dim is not None else "")
    if request is None:
        return ArrayResult(record.name, values, shape, arrays.warnings)
    from .run import one_off_at

    def element(i: int) -> Result:
        return Result(one_off_at(request, arrays.columns, i), registry)
    return ArrayResult(record.name, values, shape, arrays.warnings, element)
