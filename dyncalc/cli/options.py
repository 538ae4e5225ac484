"""The output contract every computing command shares, as one decorator.

``@output_options`` adds ``--json``, ``--value``, ``--unit``, ``--digits``, ``--check``,
``--rtol``, ``--explain``, ``--strict-units`` and ``--debug`` and hands the command an
:class:`Output` whose :meth:`Output.emit` renders a :class:`~dyncalc.result.Result` and returns
the exit status.
"""
from __future__ import annotations

import functools
import os
import sys
from dataclasses import dataclass, field

import click

from ..errors import EXIT_CHECK_FAILED, EXIT_OK, InputError

__all__ = ["Output", "output_options"]

MAX_DIGITS = 17


@dataclass
class Output:
    """How the user asked to see the result."""

    as_json: bool = False
    value: str | None = None
    units: list[str] = field(default_factory=list)
    digits: int = 6
    checks: list[str] = field(default_factory=list)
    rtol: float | None = None
    explain: bool = False
    strict: bool = False

    def unit_map(self, result) -> dict[str, str]:
        from ..checks import split_assignment

        units = {}
        for spec in self.units:
            name, unit = split_assignment(spec, "--unit")
            entry = result.results.get(name)
            if entry is None:
                raise InputError(f"--unit {name}: there is no result named {name!r}; the "
                                 f"results are {', '.join(result.results)}")
            unit = unit.strip()
            entry.value_in(unit)  # refuses a unit of the wrong dimension or rate kind now
            units[name] = unit
        return units

    def emit(self, result) -> int:
        """Print ``result`` in the chosen form; the exit status (1 if a check failed)."""
        from ..checks import run_checks
        from . import render

        units = self.unit_map(result)
        checks = run_checks(result, self.checks, self.rtol) if self.checks else []
        if self.value is not None:
            text = render.bare_value(result, self.value, units)
            for w in result.warnings:
                click.echo(f"warning: {w}", err=True)
            for c in checks:
                if not c.passed:
                    click.echo(render._check_line(c, self.digits), err=True)
            click.echo(text)
        elif self.as_json:
            click.echo(render.to_json(result, units, checks, self.explain))
        elif _is_terminal():
            from rich.console import Console

            render.rich_text(result, units, self.digits, checks, self.explain, Console())
        else:
            click.echo(render.plain_text(result, units, self.digits, checks, self.explain))
        return EXIT_CHECK_FAILED if any(not c.passed for c in checks) else EXIT_OK


def _is_terminal() -> bool:
    if os.environ.get("DYNCALC_PLAIN"):
        return False
    try:
        return sys.stdout.isatty()
    except (AttributeError, ValueError):
        return False


def _positive_rtol(ctx, param, value):
    if value is not None and not (0 < value < 1):
        raise click.BadParameter(f"must be between 0 and 1 (exclusive); got {value:g}")
    return value


def output_options(command):
    """Add the shared output options to a click command function (which takes ``out``)."""

    @functools.wraps(command)
    def wrapper(*args, as_json, value, units, digits, checks, rtol, explain, strict_units,
                debug, **kwargs):
        out = Output(as_json=as_json, value=value, units=list(units), digits=digits,
                     checks=list(checks), rtol=rtol, explain=explain, strict=strict_units)
        return command(*args, out=out, **kwargs)

    decorators = [
        click.option("--json", "as_json", is_flag=True,
                     help="Print one JSON object (full precision)."),
        click.option("--value", metavar="NAME",
                     help="Print only the number of result NAME (full precision)."),
        click.option("--unit", "units", multiple=True, metavar="NAME=UNIT",
                     help="Show result NAME in UNIT (repeatable), e.g. --unit k_eq=lbf/in."),
        click.option("--digits", type=click.IntRange(1, MAX_DIGITS), default=6,
                     show_default=True, help="Significant digits in human output."),
        click.option("--check", "checks", multiple=True, metavar="NAME=QUANTITY",
                     help="Compare result NAME with your answer; exit 1 if it differs by more "
                          "than --rtol (repeatable)."),
        click.option("--rtol", type=float, default=None, callback=_positive_rtol,
                     help="Relative tolerance: of --check (default 1e-2) and of the model that "
                          "computes the result (default 1e-9)."),
        click.option("--explain", is_flag=True,
                     help="Show the formula, the values substituted and the assumptions."),
        click.option("--strict-units", is_flag=True,
                     help="Refuse bare numbers: every quantity needs its unit."),
        click.option("--debug", is_flag=True, help="Show a traceback on internal errors."),
    ]
    for decorate in reversed(decorators):
        wrapper = decorate(wrapper)
    return wrapper
