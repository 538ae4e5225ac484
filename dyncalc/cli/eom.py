"""``dyncalc eom``: the click command generated from its record
(:data:`dyncalc.commands.eom.COMMAND`)."""
from __future__ import annotations

from ..commands.eom import COMMAND
from .options import build_command


def _rows(settings, out):
    from ..batch import EomRows

    return EomRows(scene=settings["scene"], about=settings["about"], rtol=out.rtol,
                   strict=out.strict)


eom = build_command(COMMAND, rows=_rows)

COMMANDS = [eom]
