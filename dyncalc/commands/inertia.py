"""``inertia``: mass, centre of mass and inertia tensors of standard bodies and composites
(../shared/SPEC.md v2, "inertia").

:func:`read` reads the body words and ``--axis`` (:mod:`.inertia_read`); :func:`compute`
places each body (:func:`dyncalc.physics.inertia_tensor.placed`), sums them (holes
subtract), and gives ``m``, ``r_c``, ``J_O``, ``J_C``, the principal moments ``J_1 <= J_2 <=
J_3`` and axes, and with ``--axis`` ``J_axis`` and ``radius_of_gyration``. Products of inertia
carry the minus sign, ``J_xy = -int x y dm`` (the book's convention, Example 3.41).
"""
from __future__ import annotations

import math

from ..errors import InputError, PhysicsError
from ..lazy import numpy as np
from ..result import Result
from ..result.entries import Entry, Explanation, entry_from_parsed, format_number
from ..units import DIMENSIONLESS, INERTIA, LENGTH, MASS
from .inertia_read import DENSITY, AxisText, BodyWord, read_axis, read_bodies
from .record import Command, Parameter, ResultName

__all__ = ["COMMAND", "InertiaInputs", "read", "compute", "inertia"]

_SIGN_CONVENTION = "products of inertia off the diagonal as J_xy = -int x y dm"


class InertiaInputs:
    """The bodies as read (:class:`~.inertia_read.BodyWord`) and the ``--axis`` (or
    ``None``)."""

    __slots__ = ("bodies", "axis")

    def __init__(self, bodies: list[BodyWord], axis: AxisText | None):
        self.bodies, self.axis = bodies, axis


def read(words, axis: str | None = None, strict: bool = False) -> InertiaInputs:
    """The body words and the ``--axis`` text -> :class:`InertiaInputs`."""
    bodies = read_bodies(words, strict)
    return InertiaInputs(bodies, read_axis(axis, strict) if axis is not None else None)


def _numbers(body: BodyWord) -> dict[str, float]:
    """A body's scalar inputs in SI (``m`` or ``rho``, and its dimensions)."""
    return {key: float(p.si) for key, p in body.parsed.items() if key not in ("at", "along")}


def _place(body: BodyWord, numbers: dict[str, float]):
    """The body placed, from its SI numbers: ``(PlacedBody, mass)``."""
    from ..physics.inertia import BODY_DIMENSIONS, check_dimensions, mass_from_density
    from ..physics.inertia_tensor import placed

    dims = {d: numbers[d] for d in BODY_DIMENSIONS[body.kind]}
    check_dimensions(body.kind, dims, f"body {body.index} ({body.kind})")
    m = numbers["m"] if "m" in numbers else mass_from_density(body.kind, numbers["rho"], dims)
    if not math.isfinite(m):
        raise InputError(f"the mass of body {body.index} ({body.kind}) overflows float64")
    at = body.parsed["at"].si if "at" in body.parsed else (0.0, 0.0, 0.0)
    along = body.parsed.get("along", (0.0, 0.0, 1.0))
    return placed(body.kind, m, dims, at=at, along=along, sign=body.sign), m


def _evaluate(inputs: InertiaInputs, numbers: list[dict[str, float]]) -> dict:
    """Every result's SI value (and the placed bodies under ``"_bodies"``); overflow refused
    (PhysicsError), never warned by numpy."""
    with np.errstate(all="ignore"):
        out = _evaluate_quietly(inputs, numbers)
    if not all(np.all(np.isfinite(v)) for k, v in out.items() if not k.startswith("_")):
        from ..physics.inertia_tensor import _OVERFLOW

        raise PhysicsError(_OVERFLOW)
    return out


def _evaluate_quietly(inputs: InertiaInputs, numbers: list[dict[str, float]]) -> dict:
    from ..physics.inertia_tensor import composite, moment_about, principal

    bodies = [_place(b, n)[0] for b, n in zip(inputs.bodies, numbers)]
    total = composite(bodies)
    moments, axes = principal(total.J_C)
    moments = np.maximum(moments, 0.0)  # -1e-17: the rounding of a zero (composite() checked)
    out = {"m": float(total.m), "r_c": total.r_c + 0.0, "J_O": total.J_O + 0.0,
           "J_C": total.J_C + 0.0}
    for i in range(3):
        out[f"J_{i + 1}"] = float(moments[i])
    for i in range(3):
        out[f"axis_{i + 1}"] = axes[i]
    if inputs.axis is not None:
        J = moment_about(total.J_C, total.m, total.r_c, inputs.axis.direction,
                         inputs.axis.point)
        if J < 0.0:
            J = 0.0  # rounding of a moment that is zero (a rod about its own line)
        out["J_axis"] = J
        out["radius_of_gyration"] = math.sqrt(J / total.m)
    out["_bodies"] = bodies
    out["_total"] = total
    return out


_KINDS = {
    "m": (MASS, "m", "total mass"),
    "r_c": (LENGTH, "r_c", "centre of mass"),
    "J_O": (INERTIA, "J_O", "inertia tensor about the origin (" + _SIGN_CONVENTION + ")"),
    "J_C": (INERTIA, "J_C", "inertia tensor about the centre of mass (" + _SIGN_CONVENTION
            + ")"),
    "J_1": (INERTIA, "J_1", "smallest principal moment about the centre of mass"),
    "J_2": (INERTIA, "J_2", "middle principal moment about the centre of mass"),
    "J_3": (INERTIA, "J_3", "largest principal moment about the centre of mass"),
    "axis_1": (DIMENSIONLESS, "axis_1", "principal axis of J_1 (unit vector, its largest "
                                        "component positive)"),
    "axis_2": (DIMENSIONLESS, "axis_2", "principal axis of J_2"),
    "axis_3": (DIMENSIONLESS, "axis_3", "principal axis of J_3"),
    "J_axis": (INERTIA, "J_axis", "moment of inertia about --axis"),
    "radius_of_gyration": (LENGTH, "k", "radius of gyration about --axis, sqrt(J_axis/m)"),
}


def _input_entries(inputs: InertiaInputs) -> dict[str, Entry]:
    entries: dict[str, Entry] = {}
    for body in inputs.bodies:
        for key, parsed in body.parsed.items():
            name = f"b{body.index}.{key}"
            if key == "along":
                entries[name] = Entry(name, np.asarray(parsed, dtype=float) + 0.0,
                                      DIMENSIONLESS, text=body.along_word or "",
                                      description="direction of the body's own z axis")
                if body.along_word is None:
                    entries[name].text = _along_text(body)
            elif key == "at":
                entries[name] = Entry(name, np.asarray(parsed.si, dtype=float) + 0.0, LENGTH,
                                      unit=parsed.unit_text or LENGTH.si,
                                      assumed_si=parsed.assumed_si, text=parsed.text,
                                      description="position of the body's reference point")
                if parsed.unit_text:
                    entries[name].exact = np.asarray(parsed.quantity.magnitude, dtype=float)
            else:
                dim = MASS if key == "m" else (DENSITY[_density_kind(body)] if key == "rho"
                                               else LENGTH)
                entries[name] = entry_from_parsed(name, parsed, dim)
    if inputs.axis is not None:
        entries["axis"] = Entry("axis", inputs.axis.direction + 0.0, DIMENSIONLESS,
                                text=inputs.axis.text, description="direction of --axis")
    return entries


def _along_text(body: BodyWord) -> str:
    import re

    found = re.search(r"along\s*=\s*(\([^)]*\)|\[[^\]]*\])", body.text)
    return found.group(1) if found else "along"


def _density_kind(body: BodyWord) -> str:
    from ..physics.inertia import DENSITY_KIND

    return DENSITY_KIND[body.kind]


def compute(inputs: InertiaInputs) -> Result:
    """The composite's results (see the module docstring)."""
    numbers = [_numbers(b) for b in inputs.bodies]
    values = _evaluate(inputs, numbers)
    results: dict[str, Entry] = {}
    for name, (dim, symbol, description) in _KINDS.items():
        if name in values:
            value = values[name]
            results[name] = Entry(name, value, dim, unit=dim.si, symbol=symbol,
                                  description=description)
    result = Result(command="inertia", results=results, inputs=_input_entries(inputs),
                    model="composite" if len(inputs.bodies) > 1 else inputs.bodies[0].kind,
                    explanation=lambda: _explain(inputs, values))
    if inputs.axis is not None:
        n, total = inputs.axis.direction, values["_total"]
        with np.errstate(all="ignore"):
            centre = float(n @ total.J_C @ n)
        result.slips["J_axis"] = {
            "the parallel-axis term left out (the moment about the parallel axis through the "
            "centre of mass)": centre}
    result.sensitivity = lambda: _sensitivity(inputs, numbers, values)
    return result


def _sensitivity(inputs: InertiaInputs, numbers, values):
    """Central differences on the parsed inputs (two placements per uncertain input)."""
    from ..result.propagate import UncertainInput, central_differences

    where: list[tuple[int, str]] = []
    items: list[UncertainInput] = []
    for i, body in enumerate(inputs.bodies):
        for key, parsed in body.parsed.items():
            if key in ("at", "along") or parsed.uncertainty is None:
                continue
            where.append((i, key))
            items.append(UncertainInput(f"b{body.index}.{key}", float(parsed.si),
                                        float(parsed.uncertainty)))
    nominal = {k: v for k, v in values.items() if not k.startswith("_")}

    def rerun(index: int, offset: float):
        i, key = where[index]
        moved = [dict(n) for n in numbers]
        moved[i][key] += offset
        try:
            out = _evaluate(inputs, moved)
        except (InputError, PhysicsError, ArithmeticError, ValueError):
            return None
        return {k: np.asarray(v, dtype=float) for k, v in out.items() if not k.startswith("_")}

    return central_differences(items, nominal, rerun)


def _show(value, unit: str = "") -> str:
    text = format_number(np.asarray(value, dtype=float) + 0.0
                         if not isinstance(value, float) else value, 6)
    return f"{text} {unit}".rstrip()


def _explain(inputs: InertiaInputs, values: dict) -> Explanation:
    with np.errstate(all="ignore"):  # a parallel-axis term beyond float64 is shown as inf
        return _explain_quietly(inputs, values)


def _explain_quietly(inputs: InertiaInputs, values: dict) -> Explanation:
    from ..physics.inertia import FORMULAS

    formula = []
    for body in inputs.bodies:
        mass, moments = FORMULAS[body.kind]
        own = f"b{body.index} = {'-' if body.sign < 0 else ''}{body.kind}: {moments}"
        if "rho" in body.parsed:
            own += f"; {mass}"
        formula.append(own + " (own axes, about its centre)")
    formula += [
        "J_C,i = R_i diag(J_xx, J_yy, J_zz) R_i^T  (R_i: the body's own axes; z along along=)",
        "J_O,i = J_C,i + m_i (|c_i|^2 I - c_i c_i^T)  (parallel-axis theorem; c_i its centre)",
        "m = sum m_i,  r_c = sum m_i c_i / m,  J_O = sum J_O,i  (a hole counts negative)",
        "J_C = J_O - m (|r_c|^2 I - r_c r_c^T);  J_1 <= J_2 <= J_3, axes: eigenvectors of J_C",
    ]
    if inputs.axis is not None:
        formula.append("J_axis = n^T (J_C + m (|d|^2 I - d d^T)) n,  d = r_c - p;  "
                       "radius_of_gyration = sqrt(J_axis / m)")
    unit = INERTIA.si
    substituted = []
    for body, placed in zip(inputs.bodies, values["_bodies"]):
        sign = "-" if body.sign < 0 else ""
        substituted.append(
            f"b{body.index}: m = {sign}{_show(abs(placed.m), 'kg')}, c = {_show(placed.c, 'm')}, "
            f"J_C = {_show(placed.J_C, unit)}, m (|c|^2 I - c c^T) = "
            f"{_show(placed.steiner, unit)}, J_O = {_show(placed.J_O, unit)}")
    substituted += [f"m = {_show(values['m'], 'kg')}", f"r_c = {_show(values['r_c'], 'm')}",
                    f"J_O = {_show(values['J_O'], unit)}", f"J_C = {_show(values['J_C'], unit)}"]
    if inputs.axis is not None:
        d = values["r_c"] - inputs.axis.point
        n = inputs.axis.direction
        term = values["m"] * (float(d @ d) - float(n @ d) ** 2)
        substituted.append(f"n = {_show(n)}, p = {_show(inputs.axis.point, 'm')}, d = "
                           f"{_show(d, 'm')}: J_axis = {_show(float(n @ values['J_C'] @ n), unit)}"
                           f" + {_show(term, unit)} = {_show(values['J_axis'], unit)}")
    assumptions = ["homogeneous bodies; rod, ring, disk, plate and shells have no thickness",
                   "a negative body (a hole) lies inside the body it cuts",
                   "the tensor carries the " + _SIGN_CONVENTION + " (L = J omega)"]
    return Explanation(formula, substituted, assumptions,
                       "Gross et al., Engineering Mechanics 3, Section 3.2.3 (Table 3.1) and "
                       "Example 3.41")


def inertia(words, axis: str | None = None, strict: bool = False) -> Result:
    """The command: body words (``"rod(m=2kg, l=1m)"``) and ``--axis`` -> the Result.

    >>> r = inertia(["rod(m=3kg, l=2m, along=x, at=(1, 0, 0) m)"], axis="z")
    >>> round(r.results["J_axis"].si, 12)   # m l^2 / 3 about its end
    4.0
    """
    return compute(read(words, axis, strict))


def _run(values: dict[str, str | None], words=(), *, rtol=None, strict=False) -> Result:
    return inertia(list(words), values.get("axis"), strict)


COMMAND = Command(
    "inertia",
    "Mass, centre of mass, inertia tensors, principal axes of bodies and composites.",
    """Mass m, centre of mass r_c, the inertia tensors J_O (about the origin) and J_C (about
    the centre of mass), the principal moments J_1 <= J_2 <= J_3 and their axes, and with
    --axis the moment J_axis and radius of gyration about any axis. Products of inertia carry
    the minus sign: J_xy = -int x y dm off the diagonal (L = J omega).

    \b
    Each BODY is one of (a leading '-' cuts it out: a hole):
      rod(m=, l=)  disk(m=, r=)  ring(m=, r=)  solid-sphere(m=, r=)
      hollow-sphere(m=, r=)  solid-cylinder(m=, r=, h=)  hollow-cylinder(m=, ri=, ro=, h=)
      plate(m=, a=, b=)  half-cylinder-shell(m=, r=, h=)  point(m=)
    and may take at=(x, y, z) m (its centre; a half-cylinder shell's axis middle),
    along=x|y|z|(x, y, z) (a rod's length, the symmetry axis, a plate's normal; default z,
    a plate's a then along x), and rho= instead of m=: linear density for rod and ring,
    areal for disk, plate and the shells, volume density for the solids.

    \b
    Examples:
      dyncalc inertia "rod(m=2kg, l=1m, along=x, at=(0.5, 0, 0) m)" --axis z
      dyncalc inertia "disk(m=4kg, r=0.2m)" "-disk(m=0.25kg, r=5cm, at=(0.1, 0, 0) m)"
      dyncalc inertia "plate(rho=7.8 kg/m^2, a=0.4m, b=0.2m)" --axis "z through (0.2, 0.1, 0) m"
      dyncalc inertia "rod(m=2kg, l=2m, along=x, at=(1, 0, 0) m)" \\
          "rod(m=1kg, l=1m, at=(2, 0, 0.5) m)"                  # E3.41's bent bar, l = 1 m
    """,
    (
        Parameter("axis", None, "Axis for J_axis and the radius of gyration: x, y, z, a vector "
                  "'(1, 1, 0)', or 'z through (0.1, 0, 0) m' (default: through the origin).",
                  "AXIS", kind="text"),
    ),
    tuple(ResultName(name, symbol, dim.si, description)
          for name, (dim, symbol, description) in _KINDS.items()),
    _run,
    words="BODY...",
)
