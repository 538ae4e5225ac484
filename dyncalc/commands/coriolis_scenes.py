"""``coriolis --scene NAME``: the relative-motion scenes of the catalog
(:mod:`dyncalc.scenes.relative`) run through the scene runner, their parameters as
``NAME=QUANTITY`` words (or the options of the same name: ``--r``, ``--t``, ``--omega``, and
``--mass`` for ``m``)."""
from __future__ import annotations

from ..errors import InputError
from ..result import Result
from .words import gather_texts

__all__ = ["scene_result"]

#: coriolis options that stand for a scene parameter of another name.
_ALIASES = {"mass": "m"}


def scene_result(name: str, values: dict[str, str | None], words=(), *, rtol=None,
                 strict: bool = False) -> Result:
    """Run relative-motion scene ``name`` (refusing any other scene) on the options and words
    as typed."""
    from ..scenes import get_scene
    from ..scenes.relative import relative_scene_names
    from .natural_frequency import compute_scene

    scene = get_scene(name)
    if scene.name not in relative_scene_names():
        raise InputError(f"--scene {scene.name} is not a relative-motion scene; coriolis takes "
                         f"{', '.join(relative_scene_names())} (dyncalc scenes --command "
                         "coriolis)")
    flagged = {}
    for option, text in values.items():
        if text is None or option in ("scene", "plot", "basis"):
            if text is not None and option != "scene":
                raise InputError(f"--{option} does not go with --scene {scene.name}: it is for "
                                 "a motion given in time")
            continue
        param = _ALIASES.get(option, option)
        if scene.param(param) is None:
            raise InputError(f"--{option} does not go with --scene {scene.name}: give its "
                             f"parameters as NAME=QUANTITY words ({scene.signature()})")
        flagged[param] = (text, f"--{option}")
    texts, labels = gather_texts(flagged, words, "a scene parameter")
    return compute_scene(scene, texts, labels=labels, rtol=rtol, strict=strict,
                         command="coriolis")
