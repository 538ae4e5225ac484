"""Limit: spring-series with element words, ``k1`` = ``"cantilever(l=X m, EI=Y N*m^2)"``,
``k2`` = ``"axial(l=X m, EA=Y N)"``, ``k3 [N/m]`` a stiffness -> k_eq, k1, k2.

    python spring_elements.py FILE [--json]

``3 EI / l^3`` and ``EA / l`` as dyncalc's ``monomial`` (mantissas and binary exponents:
``monomial_array``, a numpy-only module), the series sum dyncalc's exact one."""
import polars as pl

from dyncalc.physics.numerics_arrays import monomial_array, series_sum_rows
from _limit import arguments, csv_line, json_lines, json_result, number, read, text
import numpy as np

path, as_json = arguments()
df = read(path)
beam = [df["k1"].str.extract(r"^cantilever\(l=([^ ]+) m, EI=([^ ]+) N\*m\^2\)$", i)
        for i in (1, 2)]
bar = [df["k2"].str.extract(r"^axial\(l=([^ ]+) m, EA=([^ ]+) N\)$", i) for i in (1, 2)]
l1, EI, l2, EA = (t.cast(pl.Float64).to_numpy() for t in (*beam, *bar))
k3 = number(df, "k3 [N/m]")
k1 = monomial_array(3.0, [(EI, 1), (l1, -3)])
k2 = monomial_array(1.0, [(EA, 1), (l2, -1)])
k_eq = series_sum_rows(np.column_stack([k1, k2, k3]))[0]
out = {"k_eq": text(k_eq), "k1": text(k1), "k2": text(k2)}
if as_json:
    head = ('"schema": "dyncalc/2", "command": "spring-series", "scene": null, '
            '"model": "series", "method": "closed-form"')
    inputs = []
    for name, unit, typed in (("k1.l", "m", beam[0]), ("k1.EI", "N*m^2", beam[1]),
                              ("k2.l", "m", bar[0]), ("k2.EA", "N", bar[1]),
                              ("k3", "N/m", df["k3 [N/m]"])):
        inputs += [("" if name == "k1.l" else ", ") + f'"{name}": {{"value": ',
                   text(typed.cast(pl.Float64).to_numpy()), f', "unit": "{unit}", "text": "',
                   typed, f' {unit}"}}']
    results = (json_result("k_eq", out["k_eq"], "N/m", True) + json_result("k1", out["k1"], "N/m")
               + json_result("k2", out["k2"], "N/m"))
    json_lines(len(df), head, inputs, results)
else:
    csv_line(df, out, {"k_eq": "k_eq [N/m]", "k1": "k1_result [N/m]", "k2": "k2_result [N/m]"})
