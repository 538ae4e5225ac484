"""What every benchmark needs to time a child process: spawn it, wait for it, and read its
wall time, CPU time and peak memory, plus the header line that says where and when.

``posix_spawn`` and ``wait4`` rather than :mod:`subprocess`: no Python-side pipes or threads
in the timed interval, and ``wait4`` gives the child's own resource usage (``ru_maxrss``: its
peak resident memory; ``ru_utime + ru_stime``: its CPU time).

>>> import sys
>>> sample = spawn([sys.executable, "-c", "pass"])
>>> sample.wall > 0 and sample.cpu >= 0 and sample.peak_mb > 1
True
"""
from __future__ import annotations

import os
import platform
import statistics
import time
from typing import NamedTuple

__all__ = ["Sample", "spawn", "child_env", "machine", "load", "quartiles", "paired_median"]


class Sample(NamedTuple):
    """One child's run: wall seconds, CPU seconds (user + system), peak memory in MB."""

    wall: float
    cpu: float
    peak_mb: float


def spawn(argv: list[str], env: dict[str, str] | None = None, stdout: str = os.devnull,
          stderr: str = os.devnull) -> Sample:
    """Run ``argv`` (``argv[0]`` a path) with ``env`` (default: this process's), its stdout
    and stderr written to the files named (default /dev/null); a non-zero exit stops the
    benchmark (a one-line message, the command and its status).

    ``peak_mb`` is at least this process's own resident size at the spawn (Linux carries the
    high-water mark of the memory the child shares with its parent until ``exec`` into the
    child's), so spawn from a small process: the benchmarks' parents are a few tens of MB,
    below any dyncalc run."""
    start = time.perf_counter()
    pid = os.posix_spawn(argv[0], argv, dict(os.environ) if env is None else env,
                         file_actions=[
                             (os.POSIX_SPAWN_OPEN, 1, stdout,
                              os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644),
                             (os.POSIX_SPAWN_OPEN, 2, stderr,
                              os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)])
    _pid, status, usage = os.wait4(pid, 0)
    wall = time.perf_counter() - start
    code = os.waitstatus_to_exitcode(status)
    if code != 0:
        raise SystemExit(f"{' '.join(argv)} exited {code}")
    return Sample(wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024)  # Linux: kB


def child_env(**extra: str) -> dict[str, str]:
    """This process's environment for a child, without ``PYTHONDONTWRITEBYTECODE`` (dyncalc's
    modules load from their bytecode cache, as pint's and numpy's do), plus ``extra``."""
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env.update(extra)
    return env


def load() -> str:
    """The three load averages, ``"1.20, 0.80, 0.55"``."""
    return ", ".join(f"{x:.2f}" for x in os.getloadavg())


def machine() -> str:
    """Python, CPUs, architecture and processor, date and time, load averages."""
    return (f"Python {platform.python_version()}, {os.cpu_count()} CPUs, {platform.machine()} "
            f"({platform.processor() or platform.platform()}); "
            f"{time.strftime('%Y-%m-%d %H:%M')}; load average {load()} at the start")


def quartiles(values: list[float]) -> tuple[float, float, float]:
    """(first quartile, median, third quartile); one value is all three."""
    if len(values) < 2:
        return values[0], values[0], values[0]
    q1, q2, q3 = statistics.quantiles(values, n=4, method="inclusive")
    return q1, statistics.median(values), q3


def paired_median(times: list[float], bases: list[float]) -> float:
    """The median over rounds of ``times[i] / bases[i]`` (each pair measured in the same
    round, so a drift of the machine's load hits both)."""
    return statistics.median(a / b for a, b in zip(times, bases))
