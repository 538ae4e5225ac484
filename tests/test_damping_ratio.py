"""``dyncalc damping-ratio`` (SPEC.md, issue 4): every input form, the fit and its shape test,
the regimes and their boundary, unit invariance, accuracy at the extremes against mpmath,
every refusal, and the picture.

Independent checks: the textbook's E5.18 and E5.14; the equation of motion integrated with
scipy (peaks found as zeros of the velocity) against the closed forms; the fit on synthetic
decays with seeded noise against the statistics of least squares; mpmath at 50 digits from the
float inputs, errors in ulps.
"""
import json
import math
import subprocess
import sys

import mpmath
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from dyncalc.commands.damping_ratio import damping_ratio
from dyncalc.physics.damping import (CRITICAL_BAND, damping_from_coefficients,
                                     damping_from_decrement, damping_from_zeta,
                                     decrement_from_zeta, free_response, zeta_from_decrement)
from dyncalc.physics.decay_fit import fit_decrement, t_critical
from dyncalc.units import Q_
from helpers import error_line, invoke, json_of

MPMATH_DPS = 50  # mpmath's digits in this module's tests (tests/conftest.py)
TWO_PI = 2 * math.pi
G = 9.80665


def run(*args):
    return invoke("damping-ratio", *args)


def run_json(*args):
    return json_of("damping-ratio", *args)


def results(*args):
    return {k: v["value"] for k, v in run_json(*args)["results"].items()}




def ulps(x, ref) -> float:
    """|x - ref| in units of the last place of ref rounded to float64."""
    return float(abs(mpmath.mpf(x) - ref) / mpmath.mpf(math.ulp(float(ref))))


def zeta_exact(delta):
    return delta / math.sqrt(4 * math.pi ** 2 + delta ** 2)


# --- the ODE: m x'' + c x' + k x = 0 from x = 1, v = 0 ----------------------------------------

def simulated_peaks(c, k, m, cycles=4):
    """Times and values of the maxima of x(t) after t = 0 (velocity crossing + to -)."""
    omega = math.sqrt(k / m)

    def rhs(t, y):
        return [y[1], -(c * y[1] + k * y[0]) / m]

    def maximum(t, y):
        return y[1]

    maximum.direction = -1
    t_end = (cycles + 0.5) * TWO_PI / (omega * math.sqrt(max(1 - (c / (2 * math.sqrt(k * m))) ** 2,
                                                              1e-6)))
    sol = solve_ivp(rhs, (0, t_end), [1.0, 0.0], method="DOP853", rtol=1e-12, atol=1e-15,
                    events=maximum)
    times, states = sol.t_events[0], sol.y_events[0]
    keep = times > 1e-9
    return times[keep], states[keep, 0]


# --- E5.18 and E5.14 -------------------------------------------------------------------------

def test_e518_a_tenth_in_ten_cycles():
    delta = math.log(10) / 10
    zeta = delta / math.sqrt(4 * math.pi ** 2 + delta ** 2)
    got = results("--ratio", "10", "--cycles", "10")
    assert got["zeta"] == pytest.approx(zeta, rel=1e-15)
    assert got["zeta"] == pytest.approx(0.036622, rel=2e-3)   # the contract smoke test
    assert round(got["zeta"], 3) == 0.037                      # the textbook's answer
    assert got["delta"] == pytest.approx(delta, rel=1e-15)
    assert got["Q"] == pytest.approx(1 / (2 * zeta), rel=1e-15)
    assert got["regime"] == "underdamped"


def test_e518_through_the_pendulum_scene():
    # E5.18 asks which dashpot gives a tenth in ten cycles: with d = 8 zeta sqrt(k m + g m^2/2a)
    # the scene's decrement must be ln(10)/10.
    m, a, k = 2.0, 0.5, 200.0
    delta = math.log(10) / 10
    d = 8 * zeta_exact(delta) * math.sqrt(k * m + G * m * m / (2 * a))
    got = results("--scene", "pendulum-spring-dashpot", f"m={m}kg", f"a={a}m", f"k={k}N/m",
                  f"d={d!r} N*s/m")
    assert got["delta"] == pytest.approx(delta, rel=1e-13)
    assert got["regime"] == "underdamped"
    # and the decay integrated from the figure's equation 4 m a^2 phi'' + d a^2 phi' +
    # (4 k a^2 + 2 m g a) phi = 0, as m' x'' + c' x' + k' x = 0
    times, peaks = simulated_peaks(d * a * a, 4 * k * a * a + 2 * m * G * a, 4 * m * a * a,
                                   cycles=11)
    assert peaks[0] / peaks[10] == pytest.approx(10.0, rel=1e-8)


def test_e514_critical_drag_of_the_rod():
    m, l = 1.5, 0.8
    beta_crit = (m / l) * math.sqrt(6 * G / l)
    got = results("--scene", "rod-in-fluid", f"m={m}kg", f"l={l}m", "beta=2 N*s/m^2")
    assert got["beta_crit"] == pytest.approx(beta_crit, rel=1e-15)
    assert got["zeta"] == pytest.approx(2 / beta_crit, rel=1e-15)
    assert got["delta"] == pytest.approx(decrement_from_zeta(2 / beta_crit), rel=1e-15)
    assert got["Q"] == pytest.approx(beta_crit / 4, rel=1e-15)
    # at the critical drag (typed as printed) the rod no longer oscillates
    data = run_json("--scene", "rod-in-fluid", f"m={m}kg", f"l={l}m",
                    f"beta={got['beta_crit']!r} N*s/m^2")
    assert data["results"]["regime"]["value"] == "critically damped"
    assert data["results"]["zeta"]["value"] == 1.0
    assert "omega_d" not in data["results"] and "delta" not in data["results"]
    # twice the critical drag: overdamped, no damped frequency and no NaN
    data = run_json("--scene", "rod-in-fluid", f"m={m}kg", f"l={l}m",
                    f"beta={2 * beta_crit!r} N*s/m^2")
    assert data["results"]["regime"]["value"] == "overdamped"
    assert data["results"]["zeta"]["value"] == pytest.approx(2.0, rel=1e-15)
    assert "omega_d" not in data["results"]
    assert any("overdamped" in w for w in data["warnings"])


def test_frame_brace_damper_scene():
    got = results("--scene", "frame-brace-damper", "m=500kg", "k=200 kN/m", "d=2 kN*s/m",
                  "b0=1 m/s^2")
    zeta = 1 / math.sqrt(200)  # (d/2) sqrt(1/(2 k m))
    assert got["zeta"] == pytest.approx(zeta, rel=1e-15)
    assert got["delta"] == pytest.approx(TWO_PI * zeta / math.sqrt(1 - zeta ** 2), rel=1e-14)
    assert got["y_max"] == pytest.approx(0.035444060250416795, rel=1e-14)  # the scene's own


def test_scene_takes_standard_options():
    a = results("--scene", "pendulum-spring-dashpot", "--k", "200N/m", "--m", "2kg", "a=0.5m",
                "d=6N*s/m", "--g", "9.81 m/s^2")
    b = results("--scene", "pendulum-spring-dashpot", "k=200N/m", "m=2kg", "a=0.5m",
                "d=6N*s/m", "g=9.81 m/s^2")
    assert a == b


# --- each input form against an independent derivation --------------------------------------

@pytest.mark.parametrize("c, k, m", [(4.0, 100.0, 1.0), (0.3, 2500.0, 3.7), (12.0, 40.0, 2.5)])
def test_coefficients_against_the_integrated_decay(c, k, m):
    got = results("--c", f"{c} N*s/m", "--k", f"{k} N/m", "--m", f"{m} kg")
    times, peaks = simulated_peaks(c, k, m)
    assert len(peaks) >= 3
    delta_sim = math.log(peaks[0] / peaks[1])
    assert got["delta"] == pytest.approx(delta_sim, rel=1e-8)
    assert got["T_d"] == pytest.approx(times[1] - times[0], rel=1e-8)
    assert got["omega_d"] == pytest.approx(TWO_PI / (times[1] - times[0]), rel=1e-8)
    assert got["f_d"] == pytest.approx(1 / (times[1] - times[0]), rel=1e-8)
    assert got["c_c"] == pytest.approx(2 * math.sqrt(k * m), rel=1e-15)
    assert got["c"] == c
    assert got["omega"] == pytest.approx(math.sqrt(k / m), rel=1e-15)
    assert got["xi"] == pytest.approx(c / (2 * m), rel=1e-15)
    assert got["zeta"] == pytest.approx(zeta_from_decrement(delta_sim), rel=1e-8)


def test_decrement_with_k_and_m_against_the_integrated_decay():
    k, m, delta = 300.0, 1.2, 0.5
    got = results("--decrement", str(delta), "--k", f"{k}N/m", "--m", f"{m}kg")
    # the c it reports, put back into the equation of motion, decays by exp(delta) a cycle
    times, peaks = simulated_peaks(got["c"], k, m)
    assert math.log(peaks[0] / peaks[1]) == pytest.approx(delta, rel=1e-8)
    assert got["T_d"] == pytest.approx(times[1] - times[0], rel=1e-8)
    assert got["c_c"] == pytest.approx(2 * math.sqrt(k * m), rel=1e-15)
    assert got["c"] == pytest.approx(zeta_exact(delta) * 2 * math.sqrt(k * m), rel=1e-15)


def test_decrement_with_omega():
    delta, omega = 0.23, 12.0
    got = results("--decrement", str(delta), "--omega", f"{omega} rad/s")
    zeta = zeta_exact(delta)
    assert got["zeta"] == pytest.approx(zeta, rel=1e-15)
    assert got["omega_d"] == pytest.approx(omega * math.sqrt(1 - zeta ** 2), rel=1e-15)
    assert got["T_d"] == pytest.approx(TWO_PI / (omega * math.sqrt(1 - zeta ** 2)), rel=1e-15)
    assert got["xi"] == pytest.approx(zeta * omega, rel=1e-15)
    # the same with k and m of that frequency: the damped quantities agree
    other = results("--decrement", str(delta), "--k", "144 N/m", "--m", "1 kg")
    for name in ("zeta", "omega_d", "T_d", "f_d", "xi"):
        assert other[name] == pytest.approx(got[name], rel=1e-15)


@pytest.mark.parametrize("ratio, cycles", [("10", "10"), ("2", "1"), ("1.0001", "3"),
                                           ("1e6", "7")])
def test_ratio_against_the_integrated_decay(ratio, cycles):
    k, m = 100.0, 1.0
    got = results("--ratio", ratio, "--cycles", cycles, "--k", "100N/m", "--m", "1kg")
    assert got["delta"] == pytest.approx(math.log(float(ratio)) / int(cycles), rel=1e-15)
    times, peaks = simulated_peaks(got["c"], k, m, cycles=int(cycles) + 1)
    assert peaks[0] / peaks[int(cycles)] == pytest.approx(float(ratio), rel=1e-7)


def test_ratio_cycles_default_to_successive_peaks():
    assert results("--ratio", "2") == results("--ratio", "2", "--cycles", "1")


def test_amplitudes_from_an_integrated_decay():
    c, k, m = 0.8, 50.0, 0.5
    times, peaks = simulated_peaks(c, k, m, cycles=8)
    text = ", ".join(repr(float(p)) for p in peaks[:8]) + " mm"
    got = results("--amplitudes", text, "--k", f"{k}N/m", "--m", f"{m}kg")
    exact = results("--c", str(c), "--k", str(k), "--m", str(m))
    assert got["delta"] == pytest.approx(exact["delta"], rel=1e-8)
    assert got["zeta"] == pytest.approx(exact["zeta"], rel=1e-8)
    assert got["c"] == pytest.approx(c, rel=1e-8)
    assert got["T_d"] == pytest.approx(exact["T_d"], rel=1e-8)
    assert got["residual"] < 1e-8
    for method in ("log-linear", "nonlinear"):
        data = run_json("--amplitudes", text, "--method", method)
        assert data["method"] == method
        assert data["results"]["delta"]["value"] == pytest.approx(exact["delta"], rel=1e-8)
        assert data["warnings"] == []


# --- the fit on synthetic decays --------------------------------------------------------------

def noisy_decay(delta, n, sigma, seed):
    """Peaks exp(-delta i) with multiplicative (log-normal) noise of sigma, seeded."""
    rng = np.random.default_rng(seed)
    return 5.0 * np.exp(-delta * np.arange(n)) * np.exp(rng.normal(0.0, sigma, n))


def slope_se(n, sigma):
    """Standard error of a least-squares slope: sigma / sqrt(sum (i - mean i)^2)."""
    return sigma / math.sqrt(n * (n * n - 1) / 12)


@pytest.mark.parametrize("delta, n, sigma", [(0.2, 12, 0.02), (0.05, 30, 0.01),
                                             (1.5, 6, 0.03), (0.01, 40, 0.002)])
def test_fit_recovers_the_decrement_from_noisy_peaks(delta, n, sigma):
    # Tolerance: with log-normal noise sigma the log-linear slope is unbiased with standard
    # error sigma/sqrt(Sxx); 4 standard errors leave a 6e-5 chance per case (fixed seeds).
    se = slope_se(n, sigma)
    for seed in range(5):
        peaks = noisy_decay(delta, n, sigma, seed)
        fit = fit_decrement(peaks)
        assert abs(fit.delta - delta) < 4 * se
        assert fit.delta_se == pytest.approx(se, rel=0.8)   # an estimate from n - 2 dof
        assert not fit.systematic


@pytest.mark.parametrize("delta, n, noise", [(0.2, 12, 0.02), (1.5, 6, 0.01),
                                             (0.05, 30, 0.05)])
def test_nonlinear_fit_recovers_the_decrement_under_instrument_noise(delta, n, noise):
    # The nonlinear fit weights absolute errors: its model is a fixed instrument noise added to
    # the peaks. Under that noise its own standard error (from the Jacobian) is right, and the
    # estimate is within 4 of them (fixed seeds).
    for seed in range(5):
        rng = np.random.default_rng(seed)
        peaks = 5.0 * np.exp(-delta * np.arange(n)) + rng.normal(0.0, noise, n)
        peaks = np.abs(peaks) + 1e-3 * (peaks == 0)
        fit = fit_decrement(peaks, method="nonlinear")
        assert fit.converged
        assert abs(fit.delta - delta) < 4 * fit.delta_se


def test_fit_statistics_over_many_seeds():
    # Over 400 seeded decays the estimates scatter as least squares says they should, the
    # reported standard error matches that scatter, and the shape test rarely cries wolf.
    delta, n, sigma = 0.15, 15, 0.02
    se = slope_se(n, sigma)
    fits = [fit_decrement(noisy_decay(delta, n, sigma, seed)) for seed in range(400)]
    estimates = np.array([f.delta for f in fits])
    assert abs(estimates.mean() - delta) < 4 * se / math.sqrt(400)
    assert estimates.std(ddof=1) == pytest.approx(se, rel=0.1)
    assert np.median([f.delta_se for f in fits]) == pytest.approx(se, rel=0.1)
    false_alarms = sum(bool(f.warnings) for f in fits)
    assert false_alarms <= 4  # the curvature test alone is set at 0.1 %


def test_coulomb_friction_peaks_are_not_exponential():
    # Dry friction F on a spring k: every cycle the peak drops by the same 4 F / k.
    rng = np.random.default_rng(7)
    peaks = 10.0 - 0.9 * np.arange(10)
    peaks = peaks * (1 + rng.normal(0, 0.002, peaks.size))
    text = ",".join(f"{p:.6g}" for p in peaks) + " mm"
    data = run_json("--amplitudes", text)
    systematic = [w for w in data["warnings"] if "bends systematically" in w]
    assert len(systematic) == 1 and "Coulomb" in systematic[0]
    assert data["extra"]["fit"]["systematic"] is True
    assert data["extra"]["fit"]["delta_end"] > 3 * data["extra"]["fit"]["delta_start"]
    assert abs(data["extra"]["fit"]["curvature_t"]) > t_critical(10 - 3)


def test_amplitude_dependent_damping_bends_the_other_way():
    # Quadratic (velocity-squared) damping: the decrement is proportional to the amplitude,
    # delta_i = b x_i, so the peaks follow x_(i+1) = x_i exp(-b x_i).
    peaks = [10.0]
    for _ in range(11):
        peaks.append(peaks[-1] * math.exp(-0.05 * peaks[-1]))
    fit = fit_decrement(peaks)
    assert fit.systematic and fit.delta_end < fit.delta_start
    assert "amplitude-dependent" in fit.warnings[0]


def test_large_scatter_is_reported():
    # 5 % noise on a decay of 0.01 per cycle: the noise swamps the decay.
    peaks = noisy_decay(0.01, 10, 0.05, seed=3)
    fit = fit_decrement(peaks)
    assert fit.scattered and fit.r_squared < 0.99
    assert any("scatter" in w and "+/-" in w for w in fit.warnings)


def test_exact_exponentials_fit_without_warnings():
    for delta in (1e-12, 0.3, 5.0):
        peaks = 3.0 * np.exp(-delta * np.arange(10))
        fit = fit_decrement(peaks)
        assert fit.delta == pytest.approx(delta, rel=1e-4 if delta < 1e-6 else 1e-14)
        assert fit.warnings == [] and not fit.systematic and not fit.scattered
    fit = fit_decrement([8.0, 4.0])
    assert fit.delta == math.log(2) and fit.delta_se is None and fit.residual == 0.0


def test_constant_peaks_are_undamped():
    got = results("--amplitudes", "2.5, 2.5, 2.5, 2.5")
    assert got["delta"] == 0.0 and got["zeta"] == 0.0 and got["regime"] == "undamped"
    assert "Q" not in got


def test_peaks_that_do_not_decay_measurably_are_taken_as_undamped():
    data = run_json("--amplitudes", "1.00, 1.01, 0.99, 1.00, 1.01")
    assert data["results"]["delta"]["value"] == 0.0
    assert data["results"]["regime"]["value"] == "undamped"
    assert any("not distinguishable from zero" in w for w in data["warnings"])


def test_t_critical_matches_scipy():
    from scipy.stats import t

    for dof in (1, 2, 5, 12, 30, 31, 45, 100, 1000):
        assert t_critical(dof) == pytest.approx(t.ppf(0.9995, dof), rel=2e-4)


# --- regimes and their boundary ---------------------------------------------------------------

def regime(*args):
    return results(*args)["regime"]


def test_regime_boundaries_from_coefficients():
    k, m = "100 N/m", "1 kg"   # c_c = 20 N s/m exactly
    assert regime("--c", "0", "--k", k, "--m", m) == "undamped"
    assert regime("--c", "19.9", "--k", k, "--m", m) == "underdamped"
    assert regime("--c", repr(20 * (1 - 1e-12)), "--k", k, "--m", m) == "underdamped"
    got = results("--c", "20", "--k", k, "--m", m)
    assert got["regime"] == "critically damped" and got["zeta"] == 1.0 and got["Q"] == 0.5
    assert "omega_d" not in got and "delta" not in got
    assert regime("--c", repr(20 * (1 + 1e-12)), "--k", k, "--m", m) == "overdamped"
    assert regime("--c", "20.1", "--k", k, "--m", m) == "overdamped"


def test_c_typed_as_the_printed_c_c_is_critical():
    # c_c = 2 sqrt(6) is irrational: the c the user copies from the output is 1e-16 away
    c_c = results("--c", "1", "--k", "2", "--m", "3")["c_c"]
    data = run_json("--c", repr(c_c), "--k", "2", "--m", "3")
    assert data["results"]["regime"]["value"] == "critically damped"
    assert data["results"]["zeta"]["value"] == 1.0
    assert any("less than the rounding of the inputs" in w for w in data["warnings"])
    # one step further than the band either way is decided by the sign of 4 k m - c^2
    for factor, word in ((1 - 4e-15, "underdamped"), (1 + 4e-15, "overdamped")):
        assert regime("--c", repr(c_c * factor), "--k", "2", "--m", "3") == word


def test_regime_from_zeta_at_the_band():
    assert damping_from_zeta(1.0).values["regime"] == "critically damped"
    for z in (1 - 2 ** -53, 1 - 2 ** -52, 1 - 2 ** -51, 1 + 2 ** -52):
        out = damping_from_zeta(z)
        assert out.values["regime"] == "critically damped" and out.values["zeta"] == 1.0
        assert "rounding of the inputs" in out.warnings[0]
    assert damping_from_zeta(1 - 2 ** -49).values["regime"] == "underdamped"
    assert damping_from_zeta(1 + 2 ** -51).values["regime"] == "overdamped"
    assert damping_from_zeta(0.0).values["regime"] == "undamped"
    assert abs((1 - (1 - 2 ** -52)) * (1 + (1 - 2 ** -52))) <= CRITICAL_BAND


def test_a_huge_decrement_is_still_underdamped():
    # zeta rounds to 1 from delta = 1e9, but a measured decrement means an oscillation
    data = run_json("--decrement", "1e9", "--omega", "1 rad/s")
    res = data["results"]
    assert res["regime"]["value"] == "underdamped"
    h = mpmath.sqrt(4 * mpmath.pi ** 2 + mpmath.mpf(10) ** 18)
    assert ulps(res["omega_d"]["value"], 2 * mpmath.pi / h) <= 2
    assert ulps(res["T_d"]["value"], h) <= 2


@settings(max_examples=150, deadline=None)
@given(st.floats(1e-30, 1e30), st.floats(1e-30, 1e30), st.floats(1e-30, 1e30),
       st.floats(1.0001, 10.0))
def test_zeta_is_monotone_in_c_and_the_regime_follows_it(c, k, m, factor):
    a = damping_from_coefficients(Q_(c, "N*s/m"), Q_(k, "N/m"), Q_(m, "kg")).values
    b = damping_from_coefficients(Q_(c * factor, "N*s/m"), Q_(k, "N/m"), Q_(m, "kg")).values
    assert b["zeta"] > a["zeta"] > 0
    for v in (a, b):
        z = v["zeta"]
        assert v["regime"] == ("underdamped" if z < 1 else
                               "critically damped" if z == 1 else "overdamped")
        assert ("omega_d" in v) == ("delta" in v) == (v["regime"] == "underdamped")
        assert all(math.isfinite(x.magnitude if hasattr(x, "magnitude") else x)
                   for x in v.values() if not isinstance(x, str))


# --- unit invariance --------------------------------------------------------------------------

LBF_S_PER_IN = 4.4482216152605 / 0.0254
LBF_PER_IN = 4.4482216152605 / 0.0254
LB = 0.45359237


def test_coefficients_in_other_units():
    si = run_json("--c", "3 N*s/m", "--k", "400 N/m", "--m", "2 kg")["results"]
    us = run_json("--c", f"{3 / LBF_S_PER_IN!r} lbf*s/in", "--k", f"{400 / LBF_PER_IN!r} lbf/in",
                  "--m", f"{2 / LB!r} lb")["results"]
    # JSON gives c and c_c in the canonical N*s/m, whatever unit c was typed in
    assert us["c"]["unit"] == "N*s/m" and us["c_c"]["unit"] == "N*s/m"
    assert us["c"]["value"] == pytest.approx(3.0, rel=1e-14)
    for name in ("zeta", "delta", "Q", "omega", "omega_d", "T_d", "xi"):
        assert us[name]["value"] == pytest.approx(si[name]["value"], rel=1e-14)
    assert us["c_c"]["value"] == pytest.approx(si["c_c"]["value"], rel=1e-14)
    # --unit converts either way
    again = run_json("--c", "3 N*s/m", "--k", "400 N/m", "--m", "2 kg",
                     "--unit", "c_c=lbf*s/in")["results"]["c_c"]
    assert again["unit"] == "lbf*s/in"
    assert again["value"] * LBF_S_PER_IN == pytest.approx(us["c_c"]["value"], rel=1e-14)


def test_omega_in_other_units_and_amplitudes_in_any_unit():
    a = results("--decrement", "0.4", "--omega", "60 rpm")
    b = results("--decrement", "0.4", "--omega", f"{TWO_PI!r} rad/s")
    c = results("--decrement", "0.4", "--omega", "360 deg/s")
    assert a["regime"] == b["regime"] == c["regime"] == "underdamped"
    for name in set(a) - {"regime"}:
        assert a[name] == pytest.approx(b[name], rel=1e-14)
        assert c[name] == pytest.approx(b[name], rel=1e-14)
    mm = results("--amplitudes", "25.4, 20.32, 17.78, 12.7 mm")
    inch = results("--amplitudes", "1.0, 0.8, 0.7, 0.5 in")
    bare = results("--amplitudes", "[1.0, 0.8, 0.7, 0.5]")
    for name in ("zeta", "delta", "residual"):
        assert mm[name] == pytest.approx(inch[name], rel=1e-12, abs=1e-15)
        assert bare[name] == inch[name]


# --- accuracy at the extremes (mpmath from the float inputs, in ulps) -----------------------

def test_decrement_extremes_against_mpmath():
    worst = 0.0
    for delta in (1e-12, 40.0, 1e-300, 1e300):
        got = damping_from_decrement(delta, omega=Q_(3.0, "rad/s")).values
        d = mpmath.mpf(delta)
        h = mpmath.sqrt(4 * mpmath.pi ** 2 + d * d)
        refs = {"zeta": d / h, "Q": h / (2 * d), "omega_d": 3 * 2 * mpmath.pi / h,
                "T_d": h / 3, "xi": 3 * d / h}
        for name, ref in refs.items():
            if not 1e-300 < abs(ref) < 1e300:
                continue
            value = got[name].magnitude if hasattr(got[name], "magnitude") else got[name]
            worst = max(worst, ulps(value, ref))
    assert worst <= 3


def test_zeta_a_hair_below_one_against_mpmath():
    # from the coefficients: 4 k m - c^2 is formed exactly, so omega_d and delta keep their
    # digits where the naive omega sqrt(1 - zeta^2) keeps only about four
    k, m = 3.7, 0.9
    c = (1 - 1e-12) * 2 * math.sqrt(k * m)
    got = damping_from_coefficients(Q_(c, "N*s/m"), Q_(k, "N/m"), Q_(m, "kg")).values
    C, K, M = mpmath.mpf(c), mpmath.mpf(k), mpmath.mpf(m)
    excess = 4 * K * M - C * C
    refs = {"zeta": C / (2 * mpmath.sqrt(K * M)), "omega_d": mpmath.sqrt(excess) / (2 * M),
            "delta": 2 * mpmath.pi * C / mpmath.sqrt(excess),
            "T_d": 4 * mpmath.pi * M / mpmath.sqrt(excess)}
    for name, ref in refs.items():
        value = got[name].magnitude if hasattr(got[name], "magnitude") else got[name]
        assert ulps(value, ref) <= 3, name
    naive = math.sqrt(k / m) * math.sqrt(1 - got["zeta"] ** 2)
    assert ulps(naive, refs["omega_d"]) > 1e3  # what the care buys
    # from a damping ratio (a scene): (1 - zeta)(1 + zeta), not 1 - zeta^2
    z = 1 - 1e-12
    Z = mpmath.mpf(z)
    assert ulps(decrement_from_zeta(z), 2 * mpmath.pi * Z / mpmath.sqrt(1 - Z * Z)) <= 3


EXTREMES = [1e-100, 1e200]


@pytest.mark.parametrize("c", EXTREMES)
@pytest.mark.parametrize("k", EXTREMES)
@pytest.mark.parametrize("m", EXTREMES)
def test_coefficient_extremes_against_mpmath(c, k, m):
    got = damping_from_coefficients(Q_(c, "N*s/m"), Q_(k, "N/m"), Q_(m, "kg")).values
    C, K, M = mpmath.mpf(c), mpmath.mpf(k), mpmath.mpf(m)
    cc = 2 * mpmath.sqrt(K * M)
    refs = {"c_c": cc, "zeta": C / cc, "omega": mpmath.sqrt(K / M), "Q": cc / (2 * C),
            "xi": C / (2 * M)}
    excess = 4 * K * M - C * C
    if excess > 0:
        refs.update(omega_d=mpmath.sqrt(excess) / (2 * M),
                    delta=2 * mpmath.pi * C / mpmath.sqrt(excess),
                    T_d=4 * mpmath.pi * M / mpmath.sqrt(excess))
        assert got["regime"] == "underdamped"
    else:
        assert got["regime"] == "overdamped" and "omega_d" not in got
    for name, ref in refs.items():
        value = got[name].magnitude if hasattr(got[name], "magnitude") else got[name]
        assert math.isfinite(value) and ulps(value, ref) <= 3, (name, value, ref)


def test_an_overflowing_c_c_is_left_out_with_a_warning():
    data = run_json("--c", "1e300", "--k", "1e308", "--m", "1e308")
    assert data["results"]["c_c"]["value"] is None
    assert any("c_c overflows float64" in w for w in data["warnings"])
    assert data["results"]["zeta"]["value"] == pytest.approx(5e-9, rel=1e-15)


def test_a_decrement_that_underflows_zeta_is_reported():
    data = run_json("--decrement", "5e-324")
    assert data["results"]["zeta"]["value"] == 0.0
    assert any("zeta underflows" in w for w in data["warnings"])
    assert any("Q overflows" in w for w in data["warnings"])


# --- output ------------------------------------------------------------------------------------

def test_json_shape_regime_and_method():
    data = run_json("--amplitudes", "12.1, 9.0, 6.8, 5.1, 3.8 mV", "--omega", "25 rad/s")
    assert data["command"] == "damping-ratio" and data["scene"] is None
    assert data["model"] == "linear" and data["method"] == "log-linear"
    assert data["results"]["regime"] == {"value": "underdamped", "unit": ""}
    assert data["inputs"]["amplitudes"] == {"value": [12.1, 9.0, 6.8, 5.1, 3.8], "unit": "mV",
                                            "text": "12.1, 9.0, 6.8, 5.1, 3.8 mV"}
    assert set(data["extra"]["fit"]) >= {"peaks", "residual", "delta_se", "r_squared", "x0"}
    assert data["results"]["residual"]["value"] == data["extra"]["fit"]["residual"]
    for key in ("zeta", "delta", "Q", "omega_d", "T_d", "f_d", "xi", "residual", "delta_se"):
        assert isinstance(data["results"][key]["value"], float)
    assert run_json("--amplitudes", "3,2,1.4", "--method", "nonlinear")["method"] == "nonlinear"
    assert run_json("--decrement", "0.1")["method"] == "closed-form"


def test_value_check_and_rtol():
    result = run("--ratio", "10", "--cycles", "10", "--value", "regime")
    assert result.exit_code == 0 and result.stdout == "underdamped\n"
    result = run("--ratio", "10", "--cycles", "10", "--value", "zeta")
    assert float(result.stdout) == zeta_exact(math.log(10) / 10)
    assert run("--ratio", "10", "--cycles", "10", "--check", "zeta=0.0366").exit_code == 0
    failed = run("--ratio", "10", "--cycles", "10", "--check", "zeta=0.0366", "--rtol", "1e-4")
    assert failed.exit_code == 1 and "FAIL" in failed.stdout


def test_overdamped_has_no_damped_frequency_and_no_nan():
    result = run("--c", "30", "--k", "100", "--m", "1", "--json")
    assert "NaN" not in result.stdout and "Infinity" not in result.stdout
    data = json.loads(result.stdout)
    assert data["results"]["regime"]["value"] == "overdamped"
    assert not {"omega_d", "f_d", "T_d", "delta"} & set(data["results"])
    assert data["warnings"] == ["zeta = 1.5: the system is overdamped; it does not oscillate, "
                                "so there is no damped frequency, period or logarithmic "
                                "decrement"]


def test_human_output_and_help():
    result = run("--ratio", "10", "--cycles", "10")
    assert result.exit_code == 0
    assert result.stdout.splitlines()[0] == "damping-ratio   model: linear   method: closed-form"
    assert "regime  regime  underdamped" in result.stdout
    help_text = run("--help").stdout
    assert "Examples:" in help_text and "dyncalc damping-ratio --ratio 10 --cycles 10" in help_text


def test_library_call():
    r = damping_ratio(c="4 N*s/m", k="100 N/m", m="1 kg")
    assert r.results["zeta"].si == 0.2 and r.results["c_c"].si == 20.0


# --- refusals: exact message, exit 2 ----------------------------------------------------------

USAGE = ('--c C --k K --m M, --decrement DELTA, --ratio R --cycles N, --amplitudes "x0,x1,...", '
         'or --scene NAME NAME=QUANTITY ...')
DAMPED = "pendulum-spring-dashpot, rod-in-fluid, frame-brace-damper"


@pytest.mark.parametrize("args, message", [
    (["--c", "-1 N*s/m", "--k", "100", "--m", "1"],
     "--c must not be negative; got -1 newton * second / meter"),
    (["--ratio", "0.5", "--cycles", "2"],
     "--ratio must be at least 1: it is x_i / x_(i+N), the earlier peak over the later one; "
     "got 0.5 (for decaying peaks, did you mean 2?)"),
    (["--ratio", "-2"],
     "--ratio must be at least 1: it is x_i / x_(i+N), the earlier peak over the later one; "
     "got -2"),
    (["--ratio", "10", "--cycles", "0"],
     "--cycles must be at least 1 (a whole number of cycles); got 0"),
    (["--ratio", "10", "--cycles", "2.5"],
     "--cycles must be a whole number of cycles (1, 2, 3, ...); got 2.5"),
    (["--ratio", "10", "--cycles", "-3"],
     "--cycles must be at least 1 (a whole number of cycles); got -3"),
    (["--amplitudes", "5 mm"],
     "--amplitudes needs at least 2 peaks (one per cycle) to measure a decrement; got 1"),
    (["--amplitudes", "5, 0, 3"],
     "--amplitudes: every peak must be positive (give the peak magnitudes |x|); x1 is 0"),
    (["--amplitudes", "5, 4, -1 mm"],
     "--amplitudes: every peak must be positive (give the peak magnitudes |x|); x2 is -1"),
    (["--amplitudes", "5,,3"], "--amplitudes: x1 is empty; separate the peaks by single commas"),
    (["--amplitudes", "5, 4 m, 3 m"],
     "--amplitudes: x1 ('4 m') is not a plain number; give the peaks as numbers with one unit "
     'at the end, e.g. "12.1, 8.3, 5.9 mm"'),
    (["--amplitudes", "1, 2"],
     "--amplitudes: the peaks grow (fitted delta = -0.6931 per cycle): that is not a free "
     "decay; list the peaks in time order, the first peak first"),
    (["--c", "5 kg", "--k", "100", "--m", "1"],
     "--c must be a damping coefficient [force]*[time]/[length]; got 5 kilogram ([mass])"),
    (["--c", "1", "--k", "5 kg", "--m", "1"],
     "--k must be a stiffness [force]/[length]; got 5 kilogram ([mass])"),
    (["--decrement", "2 m"], "--decrement must be a pure number; got 2 meter ([length])"),
    (["--decrement", "-0.1"], "--decrement must not be negative; got -0.1"),
    (["--decrement", "0.1", "--omega", "3 Hz"],
     "--omega is an angular rate; give it in rad/s, deg/s, rpm or rev/s, not Hz (a frequency "
     "in cycles)"),
    ([], f"damping-ratio needs one measurement of the damping: {USAGE}"),
    (["--k", "100", "--m", "1"], f"damping-ratio needs one measurement of the damping: {USAGE}"),
    (["--decrement", "0.1", "--ratio", "3"],
     "damping-ratio takes one measurement of the damping, not 2: got --decrement and --ratio; "
     f"give one of {USAGE}"),
    (["--c", "1", "--k", "1", "--m", "1", "--amplitudes", "3,2"],
     "damping-ratio takes one measurement of the damping, not 2: got --c and --amplitudes; "
     f"give one of {USAGE}"),
    (["--c", "1", "--k", "1"], "--c needs --m too: zeta = c / (2 sqrt(k m))"),
    (["--c", "1"], "--c needs --k and --m too: zeta = c / (2 sqrt(k m))"),
    (["--cycles", "3"],
     "--cycles goes with --ratio R (the ratio x_i / x_(i+N) of two peaks N cycles apart)"),
    (["--decrement", "0.1", "--k", "1"],
     "--k needs --m: together they give the natural frequency sqrt(k/m) and c_c = 2 sqrt(k m)"),
    (["--decrement", "0.1", "--omega", "3", "--k", "1", "--m", "1"],
     "give the natural frequency as --omega or as --k and --m, not both"),
    # issue 15: no --k was given, yet the message said "not both"
    (["--c", "1", "--omega", "3", "--m", "1"],
     "--c goes with --k and --m (zeta = c / (2 sqrt(k m))), not with --omega: give --k "
     "instead of --omega"),
    (["--c", "1", "--omega", "3"],
     "--c goes with --k and --m (zeta = c / (2 sqrt(k m))), not with --omega: give --k and "
     "--m instead of --omega"),
    (["--decrement", "0.1", "--omega", "3", "--m", "1"],
     "--m does not go with --omega: give the natural frequency as --omega, or as --k and --m"),
    (["--scene", "mass-spring", "k=1", "m=1"],
     f"damping-ratio --scene takes a scene with a damper: {DAMPED}; mass-spring has none "
     "(natural-frequency computes it)"),
    (["m=1"], f"NAME=QUANTITY parameters need --scene NAME (a scene with a damper: {DAMPED})"),
    (["--scene", "rod-in-fluid", "m=1", "l=1", "beta=1", "--omega", "3"],
     "--omega is not used with --scene: the scene gives its own natural frequency"),
    (["--scene", "rod-in-fluid", "m=1", "l=1", "beta=-1"],
     "beta must not be negative; got -1 newton * second / meter ** 2"),
    (["--amplitudes", "5,4", "--method", "foo"],
     "--method foo is not offered for --amplitudes; it offers log-linear (the default) and "
     "nonlinear"),
    (["--decrement", "1", "--method", "nonlinear"],
     "--method nonlinear does not apply to --decrement, which has a closed form; --method "
     "log-linear or nonlinear chooses the fit of --amplitudes"),
    (["--g", "3", "--decrement", "1"], "--g is a scene parameter: use it with --scene"),
    (["--decrement", "0.1", "--plot", "decay.gif"],
     "--plot: 'decay.gif' must end in .png, .svg or .pdf"),
    (["--decrement", "0.1", "--strict-units", "--omega", "3"],
     "--omega: '3' has no unit and --strict-units is on; write it with a unit, e.g. 3 rad/s"),
])
def test_refusals(args, message):
    assert error_line(run(*args)) == f"Error: {message}"


def test_a_zero_ratio_and_equal_peaks():
    # R = 1 (no decay over N cycles) is the undamped limit, like --decrement 0 and --c 0
    got = results("--ratio", "1", "--cycles", "3")
    assert got["zeta"] == 0.0 and got["regime"] == "undamped"
    assert error_line(run("--ratio", "0")).startswith("Error: --ratio must be at least 1")


# --- the picture ------------------------------------------------------------------------------

def png_size(path):
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert data[12:16] == b"IHDR"
    return len(data), int.from_bytes(data[16:20], "big"), int.from_bytes(data[20:24], "big")


@pytest.mark.parametrize("args", [
    ["--amplitudes", "12.1, 9.0, 6.8, 5.1, 3.8 mV", "--omega", "25 rad/s"],
    ["--amplitudes", "10,9,8,7,6,5,4,3"],
    ["--decrement", "0.3"],
    ["--c", "4", "--k", "100", "--m", "1"],
    ["--c", "30", "--k", "100", "--m", "1"],
    ["--c", "20", "--k", "100", "--m", "1"],
    ["--scene", "rod-in-fluid", "m=1.5kg", "l=0.8m", "beta=2 N*s/m^2"],
], ids=["peaks", "coulomb", "decrement", "underdamped", "overdamped", "critical", "scene"])
def test_plot_is_a_real_png(tmp_path, args):
    target = tmp_path / "decay.png"
    result = run(*args, "--plot", str(target), "--json")
    assert result.exit_code == 0, result.stderr
    size, width, height = png_size(target)
    assert size > 5000
    assert (width, height) == (900, 480)
    assert json.loads(result.stdout)["extra"]["plot"] == str(target)


def test_plot_without_a_natural_frequency_says_so(tmp_path):
    data = run_json("--ratio", "3", "--plot", str(tmp_path / "x.png"))
    assert any("time axis is dimensionless" in w for w in data["warnings"])
    assert not any("dimensionless" in w for w in
                   run_json("--ratio", "3", "--omega", "2 rad/s", "--plot",
                            str(tmp_path / "y.png"))["warnings"])


def test_plot_to_a_missing_folder_is_refused(tmp_path):
    line = error_line(run("--decrement", "0.1", "--plot", str(tmp_path / "no" / "x.png")))
    assert line.startswith("Error: --plot: cannot write")


def test_free_response_solves_the_equation_of_motion():
    for zeta in (0.0, 0.1, 1.0, 2.5):
        sol = solve_ivp(lambda t, y: [y[1], -2 * zeta * y[1] - y[0]], (0, 12), [1.0, 0.0],
                        rtol=1e-11, atol=1e-13, dense_output=True)
        tau = np.linspace(0, 12, 50)
        assert np.allclose(free_response(zeta, tau), sol.sol(tau)[0], atol=1e-8)


def test_matplotlib_and_scipy_optimize_load_only_when_needed():
    code = ("import sys\nfrom dyncalc.cli import main\n"
            "try:\n    main(['damping-ratio', '--amplitudes', '3,2,1.4', '--json'])\n"
            "except SystemExit:\n    pass\n"
            "print(sorted(m for m in ('matplotlib', 'scipy.optimize') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip().splitlines()[-1] == "[]"


def test_plot_path_with_a_nul_is_refused_in_one_line(tmp_path):
    """matplotlib raises ValueError ("embedded null byte") for such a path: an Error: line,
    not an internal error (found by the long fuzz run)."""
    from click.testing import CliRunner

    from dyncalc.cli import cli

    path = str(tmp_path / "a\x00.png")
    result = CliRunner().invoke(cli, ["damping-ratio", "--decrement", "0.5", "--plot", path])
    assert result.exit_code == 2
    assert result.output == (f"Error: --plot: cannot write {path[:80]!r}: embedded null "
                             "byte\n")


def test_peak_plot_with_a_period_near_float_max_draws_against_cycles(tmp_path):
    """--omega 1e-306 rad/s: T_d = 6.3e306 s and 9 T_d overflows; the axis falls back to the
    cycle count, with no numpy overflow warning (found by the long fuzz run)."""
    import warnings

    from click.testing import CliRunner

    from dyncalc.cli import cli

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = CliRunner().invoke(cli, ["damping-ratio", "--amplitudes", "1,0.8,0.64,0.5",
                                          "--omega", "1e-306 rad/s", "--plot",
                                          str(tmp_path / "p.png")])
    assert result.exit_code == 0, result.output
    assert (tmp_path / "p.png").stat().st_size > 0
