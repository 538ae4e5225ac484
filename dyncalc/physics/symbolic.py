"""Expression trees of :mod:`dyncalc.units.expression` -> sympy objects, and back to text.

The only modules that import sympy are this one, :mod:`dyncalc.physics.lagrange_equations` and
:mod:`dyncalc.physics.relative_time`, and only ``eom`` and ``coriolis`` with a motion given in
time (``--t``) import them (tests/test_eom.py and tests/test_coriolis_time.py check that no other
command or path loads sympy).
Nothing here reads text: the tree was parsed by the closed grammar, never by ``sympify``.

A number typed without a unit becomes an exact sympy number (``2`` an Integer, ``0.5`` the
Rational 1/2), so ``m*x'^2/2`` stays exact; one with a unit is its SI value as a Float
(``35deg`` is 0.610865...). Coordinates are the symbols ``x``; their rates ``x'`` and ``x''``
are symbols of those names.
"""
from __future__ import annotations

import sympy

from ..units.expression import Node

__all__ = ["to_sympy", "Symbols", "text_of", "latex_of"]


class Symbols:
    """The sympy symbols of one problem: coordinates ``q``, rates ``qd`` (``x'``),
    accelerations ``qdd`` (``x''``), the parameters (positive unless ``signed``) and ``t``."""

    def __init__(self, coordinates, parameters=(), signed=()):
        self.coordinates = list(coordinates)
        self.q = [sympy.Symbol(c, real=True) for c in self.coordinates]
        self.qd = [sympy.Symbol(c + "'", real=True) for c in self.coordinates]
        self.qdd = [sympy.Symbol(c + "''", real=True) for c in self.coordinates]
        self.t = sympy.Symbol("t", real=True)
        self.signed = set(signed)
        self.params: dict[str, sympy.Symbol] = {}
        for name in parameters:
            self.param(name)

    def param(self, name: str) -> sympy.Symbol:
        if name not in self.params:
            if name in self.signed:
                self.params[name] = sympy.Symbol(name, real=True)
            else:
                self.params[name] = sympy.Symbol(name, positive=True)
        return self.params[name]

    def of(self, node: Node):
        if node.kind == "rate":
            i = self.coordinates.index(node.name)
            return (self.qd if node.order == 1 else self.qdd)[i]
        if node.name == "t":
            return self.t
        if node.name in self.coordinates:
            return self.q[self.coordinates.index(node.name)]
        return self.param(node.name)


def _number(node: Node):
    if not node.unit:
        text = node.text
        if "e" not in text.lower() and "." not in text:
            return sympy.Integer(int(text))
        return sympy.Rational(text)
    return sympy.Float(node.value, 15)


_FUNCTIONS = {"sin": sympy.sin, "cos": sympy.cos, "tan": sympy.tan, "exp": sympy.exp,
              "log": sympy.log, "sqrt": sympy.sqrt, "sinh": sympy.sinh, "cosh": sympy.cosh,
              "atan2": sympy.atan2, "abs": sympy.Abs}


def to_sympy(node: Node, symbols: Symbols):
    """The sympy expression of ``node`` (an explicit stack: no recursion limit to meet).

    >>> from dyncalc.units.expression import parse_expression
    >>> s = Symbols(["x"])
    >>> to_sympy(parse_expression("m*x'^2/2 + 0.5*k*x^2", coordinates=("x",)), s)
    k*x**2/2 + m*x'**2/2
    """
    out: dict[int, object] = {}
    stack = [(node, False)]
    while stack:
        n, done = stack.pop()
        if not done and n.args:
            stack.append((n, True))
            stack.extend((a, False) for a in n.args)
            continue
        kind = n.kind
        if kind == "num":
            value = _number(n)
        elif kind == "pi":
            value = sympy.pi
        elif kind in ("name", "rate"):
            value = symbols.of(n)
        else:
            args = [out.pop(id(a)) for a in n.args]
            if kind == "neg":
                value = -args[0]
            elif kind == "add":
                value = args[0] + args[1]
            elif kind == "sub":
                value = args[0] - args[1]
            elif kind == "mul":
                value = args[0] * args[1]
            elif kind == "div":
                value = args[0] / args[1]
            elif kind == "pow":
                exponent = args[1]
                value = args[0] ** exponent
            else:
                value = _FUNCTIONS[n.name](*args)
        out[id(n)] = value
    return out[id(node)]


def text_of(expr) -> str:
    """A sympy expression as the grammar writes it: ``^`` for powers.

    >>> text_of(sympy.Symbol("k") * sympy.Symbol("x")**2 / 2)
    'k*x^2/2'
    """
    return sympy.sstr(expr).replace("**", "^")


def latex_of(expr, symbols: Symbols | None = None) -> str:
    """LaTeX of a sympy expression; rates as dots (``\\dot{x}``, ``\\ddot{x}``)."""
    names = {}
    if symbols is not None:
        for q, qd, qdd in zip(symbols.q, symbols.qd, symbols.qdd):
            base = sympy.latex(q)
            names[qd] = r"\dot{%s}" % base
            names[qdd] = r"\ddot{%s}" % base
    return sympy.latex(expr, symbol_names=names)
