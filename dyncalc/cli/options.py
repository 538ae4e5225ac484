"""The output contract every computing command shares, as one decorator.

``@output_options`` adds ``--json``, ``--value``, ``--unit``, ``--digits``, ``--check``,
``--rtol``, ``--explain``, ``--format``, ``--strict-units``, ``--batch``, ``--on-error`` and
``--debug`` and hands the command an :class:`Output` whose :meth:`Output.emit` renders a
:class:`~dyncalc.result.Result` and returns the exit status, and whose :meth:`Output.run_batch`
runs the command over the rows of a ``--batch`` file (:mod:`dyncalc.batch`).
"""
from __future__ import annotations

import functools
import os
import sys

import click

from ..errors import EXIT_CHECK_FAILED, EXIT_OK, InputError, one_line
from .command import Command

__all__ = ["Output", "output_options", "complete_scene", "build_command", "Command",
           "COMMON_UNITS"]

MAX_DIGITS = 17

#: The forms of ``--explain=FORMAT`` (``--explain`` alone is ``text``).
EXPLAIN_FORMATS = ("text", "markdown", "latex")
#: The forms of ``--format`` (the human output's results table).
TABLE_FORMATS = ("table", "markdown", "csv", "tsv")


class Output:
    """How the user asked to see the result (and, with ``--batch``, where the rows come from).

    ``explain`` is False, or the format of ``--explain``: ``text``, ``markdown`` or ``latex``;
    ``format`` that of ``--format`` (None when not given).
    """

    __slots__ = ("as_json", "value", "units", "digits", "checks", "rtol", "explain", "strict",
                 "batch", "on_error", "debug", "format")

    def __init__(self, as_json: bool = False, value: str | list[str] | None = None,
                 units: list[str] | None = None, digits: int = 6,
                 checks: list[str] | None = None, rtol: float | None = None,
                 explain: bool | str = False, strict: bool = False, batch: str | None = None,
                 on_error: str = "stop", debug: bool = False, format: str | None = None):
        self.as_json, self.digits = as_json, digits
        #: the results of ``--value`` (repeatable), in the order given; empty without it
        self.value = [value] if isinstance(value, str) else list(value or [])
        self.units = list(units or [])
        self.checks = list(checks or [])
        self.rtol, self.explain, self.strict = rtol, explain, strict
        self.batch, self.on_error, self.debug = batch, on_error, debug
        self.format = format

    def __repr__(self) -> str:
        fields = ", ".join(f"{name}={getattr(self, name)!r}" for name in self.__slots__)
        return f"Output({fields})"

    def unit_map(self, result) -> dict[str, str]:
        from ..result.checks import split_assignment

        units = {}
        for spec in self.units:
            name, unit = split_assignment(spec, "--unit")
            entry = result.results.get(name)
            if entry is None and name in getattr(result, "unavailable", {}):
                raise InputError(f"--unit {name}: {result.unavailable[name]}")
            if entry is None:
                raise InputError(f"--unit {name}: there is no result named {name!r}; the "
                                 f"results are {', '.join(result.results)}")
            if name in units:
                raise InputError(f"--unit {name}= given twice: give it once")
            unit = unit.strip()
            entry.value_in(unit)  # refuses a unit of the wrong dimension or rate kind now
            units[name] = unit
        return units

    def compute(self, run):
        """``run()`` (a Result), with the uncertainties of inputs typed with ``±`` propagated
        to its results (:func:`dyncalc.result.propagate.propagate`)."""
        from ..result.propagate import propagate

        return propagate(run)

    def emit(self, result) -> int:
        """Print ``result`` in the chosen form; the exit status (1 if a check failed)."""
        from ..result import encode

        units = self.unit_map(result) if self.units else {}
        checks = []
        if self.checks:
            from ..result.checks import run_checks

            checks = run_checks(result, self.checks, self.rtol)
        if self.value:
            text = "\n".join(encode.bare_value(result, name, units) for name in self.value)
            for w in result.warnings:
                click.echo(f"warning: {one_line(w)}", err=True)
            for c in checks:
                if not c.passed:
                    from .render_parts import check_line

                    click.echo(check_line(c, self.digits), err=True)
            click.echo(text)
        elif self.as_json:
            click.echo(encode.to_json(result, units, checks, self.explain))
        else:
            from . import render  # human forms only: not for --json or --value (start-up)

            render.human(result, units, self.digits, checks, self.explain, self.format,
                         terminal=_is_terminal())
        return EXIT_CHECK_FAILED if any(not c.passed for c in checks) else EXIT_OK

    def run_batch(self, spec, given: dict[str, object] | None = None) -> int:
        """Run the command described by ``spec`` (a :class:`dyncalc.batch.RowSpec`) over the
        rows of ``--batch``; ``given`` maps the command's parameter options (``--k``) and
        words to what was typed, all of which must be empty: the file gives the parameters."""
        from ..batch import run_batch

        for option, used in (("--value", self.value), ("--check", self.checks),
                             ("--explain", self.explain), ("--format", self.format)):
            if used:
                raise InputError(f"{option} does not go with --batch: {_BATCH_REFUSALS[option]}")
        for label, value in (given or {}).items():
            if not value:
                continue
            if label in _BATCH_REFUSALS:
                raise InputError(f"{label} does not go with --batch: {_BATCH_REFUSALS[label]}")
            shown = label if label.startswith("-") else " ".join(value)
            raise InputError(f"{shown[:80]} and --batch do not go together: with --batch "
                             "every parameter comes from a column of the file")
        units = {}
        for spec_text in self.units:
            from ..result.checks import split_assignment  # only with --unit (batch start-up)

            name, unit = split_assignment(spec_text, "--unit")
            if name in units:
                raise InputError(f"--unit {name}= given twice: give it once")
            units[name] = unit.strip()
        from ..batch.memory import hold_freed_memory

        hold_freed_memory()  # this process is dyncalc's: its allocator keeps freed chunks
        return run_batch(spec, self.batch, as_json=self.as_json, units=units,
                         on_error=self.on_error, debug=self.debug)


_BATCH_REFUSALS = {
    "--value": "every result is a column of the output (--unit NAME=UNIT sets its unit)",
    "--check": "compare the output's columns with your answers instead",
    "--explain": "run one row on its own with --explain",
    "--plot": "draw one row's decay on its own with --plot",
    "--format": "the output is CSV (or JSON lines with --json)",
}


def _is_terminal() -> bool:
    """Whether the table is drawn for a terminal, with colour: stdout is one, or
    ``FORCE_COLOR`` is set (not empty) and ``NO_COLOR`` is not (``NO_COLOR`` wins)."""
    if os.environ.get("DYNCALC_PLAIN"):
        return False
    if os.environ.get("FORCE_COLOR") and not os.environ.get("NO_COLOR"):
        return True
    try:
        return sys.stdout.isatty()
    except (AttributeError, ValueError):
        return False


def complete_scene(ctx, param, incomplete):
    """Shell completion of ``--scene``: the scene names (``dyncalc.cli.scenes`` is imported
    only when completing, not on every run of the commands that take ``--scene``)."""
    from .scenes import _complete_scene

    return _complete_scene(ctx, param, incomplete)


#: The units ``--unit NAME=`` completes to, by the result's canonical unit: the canonical one
#: first, then a few common ones (tests/test_completion_custom.py runs each one).
COMMON_UNITS: dict[str, tuple[str, ...]] = {
    "N/m": ("N/m", "N/mm", "kN/m", "lbf/in"),
    "rad/s": ("rad/s", "deg/s", "rpm"),
    "Hz": ("Hz", "kHz", "mHz"),
    "s": ("s", "ms", "min", "h"),
    "1/s": ("1/s", "1/ms", "1/min"),
    "N*s/m": ("N*s/m", "kN*s/m", "lbf*s/in"),
    "m": ("m", "mm", "cm", "km", "in", "ft"),
    "m/s": ("m/s", "mm/s", "km/h", "ft/s", "mph"),
    "m/s^2": ("m/s^2", "mm/s^2", "ft/s^2"),
    "rad/s^2": ("rad/s^2", "deg/s^2", "rpm/s"),
    "N": ("N", "kN", "lbf"),
    "rad": ("rad", "deg"),
    "kg": ("kg", "g", "t", "lb"),
    "kg*m^2": ("kg*m^2", "g*cm^2", "kg*mm^2", "lb*ft^2", "lb*in^2"),
    "rad/s^2": ("rad/s^2", "deg/s^2", "rpm/s"),
    "N*m": ("N*m", "kN*m", "N*mm", "lbf*ft", "lbf*in"),
    "N*s": ("N*s", "kN*s", "lbf*s"),
    "J": ("J", "kJ", "N*m", "ft*lbf"),
    "kg*m^2/s": ("kg*m^2/s", "N*m*s", "lb*ft^2/s"),
}


def _complete_result(ctx, param, incomplete):
    """Shell completion of ``--value``, ``--unit`` and ``--check``: the result names of the
    command's record (``NAME=`` for the two that take an assignment); after ``--unit NAME=``,
    the common units of that result's canonical unit (:data:`COMMON_UNITS`)."""
    from click.shell_completion import CompletionItem

    record = getattr(ctx.command, "record", None)
    if record is None:
        return []
    if param.name == "units" and "=" in incomplete:
        name, _, unit = incomplete.partition("=")
        canonical = next((r.unit for r in record.results
                          if r.name.replace("<i>", "1") == name
                          or (r.name.endswith("<i>") and name.startswith(r.name[:-3])
                              and name[len(r.name) - 3:].isdigit())), None)
        return [CompletionItem(f"{name}={u}") for u in COMMON_UNITS.get(canonical or "", ())
                if u.startswith(unit)]
    suffix = "=" if param.name in ("units", "checks") else ""
    return [CompletionItem(name + suffix) for name in record.result_names()
            if name.startswith(incomplete)]


def _complete_file(ctx, param, incomplete):
    """Shell completion of ``--batch`` and ``--plot``: the shell's own file names."""
    from click.shell_completion import CompletionItem

    return [CompletionItem(incomplete, type="file")]


def _complete_words(words):
    """Shell completion from a parameter's words: a tuple, or a function giving one, called
    with the ``--scene`` typed before (``scene=``) when it takes that keyword."""
    def complete(ctx, param, incomplete):
        from click.shell_completion import CompletionItem

        if callable(words):
            takes_scene = "scene" in words.__code__.co_varnames[:words.__code__.co_argcount]
            choices = words(scene=ctx.params.get("scene")) if takes_scene else words()
        else:
            choices = words
        return [CompletionItem(w) for w in choices if w.startswith(incomplete)]
    return complete


def build_command(record, *, rows=None, after=None, cls=None, route=None):
    """The click command of a :class:`dyncalc.commands.record.Command`: an option per
    parameter, in the record's order (a ``choice``, or a setting with fixed words, validated
    by click; words given as a function only completed), the free words as an argument, the
    shared output options. The callback runs ``record.compute`` on the texts as typed, or
    with ``--batch`` the row adapter ``rows(settings, out)`` over the file's rows; ``after``
    acts on the result before it is shown (``--plot``); ``cls`` a subclass of
    :class:`Command` that reads the command line its own way; ``route(values, words, out)``
    runs first and may take the run over (an exit status) or leave it (``None``): coriolis's
    list of times."""

    def callback(out, words=(), **values):
        if route is not None:
            status = route(values, words, out)
            if status is not None:
                return status
        if out.batch is not None:
            settings = {p.name: values[p.name] for p in record.parameters
                        if p.kind == "setting"}
            given: dict[str, object] = {p.flag: values[p.name] for p in record.parameters
                                        if p.kind != "setting"}
            if record.words is not None:
                given[""] = words
            return out.run_batch(rows(settings, out), given)
        result = out.compute(lambda: record.compute(values, words, rtol=out.rtol,
                                                    strict=out.strict))
        if after is not None:
            after(result, values)
        return out.emit(result)

    callback.__name__ = record.name.replace("-", "_")
    callback.__doc__ = record.help
    decorated = output_options(callback)
    for parameter in reversed(record.parameters):
        extra: dict[str, object] = {}
        if isinstance(parameter.choices, tuple) and parameter.kind in ("choice", "setting"):
            extra["type"] = click.Choice(parameter.choices)
        elif parameter.choices is not None:
            extra["shell_complete"] = _complete_words(parameter.choices)
        elif parameter.kind == "after":
            extra["shell_complete"] = _complete_file
        if parameter.default is not None and parameter.kind == "setting":
            extra["default"] = parameter.default
        decorated = click.option(parameter.flag, parameter.name, metavar=parameter.metavar,
                                 help=parameter.help, **extra)(decorated)
    if record.words is not None:
        decorated = click.argument("words", nargs=-1, metavar=record.words)(decorated)
    command = click.command(record.name, cls=cls or Command, help=record.help,
                            short_help=record.summary)(decorated)
    command.record = record
    return command


def _positive_rtol(ctx, param, value):
    if value is not None and not (0 < value < 1):
        raise click.BadParameter(f"must be between 0 and 1 (exclusive); got {value:g}")
    return value


def _explain_with(fmt: str | None, as_json: bool, value, explain: bool | str) -> bool | str:
    """``--explain``'s format once ``--format`` is taken into account (``--format markdown``
    makes a plain ``--explain`` Markdown); refuses the combinations that cannot be honoured."""
    if fmt is None:
        return explain
    for flag, used in (("--json", as_json), ("--value", value)):
        if used:
            raise InputError(f"--format does not go with {flag}: {flag} prints its own "
                             "form; --format is for the human output")
    if explain and fmt in ("csv", "tsv"):
        raise InputError(f"--explain does not go with --format {fmt}: the {fmt.upper()} is "
                         "the results table alone (use --format markdown --explain)")
    if explain in ("markdown", "latex") and fmt != explain:
        raise InputError(f"--explain={explain} and --format {fmt} do not go together: "
                         f"--explain={explain} makes the whole output "
                         f"{'Markdown' if explain == 'markdown' else 'LaTeX'}")
    return "markdown" if explain and fmt == "markdown" else explain


def output_options(command):
    """Add the shared output options to a click command function (which takes ``out``)."""

    @functools.wraps(command)
    def wrapper(*args, as_json, value, units, digits, checks, rtol, explain, explain_format,
                strict_units, batch, on_error, debug, table_format, **kwargs):
        explained = (explain_format or "text") if explain else False
        out = Output(as_json=as_json, value=list(value), units=list(units), digits=digits,
                     checks=list(checks), rtol=rtol,
                     explain=_explain_with(table_format, as_json, value, explained),
                     strict=strict_units,
                     batch=batch, on_error=on_error, debug=debug, format=table_format)
        return command(*args, out=out, **kwargs)

    decorators = [
        click.option("--json", "as_json", is_flag=True,
                     help="Print one JSON object (schema dyncalc/2, full precision; results "
                          "in their canonical SI unit)."),
        click.option("--value", metavar="NAME", multiple=True, shell_complete=_complete_result,
                     help="Print only the number of result NAME (full precision, in its "
                          "canonical SI unit); repeatable, one number a line."),
        click.option("--unit", "units", multiple=True, metavar="NAME=UNIT",
                     shell_complete=_complete_result,
                     help="Show result NAME in UNIT, in every form (repeatable), e.g. "
                          "--unit k_eq=lbf/in."),
        click.option("--digits", type=click.IntRange(1, MAX_DIGITS), default=6,
                     show_default=True, help="Significant digits in human output."),
        click.option("--check", "checks", multiple=True, metavar="NAME=QUANTITY",
                     shell_complete=_complete_result,
                     help="Compare result NAME with your answer; exit 1 if it differs by more "
                          "than --rtol (repeatable)."),
        click.option("--rtol", type=float, default=None, callback=_positive_rtol,
                     help="Relative tolerance: of --check (default 1e-2) and of the model that "
                          "computes the result (default 1e-9)."),
        click.option("--explain", is_flag=True,
                     help="Show the formula, the values substituted, the assumptions and the "
                          "textbook example; --explain=markdown or --explain=latex for "
                          "pasting."),
        click.option("--explain-format", type=click.Choice(EXPLAIN_FORMATS), default=None,
                     hidden=True, help="Format of --explain (what --explain=FORMAT sets)."),
        click.option("--format", "table_format", type=click.Choice(TABLE_FORMATS),
                     default=None,
                     help="The results table as an aligned table (the default), Markdown (the "
                          "whole output), or CSV/TSV (the table alone: full precision, "
                          "canonical units, a name,value,unit header)."),
        click.option("--strict-units", is_flag=True,
                     help="Refuse bare numbers: every quantity needs its unit."),
        click.option("--batch", metavar="FILE", shell_complete=_complete_file,
                     help="Compute every row of a CSV file ('-': standard input) whose header "
                          "names the parameters ('k [N/m],m [kg]'); print CSV with a column "
                          "per result, or JSON lines with --json."),
        click.option("--on-error", type=click.Choice(["stop", "skip"]), default="stop",
                     show_default=True,
                     help="With --batch: at a bad row, stop, or skip it and go on (exit 2 "
                          "either way)."),
        click.option("--debug", is_flag=True, help="Show a traceback on internal errors."),
    ]
    for decorate in reversed(decorators):
        wrapper = decorate(wrapper)
    return wrapper
