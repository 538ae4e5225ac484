"""The column kernel of dyncalc.physics.frames.relative_acceleration against the one-off,
bit for bit; rows where the one-off refuses (overflow) or warns (underflow) are not exact."""
from __future__ import annotations

import numpy as np
import pytest

from dyncalc.errors import InputError, PhysicsError
from dyncalc.physics.columns import kernel_of
from dyncalc.physics.frames import relative_acceleration


def test_relative_acceleration_kernel():
    rng = np.random.default_rng(15)
    n = 1000

    def vectors(low, high):
        v = 10.0 ** rng.uniform(low, high, (n, 3)) * rng.choice([-1.0, 1.0], (n, 3))
        return v * (rng.random((n, 3)) > 0.1)

    Om, v, r, al, a0, ar = (vectors(-3, 3) for _ in range(6))
    m = 10.0 ** rng.uniform(-3, 3, n)
    Om[:100], r[:100] = vectors(-300, 300)[:100], vectors(-300, 300)[:100]
    Om[100], v[100], r[100] = [0.0, 0.0, 2.0], [3.0, 0.0, 0.0], [0.5, 0.0, 1.0]
    al[100], a0[100], ar[100] = [0.0, 0.0, 3.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
    out = kernel_of(relative_acceleration)(Om, v, r=r, alpha=al, a0=a0, a_r=ar, m=m)
    assert list(out.values) == ["a_c", "a_euler", "a_centripetal", "a_transport", "a", "F_c"]
    for i in range(n):
        try:
            fa = relative_acceleration(Om[i], v[i], r=r[i], alpha=al[i], a0=a0[i], a_r=ar[i],
                                       m=m[i])
        except PhysicsError:
            assert not out.exact[i]
            continue
        if fa.warnings:
            assert not out.exact[i]
        if out.exact[i]:
            for name, value in out.values.items():
                assert np.array_equal(getattr(fa, name).view(np.int64),
                                      value[i].view(np.int64)), (i, name)
    assert out.exact[101:].mean() > 0.95
    # a_c = 2 Omega x v_r = (0, 12, 0); Omega x (Omega x r) = (-2, 0, 0); alpha x r = (0, 1.5, 0)
    assert out.values["a_c"][100].tolist() == [0.0, 12.0, 0.0]
    assert out.values["a_centripetal"][100].tolist() == [-2.0, 0.0, 0.0]
    assert out.values["a"][100].tolist() == [-2.0, 13.5, 0.0]


def test_relative_acceleration_kernel_without_optional_vectors():
    Om = np.array([[0.0, 0.0, 2.0], [1e200, 0.0, 0.0]])
    v = np.array([[3.0, 0.0, 0.0], [0.0, 1e200, 0.0]])
    out = kernel_of(relative_acceleration)(Om, v)
    assert "F_c" not in out.values
    assert out.exact.tolist() == [True, False]          # 2e400 overflows: refused
    assert out.values["a"][0].tolist() == [0.0, 12.0, 0.0]


@pytest.mark.parametrize("given", [(), ("r",), ("alpha",), ("r", "alpha"), ("a0",), ("a_r",),
                                   ("m",), ("alpha", "a_r", "m")])
def test_relative_acceleration_kernel_on_subsets(given):
    """Terms of vectors not given are not computed (zeros, or ``a_c`` itself): the same bits
    and the same exact rows as the one-off, with extremes (subnormal, huge, inf, nan, -0.0)."""
    rng = np.random.default_rng(len(given) * 7 + sum(map(len, given)))
    n = 600

    def vectors():
        v = 10.0 ** rng.uniform(-320, 300, (n, 3)) * rng.choice([-1.0, 1.0], (n, 3))
        v = v * (rng.random((n, 3)) > 0.2)
        v[rng.random((n, 3)) < 0.01] = np.inf
        v[rng.random((n, 3)) < 0.01] = np.nan
        v[rng.random((n, 3)) < 0.05] = -0.0
        return np.where(rng.random((n, 1)) < 0.5, v, 10.0 ** rng.uniform(-3, 3, (n, 3)))

    Om, v = vectors(), vectors()
    extra = {name: vectors() for name in given if name != "m"}
    if "m" in given:
        extra["m"] = 10.0 ** rng.uniform(-3, 3, n)
    out = kernel_of(relative_acceleration)(Om, v, **extra)
    names = ["a_c", "a_euler", "a_centripetal", "a_transport", "a"] + (["F_c"] if "m" in given
                                                                       else [])
    assert list(out.values) == names
    exact = 0
    for i in range(n):
        try:
            with np.errstate(all="ignore"):
                fa = relative_acceleration(Om[i], v[i], **{k: x[i] for k, x in extra.items()})
        except (PhysicsError, InputError):
            assert not out.exact[i], i
            continue
        if fa.warnings:
            assert not out.exact[i], i
        if out.exact[i]:
            exact += 1
            for name in names:
                assert np.array_equal(getattr(fa, name).view(np.int64),
                                      out.values[name][i].view(np.int64)), (i, name)
    assert exact > n // 4


@pytest.mark.parametrize("given", [(), ("v0",), ("v_r",), ("v0", "v_r")])
def test_transport_velocity_kernel(given):
    """v0 + Omega x r (+ v_r), exact sums: the column kernel gives the one-off's bits where it
    says exact, with extremes (subnormal, huge, inf, nan, -0.0) and near-cancelling rows."""
    from dyncalc.physics.relative_motion import transport_velocity

    rng = np.random.default_rng(31 + len(given))
    n = 800

    def vectors(low=-320, high=300):
        v = 10.0 ** rng.uniform(low, high, (n, 3)) * rng.choice([-1.0, 1.0], (n, 3))
        v = v * (rng.random((n, 3)) > 0.2)
        v[rng.random((n, 3)) < 0.01] = np.inf
        v[rng.random((n, 3)) < 0.01] = np.nan
        v[rng.random((n, 3)) < 0.05] = -0.0
        return np.where(rng.random((n, 1)) < 0.5, v, 10.0 ** rng.uniform(-3, 3, (n, 3)))

    Om, r = vectors(), vectors()
    extra = {name: vectors() for name in given}
    if "v0" in extra:  # rows where v0 nearly cancels Omega x r
        Om[:50], r[:50] = vectors(5, 6)[:50], vectors(5, 6)[:50]
        with np.errstate(all="ignore"):
            extra["v0"][:50] = -np.cross(Om[:50], r[:50]) * (1 + 1e-12)
    out = kernel_of(transport_velocity)(Om, r, **extra)
    exact = 0
    for i in range(n):
        try:
            with np.errstate(all="ignore"):
                one = transport_velocity(Om[i], r[i], **{k: x[i] for k, x in extra.items()})
        except (PhysicsError, InputError):
            assert not out.exact[i], i
            continue
        if out.exact[i]:
            exact += 1
            assert np.array_equal(one.view(np.int64), out.values["v"][i].view(np.int64)), i
    assert exact > n // 4
