"""``dyncalc coriolis``: the relative-motion formula a = a0 + alpha x r + Omega x (Omega x r)
+ 2 Omega x v_r + a_r, with vectors, with magnitudes and on the rotating Earth.

Checked against the textbook's worked set-ups (Gross et al., Engineering Mechanics 3, E6.6,
E6.10, E6.12) with numbers of our own, against the absolute acceleration found independently
by differentiating the inertial position twice with mpmath, against hand calculations on the
Earth, by hypothesis properties of the cross product, for unit invariance and for every
refusal's exact message.
"""
import json
import math

import mpmath
import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncalc.cli import cli
from dyncalc.errors import InputError
from dyncalc.commands.coriolis import coriolis_result
from dyncalc.physics.frames import EARTH_RATE, cos_sin_degrees, relative_acceleration

W = EARTH_RATE


def run(*args):
    """The JSON of a successful coriolis call."""
    result = CliRunner().invoke(cli, ["coriolis", *args, "--json"])
    assert result.exit_code == 0, result.output + result.stderr
    return json.loads(result.stdout)


def results(*args):
    """Result name -> value (numpy arrays for vectors) of a coriolis call."""
    out = {}
    for name, item in run(*args)["results"].items():
        value = item["value"]
        out[name] = np.array(value) if isinstance(value, list) else value
    return out


def refusal(*args):
    """The one error line of a refused coriolis call (exit status 2)."""
    result = CliRunner().invoke(cli, ["coriolis", *args])
    assert result.exit_code == 2, result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    return lines[0]


def vec(v, unit=""):
    """A vector option text with full-precision components."""
    return ",".join(repr(float(x)) for x in v) + (f" {unit}" if unit else "")


# --------------------------------------------------------------------------------------------
# The scalar form (the contract's smoke test)


def test_contract_scalar():
    data = run("--omega", "2 rad/s", "--vr", "3 m/s")
    assert data["results"]["a_c"] == {"value": 12.0, "unit": "m/s^2"}
    assert data["command"] == "coriolis" and data["warnings"] == []
    assert data["inputs"]["omega"] == {"value": 2.0, "unit": "rad/s", "text": "2 rad/s"}


def test_scalar_form_terms():
    res = results("--omega", "2 rad/s", "--vr", "3 m/s", "--r", "0.5 m", "--alpha",
                  "4 rad/s^2", "--mass", "2 kg")
    assert res["a_c"] == 12.0
    assert res["F_c"] == 24.0  # a magnitude: m a_c, directed opposite to a_c
    assert res["a_euler"] == 2.0  # alpha r
    assert res["a_centripetal"] == 2.0  # Omega^2 r
    assert res["a_transport"] == pytest.approx(math.hypot(2.0, 2.0), rel=1e-15)
    assert "a" not in res and "a_c_mag" not in res  # no direction of v_r relative to r


def test_scalar_form_without_transport_terms():
    res = results("--omega", "30 rpm", "--vr", "2 m/s")
    assert list(res) == ["a_c"]
    assert res["a_c"] == pytest.approx(2 * math.pi * 2, rel=1e-15)


def test_scalar_zero_rate():
    res = results("--omega", "0 rad/s", "--vr", "3 m/s", "--r", "1 m")
    assert res["a_c"] == 0.0 and res["a_centripetal"] == 0.0


# --------------------------------------------------------------------------------------------
# The textbook's set-ups, with numbers of our own


def test_e6_6_point_on_a_disk_on_a_turntable():
    """E6.6: the platform turns at Omega about z; on it a disk of radius R turns at omega about
    the horizontal x axis. Point P at angle phi from y on the rim: v_r = omega x rho and
    a_c = (2 R omega Omega sin phi, 0, 0)."""
    Om, om, R, phi = 3.0, 5.0, 0.4, math.radians(30)
    rho = np.array([0.0, R * math.cos(phi), R * math.sin(phi)])
    v_r = np.cross([om, 0, 0], rho)
    res = results("--omega", "0,0,3 rad/s", "--vr", vec(v_r, "m/s"))
    expected = 2 * R * om * Om * math.sin(phi)
    assert res["a_c"] == pytest.approx([expected, 0, 0], abs=1e-14)
    assert res["a_c_mag"] == pytest.approx(6.0, rel=1e-14)


def test_e6_6_absolute_acceleration_by_differentiation():
    """The disk's centre sits at c on the platform; a = X''(0) of the inertial position
    X(t) = Rz(Omega t) (c + Rx(omega t) rho0), differentiated by mpmath."""
    Om, om, R, phi = 3.0, 5.0, 0.4, 0.7
    c = np.array([1.2, 0.0, 0.3])
    rho = np.array([0.0, R * math.cos(phi), R * math.sin(phi)])
    v_r = np.cross([om, 0, 0], rho)
    a_r = -om ** 2 * rho
    res = results("--omega", "0,0,3", "--vr", vec(v_r), "--r", vec(c + rho), "--ar", vec(a_r))

    mpmath.mp.dps = 30

    def X(t, k):
        ang = phi + om * t
        p = [c[0], c[1] + R * mpmath.cos(ang), c[2] + R * mpmath.sin(ang)]
        cz, sz = mpmath.cos(Om * t), mpmath.sin(Om * t)
        return [cz * p[0] - sz * p[1], sz * p[0] + cz * p[1], p[2]][k]

    exact = [float(mpmath.diff(lambda t: X(t, k), 0, 2)) for k in range(3)]
    assert res["a"] == pytest.approx(exact, rel=1e-12, abs=1e-12)


def test_e6_10_point_on_a_circle_on_an_eccentric_platform():
    """E6.10: the platform turns at Omega about O; P runs round a circle of radius r about M
    (OM = e) at the relative rate omega. a = -Omega^2 e e_x - r (Omega + omega)^2 e_rho."""
    Om, om, e, r, psi = 2.0, 3.0, 0.5, 0.2, math.radians(40)
    e_rho = np.array([math.cos(psi), math.sin(psi), 0.0])
    pos = np.array([e, 0.0, 0.0]) + r * e_rho
    v_r = r * om * np.array([-math.sin(psi), math.cos(psi), 0.0])
    a_r = -r * om ** 2 * e_rho
    res = results("--omega", "0,0,2 rad/s", "--vr", vec(v_r, "m/s"), "--r", vec(pos, "m"),
                  "--ar", vec(a_r, "m/s^2"))
    expected = -np.array([Om ** 2 * e, 0, 0]) - r * (Om + om) ** 2 * e_rho
    assert res["a"] == pytest.approx(expected, rel=1e-13, abs=1e-14)
    assert res["a_c"] == pytest.approx(-2 * Om * r * om * e_rho, rel=1e-13, abs=1e-14)
    assert res["a_centripetal"] == pytest.approx(-Om ** 2 * pos, rel=1e-14)
    assert res["a_euler"].tolist() == [0.0, 0.0, 0.0]
    assert res["a_transport"] == pytest.approx(res["a_centripetal"], rel=1e-15)


@pytest.mark.parametrize("phi_deg", [0.0, 60.0, 90.0, 135.0, 180.0, 250.0])
def test_e6_12_translating_frame(phi_deg):
    """E6.12: the frame translates with a0 (no rotation); P runs round a circle of radius r at
    constant speed v_r; phi from the direction of a0:
    |a| = sqrt(a0^2 + v_r^4/r^2 - 2 a0 v_r^2 cos(phi)/r)."""
    a0, v, r = 4.0, 3.0, 1.5
    phi = math.radians(phi_deg)
    e_rho = np.array([math.cos(phi), math.sin(phi), 0.0])
    t = np.array([-math.sin(phi), math.cos(phi), 0.0])
    res = results("--omega", "0,0,0 rad/s", "--vr", vec(v * t, "m/s"), "--r", vec(r * e_rho, "m"),
                  "--a0", "4,0,0 m/s^2", "--ar", vec(-v ** 2 / r * e_rho, "m/s^2"))
    expected = math.sqrt(a0 ** 2 + v ** 4 / r ** 2 - 2 * a0 * v ** 2 * math.cos(phi) / r)
    assert res["a_mag"] == pytest.approx(expected, rel=1e-13)
    assert res["a_c"].tolist() == [0.0, 0.0, 0.0]
    assert res["a_centripetal"].tolist() == [0.0, 0.0, 0.0]
    assert res["a_transport"].tolist() == [4.0, 0.0, 0.0]


def _rotation(axis, angle):
    """Rodrigues' rotation matrix (mpmath) about the unit ``axis``."""
    n = mpmath.matrix(axis)
    c, s = mpmath.cos(angle), mpmath.sin(angle)
    K = mpmath.matrix([[0, -n[2], n[1]], [n[2], 0, -n[0]], [-n[1], n[0], 0]])
    return mpmath.eye(3) + s * K + (1 - c) * K * K


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_every_term_against_differentiation(seed):
    """A frame turning about a fixed axis n by theta(t) = Omega t + alpha t^2 / 2, its origin
    at a0 t^2 / 2, a point at p(t) = r + v t + a_r t^2 / 2 in it: the command's a equals the
    second derivative of the inertial position at t = 0 (mpmath, 30 digits)."""
    rng = np.random.default_rng(seed)
    n = rng.normal(size=3)
    n /= np.linalg.norm(n)
    Om, al = rng.uniform(-3, 3), rng.uniform(-2, 2)
    r, v, a_r, a0 = (rng.uniform(-2, 2, size=3) for _ in range(4))
    res = results("--omega", vec(Om * n, "rad/s"), "--alpha", vec(al * n, "rad/s^2"),
                  "--vr", vec(v, "m/s"), "--r", vec(r, "m"), "--ar", vec(a_r, "m/s^2"),
                  "--a0", vec(a0, "m/s^2"))
    mpmath.mp.dps = 30
    axis = [mpmath.mpf(float(x)) for x in n]

    def X(t, k):
        p = mpmath.matrix([r[i] + v[i] * t + a_r[i] * t ** 2 / 2 for i in range(3)])
        q = _rotation(axis, Om * t + al * t ** 2 / 2) * p
        return a0[k] * t ** 2 / 2 + q[k]

    exact = [float(mpmath.diff(lambda t: X(t, k), 0, 2)) for k in range(3)]
    assert res["a"] == pytest.approx(exact, rel=1e-11, abs=1e-11)
    total = res["a_transport"] + res["a_c"] + a_r
    assert res["a"] == pytest.approx(total, rel=1e-15, abs=1e-15)


def test_force_is_minus_m_a_c():
    res = results("--omega", "0,0,2 rad/s", "--vr", "3,0,0 m/s", "--mass", "500 g")
    assert res["a_c"].tolist() == [0.0, 12.0, 0.0]
    assert res["F_c"].tolist() == [0.0, -6.0, 0.0]
    assert res["F_c_mag"] == 6.0


def test_only_a_c_without_transport_inputs():
    res = results("--omega", "0,0,2", "--vr", "3,0,0")
    assert list(res) == ["a_c", "a_c_mag"]


# --------------------------------------------------------------------------------------------
# Properties of the Coriolis term


def _normal(x):
    """Far from the subnormal range, where rounding is relative (tolerances scale with it)."""
    return 0.0 if abs(x) < 1e-200 else x


component = st.floats(-1e3, 1e3).map(_normal)
vector = st.tuples(component, component, component)
factor = st.floats(-100, 100).map(_normal)


def a_c_of(omega, v_r):
    res = coriolis_result({"omega": vec(omega, "rad/s"), "vr": vec(v_r, "m/s")})
    return res.results["a_c"].si, res.results["a_c_mag"].si


def norm(v):
    return math.hypot(*v)


@settings(max_examples=60, deadline=None)
@given(vector, vector)
def test_a_c_is_perpendicular_to_omega_and_v_r(omega, v_r):
    a_c, _ = a_c_of(omega, v_r)
    scale = 2 * norm(omega) * norm(v_r)
    assert abs(np.dot(a_c, omega)) <= 1e-13 * scale * norm(omega) + 1e-300
    assert abs(np.dot(a_c, v_r)) <= 1e-13 * scale * norm(v_r) + 1e-300


@settings(max_examples=60, deadline=None)
@given(st.floats(1e-3, 1e3), st.floats(1e-3, 1e3), st.floats(0, math.pi),
       st.floats(0, 2 * math.pi), st.floats(-math.pi, math.pi), st.floats(0, math.pi))
def test_magnitude_is_2_omega_v_sin_angle(w, v, angle, beta, yaw, pitch):
    """Omega along z and v_r at ``angle`` from it, both turned by the same rotation."""
    turn = (np.array([[math.cos(yaw), -math.sin(yaw), 0], [math.sin(yaw), math.cos(yaw), 0],
                      [0, 0, 1]])
            @ np.array([[1, 0, 0], [0, math.cos(pitch), -math.sin(pitch)],
                        [0, math.sin(pitch), math.cos(pitch)]]))
    omega = turn @ np.array([0.0, 0.0, w])
    v_r = turn @ (v * np.array([math.sin(angle) * math.cos(beta),
                                math.sin(angle) * math.sin(beta), math.cos(angle)]))
    _, mag = a_c_of(omega, v_r)
    assert mag == pytest.approx(2 * w * v * math.sin(angle), abs=1e-12 * 2 * w * v)


@settings(max_examples=60, deadline=None)
@given(vector, factor, st.integers(-20, 20))
def test_a_c_vanishes_for_v_r_parallel_to_omega(omega, k, j):
    a_c, _ = a_c_of(omega, [k * x for x in omega])
    assert norm(a_c) <= 1e-13 * 2 * norm(omega) ** 2 * abs(k)
    exact, _ = a_c_of(omega, [math.ldexp(x, j) for x in omega])  # exactly parallel
    assert exact.tolist() == [0.0, 0.0, 0.0]


@settings(max_examples=60, deadline=None)
@given(vector, vector, vector, factor)
def test_a_c_is_linear_in_v_r(omega, v1, v2, k):
    a1, _ = a_c_of(omega, v1)
    a2, _ = a_c_of(omega, v2)
    v12 = np.array(v1) + np.array(v2)
    a12, _ = a_c_of(omega, v12)
    tol = 1e-12 * 2 * norm(omega) * (norm(v1) + norm(v2))
    assert np.all(np.abs(a12 - (a1 + a2)) <= tol)
    ak, _ = a_c_of(omega, k * np.array(v1))
    assert np.all(np.abs(ak - k * a1) <= 1e-12 * 2 * norm(omega) * abs(k) * norm(v1))


@settings(max_examples=40, deadline=None)
@given(vector, vector, vector)
def test_transport_terms_as_in_the_formula(omega, r, alpha):
    fa = relative_acceleration(omega, [0, 0, 0], r=r, alpha=alpha)
    scale = norm(omega) ** 2 * norm(r)
    assert np.all(np.abs(fa.a_centripetal - np.cross(omega, np.cross(omega, r)))
                  <= 1e-12 * scale + 1e-300)
    assert np.all(np.abs(fa.a_euler - np.cross(alpha, r))
                  <= 1e-13 * norm(alpha) * norm(r) + 1e-300)
    # the centripetal term points at the axis: perpendicular to Omega, opposite to r's part
    assert np.dot(fa.a_centripetal, omega) == pytest.approx(0, abs=1e-12 * scale * norm(omega)
                                                             + 1e-300)
    assert np.dot(fa.a_centripetal, r) <= 1e-12 * scale * norm(r)


# --------------------------------------------------------------------------------------------
# The rotating Earth against hand calculations


def test_northward_train_at_45_north():
    v = 50.0  # 180 km/h
    data = run("--latitude", "45deg", "--speed", "180 km/h", "--heading", "0deg",
               "--mass", "4e5 kg")
    res = {k: np.array(x["value"]) for k, x in data["results"].items()}
    s45 = math.sqrt(0.5)
    assert float(res["a_c_mag"]) == pytest.approx(2 * W * v * s45, rel=1e-14)
    assert res["a_c"] == pytest.approx([-2 * W * v * s45, 0, 0], rel=1e-14)  # west
    assert res["F_c"] == pytest.approx([4e5 * 2 * W * v * s45, 0, 0], rel=1e-14)  # east
    assert res["Omega"] == pytest.approx([0, W * s45, W * s45], rel=1e-15)
    assert res["v_r"].tolist() == [0.0, 50.0, 0.0]
    assert data["extra"]["directions"] == {"a_c": "west", "F_c": "east"}
    assert data["extra"]["frame"] == "east-north-up"


def test_northward_train_explains_the_directions():
    out = CliRunner().invoke(cli, ["coriolis", "--latitude", "45deg", "--vr", "0,50,0 m/s",
                                   "--explain"]).stdout
    assert "a_c points west (bearing 270 deg" in out
    assert ("the Coriolis force F_c = -m a_c points east (bearing 90 deg, horizontal part "
            "0.0051563 N/kg): to the right of the horizontal motion") in out
    assert "latitude phi = 45 deg N" in out


def test_eastward_car_at_30_north():
    v = 25.0
    data = run("--latitude", "30 deg", "--vr", "90,0,0 km/h", "--mass", "1200 kg")
    res = data["results"]
    # a_c = 2 Omega v (0, sin 30, -cos 30): north and down; the force south and up
    assert res["a_c"]["value"] == pytest.approx([0, W * v, -2 * W * v * math.cos(math.pi / 6)],
                                                rel=1e-14)
    assert res["a_c"]["value"][1] == W * v * 2 * 0.5  # sin 30 deg is exactly 0.5
    assert res["a_c_mag"]["value"] == pytest.approx(2 * W * v, rel=1e-15)
    assert res["coriolis_parameter"]["value"] == W  # 2 Omega sin 30 deg
    assert data["extra"]["directions"] == {"a_c": "north and down", "F_c": "south and up"}
    assert res["F_c"]["value"] == pytest.approx(
        [0, -1200 * W * v, 1200 * 2 * W * v * math.cos(math.pi / 6)], rel=1e-14)


def test_equator():
    north = results("--latitude", "0deg", "--vr", "0,10,0 m/s")
    assert north["a_c"].tolist() == [0.0, 0.0, 0.0]  # Omega parallel to v_r
    assert north["coriolis_parameter"] == 0.0
    east = results("--latitude", "0deg", "--vr", "10,0,0 m/s")
    assert east["a_c"].tolist() == [0.0, 0.0, -20 * W]  # straight down: the force lifts


def test_equator_explains_why_a_c_vanishes():
    out = CliRunner().invoke(cli, ["coriolis", "--latitude", "0deg", "--vr", "0,10,0 m/s",
                                   "--explain"]).stdout
    assert ("2 Omega x v_r = 0: v_r is parallel to Omega (motion along the rotation axis)"
            in out)
    assert "a_c is zero" in out


@pytest.mark.parametrize("latitude, sign", [("90deg", 1.0), ("-90deg", -1.0),
                                             ("1.5707963267948966 rad", 1.0)])
def test_poles(latitude, sign):
    res = results("--latitude", latitude, "--vr", "10,0,0 m/s")
    assert res["Omega"].tolist() == [0.0, 0.0, sign * W]
    # eastward at the North Pole: a_c north (the force south, to the right); reversed at the
    # South Pole; no vertical part
    assert res["a_c"].tolist() == [0.0, sign * 20 * W, 0.0]
    assert res["a_c_mag"] == 20 * W


def test_south_pole_deflects_left():
    data = run("--latitude", "-90deg", "--speed", "10 m/s", "--heading", "90deg")
    assert data["extra"]["directions"] == {"a_c": "south", "F_c": "north"}
    out = CliRunner().invoke(cli, ["coriolis", "--latitude", "-90deg", "--speed", "10 m/s",
                                   "--heading", "90deg", "--explain"]).stdout
    assert "to the left of the horizontal motion" in out


def test_heading_is_the_same_as_vr():
    a = results("--latitude", "52deg", "--speed", "20 m/s", "--heading", "90deg")
    b = results("--latitude", "52deg", "--vr", "20,0,0 m/s")
    assert a["a_c"].tolist() == b["a_c"].tolist()
    c = results("--latitude", "52deg", "--speed", "20 m/s", "--heading", "225deg")
    s = 20 * math.sqrt(0.5)
    d = results("--latitude", "52deg", "--vr", vec([-s, -s, 0], "m/s"))
    assert c["a_c"] == pytest.approx(d["a_c"], rel=1e-15)


def test_falling_body_is_deflected_east():
    data = run("--latitude", "45deg", "--vertical=-10m/s")
    assert data["results"]["a_c"]["value"] == pytest.approx(
        [-20 * W * math.sqrt(0.5), 0, 0], rel=1e-14)
    assert data["extra"]["directions"]["F_c"] == "east"


def test_custom_rotation_rate():
    mars = 7.088218e-5
    res = results("--latitude", "30deg", "--omega", f"{mars} rad/s", "--vr", "0,10,0 m/s")
    assert res["a_c"].tolist() == [-2 * mars * 10 * 0.5, 0.0, 0.0]


def test_cos_sin_degrees_exact_points():
    assert cos_sin_degrees(0.0) == (1.0, 0.0)
    assert cos_sin_degrees(90.0) == (0.0, 1.0)
    assert cos_sin_degrees(-90.0) == (0.0, -1.0)
    assert cos_sin_degrees(270.0) == (0.0, -1.0)
    assert cos_sin_degrees(30.0)[1] == 0.5 and cos_sin_degrees(60.0)[0] == 0.5
    c, s = cos_sin_degrees(45.0)
    assert c == s == math.sqrt(0.5)


@pytest.mark.parametrize("degrees", [0.1, 12.5, 33.3, 44.9, 77.7, 89.999, 123.4, -61.0, 301.0])
def test_cos_sin_degrees_against_mpmath(degrees):
    mpmath.mp.dps = 30
    c, s = cos_sin_degrees(degrees)
    x = mpmath.radians(mpmath.mpf(degrees))
    assert abs(c - mpmath.cos(x)) <= math.ulp(c)
    assert abs(s - mpmath.sin(x)) <= math.ulp(s)


# --------------------------------------------------------------------------------------------
# Unit invariance


def test_rpm_and_rad_per_second():
    a = results("--omega", "0,0,30 rpm", "--vr", "2,1,0 m/s", "--r", "0.3,0,0 m")
    b = results("--omega", f"0,0,{math.pi!r} rad/s", "--vr", "2,1,0 m/s", "--r", "0.3,0,0 m")
    c = results("--omega", "0,0,180 deg/s", "--vr", "2,1,0 m/s", "--r", "0.3,0,0 m")
    for name in ("a_c", "a_centripetal", "a"):
        assert a[name] == pytest.approx(b[name], rel=1e-14)
        assert c[name] == pytest.approx(b[name], rel=1e-14)


def test_km_per_hour_and_m_per_second():
    a = results("--omega", "0,1,2 rad/s", "--vr", "36,-18,72 km/h")
    b = results("--omega", "0,1,2 rad/s", "--vr", "10,-5,20 m/s")
    assert a["a_c"] == pytest.approx(b["a_c"], rel=1e-14)


def test_scalar_unit_invariance():
    a = results("--omega", "60 rpm", "--vr", "36 km/h", "--mass", "500 g")
    b = results("--omega", f"{2 * math.pi!r} rad/s", "--vr", "10 m/s", "--mass", "0.5 kg")
    assert a["a_c"] == pytest.approx(b["a_c"], rel=1e-15)
    assert a["F_c"] == pytest.approx(b["F_c"], rel=1e-15)


def test_earth_units():
    a = results("--latitude", "0.5 rad", "--speed", "3.6 km/h", "--heading", "0.25 turn")
    b = results("--latitude", f"{math.degrees(0.5)!r} deg", "--vr", "1,0,0 m/s")
    assert a["a_c"] == pytest.approx(b["a_c"], rel=1e-14)


def test_vector_forms_are_the_same():
    forms = ["0,0,2 rad/s", "(0, 0, 2) rad/s", "[0,0,2] rad/s", "0,0,2"]
    values = [results("--omega", f, "--vr", "[1,0,0] m/s")["a_c"].tolist() for f in forms]
    assert values == [[0.0, 4.0, 0.0]] * 4


# --------------------------------------------------------------------------------------------
# Output forms


def test_value_unit_and_check():
    out = CliRunner().invoke(cli, ["coriolis", "--omega", "0,0,2 rad/s", "--vr", "3,0,0 m/s",
                                   "--value", "a_c"])
    assert out.exit_code == 0 and out.stdout == "0.0,12.0,0.0\n"
    ok = CliRunner().invoke(cli, ["coriolis", "--omega", "0,0,2 rad/s", "--vr", "3,0,0 m/s",
                                  "--check", "a_c_mag=12m/s^2"])
    assert ok.exit_code == 0 and "check a_c_mag: expected 12 m/s^2" in ok.stdout
    bad = CliRunner().invoke(cli, ["coriolis", "--omega", "2 rad/s", "--vr", "3 m/s",
                                   "--check", "a_c=6m/s^2"])
    assert bad.exit_code == 1
    data = run("--omega", "0,0,2 rad/s", "--vr", "3,0,0 m/s", "--unit", "a_c=cm/s^2")
    assert data["results"]["a_c"] == {"value": [0.0, 1200.0, 0.0], "unit": "cm/s^2"}


def test_plain_text_table():
    out = CliRunner().invoke(cli, ["coriolis", "--omega", "0,0,2 rad/s", "--vr", "3,0,0 m/s",
                                   "--mass", "2kg"]).stdout.splitlines()
    assert out[0] == "coriolis   model: vectors   method: closed-form"
    assert out[2].split() == ["a_c", "2Ω×v_r", "(0,", "12,", "0)", "m/s^2"]
    assert out[-1] == ("inputs: omega = (0, 0, 2) rad/s, vr = (3, 0, 0) m/s, mass = 2 kg")


def test_explain_lists_every_term_and_why_it_vanishes():
    out = CliRunner().invoke(cli, ["coriolis", "--omega", "0,0,2 rad/s", "--vr", "0,0,3 m/s",
                                   "--r", "0,0,1 m", "--explain"]).stdout
    for line in ["a = a0 + alpha x r + Omega x (Omega x r) + 2 Omega x v_r + a_r",
                 "2 Omega x v_r = 0: v_r is parallel to Omega (motion along the rotation axis)",
                 "a0 = 0: no --a0 (the frame's origin rests or moves at constant velocity)",
                 "alpha x r = 0: no --alpha (the frame turns at a constant rate)",
                 "Omega x (Omega x r) = 0: r lies on the rotation axis (parallel to Omega)",
                 "a_r = 0: no --ar (the velocity relative to the frame is constant)",
                 "a = a_transport + 2 Omega x v_r + a_r = (0, 0, 0) m/s^2, |a| = 0 m/s^2"]:
        assert line in out, line
    json_data = run("--omega", "0,0,2", "--vr", "1,0,0", "--explain")
    assert json_data["extra"]["explanation"]["formula"][0].startswith("a = a0 + alpha x r")


def test_explain_with_numbers():
    out = CliRunner().invoke(cli, ["coriolis", "--omega", "0,0,2 rad/s", "--vr", "3,0,0 m/s",
                                   "--r", "1,0,0 m", "--alpha", "0,0,1 rad/s^2", "--explain"])
    text = out.stdout
    assert "2 Omega x v_r = 2 (0, 0, 2) rad/s x (3, 0, 0) m/s = (0, 12, 0) m/s^2" in text
    assert "alpha x r = (0, 0, 1) rad/s^2 x (1, 0, 0) m = (0, 1, 0) m/s^2" in text
    assert ("Omega x (Omega x r) = (0, 0, 2) rad/s x ((0, 0, 2) rad/s x (1, 0, 0) m) = "
            "(-4, 0, 0) m/s^2") in text


def test_no_overflow_in_intermediate_products():
    res = results("--omega", "0,0,1e200", "--vr", "0,0,0", "--r", "1e-300,0,0")
    assert res["a_centripetal"].tolist() == [-1e100, 0.0, 0.0]


def test_underflow_warns():
    data = run("--omega", "0,0,1e-200", "--vr", "1e-200,0,0")
    assert data["results"]["a_c"]["value"] == [0.0, 0.0, 0.0]
    assert data["warnings"] == ["a_c underflows to zero (below 4.9e-324 m/s^2) although its "
                                "factors are not zero"]


def test_bare_heading_warns():
    data = run("--latitude", "45deg", "--speed", "3 m/s", "--heading", "90")
    assert data["warnings"] == ["--heading 90 has no unit and is read in radians; write 90deg "
                                "for compass degrees"]


def test_help_has_examples():
    out = CliRunner().invoke(cli, ["coriolis", "--help"])
    assert out.exit_code == 0
    assert "Examples:" in out.stdout and "--latitude 45deg" in out.stdout


# --------------------------------------------------------------------------------------------
# Refusals: exit status 2 and one line saying what to change


REFUSALS = [
    (["--omega", "0,0,2 m/s", "--vr", "3,0,0"],
     "Error: --omega must be an angular rate [angle]/[time]; got (0, 0, 2) meter / second "
     "([length] / [time])"),
    (["--omega", "0,0,2", "--vr", "3,0,0 kg"],
     "Error: --vr must be a velocity [length]/[time]; got (3, 0, 0) kilogram ([mass])"),
    (["--omega", "2 Hz", "--vr", "3 m/s"],
     "Error: --omega is an angular rate; give it in rad/s, deg/s, rpm or rev/s, not Hz (a "
     "frequency in cycles)"),
    (["--omega", "0,2 rad/s", "--vr", "3,0,0"],
     "Error: --omega must have 3 components; got 2 in '0,2 rad/s'"),
    (["--omega", "0,0,2", "--vr", "3,0,0,1 m/s"],
     "Error: --vr must have 3 components; got 4 in '3,0,0,1 m/s'"),
    (["--omega", "0,,2 rad/s", "--vr", "3,0,0"],
     "Error: --omega: cannot read '0,,2 rad/s': component 2 is empty"),
    (["--omega", "0,0,2", "--vr", "(3, ,0) m/s"],
     "Error: --vr: cannot read '(3, ,0) m/s': component 2 is empty"),
    (["--latitude", "100deg", "--vr", "0,1,0"],
     "Error: --latitude must be between -90 deg and 90 deg; got 100 degree"),
    (["--latitude", "-90.5 deg", "--vr", "0,1,0"],
     "Error: --latitude must be between -90 deg and 90 deg; got -90.5 degree"),
    (["--latitude", "45", "--vr", "0,1,0"],
     "Error: --latitude must be between -90 deg and 90 deg; got 45 radian (a bare number is "
     "read in radians; write 45deg for degrees)"),
    (["--omega", "0,0,2 rad/s"],
     "Error: --vr is missing: give the velocity relative to the frame, e.g. --vr '3,0,0 m/s' "
     "(or a magnitude such as '3 m/s' with a magnitude --omega), or --r for the velocity and "
     "acceleration of the frame point"),
    (["--latitude", "45deg"],
     "Error: --vr is missing: give the velocity relative to the Earth as east, north, up "
     "components, e.g. --vr '0,20,0 m/s', or --speed with --heading"),
    (["--vr", "3,0,0 m/s"],
     "Error: --omega is missing: give the frame's angular velocity, e.g. --omega '0,0,2 rad/s' "
     "('0,0,0 rad/s' for a frame that only translates), or --latitude for the rotating Earth"),
    (["--omega", "(0,0,inf) rad/s", "--vr", "3,0,0"],
     "Error: --omega must be finite; got (0, 0, inf) radian / second"),
    (["--omega", "2 rad/s", "--vr", "inf m/s"],
     "Error: --vr must be finite; got inf meter / second"),
    (["--omega", "0,0,2", "--vr", "3,0,inf m/s"],
     "Error: --vr: cannot read '3,0,inf m/s': component 3 is not a number"),
    (["--omega", "0,0,1e400 rad/s", "--vr", "3,0,0"],
     "Error: --omega: cannot read '0,0,1e400 rad/s': component 3: 1e400 overflows float64 (the "
     "largest is 1.8e308)"),
    (["--latitude", "45deg", "--omega", "0,0,1 rad/s", "--vr", "0,1,0"],
     "Error: --omega with --latitude is the rotation rate only, a magnitude such as "
     "'7.2921159e-5 rad/s'; its direction follows from the latitude (for a vector --omega "
     "leave out --latitude)"),
    (["--latitude", "45deg", "--vr", "3 m/s"],
     "Error: --vr with --latitude is a vector of east, north, up components, e.g. --vr "
     "'0,20,0 m/s' for 20 m/s northward (or give --speed with --heading)"),
    (["--latitude", "45deg", "--vr", "0,1,0", "--r", "2 m"],
     "Error: --r with --latitude is a vector of east, north, up components, e.g. '0,0,1 m'"),
    (["--latitude", "45deg", "--speed", "3 m/s"],
     "Error: --speed and --heading go together: the horizontal speed and its compass direction "
     "(0 = north, 90deg = east)"),
    (["--latitude", "45deg", "--speed", "-3 m/s", "--heading", "0deg"],
     "Error: --speed must not be negative; got -3 meter / second"),
    (["--latitude", "45deg", "--vr", "0,1,0", "--heading", "0deg"],
     "Error: give --vr or --heading, not both: --speed, --heading and --vertical are another "
     "way to give v_r"),
    (["--omega", "1 rad/s", "--vr", "1 m/s", "--speed", "3 m/s"],
     "Error: --speed describes motion over the Earth and needs --latitude; in a machine frame "
     "give --vr (3 components)"),
    (["--omega", "0,0,2 rad/s", "--vr", "3 m/s"],
     "Error: --vr is a magnitude but --omega is a vector; give --vr with 3 components too, "
     "e.g. '1,0,0 m/s' (or every input as a magnitude: the scalar form)"),
    (["--omega", "2 rad/s", "--vr", "3,0,0 m/s"],
     "Error: --vr is a vector but --omega is a magnitude; give both with 3 components (e.g. "
     "--omega '0,0,2 rad/s') or both as magnitudes (the scalar form: perpendicular vectors)"),
    (["--omega", "2 rad/s", "--vr", "3 m/s", "--a0", "1 m/s^2"],
     "Error: --a0 needs a direction: give --omega, --vr and --a0 as vectors (3 components, "
     "e.g. --omega '0,0,2 rad/s'); the scalar form takes only --omega, --vr, --r (distance "
     "from the axis), --alpha and --mass"),
    (["--omega", "-2 rad/s", "--vr", "3 m/s"],
     "Error: --omega as a scalar is a magnitude and must not be negative; got -2 radian / "
     "second (give a vector for a direction)"),
    (["--omega", "2 rad/s", "--vr", "3 m/s", "--mass", "0 kg"],
     "Error: --mass must be positive; got 0 kilogram"),
    (["--omega", "0,0,1e200", "--vr", "1e200,0,0"],
     "Error: a_c overflows float64 at these inputs (a component beyond 1.8e308 m/s^2)"),
    (["--omega", "0,0,1e200", "--vr", "0,0,0", "--r", "1e200,0,0"],
     "Error: a_centripetal overflows float64 at these inputs (a component beyond 1.8e308 "
     "m/s^2)"),
    (["--omega", "0,0,0", "--vr", "0,0,0", "--a0", "1.5e308,0,0", "--ar", "1.5e308,0,0"],
     "Error: a overflows float64 at these inputs (a component beyond 1.8e308 m/s^2)"),
    (["--omega", "0,0,6.5e153", "--vr", "1e154,1e154,0"],
     "Error: a_c_mag overflows float64 at these inputs (beyond 1.8e308 m/s^2)"),
    (["--omega", "0,0,2 rad/s", "--vr", "3,0,0", "--strict-units"],
     "Error: --vr: '3,0,0' has no unit and --strict-units is on; write it with a unit, e.g. "
     "3,0,0 m/s"),
]


@pytest.mark.parametrize("args, message", REFUSALS, ids=[" ".join(a) for a, _ in REFUSALS])
def test_refusals(args, message):
    assert refusal(*args) == message


def test_library_refuses_with_input_error():
    with pytest.raises(InputError, match="--vr is missing"):
        coriolis_result({"omega": "0,0,1"})


def test_earth_mode_coriolis_parameter_overflow_is_refused_without_a_numpy_warning():
    """2 Omega sin(90 deg) with Omega = 1e308 rad/s overflows: one Error: line, and no numpy
    RuntimeWarning (found by the long fuzz run; the product was of numpy scalars)."""
    import warnings

    from click.testing import CliRunner

    from dyncalc.cli import cli

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = CliRunner().invoke(cli, ["coriolis", "--latitude", "90deg", "--speed",
                                          "0.001 knot", "--heading", "90deg", "--omega",
                                          "1e308 rad/s"])
    assert result.exit_code == 2
    assert result.output == ("Error: coriolis_parameter overflows float64 at these inputs "
                             "(beyond 1.8e308 1/s)\n")
