"""Vectors whose components are expressions with units: ``"0.1*5*sin(35deg), 0, 0 m/s"``,
``"l*cos(30deg), l*sin(30deg), 0"`` with ``l=2m`` (SPEC "Quantities on the command line":
"a component may be an expression with units").

Each component is read by the closed grammar of :mod:`dyncalc.units.expression` (never
``eval``) and evaluated here on floats. A component that carries its own unit (a dimension,
through its numbers or parameters) is taken as it is; a bare one (a pure number, angles
included) takes the trailing unit: the unit written after the last number of the last
component, or after the closing bracket (``"(l, 0, 0) m"``); with no unit at all a bare
component is in the SI unit of the vector (and refused by ``--strict-units``). A component of
another dimension is refused naming it. ``t`` belongs to motion given in time.

:func:`needs_expressions` says whether a text needs this reader (an operator, a parenthesis,
a parameter or a unit inside a component); a vector of plain numbers stays with
:func:`~dyncalc.units.grammar.parse_vector` and its messages.
"""
from __future__ import annotations

import math
import re

from ..errors import InputError
from .expression import (Dimension, DimensionError, Node, dimension_of, float_value,
                         names_in, parse_expression)

__all__ = ["needs_expressions", "split_components", "parse_vector_expression",
           "evaluate", "read_parameters"]

_WORD_RE = re.compile(r"[A-Za-z_][A-Za-z_0-9]*")
_OPENERS, _CLOSERS = "([", ")]"
#: A unit at the end of the last component (``m/s^2``, ``kN*m/rad``), after a space or digit.
_TRAILING_UNIT_RE = re.compile(r"(?<=[\s\d.])(?:1\s*/\s*)?[A-Za-z_°µμΩ][\w°µμΩ^·.]*"
                               r"(?:\s*[*/]\s*[A-Za-z_°µμΩ1][\w°µμΩ^·.]*)*\s*$")


def split_components(text: str) -> tuple[list[tuple[int, str]], str]:
    """``([(offset, component text), ...], unit after a closing bracket)``: the components of
    ``text`` split at the commas outside parentheses, ``offset`` the 0-based position of each
    component in ``text``. ``"(a, b, c) m/s"`` gives the three inside and ``"m/s"``."""
    stripped = len(text) - len(text.lstrip())
    body, base, unit = text, 0, ""
    if text.lstrip()[:1] in ("(", "["):
        depth, close = 0, None
        for i in range(stripped, len(text)):
            if text[i] in _OPENERS:
                depth += 1
            elif text[i] in _CLOSERS:
                depth -= 1
                if depth == 0:
                    close = i
                    break
        if close is not None and _top_commas(text[stripped + 1:close]):
            body, base, unit = text[stripped + 1:close], stripped + 1, text[close + 1:].strip()
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(body):
        if ch in _OPENERS:
            depth += 1
        elif ch in _CLOSERS:
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append((base + start, body[start:i]))
            start = i + 1
    parts.append((base + start, body[start:]))
    return parts, unit


def _top_commas(text: str) -> bool:
    depth = 0
    for ch in text:
        depth += ch in _OPENERS
        depth -= ch in _CLOSERS
        if ch == "," and depth == 0:
            return True
    return False


def needs_expressions(text: str, names=()) -> bool:
    """Whether the vector ``text`` has a component that is more than a signed number (the
    last one may end in the trailing unit): an operator or parenthesis inside a component, a
    parameter's name, or a unit on any component but the last."""
    if not isinstance(text, str) or "," not in text:
        return False
    parts, _unit = split_components(text)
    names = set(names)
    for index, (_, part) in enumerate(parts):
        body = _TRAILING_UNIT_RE.sub("", part) if index == len(parts) - 1 else part
        if any(ch in body for ch in "*/^()"):
            return True
        words = set(_WORD_RE.findall(part.replace("e+", " ").replace("e-", " ")))
        if words & names:
            return True
        if index < len(parts) - 1 and any(ch.isalpha() for ch in part.strip().lstrip("+-")
                                          if ch not in "eE"):
            return True
    return False


def evaluate(node: Node, values: dict[str, float], label: str = "expression") -> float:
    """The float value of ``node`` with ``values`` (SI) for its names; numbers are in SI
    already. Raises :class:`~dyncalc.errors.InputError` where a function is not defined or a
    value overflows, naming the column.

    >>> evaluate(parse_expression("l*cos(60deg)", names={"l"}), {"l": 2.0})
    1.0000000000000002
    """
    kind = node.kind
    if kind == "num":
        return node.value
    if kind == "pi":
        return math.pi
    if kind == "name":
        return values[node.name]
    args = [evaluate(a, values, label) for a in node.args]
    try:
        out = float_value(node.name if kind == "call" else kind, args)
    except ZeroDivisionError:
        raise InputError(f"{label}: division by zero at column {node.pos + 1}") from None
    except (ValueError, OverflowError):
        what = node.name + "()" if kind == "call" else "the value"
        raise InputError(f"{label}: {what} is not defined or overflows at column "
                         f"{node.pos + 1}") from None
    if not math.isfinite(out):
        raise InputError(f"{label}: the value overflows float64 at column {node.pos + 1}")
    return out


def read_parameters(texts: dict[str, str], labels: dict[str, str] | None = None
                    ) -> dict[str, tuple[float, Dimension, str]]:
    """``NAME=QUANTITY`` parameters of the expressions: name -> (SI value, dimension, how it
    was read). A name of a function, ``t`` or ``pi`` is refused."""
    from .expression import FUNCTIONS
    from .grammar import quantity_in_base

    out = {}
    for name, text in texts.items():
        label = (labels or {}).get(name, f"{name}=")
        if name in FUNCTIONS or name in ("t", "pi") or not _WORD_RE.fullmatch(name):
            raise InputError(f"{label}: {name!r} cannot be a parameter name (it is a function, "
                             "t or pi)")
        value, powers, reading = quantity_in_base(text, label=label)
        out[name] = (value, Dimension(powers), reading)
    return out


def _dimension(dim) -> Dimension:
    from .grammar import unit_in_base

    return Dimension(unit_in_base(dim.si)[1]) if dim.si else Dimension()


def parse_vector_expression(text: str, dim, *, label: str, params=None,
                            strict: bool = False):
    """Read a vector of 3 component expressions -> :class:`~dyncalc.units.grammar.Parsed`
    (``si`` a numpy array in the SI unit of ``dim``, ``unit_text`` empty: the value is SI).

    Parameters
    ----------
    text : str
        ``"0.1*5*sin(35deg), 0, 0 m/s"``, ``"(l*cos(30deg), l*sin(30deg), 0) m"``.
    dim : Dim
        The vector's dimension (``VELOCITY``, ``ANGULAR_RATE``, ...).
    label : str
        The option (``--vr``): every message starts with it.
    params : dict, optional
        From :func:`read_parameters`: name -> (SI value, Dimension, reading).
    strict : bool
        ``--strict-units``: a bare component with no trailing unit is refused.

    Examples
    --------
    >>> from dyncalc.units import VELOCITY
    >>> parse_vector_expression("0.5*sin(30deg), 0, 2 km/h", VELOCITY, label="--vr").si.round(6)
    array([0.069444, 0.      , 0.555556])
    """
    import numpy as np

    from .grammar import Parsed, parse_quantity, registry

    params = params or {}
    _check_brackets(text, label)
    parts, unit = split_components(text)
    if len(parts) != 3:
        raise InputError(f"{label} must have 3 components; got {len(parts)} in "
                         f"{_quote(text)}")
    nodes = []
    for index, (offset, part) in enumerate(parts, 1):
        if not part.strip():
            raise InputError(f"{label}: component {index} is empty in {_quote(text)}")
        try:
            node = parse_expression(part, label=label, names=set(params), free_names=False)
        except InputError as exc:
            column = getattr(exc, "column", None)
            if column is None:
                raise
            raise InputError(f"{label}: {exc.why} at column {offset + column}: "
                             f"{_quote(text)}") from None
        nodes.append((offset, node))
    if not unit:
        unit = _trailing_unit(nodes[-1][1], parts[-1][1])
    factor = 1.0
    if unit:
        factor = float(parse_quantity(f"1 {unit}", dim, label=f"{label} (its unit)").si)
    elif strict and dim.kind != "dimensionless":
        raise InputError(f"{label}: {_quote(text)} has no unit and --strict-units is on; "
                         f"write it with a unit, e.g. {text.strip()} {dim.si}")
    expected = _dimension(dim)
    dims = {name: d for name, (_v, d, _r) in params.items()}
    values = {name: v for name, (v, _d, _r) in params.items()}
    out, bare, own = [], False, False
    for index, (offset, node) in enumerate(nodes, 1):
        if "t" in names_in(node):
            raise InputError(f"{label}: component {index} depends on t: motion given in time "
                             "needs --t (the time to evaluate at)")
        try:
            found = dimension_of(node, dims, label)
        except DimensionError as exc:
            message = re.sub(r"column (\d+)", lambda m: f"column {offset + int(m.group(1))}",
                             str(exc))
            if message.endswith(")") and "(column" in message:
                message = message[:-1].replace("(column", "at column")
            raise InputError(f"{message}: {_quote(text)}") from None
        value = evaluate(node, values, label)
        if not found.none:
            _check_units(node, dim, expected, label)
        if found.none:
            bare = True
            value *= factor
        elif found != expected:
            start = offset + len(parts[index - 1][1]) - len(parts[index - 1][1].lstrip())
            raise InputError(f"{label}: component {index} is {found}, not {dim.name} "
                             f"{dim.display} at column {start + 1}: {_quote(text)}")
        else:
            own = True
        out.append(value)
    si = np.array(out, dtype=float) + 0.0
    if not np.all(np.isfinite(si)):
        raise InputError(f"{label} must be finite; got {_quote(text)}")
    quantity = registry().Quantity(si, dim.si.replace("^", "**") if dim.si else "")
    assumed = bare and not own and not unit and dim.kind != "dimensionless"
    return Parsed(quantity, si, assumed, "", text)


def _check_brackets(text: str, label: str) -> None:
    """Refuse an unclosed or unmatched parenthesis or bracket, pointing at it."""
    opened = []
    for i, ch in enumerate(text):
        if ch in _OPENERS:
            opened.append(i)
        elif ch in _CLOSERS:
            if not opened:
                raise InputError(f"{label}: this {ch!r} closes nothing at column {i + 1}: "
                                 f"{_quote(text)}")
            opened.pop()
    if opened:
        raise InputError(f"{label}: this {text[opened[-1]]!r} is never closed at column "
                         f"{opened[-1] + 1}: {_quote(text)}")


def _check_units(node: Node, dim, expected: Dimension, label: str) -> None:
    """Each number of ``node`` whose unit has the vector's dimension goes through
    :func:`~dyncalc.units.grammar.parse_quantity`'s checks for it (Hz refused for an angular
    rate, ``1/min`` with its advice, ...)."""
    from .grammar import parse_quantity, unit_in_base

    stack = [node]
    while stack:
        n = stack.pop()
        stack.extend(n.args)
        if n.kind == "num" and n.unit and Dimension(unit_in_base(n.unit)[1]) == expected:
            parse_quantity(f"{n.text} {n.unit}", dim, label=label)


def _trailing_unit(node: Node, part: str) -> str:
    """The unit written after the last number of the last component, when it ends the
    component (``"0 m/s"``, ``"2*l m"`` is not: a unit follows only a number)."""
    last = node
    while last.args and last.kind != "num":
        last = last.args[-1]
    if last.kind == "num" and last.unit and part.rstrip().endswith(last.unit):
        return last.unit
    return ""


def _quote(text: str) -> str:
    from .expression import _show

    return _show(text)
