"""Regenerate every benchmarks/results/*.md in one run, each benchmark as a child process with
its own command line (which its file records, with the machine, the load and the date).

    python benchmarks/run_all.py [--quick] [--only NAME ...] [--dry-run]

``--quick`` runs each benchmark at its small sizes (minutes instead of an hour or more).
Run it with the project's virtual environment's python (dyncalc and the ``bench`` extra
installed), on an otherwise quiet machine: check ``uptime`` first.
"""
from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"

#: name -> (full arguments, quick arguments, how its file is written: ``out`` (by the
#: benchmark, given ``--out``), ``self`` (by the benchmark, at its own path) or ``stdout``
#: (what it prints, under a header written here))
BENCHMARKS = {
    # issue 17's "Done when": the batch part of limits.py and the one-off against qalc in
    # one run; writes results/done_when.md and the batch part again as results/limits.md
    "done_when": (["--limits-out", str(RESULTS / "limits.md")],
                  ["--quick", "--limits-out", str(RESULTS / "limits.md")], "out"),
    "batch_commands": (["--rows", "100000", "--generic-rows", "1000", "--repeat", "3"],
                       ["--rows", "20000", "--generic-rows", "200", "--repeat", "1"], "out"),
    "batch": ([], ["--max-rows", "100000", "--repeat", "1"], "out"),
    "startup": ([], ["--rounds", "5"], "out"),
    "propagation": ([], ["--rounds", "2"], "stdout"),
    "speed_accuracy": ([], ["--quick"], "self"),
}


def machine() -> str:
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg())
    return (f"Python {platform.python_version()}, {os.cpu_count()} CPUs, {platform.machine()}; "
            f"{time.strftime('%Y-%m-%d %H:%M')}; load average {load} at the start")


def argv_for(name: str, quick: bool) -> list[str]:
    full, fast, how = BENCHMARKS[name]
    argv = [sys.executable, str(HERE / f"{name}.py"), *(fast if quick else full)]
    return argv + (["--out", str(RESULTS / f"{name}.md")] if how == "out" else [])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--only", nargs="*", choices=sorted(BENCHMARKS))
    parser.add_argument("--dry-run", action="store_true", help="print the commands only")
    args = parser.parse_args()
    print(f"load average {', '.join(f'{x:.2f}' for x in os.getloadavg())}", flush=True)
    for name in args.only or BENCHMARKS:
        argv = argv_for(name, args.quick)
        print("$", " ".join(argv), flush=True)
        if args.dry_run:
            continue
        start = time.perf_counter()
        header = machine()
        how = BENCHMARKS[name][2]
        done = subprocess.run(argv, cwd="/tmp", text=True,
                              stdout=subprocess.PIPE if how == "stdout" else None)
        if how == "stdout" and done.returncode == 0:
            print(done.stdout, end="")
            command = " ".join(["python", f"benchmarks/{name}.py", *argv[2:]])
            (RESULTS / f"{name}.md").write_text(
                f"# {name}\n\n{header}; command: `{command}` (through "
                f"`python benchmarks/run_all.py {' '.join(sys.argv[1:])}`)\n\n```\n"
                + done.stdout + "```\n")
        print(f"# {name}: exit {done.returncode}, {time.perf_counter() - start:.0f} s",
              flush=True)
        if done.returncode != 0:
            raise SystemExit(done.returncode)


if __name__ == "__main__":
    main()
