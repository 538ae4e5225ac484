"""Time ``modes`` on the uniform fixed-fixed chain of n masses (n = 10, 100, 500): the
eigen solve alone (:func:`dyncalc.physics.modes.solve_modes`) and the whole command reading
@FILE.csv matrices, best of five runs; prints a table. Goal (issue 19): well under a second
at n = 500.

    python benchmarks/modes.py
"""
from __future__ import annotations

import os
import tempfile
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # as the CLI runs (dyncalc.cli.main)

import numpy as np  # noqa: E402 (after the thread setting, which numpy reads on import)

from dyncalc.commands.modes import modes  # noqa: E402
from dyncalc.physics.modes import solve_modes  # noqa: E402


def chain(n: int):
    return np.eye(n) * 2.0, (2 * np.eye(n) - np.eye(n, k=1) - np.eye(n, k=-1)) * 1e4


def best(run, repeat: int = 5) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        run()
        times.append(time.perf_counter() - start)
    return min(times)


def main() -> None:
    print("| n | solve_modes [s] | modes command, @FILE.csv [s] |")
    print("| ---: | ---: | ---: |")
    with tempfile.TemporaryDirectory() as folder:
        for n in (10, 100, 500):
            M, K = chain(n)
            paths = {}
            for name, matrix in (("M", M), ("K", K)):
                paths[name] = os.path.join(folder, f"{name}{n}.csv")
                with open(paths[name], "w") as handle:
                    handle.write("\n".join(",".join(repr(float(v)) for v in row)
                                           for row in matrix))
            solve = best(lambda: solve_modes(M, K))
            whole = best(lambda: modes({"M": f"@{paths['M']}", "K": f"@{paths['K']}"}))
            print(f"| {n} | {solve:.4f} | {whole:.4f} |")


if __name__ == "__main__":
    main()
