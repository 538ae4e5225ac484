"""Scenes of dyncalc/scenes/rotating.py: half-cylinder-shell, rod-torsion-spring, coupled-blocks,
pendulum-accelerating-support, pendulum-on-rotating-disk, bead-on-rotating-ring, quarter-car.

Each scene is checked against its SCENES.md formula, and independently: equations of motion
integrated with scipy's solve_ivp and their periods measured, eigenproblems solved by numpy and
scipy, and mpmath references (from the float inputs) with the error counted in ulp.
"""
import json
import math
import shlex

import mpmath
import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from dyncalc.cli import cli
from dyncalc.errors import InputError, PhysicsError
from dyncalc.physics.coupled import two_by_two_modes
from dyncalc.physics.nonlinear import (WOUND_THRESHOLD, _shell_quadrature,
                                       _shell_small_error_bound, half_cylinder_shell)
from dyncalc.physics.rotating import bead_on_rotating_ring, quarter_car
from dyncalc.scenes import get_scene
from dyncalc.scenes.runner import run_scene
from dyncalc.units import Q_

G = 9.80665
SCENES = ["half-cylinder-shell", "rod-torsion-spring", "coupled-blocks",
          "pendulum-accelerating-support", "pendulum-on-rotating-disk",
          "bead-on-rotating-ring", "quarter-car"]


def cli_json(*args):
    result = CliRunner().invoke(cli, ["natural-frequency", *args, "--json"])
    assert result.exit_code == 0, result.output + result.stderr
    return json.loads(result.stdout)


def refusal(*args):
    """The one error line of a refused natural-frequency call (exit status 2)."""
    result = CliRunner().invoke(cli, ["natural-frequency", *args])
    assert result.exit_code == 2, result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    return lines[0]


def run_refusal(scene, texts, **kw):
    with pytest.raises(InputError) as info:
        run_scene(scene, texts, **kw)
    return str(info.value)


def si(scene, texts, **kw):
    """SI values of every result of ``scene``."""
    result = run_scene(scene, texts, **kw)
    return {name: entry.si for name, entry in result.results.items()}


def ulps(value, exact):
    """Distance of ``value`` from the mpmath value ``exact`` in units of the latter's ulp."""
    return float(abs(mpmath.mpf(value) - exact) / math.ulp(float(exact)))


def measured_period(accel, x_eq, offset, t_max, rtol=1e-12):
    """Period of ``x'' = accel(x, x')`` released at rest from ``x_eq + offset``.

    Integrated in the deviation from ``x_eq`` (so the tolerance is relative to the swing);
    the period is the time between two successive downward crossings of ``x_eq``, which holds
    for potentials that are not symmetric about ``x_eq`` as well.
    """
    def rhs(_t, y):
        return [y[1], accel(x_eq + y[0], y[1])]

    def crossing(_t, y):
        return y[0]

    crossing.direction = -1.0
    sol = solve_ivp(rhs, (0.0, t_max), [offset, 0.0], method="DOP853", rtol=rtol,
                    atol=1e-3 * rtol * abs(offset), events=crossing)
    times = sol.t_events[0]
    assert len(times) >= 2, "integrate for longer"
    return times[1] - times[0]


# --- every scene: its example ----------------------------------------------------------------

@pytest.mark.parametrize("name", SCENES)
def test_example_reproduces_its_result(name):
    """The example command gives example_result (mpmath at 30 digits) to 1e-12 and the scene
    documents itself (figure, equation, formula, reference)."""
    scene = get_scene(name)
    assert scene.figure and scene.equation and scene.formula and scene.reference
    args = shlex.split(scene.example)
    assert args[:2] == ["dyncalc", "natural-frequency"]
    data = cli_json(*args[2:])
    assert data["scene"] == name and data["warnings"] == []
    for key, text in scene.example_result.items():
        number, unit = text.split(" ", 1)
        got = data["results"][key]
        want = Q_(float(number), unit).to(got["unit"] or "").magnitude
        assert got["value"] == pytest.approx(want, rel=1e-12, abs=0), key


def test_scene_help_lists_methods():
    result = CliRunner().invoke(cli, ["scenes", "half-cylinder-shell"])
    assert result.exit_code == 0
    assert "methods: auto, linear, quadrature, ode" in result.stdout


# --- half-cylinder-shell ---------------------------------------------------------------------

def shell_accel(r, g=G):
    """phi'' of phi''(pi - 2 cos phi) + phi'^2 sin phi + (g/r) sin phi = 0."""
    return lambda phi, rate: -(rate * rate + g / r) * math.sin(phi) / (math.pi - 2 * math.cos(phi))


def shell_period_mpmath(r, g, phi0):
    """The energy integral at 30 digits (mpmath.quad), from the float inputs."""
    with mpmath.workdps(30):
        k2 = mpmath.sin(mpmath.mpf(phi0) / 2) ** 2
        a = mpmath.pi - 2
        integral = mpmath.quad(lambda u: mpmath.sqrt(a + 4 * k2 * mpmath.sin(u) ** 2)
                               / mpmath.sqrt(1 - k2 * mpmath.sin(u) ** 2), [0, mpmath.pi / 2])
        return 4 * mpmath.sqrt(mpmath.mpf(r) / mpmath.mpf(g)) * integral


@pytest.mark.parametrize("r", [0.01, 0.5, 3.0, 1e5])
def test_shell_small_oscillations(r):
    values = si("half-cylinder-shell", {"r": f"{r} m"})
    assert values["omega"] == pytest.approx(math.sqrt(G / ((math.pi - 2) * r)), rel=2e-16)
    assert values["T"] == pytest.approx(2 * math.pi / values["omega"], rel=1e-16)
    with mpmath.workdps(40):
        exact = mpmath.sqrt(mpmath.mpf(G) / ((mpmath.pi - 2) * mpmath.mpf(r)))
    assert ulps(values["omega"], exact) <= 1.0


@pytest.mark.parametrize("degrees", [5.0, 30.0, 60.0, 80.0, 89.0])
def test_shell_large_amplitude_against_the_integrated_motion(degrees):
    """quadrature and ode methods against the equation of motion integrated here, and both
    against the mpmath energy integral."""
    r = 0.7
    phi0 = math.radians(degrees)
    t0 = 2 * math.pi * math.sqrt((math.pi - 2) * r / G)
    measured = measured_period(shell_accel(r), 0.0, phi0, 2.5 * t0, rtol=1e-12)
    exact = shell_period_mpmath(r, G, phi0)
    texts = {"r": f"{r} m", "amplitude": f"{degrees} deg"}
    for method in ("quadrature", "ode"):
        result = run_scene("half-cylinder-shell", texts, method=method)
        period = result.results["T"].si
        assert result.method == method and result.model == "nonlinear"
        assert period == pytest.approx(measured, rel=1e-9)
        error = abs(period / float(exact) - 1)
        assert error <= max(result.extra["error_estimate"], 4e-16)
        assert result.extra["error_estimate"] <= 1e-9
        assert result.results["omega_0"].si == pytest.approx(2 * math.pi / t0, rel=1e-15)
    assert run_scene("half-cylinder-shell", texts).method == "quadrature"


def test_shell_quadrature_accuracy_at_80_degrees():
    """At the default rtol the quadrature period is within a few ulp of mpmath's."""
    phi0 = math.radians(80.0)
    values = si("half-cylinder-shell", {"r": "0.5 m", "amplitude": "80 deg"})
    assert ulps(values["T"], shell_period_mpmath(0.5, G, phi0)) <= 4


def test_shell_auto_takes_linear_only_within_tolerance():
    """At 0.1 deg the small-oscillation period is 8.6e-7 short (bound 8.6e-7 too)."""
    tiny = run_scene("half-cylinder-shell", {"r": "1 m", "amplitude": "0.1 deg"}, rtol=1e-6)
    assert (tiny.model, tiny.method) == ("linear", "linear")
    assert tiny.extra["error_estimate"] <= 1e-6 and tiny.warnings == []
    assert tiny.results["omega"].si == tiny.results["omega_0"].si
    exact = shell_period_mpmath(1.0, G, math.radians(0.1))
    assert 1 - tiny.results["T"].si / float(exact) <= tiny.extra["error_estimate"]
    assert run_scene("half-cylinder-shell", {"r": "1 m", "amplitude": "0.1 deg"},
                     rtol=1e-9).method == "quadrature"
    assert run_scene("half-cylinder-shell", {"r": "1 m", "amplitude": "0 deg"}).method == "linear"


@pytest.mark.parametrize("degrees", [1e-3, 1.0, 10.0, 45.0, 70.0, 89.99])
def test_shell_small_error_bound_bounds_the_error(degrees):
    """The bound auto uses is above the true T/T0 - 1 and tight at small amplitude."""
    k2 = math.sin(math.radians(degrees) / 2) ** 2
    factor, _ = _shell_quadrature(k2, 1e-14)
    true_error = factor - 1
    bound = _shell_small_error_bound(k2)
    assert bound >= true_error
    if degrees <= 1.0:
        assert bound == pytest.approx(true_error, rel=1e-3)


def test_shell_forced_linear_model_warns():
    result = run_scene("half-cylinder-shell", {"r": "1 m", "amplitude": "30 deg"},
                       method="linear")
    assert result.results["T"].si == pytest.approx(
        2 * math.pi * math.sqrt((math.pi - 2) / G), rel=1e-15)
    error = result.extra["error_estimate"]
    exact = shell_period_mpmath(1.0, G, math.radians(30))
    assert error == pytest.approx(1 - result.results["T"].si / float(exact), rel=1e-9)
    assert result.warnings == [f"the linear model misses the requested tolerance 1e-09: its "
                               f"period is {100 * error:.3g}% short at 30 deg; use --method "
                               "quadrature"]


def test_shell_ode_error_estimate_follows_rtol():
    loose = half_cylinder_shell(Q_(1, "m"), Q_(G, "m/s^2"), Q_(60, "deg"), "ode", 1e-5)
    exact = shell_period_mpmath(1.0, G, math.radians(60))
    error = abs(loose.values["T"].magnitude / float(exact) - 1)
    assert error <= loose.error_estimate <= 1e-5
    assert loose.warnings == []


def test_shell_refusals():
    message = ("Error: the amplitude must be below 90 degrees; at {} the rim of the "
               "half-cylinder shell touches the ground and the rocking model ends")
    assert refusal("--scene", "half-cylinder-shell", "r=1m", "--amplitude", "90deg") == (
        message.format("90 deg"))
    assert refusal("--scene", "half-cylinder-shell", "r=1m", "amplitude=120deg") == (
        message.format("120 deg"))
    assert refusal("--scene", "half-cylinder-shell", "r=1m", "--amplitude", "1.6 rad") == (
        message.format("1.6 rad"))
    with pytest.raises(PhysicsError):
        half_cylinder_shell(Q_(1, "m"), Q_(G, "m/s^2"), Q_(math.pi / 2, "rad"))
    assert refusal("--scene", "half-cylinder-shell", "r=1m", "--method", "ode") == (
        "Error: --method ode needs an amplitude (--amplitude or amplitude=); without one the "
        "shell's oscillation is linear")
    assert refusal("--scene", "half-cylinder-shell", "r=1m", "--amplitude", "10deg",
                   "--method", "elliptic") == (
        "Error: --method elliptic is not offered by half-cylinder-shell; it offers auto, "
        "linear, quadrature, ode")


def test_shell_unit_invariance():
    metric = si("half-cylinder-shell", {"r": "0.3048 m", "amplitude": "45 deg"})
    imperial = si("half-cylinder-shell", {"r": "1 ft", "amplitude": f"{math.pi / 4} rad",
                                          "g": "32.17404855643044 ft/s^2"})
    for name in ("omega", "T", "omega_0"):
        assert imperial[name] == pytest.approx(metric[name], rel=1e-14)


# --- rod-torsion-spring ----------------------------------------------------------------------

def rod_reference(m, l, kt, g):
    """(phi_0, omega) at 40 digits from the float inputs (mpmath.findroot)."""
    with mpmath.workdps(40):
        kappa = mpmath.mpf(kt) / (mpmath.mpf(m) * mpmath.mpf(g) * mpmath.mpf(l))
        phi = mpmath.findroot(lambda p: mpmath.cos(p) - kappa * p, (0, mpmath.pi / 2),
                              solver="anderson")
        omega = mpmath.sqrt(mpmath.mpf(g) / mpmath.mpf(l) * (mpmath.sin(phi) + kappa))
        return phi, omega


@pytest.mark.parametrize("m, l, kt", [(2.0, 1.0, 30.0), (0.5, 0.3, 0.02), (10.0, 2.0, 5000.0),
                                      (1.0, 1.0, 1e-6), (1.0, 1.0, 1e9)])
def test_rod_formula_and_accuracy(m, l, kt):
    values = si("rod-torsion-spring", {"m": f"{m} kg", "l": f"{l} m", "kt": f"{kt} N*m/rad"})
    phi0 = values["phi_0"]
    assert 0 < phi0 < math.pi / 2
    assert (G / l) * math.cos(phi0) == pytest.approx(kt * phi0 / (m * l * l), rel=1e-13)
    assert values["omega"] ** 2 == pytest.approx(
        (G / l) * math.sin(phi0) + kt / (m * l * l), rel=1e-14)
    phi_ref, omega_ref = rod_reference(m, l, kt, G)
    assert ulps(phi0, phi_ref) <= 4
    assert ulps(values["omega"], omega_ref) <= 4


@pytest.mark.parametrize("kappa", [1e-300, 1e-20, 3.9e-17, 1e-8, 0.3365, 1.0, 7.3e5, 1e18,
                                   3.7e300])
def test_rod_equilibrium_over_the_whole_range(kappa):
    """The monotone Newton of _rod_equilibrium against mpmath (ulp) and scipy's brentq where
    its float bracket holds (cos(fl(pi/2)) = 6.1e-17 makes F(pi/2) > 0 for tiny kappa)."""
    from scipy.optimize import brentq

    from dyncalc.physics.nonlinear import _rod_equilibrium

    phi = _rod_equilibrium(kappa)
    with mpmath.workdps(40):
        k = mpmath.mpf(kappa)
        exact = (mpmath.findroot(lambda p: mpmath.cos(p) - k * p, (0, mpmath.pi / 2),
                                 solver="anderson") if kappa > 1e-30 else mpmath.pi / 2 * (1 - k))
    assert ulps(phi, exact) <= 2
    if 1e-16 < kappa < 1e280:
        root = brentq(lambda p: math.cos(p) - kappa * p, 0, math.pi / 2, xtol=1e-300,
                      rtol=4 * 2 ** -52)
        assert abs(root - phi) <= 8 * math.ulp(phi)


@pytest.mark.parametrize("m, l, kt", [(2.0, 1.0, 30.0), (0.5, 0.3, 0.4), (1.0, 2.0, 3.0)])
def test_rod_linearised_numerically(m, l, kt):
    """A small swing about phi_0 of m l^2 phi'' = m g l cos(phi) - kt phi, its period measured."""
    values = si("rod-torsion-spring", {"m": f"{m} kg", "l": f"{l} m", "kt": f"{kt} N*m/rad"})

    def accel(phi, _rate):
        return (G / l) * math.cos(phi) - kt * phi / (m * l * l)

    period = measured_period(accel, values["phi_0"], 1e-5, 2.5 * values["T"])
    assert period == pytest.approx(values["T"], rel=1e-8)


def test_rod_wound_threshold():
    """WOUND_THRESHOLD is sin(psi) with psi sin(psi) + cos(psi) = 0 in (pi/2, pi), and it is
    where roots of cos(phi) = kappa phi past the vertical (phi in (-pi, -pi/2)) appear."""
    from scipy.optimize import brentq, minimize_scalar

    psi = brentq(lambda x: x * math.sin(x) + math.cos(x), math.pi / 2, math.pi, xtol=1e-16)
    assert WOUND_THRESHOLD == pytest.approx(math.sin(psi), rel=4e-16)
    with mpmath.workdps(40):
        exact = mpmath.sin(mpmath.findroot(lambda x: x * mpmath.sin(x) + mpmath.cos(x), 2.8))
    assert ulps(WOUND_THRESHOLD, exact) <= 0.5

    def lowest(kappa):  # min of cos(phi) - kappa phi over the wound side
        return minimize_scalar(lambda p: math.cos(p) - kappa * p, bounds=(-math.pi, -math.pi / 2),
                               method="bounded", options={"xatol": 1e-12}).fun

    assert lowest(WOUND_THRESHOLD * (1 - 1e-6)) < 0 < lowest(WOUND_THRESHOLD * (1 + 1e-6))


def test_rod_warns_of_wound_equilibria():
    m, l = 1.0, 1.0
    below = run_scene("rod-torsion-spring", {"m": "1 kg", "l": "1 m",
                                             "kt": f"{0.3 * m * G * l} N*m/rad"})
    assert below.warnings == [
        "kt = 0.3 m g l is at most 0.336508 m g l: further equilibria exist with the rod wound "
        "past the vertical; this result is the one between the horizontal and the downward "
        "vertical"]
    above = run_scene("rod-torsion-spring", {"m": "1 kg", "l": "1 m",
                                             "kt": f"{0.34 * m * G * l} N*m/rad"})
    assert above.warnings == []


def test_rod_refuses_kt_not_positive():
    assert refusal("--scene", "rod-torsion-spring", "m=1kg", "l=1m", "kt=0") == (
        "Error: kt must be positive; got 0 meter * newton / radian")
    assert refusal("--scene", "rod-torsion-spring", "m=1kg", "l=1m", "--kt", "-3 N*m/rad") == (
        "Error: --kt must be positive; got -3 meter * newton / radian")


def test_rod_unit_invariance():
    metric = si("rod-torsion-spring", {"m": "0.45359237 kg", "l": "0.3048 m",
                                       "kt": "1.3558179483314004 N*m/rad"})
    imperial = si("rod-torsion-spring", {"m": "1 lb", "l": "1 ft", "kt": "1 lbf*ft/rad"})
    for name in ("omega", "T", "phi_0"):
        assert imperial[name] == pytest.approx(metric[name], rel=1e-13)


# --- coupled-blocks --------------------------------------------------------------------------

def coupled_texts(m1, m2, k1, k2, k3):
    return {"m1": f"{m1} kg", "m2": f"{m2} kg", "k1": f"{k1} N/m", "k2": f"{k2} N/m",
            "k3": f"{k3} N/m"}


@pytest.mark.parametrize("params", [(1, 2, 100, 200, 50), (3.5, 0.2, 10, 0, 4), (1, 1, 1, 1, 1),
                                    (2, 7, 0, 300, 30), (1, 1e-3, 5, 5e3, 1e-2)])
def test_coupled_against_numpy(params):
    m1, m2, k1, k2, k3 = params
    values = si("coupled-blocks", coupled_texts(*params))
    K = np.array([[k1 + k3, -k3], [-k3, k2 + k3]], dtype=float)
    M = np.diag([m1, m2]).astype(float)
    eigenvalues = np.sort(np.linalg.eig(np.linalg.inv(M) @ K)[0].real)
    assert values["omega_1"] <= values["omega_2"]
    for i, lam in enumerate(eigenvalues, 1):
        omega = values[f"omega_{i}"]
        # eig of the non-symmetric M^-1 K is accurate relative to the largest eigenvalue
        assert omega ** 2 == pytest.approx(lam, rel=1e-13, abs=1e-13 * eigenvalues[-1])
        assert values[f"f_{i}"] == pytest.approx(omega / (2 * math.pi), rel=1e-15)
        assert values[f"T_{i}"] == pytest.approx(2 * math.pi / omega, rel=1e-15)
        v = values[f"mode_{i}"]
        assert np.linalg.norm(v) == pytest.approx(1.0, rel=1e-15)
        assert v[0] > 0 or (v[0] == 0 and v[1] > 0)
        residual = K @ v - omega ** 2 * (M @ v)
        assert np.abs(residual).max() <= 1e-12 * np.abs(K).max()
    # the modes are M-orthogonal
    assert abs(values["mode_1"] @ M @ values["mode_2"]) <= 1e-13 * max(m1, m2)


positive = st.floats(min_value=1e-6, max_value=1e6, allow_nan=False, allow_infinity=False)


@settings(max_examples=200, deadline=None)
@given(positive, positive, positive, positive, positive)
def test_coupled_closed_form_against_eigh(m1, m2, k1, k2, k3):
    from scipy.linalg import eigh

    lam1, lam2, v1, v2 = two_by_two_modes(k1, k2, k3, m1, m2)
    K = np.array([[k1 + k3, -k3], [-k3, k2 + k3]])
    M = np.diag([m1, m2])
    w, V = eigh(K, M)
    # eigh is backward stable: its eigenvalues are accurate relative to the largest one
    assert lam1 == pytest.approx(w[0], rel=1e-12, abs=1e-13 * w[1])
    assert lam2 == pytest.approx(w[1], rel=1e-12)
    for lam, v in ((lam1, v1), (lam2, v2)):
        scale = np.abs(K).max() + lam * max(m1, m2)
        assert np.abs(K @ v - lam * (M @ v)).max() <= 1e-13 * scale


def test_coupled_stiff_coupling_keeps_the_slow_mode():
    """k3 >> k1, k2: the textbook (a + d)/2 - sqrt(...) loses every digit of omega_1^2;
    det / lambda_2 keeps it (mpmath reference from the float inputs, in ulp)."""
    m1, m2, k1, k2, k3 = 1.3, 2.9, 2.1, 5.3, 1.234567e14
    values = si("coupled-blocks", coupled_texts(m1, m2, k1, k2, k3))
    with mpmath.workdps(50):
        K = mpmath.matrix([[k1 + mpmath.mpf(k3), -k3], [-k3, k2 + mpmath.mpf(k3)]])
        A = mpmath.inverse(mpmath.diag([m1, m2])) * K
        lams = sorted(mpmath.re(e) for e in mpmath.eig(A)[0])
        omegas = [mpmath.sqrt(lam) for lam in lams]
    assert ulps(values["omega_1"], omegas[0]) <= 2
    assert ulps(values["omega_2"], omegas[1]) <= 2
    a, d = (k1 + k3) / m1, (k2 + k3) / m2
    naive = (a + d) / 2 - math.sqrt(((a - d) / 2) ** 2 + k3 * k3 / (m1 * m2))
    assert abs(naive / float(lams[0]) - 1) > 1e-3  # what the closed form avoids


def test_coupled_decoupled_modes_are_exact():
    values = si("coupled-blocks", coupled_texts(1, 1, 100, 400, 0))
    assert values["omega_1"] == 10.0 and values["omega_2"] == 20.0
    assert values["mode_1"].tolist() == [1.0, 0.0] and values["mode_2"].tolist() == [0.0, 1.0]
    values = si("coupled-blocks", coupled_texts(1, 1, 400, 100, 0))
    assert values["mode_1"].tolist() == [0.0, 1.0] and values["mode_2"].tolist() == [1.0, 0.0]


def test_coupled_json_has_mode_lists():
    data = cli_json("--scene", "coupled-blocks", "m1=1kg", "m2=1kg", "k1=1N/m", "k2=1N/m",
                    "k3=1N/m")
    assert data["results"]["omega_2"]["value"] == pytest.approx(math.sqrt(3), rel=1e-15)
    assert data["results"]["mode_2"]["unit"] == ""
    assert data["results"]["mode_2"]["value"] == pytest.approx([2 ** -0.5, -(2 ** -0.5)],
                                                               rel=1e-15)


def test_coupled_refusals():
    base = ["--scene", "coupled-blocks", "m1=1kg", "m2=2kg", "k1=100N/m", "k2=200N/m",
            "k3=50N/m"]
    params = ("the parameters of coupled-blocks are: m1 [mass], m2 [mass], k1 [force]/[length], "
              "k2 [force]/[length], k3 [force]/[length]")
    no_zeta = ("Error: coupled-blocks takes no zeta: it has two modes, and one damping ratio "
               f"for both would be ambiguous; {params}")
    assert refusal(*base, "--zeta", "0.1") == no_zeta
    assert refusal(*base, "zeta=0.1") == no_zeta
    assert refusal(*base, "--method", "ode") == (
        "Error: --method ode is not offered by coupled-blocks; it offers auto (a closed form "
        "only)")
    assert refusal("--scene", "coupled-blocks", "m1=1kg", "m2=2kg", "k1=0N/m", "k2=0N/m",
                   "k3=50N/m") == (
        "Error: coupled-blocks needs at least two of k1, k2, k3 positive; otherwise a block "
        "drifts freely (a mode of zero frequency)")
    assert run_refusal("coupled-blocks", coupled_texts(1, 2, 100, -1, 50)) == (
        "k2 must not be negative; got -1 newton / meter")


def test_coupled_unit_invariance():
    metric = si("coupled-blocks", {"m1": "0.45359237 kg", "m2": "0.90718474 kg",
                                   "k1": "175.12683524647636 N/m", "k2": "350.2536704929527 N/m",
                                   "k3": "87.56341762323818 N/m"})
    imperial = si("coupled-blocks", {"m1": "1 lb", "m2": "2 lb", "k1": "1 lbf/in",
                                     "k2": "2 lbf/in", "k3": "0.5 lbf/in"})
    for name in ("omega_1", "omega_2", "T_1", "T_2"):
        assert imperial[name] == pytest.approx(metric[name], rel=1e-13)
    for name in ("mode_1", "mode_2"):
        assert imperial[name] == pytest.approx(metric[name], rel=1e-13)


# --- pendulum-accelerating-support -----------------------------------------------------------

@pytest.mark.parametrize("a0", [3.0, -7.5, 0.0, 25.0, 1e-9])
def test_accelerating_support_formula_and_motion(a0):
    l = 0.8
    values = si("pendulum-accelerating-support", {"l": f"{l} m", "a0": f"{a0} m/s^2"})
    assert values["phi_0"] == pytest.approx(-math.atan(a0 / G), rel=1e-15, abs=0)
    assert values["omega"] == pytest.approx(math.sqrt(math.sqrt(G * G + a0 * a0) / l), rel=1e-15)

    def accel(phi, _rate):
        return -(G * math.sin(phi) + a0 * math.cos(phi)) / l

    period = measured_period(accel, values["phi_0"], 1e-5, 2.5 * values["T"])
    assert period == pytest.approx(values["T"], rel=1e-8)


def test_accelerating_support_signs_and_extremes():
    at_rest = si("pendulum-accelerating-support", {"l": "1 m", "a0": "0 m/s^2"})
    assert at_rest["phi_0"] == 0.0 and math.copysign(1, at_rest["phi_0"]) == 1  # not -0
    assert at_rest["omega"] == math.sqrt(G)
    braking = si("pendulum-accelerating-support", {"l": "1 m", "a0": "-9.80665 m/s^2"})
    assert braking["phi_0"] == pytest.approx(math.pi / 4, rel=1e-15)
    huge = si("pendulum-accelerating-support", {"l": "1 m", "a0": "1e200 m/s^2"})
    assert huge["phi_0"] == pytest.approx(-math.pi / 2, rel=1e-15)
    assert huge["omega"] == pytest.approx(1e100, rel=1e-15)  # hypot: no overflow of a0^2
    with mpmath.workdps(40):
        exact = mpmath.sqrt(mpmath.sqrt(mpmath.mpf(G) ** 2 + mpmath.mpf(3.7) ** 2)
                            / mpmath.mpf(0.45))
        phi = -mpmath.atan(mpmath.mpf(3.7) / mpmath.mpf(G))
    values = si("pendulum-accelerating-support", {"l": "0.45 m", "a0": "3.7 m/s^2"})
    assert ulps(values["omega"], exact) <= 1.5 and ulps(values["phi_0"], phi) <= 1


def test_accelerating_support_unit_invariance():
    metric = si("pendulum-accelerating-support", {"l": "0.9144 m", "a0": "1.524 m/s^2"})
    imperial = si("pendulum-accelerating-support", {"l": "3 ft", "a0": "5 ft/s^2"})
    for name in ("omega", "T", "phi_0"):
        assert imperial[name] == pytest.approx(metric[name], rel=1e-14)


# --- pendulum-on-rotating-disk ---------------------------------------------------------------

def test_rotating_disk_formula_and_units():
    values = si("pendulum-on-rotating-disk", {"r": "0.5 m", "l": "0.2 m", "Omega": "3 rad/s"})
    assert values["omega"] == pytest.approx(math.sqrt(0.5 / 0.2) * 3, rel=1e-15)
    rpm = si("pendulum-on-rotating-disk", {"r": "0.5 m", "l": "0.2 m", "Omega": "60 rpm"})
    rad = si("pendulum-on-rotating-disk", {"r": "0.5 m", "l": "0.2 m",
                                           "Omega": f"{2 * math.pi} rad/s"})
    assert rpm["omega"] == pytest.approx(rad["omega"], rel=1e-15)
    feet = si("pendulum-on-rotating-disk", {"r": "5 ft", "l": "2 ft", "Omega": "60 rpm"})
    assert feet["omega"] == pytest.approx(rpm["omega"], rel=1e-15)
    reverse = si("pendulum-on-rotating-disk", {"r": "0.5 m", "l": "0.2 m", "Omega": "-60 rpm"})
    assert reverse["omega"] == rpm["omega"]


def test_rotating_disk_motion():
    """phi'' = -(r/l) Omega^2 sin(phi) in the disk's frame, a small swing measured."""
    r, l, spin = 0.5, 0.2, 3.0
    values = si("pendulum-on-rotating-disk", {"r": f"{r} m", "l": f"{l} m",
                                              "Omega": f"{spin} rad/s"})
    period = measured_period(lambda phi, _: -(r / l) * spin ** 2 * math.sin(phi), 0.0, 1e-5,
                             2.5 * values["T"])
    assert period == pytest.approx(values["T"], rel=1e-8)


def test_rotating_disk_refuses_zero_spin():
    assert refusal("--scene", "pendulum-on-rotating-disk", "r=1m", "l=1m", "Omega=0rpm") == (
        "Error: Omega must not be zero")


# --- bead-on-rotating-ring -------------------------------------------------------------------

def bead_reference(r, spin, g=G):
    """(theta_eq, omega) at 40 digits from the float inputs."""
    with mpmath.workdps(40):
        r, spin, g = mpmath.mpf(r), mpmath.mpf(spin), mpmath.mpf(g)
        if r * spin ** 2 < g:
            return mpmath.mpf(0), mpmath.sqrt(g / r - spin ** 2)
        return mpmath.acos(g / (r * spin ** 2)), mpmath.sqrt(spin ** 2 - (g / (r * spin)) ** 2)


@pytest.mark.parametrize("spin", [0.0, 3.0, 6.5, 8.0, 12.0, 100.0])
def test_bead_formula_and_rotating_frame_motion(spin):
    r = 0.2
    values = si("bead-on-rotating-ring", {"r": f"{r} m", "Omega": f"{spin} rad/s"})
    if spin * spin < G / r:
        assert values["theta_eq"] == 0.0
        assert values["omega"] == pytest.approx(math.sqrt(G / r - spin * spin), rel=1e-14)
    else:
        assert values["theta_eq"] == pytest.approx(math.acos(G / (r * spin * spin)), rel=1e-14)
        assert values["omega"] == pytest.approx(
            math.sqrt(spin ** 2 - (G / (r * spin)) ** 2), rel=1e-14)

    def accel(theta, _rate):
        return math.sin(theta) * (spin * spin * math.cos(theta) - G / r)

    period = measured_period(accel, values["theta_eq"], 1e-5, 2.5 * values["T"])
    assert period == pytest.approx(values["T"], rel=1e-8)


@pytest.mark.parametrize("relative", [1e-3, 1e-6, 1e-9, 1e-12, -1e-6, -1e-10])
def test_bead_near_the_bifurcation_keeps_its_digits(relative):
    """Omega a hair from sqrt(g/r): theta_eq and omega within a few ulp of mpmath (from the
    float inputs), where acos(g/(r Omega^2)) in floats is off in the leading digits."""
    r = 0.3
    spin = math.sqrt(G / r) * (1 + relative)
    out = bead_on_rotating_ring(Q_(r, "m"), Q_(spin, "rad/s"), Q_(G, "m/s^2"))
    theta, omega = out.values["theta_eq"].magnitude, out.values["omega"].magnitude
    theta_ref, omega_ref = bead_reference(r, spin)
    assert ulps(omega, omega_ref) <= 3
    if relative > 0:
        assert ulps(theta, theta_ref) <= 3
        naive = math.acos(G / (r * spin * spin))
        if relative <= 1e-9:  # millions of ulp off
            assert abs(naive / float(theta_ref) - 1) > 1e-9
    else:
        assert theta == 0.0
    assert out.warnings == [
        f"Omega is {100 * abs(spin / math.sqrt(G / r) - 1):.2g}% "
        f"{'above' if relative > 0 else 'below'} the bifurcation speed sqrt(g/r) = "
        f"{math.sqrt(G / r):.6g} rad/s: the stiffness about the equilibrium is small, so this "
        "frequency holds only for very small amplitudes and changes fast with Omega"]


def test_bead_at_the_bifurcation():
    """r = g / Omega^2 exactly: omega = 0 with a warning, T infinite (JSON null, --value inf)."""
    out = bead_on_rotating_ring(Q_(G, "m"), Q_(1, "rad/s"), Q_(G, "m/s^2"))
    assert out.values["omega"].magnitude == 0.0 and out.values["T"].magnitude == math.inf
    assert out.values["theta_eq"].magnitude == 0.0
    assert out.warnings == [
        "Omega is at the bifurcation Omega^2 = g/r (Omega = 1 rad/s): the linear stiffness "
        "vanishes, so omega = 0 and the period is infinite; the real oscillation is governed "
        "by the cubic term and depends on its amplitude"]
    data = cli_json("--scene", "bead-on-rotating-ring", f"r={G}m", "Omega=1rad/s")
    assert data["results"]["omega"]["value"] == 0.0
    assert data["results"]["T"]["value"] is None
    assert data["warnings"][0] == out.warnings[0]
    value = CliRunner().invoke(cli, ["natural-frequency", "--scene", "bead-on-rotating-ring",
                                     f"r={G}m", "Omega=1rad/s", "--value", "T"])
    assert value.exit_code == 0 and value.stdout == "inf\n"


def test_bead_sense_of_spin_and_units():
    rad = si("bead-on-rotating-ring", {"r": "0.2 m", "Omega": f"{4 * math.pi} rad/s"})
    rpm = si("bead-on-rotating-ring", {"r": "0.2 m", "Omega": "120 rpm"})
    reverse = si("bead-on-rotating-ring", {"r": "0.2 m", "Omega": "-120 rpm"})
    feet = si("bead-on-rotating-ring", {"r": f"{0.2 / 0.3048} ft", "Omega": "2 rev/s"})
    for name in ("omega", "T", "theta_eq"):
        assert rpm[name] == pytest.approx(rad[name], rel=1e-14)
        assert reverse[name] == rpm[name]
        assert feet[name] == pytest.approx(rpm[name], rel=1e-14)


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=1e-3, max_value=1e3), st.floats(min_value=0.0, max_value=1e3))
def test_bead_properties(r, spin):
    out = bead_on_rotating_ring(Q_(r, "m"), Q_(spin, "rad/s"), Q_(G, "m/s^2"))
    theta, omega = out.values["theta_eq"].magnitude, out.values["omega"].magnitude
    assert 0.0 <= theta < math.pi / 2
    theta_ref, omega_ref = bead_reference(r, spin)
    if omega > 0:
        assert ulps(omega, omega_ref) <= 3
    if theta > 0:
        assert ulps(theta, theta_ref) <= 3


# --- quarter-car -----------------------------------------------------------------------------

def car_texts(k, m, L, U0, v0):
    return {"k": f"{k!r} N/m", "m": f"{m!r} kg", "L": f"{L!r} m", "U0": f"{U0!r} m",
            "v0": f"{v0!r} m/s"}


def car_amplitude_reference(k, m, L, U0, v0):
    with mpmath.workdps(40):
        k, m, L, U0, v0 = (mpmath.mpf(x) for x in (k, m, L, U0, v0))
        omega2 = k / m
        forcing2 = (2 * mpmath.pi * v0 / L) ** 2
        return U0 / abs(1 - forcing2 / omega2)


@pytest.mark.parametrize("v0", [0.0, 5.0, 15.0, 16.5, 20.0, 60.0])
def test_quarter_car_formula(v0):
    k, m, L, U0 = 40e3, 400.0, 10.0, 0.02
    values = si("quarter-car", car_texts(k, m, L, U0, v0))
    omega = math.sqrt(k / m)
    forcing = 2 * math.pi * v0 / L
    assert values["omega"] == pytest.approx(omega, rel=1e-15)
    assert values["Omega"] == pytest.approx(forcing, rel=1e-15)
    assert values["v_crit"] == pytest.approx(L * omega / (2 * math.pi), rel=1e-15)
    assert values["x_amp"] == pytest.approx(U0 / abs(1 - forcing ** 2 / omega ** 2), rel=1e-13)
    assert ulps(values["x_amp"], car_amplitude_reference(k, m, L, U0, v0)) <= 1


def test_quarter_car_steady_state_of_the_motion():
    """m x'' + k x = k U0 cos(Omega t) started on the steady orbit stays on it: its peak over a
    few forcing periods is x_amp (an independent check of amplitude and phase)."""
    k, m, L, U0, v0 = 40e3, 400.0, 10.0, 0.02, 20.0
    values = si("quarter-car", car_texts(k, m, L, U0, v0))
    forcing = values["Omega"]
    # the steady solution is X cos(Omega t) with X = U0 / (1 - eta^2), here negative (above
    # resonance the body moves against the road)
    X = U0 / (1 - (forcing ** 2) * m / k)
    sol = solve_ivp(lambda t, y: [y[1], (k * U0 * math.cos(forcing * t) - k * y[0]) / m],
                    (0, 5 * 2 * math.pi / forcing), [X, 0.0], method="DOP853", rtol=1e-12,
                    atol=1e-15, dense_output=True)
    t = np.linspace(0, sol.t[-1], 20001)
    assert np.abs(sol.sol(t)[0]).max() == pytest.approx(values["x_amp"], rel=1e-7)


@pytest.mark.parametrize("relative", [1e-4, 1e-7, -1e-9, 1e-12])
def test_quarter_car_near_resonance(relative):
    """A hair from v_crit: x_amp within 1 ulp of mpmath from the float inputs (the form
    (omega - Omega)(omega + Omega) would inherit their rounding, amplified), and a warning."""
    k, m, L, U0 = 40e3, 400.0, 10.0, 0.02
    v_crit = L * math.sqrt(k / m) / (2 * math.pi)
    v0 = v_crit * (1 + relative)
    out = quarter_car(Q_(k, "N/m"), Q_(m, "kg"), Q_(L, "m"), Q_(U0, "m"), Q_(v0, "m/s"))
    amplitude = out.values["x_amp"].magnitude
    exact = car_amplitude_reference(k, m, L, U0, v0)
    assert ulps(amplitude, exact) <= 1
    gain = amplitude / U0
    if gain > 1e6:
        assert out.warnings == [
            f"v0 = {v0:.6g} m/s is within {100 * abs(v0 / v_crit - 1):.2g}% of the critical "
            f"speed v_crit = {v_crit:.6g} m/s: the undamped amplitude is {gain:.3g} times the "
            "road amplitude; a real suspension is limited by the damping this model leaves out"]
    else:
        assert out.warnings == []


def test_quarter_car_refuses_resonance():
    """k = 400 N/m, m = 1 kg, L = 1 m: v_crit = 20/(2 pi), and v0 typed as that float."""
    v0 = 20 / (2 * math.pi)
    assert refusal("--scene", "quarter-car", "k=400N/m", "m=1kg", "L=1m", "U0=1cm",
                   f"v0={v0!r}m/s") == (
        "Error: v0 = 3.1831 m/s is the critical speed v_crit = L sqrt(k/m) / (2 pi) = "
        "3.1831 m/s: the road excites the body at resonance and the undamped amplitude is "
        "unbounded; choose another speed")
    with pytest.raises(PhysicsError):
        quarter_car(Q_(400, "N/m"), Q_(1, "kg"), Q_(1, "m"), Q_(1, "cm"),
                    Q_(math.nextafter(v0, 0), "m/s"))


def test_quarter_car_refuses_zeta():
    assert refusal("--scene", "quarter-car", "k=40kN/m", "m=400kg", "L=10m", "U0=2cm",
                   "v0=20m/s", "--zeta", "0.1") == (
        "Error: quarter-car takes no zeta: x_amp is the undamped steady amplitude, which a "
        "zeta would not reach; the parameters of quarter-car are: "
        "k [force]/[length], m [mass], L [length], U0 [length], v0 [length]/[time]")


def test_quarter_car_unit_invariance():
    metric = si("quarter-car", {"k": "40 kN/m", "m": "400 kg", "L": "10 m", "U0": "2 cm",
                                "v0": "72 km/h"})
    other = si("quarter-car", {"k": "40 N/mm", "m": f"{400 / 0.45359237!r} lb",
                               "L": f"{10 / 0.3048!r} ft", "U0": "20 mm", "v0": "20 m/s"})
    for name in ("omega", "Omega", "x_amp", "v_crit", "T"):
        assert other[name] == pytest.approx(metric[name], rel=1e-13)


@pytest.mark.parametrize("method", ["linear", "quadrature", "ode"])
def test_shell_error_estimate_bounds_the_true_error_everywhere(method):
    """The printed estimate is an upper bound of |T - T_exact| / T_exact (rounding included)
    at amplitudes from 0 to 89.9 deg, against the mpmath energy integral at 30 digits."""
    degrees = [0.0, 1e-6, 0.01, 0.5, 5.0, 17.0, 33.3, 50.0, 61.0, 75.0, 84.0, 89.9]
    if method == "ode":
        degrees = degrees[1::2]   # the integration costs tens of milliseconds each
    for r, angle in ((0.7, d) for d in degrees):
        result = run_scene("half-cylinder-shell", {"r": f"{r} m", "amplitude": f"{angle} deg"},
                           method=method)
        exact = float(shell_period_mpmath(r, G, math.radians(angle)))
        error = abs(result.results["T"].si / exact - 1)
        assert error <= result.extra["error_estimate"], (angle, error)
