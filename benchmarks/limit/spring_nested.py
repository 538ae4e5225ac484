"""Limit: spring-series of a nested group and a stiffness with a shared value, ``k1`` =
``"parallel(cantilever(l=X m), Y N/m)"``, ``k2 [N/m]`` a stiffness, ``EI [N*m^2]`` the
cantilever's rigidity -> k_eq, k1.

    python spring_nested.py FILE [--json]

``3 EI / l^3`` as dyncalc's ``monomial`` (``monomial_array``, a numpy-only module), the
parallel group's correctly rounded sum and the series sum dyncalc's exact ones."""
import polars as pl

from dyncalc.physics.numerics_arrays import monomial_array, parallel_sum_rows, series_sum_rows
from _limit import arguments, csv_line, json_input, json_lines, json_result, number, read, text
import numpy as np

path, as_json = arguments()
df = read(path)
group = [df["k1"].str.extract(r"^parallel\(cantilever\(l=([^ ]+) m\),( ([^ ]+) N/m)\)$", i)
         for i in (1, 3, 2)]
l1, k2 = (t.cast(pl.Float64).to_numpy() for t in group[:2])
EI = number(df, "EI [N*m^2]")
k3 = number(df, "k2 [N/m]")
k1 = monomial_array(3.0, [(EI, 1), (l1, -3)])
inner = parallel_sum_rows(np.column_stack([k1, k2]))[0]
k_eq = series_sum_rows(np.column_stack([inner, k3]))[0]
out = {"k_eq": text(k_eq), "k1": text(k1)}
if as_json:
    head = ('"schema": "dyncalc/2", "command": "spring-series", "scene": null, '
            '"model": "network", "method": "closed-form"')
    inputs = ['"k1.l": {"value": ', text(l1), ', "unit": "m", "text": "', group[0],
              ' m"}', *json_input(df, "EI [N*m^2]", "k1.EI", "N*m^2"),
              ', "k2": {"value": ', text(k2), ', "unit": "N/m", "text": "', group[2], '"}',
              *json_input(df, "k2 [N/m]", "k3", "N/m")]
    results = json_result("k_eq", out["k_eq"], "N/m", True) + json_result("k1", out["k1"], "N/m")
    json_lines(len(df), head, inputs, results)
else:
    csv_line(df, out, {"k_eq": "k_eq [N/m]", "k1": "k1_result [N/m]"})
