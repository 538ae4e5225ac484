"""rolling-onset reads, then computes: the propagation of uncertainties works on the parsed
inputs (``result.sensitivity``), exact derivatives of the closed form, central differences on
the parsed values for ``--method ode`` and where the closed form has a kink (``s0 = 0``).

References: the hand derivatives of the solid sphere (``t = 2 v0/(7 mu g)``,
``x = 12 v0^2/(49 mu g)``, ``v = 5 v0/7``), and ``mpmath.diff`` at 30 digits of the closed
form written out independently below (``closed_form``), with spin and on a slope.
"""
import math

import mpmath
import pytest

from dyncalc.commands import rolling_onset as rolling_module
from dyncalc.commands.rolling_onset import TIMING_RUNS, compute, read, rolling_onset_result
from dyncalc.physics import rolling as rolling_physics
from dyncalc.result.propagate import RELATIVE_STEP, propagate
from helpers import count_readings, json_of

G0 = 9.80665
INPUTS = ("v0", "mu", "kappa", "radius", "omega0", "g", "incline")


@pytest.fixture(autouse=True)
def mp_precision():
    """30 digits for the mpmath references, restored afterwards."""
    with mpmath.workdps(30):
        yield


def closed_form(values: dict, sigma: int) -> dict:
    """The closed form in mpmath (SI, incline in radians), the slip's sign held at
    ``sigma``: t = kappa |s0| / (g (mu (1 + kappa) cos + sigma kappa sin)),
    v = v0 - g (sin + sigma mu cos) t, x = (v0 + v) t / 2, omega = v / r,
    path = (v0^2 + v^2) / (2 |a|), mu_min = kappa |tan| / (1 + kappa)."""
    v0, mu, kappa, r, w, g, beta = (values[n] for n in INPUTS)
    s0 = v0 - r * w
    sin, cos = mpmath.sin(beta), mpmath.cos(beta)
    t = kappa * abs(s0) / (g * (mu * (1 + kappa) * cos + sigma * kappa * sin))
    a = g * (sin + sigma * mu * cos)
    v = v0 - a * t
    return {"t_roll": t, "x_roll": (v0 + v) * t / 2, "v_roll": v, "omega_roll": v / r,
            "path_roll": (v0 ** 2 + v ** 2) / (2 * abs(a)),
            "mu_min": kappa * abs(mpmath.tan(beta)) / (1 + kappa)}


def mp_slopes(result, sigma: int) -> dict:
    """d result / d input by mpmath.diff of :func:`closed_form` at the parsed SI values."""
    at = {n: mpmath.mpf(result.inputs[n].si) for n in INPUTS}
    slopes = {}
    for name in result.results:
        row = {}
        for n in INPUTS:
            def one(x, n=n, name=name):
                return closed_form({**at, n: x}, sigma)[name]
            row[n] = mpmath.diff(one, at[n])
        slopes[name] = row
    return slopes


def sensitivity_rows(result) -> dict:
    """The result's own derivatives, by result name and input name."""
    sens = result.sensitivity()
    return {name: {sens.inputs[i].name: slope for i, slope in row.items()}
            for name, row in sens.slopes.items()}


def test_sphere_derivatives_are_exact_to_1e_13():
    """Solid sphere, v0 = 5 ± 0.1 m/s, mu = 0.3 ± 0.01: dt/dv0 = 2/(7 mu g) = t/v0,
    dt/dmu = -t/mu, dx/dv0 = 24 v0/(49 mu g) = 2 x/v0, dx/dmu = -x/mu, dv/dv0 = 5/7,
    dv/dmu = 0. Met to 1e-13 relative, which central differences with h = 1e-6 |x| cannot:
    their truncation error is ~(h/mu)^2 = 1e-12 for the 1/mu dependence (checked below) and
    their rounding error ~eps/h = 2e-10."""
    texts = {"v0": "5+/-0.1 m/s", "mu": "0.3+/-0.01"}
    data = json_of("rolling-onset", "--v0", texts["v0"], "--mu", texts["mu"], "--explain")
    results, variance = data["results"], data["extra"]["explanation"]["variance"]
    t = 2 * 5 / (7 * 0.3 * G0)
    x = 12 * 25 / (49 * 0.3 * G0)
    u = {"t_roll": t * math.hypot(0.1 / 5, 0.01 / 0.3),
         "x_roll": x * math.hypot(2 * 0.1 / 5, 0.01 / 0.3),
         "v_roll": 5 / 7 * 0.1}
    for name, expected in u.items():
        assert results[name]["uncertainty"] == pytest.approx(expected, rel=1e-13, abs=0), name
    t_terms = ((0.1 / 5) ** 2, (0.01 / 0.3) ** 2)
    assert variance["t_roll"]["mu"] == pytest.approx(t_terms[1] / sum(t_terms), rel=1e-13,
                                                            abs=0)
    assert variance["v_roll"] == {"v0": 1.0, "mu": 0.0}

    rows = sensitivity_rows(rolling_onset_result(texts))
    hand = {"t_roll": {"v0": 2 / (7 * 0.3 * G0), "mu": -t / 0.3},
            "x_roll": {"v0": 24 * 5 / (49 * 0.3 * G0), "mu": -x / 0.3},
            "v_roll": {"v0": 5 / 7, "mu": 0.0}}
    for name, row in hand.items():
        for n, slope in row.items():
            assert rows[name][n] == pytest.approx(slope, rel=1e-13, abs=0.0), (name, n)
    # the central difference misses 1e-13: dt/dmu of t ~ 1/mu is off by ~(h/mu)^2
    h = RELATIVE_STEP * 0.3
    central = (rolling_physics.onset_closed_form(5.0, 0.3 + h, 0.4, G0).t
               - rolling_physics.onset_closed_form(5.0, 0.3 - h, 0.4, G0).t) / (2 * h)
    assert abs(central / (-t / 0.3) - 1) > 1e-13


@pytest.mark.parametrize("texts, sigma", [
    # backspin that brings it back, uphill: all seven inputs uncertain, path_roll and mu_min
    ({"v0": "3+/-0.1 m/s", "mu": "0.25+/-0.01", "kappa": "0.4+/-0.02",
      "radius": "0.1+/-0.001 m", "omega0": "-200+/-3 rad/s", "g": "9.8+/-0.02",
      "incline": "10+/-0.5 deg"}, 1),
    # topspin faster than the centre (the slip is backward, sigma = -1), downhill
    ({"v0": "2+/-0.05 m/s", "mu": "0.2+/-0.01", "kappa": "0.5+/-0.01",
      "radius": "28.5+/-0.1 mm", "omega0": "90+/-5 rad/s", "g": "9.81+/-0.01",
      "incline": "-7+/-0.2 deg"}, -1),
    # topspin far beyond rolling (r omega0 = 1e5 v0): omega_roll's terms in r nearly cancel
    ({"v0": "0.01+/-0.001 m/s", "mu": "0.3+/-0.01", "kappa": "0.4+/-0.01",
      "radius": "0.1+/-0.001 m", "omega0": "1e5+/-1e3 rad/s", "g": "9.81+/-0.01",
      "incline": "5+/-0.5 deg"}, -1),
    # forward spin below rolling, a bare angle in radians, on level-ish ground
    ({"v0": "4+/-0.1 m/s", "mu": "0.3+/-0.01", "kappa": "0.6667+/-0.001",
      "radius": "0.11+/-0.001 m", "omega0": "12+/-1 rad/s", "g": "9.80665+/-0.001",
      "incline": "0.05+/-0.01"}, 1),
])
def test_spin_and_slope_derivatives_against_mpmath(texts, sigma):
    """Every result against every input, the command's derivatives against mpmath.diff of the
    closed form at 30 digits (its own derivation, above), each to 1e-13 relative (those that
    are zero, zero to within mpmath's own noise); and the propagated uncertainty and the
    variance shares from them."""
    result = rolling_onset_result(texts)
    assert result.warnings == []
    assert set(result.results) >= {"t_roll", "x_roll", "v_roll", "omega_roll", "mu_min"}
    assert ("path_roll" in result.results) == (texts["omega0"].startswith("-"))
    rows = sensitivity_rows(result)
    reference = mp_slopes(result, sigma)
    sigmas = {n: result.inputs[n].uncertainty for n in INPUTS}
    for name, row in reference.items():
        scale = max(abs(float(row[n])) * sigmas[n] for n in INPUTS)
        for n in INPUTS:
            noise = 1e-25 * scale / sigmas[n]  # mpmath.diff's error at 30 digits
            assert rows[name][n] == pytest.approx(float(row[n]), rel=1e-13, abs=noise), (name, n)

    propagated = propagate(lambda: rolling_onset_result(texts))
    for name, row in reference.items():
        terms = {n: (row[n] * sigmas[n]) ** 2 for n in INPUTS}
        total = mpmath.fsum(terms.values())
        assert propagated.results[name].uncertainty == pytest.approx(
            float(mpmath.sqrt(total)), rel=1e-13, abs=0), name
        shares = propagated.explanation.variance[name]
        assert set(shares) == set(INPUTS)
        for n in INPUTS:
            share = float(terms[n] / total)
            share = share if share > 1e-12 else 0.0  # propagate gives a share below 1e-12 as 0
            assert shares[n] == pytest.approx(share, rel=1e-12, abs=1e-15), (name, n)


def test_the_text_is_read_once_per_input(monkeypatch):
    """Propagation parses nothing again: one parse_quantity per quantity typed (and one for
    the default --g), with one uncertain input or seven, with the closed form or the ODE."""
    calls = count_readings(monkeypatch, rolling_module)
    seven = {"v0": "3+/-0.1 m/s", "mu": "0.25+/-0.01", "kappa": "0.4+/-0.02",
             "radius": "0.1+/-0.001 m", "omega0": "-200+/-3 rad/s", "g": "9.8+/-0.02",
             "incline": "10+/-0.5 deg"}
    cases = [({"v0": "5+/-0.1 m/s", "mu": "0.3"}, None, 3),
             (seven, None, 7), (seven, "ode", 7),
             ({"v0": "5+/-0.1 m/s", "mu": "0.3+/-0.01", "body": "hoop"}, "ode", 3)]
    for texts, method, readings in cases:
        calls.clear()
        result = propagate(lambda: rolling_onset_result(texts, method=method))
        assert len(calls) == readings, (texts, calls)
        assert result.results["t_roll"].uncertainty > 0
    # read() and compute() apart: the same reading, the same result
    calls.clear()
    inputs = read(seven)
    assert len(calls) == 7
    assert ({n: e.si for n, e in compute(inputs).results.items()}
            == {n: e.si for n, e in rolling_onset_result(seven).results.items()})


def test_exact_derivatives_compute_nothing_again(monkeypatch):
    """With the closed form the derivatives cost no computation: the closed-form kernel runs
    only for the run as typed (timed, the best of TIMING_RUNS), whatever the number of
    uncertain inputs."""
    calls = []
    original = rolling_physics.onset_closed_form
    monkeypatch.setattr(rolling_physics, "onset_closed_form",
                        lambda *a, **k: calls.append(1) or original(*a, **k))
    texts = {"v0": "3+/-0.1 m/s", "mu": "0.25+/-0.01", "kappa": "0.4+/-0.02",
             "radius": "0.1+/-0.001 m", "omega0": "-200+/-3 rad/s", "g": "9.8+/-0.02",
             "incline": "10+/-0.5 deg"}
    result = propagate(lambda: rolling_onset_result(texts))
    assert len(calls) == TIMING_RUNS
    assert all(e.uncertainty > 0 for e in result.results.values())


@pytest.mark.parametrize("n", [1, 2, 3])
def test_ode_calls_the_kernel_twice_per_uncertain_input(monkeypatch, n):
    """--method ode: central differences on the parsed inputs, one integration per nudge. The
    run as typed times the ODE kernel (the best of TIMING_RUNS = 3 runs, as --method ode
    reports its timing): 1 timed computation + 2 n nudged ones = TIMING_RUNS + 2 n calls.
    The uncertainties agree with the closed form's exact ones to the ODE's accuracy."""
    calls = []
    original = rolling_physics.onset_ode
    monkeypatch.setattr(rolling_physics, "onset_ode",
                        lambda *a, **k: calls.append(k.get("rtol")) or original(*a, **k))
    texts = {"v0": "5 m/s", "mu": "0.3", "radius": "0.11 m", "omega0": "-20 rad/s"}
    for name, text in list(zip(("v0", "mu", "omega0"),
                               ("5+/-0.1 m/s", "0.3+/-0.01", "-20+/-1 rad/s")))[:n]:
        texts[name] = text
    result = propagate(lambda: rolling_onset_result(texts, method="ode"))
    assert result.method == "ode"
    assert len(calls) == TIMING_RUNS + 2 * n
    exact = propagate(lambda: rolling_onset_result(texts))
    for name, entry in exact.results.items():
        assert result.results[name].uncertainty == pytest.approx(entry.uncertainty,
                                                                  rel=1e-6, abs=0), name
    assert result.explanation.variance.keys() == exact.explanation.variance.keys()


def test_set_down_rolling_takes_central_differences_on_the_parsed_inputs():
    """s0 = v0 - r omega0 = 0 (2 m/s, 0.1 m, 20 rad/s): t_roll ~ |s0| has a kink, so the
    derivatives are central differences on the parsed values; on level ground
    v_roll = (v0 + kappa r omega0)/(1 + kappa) is smooth through it, so u(v_roll) is the
    hand value: (u(v0)^2 + (kappa omega0 u(r))^2 + (kappa r u(omega0))^2)^0.5 / (1 + kappa)."""
    texts = {"v0": "2+/-0.05 m/s", "mu": "0.2+/-0.01", "radius": "0.1+/-0.001 m",
             "omega0": "20+/-1 rad/s"}
    result = propagate(lambda: rolling_onset_result(texts))
    kappa = 0.4
    hand = math.sqrt(0.05 ** 2 + (kappa * 20 * 0.001) ** 2 + (kappa * 0.1 * 1) ** 2) / 1.4
    assert result.results["v_roll"].value_in() == 2.0
    assert result.results["v_roll"].uncertainty == pytest.approx(hand, rel=1e-8, abs=0)
    assert result.explanation.variance["v_roll"]["mu"] == 0.0


def test_an_uncertain_zero_spin_without_radius_is_not_propagated():
    """--omega0 '0+/-1 rad/s' without --radius: any other spin is refused (it needs the
    radius), so both nudges are refused and no result gets an uncertainty (as before)."""
    result = propagate(lambda: rolling_onset_result({"v0": "2+/-0.05 m/s", "mu": "0.2",
                                                     "omega0": "0+/-1 rad/s"}))
    assert [e.uncertainty for e in result.results.values()] == [None, None, None]
    assert result.warnings == [f"the uncertainty of {name} could not be propagated (a nudged "
                               "input was refused or gave no finite result)"
                               for name in ("t_roll", "x_roll", "v_roll")]
