"""Limit (issue 17): inertia, a disk with a concentric hole a row (``b1`` =
``"disk(m=X kg, r=Y m)"``, ``b2`` = ``"-disk(m=x kg, r=y m)"``) -> m, r_c, J_O, J_C,
J_1..J_3, axis_1..axis_3.

Table 3.1 for each disk, ``J_zz = m r^2 / 2`` (dyncalc's order: ``1/2 * m * (r r)``),
``J_xx = J_yy = J_zz / 2``; the composite is the difference (both centred at the origin:
no parallel-axis term), ``m = X - x``, and its principal axes x, y (equal moments) and z."""
import polars as pl

from _limit import arguments, csv_line, json_lines, json_result, read, text

path, as_json = arguments()
df = read(path)
pattern = r"^(-?)disk\(m=([^ ]+) kg, r=([^ ]+) m\)$"
texts = {}
for column in ("b1", "b2"):
    texts[column] = [df[column].str.extract(pattern, i) for i in (2, 3)]
(M_text, R_text), (m_text, r_text) = texts["b1"], texts["b2"]
M, R, m, r = (t.cast(pl.Float64).to_numpy() for t in (M_text, R_text, m_text, r_text))
axial = 0.5 * M * (R * R) - 0.5 * m * (r * r)
across = 0.5 * M * (R * R) / 2.0 - 0.5 * m * (r * r) / 2.0
mass = M - m
a, c = text(across), text(axial)
if as_json:
    matrix = pl.concat_str([pl.lit("[["), pl.lit(a), pl.lit(", 0.0, 0.0], [0.0, "), pl.lit(a),
                            pl.lit(", 0.0], [0.0, 0.0, "), pl.lit(c), pl.lit("]]")])
    head = ('"schema": "dyncalc/2", "command": "inertia", "scene": null, '
            '"model": "composite", "method": "closed-form"')
    inputs = []
    for index, (mass_text, radius_text), (mass_value, radius_value) in (
            (1, texts["b1"], (M, R)), (2, texts["b2"], (m, r))):
        inputs += [", " if index > 1 else "", f'"b{index}.m": {{"value": ', text(mass_value),
                   ', "unit": "kg", "text": "', mass_text, f' kg"}}, "b{index}.r": {{"value": ',
                   text(radius_value), ', "unit": "m", "text": "', radius_text, ' m"}']
    results = (json_result("m", text(mass), "kg", True)
               + json_result("r_c", "[0.0, 0.0, 0.0]", "m") + json_result("J_O", matrix, "kg*m^2")
               + json_result("J_C", matrix, "kg*m^2") + json_result("J_1", a, "kg*m^2")
               + json_result("J_2", a, "kg*m^2") + json_result("J_3", c, "kg*m^2")
               + json_result("axis_1", "[1.0, 0.0, 0.0]", "")
               + json_result("axis_2", "[0.0, 1.0, 0.0]", "")
               + json_result("axis_3", "[0.0, 0.0, 1.0]", ""))
    json_lines(len(df), head, inputs, results)
else:
    matrix = pl.concat_str([pl.lit(a), pl.lit(",0.0,0.0;0.0,"), pl.lit(a),
                            pl.lit(",0.0;0.0,0.0,"), pl.lit(c)])
    units = {"m": "kg", "r_c": "m", "J_O": "kg*m^2", "J_C": "kg*m^2", "J_1": "kg*m^2",
             "J_2": "kg*m^2", "J_3": "kg*m^2"}
    out = {"m": text(mass), "r_c": "0.0,0.0,0.0", "J_O": matrix, "J_C": matrix, "J_1": a,
           "J_2": a, "J_3": c, "axis_1": "1.0,0.0,0.0", "axis_2": "0.0,1.0,0.0",
           "axis_3": "0.0,0.0,1.0"}
    csv_line(df, out, {n: f"{n} [{units[n]}]" if n in units else n for n in out})
