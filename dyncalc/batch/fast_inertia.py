"""The vectorised path of ``inertia --batch``: the rows whose bodies are all at the origin
along z (``disk(m=4kg, r=0.2m)``, and composites such as a disk and ``-disk(...)``, a hole:
mass or density and dimensions, plain numbers with plain units; no ``at=``, ``along=`` or
``axis`` but a world axis), grouped by bodies and the parameters they name, through
:func:`dyncalc.physics.inertia_columns.centred_composite`; placed and turned bodies and other
axes through :mod:`.fast_inertia_placed`. Each group's first
row is also computed by the one-off (a *probe*): the group takes the generic path unless its
results are the kernel's to the bit and its input entries the ones assembled here. Every
other row takes the generic path.
"""
from __future__ import annotations

import json
import re

import numpy as np

from .columns import _LITERAL_CELL, _read_column
from .fast import FastBlock, json_head
from .floats import json_floats
from .inertia_probe import _dim, _Param, _probed

__all__ = ["inertia_fast"]

#: A body word the vectorised path reads: a body at its place, parameters without
#: parentheses (no vector, no expression).
_WORD_RE = re.compile(r"^\s*(-?)\s*([a-z][a-z-]*)\s*\(([^()]*)\)\s*$")
_PAIR_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*=(.*)$", re.S)


def _shape(cell: str):
    """``(kind, keys, value texts, sign)`` of a body word the vectorised path takes (``-``
    before it: a hole, sign -1), or ``None``."""
    from ..physics.inertia_columns import CENTRED

    match = _WORD_RE.match(cell)
    if match is None or match.group(2) not in CENTRED:
        return None
    keys, texts = [], []
    for part in match.group(3).split(","):
        pair = _PAIR_RE.match(part)
        if pair is None:
            return None
        keys.append(pair.group(1))
        texts.append(pair.group(2))
    return match.group(2), tuple(keys), texts, -1.0 if match.group(1) else 1.0


def _allowed(kind: str, keys: tuple) -> bool:
    """Whether ``keys`` are exactly what the one-off reads without refusal: ``m`` or
    ``rho``, and each dimension of the body once."""
    from ..physics.inertia import BODY_DIMENSIONS, DENSITY_KIND

    masses = [k for k in keys if k in ("m", "rho")]
    if len(masses) != 1 or (masses[0] == "rho" and kind not in DENSITY_KIND):
        return False
    rest = sorted(k for k in keys if k not in ("m", "rho"))
    return rest == sorted(BODY_DIMENSIONS[kind]) and len(set(keys)) == len(keys)


#: A number after ``=``, ``(``, ``[``, ``,`` or a blank (a template whose every number starts
#: a value, after its ``=`` and blanks, is checked by :data:`_SLOT_RE`, or a component of
#: ``at=``, by :mod:`.fast_inertia_placed`; the one-off reads it as this literal).
_VALUE_RE = re.compile(rf"(?<=[=(\[, \t]){_LITERAL_CELL}")
_SLOT_RE = re.compile(r"^([ \t]*)#([^#]*)$")
#: A slot of a template, as a pattern: the literal :data:`_VALUE_RE` takes there.
_SLOT = f"({_LITERAL_CELL})"


def inertia_fast(spec, columns, table, want_json: bool, cache: dict) -> list[FastBlock]:
    """The rows of this chunk the vectorised path computes, as blocks (one per *template*:
    the body words of the row's non-empty body cells, with their numbers taken out: the same
    bodies, signs, parameters, units and spacing; the ``axis`` cell empty); every other row
    is left to the generic path. The numbers of a template's rows are read in one pass a
    body."""
    if not table:
        return []
    bodies = [col for col in columns if spec.is_body(col.key)]
    if not bodies or any(col.unit for col in bodies):
        return []
    axes = [list(table[col.index]) for col in columns if not spec.is_body(col.key)]
    body_cells = [list(table[col.index]) for col in bodies]
    n = len(body_cells[0])
    candidates = range(n)
    axis_cells = axes[0] if axes else [""] * n
    if not candidates or any("\n" in "".join(cells) for cells in body_cells):
        return []
    whole = len(candidates) == n
    if whole and axis_cells.count(axis_cells[0]) == n:  # one template a column: one pass
        parts = _one_template(bodies, body_cells, cache)
        if parts is not None:
            block = _block(spec, parts, np.arange(n, dtype=np.intp), body_cells, bodies,
                           axis_cells[0], want_json, cache)
            return [] if block is None else [block]
    templates = []
    for cells in body_cells:
        picked = cells if whole else [cells[i] for i in candidates]
        templates.append([t if t.strip() else "" for t in
                          _VALUE_RE.sub("#", "\n".join(picked)).split("\n")])
    keys = list(zip(*templates, axis_cells if whole else [axis_cells[i] for i in candidates]))
    groups: dict[tuple, list[int]] = {}
    if keys.count(keys[0]) == len(keys):
        groups[keys[0]] = list(candidates)
    else:
        for i, key in zip(candidates, keys):
            groups.setdefault(key, []).append(i)
    blocks = []
    for key, members in groups.items():
        key, axis = key[:-1], key[-1]
        used = [j for j, template in enumerate(key) if template]
        shapes = [_template(key[j], cache) for j in used]
        if not used or any(shape is None for shape in shapes):
            continue
        every = len(members) == n
        parts = []
        for j, shape in zip(used, shapes):
            group = body_cells[j] if every else [body_cells[j][i] for i in members]
            found = _VALUE_RE.findall("\n".join(group))
            k = len(shape[1])
            if len(found) != k * len(group):
                break
            parts.append((bodies[j], shape, [found[i::k] for i in range(k)]))
        else:
            block = _block(spec, parts, np.asarray(members, dtype=np.intp), body_cells,
                           bodies, axis, want_json, cache)
            if block is not None:
                blocks.append(block)
    return blocks


def _one_template(bodies, body_cells, cache: dict):
    """The ``parts`` of :func:`_block` when every cell of each body column has its first
    cell's template (or ``None``): each column is read in one pass by a pattern made of the
    template's fixed text with a literal in each slot, the numbers of each slot coming out as
    a column. The fixed text before a slot ends in ``=`` or a blank, which no literal holds,
    so a cell matching the pattern has the template :data:`_VALUE_RE` gives it.

    Where no literal can run into the fixed text (:func:`_clear`), the slots are first taken
    as runs of a literal's characters (:func:`_loose`, half the cost of the literal's own
    pattern) and read as JSON numbers: the same texts, read once."""
    parts = []
    for column, cells in zip(bodies, body_cells):
        first = cells[0]
        if "#" in first or not first.strip():
            return None
        template = _VALUE_RE.sub("#", first)
        shape = _template(template, cache)
        if shape is None:
            return None
        pieces = template.split("#")
        k, n = len(shape[1]) + 1, len(cells)
        joined = "\n".join(cells)
        literals = _loose(pieces, joined, n, k, cache)
        if literals is None:
            literals = _slots(pieces, _SLOT, joined, n, k, cache)
            if literals is None:
                return None
        parts.append((column, shape, literals))
    return parts


def _slots(pieces: list[str], slot: str, joined: str, n: int, k: int, cache: dict):
    """Each slot's texts (a list a slot) of ``joined`` (``n`` cells, ``k - 1`` slots), split
    by the pattern of ``pieces`` with ``slot`` in each slot (compiled once a run); ``None``
    where a cell is off it. The split gives the text between matches, then a match's slots,
    ...; every cell matched where the text between is only the line breaks."""
    key = ("inertia-pattern", slot, tuple(pieces))
    if key not in cache:
        cache[key] = re.compile("^" + slot.join(map(re.escape, pieces)) + "$", re.M)
    split = cache[key].split(joined)
    if len(split) != 1 + n * k or "".join(split[::k]) != "\n" * (n - 1):
        return None
    return [split[j::k] for j in range(1, k)]


#: A slot of a template no literal can run into: a run of a literal's characters (checked
#: after as one JSON number a cell).
_LOOSE_SLOT = "([0-9.eE+-]+)"
_LITERAL_CHARS = "0123456789.eE+-"


class _Literals(list):
    """A slot's literal texts (one a cell) and their values, already read (a float64 array)."""

    __slots__ = ("values",)


def _clear(pieces: list[str]) -> bool:
    """Whether no literal can run into the template's fixed text: no piece before a slot
    ends, and none after one starts, with a literal's character (and none holds a line
    break), so a slot's run of those characters is the one-off's whole literal."""
    return (not any("\n" in p for p in pieces)
            and not any(p and p[-1] in _LITERAL_CHARS for p in pieces[:-1])
            and not any(p and p[0] in _LITERAL_CHARS for p in pieces[1:]))


def _loose(pieces, joined: str, n: int, k: int, cache: dict):
    """The slots' literals (:class:`_Literals`, their values read) of ``joined`` (``n``
    cells, ``k - 1`` slots), split by :data:`_LOOSE_SLOT`; ``None`` where the template is
    not :func:`_clear`, a cell is off it, or a slot is not a JSON number (JSON's number
    grammar is part of the one-off's literal grammar, so each slot is then one literal, as
    the literal's own pattern would split it; the rest, ``+5``, ``.5``, ``007``, take that
    pattern)."""
    if not _clear(pieces):
        return None
    split = _slots(pieces, _LOOSE_SLOT, joined, n, k, cache)
    if split is None:
        return None
    out = []
    for column in split:
        texts = _Literals(column)
        texts.values = json_floats(",".join(texts), n, texts)
        if texts.values is None:
            return None
        out.append(texts)
    return out


def _template(template: str, cache: dict):
    """``(kind, keys, (space, unit text) of each value)`` of a template the vectorised path
    takes (each value one number and a unit), or ``None``."""
    key = ("inertia-template", template)
    if key not in cache:
        shape = _shape(template)
        slots = [] if shape is not None and _allowed(*shape[:2]) else None
        for text in shape[2] if slots is not None else ():
            slot = _SLOT_RE.match(text)
            if slot is None:
                slots = None
                break
            slots.append((slot.group(1), slot.group(2)))
        cache[key] = None if slots is None else (shape[0], shape[1], slots, shape[3])
        if cache[key] is None:  # a placed or turned body (.fast_inertia_placed)
            from .fast_inertia_placed import placed_template

            cache[key] = placed_template(template)
    return cache[key]


def _block(spec, parts, rows, body_cells, bodies, axis: str, want_json, cache):
    """One template's rows: ``parts`` holds each body's column, template shape and number
    literals (a list a parameter), in the order of the row's bodies (``b1``, ``b2``, ...);
    ``axis`` the rows' axis cell (a world axis, perhaps signed, or empty)."""
    from ..physics.inertia import mass_from_density
    from ..physics.inertia_columns import centred_composite

    if any(len(shape) > 4 for _c, shape, _l in parts) or not _world_axis(axis):
        from .fast_inertia_placed import placed_block

        return placed_block(spec, parts, rows, body_cells, bodies, axis, want_json, cache)
    n = len(rows)
    good = np.ones(n, dtype=bool)
    reads, placed = [], []
    for index, (_column, (kind, keys, slots, sign), literals) in enumerate(parts, start=1):
        si = {}
        for j, key in enumerate(keys):
            column = literals[j]
            read = _read_column(column, slots[j][1].strip(), _Param(key, _dim(kind, key)),
                                spec.strict, cache, getattr(column, "values", None))
            good &= read.ok
            reads.append((f"b{index}.{key}", read, column, slots[j]))
            si[key] = read.si
        placed.append((kind, sign, si))
    bodies_si = []
    with np.errstate(all="ignore"):
        for kind, sign, si in placed:
            si = {key: np.where(good, value, 1.0) for key, value in si.items()}
            dims = {key: value for key, value in si.items() if key not in ("m", "rho")}
            if kind == "hollow-cylinder":
                good &= dims["ri"] < dims["ro"]
            m = si["m"] if "m" in si else mass_from_density(kind, si["rho"], dims)
            good &= np.isfinite(m)
            bodies_si.append((kind, sign, m, dims))
        bodies_si = [(kind, sign, np.where(good, m, 1.0), dims)
                     for kind, sign, m, dims in bodies_si]
        out = centred_composite(bodies_si)
    if out is None:
        return None
    good &= out.exact
    if axis.strip():
        _about_world_axis(out, axis)
        good &= out.values["J_axis"] > 0.0   # a zero moment: the one-off's signed zero
    if not good.any():
        return None
    keep = np.flatnonzero(good)
    first = int(keep[0])
    # a template probed once (its first chunk's first row) is not probed again: the probe
    # gives what every row of it shares (method, dimensions, the axis entry)
    key = ("inertia-probed", axis, want_json, out.model,
           tuple((column.key, kind, keys, tuple(slots), sign)
                 for column, (kind, keys, slots, sign), _l in parts))
    if key not in cache:
        found = _probed(spec, parts, rows, body_cells, bodies, axis, want_json, out, first,
                        lambda i: _entries(reads, np.array([i]), 1)[0])
        if found is None:
            return None
        cache[key] = found
    method, result_dims, tail = cache[key]
    values = {name: array[keep] for name, array in out.values.items()}
    head = inputs = None
    if want_json:
        head = json_head("inertia", None, out.model, method)
        inputs = _entries(reads, keep, None) + ([tail] if tail else [])
    return FastBlock(rows[keep], values, result_dims, head, inputs)


def _world_axis(axis: str) -> bool:
    """Whether the axis cell is empty or a world axis through the origin (``x``, ``-y``)."""
    return axis.strip().lstrip("+-").strip() in ("", "x", "y", "z")


def _about_world_axis(out, axis: str) -> None:
    """Add ``J_axis`` and ``radius_of_gyration`` about a world axis through the origin (the
    centre of mass of a centred composite): the one-off's ``n^T (J_C + 0) n`` with ``n`` a
    signed unit axis is the diagonal element exactly (every other product is a zero)."""
    k = "xyz".index(axis.strip().lstrip("+-").strip())
    J = np.ascontiguousarray(out.values["J_C"][:, k, k])
    with np.errstate(all="ignore"):
        out.values["J_axis"] = J
        out.values["radius_of_gyration"] = np.sqrt(J / out.values["m"])


def _entries(reads, keep: np.ndarray, lines: int | None):
    """The parts of the JSON input entries ``bI.KEY`` of the kept rows (the value in the unit
    typed, that unit, the text as typed: the number between the template's spacing and unit
    text); with ``lines``, those lines' texts instead."""
    from . import assemble

    parts: list = []
    every = len(keep) == len(reads[0][1].shown) if reads else True
    rows = keep.tolist()
    for key, read, column, (space, rest) in reads:
        prefix = (", " if parts else "") + json.dumps(key) + ': {"value": '
        shown = np.asarray(read.shown, dtype=np.float64)
        typed = column if every else [column[i] for i in rows]
        unit, assumed = read.unit_json[rows[0]]  # one unit: the template's
        parts += [prefix, shown if every else shown[keep],
                  f', "unit": {unit}, "text": ' + json.dumps(space)[:-1], typed,
                  json.dumps(rest)[1:] + assumed + "}"]
    if lines is not None:
        return assemble.lines(parts, lines)
    return parts
