"""Spring networks written on the command line, and their equivalent stiffness.

The grammar (one element per command-line word; the command combines its words in series or
in parallel)::

    element := STIFFNESS                      200N/m, "3 kN*m/rad", inf (a rigid link)
             | series(element, element, ...)
             | parallel(element, element, ...)
             | cantilever(l=..., EI=... | E=..., I=...)            3 EI / l^3
             | simply-supported(l=..., EI=... | E=..., I=...)      48 EI / l^3 (midspan)
             | beam(c=..., l=..., EI=... | E=..., I=...)           c EI / l^3 (any beam table)
             | axial(l=..., EA=... | E=..., A=...)                 EA / l
             | torsion-bar(l=..., GJ_t=... | G=..., J_t=...)       G J_t / l  (torsional)
             | coil(G=..., d=..., D=..., n=...)                    G d^4 / (8 D^3 n)
    shared  := NAME=QUANTITY                  a value every element that needs NAME and does
                                              not give it takes (E=200GPa, EI=..., l=...)

Leaves are numbered k1, k2, ... depth first; each element function's stiffness is reported as
a result of that name. Linear ``[force]/[length]`` and torsional ``[force]*[length]/[angle]``
elements cannot be mixed. The result is shown in the unit the elements were typed in when they
all share one, otherwise in SI.
"""
from __future__ import annotations

import functools
import math
import re
from dataclasses import dataclass, field

from ..errors import InputError, PhysicsError
from ..result.entries import Entry, Explanation, Result, entry_from_parsed
from ..units import (AREA, DIMENSIONLESS, FORCE, LENGTH, MODULUS, RIGIDITY, SECOND_MOMENT,
                     STIFFNESS, TORSIONAL_RIGIDITY, TORSIONAL_STIFFNESS, Dim, parse_quantity)
from ..units.split import split_top
from .record import Command, ResultName

__all__ = ["SPRING_SERIES", "SPRING_PARALLEL", "ELEMENTS", "network_stiffness", "parse_network",
           "read", "compute", "NetworkInputs"]

MAX_NETWORK_DEPTH = 16
MAX_ELEMENTS = 1000



@dataclass(frozen=True)
class ElementKind:
    """A standard elastic element: its parameters and the physics function that gives k."""

    name: str
    formula: str
    params: dict[str, Dim]
    alternatives: tuple[tuple[str, ...], ...]  # one group must be given: ("EI",) or ("E", "I")
    required: tuple[str, ...]
    function: str
    #: the element's stiffness is a product of powers of its parameters: name -> exponent
    #: (exact derivatives for the propagation of uncertainties: d k / d x = a k / x)
    exponents: dict[str, int] = field(default_factory=dict)
    torsional: bool = False

    def usage(self) -> str:
        groups = " | ".join(", ".join(f"{p}=..." for p in g) for g in self.alternatives)
        need = ", ".join(f"{p}=..." for p in self.required)
        return f"{self.name}({need}{', ' if groups and need else ''}{groups})"


_BEAM = {"EI": RIGIDITY, "E": MODULUS, "I": SECOND_MOMENT, "l": LENGTH}
_BEAM_POWERS = {"EI": 1, "E": 1, "I": 1, "l": -3, "c": 1}
ELEMENTS = {
    "cantilever": ElementKind("cantilever", "3 EI / l^3", _BEAM, (("EI",), ("E", "I")), ("l",),
                              "cantilever_stiffness", _BEAM_POWERS),
    "simply-supported": ElementKind("simply-supported", "48 EI / l^3", _BEAM,
                                    (("EI",), ("E", "I")), ("l",), "midspan_stiffness",
                                    _BEAM_POWERS),
    "beam": ElementKind("beam", "c EI / l^3", {**_BEAM, "c": DIMENSIONLESS},
                        (("EI",), ("E", "I")), ("c", "l"), "beam_stiffness", _BEAM_POWERS),
    "axial": ElementKind("axial", "EA / l", {"EA": FORCE, "E": MODULUS, "A": AREA, "l": LENGTH},
                         (("EA",), ("E", "A")), ("l",), "axial_stiffness",
                         {"EA": 1, "E": 1, "A": 1, "l": -1}),
    "torsion-bar": ElementKind("torsion-bar", "G J_t / l",
                               {"GJ_t": TORSIONAL_RIGIDITY, "G": MODULUS, "J_t": SECOND_MOMENT,
                                "l": LENGTH},
                               (("GJ_t",), ("G", "J_t")), ("l",), "torsion_bar_stiffness",
                               {"GJ_t": 1, "G": 1, "J_t": 1, "l": -1}, torsional=True),
    "coil": ElementKind("coil", "G d^4 / (8 D^3 n)",
                        {"G": MODULUS, "d": LENGTH, "D": LENGTH, "n": DIMENSIONLESS},
                        (), ("G", "d", "D", "n"), "coil_spring_stiffness",
                        {"G": 1, "d": 4, "D": -3, "n": -1}),
}
GROUPS = ("series", "parallel")


@dataclass
class Leaf:
    """A stiffness typed directly."""

    name: str
    parsed: object
    dim: Dim


@dataclass
class Element:
    """A standard element with its parameter texts (shared values filled in later)."""

    name: str
    kind: ElementKind
    texts: dict[str, str]
    parsed: dict = field(default_factory=dict)
    shared: set = field(default_factory=set)  # the parameters taken from a NAME= word


@dataclass
class Group:
    how: str  # "series" or "parallel"
    children: list


_CALL_RE = re.compile(r"^\s*([A-Za-z][A-Za-z_-]*)\s*\((.*)\)\s*$", re.S)
_OPEN_RE = re.compile(r"^\s*([A-Za-z][A-Za-z_-]*)\s*\(")
_SHARED_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*=(.*)$", re.S)


class _Reader:
    def __init__(self, strict: bool):
        self.strict = strict
        self.count = 0

    def next_name(self) -> str:
        self.count += 1
        if self.count > MAX_ELEMENTS:
            raise InputError(f"the network has more than {MAX_ELEMENTS} elements")
        return f"k{self.count}"

    def read(self, text: str, depth: int):
        if depth > MAX_NETWORK_DEPTH:
            raise InputError(f"the network is nested more than {MAX_NETWORK_DEPTH} levels deep")
        call = _CALL_RE.match(text)
        opened = _OPEN_RE.match(text)
        if not call and opened and (opened.group(1) in GROUPS or opened.group(1) in ELEMENTS):
            raise InputError(f"{opened.group(1)}(...): a '(' is not closed")
        if call and (call.group(1) in GROUPS or call.group(1) in ELEMENTS):
            fname, body = call.group(1), call.group(2)
            where = f"{fname}(...)"
            args = split_top(body, ",", where)
            if fname in GROUPS:
                if not any(a.strip() for a in args):
                    raise InputError(f"{fname}() needs at least one element")
                for a in args:
                    if not a.strip():
                        raise InputError(f"{fname}(...): an element is empty (two commas in "
                                         f"a row?)")
                return Group(fname, [self.read(a, depth + 1) for a in args])
            return self.element(ELEMENTS[fname], args)
        if call and not re.match(r"^\s*(inf|infinity)\s*\(", text, re.I):
            known = ", ".join((*GROUPS, *ELEMENTS))
            raise InputError(f"unknown element {call.group(1)!r}; the elements are {known}")
        return self.leaf(text)

    def leaf(self, text: str) -> Leaf:
        name = self.next_name()
        label = f"element {name} ({text.strip()[:40]})"
        try:
            parsed = parse_quantity(text, STIFFNESS, label=label, strict=self.strict,
                                    allow_inf=True, constraint="positive")
            return Leaf(name, parsed, STIFFNESS)
        except InputError as linear_error:
            try:
                parsed = parse_quantity(text, TORSIONAL_STIFFNESS, label=label,
                                        strict=self.strict, allow_inf=True,
                                        constraint="positive")
                return Leaf(name, parsed, TORSIONAL_STIFFNESS)
            except InputError:
                pass
            message = str(linear_error)
            if " must be a stiffness " in message:
                message = message.replace(
                    "must be a stiffness [force]/[length];",
                    "must be a stiffness [force]/[length] or [force]*[length]/[angle];")
            raise InputError(message) from None

    def element(self, kind: ElementKind, args: list[str]) -> Element:
        name = self.next_name()
        texts: dict[str, str] = {}
        for arg in args:
            if not arg.strip():
                if len(args) == 1:
                    continue
                raise InputError(f"{kind.name}(...): a parameter is empty (two commas in a row?)")
            m = _SHARED_RE.match(arg)
            if not m:
                raise InputError(f"{kind.name}(...): write parameters as NAME=QUANTITY; got "
                                 f"{arg.strip()[:40]!r}; usage: {kind.usage()}")
            pname, ptext = m.group(1), m.group(2)
            if pname not in kind.params:
                raise InputError(f"{kind.name}() has no parameter {pname!r}; usage: "
                                 f"{kind.usage()}")
            if pname in texts:
                raise InputError(f"{kind.name}(): {pname} is given twice")
            texts[pname] = ptext
        return Element(name, kind, texts)


def _leaves(node):
    if isinstance(node, Group):
        for child in node.children:
            yield from _leaves(child)
    else:
        yield node


def parse_network(how: str, words: list[str], strict: bool = False):
    """Read the command line's words into a network tree and the shared ``NAME=QUANTITY``.

    Returns ``(root, shared)`` where ``root`` is a :class:`Group` of kind ``how``.
    """
    reader = _Reader(strict)
    children, shared = [], {}
    for word in words:
        m = _SHARED_RE.match(word)
        if m and not _CALL_RE.match(word):
            pname = m.group(1)
            if pname in shared:
                raise InputError(f"{pname} is given twice")
            shared[pname] = m.group(2)
        else:
            if not word.strip():
                raise InputError("an element is empty")
            children.append(reader.read(word, 1))
    if not children:
        raise InputError(f"spring-{how} needs at least one stiffness, e.g. "
                         f"dyncalc spring-{how} 200N/m 300N/m")
    root = Group(how, children)
    _resolve_shared(root, shared, strict)
    return root, shared


def _resolve_shared(root, shared: dict[str, str], strict: bool) -> None:
    used = set()
    for leaf in _leaves(root):
        if not isinstance(leaf, Element):
            continue
        kind = leaf.kind
        own = set(leaf.texts)  # the rest come from the shared NAME=QUANTITY words
        for pname in kind.required:
            if pname not in leaf.texts:
                if pname not in shared:
                    raise InputError(f"{kind.name}() ({leaf.name}) needs {pname}: give it inside "
                                     f"the parentheses or as {pname}=... after the elements; "
                                     f"usage: {kind.usage()}")
                leaf.texts[pname] = shared[pname]
                used.add(pname)
        if kind.alternatives:
            given = [g for g in kind.alternatives if any(p in leaf.texts for p in g)]
            if len(given) > 1:
                raise InputError(f"{kind.name}() ({leaf.name}): give "
                                 f"{' or '.join('+'.join(g) for g in kind.alternatives)}, "
                                 "not both")
            if not given:
                usable = [g for g in kind.alternatives if all(p in shared for p in g)]
                if not usable:
                    need = " or ".join(" and ".join(g) for g in kind.alternatives)
                    raise InputError(f"{kind.name}() ({leaf.name}) needs {need}; usage: "
                                     f"{kind.usage()}")
                group = usable[0]
            else:
                group = given[0]
                missing = [p for p in group if p not in leaf.texts]
                for p in missing:
                    if p not in shared:
                        raise InputError(f"{kind.name}() ({leaf.name}) needs {p} with "
                                         f"{', '.join(q for q in group if q != p)}")
            for p in group:
                if p not in leaf.texts:
                    leaf.texts[p] = shared[p]
                    used.add(p)
        leaf.shared = set(leaf.texts) - own
        for pname, ptext in leaf.texts.items():
            dim = kind.params[pname]
            constraint = "positive"
            leaf.parsed[pname] = parse_quantity(
                ptext, dim, label=f"{pname} of {leaf.name}", strict=strict,
                constraint=constraint)
    unused = sorted(set(shared) - used)
    if unused:
        raise InputError(f"{unused[0]}={shared[unused[0]].strip()} is not used by any element; "
                         "shared values are for the parameters of cantilever(), "
                         "simply-supported(), beam(), axial(), torsion-bar() and coil()")


def _element_stiffness(element: Element):
    from ..physics import springs

    kind = element.kind
    q = {p: v.quantity for p, v in element.parsed.items()}
    fn = getattr(springs, kind.function)
    if kind.name == "coil":
        return fn(q["G"], q["d"], q["D"], element.parsed["n"].si)
    if kind.name == "beam":
        return fn(element.parsed["c"].si, q["l"], **{k: v for k, v in q.items()
                                                     if k not in ("c", "l")})
    return fn(q["l"], **{k: v for k, v in q.items() if k != "l"})


class NetworkInputs:
    """A network as read: its tree (every quantity parsed and checked) and how the top level
    combines; what :func:`compute` needs, and nothing typed is read again after this."""

    __slots__ = ("how", "root")

    def __init__(self, how: str, root: Group):
        self.how, self.root = how, root

    def __repr__(self) -> str:
        return f"NetworkInputs({self.how!r}, {len(list(_leaves(self.root)))} elements)"


def read(how: str, words: list[str], strict: bool = False) -> NetworkInputs:
    """The command's texts -> :class:`NetworkInputs` (see :func:`parse_network`)."""
    root, _shared = parse_network(how, words, strict)
    return NetworkInputs(how, root)


def network_stiffness(how: str, words: list[str], strict: bool = False) -> Result:
    """Equivalent stiffness of the network written in ``words``, combined ``how``
    (:func:`read`, then :func:`compute`).

    Parameters
    ----------
    how : {"series", "parallel"}
    words : list of str
        Elements and shared values as typed (see the module docstring).
    strict : bool
        ``--strict-units``: refuse bare numbers.

    Returns
    -------
    Result
        ``k_eq`` first, then each element function's own stiffness ``k1``, ``k2``, ...

    Examples
    --------
    >>> network_stiffness("series", ["200 N/m", "300 N/m"]).results["k_eq"].si
    120.0
    """
    return compute(read(how, words, strict))


def compute(inputs: NetworkInputs) -> Result:
    """The Result of a network read by :func:`read`: ``k_eq`` first, then each element
    function's own stiffness; the derivatives for the propagation of uncertainties are exact
    (:func:`_sensitivity`)."""
    from ..physics.springs import parallel_stiffness, series_stiffness

    how, root = inputs.how, inputs.root
    stiffness: dict[str, object] = {}
    inputs: dict[str, Entry] = {}
    element_results: dict[str, Entry] = {}
    kinds = set()
    for leaf in _leaves(root):
        if isinstance(leaf, Leaf):
            stiffness[leaf.name] = leaf.parsed.quantity
            inputs[leaf.name] = entry_from_parsed(leaf.name, leaf.parsed, leaf.dim)
            kinds.add(leaf.dim)
        else:
            k = _element_stiffness(leaf)
            dim = TORSIONAL_STIFFNESS if leaf.kind.torsional else STIFFNESS
            kinds.add(dim)
            if not math.isfinite(k.magnitude):
                raise PhysicsError(f"the stiffness of {leaf.kind.name}() ({leaf.name}) "
                                   f"overflows float64 ({k.units:~C})")
            stiffness[leaf.name] = k
            for pname, parsed in leaf.parsed.items():
                inputs[f"{leaf.name}.{pname}"] = entry_from_parsed(
                    f"{leaf.name}.{pname}", parsed, leaf.kind.params[pname])
            element_results[leaf.name] = Entry(
                leaf.name, float(k.magnitude), dim, unit=dim.si, symbol=leaf.name,
                description=f"{leaf.kind.name}: {leaf.kind.formula}")
    if len(kinds) > 1:
        raise InputError("linear [force]/[length] and torsional [force]*[length]/[angle] "
                         "stiffnesses cannot be combined in one network")
    dim = kinds.pop()

    def combine(node):
        if not isinstance(node, Group):
            return stiffness[node.name]
        parts = [combine(c) for c in node.children]
        return series_stiffness(parts) if node.how == "series" else parallel_stiffness(parts)

    si = dim.si.replace("^", "**")
    combined = combine(root)
    k_eq = float(combined.to(si).magnitude)
    all_finite = all(math.isfinite(float(q.to(si).magnitude)) for q in stiffness.values())
    warnings = []
    if math.isinf(k_eq):
        if all_finite:
            raise PhysicsError(f"k_eq overflows float64 (the largest is 1.8e308 {dim.si})")
        warnings.append("k_eq is infinite: the network is rigid (a rigid element carries the "
                        "load alone); JSON gives its value as null")
    # Shown in the unit the elements were typed in when every element is a stiffness typed in
    # one unit (then computed in it, exactly); otherwise in SI.
    leaves = list(_leaves(root))
    typed = {leaf.parsed.unit_text for leaf in leaves if isinstance(leaf, Leaf)}
    same_unit = (all(isinstance(leaf, Leaf) and inputs[leaf.name].exact is not None
                     for leaf in leaves) and len(typed) == 1)
    shown = typed.pop() if same_unit else dim.si
    exact = float(combined.to(leaves[0].parsed.quantity.units).magnitude) if same_unit else None
    results = {"k_eq": Entry("k_eq", k_eq, dim, unit=shown, symbol="k_eq",
                             description=f"equivalent stiffness ({how})", exact=exact)}
    results.update(element_results)
    result = Result(command=f"spring-{how}", results=results, inputs=inputs,
                    model="network" if _is_nested(root) else how, warnings=warnings,
                    explanation=lambda: _explain(root, stiffness, dim, results["k_eq"]))
    result.add_underflow_warnings()
    if len(root.children) > 1:
        result.slips["k_eq"] = _swapped_networks(root, combine, stiffness, si)
    result.sensitivity = lambda: _sensitivity(root, stiffness, si, k_eq)
    return result


def _sensitivity(root: Group, stiffness: dict, si: str, k_eq: float):
    """Exact derivatives of ``k_eq`` and of each element's stiffness with respect to every
    uncertain input (a stiffness typed, or an element's parameter; a shared ``NAME=`` value is
    one input, however many elements use it).

    Down the tree, ``d k_eq / d k_node`` is the product along the path of ``(K_g / k_c)^2``
    for a series group ``g`` (``1/K_g = sum 1/k_c``) and of 1 for a parallel one; an element's
    stiffness is a product of powers of its parameters, ``d k / d x = a k / x``.
    """
    from ..result.propagate import Sensitivity, UncertainInput

    values = {name: float(q.to(si).magnitude) for name, q in stiffness.items()}
    inputs: list[UncertainInput] = []
    index: dict[str, int] = {}
    # (input index, result name, d result / d input), summed per pair below
    parts: list[tuple[int, str, float]] = []

    def slot(key: str, parsed) -> int:
        if key not in index:
            index[key] = len(inputs)
            inputs.append(UncertainInput(key, float(parsed.si), float(parsed.uncertainty)))
        return index[key]

    def walk(node, weight: float, value: float) -> None:
        if isinstance(node, Group):
            for child in node.children:
                child_value = _node_value(child, values)
                if node.how == "parallel":
                    factor = 1.0
                else:  # K / k_c -> 1 for an element that underflowed to zero (K ~ k_c)
                    factor = (value / child_value) ** 2 if child_value > 0 else 1.0
                walk(child, weight * factor, child_value)
            return
        if isinstance(node, Leaf):
            if node.parsed.uncertainty is not None:
                parts.append((slot(node.name, node.parsed), "k_eq", weight))
            return
        for pname, parsed in node.parsed.items():
            if parsed.uncertainty is None:
                continue
            key = pname if pname in node.shared else f"{node.name}.{pname}"
            dk_dx = node.kind.exponents[pname] * value / float(parsed.si)
            i = slot(key, parsed)
            parts.append((i, node.name, dk_dx))
            parts.append((i, "k_eq", weight * dk_dx))

    walk(root, 1.0, k_eq)
    slopes: dict[str, dict[int, float]] = {}
    for i, name, slope in parts:
        row = slopes.setdefault(name, {})
        row[i] = row.get(i, 0.0) + slope
    failed = {"k_eq"} if not math.isfinite(k_eq) and inputs else set()
    return Sensitivity(inputs, slopes, failed)


def _node_value(node, values: dict[str, float]) -> float:
    """A node's stiffness in SI: an element's own, a group's combined (in floats, as the
    derivatives need it; k_eq itself is computed by the careful kernels)."""
    if not isinstance(node, Group):
        return values[node.name]
    parts = [_node_value(c, values) for c in node.children]
    if node.how == "parallel":
        return math.fsum(parts)
    if not all(p > 0 for p in parts):
        return 0.0
    inverse = math.fsum(1.0 / p for p in parts)
    return 1.0 / inverse if inverse > 0 else math.inf


def _swapped_networks(root: Group, combine, stiffness: dict, si: str) -> dict[str, float]:
    """What a network gives with series and parallel swapped: at the top (its elements
    combined the other way) and, for a nested network, everywhere."""
    from ..physics.springs import parallel_stiffness, series_stiffness

    def other(how: str):
        return series_stiffness if how == "parallel" else parallel_stiffness

    def all_swapped(node):
        if not isinstance(node, Group):
            return stiffness[node.name]
        return other(node.how)([all_swapped(c) for c in node.children])

    flipped = "series" if root.how == "parallel" else "parallel"
    ways = {f"the elements combined in {flipped}, not in {root.how}":
            lambda: other(root.how)([combine(c) for c in root.children])}
    if _is_nested(root):
        ways["series and parallel swapped throughout the network"] = lambda: all_swapped(root)
    slips = {}
    for words, way in ways.items():
        try:  # a slip beyond float64 is no slip anyone made
            slips[words] = float(way().to(si).magnitude)
        except (InputError, ArithmeticError):
            continue
    return slips


def _is_nested(root: Group) -> bool:
    return any(isinstance(c, Group) for c in root.children)


def _formula(node) -> str:
    if not isinstance(node, Group):
        return node.name
    inner = [_formula(c) for c in node.children]
    if node.how == "parallel":
        return " + ".join(inner) if len(inner) > 1 else inner[0]
    if len(inner) == 1:
        return inner[0]
    return "1/(" + " + ".join(f"1/{i}" if "+" not in i else f"1/({i})" for i in inner) + ")"


def _latex(node) -> str:
    """The network as a LaTeX template (``$k1`` for an element)."""
    if not isinstance(node, Group):
        return "${" + node.name + "}"
    inner = [_latex(c) for c in node.children]
    if node.how == "parallel" or len(inner) == 1:
        return " + ".join(inner)
    return r"\frac{1}{" + " + ".join(r"\frac{1}{" + i + "}" for i in inner) + "}"


def _explain(root, stiffness, dim: Dim, k_eq: Entry | None = None) -> Explanation:
    from ..result.explain import Term, render_formulas, symbol_latex

    si = dim.si.replace("^", "**")
    formula = ["k_eq = " + _formula(root)]
    substituted = [f"{name} = {float(q.to(si).magnitude):.6g} {dim.si}"
                   for name, q in stiffness.items()]
    latex = latex_substituted = []
    names = [leaf.name for leaf in _leaves(root)]
    if k_eq is not None and all(n.isidentifier() for n in names):
        terms = {name: Term(symbol_latex(name), float(q.to(si).magnitude), dim.si)
                 for name, q in stiffness.items()}
        terms["k_eq"] = Term(symbol_latex("k_eq"), k_eq.value_in(), k_eq.unit)
        latex, latex_substituted, text = render_formulas(
            ["$k_eq = " + _latex(root)], terms)
        substituted += text
    for leaf in _leaves(root):
        if isinstance(leaf, Element):
            formula.append(f"{leaf.name} = {leaf.kind.formula}  ({leaf.kind.name})")
    assumptions = ["linear elastic, massless elements",
                   "series: every element carries the same force; parallel: every element has "
                   "the same displacement"]
    return Explanation(formula, substituted, assumptions,
                       "Gross et al., Engineering Mechanics 3, Examples 5.11, 5.19, 5.26",
                       latex=latex, latex_substituted=latex_substituted)



_ELEMENT_KEY = re.compile(r"^k[0-9]+$")


def columns(given: dict, settings: dict):
    """``k_eq`` of a block of batch rows at once, or ``None`` when not vectorised here.

    ``given`` maps the element columns ``k1``, ``k2``, ... (in column order) to float64
    arrays: plain stiffnesses in SI (N/m, or N*m/rad for torsional elements); ``settings``
    holds ``how`` (``series`` or ``parallel``), ``units`` (key -> the unit the elements were
    typed in, ``""`` for a bare number: without it, ``None``) and ``typed`` (key -> the
    magnitudes as typed). Element functions (``cantilever(...)``) and shared values are not
    vectorised. Where the first element was typed in another unit than SI the one-off adds the
    elements in that unit (:func:`dyncalc.physics.springs._common_unit`): so does the adapter,
    from the magnitudes typed, each column converted by pint as the one-off converts a cell,
    and ``k_eq`` converted back to SI. Returns
    :class:`~dyncalc.physics.columns.Columns` with ``k_eq`` (the one-off's ``results``), exact
    where the one-off gives the same ``k_eq`` with no warning (no underflow to zero, no
    overflow, no rigid element) and no refusal.
    """
    from ..lazy import numpy as np
    from ..physics.columns import Columns
    from ..physics.springs import parallel_stiffness, series_stiffness
    from ..units import Q_
    from .columns import typed_in_si

    how = settings.get("how")
    if how not in GROUPS or not given or not all(_ELEMENT_KEY.match(key) for key in given):
        return None
    first = next(iter(given))
    k = np.column_stack([np.asarray(v, dtype=float) for v in given.values()])
    kernel = (series_stiffness if how == "series" else parallel_stiffness).columns
    exact = np.all(np.isfinite(k), axis=1)
    if typed_in_si(settings, first, "N/m", "N*m/rad"):
        out = kernel(k)
        k_eq = out.values["k_eq"]
    else:
        in_first = _in_first_unit(given, settings)
        if in_first is None:
            return None
        with np.errstate(all="ignore"):
            out = kernel(in_first)
            exact = exact & np.all(np.isfinite(in_first), axis=1)  # else the one-off adds in SI
            k_eq = np.asarray(Q_(out.values["k_eq"], _unit_of(settings["units"][first]))
                              .to("N/m").magnitude, dtype=float)
    exact = out.exact & exact & np.isfinite(k_eq) & (k_eq != 0.0)
    return Columns({"k_eq": k_eq}, exact=exact, model=how)


def _in_first_unit(given: dict, settings: dict):
    """The elements' magnitudes converted to the unit the first was typed in (rows x
    elements), as :func:`~dyncalc.physics.springs._common_unit` converts each quantity; ``None``
    where a unit or the magnitudes typed are not known, or an element is not linear."""
    from ..lazy import numpy as np
    from ..units import Q_

    units, typed = settings.get("units") or {}, settings.get("typed") or {}
    if not all(key in units and key in typed for key in given):
        return None
    try:
        first = _unit_of(units[next(iter(given))])
        with np.errstate(all="ignore"):
            columns = [np.asarray(Q_(np.asarray(typed[key], dtype=float), _unit_of(units[key]))
                                  .to(first).magnitude, dtype=float) for key in given]
    except (InputError, ValueError, TypeError, ArithmeticError):
        return None
    return np.column_stack(columns)


@functools.lru_cache(maxsize=64)
def _unit_of(text: str):
    """pint's unit of a stiffness typed in ``text`` (``""``: N/m), as the reader gives it."""
    from ..units import parse_quantity

    if not str(text).strip():
        return parse_quantity("1 N/m", STIFFNESS, label="k").quantity.units
    return parse_quantity(f"1 {text}", STIFFNESS, label="k").quantity.units


# --- the command records ---------------------------------------------------------------------

NETWORK_HELP = """
\b
Each ELEMENT is one of:
  200N/m, "3 kN*m/rad", inf         a stiffness (inf: a rigid link)
  "series(A, B, ...)"               elements in series, nested freely
  "parallel(A, B, ...)"             elements in parallel
  "cantilever(l=2m, EI=...)"        3 EI/l^3   (or E=... and I=...)
  "simply-supported(l=4m, EI=...)"  48 EI/l^3  at midspan
  "beam(c=..., l=..., EI=...)"      c EI/l^3   from any beam table
  "axial(l=..., EA=...)"            EA/l       (or E=... and A=...)
  "torsion-bar(l=..., GJ_t=...)"    G J_t/l    (or G=... and J_t=...), torsional
  "coil(G=..., d=..., D=..., n=...)"  G d^4/(8 D^3 n)
A word NAME=QUANTITY (E=200GPa, EI="2e4 N*m^2", l=1m) is a shared value that every
element needing NAME and not giving it takes. Linear and torsional elements cannot
be mixed. The result k_eq is in the unit the elements were typed in when they
share one, otherwise SI; element functions also report their own stiffness (k1, ...).
"""


def _record(how: str, summary: str, examples: str) -> Command:
    def run(values, words=(), *, rtol=None, strict=False) -> Result:
        return network_stiffness(how, list(words), strict=strict)

    results = (ResultName("k_eq", "k_eq", "N/m", f"equivalent stiffness ({how}); N*m/rad for "
                          "torsional elements"),
               ResultName("k<i>", "k<i>", "N/m", "the stiffness of element i, when it is a "
                          "standard element (cantilever(), coil(), ...)"))
    def adapter(given, settings):
        return columns(given, {**settings, "how": how})

    return Command(f"spring-{how}", summary.split("\n")[0],
                   f"{summary}\n{NETWORK_HELP}\n{examples}", (), results, run,
                   words="ELEMENT...", columns=adapter)


SPRING_SERIES = _record(
    "series",
    "Equivalent stiffness of springs in series: 1/k_eq = sum 1/k_i.",
    """\b
Examples:
  dyncalc spring-series "200 N/m" "300 N/m"                      # k_eq = 120 N/m
  dyncalc spring-series "parallel(cantilever(l=2m), cantilever(l=1m))" 5kN/m \\
      EI="2e4 N*m^2"                                   # E5.26, system 2
  dyncalc spring-series "beam(c=1, l=1m, EI=2e4N*m^2)" 5kN/m   # E5.19""")

SPRING_PARALLEL = _record(
    "parallel",
    "Equivalent stiffness of springs in parallel: k_eq = sum k_i.",
    """\b
Examples:
  dyncalc spring-parallel "200 N/m" "300 N/m"                    # k_eq = 500 N/m
  dyncalc spring-parallel "simply-supported(l=2*1.5m)" \\
      "axial(l=(1+2**0.5)*1.5m)" EI="1e5 N*m^2" EA="2e7 N"        # E5.11
  dyncalc spring-parallel "cantilever(l=2m)" "cantilever(l=1m)" 5kN/m \\
      EI="2e4 N*m^2"                                   # E5.26, system 1""")
