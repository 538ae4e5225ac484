"""Numerically careful kernels, on plain floats and numpy arrays.

Each kernel is named for the trap it avoids and is tested on its own against mpmath
(tests/test_numerics.py). The physics modules call these instead of writing the naive formula.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["series_sum", "parallel_sum", "monomial", "two_product"]


def two_product(a: float, b: float) -> tuple[float, float]:
    """``(p, e)`` with ``p = fl(a*b)`` and ``a*b = p + e`` exactly (Dekker's algorithm).

    Exact when neither ``a*b`` nor the split of ``a`` and ``b`` overflows or underflows, which
    holds for magnitudes between about 1e-290 and 1e290; callers scale by powers of two.

    >>> two_product(0.1, 3.0)
    (0.30000000000000004, -2.7755575615628914e-17)
    """
    p = a * b
    ah, al = _split(a)
    bh, bl = _split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _split(a: float) -> tuple[float, float]:
    c = 134217729.0 * a  # 2**27 + 1 (Veltkamp)
    hi = c - (c - a)
    return hi, a - hi


def _quotient(num: float, den_hi: float, den_lo: float) -> float:
    """``num / (den_hi + den_lo)`` rounded once more than correctly, for 0.5 <= num < 1 and
    1 <= den_hi: the first quotient's residual is recovered exactly and corrected."""
    q = num / den_hi
    p, e = two_product(q, den_hi)
    return q + (((num - p) - e) - q * den_lo) / den_hi


def series_sum(values) -> float:
    """Reciprocal of the sum of reciprocals, scaled by the smallest element.

    .. math:: k = \\left(\\sum_i 1/k_i\\right)^{-1} = k_{min} / \\sum_i (k_{min}/k_i)

    Every ratio lies in (0, 1] and the sum in [1, n], so nothing overflows or underflows on the
    way even when the elements span 1e-320 to 1e308 (the naive ``1/sum(1/k)`` gives inf or 0
    there). Each ratio is carried with its exact rounding residual (:func:`two_product`), the
    sum is taken exactly (``math.fsum``) as a double-double, and the final division is
    corrected the same way: the result is within 1 ulp of the true value and exact where that
    is representable (200 and 300 in series give 120, not 120.00000000000001). Infinite
    elements (rigid links) add nothing; if every element is infinite the result is infinite.

    Parameters
    ----------
    values : sequence of float
        Positive elements (zero and negatives are the caller's to refuse).

    Examples
    --------
    >>> series_sum([200.0, 300.0])
    120.0
    >>> series_sum([1e-320, 1.0])
    1e-320
    >>> series_sum([1e308, 1e308])
    5e+307
    """
    arr = np.asarray(values, dtype=float)
    finite = arr[np.isfinite(arr)].tolist()
    if not finite:
        return math.inf
    smallest = min(finite)
    terms = []
    for k in finite:
        m, e = math.frexp(k)             # k = m 2**e, 0.5 <= m < 1
        a = math.ldexp(smallest, -e)     # smallest / 2**e <= 1 (exact unless negligible)
        r = a / m
        p, pe = two_product(r, m)
        terms += [r, ((a - p) - pe) / m]  # a - r m is exact (Sterbenz)
    total = math.fsum(terms)
    low = math.fsum(terms + [-total])
    m, e = math.frexp(smallest)
    return math.ldexp(_quotient(m, total, low), e)


def parallel_sum(values) -> float:
    """Sum of positive elements, correctly rounded; ``inf`` if it overflows or any is infinite.

    >>> parallel_sum([0.1, 0.2, 0.3])
    0.6
    """
    arr = np.asarray(values, dtype=float)
    if np.any(np.isinf(arr)):
        return math.inf
    try:
        return math.fsum(arr.tolist())
    except OverflowError:
        return math.inf


def monomial(coefficient: float, factors) -> float:
    """``coefficient * prod(x ** p)`` for small integer powers, without intermediate overflow.

    Each factor is split into mantissa and binary exponent (``math.frexp``); mantissas are
    multiplied, exponents added, and the result is assembled once at the end. So
    ``3 * E * I / l**3`` with ``l = 1e-120`` gives the right finite answer instead of dividing
    by an underflowed zero. The result is ``inf`` only when the true result overflows, and it
    underflows gradually only when the true result is below 2.2e-308.

    Parameters
    ----------
    coefficient : float
        A positive constant (3 for a cantilever, 48 for a midspan load, 1/8 for a coil).
    factors : iterable of (float, int)
        Positive finite values with integer powers, e.g. ``[(E, 1), (I, 1), (l, -3)]``.

    Examples
    --------
    >>> monomial(3.0, [(2e11, 1), (1e-6, 1), (2.0, -3)])
    75000.0
    >>> monomial(3.0, [(1e200, 1), (1e200, 1), (1e100, -3)])  # naive: inf * 1e-300
    3e+100
    >>> monomial(1.0, [(1e-120, -3)])  # the true result, 1e360, overflows
    inf
    """
    mantissa, exponent = math.frexp(coefficient)
    for value, power in factors:
        m, e = math.frexp(value)
        mantissa *= m ** power
        exponent += e * power
        mantissa, e2 = math.frexp(mantissa)
        exponent += e2
    try:
        return math.ldexp(mantissa, exponent)
    except OverflowError:
        return math.inf
