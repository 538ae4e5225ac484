"""The rigid scenes of SCENES.md (natural-frequency table): rolling-disk-spring,
rolling-in-track, drum-block-spring, board-on-drums, clock-pendulum, pulley-block-spring,
disk-torsion-offset-mass, wheel-on-moving-beam, angled-member.

For each: (1) a textbook example through the CLI against the SCENES.md formula evaluated here
with mpmath; (2) an independent second derivation (Newton-Euler solved as a linear system, the
equation of motion integrated numerically, an eigenvalue problem, a numerical integral over the
body, or a limiting case through another scene); (3) unit invariance; (4) the refusals, with
their exact messages.
"""
import json
import math
import re

import numpy as np
import pytest
from click.testing import CliRunner
from mpmath import mp, mpf
from scipy.integrate import dblquad, quad, solve_ivp
from scipy.linalg import eig

from dyncalc.cli import cli
from dyncalc.errors import InputError, PhysicsError
from dyncalc.physics import rigid
from dyncalc.scenes import get_scene
from dyncalc.scenes.runner import run_scene

G = 9.80665
# Exact unit definitions (NIST): used to type the same physics in other units.
LB, FT, INCH, LBF = 0.45359237, 0.3048, 0.0254, 0.45359237 * 9.80665


def cli_json(scene, *words):
    result = CliRunner().invoke(cli, ["natural-frequency", "--scene", scene, *words, "--json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def cli_error(scene, *words):
    """The exit code and the one stderr line of a refusal."""
    result = CliRunner().invoke(cli, ["natural-frequency", "--scene", scene, *words])
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and "Traceback" not in result.stderr, result.stderr
    return result.exit_code, lines[0]


def omega(scene, **texts):
    """omega in rad/s from run_scene."""
    return run_scene(scene, texts).results["omega"].si


def mp_sqrt(x):
    with mp.workdps(30):
        return float(mp.sqrt(x))


def period_of(rhs, y0, t_end):
    """Mean period between upward zero crossings of y[0] of the integrated ODE."""
    def crossing(t, y):
        return y[0]

    crossing.direction = 1
    scale = abs(y0[0])
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", events=crossing, rtol=1e-12,
                    atol=1e-14 * scale)
    times = sol.t_events[0]
    assert len(times) >= 3
    return (times[-1] - times[0]) / (len(times) - 1)


# --- (1) the textbook examples through the CLI, against SCENES.md --------------------------

KAPPA = {"solid-sphere": mpf(2) / 5, "hollow-sphere": mpf(2) / 3, "solid-cylinder": mpf(1) / 2,
         "hollow-cylinder": mpf(1), "hoop": mpf(1)}


@pytest.mark.parametrize("body", list(KAPPA))
def test_rolling_disk_spring_example(body):
    """E4.8: omega^2 = k / ((1 + kappa) m); a disk gives 2k/(3m)."""
    data = cli_json("rolling-disk-spring", "k=300N/m", "m=2kg", f"body={body}")
    with mp.workdps(30):
        expected = float(mp.sqrt(mpf(300) / ((1 + KAPPA[body]) * 2)))
    assert data["results"]["omega"]["value"] == pytest.approx(expected, rel=1e-14)
    assert data["inputs"]["body"]["value"] == body


def test_rolling_disk_spring_disk_is_two_thirds():
    assert omega("rolling-disk-spring", k="300 N/m", m="2 kg") == pytest.approx(10.0,
                                                                                rel=1e-15)
    assert omega("rolling-disk-spring", k="3 N/m", m="2 kg", kappa="0.5") == pytest.approx(
        mp_sqrt(mpf(2) * 3 / (3 * 2)), rel=1e-15)


@pytest.mark.parametrize("body", list(KAPPA))
def test_rolling_in_track_example(body):
    """E4.9, E5.17: omega^2 = g / ((1 + kappa)(R - r))."""
    data = cli_json("rolling-in-track", "R=1m", "r=0.2m", f"body={body}")
    with mp.workdps(30):
        expected = float(mp.sqrt(mpf(G) / ((1 + KAPPA[body]) * (1 - mpf(0.2)))))
    assert data["results"]["omega"]["value"] == pytest.approx(expected, rel=1e-14)


def test_drum_block_spring_example():
    """E5.12: omega^2 = 2k / (M + 2m), no drum radius asked."""
    data = cli_json("drum-block-spring", "k=2kN/m", "m=4kg", "M=10kg")
    assert data["results"]["omega"]["value"] == pytest.approx(mp_sqrt(mpf(4000) / 18),
                                                              rel=1e-14)
    assert set(data["inputs"]) == {"k", "m", "M"}


@pytest.mark.parametrize("g", ["9.80665 m/s^2", "1.62 m/s^2"])
def test_board_on_drums_example(g):
    """E5.13: omega^2 = 2 mu g / a, whatever the drums' speed (it is not a parameter)."""
    data = cli_json("board-on-drums", "mu=0.4", "a=0.8m", f"g={g}")
    g_si = float(g.split()[0])
    assert data["results"]["omega"]["value"] == pytest.approx(
        mp_sqrt(2 * mpf(0.4) * mpf(g_si) / mpf(0.8)), rel=1e-14)
    assert data["inputs"]["sense"]["value"] == "inward"
    assert set(data["inputs"]) == {"mu", "a", "g", "sense"}


def test_clock_pendulum_example():
    """E5.15: J_A = m l^2/3 + M (r^2 + 2 a^2)/2, omega^2 = (m l + 2 M a) g / (2 J_A)."""
    data = cli_json("clock-pendulum", "m=0.5kg", "l=1m", "M=2kg", "r=0.1m", "a=0.9m")
    with mp.workdps(30):
        m, l, M, r, a = mpf(0.5), mpf(1), mpf(2), mpf(0.1), mpf(0.9)
        ja = m * l ** 2 / 3 + M * (r ** 2 + 2 * a ** 2) / 2
        expected = float(mp.sqrt((m * l + 2 * M * a) * G / (2 * ja)))
        ja = float(ja)
    assert data["results"]["omega"]["value"] == pytest.approx(expected, rel=1e-14)
    assert data["results"]["J_A"]["value"] == pytest.approx(ja, rel=1e-14)
    assert data["results"]["J_A"]["unit"] == "kg*m^2"


def test_pulley_block_spring_example():
    """E5.16: omega^2 = k / (4m + 3M/2)."""
    data = cli_json("pulley-block-spring", "k=1kN/m", "m=3kg", "M=4kg")
    assert data["results"]["omega"]["value"] == pytest.approx(mp_sqrt(mpf(1000) / 18),
                                                              rel=1e-14)


def test_disk_torsion_offset_mass_example():
    """E5.25: omega^2 = (kt + m g a) / (M R^2/2 + m (r^2/2 + a^2))."""
    data = cli_json("disk-torsion-offset-mass", "M=20kg", "R=0.3m", "m=2kg", "r=0.05m",
                    "a=0.2m", "kt=50 N*m/rad")
    with mp.workdps(30):
        M, R, m, r, a, kt = mpf(20), mpf(0.3), mpf(2), mpf(0.05), mpf(0.2), mpf(50)
        inertia = M * R ** 2 / 2 + m * (r ** 2 / 2 + a ** 2)
        expected = float(mp.sqrt((kt + m * G * a) / inertia))
        inertia = float(inertia)
    assert data["results"]["omega"]["value"] == pytest.approx(expected, rel=1e-14)
    assert data["results"]["J_A"]["value"] == pytest.approx(inertia, rel=1e-14)


@pytest.mark.parametrize("body", list(KAPPA))
def test_wheel_on_moving_beam_example(body):
    """E5.27: omega^2 = k / (m + M / (1 + M/(kappa m))) (the textbook's form)."""
    data = cli_json("wheel-on-moving-beam", "k=500N/m", "m=5kg", "M=20kg", f"body={body}")
    with mp.workdps(30):
        k, m, M, kappa = mpf(500), mpf(5), mpf(20), KAPPA[body]
        expected = float(mp.sqrt(k / (m + M / (1 + M / (kappa * m)))))
    assert data["results"]["omega"]["value"] == pytest.approx(expected, rel=1e-14)


def test_wheel_on_moving_beam_reports_the_drift_mode():
    result = CliRunner().invoke(cli, ["natural-frequency", "--scene", "wheel-on-moving-beam",
                                      "k=500N/m", "m=5kg", "M=20kg", "--explain"])
    assert result.exit_code == 0, result.stderr
    assert "zero frequency" in result.stdout and "drifts" in result.stdout


def test_angled_member_example():
    """E3.44: omega^2 = (sqrt(65)/14) g / l."""
    data = cli_json("angled-member", "l=0.5m")
    with mp.workdps(30):
        expected = float(mp.sqrt(mp.sqrt(65) / 14 * mpf(G) / mpf(0.5)))
    assert data["results"]["omega"]["value"] == pytest.approx(expected, rel=1e-14)
    with mp.workdps(40):
        assert rigid.ANGLED_MEMBER_FACTOR == float(mp.sqrt(mp.sqrt(65) / 14))


def test_every_example_result_is_what_the_cli_gives():
    """The catalog entries' example_result (computed with mpmath) against their commands."""
    import shlex

    for name in ["rolling-disk-spring", "rolling-in-track", "drum-block-spring",
                 "board-on-drums", "clock-pendulum", "pulley-block-spring",
                 "disk-torsion-offset-mass", "wheel-on-moving-beam", "angled-member"]:
        scene = get_scene(name)
        words = shlex.split(scene.example)
        assert words[:4] == ["dyncalc", "natural-frequency", "--scene", name]
        data = cli_json(name, *words[4:])
        for result, text in scene.example_result.items():
            value = float(text.split()[0])
            assert data["results"][result]["value"] == pytest.approx(value, rel=1e-14), name


# --- (2) independent derivations --------------------------------------------------------------

def test_rolling_disk_spring_newton_euler():
    """Newton-Euler with the friction force as an unknown, any radius: (x'', phi'', F)."""
    k, m, r = 300.0, 2.0, 0.37
    for kappa in (0.4, 0.5, 2 / 3, 1.0, 0.0):
        J = kappa * m * r * r
        x = 1e-3
        # m x'' = -k x + F;  J phi'' = -F r (clockwise phi);  x'' = r phi'' (rolling)
        A = np.array([[m, 0.0, -1.0], [0.0, J, r], [1.0, -r, 0.0]])
        xdd, _, _ = np.linalg.solve(A, [-k * x, 0.0, 0.0])
        assert omega("rolling-disk-spring", k="300 N/m", m="2 kg", kappa=repr(kappa)) == \
            pytest.approx(math.sqrt(-xdd / x), rel=1e-13)


def test_rolling_disk_spring_kappa_zero_is_a_sliding_block():
    assert omega("rolling-disk-spring", k="300 N/m", m="2 kg", kappa="0") == \
        omega("mass-spring", k="300 N/m", m="2 kg")


def test_rolling_in_track_integrated_newton_euler():
    """The body's motion from Newton-Euler (friction solved at each step), integrated."""
    R, r, m, kappa = 1.0, 0.2, 3.0, 0.4
    l, J = R - r, kappa * m * r * r

    def rhs(t, y):
        phi, dphi = y
        # unknowns: phi'' (centre on its circle), w' (body's spin, +z), F (friction along
        # e_theta). Tangential: m l phi'' = -m g sin phi + F. Spin: J w' = r F (contact at
        # r e_r). Rolling, contact at rest: l phi' + r w = 0.
        A = np.array([[m * l, 0.0, -1.0], [0.0, J, -r], [l, r, 0.0]])
        ddphi, _, _ = np.linalg.solve(A, [-m * G * math.sin(phi), 0.0, 0.0])
        return [dphi, ddphi]

    small = omega("rolling-in-track", R="1 m", r="0.2 m", body="solid-sphere")
    amplitude = 1e-3  # period error of small oscillations ~ amplitude^2/16 = 6e-8
    T = period_of(rhs, [amplitude, 0.0], 6 * 2 * math.pi / small)
    assert 2 * math.pi / T == pytest.approx(small, rel=2e-7)


def test_rolling_in_track_is_a_pendulum_of_length_1_plus_kappa_times_gap():
    for body, kappa in (("solid-sphere", "0.4"), ("hoop", "1")):
        length = (1 + float(kappa)) * (1.0 - 0.2)
        assert omega("rolling-in-track", R="1 m", r="0.2 m", body=body) == pytest.approx(
            omega("pendulum", l=repr(length)), rel=1e-15)
    assert omega("rolling-in-track", R="1 m", r="0.2 m", kappa="0") == \
        omega("pendulum", l=repr(1.0 - 0.2))


def test_rolling_in_track_gap_kept_in_the_unit_typed():
    """A body a hair smaller than its track: R - r in mm keeps every digit of the gap."""
    got = omega("rolling-in-track", R="1000.001 mm", r="1000 mm", kappa="0")
    with mp.workdps(30):
        gap = (mpf(1000.001) - 1000) / 1000
        assert got == pytest.approx(float(mp.sqrt(G / gap)), rel=1e-12)


def test_drum_block_spring_newton_euler_any_radius():
    """Block: m x'' = -k x - S; drum: (M R^2/2) phi'' = S R; rope: x = R phi."""
    k, m, M, x = 2000.0, 4.0, 10.0, 1e-2
    for R in (0.05, 0.3, 7.0):
        A = np.array([[m, 0.0, 1.0], [0.0, M * R * R / 2, -R], [1.0, -R, 0.0]])
        xdd, _, _ = np.linalg.solve(A, [-k * x, 0.0, 0.0])
        assert omega("drum-block-spring", k="2 kN/m", m="4 kg", M="10 kg") == pytest.approx(
            math.sqrt(-xdd / x), rel=1e-13)


def _board_rhs(mu, a, m, surface_speed, sense):
    """The board on the drums: normal forces from the moment balance, friction from the
    direction of sliding. Inward: the left drum's top moves right, the right one's left."""
    left_top = surface_speed if sense == "inward" else -surface_speed
    right_top = -left_top

    def rhs(t, y):
        x, v = y
        n_left = m * G * (a / 2 - x) / a      # moments about the right drum
        n_right = m * G * (a / 2 + x) / a     # moments about the left drum
        force = (mu * n_left * math.copysign(1.0, left_top - v)
                 + mu * n_right * math.copysign(1.0, right_top - v))
        return [v, force / m]

    return rhs


def test_board_on_drums_simulated_at_two_drum_speeds():
    """The period of the simulated board does not depend on the drums' speed (nor the mass)."""
    mu, a = 0.4, 0.8
    expected = omega("board-on-drums", mu="0.4", a="0.8 m")
    for speed, mass in ((2.0, 3.0), (40.0, 50.0)):
        T = period_of(_board_rhs(mu, a, mass, speed, "inward"), [0.01, 0.0],
                      5 * 2 * math.pi / expected)
        assert 2 * math.pi / T == pytest.approx(expected, rel=1e-8)


def test_board_on_drums_outward_runs_off_at_the_rate_in_the_message():
    with pytest.raises(PhysicsError) as err:
        run_scene("board-on-drums", {"mu": "0.4", "a": "0.8 m", "sense": "outward"})
    rate = float(re.search(r"= ([0-9.]+) 1/s", str(err.value)).group(1))
    x0, t = 1e-6, 2.0
    sol = solve_ivp(_board_rhs(0.4, 0.8, 3.0, 5.0, "outward"), (0, t), [x0, 0.0],
                    method="DOP853", rtol=1e-12, atol=1e-18)
    measured = math.acosh(sol.y[0, -1] / x0) / t   # x = x0 cosh(lambda t)
    assert measured == pytest.approx(rate, rel=1e-5)
    assert rate == pytest.approx(math.sqrt(2 * 0.4 * G / 0.8), rel=1e-5)


def test_clock_pendulum_is_a_physical_pendulum_of_rod_and_disk():
    """Combine the parts by hand: total mass, centre of mass, J about the pivot."""
    m, l, M, r, a = 0.5, 1.0, 2.0, 0.1, 0.9
    total = m + M
    centre = (m * l / 2 + M * a) / total
    j_pivot = (m * l * l / 12 + m * (l / 2) ** 2) + (M * r * r / 2 + M * a * a)
    result = run_scene("clock-pendulum", {"m": "0.5 kg", "l": "1 m", "M": "2 kg",
                                          "r": "0.1 m", "a": "0.9 m"})
    reference = run_scene("physical-pendulum", {"m": repr(total), "a": repr(centre),
                                                "J_A": repr(j_pivot)})
    assert result.results["omega"].si == pytest.approx(reference.results["omega"].si,
                                                       rel=1e-14)
    assert result.results["J_A"].si == pytest.approx(j_pivot, rel=1e-14)


def test_pulley_block_spring_newton_euler_any_radius():
    """Unknowns y'' (pulley centre), S1 (fixed strand), S2 (block's strand), any radius.

    Pulley: M y'' = S1 + S2 - k y; spin (rolling on the fixed strand, w r = y'):
    (M r^2/2)(y''/r) = (S2 - S1) r; the block moves 2y against S2: 2 m y'' = -S2.
    """
    k, m, M, y = 1000.0, 3.0, 4.0, 1e-3
    for r in (0.02, 0.5):
        A = np.array([[M, -1.0, -1.0], [M * r / 2, r, -r], [2 * m, 0.0, 1.0]])
        ydd, _, _ = np.linalg.solve(A, [-k * y, 0.0, 0.0])
        assert omega("pulley-block-spring", k="1 kN/m", m="3 kg", M="4 kg") == \
            pytest.approx(math.sqrt(-ydd / y), rel=1e-13)


def test_disk_torsion_offset_mass_by_integration_and_energy():
    """J from integrating r^2 dm over both disks; the stiffness as V''(0) of the true
    potential (shaft plus the small disk's weight), by a central difference."""
    M, R, m, r, a, kt = 20.0, 0.3, 2.0, 0.05, 0.2, 50.0
    j_large = dblquad(lambda s, t: (M / (math.pi * R * R)) * s ** 3, 0, 2 * math.pi, 0, R)[0]

    def small_disk(s, t):  # polar about the small disk's centre (0, -a)
        x, y = s * math.cos(t), -a + s * math.sin(t)
        return (m / (math.pi * r * r)) * (x * x + y * y) * s

    j_small = dblquad(small_disk, 0, 2 * math.pi, 0, r, epsabs=1e-14, epsrel=1e-13)[0]

    def potential(phi):
        return kt * phi * phi / 2 + m * G * a * (1 - math.cos(phi))

    h = 1e-3
    stiffness = (potential(h) - 2 * potential(0.0) + potential(-h)) / (h * h)
    result = run_scene("disk-torsion-offset-mass", {"M": "20 kg", "R": "0.3 m", "m": "2 kg",
                                                    "r": "0.05 m", "a": "0.2 m",
                                                    "kt": "50 N*m/rad"})
    assert result.results["J_A"].si == pytest.approx(j_large + j_small, rel=1e-10)
    assert result.results["omega"].si == pytest.approx(
        math.sqrt(stiffness / (j_large + j_small)), rel=1e-7)


def test_disk_torsion_offset_mass_limits():
    base = {"M": "20 kg", "R": "0.3 m", "m": "2 kg", "r": "0.05 m", "a": "0.2 m"}
    # no shaft: a physical pendulum of the offset disk, with the large disk as extra inertia
    no_shaft = run_scene("disk-torsion-offset-mass", {**base, "kt": "0 N*m/rad"})
    pendulum = run_scene("physical-pendulum", {"m": "2 kg", "a": "0.2 m",
                                               "J": repr(20 * 0.3 ** 2 / 2 + 2 * 0.05 ** 2 / 2)})
    assert no_shaft.results["omega"].si == pytest.approx(pendulum.results["omega"].si,
                                                         rel=1e-14)
    # centred small disk: a torsional oscillator
    centred = omega("disk-torsion-offset-mass", **{**base, "a": "0 m"}, kt="50 N*m/rad")
    assert centred == pytest.approx(
        omega("torsional", kt="50 N*m/rad", J=repr(20 * 0.3 ** 2 / 2 + 2 * 0.05 ** 2 / 2)),
        rel=1e-14)


@pytest.mark.parametrize("kappa", [0.0, 0.4, 0.5, 1.0, 3.0])
def test_wheel_on_moving_beam_eigenvalues(kappa):
    """Lagrange: T = m x'^2/2 + kappa m (x' - X')^2/2 + M X'^2/2, V = k x^2/2; the
    generalised eigenvalues of (K, M) are 0 (the beam's drift) and omega^2."""
    k, m, M = 500.0, 5.0, 20.0
    mass = np.array([[m + kappa * m, -kappa * m], [-kappa * m, M + kappa * m]])
    stiff = np.array([[k, 0.0], [0.0, 0.0]])
    values, vectors = eig(stiff, mass)
    values = np.sort(values.real)
    assert abs(values[0]) < 1e-12 * values[1]
    got = omega("wheel-on-moving-beam", k="500 N/m", m="5 kg", M="20 kg", kappa=repr(kappa))
    assert got == pytest.approx(math.sqrt(values[1]), rel=1e-13)


def test_wheel_on_moving_beam_limits():
    wheel = {"k": "500 N/m", "m": "5 kg"}
    # a frictionless slider (kappa = 0) ignores the beam
    assert omega("wheel-on-moving-beam", **wheel, M="20 kg", kappa="0") == pytest.approx(
        omega("mass-spring", **wheel), rel=1e-15)
    # a beam far heavier than the wheel is the fixed floor of rolling-disk-spring
    assert omega("wheel-on-moving-beam", **wheel, M="1e12 kg", body="hoop") == pytest.approx(
        omega("rolling-disk-spring", **wheel, body="hoop"), rel=1e-11)
    # a weightless beam turns with the wheel: again the bare mass
    assert omega("wheel-on-moving-beam", **wheel, M="1e-12 kg") == pytest.approx(
        omega("mass-spring", **wheel), rel=1e-11)


def test_angled_member_by_integration_over_the_bar():
    """Centre of mass and J about the pivot integrated along the bent bar (rho per length)."""
    l, rho = 0.5, 1.7
    # long arm from the pivot (0, 0) to (2l, 0); short arm from (2l, 0) to (2l, l)
    mass = rho * 3 * l
    sx = quad(lambda s: rho * s, 0, 2 * l)[0] + quad(lambda s: rho * 2 * l, 0, l)[0]
    sy = quad(lambda s: rho * s, 0, l)[0]
    j_pivot = (quad(lambda s: rho * s * s, 0, 2 * l)[0]
               + quad(lambda s: rho * ((2 * l) ** 2 + s * s), 0, l)[0])
    distance = math.hypot(sx, sy) / mass
    expected = math.sqrt(mass * G * distance / j_pivot)
    assert omega("angled-member", l="0.5 m") == pytest.approx(expected, rel=1e-13)
    # the same through the physical-pendulum scene
    assert omega("physical-pendulum", m=repr(mass), a=repr(distance),
                 J_A=repr(j_pivot)) == pytest.approx(expected, rel=1e-13)


# --- extreme magnitudes: no overflow midway ----------------------------------------------------

@pytest.mark.parametrize("scene, texts, formula", [
    ("drum-block-spring", {"k": "1.5e308 N/m", "m": "1.5e308 kg", "M": "1e308 kg"},
     lambda v: 2 * v["k"] / (v["M"] + 2 * v["m"])),
    ("pulley-block-spring", {"k": "1e-300 N/m", "m": "1e300 kg", "M": "1e300 kg"},
     lambda v: v["k"] / (4 * v["m"] + 3 * v["M"] / 2)),
    ("clock-pendulum", {"m": "1e200 kg", "l": "1e200 m", "M": "3e200 kg", "r": "1e199 m",
                        "a": "8e199 m"},
     lambda v: (v["m"] * v["l"] + 2 * v["M"] * v["a"]) * G
     / (2 * (v["m"] * v["l"] ** 2 / 3 + v["M"] * (v["r"] ** 2 + 2 * v["a"] ** 2) / 2))),
    ("wheel-on-moving-beam", {"k": "1e300 N/m", "m": "1.7e308 kg", "M": "1.7e308 kg"},
     lambda v: v["k"] / (v["m"] + v["M"] / (1 + v["M"] / (mpf("0.5") * v["m"])))),
    ("disk-torsion-offset-mass", {"M": "1e250 kg", "R": "1e100 m", "m": "1e250 kg",
                                  "r": "1e99 m", "a": "1e100 m", "kt": "1e300 N*m/rad"},
     lambda v: (v["kt"] + v["m"] * G * v["a"])
     / (v["M"] * v["R"] ** 2 / 2 + v["m"] * (v["r"] ** 2 / 2 + v["a"] ** 2))),
    ("rolling-disk-spring", {"k": "1e-320 N/m", "m": "1e300 kg", "kappa": "0.5"},
     lambda v: v["k"] / ((1 + v["kappa"]) * v["m"])),
    ("angled-member", {"l": "1e-320 m"}, lambda v: mp.sqrt(65) / 14 * G / v["l"]),
])
def test_extreme_magnitudes(scene, texts, formula):
    with mp.workdps(40):
        values = {name: mpf(float(text.split()[0])) for name, text in texts.items()}
        expected = float(mp.sqrt(formula(values)))
    assert omega(scene, **texts) == pytest.approx(expected, rel=1e-14)


# --- (3) unit invariance -------------------------------------------------------------------

UNITS = [
    ("rolling-disk-spring", {"k": "2.5 lbf/in", "m": "3 lb", "body": "solid-sphere"},
     {"k": 2.5 * LBF / INCH, "m": 3 * LB, "body": "solid-sphere"}),
    ("rolling-in-track", {"R": "3 ft", "r": "5 in", "g": "32.174 ft/s^2"},
     {"R": 3 * FT, "r": 5 * INCH, "g": 32.174 * FT}),
    ("drum-block-spring", {"k": "20 lbf/in", "m": "4000 g", "M": "22 lb"},
     {"k": 20 * LBF / INCH, "m": 4.0, "M": 22 * LB}),
    ("board-on-drums", {"mu": "0.35", "a": "750 mm", "g": "32 ft/s^2"},
     {"mu": 0.35, "a": 0.75, "g": 32 * FT}),
    ("clock-pendulum", {"m": "1.1 lb", "l": "39 in", "M": "4.4 lb", "r": "4 in", "a": "35 in"},
     {"m": 1.1 * LB, "l": 39 * INCH, "M": 4.4 * LB, "r": 4 * INCH, "a": 35 * INCH}),
    ("pulley-block-spring", {"k": "6 lbf/in", "m": "6.6 lb", "M": "9 lb"},
     {"k": 6 * LBF / INCH, "m": 6.6 * LB, "M": 9 * LB}),
    ("disk-torsion-offset-mass", {"M": "44 lb", "R": "1 ft", "m": "4.4 lb", "r": "2 in",
                                  "a": "8 in", "kt": "40 lbf*ft/rad"},
     {"M": 44 * LB, "R": FT, "m": 4.4 * LB, "r": 2 * INCH, "a": 8 * INCH,
      "kt": 40 * LBF * FT}),
    ("wheel-on-moving-beam", {"k": "3 lbf/in", "m": "11 lb", "M": "44 lb", "kappa": "0.6"},
     {"k": 3 * LBF / INCH, "m": 11 * LB, "M": 44 * LB, "kappa": 0.6}),
    ("angled-member", {"l": "20 in", "g": "32.174 ft/s^2"}, {"l": 20 * INCH, "g": 32.174 * FT}),
]


@pytest.mark.parametrize("scene, other, si", UNITS, ids=[u[0] for u in UNITS])
def test_unit_invariance(scene, other, si):
    si_texts = {name: value if isinstance(value, str) else repr(value)
                for name, value in si.items()}
    in_other = run_scene(scene, other)
    in_si = run_scene(scene, si_texts)
    assert in_other.results["omega"].si == pytest.approx(in_si.results["omega"].si, rel=1e-12)
    for name, entry in in_si.results.items():
        assert in_other.results[name].si == pytest.approx(entry.si, rel=1e-12), name


def test_kt_in_degrees():
    """A torsional stiffness per degree is 180/pi times the same number per radian."""
    base = {"M": "20 kg", "R": "0.3 m", "m": "2 kg", "r": "0.05 m", "a": "0.2 m"}
    assert omega("disk-torsion-offset-mass", **base, kt="1 N*m/deg") == pytest.approx(
        omega("disk-torsion-offset-mass", **base, kt=f"{180 / math.pi!r} N*m/rad"),
        rel=1e-14)


# --- (4) refusals ------------------------------------------------------------------------------

DRUM_PARAMS = ("the parameters of drum-block-spring are: k [force]/[length], m [mass], "
               "M [mass], zeta dimensionless?")
DISK_PARAMS = ("the parameters of rolling-disk-spring are: k [force]/[length], m [mass], "
               "body {solid-sphere, hollow-sphere, solid-cylinder, hollow-cylinder, hoop} = "
               "solid-cylinder, kappa dimensionless?, zeta dimensionless?")
TRACK = ("rolling-in-track needs R > r: the body rolls inside the track, so its radius r must "
         "be smaller than the track's radius R")
OUTWARD = ("with the drums turning outward (tops moving apart) the board does not oscillate: "
           "friction pushes it further from the middle and it runs off exponentially, any "
           "offset growing like exp(lambda t) with lambda = sqrt(2 mu g / a) = 3.13156 1/s; "
           "with sense=inward it oscillates at omega = 3.13156 rad/s")
BODY = ("body must be one of solid-sphere, hollow-sphere, solid-cylinder, hollow-cylinder, "
        "hoop; got 'cube'")

REFUSALS = [
    ("missing", "drum-block-spring", {"k": "2kN/m", "m": "4kg"},
     f"drum-block-spring needs M; {DRUM_PARAMS}"),
    ("drum-radius", "drum-block-spring", {"k": "2kN/m", "m": "4kg", "M": "10kg", "R": "0.2m"},
     f"drum-block-spring has no parameter 'R'; {DRUM_PARAMS}"),
    ("R-equals-r", "rolling-in-track", {"R": "0.2m", "r": "0.2m"}, TRACK),
    ("R-below-r", "rolling-in-track", {"R": "10cm", "r": "0.2m", "body": "hoop"}, TRACK),
    ("body-and-kappa", "rolling-disk-spring", {"k": "1N/m", "m": "1kg", "body": "hoop",
                                                "kappa": "1"},
     f"rolling-disk-spring: give body or kappa, not both; {DISK_PARAMS}"),
    ("unknown-body", "rolling-disk-spring", {"k": "1N/m", "m": "1kg", "body": "cube"}, BODY),
    ("negative-mass", "pulley-block-spring", {"k": "1N/m", "m": "-2kg", "M": "1kg"},
     "m must be positive; got -2 kilogram"),
    ("negative-kappa", "wheel-on-moving-beam", {"k": "1N/m", "m": "1kg", "M": "1kg",
                                                 "kappa": "-0.1"},
     "kappa must not be negative; got -0.1"),
    ("outward", "board-on-drums", {"mu": "0.4", "a": "0.8m", "sense": "outward"}, OUTWARD),
    ("unknown-sense", "board-on-drums", {"mu": "0.4", "a": "0.8m", "sense": "up"},
     "sense must be one of inward, outward; got 'up'"),
    ("no-friction", "board-on-drums", {"mu": "0", "a": "0.8m"}, "mu must be positive; got 0"),
    ("no-restoring", "disk-torsion-offset-mass", {"M": "1kg", "R": "1m", "m": "1kg",
                                                   "r": "0.1m", "a": "0m", "kt": "0 N*m/rad"},
     "with kt = 0 and a = 0 nothing pulls the disk back (neutral equilibrium): it does not "
     "oscillate"),
    ("wrong-dimension", "clock-pendulum", {"m": "1kg", "l": "1kg", "M": "1kg", "r": "1m",
                                            "a": "1m"},
     "l must be a length [length]; got 1 kilogram ([mass])"),
    ("unknown-parameter", "angled-member", {"l": "1m", "m": "2kg"},
     "angled-member has no parameter 'm'; the parameters of angled-member are: l [length], "
     "g [length]/[time]^2 = 9.80665 m/s^2, zeta dimensionless?"),
]


@pytest.mark.parametrize("scene, texts, message", [r[1:] for r in REFUSALS],
                         ids=[r[0] for r in REFUSALS])
def test_refusal_message(scene, texts, message):
    with pytest.raises(InputError) as err:
        run_scene(scene, texts)
    assert str(err.value) == message


@pytest.mark.parametrize("scene, texts, message", [r[1:] for r in REFUSALS],
                         ids=[r[0] for r in REFUSALS])
def test_refusal_through_the_cli(scene, texts, message):
    code, line = cli_error(scene, *(f"{name}={text}" for name, text in texts.items()))
    assert code == 2
    assert line == f"Error: {message}"


def test_outward_is_a_physics_error():
    with pytest.raises(PhysicsError):
        run_scene("board-on-drums", {"mu": "0.4", "a": "0.8m", "sense": "outward"})


def test_physics_functions_refuse_directly():
    from dyncalc.units import Q_

    with pytest.raises(PhysicsError, match="must be smaller than the track"):
        rigid.rolling_in_track(Q_(1, "m"), Q_(2, "m"), Q_(G, "m/s^2"))
    with pytest.raises(PhysicsError, match="kappa"):
        rigid.rolling_disk_spring(Q_(1, "N/m"), Q_(1, "kg"), -1.0)
    with pytest.raises(PhysicsError, match="inward or outward"):
        rigid.board_on_drums(0.4, Q_(1, "m"), Q_(G, "m/s^2"), "sideways")
