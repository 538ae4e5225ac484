"""Finding scenes (issue 16 item 5): a textbook example id (``E5.12``) names the scene that
reproduces it, in ``dyncalc scenes ID`` and in ``--scene ID``; the list shows each scene's
examples and the commands that take it; ``dyncalc scenes --command NAME`` filters."""
from __future__ import annotations

import math

import pytest

from helpers import error_line, invoke, json_of

DAMPED = ["pendulum-spring-dashpot", "rod-in-fluid", "frame-brace-damper"]


def _listing(*args):
    result = invoke("scenes", *args)
    assert result.exit_code == 0, result.stderr
    lines = result.stdout.splitlines()
    assert len(lines) % 3 == 0, result.stdout
    return [lines[i:i + 3] for i in range(0, len(lines), 3)]


def test_examples_are_read_from_the_reference():
    from dyncalc.scenes import get_scene

    assert get_scene("mass-spring").examples == ("E5.11", "E5.19", "E5.26")
    assert get_scene("rolling-in-track").examples == ("E4.9", "E5.17")
    assert get_scene("torsional").examples == ()


def test_scenes_id_shows_the_scene_that_reproduces_it():
    by_id, by_name = invoke("scenes", "E5.12"), invoke("scenes", "drum-block-spring")
    assert by_id.exit_code == 0, by_id.stderr
    assert by_id.stdout == by_name.stdout
    assert by_id.stdout.startswith("drum-block-spring: ")
    assert "examples: E5.12\n" in by_id.stdout
    assert json_of("scenes", "e5.12") == json_of("scenes", "drum-block-spring")


def test_scenes_id_of_several_scenes_lists_them():
    blocks = _listing("E3.44")
    assert [b[0].split()[0] for b in blocks] == ["physical-pendulum", "angled-member"]
    assert blocks[0][2].strip() == ("examples: E3.44, E5.15; commands: natural-frequency, "
                                    "forced-response, eom")


def test_scenes_unknown_id_is_refused():
    assert error_line(invoke("scenes", "E9.99")) == (
        "Error: no scene reproduces example E9.99; 'dyncalc scenes' lists the examples of "
        "each scene")


def test_scene_option_takes_an_example_id():
    data = json_of("natural-frequency", "--scene", "E5.12", "k=2kN/m", "m=4kg", "M=10kg")
    assert data["scene"] == "drum-block-spring"
    # omega^2 = 2k / (M + 2m) (Gross et al., E5.12): the drum radius cancels
    assert data["results"]["omega"]["value"] == pytest.approx(math.sqrt(2 * 2000 / (10 + 2 * 4)),
                                                     rel=1e-14)
    assert data == json_of("natural-frequency", "--scene", "drum-block-spring", "k=2kN/m",
                           "m=4kg", "M=10kg")


def test_scene_option_refuses_an_id_of_several_scenes():
    assert error_line(invoke("natural-frequency", "--scene", "E3.44", "l=0.5m")) == (
        "Error: example E3.44 is reproduced by several scenes: physical-pendulum, "
        "angled-member; name one of them")


def test_damping_ratio_scene_takes_an_example_id():
    args = ["m=1.5kg", "l=0.8m", "beta=2 N*s/m^2"]
    by_id = json_of("damping-ratio", "--scene", "E5.14", *args)
    assert by_id["scene"] == "rod-in-fluid"
    assert by_id == json_of("damping-ratio", "--scene", "rod-in-fluid", *args)
    assert error_line(invoke("damping-ratio", "--scene", "E5.12", "k=2kN/m")) == (
        "Error: damping-ratio --scene takes a scene with a damper: "
        f"{', '.join(DAMPED)}; drum-block-spring has none (natural-frequency computes it)")


def test_batch_scene_takes_an_example_id(tmp_path):
    rows = tmp_path / "rows.csv"
    rows.write_text("k [kN/m],m [kg],M [kg]\n2,4,10\n")
    result = invoke("natural-frequency", "--scene", "E5.12", "--batch", str(rows))
    assert result.exit_code == 0, result.stderr
    header, row = result.stdout.splitlines()[:2]
    omega = float(row.split(",")[header.split(",").index("omega [rad/s]")])
    assert omega == pytest.approx(math.sqrt(2 * 2000 / 18), rel=1e-14)


def test_the_list_shows_examples_and_commands():
    from dyncalc.scenes import catalog

    blocks = _listing()
    assert len(blocks) == len(catalog())
    shown = {b[0].split()[0]: b[2].strip() for b in blocks}
    assert shown["mass-spring"] == ("examples: E5.11, E5.19, E5.26; commands: "
                                    "natural-frequency, forced-response, eom")
    assert shown["torsional"] == ("examples: none; commands: natural-frequency, "
                                  "forced-response, eom")
    assert shown["rod-in-fluid"] == (
        "examples: E5.14; commands: natural-frequency, damping-ratio, forced-response, "
        "eom")
    for scene in catalog().values():  # the command of its example is among them
        assert scene.example.split()[1] in shown[scene.name].rpartition("commands: ")[2]


def test_the_json_list_has_examples_and_commands():
    scenes = {s["name"]: s for s in json_of("scenes")["scenes"]}
    assert scenes["rolling-in-track"]["examples"] == ["E4.9", "E5.17"]
    assert scenes["frame-brace-damper"]["commands"] == ["natural-frequency", "damping-ratio",
                                                        "forced-response", "eom"]


def test_command_filter():
    from dyncalc.scenes import catalog

    assert [b[0].split()[0] for b in _listing("--command", "damping-ratio")] == DAMPED
    from dyncalc.scenes.kinetics import kinetics_scene_names

    rigid = kinetics_scene_names()
    relative = {"radial-slot-release", "slotted-link"}  # coriolis --scene only
    assert rigid and len(_listing("--command", "natural-frequency")) == \
        len(set(catalog()) - relative - set(rigid))
    assert [b[0].split()[0] for b in _listing("--command", "rigid-body")] == rigid
    assert [b[0].split()[0] for b in _listing("--command", "coriolis")] == sorted(relative)
    data = json_of("scenes", "--command", "damping-ratio")
    assert [s["name"] for s in data["scenes"]] == DAMPED


@pytest.mark.parametrize("args, message", [
    (["--command", "spring-series"], "Error: spring-series takes no scene; the commands with "
                                     "scenes are natural-frequency, damping-ratio, "
                                     "coriolis, forced-response, modes, rigid-body, eom"),
    (["--command", "natral-frequency"], "Error: there is no command 'natral-frequency' (did "
                                        "you mean 'natural-frequency'?); the commands with "
                                        "scenes are natural-frequency, damping-ratio, "
                                        "coriolis, forced-response, modes, rigid-body, eom"),
    (["mass-spring", "--command", "damping-ratio"], "Error: give a scene NAME or --command, "
                                                    "not both"),
])
def test_command_filter_refusals(args, message):
    assert error_line(invoke("scenes", *args)) == message
