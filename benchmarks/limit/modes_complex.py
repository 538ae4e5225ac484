"""Limit (issue 17): modes of two-mass chains with damping that is not proportional, ``M``,
``K`` and ``C`` as quoted 2x2 cells of bare numbers -> omega_i, f_i, mode_i, modal_mass_i,
modal_stiffness_i, zeta_i, omega_d_i, and the one-off's note on every row (JSON lines: in
``warnings``; CSV: a ``warning:`` line a row on stderr).

The same math as dyncalc's stacked path (dyncalc/physics/modes_columns.py): ``M = L L^T``,
eigh of ``A = L^-1 K L^-T``, shapes ``V = L^-T w`` scaled to a largest component of +1; the
reduced state-space matrix ``[[0, I], [-A, -L^-1 C L^-T]]``, its eigenvalues with ``Im s >
0`` by ascending ``|s|``, each matched to the free undamped mode of nearest omega:
``zeta = -Re s / |s|``, ``omega_d = Im s``."""
import math
import sys

import numpy as np
import polars as pl

from _limit import arguments, csv_line, json_result, read, text, write

NOTE = ("the damping is not proportional (Phi^T C Phi is not diagonal: C M^-1 K != K M^-1 C), "
        "so the modes are complex; zeta_i and omega_d_i come from the eigenvalues s = -zeta "
        "omega +- i omega_d of the state-space form, and mode_i are the undamped mode shapes")


def matrices(df, column):
    cells = df[column].str.replace_all(r"[\[\] ]", "")
    parts = cells.str.split_exact(",", 3).struct.unnest()
    return np.column_stack([parts[c].cast(pl.Float64).to_numpy()
                            for c in parts.columns]).reshape(-1, 2, 2)


path, as_json = arguments()
df = read(path)
M, K, C = (matrices(df, name) for name in ("M", "K", "C"))
M, K, C = ((X + X.transpose(0, 2, 1)) / 2.0 for X in (M, K, C))
L = np.linalg.cholesky(M)
A = np.linalg.solve(L, np.linalg.solve(L, K).transpose(0, 2, 1))
A = (A + A.transpose(0, 2, 1)) / 2.0
lam, W = np.linalg.eigh(A)
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
Cr = np.linalg.solve(L, np.linalg.solve(L, C).transpose(0, 2, 1))
state = np.zeros((rows, 2 * n, 2 * n))
state[:, :n, n:] = np.eye(n)
state[:, n:, :n] = -A
state[:, n:, n:] = -(Cr + Cr.transpose(0, 2, 1)) / 2.0
s = np.linalg.eigvals(state)
upper = np.where(s.imag > 0.0, np.abs(s), np.inf)
order = np.argsort(upper, axis=1)[:, :n]
picked, sizes = s[r, order], upper[r, order]
zeta, omega_d = np.zeros((rows, n)), np.zeros((rows, n))
free = np.ones((rows, n), dtype=bool)
k = np.arange(rows)
for j in range(n):  # the nearest free undamped mode, a mode at a time
    nearest = np.argmin(np.where(free, np.abs(omega - sizes[:, j:j + 1]), np.inf),
                        axis=1)
    free[k, nearest] = False
    zeta[k, nearest] = -picked[:, j].real / np.abs(picked[:, j])
    omega_d[k, nearest] = picked[:, j].imag
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
            '"model": "non-proportional damping", "method": "eigh+state-space"')
    inputs = []
    for name, unit in (("M", "kg"), ("K", "N/m"), ("C", "N*s/m")):
        X = matrices(df, name)
        inputs += [(", " if inputs else "") + f'"{name}": {{"value": [', pair(X[:, 0, 0],
                   X[:, 0, 1]), ", ", pair(X[:, 1, 0], X[:, 1, 1]),
                   f'], "unit": "{unit}", "text": "', df[name], '", "assumed_si": true}']
    results = []
    for i, (name, value) in enumerate(values.items()):
        shown = pair(*value) if isinstance(value, tuple) else value
        results += json_result(name, shown, units[name], i == 0)
    extra = ('{"coordinates": [{"name": "q1", "kind": "translation", "unit": "m"}, '
             '{"name": "q2", "kind": "translation", "unit": "m"}], "normalize": "max"}')
    line = pl.Series(np.arange(2, rows + 2)).cast(pl.String)
    write(['{"line": ', line, ", " + head + ', "inputs": {', *inputs, '}, "results": {',
           *results, '}, "warnings": ["' + NOTE + '"], "extra": ' + extra + "}"])
else:
    shown = {name: pl.concat_str([pl.lit(text(value[0])), pl.lit(","), pl.lit(text(value[1]))])
             if isinstance(value, tuple) else value for name, value in values.items()}
    csv_line(df, shown, {name: f"{name} [{u}]" if u else name for name, u in units.items()})
    sys.stdout.flush()
    lines = pl.select(pl.concat_str([pl.lit("warning: line "),
                                     pl.Series(np.arange(2, rows + 2)).cast(pl.String),
                                     pl.lit(": " + NOTE)]).alias("w"))
    lines.write_csv(sys.stderr.buffer, include_header=False, quote_style="never")
