"""Reading the ``coriolis`` options: every quantity and vector parsed and checked once into a
:class:`CoriolisInputs`, the form (vectors, magnitudes, Earth) chosen by the options given
(:func:`read`); :mod:`dyncalc.commands.coriolis` computes on what it read.
"""
from __future__ import annotations

from ..errors import InputError
from ..lazy import numpy as np
from ..result.entries import Entry, entry_from_parsed, format_number
from ..units import (ACCELERATION, ANGLE, ANGULAR_ACCELERATION, ANGULAR_RATE, LENGTH, MASS,
                    VELOCITY, Dim, Parsed, format_quantity, parse_quantity, parse_vector)

__all__ = ["OPTIONS", "CoriolisInputs", "read", "bare_latitude_warning",
           "bare_heading_warning"]

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


def bare_latitude_warning(text: str, degrees: float) -> str:
    """The warning of a latitude typed without a unit (``text``, read in radians: ``degrees``
    of latitude), for the one-off and the batch's rows alike.

    >>> bare_latitude_warning(" 0.7", 40.10704565915762)
    '--latitude 0.7 has no unit and is read in radians (40.107 deg); write 0.7deg for degrees'
    """
    text = text.strip()
    return (f"--latitude {text} has no unit and is read in radians "
            f"({format_number(degrees, 6)} deg); write {text}deg for degrees")


def bare_heading_warning(text: str) -> str:
    """The warning of a heading typed without a unit (``text``, read in radians).

    >>> bare_heading_warning("1")
    '--heading 1 has no unit and is read in radians; write 1deg for compass degrees'
    """
    text = text.strip()
    return (f"--heading {text} has no unit and is read in radians; write {text}deg for "
            "compass degrees")


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
        warnings.append(bare_latitude_warning(latitude.text, degrees))

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
            warnings.append(bare_heading_warning(heading.text))
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


