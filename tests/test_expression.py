"""The closed expression grammar (dyncalc/units/expression.py): what it reads, how it reads
it (precedence, units after numbers, exact constants), what it refuses with which message,
and a hypothesis suite of hostile strings that never escapes the grammar, never raises
anything but InputError and does a bounded amount of work per character."""
from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from dyncalc.errors import InputError
from dyncalc.units.expression import (MAX_DEPTH, MAX_LENGTH, Dimension, DimensionError,
                                      Parser, dimension_of, parse_expression)


def _value(text, **names):
    """Evaluate a parsed tree with plain floats (an independent evaluator of the tree)."""
    node = parse_expression(text, coordinates=("x",), names=set(names))

    def ev(n):
        if n.kind == "num":
            return n.value
        if n.kind == "pi":
            return math.pi
        if n.kind == "name":
            return names[n.name]
        if n.kind == "rate":
            return names[n.name + "'" * n.order]
        a = [ev(x) for x in n.args]
        return {"neg": lambda: -a[0], "add": lambda: a[0] + a[1], "sub": lambda: a[0] - a[1],
                "mul": lambda: a[0] * a[1], "div": lambda: a[0] / a[1],
                "pow": lambda: a[0] ** a[1]}.get(n.kind, lambda: {
                    "atan2": lambda: math.atan2(*a), "abs": lambda: abs(a[0])}.get(
                        n.name, lambda: getattr(math, n.name)(a[0]))())()
    return ev(node)


@pytest.mark.parametrize("text, expected", [
    ("1 + 2*3", 7.0),
    ("2^3*2", 16.0),
    ("-2^2", -4.0),                 # the power binds tighter than the sign
    ("2*-3", -6.0),
    ("8/2/2", 2.0),                 # left to right
    ("(1 + 2)*3", 9.0),
    ("2**3", 8.0),
    ("2^-1", 0.5),
    ("sqrt(16) + abs(-2)", 6.0),
    ("atan2(1, 1)*4", math.pi),
    ("cos(pi)", -1.0),
    ("sin(30deg)", 0.5),
    ("1500 N / 7 mm", 1500 / 0.007),  # a number and its unit are one factor
    ("9.81 m/s^2 * 2", 19.62),
    ("2 kg*m^2", 2.0),
    ("1 km/h", 1000 / 3600),
    ("3 kN*m/rad", 3000.0),
    ("exp(0) + log(1) + sinh(0) + cosh(0) + tan(0)", 2.0),
])
def test_values_and_precedence(text, expected):
    assert _value(text) == pytest.approx(expected, rel=1e-14)


def test_names_rates_and_time():
    assert _value("m*x'^2/2 + k*x^2/2", m=2.0, k=8.0, x=0.5, **{"x'": 3.0}) == 10.0
    node = parse_expression("U0*cos(w*t)", names={"U0", "w"})
    assert repr(node) == "mul(U0, cos(mul(w, t)))"
    assert repr(parse_expression("x''", coordinates=("x",), max_order=2)) == "x''"


def test_a_unit_only_after_a_number_and_never_a_name_of_the_expression():
    # m is a parameter here, so "2*m" is twice it; "2 m" after a number is two metres
    assert repr(parse_expression("2*m", names={"m"})) == "mul(num(2), m)"
    assert repr(parse_expression("2 m*x", coordinates=("x",))) == "mul(num(2 m), x)"
    # a unit goes on across * and / without spaces only
    assert repr(parse_expression("9.81 m/s^2 * m")) == "mul(num(9.81 m/s^2), m)"
    # t is always time, never the tonne
    with pytest.raises(InputError, match=r"unexpected name 't' \(use \* to multiply\)"):
        parse_expression("2 t")


@pytest.mark.parametrize("text, message", [
    ("__import__('os')", "--T: names may not begin with '_' ('__import__') at column 1: "
                         "'__import__('os')'"),
    ("os.system(1)", "--T: attribute access is not part of the grammar at column 3: "
                     "'os.system(1)'"),
    ("lambda x: x", "--T: 'lambda' is not a name the grammar reads at column 1: 'lambda x: x'"),
    ("x[0]", "--T: indexing and brackets are not part of the grammar; use ( ) at column 2: "
             "'x[0]'"),
    ("'abc'", "--T: strings are not part of the grammar (x' is the rate of a coordinate x) "
              "at column 1: ''abc''"),
    ("open(1)", "--T: unknown function 'open' (the functions are sin, cos, tan, exp, log, "
                "sqrt, sinh, cosh, atan2, abs) at column 1: 'open(1)'"),
    ("2^3^2", "--T: a power of a power needs parentheses: (a^b)^c or a^(b^c) at column 4: "
              "'2^3^2'"),
    ("x^y", "--T: an exponent must be a constant number (use exp() for a variable one) at "
            "column 2: 'x^y'"),
    ("x^65", "--T: an exponent must lie between -64 and 64 at column 2: 'x^65'"),
    ("(10^64)^64", "--T: a constant here overflows float64, divides by zero or takes a "
                   "fractional power of a negative number at column 8: '(10^64)^64'"),
    ("exp(1000)", "--T: exp() is not defined (or overflows) at 1000 at column 1: 'exp(1000)'"),
    ("1/0", "--T: a constant here overflows float64, divides by zero or takes a fractional "
            "power of a negative number at column 2: '1/0'"),
    ("sin(x", "--T: this '(' is never closed at column 4: 'sin(x'"),
    ("2 y", "--T: unknown unit 'y' after the number 2 (use * to multiply) at column 3: '2 y'"),
    ("2 x", "--T: unexpected name 'x' (use * to multiply) at column 3: '2 x'"),
    ("k x", "--T: unexpected name 'x' (use * to multiply) at column 3: 'k x'"),
    ("x +", "--T: the expression ends too early at column 4: 'x +'"),
    ("", "--T: the expression is empty at column 1: ''"),
    ("m'", "--T: m' is a rate, but 'm' is not a coordinate (the coordinates are x) at "
           "column 2: 'm''"),
    ("x''", "--T: x'': at most 1 prime here at column 2: 'x'''"),
    ("a = 1", "--T: an expression has no '=' at column 3: 'a = 1'"),
    ("a; b", "--T: one expression only at column 2: 'a; b'"),
    ("0x1F", "--T: hexadecimal, octal and binary literals are not read at column 1: '0x1F'"),
    ("1e400", "--T: 1e400 overflows float64 at column 1: '1e400'"),
    ("sin(1, 2)", "--T: sin() takes 1 argument, not 2 at column 1: 'sin(1, 2)'"),
    ("x\x1b[31m", "--T: an invisible or control character U+001B at column 2: "
                  "'x\\u001b[31m'"),
    ("2 kgg", "--T: unknown unit 'kgg' after the number 2 (use * to multiply) at column 3: "
              "'2 kgg'"),
])
def test_refusals_name_the_column(text, message):
    with pytest.raises(InputError) as raised:
        parse_expression(text, label="--T", coordinates=("x",))
    assert str(raised.value) == message


def test_limits():
    deep = "(" * (MAX_DEPTH + 1) + "x" + ")" * (MAX_DEPTH + 1)
    with pytest.raises(InputError, match=f"nests deeper than {MAX_DEPTH} levels at column "
                                         f"{MAX_DEPTH + 1}"):
        parse_expression(deep)
    parse_expression("(" * (MAX_DEPTH - 1) + "x" + ")" * (MAX_DEPTH - 1))
    with pytest.raises(InputError) as raised:
        parse_expression("x+" * 300 + "x", label="--V")
    assert str(raised.value) == (f"--V: the expression is 601 characters long; dyncalc reads "
                                 f"at most {MAX_LENGTH}")
    with pytest.raises(InputError, match="unknown name 'y'"):
        parse_expression("y", free_names=False)


def test_dimensions():
    L, M, T = (Dimension({f"[{d}]": 1}) for d in ("length", "mass", "time"))
    energy = M * L ** 2 / T ** 2
    tree = parse_expression("m*x'^2/2 + m*g*x", coordinates=("x",))
    assert dimension_of(tree, {"m": M, "g": L / T ** 2, "x": L}) == energy
    with pytest.raises(DimensionError) as raised:
        dimension_of(parse_expression("x + 1 s", coordinates=("x",)), {"x": L}, "--V")
    assert str(raised.value) == ("--V: the terms of a sum differ in dimension ([length] and "
                                 "[time]) at column 3")
    with pytest.raises(DimensionError, match=r"sin\(\) takes a pure number or an angle"):
        dimension_of(parse_expression("sin(x)", coordinates=("x",)), {"x": L}, "--V")
    assert dimension_of(parse_expression("sqrt(g/l)"), {"g": L / T ** 2, "l": L}) == T ** -1
    assert dimension_of(parse_expression("sin(30deg)"), {}) == Dimension()


# --- hostile strings ------------------------------------------------------------------------

_PIECES = ["__import__", "(", ")", "'os'", ".", "system", "lambda", ":", "x", "x'", "x''",
           "[", "]", "{", "}", "=", ";", ",", "\"", "^", "**", "*", "/", "+", "-", "9", "1e308",
           "1e-400", "0x", "07", "sin", "atan2", "exp", "pi", "t", "m", "kg", "m/s^2", " ",
           "\\", "@", "#", "`", "!", "$", "&", "|", "~", "<", ">", "?", "\x00", "\u202e",
           "\u200b", "é", "日", "eval", "getattr", "__class__", "mro", "globals", "10^10",
           "(((((", ")))))", "--", "nan", "inf"]


def _parse_counted(text):
    """Parse ``text``; the steps the parser took (it must be bounded by its length)."""
    parser = None
    try:
        parser = Parser(text, "--T", ("x",), {"m"}, True, 1)
        parser.parse()
    except InputError:
        pass
    return 0 if parser is None else parser.steps


@settings(max_examples=400, deadline=None)
@given(st.lists(st.sampled_from(_PIECES), max_size=60))
def test_hostile_pieces_are_refused_or_read_never_escape(pieces):
    text = "".join(pieces)
    try:
        node = parse_expression(text, label="--T", coordinates=("x",), names={"m"})
    except InputError as exc:
        message = str(exc)
        assert message.startswith("--T: ") and "\n" not in message
    else:
        assert node.kind in ("num", "name", "rate", "pi", "neg", "add", "sub", "mul", "div",
                             "pow", "call")
    assert _parse_counted(text) <= 12 * len(text) + 12


@settings(max_examples=300, deadline=None)
@given(st.text(max_size=MAX_LENGTH + 20))
def test_any_text_is_read_or_refused_with_input_error(text):
    try:
        parse_expression(text, label="--V", coordinates=("x",))
    except InputError as exc:
        assert str(exc).startswith("--V: ")
    assert _parse_counted(text[:MAX_LENGTH]) <= 12 * len(text) + 12


@settings(max_examples=100, deadline=None)
@given(st.integers(min_value=1, max_value=MAX_DEPTH + 10))
def test_nesting_is_bounded_whatever_the_form(depth):
    for text in ("-" * depth + "x", "(" * depth + "x" + ")" * depth,
                 "sin(" * depth + "x" + ")" * depth):
        try:
            parse_expression(text, coordinates=("x",))
        except InputError as exc:
            assert "nests deeper" in str(exc) and depth >= MAX_DEPTH
