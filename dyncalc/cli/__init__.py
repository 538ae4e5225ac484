"""The ``dyncalc`` command line: a click group whose ``main`` maps every error to exit 2 and
one ``Error:`` line on stderr (a traceback only with ``--debug``).

Importing this package imports click and nothing heavy: pint, numpy and rich load only when a
command computes or draws, so ``--help`` and shell completion stay fast. A command's module is
imported only when that command is run, completed or listed (``--help``), so a one-off pays
for its own command alone.
"""
from __future__ import annotations

import errno
import gc
import importlib
import sys

import click

from .._version import __version__
from ..errors import (EXIT_BAD_INPUT, EXIT_BROKEN_PIPE, EXIT_INTERRUPTED, InputError,
                      one_line as _one_line)
from . import streams
from .modules import COMMAND_MODULES

__all__ = ["cli", "main"]


class _LazyCommands(dict):
    """The group's commands by name, each module imported when its command is first looked up;
    listing or iterating imports them all (``--help`` shows every command's summary)."""

    def _load(self, name: str) -> None:
        module = importlib.import_module(f"{__name__}.{COMMAND_MODULES[name]}")
        for command in module.COMMANDS:
            dict.setdefault(self, command.name, command)

    def _load_all(self) -> None:
        for name in COMMAND_MODULES:
            if not dict.__contains__(self, name):
                self._load(name)

    def __missing__(self, name):
        if name not in COMMAND_MODULES:
            raise KeyError(name)
        self._load(name)
        return dict.__getitem__(self, name)

    def __contains__(self, name) -> bool:
        return dict.__contains__(self, name) or name in COMMAND_MODULES

    def get(self, name, default=None):
        try:
            return self[name]
        except KeyError:
            return default

    def __iter__(self):
        self._load_all()
        return dict.__iter__(self)

    def __len__(self) -> int:
        self._load_all()
        return dict.__len__(self)

    def keys(self):
        self._load_all()
        return dict.keys(self)

    def values(self):
        self._load_all()
        return dict.values(self)

    def items(self):
        self._load_all()
        return dict.items(self)


class DyncalcGroup(click.Group):
    """A click group that turns every failure into the contract's exit status and message,
    and imports each command's module when that command is first looked up."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.commands = _LazyCommands(self.commands)

    def main(self, args=None, prog_name=None, complete_var=None, standalone_mode=True,
             **extra):
        args = list(sys.argv[1:] if args is None else args)
        debug = "--debug" in args
        streams.prepare()
        try:
            code = self._run(args, prog_name, complete_var, extra, debug)
            streams.flush()  # a failed write shows here, while its status can be given
        except OSError as exc:  # stdout full, closed, or its reader gone
            code = streams.exit_status_of(exc)
            streams.discard_stdout()
            if code != EXIT_BROKEN_PIPE:
                streams.say(f"Error: cannot write the output: "
                            f"{_one_line(exc.strerror or exc)}")
        except KeyboardInterrupt:
            streams.say("Error: interrupted")
            code = EXIT_INTERRUPTED
        if standalone_mode:
            sys.exit(code)
        return code

    def _run(self, args, prog_name, complete_var, extra, debug) -> int:
        """Run the command; its exit status, every error but a failed write (an OSError)
        and Ctrl-C turned into one ``Error:`` line."""
        stdout, stderr = sys.stdout, sys.stderr
        try:
            args = _explain_equals(args)
            rv = super().main(args=args, prog_name=prog_name or "dyncalc",
                              complete_var=complete_var, standalone_mode=False, **extra)
            return rv if isinstance(rv, int) else 0
        except click.exceptions.Exit as exc:
            return exc.exit_code
        except SystemExit:
            if sys.stdout is not stdout:  # click's end of a broken pipe (it swaps the streams
                sys.stdout, sys.stderr = stdout, stderr  # and exits 1): the contract's 141
                raise BrokenPipeError(errno.EPIPE, "Broken pipe") from None
            raise
        except click.exceptions.NoArgsIsHelpError as exc:  # bare ``dyncalc``: its help
            click.echo(exc.ctx.get_help())
            return 0
        except click.ClickException as exc:
            command = _command_name(args)
            hint = f"; see 'dyncalc {command} --help'" if command else "; see 'dyncalc --help'"
            shown = _one_line(_usage_message(exc)).rstrip(".")
            streams.say(f"Error: {shown}{_one_line(hint)}")
            return EXIT_BAD_INPUT
        except InputError as exc:
            streams.say(f"Error: {_one_line(exc)}")
            return EXIT_BAD_INPUT
        except click.Abort:  # click's form of Ctrl-C
            streams.say("Error: interrupted")
            return EXIT_INTERRUPTED
        except (OSError, KeyboardInterrupt):
            raise
        except Exception as exc:  # a bug: never a traceback unless asked for
            if debug:
                raise
            streams.say(f"Error: internal error ({type(exc).__name__}: "
                        f"{_one_line(exc)[:200]}); please report it, with --debug for the "
                        "traceback")
            return EXIT_BAD_INPUT

    def resolve_command(self, ctx, args):
        """The command named by ``args[0]``; a misspelt one is refused with the closest names
        (``No such command 'natral-frequency' (did you mean 'natural-frequency'?)``)."""
        name = args[0] if args else ""
        if name and not name.startswith("-") and name not in self.commands:
            raise click.UsageError(_no_such("command", name, list(COMMAND_MODULES)), ctx)
        return super().resolve_command(ctx, args)


def _no_such(kind: str, name: str, possibilities) -> str:
    from difflib import get_close_matches

    message = f"No such {kind} {name!r}"
    close = get_close_matches(name, possibilities)
    if close:
        message += f" (did you mean {' or '.join(repr(c) for c in close)}?)"
    return message


def _explain_equals(args: list[str]) -> list[str]:
    """``--explain=FMT`` -> ``--explain --explain-format=FMT`` (before any ``--``), so that
    ``--explain`` stays a flag: ``--explain k=2N/m`` is the flag and a parameter."""
    from .options import EXPLAIN_FORMATS

    out = []
    for i, arg in enumerate(args):
        if arg == "--":
            return out + args[i:]
        if arg.startswith("--explain="):
            fmt = arg.partition("=")[2]
            if fmt not in EXPLAIN_FORMATS:
                raise InputError(f"--explain={fmt[:40]}: the formats are "
                                 f"{', '.join(EXPLAIN_FORMATS)} (--explain alone is text)")
            out += ["--explain", f"--explain-format={fmt}"]
        else:
            out.append(arg)
    return out


def _usage_message(exc: click.ClickException) -> str:
    """click's message, with an unknown option said the same way whatever click's version
    (8.2 writes ``No such option: --foo``, later ones ``No such option '--foo'.`` with their
    own suggestion): ``No such option '--jsn' (did you mean '--json'?)``."""
    if not isinstance(exc, click.NoSuchOption):
        return exc.format_message()
    return _no_such("option", exc.option_name, exc.possibilities or [])


def _command_name(args: list[str]) -> str | None:
    for arg in args:
        if not arg.startswith("-"):
            return arg if arg in cli.commands else None
    return None


@click.group(cls=DyncalcGroup, context_settings={"help_option_names": ["-h", "--help"],
                                                 "max_content_width": 100})
@click.version_option(__version__, "--version", prog_name="dyncalc",
                      message="%(prog)s %(version)s")
def cli():
    """A units-aware calculator for vibration and dynamics.

    Quantities take any units pint knows ("2 kN/m", 4kg, "30 deg", "1500 rpm"); a bare number
    is read in SI. Every command prints a table, or --json, or --value NAME for scripts;
    exit status 0 ok, 1 a --check failed, 2 bad input, 3 the output could not be written,
    130 interrupted, 141 the reader went away.

    \b
    Examples:
      dyncalc spring-series "200 N/m" "300 N/m"
      dyncalc spring-parallel 2kN/m "12 lbf/in" --unit k_eq=N/mm
      dyncalc scenes
    """


def main(argv=None):
    """Console-script entry point.

    The cyclic garbage collector is paused for the run: loading numpy, pint and the registry
    allocates some 10^5 objects that live as long as the process and makes no garbage cycles,
    yet collecting them costs about 5 % of a one-off (13 ms of 260; issue 8). Reference
    counting still frees everything else; batch mode, which runs long, turns the collector
    back on (:func:`dyncalc.batch.run_batch`).

    BLAS runs on one thread unless the environment says otherwise (``OPENBLAS_NUM_THREADS``,
    read when numpy loads): a one-off's matrices are small, and OpenBLAS's threads spin when
    the cores are busy. ``modes`` on a 500-mass chain took 8 s instead of 0.07 s for its
    eigensolve on a loaded two-core machine (docs/performance.md).
    """
    if "numpy" not in sys.modules:
        import os

        os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    enabled = gc.isenabled()
    gc.disable()
    try:
        return cli.main(args=argv, prog_name="dyncalc")
    finally:
        gc.freeze()  # what the run made is kept out of the collections at exit
        if enabled:
            gc.enable()

