"""The one pint registry of the program (built on first use, from pint's cache) and ``Q_``."""
from __future__ import annotations

from typing import Any

__all__ = ["registry", "Q_"]

# --------------------------------------------------------------------------------------------
# The registry


_REGISTRY = None


def registry():
    """The one :class:`pint.UnitRegistry` of the program, built on first use from pint's cache."""
    global _REGISTRY
    if _REGISTRY is None:
        import pint

        try:
            ureg = pint.UnitRegistry(cache_folder=":auto:")
        except OSError:  # an unwritable cache folder: build it the slow way
            ureg = pint.UnitRegistry()
        ureg.define("@alias turn = rev")  # rev/s, rev/min, as engineers write them
        _REGISTRY = ureg
    return _REGISTRY


def Q_(value: Any, unit: Any = ""):
    """A quantity of the program's registry: ``Q_(2, "kg")``."""
    return registry().Quantity(value, unit)
