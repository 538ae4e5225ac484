"""``dyncalc forced-response``: the refusals with their exact messages and exit status, unit
invariance, the textbook scenes (E5.21-E5.24), inverse problems, explain, batch and the
Python API; numbers checked against independent derivations (complex frequency response,
mpmath)."""
import json
import math

import mpmath
import pytest
from click.testing import CliRunner

import dyncalc
from dyncalc.cli import cli


def run(*args):
    return CliRunner().invoke(cli, ["forced-response", *args])


def results(*args):
    result = run(*args, "--json")
    assert result.exit_code == 0, result.stderr
    data = json.loads(result.stdout)
    assert data["schema"] == "dyncalc/2" and data["command"] == "forced-response"
    return {n: r["value"] for n, r in data["results"].items()}


BASE = ("--k", "40kN/m", "--m", "40kg")


@pytest.mark.parametrize("args, message", [
    ((*BASE, "--F0", "1N", "--base", "1mm", "--Omega", "1rad/s"),
     "forced-response takes one excitation, not 2: got --F0 and --base; give one of --F0 "
     "FORCE, --base U0, --base-accel B0 or --unbalance ME"),
    ((*BASE, "--Omega", "1rad/s"),
     "forced-response needs one excitation: --F0 FORCE, --base U0, --base-accel B0 or "
     "--unbalance ME"),
    ((*BASE, "--F0", "1N", "--Omega", "1rad/s", "--f-exc", "1Hz"),
     "give the excitation frequency as --Omega or as --f-exc, not both"),
    ((*BASE, "--F0", "1N"),
     "forced-response needs the excitation frequency: --Omega W (rad/s, rpm) or --f-exc F "
     "(Hz)"),
    ((*BASE, "--zeta", "-0.1", "--F0", "1N", "--Omega", "2rad/s"),
     "--zeta must not be negative; got -0.1"),
    ((*BASE, "--F0", "1N", "--Omega", "2Hz"),
     "--Omega is an angular rate; give it in rad/s, deg/s, rpm or rev/s, not Hz (a frequency "
     "in cycles)"),
    (("--k", "1N/m", "--F0", "1N", "--Omega", "2rad/s"),
     "--k needs --m: together they give the natural frequency sqrt(k/m)"),
    (("--omega", "1rad/s", "--unbalance", "1kg*m", "--Omega", "2rad/s"),
     "--unbalance needs --m (the whole machine's mass): X = (m_u e / m) V"),
    ((*BASE, "--zeta", "0.1", "--c", "1N*s/m", "--F0", "1N", "--Omega", "2rad/s"),
     "give the damping as one of --zeta, --c and --Q, not 2: got --zeta and --c"),
    ((*BASE, "--F0", "1N", "--Omega", "2rad/s", "--x0", "1mm"),
     "--x0 and --v0 give the total response at a time: give --t TIME too"),
    (("--m", "1kg", "--F0", "1N", "--Omega", "2rad/s"),
     "forced-response needs the natural frequency: --k K --m M, or --omega OMEGA_N (with --m "
     "M for the amplitude of a force or an unbalance)"),
    ((*BASE, "--omega", "1rad/s", "--F0", "1N", "--Omega", "2rad/s"),
     "give the natural frequency as --k and --m or as --omega, not both"),
    (("--k", "100N/m", "--m", "1kg", "--F0", "1N", "--Omega", "10rad/s"),
     "undamped at resonance (Omega = omega = 10 rad/s): the steady state does not exist, the "
     "amplitude grows without bound; give damping (zeta, c or Q), another excitation "
     "frequency, or a time t for the growing response"),
    (("--scene", "coupled-blocks", "m1=1kg", "m2=1kg", "k1=1N/m", "k2=1N/m", "k3=1N/m"),
     "forced-response --scene takes a scene with one degree of freedom; coupled-blocks has "
     "more than one (modes gives its frequencies and mode shapes), so it has no single effective mass "
     "and stiffness to drive"),
    (("--scene", "quarter-car", "k=40kN/m", "m=400kg", "L=10m", "U0=2cm", "v0=20m/s", "--F0",
      "1N"),
     "--F0 does not go with --scene quarter-car: the scene has its own forcing; its "
     "parameters are k [force]/[length], m [mass], L [length], U0 [length], v0 "
     "[length]/[time], zeta dimensionless = 0, c [force]*[time]/[length]?, Q dimensionless?"),
])
def test_refusals(args, message):
    result = run(*args)
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr == f"Error: {message}\n"


def reference(kind, k, m, zeta, W, amp):
    """X, phi, TR, F_T from the complex frequency response at 30 digits."""
    mpmath.mp.dps = 30
    omega = mpmath.sqrt(mpmath.mpf(k) / m)
    eta = W / omega
    h = 1 / mpmath.mpc(1 - eta**2, 2 * zeta * eta)
    tr = abs(mpmath.mpc(1, 2 * zeta * eta) * h)
    if kind == "force":
        x = amp / k * h
        ft = amp * tr
    elif kind == "unbalance":
        x = amp / m * eta**2 * h
        ft = amp * W**2 * tr
    else:  # base motion
        x = amp * mpmath.mpc(1, 2 * zeta * eta) * h
        ft = m * W**2 * abs(x)
    return {"X": abs(x), "phi": -mpmath.arg(x), "TR": tr, "F_T": ft}


@pytest.mark.parametrize("kind, option, amp", [("force", "--F0", 100.0),
                                               ("unbalance", "--unbalance", 0.01),
                                               ("base", "--base", 0.002)])
def test_numbers_against_the_complex_response(kind, option, amp):
    got = results(*BASE, "--zeta", "0.05", option, repr(amp), "--Omega", "157rad/s")
    ref = reference(kind, 40000.0, 40.0, 0.05, 157.0, amp)
    for name, value in ref.items():
        assert got[name] == pytest.approx(float(value), rel=1e-13), name


#: The pound-force and the pound (exact by definition) and the inch.
LBF, LB, INCH = 4.4482216152605, 0.45359237, 0.0254


@pytest.mark.parametrize("typed", [
    ("--k", "40kN/m", "--m", "40kg", "--Omega", "1500rpm", "--F0", "100N"),
    ("--k", f"{40000 * INCH / LBF!r} lbf/in", "--m", f"{40 / LB!r} lb", "--Omega",
     f"{50 * math.pi!r} rad/s", "--F0", f"{100 / LBF!r} lbf"),
    ("--k", "40000 N/m", "--m", "40kg", "--f-exc", "25Hz", "--F0", "0.1kN"),
])
def test_unit_invariance(typed):
    """The same machine typed in rpm, rad/s or Hz, N or lbf, N/m or lbf/in: the same SI
    results (to the rounding of the conversions)."""
    got = results(*typed, "--zeta", "0.05")
    ref = results("--k", "40000", "--m", "40", "--Omega", repr(50 * math.pi), "--F0", "100",
                  "--zeta", "0.05")
    assert set(got) == set(ref)
    for name in ref:
        assert got[name] == pytest.approx(ref[name], rel=1e-12), name


def test_omega_in_hz_and_f_exc_agree_exactly():
    a = results(*BASE, "--zeta", "0.1", "--F0", "1N", "--f-exc", "3Hz")
    b = results(*BASE, "--zeta", "0.1", "--F0", "1N", "--Omega", "180rpm")
    for name in a:
        assert a[name] == pytest.approx(b[name], rel=1e-15)


def test_quarter_car_e5_23_undamped_is_the_catalog_scene_and_damping_lowers_it():
    words = ("--scene", "quarter-car", "k=40kN/m", "m=400kg", "L=10m", "U0=2cm", "v0=20m/s")
    undamped = results(*words)
    # SCENES.md: x_amp = U0/|1 - Omega^2/omega^2|, Omega = 2 pi v0/L = 4 pi, omega = 10
    assert undamped["x_amp"] == pytest.approx(0.02 / abs(1 - (4 * math.pi) ** 2 / 100),
                                              rel=1e-14)
    damped = results(*words, "--zeta", "0.2")
    eta = 4 * math.pi / 10
    assert damped["x_amp"] == pytest.approx(
        0.02 * math.hypot(1, 0.4 * eta) / math.hypot(1 - eta**2, 0.4 * eta), rel=1e-14)
    assert damped["v_crit"] == pytest.approx(100 / (2 * math.pi), rel=1e-15)


def test_frame_brace_damper_e5_21():
    """E5.21: y0 = 2 m b0 / k = 5 mm, y_max = y0 / (2 zeta sqrt(1 - zeta^2)) at
    zeta = (d/2) sqrt(1/(2 k m)) = 0.0707."""
    got = results("--scene", "frame-brace-damper", "m=500kg", "k=200 kN/m", "d=2 kN*s/m",
                  "b0=1 m/s^2", "--Omega", "14rad/s")
    zeta = 1000 * math.sqrt(1 / (2 * 200e3 * 500))
    assert got["zeta"] == pytest.approx(zeta, rel=1e-15)
    assert got["y0"] == pytest.approx(0.005, rel=1e-15)
    assert got["y_max"] == pytest.approx(0.005 / (2 * zeta * math.sqrt(1 - zeta**2)),
                                         rel=1e-14)
    # at 14 rad/s, the amplitude relative to the ground from the complex response
    eta = 14 / math.sqrt(200e3 / 1000)
    assert got["X"] == pytest.approx(0.005 / abs(complex(1 - eta**2, 2 * zeta * eta)),
                                     rel=1e-14)


def test_given_response_e5_22():
    before = results("--scene", "E5.22", "m=4kg", "k=1N/m", "x0=1m", "t0=1s", "T=2s",
                     "t=1s")
    after = results("--scene", "E5.22", "m=4kg", "k=1N/m", "x0=1m", "t0=1s", "T=2s", "t=5s")
    assert before["F"] == 0.0 and after["F"] == 20.0   # the book: 0 N, then 20 N
    assert after["x"] == pytest.approx(math.cos(2.5) + 20 * (1 - math.cos(1.5)), rel=1e-14)


def test_rolling_wheel_e5_24_book_forms():
    got = results("--scene", "E5.24", "m=2kg", "k=300N/m", "u0=1cm", "Omega=20rad/s")
    k, m, u0, W, g = 300.0, 2.0, 0.01, 20.0, 9.80665
    assert got["x_amp"] == pytest.approx(u0 / (3 * abs(2 * k / (3 * m * W**2) - 1)),
                                         rel=1e-14)
    assert got["mu0"] == pytest.approx(
        u0 * W**2 / (3 * g) * abs((k / (m * W**2) - 1) / (2 * k / (3 * m * W**2) - 1)),
        rel=1e-14)


def test_inverse_mount_for_90_percent_isolation():
    got = results("TR=0.1", "--zeta", "0.05", "--Omega", "1500rpm", "--m", "40kg", "k=?")
    k = got["k"]
    W = 50 * math.pi
    eta = W / math.sqrt(k / 40)
    tr = math.hypot(1, 0.1 * eta) / math.hypot(1 - eta**2, 0.1 * eta)
    assert tr == pytest.approx(0.1, rel=1e-12)


def test_inverse_for_zeta_and_omega_from_x():
    got = results(*BASE, "--F0", "100N", "--Omega", "30rad/s", "X=5mm", "zeta=?")
    eta = 30 / math.sqrt(1000)
    assert 100 / 40000 / math.hypot(1 - eta**2, 2 * got["zeta"] * eta) == \
        pytest.approx(0.005, rel=1e-12)
    both = run(*BASE, "--zeta", "0.1", "--F0", "100N", "X=5mm", "Omega=?", "--json")
    data = json.loads(both.stdout)
    roots = sorted(v["value"] for n, v in data["results"].items() if n.startswith("Omega_"))
    assert len(roots) == 2 and roots[0] < math.sqrt(1000) < roots[1]


def test_total_response_without_damping_grows_linearly():
    xs = [results("--k", "100N/m", "--m", "1kg", "--F0", "1N", "--Omega", "10rad/s", "--t",
                  f"{t}s")["x"] for t in (math.pi / 20, math.pi / 20 + 2 * math.pi)]
    # x = (F0/k) (omega t / 2) sin(omega t) from rest
    assert xs[0] == pytest.approx(0.01 * 10 * math.pi / 40, rel=1e-14)
    assert xs[1] / xs[0] == pytest.approx(41.0, rel=1e-12)


def test_explain_gives_formulas_values_and_assumptions():
    data = json.loads(run(*BASE, "--zeta", "0.05", "--F0", "100N", "--Omega", "1500rpm",
                          "--json", "--explain").stdout)
    ex = data["extra"]["explanation"]
    text = "\n".join(ex["substituted"])
    assert "X = (100 N) / (40 kN/m) × 0.0422311 = 0.000105578 m" in text
    assert any("linear viscous damping" in a for a in ex["assumptions"])
    settle = 4 / (0.05 * math.sqrt(40000 / 40))   # 2.53 s
    assert any(f"4/(zeta omega) = {settle:.3g} s" in a for a in ex["assumptions"])


def test_no_mass_with_omega_leaves_the_force_amplitude_out():
    result = run("--omega", "10rad/s", "--zeta", "0.1", "--F0", "1N", "--Omega", "5rad/s")
    assert result.exit_code == 0
    assert "warning: X need the mass: give m (with omega, or k and m)" in result.output


def test_python_api():
    r = dyncalc.forced_response(k="40 kN/m", m=40, zeta=0.05, F0="100 N", Omega="1500 rpm")
    assert r["TR"].magnitude == pytest.approx(results(*BASE, "--zeta", "0.05", "--F0", "100N",
                                                      "--Omega", "1500rpm")["TR"], rel=1e-15)


def test_batch_rows(tmp_path):
    rows = tmp_path / "rows.csv"
    rows.write_text("k [N/m],m [kg],zeta,F0 [N],Omega [rad/s]\n40000,40,0.05,100,157\n"
                    "40000,40,0.1,100,30\n")
    result = CliRunner().invoke(cli, ["forced-response", "--batch", str(rows)])
    assert result.exit_code == 0, result.stderr
    lines = result.stdout.splitlines()
    header = lines[0].split(",")
    for line, (zeta, W) in zip(lines[1:], ((0.05, 157.0), (0.1, 30.0))):
        row = dict(zip(header, line.split(",")))
        ref = reference("force", 40000.0, 40.0, zeta, W, 100.0)
        assert float(row["X [m]"]) == pytest.approx(float(ref["X"]), rel=1e-13)
