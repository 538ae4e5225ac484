"""Limit: forced-response (k [N/m], m [kg], zeta, F0 [N], Omega [rad/s]), damped below the
peak's and the bandwidth's limits (zeta < 0.38): the steady state of _forced.py (its docstring
says how each term is rounded, as dyncalc rounds it)."""
from _forced import steady, write_steady
from _limit import arguments, number, read

path, as_json = arguments()
df = read(path)
columns = [("k [N/m]", "k", "N/m"), ("m [kg]", "m", "kg"), ("zeta", "zeta", ""),
           ("F0 [N]", "F0", "N"), ("Omega [rad/s]", "Omega", "rad/s")]
k, m, zeta, F0, W = (number(df, c) for c, _, _ in columns)
values, units = steady(k, m, zeta, F0, W)
write_steady(df, columns, values, units, as_json)
