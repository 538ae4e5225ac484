"""Limit (issue 17): modes of two-mass chains with damping that is not proportional, ``M``,
``K`` and ``C`` as quoted 2x2 cells of bare numbers -> omega_i, f_i, mode_i, modal_mass_i,
modal_stiffness_i, zeta_i, omega_d_i, and the one-off's note on every row (JSON lines: in
``warnings``; CSV: a ``warning:`` line a row on stderr).

The same math as dyncalc's stacked path (dyncalc/physics/modes_columns.py): ``M = L L^T``,
eigh of ``A = L^-1 K L^-T``, shapes ``V = L^-T w`` scaled to a largest component of +1; the
reduced state-space matrix ``[[0, I], [-A, -L^-1 C L^-T]]``, its eigenvalues with ``Im s >
0`` by ascending ``|s|``, each matched to the free undamped mode of nearest omega:
``zeta = -Re s / |s|``, ``omega_d = Im s``, ``|s|`` in dyncalc's scaled form."""
import numpy as np
import polars as pl

from _limit import arguments, json_result, read, text, warning_lines, write
from _modes import matrices, pair, undamped, undamped_values, write_csv

NOTE = ("the damping is not proportional (Phi^T C Phi is not diagonal: C M^-1 K != K M^-1 C), "
        "so the modes are complex; zeta_i and omega_d_i come from the eigenvalues s = -zeta "
        "omega +- i omega_d of the state-space form, and mode_i are the undamped mode shapes")


path, as_json = arguments()
df = read(path)
M, K, C = (matrices(df, name) for name in ("M", "K", "C"))
M, K, C = ((X + X.transpose(0, 2, 1)) / 2.0 for X in (M, K, C))
L, A, V, omega, shapes, modal_mass, modal_stiffness = undamped(M, K)
rows, n = len(M), 2
r = np.arange(rows)[:, None]
Cr = np.linalg.solve(L, np.linalg.solve(L, C).transpose(0, 2, 1))
state = np.zeros((rows, 2 * n, 2 * n))
state[:, :n, n:] = np.eye(n)
state[:, n:, :n] = -A
state[:, n:, n:] = -(Cr + Cr.transpose(0, 2, 1)) / 2.0
s = np.linalg.eigvals(state)


def modulus(z):
    """|z| as b sqrt(1 + (a/b)^2), a <= b the sizes of Re z and Im z (dyncalc's form)."""
    a, b = np.abs(z.real), np.abs(z.imag)
    big, small = np.maximum(a, b), np.minimum(a, b)
    with np.errstate(invalid="ignore", divide="ignore"):
        q = np.where(big > 0.0, small / big, 0.0)
    return big * np.sqrt(1.0 + q * q)


upper = np.where(s.imag > 0.0, modulus(s), np.inf)
order = np.argsort(upper, axis=1)[:, :n]
picked, sizes = s[r, order], upper[r, order]
zeta, omega_d = np.zeros((rows, n)), np.zeros((rows, n))
free = np.ones((rows, n), dtype=bool)
k = np.arange(rows)
for j in range(n):  # the nearest free undamped mode, a mode at a time
    nearest = np.argmin(np.where(free, np.abs(omega - sizes[:, j:j + 1]), np.inf),
                        axis=1)
    free[k, nearest] = False
    zeta[k, nearest] = -picked[:, j].real / modulus(picked[:, j])
    omega_d[k, nearest] = picked[:, j].imag
values, units = undamped_values(omega, shapes, modal_mass, modal_stiffness)
for i in range(n):
    values[f"zeta_{i + 1}"], units[f"zeta_{i + 1}"] = text(zeta[:, i]), ""
for i in range(n):
    values[f"omega_d_{i + 1}"], units[f"omega_d_{i + 1}"] = text(omega_d[:, i]), "rad/s"


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
    write_csv(df, values, units)
    warning_lines(rows, NOTE)
