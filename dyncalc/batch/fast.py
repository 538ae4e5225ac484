"""The vectorised path: whole chunks of closed-form ``natural-frequency`` rows with numpy."""
from __future__ import annotations

import json
from typing import Any

import numpy as np

from ..errors import InputError
from ..physics.numerics import sqrt_ratio_array
from ..physics.outcome import damped_arrays, periodic_arrays
from .columns import _plain_floats, _read_column
from .header import Column, with_header_unit

#: The natural-frequency scenes the vectorised path computes: scene -> (the two parameters of
#: omega = sqrt(a / b), the parameters the row must not give (they need another model)).
FAST_SCENES = {
    "mass-spring": (("k", "m"), ()),
    "torsional": (("kt", "J"), ()),
    "pendulum": (("g", "l"), ("amplitude",)),
}


class FastBlock:
    """Rows of a chunk computed together: their positions in the chunk, the result arrays (SI,
    in the order the one-off gives them) and kinds, and for JSON the constant part of each
    line (``head``) and each row's ``inputs`` object text."""

    __slots__ = ("rows", "values", "kinds", "head", "inputs")

    def __init__(self, rows, values, kinds, head, inputs):
        self.rows, self.values, self.kinds, self.head, self.inputs = (
            rows, values, kinds, head, inputs)


def _default_input(p, strict: bool, cache: dict):
    """(SI value, JSON text of the input entry) of a scene parameter's default."""
    key = ("default", p.name, p.default, strict)
    if key not in cache:
        from ..units import parse_quantity

        parsed = parse_quantity(p.default, p.dim, label=p.name, strict=strict,
                                constraint=p.constraint)
        shown = float(parsed.quantity.magnitude) if parsed.unit_text else parsed.si
        text = json.dumps({p.name: {"value": shown, "unit": parsed.unit_text or p.dim.si,
                                    "text": p.default}})
        cache[key] = (parsed.si, text[1:-1])
    return cache[key]


def _natural_frequency_fast(spec, columns: list[Column], table, want_json: bool,
                            cache: dict) -> list[FastBlock]:
    """The rows of this chunk the vectorised path computes, as blocks (one per scene and set
    of parameters given); every other row is left to the generic path. ``spec`` is the run's
    :class:`~dyncalc.batch.rows.NaturalFrequencyRows` (which names this function its ``fast``
    path); ``table`` holds the chunk's cells column by column."""
    from ..scenes import get_scene
    from ..result.kinds import result_kind

    if spec.method not in (None, "auto") or not table or len(columns) > 62:
        return []
    n = len(table[0])
    present: dict[str, np.ndarray] = {}
    cells: dict[str, Any] = {}
    plain: dict[str, np.ndarray | None] = {}
    for col in columns:
        column = table[col.index]
        values = _plain_floats(column)
        plain[col.key] = values
        if values is not None:
            present[col.key] = np.ones(n, dtype=bool)
            cells[col.key] = column
            continue
        column = [c.strip() for c in column]
        cells[col.key] = column
        present[col.key] = np.fromiter((c != "" for c in column), dtype=bool, count=n)
    keys = [col.key for col in columns]
    units = {col.key: col.unit for col in columns}
    signature = np.zeros(n, dtype=np.int64)
    for bit, key in enumerate(keys):
        signature |= present[key].astype(np.int64) << bit
    blocks = []
    # the distinct signatures, in order (np.unique would import numpy.ma: 6 ms)
    for sig in sorted(set(signature.tolist())):
        given = [key for bit, key in enumerate(keys) if (sig >> bit) & 1]
        if not given:
            continue
        try:
            scene_name = spec.scene_for(given)
        except InputError:
            continue
        if scene_name not in FAST_SCENES:
            continue
        (a_name, b_name), excluded = FAST_SCENES[scene_name]
        scene = get_scene(scene_name)
        names = {p.name for p in scene.params}
        if any(k not in names or k in excluded for k in given):
            continue
        params = [p for p in scene.params if p.name not in excluded
                  and (p.name in given or p.default is not None)]
        if any(p.default is None and not p.optional and p.name not in given
               for p in scene.params if p.name not in excluded):
            continue
        rows = np.arange(n) if sig == int(signature[0]) and (signature == sig).all() \
            else np.flatnonzero(signature == sig)
        whole = len(rows) == n
        good = np.ones(len(rows), dtype=bool)
        si: dict[str, Any] = {}
        inputs = []
        for p in params:
            if p.name in given:
                column = cells[p.name] if whole else [cells[p.name][i] for i in rows]
                read = _read_column(column, units[p.name], p, spec.strict, cache,
                                    plain[p.name] if whole else None)
                good &= read.ok
                si[p.name] = read.si
                inputs.append((p.name, read, column, units[p.name],
                               whole and plain[p.name] is not None))
            else:
                value, text = _default_input(p, spec.strict, cache)
                si[p.name] = np.full(len(rows), value)
                inputs.append((p.name, text, None, None, False))
        if not good.any():
            continue
        with np.errstate(all="ignore"):
            omega = sqrt_ratio_array(np.where(good, si[a_name], 1.0),
                                     np.where(good, si[b_name], 1.0))
            values = periodic_arrays(omega)
            if "zeta" in si:
                good &= si["zeta"] < 1.0   # at or above critical: a warning, generic path
                values.update(damped_arrays(omega, np.where(good, si["zeta"], 0.0)))
            for array in values.values():  # zero or beyond float64: warnings, generic path
                good &= np.isfinite(array) & (array != 0.0)
        if not good.any():
            continue
        keep = np.flatnonzero(good)
        if len(keep) != len(rows):
            rows = rows[keep]
            values = {name: array[keep] for name, array in values.items()}
        kinds = {name: result_kind(name) for name in values}
        head = texts = None
        if want_json:
            head = (f'"schema": "dyncalc/2", "command": "natural-frequency", '
                    f'"scene": {json.dumps(scene_name)}, "model": "linear", '
                    '"method": "closed-form"')
            parts = []
            for name, read, column, header_unit, plain_column in inputs:
                if isinstance(read, str):
                    parts.append([read] * len(keep))
                    continue
                every = len(keep) == len(read.shown)
                shown = read.shown if every else read.shown[keep]
                unit_json = read.unit_json if every else [read.unit_json[i]
                                                          for i in keep.tolist()]
                typed = column if every else [column[i] for i in keep.tolist()]
                if plain_column:  # plain numbers: the text is the cell and the header's unit
                    suffix = json.dumps(" " + header_unit)[1:-1] if header_unit else ""
                    typed = ['"' + c.strip() + suffix + '"' for c in typed]
                else:
                    typed = [json.dumps(with_header_unit(c.strip(), header_unit))
                             for c in typed]
                prefix = json.dumps(name) + ': {"value": '
                if unit_json and unit_json.count(unit_json[0]) == len(unit_json):
                    unit, assumed = (u.replace("%", "%%") for u in unit_json[0])
                    template = (prefix.replace("%", "%%") + '%r, "unit": ' + unit
                                + ', "text": %s' + assumed + "}")
                    parts.append(list(map(template.__mod__, zip(shown.tolist(), typed))))
                else:
                    parts.append([f'{prefix}{v!r}, "unit": {u}, "text": {t}{a}}}'
                                  for v, (u, a), t in zip(shown.tolist(), unit_json, typed)])
            texts = list(map(", ".join, zip(*parts)))
        blocks.append(FastBlock(rows, values, kinds, head, texts))
    return blocks
