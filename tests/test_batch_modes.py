"""``modes --batch`` on its vectorised path (dyncalc/batch/fast_modes.py, a stacked Cholesky
reduction and eigh) against the one-off row by row: the same rows, columns, refusals and
texts, the numbers within 1e-12 relative (the documented difference: LAPACK's sygvd rounds
otherwise), and against the closed form of a two-mass chain."""
from __future__ import annotations

import csv
import io
import json
import math
import random

import numpy as np
import pytest

from dyncalc.batch import run_batch
from dyncalc.batch.header import read_header
from dyncalc.batch.rows import ModesRows

RTOL = 1e-12


def _matrix(rng, n: int, scale: float, style: str) -> str:
    a = np.array([[rng.uniform(-1, 1) for _ in range(n)] for _ in range(n)])
    spd = (a @ a.T + n * np.eye(n)) * scale
    spd = (spd + spd.T) / 2.0
    rows = [[repr(float(x)) for x in row] for row in spd]
    if style == "semicolons":
        return ";".join(",".join(r) for r in rows)
    return "[" + ", ".join("[" + ", ".join(r) + "]" for r in rows) + "]"


def _file(tmp_path, seed: int, count: int = 120, sizes=(1, 2, 3, 4)):
    rng = random.Random(seed)
    lines = ["M,K"]
    for _ in range(count):
        n = rng.choice(sizes)
        style = rng.choice(["brackets", "semicolons"])
        scale_m = rng.choice([1.0, 1e-100, 1e100, 3.5])
        scale_k = rng.choice([1.0, 1e-90, 1e90, 250.0])
        lines.append(f'"{_matrix(rng, n, scale_m, style)}","{_matrix(rng, n, scale_k, style)}"')
    lines += ['"[[1,0],[0,1]]","[[1,0],[0,1]]"',       # repeated frequencies: the one-off's
              '"[[1,0],[0,1]]","[[1,-1],[-1,1]]"',     # a rigid-body mode: a warning
              '"[[1,2],[2,1]]","[[1,0],[0,1]]"',       # M not positive definite: refused
              '"[[1,0],[0,1]]","[[1,5],[0,1]]"',       # K not symmetric: refused
              '"[[1,0],[0,1]]","[[1e400,0],[0,1]]"']   # beyond float64: refused
    path = tmp_path / "systems.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def _run(path, as_json: bool, fast: bool, normalize=None):
    out, err = io.StringIO(), io.StringIO()
    status = run_batch(ModesRows(normalize=normalize), str(path), as_json=as_json,
                       on_error="skip", out=out, err=err, fast=fast)
    return status, out.getvalue(), err.getvalue()


def _close(a, b) -> bool:
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_close(a[k], b[k]) for k in a)
    if isinstance(a, list):
        return len(a) == len(b) and all(_close(x, y) for x, y in zip(a, b))
    if isinstance(a, float) and isinstance(b, float):
        return math.isclose(a, b, rel_tol=RTOL, abs_tol=RTOL * 1e-300) or \
            abs(a - b) <= RTOL  # a mode component (largest is 1) may be near zero
    return a == b


def _cell(c: str):
    """A result cell as its floats (``a,b;c,d``), or the text (an input matrix, a name)."""
    try:
        return [float(x) for x in c.replace(";", ",").split(",")] if c else c
    except ValueError:
        return c


def _cells(text: str) -> list:
    return [[_cell(c) for c in row] for row in csv.reader(io.StringIO(text))]


@pytest.mark.parametrize("normalize", [None, "mass"])
@pytest.mark.parametrize("seed", [1, 2])
def test_vectorised_rows_are_the_one_off_within_1e_12(tmp_path, seed, normalize):
    path = _file(tmp_path, seed, sizes=(2,))  # CSV: the first row's columns (two modes)
    fast, generic = _run(path, False, True, normalize), _run(path, False, False, normalize)
    assert (fast[0], fast[2]) == (generic[0], generic[2]) and fast[0] == 2
    assert fast[2].count("Error: line") == 3 and fast[2].count("warning: line") == 1
    mine, theirs = _cells(fast[1]), _cells(generic[1])
    assert len(mine) == len(theirs) == 1 + 122
    for a, b in zip(mine, theirs):
        assert len(a) == len(b)
        for x, y in zip(a, b):
            assert _close(x, y), (x, y)
    path = _file(tmp_path, seed)  # JSON lines: every size
    jf, jg = _run(path, True, True, normalize), _run(path, True, False, normalize)
    assert (jf[0], jf[2]) == (jg[0], jg[2])
    lines_f, lines_g = jf[1].splitlines(), jg[1].splitlines()
    assert len(lines_f) == len(lines_g) == 122
    for a, b in zip(lines_f, lines_g):
        assert _close(json.loads(a), json.loads(b))


def test_most_rows_take_the_vectorised_path(tmp_path):
    path = _file(tmp_path, 3)
    rows = list(csv.reader(path.open()))
    spec = ModesRows()
    columns = read_header(1, rows[0], spec)
    blocks = spec.fast(spec, columns, [[r[0] for r in rows[1:]], [r[1] for r in rows[1:]]],
                       False, {})
    covered = sum(len(b.rows) for b in blocks)
    assert covered >= 100  # of 120 well-posed rows
    # repeated frequencies and a rigid-body mode: the one-off's physics a row at a time
    # (dyncalc/batch/fast_modes_rows.py); the three it refuses: row by row, its messages
    taken = {i for b in blocks for i in b.rows.tolist()}
    assert {120, 121} <= taken and not taken & {122, 123, 124}


def test_a_two_mass_chain_against_its_closed_form(tmp_path):
    """m, k between walls, m, k, m... : M = m I, K = k [[2, -1], [-1, 2]] gives
    omega_1 = sqrt(k/m) (in phase) and omega_2 = sqrt(3 k/m) (out of phase)."""
    rng = random.Random(4)
    lines = ["M,K"]
    expected = []
    for _ in range(50):
        m, k = rng.uniform(0.1, 10.0), rng.uniform(10.0, 1e4)
        lines.append(f'"[[{m!r},0],[0,{m!r}]]","[[{2 * k!r},{-k!r}],[{-k!r},{2 * k!r}]]"')
        expected.append((math.sqrt(k / m), math.sqrt(3.0 * k / m)))
    path = tmp_path / "chain.csv"
    path.write_text("\n".join(lines) + "\n")
    status, out, err = _run(path, True, True)
    assert (status, err) == (0, "")
    for line, (w1, w2) in zip(out.splitlines(), expected):
        results = json.loads(line)["results"]
        assert results["omega_1"]["value"] == pytest.approx(w1, rel=1e-13)
        assert results["omega_2"]["value"] == pytest.approx(w2, rel=1e-13)
        assert results["mode_1"]["value"] == [1.0, 1.0]
        shape = results["mode_2"]["value"]  # the first largest component is the +1
        assert shape[0] == 1.0 and shape[1] == pytest.approx(-1.0, rel=1e-13)


def _unit_file(tmp_path, seed: int, header: bool):
    """Matrices with units: in the header (``M [g]``) or after each cell's matrix
    (``[[...]] kg``); a row of bare numbers and one with a wrong unit among them."""
    rng = random.Random(seed)
    units_m, units_k = ["kg", "g", "t", "lb"], ["N/m", "kN/m", "lbf/in"]
    unit_m, unit_k = rng.choice(units_m), rng.choice(units_k)
    lines = [f"M [{unit_m}],K [{unit_k}]" if header else "M,K"]
    for _ in range(100):
        m, k = _matrix(rng, 2, 3.5, "brackets"), _matrix(rng, 2, 250.0, "brackets")
        if not header:
            m, k = f"{m} {rng.choice(units_m)}", f"{k} {rng.choice(units_k)}"
        lines.append(f'"{m}","{k}"')
    if not header:
        lines += ['"[[1, 0], [0, 2]]","[[300, -100], [-100, 100]]"',
                  '"[[1, 0], [0, 2]] kg","[[300, -100], [-100, 100]] N"']
    path = tmp_path / "units.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("header", [True, False], ids=["header-units", "cell-units"])
def test_rows_with_units_are_the_one_off_within_1e_12(tmp_path, header):
    """Units in the header or in the cells: each matrix times its unit's SI value, as the
    one-off reads it; the input entries (SI values, the text with its unit) exactly the
    one-off's, the results within 1e-12; a wrong unit refused as the one-off refuses it."""
    path = _unit_file(tmp_path, 11, header)
    for as_json in (False, True):
        fast, generic = _run(path, as_json, True), _run(path, as_json, False)
        assert (fast[0], fast[2]) == (generic[0], generic[2])
        if as_json:
            for a, b in zip(fast[1].splitlines(), generic[1].splitlines()):
                a, b = json.loads(a), json.loads(b)
                assert a["inputs"] == b["inputs"] and _close(a, b)
        else:
            for a, b in zip(_cells(fast[1]), _cells(generic[1])):
                assert all(_close(x, y) for x, y in zip(a, b)) and len(a) == len(b)
    if not header:
        assert fast[0] == 2 and fast[2].count("Error: line") == 1
    rows = list(csv.reader(path.open()))
    spec = ModesRows()
    blocks = spec.fast(spec, read_header(1, rows[0], spec),
                       [[r[0] for r in rows[1:]], [r[1] for r in rows[1:]]], True, {})
    assert sum(len(b.rows) for b in blocks) >= 80


def _damped_file(tmp_path, seed: int, count: int = 120):
    """Rows with a proportional C = a M + b K (underdamped modes, zeta about 1e-3 to 0.3, at
    scales 1e-100 to 1e100), followed by rows the kernel leaves to the one-off: damping that is
    not proportional (state-space), overdamped (a note), a zero C, C not symmetric."""
    rng = random.Random(seed)
    lines = ["M,K,C"]
    for _ in range(count):
        n = rng.choice((1, 2, 3))
        style = rng.choice(["brackets", "semicolons"])
        scale_m, scale_k = rng.choice([1.0, 1e-100, 3.5]), rng.choice([1.0, 1e90, 250.0])
        m_text, k_text = (_matrix(rng, n, s, style) for s in (scale_m, scale_k))
        M, K = (np.array([[float(x) for x in r.split(",")]
                          for r in t.strip("[]").replace("], [", ";").split(";")])
                for t in (m_text, k_text))
        rate = math.sqrt(scale_k / scale_m)
        a, b = rng.uniform(1e-3, 0.1) * rate, rng.uniform(1e-4, 0.05) / rate
        C = a * M + b * K
        c_text = "[" + ", ".join("[" + ", ".join(repr(float(x)) for x in r) + "]"
                                 for r in C) + "]"
        lines.append(f'"{m_text}","{k_text}","{c_text}"')
    lines += ['"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[0.3,0],[0,0]]"',     # not proportional
              '"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[5,0],[0,5]]"',       # overdamped: a note
              '"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[0,0],[0,0]]"',       # no damping
              '"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[1,0.5],[0,1]]"',     # C not symmetric
              '"[[1,0],[0,1]]","[[2,-1],[-1,2]]",""']                    # no C in this row
    path = tmp_path / "damped.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("normalize", [None, "mass"])
def test_damped_rows_are_the_one_off_within_1e_12(tmp_path, normalize):
    """Proportional damping on the stack: zeta_i, omega_d_i and the rest within 1e-12 of the
    one-off, the inputs (C with its unit) exactly; the rows it cannot take (overdamped, a zero
    or unsymmetric C) have the one-off's results, notes and refusals (the non-proportional row
    is on the stack too: tests/test_batch_modes_complex.py)."""
    path = _damped_file(tmp_path, 21)
    for as_json in (False, True):
        fast, generic = _run(path, as_json, True, normalize), _run(path, as_json, False,
                                                                    normalize)
        assert (fast[0], fast[2]) == (generic[0], generic[2]) and fast[0] == 2
        assert fast[2].count("Error: line") == 1
        assert fast[2].count("warning: line") == (0 if as_json else 3)  # JSON: in "warnings"
        if as_json:
            lines_f, lines_g = fast[1].splitlines(), generic[1].splitlines()
            assert len(lines_f) == len(lines_g) == 124
            for a, b in zip(lines_f, lines_g):
                a, b = json.loads(a), json.loads(b)
                assert a["inputs"] == b["inputs"] and _close(a, b)
                for name in a["results"]:  # a damping ratio is small: relative, no floor
                    if name.startswith(("zeta", "omega_d")):
                        assert math.isclose(a["results"][name]["value"],
                                            b["results"][name]["value"], rel_tol=RTOL)
        else:
            mine, theirs = _cells(fast[1]), _cells(generic[1])
            assert len(mine) == len(theirs) == 125
            for a, b in zip(mine, theirs):
                assert len(a) == len(b) and all(_close(x, y) for x, y in zip(a, b)), (a, b)
    rows = list(csv.reader(path.open()))
    spec = ModesRows()
    blocks = spec.fast(spec, read_header(1, rows[0], spec),
                       [[r[i] for r in rows[1:]] for i in range(3)], True, {})
    covered = [i for b in blocks for i in b.rows.tolist()]
    # row 120 (not proportional) on the stack's state-space path since round 7; row 121
    # (overdamped, a note) through the one-off's physics a row at a time since round 8
    # (dyncalc/batch/fast_modes_rows.py); row 122 (C all zero: the one-off's JSON input shows
    # no "assumed_si", which the check of the input entries catches) and row 123 (C not
    # symmetric, refused) row by row
    assert len(covered) >= 100 and {120, 121, 124} <= set(covered)
    assert not {122, 123} & set(covered)


def test_damped_two_mass_chain_against_its_closed_form(tmp_path):
    """M = m I, K = k [[2, -1], [-1, 2]], C = c I: zeta_i = c / (2 m omega_i) with
    omega_1 = sqrt(k/m), omega_2 = sqrt(3 k/m), omega_d_i = omega_i sqrt(1 - zeta_i^2)."""
    rng = random.Random(5)
    lines, expected = ["M,K,C"], []
    for _ in range(40):
        m, k, c = rng.uniform(0.1, 10.0), rng.uniform(10.0, 1e4), rng.uniform(0.01, 1.0)
        lines.append(f'"[[{m!r},0],[0,{m!r}]]","[[{2 * k!r},{-k!r}],[{-k!r},{2 * k!r}]]",'
                     f'"[[{c!r},0],[0,{c!r}]]"')
        expected.append([(w, c / (2.0 * m * w)) for w in (math.sqrt(k / m),
                                                          math.sqrt(3.0 * k / m))])
    path = tmp_path / "chain.csv"
    path.write_text("\n".join(lines) + "\n")
    status, out, err = _run(path, True, True)
    assert (status, err) == (0, "")
    for line, modes in zip(out.splitlines(), expected):
        record = json.loads(line)
        assert record["model"] == "proportional damping"
        results = record["results"]
        for i, (w, zeta) in enumerate(modes, start=1):
            assert results[f"zeta_{i}"]["value"] == pytest.approx(zeta, rel=1e-13, abs=0.0)
            assert results[f"omega_d_{i}"]["value"] == pytest.approx(
                w * math.sqrt(1.0 - zeta ** 2), rel=1e-13, abs=0.0)
