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
from .columns import _read_column
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


def inertia_fast(spec, columns, table, want_json: bool, cache: dict) -> list[FastBlock]:
    """The rows of this chunk the vectorised path computes, as blocks (one per body and
    parameters named); every other row is left to the generic path."""
    if not table:
        return []
    bodies = [col for col in columns if spec.is_body(col.key)]
    if len(bodies) != 1 or bodies[0].unit:
        return []
    body = bodies[0]
    others = [table[col.index] for col in columns if col is not body]
    cells = table[body.index]
    groups: dict[tuple, list[int]] = {}
    texts: list = [None] * len(cells)
    for i, cell in enumerate(cells):
        if any(column[i].strip() for column in others):
            continue
        shape = _shape(cell)
        if shape is None:
            continue
        texts[i] = shape[2]
        groups.setdefault(shape[:2], []).append(i)
    blocks = []
    for (kind, keys), members in groups.items():
        if not _allowed(kind, keys):
            continue
        rows = np.asarray(members, dtype=np.intp)
        block = _block(spec, body, kind, keys, rows, [texts[i] for i in members], cells,
                       want_json, cache)
        if block is not None:
            blocks.append(block)
    return blocks


def _dim(kind: str, key: str):
    from ..commands.inertia_read import DENSITY
    from ..physics.inertia import DENSITY_KIND
    from ..units import LENGTH, MASS

    if key == "m":
        return MASS
    return DENSITY[DENSITY_KIND[kind]] if key == "rho" else LENGTH


def _block(spec, body, kind, keys, rows, texts, cells, want_json, cache):
    from ..physics.inertia import mass_from_density
    from ..physics.inertia_columns import single_body

    n = len(rows)
    good = np.ones(n, dtype=bool)
    reads = []
    for j, key in enumerate(keys):
        column = [t[j] for t in texts]
        read = _read_column(column, "", _Param(key, _dim(kind, key)), spec.strict, cache)
        good &= read.ok
        reads.append((key, read, column))
    si = {key: np.where(good, read.si, 1.0) for key, read, _c in reads}
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
    typed, that unit, the text as typed); with ``lines``, those lines' texts instead."""
    from . import assemble

    parts: list = []
    rows = keep.tolist()
    for key, read, column in reads:
        prefix = (", " if parts else "") + json.dumps("b1." + key) + ': {"value": '
        shown = np.asarray(read.shown, dtype=np.float64)[keep]
        ends = [f', "unit": {read.unit_json[i][0]}, "text": {json.dumps(column[i])}'
                f'{read.unit_json[i][1]}}}' for i in rows]
        parts += [prefix, shown, ends]
    if lines is not None:
        return assemble.lines(parts, lines)
    return parts
