"""``dyncalc rigid-body``: the click command generated from its record
(:data:`dyncalc.commands.rigid_body.COMMAND`)."""
from __future__ import annotations

from ..commands.rigid_body import COMMAND
from .options import build_command


def _rows(settings, out):
    from ..batch import RigidRows

    return RigidRows(scene=settings["scene"], rtol=out.rtol, strict=out.strict)


def _plot(result, values) -> None:
    if values.get("plot") is not None:
        from .plot import plot_loads

        plot_loads(result, values["plot"])


rigid_body = build_command(COMMAND, rows=_rows, after=_plot)

COMMANDS = [rigid_body]
