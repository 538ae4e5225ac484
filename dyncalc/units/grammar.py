"""The strict quantity grammar: text -> checked pint quantities, vectors and units.

Everything the user types as a quantity passes through :func:`parse_quantity` or
:func:`parse_vector`. They implement the input rules of the contract (docs/guide/quantities.md,
"Typing quantities and units"):

* a bare number means the parameter's SI unit (flagged ``assumed_si``; ``strict`` refuses it);
* the dimension is checked, with the message ``--k must be a stiffness [force]/[length];
  got 5 kilogram ([mass])``;
* NaN is refused, infinity only where the caller allows it, a literal or result that overflows
  float64 is refused rather than read as infinity;
* text that pint would read silently wrong is refused: a comma in a scalar (``1,5 m`` is 15 m to
  pint), hexadecimal/octal/binary literals, leading-zero integers (``007``), two numbers side by
  side (``1 000`` is 0 to pint), a unit with no number (``N/mm``), comments, ``@``,
  control and zero-width characters;
* a standard uncertainty may follow the value once, at the top: ``2.0+/-0.1 kg``,
  ``(100 ± 5) N/m``, ``2 kg ± 100 g`` (see :func:`parse_quantity`);
* nothing runaway is ever computed: the text is limited to :data:`MAX_TEXT` characters, nesting
  to :data:`MAX_DEPTH`, powers cannot be chained, unit exponents are bounded, and every number
  is a float (so ``9**9**9`` overflows at once instead of building a huge integer).

Why not ``ureg.Quantity(text)``: pint's own expression parser evaluates integer powers exactly
(``9**9**9`` runs for hours), recurses without a bound, reads ``1,5`` as 15 and ``007`` as 0,
and leans on ``assert`` (so ``python -O`` changes it). So dyncalc tokenises and evaluates the
small quantity grammar itself and asks pint only for what pint does well: the meaning of each
unit name (prefixes, plurals, aliases), unit algebra and conversion.

Grammar (SPEC v2: a number with its unit, and juxtaposed factors, bind tighter than ``/``,
as in GNU units; explicit ``*`` and ``/`` go left to right)::

    expr     := term (('+' | '-') term)*             # terms of different [angle] refused
    term     := group (('*' | '/') group)*
    group    := unary (juxtaposed power)*            # "7 mm", "2 kg m", "x (3 s)"
              | literal
    literal  := NUMBER-ish unit (('*' | '/') unit_group)*   # "9.81 m/s^2": one quantity
    unit_group := power NAME-power*                  # a divisor in a unit: "m/s s" = m/(s s)
    unary    := ('+' | '-') unary | power
    power    := atom (('**' | '^') exponent)?          # 2**3**2 is refused, not guessed
    exponent := ('+' | '-')? (NUMBER | '(' expr ')')    # a plain number
    atom     := NUMBER | UNIT | '(' expr ')'

``NUMBER-ish`` is a signed number or a parenthesised pure number (``(2/12) kg*m^2``). A number
is juxtaposed only as ``1/unit`` (``2 1/s``); ``1 000`` and ``2 3/4`` are refused. So
``1500 N / 7 mm`` is ``1500 N / (7 mm)``, ``450 N / 9.81 m/s^2`` a mass, ``100 N/2 m``
50 N/m. The reading with these parentheses made explicit is kept (:attr:`Parsed.reading`)
and shown in the human output.

Angles (SPEC v2): pint counts the radian as dimensionless; dyncalc counts the power of
``[angle]`` (:func:`dyncalc.units.dimensions.angle_power`) and checks it against the
parameter's :attr:`Dim.angles`: a torsional stiffness is ``N*m/angle`` or a bare ``N*m``,
never ``N*m*deg``; an angle has exactly one; ``%`` is a ratio, never an angle.

Angular rates and cycle rates: pint counts the radian as dimensionless, so it converts
``1 rad/s`` to ``1 Hz`` and ``1 rpm`` to ``0.105 Hz``. dyncalc never relies on that: an
:data:`ANGULAR_RATE` refuses Hz, a :data:`CYCLE_RATE` refuses radians and degrees and counts a
revolution (``rpm``, ``rps``, ``turn``) as one cycle. See :func:`convert`.
"""
from __future__ import annotations

import math
import re
import unicodedata
from typing import Any

from ..errors import InputError
from ..records import Frozen
from .dimensions import DIMENSIONLESS, Dim, _unit_class, _unit_names, angle_power
from .registry import registry

__all__ = ["Parsed", "ReadError", "parse_quantity", "parse_vector", "parse_unit", "convert",
           "to_si", "format_quantity", "MAX_TEXT", "MAX_DEPTH"]

MAX_TEXT = 200        #: characters in one quantity
MAX_DEPTH = 24        #: nesting of parentheses and signs
MAX_UNIT_POWER = 16   #: largest exponent of a unit after evaluation

# --------------------------------------------------------------------------------------------
# Reading text


class Parsed(Frozen):
    """A quantity read from the user's text.

    ``quantity`` is the pint quantity (rates already normalised to rad/s or Hz, see
    :func:`convert`), ``si`` its magnitude in the SI unit of its dimension (a float, or a numpy
    array for vectors), ``assumed_si`` whether a bare number was given, ``unit_text`` the unit as
    the user wrote it (``""`` when none), ``text`` the original text, ``uncertainty`` the
    standard uncertainty in the same SI unit when the text carried one (``2.0+/-0.1 kg``),
    ``reading`` the value's text with the parentheses the precedence implies made explicit
    (``1500 N / (7 mm)``; ``""`` for a vector).
    """

    __slots__ = ("quantity", "si", "assumed_si", "unit_text", "text", "uncertainty", "reading")

    def __init__(self, quantity: Any, si: Any, assumed_si: bool, unit_text: str, text: str,
                 uncertainty: float | None = None, reading: str = ""):
        setattr_ = object.__setattr__
        setattr_(self, "reading", reading)
        setattr_(self, "quantity", quantity)
        setattr_(self, "si", si)
        setattr_(self, "assumed_si", assumed_si)
        setattr_(self, "unit_text", unit_text)
        setattr_(self, "text", text)
        setattr_(self, "uncertainty", uncertainty)


_NUMBER_RE = re.compile(r"(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_IDENT_START = set("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_µμΩΩÅ°")
_IDENT_REST = _IDENT_START | set("0123456789")
_SUPERSCRIPTS = {"²": 2.0, "³": 3.0}
_WORD_NUMBERS = {"inf": math.inf, "infinity": math.inf}
_WORD_NAN = {"nan"}
_HEX_RE = re.compile(r"(?<![\w.])0[xXoObB][0-9A-Fa-f]")


def _show(text: str, limit: int = 60) -> str:
    """The user's text quoted for a one-line message: escapes for the unprintable, cut short."""
    out = []
    for ch in text[:limit]:
        if ch.isprintable() and unicodedata.category(ch) not in ("Cf", "Zl", "Zp"):
            out.append(ch)
        else:
            out.append(f"\\u{ord(ch):04x}")
    shown = "".join(out) + ("..." if len(text) > limit else "")
    return f"'{shown}'"


class ReadError(InputError):
    """Text that cannot be read as a quantity; keeps the reason so a caller reading a part of
    the user's text (a vector's unit) can quote the whole of it instead."""

    def __init__(self, label: str, text: str, why: str):
        super().__init__(f"{label}: cannot read {_show(text)}: {why}")
        self.label, self.text, self.why = label, text, why


def _refuse(label: str, text: str, why: str) -> ReadError:
    return ReadError(label, text, why)


def _check_characters(text: str, label: str) -> None:
    """Refuse control, zero-width and unusual space characters anywhere in ``text``."""
    for ch in text:
        if ch in " \t":
            continue
        cat = unicodedata.category(ch)
        if cat.startswith("C") or cat.startswith("Z"):
            raise _refuse(label, text, f"it holds an invisible or control character "
                                       f"U+{ord(ch):04X}")


class _Tok:
    """A token: ``kind`` NUM, NAME or OP; ``value`` a float for NUM, text otherwise; ``pos``
    where it starts and ``end`` where it ends in the text; ``exponent`` a number that is a
    power (m^2, s**-1, m²), not a magnitude."""

    __slots__ = ("kind", "value", "pos", "exponent", "end")

    def __init__(self, kind: str, value: Any, pos: int, exponent: bool = False,
                 end: int | None = None):
        self.kind, self.value, self.pos, self.exponent = kind, value, pos, exponent
        self.end = pos + 1 if end is None else end

    def __repr__(self) -> str:
        return (f"_Tok(kind={self.kind!r}, value={self.value!r}, pos={self.pos!r}, "
                f"exponent={self.exponent!r})")


def _tokenize(text: str, label: str) -> list[_Tok]:
    toks: list[_Tok] = []
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch in " \t":
            i += 1
            continue
        if ch in _SUPERSCRIPTS:
            toks.append(_Tok("OP", "**", i))
            toks.append(_Tok("NUM", _SUPERSCRIPTS[ch], i, exponent=True))
            i += 1
            continue
        if ch.isdigit() and not ch.isascii():
            raise _refuse(label, text, f"the digit {ch!r} is not an ASCII digit 0-9")
        if ch.isascii() and ch.isdigit() or (ch == "." and i + 1 < n
                                             and text[i + 1] in "0123456789"):
            m = _NUMBER_RE.match(text, i)
            lit = m.group(0)
            if _HEX_RE.match(text, i):
                raise _refuse(label, text, "hexadecimal, octal and binary literals are not read; "
                                           "write the number in decimal")
            if re.match(r"0\d", lit):
                if toks and toks[-1].kind == "NUM":
                    raise _refuse(label, text, "two numbers side by side; write 1000, not "
                                               "1 000, and use * to multiply")
                raise _refuse(label, text, f"the leading zero in {lit!r} is ambiguous (octal?); "
                                           f"write {lit.lstrip('0') or '0'}")
            end = m.end()
            if end < n and text[end] == "_":
                raise _refuse(label, text, "digit separators ('_') are not read; write 1000, "
                                           "not 1_000")
            value = float(lit)
            if math.isinf(value):
                raise _refuse(label, text, f"{lit} overflows float64 (the largest is 1.8e308)")
            if value == 0.0 and re.search(r"[1-9]", lit.split("e")[0].split("E")[0]):
                raise _refuse(label, text, f"{lit} underflows float64 (the smallest is "
                                           "4.9e-324)")
            after_power = (toks and toks[-1].kind == "OP" and toks[-1].value in ("**", "^")) or (
                len(toks) >= 2 and toks[-1].kind == "OP" and toks[-1].value in "+-"
                and toks[-2].kind == "OP" and toks[-2].value in ("**", "^"))
            toks.append(_Tok("NUM", value, i, exponent=bool(after_power), end=end))
            i = end
            continue
        if ch in _IDENT_START:
            j = i + 1
            while j < n and text[j] in _IDENT_REST:
                j += 1
            word = text[i:j]
            low = word.lower()
            if low in _WORD_NAN:
                raise _refuse(label, text, "NaN is not a number dyncalc accepts")
            if low in _WORD_NUMBERS:
                toks.append(_Tok("NUM", _WORD_NUMBERS[low], i, end=j))
            else:
                toks.append(_Tok("NAME", "degree" if word == "°" else word, i, end=j))
            i = j
            continue
        if ch in "·×":
            toks.append(_Tok("OP", "*", i))
            i += 1
            continue
        if ch == "%":
            toks.append(_Tok("NAME", "percent", i))
            i += 1
            continue
        if text.startswith("**", i):
            toks.append(_Tok("OP", "**", i, end=i + 2))
            i += 2
            continue
        if ch == "+" and text.startswith("+/-", i) or ch == "±":
            raise _refuse(label, text, "an uncertainty (+/- or ±) goes once, at the top: "
                                       "2.0+/-0.1 kg or (100 ± 5) N/m")
        if ch in "*/^+-()":
            toks.append(_Tok("OP", ch, i))
            i += 1
            continue
        if ch == "[" or ch == "]":
            toks.append(_Tok("OP", "(" if ch == "[" else ")", i))
            i += 1
            continue
        if ch == ",":
            raise _refuse(label, text, "a comma is neither a decimal point nor a thousands "
                                       "separator here; write 1.5 or 1500")
        if ch == "#":
            raise _refuse(label, text, "comments ('#') are not read")
        cat = unicodedata.category(ch)
        if cat.startswith("C") or cat.startswith("Z"):
            raise _refuse(label, text, f"it holds an invisible or control character "
                                       f"U+{ord(ch):04X}")
        raise _refuse(label, text, f"the character {ch!r} is not part of a quantity")
    return toks


class _Parser:
    """Recursive descent over the tokens; evaluates to pint quantities with float magnitudes."""

    def __init__(self, toks: list[_Tok], text: str, label: str):
        self.toks, self.text, self.label = toks, text, label
        self.i = 0
        self.depth = 0
        self.ureg = registry()
        self.had_inf = any(t.kind == "NUM" and math.isinf(t.value) for t in toks)
        self.mixed_turns = False  # a sum of a term in revolutions and one not
        self.wraps: list[tuple[int, int]] = []  # implicit groups after '/', to show in ( )
        self.angle_mismatch = ""  # a sum of an angle and a non-angle: why it is refused

    # -- helpers
    def peek(self):
        return self.toks[self.i] if self.i < len(self.toks) else None

    def take(self):
        tok = self.toks[self.i]
        self.i += 1
        return tok

    def fail(self, why: str) -> InputError:
        return _refuse(self.label, self.text, why)

    def enter(self):
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise self.fail(f"it is nested more than {MAX_DEPTH} levels deep")

    def leave(self):
        self.depth -= 1

    def is_op(self, tok, *ops):
        return tok is not None and tok.kind == "OP" and tok.value in ops

    def finite(self, q):
        mag = q.magnitude
        if isinstance(mag, complex):
            raise self.fail("it has no real value")
        if not math.isfinite(mag):
            if math.isnan(mag):
                raise self.fail("it is not a number (NaN)")
            if not self.had_inf:
                raise self.fail("its value overflows float64 (the largest is 1.8e308)")
        return q

    # -- grammar
    def parse(self):
        if not self.toks:
            raise self.fail("it is empty")
        q = self.expr()
        if self.peek() is not None:
            tok = self.peek()
            raise self.fail(f"unexpected {tok.value!r} at position {tok.pos + 1}")
        return q

    def parenthesised(self):
        """``( expr )`` after the '(' was taken: one level of nesting."""
        self.enter()
        q = self.expr()
        self.leave()
        if not self.is_op(self.peek(), ")"):
            raise self.fail("a '(' is not closed")
        self.take()
        return q

    def expr(self):
        q = self.term()
        while self.is_op(self.peek(), "+", "-"):
            op = self.take().value
            rhs = self.term()
            if _has_turns(q) != _has_turns(rhs):
                self.mixed_turns = True
            if angle_power(q) != angle_power(rhs) and not self.angle_mismatch:
                verb = "add" if op == "+" else "subtract"  # refused once the dimension's
                self.angle_mismatch = (  # own advice (Hz for omega, ...) had its say
                    f"cannot {verb} {_unit_words(rhs)} and {_unit_words(q)}: an angle and a "
                    "quantity without one do not add")
            try:
                q = q + rhs if op == "+" else q - rhs
            except Exception as exc:  # pint: DimensionalityError, OffsetUnitCalculusError
                raise self.fail(f"cannot {'add' if op == '+' else 'subtract'} "
                                f"{rhs.units} and {q.units}") from exc
            self.finite(q)
        return q

    def term(self):
        """Explicit ``*`` and ``/``, equal precedence, left to right, between groups."""
        q, _ = self.group()
        while self.is_op(self.peek(), "*", "/"):
            op = self.take().value
            start = self.i
            rhs, factors = self.group()
            if op == "/" and factors > 1:  # shown as the parentheses the precedence implies
                self.wraps.append((self.toks[start].pos, self.toks[self.i - 1].end))
            q = self.combine(q, rhs, op)
        return q

    def group(self):
        """A number with its unit, or juxtaposed factors: both bind tighter than an explicit
        ``/``, as in GNU units. ``1500 N / 7 mm`` is ``1500 N / (7 mm)``; a number's unit runs
        on over ``*``, ``/`` and names (``450 N / 9.81 m/s^2`` is ``450 N / (9.81 m/s^2)``;
        a parenthesised pure number is a number: ``(2/12) kg*m^2``),
        and a divisor in a unit is its juxtaposed names (``m/s s`` is ``m/(s s)``). A number
        is juxtaposed only as ``1/unit`` (``2 1/s``); ``1 000`` and ``2 3/4`` are refused.
        Returns the value and the number of factors (to show the implied parentheses)."""
        first = self.peek()
        q = self.unary()
        literal = first is not None and (first.kind == "NUM" or self.is_op(first, "+", "-")
                                         or (self.is_op(first, "(") and q.unitless))
        factors = 1
        while True:
            tok = self.peek()
            if tok is None:
                return q, factors
            after = self.toks[self.i + 1] if self.i + 1 < len(self.toks) else None
            if tok.kind == "NUM":
                if not (tok.value == 1.0 and self.is_op(after, "/")):  # "2 1/s" is 2/s
                    raise self.fail("two numbers side by side; write 1000, not 1 000, and use "
                                    "* to multiply")
                q = self.combine(q, self.power(), "*")
            elif tok.kind == "NAME" or self.is_op(tok, "("):
                q = self.combine(q, self.power(), "*")
            elif literal and self.is_op(tok, "*", "/") and after is not None and (
                    after.kind == "NAME"):
                op = self.take().value
                start = self.i
                rhs, count = self.unit_group()
                if op == "/" and count > 1:
                    self.wraps.append((self.toks[start].pos, self.toks[self.i - 1].end))
                q = self.combine(q, rhs, op)
            else:
                return q, factors
            factors += 1

    def unit_group(self):
        """Juxtaposed unit names (``s s``, ``kg m^2``) inside a number's unit."""
        q = self.power()
        count = 1
        while self.peek() is not None and self.peek().kind == "NAME":
            q = self.combine(q, self.power(), "*")
            count += 1
        return q, count

    def combine(self, q, rhs, op: str):
        """``q * rhs`` or ``q / rhs``, checked (division by zero, unit powers, overflow)."""
        return self.checked(lambda: q * rhs if op == "*" else q / rhs)

    def checked(self, compute):
        """``compute()``, a product, quotient or power of quantities: its failures refused in
        words, its units and its size checked."""
        try:
            q = compute()
        except OverflowError as exc:
            raise self.fail("its value overflows float64 (the largest is 1.8e308)") from exc
        except ZeroDivisionError as exc:
            raise self.fail("it divides by zero") from exc
        except Exception as exc:
            raise self.fail(str(exc).splitlines()[0]) from exc
        self.check_units(q)
        return self.finite(q)

    def unary(self):
        tok = self.peek()
        if self.is_op(tok, "+", "-"):
            self.take()
            self.enter()
            q = self.unary()
            self.leave()
            return -q if tok.value == "-" else q
        return self.power()

    def power(self):
        base = self.atom()
        if not self.is_op(self.peek(), "**", "^"):
            return base
        self.take()
        exponent = self.exponent()
        if self.is_op(self.peek(), "**", "^"):
            raise self.fail("chained powers (a**b**c) are not read; use parentheses")
        return self.checked(lambda: base ** exponent)

    def exponent(self) -> float:
        sign = 1.0
        while self.is_op(self.peek(), "+", "-"):
            if self.take().value == "-":
                sign = -sign
        tok = self.peek()
        if tok is not None and tok.kind == "NUM":
            self.take()
            value = tok.value
        elif self.is_op(tok, "("):
            self.take()
            q = self.parenthesised()
            if not q.unitless:
                raise self.fail("an exponent must be a plain number")
            value = float(q.magnitude)
        else:
            raise self.fail("an exponent must be a plain number")
        if not math.isfinite(value):
            raise self.fail("an exponent must be finite")
        return sign * value

    def atom(self):
        tok = self.peek()
        if tok is None:
            raise self.fail("it ends where a number or unit should follow")
        self.take()
        if tok.kind == "NUM":
            return self.ureg.Quantity(tok.value)
        if tok.kind == "NAME":
            try:
                unit = self.ureg.parse_units(tok.value)
            except Exception as exc:
                raise self.fail(_unknown_unit(tok.value)) from exc
            return self.ureg.Quantity(1.0, unit)
        if tok.value == "(":
            return self.parenthesised()
        raise self.fail(f"unexpected {tok.value!r} at position {tok.pos + 1}")

    def check_units(self, q):
        for name, power in q.unit_items():
            if abs(power) > MAX_UNIT_POWER:
                raise self.fail(f"the unit {name} is raised to the power {power:g}; dyncalc "
                                f"reads powers up to {MAX_UNIT_POWER}")


class _Reading:
    """What the parser read: the quantity, whether a unit was named, the unit as typed, the
    canonical names of every unit mentioned, whether it adds revolutions to non-revolutions
    (``1 turn/s + 1 Hz``, which pint sums through radians), and the text with the parentheses
    the precedence implies made explicit (``1500 N / (7 mm)``)."""

    __slots__ = ("quantity", "named", "unit_text", "names", "mixed_turns", "explicit",
                 "angle_mismatch")

    def __init__(self, quantity: Any, named: bool, unit_text: str, names: list[str],
                 mixed_turns: bool, explicit: str = "", angle_mismatch: str = ""):
        self.quantity, self.named, self.unit_text = quantity, named, unit_text
        self.names, self.mixed_turns, self.explicit = names, mixed_turns, explicit
        self.angle_mismatch = angle_mismatch


def _evaluate(text: str, label: str) -> _Reading:
    """Read ``text`` (see the module docstring for the grammar and the refusals)."""
    if not isinstance(text, str):
        raise InputError(f"{label}: expected text, got {type(text).__name__}")
    if len(text) > MAX_TEXT:
        raise InputError(f"{label}: the quantity is {len(text)} characters long; dyncalc reads "
                         f"at most {MAX_TEXT}")
    toks = _tokenize(text, label)
    if not toks:
        raise _refuse(label, text, "it is empty")
    magnitudes = [i for i, t in enumerate(toks) if t.kind == "NUM" and not t.exponent]
    if not magnitudes:
        if any(t.kind == "NAME" for t in toks):
            raise _refuse(label, text, f"it has a unit but no number; write 1 {text.strip()} "
                                       "if that is what you mean")
        raise _refuse(label, text, "it holds no number")
    parser = _Parser(toks, text, label)
    quantity = parser.parse()
    ureg = registry()
    names = [_canonical(ureg, t.value) for t in toks if t.kind == "NAME"]
    unit_text = ""
    first = magnitudes[0]
    signs_only = all(t.kind == "OP" and t.value in "+-" for t in toks[:first])
    if (names and len(magnitudes) == 1 and signs_only and first + 1 < len(toks)
            and toks[first + 1].kind == "NAME"):
        unit_text = text[toks[first + 1].pos:].strip()
    return _Reading(quantity, bool(names), unit_text, names, parser.mixed_turns,
                    _explicit(text, parser.wraps), parser.angle_mismatch)


def _explicit(text: str, wraps: list[tuple[int, int]]) -> str:
    """``text`` with ``(`` and ``)`` around each ``(start, end)`` span, stripped."""
    for start, end in sorted(wraps, reverse=True):
        text = text[:start] + "(" + text[start:end] + ")" + text[end:]
    return text.strip()


def _unit_words(quantity) -> str:
    """A quantity's unit for a message: ``degree``, ``meter / second``, ``a pure number``."""
    return "a pure number" if quantity.unitless else str(quantity.units)


_VOCABULARY: list[str] = []


#: Prefixed units offered by "did you mean" besides the unprefixed ones pint defines.
_COMMON_PREFIXED = ("mm", "cm", "km", "um", "mg", "ms", "us", "kN", "MN", "mN", "kPa", "MPa",
                    "GPa", "kHz", "MHz", "mrad", "kJ", "kW", "kNm")


def _vocabulary() -> list[str]:
    """The unit names, symbols and aliases pint defines without a prefix, and the common
    prefixed ones (for "did you mean"). Prefixed units pint has met already sit in its table
    too, but which depends on what this process read before: they are left out, so that the
    suggestion for a text is always the same."""
    if not _VOCABULARY:
        ureg = registry()
        words = set(_COMMON_PREFIXED)
        for name, definition in ureg._units.items():
            if any(prefix for prefix, _unit, _suffix in ureg.parse_unit_name(name)) \
                    and name != "kilogram":
                continue
            words.add(name)
            if getattr(definition, "symbol", None):
                words.add(definition.symbol)
            words.update(a for a in getattr(definition, "aliases", ()) or () if a)
        _VOCABULARY.extend(sorted(w for w in words if w.isidentifier()))
    return _VOCABULARY


def _is_unit(word: str) -> bool:
    try:
        registry().parse_units(word)
    except Exception:
        return False
    return True


def _unknown_unit(word: str) -> str:
    """``unknown unit 'kgg' (did you mean 'kg'?)``. Tried in turn, the first that finds
    something wins: the same letters in another case (``hz``, ``Mpa``) or order (``rmp``), a
    plural (``lbs``), a power written without ``^`` (``m2``), a close name pint knows, two
    units written together (``Nm``), a prefix with a close name (``kiloneuton``)."""
    import difflib

    vocabulary = _vocabulary()
    low = word.lower()
    def other_case_prefixed():
        found = []
        for cut in range(1, min(6, len(word))):
            rest = word[cut:].lower()
            bases = [w for w in vocabulary if w.lower() == rest]
            for prefix in dict.fromkeys((word[:cut], word[:cut].upper(), word[:cut].lower())):
                if prefix != "m" and _is_unit(prefix + "m"):
                    found += [prefix + w for w in bases if _is_unit(prefix + w)]
        return found

    tries = [
        lambda: [w for w in vocabulary if w.lower() == low] + other_case_prefixed(),
        lambda: [w for w in vocabulary if len(w) == len(word) and len(w) > 2
                 and sorted(w) == sorted(word)],
        lambda: [word[:-1]] if len(word) > 2 and word.endswith("s") and _is_unit(word[:-1])
        else [],
        lambda: ([f"{word[:-1]}^{word[-1]}"] if len(word) > 1 and word[-1] in "23456789"
                 and _is_unit(word[:-1]) else []),
        lambda: (difflib.get_close_matches(word, vocabulary, n=2, cutoff=0.8)
                 + [f"{word[:cut]}*{word[cut:]}" for cut in range(len(word) - 1, 0, -1)
                    if len(word) <= 5 and not word[cut:].isdigit() and _is_unit(word[:cut])
                    and _is_unit(word[cut:])][:1]),
        lambda: [word[:cut] + base for cut in range(1, min(6, len(word)))
                 if _is_unit(word[:cut] + "m") and word[:cut] != "m"
                 for base in difflib.get_close_matches(word[cut:], vocabulary, n=2, cutoff=0.8)
                 if _is_unit(word[:cut] + base)],
    ]
    for attempt in tries:
        found = [w for w in dict.fromkeys(attempt()) if w != word]
        if found:
            shown = " or ".join(repr(w) for w in found[:3])
            return f"unknown unit {word!r} (did you mean {shown}?)"
    return f"unknown unit {word!r}"


def _has_turns(quantity) -> bool:
    return any(_unit_class(n) == "turn" for n in _unit_names(quantity.units))


def _canonical(ureg, name: str) -> str:
    try:
        return ureg.get_name(name)
    except Exception:
        return name


# --------------------------------------------------------------------------------------------
# Dimensions and conversion


def _dimensionality(quantity) -> str:
    """pint's dimensionality with dyncalc's ``[angle]``: ``[length] * [mass] / [time] ** 2 *
    [angle]`` for ``N*m*deg``."""
    power = angle_power(quantity)
    text = "" if quantity.dimensionless else str(quantity.dimensionality)
    if not power:
        return text or "dimensionless"
    num, _, den = text.partition(" / ")
    num = "" if num in ("", "1") else num
    shown = "[angle]" if abs(power) == 1 else f"[angle] ** {abs(power):g}"
    if power > 0:
        num = f"{num} * {shown}" if num else shown
    else:
        den = f"{den} * {shown}" if den else shown
    text = f"{num or '1'} / {den}" if den else num
    return text or "dimensionless"


_RATIO_NAMES = frozenset({"percent", "permille", "ppm"})


def _dimension_message(label: str, dim: Dim, quantity) -> InputError:
    got = f"{format_quantity(quantity)} ({_dimensionality(quantity)})"
    if dim.kind == "dimensionless":
        return InputError(f"{label} must be a pure number; got {got}")
    article = "an" if dim.name[0] in "aeiou" else "a"
    return InputError(f"{label} must be {article} {dim.name} {dim.display}; got {got}")


def format_quantity(quantity) -> str:
    """``5 kilogram``: the magnitude to 15 digits and pint's long unit name, for messages."""
    mag = quantity.magnitude
    if hasattr(mag, "__len__"):
        shown = "(" + ", ".join(f"{float(x):.15g}" for x in mag) + ")"
    else:
        shown = f"{float(mag):.15g}"
    unit = str(quantity.units)
    return f"{shown} {unit}" if unit != "dimensionless" else shown


def _normalise(quantity, dim: Dim, label: str, names: list[str] | None = None,
               mixed_turns: bool = False):
    """Check ``quantity`` has dimension ``dim``; return it in the unit the physics works in.

    ``names`` are the units the user mentioned (all of them, not only those pint kept after
    adding: ``1 rad/s + 1 Hz`` must not pass as 2 rad/s). Angular rates come back in rad/s and
    cycle rates in Hz, applying the 2 pi where revolutions meet cycles; the other dimensions
    come back unchanged (pint converts them correctly).
    """
    ureg = registry()
    classes = {_unit_class(n) for n in (names if names is not None
                                        else _unit_names(quantity.units))}
    if dim.kind == "dimensionless":
        if not quantity.dimensionless:
            raise _dimension_message(label, dim, quantity)
        if classes & {"angle", "turn"}:
            raise InputError(f"{label} is a pure number, not an angle; got "
                             f"{format_quantity(quantity)}")
        return quantity
    if dim.kind == "angle":
        if not quantity.dimensionless:
            raise _dimension_message(label, dim, quantity)
        if angle_power(quantity) != 1:
            if angle_power(quantity) == 0 and set(names or ()) & _RATIO_NAMES:
                raise _ratio_not_angle(label, quantity)
            raise _dimension_message(label, dim, quantity)
        return quantity
    if not quantity.check(dim.check):
        raise _dimension_message(label, dim, quantity)
    if dim.kind == "angular-rate":
        if "cycle" in classes:
            raise InputError(f"{label} is an angular rate; give it in rad/s, deg/s, rpm or "
                             f"rev/s, not Hz (a frequency in cycles)")
        power = angle_power(quantity)
        if power == 0:  # a plain rate: 1/s is read as rad/s (SPEC), any other is refused
            used = names if names is not None else _unit_names(quantity.units)
            if any(name != "second" for name in used):
                raise InputError(
                    f"{label} is an angular rate; got {_compact(quantity)}, a plain "
                    f"rate with no angle (only 1/s is read as rad/s): for revolutions per "
                    f"minute write rpm or rev/min, or give rad/s")
        elif power not in dim.angles:
            raise _dimension_message(label, dim, quantity)
        return _convert(quantity, dim.si.replace("^", "**"), label)
    if dim.kind == "cycle-rate":
        if "angle" in classes:
            raise InputError(f"{label} is a frequency in cycles; give it in Hz, 1/s, 1/min or "
                             f"rpm, not in radians or degrees per time (that is omega)")
        if mixed_turns:
            raise InputError(f"{label}: a sum of revolutions and Hz or 1/s is ambiguous; "
                             "give the frequency in one kind of unit")
        if "turn" in classes:
            return ureg.Quantity(_convert(quantity, "turn/s", label).magnitude, "Hz")
        return _convert(quantity, "Hz", label)
    if angle_power(quantity) not in dim.angles:
        raise _dimension_message(label, dim, quantity)
    return quantity


def _compact(quantity) -> str:
    """``60 1/min``: a scalar quantity with pint's short unit symbols, for messages."""
    return f"{float(quantity.magnitude):.15g} {format(quantity.units, '~C')}"


def _ratio_not_angle(label: str, quantity) -> InputError:
    """A percent (or permille, ppm) where an angle belongs: never read as radians. A grade
    of 100 % is atan(1) = 45 deg; the message says so, for the value given."""
    import numpy as np

    ratio = np.asarray(quantity.to("dimensionless").magnitude, dtype=float)
    shown = format_quantity(quantity)
    if ratio.ndim == 0 and math.isfinite(float(ratio)):
        degrees = math.degrees(math.atan(float(ratio)))
        return InputError(f"{label} must be an angle; got {shown}, a ratio, not an angle: a "
                          f"grade of {format_quantity(quantity)} is {degrees:.6g} deg, so give "
                          f"the angle ({degrees:.6g}deg)")
    return InputError(f"{label} must be an angle; got {shown}, a ratio, not an angle; give the "
                      "angle (a grade of 100 % is 45 deg)")


def _convert(quantity, unit: str, label: str, shown=None):
    """``quantity.to(unit)``, refusing a conversion that overflows float64 (numpy's overflow
    warning silenced: the refusal says it, quoting ``shown``, by default ``quantity``)."""
    import numpy as np

    with np.errstate(over="ignore", invalid="ignore"):
        out = quantity.to(unit)
    if not np.all(np.isfinite(out.magnitude)) and np.all(np.isfinite(quantity.magnitude)):
        quoted = format_quantity(quantity if shown is None else shown)
        raise InputError(f"{label}: {quoted} overflows float64 in {unit.replace('**', '^')}")
    return out


def to_si(quantity, dim: Dim, label: str = "value"):
    """The magnitude of ``quantity`` in ``dim.si`` (float or array); refuses an overflow."""
    q = _normalise(quantity, dim, label)
    return _convert(q, dim.si.replace("^", "**"), label, shown=quantity).magnitude


def _check_value(si, dim: Dim, label: str, allow_inf: bool, constraint: str | None, q):
    import numpy as np

    arr = np.asarray(si, dtype=float)
    if np.any(np.isnan(arr)):
        raise InputError(f"{label}: NaN is not a number dyncalc accepts")
    if np.any(np.isinf(arr)) and not allow_inf:
        raise InputError(f"{label} must be finite; got {format_quantity(q)}")
    if constraint == "positive" and np.any(arr <= 0):
        raise InputError(f"{label} must be positive; got {format_quantity(q)}")
    if constraint == "nonnegative" and np.any(arr < 0):
        raise InputError(f"{label} must not be negative; got {format_quantity(q)}")
    if constraint == "nonzero" and np.any(arr == 0):
        raise InputError(f"{label} must not be zero")


def parse_quantity(text: str, dim: Dim, *, label: str = "value", strict: bool = False,
                   allow_inf: bool = False, constraint: str | None = None) -> Parsed:
    """Read one scalar quantity of dimension ``dim`` from ``text``.

    Parameters
    ----------
    text : str
        What the user typed: ``"2 kN/m"``, ``"1.5e3 lbf/in"``, ``"30deg"``, ``"4"``.
    dim : Dim
        The dimension it must have (``STIFFNESS``, ``MASS``, ...); its ``si`` unit is used for a
        bare number.
    label : str
        How the user named it (``--k``, ``element 2``): every message starts with it.
    strict : bool
        Refuse a bare number for a dimensional quantity (``--strict-units``).
    allow_inf : bool
        Accept ``inf`` (a rigid spring); otherwise infinities are refused.
    constraint : {None, "positive", "nonnegative", "nonzero"}

    Returns
    -------
    Parsed

    Examples
    --------
    >>> from dyncalc.units import STIFFNESS
    >>> p = parse_quantity("2 kN/m", STIFFNESS, label="--k")
    >>> p.si, p.assumed_si, p.unit_text
    (2000.0, False, 'kN/m')
    """
    split = _split_uncertainty(text, label)
    if split is not None:
        return _parse_uncertain(text, split, dim, label, strict, allow_inf, constraint)
    return _finish(_evaluate(text, label), text, dim, label, strict, allow_inf, constraint)


def _finish(reading: _Reading, text: str, dim: Dim, label: str, strict: bool, allow_inf: bool,
            constraint: str | None) -> Parsed:
    """The checks of :func:`parse_quantity` after the text was read."""
    quantity = reading.quantity
    assumed = False
    if not reading.named and dim.kind != "dimensionless":
        if strict:
            raise InputError(f"{label}: {_show(text)} has no unit and --strict-units is on; "
                             f"write it with a unit, e.g. {text.strip()} {dim.si}")
        quantity = registry().Quantity(quantity.magnitude, dim.si.replace("^", "**"))
        assumed = True
    try:
        quantity = _normalise(quantity, dim, label, reading.names if reading.named else None,
                              reading.mixed_turns)
    except InputError as exc:
        if reading.explicit == text.strip() or "(" not in reading.explicit:
            raise
        raise InputError(f"{exc} (the text was read as {_show(reading.explicit)}: a number "
                         "and its unit bind tighter than /)") from None
    if reading.angle_mismatch:
        raise _refuse(label, text, reading.angle_mismatch)
    si = to_si(quantity, dim, label)
    _check_value(si, dim, label, allow_inf, constraint, quantity)
    return Parsed(quantity, float(si), assumed, reading.unit_text, text,
                  reading=reading.explicit)


_PLUS_MINUS_RE = re.compile(r"\+/-|±")


def _split_uncertainty(text: str, label: str) -> tuple[str, str, str] | None:
    """``(value, uncertainty, shared unit)`` texts of ``2.0+/-0.1 kg`` (``("2.0", "0.1 kg",
    "")``) or ``(100 ± 5) N/m`` (``("100", "5", "N/m")``); ``None`` without ``±``/``+/-``."""
    if not isinstance(text, str) or len(text) > MAX_TEXT:
        return None  # _evaluate refuses it with its own message
    marks = list(_PLUS_MINUS_RE.finditer(text))
    if not marks:
        return None
    if len(marks) > 1:
        raise _refuse(label, text, "it has more than one uncertainty (+/- or ±)")
    left, right = text[:marks[0].start()], text[marks[0].end():]
    depth = left.count("(") - left.count(")")
    if depth == 0:
        return left, right, ""
    inner = left.lstrip()[1:]
    if depth == 1 and left.lstrip().startswith("(") and inner.count("(") == inner.count(")"):
        for i, ch in enumerate(right):
            depth += (ch == "(") - (ch == ")")
            if depth == 0:
                return inner, right[:i], right[i + 1:]
    raise _refuse(label, text, "an uncertainty (+/- or ±) goes once, at the top: "
                               "2.0+/-0.1 kg or (100 ± 5) N/m")


def _with_unit(reading: _Reading, unit, names: list[str], unit_text: str, label: str,
               text: str, mixed_turns: bool = False) -> _Reading:
    """``reading`` (a plain number) times ``unit`` (typed as ``unit_text``, mixing
    revolutions with cycles if ``mixed_turns``), as if typed together."""
    if reading.named:
        raise _refuse(label, text, "give the unit once, after the parentheses: (100 ± 5) N/m")
    return _Reading(reading.quantity * unit, True, unit_text.strip(), names,
                    reading.mixed_turns or mixed_turns, reading.explicit,
                    reading.angle_mismatch)


def _parse_uncertain(text: str, split: tuple[str, str, str], dim: Dim, label: str,
                     strict: bool, allow_inf: bool, constraint: str | None) -> Parsed:
    """A quantity with its standard uncertainty; a side without a unit takes the other's.
    An uncertainty in percent (or permille, ppm) of a quantity with a dimension is relative:
    ``100 N/m ± 5%`` is 5 N/m."""
    value_text, sigma_text, shared = split
    if not value_text.strip() or not any(ch.isdigit() for ch in sigma_text):
        raise _refuse(label, text, "write the value, then +/- or ±, then its standard "
                                   "uncertainty: 2.0+/-0.1 kg or (100 ± 5) N/m")
    try:
        value = _evaluate(value_text, label)
        sigma = _evaluate(sigma_text, label)
        sigma_toks = _tokenize(sigma_text, label)
    except ReadError as exc:  # quote the whole text, not the half that failed
        raise _refuse(label, text, exc.why) from None
    extra = _not_a_unit(sigma_toks[_number_end(sigma_toks):])
    if extra is not None:
        raise _refuse(label, text, f"only the uncertainty and its own unit may follow +/- or "
                                   f"±, not {sigma_text[extra:].strip()!r}; write one value "
                                   "and its uncertainty: 2.0 ± 0.1 kg or (100 ± 5) N/m")
    relative = (dim.kind != "dimensionless" and not shared.strip() and sigma.named
                and set(sigma.names) <= _RELATIVE_UNITS)
    if sigma.named and set(sigma.names) & _RELATIVE_UNITS and not relative \
            and not set(sigma.names) <= _RELATIVE_UNITS:
        # 1 ± 1%m: a percent of a metre (0.01 m), never what was meant by a relative spread
        raise _refuse(label, text, f"a percent goes alone after +/- or ±, not "
                                   f"{sigma_text.strip()!r}: write 1 m ± 1% (a relative "
                                   "uncertainty) or (1 ± 0.01) m")
    if dim.kind == "dimensionless" and value.named != sigma.named and not shared.strip():
        raise _refuse(label, text, "a pure number with a unit (%) on one side only is "
                                   "ambiguous; write both sides alike: 5% ± 1% or 0.05 ± 0.01")
    if shared.strip():
        try:
            unit, names = _read_unit(shared, label)
        except ReadError:
            raise _refuse(label, text, "only a unit may follow (value ± uncertainty): "
                                       "(100 ± 5) N/m") from None
        value = _with_unit(value, unit, names, shared, label, text)
        sigma = _with_unit(sigma, unit, names, shared, label, text)
    elif value.named != sigma.named and not relative:  # the bare side takes the other's unit
        bare, named = (sigma, value) if value.named else (value, sigma)
        bare = _with_unit(bare, named.quantity.units, named.names, named.unit_text, label, text,
                          named.mixed_turns)
        value, sigma = (named, bare) if value.named else (bare, named)
    parsed = _finish(value, text, dim, label, strict, allow_inf, constraint)
    spread_label = f"{label} (its uncertainty)"
    if relative:
        fraction = _finish(sigma, text, DIMENSIONLESS, spread_label, strict, False,
                           "nonnegative").si
        sigma_si = abs(parsed.si) * fraction
    else:
        sigma_si = _finish(sigma, text, dim, spread_label, strict, False, "nonnegative").si
    parsed = Parsed(parsed.quantity, parsed.si, parsed.assumed_si, parsed.unit_text, text,
                    uncertainty=sigma_si, reading=parsed.reading)
    return parsed


#: Units of an uncertainty that is a fraction of the value (``± 5%``).
_RELATIVE_UNITS = frozenset({"percent", "permille", "ppm"})


_VECTOR_RE = re.compile(r"^\s*[\(\[]([^\)\]]*)[\)\]]\s*(.*)$")
_COMPONENT_RE = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")


def parse_vector(text: str, dim: Dim, *, label: str = "value", size: int = 3,
                 strict: bool = False, allow_scalar: bool = False,
                 constraint: str | None = None) -> Parsed:
    """Read a vector of ``size`` components with one unit: ``"0,0,2 rad/s"``,
    ``"(0, 0, 2) rad/s"``, ``"[1,0,0] m/s"``.

    Each component is a plain decimal number (sign allowed). With ``allow_scalar`` a text with
    no comma is read by :func:`parse_quantity` and returned as a float (the caller gives it a
    meaning). ``si`` is then a numpy array of ``size`` floats.

    >>> from dyncalc.units import ANGULAR_RATE
    >>> parse_vector("(0, 0, 2) rad/s", ANGULAR_RATE, label="--omega").si.tolist()
    [0.0, 0.0, 2.0]
    """
    import numpy as np

    if not isinstance(text, str):
        raise InputError(f"{label}: expected text, got {type(text).__name__}")
    if len(text) > MAX_TEXT:
        raise InputError(f"{label}: the quantity is {len(text)} characters long; dyncalc reads "
                         f"at most {MAX_TEXT}")
    _check_characters(text, label)
    if "," not in text:
        if allow_scalar:
            return parse_quantity(text, dim, label=label, strict=strict, constraint=constraint)
        raise InputError(f"{label} must be a vector of {size} components, e.g. '0,0,2 {dim.si}';"
                         f" got {_show(text)}")
    if _HEX_RE.search(text):
        raise _refuse(label, text, "hexadecimal, octal and binary literals are not read; write "
                                   "the number in decimal")
    m = _VECTOR_RE.match(text)
    if m:
        parts = m.group(1).split(",")
        unit_text = m.group(2).strip()
    else:
        parts = text.split(",")
        last = parts[-1].strip()
        num = _COMPONENT_RE.match(last)
        if num is None:
            raise _refuse(label, text, f"component {len(parts)} is not a number")
        parts[-1] = num.group(0)
        unit_text = last[num.end():].strip()
    if len(parts) != size:
        raise InputError(f"{label} must have {size} components; got {len(parts)} in {_show(text)}")
    values = []
    for index, part in enumerate(parts, 1):
        part = part.strip()
        if not part:
            raise _refuse(label, text, f"component {index} is empty")
        try:
            toks = _tokenize(part, label)
        except ReadError as exc:
            raise _refuse(label, text, f"component {index}: {exc.why}") from None
        sign = 1.0
        while toks and toks[0].kind == "OP" and toks[0].value in "+-":
            sign = -sign if toks[0].value == "-" else sign
            toks = toks[1:]
        if len(toks) != 1 or toks[0].kind != "NUM":
            raise _refuse(label, text, f"component {index} ({part!r}) is not a plain number")
        values.append(sign * toks[0].value)
    names = None
    if unit_text:
        try:
            unit, names = _read_unit(unit_text, label)
        except ReadError as exc:
            raise _refuse(label, text, exc.why) from None
        named = True
    else:
        if strict and dim.kind != "dimensionless":
            raise InputError(f"{label}: {_show(text)} has no unit and --strict-units is on; "
                             f"write it with a unit, e.g. {text.strip()} {dim.si}")
        unit = registry().parse_units(dim.si.replace("^", "**")) if dim.si else None
        named = False
    quantity = registry().Quantity(np.array(values, dtype=float), unit)
    quantity = _normalise(quantity, dim, label, names)
    si = np.asarray(to_si(quantity, dim, label), dtype=float)
    if np.any(np.isinf(si)):
        raise InputError(f"{label} must be finite; got {format_quantity(quantity)}")
    _check_value(si, dim, label, False, constraint, quantity)
    return Parsed(quantity, si, not named and dim.kind != "dimensionless", unit_text, text)


def _number_end(toks: list[_Tok]) -> int:
    """How many tokens the leading number takes: signs and a number, or a parenthesised
    signed number (``(-0.1)``); 0 when ``toks`` do not start with one."""
    k = 0
    opened = bool(toks) and toks[0].kind == "OP" and toks[0].value == "("
    k += opened
    while k < len(toks) and toks[k].kind == "OP" and toks[k].value in "+-":
        k += 1
    if k >= len(toks) or toks[k].kind != "NUM":
        return 0
    k += 1
    if opened:
        if k < len(toks) and toks[k].kind == "OP" and toks[k].value == ")":
            return k + 1
        return 0
    return k


def _not_a_unit(toks: list[_Tok]) -> int | None:
    """Where ``toks`` stop being a unit (names, ``*``, ``/``, parentheses, powers): the text
    position of the first number that is not an exponent or the ``1`` of ``1/s``, or of a
    ``+``/``-`` that is not an exponent's sign; ``None`` when all of it is a unit."""
    for k, tok in enumerate(toks):
        before = toks[k - 1] if k else None
        after = toks[k + 1] if k + 1 < len(toks) else None
        if tok.kind == "NUM" and not tok.exponent and not (
                tok.value == 1.0 and after is not None and after.kind == "OP"
                and after.value == "/"):
            return tok.pos
        if (tok.kind == "OP" and tok.value in "+-"
                and not (before is not None and before.kind == "OP"
                         and before.value in ("**", "^"))):
            return tok.pos
    return None


def _read_unit(text: str, label: str):
    """(pint unit, unit names mentioned) of a unit text such as ``kN/m`` or ``1/s``."""
    if not isinstance(text, str) or not text.strip():
        raise _refuse(label, str(text), "no unit is given")
    _check_characters(text, label)
    stripped = text.strip()
    toks = _tokenize(stripped, label)
    lead = 1 if toks and toks[0].kind == "NUM" and toks[0].value == 1.0 else 0
    if _not_a_unit(toks[lead:]) is not None:
        raise _refuse(label, text, "give a unit, not a quantity")
    probe = stripped if _NUMBER_RE.match(stripped) else "1 " + stripped
    try:
        reading = _evaluate(probe, label)
    except ReadError as exc:
        raise _refuse(label, text, exc.why) from None
    if reading.quantity.magnitude != 1.0:
        raise _refuse(label, text, "give a unit, not a quantity")
    return reading.quantity.units, reading.names


def parse_unit(text: str, *, label: str = "unit"):
    """Read a unit (``"kN/m"``, ``"1/s"``, ``"rpm"``) and return the pint unit.

    A quantity with a magnitude other than 1 (``"2 m"``) is refused.
    """
    return _read_unit(text, label)[0]


def convert(si_value, dim: Dim, unit_text: str, *, label: str = "unit", name: str = "it"):
    """Express an SI magnitude of ``dim`` in ``unit_text``; returns the converted magnitude.

    The rate rules of the contract apply (docs/guide/quantities.md, "Angular rate and frequency"): an angular
    rate cannot be shown in Hz, a cycle rate cannot be shown in rad/s or deg/s, and ``rpm`` is
    one revolution (one cycle) per minute for both.
    ``name`` is the result's name, for the messages.
    """
    ureg = registry()
    unit, names = _read_unit(unit_text, label)
    classes = {_unit_class(n) for n in names}
    if dim.kind == "cycle-rate":
        if "angle" in classes:
            raise InputError(f"{label}: {name} is a frequency in cycles; use omega for "
                             f"{unit_text}")
        base = ureg.Quantity(si_value, "turn/s" if "turn" in classes else "Hz")
    elif dim.kind == "angular-rate":
        if "cycle" in classes:
            raise InputError(f"{label}: {name} is an angular rate; use f for {unit_text}")
        base = ureg.Quantity(si_value, dim.si.replace("^", "**"))
    else:
        base = ureg.Quantity(si_value, dim.si.replace("^", "**") if dim.si else "")
        if dim.kind != "dimensionless" and angle_power(ureg.Quantity(1.0, unit)) not in dim.angles:
            article = "an" if dim.name[0] in "aeiou" else "a"
            raise InputError(f"{label}: {unit_text} is not a unit of {dim.display}; {name} is "
                             f"{article} {dim.name}")
        if dim.kind == "dimensionless" and classes & {"angle", "turn"}:
            raise InputError(f"{label}: {unit_text} is an angle unit; {name} is a pure number")
    try:
        return base.to(unit).magnitude
    except Exception as exc:  # pint's DimensionalityError
        article = "an" if dim.name[0] in "aeiou" else "a"
        raise InputError(f"{label}: {unit_text} is not a unit of {dim.display}; {name} is "
                         f"{article} {dim.name}") from exc


def is_unit_word(word: str) -> bool:
    """Whether pint knows ``word`` as a unit (``N``, ``deg``, ``kg``), for the expression
    grammar (:mod:`dyncalc.units.expression`), which reads a unit only after a number."""
    return _is_unit(word)


def unit_in_base(text: str, *, label: str = "unit") -> tuple[float, dict[str, float]]:
    """The factor that takes ``text`` (a unit: ``"kN/m"``, ``"deg"``) to SI base units, and
    its dimensionality as ``{"[mass]": 1, "[time]": -2}`` (angles count as pure numbers, as
    in pint: ``deg`` gives ``(pi/180, {})``).

    >>> unit_in_base("km/h")
    (0.2777777777777778, {'[length]': 1.0, '[time]': -1.0})
    """
    unit = _read_unit(text, label)[0]
    base = registry().Quantity(1.0, unit).to_base_units()
    return float(base.magnitude), {k: float(v) for k, v in base.dimensionality.items()}


def quantity_in_base(text: str, *, label: str = "value") -> tuple[float, dict[str, float], str]:
    """A quantity of any dimension (``"2 kg"``, ``"9.81 m/s^2"``, ``"300 rpm"``): its SI base
    magnitude, its dimensionality (as :func:`unit_in_base`) and its reading (the text with the
    parentheses the precedence implies). For the parameters of ``eom``, whose dimension the
    expressions decide. An uncertainty is refused (``eom`` does not propagate one).

    >>> quantity_in_base("1500 N / 7 mm")[:2]
    (214285.7142857143, {'[mass]': 1.0, '[time]': -2.0})
    """
    if _split_uncertainty(text, label) is not None:
        raise InputError(f"{label}: an uncertainty is not read here (eom does not propagate "
                         "one); give the value alone")
    reading = _evaluate(text, label)
    if reading.angle_mismatch:
        raise _refuse(label, text, reading.angle_mismatch)
    base = reading.quantity.to_base_units()
    value = float(base.magnitude)
    if not math.isfinite(value):
        raise _refuse(label, text, "it is not a finite number")
    return value, {k: float(v) for k, v in base.dimensionality.items()}, reading.explicit
