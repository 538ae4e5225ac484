"""Array twins of the numerics kernels, for the column kernels of batch mode.

Each twin computes on float64 numpy arrays, element by element, the very floats its scalar
twin in :mod:`dyncalc.physics.numerics` computes (same operations in the same order; IEEE
``+ - * /`` and ``sqrt`` are correctly rounded in both), and is tested bitwise against it
(tests/test_numerics_arrays_b.py). Where the scalar code calls libm (``sin``, ``asin``,
``atan2``, ``pow``) or Python's own ``math.hypot``, numpy's versions may differ by an ulp, so
the twin calls the very same function row by row (:func:`elementwise`).
"""
from __future__ import annotations

import math

from ..lazy import numpy as np


# --- twins for rotating, damping, nonlinear, coupled ---

def elementwise(function, *arrays):
    """``function`` (a ``math`` function taking floats) applied row by row to float64 arrays:
    the one-off functions' libm calls bit for bit, where numpy's own ``sin``, ``atan2``,
    ``hypot`` or ``power`` may round differently (measured: ``np.arctan2`` differs from
    ``math.atan2`` on 5 % of random inputs here, ``np.hypot`` from ``math.hypot`` on 1 %).

    >>> elementwise(math.atan2, np.array([1.0]), np.array([1.0])).tolist() == [math.pi / 4]
    True
    """
    lists = [np.asarray(a, dtype=float).ravel().tolist() for a in arrays]
    return np.fromiter(map(function, *lists), dtype=float, count=len(lists[0]))


def _safe_hypot(a: float, b: float) -> float:
    try:
        return math.hypot(a, b)
    except OverflowError:
        return math.inf


def hypot_array(a, b):
    """``math.hypot`` row by row, ``inf`` where it overflows (the twin of
    ``damping._hypot``; Python's hypot is not libm's, so ``np.hypot`` differs)."""
    return elementwise(_safe_hypot, a, b)


def _scaled_product_array(coefficient: float, factors):
    """The twin of ``numerics._scaled_product``: ``(mantissa, exponent, zero)`` arrays, ``zero``
    where a factor is 0 (the scalar returns ``None`` there)."""
    factors = [(np.asarray(value, dtype=float), power) for value, power in factors]
    shape = np.broadcast_shapes(*(value.shape for value, _ in factors))
    m0, e0 = math.frexp(coefficient)
    mantissa = np.full(shape, m0)
    exponent = np.full(shape, e0, dtype=np.int64)
    zero = np.zeros(shape, dtype=bool)
    for value, power in factors:
        zero |= value == 0.0
        m, e = np.frexp(value)
        if power == 1:
            mantissa = mantissa * m
        else:   # m ** power: libm's pow, as the scalar code calls it (np.power differs)
            safe = np.where(m == 0.0, 1.0, m).ravel().tolist()
            mantissa = mantissa * np.fromiter(map(pow, safe, [power] * len(safe)),
                                              dtype=float, count=len(safe)).reshape(shape)
        exponent = exponent + e.astype(np.int64) * power
        mantissa, e2 = np.frexp(mantissa)
        exponent = exponent + e2
    return mantissa, exponent, zero


def _ldexp(mantissa, exponent):
    with np.errstate(over="ignore", under="ignore"):
        return np.ldexp(mantissa, np.clip(exponent, -20000, 20000).astype(np.int32))


def monomial_array(coefficient: float, factors):
    """:func:`~dyncalc.physics.numerics.monomial` elementwise: ``coefficient * prod(x ** p)``
    from binary mantissas and exponents; ``factors`` is a list of ``(array, int power)``; a zero
    factor gives 0, a true result beyond float64 ``inf``.

    >>> monomial_array(3.0, [(np.array([1e200]), 1), (np.array([1e100]), -3)]).tolist()
    [3e-100]
    """
    mantissa, exponent, zero = _scaled_product_array(coefficient, factors)
    return np.where(zero, 0.0, _ldexp(mantissa, exponent))


def root_monomial_array(coefficient: float, factors):
    """:func:`~dyncalc.physics.numerics.root_monomial` elementwise: ``sqrt(coefficient *
    prod(x ** p))`` with the binary exponent halved exactly.

    >>> root_monomial_array(6.0, [(np.array([1e200, 1e200]), 1),
    ...                           (np.array([1e-100, 1e-200]), -3)]).tolist()  # sqrt(6e800)
    [2.4494897427831778e+250, inf]
    """
    mantissa, exponent, zero = _scaled_product_array(coefficient, factors)
    odd = (exponent % 2).astype(bool)
    mantissa = np.where(odd, 2.0 * mantissa, mantissa)
    exponent = exponent - odd
    return np.where(zero, 0.0, _ldexp(np.sqrt(mantissa), exponent // 2))


# double-double arithmetic on arrays (values hi + lo, |lo| <= ulp(hi)/2) -----------------------

def two_sum_array(a, b):
    """The twin of ``numerics._two_sum``: ``(s, e)`` with ``s = fl(a + b)``, ``a + b = s + e``
    exactly (Knuth)."""
    s = a + b
    back = s - a
    return s, (a - (s - back)) + (b - back)


def _split_array(a):
    c = 134217729.0 * a   # 2**27 + 1 (Veltkamp)
    hi = c - (c - a)
    return hi, a - hi


def two_product_array(a, b):
    """The twin of :func:`~dyncalc.physics.numerics.two_product` (Dekker): ``(p, e)`` with
    ``p = fl(a b)`` and ``a b = p + e`` exactly for magnitudes within about 1e-290..1e290."""
    with np.errstate(over="ignore", invalid="ignore"):
        p = a * b
        ah, al = _split_array(a)
        bh, bl = _split_array(b)
        return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _renormalise(hi, lo):
    s = hi + lo
    return s, lo - (s - hi)


def dd_mul(ah, al, bh, bl):
    """``(ah + al)(bh + bl)`` as a double-double, relative error below ``2^-104``."""
    p, e = two_product_array(ah, bh)
    return _renormalise(p, e + (ah * bl + al * bh))


def dd_div(ah, al, bh, bl):
    """``(ah + al) / (bh + bl)`` as a double-double, relative error below ``2^-103``."""
    q = ah / bh
    ph, pl = dd_mul(bh, bl, q, 0.0)
    sh, sl = two_sum_array(ah, -ph)
    return _renormalise(q, ((sh + (sl - pl + al)) / bh))


def dd_one_minus(ah, al):
    """``1 - (ah + al)`` as a double-double (exact but for the final renormalisation)."""
    s, e = two_sum_array(1.0, -ah)
    return _renormalise(s, e - al)


def round_certified(hi, lo, bound):
    """``(fl(hi + lo), certain)``: the float nearest ``hi + lo``, and where it is *certainly*
    the float nearest the exact value ``x`` the double-double approximates, given
    ``|hi + lo - x| <= bound |hi + lo|``: the interval around ``hi + lo`` holds no rounding
    boundary (a midpoint between floats). Where ``certain`` is False the caller leaves the row
    to the one-off code (a chance of about ``bound / 2^-53`` per row). Zero (exact) is certain;
    subnormal results are not (their spacing is not relative).
    """
    z = hi + lo
    residual = (hi - z) + lo                      # hi + lo - z, to a rounding of itself
    with np.errstate(invalid="ignore", over="ignore"):
        spacing = np.abs(z) - np.nextafter(np.abs(z), 0.0)   # the smaller of the two spacings
        room = 0.5 * spacing - np.abs(residual) - bound * np.abs(z) * 1.0000001
        certain = (np.isfinite(z) & (np.abs(z) >= 2.0 ** -1022) & (room > 0.0)) | (
            (hi == 0.0) & (lo == 0.0))
    return z, certain


def dd_add(ah, al, bh, bl):
    """``(ah + al) + (bh + bl)`` as a double-double: relative error below ``2^-104`` for
    operands of one sign; for opposite signs below ``2^-104`` of the larger operand."""
    s, e = two_sum_array(ah, bh)
    return _renormalise(s, e + (al + bl))


def dd_sqrt(ah, al):
    """``sqrt(ah + al)`` as a double-double (one Newton correction of the float root, its
    square formed exactly): relative error below ``2^-103``; 0 gives 0."""
    with np.errstate(divide="ignore", invalid="ignore"):
        s = np.sqrt(ah)
        p, e = two_product_array(s, s)
        correction = np.where(s > 0.0, (((ah - p) - e) + al) / (2.0 * s), 0.0)
    return _renormalise(s, correction)
