"""The vectorised path of ``inertia --batch``: the rows whose only cell is one body at the
origin along z (``disk(m=4kg, r=0.2m)``: mass or density and dimensions, plain numbers with
plain units; no ``at=``, ``along=``, hole or ``axis``), grouped by body and the parameters
they name, through :func:`dyncalc.physics.inertia_columns.single_body`. Each group's first
row is also computed by the one-off (a *probe*): the group takes the generic path unless its
results are the kernel's to the bit and its input entries the ones assembled here. Every
other row takes the generic path.
"""
from __future__ import annotations

import json
import re

import numpy as np

from ..errors import InputError
from .columns import _LITERAL_CELL, _read_column
from .fast import FastBlock

__all__ = ["inertia_fast"]

#: A body word the vectorised path reads: a body at its place, parameters without
#: parentheses (no vector, no expression).
_WORD_RE = re.compile(r"^\s*([a-z][a-z-]*)\s*\(([^()]*)\)\s*$")
_PAIR_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*=(.*)$", re.S)


class _Param:
    """What :func:`~dyncalc.batch.columns._read_column` needs: a dimension and a positive
    value (the body reader's constraint on every mass, density and length)."""

    __slots__ = ("name", "dim", "constraint")

    def __init__(self, name: str, dim):
        self.name, self.dim, self.constraint = name, dim, "positive"


def _shape(cell: str):
    """``(kind, keys, value texts)`` of a body word the vectorised path takes, or ``None``."""
    from ..physics.inertia_columns import CENTRED

    match = _WORD_RE.match(cell)
    if match is None or match.group(1) not in CENTRED:
        return None
    keys, texts = [], []
    for part in match.group(2).split(","):
        pair = _PAIR_RE.match(part)
        if pair is None:
            return None
        keys.append(pair.group(1))
        texts.append(pair.group(2))
    return match.group(1), tuple(keys), texts


def _allowed(kind: str, keys: tuple) -> bool:
    """Whether ``keys`` are exactly what the one-off reads without refusal: ``m`` or
    ``rho``, and each dimension of the body once."""
    from ..physics.inertia import BODY_DIMENSIONS, DENSITY_KIND

    masses = [k for k in keys if k in ("m", "rho")]
    if len(masses) != 1 or (masses[0] == "rho" and kind not in DENSITY_KIND):
        return False
    rest = sorted(k for k in keys if k not in ("m", "rho"))
    return rest == sorted(BODY_DIMENSIONS[kind]) and len(set(keys)) == len(keys)


#: A number after ``=`` or a blank (a template whose every number starts a value, after its
#: ``=`` and blanks, is checked by :data:`_SLOT_RE`; the one-off reads it as this literal).
_VALUE_RE = re.compile(rf"(?<=[= \t]){_LITERAL_CELL}")
_SLOT_RE = re.compile(r"^([ \t]*)#([^#]*)$")


def inertia_fast(spec, columns, table, want_json: bool, cache: dict) -> list[FastBlock]:
    """The rows of this chunk the vectorised path computes, as blocks (one per *template*:
    a body word in the first body column, every other cell of the row empty, with its
    numbers taken out: the same body, parameters, units and spacing);
    every other row is left to the generic path. The numbers of a template's rows are read
    in one pass over their cells joined."""
    if not table:
        return []
    bodies = [col for col in columns if spec.is_body(col.key)]
    if not bodies or any(col.unit for col in bodies):
        return []
    body = bodies[0]  # the rows whose every other cell (b2, ..., axis) is empty
    cells = list(table[body.index])
    others = [table[col.index] for col in columns if col is not body]
    candidates = range(len(cells))
    if any("".join(column).strip() for column in others):  # rows with an axis or 2nd body
        candidates = [i for i in candidates if not any(c[i].strip() for c in others)]
    if "\n" in "".join(cells):
        return []
    picked = cells if len(candidates) == len(cells) else [cells[i] for i in candidates]
    templates = _VALUE_RE.sub("#", "\n".join(picked)).split("\n")
    groups: dict[str, list[int]] = {}
    if templates.count(templates[0]) == len(templates):
        groups[templates[0]] = list(candidates)
    else:
        for i, template in zip(candidates, templates):
            groups.setdefault(template, []).append(i)
    blocks = []
    for template, members in groups.items():
        shape = _template(template, cache)
        if shape is None:
            continue
        kind, keys, slots = shape
        group = cells if len(members) == len(cells) else [cells[i] for i in members]
        found = _VALUE_RE.findall("\n".join(group))
        if len(found) != len(keys) * len(group):
            continue
        literals = found
        rows = np.asarray(members, dtype=np.intp)
        block = _block(spec, body, kind, keys, slots, rows, literals, cells, want_json, cache)
        if block is not None:
            blocks.append(block)
    return blocks


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
        cache[key] = None if slots is None else (shape[0], shape[1], slots)
    return cache[key]


def _dim(kind: str, key: str):
    from ..commands.inertia_read import DENSITY
    from ..physics.inertia import DENSITY_KIND
    from ..units import LENGTH, MASS

    if key == "m":
        return MASS
    return DENSITY[DENSITY_KIND[kind]] if key == "rho" else LENGTH


def _block(spec, body, kind, keys, slots, rows, literals, cells, want_json, cache):
    from ..physics.inertia import mass_from_density
    from ..physics.inertia_columns import single_body

    n = len(rows)
    k = len(keys)
    good = np.ones(n, dtype=bool)
    reads = []
    for j, key in enumerate(keys):
        column = literals[j::k]
        unit = slots[j][1].strip()
        read = _read_column(column, unit, _Param(key, _dim(kind, key)), spec.strict, cache)
        good &= read.ok
        reads.append((key, read, column, slots[j]))
    si = {key: np.where(good, read.si, 1.0) for key, read, _c, _s in reads}
    dims = {key: value for key, value in si.items() if key not in ("m", "rho")}
    if kind == "hollow-cylinder":
        good &= dims["ri"] < dims["ro"]
    with np.errstate(all="ignore"):
        m = si["m"] if "m" in si else mass_from_density(kind, si["rho"], dims)
        good &= np.isfinite(m)
        out = single_body(kind, np.where(good, m, 1.0), dims)
    if out is None:
        return None
    good &= out.exact
    if not good.any():
        return None
    keep = np.flatnonzero(good)
    first = int(keep[0])
    probe = _probe(spec, body, cells[int(rows[first])], out, first)
    if probe is None or (want_json and _entries(reads, np.array([first]), 1)[0]
                         != _probe_inputs(probe)):
        return None
    values = {name: array[keep] for name, array in out.values.items()}
    result_dims = {name: entry.dim for name, entry in probe.results.items()}
    head = inputs = None
    if want_json:
        head = (f'"schema": "dyncalc/2", "command": "inertia", "scene": null, '
                f'"model": {json.dumps(out.model)}, "method": {json.dumps(probe.method)}')
        inputs = _entries(reads, keep, None)
    return FastBlock(rows[keep], values, result_dims, head, inputs)


def _probe(spec, body, cell: str, out, i: int):
    """The one-off Result of one row, or ``None`` where it is not the kernel's to the bit."""
    from .fast_commands import _same

    try:
        result = spec.compute({body.key: cell}, {body.key: body.name})
    except InputError:
        return None
    if (result.warnings or result.model != out.model or set(result.extra)
            or list(result.results) != list(out.values)):
        return None
    for name, entry in result.results.items():
        if entry.uncertainty is not None or not _same(entry.si, out.values[name][i]):
            return None
    return result


def _probe_inputs(result) -> str:
    from ..result.encode import _json_inputs

    return json.dumps(_json_inputs(result.inputs))[1:-1]


def _entries(reads, keep: np.ndarray, lines: int | None):
    """The parts of the JSON input entries ``b1.KEY`` of the kept rows (the value in the unit
    typed, that unit, the text as typed: the number between the template's spacing and unit
    text); with ``lines``, those lines' texts instead."""
    from . import assemble

    parts: list = []
    every = len(keep) == len(reads[0][1].shown) if reads else True
    rows = keep.tolist()
    for key, read, column, (space, rest) in reads:
        prefix = (", " if parts else "") + json.dumps("b1." + key) + ': {"value": '
        shown = np.asarray(read.shown, dtype=np.float64)
        typed = column if every else [column[i] for i in rows]
        unit, assumed = read.unit_json[rows[0]]  # one unit: the template's
        parts += [prefix, shown if every else shown[keep],
                  f', "unit": {unit}, "text": ' + json.dumps(space)[:-1], typed,
                  json.dumps(rest)[1:] + assumed + "}"]
    if lines is not None:
        return assemble.lines(parts, lines)
    return parts
