"""The half-cylinder shell at an amplitude on columns (dyncalc/physics/shell_columns.py): the
quadrature's mean is ``math.fsum``'s to the bit, and batch rows through the kernel are the
one-off's byte for byte (CSV and JSON lines, whose ``extra.error_estimate`` differs row by
row); linear, warning and refused rows stay the one-off's."""
from __future__ import annotations

import io
import math
import random

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from dyncalc import batch
from dyncalc.batch import fast as fast_path
from dyncalc.commands.natural_frequency import STANDARD
from dyncalc.errors import InputError
from dyncalc.physics.nonlinear import PI_MINUS_2
from dyncalc.physics.shell_columns import exact_mean

C = 4.0 / PI_MINUS_2
HALVES = {"deg": 180.0, "rad": math.pi, "": math.pi, "turn": 0.5, "grad": 200.0}


@settings(max_examples=200, deadline=None)
@given(st.floats(0.0, 0.5), st.sampled_from([8, 16, 32, 64, 128, 1024]))
def test_the_integer_sum_is_fsum(k2, n):
    """Every node in [1, 4): the uint64 sum rounded once is math.fsum's float."""
    mean, ok = exact_mean(np.array([k2]), n, C)
    x = k2 * np.sin(np.arange(n) * (math.pi / n)) ** 2
    nodes = np.sqrt((1.0 + C * x) / (1.0 - x)).tolist()
    assert ok.tolist() == [True]
    assert mean[0] == math.fsum(nodes) / n


def test_a_sum_that_plain_addition_rounds_otherwise():
    """Where a left-to-right float sum differs from fsum, the kernel still gives fsum's."""
    rng = random.Random(7)
    for _ in range(200):
        k2 = rng.uniform(0.2, 0.5)
        x = k2 * np.sin(np.arange(64) * (math.pi / 64)) ** 2
        nodes = np.sqrt((1.0 + C * x) / (1.0 - x)).tolist()
        if sum(nodes) != math.fsum(nodes):
            assert exact_mean(np.array([k2]), 64, C)[0][0] == math.fsum(nodes) / 64
            return
    pytest.fail("no sum found where rounding order matters")


def _rows(rng: random.Random, n: int) -> list[list[str]]:
    rows = []
    for _ in range(n):
        unit = rng.choice(list(HALVES))
        x = rng.choice([rng.uniform(0.0, 0.999), 1.0 - 10.0 ** -rng.randint(2, 15), 1.0,
                        1.2, 0.0, 10.0 ** -rng.randint(3, 12)])
        amplitude = f"{x * HALVES[unit] / 2!r} {unit}".strip()
        rows.append([repr(rng.uniform(0.05, 5.0) * 10.0 ** rng.randint(-3, 3)), amplitude])
    return rows


def _run(path, fast: bool, as_json: bool, **options):
    out, err = io.StringIO(), io.StringIO()
    spec = batch.NaturalFrequencyRows(STANDARD, scene="half-cylinder-shell", **options)
    code = batch.run_batch(spec, str(path), as_json=as_json, on_error="skip", out=out,
                           err=err, fast=fast)
    return code, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("options", [{}, {"rtol": 1e-6}, {"rtol": 1e-14},
                                     {"method": "quadrature"}, {"method": "linear"}],
                         ids=["auto", "rtol-6", "rtol-14", "quadrature", "linear"])
def test_batch_rows_equal_the_one_off_rows(tmp_path, options):
    rng = random.Random(str(options))
    rows = _rows(rng, 300)
    path = tmp_path / "rows.csv"
    path.write_text("r,amplitude\n" + "\n".join(",".join(r) for r in rows) + "\n")
    for as_json in (False, True):
        fast, slow = _run(path, True, as_json, **options), _run(path, False, as_json, **options)
        assert fast == slow


def test_the_quadrature_rows_take_the_vectorised_path():
    """Every row the one-off computes by quadrature without a warning is the kernel's; the
    linear rows (tiny amplitudes), the refused ones (90 degrees and beyond) are not."""
    rows = _rows(random.Random(3), 300)
    spec = batch.NaturalFrequencyRows(STANDARD, scene="half-cylinder-shell")
    columns = [batch.Column(i, p, p, "", p) for i, p in enumerate(["r", "amplitude"])]
    blocks = fast_path._natural_frequency_fast(spec, columns, [list(c) for c in zip(*rows)],
                                               True, {})
    covered = {i for block in blocks for i in block.rows.tolist()}
    clean, methods = set(), set()
    for i, row in enumerate(rows):
        try:
            result = spec.compute(dict(zip(["r", "amplitude"], row)), {})
        except InputError:
            methods.add("refused")
            continue
        methods.add(result.method)
        if not result.warnings and result.method == "quadrature":
            clean.add(i)
    assert methods >= {"refused", "linear", "quadrature"}
    assert len(clean) >= 80
    assert covered == clean
    # the parts of each row's extra: '{"error_estimate": ', one text a row, '}'
    estimates = {e for block in blocks for e in block.extra[1]}
    assert len(estimates) > 10  # an estimate per row, not one per block
