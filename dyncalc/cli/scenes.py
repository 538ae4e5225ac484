"""``dyncalc scenes``: the catalog, read from the scene registry."""
from __future__ import annotations

import json

import click

from .command import Command


def _complete_scene(ctx, param, incomplete):
    from ..scenes import scene_names

    return [n for n in scene_names() if n.startswith(incomplete)]


def _describe(scene) -> dict:
    return {
        "name": scene.name,
        "summary": scene.summary,
        "figure": scene.figure,
        "equation": scene.equation,
        "formula": scene.formula,
        "reference": scene.reference,
        "example": scene.example,
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


@click.command("scenes", cls=Command)
@click.argument("name", required=False, shell_complete=_complete_scene)
@click.option("--json", "as_json", is_flag=True, help="Print the catalog as JSON.")
@click.option("--debug", is_flag=True, help="Show a traceback on internal errors.")
def scenes(name, as_json, debug):
    """List the scene catalog, or show one scene in full.

    A scene is a textbook set-up with exactly the parameters its answer needs.

    \b
    Examples:
      dyncalc scenes
      dyncalc scenes --json
      dyncalc scenes mass-spring
    """
    from ..scenes import catalog, get_scene

    if name is not None:
        scene = get_scene(name)
        if as_json:
            click.echo(json.dumps(_describe(scene), indent=2))
            return 0
        lines = [f"{scene.name}: {scene.summary}", f"figure: {scene.figure}",
                 f"equation of motion: {scene.equation}", f"result: {scene.formula}",
                 "parameters:"]
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
        lines += [f"reference: {scene.reference}", f"example: {scene.example}"]
        click.echo("\n".join(lines))
        return 0
    scenes_ = catalog()
    if as_json:
        click.echo(json.dumps({"scenes": [_describe(s) for s in scenes_.values()]}, indent=2))
        return 0
    if not scenes_:
        click.echo("The scene catalog is empty in this version.")
        return 0
    width = max(len(n) for n in scenes_)
    for scene in scenes_.values():
        click.echo(f"{scene.name.ljust(width)}  {scene.summary}")
        click.echo(f"{' ' * width}  {scene.signature()}")
    return 0


COMMANDS = [scenes]
