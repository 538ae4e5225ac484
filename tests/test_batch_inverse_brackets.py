"""Bracketed inverse rows on columns (dyncalc/scenes/inverse_brackets.py): an angle solved
from a result monotone in it. Batch rows through the bracket kernel are the one-off's byte for
byte (CSV and JSON lines, errors included); the rows it leaves (a root below the grid's
second point or at its far end, no root, another method) stay the one-off's; the roots agree
with mpmath's elliptic integral."""
from __future__ import annotations

import io
import math
import random

import mpmath
import pytest

from dyncalc import batch
from dyncalc.batch.fast import _natural_frequency_fast
from dyncalc.batch.header import read_header
from dyncalc.commands.natural_frequency import STANDARD
from dyncalc.errors import InputError

G = 9.80665


def _pendulum_rows(rng: random.Random, n: int) -> list[list[str]]:
    rows = []
    for _ in range(n):
        l = rng.uniform(0.05, 5.0) * 10.0 ** rng.randint(-2, 2)
        T0 = 2.0 * math.pi * math.sqrt(l / G)
        ratio = rng.choice([rng.uniform(1.001, 2.5), rng.uniform(1.001, 1.2),
                            rng.uniform(0.5, 1.0), 1.0 + 10.0 ** -rng.randint(5, 14),
                            rng.uniform(3.0, 12.0), 1e300])
        rows.append([repr(T0 * ratio), repr(l), rng.choice(["?", "?", " ? "])])
    return rows


def _run(path, scene: str, fast: bool, as_json: bool, **options):
    out, err = io.StringIO(), io.StringIO()
    spec = batch.NaturalFrequencyRows(STANDARD, scene=scene, **options)
    code = batch.run_batch(spec, str(path), as_json=as_json, on_error="skip", out=out,
                           err=err, fast=fast)
    return code, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("options", [{}, {"rtol": 1e-6}, {"method": "elliptic"}],
                         ids=["auto", "rtol-6", "elliptic"])
def test_pendulum_amplitudes_are_the_one_off_byte_for_byte(tmp_path, options):
    rows = _pendulum_rows(random.Random(str(options)), 50)
    path = tmp_path / "rows.csv"
    path.write_text("T [s],l [m],amplitude\n" + "\n".join(",".join(r) for r in rows) + "\n")
    for as_json in (False, True):
        fast = _run(path, "pendulum", True, as_json, **options)
        assert fast == _run(path, "pendulum", False, as_json, **options)
    assert fast[0] == 2 and "no value of amplitude gives T" in fast[2]


def test_physical_pendulum_amplitudes_are_the_one_off_byte_for_byte(tmp_path):
    rng = random.Random(9)
    lines = ["m [kg],a [m],J_A [kg*m^2],f [Hz],amplitude"]
    for _ in range(30):
        m, a = rng.uniform(0.5, 5.0), rng.uniform(0.05, 1.0)
        J_A = m * a * a * rng.uniform(1.0, 3.0)
        f0 = math.sqrt(m * G * a / J_A) / (2.0 * math.pi)
        lines.append(f"{m!r},{a!r},{J_A!r},{f0 * rng.uniform(0.3, 1.05)!r},?")
    path = tmp_path / "rows.csv"
    path.write_text("\n".join(lines) + "\n")
    for as_json in (False, True):
        assert _run(path, "physical-pendulum", True, as_json) == \
            _run(path, "physical-pendulum", False, as_json)


def _covered(rows, header, scene="pendulum"):
    spec = batch.NaturalFrequencyRows(STANDARD, scene=scene)
    blocks = _natural_frequency_fast(spec, read_header(1, header, spec),
                                     [list(c) for c in zip(*rows)], True, {})
    return spec, blocks, {i for b in blocks for i in b.rows.tolist()}


def test_roots_inside_the_grid_take_the_vectorised_path():
    """Every row whose root lies between the grid's second point (2 degrees) and its far tail
    is the kernel's; the others are left to the one-off."""
    rows = _pendulum_rows(random.Random(4), 120)
    spec, blocks, covered = _covered(rows, ["T [s]", "l [m]", "amplitude"])
    inside, outside = set(), set()  # (the far tail, 179.999 degrees on: either)
    for i, row in enumerate(rows):
        try:
            result = spec.compute({"T": row[0] + " s", "l": row[1] + " m", "amplitude": "?"},
                                  {})
        except InputError:
            outside.add(i)
            continue
        degrees = math.degrees(result.results["amplitude"].si)
        if result.warnings or degrees <= 2.0:
            outside.add(i)
        elif degrees < 179.999:
            inside.add(i)
    assert len(inside) > 30 and len(outside) > 20
    assert inside <= covered and not covered & outside
    assert all(b.extra.startswith('{"error_estimate": 1e-15, "inverse": {"unknown": '
                                  '"amplitude", "method": "bracketed-root"') for b in blocks)


@pytest.mark.parametrize("degrees", [3.3, 31.0, 89.3, 151.0, 179.5])
def test_the_root_is_the_amplitude_of_the_elliptic_period(degrees):
    """T = 4 sqrt(l/g) K(sin^2(theta0/2)) (mpmath at 30 digits) gives the period; the batch
    solves it back to theta0 within a few rounding errors (Brent to four epsilons)."""
    with mpmath.workdps(30):
        T = 4 * mpmath.sqrt(mpmath.mpf(2) / G) * mpmath.ellipk(
            mpmath.sin(mpmath.radians(degrees) / 2) ** 2)
    _spec, blocks, covered = _covered([[repr(float(T)), "2.0", "?"]],
                                      ["T [s]", "l [m]", "amplitude"])
    assert covered == {0}
    root = blocks[0].values["amplitude"][0]
    assert root == pytest.approx(math.radians(degrees), rel=2e-14)
