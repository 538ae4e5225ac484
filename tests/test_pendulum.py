"""The large-amplitude pendulum (physics.oscillators: large_amplitude, pendulum,
physical_pendulum; scenes pendulum and physical-pendulum).

Accuracy is measured against mpmath at 40 digits from the float64 inputs, in ulp of the
period; the elliptic period is cross-checked with scipy's complete elliptic integral and with
the equation of motion integrated numerically; the CLI's methods, tolerances and refusals are
checked with their exact output.
"""
import math
import random

import mpmath
import pytest
from scipy.integrate import solve_ivp
from scipy.special import ellipkm1

from dyncalc.physics.oscillators import ELLIPTIC_ERROR, pendulum, physical_pendulum
from dyncalc.units import Q_
from helpers import error_line, invoke, json_of

G = 9.80665
L = 1.0

#: Amplitudes in degrees: log-spaced from 1e-7 up to 10, a grid through the middle, and
#: log-spaced toward 180 (180 - 10^-k for k = 1..9, and 179.9999).
NEAR_ZERO = [10.0 ** (e / 2) for e in range(-14, 3)]
MIDDLE = [15.0, 30.0, 45.0, 60.0, 75.0, 90.0, 105.0, 120.0, 135.0, 150.0, 165.0, 170.0, 175.0,
          179.0, 179.9999]
NEAR_HALF_TURN = [180.0 - 10.0 ** -k for k in range(1, 10)]
DEGREES = NEAR_ZERO + MIDDLE + NEAR_HALF_TURN

#: unit -> the size of half a turn in it (None: radians, where the float input is itself the
#: rounding of a multiple of pi).
HALF_TURN = {"degree": 180, "grade": 200, "radian": None}


def mp_period(theta, l=L, g=G):
    """T = 2 pi sqrt(l/g) / AGM(1, cos(theta/2)), theta an mpf in radians, l and g the floats."""
    return 2 * mpmath.pi * mpmath.sqrt(mpmath.mpf(l) / mpmath.mpf(g)) / mpmath.agm(
        1, mpmath.cos(theta / 2))


def typed(degrees, unit):
    """The amplitude typed in ``unit`` (the float nearest to it) and the exact angle in radians
    that float stands for (an mpf)."""
    with mpmath.workdps(40):
        half = HALF_TURN[unit]
        if half is None:
            value = float(mpmath.mpf(degrees) * mpmath.pi / 180)
            return value, mpmath.mpf(value)
        value = degrees if half == 180 else float(mpmath.mpf(degrees) * half / 180)
        return value, mpmath.mpf(value) * mpmath.pi / half


def ulp_error(got, reference):
    return float(abs(mpmath.mpf(got) - reference) / mpmath.mpf(math.ulp(float(reference))))


def elliptic_period(value, unit, l=L, g=G):
    out = pendulum(Q_(l, "m"), Q_(g, "m/s^2"), Q_(value, unit), method="elliptic")
    return out.values["T"].magnitude


# --- accuracy against mpmath ---------------------------------------------------------------------

@pytest.mark.parametrize("unit", ["degree", "grade", "radian"])
def test_period_within_a_few_ulp_of_mpmath(unit):
    """The elliptic period from the float amplitude, against mpmath at 40 digits.

    Degrees and grads: the complement (half turn - amplitude) is exact in the unit typed, so
    only the AGM iteration and the last few divisions round. Radians: the float typed is itself
    a rounding of the intended angle (near pi by up to 2.2e-16 absolute, which moves the period
    by ~1e-7 relative at 180 - 1e-9 deg, see below); but the reference is computed from that
    float exactly, and half_complement_sin takes pi - x against the double-double pi
    (PI_HI - x is exact by Sterbenz, PI_LO supplies the next 16 digits), so the complement
    keeps its relative accuracy and the period stays within a few ulp there too.
    """
    worst, where = 0.0, None
    with mpmath.workdps(40):
        for degrees in DEGREES:
            value, theta = typed(degrees, unit)
            error = ulp_error(elliptic_period(value, unit), mp_period(theta))
            if error > worst:
                worst, where = error, value
    assert worst <= 4.0, f"worst error {worst:.2f} ulp at {where!r} {unit}"


@pytest.mark.parametrize("unit", ["degree", "grade", "radian"])
def test_period_relative_error_over_a_random_sweep(unit):
    """Over random amplitudes the error stays below ELLIPTIC_ERROR (1e-15 relative), the bound
    the elliptic method reports; in ulp it reaches about 4.3 (5.4 in radians) because T, 1/AGM
    and AGM fall in different places of their binades (the AGM loop itself rounds by up to
    ~2.6 ulp)."""
    rng = random.Random(20240611)
    angles = ([rng.uniform(0.0, 180.0) for _ in range(150)]
              + [180.0 - 10 ** rng.uniform(-9, 1) for _ in range(150)])
    worst = worst_ulp = 0.0
    with mpmath.workdps(40):
        for degrees in angles:
            value, theta = typed(degrees, unit)
            period, reference = elliptic_period(value, unit), mp_period(theta)
            worst = max(worst, float(abs(period / reference - 1)))
            worst_ulp = max(worst_ulp, ulp_error(period, reference))
    assert worst <= ELLIPTIC_ERROR, f"worst {worst:.3g} relative ({worst_ulp:.2f} ulp) in {unit}"
    assert worst_ulp <= 6.0, f"worst {worst_ulp:.2f} ulp in {unit}"


def test_radians_near_pi_the_input_float_matters():
    """180 - 1e-9 degrees typed in radians is a float 1.7e-11 short of pi, known only to
    +-2.2e-16: that moves the period by ~1e-7 relative (the period is ill-conditioned there).
    Each result is within a few ulp of the period of the float actually typed."""
    degrees = 180.0 - 1e-9
    radians, theta = typed(degrees, "radian")
    in_degrees = elliptic_period(degrees, "degree")
    in_radians = elliptic_period(radians, "radian")
    with mpmath.workdps(40):
        assert ulp_error(in_radians, mp_period(theta)) <= 4.0
        assert ulp_error(in_degrees, mp_period(mpmath.mpf(degrees) * mpmath.pi / 180)) <= 4.0
        conditioned = float(mp_period(theta) / mp_period(mpmath.mpf(degrees) * mpmath.pi / 180))
    assert in_radians / in_degrees == pytest.approx(conditioned, rel=1e-14)
    assert 1e-9 < abs(in_radians / in_degrees - 1) < 1e-5


def test_naive_conversion_would_lose_digits():
    """What half_complement_sin avoids: cos(radians(179.999)/2) is wrong from the 10th digit,
    so a period from it would be off by ~1e-12 relative (thousands of ulp)."""
    with mpmath.workdps(40):
        reference = mp_period(mpmath.mpf(179.999) * mpmath.pi / 180)
        naive = 2 * math.pi * math.sqrt(L / G) / mpmath.agm(
            1, math.cos(math.radians(179.999) / 2))
        assert ulp_error(float(naive), reference) > 1000
        assert ulp_error(elliptic_period(179.999, "degree"), reference) <= 4.0


# --- independent checks -----------------------------------------------------------------------

@pytest.mark.parametrize("degrees", [1e-3, 5.0, 30.0, 90.0, 150.0, 179.0, 179.99, 179.999999])
def test_elliptic_integral_cross_check(degrees):
    """T = 4 K(m) / omega0 with 1 - m = cos^2(theta0/2) (scipy.special.ellipkm1)."""
    with mpmath.workdps(40):
        p = float(mpmath.cos(mpmath.mpf(degrees) * mpmath.pi / 360) ** 2)
    period = 4 * ellipkm1(p) / math.sqrt(G / L)
    assert elliptic_period(degrees, "degree") == pytest.approx(period, rel=1e-14)


@pytest.mark.parametrize("degrees", [10.0, 90.0, 170.0])
def test_quarter_period_by_integration(degrees):
    """theta'' = -(g/l) sin(theta) from (theta0, 0) reaches theta = 0 after a quarter period."""
    def rhs(t, y):
        return [y[1], -G / L * math.sin(y[0])]

    def bottom(t, y):
        return y[0]
    bottom.terminal = True
    bottom.direction = -1

    theta0 = math.radians(degrees)
    sol = solve_ivp(rhs, (0.0, 10.0), [theta0, 0.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=bottom)
    assert sol.status == 1 and len(sol.t_events[0]) == 1
    assert 4 * sol.t_events[0][0] == pytest.approx(elliptic_period(degrees, "degree"),
                                                   rel=1e-9)


# --- the command line ---------------------------------------------------------------------------

def run(*args):
    return invoke("natural-frequency", *args)


def run_json(*args):
    return json_of("natural-frequency", *args)




def test_cli_value_near_the_top():
    result = run("--length", "1m", "--amplitude", "179.999deg", "--value", "T")
    assert result.exit_code == 0 and result.stderr == ""
    with mpmath.workdps(40):
        reference = mp_period(mpmath.mpf(179.999) * mpmath.pi / 180)
        error = ulp_error(float(result.stdout), reference)
    assert error <= 4.0, f"{error:.2f} ulp"
    # near the top K = ln(4/k') + (k'^2/4)(ln(4/k') - 1) + O(k'^4 ln k'), k' = cos(theta0/2)
    k1 = math.sin(math.radians(180 - 179.999) / 2)     # the float 179.999, complement exact
    big_k = math.log(4 / k1) + k1 * k1 / 4 * (math.log(4 / k1) - 1)
    assert float(result.stdout) == pytest.approx(4 * big_k / math.sqrt(G / L), rel=1e-14)


def test_cli_small_angle_method_at_30_degrees():
    data = run_json("--length", "1m", "--amplitude", "30deg", "--method", "small-angle")
    assert data["method"] == "small-angle" and data["model"] == "linear"
    small = 2 * math.pi / math.sqrt(G)
    assert data["results"]["T"]["value"] == pytest.approx(small, rel=1e-15)
    assert data["results"]["omega_0"] == data["results"]["omega"]
    with mpmath.workdps(40):
        error = 1 - mpmath.agm(1, mpmath.cos(mpmath.pi / 12))  # (T - T0) / T
    assert data["extra"]["error_estimate"] == pytest.approx(float(error), rel=1e-12)
    assert data["warnings"] == ["the small-angle model misses the requested tolerance 1e-09: "
                                "its period is 1.71% short at 30 deg; use --method elliptic"]


@pytest.mark.parametrize("amplitude, rtol, method", [
    ("1e-5deg", None, "small-angle"),     # bound 1.9e-15 meets the default 1e-9
    ("1deg", None, "elliptic"),           # bound 1.9e-5 does not
    ("10deg", "1e-2", "small-angle"),     # 0.19% meets 1%
    ("10deg", "1e-3", "elliptic"),
])
def test_cli_auto_picks_the_cheapest_model_meeting_rtol(amplitude, rtol, method):
    extra = ["--rtol", rtol] if rtol else []
    data = run_json("--length", "1m", "--amplitude", amplitude, *extra)
    assert data["method"] == method
    assert data["warnings"] == []
    assert data["model"] == ("linear" if method == "small-angle" else "nonlinear")


def test_cli_elliptic_reports_omega_0():
    data = run_json("--length", "1m", "--amplitude", "90deg")
    assert data["method"] == "elliptic" and data["extra"]["error_estimate"] == ELLIPTIC_ERROR
    omega_0 = data["results"]["omega_0"]["value"]
    assert omega_0 == pytest.approx(math.sqrt(G), rel=1e-15)
    with mpmath.workdps(40):
        ratio = float(mpmath.agm(1, mpmath.sqrt(0.5)))
    assert data["results"]["omega"]["value"] == pytest.approx(omega_0 * ratio, rel=1e-15)


@pytest.mark.parametrize("args, message", [
    (["--amplitude", "180deg"], "Error: the amplitude must be below 180 degrees; at 180 deg "
                                "the pendulum goes over the top and does not swing back"),
    (["--amplitude", "200deg"], "Error: the amplitude must be below 180 degrees; at 200 deg "
                                "the pendulum goes over the top and does not swing back"),
    (["--amplitude", "-5deg"], "Error: --amplitude must not be negative; got -5 degree"),
    (["--method", "elliptic"], "Error: --method elliptic needs an amplitude (--amplitude or "
                               "amplitude=); without one the pendulum is linear"),
    (["--method", "quadrature", "--amplitude", "30deg"],
     "Error: --method quadrature is not offered by pendulum; it offers auto, small-angle, "
     "series, elliptic, ode"),
    (["--method", "series"], "Error: --method series needs an amplitude (--amplitude or "
                             "amplitude=); without one the pendulum is linear"),
    (["--method", "ode"], "Error: --method ode needs an amplitude (--amplitude or "
                          "amplitude=); without one the pendulum is linear"),
])
def test_cli_refusals(args, message):
    assert error_line(run("--length", "1m", *args)) == message


# --- physical pendulum ----------------------------------------------------------------------------

@pytest.mark.parametrize("amplitude", [[], ["--amplitude", "120deg"]])
def test_physical_pendulum_J_or_J_A_same_result(amplitude):
    about_centre = run_json("--scene", "physical-pendulum", "m=2kg", "a=0.5m",
                            "J=0.125 kg*m^2", *amplitude)
    about_pivot = run_json("--scene", "physical-pendulum", "m=2kg", "a=0.5m",
                           "J_A=0.625 kg*m^2", *amplitude)   # 0.125 + 2 * 0.5^2, exact
    for name in ("omega", "f", "T", "J_A"):
        assert about_centre["results"][name] == about_pivot["results"][name], name
    assert about_centre["results"]["omega"]["value"] == pytest.approx(
        math.sqrt(2 * G * 0.5 / 0.625) * (1 if not amplitude else float(
            mpmath.agm(1, mpmath.cos(mpmath.pi / 3)))), rel=1e-15)


def test_physical_pendulum_function_matches_simple_pendulum():
    """A point mass (J = 0) on an arm a is the simple pendulum of length a, at any amplitude."""
    body = physical_pendulum(Q_(3.0, "kg"), Q_(0.7, "m"), Q_(G, "m/s^2"), J=Q_(0.0, "kg*m^2"),
                             amplitude=Q_(150.0, "deg"))
    point = pendulum(Q_(0.7, "m"), Q_(G, "m/s^2"), Q_(150.0, "deg"))
    assert body.values["T"].magnitude == pytest.approx(point.values["T"].magnitude, rel=1e-15)


def test_physical_pendulum_J_A_below_m_a2_refused():
    result = run("--scene", "physical-pendulum", "m=2kg", "a=0.5m", "J_A=0.4 kg*m^2")
    assert error_line(result) == ("Error: J_A = 0.4 kg*m^2 is less than m a^2 = 0.5 kg*m^2, "
                                  "which no body can have (J_A = J + m a^2 with J >= 0)")


# --- amplitudes in other angle units -----------------------------------------------------------

def test_amplitude_in_milliradians():
    """Units without an exact half turn (mrad, urad) are converted to radians first."""
    degrees = elliptic_period(90.0, "degree")
    assert elliptic_period(500 * math.pi, "milliradian") == pytest.approx(degrees, rel=1e-14)


# --- the amplitude series and the integrated equation of motion ---------------------------------

def true_relative_error(period, degrees):
    with mpmath.workdps(40):
        reference = mp_period(mpmath.mpf(degrees) * mpmath.pi / 180)
        return float(abs(mpmath.mpf(period) / reference - 1))


@pytest.mark.parametrize("degrees", [1e-4, 1.0, 30.0, 90.0, 150.0])
@pytest.mark.parametrize("rtol", ["1e-3", "1e-6", "1e-9", "1e-12"])
def test_series_meets_rtol_and_its_bound_holds(degrees, rtol):
    """The series stops at the order rtol needs: its true error (mpmath) is within the
    error_estimate it reports (tail bound plus rounding bound), which is within rtol."""
    data = run_json("--length", "1m", "--amplitude", f"{degrees!r}deg", "--method", "series",
                    "--rtol", rtol)
    assert data["method"] == "series" and data["model"] == "nonlinear"
    assert data["warnings"] == []
    error = true_relative_error(data["results"]["T"]["value"], degrees)
    assert error <= data["extra"]["error_estimate"] <= float(rtol)
    assert data["results"]["omega_0"]["value"] == pytest.approx(math.sqrt(G), rel=1e-15)


def test_series_terms_grow_with_the_amplitude():
    """The series' order is reported in the assumptions: one term more for a tighter rtol,
    many more toward 180 degrees (its terms fall like sin^(2n)(theta0/2))."""
    def terms(amplitude, rtol):
        data = run_json("--length", "1m", "--amplitude", amplitude, "--method", "series",
                        "--rtol", rtol, "--explain")
        text = " ".join(data["extra"]["explanation"]["assumptions"])
        return int(text.split(" terms; tail bound")[0].rsplit("(", 1)[1])
    assert terms("1deg", "1e-3") == 1                 # T0 alone: theta^2/16 = 2e-5
    assert terms("1deg", "1e-6") == 2
    assert terms("90deg", "1e-9") == 26
    assert terms("170deg", "1e-3") > 100


def test_series_near_the_top_misses_rtol_and_says_so():
    data = run_json("--length", "1m", "--amplitude", "179.9deg", "--method", "series")
    error = true_relative_error(data["results"]["T"]["value"], 179.9)
    assert data["extra"]["error_estimate"] == pytest.approx(error, rel=1e-6)
    assert data["warnings"] == [
        "the series misses the requested tolerance 1e-09: after 1001 terms its period is "
        "still 39% short at 179.9 deg (its terms fall like sin^(2n)(theta0/2)); use --method "
        "elliptic"]


def test_series_below_the_rounding_floor_warns():
    data = run_json("--length", "1m", "--amplitude", "60deg", "--method", "series", "--rtol",
                    "1e-17")
    assert len(data["warnings"]) == 1
    assert data["warnings"][0].startswith("the series misses the requested tolerance 1e-17: "
                                          "the rounding of its ")
    assert (true_relative_error(data["results"]["T"]["value"], 60.0)
            <= data["extra"]["error_estimate"])


def test_elliptic_below_float64_accuracy_warns():
    data = run_json("--length", "1m", "--amplitude", "60deg", "--method", "elliptic", "--rtol",
                    "1e-16")
    assert data["warnings"] == ["the requested tolerance 1e-16 is below the accuracy of float64 "
                                "arithmetic: the elliptic period is within 1e-15 (a few ulp)"]


@pytest.mark.parametrize("amplitude, degrees", [
    ("1e-6deg", 1e-6), ("10deg", 10.0), ("90deg", 90.0), ("170deg", 170.0),
    ("179.999999deg", 179.999999),
])
@pytest.mark.parametrize("rtol", ["1e-6", "1e-10"])
def test_ode_reaches_rtol_against_mpmath(amplitude, degrees, rtol):
    """solve_ivp (DOP853) to the bottom, a quarter period; beyond 90 degrees in the angle from
    the top, so 179.999999 deg integrates as well as 10 deg. Its error_estimate is its
    difference from the elliptic period (plus the elliptic period's own 1e-15)."""
    data = run_json("--length", "1m", "--amplitude", amplitude, "--method", "ode", "--rtol",
                    rtol)
    assert data["method"] == "ode" and data["model"] == "nonlinear"
    assert data["warnings"] == []
    error = true_relative_error(data["results"]["T"]["value"], degrees)
    assert error <= float(rtol)
    assert error == pytest.approx(data["extra"]["error_estimate"], abs=2e-15)


def test_ode_in_radians_a_hair_below_pi():
    value = 3.14159265
    out = pendulum(Q_(L, "m"), Q_(G, "m/s^2"), Q_(value, "rad"), method="ode", rtol=1e-9)
    with mpmath.workdps(40):
        error = abs(out.values["T"].magnitude / mp_period(mpmath.mpf(value)) - 1)
    assert error <= 1e-9 and out.warnings == []


def test_ode_below_the_solver_floor_warns():
    data = run_json("--length", "1m", "--amplitude", "45deg", "--method", "ode", "--rtol",
                    "1e-13")
    assert data["warnings"] == ["--rtol 1e-13 is below what solve_ivp accepts; the ODE ran at "
                                "2.22e-14"]


def test_ode_imports_scipy_only_when_used():
    import subprocess
    import sys

    code = ("import sys; from dyncalc.units import Q_; "
            "from dyncalc.physics.oscillators import pendulum; "
            "pendulum(Q_(1, 'm'), Q_(9.8, 'm/s^2'), Q_(30, 'deg'), method='series'); "
            "print('scipy.integrate' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "False"


@pytest.mark.parametrize("amplitude", ["1e-6deg", "0.01deg", "1deg", "30deg", "179deg"])
@pytest.mark.parametrize("rtol", ["1e-2", "1e-6", "1e-12"])
def test_auto_never_takes_series_or_ode(amplitude, rtol):
    """The AGM costs about what the series' first term costs and auto has it in hand already
    (it decides on the exact small-angle error), so auto is small-angle or elliptic."""
    data = run_json("--length", "1m", "--amplitude", amplitude, "--rtol", rtol)
    assert data["method"] in ("small-angle", "elliptic")
    assert data["extra"]["error_estimate"] <= float(rtol) and data["warnings"] == []


@pytest.mark.parametrize("method", ["series", "ode"])
def test_physical_pendulum_offers_every_method(method):
    data = run_json("--scene", "physical-pendulum", "m=2kg", "a=0.5m", "J=0.125 kg*m^2",
                    "--amplitude", "120deg", "--method", method)
    elliptic = run_json("--scene", "physical-pendulum", "m=2kg", "a=0.5m", "J=0.125 kg*m^2",
                        "--amplitude", "120deg")
    assert data["method"] == method and data["warnings"] == []
    assert data["results"]["T"]["value"] == pytest.approx(elliptic["results"]["T"]["value"],
                                                          rel=1e-9)


def test_physical_pendulum_frequency_squared_beyond_float64():
    """omega_0^2 = m g a / J_A of 1e400 (or 1e-400) is out of float64 although omega_0 is
    not: the root is taken of the scaled monomial (root_monomial), never of its overflow."""
    huge = physical_pendulum(Q_(1e-100, "kg"), Q_(1e-100, "m"), Q_(1e300, "m/s^2"),
                             J_A=Q_(1e-300, "kg*m^2"))
    tiny = physical_pendulum(Q_(1e-300, "kg"), Q_(1.0, "m"), Q_(1e-100, "m/s^2"),
                             J_A=Q_(1.0, "kg*m^2"), amplitude=Q_(90, "deg"))
    with mpmath.workdps(40):
        big_ref = mpmath.sqrt(mpmath.mpf(1e-100) * mpmath.mpf(1e-100) * mpmath.mpf(1e300)
                              / mpmath.mpf(1e-300))
        small_ref = mpmath.sqrt(mpmath.mpf(1e-300) * mpmath.mpf(1e-100))
        assert ulp_error(huge.values["omega"].magnitude, big_ref) <= 2.0
        assert ulp_error(tiny.values["omega_0"].magnitude, small_ref) <= 2.0
