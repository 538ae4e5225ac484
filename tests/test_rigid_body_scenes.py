"""The rigid-body scenes against independent derivations: Newton-Euler for each body solved as
a linear system here, Lagrange's equations by sympy, a numerical integration of the drum with
elastic ropes, the momentum and energy balances of the impact, the impulse-momentum equations
of the double pendulum; the textbook's closed forms (E3.46, E4.10); unit invariance."""
from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

from dyncalc.scenes.runner import run_scene

G = 9.80665


def run(scene: str, **texts) -> dict[str, float]:
    result = run_scene(scene, {k: str(v) for k, v in texts.items()}, command="rigid-body")
    return {name: entry.si for name, entry in result.results.items()}


RNG = np.random.default_rng(21)
DRUMS = [dict(m1=float(a), m2=float(b), r1=float(c), r2=float(d), J_A=float(e))
         for a, b, c, d, e in RNG.uniform([1, 1, 0.05, 0.05, 0.0], [50, 50, 0.5, 0.5, 5],
                                          (6, 5))]


# --- drum-two-blocks (E4.10) -------------------------------------------------------------------

@pytest.mark.parametrize("p", DRUMS)
def test_drum_two_blocks_newton_euler(p):
    """Each body on its own: m1 a1 = S1 - m1 g, m2 a2 = m2 g - S2, J_A alpha = S2 r2 - S1 r1,
    a1 = r1 alpha, a2 = r2 alpha; unknowns alpha, S1, S2."""
    m1, m2, r1, r2, J = p["m1"], p["m2"], p["r1"], p["r2"], p["J_A"]
    A = np.array([[m1 * r1, -1.0, 0.0], [m2 * r2, 0.0, 1.0], [J, r1, -r2]])
    alpha, S1, S2 = np.linalg.solve(A, [-m1 * G, m2 * G, 0.0])
    got = run("drum-two-blocks", **p)
    assert got["alpha"] == pytest.approx(alpha, rel=1e-12)
    assert got["a1"] == pytest.approx(r1 * alpha, rel=1e-12)
    assert got["a2"] == pytest.approx(r2 * alpha, rel=1e-12)
    assert got["S1"] == pytest.approx(S1, rel=1e-12)
    assert got["S2"] == pytest.approx(S2, rel=1e-12)


def _lagrange(T, V, q, Q=0):
    """q'' from Lagrange's equation d/dt dT/dq' - dT/dq + dV/dq = Q (one coordinate)."""
    t = sp.Symbol("t")
    x = sp.Function("x")(t)
    T, V = T.subs(q[1], x.diff(t)).subs(q[0], x), V.subs(q[0], x)
    eq = sp.diff(T.diff(x.diff(t)), t) - T.diff(x) + V.diff(x) - Q
    return sp.solve(eq, x.diff(t, 2))[0]


def test_drum_two_blocks_lagrange_by_sympy():
    phi, dphi, m1, m2, r1, r2, J, g = sp.symbols("phi dphi m1 m2 r1 r2 J g", positive=True)
    T = (J + m1 * r1 ** 2 + m2 * r2 ** 2) * dphi ** 2 / 2
    V = (m1 * r1 - m2 * r2) * g * phi
    acc = _lagrange(T, V, (phi, dphi))
    for p in DRUMS:
        value = float(acc.subs({m1: p["m1"], m2: p["m2"], r1: p["r1"], r2: p["r2"],
                                J: p["J_A"], g: G}))
        assert run("drum-two-blocks", **p)["alpha"] == pytest.approx(value, rel=1e-12)


def test_drum_two_blocks_textbook_forms_and_balance():
    """E4.10's rope forces in the book's closed form; static balance at m1 r1 = m2 r2."""
    p = dict(m1=20.0, m2=15.0, r1=0.2, r2=0.4, J_A=2.0)
    D = 2.0 + 20.0 * 0.04 + 15.0 * 0.16
    got = run("drum-two-blocks", **p)
    assert got["S1"] == pytest.approx(20.0 * G * (0.4 * 0.6 * 15.0 + 2.0) / D, rel=1e-14)
    assert got["S2"] == pytest.approx(15.0 * G * (0.2 * 0.6 * 20.0 + 2.0) / D, rel=1e-14)
    balanced = run_scene("drum-two-blocks", {"m1": "20", "m2": "10", "r1": "0.2", "r2": "0.4",
                                             "J_A": "2"})
    assert balanced.warnings == []  # an exact zero, not an underflow
    still = {name: entry.si for name, entry in balanced.results.items()}
    assert still["alpha"] == 0.0 and still["S1"] == pytest.approx(20 * G, rel=1e-15)


def test_drum_two_blocks_numerical_integration_with_elastic_ropes():
    """The drum and both blocks as three free bodies joined by stiff damped ropes (solve_ivp,
    Radau): block 2's fall over 1 s matches a2 t^2/2 and the mean rope force S2."""
    from scipy.integrate import solve_ivp

    m1, m2, r1, r2, J = 20.0, 15.0, 0.2, 0.4, 2.0
    k, c = 1e7, 2e4

    def rhs(_t, y):
        phi, y1, y2, dphi, dy1, dy2 = y
        S1 = k * (r1 * phi - y1) + c * (r1 * dphi - dy1)
        S2 = k * (y2 - r2 * phi) + c * (dy2 - r2 * dphi)
        return [dphi, dy1, dy2, (S2 * r2 - S1 * r1) / J, S1 / m1 - G, G - S2 / m2]

    got = run("drum-two-blocks", m1=m1, m2=m2, r1=r1, r2=r2, J_A=J)
    y0 = [0.0, -got["S1"] / k, got["S2"] / k, 0.0, 0.0, 0.0]  # ropes stretched as at t = 0+
    sol = solve_ivp(rhs, (0.0, 1.0), y0, method="Radau", rtol=1e-10, atol=1e-13)
    assert sol.success
    assert sol.y[2, -1] - y0[2] == pytest.approx(got["a2"] / 2.0, rel=1e-5)
    assert sol.y[0, -1] == pytest.approx(got["alpha"] / 2.0, rel=1e-5)


# --- wheel-incline-block (E4.12) ---------------------------------------------------------------

WHEELS = [dict(m1=20.0, m2=15.0, beta=0.5, J_A=0.4, r=0.2),
          dict(m1=5.0, m2=1.0, beta=0.9, J_A=0.1, r=0.3),     # the wheel rolls down
          dict(m1=3.0, m2=8.0, beta=-0.2, J_A=0.02, r=0.1)]


@pytest.mark.parametrize("p", WHEELS)
def test_wheel_incline_block_newton_euler(p):
    """Wheel along the slope m1 a = S - m1 g sin(beta) - H, about its centre J_A a / r = H r
    (rolling), block m2 a = m2 g - S; unknowns a, S, H."""
    m1, m2, b, J, r = p["m1"], p["m2"], p["beta"], p["J_A"], p["r"]
    A = np.array([[m1, -1.0, 1.0], [J / r, 0.0, -r], [m2, 1.0, 0.0]])
    a, S, H = np.linalg.solve(A, [-m1 * G * math.sin(b), 0.0, m2 * G])
    got = run("wheel-incline-block", **{**p, "beta": f"{b} rad"})
    assert got["a"] == pytest.approx(a, rel=1e-12)
    assert got["S"] == pytest.approx(S, rel=1e-12)
    assert got["H"] == pytest.approx(H, rel=1e-12)
    assert got["N"] == pytest.approx(m1 * G * math.cos(b), rel=1e-14)
    assert got["mu_min"] == pytest.approx(abs(H) / (m1 * G * math.cos(b)), rel=1e-12)


def test_wheel_incline_block_lagrange_by_sympy_and_kappa_form():
    x, dx, m1, m2, b, k, g = sp.symbols("x dx m1 m2 beta kappa g")
    T = ((1 + k) * m1 + m2) * dx ** 2 / 2
    V = (m1 * sp.sin(b) - m2) * g * x
    acc = _lagrange(T, V, (x, dx))
    for body, kappa in (("solid-cylinder", 0.5), ("hoop", 1.0), ("solid-sphere", 0.4)):
        value = float(acc.subs({m1: 7.0, m2: 4.0, b: 0.3, k: kappa, g: G}))
        got = run("wheel-incline-block", m1=7.0, m2=4.0, beta="0.3 rad", body=body)
        assert got["a"] == pytest.approx(value, rel=1e-12), body
        # J_A = kappa m1 r^2 with any r gives the same answer
        same = run("wheel-incline-block", m1=7.0, m2=4.0, beta="0.3 rad",
                   J_A=kappa * 7.0 * 0.25 ** 2, r=0.25)
        assert same["a"] == pytest.approx(value, rel=1e-12), body


# --- two-drums-rope-drive (E4.13) --------------------------------------------------------------

DRIVES = [dict(m1=10.0, m2=20.0, r1=0.3, r2=0.2, J1=1.5, J2=0.8, M0=50.0),
          dict(m1=40.0, m2=5.0, r1=0.5, r2=0.1, J1=0.3, J2=0.2, M0=-3.0)]


@pytest.mark.parametrize("p", DRIVES)
def test_two_drums_newton_euler(p):
    """Block 1 m1 a1 = S1 - m1 g, block 2 m2 a2 = m2 g - S2, drum 1 J1 alpha = M0 - S1 r1 -
    T r2, drum 2 J2 alpha = T r2 + S2 r2 (T the coupling rope), a1 = r1 alpha, a2 = r2 alpha;
    unknowns alpha, S1, S2, T."""
    m1, m2, r1, r2, J1, J2, M0 = (p[n] for n in ("m1", "m2", "r1", "r2", "J1", "J2", "M0"))
    A = np.array([[m1 * r1, -1.0, 0.0, 0.0], [m2 * r2, 0.0, 1.0, 0.0],
                  [J1, r1, 0.0, r2], [J2, 0.0, -r2, -r2]])
    alpha, S1, S2, _T = np.linalg.solve(A, [-m1 * G, m2 * G, M0, 0.0])
    got = run("two-drums-rope-drive", **p)
    assert got["alpha"] == pytest.approx(alpha, rel=1e-12)
    assert got["a2"] == pytest.approx(r2 * alpha, rel=1e-12)
    assert got["a1"] == pytest.approx(r1 * alpha, rel=1e-12)
    assert got["S1"] == pytest.approx(S1, rel=1e-12)
    assert got["S2"] == pytest.approx(S2, rel=1e-12)


def test_two_drums_lagrange_by_sympy():
    x, dx, m1, m2, r1, r2, J1, J2, M0, g = sp.symbols("x dx m1 m2 r1 r2 J1 J2 M0 g")
    T = (m2 * dx ** 2 + m1 * (r1 / r2 * dx) ** 2 + (J1 + J2) * (dx / r2) ** 2) / 2
    V = (m1 * r1 / r2 - m2) * g * x
    acc = _lagrange(T, V, (x, dx), Q=M0 / r2)
    for p in DRIVES:
        value = float(acc.subs({m1: p["m1"], m2: p["m2"], r1: p["r1"], r2: p["r2"],
                                J1: p["J1"], J2: p["J2"], M0: p["M0"], g: G}))
        assert run("two-drums-rope-drive", **p)["a2"] == pytest.approx(value, rel=1e-12)


def test_two_drums_warn_when_a_rope_goes_slack():
    result = run_scene("two-drums-rope-drive", {"m1": "10kg", "m2": "20kg", "r1": "0.3m",
                                                "r2": "0.2m", "J1": "0", "J2": "0",
                                                "M0": "500 N*m"})
    a2 = result.results["a2"].si
    assert a2 > G and result.results["S2"].si < 0
    assert result.warnings == [f"the rope of block 2 goes slack: a2 = {a2:.6g} m/s^2 exceeds "
                               "g; block 2 falls freely and these results do not hold"]
    down = run_scene("two-drums-rope-drive", {"m1": "10kg", "m2": "1kg", "r1": "0.3m",
                                              "r2": "0.2m", "J1": "0", "J2": "0",
                                              "M0": "-500 N*m"})
    a1 = down.results["a1"].si
    assert a1 < -G
    assert down.warnings == [f"the rope of block 1 goes slack: a1 = {a1:.6g} m/s^2 is below "
                             "-g; block 1 falls freely and these results do not hold"]


# --- direct-central-impact ---------------------------------------------------------------------

@pytest.mark.parametrize("m1, m2, v1, v2, e", [(2.0, 3.0, 4.0, -1.0, 0.6), (1.0, 1.0, 2.0, 0.0, 1.0),
                                              (5.0, 0.5, -1.0, -7.0, 0.0),
                                              (0.1, 80.0, 30.0, 0.0, 0.3)])
def test_impact_balances(m1, m2, v1, v2, e):
    """Momentum conserved; separation speed e times approach speed; the energy lost equals
    the difference of the kinetic energies; the impulse changes each body's momentum; the
    compression impulse (to the common velocity) times (1 + e)."""
    got = run("direct-central-impact", m1=m1, m2=m2, v1=v1, v2=v2, e=e)
    w1, w2 = got["v1_post"], got["v2_post"]
    assert m1 * w1 + m2 * w2 == pytest.approx(m1 * v1 + m2 * v2, rel=1e-12, abs=1e-12)
    assert w2 - w1 == pytest.approx(e * (v1 - v2), rel=1e-12, abs=1e-12)
    lost = (m1 * v1 ** 2 + m2 * v2 ** 2 - m1 * w1 ** 2 - m2 * w2 ** 2) / 2
    assert got["dE"] == pytest.approx(lost, rel=1e-9, abs=1e-12)
    assert got["F_hat"] == pytest.approx(m2 * (w2 - v2), rel=1e-12)
    assert got["F_hat"] == pytest.approx(m1 * (v1 - w1), rel=1e-12)
    compression = m1 * (v1 - got["v_c"])
    assert got["F_hat"] == pytest.approx((1 + e) * compression, rel=1e-12)
    assert (got["dE"] == 0.0) == (e == 1.0)


# --- double-pendulum-impulse (E3.46) -----------------------------------------------------------

def _impulse_system(m, l, F, d):
    """Impulse-momentum with unknowns omega_1, omega_2, B, A: bar 1 about A (m l^2/3)
    omega_1 = B l; bar 2: m v_2 = F - B, about its centre (m l^2/12) omega_2 = F (l/2 - d)
    + B l/2, v_2 = l omega_1 + (l/2) omega_2; bar 1's momentum m (l/2) omega_1 = A + B."""
    A = np.array([[m * l * l / 3, 0.0, -l, 0.0],
                  [m * l, m * l / 2, 1.0, 0.0],
                  [0.0, m * l * l / 12, -l / 2, 0.0],
                  [m * l / 2, 0.0, -1.0, -1.0]])
    return np.linalg.solve(A, [0.0, F, F * (l / 2 - d), 0.0])


@pytest.mark.parametrize("d", [0.0, 0.1, 0.4, 0.75, 1.0, 1.2])
def test_double_pendulum_impulse_as_a_linear_system(d):
    m, l, F = 3.0, 1.2, 12.0
    w1, w2, B, A = _impulse_system(m, l, F, d)
    got = run("double-pendulum-impulse", m=m, l=l, F_hat=F, d=d)
    assert got["omega_1"] == pytest.approx(w1, rel=1e-12, abs=1e-14)
    assert got["omega_2"] == pytest.approx(w2, rel=1e-12, abs=1e-14)
    assert got["B_hat"] == pytest.approx(B, rel=1e-12, abs=1e-14)
    assert got["A_hat"] == pytest.approx(A, rel=1e-12, abs=1e-14)
    assert got["v_2"] == pytest.approx(l * w1 + l * w2 / 2, rel=1e-12)


def test_double_pendulum_impulse_textbook_answers_at_d0():
    """E3.46: at d_0 = 5l/8 (the default) omega_1 = 3F/(4ml), omega_2 = 0, B = F/4, A = F/8;
    at d_A0 = l/3 neither pin takes an impulse."""
    m, l, F = 2.5, 0.8, 7.0
    got = run("double-pendulum-impulse", m=m, l=l, F_hat=F)
    assert got["omega_1"] == pytest.approx(3 * F / (4 * m * l), rel=1e-14)
    assert got["omega_2"] == 0.0
    assert got["B_hat"] == pytest.approx(F / 4, rel=1e-14)
    assert got["A_hat"] == pytest.approx(F / 8, rel=1e-14)
    assert got["d_0"] == pytest.approx(5 * l / 8, rel=1e-15)
    free = run("double-pendulum-impulse", m=m, l=l, F_hat=F, d=got["d_A0"])
    assert free["A_hat"] == pytest.approx(0.0, abs=1e-14)
    assert free["B_hat"] == pytest.approx(0.0, abs=1e-14)


# --- unit invariance (lb, in, lbf) -------------------------------------------------------------

LB, INCH, LBF = 0.45359237, 0.0254, 4.4482216152605


@pytest.mark.parametrize("scene, si, imperial", [
    ("drum-two-blocks", dict(m1="20 kg", m2="15 kg", r1="0.2 m", r2="0.4 m", J_A="2 kg*m^2"),
     dict(m1=f"{20 / LB!r} lb", m2=f"{15 / LB!r} lb", r1=f"{0.2 / INCH!r} in",
          r2=f"{0.4 / INCH!r} in", J_A=f"{2 / (LB * INCH ** 2)!r} lb*in^2")),
    ("two-drums-rope-drive", dict(m1="10kg", m2="20kg", r1="0.3m", r2="0.2m",
                                  J1="1.5 kg*m^2", J2="0.8 kg*m^2", M0="50 N*m"),
     dict(m1=f"{10 / LB!r} lb", m2=f"{20 / LB!r} lb", r1=f"{0.3 / INCH!r} in",
          r2=f"{0.2 / INCH!r} in", J1=f"{1.5 / (LB * INCH ** 2)!r} lb*in^2",
          J2=f"{0.8 / (LB * INCH ** 2)!r} lb*in^2", M0=f"{50 / (LBF * INCH)!r} lbf*in")),
    ("double-pendulum-impulse", dict(m="3kg", l="1.2m", F_hat="12 N*s", d="0.3m"),
     dict(m=f"{3 / LB!r} lb", l=f"{1.2 / INCH!r} in", F_hat=f"{12 / LBF!r} lbf*s",
          d=f"{0.3 / INCH!r} in")),
])
def test_unit_invariance_in_pounds_and_inches(scene, si, imperial):
    base, other = run(scene, **si), run(scene, **imperial)
    for name, value in base.items():
        assert other[name] == pytest.approx(value, rel=1e-12, abs=1e-300), name
