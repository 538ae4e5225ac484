"""``natural-frequency``: the parameter texts of a scene -> its Result, forward or inverse.

The command decides what the texts ask for: a result given as an input (``f=5Hz``) is an
inverse problem (:func:`dyncalc.scenes.inverse.solve`), anything else runs the scene
(:func:`dyncalc.scenes.runner.run_scene`). Without ``--scene`` the parameters choose it.
"""
from __future__ import annotations

from ..errors import InputError
from ..result import Result
from ..scenes import RELATIVE_MODULE, Scene, get_scene, refuse_kinetics, registered_by
from ..units import (ACCELERATION, ANGLE, ANGULAR_RATE, CYCLE_RATE, DIMENSIONLESS, INERTIA,
                     LENGTH, MASS, STIFFNESS, TIME, TORSIONAL_STIFFNESS)
from .record import Command, Parameter, ResultName
from .words import gather_texts

__all__ = ["COMMAND", "STANDARD", "INFERENCE", "collect_parameters", "infer_scene", "compute_scene",
           "natural_frequency"]

#: Standard options whose scene parameter has another name (``--inertia`` is ``J``).
_SCENE_NAMES = {"inertia": "J", "length": "l"}

#: Without --scene, the parameters given choose the scene (docs/scenes.md, the top).
INFERENCE = (("mass-spring", {"k", "m"}), ("torsional", {"kt", "J"}), ("pendulum", {"l"}))


def collect_parameters(options: dict[str, str | None], words: tuple[str, ...] | list[str]):
    """Standard options and NAME=QUANTITY words -> (texts by parameter, labels by parameter)."""
    flagged = {param: (options.get(option), f"--{option}") for option, param in STANDARD.items()}
    return gather_texts(flagged, words, "a scene parameter")


def method_names(scene: str | None = None) -> list[str]:
    """The words ``--method`` takes: ``auto`` and the methods of scene ``scene`` (a name or an
    example id), or of every scene when none (or an unknown one) is given: for completion."""
    if scene is not None:
        try:
            return ["auto", *get_scene(scene).methods]
        except InputError:
            pass
    from ..scenes import catalog

    return list(dict.fromkeys(["auto", *(m for s in catalog().values() for m in s.methods)]))


def infer_scene(names: set[str]) -> str:
    """The scene the parameter names fit: mass-spring (the default), torsional or pendulum
    (results given to solve for, ``f=5Hz``, do not choose)."""
    from ..scenes.runner import is_result_name

    given = {n for n in names if n != "zeta" and not is_result_name(n)}
    if not given:
        return "mass-spring"
    for scene_name, keys in INFERENCE:
        if given & keys and given <= {p.name for p in get_scene(scene_name).params}:
            return scene_name
    raise InputError(f"the parameters given ({', '.join(sorted(given))}) fit no scene on their "
                     "own; name one with --scene (dyncalc scenes lists them)")


def compute_scene(scene: Scene | str, texts: dict[str, str], *,
                  labels: dict[str, str] | None = None, method: str | None = None,
                  rtol: float | None = None, strict: bool = False,
                  command: str = "natural-frequency") -> Result:
    """``scene`` computed from the parameter texts: solved for the unknown when a result is
    given as an input (``f=5Hz`` with ``k`` left out or ``k=?``), run forward otherwise."""
    from ..scenes.runner import is_inverse, run_scene

    if isinstance(scene, str):
        scene = get_scene(scene)
    if is_inverse(scene, texts):
        from ..scenes.inverse import solve  # the solver (and scipy) only for inverse problems

        return solve(scene, texts, labels=labels or {}, method=method, rtol=rtol,
                     strict=strict, command=command)
    return run_scene(scene, texts, labels=labels, method=method, rtol=rtol, strict=strict,
                     command=command)


def natural_frequency(options: dict[str, str | None], words: tuple[str, ...] | list[str], *,
                      scene: str | None = None, method: str | None = None,
                      rtol: float | None = None, strict: bool = False) -> Result:
    """The command: standard options (``{"k": "2 kN/m", ...}``) and ``NAME=QUANTITY`` words
    -> the Result of the scene they name or choose."""
    texts, labels = collect_parameters(options, words)
    name = scene if scene is not None else infer_scene(set(texts))
    chosen = get_scene(name)
    refuse_kinetics(chosen.name, "natural-frequency")
    if registered_by(chosen.name) == RELATIVE_MODULE:
        raise InputError(f"--scene {chosen.name} is a relative-motion scene with no "
                         f"frequency: run it with dyncalc coriolis --scene {chosen.name}")
    return compute_scene(chosen, texts, labels=labels, method=method, rtol=rtol, strict=strict)


def natural_scene_names() -> list[str]:
    """The scenes ``natural-frequency --scene`` takes: every scene but the rigid-body ones and
    the relative-motion ones (``coriolis --scene``)."""
    from ..scenes import KINETICS_MODULES, catalog

    return [name for name in catalog()
            if registered_by(name) not in (*KINETICS_MODULES, RELATIVE_MODULE)]


# --- the command record ----------------------------------------------------------------------

def _run(values: dict[str, str | None], words=(), *, rtol=None, strict=False) -> Result:
    return natural_frequency({option: values.get(option) for option in STANDARD}, words,
                             scene=values.get("scene"), method=values.get("method"),
                             rtol=rtol, strict=strict)


COMMAND = Command(
    "natural-frequency",
    "Natural frequency omega (rad/s), f (Hz) and period T (s).",
    """Natural frequency omega (rad/s), f (Hz) and period T (s) of a scene.

    Scene parameters are given as NAME=QUANTITY words or by the standard options; a
    parameter that cancels out of the answer is never asked for. Bare numbers are SI.

    \b
    Examples:
      dyncalc natural-frequency --k "2 kN/m" --m 4kg
      dyncalc natural-frequency --k 100N/m --m 2kg --zeta 0.05
      dyncalc natural-frequency --length 1m --amplitude 170deg
      dyncalc natural-frequency --scene physical-pendulum m=2kg a=0.5m "J=(2/12) kg*m^2"
      dyncalc natural-frequency --k 100N/m --m 2kg --check f=1.13Hz
      dyncalc natural-frequency --batch rows.csv     # header: k [N/m],m [kg]
    """,
    (
        Parameter("scene", None, "The set-up (dyncalc scenes lists them); default: chosen by "
                  "the parameters given (k, m: mass-spring; kt, J: torsional; l: pendulum).",
                  "NAME", kind="setting", choices=natural_scene_names),
        Parameter("k", STIFFNESS, "Stiffness, e.g. '2 kN/m' (k=).", "K"),
        Parameter("m", MASS, "Mass, e.g. 4kg (m=).", "M"),
        Parameter("kt", TORSIONAL_STIFFNESS, "Torsional stiffness, e.g. '3 kN*m/rad' (kt=).",
                  "KT"),
        Parameter("inertia", INERTIA, "Mass moment of inertia, e.g. '1.2 kg*m^2' (J=).", "J"),
        Parameter("length", LENGTH, "Pendulum length (l=).", "L"),
        Parameter("amplitude", ANGLE, "Swing amplitude for the exact large-amplitude period, "
                  "e.g. 30deg.", "ANGLE"),
        Parameter("zeta", DIMENSIONLESS, "Damping ratio: adds omega_d, f_d, T_d.", "ZETA"),
        Parameter("g", ACCELERATION, "Gravitational acceleration (default 9.80665 m/s^2).",
                  "G"),
        Parameter("method", None, "auto (default: the cheapest model meeting --rtol), or one "
                  "the scene offers (dyncalc scenes NAME lists them; pendulums: small-angle, "
                  "series, elliptic, ode; half-cylinder-shell: linear, quadrature, ode).",
                  "METHOD", kind="setting", choices=method_names),
    ),
    (
        ResultName("omega", "ω", ANGULAR_RATE.si, "angular frequency"),
        ResultName("f", "f", CYCLE_RATE.si, "frequency"),
        ResultName("T", "T", TIME.si, "period"),
        ResultName("zeta", "ζ", "", "damping ratio (with --zeta or a damped scene)"),
        ResultName("omega_d", "ωd", ANGULAR_RATE.si, "damped angular frequency"),
        ResultName("f_d", "fd", CYCLE_RATE.si, "damped frequency"),
        ResultName("T_d", "Td", TIME.si, "damped period"),
        ResultName("omega_<i>", "ω<i>", ANGULAR_RATE.si, "angular frequency of mode i"),
        ResultName("f_<i>", "f<i>", CYCLE_RATE.si, "frequency of mode i"),
        ResultName("T_<i>", "T<i>", TIME.si, "period of mode i"),
    ),
    _run,
    words="[NAME=QUANTITY]...",
)

#: Standard options and the scene parameter each one is (docs/commands.md), from the record.
STANDARD = {p.name: _SCENE_NAMES.get(p.name, p.name) for p in COMMAND.inputs}
