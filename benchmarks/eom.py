"""``eom`` derivation times for every scene of the energies table, in one process.

For each scene: the derivation alone (parse, Lagrange's equations, the accelerations solved and
tidied: symbolic, no values), and the whole command with the scene's test values (derivation,
the grid search for equilibria, linearisation, frequencies). The median over ``--rounds``
runs; sympy's import (once per process) is timed apart, as is one cold one-off through the
command line for the slowest scene.

    python benchmarks/eom.py [--rounds 3]

Run it with the project's virtual environment's python (dyncalc installed in it).
"""
from __future__ import annotations

import argparse
import importlib
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "tests"))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()

    start = time.perf_counter()
    importlib.import_module("sympy")  # timed: eom pays it once per process
    print(f"import sympy: {time.perf_counter() - start:.2f} s")

    from dyncalc.commands.eom import eom
    from dyncalc.scenes.energies import energies, energy_scene_names
    from test_eom_scenes import VALUES

    rows = []
    for scene in energy_scene_names():
        n = len(energies(scene).coords)
        derive, whole = [], []
        for _ in range(args.rounds):
            t0 = time.perf_counter()
            eom({}, [], scene=scene)
            t1 = time.perf_counter()
            eom({}, [f"{k}={v}" for k, v in VALUES[scene].items()], scene=scene)
            t2 = time.perf_counter()
            derive.append(t1 - t0)
            whole.append(t2 - t1)
        rows.append((scene, n, statistics.median(derive), statistics.median(whole)))
    print(f"{'scene':32s} {'dof':>3s} {'symbolic [s]':>12s} {'with values [s]':>15s}")
    for scene, n, d, w in rows:
        print(f"{scene:32s} {n:3d} {d:12.3f} {w:15.3f}")
    slowest = max(rows, key=lambda r: max(r[2], r[3]))
    print(f"slowest: {slowest[0]} ({max(slowest[2], slowest[3]):.3f} s)")
    words = [f"{k}={v}" for k, v in VALUES[slowest[0]].items()]
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "dyncalc", "eom", "--scene", slowest[0], *words],
                   check=True, capture_output=True)
    print(f"cold one-off of {slowest[0]} (new process, sympy import included): "
          f"{time.perf_counter() - t0:.2f} s")


if __name__ == "__main__":
    main()
