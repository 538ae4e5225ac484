"""Limit: eom --scene bead-on-rotating-ring (r, Omega, theta, theta_dot; g at its default):
the equilibria 0, pi and, where Omega^2 r > g, +-acos(g/(Omega^2 r)) (then the stable ones,
else the bottom), M = r^2, K = Omega^2 r^2 (sin^2 - cos^2) + g r cos at the one chosen,
omega = sqrt(K/M), theta'' = (Omega^2 r cos(theta) - g) sin(theta)/r (per unit mass); each
row's equilibria text and JSON extra written from its numbers."""
import numpy as np
import polars as pl
from _limit import (TWO_PI, arguments, csv_line, json_lines, json_input, json_result, number,
                    read, text)

G = 9.80665
path, as_json = arguments()
df = read(path)
r, spin = number(df, "r [m]"), number(df, "Omega [rad/s]")
theta, rate = number(df, "theta [rad]"), number(df, "theta_dot [rad/s]")
with np.errstate(invalid="ignore"):
    ride = np.arccos(G / (spin ** 2 * r))
riding = ~np.isnan(ride)
at = np.where(riding, ride, 0.0)
M = r ** 2
K = spin ** 2 * r ** 2 * np.sin(at) ** 2 - spin ** 2 * r ** 2 * np.cos(at) ** 2 \
    + G * r * np.cos(at)
omega = np.sqrt(K / M)
acc = (spin ** 2 * r * np.cos(theta) - G) * np.sin(theta) / r
EOM = "theta'' = (Omega^2*r*cos(theta) - g)*sin(theta)/r"
low = "theta=0 (stable); theta=3.14159 (unstable)"
eq = [f"theta=0 (unstable); theta={v:.6g} (stable); theta={-v:.6g} (stable); "
      "theta=3.14159 (unstable)" if ok else low for v, ok in zip(at.tolist(), riding.tolist())]
eq = pl.Series(eq)
units = {"eom_1": "", "equilibria": "", "mass_matrix": "m^2",
         "stiffness_matrix": "m^2/s^2/rad", "omega_1": "rad/s", "f_1": "Hz",
         "theta_ddot": "rad/s^2"}
if as_json:
    head = ('"schema": "dyncalc/2", "command": "eom", "scene": "bead-on-rotating-ring", '
            '"model": "lagrange", "method": "symbolic + numeric equilibria"')
    inputs = json_input(df, "r [m]", "r", "m", True) + json_input(df, "Omega [rad/s]", "Omega",
                                                                    "rad/s")
    inputs.append(', "g": {"value": 9.80665, "unit": "m/s^2", "text": "9.80665 m/s^2"}')
    results = [f'"eom_1": {{"value": "{EOM}", "unit": ""}}, "equilibria": {{"value": "', eq,
               '", "unit": ""}, "mass_matrix": {"value": [[', text(M),
               ']], "unit": "m^2"}, "stiffness_matrix": {"value": [[', text(K),
               ']], "unit": "m^2/s^2/rad"}']
    for name, values in (("omega_1", omega), ("f_1", omega / TWO_PI), ("theta_ddot", acc)):
        results += json_result(name, text(values), units[name])
    top = ', {"theta": 3.141592653589793, "stable": false}], "about": {"theta": '
    extra = pl.Series([
        f'{{"equilibria": [{{"theta": 0.0, "stable": false}}, {{"theta": {v!r}, "stable": '
        f'true}}, {{"theta": {-v!r}, "stable": true}}{top}{v!r}}}}}' if ok else
        '{"equilibria": [{"theta": 0.0, "stable": true}' + top + '0.0}}'
        for v, ok in zip(at.tolist(), riding.tolist())])
    json_lines(len(df), head, inputs, results, [extra])
else:
    out = {"eom_1": EOM, "equilibria": eq, "mass_matrix": text(M), "stiffness_matrix": text(K),
           "omega_1": text(omega), "f_1": text(omega / TWO_PI), "theta_ddot": text(acc)}
    csv_line(df, out, {n: f"{n} [{u}]" if u else n for n, u in units.items()})
