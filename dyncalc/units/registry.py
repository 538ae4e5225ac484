"""The one pint registry of the program (built on first use, from its disk cache) and ``Q_``."""
from __future__ import annotations

from typing import Any

__all__ = ["registry", "Q_", "same_units"]

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


def same_units(units: Any, target: Any) -> bool:
    """Whether pint's conversion from ``units`` to ``target`` hands back the magnitude itself:
    its ``convert`` returns the value unchanged when both are the same unit container
    (``kg`` to ``kg``), so such a conversion can be skipped, bit for bit.

    Example: ``same_units(registry().kg, "kg")`` is true, ``same_units(registry().g, "kg")``
    false."""
    from pint.util import to_units_container

    ureg = registry()
    return to_units_container(units, ureg) == to_units_container(target, ureg)
