"""Custom shell completion (issue 16 item 3): what click cannot guess, asked the way a shell
asks (``_DYNCALC_COMPLETE=bash_complete`` with ``COMP_WORDS``/``COMP_CWORD``) of the real
program in-process: scene names the command takes, result names, ``NAME=`` then common units
for ``--unit``, method names by scene, files for ``--batch`` and ``--plot``."""
from __future__ import annotations

import shlex

import pytest

from helpers import invoke

DAMPED = ["pendulum-spring-dashpot", "rod-in-fluid", "frame-brace-damper"]


def complete(line: str, monkeypatch, capsys, shell: str = "bash") -> list[tuple[str, str]]:
    """What ``dyncalc`` answers a shell completing ``line`` (its last word, possibly empty,
    is the one being completed): ``(type, value)`` pairs."""
    import dyncalc.cli

    words = shlex.split(line) + ([""] if line.endswith(" ") else [])
    monkeypatch.setenv("_DYNCALC_COMPLETE", f"{shell}_complete")
    monkeypatch.setenv("COMP_WORDS", line)
    monkeypatch.setenv("COMP_CWORD", str(len(words) - 1))
    capsys.readouterr()
    with pytest.raises(SystemExit) as stop:
        dyncalc.cli.main([])
    assert stop.value.code == 0
    out = capsys.readouterr().out.splitlines()
    if shell == "zsh":  # type, value, description: three lines each
        return [(out[i], out[i + 1]) for i in range(0, len(out), 3)]
    return [tuple(item.split(",", 1)) for item in out if item]  # none: one empty line


def values(line, monkeypatch, capsys) -> list[str]:
    items = complete(line, monkeypatch, capsys)
    assert {t for t, _ in items} <= {"plain"}, items
    return [v for _, v in items]


def test_scene_names_only_those_the_command_takes(monkeypatch, capsys):
    from dyncalc.commands.natural_frequency import natural_scene_names
    from dyncalc.scenes.kinetics import kinetics_scene_names

    relative = ["radial-slot-release", "slotted-link"]
    assert values("dyncalc natural-frequency --scene ", monkeypatch, capsys) == \
        natural_scene_names()
    assert not set(relative) & set(natural_scene_names())
    assert values("dyncalc coriolis --scene ", monkeypatch, capsys) == relative
    assert values("dyncalc rigid-body --scene ", monkeypatch, capsys) == kinetics_scene_names()
    assert values("dyncalc natural-frequency --scene pend", monkeypatch, capsys) == [
        "pendulum", "pendulum-accelerating-support", "pendulum-on-rotating-disk",
        "pendulum-spring-dashpot", "pendulum-on-sliding-block"]
    assert values("dyncalc damping-ratio --scene ", monkeypatch, capsys) == DAMPED
    assert values("dyncalc damping-ratio --scene pend", monkeypatch, capsys) == [
        "pendulum-spring-dashpot"]


def test_result_names(monkeypatch, capsys):
    assert values("dyncalc natural-frequency --k 1N/m --m 1kg --value ", monkeypatch,
                  capsys)[:3] == ["omega", "f", "T"]
    assert values("dyncalc natural-frequency --value omega_", monkeypatch, capsys) == [
        "omega_d", "omega_1"]
    assert values("dyncalc spring-series --check k", monkeypatch, capsys) == ["k_eq=", "k1="]
    assert values("dyncalc coriolis --unit a_c", monkeypatch, capsys) == [
        "a_c=", "a_c_mag=", "a_centripetal=", "a_c_horizontal=", "a_c_horizontal_mag="]


def test_units_after_unit_name_equals(monkeypatch, capsys):
    assert values("dyncalc spring-series --unit k_eq=", monkeypatch, capsys) == [
        "k_eq=N/m", "k_eq=N/mm", "k_eq=kN/m", "k_eq=lbf/in"]
    assert values("dyncalc natural-frequency --unit T=m", monkeypatch, capsys) == [
        "T=ms", "T=min"]
    assert values("dyncalc natural-frequency --unit omega=", monkeypatch, capsys) == [
        "omega=rad/s", "omega=deg/s", "omega=rpm"]
    assert values("dyncalc natural-frequency --unit nothing=", monkeypatch, capsys) == []
    assert values("dyncalc natural-frequency --unit zeta=", monkeypatch, capsys) == []


def test_methods_by_scene(monkeypatch, capsys):
    assert values("dyncalc natural-frequency --scene pendulum --method ", monkeypatch,
                  capsys) == ["auto", "small-angle", "series", "elliptic", "ode"]
    assert values("dyncalc natural-frequency --scene E4.18 --method ", monkeypatch,
                  capsys) == ["auto", "linear", "quadrature", "ode"]
    assert values("dyncalc natural-frequency --scene mass-spring --method ", monkeypatch,
                  capsys) == ["auto"]
    every = values("dyncalc natural-frequency --method ", monkeypatch, capsys)
    assert every == ["auto", "small-angle", "series", "elliptic", "ode", "linear", "quadrature",
                     "exact", "small-damping"]
    assert values("dyncalc natural-frequency --scene nonsense --method a", monkeypatch,
                  capsys) == ["auto"]
    assert values("dyncalc damping-ratio --method ", monkeypatch, capsys) == [
        "log-linear", "nonlinear"]
    assert values("dyncalc damping-ratio --scene frame-brace-damper --method ", monkeypatch,
                  capsys) == ["auto", "exact", "small-damping"]
    assert values("dyncalc rolling-onset --method ", monkeypatch, capsys) == [
        "auto", "closed-form", "ode"]


@pytest.mark.parametrize("line", ["dyncalc natural-frequency --batch ",
                                  "dyncalc spring-series --batch ro",
                                  "dyncalc damping-ratio --plot dec"])
def test_files(line, monkeypatch, capsys):
    word = shlex.split(line + "x")[-1][:-1]
    assert complete(line, monkeypatch, capsys) == [("file", word)]


def test_scenes_command_option_and_zsh_protocol(monkeypatch, capsys):
    assert values("dyncalc scenes --command ", monkeypatch, capsys) == [
        "natural-frequency", "damping-ratio", "coriolis", "forced-response", "modes",
        "rigid-body", "eom"]
    assert complete("dyncalc damping-ratio --scene rod", monkeypatch, capsys, "zsh") == [
        ("plain", "rod-in-fluid")]


def _first_example(command: str) -> list[str]:
    from dyncalc.cli.modules import click_command

    help_text = click_command(command).record.help
    line = next(l for l in help_text.split("Examples:")[1].splitlines() if l.strip())
    return shlex.split(line.split("#")[0])[1:]


def test_every_suggested_unit_is_taken_by_unit(monkeypatch, capsys):
    """Each unit offered after ``--unit NAME=`` is accepted for NAME by the real command (and
    every canonical unit of a result with a dimension has a list)."""
    import json

    from dyncalc.cli.modules import COMMAND_MODULES, click_command
    from dyncalc.cli.options import COMMON_UNITS

    canonical = {r.unit for c in COMMAND_MODULES if c != "scenes"
                 for r in click_command(c).record.results if r.unit}
    assert canonical == set(COMMON_UNITS)
    tried = set()
    runs = []
    for command in COMMAND_MODULES:
        if command == "scenes":
            continue
        args = [a for a in _first_example(command) if a != "--explain"]
        if command == "damping-ratio":  # a form with dimensioned results
            args = ["damping-ratio", "--c", "4N*s/m", "--k", "100N/m", "--m", "1kg"]
        if command == "coriolis":  # with the force; and a motion in time (alpha)
            args += ["--mass", "2kg"]
            runs.append(["coriolis", "--r", "1 m, 0, 0", "--omega", "0, 0, k*t",
                         "k=1rad/s^2", "--t", "1s"])
        runs.append(args)
        if command == "rigid-body":  # an impact (N*s, J) and Euler mode (N*m, kg*m^2/s)
            runs += [["rigid-body", "--scene", "direct-central-impact", "m1=2kg", "m2=3kg",
                      "v1=4m/s", "v2=-1m/s", "e=0.6"],
                     ["rigid-body", "--inertia-tensor", "1,0,0;0,1,0;0,0,2", "--omega",
                      "2,0,3", "--alpha", "0,0,1"]]
    for args in runs:
        result = invoke(*args, "--json")
        assert result.exit_code == 0, (args, result.stderr)
        for name in json.loads(result.stdout)["results"]:
            offered = values(f"dyncalc {shlex.join(args)} --unit {name}=", monkeypatch,
                             capsys)
            for item in offered:
                shown = invoke(*args, "--unit", item)
                assert shown.exit_code == 0, (args, item, shown.stderr)
                tried.add(item.partition("=")[2])
    assert tried == {u for units in COMMON_UNITS.values() for u in units}
