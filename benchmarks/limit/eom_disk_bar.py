"""Limit: eom --scene disk-on-swinging-bar (m1, l, m2, J2, phi, x, phi_dot, x_dot; g at its
default): the equations as derived (the same texts every row), no equilibrium (phi = +-pi/2,
x = -m1 l / (2 m2) lies off the bar 0 <= x <= l for every row here), the two accelerations
(the generated expressions of dyncalc/scenes/eom_tables2.py, the same float operations in the
same order) and the one-off's warning on every row (JSON lines: in ``warnings``; CSV: a
``warning:`` line a row on stderr)."""
import numpy as np
import polars as pl
from _limit import (arguments, csv_line, json_input, json_result, number, read, text,
                    warning_lines, write)

G = 9.80665
WARNING = "no equilibrium: the system is never at rest at these values"
path, as_json = arguments()
df = read(path)
m1, l, m2 = number(df, "m1 [kg]"), number(df, "l [m]"), number(df, "m2 [kg]")
J2 = number(df, "J2 [kg*m^2]")
phi, x = number(df, "phi [rad]"), number(df, "x [m]")
phi_dot, x_dot = number(df, "phi_dot [rad/s]"), number(df, "x_dot [m/s]")
aphi = ((-2*x_dot*phi_dot*m2*x + G*(-1/2*l*m1 - m2*x)*np.sin(phi))
        / (J2 + (1/3)*l**2*m1 + m2*x**2))
ax = phi_dot**2*x + G*np.cos(phi)
EOM1 = "phi'' = (g*(-l*m1/2 - m2*x)*sin(phi) - 2*m2*phi'*x*x')/(J2 + l^2*m1/3 + m2*x^2)"
EOM2 = "x'' = g*cos(phi) + phi'^2*x"
units = {"eom_1": "", "eom_2": "", "equilibria": "", "phi_ddot": "rad/s^2", "x_ddot": "m/s^2"}
if as_json:
    head = ('"schema": "dyncalc/2", "command": "eom", "scene": "disk-on-swinging-bar", '
            '"model": "lagrange", "method": "symbolic"')
    inputs = json_input(df, "m1 [kg]", "m1", "kg", True) + json_input(df, "l [m]", "l", "m")
    inputs += json_input(df, "m2 [kg]", "m2", "kg")
    inputs += json_input(df, "J2 [kg*m^2]", "J2", "kg*m^2")
    inputs += [', "g": {"value": 9.80665, "unit": "m/s^2", "text": "9.80665 m/s^2"}']
    results = [f'"eom_1": {{"value": "{EOM1}", "unit": ""}}, "eom_2": {{"value": "{EOM2}", '
               '"unit": ""}, "equilibria": {"value": "none", "unit": ""}']
    results += json_result("phi_ddot", text(aphi), "rad/s^2")
    results += json_result("x_ddot", text(ax), "m/s^2")
    line = pl.Series(np.arange(2, len(df) + 2)).cast(pl.String)
    write(['{"line": ', line, ", " + head + ', "inputs": {', *inputs, '}, "results": {',
           *results, '}, "warnings": ["' + WARNING + '"], "extra": {"equilibria": []}}'])
else:
    out = {"eom_1": EOM1, "eom_2": EOM2, "equilibria": "none", "phi_ddot": text(aphi),
           "x_ddot": text(ax)}
    csv_line(df, out, {n: f"{n} [{u}]" if u else n for n, u in units.items()})
    warning_lines(len(df), WARNING)
