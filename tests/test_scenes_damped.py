"""The damping scenes (SCENES.md): pendulum-spring-dashpot (E5.18), rod-in-fluid (E5.14) and
frame-brace-damper (E5.21).

Each scene: its textbook formula, its worked example, an independent check (the equation of
motion set up again from the figure and integrated with scipy; the resonance peak found by
maximising the steady amplitude numerically), unit invariance and its refusals.
"""
import math

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import quad, solve_ivp
from scipy.optimize import minimize_scalar

from dyncalc.scenes.runner import run_scene
from dyncalc.units import Q_
from helpers import error_line, invoke, json_of

G = 9.80665
TWO_PI = 2 * math.pi

PSD = "pendulum-spring-dashpot"
ROD = "rod-in-fluid"
FRAME = "frame-brace-damper"

PSD_TEXTS = {"m": "2 kg", "a": "0.5 m", "k": "200 N/m", "d": "6 N*s/m"}
ROD_TEXTS = {"m": "1.5 kg", "l": "0.8 m", "beta": "2 N*s/m^2"}
FRAME_TEXTS = {"m": "500 kg", "k": "200 kN/m", "d": "2 kN*s/m", "b0": "1 m/s^2"}


def si(result, name):
    return result.results[name].si


def run(*args):
    return invoke("natural-frequency", *args)


def run_json(*args):
    return json_of("natural-frequency", *args)




def words(texts):
    return [f"{name}={text}" for name, text in texts.items()]


# --- the textbook formulas -------------------------------------------------------------------

@pytest.mark.parametrize("m, a, k, d, g", [
    (2.0, 0.5, 200.0, 6.0, G), (0.3, 1.7, 5.0, 0.01, 1.62), (80.0, 0.05, 1e5, 900.0, G),
])
def test_pendulum_spring_dashpot_formula(m, a, k, d, g):
    out = run_scene(PSD, {"m": repr(m), "a": repr(a), "k": repr(k), "d": repr(d),
                          "g": repr(g)})
    omega = math.sqrt(k / m + g / (2 * a))
    xi = d / (8 * m)
    zeta = xi / omega
    assert si(out, "omega") == pytest.approx(omega, rel=1e-15)
    assert si(out, "f") == pytest.approx(omega / TWO_PI, rel=1e-15)
    assert si(out, "T") == pytest.approx(TWO_PI / omega, rel=1e-15)
    assert si(out, "xi") == pytest.approx(xi, rel=1e-15)
    assert si(out, "zeta") == pytest.approx(zeta, rel=1e-15)
    omega_d = omega * math.sqrt(1 - zeta ** 2)
    assert si(out, "omega_d") == pytest.approx(omega_d, rel=1e-15)
    assert si(out, "T_d") == pytest.approx(TWO_PI / omega_d, rel=1e-15)
    assert out.scene == PSD and out.method == "closed-form" and out.warnings == []


@pytest.mark.parametrize("m, l, beta, g", [
    (1.5, 0.8, 2.0, G), (0.02, 0.3, 1e-3, G), (1000.0, 12.0, 50.0, 3.71),
])
def test_rod_in_fluid_formula(m, l, beta, g):
    out = run_scene(ROD, {"m": repr(m), "l": repr(l), "beta": repr(beta), "g": repr(g)})
    omega = math.sqrt(3 * g / (2 * l))
    xi = beta * l / (2 * m)
    beta_crit = m / l * math.sqrt(6 * g / l)
    assert si(out, "omega") == pytest.approx(omega, rel=1e-15)
    assert si(out, "xi") == pytest.approx(xi, rel=1e-15)
    assert si(out, "zeta") == pytest.approx(xi / omega, rel=1e-14)
    assert si(out, "zeta") == pytest.approx(beta / beta_crit, rel=1e-14)
    assert si(out, "beta_crit") == pytest.approx(beta_crit, rel=1e-15)
    assert si(out, "omega_d") == pytest.approx(omega * math.sqrt(1 - (xi / omega) ** 2),
                                               rel=1e-14)


@pytest.mark.parametrize("m, k, d, b0", [
    (500.0, 2e5, 2e3, 1.0), (3.0, 40.0, 0.5, 9.81), (1e4, 3e7, 2e5, 0.2),
])
def test_frame_brace_damper_formula(m, k, d, b0):
    out = run_scene(FRAME, {"m": repr(m), "k": repr(k), "d": repr(d), "b0": repr(b0)})
    omega = math.sqrt(k / (2 * m))
    zeta = d / 2 * math.sqrt(1 / (2 * k * m))
    y0 = 2 * m * b0 / k
    assert si(out, "omega") == pytest.approx(omega, rel=1e-15)
    assert si(out, "zeta") == pytest.approx(zeta, rel=1e-15)
    assert si(out, "y0") == pytest.approx(y0, rel=1e-15)
    assert si(out, "y_max") == pytest.approx(y0 / (2 * zeta * math.sqrt(1 - zeta ** 2)),
                                             rel=1e-14)
    assert si(out, "omega_d") == pytest.approx(omega * math.sqrt(1 - zeta ** 2), rel=1e-15)
    assert out.method == "exact" and out.extra == {}


def test_frame_heavy_damping_gives_the_static_amplitude():
    """zeta >= 1/sqrt(2): no resonance peak, y_max = y0 (the formulas meet at 1/sqrt(2))."""
    out = run_scene(FRAME, {**FRAME_TEXTS, "d": "20 kN*s/m"})   # zeta = 0.707106...
    zeta = si(out, "zeta")
    assert zeta == pytest.approx(math.sqrt(0.5), rel=1e-15)
    assert si(out, "y_max") == pytest.approx(si(out, "y0"), rel=1e-15)
    heavy = run_scene(FRAME, {**FRAME_TEXTS, "d": "30 kN*s/m"})  # zeta = 1.06
    assert si(heavy, "y_max") == si(heavy, "y0") == 0.005
    assert "omega_d" not in heavy.results
    assert heavy.warnings == ["zeta = 1.06066: the system is overdamped; it does not "
                              "oscillate, so there is no damped frequency"]


# --- the worked examples -----------------------------------------------------------------------

def test_e5_18_amplitude_to_a_tenth_in_ten_cycles():
    """E5.18: the amplitude falls to a tenth in ten cycles: delta = ln(10)/10 per cycle, so
    zeta = delta / sqrt(4 pi^2 + delta^2) = 0.037 (ln(10)/(2 pi 10) for small damping)."""
    delta = math.log(10) / 10
    zeta = delta / math.sqrt(4 * math.pi ** 2 + delta ** 2)
    assert round(zeta, 3) == round(math.log(10) / (2 * math.pi * 10), 3) == 0.037
    m, a, k = 2.0, 0.5, 200.0
    omega = math.sqrt(k / m + G / (2 * a))
    d = 8 * m * zeta * omega                      # the dashpot that gives it
    out = run_scene(PSD, {"m": f"{m} kg", "a": f"{a} m", "k": f"{k} N/m", "d": f"{d!r} N*s/m"})
    assert si(out, "zeta") == pytest.approx(zeta, rel=1e-14)
    # ten damped periods shrink the amplitude by exp(-xi 10 T_d) = 1/10
    assert math.exp(si(out, "xi") * 10 * si(out, "T_d")) == pytest.approx(10, rel=1e-13)


def test_e5_18_underdamped_iff_d_below_the_critical_value():
    m, a, k = 2.0, 0.5, 200.0
    critical = 8 * math.sqrt(k * m + G * m ** 2 / (2 * a))
    below = run_scene(PSD, {"m": "2 kg", "a": "0.5 m", "k": "200 N/m",
                            "d": f"{critical * (1 - 1e-9)!r} N*s/m"})
    assert si(below, "zeta") < 1 and "omega_d" in below.results and below.warnings == []
    above = run_scene(PSD, {"m": "2 kg", "a": "0.5 m", "k": "200 N/m", "d": "300 N*s/m"})
    assert si(above, "zeta") == pytest.approx(300 / critical, rel=1e-15)
    assert "omega_d" not in above.results and "T_d" not in above.results
    assert above.warnings == [
        "zeta = 1.78932: the system is overdamped; it does not oscillate, so there is no "
        "damped frequency; it oscillates only for d < 8 sqrt(k m + g m^2/(2a)) = 167.662 N*s/m"]


def test_e5_18_at_the_critical_dashpot_the_scene_says_critically_damped_as_damping_ratio():
    """Issue 15: at d = 8 sqrt(k m + g m^2/(2a)) (mpmath, 40 digits, rounded to the nearest
    float) zeta rounds to 1 + 2^-52; the scene called that "overdamped" while damping-ratio
    called the same zeta "critically damped". Both now say critically damped."""
    from dyncalc.physics.damping import damping_from_zeta

    with mpmath.workdps(40):
        critical = float(8 * mpmath.sqrt(15 * 1 + mpmath.mpf("9.80665") / (2 * mpmath.mpf("0.3"))))
    out = run_scene(PSD, {"m": "1 kg", "a": "0.3 m", "k": "15 N/m", "d": f"{critical!r} N*s/m"})
    zeta = si(out, "zeta")
    assert zeta != 1.0 and abs(zeta - 1.0) <= 2.0 ** -51   # the rounding, not the physics
    assert "omega_d" not in out.results
    assert out.warnings[0].startswith("zeta = 1: the system is critically damped; it does not "
                                      "oscillate")
    assert damping_from_zeta(zeta).values["regime"] == "critically damped"


def test_e5_14_critical_drag():
    """E5.14: the rod stops oscillating at beta_crit = (m/l) sqrt(6 g/l) (mpmath, 40 digits)."""
    with mpmath.workdps(40):
        m, l = mpmath.mpf("1.5"), mpmath.mpf("0.8")
        beta_crit = m / l * mpmath.sqrt(6 * mpmath.mpf("9.80665") / l)
    out = run_scene(ROD, ROD_TEXTS)
    assert si(out, "beta_crit") == pytest.approx(float(beta_crit), rel=4e-16)
    at = run_scene(ROD, {**ROD_TEXTS, "beta": f"{float(beta_crit)!r} N*s/m^2"})
    assert si(at, "zeta") == pytest.approx(1.0, rel=1e-15)
    assert si(at, "xi") == pytest.approx(si(at, "omega"), rel=1e-15)
    assert ("omega_d" in at.results) == (si(at, "zeta") < 1.0)    # either side, by rounding
    above = run_scene(ROD, {**ROD_TEXTS, "beta": f"{float(beta_crit) * 1.001!r}"})
    assert "omega_d" not in above.results
    assert above.warnings == ["zeta = 1.001: the system is overdamped; it does not oscillate, "
                              "so there is no damped frequency; it oscillates only for "
                              "beta < beta_crit = 16.0802 N*s/m^2"]
    just_below = run_scene(ROD, {**ROD_TEXTS, "beta": f"{float(beta_crit) * 0.999!r}"})
    assert si(just_below, "zeta") == pytest.approx(0.999, rel=1e-14)
    assert si(just_below, "omega_d") == pytest.approx(
        si(just_below, "omega") * math.sqrt(1 - 0.999 ** 2), rel=1e-12)


def test_e5_21_example():
    data = run_json("--scene", FRAME, *words(FRAME_TEXTS))
    assert data["method"] == "exact" and data["warnings"] == []
    assert "error_estimate" not in data["extra"]
    assert data["results"]["y0"] == {"value": 0.005, "unit": "m"}
    assert data["results"]["y_max"]["value"] == pytest.approx(0.035444060250416795, rel=1e-15)


# --- independent checks: the equation of motion set up from the figure and integrated ------

def _damped_motion(mass, damping, stiffness, x0):
    """Integrate mass x'' + damping x' + stiffness x = 0 from (x0, 0); return the damped period
    (from successive upward zero crossings) and the decay rate (from successive peaks)."""
    omega = math.sqrt(stiffness / mass)
    periods = 6
    t_end = periods * TWO_PI / omega * 1.5

    def rhs(t, y):
        return [y[1], -(damping * y[1] + stiffness * y[0]) / mass]

    def upward(t, y):
        return y[0]
    upward.direction = 1

    def peak(t, y):
        return y[1]
    peak.direction = -1

    sol = solve_ivp(rhs, (0.0, t_end), [x0, 0.0], method="DOP853", rtol=1e-12,
                    atol=1e-15 * abs(x0), events=[upward, peak])
    assert sol.success
    crossings = sol.t_events[0]
    peak_t, peak_x = sol.t_events[1], sol.y_events[1][:, 0]
    assert len(crossings) >= 4 and len(peak_t) >= 4
    period = np.diff(crossings)
    assert np.ptp(period) < 1e-9 * period.mean()          # evenly spaced, as it must be
    decay = np.log(peak_x[:-1] / peak_x[1:]) / np.diff(peak_t)
    return period.mean(), decay.mean()


def test_pendulum_spring_dashpot_integrated():
    """Moments about the pivot: the bob m at 2a (inertia m (2a)^2), the spring at 2a (arm 2a,
    stretch 2a phi), the dashpot at a (arm a, speed a phi'), the weight at 2a."""
    m, a, k, d = 2.0, 0.5, 200.0, 6.0
    inertia = m * (2 * a) ** 2
    damping = d * a * a
    stiffness = k * (2 * a) ** 2 + m * G * 2 * a
    period, decay = _damped_motion(inertia, damping, stiffness, math.radians(3))
    out = run_scene(PSD, PSD_TEXTS)
    assert si(out, "T_d") == pytest.approx(period, rel=1e-9)
    assert si(out, "xi") == pytest.approx(decay, rel=1e-7)


def test_rod_in_fluid_integrated():
    """The rod's inertia, drag moment and weight moment summed element by element (quad)."""
    m, l, beta = 1.5, 0.8, 2.0
    inertia = quad(lambda x: m / l * x * x, 0, l)[0]           # element dm = m/l dx at x
    damping = quad(lambda x: beta * x * x, 0, l)[0]            # drag beta (x phi') dx, arm x
    stiffness = quad(lambda x: m / l * G * x, 0, l)[0]         # weight g dm, arm x sin(phi)
    period, decay = _damped_motion(inertia, damping, stiffness, math.radians(2))
    out = run_scene(ROD, ROD_TEXTS)
    assert si(out, "T_d") == pytest.approx(period, rel=1e-9)
    assert si(out, "xi") == pytest.approx(decay, rel=1e-7)


def _frame_coefficients(m, k, d):
    """A brace at 45 degrees: a sway y stretches it by y cos(45), and its force acts on the beam
    with the horizontal share cos(45): k_h = k cos^2(45), d_h = d cos^2(45)."""
    c2 = math.cos(math.pi / 4) ** 2
    return m, d * c2, k * c2


def test_frame_brace_damper_integrated():
    m, k, d = 500.0, 2e5, 2e3
    mass, damping, stiffness = _frame_coefficients(m, k, d)
    period, decay = _damped_motion(mass, damping, stiffness, 0.01)
    out = run_scene(FRAME, FRAME_TEXTS)
    assert si(out, "T_d") == pytest.approx(period, rel=1e-9)
    assert si(out, "zeta") * si(out, "omega") == pytest.approx(decay, rel=1e-7)


@pytest.mark.parametrize("d", [2e3, 8e3, 15e3, 25e3])
def test_frame_y_max_is_the_largest_steady_amplitude(d):
    """The steady amplitude of m y'' + d_h y' + k_h y = -m b0 cos(W t) is
    m b0 / |k_h - m W^2 + i d_h W|: maximise it over W numerically."""
    m, k, b0 = 500.0, 2e5, 1.0
    mass, damping, stiffness = _frame_coefficients(m, k, d)
    omega = math.sqrt(stiffness / mass)

    def minus_amplitude(w):
        return -mass * b0 / abs(stiffness - mass * w * w + 1j * damping * w)

    best = minimize_scalar(minus_amplitude, bounds=(0.0, 3 * omega), method="bounded",
                           options={"xatol": 1e-12 * omega})
    peak = max(-best.fun, -minus_amplitude(0.0))
    out = run_scene(FRAME, {**FRAME_TEXTS, "d": f"{d!r} N*s/m"})
    assert si(out, "y_max") == pytest.approx(peak, rel=1e-12)


def test_frame_forced_response_reaches_y_max():
    """Shake the ground at the peak frequency from rest; once the transient has died the
    sway swings with amplitude y_max."""
    m, k, d, b0 = 500.0, 2e5, 6e3, 1.0         # zeta = 0.212: the transient dies quickly
    mass, damping, stiffness = _frame_coefficients(m, k, d)
    out = run_scene(FRAME, {**FRAME_TEXTS, "d": "6 kN*s/m"})
    omega, zeta = si(out, "omega"), si(out, "zeta")
    forcing = omega * math.sqrt(1 - 2 * zeta ** 2)
    settle = 30 / (zeta * omega)                # transient below e^-30

    def rhs(t, y):
        return [y[1], -(damping * y[1] + stiffness * y[0]) / mass - b0 * math.cos(forcing * t)]

    def peak(t, y):
        return y[1]

    t_end = settle + 3 * TWO_PI / forcing
    sol = solve_ivp(rhs, (0.0, t_end), [0.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-16,
                    events=[peak])
    late = np.abs(sol.y_events[0][:, 0][sol.t_events[0] > settle])
    assert len(late) >= 4
    assert late.max() == pytest.approx(si(out, "y_max"), rel=1e-8)


# --- methods of frame-brace-damper -------------------------------------------------------------

def test_frame_auto_takes_small_damping_only_when_it_meets_rtol():
    exact = run_json("--scene", FRAME, *words(FRAME_TEXTS))
    assert exact["method"] == "exact"
    loose = run_json("--scene", FRAME, *words(FRAME_TEXTS), "--rtol", "1e-2")
    assert loose["method"] == "small-damping" and loose["warnings"] == []
    with mpmath.workdps(30):
        zeta = mpmath.mpf(2000) / 2 * mpmath.sqrt(1 / (mpmath.mpf(2) * 2e5 * 500))
        error = 1 - mpmath.sqrt(1 - zeta ** 2)
    assert loose["extra"]["error_estimate"] == pytest.approx(float(error), rel=1e-12)
    assert loose["results"]["y_max"]["value"] == pytest.approx(0.005 / (2 * float(zeta)),
                                                               rel=1e-15)
    assert run_json("--scene", FRAME, *words(FRAME_TEXTS), "--rtol", "2e-3")["method"] == "exact"
    # a very light damper: zeta = 7.07e-6, error 2.5e-11 meets the default 1e-9
    light = run_json("--scene", FRAME, *words({**FRAME_TEXTS, "d": "0.2 N*s/m"}))
    assert light["method"] == "small-damping"
    assert light["extra"]["error_estimate"] == pytest.approx(2.5e-11, rel=1e-9)


def test_frame_forced_small_damping_warns_when_it_misses_rtol():
    data = run_json("--scene", FRAME, *words(FRAME_TEXTS), "--method", "small-damping")
    assert data["method"] == "small-damping"
    assert data["warnings"] == ["the small-damping model misses the requested tolerance 1e-09: "
                                "its y_max is 0.25% low at zeta = 0.0707107; use --method exact"]
    exact = run_json("--scene", FRAME, *words(FRAME_TEXTS), "--method", "exact")
    assert exact["method"] == "exact" and exact["warnings"] == []
    ratio = data["results"]["y_max"]["value"] / exact["results"]["y_max"]["value"]
    assert 1 - ratio == pytest.approx(data["extra"]["error_estimate"], rel=1e-12)


# --- zero damping is allowed -------------------------------------------------------------------

def test_zero_damping():
    psd = run_scene(PSD, {**PSD_TEXTS, "d": "0 N*s/m"})
    assert si(psd, "zeta") == 0.0 and si(psd, "xi") == 0.0
    assert si(psd, "omega_d") == si(psd, "omega") and psd.warnings == []
    rod = run_scene(ROD, {**ROD_TEXTS, "beta": "0"})
    assert si(rod, "zeta") == 0.0 and si(rod, "T_d") == si(rod, "T")
    frame = run_scene(FRAME, {**FRAME_TEXTS, "d": "0"})
    assert si(frame, "zeta") == 0.0 and "y_max" not in frame.results
    assert frame.warnings == ["without damping (d = 0) the steady amplitude grows without "
                              "bound at resonance (Omega = omega); y_max is not given"]


# --- extremes: no overflow on the way --------------------------------------------------------

@mpmath.workdps(40)
def test_extreme_inputs_match_mpmath():
    """Products such as m^3 b0^2 or k m overflow float64 here; the results do not."""
    mp = mpmath.mpf
    m, k, d, b0 = 1e200, 1e300, 1e-10, 1e100
    out = run_scene(FRAME, {"m": repr(m), "k": repr(k), "d": repr(d), "b0": repr(b0)})
    zeta = mp(d) / 2 * mpmath.sqrt(1 / (2 * mp(k) * mp(m)))
    y0 = 2 * mp(m) * mp(b0) / mp(k)
    assert si(out, "zeta") == pytest.approx(float(zeta), rel=1e-15)
    assert si(out, "y0") == pytest.approx(float(y0), rel=1e-15)
    y_max = y0 / (2 * zeta * mpmath.sqrt(1 - zeta ** 2))   # 2.8e260; m^3 b0^2 is 1e800
    assert si(out, "y_max") == pytest.approx(float(y_max), rel=1e-15)
    assert out.method == "small-damping"  # at zeta = 3.5e-261 it is exact to rounding

    out = run_scene(FRAME, {"m": "1", "k": "1", "d": "1e-10", "b0": "1e300"})
    assert si(out, "y0") == 2e300
    assert "y_max" not in out.results      # 2e300 / 7e-11 overflows: said, not printed as inf
    assert out.warnings == ["the resonance peak overflows float64 at zeta = 3.53553e-11; "
                            "y_max is not given"]

    m, a, k, d = 1e-300, 1e-300, 1e300, 1e-150
    out = run_scene(PSD, {"m": repr(m), "a": repr(a), "k": repr(k), "d": repr(d), "g": "1"})
    omega = mpmath.sqrt(mp(k) / mp(m) + 1 / (2 * mp(a)))
    assert si(out, "omega") == pytest.approx(float(omega), rel=1e-15)
    assert si(out, "zeta") == pytest.approx(float(mp(d) / (8 * mp(m) * omega)), rel=1e-15)

    m, l, beta = 1e150, 1e-100, 1e250
    out = run_scene(ROD, {"m": repr(m), "l": repr(l), "beta": repr(beta), "g": "1"})
    crit = mp(m) / mp(l) * mpmath.sqrt(6 / mp(l))
    assert si(out, "beta_crit") == pytest.approx(float(crit), rel=1e-15)
    assert si(out, "zeta") == pytest.approx(float(mp(beta) / crit), rel=1e-15)


def test_overflowing_result_is_null_with_a_warning():
    """The runner's rule for every scene: an overflowed result is kept as inf (JSON null) with
    a warning; --value of it is refused."""
    out = run_scene(PSD, {"m": "1e-300", "a": "1", "k": "1e300", "d": "1e300"})
    assert math.isinf(out.results["xi"].si) and out.results["xi"].overflowed
    assert ("xi overflows float64 at these inputs (beyond 1.8e308 1/s); it is left out (null "
            "in JSON)") in out.warnings
    result = run("--scene", PSD, "m=1e-300", "a=1", "k=1e300", "d=1e300", "--value", "xi")
    assert error_line(result) == "Error: --value xi: xi overflows float64 at these inputs"


# --- properties --------------------------------------------------------------------------------

@settings(max_examples=40, deadline=None)
@given(st.floats(1e-3, 1e3), st.floats(1e-3, 1e3), st.just(0.0) | st.floats(1e-6, 1e3),
       st.floats(1e-6, 1e3))
def test_zeta_grows_in_proportion_to_the_damper(m, k, d1, d2):
    lo, hi = sorted((d1, d2))
    texts = {"m": repr(m), "k": repr(k), "b0": "1"}
    z_lo = si(run_scene(FRAME, {**texts, "d": repr(lo)}), "zeta")
    z_hi = si(run_scene(FRAME, {**texts, "d": repr(hi)}), "zeta")
    assert z_lo <= z_hi
    if lo > 0:
        assert z_hi / z_lo == pytest.approx(hi / lo, rel=1e-14)


# --- unit invariance ---------------------------------------------------------------------------

def _in(value_si, si_unit, unit):
    """The SI value re-typed in ``unit``."""
    return f"{value_si / Q_(1.0, unit).to(si_unit).magnitude!r} {unit}"


@pytest.mark.parametrize("scene, si_texts, other", [
    (PSD, {"m": 2.0, "a": 0.5, "k": 200.0, "d": 6.0, "g": G},
     {"m": ("kg", "lb"), "a": ("m", "ft"), "k": ("N/m", "lbf/in"), "d": ("N*s/m", "lbf*s/in"),
      "g": ("m/s^2", "ft/s^2")}),
    (ROD, {"m": 1.5, "l": 0.8, "beta": 2.0, "g": G},
     {"m": ("kg", "oz"), "l": ("m", "in"), "beta": ("N*s/m^2", "lbf*s/ft^2"),
      "g": ("m/s^2", "cm/s^2")}),
    (FRAME, {"m": 500.0, "k": 2e5, "d": 2e3, "b0": 1.0},
     {"m": ("kg", "t"), "k": ("N/m", "kN/mm"), "d": ("N*s/m", "lbf*min/ft"),
      "b0": ("m/s^2", "ft/s^2")}),
])
def test_unit_invariance(scene, si_texts, other):
    base = run_scene(scene, {name: repr(value) for name, value in si_texts.items()})
    texts = {name: _in(value, *other[name]) for name, value in si_texts.items()}
    again = run_scene(scene, texts)
    assert set(again.results) == set(base.results)
    for name, entry in base.results.items():
        assert again.results[name].si == pytest.approx(entry.si, rel=1e-13), name


# --- refusals ----------------------------------------------------------------------------------

PSD_PARAMS = ("the parameters of pendulum-spring-dashpot are: m [mass], a [length], "
              "k [force]/[length], d [force]*[time]/[length], g [length]/[time]^2 = "
              "9.80665 m/s^2")


def test_negative_damper_refused():
    result = run("--scene", PSD, *words({**PSD_TEXTS, "d": "-6 N*s/m"}))
    assert error_line(result) == "Error: d must not be negative; got -6 newton * second / meter"
    result = run("--scene", ROD, *words({**ROD_TEXTS, "beta": "-2 N*s/m^2"}))
    assert error_line(result) == ("Error: beta must not be negative; got -2 newton * second / "
                                  "meter ** 2")
    result = run("--scene", FRAME, *words({**FRAME_TEXTS, "d": "-1 N*s/m"}))
    assert error_line(result) == "Error: d must not be negative; got -1 newton * second / meter"


def test_missing_parameter_refused():
    texts = dict(PSD_TEXTS)
    del texts["k"]
    result = run("--scene", PSD, *words(texts))
    assert error_line(result) == f"Error: pendulum-spring-dashpot needs k; {PSD_PARAMS}"
    result = run("--scene", FRAME, "m=500kg", "k=200kN/m")
    assert error_line(result) == (
        "Error: frame-brace-damper needs d, b0; the parameters of frame-brace-damper are: "
        "m [mass], k [force]/[length], d [force]*[time]/[length], b0 [length]/[time]^2")


@pytest.mark.parametrize("how", [["zeta=0.1"], ["--zeta", "0.1"]])
def test_zeta_refused_by_a_scene_with_its_own_damper(how):
    result = run("--scene", PSD, *words(PSD_TEXTS), *how)
    assert error_line(result) == ("Error: pendulum-spring-dashpot takes no zeta: its damping "
                                  f"comes from its own parameters; {PSD_PARAMS}")


def test_wrong_dimension_and_methods_refused():
    result = run("--scene", ROD, *words({**ROD_TEXTS, "beta": "2 N*s/m"}))
    assert error_line(result) == ("Error: beta must be a drag per unit length "
                                  "[force]*[time]/[length]^2; got 2 newton * second / meter "
                                  "([mass] / [time])")
    result = run("--scene", PSD, *words(PSD_TEXTS), "--method", "exact")
    assert error_line(result) == ("Error: --method exact is not offered by "
                                  "pendulum-spring-dashpot; it offers auto (a closed form only)")
    result = run("--scene", FRAME, *words(FRAME_TEXTS), "--method", "elliptic")
    assert error_line(result) == ("Error: --method elliptic is not offered by "
                                  "frame-brace-damper; it offers auto, exact, small-damping")
