"""The relative-motion scenes through ``coriolis --scene`` (SCENES.md, "Relative-motion
scenes"): radial-slot-release (E6.7) and slotted-link (E6.9).

References found independently: the block's equation of motion integrated with scipy up to the
rim (an event), the slotted link's geometry differentiated by central finite differences, the
book's instant by hand, and ``eom``'s own Lagrange equations of the same scene.
"""
import json
import math

import numpy as np
import pytest

from tests.helpers import error_line, invoke, json_of


def scene(name, *words):
    data = json_of("coriolis", "--scene", name, *words)
    assert data["scene"] == name
    return {k: v["value"] for k, v in data["results"].items()}


def test_slotted_link_at_the_books_instant():
    """d = 4 l, c = 3 l, theta = 90 deg, drum clockwise at w: omega_AD = -9 w/25,
    v_r = 12 w l/5 (l = 0.25 m, w = 2 rad/s)."""
    got = scene("slotted-link", "d=1m", "c=0.75m", "theta=90deg", "omega=-2rad/s")
    assert got["rho"] == 1.25
    assert got["omega_AD"] == pytest.approx(-9 * 2 / 25, rel=1e-15)
    assert got["v_r"] == pytest.approx(12 * 2 * 0.25 / 5, rel=1e-15)
    assert got["v_C"] == 1.5


@pytest.mark.parametrize("d, c, theta, omega", [
    (0.4, 0.3, 35.0, -10.0), (0.2, 0.5, 160.0, 3.0), (1.0, 0.999, 179.0, 1.0),
    (0.3, 0.3, -60.0, 7.0),
])
def test_slotted_link_against_the_geometry_differentiated(d, c, theta, omega):
    """A at the origin, B at (d, 0), C = B + c (cos, sin)(theta + omega t): the link's angle
    and AC differentiated at t = 0."""
    got = scene("slotted-link", f"d={d}m", f"c={c}m", f"theta={theta}deg",
                f"omega={omega}rad/s")
    h = 1e-6

    def pin(s):
        angle = math.radians(theta) + omega * s
        return np.array([d + c * math.cos(angle), c * math.sin(angle)])

    angle = [math.atan2(*pin(s)[::-1]) for s in (-h, h)]
    length = [np.hypot(*pin(s)) for s in (-h, h)]
    assert got["rho"] == pytest.approx(np.hypot(*pin(0.0)), rel=1e-14)
    assert got["omega_AD"] == pytest.approx((angle[1] - angle[0]) / (2 * h), rel=1e-7)
    assert got["v_r"] == pytest.approx((length[1] - length[0]) / (2 * h), rel=1e-7, abs=1e-9)
    assert got["v_C"] == pytest.approx(c * abs(omega), rel=1e-15)


def test_radial_slot_release_against_the_integrated_equation_of_motion():
    """x'' = Omega^2 x from x = a at rest, integrated to x = r: t_R, v_r, and the absolute
    speed hypot(v_r, Omega r); the side force 2 m Omega v_r."""
    from scipy.integrate import solve_ivp

    W, a, r, m = 3.0, 0.05, 0.4, 0.3
    rim = lambda s, y: y[0] - r  # noqa: E731
    rim.terminal = True
    sol = solve_ivp(lambda s, y: [y[1], W * W * y[0]], (0, 10), [a, 0.0], events=rim,
                    rtol=1e-12, atol=1e-14, method="DOP853")
    t_R, (x, v) = sol.t_events[0][0], sol.y_events[0][0]
    assert x == pytest.approx(r, rel=1e-12)
    got = scene("radial-slot-release", f"Omega={W}rad/s", f"a={a}m", f"r={r}m", f"m={m}kg")
    assert got["t_R"] == pytest.approx(t_R, rel=1e-9)
    assert got["v_r"] == pytest.approx(v, rel=1e-9)
    assert got["v_abs"] == pytest.approx(math.hypot(v, W * r), rel=1e-9)
    assert got["F_slot"] == pytest.approx(2 * m * W * v, rel=1e-9)


def test_radial_slot_release_at_a_time_matches_the_motion_given_in_time():
    """The scene's x_t, v_t, F_t against coriolis --r "a*cosh(W*t), 0, 0 m": there the
    radial absolute acceleration vanishes (the slot is frictionless) and the side one is
    2 W v_t = F_t/m."""
    W, a, r, m, t = 2.0, 0.1, 0.5, 0.2, 0.6
    got = scene("radial-slot-release", f"Omega={W}rad/s", f"a={a}m", f"r={r}m", f"m={m}kg",
                f"t={t}s")
    data = json_of("coriolis", "--r", "a*cosh(W*t), 0, 0 m", f"a={a}m", f"W={W}rad/s",
                   "--omega", "0, 0, W", "--t", f"{t}s", "--mass", f"{m}kg")["results"]
    assert data["r"]["value"][0] == pytest.approx(got["x_t"], rel=1e-15)
    assert data["v_r"]["value"][0] == pytest.approx(got["v_t"], rel=1e-15)
    assert data["a"]["value"][0] == pytest.approx(0.0, abs=1e-14)
    assert data["a"]["value"][1] == pytest.approx(got["F_t"] / m, rel=1e-14)
    assert data["F_c_mag"]["value"] == pytest.approx(got["F_t"], rel=1e-14)


def test_eom_gives_the_acceleration_of_the_scenes_x_of_t():
    """eom --scene radial-slot-release at the state (x_t, v_t) gives x'' = Omega^2 x_t, the
    same as the finite-difference derivative of the scene's own v_t."""
    W, a, r, t, h = 2.0, 0.1, 0.5, 0.6, 1e-5
    v = [scene("radial-slot-release", f"Omega={W}rad/s", f"a={a}m", f"r={r}m",
               f"t={s!r}s")["v_t"] for s in (t - h, t + h)]
    now = scene("radial-slot-release", f"Omega={W}rad/s", f"a={a}m", f"r={r}m", f"t={t}s")
    eom = json_of("eom", "--scene", "radial-slot-release", "m=1kg", f"Omega={W}rad/s",
                  f"x={now['x_t']!r}m", f"x_dot={now['v_t']!r}m/s")
    x_ddot = eom["results"]["x_ddot"]["value"]
    assert x_ddot == pytest.approx((v[1] - v[0]) / (2 * h), rel=1e-8)
    assert x_ddot == pytest.approx(W * W * now["x_t"], rel=1e-14)


def test_unit_invariance():
    base = scene("radial-slot-release", "Omega=30rpm", "a=0.1m", "r=0.5m", "m=0.2kg",
                 "t=0.5s")
    other = scene("radial-slot-release", f"Omega={math.pi}rad/s", "a=10cm", "r=500mm",
                  "m=200g", "t=500ms")
    for name, value in base.items():
        assert other[name] == pytest.approx(value, rel=1e-14), name


def test_coriolis_takes_exactly_the_relative_motion_scenes():
    listed = json.loads(invoke("scenes", "--command", "coriolis", "--json").stdout)
    assert [s["name"] for s in listed["scenes"]] == ["radial-slot-release", "slotted-link"]
    others = json.loads(invoke("scenes", "--command", "natural-frequency", "--json").stdout)
    assert not {"radial-slot-release", "slotted-link"} & {s["name"] for s in others["scenes"]}


@pytest.mark.parametrize("args, message", [
    (["coriolis", "--scene", "radial-slot-release", "Omega=2rad/s", "a=0.5m", "r=0.5m"],
     "Error: radial-slot-release needs 0 < a < r: the block is released inside the radius r "
     "it reaches (a block released at the centre stays there, unstably)"),
    (["coriolis", "--scene", "radial-slot-release", "Omega=2rad/s", "a=0.1m", "r=0.5m",
      "t=2s"],
     "Error: t = 2 s is after t_R = 1.14622 s, when the block reaches r = 0.5 m: x(t) = "
     "a cosh(Omega t) holds only inside the slot"),
    (["coriolis", "--scene", "slotted-link", "d=0.3m", "c=0.3m", "theta=180deg",
      "omega=1rad/s"],
     "Error: rho = AC is zero: the pin C reaches the pivot A (c = d, theta = 180 deg) and the "
     "link's angle is undefined there"),
    (["coriolis", "--scene", "pendulum", "l=1m"],
     "Error: --scene pendulum is not a relative-motion scene; coriolis takes "
     "radial-slot-release, slotted-link (dyncalc scenes --command coriolis)"),
    (["coriolis", "--scene", "radial-slot-release", "Omega=2rad/s", "a=0.1m", "r=0.5m",
      "--vr", "1m/s"],
     "Error: --vr does not go with --scene radial-slot-release: give its parameters as "
     "NAME=QUANTITY words (Omega [angle]/[time], a [length], r [length], m [mass]?, "
     "t [time]?)"),
    (["natural-frequency", "--scene", "slotted-link", "d=1m"],
     "Error: --scene slotted-link is a relative-motion scene with no frequency: run it with "
     "dyncalc coriolis --scene slotted-link"),
])
def test_refusals(args, message):
    assert error_line(invoke(*args)) == message
