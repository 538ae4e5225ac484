"""``inertia --batch`` with placed and turned bodies (``at=``, ``along=`` a world axis, half-
cylinder shells) and world axes: the vectorised path (dyncalc/batch/fast_inertia_placed.py,
physics/inertia_placed_columns.py) byte for byte the one-off on random rows with extremes
(1e-300..1e300, zero offsets, 90 and 180 degree turns), rows the kernel cannot take row by row
with the one-off's messages, and values against the parallel-axis theorem."""
from __future__ import annotations

import io
import json
import math
import random

import numpy as np
import pytest

from dyncalc.batch import run_batch
from dyncalc.batch.fast_inertia import inertia_fast
from dyncalc.batch.header import read_header
from dyncalc.batch.inertia_rows import InertiaRows

_DIMS = {"rod": ["l"], "disk": ["r"], "ring": ["r"], "solid-sphere": ["r"],
         "hollow-sphere": ["r"], "point": [], "solid-cylinder": ["r", "h"],
         "hollow-cylinder": ["ri", "ro", "h"], "plate": ["a", "b"],
         "half-cylinder-shell": ["r", "h"]}
_EXTREMES = [1e-300, 1e-150, 1e150, 1e300, 2.5e-320]


def _number(rng, signed=False) -> str:
    if rng.random() < 0.15:
        x = rng.choice(_EXTREMES) * rng.uniform(0.5, 2.0)
    elif signed and rng.random() < 0.3:
        x = 0.0
    else:
        x = rng.uniform(0.01, 3.0)
    if signed and rng.random() < 0.4:
        x = -x
    return rng.choice([repr(x), f"{x:.6g}", f"{x:.3E}"])


def _body(rng, hole=False) -> str:
    kind = rng.choice(list(_DIMS))
    parts = [f"m={_number(rng)} {rng.choice(['kg', 'g'])}"]
    parts += [f"{d}={_number(rng)}{rng.choice([' m', 'cm', ' mm'])}" for d in _DIMS[kind]]
    if rng.random() < 0.8:
        xyz = ", ".join(_number(rng, signed=True) for _ in range(3))
        parts.append(f"at=({xyz}) {rng.choice(['m', 'cm'])}")
    if rng.random() < 0.6:
        parts.append("along=" + rng.choice(["x", "y", "z", "-x", "-y", "-z", " +y"]))
    rng.shuffle(parts)
    return ("-" if hole else "") + f"{kind}({', '.join(parts)})"


def _run(path, as_json: bool, fast: bool):
    out, err = io.StringIO(), io.StringIO()
    status = run_batch(InertiaRows(), str(path), as_json=as_json, on_error="skip",
                       out=out, err=err, fast=fast)
    return status, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("as_json", [False, True])
@pytest.mark.parametrize("seed", [1, 2])
def test_placed_rows_are_the_one_off_byte_for_byte(tmp_path, as_json, seed):
    rng = random.Random(seed)
    rows = []
    for _ in range(250):
        cells = [f'"{_body(rng, i > 0 and rng.random() < 0.3)}"' for i in range(2)]
        axis = rng.choice(["", "z", "-x", "y", "z through (0.1, 0, 0) m"])
        rows.append(",".join(cells) + "," + (f'"{axis}"' if " " in axis else axis))
    rows += ['"disk(m=1kg, r=1m, at=(0, 0, 0) m)","-disk(m=1kg, r=1m, at=(0,0,0) m)",',
             '"rod(m=1e300kg, l=1m, at=(1e300, 0, 0) m)",,z',
             '"rod(m=2kg, l=1m, along=(1, 1, 0), at=(1, 0, 0) m)",,z']
    path = tmp_path / "placed.csv"
    path.write_text("b1,b2,axis\n" + "\n".join(rows) + "\n")
    fast, generic = _run(path, as_json, True), _run(path, as_json, False)
    assert fast == generic
    assert fast[2].count("Error: line") >= 2


def _covered(table, names, as_json=False):
    spec = InertiaRows()
    blocks = inertia_fast(spec, read_header(1, names, spec), table, as_json, {})
    return blocks, sorted(i for b in blocks for i in b.rows.tolist())


def test_most_placed_rows_take_the_vectorised_path():
    rng = random.Random(3)
    n = 200
    table = [[f"disk(m={rng.uniform(1, 5)!r} kg, r=0.2 m, at=({rng.uniform(-1, 1)!r}, "
              f"{rng.uniform(-1, 1)!r}, 0) m)" for _ in range(n)],
             [f"rod(m=0.1 kg, l={rng.uniform(0.1, 2)!r} m, along=x, at=(0.5, "
              f"{rng.uniform(-1, 1)!r}, 0) m)" for _ in range(n)], ["z"] * n]
    _blocks, rows = _covered(table, ["b1", "b2", "axis"])
    assert len(rows) >= 0.95 * n


def test_turned_rods_about_their_ends_are_m_l2_over_3():
    """A rod of 3 kg, 2 m along x (and -x: a 180 degree turn) centred at (1, 0, 0) m: about z
    through the origin (its end) J = m l^2 / 3 = 4 kg*m^2 (Gross et al. E3.41); along y
    (90 degrees), at (0, 1, 0) m: the same about z, and J_C's largest moment m l^2/12 = 1."""
    table = [["rod(m=3 kg, l=2 m, along=x, at=(1, 0, 0) m)",
              "rod(m=3 kg, l=2 m, along=-x, at=(1, 0, 0) m)",
              "rod(m=3 kg, l=2 m, along=y, at=(0, 1, 0) m)"], ["z"] * 3]
    blocks, rows = _covered(table, ["b1", "axis"])
    assert rows == [0, 1, 2]
    for block in blocks:
        assert block.values["J_axis"].tolist() == pytest.approx([4.0] * len(block.rows),
                                                                rel=1e-15)
        assert block.values["J_3"] == pytest.approx(1.0, rel=1e-15)
        assert block.values["radius_of_gyration"] == pytest.approx(math.sqrt(4.0 / 3.0),
                                                                   rel=1e-15)


def test_a_disk_with_an_off_centre_hole_is_the_parallel_axis_theorem(tmp_path):
    """disk 4 kg, r 0.2 m at the origin; hole 0.25 kg, r 0.05 m at (0.1, 0, 0) m:
    m = 3.75, r_c = -0.025/3.75 x, J_O,zz = 0.08 - (0.25 (0.0025/2 + 0.01)) (Steiner)."""
    path = tmp_path / "a.csv"
    path.write_text('b1,b2,axis\n"disk(m=4kg, r=0.2m, at=(0, 0, 0) m)",'
                    '"-disk(m=0.25kg, r=0.05m, at=(0.1, 0, 0) m)",z\n')
    status, out, err = _run(path, True, True)
    assert (status, err) == (0, "")
    results = json.loads(out)["results"]
    assert results["m"]["value"] == 3.75
    assert results["r_c"]["value"][0] == pytest.approx(-0.025 / 3.75, rel=1e-15)
    J_O = 4 * 0.04 / 2 - 0.25 * (0.0025 / 2 + 0.01)
    assert results["J_O"]["value"][2][2] == pytest.approx(J_O, rel=1e-14)
    assert results["J_axis"]["value"] == pytest.approx(J_O, rel=1e-14)
    J_C = J_O - 3.75 * (0.025 / 3.75) ** 2
    assert results["J_3"]["value"] == pytest.approx(J_C, rel=1e-14)


def test_rows_the_kernel_cannot_take_keep_the_one_off_messages(tmp_path):
    """A hole heavier than the body (refused), a turn by a vector (row by row), an
    overflowing offset: the same lines, the same one-line errors as the generic path."""
    path = tmp_path / "bad.csv"
    path.write_text(
        'b1,b2,axis\n'
        '"disk(m=1kg, r=1m, at=(1, 0, 0) m)","-disk(m=2kg, r=1m, at=(1, 0, 0) m)",\n'
        '"rod(m=2kg, l=1m, along=(1, 1, 0), at=(1, 0, 0) m)",,z\n'
        '"disk(m=1e300kg, r=1m, at=(1e300, 0, 0) m)",,\n'
        '"disk(m=1kg, r=1m, at=(1, 0, 0) m)",,z\n')
    fast, generic = _run(path, False, True), _run(path, False, False)
    assert fast == generic
    assert fast[2].splitlines() == [
        "Error: line 2: the negative bodies weigh as much as the others or more: the total "
        "mass is -1 kg; a hole cannot be larger than what it cuts",
        "Error: line 4: a mass, centre or moment of inertia overflows float64 (beyond 1.8e308 "
        "in kg, m, kg*m^2): give the bodies sizes and positions that keep them in range"]
    _blocks, rows = _covered([[line.split('",')[0].strip('"') for line in
                               path.read_text().splitlines()[2:]], ["z", "", "z"]],
                             ["b1", "axis"])
    assert rows == [2]


@pytest.mark.filterwarnings("ignore::RuntimeWarning")
@pytest.mark.parametrize("slice_rows", [4096, 64])
def test_the_kernel_is_the_one_off_on_stacked_random_composites(monkeypatch, slice_rows):
    """The kernel alone against inertia_tensor.placed/composite/principal row by row, all
    400 rows at once and 64 at a time (its ``SLICE``: the last slice shorter)."""
    from dyncalc.physics import inertia_placed_columns
    from dyncalc.physics.inertia_placed_columns import placed_composite
    from dyncalc.physics.inertia_tensor import body_frame, composite, placed, principal

    monkeypatch.setattr(inertia_placed_columns, "SLICE", slice_rows)

    rng = np.random.default_rng(7)
    n = 400
    frames = [body_frame(v) for v in ([1.0, 0, 0], [0, -1.0, 0], [0, 0, -1.0])]
    bodies = [("solid-cylinder", 1.0, rng.uniform(0.1, 9, n),
               {"r": rng.uniform(0.1, 1, n), "h": rng.uniform(0.1, 1, n)},
               rng.normal(size=(n, 3)) * 10.0 ** rng.integers(-200, 200, (n, 1)), frames[0]),
              ("half-cylinder-shell", -1.0, rng.uniform(0.001, 0.01, n),
               {"r": rng.uniform(0.01, 0.1, n), "h": rng.uniform(0.01, 0.1, n)},
               rng.normal(size=(n, 3)) * 0.1, frames[1]),
              ("point", 1.0, rng.uniform(0.1, 1, n), {}, np.zeros((n, 3)), frames[2])]
    out = placed_composite(bodies, axis=(np.array([0.0, 1.0, 0.0]), np.zeros(3)))
    checked = 0
    for i in range(n):
        row = [placed(kind, float(m[i]), {k: float(v[i]) for k, v in dims.items()},
                      at=at[i], along=frame[:, 2], sign=int(sign))
               for kind, sign, m, dims, at, frame in bodies]
        try:
            with np.errstate(all="ignore"):
                total = composite(row)
        except Exception:  # noqa: BLE001 (a refusal: the kernel must not claim the row)
            assert not out.exact[i]
            continue
        if not out.exact[i]:
            continue
        checked += 1
        moments, axes = principal(total.J_C)
        assert out.values["J_C"][i].tolist() == (total.J_C + 0.0).tolist()
        assert out.values["J_O"][i].tolist() == (total.J_O + 0.0).tolist()
        assert out.values["r_c"][i].tolist() == (total.r_c + 0.0).tolist()
        assert [out.values[f"J_{k}"][i] for k in (1, 2, 3)] == np.maximum(moments, 0).tolist()
        assert [out.values[f"axis_{k}"][i].tolist() for k in (1, 2, 3)] == axes.tolist()
    assert checked > 0.3 * n  # positions beyond 1e154 overflow: refused by both


def _literal(rng, signed=False) -> str:
    """A number as a user may type it, extremes among them (and zeros where signed)."""
    if rng.random() < 0.1:
        x = rng.choice(_EXTREMES) * rng.uniform(0.5, 2.0)
    elif signed and rng.random() < 0.2:
        x = 0.0
    else:
        x = rng.uniform(0.01, 3.0)
    if signed and rng.random() < 0.4:
        x = -x
    return rng.choice([repr(x), f"{x:.6g}", f"{x:.3E}"])


@pytest.mark.parametrize("as_json", [False, True])
@pytest.mark.parametrize("axes", [["z"], ["x", " -y", "z", ""],
                                  ["(1, 1, 0)", "z through (0.1, 0, 0) m", "(0.3,-2,1e-3)"]])
def test_one_template_placed_columns_are_the_one_off_byte_for_byte(tmp_path, as_json, axes):
    """Two body columns of one template each (a turned disk placed in cm, a rod along x, a
    half-cylinder shell): most rows in blocks whose only first row is probed, so each row's
    bits are the kernel's; extremes overflow and are refused row by row as the one-off does."""
    rng = random.Random(len(axes) + 10 * as_json)
    rows, cells = [], []
    for _ in range(300):
        at = [_literal(rng, signed=True) for _ in range(6)]
        b1 = (f'disk(m={_literal(rng)} kg, r={_literal(rng)} m, at=({at[0]}, {at[1]}, '
              f'{at[2]}) cm, along=-y)')
        b2 = (f'rod(m={_literal(rng)} kg, l={_literal(rng)} m, along=x, at=({at[3]},{at[4]},'
              f'{at[5]}) m)')
        b3 = f'half-cylinder-shell(m={_literal(rng)} g, r={_literal(rng)} mm, h=2 m, along=z)'
        cells.append([b1, b2, b3, rng.choice(axes)])
        axis = cells[-1][3]
        rows.append(f'"{b1}","{b2}","{b3}",' + (f'"{axis}"' if "," in axis else axis))
    path = tmp_path / "template.csv"
    path.write_text("b1,b2,b3,axis\n" + "\n".join(rows) + "\n")
    fast, generic = _run(path, as_json, True), _run(path, as_json, False)
    assert fast == generic
    table = [list(column) for column in zip(*cells)]
    blocks, covered = _covered(table, ["b1", "b2", "b3", "axis"], as_json)
    assert len(covered) >= 0.6 * len(rows)
    assert len(blocks) <= 4


def test_other_axes_are_the_parallel_axis_theorem():
    """A rod of 3 kg, 2 m along x centred at the origin about z through its end (1, 0, 0) m:
    m l^2 / 3 = 4 kg*m^2; a disk of 4 kg, r = 0.2 m at (0, 0, 0.5) m about the in-plane
    direction (1, 1, 0) through the origin: m r^2 / 4 + m 0.5^2 = 0.04 + 1 (Table 3.1 and
    Steiner); both on columns."""
    table = [["rod(m=3 kg, l=2 m, along=x, at=(0, 0, 0) m)"] * 2, ["z through (1, 0, 0) m"] * 2]
    blocks, rows = _covered(table, ["b1", "axis"])
    assert rows == [0, 1]
    assert blocks[0].values["J_axis"].tolist() == pytest.approx([4.0, 4.0], rel=1e-15)
    table = [["disk(m=4 kg, r=0.2 m, at=(0, 0, 0.5) m)"], ["(1, 1, 0)"]]
    blocks, rows = _covered(table, ["b1", "axis"])
    assert rows == [0]
    assert blocks[0].values["J_axis"][0] == pytest.approx(0.04 + 1.0, rel=1e-15)
    assert blocks[0].values["radius_of_gyration"][0] == pytest.approx(math.sqrt(1.04 / 4.0),
                                                                      rel=1e-15)
