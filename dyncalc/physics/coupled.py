"""Two degrees of freedom: two blocks coupled by springs.

Pure functions on pint quantities returning an :class:`~dyncalc.physics.outcome.Outcome`.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapter 4.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import PhysicsError
from .numerics import sqrt_ratio
from .oscillators import _si
from .outcome import Outcome, periodic

__all__ = ["coupled_blocks", "two_by_two_modes"]


def _scaled_modes(k1: float, k2: float, k3: float, m1: float,
                     m2: float) -> tuple[float, float, np.ndarray, np.ndarray]:
    """Eigenvalues ``lambda_1 <= lambda_2`` of ``K v = lambda M v`` and their mode shapes, for
    ``K = [[k1 + k3, -k3], [-k3, k2 + k3]]`` and ``M = diag(m1, m2)``.

    Closed form, free of cancellation: with ``a = (k1 + k3)/m1`` and ``d = (k2 + k3)/m2``,

    * ``lambda_2 = (a + d)/2 + sqrt(((a - d)/2)^2 + k3^2/(m1 m2))`` adds positive terms only
      (the rounding of ``a - d`` is absolute and ``lambda_2 >= max(a, d)``, so it stays a few
      ulp of ``lambda_2``);
    * ``lambda_1 = det / lambda_2`` with ``det = (k1 k2 + k1 k3 + k2 k3)/(m1 m2)``, the
      determinant expanded so that ``k3^2`` cancels exactly, not in floating point (the
      textbook ``(a + d)/2 - sqrt(...)`` loses every digit when ``k3`` is stiff).

    The modes come from the symmetric form ``A = [[a, b], [b, d]] = M^-1/2 K M^-1/2``,
    ``b = -k3/sqrt(m1 m2)``: its eigenvector for ``lambda_2`` is ``(lambda_2 - d, b)`` when
    ``a >= d`` and ``(b, lambda_2 - a)`` otherwise, the gap formed as
    ``|a - d|/2 + sqrt(...)`` (no cancellation); the one for ``lambda_1`` is orthogonal to it;
    then ``v = M^-1/2 u``. Each is scaled to unit Euclidean length with its first non-zero
    component positive. Stiffnesses and masses are scaled by their largest value first, so
    nothing overflows midway.

    Parameters
    ----------
    k1, k2, k3 : float
        Non-negative stiffnesses (N/m), at least two positive (else a mode has zero
        frequency and ``lambda_1 = 0``).
    m1, m2 : float
        Positive masses (kg).

    Returns
    -------
    ``(lambda_1, lambda_2, ks, ms, mode_1, mode_2)``: the eigenvalues of the problem with the
    stiffnesses divided by ``ks`` (the largest) and the masses by ``ms`` (the largest), so the
    true eigenvalues are ``lambda ks/ms``; modes as numpy arrays.

    >>> l1, l2, ks, ms, v1, v2 = _scaled_modes(2.0, 2.0, 2.0, 4.0, 4.0)
    >>> l1, l2, ks, ms
    (1.0, 3.0, 2.0, 4.0)
    """
    ks = max(k1, k2, k3)
    ms = max(m1, m2)
    k1, k2, k3 = k1 / ks, k2 / ks, k3 / ks
    m1, m2 = m1 / ms, m2 / ms
    a = (k1 + k3) / m1
    d = (k2 + k3) / m2
    b = -k3 / math.sqrt(m1 * m2)
    radius = math.hypot(0.5 * (a - d), b)
    lam2 = 0.5 * (a + d) + radius
    lam1 = ((k1 * k2 + k1 * k3 + k2 * k3) / (m1 * m2)) / lam2
    # eigenvector of A for lam2 from the row whose diagonal gap has no cancellation
    if a >= d:
        u1, u2 = 0.5 * (a - d) + radius, b        # (lam2 - d, b)
    else:
        u1, u2 = b, 0.5 * (d - a) + radius        # (b, lam2 - a)
    if u1 == 0.0 and u2 == 0.0:                   # a == d and no coupling: any basis
        u1 = 1.0
    return (lam1, lam2, ks, ms, _unit_mode(-u2, u1, m1, m2), _unit_mode(u1, u2, m1, m2))


def two_by_two_modes(k1, k2, k3, m1, m2):
    """``(lambda_1, lambda_2, mode_1, mode_2)`` of ``K v = lambda M v`` (see
    :func:`_scaled_modes`); the eigenvalues in 1/s^2, which can leave float64 where the
    frequencies do not (:func:`coupled_blocks` takes their roots scaled, not these).

    >>> l1, l2, v1, v2 = two_by_two_modes(1.0, 1.0, 1.0, 1.0, 1.0)
    >>> l1, l2, v1.round(12).tolist(), v2.round(12).tolist()
    (1.0, 3.0, [0.707106781187, 0.707106781187], [0.707106781187, -0.707106781187])
    """
    lam1, lam2, ks, ms, mode1, mode2 = _scaled_modes(k1, k2, k3, m1, m2)
    return lam1 * (ks / ms), lam2 * (ks / ms), mode1, mode2


def _root(lam: float, ks: float, ms: float) -> float:
    """``sqrt(lam ks / ms)``: directly where ``lam ks/ms`` is a normal float (one rounding
    fewer), else ``sqrt(lam) sqrt_ratio(ks, ms)`` so that omega fits where omega^2 does not."""
    square = lam * (ks / ms)
    if 2.2250738585072014e-308 <= square < math.inf:
        return math.sqrt(square)
    return math.sqrt(lam) * sqrt_ratio(ks, ms)


def _unit_mode(u1: float, u2: float, m1: float, m2: float) -> np.ndarray:
    v = np.array([u1 / math.sqrt(m1), u2 / math.sqrt(m2)])
    v /= math.hypot(v[0], v[1])
    if v[0] < 0.0 or (v[0] == 0.0 and v[1] < 0.0):
        v = -v
    return v + 0.0  # no negative zeros


def coupled_blocks(m1, m2, k1, k2, k3) -> Outcome:
    """Two blocks on a frictionless floor between two walls: ``k1`` ties block 1 to its wall,
    ``k2`` block 2 to the other wall, ``k3`` couples the blocks.

    .. math:: M \\ddot x + K x = 0, \\quad
              K = \\begin{pmatrix} k_1 + k_3 & -k_3 \\\\ -k_3 & k_2 + k_3 \\end{pmatrix}, \\quad
              M = \\mathrm{diag}(m_1, m_2), \\qquad K v = \\omega^2 M v

    solved in closed form by :func:`two_by_two_modes`.

    Parameters
    ----------
    m1, m2 : Quantity
        Block masses ``[mass]``.
    k1, k2, k3 : Quantity
        Spring stiffnesses ``[force]/[length]``, non-negative, at least two positive.

    Returns
    -------
    Outcome with ``omega_1 <= omega_2`` (rad/s) with ``f_1``, ``T_1``, ``f_2``, ``T_2``, and
    ``mode_1``, ``mode_2``: the amplitude ratios ``(x1, x2)`` of each mode, unit Euclidean
    length, first non-zero component positive.

    Examples
    --------
    The set-up of E4.15 of [1] with equal blocks and springs: the in-phase mode at
    ``sqrt(k/m)`` and the anti-phase mode at ``sqrt(3k/m)``:

    >>> from dyncalc.units import Q_
    >>> kg, k = Q_(1, "kg"), Q_(100, "N/m")
    >>> out = coupled_blocks(kg, kg, k, k, k)
    >>> out.values["omega_1"].magnitude, out.values["omega_2"].magnitude  # rad/s
    (10.0, 17.320508075688775)
    >>> out.values["mode_2"].round(12).tolist()
    [0.707106781187, -0.707106781187]
    """
    m1_, m2_ = _si(m1, "kg"), _si(m2, "kg")
    k1_, k2_, k3_ = _si(k1, "N/m"), _si(k2, "N/m"), _si(k3, "N/m")
    if min(k1_, k2_, k3_) < 0.0 or (k1_ > 0.0) + (k2_ > 0.0) + (k3_ > 0.0) < 2:
        raise PhysicsError("coupled-blocks needs k1, k2, k3 >= 0 with at least two of them "
                           "positive; otherwise a block drifts freely (a zero-frequency mode)")
    lam1, lam2, ks, ms, mode1, mode2 = _scaled_modes(k1_, k2_, k3_, m1_, m2_)
    values = {**periodic(_root(lam1, ks, ms), "_1"), **periodic(_root(lam2, ks, ms), "_2"),
              "mode_1": mode1, "mode_2": mode2}
    return Outcome(values, model="linear", method="closed-form",
                   assumptions=["linear springs, frictionless floor, no damping; mode shapes "
                                "are (x1, x2) amplitude ratios scaled to unit length"])
