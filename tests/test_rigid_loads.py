"""Physics of the rigid-body load scenes (dyncalc/physics/kinetics_loads.py, euler_bearing.py)
against derivations made here independently: the angled bar from its inertia tensor (dyncalc
inertia's bodies and a direct sum) and Newton-Euler with the bearing equilibrium solved as a
linear system; the precessing shaft from dH/dt of H = R J R^T w differentiated numerically in
the fixed frame; the beam and the arm from integrating their distributed loads with quad."""
import math

import numpy as np
import pytest
from scipy.integrate import quad

from dyncalc.errors import InputError
from dyncalc.physics.euler_bearing import precessing_shaft
from dyncalc.physics.inertia_tensor import composite, placed
from dyncalc.physics.kinetics_loads import (angled_bar_on_shaft, arm_leg_a, arm_leg_b,
                                            beam_spun_up, rotating_angled_arm)
from dyncalc.units import Q_


# --- angled-bar-on-shaft (E3.41) ------------------------------------------------------------

def _bar_tensor(m, l):
    """J_O of the bent bar from dyncalc inertia's rods (xi, eta, zeta = x, y, z)."""
    legs = [placed("rod", 2 * m / 3, {"l": 2 * l}, at=(l, 0, 0), along=(1, 0, 0)),
            placed("rod", m / 3, {"l": l}, at=(2 * l, 0, l / 2), along=(0, 0, 1))]
    return composite(legs)


def _bar_tensor_by_sum(m, l, n=4000):
    """J_O = sum dm (|r|^2 I - r r^T) over the two legs, midpoint rule (exact for a line of
    points up to O(1/n^2) in the rod's own moment)."""
    mu = m / (3 * l)
    J = np.zeros((3, 3))
    for start, direction, length in (((0, 0, 0), (1, 0, 0), 2 * l), ((2 * l, 0, 0), (0, 0, 1), l)):
        ds = length / n
        for i in range(n):
            r = np.array(start, float) + (i + 0.5) * ds * np.array(direction, float)
            J += mu * ds * (r @ r * np.eye(3) - np.outer(r, r))
    return J


def test_bar_inertia_data_of_scenes_md():
    m, l = 3.0, 0.5
    body = _bar_tensor(m, l)
    assert body.J_O[2, 2] == pytest.approx(20 * m * l * l / 9, rel=1e-14)
    assert body.J_O[0, 2] == pytest.approx(-m * l * l / 3, rel=1e-14)
    assert body.r_c[0] == pytest.approx(4 * l / 3, rel=1e-14)
    assert body.r_c[2] == pytest.approx(l / 6, rel=1e-14)
    assert _bar_tensor_by_sum(m, l) == pytest.approx(body.J_O, rel=1e-6, abs=1e-9)


def bar_by_newton_euler(m, l, M0, omega, J, c):
    """Unknowns A_xi, A_eta, B_xi, B_eta, alpha: Newton (2 eqs), Euler about O (3 eqs) with
    the tensor J about O and the centre c, bearings at zeta = +-2l; returns them by name."""
    # Euler about O: sum of moments = J alpha + w x (J w), w = omega e_z, alpha e_z unknown.
    # Moments: r_A x A + r_B x B + M0 e_z; r_A = (0,0,2l), r_B = (0,0,-2l)
    w = np.array([0.0, 0.0, omega])
    gyro = np.cross(w, J @ w)
    rows, rhs = [], []
    # Newton: A + B = m (alpha e_z x c - omega^2 c_perp)
    rows += [[1, 0, 1, 0, 0], [0, 1, 0, 1, -m * c[0]]]
    rhs += [-m * omega ** 2 * c[0], 0.0]
    # moment of a force F at (0, 0, z): (-z F_eta, z F_xi, 0)
    rows += [[0, -2 * l, 0, 2 * l, -J[0, 2]], [2 * l, 0, -2 * l, 0, -J[1, 2]],
             [0, 0, 0, 0, -J[2, 2]]]
    rhs += [gyro[0], gyro[1], gyro[2] - M0]
    solved = np.linalg.solve(np.array(rows, float), np.array(rhs))
    return dict(zip(("A_xi", "A_eta", "B_xi", "B_eta", "alpha"), map(float, solved)))


@pytest.mark.parametrize("m, l, M0, omega", [(3.0, 0.5, 10.0, 2.0), (7.5, 1.3, -4.0, -11.0),
                                             (0.2, 0.05, 0.3, 0.0)])
def test_bar_against_newton_euler_linear_system(m, l, M0, omega):
    body = _bar_tensor(m, l)
    c = body.r_c
    ref = bar_by_newton_euler(m, l, M0, omega, body.J_O, c)
    A_xi, A_eta, B_xi, B_eta, alpha = (ref[n] for n in ("A_xi", "A_eta", "B_xi", "B_eta",
                                                        "alpha"))
    out = angled_bar_on_shaft(Q_(m, "kg"), Q_(l, "m"), Q_(M0, "N*m"), Q_(omega, "rad/s")).values
    scale = abs(M0) / l + m * l * omega ** 2
    for name, value in (("A_xi", A_xi), ("A_eta", A_eta), ("B_xi", B_xi), ("B_eta", B_eta)):
        assert out[name] == pytest.approx(value, rel=1e-12, abs=1e-13 * scale), name
    assert out["alpha"] == pytest.approx(alpha, rel=1e-13)
    # the checks of SCENES.md
    assert out["A_xi"] + out["B_xi"] == pytest.approx(-m * c[0] * omega ** 2, abs=1e-12 * scale)
    assert out["A_eta"] + out["B_eta"] == pytest.approx(m * c[0] * out["alpha"], rel=1e-13)


def test_bar_textbook_fractions_and_units():
    out = angled_bar_on_shaft(Q_(3, "kg"), Q_(50, "cm"), Q_(10, "N*m"), Q_(2, "rad/s")).values
    assert out == pytest.approx({"alpha": 9 * 10 / (20 * 3 * 0.25), "A_xi": -0.75 * 3 * 0.5 * 4,
                                 "A_eta": 27 * 10 / 40, "B_xi": -7 * 3 * 0.5 * 4 / 12,
                                 "B_eta": 21 * 10 / 40}, rel=1e-15)
    inch = angled_bar_on_shaft(Q_(3 / 0.45359237, "lb"), Q_(0.5 / 0.0254, "inch"),
                               Q_(10, "N*m"), Q_(2 * 60 / (2 * math.pi), "rpm")).values
    assert inch == pytest.approx(out, rel=1e-13)


# --- precessing-shaft (E3.42) ---------------------------------------------------------------

def _Rz(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


def _Rx(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0, 0], [0, c, -s], [0, s, c]])


_CENTRAL8 = (1 / 280, -4 / 105, 1 / 5, -4 / 5, 0.0, 4 / 5, -1 / 5, 4 / 105, -1 / 280)


def _moment_by_dH_dt(J1, J2, J3, omega0, alpha, psi0, t0, h=2e-3):
    """dH/dt in the fixed frame (eighth-order central differences), in turning-frame axes.
    The body's principal axes are the turning frame's turned by psi = psi0 + omega0 (t - t0)
    about axis 1; the turning frame is turned by alpha(t) about z."""
    def H(t):
        a, psi = alpha(t), psi0 + omega0 * (t - t0)
        R = _Rz(a) @ _Rx(psi)
        w = _Rz(a) @ np.array([omega0, 0.0, 0.0]) + np.array([0, 0, _rate(alpha, t)])
        return R @ np.diag([J1, J2, J3]) @ R.T @ w

    dH = sum(c * H(t0 + (i - 4) * h) for i, c in enumerate(_CENTRAL8)) / h
    return _Rz(alpha(t0)).T @ dH


def _rate(alpha, t):
    """alpha'(t) by the same eighth-order stencil, step 1e-4."""
    h = 1e-4
    return sum(c * alpha(t + (i - 4) * h) for i, c in enumerate(_CENTRAL8)) / h


@pytest.mark.parametrize("J1, J2, J3, omega0, psi", [
    (0.02, 0.5, 0.5, 100.0, 0.0), (0.3, 0.9, 0.5, 7.0, 0.7), (0.3, 0.4, 1.1, -5.0, 2.2),
    (0.05, 0.2, 0.6, 12.0, -1.0)])
def test_harmonic_turning_against_dH_dt(J1, J2, J3, omega0, psi):
    a0, W, t = 0.4, 3.0, 0.35
    out = precessing_shaft(Q_(J1, "kg*m^2"), Q_(J3, "kg*m^2"), Q_(omega0, "rad/s"),
                           Q_(W, "rad/s"), J2=Q_(J2, "kg*m^2"), alpha0=Q_(a0, "rad"),
                           t=Q_(t, "s"), psi=Q_(psi, "rad")).values
    M = _moment_by_dH_dt(J1, J2, J3, omega0, lambda s: a0 * math.sin(W * s), psi, t)
    scale = max(J1, J2, J3) * (abs(omega0) * a0 * W + a0 * W * W + (a0 * W) ** 2)
    for i, name in enumerate(("M1", "M2", "M3")):
        assert out[name] == pytest.approx(M[i], abs=1e-8 * scale), name


@pytest.mark.parametrize("psi", [0.0, 0.4, 1.9])
def test_uniform_turning_against_dH_dt(psi):
    J1, J2, J3, omega0, W = 0.1, 0.7, 0.45, 30.0, 2.5
    out = precessing_shaft(Q_(J1, "kg*m^2"), Q_(J3, "kg*m^2"), Q_(omega0, "rad/s"),
                           Q_(W, "rad/s"), J2=Q_(J2, "kg*m^2"), psi=Q_(psi, "rad")).values
    M = _moment_by_dH_dt(J1, J2, J3, omega0, lambda s: W * s, psi, 0.8)
    for i, name in enumerate(("M1", "M2", "M3")):
        assert out[name] == pytest.approx(M[i], abs=1e-8 * J2 * omega0 * W), name
    # at psi = 0 the derived M2 is (J1 + J2 - J3) omega0 Omega (SCENES.md erratum)
    if psi == 0.0:
        assert out["M2"] == pytest.approx((J1 + J2 - J3) * omega0 * W, rel=1e-14)


def test_erratum_numbers_and_thin_rod():
    """SCENES.md: J1 = 0.02, J2 = J3 = 0.5 kg m^2, omega0 = 100, Omega = 2 rad/s: +4 N m (the
    book's form gives -96); a thin rod (J1 -> 0) spinning on its axis has no gyroscopic
    moment, by dH/dt as well."""
    out = precessing_shaft(Q_(0.02, "kg*m^2"), Q_(0.5, "kg*m^2"), Q_(100, "rad/s"),
                           Q_(2, "rad/s")).values
    assert (out["M1"], out["M2"], out["M3"]) == (0.0, pytest.approx(4.0, rel=1e-15), 0.0)
    book = (0.02 - 0.5) * 100 * 2
    assert book == pytest.approx(-96.0) and abs(out["M2"] - book) > 99
    rod = precessing_shaft(0.0, 0.5, 100.0, 2.0, alpha0=0.3, t=0.2).values
    M = _moment_by_dH_dt(0.0, 0.5, 0.5, 100.0, lambda s: 0.3 * math.sin(2 * s), 0.0, 0.2)
    assert rod["M2"] == 0.0 and abs(M[1]) < 1e-9
    assert rod["M3"] == pytest.approx(-0.5 * 0.3 * 4 * math.sin(0.4), rel=1e-14)
    assert M[2] == pytest.approx(rod["M3"], rel=1e-8)


def test_symmetric_harmonic_and_unit_invariance():
    si = precessing_shaft(0.02, 0.5, 100.0, 2.0, alpha0=0.3, t=1.1).values
    rate, accel = 0.3 * 2 * math.cos(2.2), -0.3 * 4 * math.sin(2.2)
    assert si["alpha_dot"] == pytest.approx(rate, rel=1e-15)
    assert si["M2"] == pytest.approx(0.02 * 100 * rate, rel=1e-14)
    assert si["M3"] == pytest.approx(0.5 * accel, rel=1e-14)
    other = precessing_shaft(Q_(0.02 / 0.0421401100938048, "lb*ft^2"),
                             Q_(0.5e4, "kg*cm^2"), Q_(100 * 60 / (2 * math.pi), "rpm"),
                             Q_(2, "rad/s"), alpha0=Q_(math.degrees(0.3), "deg"),
                             t=Q_(1100, "ms")).values
    assert other == pytest.approx(si, rel=1e-12)


@pytest.mark.parametrize("kwargs, message", [
    ({"t": 1.0}, "precessing-shaft: t goes with alpha0 (harmonic turning alpha = alpha0 "
                 "sin(Omega t)); uniform turning (alpha = Omega t, no alpha0) is the same at "
                 "every instant"),
    ({"alpha0": 0.2}, "precessing-shaft: harmonic turning (alpha0 given) needs t, the instant "
                      "asked for"),
    ({"alpha0": 0.2, "t": -1.0}, "t is the time since the start: t >= 0; got t = -1 s")])
def test_shaft_refusals(kwargs, message):
    with pytest.raises(InputError) as caught:
        precessing_shaft(0.1, 0.5, 10.0, 2.0, **kwargs)
    assert str(caught.value) == message


# --- beam-spun-up (E3.43) -------------------------------------------------------------------

def _beam_by_quad(m, l, M0, x, t):
    """d'Alembert on the outer part x..l: tangential load mu s alpha, centripetal mu s omega^2;
    M from the moment of the tangential load about the section (against the rotation)."""
    mu, alpha = m / l, M0 / (m * l * l / 3)
    omega = alpha * t
    N = quad(lambda s: mu * s * omega ** 2, x, l, epsabs=0, epsrel=1e-13)[0]
    V = quad(lambda s: mu * s * alpha, x, l, epsabs=0, epsrel=1e-13)[0]
    M = -quad(lambda s: mu * s * alpha * (s - x), x, l, epsabs=0, epsrel=1e-13)[0]
    return N, V, M


@pytest.mark.parametrize("x", [0.0, 0.1, 0.5, 1.37, 2.0])
def test_beam_against_integrated_loads(x):
    m, l, M0, t = 6.0, 2.0, 12.0, 2.0
    out = beam_spun_up(Q_(m, "kg"), Q_(l, "m"), Q_(M0, "N*m"), Q_(x, "m"), Q_(t, "s")).values
    N, V, M = _beam_by_quad(m, l, M0, x, t)
    assert out["N"] == pytest.approx(N, rel=1e-12, abs=1e-12)
    assert out["V"] == pytest.approx(V, rel=1e-12, abs=1e-12)
    assert out["M"] == pytest.approx(M, rel=1e-12, abs=1e-12)
    assert out["alpha"] == pytest.approx(M0 / (m * l * l / 3), rel=1e-15)
    assert out["omega"] == pytest.approx(out["alpha"] * t, rel=1e-15)


def test_beam_end_values_and_slope():
    """M(0) = -M0 (the pin's moment), all zero at the free end, dM/dx = V (central
    differences), V and M independent of t."""
    m, l, M0 = 2.5, 1.2, 7.0
    f = lambda x, t=3.0: beam_spun_up(m, l, M0, x, t).values
    assert f(0.0)["M"] == -M0 and f(l) == {"alpha": f(l)["alpha"], "omega": f(l)["omega"],
                                            "N": 0.0, "V": 0.0, "M": 0.0}
    for x in (0.2, 0.6, 1.0):
        h = 1e-4
        slope = (f(x + h)["M"] - f(x - h)["M"]) / (2 * h)
        assert slope == pytest.approx(f(x)["V"], rel=1e-7)
        assert f(x, 0.0)["V"] == f(x, 9.0)["V"] and f(x, 0.0)["M"] == f(x, 9.0)["M"]
        assert f(x, 0.0)["N"] == 0.0 and f(x, 2.0)["N"] * 4 == pytest.approx(f(x, 4.0)["N"])
    assert set(beam_spun_up(m, l, M0).values) == {"alpha"}
    assert set(beam_spun_up(m, l, M0, x=0.3).values) == {"alpha", "V", "M"}
    assert set(beam_spun_up(m, l, M0, t=0.3).values) == {"alpha", "omega"}


def test_beam_unit_invariance():
    si = beam_spun_up(6.0, 2.0, 12.0, 0.5, 2.0).values
    other = beam_spun_up(Q_(6000, "g"), Q_(200, "cm"), Q_(12 / 1.3558179483314004, "lbf*ft"),
                         Q_(500, "mm"), Q_(2 / 60, "min")).values
    assert other == pytest.approx(si, rel=1e-13)


@pytest.mark.parametrize("x, t, message", [
    (2.5, 1.0, "x must lie on the bar: 0 <= x <= l; got x = 2.5 m with l = 2 m"),
    (-0.1, 1.0, "x must lie on the bar: 0 <= x <= l; got x = -0.1 m with l = 2 m"),
    (0.5, -2.0, "t is the time since the start: t >= 0; got t = -2 s")])
def test_beam_refusals(x, t, message):
    with pytest.raises(InputError) as caught:
        beam_spun_up(6.0, 2.0, 12.0, x, t)
    assert str(caught.value) == message


# --- rotating-angled-arm (E4.11) ------------------------------------------------------------

def _arm_by_quad(m, a, b, W, leg, x):
    """Centrifugal loads dm r Omega^2 on the outer part (toward E) integrated with quad, in a
    plane frame: axis at 0, leg a along +X to K = (a, 0), leg b from K along +Y to E = (a, b).
    Returns N (along the running direction toward the axis, tension), V (along z, to the
    inside of the L) and M (the internal moment on the outer part about +Z, converted to
    'stretches the inside fibres')."""
    mu = m / (a + b)
    q = lambda X, Y: (mu * W * W * X, mu * W * W * Y)
    if leg == "b":
        P, parts = (a, b - x), [((a, b - x), (0, 1), x)]
        run, z = (0, -1), (-1, 0)
    else:
        P, parts = (a - x, 0.0), [((a, 0), (0, 1), b), ((a - x, 0), (1, 0), x)]
        run, z = (-1, 0), (0, 1)
    F = [0.0, 0.0]
    Mc = 0.0
    for (X0, Y0), (dx, dy), length in parts:
        for k in range(2):
            F[k] += quad(lambda s: q(X0 + s * dx, Y0 + s * dy)[k], 0, length,
                         epsabs=0, epsrel=1e-13)[0]
        Mc += quad(lambda s: (X0 + s * dx - P[0]) * q(X0 + s * dx, Y0 + s * dy)[1]
                   - (Y0 + s * dy - P[1]) * q(X0 + s * dx, Y0 + s * dy)[0], 0, length,
                   epsabs=0, epsrel=1e-13)[0] if length else 0.0
    inner = (-F[0], -F[1])          # the inner part holds the outer part in balance
    N = inner[0] * run[0] + inner[1] * run[1]
    V = inner[0] * z[0] + inner[1] * z[1]
    return N, V, -Mc


@pytest.mark.parametrize("leg, x", [("b", 0.0), ("b", 0.25), ("b", 0.5), ("a", 0.0),
                                     ("a", 0.3), ("a", 1.0)])
def test_arm_against_integrated_loads(leg, x):
    m, a, b, W = 3.0, 1.0, 0.5, 10.0
    key = "x1" if leg == "b" else "x2"
    out = rotating_angled_arm(Q_(m, "kg"), Q_(a, "m"), Q_(b, "m"), Q_(W, "rad/s"),
                              **{key: Q_(x, "m")}).values
    N, V, M = _arm_by_quad(m, a, b, W, leg, x)
    for name, value in (("N", N), ("V", V), ("M", M)):
        assert out[name] == pytest.approx(value, rel=1e-12, abs=1e-11), name
    mu_W2 = m / (a + b) * W * W
    assert (out["N0"], out["V0"], out["M0"]) == pytest.approx(
        (mu_W2 * a * b, -mu_W2 * b * b / 2, mu_W2 * a * b * b / 2), rel=1e-15)


def test_arm_corner_axis_and_slope():
    mu_W2, a, b = 7.0, 1.3, 0.6
    assert arm_leg_a(mu_W2, a, b, a)[2] == 0.0                      # M = 0 at the axis
    N0, V0, M0 = arm_leg_a(mu_W2, a, b, 0.0)
    Nb, Vb, Mb = arm_leg_b(mu_W2, a, b, b)
    assert N0 == pytest.approx(Vb, rel=1e-15) and V0 == pytest.approx(-Nb, rel=1e-15)
    assert M0 == pytest.approx(Mb, rel=1e-15)
    h = 1e-5
    for leg, x in ((arm_leg_b, 0.3), (arm_leg_a, 0.7)):
        slope = (leg(mu_W2, a, b, x + h)[2] - leg(mu_W2, a, b, x - h)[2]) / (2 * h)
        # x runs toward the axis and z to the inside of the L on both legs: dM/dx = V
        assert slope == pytest.approx(leg(mu_W2, a, b, x)[1], rel=1e-8)


def test_arm_unit_invariance():
    si = rotating_angled_arm(3.0, 1.0, 0.5, 10.0, x2=0.4).values
    other = rotating_angled_arm(Q_(3 / 0.45359237, "lb"), Q_(100, "cm"), Q_(0.5 / 0.3048, "ft"),
                                Q_(600 / (2 * math.pi), "rpm"), x2=Q_(400, "mm")).values
    assert other == pytest.approx(si, rel=1e-13)


@pytest.mark.parametrize("kwargs, message", [
    ({"x1": 0.6}, "x1 must lie on the bar: 0 <= x1 <= b; got x1 = 0.6 m with b = 0.5 m"),
    ({"x2": 1.5}, "x2 must lie on the bar: 0 <= x2 <= a; got x2 = 1.5 m with a = 1 m"),
    ({"x2": -0.5}, "x2 must lie on the bar: 0 <= x2 <= a; got x2 = -0.5 m with a = 1 m"),
    ({}, "rotating-angled-arm needs exactly one section: x1 (on leg b, from its free end) or "
         "x2 (on leg a, from the corner)"),
    ({"x1": 0.1, "x2": 0.1}, "rotating-angled-arm needs exactly one section: x1 (on leg b, "
                             "from its free end) or x2 (on leg a, from the corner)")])
def test_arm_refusals(kwargs, message):
    with pytest.raises(InputError) as caught:
        rotating_angled_arm(3.0, 1.0, 0.5, 10.0, **kwargs)
    assert str(caught.value) == message
