"""Limit: forced-response undamped (k [N/m], m [kg], F0 [N], Omega [rad/s], no damping), away
from resonance: ``1 - eta^2`` exactly rounded as in forced_response.py; with ``zeta = 0``,
``V = TR = 1/|1 - eta^2|`` and ``phi`` 0 below resonance, pi above; the one-off's warning on
every row (JSON lines: in ``warnings``; CSV: a ``warning:`` line a row on stderr)."""
import math

import numpy as np
import polars as pl

from _forced import one_minus_eta_squared
from _limit import (arguments, csv_line, json_input, json_result, number, read, text,
                    warning_lines, write)

WARNING = "undamped: X_res, the peak and the bandwidth are unbounded; not given"


path, as_json = arguments()
df = read(path)
columns = [("k [N/m]", "k", "N/m"), ("m [kg]", "m", "kg"), ("F0 [N]", "F0", "N"),
           ("Omega [rad/s]", "Omega", "rad/s")]
k, m, F0, W = (number(df, c) for c, _, _ in columns)

gap = one_minus_eta_squared(k, m, W)

omega = np.sqrt(k / m)
TR = 1.0 / np.abs(gap)          # hypot(1, 0) / hypot(gap, 0), exactly
isolated = TR < 1.0
values = {"omega": omega, "zeta": np.zeros_like(k), "eta": W / omega, "X": F0 / k * TR,
          "phi": np.where(gap > 0.0, 0.0, math.pi), "V": TR, "TR": TR, "F_T": F0 * TR,
          "Omega_iso": math.sqrt(2.0) * omega, "isolation": 1.0 - TR}
units = {"omega": "rad/s", "zeta": "", "eta": "", "X": "m", "phi": "rad", "V": "", "TR": "",
         "F_T": "N", "Omega_iso": "rad/s", "isolation": ""}
out = {n: text(v) for n, v in values.items()}
mask = pl.Series(isolated)
iso = out.pop("isolation")
if as_json:
    head = ('"schema": "dyncalc/2", "command": "forced-response", "scene": '
            '"mass-spring-damper", "model": "linear", "method": "closed-form"')
    inputs = [p for i, (col, n, u) in enumerate(columns[:2]) for p in json_input(df, col, n, u, i == 0)]
    inputs.append(', "zeta": {"value": 0.0, "unit": "", "text": "0"}')
    inputs += [p for col, n, u in columns[2:] for p in json_input(df, col, n, u)]
    results = [p for i, (n, v) in enumerate(out.items()) for p in json_result(n, v, units[n], i == 0)]
    results.append(pl.select(pl.when(pl.lit(mask)).then(pl.concat_str(
        [pl.lit(', "isolation": {"value": '), pl.lit(iso), pl.lit(', "unit": ""}')]))
        .otherwise(pl.lit(""))).to_series())
    line = pl.Series(np.arange(2, len(df) + 2)).cast(pl.String)
    write(['{"line": ', line, ", " + head + ', "inputs": {', *inputs, '}, "results": {',
           *results, '}, "warnings": ["' + WARNING + '"], "extra": {}}'])
else:
    if isolated.any():
        out["isolation"] = pl.select(pl.when(pl.lit(mask)).then(pl.lit(iso))
                                     .otherwise(None)).to_series()
    csv_line(df, out, {n: f"{n} [{u}]" if u else n for n, u in units.items()})
    warning_lines(len(df), WARNING)
