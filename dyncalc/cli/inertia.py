"""``dyncalc inertia``: the click command generated from its record
(:data:`dyncalc.commands.inertia.COMMAND`).

A hole is a body word with a leading '-' (``-disk(m=1kg, r=5cm)``), which click would read as
a cluster of short options; :class:`BodiesCommand` moves the body words behind ``--`` (in
their order, options staying in front) before click parses the line."""
from __future__ import annotations

import re

from ..commands.inertia import COMMAND
from .command import Command
from .options import build_command

_BODY_WORD = re.compile(r"^-?\s*[A-Za-z][A-Za-z0-9_-]*\s*\(")


def bodies_last(args: list[str]) -> list[str]:
    """``args`` with its body words (``rod(...)``, ``-disk(...)``) after a ``--``, in their
    order; everything after a ``--`` already there stays where it is. No option's value looks
    like ``NAME(`` (an axis is ``z`` or ``(1, 1, 0)``), so options keep their values.

    >>> bodies_last(["-disk(r=1m)", "--axis", "z", "rod(l=1m)"])
    ['--axis', 'z', '--', '-disk(r=1m)', 'rod(l=1m)']
    """
    front: list[str] = []
    bodies: list[str] = []
    rest: list[str] = []
    for i, word in enumerate(args):
        if word == "--":
            rest = args[i + 1:]
            break
        (bodies if _BODY_WORD.match(word) else front).append(word)
    if not bodies and not rest:
        return front
    return front + ["--"] + bodies + rest


class BodiesCommand(Command):
    """``inertia``'s click command: body words may start with '-' (holes)."""

    def parse_args(self, ctx, args):
        return super().parse_args(ctx, bodies_last(list(args)))


def _rows(settings, out):
    from ..batch.inertia_rows import InertiaRows

    return InertiaRows(strict=out.strict)


inertia = build_command(COMMAND, rows=_rows, cls=BodiesCommand)

COMMANDS = [inertia]
