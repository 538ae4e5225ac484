"""Limit (issue 17): modes of two-mass chains, ``M`` and ``K`` (and, with ``damped``, ``C``)
as quoted 2x2 cells of bare numbers (``"[[m1,0],[0,m2]]"``) -> omega_i, f_i, mode_i,
modal_mass_i, modal_stiffness_i (and zeta_i, omega_d_i of proportional damping).

The same math as dyncalc's stacked path: ``M = L L^T``, eigh of ``L^-1 K L^-T``, shapes
``L^-T w`` scaled to a largest component of +1, ``m_i = phi^T M phi``, ``k_i = phi^T K phi``
(numpy on the stack); with C, ``zeta_i = (V^T C V)_ii / (2 omega_i)`` on the mass-normalised
shapes ``V`` and ``omega_d_i = omega_i sqrt((1 - zeta_i)(1 + zeta_i))``."""
import sys
import json

import numpy as np

from _limit import arguments, json_lines, json_result, read, text
from _modes import matrices, pair, undamped, undamped_values, write_csv

damped = sys.argv[1] == "damped"  # modes.py [damped] FILE [--json]
if damped:
    del sys.argv[1]
path, as_json = arguments()
df = read(path)
M, K = matrices(df, "M"), matrices(df, "K")
M = (M + M.transpose(0, 2, 1)) / 2.0
K = (K + K.transpose(0, 2, 1)) / 2.0
if damped:
    C = matrices(df, "C")
    C = (C + C.transpose(0, 2, 1)) / 2.0
_L, _A, V, omega, shapes, modal_mass, modal_stiffness = undamped(M, K)
rows, n = len(M), 2
values, units = undamped_values(omega, shapes, modal_mass, modal_stiffness)
if damped:
    zeta = np.diagonal(V.transpose(0, 2, 1) @ C @ V, axis1=1, axis2=2) / (2.0 * omega)
    omega_d = omega * np.sqrt((1.0 - zeta) * (1.0 + zeta))
    for i in range(n):
        values[f"zeta_{i + 1}"], units[f"zeta_{i + 1}"] = text(zeta[:, i]), ""
    for i in range(n):
        values[f"omega_d_{i + 1}"], units[f"omega_d_{i + 1}"] = text(omega_d[:, i]), "rad/s"

if as_json:
    head = ('"schema": "dyncalc/2", "command": "modes", "scene": null, '
            f'"model": "{"proportional damping" if damped else "linear"}", "method": "eigh"')
    inputs = []
    given = [("M", "kg"), ("K", "N/m")] + ([("C", "N*s/m")] if damped else [])
    for name, unit in given:
        X = matrices(df, name)
        inputs += [(", " if inputs else "") + f'"{name}": {{"value": [', pair(X[:, 0, 0],
                   X[:, 0, 1]), ", ", pair(X[:, 1, 0], X[:, 1, 1]),
                   f'], "unit": "{unit}", "text": "', df[name], '", "assumed_si": true}']
    results = []
    for i, (name, value) in enumerate(values.items()):
        shown = pair(*value) if isinstance(value, tuple) else value
        results += json_result(name, shown, units[name], i == 0)
    extra = json.dumps({"coordinates": [{"name": f"q{i + 1}", "kind": "translation",
                                         "unit": "m"} for i in range(n)],
                        "normalize": "max"})
    json_lines(rows, head, inputs, results, extra)
else:
    write_csv(df, values, units)
