"""``rigid-body``: the kinetics of rigid and connected bodies (../shared/SPEC.md v2,
"rigid-body").

Two modes. With ``--scene NAME`` (or a textbook id, ``E4.10``) and ``NAME=QUANTITY`` words,
a scene of :mod:`dyncalc.scenes.kinetics` or :mod:`dyncalc.scenes.kinetics_loads` runs
forward, or is solved for its one unknown when a result is given (``alpha=2rad/s^2
J_A=?``: :mod:`dyncalc.scenes.inverse`). With ``--inertia-tensor MATRIX`` (``--omega VEC``,
``--alpha VEC``, each zero when left out), Euler's equations give the moment
``M = J alpha + omega x (J omega)`` in the body's axes (:mod:`dyncalc.physics.euler`), with
the angular momentum ``H = J omega`` and the kinetic energy ``T = omega . J omega / 2``.
"""
from __future__ import annotations

from ..errors import InputError
from ..result import Result
from ..units import (ANGULAR_ACCELERATION, ANGULAR_MOMENTUM, ANGULAR_RATE, ENERGY, INERTIA,
                     TORQUE)
from .record import Command, Parameter, ResultName
from .words import gather_texts

__all__ = ["COMMAND", "RigidInputs", "read", "compute", "rigid_body"]

#: The Euler-mode options, by parameter name.
_EULER = ("inertia_tensor", "omega", "alpha")
_USAGE = ("rigid-body needs --scene NAME with its NAME=QUANTITY words ('dyncalc scenes "
          "--command rigid-body' lists the scenes), or --inertia-tensor MATRIX with --omega VEC "
          "and --alpha VEC (Euler's equations)")


class RigidInputs:
    """What :func:`read` checked: a scene and its parameter texts (scene mode), or the SI
    tensor and vectors with their input entries (Euler mode)."""

    __slots__ = ("scene", "texts", "labels", "rtol", "strict", "euler", "entries")

    def __init__(self, scene=None, texts=None, labels=None, rtol=None, strict=False,
                 euler=None, entries=None):
        self.scene, self.texts, self.labels = scene, texts or {}, labels or {}
        self.rtol, self.strict = rtol, strict
        self.euler, self.entries = euler, entries or {}


def _flag(name: str) -> str:
    return "--" + name.replace("_", "-")


def read(options: dict[str, str | None], words=(), *, scene: str | None = None,
         rtol: float | None = None, strict: bool = False) -> RigidInputs:
    """The options as typed and the ``NAME=QUANTITY`` words -> :class:`RigidInputs`."""
    given = [name for name in _EULER if options.get(name) is not None]
    if scene is not None:
        if given:
            raise InputError(f"{_flag(given[0])} does not go with --scene: Euler's equations "
                             "(--inertia-tensor, --omega, --alpha) are the other mode of "
                             "rigid-body")
        chosen = rigid_scene(scene)
        texts, labels = gather_texts({}, words, "a scene parameter")
        return RigidInputs(chosen, texts, labels, rtol, strict)
    if not given:
        if words:
            raise InputError(f"NAME=QUANTITY words go with --scene NAME; got "
                             f"{str(words[0])[:60]!r}. {_USAGE}")
        raise InputError(_USAGE)
    if words:
        raise InputError(f"--inertia-tensor takes no NAME=QUANTITY words; got "
                         f"{str(words[0])[:60]!r}")
    if options.get("inertia_tensor") is None:
        raise InputError(f"{_flag(given[0])} needs --inertia-tensor MATRIX (in the body's "
                         "axes, e.g. \"2, 0, 0; 0, 2, 0; 0, 0, 1 kg*m^2\")")
    from .rigid_euler import read_euler

    euler, entries = read_euler(options, strict)
    return RigidInputs(rtol=rtol, strict=strict, euler=euler, entries=entries)


def rigid_scene(name: str):
    """The rigid-body scene called ``name`` (or reproducing example ``name``); refuses a
    scene of another command with the command that takes it."""
    from ..scenes import get_scene
    from ..scenes.kinetics import is_kinetics_scene, kinetics_scene_names

    chosen = get_scene(name)
    if not is_kinetics_scene(chosen.name):
        raise InputError(f"{chosen.name} is not a rigid-body scene ('dyncalc scenes "
                         f"{chosen.name}' names the commands that take it); the rigid-body "
                         f"scenes are: {', '.join(kinetics_scene_names())}")
    return chosen


def compute(inputs: RigidInputs) -> Result:
    """Run the scene forward or solve it for its unknown; or Euler's equations."""
    if inputs.euler is not None:
        from .rigid_euler import euler_result

        return euler_result(inputs.euler, inputs.entries)
    from .natural_frequency import compute_scene
    from .rigid_slips import add_slips

    result = compute_scene(inputs.scene, inputs.texts, labels=inputs.labels, rtol=inputs.rtol,
                           strict=inputs.strict, command="rigid-body")
    add_slips(inputs.scene.name, result)
    return result


def rigid_body(options: dict[str, str | None], words=(), *, scene: str | None = None,
               rtol: float | None = None, strict: bool = False) -> Result:
    """The command: the options as typed and ``NAME=QUANTITY`` words -> the Result
    (:func:`read`, then :func:`compute`).

    >>> r = rigid_body({}, ["m1=20kg", "m2=15kg", "r1=0.2m", "r2=0.4m", "J_A=2kg*m^2"],
    ...                scene="drum-two-blocks")
    >>> round(r.results["alpha"].si, 9), round(r.results["S2"].si, 6)
    (3.771788462, 124.469019)
    """
    return compute(read(options, words, scene=scene, rtol=rtol, strict=strict))


def _run(values: dict[str, str | None], words=(), *, rtol=None, strict=False) -> Result:
    return rigid_body({name: values.get(name) for name in _EULER}, words,
                      scene=values.get("scene"), rtol=rtol, strict=strict)


def _scene_choices():
    from ..scenes.kinetics import kinetics_scene_names

    return kinetics_scene_names()


COMMAND = Command(
    "rigid-body",
    "Kinetics of rigid bodies: accelerations, rope forces, impulses, Euler's equations.",
    """Accelerations, rope and support forces, impulses and stress resultants of the
    rigid-body scenes (dyncalc scenes --command rigid-body), or the moment of Euler's
    equations M = J alpha + omega x (J omega) for an inertia tensor.

    Scene mode: --scene NAME (or a textbook id such as E4.10) with NAME=QUANTITY words; a
    result given as NAME=QUANTITY with one parameter left out (or NAME=?) is solved for it.
    Euler mode: --inertia-tensor MATRIX (rows by ';', one trailing unit; a bare matrix is
    kg*m^2, as 'dyncalc inertia ... --value J_C' prints it) with --omega and --alpha (body
    axes; each zero when left out); also the angular momentum H = J omega and the kinetic
    energy T = omega.J omega/2.

    \b
    Examples:
      dyncalc rigid-body --scene E4.10 m1=20kg m2=15kg r1=0.2m r2=0.4m "J_A=2 kg*m^2"
      dyncalc rigid-body --scene E4.10 m1=20kg m2=15kg r1=0.2m r2=0.4m alpha=3rad/s^2 J_A=?
      dyncalc rigid-body --scene direct-central-impact m1=2kg m2=3kg v1=4m/s v2=-1m/s e=0.6
      dyncalc rigid-body --inertia-tensor "1, 0, 0; 0, 1, 0; 0, 0, 2 kg*m^2" \\
          --omega "2, 0, 3 rad/s" --alpha "0, 0, 1 rad/s^2"
      dyncalc rigid-body --inertia-tensor "$(dyncalc inertia 'rod(m=2kg, l=1m)' \\
          --value J_C)" --omega "0, 1, 0 rad/s" --alpha "0, 0, 0"
    """,
    (
        Parameter("scene", None, "A rigid-body set-up with its parameters as NAME=QUANTITY "
                  "words (dyncalc scenes --command rigid-body lists them).", "NAME",
                  kind="setting", choices=_scene_choices),
        Parameter("inertia_tensor", INERTIA, "Inertia tensor in the body's axes, e.g. "
                  "'2, 0, 0; 0, 2, 0; 0, 0, 1 kg*m^2' (a bare matrix is kg*m^2).", "MATRIX",
                  kind="text"),
        Parameter("omega", ANGULAR_RATE, "Angular velocity in the body's axes, e.g. "
                  "'0, 0, 2 rad/s' (default zero).", "VEC", kind="text"),
        Parameter("alpha", ANGULAR_ACCELERATION, "Angular acceleration in the body's axes, "
                  "e.g. '0, 0, 1 rad/s^2' (default zero).", "VEC", kind="text"),
        Parameter("plot", None, "Draw the N, V, M diagrams along the bar (beam-spun-up, with "
                  "t=; rotating-angled-arm, both legs), the section x= marked, into FILE "
                  "(.png, .svg or .pdf); needs matplotlib (the plot extra).", "FILE.png",
                  kind="after"),
    ),
    (
        ResultName("M", "M", TORQUE.si, "moment on the body, J alpha + omega x (J omega) "
                                         "(Euler mode)"),
        ResultName("M_mag", "|M|", TORQUE.si, "magnitude of M (Euler mode)"),
        ResultName("H", "H", ANGULAR_MOMENTUM.si, "angular momentum J omega (Euler mode; "
                   "in wheel-incline-block the friction force H, in N)"),
        ResultName("T", "T", ENERGY.si, "kinetic energy of rotation omega.J omega/2 (Euler "
                                         "mode)"),
        ResultName("alpha", "α", ANGULAR_ACCELERATION.si, "angular acceleration (scenes)"),
        ResultName("a1", "a1", "m/s^2", "acceleration of block 1"),
        ResultName("a2", "a2", "m/s^2", "acceleration of block 2"),
        ResultName("S1", "S1", "N", "force in the rope of block 1"),
        ResultName("S2", "S2", "N", "force in the rope of block 2"),
        ResultName("a", "a", "m/s^2", "acceleration of the block (wheel-incline-block)"),
        ResultName("S", "S", "N", "rope force (wheel-incline-block)"),
        ResultName("N", "N", "N", "normal force on the wheel (wheel-incline-block)"),
        ResultName("mu_min", "μ_min", "", "least static friction coefficient for rolling"),
        ResultName("v_c", "v_c", "m/s", "common velocity at the end of compression"),
        ResultName("v1_post", "v1'", "m/s", "velocity of body 1 after the impact"),
        ResultName("v2_post", "v2'", "m/s", "velocity of body 2 after the impact"),
        ResultName("F_hat", "F_hat", "N*s", "impulse each body receives in the impact"),
        ResultName("dE", "ΔE", "J", "kinetic energy lost in the impact"),
        ResultName("omega_1", "ω1", "rad/s", "angular velocity of bar 1 after the blow"),
        ResultName("omega_2", "ω2", "rad/s", "angular velocity of bar 2 after the blow"),
        ResultName("v_2", "v2", "m/s", "velocity of the centre of bar 2 after the blow"),
        ResultName("A_hat", "A_hat", "N*s", "impulse of the pin A on bar 1"),
        ResultName("B_hat", "B_hat", "N*s", "impulse bar 1 passes to bar 2 at B"),
        ResultName("d_0", "d0", "m", "height of the blow for which bar 2 only translates"),
        ResultName("d_A0", "d_A0", "m", "height of the blow for which the pins take no "
                                         "impulse"),
    ),
    _run,
    words="[NAME=QUANTITY]...",
)
