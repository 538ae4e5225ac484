"""``spring-series`` / ``spring-parallel --batch`` with element words on columns.

A cell of an element column (``k1``, ``k2``, ...) may hold a standard element,
``cantilever(l=2m, EI=2e4 N*m^2)``, ``simply-supported(...)``, ``beam(...)``,
``axial(...)``, ``torsion-bar(...)`` or ``coil(...)``, as on the command line. The rows of a chunk are grouped by the shape of their
cells (which element with which parameters, in which order, or a plain stiffness); each
parameter is read a column at a time (:func:`~dyncalc.batch.columns._read_column`), each
element's stiffness is :func:`~dyncalc.physics.numerics.monomial`'s twin
(:func:`~dyncalc.physics.numerics_arrays.monomial_array`) with the physics function's
coefficient and factors in its order, and the network is the series or parallel column kernel
in N/m, bit for bit the one-off (tests/test_batch_spring_elements.py). The one-off adds in the
first element's unit: an element's is SI (N/m, N*m/rad), so a group is taken where its
first element is an element word or a stiffness typed in SI (or bare).

A column whose cells share one template (the same word, names, units and spacing; only
the numbers differ: the common file) is split without a pass per cell: the template's fixed
texts are replaced away and the literals read as JSON at once, the split checked by writing
the lines back (:func:`_split_fixed`; one regular expression where JSON refuses a literal).

Shared values (``EI=...`` columns) and nested groups are
:mod:`dyncalc.batch.fast_spring_trees`'s. Left to the one-off row by row: expressions in
parentheses, a header unit on a column of element words, and every row that warns or is refused (a non-positive or infinite value, an
element or a result that overflows or underflows).
"""
from __future__ import annotations

import json
import re

import numpy as np

from .cells import Table
from .columns import _read_column, read_literals
from .fast import FastBlock, _input_texts, json_head
from .floats import json_floats
from .spring_forms import ELEMENT_FORMS

__all__ = ["spring_fast", "ELEMENT_FORMS"]

_CELL_RE = re.compile(r"^\s*(cantilever|simply-supported|beam|axial|torsion-bar|coil)\s*"
                      r"\(([^()\[\]\"]*)\)\s*$")
_ARG_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*=(.*)$", re.S)
_NUMBER_START_RE = re.compile(r"^\s*[-+.0-9]")
#: A parameter's value (after its ``=``, up to the next comma or parenthesis): the cells of a
#: column differ in these alone when they have one shape.
_VALUE_RE = re.compile(r"=([^,()\n]*)")
#: The smallest normal float: a result below it may have underflowed (the one-off warns).
_TINY = 2.2250738585072014e-308


def spring_fast(spec, columns, table, want_json: bool, cache: dict) -> list[FastBlock]:
    """The chunk's rows of plain stiffnesses (:func:`~dyncalc.batch.fast_commands._command_fast`)
    and of element words (here); the others are left to the generic path."""
    from .fast_commands import _command_fast
    from .fast_spring_trees import tree_fast

    if table and columns and any(spec.parameter(col.key) is None for col in columns):
        n = table.n if isinstance(table, Table) else len(table[0])
        cells = {col.key: list(map(str.strip, table[col.index])) for col in columns}
        return tree_fast(spec, columns, cells, range(n), want_json, cache)
    if not table or not columns or (isinstance(table, Table) and table.numbers() is not None):
        return _command_fast(spec, columns, table, want_json, cache)
    uniform = _uniform(columns, table)
    if uniform is not None:  # every row one shape, its values read off each column at once
        key, parsed = uniform
        n = table.n if isinstance(table, Table) else len(table[0])
        block = _group_block(spec, columns, key, np.arange(n),
                             {col.key: table[col.index] for col in columns}, want_json, cache,
                             parsed)
        return [] if block is None else [block]
    cells = {col.key: list(map(str.strip, table[col.index])) for col in columns}
    if not any("(" in c for col in columns for c in cells[col.key]):
        return _command_fast(spec, columns, table, want_json, cache)
    # a column of element words in every row leaves no row to the plain stiffnesses' path
    blocks = [] if any(all("(" in c for c in cells[col.key]) for col in columns) else \
        _command_fast(spec, columns, table, want_json, cache)
    known: dict[str, object] = {}   # the shape of each skeleton (a cell with its values cut)
    shapes = [[_shape_of(c, known) for c in cells[col.key]] for col in columns]
    groups: dict[tuple, list[int]] = {}
    for i, key in enumerate(zip(*shapes)):
        groups.setdefault(key, []).append(i)
    nested = []
    for key, members in groups.items():
        if any(s is None for s in key):
            nested += members
            continue
        if not any(isinstance(s, tuple) for s in key):
            continue
        block = _group_block(spec, columns, key, np.asarray(members, dtype=np.intp), cells,
                             want_json, cache)
        if block is not None:
            blocks.append(block)
    if nested:  # nested groups (and what else parse_cell takes)
        blocks += tree_fast(spec, columns, cells, sorted(nested), want_json, cache)
    return blocks


def _uniform(columns, table):
    """``(shapes, parsed)`` where every cell of each column has its first cell's form: a
    plain number (``parsed[key]``: ``(values, cells)``) or one element word whose cells differ
    only in their number literals (``parsed[key]``: ``{parameter: (literals, values or None,
    unit, texts around the literal)}``); ``None`` otherwise (then rows are grouped by shape)."""
    from .columns import _plain_floats

    shapes, parsed = [], {}
    for col in columns:
        column = table[col.index]
        first = column[0] if len(column) else ""
        if "(" not in first:
            values = _plain_floats(column)
            if values is None:
                return None
            shapes.append("leaf")
            parsed[col.key] = (values, column)
            continue
        read = _element_column(column, first)
        if read is None:
            return None
        shapes.append(read[0])
        parsed[col.key] = read[1]
    return tuple(shapes), parsed


def _element_column(column: list[str], first: str):
    """``(shape, {parameter: (literals, values or None, unit, (text before, text after the
    literal))})`` of a column of element words whose every cell is ``first`` but for its
    number literals (split off as :func:`~dyncalc.batch.columns._read_column` splits a value
    from its unit), or ``None``.

    Example: ``["axial(l=2 m, EA=3 N)", "axial(l=5 m, EA=1e6 N)"]`` gives the shape
    ``("axial", ("l", "EA"))``, ``l``'s literals ``["2", "5"]`` in ``m``, ``EA``'s
    ``["3", "1e6"]`` in ``N``."""
    from .columns import _CELL_LINE_RE, _LITERAL_CELL

    shape = _shape(_VALUE_RE.sub("=", first)) if first == first.strip() else None
    if not isinstance(shape, tuple):
        return None
    fixed, pattern, units, at = [], ["^"], [], 0
    for m in _VALUE_RE.finditer(first):
        value = m.group(1)
        lead = value[:len(value) - len(value.lstrip(" \t"))]
        split = _CELL_LINE_RE.match(value.strip())
        if split is None or value.strip() != value[len(lead):].rstrip():
            return None
        rest = value[len(lead) + len(split.group(1)):]
        fixed.append(first[at:m.start(1)] + lead)
        fixed.append(rest)
        pattern += [re.escape(fixed[-2]), f"({_LITERAL_CELL})", re.escape(rest)]
        units.append((split.group(2).rstrip(" \t"), (lead, rest)))
        at = m.end(1)
    pattern += [re.escape(first[at:]), "$"]
    texts = [fixed[0], *(fixed[i] + fixed[i + 1] for i in range(1, len(fixed) - 1, 2)),
             fixed[-1] + first[at:]]
    n, k = len(column), len(units)
    joined = "\n".join(column)
    if joined.count("\n") != n - 1:
        return None
    found = _split_fixed(joined, n, texts)
    values = None
    if found is not None:
        values = json_floats(",".join(found), n * k, found)
        if values is None:
            found = None
    if found is None:  # (a literal JSON does not read: ``+5``, ``.5``)
        found = re.compile("".join(pattern), re.M).findall(joined)
        if len(found) != n:
            return None
        found = [x for row in found for x in row] if k > 1 else found
    literals = [found[j::k] for j in range(k)] if k > 1 else [found]
    values = [None] * k if values is None else list(values.reshape(n, k).T)
    return shape, {name: (lits, vals, unit, around) for name, lits, vals, (unit, around)
                   in zip(shape[1], literals, values, units)}


#: Characters that may continue a number literal: a fixed text starting with one could
#: take part of the literal (the reader splits a literal off greedily).
_CONTINUES = frozenset("0123456789.eE")


def _split_fixed(joined: str, n: int, texts: list[str]) -> list[str] | None:
    """The values of ``n`` lines (``joined``) that each read ``texts[0] v1 texts[1] v2 ...
    texts[k]``, row after row (``[v1, v2, ..., vk, v1, ...]``), where every value is a JSON
    number (the caller checks), split by plain text replacement and checked by writing the
    lines back; ``None`` otherwise."""
    k = len(texts) - 1
    if any(not t or t[0] in _CONTINUES for t in texts[1:]) or "\n" in "".join(texts):
        return None
    text = ("\n" + joined + "\n").replace("\n" + texts[0], "\n").replace(texts[-1] + "\n", "\n")
    for t in texts[1:-1]:
        text = text.replace(t, "\n")
    found = text[1:-1].split("\n")
    if len(found) != n * k or " " in text or "\t" in text or "\r" in text:
        return None
    width = 2 * k + 1
    parts: list = [None] * (n * width)
    parts[0::width] = [texts[0]] * n
    for j in range(k):
        parts[2 * j + 1::width] = found[j::k]
        parts[2 * j + 2::width] = [texts[j + 1]] * n
    parts[width - 1::width] = [texts[-1] + "\n"] * n
    return found if "".join(parts) == joined + "\n" else None


def _shape_of(cell: str, known: dict):
    """``""`` (empty), ``"leaf"`` (a stiffness), ``(kind, (names...))`` (an element taken
    here) or ``None`` (anything else: the one-off's); ``known``: the shapes of the skeletons
    seen (the cell with its values cut out)."""
    if not cell:
        return ""
    if "(" not in cell:
        return "leaf" if _NUMBER_START_RE.match(cell) else None
    skeleton = _VALUE_RE.sub("=", cell)
    if skeleton not in known:
        known[skeleton] = _shape(skeleton)
    return known[skeleton]


def _shape(skeleton: str):
    """The shape of an element cell whose values are cut out (``cantilever(l=, EI=)``)."""
    m = _CELL_RE.match(skeleton)
    if m is None:
        return None
    kind, body = m.group(1), m.group(2)
    names = []
    for arg in body.split(","):
        a = _ARG_RE.match(arg)
        if a is None or a.group(2).strip():
            return None
        names.append(a.group(1))
    _coefficient, lead, alternatives, required = ELEMENT_FORMS[kind]
    if len(set(names)) != len(names):
        return None
    need = {name for name, _p in (*lead, *required)}
    chosen = [g for g in alternatives if any(name in names for name, _p in g)]
    if len(chosen) > 1 or (alternatives and not chosen):
        return None
    if chosen:
        need |= {name for name, _p in chosen[0]}
    if set(names) != need:
        return None
    return kind, tuple(names)


def _texts(cells: list[str], names: tuple) -> dict[str, list[str]] | None:
    """The parameter texts of element cells of one shape (``names`` in the cells' order), by
    name, read off the whole column in one pass (as typed: blanks kept, as the one-off's
    input entries show them); ``None`` if the values do not line up."""
    values = _VALUE_RE.findall("\n".join(cells))
    if len(values) != len(cells) * len(names):
        return None
    k = len(names)
    return {name: values[j::k] for j, name in enumerate(names)}


def _group_block(spec, columns, key, rows, cells, want_json, cache,
                 parsed=None) -> FastBlock | None:
    """The block of ``rows`` (one shape a column: ``key``), or ``None``; ``parsed``: the
    columns read by :func:`_uniform` (``rows`` is then every row of the chunk, ``cells``
    the columns as they are, not stripped)."""
    from ..commands.springs import ELEMENTS
    from ..physics.columns import Columns
    from ..physics.numerics_arrays import monomial_array
    from ..physics.springs import parallel_stiffness, series_stiffness
    from ..units import STIFFNESS, TORSIONAL_STIFFNESS
    from .fast_commands import _Param, _probe

    how = spec.how
    given = [col for col, shape in zip(columns, key) if shape != ""]
    shapes = [shape for shape in key if shape != ""]
    torsional = {shape[0] == "torsion-bar" for shape in shapes if shape != "leaf"}
    if len(torsional) > 1:
        return None  # linear and torsional elements: the one-off's refusal
    dim = TORSIONAL_STIFFNESS if torsional.pop() else STIFFNESS
    m = len(rows)
    good = np.ones(m, dtype=bool)
    stiffness, inputs, results = [], [], {}
    row_list = rows.tolist()
    for index, (col, shape) in enumerate(zip(given, shapes), 1):
        name = f"k{index}"
        if parsed is not None and shape == "leaf":
            values, column = parsed[col.key]
            read = _read_column(column, col.unit, _Param(name, dim), spec.strict, cache,
                                values)
        elif shape == "leaf":
            column = [cells[col.key][i] for i in row_list]
            read = _read_column(column, col.unit, _Param(name, dim), spec.strict, cache)
        if shape == "leaf":
            good &= read.ok & np.isfinite(read.si) & (read.si > 0.0)
            if dim is TORSIONAL_STIFFNESS:  # a bare number is N/m to the one-off: linear
                good &= np.array([not assumed for _u, assumed in read.unit_json], dtype=bool)
            if index == 1:  # the one-off adds in the first element's unit: SI here
                good &= np.array([json.loads(u) == dim.si for u, _a in read.unit_json],
                                 dtype=bool) if m else good
            stiffness.append(read.si)
            inputs.append((name, read, column, col.unit, parsed is not None, None))
            continue
        if col.unit:
            return None
        kind, names = shape
        coefficient, lead, alternatives, required = ELEMENT_FORMS[kind]
        dims = ELEMENTS[kind].params
        texts = _texts([cells[col.key][i] for i in row_list], names) if parsed is None \
            else None
        if parsed is None and texts is None:
            return None
        si = {}
        for pname in names:
            if parsed is None:
                read = _read_column([v.strip() for v in texts[pname]], "",
                                    _Param(pname, dims[pname]), spec.strict, cache)
                shown = (texts[pname], "as typed")
            else:
                literals, values, unit, around = parsed[col.key][pname]
                read = read_literals(literals, unit, _Param(pname, dims[pname]), spec.strict,
                                     cache, values)
                shown = (literals, around)
            good &= read.ok & np.isfinite(read.si) & (read.si > 0.0)
            si[pname] = np.where(good, read.si, 1.0)
            inputs.append((f"{name}.{pname}", read, shown[0], "", shown[1], None))
        chosen = [g for g in alternatives if g[0][0] in names]
        factors = [(si[p], power) for p, power in (*lead, *(chosen[0] if chosen else ()))]
        factors += [(si[p], power) for p, power in required]
        k = monomial_array(coefficient, factors)
        good &= np.isfinite(k) & (k >= _TINY)
        stiffness.append(k)
        results[name] = k
    if not good.any():
        return None
    kernel = (series_stiffness if how == "series" else parallel_stiffness).columns
    with np.errstate(all="ignore"):
        out = kernel(np.column_stack([np.where(good, k, 1.0) for k in stiffness]))
    k_eq = out.values["k_eq"]
    good &= out.exact & np.isfinite(k_eq) & (k_eq >= _TINY)
    if not good.any():
        return None
    values = {"k_eq": k_eq, **results}
    first = int(np.argmax(good))
    columns_out = Columns(values, exact=good, model=how)
    # one probe per kind of block a run (the shapes, the units typed), not one per chunk
    kind = ("elements", key, tuple(read.unit_json[first] for _n, read, *_r in inputs))
    probed = getattr(spec, "probed", {})
    if kind not in probed:
        if parsed is not None:  # the first good row's cells, as the one-off reads them
            cells = {col.key: {first: cells[col.key][first].strip()} for col in given}
        if _probe(spec, given, cells, int(rows[first]), columns_out,
                  {name: array[first] for name, array in values.items()}) is None:
            return None
        probed[kind] = True
    keep = np.flatnonzero(good)
    head = texts_out = None
    if want_json:
        head = json_head(spec.command, None, how, "closed-form")
        texts_out = _input_texts(inputs, keep, {})
    return FastBlock(rows[keep], {name: array[keep] for name, array in values.items()},
                     {name: dim for name in values}, head, texts_out, "{}")

