"""Numerically careful kernels, on plain floats and numpy arrays.

Each kernel is named for the trap it avoids and is tested on its own against mpmath
(tests/test_numerics.py). The physics modules call these instead of writing the naive formula.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["series_sum", "parallel_sum", "monomial", "two_product", "agm", "half_complement_sin",
           "pendulum_period_factor", "sqrt_ratio", "root_monomial", "Wide"]


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


def sqrt_ratio(a: float, b: float) -> float:
    """``sqrt(a / b)`` for positive finite ``a``, ``b``, with no overflow or underflow midway.

    The binary exponents are split off first (``math.frexp``) and halved exactly, so only the
    mantissa quotient and its square root are rounded (within about 1 ulp, as
    ``sqrt(a/b)``), while ``a/b`` itself may lie far outside float64: ``1e300 / 1e-300``.

    >>> sqrt_ratio(100.0, 2.0)
    7.0710678118654755
    >>> sqrt_ratio(1e300, 1e-300)
    1e+300
    >>> sqrt_ratio(1e308, 5e-324)  # 4.5e315 overflows: inf, for the caller to refuse
    inf
    """
    ma, ea = math.frexp(a)
    mb, eb = math.frexp(b)
    shift = ea - eb
    if shift % 2:
        ma *= 2.0
        shift -= 1
    try:
        return math.ldexp(math.sqrt(ma / mb), shift // 2)
    except OverflowError:  # the true result is above 1.8e308
        return math.inf


class Wide:
    """A positive (or zero) number ``mantissa * 2**exponent`` with an unbounded exponent.

    The mantissa is kept in [0.5, 1) (or is 0); products, quotients and sums round the
    mantissa once, as a float operation would, and never overflow or underflow. Sums align
    the smaller term to the larger exponent, so a term below 2**-1074 of the other is dropped,
    as float addition would round it away. Used where a formula is a ratio of sums of products
    of the inputs (the rigid-body scenes); :func:`monomial` is the product-only special case.

    >>> float((Wide(1e200) * Wide(1e200) + Wide(1e300) * Wide(1e100)) / Wide(1e300))
    2e+100
    >>> float(Wide(1e-300).sqrt() * Wide(1e-300).sqrt())
    1e-300
    """

    __slots__ = ("m", "e")

    def __init__(self, value: float = 0.0, exponent: int = 0):
        m, e = math.frexp(value)
        self.m, self.e = m, (e + exponent if m else 0)

    def __mul__(self, other):
        other = other if isinstance(other, Wide) else Wide(other)
        return Wide(self.m * other.m, self.e + other.e)

    __rmul__ = __mul__

    def __truediv__(self, other):
        other = other if isinstance(other, Wide) else Wide(other)
        return Wide(self.m / other.m, self.e - other.e)

    def __add__(self, other):
        other = other if isinstance(other, Wide) else Wide(other)
        if not other.m:
            return self
        if not self.m:
            return other
        top = max(self.e, other.e)
        return Wide(math.ldexp(self.m, self.e - top) + math.ldexp(other.m, other.e - top),
                     top)

    __radd__ = __add__

    def sqrt(self) -> Wide:
        m, e = self.m, self.e
        if e % 2:
            m, e = 2.0 * m, e - 1
        return Wide(math.sqrt(m), e // 2)

    def __float__(self) -> float:
        try:
            return math.ldexp(self.m, self.e)
        except OverflowError:
            return math.inf


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


def _scaled_product(coefficient: float, factors) -> tuple[float, int] | None:
    """``coefficient * prod(x ** p)`` as (mantissa, binary exponent), or ``None`` if it is 0."""
    mantissa, exponent = math.frexp(coefficient)
    for value, power in factors:
        if value == 0.0:
            return None
        m, e = math.frexp(value)
        mantissa *= m ** power
        exponent += e * power
        mantissa, e2 = math.frexp(mantissa)
        exponent += e2
    return mantissa, exponent


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
        Non-negative finite values with integer powers, e.g. ``[(E, 1), (I, 1), (l, -3)]``.

    Examples
    --------
    >>> monomial(3.0, [(2e11, 1), (1e-6, 1), (2.0, -3)])
    75000.0
    >>> monomial(3.0, [(1e200, 1), (1e200, 1), (1e100, -3)])  # naive: inf * 1e-300
    3e+100
    >>> monomial(1.0, [(1e-120, -3)])  # the true result, 1e360, overflows
    inf
    """
    scaled = _scaled_product(coefficient, factors)
    if scaled is None:
        return 0.0
    try:
        return math.ldexp(*scaled)
    except OverflowError:
        return math.inf


def root_monomial(coefficient: float, factors) -> float:
    """``sqrt(coefficient * prod(x ** p))`` with no overflow or underflow on the way.

    :func:`monomial` with the binary exponent halved exactly before the result is assembled:
    only the mantissas are rounded, and the result is ``inf`` only when the true root
    overflows (a frequency ``sqrt(k/m)`` from ``k = 1e300``, ``m = 1e-300`` is fine although
    ``k/m`` is not). A zero factor gives zero.

    >>> root_monomial(6.0, [(1e200, 1), (1e200, 2), (1e-100, -3)])  # sqrt(6e900) overflows
    inf
    >>> root_monomial(8.0, [(1e200, 3), (1e100, 2), (1e300, -1), (1e-10, -2)])  # sqrt(8e520)
    2.82842712474619e+260
    """
    scaled = _scaled_product(coefficient, factors)
    if scaled is None:
        return 0.0
    mantissa, exponent = scaled
    if exponent % 2:
        mantissa, exponent = 2.0 * mantissa, exponent - 1
    try:
        return math.ldexp(math.sqrt(mantissa), exponent // 2)
    except OverflowError:
        return math.inf


# --- large-amplitude pendulum ----------------------------------------------------------------

#: pi as a double-double: PI_HI + PI_LO is pi to about 32 digits.
PI_HI = math.pi
PI_LO = 1.2246467991473532e-16

#: Half a turn in angle units whose value for it is exact, so that 180 deg - theta (or
#: 200 grad - theta) is computed without rounding. Radians use the double-double pi.
HALF_TURN = {"degree": 180.0, "grade": 200.0, "arcminute": 10800.0, "arcsecond": 648000.0,
             "turn": 0.5}


def agm(a: float, b: float) -> float:
    """Arithmetic-geometric mean of two non-negative numbers.

    Iterates ``a, b = (a + b)/2, sqrt(a b)`` until the two agree to the last bit; converges
    quadratically (at most about 6 steps for ``b/a`` down to 1e-300, since the count grows like
    ``log2(log(a/b))``). Stable: every step is a mean of positive numbers.

    >>> agm(1.0, 1.0)
    1.0
    >>> agm(1.0, 2 ** -0.5)  # 1/G with G Gauss's constant, 0.84721308479397908...
    0.8472130847939792
    """
    if a < b:
        a, b = b, a
    if b == 0.0:
        return 0.0
    for _ in range(64):
        if a - b <= 2.0 * math.ulp(a):
            break
        a, b = 0.5 * (a + b), math.sqrt(a * b)
    return 0.5 * (a + b)


def half_complement_sin(amplitude: float, unit: str) -> float:
    """``cos(theta/2)`` computed as ``sin((half turn - theta)/2)`` in the unit typed.

    For an amplitude a hair below half a turn, ``cos(theta/2)`` is tiny and converting
    ``179.999 deg`` to radians first loses most of its digits (the rounding of ``theta`` in
    radians is ~1e-16 absolute, against a complement of ~1e-5). In degrees (grads, arcminutes,
    turns) the complement ``180 - theta`` is exact (Sterbenz), and in radians it is taken
    against the double-double ``pi``. Then only a relative rounding or two remain.

    Parameters
    ----------
    amplitude : float
        The amplitude in ``unit``, between 0 and half a turn.
    unit : str
        pint's name of the unit (``"degree"``, ``"radian"``, ...); others go through radians.

    >>> half_complement_sin(90.0, "degree")  # sin(pi/4) = 0.70710678118654752...
    0.7071067811865475
    >>> half_complement_sin(179.999, "degree")  # mpmath: 8.72664625990255427e-6
    8.726646259902554e-06
    >>> math.cos(math.radians(179.999) / 2)      # the naive form: wrong from the 10th digit
    8.726646260010393e-06
    """
    if unit in HALF_TURN:
        complement = HALF_TURN[unit] - amplitude
        radians = complement * (math.pi / HALF_TURN[unit])
    else:
        radians = (PI_HI - amplitude) + PI_LO
    return math.sin(0.5 * radians)


def pendulum_period_factor(cos_half: float) -> float:
    """``T / T0`` of a pendulum of amplitude theta from ``cos(theta/2)``: ``1 / AGM(1, cos)``.

    The exact period is ``T = 4 K(sin(theta/2)) / omega0 = 2 pi / (omega0 AGM(1, cos(theta/2)))``
    with ``K`` the complete elliptic integral of the first kind.

    >>> pendulum_period_factor(1.0)
    1.0
    """
    return 1.0 / agm(1.0, cos_half)
