"""``dyncalc scenes``: the catalog, read from the scene registry."""
from __future__ import annotations

import json

import click


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
        "constraints": list(scene.constraints),
        "params": [{"name": p.name, "dimension": p.dim.display, "unit": p.dim.si,
                    "default": p.default, "description": p.description} for p in scene.params],
    }


def _params_line(scene) -> str:
    return ", ".join(f"{p.name} {p.dim.display}" + (f"={p.default}" if p.default else "")
                     for p in scene.params)


@click.command("scenes")
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
        lines += [f"  {p.name}  {p.dim.display}  {p.description}"
                  + (f" (default {p.default})" if p.default else "") for p in scene.params]
        if scene.constraints:
            lines.append("constraints: " + ", ".join(scene.constraints))
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
        click.echo(f"{scene.name.ljust(width)}  {scene.summary}  [{_params_line(scene)}]")
    return 0


COMMANDS = [scenes]
