"""dyncalc's batch mode against the limit: a hand-written numpy/polars script per command.

For every case of benchmarks/batch_commands.py that has a limit script (benchmarks/limit/),
one run prints: dyncalc's wall time and the limit script's at 10^6 rows (median of ``--repeat``
interleaved runs, start-up included for both, output to /dev/null), their ratio, for CSV and
JSON lines; and dyncalc's peak resident memory at 10^7 rows (``ru_maxrss`` of the child), CSV
and JSON lines. Before timing, each case's outputs at 10^6 rows are compared byte for byte (a
limit that wrote other bytes would make the ratio meaningless). The header gives the machine,
the load average, the date and the command; ``--out`` writes the table as Markdown.

    python benchmarks/limits.py [--rows 1000000] [--memory-rows 10000000] [--repeat 5]
                                [--quick] [--only LABEL] [--out benchmarks/results/limits.md]

``--quick``: 10^5 rows timed, 10^6 for memory. Run it with the project's virtual environment's
python (dyncalc and the ``bench`` extra installed), on an otherwise quiet machine.
"""
from __future__ import annotations

import argparse
import hashlib
import statistics
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from _timing import load, machine, spawn  # noqa: E402
from batch_commands import CASES, dyncalc, write_file  # noqa: E402

LIMIT = HERE / "limit"
#: case label -> the limit script's argv after ``python``
LIMITS = {
    "natural-frequency mass-spring": [str(LIMIT / "mass_spring.py")],
    "natural-frequency clock-pendulum": [str(LIMIT / "clock_pendulum.py")],
    "spring-series": [str(LIMIT / "springs.py"), "series"],
    "spring-parallel": [str(LIMIT / "springs.py"), "parallel"],
    "spring-series cantilever, axial bar and a stiffness": [str(LIMIT / "spring_elements.py")],
    "damping-ratio": [str(LIMIT / "damping_ratio.py")],
    "rolling-onset": [str(LIMIT / "rolling_onset.py")],
    "coriolis": [str(LIMIT / "coriolis.py")],
    "coriolis Earth": [str(LIMIT / "coriolis_earth.py")],
    "forced-response": [str(LIMIT / "forced_response.py")],
    # round 4 (issue 17): inertia and modes
    "inertia one disk a row": [str(LIMIT / "inertia.py")],
    # round 6: composites of centred bodies (issue 17's brief, batchrest3)
    "inertia composite": [str(LIMIT / "inertia_composite.py")],
    # round 7: placed bodies, the parallel-axis terms on columns (issue 17, inertiaplaced)
    "inertia placed composite": [str(LIMIT / "inertia_placed.py")],
    # round 5: forced-response rows with --t (issue 17's brief, batchrest2)
    "forced-response total response": [str(LIMIT / "forced_total.py")],
    "forced-response undamped": [str(LIMIT / "forced_undamped.py")],
    "modes two-mass chain": [str(LIMIT / "modes.py")],
    "modes damped two-mass chain": [str(LIMIT / "modes.py"), "damped"],
    # round 8: damping that is not proportional, and scenes (issue 17, modesscene)
    "modes non-proportional": [str(LIMIT / "modes_complex.py")],
    "modes coupled-blocks": [str(LIMIT / "modes_scene.py")],
    # round 10: a rigid-body drift in closed form (issue 17)
    "modes pendulum-on-sliding-block": [str(LIMIT / "modes_drift.py")],
    # round 6: rigid-body scenes on column kernels (issue 17's brief, rigidbatch)
    "rigid-body drum-two-blocks": [str(LIMIT / "rigid_body.py"), "drum"],
    "rigid-body angled-bar-on-shaft": [str(LIMIT / "rigid_body.py"), "angled-bar"],
    # round 6: eom --scene, derived once (issue 17's brief, eombatch)
    "eom pendulum": [str(LIMIT / "eom.py")],
    # round 6: equilibria that depend on the values, closed forms on columns (eom2)
    "eom bead-on-rotating-ring": [str(LIMIT / "eom_bead.py")],
    # round 7: two coordinates from a generated table (issue 17's brief, eom2c)
    "eom coupled-blocks": [str(LIMIT / "eom_coupled.py")],
    # round 8: a unit on each matrix entry, from the same table (issue 17's brief, eom2d)
    "eom pendulum-on-sliding-block": [str(LIMIT / "eom_sliding.py")],
    # round 10: an equilibrium the values move, a unit on each matrix entry (issue 17)
    "eom block-disk-springs": [str(LIMIT / "eom_block_disk.py")],
    # round 14: the two-coordinate table's closed forms outside the scene's domain
    "eom disk-on-swinging-bar": [str(LIMIT / "eom_disk_bar.py")],
    "eom spring-coupled-pendulums": [str(LIMIT / "eom_spring_pendulums.py")],
    # round 7: inverse rows on columns (issue 17's brief, rigidinv)
    "coriolis Earth inverse vr": [str(LIMIT / "coriolis_earth_inverse.py")],
    # round 8: a bracketed inverse on columns (issue 17's brief, rigidbracket)
    "rigid-body inverse": [str(LIMIT / "rigid_body_inverse.py")],
    # round 10: the drum's inertia from its angular acceleration (issue 17)
    "rigid-body drum J_A inverse": [str(LIMIT / "rigid_drum_inverse.py")],
    # round 8: a motion in time and a nested spring network (issue 17's brief, springnest)
    "coriolis over times": [str(LIMIT / "coriolis_time.py")],
    "spring-series nested group with a shared EI": [str(LIMIT / "spring_nested.py")],
}
GOAL_RATIO, GOAL_MB = 2.0, 100


def cases(only: str | None = None):
    """(label, dyncalc argv after the program, header, row maker, limit argv) of each case."""
    for label, argv, header, make in CASES:
        if label in LIMITS and (only is None or only in label):
            yield label, argv, header, make, LIMITS[label]


def commands(argv, limit, path: Path, as_json: bool) -> tuple[list[str], list[str]]:
    """(dyncalc's argv, the limit script's argv) for one file."""
    flag = ["--json"] if as_json else []
    return ([*dyncalc(), *argv, "--batch", str(path), *flag],
            [sys.executable, *limit[:1], *limit[1:], str(path), *flag])


def digest(path: str) -> str:
    sha = hashlib.sha256()
    with open(path, "rb") as f:
        while block := f.read(1 << 20):
            sha.update(block)
    return sha.hexdigest()


def same_output(mine: list[str], theirs: list[str], folder: Path) -> bool:
    spawn(mine, stdout=str(folder / "mine.out"))
    spawn(theirs, stdout=str(folder / "theirs.out"))
    return digest(str(folder / "mine.out")) == digest(str(folder / "theirs.out"))


def sizes_text(rows: int, repeat: int, memory_rows: int) -> str:
    return (f"{rows:,} rows timed (median of {repeat} interleaved runs, start-up included), "
            f"{memory_rows:,} rows for peak memory")


def header_text(args) -> str:
    return (f"{machine()}; command: `python benchmarks/limits.py {' '.join(sys.argv[1:])}`; "
            f"{sizes_text(args.rows, args.repeat, args.memory_rows)}.")


def parser(description: str = __doc__.split("\n")[0]) -> argparse.ArgumentParser:
    """The options of the batch part (benchmarks/done_when.py adds its own to these)."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--rows", type=int, default=1_000_000)
    parser.add_argument("--memory-rows", type=int, default=10_000_000)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--quick", action="store_true", help="10^5 rows timed, 10^6 for memory")
    parser.add_argument("--only", help="the cases whose label holds this text")
    parser.add_argument("--out", type=Path)
    return parser


def settle(args) -> None:
    """``--quick``: the small sizes."""
    if args.quick:
        args.rows, args.memory_rows, args.repeat = 100_000, 1_000_000, 3


def table(args) -> tuple[list[str], str]:
    """(the Markdown table's lines, printed as they come, the footer) of every case: dyncalc
    and its limit script at ``args.rows`` rows, peak memory at ``args.memory_rows``."""
    lines = ["| command | output | dyncalc (s) | limit (s) | ratio | peak memory at "
             f"{args.memory_rows:.0e} rows (MB) | goal met |",
             "| --- | --- | ---: | ---: | ---: | ---: | --- |"]
    print("\n".join(lines), flush=True)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for label, argv, header, make, limit in cases(args.only):
            path = write_file(folder, label, header, make, args.rows)
            big = write_file(folder, label, header, make, args.memory_rows)
            for as_json in (False, True):
                mine, theirs = commands(argv, limit, path, as_json)
                if not same_output(mine, theirs, folder):
                    raise SystemExit(f"{label}: the limit script's output differs from "
                                     f"dyncalc's: {' '.join(theirs)}")
                walls, limits = [], []
                for _ in range(args.repeat):  # interleaved: load drifts hit both alike
                    walls.append(spawn(mine).wall)
                    limits.append(spawn(theirs).wall)
                wall, floor = statistics.median(walls), statistics.median(limits)
                memory = spawn(commands(argv, limit, big, as_json)[0]).peak_mb
                ok = wall / floor <= GOAL_RATIO and memory <= GOAL_MB
                lines.append(f"| {label} | {'JSON lines' if as_json else 'CSV'} | "
                             f"{wall:.2f} | {floor:.2f} | {wall / floor:.2f}x | "
                             f"{memory:.0f} | {'yes' if ok else 'no'} |")
                print(lines[-1], flush=True)
            big.unlink(missing_ok=True)  # the same file when --rows = --memory-rows
            path.unlink(missing_ok=True)
    footer = (f"Load average {load()} at the end. Goal: ratio <= {GOAL_RATIO}x, "
              f"memory <= {GOAL_MB} MB.")
    return lines, footer


def write(path: Path, top: str, lines: list[str], footer: str) -> None:
    path.write_text("# Batch mode against the limit scripts\n\n" + top + "\n\n"
                    + "\n".join(lines) + "\n\n" + footer + "\n")


def main() -> None:
    args = parser().parse_args()
    settle(args)
    top = header_text(args)
    print(top, flush=True)
    lines, footer = table(args)
    print(footer)
    if args.out:
        write(args.out, top, lines, footer)


if __name__ == "__main__":
    main()
