"""The numbers of a two-coordinate ``eom`` derivation on arrays: the linearised mass and
stiffness matrices, the two natural frequencies and the accelerations at a state, from the
numpy functions generated out of the symbolic derivation (:mod:`dyncalc.scenes.eom_tables2`).

The one-off (:mod:`dyncalc.commands.eom_results`) and ``eom --scene --batch`` both evaluate
these on float64 arrays (the one-off on arrays of one row), so they agree bit for bit.

The frequencies solve ``det(K - lam M) = 0`` through the symmetric reduction ``C = L^-1 K
L^-T`` (``M = L L^T``, ``det M`` and ``det K`` from the symbolic derivation, so a nearly
singular ``K`` keeps its small eigenvalue):

.. math:: c_{00} = K_{00}/M_{00}, \\quad
          c_{01} = (K_{01} M_{00} - K_{00} M_{01}) / (M_{00} \\sqrt{\\det M}), \\quad
          c_{11} = (K_{11} M_{00}^2 - 2 M_{01} K_{01} M_{00} + M_{01}^2 K_{00})
                   / (M_{00} \\det M)

.. math:: \\lambda_\\pm = (c_{00} + c_{11})/2 \\pm \\mathrm{hypot}((c_{00} - c_{11})/2,
          c_{01}), \\quad \\lambda_+ \\lambda_- = \\det K / \\det M

the one of the two without cancellation taken from the sum, the other from the product;
``omega_i = sqrt(lam_i)`` (ascending), stable where both ``lam >= -1e-10 max |lam|`` (the
rule of :func:`~dyncalc.physics.lagrange_equations.frequencies`).

Reference: Gross et al., *Engineering Mechanics 3*, 2nd ed., 4.3; Golub & Van Loan,
*Matrix Computations*, 4th ed., 8.7.2 (the symmetric-definite problem).
"""
from __future__ import annotations

from ..lazy import numpy as np

__all__ = ["PairPlan", "two_frequencies", "finite_rows"]


class PairPlan:
    """The generated functions of one two-coordinate scene (an entry of
    :mod:`dyncalc.scenes.eom_tables2`): ``names`` (the parameters, in the order the functions
    take them after the coordinates), ``M(q1, q2, *p)`` and ``K(q1, q2, *p)`` (the four
    entries, row by row), ``detM`` and ``detK`` (the same arguments), ``a(q1, q2, q1',
    q2', t, *p)`` (the two accelerations), ``roots`` (the equilibria, ``None`` for a free
    coordinate) or, where the values move the one equilibrium, ``root_forms`` (``R(*p)``)."""

    __slots__ = ("names", "mass", "stiffness", "det_mass", "det_stiffness", "acceleration",
                 "roots", "root_forms")

    def __init__(self, entry: dict):
        self.names, self.roots = list(entry["names"]), entry["roots"]
        self.root_forms = entry.get("R")
        self.mass, self.stiffness = entry["M"], entry["K"]
        self.det_mass, self.det_stiffness = entry["detM"], entry["detK"]
        self.acceleration = entry["a"]

    def _args(self, params: dict):
        return [params[name] for name in self.names]

    def matrices(self, q1, q2, params: dict):
        """``(M, K, detM, detK)`` at ``(q1, q2)`` (arrays of ``n``): ``(n, 2, 2)`` matrices
        and ``(n,)`` determinants."""
        args = self._args(params)
        n = np.shape(q1)
        M = np.stack([_array(v, n) for v in self.mass(q1, q2, *args)], axis=-1)
        K = np.stack([_array(v, n) for v in self.stiffness(q1, q2, *args)], axis=-1)
        return (M.reshape(n + (2, 2)), K.reshape(n + (2, 2)),
                _array(self.det_mass(q1, q2, *args), n),
                _array(self.det_stiffness(q1, q2, *args), n))

    def root_rows(self, params: dict, n: int) -> list:
        """The one equilibrium of each row where the values move it (``roots`` is ``None``):
        two arrays of ``n``, ``|q| < 1e-12`` made 0 (as the equilibria search writes it)."""
        return [np.where(np.abs(q) < 1e-12, 0.0, q) for q in
                (_array(v, (n,)) for v in self.root_forms(*self._args(params)))]

    def accelerations(self, q1, q2, qd1, qd2, t, params: dict):
        """The two accelerations at the state (arrays)."""
        return [_array(v, np.shape(q1))
                for v in self.acceleration(q1, q2, qd1, qd2, t, *self._args(params))]


def _array(value, shape):
    out = np.asarray(value, dtype=float)
    return out if out.shape == shape else np.full(shape, float(out))


def two_frequencies(M, K, det_m, det_k):
    """``(omega, stable)``: ``(n, 2)`` ascending natural angular frequencies and ``(n,)``
    stabilities of ``M q'' + K q = 0`` (``M``, ``K``: ``(n, 2, 2)``; ``det_m``, ``det_k``
    their determinants); a frequency whose ``lam <= 1e-10 max |lam|`` is 0.

    >>> import numpy as np
    >>> M = np.array([[[1.0, 0.0], [0.0, 2.0]]]); K = np.array([[[150.0, -50.0], [-50.0, 250.0]]])
    >>> two_frequencies(M, K, np.array([2.0]), np.array([35000.0]))[0]
    array([[10.        , 13.22875656]])
    """
    lo, hi = _reduced(M, K, det_m, det_k)
    with np.errstate(all="ignore"):
        tol = 1e-10 * np.maximum(np.abs(lo), np.abs(hi))
        stable = (lo >= -tol) & (hi >= -tol)
        lam = np.stack([lo, hi], axis=-1)
        omega = np.where(lam > tol[:, None], np.sqrt(np.where(lam > tol[:, None], lam, 0.0)),
                         0.0)
    return omega, stable


def finite_rows(M, K, det_m, det_k):
    """``(n,)`` True where the reduction is finite throughout (``M``, ``K``, ``det K``, both
    eigenvalues; ``0 < det M < inf``): the rows :func:`two_frequencies` answers; elsewhere
    (an overflow, a singular ``M``) the one-off takes the symbolic path."""
    lo, hi = _reduced(M, K, det_m, det_k)
    with np.errstate(all="ignore"):
        return (np.isfinite(M).all(axis=(1, 2)) & np.isfinite(K).all(axis=(1, 2))
                & (det_m > 0) & np.isfinite(det_m) & np.isfinite(det_k)
                & np.isfinite(lo) & np.isfinite(hi))


def _reduced(M, K, det_m, det_k):
    """``(lo, hi)``: the two eigenvalues of the symmetric reduction (the module's formulas)."""
    with np.errstate(all="ignore"):
        m00, m01 = M[:, 0, 0], M[:, 0, 1]
        k00, k01, k11 = K[:, 0, 0], K[:, 0, 1], K[:, 1, 1]
        c00 = k00 / m00
        c01 = (k01 * m00 - k00 * m01) / (m00 * np.sqrt(det_m))
        c11 = (k11 * m00 * m00 - 2 * m01 * k01 * m00 + m01 * m01 * k00) / (m00 * det_m)
        mean, radius = (c00 + c11) / 2, np.hypot((c00 - c11) / 2, c01)
        product = det_k / det_m
        up = mean >= 0
        big = np.where(up, mean + radius, mean - radius)  # (no cancellation)
        other = np.where(big != 0, product / big, 0.0)
        return np.where(up, other, big), np.where(up, big, other)
