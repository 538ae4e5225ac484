"""Limit: eom --scene pendulum (l, phi, phi_dot; g at its default): the equations as derived
(the same text every row), M = l^2, K = g l cos(0), omega = sqrt(K/M), phi'' = -g sin(phi)/l
(per unit mass)."""
import numpy as np
from _limit import (TWO_PI, arguments, csv_line, json_lines, json_input, json_result, number,
                    read, text)

G = 9.80665
path, as_json = arguments()
df = read(path)
l, phi = number(df, "l [m]"), number(df, "phi [rad]")
M = l ** 2
K = G * l * np.cos(np.zeros_like(l))
omega = np.sqrt(K / M)
acc = -G * np.sin(phi) / l
EOM, EQ = "phi'' = -g*sin(phi)/l", "phi=0 (stable); phi=3.14159 (unstable)"
units = {"eom_1": "", "equilibria": "", "mass_matrix": "m^2",
         "stiffness_matrix": "m^2/s^2/rad", "omega_1": "rad/s", "f_1": "Hz",
         "phi_ddot": "rad/s^2"}
if as_json:
    head = ('"schema": "dyncalc/2", "command": "eom", "scene": "pendulum", '
            '"model": "lagrange", "method": "symbolic + numeric equilibria"')
    inputs = json_input(df, "l [m]", "l", "m", True)
    inputs.append(', "g": {"value": 9.80665, "unit": "m/s^2", "text": "9.80665 m/s^2"}')
    results = [f'"eom_1": {{"value": "{EOM}", "unit": ""}}, "equilibria": {{"value": '
               f'"{EQ}", "unit": ""}}, "mass_matrix": {{"value": [[', text(M),
               ']], "unit": "m^2"}, "stiffness_matrix": {"value": [[', text(K),
               ']], "unit": "m^2/s^2/rad"}']
    for name, values in (("omega_1", omega), ("f_1", omega / TWO_PI), ("phi_ddot", acc)):
        results += json_result(name, text(values), units[name])
    json_lines(len(df), head, inputs, results,
               '{"equilibria": [{"phi": 0.0, "stable": true}, {"phi": 3.141592653589793, '
               '"stable": false}], "about": {"phi": 0.0}}')
else:
    out = {"eom_1": EOM, "equilibria": EQ, "mass_matrix": text(M), "stiffness_matrix": text(K),
           "omega_1": text(omega), "f_1": text(omega / TWO_PI), "phi_ddot": text(acc)}
    csv_line(df, out, {n: f"{n} [{u}]" if u else n for n, u in units.items()})
