"""``dyncalc natural-frequency``: the click command generated from its record
(:data:`dyncalc.commands.natural_frequency.COMMAND`)."""
from __future__ import annotations

from ..commands.natural_frequency import COMMAND, STANDARD
from .options import build_command


def _rows(settings, out):
    from ..batch import NaturalFrequencyRows

    return NaturalFrequencyRows(STANDARD, scene=settings["scene"], method=settings["method"],
                                rtol=out.rtol, strict=out.strict)


natural_frequency = build_command(COMMAND, rows=_rows)

COMMANDS = [natural_frequency]
