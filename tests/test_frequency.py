"""dyncalc natural-frequency: options, scene inference, damping, rates, checks, refusals."""
import json
import math

import mpmath
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from helpers import error_line, invoke

TWO_PI = 2 * math.pi


def run(*args):
    return invoke("natural-frequency", *args)


def results(*args):
    result = run(*args, "--json")
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def value(*args):
    result = run(*args)
    assert result.exit_code == 0, result.stderr
    return float(result.stdout)




def test_contract_smoke_mass_spring():
    data = results("--k", "100 N/m", "--m", "2 kg")
    assert data["scene"] == "mass-spring" and data["model"] == "linear"
    assert data["method"] == "closed-form"
    assert data["inputs"] == {"k": {"value": 100.0, "unit": "N/m", "text": "100 N/m"},
                              "m": {"value": 2.0, "unit": "kg", "text": "2 kg"}}
    omega = math.sqrt(50)
    assert data["results"]["omega"] == {"value": omega, "unit": "rad/s"}
    assert data["results"]["f"]["unit"] == "Hz" and data["results"]["T"]["unit"] == "s"
    assert data["results"]["f"]["value"] == pytest.approx(omega / TWO_PI, rel=1e-16)
    assert data["results"]["T"]["value"] == pytest.approx(TWO_PI / omega, rel=2.3e-16)


def test_the_units_they_typed():
    """2 kN/m and 4 kg: omega = sqrt(500) rad/s, f in Hz, T in s."""
    data = results("--k", "2 kN/m", "--m", "4kg")
    assert data["results"]["omega"]["value"] == pytest.approx(math.sqrt(500), rel=1e-16)
    assert data["inputs"]["k"] == {"value": 2.0, "unit": "kN/m", "text": "2 kN/m"}


@settings(max_examples=60, deadline=None)
@given(st.floats(1e-3, 1e6), st.floats(1e-3, 1e6))
def test_omega_f_T_relations(k, m):
    data = results("--k", f"{k!r} N/m", "--m", f"{m!r} kg")["results"]
    omega, f, T = (data[n]["value"] for n in ("omega", "f", "T"))
    assert omega == pytest.approx(math.sqrt(k / m), rel=4e-16)
    assert f == pytest.approx(omega / TWO_PI, rel=4e-16)
    assert T * f == pytest.approx(1.0, rel=6e-16)


def test_extremes_do_not_overflow():
    """k = 1e300 N/m, m = 1e-300 kg: k/m overflows, omega = 1e300 rad/s does not."""
    assert value("--k", "1e300 N/m", "--m", "1e-300 kg", "--value", "omega") == 1e300
    assert value("--k", "1e-300 N/m", "--m", "1e300 kg", "--value", "omega") == 1e-300


def test_mpmath_reference_at_extremes():
    mpmath.mp.dps = 40
    for k, m in [(1e-300, 1e-300), (3e-200, 7e250), (1.5e308, 2e-308), (5e-324, 1.0)]:
        got = value("--k", f"{k!r} N/m", "--m", f"{m!r} kg", "--value", "omega")
        ref = mpmath.sqrt(mpmath.mpf(k) / mpmath.mpf(m))
        assert abs(mpmath.mpf(got) - ref) <= mpmath.mpf(math.ulp(float(ref))), (k, m)


def test_torsional_by_options():
    data = results("--kt", "3 kN*m/rad", "--inertia", "1.2 kg*m^2")
    assert data["scene"] == "torsional"
    assert data["results"]["omega"]["value"] == pytest.approx(50.0, rel=1e-16)


def test_scene_by_positional_parameters():
    data = results("k=2kN/m", "m=4kg")
    assert data["scene"] == "mass-spring"
    data = results("--scene", "pendulum", "l=2m")
    assert data["results"]["omega"]["value"] == pytest.approx(math.sqrt(9.80665 / 2), rel=1e-15)


def test_length_chooses_pendulum():
    data = results("--length", "1 m")
    assert data["scene"] == "pendulum"
    assert data["results"]["T"]["value"] == pytest.approx(TWO_PI / math.sqrt(9.80665),
                                                          rel=1e-15)
    assert data["inputs"]["g"] == {"value": 9.80665, "unit": "m/s^2", "text": "9.80665 m/s^2"}


def test_g_option():
    omega = value("--length", "1 m", "--g", "1.62 m/s^2", "--value", "omega")
    assert omega == pytest.approx(math.sqrt(1.62), rel=1e-15)


def test_zeta_adds_damped_results():
    data = results("--k", "100 N/m", "--m", "2 kg", "--zeta", "0.05")["results"]
    omega = math.sqrt(50)
    assert data["zeta"] == {"value": 0.05, "unit": ""}
    assert data["omega_d"]["value"] == pytest.approx(omega * math.sqrt(1 - 0.05**2), rel=1e-15)
    assert data["T_d"]["value"] == pytest.approx(TWO_PI / data["omega_d"]["value"], rel=1e-15)


def test_zeta_a_hair_below_one():
    """(1 - zeta)(1 + zeta) keeps its digits where 1 - zeta^2 loses them."""
    zeta = 1 - 1e-12
    mpmath.mp.dps = 40
    got = value("--k", "1 N/m", "--m", "1 kg", "--zeta", repr(zeta), "--value", "omega_d")
    ref = mpmath.sqrt(1 - mpmath.mpf(zeta) ** 2)
    assert abs(mpmath.mpf(got) - ref) / ref < 1e-15


def test_overdamped_warns_and_gives_no_damped_frequency():
    data = results("--k", "1 N/m", "--m", "1 kg", "--zeta", "2")
    assert "omega_d" not in data["results"]
    assert data["warnings"] == ["zeta = 2: the system is overdamped; it does not oscillate, "
                                "so there is no damped frequency"]


def test_zeta_percent():
    data = results("--k", "1 N/m", "--m", "1 kg", "--zeta", "5%")
    assert data["results"]["zeta"]["value"] == pytest.approx(0.05, rel=1e-15)


# --- omega and f are never confused ---------------------------------------------------------

def test_check_f_in_hz_and_rpm():
    assert run("--k", "100N/m", "--m", "2kg", "--check", "f=1.13Hz").exit_code == 0
    # f = 1.1254 Hz = 67.52 cycles per minute: rpm is one cycle a minute for a frequency
    assert run("--k", "100N/m", "--m", "2kg", "--check", "f=67.5 rpm").exit_code == 0
    # omega = 7.071 rad/s = 67.52 rpm as well (one revolution is 2 pi rad)
    assert run("--k", "100N/m", "--m", "2kg", "--check", "omega=67.5 rpm").exit_code == 0


def test_check_omega_given_as_f_fails():
    result = run("--k", "100N/m", "--m", "2kg", "--check", "omega=1.1254 1/s")
    assert result.exit_code == 1
    result = run("--k", "100N/m", "--m", "2kg", "--check", "omega=7.07 1/s")
    assert result.exit_code == 0


def test_check_f_in_rad_per_s_refused():
    result = run("--k", "100N/m", "--m", "2kg", "--check", "f=7.07rad/s")
    assert error_line(result) == ("Error: --check f is a frequency in cycles; give it in Hz, "
                                  "1/s, 1/min or rpm, not in radians or degrees per time (that "
                                  "is omega)")


def test_check_omega_in_hz_refused():
    result = run("--k", "100N/m", "--m", "2kg", "--check", "omega=1.13Hz")
    assert error_line(result) == ("Error: --check omega is an angular rate; give it in rad/s, "
                                  "deg/s, rpm or rev/s, not Hz (a frequency in cycles)")


@pytest.mark.parametrize("spec, message", [
    ("f=rad/s", "Error: --unit f: f is a frequency in cycles; use omega for rad/s"),
    ("omega=Hz", "Error: --unit omega: omega is an angular rate; use f for Hz"),
])
def test_unit_rate_refusals(spec, message):
    assert error_line(run("--k", "100N/m", "--m", "2kg", "--unit", spec)) == message


def test_unit_rpm_for_both():
    omega = math.sqrt(50)
    f_rpm = value("--k", "100N/m", "--m", "2kg", "--unit", "f=rpm", "--value", "f")
    w_rpm = value("--k", "100N/m", "--m", "2kg", "--unit", "omega=rpm", "--value", "omega")
    assert f_rpm == pytest.approx(omega / TWO_PI * 60, rel=1e-15)
    assert w_rpm == pytest.approx(omega / TWO_PI * 60, rel=1e-15)
    t_ms = value("--k", "100N/m", "--m", "2kg", "--unit", "T=ms", "--value", "T")
    assert t_ms == pytest.approx(TWO_PI / omega * 1000, rel=1e-15)


# --- explain -----------------------------------------------------------------------------------

def test_explain_shows_formula_values_and_reference():
    result = run("--k", "100N/m", "--m", "2kg", "--explain")
    out = result.stdout
    assert "  equation of motion: m x'' + k x = 0" in out
    assert "  omega^2 = k / m" in out
    assert "  omega = sqrt((100 N/m) / (2 kg)) = 7.07107 rad/s" in out
    assert "reference: E5.11, E5.19, E5.26" in out


def test_explain_pendulum_says_how_wrong_small_angle_is():
    data = results("--length", "1m", "--amplitude", "30deg", "--explain")
    assumptions = data["extra"]["explanation"]["assumptions"]
    assert any("the small-angle period is 1.71% short at an amplitude of 30 deg" in a
               for a in assumptions), assumptions


# --- refusals ----------------------------------------------------------------------------------

@pytest.mark.parametrize("args, message", [
    (["--k", "5 kg", "--m", "2 kg"], "Error: --k must be a stiffness [force]/[length]; got 5 "
                                     "kilogram ([mass])"),
    (["--k", "-5 N/m", "--m", "2 kg"], "Error: --k must be positive; got -5 newton / meter"),
    (["--k", "0 N/m", "--m", "2 kg"], "Error: --k must be positive; got 0 newton / meter"),
    (["--k", "nan", "--m", "2 kg"], "Error: --k: cannot read 'nan': NaN is not a number "
                                    "dyncalc accepts"),
    (["--k", "inf N/m", "--m", "2 kg"], "Error: --k must be finite; got inf newton / meter"),
    (["--k", "1 N/m"], "Error: mass-spring needs m; the parameters of mass-spring are: k "
                       "[force]/[length], m [mass], zeta dimensionless?"),
    ([], "Error: mass-spring needs k, m; the parameters of mass-spring are: k [force]/[length], "
         "m [mass], zeta dimensionless?"),
    (["--k", "1 N/m", "k=2 N/m", "--m", "1 kg"], "Error: k is given twice (--k and k=)"),
    (["--k", "1 N/m", "--m", "1 kg", "--g", "9.81"], "Error: the parameters given (g, k, m) fit "
                                                      "no scene on their own; name one with "
                                                      "--scene (dyncalc scenes lists them)"),
    (["--scene", "mass-spring", "--k", "1 N/m", "--m", "1 kg", "--g", "9.81"],
     "Error: mass-spring has no parameter 'g'; the parameters of mass-spring are: k "
     "[force]/[length], m [mass], zeta dimensionless?"),
    (["--k", "1 N/m", "--m", "1 kg", "--check", "f=2 3/4 Hz"],
     "Error: --check f: cannot read '2 3/4 Hz': two numbers side by side; write 1000, not "
     "1 000, and use * to multiply"),
    (["--k", "1 N/m", "--length", "1 m"], "Error: the parameters given (k, l) fit no scene on "
                                          "their own; name one with --scene (dyncalc scenes "
                                          "lists them)"),
    (["--scene", "nope"], "Error: there is no scene 'nope'; the scenes are: " + ", ".join(
        __import__("dyncalc.scenes", fromlist=["x"]).scene_names())),
    (["--k", "1 N/m", "--m", "1 kg", "--zeta", "-0.1"], "Error: --zeta must not be negative; "
                                                        "got -0.1"),
    (["--k", "1 N/m", "--m", "1 kg", "--method", "ode"], "Error: --method ode is not offered by "
                                                         "mass-spring; it offers auto (a closed "
                                                         "form only)"),
    (["--k", "1 N/m", "--m", "1 kg", "oops"], "Error: a scene parameter takes NAME=VALUE (for "
                                              "example m=2kg); got 'oops'"),
    (["--k", "1 N/m", "--m", "1 kg", "--strict-units", "--zeta", "0.1"], None),
    (["--k", "100", "--m", "1 kg", "--strict-units"], "Error: --k: '100' has no unit and "
                                                      "--strict-units is on; write it with a "
                                                      "unit, e.g. 100 N/m"),
])
def test_refusals(args, message):
    result = run(*args)
    if message is None:
        assert result.exit_code == 0, result.stderr
        return
    assert error_line(result) == message
