"""Limit: eom --scene pendulum-on-sliding-block (m1, m2, l, x, phi, x_dot, phi_dot; g its
default): the equations as derived (the same texts every row), the equilibria phi = 0
(stable) and pi (unstable) with x free, M = [[m1 + m2, l m2], [l m2, l^2 m2]] and
K = [[0, 0], [0, g l m2]] (a unit on each entry), omega_1 = 0 (x free) and omega_2 from the
symmetric reduction of ``det(K - lam M) = 0`` as dyncalc.physics.eom_pairs writes it
(here K_00 = K_01 = 0), and the two accelerations."""
import numpy as np
from _limit import (TWO_PI, arguments, csv_line, joined, json_input, json_lines, json_result,
                    number, read, text, two_lams)

G = 9.80665
path, as_json = arguments()
df = read(path)
m1, m2, l = number(df, "m1 [kg]"), number(df, "m2 [kg]"), number(df, "l [m]")
phi, phi_dot = number(df, "phi [rad]"), number(df, "phi_dot [rad/s]")
m00, m01, m11, k11 = m1 + m2, l * m2 * 1.0, l ** 2 * m2, G * l * m2 * 1.0
det_m = l ** 2 * m2 * (m1 + m2 * 0.0)
_lo, hi = two_lams(m00, m01, m11, 0.0, 0.0, k11, det_m, 0.0)
omega2 = np.sqrt(hi)
s, c = np.sin(phi), np.cos(phi)
ax = m2 * (phi_dot ** 2 * l + G * c) * s / (m1 + m2 * s ** 2)
aphi = -(phi_dot ** 2 * l * m2 * c + G * (m1 + m2)) * s / (l * (m1 + m2 * s ** 2))
EOM1 = "x'' = m2*(g*cos(phi) + l*phi'^2)*sin(phi)/(m1 + m2*sin(phi)^2)"
EOM2 = "phi'' = -(g*(m1 + m2) + l*m2*phi'^2*cos(phi))*sin(phi)/(l*(m1 + m2*sin(phi)^2))"
EQ = "x=any, phi=0 (stable); x=any, phi=3.14159 (unstable)"
units = {"eom_1": "", "eom_2": "", "equilibria": "", "mass_matrix": "", "stiffness_matrix": "",
         "omega_1": "rad/s", "omega_2": "rad/s", "f_1": "Hz", "f_2": "Hz",
         "x_ddot": "m/s^2", "phi_ddot": "rad/s^2"}
m00, m01, m11, k11 = text(m00), text(m01), text(m11), text(k11)
if as_json:
    head = ('"schema": "dyncalc/2", "command": "eom", "scene": "pendulum-on-sliding-block", '
            '"model": "lagrange", "method": "symbolic + numeric equilibria"')
    inputs = json_input(df, "m1 [kg]", "m1", "kg", True) + json_input(df, "m2 [kg]", "m2", "kg")
    inputs += json_input(df, "l [m]", "l", "m")
    inputs += [', "g": {"value": 9.80665, "unit": "m/s^2", "text": "9.80665 m/s^2"}']
    results = [f'"eom_1": {{"value": "{EOM1}", "unit": ""}}, "eom_2": {{"value": "{EOM2}", '
               f'"unit": ""}}, "equilibria": {{"value": "{EQ}", "unit": ""}}, "mass_matrix": '
               '{"value": [[', m00, ", ", m01, "], [", m01, ", ", m11, ']], "unit": ""}, '
               '"stiffness_matrix": {"value": [[0.0, 0.0], [0.0, ', k11, ']], "unit": ""}']
    for name, values in (("omega_1", "0.0"), ("omega_2", text(omega2)), ("f_1", "0.0"),
                         ("f_2", text(omega2 / TWO_PI)), ("x_ddot", text(ax)),
                         ("phi_ddot", text(aphi))):
        results += json_result(name, values, units[name])
    json_lines(len(df), head, inputs, results,
               '{"equilibria": [{"x": null, "phi": 0.0, "stable": true}, {"x": null, '
               '"phi": 3.141592653589793, "stable": false}], "about": {"x": null, "phi": 0.0}, '
               '"matrix_units": {"mass_matrix": [["kg", "kg*m"], ["kg*m", "kg*m^2"]], '
               '"stiffness_matrix": [["N/m", "N/rad"], ["N/rad", "N*m/rad"]]}}')
else:
    out = {"eom_1": EOM1, "eom_2": EOM2, "equilibria": EQ,
           "mass_matrix": joined("[[", m00, " kg, ", m01, " kg*m], [", m01, " kg*m, ", m11,
                               " kg*m^2]]"),
           "stiffness_matrix": joined("[[0.0 N/m, 0.0 N/rad], [0.0 N/rad, ", k11, " N*m/rad]]"),
           "omega_1": "0.0", "omega_2": text(omega2), "f_1": "0.0",
           "f_2": text(omega2 / TWO_PI), "x_ddot": text(ax), "phi_ddot": text(aphi)}
    csv_line(df, out, {n: f"{n} [{u}]" if u else n for n, u in units.items()})
