"""Array twins of the careful scalar kernels: the same float operations, elementwise on numpy
arrays, so that a column kernel (:mod:`dyncalc.physics.columns`) reproduces the one-off
function bit for bit.

Each twin names its scalar original and is tested for bitwise equality against it over random
inputs from 1e-300 to 1e300 (tests/test_numerics_arrays.py). numpy's elementwise ``+ - * /``,
``sqrt``, ``frexp`` and ``ldexp`` round as the scalar operations do (IEEE 754, no fused
multiply-add), so the twins only need to repeat the scalar steps in the same order; where the
scalar code branches, the twins compute both sides and select.
"""
from __future__ import annotations

from ..lazy import numpy as np

__all__ = ["two_sum_array", "two_product_array", "fsum_rows", "WideArray", "hypot_rows",
           "series_sum_rows", "parallel_sum_rows",
           "ldexp_array"]

#: Exponents beyond these make ``ldexp`` give 0 or inf whatever the mantissa (and fit int32).
_EXP_LIMIT = 1 << 20


def ldexp_array(m, e):
    """``m * 2**e`` elementwise as ``math.ldexp`` gives it (``inf`` where that raises
    OverflowError); ``e`` may be any integer array."""
    e = np.clip(np.asarray(e, dtype=np.int64), -_EXP_LIMIT, _EXP_LIMIT).astype(np.int32)
    with np.errstate(over="ignore", under="ignore"):
        return np.ldexp(m, e)


def two_sum_array(a, b):
    """``(s, e)``, ``s = fl(a + b)``, ``a + b = s + e`` exactly: the twin of
    ``numerics._two_sum`` (Knuth)."""
    s = a + b
    back = s - a
    return s, (a - (s - back)) + (b - back)


def _split(a):
    c = 134217729.0 * a
    hi = c - (c - a)
    return hi, a - hi


def two_product_array(a, b):
    """``(p, e)``, ``p = fl(a b)``, ``a b = p + e`` exactly: the twin of
    :func:`dyncalc.physics.numerics.two_product` (Dekker; the same range caveats)."""
    p = a * b
    ah, al = _split(a)
    bh, bl = _split(b)
    return p, ((ah * bh - p) + ah * bl + al * bh) + al * bl


def fsum_rows(terms):
    """``math.fsum`` of each row of ``terms`` (shape ``(n, k)``) -> ``(sums, ok)``.

    The twin of CPython's ``math.fsum``: the same partials (Shewchuk's non-overlapping
    expansion, built with the same swap-and-add steps; a zero stands where CPython drops a
    partial) and the same final rounding with its half-way correction, so the sum is the
    correctly rounded exact sum, bit for bit fsum's. ``ok`` is False on rows with a
    non-finite term or an intermediate overflow (where fsum returns inf/nan or raises).

    >>> s, ok = fsum_rows(np.array([[0.1, 0.2, 0.3], [1e100, 1.0, -1e100]]))
    >>> s.tolist(), ok.tolist()
    ([0.6, 1.0], [True, True])
    """
    t = np.asarray(terms, dtype=float)
    n, k = t.shape
    ok = np.all(np.isfinite(t), axis=1)
    parts = np.zeros((n, k))
    with np.errstate(over="ignore", invalid="ignore"):
        for j in range(k):
            x = t[:, j].copy()
            for i in range(j):
                y = parts[:, i]
                swap = np.abs(x) < np.abs(y)
                big, small = np.where(swap, y, x), np.where(swap, x, y)
                hi = big + small
                parts[:, i] = small - (hi - big)
                x = hi
            parts[:, j] = x
            ok &= np.isfinite(x)
        hi = np.zeros(n)
        lo = np.zeros(n)
        started = np.zeros(n, dtype=bool)
        done = np.zeros(n, dtype=bool)
        pending = np.zeros(n, dtype=bool)   # broke off; waiting for the next partial's sign
        below = np.zeros(n)                 # that sign's partial
        for i in range(k - 1, -1, -1):
            y = parts[:, i]
            nonzero = y != 0.0
            take = pending & nonzero
            below = np.where(take, y, below)
            pending &= ~take
            active = ~done & nonzero
            start = active & ~started
            going = active & started
            s = hi + y
            low = y - (s - hi)
            hi = np.where(start, y, np.where(going, s, hi))
            started |= start
            brk = going & (low != 0.0)
            lo = np.where(brk, low, lo)
            done |= brk
            pending |= brk
        same = ((lo < 0.0) & (below < 0.0)) | ((lo > 0.0) & (below > 0.0))
        y = lo * 2.0
        x = hi + y
        hi = np.where(same & (y == x - hi), x, hi)
    return hi + 0.0, ok


class WideArray:
    """Arrays of numbers ``m * 2**e`` with unbounded exponents: the twin of
    :class:`dyncalc.physics.numerics.Wide` (products, quotients and square roots round the
    mantissa exactly as it does; ``float(Wide)`` is :meth:`value`).

    >>> a = WideArray(np.array([1e300, 2.0]))
    >>> (a * a / WideArray(np.array([1e300, 4.0]))).value().tolist()
    [1e+300, 1.0]
    """

    __slots__ = ("m", "e")

    def __init__(self, value, exponent=0):
        m, e = np.frexp(np.asarray(value, dtype=float))
        self.m = m
        self.e = np.where(m != 0.0, e.astype(np.int64) + exponent, 0)

    def __mul__(self, other):
        other = other if isinstance(other, WideArray) else WideArray(other)
        return WideArray(self.m * other.m, self.e + other.e)

    def __truediv__(self, other):
        other = other if isinstance(other, WideArray) else WideArray(other)
        with np.errstate(divide="ignore", invalid="ignore"):
            return WideArray(self.m / other.m, self.e - other.e)

    def sqrt(self):
        odd = (self.e % 2) != 0
        m = np.where(odd, 2.0 * self.m, self.m)
        e = np.where(odd, self.e - 1, self.e)
        with np.errstate(invalid="ignore"):
            return WideArray(np.sqrt(m), e // 2)

    def value(self):
        """The floats (``inf`` beyond float64, as ``float(Wide)``)."""
        return ldexp_array(self.m, self.e)


def _dl_split(x):
    t = x * 134217729.0
    hi = t - (t - x)
    return hi, x - hi


def _dl_mul(x, y):
    """CPython's ``dl_mul`` (Dekker's mul12): ``x y = z + zz``."""
    xh, xl = _dl_split(x)
    yh, yl = _dl_split(y)
    p = xh * yh
    q = xh * yl + xl * yh
    z = p + q
    return z, ((p - z) + q) + xl * yl


def hypot_rows(*columns):
    """``math.hypot(*row)`` for the rows of the given columns -> ``(values, ok)``: the twin of
    CPython's ``vector_norm`` (scaled by a power of two, squares and sum carried exactly, one
    differential correction). ``ok`` is False where the twin may differ: a non-finite value,
    the largest below 2^-1000 (CPython rescales those first) or a non-zero element below
    2^-450 of the largest (its square leaves the exact range of the split).

    >>> v, ok = hypot_rows(np.array([3.0, 1e300]), np.array([4.0, 1e300]))
    >>> v.tolist()
    [5.0, 1.4142135623730952e+300]
    """
    cols = [np.abs(np.asarray(c, dtype=float)) for c in columns]
    top = cols[0]
    for c in cols[1:]:
        top = np.maximum(top, c)
    ok = np.isfinite(top) & ((top >= 2.0 ** -1000) | (top == 0.0))
    _, max_e = np.frexp(top)
    scale = ldexp_array(1.0, -max_e.astype(np.int64))
    csum = np.ones_like(top)
    frac1 = np.zeros_like(top)
    frac2 = np.zeros_like(top)
    with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
        for c in cols:
            x = c * scale
            ok &= (x == 0.0) | (x >= 2.0 ** -450)
            hi, lo = _dl_mul(x, x)
            s = csum + hi
            frac2 = frac2 + ((csum - s) + hi)
            csum = s
            frac1 = frac1 + lo
        h = np.sqrt(csum - 1.0 + (frac1 + frac2))
        hi, lo = _dl_mul(-h, h)
        s = csum + hi
        frac2 = frac2 + ((csum - s) + hi)
        csum = s
        frac1 = frac1 + lo
        x = csum - 1.0 + (frac1 + frac2)
        h = h + x / (2.0 * h)
        out = h / scale
    out = np.where(top == 0.0, 0.0, out) if len(cols) > 1 else top
    return out, ok


def _quotient_array(num, den_hi, den_lo):
    """The twin of ``numerics._quotient``: ``num / (den_hi + den_lo)`` with the first
    quotient's residual recovered exactly and corrected."""
    q = num / den_hi
    p, e = two_product_array(q, den_hi)
    return q + (((num - p) - e) - q * den_lo) / den_hi


def series_sum_rows(values):
    """:func:`dyncalc.physics.numerics.series_sum` of each row of ``values`` (shape
    ``(n, k)``, positive) -> ``(sums, ok)``: the same ratios to the smallest finite element
    with their exact residuals, the same two fsums (:func:`fsum_rows`) and the same corrected
    division. Infinite elements add nothing; a row of infinities gives ``inf``. ``ok`` is
    False where an fsum overflowed.

    >>> s, ok = series_sum_rows(np.array([[200.0, 300.0], [1e-320, 1.0]]))
    >>> s.tolist()
    [120.0, 1e-320]
    """
    k = np.asarray(values, dtype=float)
    n, count = k.shape
    finite = np.isfinite(k)
    smallest = np.min(np.where(finite, k, np.inf), axis=1)
    safe = np.where(finite, k, 1.0)
    m, e = np.frexp(safe)
    with np.errstate(over="ignore", under="ignore", invalid="ignore", divide="ignore"):
        a = ldexp_array(np.where(np.isfinite(smallest), smallest, 1.0)[:, None],
                        -e.astype(np.int64))
        r = a / m
        p, pe = two_product_array(r, m)
        residual = ((a - p) - pe) / m
        terms = np.empty((n, 2 * count))
        terms[:, 0::2] = np.where(finite, r, 0.0)
        terms[:, 1::2] = np.where(finite, residual, 0.0)
        total, ok = fsum_rows(terms)
        low, ok_low = fsum_rows(np.concatenate([terms, -total[:, None]], axis=1))
        ms, es = np.frexp(np.where(np.isfinite(smallest), smallest, 1.0))
        out = ldexp_array(_quotient_array(ms, total, low), es.astype(np.int64))
    out = np.where(np.isfinite(smallest), out, np.inf)
    out = np.where(smallest == 0.0, 0.0, out)
    return out, ok & ok_low


def parallel_sum_rows(values):
    """:func:`dyncalc.physics.numerics.parallel_sum` of each row -> ``(sums, ok)``: fsum
    (:func:`fsum_rows`), ``inf`` where an element is infinite or the sum overflows (where
    fsum raises and the one-off gives ``inf`` too); ``ok`` is False only on rows with NaN."""
    k = np.asarray(values, dtype=float)
    rigid = np.any(np.isinf(k), axis=1)
    total, summed = fsum_rows(np.where(np.isinf(k), 0.0, k))
    return np.where(rigid | ~summed, np.inf, total), ~np.any(np.isnan(k), axis=1)
