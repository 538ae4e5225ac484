"""``dyncalc scenes``: the catalog, read from the scene registry."""
from __future__ import annotations

import json

import click

from ..errors import InputError
from .command import Command


def _complete_scene(ctx, param, incomplete):
    from ..scenes import scene_names

    return [n for n in scene_names() if n.startswith(incomplete)]


def scene_commands() -> dict[str, list[str]]:
    """Command name -> the scenes it accepts (the choices of its record's ``--scene``), for the
    commands that take a scene, in the order of ``dyncalc --help``."""
    from .modules import COMMAND_MODULES, click_command

    out = {}
    for name in COMMAND_MODULES:
        record = getattr(click_command(name), "record", None)
        param = record.parameter("scene") if record is not None else None
        if param is not None:
            choices = param.choices() if callable(param.choices) else param.choices
            out[name] = list(choices or ())
    return out


def _commands_of(name: str, commands: dict[str, list[str]]) -> list[str]:
    return [command for command, accepted in commands.items() if name in accepted]


def _filter(command: str, commands: dict[str, list[str]]) -> list[str]:
    """The scenes ``dyncalc scenes --command COMMAND`` lists; refuses a command without."""
    from difflib import get_close_matches

    from .modules import COMMAND_MODULES

    with_scenes = f"the commands with scenes are {', '.join(commands)}"
    if command in commands:
        return commands[command]
    if command in COMMAND_MODULES:
        raise InputError(f"{command} takes no scene; {with_scenes}")
    close = get_close_matches(command, list(COMMAND_MODULES))
    hint = f" (did you mean {' or '.join(repr(c) for c in close)}?)" if close else ""
    raise InputError(f"there is no command {command[:80]!r}{hint}; {with_scenes}")


def _derived(name: str) -> list[str]:
    """The equations ``eom --scene NAME`` derives from the scene's energies (generated data:
    no sympy here), or none."""
    from ..scenes.derived import DERIVED

    return list(DERIVED.get(name, ()))


def _describe(scene, commands: dict[str, list[str]]) -> dict:
    return {
        "name": scene.name,
        "summary": scene.summary,
        "figure": scene.figure,
        "equation": scene.equation,
        "derived": _derived(scene.name),
        "formula": scene.formula,
        "reference": scene.reference,
        "examples": list(scene.examples),
        "commands": _commands_of(scene.name, commands),
        "example": scene.example,
        "no_frequency": scene.no_frequency,
        "constraints": [c.text for c in scene.constraints],
        "one_of": [list(group) for group in scene.one_of],
        "methods": ["auto", *scene.methods],
        "params": [_describe_param(p) for p in scene.params],
    }


def _describe_param(p) -> dict:
    required = p.default is None and not p.optional
    return {"name": p.name,
            "dimension": p.dim.display if p.dim is not None else "choice",
            "unit": p.dim.si if p.dim is not None else "",
            "choices": list(p.choices) if p.choices else None,
            "default": p.default, "required": required, "description": p.description}


def _driven_lines(name: str) -> list[str]:
    """A single-degree-of-freedom scene: its coordinate and forced-response example."""
    from ..scenes.sdof import COORDINATES, forced_example

    coordinate = COORDINATES.get(name)
    if coordinate is None:
        return []
    added = f" (adds m: {coordinate.mass})" if coordinate.mass else ""
    return [f"forced-response: {coordinate.sentence()}{added}", f"example: {forced_example(name)}"]


def _complete_command(ctx, param, incomplete):
    return [n for n in scene_commands() if n.startswith(incomplete)]


@click.command("scenes", cls=Command)
@click.argument("name", required=False, shell_complete=_complete_scene)
@click.option("--command", "command", metavar="COMMAND", shell_complete=_complete_command,
              help="List only the scenes COMMAND takes (natural-frequency, damping-ratio).")
@click.option("--json", "as_json", is_flag=True, help="Print the catalog as JSON.")
@click.option("--debug", is_flag=True, help="Show a traceback on internal errors.")
def scenes(name, command, as_json, debug):
    """List the scene catalog, or show one scene in full.

    A scene is a textbook set-up with exactly the parameters its answer needs. NAME may be a
    textbook example id (E5.12): the scene that reproduces it (several are listed).

    \b
    Examples:
      dyncalc scenes
      dyncalc scenes --json
      dyncalc scenes mass-spring
      dyncalc scenes E5.12
      dyncalc scenes --command damping-ratio
    """
    from ..scenes import catalog, get_scene, is_example_id, scenes_of_example

    commands = scene_commands()
    if name is not None and command is not None:
        raise InputError("give a scene NAME or --command, not both")
    if name is not None and is_example_id(name) and len(scenes_of_example(name)) > 1:
        return _list(scenes_of_example(name), commands, as_json)
    if name is not None:
        scene = get_scene(name)
        if as_json:
            click.echo(json.dumps(_describe(scene, commands), indent=2))
            return 0
        lines = [f"{scene.name}: {scene.summary}", f"figure: {scene.figure}",
                 f"equation of motion: {scene.equation}"]
        derived = _derived(scene.name)
        if derived:
            lines.append(f"derived by eom: {'; '.join(derived)}")
        lines += [f"result: {scene.formula}", "parameters:"]
        width = max(len(p.name) for p in scene.params)
        for p in scene.params:
            kind = p.dim.display if p.dim is not None else "one of " + ", ".join(p.choices)
            note = (f" (default {p.default})" if p.default is not None
                    else " (optional)" if p.optional else "")
            lines.append(f"  {p.name.ljust(width)}  {kind}: {p.description}{note}")
        for group in scene.one_of:
            lines.append("give one of: " + ", ".join(group))
        if scene.constraints:
            lines.append("constraints: " + ", ".join(c.text for c in scene.constraints))
        if scene.methods:
            lines.append("methods: auto, " + ", ".join(scene.methods))
        lines += [f"reference: {scene.reference}",
                  f"examples: {', '.join(scene.examples) or 'none'}",
                  f"commands: {', '.join(_commands_of(scene.name, commands))}",
                  f"example: {scene.example}"]
        if scene.no_frequency:
            lines.append(f"natural-frequency and modes refuse it: {scene.no_frequency}")
        lines += _driven_lines(scene.name)
        click.echo("\n".join(lines))
        return 0
    listed = list(catalog().values())
    if command is not None:
        accepted = set(_filter(command, commands))
        listed = [s for s in listed if s.name in accepted]
    return _list(listed, commands, as_json)


def _list(listed, commands: dict[str, list[str]], as_json: bool) -> int:
    """The scenes ``listed``, three lines each (name and summary, parameters, examples and
    commands), or as JSON."""
    if as_json:
        click.echo(json.dumps({"scenes": [_describe(s, commands) for s in listed]}, indent=2))
        return 0
    if not listed:
        click.echo("The scene catalog is empty in this version.")
        return 0
    width = max(len(s.name) for s in listed)
    for scene in listed:
        click.echo(f"{scene.name.ljust(width)}  {scene.summary}")
        click.echo(f"{' ' * width}  {scene.signature()}")
        click.echo(f"{' ' * width}  examples: {', '.join(scene.examples) or 'none'}; "
                   f"commands: {', '.join(_commands_of(scene.name, commands))}")
    return 0


COMMANDS = [scenes]
