"""The scalar inverse problems of ``coriolis`` (``a_c=12m/s^2 --omega 2rad/s vr=?``,
``a_c_mag=0.01m/s^2 --latitude 45deg vr=?``), posed as the scenes of
:mod:`dyncalc.scenes.coriolis_scalar` and solved by :func:`dyncalc.scenes.inverse.solve`.
"""
from __future__ import annotations

from ..errors import InputError
from ..result.entries import Result

#: Options an inverse problem reads, by set-up: option -> the scene parameter it gives.
_INVERSE_OPTIONS = {"perpendicular": {"omega": "omega", "vr": "vr", "mass": "mass"},
                    "earth": {"latitude": "latitude", "vr": "vr", "speed": "vr",
                              "heading": "heading", "omega": "omega", "mass": "mass"}}


def _inverse(texts: dict[str, str | None], words, strict: bool) -> Result | None:
    """A scalar inverse problem (``a_c=12m/s^2 --omega 2rad/s vr=?``,
    ``a_c_mag=0.01m/s^2 --latitude 45deg vr=?``) solved through
    :func:`dyncalc.scenes.inverse.solve`, or ``None`` when the words pose none."""
    if not words:
        return None
    from ..result.checks import split_assignment
    from ..scenes.coriolis_scalar import EARTH, PERPENDICULAR, TARGETS

    pairs = [split_assignment(word, "a parameter") for word in words]
    every = {n for names in TARGETS.values() for n in names}
    if not any(name in every or text.strip() == "?" for name, text in pairs):
        return None
    earthly = ("latitude", "speed", "heading")
    form = ("earth" if any(texts.get(n) is not None for n in earthly)
            or any(name in earthly for name, _text in pairs) else "perpendicular")
    scene = EARTH if form == "earth" else PERPENDICULAR
    allowed = _INVERSE_OPTIONS[form]
    scene_texts: dict[str, str] = {}
    labels: dict[str, str] = {}
    for option, text in texts.items():
        if text is None:
            continue
        if option not in allowed:
            raise InputError(f"--{option} does not go with an inverse problem: coriolis "
                             f"solves {scene.formula} for one unknown from "
                             f"{', '.join(p.name for p in scene.params)}")
        if form == "perpendicular" and "," in text:
            raise InputError(f"--{option}: an inverse problem takes magnitudes (perpendicular "
                             "vectors), e.g. --omega 2rad/s; give vectors to compute forward")
        name = allowed[option]
        if name in scene_texts:
            raise InputError("give --vr or --speed, not both")
        scene_texts[name], labels[name] = text, f"--{option}"
    if not any(name in every for name, _text in pairs):
        asked = next(name for name, text in pairs if text.strip() == "?")
        raise InputError(f"{asked}=? needs a result to solve from: one of "
                         f"{', '.join(TARGETS[form])}, e.g. {TARGETS[form][0]}=0.01m/s^2")
    for name, text in pairs:
        if name in every and name not in TARGETS[form]:
            other = ("--latitude" if form == "perpendicular" else "magnitudes without "
                     "--latitude")
            raise InputError(f"{name}= is not a result of this form: with "
                             f"{'magnitudes' if form == 'perpendicular' else '--latitude'} "
                             f"give one of {', '.join(TARGETS[form])} (or use {other})")
        if name in scene_texts:
            raise InputError(f"{name} is given twice ({labels[name]} and {name}=)")
        scene_texts[name], labels[name] = text, f"{name}="
    from ..scenes.inverse import solve

    return solve(scene, scene_texts, labels=labels, method=None, rtol=None, strict=strict,
                 command="coriolis")

