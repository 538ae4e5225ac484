"""Reading quantities (dyncalc.units): the contract of SPEC.md "Quantities on the command line".

Every expected number is derived here from exact definitions (``fractions.Fraction`` for the
rational ones, ``mpmath`` for those with pi), never from pint; every refusal is pinned by the
exact text of ``str(InputError)``.
"""
import math
import subprocess
import sys
import time
from fractions import Fraction

import mpmath
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from dyncalc.errors import InputError
from dyncalc.units import (
    ACCELERATION, ANGLE, ANGULAR_RATE, AREA, CYCLE_RATE, DIMENSIONLESS, FORCE, INERTIA, LENGTH,
    MASS, MAX_DEPTH, MAX_TEXT, STIFFNESS, TIME, TORSIONAL_STIFFNESS, VELOCITY, convert,
    parse_quantity, parse_unit, parse_vector, registry, to_si,
)


# Exact definitions (NIST SP 811): 1 lbf = 4.4482216152605 N, 1 in = 0.0254 m.
LBF = Fraction("4.4482216152605")
INCH = Fraction("0.0254")
LBF_PER_IN = LBF / INCH                         # 175.126835246476377952755905511811... N/m
PI = mpmath.pi
HANG = 1.0                                      # seconds: a hang guard, generous on purpose


@pytest.fixture(autouse=True, scope="module")
def _warm_registry():
    """Build pint's registry once, so that no timed call pays for it."""
    registry()


def ulps_off(got, exact):
    """How many units in the last place ``got`` is from the exact value (Fraction or mpf)."""
    ref = float(exact)
    if isinstance(exact, Fraction):
        err = abs(Fraction(got) - exact)
    else:
        err = abs(mpmath.mpf(got) - exact)
    return float(err) / math.ulp(ref)


def refusal(fn, *args, **kwargs):
    """The message of the InputError ``fn`` raises; also asserts it answers in under HANG s."""
    start = time.perf_counter()
    with pytest.raises(InputError) as info:
        fn(*args, **kwargs)
    elapsed = time.perf_counter() - start
    assert elapsed < HANG, f"took {elapsed:.2f} s"
    assert isinstance(info.value, InputError)
    return str(info.value)


# ============================================================================================
# 1. Reading


@pytest.mark.parametrize("text, dim, exact, max_ulps, unit_text", [
    ("100 N/m", STIFFNESS, Fraction(100), 0, "N/m"),
    ("100N/m", STIFFNESS, Fraction(100), 0, "N/m"),
    ("2kg", MASS, Fraction(2), 0, "kg"),
    # 1500 lbf/in = 1500 * 4.4482216152605 N / 0.0254 m = 262690.25286971456692913... N/m;
    # pint builds lbf from pound * g0 and inch from yard/36, a few roundings: 4 ulps.
    ("1.5e3 lbf/in", STIFFNESS, 1500 * LBF_PER_IN, 4, "lbf/in"),
    ("1 lbf/in", STIFFNESS, LBF_PER_IN, 4, "lbf/in"),
    ("30deg", ANGLE, PI / 6, 1, "deg"),
    ("30°", ANGLE, PI / 6, 1, "°"),
    ("1 turn", ANGLE, 2 * PI, 1, "turn"),
    ("3 kN*m/rad", TORSIONAL_STIFFNESS, Fraction(3000), 0, "kN*m/rad"),
    ("1 kN*m/deg", TORSIONAL_STIFFNESS, 180000 / PI, 1, "kN*m/deg"),
    ("9.81 m/s^2", ACCELERATION, Fraction("9.81"), 0.5, None),
    ("9.81 m/s**2", ACCELERATION, Fraction("9.81"), 0.5, None),
    ("1 m + 30 cm", LENGTH, Fraction(13, 10), 1, ""),
    ("1 m - 30 cm", LENGTH, Fraction(7, 10), 1, ""),
    ("2*1.5 m", LENGTH, Fraction(3), 0, ""),
    ("(1+2**0.5)*1.5 m", LENGTH, (1 + mpmath.sqrt(2)) * Fraction(3, 2), 2, ""),
    ("[5] m", LENGTH, Fraction(5), 0, ""),
    ("5 %", DIMENSIONLESS, Fraction(5, 100), 1, "%"),
    ("5 \u00b5m", LENGTH, Fraction(5, 10**6), 1, "\u00b5m"),      # MICRO SIGN
    ("5 \u03bcm", LENGTH, Fraction(5, 10**6), 1, "\u03bcm"),      # GREEK SMALL LETTER MU
    ("1 \u00c5", LENGTH, Fraction(1, 10**10), 1, "\u00c5"),
    ("12 in", LENGTH, 12 * INCH, 1, "in"),
    ("2 kg*m^2", INERTIA, Fraction(2), 0, None),
    ("2 kg m^2", INERTIA, Fraction(2), 0, None),
    ("1.", DIMENSIONLESS, Fraction(1), 0, ""),
    (".5", DIMENSIONLESS, Fraction(1, 2), 0, ""),
    ("0e5", DIMENSIONLESS, Fraction(0), 0, ""),
    ("1.7976931348623157e308 m", LENGTH, Fraction(1.7976931348623157e308), 0, "m"),
])
def test_reads(text, dim, exact, max_ulps, unit_text):
    p = parse_quantity(text, dim, label="--x")
    assert isinstance(p.si, float)
    assert ulps_off(p.si, exact) <= max_ulps, (p.si, float(exact))
    assert p.assumed_si is False
    assert p.text == text
    if unit_text is not None:
        assert p.unit_text == unit_text


@pytest.mark.parametrize("text, dim, exact", [
    ("2 m\u00b2", AREA, 2.0),
    ("2 kg\u00b7m\u00b2", INERTIA, 2.0),
    ("1 cm\u00b2", AREA, 1e-4),
    ("2 m\u00b3/m", AREA, 2.0),
])
def test_reads_superscript_powers(text, dim, exact):
    """units.py maps ² and ³ to powers (_SUPERSCRIPTS); "m²" is an ordinary way to write m^2."""
    p = parse_quantity(text, dim, label="--x")
    assert ulps_off(p.si, Fraction(exact)) <= 1


@pytest.mark.parametrize("text, dim, unit_text", [
    ("2 kN/m", STIFFNESS, "kN/m"),
    ("100N/m", STIFFNESS, "N/m"),
    ("1.5e3 lbf/in", STIFFNESS, "lbf/in"),
    ("30deg", ANGLE, "deg"),
    ("2kg", MASS, "kg"),
    ("4", STIFFNESS, ""),
    ("1 m + 30 cm", LENGTH, ""),      # no single unit to echo: the SI unit is used instead
])
def test_unit_text(text, dim, unit_text):
    assert parse_quantity(text, dim).unit_text == unit_text


@pytest.mark.parametrize("text, dim, unit_text", [
    ("9.81 m/s^2", ACCELERATION, "m/s^2"),
    ("32.17 ft/s**2", ACCELERATION, "ft/s**2"),
    ("2 kg*m^2", INERTIA, "kg*m^2"),
    ("-2 kg", MASS, "kg"),
])
def test_unit_text_with_exponent_or_sign(text, dim, unit_text):
    """Parsed.unit_text is "the unit as the user wrote it": an exponent or a sign does not make
    the text have no unit (the echoed input would otherwise switch to SI)."""
    assert parse_quantity(text, dim).unit_text == unit_text


def test_bare_number_is_si_and_flagged():
    p = parse_quantity("4", STIFFNESS, label="--k")
    assert p.si == 4.0 and p.assumed_si is True and p.unit_text == ""
    assert str(p.quantity.units) == "newton / meter"
    p = parse_quantity("2", MASS, label="--m")
    assert p.si == 2.0 and p.assumed_si is True and str(p.quantity.units) == "kilogram"
    p = parse_quantity("30", ANGLE)
    assert p.si == 30.0 and p.assumed_si is True           # radians, not degrees
    p = parse_quantity("4", DIMENSIONLESS, label="--zeta")
    assert p.si == 4.0 and p.assumed_si is False
    p = parse_quantity("4 N/m", STIFFNESS)
    assert p.assumed_si is False


def test_strict_refuses_bare_number():
    assert refusal(parse_quantity, "4", STIFFNESS, label="--k", strict=True) == (
        "--k: '4' has no unit and --strict-units is on; write it with a unit, e.g. 4 N/m")
    assert refusal(parse_quantity, " 2 ", MASS, label="--m", strict=True) == (
        "--m: ' 2 ' has no unit and --strict-units is on; write it with a unit, e.g. 2 kg")
    # a pure number has no unit to give; a quantity with a unit passes
    assert parse_quantity("4", DIMENSIONLESS, strict=True).si == 4.0
    assert parse_quantity("4 N/m", STIFFNESS, strict=True).si == 4.0


def test_to_si():
    q = parse_quantity("2 kN/m", STIFFNESS).quantity
    assert to_si(q, STIFFNESS) == 2000.0
    assert refusal(to_si, q, MASS, "--m") == (
        "--m must be a mass [mass]; got 2 kilonewton / meter ([mass] / [time] ** 2)")


# ============================================================================================
# 2. Dimension errors


@pytest.mark.parametrize("text, dim, label, message", [
    ("5 kg", STIFFNESS, "--k",
     "--k must be a stiffness [force]/[length]; got 5 kilogram ([mass])"),
    ("1.5e3 lbf/in", MASS, "--m",
     "--m must be a mass [mass]; got 1500 force_pound / inch ([mass] / [time] ** 2)"),
    ("2 m", TORSIONAL_STIFFNESS, "--kt",
     "--kt must be a torsional stiffness [force]*[length]/[angle]; got 2 meter ([length])"),
    ("5 kg", INERTIA, "--inertia",
     "--inertia must be a mass moment of inertia [mass]*[length]^2; got 5 kilogram ([mass])"),
    ("5 N", ACCELERATION, "--g",
     "--g must be an acceleration [length]/[time]^2; got 5 newton "
     "([mass] * [length] / [time] ** 2)"),
    ("5 kg", ANGULAR_RATE, "--omega",
     "--omega must be an angular rate [angle]/[time]; got 5 kilogram ([mass])"),
    ("3 s", CYCLE_RATE, "f",
     "f must be a frequency [cycles]/[time]; got 3 second ([time])"),
    ("2 rad/s", ANGLE, "--incline",
     "--incline must be an angle [angle]; got 2 radian / second ([angle] / [time])"),
    ("5 kg", DIMENSIONLESS, "--zeta",
     "--zeta must be a pure number; got 5 kilogram ([mass])"),
    ("0.5 m", TIME, "--t",
     "--t must be a time [time]; got 0.5 meter ([length])"),
])
def test_wrong_dimension(text, dim, label, message):
    assert refusal(parse_quantity, text, dim, label=label) == message


# ============================================================================================
# 3. Refusals of text pint would read silently wrong (and other bad text)


def _cannot(text, why, label="--x"):
    return f"{label}: cannot read {text!r}: {why}"


HEX = "hexadecimal, octal and binary literals are not read; write the number in decimal"
CONTROL = "it holds an invisible or control character"
UNCERTAIN_TWICE = "it has more than one uncertainty (+/- or \u00b1)"
UNCERTAIN_FORM = ("write the value, then +/- or \u00b1, then its standard uncertainty: "
                  "2.0+/-0.1 kg or (100 \u00b1 5) N/m")
NAN = "NaN is not a number dyncalc accepts"
OVERFLOW = "its value overflows float64 (the largest is 1.8e308)"
SIDE_BY_SIDE = "two numbers side by side; write 1000, not 1 000, and use * to multiply"


@pytest.mark.parametrize("text, dim, message", [
    ("1,5 m", LENGTH, _cannot("1,5 m", "a comma is neither a decimal point nor a thousands "
                                       "separator here; write 1.5 or 1500")),
    ("1,500 N", FORCE, _cannot("1,500 N", "a comma is neither a decimal point nor a thousands "
                                          "separator here; write 1.5 or 1500")),
    ("0x1F", DIMENSIONLESS, _cannot("0x1F", HEX)),
    ("0X1f m", LENGTH, _cannot("0X1f m", HEX)),
    ("0o17", DIMENSIONLESS, _cannot("0o17", HEX)),
    ("0b101", DIMENSIONLESS, _cannot("0b101", HEX)),
    ("007", DIMENSIONLESS, _cannot("007", "the leading zero in '007' is ambiguous (octal?); "
                                          "write 7")),
    ("00", DIMENSIONLESS, _cannot("00", "the leading zero in '00' is ambiguous (octal?); "
                                        "write 0")),
    ("012.5 m", LENGTH, _cannot("012.5 m", "the leading zero in '012.5' is ambiguous "
                                           "(octal?); write 12.5")),
    # "1 000": a zero-led number right after another number is two numbers side by side
    ("1 000 N", FORCE, _cannot("1 000 N", SIDE_BY_SIDE)),
    ("1 200 N", FORCE, _cannot("1 200 N", SIDE_BY_SIDE)),
    ("1 2", DIMENSIONLESS, _cannot("1 2", SIDE_BY_SIDE)),
    ("1.2.3", DIMENSIONLESS, _cannot("1.2.3", SIDE_BY_SIDE)),
    ("N/mm", STIFFNESS, _cannot("N/mm", "it has a unit but no number; write 1 N/mm if that is "
                                        "what you mean")),
    ("kg", MASS, _cannot("kg", "it has a unit but no number; write 1 kg if that is what "
                               "you mean")),
    ("5 m # x", LENGTH, _cannot("5 m # x", "comments ('#') are not read")),
    ("5 @ m", LENGTH, _cannot("5 @ m", "the character '@' is not part of a quantity")),
    ("[link=x]", LENGTH, _cannot("[link=x]", "the character '=' is not part of a quantity")),
    ("[/]", LENGTH, _cannot("[/]", "it holds no number")),
    ("5\u200bm", LENGTH, "--x: cannot read '5\\u200bm': " + CONTROL + " U+200B"),
    ("5\u0007m", LENGTH, "--x: cannot read '5\\u0007m': " + CONTROL + " U+0007"),
    ("5\nm", LENGTH, "--x: cannot read '5\\u000am': " + CONTROL + " U+000A"),
    ("5\u00a0m", LENGTH, "--x: cannot read '5\\u00a0m': " + CONTROL + " U+00A0"),
    ("\ufeff5 m", LENGTH, "--x: cannot read '\\ufeff5 m': " + CONTROL + " U+FEFF"),
    ("5 \u202em", LENGTH, "--x: cannot read '5 \\u202em': " + CONTROL + " U+202E"),
    ("5 \x1b[31mm", LENGTH, "--x: cannot read '5 \\u001b[31mm': " + CONTROL + " U+001B"),
    ("5\r", LENGTH, "--x: cannot read '5\\u000d': " + CONTROL + " U+000D"),
    ("\u0663 m", LENGTH, _cannot("\u0663 m", "the digit '\u0663' is not an ASCII digit 0-9")),
    ("\uff11 m", LENGTH, _cannot("\uff11 m", "the digit '\uff11' is not an ASCII digit 0-9")),
    ("2 \u00b1 1 \u00b1 1 kg", MASS, _cannot("2 \u00b1 1 \u00b1 1 kg", UNCERTAIN_TWICE)),
    ("2+/-0.1+/-0.1 kg", MASS, _cannot("2+/-0.1+/-0.1 kg", UNCERTAIN_TWICE)),
    ("\u00b1 5 N/m", STIFFNESS, _cannot("\u00b1 5 N/m", UNCERTAIN_FORM)),
    ("2.0+/-", MASS, _cannot("2.0+/-", UNCERTAIN_FORM)),
    ("2 kg+/-(-0.1)", MASS, "--x (its uncertainty) must not be negative; got -0.1 kilogram"),
    ("2 kg+/-0.1 m", MASS, "--x (its uncertainty) must be a mass [mass]; got 0.1 meter "
                           "([length])"),
    ("(2 kg \u00b1 1) kg", MASS, _cannot("(2 kg \u00b1 1) kg", "give the unit once, after the "
                                                              "parentheses: (100 \u00b1 5) N/m")),
    ("nan", DIMENSIONLESS, _cannot("nan", NAN)),
    ("NaN", DIMENSIONLESS, _cannot("NaN", NAN)),
    ("NAN", DIMENSIONLESS, _cannot("NAN", NAN)),
    ("nan m", LENGTH, _cannot("nan m", NAN)),
    ("-nan N/m", STIFFNESS, _cannot("-nan N/m", NAN)),
    ("inf-inf", DIMENSIONLESS, _cannot("inf-inf", "it is not a number (NaN)")),
    ("0*inf", DIMENSIONLESS, _cannot("0*inf", "it is not a number (NaN)")),
    ("1e400", DIMENSIONLESS, _cannot("1e400", "1e400 overflows float64 (the largest is 1.8e308)")),
    ("-1e400 m", LENGTH, _cannot("-1e400 m", "1e400 overflows float64 (the largest is 1.8e308)")),
    ("1.8e308 m", LENGTH, _cannot("1.8e308 m", "1.8e308 overflows float64 (the largest is "
                                               "1.8e308)")),
    ("1e308*10", DIMENSIONLESS, _cannot("1e308*10", OVERFLOW)),
    ("1e308 m * 10", LENGTH, _cannot("1e308 m * 10", OVERFLOW)),
    ("1e308 m + 1e308 m", LENGTH, _cannot("1e308 m + 1e308 m", OVERFLOW)),
    ("1e200 m * 1e200 m", AREA, _cannot("1e200 m * 1e200 m", OVERFLOW)),
    ("1e308**2", DIMENSIONLESS, _cannot("1e308**2", OVERFLOW)),
    ("1e308 km", LENGTH, "--x: 1e+308 kilometer overflows float64 in m"),
    ("1e308 lbf/in", STIFFNESS, "--x: 1e+308 force_pound / inch overflows float64 in N/m"),
    ("1/0", DIMENSIONLESS, _cannot("1/0", "it divides by zero")),
    ("1 m/(2-2)", LENGTH, _cannot("1 m/(2-2)", "it divides by zero")),
    ("0 ** -1", DIMENSIONLESS, _cannot("0 ** -1", "it divides by zero")),
    ("(-8)**(1/3)", DIMENSIONLESS, _cannot("(-8)**(1/3)", "it has no real value")),
    ("(-8 m)**(1/3)", LENGTH, _cannot("(-8 m)**(1/3)", "it has no real value")),
    ("2 ** inf", DIMENSIONLESS, _cannot("2 ** inf", "an exponent must be finite")),
    ("2**m", DIMENSIONLESS, _cannot("2**m", "an exponent must be a plain number")),
    ("2 m**(1 m)", AREA, _cannot("2 m**(1 m)", "an exponent must be a plain number")),
    ("", LENGTH, _cannot("", "it is empty")),
    ("   ", LENGTH, _cannot("   ", "it is empty")),
    ("\t", LENGTH, "--x: cannot read '\\u0009': it is empty"),
    ("()", LENGTH, _cannot("()", "it holds no number")),
    ("1_000", FORCE, _cannot("1_000", "digit separators ('_') are not read; write 1000, "
                                      "not 1_000")),
    ("1 foo", LENGTH, _cannot("1 foo", "unknown unit 'foo' (did you mean 'foot'?)")),
    ("1 km2", AREA, _cannot("1 km2", "unknown unit 'km2' (did you mean 'km^2'?)")),
    ("1 \uff4d", LENGTH, _cannot("1 \uff4d", "the character '\uff4d' is not part of a quantity")),
    ("\u00bd m", LENGTH, _cannot("\u00bd m", "the character '\u00bd' is not part of a quantity")),
    ("1 m)", LENGTH, _cannot("1 m)", "unexpected ')' at position 4")),
    ("(1 m", LENGTH, _cannot("(1 m", "a '(' is not closed")),
    ("1 m*", LENGTH, _cannot("1 m*", "it ends where a number or unit should follow")),
    ("1 m + 2", LENGTH, _cannot("1 m + 2", "cannot add dimensionless and meter")),
    ("1 m - 2 s", LENGTH, _cannot("1 m - 2 s", "cannot subtract second and meter")),
])
def test_refused(text, dim, message):
    assert refusal(parse_quantity, text, dim, label="--x") == message


def test_refused_non_text():
    assert refusal(parse_quantity, 5, LENGTH, label="--l") == "--l: expected text, got int"
    assert refusal(parse_vector, None, VELOCITY, label="--vr") == (
        "--vr: expected text, got NoneType")


def test_infinity_only_when_allowed():
    assert refusal(parse_quantity, "inf N/m", STIFFNESS, label="--k") == (
        "--k must be finite; got inf newton / meter")
    assert refusal(parse_quantity, "-inf N/m", STIFFNESS, label="--k") == (
        "--k must be finite; got -inf newton / meter")
    assert refusal(parse_quantity, "inf", DIMENSIONLESS, label="--zeta") == (
        "--zeta must be finite; got inf")
    assert refusal(parse_quantity, "inf m", LENGTH, label="--length") == (
        "--length must be finite; got inf meter")
    p = parse_quantity("inf N/m", STIFFNESS, label="--k", allow_inf=True)
    assert p.si == math.inf and p.unit_text == "N/m" and p.assumed_si is False
    p = parse_quantity("inf kN/m", STIFFNESS, allow_inf=True)
    assert p.si == math.inf
    p = parse_quantity("Infinity", STIFFNESS, allow_inf=True)
    assert p.si == math.inf and p.assumed_si is True
    # an overflow is never read as infinity, not even where infinity is allowed
    assert refusal(parse_quantity, "1e308*10", STIFFNESS, label="--k", allow_inf=True) == (
        _cannot("1e308*10", OVERFLOW, label="--k"))
    assert refusal(parse_quantity, "1e400 N/m", STIFFNESS, label="--k", allow_inf=True) == (
        _cannot("1e400 N/m", "1e400 overflows float64 (the largest is 1.8e308)", label="--k"))


@pytest.mark.parametrize("text, constraint, message", [
    ("-2 kg", "positive", "--m must be positive; got -2 kilogram"),
    ("-2", "positive", "--m must be positive; got -2 kilogram"),
    ("0 kg", "positive", "--m must be positive; got 0 kilogram"),
    ("0 g", "positive", "--m must be positive; got 0 gram"),
    ("-0.5 kg", "nonnegative", "--m must not be negative; got -0.5 kilogram"),
    ("-1 g", "nonnegative", "--m must not be negative; got -1 gram"),
    ("0 kg", "nonzero", "--m must not be zero"),
])
def test_constraint_refusals(text, constraint, message):
    assert refusal(parse_quantity, text, MASS, label="--m", constraint=constraint) == message


def test_constraint_accepts():
    assert parse_quantity("0 kg", MASS, constraint="nonnegative").si == 0.0
    assert parse_quantity("1e-3 g", MASS, constraint="positive").si == pytest.approx(1e-6,
                                                                                       rel=1e-15)
    assert parse_quantity("-2 kg", MASS, constraint="nonzero").si == -2.0
    assert parse_quantity("-2 kg", MASS).si == -2.0          # no constraint: the caller decides


# ============================================================================================
# 4. Runaway input is refused fast


def _too_long(n, label="--x"):
    return f"{label}: the quantity is {n} characters long; dyncalc reads at most {MAX_TEXT}"


def _kg_chain():
    text = "2 kg" + " kg" * 60
    assert len(text) <= MAX_TEXT
    return text


NESTED_25 = "(" * 25 + "1" + ")" * 25 + " m"
assert len(NESTED_25) <= MAX_TEXT

CHAINED = "chained powers (a**b**c) are not read; use parentheses"


@pytest.mark.parametrize("text, dim, message", [
    ("9**9**9", DIMENSIONLESS, _cannot("9**9**9", CHAINED)),
    ("10**10**10 m", LENGTH, _cannot("10**10**10 m", CHAINED)),
    ("2^3^2", DIMENSIONLESS, _cannot("2^3^2", CHAINED)),
    ("2**99999", DIMENSIONLESS, _cannot("2**99999", OVERFLOW)),
    ("(2**9999)**9999", DIMENSIONLESS, _cannot("(2**9999)**9999", OVERFLOW)),
    ("9" * 5000, DIMENSIONLESS, _too_long(5000)),
    ("(" * 1000 + "1" + ")" * 1000, DIMENSIONLESS, _too_long(2001)),
    ("1 m" + " " * MAX_TEXT, LENGTH, _too_long(MAX_TEXT + 3)),
    (_kg_chain(), MASS, "--x: cannot read '" + _kg_chain()[:60] + "...': the unit kilogram is "
                        "raised to the power 17; dyncalc reads powers up to 16"),
    ("1 m**100", LENGTH, _cannot("1 m**100", "the unit meter is raised to the power 100; "
                                             "dyncalc reads powers up to 16")),
    ("1 m**17/m**16", LENGTH, _cannot("1 m**17/m**16", "the unit meter is raised to the power "
                                                       "17; dyncalc reads powers up to 16")),
    ("1 m**-1e300", LENGTH, _cannot("1 m**-1e300", "the unit meter is raised to the power "
                                                   "-1e+300; dyncalc reads powers up to 16")),
    (NESTED_25, LENGTH, _cannot(NESTED_25, f"it is nested more than {MAX_DEPTH} levels deep")),
    ("-" * 30 + "1 m", LENGTH, _cannot("-" * 30 + "1 m",
                                       f"it is nested more than {MAX_DEPTH} levels deep")),
])
def test_runaway_refused_fast(text, dim, message):
    assert refusal(parse_quantity, text, dim, label="--x") == message


def test_unit_to_the_power_100_without_number_refused_fast():
    # Refused either for the power or (once exponents stop counting as "the number") for the
    # missing number; in no case computed.
    message = refusal(parse_quantity, "m**100", LENGTH, label="--x")
    assert message in (
        _cannot("m**100", "the unit meter is raised to the power 100; dyncalc reads powers up "
                          "to 16"),
        _cannot("m**100", "it has a unit but no number; write 1 m**100 if that is what you mean"),
    )


def test_length_limit_is_exact():
    at_limit = "1" + " " * (MAX_TEXT - 3) + " m"
    assert len(at_limit) == MAX_TEXT
    assert parse_quantity(at_limit, LENGTH).si == 1.0
    assert refusal(parse_quantity, at_limit + " ", LENGTH, label="--l") == (
        _too_long(MAX_TEXT + 1, label="--l"))


def test_nesting_up_to_max_depth_is_read():
    """MAX_DEPTH is "nesting of parentheses and signs" and the refusal says "nested more than
    24 levels deep": 24 levels of parentheses must be read, 25 refused."""
    ok = "(" * MAX_DEPTH + "1" + ")" * MAX_DEPTH + " m"
    assert parse_quantity(ok, LENGTH).si == 1.0


def test_nesting_of_signs():
    assert parse_quantity("-" * 11 + "1 m", LENGTH).si == -1.0
    assert parse_quantity("-+-" + "(" * 5 + "2 m" + ")" * 5, LENGTH).si == 2.0


# ============================================================================================
# 5. Angular rate vs cycle rate


TWO_PI = 2 * PI
OMEGA_NOT_HZ = ("--omega is an angular rate; give it in rad/s, deg/s, rpm or rev/s, not Hz "
                "(a frequency in cycles)")
F_NOT_RAD = ("f is a frequency in cycles; give it in Hz, 1/s, 1/min or rpm, not in radians or "
             "degrees per time (that is omega)")


@pytest.mark.parametrize("text, exact, max_ulps", [
    ("2 rad/s", Fraction(2), 0),
    ("120 deg/s", TWO_PI / 3, 1),
    ("60 rpm", TWO_PI, 1),
    ("1 rps", TWO_PI, 1),
    ("1 turn/s", TWO_PI, 1),
    ("1 revolution/s", TWO_PI, 1),
    ("3/s", Fraction(3), 0),
    ("3 s^-1", Fraction(3), 0),
    ("3", Fraction(3), 0),                        # bare: rad/s
    ("1 rad/s + 60 rpm", 1 + TWO_PI, 1),
])
def test_angular_rate_reads(text, exact, max_ulps):
    p = parse_quantity(text, ANGULAR_RATE, label="--omega")
    assert ulps_off(p.si, exact) <= max_ulps, p.si
    assert str(p.quantity.units) == "radian / second"


@pytest.mark.parametrize("text, exact", [
    ("1 rev/s", TWO_PI),          # SPEC lists rev/s; the Hz refusal itself recommends it
    ("3 1/s", Fraction(3)),       # SPEC: "or a plain 1/s" (pint reads "3 1/s" as 3/s)
])
def test_angular_rate_reads_spec_units(text, exact):
    p = parse_quantity(text, ANGULAR_RATE, label="--omega")
    assert ulps_off(p.si, exact) <= 1


@pytest.mark.parametrize("text", ["10 Hz", "1 Hz", "1 Hz + 60 rpm", "1 kHz", "2 MHz"])
def test_angular_rate_refuses_hz(text):
    assert refusal(parse_quantity, text, ANGULAR_RATE, label="--omega") == OMEGA_NOT_HZ


@pytest.mark.parametrize("text, exact", [
    ("5 Hz", Fraction(5)),
    ("2 kHz", Fraction(2000)),
    ("60 rpm", Fraction(1)),           # one cycle a minute: 1 Hz, not 0.105 Hz
    ("90 rpm", Fraction(3, 2)),
    ("1 rps", Fraction(1)),
    ("1 turn/s", Fraction(1)),
    ("1 revolution/s", Fraction(1)),
    ("1 cycle/s", Fraction(1)),
    ("1 turn/min", Fraction(1, 60)),
    ("120/min", Fraction(2)),
    ("120 min^-1", Fraction(2)),
    ("3/s", Fraction(3)),
    ("3", Fraction(3)),                # bare: Hz
])
def test_cycle_rate_reads(text, exact):
    p = parse_quantity(text, CYCLE_RATE, label="f")
    assert ulps_off(p.si, exact) <= 1, p.si
    assert str(p.quantity.units) == "hertz"


@pytest.mark.parametrize("text, exact", [
    ("120 1/min", Fraction(2)),        # SPEC: cycle rates take 1/min
    ("3 1/s", Fraction(3)),            # SPEC: cycle rates take 1/s
    ("1 rev/s", Fraction(1)),          # SPEC: revolution-based units
    ("30 rev/min", Fraction(1, 2)),
])
def test_cycle_rate_reads_spec_units(text, exact):
    p = parse_quantity(text, CYCLE_RATE, label="f")
    assert ulps_off(p.si, exact) <= 1


@pytest.mark.parametrize("text", ["2 rad/s", "30 deg/s", "1 rad/min", "2 mrad/s", "60 rpm*rad"])
def test_cycle_rate_refuses_radians(text):
    assert refusal(parse_quantity, text, CYCLE_RATE, label="f") == F_NOT_RAD


def test_mixed_rate_sums_never_use_pints_radian_as_one():
    """pint converts 1 Hz to 1 rad/s and 1 turn/s to 2 pi Hz; a sum must not smuggle that in.
    An angular rate with Hz in it is refused, a cycle rate with radians in it is refused, and
    turns plus Hz is either 2 Hz or refused -- never 1.159 Hz or 7.283 Hz."""
    assert refusal(parse_quantity, "1 rad/s + 1 Hz", ANGULAR_RATE, label="--omega") == (
        OMEGA_NOT_HZ)
    assert refusal(parse_quantity, "60 rpm + 1 Hz", ANGULAR_RATE, label="--omega") == (
        OMEGA_NOT_HZ)
    assert refusal(parse_quantity, "1 Hz + 1 rad/s", CYCLE_RATE, label="f") == F_NOT_RAD
    for text in ("1 turn/s + 1 Hz", "1 Hz + 1 turn/s", "60 rpm + 1 Hz", "1 turn/s + 1/s"):
        try:
            si = parse_quantity(text, CYCLE_RATE, label="f").si
        except InputError:
            continue
        assert ulps_off(si, Fraction(2)) <= 1, (text, si)


def test_convert_rates():
    assert convert(1.0, CYCLE_RATE, "rpm") == 60.0
    assert convert(1.0, CYCLE_RATE, "1/min") == 60.0
    assert convert(1.0, CYCLE_RATE, "turn/s") == 1.0
    assert convert(1.0, CYCLE_RATE, "Hz") == 1.0
    assert convert(1.0, CYCLE_RATE, "1/s") == 1.0
    assert convert(2500.0, CYCLE_RATE, "kHz") == 2.5
    assert abs(convert(2 * math.pi, ANGULAR_RATE, "rpm") - 60.0) <= 1e-12
    assert ulps_off(convert(1.0, ANGULAR_RATE, "rpm"), 30 / PI) <= 2
    assert ulps_off(convert(1.0, ANGULAR_RATE, "deg/s"), 180 / PI) <= 1
    assert ulps_off(convert(1.0, ANGULAR_RATE, "rps"), 1 / TWO_PI) <= 2
    assert convert(3.0, ANGULAR_RATE, "1/s") == 3.0
    assert convert(3.0, ANGULAR_RATE, "rad/s") == 3.0
    # round trips through the reader
    assert convert(parse_quantity("60 rpm", CYCLE_RATE).si, CYCLE_RATE, "rpm") == 60.0
    assert abs(convert(parse_quantity("60 rpm", ANGULAR_RATE).si, ANGULAR_RATE, "rpm")
               - 60.0) <= 1e-12


def test_convert_rev_per_second():
    assert convert(1.0, CYCLE_RATE, "rev/s") == 1.0
    assert ulps_off(convert(1.0, ANGULAR_RATE, "rev/s"), 1 / TWO_PI) <= 2


def test_convert_refusals():
    assert refusal(convert, 1.0, CYCLE_RATE, "rad/s", label="--unit f", name="f") == (
        "--unit f: f is a frequency in cycles; use omega for rad/s")
    assert refusal(convert, 1.0, CYCLE_RATE, "deg/s", label="--unit f", name="f") == (
        "--unit f: f is a frequency in cycles; use omega for deg/s")
    assert refusal(convert, 1.0, ANGULAR_RATE, "Hz", label="--unit omega", name="omega") == (
        "--unit omega: omega is an angular rate; use f for Hz")
    assert refusal(convert, 1.0, ANGULAR_RATE, "kHz", label="--unit omega", name="omega") == (
        "--unit omega: omega is an angular rate; use f for kHz")
    assert refusal(convert, 1.0, ANGULAR_RATE, "kg", label="--unit omega", name="omega") == (
        "--unit omega: kg is not a unit of [angle]/[time]; omega is an angular rate")
    assert refusal(convert, 1.0, CYCLE_RATE, "s", label="--unit f", name="f") == (
        "--unit f: s is not a unit of [cycles]/[time]; f is a frequency")
    assert refusal(convert, 1.0, STIFFNESS, "kg", label="--unit k", name="k") == (
        "--unit k: kg is not a unit of [force]/[length]; k is a stiffness")
    assert refusal(convert, 1.0, INERTIA, "kg", label="--unit J", name="J") == (
        "--unit J: kg is not a unit of [mass]*[length]^2; J is a mass moment of inertia")
    assert refusal(convert, 1.0, STIFFNESS, "kg", label="--unit k") == (
        "--unit k: kg is not a unit of [force]/[length]; it is a stiffness")
    assert refusal(convert, 1.0, ANGULAR_RATE, "2 rad/s", label="--unit omega") == (
        "--unit omega: cannot read '2 rad/s': give a unit, not a quantity")


def test_convert_plain():
    assert ulps_off(convert(1.0, STIFFNESS, "lbf/in"), 1 / LBF_PER_IN) <= 4
    assert convert(2000.0, STIFFNESS, "kN/m") == 2.0
    assert convert(0.05, DIMENSIONLESS, "%") == 5.0
    assert ulps_off(convert(1.0, ANGLE, "deg"), 180 / PI) <= 1
    assert convert(1.0, LENGTH, "mm") == 1000.0


# ============================================================================================
# 6. Vectors


@pytest.mark.parametrize("text, dim, values, unit_text, assumed", [
    ("0,0,2 rad/s", ANGULAR_RATE, [0.0, 0.0, 2.0], "rad/s", False),
    ("(0, 0, 2) rad/s", ANGULAR_RATE, [0.0, 0.0, 2.0], "rad/s", False),
    ("[1,0,0] m/s", VELOCITY, [1.0, 0.0, 0.0], "m/s", False),
    ("1,2,3", VELOCITY, [1.0, 2.0, 3.0], "", True),
    ("(1,2,3)", VELOCITY, [1.0, 2.0, 3.0], "", True),
    ("-1,+2,-3.5 m/s", VELOCITY, [-1.0, 2.0, -3.5], "m/s", False),
    ("(-1, -2, -3) m/s", VELOCITY, [-1.0, -2.0, -3.0], "m/s", False),
    ("1e-3,0,0 m", LENGTH, [1e-3, 0.0, 0.0], "m", False),
    ("1,2,3m/s", VELOCITY, [1.0, 2.0, 3.0], "m/s", False),
    ("1, 2.5E2, .5 km/h", VELOCITY, [1 / 3.6, 250 / 3.6, 0.5 / 3.6], "km/h", False),
    ("1,2,3 1/s", ANGULAR_RATE, [1.0, 2.0, 3.0], "1/s", False),
])
def test_vector_reads(text, dim, values, unit_text, assumed):
    p = parse_vector(text, dim, label="--v")
    assert isinstance(p.si, np.ndarray) and p.si.shape == (3,) and p.si.dtype == float
    for got, want in zip(p.si.tolist(), values):
        assert got == pytest.approx(want, rel=3e-16, abs=0.0)
    assert p.unit_text == unit_text
    assert p.assumed_si is assumed


def test_vector_rates_apply_two_pi():
    p = parse_vector("0,0,60 rpm", ANGULAR_RATE, label="--omega")
    assert p.si[:2].tolist() == [0.0, 0.0] and ulps_off(p.si[2], TWO_PI) <= 1
    assert refusal(parse_vector, "0,0,1 Hz", ANGULAR_RATE, label="--omega") == OMEGA_NOT_HZ


@pytest.mark.parametrize("text, kwargs, message", [
    ("1,2 m/s", {}, "--v must have 3 components; got 2 in '1,2 m/s'"),
    ("1,2,3,4 m/s", {}, "--v must have 3 components; got 4 in '1,2,3,4 m/s'"),
    ("(1, 2) m/s", {}, "--v must have 3 components; got 2 in '(1, 2) m/s'"),
    ("1,,2 m/s", {}, "--v: cannot read '1,,2 m/s': component 2 is empty"),
    ("(1, ,2) m/s", {}, "--v: cannot read '(1, ,2) m/s': component 2 is empty"),
    ("1,a,2 m/s", {}, "--v: cannot read '1,a,2 m/s': component 2 ('a') is not a plain number"),
    ("1,2*3,2 m/s", {}, "--v: cannot read '1,2*3,2 m/s': component 2 ('2*3') is not a plain "
                        "number"),
    ("1,2,a m/s", {}, "--v: cannot read '1,2,a m/s': component 3 is not a number"),
    ("0,0,inf m/s", {}, "--v: cannot read '0,0,inf m/s': component 3 is not a number"),
    ("0,0,nan m/s", {}, "--v: cannot read '0,0,nan m/s': component 3 is not a number"),
    ("(1,2,3", {}, "--v: cannot read '(1,2,3': component 1 ('(1') is not a plain number"),
    ("2 m/s", {}, "--v must be a vector of 3 components, e.g. '0,0,2 m/s'; got '2 m/s'"),
    ("1,2,3 kg", {}, "--v must be a velocity [length]/[time]; got (1, 2, 3) kilogram ([mass])"),
    ("1,2,3 2 m/s", {}, "--v: cannot read '1,2,3 2 m/s': give a unit, not a quantity"),
    ("1,2,3", {"strict": True}, "--v: '1,2,3' has no unit and --strict-units is on; write it "
                                "with a unit, e.g. 1,2,3 m/s"),
    ("0,0,1e308 km/s", {}, "--v: (0, 0, 1e+308) kilometer / second overflows float64 in m/s"),
    ("-1,2,3 m/s", {"constraint": "nonnegative"},
     "--v must not be negative; got (-1, 2, 3) meter / second"),
    (",".join(["1"] * 150), {}, _too_long(299, label="--v")),
])
def test_vector_refusals(text, kwargs, message):
    with np.errstate(all="ignore"):
        assert refusal(parse_vector, text, VELOCITY, label="--v", **kwargs) == message


@pytest.mark.parametrize("text", ["1,2,0x1 m/s", "0x1,2,3 m/s", "1,007,3 m/s", "1,2,3 m/s # x",
                                  "1,2,3 N/mm", "1,2\u200b,3 m/s", "1,2,3 m/s\n",
                                  "\n1,2,3 m/s", "1,2,3\u00a0m/s", "1,2\u3000,3 m/s"])
def test_vector_refuses_bad_text(text):
    refusal(parse_vector, text, VELOCITY, label="--v")


def test_vector_scalar():
    p = parse_vector("2 m/s", VELOCITY, label="--vr", allow_scalar=True)
    assert p.si == 2.0 and isinstance(p.si, float)
    assert p.unit_text == "m/s" and p.assumed_si is False
    p = parse_vector("2", VELOCITY, label="--vr", allow_scalar=True)
    assert p.si == 2.0 and p.assumed_si is True
    p = parse_vector("60 rpm", ANGULAR_RATE, label="--omega", allow_scalar=True)
    assert ulps_off(p.si, TWO_PI) <= 1
    assert refusal(parse_vector, "2 kg", VELOCITY, label="--vr", allow_scalar=True) == (
        "--vr must be a velocity [length]/[time]; got 2 kilogram ([mass])")
    assert refusal(parse_vector, "2", VELOCITY, label="--vr", allow_scalar=True,
                   strict=True) == ("--vr: '2' has no unit and --strict-units is on; write it "
                                    "with a unit, e.g. 2 m/s")


# ============================================================================================
# 7. Units


def test_parse_unit_reads():
    assert str(parse_unit("kN/m")) == "kilonewton / meter"
    assert str(parse_unit("1/s")) == "1 / second"
    assert str(parse_unit("rpm")) == "revolutions_per_minute"
    assert str(parse_unit("lbf/in")) == "force_pound / inch"
    assert str(parse_unit("m^2")) == "meter ** 2"
    assert str(parse_unit("1 m")) == "meter"


def test_parse_unit_refusals():
    assert refusal(parse_unit, "2 m", label="--unit x") == (
        "--unit x: cannot read '2 m': give a unit, not a quantity")
    assert refusal(parse_unit, "2", label="--unit x") == (
        "--unit x: cannot read '2': give a unit, not a quantity")
    assert refusal(parse_unit, "", label="--unit x") == ("--unit x: cannot read '': no unit is "
                                                         "given")


def test_parse_unit_quotes_what_the_user_typed():
    """SPEC: an error quotes the user's text; parse_unit prefixes "1 " internally and must not
    show that prefix."""
    assert refusal(parse_unit, "foo", label="--unit x") == (
        "--unit x: cannot read 'foo': unknown unit 'foo' (did you mean 'foot'?)")
    assert refusal(parse_unit, "m**100", label="--unit x") == (
        "--unit x: cannot read 'm**100': the unit meter is raised to the power 100; dyncalc "
        "reads powers up to 16")


@pytest.mark.parametrize("text, dim", [
    ("m^2", AREA), ("m**2", AREA), ("N/mm**1", STIFFNESS), ("kg*m^2", INERTIA),
])
def test_unit_with_exponent_but_no_number_refused(text, dim):
    """SPEC: a unit with no number is refused ("N/mm" is 1000 N/m to pint). The digits of an
    exponent are not the quantity's number: "N/mm**1" is "N/mm"."""
    assert refusal(parse_quantity, text, dim, label="--x") == _cannot(
        text, f"it has a unit but no number; write 1 {text} if that is what you mean")


# ============================================================================================
# 8. Properties


STIFFNESS_UNITS = {            # unit -> (exact factor to N/m, ulps allowed, pint's long name)
    "N/m": (Fraction(1), 0.5, "newton / meter"),
    "kN/m": (Fraction(1000), 0.5, "kilonewton / meter"),
    "N/mm": (Fraction(1000), 1, "newton / millimeter"),
    "lbf/in": (LBF_PER_IN, 4, "force_pound / inch"),
}
MAX_FLOAT = Fraction(sys.float_info.max)
FINITE = st.floats(allow_nan=False, allow_infinity=False)
PROPS = settings(max_examples=250, deadline=None,
                 suppress_health_check=[HealthCheck.too_slow])


@PROPS
@given(FINITE, st.sampled_from(sorted(STIFFNESS_UNITS)))
def test_property_stiffness_in_any_unit(x, unit):
    factor, max_ulps, long_name = STIFFNESS_UNITS[unit]
    exact = Fraction(x) * factor
    text = f"{x!r} {unit}"
    overflow = f"--k: {x:.15g} {long_name} overflows float64 in N/m"
    if abs(exact) > MAX_FLOAT * Fraction(1 + 10**-15):
        with np.errstate(all="ignore"):
            assert refusal(parse_quantity, text, STIFFNESS, label="--k") == overflow
        return
    if abs(exact) > MAX_FLOAT * Fraction(1 - 10**-15):
        # within pint's few ulps of the largest float: either answer, but no other
        try:
            with np.errstate(all="ignore"):
                p = parse_quantity(text, STIFFNESS, label="--k")
        except InputError as exc:
            assert str(exc) == overflow
        else:
            assert math.isfinite(p.si)
        return
    p = parse_quantity(text, STIFFNESS, label="--k")
    assert ulps_off(p.si, exact) <= max_ulps, (text, p.si, float(exact))
    assert p.assumed_si is False
    if not text.startswith("-"):            # "-2 kg": see test_unit_text_with_exponent_or_sign
        assert p.unit_text == unit
    # and back: convert() undoes the reading
    back = convert(p.si, STIFFNESS, unit)
    assert ulps_off(back, Fraction(x)) <= 2 * max_ulps + 1 or (
        x != 0 and abs(x) < 1e-300), (x, back)


@PROPS
@given(FINITE)
def test_property_repr_round_trips(x):
    p = parse_quantity(repr(x), DIMENSIONLESS)
    assert p.si == x and math.copysign(1.0, p.si) == math.copysign(1.0, x)
    p = parse_quantity(repr(x) + " m", LENGTH)
    assert p.si == x and math.copysign(1.0, p.si) == math.copysign(1.0, x)
    p = parse_quantity(repr(x), STIFFNESS)
    assert p.si == x and p.assumed_si is True


@PROPS
@given(st.floats(min_value=-1e300, max_value=1e300, allow_nan=False))
def test_property_rpm_is_a_cycle_a_minute(x):
    f = parse_quantity(f"{x!r} rpm", CYCLE_RATE).si
    assert ulps_off(f, Fraction(x) / 60) <= 1 or abs(x) < 1e-290
    omega = parse_quantity(f"{x!r} rpm", ANGULAR_RATE).si
    assert ulps_off(omega, mpmath.mpf(x) * TWO_PI / 60) <= 2 or abs(x) < 1e-290


@PROPS
@given(st.lists(FINITE, min_size=3, max_size=3), st.sampled_from(["", " m/s", " km/h"]),
       st.booleans())
def test_property_vectors(values, unit, brackets):
    body = ", ".join(repr(v) for v in values)
    text = (f"({body})" if brackets else body) + unit
    factor = {"": Fraction(1), " m/s": Fraction(1), " km/h": Fraction(1000, 3600)}[unit]
    exact = [Fraction(v) * factor for v in values]
    p = parse_vector(text, VELOCITY, label="--v")
    for got, want in zip(p.si.tolist(), exact):
        assert ulps_off(got, want) <= 2 or abs(want) < Fraction(1, 10**300)
    assert p.assumed_si is (unit == "")


HOSTILE = ["\u200b", "\x00", "\n", "\u00a0", "\u0663", "\u00b1", "+/-", "#", "@", "%", "\u00b0",
           "\u00b2", "\u00b3", "\u00b5", "\u03bc", ",", "_", "[", "]", "\u202e", "\ufeff", "\x1b",
           "\U0001d7d9", "\u00bd", "'", '"', "\\", "$", "{", "}", "`", ";", "=", "e", "E", ".", "j"]
PIECES = ["0", "1", "2", "9", "007", "1.5", ".5", "1e3", "1e-3", "1e400", "1e-400", "99999",
          "1e308", "inf", "nan", "Infinity", "0x1F", "0o7", "0b1",
          "+", "-", "*", "/", "**", "^", "(", ")", " ", " ",
          "m", "mm", "kg", "g", "N", "kN", "s", "min", "Hz", "rad", "deg", "rpm", "rps", "turn",
          "rev", "lbf", "in", "ft", "1/s", "degC", "delta_degC", "percent", "dimensionless",
          "cycle", "x", "foo"] + HOSTILE
GRAMMARISH = st.lists(st.sampled_from(PIECES), max_size=30).map("".join)
ARBITRARY = st.one_of(st.text(max_size=60), GRAMMARISH,
                      st.text(alphabet=st.sampled_from("0123456789.eE+-*/^() ,m"), max_size=40))
DIMS = [STIFFNESS, TORSIONAL_STIFFNESS, MASS, LENGTH, ANGLE, ANGULAR_RATE, CYCLE_RATE,
        DIMENSIONLESS, AREA, INERTIA, VELOCITY]


def _only_input_errors(fn):
    start = time.perf_counter()
    try:
        result = fn()
    except InputError:
        result = None
    elapsed = time.perf_counter() - start
    assert elapsed < HANG, f"took {elapsed:.2f} s"
    return result


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(ARBITRARY, st.sampled_from(DIMS), st.booleans())
def test_property_never_anything_but_input_error(text, dim, flag):
    with np.errstate(all="ignore"):
        p = _only_input_errors(lambda: parse_quantity(text, dim, allow_inf=flag, strict=flag,
                                                      constraint="positive" if flag else None))
        if p is not None:
            assert isinstance(p.si, float) and not math.isnan(p.si)
            assert flag or math.isfinite(p.si)
            assert not flag or p.si > 0
        v = _only_input_errors(lambda: parse_vector(text, dim, allow_scalar=flag))
        if v is not None and not flag:
            assert v.si.shape == (3,) and np.all(np.isfinite(v.si))
        _only_input_errors(lambda: parse_unit(text))
        _only_input_errors(lambda: convert(1.5, dim, text))


# ============================================================================================
# 9. python -O


def test_same_results_under_python_O():
    script = (
        "from dyncalc.units import *\n"
        "from dyncalc.errors import InputError\n"
        "print(parse_quantity('1.5e3 lbf/in', STIFFNESS).si)\n"
        "for t in ['2 kN*m/rad', '9.81 m/s**2', '60 rpm', '1,5 m', '007', 'N/mm', '9**9**9']:\n"
        "    try:\n"
        "        print(repr(parse_quantity(t, TORSIONAL_STIFFNESS).si))\n"
        "    except InputError as e:\n"
        "        print(e)\n"
    )
    outs = []
    for flags in ([], ["-O"]):
        proc = subprocess.run([sys.executable, *flags, "-c", script], capture_output=True,
                              text=True, timeout=60)
        assert proc.returncode == 0, proc.stderr
        outs.append(proc.stdout)
    assert outs[0] == outs[1]
    first = outs[0].splitlines()[0]
    assert ulps_off(float(first), 1500 * LBF_PER_IN) <= 4
    assert outs[0].splitlines()[1] == "2000.0"


@pytest.mark.parametrize("typed, target, same", [
    ("kg", "kg", True), ("kilogram", "kg", True), ("m", "m", True), ("kg/m**3", "kg/m**3", True),
    ("g", "kg", False), ("mm", "m", False), ("rpm", "rad/s", False), ("N/m", "kg/s**2", False)])
def test_same_units_is_where_pint_hands_back_the_magnitude(typed, target, same):
    """``same_units`` (batch skips the conversion of a column there) is true exactly where
    pint's conversion returns the array itself (``N/m`` to ``kg/s**2``: a new array)."""
    from dyncalc.units import registry, same_units

    ureg = registry()
    values = np.array([0.1, 3.0, 7.25, 1e-300])
    converted = ureg.Quantity(values, ureg.parse_units(typed)).to(target).magnitude
    assert same_units(ureg.parse_units(typed), target) is same
    assert (converted is values) is same
