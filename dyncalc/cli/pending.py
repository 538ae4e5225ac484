"""Commands of SPEC.md that are named but not built yet: they say so and exit 2."""
from __future__ import annotations

import click

from ..errors import InputError

_PENDING = {
    "damping-ratio": "Damping ratio, log decrement and damped period from any measurement.",
    "rolling-onset": "When a sliding ball, cylinder or hoop starts to roll without slipping.",
    "coriolis": "Coriolis and relative-motion acceleration in a rotating frame.",
}


def _pending_command(name: str, summary: str):
    @click.command(name, help=f"{summary}\n\nNot built yet in this version: it exits with "
                              "status 2.", short_help=f"(not built yet) {summary}",
                   context_settings={"ignore_unknown_options": True,
                                     "allow_extra_args": True})
    @click.pass_context
    def command(ctx):
        raise InputError(f"{name} is not built yet in dyncalc {_version()}; the commands that "
                         "work today are spring-series, spring-parallel, natural-frequency and "
                         "scenes")

    return command


def _version() -> str:
    from .._version import __version__

    return __version__


COMMANDS = [_pending_command(name, summary) for name, summary in _PENDING.items()]
