"""What both vectorised paths of ``inertia --batch`` (:mod:`.fast_inertia`,
:mod:`.fast_inertia_placed`) share: the parameter record the column reader takes, the
dimension of a body parameter, and the probe (a block's first row computed by the one-off)."""
from __future__ import annotations

import json

from ..errors import InputError

__all__ = ["_Param", "_dim", "_probe", "_probe_inputs", "_probed"]


class _Param:
    """What :func:`~dyncalc.batch.columns._read_column` needs: a dimension and a positive
    value (the body reader's constraint on every mass, density and length)."""

    __slots__ = ("name", "dim", "constraint")

    def __init__(self, name: str, dim):
        self.name, self.dim, self.constraint = name, dim, "positive"


def _dim(kind: str, key: str):
    from ..commands.inertia_read import DENSITY
    from ..physics.inertia import DENSITY_KIND
    from ..units import LENGTH, MASS

    if key == "m":
        return MASS
    return DENSITY[DENSITY_KIND[kind]] if key == "rho" else LENGTH


def _probe(spec, texts: dict, labels: dict, out, i: int):
    """The one-off Result of one row, or ``None`` where it is not the kernel's to the bit."""
    from .fast_commands import _same

    try:
        result = spec.compute(texts, labels)
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


def _probed(spec, parts, rows, body_cells, bodies, axis, want_json, out, first, inputs_of):
    """``(method, result dimensions, JSON axis entry)`` of a block from the one-off's result
    of its row ``first`` (:func:`~.inertia_probe._probe`), or ``None`` where that result is
    not the kernel's to the bit or its input entries not those the path assembles
    (``inputs_of(i)``: the JSON text of row ``i``'s input entries, as the path writes them)."""
    row = int(rows[first])
    texts = {column.key: body_cells[bodies.index(column)][row] for column, _s, _l in parts}
    labels = {column.key: column.name for column, _s, _l in parts}
    if axis.strip():
        texts["axis"], labels["axis"] = axis.strip(), "axis"
    probe = _probe(spec, texts, labels, out, first)
    if probe is None:
        return None
    tail = ""
    if want_json:  # the axis entry, the same on every row: the probe's
        mine, theirs = inputs_of(first), _probe_inputs(probe)
        tail = theirs[len(mine):]
        if not theirs.startswith(mine) or (tail and not tail.startswith(', "axis": ')):
            return None
    return probe.method, {name: e.dim for name, e in probe.results.items()}, tail
