"""Every scene's energies (dyncalc/scenes/energies.py) against SCENES.md: the derived
equations of motion satisfy the equations the catalog lists (symbolically: the ``eom_i``
strings are read back through the closed grammar and substituted), and the linearised
frequencies agree with ``natural-frequency --scene`` (catalog scenes) or with SCENES.md's
closed forms (the Lagrange scenes), at numbers and, for one-coordinate scenes, symbolically."""
from __future__ import annotations

import math
from functools import lru_cache

import pytest
import sympy
from scipy.optimize import brentq

import dyncalc
from dyncalc.commands.eom import eom
from dyncalc.physics.symbolic import Symbols, to_sympy
from dyncalc.scenes.energies import NO_COORDINATE, energies, energy_scene_names
from dyncalc.units.expression import parse_expression

G = 9.80665

#: Parameter values for each scene (the ones natural-frequency takes too).
VALUES = {
    "mass-spring": dict(m="2 kg", k="300 N/m"),
    "torsional": dict(J="0.3 kg*m^2", kt="40 N*m/rad"),
    "pendulum": dict(l="0.8 m"),
    "physical-pendulum": dict(m="3 kg", a="0.2 m", J="0.05 kg*m^2"),
    "rolling-disk-spring": dict(k="300 N/m", m="2 kg"),
    "rolling-in-track": dict(R="1 m", r="0.1 m"),
    "drum-block-spring": dict(k="500 N/m", m="2 kg", M="3 kg"),
    "clock-pendulum": dict(m="0.5 kg", l="1 m", M="1 kg", r="0.1 m", a="0.9 m"),
    "pulley-block-spring": dict(k="500 N/m", m="2 kg", M="1 kg"),
    "pendulum-spring-dashpot": dict(m="1 kg", a="0.5 m", k="100 N/m", d="1 N*s/m"),
    "rod-torsion-spring": dict(m="1 kg", l="0.5 m", kt="20 N*m/rad"),
    "disk-torsion-offset-mass": dict(M="5 kg", R="0.3 m", m="1 kg", r="0.05 m", a="0.2 m",
                                     kt="50 N*m/rad"),
    "wheel-on-moving-beam": dict(k="100 N/m", m="2 kg", M="3 kg"),
    "angled-member": dict(l="0.7 m"),
    "half-cylinder-shell": dict(r="0.3 m"),
    "coupled-blocks": dict(m1="1 kg", m2="2 kg", k1="100 N/m", k2="200 N/m", k3="50 N/m"),
    "pendulum-accelerating-support": dict(l="0.5 m", a0="3 m/s^2"),
    "pendulum-on-rotating-disk": dict(r="0.4 m", l="0.1 m", Omega="5 rad/s"),
    "bead-on-rotating-ring": dict(r="0.2 m", Omega="10 rad/s"),
    "quarter-car": dict(k="40 kN/m", m="400 kg", L="10 m", U0="2 cm", v0="20 m/s"),
    "rod-in-fluid": dict(m="1.5 kg", l="0.8 m", beta="2 N*s/m^2"),
    "frame-brace-damper": dict(m="100 kg", k="20 kN/m", d="400 N*s/m", b0="1 m/s^2"),
    "board-on-drums": dict(mu="0.3", a="0.5 m"),
    "mass-spring-given-response": dict(m="1 kg", k="100 N/m"),
    "rolling-wheel-moving-ground": dict(m="2 kg", k="300 N/m", u0="1 cm",
                                        Omega="7 rad/s"),
    "angled-bar-on-shaft": dict(m="1 kg", l="0.5 m", M0="2 N*m"),
    "beam-spun-up": dict(m="1 kg", l="0.5 m", M0="2 N*m"),
    "drum-two-blocks": dict(J_A="0.5 kg*m^2", m1="2 kg", r1="0.2 m", m2="3 kg", r2="0.3 m"),
    "wheel-incline-block": dict(m1="2 kg", m2="3 kg", beta="30 deg"),
    "two-drums-rope-drive": dict(m1="2 kg", m2="3 kg", r1="0.2 m", r2="0.3 m",
                                 J1="0.1 kg*m^2", J2="0.2 kg*m^2", M0="5 N*m"),
    "radial-slot-release": dict(m="1 kg", Omega="2 rad/s"),
    "block-disk-springs": dict(M="3 kg", m="1 kg", r="0.1 m", k="100 N/m"),
    "spring-coupled-pendulums": dict(m="1 kg", l="1 m", k="10 N/m", b="0.5 m"),
    "disk-on-swinging-bar": dict(m1="1 kg", l="1 m", m2="1 kg", J2="0.1 kg*m^2"),
    "pendulum-on-sliding-block": dict(m1="2 kg", m2="1 kg", l="0.5 m"),
}

#: SCENES.md's equations of motion (left side minus right side), typed from the table.
EQUATIONS = {
    "mass-spring": ["m*x'' + k*x"],
    "torsional": ["J*phi'' + kt*phi"],
    "pendulum": ["l*phi'' + g*sin(phi)"],
    "physical-pendulum": ["(J + m*a^2)*phi'' + m*g*a*sin(phi)"],
    "rolling-disk-spring": ["(1 + kappa)*m*x'' + k*x"],
    "rolling-in-track": ["(1 + kappa)*(R - r)*phi'' + g*sin(phi)"],
    "drum-block-spring": ["(2*m + M)*x'' + 2*k*x"],
    "clock-pendulum": ["(m*l^2/3 + M*(r^2 + 2*a^2)/2)*phi'' + (m*l/2 + M*a)*g*sin(phi)"],
    "pulley-block-spring": ["(4*m + 3*M/2)*x'' + k*x"],
    "pendulum-spring-dashpot": ["4*m*a^2*phi'' + d*a^2*cos(phi)^2*phi' "
                                "+ 4*k*a^2*sin(phi)*cos(phi) + 2*m*g*a*sin(phi)"],
    "rod-torsion-spring": ["m*l^2*phi'' + kt*phi - m*g*l*cos(phi)"],
    "disk-torsion-offset-mass": ["(M*R^2/2 + m*(r^2/2 + a^2))*phi'' + kt*phi "
                                 "+ m*g*a*sin(phi)"],
    "wheel-on-moving-beam": ["(1 + kappa)*m*x'' - kappa*m*y'' + k*x",
                             "(M + kappa*m)*y'' - kappa*m*x''"],
    "angled-member": ["14*l*phi'' + sqrt(65)*g*sin(phi)"],
    "half-cylinder-shell": ["phi''*(pi - 2*cos(phi)) + phi'^2*sin(phi) + (g/r)*sin(phi)"],
    "coupled-blocks": ["m1*x1'' + (k1 + k3)*x1 - k3*x2", "m2*x2'' - k3*x1 + (k2 + k3)*x2"],
    "pendulum-accelerating-support": ["l*phi'' + g*sin(phi) + a0*cos(phi)"],
    "pendulum-on-rotating-disk": ["l*phi'' + r*Omega^2*sin(phi)"],
    "bead-on-rotating-ring": ["theta'' + (g/r)*sin(theta) - Omega^2*sin(theta)*cos(theta)"],
    "quarter-car": ["m*x'' + k*x - k*U0*cos(2*pi*v0*t/L)"],
    "rod-in-fluid": ["(m*l^2/3)*phi'' + (beta*l^3/3)*phi' + (m*g*l/2)*sin(phi)"],
    "frame-brace-damper": ["m*y'' + (d/2)*y' + (k/2)*y + m*b0*cos(Omega*t)"],
    "board-on-drums": ["x'' + 2*mu*g*x/a"],
    "angled-bar-on-shaft": ["(20/9)*m*l^2*phi'' - M0"],
    "beam-spun-up": ["(m*l^2/3)*phi'' - M0"],
    "drum-two-blocks": ["(J_A + m1*r1^2 + m2*r2^2)*phi'' - (m2*r2 - m1*r1)*g"],
    "wheel-incline-block": ["((1 + kappa)*m1 + m2)*x'' - (m2 - m1*sin(beta))*g"],
    "two-drums-rope-drive": ["(m2 + m1*(r1/r2)^2 + (J1 + J2)/r2^2)*x2'' - M0/r2 "
                             "- (m2 - m1*r1/r2)*g"],
    "mass-spring-given-response": ["m*x'' + k*x - F"],
    "rolling-wheel-moving-ground": ["(1 + kappa)*m*x'' + k*x "
                                    "+ kappa*m*u0*Omega^2*cos(Omega*t)"],
    "radial-slot-release": ["x'' - Omega^2*x"],
    "block-disk-springs": ["(M + m)*x'' - m*r*phi'' + k*x - F",
                           "-m*x'' + (3/2)*m*r*phi'' + k*r*phi"],
    "spring-coupled-pendulums": ["l*phi1'' + g*sin(phi1)*cos(phi2)",
                                 "m*l*phi2'' + m*g*cos(phi1)*sin(phi2) "
                                 "+ k*(2*l*sin(phi2) - b)*cos(phi2)"],
    "disk-on-swinging-bar": ["(m1*l^2/3 + m2*x^2 + J2)*phi'' + 2*m2*x*x'*phi' "
                             "+ (m1*l/2 + m2*x)*g*sin(phi)", "x'' - x*phi'^2 - g*cos(phi)"],
    "pendulum-on-sliding-block": ["(m1 + m2)*x'' + m2*l*phi''*cos(phi) "
                                  "- m2*l*phi'^2*sin(phi)", "x''*cos(phi) + l*phi'' + g*sin(phi)"],
}

#: SCENES.md's omega^2 of the one-coordinate scenes whose equilibrium is 0 (symbolic check).
OMEGA_SQUARED = {
    "mass-spring": "k/m", "torsional": "kt/J", "pendulum": "g/l",
    "physical-pendulum": "m*g*a/(J + m*a^2)", "rolling-disk-spring": "k/((1 + kappa)*m)",
    "rolling-in-track": "g/((1 + kappa)*(R - r))", "drum-block-spring": "2*k/(M + 2*m)",
    "clock-pendulum": "(m*l + 2*M*a)*g/(2*(m*l^2/3 + M*(r^2 + 2*a^2)/2))",
    "pulley-block-spring": "k/(4*m + 3*M/2)", "pendulum-spring-dashpot": "k/m + g/(2*a)",
    "disk-torsion-offset-mass": "(kt + m*g*a)/(M*R^2/2 + m*(r^2/2 + a^2))",
    "angled-member": "(sqrt(65)/14)*g/l", "half-cylinder-shell": "g/((pi - 2)*r)",
    "pendulum-on-rotating-disk": "r*Omega^2/l", "quarter-car": "k/m",
    "rod-in-fluid": "3*g/(2*l)", "frame-brace-damper": "k/(2*m)",
    "board-on-drums": "2*mu*g/a", "rolling-wheel-moving-ground": "k/((1 + kappa)*m)",
}

#: What natural-frequency needs besides (the prescribed motion of E5.22).
NF_EXTRA = {"mass-spring-given-response": dict(x0="1 cm", t0="1 s", T="2 s", t="0.5 s")}
NO_FREQUENCY = {"angled-bar-on-shaft", "beam-spun-up", "drum-two-blocks",
                "wheel-incline-block", "two-drums-rope-drive", "radial-slot-release",
                "disk-on-swinging-bar"}
LAGRANGE = {"block-disk-springs", "spring-coupled-pendulums", "disk-on-swinging-bar",
            "pendulum-on-sliding-block"}


def test_every_scene_has_values_and_equations():
    assert set(VALUES) == set(energy_scene_names()) == set(EQUATIONS)
    from dyncalc.scenes import catalog

    mechanical = set(catalog()) - set(NO_COORDINATE)
    assert mechanical <= set(energy_scene_names())


@lru_cache(maxsize=None)
def _run(scene: str, numbers: bool = True):
    words = [f"{k}={v}" for k, v in VALUES[scene].items()] if numbers else []
    return eom({}, words, scene=scene)


def _read_back(scene: str, text: str, s: Symbols):
    record = energies(scene)
    lhs, _, rhs = text.partition(" = ")
    tree = parse_expression(rhs, coordinates=record.coords,
                            names={p.name for p in record.params}, free_names=False)
    return lhs, to_sympy(tree, s)


@pytest.mark.parametrize("scene", sorted(EQUATIONS))
def test_derived_equations_are_the_catalogs(scene):
    record = energies(scene)
    signed = [p.name for p in record.params if p.signed]
    s = Symbols(record.coords, signed=signed)
    result = _run(scene, False)
    accelerations = {}
    for i, c in enumerate(record.coords, start=1):
        lhs, rhs = _read_back(scene, result.results[f"eom_{i}"].si, s)
        assert lhs == f"{c}''"
        accelerations[s.qdd[i - 1]] = rhs
    defaults = {s.param(p.name): sympy.nsimplify(p.default.split()[0])
                for p in record.params if p.default is not None}
    for text in EQUATIONS[scene]:
        tree = parse_expression(text, coordinates=record.coords, max_order=2,
                                names={p.name for p in record.params}, free_names=False)
        residual = to_sympy(tree, s).subs(accelerations).subs(defaults)
        assert sympy.simplify(residual) == 0, (text, residual)


def _omegas(result):
    return sorted(e.si for name, e in result.results.items() if name.startswith("omega_"))


def _catalog_omegas(scene):
    r = dyncalc.natural_frequency(scene=scene, **VALUES[scene], **NF_EXTRA.get(scene, {}))
    r = r.to_dict()["results"]
    return sorted(item["value"] for name, item in r.items()
                  if name == "omega" or name.startswith("omega_") and name != "omega_d")


@pytest.mark.parametrize("scene", sorted(set(VALUES) - NO_FREQUENCY))
def test_frequencies_are_natural_frequencys(scene):
    ours = [w for w in _omegas(_run(scene)) if w != 0.0]  # a drift mode is omega = 0
    assert ours == pytest.approx(_catalog_omegas(scene), rel=1e-9)


@pytest.mark.parametrize("scene", sorted(OMEGA_SQUARED))
def test_one_coordinate_frequency_symbolically(scene):
    record = energies(scene)
    s = Symbols(record.coords, signed=[p.name for p in record.params if p.signed])
    result = _run(scene, False)
    names = {p.name for p in record.params}

    def read(name):
        text = result.results[name].si.strip("[]")
        return to_sympy(parse_expression(text, names=names, coordinates=record.coords), s)
    defaults = {s.param(p.name): float(p.default.split()[0])
                for p in record.params if p.default is not None}
    expected = to_sympy(parse_expression(OMEGA_SQUARED[scene], names=names), s)
    ratio = sympy.simplify(read("stiffness_matrix") / read("mass_matrix"))
    expected = expected.subs(defaults)
    # g enters as its float value (a default): the forms agree at any values of the rest
    symbols = sorted(ratio.free_symbols | expected.free_symbols, key=str)
    for trial in range(3):
        point = {x: 0.37 + 0.61 * (trial + 1) * (i + 1) for i, x in enumerate(symbols)}
        if scene == "rolling-in-track":
            point[s.param("R")] += 5.0  # R > r
        assert float(ratio.subs(point)) == pytest.approx(float(expected.subs(point)),
                                                         rel=1e-13)


def test_block_disk_springs_closed_form():
    M, m, k = 3.0, 1.0, 100.0
    root = math.sqrt(4 * M * M - 4 * M * m + 17 * m * m)
    expected = [math.sqrt(k * ((2 * M + 5 * m) + sign * root) / (2 * m * (3 * M + m)))
                for sign in (-1, 1)]
    assert _omegas(_run("block-disk-springs")) == pytest.approx(expected, rel=1e-12)


def test_spring_coupled_pendulums_closed_form():
    m, l, k, b = 1.0, 1.0, 10.0, 0.5
    phi2 = brentq(lambda p: m * G * math.sin(p) + k * (2 * l * math.sin(p) - b) * math.cos(p),
                  0.0, math.pi / 2 - 1e-12, xtol=1e-15)
    w1 = math.sqrt(G * math.cos(phi2) / l)
    w2 = math.sqrt(G / (l * math.cos(phi2)) + 2 * k * math.cos(phi2) ** 2 / m)
    result = _run("spring-coupled-pendulums")
    assert _omegas(result) == pytest.approx([w1, w2], rel=1e-10)
    assert result.extra["about"] == {"phi1": 0.0, "phi2": pytest.approx(phi2, rel=1e-12)}


def test_pendulum_on_sliding_block_closed_form():
    m1, m2, l = 2.0, 1.0, 0.5
    assert _omegas(_run("pendulum-on-sliding-block")) == pytest.approx(
        [0.0, math.sqrt((m1 + m2) * G / (m1 * l))], rel=1e-13)


def test_disk_on_swinging_bar_has_no_equilibrium():
    result = _run("disk-on-swinging-bar")
    assert result.results["equilibria"].si == "none"
    assert "no equilibrium: the system is never at rest at these values" in result.warnings
    assert not _omegas(result)


@pytest.mark.parametrize("scene, state, expected", [
    # E4.10: phi'' = (m2 r2 - m1 r1) g / (J_A + m1 r1^2 + m2 r2^2)
    ("drum-two-blocks", ["phi=0"], (0.9 - 0.4) * G / (0.5 + 0.08 + 0.27)),
    # E4.12: x'' = (m2 - m1 sin(beta)) g / ((1 + kappa) m1 + m2), a disk kappa = 1/2
    ("wheel-incline-block", ["x=0"], (3 - 2 * 0.5) * G / (1.5 * 2 + 3)),
    # E6.7: x'' = Omega^2 x
    ("radial-slot-release", ["x=0.3m", "x_dot=1m/s"], 4 * 0.3),
])
def test_accelerations_of_scenes_without_a_frequency(scene, state, expected):
    words = [f"{k}={v}" for k, v in VALUES[scene].items()] + state
    result = eom({}, words, scene=scene)
    name = energies(scene).coords[0] + "_ddot"
    assert result.results[name].si == pytest.approx(expected, rel=1e-13)


# --- the scene cards print the derived equations (dyncalc/scenes/derived.py) ---------------

@pytest.mark.parametrize("scene", sorted(EQUATIONS))
def test_card_data_is_what_eom_derives_now(scene):
    """The generated card data (tools/gen_equations.py) equals eom's derivation today, and
    the card prints it: the equations on a card are derived and tested, not typed."""
    from click.testing import CliRunner

    from dyncalc.cli import cli
    from dyncalc.scenes.derived import DERIVED

    result = _run(scene, False)
    derived = tuple(result.results[f"eom_{i}"].si
                    for i in range(1, len(energies(scene).coords) + 1))
    assert DERIVED[scene] == derived, "stale: run python tools/gen_equations.py"
    card = CliRunner().invoke(cli, ["scenes", scene])
    if card.exit_code == 0:  # a catalog scene
        assert f"derived by eom: {'; '.join(derived)}" in card.stdout.splitlines()


def test_every_scene_with_energies_has_card_data():
    from dyncalc.scenes.derived import DERIVED

    assert list(DERIVED) == energy_scene_names()


def test_cards_load_no_sympy():
    """The card reads the generated data; sympy stays out of dyncalc scenes."""
    import subprocess
    import sys

    code = ("import sys\nfrom dyncalc.cli import main\n"
            "try:\n    main(['scenes', 'pendulum-on-sliding-block'])\nexcept SystemExit:\n"
            "    pass\nprint('sympy' in sys.modules, file=sys.stderr)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=60)
    assert out.stderr.strip().splitlines()[-1] == "False"
    assert "derived by eom: x'' = " in out.stdout
