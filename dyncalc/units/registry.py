"""The one pint registry of the program (built on first use, from its disk cache) and ``Q_``."""
from __future__ import annotations

from typing import Any

__all__ = ["registry", "Q_"]

# --------------------------------------------------------------------------------------------
# The registry


_REGISTRY = None


def registry():
    """The one :class:`pint.UnitRegistry` of the program, built on first use from the disk
    cache (:mod:`dyncalc.units.cache`: a bad or unwritable cache never fails a run)."""
    global _REGISTRY
    if _REGISTRY is None:
        from .cache import build_registry

        ureg = build_registry()
        ureg.define("@alias turn = rev")  # rev/s, rev/min, as engineers write them
        _REGISTRY = ureg
    return _REGISTRY


def Q_(value: Any, unit: Any = ""):
    """A quantity of the program's registry: ``Q_(2, "kg")``."""
    return registry().Quantity(value, unit)
