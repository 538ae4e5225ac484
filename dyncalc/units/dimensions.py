"""Dimensions: the :class:`Dim` record, one constant per kind of quantity dyncalc reads (angles
and the two kinds of rate included, which pint alone does not tell apart), and the class of
each unit name (angle, turn, cycle)."""
from __future__ import annotations

from ..records import Frozen
from .registry import registry

__all__ = [
    "Dim", "STIFFNESS", "TORSIONAL_STIFFNESS", "MASS", "INERTIA", "LENGTH", "AREA",
    "SECOND_MOMENT", "TIME", "VELOCITY", "ACCELERATION", "FORCE", "MODULUS", "DAMPING", "ANGLE",
    "ANGULAR_RATE", "ANGULAR_ACCELERATION", "CYCLE_RATE", "DIMENSIONLESS", "DECAY_RATE",
    "UNBALANCE", "COUPLING_MASS", "COUPLING_STIFFNESS", "TORSIONAL_DAMPING", "COUPLING_DAMPING",
    "TORQUE", "IMPULSE", "ENERGY", "ANGULAR_MOMENTUM",
    "LINEAR_DRAG", "RIGIDITY", "TORSIONAL_RIGIDITY", "angle_power", "angle_exponent",
]

# --------------------------------------------------------------------------------------------
# Dimensions


class Dim(Frozen):
    """A physical dimension a parameter or result has.

    ``name`` is the word in messages ("stiffness"), ``display`` the dimension as shown
    (``[force]/[length]``), ``check`` the pint dimensionality it must have, ``si`` the unit of a
    bare number and of SI output, ``kind`` one of plain, angle, angular-rate, cycle-rate,
    dimensionless; ``angles`` the powers of ``[angle]`` a quantity of it may carry (pint counts
    the radian as dimensionless, dyncalc does not: see :func:`angle_power`). A torsional
    stiffness takes ``(-1, 0)`` (``N*m/rad``, or a bare ``N*m`` read as per radian), an angle
    ``(1,)``, a linear stiffness ``(0,)``.
    """

    __slots__ = ("name", "display", "check", "si", "kind", "angles")

    def __init__(self, name: str, display: str, check: str, si: str, kind: str = "plain",
                 angles: tuple[int, ...] = (0,)):
        setattr_ = object.__setattr__
        setattr_(self, "name", name)
        setattr_(self, "display", display)
        setattr_(self, "check", check)
        setattr_(self, "si", si)
        setattr_(self, "kind", kind)
        setattr_(self, "angles", angles)


STIFFNESS = Dim("stiffness", "[force]/[length]", "[force]/[length]", "N/m")
TORSIONAL_STIFFNESS = Dim("torsional stiffness", "[force]*[length]/[angle]",
                          "[force]*[length]", "N*m/rad", angles=(-1, 0))
MASS = Dim("mass", "[mass]", "[mass]", "kg")
INERTIA = Dim("mass moment of inertia", "[mass]*[length]^2", "[mass]*[length]**2", "kg*m^2")
LENGTH = Dim("length", "[length]", "[length]", "m")
AREA = Dim("area", "[length]^2", "[length]**2", "m^2")
SECOND_MOMENT = Dim("second moment of area", "[length]^4", "[length]**4", "m^4")
TIME = Dim("time", "[time]", "[time]", "s")
VELOCITY = Dim("velocity", "[length]/[time]", "[length]/[time]", "m/s")
ACCELERATION = Dim("acceleration", "[length]/[time]^2", "[length]/[time]**2", "m/s^2")
FORCE = Dim("force", "[force]", "[force]", "N")
UNBALANCE = Dim("unbalance", "[mass]*[length]", "[mass]*[length]", "kg*m")
# The entries of a mass, stiffness or damping matrix that couple a translation with a rotation
# (``modes``), and a rotation's damping.
COUPLING_MASS = Dim("translation-rotation mass coupling", "[mass]*[length]",
                    "[mass]*[length]", "kg*m")
COUPLING_STIFFNESS = Dim("translation-rotation stiffness coupling", "[force]/[angle]",
                         "[force]", "N/rad", angles=(-1, 0))
TORSIONAL_DAMPING = Dim("torsional damping coefficient", "[force]*[length]*[time]/[angle]",
                        "[force]*[length]*[time]", "N*m*s/rad", angles=(-1, 0))
COUPLING_DAMPING = Dim("translation-rotation damping coupling", "[force]*[time]/[angle]",
                       "[force]*[time]", "N*s/rad", angles=(-1, 0))
TORQUE = Dim("torque", "[force]*[length]", "[force]*[length]", "N*m")
IMPULSE = Dim("impulse", "[force]*[time]", "[force]*[time]", "N*s")
ENERGY = Dim("energy", "[force]*[length]", "[force]*[length]", "J")
ANGULAR_MOMENTUM = Dim("angular momentum", "[mass]*[length]^2/[time]",
                       "[mass]*[length]**2/[time]", "kg*m^2/s", angles=(0, 1))
MODULUS = Dim("modulus", "[force]/[length]^2", "[force]/[length]**2", "Pa")
DAMPING = Dim("damping coefficient", "[force]*[time]/[length]", "[force]*[time]/[length]",
              "N*s/m")
ANGLE = Dim("angle", "[angle]", "", "rad", "angle", angles=(1,))
ANGULAR_RATE = Dim("angular rate", "[angle]/[time]", "1/[time]", "rad/s", "angular-rate",
                   angles=(1,))
ANGULAR_ACCELERATION = Dim("angular acceleration", "[angle]/[time]^2", "1/[time]**2",
                           "rad/s^2", "angular-rate", angles=(1,))
CYCLE_RATE = Dim("frequency", "[cycles]/[time]", "1/[time]", "Hz", "cycle-rate")
DIMENSIONLESS = Dim("pure number", "dimensionless", "", "", "dimensionless")
DECAY_RATE = Dim("decay rate", "1/[time]", "1/[time]", "1/s")
LINEAR_DRAG = Dim("drag per unit length", "[force]*[time]/[length]^2",
                  "[force]*[time]/[length]**2", "N*s/m^2")
RIGIDITY = Dim("bending stiffness", "[force]*[length]^2", "[force]*[length]**2", "N*m^2")
TORSIONAL_RIGIDITY = Dim("torsional rigidity", "[force]*[length]^2", "[force]*[length]**2",
                         "N*m^2", angles=(-1, 0))

_TURN_UNITS = {"turn", "revolutions_per_minute", "revolutions_per_second"}
_CYCLE_ONLY_UNITS = {"hertz"}


_ANGLE_EXPONENTS: dict[str, float] = {}


def angle_exponent(name: str) -> float:
    """The power of ``[angle]`` in one pint unit name: 1 for ``degree``, ``turn``,
    ``revolutions_per_minute``; 2 for ``steradian``; 0 for ``hertz``, ``percent``, ``meter``."""
    known = _ANGLE_EXPONENTS.get(name)
    if known is None:
        try:
            root = registry().get_root_units(name)[1]._units
            known = float(root.get("radian", 0.0))
        except Exception:  # not a unit pint knows: no angle
            known = 0.0
        _ANGLE_EXPONENTS[name] = known
    return known


def angle_power(quantity) -> float:
    """The power of ``[angle]`` in ``quantity``'s unit, as typed: ``N*m/deg`` -1, ``rpm`` 1,
    ``N*m*deg`` 1, ``%`` 0. (pint keeps the units as multiplied and divided; sums of
    quantities with different angle powers are refused by the grammar.)"""
    return sum(power * angle_exponent(name) for name, power in quantity.unit_items())


def _unit_names(unit) -> list[str]:
    return list(unit._units.keys())


def _base_name(name: str) -> str:
    """pint's unit name without its prefix: ``kilohertz`` -> ``hertz``."""
    try:
        return registry().parse_unit_name(name)[0][1]
    except (IndexError, Exception):  # not a unit pint can split: keep it as it is
        return name


_UNIT_CLASSES: dict[str, str] = {}


def _unit_class(name: str) -> str:
    """``turn`` (revolutions), ``angle`` (radian, degree, ...), ``cycle`` (hertz), ``rate``
    (a plain 1/time such as 1/s, 1/min) or ``other``. Remembered per name: asking pint costs
    a fraction of a millisecond each time, and a quantity asks for every unit it names."""
    known = _UNIT_CLASSES.get(name)
    if known is None:
        known = _UNIT_CLASSES[name] = _classify_unit(name)
    return known


def _classify_unit(name: str) -> str:
    base = _base_name(name)
    if base in _TURN_UNITS:
        return "turn"
    if base in _CYCLE_ONLY_UNITS:
        return "cycle"
    root = registry().get_root_units(base)[1]._units
    if "radian" in root:
        return "angle"
    return "other"
