"""The click command class of every dyncalc command: options given twice are refused."""
from __future__ import annotations

import click

from ..errors import InputError

__all__ = ["Command", "refuse_repeats"]


class Command(click.Command):
    """A click command that refuses an option given twice (``--k 100N/m --k 200N/m``: click
    would keep the last silently), except those declared ``multiple`` (``--unit``,
    ``--check``, ``--value``). Every dyncalc command is one."""

    def parse_args(self, ctx, args):
        if not ctx.resilient_parsing:  # shell completion parses half-typed lines
            refuse_repeats(self, ctx, args)
        return super().parse_args(ctx, args)


def refuse_repeats(command: click.Command, ctx, args: list[str]) -> None:
    """Raise :class:`InputError` (``--k given twice: give it once``) when an option of
    ``command`` that is not repeatable occurs twice in ``args``. click's parser records every
    occurrence in its processing order, which is what is read here."""
    _opts, _rest, order = command.make_parser(ctx).parse_args(args=list(args))
    seen: set[str] = set()
    for param in order:
        if not isinstance(param, click.Option) or param.multiple or param.count:
            continue
        if param.name in seen:
            flag = max(param.opts, key=len)
            raise InputError(f"{flag} given twice: give it once")
        seen.add(param.name)
