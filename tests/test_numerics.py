"""The careful kernels of dyncalc.physics.numerics, each against mpmath at 40 digits."""
import math
import random

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncalc.physics.numerics import (Wide, agm, root_monomial, sqrt_ratio, two_product)

TINY, HUGE = mpmath.mpf("2.2250738585072014e-308"), mpmath.mpf("1.7976931348623157e308")


def ulps(got, ref):
    return float(abs(mpmath.mpf(got) - ref) / mpmath.mpf(math.ulp(float(ref))))


def log_uniform(rnd, low=-300, high=300):
    return 10 ** rnd.uniform(low, high)


@settings(max_examples=500, deadline=None)
@given(st.floats(min_value=-1e290, max_value=1e290, allow_nan=False),
       st.floats(min_value=-1e10, max_value=1e10, allow_nan=False))
def test_two_product_is_exact(a, b):
    p, e = two_product(a, b)
    if abs(a * b) > 1e-290 or a == 0 or b == 0:  # no underflow in the product
        assert mpmath.mpf(p) + mpmath.mpf(e) == mpmath.mpf(a) * mpmath.mpf(b)


def test_sqrt_ratio_within_one_ulp_across_the_range():
    rnd = random.Random(11)
    worst = 0.0
    for _ in range(5000):
        a, b = log_uniform(rnd), log_uniform(rnd)
        ref = mpmath.sqrt(mpmath.mpf(a) / mpmath.mpf(b))
        if TINY < ref < HUGE:
            worst = max(worst, ulps(sqrt_ratio(a, b), ref))
    assert worst <= 1.0, f"worst {worst:.2f} ulp"


def test_sqrt_ratio_overflow_and_subnormal_inputs():
    assert sqrt_ratio(1e308, 5e-324) == math.inf
    assert sqrt_ratio(5e-324, 1.0) == pytest.approx(math.sqrt(5e-324), rel=1e-15)


def test_root_monomial_within_two_ulp():
    rnd = random.Random(12)
    worst = 0.0
    for _ in range(3000):
        factors = [(log_uniform(rnd, -100, 100), rnd.choice([-3, -2, -1, 1, 2, 3]))
                   for _ in range(rnd.randint(1, 4))]
        c = rnd.choice([0.5, 1.0, 1.5, 6.0])
        ref = mpmath.mpf(c)
        for x, p in factors:
            ref *= mpmath.mpf(x) ** p
        ref = mpmath.sqrt(ref)
        if TINY < ref < HUGE:
            worst = max(worst, ulps(root_monomial(c, factors), ref))
    assert worst <= 2.0, f"worst {worst:.2f} ulp"


def test_wide_keeps_products_and_sums_in_range():
    rnd = random.Random(13)
    for _ in range(2000):
        a, b, c, d = (log_uniform(rnd, -250, 250) for _ in range(4))
        got = float((Wide(a) * Wide(b) + Wide(c) * Wide(d)) / (Wide(a) + Wide(c)))
        ref = ((mpmath.mpf(a) * b + mpmath.mpf(c) * d) / (mpmath.mpf(a) + c))
        if TINY < ref < HUGE:
            assert ulps(got, ref) <= 4.0


def test_agm_against_mpmath():
    rnd = random.Random(14)
    for _ in range(2000):
        b = rnd.choice([rnd.random(), log_uniform(rnd, -300, 0)])
        assert ulps(agm(1.0, b), mpmath.agm(1, mpmath.mpf(b))) <= 4.0  # the project's goal


def test_agm_terminates_at_the_extremes():
    assert agm(1.0, 5e-324) == pytest.approx(float(mpmath.agm(1, mpmath.mpf(5e-324))),
                                             rel=1e-15)
    assert agm(1.0, 0.0) == 0.0
    assert agm(2.0, 2.0) == 2.0
