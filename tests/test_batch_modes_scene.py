"""``modes --scene NAME --batch`` on columns (dyncalc/commands/modes_scene_columns.py: the
scene's matrices a column at a time, then the stacked kernel) against the one-off row by
row: the same rows, columns, refusals and texts, the numbers within 1e-12 relative (the
documented tolerance of ``modes --batch``: the stack rounds otherwise than sygvd), and
coupled-blocks against its closed form."""
from __future__ import annotations

import csv
import io
import json
import math
import random

import pytest

from dyncalc.batch import run_batch
from dyncalc.errors import InputError
from dyncalc.batch.header import read_header
from dyncalc.batch.rows import ModesRows

RTOL = 1e-12

#: Each scene's header and a random row of its parameters (units as typed).
_SCENES = {
    "coupled-blocks": ("m1 [kg],m2 [g],k1 [N/m],k2 [kN/m],k3 [N/m]",
                       lambda r: [r.uniform(0.1, 10), r.uniform(100, 9000),
                                  r.uniform(1, 500), r.uniform(0.01, 2), r.uniform(1, 500)]),
    "block-disk-springs": ("M [kg],m [kg],r [cm],k [N/m]",
                           lambda r: [r.uniform(0.1, 10), r.uniform(0.1, 10),
                                      r.uniform(1, 50), r.uniform(1, 1000)]),
    "spring-coupled-pendulums": ("m [kg],l [m],k [N/m],b [m]",
                                 lambda r: [r.uniform(0.1, 5), r.uniform(0.2, 3),
                                            r.uniform(1, 300), r.choice([0.0, r.uniform(0, 2)])]),
}


def _file(tmp_path, scene: str, seed: int, count: int = 80, bad=()):
    rng = random.Random(seed)
    header, row = _SCENES[scene]
    lines = [header]
    for _ in range(count):
        scale = rng.choice([1.0, 1e-30, 1e30])  # every mass and stiffness scaled alike
        values = row(rng)
        if scene == "coupled-blocks":
            values = [v * scale for v in values]
        lines.append(",".join(repr(v) for v in values))
    lines += list(bad)
    path = tmp_path / f"{scene}.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def _run(path, scene, as_json: bool, fast: bool, normalize=None):
    out, err = io.StringIO(), io.StringIO()
    status = run_batch(ModesRows(scene=scene, normalize=normalize), str(path), as_json=as_json,
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
    try:
        return [float(x) for x in c.split(",")] if c else c
    except ValueError:
        return c


def _cells(text: str) -> list:
    return [[_cell(c) for c in row] for row in csv.reader(io.StringIO(text))]


def _blocks(path, scene):
    rows = list(csv.reader(path.open()))
    spec = ModesRows(scene=scene)
    columns = read_header(1, rows[0], spec)
    table = [[r[i] for r in rows[1:]] for i in range(len(rows[0]))]
    return spec.fast(spec, columns, table, True, {})


@pytest.mark.parametrize("normalize", [None, "mass"])
@pytest.mark.parametrize("scene", sorted(_SCENES))
def test_scene_rows_are_the_one_off_within_1e_12(tmp_path, scene, normalize):
    path = _file(tmp_path, scene, 5)
    assert sum(len(b.rows) for b in _blocks(path, scene)) >= 70  # of 80: on columns
    for as_json in (False, True):
        fast = _run(path, scene, as_json, True, normalize)
        generic = _run(path, scene, as_json, False, normalize)
        assert (fast[0], fast[2]) == (generic[0], generic[2])
        if as_json or scene != "block-disk-springs":
            assert (fast[0], fast[2]) == (0, "")
        else:  # a modal mass in kg under the first row's kg*m^2 column (or the other way)
            assert fast[0] == 2 and fast[2].count("\n") >= 1 and all(
                " cannot be shown in the column's unit kg" in line and
                line.endswith("; give such rows a file of their own")
                for line in fast[2].splitlines())
        if as_json:
            mine = [json.loads(line) for line in fast[1].splitlines()]
            theirs = [json.loads(line) for line in generic[1].splitlines()]
        else:
            mine, theirs = _cells(fast[1]), _cells(generic[1])
        assert len(mine) == len(theirs) == 80 + (0 if as_json else 1) - \
            fast[2].count("\n")
        for a, b in zip(mine, theirs):
            assert _close(a, b), (a, b)


def test_block_disk_springs_modal_masses_keep_their_units(tmp_path):
    """A mode whose largest component is the disk's rotation has its modal mass in kg*m^2,
    the block's translation in kg: rows of both kinds, each block probed on its own."""
    path = _file(tmp_path, "block-disk-springs", 6)
    units = {(b.dims["modal_mass_1"].si, b.dims["modal_mass_2"].si)
             for b in _blocks(path, "block-disk-springs")}
    assert len(units) >= 2 and units <= {(a, b) for a in ("kg", "kg*m^2")
                                         for b in ("kg", "kg*m^2")}
    lines = [json.loads(x) for x in _run(path, "block-disk-springs", True, True)[1].splitlines()]
    shown = {line["results"]["modal_mass_1"]["unit"] for line in lines}
    assert shown == {"kg", "kg*m^2"}


def test_pendulums_equilibrium_is_the_one_off_bit_for_bit(tmp_path):
    path = _file(tmp_path, "spring-coupled-pendulums", 7)
    fast = [json.loads(x) for x in _run(path, "spring-coupled-pendulums", True, True)[1]
            .splitlines()]
    generic = [json.loads(x) for x in _run(path, "spring-coupled-pendulums", True, False)[1]
               .splitlines()]
    assert [f["results"]["phi2_0"]["value"] for f in fast] == \
        [g["results"]["phi2_0"]["value"] for g in generic]
    assert [f["extra"]["equilibrium"] for f in fast] == [g["extra"]["equilibrium"]
                                                         for g in generic]


def test_coupled_blocks_against_the_closed_form(tmp_path):
    """omega^2 = (a + d)/2 -+ sqrt(((a - d)/2)^2 + k3^2/(m1 m2)), a = (k1 + k3)/m1,
    d = (k2 + k3)/m2 (the scene's record), with mpmath-free floats to 1e-12."""
    path = _file(tmp_path, "coupled-blocks", 8, count=40)
    rows = list(csv.reader(path.open()))[1:]
    out = _cells(_run(path, "coupled-blocks", False, True)[1])[1:]
    for row, line in zip(rows, out):
        m1, m2, k1, k2, k3 = (float(x) for x in row)
        m2, k2 = m2 / 1000.0, k2 * 1000.0
        a, d = (k1 + k3) / m1, (k2 + k3) / m2
        root = math.hypot((a - d) / 2.0, k3 / math.sqrt(m1 * m2))
        lo = 2.0 * (a * d - k3 * k3 / (m1 * m2)) / (a + d + 2.0 * root)  # (no cancellation)
        assert math.isclose(line[5][0], math.sqrt(lo), rel_tol=1e-12)
        assert math.isclose(line[6][0], math.sqrt((a + d) / 2.0 + root), rel_tol=1e-12)


def test_rows_the_columns_cannot_take_fall_back_with_the_one_offs_messages(tmp_path):
    bad = ["-1,1000,100,0.2,50",        # a negative mass: refused by the one-off
           "1,1000,0,0,50",             # one positive spring: the scene's relation
           "1,1000,100,0.1,100",        # a tie of the two components: the one-off's pick
           "1,1000,100,abc,50"]         # not a number
    path = _file(tmp_path, "coupled-blocks", 9, count=30, bad=bad)
    blocks = _blocks(path, "coupled-blocks")
    taken = {i for b in blocks for i in b.rows.tolist()}
    assert taken and not taken & {30, 31, 32, 33}
    for as_json in (False, True):
        fast = _run(path, "coupled-blocks", as_json, True)
        generic = _run(path, "coupled-blocks", as_json, False)
        assert fast[0] == generic[0] == 2
        assert fast[2] == generic[2]
        assert fast[2].splitlines() == [
            "Error: line 32: m1 must be positive; got -1 kilogram",
            "Error: line 33: coupled-blocks needs at least two of k1, k2, k3 positive; "
            "otherwise a block drifts freely (a mode of zero frequency)",
            fast[2].splitlines()[2]]
        assert fast[2].splitlines()[2].startswith("Error: line 35: ")
        # the tie row is the one-off's own, digit for digit
        tie = (fast[1].splitlines()[-1], generic[1].splitlines()[-1])
        assert tie[0] == tie[1]


def test_a_refusal_of_the_one_off_stays_row_by_row(tmp_path):
    """r left out of block-disk-springs is the one-off's refusal."""
    path = tmp_path / "no_r.csv"
    path.write_text("M [kg],m [kg],k [N/m]\n2,1,100\n")
    assert _blocks(path, "block-disk-springs") == []
    status, _out, err = _run(path, "block-disk-springs", False, True)
    assert status == 2 and err == ("Error: line 2: modes --scene block-disk-springs needs r= "
                                   "(the disk's radius): it cancels from the frequencies but "
                                   "not from the mode shapes\n")


DRIFT = "pendulum-on-sliding-block"
DRIFT_NOTE = ("omega_1 = 0: a rigid-body mode (an eigenvalue omega^2 within 1e-10 of the terms "
              "of K that sum to it is taken as zero)")


def _drift_file(tmp_path, seed: int, count: int = 80, x_first: bool | None = None):
    """Rows of the drift scene (m1 in kg, m2 in g, l in cm, g perhaps): the block's share of
    the mass from 0.01 to 0.99, the swing's largest component x or phi (``x_first``: all
    one, so that a CSV column keeps its unit), lengths and masses scaled alike."""
    rng = random.Random(seed)
    lines = ["m1 [kg],m2 [g],l [cm]"]
    while len(lines) <= count:
        share = rng.uniform(0.01, 0.99)
        total = 10.0 ** rng.uniform(-3, 3)
        m1, m2 = share * total, (1.0 - share) * total
        l_ = 10.0 ** rng.uniform(-2, 2)
        s = m2 * l_ / total
        if x_first is not None and (s > 1.0) != x_first:
            continue
        lines.append(f"{m1!r},{m2 * 1000.0!r},{l_ * 100.0!r}")
    path = tmp_path / "drift.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("normalize", [None, "mass"])
def test_drift_rows_are_the_one_off_within_1e_12(tmp_path, normalize):
    """pendulum-on-sliding-block on columns (the closed form of physics/modes_drift.py)
    against the one-off's LAPACK solve a row at a time: the same note on every row, the
    same units, the numbers within 1e-12 (JSON lines: every row; CSV: one kind of swing a
    file, as a column keeps one unit)."""
    path = _drift_file(tmp_path, 11)
    assert sum(len(b.rows) for b in _blocks(path, DRIFT)) == 80
    fast, generic = _run(path, DRIFT, True, True, normalize), \
        _run(path, DRIFT, True, False, normalize)
    assert (fast[0], fast[2]) == (generic[0], generic[2]) == (0, "")
    mine = [json.loads(line) for line in fast[1].splitlines()]
    theirs = [json.loads(line) for line in generic[1].splitlines()]
    assert len(mine) == len(theirs) == 80
    assert {line["results"]["modal_mass_2"]["unit"] for line in mine} == {"kg", "kg*m^2"}
    for a, b in zip(mine, theirs):
        assert a["warnings"] == b["warnings"] == [DRIFT_NOTE]
        assert _close(a, b), (a, b)
    for x_first in (False, True):
        path = _drift_file(tmp_path, 12 + x_first, count=40, x_first=x_first)
        fast, generic = _run(path, DRIFT, False, True, normalize), \
            _run(path, DRIFT, False, False, normalize)
        assert (fast[0], fast[2]) == (generic[0], generic[2])
        assert fast[0] == 0 and fast[2].count(DRIFT_NOTE) == 40
        assert all(_close(a, b) for a, b in zip(_cells(fast[1]), _cells(generic[1])))


def test_drift_is_the_textbook_example_e4_19(tmp_path):
    """E4.19: m1 = 3 kg, m2 = 1 kg, l = 0.5 m: omega = sqrt((m1 + m2) g / (m1 l)) =
    5.11381136400890980955 rad/s (the scene's reference, to 30 digits); the swing
    [-m2 l / (m1 + m2), 1] = [-0.125, 1] with modal mass m1 m2 l^2 / (m1 + m2) = 0.1875 kg m^2
    and stiffness m2 g l; the drift [1, 0] with the whole mass 4 kg and no stiffness. The
    same in grams and centimetres."""
    for header, row in (("m1 [kg],m2 [kg],l [m]", "3,1,0.5"),
                        ("m1 [g],m2 [g],l [cm]", "3000,1000,50")):
        path = tmp_path / "e4_19.csv"
        path.write_text(f"{header}\n{row}\n")
        assert sum(len(b.rows) for b in _blocks(path, DRIFT)) == 1
        status, out, err = _run(path, DRIFT, True, True)
        assert status == 0 and err == ""
        line = json.loads(out)
        r = {name: entry["value"] for name, entry in line["results"].items()}
        assert math.isclose(r["omega_2"], 5.11381136400890980955, rel_tol=2e-16)
        assert (r["omega_1"], r["f_1"], r["mode_1"], r["modal_mass_1"],
                r["modal_stiffness_1"]) == (0.0, 0.0, [1.0, 0.0], 4.0, 0.0)
        assert r["mode_2"] == [-0.125, 1.0] and r["modal_mass_2"] == 0.1875
        assert math.isclose(r["modal_stiffness_2"], 1 * 9.80665 * 0.5, rel_tol=1e-15)
        assert line["results"]["modal_mass_2"]["unit"] == "kg*m^2"
        assert line["warnings"] == [DRIFT_NOTE]
        assert line["extra"]["equilibrium"] == "phi = 0 (bob below the pin), any x"


def test_ill_conditioned_drift_rows_are_left_to_the_one_off(tmp_path):
    """A block under 1 % of the mass (M's condition number over 400) and a swing whose small
    component is near the floor below which the one-off shows 0 take the row-by-row path;
    the output is the one-off's either way, and bad values its one-line refusals."""
    from dyncalc.physics.modes import _COMPONENT_FLOOR

    tiny = _COMPONENT_FLOOR * 1.3  # s = m2 l / (m1 + m2): within a factor 2 of the floor
    path = tmp_path / "edge.csv"
    path.write_text("m1 [kg],m2 [kg],l [m]\n3,1,0.5\n0.001,1,0.5\n"
                    f"1,1,{2 * tiny!r}\n1,1,{2 * tiny * 1e-3!r}\n-3,1,0.5\n3,1,0\n")
    blocks = _blocks(path, DRIFT)
    assert sorted(int(i) for b in blocks for i in b.rows) == [0, 3]
    fast, generic = _run(path, DRIFT, True, True), _run(path, DRIFT, True, False)
    assert (fast[0], fast[2]) == (generic[0], generic[2])
    assert fast[2] == ("Error: line 6: m1 must be positive; got -3 kilogram\n"
                       "Error: line 7: l must be positive; got 0 meter\n")
    mine = [json.loads(line) for line in fast[1].splitlines()]
    theirs = [json.loads(line) for line in generic[1].splitlines()]
    assert len(mine) == 4 and all(_close(a, b) for a, b in zip(mine, theirs))
    assert mine[3]["results"]["mode_2"]["value"] == [0.0, 1.0]  # below the floor: 0


def test_with_a_scene_every_column_is_a_scene_parameter(tmp_path):
    """block-disk-springs' M is the block's mass (it was read as --M and every row refused);
    a matrix column K, or a result name, is no column of a scene's rows."""
    path = tmp_path / "block.csv"
    path.write_text("M [kg],m [kg],r [m],k [N/m]\n2,1,0.1,100\n")
    status, out, err = _run(path, "block-disk-springs", False, False)
    assert (status, err) == (0, "")
    omega_1 = float(out.splitlines()[1].split(",")[4])
    # E4.14: omega_1^2 = k ((2M + 5m) - sqrt(4M^2 - 4Mm + 17m^2)) / (2m (3M + m))
    assert math.isclose(omega_1, math.sqrt(100 * (9 - math.sqrt(25)) / 14), rel_tol=1e-14)
    for column in ("K", "omega_1"):
        path.write_text(f"m1 [kg],m2 [kg],k1 [N/m],k2 [N/m],k3 [N/m],{column}\n1,2,3,4,5,6\n")
        with pytest.raises(InputError) as caught:
            _run(path, "coupled-blocks", False, True)
        assert str(caught.value) == (f"line 1: unknown column '{column}'; modes --scene "
                                     "coupled-blocks reads m1, m2, k1, k2, k3")
