"""Splitting a list typed on the command line at its separators, outside parentheses and
brackets: a spring network's arguments, a body's keys, a matrix's rows and entries."""
from __future__ import annotations

from ..errors import InputError

__all__ = ["split_top"]


def split_top(text: str, sep: str = ",", where: str | None = None) -> list[str]:
    """``text`` split at ``sep`` where no parenthesis or bracket is open.

    With ``where`` (the option or word being read, for the message), an unbalanced ``)`` or
    ``(`` is refused; without it the parts are returned as they are and the caller's own
    reading refuses them.

    >>> split_top("m=2kg, at=(0.1, 0, 0) m")
    ['m=2kg', ' at=(0.1, 0, 0) m']
    """
    parts, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        if ch in "([":
            depth += 1
        elif ch in ")]":
            depth -= 1
            if depth < 0 and where is not None:
                raise InputError(f"{where}: a ')' has no matching '('")
        elif ch == sep and depth == 0:
            parts.append(text[start:i])
            start = i + 1
    if depth != 0 and where is not None:
        raise InputError(f"{where}: a '(' is not closed")
    parts.append(text[start:])
    return parts
