"""Limit: eom --scene coupled-blocks (m1, m2, k1, k2, k3, x1, x2, x1_dot, x2_dot): the equations
as derived (the same texts every row), the one equilibrium x1 = x2 = 0, M = diag(m1, m2),
K = [[k1 + k3, -k3], [-k3, k2 + k3]], the two frequencies by the symmetric reduction of
``det(K - lam M) = 0`` (dyncalc.physics.eom_pairs: scaled by diag(M_ii^-1/2), c = L^-1 K L^-T,
lam = mean +- hypot, the smaller from det K / det M / the larger) and the accelerations."""
import numpy as np
from _limit import (TWO_PI, arguments, csv_line, joined, json_lines, json_input, json_result,
                    number, read, text, two_lams)

path, as_json = arguments()
df = read(path)
m1, m2 = number(df, "m1 [kg]"), number(df, "m2 [kg]")
k1, k2, k3 = number(df, "k1 [N/m]"), number(df, "k2 [N/m]"), number(df, "k3 [N/m]")
x1, x2 = number(df, "x1 [m]"), number(df, "x2 [m]")
K00, K01, K11 = k1 + k3, -k3, k2 + k3
det_m, det_k = m1 * m2, k1 * k2 + k1 * k3 + k2 * k3
lo, hi = two_lams(m1, 0.0, m2, K00, K01, K11, det_m, det_k)
omega1, omega2 = np.sqrt(lo), np.sqrt(hi)
a1 = (-k1 * x1 - k3 * (x1 - x2)) / m1
a2 = (-k2 * x2 + k3 * (x1 - x2)) / m2
EOM1, EOM2 = "x1'' = (-k1*x1 - k3*(x1 - x2))/m1", "x2'' = (-k2*x2 + k3*(x1 - x2))/m2"
EQ = "x1=0, x2=0 (stable)"
units = {"eom_1": "", "eom_2": "", "equilibria": "", "mass_matrix": "kg",
         "stiffness_matrix": "N/m", "omega_1": "rad/s", "omega_2": "rad/s", "f_1": "Hz",
         "f_2": "Hz", "x1_ddot": "m/s^2", "x2_ddot": "m/s^2"}
K00, K01, K11 = text(K00), text(K01), text(K11)
if as_json:
    head = ('"schema": "dyncalc/2", "command": "eom", "scene": "coupled-blocks", '
            '"model": "lagrange", "method": "symbolic + numeric equilibria"')
    inputs = json_input(df, "m1 [kg]", "m1", "kg", True)
    for name, unit in (("m2", "kg"), ("k1", "N/m"), ("k2", "N/m"), ("k3", "N/m")):
        inputs += json_input(df, f"{name} [{unit}]", name, unit)
    results = [f'"eom_1": {{"value": "{EOM1}", "unit": ""}}, "eom_2": {{"value": "{EOM2}", '
               f'"unit": ""}}, "equilibria": {{"value": "{EQ}", "unit": ""}}, "mass_matrix": '
               '{"value": [[', text(m1), ", 0.0], [0.0, ", text(m2), ']], "unit": "kg"}, '
               '"stiffness_matrix": {"value": [[', K00, ", ", K01, "], [", K01, ", ", K11,
               ']], "unit": "N/m"}']
    for name, values in (("omega_1", omega1), ("omega_2", omega2), ("f_1", omega1 / TWO_PI),
                         ("f_2", omega2 / TWO_PI), ("x1_ddot", a1), ("x2_ddot", a2)):
        results += json_result(name, text(values), units[name])
    json_lines(len(df), head, inputs, results,
               '{"equilibria": [{"x1": 0.0, "x2": 0.0, "stable": true}], '
               '"about": {"x1": 0.0, "x2": 0.0}}')
else:
    out = {"eom_1": EOM1, "eom_2": EOM2, "equilibria": EQ,
           "mass_matrix": joined(text(m1), ",0.0;0.0,", text(m2)),
           "stiffness_matrix": joined(K00, ",", K01, ";", K01, ",", K11),
           "omega_1": text(omega1), "omega_2": text(omega2), "f_1": text(omega1 / TWO_PI),
           "f_2": text(omega2 / TWO_PI), "x1_ddot": text(a1), "x2_ddot": text(a2)}
    csv_line(df, out, {n: f"{n} [{u}]" if u else n for n, u in units.items()})
