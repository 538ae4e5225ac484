"""``dyncalc coriolis``: the click command generated from its record
(:data:`dyncalc.commands.coriolis.COMMAND`). A motion given in time is routed here when it
asks for a table (a list of times in ``--t``, or ``--batch`` over times: one row per time) or
a ``--plot``."""
from __future__ import annotations

from ..commands.coriolis import COMMAND
from ..errors import InputError
from .options import build_command


def _rows(settings, out):
    from ..batch import CoriolisRows

    return CoriolisRows(strict=out.strict)


def _route(values, words, out):
    """A table over times, or a one-off with ``--plot``; ``None`` for everything else."""
    from ..commands.coriolis_time import is_time_motion, split_times

    if values.get("scene") is not None or not is_time_motion(values):
        return None
    times = split_times(values["t"]) if values.get("t") is not None else None
    plot = values.get("plot")
    if out.batch is None and (times is None or len(times) == 1):
        if plot is None:
            return None
        result = out.compute(lambda: COMMAND.compute(values, words, rtol=out.rtol,
                                                     strict=out.strict))
        from ..commands.coriolis_time import path_data
        from .plot import plot_coriolis

        result.extra["plot"] = plot_coriolis(path_data(values, words, strict=out.strict),
                                             plot)
        return out.emit(result)
    if plot is not None:
        raise InputError("--plot draws one time: give --t a single time (not a list or "
                         "--batch)")
    if out.batch is not None and times is not None:
        raise InputError("--t and --batch do not go together: the file's t column gives the "
                         "times")
    from ..batch import CoriolisTimeRows

    spec = CoriolisTimeRows(values, words, strict=out.strict)
    if out.batch is None:
        import io

        out.batch = io.StringIO("t\n" + "".join(f'"{t}"\n' for t in times))
    return out.run_batch(spec, {})


coriolis = build_command(COMMAND, rows=_rows, route=_route)

COMMANDS = [coriolis]
