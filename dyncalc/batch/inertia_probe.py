"""What both vectorised paths of ``inertia --batch`` (:mod:`.fast_inertia`,
:mod:`.fast_inertia_placed`) share: the parameter record the column reader takes, the
dimension of a body parameter, and the probe (a block's first row computed by the one-off)."""
from __future__ import annotations

import json

from ..errors import InputError

__all__ = ["_Param", "_dim", "_probe", "_probe_inputs"]


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
