"""dyncalc.physics.forced against independent solutions: the equation of motion integrated to
steady state with scipy (amplitude and phase fitted), the complex frequency response, peaks
found by numerical maximisation, half-power frequencies by root finding, the total response
against solve_ivp, and every closed form against mpmath at 50 digits in ulps."""
import math

import mpmath
import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar

from dyncalc.errors import InputError, PhysicsError
from dyncalc.physics import forced
from dyncalc.physics.forced import forced_response

KINDS = ("force", "base", "base-accel", "unbalance")
AMPLITUDE = {"force": ("F0", 3.0), "base": ("base", 0.02), "base-accel": ("base_accel", 1.5),
             "unbalance": ("unbalance", 0.01)}


def excitation(kind, k, m, c, W):
    """The right-hand side of m x'' + c x' + k x = rhs(t), written from the physics of each
    excitation (not from the module)."""
    a = AMPLITUDE[kind][1]
    if kind == "force":
        return lambda t: a * math.cos(W * t)
    if kind == "base":
        return lambda t: k * a * math.cos(W * t) - c * a * W * math.sin(W * t)
    if kind == "base-accel":
        return lambda t: -m * a * math.cos(W * t)
    return lambda t: a * W * W * math.cos(W * t)


def integrate(kind, k, m, c, W, x0=0.0, v0=0.0, t_end=None, t_eval=None):
    rhs = excitation(kind, k, m, c, W)

    def f(t, y):
        return [y[1], (rhs(t) - c * y[1] - k * y[0]) / m]

    return solve_ivp(f, (0.0, t_end), [x0, v0], method="DOP853", rtol=1e-12, atol=1e-15,
                     t_eval=t_eval, dense_output=t_eval is None)


def fitted(kind, k, m, c, W):
    """Steady amplitude and phase lag read off the integrated motion after the transient:
    a least-squares fit of a cos(Wt) + b sin(Wt) over five periods."""
    omega = math.sqrt(k / m)
    zeta = c / (2 * math.sqrt(k * m))
    slowest = zeta * omega if zeta < 1 else omega / (zeta + math.sqrt(zeta * zeta - 1))
    t0 = 40.0 / slowest
    ts = np.linspace(t0, t0 + 5 * 2 * math.pi / W, 400)
    sol = integrate(kind, k, m, c, W, t_end=ts[-1], t_eval=ts)
    basis = np.column_stack([np.cos(W * ts), np.sin(W * ts)])
    (a, b), *_ = np.linalg.lstsq(basis, sol.y[0], rcond=None)
    if kind == "base-accel":  # the relative motion answers -m B0 cos: lag behind that force
        a, b = -a, -b
    return math.hypot(a, b), math.atan2(b, a) % (2 * math.pi)


CASES = [(kind, zeta, eta) for kind in KINDS for zeta in (0.05, 0.3, 1.4)
         for eta in (0.4, 1.0, 2.7)]


@pytest.mark.parametrize("kind,zeta,eta", CASES)
def test_steady_amplitude_and_phase_match_the_integrated_motion(kind, zeta, eta):
    k, m = 800.0, 2.0
    omega = math.sqrt(k / m)
    c = 2 * zeta * math.sqrt(k * m)
    W = eta * omega
    name, value = AMPLITUDE[kind]
    out = forced_response(k=k, m=m, c=c, Omega=W, **{name: value}).values
    X, phi = fitted(kind, k, m, c, W)
    assert out["X"] == pytest.approx(X, rel=1e-7)
    assert out["phi"] == pytest.approx(phi, abs=1e-7)
    assert 0.0 <= out["phi"] <= math.pi


def frequency_response(kind, zeta, eta):
    """V (the module's normalisation) and TR from the complex frequency response."""
    h = 1.0 / complex(1 - eta * eta, 2 * zeta * eta)
    tr = abs(complex(1, 2 * zeta * eta) * h)
    v = {"force": abs(h), "base-accel": abs(h), "unbalance": eta * eta * abs(h), "base": tr}
    return v[kind], tr


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("zeta", [0.0, 0.01, 0.2, 0.5, 0.9, 3.0])
@pytest.mark.parametrize("eta", [0.1, 0.99, 1.3, math.sqrt(2), 10.0])
def test_magnification_and_transmissibility_match_the_complex_response(kind, zeta, eta):
    gap = forced.resonance_gap(eta, omega=1.0)
    v, tr = frequency_response(kind, zeta, eta)
    assert forced.magnification(kind, gap, zeta, eta) == pytest.approx(v, rel=1e-13)
    assert forced.transmissibility(gap, zeta, eta) == pytest.approx(tr, rel=1e-13)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("zeta", [0.001, 0.05, 0.2, 0.38, 0.5, 0.7])
def test_peak_is_the_numerical_maximum(kind, zeta):
    top = forced.peak(kind, zeta)
    assert top is not None
    eta_p, v_p = top

    def minus_v(log_eta):
        return -frequency_response(kind, zeta, math.exp(log_eta))[0]

    lo, hi = math.log(eta_p) - 0.5, math.log(eta_p) + 0.5
    best = minimize_scalar(minus_v, bounds=(lo, hi), method="bounded",
                           options={"xatol": 1e-12})
    assert math.exp(best.x) == pytest.approx(eta_p, rel=1e-5)
    assert -best.fun == pytest.approx(v_p, rel=1e-10)
    # and it is a maximum: larger than at the neighbours
    for step in (0.99, 1.01):
        assert frequency_response(kind, zeta, eta_p * step)[0] < v_p


def test_peaks_differ_by_excitation():
    zeta = 0.2
    etas = {kind: forced.peak(kind, zeta)[0] for kind in KINDS}
    assert etas["force"] == etas["base-accel"] == pytest.approx(math.sqrt(1 - 2 * zeta**2))
    assert etas["unbalance"] == pytest.approx(1 / math.sqrt(1 - 2 * zeta**2))
    assert etas["base"] == pytest.approx(math.sqrt(2 / (1 + math.sqrt(1 + 8 * zeta**2))))
    assert len(set(etas.values())) == 3


@pytest.mark.parametrize("kind", ["force", "base-accel", "unbalance"])
def test_no_peak_above_one_over_sqrt2(kind):
    assert forced.peak(kind, 0.71) is None
    assert forced.peak(kind, 0.0) is None
    assert forced.peak("base", 5.0) is not None  # base motion always peaks below omega


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("zeta", [1e-6, 0.01, 0.1, 0.3, 0.37])
def test_half_power_frequencies_are_where_v_is_peak_over_sqrt2(kind, zeta):
    eta_p, v_p = forced.peak(kind, zeta)
    low, high, width = forced.half_power(kind, zeta)
    target = v_p / math.sqrt(2)

    def g(eta):
        return frequency_response(kind, zeta, eta)[0] - target

    ref_low = brentq(g, 1e-9, eta_p, xtol=1e-15, rtol=1e-15)
    ref_high = brentq(g, eta_p, 1e6, xtol=1e-15, rtol=1e-15)
    assert low == pytest.approx(ref_low, rel=1e-8)
    assert high == pytest.approx(ref_high, rel=1e-8)
    assert width == pytest.approx(ref_high - ref_low, rel=max(1e-8, 1e-15 / zeta))


def test_half_power_width_is_not_two_zeta():
    low, high, width = forced.half_power("force", 0.2)
    assert width == pytest.approx(high - low, rel=1e-14)
    assert abs(width - 0.4) > 1e-3


@pytest.mark.parametrize("kind,lost", [("force", "low"), ("base-accel", "low"),
                                       ("unbalance", "high")])
def test_half_power_frequency_lost_above_0_38268(kind, lost):
    edge = math.sqrt((2 - math.sqrt(2)) / 4)
    below = forced.half_power(kind, edge * (1 - 1e-9))
    above = forced.half_power(kind, edge * (1 + 1e-9))
    assert None not in below
    assert above[2] is None
    assert (above[0] is None) == (lost == "low") and (above[1] is None) == (lost == "high")


def test_base_lower_half_power_frequency_lost_when_the_peak_is_low():
    # TR_peak <= sqrt 2: the half-power level is below TR(0) = 1
    low, high, width = forced.half_power("base", 1.0)
    assert low is None and width is None and high is not None
    v = frequency_response("base", 1.0, high)[0]
    assert v == pytest.approx(forced.peak("base", 1.0)[1] / math.sqrt(2), rel=1e-12)


# --- accuracy against mpmath --------------------------------------------------------------

MPMATH_DPS = 50  # mpmath's digits in this module's tests (tests/conftest.py)


def ulps(got, exact):
    exact = float(exact)
    if got == exact:
        return 0
    return abs(got - exact) / math.ulp(exact)


def reference(kind, k, m, zeta, W, amp):
    k, m, z, W, a = (mpmath.mpf(v) for v in (k, m, zeta, W, amp))
    omega = mpmath.sqrt(k / m)
    eta = W / omega
    d = mpmath.sqrt((1 - eta**2) ** 2 + (2 * z * eta) ** 2)
    tr = mpmath.sqrt(1 + (2 * z * eta) ** 2) / d
    if kind == "base":
        phi = mpmath.atan2(2 * z * eta**3, 1 - eta**2 + (2 * z * eta) ** 2)
        x = a * tr
    else:
        phi = mpmath.atan2(2 * z * eta, 1 - eta**2)
        static = {"force": a / k, "base-accel": a * m / k, "unbalance": a / m}[kind]
        x = static * (eta**2 if kind == "unbalance" else 1) / d
    return {"X": x, "phi": phi, "TR": tr, "eta": eta, "omega": omega}


EXTREMES = []
for scale in (1e-300, 1e-150, 1.0, 1e150, 1e300):
    for zeta in (1e-12, 1e-9, 0.3, 10.0):
        for eta_shift in (-1e-12, 1e-12, -0.5, 3.0):
            EXTREMES.append((scale, zeta, eta_shift))


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("scale,zeta,shift", EXTREMES)
def test_accuracy_in_ulps_against_mpmath(kind, scale, zeta, shift):
    """k and m scaled together over 1e-300..1e300 (omega stays 3 rad/s), eta = 1 +- 1e-12 and
    far from resonance, zeta from 1e-12 to 10: X, phi, TR within a few ulp of the 50-digit
    value from the same float inputs."""
    k, m = 9.0 * scale, 1.0 * scale
    W = 3.0 * (1.0 + shift)
    amp = {"force": 2.0 * scale, "base": 0.01, "base-accel": 0.7, "unbalance": 0.05 * scale}
    name = AMPLITUDE[kind][0]
    out = forced_response(k=k, m=m, zeta=zeta, Omega=W, **{name: amp[kind]}).values
    ref = reference(kind, k, m, zeta, W, amp[kind])
    assert ulps(out["X"], ref["X"]) <= 8
    assert ulps(out["phi"], ref["phi"]) <= 8
    assert ulps(out["TR"], ref["TR"]) <= 8


@pytest.mark.parametrize("omega_scale", [1e-150, 1.0, 1e150])
def test_accuracy_when_omega_itself_is_extreme(omega_scale):
    """k scaled, m fixed: omega from 1e-75 to 1e75, the excitation 1e-12 off it."""
    k, m = 4.0 * omega_scale, 1.0
    omega = 2.0 * math.sqrt(omega_scale)
    W = omega * (1 + 1e-12)
    out = forced_response(k=k, m=m, zeta=1e-9, Omega=W, F0=1.0).values
    ref = reference("force", k, m, 1e-9, W, 1.0)
    for name in ("X", "phi", "TR"):
        assert ulps(out[name], ref[name]) <= 8, name


def test_near_resonance_the_exact_gap_is_needed():
    """eta = 1 + 1e-12 from k = 2, m = 1: eta rounded to a float, then (1 - eta)(1 + eta),
    loses digits of the gap that forming k - m Omega^2 exactly keeps."""
    k, m = 2.0, 1.0
    W = math.sqrt(2.0) * (1 + 1e-12)
    out = forced_response(k=k, m=m, zeta=1e-15, Omega=W, F0=1.0).values
    ref = reference("force", k, m, 1e-15, W, 1.0)
    eta = W / math.sqrt(k / m)
    naive = (1.0 / k) / math.hypot((1 - eta) * (1 + eta), 2e-15 * eta)
    assert ulps(out["X"], ref["X"]) <= 4
    assert ulps(naive, ref["X"]) > 1000


# --- total response -----------------------------------------------------------------------

@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("zeta", [0.0, 0.1, 1.0, 2.5])
@pytest.mark.parametrize("t", [0.0, 0.37, 2.9])
def test_total_response_matches_solve_ivp(kind, zeta, t):
    k, m, W = 50.0, 2.0, 3.3
    c = 2 * zeta * math.sqrt(k * m)
    x0, v0 = 0.004, -0.03
    name, value = AMPLITUDE[kind]
    out = forced_response(k=k, m=m, c=c, Omega=W, x0=x0, v0=v0, t=t, **{name: value}).values
    if t == 0.0:
        assert out["x"] == pytest.approx(x0, rel=1e-13)
        return
    sol = integrate(kind, k, m, c, W, x0=x0, v0=v0, t_end=t)
    assert out["x"] == pytest.approx(sol.sol(t)[0], rel=1e-8, abs=1e-12)


@pytest.mark.parametrize("kind", KINDS)
def test_undamped_resonance_grows_linearly_as_integrated(kind):
    k, m = 49.0, 1.0
    W = 7.0
    name, value = AMPLITUDE[kind]
    xs = []
    for t in (3.0, 30.0):
        out = forced_response(k=k, m=m, Omega=W, x0=0.001, v0=0.0, t=t,
                              **{name: value}).values
        sol = integrate(kind, k, m, 0.0, W, x0=0.001, t_end=t)
        assert out["x"] == pytest.approx(sol.sol(t)[0], rel=1e-8, abs=1e-12)
        assert set(out) == {"omega", "zeta", "eta", "x"}
        xs.append(out)


def test_undamped_resonance_steady_state_refused():
    with pytest.raises(PhysicsError) as info:
        forced_response(k=49.0, m=1.0, Omega=7.0, F0=1.0)
    assert str(info.value) == (
        "undamped at resonance (Omega = omega = 7 rad/s): the steady state does not exist, "
        "the amplitude grows without bound; give damping (zeta, c or Q), another excitation "
        "frequency, or a time t for the growing response")


def test_critical_and_overdamped_transients_are_continuous_in_zeta():
    near = [forced.transient(3.0, z, 0.2, -1.0, 0.8) for z in (1 - 1e-7, 1.0, 1 + 1e-7)]
    assert near[0] == pytest.approx(near[1], abs=1e-7)
    assert near[2] == pytest.approx(near[1], abs=1e-7)


# --- the other results ----------------------------------------------------------------------

def test_isolation_above_sqrt2_omega_only():
    below = forced_response(k=100.0, m=1.0, zeta=0.1, Omega=14.0, F0=1.0).values
    above = forced_response(k=100.0, m=1.0, zeta=0.1, Omega=14.2, F0=1.0).values
    assert below["Omega_iso"] == pytest.approx(10 * math.sqrt(2), rel=1e-15)
    assert "isolation" not in below and below["TR"] > 1
    assert above["isolation"] == pytest.approx(1 - above["TR"], rel=1e-15)


def test_resonance_values_and_q():
    out = forced_response(k=100.0, m=1.0, zeta=0.05, Omega=3.0, F0=2.0).values
    assert out["V_res"] == pytest.approx(10.0, rel=1e-15)
    assert out["X_res"] == pytest.approx(2.0 / 100.0 * 10.0, rel=1e-15)
    assert out["Q"] == pytest.approx(10.0, rel=1e-15)
    base = forced_response(k=100.0, m=1.0, zeta=0.05, Omega=3.0, base=0.01).values
    assert base["V_res"] == pytest.approx(math.sqrt(1 + 0.01) / 0.1, rel=1e-14)


def test_transmitted_force_is_the_spring_and_damper_force():
    """F_T against the amplitude of k x + c x' (force) and of k z + c z' (base motion) from
    the integrated motion."""
    k, m, zeta, W = 800.0, 2.0, 0.1, 30.0
    c = 2 * zeta * math.sqrt(k * m)
    force = forced_response(k=k, m=m, zeta=zeta, Omega=W, F0=3.0).values
    X, _ = fitted("force", k, m, c, W)
    assert force["F_T"] == pytest.approx(X * math.hypot(k, c * W), rel=1e-7)
    base = forced_response(k=k, m=m, zeta=zeta, Omega=W, base=0.02).values
    assert base["F_T"] == pytest.approx(m * W * W * base["X"], rel=1e-14)
    assert base["Z"] == pytest.approx(abs(base["X"] * complex(math.cos(base["phi"]),
                                                                -math.sin(base["phi"])) - 0.02),
                                      rel=1e-12)


def test_omega_without_mass_leaves_out_what_needs_it():
    out = forced_response(omega=10.0, zeta=0.1, Omega=5.0, F0=1.0)
    assert "X" not in out.values and "TR" in out.values and "V" in out.values
    assert out.warnings[0] == "X need the mass: give m (with omega, or k and m)"


def test_bad_combinations_are_refused():
    with pytest.raises(InputError, match="exactly one excitation"):
        forced_response(k=1.0, m=1.0, Omega=2.0, F0=1.0, base=1.0)
    with pytest.raises(InputError, match="k needs m"):
        forced_response(k=1.0, Omega=2.0, F0=1.0)
