"""CSV lines as ``csv.writer`` writes them: the input rows echoed, the output rows."""
from __future__ import annotations

import csv


class _Sink:
    """A file-like object collecting what a ``csv.writer`` writes, one string per row."""

    __slots__ = ("write",)

    def __init__(self, collect):
        self.write = collect


def _csv_lines(rows) -> list[str]:
    """Each row as one CSV line (without the line end), quoted as ``csv.writer`` quotes (the
    writer quotes a cell holding a line break only if the line end has that character)."""
    lines: list[str] = []
    csv.writer(_Sink(lambda line: lines.append(line[:-2])),
               lineterminator="\r\n").writerows(rows)
    return lines
