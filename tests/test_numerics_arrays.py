"""The array twins (dyncalc.physics.numerics_arrays) against their scalar originals, bit for
bit, over random inputs from 1e-300 to 1e300, near cancellations and half-way ties."""
from __future__ import annotations

import math

import numpy as np
import pytest

from dyncalc.physics.numerics import Wide, parallel_sum, series_sum, two_product
from dyncalc.physics.numerics_arrays import (WideArray, fsum_rows, hypot_rows,
                                             parallel_sum_rows, series_sum_rows,
                                             two_product_array)

RNG = np.random.default_rng(7)


def _bits(a):
    return np.asarray(a, dtype=float).view(np.int64)


def _wide(rng, shape, low=-300, high=300):
    return 10.0 ** rng.uniform(low, high, shape) * rng.choice([-1.0, 1.0], shape)


@pytest.mark.parametrize("k", [1, 2, 3, 4, 7])
def test_fsum_rows_is_math_fsum(k):
    n = 4000
    t = _wide(RNG, (n, k))
    t[: n // 2] = RNG.uniform(0.5, 2.0, (n // 2, k)) * RNG.choice([-1.0, 1.0], (n // 2, k)) \
        * 2.0 ** RNG.integers(-60, 60, (n // 2, k))            # heavy cancellation
    t[: n // 8, 0] = 1.0                                       # half-way ties
    if k > 1:
        t[: n // 8, 1] = 2.0 ** -53 * RNG.choice([-1.0, 1.0, 3.0], n // 8)
    if k > 2:
        t[: n // 8, 2] = 2.0 ** -140 * RNG.choice([-1.0, 1.0], n // 8)
    s, ok = fsum_rows(t)
    assert ok.all()
    assert np.array_equal(_bits(s), _bits([math.fsum(row) for row in t.tolist()]))


def test_fsum_rows_flags_an_intermediate_overflow():
    s, ok = fsum_rows(np.array([[1.7e308, 1.7e308, -1.7e308], [1.0, np.inf, 0.0]]))
    assert ok.tolist() == [False, False]
    with pytest.raises(OverflowError):
        math.fsum([1.7e308, 1.7e308, -1.7e308])


def test_two_product_array_is_two_product():
    a, b = _wide(RNG, 5000, -140, 140), _wide(RNG, 5000, -140, 140)
    p, e = two_product_array(a, b)
    ref = [two_product(x, y) for x, y in zip(a.tolist(), b.tolist())]
    assert np.array_equal(_bits(p), _bits([r[0] for r in ref]))
    assert np.array_equal(_bits(e), _bits([r[1] for r in ref]))


def test_wide_array_is_wide():
    a, b, c = (np.abs(_wide(RNG, 5000)) for _ in range(3))
    c[:10] = 5e-324
    got = ((WideArray(4.0) * WideArray(a) * WideArray(b)).sqrt() / WideArray(c)
           * WideArray(0.5)).value()
    ref = [float((Wide(4.0) * Wide(x) * Wide(y)).sqrt() / Wide(z) * Wide(0.5))
           for x, y, z in zip(a.tolist(), b.tolist(), c.tolist())]
    assert np.isinf(ref).any() and (np.asarray(ref) == 0).any()   # both ends reached
    assert np.array_equal(_bits(got), _bits(ref))


@pytest.mark.parametrize("k", [2, 3])
def test_hypot_rows_is_math_hypot(k):
    for cols in ([_wide(RNG, 4000) for _ in range(k)],
                 [RNG.uniform(-10, 10, 4000) for _ in range(k)]):
        value, ok = hypot_rows(*cols)
        ref = []
        for row in zip(*[c.tolist() for c in cols]):
            try:
                ref.append(math.hypot(*row))
            except OverflowError:
                ref.append(math.inf)
        assert ok.mean() > 0.3
        assert np.array_equal(_bits(value[ok]), _bits(np.asarray(ref)[ok]))
    value, ok = hypot_rows(np.array([3.0, 0.0]), np.array([4.0, 0.0]))
    assert value.tolist() == [5.0, 0.0] and ok.all()


def test_series_and_parallel_sum_rows():
    n, k = 3000, 3
    values = np.abs(_wide(RNG, (n, k), -320, 308))
    values[:5] = [[200.0, 300.0, np.inf], [np.inf] * 3, [1e-320, 1.0, 1.0],
                  [1e308, 1e308, 1e308], [0.1, 0.2, 0.3]]
    s, ok = series_sum_rows(values)
    ref = [series_sum(row) for row in values.tolist()]
    assert ok.all() and np.array_equal(_bits(s), _bits(ref))
    assert s[0] == 120.0 and s[1] == math.inf
    p, ok = parallel_sum_rows(values)
    ref = [parallel_sum(row) for row in values.tolist()]
    assert ok.all() and np.array_equal(_bits(p), _bits(ref))
    assert p[3] == math.inf and p[4] == 0.6
