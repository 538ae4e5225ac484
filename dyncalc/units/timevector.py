"""Vectors whose components are expressions in time: ``"s0 - b*t^2/2, 0, 0 m"``.

The reading of ``coriolis``'s motion given in time (``--r``, ``--omega``, ``--R0`` with
``--t``): three components separated by commas outside parentheses, each read by the closed
grammar of :mod:`dyncalc.units.expression` (never ``eval``), with one optional trailing unit
after the last component (``"R*cos(w*t), R*sin(w*t), 0 m"``) or after brackets
(``"(s0 - b*t^2/2, 0, 0) m"``). A component of the vector's dimension is taken as it is; a
component that is a pure number takes the trailing unit; anything else is refused naming the
component. ``t`` is always time, never the tonne. No sympy here: the dimensions are checked on
the trees (:func:`~dyncalc.units.expression.dimension_of`) before anything is derived.
"""
from __future__ import annotations

from ..errors import InputError
from .expression import Dimension, Node, dimension_of, names_in, parse_expression
from .split import split_top

__all__ = ["TimeComponent", "TimeVector", "read_time_vector", "has_time"]


class TimeComponent:
    """One component: its tree, the SI factor it is multiplied by (the trailing unit's, 1.0 for
    a component carrying its own unit) and the text as typed."""

    __slots__ = ("node", "scale", "text")

    def __init__(self, node: Node, scale: float, text: str):
        self.node, self.scale, self.text = node, scale, text


class TimeVector:
    """Three :class:`TimeComponent` of one option (``label``: ``--r``), with the text typed;
    ``assumed_si`` the (1-based) components read in SI for want of a unit."""

    __slots__ = ("label", "components", "text", "assumed_si")

    def __init__(self, label: str, components: list[TimeComponent], text: str,
                 assumed_si: list[int] | None = None):
        self.label, self.components, self.text = label, components, text
        self.assumed_si = list(assumed_si or [])

    @property
    def names(self) -> set[str]:
        """The parameter names the components use (``t`` not included)."""
        out: set[str] = set()
        for c in self.components:
            out |= names_in(c.node)
        out.discard("t")
        return out

    @property
    def depends_on_time(self) -> bool:
        return any("t" in names_in(c.node) for c in self.components)


def _brackets(text: str) -> tuple[str, str] | None:
    """``("a, b, c", "m")`` for ``"(a, b, c) m"`` when the first bracket closes after the last
    component, else ``None``."""
    stripped = text.strip()
    if not stripped or stripped[0] not in "([":
        return None
    depth = 0
    for i, ch in enumerate(stripped):
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
            if depth == 0:
                inner, rest = stripped[1:i], stripped[i + 1:].strip()
                if "," not in "".join(split_top(inner)) and len(split_top(inner)) == 1:
                    return None  # "(a + b)*c, ..." : the brackets group one component
                if rest and rest[0] in "*/^+-":
                    return None
                return inner, rest
    return None


def _trailing_unit(last: str, names: set[str]) -> tuple[str, str]:
    """``(expression, unit)`` of the last component: the longest tail after a blank that is a
    unit (no parameter name, no ``t``) and leaves an expression before it; ``unit`` is ``""``
    when there is none."""
    from .grammar import unit_in_base

    text = last.strip()
    for i, ch in enumerate(text):
        if not ch.isspace() or i == 0:
            continue
        head, tail = text[:i].strip(), text[i:].strip()
        if not head or not tail or not (tail[0].isalpha() or tail[0] in "°µ"):
            continue
        words = {w for w in _words(tail)}
        if words & (names | {"t"}):
            continue
        try:
            unit_in_base(tail)
        except (InputError, Exception):  # noqa: BLE001 - not a unit: try a shorter tail
            continue
        return head, tail
    return text, ""


def _words(text: str) -> list[str]:
    out, word = [], ""
    for ch in text:
        if ch.isalnum() or ch == "_":
            word += ch
        else:
            if word:
                out.append(word)
            word = ""
    if word:
        out.append(word)
    return [w for w in out if not w[0].isdigit()]


def read_time_vector(text: str, dim: Dimension, *, label: str, params: dict[str, Dimension],
                     dim_words: str, unit_hint: str, strict: bool = False) -> TimeVector:
    """Read ``text`` as three component expressions of dimension ``dim``.

    Parameters
    ----------
    text : str
        The vector as typed, e.g. ``"s0 - b*t^2/2, 0, 0 m"``.
    dim : Dimension
        The dimension every component must have (angles count as pure numbers).
    label : str
        The option (``--r``): every message starts with it.
    params : dict of str to Dimension
        The parameters given (``NAME=`` words) and their dimensions; any other name is
        refused.
    dim_words, unit_hint : str
        The dimension in words (``a length``) and an example unit (``m``), for messages.
    strict : bool
        ``--strict-units``: a pure-number component without a trailing unit is refused
        (otherwise it is read in SI, and listed in ``assumed_si``).

    Examples
    --------
    >>> L, T = Dimension({"[length]": 1}), Dimension({"[time]": 1})
    >>> v = read_time_vector("s0 - b*t^2/2, 0, 0 m", L, label="--r",
    ...                      params={"s0": L, "b": L / T**2}, dim_words="a length",
    ...                      unit_hint="m")
    >>> [c.scale for c in v.components], sorted(v.names), v.depends_on_time
    ([1.0, 1.0, 1.0], ['b', 's0'], True)
    """
    from .grammar import unit_in_base

    names = set(params)
    if not isinstance(text, str):
        raise InputError(f"{label}: expected text, got {type(text).__name__}")
    bracketed = _brackets(text)
    if bracketed is not None:
        inner, unit = bracketed
        parts = split_top(inner, ",", where=label)
    else:
        parts = split_top(text, ",", where=label)
        unit = ""
        if len(parts) == 3:
            parts[-1], unit = _trailing_unit(parts[-1], names)
    if len(parts) != 3:
        raise InputError(f"{label} must have 3 components; got {len(parts)} in '{text[:80]}'")
    scale = 1.0
    if unit:
        factor, powers = unit_in_base(unit, label=label)
        if Dimension(powers) != dim:
            raise InputError(f"{label}: the unit {unit} is not {dim_words} ({dim}); give the "
                             f"components in {unit_hint}")
        scale = factor
    components, assumed = [], []
    for index, part in enumerate(parts, 1):
        where = f"{label} component {index}"
        if not part.strip():
            raise InputError(f"{where} is empty")
        node = parse_expression(part, label=where, names=names, free_names=False)
        got = dimension_of(node, params, where)
        if got == dim:
            components.append(TimeComponent(node, 1.0, part.strip()))
        elif got.none and unit:
            components.append(TimeComponent(node, scale, part.strip()))
        elif got.none and strict:
            raise InputError(f"{where} '{part.strip()}' has no unit (--strict-units): give the "
                             f"vector a trailing unit ('..., 0 {unit_hint}') or the component "
                             "its own")
        elif got.none:
            components.append(TimeComponent(node, 1.0, part.strip()))
            assumed.append(index)
        else:
            raise InputError(f"{where} '{part.strip()}' must be {dim_words} ({dim}); got {got}")
    return TimeVector(label, components, text, assumed)


def has_time(text: str) -> bool:
    """Whether ``text`` mentions the name ``t`` (a motion given in time), without reading it."""
    return "t" in _words(text)
