"""The scene catalog as a whole: every scene's example reproduces its textbook value, every
scene is unit invariant, the catalog matches SCENES.md, and the runner's refusals."""
import json
import math
import shlex

import pytest
from click.testing import CliRunner

from dyncalc.cli import cli
from dyncalc.commands.natural_frequency import STANDARD
from dyncalc.errors import InputError
from dyncalc.scenes import catalog, computed_scenes, get_scene
from dyncalc.scenes.runner import run_scene, scene_kind
from dyncalc.units import convert, parse_quantity

#: Every scene of ../shared/SCENES.md (natural-frequency and damping tables).
SCENES_MD = {
    "mass-spring", "torsional", "pendulum", "physical-pendulum", "rolling-disk-spring",
    "rolling-in-track", "drum-block-spring", "board-on-drums", "clock-pendulum",
    "pulley-block-spring", "pendulum-spring-dashpot", "rod-torsion-spring",
    "disk-torsion-offset-mass", "wheel-on-moving-beam", "angled-member", "half-cylinder-shell",
    "coupled-blocks", "pendulum-accelerating-support", "pendulum-on-rotating-disk",
    "bead-on-rotating-ring", "quarter-car", "rod-in-fluid", "frame-brace-damper",
    "mass-spring-given-response", "rolling-wheel-moving-ground",
    "block-disk-springs", "spring-coupled-pendulums", "disk-on-swinging-bar",
    "pendulum-on-sliding-block",
    # rigid-body scenes (the rigid-body command)
    "drum-two-blocks", "wheel-incline-block", "two-drums-rope-drive", "direct-central-impact",
    "double-pendulum-impulse", "angled-bar-on-shaft", "precessing-shaft", "beam-spun-up",
    "rotating-angled-arm",
    # relative-motion scenes (coriolis --scene)
    "radial-slot-release", "slotted-link",
}

#: The scenes natural-frequency computes (disk-on-swinging-bar's example is eom's: no
#: equilibrium; tests/test_disk_on_swinging_bar.py).
SCENES = list(computed_scenes().values())
IDS = [s.name for s in SCENES]


def run_json(words):
    result = CliRunner().invoke(cli, [*words, "--json"])
    assert result.exit_code == 0, result.stderr
    return json.loads(result.stdout)


def example_words(scene):
    words = shlex.split(scene.example)
    assert words[0] == "dyncalc" and words[1] in ("natural-frequency", "forced-response",
                                                  "rigid-body", "coriolis"), \
        scene.example
    return words[1:]


def test_catalog_is_scenes_md():
    assert set(catalog()) == SCENES_MD


def test_scenes_json_lists_every_scene_with_dimensions():
    data = run_json(["scenes"])
    assert {s["name"] for s in data["scenes"]} == set(catalog())
    for scene in data["scenes"]:
        assert scene["params"], scene["name"]
        for p in scene["params"]:
            assert p["dimension"], (scene["name"], p["name"])
        command = ("dyncalc eom --scene" if scene["no_frequency"] else
                   ("dyncalc natural-frequency", "dyncalc forced-response",
                    "dyncalc rigid-body", "dyncalc coriolis"))
        assert scene["example"].startswith(command)


@pytest.mark.parametrize("scene", list(catalog().values()), ids=list(catalog()))
def test_scene_has_everything(scene):
    assert scene.summary and scene.figure and scene.equation and scene.formula
    assert scene.example_result, f"{scene.name} has no example_result"
    detail = CliRunner().invoke(cli, ["scenes", scene.name])
    assert detail.exit_code == 0
    assert f"example: {scene.example}" in detail.stdout


@pytest.mark.parametrize("scene", SCENES, ids=IDS)
def test_example_reproduces_textbook_value(scene):
    """One parametrised test runs every scene's example command and checks its result."""
    data = run_json(example_words(scene))
    assert data["scene"] == scene.name
    for name, text in scene.example_result.items():
        kind = scene_kind(scene, name)
        expected = parse_quantity(text, kind.dim, label=name, constraint=None).si
        got = data["results"][name]
        shown = convert(expected, kind.dim, got["unit"]) if got["unit"] != kind.dim.si else expected
        assert got["value"] == pytest.approx(shown, rel=1e-12, abs=1e-300), name


ALTERNATIVE = {"m": "ft", "kg": "lb", "N/m": "lbf/in", "N*m/rad": "lbf*ft/deg",
               "kg*m^2": "lb*ft^2", "m/s^2": "ft/s^2", "rad": "deg", "rad/s": "rpm",
               "m/s": "mph", "Pa": "psi", "N*s/m": "lbf*s/in", "N*s/m^2": "lbf*s/ft^2",
               "N": "lbf", "s": "min"}


def _parameters(scene):
    """The example's parameter texts by name (standard options mapped to their parameters)."""
    words = example_words(scene)[1:]
    texts, i = {}, 0
    while i < len(words):
        word = words[i]
        if word == "--scene":
            i += 2
            continue
        if word.startswith("--"):
            texts[STANDARD[word[2:]]] = words[i + 1]
            i += 2
            continue
        name, _, text = word.partition("=")
        texts[name] = text
        i += 1
    return texts


@pytest.mark.parametrize("scene", SCENES, ids=IDS)
def test_unit_invariance(scene):
    """The example with every quantity re-typed in another unit gives the same SI results."""
    texts = _parameters(scene)
    converted = {}
    for name, text in texts.items():
        param = scene.param(name)
        if param.dim is None or param.dim.si not in ALTERNATIVE:
            converted[name] = text
            continue
        si = parse_quantity(text, param.dim, constraint=None).si
        unit = ALTERNATIVE[param.dim.si]
        converted[name] = f"{convert(si, param.dim, unit)!r} {unit}"
    assert converted != texts or not texts, f"{scene.name}: nothing to convert"
    base = run_scene(scene, texts)
    other = run_scene(scene, converted)
    for name, entry in base.results.items():
        if isinstance(entry.si, float) and math.isfinite(entry.si):
            assert other.results[name].si == pytest.approx(entry.si, rel=1e-12, abs=1e-300), name


# --- the runner's refusals -------------------------------------------------------------------

def test_unknown_parameter_lists_the_scene_parameters():
    with pytest.raises(InputError) as err:
        run_scene("mass-spring", {"k": "1 N/m", "m": "1 kg", "c": "3"})
    assert str(err.value) == ("mass-spring has no parameter 'c'; the parameters of mass-spring "
                              "are: k [force]/[length], m [mass], zeta dimensionless?")


def test_missing_parameters_listed():
    with pytest.raises(InputError) as err:
        run_scene("mass-spring", {})
    assert str(err.value) == ("mass-spring needs k, m; the parameters of mass-spring are: "
                              "k [force]/[length], m [mass], zeta dimensionless?")


@pytest.mark.parametrize("typed, close", [
    ("mas-spring", "'mass-spring'"),
    ("pendulm", "'pendulum' or 'clock-pendulum'"),
    ("quartercar", "'quarter-car'"),
])
def test_a_misspelt_scene_gets_did_you_mean(typed, close):
    """Issue 15: a misspelt scene name gets the closest names (difflib), not the whole list."""
    with pytest.raises(InputError) as err:
        get_scene(typed)
    assert str(err.value) == (f"there is no scene {typed!r} (did you mean {close}?); "
                              "'dyncalc scenes' lists them all")


def test_unknown_scene():
    with pytest.raises(InputError) as err:
        get_scene("spring-mass")
    assert str(err.value).startswith("there is no scene 'spring-mass'; the scenes are: "
                                     "mass-spring, torsional, pendulum")


def test_default_parameter_can_be_overridden():
    moon = run_scene("pendulum", {"l": "1 m", "g": "1.62 m/s^2"})
    assert moon.results["omega"].si == pytest.approx(math.sqrt(1.62), rel=1e-15)
    assert moon.inputs["g"].value_in() == 1.62


def test_catalog_order_does_not_depend_on_which_scene_module_was_imported_first():
    """A test or command importing dyncalc.scenes.forced before the catalog loads must not move
    its scenes ahead of the others (docs/scenes.md is generated in catalog order)."""
    import subprocess
    import sys

    code = ("import {first}\nfrom dyncalc.scenes import catalog\nprint(','.join(catalog()))")
    plain = subprocess.run([sys.executable, "-c", code.format(first="dyncalc")],
                           capture_output=True, text=True, check=True).stdout
    early = subprocess.run([sys.executable, "-c", code.format(first="dyncalc.scenes.forced")],
                           capture_output=True, text=True, check=True).stdout
    assert plain.split(",").index("mass-spring") == 0
    assert early == plain
