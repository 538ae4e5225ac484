"""What the modes limit scripts share: 2x2 matrix cells read a column at a time, the undamped
modal analysis on the stack (dyncalc's stacked path: ``M = L L^T``, eigh of ``L^-1 K L^-T``,
shapes ``L^-T w`` scaled to a largest component of +1, ``m_i = phi^T M phi``,
``k_i = phi^T K phi``), its result columns, and their CSV and JSON forms."""
import math

import numpy as np
import polars as pl

from _limit import csv_line, text


def matrices(df, column):
    """The column's ``"[[a,b],[c,d]]"`` cells as a (rows, 2, 2) stack."""
    cells = df[column].str.replace_all(r"[\[\] ]", "")
    parts = cells.str.split_exact(",", 3).struct.unnest()
    return np.column_stack([parts[c].cast(pl.Float64).to_numpy()
                            for c in parts.columns]).reshape(-1, 2, 2)


def undamped(M, K):
    """``(L, A, V, omega, shapes, modal_mass, modal_stiffness)`` of each row: ``A`` the
    symmetrised ``L^-1 K L^-T``, ``V`` the mass-normalised shapes."""
    L = np.linalg.cholesky(M)
    A = np.linalg.solve(L, np.linalg.solve(L, K).transpose(0, 2, 1))
    A = (A + A.transpose(0, 2, 1)) / 2.0
    lam, W = np.linalg.eigh(A)
    V = np.linalg.solve(L.transpose(0, 2, 1), W)
    rows, n = V.shape[0], V.shape[2]
    reference = np.argmax(np.abs(V), axis=1)
    r, cols = np.arange(rows)[:, None], np.arange(n)[None, :]
    shapes = V / V[r, reference, cols][:, None, :]
    largest = np.abs(shapes[r, reference, cols])
    shapes = np.where(np.abs(shapes) < 2.0 ** -46 * largest[:, None, :], 0.0, shapes) + 0.0
    shapes[r, reference, cols] = 1.0
    modal_mass = np.sum(shapes * (M @ shapes), axis=1)
    modal_stiffness = np.sum(shapes * (K @ shapes), axis=1)
    return L, A, V, np.sqrt(lam), shapes, modal_mass, modal_stiffness


def undamped_values(omega, shapes, modal_mass, modal_stiffness):
    """``(values, units)``: the result columns of the undamped modes, in dyncalc's order
    (a mode shape as its two float columns)."""
    values, units = {}, {}
    n = omega.shape[1]
    for i in range(n):
        values[f"omega_{i + 1}"], units[f"omega_{i + 1}"] = text(omega[:, i]), "rad/s"
    for i in range(n):
        values[f"f_{i + 1}"], units[f"f_{i + 1}"] = text(omega[:, i] / (2.0 * math.pi)), "Hz"
    for i in range(n):
        values[f"mode_{i + 1}"] = (shapes[:, 0, i], shapes[:, 1, i])
        units[f"mode_{i + 1}"] = ""
        values[f"modal_mass_{i + 1}"] = text(modal_mass[:, i])
        units[f"modal_mass_{i + 1}"] = "kg"
        values[f"modal_stiffness_{i + 1}"] = text(modal_stiffness[:, i])
        units[f"modal_stiffness_{i + 1}"] = "N/m"
    return values, units


def pair(a, b):
    """Two float columns as ``[a, b]`` (JSON)."""
    return pl.concat_str([pl.lit("["), pl.lit(text(a)), pl.lit(", "), pl.lit(text(b)),
                          pl.lit("]")])


def write_csv(df, values, units):
    """The CSV lines: the input cells, then each result (a shape as ``"a,b"``)."""
    shown = {name: pl.concat_str([pl.lit(text(value[0])), pl.lit(","), pl.lit(text(value[1]))])
             if isinstance(value, tuple) else value for name, value in values.items()}
    csv_line(df, shown, {name: f"{name} [{u}]" if u else name for name, u in units.items()})
