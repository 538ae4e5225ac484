"""The catalog's single-degree-of-freedom scenes as forced-response runs them: driven by
``--F0`` on their coordinate (../shared/SPEC.md, "forced-response": "other scenes give their
effective mass and stiffness and take --F0 on their coordinate").

Each entry of :data:`COORDINATES` says which coordinate the scene is driven on (a
displacement, driven by a force, or an angle, driven by a torque), what ``F0`` is there, and
the mass a scene adds when its frequency does not need one. :func:`driven_variant` builds the
scene forced-response runs: the scene's own parameters (an amplitude left out: the response is
linear), the mass where added, damping (unless the scene has its own), ``F0``, the excitation
frequency and the initial conditions; its physics is
:func:`dyncalc.physics.sdof.forced_coordinate`, which takes ``omega`` from the scene's own
function (natural-frequency's) and ``m_eff`` from the same formulas.
"""
from __future__ import annotations

import functools

from ..errors import InputError
from ..physics.sdof import forced_coordinate
from ..units import (ANGLE, ANGULAR_RATE, DAMPING, FORCE, LENGTH, MASS, TIME, TORQUE,
                     TORSIONAL_DAMPING, VELOCITY)
from . import Param, Scene

__all__ = ["COORDINATES", "Coordinate", "driven_variant", "is_driven_sdof"]


class Coordinate:
    """How a scene is driven: ``symbol`` (``x``, ``phi``), ``rotation`` (an angle driven by
    a torque), ``what`` the coordinate is, ``drive`` what F0 is, ``mass`` the description of
    the mass the variant adds (``""``: the scene has its own), ``damped`` whether the scene
    has its own damping."""

    __slots__ = ("symbol", "rotation", "what", "drive", "mass", "damped")

    def __init__(self, symbol: str, rotation: bool, what: str, drive: str, mass: str = "",
                 damped: bool = False):
        self.symbol, self.rotation, self.what, self.drive = symbol, rotation, what, drive
        self.mass, self.damped = mass, damped

    def sentence(self) -> str:
        """``driven on x, the block's displacement: F0 is a force on the block along it``"""
        return f"driven on {self.symbol}, {self.what}: F0 is {self.drive}"


_PIVOT = "a torque about the pivot"
COORDINATES = {
    "mass-spring": Coordinate("x", False, "the mass's displacement", "a force on the mass"),
    "torsional": Coordinate("phi", True, "the rotor's angle", "a torque on the rotor"),
    "pendulum": Coordinate("theta", True, "the angle from the vertical", _PIVOT,
                           mass="mass of the bob"),
    "physical-pendulum": Coordinate("phi", True, "the angle from the vertical", _PIVOT),
    "rolling-disk-spring": Coordinate("x", False, "the centre's displacement",
                                      "a horizontal force at the centre"),
    "rolling-in-track": Coordinate("s", False, "the arc length of the centre's path from the "
                                   "bottom", "a force at the centre along its path",
                                   mass="mass of the body"),
    "drum-block-spring": Coordinate("x", False, "the block's displacement",
                                    "a force on the block along the rope"),
    "board-on-drums": Coordinate("x", False, "the board's displacement",
                                 "a horizontal force on the board", mass="mass of the board"),
    "clock-pendulum": Coordinate("phi", True, "the angle from the vertical", _PIVOT),
    "pulley-block-spring": Coordinate("x", False, "the pulley centre's displacement",
                                      "a force on the pulley's axle along the spring"),
    "disk-torsion-offset-mass": Coordinate("phi", True, "the disks' angle",
                                           "a torque about the shaft"),
    "wheel-on-moving-beam": Coordinate("x", False, "the wheel centre's displacement",
                                       "a horizontal force at the wheel's centre"),
    "angled-member": Coordinate("phi", True, "the angle from the equilibrium", _PIVOT,
                                mass="mass of the whole bar"),
    "half-cylinder-shell": Coordinate("phi", True, "the rocking angle",
                                      "a torque about the contact point",
                                      mass="mass of the shell"),
    "rod-torsion-spring": Coordinate("phi", True, "the angle from the equilibrium phi_0",
                                     _PIVOT),
    "pendulum-accelerating-support": Coordinate("phi", True,
                                                "the angle from the equilibrium phi_0", _PIVOT,
                                                mass="mass of the bob"),
    "pendulum-on-rotating-disk": Coordinate("phi", True, "the angle from the radial line",
                                            _PIVOT, mass="mass of the bob"),
    "bead-on-rotating-ring": Coordinate("theta", True, "the angle from the equilibrium "
                                        "theta_eq", "a torque about the ring's centre (a "
                                        "tangential force times r)", mass="mass of the bead"),
    "pendulum-spring-dashpot": Coordinate("phi", True, "the angle from the vertical", _PIVOT,
                                          damped=True),
    "rod-in-fluid": Coordinate("phi", True, "the angle from the vertical", _PIVOT,
                               damped=True),
}

#: The forcing parameters every variant takes, in order (damping first unless its own).
_DAMPING_NAMES = ("zeta", "c", "Q")
FORCING_NAMES = ("zeta", "c", "Q", "F0", "Omega", "f_exc", "x0", "v0", "t")


def is_driven_sdof(name: str) -> bool:
    return name in COORDINATES


def has_spin(name: str) -> bool:
    """Whether scene ``name`` has its own ``Omega`` (a spin): its excitation is ``f_exc``."""
    from . import get_scene

    return get_scene(name).param("Omega") is not None


def _forcing_params(coordinate: Coordinate) -> tuple[Param, ...]:
    from .forced_parts import _damping, _frequency

    rot = coordinate.rotation
    damping = ()
    if not coordinate.damped:
        zeta, c, Q = _damping()
        c = Param("c", TORSIONAL_DAMPING if rot else DAMPING,
                  "viscous damping coefficient on " + coordinate.symbol, optional=True,
                  constraint="nonnegative")
        damping = (zeta, c, Q)
    return (*damping,
            Param("F0", TORQUE if rot else FORCE, f"amplitude of the drive: {coordinate.drive}",
                  optional=True, constraint="nonnegative", symbol="F_{0}"),
            *_frequency(),
            Param("x0", ANGLE if rot else LENGTH, f"initial {coordinate.symbol} (with t)",
                  optional=True, constraint=None, symbol="x_{0}"),
            Param("v0", ANGULAR_RATE if rot else VELOCITY,
                  f"initial rate of {coordinate.symbol} (with t)", optional=True,
                  constraint=None, symbol="v_{0}"),
            Param("t", TIME, "time of the total response x", optional=True,
                  constraint="nonnegative"))


def _compute(scene: Scene, coordinate: Coordinate, spin: bool, **kwargs):
    """The variant's physics: the scene's own parameters apart from the forcing ones (a
    scene's own ``Omega``, a spin, stays its own: the excitation is then ``f_exc``)."""
    forcing = {n: kwargs.pop(n) for n in FORCING_NAMES
               if n in kwargs and not (spin and n == "Omega")}
    mass = kwargs.pop("m") if coordinate.mass else None
    return forced_coordinate(scene.name, scene.compute, kwargs, forcing,
                             rotation=coordinate.rotation, mass=mass,
                             own_damping=coordinate.damped)


@functools.lru_cache(maxsize=None)
def driven_variant(name: str) -> Scene:
    """The scene ``forced-response --scene NAME`` runs for a single-degree-of-freedom scene
    of the catalog: driven by ``F0`` on its coordinate."""
    from . import get_scene
    from .forced_parts import _STEADY_LATEX

    scene = get_scene(name)
    coordinate = COORDINATES[scene.name]
    spin = has_spin(name)
    own = tuple(p for p in scene.params if p.name not in ("amplitude", "zeta"))
    if coordinate.mass:
        own = (*own, Param("m", MASS, coordinate.mass))
    forcing = tuple(p for p in _forcing_params(coordinate) if not (spin and p.name == "Omega"))
    params = (*own, *forcing)
    one_of = (*scene.one_of, *(() if coordinate.damped else (_DAMPING_NAMES,)),
              *(() if spin else (("Omega", "f_exc"),)))
    sym = coordinate.symbol
    unit = "rad" if coordinate.rotation else "m"
    equation = (f"m_eff {sym}'' + c {sym}' + k_eff {sym} = F0 cos(Omega t), from "
                f"{scene.equation} (small motion)")
    formula = (f"omega as natural-frequency gives it, m_eff the scene's inertia in {sym}, "
               f"k_eff = m_eff omega^2; X = (F0/k_eff) V ({unit}), "
               "V = 1/sqrt((1 - eta^2)^2 + (2 zeta eta)^2)")
    steady = tuple(t for t in _STEADY_LATEX if not any(
        f"${n}" in (t if isinstance(t, str) else t.template)
        for n in ("base", "unbalance", "k", "c", "F_T", "Z", "X", *(("f_exc",) if spin else ()))))
    latex = (r"$k_eff = $m_eff\,$omega^2", r"$X = \frac{$F0}{$k_eff}\,$V",
             r"$F_T = $TR\,$F0", *steady)
    return scene.replace(
        summary=f"{scene.summary}, driven by F0 on {sym}",
        figure=f"{scene.figure}; {coordinate.sentence()}",
        params=params, compute=functools.partial(_compute, scene, coordinate, spin),
        equation=equation, formula=formula, methods=(), one_of=one_of,
        accepts_zeta=False, example=forced_example(name), example_result={},
        no_zeta_because="its damping is its own" if coordinate.damped else "",
        latex=latex, sizes=(),
        assumptions=(*scene.assumptions, f"small motion about the equilibrium, "
                     f"{coordinate.sentence()}; X is the amplitude of {sym} (in {unit})"))


#: A runnable forced-response example per scene (the scene's own example's parameters).
_EXAMPLE_DRIVE = {False: '--F0 10N', True: '--F0 "0.5 N*m"'}


def forced_example(name: str) -> str:
    """``dyncalc forced-response --scene NAME ... --zeta 0.05 --F0 ... --Omega ...``."""
    from . import get_scene

    scene = get_scene(name)
    coordinate = COORDINATES[scene.name]
    words = _EXAMPLE_WORDS.get(name, "")
    damping = "" if coordinate.damped else " --zeta 0.05"
    frequency = ("--Omega 5rad/s" if scene.param("Omega") is None
                 else "--f-exc 2Hz" if name == "pendulum-on-rotating-disk" else "--f-exc 1Hz")
    drive = _EXAMPLE_F0.get(name, _EXAMPLE_DRIVE[coordinate.rotation])
    return (f"dyncalc forced-response --scene {name} {words}{damping} {drive} {frequency}")


_EXAMPLE_F0 = {"pendulum-on-rotating-disk": '--F0 "0.01 N*m"',
               "bead-on-rotating-ring": '--F0 "0.01 N*m"', "torsional": '--F0 "50 N*m"'}
_EXAMPLE_WORDS = {
    "mass-spring": "k=100N/m m=2kg",
    "torsional": '"kt=3 kN*m/rad" "J=1.2 kg*m^2"',
    "pendulum": "l=1m m=2kg",
    "physical-pendulum": 'm=2kg a=0.5m "J=(2/12) kg*m^2"',
    "rolling-disk-spring": "k=300N/m m=2kg",
    "rolling-in-track": "R=1m r=0.2m m=2kg",
    "drum-block-spring": "k=2kN/m m=4kg M=10kg",
    "board-on-drums": "mu=0.4 a=0.8m m=5kg",
    "clock-pendulum": "m=0.5kg l=1m M=2kg r=0.1m a=0.9m",
    "pulley-block-spring": "k=1kN/m m=3kg M=4kg",
    "disk-torsion-offset-mass": '"M=20kg" R=0.3m m=2kg r=0.05m a=0.2m "kt=50 N*m/rad"',
    "wheel-on-moving-beam": "k=500N/m m=5kg M=20kg",
    "angled-member": "l=0.5m m=3kg",
    "half-cylinder-shell": "r=0.5m m=2kg",
    "rod-torsion-spring": '"m=2kg" l=1m "kt=30 N*m/rad"',
    "pendulum-accelerating-support": "l=1m a0=3m/s^2 m=1kg",
    "pendulum-on-rotating-disk": "r=0.4m l=0.1m Omega=3rad/s m=0.2kg",
    "bead-on-rotating-ring": "r=0.5m Omega=2rad/s m=0.1kg",
    "pendulum-spring-dashpot": '"m=2kg" a=0.5m k=200N/m "d=6 N*s/m"',
    "rod-in-fluid": '"m=1.5kg" l=0.8m "beta=2 N*s/m^2"',
}


def refuse_excitation(name: str, option: str) -> InputError:
    """The refusal of ``--base``, ``--base-accel`` or ``--unbalance`` on a driven scene."""
    coordinate = COORDINATES[name]
    return InputError(f"{option} does not go with --scene {name}: the scene is driven by "
                      f"--F0 on its coordinate ({coordinate.symbol}, {coordinate.what}; F0 is "
                      f"{coordinate.drive}); base motion, ground acceleration and unbalance "
                      "are the mass-spring-damper's (--k, --m without --scene)")
