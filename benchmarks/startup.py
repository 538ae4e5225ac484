"""One-off start-up: dyncalc against the floor of its stack, measured side by side.

The floor is ``python -c`` importing pint and numpy, loading the registry from pint's cache and
computing one quantity: dyncalc cannot answer faster than its stack loads. Each round runs
every command once, in turn, so the machine's drift hits them alike; the table gives medians,
the spread (interquartile range) and the ratio of medians to the floor.

    python benchmarks/startup.py [--rounds 21]

Run it from the project root with the project's virtual environment active (or its python).
"""
from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time

FLOOR = ("import pint, numpy; u = pint.UnitRegistry(cache_folder=':auto:'); "
         "print((u.Quantity(100, 'N/m') / u.Quantity(2, 'kg')) ** 0.5)")

COMMANDS = {
    "floor: python -c 'import pint, numpy; registry; one quantity'": [sys.executable, "-c",
                                                                       FLOOR],
    "dyncalc natural-frequency --k 100N/m --m 2kg --json": [
        sys.executable, "-m", "dyncalc", "natural-frequency", "--k", "100N/m", "--m", "2kg",
        "--json"],
    "dyncalc spring-series 200N/m 300N/m --value k_eq": [
        sys.executable, "-m", "dyncalc", "spring-series", "200N/m", "300N/m", "--value",
        "k_eq"],
    "dyncalc --help": [sys.executable, "-m", "dyncalc", "--help"],
}


def timed(argv: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=21)
    rounds = parser.parse_args().rounds
    for argv in COMMANDS.values():  # warm the caches (pint's registry cache, the page cache)
        timed(argv)
    samples: dict[str, list[float]] = {name: [] for name in COMMANDS}
    for _ in range(rounds):
        for name, argv in COMMANDS.items():
            samples[name].append(timed(argv))
    floor = statistics.median(next(iter(samples.values())))
    print(f"{rounds} rounds, {sys.version.split()[0]}\n")
    print("| command | median (ms) | IQR (ms) | / floor |")
    print("| --- | ---: | ---: | ---: |")
    for name, times in samples.items():
        q1, _q2, q3 = statistics.quantiles(times, n=4)
        median = statistics.median(times)
        print(f"| `{name}` | {1000 * median:.0f} | {1000 * (q3 - q1):.0f} | "
              f"{median / floor:.2f} |")


if __name__ == "__main__":
    main()
