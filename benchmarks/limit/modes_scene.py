"""Limit (issue 17): ``modes --scene coupled-blocks`` (m1 [kg], m2 [kg], k1, k2, k3 [N/m]) ->
omega_i, f_i, mode_i, modal_mass_i, modal_stiffness_i.

The scene's matrices ``M = diag(m1, m2)``, ``K = [[k1 + k3, -k3], [-k3, k2 + k3]]``, then the
same math as dyncalc's stacked path: ``M = L L^T``, eigh of ``L^-1 K L^-T``, shapes
``L^-T w`` scaled to a largest component of +1, ``m_i = phi^T M phi``, ``k_i = phi^T K phi``
(numpy on the stack)."""
import json
import math

import numpy as np
import polars as pl

from _limit import (arguments, csv_line, json_input, json_lines, json_result, number, read,
                    text)

path, as_json = arguments()
df = read(path)
columns = [("m1 [kg]", "m1", "kg"), ("m2 [kg]", "m2", "kg"), ("k1 [N/m]", "k1", "N/m"),
           ("k2 [N/m]", "k2", "N/m"), ("k3 [N/m]", "k3", "N/m")]
m1, m2, k1, k2, k3 = (number(df, c) for c, _, _ in columns)
rows, n = len(df), 2
zero = np.zeros(rows)
M = np.stack([np.stack([m1, zero], -1), np.stack([zero, m2], -1)], -2)
K = np.stack([np.stack([k1 + k3, -k3], -1), np.stack([-k3, k2 + k3], -1)], -2)
L = np.linalg.cholesky(M)
A = np.linalg.solve(L, np.linalg.solve(L, K).transpose(0, 2, 1))
lam, W = np.linalg.eigh((A + A.transpose(0, 2, 1)) / 2.0)
V = np.linalg.solve(L.transpose(0, 2, 1), W)
reference = np.argmax(np.abs(V), axis=1)
r, cols = np.arange(rows)[:, None], np.arange(n)[None, :]
shapes = V / V[r, reference, cols][:, None, :]
largest = np.abs(shapes[r, reference, cols])
shapes = np.where(np.abs(shapes) < 2.0 ** -46 * largest[:, None, :], 0.0, shapes) + 0.0
shapes[r, reference, cols] = 1.0
omega = np.sqrt(lam)
modal_mass = np.sum(shapes * (M @ shapes), axis=1)
modal_stiffness = np.sum(shapes * (K @ shapes), axis=1)
values, units = {}, {}
for i in range(n):
    values[f"omega_{i + 1}"], units[f"omega_{i + 1}"] = text(omega[:, i]), "rad/s"
for i in range(n):
    values[f"f_{i + 1}"], units[f"f_{i + 1}"] = text(omega[:, i] / (2.0 * math.pi)), "Hz"
for i in range(n):
    values[f"mode_{i + 1}"] = (shapes[:, 0, i], shapes[:, 1, i])
    units[f"mode_{i + 1}"] = ""
    values[f"modal_mass_{i + 1}"], units[f"modal_mass_{i + 1}"] = text(modal_mass[:, i]), "kg"
    values[f"modal_stiffness_{i + 1}"] = text(modal_stiffness[:, i])
    units[f"modal_stiffness_{i + 1}"] = "N/m"

if as_json:
    head = ('"schema": "dyncalc/2", "command": "modes", "scene": "coupled-blocks", '
            '"model": "linear", "method": "eigh"')
    inputs = [p for i, (c, name, unit) in enumerate(columns)
              for p in json_input(df, c, name, unit, i == 0)]
    results = []
    for i, (name, value) in enumerate(values.items()):
        shown = value if not isinstance(value, tuple) else pl.concat_str(
            [pl.lit("["), pl.lit(text(value[0])), pl.lit(", "), pl.lit(text(value[1])),
             pl.lit("]")])
        results += json_result(name, shown, units[name], i == 0)
    extra = json.dumps({"coordinates": [{"name": f"x{i + 1}", "kind": "translation",
                                         "unit": "m"} for i in range(n)],
                        "normalize": "max", "equilibrium": "x1 = x2 = 0 (springs unstretched)"})
    json_lines(rows, head, inputs, results, extra)
else:
    shown = {name: pl.concat_str([pl.lit(text(value[0])), pl.lit(","), pl.lit(text(value[1]))])
             if isinstance(value, tuple) else value for name, value in values.items()}
    csv_line(df, shown, {name: f"{name} [{u}]" if u else name for name, u in units.items()})
