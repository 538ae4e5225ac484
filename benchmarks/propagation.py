"""Uncertainty propagation against the number of uncertain inputs, before and after, side by side.

One one-off per cell: ``dyncalc spring-series`` with ``n`` springs, each typed with an
uncertainty (``"100 N/m ± 1%"`` ...), printing ``u(k_eq)``; and ``natural-frequency`` of a
physical pendulum with its three parameters uncertain. Each round runs every cell once in a
fresh random order (the machine's drift hits every cell alike); the table gives the median
wall time over the rounds, and with ``--before DIR`` (a checkout of an earlier commit, e.g.
``git archive cd04a5e | tar -x -C /tmp/before``) the same cells from that code in the same
rounds, and the ratio of the medians. Linear cost shows as time growing in proportion to
``n`` (after subtracting the start-up, the n = 1 cell).

    python benchmarks/propagation.py [--rounds 5] [--sizes 1,10,30,100,300]
    python benchmarks/propagation.py --before /tmp/before --sizes 1,10,30,100

Run it with the project's virtual environment's python (dyncalc installed in it).
"""
from __future__ import annotations

import argparse
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def springs(n: int) -> list[str]:
    texts = [f"{100 + i} N/m ± 1%" for i in range(n)]
    return ["spring-series", *texts, "--value", "u(k_eq)"]


PENDULUM = ["natural-frequency", "--scene", "physical-pendulum", "m=(2 ± 0.02) kg",
            "a=(0.5 ± 0.005) m", "J=(0.17 ± 0.002) kg*m^2", "--value", "u(omega)"]


def run_once(argv: list[str], tree: Path) -> tuple[float, str]:
    """One one-off of the dyncalc package in ``tree``: first on PYTHONPATH, and run from a
    neutral folder (``python -m`` puts the working directory first on the path, ahead of
    PYTHONPATH, so a run from a checkout would always load that checkout)."""
    env = {**os.environ, "PYTHONPATH": str(tree)}
    start = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "dyncalc", *argv], capture_output=True,
                          text=True, env=env, timeout=900, cwd=tempfile.gettempdir())
    elapsed = time.perf_counter() - start
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(argv[:3])} ... failed in {tree}: {proc.stderr.strip()}")
    return elapsed, proc.stdout.strip()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--sizes", default="1,10,30,100,300")
    parser.add_argument("--before", type=Path, help="an earlier checkout to compare with")
    args = parser.parse_args(argv)
    sizes = [int(s) for s in args.sizes.split(",")]
    cells = {f"spring-series, {n} uncertain springs": springs(n) for n in sizes}
    cells["physical pendulum, 3 uncertain inputs"] = PENDULUM
    trees = {"after": ROOT}
    if args.before is not None:
        trees["before"] = args.before.resolve()
    times: dict[tuple[str, str], list[float]] = {(c, t): [] for c in cells for t in trees}
    answers: dict[tuple[str, str], str] = {}
    for _ in range(args.rounds):
        order = list(times)
        random.shuffle(order)
        for cell, tree in order:
            elapsed, answer = run_once(cells[cell], trees[tree])
            times[(cell, tree)].append(elapsed)
            answers[(cell, tree)] = answer
    print(f"`python benchmarks/propagation.py {' '.join(argv or sys.argv[1:])}` "
          f"({args.rounds} rounds, median wall time of a one-off, seconds)\n")
    header = "| cell | after (s) | u printed |"
    rule = "| --- | --- | --- |"
    if "before" in trees:
        header = "| cell | before (s) | after (s) | before / after | u before | u after |"
        rule = "| --- | --- | --- | --- | --- | --- |"
    print(header)
    print(rule)
    for cell in cells:
        after = statistics.median(times[(cell, "after")])
        if "before" in trees:
            before = statistics.median(times[(cell, "before")])
            print(f"| {cell} | {before:.3f} | {after:.3f} | {before / after:.1f} | "
                  f"{answers[(cell, 'before')]} | {answers[(cell, 'after')]} |")
        else:
            print(f"| {cell} | {after:.3f} | {answers[(cell, 'after')]} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
