"""Euler's equations on columns: ``rigid-body --batch`` rows of ``inertia_tensor``, ``omega``
and ``alpha`` (``dyncalc.commands.rigid_body``'s Euler mode), bit for bit the one-off.

.. math:: \\mathbf M = J\\boldsymbol\\alpha + \\boldsymbol\\omega\\times(J\\boldsymbol\\omega),
          \\quad \\mathbf H = J\\boldsymbol\\omega,\\quad T = \\tfrac12\\,\\boldsymbol\\omega
          \\cdot J\\boldsymbol\\omega

The twin of :func:`~dyncalc.physics.euler.euler_moment`: the products ``J v`` and ``w . H`` by
:func:`~dyncalc.physics.euler.matvec` and :func:`~dyncalc.physics.euler.dot` (the one-off's
own, correctly rounded, with their row twins), the cross product by the scaled, correctly rounded twin of
:mod:`dyncalc.physics.frames` (``_ScaledRows``) and ``|M|`` by
:func:`~dyncalc.physics.numerics_arrays.hypot_rows` (CPython's ``math.hypot``). The tensor
checks of :func:`~dyncalc.physics.euler.check_tensor` run on the stack (LAPACK's ``syevd`` on
each matrix, as for one); a row they refuse, or whose results overflow, is not exact (the
one-off gives its message).
"""
from __future__ import annotations

from ..lazy import numpy as np
from .columns import Columns
from .euler import TENSOR_RTOL, dot, matvec
from .frames import _ScaledRows
from .numerics_arrays import hypot_rows

__all__ = ["euler_columns", "tensor_rows_ok"]


def tensor_rows_ok(J):
    """Where each ``(3, 3)`` matrix of the stack ``J`` passes
    :func:`~dyncalc.physics.euler.check_tensor` (finite, symmetric, positive semi-definite,
    the triangle inequality of its principal moments, each within ``TENSOR_RTOL`` of its
    largest entry).

    >>> tensor_rows_ok(np.array([np.eye(3), np.diag([1.0, 1.0, 3.0])])).tolist()
    [True, False]
    """
    n = len(J)
    finite = np.isfinite(J).all(axis=(1, 2))
    J = np.where(finite[:, None, None], J, 0.0)
    scale = np.abs(J).max(axis=(1, 2))
    tol = TENSOR_RTOL * scale
    ok = finite.copy()
    for i in range(3):
        for j in range(i + 1, 3):
            ok &= ~(np.abs(J[:, i, j] - J[:, j, i]) > tol)
    moments = np.zeros((n, 3))
    some = scale > 0.0
    if some.any():
        with np.errstate(all="ignore"):
            sym = (J[some] + np.transpose(J[some], (0, 2, 1))) / 2.0
            moments[some] = np.linalg.eigvalsh(sym)
    ok &= ~(moments[:, 0] < -tol)
    ok &= ~(moments[:, 0] + moments[:, 1] < moments[:, 2] - tol)
    return ok


def euler_columns(J, omega, alpha) -> Columns:
    """``M``, ``M_mag``, ``H``, ``T`` of each row (``J``: ``(n, 3, 3)`` in kg*m^2; ``omega``,
    ``alpha``: ``(n, 3)`` in rad/s and rad/s^2), exact where the one-off gives them."""
    J = np.asarray(J, dtype=float)
    w, a = np.asarray(omega, dtype=float), np.asarray(alpha, dtype=float)
    ok = tensor_rows_ok(J) & np.isfinite(w).all(axis=1) & np.isfinite(a).all(axis=1)
    with np.errstate(all="ignore"):
        H, sure_h = matvec(J, w)
        gyro = _ScaledRows.of(w).cross(_ScaledRows.of(H)).value()
        Ja, sure_a = matvec(J, a)
        M = Ja + gyro + 0.0
        wH, sure_t = dot(w, H)
        T = wH / 2.0
        H = H + 0.0
        ok &= sure_h & sure_a & sure_t
        ok &= np.isfinite(M).all(axis=1) & np.isfinite(H).all(axis=1) & np.isfinite(T)
        size, fine = hypot_rows(M[:, 0], M[:, 1], M[:, 2])
    return Columns({"M": M, "M_mag": size, "H": H, "T": T}, exact=ok & fine,
                   model="euler")
