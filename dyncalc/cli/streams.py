"""The standard streams under every condition of SPEC's exit table: closed, full, a reader
that goes away, an encoding that cannot carry the symbols.

* :func:`prepare` runs before a command: a closed stdout or stdin (``>&-``, ``<&-``: Python
  then sets ``sys.stdout`` to None and would drop the output silently) becomes a stream that
  fails on use, and symbols the output encoding cannot carry fall back to ASCII names
  (``ω`` -> ``omega``, ``±`` -> ``+/-``) through the ``dyncalc-ascii`` error handler.
* :func:`flush` writes what is buffered while the errors can still be reported; a failure
  shows at once, not in the interpreter's own flush at exit (which would exit 120).
* :func:`exit_status_of` maps a write failure to the exit status: 141 for a reader that went
  away (EPIPE, quiet, as coreutils would end), 3 for any other (disk full, stdout closed).
* :func:`discard_stdout` points file descriptor 1 at ``/dev/null`` after such a failure, so
  that nothing buffered fails again at exit.
"""
from __future__ import annotations

import codecs
import errno
import io
import os
import sys
import unicodedata

from ..errors import EXIT_BROKEN_PIPE, EXIT_OUTPUT_FAILED

__all__ = ["prepare", "fit", "flush", "exit_status_of", "discard_stdout", "say", "ascii_name"]

ERRORS = "dyncalc-ascii"

#: ASCII for the symbols of the output that are not letters (Greek letters go by their name).
_ASCII = {
    "±": "+/-", "×": "x", "·": "*", "⋅": "*", "−": "-", "–": "-", "—": "-", "…": "...",
    "≤": "<=", "≥": ">=", "≈": "~", "≠": "!=", "√": "sqrt", "∞": "inf", "°": "deg",
    "²": "^2", "³": "^3", "¹": "^1", "⁻": "^-", "µ": "u", "∑": "sum", "∂": "d", "→": "->",
    "‘": "'", "’": "'", "“": '"', "”": '"', "\u00a0": " ",
}


def ascii_name(ch: str) -> str:
    """The ASCII a character falls back to: ``ω`` -> ``omega``, ``Ω`` -> ``Omega``,
    ``±`` -> ``+/-``; a character with no such name becomes ``?``.

    >>> ascii_name("ζ"), ascii_name("Ω"), ascii_name("±"), ascii_name("☃")
    ('zeta', 'Omega', '+/-', '?')
    """
    if ch in _ASCII:
        return _ASCII[ch]
    name = unicodedata.name(ch, "")
    for case, prefix in ((str.lower, "GREEK SMALL LETTER "), (str.capitalize,
                                                               "GREEK CAPITAL LETTER ")):
        if name.startswith(prefix):
            return case(name[len(prefix):].split()[0])
    decomposed = unicodedata.normalize("NFKD", ch).encode("ascii", "ignore").decode()
    return decomposed or "?"


def _fallback(exc: UnicodeError):
    if not isinstance(exc, UnicodeEncodeError):
        raise exc
    return "".join(ascii_name(ch) for ch in exc.object[exc.start:exc.end]), exc.end


codecs.register_error(ERRORS, _fallback)


class _Closed(io.TextIOBase):
    """A standard stream that was closed when the program started: every use fails with
    EBADF, as writing to a closed descriptor does."""

    def __init__(self, name: str):
        self.stream_name = name

    encoding = "utf-8"
    errors = "strict"

    def writable(self) -> bool:
        return True

    def readable(self) -> bool:
        return True

    def isatty(self) -> bool:
        return False

    def _fail(self, *args, **kwargs):
        raise OSError(errno.EBADF, f"standard {self.stream_name[3:]}put is closed")

    write = read = readline = fileno = _fail

    def flush(self) -> None:
        pass


class _TextOnly:
    """An ASCII text stream shown to click without its byte buffer: click would otherwise
    write UTF-8 to it (it takes an ASCII stream for a misconfigured one), where the
    user asked for ASCII (``PYTHONIOENCODING=ascii``)."""

    def __init__(self, stream):
        self._stream = stream

    def __getattr__(self, name):
        if name == "buffer":
            raise AttributeError(name)
        return getattr(self._stream, name)

    def write(self, text: str) -> int:
        return self._stream.write(text)

    def flush(self) -> None:
        self._stream.flush()


def _is_ascii(stream) -> bool:
    try:
        return codecs.lookup(getattr(stream, "encoding", None) or "utf-8").name == "ascii"
    except LookupError:
        return False


def prepare() -> None:
    """Make the standard streams follow the I/O contract (see the module's docstring)."""
    if sys.stdout is None:
        sys.stdout = _Closed("stdout")
    if sys.stdin is None:
        sys.stdin = _Closed("stdin")
    for name in ("stdout", "stderr"):
        stream = getattr(sys, name)
        reconfigure = getattr(stream, "reconfigure", None)
        if reconfigure is None or getattr(stream, "errors", None) not in ("strict",
                                                                           "backslashreplace"):
            continue
        try:
            reconfigure(errors=ERRORS)
        except (ValueError, OSError):  # a stream already closed: reported on use
            continue
        if _is_ascii(stream):
            setattr(sys, name, _TextOnly(stream))


def fit(text: str) -> str:
    """``text`` as stdout will show it: with the symbols its encoding cannot carry replaced
    by their ASCII names, so that a table can be aligned on what is printed."""
    encoding = getattr(sys.stdout, "encoding", None) or "utf-8"
    try:
        text.encode(encoding)
        return text
    except UnicodeEncodeError:
        return text.encode(encoding, errors=ERRORS).decode(encoding)
    except LookupError:
        return text


def flush() -> None:
    """Write out what stdout holds (raises the OSError of a failed write)."""
    if sys.stdout is not None:
        sys.stdout.flush()


def exit_status_of(exc: OSError) -> int:
    """141 for a reader that went away, 3 for any other failed write."""
    return EXIT_BROKEN_PIPE if exc.errno == errno.EPIPE else EXIT_OUTPUT_FAILED


def discard_stdout() -> None:
    """Point descriptor 1 at ``/dev/null`` (what is still buffered then goes nowhere quietly)."""
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, 1)
        os.close(null)
    except OSError:
        pass
    if isinstance(sys.stdout, _Closed):
        sys.stdout = open(os.devnull, "w")  # noqa: SIM115 (lives as long as the process)


def say(line: str) -> None:
    """Write one line on stderr if stderr can take it (a full or closed stderr is ignored)."""
    try:
        if sys.stderr is not None:
            sys.stderr.write(line + "\n")
            sys.stderr.flush()
    except (OSError, ValueError):
        pass
