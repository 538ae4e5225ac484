"""``dyncalc rolling-onset``: the click command generated from its record
(:data:`dyncalc.commands.rolling_onset.COMMAND`)."""
from __future__ import annotations

from ..commands.rolling_onset import COMMAND
from .options import build_command


def _rows(settings, out):
    from ..batch import RollingRows

    return RollingRows(method=settings["method"], rtol=out.rtol, strict=out.strict)


rolling_onset = build_command(COMMAND, rows=_rows)

COMMANDS = [rolling_onset]
