"""The ``coriolis`` command's computation: option texts -> checked vectors -> every term of the
relative-motion formula -> a :class:`~dyncalc.result.Result`. :func:`read` parses and checks
every option once (:class:`CoriolisInputs`), :func:`compute` works on what it read;
:func:`coriolis_result` is the two in turn.

Three forms, chosen by the options given:

* **vectors** (``--omega 0,0,2rad/s --vr 3,0,0m/s``): components in the frame's axes; results
  ``a_c`` (and ``|a_c|`` as ``a_c_mag``); with ``--mass`` ``F_c = -m a_c``; when any of
  ``--r --alpha --a0 --ar`` is given, also ``a_euler = alpha x r``,
  ``a_centripetal = Omega x (Omega x r)``, ``a_transport``, the absolute ``a`` and ``a_mag``.
  Missing optional vectors are zero.
* **magnitudes** (``--omega 2rad/s --vr 3m/s``): perpendicular vectors; ``a_c = 2 Omega v_r``,
  ``F_c = m a_c``; ``--r`` is the distance from the rotation axis and ``--alpha`` turns about
  the same axis (``a_euler = alpha r``, ``a_centripetal = Omega^2 r`` and
  ``a_transport = hypot`` of the two, which are perpendicular). ``--a0`` and ``--ar`` need a
  direction and are refused; the absolute ``a`` is not given (the direction of ``v_r`` in the
  plane is not known).
* **Earth** (``--latitude``): a local east-north-up frame turning with
  ``Omega_E (0, cos phi, sin phi)``; ``--vr`` in east, north, up components, or ``--speed`` with
  ``--heading`` (compass: 0 north, 90 deg east) and ``--vertical``; ``--omega`` may only change
  the rate (a magnitude). The explanation names the directions of ``a_c`` and of the Coriolis
  force ``-m a_c``.

Uncertainties: only scalars carry one, so the uncertain inputs are the magnitudes of the scalar
form, ``--mass`` and on the Earth ``--latitude``, ``--omega``, ``--speed``, ``--heading`` and
``--vertical``. ``result.sensitivity`` gives the exact derivatives of every result with respect
to them, worked out on the values as read (:func:`_scalar_slopes`, :func:`_frame_slopes`):
nothing is parsed or computed again.
"""
from __future__ import annotations

import math
from typing import Any, Callable

from ..errors import InputError, PhysicsError
from ..lazy import numpy as np
from ..result.entries import Entry, Explanation, Result, entry_from_parsed, format_number
from .coriolis_time import TIME_KINDS
from .record import Command, Parameter, ResultName
from ..units import (ACCELERATION, ANGLE, ANGULAR_ACCELERATION, ANGULAR_RATE, FORCE, LENGTH,
                    MASS, TIME, VELOCITY, Dim, Parsed, format_quantity, parse_quantity,
                    parse_vector)

__all__ = ["COMMAND", "coriolis_result", "OPTIONS", "read", "compute", "CoriolisInputs"]

#: Option name -> (dimension, description).
OPTIONS = {
    "omega": (ANGULAR_RATE, "angular velocity of the frame"),
    "vr": (VELOCITY, "velocity relative to the frame"),
    "r": (LENGTH, "position in the frame"),
    "alpha": (ANGULAR_ACCELERATION, "angular acceleration of the frame"),
    "v0": (VELOCITY, "velocity of the frame's origin"),
    "a0": (ACCELERATION, "acceleration of the frame's origin"),
    "ar": (ACCELERATION, "acceleration relative to the frame"),
    "mass": (MASS, "mass"),
    "latitude": (ANGLE, "latitude"),
    "speed": (VELOCITY, "horizontal speed"),
    "heading": (ANGLE, "compass heading (0 north, 90 deg east)"),
    "vertical": (VELOCITY, "vertical speed (positive up)"),
}

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


# --------------------------------------------------------------------------------------------
# Reading the options


def _fmt(value, unit: str = "") -> str:
    if hasattr(value, "__len__"):
        value = np.asarray(value, dtype=float) + 0.0
    elif isinstance(value, float):
        value += 0.0
    text = format_number(value, 6)
    return f"{text} {unit}" if unit else text


def _is_vector(parsed: Parsed) -> bool:
    return bool(np.ndim(parsed.si))


def _input_entry(name: str, parsed: Parsed, dim: Dim, description: str) -> Entry:
    if _is_vector(parsed):
        return Entry(name, np.asarray(parsed.si, dtype=float) + 0.0, dim,
                     unit=parsed.unit_text or dim.si, assumed_si=parsed.assumed_si,
                     description=description, text=parsed.text)
    return entry_from_parsed(name, parsed, dim, description=description)


class CoriolisInputs:
    """The ``coriolis`` options as :func:`read` found them, every one parsed and checked: what
    :func:`compute` needs, and nothing typed is read again after this.

    ``form`` is ``"vectors"``, ``"scalar"`` (magnitudes) or ``"earth"``; ``parsed`` maps each
    option given to its :class:`~dyncalc.units.Parsed` (SI in ``.si``: a float, or an array of
    3 for a vector); ``entries`` are the input entries in the order read; ``warnings`` what
    reading noticed (a bare latitude or heading in radians); ``degrees`` the latitude in
    degrees (Earth mode, else ``None``).
    """

    __slots__ = ("form", "parsed", "entries", "warnings", "degrees")

    def __init__(self, form: str, parsed: dict[str, Parsed], entries: dict[str, Entry],
                 warnings: list[str] | None = None, degrees: float | None = None):
        self.form, self.parsed, self.entries = form, parsed, entries
        self.warnings = [] if warnings is None else warnings
        self.degrees = degrees

    def si(self, name: str):
        """The SI value of option ``name``, ``None`` when it was not given."""
        parsed = self.parsed.get(name)
        return None if parsed is None else parsed.si

    def __repr__(self) -> str:
        return f"CoriolisInputs({self.form!r}, {list(self.parsed)})"


class _Reader:
    """Parses the option texts, remembering the parsed values and the input entries in the
    order read."""

    def __init__(self, texts: dict[str, str], strict: bool, params: dict | None = None):
        self.texts, self.strict = texts, strict
        self.params = params or {}
        self.inputs: dict[str, Entry] = {}
        self.parsed: dict[str, Parsed] = {}

    def vector(self, name: str) -> Parsed | None:
        from ..units.vector_expression import needs_expressions, parse_vector_expression

        text = self.texts.get(name)
        if text is None:
            return None
        dim, description = OPTIONS[name]
        if needs_expressions(text, self.params):
            parsed = parse_vector_expression(text, dim, label=f"--{name}", params=self.params,
                                             strict=self.strict)
        else:
            parsed = parse_vector(text, dim, label=f"--{name}", allow_scalar=True,
                                  strict=self.strict)
        self.inputs[name] = _input_entry(name, parsed, dim, description)
        self.parsed[name] = parsed
        return parsed

    def scalar(self, name: str, constraint: str | None = None) -> Parsed | None:
        text = self.texts.get(name)
        if text is None:
            return None
        dim, description = OPTIONS[name]
        parsed = parse_quantity(text, dim, label=f"--{name}", strict=self.strict,
                                constraint=constraint)
        self.inputs[name] = entry_from_parsed(name, parsed, dim, description=description)
        self.parsed[name] = parsed
        return parsed

    def done(self, form: str, warnings: list[str] | None = None,
             degrees: float | None = None) -> CoriolisInputs:
        return CoriolisInputs(form, self.parsed, self.inputs, warnings, degrees)


def _words(text: str) -> set[str]:
    import re

    return set(re.findall(r"[A-Za-z_][A-Za-z_0-9]*", text))


def _refuse_negative(name: str, parsed: Parsed) -> None:
    if parsed.si < 0:
        raise InputError(f"--{name} as a scalar is a magnitude and must not be negative; got "
                         f"{format_quantity(parsed.quantity)} (give a vector for a direction)")


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


# --------------------------------------------------------------------------------------------
# Reading: every option parsed and checked once


def coriolis_result(texts: dict[str, str | None], words=(), *,
                    strict: bool = False) -> Result:
    """Compute the ``coriolis`` command from the option texts (``{"omega": "0,0,2 rad/s",
    "vr": "3,0,0 m/s"}``; keys are the option names of :data:`OPTIONS`, ``None`` = not given):
    :func:`read`, then :func:`compute`.

    Raises :class:`~dyncalc.errors.InputError` with a message saying what to change.

    >>> res = coriolis_result({"omega": "2 rad/s", "vr": "3 m/s"})
    >>> res.results["a_c"].si, res.results["a_c"].unit
    (12.0, 'm/s^2')
    """
    solved = _inverse(texts, words, strict)
    if solved is not None:
        return solved
    return compute(read(texts, strict, words))


#: Options an inverse problem reads, by set-up: option -> the scene parameter it gives.
_INVERSE_OPTIONS = {"perpendicular": {"omega": "omega", "vr": "vr", "mass": "mass"},
                    "earth": {"latitude": "latitude", "vr": "vr", "speed": "vr",
                              "heading": "heading", "omega": "omega", "mass": "mass"}}


def _inverse(texts: dict[str, str | None], words, strict: bool) -> Result | None:
    """A scalar inverse problem (``a_c=12m/s^2 --omega 2rad/s vr=?``,
    ``a_c_mag=0.01m/s^2 --latitude 45deg vr=?``) solved through
    :func:`dyncalc.scenes.inverse.solve`, or ``None`` when the words pose none."""
    if not words:
        return None
    from ..result.checks import split_assignment
    from ..scenes.coriolis_scalar import EARTH, PERPENDICULAR, TARGETS

    pairs = [split_assignment(word, "a parameter") for word in words]
    every = {n for names in TARGETS.values() for n in names}
    if not any(name in every or text.strip() == "?" for name, text in pairs):
        return None
    earthly = ("latitude", "speed", "heading")
    form = ("earth" if any(texts.get(n) is not None for n in earthly)
            or any(name in earthly for name, _text in pairs) else "perpendicular")
    scene = EARTH if form == "earth" else PERPENDICULAR
    allowed = _INVERSE_OPTIONS[form]
    scene_texts: dict[str, str] = {}
    labels: dict[str, str] = {}
    for option, text in texts.items():
        if text is None:
            continue
        if option not in allowed:
            raise InputError(f"--{option} does not go with an inverse problem: coriolis "
                             f"solves {scene.formula} for one unknown from "
                             f"{', '.join(p.name for p in scene.params)}")
        if form == "perpendicular" and "," in text:
            raise InputError(f"--{option}: an inverse problem takes magnitudes (perpendicular "
                             "vectors), e.g. --omega 2rad/s; give vectors to compute forward")
        name = allowed[option]
        if name in scene_texts:
            raise InputError("give --vr or --speed, not both")
        scene_texts[name], labels[name] = text, f"--{option}"
    if not any(name in every for name, _text in pairs):
        asked = next(name for name, text in pairs if text.strip() == "?")
        raise InputError(f"{asked}=? needs a result to solve from: one of "
                         f"{', '.join(TARGETS[form])}, e.g. {TARGETS[form][0]}=0.01m/s^2")
    for name, text in pairs:
        if name in every and name not in TARGETS[form]:
            other = ("--latitude" if form == "perpendicular" else "magnitudes without "
                     "--latitude")
            raise InputError(f"{name}= is not a result of this form: with "
                             f"{'magnitudes' if form == 'perpendicular' else '--latitude'} "
                             f"give one of {', '.join(TARGETS[form])} (or use {other})")
        if name in scene_texts:
            raise InputError(f"{name} is given twice ({labels[name]} and {name}=)")
        scene_texts[name], labels[name] = text, f"{name}="
    from ..scenes.inverse import solve

    return solve(scene, scene_texts, labels=labels, method=None, rtol=None, strict=strict,
                 command="coriolis")


def read(texts: dict[str, str | None], strict: bool = False, words=()) -> CoriolisInputs:
    """The option texts -> :class:`CoriolisInputs`: every quantity and vector parsed and
    checked once, the form (vectors, magnitudes, Earth) chosen by the options given.

    Raises :class:`~dyncalc.errors.InputError` with a message saying what to change.
    """
    texts = {k: v for k, v in texts.items() if v is not None}
    unknown = set(texts) - set(OPTIONS)
    if unknown:
        raise InputError(f"coriolis has no option --{sorted(unknown)[0]}")
    params = _parameters(texts, words)
    if "latitude" in texts:
        return _read_earth(_Reader(texts, strict, params))
    for name in ("speed", "heading", "vertical"):
        if name in texts:
            raise InputError(f"--{name} describes motion over the Earth and needs --latitude; "
                             "in a machine frame give --vr (3 components)")
    if "omega" not in texts:
        raise InputError("--omega is missing: give the frame's angular velocity, e.g. --omega "
                         "'0,0,2 rad/s' ('0,0,0 rad/s' for a frame that only translates), or "
                         "--latitude for the rotating Earth")
    if "vr" not in texts and "r" not in texts and "v0" not in texts:
        raise InputError("--vr is missing: give the velocity relative to the frame, e.g. --vr "
                         "'3,0,0 m/s' (or a magnitude such as '3 m/s' with a magnitude --omega),"
                         " or --r for the velocity and acceleration of the frame point")
    reader = _Reader(texts, strict, params)
    omega = reader.vector("omega")
    if _is_vector(omega):
        return _read_vectors(reader)
    return _read_scalars(reader, omega)


def _parameters(texts: dict[str, str], words) -> dict:
    """The ``NAME=QUANTITY`` words: an option's name (``omega=...``) joins ``texts``; any
    other name is a parameter of the component expressions (``l=2m`` for
    ``--r "l*cos(30deg), l*sin(30deg), 0"``): name -> (SI value, dimension, reading)."""
    if not words:
        return {}
    from ..result.checks import split_assignment
    from ..units.vector_expression import read_parameters

    given: dict[str, str] = {}
    for word in words:
        name, text = split_assignment(word, "a parameter")
        if name in texts or name in given:
            where = f"--{name} and {name}=" if name in texts else f"{name}= twice"
            raise InputError(f"{name} is given twice ({where})")
        if name in OPTIONS:
            texts[name] = text
        else:
            given[name] = text
    for name in given:
        if not any(name in _words(text) for option, text in texts.items()
                   if OPTIONS[option][1] and option not in _SCALARS):
            raise InputError(f"{name}= is used by no vector component: a parameter names a "
                             "quantity inside the components of --r, --vr, --omega, ... "
                             "(--r \"l*cos(30deg), l*sin(30deg), 0\" l=2m)")
    return read_parameters(given)


#: Options that are never vectors (a NAME= parameter is not used in them).
_SCALARS = ("mass", "latitude", "speed", "heading", "vertical")


def _read_vectors(reader: _Reader) -> CoriolisInputs:
    for name in ("vr", "r", "v0", "alpha", "a0", "ar"):
        p = reader.vector(name)
        if p is not None and not _is_vector(p):
            dim = OPTIONS[name][0]
            raise InputError(f"--{name} is a magnitude but --omega is a vector; give --{name} "
                             f"with 3 components too, e.g. '1,0,0 {dim.si}' (or every input "
                             "as a magnitude: the scalar form)")
    reader.scalar("mass", "positive")
    return reader.done("vectors")


def _read_scalars(reader: _Reader, omega: Parsed) -> CoriolisInputs:
    _refuse_negative("omega", omega)
    for name in ("vr", "r", "alpha"):
        p = reader.vector(name)
        if p is None:
            continue
        if _is_vector(p):
            raise InputError(f"--{name} is a vector but --omega is a magnitude; give both with "
                             "3 components (e.g. --omega '0,0,2 rad/s') or both as magnitudes "
                             "(the scalar form: perpendicular vectors)")
        _refuse_negative(name, p)
    if "vr" not in reader.texts:
        raise InputError("--vr is missing: the scalar form (a magnitude --omega) gives "
                         "a_c = 2 Omega v_r; give --vr as a magnitude, e.g. --vr '3 m/s' (or "
                         "vectors for the velocities of the frame point)")
    for name in ("v0", "a0", "ar"):
        if name in reader.texts:
            raise InputError(f"--{name} needs a direction: give --omega, --vr and --{name} as "
                             "vectors (3 components, e.g. --omega '0,0,2 rad/s'); the scalar "
                             "form takes only --omega, --vr, --r (distance from the axis), "
                             "--alpha and --mass")
    reader.scalar("mass", "positive")
    return reader.done("scalar")


def _read_earth(reader: _Reader) -> CoriolisInputs:
    texts = reader.texts
    warnings: list[str] = []
    latitude = reader.scalar("latitude")
    degrees = float(latitude.quantity.to("degree").magnitude)
    if not -90.0 <= degrees <= 90.0:
        hint = (f" (a bare number is read in radians; write {latitude.text.strip()}deg for "
                "degrees)" if latitude.assumed_si else "")
        raise InputError(f"--latitude must be between -90 deg and 90 deg; got "
                         f"{format_quantity(latitude.quantity)}{hint}")
    if latitude.assumed_si and degrees != 0.0:
        warnings.append(f"--latitude {latitude.text.strip()} has no unit and is read in radians "
                        f"({format_number(degrees, 6)} deg); write {latitude.text.strip()}deg "
                        "for degrees")

    if "omega" in texts:
        omega = reader.vector("omega")
        if _is_vector(omega):
            raise InputError("--omega with --latitude is the rotation rate only, a magnitude "
                             "such as '7.2921159e-5 rad/s'; its direction follows from the "
                             "latitude (for a vector --omega leave out --latitude)")
        _refuse_negative("omega", omega)

    motion = [n for n in ("speed", "heading", "vertical") if n in texts]
    if "vr" in texts and motion:
        raise InputError(f"give --vr or --{motion[0]}, not both: --speed, --heading and "
                         "--vertical are another way to give v_r")
    if "vr" in texts:
        vr = reader.vector("vr")
        if not _is_vector(vr):
            raise InputError("--vr with --latitude is a vector of east, north, up components, "
                             "e.g. --vr '0,20,0 m/s' for 20 m/s northward (or give --speed "
                             "with --heading)")
    elif motion:
        if ("speed" in texts) != ("heading" in texts):
            raise InputError("--speed and --heading go together: the horizontal speed and its "
                             "compass direction (0 = north, 90deg = east)")
        reader.scalar("speed", "nonnegative")
        heading = reader.scalar("heading")
        reader.scalar("vertical")
        if heading is not None and heading.assumed_si and heading.si != 0.0:
            warnings.append(f"--heading {heading.text.strip()} has no unit and is read in "
                            f"radians; write {heading.text.strip()}deg for compass degrees")
    else:
        raise InputError("--vr is missing: give the velocity relative to the Earth as east, "
                         "north, up components, e.g. --vr '0,20,0 m/s', or --speed with "
                         "--heading")

    for name in ("r", "v0", "alpha", "a0", "ar"):
        p = reader.vector(name)
        if p is not None and not _is_vector(p):
            raise InputError(f"--{name} with --latitude is a vector of east, north, up "
                             f"components, e.g. '0,0,1 {OPTIONS[name][0].si}'")
    reader.scalar("mass", "positive")
    return reader.done("earth", warnings, degrees)


# --------------------------------------------------------------------------------------------
# Computing: the three forms


def compute(inputs: CoriolisInputs) -> Result:
    """The Result of the options read by :func:`read`, in their form (vectors, magnitudes or
    Earth), with ``sensitivity``: the exact derivatives of its results with respect to its
    uncertain inputs (:func:`_sensitivity`)."""
    if inputs.form == "earth":
        return _earth(inputs)
    if inputs.form == "vectors":
        return _vectors(inputs)
    return _scalars(inputs)


def _vectors(inputs: CoriolisInputs) -> Result:
    return _compute(inputs, inputs.si("omega"), inputs.si("vr"), model="vectors")


def _compute(inputs: CoriolisInputs, Omega, v_r, *, model: str, earth: dict | None = None,
             moves: Callable[[], dict] | None = None) -> Result:
    """Every term of the vector formula for ``Omega`` (rad/s) and ``v_r`` (m/s), 3 components
    each; ``r``, ``alpha``, ``a0``, ``ar`` and ``mass`` as read (vectors and Earth mode).
    ``moves()`` gives how each uncertain input other than the mass moves ``Omega`` and ``v_r``
    (:func:`_frame_slopes`)."""
    from ..physics.relative_motion import relative_motion

    si = inputs.si
    mass = inputs.parsed.get("mass")
    motion = relative_motion(Omega, si("r"), v_r=v_r, v0=si("v0"), alpha=si("alpha"),
                             a0=si("a0"), a_r=si("ar"), m=None if mass is None else mass.si)
    fa = motion.accel
    full = any(n in inputs.parsed for n in ("r", "alpha", "a0", "ar"))
    moving = any(n in inputs.parsed for n in ("r", "v0"))
    known = v_r is not None

    results: dict[str, Entry] = {}
    if known:
        results["a_c"] = _entry("a_c", fa.a_c, True)
        results["a_c_mag"] = _entry("a_c_mag", _mag(fa.a_c), False)
    if fa.F_c is not None:
        results["F_c"] = _entry("F_c", fa.F_c, True)
        results["F_c_mag"] = _entry("F_c_mag", _mag(fa.F_c), False)
    if full:
        for name in ("a_euler", "a_centripetal", "a_transport"):
            results[name] = _entry(name, getattr(fa, name), True)
        if known:
            results["a"] = _entry("a", fa.a, True)
            results["a_mag"] = _entry("a_mag", _mag(fa.a), False)
        results["a_transport_mag"] = _entry("a_transport_mag", _mag(fa.a_transport), False)
    if moving:
        results["v_transport"] = _entry("v_transport", motion.v_transport, True)
        results["v_transport_mag"] = _entry("v_transport_mag",
                                            motion.mags["v_transport_mag"], False)
        if known:
            results["v"] = _entry("v", motion.v, True)
            results["v_mag"] = _entry("v_mag", motion.mags["v_mag"], False)

    substituted = []
    assumptions = []
    extra = {}
    if earth is None:
        substituted.append(f"Omega = {_fmt(fa.Omega, 'rad/s')}"
                           + (f", v_r = {_fmt(fa.v_r, 'm/s')}" if known else "")
                           + (f", r = {_fmt(fa.r, 'm')}" if "r" in fa.given else ""))
        assumptions.append("a rigid frame turning with Omega (and alpha) whose origin "
                           "accelerates with a0; r, v_r and a_r are measured in the frame; all "
                           "vectors are components in the frame's axes at this instant (SI)")
    else:
        results["Omega"] = _entry("Omega", fa.Omega, True)
        if earth["derived_v"]:
            results["v_r"] = _entry("v_r", fa.v_r, True)
        results["coriolis_parameter"] = _entry("coriolis_parameter", 2.0 * float(fa.Omega[2]),
                                               False)
        for name, vector in (("a_c", fa.a_c), ("F_c", fa.F_c)):
            if vector is not None:
                flat = _horizontal(vector)
                results[name + "_horizontal"] = _entry(name + "_horizontal", flat, True)
                results[name + "_horizontal_mag"] = _entry(name + "_horizontal_mag",
                                                           _mag(flat), False)
        substituted += earth["lines"]
        assumptions += earth["assumptions"]
    substituted += _vector_lines(fa, full, None if mass is None else mass.si,
                                 motion if moving else None, known)
    assumptions.append("a_c = 2 Omega x v_r is the Coriolis term of the absolute acceleration; "
                       "an observer in the frame sees the Coriolis force F_c = -m a_c, opposite "
                       "to a_c")
    if earth is not None:
        force = -fa.a_c + 0.0
        latitude = inputs.parsed.get("latitude")
        radians = latitude is not None and (latitude.assumed_si or latitude.unit_text.strip()
                                            in ("rad", "radian", "radians"))
        substituted.append(_direction_line("a_c", fa.a_c, "m/s^2", radians))
        if fa.F_c is None:
            line = _direction_line("the Coriolis force F_c = -m a_c", force, "N/kg", radians)
        else:
            line = _direction_line("the Coriolis force F_c = -m a_c", fa.F_c, "N", radians)
        substituted.append(line + _side(fa.v_r, force))
        extra = {"frame": "east-north-up",
                 "directions": {"a_c": _direction(fa.a_c), "F_c": _direction(force)}}
    explanation = Explanation(
        formula=["a = a0 + alpha x r + Omega x (Omega x r) + 2 Omega x v_r + a_r",
                 "a_transport = a0 + alpha x r + Omega x (Omega x r), a_c = 2 Omega x v_r, "
                 "F_c = -m a_c"] + (["v = v_transport + v_r, v_transport = v0 + Omega x r"]
                                    if moving else []),
        substituted=substituted, assumptions=assumptions, reference=REFERENCE,
        latex=list(VECTOR_LATEX))
    result = Result(command="coriolis", results=results, inputs=dict(inputs.entries),
                    model=model, method="closed-form",
                    warnings=list(earth["warnings"] if earth else []) + fa.warnings,
                    explanation=explanation, extra=extra)
    result.unavailable = _unavailable(results, set(inputs.parsed) | (
        {"vr"} if known else set()))
    m = None if mass is None else float(mass.si)

    def slopes_of():
        found = {} if moves is None else moves()
        return lambda name: _frame_slopes(fa, m, found.get(name, _MASS if name == "mass"
                                                            else _STILL),
                                          motion.v_transport, motion.v)

    result.sensitivity = lambda: _sensitivity(inputs, result, slopes_of())
    return result


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


def _scalars(inputs: CoriolisInputs) -> Result:
    from ..physics.frames import relative_acceleration

    mass = inputs.parsed.get("mass")
    Om, v = inputs.si("omega"), inputs.si("vr")
    r, al = inputs.si("r"), inputs.si("alpha")
    # perpendicular vectors: Omega and alpha along z, r radial along x, v_r along y
    fa = relative_acceleration([0.0, 0.0, Om], [0.0, v, 0.0],
                               r=None if r is None else [r, 0.0, 0.0],
                               alpha=None if al is None else [0.0, 0.0, al],
                               m=None if mass is None else mass.si)
    full = r is not None or al is not None

    results = {"a_c": _entry("a_c", _mag(fa.a_c), False)}
    if fa.F_c is not None:
        results["F_c"] = _entry("F_c", _mag(fa.F_c), False)
    if full:
        for name in ("a_euler", "a_centripetal", "a_transport"):
            results[name] = _entry(name, _mag(getattr(fa, name)), False)

    def why(term):
        return _why_zero(term, fa, "scalar")

    lines = [_line("a_c", f"2 Omega v_r = 2 x {_fmt(Om, 'rad/s')} x {_fmt(v, 'm/s')}",
                   results["a_c"].si, "m/s^2", why("a_c"))]
    if full:
        rr = 0.0 if r is None else r
        aa = 0.0 if al is None else al
        lines += [
            _line("a_euler", f"alpha r = {_fmt(aa, 'rad/s^2')} x {_fmt(rr, 'm')}",
                  results["a_euler"].si, "m/s^2", why("a_euler")),
            _line("a_centripetal", f"Omega^2 r = ({_fmt(Om, 'rad/s')})^2 x {_fmt(rr, 'm')}",
                  results["a_centripetal"].si, "m/s^2", why("a_centripetal")),
            f"a_transport = sqrt((alpha r)^2 + (Omega^2 r)^2) = "
            f"{_fmt(results['a_transport'].si, 'm/s^2')} (the two are perpendicular; a0 = 0)",
            "a (absolute): not computed in the scalar form: the direction of v_r relative to r "
            "is not known; give vectors",
        ]
    else:
        lines.append("a0, alpha x r, Omega x (Omega x r), a_r: not computed (give --r and "
                     "--alpha for the transport terms, or vectors for the absolute "
                     "acceleration)")
    if fa.F_c is not None:
        lines.append(f"F_c = m a_c = {_fmt(mass.si, 'kg')} x {_fmt(results['a_c'].si, 'm/s^2')}"
                     f" = {_fmt(results['F_c'].si, 'N')} (directed opposite to a_c)")
    latex, latex_substituted, _text = _scalar_latex(results, Om, v, r, al, mass)
    explanation = Explanation(
        latex=latex, latex_substituted=latex_substituted,
        formula=["|a_c| = 2 Omega v_r (Omega perpendicular to v_r)",
                 "|alpha x r| = alpha r, |Omega x (Omega x r)| = Omega^2 r (r perpendicular to "
                 "the axis), |F_c| = m |a_c|"],
        substituted=lines,
        assumptions=["scalars are magnitudes of perpendicular vectors: v_r perpendicular to "
                     "Omega; --r is the distance from the rotation axis and --alpha turns about "
                     "the same axis; for other angles give vectors (3 components)",
                     "a_c = 2 Omega x v_r is the Coriolis term of the absolute acceleration; "
                     "the Coriolis force F_c = -m a_c is opposite to it"],
        reference=REFERENCE)
    result = Result(command="coriolis", results=results, inputs=dict(inputs.entries),
                    model="magnitudes (perpendicular vectors)", method="closed-form",
                    warnings=list(fa.warnings), explanation=explanation)
    m = None if mass is None else float(mass.si)
    result.sensitivity = lambda: _sensitivity(
        inputs, result, lambda name: _scalar_slopes(name, Om, v, r or 0.0, al or 0.0, m,
                                                    results["a_c"].si))
    return result


def _earth(inputs: CoriolisInputs) -> Result:
    from ..physics.frames import EARTH_RATE, earth_angular_velocity, enu_velocity

    latitude, degrees = inputs.parsed["latitude"], inputs.degrees
    rate_text = "Omega_E = 7.2921159e-05 rad/s (the Earth's sidereal rate)"
    rate = EARTH_RATE
    if "omega" in inputs.parsed:
        rate = inputs.si("omega")
        rate_text = f"Omega_E = {_fmt(rate, 'rad/s')} (given by --omega)"
    derived = "vr" not in inputs.parsed
    if derived:
        speed, heading = inputs.parsed.get("speed"), inputs.parsed.get("heading")
        vertical = inputs.si("vertical")
        v_r = enu_velocity(0.0 if speed is None else speed.quantity,
                           0.0 if heading is None else heading.quantity,
                           0.0 if vertical is None else vertical)
    else:
        v_r = inputs.si("vr")

    Omega = earth_angular_velocity(latitude.quantity, rate)
    lines = [f"latitude phi = {_latitude_words(degrees)}; axes x east, y north, z up",
             f"Omega = Omega_E (0, cos phi, sin phi) = {_fmt(Omega, 'rad/s')}, "
             f"{rate_text}"]
    if derived:
        lines.append(f"v_r = (speed sin heading, speed cos heading, vertical) = "
                     f"{_fmt(v_r, 'm/s')}")
    else:
        lines.append(f"v_r = {_fmt(v_r, 'm/s')}")
    hemisphere = ("northern" if degrees > 0 else "southern" if degrees < 0 else "")
    assumptions = ["a local frame fixed to the Earth's surface: x east, y north, z up; it "
                   "turns with Omega = Omega_E (0, cos phi, sin phi)",
                   "horizontal motion is deflected to the right in the northern hemisphere "
                   "and to the left in the southern" + (f" (here: {hemisphere})" if hemisphere
                                                         else " (here: the equator, no "
                                                              "horizontal deflection of "
                                                              "horizontal motion)")]
    if "r" not in inputs.parsed:
        assumptions.append("the centrifugal effect of the Earth's spin is part of the measured "
                           "g; only the Coriolis term is computed")
    earth = {"lines": lines, "assumptions": assumptions, "warnings": inputs.warnings,
             "derived_v": derived}
    return _compute(inputs, Omega, v_r, model="Earth, east-north-up", earth=earth,
                    moves=lambda: _earth_moves(inputs, rate))


# --------------------------------------------------------------------------------------------
# Whole columns at once (batch)


def columns(given: dict, settings: dict):
    """The results of a block of batch rows at once, or ``None`` when not vectorised here.

    ``given`` maps the columns the block gives (the record's input names: ``omega``, ``vr``,
    ``r``, ``v0``, ``alpha``, ``a0``, ``ar``, ``mass``) to SI arrays, ``(n, 3)`` for
    vectors and ``(n,)`` for magnitudes and the mass; ``settings`` is not used. The vector
    form and the magnitudes form are vectorised through the kernel of
    :func:`~dyncalc.physics.frames.relative_acceleration` (the velocities through that of
    :func:`~dyncalc.physics.relative_motion.transport_velocity`), magnitudes by the twin of
    ``math.hypot`` (:func:`~dyncalc.physics.numerics_arrays.hypot_rows`); the Earth form
    (``latitude``, ``speed``, ...) and mixed or missing inputs give ``None``. Exact where the
    one-off gives these values with no warning and no refusal (a term or magnitude beyond
    float64, an underflow to zero, a negative magnitude).
    """
    from ..physics.columns import Columns
    from ..physics.frames import relative_acceleration
    from ..physics.numerics_arrays import hypot_rows

    from ..physics.relative_motion import transport_velocity

    keys = set(given)
    if ("omega" not in keys or not keys & {"vr", "r", "v0"}
            or keys - {"omega", "vr", "r", "v0", "alpha", "a0", "ar", "mass"}):
        return None
    arrays = {name: np.asarray(value, dtype=float) for name, value in given.items()}
    vectors = arrays["omega"].ndim == 2
    if not vectors and ("vr" not in keys or "v0" in keys):
        return None
    shapes = {name: value.ndim for name, value in arrays.items() if name != "mass"}
    if set(shapes.values()) != {2 if vectors else 1} or arrays.get("mass", np.ones(1)).ndim != 1:
        return None
    mass = arrays.get("mass")
    ok = np.ones(len(arrays["omega"]), dtype=bool)
    for value in arrays.values():
        ok &= np.isfinite(value) if value.ndim == 1 else np.all(np.isfinite(value), axis=1)
    if mass is not None:
        ok &= mass > 0.0

    def magnitude(vector):
        value, fine = hypot_rows(vector[:, 0], vector[:, 1], vector[:, 2])
        nonlocal ok
        ok &= fine & np.isfinite(value)
        return value + 0.0

    if vectors:
        known = "vr" in keys
        omega, vr = arrays["omega"], arrays.get("vr")
        out = relative_acceleration.columns(omega, vr if known else np.zeros_like(omega),
                                            r=arrays.get("r"), alpha=arrays.get("alpha"),
                                            a0=arrays.get("a0"), a_r=arrays.get("ar"),
                                            m=mass if known else None)
        terms = out.values
        exact = out.exact
        values = {}
        if known:
            values.update(a_c=terms["a_c"], a_c_mag=magnitude(terms["a_c"]))
            if mass is not None:
                values.update(F_c=terms["F_c"], F_c_mag=magnitude(terms["F_c"]))
        if keys & {"r", "alpha", "a0", "ar"}:
            for name in ("a_euler", "a_centripetal", "a_transport"):
                values[name] = terms[name]
            if known:
                values.update(a=terms["a"], a_mag=magnitude(terms["a"]))
            values["a_transport_mag"] = magnitude(terms["a_transport"])
        if keys & {"r", "v0"}:
            r = arrays["r"] if "r" in keys else np.zeros_like(omega)
            v_t = transport_velocity.columns(omega, r, v0=arrays.get("v0"))
            values.update(v_transport=v_t.values["v"],
                          v_transport_mag=magnitude(v_t.values["v"]))
            exact = exact & v_t.exact
            if known:
                v = transport_velocity.columns(omega, r, v0=arrays.get("v0"), v_r=vr)
                values.update(v=v.values["v"], v_mag=magnitude(v.values["v"]))
                exact = exact & v.exact
        return Columns(values, exact=exact & ok, model="vectors")
    if keys & {"a0", "ar"}:
        return None
    for value in arrays.values():
        ok &= value >= 0.0
    zero = np.zeros(len(ok))

    def along(axis: int, value):
        vector = np.zeros((len(ok), 3))
        vector[:, axis] = value
        return vector

    r, alpha = arrays.get("r"), arrays.get("alpha")
    out = relative_acceleration.columns(
        np.stack([zero, zero, arrays["omega"]], axis=1), along(1, arrays["vr"]),
        r=None if r is None else along(0, r), alpha=None if alpha is None else along(2, alpha),
        m=mass)
    terms = out.values
    values = {"a_c": magnitude(terms["a_c"])}
    if mass is not None:
        values["F_c"] = magnitude(terms["F_c"])
    if r is not None or alpha is not None:
        for name in ("a_euler", "a_centripetal", "a_transport"):
            values[name] = magnitude(terms[name])
    return Columns(values, exact=out.exact & ok, model="magnitudes (perpendicular vectors)")


# --------------------------------------------------------------------------------------------
# Derivatives for the propagation of uncertainties (exact: the formulas are closed)
#
# Only scalars carry an uncertainty (a vector cannot: parse_vector reads none), so the
# uncertain inputs are the magnitudes of the scalar form, --mass and, on the Earth, --latitude,
# --omega (the rate), --speed, --heading and --vertical. Their slopes are worked out by hand on
# the values as read; nothing is parsed or computed again.

#: How an input moves (dOmega, dv_r, dm, side; ``None`` = not at all): the mass only scales
#: F_c; an input that moves neither Omega nor v_r nor m (no slope).
_MASS = (None, None, 1.0, 0)
_STILL = (None, None, 0.0, 0)


def _sensitivity(inputs: CoriolisInputs, result: Result, slopes: Callable[[str], dict]):
    """The :class:`~dyncalc.result.propagate.Sensitivity` of ``result``: its uncertain inputs
    in the order read, named by their options (``omega``, ``vr``, ``latitude`` ...), and
    ``slopes(name)`` (result name -> d result / d input, SI) for each with ``u > 0``."""
    from ..result.propagate import Sensitivity, UncertainInput

    names = [name for name, entry in inputs.entries.items() if entry.uncertainty is not None]
    uncertain = [UncertainInput(name, float(inputs.parsed[name].si),
                                float(inputs.parsed[name].uncertainty)) for name in names]
    table: dict[str, dict[int, Any]] = {name: {} for name in result.results}
    with np.errstate(all="ignore"):  # an overflow is a non-finite slope: refused there
        for index, name in enumerate(names):
            if uncertain[index].sigma == 0:
                continue
            row = slopes(name)
            for key, entry in result.results.items():
                table[key][index] = row.get(key, np.zeros(np.shape(entry.si)))
    return Sensitivity(uncertain, table)


def _scalar_slopes(name: str, Om: float, v: float, r: float, al: float, m: float | None,
                   a_c: float) -> dict[str, float]:
    """Slopes of the scalar form with respect to the magnitude ``name``: ``a_c = 2 Omega v_r``,
    ``F_c = m a_c``, ``a_euler = alpha r``, ``a_centripetal = Omega^2 r`` and
    ``a_transport = r H``, ``H = hypot(alpha, Omega^2)``.

    Parameters: ``Om`` (rad/s), ``v`` (m/s), ``r`` (m), ``al`` (rad/s^2), ``m`` (kg, ``None``
    without --mass), ``a_c`` (m/s^2, as computed). All are >= 0; where ``H = 0``
    (``alpha = Omega = 0``) ``a_transport`` has a corner and the slope is the one-sided one
    (the inputs cannot go below 0): ``r`` for alpha, 0 for Omega.
    """
    H = math.hypot(al, Om * Om)
    if name == "omega":
        row = {"a_c": 2.0 * v, "a_centripetal": 2.0 * Om * r,
               "a_transport": 2.0 * r * Om * (Om * Om / H) if H > 0 else 0.0}
    elif name == "vr":
        row = {"a_c": 2.0 * Om}
    elif name == "r":
        row = {"a_euler": al, "a_centripetal": Om * Om, "a_transport": H}
    elif name == "alpha":
        row = {"a_euler": r, "a_transport": r * (al / H) if H > 0 else r}
    else:  # mass
        return {"F_c": a_c}
    if m is not None and "a_c" in row:
        row["F_c"] = m * row["a_c"]
    return row


def _earth_moves(inputs: CoriolisInputs, rate: float) -> dict[str, tuple]:
    """How each uncertain Earth input moves ``Omega = W (0, cos phi, sin phi)`` (rad/s) and
    ``v_r = (v sin psi, v cos psi, w)`` (m/s), per SI unit of the input:
    ``dOmega/dphi = W (0, -sin phi, cos phi)``, ``dOmega/dW = (0, cos phi, sin phi)``,
    ``dv_r/dv = (sin psi, cos psi, 0)``, ``dv_r/dpsi = v (cos psi, -sin psi, 0)``,
    ``dv_r/dw = (0, 0, 1)``. ``side`` is +1 (-1) for an input at its lower (upper) bound,
    which can only grow (shrink): a speed or rate of 0, a latitude of -90 (90) deg.
    """
    from ..physics.frames import earth_angular_velocity, enu_velocity

    zero = np.zeros(3)
    _, c, s = earth_angular_velocity(inputs.parsed["latitude"].quantity, 1.0)
    degrees = inputs.degrees
    moves = {"latitude": (rate * np.array([0.0, -s, c]), zero, 0.0,
                          -1 if degrees >= 90.0 else 1 if degrees <= -90.0 else 0),
             "omega": (np.array([0.0, c, s]), zero, 0.0, 1 if rate == 0 else 0),
             "vertical": (zero, np.array([0.0, 0.0, 1.0]), 0.0, 0),
             "mass": _MASS}
    heading = inputs.parsed.get("heading")
    if heading is not None and "speed" in inputs.parsed:
        east, north, _ = enu_velocity(1.0, heading.quantity, 0.0)
        speed = float(inputs.si("speed"))
        moves["speed"] = (zero, np.array([east, north, 0.0]), 0.0, 1 if speed == 0 else 0)
        moves["heading"] = (zero, speed * np.array([north, -east, 0.0]), 0.0, 0)
    return moves


def _frame_slopes(fa, m: float | None, move: tuple, v_transport=None,
                  v_abs=None) -> dict[str, Any]:
    """Slopes of every result of the vector formula for an input that moves ``Omega`` by
    ``dOm`` and ``v_r`` by ``dv`` (per SI unit of the input) and the mass ``m`` (kg) by
    ``dm``; ``r``, ``alpha``, ``a0``, ``a_r`` are vectors and carry no uncertainty:

    ``da_c = 2 (dOm x v_r + Omega x dv)``, ``da_centripetal = dOm x (Omega x r) +
    Omega x (dOm x r)`` (= ``da_transport``), ``da = da_transport + da_c``,
    ``dv_transport = dOm x r``, ``dv = dv_transport + dv``,
    ``dF_c = -(m da_c + dm a_c)``, ``d coriolis_parameter = 2 dOm_z``; a magnitude by
    :func:`_norm_slope`.
    """
    dOm, dv, dm, side = (np.zeros(3) if x is None else x for x in move)
    Om, v, r = fa.Omega, fa.v_r, fa.r
    da_c = 2.0 * (np.cross(dOm, v) + np.cross(Om, dv))
    da_cent = np.cross(dOm, np.cross(Om, r)) + np.cross(Om, np.cross(dOm, r))
    dv_t = np.cross(dOm, r)
    row = {"a_c": da_c, "a_c_mag": _norm_slope(fa.a_c, da_c, side),
           "a_euler": np.zeros(3), "a_centripetal": da_cent, "a_transport": da_cent,
           "a_transport_mag": _norm_slope(fa.a_transport, da_cent, side),
           "a": da_cent + da_c, "a_mag": _norm_slope(fa.a, da_cent + da_c, side),
           "Omega": dOm, "v_r": dv, "coriolis_parameter": 2.0 * float(dOm[2]),
           "v_transport": dv_t, "v": dv_t + dv}
    if v_transport is not None:
        row["v_transport_mag"] = _norm_slope(v_transport, dv_t, side)
    flat = _horizontal(da_c)
    row["a_c_horizontal"] = flat
    row["a_c_horizontal_mag"] = _norm_slope(_horizontal(fa.a_c), flat, side)
    if v_abs is not None:
        row["v_mag"] = _norm_slope(v_abs, dv_t + dv, side)
    if m is not None:
        dF_c = -(m * da_c + dm * fa.a_c)
        row["F_c"] = dF_c
        row["F_c_mag"] = _norm_slope(fa.F_c, dF_c, side)
        row["F_c_horizontal"] = _horizontal(dF_c)
        row["F_c_horizontal_mag"] = _norm_slope(_horizontal(fa.F_c), _horizontal(dF_c),
                                                side)
    return row


def _norm_slope(x, dx, side: int) -> float:
    """The slope of ``|x|`` when ``x`` moves by ``dx``: ``x/|x| . dx``. At ``x = 0`` ``|x|``
    has a corner: ``side |dx|`` for an input at a bound (the one-sided slope, ``side`` = +1
    at a lower bound, -1 at an upper one), 0 otherwise (the mean of the two sides)."""
    size = _mag(x)
    if size > 0:
        return float(np.dot(np.asarray(x, dtype=float) / size, dx))
    return side * _mag(dx)


# --- the command record ----------------------------------------------------------------------

_VECTOR = "VEC"
#: option -> (metavar, help) of ``dyncalc coriolis --help``, in its order
_HELP = {
    "omega": (_VECTOR, "Angular velocity of the frame: '0,0,2 rad/s' (rad/s, deg/s, rpm), or "
              "a magnitude ('2 rad/s') for perpendicular vectors; with --latitude the rotation "
              "rate only (default 7.2921159e-5 rad/s)."),
    "vr": (_VECTOR, "Velocity relative to the frame: '3,0,0 m/s' (km/h ...), or a magnitude; "
           "with --latitude east, north, up components."),
    "r": (_VECTOR, "Position in the frame (from its origin); a magnitude is the distance from "
          "the rotation axis."),
    "alpha": (_VECTOR, "Angular acceleration of the frame, e.g. '0,0,1 rad/s^2' (a magnitude: "
              "about the axis of --omega)."),
    "v0": (_VECTOR, "Velocity of the frame's origin, e.g. '1,0,0 m/s' (vectors only): adds "
           "to v_transport = v0 + Omega x r."),
    "a0": (_VECTOR, "Acceleration of the frame's origin, e.g. '1,0,0 m/s^2' (vectors only)."),
    "ar": (_VECTOR, "Acceleration relative to the frame (vectors only)."),
    "mass": ("M", "Mass: adds the Coriolis force F_c = -m a_c."),
    "latitude": ("ANGLE", "Earth mode: latitude from -90deg to 90deg (positive north); --vr "
                 "and the other vectors are then east, north, up components."),
    "speed": ("V", "Earth mode: horizontal speed (with --heading), instead of --vr."),
    "heading": ("ANGLE", "Earth mode: compass heading of --speed, 0deg = north, 90deg = "
                "east."),
    "vertical": ("V", "Earth mode: vertical speed, positive up (with or without --speed)."),
}


def _run(values: dict[str, str | None], words=(), *, rtol=None, strict=False) -> Result:
    scene = values.get("scene")
    if scene is not None:
        from .coriolis_scenes import scene_result

        return scene_result(scene, values, words, rtol=rtol, strict=strict)
    from .coriolis_time import is_time_motion

    if is_time_motion(values):
        from .coriolis_time import time_result

        times = values.get("t")
        if times is not None and "," in times:
            raise InputError("--t: a list of times gives a table, one row per time; the "
                             "command line prints it (in Python call once per time)")
        return time_result({name: values.get(name) for name in _TIME_TEXTS}, words,
                           strict=strict)
    if values.get("basis") is not None:
        raise InputError("--basis goes with a motion given in time (--t): constant vectors "
                         "are given and shown in one frame's components")
    if values.get("plot") is not None:
        raise InputError("--plot draws a motion given in time: give --r (and --omega, --R0) "
                         "as expressions in t with --t")
    return coriolis_result({name: values.get(name) for name in OPTIONS}, words,
                           strict=strict)


#: The options the time path reads (the others it refuses by name).
_TIME_TEXTS = (*OPTIONS, "R0", "t", "basis")


def _relative_scenes():
    from ..scenes.relative import relative_scene_names

    return relative_scene_names()


COMMAND = Command(
    "coriolis",
    "Coriolis acceleration and every term of relative motion.",
    """Coriolis acceleration a_c = 2 Omega x v_r and every term of the relative-motion formula
    a = a0 + alpha x r + Omega x (Omega x r) + 2 Omega x v_r + a_r, in a machine or on Earth.

    Vectors have three components and one unit ("0,0,2 rad/s", "(0, 0, 2) rpm",
    "[1,0,0] km/h"); a component may be an expression with units ("0.5*sin(35deg), 0, 0 m/s":
    a bare component takes the trailing unit, one with its own unit is taken as it is) using
    NAME=QUANTITY parameters (--r "l*cos(30deg), l*sin(30deg), 0" l=2m). Results are in SI.

    Each result is given when its options are: a_c needs --vr; --r (or --v0) adds the
    velocities v_transport = v0 + Omega x r and, with --vr, v = v_transport + v_r; any of
    --r, --alpha, --a0, --ar adds a_euler, a_centripetal, a_transport and, with --vr, the
    absolute a; --mass adds the Coriolis force F_c = -m a_c (the apparent force). Missing
    vectors are zero; every vector has its magnitude (v_mag, a_mag, ...).

    Scalars (--omega 2rad/s --vr 3m/s) are magnitudes of perpendicular vectors: a_c = 2 Omega
    v_r and F_c = m a_c; --r is then the distance from the axis and --alpha turns about the
    same axis; --v0, --a0, --ar and the absolute a need vectors. A result given as
    NAME=QUANTITY with one unknown as NAME=? is solved for it (a_c=12m/s^2 --omega 2rad/s
    vr=?; on the Earth a_c_mag=, a_c_horizontal_mag=, heading north unless --heading).

    --latitude sets up the rotating Earth: x east, y north, z up, Omega = Omega_E (0, cos phi,
    sin phi), Omega_E the sidereal 7.2921159e-5 rad/s (the textbook's 2 pi/day is --omega
    "1 turn/day"); a_c_horizontal and F_c_horizontal are the parts that push sideways on level
    ground. --explain lists each term with its numbers, which vanish and why, and on Earth
    the directions of a_c and of the Coriolis force.

    Motion given in time: --r, --omega (rotating-frame components) and --R0 (the origin's
    position, fixed-frame components) may be expressions in t with NAME=QUANTITY parameters,
    evaluated at --t; v_r, a_r, alpha, v0, a0 are their exact derivatives (the frames
    coincide at t = 0). --basis fixed prints the vectors in the fixed frame's axes; a list of
    times in --t (or --batch over a t column) gives a table; --plot draws the path.
    --scene runs radial-slot-release or slotted-link with their NAME=QUANTITY parameters.

    \b
    Examples:
      dyncalc coriolis --omega "2 rad/s" --vr "3 m/s"
      dyncalc coriolis --omega "0,0,30 rpm" --vr "0.5,0,0 m/s" --r "0.2,0,0 m" --mass 2kg
      dyncalc coriolis --omega "0,0,2 rad/s" --r "l*cos(30deg), l*sin(30deg), 0" l=2m \\
          --vr "0.1*5*sin(35deg), 0, 0 m/s" --v0 "1,0,0 m/s"
      dyncalc coriolis --latitude 45deg --speed "100 km/h" --heading 0deg --mass 1kg --explain
      dyncalc coriolis --latitude 30deg --vr "20,0,0 m/s" --json
      dyncalc coriolis a_c_mag=0.01m/s^2 --latitude 45deg vr=?
      dyncalc coriolis --r "s0 - b*t^2/2, 0, 0 m" s0=4m b=0.5m/s^2 --omega "0,0,2 rad/s" \\
          --t 2s --basis fixed
      dyncalc coriolis --scene slotted-link d=0.4m c=0.3m theta=35deg omega=-10rad/s
    """,
    (Parameter("scene", None, "A relative-motion set-up with its own parameters as "
               "NAME=QUANTITY words (radial-slot-release, slotted-link).", "NAME",
               kind="setting", choices=_relative_scenes),
     *(Parameter(name, dim, _HELP[name][1], _HELP[name][0])
       for name, (dim, _words) in OPTIONS.items()),
     Parameter("R0", LENGTH, "Position of the frame's origin in fixed-frame components, as "
               "expressions in t: motion given in time.", _VECTOR, kind="text"),
     Parameter("t", TIME, "Time at which a motion given in time is evaluated, e.g. 2s; a "
               "list ('0, 0.5, 1 s') gives a table, one row per time.", "TIME", kind="text"),
     Parameter("basis", None, "Components of the vector results of a motion given in time: "
               "rotating (default, the frame's axes at t) or fixed.", "rotating|fixed",
               kind="setting", choices=("rotating", "fixed")),
     Parameter("plot", None, "Draw the path of the point in the fixed frame (a motion given "
               "in time) with its velocity and acceleration at --t into FILE (.png, .svg or "
               ".pdf); needs matplotlib.", "FILE.png", kind="after")),
    (*(ResultName(name, kind[2], kind[0].si, kind[-1]) for name, kind in _KINDS.items()),
     *(ResultName(name, kind[2], kind[0].si, kind[-1]) for name, kind in TIME_KINDS.items()
       if name not in _KINDS)),
    _run,
    words="[NAME=QUANTITY]...",
    columns=columns,
)
