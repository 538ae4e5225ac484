"""One-off start-up: dyncalc against the floor of its stack, measured side by side.

The floor is ``python -c`` importing pint and numpy, loading the registry from pint's cache and
computing one quantity: what dyncalc's stack costs. dyncalc's entry point pauses the cyclic
garbage collector while that stack loads (and freezes what it made before exit), which saves
about 5 % of the floor; a second floor run the same way (``gc.disable()`` ... ``gc.freeze()``)
shows what dyncalc's own code costs on top. Each round runs
every command once, in a fresh random order, so the machine's drift and any order effect hit
them alike; the tables give, per command, the median wall time and CPU time (user + system of
the child) with their interquartile ranges, and the paired ratio to the floor: the median over
rounds of (this command's time / the floor's time in the same round), with its IQR.

GNU units and qalc (``apt-get install units qalc``), when installed, do the same calculation
(omega = sqrt(k/m) for k = 100 N/m, m = 2 kg) for comparison; they are skipped when absent.
The one-off (the console script, which answers it on the quick path, :mod:`dyncalc.quick`) is
also run with an empty pint cache (``DYNCALC_CACHE_DIR`` a fresh empty folder each run) and an
unwritable one (a read-only folder, ``/proc`` when running as root), and so is the full path
(``dyncalc.cli.main``, which the quick path hands everything else to); one run prints the
one-off's paired wall-time ratio to qalc (the goal of issue 17: at most 1) and to
``python -c pass``, and the cold and unwritable-cache ratios to the warm run (at most 1.2).
The empty and unwritable cache rows read the per-user temporary cache under ``$TMPDIR``
(:func:`dyncalc.units.cache.fallback_folder`), as such runs do once any run has built the
registry on the machine; the full path's "first run on the machine" row empties that one too.

    python benchmarks/startup.py [--rounds 41] [--out benchmarks/results/startup.md]
    python benchmarks/startup.py --before /tmp/old   # also an older checkout, side by side
    python benchmarks/startup.py --instructions      # also valgrind's instruction counts

``--before DIR`` adds the one-off target run from the dyncalc package in DIR (a checkout of an
earlier commit, e.g. ``git archive HEAD~3 | tar -x -C /tmp/old``; put first on PYTHONPATH), in
the same paired rounds, so before and after are measured under the same conditions.

Run it with the project's virtual environment's python (dyncalc installed in it). The children
run without ``PYTHONDONTWRITEBYTECODE``, so dyncalc's modules load from their bytecode cache,
as pint's and numpy's do (an installed program has its bytecode compiled at install time).
"""
from __future__ import annotations

import argparse
import os
import platform
import random
import shutil
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BIN = Path(sys.executable).parent
sys.path.insert(0, str(ROOT / "benchmarks"))

from _timing import child_env as shared_env, quartiles, spawn  # noqa: E402
FLOOR = ("import pint, numpy; u = pint.UnitRegistry(cache_folder=':auto:'); "
         "print((u.Quantity(100, 'N/m') / u.Quantity(2, 'kg')) ** 0.5)")
FLOOR_NAME = "floor: python -c 'import pint, numpy; registry; one quantity'"
#: The floor run the way dyncalc's entry point runs its stack: the cyclic collector paused and
#: what was made frozen before exit (so the ratio to it is dyncalc's own cost alone).
QUIET_FLOOR = f"import gc; gc.disable(); {FLOOR}; gc.freeze()"
QUIET_FLOOR_NAME = ("floor, collector paused as dyncalc's entry pauses it (`gc.disable()` ... "
                    "`gc.freeze()`)")
TARGET = "dyncalc natural-frequency --k 100N/m --m 2kg --json"
COMPLETE_VAR = "_DYNCALC_COMPLETE"
DAMPING = "damping-ratio --c 10N*s/m --k 1kN/m --m 2kg --value zeta"
PASS = "python -c pass"
QALC = "qalc -t 'sqrt((100 N/m)/(2 kg)) to 1/s'"
FULL = "full path (dyncalc.cli.main): natural-frequency --k 100N/m --m 2kg --json"
EMPTY, UNWRITABLE = ", empty cache (a fresh folder each run)", ", unwritable cache"
#: the full path on a machine where it never ran: its cache and the per-user temporary one
#: (dyncalc.units.cache.fallback_folder, under $TMPDIR) both empty
FIRST = ", first run on the machine (empty cache and $TMPDIR each run)"
CACHE_ENV = "DYNCALC_CACHE_DIR"
#: the folders made for the cache rows, removed at the end
MADE: list[str] = []


def fresh_folder() -> str:
    """A new empty folder (the cache of a first run)."""
    import tempfile

    MADE.append(tempfile.mkdtemp(prefix="dyncalc-cold-"))
    return MADE[-1]


def unwritable_folder() -> str:
    """An empty folder nothing can be written to: read-only, or ``/proc`` for root (who
    writes through permissions)."""
    import tempfile

    folder = tempfile.mkdtemp(prefix="dyncalc-ro-")
    MADE.append(folder)
    os.chmod(folder, 0o555)
    return "/proc" if os.access(folder, os.W_OK) else folder


def commands(before: str | None = None) -> dict[str, list[str]]:
    """name -> argv; the first is the floor, the second the target of issue 8."""
    script = BIN / "dyncalc"
    dyncalc = [str(script)] if script.exists() else [sys.executable, "-m", "dyncalc"]
    one_off = ["natural-frequency", "--k", "100N/m", "--m", "2kg", "--json"]
    full = [sys.executable, "-c", "from dyncalc.cli import main; main()", *one_off]
    damping = ["damping-ratio", "--c", "10N*s/m", "--k", "1kN/m", "--m", "2kg", "--value",
               "zeta"]
    readonly = unwritable_folder()
    cmds = {
        FLOOR_NAME: [sys.executable, "-c", FLOOR],
        TARGET: [*dyncalc, *one_off],
        TARGET + EMPTY: ([*dyncalc, *one_off], {CACHE_ENV: fresh_folder}),
        TARGET + UNWRITABLE: ([*dyncalc, *one_off], {CACHE_ENV: readonly}),
        FULL: full,
        FULL + EMPTY: (full, {CACHE_ENV: fresh_folder}),
        FULL + UNWRITABLE: (full, {CACHE_ENV: readonly}),
        FULL + FIRST: (full, {CACHE_ENV: fresh_folder, "TMPDIR": fresh_folder}),
        PASS: [sys.executable, "-c", "pass"],
        "python -m dyncalc natural-frequency --k 100N/m --m 2kg --json": [
            sys.executable, "-m", "dyncalc", "natural-frequency", "--k", "100N/m", "--m", "2kg",
            "--json"],
        "dyncalc spring-series 200N/m 300N/m --value k_eq": [
            *dyncalc, "spring-series", "200N/m", "300N/m", "--value", "k_eq"],
        # the full path through the console entry, which hides dask from pint (round 10),
        # and the same without it (dyncalc.cli.main): apart where dask is installed
        DAMPING + " (console entry: dask hidden from pint)": [*dyncalc, *damping],
        DAMPING + " (dyncalc.cli.main: dask not hidden)": [
            sys.executable, "-c", "from dyncalc.cli import main; main()", *damping],
        "dyncalc --help": [*dyncalc, "--help"],
        "dyncalc shell completion (`_DYNCALC_COMPLETE=bash_complete`)": (dyncalc, {
            COMPLETE_VAR: "bash_complete", "COMP_WORDS": "dyncalc spring-", "COMP_CWORD": "1"}),
        "python -c 'import pint, numpy' (imports only)": [sys.executable, "-c",
                                                          "import pint, numpy"],
        QUIET_FLOOR_NAME: [sys.executable, "-c", QUIET_FLOOR],
    }
    if before:
        cmds[f"before ({before}): {TARGET}"] = (
            [*dyncalc, "natural-frequency", "--k", "100N/m", "--m", "2kg", "--json"],
            {"PYTHONPATH": before})
    units = shutil.which("units")
    if units:
        cmds["GNU units -t 'sqrt(100 N/m / (2 kg))' 1/s"] = [
            units, "-t", "sqrt(100 N/m / (2 kg))", "1/s"]
    qalc = shutil.which("qalc")
    if qalc:
        cmds[QALC] = [
            qalc, "-t", "sqrt((100 N/m)/(2 kg)) to 1/s"]
    return cmds


def child_env() -> dict[str, str]:
    env = shared_env(NO_COLOR="1")
    env.pop(COMPLETE_VAR, None)
    return env


def run_once(argv, env: dict[str, str]) -> tuple[float, float]:
    """(wall seconds, CPU seconds of the child: user + system); ``argv`` may come with extra
    environment variables, as ``(argv, {NAME: VALUE})``."""
    if isinstance(argv, tuple):
        argv, extra = argv
        env = {**env, **resolved(extra)}
    sample = spawn(argv, env)
    return sample.wall, sample.cpu


def resolved(extra: dict) -> dict[str, str]:
    """Extra environment variables, a callable value called now (a fresh folder a run)."""
    return {name: value() if callable(value) else value for name, value in extra.items()}


LOAD = [0.0]


def measure(cmds: dict[str, list[str]], rounds: int, seed: int = 8):
    LOAD[0] = os.getloadavg()[0]
    env = child_env()
    for argv in cmds.values():  # warm up: pint's registry cache, bytecode, the page cache
        for _ in range(2):
            run_once(argv, env)
    rng = random.Random(seed)
    wall: dict[str, list[float]] = {name: [] for name in cmds}
    cpu: dict[str, list[float]] = {name: [] for name in cmds}
    names = list(cmds)
    for _ in range(rounds):
        rng.shuffle(names)
        for name in names:
            w, c = run_once(cmds[name], env)
            wall[name].append(w)
            cpu[name].append(c)
    return wall, cpu


def table(cmds, wall, cpu, rounds: int) -> str:
    floor_wall, floor_cpu = wall[FLOOR_NAME], cpu[FLOOR_NAME]
    lines = [f"{rounds} paired rounds; Python {platform.python_version()}, "
             f"{os.cpu_count()} CPUs, {platform.machine()}; "
             f"{time.strftime('%Y-%m-%d %H:%M')}; load average {LOAD[0]:.2f} at the start "
             f"(other processes on the machine widen the spread)",
             "",
             "| command | wall median (ms) | wall IQR (ms) | CPU median (ms) | "
             "wall / floor (paired median) | ratio IQR | CPU / floor (paired median) |",
             "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for name in cmds:
        q1, med, q3 = quartiles(wall[name])
        ratios = [a / b for a, b in zip(wall[name], floor_wall)]
        r1, rmed, r3 = quartiles(ratios)
        cpu_ratio = statistics.median(a / b for a, b in zip(cpu[name], floor_cpu))
        lines.append(f"| `{name}` | {1000 * med:.0f} | {1000 * (q3 - q1):.0f} | "
                     f"{1000 * statistics.median(cpu[name]):.0f} | {rmed:.3f} | "
                     f"{r3 - r1:.3f} | {cpu_ratio:.3f} |")
    return "\n".join(lines)


def instructions(cmds, names: list[str]) -> dict[str, int]:
    """Instructions each command executes, counted by valgrind's callgrind (load-independent,
    unlike wall time; about 60 times slower): one run each, OpenBLAS on one thread and a
    fixed hash seed so that the counts repeat."""
    import subprocess

    env = {**child_env(), "OPENBLAS_NUM_THREADS": "1", "PYTHONHASHSEED": "0"}
    counts = {}
    for name in names:
        argv = cmds[name]
        extra = {}
        if isinstance(argv, tuple):
            argv, extra = argv
        done = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null",
                               *argv], env={**env, **resolved(extra)}, capture_output=True,
                              text=True,
                              check=True)
        counts[name] = int(done.stderr.split("Collected :")[1].split()[0])
    return counts


def instruction_table(counts: dict[str, int]) -> str:
    floor = counts[FLOOR_NAME]
    lines = ["| command | instructions (millions) | / floor |", "| --- | ---: | ---: |"]
    lines += [f"| `{name}` | {count / 1e6:,.0f} | {count / floor:.3f} |"
              for name, count in counts.items()]
    return "\n".join(lines)


def goal_lines(cmds, paired) -> str:
    """Issue 17's ratios (paired medians of the wall times): the one-off to qalc and to
    ``python -c pass``; cold and unwritable caches to the warm run, quick and full path."""
    lines = []
    if QALC in cmds:
        lines.append(f"- one-off / qalc: **{paired(TARGET, QALC):.3f}** (goal: at most 1.0)")
    lines.append(f"- one-off / `python -c pass`: **{paired(TARGET, PASS):.3f}**")
    for name in (TARGET, FULL):
        label = "one-off" if name == TARGET else "full path"
        lines.append(f"- {label}, empty cache / warm: {paired(name + EMPTY, name):.3f}; "
                     f"unwritable cache / warm: {paired(name + UNWRITABLE, name):.3f} "
                     "(goal: at most 1.2)")
    lines.append(f"- full path, first run on the machine / warm: {paired(FULL + FIRST, FULL):.3f}"
                 " (pint builds its registry once per user and boot)")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=41)
    parser.add_argument("--before", metavar="DIR",
                        help="also time the one-off from the dyncalc package in DIR")
    parser.add_argument("--out", default=str(ROOT / "benchmarks" / "results" / "startup.md"),
                        help="markdown file for the table ('-': do not write one)")
    parser.add_argument("--instructions", action="store_true",
                        help="also count the instructions of the floors and the one-off "
                             "(needs valgrind: apt-get install valgrind)")
    args = parser.parse_args()
    try:
        run(args)
    finally:
        for folder in MADE:
            os.chmod(folder, 0o755)
            shutil.rmtree(folder, ignore_errors=True)


def run(args) -> None:
    cmds = commands(args.before)
    missing = [tool for tool in ("units", "qalc") if not shutil.which(tool)]
    args.rounds = max(2, args.rounds)  # quartiles need two
    wall, cpu = measure(cmds, args.rounds)
    text = table(cmds, wall, cpu, args.rounds)
    def paired(name: str, base: str) -> float:
        return statistics.median(a / b for a, b in zip(wall[name], wall[base]))

    text += "\n\n" + goal_lines(cmds, paired)
    text += (f"\n\nOne-off / floor, paired median of the rounds: {paired(TARGET, FLOOR_NAME):.3f}; "
             "one-off / the floor with the collector paused as dyncalc's entry pauses it "
             f"(what dyncalc's own code costs): {paired(TARGET, QUIET_FLOOR_NAME):.3f}")
    if args.before:
        old = wall[f"before ({args.before}): {TARGET}"]
        ratio = statistics.median(a / b for a, b in zip(wall[TARGET], old))
        text += (f"\n\nAfter / before, paired median of the rounds: {ratio:.3f} "
                 f"(`{TARGET}`; before = the package in {args.before})")
    if args.instructions:
        if shutil.which("valgrind"):
            names = [FLOOR_NAME, QUIET_FLOOR_NAME, TARGET, TARGET + EMPTY,
                     TARGET + UNWRITABLE, FULL, FULL + EMPTY, FULL + UNWRITABLE, FULL + FIRST,
                     PASS]
            names += [QALC] if QALC in cmds else []
            names += [name for name in cmds if name.startswith("before (")]
            text += ("\n\nInstructions executed (valgrind callgrind, one run each; they do not "
                     "depend on the machine's load):\n\n"
                     + instruction_table(instructions(cmds, names)))
        else:
            text += "\n\n(valgrind not installed: no instruction counts)"
    if missing:
        text += (f"\n\n(not installed, skipped: {', '.join(missing)}; "
                 "`apt-get install units qalc`)")
    print(text)
    if args.out != "-":
        out = Path(args.out)
        out.parent.mkdir(parents=True, exist_ok=True)
        command = " ".join(["python benchmarks/startup.py", *sys.argv[1:]])
        out.write_text(f"## Start-up (`{command}`)\n\n" + text + "\n", encoding="utf-8")
        print(f"\nwritten to {out}", file=sys.stderr)


if __name__ == "__main__":
    main()
