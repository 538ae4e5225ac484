"""Reading text into quantities: the one registry (:mod:`.registry`), the dimensions dyncalc
checks, angles included (:mod:`.dimensions`), and the strict quantity grammar
(:mod:`.grammar`). Nothing here knows about commands, physics or output."""
from __future__ import annotations

from .dimensions import (ACCELERATION, ANGLE, ANGULAR_ACCELERATION, ANGULAR_MOMENTUM,
                         ANGULAR_RATE, AREA,
                         COUPLING_DAMPING, COUPLING_MASS, COUPLING_STIFFNESS,
                         CYCLE_RATE, DAMPING, DECAY_RATE, DIMENSIONLESS, ENERGY, FORCE, IMPULSE,
                         INERTIA, LENGTH,
                         LINEAR_DRAG, MASS, MODULUS, RIGIDITY, SECOND_MOMENT, STIFFNESS, TIME,
                         TORQUE, TORSIONAL_DAMPING, TORSIONAL_RIGIDITY, TORSIONAL_STIFFNESS,
                         UNBALANCE, VELOCITY, Dim)
from .grammar import (MAX_DEPTH, MAX_TEXT, Parsed, ReadError, convert, format_quantity,
                      parse_quantity, parse_unit, parse_vector, to_si)
from .registry import Q_, registry, same_units

__all__ = [
    "Dim", "Parsed", "ReadError", "registry", "same_units", "Q_", "parse_quantity",
    "parse_vector", "parse_unit", "convert", "to_si", "format_quantity", "MAX_TEXT", "MAX_DEPTH",
    "STIFFNESS", "TORSIONAL_STIFFNESS", "MASS", "INERTIA", "LENGTH", "TIME", "ANGLE",
    "ANGULAR_RATE", "CYCLE_RATE", "DIMENSIONLESS", "ACCELERATION", "VELOCITY", "FORCE",
    "MODULUS", "AREA", "SECOND_MOMENT", "DAMPING", "ANGULAR_ACCELERATION", "DECAY_RATE",
    "LINEAR_DRAG", "RIGIDITY", "TORSIONAL_RIGIDITY", "UNBALANCE",
    "COUPLING_MASS", "COUPLING_STIFFNESS", "TORSIONAL_DAMPING", "COUPLING_DAMPING", "TORQUE",
    "IMPULSE", "ENERGY", "ANGULAR_MOMENTUM",
]
