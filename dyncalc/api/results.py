"""What an API call returns: the results as Quantities of the caller's registry.

:class:`Result` is one computation (it wraps the :class:`dyncalc.result.Result` the CLI prints),
:class:`ArrayResult` an elementwise one (numpy, Dask or xarray arrays). Both map result names
to values: a Quantity in the result's canonical unit (docs/json.md: the SI unit of its
dimension), or a str for a word such as a damping ``regime``.
"""
from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from typing import Any

__all__ = ["Result", "ArrayResult"]


def _quantity(registry: Any, value: Any, unit: str) -> Any:
    return registry.Quantity(value, unit)


class Result(Mapping[str, Any]):
    """The results of one computation: ``r["omega"]`` is a Quantity of the caller's registry
    in the canonical unit (``rad/s``), ``r.to_dict()`` the ``--json`` object and
    ``r.explain()`` the ``--explain`` text."""

    def __init__(self, result: Any, registry: Any):
        self._result, self._registry = result, registry

    def __getitem__(self, name: str) -> Any:
        from ..result.encode import machine

        entry = self._result.results.get(name)
        if entry is None:
            raise KeyError(f"there is no result named {name!r}; the results are "
                           f"{', '.join(self._result.results)}")
        value, unit = machine(entry, {})
        return value if isinstance(value, str) else _quantity(self._registry, value, unit)

    def __iter__(self) -> Iterator[str]:
        return iter(self._result.results)

    def __len__(self) -> int:
        return len(self._result.results)

    @property
    def command(self) -> str:
        """The command computed (``natural-frequency``)."""
        return str(self._result.command)

    @property
    def scene(self) -> str | None:
        return self._result.scene

    @property
    def model(self) -> str | None:
        return self._result.model

    @property
    def method(self) -> str | None:
        return self._result.method

    @property
    def warnings(self) -> list[str]:
        """The warnings the CLI prints (the API prints nothing)."""
        return list(self._result.warnings)

    @property
    def inputs(self) -> dict[str, Any]:
        """The inputs as read, each a Quantity in the unit typed (a str for a word)."""
        out = {}
        for name, entry in self._result.inputs.items():
            value = entry.value_in()
            out[name] = value if isinstance(value, str) else _quantity(
                self._registry, value, entry.unit)
        return out

    def uncertainty(self, name: str) -> Any:
        """The standard uncertainty of result ``name`` (a Quantity in its canonical unit),
        or ``None`` when no input carried one."""
        entry = self._result.results[name]
        sigma = entry.uncertainty_in(entry.canonical_unit) if entry.uncertainty is not None \
            else None
        return None if sigma is None else _quantity(self._registry, sigma,
                                                    entry.canonical_unit)

    def to_dict(self, explain: bool | str = False) -> dict[str, Any]:
        """The object ``--json`` prints (``--json --explain[=FORMAT]`` with ``explain``)."""
        from ..result.encode import json_data

        return json_data(self._result, {}, [], explain)

    def explain(self, format: str = "text") -> str:
        """The explanation ``--explain[=FORMAT]`` prints (``text``, ``markdown``, ``latex``):
        formula, values substituted, assumptions, reference, textbook example."""
        from ..result.explain_render import FORMATS, render_explanation

        if format not in FORMATS:
            raise ValueError(f"format must be one of {', '.join(FORMATS)}; got {format!r}")
        if self._result.explanation is None:
            return "(no explanation for this result)"
        return render_explanation(self._result.explanation, format)

    def __repr__(self) -> str:
        parts = []
        for name in self:
            value = self[name]
            parts.append(f"{name}={value!r}" if isinstance(value, str)
                         else f"{name}={value:~P}")
        return f"<Result {self.command}: {', '.join(parts)}>"


class ArrayResult(Mapping[str, Any]):
    """The results of an elementwise computation: ``r["omega"]`` is an array Quantity of the
    caller's registry (wrapping a numpy or Dask array; for xarray arguments a DataArray whose
    data is the Quantity); words are object arrays. An element may lack a result the others
    have (NaN there). ``r.element(i)`` is element ``i``'s :class:`Result` (the one-off, numpy
    arguments only), ``r.to_dict()`` the list of their ``--json`` objects."""

    def __init__(self, command: str, values: dict[str, Any], shape: tuple[int, ...],
                 warnings: list[str], element: Callable[[int], Result] | None = None):
        self._values, self._element = values, element
        self.command, self.shape, self.warnings = command, shape, warnings

    def __getitem__(self, name: str) -> Any:
        if name not in self._values:
            raise KeyError(f"there is no result named {name!r}; the results are "
                           f"{', '.join(self._values)}")
        return self._values[name]

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def element(self, index: int | tuple[int, ...]) -> Result:
        """The one-off :class:`Result` of one element (``r.element(3)``, ``r.element((1,
        2))``), with its inputs, warnings and explanation."""
        if self._element is None:
            raise TypeError("element() needs numpy arguments (compute the Dask arrays first)")
        from ..lazy import numpy as np

        index = (index,) if isinstance(index, int) else tuple(index)
        return self._element(int(np.ravel_multi_index(index, self.shape)))

    def to_dict(self, explain: bool | str = False) -> list[Any]:
        """Each element's ``--json`` object, as nested lists of the arguments' shape."""
        from ..lazy import numpy as np

        out = np.empty(self.shape, dtype=object)
        for index in np.ndindex(*self.shape):
            out[index] = self.element(index).to_dict(explain)
        return list(out.tolist()) if self.shape else [out.item()]

    def explain(self, format: str = "text") -> str:
        """One explanation is of one computation: ``r.element(i).explain()``."""
        raise TypeError("explain() is for one computation; use r.element(i).explain()")

    def __repr__(self) -> str:
        return f"<ArrayResult {self.command} {self.shape}: {', '.join(self._values)}>"
