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
from .columns import Columns, column_kernel
from .face import check_units, magnitude
from .numerics_arrays import (dd_add, dd_div, dd_mul, dd_sqrt, round_certified,
                              two_product_array, two_sum_array)
from .outcome import Outcome, periodic, periodic_arrays

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


#: Ratio of the smallest non-zero stiffness (mass) to the largest beyond which the columns
#: leave the row to the one-off (the scaled double-double products would lose bits).
_SPREAD = 2.0 ** -250
#: ``max(|a - d|/2, |b|)`` below this share of ``max(a, d)`` makes the mode shapes ill
#: conditioned in the inputs (near-equal uncoupled frequencies): those rows are left to the
#: one-off, whose 40 digits and the double-double could then disagree.
_WELL_POSED = 2.0 ** -30
#: Relative error bounds of the double-double frequencies and mode components (a few 2^-104
#: per step; the modes amplified at most 2^30 by the condition above). The decimal values of
#: the one-off are within about 1e-36 of the exact ones, far inside these bounds.
_OMEGA_BOUND = 2.0 ** -95
_MODE_BOUND = 2.0 ** -68


def _unit_mode_columns(x1, x2):
    """Components of ``(x1, x2)`` (double-doubles) scaled to unit length, each rounded with
    :func:`round_certified`: ``(v1, v2, certain)``, first non-zero component positive."""
    norm = dd_sqrt(*dd_add(*dd_mul(*x1, *x1), *dd_mul(*x2, *x2)))
    v1, sure1 = round_certified(*dd_div(*x1, *norm), _MODE_BOUND)
    v2, sure2 = round_certified(*dd_div(*x2, *norm), _MODE_BOUND)
    flip = (v1 < 0.0) | ((v1 == 0.0) & (v2 < 0.0))
    sign = np.where(flip, -1.0, 1.0)
    return np.stack([sign * v1 + 0.0, sign * v2 + 0.0], axis=-1), sure1 & sure2


@column_kernel(coupled_blocks)
def _coupled_blocks_columns(m1, m2, k1, k2, k3) -> Columns:
    """:func:`coupled_blocks` on columns (masses in kg, stiffnesses in N/m).

    The one-off computes in 40-digit decimals and rounds once to floats, which numpy cannot
    repeat; but its floats are the correctly rounded exact values wherever those are not within
    about 1e-36 of a rounding boundary. So the same closed form is evaluated here in
    double-double arithmetic (stiffnesses and masses scaled by powers of two first, the
    eigenvalues scaled back exactly) and each result rounded with :func:`round_certified`: a
    row is exact only where every rounding is certainly the correct one (all but about one row
    in 2^15 for the modes). Rows not exact: stiffnesses or masses more than 2^250 apart, nearly
    equal uncoupled frequencies with a weak coupling (:data:`_WELL_POSED`), negative or fewer
    than two positive stiffnesses (refused), results zero or beyond float64.
    """
    ks = (k1, k2, k3)
    _, sk = np.frexp(np.maximum(np.maximum(k1, k2), k3))
    _, sm = np.frexp(np.maximum(m1, m2))
    with np.errstate(all="ignore"):
        K1, K2, K3 = (np.ldexp(k, -sk) for k in ks)
        M1, M2 = np.ldexp(m1, -sm), np.ldexp(m2, -sm)
        tame = (M1 >= _SPREAD) & (M2 >= _SPREAD)
        for k in (K1, K2, K3):
            tame &= (k == 0.0) | (k >= _SPREAD)
        a = dd_div(*two_sum_array(K1, K3), M1, 0.0)
        d = dd_div(*two_sum_array(K2, K3), M2, 0.0)
        mass = two_product_array(M1, M2)
        b = dd_div(-K3, 0.0, *dd_sqrt(*mass))
        half = tuple(0.5 * x for x in dd_add(*a, -d[0], -d[1]))
        radius = dd_sqrt(*dd_add(*dd_mul(*half, *half), *dd_mul(*b, *b)))
        lam2 = dd_add(*(0.5 * x for x in dd_add(*a, *d)), *radius)
        det = dd_add(*dd_add(*two_product_array(K1, K2), *two_product_array(K1, K3)),
                     *two_product_array(K2, K3))
        lam1 = dd_div(*dd_div(*det, *mass), *lam2)
        shift = sk.astype(np.int64) - sm              # lambda = lambda_scaled 2^shift
        odd = (shift % 2).astype(bool)
        twice = np.where(odd, 2.0, 1.0)
        omegas, sure = [], tame
        for lam in (lam1, lam2):
            w, ok = round_certified(*dd_sqrt(twice * lam[0], twice * lam[1]), _OMEGA_BOUND)
            omegas.append(np.ldexp(w, ((shift - odd) // 2).astype(np.int32)))
            sure = sure & ok
        largest = np.maximum(a[0], d[0])
        sure &= np.maximum(np.abs(half[0]), np.abs(b[0])) >= _WELL_POSED * largest
        ge = half[0] >= 0.0
        plus, minus = dd_add(*half, *radius), dd_add(*radius, -half[0], -half[1])
        u1 = tuple(np.where(ge, p, q) for p, q in zip(plus, b))
        u2 = tuple(np.where(ge, p, q) for p, q in zip(b, minus))
        root1, root2 = dd_sqrt(M1, 0.0), dd_sqrt(M2, 0.0)
        mode1, sure1 = _unit_mode_columns(dd_div(-u2[0], -u2[1], *root1), dd_div(*u1, *root2))
        mode2, sure2 = _unit_mode_columns(dd_div(*u1, *root1), dd_div(*u2, *root2))
        values = {**periodic_arrays(omegas[0], "_1"), **periodic_arrays(omegas[1], "_2")}
    positive = (k1 > 0.0).astype(int) + (k2 > 0.0) + (k3 > 0.0)
    exact = (sure & sure1 & sure2 & (positive >= 2) & (np.minimum(np.minimum(k1, k2), k3) >= 0.0)
             & (np.abs(omegas[0]) >= 2.0 ** -1022) & (np.abs(omegas[1]) >= 2.0 ** -1022))
    for array in values.values():
        exact &= np.isfinite(array) & (array != 0.0)
    values.update(mode_1=mode1, mode_2=mode2)
    return Columns(values, exact=exact)
