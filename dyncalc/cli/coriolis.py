"""``dyncalc coriolis``: the click command generated from its record
(:data:`dyncalc.commands.coriolis.COMMAND`)."""
from __future__ import annotations

from ..commands.coriolis import COMMAND
from .options import build_command


def _rows(settings, out):
    from ..batch import CoriolisRows

    return CoriolisRows(strict=out.strict)


coriolis = build_command(COMMAND, rows=_rows)

COMMANDS = [coriolis]
