"""``dyncalc.batch.memory.hold_freed_memory``: on glibc, a loop that makes and drops blocks of a
few megabytes touches new pages a tenth as often once it is called (minor page faults counted
by the kernel, not time); the command line's ``--batch`` calls it, a library caller's
``run_batch`` does not; off glibc it changes nothing and says so."""
from __future__ import annotations

import math
import os
import subprocess
import sys

import pytest
from click.testing import CliRunner

from dyncalc.batch import memory
from dyncalc.cli import cli

GLIBC = (os.confstr("CS_GNU_LIBC_VERSION") or "").startswith("glibc") \
    if "CS_GNU_LIBC_VERSION" in os.confstr_names else False

#: Blocks of 2 to 6 MiB, each written through, one held while the next two are made: the
#: faults (pages touched for the first time) of the loop are printed.
LOOP = """
import resource, sys
if sys.argv[1] == "hold":
    from dyncalc.batch.memory import hold_freed_memory
    assert hold_freed_memory()
def faults():
    return resource.getrusage(resource.RUSAGE_SELF).ru_minflt
before = faults()
kept = b""
for i in range(60):
    new = b"x" * ((2 + i % 5) << 20)
    text = new.decode()
    kept = new
    del text
print(faults() - before)
"""


def _faults(mode: str) -> int:
    done = subprocess.run([sys.executable, "-c", LOOP, mode], capture_output=True, text=True,
                          check=True)
    return int(done.stdout)


@pytest.mark.skipif(not GLIBC, reason="mallopt's thresholds are glibc's")
def test_held_memory_is_reused_not_touched_anew():
    held, default = _faults("hold"), _faults("default")
    # 60 blocks of 4 MiB on average and their texts: about 120,000 pages if each is new; the
    # high-water mark (three blocks of at most 6 MiB) is about 4,600
    assert held < 8000, (held, default)
    assert held * 4 < default, (held, default)


@pytest.mark.skipif(not GLIBC, reason="mallopt's thresholds are glibc's")
def test_set_on_glibc():
    assert memory.hold_freed_memory() is True


@pytest.mark.parametrize("libc", ["", None, "musl"])
def test_nothing_changes_off_glibc(monkeypatch, libc):
    monkeypatch.setattr(memory.os, "confstr", lambda name: libc)
    assert memory.hold_freed_memory() is False


def test_no_confstr_name_is_not_glibc(monkeypatch):
    def refuse(name):
        raise ValueError("unrecognized configuration name")

    monkeypatch.setattr(memory.os, "confstr", refuse)
    assert memory.hold_freed_memory() is False


def _calls(monkeypatch) -> list:
    calls: list = []
    monkeypatch.setattr(memory, "hold_freed_memory", lambda: calls.append(1) or True)
    return calls


def test_the_command_line_batch_holds(monkeypatch, tmp_path):
    calls = _calls(monkeypatch)
    path = tmp_path / "rows.csv"
    path.write_text("k [N/m],m [kg]\n100,2\n")
    ran = CliRunner().invoke(cli, ["natural-frequency", "--batch", str(path), "--value", ""])
    assert calls == [] and ran.exit_code != 0  # refused before any row: nothing set
    ran = CliRunner().invoke(cli, ["natural-frequency", "--batch", str(path)])
    assert ran.exit_code == 0, ran.output
    assert ran.output.splitlines()[1].startswith(f"100,2,{math.sqrt(100 / 2)!r},")
    assert calls == [1]


def test_a_library_run_batch_leaves_the_allocator(monkeypatch):
    import io

    from dyncalc.batch import NaturalFrequencyRows, run_batch

    calls = _calls(monkeypatch)
    out = io.StringIO()
    status = run_batch(NaturalFrequencyRows({}), io.StringIO("k [N/m],m [kg]\n100,2\n"),
                       out=out, err=io.StringIO())
    assert status == 0 and out.getvalue().count("\n") == 2
    assert calls == []


def test_a_python_without_ctypes_changes_nothing(monkeypatch):
    monkeypatch.setattr(memory.os, "confstr", lambda name: "glibc 2.36")
    monkeypatch.setitem(sys.modules, "ctypes", None)   # import ctypes raises ImportError
    assert memory.hold_freed_memory() is False
