"""``dyncalc coriolis`` velocities and accelerations of relative motion (SPEC "coriolis —
relative motion"): ``v_transport = v0 + Omega x r``, ``v = v_transport + v_r``,
``a_transport = a0 + alpha x r + Omega x (Omega x r)``, ``a = a_transport + a_c + a_r``.

Every reference is found independently: the absolute position of the point written out in
the fixed frame and differentiated with mpmath (40 digits), then turned into the moving
frame's components; the 1e12-scale cancellation against mpmath's exact arithmetic.
"""
import json

import mpmath
import numpy as np
import pytest
from click.testing import CliRunner

from dyncalc.cli import cli
from dyncalc.physics.relative_motion import relative_motion, transport_velocity



def run(*args):
    result = CliRunner().invoke(cli, ["coriolis", *args, "--json"])
    assert result.exit_code == 0, result.output + result.stderr
    return {name: np.array(item["value"]) if isinstance(item["value"], list)
            else item["value"] for name, item in json.loads(result.stdout)["results"].items()}


def refusal(*args):
    result = CliRunner().invoke(cli, ["coriolis", *args])
    assert result.exit_code == 2, result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    return lines[0]


def vec(v, unit=""):
    return ",".join(repr(float(x)) for x in v) + (f" {unit}" if unit else "")


def rot(theta, v):
    """v turned by theta about z (mpmath)."""
    c, s = mpmath.cos(theta), mpmath.sin(theta)
    return [c * v[0] - s * v[1], s * v[0] + c * v[1], v[2]]


def in_frame(theta, v):
    """Fixed-frame components -> components in a frame turned by theta about z."""
    return rot(-theta, v)


def derivatives(position, t0):
    """Velocity and acceleration of ``position(t)`` (3 mpf components) at t0, by mpmath."""
    vel = [mpmath.diff(lambda t, k=k: position(t)[k], t0) for k in range(3)]
    acc = [mpmath.diff(lambda t, k=k: position(t)[k], t0, 2) for k in range(3)]
    return vel, acc


def close(actual, expected, rtol=1e-13):
    expected = np.array([float(x) for x in expected])
    scale = max(np.max(np.abs(expected)), 1e-300)
    assert np.max(np.abs(np.asarray(actual) - expected)) <= rtol * scale, (actual, expected)


def test_point_on_a_disk_mounted_on_a_turning_disk():
    """A disk (radius rho = 0.15 m) spins at w2 = 7 rad/s on a turntable, its centre at
    R = 0.6 m from the turntable's axis; the turntable turns at theta(t) = w1 t + al t^2/2
    (w1 = 2 rad/s, al = 0.5 rad/s^2). The point's absolute position, differentiated twice,
    in the turntable's axes at t0 = 0.8 s, against the frame formula with r, v_r, a_r of the
    small disk's motion seen from the turntable."""
    R, rho, w1, w2, al = (mpmath.mpf(x) for x in ("0.6", "0.15", "2", "7", "0.5"))
    t0 = mpmath.mpf("0.8")

    def theta(t):
        return w1 * t + al * t * t / 2

    def in_turntable(t):
        return [R + rho * mpmath.cos(w2 * t), rho * mpmath.sin(w2 * t), mpmath.mpf(0)]

    vel, acc = derivatives(lambda t: rot(theta(t), in_turntable(t)), t0)
    r = in_turntable(t0)
    v_r = [-rho * w2 * mpmath.sin(w2 * t0), rho * w2 * mpmath.cos(w2 * t0), 0]
    a_r = [-rho * w2 ** 2 * mpmath.cos(w2 * t0), -rho * w2 ** 2 * mpmath.sin(w2 * t0), 0]
    Omega = w1 + al * t0
    out = run("--omega", vec([0, 0, Omega], "rad/s"), "--alpha", vec([0, 0, al], "rad/s^2"),
              "--r", vec(r, "m"), "--vr", vec(v_r, "m/s"), "--ar", vec(a_r, "m/s^2"))
    close(out["v"], in_frame(theta(t0), vel))
    close(out["a"], in_frame(theta(t0), acc))
    assert out["v_mag"] == pytest.approx(float(mpmath.norm(vel)), rel=1e-13)
    assert out["a_mag"] == pytest.approx(float(mpmath.norm(acc)), rel=1e-13)
    # the frame point: the turntable's own motion at r (rho's spin frozen)
    vel_t, acc_t = derivatives(lambda t: rot(theta(t), r), t0)
    close(out["v_transport"], in_frame(theta(t0), vel_t))
    close(out["a_transport"], in_frame(theta(t0), acc_t))


def test_the_same_disk_seen_from_a_frame_centred_on_the_small_disk():
    """The frame of the small disk's centre: it turns with the turntable, its origin moves
    (v0 = Omega x R e_x, a0 = alpha x R e_x + Omega x (Omega x R e_x)): the same absolute v
    and a as above, with r the point's offset from the centre."""
    R, rho, w1, w2, al = (mpmath.mpf(x) for x in ("0.6", "0.15", "2", "7", "0.5"))
    t0 = mpmath.mpf("0.8")
    theta = w1 * t0 + al * t0 * t0 / 2
    Omega = w1 + al * t0

    def position(t):
        return rot(w1 * t + al * t * t / 2, [R + rho * mpmath.cos(w2 * t),
                                             rho * mpmath.sin(w2 * t), mpmath.mpf(0)])

    vel, acc = derivatives(position, t0)
    v0 = [0, Omega * R, 0]
    a0 = [-Omega ** 2 * R, al * R, 0]
    r = [rho * mpmath.cos(w2 * t0), rho * mpmath.sin(w2 * t0), 0]
    v_r = [-rho * w2 * mpmath.sin(w2 * t0), rho * w2 * mpmath.cos(w2 * t0), 0]
    a_r = [-rho * w2 ** 2 * mpmath.cos(w2 * t0), -rho * w2 ** 2 * mpmath.sin(w2 * t0), 0]
    out = run("--omega", vec([0, 0, Omega]), "--alpha", vec([0, 0, al]), "--r", vec(r),
              "--v0", vec(v0), "--a0", vec(a0), "--vr", vec(v_r), "--ar", vec(a_r))
    close(out["v"], in_frame(theta, vel))
    close(out["a"], in_frame(theta, acc))


def test_trolley_on_a_crane_that_starts_to_turn():
    """A crane's jib starts to turn from rest with alpha = 0.2 rad/s^2 (theta = al t^2/2);
    the trolley runs out along it, x(t) = x0 + u t + b t^2/2, the hook h = 12 m up. At
    t0 = 1.5 s the jib turns at al t0; the absolute velocity and acceleration of the trolley,
    differentiated from its position, in the jib's axes."""
    al, x0, u, b, h = (mpmath.mpf(x) for x in ("0.2", "4", "0.8", "-0.3", "12"))
    t0 = mpmath.mpf("1.5")

    def position(t):
        return rot(al * t * t / 2, [x0 + u * t + b * t * t / 2, mpmath.mpf(0), h])

    vel, acc = derivatives(position, t0)
    x = x0 + u * t0 + b * t0 * t0 / 2
    out = run("--omega", vec([0, 0, al * t0], "rad/s"), "--alpha", vec([0, 0, al], "rad/s^2"),
              "--r", vec([x, 0, h], "m"), "--vr", vec([u + b * t0, 0, 0], "m/s"),
              "--ar", vec([b, 0, 0], "m/s^2"), "--mass", "250 kg")
    theta = al * t0 * t0 / 2
    close(out["v"], in_frame(theta, vel))
    close(out["a"], in_frame(theta, acc))
    close(out["F_c"], [-250 * 2 * al * t0 * (u + b * t0) * k for k in (0, 1, 0)])


def test_unit_invariance_of_the_velocities():
    si = run("--omega", "0,0,3.141592653589793", "--r", "0.2,0.1,0 m", "--v0", "1,0,0",
             "--vr", "0.5,0,0")
    other = run("--omega", "0,0,30 rpm", "--r", "20,10,0 cm", "--v0", "3.6,0,0 km/h",
                "--vr", "50,0,0 cm/s")
    for name in ("v_transport", "v", "v_transport_mag", "v_mag"):
        np.testing.assert_allclose(other[name], si[name], rtol=1e-15)


def test_no_cancellation_in_v0_plus_omega_x_r_at_1e12():
    """v0 = -1e12 m/s against Omega x r = 1e12 m/s + a millimetre per second: each component
    is the correctly rounded exact sum (mpmath at 60 digits), where the naive sum loses every
    digit of the difference."""
    Omega = [0.0, 0.0, 1.0e6 + 0.125]
    r = [1.0e6 - 3.0e-4, 2.5e5 + 1e-6, 3.0]
    v0 = [2.5e11, -1.0e12 - 1.25e5, 7.0]
    v_r = [1e-3, 3e-4, -7.0]
    with mpmath.workdps(60):
        Om, rr = [mpmath.mpf(x) for x in Omega], [mpmath.mpf(x) for x in r]
        cross = [Om[1] * rr[2] - Om[2] * rr[1], Om[2] * rr[0] - Om[0] * rr[2],
                 Om[0] * rr[1] - Om[1] * rr[0]]
        v_t = [float(c + mpmath.mpf(x)) for c, x in zip(cross, v0)]
        v = [float(c + mpmath.mpf(x) + mpmath.mpf(y)) for c, x, y in zip(cross, v0, v_r)]
    assert transport_velocity(Omega, r, v0=v0).tolist() == v_t
    out = relative_motion(Omega, r, v_r=v_r, v0=v0)
    assert out.v.tolist() == v
    assert abs(v_t[1]) < 1e3  # a real cancellation: the terms are 1e12, the sum -300 m/s
    naive = np.cross(Omega, r) + np.array(v0)
    assert naive[1] != v_t[1]
    cli = run("--omega", vec(Omega), "--r", vec(r), "--v0", vec(v0), "--vr", vec(v_r))
    assert cli["v_transport"].tolist() == v_t and cli["v"].tolist() == v


@pytest.mark.parametrize("args, message", [
    (["--omega", "0,0,2 rad/s", "--r", "1,0,0 m", "--value", "v"],
     "Error: --value v: v needs --vr (the velocity relative to the frame)"),
    (["--omega", "0,0,2 rad/s", "--r", "1,0,0 m", "--value", "a_c_mag"],
     "Error: --value a_c_mag: a_c_mag needs --vr (the velocity relative to the frame)"),
    (["--omega", "0,0,2 rad/s", "--vr", "1,0,0 m/s", "--value", "v_transport"],
     "Error: --value v_transport: v_transport needs --r (the position in the frame) or --v0 "
     "(the velocity of its origin)"),
    (["--omega", "0,0,2 rad/s", "--vr", "1,0,0 m/s", "--value", "a_mag"],
     "Error: --value a_mag: a_mag needs --r, --alpha, --a0 or --ar (the terms of the frame's "
     "motion)"),
    (["--omega", "0,0,2 rad/s", "--v0", "1,0,0 m/s", "--check", "F_c_mag=1N"],
     "Error: --check F_c_mag: F_c_mag needs --vr (the velocity relative to the frame) and "
     "--mass"),
    (["--omega", "0,0,2 rad/s", "--vr", "1,0,0 m/s", "--unit", "F_c=kN"],
     "Error: --unit F_c: F_c needs --mass"),
    (["--omega", "2 rad/s", "--r", "1 m"],
     "Error: --vr is missing: the scalar form (a magnitude --omega) gives a_c = 2 Omega v_r; "
     "give --vr as a magnitude, e.g. --vr '3 m/s' (or vectors for the velocities of the frame "
     "point)"),
    (["--omega", "2 rad/s", "--vr", "1 m/s", "--v0", "1 m/s"],
     "Error: --v0 needs a direction: give --omega, --vr and --v0 as vectors (3 components, "
     "e.g. --omega '0,0,2 rad/s'); the scalar form takes only --omega, --vr, --r (distance "
     "from the axis), --alpha and --mass"),
    (["--omega", "0,0,2 rad/s", "--r", "1,0,0 m", "--v0", "3 m/s"],
     "Error: --v0 is a magnitude but --omega is a vector; give --v0 with 3 components too, "
     "e.g. '1,0,0 m/s' (or every input as a magnitude: the scalar form)"),
])
def test_what_is_missing_for_which_result(args, message):
    assert refusal(*args) == message


def test_omega_and_r_alone_give_the_frame_point():
    """No --vr: the velocity and acceleration of the frame point, nothing that needs v_r."""
    out = run("--omega", "0,0,2 rad/s", "--r", "1.5,0,0 m")
    assert set(out) == {"a_euler", "a_centripetal", "a_transport", "a_transport_mag",
                        "v_transport", "v_transport_mag"}
    assert out["v_transport"].tolist() == [0.0, 3.0, 0.0]
    assert out["a_transport"].tolist() == [-6.0, 0.0, 0.0]


# --------------------------------------------------------------------------------------------
# Components as expressions with units


def test_components_as_expressions_with_the_trailing_unit():
    """0.1*5*sin(35deg) takes the trailing m/s: 0.5 sin(35 deg) m/s (math.sin of the angle in
    radians, worked out here)."""
    out = run("--omega", "0,0,2 rad/s", "--vr", "0.1*5*sin(35deg), 0, 0 m/s")
    speed = 0.5 * np.sin(np.radians(35.0))
    np.testing.assert_allclose(out["a_c"], [0.0, 4.0 * speed, 0.0], rtol=1e-15)


def test_parameters_inside_components_and_units_of_their_own():
    """l*cos(30deg) with l=2m carries its own unit; the bare 0 takes none (SI); a component
    with a unit of its own is taken as it is whatever the trailing unit."""
    a = run("--omega", "0,0,2", "--r", "l*cos(30deg), l*sin(30deg), 0", "l=2m")
    b = run("--omega", "0,0,2", "--r", "(l*cos(30deg), 200*sin(30deg), 0) cm", "l=2m")
    c = run("--omega", "0,0,2", "--r", "173.20508075688772 cm, 1 m, 0")
    expected = [2 * np.cos(np.radians(30.0)), 2 * np.sin(np.radians(30.0)), 0.0]
    for out in (a, b, c):
        np.testing.assert_allclose(out["v_transport"], [-2 * expected[1], 2 * expected[0], 0],
                                   rtol=1e-15)


def test_rates_in_expressions_follow_the_rate_rules():
    out = run("--omega", "0, 0, 2*(15 rpm)", "--vr", "1,0,0")
    assert out["a_c"].tolist() == pytest.approx([0.0, 2 * np.pi, 0.0], rel=1e-15)


@pytest.mark.parametrize("args, message", [
    (["--omega", "0,0,2", "--vr", "0.1*5*sin(35deg, 0, 0 m/s"],
     "Error: --vr: this '(' is never closed at column 10: '0.1*5*sin(35deg, 0, 0 m/s'"),
    (["--omega", "0,0,2", "--vr", "0.1*5*open(35deg), 0, 0 m/s"],
     "Error: --vr: unknown function 'open' (the functions are sin, cos, tan, exp, log, sqrt, "
     "sinh, cosh, atan2, abs) at column 7: '0.1*5*open(35deg), 0, 0 m/s'"),
    (["--omega", "0,0,2", "--vr", "0, 2*x, 0 m/s"],
     "Error: --vr: unknown name 'x' (the names here are pi, t) at column 6: '0, 2*x, 0 m/s'"),
    (["--omega", "0,0,2", "--vr", "0, 0.5*sin(35 m), 0 m/s"],
     "Error: --vr: sin() takes a pure number or an angle; got [length] at column 8: "
     "'0, 0.5*sin(35 m), 0 m/s'"),
    (["--omega", "0,0,2", "--r", "l*cos(30deg), l*sin(30deg), 0", "l=2kg"],
     "Error: --r: component 1 is [mass], not length [length] at column 1: "
     "'l*cos(30deg), l*sin(30deg), 0'"),
    (["--omega", "0, 0, 2*(3 Hz)", "--vr", "1,0,0"],
     "Error: --omega is an angular rate; give it in rad/s, deg/s, rpm or rev/s, not Hz (a "
     "frequency in cycles)"),
    (["--omega", "0,0,2", "--r", "l, 0, 0", "l=2m", "l=3m"],
     "Error: l is given twice (l= twice)"),
    (["--omega", "0,0,2", "--r", "1,0,0 m", "l=2m"],
     "Error: l= is used by no vector component: a parameter names a quantity inside the "
     "components of --r, --vr, --omega, ... (--r \"l*cos(30deg), l*sin(30deg), 0\" l=2m)"),
    (["--omega", "0,0,2", "--r", "2 m, 0, 0", "m=3kg"],
     "Error: --r: 'm' after the number 2 is a name of the expression here, not a unit: write "
     "2*m for the product at column 3: '2 m, 0, 0'"),
    (["--omega", "0,0,2", "--vr", "1,0,0", "omega=1rad/s"],
     "Error: omega is given twice (--omega and omega=)"),
    (["--omega", "0,0,2", "--vr", "1/0, 0, 0 m/s"],
     "Error: --vr: a constant here overflows float64, divides by zero or takes a fractional "
     "power of a negative number at column 2: '1/0, 0, 0 m/s'"),
    (["--omega", "0,0,2", "--r", "2*t, 0, 0 m"],
     "Error: --r: component 1 depends on t: motion given in time needs --t (the time to "
     "evaluate at)"),
    (["--omega", "0,0,2 rad/s", "--r", "l, 0, 0", "l=2m", "--strict-units", "--vr",
      "sin(1),0,0"],
     "Error: --vr: 'sin(1),0,0' has no unit and --strict-units is on; write it with a unit, "
     "e.g. sin(1),0,0 m/s"),
])
def test_expression_refusals_point_at_the_character(args, message):
    assert refusal(*args) == message


# --------------------------------------------------------------------------------------------
# Earth mode: the horizontal part


def test_rail_example_total_force_against_the_sideways_push():
    """Issue 20's rail: 1458 N total but 995 N sideways. A train of 200 t running east at
    180 km/h at 43 deg N: |F_c| = 2 m W v (its velocity is perpendicular to the axis), and the
    push on level rails is the horizontal part, 2 m W v sin(phi) (the rest is vertical)."""
    out = run("--latitude", "43deg", "--speed", "180 km/h", "--heading", "90deg", "--mass",
              "200 t")
    W, m, v, phi = (mpmath.mpf(x) for x in ("7.2921159e-5", "2e5", "50", "43"))
    total = 2 * m * W * v
    sideways = total * mpmath.sin(mpmath.radians(phi))
    assert out["F_c_mag"] == pytest.approx(float(total), rel=1e-14)
    assert out["F_c_horizontal_mag"] == pytest.approx(float(sideways), rel=1e-14)
    assert round(out["F_c_mag"]) == 1458 and round(out["F_c_horizontal_mag"]) == 995
    assert out["F_c_horizontal"][2] == 0.0
    assert out["F_c_horizontal"][1] == pytest.approx(-float(sideways), rel=1e-14)  # south
    assert out["a_c_horizontal_mag"] == pytest.approx(float(sideways / m), rel=1e-14)


def test_horizontal_part_does_not_depend_on_the_heading():
    """For horizontal motion |a_c,h| = 2 W v sin(phi) = f v whatever the heading."""
    values = [run("--latitude", "-35deg", "--speed", "20 m/s", "--heading", f"{h}deg")
              for h in (0, 37, 90, 200)]
    f = values[0]["coriolis_parameter"]
    for out in values:
        assert out["a_c_horizontal_mag"] == pytest.approx(abs(f) * 20.0, rel=1e-14)


def test_textbook_rate_one_turn_a_day():
    """The textbook's Omega = 2 pi / day is --omega "1 turn/day" (not the sidereal rate)."""
    out = run("--latitude", "43deg", "--speed", "180 km/h", "--heading", "90deg", "--mass",
              "200 t", "--omega", "1 turn/day")
    W = 2 * mpmath.pi / 86400
    assert out["Omega"][1] == pytest.approx(float(W * mpmath.cos(mpmath.radians(43))),
                                            rel=1e-15)
    assert out["F_c_mag"] == pytest.approx(float(2 * 2e5 * W * 50), rel=1e-14)


# --------------------------------------------------------------------------------------------
# Scalar inverse problems


def value(*args):
    result = CliRunner().invoke(cli, ["coriolis", *args])
    assert result.exit_code == 0, result.output + result.stderr
    return [float(x) for x in result.stdout.split()]


def test_inverse_earth_speed_from_the_coriolis_acceleration():
    """a_c_mag = 0.01 m/s^2 at 45 deg N heading north: v = a / (2 W sin 45deg) (mpmath), and
    the forward one-off at that speed gives the 0.01 back."""
    (v,) = value("a_c_mag=0.01m/s^2", "--latitude", "45deg", "vr=?", "--value", "vr")
    W = mpmath.mpf("7.2921159e-5")
    assert v == pytest.approx(float(mpmath.mpf("0.01") / (2 * W * mpmath.sin(mpmath.pi / 4))),
                              rel=1e-14)
    (a,) = value("--latitude", "45deg", "--speed", f"{v!r} m/s", "--heading", "0deg",
                 "--value", "a_c_mag")
    assert a == pytest.approx(0.01, rel=1e-14)


def test_inverse_earth_latitude_and_mass_round_trip():
    (phi,) = value("a_c_mag=0.01m/s^2", "--speed", "100 m/s", "latitude=?", "--value",
                   "latitude")
    (a,) = value("--latitude", f"{phi!r} rad", "--speed", "100 m/s", "--heading", "0deg",
                 "--value", "a_c_mag")
    assert a == pytest.approx(0.01, rel=1e-12)
    assert 0 < phi < np.pi / 2  # the northern root; -phi gives the same |a_c|
    (m,) = value("F_c_horizontal_mag=995N", "--latitude", "43deg", "--speed", "180 km/h",
                 "--heading", "90deg", "mass=?", "--value", "mass")
    (push,) = value("--latitude", "43deg", "--speed", "180 km/h", "--heading", "90deg",
                    "--mass", f"{m!r} kg", "--value", "F_c_horizontal_mag")
    assert push == pytest.approx(995.0, rel=1e-13)


@pytest.mark.parametrize("unknown, given, expected", [
    ("vr", ["--omega", "2rad/s"], 3.0), ("omega", ["--vr", "3m/s"], 2.0),
])
def test_inverse_perpendicular_round_trip(unknown, given, expected):
    """a_c = 2 Omega v_r = 12 m/s^2 at Omega = 2 rad/s, v_r = 3 m/s, solved for each."""
    (x,) = value("a_c=12m/s^2", *given, f"{unknown}=?", "--value", unknown)
    assert x == pytest.approx(expected, rel=1e-15)
    (m,) = value("F_c=24N", "--omega", "2rad/s", "--vr", "3m/s", "mass=?", "--value", "mass")
    assert m == pytest.approx(2.0, rel=1e-15)


@pytest.mark.parametrize("args, message", [
    (["--omega", "2rad/s", "--vr", "3m/s", "mass=?"],
     "Error: mass=? needs a result to solve from: one of a_c, F_c, e.g. a_c=0.01m/s^2"),
    (["a_c_mag=0.01m/s^2", "--omega", "2rad/s", "vr=?"],
     "Error: a_c_mag= is not a result of this form: with magnitudes give one of a_c, F_c (or "
     "use --latitude)"),
    (["a_c=0.01m/s^2", "--omega", "2rad/s", "--r", "1m", "vr=?"],
     "Error: --r does not go with an inverse problem: coriolis solves a_c = 2 Omega v_r, "
     "F_c = m a_c for one unknown from omega, vr, mass"),
    (["a_c=0.01m/s^2", "--omega", "0,0,2", "vr=?"],
     "Error: --omega: an inverse problem takes magnitudes (perpendicular vectors), e.g. "
     "--omega 2rad/s; give vectors to compute forward"),
    (["a_c_mag=0.01m/s^2", "--speed", "1m/s", "latitude=?"],
     "Error: no value of latitude gives a_c_mag = 0.01 m/s^2 in coriolis-earth with the other "
     "parameters given; over the values of latitude tried it ranges from 0 to 0.000145842 "
     "m/s^2"),
])
def test_inverse_refusals(args, message):
    assert refusal(*args) == message


def test_python_api_takes_the_new_options_expressions_and_inverse_problems():
    import dyncalc

    out = dyncalc.coriolis(omega="0,0,2 rad/s", r="l, 0, 0", l="1.5 m", v0="0,-1,0 m/s",
                           vr="0.5*cos(60deg), 0, 0 m/s")
    assert out["v_transport"].to("m/s").magnitude.tolist() == [0.0, 2.0, 0.0]
    assert out["v"].to("m/s").magnitude.tolist() == pytest.approx([0.25, 2.0, 0.0],
                                                                  rel=1e-15)
    solved = dyncalc.coriolis(omega="2 rad/s", a_c="12 m/s^2", vr="?")
    assert solved["vr"].to("m/s").magnitude == pytest.approx(3.0, rel=1e-15)


def test_batch_of_expression_components_equals_the_one_off(tmp_path):
    """A CSV cell may hold component expressions; each row prints what the one-off prints."""
    path = tmp_path / "rows.csv"
    path.write_text('omega,vr,r,v0\n"0,0,2 rad/s","0.1*5*sin(35deg), 0, 0 m/s","1,0,0 m",'
                    '"0,1,0"\n"0,0,2","1,0,0","2,0,0","0,0,0"\n')
    result = CliRunner().invoke(cli, ["coriolis", "--batch", str(path)])
    assert result.exit_code == 0, result.output + result.stderr
    header, *rows = result.stdout.splitlines()
    assert header.split(",")[4:] == [
        "a_c [m/s^2]", "a_c_mag [m/s^2]", "a_euler [m/s^2]", "a_centripetal [m/s^2]",
        "a_transport [m/s^2]", "a [m/s^2]", "a_mag [m/s^2]", "a_transport_mag [m/s^2]",
        "v_transport [m/s]", "v_transport_mag [m/s]", "v [m/s]", "v_mag [m/s]"]
    one = CliRunner().invoke(cli, ["coriolis", "--omega", "0,0,2 rad/s", "--vr",
                                   "0.1*5*sin(35deg), 0, 0 m/s", "--r", "1,0,0 m", "--v0",
                                   "0,1,0", "--value", "v", "--value", "a_mag"])
    v, a_mag = one.stdout.split()
    cells = rows[0].split('"')
    assert v in cells and f",{a_mag}," in rows[0]


def test_near_parallel_vectors_keep_their_cross_product():
    """Omega and v_r parallel to 1 part in 2^60: a_c = 2 Omega x v_r is -2^-59 m/s^2 exactly
    (mpmath), where the float formula of the cross product gives 0; so is a_c in a batch."""
    Omega, v_r = [1.0 + 2.0 ** -30, 1.0, 0.0], [1.0, 1.0 - 2.0 ** -30, 0.0]
    with mpmath.workdps(50):
        z = 2 * (mpmath.mpf(Omega[0]) * mpmath.mpf(v_r[1]) - mpmath.mpf(Omega[1]) * v_r[0])
    assert float(z) == -(2.0 ** -59)
    out = run("--omega", vec(Omega), "--vr", vec(v_r), "--r", "1,2,3")
    assert out["a_c"].tolist() == [0.0, 0.0, float(z)]
    assert np.cross(Omega, v_r)[2] == 0.0  # what the plain formula would have said


@pytest.mark.parametrize("latitude, bearing", [("43deg", "bearing 180 deg"),
                                               ("0.75rad", "bearing 3.142 rad")])
def test_the_bearing_of_the_force_is_in_the_unit_the_latitude_was_typed_in(latitude, bearing):
    """The compass bearing (an atan2 of the east and north parts) follows the latitude's unit:
    radians typed, radians shown (the pi of a southward push, 4 digits); else degrees."""
    out = CliRunner().invoke(cli, ["coriolis", "--latitude", latitude, "--vr", "50, 0, 0 m/s",
                                   "--explain"])
    assert out.exit_code == 0, out.stderr
    line = next(l for l in out.stdout.splitlines() if "Coriolis force F_c = -m a_c points" in l)
    assert f"points south ({bearing}," in line
