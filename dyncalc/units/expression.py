"""The closed expression grammar of ``eom`` (and, later, ``coriolis``): text -> a small tree.

A hand-written tokenizer and precedence-climbing parser, independent of sympy and of Python's
own parser: nothing the user types is ever handed to ``eval``, ``sympify`` or ``parse_expr``.
What it reads (docs/guide/eom.md, "The expression grammar")::

    expr     := term (('+' | '-') term)*
    term     := unary (('*' | '/') unary)*
    unary    := ('+' | '-') unary | power
    power    := atom (('^' | '**') exponent)?      # a^b^c is refused, not guessed
    exponent := ('+' | '-')? atom                  # a constant, |value| <= MAX_EXPONENT
    atom     := NUMBER UNIT? | NAME | NAME "'" | NAME "''" | 'pi' | 't'
              | FUNCTION '(' expr (',' expr)? ')' | '(' expr ')'

``UNIT`` is a unit right after a number (``9.81 m/s^2``, ``35deg``, ``2 kg*m^2``): pint's
unit words joined by ``*``, ``/``, juxtaposition and integer powers; a word that names a
coordinate or parameter of the expression, or ``t`` (always time, never the tonne), ends it.
So ``2*m`` is twice the parameter ``m`` while ``2 m`` is two metres: write products with
``*``. The functions are :data:`FUNCTIONS` (``atan2`` takes two arguments).

Refused, each with the column of the offending character (``--T: unknown function 'open'
at column 1: 'open(1)'``): anything outside the grammar (attributes, strings, indexing,
lambdas, keywords, ``=``, ``;``), names beginning with ``_``, unknown functions, a rate of a
name that is not a coordinate, constants that overflow float64, a variable or huge exponent.
Bounded: at most :data:`MAX_LENGTH` characters and :data:`MAX_DEPTH` levels of nesting, and
the parser does a bounded amount of work per character (:attr:`Parser.steps`), so every
refusal is immediate.

The tree (:class:`Node`) carries each number in SI base units with its dimension, so that
:func:`dimension_of` checks an expression's dimension without sympy;
:mod:`dyncalc.physics.symbolic` turns it into sympy objects.
"""
from __future__ import annotations

import math
import re
import unicodedata
from fractions import Fraction

from ..errors import InputError

__all__ = ["Node", "parse_expression", "FUNCTIONS", "MAX_LENGTH", "MAX_DEPTH", "MAX_EXPONENT",
           "Dimension", "dimension_of", "DimensionError", "names_in", "ExpressionError",
           "float_value"]

MAX_LENGTH = 500     #: characters in one expression
MAX_DEPTH = 32       #: nesting of parentheses, signs, powers and function calls
MAX_EXPONENT = 64    #: largest |exponent| of a power
MAX_NAME = 32        #: characters in one name

#: The functions of the grammar and their number of arguments.
FUNCTIONS = {"sin": 1, "cos": 1, "tan": 1, "exp": 1, "log": 1, "sqrt": 1, "sinh": 1,
             "cosh": 1, "atan2": 2, "abs": 1}


def float_value(op: str, args: list[float]) -> float:
    """The float meaning of the grammar: operator ``op`` (a node's kind: ``neg``, ``add``,
    ``sub``, ``mul``, ``div``, ``pow``) or function ``op`` (a call's name, of
    :data:`FUNCTIONS`) at ``args``. ``^`` is ``math.pow``, functions are the math module's.
    Python's own ZeroDivisionError, ValueError and OverflowError reach the caller, who words
    them (the parser folding constants, :func:`dyncalc.units.vector_expression.evaluate`).

    >>> float_value("pow", [2.0, 10.0]), float_value("atan2", [1.0, 1.0]) == math.pi / 4
    (1024.0, True)
    """
    if op == "neg":
        return -args[0]
    if op == "add":
        return args[0] + args[1]
    if op == "sub":
        return args[0] - args[1]
    if op == "mul":
        return args[0] * args[1]
    if op == "div":
        return args[0] / args[1]
    if op == "pow":
        return math.pow(args[0], args[1])
    if op == "atan2":
        return math.atan2(args[0], args[1])
    if op == "abs":
        return abs(args[0])
    return getattr(math, op)(args[0])

_NUMBER_RE = re.compile(r"(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_NAME_START = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_")
_NAME_REST = _NAME_START | frozenset("0123456789")
_RESERVED = frozenset({"inf", "infinity", "nan", "lambda", "import", "def", "class", "for",
                       "while", "if", "else", "in", "is", "not", "and", "or", "None", "True",
                       "False", "return", "yield", "from", "with", "exec", "eval"})
_WHY = {
    ".": "attribute access is not part of the grammar",
    "'": "strings are not part of the grammar (x' is the rate of a coordinate x)",
    '"': "strings are not part of the grammar",
    "[": "indexing and brackets are not part of the grammar; use ( )",
    "]": "indexing and brackets are not part of the grammar; use ( )",
    "{": "braces are not part of the grammar", "}": "braces are not part of the grammar",
    "=": "an expression has no '='", ";": "one expression only", ":": "':' is not part of "
    "the grammar", "@": "'@' is not part of the grammar", ",": "a comma separates the two "
    "arguments of atan2 only",
}


class ExpressionError(InputError):
    """Text outside the grammar: the message names the column (1-based) of the offence."""

    def __init__(self, label: str, text: str, column: int, why: str):
        super().__init__(f"{label}: {why} at column {column}: {_show(text)}")
        self.column, self.why = column, why


def _show(text: str, limit: int = 80) -> str:
    out = []
    for ch in text[:limit]:
        printable = ch.isprintable() and unicodedata.category(ch) not in ("Cf", "Zl", "Zp")
        out.append(ch if printable else f"\\u{ord(ch):04x}")
    return "'" + "".join(out) + ("..." if len(text) > limit else "") + "'"


class Node:
    """One node of an expression tree.

    ``kind`` is ``num`` (``value``: the SI base magnitude, ``dim``: its :class:`Dimension`,
    ``text``: the literal as typed, ``unit``: the unit text or ``""``), ``name`` (a parameter,
    or ``t``), ``rate`` (``name`` with ``order`` 1 or 2: ``x'``, ``x''``), ``pi``, ``neg``,
    ``add``, ``sub``, ``mul``, ``div``, ``pow`` (``args``: the operands) or ``call`` (``name``
    the function, ``args``). ``const`` is the float value of a subtree without names (used
    to bound constants and exponents), ``None`` otherwise; ``pos`` the 0-based position.
    """

    __slots__ = ("kind", "args", "name", "order", "value", "dim", "text", "unit", "const",
                 "pos")

    def __init__(self, kind: str, pos: int, args: tuple = (), name: str = "", order: int = 0,
                 value: float = 0.0, dim: Dimension | None = None, text: str = "",
                 unit: str = "", const: float | None = None):
        self.kind, self.pos, self.args, self.name, self.order = kind, pos, args, name, order
        self.value, self.dim, self.text, self.unit, self.const = value, dim, text, unit, const

    def __repr__(self) -> str:
        if self.kind == "num":
            return f"num({self.text}{' ' + self.unit if self.unit else ''})"
        if self.kind in ("name", "pi"):
            return self.name or "pi"
        if self.kind == "rate":
            return self.name + "'" * self.order
        inner = ", ".join(repr(a) for a in self.args)
        return f"{self.name or self.kind}({inner})"


class _Tok:
    __slots__ = ("kind", "text", "pos", "end")

    def __init__(self, kind: str, text: str, pos: int, end: int):
        self.kind, self.text, self.pos, self.end = kind, text, pos, end


def _tokenize(text: str, label: str) -> list[_Tok]:
    """NUM, NAME, RATE (``'`` or ``''`` right after a name), OP tokens."""
    toks: list[_Tok] = []
    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch in " \t":
            i += 1
            continue
        if ch.isascii() and ch.isdigit() or (ch == "." and i + 1 < n and text[i + 1].isdigit()
                                             and text[i + 1].isascii()):
            m = _NUMBER_RE.match(text, i)
            lit, end = m.group(0), m.end()
            if lit == "0" and end < n and text[end] in "xXoObB":
                raise ExpressionError(label, text, i + 1, "hexadecimal, octal and binary "
                                      "literals are not read")
            if re.match(r"0\d", lit):
                raise ExpressionError(label, text, i + 1, f"the leading zero in {lit!r} is "
                                      "ambiguous")
            if end < n and (text[end] in _NAME_START or text[end] == "."):
                if text[end] == "_" or text[end] == ".":
                    raise ExpressionError(label, text, end + 1, f"unexpected {text[end]!r} "
                                          "after a number")
            value = float(lit)
            if math.isinf(value):
                raise ExpressionError(label, text, i + 1, f"{lit} overflows float64")
            toks.append(_Tok("NUM", lit, i, end))
            i = end
            continue
        if ch in _NAME_START:
            j = i + 1
            while j < n and text[j] in _NAME_REST:
                j += 1
            word = text[i:j]
            if word.startswith("_"):
                raise ExpressionError(label, text, i + 1, f"names may not begin with '_' "
                                      f"({word[:MAX_NAME]!r})")
            if len(word) > MAX_NAME:
                raise ExpressionError(label, text, i + 1, f"a name is at most {MAX_NAME} "
                                      "characters")
            if word in _RESERVED:
                raise ExpressionError(label, text, i + 1, f"{word!r} is not a name the "
                                      "grammar reads")
            toks.append(_Tok("NAME", word, i, j))
            if j < n and text[j] == "'":
                k = j + 1 if not text.startswith("''", j) else j + 2
                if k < n and text[k] == "'":
                    raise ExpressionError(label, text, k + 1, "a rate has at most two primes "
                                          "(x'')")
                toks.append(_Tok("RATE", text[j:k], j, k))
                j = k
            i = j
            continue
        if text.startswith("**", i):
            toks.append(_Tok("OP", "^", i, i + 2))
            i += 2
            continue
        if ch in "+-*/^(),":
            toks.append(_Tok("OP", ch, i, i + 1))
            i += 1
            continue
        cat = unicodedata.category(ch)
        if cat.startswith("C") or cat.startswith("Z"):
            raise ExpressionError(label, text, i + 1, f"an invisible or control character "
                                  f"U+{ord(ch):04X}")
        why = _WHY.get(ch, f"the character {ch!r} is not part of the grammar")
        raise ExpressionError(label, text, i + 1, why)
    return toks


class Dimension:
    """A physical dimension as exponents of pint's base dimensions (``[mass]``, ``[length]``,
    ``[time]``, ...); angles count as pure numbers, as in pint. Immutable, hashable."""

    __slots__ = ("powers",)

    def __init__(self, powers=()):
        items = dict(powers) if not isinstance(powers, dict) else powers
        object.__setattr__(self, "powers", tuple(sorted(
            (k, Fraction(v).limit_denominator(1000)) for k, v in items.items() if v != 0)))

    def __setattr__(self, name, value):
        raise AttributeError("Dimension is immutable")

    def __mul__(self, other: Dimension) -> Dimension:
        out = dict(self.powers)
        for k, v in other.powers:
            out[k] = out.get(k, 0) + v
        return Dimension(out)

    def __truediv__(self, other: Dimension) -> Dimension:
        return self * other ** -1

    def __pow__(self, p) -> Dimension:
        p = Fraction(p).limit_denominator(1000)
        return Dimension({k: v * p for k, v in self.powers})

    def __eq__(self, other) -> bool:
        return isinstance(other, Dimension) and self.powers == other.powers

    def __hash__(self) -> int:
        return hash(self.powers)

    @property
    def none(self) -> bool:
        """Whether it is a pure number (or an angle)."""
        return not self.powers

    def __repr__(self) -> str:
        return f"Dimension({str(self)!r})"

    def __str__(self) -> str:
        if not self.powers:
            return "a pure number"
        order = ["[mass]", "[length]", "[time]"]
        ranked = sorted(self.powers, key=lambda kv: (order.index(kv[0]) if kv[0] in order
                                                     else 9, kv[0]))

        def part(k, v):
            return k if v == 1 else f"{k}^{v}" if v.denominator == 1 else f"{k}^({v})"
        up = [part(k, v) for k, v in ranked if v > 0]
        down = [part(k, -v) for k, v in ranked if v < 0]
        return ("*".join(up) or "1") + "".join("/" + d for d in down)


PURE = Dimension()


class DimensionError(InputError):
    """An expression whose parts do not fit together dimensionally."""


def dimension_of(node: Node, dims: dict[str, Dimension], label: str = "expression"
                 ) -> Dimension:
    """The dimension of ``node`` given those of its names (``dims``; a rate ``x'`` is that
    of ``x`` over time); ``t`` is a time. Raises :class:`DimensionError` on a sum of unlike
    terms, a function of a dimensioned argument or a power of a dimensioned base by a
    non-constant exponent.

    >>> L, T = Dimension({"[length]": 1}), Dimension({"[time]": 1})
    >>> str(dimension_of(parse_expression("x'^2/2", coordinates=("x",)), {"x": L}))
    '[length]^2/[time]^2'
    """
    time = Dimension({"[time]": 1})
    kind = node.kind
    if kind == "num":
        return node.dim
    if kind == "pi":
        return PURE
    if kind == "name":
        if node.name == "t":
            return time
        return dims[node.name]
    if kind == "rate":
        return dims[node.name] / time ** node.order
    if kind == "neg":
        return dimension_of(node.args[0], dims, label)
    if kind in ("add", "sub"):
        a, b = (dimension_of(x, dims, label) for x in node.args)
        if a != b:
            raise DimensionError(f"{label}: the terms of a sum differ in dimension ({a} and "
                                 f"{b}) at column {node.pos + 1}")
        return a
    if kind in ("mul", "div"):
        a, b = (dimension_of(x, dims, label) for x in node.args)
        return a * b if kind == "mul" else a / b
    if kind == "pow":
        base = dimension_of(node.args[0], dims, label)
        exponent = node.args[1]
        if not dimension_of(exponent, dims, label).none:
            raise DimensionError(f"{label}: an exponent must be a pure number (column "
                                 f"{exponent.pos + 1})")
        return base ** exponent.const if not base.none else PURE
    # call
    args = [dimension_of(x, dims, label) for x in node.args]
    if node.name == "sqrt":
        return args[0] ** Fraction(1, 2)
    if node.name == "abs":
        return args[0]
    if node.name == "atan2":
        if args[0] != args[1]:
            raise DimensionError(f"{label}: the two arguments of atan2 differ in dimension "
                                 f"({args[0]} and {args[1]}) at column {node.pos + 1}")
        return PURE
    if not args[0].none:
        raise DimensionError(f"{label}: {node.name}() takes a pure number or an angle; got "
                             f"{args[0]} at column {node.pos + 1}")
    return PURE


def names_in(node: Node) -> set[str]:
    """The names (parameters and ``t``) and the coordinates of rates in ``node``."""
    out: set[str] = set()
    stack = [node]
    while stack:
        n = stack.pop()
        if n.kind in ("name", "rate"):
            out.add(n.name)
        stack.extend(n.args)
    return out


class Parser:
    """Precedence climbing over the tokens of one expression; ``steps`` counts the work
    done (a bounded multiple of the number of tokens)."""

    def __init__(self, text: str, label: str, coordinates: tuple[str, ...], names: set[str],
                 free_names: bool, max_order: int):
        self.text, self.label = text, label
        self.coordinates, self.names = coordinates, names
        self.free_names, self.max_order = free_names, max_order
        self.toks = _tokenize(text, label)
        self.i = 0
        self.depth = 0
        self.steps = 0

    # -- helpers -------------------------------------------------------------------------
    def _fail(self, pos: int, why: str) -> ExpressionError:
        return ExpressionError(self.label, self.text, pos + 1, why)

    def _peek(self) -> _Tok | None:
        self.steps += 1
        return self.toks[self.i] if self.i < len(self.toks) else None

    def _is_op(self, tok: _Tok | None, ops: str) -> bool:
        return tok is not None and tok.kind == "OP" and tok.text in ops

    def _enter(self, pos: int) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise self._fail(pos, f"the expression nests deeper than {MAX_DEPTH} levels")

    def _unexpected(self, tok: _Tok | None) -> ExpressionError:
        if tok is None:
            return self._fail(len(self.text), "the expression ends too early")
        what = "name" if tok.kind == "NAME" else "number" if tok.kind == "NUM" else None
        shown = f"{what} {tok.text!r}" if what else repr(tok.text)
        hint = ""
        prev = self.toks[self.i - 1] if self.i > 0 else None
        if prev is not None and (tok.kind in ("NAME", "NUM") or tok.text == "(") and (
                prev.kind in ("NUM", "NAME", "RATE") or prev.text == ")"):
            hint = " (use * to multiply)"
        return self._fail(tok.pos, f"unexpected {shown}{hint}")

    # -- grammar -------------------------------------------------------------------------
    def parse(self) -> Node:
        if not self.toks:
            raise self._fail(0, "the expression is empty")
        node = self._expr()
        tok = self._peek()
        if tok is not None:
            raise self._unexpected(tok)
        return node

    def _expr(self) -> Node:
        node = self._term()
        while self._is_op(tok := self._peek(), "+-"):
            self.i += 1
            right = self._term()
            node = self._binary("add" if tok.text == "+" else "sub", node, right, tok.pos)
        return node

    def _term(self) -> Node:
        node = self._unary()
        while self._is_op(tok := self._peek(), "*/"):
            self.i += 1
            right = self._unary()
            node = self._binary("mul" if tok.text == "*" else "div", node, right, tok.pos)
        return node

    def _unary(self) -> Node:
        tok = self._peek()
        if self._is_op(tok, "+-"):
            self.i += 1
            self._enter(tok.pos)
            inner = self._unary()
            self.depth -= 1
            if tok.text == "+":
                return inner
            const = None if inner.const is None else -inner.const
            return Node("neg", tok.pos, (inner,), const=const)
        return self._power()

    def _power(self) -> Node:
        base = self._atom()
        tok = self._peek()
        if not self._is_op(tok, "^"):
            return base
        self.i += 1
        self._enter(tok.pos)
        sign = self._peek()
        negative = False
        if self._is_op(sign, "+-"):
            self.i += 1
            negative = sign.text == "-"
        exponent = self._atom()
        self.depth -= 1
        if negative:
            exponent = Node("neg", sign.pos, (exponent,),
                            const=None if exponent.const is None else -exponent.const)
        after = self._peek()
        if self._is_op(after, "^"):
            raise self._fail(after.pos, "a power of a power needs parentheses: (a^b)^c or "
                                        "a^(b^c)")
        if exponent.const is None:
            raise self._fail(tok.pos, "an exponent must be a constant number (use exp() "
                                      "for a variable one)")
        if not abs(exponent.const) <= MAX_EXPONENT:
            raise self._fail(tok.pos, f"an exponent must lie between -{MAX_EXPONENT} and "
                                      f"{MAX_EXPONENT}")
        return self._binary("pow", base, exponent, tok.pos)

    def _atom(self) -> Node:
        tok = self._peek()
        if tok is None:
            raise self._unexpected(None)
        if tok.kind == "NUM":
            self.i += 1
            return self._number(tok)
        if tok.kind == "NAME":
            self.i += 1
            return self._name(tok)
        if self._is_op(tok, "("):
            self.i += 1
            self._enter(tok.pos)
            node = self._expr()
            close = self._peek()
            if not self._is_op(close, ")"):
                if close is None:
                    raise self._fail(tok.pos, "this '(' is never closed")
                raise self._unexpected(close)
            self.i += 1
            self.depth -= 1
            return node
        raise self._unexpected(tok)

    def _name(self, tok: _Tok) -> Node:
        word = tok.text
        nxt = self._peek()
        if nxt is not None and nxt.kind == "RATE":
            self.i += 1
            order = len(nxt.text)
            if word not in self.coordinates:
                raise self._fail(nxt.pos, f"{word}{nxt.text} is a rate, but {word!r} is not "
                                          "a coordinate" + self._coordinates_said())
            if order > self.max_order:
                raise self._fail(nxt.pos, f"{word}{nxt.text}: at most {self.max_order} "
                                          f"prime{'s' if self.max_order > 1 else ''} here")
            return Node("rate", tok.pos, name=word, order=order)
        if self._is_op(nxt, "("):
            if word not in FUNCTIONS:
                raise self._fail(tok.pos, f"unknown function {word!r} (the functions are "
                                          f"{', '.join(FUNCTIONS)})")
            return self._call(word, tok)
        if word in FUNCTIONS:
            raise self._fail(tok.pos, f"{word} is a function: write {word}(...)")
        if word == "pi":
            return Node("pi", tok.pos, name="pi", const=math.pi)
        if word == "t" or word in self.coordinates or word in self.names or self.free_names:
            return Node("name", tok.pos, name=word)
        raise self._fail(tok.pos, f"unknown name {word!r}" + self._names_said())

    def _coordinates_said(self) -> str:
        if not self.coordinates:
            return ""
        return f" (the coordinates are {', '.join(self.coordinates)})"

    def _names_said(self) -> str:
        known = sorted(set(self.names) | set(self.coordinates) | {"t", "pi"})
        return f" (the names here are {', '.join(known)})"

    def _call(self, word: str, tok: _Tok) -> Node:
        self.i += 1  # the "("
        self._enter(tok.pos)
        args = [self._expr()]
        while self._is_op(self._peek(), ","):
            self.i += 1
            args.append(self._expr())
        close = self._peek()
        if not self._is_op(close, ")"):
            if close is None:
                raise self._fail(tok.pos + len(word), "this '(' is never closed")
            raise self._unexpected(close)
        self.i += 1
        self.depth -= 1
        if len(args) != FUNCTIONS[word]:
            count = FUNCTIONS[word]
            raise self._fail(tok.pos, f"{word}() takes {count} argument"
                                      f"{'s' if count > 1 else ''}, not {len(args)}")
        const = None
        if all(a.const is not None for a in args):
            const = self._fold(word, [a.const for a in args], tok.pos)
        return Node("call", tok.pos, tuple(args), name=word, const=const)

    def _fold(self, fn: str, xs: list[float], pos: int) -> float:
        try:
            value = float_value(fn, xs)
        except (ValueError, OverflowError):
            raise self._fail(pos, f"{fn}() is not defined (or overflows) at "
                                  f"{xs[0]:g}") from None
        return self._finite(value, pos)

    def _finite(self, value: float, pos: int) -> float:
        if not math.isfinite(value):
            raise self._fail(pos, "a constant here overflows float64 (or divides by zero)")
        return value

    def _binary(self, kind: str, a: Node, b: Node, pos: int) -> Node:
        const = None
        if a.const is not None and b.const is not None:
            x, y = a.const, b.const
            try:
                value = float_value(kind, [x, y])
            except (ZeroDivisionError, OverflowError, ValueError):
                raise self._fail(pos, "a constant here overflows float64, divides by zero "
                                      "or takes a fractional power of a negative number"
                                 ) from None
            const = self._finite(value, pos)
        return Node(kind, pos, (a, b), const=const)

    def _number(self, tok: _Tok) -> Node:
        from .grammar import is_unit_word, unit_in_base

        value = float(tok.text)
        start = self.i
        end = start
        # the unit after a number: unit words joined by * or / (no spaces inside the unit),
        # each with an optional integer power
        while end < len(self.toks):
            self.steps += 1
            t = self.toks[end]
            if end > start:
                prev = self.toks[end - 1]
                joined = (self._is_op(t, "*/") and prev.end == t.pos
                          and end + 1 < len(self.toks) and self.toks[end + 1].pos == t.end)
                if not joined:
                    break
                t = self.toks[end + 1]
                if not (t.kind == "NAME" and self._unit_word(t, end + 1, is_unit_word)):
                    break
                end += 1
            elif not (t.kind == "NAME" and self._unit_word(t, end, is_unit_word)):
                break
            end += 1
            if end + 1 < len(self.toks) and self._is_op(self.toks[end], "^") and \
                    self.toks[end].pos == self.toks[end - 1].end:
                k = end + 1
                if self._is_op(self.toks[k], "+-") and k + 1 < len(self.toks):
                    k += 1
                if self.toks[k].kind == "NUM" and self.toks[k].text.isdigit():
                    end = k + 1
        dim = PURE
        unit = ""
        if end > start:
            first, last = self.toks[start], self.toks[end - 1]
            unit = self.text[first.pos:last.end]
            try:
                factor, powers = unit_in_base(unit, label=self.label)
            except InputError as exc:
                raise self._fail(first.pos, f"cannot read the unit {unit!r} "
                                            f"({getattr(exc, 'why', exc)})") from None
            value *= factor
            dim = Dimension(powers)
            self.i = end
        elif start < len(self.toks) and self.toks[start].kind == "NAME" and not \
                self._is_op(self.toks[start + 1] if start + 1 < len(self.toks) else None,
                            "("):
            word = self.toks[start]
            if (word.text in self.names or word.text in self.coordinates) and \
                    is_unit_word(word.text):
                raise self._fail(word.pos, f"{word.text!r} after the number {tok.text} is a "
                                           "name of the expression here, not a unit: write "
                                           f"{tok.text}*{word.text} for the product")
            if word.text not in self.names and word.text not in self.coordinates and \
                    word.text != "t" and word.text != "pi":
                raise self._fail(word.pos, f"unknown unit {word.text!r} after the number "
                                           f"{tok.text} (use * to multiply)")
        value = self._finite(value, tok.pos)
        return Node("num", tok.pos, value=value, dim=dim, text=tok.text, unit=unit,
                    const=value)

    def _unit_word(self, tok: _Tok, index: int, is_unit_word) -> bool:
        """Whether the NAME token at ``index`` continues a number's unit."""
        word = tok.text
        if word == "t" or word in self.coordinates or word in self.names or word == "pi":
            return False
        if word in FUNCTIONS:
            return False
        nxt = self.toks[index + 1] if index + 1 < len(self.toks) else None
        if nxt is not None and (nxt.kind == "RATE" or self._is_op(nxt, "(")):
            return False
        return is_unit_word(word)


def parse_expression(text: str, *, label: str = "expression", coordinates=(),
                     names=(), free_names: bool = True, max_order: int = 1) -> Node:
    """Read ``text`` into a :class:`Node` tree.

    Parameters
    ----------
    text : str
        The expression, e.g. ``"m*x'^2/2 + 9.81 m/s^2 * m*x"``.
    label : str
        How the user gave it (``--T``): every message starts with it.
    coordinates : tuple of str
        The names whose rates (``x'``, and ``x''`` when ``max_order`` is 2) may appear.
    names : iterable of str
        Parameter names known to the caller (a unit word never takes their place).
    free_names : bool
        Whether any other name is a parameter (``eom`` without values) or refused.
    max_order : int
        Highest rate allowed (1 in energies).

    Examples
    --------
    >>> parse_expression("m*x'^2/2", coordinates=("x",))
    div(mul(m, pow(x', num(2))), num(2))
    """
    if not isinstance(text, str):
        raise InputError(f"{label}: expected text, got {type(text).__name__}")
    if len(text) > MAX_LENGTH:
        raise InputError(f"{label}: the expression is {len(text)} characters long; dyncalc "
                         f"reads at most {MAX_LENGTH}")
    parser = Parser(text, label, tuple(coordinates), set(names), free_names, max_order)
    return parser.parse()
