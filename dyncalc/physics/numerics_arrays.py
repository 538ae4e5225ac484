"""Array twins of the scalar kernels of :mod:`~dyncalc.physics.numerics`, for column kernels.

Each twin runs the same floating-point operations, in the same order, on whole float64 numpy
arrays, so every element is *bit for bit* what the scalar kernel gives for it
(tests/test_numerics_arrays.py compares them over random inputs from 1e-300 to 1e300):

* :func:`pow_array` twins Python's ``x ** p`` (the C library's ``pow``, which numpy's own
  ``power`` does not reproduce);
* :func:`monomial_array` and :func:`root_monomial_array` twin
  :func:`~dyncalc.physics.numerics.monomial` and
  :func:`~dyncalc.physics.numerics.root_monomial`;
* :class:`WideArray` twins :class:`~dyncalc.physics.numerics.Wide`;
* :func:`two_product_array`, :func:`fsum_rows` (CPython's ``math.fsum``),
  :func:`hypot_rows` (CPython's ``math.hypot``), :func:`series_sum_rows` and
  :func:`parallel_sum_rows` twin their namesakes, row by row.

numpy is imported lazily (``from ..lazy import numpy as np``).

The twins of the second part (rotating, damping, nonlinear, coupled) call libm's
function row by row where numpy's own may round differently (:func:`elementwise`), and
double-double helpers (``dd_*``, :func:`round_certified`) certify a correctly rounded result
(tests/test_numerics_arrays_b.py).
"""
from __future__ import annotations

import math

from ..lazy import numpy as np

__all__ = ["pow_array", "monomial_array", "root_monomial_array", "WideArray", "elementwise",
           "hypot_array", "two_sum_array", "two_product_array", "round_certified", "fsum_rows",
           "hypot_rows", "series_sum_rows", "parallel_sum_rows", "ldexp_array"]

#: How close (in ulp of the result) to a rounding midpoint a product or quotient may come
#: before :func:`pow_array` asks the C library's ``pow`` itself: glibc's ``pow`` is within
#: 0.52 ulp, not 0.5, and rounds differently from ``x * x`` or ``1 / x`` only there (the
#: largest gap measured on 3 million mantissas is 0.0065 ulp; this band is eight times that).
POW_BAND = 0.05


def pow_array(x, power: int):
    """``x ** power`` elementwise, bit for bit as Python computes it for each float (the C
    library's ``pow``), for mantissas ``0.5 <= x < 1`` (``math.frexp``'s) and any integer
    power.

    ``pow`` is not correctly rounded: for ``power = 2`` it differs from ``x * x`` (and for
    ``-1`` from ``1 / x``) on about one mantissa in a thousand, where the exact result lies
    within a few thousandths of an ulp of a rounding midpoint; numpy's ``power`` (vectorised
    differently) differs on one in twenty. So ``x * x`` and ``1 / x`` are taken where the exact
    value, recovered with Dekker's product, lies further than :data:`POW_BAND` ulp from a
    midpoint (where any result within 0.52 ulp rounds the same way), and Python's ``**`` is
    called on the few elements left (about one in ten), as it is for the other powers.
    ``power = 1`` is ``x`` itself (``pow`` is exact where the result is representable).

    >>> pow_array(np.array([0.75, 0.5]), 2).tolist()
    [0.5625, 0.25]
    """
    x = np.asarray(x, dtype=float)
    if power == 1:
        return x.copy()
    with np.errstate(all="ignore"):
        if power == 2:
            out = x * x
            _, err = two_product_array(x, x)
            distance = np.abs(err / np.spacing(out))        # the exact value: out + err
        elif power == -1:
            out = 1.0 / x
            high, low = two_product_array(out, x)
            distance = np.abs(((1.0 - high) - low) / x / np.spacing(out))   # 1/x - out
        else:
            return np.array([value ** power for value in x.tolist()], dtype=float)
        near = ~(np.abs(distance - 0.5) > POW_BAND)          # (NaN: near, the safe side)
    index = np.flatnonzero(near)
    if index.size:
        out[index] = [value ** power for value in x[index].tolist()]
    return out


# --- libm row by row (rotating, damping, nonlinear, coupled) ---

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
    """(mantissa, exponent, zero) arrays of ``coefficient * prod(x ** p)``: the steps of
    :func:`numerics._scaled_product`, ``zero`` marking the elements with a zero factor (where
    the scalar returns ``None``)."""
    m0, e0 = math.frexp(coefficient)
    mantissa, exponent, zero = None, None, None
    for value, power in factors:
        value = np.asarray(value, dtype=float)
        if mantissa is None:
            mantissa = np.full(value.shape, m0)
            exponent = np.full(value.shape, e0, dtype=np.int64)
            zero = np.zeros(value.shape, dtype=bool)
        here = value == 0.0
        zero |= here
        m, e = np.frexp(value)
        mantissa = mantissa * pow_array(np.where(here, 0.5, m), power)  # (0 ** -1 raises)
        exponent = exponent + e.astype(np.int64) * power
        mantissa, e2 = np.frexp(mantissa)
        exponent = exponent + e2
    return mantissa, exponent, zero


def _ldexp(mantissa, exponent):
    """``math.ldexp`` elementwise, ``inf`` where it would raise OverflowError."""
    exponent = np.clip(exponent, -4000, 4000)       # beyond, the result is 0 or inf anyway
    with np.errstate(over="ignore", under="ignore"):
        return np.ldexp(mantissa, exponent.astype(np.int32))


def monomial_array(coefficient: float, factors):
    """:func:`~dyncalc.physics.numerics.monomial` elementwise (``factors``: ``(array,
    power)`` pairs, the arrays of one length), bit for bit the scalar's result.

    >>> monomial_array(3.0, [(np.array([1e200, 2e11]), 1), (np.array([1e100, 2.0]), -3)]).tolist()
    [3e-100, 75000000000.0]
    """
    mantissa, exponent, zero = _scaled_product_array(coefficient, factors)
    return np.where(zero, 0.0, _ldexp(mantissa, exponent))


def root_monomial_array(coefficient: float, factors):
    """:func:`~dyncalc.physics.numerics.root_monomial` elementwise, bit for bit: the exponent
    halved exactly before one square root of the mantissa.

    >>> k, m = np.array([8e200, 4.0, 1e300]), np.array([1e-200, 1.0, 1e-300])
    >>> root_monomial_array(2.0, [(k, 1), (m, -1)]).tolist()   # 2e600 would overflow midway
    [4e+200, 2.8284271247461903, 1.414213562373095e+300]
    """
    mantissa, exponent, zero = _scaled_product_array(coefficient, factors)
    odd = (exponent % 2).astype(bool)
    mantissa = np.where(odd, 2.0 * mantissa, mantissa)
    exponent = exponent - odd
    return np.where(zero, 0.0, _ldexp(np.sqrt(mantissa), exponent // 2))


class WideArray:
    """:class:`~dyncalc.physics.numerics.Wide` elementwise: arrays ``m`` (the mantissas, in
    [0.5, 1) or 0) and ``e`` (int64 binary exponents), ``value = m * 2**e``.

    Every operation is Wide's, on arrays: ``np.frexp`` for ``math.frexp``, the mantissas
    multiplied, divided or (aligned by ``np.ldexp`` to the larger exponent) added with one
    float rounding, the exponents added exactly, the zero rules of ``Wide.__add__`` (a zero
    term returns the other one unchanged) and of its constructor (zero has exponent 0). So an
    expression written with WideArray operands in the order the scalar formula is written
    gives, element by element, the scalar result's bits (also for the ``inf`` and ``nan`` that
    a zero divisor makes, where the scalar raises). A float or a float array operand is
    converted as ``Wide(x)`` is.

    >>> w = (WideArray(np.array([1e200])) * 1e200 + WideArray(np.array([1e300])) * 1e100)
    >>> (w / 1e300).to_float().tolist()
    [2e+100]
    """

    __slots__ = ("m", "e")
    __array_ufunc__ = None      # ``array * WideArray`` defers to WideArray.__rmul__, as Wide

    def __init__(self, value=0.0, exponent=0):
        m, e = np.frexp(np.asarray(value, dtype=float))
        self.m = m
        self.e = np.where(m != 0.0, e.astype(np.int64) + exponent, 0)

    @staticmethod
    def _of(other) -> "WideArray":
        return other if isinstance(other, WideArray) else WideArray(other)

    def __mul__(self, other) -> "WideArray":
        other = self._of(other)
        return WideArray(self.m * other.m, self.e + other.e)

    __rmul__ = __mul__

    def __truediv__(self, other) -> "WideArray":
        other = self._of(other)
        with np.errstate(divide="ignore", invalid="ignore"):
            return WideArray(self.m / other.m, self.e - other.e)

    def __add__(self, other) -> "WideArray":
        other = self._of(other)
        top = np.maximum(self.e, other.e)
        total = WideArray(_ldexp(self.m, self.e - top) + _ldexp(other.m, other.e - top), top)
        keep_self = other.m == 0.0
        keep_other = (self.m == 0.0) & ~keep_self
        result = WideArray.__new__(WideArray)
        result.m = np.where(keep_self, self.m, np.where(keep_other, other.m, total.m))
        result.e = np.where(keep_self, self.e, np.where(keep_other, other.e, total.e))
        return result

    __radd__ = __add__

    def sqrt(self) -> "WideArray":
        odd = (self.e % 2).astype(bool)
        with np.errstate(invalid="ignore"):
            root = np.sqrt(np.where(odd, 2.0 * self.m, self.m))
        return WideArray(root, (self.e - odd) // 2)

    def to_float(self):
        """``float(Wide)`` elementwise: ``m * 2**e``, ``inf`` beyond float64."""
        return _ldexp(self.m, self.e)


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


# --- sums, products and norms, for the spring, damping and frame kernels ---------------------

#: Exponents beyond these make ``ldexp`` give 0 or inf whatever the mantissa (and fit int32).
_EXP_LIMIT = 1 << 20


def ldexp_array(m, e):
    """``m * 2**e`` elementwise as ``math.ldexp`` gives it (``inf`` where that raises
    OverflowError); ``e`` may be any integer array."""
    e = np.clip(np.asarray(e, dtype=np.int64), -_EXP_LIMIT, _EXP_LIMIT).astype(np.int32)
    with np.errstate(over="ignore", under="ignore"):
        return np.ldexp(m, e)


#: Terms below this in size cannot overflow in a row of up to 2^20 of them, whatever the order.
_FSUM_SAFE = 2.0 ** 1000


def fsum_rows(terms):
    """``math.fsum`` of each row of ``terms`` (shape ``(n, k)``) -> ``(sums, ok)``.

    The twin of CPython's ``math.fsum``: the same partials (Shewchuk's non-overlapping
    expansion, built with the same swap-and-add steps; a zero stands where CPython drops a
    partial) and the same final rounding with its half-way correction, so the sum is the
    correctly rounded exact sum, bit for bit fsum's. ``ok`` is False on rows with a
    non-finite term or an intermediate overflow (where fsum returns inf/nan or raises).

    Most rows take a cheaper road to the same bits: the terms are added in order with
    Knuth's TwoSum and their rounding errors summed with TwoSum too, the bits that sum loses
    kept as ``lost``; the total plus the errors, rounded once, is ``r``. Where nothing was
    lost, ``r`` is the exact sum rounded once, half-way cases to even: fsum's result. Else
    the exact sum is within ``|residual| + lost`` of ``r`` (``residual`` the exact error of
    that last addition), and where that is below half the smaller spacing of floats at
    ``r``, ``r`` is still the correctly rounded sum. The other rows (near a half-way point
    with bits lost, huge or non-finite terms) take the twin described above.

    >>> s, ok = fsum_rows(np.array([[0.1, 0.2, 0.3], [1e100, 1.0, -1e100]]))
    >>> s.tolist(), ok.tolist()
    ([0.6, 1.0], [True, True])
    """
    t = np.asarray(terms, dtype=float)
    n, k = t.shape
    if k == 0 or n == 0:
        return _fsum_rows_twin(t)
    with np.errstate(over="ignore", invalid="ignore"):
        total = t[:, 0].copy()
        errors = np.zeros(n)
        lost = np.zeros(n)
        largest = np.abs(total)
        for j in range(1, k):
            x = t[:, j]
            np.maximum(largest, np.abs(x), out=largest)
            hi = total + x
            back = hi - total
            error = (total - (hi - back)) + (x - back)
            total = hi
            hi = errors + error
            back = hi - errors
            lost += np.abs((errors - (hi - back)) + (error - back))
            errors = hi
        r = total + errors
        back = r - total
        residual = (total - (r - back)) + (errors - back)
        size = np.abs(r)
        below = (size.view(np.int64) - 1).view(np.float64)  # the float under size (NaN at 0)
        bound = np.abs(residual) + lost * (1.0 + 2.0 ** -40)
        sure = ((lost == 0.0) | (bound < 0.5 * (size - below))) & np.isfinite(r) \
            & (largest < _FSUM_SAFE)
    if sure.all():
        return r + 0.0, np.ones(n, dtype=bool)
    ok = np.ones(n, dtype=bool)
    rest = np.flatnonzero(~sure)
    r[rest], ok[rest] = _fsum_rows_twin(t[rest])
    return r + 0.0, ok


def _fsum_rows_twin(t):
    """:func:`fsum_rows` by CPython's own steps (partials, then the rounding with its
    half-way correction), for any rows."""
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
