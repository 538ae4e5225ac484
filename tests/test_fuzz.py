"""Fuzzing the command line (issue 9): whatever is typed, dyncalc answers right or refuses
clearly, and never crashes, hangs or prints more than the contract allows.

Every case runs ``dyncalc ARGS`` through the real click group (``CliRunner``) and asserts the
contract of SPEC.md, "Exit status and errors":

* exit status 0, 1 or 2, and no exception escapes the program;
* no ``Traceback`` anywhere, and no ``Error: internal error`` (the program's own name for a bug);
* exit 2: stderr is exactly one line, ``Error: ...``;
* exit 0 or 1: every stderr line is a ``warning:`` or a ``check ...`` line;
* no Python warning (numpy's RuntimeWarning, ...) is raised: in the real process it would be
  printed to stderr, several lines long;
* no raw control or bidirectional-override character reaches the terminal (the user's text is
  quoted safely);
* stdout that is a JSON object parses as strict JSON (no NaN or Infinity), and no result reads
  ``nan`` (NaN is always refused, never answered);
* each call returns within :data:`CALL_LIMIT` seconds (a hang guard, not a performance claim).

The arguments come from a grammar of the real options of each command (:data:`SPECS`), the
scene catalog and its parameters, ``NAME=QUANTITY`` words and quantity strings, mixed with the
hostile text of :data:`HOSTILE`. ``tools/fuzz_long.py`` runs the same strategies for 10^4 and
more cases per command; ``docs/reliability.md`` has the figures.

The explicit tests at the end pin the exact ``Error:`` line of every silent-misreading class
of SPEC.md and of every runaway input, and that each refusal takes under a second.
"""
from __future__ import annotations

import atexit
import contextlib
import functools
import json
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unicodedata
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from unittest import mock

import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from dyncalc.cli import cli
from dyncalc.physics.inertia import BODY_DIMENSIONS, DENSITY_KIND
from dyncalc.scenes import get_scene, scene_names

#: The project root (the folder of pyproject.toml), wherever this file sits.
ROOT = next(p for p in Path(__file__).resolve().parents if (p / "pyproject.toml").exists())

#: Seconds one in-process call may take before it counts as a hang (the SPEC's limit is 1 s
#: for a refusal; this guard is looser so a slow CI machine does not fail it by accident).
CALL_LIMIT = 2.0
#: Seconds after which a call is interrupted (SIGALRM) so a real hang fails instead of blocking.
ALARM = 20.0
#: Seconds an explicit refusal may take (SPEC.md: "longer than a second").
REFUSAL_LIMIT = 1.0

COMMANDS = ["spring-series", "spring-parallel", "natural-frequency", "damping-ratio",
            "rolling-onset", "coriolis", "inertia", "scenes"]

#: Examples per command in CI (8 commands: about 3000 cases with the mixed-command test).
CI_EXAMPLES = {"spring-series": 350, "spring-parallel": 250, "natural-frequency": 450,
               "damping-ratio": 400, "rolling-onset": 350, "coriolis": 350, "inertia": 250,
               "scenes": 100}
CI_MIXED_EXAMPLES = 300

SCENES = list(scene_names())
#: Every scene parameter name, and the dimensions it has across the catalog.
PARAM_DIMS: dict[str, set[str]] = {}
for _scene in SCENES:
    for _p in get_scene(_scene).params:
        PARAM_DIMS.setdefault(_p.name, set()).add(_p.dim.name if _p.dim is not None else "choice")
ALL_PARAM_NAMES = sorted(PARAM_DIMS)

# ---------------------------------------------------------------------------------------------
# Hostile text, by class (the classes are named in docs/reliability.md)

_LONG = 10_000  # "very long": 10 kB, fifty times dyncalc's limit on a quantity

HOSTILE: dict[str, list[str]] = {
    "explosive pint expressions": [
        "10**10**10 m", "9**9**9", "9**9**9**9", "2**2**2**2**2 N/m", "10^10^10", "2^3^4 kg",
        "(10**10)**(10**10)", "(2**1000)**1000 N/m", "2**1024", "2**99999999999", "10**100000",
        "10**-100000 m", "1e308*1e308", "10**308*10 N/m", "1e308 m * 1e308 m", "(1e200 m)**2",
        "1/1e-308/1e-308", "2**-1075", "m**1000", "(m**8)**8", "kg**17", "1 N/m**(2**10)",
        "1*2*3*4*5*6*7*8*9*10*11*12*13*14*15*16*17*18*19*20*21*22*23*24*25*26*27*28*29*30",
        "1" + "*99" * 60, "2" + "**2" * 50, "((((((2**2)**2)**2)**2)**2)**2)**2",
        "9**(9**9)", "(9**9)**(9**9)", "10**(10**10) kg", "1e10**1e10", "1e-300**-2",
        "2**(1/0)", "0**-1", "0**0", "(-8)**(1/3)", "(-1)**0.5 m", "-1**0.5",
    ],
    "unicode digits and look-alikes": [
        "\uff15 N/m", "\uff11\uff10\uff10 kg", "\u0665 kg", "\u0661\u0660 m", "\u0969 m",
        "\u00b2", "5 m\u00b2", "5 m\u00b3", "5 m\u2074", "\u00b9\u00b2 kg", "5\u00b2\u00b2 m",
        "5 \u00b5m", "5 \u03bcm", "5 \u00b5N/m", "5 \u03bcs", "5 \u2126", "5 \u03a9", "5 \u212b",
        "5 \u00c5", "30\u00b0", "30 \u00b0", "\u22125 N/m", "5 \u2212 3 N/m", "\u20135 kg",
        "\u20105 kg", "\u2012 5", "5\u00a0N/m", "5\u202fN/m", "5\u2009N/m", "5\u3000N/m",
        "5\u200bN/m", "5\u200dkg", "\ufeff5 kg", "5 kg\ufeff", "\u200f5 N/m", "\u200e5 m",
        "\u202e5 m/N", "5 m\u2066", "5 \uff4d", "5 \u043c", "5 \u03bf", "\u00bd m", "\u2153 kg",
        "\u2460 kg", "5\u0301 m", "5 \ufb01", "5 \U0001d7d3", "\U0001f4a9", "5 \U0001f4a9",
        "\u0035\u20e3", "5 mi\u0307", "5 \u212a", "5 K\u0335",
    ],
    "nan and inf spellings": [
        "nan", "NaN", "NAN", "-nan", "+nan", "nan m", "NaN N/m", "inf", "-inf", "+inf", "Inf",
        "INF", "infinity", "Infinity", "-infinity", "inf N/m", "-inf kg", "inf - inf",
        "inf*0", "0*inf", "inf/inf", "1/inf", "inf**0", "1e999", "-1e999", "1e309", "-1e309",
        "1e999 N/m", "\u221e", "\u221e N/m", "nan,0,0", "0,0,inf", "(inf,inf,inf) m/s",
        "snan", "NaN(123)", "1.#INF", "1.#QNAN",
    ],
    "huge and tiny exponents": [
        "1e308", "1.7976931348623157e308", "1.7976931348623159e308", "1.8e308", "1e+308 kg",
        "4.9e-324", "5e-324", "2e-324", "2.4703282292062328e-324", "1e-400", "1e-308 m",
        "2.2250738585072014e-308", "1E5", "1e", "1e+", "1e-", "e5", "1e5.5", "1.e3", ".5e-3",
        "1e0000000000000000000000005", "0e999999", "1e-99999999999", "1e99999999999999999999",
        "9" * 400, "0." + "0" * 400 + "1", "1" + "0" * 309, "123456789012345678901234567890",
        "0.1e-323", "1e-320 N/m", "1e-323 kg",
    ],
    "empty and blank": ["", " ", "  ", "\t", " \t ", "=", " = ", "k=", "k= ", "=5", "==5"],
    "lone operators": [
        "+", "-", "*", "/", "**", "^", "(", ")", "()", "[]", "(())", "+-+-", "--5", "- - 5",
        "1+", "*5", "5*", "/5", "5/", "5^", "^5", "5**", "5 m/", "5 m*", "5 m^", "(5", "5)",
        "((5)", "5 + ", ",", ".", "..", "5..5", "1.2.3", "5 */ m", "5 m ** ** 2", "-", "--",
        "---", "+5", "++5", "5 m -", "5 (m", "5 m)", "5 ()", "5 m ()", "5 m**", "**2 m",
    ],
    "very long": [
        "1" * _LONG, "5 m" + " " * _LONG, "+" * _LONG, "(" * _LONG, "m*" * (_LONG // 2),
        "1e1" * (_LONG // 3), "a" * _LONG, "9" * 199, "9" * 200, "9" * 201,
        "1+" * 99 + "1", "1+" * 100 + "1", "5 " + "k" * 300 + "g", "-" * _LONG + "5",
        ",".join(["1"] * 5000), "(" + ",".join(["0"] * 3000) + ") m/s", "[" * 5000 + "]" * 5000,
    ],
    "deep nesting": [
        "(" * 24 + "5" + ")" * 24 + " m", "(" * 25 + "5" + ")" * 25 + " m",
        "(" * 100 + "5" + ")" * 100, "(" * 1000 + "5" + ")" * 1000, "-" * 30 + "5 kg",
        "+" * 25 + "5", "-(" * 30 + "5" + ")" * 30, "[" * 30 + "5" + "]" * 30,
        "series(" * 17 + "5" + ")" * 17, "series(" * 16 + "5" + ")" * 16,
        "parallel(" * 40 + "1" + ")" * 40, "series(" * 1000 + "1" + ")" * 1000,
        "(" * 30 + "5 m", "5 m" + ")" * 30,
    ],
    "shell metacharacters": [
        "$(rm -rf /)", "$(echo 5) N/m", "`id`", "`5` kg", "; ls", "5 m; rm -rf ~", "| cat",
        "5 | cat", "> /tmp/x", "5 m > /dev/null", "< /etc/passwd", "&& echo hi", "5 & 6",
        "'", '"', "\\", "5 m\\", "'5 m'", '"5 m"', "$HOME", "${IFS}5", "~", "!!", "*",
        "5 m # x", "#", "5 m // x", "5 m /* x */", "5\nm", "5\r\nm", "5 m\n", "\x00", "5\x00m",
        "\x1b[31m5 N/m", "5 kg\x1b[2J", "\x1b]8;;http://x\x1b\\5\x1b]8;;\x1b\\ m", "\x07", "\b5",
        "\r5", "5\x7fkg", "5\x85kg", "5\u2028kg", "5\u2029kg", "%s", "%n", "{0}", "{}",
        "%(x)s", "__import__('os')", "__class__", "m.__class__", "eval", "exec", "None",
        "True", "lambda", "5 m\x0b", "\x0c5",
    ],
    "rich markup": [
        "[bold]", "[/]", "[/bold]", "[bold]5[/] N/m", "[red]5 m[/red]",
        "[link=https://x.y]5[/link]",
        "[link=file:///etc/passwd]k[/link]", "5 [link=x] N/m", "[bold red on white]5",
        ":smile:", ":warning: 5 m", "\\[bold]", "[", "]", "[[", "]]", "[/]5 m", "5 m[/]",
        "[0,0,1] rad/s", "[1,0,0] m/s", "[5] m",
    ],
    "percent and at": [
        "5%", "5 %", "50 % m", "%", "%%", "5 %m", "5 %% N/m", "100%", "5 percent", "5 ppm",
        "5 @ m", "@", "5 m@2", "m@", "@5", "5 kg @ 2", "5% N/m", "1 % kg",
    ],
    "commas and separators": [
        "1,5", "1,5 m", "1,000", "1,000.5 N/m", "1.000,5", ",5", "5,", "1,,5", "1 000 N/m",
        "1_000", "1'000 kg", "1 000 000", "2 3/4 m", "2 1/s",
    ],
    "vectors with wrong components": [
        "0,0,2 rad/s", "(0, 0, 2) rad/s", "[1,0,0] m/s", "1,2", "1,2,3,4", "(,,)", ",,",
        "(1,2,3", "1,2,3)", "(1;2;3)", "1 2 3", "(1,2,3) rad/s rad/s", "(1e999,0,0)",
        "(nan,0,0)", "(1, 2, 3 m/s)", "1,2,3 m/s m", "(1,2,3)m/s", "[0,0,1) rad/s",
        "(1,2,3]", "((1,2,3))", "(1,2,(3))", "(1,2,3) 0x1", "(0x1,2,3)", "1,2,3 kg",
        "(1,2,3) Hz", "(1 m,2 m,3 m)", "(+1,-2,+3)", "(1e308,1e308,1e308) km/s",
    ],
    "silent misreadings": [
        "0x10", "0X1F m", "0o17", "0b101", "0x1p3", "007", "00", "010 m", "0.5", "00.5",
        "N/mm", "m", "kg", "rad/s", "2\u00b10.1 kg", "2+/-0.1 kg", "(100 \u00b1 5) N/m",
        "2 +/- 0.1", "1,5 m", "5 m # x", "5 degC", "5 degF", "5 \u00b0C", "5 delta_degC",
        "5 K", "5 dimensionless", "5 pi", "pi", "5 e", "e", "5 E", "5 c", "5 g", "5 G",
        "5 Hz", "5 rpm", "5 rad", "5 deg", "5 turn", "5 cycle", "5 rev", "5 count", "5 m m",
        "5 Nm", "5 N m", "5 kgf", "5 mph", "5 kph", "5 knot", "5 lb", "5 slug", "5 stone",
        "5 year", "5 light_year", "5 planck_length", "1 rad/s + 1 Hz", "1 turn/s + 1 Hz",
        "5 m + 5 s", "5 m - 5 m", "0 kg", "-0.0 kg", "-5 kg",
    ],
}

ALL_HOSTILE = [text for texts in HOSTILE.values() for text in texts]

# ---------------------------------------------------------------------------------------------
# Well-formed quantities, by the dimension names of dyncalc.units

UNITS_BY_DIM = {
    "stiffness": ["N/m", "kN/m", "lbf/in", "N/mm", "kN/mm", "lbf/ft"],
    "torsional stiffness": ["N*m/rad", "kN*m/rad", "N*m", "lbf*ft/deg", "N*mm/rad"],
    "mass": ["kg", "g", "lb", "t", "slug", "mg"],
    "mass moment of inertia": ["kg*m^2", "g*cm^2", "lb*ft^2", "kg*mm**2"],
    "length": ["m", "mm", "cm", "in", "ft", "km", "\u00b5m"],
    "area": ["m^2", "mm^2", "cm**2", "in^2"],
    "second moment of area": ["m^4", "mm^4", "in^4", "cm**4"],
    "time": ["s", "ms", "min", "h"],
    "velocity": ["m/s", "km/h", "mph", "ft/s", "knot"],
    "acceleration": ["m/s^2", "ft/s^2", "m/s**2", "cm/s^2", "g_0"],
    "force": ["N", "kN", "lbf", "mN"],
    "modulus": ["Pa", "GPa", "MPa", "psi", "N/mm^2", "kN/m^2"],
    "damping coefficient": ["N*s/m", "kg/s", "lbf*s/in", "N*s/mm"],
    "angle": ["deg", "rad", "\u00b0", "turn", "arcmin", "mrad"],
    "angular rate": ["rad/s", "deg/s", "rpm", "rev/s", "1/s"],
    "angular acceleration": ["rad/s^2", "deg/s^2", "rpm/s", "1/s^2"],
    "frequency": ["Hz", "kHz", "1/s", "1/min", "rpm"],
    "pure number": ["", "", "", "percent", "%", "dimensionless", "ppm"],
    "drag per unit length": ["N*s/m^2", "kg/(m*s)", "N*s/mm^2"],
    "flexural rigidity": ["N*m^2", "kN*m^2", "N*mm^2", "lbf*in^2"],
    "torsional rigidity": ["N*m^2/rad", "N*m^2", "kN*m^2"],
}
ANY_UNIT = sorted({u for units in UNITS_BY_DIM.values() for u in units if u})
#: Units a well-formed value must not take for a dimension (the refusals of SPEC.md).
WRONG_KIND = {"angular rate": ["Hz", "kHz"], "frequency": ["rad/s", "deg/s"]}

#: Plain positive numbers, and the extremes a well-formed input may still reach.
PLAIN = ["1", "2", "0.5", "100", "1e3", "2.5e-3", "12.5", "7", "0.3", "3", "10", "0.001",
         "1.5", "250", "0.05", "45", "60", "0.2"]
EXTREME = ["1e-300", "1e300", "1e-320", "1e308", "4.9e-324", "1.7976931348623157e308",
           "2.2250738585072014e-308", "1e-9", "1e9", "0.999999999", "1.000000001", "1e-15",
           "1e15", "179.9999999", "89.9999", "6.283185307179586"]
NUMBER_EDGES = PLAIN + EXTREME + [
    "0", "0.0", "-0.0", "-1", "-0.5", "-90", "-1e300", "2.220446049250313e-16", "90", "180"]


def _format_float(x: float, how: int) -> str:
    if how == 0:
        return repr(x)
    if how == 1:
        return f"{x:g}"
    if how == 2:
        return f"{x:.3e}"
    if how == 3:
        return f"{x:.17g}"
    return f"{x:f}"  # 1e300 becomes 301 digits: a long text


#: Any number text, well-formed or not (NaN, inf, negative, zero, huge, 300 digits).
NUMBERS = st.one_of(
    st.sampled_from(NUMBER_EDGES),
    st.builds(_format_float, st.floats(allow_nan=True, allow_infinity=True), st.integers(0, 4)),
    st.integers(-10**30, 10**30).map(str),
    st.floats(1e-6, 1e6).map(lambda x: f"{x:.4g}"),
)
#: Positive, finite number texts: mostly plain, now and then extreme.
POSITIVE = st.one_of(
    st.sampled_from(PLAIN), st.sampled_from(PLAIN),
    st.floats(1e-3, 1e4).map(lambda x: f"{x:.4g}"),
    st.sampled_from(EXTREME),
    st.builds(_format_float, st.floats(5e-324, 1.7e308), st.integers(0, 3)),
)
PERCENT = st.integers(0, 99)
SEPARATORS = st.sampled_from([" ", "", " ", "  "])


def _clean_value(draw, dim_name: str | None, number=POSITIVE) -> str:
    """A number in one of the units of ``dim_name`` (a bare number now and then)."""
    units = UNITS_BY_DIM.get(dim_name or "", ANY_UNIT)
    unit = draw(st.sampled_from(units))
    if draw(PERCENT) < 8:
        unit = ""  # a bare number: SI
    text = draw(number)
    shown = f"{text}{draw(SEPARATORS)}{unit}".strip() if unit else text
    if draw(PERCENT) < 6:  # a standard uncertainty (issue 10), in the forms SPEC.md gives
        sigma = draw(st.sampled_from(["0.1", "0", "1e-3", "5", "1e300", "2e-320"]))
        form = draw(st.integers(0, 2))
        shown = (f"{shown} +/- {sigma}", f"({text} \u00b1 {sigma}) {unit}".strip(),
                 f"{text}+/-{sigma} {unit}".strip())[form]
    return shown


@functools.cache
def clean_quantity(dim_name: str | None, signed: bool = False):
    """A well-formed quantity of ``dim_name``: positive (or of either sign, ``signed``)."""
    number = POSITIVE if not signed else st.one_of(POSITIVE, POSITIVE.map(lambda t: "-" + t),
                                                   st.just("0"))

    @st.composite
    def build(draw):
        return _clean_value(draw, dim_name, number)
    return build()


_TOKENS = ["1", "2", "0.5", "1e3", "10", "m", "kg", "s", "N", "rad", "deg", "Hz", "rpm", "kN",
           "mm", "lbf", "in", "pi", "+", "-", "*", "/", "**", "^", "(", ")", " ", " ", "2",
           "\u00b2", "%", "inf", "e", "g", "1/s", "9", "0", "0.0", "**-1", "^0.5"]


@st.composite
def _expression(draw):
    """A small quantity expression from a grammar (numbers, units, operators, parentheses),
    well-formed or not."""
    def build(depth):
        kind = draw(st.integers(0, 5 if depth < 4 else 2))
        if kind <= 1:
            return draw(NUMBERS) + draw(st.sampled_from(["", " ", " m", " kg", " N/m", " s"]))
        if kind == 2:
            return draw(st.sampled_from(ANY_UNIT))
        if kind == 3:
            return "(" + build(depth + 1) + ")"
        if kind == 4:
            op = draw(st.sampled_from(["+", "-", "*", "/", " ", "**", "^"]))
            return build(depth + 1) + op + build(depth + 1)
        return draw(st.sampled_from(["-", "+"])) + build(depth + 1)
    if draw(st.booleans()):
        return build(0)
    return "".join(draw(st.lists(st.sampled_from(_TOKENS), min_size=1, max_size=12)))


EXPRESSION = _expression()

#: Characters beyond ASCII that look like parts of a quantity, or hide, and ASCII that a shell
#: or a markup language reads.
_ODD_CHARS = ("\u00b5\u03bc\u2212\u2013\u00a0\u200b\u200f\u202e\uff10\uff15\u0665\u00b2\u00b3"
              "\u2074\u00b0\u00b1\u221e\u00d7\u00b7\u2126\u212b\ufeff\u3000\u2028\x00\x1b\t\n\r"
              "$`;|&<>'\"\\[]{}@%#=,.:!?~_")
ODD_CHAR = st.sampled_from(list(_ODD_CHARS))

RANDOM_TEXT = st.text(
    alphabet=st.one_of(ODD_CHAR, st.characters(codec="utf-8"),
                       st.sampled_from(list("0123456789 .e+-*/^()mkgsNrad"))),
    max_size=30)
HOSTILE_TEXT = st.sampled_from(ALL_HOSTILE)
FRAGMENT = st.one_of(HOSTILE_TEXT, RANDOM_TEXT)


def _mutate(draw, text: str) -> str:
    """``text`` with hostile text inserted, a character replaced, or wrapped."""
    how = draw(st.integers(0, 4))
    fragment = draw(FRAGMENT)[:40]
    if how == 0 and text:
        i = draw(st.integers(0, len(text)))
        return text[:i] + fragment + text[i:]
    if how == 1 and text:
        i = draw(st.integers(0, len(text) - 1))
        return text[:i] + draw(ODD_CHAR) + text[i + 1:]
    if how == 2:
        return (draw(st.sampled_from(["(", "[", "-", "--", " ", "'", "$("])) + text
                + draw(st.sampled_from([")", "]", " ", "'", ",", "**2", " m"])))
    if how == 3:
        return text + draw(st.sampled_from([" ", ",", " ", ""])) + fragment
    return fragment + text


BAD_NUMBERS = st.sampled_from(["0", "-1", "-0.0", "nan", "inf", "-inf", "1e999", "1e-999",
                               "-1e300", "1e308", "4.9e-324", "0.0", "-5"])


def corrupt(draw, text: str, dim_name: str | None) -> str:
    """A bad replacement for the well-formed value ``text`` of dimension ``dim_name``."""
    how = draw(st.integers(0, 7))
    if how == 0:
        return draw(HOSTILE_TEXT)
    if how == 1:
        return _mutate(draw, text)
    if how == 2:
        return draw(RANDOM_TEXT)
    if how == 3:  # a well-formed quantity, most likely of another dimension
        return draw(clean_quantity(None, True))
    if how == 4:  # a number out of range, in the right unit
        unit = draw(st.sampled_from(UNITS_BY_DIM.get(dim_name or "", ANY_UNIT)))
        return f"{draw(BAD_NUMBERS)} {unit}".strip()
    if how == 5:
        return draw(EXPRESSION)
    if how == 6 and dim_name in WRONG_KIND:
        return f"{draw(POSITIVE)} {draw(st.sampled_from(WRONG_KIND[dim_name]))}"
    return _mutate(draw, text)


@functools.cache
def quantity(dim_name: str | None = None):
    """A quantity text for ``dim_name``: well-formed half of the time, otherwise bad."""
    clean = clean_quantity(dim_name, True)

    @st.composite
    def build(draw):
        text = draw(clean)
        return text if draw(st.booleans()) else corrupt(draw, text, dim_name)
    return build()


# ---------------------------------------------------------------------------------------------
# Argument lists: recipes of well-formed pieces, then corrupted by the case's level


@dataclass
class Piece:
    """Words of an argument list; ``words[slot]`` (if any) holds a value of ``dim`` that a
    corruption may replace; ``prefix`` is the ``NAME=`` of a positional word."""

    words: list[str]
    slot: int | None = None
    dim: str | None = None
    prefix: str = ""
    vector: bool = False


def opt(name: str, value: str, dim: str | None = None, vector: bool = False) -> Piece:
    return Piece([name, value], 1, dim, vector=vector)


def flag(name: str) -> Piece:
    return Piece([name])


def assign(name: str, value: str, dim: str | None) -> Piece:
    return Piece([f"{name}={value}"], 0, dim, prefix=f"{name}=")


def value(draw, dim_name: str | None, signed: bool = False) -> str:
    return draw(clean_quantity(dim_name, signed))


def vector_text(draw, dim_name: str, count: int = 3, signed: bool = True) -> str:
    """``count`` components and one unit, in one of the forms of SPEC.md."""
    comps = []
    for _ in range(count):
        comp = draw(st.one_of(st.sampled_from(["0", "0", "1", "-1", "2.5", "0.5", "-3", "1e-300",
                                               "1e300", "10"]),
                              st.floats(-1e3, 1e3).map(lambda x: f"{x:.4g}")))
        comps.append(comp if signed else comp.lstrip("-"))
    sep = draw(st.sampled_from([",", ", ", " , "]))
    unit = draw(st.sampled_from(UNITS_BY_DIM.get(dim_name, ANY_UNIT)))
    if draw(PERCENT) < 8:
        unit = ""
    body = sep.join(comps)
    form = draw(st.integers(0, 2))
    text = (f"{body} {unit}", f"({body}) {unit}", f"[{body}]{unit}")[form]
    return text.strip()


def corrupt_vector(draw, text: str, dim_name: str) -> str:
    """A bad vector: a wrong number of components, a bad component, bad brackets, or any
    corruption of a scalar."""
    how = draw(st.integers(0, 4))
    if how == 0:
        return vector_text(draw, dim_name, draw(st.sampled_from([0, 1, 2, 4, 5, 30])))
    if how == 1:
        comps = [draw(st.sampled_from(["0", "1", "2"])) for _ in range(3)]
        comps[draw(st.integers(0, 2))] = draw(st.one_of(BAD_NUMBERS, HOSTILE_TEXT))[:40]
        return ",".join(comps) + " " + draw(st.sampled_from(UNITS_BY_DIM.get(dim_name, ["m"])))
    if how == 2:
        return draw(st.sampled_from(["(", "[", "(("])) + text.strip("()[]") + draw(
            st.sampled_from(["]", ")", "", "))"]))
    return corrupt(draw, text, dim_name)


def scene_pieces(draw, scene_name: str, *, standard: dict[str, str] | None = None):
    """Well-formed parameters of a scene: every required one, some optional ones, one of each
    one-of group. ``standard`` maps parameter names to the option that may give them."""
    scene = get_scene(scene_name)
    groups = {name: group for group in scene.one_of for name in group}
    picked_group = {group: draw(st.sampled_from(group)) for group in scene.one_of}
    pieces = []
    for p in scene.params:
        group = groups.get(p.name)
        if group is not None:
            wanted = picked_group[group] == p.name and (p.dim is not None or draw(PERCENT) < 60)
        elif p.default is None and not p.optional:
            wanted = draw(PERCENT) < 95
        else:
            wanted = draw(PERCENT) < 30
        if not wanted:
            continue
        if p.dim is None:
            text = draw(st.sampled_from(list(p.choices)))
        elif p.name == "zeta":
            text = draw(st.sampled_from(["0", "0.05", "0.5", "1", "2", "0.999", "1e-300", "5%"]))
        elif p.dim.name == "angle":
            text = draw(st.sampled_from(["10deg", "30 deg", "90deg", "170deg", "179.9999deg",
                                         "1e-200 rad", "0.5 rad", "3 rad", "1deg", "0deg"]))
        else:
            text = value(draw, p.dim.name)
        option = (standard or {}).get(p.name)
        if option is not None and draw(st.booleans()):
            pieces.append(opt(option, text, p.dim.name if p.dim else None))
        else:
            pieces.append(assign(p.name, text, p.dim.name if p.dim else None))
    return pieces


PLOT_DIR = Path(tempfile.mkdtemp(prefix="dyncalc-fuzz-"))
atexit.register(shutil.rmtree, PLOT_DIR, ignore_errors=True)


def plot_path(draw) -> str:
    """A --plot target, always inside :data:`PLOT_DIR` (the fuzz never writes elsewhere)."""
    stem = draw(st.one_of(st.sampled_from(["decay", "decay", "a b", "[bold]", "x" * 300, "",
                                           ".", "\x00", "\u202e", "nodir/x", "\U0001f4a9"]),
                          RANDOM_TEXT.map(lambda t: t[:20])))
    if stem != "nodir/x":
        stem = stem.replace("/", "_").replace("..", "_")
    ext = draw(st.sampled_from([".png", ".png", ".svg", ".pdf", ".txt", "", ".PNG", ".png "]))
    return str(PLOT_DIR / f"{stem}{ext}")


# -- recipes: the well-formed argument lists of each command

LINEAR_ELEMENTS = {
    "cantilever": [("l", "length"), ("EI", "flexural rigidity")],
    "simply-supported": [("l", "length"), ("E", "modulus"), ("I", "second moment of area")],
    "beam": [("c", "pure number"), ("l", "length"), ("EI", "flexural rigidity")],
    "axial": [("l", "length"), ("EA", "force")],
    "coil": [("G", "modulus"), ("d", "length"), ("D", "length"), ("n", "pure number")],
}
TORSIONAL_ELEMENTS = {
    "torsion-bar": [("l", "length"), ("GJ_t", "torsional rigidity")],
    "torsion-bar ": [("l", "length"), ("G", "modulus"), ("J_t", "second moment of area")],
}


def network_element(draw, torsional: bool, shared: dict, depth: int = 0) -> str:
    kind = draw(st.integers(0, 6 if depth < 3 else 1))
    if kind <= 2:
        return value(draw, "torsional stiffness" if torsional else "stiffness")
    if kind == 3:
        return draw(st.sampled_from(["inf", "1e308 N*m/rad" if torsional else "1e308 N/m"]))
    if kind == 4:
        how = draw(st.sampled_from(["series", "parallel"]))
        inner = [network_element(draw, torsional, shared, depth + 1)
                 for _ in range(draw(st.integers(1, 3)))]
        return f"{how}({', '.join(inner)})"
    table = TORSIONAL_ELEMENTS if torsional else LINEAR_ELEMENTS
    fname = draw(st.sampled_from(sorted(table)))
    args = []
    for pname, dim in table[fname]:
        text = value(draw, dim)
        if draw(PERCENT) < 15:  # leave it to a shared NAME=QUANTITY word
            shared.setdefault(pname, (text, dim))
        else:
            args.append(f"{pname}={text}")
    return f"{fname.strip()}({', '.join(args)})"


def recipe_network(draw) -> list[Piece]:
    torsional = draw(PERCENT) < 25
    shared: dict = {}
    pieces = [Piece([network_element(draw, torsional, shared)], 0,
                    "torsional stiffness" if torsional else "stiffness")
              for _ in range(draw(st.integers(1, 4)))]
    pieces += [assign(name, text, dim) for name, (text, dim) in shared.items()]
    return pieces


FREQUENCY_STANDARD = {"k": "--k", "m": "--m", "kt": "--kt", "J": "--inertia", "l": "--length",
                      "amplitude": "--amplitude", "zeta": "--zeta", "g": "--g"}


def recipe_frequency(draw) -> list[Piece]:
    scene = draw(st.sampled_from(SCENES))
    pieces = scene_pieces(draw, scene, standard=FREQUENCY_STANDARD)
    inferred = {"mass-spring", "torsional", "pendulum"}
    if scene not in inferred or draw(PERCENT) < 50:
        pieces.append(opt("--scene", scene))
    methods = get_scene(scene).methods
    if methods and draw(PERCENT) < 40:
        pieces.append(opt("--method", draw(st.sampled_from(["auto", *methods]))))
    if draw(PERCENT) < 12:  # an inverse problem (issue 10): a result given, one unknown
        target = draw(st.sampled_from(["omega", "f", "T", "zeta", "omega_d"]))
        dim = {"omega": "angular rate", "f": "frequency", "T": "time",
               "zeta": "pure number", "omega_d": "angular rate"}[target]
        pieces.append(assign(target, value(draw, dim), dim))
        numeric = [p.name for p in get_scene(scene).params if p.dim is not None]
        if numeric and draw(PERCENT) < 60:
            pieces.append(Piece([f"{draw(st.sampled_from(numeric))}=?"]))
    return pieces


DAMPING_SCENES = [s for s in ("rod-in-fluid", "pendulum-spring-dashpot", "frame-brace-damper")
                  if s in SCENES]


def recipe_damping(draw) -> list[Piece]:
    form = draw(st.integers(0, 4))
    pieces: list[Piece] = []
    if form == 0:
        pieces += [opt("--c", value(draw, "damping coefficient"), "damping coefficient"),
                   opt("--k", value(draw, "stiffness"), "stiffness"),
                   opt("--m", value(draw, "mass"), "mass")]
    elif form == 1:
        pieces.append(opt("--decrement", draw(st.one_of(POSITIVE, st.just("0"))),
                          "pure number"))
    elif form == 2:
        pieces.append(opt("--ratio", draw(st.sampled_from(["10", "2", "1", "1.0001", "1e300",
                                                           "1e308", "100"])), "pure number"))
        if draw(st.booleans()):
            pieces.append(opt("--cycles", draw(st.sampled_from(["1", "2", "10", "100", "1e6"])),
                              "pure number"))
    elif form == 3:
        x0 = draw(st.sampled_from([1.0, 12.1, 1e-300, 1e300, 5e-3]))
        r = draw(st.sampled_from([0.5, 0.9, 0.99, 0.999999, 1.0, 0.01, 1e-10]))
        n = draw(st.integers(2, 12))
        peaks = [x0 * r ** i for i in range(n)]
        if draw(st.booleans()):  # noise on the peaks
            peaks = [x * draw(st.floats(0.9, 1.1)) for x in peaks]
        unit = draw(st.sampled_from(["", " mm", " mV", " m", " deg"]))
        text = ", ".join(f"{x:.6g}" for x in peaks) + unit
        pieces.append(opt("--amplitudes", text, None, vector=False))
        if draw(PERCENT) < 40:
            pieces.append(opt("--method", draw(st.sampled_from(["log-linear", "nonlinear"]))))
    else:
        scene = draw(st.sampled_from(DAMPING_SCENES or SCENES))
        pieces.append(opt("--scene", scene))
        pieces += scene_pieces(draw, scene, standard={"g": "--g"})
        methods = get_scene(scene).methods
        if methods and draw(PERCENT) < 40:
            pieces.append(opt("--method", draw(st.sampled_from(["auto", *methods]))))
    if form != 0 and draw(PERCENT) < 40:
        pieces.append(opt("--omega", value(draw, "angular rate"), "angular rate"))
    if form in (1, 2, 3) and draw(PERCENT) < 15:
        pieces += [opt("--k", value(draw, "stiffness"), "stiffness"),
                   opt("--m", value(draw, "mass"), "mass")]
    if draw(PERCENT) < 4:
        pieces.append(Piece(["--plot", plot_path(draw)]))
    return pieces


BODIES = ["solid-sphere", "hollow-sphere", "solid-cylinder", "hollow-cylinder", "hoop"]


def recipe_rolling(draw) -> list[Piece]:
    pieces = [opt("--v0", value(draw, "velocity"), "velocity"),
              opt("--mu", draw(st.sampled_from(["0.3", "0.2", "0.05", "1", "1e-300", "1e300",
                                                "0.999", "5%"])), "pure number")]
    if draw(PERCENT) < 30:
        pieces.append(opt("--body", draw(st.sampled_from(BODIES))))
    elif draw(PERCENT) < 15:
        pieces.append(opt("--kappa", draw(st.sampled_from(["0", "0.4", "1", "2", "1e-300",
                                                           "1e300"])), "pure number"))
    if draw(PERCENT) < 40:
        pieces.append(opt("--radius", value(draw, "length"), "length"))
        if draw(st.booleans()):
            pieces.append(opt("--omega0", value(draw, "angular rate", signed=True),
                              "angular rate"))
    if draw(PERCENT) < 15:
        pieces.append(opt("--g", value(draw, "acceleration"), "acceleration"))
    if draw(PERCENT) < 30:
        pieces.append(opt("--incline", draw(st.sampled_from(
            ["10deg", "-10deg", "0", "45 deg", "-45deg", "89.9999deg", "-89.9999 deg", "0.1 rad",
             "1e-300 deg", "30\u00b0"])), "angle"))
    if draw(PERCENT) < 30:
        pieces.append(opt("--method", draw(st.sampled_from(["auto", "closed-form", "ode"]))))
    return pieces


def recipe_coriolis(draw) -> list[Piece]:
    pieces: list[Piece] = []
    scalar = draw(PERCENT) < 30
    earth = draw(PERCENT) < 30

    def vec(name, dim, signed=True):
        if scalar and name in ("--omega", "--vr", "--r", "--alpha"):
            return opt(name, value(draw, dim, signed=False), dim, vector=False)
        return opt(name, vector_text(draw, dim, signed=signed), dim, vector=True)

    if earth:
        pieces.append(opt("--latitude", draw(st.sampled_from(
            ["45deg", "-30 deg", "0", "90deg", "-90 deg", "51.5\u00b0", "1e-300 deg", "0.5"])),
            "angle"))
        if draw(st.booleans()):
            pieces.append(vec("--vr", "velocity"))
        else:
            pieces.append(opt("--speed", value(draw, "velocity"), "velocity"))
            pieces.append(opt("--heading", draw(st.sampled_from(["0deg", "90deg", "-45 deg",
                                                                 "360deg", "1 rad"])), "angle"))
        if draw(PERCENT) < 30:
            pieces.append(opt("--vertical", value(draw, "velocity", signed=True), "velocity"))
        if draw(PERCENT) < 20:
            pieces.append(opt("--omega", value(draw, "angular rate"), "angular rate"))
    else:
        pieces += [vec("--omega", "angular rate"), vec("--vr", "velocity")]
        for name, dim, percent in (("--r", "length", 35), ("--alpha", "angular acceleration", 20),
                                   ("--a0", "acceleration", 15), ("--ar", "acceleration", 15),
                                   ("--v0", "velocity", 15)):
            if draw(PERCENT) < percent:
                pieces.append(vec(name, dim))
    if draw(PERCENT) < 35:
        pieces.append(opt("--mass", value(draw, "mass"), "mass"))
    return pieces


DENSITY_UNITS = {"linear": ["kg/m", "g/cm", "lb/ft"], "areal": ["kg/m^2", "g/cm^2", "lb/in^2"],
                 "volume": ["kg/m^3", "g/cm^3", "lb/ft^3"]}
AXES = ["z", "x", "-y", "(1, 1, 0)", "[0, 0, 2]", "z through (0.1, 0, 0) m",
        "(1e300, 1e-300, 0) through (1e300, 0, 0) m", "x through [0, 1e-320, 2] in"]


def recipe_inertia(draw) -> list[Piece]:
    """One to three bodies (a fifth of them holes), each with its mass or density, its
    dimensions, and perhaps at= and along=; sometimes --axis."""
    pieces: list[Piece] = []
    for _ in range(draw(st.integers(1, 3))):
        kind = draw(st.sampled_from(sorted(BODY_DIMENSIONS)))
        args = []
        if kind == "point" or draw(PERCENT) < 70:
            args.append(f"m={value(draw, 'mass')}")
        else:
            unit = draw(st.sampled_from(DENSITY_UNITS[DENSITY_KIND[kind]]))
            args.append(f"rho={draw(st.sampled_from(PLAIN + EXTREME))} {unit}")
        args += [f"{d}={value(draw, 'length')}" for d in BODY_DIMENSIONS[kind]]
        for key, dim, unit in (("at", "length", True), ("along", "pure number", False)):
            if draw(PERCENT) < 50:
                comps = ", ".join(draw(st.sampled_from(["0", "1", "-1", "2.5", "1e-300",
                                                        "1e300", "-3"])) for _ in range(3))
                shown = draw(st.sampled_from(UNITS_BY_DIM["length"])) if unit else ""
                args.append(f"{key}=({comps}) {shown}".rstrip())
        if draw(PERCENT) < 15:
            args.append(f"along={draw(st.sampled_from(['x', 'y', 'z', '-x']))}")
        sign = "-" if draw(PERCENT) < 20 else ""
        pieces.append(Piece([f"{sign}{kind}({', '.join(draw(st.permutations(args)))})"]))
    if draw(PERCENT) < 40:
        pieces.append(opt("--axis", draw(st.sampled_from(AXES))))
    return pieces


#: Textbook example ids: those the scenes cite (one scene or several) and one none cites.
EXAMPLE_IDS = sorted({e for name in SCENES for e in get_scene(name).examples}) + ["E9.99"]


def recipe_scenes(draw) -> list[Piece]:
    pieces = []
    if draw(PERCENT) < 80:
        pieces.append(Piece([draw(st.sampled_from(SCENES + EXAMPLE_IDS))], 0, None))
    if draw(PERCENT) < 20:
        pieces.append(opt("--command", draw(st.sampled_from(COMMANDS))))
    if draw(st.booleans()):
        pieces.append(flag("--json"))
    return pieces


@dataclass
class Spec:
    """How to draw an argument list for one command: its recipe of well-formed pieces, every
    option it has (for the chaos level) and its result names."""

    recipe: object
    options: dict[str, str | None]           # option -> dimension of its value (None: text)
    results: list[str]
    result_dims: dict[str, str] = field(default_factory=dict)
    flags: list[str] = field(default_factory=list)
    words: bool = True                        # takes NAME=QUANTITY / element positionals


def methods_of(scenes):
    names = {"auto"}
    for s in scenes:
        names.update(get_scene(s).methods)
    return sorted(names)


SPECS: dict[str, Spec] = {
    "spring-series": Spec(recipe_network, {}, ["k_eq", "k1", "k2", "k3"],
                          {"k_eq": "stiffness", "k1": "stiffness", "k2": "stiffness"}),
    "spring-parallel": Spec(recipe_network, {}, ["k_eq", "k1", "k2", "k3"],
                            {"k_eq": "stiffness", "k1": "stiffness", "k2": "stiffness"}),
    "natural-frequency": Spec(
        recipe_frequency,
        {"--scene": None, "--k": "stiffness", "--m": "mass", "--kt": "torsional stiffness",
         "--inertia": "mass moment of inertia", "--length": "length", "--amplitude": "angle",
         "--zeta": "pure number", "--g": "acceleration", "--method": None},
        ["omega", "f", "T", "zeta", "omega_d", "f_d", "T_d", "omega_1", "omega_2", "f_1"],
        {"omega": "angular rate", "f": "frequency", "T": "time", "T_d": "time",
         "omega_d": "angular rate", "f_d": "frequency", "omega_1": "angular rate",
         "f_1": "frequency", "zeta": "pure number"}),
    "damping-ratio": Spec(
        recipe_damping,
        {"--c": "damping coefficient", "--k": "stiffness", "--m": "mass",
         "--decrement": "pure number", "--ratio": "pure number", "--cycles": "pure number",
         "--amplitudes": None, "--scene": None, "--omega": "angular rate",
         "--g": "acceleration", "--method": None, "--plot": None},
        ["zeta", "delta", "c_c", "c", "omega_d", "T_d", "f_d", "Q", "regime", "s_fit"],
        {"zeta": "pure number", "delta": "pure number", "c_c": "damping coefficient",
         "c": "damping coefficient", "omega_d": "angular rate", "T_d": "time",
         "Q": "pure number"}),
    "rolling-onset": Spec(
        recipe_rolling,
        {"--v0": "velocity", "--mu": "pure number", "--body": None, "--kappa": "pure number",
         "--radius": "length", "--omega0": "angular rate", "--g": "acceleration",
         "--incline": "angle", "--method": None},
        ["t_roll", "x_roll", "v_roll", "omega_roll", "path_roll", "mu_min"],
        {"t_roll": "time", "x_roll": "length", "v_roll": "velocity",
         "omega_roll": "angular rate", "path_roll": "length", "mu_min": "pure number"},
        words=False),
    "coriolis": Spec(
        recipe_coriolis,
        {"--omega": "angular rate", "--vr": "velocity", "--r": "length",
         "--alpha": "angular acceleration", "--a0": "acceleration", "--ar": "acceleration",
         "--mass": "mass", "--latitude": "angle", "--speed": "velocity", "--heading": "angle",
         "--vertical": "velocity", "--v0": "velocity",
         "--scene": None, "--R0": "length", "--t": "time", "--basis": None, "--plot": None},
        ["a_c", "a_c_mag", "F_c", "F_c_mag", "a_transport", "a", "a_mag", "a_euler",
         "a_centripetal", "v_transport", "v", "v_mag", "a_transport_mag"],
        {"a_c_mag": "acceleration", "F_c_mag": "force", "a_mag": "acceleration",
         "v_mag": "velocity"},
        words=False),
    "inertia": Spec(
        recipe_inertia, {"--axis": None},
        ["m", "r_c", "J_O", "J_C", "J_1", "J_2", "J_3", "axis_1", "J_axis",
         "radius_of_gyration"],
        {"m": "mass", "J_1": "mass moment of inertia", "J_axis": "mass moment of inertia",
         "radius_of_gyration": "length"}),
    "scenes": Spec(recipe_scenes, {"--command": None}, [], flags=["--json"]),
}

#: Options of a command that the grammar does not draw, and why.
NOT_DRAWN = {
    "--debug": "shows a traceback by design",
    "--help": "drawn as a junk word",
    "--batch": "reads files: batch robustness is item 4 of issue 9 (a later suite)",
    "--on-error": "goes with --batch",
    "--explain-format": "hidden: what --explain=FORMAT is rewritten into (drawn as such)",
}
OUTPUT_FLAGS = ["--json", "--explain", "--strict-units", "--explain=markdown",
                "--explain=latex", "--explain=text"]
OUTPUT_OPTIONS = ["--value", "--unit", "--digits", "--check", "--rtol", "--format"]
FORMATS = ["table", "markdown", "csv", "tsv"]

#: Values of the options whose value is a name or a path, not a quantity.
NAMED_VALUES = {
    "--scene": SCENES + ["mass_spring", "Mass-Spring", "pendulum "],
    "--method": methods_of(SCENES) + ["log-linear", "nonlinear", "closed-form", "exact",
                                      "small-damping", "ODE"],
    "--body": BODIES + ["sphere", "Hoop"],
    "--format": FORMATS + ["CSV", "html", "latex"],
    "--basis": ["rotating", "fixed", "Fixed", "inertial"],
}


def output_pieces(draw, spec: Spec) -> list[Piece]:
    """Well-formed output options (--json, --value, --unit, --digits, --check, --rtol, ...)."""
    pieces = []
    for name in OUTPUT_FLAGS:
        if draw(PERCENT) < 15:
            pieces.append(flag(name))
    results = spec.results or ["x"]
    if draw(PERCENT) < 20:
        pieces.append(Piece(["--value", draw(st.sampled_from(results))], 1, None))
    if draw(PERCENT) < 20:
        name = draw(st.sampled_from(results))
        units = [u for u in UNITS_BY_DIM.get(spec.result_dims.get(name, ""), ANY_UNIT) if u]
        unit = draw(st.sampled_from(units or ANY_UNIT))
        pieces.append(Piece(["--unit", f"{name}={unit}"], 1, None))
    if draw(PERCENT) < 8:
        pieces.append(Piece(["--digits", str(draw(st.integers(1, 17)))], 1, None))
    if draw(PERCENT) < 10:
        pieces.append(Piece(["--format", draw(st.sampled_from(FORMATS))], 1, None))
    if draw(PERCENT) < 20:
        name = draw(st.sampled_from(results))
        dim = spec.result_dims.get(name)
        pieces.append(Piece(["--check", f"{name}={value(draw, dim)}"], 1, dim,
                            prefix=f"{name}="))
    if draw(PERCENT) < 12:
        pieces.append(Piece(["--rtol", draw(st.sampled_from(
            ["1e-2", "1e-9", "1e-15", "1e-300", "0.5", "1e-16", "0.999999", "1e-12"]))], 1,
            None))
    return pieces


JUNK = [["--"], ["-"], ["--nonexistent"], ["-x"], ["--json=yes"], ["--help"], ["-h"],
        ["--k"], ["--value"], ["--unit"], ["--check"], ["--digits"], ["--rtol"],
        ["--explain=1"], ["--k="], ["--m", "--k"], ["extra"], ["--scene"], ["--version"],
        ["---"], ["--\x1b[31m"], ["-\u2212k"], ["\u2014k"], ["--\uff4b", "1"], ["@file"],
        ["--digits", "0"], ["--digits", "99"], ["--digits", "six"], ["--rtol", "0"],
        ["--rtol", "1"], ["--rtol", "nan"], ["--rtol", "-1"], ["--rtol", "inf"],
        ["--rtol", "1e999"], ["--value", ""], ["--unit", "="], ["--check", "="],
        ["--check", "x"], ["--unit", "k_eq"]]


def _corrupt_piece(draw, piece: Piece) -> Piece:
    """The piece with its value replaced by a bad one (or, for a name, a strange name)."""
    if piece.slot is None:
        return Piece([draw(FRAGMENT)] if draw(st.booleans()) else piece.words)
    old = piece.words[piece.slot][len(piece.prefix):]
    if piece.words[0] in NAMED_VALUES and piece.slot == 1:
        new = draw(st.one_of(HOSTILE_TEXT, RANDOM_TEXT, st.just(_mutate(draw, old))))
    elif piece.vector:
        new = corrupt_vector(draw, old, piece.dim or "")
    else:
        new = corrupt(draw, old, piece.dim)
    prefix = piece.prefix
    if prefix and draw(PERCENT) < 15:  # the NAME= itself goes wrong
        prefix = draw(st.sampled_from([prefix.replace("=", "=="), prefix.replace("=", ":"),
                                       prefix.replace("=", " = "), "=", "",
                                       draw(FRAGMENT)[:10] + "="]))
        new = old if draw(st.booleans()) else new
    words = list(piece.words)
    words[piece.slot] = prefix + new
    return Piece(words, piece.slot, piece.dim, piece.prefix, piece.vector)


def _stray_option(draw, spec: Spec, command: str) -> Piece:
    """Any option of the command, with a value drawn for it (well-formed or not)."""
    names = sorted(spec.options) + (OUTPUT_OPTIONS if command != "scenes" else [])
    if not names:
        return Piece(draw(st.sampled_from(JUNK)))
    name = draw(st.sampled_from(names))
    dim = spec.options.get(name)
    if name in NAMED_VALUES:
        text = draw(st.one_of(st.sampled_from(NAMED_VALUES[name]), HOSTILE_TEXT))
    elif name == "--amplitudes":
        text = draw(st.one_of(HOSTILE_TEXT, st.lists(NUMBERS, max_size=8).map(", ".join)))
    elif name == "--plot":
        text = plot_path(draw)
    elif name in OUTPUT_OPTIONS:
        result = draw(st.one_of(st.sampled_from(spec.results or ["x"]), HOSTILE_TEXT))
        text = {"--value": result, "--unit": f"{result}={draw(st.sampled_from(ANY_UNIT))}",
                "--check": f"{result}={draw(quantity(None))}"}.get(
            name, draw(st.one_of(NUMBERS, HOSTILE_TEXT)))
    else:
        text = draw(quantity(dim))
    return opt(name, text, dim)


def _stray_word(draw) -> Piece:
    """A NAME=QUANTITY word of any scene parameter, or a name no scene has."""
    name = draw(st.one_of(st.sampled_from(ALL_PARAM_NAMES),
                          st.sampled_from(["f", "omega", "T", "k_eq", "x", "K", "_", "k.x", "1k",
                                           "", "k k", "[bold]", "\u00b5", "EI", "E", "l"]),
                          RANDOM_TEXT.map(lambda t: t[:8])))
    dims = PARAM_DIMS.get(name, {None})
    dim = min(dims, key=str)
    dim = None if dim == "choice" else dim
    return assign(name, draw(quantity(dim)), dim)


LEVELS = st.sampled_from(["clean", "clean", "clean", "clean", "one", "one", "one", "one",
                          "chaos", "chaos"])


@st.composite
def argv_for(draw, command: str, level: str | None = None):
    """An argument list for ``dyncalc COMMAND``. The level of the case decides how hostile it
    is: ``clean`` (a well-formed request from the command's recipe, with extreme but valid
    values), ``one`` (the same with exactly one value made bad) or ``chaos`` (values bad half
    of the time, stray options and words, junk)."""
    spec = SPECS[command]
    level = level or draw(LEVELS)
    pieces = spec.recipe(draw)
    if command != "scenes":
        pieces += output_pieces(draw, spec)
    if level == "one":
        slots = [i for i, p in enumerate(pieces) if p.slot is not None]
        if slots:
            i = draw(st.sampled_from(slots))
            pieces[i] = _corrupt_piece(draw, pieces[i])
        else:
            pieces.append(Piece(draw(st.sampled_from(JUNK))))
    elif level == "chaos":
        pieces = [_corrupt_piece(draw, p) if draw(st.booleans()) else p for p in pieces]
        if pieces and draw(PERCENT) < 30:  # something left out
            del pieces[draw(st.integers(0, len(pieces) - 1))]
        for _ in range(draw(st.integers(0, 3))):
            pieces.append(_stray_option(draw, spec, command))
        if spec.words or draw(PERCENT) < 10:
            for _ in range(draw(st.integers(0, 2))):
                pieces.append(_stray_word(draw))
        if draw(PERCENT) < 50:
            pieces.append(Piece(draw(st.sampled_from(JUNK))))
    order = draw(st.permutations(range(len(pieces)))) if draw(PERCENT) < 50 else range(
        len(pieces))
    return [command] + [w for i in order for w in pieces[i].words]


def any_argv():
    """Argument lists of any command, or junk in the command's place."""
    return st.one_of(
        st.sampled_from(COMMANDS).flatmap(argv_for),
        st.lists(st.one_of(HOSTILE_TEXT, st.sampled_from(COMMANDS + ["--help", "--version",
                                                                     "help", "spring", ""]),
                           RANDOM_TEXT), max_size=4),
    )


# ---------------------------------------------------------------------------------------------
# Running one case and judging it


class Hang(BaseException):
    """Raised by the alarm: a call ran for :data:`ALARM` seconds (BaseException, so neither
    the program's catch-all nor CliRunner swallows it)."""


@contextlib.contextmanager
def alarm(seconds: float):
    """Interrupt the block after ``seconds`` (POSIX, main thread); a no-op elsewhere."""
    main = threading.current_thread() is threading.main_thread()
    if not hasattr(signal, "setitimer") or not main:
        yield
        return

    def ring(signum, frame):
        raise Hang(f"no answer after {seconds:g} s")

    old = signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


#: Warnings the real interpreter does not print by default (so they cannot reach stderr).
_SILENT_WARNINGS = (DeprecationWarning, PendingDeprecationWarning, ImportWarning,
                    ResourceWarning)
_RUNNER_ENV = {"NO_COLOR": None, "FORCE_COLOR": None, "DYNCALC_PLAIN": None,
               "TTY_COMPATIBLE": None, "TTY_INTERACTIVE": None, "COLUMNS": "100"}
_BIDI = set("\u061c\u200e\u200f\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069")


@dataclass
class Outcome:
    """What one run printed and returned, and the contract rules it broke (``problems``)."""

    argv: list[str]
    exit_code: int | None
    stdout: str
    stderr: str
    seconds: float
    warnings: list[str]
    exception: str | None
    problems: list[str] = field(default_factory=list)
    retimed: float | None = None  # the first, slower time of a case that was run twice

    def describe(self) -> str:
        again = f" (first run {self.retimed:.3f} s)" if self.retimed is not None else ""
        return (f"argv={self.argv!r}\nexit={self.exit_code} in {self.seconds:.3f} s{again}\n"
                f"problems={self.problems}\nstdout={self.stdout[:800]!r}\n"
                f"stderr={self.stderr[:1500]!r}\nwarnings={self.warnings[:5]}\n"
                f"exception={self.exception}")


def run_cli(argv: list[str], tty: bool = False, retime: bool = True) -> Outcome:
    """``dyncalc ARGV`` in-process; ``tty`` takes the rich (terminal) output path. Colour is
    left on in click so that a raw escape sequence in the output is seen, not stripped.

    A call slower than :data:`CALL_LIMIT` is run once more and keeps the faster time
    (``retimed``): dyncalc is deterministic, so a second slow run is the program's doing,
    while one slow run next to a fast one is the machine's (a busy CI runner)."""
    out = _run_once(argv, tty)
    if retime and out.exception is None and out.seconds >= CALL_LIMIT:
        again = _run_once(argv, tty)
        again.retimed = out.seconds
        if again.seconds < out.seconds:
            out = again
        out.retimed = again.retimed
    return judge(out)


def _run_once(argv: list[str], tty: bool) -> Outcome:
    runner = CliRunner(env=_RUNNER_ENV)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with mock.patch("dyncalc.cli.options._is_terminal", return_value=tty):
            start = time.perf_counter()
            try:
                with alarm(ALARM):
                    result = runner.invoke(cli, argv, color=True)
            except Hang as exc:
                return Outcome(argv, None, "", "", time.perf_counter() - start, [],
                               f"Hang: {exc}")
            seconds = time.perf_counter() - start
    shown = [f"{w.category.__name__}: {w.message} ({w.filename}:{w.lineno})" for w in caught
             if not issubclass(w.category, _SILENT_WARNINGS)]
    exception = None
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        import traceback

        exception = "".join(traceback.format_exception(*result.exc_info))
    return Outcome(argv, result.exit_code, result.stdout, result.stderr, seconds, shown,
                   exception)


def _strict_constant(name):
    raise ValueError(f"{name} is not JSON")


_NAN_WORD = re.compile(r"(?<![\w.])[-+]?nan(?!\w)", re.IGNORECASE)


def judge(out: Outcome, limit: float = CALL_LIMIT) -> Outcome:
    """Fill ``out.problems`` with every rule of the contract the run broke."""
    p = out.problems
    if out.exception is not None:
        p.append("exception escaped: " + out.exception.strip().splitlines()[-1])
    if out.exit_code not in (0, 1, 2):
        p.append(f"exit status {out.exit_code}")
    if "Traceback" in out.stdout or "Traceback" in out.stderr:
        p.append("traceback printed")
    if "Error: internal error (" in out.stderr:  # not the user's own words echoed
        kind = re.search(r"Error: internal error \((\w+)", out.stderr)
        p.append(f"internal error ({kind.group(1) if kind else '?'})")
    lines = out.stderr.splitlines()
    if out.exit_code == 2:
        if len(lines) != 1 or not out.stderr.endswith("\n"):
            p.append(f"exit 2 with {len(lines)} stderr lines")
        elif not lines[0].startswith("Error: "):
            p.append("exit 2 without 'Error: '")
    elif out.exit_code in (0, 1):
        stray = [line for line in lines if not line.startswith(("warning:", "check "))]
        if stray:
            p.append(f"stray stderr line: {stray[0][:80]!r}")
    if out.exit_code == 1 and "FAIL" not in out.stdout + out.stderr \
            and '"pass": false' not in out.stdout:
        p.append("exit 1 without a failed check")
    if out.warnings:
        p.append("Python warning would reach stderr: " + out.warnings[0][:120])
    for stream, text in (("stdout", out.stdout), ("stderr", out.stderr)):
        bad = sorted({ch for ch in text if (unicodedata.category(ch) == "Cc"
                                            and ch not in "\n\t") or ch in _BIDI})
        if bad:
            p.append(f"raw control character in {stream}: "
                     + ", ".join(f"U+{ord(ch):04X}" for ch in bad))
    if out.exit_code in (0, 1) and out.stdout.lstrip().startswith("{"):
        try:
            json.loads(out.stdout, parse_constant=_strict_constant)
        except ValueError as exc:
            p.append(f"stdout is not strict JSON: {exc}")
    if out.exit_code in (0, 1) and _NAN_WORD.search(out.stdout):
        p.append("a result reads nan")
    if out.seconds >= limit:
        p.append(f"took {out.seconds:.2f} s")
    return out


def assert_contract(out: Outcome) -> None:
    assert not out.problems, out.describe()


def warm_up() -> None:
    """Import what the first call of each kind would import (pint's registry, scipy,
    matplotlib), so the hang guard measures the call, not the imports."""
    for argv in (["spring-series", "1", "2"],
                 ["natural-frequency", "--length", "1m", "--amplitude", "170deg", "--method",
                  "ode"],
                 ["rolling-onset", "--v0", "1", "--mu", "0.2", "--method", "ode"],
                 ["damping-ratio", "--amplitudes", "3,2,1", "--method", "nonlinear"],
                 ["damping-ratio", "--ratio", "2", "--omega", "1 rad/s", "--plot",
                  str(PLOT_DIR / "warm.png")],
                 ["coriolis", "--omega", "1", "--vr", "1"]):
        CliRunner().invoke(cli, argv)
    with mock.patch("dyncalc.cli.options._is_terminal", return_value=True):
        CliRunner().invoke(cli, ["spring-series", "1", "2", "--explain"])


@pytest.fixture(scope="module", autouse=True)
def _warm():
    warm_up()


# ---------------------------------------------------------------------------------------------
# The fuzz suite (a fixed, reproducible budget for CI)

#: Shrinking a failing case to a small one takes minutes on these grammars; CI reports the
#: first failing case as drawn (every bug the fuzz found has its own small test below).
#: DYNCALC_FUZZ_SHRINK=1 turns shrinking on when hunting a new failure.
_PHASES = [Phase.explicit, Phase.reuse, Phase.generate]
if os.environ.get("DYNCALC_FUZZ_SHRINK"):
    _PHASES.append(Phase.shrink)
FUZZ_SETTINGS = {"deadline": None, "derandomize": True, "database": None, "print_blob": True,
                 "phases": _PHASES,
                 "suppress_health_check": [HealthCheck.too_slow, HealthCheck.data_too_large,
                                           HealthCheck.filter_too_much,
                                           HealthCheck.large_base_example]}


def test_grammar_knows_every_option():
    """The grammar draws every option of every command (a new option needs a strategy)."""
    for command in COMMANDS:
        spec = SPECS[command]
        known = set(spec.options) | set(spec.flags) | set(NOT_DRAWN)
        if command != "scenes":
            known |= set(OUTPUT_FLAGS) | set(OUTPUT_OPTIONS)
        for param in cli.get_command(None, command).params:
            for name in getattr(param, "opts", []):
                if name.startswith("-"):
                    assert name in known or name == "-h", (command, name)


MIXED = "*"  # the mixed run: any command, or junk where the command belongs
TTY = st.integers(0, 9).map(lambda n: n == 0)  # one case in ten takes the terminal path


def fuzz_runner(command: str, examples: int, check, **overrides):
    """The hypothesis test of ``command`` (or :data:`MIXED`): ``examples`` argument lists from
    the grammar, each run and handed to ``check``. The CI tests check with
    :func:`assert_contract`; tools/fuzz_long.py counts instead (with the CI settings it draws
    exactly the CI cases: derandomize seeds from this function)."""
    strategy = any_argv() if command == MIXED else argv_for(command)

    @settings(max_examples=examples, **{**FUZZ_SETTINGS, **overrides})
    @given(argv=strategy, tty=TTY)
    def fuzz(argv, tty):
        check(run_cli(argv, tty))

    return fuzz


@pytest.mark.parametrize("command", COMMANDS)
def test_fuzz_command(command):
    """Arguments of ``command`` from its grammar, with hostile text mixed in."""
    fuzz_runner(command, CI_EXAMPLES[command], assert_contract)()


def test_fuzz_any_words():
    """Any command, or junk where the command belongs."""
    fuzz_runner(MIXED, CI_MIXED_EXAMPLES, assert_contract)()


# ---------------------------------------------------------------------------------------------
# The real process: python -m dyncalc with hostile argv

SUBPROCESS_LIMIT = 15.0  # a fresh interpreter imports pint, numpy, scipy: a generous bound

REAL_ARGV = [
    ["spring-series", "10**10**10 N/m", "3 N/m"],
    ["spring-series", "1" * 100_000],
    ["natural-frequency", "--k", "(" * 1000 + "1" + ")" * 1000, "--m", "1kg"],
    ["natural-frequency", "--k", "1,5 N/m", "--m", "\uff12kg"],
    ["coriolis", "--omega", "$(rm -rf /)", "--vr", "`id`"],
    ["rolling-onset", "--v0", "[link=http://x]5[/link] m/s", "--mu", "0.2"],
    ["damping-ratio", "--ratio", "nan", "--cycles", "1e999"],
    ["scenes", "\u202e" + "gnirps-ssam"],
    ["natural-frequency", "--k", "2 kN/m", "--m", "4kg", "--json"],
    ["spring-parallel", "1e308N/m", "1e308N/m"],
]


def run_real(argv, *, optimise: bool = False, env=None) -> Outcome:
    cmd = [sys.executable] + (["-O"] if optimise else []) + ["-m", "dyncalc", *argv]
    start = time.perf_counter()
    try:
        proc = subprocess.run(cmd, capture_output=True, timeout=60, cwd=ROOT, check=False,
                              env=env or {**os.environ, "PYTHONIOENCODING": "utf-8"})
    except subprocess.TimeoutExpired:
        return judge(Outcome([str(a) for a in argv], None, "", "", 60.0, [], "Hang: 60 s"),
                     SUBPROCESS_LIMIT)
    seconds = time.perf_counter() - start
    return judge(Outcome([os.fsdecode(a) if isinstance(a, bytes) else a for a in argv],
                         proc.returncode, proc.stdout.decode("utf-8", "backslashreplace"),
                         proc.stderr.decode("utf-8", "backslashreplace"), seconds, [], None),
                 SUBPROCESS_LIMIT)


@pytest.mark.parametrize("argv", REAL_ARGV, ids=range(len(REAL_ARGV)))
def test_real_process_hostile_argv(argv):
    assert_contract(run_real(argv))


def test_real_process_undecodable_argv():
    """Bytes that are not UTF-8 arrive as lone surrogates (surrogateescape)."""
    out = run_real([b"spring-series", b"5 \xff\xfe N/m", b"3 N/m"])
    assert_contract(out)
    assert out.exit_code == 2


def test_real_process_python_dash_O_refuses_alike():
    """pint leans on assert; dyncalc's reading of hostile text must not change under -O."""
    for argv in (["spring-series", "007 N/m", "1"], ["spring-series", "1,5 N/m", "1"],
                 ["natural-frequency", "--k", "N/mm", "--m", "1kg"],
                 ["natural-frequency", "--k", "5 % N/m", "--m", "1kg", "--value", "f"]):
        plain, optimised = run_real(argv), run_real(argv, optimise=True)
        assert_contract(plain)
        assert (plain.exit_code, plain.stdout, plain.stderr) == (
            optimised.exit_code, optimised.stdout, optimised.stderr)


def _run_on_terminal(argv: list[str]) -> tuple[int, bytes]:
    """Run ``python -m dyncalc ARGV`` with stdout and stderr on a pseudo-terminal."""
    pty = pytest.importorskip("pty")
    import select

    master, slave = pty.openpty()
    proc = subprocess.Popen([sys.executable, "-m", "dyncalc", *argv], stdin=subprocess.DEVNULL,
                            stdout=slave, stderr=slave, close_fds=True, cwd=ROOT)
    os.close(slave)
    data = b""
    try:
        while True:
            ready, _, _ = select.select([master], [], [], 30)
            if not ready:
                break
            try:
                chunk = os.read(master, 65536)
            except OSError:  # EIO: the child closed the terminal
                break
            if not chunk:
                break
            data += chunk
    finally:
        os.close(master)
        code = proc.wait(timeout=30)
    return code, data


@pytest.mark.parametrize("text", ["\x1b[31m5 N/m", "\x1b]8;;http://evil.example\x1b\\5 N/m",
                                  "\x1b[2J5 N/m", "\u202e5 m/N"])
def test_real_terminal_gets_no_escape_sequence_from_the_input(text):
    """SPEC.md: an error quotes the user's text safely. On a terminal (click strips escape
    sequences only when stderr is not one) the input's ESC must not reach the screen raw, nor
    a bidirectional override that reorders the line."""
    code, data = _run_on_terminal(["spring-series", text, "3 N/m"])
    assert code == 2
    line = data.decode("utf-8", "replace")
    assert line.startswith("Error: "), line
    assert "\x1b" not in line and "\u202e" not in line, repr(line)


# ---------------------------------------------------------------------------------------------
# Explicit cases: the silent misreadings of SPEC.md and runaway input, with their exact message


def refusal(argv) -> str:
    """The one ``Error:`` line of ``dyncalc ARGV``, asserting the contract and the 1 s limit."""
    out = run_cli(list(argv))
    assert_contract(out)
    assert out.exit_code == 2, out.describe()
    assert out.seconds < REFUSAL_LIMIT, out.describe()
    return out.stderr.rstrip("\n")


def _k(text):
    return ["natural-frequency", "--k", text, "--m", "1kg"]


SILENT_MISREADINGS = [
    # a comma inside a scalar ("1,5 m" is 15 m to pint)
    ("comma", _k("1,5 N/m"),
     "Error: --k: cannot read '1,5 N/m': a comma is neither a decimal point nor a thousands "
     "separator here; write 1.5 or 1500"),
    ("comma-thousands", ["natural-frequency", "--length", "1,000 mm"],
     "Error: --length: cannot read '1,000 mm': a comma is neither a decimal point nor a "
     "thousands separator here; write 1.5 or 1500"),
    # hexadecimal, octal and binary literals
    ("hex", _k("0x10 N/m"),
     "Error: --k: cannot read '0x10 N/m': hexadecimal, octal and binary literals are not read; "
     "write the number in decimal"),
    ("octal", _k("0o17 N/m"),
     "Error: --k: cannot read '0o17 N/m': hexadecimal, octal and binary literals are not read; "
     "write the number in decimal"),
    ("binary", _k("0b101 N/m"),
     "Error: --k: cannot read '0b101 N/m': hexadecimal, octal and binary literals are not read; "
     "write the number in decimal"),
    # a leading-zero integer (007 is 0 to pint on Python 3.11)
    ("leading-zero", _k("007 N/m"),
     "Error: --k: cannot read '007 N/m': the leading zero in '007' is ambiguous (octal?); "
     "write 7"),
    # a unit with no number ("N/mm" is 1000 N/m to pint)
    ("unit-without-number", _k("N/mm"),
     "Error: --k: cannot read 'N/mm': it has a unit but no number; write 1 N/mm if that is "
     "what you mean"),
    # comments
    ("comment", _k("5 N/m # x"),
     "Error: --k: cannot read '5 N/m # x': comments ('#') are not read"),
    # control and zero-width characters
    ("zero-width-space", _k("5\u200bN/m"),
     "Error: --k: cannot read '5\\u200bN/m': it holds an invisible or control character "
     "U+200B"),
    ("no-break-space", _k("5\u00a0N/m"),
     "Error: --k: cannot read '5\\u00a0N/m': it holds an invisible or control character "
     "U+00A0"),
    ("nul", _k("5\x00N/m"),
     "Error: --k: cannot read '5\\u0000N/m': it holds an invisible or control character "
     "U+0000"),
    ("rtl-mark", _k("\u200f5 N/m"),
     "Error: --k: cannot read '\\u200f5 N/m': it holds an invisible or control character "
     "U+200F"),
    # "±" and "+/-" are uncertainties (issue 10): never read as nothing, refused when misplaced
    ("plus-minus-twice", ["natural-frequency", "--k", "100 N/m", "--m", "2\u00b10.1\u00b10.1 kg"],
     "Error: --m: cannot read '2\u00b10.1\u00b10.1 kg': it has more than one uncertainty (+/- "
     "or \u00b1)"),
    ("plus-slash-minus-inside", ["natural-frequency", "--k", "100 N/m", "--m", "(2+/-0.1)*2 kg"],
     "Error: --m: cannot read '(2+/-0.1)*2 kg': only a unit may follow (value \u00b1 "
     "uncertainty): (100 \u00b1 5) N/m"),
    ("plus-minus-in-a-product", ["natural-frequency", "--k", "100 N/m", "--m", "2*(2+/-0.1) kg"],
     "Error: --m: cannot read '2*(2+/-0.1) kg': an uncertainty (+/- or \u00b1) goes once, at "
     "the top: 2.0+/-0.1 kg or (100 \u00b1 5) N/m"),
    # 1e999 read as infinity
    ("1e999", _k("1e999 N/m"),
     "Error: --k: cannot read '1e999 N/m': 1e999 overflows float64 (the largest is 1.8e308)"),
    ("1e400-bare", ["natural-frequency", "--k", "1e400", "--m", "1kg"],
     "Error: --k: cannot read '1e400': 1e400 overflows float64 (the largest is 1.8e308)"),
    ("negative-1e999", ["natural-frequency", "--k", "100 N/m", "--m", "-1e999 kg"],
     "Error: --m: cannot read '-1e999 kg': 1e999 overflows float64 (the largest is 1.8e308)"),
    ("1e-999", _k("1e-999 N/m"),
     "Error: --k: cannot read '1e-999 N/m': 1e-999 underflows float64 (the smallest is "
     "4.9e-324)"),
    ("result-overflow", ["spring-parallel", "1e308N/m", "1e308N/m"], None),
    # NaN is always refused
    ("nan", _k("nan"), "Error: --k: cannot read 'nan': NaN is not a number dyncalc accepts"),
    ("NaN-unit", _k("NaN N/m"),
     "Error: --k: cannot read 'NaN N/m': NaN is not a number dyncalc accepts"),
    ("inf-not-allowed", _k("inf N/m"), "Error: --k must be finite; got inf newton / meter"),
    # pint's "@" and "%" oddities
    ("at-sign", _k("5 @ N/m"),
     "Error: --k: cannot read '5 @ N/m': the character '@' is not part of a quantity"),
    ("lone-percent", ["natural-frequency", "--k", "1", "--m", "1", "--zeta", "%"],
     "Error: --zeta: cannot read '%': it has a unit but no number; write 1 % if that is what "
     "you mean"),
    ("percent-of-stiffness-dimension", ["natural-frequency", "--k", "50%", "--m", "1kg"],
     "Error: --k must be a stiffness [force]/[length]; got 50 percent (dimensionless)"),
    # two numbers side by side, digit separators ("1 000" is 0 to pint)
    ("space-thousands", _k("1 000 N/m"),
     "Error: --k: cannot read '1 000 N/m': two numbers side by side; write 1000, not 1 000, "
     "and use * to multiply"),
    ("underscore", _k("1_000 N/m"),
     "Error: --k: cannot read '1_000 N/m': digit separators ('_') are not read; write 1000, "
     "not 1_000"),
    # unicode digits and look-alikes
    ("fullwidth-digit", _k("\uff15 N/m"),
     "Error: --k: cannot read '\uff15 N/m': the digit '\uff15' is not an ASCII digit 0-9"),
    ("arabic-indic-digit", _k("\u0665 N/m"),
     "Error: --k: cannot read '\u0665 N/m': the digit '\u0665' is not an ASCII digit 0-9"),
    ("unicode-minus", ["natural-frequency", "--length", "1m", "--amplitude", "\u221230deg"],
     "Error: --amplitude: cannot read '\u221230deg': the character '\u2212' is not part of a "
     "quantity"),
    # rich markup is quoted, not interpreted
    ("markup", _k("[bold]5[/] N/m"),
     "Error: --k: cannot read '[bold]5[/] N/m': unknown unit 'bold'"),
    ("markup-link", _k("[link=http://x]5 N/m"),
     "Error: --k: cannot read '[link=http://x]5 N/m': the character '=' is not part of a "
     "quantity"),
    # counts are whole numbers
    ("fractional-count", ["damping-ratio", "--ratio", "2", "--cycles", "2.5"],
     "Error: --cycles must be a whole number of cycles (1, 2, 3, ...); got 2.5"),
    # a scene parameter given twice, or one the scene does not have
    ("parameter-twice", ["natural-frequency", "--k", "1", "--m", "1", "k=2"],
     "Error: k is given twice (--k and k=)"),
    ("unknown-parameter", ["natural-frequency", "--scene", "mass-spring", "k=1", "m=1", "x=2"],
     "Error: mass-spring has no parameter 'x'; the parameters of mass-spring are: "
     "k [force]/[length], m [mass], zeta dimensionless?"),
    # radians are not silently Hz, nor Hz radians
    ("hz-for-an-angular-rate", ["coriolis", "--omega", "2 Hz", "--vr", "1"],
     "Error: --omega is an angular rate; give it in rad/s, deg/s, rpm or rev/s, not Hz (a "
     "frequency in cycles)"),
    ("rad-per-s-for-a-frequency", ["natural-frequency", "--k", "1", "--m", "1", "--unit",
                                   "f=rad/s"],
     "Error: --unit f: f is a frequency in cycles; use omega for rad/s"),
    ("angle-for-a-pure-number", ["natural-frequency", "--k", "1", "--m", "1", "--zeta",
                                 "1 rad"],
     "Error: --zeta is a pure number, not an angle; got 1 radian"),
    # a bare number under --strict-units
    ("strict-units", ["natural-frequency", "--strict-units", "--k", "100", "--m", "1kg"],
     "Error: --k: '100' has no unit and --strict-units is on; write it with a unit, e.g. "
     "100 N/m"),
]


@pytest.mark.parametrize("name, argv, message", SILENT_MISREADINGS,
                         ids=[case[0] for case in SILENT_MISREADINGS])
def test_silent_misreading_is_refused(name, argv, message):
    line = refusal(argv)
    if message is None:  # result overflow: the wording is the runner's; the refusal is the rule
        assert line.startswith("Error: ") and "overflows float64" in line, line
    else:
        assert line == message


def test_read_right_not_refused():
    """What must be read, and read right (the other side of each refusal above)."""
    def value(*argv):
        out = run_cli(list(argv))
        assert_contract(out)
        return float(out.stdout)

    assert value("natural-frequency", "--k", "1", "--m", "1", "--zeta", "5%", "--value",
                 "zeta") == pytest.approx(0.05, rel=1e-15)
    assert value("spring-series", "0.5 N/m", "0.5 N/m", "--value", "k_eq") == 0.25
    assert value("spring-series", "5 \u00b5N/m", "5 \u03bcN/m", "--value",
                 "k_eq") == pytest.approx(2.5e-6, rel=1e-15, abs=0)
    assert value("spring-parallel", "1.5e3 N/m", "1E3 N/m", "--value", "k_eq") == 2500.0
    assert value("spring-parallel", "2 m\u00b2*N/m^3", "1", "--value", "k_eq") == 3.0


RUNAWAY = [
    ("length-10kB", _k("1" * 10_000),
     "Error: --k: the quantity is 10000 characters long; dyncalc reads at most 200"),
    ("length-201", _k("1" * 197 + " N/m"),
     "Error: --k: the quantity is 201 characters long; dyncalc reads at most 200"),
    ("length-100kB-element", ["spring-series", "9" * 100_000],
     "Error: element k1 (" + "9" * 40 + "): the quantity is 100000 characters long; dyncalc "
     "reads at most 200"),
    ("power-tower", _k("10**10**10 N/m"),
     "Error: --k: cannot read '10**10**10 N/m': chained powers (a**b**c) are not read; use "
     "parentheses"),
    ("power-tower-caret", _k("9^9^9"),
     "Error: --k: cannot read '9^9^9': chained powers (a**b**c) are not read; use parentheses"),
    ("huge-integer-power", _k("10**100000 N/m"),
     "Error: --k: cannot read '10**100000 N/m': its value overflows float64 (the largest is "
     "1.8e308)"),
    ("power-of-power", _k("(10**10)**(10**10) N/m"),
     "Error: --k: cannot read '(10**10)**(10**10) N/m': its value overflows float64 (the "
     "largest is 1.8e308)"),
    ("nested-exponent", _k("9**(9**9) N/m"),
     "Error: --k: cannot read '9**(9**9) N/m': its value overflows float64 (the largest is "
     "1.8e308)"),
    ("unit-power", _k("1 N/m**1000"),
     "Error: --k: cannot read '1 N/m**1000': the unit meter is raised to the power 1000; "
     "dyncalc reads powers up to 16"),
    ("factorial-chain", _k("*".join(str(i) for i in range(1, 70)) + " N/m"),
     "Error: --k: the quantity is 201 characters long; dyncalc reads at most 200"),
    ("deep-parentheses", _k("(" * 25 + "5" + ")" * 25 + " N/m"),
     "Error: --k: cannot read '" + "(" * 25 + "5" + ")" * 25 + " N/m': it is nested more "
     "than 24 levels deep"),
    ("deep-signs", _k("-" * 30 + "5 N/m"),
     "Error: --k: cannot read '" + "-" * 30 + "5 N/m': it is nested more than 24 levels deep"),
    ("deep-network", ["spring-series", "series(" * 17 + "5" + ")" * 17],
     "Error: the network is nested more than 16 levels deep"),
    ("deep-network-1000", ["spring-series", "series(" * 1000 + "5" + ")" * 1000], None),
    ("long-vector", ["coriolis", "--omega", "(" + ",".join(["0"] * 3000) + ") rad/s", "--vr",
                     "1,0,0"],
     "Error: --omega: the quantity is 6007 characters long; dyncalc reads at most 200"),
]


@pytest.mark.parametrize("name, argv, message", RUNAWAY, ids=[case[0] for case in RUNAWAY])
def test_runaway_input_is_refused_fast(name, argv, message):
    line = refusal(argv)
    if message is not None:
        assert line == message


def test_longest_products_under_the_limit_answer_fast():
    """A factorial-like chain that fits in 200 characters (59!) cannot overflow: it is read
    (as a float, not a big integer) and answered at once."""
    out = run_cli(_k("*".join(str(i) for i in range(1, 60)) + " N/m") + ["--value", "omega"])
    assert_contract(out)
    assert out.exit_code == 0 and out.seconds < REFUSAL_LIMIT
    assert float(out.stdout) == pytest.approx(math.sqrt(math.factorial(59)), rel=1e-12)
    out = run_cli(_k("99" + "*99" * 60 + " N/m"))  # 99**61 = 5e121: read, answered
    assert_contract(out)
    assert out.exit_code == 0 and out.seconds < REFUSAL_LIMIT


def test_refusals_stay_fast_at_scale():
    """The same runaway text a hundred times over: no refusal is slow, even the 100th."""
    start = time.perf_counter()
    for _ in range(100):
        refusal(_k("9**(9**9) N/m"))
        refusal(_k("(" * 25 + "5" + ")" * 25))
    assert time.perf_counter() - start < 100 * 2 * REFUSAL_LIMIT


# ---------------------------------------------------------------------------------------------
# Bugs the fuzz found, kept as failing tests until fixed (see docs/reliability.md)


@pytest.mark.parametrize("peaks", ["1e300,1e-300,1", "1e300,1e-300,1e300,1e-300",
                                   "1e308,1e-308,1"])
@pytest.mark.parametrize("method", ["log-linear", "nonlinear"])
def test_amplitudes_spanning_more_than_float_range_do_not_crash(peaks, method):
    """Peaks whose ratio to the first is beyond float64 (1e-300 after 1e300): the fit's
    ldexp scaling underflows to 0, log gives -inf, fsum raises ValueError -> 'internal error'
    and two numpy RuntimeWarnings on stderr."""
    out = run_cli(["damping-ratio", "--amplitudes", peaks, "--method", method])
    assert_contract(out)


def test_two_peaks_spanning_more_than_float_range_give_the_right_zeta():
    """1e300 then 1e-300: delta = ln(1e600) = 1381.55, zeta = delta / sqrt(4 pi^2 + delta^2);
    dyncalc answered zeta = nan with exit 0 (and RuntimeWarnings on stderr)."""
    out = run_cli(["damping-ratio", "--amplitudes", "1e300,1e-300", "--value", "zeta"])
    assert_contract(out)
    assert (out.exit_code, out.stderr) == (0, "")
    delta = 600 * math.log(10)
    assert float(out.stdout) == pytest.approx(delta / math.hypot(2 * math.pi, delta), rel=1e-12)


def test_nonlinear_fit_refuses_peaks_beyond_float_range():
    """The absolute-error fit cannot see a peak 1e-600 of the largest: refused, with the way
    out (the log-linear fit, which answers: see above)."""
    assert refusal(["damping-ratio", "--amplitudes", "1e300,1e-300,1", "--method",
                    "nonlinear"]) == (
        "Error: --method nonlinear: the peaks span more than float64's range (the smallest is "
        "below 2.2e-308 of the largest), so their absolute errors cannot be fitted; use "
        "--method log-linear")


@pytest.mark.parametrize("peaks", ["2,1", "8,4,2,1"])
def test_an_exact_fit_has_no_underflow_warning(peaks):
    """Two peaks, or peaks exactly geometric, fit with residual 0: exact, not an underflow."""
    out = run_cli(["damping-ratio", "--amplitudes", peaks])
    assert_contract(out)
    assert out.exit_code == 0 and "warning" not in out.stdout + out.stderr, out.describe()


@pytest.mark.parametrize("argv", [
    ["spring-series", "\x1b[31m5 N/m", "3 N/m"],
    ["spring-series", "5 kg\x1b[2J", "3 N/m"],
    ["natural-frequency", "--k", "1", "--m", "1", "--value", "x\x1b[2J"],
    ["spring-series", "\u202e5 m/N", "3 N/m"],
], ids=["ansi-colour", "ansi-clear-screen", "value-name", "bidi-override"])
def test_error_line_quotes_control_characters_safely(argv):
    """The label of an error repeats the user's text raw (``element k1 (<text>)``,
    ``--value <name>``); on a terminal click passes the escape sequence through."""
    out = run_cli(argv)
    assert_contract(out)


def test_error_line_shows_control_characters_as_escapes():
    """Bug 1's fix: the label keeps the user's text, with each unsafe character escaped."""
    assert refusal(["spring-series", "\x1b[31m5 N/m", "3 N/m"]) == (
        "Error: element k1 (\\u001b[31m5 N/m): cannot read '\\u001b[31m5 N/m': it holds an "
        "invisible or control character U+001B")
    assert refusal(["natural-frequency", "--k", "1", "--m", "1", "--value", "x\u2028\u202ey"]) == (
        "Error: --value x\\u2028\\u202ey: there is no result named 'x\\u2028\\u202ey'; the "
        "results are omega, f, T")


def test_one_line_escapes_every_unsafe_character():
    from dyncalc.errors import one_line

    assert one_line("a  b\n c") == "a b c"
    assert one_line("\x00\t\r\x1b\x7f\x85\x9b\u00a0\u200b\u202e\u2066\u2028\u2029\ufeff") == (
        "\\u0000\\u0009\\u000d\\u001b\\u007f\\u0085\\u009b\\u00a0\\u200b\\u202e\\u2066"
        "\\u2028\\u2029\\ufeff")
    assert one_line("\U000e0001 \U0010fffd") == "\\U000e0001 \\U0010fffd"
    assert one_line("µm² Ω é 5 N/m [bold]") == "µm² Ω é 5 N/m [bold]"


@pytest.mark.parametrize("argv", [
    ["spring-series", "cantilever(l=1e300 m, EI=1 N*m^2)", "1 N/m"],
    ["spring-series", "coil(G=1 Pa, d=1e-100 m, D=1 m, n=1)"],
    ["spring-series", "5 N/m", "axial(l=1e308 m, EA=1e-300 N)"],
], ids=["cantilever", "coil", "axial"])
def test_series_with_an_element_that_underflows_to_zero(argv):
    """An element function whose stiffness underflows to 0 (3 EI / l^3 with l = 1e300 m) in
    series: ``series_sum`` divides by the mantissa of 0 (ZeroDivisionError, 'internal error').
    SPEC.md: a result that underflows to zero while its inputs are non-zero comes with a
    warning (spring-parallel does exactly that for the same element)."""
    out = run_cli(argv)
    assert_contract(out)


def test_bead_on_rotating_ring_at_a_huge_spin():
    """``Omega = 1e200 rad/s``: ``BIFURCATION_ULPS * pull`` multiplies a float by an exact
    Fraction of 1e400 (OverflowError, 'internal error')."""
    out = run_cli(["natural-frequency", "--scene", "bead-on-rotating-ring", "r=1m",
                   "Omega=1e200rad/s"])
    assert_contract(out)


def test_rolling_onset_ode_json_with_an_overflowed_result():
    """x_roll overflows (null, with a warning); the ode method's error estimate against it is
    NaN, and ``json.dumps(allow_nan=False)`` raises ('internal error')."""
    out = run_cli(["rolling-onset", "--v0", "1.142e296 knot", "--mu", "1", "--body", "hoop",
                   "--method", "ode", "--json"])
    assert_contract(out)


@pytest.mark.parametrize("argv", [
    ["natural-frequency", "--scene", "coupled-blocks", "k1=1", "k2=1", "k3=1", "m1=1e-320",
     "m2=1"],
    ["natural-frequency", "--scene", "coupled-blocks", "k1=1e-300", "k2=1e-300", "k3=100",
     "m1=1e-300kg", "m2=1lb"],
], ids=["tiny-mass-divides-by-zero", "mode-shape-nan"])
def test_coupled_blocks_with_extreme_masses(argv):
    """``two_by_two_modes``: sqrt(m1 m2) underflows to 0 (ZeroDivisionError), or the mode
    vector is (inf, x) and normalising it gives NaN (exit 0 showing ``mode_2 (nan, 0)``, and
    numpy's RuntimeWarning on stderr)."""
    out = run_cli(argv)
    assert_contract(out)


def test_coupled_blocks_with_a_subnormal_mass_answers_right():
    """m1 = 1e-320 kg: (k1 + k3)/m1 = 2e320 is beyond float64, omega_2 = 1.41e160 rad/s is
    not. Block 1 follows block 2 statically in the slow mode (x1 = x2/2) and moves alone in
    the fast one (mpmath reference from the float inputs)."""
    import mpmath as mp

    out = run_cli(["natural-frequency", "--scene", "coupled-blocks", "k1=1", "k2=1", "k3=1",
                   "m1=1e-320", "m2=1", "--json"])
    assert_contract(out)
    data = json.loads(out.stdout)
    assert data["warnings"] == []
    results = {name: entry["value"] for name, entry in data["results"].items()}
    with mp.workdps(60):
        m1 = mp.mpf(1e-320)
        a, d, b2 = 2 / m1, mp.mpf(2), 1 / m1
        lam2 = (a + d) / 2 + mp.sqrt(((a - d) / 2) ** 2 + b2)
        lam1 = 3 / m1 / lam2
        assert results["omega_1"] == pytest.approx(float(mp.sqrt(lam1)), rel=1e-15)
        assert results["omega_2"] == pytest.approx(float(mp.sqrt(lam2)), rel=1e-15)
    assert results["mode_1"] == pytest.approx([1 / math.sqrt(5), 2 / math.sqrt(5)], rel=1e-15)
    assert results["mode_2"][0] == 1.0 and -1e-320 < results["mode_2"][1] < 0


def test_coupled_blocks_frequencies_do_not_underflow_on_the_way():
    """m1 = 1e200 kg, m2 = 1 kg, k1 = k2 = k3 = 1e-200 N/m: omega_2 = 1.414e-100 rad/s and
    omega_1 = 1.22e-200 rad/s are ordinary floats, but ``scale = ks / ms`` = 1e-400 underflows
    to 0, so dyncalc answers 0 for both with the warning that they underflow (a wrong answer,
    exit 0)."""
    import mpmath as mp

    mp.mp.dps = 50
    m1, m2, k1, k2, k3 = (mp.mpf(x) for x in (1e200, 1.0, 1e-200, 1e-200, 1e-200))
    a, d, b2 = (k1 + k3) / m1, (k2 + k3) / m2, k3 ** 2 / (m1 * m2)
    lam2 = (a + d + mp.sqrt((a - d) ** 2 + 4 * b2)) / 2
    lam1 = (k1 * k2 + k1 * k3 + k2 * k3) / (m1 * m2) / lam2
    argv = ["natural-frequency", "--scene", "coupled-blocks", "m1=1e200kg", "m2=1kg",
            "k1=1e-200N/m", "k2=1e-200N/m", "k3=1e-200N/m", "--json"]
    out = run_cli(argv)
    assert_contract(out)
    results = json.loads(out.stdout)["results"]
    for name, lam in (("omega_1", lam1), ("omega_2", lam2)):
        assert results[name]["value"] == pytest.approx(float(mp.sqrt(lam)), rel=1e-12, abs=0)


def test_check_json_with_a_relative_difference_beyond_float():
    """``--check k_eq=180 N/m`` against k_eq = 2e-320 N/m: ``run_checks`` computes the
    relative difference 180 / 2e-320 = inf, and ``json.dumps(allow_nan=False)`` raises
    ('internal error'; the human form prints the check and exits 1)."""
    argv = ["spring-parallel", "1e-320 N/m", "1e-320 N/m", "--check", "k_eq=180 N/m"]
    human = run_cli(argv)
    assert_contract(human)
    assert human.exit_code == 1
    out = run_cli([*argv, "--json"])
    assert_contract(out)


def test_quarter_car_with_a_huge_mass_and_speed():
    """``float(gap)`` of an exact Fraction beyond float64 (physics/rotating.py quarter_car):
    OverflowError, 'internal error'."""
    out = run_cli(["natural-frequency", "--scene", "quarter-car", "k=1", "m=1e305kg", "L=90m",
                   "U0=60m", "v0=1e9 mph"])
    assert_contract(out)


def test_plot_of_an_overdamped_decay_whose_time_axis_overflows():
    """k = 4.9e-324 N/m, m = 0.5 kg, c = 1 N*s/m: zeta = 3e161 and omega = 3e-162 rad/s;
    ``_draw_response`` divides the dimensionless time (up to 1.5e162) by omega and numpy
    prints 'RuntimeWarning: overflow encountered in divide' to stderr (exit 0)."""
    out = run_cli(["damping-ratio", "--c", "1", "--k", "4.941e-324", "--m", "0.5", "--plot",
                   str(PLOT_DIR / "overdamped.png"), "--value", "Q"])
    assert_contract(out)
    assert out.exit_code == 0
    assert out.stderr.splitlines()[-1] == (
        "warning: --plot: the decay lasts 2.93e+162 / omega with omega = 3.14e-162 rad/s, a "
        "time beyond float64, so the plot's time axis is dimensionless")


@pytest.mark.parametrize("argv", [
    ["coriolis", "--omega", "1e308,1,2 rev/s", "--vr", "1,0,0"],
    ["coriolis", "--omega", "1,1,1", "--vr", "1e308,0,0 km/s"],
], ids=["omega-rev-per-s", "vr-km-per-s"])
def test_vector_whose_conversion_overflows(argv):
    """A vector in a unit whose conversion to SI overflows: the refusal is right, but pint
    multiplies the numpy array first and numpy prints 'RuntimeWarning: overflow encountered
    in multiply' (two more stderr lines before the Error line)."""
    out = run_cli(argv)
    assert_contract(out)
    assert out.exit_code == 2
    label, shown, unit = (("--omega", "(1e+308, 1, 2) turn / second", "rad/s")
                          if argv[2].endswith("rev/s") else
                          ("--vr", "(1e+308, 0, 0) kilometer / second", "m/s"))
    assert out.stderr == f"Error: {label}: {shown} overflows float64 in {unit}\n"


def test_earth_heading_whose_degrees_overflow():
    """Bug 10 (second long run): ``--heading 2.62139e+307`` (radians) is finite, but in
    degrees it overflows and ``math.fmod(inf, 360)`` raised ('internal error'). Reduced in
    turns first, it is a whole number of turns: heading north, v_r = (0, 1, 0) m/s."""
    out = run_cli(["coriolis", "--latitude", "45deg", "--heading", "2.62139e+307 rad",
                   "--speed", "1 m/s", "--json"])
    assert_contract(out)
    assert out.exit_code == 0
    assert json.loads(out.stdout)["results"]["v_r"]["value"] == [0.0, 1.0, 0.0]


def test_damping_note_of_a_scene_whose_frequency_overflows():
    """Long run of issue 14 (seed 14): ``zeta=1e-300`` on a pendulum-on-rotating-disk whose
    omega overflows: the explanation said "nan% below omega" (1 - inf/inf). The drop is now
    worked out from zeta alone, zeta^2 / (1 + sqrt(1 - zeta^2)): 0 % here, 0.125 % at 0.05."""
    argv = ["natural-frequency", "zeta=1e-300", "--explain", "--scene",
            "pendulum-on-rotating-disk", "r=7.409e+279mm", "--json", "l=7  ft",
            "Omega=7.409e+279 1/s"]
    out = run_cli(argv)
    assert_contract(out)
    assumptions = json.loads(out.stdout)["extra"]["explanation"]["assumptions"]
    assert ("damping lowers the frequency: omega_d = omega sqrt(1 - zeta^2) is 0% below omega "
            "at zeta = 1e-300") in assumptions
    ordinary = json.loads(run_cli(["natural-frequency", "--k", "100N/m", "--m", "2kg", "--zeta",
                                   "0.05", "--explain", "--json"]).stdout)
    assert ("damping lowers the frequency: omega_d = omega sqrt(1 - zeta^2) is 0.125% below "
            "omega at zeta = 0.05") in ordinary["extra"]["explanation"]["assumptions"]


def test_damping_scene_solved_from_zeta_with_several_roots():
    """Found by a random sweep during issue 14: ``damping-ratio --scene rod-in-fluid
    l=1e-300m zeta=4.9e-324`` solves beta with five roots, whose results carry no zeta, and
    the command read ``results["zeta"]`` (internal error, KeyError). Every root has the zeta
    solved from, so it stays a result, with the decrement and Q it gives."""
    out = run_cli(["damping-ratio", "--scene", "rod-in-fluid", "m=0.5kg", "l=1e-300m",
                   "zeta=4.9e-324", "--json"])
    assert_contract(out)
    results = json.loads(out.stdout)["results"]
    assert [name for name in results if name.startswith("beta_")] == [
        f"beta_{i}" for i in range(1, 6)]
    assert results["zeta"]["value"] == 5e-324
    # 2 pi zeta among subnormals: a multiple of 4.9e-324 (6 of them), within its spacing
    assert results["delta"]["value"] == pytest.approx(2 * math.pi * 5e-324, rel=0.2)
    assert results["regime"]["value"] == "underdamped"
    # Q = 1/(2 zeta) overflows: null, with the warning every overflowed result gets
    assert results["Q"]["value"] is None
    assert ("Q overflows float64 at these inputs (beyond 1.8e308); it is left out (null in "
            "JSON)") in json.loads(out.stdout)["warnings"]
