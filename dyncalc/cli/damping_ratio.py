"""``dyncalc damping-ratio``: the click command generated from its record
(:data:`dyncalc.commands.damping_ratio.COMMAND`), and its ``--plot``."""
from __future__ import annotations

from ..commands.damping_ratio import COMMAND
from .options import build_command


def _rows(settings, out):
    from ..batch import DampingRows

    return DampingRows(scene=settings["scene"], method=settings["method"], rtol=out.rtol,
                       strict=out.strict)


def _plot(result, values) -> None:
    if values.get("plot") is not None:
        from .plot import plot_decay

        plot_decay(result, values["plot"])


damping_ratio = build_command(COMMAND, rows=_rows, after=_plot)

COMMANDS = [damping_ratio]
