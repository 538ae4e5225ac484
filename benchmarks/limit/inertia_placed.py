"""Limit (issue 17): inertia, a disk with an off-centre hole a row (``b1`` =
``"disk(m=M kg, r=R m, at=(X, Y, 0) m)"``, ``b2`` = ``"-disk(m=m kg, r=r m, at=(x, y, 0) m)"``)
-> m, r_c, J_O, J_C, J_1..J_3, axis_1..axis_3.

Table 3.1 for each disk (``J_zz = m r^2 / 2``, ``J_xx = J_yy = J_zz / 2``), the parallel-axis
theorem ``J_O,i = J_C,i + m_i (|c_i|^2 I - c_i c_i^T)`` with ``|c|^2 = (x^2 + y^2) + z^2``
(dyncalc's order), ``r_c = sum m_i c_i / m``, ``J_C = J_O - m (|r_c|^2 I - r_c r_c^T)``;
principal moments and axes from numpy's eigh on the stack, each axis with its largest
component positive."""
import numpy as np
import polars as pl

from _limit import arguments, csv_line, json_lines, json_result, read, text

path, as_json = arguments()
df = read(path)
pattern = r"^-?disk\(m=([^ ]+) kg, r=([^ ]+) m, at=\(([^,]+), ([^,]+), ([^)]+)\) m\)$"
texts = {c: [df[c].str.extract(pattern, i) for i in range(1, 6)] for c in ("b1", "b2")}
nums = {c: [t.cast(pl.Float64).to_numpy() for t in texts[c]] for c in texts}
n = len(df)


def steiner(m, d):
    s = (d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1]) + d[:, 2] * d[:, 2]
    out = np.empty((n, 3, 3))
    for i in range(3):
        for j in range(3):
            out[:, i, j] = m * ((s * (1.0 if i == j else 0.0)) - d[:, i] * d[:, j])
    return out


def sym(J):
    return (J + J.transpose(0, 2, 1)) / 2.0


mass = moment = J_O = 0.0
for column, sign in (("b1", 1.0), ("b2", -1.0)):
    m, r, x, y, z = nums[column]
    axial = 0.5 * m * (r * r)
    J = np.zeros((n, 3, 3))
    J[:, 0, 0] = J[:, 1, 1] = axial / 2.0
    J[:, 2, 2] = axial
    c = np.column_stack([x, y, z]) + 0.0
    J_O = J_O + sign * (sym(J) + steiner(m, c))
    mass = mass + sign * m
    moment = moment + (sign * m)[:, None] * c
r_c = moment / mass[:, None]
J_O = sym(J_O)
J_C = sym(J_O - steiner(mass, r_c))
moments, vectors = np.linalg.eigh(J_C)
axes = vectors.transpose(0, 2, 1)
size = np.abs(axes)
first = np.argmax(size >= size.max(axis=2, keepdims=True) * (1.0 - 1e-12), axis=2)
lead = np.take_along_axis(axes, first[:, :, None], axis=2)[:, :, 0]
axes = np.where((lead > 0.0)[:, :, None], axes, -axes) + 0.0
moments = np.maximum(moments, 0.0)


def join(values, inner, outer, left="", right=""):
    """A vector or matrix as text: components joined by ``inner``, rows by ``outer``."""
    if values.ndim == 2:
        parts = [pl.lit(left)]
        for k in range(3):
            parts += [pl.lit(text(values[:, k]))] + ([pl.lit(inner)] if k < 2 else [])
        return pl.concat_str(parts + [pl.lit(right)])
    rows = [join(values[:, i, :], inner, outer, left, right) for i in range(3)]
    glue = [rows[0], pl.lit(outer), rows[1], pl.lit(outer), rows[2]]
    return pl.concat_str(([pl.lit(left)] if left else []) + glue
                         + ([pl.lit(right)] if right else []))


units = {"m": "kg", "r_c": "m", "J_O": "kg*m^2", "J_C": "kg*m^2", "J_1": "kg*m^2",
         "J_2": "kg*m^2", "J_3": "kg*m^2", "axis_1": "", "axis_2": "", "axis_3": ""}
if as_json:
    head = ('"schema": "dyncalc/2", "command": "inertia", "scene": null, '
            '"model": "composite", "method": "closed-form"')
    inputs = []
    for index, column in ((1, "b1"), (2, "b2")):
        (mt, rt, xt, yt, zt), (m, r, x, y, z) = texts[column], nums[column]
        inputs += [", " if index > 1 else "", f'"b{index}.m": {{"value": ', text(m),
                   ', "unit": "kg", "text": "', mt, f' kg"}}, "b{index}.r": {{"value": ',
                   text(r), ', "unit": "m", "text": "', rt, f' m"}}, "b{index}.at": '
                   '{"value": [', text(x), ", ", text(y), ", ", text(z),
                   '], "unit": "m", "text": "(', xt, ", ", yt, ", ", zt, ') m"}']
    vec = {"left": "[", "right": "]", "inner": ", ", "outer": ", "}
    out = {"m": text(mass), "r_c": join(r_c, **vec), "J_O": join(J_O, **vec),
           "J_C": join(J_C, **vec)}
    out.update({f"J_{k + 1}": text(moments[:, k]) for k in range(3)})
    out.update({f"axis_{k + 1}": join(axes[:, k, :], **vec) for k in range(3)})
    results = []
    for i, (name, values) in enumerate(out.items()):
        results += json_result(name, values, units[name], i == 0)
    json_lines(n, head, inputs, results)
else:
    out = {"m": text(mass), "r_c": join(r_c, ",", ";"), "J_O": join(J_O, ",", ";"),
           "J_C": join(J_C, ",", ";")}
    out.update({f"J_{k + 1}": text(moments[:, k]) for k in range(3)})
    out.update({f"axis_{k + 1}": join(axes[:, k, :], ",", ";") for k in range(3)})
    csv_line(df, out, {k: f"{k} [{u}]" if u else k for k, u in units.items()})
