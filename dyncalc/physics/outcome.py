"""What a scene's physics function returns, and the helpers every oscillator shares.

A physics function returns an :class:`Outcome`: named pint quantities (``omega``, ``f``, ``T``
and whatever else the scene gives), plus the model and method used, an error estimate,
warnings and the assumptions with their size at these inputs. It never prints.
"""
from __future__ import annotations

import math
from typing import Any

from ..lazy import numpy as np

from ..units import Q_
from ..records import Record

__all__ = ["Outcome", "periodic", "damped", "periodic_arrays", "damped_arrays", "CRITICAL_BAND"]


class Outcome(Record):
    """The answer of one physics function.

    ``values`` maps result names to pint quantities (or plain floats for pure numbers, numpy
    arrays for mode shapes) in the order they are shown; ``error_estimate`` is the relative
    error bound of the method at these inputs (``None`` for closed forms exact to rounding);
    ``exact_zeros`` names results that are zero by the physics (an equilibrium at the bottom),
    which must not be reported as underflow.

    A plain class with the constructor, repr and equality of the dataclass it was (no code
    generated at import, issue 8).
    """

    _FIELDS = ("values", "model", "method", "error_estimate", "warnings", "assumptions",
               "exact_zeros")
    __hash__ = None  # mutable, compared by value

    def __init__(self, values: dict[str, Any], model: str = "linear",
                 method: str = "closed-form", error_estimate: float | None = None,
                 warnings: list[str] | None = None, assumptions: list[str] | None = None,
                 exact_zeros: set[str] | None = None):
        self.values = values
        self.model = model
        self.method = method
        self.error_estimate = error_estimate
        self.warnings = [] if warnings is None else warnings
        self.assumptions = [] if assumptions is None else assumptions
        self.exact_zeros = set() if exact_zeros is None else exact_zeros


def periodic(omega_si: float, suffix: str = "") -> dict[str, Any]:
    """``omega``, ``f = omega / 2 pi`` and ``T = 2 pi / omega`` from an angular frequency.

    ``omega_si`` in rad/s; ``suffix`` names a family (``"_d"`` gives ``omega_d``, ``f_d``,
    ``T_d``; ``"_1"`` the first mode). A zero frequency has an infinite period (``inf``).

    >>> periodic(2 * math.pi)["T"]
    <Quantity(1.0, 'second')>
    """
    period = 2.0 * math.pi / omega_si if omega_si > 0 else math.inf
    return {f"omega{suffix}": Q_(omega_si, "rad/s"),
            f"f{suffix}": Q_(omega_si / (2.0 * math.pi), "Hz"),
            f"T{suffix}": Q_(period, "s")}


#: ``|1 - zeta^2|`` at or below this (``2**-50``, about 8.9e-16) counts as critical damping.
#: The inputs themselves carry a relative rounding of ``2**-53`` each (more after a unit
#: conversion), so ``c^2 / (4 k m)`` is only known to about four roundings: a system closer
#: than that to critical damping cannot be told from critical with float64 inputs.
CRITICAL_BAND = 2.0 ** -50


def damped(omega_si: float, zeta: float) -> tuple[dict[str, Any], list[str]]:
    """Damped quantities of an oscillator of natural frequency ``omega_si`` and damping ratio
    ``zeta``: ``zeta``, and for ``zeta < 1`` ``omega_d = omega sqrt((1 - zeta)(1 + zeta))``
    with ``f_d`` and ``T_d`` (the product form keeps its digits for zeta a hair below 1).

    Returns ``(values, warnings)``; at or above critical damping there is no damped frequency
    and a warning says so instead; within :data:`CRITICAL_BAND` of 1 it is critical damping,
    as ``damping-ratio`` says.

    >>> values, warnings = damped(10.0, 0.6)
    >>> values["omega_d"]
    <Quantity(8.0, 'radian / second')>
    """
    values: dict[str, Any] = {"zeta": float(zeta)}
    if zeta < 1.0:
        values.update(periodic(omega_si * math.sqrt((1.0 - zeta) * (1.0 + zeta)), "_d"))
        return values, []
    regime = ("critically damped" if abs((1.0 - zeta) * (1.0 + zeta)) <= CRITICAL_BAND
              else "overdamped")
    return values, [f"zeta = {zeta:.6g}: the system is {regime}; it does not oscillate, so "
                    "there is no damped frequency"]


_TWO_PI = 2.0 * math.pi


def periodic_arrays(omega, suffix: str = "") -> dict[str, Any]:
    """``omega``, ``f = omega / 2 pi``, ``T = 2 pi / omega`` for positive ``omega`` arrays (the
    array form of :func:`periodic`, used by batch mode)."""
    with np.errstate(over="ignore", under="ignore", divide="ignore"):
        return {f"omega{suffix}": omega, f"f{suffix}": omega / _TWO_PI,
                f"T{suffix}": _TWO_PI / omega}


def damped_arrays(omega, zeta) -> dict[str, Any]:
    """``zeta``, ``omega_d = omega sqrt((1 - zeta)(1 + zeta))``, ``f_d``, ``T_d`` for
    ``0 <= zeta < 1`` (the array form of :func:`damped`)."""
    values = {"zeta": zeta}
    values.update(periodic_arrays(omega * np.sqrt((1.0 - zeta) * (1.0 + zeta)), "_d"))
    return values
