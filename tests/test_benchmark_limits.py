"""The limit scripts (benchmarks/limit/) write exactly what ``dyncalc ... --batch`` writes.

benchmarks/limits.py reports dyncalc's batch time as a ratio to these hand-written
numpy/polars scripts; the ratio is honest only if both do the same work to the same bytes. For
each case (the rows benchmarks/batch_commands.py generates, a few hundred of them), dyncalc's
CSV and JSON lines are compared byte for byte with the limit script's.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from dyncalc.cli import cli

BENCHMARKS = Path(__file__).resolve().parent.parent / "benchmarks"
sys.path.insert(0, str(BENCHMARKS))

import limits  # noqa: E402

CASES = list(limits.cases())
ROWS = 400


def test_every_command_of_the_brief_has_a_limit_script():
    labels = {case[0] for case in CASES}
    assert labels == {"natural-frequency mass-spring", "natural-frequency clock-pendulum",
                      "spring-series", "spring-parallel", "damping-ratio", "rolling-onset",
                      "spring-series cantilever, axial bar and a stiffness",
                      "coriolis", "coriolis Earth", "forced-response",
                      "inertia one disk a row", "inertia composite", "inertia placed composite",
                      "modes two-mass chain",
                      "modes damped two-mass chain", "modes non-proportional",
                      "modes coupled-blocks",
                      "forced-response total response", "forced-response undamped",
                      "eom pendulum", "eom bead-on-rotating-ring", "eom coupled-blocks",
                      "eom pendulum-on-sliding-block",
                      "rigid-body drum-two-blocks",
                      "rigid-body angled-bar-on-shaft", "coriolis Earth inverse vr",
                      "rigid-body inverse",
                      "coriolis over times", "spring-series nested group with a shared EI"}


@pytest.mark.parametrize("as_json", [False, True], ids=["csv", "json"])
@pytest.mark.parametrize("case", CASES, ids=[case[0] for case in CASES])
def test_the_limit_script_writes_dyncalcs_bytes(tmp_path, case, as_json):
    label, argv, header, make, limit = case
    path = limits.write_file(tmp_path, label, header, make, ROWS)
    mine, theirs = limits.commands(argv, limit, path, as_json)
    ours = CliRunner().invoke(cli, mine[mine.index(argv[0]):])
    assert ours.exit_code == 0, ours.stderr
    done = subprocess.run(theirs, capture_output=True, timeout=120, cwd=tmp_path)
    assert done.returncode == 0, done.stderr.decode()
    # no warnings, or (undamped, non-proportional damping; CSV) the same warning lines
    assert done.stderr.decode() == ours.stderr
    assert (("undamped" in label or "non-proportional" in label) and not as_json) == \
        (ours.stderr != "")
    expected = ours.stdout_bytes
    assert len(expected.splitlines()) == ROWS + (0 if as_json else 1)
    assert done.stdout == expected


def test_a_limit_script_that_differs_is_caught(tmp_path):
    """The comparison can fail: the mass-spring limit on a file whose k column holds a value
    dyncalc refuses (a negative stiffness) writes a line where dyncalc writes none."""
    label, argv, header, make, limit = CASES[0]
    path = tmp_path / "bad.csv"
    path.write_text(header + "\n-100,2\n")
    mine, theirs = limits.commands(argv, limit, path, False)
    ours = CliRunner().invoke(cli, mine[mine.index(argv[0]):])
    assert ours.exit_code == 2
    assert ours.stderr == "Error: line 2: k must be positive; got -100 newton / meter\n"
    done = subprocess.run(theirs, capture_output=True, timeout=120, cwd=tmp_path)
    assert done.stdout != ours.stdout_bytes
