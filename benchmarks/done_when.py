"""Issue 17's "Done when", in one run on one machine: every batch case against its limit
script, and the one-off against qalc and ``python -c pass``.

One process tree, one part after the other, one report:

1. **Batch** (:mod:`limits`): every command's wall time at 10^6 rows against its hand-written
   numpy/polars limit script (median of ``--repeat`` interleaved runs, start-up included,
   outputs compared byte for byte first) and its peak memory at 10^7 rows, CSV and JSON lines.
   Goal: ratio at most 2, memory at most 100 MB.
2. **One-off**: ``dyncalc natural-frequency --k "100 N/m" --m "2 kg"`` (the plain table) and
   the same with ``--value f``, run from a non-editable install of this checkout in a fresh
   virtual environment under /tmp (as a user installs it; ``--venv DIR`` reuses one), stdout
   to /dev/null (not a terminal, so the quick path answers), against qalc computing the same
   (``qalc "sqrt((100 N/m)/(2 kg))"``, ``qalc -t "sqrt((100 N/m)/(2 kg))/(2*pi) to Hz"``)
   and ``python -c pass``, in ``--rounds`` rounds, each running every command once in a fresh
   random order; the ratios are paired medians (each round's ratio, then the median). Goal:
   one-off / qalc at most 1.0. ``--instructions`` adds valgrind's instruction counts (they do
   not depend on the load).

The report starts with the machine, the load, the date and the command, and ends with the
load at the end; ``--out`` writes it as Markdown (run_all.py: benchmarks/results/done_when.md)
and ``--limits-out`` the batch part alone in limits.py's form.

    python benchmarks/done_when.py [--quick] [--rows N] [--memory-rows N] [--repeat N]
                                   [--only TEXT] [--rounds 21] [--venv DIR] [--instructions]
                                   [--out FILE] [--limits-out FILE]

``--quick``: 10^5 rows timed, 10^6 for memory, 7 one-off rounds. Run it with the project's
virtual environment's python (the ``bench`` extra installed), on an otherwise quiet machine.
"""
from __future__ import annotations

import math
import random
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import limits  # noqa: E402
from _timing import child_env, load, machine, paired_median, quartiles, spawn  # noqa: E402

ONE_OFF = ["natural-frequency", "--k", "100 N/m", "--m", "2 kg"]
#: name -> (argv after the program, or None for ``python -c pass``; the program: dyncalc,
#: qalc or python)
ONE_OFFS = {
    'dyncalc natural-frequency --k "100 N/m" --m "2 kg"': ("dyncalc", ONE_OFF),
    'dyncalc natural-frequency --k "100 N/m" --m "2 kg" --value f': (
        "dyncalc", [*ONE_OFF, "--value", "f"]),
    'qalc "sqrt((100 N/m)/(2 kg))"': ("qalc", ["sqrt((100 N/m)/(2 kg))"]),
    'qalc -t "sqrt((100 N/m)/(2 kg))/(2*pi) to Hz"': (
        "qalc", ["-t", "sqrt((100 N/m)/(2 kg))/(2*pi) to Hz"]),
    "python -c pass": ("python", ["-c", "pass"]),
}
#: (one-off, its qalc twin)
PAIRS = list(zip(list(ONE_OFFS)[:2], list(ONE_OFFS)[2:4]))
PASS = "python -c pass"
GOAL_QALC = 1.0


def fresh_venv(folder: Path) -> Path:
    """A new virtual environment in ``folder`` with this checkout installed into it as a
    user installs it (``pip install .``, not editable); its ``bin``."""
    subprocess.run([sys.executable, "-m", "venv", str(folder)], check=True)
    done = subprocess.run([str(folder / "bin" / "python"), "-m", "pip", "install", "-q",
                           "--disable-pip-version-check", str(ROOT)],
                          capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"pip install {ROOT} into {folder} failed:\n{done.stderr[-2000:]}")
    return folder / "bin"


def programs(bin_dir: Path) -> dict[str, list[str]]:
    """name -> full argv of each one-off command (qalc's left out when it is not installed)."""
    exe = {"dyncalc": str(bin_dir / "dyncalc"), "python": str(bin_dir / "python"),
           "qalc": shutil.which("qalc")}
    if not Path(exe["dyncalc"]).exists():
        raise SystemExit(f"{bin_dir} holds no dyncalc console script")
    return {name: [exe[program], *argv] for name, (program, argv) in ONE_OFFS.items()
            if exe[program]}


def check_answer(cmds: dict[str, list[str]]) -> None:
    """The installed one-off answers ``f = sqrt(k/m) / (2 pi)`` (a benchmark of a wrong
    answer, or of an error message, would be worthless)."""
    argv = cmds[list(ONE_OFFS)[1]]
    done = subprocess.run(argv, capture_output=True, text=True)
    expected = math.sqrt(100.0 / 2.0) / (2.0 * math.pi)
    if done.returncode != 0 or abs(float(done.stdout or "nan") / expected - 1) > 1e-15:
        raise SystemExit(f"{' '.join(argv)} printed {done.stdout!r} (exit "
                         f"{done.returncode}), not f = {expected!r}: {done.stderr.strip()}")


def rounds_of(cmds: dict[str, list[str]], rounds: int, seed: int = 17) -> dict[str, list]:
    """name -> its wall times, one per round; every round runs each command once, in a
    fresh random order (after two warm-up runs each: bytecode and the page cache)."""
    env = child_env(NO_COLOR="1")
    for argv in cmds.values():
        for _ in range(2):
            spawn(argv, env)
    rng = random.Random(seed)
    names = list(cmds)
    wall: dict[str, list[float]] = {name: [] for name in cmds}
    for _ in range(rounds):
        rng.shuffle(names)
        for name in names:
            wall[name].append(spawn(cmds[name], env).wall)
    return wall


def instructions(argv: list[str]) -> int:
    """Instructions one run executes (valgrind callgrind; one BLAS thread, a fixed hash
    seed, so that the count repeats)."""
    env = child_env(NO_COLOR="1", OPENBLAS_NUM_THREADS="1", PYTHONHASHSEED="0")
    done = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                           *argv], env=env, capture_output=True, text=True, check=True)
    return int(done.stderr.split("Collected :")[1].split()[0])


def one_off_table(cmds, wall, counts: dict[str, int] | None) -> list[str]:
    lines = ["| command | wall median (ms) | wall IQR (ms) | / `python -c pass` (paired) |"
             + (" instructions (millions) |" if counts else ""),
             "| --- | ---: | ---: | ---: |" + (" ---: |" if counts else "")]
    for name in cmds:
        q1, med, q3 = quartiles(wall[name])
        line = (f"| `{name}` | {1000 * med:.1f} | {1000 * (q3 - q1):.1f} | "
                f"{paired_median(wall[name], wall[PASS]):.2f} |")
        if counts:
            line += f" {counts[name] / 1e6:,.0f} |"
        lines.append(line)
    return lines


def one_off_verdict(cmds, wall) -> list[str]:
    lines = []
    for mine, theirs in PAIRS:
        to_pass = paired_median(wall[mine], wall[PASS])
        if theirs in cmds:
            ratio = paired_median(wall[mine], wall[theirs])
            lines.append(f"- `{mine}`: **{ratio:.3f}** x qalc (`{theirs}`; goal <= "
                         f"{GOAL_QALC}: {'met' if ratio <= GOAL_QALC else 'not met'}), "
                         f"**{to_pass:.2f}** x `python -c pass`")
        else:
            lines.append(f"- `{mine}`: qalc not installed (`apt-get install qalc`), "
                         f"**{to_pass:.2f}** x `python -c pass`")
    return lines


def batch_verdict(rows: list[str]) -> str:
    cells = [row.split(" | ") for row in rows[2:]]
    met = sum(cell[-1].strip(" |") == "yes" for cell in cells)
    worst = max((float(cell[4].rstrip("x")), cell[0].strip("| ") + " " + cell[1])
                for cell in cells)
    memory = max(float(cell[5]) for cell in cells)
    return (f"- batch: {met} of {len(cells)} cases meet both goals; the largest ratio "
            f"{worst[0]:.2f}x ({worst[1]}), the largest peak memory {memory:.0f} MB")


def main() -> None:
    parser = limits.parser(__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=21, help="one-off rounds")
    parser.add_argument("--venv", type=Path,
                        help="an environment with dyncalc installed (default: a fresh one "
                             "under /tmp, this checkout installed into it, removed after)")
    parser.add_argument("--instructions", action="store_true",
                        help="also valgrind's instruction counts of the one-off commands")
    parser.add_argument("--limits-out", type=Path,
                        help="also the batch part alone, in limits.py's form")
    args = parser.parse_args()
    limits.settle(args)
    if args.quick:
        args.rounds = min(args.rounds, 7)
    args.rounds = max(2, args.rounds)
    command = f"python benchmarks/done_when.py {' '.join(sys.argv[1:])}".rstrip()
    top = f"{machine()}; command: `{command}`"
    print(top, flush=True)
    start = time.perf_counter()
    made = None
    try:
        if args.venv is None:
            made = Path(tempfile.mkdtemp(prefix="dyncalc-venv-", dir="/tmp"))
            print(f"installing this checkout into a fresh environment, {made} ...", flush=True)
            bin_dir = fresh_venv(made)
        else:
            bin_dir = args.venv / "bin"
        cmds = programs(bin_dir)
        check_answer(cmds)
        print("\n## Batch against the limit scripts\n", flush=True)
        sizes = limits.sizes_text(args.rows, args.repeat, args.memory_rows)
        rows, batch_footer = limits.table(args)
        print(f"\n## One-off ({args.rounds} paired rounds)\n", flush=True)
        wall = rounds_of(cmds, args.rounds)
        counts = ({name: instructions(argv) for name, argv in cmds.items()}
                  if args.instructions and shutil.which("valgrind") else None)
        table = one_off_table(cmds, wall, counts)
        print("\n".join(table), flush=True)
    finally:
        if made is not None:
            shutil.rmtree(made, ignore_errors=True)
    verdict = [batch_verdict(rows), *one_off_verdict(cmds, wall)]
    where = (f"the one-off from {'a fresh non-editable install' if made else bin_dir.parent}"
             f" ({bin_dir.parent if not made else 'pip install . into a new venv under /tmp'}),"
             " stdout to /dev/null")
    end = f"Load average {load()} at the end; {time.perf_counter() - start:.0f} s in all."
    print("\n## Done when\n\n" + "\n".join(verdict) + "\n\n" + end, flush=True)
    if args.out:
        args.out.write_text(
            "# Issue 17, done when: batch against the limit scripts, one-off against qalc\n\n"
            f"{top}\n\n## Batch against the limit scripts\n\n{sizes}.\n\n" + "\n".join(rows)
            + f"\n\n{batch_footer}\n\n## One-off\n\n{args.rounds} paired rounds, {where}; "
            "each round runs every command once in a fresh random order; ratios are paired "
            "medians.\n\n" + "\n".join(table) + "\n\n## Done when\n\n" + "\n".join(verdict)
            + f"\n\n{end}\n")
    if args.limits_out:
        limits.write(args.limits_out, f"{machine_line(top)}; {sizes} (the batch part of "
                     f"`{command}`).", rows, batch_footer)


def machine_line(top: str) -> str:
    """The header without its command."""
    return top.split("; command:")[0]


if __name__ == "__main__":
    main()
