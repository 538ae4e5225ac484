""":func:`dyncalc.physics.forced.forced_response` on whole columns (the batch kernel of
``forced-response``), bit for bit the one-off on every row it answers.

The one-off forms the two differences that cancel near resonance and near the peak's limits in
exact rational arithmetic and rounds them once: ``1 - eta^2 = (k - m Omega^2)/k`` (or
``(omega^2 - Omega^2)/omega^2``), ``1 - 2 zeta^2`` and ``1 - 8 zeta^2 + 8 zeta^4``. Here the
same exact values come from error-free transformations on arrays
(:mod:`~dyncalc.physics.numerics_arrays`): each square and product is split by Dekker's
product into two floats whose sum is exact, so every difference is an exact sum of a few
floats; ``math.fsum``'s twin (:func:`fsum_rows`) rounds a sum correctly, which is the
one-off's rounding of the same rational. The quotient by ``k`` (or ``omega^2``) is a
double-double (the numerator's correctly rounded residual kept, then :func:`dd_div`) whose
rounding is certified (:func:`round_certified`: no rounding boundary within its error bound);
a row where it is not (about one in 2^47), or whose inputs lie outside
:data:`DOMAIN` (where a Dekker product could overflow or its error underflow), is left to the
one-off code. Everything else is the one-off's float operations in its order; ``hypot``,
``atan2`` and ``x**2`` are CPython's, called row by row (:func:`elementwise`), where numpy's
own round differently.
"""
from __future__ import annotations

import math

from ..lazy import numpy as np
from .forced import RESONANCE_GAP
from .numerics import sqrt_ratio_array
from .outcome import CRITICAL_BAND
from .numerics_arrays import dd_div, elementwise, fsum_rows, round_certified, two_product_array

__all__ = ["DOMAIN", "forced_columns", "resonance_gap_columns", "one_minus_two_z2_columns",
           "half_power_product_columns", "total_response_columns"]

#: Inputs (SI, positive) within which every Dekker product here is exact: squares and
#: products stay far inside float64, their error terms far above the subnormals.
DOMAIN = (1e-50, 1e50)
#: The double-double quotient's relative error bound (2^-103 from dd_div, 2^-106 from the
#: numerator's residual, with room).
_DD_BOUND = 2.0 ** -100
_SQRT2, _SQRT8, _TWO_PI = math.sqrt(2.0), math.sqrt(8.0), 2.0 * math.pi


def _hypot(a, b):
    return elementwise(math.hypot, a, b)


def _square(x):
    return elementwise(lambda v: v ** 2, x)


def _residual_pair(terms):
    """``(hi, lo, ok)``: the correctly rounded sum of each row of ``terms`` (exact floats)
    and the correctly rounded residual ``sum - hi``: a double-double within ``2^-106``."""
    hi, ok = fsum_rows(terms)
    lo, ok2 = fsum_rows(np.column_stack([terms, -hi]))
    return hi, lo, ok & ok2


def resonance_gap_columns(W, *, k=None, m=None, omega=None):
    """``(gap, certain)``: ``1 - eta^2`` as :func:`dyncalc.physics.forced.resonance_gap` rounds
    the exact ``(k - m W^2)/k`` (or ``(omega^2 - W^2)/omega^2``), and where that is certain.

    >>> import numpy as np
    >>> gap, ok = resonance_gap_columns(np.array([1.000000000001]), omega=np.array([1.0]))
    >>> gap.tolist(), ok.tolist()  # resonance_gap(1.000000000001, omega=1.0)
    ([-2.000177801165682e-12], [True])
    """
    p, e = two_product_array(W, W)
    if k is not None:
        q1, f1 = two_product_array(m, p)
        q2, f2 = two_product_array(m, e)
        hi, lo, ok = _residual_pair(np.column_stack([k, -q1, -f1, -q2, -f2]))
        dh, dl = k, np.zeros_like(k)
    else:
        a, b = two_product_array(omega, omega)
        hi, lo, ok = _residual_pair(np.column_stack([a, b, -p, -e]))
        dh, dl = a, b
    with np.errstate(all="ignore"):
        qh, ql = dd_div(hi, lo, dh, dl)
        gap, certain = round_certified(qh, ql, _DD_BOUND)
    return gap, certain & ok


def one_minus_two_z2_columns(zeta):
    """``1 - 2 zeta^2`` correctly rounded (the one-off's exact rational), with ``ok``."""
    p, e = two_product_array(zeta, zeta)
    ones = np.ones_like(zeta)
    return fsum_rows(np.column_stack([ones, -2.0 * p, -2.0 * e]))


def half_power_product_columns(zeta):
    """``1 - 8 zeta^2 + 8 zeta^4`` correctly rounded, with ``ok``: ``zeta^2 = p + e`` exactly,
    ``zeta^4 = p^2 + 2 p e + e^2``, each product split again."""
    p, e = two_product_array(zeta, zeta)
    q1, f1 = two_product_array(p, p)
    q2, f2 = two_product_array(2.0 * p, e)
    q3, f3 = two_product_array(e, e)
    ones = np.ones_like(zeta)
    return fsum_rows(np.column_stack([ones, -8.0 * p, -8.0 * e, 8.0 * q1, 8.0 * f1, 8.0 * q2,
                                      8.0 * f2, 8.0 * q3, 8.0 * f3]))


_KINDS = {"F0": "force", "base": "base", "base_accel": "base-accel", "unbalance": "unbalance"}


def forced_columns(given: dict, *, with_warnings: bool = False):
    """``(values, exact)`` for the rows of one block, or ``None`` when the block's form gives
    no row a full answer here (undamped, no mass where the amplitude needs it, initial
    conditions).

    ``given``: SI float64 arrays by the oscillator's parameter names (``k``, ``m`` or
    ``omega``; ``zeta``, ``c`` or ``Q``; one excitation; ``Omega`` or ``f_exc``). ``exact``
    marks the rows answered bit for bit as the one-off answers them, with no warning (inputs
    finite, positive and within :data:`DOMAIN`, damped below the peak's and the bandwidth's
    limits, the roundings certified, every result finite and non-zero); ``values`` holds the
    results by name (``isolation`` NaN where ``TR >= 1``), NaN on the other rows.

    ``with_warnings``: also the damped rows beyond those limits, whose one-off warns
    (``zeta >= 1/sqrt 2``: no peak; ``0.38268 < zeta < 1/sqrt 2``, or a heavily damped base
    motion: one half-power frequency only), their missing results NaN, and a third item
    ``notes(rows)`` giving the warnings of the rows of an index array (a tuple of texts each,
    formatted by the one-off's own :func:`~dyncalc.physics.forced.no_peak_warning` and
    :func:`~dyncalc.physics.forced.half_power_warning`; ``None`` where none of them warns).

    >>> import numpy as np
    >>> given = {"k": np.array([100.0, 100.0]), "m": np.array([1.0, 1.0]),
    ...          "zeta": np.array([0.1, 0.9]), "F0": np.array([1.0, 1.0]),
    ...          "Omega": np.array([5.0, 5.0])}
    >>> values, exact, notes = forced_columns(given, with_warnings=True)
    >>> exact.tolist(), np.isnan(values["V_peak"]).tolist(), notes(np.array([0, 1]))[1][0][:24]
    ([True, True], [False, True], 'zeta = 0.9 >= 1/sqrt(2):')
    """
    names = set(given)
    excitation = [n for n in _KINDS if n in names]
    if len(excitation) != 1:
        return None
    undamped = not names & {"zeta", "c", "Q"}
    if names & {"x0", "v0"} and "t" not in names:
        return None         # the one-off refuses: x0 and v0 need t
    kind, amp = _KINDS[excitation[0]], given[excitation[0]]
    m = given.get("m")
    if kind in ("base", "base-accel", "unbalance") and m is None:
        return None
    if kind == "force" and "k" not in names and m is None:
        return None
    a = {n: np.asarray(v, dtype=float) for n, v in given.items()}
    start = {n: a.pop(n) for n in ("x0", "v0", "t") if n in a}
    low, high = DOMAIN
    ok = np.ones(len(amp), dtype=bool)
    for value in a.values():
        ok &= (value >= low) & (value <= high)
    for name, value in start.items():   # x0, v0 of any sign (or zero), t positive
        ok &= np.isfinite(value) if name != "t" else (value >= low) & (value <= high)
    absent = {}  # a result a row may lack, with a warning: where it does
    notes = _NO_NOTES
    with np.errstate(all="ignore"):
        if undamped:  # zeta = 0: no resonance results; refused at resonance
            a["zeta"] = np.zeros(len(amp))
            values, exact, _damped, gap, _limits = _steady(kind, a, m, ok)
            exact &= np.abs(gap) > RESONANCE_GAP
            for name in _DAMPED_ONLY:
                del values[name]
        else:
            values, exact, damped, _gap, limits = _steady(kind, a, m, ok)
            exact &= damped
            if with_warnings:
                absent, notes = _beyond(kind, values, limits)
            else:
                exact &= limits.has_peak & limits.has_width
        if "t" in start:
            zero = np.zeros(len(amp))
            sign = -1.0 if kind == "base-accel" else 1.0
            W = a["Omega"] if "Omega" in a else _TWO_PI * a["f_exc"]
            values["x"] = total_response_columns(
                values["omega"], values["zeta"], W, values["X"], values["phi"], sign,
                start.get("x0", zero), start.get("v0", zero), start["t"])
    for name, value in values.items():
        if undamped and name in ("zeta", "phi"):  # 0 (phi: 0 or pi), as the one-off gives
            exact &= np.isfinite(value)
            continue
        good = np.isfinite(value) & (value != 0.0)
        if name in absent:
            good |= absent[name]
        exact &= (good | np.isnan(value)) if name == "isolation" else good
    nan = np.nan
    out = {n: np.where(exact & ~absent[n] if n in absent else exact, v, nan)
           for n, v in values.items()}
    if not with_warnings:
        return out, exact
    return out, exact, lambda rows: notes(rows, exact)


def _NO_NOTES(rows, exact):
    return None  # (no row of the block warns)


class _Limits:
    """Where a damped row has its peak and half-power bandwidth (``has_peak``,
    ``has_width``), and the half-power frequency it has where it lacks the other (``edge``,
    as ``eta``: the upper one, the lower for unbalance)."""

    __slots__ = ("has_peak", "has_width", "edge")

    def __init__(self, has_peak, has_width, edge):
        self.has_peak, self.has_width, self.edge = has_peak, has_width, edge


def _beyond(kind, values, limits):
    """The results rows beyond the peak's and the bandwidth's limits lack, by name (a mask
    each), and the function of their warnings (the one-off's texts, its order)."""
    from .columns import warnings_of_rows
    from .forced import half_power_warning, no_peak_warning

    no_peak, no_width = ~limits.has_peak, ~limits.has_width
    half = limits.has_peak & no_width  # one half-power frequency only
    absent = {"Omega_peak": no_peak, "X_peak": no_peak, "V_peak": no_peak,
              "bandwidth": no_width}
    zeta, omega, edge = values["zeta"], values["omega"], limits.edge
    lower = kind == "unbalance"  # the frequency it has: the lower one

    def texts_of(i):
        if no_peak[i]:
            return (no_peak_warning(kind, float(zeta[i])),)
        e = float(edge[i])
        return (half_power_warning(float(zeta[i]), e if lower else None, None if lower else e,
                                   float(omega[i])),)

    def notes(rows, exact):
        return warnings_of_rows(rows, exact & (no_peak | half), texts_of)
    return absent, notes


#: The results an undamped oscillator does not have (unbounded).
_DAMPED_ONLY = ("X_res", "V_res", "Omega_peak", "X_peak", "V_peak", "bandwidth", "Q")


def _steady(kind, a, m, ok):
    """The one-off's steps (forced_response, _steady, peak, half_power) on columns:
    ``(values, ok, damped, gap)``, ``damped`` where the damping's results (resonance, peak,
    bandwidth) are the one-off's too."""
    k = a.get("k")
    if k is not None:
        w = sqrt_ratio_array(k, m)
        k_ = k
    else:
        w = a["omega"]
        k_ = m * w * w if m is not None else None
    if "c" in a:
        c = a["c"]
        zeta = c / (2.0 * np.sqrt(k_) * np.sqrt(m)) if k_ is not None else c / (2.0 * m * w)
    elif "Q" in a:
        zeta = 0.5 / a["Q"]
    else:
        zeta = a["zeta"]
    W = a["Omega"] if "Omega" in a else _TWO_PI * a["f_exc"]
    amp = a[{"force": "F0", "base": "base", "base-accel": "base_accel",
             "unbalance": "unbalance"}[kind]]
    if k is not None:       # rows outside the domain give what they give: not exact
        gap, certain = resonance_gap_columns(W, k=k, m=m)
    else:
        gap, certain = resonance_gap_columns(W, omega=w)
    ok &= certain
    zeta_ok = (zeta >= DOMAIN[0]) & (zeta <= DOMAIN[1])
    eta = W / w
    static = {"force": lambda: amp / k_, "base": lambda: amp,
              "base-accel": lambda: amp / w / w, "unbalance": lambda: amp / m}[kind]()
    two_ze = 2.0 * zeta * eta
    TR = _hypot(np.ones_like(two_ze), two_ze) / _hypot(gap, two_ze)
    if kind == "base":
        V = TR
        phi = elementwise(math.atan2, two_ze * eta * eta, gap + two_ze * two_ze)
    else:
        d = _hypot(gap, 2.0 * zeta * eta)
        V = eta / (d / eta) if kind == "unbalance" else 1.0 / d
        phi = elementwise(math.atan2, two_ze, gap)
    X = static * V
    values = {"omega": w, "zeta": zeta, "eta": eta, "X": X, "phi": phi, "V": V, "TR": TR}
    if kind == "force":
        values["F_T"] = amp * TR
    elif kind == "unbalance":
        values["F_T"] = amp * W * W * TR
    elif kind == "base":
        values["F_T"] = m * W * W * X
    else:
        values["F_T"] = m * amp * TR
    if kind == "base":
        values["Z"] = amp * eta * (eta / _hypot(gap, 2.0 * zeta * eta))
    elif kind == "base-accel":
        values["Z"] = X
    two_z = 2.0 * zeta * 1.0
    if kind == "base":
        V_res = _hypot(np.ones_like(two_z), two_z) / _hypot(np.zeros_like(two_z), two_z)
    else:
        d_res = _hypot(np.zeros_like(two_z), two_z)
        V_res = 1.0 / (d_res / 1.0) if kind == "unbalance" else 1.0 / d_res
    values["X_res"] = static * V_res
    values["V_res"] = V_res
    eta_peak, V_peak, has_peak, peak_ok = _peak(kind, zeta)
    values["Omega_peak"] = eta_peak * w
    values["X_peak"] = static * V_peak
    values["V_peak"] = V_peak
    values["Omega_iso"] = _SQRT2 * w
    values["isolation"] = np.where(TR < 1.0, 1.0 - TR, np.nan)
    width, has_width, width_ok, edge = _half_power(kind, zeta)
    values["bandwidth"] = width * w
    values["Q"] = 0.5 / zeta
    return values, ok, zeta_ok & peak_ok & width_ok, gap, _Limits(has_peak, has_width, edge)


def _peak(kind, zeta):
    """:func:`dyncalc.physics.forced.peak` on columns: ``(eta_peak, V_peak, exists,
    certain)`` (``certain``: whether it exists is the one-off's answer)."""
    if kind == "base":
        r = _hypot(np.ones_like(zeta), _SQRT8 * zeta)
        s = 2.0 / (1.0 + r)
        w = _square(_SQRT8 * zeta / (1.0 + r))
        eta = np.sqrt(s)
        two_ze = 2.0 * zeta * eta
        every = np.ones(len(zeta), dtype=bool)
        return eta, _hypot(np.ones_like(two_ze), two_ze) / _hypot(w, two_ze), every, every
    s, ok = one_minus_two_z2_columns(zeta)
    v = 1.0 / (2.0 * zeta * np.sqrt((1.0 - zeta) * (1.0 + zeta)))
    root = np.sqrt(s)
    return (root if kind != "unbalance" else 1.0 / root), v, s > 0.0, ok


def _half_power(kind, zeta):
    """``(bandwidth/omega, exists, certain, edge)`` as
    :func:`dyncalc.physics.forced.half_power` gives it: ``exists`` where it gives a
    bandwidth, ``certain`` where that is the one-off's answer, ``edge`` the one half-power
    frequency (``eta``) of a row with one only (the upper; the lower for unbalance)."""
    if kind == "base":
        return _half_power_base(zeta)
    s, ok = one_minus_two_z2_columns(zeta)
    root = np.sqrt((1.0 - zeta) * (1.0 + zeta))
    plus = s + 2.0 * zeta * root
    product, ok2 = half_power_product_columns(zeta)
    exists = (s > 0.0) & (product > 0.0)
    minus = product / plus
    spread = 4.0 * zeta * root
    if kind != "unbalance":
        low = np.sqrt(minus)
        return spread / (np.sqrt(plus) + low), exists, ok & ok2, np.sqrt(plus)
    return (spread / ((np.sqrt(plus) + np.sqrt(minus)) * np.sqrt(product)), exists, ok & ok2,
            1.0 / np.sqrt(plus))


def _half_power_base(zeta):
    """The base-motion half-power bandwidth (:func:`dyncalc.physics.forced._half_power_base`,
    ``zeta >= 1e-100``: :data:`DOMAIN` keeps to it)."""
    a = 4.0 * zeta * zeta
    r = _hypot(np.ones_like(zeta), _SQRT8 * zeta)
    s = 2.0 / (1.0 + r)
    w = _square(_SQRT8 * zeta / (1.0 + r))
    den = w * w + a * s
    p = (1.0 + a * s) / den
    n = 2.0 * (1.0 + a) * w * w + a * (1.0 - 2.0 * w) + a * a * s
    lin = a * (p - 2.0)
    disc = np.sqrt(lin * lin + 4.0 * p * n / den)
    q = lin + np.copysign(disc, lin)
    w1 = q / (2.0 * p)
    w2 = -n / (den * p * w1)
    w_pos = np.where(w2 > w1, w2, w1)
    w_neg = np.where(w2 < w1, w2, w1)
    high = np.sqrt(1.0 - w_neg)
    exists = 1.0 - w_pos > 0.0
    low = np.sqrt(1.0 - w_pos)
    return (disc / p) / (high + low), exists, np.ones(len(zeta), dtype=bool), high


def _libm(function):
    """``function`` row by row (CPython's libm, as the one-off calls it), NaN where it raises."""
    def safe(x: float) -> float:
        try:
            return function(x)
        except (OverflowError, ValueError):
            return math.nan
    return lambda array: elementwise(safe, array)


_cos, _sin, _exp = _libm(math.cos), _libm(math.sin), _libm(math.exp)


def total_response_columns(omega, zeta, Omega, X, phi, sign: float, x0, v0, t):
    """:func:`dyncalc.physics.forced.total_response` on columns, bit for bit: the steady state
    ``sign X cos(Omega t - phi)`` plus :func:`transient_columns` from ``x0 - sign X cos phi``,
    ``v0 - sign X Omega sin phi`` (the one-off's operations in its order; ``cos``, ``sin`` and
    ``exp`` are CPython's, row by row)."""
    sx = sign * X
    steady = sx * _cos(Omega * t - phi)
    h0 = x0 - sx * _cos(phi)
    hv = v0 - sx * Omega * _sin(phi)
    return steady + transient_columns(omega, zeta, h0, hv, t)


def transient_columns(omega, zeta, x0, v0, t):
    """:func:`dyncalc.physics.forced.transient` on columns, each row through its own branch
    (``t = 0``; critical within :data:`~dyncalc.physics.outcome.CRITICAL_BAND`; under- and
    overdamped), with the one-off's float operations in its order.

    >>> import numpy as np
    >>> transient_columns(np.ones(1), np.zeros(1), np.ones(1), np.zeros(1),
    ...                   np.array([math.pi])).round(15).tolist()   # cos(pi)
    [-1.0]
    """
    with np.errstate(all="ignore"):  # rows beyond float64 give what the one-off gives
        return _transient(omega, zeta, x0, v0, t)


def _transient(omega, zeta, x0, v0, t):
    decay = _exp(-zeta * omega * t)
    band = (1.0 - zeta) * (1.0 + zeta)
    critical = np.abs(band) <= CRITICAL_BAND
    under = ~critical & (zeta < 1.0)
    over = ~critical & ~under
    b = v0 + zeta * omega * x0
    out = decay * (x0 + (v0 + omega * x0) * t)
    if under.any():
        wd = omega * np.sqrt(np.where(under, band, 1.0))
        out = np.where(under, decay * (x0 * _cos(wd * t) + b * _sin(wd * t) / wd), out)
    if over.any():
        root = np.sqrt(np.where(over, zeta - 1.0, 1.0)) * np.sqrt(zeta + 1.0)
        ws = omega * root
        slow, fast = _exp(-(omega / (zeta + root)) * t), _exp(-(zeta * omega + ws) * t)
        out = np.where(over, 0.5 * x0 * (slow + fast) + 0.5 * b * (slow - fast) / ws, out)
    return np.where(t == 0.0, x0, out)
