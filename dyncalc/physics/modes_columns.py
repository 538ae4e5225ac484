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
from .modes import _COMPONENT_FLOOR, PROPORTIONAL_RTOL, SYMMETRY_RTOL

__all__ = ["stacked_modes", "MARGIN", "APART", "DAMPING_SPREAD", "UNDERDAMPED"]

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


def stacked_modes(M, K, normalize: str = "max", C=None) -> Columns:
    """The one-off's results of every row (see the module); ``exact`` marks the rows the
    vectorised path takes. With ``C`` (N s/m, (rows, n, n)) also the proportional damping's
    ``zeta_i`` and ``omega_d_i`` (:func:`_damping`)."""
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
