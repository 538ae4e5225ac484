"""Columns of 3x3 matrix cells on the vectorised path (``rigid-body``'s ``inertia_tensor``):
``"a, b, c; d, e, f; g, h, i"``, nine plain numbers, rows by ``;``, in the parameter's SI
unit (no unit in the cell or the header: the one-off reads a bare matrix so, and says it
assumed it). Any other cell (a unit, brackets, a file, ``-0``) is left to the generic path.
"""
from __future__ import annotations

import json
import re

import numpy as np

from .columns import _LITERAL_CELL

__all__ = ["read_matrices", "Matrices"]

_ROW = rf"[ \t]*({_LITERAL_CELL})[ \t]*,[ \t]*({_LITERAL_CELL})[ \t]*,[ \t]*({_LITERAL_CELL})[ \t]*"
_MATRIX_RE = re.compile(f"{_ROW};{_ROW};{_ROW}")


def read_matrices(column: list[str], unit: str, dim, strict: bool):
    """``(ok, SI values (n, 3, 3), Matrices, None, "matrix")`` of a column of 3x3 cells, or
    ``None`` where the generic path reads it (a unit in the header, ``--strict``, which
    refuses a bare matrix)."""
    if unit or strict:
        return None
    n = len(column)
    typed = np.zeros((n, 9))
    ok = np.zeros(n, dtype=bool)
    for i, cell in enumerate(column):
        m = _MATRIX_RE.fullmatch(cell)
        if m is not None:
            typed[i] = [float(x) for x in m.groups()]
            ok[i] = True
    ok &= np.isfinite(typed).all(axis=1) & ~(np.signbit(typed) & (typed == 0.0)).any(axis=1)
    si = typed.reshape(n, 3, 3)
    return ok, si, Matrices(si + 0.0, column, dim.si), None, "matrix"


class Matrices:
    """A column of matrices as JSON input entries: the SI values, the cell as typed, the SI
    unit assumed (what the one-off's entry of a bare matrix holds)."""

    def __init__(self, shown, column, unit: str):
        self.shown, self.column, self.unit = shown, column, unit

    def parts(self, name: str, keep) -> list:
        """The parts (:func:`dyncalc.batch.assemble.lines`) of the kept rows' entries."""
        rows = keep.tolist()
        shown = np.asarray(self.shown, dtype=np.float64)[keep]
        texts = [json.dumps(self.column[i]) for i in rows]
        parts: list = [f"{json.dumps(name)}: {{\"value\": [["]
        for r in range(3):
            for c in range(3):
                parts.append(np.ascontiguousarray(shown[:, r, c]))
                parts.append(", " if c < 2 else ("], [" if r < 2 else "]]"))
        parts += [f', "unit": {json.dumps(self.unit)}, "text": ', texts, ', "assumed_si": true}']
        return parts
