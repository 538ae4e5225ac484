"""``modes --batch`` rows the stacked kernel leaves (:mod:`dyncalc.batch.fast_modes`): the
one-off's physics (:func:`dyncalc.physics.modes.solve_modes`) a row at a time on the SI
matrices already read, so bit for bit the one-off, without its parsing, units and Result.

These are the rows whose damping is barely there (a ``zeta`` below 1e-3 without proportional
damping: ``Re s`` carries the rounding of ``|s|``, so only the one-off's own ``ggev`` gives its
digits), leaves coordinates uncoupled (the one-off solves such groups apart), or otherwise
falls outside the stack's margins (repeated frequencies, a near-singular M, a rigid-body
mode). Rows are grouped by their model, notes and results: each group is a block with those
notes as its warnings (at most :data:`MAX_GROUPS` groups a chunk, the largest; the others,
and the rows the one-off refuses, take the generic path with their messages).

Example::

    >>> import numpy as np
    >>> M, K = np.eye(2)[None], np.array([[[2.0, -1.0], [-1.0, 2.0]]])
    >>> C = np.array([[[1e-4, 0.0], [0.0, 0.0]]])
    >>> [out.model for out in rowwise_modes(M, K, C)]
    ['non-proportional damping']
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

__all__ = ["rowwise_modes", "MAX_GROUPS"]

#: The most groups (model, notes, results) of a chunk's rows made blocks.
MAX_GROUPS = 8


def rowwise_modes(M, K, C=None, normalize: str = "max") -> list:
    """One :class:`~dyncalc.physics.columns.Columns` a group of rows (the one-off's values of
    its rows, ``exact`` marking them), the largest groups first."""
    from ..physics.columns import Columns
    from ..physics.modes import solve_modes

    rows, n = M.shape[0], M.shape[1]
    found: dict[tuple, list] = {}
    finite = np.isfinite(M).all(axis=(1, 2)) & np.isfinite(K).all(axis=(1, 2))
    if C is not None:
        finite &= np.isfinite(C).all(axis=(1, 2))
    for i in np.flatnonzero(finite).tolist():  # (a number beyond float64: the one-off's)
        try:
            with np.errstate(all="ignore"):
                out = solve_modes(M[i], K[i], None if C is None else C[i],
                                  normalize=normalize)
        except (InputError, ArithmeticError, ValueError, np.linalg.LinAlgError):
            continue  # refused: the generic path gives the message
        if C is None:
            model, method, damped = "linear", "eigh", ()
        elif out.proportional:
            model, method = "proportional damping", "eigh"
        else:
            model, method = "non-proportional damping", "eigh+state-space"
        if C is not None:
            damped = tuple(not math.isnan(z) for z in out.zeta) + tuple(
                not math.isnan(w) for w in out.omega_d)
        found.setdefault((model, method, tuple(out.notes), damped), []).append((i, out))
    groups = sorted(found.items(), key=lambda item: -len(item[1]))[:MAX_GROUPS]
    return [_columns(Columns, key, members, rows, n) for key, members in groups]


def _columns(Columns, key, members, rows: int, n: int):
    """The Columns of one group: its rows' values at their places, the others zero."""
    model, method, notes, damped = key
    exact = np.zeros(rows, dtype=bool)
    exact[[i for i, _out in members]] = True
    values: dict[str, np.ndarray] = {}

    def put(name: str, get, shape=()):
        array = np.zeros((rows, *shape))
        for i, out in members:
            array[i] = get(out)
        values[name] = array
    for j in range(n):
        put(f"omega_{j + 1}", lambda out, j=j: out.omega[j])
    for j in range(n):
        put(f"f_{j + 1}", lambda out, j=j: float(out.omega[j]) / (2.0 * math.pi))
    for j in range(n):
        put(f"mode_{j + 1}", lambda out, j=j: out.shapes[:, j], (n,))
        put(f"modal_mass_{j + 1}", lambda out, j=j: out.modal_mass[j])
        put(f"modal_stiffness_{j + 1}", lambda out, j=j: out.modal_stiffness[j])
    for j in range(n if damped else 0):
        if damped[j]:
            put(f"zeta_{j + 1}", lambda out, j=j: out.zeta[j])
    for j in range(n if damped else 0):
        if damped[n + j]:
            put(f"omega_d_{j + 1}", lambda out, j=j: out.omega_d[j])
    return Columns(values, exact, model=model, method=method, warnings=notes,
                   warned=exact.copy() if notes else None)
