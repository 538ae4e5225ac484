"""The physics face's rule: a plain number is a quantity in its SI unit. Every scene's physics
function, called with SI numbers for its quantities (angles excepted: the physics works in the
unit an angle is given in), gives what it gives for the same quantities typed in SI units, to
the bit; the inverse solver relies on it (dyncalc.scenes.inverse._si_where_typed_in_si)."""
from __future__ import annotations

import pytest

from dyncalc.errors import InputError, PhysicsError
from dyncalc.scenes import computed_scenes, get_scene
from dyncalc.scenes.runner import compute_values, read_inputs
from dyncalc.units import ANGLE


def _example_texts(scene) -> dict[str, str]:
    """The scene's parameters at plain SI values: 1.5 of each (0.4 for a pure number, 0.3 for
    the smaller of two radii), the defaults left to the scene."""
    texts = {}
    for p in scene.params:
        if p.default is not None or p.optional or p.choices is not None or p.dim is ANGLE:
            continue
        if any(p.name in group[1:] for group in scene.one_of):
            continue
        texts[p.name] = "0.4" if not p.dim.si else f"1.5 {p.dim.si}"
    for group in scene.one_of:  # one of each group of alternatives (J or J_A)
        first = scene.param(group[0])
        if not any(n in texts or scene.param(n).default is not None for n in group) \
                and first.dim is not None:
            texts[first.name] = "0.4" if not first.dim.si else f"1.5 {first.dim.si}"
    if "r" in texts and ("R" in texts or "a" in texts):
        texts["r"] = "0.3 m"
    if scene.constraints and "a" in texts and "r" in texts and not scene.constraints[0].holds(
            {"a": 1.5, "r": 0.3}):  # a release radius inside r (radial-slot-release)
        texts["a"], texts["r"] = "0.3 m", "1.5 m"
    for p in scene.params:  # a required angle (slotted-link's theta)
        if p.dim is ANGLE and p.default is None and not p.optional:
            texts[p.name] = "0.5 rad"
    if "mu" in texts:
        texts["mu"] = "0.4"
    for p in scene.params:  # a required angle (an incline), given in radians
        if p.dim is ANGLE and p.default is None and not p.optional:
            texts[p.name] = "0.3 rad"
    if "J_A" in texts and scene.param("r") is not None and "r" not in texts:
        texts["r"] = "0.3 m"  # a wheel's J_A goes with its radius
    if "v1" in texts and "v2" in texts:
        texts["v2"] = "-0.5 m/s"  # an impact: body 1 catches body 2
    return texts


@pytest.mark.parametrize("name", list(computed_scenes()))
def test_si_numbers_give_what_si_quantities_give(name):
    scene = get_scene(name)
    prepared = read_inputs(scene, _example_texts(scene), {}, False)
    try:
        typed = compute_values(scene, prepared.kwargs, prepared.zeta, None, None)
    except (InputError, PhysicsError) as exc:
        pytest.fail(f"{name}: the example values are refused: {exc}")
    plain = dict(prepared.kwargs)
    for key, value in prepared.kwargs.items():
        param = scene.param(key)
        if param is not None and param.dim is not ANGLE and hasattr(value, "units"):
            plain[key] = prepared.si[key]
    numbers = compute_values(scene, plain, prepared.zeta, None, None)
    assert numbers[0].model == typed[0].model and numbers[2] == typed[2]
    assert list(numbers[1]) == list(typed[1])
    for result, value in typed[1].items():
        other = numbers[1][result]
        a = value.magnitude if hasattr(value, "units") else value
        b = other.magnitude if hasattr(other, "units") else other
        assert str(getattr(value, "units", "")) == str(getattr(other, "units", ""))
        assert repr(a) == repr(b), (name, result)
