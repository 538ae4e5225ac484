"""Uncertainty (issue 10): first-order propagation against hand propagation and Monte Carlo.

Hand propagation is the GUM law u(y)^2 = sum (dy/dx_i)^2 u(x_i)^2 with the derivatives worked
from the SCENES.md formulas (or taken by mpmath.diff of the hand formula at 30 digits).

Tolerances. dyncalc differentiates by central differences with h = 1e-6 |x|: truncation
~h^2 = 1e-12, rounding ~eps/h = 2e-10 relative; 1e-8 against the hand value leaves room.
A Monte-Carlo standard deviation from N normal draws has a relative standard error of about
1/sqrt(2N) (0.5 % for N = 20000, 1.6 % for N = 2000); with 1 % input uncertainties the
second-order terms first-order propagation leaves out are ~1e-4 relative. The tolerances
(3 % and 5 %) are three to six standard errors; the seeds are fixed, so the tests are
deterministic.
"""
import json
import math

import mpmath
import numpy as np
import pytest

from dyncalc.scenes.runner import run_scene
from dyncalc.result.propagate import propagate
from helpers import count_readings, error_line, invoke, json_of

TWO_PI = 2 * math.pi
G0 = 9.80665
DIFF_TOL = 1e-8       # see the module docstring
MC_TOL_20000 = 0.03
MC_TOL_2000 = 0.05


@pytest.fixture(autouse=True)
def mp_precision():
    """30 digits for the mpmath references, restored afterwards (other modules set theirs)."""
    with mpmath.workdps(30):
        yield


def explained(*args):
    """(results, inputs, variance shares) of ``dyncalc ARGS --json --explain``."""
    data = json_of(*args, "--explain")
    return data["results"], data["inputs"], data["extra"]["explanation"]["variance"]


def assert_shares(shares, expected_terms):
    """Shares are the hand terms over their sum, and add up to 1."""
    total = sum(expected_terms.values())
    assert set(shares) == set(expected_terms), shares
    for name, term in expected_terms.items():
        assert shares[name] == pytest.approx(term / total, rel=1e-6, abs=1e-12), name
    assert sum(shares.values()) == pytest.approx(1.0, rel=1e-12)


def mc_sigma(function, means, sigmas, n=20000, seed=20240610):
    """Standard deviation of ``function(*draws)`` over ``n`` independent normal draws."""
    rng = np.random.default_rng(seed)
    draws = [rng.normal(mu, s, n) for mu, s in zip(means, sigmas)]
    return float(np.std(function(*draws), ddof=1))


# -- hand propagation -------------------------------------------------------------------------

def test_mass_spring_hand_propagation():
    """omega = sqrt(k/m): u(omega)/omega = 1/2 sqrt((u_k/k)^2 + (u_m/m)^2); f = omega/2pi and
    T = 2pi/omega carry the same relative uncertainty."""
    results, inputs, variance = explained("natural-frequency", "--k", "(100 ± 3) N/m",
                                          "--m", "2.0+/-0.08 kg")
    omega = math.sqrt(50)
    rel_u = 0.5 * math.hypot(0.03, 0.04)
    assert inputs == {"k": {"value": 100.0, "uncertainty": 3.0, "unit": "N/m",
                            "text": "(100 ± 3) N/m"},
                      "m": {"value": 2.0, "uncertainty": 0.08, "unit": "kg",
                            "text": "2.0+/-0.08 kg"}}
    assert results["omega"]["value"] == pytest.approx(omega, rel=1e-15)
    assert results["omega"]["uncertainty"] == pytest.approx(omega * rel_u, rel=DIFF_TOL)
    assert results["f"]["uncertainty"] == pytest.approx(omega * rel_u / TWO_PI, rel=DIFF_TOL)
    assert results["T"]["uncertainty"] == pytest.approx(TWO_PI / omega * rel_u, rel=DIFF_TOL)
    assert list(results["omega"]) == ["value", "uncertainty", "unit"]
    for name in ("omega", "f", "T"):   # shares (u_k/2k)^2 : (u_m/2m)^2 = 9 : 16
        assert_shares(variance[name], {"k": 0.015 ** 2, "m": 0.02 ** 2})


def test_human_output_shows_plus_minus():
    result = invoke("natural-frequency", "--k", "(100 ± 5) N/m", "--m", "2.0+/-0.1 kg")
    assert result.exit_code == 0, result.stderr
    lines = result.stdout.splitlines()
    assert any(line.split() == ["omega", "ω", "7.07107", "±", "0.25", "rad/s"]
               for line in lines), result.stdout
    assert "inputs: k = 100 ± 5 N/m, m = 2 ± 0.1 kg" in lines
    explain = invoke("natural-frequency", "--k", "(100 ± 5) N/m", "--m", "2.0+/-0.1 kg",
                     "--explain")
    assert "variance of omega: k 50.0 %, m 50.0 %" in explain.stdout.splitlines()


def test_value_of_the_uncertainty():
    result = invoke("natural-frequency", "--k", "(100 ± 5) N/m", "--m", "2 kg",
                    "--value", "u(omega)")
    assert result.exit_code == 0, result.stderr
    assert float(result.stdout) == pytest.approx(math.sqrt(50) * 0.025, rel=DIFF_TOL)


def test_pendulum_small_angle_in_length_and_gravity():
    """omega = sqrt(g/l): u(omega)/omega = 1/2 sqrt((u_l/l)^2 + (u_g/g)^2)."""
    results, _inputs, variance = explained("natural-frequency", "--length", "1 ± 0.01 m",
                                           "--g", "9.81 ± 0.05 m/s^2")
    omega = math.sqrt(9.81)
    terms = {"l": (0.5 * 0.01) ** 2, "g": (0.5 * 0.05 / 9.81) ** 2}
    rel_u = math.sqrt(sum(terms.values()))
    assert results["omega"]["uncertainty"] == pytest.approx(omega * rel_u, rel=DIFF_TOL)
    assert results["T"]["uncertainty"] == pytest.approx(TWO_PI / omega * rel_u, rel=DIFF_TOL)
    for name in ("omega", "f", "T"):
        assert_shares(variance[name], terms)


def test_spring_series_hand_propagation():
    """1/k_eq = 1/k1 + 1/k2: d k_eq / d k_i = (k_eq/k_i)^2 (0.36 and 0.16 at 200, 300 N/m)."""
    results, inputs, variance = explained("spring-series", "200+/-10 N/m", "300+/-20 N/m")
    terms = {"k1": (0.36 * 10) ** 2, "k2": (0.16 * 20) ** 2}
    assert results["k_eq"]["value"] == pytest.approx(120.0, rel=1e-15)
    assert results["k_eq"]["uncertainty"] == pytest.approx(math.sqrt(sum(terms.values())),
                                                           rel=DIFF_TOL)
    assert inputs["k2"] == {"value": 300.0, "uncertainty": 20.0, "unit": "N/m",
                            "text": "300+/-20 N/m"}
    assert_shares(variance["k_eq"], terms)


def test_rolling_onset_sphere_hand_propagation():
    """Solid sphere: t = 2 v0/(7 mu g), x = 12 v0^2/(49 mu g), v = 5 v0/7."""
    results, _inputs, variance = explained("rolling-onset", "--v0", "5+/-0.1 m/s",
                                           "--mu", "0.3+/-0.01")
    t = 2 * 5 / (7 * 0.3 * G0)
    x = 12 * 25 / (49 * 0.3 * G0)
    t_terms = {"v0": (0.1 / 5) ** 2, "mu": (0.01 / 0.3) ** 2}
    x_terms = {"v0": (2 * 0.1 / 5) ** 2, "mu": (0.01 / 0.3) ** 2}
    assert results["t_roll"]["value"] == pytest.approx(t, rel=1e-14)
    assert results["t_roll"]["uncertainty"] == pytest.approx(
        t * math.sqrt(sum(t_terms.values())), rel=DIFF_TOL)
    assert results["x_roll"]["uncertainty"] == pytest.approx(
        x * math.sqrt(sum(x_terms.values())), rel=DIFF_TOL)
    assert results["v_roll"]["uncertainty"] == pytest.approx(5 / 7 * 0.1, rel=DIFF_TOL)
    assert_shares(variance["t_roll"], t_terms)
    assert_shares(variance["x_roll"], x_terms)
    assert_shares(variance["v_roll"], {"v0": 1.0, "mu": 0.0})


def test_damping_ratio_from_c_k_m():
    """zeta = c/(2 sqrt(k m)): relative terms u_c/c, u_k/2k, u_m/2m; omega_d = sqrt(k/m -
    c^2/(4 m^2)) differentiated by mpmath."""
    results, _inputs, variance = explained("damping-ratio", "--c", "(10 ± 1) N*s/m",
                                           "--k", "(100 ± 5) N/m", "--m", "2 ± 0.1 kg")
    zeta = 10 / (2 * math.sqrt(200))
    terms = {"c": 0.1 ** 2, "k": 0.025 ** 2, "m": 0.025 ** 2}
    assert results["zeta"]["uncertainty"] == pytest.approx(
        zeta * math.sqrt(sum(terms.values())), rel=DIFF_TOL)
    assert_shares(variance["zeta"], terms)
    # Q = 1/(2 zeta): the same relative uncertainty
    assert results["Q"]["uncertainty"] / results["Q"]["value"] == pytest.approx(
        math.sqrt(sum(terms.values())), rel=DIFF_TOL)

    point = {"c": mpmath.mpf(10), "k": mpmath.mpf(100), "m": mpmath.mpf(2)}
    sigma = {"c": 1.0, "k": 5.0, "m": 0.1}

    def omega_d(c, k, m):
        return mpmath.sqrt(k / m - c ** 2 / (4 * m ** 2))

    wd_terms = {}
    for i, name in enumerate(("c", "k", "m")):
        order = [0, 0, 0]
        order[i] = 1
        slope = mpmath.diff(omega_d, (point["c"], point["k"], point["m"]), tuple(order))
        wd_terms[name] = float(slope * sigma[name]) ** 2
    assert results["omega_d"]["uncertainty"] == pytest.approx(
        math.sqrt(sum(wd_terms.values())), rel=DIFF_TOL)
    assert_shares(variance["omega_d"], wd_terms)


def test_coriolis_scalar():
    """a_c = 2 Omega v: u = 2 sqrt((v u_Omega)^2 + (Omega u_v)^2)."""
    results, _inputs, variance = explained("coriolis", "--omega", "2+/-0.1 rad/s",
                                           "--vr", "3+/-0.2 m/s")
    terms = {"omega": (2 * 3 * 0.1) ** 2, "vr": (2 * 2 * 0.2) ** 2}
    assert results["a_c"]["value"] == pytest.approx(12.0, rel=1e-15)
    assert results["a_c"]["uncertainty"] == pytest.approx(math.sqrt(sum(terms.values())),
                                                           rel=DIFF_TOL)
    assert_shares(variance["a_c"], terms)


def test_angle_result_uncertainty_in_degrees():
    """phi_0 = -atan(a0/g): dphi_0/da0 = -g/(g^2 + a0^2); the uncertainty is in phi_0's own
    unit: the canonical rad, or deg with --unit phi_0=deg."""
    words = ("natural-frequency", "--scene", "pendulum-accelerating-support", "l=1m",
             "a0=-3 ± 0.1 m/s^2")
    phi = json_of(*words)["results"]["phi_0"]
    assert phi["unit"] == "rad"
    assert phi["value"] == pytest.approx(math.atan(3 / G0), rel=1e-14)
    assert phi["uncertainty"] == pytest.approx(G0 / (G0 ** 2 + 9) * 0.1, rel=DIFF_TOL)
    phi = json_of(*words, "--unit", "phi_0=deg")["results"]["phi_0"]
    assert phi["unit"] == "deg"
    assert phi["value"] == pytest.approx(math.degrees(math.atan(3 / G0)), rel=1e-14)
    assert phi["uncertainty"] == pytest.approx(math.degrees(G0 / (G0 ** 2 + 9) * 0.1),
                                               rel=DIFF_TOL)


def test_at_a_bound_the_difference_is_one_sided():
    """d = 0 +- 0.5 N*s/m (d >= 0): d - h is refused, so dzeta/dd comes from d + h alone;
    zeta = d/(8 m omega), xi = d/(8 m) are linear in d: u = 0.5/(8 m omega), 0.5/(8 m)."""
    data = json_of("natural-frequency", "--scene", "pendulum-spring-dashpot", "m=2kg",
                   "a=0.5m", "k=200N/m", "d=0 ± 0.5 N*s/m")
    omega = math.sqrt(200 / 2 + G0 / (2 * 0.5))
    assert data["results"]["zeta"]["value"] == 0.0
    assert data["results"]["zeta"]["uncertainty"] == pytest.approx(0.5 / (16 * omega),
                                                                   rel=1e-6)
    assert data["results"]["xi"]["uncertainty"] == pytest.approx(0.5 / 16, rel=1e-6)
    assert data["results"]["omega"]["uncertainty"] == 0.0
    assert data["warnings"] == []


def test_variance_shares_always_sum_to_one():
    _results, _inputs, variance = explained(
        "natural-frequency", "--scene", "clock-pendulum", "m=0.5 ± 0.01 kg", "l=1 ± 0.01 m",
        "M=2 ± 0.05 kg", "r=0.1 ± 0.002 m", "a=0.9 ± 0.01 m", "g=9.81 ± 0.01 m/s^2")
    assert set(variance) >= {"omega", "f", "T", "J_A"}
    for name, shares in variance.items():
        assert set(shares) == {"m", "l", "M", "r", "a", "g"} or name == "J_A", shares
        assert all(0 <= s <= 1 for s in shares.values()), shares
        assert sum(shares.values()) == pytest.approx(1.0, rel=1e-12), name


def test_python_api():
    """dyncalc.result.propagate.propagate over run_scene: SI uncertainties on the entries."""
    result = propagate(lambda: run_scene("mass-spring", {"k": "100+/-5 N/m", "m": "2 kg"}))
    assert result.results["omega"].uncertainty == pytest.approx(math.sqrt(50) * 0.025,
                                                                rel=DIFF_TOL)
    assert result.inputs["k"].uncertainty == 5.0
    assert result.explanation.variance["omega"] == {"k": 1.0}
    plain = propagate(lambda: run_scene("mass-spring", {"k": "100 N/m", "m": "2 kg"}))
    assert plain.results["omega"].uncertainty is None


# -- Monte Carlo --------------------------------------------------------------------------------

def test_monte_carlo_mass_spring():
    """20000 draws, 1 % uncertainties: sd of sqrt(k/m) against the propagated u(omega)."""
    results = json_of("natural-frequency", "--k", "(100 ± 1) N/m", "--m", "(2 ± 0.02) kg")
    mc = mc_sigma(lambda k, m: np.sqrt(k / m), (100, 2), (1, 0.02))
    assert results["results"]["omega"]["uncertainty"] == pytest.approx(mc, rel=MC_TOL_20000)


def test_monte_carlo_spring_series():
    results = json_of("spring-series", "200 ± 2 N/m", "300 ± 3 N/m", "50 ± 0.5 N/m")
    mc = mc_sigma(lambda a, b, c: 1 / (1 / a + 1 / b + 1 / c), (200, 300, 50), (2, 3, 0.5))
    assert results["results"]["k_eq"]["uncertainty"] == pytest.approx(mc, rel=MC_TOL_20000)


def test_monte_carlo_rolling_onset():
    results = json_of("rolling-onset", "--v0", "5 ± 0.05 m/s", "--mu", "0.3 ± 0.003")
    mc_t = mc_sigma(lambda v, mu: 2 * v / (7 * mu * G0), (5, 0.3), (0.05, 0.003))
    mc_x = mc_sigma(lambda v, mu: 12 * v ** 2 / (49 * mu * G0), (5, 0.3), (0.05, 0.003))
    assert results["results"]["t_roll"]["uncertainty"] == pytest.approx(mc_t,
                                                                        rel=MC_TOL_20000)
    assert results["results"]["x_roll"]["uncertainty"] == pytest.approx(mc_x,
                                                                        rel=MC_TOL_20000)


def test_monte_carlo_damping_ratio():
    results = json_of("damping-ratio", "--c", "10 ± 0.1 N*s/m", "--k", "100 ± 1 N/m",
                      "--m", "2 ± 0.02 kg")
    mc = mc_sigma(lambda c, k, m: c / (2 * np.sqrt(k * m)), (10, 100, 2), (0.1, 1, 0.02))
    assert results["results"]["zeta"]["uncertainty"] == pytest.approx(mc, rel=MC_TOL_20000)


def test_monte_carlo_coriolis():
    results = json_of("coriolis", "--omega", "2 ± 0.02 rad/s", "--vr", "3 ± 0.03 m/s")
    mc = mc_sigma(lambda w, v: 2 * w * v, (2, 3), (0.02, 0.03))
    assert results["results"]["a_c"]["uncertainty"] == pytest.approx(mc, rel=MC_TOL_20000)


def test_large_amplitude_pendulum_against_mpmath_and_monte_carlo():
    """T = 4 K(sin^2(theta0/2))/omega_0 at theta0 = 120 +- 2 deg, l = 1 m. The propagated
    u(T) is |dT/dtheta0| u(theta0) (mpmath.diff, tight) and the sd of 2000 runs of the scene
    itself with normal amplitudes (statistical, 5 %)."""
    data = json_of("natural-frequency", "--length", "1m", "--amplitude", "120 ± 2 deg")
    u_T = data["results"]["T"]["uncertainty"]
    assert data["inputs"]["amplitude"] == {"value": 120.0, "uncertainty": 2.0, "unit": "deg",
                                           "text": "120 ± 2 deg"}

    omega0 = mpmath.sqrt(mpmath.mpf(G0))
    slope = mpmath.diff(lambda t: 4 * mpmath.ellipk(mpmath.sin(t / 2) ** 2) / omega0,
                        mpmath.radians(120))
    assert u_T == pytest.approx(float(abs(slope) * mpmath.radians(2)), rel=1e-7)

    rng = np.random.default_rng(7)
    amplitudes = rng.normal(120.0, 2.0, 2000)
    periods = [run_scene("pendulum", {"l": "1 m", "amplitude": f"{float(a)!r} deg"})
               .results["T"].si for a in amplitudes]
    assert u_T == pytest.approx(float(np.std(periods, ddof=1)), rel=MC_TOL_2000)


# -- units --------------------------------------------------------------------------------------

def test_unit_option_converts_the_uncertainty():
    hz = json_of("natural-frequency", "--k", "(100 ± 5) N/m", "--m", "2 ± 0.1 kg")
    rpm = json_of("natural-frequency", "--k", "(100 ± 5) N/m", "--m", "2 ± 0.1 kg",
                  "--unit", "f=rpm")
    assert rpm["results"]["f"]["unit"] == "rpm"
    assert rpm["results"]["f"]["value"] == pytest.approx(60 * hz["results"]["f"]["value"],
                                                         rel=1e-14)
    assert rpm["results"]["f"]["uncertainty"] == pytest.approx(
        60 * hz["results"]["f"]["uncertainty"], rel=1e-14)
    assert rpm["results"]["f"]["uncertainty"] == pytest.approx(
        60 * math.sqrt(50) * 0.5 * math.hypot(0.05, 0.05) / TWO_PI, rel=DIFF_TOL)


@pytest.mark.parametrize("mass", ["2000 g ± 100 g", "(2000 ± 100) g", "2 kg ± 100 g",
                                  "(2 ± 0.1) kg", "2 ± 0.1"])
def test_mass_in_grams_or_kilograms(mass):
    """The same mass and uncertainty in any unit gives the same propagated omega."""
    data = json_of("natural-frequency", "--k", "100 N/m", "--m", mass)
    assert data["results"]["omega"]["uncertainty"] == pytest.approx(
        math.sqrt(50) * 0.5 * 0.05, rel=1e-9)


def test_mixed_units_input_shown_in_the_value_unit():
    data = json_of("natural-frequency", "--k", "100 N/m", "--m", "2 kg ± 100 g")
    assert data["inputs"]["m"] == {"value": 2.0, "uncertainty": 0.1, "unit": "kg",
                                   "text": "2 kg ± 100 g"}


def test_zero_uncertainty_gives_zero():
    results, inputs, variance = explained("natural-frequency", "--k", "(100 ± 0) N/m",
                                          "--m", "2 kg")
    assert inputs["k"] == {"value": 100.0, "uncertainty": 0.0, "unit": "N/m",
                           "text": "(100 ± 0) N/m"}
    for name in ("omega", "f", "T"):
        assert results[name]["uncertainty"] == 0.0
    assert not any(variance.values())


# -- refusals -------------------------------------------------------------------------------

def refusal(k_text):
    return error_line(invoke("natural-frequency", "--k", k_text, "--m", "2kg"))


def test_negative_uncertainty():
    assert refusal("100+/--5 N/m") == ("Error: --k (its uncertainty) must not be negative; "
                                       "got -5 newton / meter")
    assert refusal("(100 ± -5) N/m") == ("Error: --k (its uncertainty) must not be negative; "
                                         "got -5 newton / meter")


def test_two_plus_minus_signs():
    assert refusal("100+/-5+/-1 N/m") == ("Error: --k: cannot read '100+/-5+/-1 N/m': it has "
                                          "more than one uncertainty (+/- or ±)")
    assert refusal("100 ± 5 ± 1 N/m") == ("Error: --k: cannot read '100 ± 5 ± 1 N/m': it has "
                                          "more than one uncertainty (+/- or ±)")


def test_missing_value():
    assert refusal("+/-5 N/m") == ("Error: --k: cannot read '+/-5 N/m': write the value, then "
                                   "+/- or ±, then its standard uncertainty: 2.0+/-0.1 kg or "
                                   "(100 ± 5) N/m")


def test_missing_uncertainty_without_unit():
    assert refusal("100+/-") == ("Error: --k: cannot read '100+/-': write the value, then "
                                 "+/- or ±, then its standard uncertainty: 2.0+/-0.1 kg or "
                                 "(100 ± 5) N/m")


def test_missing_uncertainty_before_a_unit():
    """'100+/- N/m' lacks the uncertainty exactly as '100+/-' does; the refusal must say so
    and quote what was typed, not the fragment ' N/m' with the advice 'write 1 N/m'."""
    assert refusal("100+/- N/m") == ("Error: --k: cannot read '100+/- N/m': write the value, "
                                     "then +/- or ±, then its standard uncertainty: "
                                     "2.0+/-0.1 kg or (100 ± 5) N/m")


def test_uncertainty_of_the_wrong_dimension():
    assert refusal("100 N/m ± 5 kg") == ("Error: --k (its uncertainty) must be a stiffness "
                                         "[force]/[length]; got 5 kilogram ([mass])")


def test_unit_inside_and_outside_the_parentheses():
    assert refusal("(100 ± 5 kg) N/m") == ("Error: --k: cannot read '(100 ± 5 kg) N/m': give "
                                           "the unit once, after the parentheses: "
                                           "(100 ± 5) N/m")


# -- with inverse problems ----------------------------------------------------------------------

def test_inverse_carries_the_uncertainty_of_the_target():
    """k = (2 pi f)^2 m: u(k) = 2 k u(f)/f."""
    data = json_of("natural-frequency", "f=5 ± 0.1 Hz", "m=2kg")
    k = (TWO_PI * 5) ** 2 * 2
    assert data["inputs"]["f"] == {"value": 5.0, "uncertainty": 0.1, "unit": "Hz",
                                   "text": "5 ± 0.1 Hz"}
    assert data["results"]["k"]["value"] == pytest.approx(k, rel=1e-12)
    assert data["results"]["k"]["uncertainty"] == pytest.approx(2 * k * 0.1 / 5, rel=DIFF_TOL)
    assert data["results"]["omega"]["uncertainty"] == pytest.approx(TWO_PI * 0.1,
                                                                    rel=DIFF_TOL)


def test_inverse_with_two_uncertain_inputs():
    """u(k)/k = sqrt((2 u_f/f)^2 + (u_m/m)^2): shares 0.8 (f) and 0.2 (m)."""
    results, _inputs, variance = explained("natural-frequency", "f=5 ± 0.1 Hz",
                                           "m=2 ± 0.04 kg")
    k = (TWO_PI * 5) ** 2 * 2
    terms = {"f": (2 * 0.02) ** 2, "m": 0.02 ** 2}
    assert results["k"]["uncertainty"] == pytest.approx(k * math.sqrt(sum(terms.values())),
                                                        rel=DIFF_TOL)
    assert_shares(variance["k"], terms)


def test_inverse_with_two_roots_propagates_each():
    """bead-on-rotating-ring, omega = 2 +- 0.02 rad/s: below the bifurcation Omega^2 = g/r -
    omega^2 (dOmega/domega = -omega/Omega); above it Omega^2 = (omega^2 + sqrt(omega^4 +
    4 (g/r)^2))/2 (differentiated by mpmath)."""
    data = json_of("natural-frequency", "--scene", "bead-on-rotating-ring",
                   "omega=2 ± 0.02 rad/s", "r=0.5m", "Omega=?")
    gr = G0 / 0.5
    low = math.sqrt(gr - 4)
    high_slope = mpmath.diff(lambda w: mpmath.sqrt((w ** 2 + mpmath.sqrt(w ** 4 + 4 * gr ** 2))
                                                   / 2), 2)
    # Omega_1, Omega_2 are the same spins the other way (-high, -low): the same uncertainty
    for low_name, high_name in (("Omega_3", "Omega_4"), ("Omega_2", "Omega_1")):
        assert data["results"][low_name]["uncertainty"] == pytest.approx(2 / low * 0.02,
                                                                         rel=1e-7)
        assert data["results"][high_name]["uncertainty"] == pytest.approx(
            float(high_slope) * 0.02, rel=1e-7)


# -- inputs the propagation must keep apart -------------------------------------------------------

def test_standard_option_aliases_with_equal_values():
    """--kt 2 +- 0.5 N*m/rad and --inertia 2 +- 0.1 kg*m^2 (equal SI numbers): omega =
    sqrt(kt/J) = 1 rad/s, u = 1/2 sqrt(0.25^2 + 0.05^2) = 0.1275 rad/s, shares 25:1. The same
    inputs typed kt= and J= give it; the option spelling must not change the answer."""
    results, _inputs, variance = explained("natural-frequency", "--kt", "2 ± 0.5 N*m/rad",
                                           "--inertia", "2 ± 0.1 kg*m^2")
    terms = {"kt": 0.125 ** 2, "J": 0.025 ** 2}
    assert results["omega"]["uncertainty"] == pytest.approx(math.sqrt(sum(terms.values())),
                                                            rel=DIFF_TOL)
    assert_shares(variance["omega"], terms)


def test_two_equal_springs_are_two_inputs():
    """spring-series 200+-10 N/m 200+-10 N/m: k_eq = 100 N/m, dk_eq/dk_i = 1/4 for each, so
    u = 2.5 sqrt(2) = 3.54 N/m, half the variance from each spring."""
    results, _inputs, variance = explained("spring-series", "200 ± 10 N/m", "200 ± 10 N/m")
    assert results["k_eq"]["uncertainty"] == pytest.approx(2.5 * math.sqrt(2), rel=DIFF_TOL)
    assert_shares(variance["k_eq"], {"k1": 6.25, "k2": 6.25})


def test_shared_value_is_one_input():
    """EI=(2e4 +- 200) N*m^2 shared by two cantilevers in parallel: k_eq = 3 EI/8 + 3 EI =
    3.375 EI, one uncertain quantity, so u(k_eq) = 3.375 * 200 = 675 N/m; u(k1) = 3/8 * 200 =
    75 N/m, u(k2) = 3 * 200 = 600 N/m."""
    data = json_of("spring-parallel", "cantilever(l=2m)", "cantilever(l=1m)",
                   "EI=(2e4 ± 200) N*m^2")
    assert data["results"]["k_eq"]["value"] == pytest.approx(67500.0, rel=1e-15)
    assert data["results"]["k1"]["uncertainty"] == pytest.approx(75.0, rel=DIFF_TOL)
    assert data["results"]["k2"]["uncertainty"] == pytest.approx(600.0, rel=DIFF_TOL)
    assert data["results"]["k_eq"]["uncertainty"] == pytest.approx(675.0, rel=DIFF_TOL)


def test_per_element_values_are_independent_inputs():
    """The same EI typed in each element: two independent quantities, u(k_eq) =
    sqrt(75^2 + 600^2) N/m."""
    data = json_of("spring-parallel", "cantilever(l=2m, EI=(2e4 ± 200) N*m^2)",
                   "cantilever(l=1m, EI=(2e4 ± 200) N*m^2)")
    assert data["results"]["k1"]["uncertainty"] == pytest.approx(75.0, rel=DIFF_TOL)
    assert data["results"]["k2"]["uncertainty"] == pytest.approx(600.0, rel=DIFF_TOL)
    assert data["results"]["k_eq"]["uncertainty"] == pytest.approx(math.hypot(75, 600),
                                                                   rel=DIFF_TOL)


def test_json_is_valid_and_full_precision():
    result = invoke("natural-frequency", "--k", "(100 ± 5) N/m", "--m", "2 kg", "--json")
    data = json.loads(result.stdout)
    assert isinstance(data["results"]["omega"]["uncertainty"], float)


# --- propagation on the parsed inputs (issue 14): exact where closed, linear in cost ---------

def test_spring_network_derivatives_are_exact():
    """The network's derivatives are worked out in closed form, not by differences: the
    hand value sqrt((0.36*10)^2 + (0.16*20)^2) is met to rounding (central differences with a
    step of 1e-6 are off by about 1e-10)."""
    results, _inputs, variance = explained("spring-series", "200+/-10 N/m", "300+/-20 N/m")
    expected = math.hypot(0.36 * 10, 0.16 * 20)
    assert results["k_eq"]["uncertainty"] == pytest.approx(expected, rel=1e-14)
    total = (0.36 * 10) ** 2 + (0.16 * 20) ** 2
    assert variance["k_eq"]["k1"] == pytest.approx((0.36 * 10) ** 2 / total, rel=1e-14)


def test_nested_network_and_element_derivatives_are_exact():
    """series(parallel(cantilever(l=2m), 5 kN/m), 10 kN/m) with EI = (2e4 ± 200) N*m^2 shared
    and l of the cantilever ± 1 cm: k_c = 3 EI / l^3 = 7500 N/m, K_p = 12500 N/m,
    k_eq = 1/(1/12500 + 1/10000) = 50000/9 N/m; d k_eq / d K_p = (k_eq / K_p)^2 = 16/81,
    d k_c / d EI = 3 / l^3 = 0.375 /m, d k_c / d l = -3 k_c / l = -11250 N/m^2."""
    data = json_of("spring-series", "parallel(cantilever(l=(2 ± 0.01) m), 5 kN/m)",
                   "10 kN/m", "EI=(2e4 ± 200) N*m^2")
    down = 16 / 81
    u_kc = math.hypot(0.375 * 200, 11250 * 0.01)
    assert data["results"]["k1"]["uncertainty"] == pytest.approx(u_kc, rel=1e-14)
    assert data["results"]["k_eq"]["value"] == pytest.approx(50000 / 9, rel=1e-15)
    assert data["results"]["k_eq"]["uncertainty"] == pytest.approx(down * u_kc, rel=1e-14)


def test_propagation_reads_every_text_once(monkeypatch):
    """The cost of propagation grows linearly with the number of uncertain inputs: nothing is
    parsed again (n uncertain springs: exactly n readings, for n = 5 and n = 40), and a
    scene's nudged computations call its physics twice per uncertain input, no more."""
    from dyncalc.commands import springs as springs_module

    calls = count_readings(monkeypatch, springs_module)
    for n in (5, 40):
        calls.clear()
        texts = [f"{100 + i} N/m ± 1%" for i in range(n)]
        result = propagate(lambda: springs_module.network_stiffness("series", texts))
        assert len(calls) == n
        assert result.results["k_eq"].uncertainty > 0

    scene_calls = []
    from dyncalc.scenes import get_scene

    scene = get_scene("mass-spring")
    counted = scene.replace(compute=lambda **kw: scene_calls.append(1) or scene.compute(**kw))
    propagate(lambda: run_scene(counted, {"k": "100+/-5 N/m", "m": "2+/-0.1 kg"}))
    assert len(scene_calls) == 1 + 2 * 2


def test_inverse_problem_propagates_by_the_implicit_function_theorem(monkeypatch):
    """f = (5 ± 0.1) Hz, m = (2 ± 0.05) kg, k solved: k = (2 pi f)^2 m, so dk/df = 2 k / f and
    dk/dm = k / m; the root is searched for once (the derivatives come from the forward scene
    next to it, not from solving again)."""
    from dyncalc.commands.natural_frequency import compute_scene
    from dyncalc.scenes import inverse

    searches = []
    original = inverse._Problem.roots

    def counting(self, goal):
        searches.append(goal)
        return original(self, goal)

    monkeypatch.setattr(inverse._Problem, "roots", counting)
    result = propagate(lambda: compute_scene("mass-spring",
                                             {"f": "(5 ± 0.1) Hz", "m": "(2 ± 0.05) kg"}))
    k = (2 * math.pi * 5) ** 2 * 2
    assert result.results["k"].si == pytest.approx(k, rel=1e-14)
    expected = k * math.hypot(2 * 0.1 / 5, 0.05 / 2)
    assert result.results["k"].uncertainty == pytest.approx(expected, rel=DIFF_TOL)
    assert len(searches) == 1
