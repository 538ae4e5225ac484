"""``forced-response --scene NAME`` for the catalog's single-degree-of-freedom scenes, driven
by ``--F0`` on their coordinate (dyncalc.scenes.sdof, dyncalc.physics.sdof).

* omega is natural-frequency's omega to the bit, for every scene at random parameters;
* m_eff and k_eff against the kinetic and potential energies of each set-up, written out here
  independently (mpmath at 30 digits);
* the amplitude and phase against a numerical integration (scipy solve_ivp to the steady state)
  of the set-up's own equations of motion: a displacement (the wheel on a free beam, two
  degrees of freedom integrated together), an angle (the clock pendulum with its full
  ``sin phi``, a torsional damper in N*m*s/rad) and a scene with its own damping;
* unit invariance; the refusals with their exact messages and exit status.
"""
import json
import math
import random

import mpmath
import pytest
from click.testing import CliRunner

from dyncalc.cli import cli
from dyncalc.commands.forced_response import forced_response
from dyncalc.commands.natural_frequency import natural_frequency
from dyncalc.scenes import catalog
from dyncalc.scenes.forced import DRIVEN, forced_scene_names
from dyncalc.scenes.sdof import COORDINATES, forced_example

G = 9.80665


def _u(rng, low, high):
    """A random positive number, log-uniform in [low, high], as a repr (every digit)."""
    return math.exp(rng.uniform(math.log(low), math.log(high)))


#: Per scene: random parameters (SI numbers by name) and the independent m_eff, k_eff (mpmath,
#: from the set-up's kinetic and potential energy in its coordinate).
def _params(name, rng):
    u = lambda lo=0.1, hi=10.0: _u(rng, lo, hi)  # noqa: E731
    if name == "rolling-in-track":
        r = u(0.01, 1.0)
        return {"R": r + u(0.01, 1.0), "r": r, "m": u(), "kappa": rng.choice([0.4, 0.5, 1.0])}
    if name == "bead-on-rotating-ring":
        r = u(0.1, 2.0)
        return {"r": r, "Omega": math.sqrt(G / r) * rng.uniform(0.1, 0.9), "m": u()}
    if name == "rod-torsion-spring":
        m, l = u(), u(0.2, 2.0)
        return {"m": m, "l": l, "kt": m * G * l * rng.uniform(0.5, 5.0)}
    if name == "pendulum-spring-dashpot":
        return {"m": u(), "a": u(0.1, 1.0), "k": u(10, 1000), "d": u(0.01, 1.0)}
    if name == "rod-in-fluid":
        return {"m": u(), "l": u(0.2, 2.0), "beta": u(0.01, 1.0)}
    names = {"mass-spring": ("k", "m"), "torsional": ("kt", "J"), "pendulum": ("l", "m"),
             "physical-pendulum": ("m", "a", "J"), "rolling-disk-spring": ("k", "m"),
             "drum-block-spring": ("k", "m", "M"), "board-on-drums": ("mu", "a", "m"),
             "clock-pendulum": ("m", "l", "M", "r", "a"), "pulley-block-spring": ("k", "m", "M"),
             "disk-torsion-offset-mass": ("M", "R", "m", "r", "a", "kt"),
             "wheel-on-moving-beam": ("k", "m", "M"), "angled-member": ("l", "m"),
             "half-cylinder-shell": ("r", "m"),
             "pendulum-accelerating-support": ("l", "a0", "m"),
             "pendulum-on-rotating-disk": ("r", "l", "Omega", "m")}[name]
    out = {n: u() for n in names}
    if name in ("rolling-disk-spring", "wheel-on-moving-beam"):
        out["kappa"] = rng.choice([0.4, 0.5, 2 / 3, 1.0])
    if name == "board-on-drums":
        out["mu"] = rng.uniform(0.05, 0.9)
    return out


def _energies(name, p):
    """(m_eff, k_eff) of scene ``name`` at parameters ``p`` (SI), from its energies."""
    mp = mpmath.mpf
    p = {k: mp(v) for k, v in p.items()}
    g = mp(G)
    kap = p.get("kappa", mp(1) / 2)
    if name == "mass-spring":
        return p["m"], p["k"]
    if name == "torsional":
        return p["J"], p["kt"]
    if name == "pendulum":
        return p["m"] * p["l"] ** 2, p["m"] * g * p["l"]
    if name == "physical-pendulum":
        return p["J"] + p["m"] * p["a"] ** 2, p["m"] * g * p["a"]
    if name == "rolling-disk-spring":   # T = m x'^2/2 + kappa m r^2 (x'/r)^2/2
        return (1 + kap) * p["m"], p["k"]
    if name == "rolling-in-track":      # s the centre's arc: V = m g (R - r)(1 - cos(s/(R-r)))
        return (1 + kap) * p["m"], p["m"] * g / (p["R"] - p["r"])
    if name == "drum-block-spring":     # the drum (M R^2/2) at x'/R
        return p["m"] + p["M"] / 2, p["k"]
    if name == "board-on-drums":        # friction difference mu g x (m/a) ... 2 mu m g / a
        return p["m"], 2 * p["mu"] * p["m"] * g / p["a"]
    if name == "clock-pendulum":
        J = p["m"] * p["l"] ** 2 / 3 + p["M"] * p["r"] ** 2 / 2 + p["M"] * p["a"] ** 2
        return J, (p["m"] * p["l"] / 2 + p["M"] * p["a"]) * g
    if name == "pulley-block-spring":   # block 2x: 2 m x'^2; pulley rolls: 3 M x'^2 / 4
        return 4 * p["m"] + 3 * p["M"] / 2, p["k"]
    if name == "disk-torsion-offset-mass":
        J = p["M"] * p["R"] ** 2 / 2 + p["m"] * p["r"] ** 2 / 2 + p["m"] * p["a"] ** 2
        return J, p["kt"] + p["m"] * g * p["a"]
    if name == "wheel-on-moving-beam":  # beam eliminated: M X'' = kappa m (x'' - X'')
        m, M = p["m"], p["M"]
        return m + kap * m * M / (kap * m + M), p["k"]
    if name == "angled-member":         # bar 3l of mass m: long arm 2l, short arm l
        lam = p["m"] / 3                # mass per length l
        l = p["l"]
        J = 2 * lam * (2 * l) ** 2 / 3 + lam * (l ** 2 / 12 + (2 * l) ** 2 + (l / 2) ** 2)
        # centre of mass from the pivot: long arm's at (0, l), short arm's at (l/2, 2l)
        cx, cy = (lam * l / 2) / (3 * lam), (2 * lam * l + lam * 2 * l) / (3 * lam)
        return J, p["m"] * g * mpmath.hypot(cx, cy)
    if name == "half-cylinder-shell":   # centre of mass 2r/pi from the axis
        r, m = p["r"], p["m"]
        e = 2 * r / mpmath.pi
        J_contact = m * r ** 2 - m * e ** 2 + m * (r - e) ** 2
        return J_contact, m * g * e
    if name == "rod-torsion-spring":
        m, l, kt = p["m"], p["l"], p["kt"]
        phi0 = mpmath.findroot(lambda f: m * g * l * mpmath.cos(f) - kt * f, 0.5)
        return m * l ** 2, kt + m * g * l * mpmath.sin(phi0)
    if name == "pendulum-accelerating-support":
        return p["m"] * p["l"] ** 2, p["m"] * p["l"] * mpmath.hypot(g, p["a0"])
    if name == "pendulum-on-rotating-disk":
        return p["m"] * p["l"] ** 2, p["m"] * p["r"] * p["l"] * p["Omega"] ** 2
    if name == "bead-on-rotating-ring":  # at the bottom: V = m g r (1 - cos), centrifugal
        r, m = p["r"], p["m"]
        return m * r ** 2, m * r ** 2 * (g / r - p["Omega"] ** 2)
    if name == "pendulum-spring-dashpot":  # mass and spring at 2a
        a = p["a"]
        return 4 * p["m"] * a ** 2, 4 * p["k"] * a ** 2 + 2 * p["m"] * g * a
    if name == "rod-in-fluid":
        return p["m"] * p["l"] ** 2 / 3, p["m"] * g * p["l"] / 2
    raise KeyError(name)


_UNITS = {"k": "N/m", "m": "kg", "M": "kg", "kt": "N*m/rad", "J": "kg*m^2", "l": "m", "a": "m",
          "r": "m", "R": "m", "a0": "m/s^2", "Omega": "rad/s", "d": "N*s/m",
          "beta": "N*s/m^2", "mu": "", "kappa": ""}


def _words(p, drop=()):
    return [f"{n}={v!r} {_UNITS[n]}".rstrip() for n, v in p.items() if n not in drop]


def _drive(name, rng):
    rot = COORDINATES[name].rotation
    options = {"F0": f"{rng.uniform(0.1, 10)!r} {'N*m' if rot else 'N'}"}
    if not COORDINATES[name].damped:
        options["zeta"] = repr(rng.uniform(0.01, 0.5))
    freq = rng.uniform(0.1, 10)
    if name in ("pendulum-on-rotating-disk", "bead-on-rotating-ring"):
        options["f_exc"] = f"{freq!r} Hz"
    else:
        options["Omega"] = f"{freq!r} rad/s"
    return options


def test_every_one_degree_scene_is_driven_or_refused_with_its_reason():
    """The catalog split: a forced scene, a driven variant, a scene driven on its coordinate,
    or one with several degrees of freedom or a rigid-body scene (refused)."""
    from dyncalc.scenes.kinetics import is_kinetics_scene

    forced = set(forced_scene_names())
    for name, scene in catalog().items():
        if scene.compute.__module__ == "dyncalc.physics.relative_scenes":  # coriolis --scene
            assert name not in forced
            continue
        several = scene.matrices is not None  # served by modes: several degrees of freedom
        assert (name in forced) is not (several or is_kinetics_scene(name)), name
        if name in forced and name not in DRIVEN and \
                scene.compute.__module__ != "dyncalc.physics.forced_scenes":
            assert name in COORDINATES


@pytest.mark.parametrize("name", sorted(COORDINATES))
def test_omega_is_natural_frequencys_and_m_k_are_the_energies(name):
    rng = random.Random(f"sdof-{name}")
    for _ in range(6):
        p = _params(name, rng)
        mass_added = bool(COORDINATES[name].mass)
        nf = natural_frequency({}, _words(p, drop=("m",) if mass_added else ()), scene=name)
        out = forced_response(_drive(name, rng), _words(p), scene=name)
        assert out.results["omega"].si == nf.results["omega"].si      # to the bit
        m_ref, k_ref = _energies(name, p)
        assert out.results["m_eff"].si == pytest.approx(float(m_ref), rel=4e-15)
        assert out.results["k_eff"].si == pytest.approx(float(k_ref), rel=1e-13)


def test_every_scene_example_runs():
    for name in COORDINATES:
        result = CliRunner().invoke(cli, [*__import__("shlex").split(forced_example(name))[1:],
                                          "--json"])
        assert result.exit_code == 0, (name, result.stderr)
        data = json.loads(result.stdout)
        assert data["scene"] == name
        assert data["extra"]["coordinate"]["name"] == COORDINATES[name].symbol
        assert data["results"]["X"]["unit"] == ("rad" if COORDINATES[name].rotation else "m")


# --- against a numerical integration of the set-up's own equations of motion -------------------

def _steady_fit(rhs, y0, W, t_end, periods=4):
    """Integrate to ``t_end`` (transient gone), then fit ``q = A cos Wt + B sin Wt`` to the
    last periods: (amplitude, phase lag)."""
    import numpy as np
    from scipy.integrate import solve_ivp

    start = t_end - periods * 2 * math.pi / W
    t = np.linspace(start, t_end, 400)
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", rtol=1e-11, atol=1e-14,
                    t_eval=t)
    basis = np.column_stack([np.cos(W * t), np.sin(W * t)])
    (a, b), *_ = np.linalg.lstsq(basis, sol.y[0], rcond=None)
    return math.hypot(a, b), math.atan2(b, a)


def results(*args):
    result = CliRunner().invoke(cli, ["forced-response", *args, "--json"])
    assert result.exit_code == 0, result.stderr
    return {n: r["value"] for n, r in json.loads(result.stdout)["results"].items()}


def test_translation_wheel_on_free_beam_two_degrees_integrated():
    """Rao-style problem set up on E5.27: a force F0 cos(Omega t) at the wheel's centre, a
    damper c from the wall; x (wheel) and X (beam) integrated together."""
    import numpy as np

    k, m, M, kap, c, F0, W = 500.0, 5.0, 20.0, 0.5, 12.0, 10.0, 7.0
    got = results("--scene", "wheel-on-moving-beam", "k=500N/m", "m=5kg", "M=20kg",
                  "--c", "12 N*s/m", "--F0", "10N", "--Omega", "7rad/s")
    mass = np.array([[m + kap * m, -kap * m], [-kap * m, M + kap * m]])

    def rhs(t, y):
        x, X, v, V = y
        acc = np.linalg.solve(mass, [F0 * math.cos(W * t) - c * v - k * x, 0.0])
        return [v, V, *acc]

    amp, lag = _steady_fit(lambda t, y: rhs(t, y), [0, 0, 0, 0], W, 40.0)
    assert got["X"] == pytest.approx(amp, rel=1e-7)
    assert got["phi"] == pytest.approx(lag, rel=1e-7)


def test_rotation_clock_pendulum_full_sin_with_torsional_damper():
    """E5.15's clock pendulum driven by a small torque, its equation with sin(phi) in full:
    J_A phi'' + c phi' + (m l/2 + M a) g sin(phi) = T0 cos(Omega t)."""
    m, l, M, r, a = 0.5, 1.0, 2.0, 0.1, 0.9
    c, T0, W = 1.0, 1e-4, 3.0
    got = results("--scene", "clock-pendulum", "m=0.5kg", "l=1m", "M=2kg", "r=0.1m", "a=0.9m",
                  "--c", "1 N*m*s/rad", "--F0", "1e-4 N*m", "--Omega", "3rad/s")
    J = m * l * l / 3 + M * r * r / 2 + M * a * a
    moment = (m * l / 2 + M * a) * G

    def rhs(t, y):
        return [y[1], (T0 * math.cos(W * t) - c * y[1] - moment * math.sin(y[0])) / J]

    amp, lag = _steady_fit(rhs, [0.0, 0.0], W, 120.0)
    assert got["X"] == pytest.approx(amp, rel=1e-6)      # sin phi = phi to 1e-9 here
    assert got["phi"] == pytest.approx(lag, rel=1e-6)


def test_own_damping_pendulum_spring_dashpot_integrated():
    """E5.18's pendulum with its own dashpot: 4 m a^2 phi'' + d a^2 phi' + (4 k a^2 + 2 m g a)
    phi = T0 cos(Omega t); --zeta is not taken."""
    m, a, k, d, T0, W = 2.0, 0.5, 200.0, 6.0, 0.5, 18.0
    got = results("--scene", "pendulum-spring-dashpot", "m=2kg", "a=0.5m", "k=200N/m",
                  "d=6 N*s/m", "--F0", "0.5 N*m", "--Omega", "18rad/s")

    def rhs(t, y):
        return [y[1], (T0 * math.cos(W * t) - d * a * a * y[1]
                       - (4 * k * a * a + 2 * m * G * a) * y[0]) / (4 * m * a * a)]

    amp, lag = _steady_fit(rhs, [0.0, 0.0], W, 60.0)
    assert got["X"] == pytest.approx(amp, rel=1e-7)
    assert got["phi"] == pytest.approx(lag, rel=1e-7)
    assert got["zeta"] == pytest.approx(d / (8 * math.sqrt(k * m + G * m * m / (2 * a))),
                                        rel=1e-14)


def test_textbook_drum_block_by_hand():
    """E5.12's drum and block (k = 2 kN/m, m = 4 kg, M = 10 kg) pushed by 10 N at 10 rad/s,
    undamped: m_eff = m + M/2 = 9 kg, X = F0/(k - m_eff Omega^2) = 10/1100 m, in phase."""
    got = results("--scene", "E5.12", "k=2kN/m", "m=4kg", "M=10kg", "--F0", "10N",
                  "--Omega", "10rad/s")
    assert got["m_eff"] == 9.0 and got["k_eff"] == pytest.approx(2000.0, rel=1e-15)
    assert got["X"] == pytest.approx(10 / 1100, rel=1e-15)
    assert got["phi"] == 0.0


@pytest.mark.parametrize("typed", [
    ("l=100cm", "m=2000g", "--F0", "50 N*cm", "--Omega", "3rad/s", "--c", "0.2 N*m*s/rad"),
    ("l=1m", "m=2kg", "--F0", "0.5 N*m", "--Omega", f"{90 / math.pi!r} rpm", "--c",
     "200 N*mm*s/rad"),
    ("l=1m", "m=2kg", "--F0", "0.5 J", "--f-exc", f"{3 / (2 * math.pi)!r} Hz", "--c",
     "0.2 N*m*s"),
])
def test_unit_invariance_rotation(typed):
    got = results("--scene", "pendulum", *typed, "--x0", "1deg", "--v0", "0.1rad/s", "--t",
                  "2s")
    ref = results("--scene", "pendulum", "l=1", "m=2", "--F0", "0.5", "--Omega", "3",
                  "--c", "0.2", "--x0", repr(math.pi / 180), "--v0", "0.1", "--t", "2")
    assert set(got) == set(ref)
    for name in ref:
        assert got[name] == pytest.approx(ref[name], rel=1e-12), name


@pytest.mark.parametrize("args, message", [
    (("--scene", "pendulum", "l=1m", "m=2kg", "--base", "1cm", "--Omega", "3rad/s"),
     "--base does not go with --scene pendulum: the scene is driven by --F0 on its coordinate "
     "(theta, the angle from the vertical; F0 is a torque about the pivot); base motion, "
     "ground acceleration and unbalance are the mass-spring-damper's (--k, --m without "
     "--scene)"),
    (("--scene", "drum-block-spring", "k=2kN/m", "m=4kg", "M=10kg", "--unbalance", "1kg*m",
      "--Omega", "3rad/s"),
     "--unbalance does not go with --scene drum-block-spring: the scene is driven by --F0 on "
     "its coordinate (x, the block's displacement; F0 is a force on the block along the "
     "rope); base motion, ground acceleration and unbalance are the mass-spring-damper's "
     "(--k, --m without --scene)"),
    (("--scene", "coupled-blocks", "m1=1kg", "m2=1kg", "k1=1N/m", "k2=1N/m", "k3=1N/m",
      "--F0", "1N", "--Omega", "1rad/s"),
     "forced-response --scene takes a scene with one degree of freedom; coupled-blocks has "
     "more than one (modes gives its frequencies and mode shapes), so it has no single effective mass "
     "and stiffness to drive"),
    (("--scene", "rod-in-fluid", "m=1kg", "l=1m", "beta=1 N*s/m^2", "--zeta", "0.1", "--F0",
      "1N*m", "--Omega", "1rad/s"),
     "--zeta does not go with --scene rod-in-fluid: its damping is its own (its parameters "
     "give zeta)"),
    (("--scene", "pendulum-on-rotating-disk", "r=0.4m", "l=0.1m", "m=0.2kg", "--F0", "1N*m",
      "--Omega", "1rad/s"),
     "--Omega does not go with --scene pendulum-on-rotating-disk: its Omega= is the spin of "
     "the set-up; give the excitation frequency as --f-exc"),
    (("--scene", "pendulum", "l=1m", "m=2kg", "--F0", "0.5N", "--Omega", "3rad/s"),
     "--F0 must be a torque [force]*[length]; got 0.5 newton ([mass] * [length] / [time] ** "
     "2)"),
    (("--scene", "pendulum", "l=1m", "m=2kg", "amplitude=10deg", "--F0", "0.5N*m", "--Omega",
      "3rad/s"),
     "amplitude= does not go with forced-response --scene pendulum: the driven response is "
     "linear (small motion about the equilibrium); natural-frequency takes an amplitude"),
    (("--scene", "pendulum", "l=1m", "m=2kg", "--F0", "0.5N*m", "--Omega", "3rad/s", "X=1rad"),
     "forced-response --scene pendulum runs forward only: give every parameter (an inverse "
     "problem works on the mass-spring-damper itself, --k --m without --scene)"),
    (("--scene", "pendulum", "l=1m", "--k", "2N/m", "--m", "2kg", "--F0", "1N*m", "--Omega",
      "1rad/s"),
     "--k does not go with --scene pendulum: it is driven by --F0 on its coordinate; its "
     "parameters are l [length], g [length]/[time]^2 = 9.80665 m/s^2, m [mass], zeta "
     "dimensionless = 0, c [force]*[length]*[time]/[angle]?, Q dimensionless?, F0 "
     "[force]*[length]?, Omega [angle]/[time]?, f_exc [cycles]/[time]?, x0 [angle]?, v0 "
     "[angle]/[time]?, t [time]?"),
    (("--scene", "board-on-drums", "mu=0.4", "a=0.8m", "m=5kg", "sense=outward", "--F0", "1N",
      "--Omega", "1rad/s"),
     "with the drums turning outward (tops moving apart) the board does not oscillate: "
     "friction pushes it further from the middle and it runs off exponentially, any offset "
     "growing like exp(lambda t) with lambda = sqrt(2 mu g / a) = 3.13156 1/s; with "
     "sense=inward it oscillates at omega = 3.13156 rad/s"),
    (("--scene", "bead-on-rotating-ring", "r=1m", "Omega=3.1315571206669692 rad/s", "m=1kg",
      "--F0", "1N*m", "--f-exc", "1Hz"),     # at the bifurcation: Omega^2 = g/r
     "bead-on-rotating-ring has no oscillation here (omega = 0 rad/s): its linear stiffness "
     "vanishes, so a harmonic drive has no steady amplitude"),
])
def test_refusals(args, message):
    result = CliRunner().invoke(cli, ["forced-response", *args])
    assert result.exit_code == 2, result.output
    assert result.stdout == ""
    assert result.stderr == f"Error: {message}\n"


def test_total_response_of_an_angle_from_its_initial_conditions(tmp_path):
    """theta(t) from theta(0) = 2 deg, theta'(0) = -0.1 rad/s (transient plus steady state)
    against solve_ivp of m l^2 theta'' + c theta' + m g l theta = T0 cos(Omega t); the plot's
    time panel is drawn for it."""
    from scipy.integrate import solve_ivp

    l, m, c, T0, W, t = 1.0, 2.0, 0.3, 0.5, 3.0, 4.0
    plot = tmp_path / "pendulum.png"
    got = results("--scene", "pendulum", "l=1m", "m=2kg", "--c", "0.3 N*m*s/rad", "--F0",
                  "0.5 N*m", "--Omega", "3rad/s", "--x0", "2deg", "--v0", "-0.1rad/s",
                  "--t", "4s", "--plot", str(plot))
    sol = solve_ivp(lambda s, y: [y[1], (T0 * math.cos(W * s) - c * y[1] - m * G * l * y[0])
                                  / (m * l * l)], (0.0, t), [math.radians(2.0), -0.1],
                    method="DOP853", rtol=1e-12, atol=1e-15)
    assert got["x"] == pytest.approx(sol.y[0][-1], rel=1e-9)
    assert plot.stat().st_size > 10_000
