"""Euler's equations for a rigid body: the moment that gives an angular acceleration.

.. math:: \\mathbf M = J\\boldsymbol\\alpha + \\boldsymbol\\omega \\times (J\\boldsymbol\\omega)

in the body's axes, with ``J`` the inertia tensor about the centre of mass (or a fixed point)
in those axes. The cross product is the exact scaled kernel of :mod:`dyncalc.physics.frames`
(no overflow midway). Also the angular momentum ``H = J omega`` and the kinetic energy of
rotation ``T = omega . J omega / 2``.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Section 3.3 (Euler's equations).
"""
from __future__ import annotations

import math

from ..errors import InputError, PhysicsError
from ..lazy import numpy as np
from .frames import _Scaled, magnitude as vector_magnitude

__all__ = ["check_tensor", "euler_moment", "dot", "matvec"]

#: Relative tolerance (of the largest entry) of the symmetry, definiteness and triangle checks:
#: a tensor printed by ``inertia --value`` to 17 digits passes, a typing slip does not.
TENSOR_RTOL = 1e-9


def check_tensor(J, label: str = "--inertia-tensor") -> None:
    """Refuse a 3x3 array that is no inertia tensor: not symmetric, not positive
    semi-definite, or principal moments that break the triangle inequality
    ``J_1 + J_2 >= J_3`` (no mass distribution has them). Messages name the entry or the
    moments, in kg*m^2.

    >>> check_tensor([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 3.0]])
    Traceback (most recent call last):
    ...
    dyncalc.errors.InputError: --inertia-tensor violates the triangle inequality of principal moments: J_1 + J_2 = 2 < J_3 = 3 kg*m^2 (no rigid body has such moments)
    """
    J = np.asarray(J, dtype=float)
    if J.shape != (3, 3):
        raise InputError(f"{label} must be a 3x3 matrix (rows by ';'); got {J.shape[0]}x"
                         f"{J.shape[1] if J.ndim > 1 else 1}")
    if not np.all(np.isfinite(J)):
        raise InputError(f"{label}: every entry must be finite")
    scale = float(np.max(np.abs(J)))
    tol = TENSOR_RTOL * scale
    for i in range(3):
        for j in range(i + 1, 3):
            if abs(J[i, j] - J[j, i]) > tol:
                raise InputError(f"{label} is not symmetric: row {i + 1}, column {j + 1} is "
                                 f"{J[i, j]:.6g} but row {j + 1}, column {i + 1} is "
                                 f"{J[j, i]:.6g} kg*m^2")
    with np.errstate(all="ignore"):
        moments = np.linalg.eigvalsh((J + J.T) / 2.0) if scale > 0.0 else np.zeros(3)
    if moments[0] < -tol:
        raise InputError(f"{label} is not positive semi-definite: its principal moments are "
                         f"{', '.join(f'{v:.6g}' for v in moments)} kg*m^2 (one is negative)")
    if moments[0] + moments[1] < moments[2] - tol:
        raise InputError(f"{label} violates the triangle inequality of principal moments: "
                         f"J_1 + J_2 = {moments[0] + moments[1]:.6g} < J_3 = "
                         f"{moments[2]:.6g} kg*m^2 (no rigid body has such moments)")


def dot(u, v):
    """``u . v`` over the last axis (one vector, or rows of them), correctly rounded: the
    three products split exactly (Dekker's :func:`~dyncalc.physics.numerics.two_product`) and
    summed by ``math.fsum`` (on rows, their twins :func:`two_product_array` and
    :func:`fsum_rows`, bit for bit); where a part is not finite or the sum overflows, the
    float sum ``(u_0 v_0 + u_1 v_1) + u_2 v_2``. Neither depends on the BLAS numpy links, whose
    ``@`` sums in its own order. On rows, ``(values, ok)``: ``ok`` False where the twin may
    differ from the one-off.

    >>> float(dot(np.array([1.0, 2.0, 3.0]), np.array([4.0, 5.0, 6.0])))
    32.0
    """
    u, v = np.asarray(u, dtype=float), np.asarray(v, dtype=float)
    plain = (u[..., 0] * v[..., 0] + u[..., 1] * v[..., 1]) + u[..., 2] * v[..., 2]
    if u.ndim == 1:
        from .numerics import two_product

        terms = [x for a, b in zip(u.tolist(), v.tolist()) for x in two_product(a, b)]
        if not all(math.isfinite(x) for x in terms):
            return plain
        try:
            return np.float64(math.fsum(terms))
        except OverflowError:
            return plain
    from .numerics_arrays import fsum_rows, two_product_array

    parts = [x for j in range(3) for x in two_product_array(u[..., j], v[..., j])]
    terms = np.stack(parts, axis=-1)
    finite = np.isfinite(terms).all(axis=-1)
    sums, ok = fsum_rows(np.where(finite[:, None], terms, 0.0))
    # (a row whose fsum overflows: the one-off's plain sum; its results overflow, refused)
    return np.where(finite, sums, plain), ok | ~finite


def matvec(J, v):
    """``J v`` for one 3x3 ``J``, each component :func:`dot` of a row; on a stack of them
    (``(n, 3, 3)`` and ``(n, 3)``), ``(values (n, 3), ok)``.

    >>> matvec(np.eye(3) * 2.0, np.array([1.0, 2.0, 3.0])).tolist()
    [2.0, 4.0, 6.0]
    """
    J = np.asarray(J, dtype=float)
    if J.ndim == 2:
        return np.array([dot(J[i], v) for i in range(3)])
    rows = [dot(J[:, i, :], v) for i in range(3)]
    return np.stack([r[0] for r in rows], axis=-1), rows[0][1] & rows[1][1] & rows[2][1]


def euler_moment(J, omega, alpha) -> dict:
    """The moment, angular momentum and kinetic energy of a rigid body turning at ``omega``
    with angular acceleration ``alpha``.

    .. math:: \\mathbf M = J\\boldsymbol\\alpha + \\boldsymbol\\omega\\times(J\\boldsymbol\\omega),
              \\quad \\mathbf H = J\\boldsymbol\\omega,\\quad T = \\tfrac12\\,\\boldsymbol\\omega
              \\cdot J\\boldsymbol\\omega

    Parameters
    ----------
    J : array (3, 3)
        Inertia tensor in the body's axes, SI ``[mass]*[length]^2`` (checked by
        :func:`check_tensor`).
    omega : array (3,)
        Angular velocity, SI ``[angle]/[time]``.
    alpha : array (3,)
        Angular acceleration, SI ``[angle]/[time]^2``.

    Returns
    -------
    dict with ``M`` (N*m, vector), ``M_mag`` (N*m), ``H`` (kg*m^2/s, vector) and ``T`` (J).

    Examples
    --------
    A symmetric top (J = diag(1, 1, 2)) spinning about z at 3 rad/s and precessing about x at
    2 rad/s needs only the gyroscopic moment ``omega x (J omega)``:

    >>> out = euler_moment([[1, 0, 0], [0, 1, 0], [0, 0, 2]], [2, 0, 3], [0, 0, 0])
    >>> out["M"].tolist(), out["T"]
    ([0.0, -6.0, 0.0], 11.0)
    """
    J = np.asarray(J, dtype=float)
    w, a = np.asarray(omega, dtype=float), np.asarray(alpha, dtype=float)
    with np.errstate(all="ignore"):
        H = matvec(J, w)
        gyro = _Scaled.of(w).cross(_Scaled.of(H)).value()
        M = matvec(J, a) + gyro + 0.0
        T = float(dot(w, H)) / 2.0
    values = {"M": M, "H": H + 0.0, "T": T}
    for name, value in values.items():
        if not np.all(np.isfinite(value)):
            raise PhysicsError(f"{name} overflows float64 at these inputs")
    values["M_mag"] = vector_magnitude(M)
    return {"M": M, "M_mag": values["M_mag"], "H": values["H"], "T": T}
