"""What each result name of the scenes means: its dimension, display unit, symbol and words.

Families share a stem: ``omega``, ``omega_0``, ``omega_d``, ``omega_1`` are angular rates;
``f...`` cycle rates; ``T...`` periods.
"""
from __future__ import annotations

import re

from ..units import (ACCELERATION, ANGLE, ANGULAR_RATE, CYCLE_RATE, DECAY_RATE, DIMENSIONLESS, FORCE,
                     INERTIA, LENGTH, LINEAR_DRAG, MASS, STIFFNESS, TIME, VELOCITY, Dim)
from ..records import Frozen

__all__ = ["ResultKind", "result_kind", "DECAY_RATE", "LINEAR_DRAG"]



class ResultKind(Frozen):
    """A result's dimension, display unit, symbol and words (a frozen record, written out
    rather than a dataclass: no code generated at import, issue 8)."""

    __slots__ = ("dim", "unit", "symbol", "description")

    def __init__(self, dim: Dim, unit: str, symbol: str, description: str):
        setattr_ = object.__setattr__
        setattr_(self, "dim", dim)
        setattr_(self, "unit", unit)
        setattr_(self, "symbol", symbol)
        setattr_(self, "description", description)


_SUFFIX = {"": "", "_0": " (small oscillations)", "_d": " (damped)"}

_FIXED = {
    "zeta": ResultKind(DIMENSIONLESS, "", "ζ", "damping ratio"),
    "xi": ResultKind(DECAY_RATE, "1/s", "ξ", "decay rate (amplitude ~ exp(-xi t))"),
    "phi_0": ResultKind(ANGLE, "deg", "φ0", "equilibrium angle"),
    "phi2_0": ResultKind(ANGLE, "deg", "φ2,0", "half the opening angle at rest"),
    "theta_eq": ResultKind(ANGLE, "deg", "θeq", "stable equilibrium angle"),
    "J_A": ResultKind(INERTIA, "kg*m^2", "J_A", "moment of inertia about the pivot"),
    "v_crit": ResultKind(VELOCITY, "m/s", "v_crit", "critical (resonance) speed"),
    "x_amp": ResultKind(LENGTH, "m", "x_amp", "steady amplitude"),
    "y0": ResultKind(LENGTH, "m", "y0", "static amplitude"),
    "y_max": ResultKind(LENGTH, "m", "y_max", "largest steady amplitude"),
    "Omega": ResultKind(ANGULAR_RATE, "rad/s", "Ω", "forcing angular frequency"),
    "beta_crit": ResultKind(LINEAR_DRAG, "N*s/m^2", "β_crit", "critical drag coefficient"),
    "error_estimate": ResultKind(DIMENSIONLESS, "", "ε", "relative error estimate"),
    # the coriolis command's scalar set-ups (its inverse problems)
    "a_c": ResultKind(ACCELERATION, "m/s^2", "a_c", "Coriolis acceleration 2 Omega v_r"),
    "F_c": ResultKind(FORCE, "N", "F_c", "Coriolis force m a_c"),
    "a_c_mag": ResultKind(ACCELERATION, "m/s^2", "|a_c|", "magnitude of a_c"),
    "F_c_mag": ResultKind(FORCE, "N", "|F_c|", "magnitude of F_c"),
    "a_c_horizontal_mag": ResultKind(ACCELERATION, "m/s^2", "|a_c,h|",
                                     "horizontal part of a_c"),
    "F_c_horizontal_mag": ResultKind(FORCE, "N", "|F_c,h|",
                                     "horizontal part of F_c (the sideways push)"),
    # forced response (forced-response)
    "eta": ResultKind(DIMENSIONLESS, "", "η", "frequency ratio Omega/omega"),
    "X": ResultKind(LENGTH, "m", "X", "steady amplitude"),
    "phi": ResultKind(ANGLE, "deg", "φ", "phase lag behind the excitation (0 to 180 deg)"),
    "V": ResultKind(DIMENSIONLESS, "", "V", "magnification (amplitude over its static "
                                               "reference)"),
    "TR": ResultKind(DIMENSIONLESS, "", "TR", "transmissibility"),
    "F_T": ResultKind(FORCE, "N", "F_T", "amplitude of the force on the support"),
    "Z": ResultKind(LENGTH, "m", "Z", "amplitude of the spring's deflection"),
    "X_res": ResultKind(LENGTH, "m", "X_res", "steady amplitude at Omega = omega"),
    "V_res": ResultKind(DIMENSIONLESS, "", "V_res", "magnification at Omega = omega"),
    "Omega_peak": ResultKind(ANGULAR_RATE, "rad/s", "Ω_peak", "excitation frequency of the "
                                                                "largest amplitude"),
    "X_peak": ResultKind(LENGTH, "m", "X_peak", "largest steady amplitude over Omega"),
    "V_peak": ResultKind(DIMENSIONLESS, "", "V_peak", "largest magnification over Omega"),
    "Omega_iso": ResultKind(ANGULAR_RATE, "rad/s", "Ω_iso", "above it TR < 1 (isolation)"),
    "isolation": ResultKind(DIMENSIONLESS, "", "I", "isolation 1 - TR"),
    "bandwidth": ResultKind(ANGULAR_RATE, "rad/s", "Δω", "half-power bandwidth (exact)"),
    "Q": ResultKind(DIMENSIONLESS, "", "Q", "quality factor 1/(2 zeta)"),
    "x": ResultKind(LENGTH, "m", "x", "total displacement at time t"),
    "m_eff": ResultKind(MASS, "kg", "m_eff", "effective mass in the driven coordinate"),
    "k_eff": ResultKind(STIFFNESS, "N/m", "k_eff", "effective stiffness in the driven "
                                                    "coordinate"),
    "F": ResultKind(FORCE, "N", "F", "force at time t"),
    "H_max": ResultKind(FORCE, "N", "H_max", "largest contact friction force"),
    "mu0": ResultKind(DIMENSIONLESS, "", "μ0", "least static friction coefficient"),
    # relative motion (coriolis --scene)
    "v_r": ResultKind(VELOCITY, "m/s", "v_r", "velocity relative to the moving frame"),
    "t_R": ResultKind(TIME, "s", "t_R", "time to reach the radius r"),
    "v_abs": ResultKind(VELOCITY, "m/s", "v_abs", "absolute speed"),
    "F_slot": ResultKind(FORCE, "N", "F_slot", "side force of the slot wall"),
    "x_t": ResultKind(LENGTH, "m", "x(t)", "distance from the centre at time t"),
    "v_t": ResultKind(VELOCITY, "m/s", "v(t)", "speed along the slot at time t"),
    "F_t": ResultKind(FORCE, "N", "F(t)", "side force of the slot wall at time t"),
    "rho": ResultKind(LENGTH, "m", "ρ", "distance AC of the pin from the pivot"),
    "omega_AD": ResultKind(ANGULAR_RATE, "rad/s", "ω_AD", "angular velocity of the link"),
    "v_C": ResultKind(VELOCITY, "m/s", "v_C", "speed of the pin"),
}

_STEMS = {
    "omega": (ANGULAR_RATE, "rad/s", "ω", "angular frequency"),
    "f": (CYCLE_RATE, "Hz", "f", "frequency"),
    "T": (TIME, "s", "T", "period"),
}
_FAMILY_RE = re.compile(r"^(omega|f|T)(_0|_d|_\d+)?$")
_MODE_RE = re.compile(r"^mode_(\d+)$")


def result_kind(name: str) -> ResultKind:
    """The kind of result ``name``; ``KeyError`` for a name no scene should produce."""
    if name in _FIXED:
        return _FIXED[name]
    m = _FAMILY_RE.match(name)
    if m:
        dim, unit, symbol, words = _STEMS[m.group(1)]
        suffix = m.group(2) or ""
        if suffix in _SUFFIX:
            return ResultKind(dim, unit, symbol + suffix.replace("_", ""), words + _SUFFIX[suffix])
        return ResultKind(dim, unit, symbol + suffix.replace("_", ""),
                          f"{words} of mode {suffix[1:]}")
    m = _MODE_RE.match(name)
    if m:
        return ResultKind(DIMENSIONLESS, "", f"mode {m.group(1)}",
                          f"shape of mode {m.group(1)} (normalised)")
    raise KeyError(name)
