"""Batch throughput: ``dyncalc natural-frequency --batch FILE`` for 10^3 .. 10^7 rows.

Each size's CSV (``k [N/m],m [kg]``, random values) is generated on the fly into a temporary
file; dyncalc runs as a child process writing to /dev/null, and the table gives the wall time
end to end (start-up included), rows per second, and the child's peak memory (``ru_maxrss``
from ``wait4``). Further rows: JSON lines output, cells that carry their own (mixed) units, the
generic row-by-row path (``DYNCALC_BATCH_GENERIC=1``, what every command other than
natural-frequency's closed-form scenes uses), and the loop of one-off calls a shell script
would run instead (100 calls, extrapolated).

    python benchmarks/batch.py [--max-rows 10000000] [--repeat 3]
                               [--out benchmarks/results/batch.md] [--baseline DIR]

Run it with the project's virtual environment's python (dyncalc installed in it), from a
neutral folder such as /tmp. ``--baseline DIR`` measures another dyncalc side by side, each
run of the two interleaved: DIR holds its ``dyncalc`` package (``git archive COMMIT dyncalc |
tar -x -C DIR``), put first on the children's ``PYTHONPATH`` with the same environment
otherwise; each row is then followed by the baseline's and the ratio of the wall times.
"""
from __future__ import annotations

import argparse
import os
import platform
import random
import statistics
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BIN = Path(sys.executable).parent
sys.path.insert(0, str(ROOT / "benchmarks"))

from _timing import child_env as shared_env, spawn  # noqa: E402


def dyncalc() -> list[str]:
    script = BIN / "dyncalc"
    return [str(script)] if script.exists() else [sys.executable, "-m", "dyncalc"]


def child_env(**extra) -> dict[str, str]:
    """The children's environment (:func:`_timing.child_env`), ``unset=NAME`` removing one."""
    unset = extra.pop("unset", "")
    env = shared_env(**extra)
    env.pop(unset, None)
    return env


def write_rows(path: Path, n: int, *, units: bool = False, seed: int = 8) -> None:
    """``n`` rows of (k, m), written in blocks so that 10^7 rows take little memory here."""
    rng = random.Random(seed)
    k_units = ("N/m", "kN/m", "lbf/in")
    m_units = ("kg", "g", "lb")
    with open(path, "w", encoding="utf-8") as f:
        f.write("k,m\n" if units else "k [N/m],m [kg]\n")
        block = 100_000
        for start in range(0, n, block):
            count = min(block, n - start)
            if units:
                lines = [f"{rng.uniform(1, 1000):.6g} {rng.choice(k_units)},"
                         f"{rng.uniform(0.1, 10):.4g} {rng.choice(m_units)}\n"
                         for _ in range(count)]
            else:
                lines = [f"{rng.uniform(1, 1000):.6g},{rng.uniform(0.1, 10):.4g}\n"
                         for _ in range(count)]
            f.write("".join(lines))


def run(argv: list[str], env: dict[str, str]) -> tuple[float, int]:
    """(wall seconds, peak resident memory of the child in MB)."""
    sample = spawn(argv, env)
    return sample.wall, int(sample.peak_mb)


#: ``--baseline``: (the folder holding the other dyncalc package, its name in the table)
BASELINE: tuple[str, str] | None = None


def measure(label: str, argv: list[str], env: dict[str, str], rows: int,
            repeat: int) -> list[str]:
    """The table row of ``label`` (and with ``--baseline`` the baseline's row and the ratio
    of the medians, the runs of the two alternating)."""
    variants = [(label, env)]
    if BASELINE is not None:
        folder, name = BASELINE
        variants.append((f"{label}, {name}",
                         {**env, "PYTHONPATH": os.pathsep.join(
                             [folder, *filter(None, [env.get("PYTHONPATH")])])}))
    times: list[list[float]] = [[] for _ in variants]
    peaks: list[list[int]] = [[] for _ in variants]
    for _ in range(repeat):
        for k, (_label, variant_env) in enumerate(variants):
            wall, peak = run(argv, variant_env)
            times[k].append(wall)
            peaks[k].append(peak)
    out, medians = [], []
    for (name, _env), runs, peak in zip(variants, times, peaks):
        wall = statistics.median(runs)
        medians.append(wall)
        spread = (max(runs) - min(runs)) if repeat > 1 else 0.0
        out.append(f"| {name} | {rows:,} | {wall:.2f} | {spread:.2f} | {rows / wall:,.0f} | "
                   f"{max(peak)} |")
    if len(medians) == 2:
        out.append(f"| ratio of the wall times, this / {BASELINE[1]} | | "
                   f"{medians[0] / medians[1]:.2f} | | | |")
    print("\n".join(out), flush=True)
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-rows", type=int, default=10_000_000)
    parser.add_argument("--repeat", type=int, default=3,
                        help="runs per size up to 10^6 rows (the median is shown)")
    parser.add_argument("--out", default=str(ROOT / "benchmarks" / "results" / "batch.md"),
                        help="markdown file for the table ('-': do not write one)")
    parser.add_argument("--baseline", metavar="DIR",
                        help="a folder holding another dyncalc package, measured side by side")
    parser.add_argument("--baseline-name", default="baseline",
                        help="the baseline's name in the table (e.g. its commit)")
    args = parser.parse_args()
    global BASELINE
    if args.baseline:
        if not (Path(args.baseline) / "dyncalc" / "__init__.py").exists():
            raise SystemExit(f"--baseline: {args.baseline} holds no dyncalc package")
        BASELINE = (str(Path(args.baseline).resolve()), args.baseline_name)
    exe = dyncalc()
    env = child_env()
    lines = [f"Python {platform.python_version()}, {os.cpu_count()} CPUs, "
             f"{platform.machine()}; {time.strftime('%Y-%m-%d %H:%M')}; load average "
             f"{os.getloadavg()[0]:.2f} at the start; wall time end to end (start-up "
             "included), median of the runs, spread = max - min"
             + (f"; each row's runs alternate with those of {BASELINE[1]} (its dyncalc "
                "package first on PYTHONPATH, the same environment otherwise)"
                if BASELINE else ""),
             "",
             "| run | rows | wall (s) | spread (s) | rows/s | peak memory (MB) |",
             "| --- | ---: | ---: | ---: | ---: | ---: |"]
    print("\n".join(lines), flush=True)
    with tempfile.TemporaryDirectory(prefix="dyncalc-batch-") as tmp:
        path = Path(tmp) / "rows.csv"
        sizes = [n for n in (10**3, 10**4, 10**5, 10**6, 10**7) if n <= args.max_rows]
        for n in sizes:
            write_rows(path, n)
            repeat = args.repeat if n <= 10**6 else 1
            lines.extend(measure("`natural-frequency --batch` (CSV)",
                                 [*exe, "natural-frequency", "--batch", str(path)], env, n,
                                 repeat))
            if n == 10**5:
                lines.extend(measure("`natural-frequency --batch --json` (JSON lines)",
                                     [*exe, "natural-frequency", "--batch", str(path),
                                      "--json"], env, n, args.repeat))
        n = min(10**5, args.max_rows)
        write_rows(path, n, units=True)
        lines.extend(measure("cells with mixed units (`2 kN/m`, `12 lbf/in`, ...)",
                             [*exe, "natural-frequency", "--batch", str(path)], env, n,
                             args.repeat))
        n = min(10**3, args.max_rows)
        write_rows(path, n)
        lines.extend(measure("generic path, row by row (`DYNCALC_BATCH_GENERIC=1`)",
                             [*exe, "natural-frequency", "--batch", str(path)],
                             child_env(DYNCALC_BATCH_GENERIC="1"), n, args.repeat))
    # the loop a shell script would run instead: 100 one-off calls, extrapolated
    rng = random.Random(8)
    calls = 100
    start = time.perf_counter()
    for _ in range(calls):
        run([*exe, "natural-frequency", "--k", f"{rng.uniform(1, 1000):.6g}N/m", "--m",
             f"{rng.uniform(0.1, 10):.4g}kg", "--json"], env)
    each = (time.perf_counter() - start) / calls
    row = (f"| loop of one-off calls (`dyncalc natural-frequency --k ... --m ... --json`), "
           f"{calls} calls | {calls} | {each * calls:.2f} | | {1 / each:,.1f} | |")
    print(row)
    lines.append(row)
    lines += ["", f"A loop of one-off calls takes {each:.3f} s a row: 10^5 rows would take "
                  f"{each * 1e5 / 3600:.1f} hours (extrapolated from {calls} calls)."]
    text = "\n".join(lines)
    print(lines[-1])
    if args.out != "-":
        out = Path(args.out)
        out.parent.mkdir(parents=True, exist_ok=True)
        out.write_text("## Batch (`python benchmarks/batch.py`)\n\n" + text + "\n",
                       encoding="utf-8")
        print(f"\nwritten to {out}", file=sys.stderr)


if __name__ == "__main__":
    main()
