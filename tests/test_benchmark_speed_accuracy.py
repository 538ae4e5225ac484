"""benchmarks/speed_accuracy.py at tiny sizes: its mpmath references against independent
derivations, its one-off command lines against the in-process calls, and the rows it adds
for frame-brace-damper and forced-response. Smoke tests: no timing is asserted."""
from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import mpmath
import pytest

BENCHMARKS = Path(__file__).resolve().parent.parent / "benchmarks"
sys.path.insert(0, str(BENCHMARKS))

import speed_accuracy as sa  # noqa: E402


def test_forced_reference_at_resonance_is_the_textbook_peak():
    """At eta = 1 exactly: phi = pi/2, X = F0 / (2 zeta k), TR = sqrt(1 + 4 zeta^2)/(2 zeta)
    (Rao, Mechanical Vibrations, eqs. 3.30 and 9.94)."""
    zeta = 0.05
    ref = sa.forced_reference(100.0, zeta)   # k = 1e4 N/m, m = 1 kg: omega = 100 rad/s
    assert float(ref["phi"]) == pytest.approx(math.pi / 2, rel=1e-15)
    assert float(ref["X"]) == pytest.approx(1 / (2 * zeta * 1e4), rel=1e-15)
    assert float(ref["TR"]) == pytest.approx(math.sqrt(1 + 4 * zeta ** 2) / (2 * zeta),
                                             rel=1e-15)


def test_forced_reference_keeps_the_tiny_gap():
    """Omega a hair above omega: 1 - eta^2 = -(2 d + d^2)/omega^2 with Omega = omega + d,
    the phase a hair past pi/2 by atan(|gap| / (2 zeta eta))."""
    Omega = sa.FORCED_ETAS[2] * 100.0
    d = mpmath.mpf(Omega) - 100
    gap = -(2 * d * 100 + d * d) / 10000
    ref = sa.forced_reference(Omega, 1e-9)
    two_ze = 2 * mpmath.mpf(1e-9) * mpmath.mpf(Omega) / 100
    assert abs(ref["phi"] - (mpmath.pi / 2 + mpmath.atan(-gap / two_ze))) < mpmath.mpf(1e-25)


def test_frame_reference_is_y0_over_2_zeta_for_small_damping():
    d = sa.frame_cases()[0]                       # zeta = 1e-4
    m, k, b0 = sa.FRAME
    y0 = 2 * m * b0 / k
    assert float(sa.frame_reference(d)) == pytest.approx(y0 / (2 * 1e-4), rel=1e-8)
    assert float(sa.frame_reference(sa.frame_cases()[-1])) == pytest.approx(y0, rel=1e-15)


def test_the_new_rows_are_measured_and_accurate():
    frame = sa.bench_frame(1)
    assert [(r["method"], r["rtol"]) for r in frame] == [
        (m, t) for m in ("exact", "small-damping") for t in sa.RTOLS]
    assert all(r["error"] < 1e-14 for r in frame if r["method"] == "exact")
    # the small-damping model's worst case is zeta = 0.9, past 1/sqrt 2: y_max = y0 there,
    # the model gives y0 / (2 zeta), 44 % low
    assert all(r["error"] == pytest.approx(1 - 1 / (2 * 0.9), rel=1e-12)
               for r in frame if r["method"] == "small-damping")
    (forced,) = sa.bench_forced(1)
    assert forced["method"] == "closed-form" and forced["rtol"] is None
    assert forced["error"] < 8 * 2.0 ** -52
    assert forced["seconds"] > 0


def test_every_one_off_command_line_answers_as_the_library_does():
    """Each command line of the one-off column runs (exit 0, one number a line), and the
    forced-response one prints the mpmath reference's X and phi to a few ulp."""
    exe = sa.dyncalc()
    for command, make in sa.CLI.items():
        done = subprocess.run([*exe, *make("auto" if command != "rolling-onset"
                                           else "closed-form", "1e-9")],
                              capture_output=True, text=True, timeout=120)
        assert done.returncode == 0, (command, done.stderr)
        numbers = [float(line) for line in done.stdout.splitlines()]
        assert numbers and all(math.isfinite(x) for x in numbers)
        if command == "forced-response":
            ref = sa.forced_reference(100.0000000001, 1e-9)
            assert numbers[0] == pytest.approx(float(ref["X"]), rel=1e-15)
            assert numbers[1] == pytest.approx(float(ref["phi"]), rel=1e-15)


def test_one_offs_fill_the_rows():
    rows = [dict(command="forced-response", method="closed-form", rtol=None),
            dict(command="natural-frequency (pendulum)", method="elliptic", rtol=1e-6)]
    sa.one_offs(rows, 1)
    assert all(r["one_off"] > 0 for r in rows)
    assert sa.time_text(rows[0]["one_off"]).endswith("ms")
