"""The array twins of dyncalc.physics.numerics_arrays against their scalar kernels: the same
bits, element by element, over random inputs from 1e-300 to 1e300 and ordinary values."""
from __future__ import annotations

import math

import numpy as np
import pytest

from dyncalc.physics.numerics import (Wide, monomial, parallel_sum, root_monomial, series_sum,
                                     two_product)
from dyncalc.physics.numerics_arrays import (WideArray, fsum_rows, hypot_rows, monomial_array,
                                             parallel_sum_rows, pow_array, root_monomial_array,
                                             series_sum_rows, two_product_array)

RNG_SEED = 20240611


def _bits(values) -> np.ndarray:
    return np.asarray(values, dtype=float).view(np.int64)


def _log_uniform(rng, n, low=-300.0, high=300.0):
    return 10.0 ** rng.uniform(low, high, n)


def _mantissas(rng, n):
    """Random mantissas in [0.5, 1), half of them with 27 significant bits (their squares are
    exact rounding midpoints, where the C library's pow and x * x part ways most often)."""
    plain = rng.uniform(0.5, 1.0, n // 2)
    short = (rng.integers(2 ** 26, 2 ** 27, n - n // 2) | 1) * 2.0 ** -27
    return np.concatenate([plain, short])


@pytest.mark.parametrize("power", [1, 2, -1, 3, -2])
def test_pow_array_is_pythons_pow(power):
    x = _mantissas(np.random.default_rng(RNG_SEED + power), 40_000)
    expected = [value ** power for value in x.tolist()]
    assert np.array_equal(_bits(pow_array(x, power)), _bits(expected))


def test_pow_array_would_fail_with_the_plain_product():
    """The check above can fail: on these inputs x * x is not Python's x ** 2 everywhere."""
    x = _mantissas(np.random.default_rng(RNG_SEED), 40_000)
    assert not np.array_equal(_bits(x * x), _bits([value ** 2 for value in x.tolist()]))


FACTOR_SETS = [[1, 2], [1, 1, 1, -1], [1, -3], [2, -1, 1]]


@pytest.mark.parametrize("powers", FACTOR_SETS)
@pytest.mark.parametrize("twin, scalar", [(monomial_array, monomial),
                                          (root_monomial_array, root_monomial)])
def test_monomials_are_bitwise_the_scalar_kernels(powers, twin, scalar):
    rng = np.random.default_rng(RNG_SEED + len(powers))
    n = 6000
    columns = [np.concatenate([_log_uniform(rng, n // 2), rng.uniform(0.1, 10.0, n // 2)])
               for _ in powers]
    columns[0][:5] = [0.0, 1.0, 2.0, 5e-324, 1.7e308]      # a zero factor, the extremes
    coefficient = 0.75
    got = twin(coefficient, list(zip(columns, powers)))
    expected = [scalar(coefficient, list(zip(row, powers))) for row in zip(*columns)]
    assert np.array_equal(_bits(got), _bits(expected))
    # the sample reaches the zero factor, overflow beyond float64 and the ordinary range
    assert got[0] == 0.0 and np.isinf(got).any() and (np.abs(np.log10(got[-100:])) < 30).all()


def _wide_pairs(rng, n):
    values = np.concatenate([_log_uniform(rng, n // 2), rng.uniform(0.1, 10.0, n // 2)])
    values[:3] = [0.0, 5e-324, 1.7e308]
    return values


def test_wide_array_operations_are_wides():
    rng = np.random.default_rng(RNG_SEED)
    n = 4000
    a, b, c = (_wide_pairs(rng, n) for _ in range(3))
    b = rng.permutation(b)
    wa, wb, wc = WideArray(a), WideArray(b), WideArray(c)
    got = {
        "product": (wa * wb * wc),
        "sum": (wa * wb + wc * 3.0),
        "sum with a float": (2.0 * wa + wb / 3.0),
        "quotient": (wa + 0.5 * wb) / (wc * wc + wa),
        "root": (wa * wb / wc).sqrt(),
    }
    scalar = {
        "product": lambda x, y, z: Wide(x) * Wide(y) * Wide(z),
        "sum": lambda x, y, z: Wide(x) * Wide(y) + Wide(z) * 3.0,
        "sum with a float": lambda x, y, z: 2.0 * Wide(x) + Wide(y) / 3.0,
        "quotient": lambda x, y, z: (Wide(x) + 0.5 * Wide(y)) / (Wide(z) * Wide(z) + Wide(x)),
        "root": lambda x, y, z: (Wide(x) * Wide(y) / Wide(z)).sqrt(),
    }
    for name, wide in got.items():
        ms, es, floats = [], [], []
        for x, y, z in zip(a.tolist(), b.tolist(), c.tolist()):
            try:
                w = scalar[name](x, y, z)
            except ZeroDivisionError:
                ms.append(math.nan), es.append(0), floats.append(math.nan)
                continue
            ms.append(w.m), es.append(w.e), floats.append(float(w))
        ok = ~np.isnan(ms)
        assert np.array_equal(_bits(wide.m)[ok], _bits(ms)[ok]), name
        assert np.array_equal(wide.e[ok], np.asarray(es)[ok]), name
        assert np.array_equal(_bits(wide.to_float())[ok], _bits(floats)[ok]), name
        assert not np.isfinite(wide.to_float()[~ok]).any(), name   # the scalar raised there


def test_wide_array_sums_far_apart_and_zero_terms():
    """Terms 2^-1074 apart and beyond (dropped, as float addition drops them) and zeros."""
    a = np.array([1.0, 1.0, 1.0, 0.0, 3.0, 1e300])
    b = np.array([2.0 ** -1074, 2.0 ** -1075 * 3, 0.0, 7.0, 1e-300, 1e300])
    wide = WideArray(a) * 1e300 * 1e300 + WideArray(b)   # 1e600: beyond float64
    for i, (x, y) in enumerate(zip(a.tolist(), b.tolist())):
        w = Wide(x) * 1e300 * 1e300 + Wide(y)
        assert (wide.m[i], int(wide.e[i])) == (w.m, w.e)
        assert _bits(wide.to_float()[i]) == _bits(float(w))


# --- fsum, two_product, hypot, series and parallel sums, row by row -------------------------

RNG = np.random.default_rng(7)


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


@pytest.mark.parametrize("k", [2, 3, 5])
def test_fsum_rows_near_ties_subnormals_and_huge_terms(k):
    """The cheap road (TwoSum in order, one rounding) is taken only where it is certain: rows
    built to sit on or next to a half-way point, with subnormal or huge terms, or summing to
    zero, give fsum's bits; a plain rounding of the same rows would not."""
    rng = np.random.default_rng(11 + k)
    n = 6000
    base = rng.uniform(1.0, 2.0, n) * 2.0 ** rng.integers(-1060, 1000, n)
    ulp = np.array([math.ulp(x) for x in base.tolist()])
    t = np.zeros((n, k))
    t[:, 0] = base
    t[:, 1] = ulp * rng.choice([0.5, -0.5, 0.25, 1.5], n)           # a half-way point or near
    for j in range(2, k):
        t[:, j] = ulp * 2.0 ** -rng.integers(1, 80, n) * rng.choice([-1.0, 1.0], n)
    t[: n // 10] = -t[: n // 10, ::-1]                                 # the order reversed
    t[n // 10: n // 5, :] = 5e-324 * rng.integers(-3, 4, (n // 5 - n // 10, k))   # subnormal
    t[n // 5: n // 4, 0] = 1e300 * rng.choice([-1.0, 1.0], n // 4 - n // 5)       # huge
    t[n // 4: n // 3, -1] = -np.sum(t[n // 4: n // 3, :-1], axis=1)              # near zero
    s, ok = fsum_rows(t)
    expected = [math.fsum(row) for row in t.tolist()]
    assert ok.all()
    assert np.array_equal(_bits(s), _bits(expected))
    if k > 2:  # (two terms: one addition is already the correctly rounded sum)
        plain = t.sum(axis=1)
        assert not np.array_equal(_bits(plain + 0.0), _bits(expected))


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
