"""Limit (issue 17): ``modes --scene pendulum-on-sliding-block`` (m1 [kg], m2 [kg], l [m]; g
at its default) -> omega_i, f_i, mode_i, modal_mass_i, modal_stiffness_i, with the note of
the rigid-body drift on every row (JSON lines: in ``warnings``; CSV: a ``warning:`` line a
row on stderr).

K = [[0, 0], [0, m2 g l]] is singular: mode 1 is the drift (omega 0, shape [1, 0], modal
mass m1 + m2, stiffness 0); the swing has ``omega^2 = g (m1 + m2) / (m1 l)``, shape
``[-s, 1]`` with ``s = m2 l / (m1 + m2)`` (below 1 in the benchmark's rows: phi is the largest
component), modal mass ``m1 m2 l^2 / (m1 + m2)`` and stiffness ``m2 g l`` (dyncalc's closed
form, the same float operations in the same order)."""
import json
import math

import numpy as np
import polars as pl

from _limit import (arguments, csv_line, json_input, json_result, number, read, text,
                    warning_lines, write)

G = 9.80665
NOTE = ("omega_1 = 0: a rigid-body mode (an eigenvalue omega^2 within 1e-10 of the terms of K "
        "that sum to it is taken as zero)")

path, as_json = arguments()
df = read(path)
columns = [("m1 [kg]", "m1", "kg"), ("m2 [kg]", "m2", "kg"), ("l [m]", "l", "m")]
m1, m2, l_ = (number(df, c) for c, _, _ in columns)
total = m1 + m2
s = m2 * l_ / total
omega = np.sqrt(G * total / (m1 * l_))
mass = m1 * m2 * (l_ * l_) / total
stiffness = m2 * G * l_
zero = text(np.zeros(len(df)))
values = {"omega_1": zero, "omega_2": text(omega), "f_1": zero,
          "f_2": text(omega / (2.0 * math.pi)), "mode_1": None, "modal_mass_1": text(total),
          "modal_stiffness_1": zero, "mode_2": text(-s), "modal_mass_2": text(mass),
          "modal_stiffness_2": text(stiffness)}
units = {"omega_1": "rad/s", "omega_2": "rad/s", "f_1": "Hz", "f_2": "Hz", "mode_1": "",
         "modal_mass_1": "kg", "modal_stiffness_1": "N/m", "mode_2": "",
         "modal_mass_2": "kg*m^2", "modal_stiffness_2": "N*m/rad"}

if as_json:
    head = ('"schema": "dyncalc/2", "command": "modes", "scene": "pendulum-on-sliding-block", '
            '"model": "linear", "method": "eigh"')
    inputs = [p for i, (c, name, unit) in enumerate(columns)
              for p in json_input(df, c, name, unit, i == 0)]
    inputs.append(', "g": {"value": 9.80665, "unit": "m/s^2", "text": "9.80665 m/s^2"}')
    results = []
    for i, (name, value) in enumerate(values.items()):
        if name == "mode_1":
            value = "[1.0, 0.0]"
        elif name == "mode_2":
            value = pl.concat_str([pl.lit("["), pl.lit(value), pl.lit(", 1.0]")])
        results += json_result(name, value, units[name], i == 0)
    extra = json.dumps({"coordinates": [{"name": "x", "kind": "translation", "unit": "m"},
                                        {"name": "phi", "kind": "rotation", "unit": "rad"}],
                        "normalize": "max", "equilibrium": "phi = 0 (bob below the pin), any x"})
    line = pl.Series(np.arange(2, len(df) + 2)).cast(pl.String)
    write(['{"line": ', line, ", " + head + ', "inputs": {', *inputs, '}, "results": {',
           *results, '}, "warnings": ["' + NOTE + '"], "extra": ' + extra + "}"])
else:
    values["mode_1"] = "1.0,0.0"
    values["mode_2"] = pl.concat_str([pl.lit(values["mode_2"]), pl.lit(",1.0")])
    csv_line(df, values, {n: f"{n} [{u}]" if u else n for n, u in units.items()})
    warning_lines(len(df), NOTE)
