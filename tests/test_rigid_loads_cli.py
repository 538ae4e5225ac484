"""The rigid-body load scenes end to end: the command's numbers against independent
derivations (tests/test_rigid_loads.py's quad integrations), inverse problems, --explain,
--batch with x as a column (the diagram as a table), the Python API, the exact refusals, and
--plot (the N, V, M diagrams written and readable; matplotlib not loaded without --plot)."""
import json
import math
import subprocess
import sys

import pytest

import dyncalc
import numpy as np
from dyncalc.commands.rigid_body import rigid_body
from dyncalc.commands.rigid_diagrams import load_diagram
from dyncalc.scenes import get_scene
from helpers import error_line, invoke, json_of
from test_rigid_loads import _arm_by_quad, _bar_tensor, _beam_by_quad, bar_by_newton_euler

BEAM = ("rigid-body", "--scene", "beam-spun-up", "m=6kg", "l=2m", "M0=12 N*m")
ARM = ("rigid-body", "--scene", "rotating-angled-arm", "m=3kg", "a=1m", "b=0.5m",
       "Omega=10rad/s")


def _values(data):
    return {name: r["value"] for name, r in data["results"].items()}


def test_beam_json_against_integrated_loads():
    data = json_of(*BEAM, "x=0.5m", "t=2s")
    assert data["schema"] == "dyncalc/2" and data["scene"] == "beam-spun-up"
    N, V, M = _beam_by_quad(6.0, 2.0, 12.0, 0.5, 2.0)
    got = _values(data)
    assert got == pytest.approx({"alpha": 12 / (6 * 4 / 3), "omega": 2 * 12 / (6 * 4 / 3),
                                 "N": N, "V": V, "M": M}, rel=1e-12)
    assert data["results"]["M"]["unit"] == "N*m" and data["results"]["V"]["unit"] == "N"


def test_book_example_ids_find_the_scenes():
    for example, name in (("E3.41", "angled-bar-on-shaft"), ("E3.42", "precessing-shaft"),
                          ("E3.43", "beam-spun-up"), ("E4.11", "rotating-angled-arm")):
        assert get_scene(example).name == name


def test_erratum_numbers_from_the_command():
    """SCENES.md, book errata: +4 N m, not the book's -96 N m."""
    data = json_of("rigid-body", "--scene", "E3.42", "J1=0.02 kg*m^2", "J2=0.5 kg*m^2",
                   "J3=0.5 kg*m^2", "omega0=100rad/s", "Omega=2rad/s")
    assert _values(data)["M2"] == pytest.approx(4.0, rel=1e-15)
    assert _values(data)["M1"] == 0.0 and not data["warnings"]


def test_arm_both_legs_and_the_corner():
    for word, leg, x in (("x1=0.25m", "b", 0.25), ("x2=30cm", "a", 0.3)):
        got = _values(json_of(*ARM, word))
        N, V, M = _arm_by_quad(3.0, 1.0, 0.5, 10.0, leg, x)
        assert (got["N"], got["V"], got["M"]) == pytest.approx((N, V, M), rel=1e-12)
        assert (got["N0"], got["V0"], got["M0"]) == pytest.approx(
            _arm_by_quad(3.0, 1.0, 0.5, 10.0, "a", 0.0), rel=1e-12)


def test_inverse_problems():
    """alpha = 9 M0/(20 m l^2) solved for M0; M at a section solved for M0; M2 solved for
    omega0."""
    bar = _values(json_of("rigid-body", "--scene", "angled-bar-on-shaft", "m=3kg", "l=0.5m",
                          "alpha=6rad/s^2", "M0=?"))
    assert bar["M0"] == pytest.approx(20 * 3 * 0.25 * 6 / 9, rel=1e-12)
    beam = _values(json_of("rigid-body", "--scene", "beam-spun-up", "m=6kg", "l=2m",
                           "x=0.5m", "M=-7.59375 N*m", "M0=?"))
    assert beam["M0"] == pytest.approx(7.59375 / (0.75 ** 2 * 1.125), rel=1e-12)
    shaft = _values(json_of("rigid-body", "--scene", "precessing-shaft", "J1=0.02 kg*m^2",
                            "J3=0.5 kg*m^2", "Omega=2rad/s", "M2=4 N*m", "omega0=?"))
    assert shaft["omega0"] == pytest.approx(4 / (0.02 * 2), rel=1e-12)


def test_explain_substitutes_the_values():
    out = invoke(*BEAM, "x=0.5m", "t=2s", "--explain")
    assert out.exit_code == 0, out.stderr
    assert ("  M = -(12 N*m) × (1 - (0.5 m) / (2 m))^2 × (1 + (0.5 m) / (2 × (2 m))) "
            "= -7.59375 N*m") in out.stdout.splitlines()
    shaft = invoke("rigid-body", "--scene", "precessing-shaft", "J1=0.1 kg*m^2", "J2=0.7 kg*m^2",
                   "J3=0.5 kg*m^2", "omega0=10rad/s", "Omega=2rad/s", "alpha0=0.5rad", "t=0s",
                   "--explain")
    assert shaft.exit_code == 0, shaft.stderr
    lines = shaft.stdout.splitlines()
    assert "  alpha_dot = (0.5 rad) × (2 rad/s) × cos((2 rad/s) × (0 s)) = 1 rad/s" in lines
    assert any(line.startswith("  M_2 = (0.1 kg*m^2) × (10 rad/s) × (1 rad/s) + ")
               and line.endswith(" = 3 N*m") for line in lines), lines


def test_batch_gives_the_diagram_as_a_table(tmp_path):
    rows = [0.0, 0.5, 1.0, 1.37, 2.0]
    csv = tmp_path / "x.csv"
    csv.write_text("m [kg],l [m],M0 [N*m],t [s],x [m]\n"
                   + "".join(f"6,2,12,2,{x}\n" for x in rows))
    out = invoke("rigid-body", "--scene", "beam-spun-up", "--batch", str(csv))
    assert out.exit_code == 0, out.stderr
    lines = out.stdout.splitlines()
    assert lines[0] == ("m [kg],l [m],M0 [N*m],t [s],x [m],alpha [rad/s^2],omega [rad/s],"
                        "N [N],V [N],M [N*m]")
    for x, line in zip(rows, lines[1:]):
        N, V, M = (float(v) for v in line.split(",")[-3:])
        assert (N, V, M) == pytest.approx(_beam_by_quad(6.0, 2.0, 12.0, x, 2.0), rel=1e-12,
                                          abs=1e-12)
    assert out.stderr == ""                    # the free end is an exact zero, no warning


def test_python_api():
    r = dyncalc.rigid_body(scene="rotating-angled-arm", m="3 kg", a="1 m", b="0.5 m",
                           Omega="10 rad/s", x2="0 m")
    N, V, M = _arm_by_quad(3.0, 1.0, 0.5, 10.0, "a", 0.0)
    assert r["N"].to("N").magnitude == pytest.approx(N, rel=1e-12)
    assert r["M0"].to("N*m").magnitude == pytest.approx(M, rel=1e-12)
    arrays = dyncalc.rigid_body(scene="beam-spun-up", m="6 kg", l="2 m", M0="12 N*m",
                                t="2 s", x=[0.0, 0.5, 2.0])      # elementwise, x in m
    assert arrays["M"].to("N*m").magnitude.tolist() == pytest.approx(
        [_beam_by_quad(6.0, 2.0, 12.0, x, 2.0)[2] for x in (0.0, 0.5, 2.0)], rel=1e-12,
        abs=1e-12)


def _signature(name):
    return get_scene(name).signature()


@pytest.mark.parametrize("words, message", [
    (BEAM + ("x=3m",), "x must lie on the bar: 0 <= x <= l; got x = 3 m with l = 2 m"),
    (BEAM + ("x=-1cm",), "x must lie on the bar: 0 <= x <= l; got x = -0.01 m with l = 2 m"),
    (BEAM + ("x=1m", "t=-1s"), "t is the time since the start: t >= 0; got t = -1 s"),
    (ARM + ("x1=60cm",), "x1 must lie on the bar: 0 <= x1 <= b; got x1 = 0.6 m with b = 0.5 m"),
    (ARM + ("x2=1.5m",), "x2 must lie on the bar: 0 <= x2 <= a; got x2 = 1.5 m with a = 1 m"),
    (ARM + ("x1=0.1m", "x2=0.1m"),
     "rotating-angled-arm: give x1 or x2, not both; the parameters of rotating-angled-arm are: "
     + _signature("rotating-angled-arm")),
    (ARM, "rotating-angled-arm needs x1 or x2; the parameters of rotating-angled-arm are: "
          + _signature("rotating-angled-arm")),
    (("rigid-body", "--scene", "precessing-shaft", "J1=0.1kg*m^2", "J3=0.5kg*m^2",
      "omega0=10rad/s", "Omega=2rad/s", "t=1s"),
     "precessing-shaft: t goes with alpha0 (harmonic turning alpha = alpha0 sin(Omega t)); "
     "uniform turning (alpha = Omega t, no alpha0) is the same at every instant"),
    (("rigid-body", "--scene", "precessing-shaft", "J1=0.1kg*m^2", "J3=0.5kg*m^2",
      "omega0=10rad/s", "Omega=2rad/s", "alpha0=10deg"),
     "precessing-shaft: harmonic turning (alpha0 given) needs t, the instant asked for"),
    (("rigid-body", "--scene", "angled-bar-on-shaft", "m=3kg", "l=0.5m", "M0=10 N"),
     "M0 must be a torque [force]*[length]; got 10 newton ([mass] * [length] / [time] ** 2)"),
])
def test_refusals(words, message):
    assert error_line(invoke(*words)) == "Error: " + message


# --- --plot ---------------------------------------------------------------------------------

def test_plot_beam_png(tmp_path):
    target = tmp_path / "beam.png"
    out = invoke(*BEAM, "x=0.5m", "t=2s", "--plot", str(target), "--json")
    assert out.exit_code == 0, out.stderr
    data = target.read_bytes()
    assert data.startswith(b"\x89PNG\r\n\x1a\n") and len(data) > 10000
    assert json.loads(out.stdout)["extra"]["plot"] == str(target)


def test_plot_arm_svg_has_six_axes(tmp_path):
    target = tmp_path / "arm.svg"
    out = invoke(*ARM, "x2=0.3m", "--plot", str(target))
    assert out.exit_code == 0, out.stderr
    text = target.read_text()
    assert text.lstrip().startswith("<?xml") and "<svg" in text
    assert 'id="axes_6"' in text and 'id="axes_7"' not in text


def test_plot_pdf(tmp_path):
    target = tmp_path / "beam.pdf"
    assert invoke(*BEAM, "t=1s", "--plot", str(target)).exit_code == 0
    assert target.read_bytes().startswith(b"%PDF")


def test_diagram_curves_pass_through_the_section():
    r = rigid_body({}, ["m=3kg", "a=1m", "b=0.5m", "Omega=10rad/s", "x1=0.22m"],
                   scene="rotating-angled-arm")
    legs = load_diagram(r, points=11).legs
    assert [leg.name for leg in legs] == ["leg b", "leg a"]
    b, a = legs
    assert b.x[0] == 0.0 and b.x[-1] == 0.5 and 0.22 in b.x and len(b.x) == 12
    assert b.x == sorted(b.x) and b.section == 0.22
    i = b.x.index(0.22)
    assert (b.N[i], b.V[i], b.M[i]) == pytest.approx(
        (r.results["N"].si, r.results["V"].si, r.results["M"].si), rel=1e-15)
    assert a.section is None and a.M[-1] == 0.0                # no moment at the axis
    assert a.M[0] == pytest.approx(b.M[-1], rel=1e-15)           # continuous at the corner
    for k in range(len(a.x)):
        assert (a.N[k], a.V[k], a.M[k]) == pytest.approx(
            _arm_by_quad(3.0, 1.0, 0.5, 10.0, "a", a.x[k]), rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("words, message", [
    (BEAM + ("x=1m",), "--plot: beam-spun-up's normal force N grows with t^2: give t= to draw "
                       "the N, V, M diagrams"),
    (("rigid-body", "--scene", "angled-bar-on-shaft", "m=3kg", "l=0.5m", "M0=10 N*m"),
     "--plot: the N, V, M diagrams are drawn for beam-spun-up and rotating-angled-arm; "
     "angled-bar-on-shaft has no stress resultants along a bar"),
    (("rigid-body", "--scene", "precessing-shaft", "J1=0.1kg*m^2", "J3=0.5kg*m^2",
      "omega0=10rad/s", "Omega=2rad/s"),
     "--plot: the N, V, M diagrams are drawn for beam-spun-up and rotating-angled-arm; "
     "precessing-shaft has no stress resultants along a bar"),
    (("rigid-body", "--inertia-tensor", "1, 0, 0; 0, 1, 0; 0, 0, 1.5", "--omega", "0, 0, 1"),
     "--plot: the N, V, M diagrams are drawn for beam-spun-up and rotating-angled-arm; "
     "Euler's equations give one moment, not a diagram"),
    (("rigid-body", "--scene", "rotating-angled-arm", "m=3kg", "a=1m", "b=0.5m", "x2=0.5m",
      "M0=25 N*m", "Omega=?"),
     "--plot: Omega has 2 solutions (Omega_1, Omega_2): give one of them as Omega= to draw "
     "the diagrams"),
])
def test_plot_refusals(tmp_path, words, message):
    target = tmp_path / "p.png"
    assert error_line(invoke(*words, "--plot", str(target))) == "Error: " + message
    assert not target.exists()


def test_plot_of_an_inverse_problem(tmp_path):
    """M0 solved from M at a section: the diagram is drawn with the solved M0 and passes
    through the given M."""
    words = ["m=6kg", "l=2m", "x=0.5m", "t=1s", "M=-7.59375 N*m", "M0=?"]
    r = rigid_body({}, words, scene="beam-spun-up")
    leg = load_diagram(r, points=5).legs[0]
    assert leg.M[leg.x.index(0.5)] == pytest.approx(-7.59375, rel=1e-12)
    assert leg.M[0] == pytest.approx(-12.0, rel=1e-12)              # M(0) = -M0
    target = tmp_path / "inverse.png"
    assert invoke("rigid-body", "--scene", "beam-spun-up", *words, "--plot",
                  str(target)).exit_code == 0
    assert target.stat().st_size > 10000


def test_plot_bad_suffix():
    assert error_line(invoke(*ARM, "x1=0.1m", "--plot", "arm.gif")) == (
        "Error: --plot: 'arm.gif' must end in .png, .svg or .pdf")


def test_matplotlib_not_loaded_without_plot():
    code = ("import sys; from dyncalc.cli import main\n"
            "sys.argv = ['dyncalc', 'rigid-body', '--scene', 'rotating-angled-arm', 'm=3kg', "
            "'a=1m', 'b=0.5m', 'Omega=10rad/s', 'x1=0.1m']\n"
            "try:\n    main()\nexcept SystemExit:\n    pass\n"
            "print('matplotlib' in sys.modules, file=sys.stderr)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120)
    assert done.stderr.strip().splitlines()[-1] == "False", done.stderr
    assert "N0" in done.stdout and math.isfinite(1.0)


# --- --check slips --------------------------------------------------------------------------

def _slip_line(words, check):
    out = invoke(*words, "--check", check)
    assert out.exit_code == 1, out.stderr
    return next(line for line in out.stdout.splitlines() if line.startswith("check "))


@pytest.mark.parametrize("flip, why", [
    (-1.0, "the sign of the product of inertia J_xizeta wrong (+m l^2/3)"),
    (0.0, "the product of inertia J_xizeta left out (the bearings share equally)")])
def test_bar_slips_match_the_wrong_tensor(flip, why):
    """The slip values are the Newton-Euler solution with J_xizeta negated or zeroed."""
    body = _bar_tensor(3.0, 0.5)
    J = np.array(body.J_O)
    J[0, 2] = J[2, 0] = flip * J[0, 2]
    wrong = bar_by_newton_euler(3.0, 0.5, 10.0, 2.0, J, body.r_c)
    words = ("rigid-body", "--scene", "angled-bar-on-shaft", "m=3kg", "l=0.5m", "M0=10 N*m",
             "omega=2rad/s")
    for name in ("A_xi", "A_eta", "B_xi", "B_eta"):
        line = _slip_line(words, f"{name}={wrong[name]!r} N")
        assert line.endswith(f"FAIL; likely slip: {why}"), line


def test_beam_and_shaft_slips():
    """m l^2/12 about the pin gives alpha = M0/(m l^2/12); the book's M2 at the erratum's
    numbers is (J1 - J3) omega0 Omega = -96 N m."""
    beam = _slip_line(BEAM, f"alpha={12 / (6 * 4 / 12)!r} rad/s^2")
    assert beam.endswith("FAIL; likely slip: the moment of inertia about the centre (m l^2/12) "
                         "used about the pin"), beam
    shaft = _slip_line(("rigid-body", "--scene", "E3.42", "J1=0.02 kg*m^2", "J3=0.5 kg*m^2",
                        "omega0=100rad/s", "Omega=2rad/s"), "M2=-96 N*m")
    assert shaft.endswith("FAIL; likely slip: the rate of the body-fixed omega_2 taken as zero "
                          "(the book's misprint (J1 - J3) omega0 alpha')"), shaft
