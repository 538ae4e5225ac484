"""Limit (issue 17): eom --scene block-disk-springs (M, m, r, k, x, phi, x_dot, phi_dot; F at
its default 0): the equations as derived (the same texts every row), the one equilibrium
x = F/k = 0, phi = 0 (stable), M = [[M + m, -m r], [-m r, 3/2 m r^2]] and
K = [[k, 0], [0, k r^2]] (a unit on each entry), det M = m r^2 (3 M + m)/2, det K = k^2 r^2,
the two frequencies from the symmetric reduction of ``det(K - lam M) = 0`` as
dyncalc.physics.eom_pairs writes it, and the two accelerations (the generated expressions of
dyncalc/scenes/eom_tables2.py, the same float operations in the same order)."""
import json

import numpy as np
from _limit import (TWO_PI, arguments, csv_line, joined, json_input, json_lines, json_result,
                    number, read, text, two_lams)

path, as_json = arguments()
df = read(path)
M, m, r, k = (number(df, c) for c in ("M [kg]", "m [kg]", "r [m]", "k [N/m]"))
x, phi = number(df, "x [m]"), number(df, "phi [rad]")
F = np.zeros(len(df))
m00, m01, m11 = M + m, -m*r, (3/2)*m*r**2
k00, k01, k11 = k, np.zeros(len(df)), k*r**2
det_m, det_k = (1/2)*m*r**2*(3*M + m), k**2*r**2
lo, hi = two_lams(m00, m01, m11, k00, k01, k11, det_m, det_k)  # (mean > 0 on every row)
tol = 1e-10 * np.maximum(np.abs(lo), np.abs(hi))
omega1 = np.where(lo > tol, np.sqrt(np.where(lo > tol, lo, 0.0)), 0.0)
omega2 = np.where(hi > tol, np.sqrt(np.where(hi > tol, hi, 0.0)), 0.0)
ax = (3*F - 2*k*phi*r - 3*k*x)/(3*M + m)
aphi = 2*(k*phi*r*(M + m) - m*(F - k*x))/(m*r*(-3*M - m))
EOM1 = "x'' = (3*F - 2*k*phi*r - 3*k*x)/(3*M + m)"
EOM2 = "phi'' = 2*(k*phi*r*(M + m) - m*(F - k*x))/(m*r*(-3*M - m))"
EQ = "x=0, phi=0 (stable)"
UNITS = {"mass_matrix": [["kg", "kg*m"], ["kg*m", "kg*m^2"]],
         "stiffness_matrix": [["N/m", "N/rad"], ["N/rad", "N*m/rad"]]}
units = {"eom_1": "", "eom_2": "", "equilibria": "", "mass_matrix": "", "stiffness_matrix": "",
         "omega_1": "rad/s", "omega_2": "rad/s", "f_1": "Hz", "f_2": "Hz",
         "x_ddot": "m/s^2", "phi_ddot": "rad/s^2"}
m00, m01, m11, k00, k11 = text(m00), text(m01), text(m11), text(k00), text(k11)
if as_json:
    head = ('"schema": "dyncalc/2", "command": "eom", "scene": "block-disk-springs", '
            '"model": "lagrange", "method": "symbolic + numeric equilibria"')
    inputs = json_input(df, "M [kg]", "M", "kg", True) + json_input(df, "m [kg]", "m", "kg")
    inputs += json_input(df, "r [m]", "r", "m") + json_input(df, "k [N/m]", "k", "N/m")
    inputs += [', "F": {"value": 0.0, "unit": "N", "text": "0 N"}']
    results = [f'"eom_1": {{"value": "{EOM1}", "unit": ""}}, "eom_2": {{"value": "{EOM2}", '
               f'"unit": ""}}, "equilibria": {{"value": "{EQ}", "unit": ""}}, "mass_matrix": '
               '{"value": [[', m00, ", ", m01, "], [", m01, ", ", m11, ']], "unit": ""}, '
               '"stiffness_matrix": {"value": [[', k00, ", 0.0], [0.0, ", k11,
               ']], "unit": ""}']
    for name, values in (("omega_1", text(omega1)), ("omega_2", text(omega2)),
                         ("f_1", text(omega1 / TWO_PI)), ("f_2", text(omega2 / TWO_PI)),
                         ("x_ddot", text(ax)), ("phi_ddot", text(aphi))):
        results += json_result(name, values, units[name])
    json_lines(len(df), head, inputs, results, json.dumps(
        {"equilibria": [{"x": 0.0, "phi": 0.0, "stable": True}],
         "about": {"x": 0.0, "phi": 0.0}, "matrix_units": UNITS}))
else:
    out = {"eom_1": EOM1, "eom_2": EOM2, "equilibria": EQ,
           "mass_matrix": joined("[[", m00, " kg, ", m01, " kg*m], [", m01, " kg*m, ", m11,
                               " kg*m^2]]"),
           "stiffness_matrix": joined("[[", k00, " N/m, 0.0 N/rad], [0.0 N/rad, ", k11,
                                    " N*m/rad]]"),
           "omega_1": text(omega1), "omega_2": text(omega2), "f_1": text(omega1 / TWO_PI),
           "f_2": text(omega2 / TWO_PI), "x_ddot": text(ax), "phi_ddot": text(aphi)}
    csv_line(df, out, {n: f"{n} [{u}]" if u else n for n, u in units.items()})
