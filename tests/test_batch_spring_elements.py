"""``spring-series`` / ``spring-parallel --batch`` with element words in the cells
(dyncalc/batch/fast_springs.py): the rows computed on columns are byte for byte what the
generic path (the one-off row by row) writes, CSV and JSON lines, stderr and exit status, on
random rows of every element taken (units mixed, extremes that overflow or underflow
included); the textbook values check the numbers themselves."""
from __future__ import annotations

import io
import json
import random

import pytest

from dyncalc import batch
from dyncalc.batch.fast_springs import spring_fast

UNITS = {"l": ["m", "mm", "cm", "ft"], "EI": ["N*m^2", "kN*m^2"], "E": ["GPa", "MPa", "Pa"],
         "I": ["m^4", "cm^4", "mm^4"], "EA": ["N", "kN"], "A": ["m^2", "cm^2", "mm^2"],
         "G": ["GPa", "MPa"], "d": ["mm", "m"], "D": ["mm", "cm"], "n": [""], "c": [""],
         "GJ_t": ["N*m^2", "kN*m^2"], "J_t": ["m^4", "mm^4"]}
KINDS = {"cantilever": [("l", "EI"), ("E", "I", "l")],
         "simply-supported": [("EI", "l"), ("l", "E", "I")],
         "beam": [("c", "l", "EI"), ("E", "I", "l", "c")],
         "axial": [("l", "EA"), ("E", "A", "l")], "coil": [("G", "d", "D", "n")]}
TORSIONAL = [("l", "GJ_t"), ("G", "J_t", "l")]


def _run(how, path, fast, as_json):
    out, err = io.StringIO(), io.StringIO()
    code = batch.run_batch(batch.SpringRows(how), str(path), as_json=as_json, on_error="skip",
                           out=out, err=err, fast=fast)
    return code, out.getvalue(), err.getvalue()


def _value(rng: random.Random) -> str:
    exponent = rng.choice([rng.uniform(-3, 4)] * 8 + [rng.uniform(-200, 200)])
    return repr(10.0 ** exponent) if rng.random() < 0.5 else f"{10.0 ** exponent:.4g}"


def _element(rng: random.Random, torsional: bool = False) -> str:
    kind = "torsion-bar" if torsional else rng.choice(sorted(KINDS))
    names = rng.choice(TORSIONAL if torsional else KINDS[kind])
    args = []
    for name in names:
        unit = rng.choice(UNITS[name])
        args.append(f"{name}={_value(rng)}{rng.choice(['', ' '])}{unit}".rstrip())
    return f'"{kind}({", ".join(args)})"'


def _table(rng: random.Random, rows: int, torsional: bool = False) -> str:
    lines = ["k1,k2,k3 [N*m/rad]" if torsional else "k1,k2,k3 [N/m]"]
    units = ["", " N*m/rad", " kN*m/rad"] if torsional else ["", " N/m", " lbf/in"]
    for _ in range(rows):
        cells = []
        for j in range(3):
            pick = rng.random()
            if pick < 0.55 and j < 2:
                cells.append(_element(rng, torsional))
            elif pick < 0.9 or j == 0:
                cells.append(_value(rng) + ("" if j == 2 else rng.choice(units)))
            else:
                cells.append("")
        lines.append(",".join(cells))
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("torsional", [False, True], ids=["linear", "torsional"])
@pytest.mark.parametrize("how", ["series", "parallel"])
def test_random_element_rows_equal_the_one_off(tmp_path, how, torsional):
    path = tmp_path / "elements.csv"
    path.write_text(_table(random.Random(f"elements-{how}-{torsional}"), 300, torsional))
    for as_json in (False, True):
        assert _run(how, path, True, as_json) == _run(how, path, False, as_json)


@pytest.mark.parametrize("how", ["series", "parallel"])
def test_ordinary_element_rows_take_the_columns(how):
    """The rows of ordinary values (no warning, no refusal) are computed on columns."""
    rng = random.Random(f"cover-{how}")
    spec = batch.SpringRows(how)
    rows = []
    for _ in range(60):
        cells = [_element(rng).strip('"'), _element(rng).strip('"'),
                 f"{rng.uniform(1, 1e4):.6g}"]
        cells = [c.replace("e+", "e") for c in cells]
        rows.append(cells)
    columns = [batch.Column(i, n, n, "", n) for i, n in enumerate(["k1", "k2", "k3"])]
    table = [list(column) for column in zip(*rows)]
    covered = {i for block in spring_fast(spec, columns, table, True, {})
               for i in block.rows.tolist()}
    clean = set()
    for i, row in enumerate(rows):
        try:
            result = spec.compute({f"k{j + 1}": c for j, c in enumerate(row)}, {})
        except Exception:  # noqa: BLE001 (a refusal: the one-off's)
            continue
        if not result.warnings:
            clean.add(i)
    assert covered <= clean and len(covered) >= 0.9 * len(clean) and len(clean) > 20


def test_textbook_values(tmp_path):
    """3 EI / l^3 = 3 * 2e4 / 8 = 7500 N/m in series with 5000 N/m: 3000 N/m; a coil
    G d^4 / (8 D^3 n) = 80e9 * 16e-12 / (8 * 8e-6 * 10) = 2000 N/m in parallel with an axial
    bar E A / l = 200e9 * 1e-4 / 2 = 1e7 N/m."""
    path = tmp_path / "book.csv"
    path.write_text('k1,k2\n"cantilever(l=2m, EI=2e4 N*m^2)",5000 N/m\n')
    code, out, err = _run("series", path, True, False)
    assert (code, err) == (0, "")
    assert out.splitlines()[1].split(",")[-2:] == ["3000.0", "7500.0"]
    path.write_text('k1,k2\n"coil(G=80GPa, d=2mm, D=20mm, n=10)","axial(l=2m, E=200GPa, '
                    'A=1cm^2)"\n')
    code, out, err = _run("parallel", path, True, True)
    line = json.loads(out)
    assert (code, err) == (0, "")
    assert line["results"]["k1"]["value"] == pytest.approx(2000.0, rel=1e-15)
    assert line["results"]["k2"]["value"] == pytest.approx(1e7, rel=1e-15)
    assert line["results"]["k_eq"]["value"] == pytest.approx(1e7 + 2000.0, rel=1e-15)
    assert list(line["inputs"]) == ["k1.G", "k1.d", "k1.D", "k1.n", "k2.l", "k2.E", "k2.A"]


def test_an_overflowing_element_falls_back_to_the_one_off(tmp_path):
    """A row the columns cannot take (its element overflows) gets the one-off's refusal; the
    next row is still computed."""
    path = tmp_path / "over.csv"
    path.write_text('k1,k2\n"cantilever(l=1e-120 m, EI=1 N*m^2)",5\n'
                    '"cantilever(l=1m, EI=3 N*m^2)",9\n')
    code, out, err = _run("series", path, True, False)
    assert err == ("Error: line 2: the stiffness of cantilever() (k1) overflows float64 "
                   "(N/m)\n")
    assert code == 2 and out.splitlines()[1:] == ['"cantilever(l=1m, EI=3 N*m^2)",9,4.5,9.0']
    assert (code, out, err) == _run("series", path, False, False)


@pytest.mark.parametrize("cell", ["cantilever(l=, EI=3 N*m^2)", "cantilever(l=2m, EI=3 kg)",
                                  "cantilever(l=-2m, EI=3 N*m^2)", "coil(G=1GPa, d=1mm, D=1cm)",
                                  "axial(l=1m, EA=2N, E=3Pa)", "cantilever(l=(1-1)*1m, EI=3)",
                                  "cantilever(l=2m, EI=\"3\")", "rod(E=1Pa, A=1m^2, L=1m)"])
def test_bad_element_cells_get_the_one_offs_message(tmp_path, cell):
    path = tmp_path / "bad.csv"
    quoted = cell.replace('"', '""')
    path.write_text(f'k1,k2\n"{quoted}",5\n"cantilever(l=1m, EI=3 N*m^2)",9\n')
    for as_json in (False, True):
        fast = _run("series", path, True, as_json)
        assert fast == _run("series", path, False, as_json)
        assert fast[2].startswith("Error: line 2: ") and fast[2].count("\n") == 1
