"""A command function's call: its arguments sorted into the record's parameters, then one
computation, an elementwise one over numpy arrays, or one over Dask or xarray arrays
(:mod:`.duck`)."""
from __future__ import annotations

from ..errors import InputError
from .build import Slot, array_result, caller_registry, choice_error, request_of
from .results import ArrayResult, Result
from .run import ApiError, evaluate, one_off
from .values import dask_array_type, is_quantity, xarray_type

__all__ = ["call"]


def _sort(record, elements: tuple, parameters: dict[str, object]):
    """``(settings, slots, values)``: the settings (texts), and each argument's slot and
    value; wrong keywords raise TypeError, as a Python function's would."""
    fname = record.name.replace("-", "_")
    by_name = {p.name: p for p in record.parameters}
    if elements and record.words not in ("ELEMENT...", "BODY..."):
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
                              listed=p.kind == "text" and "," in p.metavar,
                              matrix=p.metavar == "MATRIX"))
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
            word = settings.get(p.name)
            if word is None:
                word = settings[p.name] = p.default
            if isinstance(p.choices, tuple) and word is not None and word not in p.choices:
                raise choice_error(record, p, word)
    return settings, slots, values


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


