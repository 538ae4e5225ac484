"""The search kernels of dyncalc.physics.numerics that the inverse solver uses (issue 15):
float_boundary (an edge to adjacent floats), float_approach (geometric in the float order) and
bracketed_minimum (Brent), each against an independent reference: math.nextafter stepping,
mpmath at 40 digits."""
import math
import random

import mpmath
import pytest

from dyncalc.physics.numerics import bracketed_minimum, float_approach, float_boundary


def step(x, n, toward):
    """``x`` moved ``n`` floats toward ``toward`` by repeated math.nextafter."""
    for _ in range(n):
        x = math.nextafter(x, toward)
    return x


@pytest.mark.parametrize("threshold, good, bad", [
    (0.3, 0.0, 1.0), (1e-310, 0.0, 1.0), (5e-324, 0.0, 1e308), (1e300, 1.0, 1.7e308),
    (-2.5, -1e308, 0.0), (0.0, -1.0, 1.0), (123456.789, 1e-300, 1e300),
])
def test_float_boundary_is_the_last_float_inside(threshold, good, bad):
    """inside = x < threshold: the edge is the largest float below the threshold."""
    calls = []

    def inside(x):
        calls.append(x)
        return x < threshold

    edge, tried = float_boundary(inside, good, bad)
    assert edge == math.nextafter(threshold, -math.inf)
    assert not inside(math.nextafter(edge, math.inf))
    assert len(tried) == len(calls) - 1 <= 64
    assert all(ok == (x < threshold) for x, ok in tried)


def test_float_boundary_from_above():
    """The edge approached from the side of larger values: inside = x > threshold."""
    rnd = random.Random(5)
    for _ in range(300):
        threshold = 10 ** rnd.uniform(-300, 300)
        edge, tried = float_boundary(lambda x: x > threshold, 1.7e308, 0.0)
        assert edge == math.nextafter(threshold, math.inf) and len(tried) <= 64


@pytest.mark.parametrize("edge, toward", [(1.0, 2.0), (0.13, 0.0), (0.0, 1.0), (-3.0, 5.0),
                                          (math.pi, 3.0), (1e-300, 1e300)])
def test_float_approach_is_geometric_in_the_float_order(edge, toward):
    """The k-th point is 2^k floats from the edge (math.nextafter counted), all strictly
    between edge and toward, nearest first."""
    points = float_approach(edge, toward)
    for k, x in enumerate(points[:12]):
        assert x == step(edge, 2 ** k, toward)
    lo, hi = sorted((edge, toward))
    assert all(lo < x < hi for x in points)
    assert points == sorted(points, key=lambda x: abs(x - edge))
    assert 1 <= len(points) <= 64


def test_float_approach_between_neighbours_is_empty():
    assert float_approach(1.0, math.nextafter(1.0, 2.0)) == []


C = mpmath.mpf(1) / 3 + mpmath.mpf("0.01")


@pytest.mark.parametrize("f, mp_f, mp_df, bracket", [
    (lambda x: -x * math.exp(-x), lambda x: -x * mpmath.exp(-x),
     lambda x: (x - 1) * mpmath.exp(-x), (0.1, 0.9, 7.0)),
    (lambda x: math.cosh(x - 0.3) + 0.1 * x ** 4, lambda x: mpmath.cosh(x - 0.3) + x ** 4 / 10,
     lambda x: mpmath.sinh(x - 0.3) + 2 * x ** 3 / 5, (-2.0, 0.0, 3.0)),
    (lambda x: x ** 4 - 3 * x ** 2 + x, lambda x: x ** 4 - 3 * x ** 2 + x,
     lambda x: 4 * x ** 3 - 6 * x + 1, (0.5, 1.0, 2.0)),
    # in log coordinates, as the inverse solver uses it (x = e^u): the clock pendulum's peak,
    # -(1/2 + 4x)/(C + 2x^2), whose derivative in x vanishes where 8x^2 + 2x - 4C = 0
    (lambda u: -((0.5 + 4 * math.exp(u)) / (1 / 3 + 0.01 + 2 * math.exp(2 * u))),
     lambda u: -((mpmath.mpf("0.5") + 4 * mpmath.exp(u)) / (C + 2 * mpmath.exp(2 * u))),
     lambda u: 8 * mpmath.exp(2 * u) + 2 * mpmath.exp(u) - 4 * C,
     (math.log(1e-5), math.log(0.1), math.log(1.0))),
])
def test_bracketed_minimum_against_mpmath(f, mp_f, mp_df, bracket):
    """x within 1e-7 (the values place a smooth minimum to about sqrt(eps)) and f(x) within 2
    ulp of the true minimum value (the derivative's root, mpmath at 40 digits); a few dozen
    evaluations at most."""
    with mpmath.workdps(40):
        x_ref = mpmath.findroot(mp_df, (bracket[0], bracket[2]), solver="anderson")
        f_ref = mp_f(x_ref)
    found = bracketed_minimum(f, *bracket)
    assert abs(found.x - float(x_ref)) <= 1e-7 * max(1.0, abs(float(x_ref)))
    assert abs(found.fx - float(f_ref)) <= 2 * math.ulp(float(f_ref))
    assert found.fx == f(found.x)
    assert found.evaluations <= 40


def test_bracketed_minimum_steps_around_nan():
    """Where f does not answer (NaN) counts as +inf: the minimum at the edge of the region is
    approached from inside."""
    found = bracketed_minimum(lambda x: math.nan if x > 0.5 else -x, 0.0, 0.4, 1.0)
    assert 0.5 - 1e-7 <= found.x <= 0.5 and found.fx == -found.x


def test_bracketed_minimum_stops_within_max_iter():
    found = bracketed_minimum(lambda x: abs(x - 1e-3), 0.0, 1e-3, 1.0, max_iter=15)
    assert found.evaluations <= 15
