"""Element words whose cells share one template (dyncalc/batch/fast_springs.py ``_uniform``:
the values split off a whole column by text replacement, or one regular expression where
JSON does not read a literal): byte for byte what the generic path (the one-off row by row)
writes, CSV and JSON lines, stderr and exit status, on random literals of every form the
reader takes or refuses (``+5``, ``.5``, ``5.``, ``-0``, ``007``, ``1e400``, ``1e-400``,
values that overflow or underflow an element) and templates with odd spacing."""
from __future__ import annotations

import io
import random

import pytest

from dyncalc import batch
from dyncalc.batch import fast_springs
from dyncalc.batch.fast_springs import _element_column, _split_fixed, spring_fast

#: (template, the parameters' names): ``{}`` is a literal
TEMPLATES = [
    ("cantilever(l={} m, EI={} N*m^2)", ("l", "EI")),
    ("cantilever(l={}m, EI={}kN*m^2)", ("l", "EI")),
    ("simply-supported(EI= {} N*m^2 , l={} mm)", ("EI", "l")),
    ("beam(c={}, l={} m, E={} GPa, I={} cm^4)", ("c", "l", "E", "I")),
    ("axial(l={} m, EA={} N)", ("l", "EA")),
    ("axial(E={} MPa, A={}  mm^2, l={}ft)", ("E", "A", "l")),
    ("coil(G={} GPa, d={} mm, D={} cm, n={})", ("G", "d", "D", "n")),
]
ODD = ["+5", ".5", "5.", "-0", "0", "007", "1e400", "1e-400", "-3", "2e", "1E+2", "-0.0",
       "1e-200", "1e200", "0e5"]


def _literal(rng: random.Random) -> str:
    if rng.random() < 0.04:
        return rng.choice(ODD)
    x = 10.0 ** rng.uniform(-3, 4)
    return rng.choice([repr(x), f"{x:.4g}", f"{x:.6e}", str(int(x) + 1)])


def _cell(template: str, rng: random.Random) -> str:
    return template.format(*(_literal(rng) for _ in range(template.count("{}"))))


def _run(how, path, fast, as_json):
    out, err = io.StringIO(), io.StringIO()
    code = batch.run_batch(batch.SpringRows(how), str(path), as_json=as_json, on_error="skip",
                           out=out, err=err, fast=fast)
    return code, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("seed", range(6))
def test_random_literals_in_one_template_equal_the_one_off(tmp_path, seed):
    rng = random.Random(f"uniform-{seed}")
    how = rng.choice(["series", "parallel"])
    first, second = rng.sample([t for t, _n in TEMPLATES], 2)
    lines = ["k1,k2,k3 [N/m]"]
    for _ in range(400):
        lines.append(f'"{_cell(first, rng)}","{_cell(second, rng)}",{_literal(rng)}')
    path = tmp_path / "uniform.csv"
    path.write_text("\n".join(lines) + "\n")
    for as_json in (False, True):
        fast = _run(how, path, True, as_json)
        assert fast == _run(how, path, False, as_json)
    assert fast[1].count("\n") > 200  # most rows are written


def test_the_uniform_path_takes_the_ordinary_rows():
    """Every clean row of a one-template chunk is computed on columns, by text replacement
    (not the regular expression) where every literal reads as JSON."""
    rng = random.Random("uniform-cover")
    spec = batch.SpringRows("series")
    rows = [[f"cantilever(l={rng.uniform(0.2, 3):.6g} m, EI={rng.uniform(1e3, 1e6):.6g} N*m^2)",
             f"{rng.uniform(10, 1e4):.6g}"] for _ in range(200)]
    columns = [batch.Column(i, n, n, "", n) for i, n in enumerate(["k1", "k2"])]
    table = [list(column) for column in zip(*rows)]
    assert fast_springs._uniform(columns, table) is not None
    blocks = spring_fast(spec, columns, table, False, {})
    assert [block.rows.tolist() for block in blocks] == [list(range(200))]
    k_eq = blocks[0].values["k_eq"]
    for i in (0, 77, 199):  # 1 / (l^3 / (3 EI) + 1 / k2), independently
        l, ei = (float(x.split("=")[1].split()[0]) for x in rows[i][0][11:-1].split(", "))
        assert k_eq[i] == pytest.approx(1 / (l ** 3 / (3 * ei) + 1 / float(rows[i][1])),
                                        rel=1e-14)


def test_one_odd_row_sends_the_chunk_to_the_grouping():
    rows = ["cantilever(l=2 m, EI=3 N*m^2)", "cantilever(l=4 m, EI=5 N*m^2)",
            "cantilever(EI=5 N*m^2, l=4 m)"]
    assert _element_column(rows[:2], rows[0]) is not None
    assert _element_column(rows, rows[0]) is None
    columns = [batch.Column(0, "k1", "k1", "", "k1")]
    assert fast_springs._uniform(columns, [rows]) is None


@pytest.mark.parametrize("cells, values", [
    (["cantilever(l=2 m, EI=3 N*m^2)", "cantilever(l=-0.5 m, EI=1e5 N*m^2)"],
     ["2", "3", "-0.5", "1e5"]),
    (["cantilever(l=2 m, EI=3 N*m^2)", "cantilever(l=2 m, EI=3 m, EI=4 N*m^2)"], None),
    (["cantilever(l=2 m, EI=3 N*m^2)", "cantilever(l=2 m, EI=3 N*m^2) "], None),
    (["cantilever(l=2 m, EI=3 N*m^2)", "cantilever(l=2  m, EI=3 N*m^2)"], None),
])
def test_split_fixed(cells, values):
    texts = ["cantilever(l=", " m, EI=", " N*m^2)"]
    assert _split_fixed("\n".join(cells), len(cells), texts) == values


def test_a_text_that_could_continue_a_literal_is_not_split_by_replacement():
    """``l=2.5 m`` against the template of ``l=1e5.5 m`` (the literal ``1e5``, then ``.5 m``):
    replacement would read ``2``; the regular expression reads ``2.5`` and refuses the row."""
    assert _split_fixed("axial(l=1e5.5 m, EA=1 N)", 1, ["axial(l=", ".5 m, EA=", " N)"]) is None
    assert _element_column(["axial(l=1e5.5 m, EA=1 N)", "axial(l=2.5 m, EA=1 N)"],
                           "axial(l=1e5.5 m, EA=1 N)") is None


def test_values_typed_with_blanks_show_as_typed_on_both_paths(tmp_path):
    """The one-off's input entry shows a value as typed between ``=`` and the comma
    (``" 2 m "``); so do the one-template path and the grouping of mixed templates."""
    path = tmp_path / "blanks.csv"
    one = ['"cantilever(l= 2 m , EI=3 N*m^2)",5', '"cantilever(l= 4 m , EI=7 N*m^2)",6']
    path.write_text("k1,k2\n" + "\n".join(one) + "\n")
    code, out, err = _run("series", path, True, True)
    assert (code, err) == (0, "") and out.count('"text": " 2 m "') == 1
    assert (code, out, err) == _run("series", path, False, True)
    path.write_text("k1,k2\n" + "\n".join(one + ['"axial(l=\t2 m, EA=3 N)",5']) + "\n")
    code, out, err = _run("parallel", path, True, True)
    assert (code, err) == (0, "") and out.count('"text": "\\t2 m"') == 1
    assert (code, out, err) == _run("parallel", path, False, True)


@pytest.mark.parametrize("rows, probes", [
    (["100,200"] * 25, 1),
    (['"axial(l=2 m, EA=3 N)",5'] * 25, 1),
    (["100 N/m,200"] * 12 + ["100 lbf/in,200"] * 13, 2),  # another unit typed: its own probe
])
def test_one_probe_per_kind_of_block_a_run(tmp_path, monkeypatch, rows, probes):
    """The one-off checks one row of each kind of block once a run, not once a chunk (a
    third of a plain run's time went to one probe a chunk); the output is unchanged."""
    from dyncalc.batch import fast_commands

    calls = []
    probe = fast_commands._probe
    monkeypatch.setattr(fast_commands, "_probe", lambda *a, **k: calls.append(1) or probe(*a, **k))
    monkeypatch.setattr(batch, "CHUNK_ROWS", 10)
    path = tmp_path / "chunks.csv"
    path.write_text("k1,k2\n" + "\n".join(rows) + "\n")
    fast = _run("parallel", path, True, False)
    assert len(calls) == probes
    assert fast == _run("parallel", path, False, False) and fast[1].count("\n") == 26
