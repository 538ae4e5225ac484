"""A failed --check names the likely slip (issue 10); a right answer never gets a diagnosis.

Every slip of the list is produced by hand from the true answer (the slip's factor applied to
an independently computed value), checked through the CLI, and must come back as exit 1 with
the exact words in the JSON check object and after "; likely slip: " on the human check line.
"""
import json
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from helpers import invoke

TWO_PI = 2 * math.pi
G0 = 9.80665
OMEGA = math.sqrt(50)             # k = 100 N/m, m = 2 kg
MS = ("natural-frequency", "--k", "100N/m", "--m", "2kg")


def check(*args):
    """(exit code, the JSON check objects) of ``dyncalc ARGS --json``."""
    result = invoke(*args, "--json")
    assert result.exit_code in (0, 1), result.stderr
    return result.exit_code, json.loads(result.stdout)["extra"]["checks"]


def human_check_lines(*args):
    result = invoke(*args)
    assert result.exit_code in (0, 1), result.stderr
    return result.exit_code, [l for l in result.stdout.splitlines() if l.startswith("check ")]


# -- each slip recognised ---------------------------------------------------------------------

OMEGA_D = OMEGA * math.sqrt(1 - 0.3 ** 2)
PHI_0 = 0.5554797406855145        # rod-torsion-spring example, rad (tests/test_inverse: kt)
ZETA_OF_DELTA = 0.5 / math.sqrt(4 * math.pi ** 2 + 0.25)
CLOCK_J_A = 0.5 * 1 / 3 + 2 * (0.1 ** 2 + 2 * 0.9 ** 2) / 2   # m l^2/3 + M (r^2 + 2a^2)/2
DELTA_CKM = TWO_PI * (10 / (2 * math.sqrt(200))) / math.sqrt(1 - 50 / 400)

SLIPS = [
    pytest.param(MS, f"f={OMEGA!r}Hz",
                 "that is omega in rad/s, not f in Hz: f = omega / 2 pi", id="omega-for-f"),
    pytest.param(MS, f"omega={OMEGA / TWO_PI!r}rad/s",
                 "that is f in Hz, not omega in rad/s: omega = 2 pi f", id="f-for-omega"),
    pytest.param(MS, f"T={1 / OMEGA!r}s",
                 "that is 1/omega: the period is T = 2 pi / omega", id="T-as-1/omega"),
    pytest.param(MS, f"T={TWO_PI * TWO_PI / OMEGA!r}s",
                 "that is 2 pi/f: the period is T = 1 / f", id="T-as-2pi/f"),
    pytest.param((*MS, "--zeta", "0.3"), f"omega={OMEGA_D!r}rad/s",
                 "that is the damped frequency omega_d, not omega (omega_d = omega "
                 "sqrt(1 - zeta^2))", id="omega_d-for-omega"),
    pytest.param((*MS, "--zeta", "0.3"), f"omega_d={OMEGA!r}rad/s",
                 "that is the undamped natural frequency omega, not omega_d", id="omega-for-omega_d"),
    pytest.param((*MS, "--zeta", "0.3"), f"f_d={OMEGA / TWO_PI!r}Hz",
                 "that is the undamped natural frequency f, not f_d", id="f-for-f_d"),
    pytest.param((*MS, "--zeta", "0.3"), f"T_d={TWO_PI / OMEGA!r}s",
                 "that is the undamped natural period T, not T_d", id="T-for-T_d"),
    pytest.param(("damping-ratio", "--c", "10 N*s/m", "--k", "100N/m", "--m", "2kg"),
                 f"omega={OMEGA * math.sqrt(1 - 50 / 400)!r}rad/s",
                 "that is the damped frequency omega_d, not omega (omega_d = omega "
                 "sqrt(1 - zeta^2))", id="damping-ratio-omega_d-for-omega"),
    pytest.param(("natural-frequency", "--scene", "rod-torsion-spring", "m=2kg", "l=1m",
                  "kt=30 N*m/rad"), f"phi_0={math.degrees(PHI_0)!r}",
                 "a factor 180/pi: degrees and radians mixed up", id="degrees-as-radians"),
    pytest.param(("natural-frequency", "--scene", "rod-torsion-spring", "m=2kg", "l=1m",
                  "kt=30 N*m/rad"), f"phi_0={PHI_0!r}deg",
                 "a factor pi/180: degrees and radians mixed up", id="radians-as-degrees"),
    pytest.param(MS, f"omega={OMEGA / math.sqrt(1000)!r}rad/s",
                 "a factor 1/sqrt(1000): a mass in grams taken as kilograms (or the reverse)",
                 id="grams-omega-down"),
    pytest.param(MS, f"omega={OMEGA * math.sqrt(1000)!r}rad/s",
                 "a factor sqrt(1000) = 31.6: a mass in grams taken as kilograms (or the "
                 "reverse)", id="grams-omega-up"),
    pytest.param(("natural-frequency", "--scene", "clock-pendulum", "m=0.5kg", "l=1m",
                  "M=2kg", "r=0.1m", "a=0.9m"), f"J_A={1000 * CLOCK_J_A!r}kg*m^2",
                 "a factor 1000: a mass in grams taken as kilograms (or the reverse)",
                 id="grams-inertia-up"),
    pytest.param(("natural-frequency", "--scene", "pendulum-spring-dashpot", "m=2kg",
                  "a=0.5m", "k=200N/m", "d=6 N*s/m"), f"xi={6 / (8 * 2) / 1000!r}/s",
                 "a factor 1/1000: a mass in grams taken as kilograms (or the reverse)",
                 id="grams-decay-down"),
    pytest.param(("damping-ratio", "--decrement", "0.5"), "zeta=0.5",
                 "that is the logarithmic decrement per cycle (delta); zeta is about delta / "
                 "2 pi (exactly delta / sqrt(4 pi^2 + delta^2))", id="delta-as-zeta"),
    pytest.param(("damping-ratio", "--c", "10 N*s/m", "--k", "100N/m", "--m", "2kg"),
                 f"delta={DELTA_CKM / TWO_PI!r}",
                 "that is the decrement per radian (delta / 2 pi); delta is per cycle",
                 id="delta-per-radian"),
    pytest.param(("spring-series", "200N/m", "300N/m"), "k_eq=500N/m",
                 "the elements combined in parallel, not in series", id="parallel-for-series"),
    pytest.param(("spring-series", "1lbf/in", "2lbf/in"), "k_eq=3lbf/in",
                 "the elements combined in parallel, not in series", id="series-in-lbf/in"),
    pytest.param(("spring-parallel", "200N/m", "300N/m"), "k_eq=120N/m",
                 "the elements combined in series, not in parallel", id="series-for-parallel"),
    # parallel(100, 200) = 300 in series with 300 is 150 N/m; the two combined in parallel 600
    pytest.param(("spring-series", "parallel(100N/m, 200N/m)", "300N/m"), "k_eq=600N/m",
                 "the elements combined in parallel, not in series", id="nested-network"),
    pytest.param(("natural-frequency", "--scene", "coupled-blocks", "m1=1kg", "m2=2kg",
                  "k1=100N/m", "k2=200N/m", "k3=50N/m"), "f_1=10Hz",
                 "that is omega_1 in rad/s, not f_1 in Hz: f_1 = omega_1 / 2 pi",
                 id="omega_1-for-f_1"),
]


@pytest.mark.parametrize("command, spec, words", SLIPS)
def test_slip_recognised(command, spec, words):
    code, checks = check(*command, "--check", spec)
    assert code == 1
    (only,) = checks
    assert only["pass"] is False
    assert only["diagnosis"] == words
    assert set(only) == {"name", "expected", "given", "unit", "rel_diff", "rtol", "pass",
                         "diagnosis"}
    code, lines = human_check_lines(*command, "--check", spec)
    assert code == 1
    assert lines[0].endswith(f": FAIL; likely slip: {words}"), lines


def test_damped_period_slip_states_the_period_relation():
    """T given the damped period: T_d = 2 pi/omega_d = T / sqrt(1 - zeta^2) is longer than T.
    The words must not call T_d a frequency nor state T_d = T sqrt(1 - zeta^2) (that is the
    frequencies' relation, upside down for periods)."""
    _code, (only,) = check(*MS, "--zeta", "0.3", "--check", f"T={TWO_PI / OMEGA_D!r}s")
    assert only["diagnosis"] == ("that is the damped period T_d, not T "
                                 "(T_d = T / sqrt(1 - zeta^2))")


def test_the_slips_expected_value_is_the_true_one():
    """The check object reports the true answer, not the slip's value."""
    _code, (only,) = check(*MS, "--check", f"f={OMEGA!r}Hz")
    assert only["expected"] == pytest.approx(OMEGA / TWO_PI, rel=1e-15)
    assert only["given"] == pytest.approx(OMEGA, rel=1e-15)
    assert only["unit"] == "Hz"
    assert only["rel_diff"] == pytest.approx(TWO_PI - 1, rel=1e-12)


def test_slip_in_other_units():
    """424.26 rpm is 7.071 cycles a second: omega's number given as f."""
    _code, (only,) = check(*MS, "--check", f"f={60 * OMEGA!r} rpm")
    assert only["unit"] == "rpm"
    assert only["diagnosis"] == "that is omega in rad/s, not f in Hz: f = omega / 2 pi"


def test_slip_on_the_value_line_goes_to_stderr():
    result = invoke(*MS, "--value", "f", "--check", f"f={OMEGA!r}Hz")
    assert result.exit_code == 1
    assert float(result.stdout) == pytest.approx(OMEGA / TWO_PI, rel=1e-15)
    assert result.stderr.rstrip().endswith(
        "; likely slip: that is omega in rad/s, not f in Hz: f = omega / 2 pi")


def test_only_the_failed_check_is_diagnosed():
    code, checks = check(*MS, "--check", f"f={OMEGA / TWO_PI!r}Hz", "--check",
                         f"omega={OMEGA / TWO_PI!r}rad/s")
    assert code == 1
    assert checks[0]["pass"] is True and "diagnosis" not in checks[0]
    assert checks[1]["diagnosis"] == "that is f in Hz, not omega in rad/s: omega = 2 pi f"


@pytest.mark.parametrize("off, diagnosed", [(0.5, True), (3.0, False)])
def test_a_slip_matches_within_the_tolerance_only(off, diagnosed):
    """--rtol 1e-3: omega's number 0.05 % off is still that slip; 0.3 % off is not."""
    given_f = OMEGA * (1 + off * 1e-3)
    code, (only,) = check(*MS, "--rtol", "1e-3", "--check", f"f={given_f!r}Hz")
    assert code == 1
    assert ("diagnosis" in only) is diagnosed


# -- a right answer never diagnosed; a wrong one matching no slip neither ----------------------

def true_values(k, m, zeta):
    omega = math.sqrt(k / m)
    omega_d = omega * math.sqrt(1 - zeta ** 2)
    return {"omega": omega, "f": omega / TWO_PI, "T": TWO_PI / omega,
            "omega_d": omega_d, "f_d": omega_d / TWO_PI, "T_d": TWO_PI / omega_d}


UNITS = {"omega": "rad/s", "f": "Hz", "T": "s", "omega_d": "rad/s", "f_d": "Hz", "T_d": "s"}


@settings(max_examples=60, deadline=None)
@given(k=st.floats(1e-2, 1e6), m=st.floats(1e-3, 1e4), zeta=st.floats(0, 0.95),
       name=st.sampled_from(sorted(UNITS)), u=st.floats(-0.9, 0.9),
       rtol=st.sampled_from([None, 1e-2, 1e-4, 0.2]))
def test_right_answer_is_never_diagnosed(k, m, zeta, name, u, rtol):
    """The true answer (SCENES.md formulas), moved by less than the tolerance, passes: exit 0
    and no diagnosis, whatever slips happen to lie near it (with --rtol 0.2, omega_d lies
    within the tolerance of omega for small zeta)."""
    tol = 1e-2 if rtol is None else rtol
    value = true_values(k, m, zeta)[name] * (1 + u * tol)
    args = ["natural-frequency", "--k", f"{k!r} N/m", "--m", f"{m!r} kg", "--zeta",
            repr(zeta), "--check", f"{name}={value!r} {UNITS[name]}"]
    if rtol is not None:
        args += ["--rtol", repr(rtol)]
    code, (only,) = check(*args)
    assert code == 0 and only["pass"] is True
    assert "diagnosis" not in only


@settings(max_examples=30, deadline=None)
@given(k1=st.floats(1, 1e5), k2=st.floats(1, 1e5), u=st.floats(-0.9, 0.9))
def test_right_spring_network_answer_is_never_diagnosed(k1, k2, u):
    k_eq = 1 / (1 / k1 + 1 / k2) * (1 + u * 1e-2)
    code, (only,) = check("spring-series", f"{k1!r}N/m", f"{k2!r}N/m", "--check",
                          f"k_eq={k_eq!r}N/m")
    assert code == 0 and "diagnosis" not in only


@settings(max_examples=40, deadline=None)
@given(k=st.floats(1e-2, 1e6), m=st.floats(1e-3, 1e4), zeta=st.floats(0, 0.3),
       name=st.sampled_from(sorted(UNITS)),
       factor=st.one_of(st.floats(1.2, 1.5), st.floats(0.5, 0.8), st.floats(2.0, 5.0)))
def test_wrong_answer_matching_no_slip_has_no_diagnosis(k, m, zeta, name, factor):
    """Factors 0.5-0.8, 1.2-1.5 and 2-5 are none of the slips (2 pi, 180/pi, 1000, sqrt(1000)
    and their inverses; sqrt(1 - zeta^2) >= 0.95 for zeta <= 0.3): fail, no diagnosis."""
    value = true_values(k, m, zeta)[name] * factor
    args = ("natural-frequency", "--k", f"{k!r} N/m", "--m", f"{m!r} kg", "--zeta",
            repr(zeta), "--check", f"{name}={value!r} {UNITS[name]}")
    code, (only,) = check(*args)
    assert code == 1 and only["pass"] is False
    assert "diagnosis" not in only
    _code, lines = human_check_lines(*args)
    assert lines[0].endswith(": FAIL"), lines


def test_wrong_network_answer_matching_no_slip():
    """150 N/m is the answer; 200 N/m is no slip of the list. 366.67 N/m is every combination
    swapped (series(100, 200) = 66.67 in parallel with 300), which is one."""
    code, (only,) = check("spring-series", "parallel(100N/m, 200N/m)", "300N/m",
                          "--check", "k_eq=200N/m")
    assert code == 1 and "diagnosis" not in only
    code, (only,) = check("spring-series", "parallel(100N/m, 200N/m)", "300N/m",
                          "--check", "k_eq=366.6667N/m")
    assert code == 1
    assert only["diagnosis"] == "series and parallel swapped throughout the network"


def test_nested_network_swapped_throughout():
    """parallel(100, 200) in series with 300 and 400 N/m is 109.09 N/m; with every rule
    swapped, series(100, 200) = 66.67 N/m in parallel with 300 and 400 gives 766.67 N/m."""
    from click.testing import CliRunner

    from dyncalc.cli import cli

    swapped = 100 * 200 / 300 + 300 + 400
    result = CliRunner().invoke(cli, ["spring-series", "parallel(100N/m, 200N/m)", "300N/m",
                                      "400N/m", "--check", f"k_eq={swapped!r}N/m", "--json"])
    assert result.exit_code == 1
    check = json.loads(result.output)["extra"]["checks"][0]
    assert check["diagnosis"] == "series and parallel swapped throughout the network"
