"""Limit (issue 17): ``modes --scene coupled-blocks`` (m1 [kg], m2 [kg], k1, k2, k3 [N/m]) ->
omega_i, f_i, mode_i, modal_mass_i, modal_stiffness_i.

The scene's matrices ``M = diag(m1, m2)``, ``K = [[k1 + k3, -k3], [-k3, k2 + k3]]``, then the
same math as dyncalc's stacked path: ``M = L L^T``, eigh of ``L^-1 K L^-T``, shapes
``L^-T w`` scaled to a largest component of +1, ``m_i = phi^T M phi``, ``k_i = phi^T K phi``
(numpy on the stack)."""
import json

import numpy as np

from _limit import arguments, json_input, json_lines, json_result, number, read
from _modes import pair, undamped, undamped_values, write_csv

path, as_json = arguments()
df = read(path)
columns = [("m1 [kg]", "m1", "kg"), ("m2 [kg]", "m2", "kg"), ("k1 [N/m]", "k1", "N/m"),
           ("k2 [N/m]", "k2", "N/m"), ("k3 [N/m]", "k3", "N/m")]
m1, m2, k1, k2, k3 = (number(df, c) for c, _, _ in columns)
rows, n = len(df), 2
zero = np.zeros(rows)
M = np.stack([np.stack([m1, zero], -1), np.stack([zero, m2], -1)], -2)
K = np.stack([np.stack([k1 + k3, -k3], -1), np.stack([-k3, k2 + k3], -1)], -2)
_L, _A, _V, omega, shapes, modal_mass, modal_stiffness = undamped(M, K)
values, units = undamped_values(omega, shapes, modal_mass, modal_stiffness)

if as_json:
    head = ('"schema": "dyncalc/2", "command": "modes", "scene": "coupled-blocks", '
            '"model": "linear", "method": "eigh"')
    inputs = [p for i, (c, name, unit) in enumerate(columns)
              for p in json_input(df, c, name, unit, i == 0)]
    results = []
    for i, (name, value) in enumerate(values.items()):
        shown = pair(*value) if isinstance(value, tuple) else value
        results += json_result(name, shown, units[name], i == 0)
    extra = json.dumps({"coordinates": [{"name": f"x{i + 1}", "kind": "translation",
                                         "unit": "m"} for i in range(n)],
                        "normalize": "max", "equilibrium": "x1 = x2 = 0 (springs unstretched)"})
    json_lines(rows, head, inputs, results, extra)
else:
    write_csv(df, values, units)
