"""``modes --batch`` rows the stacked kernel leaves (barely damped, overdamped, uncoupled
coordinates with damping that is not proportional): the one-off's physics a row at a time
(dyncalc/batch/fast_modes_rows.py), so the bytes are the one-off's, warnings included; a
row the one-off refuses keeps its message."""
from __future__ import annotations

import csv
import io
import json
import math
import random

import numpy as np

from dyncalc.batch import run_batch
from dyncalc.batch.header import read_header
from dyncalc.batch.rows import ModesRows


def _text(X) -> str:
    return "[" + ", ".join("[" + ", ".join(repr(float(x)) for x in row) + "]"
                           for row in X) + "]"


def _file(tmp_path, seed: int, count: int = 60, bad=()):
    """Two-mass chains with a dashpot on mass 1 only, barely there (zeta about 1e-6 to 1e-4:
    not proportional), and three masses where the third is uncoupled (its own spring and
    dashpot) from a pair damped otherwise than proportionally."""
    rng = random.Random(seed)
    lines = ["M,K,C"]
    for i in range(count):
        m1, m2, k1, k2 = rng.uniform(0.5, 20), rng.uniform(0.5, 20), rng.uniform(1e2, 1e4), \
            rng.uniform(1e2, 1e4)
        if i % 2:
            M = np.diag([m1, m2])
            K = np.array([[k1 + k2, -k2], [-k2, k2]])
            C = np.diag([rng.uniform(1e-6, 1e-4) * 2.0 * math.sqrt(k1 * m1), 0.0])
        else:
            m3, k3 = rng.uniform(0.5, 20), rng.uniform(1e2, 1e4)
            M = np.diag([m1, m2, m3])
            K = np.array([[k1 + k2, -k2, 0.0], [-k2, k2, 0.0], [0.0, 0.0, k3]])
            C = np.diag([rng.uniform(0.01, 0.05) * 2.0 * math.sqrt(k1 * m1), 0.0,
                         rng.uniform(0.01, 0.05) * 2.0 * math.sqrt(k3 * m3)])
        lines.append(f'"{_text(M)}","{_text(K)}","{_text(C)}"')
    lines += list(bad)
    path = tmp_path / "rows.csv"
    path.write_text("\n".join(lines) + "\n")
    return path


def _run(path, as_json: bool, fast: bool):
    out, err = io.StringIO(), io.StringIO()
    status = run_batch(ModesRows(), str(path), as_json=as_json, on_error="skip", out=out,
                       err=err, fast=fast)
    return status, out.getvalue(), err.getvalue()


def _covered(path) -> set[int]:
    rows = list(csv.reader(path.open()))
    spec = ModesRows()
    blocks = spec.fast(spec, read_header(1, rows[0], spec),
                       [[r[i] for r in rows[1:]] for i in range(3)], True, {})
    return {i for b in blocks for i in b.rows.tolist()}


def test_rows_the_stack_leaves_are_the_one_offs_bytes(tmp_path):
    path = _file(tmp_path, 1)
    assert _covered(path) == set(range(60))  # none run the one-off's reading and Result
    for as_json in (False, True):
        fast, generic = _run(path, as_json, True), _run(path, as_json, False)
        assert fast == generic
        assert fast[0] == 0 and fast[2].count("warning: line") == (0 if as_json else 60)
        assert fast[2].count("the damping is not proportional") == (0 if as_json else 60)


def test_barely_damped_rows_against_the_first_order_perturbation(tmp_path):
    """Light damping: zeta_i = phi_i^T C phi_i / (2 omega_i phi_i^T M phi_i) to first order in
    C (the error is of order zeta^2), an independent check of the one-off's digits."""
    path = _file(tmp_path, 2, count=20)
    out = list(csv.reader(io.StringIO(_run(path, False, True)[1])))
    head = out[0]
    for row, cells in zip(out[2::2], list(csv.reader(path.open()))[2::2]):  # two masses
        M, K, C = (np.array(json.loads(c)) for c in cells)
        for i in (1, 2):
            phi = np.array([float(x) for x in row[head.index(f"mode_{i}")].split(",")])
            omega = float(row[head.index(f"omega_{i} [rad/s]")])
            zeta = phi @ C @ phi / (2.0 * omega * (phi @ M @ phi))
            assert math.isclose(float(row[head.index(f"zeta_{i}")]), zeta, rel_tol=1e-6)


def test_overdamped_rows_keep_their_notes_and_refused_rows_their_messages(tmp_path):
    bad = ['"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[5,0],[0,5]]"',      # overdamped: notes
           '"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[50,0],[0,0]]"',     # real eigenvalues
           '"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[1,0.5],[0,1]]"',    # C not symmetric
           '"[[1,0],[0,1]]","[[2,-1],[-1,2]]","[[-1,0],[0,0]]"']     # C not semi-definite
    path = _file(tmp_path, 3, count=4, bad=bad)
    taken = _covered(path)
    assert {0, 1, 2, 3, 4, 5} <= taken and not {6, 7} & taken
    for as_json in (False, True):
        fast, generic = _run(path, as_json, True), _run(path, as_json, False)
        assert fast == generic and fast[0] == 2
        errors = [line for line in fast[2].splitlines() if line.startswith("Error")]
        assert errors[0] == ("Error: line 8: --C is not symmetric: row 1, column 2 is 0.5 but "
                             "row 2, column 1 is 0 (in SI; mirrored entries may differ by at "
                             "most 1e-09 of the largest entry)")
        assert errors[1].startswith("Error: line 9: --C ") and len(errors) == 2
    assert "mode 1 is overdamped (zeta_1 = 2.5 > 1)" in fast[1]
