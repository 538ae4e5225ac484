"""Array types that follow numpy's protocols: Dask arrays (computed block by block, lazily,
each block as a numpy array through :func:`.run.evaluate`) and xarray DataArrays (broadcast
by their dimension names, computed on their data, the results DataArrays of the same
coordinates whose data are the Quantities). Neither package is imported unless the caller
passed one of its arrays."""
from __future__ import annotations

from typing import Any

from .results import ArrayResult
from .run import evaluate, one_off
from .values import Given, dask_array_type, is_quantity, xarray_type

__all__ = ["call_xarray", "call_dask", "Tagged"]


class Tagged:
    """A magnitude and the text of its unit (a DataArray's ``attrs["units"]``), read as a
    Quantity would be."""

    __slots__ = ("magnitude", "unit")

    def __init__(self, magnitude: Any, unit: str):
        self.magnitude, self.unit = magnitude, unit


def _split(value: object) -> tuple[Any, str | None]:
    """(magnitude, unit text or None for plain values) of an argument."""
    from .values import unit_text

    if isinstance(value, Tagged):
        return value.magnitude, value.unit
    if is_quantity(value):
        return value.magnitude, unit_text(value.units)  # type: ignore[attr-defined]
    return value, None


def _rejoin(magnitude: Any, unit: str | None) -> object:
    return magnitude if unit is None else Tagged(magnitude, unit)


def call_xarray(record, settings, slots, values, rtol, strict, registry) -> ArrayResult:
    """DataArray arguments: broadcast by name (``xarray.broadcast``), computed on their data
    (numpy or Dask), each result a DataArray of the same dims and coords (a vector result
    adds a last dim ``component``) wrapping the Quantity."""
    import xarray as xr

    kind = xarray_type()
    positions = [i for i, v in enumerate(values) if isinstance(v, kind)]
    template = xr.broadcast(*[values[i] for i in positions])
    plain = list(values)
    for i, array in zip(positions, template):
        data = array.data
        unit = array.attrs.get("units")
        plain[i] = data if is_quantity(data) or not unit else Tagged(data, str(unit))
    first = template[0]
    inner = _call_plain(record, settings, slots, plain, rtol, strict, registry)
    out = {}
    for name in inner:
        value = inner[name]
        dims = first.dims + (("component",) if value.ndim > first.ndim else ())
        out[name] = xr.DataArray(value, dims=dims, coords=first.coords, name=name)
    return ArrayResult(record.name, out, tuple(first.shape), inner.warnings,
                       inner._element)


def _call_plain(record, settings, slots, values, rtol, strict, registry):
    """The numpy (or Dask) computation of the sorted arguments."""
    from .build import array_result, request_of
    from .run import evaluate as run

    if any(_is_dask(v) for v in values):
        return call_dask(record, settings, slots, values, rtol, strict, registry)
    request = request_of(record, settings, slots, [_as_value(v) for v in values], rtol, strict)
    shape = request.shape()
    return array_result(record, request, run(request, shape), shape, registry)


def _is_dask(value: object) -> bool:
    kind = dask_array_type()
    magnitude, _ = _split(value)
    return kind is not None and isinstance(magnitude, kind)


def _as_value(value: object) -> object:
    """A :class:`Tagged` as a value :func:`.values.given` reads."""
    if isinstance(value, Tagged):
        return _TaggedQuantity(value.magnitude, value.unit)
    return value


class _TaggedQuantity:
    """What :func:`.values.given` takes for a Quantity: a magnitude and units whose
    ``~D`` format is the unit text."""

    _REGISTRY = None

    def __init__(self, magnitude: Any, unit: str):
        self.magnitude, self.units = magnitude, _UnitText(unit)


class _UnitText(str):
    def __format__(self, spec: str) -> str:
        return str(self)


def call_dask(record, settings, slots, values, rtol, strict, registry) -> ArrayResult:
    """Dask arguments: broadcast, then one lazy computation per block (``map_blocks``, a
    structured array with a field per result), each result a Quantity wrapping a Dask array.
    The first element is computed at once: its refusal is raised now, and its results name
    the fields (an element lacking one has NaN there; a result only other elements give is
    not kept). A vector parameter takes numpy arrays only."""
    import dask.array as da
    import numpy as np

    from .build import request_of

    split = [_split(v) for v in values]
    arrays = [i for i, (m, _) in enumerate(split) if hasattr(m, "shape") and m.shape != ()]
    for i in arrays:
        if slots[i].vector or slots[i].listed:
            raise TypeError(f"{slots[i].name}: a vector or a list takes numpy arrays, not "
                            "Dask arrays")
    broadcast = da.broadcast_arrays(*[da.asarray(split[i][0]) for i in arrays])
    shape = tuple(int(s) for s in broadcast[0].shape)
    first = list(values)
    for i, array in zip(arrays, broadcast):
        element = np.asarray(array[(0,) * len(shape)].compute()) if shape else array
        first[i] = _as_value(_rejoin(element, split[i][1]))
    probe_request = request_of(record, settings, slots, first, rtol, strict)
    try:
        probe = one_off(probe_request, [(k, n, _cell_text(g)) for k, n, g
                                        in probe_request.givens()])
    except Exception as exc:
        from ..errors import InputError
        from .run import ApiError

        if isinstance(exc, InputError):
            where = "0" if len(shape) == 1 else str((0,) * len(shape))
            raise ApiError(exc, f"at index {where}: ") from None
        raise
    from ..result.encode import machine

    fields: list[tuple[Any, ...]] = []
    units: dict[str, str | None] = {}
    for name, entry in probe.results.items():
        value = machine(entry, {})[0]
        if isinstance(value, str):
            fields.append((name, object))
        else:
            fields.append((name, float, np.shape(value)))
        units[name] = entry.dim.si if entry.dim is not None else None
    dtype = np.dtype(fields)
    names = dtype.names or ()

    def block(*blocks, block_info=None):
        here = list(values)
        for i, b in zip(arrays, blocks):
            here[i] = _as_value(_rejoin(np.asarray(b), split[i][1]))
        request = request_of(record, settings, slots, here, rtol, strict)
        block_shape = np.shape(blocks[0])
        origin = tuple(start for start, _ in block_info[None]["array-location"])
        result = evaluate(request, block_shape, origin)
        out = np.zeros(block_shape, dtype=dtype)
        for name in names:
            if name in result.values:
                flat = result.values[name]
                out[name] = flat.reshape(*block_shape, *flat.shape[1:])
            else:
                out[name] = None if dtype[name] == object else np.nan
        return out

    lazy = da.map_blocks(block, *broadcast, dtype=dtype)
    out = {}
    for name in names:
        field = lazy[name]
        out[name] = field if units[name] is None else registry.Quantity(field, units[name])
    return ArrayResult(record.name, out, shape, list(probe.warnings and
                                                     [f"at index 0: {w}" for w in
                                                      probe.warnings]))


def _cell_text(g: Given) -> str:
    from .run import _text

    return _text(g.cells.item(), g.unit)
