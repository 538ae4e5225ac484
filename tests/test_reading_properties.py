"""Property tests of the quantity grammar (issue 15): generated *plausible user text* is read
by dyncalc and, independently, by pint on a fully parenthesised form that the test builds from
the same structure. Each text must either read to the same value and dimension (relative 1e-12;
angles counted as a dimension), or be refused with an ``InputError`` (exit status 2).

The generator knows the structure it writes, so it knows the reading SPEC.md asks for:
``a / 9.81 m/s^2`` is ``a / ((9.81) * (meter / second ** 2))``; a number's unit runs on over
``*``, ``/`` and names; a divisor inside a unit is its juxtaposed names (``m/s s`` is
``m / (s s)``); juxtaposed groups bind tighter than an explicit ``/``; ``*`` and ``/`` go left to
right; ``+`` and ``-`` come last.

Sizes: ``DYNCALC_PROPERTY_EXAMPLES`` (default 150 per test, the CI size, a few seconds) sets
the number of examples of each test; a long run (docs/reliability.md, "Reading properties")
sets it high and ``DYNCALC_PROPERTY_RANDOM=1`` to draw new examples instead of the suite's
fixed ones.
"""
from __future__ import annotations

import math
import os

import pint
import pytest
from click.testing import CliRunner
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dyncalc.cli import cli
from dyncalc.errors import InputError
from dyncalc.units import (ACCELERATION, ANGLE, ANGULAR_RATE, DIMENSIONLESS, FORCE, LENGTH,
                           MASS, MODULUS, STIFFNESS, TIME, TORSIONAL_STIFFNESS, parse_quantity)
from dyncalc.units.grammar import _evaluate

EXAMPLES = int(os.environ.get("DYNCALC_PROPERTY_EXAMPLES", "150"))
RANDOM = os.environ.get("DYNCALC_PROPERTY_RANDOM") == "1"
SETTINGS = settings(max_examples=EXAMPLES, deadline=None, derandomize=not RANDOM,
                    database=None, suppress_health_check=list(HealthCheck))
RTOL = 1e-12

#: The reference: a registry of its own, built once, never the program's.
REF = pint.UnitRegistry()

# (typed, pint name for the reference, power of [angle])
UNITS = {
    "length": [("m", "meter", 0), ("mm", "millimeter", 0), ("cm", "centimeter", 0),
               ("km", "kilometer", 0), ("µm", "micrometer", 0), ("in", "inch", 0),
               ("ft", "foot", 0)],
    "force": [("N", "newton", 0), ("kN", "kilonewton", 0), ("mN", "millinewton", 0),
              ("lbf", "force_pound", 0)],
    "mass": [("kg", "kilogram", 0), ("g", "gram", 0), ("lb", "pound", 0)],
    "time": [("s", "second", 0), ("ms", "millisecond", 0), ("min", "minute", 0),
             ("h", "hour", 0)],
    "angle": [("rad", "radian", 1), ("deg", "degree", 1), ("°", "degree", 1),
              ("grad", "grade", 1), ("arcmin", "arcminute", 1), ("arcsec", "arcsecond", 1),
              ("turn", "turn", 1), ("rev", "turn", 1), ("mrad", "milliradian", 1),
              ("degree", "degree", 1)],
    "pressure": [("Pa", "pascal", 0), ("kPa", "kilopascal", 0), ("MPa", "megapascal", 0),
                 ("GPa", "gigapascal", 0)],
    "other": [("J", "joule", 0), ("Hz", "hertz", 0), ("rpm", "revolutions_per_minute", 1)],
}
ALL_UNITS = [u for group in UNITS.values() for u in group]
RATIOS = [("%", "percent"), ("percent", "percent"), ("ppm", "ppm")]


# --------------------------------------------------------------------------------------------
# Generation: every piece is (typed text, reference text, angle power)


@st.composite
def numbers(draw, low=1e-3, high=1e6):
    """A positive decimal in any notation SPEC allows: 15, 1.5, .5, 5., 1e3, 1.5E-3, 2e+2."""
    mantissa = draw(st.integers(1, 99999))
    scale = draw(st.integers(-3, 3))
    value = mantissa * 10.0 ** scale
    value = min(max(value, low), high)
    style = draw(st.sampled_from(["int", "dec", "lead", "trail", "exp", "EXP", "exp+"]))
    if style == "int" and value == int(value) and value < 1e6:
        text = str(int(value))
    elif style == "lead" and value < 1:
        text = f"{value:.6f}".rstrip("0")[1:] or ".5"  # .5
    elif style == "trail" and value == int(value):
        text = f"{int(value)}."
    elif style.startswith("exp") or style == "EXP":
        m, e = f"{value:.6e}".split("e")
        m = m.rstrip("0").rstrip(".")
        e = int(e)
        sign = "+" if style == "exp+" and e >= 0 else ""
        text = f"{m}{'E' if style == 'EXP' else 'e'}{sign}{e}"
    else:
        text = repr(value)
    return text, f"({text})", 0


@st.composite
def factors(draw):
    """A unit with an optional power: m, m^2, s**-1, m², µm^3."""
    typed, ref, angle = draw(st.sampled_from(ALL_UNITS))
    power = draw(st.sampled_from([1, 1, 1, 2, 3, -1]))
    if power == 1:
        return typed, ref, angle
    styles = ["^", "**"] + (["sup"] if power in (2, 3) else [])
    style = draw(st.sampled_from(styles))
    shown = {"^": f"^{power}", "**": f"**{power}", "sup": "²" if power == 2 else "³"}[style]
    return f"{typed}{shown}", f"{ref} ** {power}", angle * power


@st.composite
def unit_groups(draw):
    """Juxtaposed factors (``kg m^2``): a divisor's extent inside a unit."""
    parts = draw(st.lists(factors(), min_size=1, max_size=2))
    return (" ".join(p[0] for p in parts), "(" + " * ".join(p[1] for p in parts) + ")",
            sum(p[2] for p in parts))


@st.composite
def units(draw):
    """A unit expression: groups joined by ``*`` and ``/``, left to right."""
    return _chain(draw, draw(unit_groups()), unit_groups())


def _chain(draw, first, parts):
    """``first`` (typed, reference, angle power) followed by up to two more of ``parts``,
    joined by ``*`` or ``/`` with or without spaces; the reference parenthesised left to
    right."""
    typed, ref, angle = first
    for _ in range(draw(st.integers(0, 2))):
        op = draw(st.sampled_from(["*", "/"]))
        g_typed, g_ref, g_angle = draw(parts)
        space = draw(st.sampled_from(["", " "]))
        # (in an expression, after an explicit op a group that starts with a name would join
        # the unit)
        typed = f"{typed}{space}{op}{space}{g_typed}"
        ref = f"({ref} {op} {g_ref})"
        angle = angle + g_angle if op == "*" else angle - g_angle
    return typed, ref, angle


@st.composite
def literals(draw):
    """A number with its unit (or none, or a ratio): ``9.81 m/s^2``, ``5%``, ``2``, ``30°``."""
    num_typed, num_ref, _ = draw(numbers())
    kind = draw(st.sampled_from(["unit", "unit", "unit", "none", "ratio"]))
    if kind == "none":
        return num_typed, num_ref, 0
    if kind == "ratio":
        typed, ref = draw(st.sampled_from(RATIOS))
        space = "" if typed == "%" and draw(st.booleans()) else " "
        return f"{num_typed}{space}{typed}", f"({num_ref} * {ref})", 0
    u_typed, u_ref, angle = draw(units())
    space = draw(st.sampled_from(["", " "])) if u_typed[0] not in "µ°" else ""
    if num_typed.endswith(".") and not space:
        space = " "
    if draw(st.integers(0, 9)) == 0:  # "(2) m", "(1.5 m)"
        if draw(st.booleans()):
            return f"({num_typed}) {u_typed}", f"({num_ref} * {u_ref})", angle
        return f"({num_typed}{space}{u_typed})", f"({num_ref} * {u_ref})", angle
    return f"{num_typed}{space}{u_typed}", f"({num_ref} * {u_ref})", angle


@st.composite
def groups(draw):
    """Juxtaposed literals, each after the first in parentheses: ``2 m (3 s)``."""
    typed, ref, angle = draw(literals())
    angles = [angle]
    for _ in range(draw(st.integers(0, 1))):
        l_typed, l_ref, l_angle = draw(literals())
        typed, ref = f"{typed} ({l_typed})", f"({ref} * {l_ref})"
        angles.append(l_angle)
    return typed, ref, sum(angles)


@st.composite
def expressions(draw):
    """Terms of groups joined by ``*`` and ``/`` (left to right), terms joined by + and -.
    Returns (typed, reference, angle power, whether the terms' angle powers agree)."""
    terms = []
    for _ in range(draw(st.sampled_from([1, 1, 1, 2]))):
        terms.append(_chain(draw, draw(groups()), groups()))
    typed, ref, angle = terms[0]
    agree = True
    for t_typed, t_ref, t_angle in terms[1:]:
        op = draw(st.sampled_from(["+", "-"]))
        typed, ref = f"{typed} {op} {t_typed}", f"({ref} {op} {t_ref})"
        agree = agree and t_angle == angle
    return typed, ref, angle, agree


# --------------------------------------------------------------------------------------------
# The reference reading


def ref_parse(ref_text: str):
    """pint's reading of a text, always a Quantity (pint 0.25.0 gives a bare number for a text
    without units, ``(1)``; later releases a dimensionless Quantity)."""
    value = REF.parse_expression(ref_text)
    return value if isinstance(value, REF.Quantity) else REF.Quantity(value)


def reference(ref_text: str):
    """pint's value of the parenthesised form, or ``None`` when pint refuses it (a sum of
    different dimensions): then dyncalc must refuse it too."""
    try:
        return ref_parse(ref_text)
    except (pint.DimensionalityError, pint.OffsetUnitCalculusError):
        return None


def base(quantity):
    """(magnitude, dimensionality text) in base units, radians kept as radians."""
    q = quantity.to_base_units() if hasattr(quantity, "to_base_units") else quantity
    mag = float(q.magnitude) if hasattr(q, "magnitude") else float(q)
    units = dict(q.unit_items()) if hasattr(q, "unit_items") else {}
    return mag, {name: power for name, power in units.items() if power}


def close(a: float, b: float, size: float = 0.0) -> bool:
    """Equal to RTOL relative to the larger, or to ``size`` (the sum of the magnitudes of a
    sum's terms: ``10 % (999.97 %) - 1`` cancels to -3e-5, and two correct roundings of
    its terms may differ there in the 7th digit)."""
    return a == b or abs(a - b) <= RTOL * max(abs(a), abs(b), size)


def scale(ref_text: str) -> float:
    """The sum of the magnitudes of the terms of a reference form (its ``-`` made ``+``;
    every number generated is positive), in base units."""
    if " - " not in ref_text:
        return 0.0
    try:
        return abs(float(ref_parse(ref_text.replace(" - ", " + "))
                         .to_base_units().magnitude))
    except pint.PintError:
        return 0.0


#: The dimension to ask for, by the reference's base units (angles aside).
DIMS = [
    ({"meter": 1}, [LENGTH]), ({"kilogram": 1}, [MASS]), ({"second": 1}, [TIME]),
    ({"kilogram": 1, "second": -2}, [STIFFNESS]),
    ({"kilogram": 1, "meter": 2, "second": -2}, [TORSIONAL_STIFFNESS]),
    ({"kilogram": 1, "meter": 1, "second": -2}, [FORCE]),
    ({"meter": 1, "second": -2}, [ACCELERATION]),
    ({"kilogram": 1, "meter": -1, "second": -2}, [MODULUS]),
    ({}, [ANGLE, DIMENSIONLESS]),
]


def dims_for(units: dict) -> list:
    plain = {k: v for k, v in units.items() if k != "radian"}
    for key, dims in DIMS:
        if plain == key:
            return dims
    return []


# --------------------------------------------------------------------------------------------
# Properties


def _read(text: str):
    """The grammar's reading, or ``None`` when refused (a sum of an angle and a non-angle is
    refused once the parameter's dimension is known: counted as refused here)."""
    try:
        reading = _evaluate(text, "x")
    except InputError:
        return None
    return None if reading.angle_mismatch else reading


@SETTINGS
@given(expressions())
def test_expression_reads_as_its_parenthesised_form(case):
    """The grammar: same value and same dimension (angles counted) as pint's reading of the
    parenthesised form, or a refusal."""
    typed, ref_text, angle, agree = case
    expected = reference(ref_text)
    reading = _read(typed)
    if reading is None:
        return
    assert expected is not None, f"{typed!r} read, but {ref_text!r} has no value"
    assert agree, f"{typed!r} adds an angle to a non-angle and was read"
    got_mag, got_units = base(reading.quantity)
    exp_mag, exp_units = base(expected)
    got_units.pop("radian", None)
    exp_units.pop("radian", None)
    assert got_units == exp_units, (typed, ref_text, got_units, exp_units)
    from dyncalc.units.dimensions import angle_power
    assert angle_power(reading.quantity) == angle, (typed, angle)
    # pint counts radians as dimensionless: compare in base units, radians included
    got = reading.quantity.to_base_units().magnitude
    want = expected.to_base_units().magnitude
    assert close(float(got), float(want), scale(ref_text)), (typed, ref_text, got, want)


@SETTINGS
@given(expressions())
def test_parameter_reads_to_its_si_value_or_is_refused(case):
    """The whole reading of a parameter: value in SI equal to pint's; the dimension, angles
    included, is the parameter's; a well-formed text of the right dimension is not refused."""
    typed, ref_text, angle, agree = case
    expected = reference(ref_text)
    if expected is None:
        return
    exp_mag, exp_units = base(expected)
    for dim in dims_for(exp_units):
        try:
            parsed = parse_quantity(typed, dim, label="x")
        except InputError as exc:
            fits = angle in dim.angles and agree
            if dim is DIMENSIONLESS:
                fits = fits and not any(u[0] in typed for u in UNITS["angle"] + [("rpm",)])
            if dim is ANGLE:
                fits = fits and "%" not in typed and "percent" not in typed
            # "turn" and "rev" next to other angles are fine; a refusal then is a bug
            assert not fits or "Hz" in typed or "rpm" in typed, (typed, dim.name, str(exc))
            continue
        if parsed.assumed_si:  # a bare number: the parameter's SI unit (SPEC)
            assert close(parsed.si, float(expected.to("dimensionless").magnitude)), typed
            continue
        assert angle in dim.angles, (typed, dim.name, angle)
        assert agree, (typed, "an angle added to a non-angle was read")
        want = expected.to(dim.si.replace("^", "**") or "dimensionless").magnitude \
            if dim.si else expected.to("dimensionless").magnitude
        size = scale(ref_text) and float(ref_parse(ref_text.replace(" - ", " + "))
                                          .to(dim.si.replace("^", "**") or "dimensionless")
                                          .magnitude)
        assert close(parsed.si, float(want), abs(size)), (typed, ref_text, dim.name,
                                                          parsed.si, want)


@st.composite
def rate_texts(draw):
    """An angular rate as people type it: 60 rpm, 30 deg/s, 2 rad/s, 3 1/s, 60 1/min, 5 Hz."""
    num_typed, num_ref, _ = draw(numbers(1e-2, 1e4))
    typed, ref, verdict = draw(st.sampled_from([
        ("rpm", "revolutions_per_minute", "rad"), ("rev/min", "turn/minute", "rad"),
        ("deg/s", "degree/second", "rad"), ("rad/s", "radian/second", "rad"),
        ("turn/s", "turn/second", "rad"), ("1/s", "1/second", "plain"),
        ("1/min", "1/minute", "refuse"), ("Hz", "hertz", "refuse"),
        ("s^-1", "1/second", "plain"), ("1/ms", "1/millisecond", "refuse")]))
    return f"{num_typed} {typed}", f"{num_ref} * {ref}", verdict


@SETTINGS
@given(rate_texts())
def test_angular_rate(case):
    """SPEC: angle per time, or a plain 1/s read as rad/s; 1/min and Hz refused."""
    typed, ref_text, verdict = case
    try:
        parsed = parse_quantity(typed, ANGULAR_RATE, label="--omega")
    except InputError:
        assert verdict == "refuse", typed
        return
    assert verdict != "refuse", typed
    q = ref_parse(ref_text)
    want = q.to("radian/second").magnitude if verdict == "rad" else q.to("1/s").magnitude
    assert close(parsed.si, want), (typed, parsed.si, want)


@st.composite
def uncertain_texts(draw):
    """Uncertain quantities in SPEC's forms, and with text after the uncertainty."""
    value, value_ref, _ = draw(numbers(1, 1e4))
    sigma, sigma_ref, _ = draw(numbers(1e-3, 1))
    unit_typed, unit_ref, _ = draw(st.sampled_from(UNITS["length"]))
    other_typed, other_ref, _ = draw(st.sampled_from(UNITS["length"]))
    pm = draw(st.sampled_from(["±", "+/-", " ± ", " +/- "]))
    form = draw(st.sampled_from(["shared", "paren", "both", "percent", "tail"]))
    if form == "shared":
        return f"{value}{pm}{sigma} {unit_typed}", (f"{value_ref} * {unit_ref}",
                                                   f"{sigma_ref} * {unit_ref}")
    if form == "paren":
        return f"({value}{pm}{sigma}) {unit_typed}", (f"{value_ref} * {unit_ref}",
                                                     f"{sigma_ref} * {unit_ref}")
    if form == "both":
        return f"{value} {unit_typed}{pm}{sigma} {other_typed}", (
            f"{value_ref} * {unit_ref}", f"{sigma_ref} * {other_ref}")
    if form == "percent":
        return f"{value} {unit_typed}{pm}{sigma}%", (
            f"{value_ref} * {unit_ref}", f"{value_ref} * {unit_ref} * {sigma_ref} / 100")
    tail = draw(st.sampled_from([" + 5 m", " - 1 mm", " * 2", " / 2", " 3", "*2 m"]))
    return f"{value} {unit_typed}{pm}{sigma} {other_typed}{tail}", None


@SETTINGS
@given(uncertain_texts())
def test_uncertainty(case):
    """Value and standard uncertainty as pint gives them; anything after the uncertainty's
    own unit is refused (SPEC v2), never folded into it."""
    typed, refs = case
    try:
        parsed = parse_quantity(typed, LENGTH, label="--length")
    except InputError:
        assert refs is None, typed
        return
    assert refs is not None, f"{typed!r}: text after the uncertainty was read"
    value = ref_parse(refs[0]).to("meter").magnitude
    sigma = ref_parse(refs[1]).to("meter").magnitude
    assert close(parsed.si, value) and close(parsed.uncertainty, sigma), (typed, parsed.si,
                                                                         parsed.uncertainty)


BAD = ["1_000 m", "1,5 m", "007 m", "0x1F m", "0o17 m", "1 000 m", "5 m # x", "N/mm", "m",
       "1.5.2 m", "2 3/4 m", "1e400 m", "nan m", "5 m\u200b", "5 m ± 1 cm ± 1 mm", "--5 m ++",
       "5 (m", "5 m)", "5 m/", "(1 ± 0.1) m + 2 m", "5 mm ± 1 cm 2", "1e3 e3 m", "5 m^m"]


@SETTINGS
@given(st.sampled_from(BAD), st.sampled_from(["", " ", "  "]))
def test_text_pint_would_misread_is_refused(bad, pad):
    """SPEC: text that pint reads silently wrong (1,5 m as 15 m, 007, 1_000, comments, ...)
    is refused."""
    with pytest.raises(InputError):
        parse_quantity(pad + bad + pad, LENGTH, label="--length")


@settings(max_examples=max(10, EXAMPLES // 5), deadline=None, derandomize=not RANDOM,
          database=None, suppress_health_check=list(HealthCheck))
@given(expressions())
def test_cli_stiffness_answer_or_exit_2(case):
    """Through the real program: ``natural-frequency --k TEXT --m 1kg --value omega`` either
    prints sqrt(k) for pint's k, or exits 2 with one ``Error:`` line."""
    typed, ref_text, angle, agree = case
    expected = reference(ref_text)
    result = CliRunner().invoke(cli, ["natural-frequency", "--k", typed, "--m", "1kg",
                                      "--value", "omega"])
    if result.exit_code == 2:
        lines = result.stderr.splitlines()
        assert len(lines) == 1 and lines[0].startswith("Error: "), result.stderr
        return
    assert result.exit_code == 0, (typed, result.exit_code, result.output)
    assert expected is not None and angle == 0 and agree, typed
    bare = expected.dimensionless and not any(ch.isalpha() or ch in "%°µ" for ch in typed
                                             if ch not in "eE")
    k = expected.to("dimensionless" if bare else "N/m").magnitude  # bare: SI (SPEC)
    assert close(float(result.stdout), math.sqrt(k)), (typed, result.stdout, k)
