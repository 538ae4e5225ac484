"""The console entry point: a closed-form one-off answered without pint, numpy or click, and
everything else handed to the full program (:func:`dyncalc.cli.main`) untouched.

The contract: for any command line, the quick path prints exactly what the full path prints
(stdout, stderr and exit status, byte for byte) or declines and lets the full path run.
It answers ``natural-frequency`` with ``--k``/``--m`` (mass-spring), ``--kt``/``--inertia``
(torsional) or ``--length`` (with ``--g``: pendulum at small swings), and ``spring-series``
and ``spring-parallel`` of plain stiffnesses typed in one unit (or all bare numbers), where

* every quantity is a plain ``NUMBER UNIT`` whose unit is in the table generated from pint
  (:mod:`dyncalc.quick.table`, ``tools/gen_unit_table.py``), or a bare number (SI);
* the other options are only ``--value NAME`` (repeatable), ``--json`` and ``--digits N``;
* the human table is printed plain when stdout is not a terminal, and at a terminal in the
  form rich draws (:func:`.forms.terminal`: bold title, boxed table, dim inputs; rich itself
  is not imported) when it fits the terminal's width; ``FORCE_COLOR`` and ``COLUMNS`` are
  not set and the output encoding is UTF-8;
* every input is positive and finite and every result finite and non-zero (no warnings).

Anything else (another option or command, a repeated option, an error, a quantity the
table lacks, shell completion) goes to the full path, which gives the answer or the error.
The SI values are ``x * factor`` with pint's own factor (:mod:`.read`), the physics the
kernels of :mod:`dyncalc.physics.numerics` the physics functions call (:mod:`.natural`,
:mod:`.springs`), the output the full path's forms (:mod:`.forms`), so the numbers are the
full path's to the bit (tests/test_quick.py compares the two over every table unit, random
magnitudes and every output option).

Example: ``dyncalc natural-frequency --k "100 N/m" --m "2 kg" --value f`` prints
``1.1253953951963827`` in about a third of qalc's wall time and of its instructions
(benchmarks/results/startup.md).
"""
from __future__ import annotations

import os
import sys

__all__ = ["main", "answer", "hide_from_pint"]

_COMMANDS = ("natural-frequency", "spring-series", "spring-parallel")


def answer(args: list[str]) -> str | None:
    """The full stdout of the command line ``args`` (without the program name) when the quick
    path handles it, else ``None`` (the full path must run)."""
    if not args or args[0] not in _COMMANDS or "_DYNCALC_COMPLETE" in os.environ:
        return None
    try:
        if args[0] == "natural-frequency":
            from .natural import natural_frequency

            return natural_frequency(args[1:], _human_form)
        from .springs import spring_network

        return spring_network(args[0].partition("-")[2], args[1:], _human_form)
    except Exception:  # any surprise is the full path's to report
        return None


def _human_form():
    """The human form the full path would print, when the quick path can print it too:
    ``"plain"`` (not a terminal, or ``DYNCALC_PLAIN``: the plain table, unfitted), the width
    of the terminal (rich's table, :func:`.forms.terminal`), or ``None`` (the full path's to
    print: ``FORCE_COLOR`` or ``COLUMNS`` set, an output encoding other than UTF-8, a
    terminal rich would not draw on as a terminal (``TTY_COMPATIBLE`` set, ``TERM`` dumb or
    unknown))."""
    import codecs

    stdout = sys.stdout
    environ = os.environ
    if stdout is None or environ.get("FORCE_COLOR"):
        return None
    columns = environ.get("COLUMNS", "").strip()
    if columns.isdigit() and int(columns) > 0:
        return None
    try:
        if codecs.lookup(stdout.encoding or "utf-8").name != "utf-8":
            return None
        if environ.get("DYNCALC_PLAIN") or not stdout.isatty():
            return "plain"
    except (AttributeError, LookupError, ValueError):
        return None
    if ("TTY_COMPATIBLE" in environ or "COLUMNS" in environ
            or environ.get("TERM", "").lower() in ("dumb", "unknown")):
        return None
    return _terminal_width()


def _terminal_width() -> int:
    """The terminal's width as the full path's rich console takes it
    (``shutil.get_terminal_size`` without ``COLUMNS``, then 80)."""
    try:
        width = os.get_terminal_size(sys.__stdout__.fileno()).columns
    except (AttributeError, ValueError, OSError):
        width = 0
    return width if width > 0 else 80


def main(argv=None):
    """Console-script entry point: the quick answer when there is one, else
    :func:`dyncalc.cli.main`."""
    args = list(sys.argv[1:] if argv is None else argv)
    text = answer(args) if sys.stdout is not None else None
    if text is None:
        hide_from_pint()
        from ..cli import main as full

        return full(argv)
    sys.exit(_write(text + "\n"))


#: Array libraries pint imports when they are installed, which a command line never meets.
HIDDEN = ("dask",)


def hide_from_pint() -> None:
    """Keep pint from importing :data:`HIDDEN` in this (command-line) process.

    pint imports ``dask.base`` at its own import whenever dask is installed (the ``array``
    extra), which cost a run 75 ms and 12 MB (issue 17); no command line holds a dask array
    (the Python API meets one only where the caller imported dask, :mod:`dyncalc.api`, and
    never goes through here). A ``None`` in :data:`sys.modules` makes
    :func:`importlib.util.find_spec` answer ``None`` and an import fail, so pint takes dask
    for absent. A library already imported is left alone."""
    for name in HIDDEN:
        sys.modules.setdefault(name, None)  # type: ignore[arg-type]


def _write(text: str) -> int:
    """Write ``text`` on stdout; the exit status, with the full path's handling of a failed
    write (:mod:`dyncalc.cli.streams`): 141 quietly for a reader gone, else 3 and a line."""
    from ..errors import EXIT_BROKEN_PIPE, EXIT_OK, EXIT_OUTPUT_FAILED, one_line

    try:
        sys.stdout.write(text)
        sys.stdout.flush()
        return EXIT_OK
    except OSError as exc:
        import errno

        try:
            null = os.open(os.devnull, os.O_WRONLY)
            os.dup2(null, 1)
            os.close(null)
        except OSError:
            pass
        if exc.errno == errno.EPIPE:
            return EXIT_BROKEN_PIPE
        try:
            sys.stderr.write(f"Error: cannot write the output: "
                             f"{one_line(exc.strerror or exc)}\n")
            sys.stderr.flush()
        except (OSError, ValueError, AttributeError):
            pass
        return EXIT_OUTPUT_FAILED
