"""``natural-frequency``: the parameter texts of a scene -> its Result, forward or inverse.

The command decides what the texts ask for: a result given as an input (``f=5Hz``) is an
inverse problem (:func:`dyncalc.scenes.inverse.solve`), anything else runs the scene
(:func:`dyncalc.scenes.runner.run_scene`). Without ``--scene`` the parameters choose it.
"""
from __future__ import annotations

from ..errors import InputError
from ..result import Result
from ..scenes import Scene, get_scene

__all__ = ["STANDARD", "INFERENCE", "collect_parameters", "infer_scene", "compute_scene",
           "natural_frequency"]

#: Standard options and the scene parameter each one is (SPEC.md).
STANDARD = {"k": "k", "m": "m", "kt": "kt", "inertia": "J", "length": "l",
            "amplitude": "amplitude", "zeta": "zeta", "g": "g"}

#: Without --scene, the parameters given choose the scene (SPEC.md, natural-frequency).
INFERENCE = (("mass-spring", {"k", "m"}), ("torsional", {"kt", "J"}), ("pendulum", {"l"}))


def collect_parameters(options: dict[str, str | None], words: tuple[str, ...] | list[str]):
    """Standard options and NAME=QUANTITY words -> (texts by parameter, labels by parameter)."""
    from ..result.checks import split_assignment

    texts: dict[str, str] = {}
    labels: dict[str, str] = {}
    for option, param in STANDARD.items():
        if options.get(option) is not None:
            texts[param] = options[option]
            labels[param] = f"--{option}"
    for word in words:
        name, text = split_assignment(word, "a scene parameter")
        if name in texts:
            raise InputError(f"{name} is given twice ({labels[name]} and {name}=)")
        texts[name] = text
        labels[name] = f"{name}="
    return texts, labels


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
    from ..scenes.inverse import is_inverse, solve
    from ..scenes.runner import run_scene

    if isinstance(scene, str):
        scene = get_scene(scene)
    if is_inverse(scene, texts):
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
    return compute_scene(name, texts, labels=labels, method=method, rtol=rtol, strict=strict)
