"""``spring-series`` / ``spring-parallel --batch`` with nested groups and shared-value columns
(dyncalc/batch/fast_spring_trees.py): the rows computed on columns are byte for byte what the
generic path (the one-off row by row) writes, CSV and JSON lines, stderr and exit status, on
random rows (units mixed, extremes that overflow or underflow, refusals included); a
textbook network checks the numbers themselves."""
from __future__ import annotations

import io
import random

import pytest

from dyncalc import batch
from dyncalc.batch.fast_spring_trees import parse_cell, tree_fast

from test_batch_spring_elements import _value

UNITS = {"l": ["m", "mm", "ft"], "EI": ["N*m^2", "kN*m^2"], "E": ["GPa", "Pa"],
         "I": ["m^4", "cm^4"], "EA": ["N", "kN"], "A": ["m^2", "mm^2"], "G": ["GPa"],
         "d": ["mm"], "D": ["mm", "cm"], "n": [""], "c": [""]}
#: what an element gives itself; the rest comes from the shared columns (or is refused)
OWN = {"cantilever": [("l",), ("l", "EI"), (), ("E", "l"), ("l", "E", "I")],
       "simply-supported": [("l",), ()], "beam": [("c", "l"), ("c",)],
       "axial": [("l", "EA"), ("l",), ()], "coil": [("G", "d", "D", "n"), ("d", "D", "n")]}


def _run(how, path, fast, as_json):
    out, err = io.StringIO(), io.StringIO()
    code = batch.run_batch(batch.SpringRows(how), str(path), as_json=as_json, on_error="skip",
                           out=out, err=err, fast=fast)
    return code, out.getvalue(), err.getvalue()


def _param(rng, name):
    return f"{name}={rng.choice(['', ' '])}{_value(rng)}{rng.choice(['', ' '])}" \
           f"{rng.choice(UNITS[name])}".rstrip()


def _leaf(rng):
    return rng.choice(["", " "]) + _value(rng) + rng.choice(["", " N/m", " lbf/in", "N/m"])


def _node(rng, depth):
    pick = rng.random()
    if depth < 3 and pick < 0.35:
        how = rng.choice(["series", "parallel"])
        return f"{how}({','.join(_node(rng, depth + 1) for _ in range(rng.randint(1, 3)))})"
    if pick < 0.7:
        kind = rng.choice(sorted(OWN))
        return f"{kind}({', '.join(_param(rng, p) for p in rng.choice(OWN[kind]))})"
    return _leaf(rng)


def _table(rng, rows, shared=("EI", "EA", "l")):
    lines = ["k1,k2,k3 [N/m]," + ",".join(f"{s} [{UNITS[s][0]}]" for s in shared)]
    for _ in range(rows):
        cells = ['"' + _node(rng, 1 if rng.random() < 0.5 else 0) + '"',
                 '"' + _node(rng, 1) + '"' if rng.random() < 0.8 else "",
                 _value(rng) if rng.random() < 0.7 else ""]
        cells += [(_value(rng) + rng.choice(["", " " + rng.choice(UNITS[s])]))
                  if rng.random() < 0.8 else "" for s in shared]
        lines.append(",".join(cells))
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("how", ["series", "parallel"])
def test_random_network_rows_equal_the_one_off(tmp_path, how):
    path = tmp_path / "trees.csv"
    path.write_text(_table(random.Random(f"trees-{how}"), 400))
    for as_json in (False, True):
        assert _run(how, path, True, as_json) == _run(how, path, False, as_json)


@pytest.mark.parametrize("how", ["series", "parallel"])
def test_random_nested_rows_without_shared_columns_equal_the_one_off(tmp_path, how):
    path = tmp_path / "nested.csv"
    path.write_text(_table(random.Random(f"nested-{how}"), 300, shared=()).replace(",\n", "\n")
                    .replace("k3 [N/m],", "k3 [N/m]"))
    for as_json in (False, True):
        assert _run(how, path, True, as_json) == _run(how, path, False, as_json)


@pytest.mark.parametrize("how", ["series", "parallel"])
def test_ordinary_network_rows_take_the_columns(how):
    """Rows of ordinary values (no warning, no refusal) in nested groups with shared values are
    computed on columns: at least 90 % of those the one-off computes without a warning."""
    rng = random.Random(f"cover-trees-{how}")
    spec = batch.SpringRows(how)
    rows = []
    for _ in range(80):
        ei, l2 = f"{rng.uniform(1e3, 1e5):.6g} N*m^2", f"{rng.uniform(0.5, 3):.4g}m"
        rows.append([f"parallel(cantilever(l={l2}), {rng.uniform(1, 1e4):.6g} N/m)",
                     f"series(axial(l=2m, EA={rng.uniform(1, 1e6):.6g}N), "
                     f"{rng.uniform(1, 1e4):.6g})", ei])
    columns = [batch.Column(i, n, n, "", n) for i, n in enumerate(["k1", "k2", "EI"])]
    cells = {col.key: [row[col.index] for row in rows] for col in columns}
    covered = {i for block in tree_fast(spec, columns, cells, range(len(rows)), True, {})
               for i in block.rows.tolist()}
    clean = set()
    for i, row in enumerate(rows):
        result = spec.compute({"k1": row[0], "k2": row[1], "EI": row[2]}, {})
        if not result.warnings:
            clean.add(i)
    assert covered <= clean and len(covered) >= 0.9 * len(clean) and len(clean) > 60


def test_textbook_network(tmp_path):
    """E5.26, system 2 (Gross et al.): cantilevers of 2a and a in parallel, in series with k:
    27 EI k / (27 EI + 8 k a^3) with EI = 2e4 N m^2, a = 1 m, k = 5000 N/m: 540e6 / 116e3."""
    path = tmp_path / "book.csv"
    path.write_text('k1,k2,EI [N*m^2]\n"parallel(cantilever(l=2m), cantilever(l=1m))",5kN/m,2e4\n')
    code, out, err = _run("series", path, True, False)
    assert (code, err) == (0, "")
    k_eq, k1, k2 = (float(v) for v in out.splitlines()[1].split(",")[-3:])
    assert k_eq == pytest.approx(27 * 2e4 * 5000 / (27 * 2e4 + 8 * 5000), rel=2e-16)
    assert (k1, k2) == (7500.0, 60000.0)


def test_an_unused_shared_value_falls_back_to_the_one_offs_refusal(tmp_path):
    path = tmp_path / "unused.csv"
    path.write_text('k1,k2,EI,EA\n"series(cantilever(l=2m), 5)",7,3 N*m^2,2 N\n'
                    '"series(cantilever(l=2m), 5)",7,3 N*m^2,\n')
    code, out, err = _run("series", path, True, False)
    assert err == ("Error: line 2: EA=2 N is not used by any element; shared values are for the "
                   "parameters of cantilever(), simply-supported(), beam(), axial(), "
                   "torsion-bar() and coil()\n")
    assert code == 2 and len(out.splitlines()) == 2
    assert (code, out, err) == _run("series", path, False, False)


def test_an_underflowing_group_falls_back_with_the_one_offs_warning(tmp_path):
    path = tmp_path / "tiny.csv"
    path.write_text('k1,k2\n"series(1e-300, 1e-300)",1e-20\n"parallel(1, 2)",3\n')
    for as_json in (False, True):
        fast = _run("parallel", path, True, as_json)
        assert fast == _run("parallel", path, False, as_json) and fast[0] == 0


@pytest.mark.parametrize("cell, expected", [
    ("5", (("leaf",), ["5"])),
    ("series(parallel(1, 2), coil(G=1GPa, d=1mm, D=1cm, n=3))",
     (("group", "series", (("group", "parallel", (("leaf",), ("leaf",))),
                           ("element", "coil", ("G", "d", "D", "n")))),
      ["1", " 2", "1GPa", "1mm", "1cm", "3"])),
    ("series(1, (2))", None), ("axial(l=(1+2)*1m, EA=3N)", None), ("series(1,)", None),
    ("series(1, 2) x", None), ("spring(1)", None), ("series(1, 2", None)])
def test_parse_cell(cell, expected):
    assert parse_cell(cell) == expected


@pytest.mark.parametrize("how", ["series", "parallel"])
def test_random_rows_of_one_template_equal_the_one_off(tmp_path, how):
    """Every cell of a column one template (the split by text replacement), values from
    ordinary to extreme, the shared columns given or not (unused or missing: refusals)."""
    rng = random.Random(f"template-{how}")
    lines = ["k1,k2 [N/m],EI [N*m^2],EA"]
    for _ in range(300):
        lines.append(f'"parallel(cantilever(l={_value(rng)} m), series({_value(rng)} N/m,'
                     f'axial(l={_value(rng)}mm)))",{_value(rng)},'
                     + (_value(rng) if rng.random() < 0.9 else "") + ","
                     + (f"{_value(rng)} kN" if rng.random() < 0.9 else ""))
    path = tmp_path / "template.csv"
    path.write_text("\n".join(lines) + "\n")
    for as_json in (False, True):
        fast = _run(how, path, True, as_json)
        assert fast == _run(how, path, False, as_json)
        assert fast[1].count("\n") > 150  # most rows computed


@pytest.mark.parametrize("seed", range(30))
def test_a_column_of_one_template_is_split_as_each_cell_alone(seed):
    """``_uniform_split``: a column of one template is always taken, with the structure and
    values :func:`parse_cell` gives each cell; where it takes a column with a cell changed,
    every cell is the first cell's skeleton (values cut out, one cell at a time) and its
    values are the ones cut (read, and refused where they are no number, later)."""
    from dyncalc.batch.fast_spring_trees import _PIECE_RE, _uniform_split

    rng = random.Random(seed)
    template = rng.choice(["parallel(cantilever(l={} m), {} N/m)", "series({},{})",
                           "parallel(axial(l={}, EA={} N), series({} N/m, {}))",
                           "cantilever(l={})"])
    fields = template.count("{}")
    column = [template.format(*(_value(rng) for _ in range(fields)))
              for _ in range(rng.randint(1, 8))]
    got = _uniform_split(column)
    assert got is not None and got[0] == parse_cell(column[0])[0]
    assert [list(t) for t in zip(*got[1])] == [parse_cell(c)[1] for c in column]
    for _ in range(20):  # one cell changed by a character of the structure or a value's
        changed = list(column)
        i = rng.randrange(len(changed))
        at = rng.randrange(len(changed[i]) + 1)
        changed[i] = changed[i][:at] + rng.choice("(),= 1m\n") + changed[i][at + 1:]
        got = _uniform_split(changed)
        if got is not None and "(" not in changed[0]:  # a column of plain stiffnesses
            assert got == (("leaf",), [changed]) and not any("(" in c for c in changed)
        elif got is not None:
            assert got[0] == parse_cell(changed[0])[0]
            skeleton = _PIECE_RE.sub("", changed[0])
            assert [_PIECE_RE.sub("", c) for c in changed] == [skeleton] * len(changed)
            assert [list(t) for t in zip(*got[1])] == [_PIECE_RE.findall(c) for c in changed]
