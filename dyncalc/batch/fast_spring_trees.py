"""``spring-series`` / ``spring-parallel --batch``: nested groups and shared values on columns.

A cell may hold a nested network, ``parallel(cantilever(l=2m), 5 kN/m)``, and a column
named for an element parameter (``EI``, ``E``, ``l``, ...) is a shared value, as the command
line's ``NAME=QUANTITY`` words. Each row's cells are cut into a *structure* (the tree of
groups, elements with their parameter names, and stiffnesses, values taken out) and the value
texts in depth-first order (:func:`parse_cell`); rows of one structure (and the same shared
columns given) form a block, whose every value is read a column at a time, each element's
stiffness is :func:`~dyncalc.physics.numerics.monomial`'s array twin in the physics
function's order, and every group is the series or parallel column kernel of its children
(:func:`~dyncalc.physics.numerics_arrays.series_sum_rows`, ``parallel_sum_rows``), bottom
up as the one-off's ``combine``: bit for bit (tests/test_batch_spring_trees.py).

The one-off adds a group in its first element's unit; here a group is taken where its
leftmost stiffness is an element word or a stiffness typed in SI (or bare). Left to the
one-off row by row: expressions in parentheses, a header unit on a column of groups, shared
values that no element uses or that clash with an element's own (its refusals), and every row
that warns or is refused (a non-positive or infinite value, a stiffness, group or result that
overflows or underflows).
"""
from __future__ import annotations

import json
import re

import numpy as np

from .columns import _plain_floats, _read_column
from .fast import FastBlock, _input_texts, json_head

__all__ = ["parse_cell", "tree_fast"]

_SPLIT_RE = re.compile(r"([(),])")
_WORD_RE = re.compile(r"^\s*([A-Za-z][A-Za-z_-]*)\s*$")
_ARG_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*=(.*)$", re.S)
_NUMBER_START_RE = re.compile(r"^\s*[-+.0-9]")
_ELEMENT_RE = re.compile(r"^k[0-9]+$")
_TINY = 2.2250738585072014e-308


def parse_cell(cell: str):
    """``(structure, texts)`` of one element cell, or ``None`` (the one-off's to read).

    ``structure`` is ``("leaf",)``, ``("element", kind, names)`` or ``("group", how,
    children)``; ``texts`` the value texts as typed (blanks kept), depth first.

    >>> parse_cell("parallel(cantilever(l=2m), 5 kN/m)")
    (('group', 'parallel', (('element', 'cantilever', ('l',)), ('leaf',))), ['2m', ' 5 kN/m'])
    """
    from .spring_forms import ELEMENT_FORMS

    parts = _SPLIT_RE.split(cell)
    texts: list[str] = []

    def node(i: int):  # parts[i] is a text; returns (structure, next index) or None
        text = parts[i]
        if i + 1 < len(parts) and parts[i + 1] == "(":
            word = _WORD_RE.match(text)
            if word is None:
                return None
            name = word.group(1)
            if name in ("series", "parallel"):
                children, j = [], i + 2
                while True:
                    got = node(j)
                    if got is None:
                        return None
                    children.append(got[0])
                    j = got[1]
                    if j >= len(parts) or parts[j] not in ",)":
                        return None
                    if parts[j] == ")":
                        return _closed(("group", name, tuple(children)), j)
                    j += 1
            if name not in ELEMENT_FORMS:
                return None
            names, j = [], i + 2
            if j + 1 < len(parts) and not parts[j].strip() and parts[j + 1] == ")":
                return _closed(("element", name, ()), j + 1)  # ``cantilever()``: all shared
            while True:
                arg = _ARG_RE.match(parts[j]) if j < len(parts) else None
                if arg is None or j + 1 >= len(parts) or parts[j + 1] not in ",)" \
                        or not arg.group(2).strip():
                    return None
                names.append(arg.group(1))
                texts.append(arg.group(2))
                if parts[j + 1] == ")":
                    return _closed(("element", name, tuple(names)), j + 1)
                j += 2
        if not text.strip() or not _NUMBER_START_RE.match(text) or "=" in text:
            return None
        texts.append(text)
        return ("leaf",), i + 1

    def _closed(structure, j: int):  # parts[j] is the ")": only blanks may follow it
        if j + 1 >= len(parts) or parts[j + 1].strip():
            return None
        return structure, j + 2

    got = node(0)
    if got is None or got[1] != len(parts):
        return None
    return got[0], texts


def _resolve(kind: str, own: tuple, shared: tuple):
    """The element's parameter names in the one-off's order (its own as typed, then those
    taken from the shared columns, as ``_resolve_shared`` fills them) and the shared names it
    uses, or ``None`` where the one-off refuses the element."""
    from ..commands.springs import ELEMENTS

    spec = ELEMENTS[kind]
    if len(set(own)) != len(own) or any(p not in spec.params for p in own):
        return None
    names, used = list(own), []
    for p in spec.required:
        if p not in names:
            if p not in shared:
                return None
            names.append(p)
            used.append(p)
    if spec.alternatives:
        given = [g for g in spec.alternatives if any(p in own for p in g)]
        if len(given) > 1:
            return None
        if not given:
            usable = [g for g in spec.alternatives if all(p in shared for p in g)]
            if not usable:
                return None
            group = usable[0]
        else:
            group = given[0]
            if any(p not in names and p not in shared for p in group):
                return None
        for p in group:
            if p not in names:
                names.append(p)
                used.append(p)
    if set(names) - {p for g in spec.alternatives for p in g} - set(spec.required):
        return None
    return tuple(names), used


#: A value in a cell: after ``=`` or ``,`` (or a non-empty one after ``(``) up to the next
#: ``,`` or ``)``: the texts :func:`parse_cell` gives, in its order, cut out of a whole column.
_PIECE_RE = re.compile(r"(?<=[,=])[^(),=\n]*(?=[,)])|(?<=\()[^(),=\n]+(?=[,)])")


_LEAF, _OTHER = "\x00leaf", "\x00other"  # the skeletons of cells without "("


def _skeletons(column: list[str]) -> list[str] | None:
    """Each cell with its values cut out (:data:`_PIECE_RE`), in one pass over the column."""
    joined = "\n".join(column)
    if joined.count("\n") != len(column) - 1:
        return None
    return _PIECE_RE.sub("", joined).split("\n")


def _uniform_split(column: list[str]):
    """``(structure, slots)`` of a column whose every cell is its first cell's skeleton with
    other values (``slots``: each value's texts, a list a value, depth first), split by plain
    text replacement of the fixed texts and checked by writing the cells back; ``None``
    otherwise."""
    first = column[0] if column else ""
    if "(" not in first:  # plain stiffnesses (the reader refuses what is not one)
        joined = "".join(column)
        plain = "(" not in joined and "=" not in joined and all(column)
        return (("leaf",), [column]) if plain else None
    got = parse_cell(first)
    spans = [m.span() for m in _PIECE_RE.finditer(first)]
    if got is None or [first[a:b] for a, b in spans] != got[1] or not spans:
        return None
    ends = [0] + [x for span in spans for x in span] + [len(first)]
    fixed = [first[ends[i]:ends[i + 1]] for i in range(0, len(ends), 2)]
    n, k = len(column), len(spans)
    joined = "\n".join(column)
    if joined.count("\n") != n - 1 or any(not t for t in fixed[1:-1]) \
            or not joined.endswith(fixed[-1]):
        return None
    # the texts between rows (the last cell's end, a line break, the next cell's start) and
    # those inside a cell are line breaks: the values one a line (the first row's start is
    # the first cell's; the lines written back below check every cell)
    text = joined[len(fixed[0]):len(joined) - len(fixed[-1])]
    text = text.replace(fixed[-1] + "\n" + fixed[0], "\n")
    for t in fixed[1:-1]:
        text = text.replace(t, "\n")
    if any(map(text.__contains__, "(),=")) or text.count("\n") != n * k - 1:
        return None
    found = text.split("\n")
    parts: list = [None] * (n * (2 * k + 1))
    width = 2 * k + 1
    parts[0::width] = [fixed[0]] * n
    for j in range(k):
        parts[2 * j + 1::width] = found[j::k]
        parts[2 * j + 2::width] = [fixed[j + 1]] * n
    parts[width - 1::width] = [fixed[-1] + "\n"] * n
    if "".join(parts) != joined + "\n":
        return None
    return got[0], [found[j::k] for j in range(k)]


def tree_fast(spec, columns, cells: dict, rows, want_json: bool, cache: dict) -> list[FastBlock]:
    """The blocks of ``rows`` (indices into ``cells``: column key -> stripped cells) whose
    cells are networks this module takes (see the module docstring). Cells of one skeleton
    (values cut out) have one structure, read off the first (:func:`parse_cell`) and checked
    to cut its values where :data:`_PIECE_RE` does."""
    elements = [col for col in columns if _ELEMENT_RE.match(col.key)]
    shared = [col for col in columns if not _ELEMENT_RE.match(col.key)]
    rows = list(rows)
    if elements and all(cells[col.key][i] for col in elements for i in rows[:1]):
        split = [_uniform_split(_take(cells[col.key], rows)) for col in elements]
        if all(split):  # every row one structure: only the shared columns given may differ
            given = [_take(cells[col.key], rows) for col in shared]
            groups: dict[tuple, list[int]] = {}
            if shared and all(map(all, given)):  # (the common file: every value given)
                groups[(True,) * len(shared)] = list(range(len(rows)))
            else:
                present = [list(map(bool, column)) for column in given]
                for r, key in enumerate(zip(*present)):
                    groups.setdefault(key, []).append(r)
            blocks = []
            for key, members in groups.items():
                at = np.asarray(members, dtype=np.intp)
                slots = [got[1] if len(members) == len(rows) else
                         [[texts[i] for i in members] for texts in got[1]] for got in split]
                block = _block(spec, elements, [c for c, p in zip(shared, key) if p],
                               tuple(got[0] for got in split), np.asarray(rows)[at], cells,
                               want_json, cache, slots)
                if block is not None:
                    blocks.append(block)
            return blocks
    structures: dict[str, object] = {"": None, _LEAF: ("leaf",), _OTHER: False}
    keys = []
    for col in elements:
        column = _take(cells[col.key], rows)
        skeletons = _skeletons(column)
        if skeletons is None:
            return []
        skeletons = [k if "(" in c else "" if not c else _LEAF if
                     _NUMBER_START_RE.match(c) and "=" not in c else _OTHER
                     for c, k in zip(column, skeletons)]
        for cell, skeleton in zip(column, skeletons):
            if skeleton not in structures:
                got = parse_cell(cell)
                ok = got is not None and _PIECE_RE.findall(cell) == got[1]
                structures[skeleton] = got[0] if ok else False
        keys.append([structures[k] for k in skeletons])
    present = [list(map(bool, _take(cells[col.key], rows))) for col in shared]
    groups: dict[tuple, list[int]] = {}
    for r, key in enumerate(zip(*keys, *present)):
        groups.setdefault(key, []).append(rows[r])
    blocks = []
    n = len(elements)
    for key, members in groups.items():
        if any(s is False for s in key[:n]):
            continue
        block = _block(spec, elements, [c for c, p in zip(shared, key[n:]) if p], key[:n],
                       np.asarray(members, dtype=np.intp), cells, want_json, cache)
        if block is not None:
            blocks.append(block)
    return blocks


def _take(column: list[str], rows: list[int]) -> list[str]:
    """The cells of ``column`` at ``rows`` (increasing indices): the column itself where
    ``rows`` are all of it."""
    if len(rows) == len(column):
        return column
    return [column[i] for i in rows]


def _block(spec, elements, shared, key, rows, cells, want_json, cache, split=None):
    from ..commands.springs import ELEMENTS
    from ..physics.columns import Columns
    from ..physics.numerics_arrays import monomial_array
    from ..physics.springs import parallel_stiffness, series_stiffness
    from ..units import STIFFNESS, TORSIONAL_STIFFNESS
    from .fast_commands import _Param, _probe
    from .spring_forms import ELEMENT_FORMS

    given = [col for col, s in zip(elements, key) if s is not None]
    tops = [s for s in key if s is not None]
    if not tops:
        return None
    if any(col.unit and s[0] != "leaf" for col, s in zip(given, tops)):
        return None
    root = ("group", spec.how, tuple(tops))
    shared_names = tuple(col.key for col in shared)
    kinds, used = set(), set()

    def scan(node):
        if node[0] == "group":
            return all(scan(c) for c in node[2])
        if node[0] == "element":
            kinds.add(node[1] == "torsion-bar")
            got = _resolve(node[1], node[2], shared_names)
            if got is None:
                return False
            used.update(got[1])
        return True

    if not scan(root) or used != set(shared_names) or len(kinds) > 1:
        return None
    dim = TORSIONAL_STIFFNESS if kinds and kinds.pop() else STIFFNESS
    si_json = json.dumps(dim.si)
    m = len(rows)
    row_list = rows.tolist()
    good = np.ones(m, dtype=bool)
    inputs, results = [], {}
    shared_reads = {}
    for col in shared:
        pdim = next(k.params[col.key] for k in ELEMENTS.values() if col.key in k.params)
        column = _take(cells[col.key], row_list)
        plain = _plain_floats(column)
        read = _read_column(column, col.unit, _Param(col.key, pdim), spec.strict, cache, plain)
        good &= read.ok & np.isfinite(read.si) & (read.si > 0.0)
        # (plain numbers: their input texts need no check that each is a number literal)
        shared_reads[col.key] = (read, column, col.unit, plain is not None)
    count = [0]
    # the texts of each value, depth first over the element columns, a column at a time
    slots: list[list[str]] = []
    for index, (col, top) in enumerate(zip(given, tops)):
        if split is not None:  # (every element column given: no empty cell)
            slots += split[index]
            continue
        column = _take(cells[col.key], row_list)
        if top[0] == "leaf":
            slots.append(column)
            continue
        pieces = _PIECE_RE.findall("\n".join(column))
        k = len(pieces) // m
        if k * m != len(pieces):
            return None
        slots += [pieces[j::k] for j in range(k)]
    slot = [0]

    def values_at(j):
        return slots[j]

    def build(node, top_col=None):
        """(stiffness array, SI-typed first leaf mask) of a node, reading its values."""
        nonlocal good
        if node[0] == "group":
            parts, first_si = [], None
            for child in node[2]:
                k, si_first = build(child)
                parts.append(k)
                first_si = si_first if first_si is None else first_si
            good &= first_si
            kernel = (series_stiffness if node[1] == "series" else parallel_stiffness).columns
            with np.errstate(all="ignore"):
                out = kernel(np.column_stack([np.where(good, k, 1.0) for k in parts]))
            k = out.values["k_eq"]
            good &= out.exact & np.isfinite(k) & (k >= _TINY)
            return k, first_si
        count[0] += 1
        name = f"k{count[0]}"
        if node[0] == "leaf":
            typed = values_at(slot[0])
            slot[0] += 1
            unit = top_col.unit if top_col is not None else ""
            texts = list(map(str.strip, typed))
            plain = _plain_floats(texts) if top_col is not None else None
            read = _read_column(texts, unit, _Param(name, dim), spec.strict, cache, plain)
            good &= read.ok & np.isfinite(read.si) & (read.si > 0.0)
            units = read.unit_json
            if m and units.count(units[0]) == m:  # (one unit: a column of one value)
                units = [units[0]]
            if dim is TORSIONAL_STIFFNESS:  # a bare number is linear to the one-off
                good &= np.array([not a for _u, a in units], dtype=bool)
            si_first = np.array([u == si_json for u, _a in units], dtype=bool) \
                if m else np.ones(0, dtype=bool)
            if len(si_first) != m:
                si_first = np.full(m, si_first[0])
            if top_col is not None:
                inputs.append((name, read, texts, unit, plain is not None, None))
            else:
                inputs.append((name, read, typed, "", "as typed", None))
            return read.si, si_first
        kind, own = node[1], node[2]
        names, _used = _resolve(kind, own, shared_names)
        coefficient, lead, alternatives, required = ELEMENT_FORMS[kind]
        pdims = ELEMENTS[kind].params
        si = {}
        for pname in names:
            if pname in own:
                typed = values_at(slot[0])
                slot[0] += 1
                read = _read_column(list(map(str.strip, typed)), "",
                                    _Param(pname, pdims[pname]), spec.strict, cache)
                good &= read.ok & np.isfinite(read.si) & (read.si > 0.0)
                inputs.append((f"{name}.{pname}", read, typed, "", "as typed", None))
            else:
                read, column, unit, plain = shared_reads[pname]
                inputs.append((f"{name}.{pname}", read, column, unit, plain, None))
            si[pname] = np.where(good, read.si, 1.0)
        chosen = [g for g in alternatives if g[0][0] in names]
        factors = [(si[p], power) for p, power in (*lead, *(chosen[0] if chosen else ()))]
        factors += [(si[p], power) for p, power in required]
        k = monomial_array(coefficient, factors)
        good &= np.isfinite(k) & (k >= _TINY)
        results[name] = k
        return k, np.ones(m, dtype=bool)

    stiffness = []
    for col, top in zip(given, tops):
        stiffness.append(build(top, col if top[0] == "leaf" else None))
    build = None  # (a recursive closure is a reference cycle: the chunk's texts freed now)
    first_si = stiffness[0][1]
    good &= first_si
    kernel = (series_stiffness if spec.how == "series" else parallel_stiffness).columns
    with np.errstate(all="ignore"):
        out = kernel(np.column_stack([np.where(good, k, 1.0) for k, _s in stiffness]))
    k_eq = out.values["k_eq"]
    good &= out.exact & np.isfinite(k_eq) & (k_eq >= _TINY)
    if not good.any():
        return None
    model = "network" if any(t[0] == "group" for t in tops) else spec.how
    values = {"k_eq": k_eq, **results}
    first = int(np.argmax(good))
    columns_out = Columns(values, exact=good, model=model)
    kind_key = ("tree", key, shared_names,
                tuple(read.unit_json[first] for _n, read, *_r in inputs))
    probed = getattr(spec, "probed", {})
    if kind_key not in probed:
        probe_cells = {col.key: {int(rows[first]): cells[col.key][int(rows[first])]}
                       for col in (*given, *shared)}
        if _probe(spec, [*given, *shared], probe_cells, int(rows[first]), columns_out,
                  {name: array[first] for name, array in values.items()}) is None:
            return None
        probed[kind_key] = True
    keep = np.flatnonzero(good)
    head = texts_out = None
    if want_json:
        head = json_head(spec.command, None, model, "closed-form")
        texts_out = _input_texts(inputs, keep, {})
    return FastBlock(rows[keep], {name: array[keep] for name, array in values.items()},
                     {name: dim for name in values}, head, texts_out, "{}")
