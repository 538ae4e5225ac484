"""A command of SPEC.md that is named but not built yet: it says so and exits 2."""
from __future__ import annotations

import click

from ..errors import InputError


def pending_command(name: str, summary: str):
    """A click command ``name`` that refuses to run (exit 2) until it is built."""

    @click.command(name, help=f"{summary}\n\nNot built yet in this version: it exits with "
                              "status 2.", short_help=f"(not built yet) {summary}",
                   context_settings={"ignore_unknown_options": True,
                                     "allow_extra_args": True})
    @click.pass_context
    def command(ctx):
        from .._version import __version__

        raise InputError(f"{name} is not built yet in dyncalc {__version__}; the commands that "
                         "work today are spring-series, spring-parallel, natural-frequency and "
                         "scenes")

    return command
