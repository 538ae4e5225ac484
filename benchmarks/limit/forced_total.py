"""Limit: forced-response with the total response (k [N/m], m [kg], zeta, F0 [N],
Omega [rad/s], x0 [m], v0 [m/s], t [s]), damped below the peak's and the bandwidth's limits
(zeta < 0.38): forced_response.py's steady state plus ``x(t)``, the steady state and the
underdamped transient from ``x0 - X cos phi``, ``v0 - X Omega sin phi`` (Python's ``cos``,
``sin`` and ``exp`` row by row, as dyncalc calls them).

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
from _limit import (arguments, csv_line, json_input, json_lines, json_result, number, read,
                    text)


def rowwise(function, *columns):
    return np.fromiter(map(function, *(c.tolist() for c in columns)), dtype=float,
                       count=len(columns[0]))


def exact_sum(*terms):
    return fsum_rows(np.column_stack(terms))[0]


path, as_json = arguments()
df = read(path)
columns = [("k [N/m]", "k", "N/m"), ("m [kg]", "m", "kg"), ("zeta", "zeta", ""),
           ("F0 [N]", "F0", "N"), ("Omega [rad/s]", "Omega", "rad/s"), ("x0 [m]", "x0", "m"),
           ("v0 [m/s]", "v0", "m/s"), ("t [s]", "t", "s")]
k, m, zeta, F0, W, x0, v0, t = (number(df, c) for c, _, _ in columns)
ones = np.ones_like(k)

# 1 - eta^2 = (k - m W^2)/k, exactly rounded
p, e = two_product_array(W, W)
q1, f1 = two_product_array(m, p)
q2, f2 = two_product_array(m, e)
hi = exact_sum(k, -q1, -f1, -q2, -f2)
lo = exact_sum(k, -q1, -f1, -q2, -f2, -hi)
gap, certain = round_certified(*dd_div(hi, lo, k, np.zeros_like(k)), 2.0 ** -100)
for i in np.flatnonzero(~certain).tolist():
    gap[i] = float((Fraction(k[i]) - Fraction(m[i]) * Fraction(W[i]) ** 2) / Fraction(k[i]))

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
isolated = TR < 1.0
X = static * V
phi = rowwise(math.atan2, two_ze, gap)
h0 = x0 - X * rowwise(math.cos, phi)
hv = v0 - X * W * rowwise(math.sin, phi)
wd = omega * np.sqrt((1.0 - zeta) * (1.0 + zeta))
b = hv + zeta * omega * h0
x = X * rowwise(math.cos, W * t - phi) + rowwise(math.exp, -zeta * omega * t) * (
    h0 * rowwise(math.cos, wd * t) + b * rowwise(math.sin, wd * t) / wd)

values = {"omega": omega, "zeta": zeta, "eta": eta, "X": static * V,
          "phi": rowwise(math.atan2, two_ze, gap), "V": V, "TR": TR, "F_T": F0 * TR,
          "X_res": static * V_res, "V_res": V_res, "Omega_peak": np.sqrt(s) * omega,
          "X_peak": static * V_peak, "V_peak": V_peak, "Omega_iso": math.sqrt(2.0) * omega,
          "isolation": 1.0 - TR, "bandwidth": width * omega, "Q": 0.5 / zeta, "x": x}
units = {"omega": "rad/s", "zeta": "", "eta": "", "X": "m", "phi": "rad", "V": "", "TR": "",
         "F_T": "N", "X_res": "m", "V_res": "", "Omega_peak": "rad/s", "X_peak": "m",
         "V_peak": "", "Omega_iso": "rad/s", "isolation": "", "bandwidth": "rad/s", "Q": "",
         "x": "m"}
out = {n: text(v) for n, v in values.items()}
mask = pl.Series(isolated)
if as_json:
    head = ('"schema": "dyncalc/2", "command": "forced-response", "scene": '
            '"mass-spring-damper", "model": "linear", "method": "closed-form"')
    inputs = [p for i, (col, n, u) in enumerate(columns) for p in json_input(df, col, n, u, i == 0)]
    results = []
    for i, (n, v) in enumerate(out.items()):
        if n == "isolation":
            part = pl.select(pl.when(pl.lit(mask)).then(pl.concat_str(
                [pl.lit(', "isolation": {"value": '), pl.lit(v), pl.lit(', "unit": ""}')]))
                .otherwise(pl.lit(""))).to_series()
            results.append(part)
        else:
            results += json_result(n, v, units[n], i == 0)
    json_lines(len(df), head, inputs, results)
else:
    # dyncalc's header is the results in the order they first appear: isolation (on the rows
    # with TR < 1 only) in its place if the first row has it, last if a later one does
    iso = out.pop("isolation")
    if isolated.any():
        column = pl.select(pl.when(pl.lit(mask)).then(pl.lit(iso)).otherwise(None)).to_series()
        if isolated[0]:
            out = {**{n: v for n, v in out.items() if n not in ("bandwidth", "Q", "x")},
                   "isolation": column, "bandwidth": out["bandwidth"], "Q": out["Q"],
                   "x": out["x"]}
        else:  # after every result the first row has
            out["isolation"] = column
    shown = {"zeta": "zeta_result"}
    csv_line(df, out, {n: f"{shown.get(n, n)} [{u}]" if u else shown.get(n, n)
                       for n, u in units.items()})
