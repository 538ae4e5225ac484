"""Batch throughput of every command: the vectorised path against the generic (one-off, row by
row) path, side by side in one run.

For each command (and a few scenes) a CSV of random ordinary rows is generated into a
temporary file; dyncalc runs as a child process writing to /dev/null, once on the vectorised
path and once with ``DYNCALC_BATCH_GENERIC=1`` (on fewer rows: the generic path is slow), and
the table gives rows per second of each and their ratio. Wall time is end to end, start-up
included; each figure is the median of ``--repeat`` runs.

    python benchmarks/batch_commands.py [--rows 100000] [--generic-rows 2000] [--repeat 3]
                                        [--only TEXT] [--out benchmarks/results/batch_commands.md]

The inverse rows (``f [Hz],m [kg]``: k solved per row; ``T [s],l`` with ``?``) compare the
closed-form inversion on columns with the one-off's solver row by row.

Run it with the project's virtual environment's python (dyncalc installed in it).
"""
from __future__ import annotations

import argparse
import os
import platform
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BIN = Path(sys.executable).parent

#: (label, argv after ``dyncalc``, header, a function of a Random giving one row's cells)
def _chain(r) -> list[str]:
    """Two masses, two springs (wall, k1, m1, k2, m2): quoted 2x2 cells of bare numbers."""
    m1, m2, k1, k2 = (float(f"{r.uniform(lo, hi):.6g}") for lo, hi in
                      ((0.5, 20), (0.5, 20), (1e2, 1e4), (1e2, 1e4)))
    return [f'"[[{m1!r},0],[0,{m2!r}]]"', f'"[[{k1 + k2!r},{-k2!r}],[{-k2!r},{k2!r}]]"']


def _damped_chain(r) -> list[str]:
    """:func:`_chain` with a proportional damping matrix ``C = a M + b K`` (underdamped)."""
    m1, m2, k1, k2 = (float(f"{r.uniform(lo, hi):.6g}") for lo, hi in
                      ((0.5, 20), (0.5, 20), (1e2, 1e4), (1e2, 1e4)))
    a, b = r.uniform(0.01, 0.05), r.uniform(1e-5, 1e-4)
    c11, c12, c22 = a * m1 + b * (k1 + k2), -b * k2, a * m2 + b * k2
    return [f'"[[{m1!r},0],[0,{m2!r}]]"', f'"[[{k1 + k2!r},{-k2!r}],[{-k2!r},{k2!r}]]"',
            f'"[[{c11!r},{c12!r}],[{c12!r},{c22!r}]]"']


def _nonproportional_chain(r) -> list[str]:
    """:func:`_chain` with a dashpot from each mass to the ground, ``C = diag(c1, c2)``: not
    proportional (the modes are complex), every mode underdamped (zeta about 0.01 to 0.05).
    ``c2`` is moved off ``c1``'s share of the mass (``c1/m1 = c2/m2`` is ``C = a M``,
    proportional): a row close to it (1 in 3x10^5 drawn at random) is left by the stack to the
    one-off's ``ggev``, whose digits the limit script does not reproduce."""
    m1, m2, k1, k2 = (float(f"{r.uniform(lo, hi):.6g}") for lo, hi in
                      ((0.5, 20), (0.5, 20), (1e2, 1e4), (1e2, 1e4)))
    c1, c2 = (float(f"{2.0 * r.uniform(0.01, 0.05) * (k * m) ** 0.5:.6g}")
              for k, m in ((k1 + k2, m1), (k2, m2)))
    if abs(c1 / m1 - c2 / m2) < 0.05 * max(c1 / m1, c2 / m2):
        c2 = float(f"{1.5 * c2:.6g}")
    return [f'"[[{m1!r},0],[0,{m2!r}]]"', f'"[[{k1 + k2!r},{-k2!r}],[{-k2!r},{k2!r}]]"',
            f'"[[{c1!r},0],[0,{c2!r}]]"']


def _drum_goal(r) -> list[str]:
    """drum-two-blocks solved for J_A: masses and radii with m2 r2 > m1 r1 and the angular
    acceleration a drum of 0.01 to 5 kg m^2 would give, to six digits, as the goal."""
    m1, m2, r1, r2, J = (float(f"{r.uniform(lo, hi):.6g}") for lo, hi in
                         ((0.5, 5), (5, 50), (0.05, 0.2), (0.2, 0.5), (0.01, 5)))
    alpha = (m2 * r2 - m1 * r1) * 9.80665 / (J + m1 * r1 * r1 + m2 * r2 * r2)
    return [repr(m1), repr(m2), repr(r1), repr(r2), "?", f"{alpha:.6g}"]


def _annulus(r) -> list[str]:
    """A disk and a concentric hole (``-disk``), lighter and smaller: a valid composite."""
    m, a = r.uniform(0.5, 50), r.uniform(0.05, 2)
    return ['"disk(m=%.6g kg, r=%.6g m)"' % (m, a),
            '"-disk(m=%.6g kg, r=%.6g m)"' % (m * r.uniform(0.05, 0.3), a * r.uniform(0.1, 0.6))]


def _bolt_hole(r) -> list[str]:
    """A disk somewhere in the x-y plane and a hole inside it, well off its centre (never
    equal principal moments: no rule for a plane of axes in the limit script): a placed
    composite (the parallel-axis terms of both)."""
    m, a = r.uniform(0.5, 50), r.uniform(0.05, 2)
    x, y = r.uniform(-1, 1), r.uniform(-1, 1)
    hole = a * r.uniform(0.1, 0.3)
    return ['"disk(m=%.6g kg, r=%.6g m, at=(%.6g, %.6g, 0) m)"' % (m, a, x, y),
            '"-disk(m=%.6g kg, r=%.6g m, at=(%.6g, %.6g, 0) m)"'
            % (m * r.uniform(0.01, 0.05), hole, x + r.choice([-1, 1]) * r.uniform(0.2, 0.5) * a,
               y)]


CASES = [
    ("natural-frequency mass-spring", ["natural-frequency"], "k [N/m],m [kg]",
     lambda r: [f"{r.uniform(10, 1e4):.6g}", f"{r.uniform(0.1, 50):.6g}"]),
    ("natural-frequency clock-pendulum", ["natural-frequency", "--scene", "clock-pendulum"],
     "m [kg],l [m],M [kg],r [m],a [m]",
     lambda r: [f"{r.uniform(0.1, 2):.6g}", f"{r.uniform(0.5, 2):.6g}",
                f"{r.uniform(0.1, 5):.6g}", f"{r.uniform(0.05, 0.2):.6g}",
                f"{r.uniform(0.2, 0.5):.6g}"]),
    ("natural-frequency bead-on-rotating-ring",
     ["natural-frequency", "--scene", "bead-on-rotating-ring"], "r [m],Omega [rad/s]",
     lambda r: [f"{r.uniform(0.1, 1):.6g}", f"{r.uniform(0.5, 20):.6g}"]),
    ("natural-frequency pendulum amplitude", ["natural-frequency"],
     "length [m],amplitude [deg]",
     lambda r: [f"{r.uniform(0.1, 5):.6g}", f"{r.uniform(5, 170):.6g}"]),
    ("natural-frequency inverse k from f", ["natural-frequency"], "f [Hz],m [kg]",
     lambda r: [f"{r.uniform(0.5, 50):.6g}", f"{r.uniform(0.1, 50):.6g}"]),
    ("natural-frequency inverse l=? from T", ["natural-frequency", "--scene", "pendulum"],
     "T [s],l", lambda r: [f"{r.uniform(0.5, 5):.6g}", "?"]),
    ("spring-series", ["spring-series"], "k1 [N/m],k2 [N/m],k3 [N/m]",
     lambda r: [f"{r.uniform(10, 1e4):.6g}" for _ in range(3)]),
    ("spring-parallel", ["spring-parallel"], "k1 [N/m],k2 [N/m],k3 [N/m]",
     lambda r: [f"{r.uniform(10, 1e4):.6g}" for _ in range(3)]),
    ("spring-series cantilever, axial bar and a stiffness", ["spring-series"],
     "k1,k2,k3 [N/m]",
     lambda r: ['"cantilever(l=%.6g m, EI=%.6g N*m^2)"' % (r.uniform(0.2, 3), r.uniform(1e3, 1e6)),
                '"axial(l=%.6g m, EA=%.6g N)"' % (r.uniform(0.2, 3), r.uniform(1e5, 1e8)),
                f"{r.uniform(10, 1e4):.6g}"]),
    # round 8: a nested group with a shared value column (issue 17, springnest)
    ("spring-series nested group with a shared EI", ["spring-series"],
     "k1,k2 [N/m],EI [N*m^2]",
     lambda r: ['"parallel(cantilever(l=%.6g m), %.6g N/m)"' % (r.uniform(0.2, 3),
                                                                r.uniform(10, 1e4)),
                f"{r.uniform(10, 1e4):.6g}", f"{r.uniform(1e3, 1e6):.6g}"]),
    ("damping-ratio", ["damping-ratio"], "c [N*s/m],k [N/m],m [kg]",
     lambda r: [f"{r.uniform(0.1, 10):.6g}", f"{r.uniform(100, 1e4):.6g}",
                f"{r.uniform(0.5, 20):.6g}"]),
    ("rolling-onset", ["rolling-onset"], "v0 [m/s],mu",
     lambda r: [f"{r.uniform(0.5, 10):.6g}", f"{r.uniform(0.05, 0.8):.6g}"]),
    ("forced-response", ["forced-response"], "k [N/m],m [kg],zeta,F0 [N],Omega [rad/s]",
     lambda r: [f"{r.uniform(1e3, 1e6):.6g}", f"{r.uniform(1, 500):.6g}",
                f"{r.uniform(0.01, 0.3):.6g}", f"{r.uniform(1, 1e3):.6g}",
                f"{r.uniform(1, 300):.6g}"]),
    ("forced-response total response", ["forced-response"],
     "k [N/m],m [kg],zeta,F0 [N],Omega [rad/s],x0 [m],v0 [m/s],t [s]",
     lambda r: [f"{r.uniform(1e3, 1e6):.6g}", f"{r.uniform(1, 500):.6g}",
                f"{r.uniform(0.01, 0.3):.6g}", f"{r.uniform(1, 1e3):.6g}",
                f"{r.uniform(1, 300):.6g}", f"{r.uniform(-0.01, 0.01):.6g}",
                f"{r.uniform(-1, 1):.6g}", f"{r.uniform(0.001, 2):.6g}"]),
    ("forced-response undamped", ["forced-response"],
     "k [N/m],m [kg],F0 [N],Omega [rad/s]",
     lambda r: [f"{r.uniform(1e3, 1e6):.6g}", f"{r.uniform(1, 500):.6g}",
                f"{r.uniform(1, 1e3):.6g}", f"{r.uniform(1, 300):.6g}"]),
    ("inertia one disk a row", ["inertia"], "b1",
     lambda r: ['"disk(m=%.6g kg, r=%.6g m)"' % (r.uniform(0.1, 50), r.uniform(0.01, 2))]),
    ("inertia composite", ["inertia"], "b1,b2", lambda r: _annulus(r)),
    ("inertia placed composite", ["inertia"], "b1,b2", lambda r: _bolt_hole(r)),
    ("modes two-mass chain", ["modes"], "M,K", lambda r: _chain(r)),
    ("modes damped two-mass chain", ["modes"], "M,K,C", lambda r: _damped_chain(r)),
    ("modes non-proportional", ["modes"], "M,K,C", lambda r: _nonproportional_chain(r)),
    ("modes coupled-blocks", ["modes", "--scene", "coupled-blocks"],
     "m1 [kg],m2 [kg],k1 [N/m],k2 [N/m],k3 [N/m]",
     lambda r: [f"{r.uniform(lo, hi):.6g}" for lo, hi in
                ((0.5, 20), (0.5, 20), (1e2, 1e4), (1e2, 1e4), (1e2, 1e4))]),
    ("modes pendulum-on-sliding-block", ["modes", "--scene", "pendulum-on-sliding-block"],
     "m1 [kg],m2 [kg],l [m]",
     lambda r: [f"{r.uniform(lo, hi):.6g}" for lo, hi in ((1, 20), (0.1, 5), (0.1, 1))]),
    ("rigid-body drum-two-blocks", ["rigid-body", "--scene", "drum-two-blocks"],
     "m1 [kg],m2 [kg],r1 [m],r2 [m],J_A [kg*m^2]",
     lambda r: [f"{r.uniform(0.5, 50):.6g}", f"{r.uniform(0.5, 50):.6g}",
                f"{r.uniform(0.05, 0.5):.6g}", f"{r.uniform(0.05, 0.5):.6g}",
                f"{r.uniform(0.01, 5):.6g}"]),
    ("rigid-body angled-bar-on-shaft", ["rigid-body", "--scene", "angled-bar-on-shaft"],
     "m [kg],l [m],M0 [N*m],omega [rad/s]",
     lambda r: [f"{r.uniform(0.5, 20):.6g}", f"{r.uniform(0.1, 2):.6g}",
                f"{r.uniform(1, 100):.6g}", f"{r.uniform(0.5, 50):.6g}"]),
    # round 8: a signed unknown by the one-off's bracketed search, on columns
    ("rigid-body inverse", ["rigid-body", "--scene", "angled-bar-on-shaft"],
     "m [kg],l [m],M0 [N*m],omega [rad/s],alpha [rad/s^2]",
     lambda r: [f"{r.uniform(0.5, 20):.6g}", f"{r.uniform(0.1, 2):.6g}", "?",
                f"{r.uniform(0.5, 50):.6g}", f"{r.choice((-1, 1)) * r.uniform(0.1, 100):.6g}"]),
    ("rigid-body drum J_A inverse", ["rigid-body", "--scene", "drum-two-blocks"],
     "m1 [kg],m2 [kg],r1 [m],r2 [m],J_A [kg*m^2],alpha [rad/s^2]", lambda r: _drum_goal(r)),
    ("eom pendulum", ["eom", "--scene", "pendulum"], "l [m],phi [rad],phi_dot [rad/s]",
     lambda r: [f"{r.uniform(0.1, 5):.6g}", f"{r.uniform(-3, 3):.6g}",
                f"{r.uniform(-2, 2):.6g}"]),
    ("eom block-disk-springs", ["eom", "--scene", "block-disk-springs"],
     "M [kg],m [kg],r [m],k [N/m],x [m],phi [rad],x_dot [m/s],phi_dot [rad/s]",
     lambda r: [f"{r.uniform(lo, hi):.6g}" for lo, hi in
                ((0.5, 20), (0.5, 20), (0.05, 1), (10, 1e4), (-0.1, 0.1), (-1, 1), (-1, 1),
                 (-2, 2))]),
    # round 14: no equilibrium on the bar (closed forms outside the scene's domain)
    ("eom disk-on-swinging-bar", ["eom", "--scene", "disk-on-swinging-bar"],
     "m1 [kg],l [m],m2 [kg],J2 [kg*m^2],phi [rad],x [m],phi_dot [rad/s],x_dot [m/s]",
     lambda r: [f"{r.uniform(lo, hi):.6g}" for lo, hi in
                ((0.5, 20), (0.2, 3), (0.1, 10), (0.001, 1), (-3, 3), (0, 3), (-2, 2),
                 (-2, 2))]),
    # round 14: equilibria from roots written by hand (b = 0), in a domain
    ("eom spring-coupled-pendulums", ["eom", "--scene", "spring-coupled-pendulums"],
     "m [kg],l [m],k [N/m],phi1 [rad],phi2 [rad],phi1_dot [rad/s],phi2_dot [rad/s]",
     lambda r: [f"{r.uniform(lo, hi):.6g}" for lo, hi in
                ((0.5, 5), (0.2, 2), (200, 1e4), (-1, 1), (0, 1.5), (-2, 2), (-2, 2))]),
    ("eom bead-on-rotating-ring", ["eom", "--scene", "bead-on-rotating-ring"],
     "r [m],Omega [rad/s],theta [rad],theta_dot [rad/s]",
     lambda r: [f"{r.uniform(0.05, 1):.6g}", f"{r.uniform(1, 30):.6g}",
                f"{r.uniform(-3, 3):.6g}", f"{r.uniform(-2, 2):.6g}"]),
    ("eom coupled-blocks", ["eom", "--scene", "coupled-blocks"],
     "m1 [kg],m2 [kg],k1 [N/m],k2 [N/m],k3 [N/m],x1 [m],x2 [m],x1_dot [m/s],x2_dot [m/s]",
     lambda r: [f"{r.uniform(0.1, 50):.6g}", f"{r.uniform(0.1, 50):.6g}",
                f"{r.uniform(10, 1e4):.6g}", f"{r.uniform(10, 1e4):.6g}",
                f"{r.uniform(10, 1e4):.6g}", f"{r.uniform(-0.1, 0.1):.6g}",
                f"{r.uniform(-0.1, 0.1):.6g}", f"{r.uniform(-1, 1):.6g}",
                f"{r.uniform(-1, 1):.6g}"]),
    ("eom pendulum-on-sliding-block", ["eom", "--scene", "pendulum-on-sliding-block"],
     "m1 [kg],m2 [kg],l [m],x [m],phi [rad],x_dot [m/s],phi_dot [rad/s]",
     lambda r: [f"{r.uniform(0.1, 50):.6g}", f"{r.uniform(0.1, 50):.6g}",
                f"{r.uniform(0.1, 5):.6g}", f"{r.uniform(-1, 1):.6g}",
                f"{r.uniform(-3, 3):.6g}", f"{r.uniform(-1, 1):.6g}",
                f"{r.uniform(-2, 2):.6g}"]),
    ("coriolis", ["coriolis"], "omega [rad/s],vr [m/s]",
     lambda r: ['"0,0,%.6g"' % r.uniform(0.1, 5), '"%.6g,%.6g,0"' % (r.uniform(-3, 3),
                                                                   r.uniform(-3, 3))]),
    ("coriolis Earth", ["coriolis"], "latitude [deg],speed [m/s],heading [deg],mass [kg]",
     lambda r: [f"{r.uniform(-90, 90):.6g}", f"{r.uniform(0, 300):.6g}",
                f"{r.uniform(0, 360):.6g}", f"{r.uniform(0.1, 1e3):.6g}"]),
    # round 8: a motion given in time, derived once a run (issue 17, springnest)
    ("coriolis over times", ["coriolis", "--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "b=0.5m/s^2",
                             "--omega", "0,0,2 rad/s"], "t [s]",
     lambda r: [f"{r.uniform(0.01, 10):.6g}"]),
    # round 7: an inverse row on columns (the Earth's speed from |a_c|, closed form)
    ("coriolis Earth inverse vr", ["coriolis"], "a_c_mag [m/s^2],latitude [deg],vr",
     lambda r: [f"{10 ** r.uniform(-6, -2):.6g}",
                f"{r.choice((-1, 1)) * r.uniform(1, 89):.6g}", "?"]),
]


def dyncalc() -> list[str]:
    script = BIN / "dyncalc"
    return [str(script)] if script.exists() else [sys.executable, "-m", "dyncalc"]


def write_file(folder: Path, label: str, header: str, make, rows: int) -> Path:
    rng = random.Random(label)
    path = folder / f"{label.replace(' ', '_')}-{rows}.csv"
    with path.open("w") as out:
        out.write(header + "\n")
        for _ in range(rows):
            out.write(",".join(make(rng)) + "\n")
    return path


def timed(argv: list[str], path: Path, generic: bool) -> float:
    env = dict(os.environ)
    env["DYNCALC_BATCH_GENERIC"] = "1" if generic else "0"
    start = time.perf_counter()
    done = subprocess.run([*dyncalc(), *argv, "--batch", str(path)], env=env,
                          stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, cwd="/")
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"{argv} failed: {done.stderr.decode()[:300]}")
    return seconds


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rows", type=int, default=100_000)
    parser.add_argument("--generic-rows", type=int, default=2_000)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--out", type=Path)
    parser.add_argument("--only", default="", help="run only the cases whose label contains "
                        "this text (e.g. inverse)")
    args = parser.parse_args()
    lines = ["| command | vectorised rows/s | generic rows/s | ratio |",
             "| --- | ---: | ---: | ---: |"]
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        for label, argv, header, make in CASES:
            if args.only not in label:
                continue
            many = write_file(folder, label, header, make, args.rows)
            few = write_file(folder, label, header, make, args.generic_rows)
            fast, slow = [], []
            for _ in range(args.repeat):  # interleaved, so load drifts hit both alike
                fast.append(args.rows / timed(argv, many, False))
                slow.append(args.generic_rows / timed(argv, few, True))
            f, s = statistics.median(fast), statistics.median(slow)
            lines.append(f"| {label} | {f:,.0f} | {s:,.0f} | {f / s:,.0f}x |")
            print(lines[-1], flush=True)
    load = os.getloadavg()[0]
    footer = (f"\nPython {platform.python_version()}, {os.cpu_count()} CPUs, "
              f"{platform.machine()}; {time.strftime('%Y-%m-%d %H:%M')}; load average "
              f"{load:.2f} at the end; {args.rows:,} rows vectorised, {args.generic_rows:,} "
              f"generic; wall time end to end (start-up included), median of {args.repeat}.")
    text = "\n".join(lines) + "\n" + footer + "\n"
    print(footer)
    if args.out:
        args.out.write_text("# Batch throughput of every command\n\nCommand: `python "
                            "benchmarks/batch_commands.py " + " ".join(sys.argv[1:])
                            + "`\n\n" + text)


if __name__ == "__main__":
    main()
