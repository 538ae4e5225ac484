"""The speed-against-accuracy trade of every method of every command, measured.

For each command with a choice of method (the pendulum: small-angle, series, elliptic, ode;
the half-cylinder shell: linear, quadrature, ode; rolling onset: closed-form, ode; the damping
fit: log-linear, nonlinear; the frame with a brace damper: exact, small-damping) and each
tolerance 1e-3, 1e-6, 1e-9, 1e-12, and for forced-response's closed form (its only method,
at extreme inputs: zeta = 1e-9 with eta = 1 +- 1e-12), this script

* times the library function the command calls, in process: the median over repeated rounds of
  the mean time per call over a fixed set of inputs (timeit-style; scipy is imported before the
  clock starts, so the ODE's import cost is not in it);
* times the one-off: the command line ``dyncalc ... --method M --rtol R --value NAME`` run as
  a process (start-up, imports and all), the median wall time of a few runs, the rows' runs
  interleaved (:data:`CLI` holds the command lines);
* times the vectorised path over 10^5 inputs where the program has one (numpy kernels of
  dyncalc.physics.numerics; for the damping fit an input is a peak of one 10^5-peak record),
  and marks "n/a" where it has none;
* measures the achieved error: the largest relative error over the inputs against a reference
  computed with mpmath at 30 digits from the same float inputs (the elliptic integral by the
  AGM, the shell's energy integral by mpmath.quad, the rolling closed form, the exact
  least-squares minimisers of the fits, the frame's peak, the forced response's X, phi and
  TR with ``1 - eta^2`` formed exactly at 40 digits).

It writes ``benchmarks/results/speed_accuracy.md`` (the table, and the cost of the pendulum's
kernels that decides which model ``auto`` takes) and ``benchmarks/results/speed_accuracy.png``
(error against time per call, log-log, one curve per method; dashed: vectorised, per input).

    python benchmarks/speed_accuracy.py [--quick]

from the project root with the ``bench`` extra installed (``pip install ".[bench]"``: mpmath,
matplotlib). A full run takes about three minutes; ``--quick`` fewer repeats and runs.
"""
from __future__ import annotations

import argparse
import importlib
import math
import random
import statistics
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))   # the checkout's dyncalc, installed or not
sys.path.insert(0, str(ROOT / "benchmarks"))

import mpmath  # noqa: E402

from dyncalc.physics import numerics  # noqa: E402
from _timing import child_env, machine, spawn  # noqa: E402
from dyncalc.physics.damping import frame_brace_damper  # noqa: E402
from dyncalc.physics.decay_fit import fit_decrement  # noqa: E402
from dyncalc.physics.forced import forced_response  # noqa: E402
from dyncalc.physics.nonlinear import half_cylinder_shell  # noqa: E402
from dyncalc.physics.oscillators import pendulum  # noqa: E402
from dyncalc.physics.rolling import onset_closed_form, onset_ode  # noqa: E402
from dyncalc.units import Q_  # noqa: E402

RTOLS = (1e-3, 1e-6, 1e-9, 1e-12)
VECTOR_SIZE = 100_000
RESULTS = ROOT / "benchmarks" / "results"
FLOOR = 1e-17     # errors below (exact results) are plotted here
mpmath.mp.dps = 30


# --- timing ------------------------------------------------------------------------------------

def per_call(call, inputs, rounds: int, budget: float = 0.2) -> float:
    """Median over ``rounds`` of the mean seconds per call over ``inputs`` (each round runs
    the whole set as many times as fits in about ``budget`` seconds)."""
    start = time.perf_counter()
    for x in inputs:
        call(x)
    once = max(time.perf_counter() - start, 1e-9)
    number = max(1, int(budget / once))
    samples = []
    for _ in range(rounds):
        start = time.perf_counter()
        for _ in range(number):
            for x in inputs:
                call(x)
        samples.append((time.perf_counter() - start) / (number * len(inputs)))
    return statistics.median(samples)


def per_input(call, rounds: int) -> float:
    """Median seconds per input of one vectorised call over VECTOR_SIZE inputs."""
    call()
    samples = []
    for _ in range(rounds):
        start = time.perf_counter()
        call()
        samples.append((time.perf_counter() - start) / VECTOR_SIZE)
    return statistics.median(samples)


def relative(got: float, ref) -> float:
    return float(abs(mpmath.mpf(got) / ref - 1)) if ref != 0 else abs(got)


# --- the pendulum ------------------------------------------------------------------------------

G, LENGTH = 9.80665, 1.0
PENDULUM_DEGREES = [5.0, 10.0, 20.0, 30.0, 45.0, 60.0, 75.0, 90.0, 105.0, 120.0, 135.0, 150.0]


def pendulum_reference(degrees: float):
    theta = mpmath.mpf(degrees) * mpmath.pi / 180
    return (2 * mpmath.pi * mpmath.sqrt(mpmath.mpf(LENGTH) / mpmath.mpf(G))
            / mpmath.agm(1, mpmath.cos(theta / 2)))


def pendulum_vector(method: str, rtol: float):
    """The numpy path over VECTOR_SIZE amplitudes: T from the kernels, as a batch would."""
    degrees = np.resize(np.array(PENDULUM_DEGREES), VECTOR_SIZE)
    t0 = 2 * math.pi * math.sqrt(LENGTH / G)

    if method == "small-angle":
        def run():
            return np.full(degrees.shape, t0)
    elif method == "series":
        def run():
            k2 = np.sin(np.radians(degrees) / 2) ** 2
            cos_half = np.sin((180.0 - degrees) * (math.pi / 360.0))
            return t0 * numerics.pendulum_series(k2, cos_half * cos_half, rtol)[0]
    elif method == "elliptic":
        def run():
            cos_half = np.sin((180.0 - degrees) * (math.pi / 360.0))
            return t0 / numerics.agm_array(np.ones_like(cos_half), cos_half)
    else:
        return None
    return run


def bench_pendulum(rounds: int) -> list[dict]:
    rows = []
    refs = [pendulum_reference(d) for d in PENDULUM_DEGREES]
    amplitudes = [Q_(d, "deg") for d in PENDULUM_DEGREES]
    length, g = Q_(LENGTH, "m"), Q_(G, "m/s^2")
    for method in ("small-angle", "series", "elliptic", "ode"):
        for rtol in RTOLS:
            def call(amplitude, method=method, rtol=rtol):
                return pendulum(length, g, amplitude, method=method, rtol=rtol)
            error = max(relative(call(a).values["T"].magnitude, r)
                        for a, r in zip(amplitudes, refs))
            seconds = per_call(call, amplitudes, rounds, 0.1 if method == "ode" else 0.2)
            vector = pendulum_vector(method, rtol)
            vector_s = vector_error = None
            if vector is not None:
                vector_s = per_input(vector, max(3, rounds // 2))
                periods = vector()[: len(refs)]
                vector_error = max(relative(float(p), r) for p, r in zip(periods, refs))
            rows.append(dict(command="natural-frequency (pendulum)", method=method, rtol=rtol,
                             seconds=seconds, vector=vector_s, error=error,
                             vector_error=vector_error))
            print(f"  pendulum {method:11} {rtol:g}: {1e6 * seconds:9.1f} us  {error:.2g}",
                  flush=True)
    return rows


def kernel_costs(rounds: int) -> list[str]:
    """What decides ``auto``: the AGM against the series, as kernels (no pint around them)."""
    lines = ["| amplitude | rtol | series terms | series (us) | AGM (us) | compensated AGM (us) |",
             "| ---: | ---: | ---: | ---: | ---: | ---: |"]
    for degrees in (0.1, 1.0, 10.0, 30.0, 90.0, 150.0):
        theta = math.radians(degrees)
        k2 = math.sin(theta / 2) ** 2
        cos_half = numerics.half_complement_sin(degrees, "degree")
        agm_s = per_call(lambda b: numerics.agm(1.0, b), [cos_half], rounds, 0.05)
        comp_s = per_call(lambda b: numerics.agm_compensated(1.0, b), [cos_half], rounds, 0.05)
        for rtol in (1e-6, 1e-12):
            terms = numerics.pendulum_series(k2, cos_half * cos_half, rtol)[1]
            series_s = per_call(lambda r: numerics.pendulum_series(k2, cos_half * cos_half, r),
                                [rtol], rounds, 0.05)
            lines.append(f"| {degrees:g} deg | {rtol:g} | {terms + 1} | {1e6 * series_s:.2f} | "
                         f"{1e6 * agm_s:.2f} | {1e6 * comp_s:.2f} |")
    return lines


# --- the half-cylinder shell -------------------------------------------------------------------

SHELL_DEGREES = [5.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0]


def shell_reference(degrees: float):
    """T from the energy integral (mpmath.quad), T0 = 2 pi sqrt((pi - 2) r / g)."""
    k2 = mpmath.sin(mpmath.mpf(degrees) * mpmath.pi / 360) ** 2
    c = mpmath.pi - 2
    integral = mpmath.quad(lambda u: mpmath.sqrt((c + 4 * k2 * mpmath.sin(u) ** 2)
                                                 / (c * (1 - k2 * mpmath.sin(u) ** 2))),
                           [0, mpmath.pi / 2])
    t0 = 2 * mpmath.pi * mpmath.sqrt(c * mpmath.mpf(0.5) / mpmath.mpf(G))
    return t0 * 2 / mpmath.pi * integral


def bench_shell(rounds: int) -> list[dict]:
    rows = []
    refs = [shell_reference(d) for d in SHELL_DEGREES]
    amplitudes = [Q_(d, "deg") for d in SHELL_DEGREES]
    radius, g = Q_(0.5, "m"), Q_(G, "m/s^2")
    for method in ("linear", "quadrature", "ode"):
        for rtol in RTOLS:
            def call(amplitude, method=method, rtol=rtol):
                return half_cylinder_shell(radius, g, amplitude, method=method, rtol=rtol)
            error = max(relative(call(a).values["T"].magnitude, r)
                        for a, r in zip(amplitudes, refs))
            seconds = per_call(call, amplitudes, rounds, 0.1 if method == "ode" else 0.2)
            rows.append(dict(command="natural-frequency (half-cylinder-shell)", method=method,
                             rtol=rtol, seconds=seconds, vector=None, error=error,
                             vector_error=None))
            print(f"  shell {method:10} {rtol:g}: {1e6 * seconds:9.1f} us  {error:.2g}",
                  flush=True)
    return rows


# --- rolling onset -------------------------------------------------------------------------------

def rolling_cases() -> list[tuple]:
    """(v0, mu, kappa, g, r, omega0, sin_b, cos_b): bodies without spin, with topspin and
    backspin, on the flat and on slopes both ways."""
    rng = random.Random(31)
    cases = []
    for i in range(10):
        kappa = rng.choice([0.4, 2 / 3, 0.5, 1.0])
        v0, mu, r = rng.uniform(1, 10), rng.uniform(0.05, 0.5), rng.uniform(0.02, 0.2)
        omega0 = [0.0, v0 / r * rng.uniform(0.2, 0.8), -v0 / r * rng.uniform(0.2, 3.0)][i % 3]
        beta = [0.0, math.radians(rng.uniform(-8, 8))][i % 2]
        cases.append((v0, mu, kappa, G, r, omega0, math.sin(beta), math.cos(beta)))
    return cases


def rolling_reference(case) -> dict:
    """t_roll, x_roll, v_roll from the closed form in mpmath, from the float inputs."""
    v0, mu, kappa, g, r, omega0, s, c = (mpmath.mpf(x) for x in case)
    from fractions import Fraction

    exact = Fraction(case[2]).limit_denominator(1000)
    kappa = mpmath.mpf(exact.numerator) / exact.denominator   # the body's exact 2/5, 2/3
    s0 = v0 - r * omega0
    sigma = 1 if s0 > 0 else -1
    t = kappa * abs(s0) / (g * (mu * (1 + kappa) * c + sigma * kappa * s))
    v = v0 - g * (s + sigma * mu * c) * t
    return {"t_roll": t, "x_roll": t * (v0 + v) / 2, "v_roll": v}


def bench_rolling(rounds: int) -> list[dict]:
    rows = []
    cases = rolling_cases()
    refs = [rolling_reference(c) for c in cases]
    importlib.import_module("scipy.integrate")  # its import is not the method's cost

    def closed(case, rtol):
        o = onset_closed_form(*case)
        return {"t_roll": o.t, "x_roll": o.x, "v_roll": o.v}

    def ode(case, rtol):
        o = onset_ode(*case, rtol=rtol)
        return {"t_roll": o.t, "x_roll": o.x, "v_roll": o.v}

    for method, function in (("closed-form", closed), ("ode", ode)):
        for rtol in RTOLS:
            def call(case, function=function, rtol=rtol):
                return function(case, rtol)
            error = max(relative(got[name], ref[name]) for case, ref in zip(cases, refs)
                        for got in [call(case)] for name in ref)
            seconds = per_call(call, cases, rounds, 0.1 if method == "ode" else 0.2)
            rows.append(dict(command="rolling-onset", method=method, rtol=rtol,
                             seconds=seconds, vector=None, error=error, vector_error=None))
            print(f"  rolling {method:11} {rtol:g}: {1e6 * seconds:9.1f} us  {error:.2g}",
                  flush=True)
    return rows


# --- the damping fit -----------------------------------------------------------------------------

def peak_records() -> list[np.ndarray]:
    rng = random.Random(32)
    records = []
    for n, delta, noise in ((8, 0.2, 1e-2), (12, 0.05, 3e-3), (20, 0.15, 1e-3),
                            (30, 0.02, 5e-3), (6, 0.5, 1e-2)):
        records.append(np.array([math.exp(-delta * i) * (1 + noise * rng.gauss(0, 1))
                                 for i in range(n)]))
    return records


def fit_reference(peaks: np.ndarray, method: str):
    """delta of the exact least-squares minimiser: of ln x_i (a line), or of x_i itself (the
    root of the reduced normal equation in delta, the amplitude eliminated)."""
    x = [mpmath.mpf(float(p)) for p in peaks]
    n = len(x)
    u = [i - mpmath.mpf(n - 1) / 2 for i in range(n)]
    line = -mpmath.fsum(a * mpmath.log(b) for a, b in zip(u, x)) / mpmath.fsum(a * a for a in u)
    if method == "log-linear":
        return line

    def gradient(delta):
        e = [mpmath.exp(-delta * i) for i in range(n)]
        amplitude = mpmath.fsum(a * b for a, b in zip(x, e)) / mpmath.fsum(a * a for a in e)
        return mpmath.fsum((amplitude * e[i] - x[i]) * i * e[i] for i in range(n))

    return mpmath.findroot(gradient, line)


def bench_fit(rounds: int) -> list[dict]:
    rows = []
    records = peak_records()
    long_record = np.exp(-1e-4 * np.arange(VECTOR_SIZE)) * (
        1 + 1e-3 * np.random.default_rng(33).standard_normal(VECTOR_SIZE))
    for method in ("log-linear", "nonlinear"):
        refs = [fit_reference(p, method) for p in records]
        for rtol in RTOLS:
            def call(peaks, method=method, rtol=rtol):
                return fit_decrement(peaks, method=method, rtol=rtol)
            error = max(relative(call(p).delta, r) for p, r in zip(records, refs))
            seconds = per_call(call, records, rounds)
            vector_s = per_input(lambda: call(long_record), max(3, rounds // 2))
            rows.append(dict(command="damping-ratio (--amplitudes)", method=method, rtol=rtol,
                             seconds=seconds, vector=vector_s, error=error, vector_error=None))
            print(f"  fit {method:10} {rtol:g}: {1e6 * seconds:9.1f} us  {error:.2g}",
                  flush=True)
    return rows


# --- the frame with a brace damper (E5.21) --------------------------------------------------------

#: (m kg, k N/m, b0 m/s^2); the dashpot d (N s/m) set for each zeta of FRAME_ZETAS
FRAME = (500.0, 200e3, 1.0)
FRAME_ZETAS = (1e-4, 1e-3, 0.01, 0.0707, 0.2, 0.5, 0.7, 0.9)


def frame_cases() -> list[float]:
    """The dashpot coefficients d = 2 zeta sqrt(2 k m) of FRAME_ZETAS."""
    m, k, _b0 = FRAME
    return [2.0 * z * math.sqrt(2.0 * k * m) for z in FRAME_ZETAS]


def frame_reference(d: float):
    """y_max from the float inputs: y0 / (2 zeta sqrt(1 - zeta^2)) below zeta = 1/sqrt 2, else
    y0, with zeta = (d/2) sqrt(1/(2 k m)) and y0 = 2 m b0 / k."""
    m, k, b0 = (mpmath.mpf(x) for x in FRAME)
    zeta = mpmath.mpf(d) / 2 * mpmath.sqrt(1 / (2 * k * m))
    y0 = 2 * m * b0 / k
    return y0 / (2 * zeta * mpmath.sqrt(1 - zeta ** 2)) if zeta ** 2 < 0.5 else y0


def bench_frame(rounds: int) -> list[dict]:
    rows = []
    cases = frame_cases()
    refs = [frame_reference(d) for d in cases]
    m, k, b0 = Q_(FRAME[0], "kg"), Q_(FRAME[1], "N/m"), Q_(FRAME[2], "m/s^2")
    for method in ("exact", "small-damping"):
        for rtol in RTOLS:
            def call(d, method=method, rtol=rtol):
                return frame_brace_damper(m, k, Q_(d, "N*s/m"), b0, method=method, rtol=rtol)
            error = max(relative(call(d).values["y_max"].magnitude, r)
                        for d, r in zip(cases, refs))
            seconds = per_call(call, cases, rounds)
            rows.append(dict(command="natural-frequency (frame-brace-damper)", method=method,
                             rtol=rtol, seconds=seconds, vector=None, error=error,
                             vector_error=None))
            print(f"  frame {method:13} {rtol:g}: {1e6 * seconds:9.1f} us  {error:.2g}",
                  flush=True)
    return rows


# --- forced-response (issue 18) --------------------------------------------------------------------

#: k (N/m), m (kg): omega = 100 rad/s; the excitation at eta = Omega/omega of FORCED_ETAS,
#: each with every damping ratio of FORCED_ZETAS (resonance with zeta = 1e-9 included)
FORCED_KM = (1e4, 1.0)
FORCED_ETAS = (1.0 - 1e-12, 1.0, 1.0 + 1e-12, 1.0 - 1e-6, 0.5, 2.0, 1e3, 1e-3)
FORCED_ZETAS = (1e-9, 1e-6, 0.05, 0.7, 2.0)
FORCED_RESULTS = ("X", "phi", "TR")


def forced_cases() -> list[tuple[float, float]]:
    """(Omega in rad/s, zeta): the float Omega nearest eta omega."""
    return [(eta * 100.0, zeta) for eta in FORCED_ETAS for zeta in FORCED_ZETAS]


def forced_reference(Omega: float, zeta: float) -> dict:
    """X (F0 = 1 N), phi and TR in mpmath from the float inputs, eta^2 = Omega^2 m / k
    exactly (40 digits: the gap 1 - eta^2 of 1e-12 keeps 28 of them)."""
    with mpmath.workdps(40):
        k, m = (mpmath.mpf(x) for x in FORCED_KM)
        eta2 = mpmath.mpf(Omega) ** 2 * m / k
        gap, two_ze = 1 - eta2, 2 * mpmath.mpf(zeta) * mpmath.sqrt(eta2)
        root = mpmath.sqrt(gap ** 2 + two_ze ** 2)
        return {"X": 1 / (k * root), "phi": mpmath.atan2(two_ze, gap),
                "TR": mpmath.sqrt(1 + two_ze ** 2) / root}


def bench_forced(rounds: int) -> list[dict]:
    """One row: the closed form (the command's only method) over every case, near resonance
    with zeta = 1e-9 and eta = 1 +- 1e-12 included."""
    cases = forced_cases()
    refs = [forced_reference(*case) for case in cases]
    k, m, F0 = Q_(FORCED_KM[0], "N/m"), Q_(FORCED_KM[1], "kg"), Q_(1.0, "N")

    def call(case):
        return forced_response(k=k, m=m, zeta=case[1], F0=F0, Omega=Q_(case[0], "rad/s"))
    error = max(relative(got[name], ref[name]) for case, ref in zip(cases, refs)
                for got in [call(case).values] for name in FORCED_RESULTS)
    seconds = per_call(call, cases, rounds)
    print(f"  forced closed-form: {1e6 * seconds:9.1f} us  {error:.2g}", flush=True)
    return [dict(command="forced-response", method="closed-form", rtol=None, seconds=seconds,
                 vector=None, error=error, vector_error=None)]


# --- the one-off: the command line, a process per call --------------------------------------------

AMPLITUDES = "48.2, 39.1, 31.9, 25.8, 21.1, 17.2 mV"
#: command label -> the arguments after ``dyncalc`` of one representative one-off, given the
#: method and the tolerance
CLI = {
    "natural-frequency (pendulum)": lambda method, rtol: [
        "natural-frequency", "--length", "1m", "--amplitude", "30deg", "--method", method,
        "--rtol", rtol, "--value", "T"],
    "natural-frequency (half-cylinder-shell)": lambda method, rtol: [
        "natural-frequency", "--scene", "half-cylinder-shell", "r=0.5m", "--amplitude",
        "30deg", "--method", method, "--rtol", rtol, "--value", "T"],
    "rolling-onset": lambda method, rtol: [
        "rolling-onset", "--v0", "5m/s", "--mu", "0.2", "--method", method, "--rtol", rtol,
        "--value", "t_roll"],
    "damping-ratio (--amplitudes)": lambda method, rtol: [
        "damping-ratio", "--amplitudes", AMPLITUDES, "--method", method, "--rtol", rtol,
        "--value", "zeta"],
    "natural-frequency (frame-brace-damper)": lambda method, rtol: [
        "natural-frequency", "--scene", "frame-brace-damper", "m=500kg", "k=200 kN/m",
        "d=2 kN*s/m", "b0=1 m/s^2", "--method", method, "--rtol", rtol, "--value", "y_max"],
    "forced-response": lambda method, rtol: [
        "forced-response", "--k", "1e4 N/m", "--m", "1 kg", "--zeta", "1e-9", "--F0", "1 N",
        "--Omega", "100.0000000001 rad/s", "--value", "X", "--value", "phi"],
}


def dyncalc() -> list[str]:
    script = Path(sys.executable).parent / "dyncalc"
    return [str(script)] if script.exists() else [sys.executable, "-m", "dyncalc"]


def one_offs(rows: list[dict], runs: int) -> None:
    """Each row's ``one_off``: the median wall time of ``runs`` processes of its command line
    (after one unmeasured run), start-up included; the rows' runs interleaved round by round,
    so that a drift of the machine's load hits them alike."""
    env = child_env(NO_COLOR="1")
    argvs = [[*dyncalc(), *CLI[r["command"]](r["method"], f"{r['rtol'] or 1e-9:g}")]
             for r in rows]
    times: list[list[float]] = [[] for _ in rows]
    for argv in argvs:
        spawn(argv, env)
    for _ in range(runs):
        for argv, samples in zip(argvs, times):
            samples.append(spawn(argv, env).wall)
    for row, samples in zip(rows, times):
        row["one_off"] = statistics.median(samples)


# --- output ------------------------------------------------------------------------------------

def shell_word(word: str) -> str:
    return f'"{word}"' if any(c in word for c in " *,") else word


def time_text(seconds: float | None) -> str:
    if seconds is None:
        return "n/a"
    if seconds >= 1.0:
        return f"{seconds:.3g} s"
    if seconds >= 1e-3:
        return f"{1e3 * seconds:.3g} ms"
    if seconds >= 1e-6:
        return f"{1e6 * seconds:.3g} us"
    return f"{1e9 * seconds:.3g} ns"


def error_text(row: dict) -> str:
    text = f"{row['error']:.2g}" if row["error"] else "0"
    if row["vector_error"] is not None and row["vector_error"] > 2 * max(row["error"], 1e-17):
        text += f" (vectorised {row['vector_error']:.2g})"
    return text


def write_table(rows: list[dict], kernels: list[str], elapsed: float, header: str) -> Path:
    lines = [
        "# Speed against accuracy, every method of every command",
        "",
        f"{header} ({elapsed:.0f} s; numpy {np.__version__}). Time per call, in process: the "
        "median over repeated rounds of the library function the command calls (scipy "
        "already imported). One-off: the wall time of the whole command line as a process, "
        "start-up included (`dyncalc ... --method M --rtol R --value NAME`, one representative "
        "input each, the column below; the median of the runs, the rows' runs interleaved). "
        "Vectorised: per input, over 10^5 inputs in one numpy call (for the fit, per peak of "
        "one 10^5-peak record); n/a: the program has no vectorised path for it. "
        "Error: the largest relative error over the inputs against mpmath at 30 digits (40 "
        "for forced-response) from the same float inputs (pendulum: 12 amplitudes from 5 to "
        "150 deg; shell: 7 from 5 to 85 deg; rolling: 10 bodies with and without spin, flat "
        "and sloped; fit: 5 noisy records of 6 to 30 peaks, against each fit's exact "
        "least-squares minimiser; frame-brace-damper: y_max at zeta 1e-4 to 0.9; "
        "forced-response: X, phi and TR at eta = 1 - 1e-12, 1, 1 + 1e-12, 1 - 1e-6, 0.5, 2, "
        "1e3, 1e-3, each with zeta = 1e-9, 1e-6, 0.05, 0.7, 2; it has one method, and "
        "`--rtol` does not change its model).",
        "",
        "| command | method | rtol | time per call | one-off (process) | vectorised, per input "
        "| achieved max rel error |",
        "| --- | --- | ---: | ---: | ---: | ---: | ---: |",
    ]
    for row in rows:
        rtol = "-" if row["rtol"] is None else f"{row['rtol']:g}"
        lines.append(f"| {row['command']} | {row['method']} | {rtol} | "
                     f"{time_text(row['seconds'])} | {time_text(row.get('one_off'))} | "
                     f"{time_text(row['vector'])} | {error_text(row)} |")
    lines += ["", "The one-off command lines:", ""]
    lines += [f"* {command}: `dyncalc {' '.join(shell_word(w) for w in make('M', 'R'))}`"
              for command, make in CLI.items()]
    lines += [
        "",
        "## The pendulum's kernels: what `auto` weighs",
        "",
        "The amplitude series (terms counted with the leading 1) against the AGM, as bare "
        "kernels (no units around them). `auto` computes the plain AGM to judge the "
        "small-angle model on its exact error; beyond it, it takes the elliptic period, whose "
        "value comes from the compensated (correctly rounded) AGM. The series' first terms "
        "cost about what the plain AGM costs, each further term some 0.15 us more; up to a few "
        "dozen terms the series is a few microseconds cheaper than the compensated AGM, "
        "against a few hundred us for a whole call (the table above): a few per cent at most, "
        "within the timing noise, for an answer accurate to rtol instead of to 2 ulp. So "
        "`auto` skips the series; `--method series` computes it.",
        "",
        *kernels,
        "",
    ]
    RESULTS.mkdir(parents=True, exist_ok=True)
    path = RESULTS / "speed_accuracy.md"
    path.write_text("\n".join(lines))
    return path


SHORT = {"natural-frequency (pendulum)": "pendulum",
         "natural-frequency (half-cylinder-shell)": "half-cylinder shell",
         "rolling-onset": "rolling-onset", "damping-ratio (--amplitudes)": "damping fit",
         "natural-frequency (frame-brace-damper)": "frame-brace-damper",
         "forced-response": "forced-response"}


def write_plot(rows: list[dict]) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(9.5, 6.5))
    colours = {"natural-frequency (pendulum)": "tab:blue",
               "natural-frequency (half-cylinder-shell)": "tab:green",
               "rolling-onset": "tab:red", "damping-ratio (--amplitudes)": "tab:purple",
               "natural-frequency (frame-brace-damper)": "tab:orange",
               "forced-response": "tab:brown"}
    markers = ["o", "s", "^", "D"]
    seen: dict[str, int] = {}
    for (command, method) in dict.fromkeys((r["command"], r["method"]) for r in rows):
        points = [r for r in rows if r["command"] == command and r["method"] == method]
        marker = markers[seen.setdefault(command, 0) % len(markers)]
        seen[command] += 1
        short = SHORT[command]
        errors = [max(r["error"], FLOOR) for r in points]
        ax.plot([r["seconds"] for r in points], errors, marker=marker, linestyle="-",
                color=colours[command], alpha=0.85, label=f"{short}: {method}")
        if all(r["vector"] is not None for r in points):
            ax.plot([r["vector"] for r in points],
                    [max(r["vector_error"] if r["vector_error"] is not None else r["error"],
                         FLOOR) for r in points],
                    marker=marker, linestyle="--", color=colours[command], alpha=0.45,
                    markerfacecolor="none")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time per call (s); dashed: vectorised, per input")
    ax.set_ylabel(f"achieved max relative error (exact results at {FLOOR:g})")
    ax.set_title("dyncalc: error against time, each method at rtol 1e-3, 1e-6, 1e-9, 1e-12")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=7.5, ncol=1, loc="center left", framealpha=0.9)
    fig.tight_layout()
    path = RESULTS / "speed_accuracy.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="fewer repeats (a rough table)")
    quick = parser.parse_args().quick
    rounds = 3 if quick else 7
    header = (f"{machine()}; command: `python benchmarks/speed_accuracy.py"
              f"{' --quick' if quick else ''}`")
    start = time.perf_counter()
    rows = []
    print(header)
    print("timing (median time per call, achieved max relative error):")
    rows += bench_pendulum(rounds)
    rows += bench_shell(rounds)
    rows += bench_rolling(rounds)
    rows += bench_fit(rounds)
    rows += bench_frame(rounds)
    rows += bench_forced(rounds)
    kernels = kernel_costs(rounds)
    print(f"one-off command lines ({len(rows)}, {2 if quick else 5} runs each) ...", flush=True)
    one_offs(rows, 2 if quick else 5)
    elapsed = time.perf_counter() - start
    table = write_table(rows, kernels, elapsed, header)
    picture = write_plot(rows)
    print(f"wrote {table.relative_to(ROOT)} and {picture.relative_to(ROOT)} in {elapsed:.0f} s")


if __name__ == "__main__":
    main()
