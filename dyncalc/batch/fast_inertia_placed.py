"""The vectorised path of ``inertia --batch`` for placed and turned bodies: body words with
``at=(x, y, z) UNIT`` (a column of positions, read a component at a time), ``along=`` a world
axis word (``x``, ``-y``: the same turn on every row of a template), half-cylinder shells,
and the axis cell any ``--axis`` (a world axis or a vector, perhaps ``through`` a point: the
same text on every row of a block), through
:func:`dyncalc.physics.inertia_placed_columns.placed_composite`. The templates and their
reading are :mod:`.fast_inertia`'s; this module gives the shape of a placed template and
computes its block, probed against the one-off like every block there.
"""
from __future__ import annotations

import json
import re

import numpy as np

from .fast import FastBlock, json_head

__all__ = ["placed_template", "placed_block"]

_WORD_RE = re.compile(r"^\s*(-?)\s*([a-z][a-z-]*)\s*\((.*)\)\s*$", re.S)
_PAIR_RE = re.compile(r"^\s*([A-Za-z][A-Za-z0-9_]*)\s*=(.*)$", re.S)
_TOP_COMMA = re.compile(r",(?![^()\[\]]*[)\]])")
_SLOT_RE = re.compile(r"^([ \t]*)#([^#]*)$")
#: ``at=`` as a template: three slots in parentheses or brackets, then one unit
_AT_RE = re.compile(r"^([ \t]*[(\[][ \t]*)#([ \t]*,[ \t]*)#([ \t]*,[ \t]*)#([ \t]*[)\]][ \t]*)"
                    r"([^#()\[\],]*)$")


def placed_template(template: str):
    """``(kind, slot keys, slots, sign, placement)`` of a template with ``at=``/``along=``
    (or a half-cylinder shell) the placed kernel takes, or ``None``: ``slots`` the ``(space,
    unit text)`` of each slot (an ``at`` component: ``("", unit)``), ``placement`` the body's
    frame and the JSON input entries in the order typed (``("slot", i)``, ``("at", first
    slot, text pieces)`` or ``("text", constant JSON)``)."""
    from ..physics.inertia import BODY_DIMENSIONS, DENSITY_KIND

    match = _WORD_RE.match(template)
    if match is None or match.group(2) not in BODY_DIMENSIONS:
        return None
    kind, sign = match.group(2), -1.0 if match.group(1) else 1.0
    keys, slots, entries, seen = [], [], [], []
    frame = np.eye(3)
    for part in _TOP_COMMA.split(match.group(3)):
        pair = _PAIR_RE.match(part)
        if pair is None:
            return None
        key, text = pair.group(1), pair.group(2)
        seen.append(key)
        if key == "at":
            at = _AT_RE.match(text)
            if at is None:
                return None
            entries.append(("at", len(keys), [at.group(i) for i in (1, 2, 3, 4)] + [at.group(5)]))
            for axis in "xyz":
                keys.append(f"at.{axis}")
                slots.append(("", at.group(5).strip()))
        elif key == "along":
            along = _along(text, len(seen))
            if along is None:
                return None
            frame, entry = along
            entries.append(("text", entry, key))
        else:
            slot = _SLOT_RE.match(text)
            if slot is None:
                return None
            entries.append(("slot", len(keys)))
            keys.append(key)
            slots.append((slot.group(1), slot.group(2)))
    masses = [k for k in seen if k in ("m", "rho")]
    rest = sorted(k for k in seen if k not in ("m", "rho", "at", "along"))
    if (len(masses) != 1 or (masses[0] == "rho" and kind not in DENSITY_KIND)
            or rest != sorted(BODY_DIMENSIONS[kind]) or len(set(seen)) != len(seen)):
        return None
    return kind, tuple(keys), slots, sign, (frame, entries)


def _along(text: str, index: int):
    """The frame of ``along=WORD`` (a signed world axis) and its JSON entry text (the name
    is filled in later), or ``None``."""
    from ..commands.inertia_read import _direction
    from ..physics.inertia_placed_columns import is_signed_permutation
    from ..physics.inertia_tensor import body_frame

    word = text.strip()
    if "#" in word or word.lstrip("+-").strip() not in ("x", "y", "z"):
        return None
    vector, along_word = _direction(text, "along", False)
    if along_word is None:
        return None
    frame = body_frame(vector)
    if not is_signed_permutation(frame):
        return None
    value = ", ".join(repr(float(v)) for v in np.asarray(vector, dtype=float) + 0.0)
    entry = f'{{"value": [{value}], "unit": "", "text": {json.dumps(along_word)}}}'
    return frame, entry


def placed_block(spec, parts, rows, body_cells, bodies, axis: str, want_json, cache):
    """One placed template's rows (``parts`` as :func:`.fast_inertia._block` takes them, the
    shapes :func:`placed_template`'s or the centred ones)."""
    from ..batch.columns import _read_column
    from ..commands.inertia_read import read_axis
    from ..errors import InputError
    from ..physics.inertia import mass_from_density
    from ..physics.inertia_placed_columns import placed_composite
    from .inertia_probe import _dim, _Param, _probed

    about = None
    if axis.strip():
        try:
            read = read_axis(axis.strip(), spec.strict)
        except InputError:  # the one-off's message, row by row
            return None
        about = (read.direction, read.point)
    n = len(rows)
    good = np.ones(n, dtype=bool)
    reads, placed = [], []
    for index, (_column, shape, literals) in enumerate(parts, start=1):
        kind, keys, slots, sign = shape[:4]
        frame, entries = shape[4] if len(shape) > 4 else (np.eye(3), None)
        if entries is None:
            entries = [("slot", j) for j in range(len(keys))]
        si, body_reads = {}, []
        for j, key in enumerate(keys):
            param = _Param(key, _dim(kind, "r" if key.startswith("at.") else key))
            if key.startswith("at."):
                param.constraint = None
            read = _read_column(literals[j], slots[j][1].strip(), param, spec.strict, cache)
            good &= read.ok
            body_reads.append((read, literals[j]))
            si[key] = read.si
        reads.append((index, keys, slots, entries, body_reads))
        placed.append((kind, sign, si, frame))
    bodies_si = []
    with np.errstate(all="ignore"):
        for kind, sign, si, frame in placed:
            si = {key: np.where(good, value, 1.0) for key, value in si.items()}
            dims = {k: v for k, v in si.items() if k not in ("m", "rho") and "." not in k}
            if kind == "hollow-cylinder":
                good &= dims["ri"] < dims["ro"]
            m = si["m"] if "m" in si else mass_from_density(kind, si["rho"], dims)
            good &= np.isfinite(m)
            at = (np.column_stack([si["at.x"], si["at.y"], si["at.z"]]) if "at.x" in si
                  else None)
            bodies_si.append([kind, sign, m, dims, at, frame])
        for body in bodies_si:
            body[2] = np.where(good, body[2], 1.0)
        out = placed_composite([tuple(b) for b in bodies_si], about)
    good &= out.exact
    if not good.any():
        return None
    keep = np.flatnonzero(good)
    first = int(keep[0])
    from . import assemble

    found = _probed(spec, parts, rows, body_cells, bodies, axis, want_json, out, first,
                    lambda i: assemble.lines(_entries(reads, np.array([i])), 1)[0])
    if found is None:
        return None
    method, result_dims, tail = found
    values = {name: array[keep] for name, array in out.values.items()}
    head = inputs = None
    if want_json:
        head = json_head("inertia", None, out.model, method)
        inputs = _entries(reads, keep) + ([tail] if tail else [])
    return FastBlock(rows[keep], values, result_dims, head, inputs)


def _entries(reads, keep: np.ndarray) -> list:
    """The parts of the JSON input entries of the kept rows, in the order typed: ``bI.KEY``
    (the value in the unit typed, that unit, the text), ``bI.at`` (three values, one unit,
    the text with the numbers as typed), ``bI.along`` (the same on every row)."""
    parts: list = []
    rows = keep.tolist()
    every = bool(reads) and len(keep) == len(reads[0][4][0][0].shown)

    def pick(read, column):
        shown = np.asarray(read.shown, dtype=np.float64)
        return (shown if every else shown[keep]), (column if every else
                                                   [column[i] for i in rows])

    for index, keys, slots, entries, body_reads in reads:
        for entry in entries:
            sep = ", " if parts else ""
            if entry[0] == "text":
                parts.append(f'{sep}"b{index}.{entry[2]}": {entry[1]}')
                continue
            j = entry[1]
            read, column = body_reads[j]
            unit, assumed = read.unit_json[rows[0]]
            if entry[0] == "slot":
                space, rest = slots[j]
                shown, typed = pick(read, column)
                parts += [f'{sep}"b{index}.{keys[j]}": {{"value": ', shown,
                          f', "unit": {unit}, "text": ' + json.dumps(space)[:-1], typed,
                          json.dumps(rest)[1:] + assumed + "}"]
                continue
            pieces = entry[2]
            values, typed = zip(*(pick(*body_reads[j + c]) for c in range(3)))
            parts += [f'{sep}"b{index}.at": {{"value": [', values[0], ", ", values[1], ", ",
                      values[2], f'], "unit": {unit}, "text": ' + json.dumps(pieces[0])[:-1],
                      typed[0], json.dumps(pieces[1])[1:-1], typed[1],
                      json.dumps(pieces[2])[1:-1], typed[2],
                      json.dumps(pieces[3] + pieces[4])[1:] + assumed + "}"]
    return parts
