"""The errors dyncalc shows to its users.

Everything the user can get wrong is raised as :class:`InputError` (exit status 2, one
``Error:`` line on stderr). Nothing else is meant to reach the user; any other exception is a bug
and the CLI reports it as one (also exit 2, with the traceback only under ``--debug``).
"""

__all__ = ["InputError", "PhysicsError", "EXIT_OK", "EXIT_CHECK_FAILED", "EXIT_BAD_INPUT",
           "EXIT_OUTPUT_FAILED", "EXIT_INTERRUPTED", "EXIT_BROKEN_PIPE", "escape", "one_line"]

# The exit statuses of SPEC's table ("Exit status, errors and I/O").
EXIT_OK = 0
EXIT_CHECK_FAILED = 1     #: a --check failed, and nothing else
EXIT_BAD_INPUT = 2
EXIT_OUTPUT_FAILED = 3    #: the output could not be written (disk full, stdout closed)
EXIT_INTERRUPTED = 130    #: Ctrl-C
EXIT_BROKEN_PIPE = 141    #: the reader went away (128 + SIGPIPE), quietly


class InputError(ValueError):
    """Bad input or usage: the message says what to change (it becomes ``Error: <message>``)."""


class PhysicsError(InputError):
    """A well-formed request the physics cannot answer (a slope too steep to roll, resonance)."""


def escape(text: str) -> str:
    """``text`` with every character a terminal could act on shown as an escape: C0 and C1
    controls (ESC, CR, NUL, tab), format characters (bidirectional overrides, zero-width
    characters, the BOM), line and paragraph separators, unusual spaces, private-use, lone
    surrogates and unassigned code points become ``\\u00XX``/``\\uXXXX``/``\\UXXXXXXXX``."""
    if text.isprintable():  # the common case: nothing to do
        return text
    return "".join(ch if ch.isprintable() else _escaped(ch) for ch in text)


def _escaped(ch: str) -> str:
    code = ord(ch)
    return f"\\u{code:04x}" if code <= 0xFFFF else f"\\U{code:08x}"


def one_line(text: object) -> str:
    """``text`` as one line that is safe to print on a terminal: runs of spaces and newlines
    become one space, and everything else :func:`escape` escapes is escaped. Every ``Error:``
    and ``warning:`` line passes through it."""
    return " ".join(escape(part) for part in str(text).replace("\n", " ").split(" ") if part)
