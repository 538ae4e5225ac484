"""The dimensions of ``eom``'s inputs and results: which coordinates are lengths and which
angles, whether ``T``, ``V``, ``D`` and ``Q`` fit together, and the units of the linearised
matrices. No sympy: the checks run on the expression trees of :mod:`dyncalc.units.expression`.
"""
from __future__ import annotations

import itertools

from ..errors import InputError
from ..units.expression import Dimension, DimensionError, dimension_of

__all__ = ["ENERGY", "LENGTH_DIM", "infer_coordinates", "unit_text", "matrix_units",
           "dimension_of_dim", "nice_unit"]

MASS_DIM = Dimension({"[mass]": 1})
LENGTH_DIM = Dimension({"[length]": 1})
TIME_DIM = Dimension({"[time]": 1})
ENERGY = Dimension({"[mass]": 1, "[length]": 2, "[time]": -2})
PURE = Dimension()
_BASE = {"[mass]": "kg", "[length]": "m", "[time]": "s", "[current]": "A",
         "[temperature]": "K", "[substance]": "mol", "[luminosity]": "cd"}


def dimension_of_dim(dim) -> Dimension:
    """The :class:`Dimension` of a :class:`dyncalc.units.Dim` (angles are pure numbers)."""
    from ..units.grammar import unit_in_base

    if not dim.si:
        return PURE
    return Dimension(unit_in_base(dim.si)[1])


def unit_text(dim: Dimension) -> str:
    """SI base units of ``dim`` as pint reads them: ``kg*m^2/s^2``, ``1/s^2``, ``""``."""
    up, down = [], []
    order = list(_BASE)
    for name, power in sorted(dim.powers, key=lambda kv: (order.index(kv[0])
                                                          if kv[0] in order else 99)):
        unit = _BASE.get(name, name.strip("[]"))
        p = abs(power)
        shown = unit if p == 1 else f"{unit}^{p}" if p.denominator == 1 else f"{unit}^({p})"
        (up if power > 0 else down).append(shown)
    top = "*".join(up) or ("1" if down else "")
    return top + "".join("/" + d for d in down)


def _is_zero(node) -> bool:
    return node.kind == "num" and node.value == 0.0


def infer_coordinates(coords, trees: dict, dims: dict, fixed: dict | None = None):
    """``(coordinate dims, per_mass)``: the choice of length or angle for each coordinate
    (those in ``fixed`` as given) under which ``T`` is an energy (or an energy per unit mass)
    and ``V``, ``D``, each ``Q`` fit it. ``trees`` maps ``T``, ``V``, ``D``, ``Q:x`` to
    expression trees, ``dims`` the parameters' dimensions. Refuses with the reason met for the
    first choice under which ``T`` is an energy, or ``T``'s own when there is none."""
    fixed = fixed or {}
    free = [c for c in coords if c not in fixed]
    first_error = None
    t_error = None
    for choice in itertools.product((LENGTH_DIM, PURE), repeat=len(free)):
        cdims = {**fixed, **dict(zip(free, choice))}
        names = {**dims, **cdims}
        try:
            t_dim = dimension_of(trees["T"], names, "--T")
        except DimensionError as exc:
            t_error = t_error or exc
            continue
        if t_dim == ENERGY:
            per_mass = False
        elif t_dim == ENERGY / MASS_DIM:
            per_mass = True
        else:
            t_error = t_error or InputError(
                f"--T must be an energy ([mass]*[length]^2/[time]^2) or an energy per unit "
                f"mass ([length]^2/[time]^2); got {t_dim}" + _with(cdims))
            continue
        try:
            _check_rest(trees, names, t_dim, cdims)
        except InputError as exc:
            first_error = first_error or exc
            continue
        return cdims, per_mass
    raise first_error or t_error


def _with(cdims: dict) -> str:
    if not cdims:
        return ""
    parts = [f"{c} {'an angle' if d == PURE else 'a length'}" for c, d in cdims.items()]
    return " (with " + ", ".join(parts) + ")"


def _check_rest(trees, names, t_dim, cdims) -> None:
    kind = "an energy per unit mass" if t_dim != ENERGY else "an energy"
    for key, tree in trees.items():
        if key == "T" or _is_zero(tree):
            continue
        got = dimension_of(tree, names, f"--{key.split(':')[0]}")
        if key == "V":
            want, what = t_dim, f"--V must be {kind}, like --T"
        elif key == "D":
            want, what = t_dim / TIME_DIM, (f"--D must be {kind} per unit time (a power), "
                                            "like --T over time")
        else:
            coordinate = key.split(":", 1)[1]
            want = t_dim / cdims[coordinate]
            what = (f"--Q {coordinate} must be {kind} per unit of {coordinate} (a force for a "
                    "length, a moment for an angle)")
        if got != want:
            raise InputError(f"{what}; got {got}" + _with(cdims))


def matrix_units(coords, cdims: dict, per_mass: bool, stiffness: bool) -> list[list[str]]:
    """The unit of each entry of the linearised mass (or stiffness) matrix: ``kg``,
    ``kg*m``, ``kg*m^2`` (``N/m``, ``N/rad``, ``N*m/rad`` for stiffness); per unit mass
    without ``kg``."""
    out = []
    for a in coords:
        row = []
        for b in coords:
            dim = (ENERGY / MASS_DIM if per_mass else ENERGY) / cdims[a] / cdims[b]
            if not stiffness:
                dim = dim * TIME_DIM ** 2
            text = _named(dim, per_mass, stiffness)
            angles = sum(cdims[c] == PURE for c in (a, b))
            if stiffness and angles:
                text = f"{text}/rad" if text not in ("", "1") else "1/rad"
            row.append(text)
        out.append(row)
    return out


_NAMES = {(False, "kg/s^2"): "N/m", (False, "kg*m/s^2"): "N", (False, "kg*m^2/s^2"): "N*m"}


def nice_unit(dim: Dimension) -> str:
    """SI units of ``dim`` with the derived names an engineer reads (``N/m``, ``N``)."""
    text = unit_text(dim)
    return _NAMES.get((False, text), text)


def _named(dim: Dimension, per_mass: bool, stiffness: bool) -> str:
    text = unit_text(dim)
    return _NAMES.get((per_mass, text), text)
