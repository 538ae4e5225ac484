"""The ``coriolis`` results and their explanation: the result kinds with their units
(:data:`KINDS`), the entries, the lines of the terms with their numbers and why a term
vanishes, the directions on the Earth, and what a missing result needs.
"""
from __future__ import annotations

import math

from ..errors import PhysicsError
from ..lazy import numpy as np
from ..result.entries import Entry, format_number
from ..units import ACCELERATION, ANGULAR_RATE, FORCE, VELOCITY, Dim

RATE = Dim("rate", "1/[time]", "1/[time]", "1/s")

REFERENCE = ("Gross et al., Engineering Mechanics 3, Chapter 6 (relative motion): E6.6 (a point "
             "on a disk spinning on a turntable), E6.10 (a point on an eccentric platform), "
             "E6.12 (a translating frame)")

_KINDS = {  # result name -> (dim, unit, vector symbol, magnitude symbol, description)
    "a_c": (ACCELERATION, "m/s^2", "2Ω×v_r", "2Ωv_r", "Coriolis acceleration term"),
    "a_c_mag": (ACCELERATION, "m/s^2", "|a_c|", "|a_c|", "magnitude of a_c"),
    "F_c": (FORCE, "N", "-m a_c", "m a_c", "Coriolis force (apparent, in the frame)"),
    "F_c_mag": (FORCE, "N", "|F_c|", "|F_c|", "magnitude of F_c"),
    "a_euler": (ACCELERATION, "m/s^2", "α×r", "αr", "Euler term (angular acceleration)"),
    "a_centripetal": (ACCELERATION, "m/s^2", "Ω×(Ω×r)", "Ω²r", "centripetal term"),
    "a_transport": (ACCELERATION, "m/s^2", "a0+α×r+Ω×(Ω×r)", "|α×r+Ω×(Ω×r)|",
                    "transport acceleration (of the frame point)"),
    "a": (ACCELERATION, "m/s^2", "a", "|a|", "absolute acceleration"),
    "a_mag": (ACCELERATION, "m/s^2", "|a|", "|a|", "magnitude of a"),
    "a_transport_mag": (ACCELERATION, "m/s^2", "|a_transport|", "|a_transport|",
                        "magnitude of a_transport"),
    "v_transport": (VELOCITY, "m/s", "v0+Ω×r", "Ωr", "transport velocity (of the frame point)"),
    "v_transport_mag": (VELOCITY, "m/s", "|v_transport|", "|v_transport|",
                        "magnitude of v_transport"),
    "v": (VELOCITY, "m/s", "v", "|v|", "absolute velocity"),
    "v_mag": (VELOCITY, "m/s", "|v|", "|v|", "magnitude of v"),
    "Omega": (ANGULAR_RATE, "rad/s", "Ω", "Ω", "Earth's angular velocity (east, north, up)"),
    "v_r": (VELOCITY, "m/s", "v_r", "v_r", "velocity relative to the Earth (east, north, up)"),
    "coriolis_parameter": (RATE, "1/s", "2Ω sinφ", "2Ω sinφ", "Coriolis parameter f"),
    "a_c_horizontal": (ACCELERATION, "m/s^2", "a_c,h", "|a_c,h|",
                       "horizontal part of a_c (east, north, 0)"),
    "a_c_horizontal_mag": (ACCELERATION, "m/s^2", "|a_c,h|", "|a_c,h|",
                           "magnitude of a_c_horizontal"),
    "F_c_horizontal": (FORCE, "N", "F_c,h", "|F_c,h|",
                       "horizontal part of F_c (east, north, 0): the sideways push"),
    "F_c_horizontal_mag": (FORCE, "N", "|F_c,h|", "|F_c,h|", "magnitude of F_c_horizontal"),
}

_COMPASS = ["north", "north-north-east", "north-east", "east-north-east", "east",
            "east-south-east", "south-east", "south-south-east", "south", "south-south-west",
            "south-west", "west-south-west", "west", "west-north-west", "north-west",
            "north-north-west"]



def _fmt(value, unit: str = "") -> str:
    if hasattr(value, "__len__"):
        value = np.asarray(value, dtype=float) + 0.0
    elif isinstance(value, float):
        value += 0.0
    text = format_number(value, 6)
    return f"{text} {unit}" if unit else text



# --------------------------------------------------------------------------------------------
# Results


def _entry(name: str, si, vector: bool) -> Entry:
    dim, unit, vsym, ssym, description = _KINDS[name]
    if vector:
        value = np.asarray(si, dtype=float) + 0.0
    else:
        value = float(si) + 0.0
        if math.isinf(value):
            raise PhysicsError(f"{name} overflows float64 at these inputs (beyond 1.8e308 "
                               f"{unit})")
    return Entry(name, value, dim, unit=unit, symbol=vsym if vector else ssym,
                 description=description)


def _horizontal(v):
    """The east and north components of an east-north-up vector, up set to zero."""
    return np.array([float(v[0]), float(v[1]), 0.0]) + 0.0


def _mag(v) -> float:
    from ..physics.frames import magnitude

    return magnitude(v)


def _zero(v) -> bool:
    return not np.any(np.asarray(v) != 0.0)


# --------------------------------------------------------------------------------------------
# Why a term vanishes


def _why_zero(term: str, fa, form: str) -> str | None:
    """The reason the term ``term`` of ``fa`` vanishes, or ``None`` when it does not."""
    given = fa.given
    no_r = "no --r (the point is at the frame's origin)" if "r" not in given else \
        "r = 0 (the point is at the frame's origin)"
    if form == "scalar":
        no_r = ("no --r (the point is on the rotation axis)" if "r" not in given else
                "r = 0 (the point is on the rotation axis)")
    still = "alpha = 0 (the frame turns at a constant rate)"
    if term == "a0":
        if "a0" not in given:
            return "no --a0 (the frame's origin rests or moves at constant velocity)"
        return "given as zero" if _zero(fa.a0) else None
    if term == "a_euler":
        if "alpha" not in given:
            return "no --alpha (the frame turns at a constant rate)"
        if _zero(fa.alpha):
            return still
        if _zero(fa.r):
            return no_r
        if "a_euler" in fa.parallel:
            return "r is parallel to alpha"
        return None
    if term == "a_centripetal":
        if _zero(fa.Omega):
            return "Omega = 0 (the frame does not rotate)"
        if _zero(fa.r):
            return no_r
        if "a_centripetal" in fa.parallel:
            return "r lies on the rotation axis (parallel to Omega)"
        return None
    if term == "a_c":
        if _zero(fa.Omega):
            return "Omega = 0 (the frame does not rotate)"
        if _zero(fa.v_r):
            return "v_r = 0 (the point is at rest in the frame)"
        if "a_c" in fa.parallel:
            return "v_r is parallel to Omega (motion along the rotation axis)"
        return None
    if term == "a_r":
        if "a_r" not in given:
            return "no --ar (the velocity relative to the frame is constant)"
        return "given as zero" if _zero(fa.a_r) else None
    raise KeyError(term)


def _line(label: str, expression: str, value, unit: str, why: str | None) -> str:
    if why is not None:
        return f"{label} = 0: {why}"
    return f"{label} = {expression}{' = ' if expression else ''}{_fmt(value, unit)}"


def _vector_lines(fa, full: bool, mass_si: float | None, motion=None,
                  known: bool = True) -> list[str]:
    """The terms of the formula with their numbers (vectors), and which vanish and why;
    ``motion`` (a :class:`~dyncalc.physics.relative_motion.RelativeMotion`) adds the
    velocities, ``known`` is whether v_r was given."""
    om, v, r, al = (_fmt(x) for x in (fa.Omega, fa.v_r, fa.r, fa.alpha))
    lines = []
    if motion is not None:
        lines.append(f"v_transport = v0 + Omega x r = {_fmt(motion.v_transport, 'm/s')}, "
                     f"|v_transport| = {_fmt(motion.mags['v_transport_mag'], 'm/s')}")
        if known:
            lines.append(f"v = v_transport + v_r = {_fmt(motion.v, 'm/s')}, "
                         f"|v| = {_fmt(motion.mags['v_mag'], 'm/s')}")
    if known:
        lines.append(_line("2 Omega x v_r", f"2 {om} rad/s x {v} m/s", fa.a_c, "m/s^2",
                           _why_zero("a_c", fa, "vector")))
    else:
        lines.append("v, a_c = 2 Omega x v_r, a: not computed (give --vr, the velocity "
                     "relative to the frame)")
    if not full:
        lines.append("a0, alpha x r, Omega x (Omega x r), a_r: not computed (give --r, "
                     "--alpha, --a0 or --ar for the absolute acceleration a)")
    else:
        lines += [
            _line("a0", "", fa.a0, "m/s^2", _why_zero("a0", fa, "vector")),
            _line("alpha x r", f"{al} rad/s^2 x {r} m", fa.a_euler, "m/s^2",
                  _why_zero("a_euler", fa, "vector")),
            _line("Omega x (Omega x r)", f"{om} rad/s x ({om} rad/s x {r} m)",
                  fa.a_centripetal, "m/s^2", _why_zero("a_centripetal", fa, "vector")),
            _line("a_r", "", fa.a_r, "m/s^2", _why_zero("a_r", fa, "vector")),
            f"a_transport = a0 + alpha x r + Omega x (Omega x r) = "
            f"{_fmt(fa.a_transport, 'm/s^2')}",
        ]
        if known:
            lines.append(f"a = a_transport + 2 Omega x v_r + a_r = {_fmt(fa.a, 'm/s^2')}, "
                         f"|a| = {_fmt(_mag(fa.a), 'm/s^2')}")
    if fa.F_c is not None:
        lines.append(f"F_c = -m a_c = -{_fmt(mass_si, 'kg')} x {_fmt(fa.a_c, 'm/s^2')} = "
                     f"{_fmt(fa.F_c, 'N')}")
    return lines


# --------------------------------------------------------------------------------------------
# Directions on the Earth


def _compass(east: float, north: float) -> tuple[str, float]:
    bearing = math.degrees(math.atan2(east, north)) % 360.0
    return _COMPASS[round(bearing / 22.5) % 16], bearing


def _direction(v) -> str:
    """``west``, ``north and down``, ``down`` or ``none`` for an east-north-up vector."""
    east, north, up = (float(x) for x in v)
    parts = []
    if east != 0.0 or north != 0.0:
        parts.append(_compass(east, north)[0])
    if up != 0.0:
        parts.append("up" if up > 0 else "down")
    return " and ".join(parts) if parts else "none"


def _direction_line(label: str, v, unit: str, in_radians: bool = False) -> str:
    """Where ``v`` (east, north, up) points: its compass name, its bearing (an atan2 angle, in
    radians when the latitude was typed in radians, else in degrees) and its parts."""
    east, north, up = (float(x) for x in v)
    if east == 0.0 and north == 0.0 and up == 0.0:
        return f"{label} is zero"
    parts = []
    if east != 0.0 or north != 0.0:
        name, bearing = _compass(east, north)
        shown = (f"{format_number(math.radians(bearing), 4)} rad" if in_radians else
                 f"{format_number(bearing, 4)} deg")
        parts.append(f"{name} (bearing {shown}, horizontal part "
                     f"{_fmt(math.hypot(east, north), unit)})")
    if up != 0.0:
        parts.append(f"{'up' if up > 0 else 'down'} ({_fmt(abs(up), unit)})")
    return f"{label} points " + " and ".join(parts)


def _side(v_r, force) -> str:
    """Which side of the horizontal motion the horizontal force pushes."""
    turn = float(v_r[0]) * float(force[1]) - float(v_r[1]) * float(force[0])
    if (v_r[0] == 0.0 and v_r[1] == 0.0) or (force[0] == 0.0 and force[1] == 0.0):
        return ""
    if turn < 0:
        return ": to the right of the horizontal motion"
    if turn > 0:
        return ": to the left of the horizontal motion"
    return ": along the line of the horizontal motion"


def _latitude_words(degrees: float) -> str:
    if degrees == 0.0:
        return "0 deg (the equator)"
    if abs(degrees) == 90.0:
        return f"90 deg {'N (the North Pole)' if degrees > 0 else 'S (the South Pole)'}"
    return f"{format_number(abs(degrees), 6)} deg {'N' if degrees > 0 else 'S'}"


#: What each result of the vector form needs: groups of options, one of each group.
_NEEDS = {
    "a_c": (("vr",),), "F_c": (("vr",), ("mass",)), "v_transport": (("r", "v0"),),
    "v": (("vr",), ("r", "v0")), "a_transport": (("r", "alpha", "a0", "ar"),),
    "a_euler": (("r", "alpha", "a0", "ar"),), "a_centripetal": (("r", "alpha", "a0", "ar"),),
    "a": (("vr",), ("r", "alpha", "a0", "ar")),
}
_GROUP_WORDS = {
    ("vr",): "--vr (the velocity relative to the frame)", ("mass",): "--mass",
    ("r", "v0"): "--r (the position in the frame) or --v0 (the velocity of its origin)",
    ("r", "alpha", "a0", "ar"): "--r, --alpha, --a0 or --ar (the terms of the frame's motion)",
}


def _unavailable(results: dict, given) -> dict[str, str]:
    """Result name -> why it is not among ``results`` (for ``--value``, ``--check`` and
    ``--unit`` naming one): the options it needs that were not given."""
    out = {}
    for name, groups in _NEEDS.items():
        missing = [_GROUP_WORDS[g] for g in groups if not any(o in given for o in g)]
        for key in (name, name + "_mag"):
            if missing and key in _KINDS and key not in results:
                out[key] = f"{key} needs {' and '.join(missing)}"
    return out


#: The relative-motion formula in LaTeX (vectors).
VECTOR_LATEX = (
    r"\vec{a} = \vec{a}_0 + \vec{\alpha}\times\vec{r} + \vec{\Omega}\times(\vec{\Omega}\times"
    r"\vec{r}) + 2\,\vec{\Omega}\times\vec{v}_r + \vec{a}_r",
    r"\vec{a}_c = 2\,\vec{\Omega}\times\vec{v}_r, \quad \vec{F}_c = -m\,\vec{a}_c",
)

#: The magnitudes of the scalar form in LaTeX (:mod:`dyncalc.result.explain`), values in SI.
SCALAR_LATEX = (
    r"$a_c = 2\,$Omega\,$v_r",
    r"$a_euler = $alpha\,$r",
    r"$a_centripetal = $Omega^2\,$r",
    r"$a_transport = \sqrt{$a_euler^2 + $a_centripetal^2}",
    r"$F_c = $m\,$a_c",
)


def _scalar_latex(results, omega, v, r, alpha, mass):
    from ..result.explain import Term, render_formulas, symbol_latex

    given = {"Omega": (omega, "rad/s"), "v_r": (v, "m/s"), "r": (r, "m"),
             "alpha": (alpha, "rad/s^2"), "m": (None if mass is None else mass.si, "kg")}
    if r is not None or alpha is not None:
        given.update(r=(r or 0.0, "m"), alpha=(alpha or 0.0, "rad/s^2"))
    terms = {name: Term(symbol_latex(name), float(value), unit)
             for name, (value, unit) in given.items() if value is not None}
    for name, entry in results.items():
        terms[name] = Term(symbol_latex(name), float(entry.si), entry.unit)
    return render_formulas(SCALAR_LATEX, terms)


