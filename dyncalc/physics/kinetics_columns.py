"""Column kernels of the rigid-body scenes of :mod:`dyncalc.physics.kinetics` (``--batch``).

The one-off evaluates each scene's closed form in exact rational arithmetic on the float inputs
and rounds every result once (the float nearest the exact value). The kernels here evaluate
the same closed forms on whole columns in double-double arithmetic
(:mod:`~dyncalc.physics.numerics_arrays`), carry a bound on each value's relative error, and
round with :func:`~dyncalc.physics.numerics_arrays.round_certified`: a row is exact where no
rounding boundary lies within the bound of any of its results (so its floats are the
one-off's, bit for bit). Products and sums of exact floats are exact (Dekker, Knuth); a
difference of nearly equal values widens its bound by the cancellation, so such rows go back to
the one-off. Inputs are taken between ``2^-100`` and ``2^100`` in magnitude (or zero) so that
no product midway overflows or underflows; the other rows, zeros the one-off does not call
exact, and the rows that warn are left to the one-off.

    :math:`\\tilde x = x (1 + \\delta),\\ |\\delta| \\le \\varepsilon`; a sum
    :math:`a + b` carries :math:`(\\varepsilon_a |a| + \\varepsilon_b |b| + 2^{-104} (|a| +
    |b|)) / |a + b|`, a product or a quotient :math:`\\varepsilon_a + \\varepsilon_b + 2^{-103}`.

Reference: T. J. Dekker, "A floating-point technique for extending the available precision",
Numer. Math. 18 (1971) 224-242.
"""
from __future__ import annotations

import math

from ..lazy import numpy as np
from .columns import Columns
from .kinetics import (direct_central_impact, double_pendulum_impulse, drum_two_blocks,
                       two_drums_rope_drive, wheel_incline_block)
from .numerics_arrays import (dd_add, dd_div, dd_mul, elementwise, round_certified,
                              two_product_array, two_sum_array)

__all__ = ["Exact", "rounded", "KERNELS", "rigid_kernel"]

#: The rigid-body scenes' kernels by physics function. Kept here, not as the function's
#: ``columns`` attribute (:func:`~dyncalc.physics.columns.column_kernel`), which
#: natural-frequency's vectorised path would take up for scenes it refuses.
KERNELS: dict = {}


def rigid_kernel(physics):
    """Register the decorated kernel as ``physics``'s in :data:`KERNELS`."""
    def attach(kernel):
        KERNELS[physics] = kernel
        return kernel
    return attach

#: Rounding error of one double-double step (dd_add, dd_mul: 2^-104; dd_div: 2^-103).
_STEP = 2.0 ** -103
#: Inputs within these magnitudes (or zero) keep every product midway normal.
_LOW, _HIGH = 2.0 ** -100, 2.0 ** 100


class Exact:
    """A column as a double-double ``hi + lo`` with a relative error bound ``err`` (an array
    or 0.0): the exact rational value ``x`` satisfies ``|hi + lo - x| <= err |x|`` (to first
    order)."""

    __slots__ = ("hi", "lo", "err")

    def __init__(self, hi, lo=0.0, err=0.0):
        self.hi, self.lo, self.err = hi, lo, err

    @staticmethod
    def _of(other) -> "Exact":
        return other if isinstance(other, Exact) else Exact(float(other))

    def _plain(self):
        """Where the value is one float, known exactly (a sum or product of two is exact)."""
        return (np.asarray(self.lo) == 0.0) & (np.asarray(self.err) == 0.0)

    def __add__(self, other) -> "Exact":
        b = Exact._of(other)
        if (not np.any(self.lo) and not np.any(self.err) and not np.any(b.lo)
                and not np.any(b.err)):
            return Exact(*two_sum_array(self.hi, b.hi))   # Knuth: exact
        hi, lo = dd_add(self.hi, self.lo, b.hi, b.lo)
        size_a, size_b = np.abs(self.hi), np.abs(b.hi)
        step = np.where(self._plain() & b._plain(), 0.0, _STEP)
        top = self.err * size_a + b.err * size_b + step * (size_a + size_b)
        with np.errstate(divide="ignore", invalid="ignore"):
            err = np.where(top == 0.0, 0.0, top / np.abs(hi))
        # a zero of exact operands is exact: hi = 0 means ah = -bh, then lo = 0 means al = -bl
        exact = (np.asarray(self.err) == 0.0) & (np.asarray(b.err) == 0.0)
        err = np.where(exact & (hi == 0.0) & (lo == 0.0), 0.0, err)
        return Exact(hi, lo, err)

    def __neg__(self) -> "Exact":
        return Exact(-self.hi, -self.lo, self.err)

    def __sub__(self, other) -> "Exact":
        return self + (-Exact._of(other))

    def __radd__(self, other) -> "Exact":
        return Exact._of(other) + self

    def __rsub__(self, other) -> "Exact":
        return Exact._of(other) + (-self)

    def __mul__(self, other) -> "Exact":
        if isinstance(other, float) and math.frexp(other)[0] == 0.5:
            return Exact(self.hi * other, self.lo * other, self.err)   # a power of two: exact
        b = Exact._of(other)
        if (not np.any(self.lo) and not np.any(self.err) and not np.any(b.lo)
                and not np.any(b.err)):
            return Exact(*two_product_array(self.hi, b.hi))   # Dekker: exact
        hi, lo = dd_mul(self.hi, self.lo, b.hi, b.lo)
        step = np.where(self._plain() & b._plain(), 0.0, _STEP)
        err = np.where(self.is_zero() | b.is_zero(), 0.0, self.err + b.err + step)
        return Exact(hi, lo, err)

    __rmul__ = __mul__

    def __truediv__(self, other) -> "Exact":
        b = Exact._of(other)
        if isinstance(other, float) and math.frexp(other)[0] == 0.5:
            return Exact(self.hi / other, self.lo / other, self.err)   # a power of two: exact
        hi, lo = dd_div(self.hi, self.lo, b.hi, b.lo)
        return Exact(hi, lo, np.where(self.is_zero(), 0.0, self.err + b.err + _STEP))

    def __rtruediv__(self, other) -> "Exact":
        return Exact._of(other) / self

    def __abs__(self) -> "Exact":
        sign = np.where(self.hi < 0.0, -1.0, 1.0)
        return Exact(sign * self.hi, sign * self.lo, self.err)

    def is_zero(self):
        """Where the value is zero exactly (not a rounding of something else)."""
        return (self.hi == 0.0) & (np.asarray(self.lo) == 0.0) & (np.asarray(self.err) == 0.0)


def in_range(*columns):
    """Where every column is zero or between ``2^-100`` and ``2^100`` in magnitude."""
    ok = True
    for c in columns:
        size = np.abs(c)
        ok = ok & ((size == 0.0) | ((size >= _LOW) & (size <= _HIGH)))
    return ok


def rounded(values: dict, ok, zeros=()) -> Columns:
    """The kernel's :class:`Columns`: each :class:`Exact` rounded to its float, a row exact
    where ``ok`` holds and every value is certainly rounded right and finite; a zero only
    where the value is zero exactly and its name is in ``zeros`` (those the one-off calls
    exact; any other zero is left to it)."""
    out = {}
    exact = np.asarray(ok, dtype=bool)
    for name, value in values.items():
        bound = 4.0 * np.asarray(value.err) + 2.0 ** -100
        with np.errstate(all="ignore"):
            z, certain = round_certified(value.hi, value.lo, bound)
            # a value known exactly (no bound) is rounded by the one addition hi + lo, as
            # float() rounds the fraction (ties to even, binade edges included)
            certain = certain | ((np.asarray(value.err) == 0.0) & np.isfinite(z)
                                 & (np.abs(z) >= 2.0 ** -1022))
        zero = z == 0.0
        allowed = value.is_zero() if name in zeros else False
        exact = exact & np.where(zero, allowed, certain)
        out[name] = z + 0.0
    return Columns(out, exact=exact)


def _drum(m1, m2, r1, r2, J_A, g, only=None):
    m1_, m2_, r1_, r2_, J, g_ = (Exact(v) for v in (m1, m2, r1, r2, J_A, g))
    D = J + m1_ * r1_ * r1_ + m2_ * r2_ * r2_
    top = m2_ * r2_ - m1_ * r1_
    alpha = top * g_ / D
    made = {"alpha": lambda: alpha, "a1": lambda: r1_ * alpha, "a2": lambda: r2_ * alpha,
            "S1": lambda: m1_ * (g_ + r1_ * alpha), "S2": lambda: m2_ * (g_ - r2_ * alpha)}
    return {name: make() for name, make in made.items() if only in (None, name)}


@rigid_kernel(drum_two_blocks)
def _drum_two_blocks_columns(m1, m2, r1, r2, J_A, g, *, only=None) -> Columns:
    """:func:`drum_two_blocks` on columns (SI arrays); ``only``: one result's name, that
    result alone, exact where it is (``takes_only``, see
    :func:`~dyncalc.physics.columns.one_result`: the inverse's search reads one, a quarter
    less CPU in a ``J_A=?`` batch)."""
    values = _drum(m1, m2, r1, r2, J_A, g, only)
    return rounded(values, in_range(m1, m2, r1, r2, J_A, g), zeros=("alpha", "a1", "a2"))


_drum_two_blocks_columns.takes_only = True


@rigid_kernel(wheel_incline_block)
def _wheel_incline_block_columns(m1, m2, beta, J_A=None, r=None, kappa=None, g=None) -> Columns:
    """:func:`wheel_incline_block` on columns; ``sin``/``cos`` of the incline by libm, row by
    row, as the one-off calls them."""
    s, c = elementwise(math.sin, beta), elementwise(math.cos, beta)
    m1_, m2_, g_ = Exact(m1), Exact(m2), Exact(g)
    if J_A is not None:
        ok = in_range(m1, m2, g, s, c, J_A, r)
        q = Exact(J_A) / (Exact(r) * Exact(r))
    else:
        ok = in_range(m1, m2, g, s, c, kappa)
        q = Exact(kappa) * m1_
    total = m1_ + m2_ + q
    top = m2_ - m1_ * Exact(s)
    a = g_ * top / total
    H, N = q * a, m1_ * g_ * Exact(c)
    values = {"a": a, "S": m2_ * g_ * (m1_ + q + m1_ * Exact(s)) / total, "H": H, "N": N,
              "mu_min": abs(H) / N}
    return rounded(values, ok & np.isfinite(s) & np.isfinite(c),
                   zeros=("a", "H", "mu_min"))


@rigid_kernel(two_drums_rope_drive)
def _two_drums_rope_drive_columns(m1, m2, r1, r2, J1, J2, M0, g) -> Columns:
    """:func:`two_drums_rope_drive` on columns; rows whose rope goes slack (warned by the
    one-off) or whose rope force is zero are left to the one-off."""
    m1_, m2_, r1_, r2_, J1_, J2_, M, g_ = (Exact(v) for v in (m1, m2, r1, r2, J1, J2, M0, g))
    D = m2_ * r2_ * r2_ + m1_ * r1_ * r1_ + J1_ + J2_
    top = g_ * (m2_ * r2_ * r2_ - m1_ * r1_ * r2_) + M * r2_
    a2 = top / D
    a1 = r1_ / r2_ * a2
    values = {"a2": a2, "a1": a1, "alpha": a2 / r2_, "S1": m1_ * (g_ + a1),
              "S2": m2_ * (g_ - a2)}
    out = rounded(values, in_range(m1, m2, r1, r2, J1, J2, M0, g),
                  zeros=("a2", "a1", "alpha"))
    out.exact &= (out.values["S1"] > 0.0) & (out.values["S2"] > 0.0)
    return out


@rigid_kernel(direct_central_impact)
def _direct_central_impact_columns(m1, m2, v1, v2, e) -> Columns:
    """:func:`direct_central_impact` on columns (rows with ``v1 <= v2`` or ``e`` outside
    ``[0, 1]`` are the one-off's to refuse)."""
    m1_, m2_, v1_, v2_, e_ = (Exact(v) for v in (m1, m2, v1, v2, e))
    total, dv = m1_ + m2_, v1_ - v2_
    momentum = m1_ * v1_ + m2_ * v2_
    values = {"v_c": momentum / total,
              "v1_post": (momentum - e_ * m2_ * dv) / total,
              "v2_post": (momentum + e_ * m1_ * dv) / total,
              "F_hat": (1.0 + e_) * (m1_ * m2_ * dv) / total,
              "dE": (1.0 - e_ * e_) * (m1_ * m2_ * (dv * dv)) / (total * 2.0)}
    ok = in_range(m1, m2, v1, v2, e) & (v1 > v2) & (e >= 0.0) & (e <= 1.0)
    return rounded(values, ok, zeros=tuple(values))


@rigid_kernel(double_pendulum_impulse)
def _double_pendulum_impulse_columns(m, l, F_hat, d=None) -> Columns:
    """:func:`double_pendulum_impulse` on columns (``d`` left out: ``d_0 = 5 l / 8``)."""
    m_, l_, F = Exact(m), Exact(l), Exact(F_hat)
    d_0 = (l_ * 5.0) * 0.125                      # 5 l exact (Dekker), / 8 exact
    d_ = d_0 if d is None else Exact(d)
    upper, lower = d_ * 3.0 - l_, l_ * 5.0 - d_ * 8.0
    B_hat = F * 2.0 * upper / (l_ * 7.0)
    values = {"omega_1": F * 6.0 * upper / (m_ * l_ * l_ * 7.0),
              "omega_2": F * 6.0 * lower / (m_ * l_ * l_ * 7.0),
              "v_2": F * 3.0 * (l_ * 3.0 - d_ * 2.0) / (m_ * l_ * 7.0),
              "A_hat": B_hat * 0.5, "B_hat": B_hat, "d_0": d_0, "d_A0": l_ / 3.0}
    ok = in_range(m, l, F_hat) if d is None else (in_range(m, l, F_hat, d) & (d >= 0.0)
                                                  & (d <= l))
    return rounded(values, ok, zeros=("omega_1", "omega_2", "A_hat", "B_hat"))
