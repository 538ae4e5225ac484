"""The forced-response limit scripts' shared part: the steady state of the mass-spring-damper
driven by a force, a column at a time, and its CSV / JSON lines output.

``1 - eta^2 = (k - m Omega^2)/k``, ``1 - 2 zeta^2`` and ``1 - 8 zeta^2 + 8 zeta^4`` are taken
exactly as dyncalc takes them (Dekker products summed by fsum's twin; the quotient a
double-double, certified, with Fraction on the rare row it cannot certify), using the twins
of dyncalc.physics.numerics_arrays (a numpy-only module); ``hypot`` and ``atan2`` are Python's,
row by row (numpy's round differently); the rest is plain float arithmetic in dyncalc's
order."""
import math
from fractions import Fraction

import numpy as np
import polars as pl

from dyncalc.physics.numerics_arrays import (dd_div, fsum_rows, round_certified,
                                             two_product_array)
from _limit import csv_line, json_input, json_lines, json_result, text

HEAD = ('"schema": "dyncalc/2", "command": "forced-response", "scene": '
        '"mass-spring-damper", "model": "linear", "method": "closed-form"')


def rowwise(function, *columns):
    return np.fromiter(map(function, *(c.tolist() for c in columns)), dtype=float,
                       count=len(columns[0]))


def exact_sum(*terms):
    return fsum_rows(np.column_stack(terms))[0]


def one_minus_eta_squared(k, m, W):
    """``(k - m W^2)/k``, correctly rounded."""
    p, e = two_product_array(W, W)
    q1, f1 = two_product_array(m, p)
    q2, f2 = two_product_array(m, e)
    hi = exact_sum(k, -q1, -f1, -q2, -f2)
    lo = exact_sum(k, -q1, -f1, -q2, -f2, -hi)
    gap, certain = round_certified(*dd_div(hi, lo, k, np.zeros_like(k)), 2.0 ** -100)
    for i in np.flatnonzero(~certain).tolist():
        gap[i] = float((Fraction(k[i]) - Fraction(m[i]) * Fraction(W[i]) ** 2)
                       / Fraction(k[i]))
    return gap


def steady(k, m, zeta, F0, W):
    """The damped steady state's results (dyncalc's order) and their units, and ``gap``."""
    ones = np.ones_like(k)
    gap = one_minus_eta_squared(k, m, W)
    omega = np.sqrt(k / m)
    eta = W / omega
    two_ze = 2.0 * zeta * eta
    TR = rowwise(math.hypot, ones, two_ze) / rowwise(math.hypot, gap, two_ze)
    V = 1.0 / rowwise(math.hypot, gap, 2.0 * zeta * eta)
    static = F0 / k
    V_res = 1.0 / rowwise(math.hypot, np.zeros_like(zeta), 2.0 * zeta * 1.0)
    z2, z2e = two_product_array(zeta, zeta)
    s = exact_sum(ones, -2.0 * z2, -2.0 * z2e)
    V_peak = 1.0 / (2.0 * zeta * np.sqrt((1.0 - zeta) * (1.0 + zeta)))
    root = np.sqrt((1.0 - zeta) * (1.0 + zeta))
    plus = s + 2.0 * zeta * root
    a1, b1 = two_product_array(z2, z2)
    a2, b2 = two_product_array(2.0 * z2, z2e)
    a3, b3 = two_product_array(z2e, z2e)
    product = exact_sum(ones, -8.0 * z2, -8.0 * z2e, 8.0 * a1, 8.0 * b1, 8.0 * a2, 8.0 * b2,
                        8.0 * a3, 8.0 * b3)
    width = 4.0 * zeta * root / (np.sqrt(plus) + np.sqrt(product / plus))
    values = {"omega": omega, "zeta": zeta, "eta": eta, "X": static * V,
              "phi": rowwise(math.atan2, two_ze, gap), "V": V, "TR": TR, "F_T": F0 * TR,
              "X_res": static * V_res, "V_res": V_res, "Omega_peak": np.sqrt(s) * omega,
              "X_peak": static * V_peak, "V_peak": V_peak,
              "Omega_iso": math.sqrt(2.0) * omega, "isolation": 1.0 - TR,
              "bandwidth": width * omega, "Q": 0.5 / zeta}
    units = {"omega": "rad/s", "zeta": "", "eta": "", "X": "m", "phi": "rad", "V": "",
             "TR": "", "F_T": "N", "X_res": "m", "V_res": "", "Omega_peak": "rad/s",
             "X_peak": "m", "V_peak": "", "Omega_iso": "rad/s", "isolation": "",
             "bandwidth": "rad/s", "Q": ""}
    return values, units


def write_steady(df, columns, values, units, as_json):
    """dyncalc's output of these results: ``isolation`` only on the rows with ``TR < 1``; in
    CSV its column stands in its place if the first row has it, last if only a later one
    does (dyncalc's header is the results in the order they first appear)."""
    isolated = values["TR"] < 1.0
    out = {n: text(v) for n, v in values.items()}
    mask = pl.Series(isolated)
    if as_json:
        inputs = [p for i, (col, n, u) in enumerate(columns)
                  for p in json_input(df, col, n, u, i == 0)]
        results = []
        for i, (n, v) in enumerate(out.items()):
            if n == "isolation":
                results.append(pl.select(pl.when(pl.lit(mask)).then(pl.concat_str(
                    [pl.lit(', "isolation": {"value": '), pl.lit(v), pl.lit(', "unit": ""}')]))
                    .otherwise(pl.lit(""))).to_series())
            else:
                results += json_result(n, v, units[n], i == 0)
        json_lines(len(df), HEAD, inputs, results)
        return
    iso = out["isolation"]
    if isolated.any():
        column = pl.select(pl.when(pl.lit(mask)).then(pl.lit(iso)).otherwise(None)).to_series()
        if isolated[0]:
            out["isolation"] = column
        else:
            del out["isolation"]
            out["isolation"] = column
    else:
        del out["isolation"]
    shown = {"zeta": "zeta_result"}
    csv_line(df, out, {n: f"{shown.get(n, n)} [{u}]" if u else shown.get(n, n)
                       for n, u in units.items()})
