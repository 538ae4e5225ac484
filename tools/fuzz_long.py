"""The long fuzz run for maintainers (issue 9): the strategies of ``tests/test_fuzz.py``, many
more cases, and a table of what happened instead of a stop at the first broken rule.

    python tools/fuzz_long.py --examples 10000                 # every command
    python tools/fuzz_long.py --examples 20000 --command coriolis
    python tools/fuzz_long.py --examples 2000 --seed 7         # another sample
    python tools/fuzz_long.py --ci                             # count the CI suite's cases

Each case runs ``dyncalc ARGS`` in-process and is judged by the same rules as the CI suite
(``judge`` in tests/test_fuzz.py). The run prints, per command: the cases, how many ended with
exit 0, 1 and 2, how many broke a rule, and the slowest case with its time; then the refusals
(exit 2) by kind of message, and for every broken rule the first few argument lists that broke
it. The exit status is 1 when any case broke a rule, else 0. ``--seed`` makes a run
reproducible (the default seed is 0; a run with the same seed, hypothesis version, grammar and
dyncalc draws the same cases). One case in ten takes the terminal (rich) output path, as in CI.
"""
from __future__ import annotations

import argparse
import collections
import re
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))

from hypothesis import HealthCheck, Phase, seed  # noqa: E402

import test_fuzz as fuzz  # noqa: E402

#: DYNCALC_FUZZ_ARGV_LOG=FILE: append the whole argument list of every broken case to FILE
#: (the tables cut them short).
ARGV_LOG = __import__("os").environ.get("DYNCALC_FUZZ_ARGV_LOG")

#: Kinds of refusal, by the first pattern their ``Error:`` line matches.
REFUSAL_KINDS = [
    ("internal error (a bug)", r"internal error"),
    ("usage (click: option, argument)", r"No such option|Missing|requires an argument|"
                                        r"unexpected extra argument|Invalid value|"
                                        r"does not take a value|No such command|"
                                        r"Option '.*' requires|Got unexpected|is not a valid"),
    ("too long (length limit)", r"characters long; dyncalc reads at most"),
    ("too deep (nesting limit)", r"nested more than"),
    ("power refused (chained or unit power)", r"chained powers|raised to the power"),
    ("overflow / underflow", r"overflow|underflow"),
    ("NaN or infinity refused", r"NaN|must be finite"),
    ("silent misreading refused", r"comma|hexadecimal|leading zero|no number|comments|"
                                  r"invisible or control|uncertaint|side by side|"
                                  r"digit separators|not an ASCII digit"),
    ("unreadable text (other)", r"cannot read"),
    ("wrong dimension or unit kind", r"must be an? .*\[|must be a pure number|"
                                     r"is an angular rate|is a frequency in cycles|"
                                     r"not a unit of|is a pure number, not an angle"),
    ("out of range", r"must be positive|must not be|must be at least|must be between|"
                     r"must be a whole number|must end in|cannot write"),
    ("unknown name (scene, result, element)", r"there is no|unknown|does not have|"
                                              r"not a parameter|the scenes are"),
    ("combination refused (missing, twice, conflicting)", r"needs|given twice|cannot be|"
                                                          r"give |only one|either|not both|"
                                                          r"with --|without"),
    ("other refusal", r""),
]


def refusal_kind(line: str) -> str:
    for name, pattern in REFUSAL_KINDS:
        if re.search(pattern, line):
            return name
    return "other refusal"


def problem_kind(problem: str) -> str:
    """A problem message without its particulars (for grouping)."""
    kind = re.sub(r"U\+[0-9A-F]{4}(, U\+[0-9A-F]{4})*", "U+....", problem)
    kind = re.sub(r"took [0-9.]+ s", "took too long", kind)
    kind = re.sub(r"stray stderr line: .*", "stray stderr line", kind)
    kind = re.sub(r"Python warning would reach stderr: (\w+): .*\((.*?):\d+\)",
                  r"Python warning would reach stderr: \1 (\2)", kind)
    kind = re.sub(r"stdout is not strict JSON: .*", "stdout is not strict JSON", kind)
    return kind


class Tally:
    def __init__(self, command: str):
        self.command = command
        self.cases = 0
        self.exits = collections.Counter()
        self.broken = 0
        self.slowest = (0.0, None)
        self.refusals = collections.Counter()
        self.problems: dict[str, list] = collections.defaultdict(list)
        self.problem_counts = collections.Counter()
        self.seconds = 0.0
        self.retimed: list = []   # (first time, second time, argv) of cases run twice

    def add(self, out) -> None:
        self.cases += 1
        self.seconds += out.seconds
        self.exits[out.exit_code] += 1
        if out.retimed is not None:
            self.retimed.append((out.retimed, out.seconds, out.argv))
        if out.seconds > self.slowest[0]:
            self.slowest = (out.seconds, out.argv)
        if out.exit_code == 2 and out.stderr:
            self.refusals[refusal_kind(out.stderr.splitlines()[0])] += 1
        if out.problems:
            self.broken += 1
            if ARGV_LOG:  # every broken case's whole argument list, to replay it
                with open(ARGV_LOG, "a", encoding="utf-8") as log:
                    log.write(f"{out.argv!r}\t{out.problems!r}\n")
            for problem in dict.fromkeys(problem_kind(p) for p in out.problems):
                self.problem_counts[problem] += 1
                seen = [o.argv for o in self.problems[problem]]
                if len(seen) < 3 and out.argv not in seen:
                    self.problems[problem].append(out)


def run_command(command: str, examples: int | None, seed_value: int | None,
                progress: bool) -> Tally:
    """Run ``examples`` cases of ``command``; ``examples=None`` runs the CI suite's own cases
    (its budget and its derandomized draw), ``seed_value`` seeds any other run."""
    tally = Tally(command)
    started = time.perf_counter()

    def check(out):
        tally.add(out)
        if progress and tally.cases % 1000 == 0:
            rate = tally.cases / (time.perf_counter() - started)
            print(f"  {command}: {tally.cases} cases ({rate:.0f}/s)", file=sys.stderr,
                  flush=True)

    if examples is None:  # the CI cases, run through to the end
        budget = (fuzz.CI_MIXED_EXAMPLES if command == fuzz.MIXED
                  else fuzz.CI_EXAMPLES[command])
        fuzz.fuzz_runner(command, budget, check)()
    else:
        runner = fuzz.fuzz_runner(command, examples, check, derandomize=False,
                                  phases=[Phase.generate],
                                  suppress_health_check=list(HealthCheck))
        seed(seed_value)(runner)()
    return tally


def label(command: str) -> str:
    return "mixed (any command)" if command == fuzz.MIXED else command


def show_argv(argv, limit: int = 160) -> str:
    text = repr(argv)
    return text if len(text) <= limit else text[:limit] + "...]"


def report(tallies: list[Tally], wall: float, title: str) -> str:
    lines = [f"dyncalc fuzz: {title}: {sum(t.cases for t in tallies)} cases in {wall:.0f} s",
             ""]
    header = ("| command | cases | exit 0 | exit 1 | exit 2 | other | broke a rule | "
              "slowest (s) | slowest case |")
    lines += [header, "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |"]
    for t in tallies:
        other = t.cases - t.exits[0] - t.exits[1] - t.exits[2]
        lines.append(f"| {label(t.command)} | {t.cases} | {t.exits[0]} | {t.exits[1]} | "
                     f"{t.exits[2]} | {other} | {t.broken} | {t.slowest[0]:.3f} | "
                     f"`{show_argv(t.slowest[1], 90)}` |")
    total = Tally("all")
    for t in tallies:
        total.cases += t.cases
        total.exits.update(t.exits)
        total.broken += t.broken
        total.refusals.update(t.refusals)
        total.problem_counts.update(t.problem_counts)
        if t.slowest[0] > total.slowest[0]:
            total.slowest = t.slowest
    other = total.cases - total.exits[0] - total.exits[1] - total.exits[2]
    lines.append(f"| **all** | {total.cases} | {total.exits[0]} | {total.exits[1]} | "
                 f"{total.exits[2]} | {other} | {total.broken} | {total.slowest[0]:.3f} | |")
    lines += ["", "Refusals (exit 2) by kind of message:", ""]
    kinds = [name for name, _ in REFUSAL_KINDS]
    lines.append("| kind | " + " | ".join(label(t.command) for t in tallies) + " |")
    lines.append("| --- |" + " ---: |" * len(tallies))
    for kind in kinds:
        row = [t.refusals.get(kind, 0) for t in tallies]
        if any(row):
            lines.append(f"| {kind} | " + " | ".join(map(str, row)) + " |")
    lines += ["", "Slowest case of each command (seconds, arguments):", ""]
    for t in tallies:
        lines.append(f"* {label(t.command)}: {t.slowest[0]:.3f} s "
                     f"`{show_argv(t.slowest[1], 400)}`")
    retimed = [r for t in tallies for r in t.retimed]
    lines += ["", f"Cases slower than {fuzz.CALL_LIMIT:g} s on the first run, run again "
                  f"({len(retimed)}; the faster time counts):", ""]
    for first, second, argv in retimed[:20]:
        lines.append(f"* {first:.3f} s, then {second:.3f} s: `{show_argv(argv, 200)}`")
    lines += ["", "Broken rules:" if total.problem_counts else "Broken rules: none.", ""]
    for kind, count in total.problem_counts.most_common():
        per = ", ".join(f"{label(t.command)} {t.problem_counts[kind]}" for t in tallies
                        if t.problem_counts.get(kind))
        lines.append(f"* {kind}: {count} cases ({per})")
        shown = [o for t in tallies for o in t.problems.get(kind, [])][:3]
        for out in shown:
            err = out.stderr.strip().splitlines()[:1]
            lines.append(f"    - `{show_argv(out.argv)}` -> exit {out.exit_code}"
                         + (f", stderr {err[0][:150]!r}" if err else "")
                         + (f", {out.exception.strip().splitlines()[-1][:120]}"
                            if out.exception else ""))
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--examples", type=int, default=10_000,
                        help="cases per command (default 10000)")
    parser.add_argument("--command", action="append", choices=[*fuzz.COMMANDS, fuzz.MIXED],
                        help="only this command (repeatable; '*' is the mixed-words run); "
                             "default: every command")
    parser.add_argument("--seed", type=int, default=0, help="random seed (default 0)")
    parser.add_argument("--ci", action="store_true",
                        help="run the CI suite's own cases (tests/test_fuzz.py budget and "
                             "draw) through to the end and count them; ignores --examples "
                             "and --seed")
    parser.add_argument("--quiet", action="store_true", help="no progress on stderr")
    args = parser.parse_args(argv)
    commands = args.command or (fuzz.COMMANDS + [fuzz.MIXED] if args.ci else fuzz.COMMANDS)
    fuzz.warm_up()
    started = time.perf_counter()
    tallies = []
    for command in commands:
        if not args.quiet:
            print(f"{command}: {'CI cases' if args.ci else f'{args.examples} examples'} ...",
                  file=sys.stderr, flush=True)
        tallies.append(run_command(command, None if args.ci else args.examples, args.seed,
                                   not args.quiet))
    title = ("the CI suite's cases (tests/test_fuzz.py)" if args.ci else
             f"{args.examples} examples per command, seed {args.seed}")
    print(report(tallies, time.perf_counter() - started, title))
    return 1 if any(t.broken for t in tallies) else 0


if __name__ == "__main__":
    sys.exit(main())
