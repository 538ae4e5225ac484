"""``coriolis`` over times on whole columns (dyncalc/batch/fast_coriolis_time.py): byte for
byte the one-off row by row (``DYNCALC_BATCH_GENERIC=1``) on random times including extremes,
CSV and JSON lines; most rows on the vectorised path; rows it cannot take (an expression not
defined at t, an overflow, a turning axis, a fixed basis) keep the one-off's output and
refusals; and numbers against the closed form of a slider in a turning slot."""
from __future__ import annotations

import json
import math

import numpy as np
import pytest
from click.testing import CliRunner

from dyncalc.batch import GENERIC_ENV, fast_coriolis_time
from dyncalc.cli import cli

MOTIONS = {
    "slider": ["--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "b=0.5m/s^2", "--omega", "0,0,2 rad/s"],
    "spun-up": ["--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "b=0.5m/s^2", "--omega", "0, 0, c*t",
                "c=0.5rad/s^2", "--mass", "2kg"],
    "circle": ["--r", "a*cos(w*t), a*sin(w*t), h*t m", "a=0.3m", "w=3rad/s", "h=0.1m/s",
               "--omega", "0, q, 0 rad/s", "q=1.5"],
    "still": ["--r", "L/(1 + (t/T)^2), L*exp(-t/T), 0", "L=1m", "T=1s", "--omega",
              "0,0,0 rad/s"],
    "pole": ["--r", "L*T/t, 0, 0", "L=1m", "T=1s", "--omega", "0, 0, 1 rad/s"],
    "turning-axis": ["--r", "V*t, 0, 0", "V=1m/s", "--omega", "sin(t/T), 0, 1 rad/s",
                     "T=1s"],
    "fixed-basis": ["--r", "V*t, 0, 0", "V=1m/s", "--omega", "0,0,1 rad/s", "--basis",
                    "fixed"],
}


def _times(seed: int, extremes: bool = True) -> list[str]:
    rng = np.random.default_rng(seed)
    times = [repr(float(x)) for x in rng.uniform(-10, 10, 60)]
    times += ["0", "-0.0", "1e-300", "5e-324", "3.5", "2.0e2"]
    if extremes:  # (not where the one-off integrates the rotation: that far takes for ever)
        times += ["1e150", "-1e200", "1e308"]
    return times


def _run(args, text, generic: bool, monkeypatch):
    if generic:
        monkeypatch.setenv(GENERIC_ENV, "1")
    else:
        monkeypatch.delenv(GENERIC_ENV, raising=False)
    return CliRunner().invoke(cli, args, input=text)


def _counted(monkeypatch) -> list:
    """The rows the vectorised path writes, per chunk."""
    taken = []
    fast = fast_coriolis_time.coriolis_time_fast

    def counting(*args):
        blocks = fast(*args)
        taken.append(sum(len(block.rows) for block in blocks))
        return blocks

    monkeypatch.setattr(fast_coriolis_time, "coriolis_time_fast", counting)
    return taken


@pytest.mark.parametrize("motion", list(MOTIONS))
@pytest.mark.parametrize("as_json", [False, True], ids=["csv", "json"])
def test_times_on_columns_are_the_one_off_byte_for_byte(monkeypatch, motion, as_json):
    times = _times(7) if motion != "turning-axis" else _times(7, extremes=False)[:20]
    text = "t [s]\n" + "".join(t + "\n" for t in times)
    args = ["coriolis", *MOTIONS[motion], "--batch", "-", "--on-error", "skip",
            *(["--json"] if as_json else [])]
    taken = _counted(monkeypatch)
    fast = _run(args, text, False, monkeypatch)
    generic = _run(args, text, True, monkeypatch)
    assert (fast.exit_code, fast.stdout, fast.stderr) == (
        generic.exit_code, generic.stdout, generic.stderr)
    if motion in ("turning-axis", "fixed-basis"):  # the one-off's, row by row
        assert sum(taken) == 0
    else:
        assert sum(taken) >= 60  # of 69 (the pole's 67)
    if motion == "pole":  # 1/t at t = 0: refused as the one-off refuses
        assert fast.exit_code == 2 and "Error: line 62: r cannot be evaluated at t = 0 s " \
            "(float division by zero): the expression is not defined there\n" in fast.stderr


def test_a_t_list_takes_the_columns_too(monkeypatch):
    args = ["coriolis", *MOTIONS["spun-up"], "--t", "0.5 s, 1 s, 2.5 s", "--json"]
    taken = _counted(monkeypatch)
    fast = _run(args, "", False, monkeypatch)
    generic = _run(args, "", True, monkeypatch)
    assert fast.exit_code == 0 and fast.stdout == generic.stdout and taken == [3]


def test_a_slider_in_a_turning_slot_against_its_closed_form(monkeypatch):
    """r = (s0 - b t^2/2, 0, 0), Omega = (0, 0, w): v_r = (-b t, 0, 0), a_c = 2 Omega x v_r =
    (0, -2 w b t, 0), a_centripetal = (-w^2 r_x, 0, 0), theta = w t."""
    s0, b, w = 4.0, 0.5, 2.0
    times = [0.25 * k for k in range(1, 30)]
    text = "t [s]\n" + "".join(f"{t!r}\n" for t in times)
    out = _run(["coriolis", *MOTIONS["slider"], "--batch", "-", "--json"], text, False,
               monkeypatch)
    assert out.exit_code == 0, out.stderr
    for t, line in zip(times, out.stdout.splitlines()):
        record = json.loads(line)
        results = record["results"]
        x = s0 - b * t * t / 2.0
        assert results["a_c"]["value"] == pytest.approx([0.0, -2.0 * w * b * t, 0.0],
                                                        rel=1e-15, abs=0.0)
        assert results["a_centripetal"]["value"][0] == pytest.approx(-w * w * x, rel=1e-14)
        assert results["theta"]["value"] == pytest.approx(w * t, rel=1e-15)
        Q = record["extra"]["rotation_matrix"]
        assert Q[0][0] == pytest.approx(math.cos(w * t), abs=1e-15)
        assert Q[1][0] == pytest.approx(math.sin(w * t), abs=1e-15)


def test_a_column_of_plain_times_is_read_at_once_as_cell_by_cell():
    """The column read in one pass (``_plain_times``) gives the rows and the bits that the
    cell-by-cell reading gives, on literals of every form; a column it does not take (a
    unit, a leading zero, a blank inside, words) is left to the cell-by-cell reading."""
    from dyncalc.batch.header import Column

    col = Column(0, "t", "t", "", "t")
    rng = np.random.default_rng(5)
    forms = ["{:.6g}", "{!r}", "+{:.3f}", "{:.2e}", "{:.0f}.", ".{:.0f}"]
    for _ in range(200):
        cells = [forms[rng.integers(len(forms))].format(abs(x) if i % 3 else x)
                 .replace("-.", "-0.").replace(".-", ".")
                 for i, x in enumerate(rng.uniform(-1e3, 1e3, 30).tolist())]
        read = fast_coriolis_time._plain_times(cells)
        rows, times = fast_coriolis_time._times(cells, col)
        if read is None:
            continue
        assert rows.tolist() == list(range(len(cells)))
        assert np.array_equal(read.view(np.int64), times.view(np.int64)), cells
    for odd in (["1", "2 s"], ["1", "007"], ["1", "2 3"], ["1", "abc"], ["1", ""]):
        assert fast_coriolis_time._plain_times(odd) is None, odd
