"""Limit (issue 17): modes of two-mass chains, ``M`` and ``K`` (and, with ``damped``, ``C``)
as quoted 2x2 cells of bare numbers (``"[[m1,0],[0,m2]]"``) -> omega_i, f_i, mode_i,
modal_mass_i, modal_stiffness_i (and zeta_i, omega_d_i of proportional damping).

The same math as dyncalc's stacked path: ``M = L L^T``, eigh of ``L^-1 K L^-T``, shapes
``L^-T w`` scaled to a largest component of +1, ``m_i = phi^T M phi``, ``k_i = phi^T K phi``
(numpy on the stack); with C, ``zeta_i = (V^T C V)_ii / (2 omega_i)`` on the mass-normalised
shapes ``V`` and ``omega_d_i = omega_i sqrt((1 - zeta_i)(1 + zeta_i))``."""
import sys
import json
import math

import numpy as np
import polars as pl

from _limit import arguments, csv_line, json_lines, json_result, read, text


def matrices(df, column):
    cells = df[column].str.replace_all(r"[\[\] ]", "")
    parts = cells.str.split_exact(",", 3).struct.unnest()
    return np.column_stack([parts[c].cast(pl.Float64).to_numpy()
                            for c in parts.columns]).reshape(-1, 2, 2)


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
L = np.linalg.cholesky(M)
A = np.linalg.solve(L, np.linalg.solve(L, K).transpose(0, 2, 1))
lam, W = np.linalg.eigh((A + A.transpose(0, 2, 1)) / 2.0)
V = np.linalg.solve(L.transpose(0, 2, 1), W)
rows, n = len(M), 2
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
if damped:
    zeta = np.diagonal(V.transpose(0, 2, 1) @ C @ V, axis1=1, axis2=2) / (2.0 * omega)
    omega_d = omega * np.sqrt((1.0 - zeta) * (1.0 + zeta))
    for i in range(n):
        values[f"zeta_{i + 1}"], units[f"zeta_{i + 1}"] = text(zeta[:, i]), ""
    for i in range(n):
        values[f"omega_d_{i + 1}"], units[f"omega_d_{i + 1}"] = text(omega_d[:, i]), "rad/s"


def pair(a, b):
    """Two float columns as ``[a, b]`` (JSON)."""
    return pl.concat_str([pl.lit("["), pl.lit(text(a)), pl.lit(", "), pl.lit(text(b)),
                          pl.lit("]")])


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
    shown = {name: pl.concat_str([pl.lit(text(value[0])), pl.lit(","), pl.lit(text(value[1]))])
             if isinstance(value, tuple) else value for name, value in values.items()}
    csv_line(df, shown, {name: f"{name} [{u}]" if u else name for name, u in units.items()})
