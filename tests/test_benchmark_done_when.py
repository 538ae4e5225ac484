"""benchmarks/done_when.py (issue 17's "Done when" in one run) and benchmarks/_timing.py, at
tiny sizes: smoke tests of what they print and check, never of how fast anything is."""
from __future__ import annotations

import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

BENCHMARKS = Path(__file__).resolve().parent.parent / "benchmarks"
sys.path.insert(0, str(BENCHMARKS))

import _timing  # noqa: E402
import done_when  # noqa: E402

VENV = Path(sys.executable).parent.parent


def test_one_run_prints_the_batch_ratios_and_the_one_off_ratios(tmp_path):
    out, lim = tmp_path / "done_when.md", tmp_path / "limits.md"
    done = subprocess.run(
        [sys.executable, str(BENCHMARKS / "done_when.py"), "--rows", "200", "--memory-rows",
         "300", "--repeat", "1", "--only", "spring-parallel", "--rounds", "2", "--venv",
         str(VENV), "--out", str(out), "--limits-out", str(lim)],
        capture_output=True, text=True, timeout=600, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    report = out.read_text()
    assert report.startswith("# Issue 17, done when")
    assert re.search(r"\d CPUs, .*; load average [\d.]+, [\d.]+, [\d.]+ at the start; "
                     r"command: `python benchmarks/done_when.py --rows 200 ", report)
    ratios = re.findall(r"\| spring-parallel \| (CSV|JSON lines) \| ([\d.]+) \| ([\d.]+) \| "
                        r"([\d.]+)x \| (\d+) \| (yes|no) \|", report)
    assert [r[0] for r in ratios] == ["CSV", "JSON lines"]
    for _, mine, limit, ratio, memory, _ok in ratios:
        # the times are printed to 0.01 s, the ratio from the unrounded times: it lies between
        # the ratios of the printed times' extremes (plus the ratio's own rounding)
        low = (float(mine) - 0.005) / (float(limit) + 0.005)
        high = (float(mine) + 0.005) / max(float(limit) - 0.005, 1e-9)
        assert low - 0.005 <= float(ratio) <= high + 0.005
        assert 5 < int(memory) < 1000
    for name in done_when.ONE_OFFS:
        if not name.startswith("qalc") or shutil.which("qalc"):
            assert f"| `{name}` | " in report
    verdict = report.split("## Done when")[1]
    assert verdict.count("x `python -c pass`") == 2
    assert verdict.count(" x qalc (") == (2 if shutil.which("qalc") else 0)
    assert "the largest peak memory" in verdict and "at the end" in verdict
    # the batch part alone, in limits.py's form, the same rows
    batch = lim.read_text()
    assert batch.startswith("# Batch mode against the limit scripts")
    assert [line for line in batch.splitlines() if line.startswith("| spring-parallel")] == [
        line for line in report.splitlines() if line.startswith("| spring-parallel")]
    # printed as it runs: the same verdict on stdout
    assert verdict.strip().splitlines()[0] in done.stdout


def test_the_verdict_counts_the_cases_and_names_the_worst():
    rows = ["| command | output | dyncalc (s) | limit (s) | ratio | memory | goal met |",
            "| --- | --- | ---: | ---: | ---: | ---: | --- |",
            "| a | CSV | 1.00 | 0.50 | 2.00x | 70 | yes |",
            "| b | JSON lines | 3.00 | 1.00 | 3.00x | 40 | no |",
            "| c | CSV | 1.00 | 1.00 | 1.00x | 120 | no |"]
    assert done_when.batch_verdict(rows) == (
        "- batch: 1 of 3 cases meet both goals; the largest ratio 3.00x (b JSON lines), "
        "the largest peak memory 120 MB")


def test_a_wrong_one_off_answer_stops_the_benchmark():
    wrong = {name: [sys.executable, "-c", "print(1.125)"] for name in done_when.ONE_OFFS}
    with pytest.raises(SystemExit) as stop:
        done_when.check_answer(wrong)
    expected = math.sqrt(50.0) / (2 * math.pi)
    assert str(stop.value).endswith(f"printed '1.125\\n' (exit 0), not f = {expected!r}: ")


def test_a_venv_without_dyncalc_is_refused(tmp_path):
    with pytest.raises(SystemExit) as stop:
        done_when.programs(tmp_path / "bin")
    assert str(stop.value) == f"{tmp_path / 'bin'} holds no dyncalc console script"


def test_spawn_reports_peak_memory_and_a_failed_child(tmp_path):
    """Peak memory is measured from a small parent: Linux counts the parent's resident size
    at the spawn into the child's peak (posix_spawn shares its memory until the exec), so
    under pytest (hundreds of MB) every child would read as large as pytest."""
    code = ("import sys; sys.path.insert(0, sys.argv[1]); import _timing; "
            "big = _timing.spawn([sys.executable, '-c', 'b = bytearray(200_000_000); "
            "b[::4096] = bytes(len(b[::4096]))']); "
            "small = _timing.spawn([sys.executable, '-c', 'pass']); "
            "print(big.peak_mb, small.peak_mb, big.wall, big.cpu)")
    done = subprocess.run([sys.executable, "-c", code, str(BENCHMARKS)], capture_output=True,
                          text=True, timeout=120, check=True)
    big, small, wall, cpu = map(float, done.stdout.split())
    assert big - small > 150 and small < 100
    assert wall > 0 and cpu > 0
    log = tmp_path / "out.txt"
    _timing.spawn([sys.executable, "-c", "print('written')"], stdout=str(log))
    assert log.read_text() == "written\n"
    argv = [sys.executable, "-c", "raise SystemExit(3)"]
    with pytest.raises(SystemExit) as stop:
        _timing.spawn(argv)
    assert str(stop.value) == f"{' '.join(argv)} exited 3"


def test_paired_median_and_quartiles():
    assert _timing.paired_median([2.0, 3.0, 10.0], [1.0, 1.0, 1.0]) == 3.0
    assert _timing.quartiles([1.0, 2.0, 3.0, 4.0, 5.0]) == (2.0, 3.0, 4.0)
    assert _timing.quartiles([7.0]) == (7.0, 7.0, 7.0)
