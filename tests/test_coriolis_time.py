"""``coriolis`` with the motion given in time (SPEC "Motion given in time"): ``--r``,
``--omega``, ``--R0`` as expressions in ``t``, ``--t``, ``--basis``, tables over times,
``--plot``.

Every reference is found independently of dyncalc's sympy derivatives: the point's absolute
position written out in the fixed frame (its own rotation matrix, by hand or by an independent
quaternion integration with scipy) and differentiated by central finite differences (step
1e-4 s: truncation ~1e-8 relative, rounding ~1e-12), then compared in the fixed basis.
"""
import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import error_line, invoke

ROOT = Path(__file__).resolve().parents[1]
H = 1e-4  # finite-difference step (s)


def run(*args):
    result = invoke("coriolis", *args, "--json")
    assert result.exit_code == 0, result.output + result.stderr
    data = json.loads(result.stdout)
    return {name: np.array(item["value"]) if isinstance(item["value"], list)
            else item["value"] for name, item in data["results"].items()}, data


def results(*args):
    return run(*args)[0]


def Rz(angle):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def derivatives(position, t):
    """Velocity and acceleration of ``position(t)`` by central differences."""
    p0, pp, pm = position(t), position(t + H), position(t - H)
    return (pp - pm) / (2 * H), (pp - 2 * p0 + pm) / H ** 2


def check_fixed(args, position, t, rtol=1e-6):
    """The command's v and a in the fixed basis against finite differences of ``position``."""
    got = results(*args, "--basis", "fixed")
    v, a = derivatives(position, t)
    scale_v, scale_a = np.linalg.norm(v), np.linalg.norm(a)
    assert np.allclose(got["R"], position(t), rtol=0, atol=1e-12 * max(1, np.linalg.norm(
        position(t))))
    assert np.allclose(got["v"], v, rtol=0, atol=rtol * scale_v)
    assert np.allclose(got["a"], a, rtol=0, atol=rtol * scale_a)
    assert got["v_mag"] == pytest.approx(scale_v, rel=rtol)
    assert got["a_mag"] == pytest.approx(scale_a, rel=rtol)
    return got


# --- chapter 6, worked into parameters ----------------------------------------------------


def test_slider_in_a_rotating_slot():
    """A slider moving in a slot, s = s0 - b t^2/2, the slot turning at w (E6.6-type)."""
    s0, b, w, t = 4.0, 0.5, 2.0, 2.0
    args = ["--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "b=0.5m/s^2", "--omega", "0,0,w",
            "w=2rad/s", "--t", "2s"]

    def position(s):
        return Rz(w * s) @ np.array([s0 - b * s * s / 2, 0.0, 0.0])

    check_fixed(args, position, t)
    got = results(*args)
    # in the slot's own axes, by hand: radial a = -b - w^2 s, across 2 w s'
    s, sd = s0 - b * t * t / 2, -b * t
    assert got["a"].tolist() == pytest.approx([-b - w * w * s, 2 * w * sd, 0.0], abs=1e-14)
    assert got["a_c"].tolist() == pytest.approx([0.0, 2 * w * sd, 0.0], abs=1e-14)
    assert got["theta"] == pytest.approx(w * t, rel=1e-15)


def test_point_on_a_circle_drawn_on_a_rotating_platform():
    """A point running round a circle (radius R, centre at e from the axis) drawn on a
    platform turning at W (E6.10-type)."""
    e, R, w2, W, t = 0.5, 0.2, 3.0, 1.5, 0.7
    args = ["--r", "e + R*cos(w2*t), R*sin(w2*t), 0 m", "e=0.5m", "R=0.2m", "w2=3rad/s",
            "--omega", "0, 0, W", "W=1.5rad/s", "--t", "0.7s"]

    def position(s):
        return Rz(W * s) @ np.array([e + R * math.cos(w2 * s), R * math.sin(w2 * s), 0.0])

    check_fixed(args, position, t)


def test_trolley_on_a_crane_that_starts_to_turn():
    """A trolley moving out along a crane's arm at u while the crane starts from rest with
    angular acceleration k: Omega = k t, theta = k t^2/2 (exact through sympy's integral)."""
    s0, u, k, t = 2.0, 0.4, 0.05, 3.0
    args = ["--r", "s0 + u*t, 0, 0 m", "s0=2m", "u=0.4m/s", "--omega", "0, 0, k*t",
            "k=0.05rad/s^2", "--t", "3s"]

    def position(s):
        return Rz(k * s * s / 2) @ np.array([s0 + u * s, 0.0, 0.0])

    got = check_fixed(args, position, t)
    assert got["theta"] == pytest.approx(k * t * t / 2, rel=1e-15)
    rot = results(*args)
    x = s0 + u * t
    assert rot["alpha"].tolist() == pytest.approx([0.0, 0.0, k], abs=1e-15)
    assert rot["a_euler"].tolist() == pytest.approx([0.0, k * x, 0.0], rel=1e-14)


def test_drum_turning_while_its_frame_translates():
    """A point on the rim of a drum (radius R) turning at w while the frame carrying its axle
    accelerates from rest with a0 along x (E6.12-type): R0 = a0 t^2/2 in fixed components."""
    R, w, a0, t = 0.3, 4.0, 1.2, 1.1
    args = ["--r", "0.3, 0, 0 m", "--omega", "0,0,4 rad/s", "--R0", "a0*t^2/2, 0, 0 m",
            "a0=1.2m/s^2", "--t", "1.1s"]

    def position(s):
        return np.array([a0 * s * s / 2, 0.0, 0.0]) + Rz(w * s) @ np.array([R, 0.0, 0.0])

    got = check_fixed(args, position, t)
    assert got["v0"].tolist() == pytest.approx([a0 * t, 0.0, 0.0], rel=1e-15)
    assert got["a0"].tolist() == pytest.approx([a0, 0.0, 0.0], rel=1e-15)


def test_point_on_a_disk_on_a_rotating_disk():
    """A disk spinning at w2 about a horizontal axis, carried at e on a turntable turning at W
    (E6.6): the point on its rim moves out of the turntable's plane."""
    e, R, w2, W, t = 0.4, 0.1, 5.0, 2.0, 0.3
    args = ["--r", "e, R*cos(w2*t), R*sin(w2*t) m", "e=0.4m", "R=0.1m", "w2=5rad/s",
            "--omega", "0, 0, W", "W=2rad/s", "--t", "0.3s", "--mass", "2kg"]

    def position(s):
        return Rz(W * s) @ np.array([e, R * math.cos(w2 * s), R * math.sin(w2 * s)])

    got = check_fixed(args, position, t)
    rot = results(*args)
    v_r = np.array([0.0, -R * w2 * math.sin(w2 * t), R * w2 * math.cos(w2 * t)])
    assert rot["a_c"].tolist() == pytest.approx(2 * np.cross([0, 0, W], v_r), abs=1e-14)
    assert rot["F_c"].tolist() == pytest.approx(-2 * rot["a_c"], abs=1e-14)
    assert got["F_c_mag"] == pytest.approx(2 * np.linalg.norm(rot["a_c"]), rel=1e-15)


def _quaternion_rotation(omega, t):
    """The rotation of a frame with body rate ``omega(s)``, integrated as a unit quaternion
    (q' = q (0, Omega)/2) with scipy: independent of dyncalc's Q' = Q [Omega]x."""
    from scipy.integrate import solve_ivp

    def rhs(s, q):
        w0, x, y, z = q
        p, qq, r = omega(s)
        return 0.5 * np.array([-x * p - y * qq - z * r, w0 * p + y * r - z * qq,
                               w0 * qq + z * p - x * r, w0 * r + x * qq - y * p])

    q = solve_ivp(rhs, (0, t), [1.0, 0, 0, 0], rtol=1e-13, atol=1e-15, method="DOP853").y[:, -1]
    w0, x, y, z = q / np.linalg.norm(q)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - z * w0), 2 * (x * z + y * w0)],
                     [2 * (x * y + z * w0), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w0)],
                     [2 * (x * z - y * w0), 2 * (y * z + x * w0), 1 - 2 * (x * x + y * y)]])


def test_an_axis_that_turns_in_time_is_integrated_numerically_and_says_so():
    w, k, t = 1.0, 1.3, 2.0
    args = ["--r", "0.3 m + 0.1 m/s*t, 0, 0 m", "--omega", "0, w*sin(k*t), w", "w=1rad/s",
            "k=1.3rad/s", "--t", "2s"]
    got, data = run(*args, "--basis", "fixed")
    assert data["extra"]["rotation"] == "numerical"
    assert any("integrated numerically" in warning for warning in data["warnings"])
    Q = _quaternion_rotation(lambda s: (0.0, w * math.sin(k * s), w), t)
    assert np.allclose(got["R"], Q @ np.array([0.3 + 0.1 * t, 0, 0]), atol=1e-10)
    rot = results(*args)
    assert np.allclose(got["a"], Q @ rot["a"], atol=1e-10)
    assert np.allclose(got["v"], Q @ rot["v"], atol=1e-10)


def test_a_time_too_many_turns_away_on_a_turning_axis_is_refused_not_integrated_for_hours():
    # t = 1e150 s needs ~1e150 turns: the integration stops at RATE_EVALUATIONS calls of the
    # rate (about a second) with a one-line refusal; a time within reach still integrates
    args = ["--r", "0.3 m + 0.1 m/s*t, 0, 0 m", "--omega", "0, w*sin(k*t), w", "w=1rad/s",
            "k=1.3rad/s", "--basis", "fixed", "--value", "v"]
    for t in ("1e150s", "-1e150s"):
        result = invoke("coriolis", *args, "--t", t)
        assert result.exit_code == 2
        assert error_line(result) == (
            f"Error: the frame's rotation could not be integrated to t = {float(t[:-1]):g} s: "
            "the axis turns in time and reaching t needs more than 50,000 evaluations of the "
            "rate (too many turns); ask for a time nearer 0")
    assert invoke("coriolis", *args, "--t", "20s").exit_code == 0


# --- derivatives, bases, units --------------------------------------------------------------


MOTION = ["--r", "A*cos(p*t) + c*t^3, B*exp(-t/T), sqrt(1 m^2 + (c*t^3)^2) m", "A=0.3m",
          "p=2rad/s", "c=0.05m/s^3", "B=0.2m", "T=1.5s",
          "--omega", "W*sin(q*t), 0.2 rad/s, W", "W=0.7rad/s", "q=0.9rad/s",
          "--R0", "U*t, V*t^2, 0 m", "U=1.1m/s", "V=-0.3m/s^2"]


def at(t, *extra):
    return results(*MOTION, "--t", f"{t!r}s", *extra)


def test_every_derivative_against_finite_differences():
    t = 0.8
    now, plus, minus = at(t), at(t + H), at(t - H)
    assert np.allclose(now["v_r"], (plus["r"] - minus["r"]) / (2 * H), rtol=0, atol=1e-8)
    assert np.allclose(now["a_r"], (plus["r"] - 2 * now["r"] + minus["r"]) / H ** 2,
                       rtol=0, atol=1e-6)
    assert np.allclose(now["alpha"], (plus["Omega"] - minus["Omega"]) / (2 * H), rtol=0,
                       atol=1e-8)
    # v0 and a0: the origin's own motion, read through R with the point at the origin
    origin = ["--r", "0,0,0 m", *MOTION[MOTION.index("--omega"):]]
    fixed = [results(*origin, "--t", f"{s!r}s", "--basis", "fixed") for s in (t - H, t, t + H)]
    v0 = (fixed[2]["R"] - fixed[0]["R"]) / (2 * H)
    a0 = (fixed[2]["R"] - 2 * fixed[1]["R"] + fixed[0]["R"]) / H ** 2
    assert np.allclose(fixed[1]["v0"], v0, atol=1e-8)
    assert np.allclose(fixed[1]["a0"], a0, atol=1e-6)
    assert fixed[1]["v0"].tolist() == pytest.approx([1.1, -0.6 * t, 0.0], abs=1e-15)


def test_rotating_and_fixed_bases_differ_by_the_frame_rotation():
    args = ["--r", "s0 - b*t^2/2, 0.1 m, 0 m", "s0=4m", "b=0.5m/s^2", "--omega",
            "0, 0, k*t", "k=0.4rad/s^2", "--R0", "t*1 m/s, 0, 0", "--t", "1.7s", "--mass",
            "3kg"]
    rot, data = run(*args)
    fixed, fdata = run(*args, "--basis", "fixed")
    Q = Rz(0.4 * 1.7 ** 2 / 2)  # theta = k t^2/2, by hand
    assert np.allclose(fdata["extra"]["rotation_matrix"], Q, atol=1e-15)
    for name, value in rot.items():
        if isinstance(value, np.ndarray):
            assert np.allclose(fixed[name], Q @ value, rtol=0, atol=1e-13 * (
                1 + np.linalg.norm(value))), name
        else:
            assert fixed[name] == pytest.approx(value, rel=1e-14), name


def test_unit_invariance():
    base = results("--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "b=0.5m/s^2", "--omega",
                   "0, 0, 2 rad/s", "--t", "2s")
    other = results("--r", "(s0 - b*t^2/2, 0, 0) mm", "s0=400cm", "b=1800 m/min^2",
                    "--omega", "0, 0, 60/pi rpm", "--t", "2000ms")
    for name, value in base.items():
        assert np.allclose(other[name], value, rtol=1e-13, atol=1e-13), name


# --- tables and plots -----------------------------------------------------------------------


def test_a_list_of_times_is_a_table_one_row_per_time():
    args = ["coriolis", "--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "b=0.5m/s^2", "--omega",
            "0,0,2 rad/s"]
    table = invoke(*args, "--t", "0, 1, 2 s")
    assert table.exit_code == 0, table.stderr
    lines = table.stdout.splitlines()
    assert lines[0].startswith("t,r [m],v_r [m/s],")
    assert [line.split(",")[0] for line in lines[1:]] == ["0 s", "1 s", "2 s"]
    for line, t in zip(lines[1:], (0.0, 1.0, 2.0)):
        one = results(*args[1:], "--t", f"{t}s")
        assert f'"{",".join(repr(float(x)) for x in one["v"])}"' in line


def test_batch_over_times_with_a_parameter_column(tmp_path):
    rows = tmp_path / "times.csv"
    rows.write_text("t [s],b [m/s^2]\n1,0.5\n2,1\n")
    out = invoke("coriolis", "--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "b=0.5m/s^2", "--omega",
                 "0,0,2 rad/s", "--batch", str(rows), "--json")
    assert out.exit_code == 0, out.stderr
    got = [json.loads(line) for line in out.stdout.splitlines()]
    assert [g["results"]["r"]["value"][0] for g in got] == [4 - 0.5 / 2, 4 - 1 * 4 / 2]
    assert [g["results"]["v_r"]["value"][0] for g in got] == [-0.5, -2.0]


def test_plot_writes_the_path(tmp_path):
    target = tmp_path / "path.png"
    out = invoke("coriolis", "--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "b=0.5m/s^2", "--omega",
                 "0,0,2 rad/s", "--t", "2s", "--plot", str(target), "--json")
    assert out.exit_code == 0, out.stderr
    assert json.loads(out.stdout)["extra"]["plot"] == str(target)
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_plot_window():
    from dyncalc.commands.coriolis_time import plot_window

    assert plot_window(2.0, 2.0, 6.0, 13.0) == (2.0 - math.pi / 2, 2.0 + math.pi / 2,
                                                "one turn of the frame centred on t")
    assert plot_window(0.5, 0.0, 3.0, 1.5) == (0.0, 2.5, "t +- |v|/|a|, from t = 0")
    assert plot_window(-1.0, 0.0, 0.0, 0.0) == (-2.0, 0.0, "t +- 1 s")


# --- refusals -------------------------------------------------------------------------------


@pytest.mark.parametrize("args, message", [
    (["--r", "s0*t, 0, 0 m", "s0=4m", "--t", "1s"],
     "Error: --r component 1 's0*t' must be a length ([length]); got [length]*[time]"),
    (["--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "b=1m/s^2"],
     "Error: --r: component 1 depends on t: motion given in time needs --t (the time to "
     "evaluate at)"),
    (["--R0", "1, 0, 0 m"],
     "Error: --t is missing: --R0 is a motion given in time; give the time to evaluate it at, "
     "e.g. --t 2s"),
    (["--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m", "--t", "2s"],
     "Error: --r component 1: unknown name 'b' (the names here are pi, s0, t) at column 6: "
     "'s0 - b*t^2/2'"),
    (["--r", "s0 - t*1 m/s, 0, 0 m", "s0=4m", "q=2m", "--t", "2s"],
     "Error: q= is not used by --r, --omega or --R0: leave it out or use it in an expression"),
    (["--r", "1 m + t*1 m/s, 0, 0 m", "--vr", "1,0,0 m/s", "--t", "2s"],
     "Error: --vr does not go with a motion given in time: v_r = r' is derived from the "
     "expressions"),
    (["--r", "1 m + t*1 m/s, 0, 0 kg", "--t", "2s"],
     "Error: --r: the unit kg is not a length ([length]); give the components in m"),
    (["--omega", "0,0,2 rad/s", "--vr", "1,0,0 m/s", "--basis", "fixed"],
     "Error: --basis goes with a motion given in time (--t): constant vectors are given and "
     "shown in one frame's components"),
    (["--r", "1 m + t*1 m/s, 0, 0 m", "--t", "0, 1 s", "--plot", "x.png"],
     "Error: --plot draws one time: give --t a single time (not a list or --batch)"),
    (["--r", "1 m + t*1 m/s, 0, 0 m", "--t", "2 kg"],
     "Error: --t must be a time [time]; got 2 kilogram ([mass])"),
])
def test_refusals(args, message):
    assert error_line(invoke("coriolis", *args)) == message


def test_no_sympy_off_the_time_path():
    """sympy loads for a motion given in time only: not for vectors, expressions without t,
    the scenes or --help (tests/test_eom.py holds eom's side)."""
    code = ("import sys, json\nfrom click.testing import CliRunner\nfrom dyncalc.cli import cli\n"
            "r = CliRunner().invoke(cli, {args!r})\nassert r.exit_code == 0, r.output\n"
            "print(json.dumps('sympy' in sys.modules))")

    def loads(args):
        proc = subprocess.run([sys.executable, "-c", code.format(args=args)],
                              capture_output=True, text=True, timeout=120,
                              env={**os.environ, "PYTHONPATH": str(ROOT)})
        assert proc.returncode == 0, proc.stderr
        return json.loads(proc.stdout.strip().splitlines()[-1])

    for args in (["coriolis", "--omega", "0,0,2rad/s", "--vr", "1,0,0m/s", "--r",
                  "l*cos(30deg), 0, 0 m", "l=2m"],
                 ["coriolis", "--scene", "slotted-link", "d=4m", "c=3m", "theta=90deg",
                  "omega=1rad/s"],
                 ["coriolis", "--help"]):
        assert loads(args) is False, args
    assert loads(["coriolis", "--r", "1 m + t*1 m/s, 0, 0 m", "--t", "1s"]) is True


def test_the_plotted_path_is_the_position_R():
    """The path --plot draws (one integration through every time when the axis turns) is the
    result R of a one-off at each time, before and after t = 0."""
    from dyncalc.commands.coriolis_time import read_time
    from dyncalc.physics.relative_time import motion_in_time

    texts = {"r": "0.3 m + 0.1 m/s*t, 0, 0 m", "omega": "0, w*sin(k*t), w", "t": "1s"}
    words = ("w=1rad/s", "k=1.3rad/s")
    inputs = read_time(texts, words)
    motion = motion_in_time(inputs.vectors["r"], inputs.vectors["omega"], None, inputs.params)
    times = [-0.7, 0.0, 0.4, 1.9]
    path = motion.positions(times)
    for s, point in zip(times, path):
        one = results("--r", texts["r"], "--omega", texts["omega"], *words, "--t", f"{s}s",
                      "--basis", "fixed")
        assert np.allclose(point, one["R"], rtol=0, atol=1e-10), s


def test_an_uncertain_mass_carries_to_the_coriolis_force_only():
    """F_c = -m a_c: u(F_c_mag) = u(m) |a_c| exactly; nothing else depends on m."""
    out = invoke("coriolis", "--mass", "2kg ± 1%", "--r", "s0 - b*t^2/2, 0, 0 m", "s0=4m",
                 "b=0.5m/s^2", "--omega", "0, 0, 2 rad/s", "--t", "2s", "--value", "F_c_mag",
                 "--value", "u(F_c_mag)", "--value", "u(a_mag)")
    assert out.exit_code == 0, out.stderr
    assert [float(x) for x in out.stdout.split()] == [8.0, 0.02 * 4.0, 0.0]
    assert error_line(invoke("coriolis", "--r", "s0 - t*1 m/s, 0, 0 m", "s0=4m ± 1%", "--t",
                             "2s")) == ("Error: s0=: an uncertainty is not propagated through a "
                                        "motion given in time; give the value alone (--mass "
                                        "may carry one)")


def test_an_angle_without_a_usable_closed_form_is_found_by_quadrature():
    """sympy integrates sqrt(1 + t^4) to a hypergeometric function: the angle turned then
    comes from adaptive quadrature, against mpmath's."""
    import mpmath

    got, data = run("--r", "1,0,0 m", "--omega", "0,0,sqrt(1 + (q*t)^4) rad/s", "q=1rad/s",
                    "--t", "2s")
    assert data["extra"]["rotation"] == "quadrature"
    assert got["theta"] == pytest.approx(float(mpmath.quad(lambda x: mpmath.sqrt(1 + x ** 4),
                                                           [0, 2])), rel=1e-12)


def test_an_integral_sympy_takes_too_long_over_falls_back_to_quadrature(monkeypatch):
    """sympy's integrate gets INTEGRAL_BUDGET seconds; past it the angle comes from quadrature
    (never a hang). Here integrate is made to stall, and the budget is short."""
    import time

    import sympy

    from dyncalc.physics import relative_time

    def stall(*args, **kwargs):
        time.sleep(30)

    monkeypatch.setattr(relative_time, "INTEGRAL_BUDGET", 0.2)
    monkeypatch.setattr(relative_time, "_DERIVED", {})  # derived afresh, not remembered
    monkeypatch.setattr(sympy, "integrate", stall)
    started = time.monotonic()
    got, data = run("--r", "1,0,0 m", "--omega", "0,0,k*t rad/s", "k=1rad/s^2", "--t", "2s")
    assert time.monotonic() - started < 20  # the 30 s stall was cut short
    assert data["extra"]["rotation"] == "quadrature"
    assert got["theta"] == pytest.approx(2.0, rel=1e-12)  # int_0^2 t dt
