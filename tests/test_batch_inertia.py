"""``inertia --batch``: one composite per row (body columns b1, b2, ..., axis); the vectorised
path of bodies at the origin, composites and world axes included
(dyncalc/batch/fast_inertia.py) byte for byte the generic (one-off) path, on random rows with
extremes; values against the textbook formulas."""
from __future__ import annotations

import io
import json
import math
import random

import numpy as np
import pytest
from click.testing import CliRunner

from dyncalc.batch import run_batch
from dyncalc.batch.inertia_rows import InertiaRows
from dyncalc.cli import cli

_UNITS = {"m": ["kg", "g", "t", ""], "len": ["m", "cm", "mm", "ft", ""]}
_MAGNITUDES = [1.0, 0.2, 3.7, 1e-150, 1e150, 1e-300, 1e300, 7.5e200, 2.5e-320]


def _value(rng, kind):
    x = rng.choice(_MAGNITUDES) * rng.uniform(0.5, 2.0) if rng.random() < 0.3 else \
        rng.uniform(0.01, 10.0)
    unit = rng.choice(_UNITS[kind])
    return f"{x!r}{rng.choice(['', ' '])}{unit}"


def _body(rng):
    kind = rng.choice(["rod", "disk", "ring", "solid-sphere", "hollow-sphere", "point",
                       "solid-cylinder", "hollow-cylinder", "plate", "half-cylinder-shell"])
    dims = {"rod": ["l"], "disk": ["r"], "ring": ["r"], "solid-sphere": ["r"],
            "hollow-sphere": ["r"], "point": [], "solid-cylinder": ["r", "h"],
            "hollow-cylinder": ["ri", "ro", "h"], "plate": ["a", "b"],
            "half-cylinder-shell": ["r", "h"]}[kind]
    parts = [f"m={_value(rng, 'm')}"]
    if kind == "solid-cylinder" and rng.random() < 0.3:  # J_xx = J_zz: h = sqrt(3) r
        r = rng.uniform(0.1, 2.0)
        return f"solid-cylinder(m=2kg, r={r!r} m, h={math.sqrt(3.0) * r!r} m)"
    parts += [f"{d}={_value(rng, 'len')}" for d in dims]
    if kind == "rod" and rng.random() < 0.3:
        parts[0] = f"rho={rng.uniform(0.1, 5.0)!r} kg/m"
    rng.shuffle(parts)
    return f"{kind}({', '.join(parts)})"


def _run(path, as_json: bool, fast: bool) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    status = run_batch(InertiaRows(), str(path), as_json=as_json, on_error="skip",
                       out=out, err=err, fast=fast)
    return status, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("as_json", [False, True])
@pytest.mark.parametrize("seed", [1, 2])
def test_the_vectorised_path_is_the_one_off_byte_for_byte(tmp_path, as_json, seed):
    rng = random.Random(seed)
    rows = ['"' + _body(rng) + '",,' for _ in range(300)]
    rows += ['"disk(m=1kg, r=1m, at=(1, 0, 0) m)",,', '"-disk(m=1kg, r=1m)",,',
             '"rod(m=1kg)",,', '"disk(m=0kg, r=1m)",,', '"disk(m=1 s, r=1m)",,', '"",,']
    # rows with a second body or an axis (the composite kernel, or the one-off row by row)
    rows += [f'"{_body(rng)}","{_body(rng)}",' for _ in range(20)]
    rows += [f'"{_body(rng)}",,{rng.choice(["x", "z", "(1, 1, 0)"])!s}' for _ in range(20)]
    rng.shuffle(rows)
    path = tmp_path / "bodies.csv"
    path.write_text("b1,b2,axis\n" + "\n".join(rows) + "\n")
    fast, generic = _run(path, as_json, True), _run(path, as_json, False)
    assert fast == generic
    assert fast[0] == 2 and fast[2].count("Error: line") >= 5


def test_most_single_body_rows_take_the_vectorised_path(tmp_path):
    """The kernel covers the rows it should (else the byte test above proves nothing)."""
    from dyncalc.batch.fast_inertia import inertia_fast
    from dyncalc.batch.header import read_header

    rng = random.Random(3)
    cells = [[_body(rng)] for _ in range(200)]
    spec = InertiaRows()
    columns = read_header(1, ["b1", "b2", "axis"], spec)
    blocks = inertia_fast(spec, columns, [[c[0] for c in cells], [""] * 200, [""] * 200],
                          False, {})
    covered = sum(len(b.rows) for b in blocks)
    simple = sum(1 for (c,) in cells if not c.startswith("half-cylinder")
                 and all(x not in c for x in ("e300", "e-320", "e200")))
    assert covered >= 0.9 * simple > 50


def test_textbook_values_and_principal_axes(tmp_path):
    path = tmp_path / "b.csv"
    path.write_text('b1\n"solid-cylinder(m=12kg, r=1m, h=2m)"\n"disk(m=4 kg, r=20 cm)"\n'
                    '"plate(rho=7.8 kg/m^2, a=0.4m, b=0.2m)"\n')
    status, out, err = _run(path, True, True)
    assert (status, err) == (0, "")
    cyl, disk, plate = [json.loads(line)["results"] for line in out.splitlines()]
    # solid cylinder: m (3 r^2 + h^2)/12 = 7 across, m r^2/2 = 6 along its axis (Table 3.1)
    assert [cyl[f"J_{i}"]["value"] for i in (1, 2, 3)] == [6.0, 7.0, 7.0]
    assert cyl["axis_1"]["value"] == [0.0, 0.0, 1.0]
    assert [cyl["axis_2"]["value"], cyl["axis_3"]["value"]] == [[1.0, 0.0, 0.0],
                                                                 [0.0, 1.0, 0.0]]
    assert disk["J_3"]["value"] == pytest.approx(4 * 0.2 ** 2 / 2, rel=1e-15)
    assert disk["J_1"]["value"] == pytest.approx(4 * 0.2 ** 2 / 4, rel=1e-15)
    m = 7.8 * 0.4 * 0.2
    assert plate["m"]["value"] == pytest.approx(m, rel=1e-15)
    assert plate["J_3"]["value"] == pytest.approx(m * (0.4 ** 2 + 0.2 ** 2) / 12, rel=1e-15)


def test_composites_and_axis_columns_are_the_one_off(tmp_path):
    from dyncalc.commands.inertia import inertia

    path = tmp_path / "c.csv"
    path.write_text('b1,b2,axis\n'
                    '"rod(m=2kg, l=2m, along=x, at=(1, 0, 0) m)","rod(m=1kg, l=1m, at=(2, 0, 0.5) m)",z\n'
                    '"disk(m=4kg, r=0.2m)","-disk(m=0.25kg, r=5cm, at=(0.1, 0, 0) m)",\n'
                    '"rod(m=3kg, l=2m, along=x, at=(1, 0, 0) m)",,z\n')
    status, out, err = _run(path, True, True)
    assert (status, err) == (0, "")
    lines = [json.loads(line) for line in out.splitlines()]
    # the rod about its end: m l^2 / 3 = 4 kg*m^2 (independent of the code)
    assert lines[2]["results"]["J_axis"]["value"] == pytest.approx(4.0, rel=1e-15)
    one_off = inertia(["disk(m=4kg, r=0.2m)", "-disk(m=0.25kg, r=5cm, at=(0.1, 0, 0) m)"])
    assert lines[1]["results"]["J_C"]["value"] == one_off.results["J_C"].si.tolist()
    assert "J_axis" not in lines[1]["results"] and list(lines[1]["inputs"])[-1] == "b2.at"


def test_bad_rows_and_usage_have_one_line_messages(tmp_path):
    path = tmp_path / "e.csv"
    path.write_text("b1,axis\n,z\n")
    r = CliRunner().invoke(cli, ["inertia", "--batch", str(path)])
    assert (r.exit_code, r.stdout, r.stderr) == (
        2, "", "Error: line 2: no body: give at least one body cell (b1, b2, ...)\n")
    path.write_text("m,r\n1,2\n")
    r = CliRunner().invoke(cli, ["inertia", "--batch", str(path)])
    assert (r.exit_code, r.stderr) == (
        2, "Error: line 1: unknown column 'm'; inertia reads body columns b1, b2, ... (one "
           "body word a cell, e.g. \"disk(m=4kg, r=0.2m)\") and axis\n")
    path.write_text('b1\n"disk(m=1kg, r=1m)"\n')
    r = CliRunner().invoke(cli, ["inertia", "--batch", str(path), "--axis", "z"])
    assert (r.exit_code, r.stderr) == (
        2, "Error: --axis and --batch do not go together: with --batch every parameter comes "
           "from a column of the file\n")


_CENTRED = ["rod", "disk", "ring", "solid-sphere", "hollow-sphere", "point", "solid-cylinder",
            "hollow-cylinder", "plate"]


def _centred(rng, hole: bool) -> str:
    """A body at the origin along z (perhaps a hole): the kinds the composite kernel takes."""
    word = _body(rng)
    while word.split("(")[0] not in _CENTRED:
        word = _body(rng)
    return ("-" if hole else "") + word


@pytest.mark.parametrize("as_json", [False, True])
@pytest.mark.parametrize("seed", [4, 5])
def test_centred_composites_are_the_one_off_byte_for_byte(tmp_path, as_json, seed):
    """Composites of two or three bodies at the origin (holes among them, holes that cut too
    much, extremes, empty cells between the bodies; world axes, signed, and other axes),
    through the composite kernel."""
    rng = random.Random(seed)
    rows = []
    for _ in range(200):
        cells = [f'"{_centred(rng, i > 0 and rng.random() < 0.4)}"' for i in range(3)]
        if rng.random() < 0.3:
            cells[rng.randrange(3)] = ""
        if rng.random() < 0.2:  # a hole the size of the body: a total mass of zero
            cells = ['"disk(m=1kg, r=0.2m)"', '"-disk(m=1kg, r=0.1m)"', ""]
        axis = rng.choice(["", "", "z", " -x", "+y", "(1, 1, 0)", "z through (0.1, 0, 0) m"])
        rows.append(",".join(cells) + "," + (f'"{axis}"' if "," in axis else axis))
    rows += ['"disk(m=4kg, r=0.2m)","-disk(m=1kg, r=0.1m)",,z',
             '"disk(m=4kg, r=0.2m)","-disk(m=1kg, r=0.1m, at=(0.05, 0, 0) m)",,']
    path = tmp_path / "composites.csv"
    path.write_text("b1,b2,b3,axis\n" + "\n".join(rows) + "\n")
    fast, generic = _run(path, as_json, True), _run(path, as_json, False)
    assert fast == generic
    assert fast[2].count("Error: line") >= 5


def test_centred_composite_rows_take_the_vectorised_path():
    from dyncalc.batch.fast_inertia import inertia_fast
    from dyncalc.batch.header import read_header

    rng = random.Random(6)
    table = [[_centred(rng, False) for _ in range(200)],
             [_centred(rng, rng.random() < 0.5) for _ in range(200)], [""] * 200]
    spec = InertiaRows()
    blocks = inertia_fast(spec, read_header(1, ["b1", "b2", "axis"], spec), table, False, {})
    covered = {i for b in blocks for i in b.rows.tolist()}
    clean = set()
    for i in range(200):
        try:
            result = spec.compute({"b1": table[0][i], "b2": table[1][i]}, {})
        except Exception:  # noqa: BLE001 (a refusal: the generic path's)
            continue
        if not result.warnings and "e300" not in table[0][i] + table[1][i]:
            clean.add(i)
    assert covered and covered <= {i for i in range(200)}
    assert len(covered & clean) >= 0.8 * len(clean) > 50


def test_a_disk_with_a_concentric_hole_is_the_textbook_annulus(tmp_path):
    """m = 4 - 1 = 3 kg; J_zz = 4 (0.2^2)/2 - 1 (0.1^2)/2 = 0.075 kg*m^2 (Table 3.1, twice)."""
    path = tmp_path / "a.csv"
    path.write_text('b1,b2\n"disk(m=4kg, r=0.2m)","-disk(m=1kg, r=0.1m)"\n')
    status, out, err = _run(path, True, True)
    assert (status, err) == (0, "")
    results = json.loads(out)["results"]
    assert results["m"]["value"] == 3.0
    assert results["J_3"]["value"] == pytest.approx(0.075, rel=1e-15)
    assert results["J_1"]["value"] == pytest.approx(4 * 0.04 / 4 - 0.01 / 4, rel=1e-15)


def test_world_axis_rows_take_the_vectorised_path_with_the_textbook_moment():
    """``axis`` x, -y, z through the origin: J_axis is the diagonal element (a disk: m r^2/4
    across, m r^2/2 along z; Table 3.1) and k = sqrt(J_axis / m)."""
    from dyncalc.batch.fast_inertia import inertia_fast
    from dyncalc.batch.header import read_header

    spec = InertiaRows()
    table = [['disk(m=4kg, r=0.2m)'] * 3, ['-disk(m=1kg, r=0.1m)'] * 3, ["x", " -y", "z"]]
    blocks = inertia_fast(spec, read_header(1, ["b1", "b2", "axis"], spec), table, True, {})
    assert sorted(i for b in blocks for i in b.rows.tolist()) == [0, 1, 2]
    found = {int(b.rows[0]): b.values for b in blocks}
    along, across = 4 * 0.04 / 2 - 0.01 / 2, 4 * 0.04 / 4 - 0.01 / 4
    for i, expected in enumerate([across, across, along]):
        assert found[i]["J_axis"][0] == pytest.approx(expected, rel=1e-15)
        assert found[i]["radius_of_gyration"][0] == pytest.approx(math.sqrt(expected / 3.0),
                                                                  rel=1e-15)


#: Templates of one column each (one template a column: the one-pass reader), odd spacing,
#: a unit per body and per parameter, a density, a hole.
_ONE_TEMPLATE = [
    ('disk(m={} kg, r={} m)', '-disk(m={} kg, r={} m)'),
    ('disk( m =  {}kg ,r=\t{} cm )', ' - ring(m={} g,r={} mm)'),
    ('solid-cylinder(h={} ft, m={} t, r={} m)', '-rod(rho={} kg/m, l={}m)'),
    ('plate(a={}, b={} mm, m={})', 'point(m={} g)'),
]


def _number(rng) -> str:
    """A literal as a user may type it: repr, %g, an exponent in E, a sign, an extreme."""
    x = rng.choice(_MAGNITUDES) * rng.uniform(0.5, 2.0) if rng.random() < 0.05 else \
        rng.uniform(0.01, 10.0)
    form = rng.choice(["{!r}", "{:.6g}", "{:E}", "+{!r}", "{:.3e}"])
    return form.format(x)


@pytest.mark.parametrize("as_json", [False, True])
@pytest.mark.parametrize("seed", range(len(_ONE_TEMPLATE)))
def test_one_template_columns_are_the_one_off_byte_for_byte(tmp_path, as_json, seed):
    """Every cell of a column with its first cell's template (read in one pass a column):
    the one-off's bytes, and with a malformed cell, a negative mass or a leading zero among
    them, those rows the one-off's refusals while the others still match it."""
    rng, template = random.Random(seed), _ONE_TEMPLATE[seed]
    cells = [[t.format(*(_number(rng) for _ in range(t.count("{}")))) for t in template]
             for _ in range(150)]
    rows = [",".join(f'"{c}"' for c in row) for row in cells]
    from dyncalc.batch.fast_inertia import inertia_fast
    from dyncalc.batch.header import read_header

    spec = InertiaRows()  # the kernel takes most rows (else the bytes prove nothing)
    blocks = inertia_fast(spec, read_header(1, ["b1", "b2"], spec), list(zip(*cells)),
                          as_json, {})
    assert sum(len(b.rows) for b in blocks) >= 50  # (a hole heavier than the body: none)
    path = tmp_path / "one.csv"
    path.write_text("b1,b2\n" + "\n".join(rows) + "\n")
    fast, generic = _run(path, as_json, True), _run(path, as_json, False)
    assert fast == generic
    bad = ["1..5", "-2.5", "007"]
    for k, text in enumerate(bad):
        cells = [t.format(*(_number(rng) for _ in range(t.count("{}")))) for t in template]
        cells[k % 2] = template[k % 2].replace("{}", text, 1).format(
            *(_number(rng) for _ in range(template[k % 2].count("{}") - 1)))
        rows.insert(10 + 40 * k, ",".join(f'"{c}"' for c in cells))
    path.write_text("b1,b2\n" + "\n".join(rows) + "\n")
    fast, generic = _run(path, as_json, True), _run(path, as_json, False)
    assert fast == generic
    errors = {e.split(":")[1]: e for e in fast[2].splitlines()}
    assert "two numbers side by side" in errors[" line 12"]
    assert "must be positive; got -2.5" in errors[" line 52"]
    assert "the leading zero in '007' is ambiguous" in errors[" line 92"]


def test_a_one_template_column_is_one_block_and_read_in_one_pass():
    """The one-pass reader takes the columns (each slot's numbers as typed) and the rows
    become one block; the annulus m = 4 - 1, J_zz = 4 (0.2^2)/2 - 1 (0.1^2)/2 (Table 3.1)."""
    from dyncalc.batch.fast_inertia import _one_template, inertia_fast
    from dyncalc.batch.header import read_header

    spec = InertiaRows()
    columns = read_header(1, ["b1", "b2"], spec)
    b1 = ["disk( m = 4kg, r=0.2 m)", "disk( m = +4e0kg, r=20E-2 m)", "disk( m = 4.kg, r=.2 m)"]
    b2 = ["-disk(m=1 kg, r=10 cm)"] * 3
    parts = _one_template(columns, [b1, b2], {})
    assert [p[2] for p in parts] == [[["4", "+4e0", "4."], ["0.2", "20E-2", ".2"]],
                                     [["1"] * 3, ["10"] * 3]]
    blocks = inertia_fast(spec, columns, [b1, b2], True, {})
    assert len(blocks) == 1 and blocks[0].rows.tolist() == [0, 1, 2]
    assert blocks[0].values["m"].tolist() == [3.0] * 3
    assert blocks[0].values["J_C"][:, 2, 2] == pytest.approx([4 * 0.04 / 2 - 0.01 / 2] * 3,
                                                             rel=1e-15)
    # a cell off the template (a second body word, a blank) leaves it to the grouped reader
    assert _one_template(columns, [b1, b2[:2] + [""]], {}) is None
    assert _one_template(columns, [b1, b2[:2] + ["-disk(m=1 kg, r=10 cm, )"]], {}) is None


def test_the_sorted_diagonal_is_lapacks_eigh_bit_for_bit():
    """The kernel's eigen-decomposition of diagonal tensors without LAPACK (sorting the
    diagonal) against ``numpy.linalg.eigh``/``eigvalsh`` on random stacks with extremes
    (1e-320..1e300: LAPACK scales beyond about 1e+-146, those rows go to it), zeros,
    negatives, equal and next-to-equal moments: the same values bit for bit, the same axes
    where the moments differ, and signed world axes from LAPACK's rows."""
    from dyncalc.physics.inertia_columns import _diagonal_eigh

    rng = np.random.default_rng(17)
    n = 60000
    d = rng.uniform(0.01, 3.0, (n, 3)) * 10.0 ** rng.integers(-160, 160, (n, 1))
    d[rng.random(n) < 0.02] *= rng.choice([1e-170, 1e140, 2.5e-320, 0.0])
    d[rng.random((n, 3)) < 0.03] *= -1.0
    tie = rng.random(n) < 0.3
    d[tie, 1] = d[tie, 0]
    near = rng.random(n) < 0.2
    d[near, 2] = np.nextafter(d[near, 1], np.inf)
    d[rng.random(n) < 0.05] = 0.0
    J = np.zeros((n, 3, 3))
    J[:, [0, 1, 2], [0, 1, 2]] = d
    moments, world, checked, axes_ok = _diagonal_eigh(J)
    values, vectors = np.linalg.eigh(J)
    bits = np.int64
    assert np.array_equal(moments.view(bits), values.view(bits))
    assert np.array_equal(checked.view(bits), np.linalg.eigvalsh(J).view(bits))
    distinct = (np.diff(values, axis=1) != 0.0).all(axis=1)
    assert np.array_equal(world[distinct], np.argmax(np.abs(vectors), axis=1)[distinct])
    assert axes_ok.all()
    # unscaled, each moment is the diagonal element of its axis (scaled, LAPACK's rounding)
    size = np.abs(d).max(axis=1)
    plain = (size >= 1e-140) & (size <= 1e140)
    assert np.array_equal(np.take_along_axis(d, world, axis=1)[plain], moments[plain])
    assert (~plain).sum() > 100
    assert distinct.sum() > n // 2 and (~distinct).sum() > n // 5


def _strict_split(pieces, cells):
    """The slots' texts by the template's own pattern (a literal in each slot), or None."""
    import re

    from dyncalc.batch.fast_inertia import _SLOT

    pattern = re.compile("^" + _SLOT.join(map(re.escape, pieces)) + "$", re.M)
    k, n = len(pieces), len(cells)
    split = pattern.split("\n".join(cells))
    if len(split) != 1 + n * k or "".join(split[::k]) != "\n" * (n - 1):
        return None
    return [split[j::k] for j in range(1, k)]


def _loose(pieces, cells):
    from dyncalc.batch.fast_inertia import _loose as loose

    return loose(pieces, "\n".join(cells), len(cells), len(pieces), {})


def test_the_loose_split_takes_what_the_literal_pattern_takes_and_reads_it():
    """Round 10: slots split as runs of a literal's characters and read as JSON numbers give
    the literal pattern's texts, with their values; a template a literal may run into, or a
    slot JSON refuses (``+5``, ``.5``, ``5.``, ``007``, ``1-2``), is left to that pattern."""
    pieces = ["disk(m=", " kg, r=", " m)"]
    cells = ["disk(m=2 kg, r=0.5 m)", "disk(m=-0 kg, r=1E+3 m)", "disk(m=7e-300 kg, r=3 m)"]
    got = _loose(pieces, cells)
    assert got == _strict_split(pieces, cells) == [["2", "-0", "7e-300"], ["0.5", "1E+3", "3"]]
    assert [g.values.tolist() for g in got] == [[2.0, -0.0, 7e-300], [0.5, 1000.0, 3.0]]
    assert math.copysign(1.0, got[0].values[1]) == -1.0  # -0 read as float reads it
    for bad in ("+5", ".5", "5.", "007", "1-2", "1e", ""):
        odd = cells + [f"disk(m={bad} kg, r=1 m)"]
        assert _loose(pieces, odd) is None
    for template in (["a=", "e5 kg"], ["a=1", " kg"], ["a=", "\n", " m"]):
        assert _loose(template, ["".join(p + "1" for p in template[:-1]) + template[-1]]) \
            is None


@pytest.mark.parametrize("seed", range(4))
def test_the_loose_split_never_differs_from_the_literal_pattern(seed):
    """Random templates (fixed texts of letters, ``=``, ``,``, brackets, blanks, ``e``) and
    cells of literals, near-literals and pieces run together: wherever the loose split
    answers, it is the literal pattern's split, and its values are float's."""
    rng = random.Random(seed)
    alphabet = "abm=,( )µe5"
    literal_chars = "0123456789.eE+-"
    for _ in range(400):
        pieces = ["".join(rng.choice(alphabet) for _ in range(rng.randint(1, 5)))
                  for _ in range(rng.randint(2, 4))]
        cells = []
        for _ in range(rng.randint(1, 5)):
            values = [rng.choice([repr(rng.uniform(-1e3, 1e3)), str(rng.randint(-99, 99)),
                                  "".join(rng.choice(literal_chars)
                                          for _ in range(rng.randint(0, 4)))])
                      for _ in range(len(pieces) - 1)]
            cell = "".join(p + v for p, v in zip(pieces, values)) + pieces[-1]
            if rng.random() < 0.2:  # pieces and literals run together
                cell = "".join(rng.choice(pieces + values) for _ in range(rng.randint(1, 6)))
            cells.append(cell)
        got = _loose(pieces, cells)
        if got is not None:
            assert got == _strict_split(pieces, cells), (pieces, cells)
            for texts in got:
                assert texts.values.tolist() == [float(t) for t in texts]
