"""Reading ``inertia``'s words: bodies such as ``rod(m=2kg, l=1m, along=x, at=(0.5, 0, 0) m)``
or a hole ``-disk(rho=7.8 kg/m^2, r=5cm)``, and the ``--axis`` text.

The grammar (a small hand-written reader; each value goes to the quantity and vector grammar
of :mod:`dyncalc.units.grammar`, nothing is evaluated as Python)::

    body   := ["-"] NAME "(" KEY=VALUE ("," KEY=VALUE)* ")"
    KEY    := m | rho | a dimension of NAME (l, r, ri, ro, h, a, b) | at | along
    at     := a vector of lengths in parentheses or brackets: (0.5, 0, 0) m
    along  := x | y | z (a sign allowed: -x) | a vector: (1, 1, 0)
    axis   := DIRECTION [through POINT]       z, (1, 1, 0), "z through (0.1, 0, 0) m"
"""
from __future__ import annotations

import re

from ..errors import InputError
from ..lazy import numpy as np
from ..physics.inertia import BODY_DIMENSIONS, DENSITY_KIND
from ..units import DIMENSIONLESS, LENGTH, MASS, Dim, parse_quantity, parse_vector
from ..units.split import split_top

__all__ = ["BodyWord", "read_body", "read_bodies", "read_axis", "DENSITY", "AxisText",
           "MAX_BODIES"]

MAX_BODIES = 200  #: parsing takes about 0.5 ms a body: 200 answer well within a second

#: The dimension of ``rho=`` by body (:data:`dyncalc.physics.inertia.DENSITY_KIND`).
DENSITY = {
    "linear": Dim("linear density", "[mass]/[length]", "[mass]/[length]", "kg/m"),
    "areal": Dim("areal density", "[mass]/[length]^2", "[mass]/[length]**2", "kg/m^2"),
    "volume": Dim("density", "[mass]/[length]^3", "[mass]/[length]**3", "kg/m^3"),
}
_WORD_AXES = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}
_BODY_RE = re.compile(r"^\s*(-?)\s*([A-Za-z][A-Za-z0-9_-]*)\s*\((.*)\)\s*$", re.S)
_KEY_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*=(.*)$", re.S)


def usage(kind: str) -> str:
    """``disk(m= | rho=, r=, at=, along=)``."""
    mass = "m=" if kind == "point" else "m= | rho="
    dims = "".join(f", {d}=" for d in BODY_DIMENSIONS[kind])
    return f"{kind}({mass}{dims}, at=, along=)"


class BodyWord:
    """One body as read: its ``kind``, ``sign`` (-1 for a hole), number ``index`` (1, 2, ...),
    the parsed values by key (``m`` or ``rho``, the dimensions, ``at``, ``along``) and the
    text of ``along`` when given as a word (``x``)."""

    __slots__ = ("kind", "sign", "index", "parsed", "along_word", "text")

    def __init__(self, kind: str, sign: int, index: int, parsed: dict, along_word: str | None,
                 text: str):
        self.kind, self.sign, self.index, self.parsed = kind, sign, index, parsed
        self.along_word, self.text = along_word, text


def _direction(text: str, label: str, strict: bool):
    """A direction: ``x``, ``-y``, or a vector of pure numbers; refuses a zero vector."""
    word = text.strip()
    sign = -1.0 if word.startswith("-") and word[1:].strip() in _WORD_AXES else 1.0
    bare = word[1:].strip() if sign < 0 else word.lstrip("+").strip()
    if bare in _WORD_AXES:
        return sign * np.array(_WORD_AXES[bare]), word
    vector = np.asarray(parse_vector(text, DIMENSIONLESS, label=label, strict=strict).si,
                        dtype=float)
    if not float(np.max(np.abs(vector))) > 0.0:
        raise InputError(f"{label} has zero length: a direction needs a non-zero vector")
    return vector, None


def read_body(word: str, index: int, strict: bool = False) -> BodyWord:
    """One body word -> :class:`BodyWord`, every value parsed and checked."""
    match = _BODY_RE.match(word)
    if match is None:
        shown = word.strip()[:60]
        if "(" in word and ")" not in word:
            raise InputError(f"body {index} ({shown!r}): a '(' is not closed")
        raise InputError(f"body {index} ({shown!r}) is not a body: write NAME(KEY=VALUE, ...), "
                         f"e.g. rod(m=2kg, l=1m); the bodies are {', '.join(BODY_DIMENSIONS)}")
    sign = -1 if match.group(1) else 1
    kind, inner = match.group(2), match.group(3)
    if kind not in BODY_DIMENSIONS:
        raise InputError(f"unknown body {kind!r}; the bodies are {', '.join(BODY_DIMENSIONS)}")
    where = f"{kind}() (body {index})"
    texts: dict[str, str] = {}
    for part in split_top(inner, ",", where) if inner.strip() else ():
        if not part.strip():
            raise InputError(f"{where}: a parameter is empty; usage: {usage(kind)}")
        pair = _KEY_RE.match(part)
        if pair is None:
            raise InputError(f"{where}: write parameters as KEY=VALUE (a vector in parentheses:"
                             f" at=(0.5, 0, 0) m); got {part.strip()[:40]!r}")
        key, text = pair.group(1), pair.group(2)
        allowed = ("m", "at", "along", *BODY_DIMENSIONS[kind]) + (
            ("rho",) if kind in DENSITY_KIND else ())
        if key not in allowed:
            raise InputError(f"{kind}() has no parameter {key!r}; usage: {usage(kind)}")
        if key in texts:
            raise InputError(f"{where}: {key} is given twice")
        texts[key] = text
    if "m" in texts and "rho" in texts:
        raise InputError(f"{where}: give m= or rho=, not both")
    if "m" not in texts and "rho" not in texts:
        if kind == "point":
            raise InputError(f"{where} needs m=, its mass")
        density = DENSITY[DENSITY_KIND[kind]]
        raise InputError(f"{where} needs m= (its mass) or rho= (its {density.name} "
                         f"{density.display})")
    for dim_name in BODY_DIMENSIONS[kind]:
        if dim_name not in texts:
            raise InputError(f"{where} needs {dim_name}=; usage: {usage(kind)}")
    parsed: dict = {}
    along_word = None
    for key, text in texts.items():
        label = f"{key} of body {index} ({kind})"
        if key == "m":
            parsed[key] = parse_quantity(text, MASS, label=label, strict=strict,
                                         constraint="positive")
        elif key == "rho":
            parsed[key] = parse_quantity(text, DENSITY[DENSITY_KIND[kind]], label=label,
                                         strict=strict, constraint="positive")
        elif key == "at":
            parsed[key] = parse_vector(text, LENGTH, label=label, strict=strict)
        elif key == "along":
            vector, along_word = _direction(text, label, strict)
            parsed[key] = vector
        else:
            parsed[key] = parse_quantity(text, LENGTH, label=label, strict=strict,
                                         constraint="positive")
    return BodyWord(kind, sign, index, parsed, along_word, word.strip())


def read_bodies(words, strict: bool = False) -> list[BodyWord]:
    """Every body word, numbered from 1; at least one, at most :data:`MAX_BODIES`."""
    words = list(words)
    if not words:
        raise InputError("inertia needs at least one body, e.g. dyncalc inertia "
                         "\"rod(m=2kg, l=1m)\"")
    if len(words) > MAX_BODIES:
        raise InputError(f"inertia takes at most {MAX_BODIES} bodies; got {len(words)}")
    return [read_body(word, i, strict) for i, word in enumerate(words, 1)]


class AxisText:
    """``--axis`` as read: the unit ``direction``, the ``point`` it passes through (m) and
    the text."""

    __slots__ = ("direction", "point", "text", "point_parsed")

    def __init__(self, direction, point, text: str, point_parsed=None):
        self.direction, self.point, self.text = direction, point, text
        self.point_parsed = point_parsed


def read_axis(text: str, strict: bool = False) -> AxisText:
    """``z``, ``(1, 1, 0)``, ``z through (0.1, 0, 0) m`` -> :class:`AxisText`."""
    parts = re.split(r"\s+through\s+", text.strip(), maxsplit=1)
    if not parts[0].strip():
        raise InputError("--axis: give a direction (x, y, z or a vector), e.g. --axis z or "
                         "--axis \"z through (0.1, 0, 0) m\"")
    direction, _word = _direction(parts[0], "--axis", strict)
    point = np.zeros(3)
    parsed = None
    if len(parts) == 2:
        parsed = parse_vector(parts[1], LENGTH, label="--axis (the point it passes through)",
                              strict=strict)
        point = np.asarray(parsed.si, dtype=float)
    from ..physics.inertia_tensor import unit_vector

    return AxisText(unit_vector(direction, "--axis has zero length"), point, text, parsed)
