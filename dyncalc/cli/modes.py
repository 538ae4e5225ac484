"""``dyncalc modes``: the click command generated from its record
(:data:`dyncalc.commands.modes.COMMAND`)."""
from __future__ import annotations

from ..commands.modes import COMMAND
from .options import build_command


def _rows(settings, out):
    from ..batch import ModesRows

    return ModesRows(scene=settings["scene"], normalize=settings["normalize"],
                     strict=out.strict)


modes = build_command(COMMAND, rows=_rows)

COMMANDS = [modes]
