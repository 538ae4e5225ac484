"""dyncalc rolling-onset: E3.45, every body, spin both ways, slopes, the ODE against the closed
form, unit invariance, properties, and the refusals with their exact messages."""
import json
import math
from fractions import Fraction

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncalc.cli import cli
from dyncalc.errors import PhysicsError
from dyncalc.physics.bodies import KAPPA
from dyncalc.physics.rolling import (onset_closed_form, onset_ode, rolling_onset,
                                     shape_factor, slope_sin_cos)
from dyncalc.units import Q_
from helpers import error_line, invoke

G = 9.80665


def run(*args):
    return invoke("rolling-onset", *args)


def data(*args):
    result = run(*args, "--json")
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def results(*args):
    """SI values of the results by name (every unit shown is SI by default)."""
    out = data(*args)["results"]
    units = {"t_roll": "s", "x_roll": "m", "v_roll": "m/s", "omega_roll": "rad/s",
             "path_roll": "m", "mu_min": ""}
    for name, item in out.items():
        assert item["unit"] == units[name], name
    return {name: item["value"] for name, item in out.items()}




# --- E3.45 ---------------------------------------------------------------------------------------

def test_e345_bowling_ball():
    """A bowling ball set down at 5 m/s without spin, mu = 0.3: 0.49 s, 2.08 m, 3.57 m/s."""
    v0, mu = 5.0, 0.3
    got = data("--v0", "5 m/s", "--mu", "0.3")
    assert got["command"] == "rolling-onset" and got["method"] == "closed-form"
    assert got["inputs"]["v0"] == {"value": 5.0, "unit": "m/s", "text": "5 m/s"}
    res = {n: v["value"] for n, v in got["results"].items()}
    assert list(res) == ["t_roll", "x_roll", "v_roll"]
    assert res["t_roll"] == pytest.approx(2 * v0 / (7 * mu * G), rel=1e-15)
    assert res["x_roll"] == pytest.approx(12 * v0 ** 2 / (49 * mu * G), rel=1e-15)
    assert res["v_roll"] == pytest.approx(5 * v0 / 7, rel=1e-15)
    # the textbook's rounded answers, and the contract smoke test's (computed with g = 9.81)
    assert (round(res["t_roll"], 2), round(res["x_roll"], 2), round(res["v_roll"], 2)) == (
        0.49, 2.08, 3.57)
    for name, want in {"t_roll": 0.48541, "x_roll": 2.0801, "v_roll": 3.5714}.items():
        assert res[name] == pytest.approx(want, rel=2e-3)


def test_e345_correctly_rounded():
    """The exact rational closed form, rounded once: 5/7 of 5 m/s to the last bit."""
    o = onset_closed_form(5.0, 0.3, 0.4, G)
    assert o.v == float(Fraction(25, 7))
    exact_t = Fraction(2 * 5, 7) / (Fraction("0.3") * Fraction("9.80665"))
    assert o.t == float(exact_t)


def test_e345_with_g_981_matches_the_smoke_numbers():
    res = results("--v0", "5 m/s", "--mu", "0.3", "--g", "9.81 m/s^2")
    assert res["t_roll"] == pytest.approx(0.48541, abs=5e-6)
    assert res["v_roll"] == pytest.approx(3.5714, abs=5e-5)


def test_explain_names_the_example_and_the_formula():
    out = run("--v0", "5 m/s", "--mu", "0.3", "--explain").stdout
    assert "Example 3.45" in out
    assert "t_roll = kappa |s0| / (mu g (1 + kappa))" in out
    assert "t_roll = 0.4 × 5 m/s / (0.3 × 9.80665 m/s^2 × 1.4) = 0.485579 s" in out


# --- bodies --------------------------------------------------------------------------------------

def test_each_body_kappa():
    assert KAPPA == pytest.approx({"solid-sphere": 2 / 5, "hollow-sphere": 2 / 3,
                                   "solid-cylinder": 1 / 2, "hollow-cylinder": 1.0,
                                   "hoop": 1.0}, rel=1e-16)
    assert [shape_factor(KAPPA[b]) for b in KAPPA] == [
        Fraction(2, 5), Fraction(2, 3), Fraction(1, 2), 1, 1]


@pytest.mark.parametrize("body", sorted(KAPPA))
def test_each_body_through_the_cli(body):
    kappa = KAPPA[body]
    v0, mu = 4.0, 0.25
    by_name = results("--v0", "4 m/s", "--mu", "0.25", "--body", body)
    by_kappa = results("--v0", "4 m/s", "--mu", "0.25", "--kappa", repr(kappa))
    assert by_name == by_kappa
    assert by_name["t_roll"] == pytest.approx(kappa * v0 / (mu * G * (1 + kappa)), rel=1e-15)
    assert by_name["v_roll"] == pytest.approx(v0 / (1 + kappa), rel=1e-15)


def test_default_body_is_the_solid_sphere():
    assert data("--v0", "5", "--mu", "0.3")["inputs"]["body"]["value"] == "solid-sphere"


def test_kappa_zero_rolls_at_once():
    out = run("--v0", "5 m/s", "--mu", "0.3", "--kappa", "0", "--radius", "0.1 m",
              "--omega0", "-80 rad/s", "--json")
    got = json.loads(out.stdout)
    res = {n: v["value"] for n, v in got["results"].items()}
    assert res == {"t_roll": 0.0, "x_roll": 0.0, "v_roll": 5.0, "omega_roll": 50.0}
    assert any(w.startswith("kappa = 0: a body with no moment of inertia") for w in
               got["warnings"])
    assert not any("underflow" in w for w in got["warnings"])


# --- spin ------------------------------------------------------------------------------------

def test_angular_momentum_about_the_contact_is_conserved():
    """m v0 r + J omega0 = m v r + J v / r (flat ground), J = kappa m r^2: an independent check
    of v_roll (the command computes it as v0 - a t_roll)."""
    for body, kappa in KAPPA.items():
        for omega0 in (-250.0, -40.0, 0.0, 30.0, 90.0, 400.0):
            r, v0 = 0.11, 3.0
            res = results("--v0", f"{v0} m/s", "--mu", "0.2", "--body", body, "--radius",
                          f"{r} m", "--omega0", f"{omega0} rad/s")
            before = v0 * r + kappa * r * r * omega0
            after = res["v_roll"] * r + kappa * r * r * res["omega_roll"]
            assert after == pytest.approx(before, rel=1e-14, abs=1e-15), (body, omega0)
            assert res["omega_roll"] == pytest.approx(res["v_roll"] / r, rel=1e-15)


def test_topspin_speeds_it_up():
    res = results("--v0", "2 m/s", "--mu", "0.2", "--radius", "0.1 m", "--omega0",
                  "40 rad/s")
    # s0 = 2 - 4 < 0: friction pushes forward; v = (2 + 0.4 * 4)/1.4
    assert res["v_roll"] == pytest.approx(3.6 / 1.4, rel=1e-15)
    assert res["v_roll"] > 2.0
    assert res["t_roll"] == pytest.approx(0.4 * 2 / (0.2 * G * 1.4), rel=1e-15)


def test_backspin_brings_it_back():
    """|omega0| > v0/(kappa r): v_roll < 0, x_roll a displacement, path_roll the path."""
    v0, r, w0, mu, kappa = 2.0, 0.0285, -300.0, 0.2, 0.4
    assert abs(w0) > v0 / (kappa * r)
    got = data("--v0", "2 m/s", "--mu", "0.2", "--radius", "28.5mm", "--omega0", "-300 rad/s")
    res = {n: v["value"] for n, v in got["results"].items()}
    s0 = v0 - r * w0
    t = kappa * s0 / (mu * G * (1 + kappa))
    v = (v0 + kappa * r * w0) / (1 + kappa)
    assert res["t_roll"] == pytest.approx(t, rel=1e-14)
    assert res["v_roll"] == pytest.approx(v, rel=1e-14) and v < 0
    assert res["x_roll"] == pytest.approx(v0 * t - mu * G * t * t / 2, rel=1e-13)
    a = mu * G
    assert res["path_roll"] == pytest.approx((v0 ** 2 + v ** 2) / (2 * a), rel=1e-14)
    assert res["path_roll"] > abs(res["x_roll"])
    explained = run("--v0", "2 m/s", "--mu", "0.2", "--radius", "28.5mm", "--omega0",
                    "-300 rad/s", "--explain").stdout
    assert "x_roll is the displacement along the surface" in explained
    assert "not the path length" in explained
    assert "the backspin brings it back" in explained


def test_backspin_exactly_stops_it():
    """|omega0| = v0/(kappa r): it comes to rest, rolling at zero speed: v_roll = 0 exactly."""
    res = data("--v0", "2 m/s", "--mu", "0.2", "--radius", "0.1 m", "--omega0",
               "-20 rad/s", "--body", "hoop")
    assert res["results"]["v_roll"]["value"] == 0.0
    assert res["warnings"] == []


def test_already_rolling_s0_zero():
    got = data("--v0", "2 m/s", "--mu", "0.3", "--radius", "0.1 m", "--omega0", "20 rad/s")
    res = {n: v["value"] for n, v in got["results"].items()}
    assert res == {"t_roll": 0.0, "x_roll": 0.0, "v_roll": 2.0, "omega_roll": 20.0}
    assert got["warnings"] == ["v0 = r omega0: the body is set down already rolling (no "
                               "slip), so t_roll = 0 and x_roll = 0"]
    explained = run("--v0", "2 m/s", "--mu", "0.3", "--radius", "0.1 m", "--omega0",
                    "20 rad/s", "--explain").stdout
    assert "s0 = 0: set down already rolling, so t_roll = 0" in explained


def test_near_balance_keeps_its_digits():
    """v0 and r omega0 equal to 15 digits: the slip is what the inputs imply (no cancellation)."""
    res = results("--v0", "2.000000000000001 m/s", "--mu", "0.3", "--radius", "0.1 m",
                  "--omega0", "20 rad/s")
    s0 = Fraction("2.000000000000001") - 2
    t = float(Fraction(2, 5) * s0 / (Fraction("0.3") * Fraction("9.80665") * Fraction(7, 5)))
    assert res["t_roll"] == t  # naive float: (2.000000000000001 - 0.1*20) is 8% off


def test_spin_without_radius_is_refused_but_zero_spin_is_fine():
    assert results("--v0", "5", "--mu", "0.3", "--omega0", "0 rad/s")["v_roll"] == 25 / 7


# --- slopes ------------------------------------------------------------------------------------

def _slope_closed_form(v0, mu, kappa, beta_deg, r=None, w0=0.0):
    b = math.radians(beta_deg)
    s0 = v0 - (r * w0 if r else 0.0)
    sigma = math.copysign(1.0, s0)
    t = kappa * abs(s0) / (G * (mu * (1 + kappa) * math.cos(b) + sigma * kappa * math.sin(b)))
    a = G * (math.sin(b) + sigma * mu * math.cos(b))
    return t, v0 * t - a * t * t / 2, v0 - a * t


@pytest.mark.parametrize("beta", [-20.0, -5.0, 5.0, 20.0])
def test_slope_formulas(beta):
    res = results("--v0", "3 m/s", "--mu", "0.4", "--body", "solid-cylinder", "--incline",
                  f"{beta}deg")
    t, x, v = _slope_closed_form(3.0, 0.4, 0.5, beta)
    assert res["t_roll"] == pytest.approx(t, rel=1e-13)
    assert res["x_roll"] == pytest.approx(x, rel=1e-13)
    assert res["v_roll"] == pytest.approx(v, rel=1e-13)
    assert res["mu_min"] == pytest.approx(0.5 * abs(math.tan(math.radians(beta))) / 1.5,
                                          rel=1e-14)


def test_zero_incline_is_flat_ground_with_mu_min_zero():
    flat = results("--v0", "5", "--mu", "0.3")
    sloped = results("--v0", "5", "--mu", "0.3", "--incline", "0deg")
    assert sloped.pop("mu_min") == 0.0
    assert sloped == flat


def test_uphill_backspin_slope():
    """Backspin uphill: the slip is forward, gravity and friction both slow it."""
    res = results("--v0", "3 m/s", "--mu", "0.3", "--radius", "0.1m", "--omega0", "-10rad/s",
                  "--incline", "10deg")
    t, x, v = _slope_closed_form(3.0, 0.3, 0.4, 10.0, 0.1, -10.0)
    assert (res["t_roll"], res["x_roll"], res["v_roll"]) == pytest.approx((t, x, v), rel=1e-13)


def test_slope_not_sustained_warns():
    """Sliding up a steep slope: rolling is reached, but mu below mu_min cannot hold it."""
    got = data("--v0", "3 m/s", "--mu", "0.1", "--incline", "40deg")
    mu_min = 0.4 * math.tan(math.radians(40)) / 1.4
    assert got["results"]["mu_min"]["value"] == pytest.approx(mu_min, rel=1e-14)
    assert got["warnings"] == [
        f"rolling on this slope needs static friction mu_s >= mu_min = {mu_min:.6g}; unless "
        "the static coefficient reaches it (mu = 0.1 is below), the slip reverses at t_roll "
        "and the body slides on"]


def test_incline_near_90_degrees_keeps_cos():
    assert slope_sin_cos(Q_(89.9999, "deg"))[1] == 1.7453292520513826e-06
    assert slope_sin_cos(Q_(-89.9999, "deg"))[1] == 1.7453292520513826e-06
    assert slope_sin_cos(Q_(0.5, "rad")) == (math.sin(0.5), math.cos(0.5))
    assert slope_sin_cos(Q_(30, "deg")) == (math.sin(math.pi / 6), math.cos(math.pi / 6))
    assert slope_sin_cos(Q_(1.5707963, "rad"))[1] == pytest.approx(2.6794896585e-8, rel=1e-9)


# --- the ODE against the closed form ---------------------------------------------------------

SPINS = [None, 45.0, -20.0, -150.0]   # rad/s with r = 0.1 m: none, topspin, backspin, return
SLOPES = [0.0, 8.0, -8.0]             # degrees


@pytest.mark.parametrize("body", sorted(KAPPA))
def test_ode_agrees_with_the_closed_form(body):
    rtol = 1e-9
    for spin in SPINS:
        for beta in SLOPES:
            args = ["--v0", "4 m/s", "--mu", "0.35", "--body", body, "--radius", "0.1 m",
                    "--incline", f"{beta}deg", "--rtol", str(rtol)]
            if spin is not None:
                args += ["--omega0", f"{spin} rad/s"]
            closed = results(*args)
            ode = data(*args, "--method", "ode")
            assert ode["method"] == "ode", (body, spin, beta, ode["warnings"])
            assert ode["extra"]["error_estimate"] <= rtol
            assert set(ode["extra"]["timing"]) == {"closed_form_s", "ode_s"}
            timing = ode["extra"]["timing"]
            assert timing["ode_s"] > 0 and timing["closed_form_s"] > 0
            speed = max(4.0, abs(0.1 * (spin or 0.0)))
            for name in ("t_roll", "x_roll", "v_roll"):
                scale = {"t_roll": abs(closed["t_roll"]), "v_roll": speed,
                         "x_roll": speed * closed["t_roll"]}[name]
                got = ode["results"][name]["value"]
                assert abs(got - closed[name]) <= rtol * max(abs(closed[name]), scale), (
                    body, spin, beta, name)
            assert ode["results"]["mu_min"]["value"] == closed["mu_min"]


def test_ode_library_at_extreme_scales():
    """Scaled variables: the same answer for inputs near 1e-300 and 1e300."""
    for v0, mu, g in [(1e-150, 0.3, 1e-150), (1e150, 0.3, 1e150), (5.0, 1e-200, 1e200)]:
        closed = onset_closed_form(v0, mu, 0.4, g)
        ode = onset_ode(v0, mu, 0.4, g, rtol=1e-10)
        assert ode.t == pytest.approx(closed.t, rel=1e-10)
        assert ode.x == pytest.approx(closed.x, rel=1e-10)
        assert ode.v == pytest.approx(closed.v, rel=1e-10)


def test_ode_on_nothing_to_integrate_says_so():
    got = data("--v0", "2 m/s", "--mu", "0.3", "--radius", "0.1 m", "--omega0", "20 rad/s",
               "--method", "ode")
    assert got["method"] == "closed-form"
    assert ("--method ode: there is no sliding phase to integrate (the body is set down "
            "already rolling, s0 = 0); the closed form is given, exact") in got["warnings"]


def test_ode_explain_reports_the_trade():
    out = run("--v0", "5 m/s", "--mu", "0.3", "--method", "ode", "--explain").stdout
    assert "method: ode" in out.splitlines()[0]
    assert "method ode: solve_ivp (RK45, rtol 1e-09" in out
    assert "against" in out and "for the closed form" in out


# --- units ---------------------------------------------------------------------------------------

def test_unit_invariance():
    base = results("--v0", "5 m/s", "--mu", "0.3", "--radius", "0.11 m", "--omega0",
                   "-60 rad/s", "--incline", "10 deg", "--g", "9.80665 m/s^2")
    other = results("--v0", "(5/0.44704) mph", "--mu", "0.3", "--radius", "11 cm",
                    "--omega0", f"{-60 * 60 / (2 * math.pi)!r} rpm", "--incline",
                    f"{math.radians(10)!r} rad", "--g", "(9.80665/0.3048) ft/s^2")
    feet = results("--v0", "(5/0.3048) ft/s", "--mu", "0.3", "--radius", "(0.11/0.3048) ft",
                   "--omega0", f"{-60 * 180 / math.pi!r} deg/s", "--incline", "10deg")
    for name in base:
        assert other[name] == pytest.approx(base[name], rel=1e-13), name
        assert feet[name] == pytest.approx(base[name], rel=1e-13), name


def test_results_convert():
    res = run("--v0", "5 m/s", "--mu", "0.3", "--radius", "11cm", "--unit", "v_roll=mph",
              "--unit", "omega_roll=rpm", "--value", "omega_roll")
    assert float(res.stdout) == pytest.approx(25 / 7 / 0.11 * 60 / (2 * math.pi), rel=1e-14)


def test_pint_api():
    out = rolling_onset(Q_(5, "m/s"), 0.3, r=Q_(11, "cm"), incline=Q_(0, "deg"))
    assert out.values["v_roll"].to("m/s").magnitude == 25 / 7
    assert out.values["omega_roll"].units == Q_(1, "rad/s").units
    assert out.values["mu_min"] == 0.0


# --- properties ---------------------------------------------------------------------------------

@settings(max_examples=80, deadline=None)
@given(st.floats(1e-6, 1e6), st.floats(1e-3, 10.0))
def test_sphere_without_spin_rolls_at_five_sevenths(v0, mu):
    o = onset_closed_form(v0, mu, KAPPA["solid-sphere"], G)
    # the closed form reads v0 as its shortest decimal and rounds once: 5/7 of it, exactly
    # rounded (5 * v0 / 7 in floats rounds twice and may be an ulp off)
    assert o.v == pytest.approx(float(Fraction(repr(v0)) * 5 / 7), rel=1.2e-16)
    assert 5 * v0 / 7 * (1 - 1e-15) <= o.v <= v0


@settings(max_examples=120, deadline=None)
@given(st.floats(0.0, 100.0), st.floats(-2000.0, 2000.0), st.floats(1e-3, 2.0),
       st.sampled_from(sorted(KAPPA)), st.floats(0.01, 2.0))
def test_v_roll_between_v0_and_r_omega0(v0, omega0, r, body, mu):
    o = onset_closed_form(v0, mu, KAPPA[body], G, r, omega0)
    rim = float(Fraction(repr(r)) * Fraction(repr(omega0)))
    assert min(v0, rim) <= o.v <= max(v0, rim)
    assert o.t >= 0.0
    # angular momentum about the contact point: v0 + kappa r omega0 = (1 + kappa) v_roll
    k = shape_factor(KAPPA[body])
    lhs = Fraction(repr(v0)) + k * Fraction(repr(r)) * Fraction(repr(omega0))
    assert o.exact["v_roll"] * (1 + k) == lhs


@settings(max_examples=60, deadline=None)
@given(st.floats(0.1, 20.0), st.floats(0.05, 1.0), st.floats(-60.0, 60.0),
       st.sampled_from(sorted(KAPPA)))
def test_slip_vanishes_at_t_roll(v0, mu, beta_deg, body):
    """At t_roll, v - r omega = 0 from the equations of motion integrated by hand."""
    kappa = KAPPA[body]
    s, c = slope_sin_cos(Q_(beta_deg, "deg"))
    try:
        o = onset_closed_form(v0, mu, kappa, G, None, 0.0, s, c)
    except Exception as exc:  # never reached: only downhill, with mu at or below the limit
        assert beta_deg < 0 and mu <= kappa * abs(s / c) / (1 + kappa) * (1 + 1e-12), exc
        return
    rim = mu * G * c / kappa * o.t   # r omega(t) from rest, sigma = +1
    assert o.v == pytest.approx(rim, rel=1e-12)


# --- refusals ----------------------------------------------------------------------------------

REFUSALS = [
    (["--v0", "5", "--mu", "0"], "Error: --mu must be positive; got 0"),
    (["--v0", "5", "--mu", "-0.2"], "Error: --mu must be positive; got -0.2"),
    (["--v0", "5", "--mu", "nan"],
     "Error: --mu: cannot read 'nan': NaN is not a number dyncalc accepts"),
    (["--v0", "NaN m/s", "--mu", "0.3"],
     "Error: --v0: cannot read 'NaN m/s': NaN is not a number dyncalc accepts"),
    (["--v0", "5 kg", "--mu", "0.3"],
     "Error: --v0 must be a velocity [length]/[time]; got 5 kilogram ([mass])"),
    (["--v0", "5", "--mu", "0.3 m"], "Error: --mu must be a pure number; got 0.3 meter "
                                     "([length])"),
    (["--v0", "5", "--mu", "0.3", "--radius", "2 s"],
     "Error: --radius must be a length [length]; got 2 second ([time])"),
    (["--v0", "5", "--mu", "0.3", "--radius", "0.1", "--omega0", "3 Hz"],
     "Error: --omega0 is an angular rate; give it in rad/s, deg/s, rpm or rev/s, not Hz (a "
     "frequency in cycles)"),
    (["--v0", "5", "--mu", "0.3", "--incline", "3 m"],
     "Error: --incline must be an angle [angle]; got 3 meter ([length])"),
    (["--v0", "5", "--mu", "0.3", "--omega0", "30 rad/s"],
     "Error: --omega0 needs --radius: the contact point slips with v0 - r omega0, so the spin "
     "counts only with the radius; give --radius (e.g. --radius 0.11m)"),
    (["--v0", "5", "--mu", "0.3", "--body", "cube"],
     "Error: --body must be one of solid-sphere, hollow-sphere, solid-cylinder, "
     "hollow-cylinder, hoop; got 'cube' (or give the shape factor J_C/(m r^2) with --kappa)"),
    (["--v0", "5", "--mu", "0.3", "--body", "hoop", "--kappa", "1"],
     "Error: give --body or --kappa, not both (--kappa is the shape factor J_C/(m r^2) of any "
     "body)"),
    (["--v0", "5", "--mu", "0.3", "--kappa", "-0.5"],
     "Error: --kappa must not be negative; got -0.5"),
    (["--v0", "5 m/s", "--mu", "0.1", "--incline", "-30deg"],
     "Error: pure rolling is never reached on this slope: the contact point slides downhill "
     "(slip v0 - r omega0 = 5 m/s) and friction cannot stop it; that needs mu > kappa "
     "tan(alpha)/(1 + kappa) = 0.164957 (alpha = 30 deg, kappa = 0.4); got mu = 0.1"),
    (["--v0", "1 m/s", "--mu", "0.05", "--radius", "0.1m", "--omega0", "40rad/s",
      "--incline", "20deg"],
     "Error: pure rolling is never reached on this slope: the contact point slides downhill "
     "(slip v0 - r omega0 = -3 m/s) and friction cannot stop it; that needs mu > kappa "
     "tan(alpha)/(1 + kappa) = 0.103991 (alpha = 20 deg, kappa = 0.4); got mu = 0.05"),
    (["--v0", "5", "--mu", "0.3", "--incline", "90deg"],
     "Error: --incline must be between -90 and 90 degrees (a slope, not a wall); got 90 "
     "degree"),
    (["--v0", "5", "--mu", "0.3", "--incline", "-120deg"],
     "Error: --incline must be between -90 and 90 degrees (a slope, not a wall); got -120 "
     "degree"),
    (["--v0", "5", "--mu", "0.3", "--incline", "1.6 rad"],
     "Error: --incline must be between -90 and 90 degrees (a slope, not a wall); got 1.6 "
     "radian"),
    (["--v0", "5", "--mu", "0.3", "--incline", "10"],
     "Error: --incline must be between -90 and 90 degrees (a slope, not a wall); got 10 "
     "radian; a bare number is in radians: write 10deg for degrees"),
    (["--v0", "-5 m/s", "--mu", "0.3"],
     "Error: --v0 must not be negative: it is the speed, and its direction is the positive "
     "one (spin against it is a negative --omega0, moving downhill a negative --incline); got "
     "-5 meter / second"),
    (["--mu", "0.3"],
     "Error: rolling-onset needs --v0 (e.g. --v0 '5 m/s'); see 'dyncalc rolling-onset --help'"),
    (["--v0", "5"],
     "Error: rolling-onset needs --mu (e.g. --mu 0.3); see 'dyncalc rolling-onset --help'"),
    (["--v0", "5", "--mu", "0.3", "--g", "0 m/s^2"], "Error: --g must be positive; got 0 "
                                                     "meter / second ** 2"),
    (["--v0", "5", "--mu", "0.3", "--strict-units"],
     "Error: --v0: '5' has no unit and --strict-units is on; write it with a unit, e.g. 5 m/s"),
    (["--v0", "1e400 m/s", "--mu", "0.3"],
     "Error: --v0: cannot read '1e400 m/s': 1e400 overflows float64 (the largest is 1.8e308)"),
]


@pytest.mark.parametrize("args, message", REFUSALS, ids=[m[7:40] for _, m in REFUSALS])
def test_refusals(args, message):
    assert error_line(run(*args)) == message


def test_the_limit_itself_never_rolls():
    """mu exactly at kappa tan(alpha)/(1 + kappa): the slip stays constant, so refuse."""
    c = math.sqrt(0.5)
    s = -c  # 45 degrees downhill with tan = -1 exactly: the limit for a hoop is 1/2
    with pytest.raises(PhysicsError, match="pure rolling is never reached"):
        onset_closed_form(2.0, 0.5, 1.0, G, None, 0.0, s, c)
    assert onset_closed_form(2.0, 0.500000001, 1.0, G, None, 0.0, s, c).t > 1e6


def test_method_choice_is_checked():
    line = error_line(run("--v0", "5", "--mu", "0.3", "--method", "euler"))
    assert line.startswith("Error: Invalid value for '--method': 'euler' is not one of")


# --- numbers at the edges ------------------------------------------------------------------

def test_no_overflow_midway():
    """r omega0 = 1e300 m/s from 1e200 m and 1e100 rad/s, balanced by v0: exactly rolling."""
    got = data("--v0", "1e300 m/s", "--mu", "0.3", "--radius", "1e200 m", "--omega0",
               "1e100 rad/s")
    assert got["results"]["t_roll"]["value"] == 0.0
    assert got["results"]["omega_roll"]["value"] == 1e100


def test_overflow_and_underflow_are_reported():
    big = data("--v0", "1e308 m/s", "--mu", "1e-300", "--g", "1e-300 m/s^2")
    assert big["results"]["t_roll"]["value"] is None
    assert big["results"]["v_roll"]["value"] == pytest.approx(1e308 / 7 * 5, rel=1e-15)
    assert any(w.startswith("t_roll overflows float64") for w in big["warnings"])
    small = data("--v0", "1e-300 m/s", "--mu", "1e300", "--g", "1e300 m/s^2")
    assert small["results"]["t_roll"]["value"] == 0.0
    assert "t_roll underflows to zero (its true value is below 4.9e-324 in SI units)" in small[
        "warnings"]


def test_help_has_examples():
    out = CliRunner().invoke(cli, ["rolling-onset", "--help"]).stdout
    assert "Examples:" in out and "--omega0" in out and "--incline" in out
    assert 'dyncalc rolling-onset --v0 "5 m/s" --mu 0.3' in out
