"""Limit: forced-response with the total response (k [N/m], m [kg], zeta, F0 [N],
Omega [rad/s], x0 [m], v0 [m/s], t [s]), damped below the peak's and the bandwidth's limits
(zeta < 0.38): forced_response.py's steady state plus ``x(t)``, the steady state and the
underdamped transient from ``x0 - X cos phi``, ``v0 - X Omega sin phi`` (Python's ``cos``,
``sin`` and ``exp`` row by row, as dyncalc calls them).

The steady state's terms are rounded as _forced.py's docstring says."""

import math

import numpy as np

from _forced import rowwise, steady, write_steady
from _limit import arguments, number, read

path, as_json = arguments()
df = read(path)
columns = [("k [N/m]", "k", "N/m"), ("m [kg]", "m", "kg"), ("zeta", "zeta", ""),
           ("F0 [N]", "F0", "N"), ("Omega [rad/s]", "Omega", "rad/s"), ("x0 [m]", "x0", "m"),
           ("v0 [m/s]", "v0", "m/s"), ("t [s]", "t", "s")]
k, m, zeta, F0, W, x0, v0, t = (number(df, c) for c, _, _ in columns)
values, units = steady(k, m, zeta, F0, W)

omega, X, phi = values["omega"], values["X"], values["phi"]
h0 = x0 - X * rowwise(math.cos, phi)
hv = v0 - X * W * rowwise(math.sin, phi)
wd = omega * np.sqrt((1.0 - zeta) * (1.0 + zeta))
b = hv + zeta * omega * h0
values["x"] = X * rowwise(math.cos, W * t - phi) + rowwise(math.exp, -zeta * omega * t) * (
    h0 * rowwise(math.cos, wd * t) + b * rowwise(math.sin, wd * t) / wd)
units["x"] = "m"
write_steady(df, columns, values, units, as_json)
