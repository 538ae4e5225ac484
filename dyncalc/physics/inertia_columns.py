"""Column kernel of ``inertia`` for one body at the origin, its own axes the world's
(``along=z``, no ``at=``): whole columns of masses and dimensions at once, bit for bit
:func:`dyncalc.commands.inertia.compute` on each row.

.. math:: J_C = J_O = \\operatorname{diag}(J_{xx}, J_{yy}, J_{zz}), \\qquad r_c = 0,

the principal moments ``J_1 <= J_2 <= J_3`` and axes from :func:`numpy.linalg.eigh` on the
stack (one LAPACK call per matrix, as the one-off's), the axes chosen by the rule of
:func:`~dyncalc.physics.inertia_tensor.principal`: a world axis, and where moments are equal
(to ``DEGENERATE`` of the trace) the world axes of that plane in the order x, y, z. A row is
exact where every value is finite and the eigenvectors ``eigh`` gives are signed world axes
(where they are not, the rule's Gram-Schmidt could round otherwise: the generic path answers).

Parameters: ``kind`` (a body name), ``m`` (kg, array), ``dims`` (m, arrays by name).

Example::

    >>> out = single_body("disk", np.array([4.0]), {"r": np.array([0.2])})
    >>> out.values["J_3"].tolist(), out.values["axis_1"].tolist()
    ([0.08000000000000002], [[1.0, 0.0, 0.0]])

Reference: Gross et al., Engineering Mechanics 3, Table 3.1.
"""
from __future__ import annotations

from ..lazy import numpy as np
from .columns import Columns
from .inertia import principal_local
from .inertia_tensor import DEGENERATE

__all__ = ["single_body", "centred_composite"]

#: The bodies whose reference point is their centre of mass (a half-cylinder shell's is not).
CENTRED = ("point", "rod", "disk", "ring", "solid-sphere", "hollow-sphere", "solid-cylinder",
           "hollow-cylinder", "plate")


def single_body(kind: str, m, dims: dict) -> Columns | None:
    """The results of ``inertia "KIND(m=..., ...)"`` for every row (see the module);
    ``None`` for a body whose centre is not its reference point."""
    return centred_composite([(kind, 1.0, m, dims)])


def centred_composite(bodies: list) -> Columns | None:
    """The results of ``inertia`` for a composite of bodies at the origin along z (no
    ``at=``, no ``along=``; a body ``(kind, sign, m, dims)``, ``sign`` -1 for a hole):

    .. math:: m = \\sum_i s_i m_i, \\qquad J_O = J_C = \\sum_i s_i
              \\operatorname{diag}(J_{xx}, J_{yy}, J_{zz})_i, \\qquad r_c = 0,

    every centre at the origin, so the one-off's parallel-axis terms and rotations are exact
    zeros and identities and its sums (Python's ``sum``, left to right from 0) are these
    sums of the diagonals, bit for bit. Rows the one-off refuses (a total mass not positive,
    a tensor no body has) are not exact. ``None`` for a body whose centre is not its
    reference point."""
    if any(kind not in CENTRED for kind, _s, _m, _d in bodies):
        return None
    n = len(bodies[0][2])
    m = np.zeros(n)
    summed = np.zeros((n, 3))
    scale = np.zeros(n)
    finite = np.ones(n, dtype=bool)
    for kind, sign, mass, dims in bodies:
        local = principal_local(kind, mass, dims)
        diagonal = np.zeros((n, 3))
        for k in range(3):
            diagonal[:, k] = local[k]
        # the one-off: I diag I^T, (J + J^T)/2, + m (0 I - 0): each element d -> (d+d)/2
        own = sign * ((diagonal + diagonal) / 2.0)
        finite &= np.isfinite(mass) & np.isfinite(own).all(axis=1)
        m = m + sign * mass
        summed = summed + own
        scale = scale + np.abs((own[:, 0] + own[:, 1]) + own[:, 2])  # |trace J_O,i|
    J = np.zeros((n, 3, 3))
    idx = np.arange(3)
    J[:, idx, idx] = (summed + summed) / 2.0     # the composite's (J_O + J_O^T)/2
    exact = finite & np.isfinite(m) & (m > 0.0) & np.isfinite(J).all(axis=(1, 2))
    J[~exact] = np.eye(3)  # rows left to the generic path: any matrix eigh takes
    scale = 1e-9 * scale
    if len(bodies) > 1:  # the one-off's checks of a composite (a hole cutting too much)
        checked = np.linalg.eigvalsh(J)
        exact &= ~(checked[:, 0] < -scale) & ~(checked[:, 0] + checked[:, 1]
                                               < checked[:, 2] - scale)
    moments, vectors = np.linalg.eigh(J)
    # eigenvectors that are signed world axes: each column one +-1 and two zeros
    unit = (np.abs(vectors) == 1.0) | (vectors == 0.0)
    exact &= unit.all(axis=(1, 2)) & ((np.abs(vectors) == 1.0).sum(axis=1) == 1).all(axis=1)
    world = np.argmax(np.abs(vectors), axis=1)  # (n, 3): the world axis of moment k
    tol = DEGENERATE * np.maximum(np.abs(moments).sum(axis=1), np.finfo(float).tiny)
    # the one-off's check of a composite (never fails for one body; kept for the bit)
    exact &= ~(moments[:, 0] + moments[:, 1] < moments[:, 2] - scale)
    g02 = moments[:, 2] - moments[:, 0] <= tol
    g01 = moments[:, 1] - moments[:, 0] <= tol
    g12 = ~g01 & (moments[:, 2] - moments[:, 1] <= tol)
    order = world.copy()
    sort01 = (g01 & ~g02)
    order[sort01, :2] = np.sort(world[sort01, :2], axis=1)
    order[g12, 1:] = np.sort(world[g12, 1:], axis=1)
    order[g02] = np.sort(world[g02], axis=1)
    axes = np.zeros((n, 3, 3))
    rows = np.arange(n)
    for k in range(3):
        axes[rows, k, order[:, k]] = 1.0
    J = J + 0.0
    moments = np.maximum(moments, 0.0)
    values = {"m": m + 0.0, "r_c": np.zeros((n, 3)), "J_O": J, "J_C": J.copy()}
    for k in range(3):
        values[f"J_{k + 1}"] = np.ascontiguousarray(moments[:, k])
    for k in range(3):
        values[f"axis_{k + 1}"] = np.ascontiguousarray(axes[:, k, :])
    return Columns(values, exact, model=bodies[0][0] if len(bodies) == 1 else "composite")
