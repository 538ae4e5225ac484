"""Two degrees of freedom: two blocks coupled by springs.

Pure functions on pint quantities returning an :class:`~dyncalc.physics.outcome.Outcome`.

References
----------
.. [1] Gross, Hauger, Schröder, Wall, Govindjee, *Engineering Mechanics 3: Dynamics*, 2nd ed.,
   Springer 2013, Chapter 4.
"""
from __future__ import annotations

from decimal import Decimal, localcontext

from ..lazy import numpy as np

from ..errors import PhysicsError
from ..units import MASS, STIFFNESS
from .face import check_units, magnitude

from .outcome import Outcome, periodic

__all__ = ["coupled_blocks", "two_by_two_modes"]


def _modes(k1: float, k2: float, k3: float, m1: float, m2: float):
    """Eigenvalues ``lambda_1 <= lambda_2`` of ``K v = lambda M v``, their square roots
    ``omega_1``, ``omega_2`` and mode shapes, for ``K = [[k1 + k3, -k3], [-k3, k2 + k3]]`` and
    ``M = diag(m1, m2)``: ``(lambda_1, lambda_2, omega_1, omega_2, mode_1, mode_2)``.

    Closed form, free of cancellation: with ``a = (k1 + k3)/m1`` and ``d = (k2 + k3)/m2``,

    * ``lambda_2 = (a + d)/2 + sqrt(((a - d)/2)^2 + k3^2/(m1 m2))`` adds positive terms only;
    * ``lambda_1 = det / lambda_2`` with ``det = (k1 k2 + k1 k3 + k2 k3)/(m1 m2)``, the
      determinant expanded so that ``k3^2`` cancels exactly (the textbook
      ``(a + d)/2 - sqrt(...)`` loses every digit when ``k3`` is stiff).

    The modes come from the symmetric form ``A = [[a, b], [b, d]] = M^-1/2 K M^-1/2``,
    ``b = -k3/sqrt(m1 m2)``: its eigenvector for ``lambda_2`` is ``(lambda_2 - d, b)`` when
    ``a >= d`` and ``(b, lambda_2 - a)`` otherwise (no cancellation); the one for ``lambda_1``
    is orthogonal to it; then ``v = M^-1/2 u``, unit length, first non-zero component
    positive. The arithmetic is decimal with :data:`_DIGITS` digits and an exponent range far
    beyond float64, so nothing overflows or underflows midway (``a`` is 4e323 for a 1e-320 kg
    block); only the results are rounded to floats (an eigenvalue may leave float64 where its
    frequency does not).

    >>> _modes(2.0, 2.0, 2.0, 4.0, 4.0)[:4]
    (0.5, 1.5, 0.7071067811865476, 1.224744871391589)
    """
    with localcontext() as ctx:
        ctx.prec, ctx.Emax, ctx.Emin = _DIGITS, 10 ** 6, -10 ** 6
        k1, k2, k3, m1, m2 = (Decimal(x) for x in (k1, k2, k3, m1, m2))
        a = (k1 + k3) / m1
        d = (k2 + k3) / m2
        b = -k3 / (m1 * m2).sqrt()
        half = (a - d) / 2
        radius = (half * half + b * b).sqrt()
        lam2 = (a + d) / 2 + radius
        lam1 = ((k1 * k2 + k1 * k3 + k2 * k3) / (m1 * m2)) / lam2
        if a >= d:
            u1, u2 = half + radius, b             # (lam2 - d, b)
        else:
            u1, u2 = b, radius - half             # (b, lam2 - a)
        if u1 == 0 and u2 == 0:                   # a == d and no coupling: any basis
            u1 = Decimal(1)
        modes = [_unit_mode(x1, x2, m1, m2) for x1, x2 in ((-u2, u1), (u1, u2))]
        return (float(lam1), float(lam2), float(lam1.sqrt()), float(lam2.sqrt()), *modes)


#: Decimal digits of :func:`_modes` (float64 holds 17).
_DIGITS = 40


def two_by_two_modes(k1, k2, k3, m1, m2):
    """``(lambda_1, lambda_2, mode_1, mode_2)`` of ``K v = lambda M v`` (see :func:`_modes`);
    the eigenvalues in 1/s^2, which can leave float64 where the frequencies do not.

    >>> l1, l2, v1, v2 = two_by_two_modes(1.0, 1.0, 1.0, 1.0, 1.0)
    >>> l1, l2, v1.round(12).tolist(), v2.round(12).tolist()
    (1.0, 3.0, [0.707106781187, 0.707106781187], [0.707106781187, -0.707106781187])
    """
    lam1, lam2, _w1, _w2, mode1, mode2 = _modes(k1, k2, k3, m1, m2)
    return lam1, lam2, mode1, mode2


def _unit_mode(u1: Decimal, u2: Decimal, m1: Decimal, m2: Decimal) -> np.ndarray:
    """``M^-1/2 u`` scaled to unit length, first non-zero component positive (in the decimal
    context of the caller)."""
    v1, v2 = u1 / m1.sqrt(), u2 / m2.sqrt()
    norm = (v1 * v1 + v2 * v2).sqrt()
    v = np.array([float(v1 / norm), float(v2 / norm)])
    if v[0] < 0.0 or (v[0] == 0.0 and v[1] < 0.0):
        v = -v
    return v + 0.0  # no negative zeros


@check_units(m1=MASS, m2=MASS, k1=STIFFNESS, k2=STIFFNESS, k3=STIFFNESS)
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
    m1_, m2_ = magnitude(m1, "kg"), magnitude(m2, "kg")
    k1_, k2_, k3_ = magnitude(k1, "N/m"), magnitude(k2, "N/m"), magnitude(k3, "N/m")
    if min(k1_, k2_, k3_) < 0.0 or (k1_ > 0.0) + (k2_ > 0.0) + (k3_ > 0.0) < 2:
        raise PhysicsError("coupled-blocks needs k1, k2, k3 >= 0 with at least two of them "
                           "positive; otherwise a block drifts freely (a zero-frequency mode)")
    _lam1, _lam2, omega1, omega2, mode1, mode2 = _modes(k1_, k2_, k3_, m1_, m2_)
    values = {**periodic(omega1, "_1"), **periodic(omega2, "_2"),
              "mode_1": mode1, "mode_2": mode2}
    return Outcome(values, model="linear", method="closed-form",
                   assumptions=["linear springs, frictionless floor, no damping; mode shapes "
                                "are (x1, x2) amplitude ratios scaled to unit length"])
