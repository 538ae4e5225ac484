"""Column kernel of ``modes``: many undamped systems of the same size at once, numpy only.

.. math:: M = L L^T, \\quad A = L^{-1} K L^{-T}, \\quad A w_i = \\omega_i^2 w_i, \\quad
          \\phi_i = L^{-T} w_i,

the generalized symmetric eigenproblem ``K phi = omega^2 M phi`` reduced by the Cholesky
factor of M (the reduction LAPACK's ``sygvd`` makes, which the one-off calls through
``scipy.linalg.eigh``), on a stack of matrices: ``numpy.linalg.cholesky``, ``solve`` and
``eigh`` each loop over the stack in C. The rounding differs from ``sygvd``'s, so the values
agree with the one-off to a few units in the last place, not to the bit (a mode shape's
largest component is exactly 1 in both). Shapes are normalised, modal masses and stiffnesses
formed as in :func:`dyncalc.physics.modes.solve_modes`.

A row is exact (left to the vectorised path) where both matrices are finite and symmetric
(to ``SYMMETRY_RTOL``), M is positive definite and K positive definite with a margin (no
rigid-body mode, no refusal: those are the one-off's to say), and the frequencies are apart
(repeated frequencies have no unique shapes: the one-off's choice is its own).

Parameters: ``M`` (kg, (rows, n, n)), ``K`` (N/m, (rows, n, n)), ``normalize`` ("max" or
"mass").

Example::

    >>> out = stacked_modes(np.eye(2)[None], np.array([[[2.0, -1.0], [-1.0, 2.0]]]))
    >>> out.values["omega_2"].round(12).tolist(), out.values["mode_2"].tolist()
    ([1.732050807569], [[1.0, -1.0]])

Reference: Gross et al., Engineering Mechanics 3, Chapter 4 (E4.14 to E4.19).
"""
from __future__ import annotations

import math

from ..lazy import numpy as np
from .columns import Columns
from .modes import (_COMPONENT_FLOOR, NON_PROPORTIONAL_NOTE, PROPORTIONAL_RTOL,
                    SYMMETRY_RTOL, ZERO_RTOL)

__all__ = ["stacked_modes", "modulus", "MARGIN", "APART", "DAMPING_SPREAD", "UNDERDAMPED",
           "COMPLEX_ZETA"]


def modulus(z):
    """``|z|`` of complex ``z`` (any shape) as ``b sqrt(1 + (a/b)^2)``, ``b`` the larger and
    ``a`` the smaller of ``|Re z|`` and ``|Im z|``: within two ulp, never overflowing where
    ``|z|`` is finite, and the same bits on every machine and at every place in an array
    (``numpy.abs`` of a complex array has SIMD paths that round differently from its scalar
    path, so the same value could come out one ulp apart in two runs of different lengths).

    >>> modulus(np.array([3 + 4j, -1e300j, 0j])).tolist()
    [5.0, 1e+300, 0.0]
    """
    a, b = np.abs(z.real), np.abs(z.imag)
    big, small = np.maximum(a, b), np.minimum(a, b)
    with np.errstate(invalid="ignore", divide="ignore"):
        q = np.where(big > 0.0, small / big, 0.0)
    return big * np.sqrt(1.0 + q * q)

#: Smallest eigenvalue of M and of ``K phi = lambda M phi``, as a share of the largest, below
#: which a row goes to the one-off (its thresholds are 1e-10: a margin of 100).
MARGIN = 1e-8
#: Neighbouring frequencies squared closer than this share of the larger go to the one-off.
APART = 1e-6
#: The margin kept from the one-off's test of proportional damping (either way: rows near it
#: go to the one-off).
MARGIN_P = 100.0
#: A mode's modal damping below this share of the largest goes to the one-off.
DAMPING_SPREAD = 1e-4
#: ``(1 - zeta)(1 + zeta)`` at or below this goes to the one-off (near critical: its note).
UNDERDAMPED = 1e-6
#: Damping that is not proportional: a mode's zeta below this goes to the one-off.
COMPLEX_ZETA = 1e-3


def stacked_modes(M, K, normalize: str = "max", C=None, damping: str = "proportional"
                  ) -> Columns:
    """The one-off's results of every row (see the module); ``exact`` marks the rows the
    vectorised path takes. With ``C`` (N s/m, (rows, n, n)) also ``zeta_i`` and
    ``omega_d_i``: of proportional damping (:func:`_damping`), or with ``damping="complex"``
    of damping that is not, from the state-space eigenvalues (:func:`_complex_damping`)."""
    rows, n, _ = M.shape
    with np.errstate(all="ignore"):
        exact = np.isfinite(M).all(axis=(1, 2)) & np.isfinite(K).all(axis=(1, 2))
        if C is not None:
            exact &= np.isfinite(C).all(axis=(1, 2))
        for A in (M, K) if C is None else (M, K, C):
            scale = np.abs(A).max(axis=(1, 2))
            exact &= np.abs(A - A.transpose(0, 2, 1)).max(axis=(1, 2)) <= SYMMETRY_RTOL * scale
        eye = np.broadcast_to(np.eye(n), M.shape)
        M = np.where(exact[:, None, None], (M + M.transpose(0, 2, 1)) / 2.0, eye)
        K = np.where(exact[:, None, None], (K + K.transpose(0, 2, 1)) / 2.0, eye)
        mass_eigs = np.linalg.eigvalsh(M)
        exact &= mass_eigs[:, 0] > MARGIN * np.abs(mass_eigs[:, -1])
        M = np.where(exact[:, None, None], M, eye)
        L = np.linalg.cholesky(M)
        X = np.linalg.solve(L, K)
        A = np.linalg.solve(L, X.transpose(0, 2, 1))
        A = (A + A.transpose(0, 2, 1)) / 2.0
        lam, W = np.linalg.eigh(A)
        V = np.linalg.solve(L.transpose(0, 2, 1), W)
        top = np.maximum(np.abs(lam[:, -1]), np.abs(lam[:, 0]))
        exact &= lam[:, 0] > MARGIN * top
        if n > 1:
            exact &= ((lam[:, 1:] - lam[:, :-1]) > APART * np.abs(lam[:, 1:])).all(axis=1)
        omega = np.sqrt(np.where(exact[:, None], lam, 1.0))
        shapes = _normalised(V, normalize)
        if normalize == "mass":
            modal_mass = np.ones((rows, n))
            modal_stiffness = lam.copy()
        else:
            modal_mass = np.sum(shapes * (M @ shapes), axis=1)
            modal_stiffness = np.sum(shapes * (K @ shapes), axis=1)
        exact &= np.isfinite(shapes).all(axis=(1, 2)) & np.isfinite(modal_mass).all(axis=1) \
            & np.isfinite(modal_stiffness).all(axis=1) & np.isfinite(omega).all(axis=1)
        if C is not None:
            C = (C + C.transpose(0, 2, 1)) / 2.0
            if damping == "complex":
                zeta, omega_d, damped = _complex_damping(M, K, C, L, A, V, omega)
            else:
                zeta, omega_d, damped = _damping(C, V, omega)
            exact &= damped
    values = {}
    for i in range(n):
        values[f"omega_{i + 1}"] = np.ascontiguousarray(omega[:, i])
    for i in range(n):
        values[f"f_{i + 1}"] = omega[:, i] / (2.0 * math.pi)
    for i in range(n):
        values[f"mode_{i + 1}"] = np.ascontiguousarray(shapes[:, :, i])
        values[f"modal_mass_{i + 1}"] = np.ascontiguousarray(modal_mass[:, i])
        values[f"modal_stiffness_{i + 1}"] = np.ascontiguousarray(modal_stiffness[:, i])
    if C is not None:
        for i in range(n):
            values[f"zeta_{i + 1}"] = np.ascontiguousarray(zeta[:, i])
        for i in range(n):
            values[f"omega_d_{i + 1}"] = np.ascontiguousarray(omega_d[:, i])
        if damping == "complex":
            return Columns(values, exact, model="non-proportional damping",
                           method="eigh+state-space", warnings=(NON_PROPORTIONAL_NOTE,),
                           warned=exact.copy())
        return Columns(values, exact, model="proportional damping", method="eigh")
    return Columns(values, exact, model="linear", method="eigh")


def _damping(C, V, omega):
    """``(zeta, omega_d, exact)`` of proportional damping on a stack:

    .. math:: \\zeta_i = \\frac{(V^T C V)_{ii}}{2 \\omega_i}, \\quad
              \\omega_{d,i} = \\omega_i \\sqrt{(1 - \\zeta_i)(1 + \\zeta_i)},

    ``V`` the mass-normalised mode shapes (``V^T M V = I``), as
    :func:`dyncalc.physics.modes._damp_part` forms them. A row is exact where ``V^T C V`` is
    diagonal well inside the one-off's ``PROPORTIONAL_RTOL`` (a margin of 100), every mode's
    damping is at least :data:`DAMPING_SPREAD` of the largest (a small one would carry the
    larger ones' rounding) and every mode underdamped well below 1 (no note); the
    non-proportional (state-space) rows, rigid-body, critical and overdamped modes are the
    one-off's."""
    modal = V.transpose(0, 2, 1) @ C @ V
    diag = np.diagonal(modal, axis1=1, axis2=2)
    off = np.abs(modal - diag[:, :, None] * np.eye(modal.shape[1]))
    scale = np.abs(modal).max(axis=(1, 2))
    exact = (off.max(axis=(1, 2)) <= PROPORTIONAL_RTOL / MARGIN_P * scale) \
        & (diag.min(axis=1) > DAMPING_SPREAD * scale)
    zeta = diag / (2.0 * omega)
    gap = (1.0 - zeta) * (1.0 + zeta)
    exact &= (gap > UNDERDAMPED).all(axis=1)
    omega_d = omega * np.sqrt(np.where(gap > 0.0, gap, 1.0))
    exact &= np.isfinite(zeta).all(axis=1) & np.isfinite(omega_d).all(axis=1)
    return zeta, omega_d, exact


def _complex_damping(M, K, C, L, A, V, omega):
    """``(zeta, omega_d, exact)`` of damping that is not proportional, on a stack:

    .. math:: \\begin{bmatrix} 0 & I \\\\ -A & -L^{-1} C L^{-T} \\end{bmatrix} z = s z,
              \\quad s = -\\zeta \\omega \\pm i \\omega_d,

    the state-space form reduced by ``M = L L^T`` (``A = L^{-1} K L^{-T}``), whose
    eigenvalues are the one-off's (it solves ``[[0, I], [-K, -C]] z = s [[I, 0], [0, M]] z``
    with LAPACK's ``ggev``: the same values, rounded otherwise). As the one-off, the
    eigenvalues with ``Im s > 0``, by ascending ``|s|``, go to the free undamped mode of
    nearest ``omega``: ``zeta = -Re s / |s|``, ``omega_d = Im s``. A row is exact where
    ``V^T C V`` is far from diagonal (:data:`MARGIN_P` beyond the one-off's test), C is
    positive semi-definite with a margin, no entry of M, K or C leaves a coordinate uncoupled
    from the rest (the one-off solves such groups apart), every eigenvalue is complex, the
    ``|s|`` and the matches are clear (:data:`APART`) and every ``zeta`` is at least
    :data:`COMPLEX_ZETA` (below it, ``Re s`` carries the rounding of ``|s|``)."""
    rows, n, _ = C.shape
    modal = V.transpose(0, 2, 1) @ C @ V
    diag = np.diagonal(modal, axis1=1, axis2=2)
    off = np.abs(modal - diag[:, :, None] * np.eye(n))
    scale = np.abs(modal).max(axis=(1, 2))
    exact = off.max(axis=(1, 2)) > PROPORTIONAL_RTOL * MARGIN_P * scale
    c_eigs = np.linalg.eigvalsh(C)
    exact &= c_eigs[:, 0] >= -ZERO_RTOL / MARGIN_P * np.abs(c_eigs).max(axis=1)
    linked = ((M != 0.0) | (K != 0.0) | (C != 0.0)).astype(np.int64)
    reach = linked
    for _ in range(max(1, math.ceil(math.log2(n)))):  # paths of up to n - 1 links
        reach = np.minimum(reach @ reach + reach, 1)
    exact &= (reach > 0).all(axis=(1, 2))
    Cr = np.linalg.solve(L, np.linalg.solve(L, C).transpose(0, 2, 1))
    state = np.zeros((rows, 2 * n, 2 * n))
    state[:, :n, n:] = np.eye(n)
    state[:, n:, :n] = -A
    state[:, n:, n:] = -(Cr + Cr.transpose(0, 2, 1)) / 2.0
    state = np.where(exact[:, None, None], state, 0.0)
    s = np.linalg.eigvals(state)
    size = modulus(s)
    top = size.max(axis=1)
    exact &= np.isfinite(s).all(axis=1) & (np.abs(s.imag) > APART * top[:, None]).all(axis=1)
    upper = np.where(s.imag > 0.0, size, np.inf)
    order = np.argsort(upper, axis=1)[:, :n]  # the n with Im s > 0, ascending |s|
    r = np.arange(rows)[:, None]
    picked, sizes = s[r, order], upper[r, order]
    exact &= np.isfinite(sizes).all(axis=1)
    if n > 1:
        exact &= (np.diff(sizes, axis=1) > APART * sizes[:, 1:]).all(axis=1)
    zeta, omega_d = np.zeros((rows, n)), np.zeros((rows, n))
    free = np.ones((rows, n), dtype=bool)
    for j in range(n):  # the one-off's matching, a mode at a time
        distance = np.where(free, np.abs(omega - sizes[:, j:j + 1]), np.inf)
        nearest = np.argmin(distance, axis=1)
        if n - j > 1:
            two = np.sort(distance, axis=1)[:, :2]
            exact &= two[:, 1] - two[:, 0] > APART * sizes[:, j]
        k = np.arange(rows)
        free[k, nearest] = False
        z = picked[:, j]
        zeta[k, nearest] = -z.real / modulus(z)
        omega_d[k, nearest] = z.imag
    exact &= (zeta >= COMPLEX_ZETA).all(axis=1) & np.isfinite(omega_d).all(axis=1)
    return zeta, omega_d, exact


def _normalised(V, normalize: str):
    """:func:`dyncalc.physics.modes._normalised` on a stack: each mode (column) scaled so
    its largest component is +1 (``max``) or positive (``mass``), tiny components 0."""
    rows, n, _ = V.shape
    reference = np.argmax(np.abs(V), axis=1)  # (rows, modes)
    r = np.arange(rows)[:, None]
    cols = np.arange(n)[None, :]
    pivot = V[r, reference, cols]  # (rows, modes)
    shapes = V / pivot[:, None, :] if normalize == "max" else V * np.sign(pivot)[:, None, :]
    largest = np.abs(shapes[r, reference, cols])
    shapes = np.where(np.abs(shapes) < _COMPONENT_FLOOR * largest[:, None, :], 0.0,
                      shapes) + 0.0
    if normalize == "max":
        shapes[r, reference, cols] = 1.0
    return shapes
