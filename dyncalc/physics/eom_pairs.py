"""The numbers of a two-coordinate ``eom`` derivation on arrays: the linearised mass and
stiffness matrices, the two natural frequencies and the accelerations at a state, from the
numpy functions generated out of the symbolic derivation (:mod:`dyncalc.scenes.eom_tables2`).

The one-off (:mod:`dyncalc.commands.eom_results`) and ``eom --scene --batch`` both evaluate
these on float64 arrays (the one-off on arrays of one row), so they agree bit for bit.

The frequencies solve ``det(K - lam M) = 0`` with both matrices first scaled by ``D =
diag(M_00^-1/2, M_11^-1/2)`` (the same eigenvalues; masses far apart in size, 1e300 kg beside
1e2, no longer overflow a product and lose the coupling), then through the symmetric
reduction ``C = L^-1 K~ L^-T`` of ``M~ = D M D = L L^T`` (``det M`` and ``det K`` from the
symbolic derivation, so a nearly singular ``M`` or ``K`` keeps its small eigenvalue):

.. math:: r = \\frac{M_{01}}{\\sqrt{M_{00}}\\sqrt{M_{11}}}, \\quad
          s^2 = \\frac{\\det M}{M_{00} M_{11}}, \\quad
          \\tilde K_{ij} = \\frac{K_{ij}}{\\sqrt{M_{ii}}\\sqrt{M_{jj}}}

.. math:: c_{00} = \\tilde K_{00}, \\quad c_{01} = (\\tilde K_{01} - r \\tilde K_{00}) / s,
          \\quad c_{11} = (\\tilde K_{11} - 2 r \\tilde K_{01} + r^2 \\tilde K_{00}) / s^2

.. math:: \\lambda_\\pm = (c_{00} + c_{11})/2 \\pm \\mathrm{hypot}((c_{00} - c_{11})/2,
          c_{01}), \\quad \\lambda_+ \\lambda_- = \\det K / \\det M

the one of the two without cancellation taken from the sum, the other from the product
(divided without an overflow of ``det K / det M`` itself);
``omega_i = sqrt(lam_i)`` (ascending), stable where both ``lam >= -1e-10 max |lam|`` (the
rule of :func:`~dyncalc.physics.lagrange_equations.frequencies`).

Reference: Gross et al., *Engineering Mechanics 3*, 2nd ed., 4.3; Golub & Van Loan,
*Matrix Computations*, 4th ed., 8.7.2 (the symmetric-definite problem).
"""
from __future__ import annotations

from ..lazy import numpy as np

__all__ = ["PairPlan", "two_frequencies", "finite_rows", "frequency_rows", "within",
           "constant", "near"]


class PairPlan:
    """The generated functions of one two-coordinate scene (an entry of
    :mod:`dyncalc.scenes.eom_tables2`): ``names`` (the parameters, in the order the functions
    take them after the coordinates), ``M(q1, q2, *p)`` and ``K(q1, q2, *p)`` (the four
    entries, row by row), ``detM`` and ``detK`` (the same arguments), ``a(q1, q2, q1',
    q2', t, *p)`` (the two accelerations), ``roots`` (the equilibria, ``None`` for a free
    coordinate) or, where the values move them, ``root_forms`` (``R(*p)``: the two
    coordinates of each equilibrium in turn; or a hand-written ``Rc(*p)`` giving them and
    the rows where they are all, ``covered``), and ``domain`` (the indices of the
    coordinates the scene bounds) with ``bound_forms`` (``B(*p)``: each one's lowest and
    highest)."""

    __slots__ = ("names", "mass", "stiffness", "det_mass", "det_stiffness", "acceleration",
                 "roots", "root_forms", "covers", "domain", "bound_forms")

    def __init__(self, entry: dict):
        self.names, self.roots = list(entry["names"]), entry["roots"]
        self.covers = entry.get("Rc") is not None
        self.root_forms = entry.get("Rc") if self.covers else entry.get("R")
        self.domain, self.bound_forms = entry.get("domain", ()), entry.get("B")
        self.mass, self.stiffness = entry["M"], entry["K"]
        self.det_mass, self.det_stiffness = entry["detM"], entry["detK"]
        self.acceleration = entry["a"]

    def _args(self, params: dict):
        return [params[name] for name in self.names]

    def matrices(self, q1, q2, params: dict):
        """``(M, K, detM, detK)`` at ``(q1, q2)`` (arrays of ``n``): ``(n, 2, 2)`` matrices
        and ``(n,)`` determinants. A coordinate the same on every row (an equilibrium at
        ``pi/2``) is passed as one element, so its sines and cosines are taken once (the
        same ufunc loop on the same element as every row's: the same bits)."""
        args = self._args(params)
        n = np.shape(q1)
        q1, q2 = (q[:1] if constant(q) else q for q in (q1, q2))
        M = np.stack([_array(v, n) for v in self.mass(q1, q2, *args)], axis=-1)
        K = np.stack([_array(v, n) for v in self.stiffness(q1, q2, *args)], axis=-1)
        return (M.reshape(n + (2, 2)), K.reshape(n + (2, 2)),
                _array(self.det_mass(q1, q2, *args), n),
                _array(self.det_stiffness(q1, q2, *args), n))

    def root_rows(self, params: dict, n: int) -> tuple[list, "np.ndarray", "np.ndarray"]:
        """``(roots, distinct, covered)``: the equilibria of each row where the values move
        them (``roots`` is ``None``), a list of ``[q1, q2]`` (arrays of ``n``, ``|q| <
        1e-12`` made 0, both NaN where a row lacks that one) ordered in each row as the
        numeric search orders them (by ``|q1| + |q2|``, then the larger ``q1``, then the
        larger ``q2``; the missing last); ``distinct`` (``(n,)``) False where two of a row's
        coincide (within ``1e-7 max(1, |q|)``: the search would list one); ``covered`` False
        where the forms are not all of the row's equilibria (the one-off searches)."""
        made = self.root_forms(*self._args(params))
        made, covered = made if self.covers else (made, np.ones(n, dtype=bool))
        covered = _array(covered, (n,)).astype(bool)
        flat = [np.where(np.abs(q) < 1e-12, 0.0, q) for q in (_array(v, (n,)) for v in made)]
        roots = [flat[i:i + 2] for i in range(0, len(flat), 2)]
        distinct = np.ones(n, dtype=bool)
        if len(roots) == 1:
            return roots, distinct, covered
        q1 = np.stack([r[0] for r in roots], axis=1)
        q2 = np.stack([r[1] for r in roots], axis=1)
        with np.errstate(all="ignore"):
            order = np.lexsort((-q2, -q1, np.abs(q1) + np.abs(q2)))  # (each row's own)
            q1, q2 = (np.take_along_axis(q, order, axis=1) for q in (q1, q2))
            for i in range(len(roots)):
                for j in range(i + 1, len(roots)):
                    distinct &= ~(near(q1[:, i], q1[:, j]) & near(q2[:, i], q2[:, j]))
        return [[q1[:, k], q2[:, k]] for k in range(len(roots))], distinct, covered

    def bound_rows(self, params: dict, n: int) -> dict:
        """``{coordinate index: (lowest, highest)}`` of each row (arrays of ``n``): the
        scene's domain at the rows' values; ``{}`` where it has none."""
        if not self.domain:
            return {}
        ends = [_array(v, (n,)) for v in self.bound_forms(*self._args(params))]
        return {c: (ends[2 * i], ends[2 * i + 1]) for i, c in enumerate(self.domain)}

    def accelerations(self, q1, q2, qd1, qd2, t, params: dict):
        """The two accelerations at the state (arrays)."""
        return [_array(v, np.shape(q1))
                for v in self.acceleration(q1, q2, qd1, qd2, t, *self._args(params))]


def within(q, bounds: dict):
    """``(n,)`` True where the equilibrium ``q`` (its two coordinates, arrays of ``n``) lies
    in the scene's domain (``bounds``: :meth:`PairPlan.bound_rows`), to 1e-9 (the one-off's
    rule); NaN bounds or coordinates are outside."""
    mask = np.ones(np.shape(q[0]), dtype=bool)
    for i, (lo, hi) in bounds.items():
        mask &= (lo - 1e-9 <= q[i]) & (q[i] <= hi + 1e-9)
    return mask


def constant(q) -> bool:
    """Whether a float64 column of more than one row holds one value, bit for bit (``-0.0``
    and ``0.0`` differ: their sines do)."""
    q = np.asarray(q)
    if q.ndim != 1 or len(q) < 2 or q.dtype != np.float64:
        return False
    bits = q.view(np.int64)
    return bool((bits == bits[0]).all())


def near(a, b):
    """Where two equilibria's coordinates agree as the numeric search merges them (``a`` the
    earlier one; floats or arrays)."""
    return np.abs(a - b) <= 1e-7 * np.maximum(1.0, np.abs(a))


def _array(value, shape):
    out = np.asarray(value, dtype=float)
    return out if out.shape == shape else np.broadcast_to(out, shape).copy()


def two_frequencies(M, K, det_m, det_k):
    """``(omega, stable)``: ``(n, 2)`` ascending natural angular frequencies and ``(n,)``
    stabilities of ``M q'' + K q = 0`` (``M``, ``K``: ``(n, 2, 2)``; ``det_m``, ``det_k``
    their determinants); a frequency whose ``lam <= 1e-10 max |lam|`` is 0.

    >>> import numpy as np
    >>> M = np.array([[[1.0, 0.0], [0.0, 2.0]]]); K = np.array([[[150.0, -50.0], [-50.0, 250.0]]])
    >>> two_frequencies(M, K, np.array([2.0]), np.array([35000.0]))[0]
    array([[10.        , 13.22875656]])
    """
    return frequency_rows(M, K, det_m, det_k)[:2]


def finite_rows(M, K, det_m, det_k):
    """``(n,)`` True where the reduction is finite throughout (``M``, ``K``, ``det K``, both
    eigenvalues; ``0 < det M < inf``): the rows :func:`two_frequencies` answers; elsewhere
    (an overflow, a singular ``M``) the one-off takes the symbolic path."""
    return frequency_rows(M, K, det_m, det_k)[2]


def frequency_rows(M, K, det_m, det_k):
    """``(omega, stable, finite)``: :func:`two_frequencies` and :func:`finite_rows` from one
    reduction (a batch asks both of every equilibrium)."""
    lo, hi = _reduced(M, K, det_m, det_k)
    with np.errstate(all="ignore"):
        tol = 1e-10 * np.maximum(np.abs(lo), np.abs(hi))
        stable = (lo >= -tol) & (hi >= -tol)
        lam = np.stack([lo, hi], axis=-1)
        omega = np.where(lam > tol[:, None], np.sqrt(np.where(lam > tol[:, None], lam, 0.0)),
                         0.0)
        finite = (np.isfinite(M).all(axis=(1, 2)) & np.isfinite(K).all(axis=(1, 2))
                  & (det_m > 0) & np.isfinite(det_m) & np.isfinite(det_k)
                  & np.isfinite(lo) & np.isfinite(hi))
    return omega, stable, finite


def _reduced(M, K, det_m, det_k):
    """``(lo, hi)``: the two eigenvalues of the scaled symmetric reduction (the module's
    formulas)."""
    with np.errstate(all="ignore"):
        r0, r1 = np.sqrt(M[:, 0, 0]), np.sqrt(M[:, 1, 1])
        r = M[:, 0, 1] / r0 / r1
        s2 = det_m / M[:, 0, 0] / M[:, 1, 1]
        k00 = K[:, 0, 0] / r0 / r0
        k01 = K[:, 0, 1] / r0 / r1
        k11 = K[:, 1, 1] / r1 / r1
        c00 = k00
        c01 = (k01 - r * k00) / np.sqrt(s2)
        c11 = (k11 - 2 * r * k01 + r * r * k00) / s2
        mean, radius = (c00 + c11) / 2, np.hypot((c00 - c11) / 2, c01)
        up = mean >= 0
        big = np.where(up, mean + radius, mean - radius)  # (no cancellation)
        other = np.where(big != 0, _quotient(det_k, det_m, big), 0.0)
        return np.where(up, other, big), np.where(up, big, other)


def _quotient(a, b, c):
    """``a / b / c`` without an intermediate overflow or underflow (``det K / det M`` is the
    product of the eigenvalues: 1e367 where each is 1e183): the significands divided, the
    exponents summed (:func:`numpy.frexp`, :func:`numpy.ldexp`); the same bits as ``a / b /
    c`` wherever that stays normal."""
    (ma, ea), (mb, eb), (mc, ec) = np.frexp(a), np.frexp(b), np.frexp(c)
    return np.ldexp(ma / mb / mc, ea - eb - ec)
