"""``dyncalc spring-series`` and ``dyncalc spring-parallel``: the click commands generated
from their records (:data:`dyncalc.commands.springs.SPRING_SERIES`, ``SPRING_PARALLEL``)."""
from __future__ import annotations

from ..commands.springs import SPRING_PARALLEL, SPRING_SERIES
from .options import build_command


def _rows(how: str):
    def rows(settings, out):
        from ..batch import SpringRows

        return SpringRows(how, strict=out.strict)
    return rows


spring_series = build_command(SPRING_SERIES, rows=_rows("series"))
spring_parallel = build_command(SPRING_PARALLEL, rows=_rows("parallel"))

COMMANDS = [spring_series, spring_parallel]
