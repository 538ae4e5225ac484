"""Limit: eom --scene spring-coupled-pendulums (m, l, k, phi1, phi2, phi1_dot, phi2_dot; b and
g at their defaults, b = 0): the equations as derived (the same texts every row), the five
equilibria in the domain 0 <= phi2 <= pi/2 (phi1 = phi2 = 0 stable; pi, 0; +-pi/2, pi/2;
pi, acos(g m / (2 k l)), every row here with g m <= 2 k l), M and K at the first (the
generated expressions of dyncalc/scenes/eom_tables2.py at phi = 0, the same float operations
in the same order), the two frequencies from the scaled symmetric reduction, the two
accelerations; each row's equilibria text and JSON extra written from its numbers."""
import numpy as np
import polars as pl
from _limit import (TWO_PI, arguments, csv_line, joined, json_input, json_lines, json_result,
                    number, read, text, two_lams)

G = 9.80665
path, as_json = arguments()
df = read(path)
m, l, k = number(df, "m [kg]"), number(df, "l [m]"), number(df, "k [N/m]")
phi1, phi2 = number(df, "phi1 [rad]"), number(df, "phi2 [rad]")
b, zero = np.zeros(len(df)), np.zeros(len(df))
apart = np.arccos(G * m / (2 * k * l))
M00 = 2*l**2*m
c, s = np.cos(zero), np.sin(zero)
K00 = 2*G*l*m*c*c
K01 = -2*G*l*m*s*s
K11 = 2*G*l*m*c*c + 4*k*l**2*c**2 - 2*k*l*(-b + 2*l*s)*s
det_m = 4*l**4*m**2
det_k = 4*G*l**2*m*(b*k*s*c*c + G*m*c**2 + G*m*c**2 - G*m + 4*k*l*c*c**3 - 2*k*l*c*c)
lo, hi = two_lams(M00, 0.0, M00, K00, K01, K11, det_m, det_k)
omega1, omega2 = np.sqrt(lo), np.sqrt(hi)
a1 = -G*np.sin(phi1)*np.cos(phi2)/l
a2 = (-G*m*np.sin(phi2)*np.cos(phi1) + k*(b - 2*l*np.sin(phi2))*np.cos(phi2))/(l*m)
EOM1 = "phi1'' = -g*sin(phi1)*cos(phi2)/l"
EOM2 = "phi2'' = (-g*m*sin(phi2)*cos(phi1) + k*(b - 2*l*sin(phi2))*cos(phi2))/(l*m)"
FOUR = ("phi1=0, phi2=0 (stable); phi1=3.14159, phi2=0 (unstable); phi1=1.5708, phi2=1.5708 "
        "(unstable); phi1=-1.5708, phi2=1.5708 (unstable); phi1=3.14159, phi2={:.6g} "
        "(unstable)")
eq = pl.Series(list(map(FOUR.format, apart.tolist())))
units = {"eom_1": "", "eom_2": "", "equilibria": "", "mass_matrix": "kg*m^2",
         "stiffness_matrix": "N*m/rad", "omega_1": "rad/s", "omega_2": "rad/s", "f_1": "Hz",
         "f_2": "Hz", "phi1_ddot": "rad/s^2", "phi2_ddot": "rad/s^2"}
M00, K00, K01, K11 = text(M00), text(K00), text(K01), text(K11)
if as_json:
    head = ('"schema": "dyncalc/2", "command": "eom", "scene": "spring-coupled-pendulums", '
            '"model": "lagrange", "method": "symbolic + numeric equilibria"')
    inputs = json_input(df, "m [kg]", "m", "kg", True) + json_input(df, "l [m]", "l", "m")
    inputs += json_input(df, "k [N/m]", "k", "N/m")
    inputs += [', "b": {"value": 0.0, "unit": "m", "text": "0 m"}, "g": {"value": 9.80665, '
               '"unit": "m/s^2", "text": "9.80665 m/s^2"}']
    results = [f'"eom_1": {{"value": "{EOM1}", "unit": ""}}, "eom_2": {{"value": "{EOM2}", '
               '"unit": ""}, "equilibria": {"value": "', eq, '", "unit": ""}, "mass_matrix": '
               '{"value": [[', M00, ", 0.0], [0.0, ", M00, ']], "unit": "kg*m^2"}, '
               '"stiffness_matrix": {"value": [[', K00, ", ", K01, "], [", K01, ", ", K11,
               ']], "unit": "N*m/rad"}']
    for name, values in (("omega_1", omega1), ("omega_2", omega2), ("f_1", omega1 / TWO_PI),
                         ("f_2", omega2 / TWO_PI), ("phi1_ddot", a1), ("phi2_ddot", a2)):
        results += json_result(name, text(values), units[name])
    pi, half = repr(np.pi), repr(np.pi / 2)
    json_lines(len(df), head, inputs, results, [
        '{"equilibria": [{"phi1": 0.0, "phi2": 0.0, "stable": true}, {"phi1": ' + pi
        + ', "phi2": 0.0, "stable": false}, {"phi1": ' + half + ', "phi2": ' + half
        + ', "stable": false}, {"phi1": -' + half + ', "phi2": ' + half + ', "stable": '
        'false}, {"phi1": ' + pi + ', "phi2": ', text(apart), ', "stable": false}], "about": '
        '{"phi1": 0.0, "phi2": 0.0}}'])
else:
    out = {"eom_1": EOM1, "eom_2": EOM2, "equilibria": eq,
           "mass_matrix": joined(M00, ",0.0;0.0,", M00),
           "stiffness_matrix": joined(K00, ",", K01, ";", K01, ",", K11),
           "omega_1": text(omega1), "omega_2": text(omega2), "f_1": text(omega1 / TWO_PI),
           "f_2": text(omega2 / TWO_PI), "phi1_ddot": text(a1), "phi2_ddot": text(a2)}
    csv_line(df, out, {n: f"{n} [{u}]" if u else n for n, u in units.items()})
