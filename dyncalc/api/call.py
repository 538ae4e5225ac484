"""A command function's call: its arguments sorted into the record's parameters, then one
computation, an elementwise one over numpy arrays, or one over Dask or xarray arrays
(:mod:`.duck`)."""
from __future__ import annotations

from typing import Any

from ..errors import InputError
from .results import ArrayResult, Result
from .run import ApiError, Request, evaluate, one_off
from .values import dask_array_type, given, is_quantity, xarray_type

__all__ = ["Slot", "call", "caller_registry"]


class Slot:
    """Where an argument goes: ``kind`` (``option``, ``word``, ``element``), its ``name``,
    and whether it is a vector (``VEC``) or a list of numbers in one text."""

    __slots__ = ("kind", "name", "vector", "listed")

    def __init__(self, kind: str, name: str, vector: bool = False, listed: bool = False):
        self.kind, self.name, self.vector, self.listed = kind, name, vector, listed


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


def _choice_error(record, parameter, value: str) -> InputError:
    """The CLI's message for a word that is not among a parameter's fixed choices (click's
    ``Invalid value for '--method': ...`` and the hint)."""
    import click

    try:
        click.Choice(parameter.choices).convert(value, click.Option([parameter.flag]), None)
    except click.BadParameter as exc:
        shown = exc.format_message().rstrip(".")
        return ApiError(InputError(f"{shown}; see 'dyncalc {record.name} --help'"))
    raise AssertionError("a valid choice")  # pragma: no cover


def _sort(record, elements: tuple, parameters: dict[str, object]):
    """``(settings, slots, values)``: the settings (texts), and each argument's slot and
    value; wrong keywords raise TypeError, as a Python function's would."""
    fname = record.name.replace("-", "_")
    by_name = {p.name: p for p in record.parameters}
    if elements and record.words != "ELEMENT...":
        raise TypeError(f"{fname}() takes keyword arguments only")
    settings: dict[str, str | None] = {}
    slots: list[Slot] = []
    values: list[object] = []
    for name, value in parameters.items():
        p = by_name.get(name)
        if p is not None and p.kind == "after":
            raise TypeError(f"{fname}() does not take {name}= (the command line's {p.flag} "
                            "acts on the printed result)")
        if p is not None and p.kind == "setting":
            if value is not None and not isinstance(value, str):
                raise TypeError(f"{fname}(): {name}= takes a str, not "
                                f"{type(value).__name__}")
            settings[name] = value
            continue
        if value is None:
            continue  # as an option left out
        if p is not None:
            slots.append(Slot("option", name, vector=p.metavar == "VEC",
                              listed=p.kind == "text" and "," in p.metavar))
        elif record.words is not None:
            slots.append(Slot("word", name))
        else:
            raise TypeError(f"{fname}() got an unexpected keyword argument {name!r}")
        values.append(value)
    for i, element in enumerate(elements, 1):
        slots.append(Slot("element", f"k{i}"))
        values.append(element)
    for p in record.parameters:
        if p.kind == "setting":
            if settings.get(p.name) is None:
                settings[p.name] = p.default
            choices = p.choices
            if isinstance(choices, tuple) and settings[p.name] is not None \
                    and settings[p.name] not in choices:
                raise _choice_error(record, p, settings[p.name])
    return settings, slots, values


def _check_choices(record, request: Request) -> None:
    """Words of a ``choice`` parameter that are not among its choices: the CLI's refusal."""
    for name, g in request.options.items():
        p = record.parameter(name)
        if p.kind == "choice" and isinstance(p.choices, tuple):
            for word in sorted(set(g.cells.ravel().tolist())):
                if word not in p.choices:
                    raise _choice_error(record, p, word)


def request_of(record, settings, slots: list[Slot], values: list[object], rtol, strict,
               ) -> Request:
    options, words, elements = {}, {}, []
    for slot, value in zip(slots, values):
        label = slot.name if slot.kind != "element" else f"element {slot.name[1:]}"
        g = given(value, label, vector=slot.vector, listed=slot.listed)
        if slot.kind == "option":
            options[slot.name] = g
        elif slot.kind == "word":
            words[slot.name] = g
        else:
            elements.append(g)
    request = Request(record, settings, options, words, elements, rtol, strict)
    _check_choices(record, request)
    return request


def _is_duck(value: object, kind) -> bool:
    if kind is None:
        return False
    return isinstance(value, kind) or (is_quantity(value)
                                       and isinstance(value.magnitude, kind))  # type: ignore


def call(record, elements: tuple, parameters: dict[str, object], rtol: float | None,
         strict: bool) -> Result | ArrayResult:
    """Compute ``record`` on the arguments of its API function."""
    if rtol is not None and not (isinstance(rtol, (int, float)) and 0 < rtol < 1):
        raise ApiError(InputError(f"Invalid value for '--rtol': must be between 0 and 1 "
                                  f"(exclusive); got {rtol!r}"))
    settings, slots, values = _sort(record, elements, dict(parameters))
    registry = caller_registry(values)
    if any(_is_duck(v, xarray_type()) for v in values):
        from .duck import call_xarray

        return call_xarray(record, settings, slots, values, rtol, strict, registry)
    if any(_is_duck(v, dask_array_type()) for v in values):
        from .duck import call_dask

        return call_dask(record, settings, slots, values, rtol, strict, registry)
    request = request_of(record, settings, slots, values, rtol, strict)
    shape = request.shape()
    if shape == ():
        return Result(one_off(request, [(kind, name, _text(g))
                                        for kind, name, g in request.givens()]), registry)
    arrays = evaluate(request, shape)
    return array_result(record, request, arrays, shape, registry)


def _text(g) -> str:
    from .run import _text as text

    return text(g.cells.item(), g.unit)


def array_result(record, request: Request | None, arrays, shape, registry) -> ArrayResult:
    """The :class:`ArrayResult` of flattened ``arrays`` (:class:`~.run.Arrays`)."""
    values = {}
    for name, flat in arrays.values.items():
        array = flat.reshape(*shape, *flat.shape[1:])
        dim = arrays.dims.get(name)
        values[name] = array if flat.dtype == object else registry.Quantity(
            array, dim.si if dim is not None else "")
    element = None
    if request is not None:
        from .run import one_off_at

        columns = arrays.columns

        def element(i: int) -> Result:
            return Result(one_off_at(request, columns, i), registry)
    return ArrayResult(record.name, values, shape, arrays.warnings, element)
