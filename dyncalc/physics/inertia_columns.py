"""Column kernel of ``inertia`` for one body at the origin, its own axes the world's
(``along=z``, no ``at=``): whole columns of masses and dimensions at once, bit for bit
:func:`dyncalc.commands.inertia.compute` on each row.

.. math:: J_C = J_O = \\operatorname{diag}(J_{xx}, J_{yy}, J_{zz}), \\qquad r_c = 0,

the principal moments ``J_1 <= J_2 <= J_3`` and axes the sorted diagonal (what the one-off's
:func:`numpy.linalg.eigh` gives a diagonal tensor, bit for bit, :func:`_diagonal_eigh`; the
stack's ``eigh`` for rows LAPACK would scale), the axes chosen by the rule of
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
    moments, world, checked, axes_ok = _diagonal_eigh(J)
    exact &= axes_ok
    if len(bodies) > 1:  # the one-off's checks of a composite (a hole cutting too much)
        exact &= ~(checked[:, 0] < -scale) & ~(checked[:, 0] + checked[:, 1]
                                               < checked[:, 2] - scale)
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


#: The range of the largest element of a matrix that LAPACK's ``dsyevd`` does not scale
#: (``sqrt(safmin/eps)`` to its inverse, about 1e-146 to 1e146), within a margin.
_UNSCALED = (1e-140, 1e140)


def _diagonal_eigh(J):
    """``eigh`` of a stack of diagonal matrices: the moments (ascending), the world axis of
    each (``(n, 3)`` indices), ``eigvalsh``'s values and whether the eigenvectors are signed
    world axes (else the row is not exact), without LAPACK where its answer is known.

    For a diagonal matrix ``dsyevd`` reduces to the tridiagonal form with no reflection
    (every Householder ``tau`` is zero), every off-diagonal is zero so each eigenvalue is a
    diagonal element untouched, and the eigenvectors are the world axes, sorted with the
    values: ``eigh``'s and ``eigvalsh``'s values are the sorted diagonal, bit for bit, where
    the matrix is not scaled (its largest element within :data:`_UNSCALED`). Among equal
    moments the order of the axes may differ from LAPACK's selection sort, but the rule of
    :func:`~dyncalc.physics.inertia_tensor.principal` sorts the axes of equal moments (see
    :func:`centred_composite`). Rows outside the range (or not finite) go through ``eigh``."""
    d = np.ascontiguousarray(np.diagonal(J, axis1=1, axis2=2))
    world = np.argsort(d, axis=1, kind="stable")
    moments = np.take_along_axis(d, world, axis=1)
    size = np.abs(d).max(axis=1)
    other = np.flatnonzero(~((size >= _UNSCALED[0]) & (size <= _UNSCALED[1])))
    checked, axes_ok = moments.copy(), np.ones(len(d), dtype=bool)
    if len(other):
        values, vectors = np.linalg.eigh(J[other])
        checked[other] = np.linalg.eigvalsh(J[other])
        moments[other] = values
        world[other] = np.argmax(np.abs(vectors), axis=1)
        # eigenvectors that are signed world axes: each column one +-1 and two zeros
        unit = (np.abs(vectors) == 1.0) | (vectors == 0.0)
        axes_ok[other] = unit.all(axis=(1, 2)) & (
            (np.abs(vectors) == 1.0).sum(axis=1) == 1).all(axis=1)
    return moments, world, checked, axes_ok
