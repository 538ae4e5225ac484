"""How ``modes --batch`` reads a chunk's matrix cells (dyncalc/batch/fast_modes.py): a column
whose cells share one template is read in one pass, and that pass must give exactly what the
reference reading gives (each cell's template by ``sub``, its numbers by ``findall``, each
read by ``float``); the one-off is probed once a run per kind of rows, not once a chunk."""
from __future__ import annotations

import io
import random

import numpy as np
import pytest

from dyncalc.batch import run_batch
from dyncalc.batch import fast_modes
from dyncalc.batch.fast_modes import _NUMBER_RE, _uniform
from dyncalc.batch.rows import ModesRows


def _reference(cells: list[str]):
    """(template, floats) by the per-cell reading, or ``None`` where templates differ or
    ``float`` refuses a number (then the floats are ``None``)."""
    templates = {_NUMBER_RE.sub("#", c) for c in cells}
    if len(templates) != 1 or "#" not in next(iter(templates)):
        return None
    found = [x for c in cells for x in _NUMBER_RE.findall(c)]
    try:
        values = [float(x) for x in found]
    except ValueError:
        values = None
    return templates.pop(), values


def _read(cells: list[str]):
    return _uniform(cells, "\n".join(cells))


_PIECES = ["[", "]", ",", ";", " ", "[[", "]]", "],[", ", ", " kg", "kN/m", ".", "e", "E",
           "+", "-", "..", "x", "\t", "meter"]
_NUMBERS = ["0", "1", "-0", "+5", ".5", "5.", "1e5", "1E-3", "007", "1.5e+300", "1e400",
            "-2.25", "12", "3", "0.1", "1-2", "1e", "2.5.5", "9007199254740993"]


def _cell(rng, template: list[str]) -> str:
    return "".join(rng.choice(_NUMBERS) if part == "#" else part for part in template)


@pytest.mark.parametrize("seed", range(6))
def test_one_pass_reading_is_the_per_cell_reading(seed):
    rng = random.Random(seed)
    for _ in range(400):
        template = []
        for _ in range(rng.randint(1, 7)):
            template += [rng.choice(_PIECES)] if rng.random() < 0.6 else ["#"]
        template.append(rng.choice(["#", *_PIECES]))
        cells = [_cell(rng, template) for _ in range(rng.randint(1, 6))]
        if rng.random() < 0.3:  # a cell of another template, sometimes one of few numbers
            cells[rng.randrange(len(cells))] = _cell(rng, template[:-1] or ["#"])
        mine, theirs = _uniform(cells, "\n".join(cells)), _reference(cells)
        if theirs is None:
            assert mine is None, cells
            continue
        assert mine is not None and mine[0] == theirs[0], cells
        if theirs[1] is None:
            assert mine[1] is None, cells
        else:
            assert mine[1] is not None and mine[1].tolist() == theirs[1], cells
            assert np.signbit(mine[1]).tolist() == np.signbit(theirs[1]).tolist(), cells


def test_a_number_run_that_is_two_numbers_is_not_the_template():
    # "[.5]" reads as one number ".5"; "[..5]" as "[." and ".5": other templates
    assert _read(["[..5]", "[.5]"]) is None
    assert _read(["[[1,2],[3,4]]", "[[1,2],[3,4]5]"]) is None
    assert _read(["[[1,2],[3,4]]", "[[1,],[23,4]]"]) is None
    # the same text around the numbers and as many numbers, at other places
    assert _read(["[1, 2]", "[12, ]", "1[1, 2]"]) is None
    assert _read(["[1, 2] kg", "[12, ] kg", "[1, 2] k3g"]) is None
    template, values = _read(["[[1,-0],[2e3,4]] kg", "[[5,6],[7,.5]] kg"])
    assert template == "[[#,#],[#,#]] kg"
    assert values.tolist() == [1.0, -0.0, 2000.0, 4.0, 5.0, 6.0, 7.0, 0.5]
    assert np.signbit(values[1])


def test_numbers_are_parsed_in_slices(monkeypatch):
    monkeypatch.setattr(fast_modes, "PARSE_SLICE", 3)
    cells = [f"[[{i}.25,-{i}],[{i}e-3,{i}]]" for i in range(1, 6)]
    _template, values = _read(cells)
    assert values.tolist() == [float(x) for c in cells for x in _NUMBER_RE.findall(c)]


def _chain_rows(rng, count: int) -> list[str]:
    rows = []
    for _ in range(count):
        m1, m2, k1, k2 = (round(rng.uniform(lo, hi), 4) for lo, hi in
                          ((0.5, 20), (0.5, 20), (1e2, 1e4), (1e2, 1e4)))
        rows.append(f'"[[{m1},0],[0,{m2}]]","[[{k1 + k2},{-k2}],[{-k2},{k2}]]"')
    return rows


def test_the_one_off_is_probed_once_a_run_not_once_a_chunk(tmp_path, monkeypatch):
    rng = random.Random(7)
    rows = _chain_rows(rng, 50)
    rows[30] = rows[30].replace("[[", "[ [", 1)  # another template: probed once too
    path = tmp_path / "chains.csv"
    path.write_text("M,K\n" + "\n".join(rows) + "\n")
    spec = ModesRows()
    spec.csv_rows = 8  # seven chunks
    calls = []
    compute = spec.compute
    spec.compute = lambda texts, labels: calls.append(texts) or compute(texts, labels)
    out, err = io.StringIO(), io.StringIO()
    assert run_batch(spec, str(path), out=out, err=err) == 0 and not err.getvalue()
    assert len(calls) == 2  # the first row's template and row 30's
    generic = io.StringIO()
    assert run_batch(ModesRows(), str(path), out=generic, fast=False) == 0
    assert len(out.getvalue().splitlines()) == len(generic.getvalue().splitlines()) == 51


_PLAIN_PIECES = ["[[", "], [", "],[", ", ", ",", "]]", "; ", ";", " kg", "[", "]", " "]


@pytest.mark.parametrize("seed", range(4))
def test_columns_of_plain_templates_read_by_numpy_are_the_per_cell_reading(seed,
                                                                         monkeypatch):
    # templates whose text holds no number character: numpy on the column's bytes reads
    # them (fast_modes._plain); a space moved across a number, a missing or an extra number,
    # a number JSON refuses (+5, .5, 007, 1e400) must give what the per-cell reading gives
    taken = []
    plain = fast_modes._plain
    monkeypatch.setattr(fast_modes, "_plain",
                        lambda *a: taken.append(plain(*a) is not None) or plain(*a))
    rng = random.Random(seed)
    numbers = ["0", "1", "-0", "-2.25", "1e5", "1E-3", "0.1", "12345.678e-9", "3"]
    for _ in range(300):
        pieces = [rng.choice(["", "[[", "["])]
        for _ in range(rng.randint(1, 8)):
            pieces.append(rng.choice(_PLAIN_PIECES[1:-1]))
        pieces[-1] = rng.choice(["]]", "]", "", " kg", "]] kg"])
        template = [x for p in pieces[:-1] for x in (p, "#")] + [pieces[-1]]
        cells = ["".join(rng.choice(numbers) if part == "#" else part for part in template)
                 for _ in range(rng.randint(1, 5))]
        change = rng.random()
        i = rng.randrange(len(cells))
        if change < 0.15:
            cells[i] = cells[i].replace(", ", " ,", 1)
        elif change < 0.3:
            cells[i] = cells[i].replace(",", ",7,", 1)
        elif change < 0.4:
            cells[i] = cells[i].replace(",", ",,", 1)
        elif change < 0.55:
            cells[i] = cells[i].replace("1", rng.choice(["+5", ".5", "007", "1e400", "5."]),
                                        1)
        mine, theirs = _read(cells), _reference(cells)
        if theirs is None:
            assert mine is None, cells
            continue
        assert mine is not None and mine[0] == theirs[0], cells
        if theirs[1] is None:
            assert mine[1] is None, cells
        else:
            assert mine[1] is not None and mine[1].tolist() == theirs[1], cells
            assert np.signbit(mine[1]).tolist() == np.signbit(theirs[1]).tolist(), cells
    assert taken.count(True) > 100 and taken.count(False) > 20


def test_quoted_cells_without_a_comma_are_left_to_the_csv_module():
    from dyncalc.batch.cells import _quoted_columns

    assert _quoted_columns('"1,2","3,4"\n"5,6","7,8"', 2) == [["1,2", "5,6"], ["3,4", "7,8"]]
    assert _quoted_columns('"1,2","3,4"\n"5,6","78"', 2) is None
    assert _quoted_columns('"12","3,4"\n"5,6","7,8"', 2) is None
