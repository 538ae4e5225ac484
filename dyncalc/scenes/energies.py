"""The energies ``eom --scene NAME`` derives each scene's equations of motion from.

Data only, keyed by scene name (../shared/SCENES.md, "Energies for eom" and "Lagrange
scenes"): the coordinates (and which are angles), ``T``, ``V``, the dissipation ``D`` and
generalized forces ``Q`` as texts of the closed grammar (:mod:`dyncalc.units.expression`), and the parameters
with their dimensions and defaults. Where the mass cancels and the scene has no ``m``, the
energies are per unit mass. The scene records of the catalog are not touched: this table
stands beside them.
"""
from __future__ import annotations

from ..errors import InputError
from ..records import Frozen
from ..units import (ACCELERATION, ANGLE, ANGULAR_RATE, DAMPING, DIMENSIONLESS, FORCE,
                     INERTIA, LENGTH, LINEAR_DRAG, MASS, STIFFNESS, TORSIONAL_STIFFNESS,
                     VELOCITY, Dim)

__all__ = ["Energies", "EParam", "energies", "energy_scene_names", "NO_COORDINATE"]

MOMENT = Dim("moment", "[force]*[length]", "[force]*[length]", "N*m")
G = "9.80665 m/s^2"


class EParam(Frozen):
    """A parameter: name, dimension, default text (or None: required), whether it may be
    negative or zero (a forcing, an acceleration), a few words."""

    __slots__ = ("name", "dim", "default", "signed", "description")

    def __init__(self, name: str, dim: Dim, description: str, default: str | None = None,
                 signed: bool = False):
        for key, value in (("name", name), ("dim", dim), ("default", default),
                           ("signed", signed), ("description", description)):
            object.__setattr__(self, key, value)


class Energies(Frozen):
    """One scene's energies: ``coords`` (names), ``angles`` (those that are angles), ``T``,
    ``V``, ``D`` (text or ""), ``Q`` ({coordinate: text}), ``params``, ``about`` (the
    equilibrium the scene's frequency is about, in words), ``note``, ``reference``,
    ``domain`` ({coordinate: (lowest, highest)} as texts of the grammar: where the model
    holds; equilibria outside it are left out)."""

    __slots__ = ("name", "coords", "angles", "T", "V", "D", "Q", "params", "note",
                 "reference", "domain")

    def __init__(self, name, coords, angles, T, V, params, D="", Q=None, note="",
                 reference="", domain=None):
        for key, value in (("name", name), ("coords", tuple(coords)),
                           ("angles", tuple(angles)), ("T", T), ("V", V), ("D", D),
                           ("Q", dict(Q or {})), ("params", tuple(params)), ("note", note),
                           ("reference", reference), ("domain", dict(domain or {}))):
            object.__setattr__(self, key, value)

    def param(self, name: str) -> EParam | None:
        return next((p for p in self.params if p.name == name), None)


def _p(name, dim, description, default=None, signed=False):
    return EParam(name, dim, description, default, signed)


def _g():
    return _p("g", ACCELERATION, "gravitational acceleration", G)


def _kappa():
    return _p("kappa", DIMENSIONLESS, "shape factor J_C/(m r^2) (or body=NAME)", "0.5")


_TABLE = (
    Energies("mass-spring", ["x"], [], "m*x'^2/2", "k*x^2/2",
             [_p("m", MASS, "mass"), _p("k", STIFFNESS, "stiffness")],
             reference="E5.11, E5.19, E5.26"),
    Energies("torsional", ["phi"], ["phi"], "J*phi'^2/2", "kt*phi^2/2",
             [_p("J", INERTIA, "moment of inertia"),
              _p("kt", TORSIONAL_STIFFNESS, "torsional stiffness")]),
    Energies("pendulum", ["phi"], ["phi"], "l^2*phi'^2/2", "g*l*(1 - cos(phi))",
             [_p("l", LENGTH, "length"), _g()], note="per unit mass"),
    Energies("physical-pendulum", ["phi"], ["phi"], "(J + m*a^2)*phi'^2/2",
             "m*g*a*(1 - cos(phi))",
             [_p("m", MASS, "mass"), _p("a", LENGTH, "pivot to centre of mass"),
              _p("J", INERTIA, "moment of inertia about the centre of mass (J = J_A - m a^2)"),
              _g()], reference="E3.44, E5.15"),
    Energies("rolling-disk-spring", ["x"], [], "(1 + kappa)*m*x'^2/2", "k*x^2/2",
             [_p("k", STIFFNESS, "stiffness"), _p("m", MASS, "mass"), _kappa()],
             reference="E4.8"),
    Energies("rolling-in-track", ["phi"], ["phi"], "(1 + kappa)*(R - r)^2*phi'^2/2",
             "g*(R - r)*(1 - cos(phi))",
             [_p("R", LENGTH, "track radius"), _p("r", LENGTH, "body radius"), _kappa(), _g()],
             note="per unit mass", reference="E4.9, E5.17"),
    Energies("drum-block-spring", ["x"], [], "(m + M/2)*x'^2/2", "k*x^2/2",
             [_p("k", STIFFNESS, "stiffness"), _p("m", MASS, "block"),
              _p("M", MASS, "drum (homogeneous disk)")], reference="E5.12"),
    Energies("clock-pendulum", ["phi"], ["phi"], "(m*l^2/3 + M*(r^2 + 2*a^2)/2)*phi'^2/2",
             "(m*l/2 + M*a)*g*(1 - cos(phi))",
             [_p("m", MASS, "rod"), _p("l", LENGTH, "rod length"), _p("M", MASS, "disk"),
              _p("r", LENGTH, "disk radius"), _p("a", LENGTH, "pivot to disk centre"), _g()],
             reference="E5.15"),
    Energies("pulley-block-spring", ["x"], [], "(m/2 + 3*M/16)*x'^2", "k*x^2/8",
             [_p("k", STIFFNESS, "stiffness"), _p("m", MASS, "block"),
              _p("M", MASS, "pulley (homogeneous disk)")], reference="E5.16"),
    Energies("pendulum-spring-dashpot", ["phi"], ["phi"], "2*m*a^2*phi'^2",
             "2*k*a^2*sin(phi)^2 + 2*m*g*a*(1 - cos(phi))",
             [_p("m", MASS, "point mass at 2a"), _p("a", LENGTH, "length a"),
              _p("k", STIFFNESS, "spring at 2a"), _p("d", DAMPING, "dashpot at a"), _g()],
             D="d*a^2*cos(phi)^2*phi'^2/2", reference="E5.18"),
    Energies("rod-torsion-spring", ["phi"], ["phi"], "m*l^2*phi'^2/2",
             "kt*phi^2/2 - m*g*l*sin(phi)",
             [_p("m", MASS, "tip mass"), _p("l", LENGTH, "rod length"),
              _p("kt", TORSIONAL_STIFFNESS, "torsional stiffness"), _g()],
             note="phi downward from the horizontal", reference="E5.20"),
    Energies("disk-torsion-offset-mass", ["phi"], ["phi"],
             "(M*R^2/2 + m*(r^2/2 + a^2))*phi'^2/2", "kt*phi^2/2 + m*g*a*(1 - cos(phi))",
             [_p("M", MASS, "large disk"), _p("R", LENGTH, "large disk radius"),
              _p("m", MASS, "small disk"), _p("r", LENGTH, "small disk radius"),
              _p("a", LENGTH, "offset below the axis"),
              _p("kt", TORSIONAL_STIFFNESS, "torsional stiffness"), _g()], reference="E5.25"),
    Energies("wheel-on-moving-beam", ["x", "y"], [],
             "m*x'^2/2 + kappa*m*(x' - y')^2/2 + M*y'^2/2", "k*x^2/2",
             [_p("k", STIFFNESS, "stiffness"), _p("m", MASS, "wheel"),
              _p("M", MASS, "beam"), _kappa()], reference="E5.27"),
    Energies("angled-member", ["phi"], ["phi"], "7*l^2*phi'^2/6",
             "sqrt(65)*g*l*(1 - cos(phi))/6", [_p("l", LENGTH, "length"), _g()],
             note="per unit mass", reference="E3.44"),
    Energies("half-cylinder-shell", ["phi"], ["phi"], "r^2*phi'^2*(1 - (2/pi)*cos(phi))",
             "(2/pi)*g*r*(1 - cos(phi))", [_p("r", LENGTH, "radius"), _g()],
             note="per unit mass; valid for |phi| < pi/2", reference="E4.18",
             domain={"phi": ("-pi/2", "pi/2")}),
    Energies("coupled-blocks", ["x1", "x2"], [], "m1*x1'^2/2 + m2*x2'^2/2",
             "k1*x1^2/2 + k3*(x2 - x1)^2/2 + k2*x2^2/2",
             [_p("m1", MASS, "block 1"), _p("m2", MASS, "block 2"),
              _p("k1", STIFFNESS, "wall spring 1"), _p("k2", STIFFNESS, "wall spring 2"),
              _p("k3", STIFFNESS, "coupling spring")], reference="E4.15"),
    Energies("pendulum-accelerating-support", ["phi"], ["phi"],
             "((a0*t + l*cos(phi)*phi')^2 + (l*sin(phi)*phi')^2)/2", "-g*l*cos(phi)",
             [_p("l", LENGTH, "length"), _p("a0", ACCELERATION, "support acceleration",
                                            signed=True), _g()],
             note="per unit mass", reference="E6.5"),
    Energies("pendulum-on-rotating-disk", ["phi"], ["phi"],
             "(r^2*Omega^2 + l^2*(Omega + phi')^2 + 2*r*l*Omega*(Omega + phi')*cos(phi))/2",
             "0", [_p("r", LENGTH, "disk centre to pivot"), _p("l", LENGTH, "length"),
                   _p("Omega", ANGULAR_RATE, "disk rate")],
             note="per unit mass", reference="E6.8"),
    Energies("bead-on-rotating-ring", ["theta"], ["theta"],
             "r^2*(theta'^2 + Omega^2*sin(theta)^2)/2", "g*r*(1 - cos(theta))",
             [_p("r", LENGTH, "ring radius"), _p("Omega", ANGULAR_RATE, "ring rate"), _g()],
             note="per unit mass; theta from the bottom", reference="E6.11"),
    Energies("quarter-car", ["x"], [], "m*x'^2/2", "k*(x - U0*cos(2*pi*v0*t/L))^2/2",
             [_p("k", STIFFNESS, "stiffness"), _p("m", MASS, "mass"),
              _p("L", LENGTH, "road wavelength"), _p("U0", LENGTH, "road amplitude", "0 m",
                                                     signed=True),
              _p("v0", VELOCITY, "speed", "0 m/s", signed=True)], reference="E5.23"),
    Energies("rod-in-fluid", ["phi"], ["phi"], "m*l^2*phi'^2/6", "m*g*l*(1 - cos(phi))/2",
             [_p("m", MASS, "rod"), _p("l", LENGTH, "length"),
              _p("beta", LINEAR_DRAG, "drag per unit length per unit speed"), _g()],
             D="beta*l^3*phi'^2/6", reference="E5.14"),
    Energies("frame-brace-damper", ["y"], [], "m*(y' + (b0/Omega)*sin(Omega*t))^2/2",
             "k*y^2/4",
             [_p("m", MASS, "beam"), _p("k", STIFFNESS, "diagonal spring"),
              _p("d", DAMPING, "diagonal dashpot"),
              _p("b0", ACCELERATION, "ground acceleration amplitude", "0 m/s^2", signed=True),
              _p("Omega", ANGULAR_RATE, "forcing frequency", "1 rad/s")],
             D="d*y'^2/4", reference="E5.21"),
    Energies("board-on-drums", ["x"], [], "x'^2/2", "0",
             [_p("mu", DIMENSIONLESS, "kinetic friction coefficient"),
              _p("a", LENGTH, "distance between the drum axes"), _g()],
             Q={"x": "-2*mu*g*x/a"}, note="per unit mass; drum tops moving toward each other",
             reference="E5.13"),
    Energies("angled-bar-on-shaft", ["phi"], ["phi"], "(10/9)*m*l^2*phi'^2", "0",
             [_p("m", MASS, "mass"), _p("l", LENGTH, "length"),
              _p("M0", MOMENT, "driving moment", "0 N*m", signed=True)],
             Q={"phi": "M0"}, reference="E3.41"),
    Energies("beam-spun-up", ["phi"], ["phi"], "m*l^2*phi'^2/6", "0",
             [_p("m", MASS, "mass"), _p("l", LENGTH, "length"),
              _p("M0", MOMENT, "driving moment", "0 N*m", signed=True)],
             Q={"phi": "M0"}, reference="E3.43"),
    Energies("drum-two-blocks", ["phi"], ["phi"], "(J_A + m1*r1^2 + m2*r2^2)*phi'^2/2",
             "(m1*r1 - m2*r2)*g*phi",
             [_p("J_A", INERTIA, "drum about its axle"), _p("m1", MASS, "block 1"),
              _p("r1", LENGTH, "radius of rope 1"), _p("m2", MASS, "block 2"),
              _p("r2", LENGTH, "radius of rope 2"), _g()], reference="E4.10"),
    Energies("wheel-incline-block", ["x"], [], "((1 + kappa)*m1 + m2)*x'^2/2",
             "(m1*sin(beta) - m2)*g*x",
             [_p("m1", MASS, "wheel"), _p("m2", MASS, "block"),
              _p("beta", ANGLE, "slope angle"), _kappa(), _g()], reference="E4.12"),
    Energies("two-drums-rope-drive", ["x2"], [],
             "(m2 + m1*(r1/r2)^2 + (J1 + J2)/r2^2)*x2'^2/2", "(m1*r1/r2 - m2)*g*x2",
             [_p("m1", MASS, "block 1"), _p("m2", MASS, "block 2"),
              _p("r1", LENGTH, "drum 1 radius"), _p("r2", LENGTH, "drum 2 radius"),
              _p("J1", INERTIA, "drum 1"), _p("J2", INERTIA, "drum 2"),
              _p("M0", MOMENT, "driving moment", "0 N*m", signed=True), _g()],
             Q={"x2": "M0/r2"}, reference="E4.13"),
    Energies("mass-spring-given-response", ["x"], [], "m*x'^2/2", "k*x^2/2",
             [_p("m", MASS, "mass"), _p("k", STIFFNESS, "stiffness"),
              _p("F", FORCE, "the force at the instant", "0 N", signed=True)],
             Q={"x": "F"}, reference="E5.22"),
    Energies("rolling-wheel-moving-ground", ["x"], [],
             "m*x'^2/2 + kappa*m*(x' + u0*Omega*sin(Omega*t))^2/2", "k*x^2/2",
             [_p("m", MASS, "wheel"), _p("k", STIFFNESS, "stiffness"),
              _p("u0", LENGTH, "ground amplitude", "0 m", signed=True),
              _p("Omega", ANGULAR_RATE, "ground frequency", "1 rad/s"), _kappa()],
             reference="E5.24"),
    Energies("radial-slot-release", ["x"], [], "m*(x'^2 + Omega^2*x^2)/2", "0",
             [_p("m", MASS, "block"), _p("Omega", ANGULAR_RATE, "platform rate")],
             reference="E6.7"),
    Energies("block-disk-springs", ["x", "phi"], ["phi"],
             "M*x'^2/2 + m*(x' - r*phi')^2/2 + m*r^2*phi'^2/4", "k*x^2/2 + k*r^2*phi^2/2",
             [_p("M", MASS, "block"), _p("m", MASS, "disk"), _p("r", LENGTH, "disk radius"),
              _p("k", STIFFNESS, "each spring"),
              _p("F", FORCE, "force on the block at the instant", "0 N", signed=True)],
             Q={"x": "F"}, reference="E4.14"),
    Energies("spring-coupled-pendulums", ["phi1", "phi2"], ["phi1", "phi2"],
             "m*l^2*(phi1'^2 + phi2'^2)",
             "-2*m*g*l*cos(phi1)*cos(phi2) + k*(2*l*sin(phi2) - b)^2/2",
             [_p("m", MASS, "each bob"), _p("l", LENGTH, "rod length"),
              _p("k", STIFFNESS, "spring"), _p("b", LENGTH, "free length of the spring",
                                                "0 m"), _g()],
             note="phi1 the bisector, phi2 half the opening", reference="E4.16",
             domain={"phi2": ("0", "pi/2")}),
    Energies("disk-on-swinging-bar", ["phi", "x"], ["phi"],
             "(m1*l^2/3 + m2*x^2 + J2)*phi'^2/2 + m2*x'^2/2", "-(m1*l/2 + m2*x)*g*cos(phi)",
             [_p("m1", MASS, "bar"), _p("l", LENGTH, "bar length"), _p("m2", MASS, "disk"),
              _p("J2", INERTIA, "disk about its centre"), _g()],
             note="no equilibrium with the disk free", reference="E4.17",
             domain={"x": ("0", "l")}),
    Energies("pendulum-on-sliding-block", ["x", "phi"], ["phi"],
             "(m1 + m2)*x'^2/2 + m2*l*x'*phi'*cos(phi) + m2*l^2*phi'^2/2",
             "-m2*g*l*cos(phi)",
             [_p("m1", MASS, "block"), _p("m2", MASS, "bob"), _p("l", LENGTH, "length"),
              _g()], reference="E4.19"),
)

_BY_NAME = {e.name: e for e in _TABLE}

#: Catalog scenes with no free coordinate, and why eom refuses them.
NO_COORDINATE = {
    "precessing-shaft": "it prescribes the motion",
    "rotating-angled-arm": "it prescribes the motion",
    "double-pendulum-impulse": "it is impulsive",
    "direct-central-impact": "it is impulsive",
    "slotted-link": "it is pure kinematics",
}


def energy_scene_names() -> list[str]:
    """The scene names ``eom --scene`` takes, in the table's order."""
    return list(_BY_NAME)


def energies(name: str) -> Energies:
    """The energies of scene ``name``; a scene without a free coordinate, or an unknown one,
    is refused (with "did you mean")."""
    if name in _BY_NAME:
        return _BY_NAME[name]
    if name in NO_COORDINATE:
        raise InputError(f"--scene {name} has no free coordinate ({NO_COORDINATE[name]}): "
                         "eom has no equation of motion to derive")
    import difflib

    close = difflib.get_close_matches(name, list(_BY_NAME), n=1)
    hint = f" (did you mean {close[0]!r}?)" if close else ""
    raise InputError(f"--scene: unknown scene {name!r} for eom{hint}; see dyncalc scenes "
                     "--command eom")
