"""Limit: coriolis over times, ``--r "s0 - b*t^2/2, 0, 0 m" s0=4m b=0.5m/s^2 --omega
"0,0,2 rad/s"`` with a ``t [s]`` column -> r, v_r, a_r, Omega, ..., a_mag, theta.

The motion derived by hand for this input, as a script for one file would: ``x = s0 - b t^2/2``,
``v_r = (-b t, 0, 0)``, ``a_r = (-b, 0, 0)``, ``Omega = (0, 0, w)``, ``theta = w t``; with
``w = 2`` every cross product is an exact scaling: ``Omega x r = (0, w x, 0)``,
``2 Omega x v_r = (0, -2 w b t, 0)``, ``Omega x (Omega x r) = (-w^2 x, 0, 0)``. Magnitudes by
the math.hypot twin of dyncalc.physics.numerics_arrays (a numpy-only module); the rotation
matrix in JSON ``extra`` is Rodrigues' ``I + sin K + (1 - cos) K^2`` about z."""
import math

import numpy as np
import polars as pl

from dyncalc.physics.numerics_arrays import hypot_rows
from _limit import arguments, csv_line, json_lines, json_result, read, text, vector

S0, B, W = 4.0, 0.5, 2.0
NAMES = ("r", "v_r", "a_r", "Omega", "alpha", "v0", "a0", "R", "v_transport",
         "v_transport_mag", "v", "v_mag", "a_c", "a_c_mag", "a_euler", "a_centripetal",
         "a_transport", "a_transport_mag", "a", "a_mag", "theta")
UNITS = {"r": "m", "v_r": "m/s", "a_r": "m/s^2", "Omega": "rad/s", "alpha": "rad/s^2",
         "v0": "m/s", "a0": "m/s^2", "R": "m", "v_transport": "m/s", "v": "m/s",
         "a_c": "m/s^2", "a_euler": "m/s^2", "a_centripetal": "m/s^2", "a_transport": "m/s^2",
         "a": "m/s^2", "theta": "rad"}

path, as_json = arguments()
df = read(path)
t = df["t [s]"].cast(pl.Float64).to_numpy()
n = len(t)
zero, one = np.zeros(n), np.ones(n)
# t**2 by Python's float power, as the compiled expression (libm's pow; numpy's square is
# t*t, which differs from it in the last bit for some t)
x = S0 - B * np.array([v ** 2 for v in t.tolist()]) / 2
vx = -B * t
cx = -W * (W * x) + 0.0       # the centripetal term
cy = 2.0 * (W * vx) + 0.0     # the Coriolis term
vt = W * x + 0.0              # the transport velocity
vecs = {"r": (x, zero, zero), "v_r": (vx + 0.0, zero, zero), "a_r": (-B * one, zero, zero),
        "Omega": (zero, zero, W * one), "alpha": (zero,) * 3, "v0": (zero,) * 3,
        "a0": (zero,) * 3, "R": (x, zero, zero), "v_transport": (zero, vt, zero),
        "v": (vx + 0.0, vt, zero), "a_c": (zero, cy, zero), "a_euler": (zero,) * 3,
        "a_centripetal": (cx, zero, zero), "a_transport": (cx, zero, zero),
        "a": (-B + cx, cy, zero)}
mags = {"v_transport_mag": "v_transport", "v_mag": "v", "a_c_mag": "a_c",
        "a_transport_mag": "a_transport", "a_mag": "a"}
theta = W * t
sep = ", " if as_json else ","
out = {}
for name in NAMES:
    if name in vecs:
        out[name] = vector(vecs[name], sep)
    elif name in mags:
        out[name] = text(hypot_rows(*vecs[mags[name]])[0] + 0.0)
    else:
        out[name] = text(theta)
if as_json:
    head = ('"schema": "dyncalc/2", "command": "coriolis", "scene": null, '
            '"model": "motion given in time (rotating basis)", "method": "exact derivatives"')
    inputs = ['"s0": {"value": 4.0, "unit": "m", "text": "4m"}, "b": {"value": 0.5, "unit": '
              '"m/s^2", "text": "0.5m/s^2"}, "r": {"value": "s0 - b*t^2/2, 0, 0 m", "unit": "", '
              '"text": "s0 - b*t^2/2, 0, 0 m"}, "omega": {"value": "0,0,2 rad/s", "unit": "", '
              '"text": "0,0,2 rad/s"}, "t": {"value": ', text(t), ', "unit": "s", "text": "',
              df["t [s]"], ' s"}']
    results = []
    for i, name in enumerate(NAMES):
        unit = UNITS.get(name) or UNITS[mags[name]]
        results += json_result(name, out[name], unit, i == 0)
    sin = np.array([math.sin(v) for v in theta.tolist()])
    cos = np.array([math.cos(v) for v in theta.tolist()])
    q00 = 1.0 + (1.0 - cos) * -1.0
    extra = ['{"basis": "rotating", "rotation": "closed form", "derivatives": {"v_r": ["-b*t", '
             '"0", "0"], "a_r": ["-b", "0", "0"], "alpha": ["0", "0", "0"], "v0": ["0", "0", '
             '"0"], "a0": ["0", "0", "0"]}, "rotation_matrix": [[', text(q00), ", ",
             text(-sin + 0.0), ", 0.0], [", text(sin + 0.0), ", ", text(q00),
             ', 0.0], [0.0, 0.0, 1.0]]}']
    json_lines(n, head, inputs, results, extra)
else:
    csv_line(df, out, {name: f"{name} [{UNITS.get(name) or UNITS[mags[name]]}]"
                       for name in NAMES})
