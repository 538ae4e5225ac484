r"""A chunk's lines split into cells column by column, without the csv module where their quotes
allow it: :class:`Table` (plain numbers read at once, the texts split only when asked for), and
the splitting of lines whose every cell is quoted (:func:`_quoted_columns`) or whose quotes
open and close whole cells (:func:`_without_quotes`), to what ``csv.reader`` reads.

Example::

    >>> _quoted_columns('"0,0,1","1,2,0"\n"0,0,2","3,4,0"', 2)
    [['0,0,1', '0,0,2'], ['1,2,0', '3,4,0']]
    >>> Table(lambda: [["1", "2"], ["3", "-0"]], 2, 2, "1,3\n2,-0").numbers().tolist()
    [[1.0, 3.0], [2.0, -0.0]]
"""
from __future__ import annotations

from itertools import repeat
from operator import contains

from .floats import json_floats


class Table:
    """The cells of a chunk's rows column by column (``table[j]``: a list of texts), split at
    commas when first asked for; and, where every cell is a plain number, the values of all
    of them read at once, without a text per cell (:meth:`numbers`)."""

    __slots__ = ("_split", "_columns", "_text", "_numbers", "_cell", "n", "width")

    def __init__(self, split, n: int, width: int, text: str | None, cell=None):
        """``split()`` gives the columns; ``text``: the rows' lines joined by line breaks
        where their cells are split at every comma (else None); ``cell(i, j)``, where given,
        the cell of row ``i``, column ``j`` as ``split()[j][i]`` without splitting the rest."""
        self._split, self._columns, self._text, self._numbers = split, None, text, False
        self._cell, self.n, self.width = cell, n, width

    def __len__(self) -> int:
        return self.width

    def __getitem__(self, j: int) -> list[str]:
        if self._columns is None:
            self._columns = self._split()
        return self._columns[j]

    def __iter__(self):
        return iter([self[j] for j in range(self.width)])

    def numbers(self):
        """The ``(n, width)`` float64 values of the cells where every one is a plain number
        (the characters of numbers, each as :func:`~dyncalc.batch.columns._plain_floats`
        reads it: ``float``'s value, read as JSON, so no leading zero), else ``None``."""
        if self._numbers is False:
            self._numbers = None
            text = self._text
            # (what JSON reads without '"[{tfn', json_floats' test, is numbers and blanks)
            if text:
                values = json_floats(text.replace("\n", ","), self.n * self.width)
                if values is not None:
                    self._numbers = values.reshape(self.n, self.width)
        return self._numbers


    def cell(self, i: int, j: int) -> str:
        """The cell of row ``i`` in column ``j``: ``self[j][i]``, splitting only its row
        until the columns are split."""
        if self._columns is None and self._cell is not None:
            return self._cell(i, j)
        return self[j][i]

    def later(self, j: int, make=None, one=None) -> "_Later":
        """Column ``j`` (or ``make(column j)``), split only when the column is asked for; a
        single cell ``i`` is ``self.cell(i, j)`` (or ``one`` of it, where ``one`` is to a cell
        what ``make`` is to the column) without splitting the chunk (a block's probe)."""
        if make is None:
            return _Later(lambda: self[j], self.n, lambda i: self.cell(i, j))
        return _Later(lambda: make(self[j]), self.n,
                      None if one is None else lambda i: one(self.cell(i, j)))


#: Cells of a :class:`_Later` column read one by one before the column is made.
SINGLES = 8


class _Later:
    """A column made only when it is needed (a column of plain numbers whose values
    :meth:`Table.numbers` gave: its texts are rarely needed): iterated, sliced, or more than
    :data:`SINGLES` of its cells asked for; a few cells are read alone."""

    __slots__ = ("make", "n", "cells", "one", "singles")

    def __init__(self, make, n: int, one=None):
        """``make()``: the column; ``one(i)``: its cell ``i`` alone (or None), used for the
        first :data:`SINGLES` cells asked for one at a time (a block's probe), after which
        the column is made (a loop over the rows splits the chunk once, not a line a row)."""
        self.make, self.n, self.cells, self.one, self.singles = make, n, None, one, 0

    def _made(self) -> list[str]:
        if self.cells is None:
            self.cells = self.make()
        return self.cells

    def __len__(self) -> int:
        return self.n

    def __getitem__(self, i):
        if self.cells is None and self.one is not None and type(i) is int \
                and self.singles < SINGLES:
            self.singles += 1
            return self.one(i)
        return self._made()[i]

    def __iter__(self):
        return iter(self._made())


def _unquoted(column: list[str]) -> list[str]:
    """A column of cells with each NUL (a comma of a quoted cell) a comma again."""
    joined = "\n".join(column)  # (no cell holds a line break)
    return joined.replace("\0", ",").split("\n") if "\0" in joined else column


def _without_quotes(lines: list[str], text: str, pieces: list[str] | None = None
                    ) -> list[str] | None:
    """``lines`` (``text`` joined by line breaks) in simple quotes (each quote opens or closes
    a whole cell, no quote inside one) without their quotes, each comma inside a quoted cell a
    NUL (which the text has not), so that splitting a line at commas gives what the csv module
    reads; ``None`` where a line is empty (the csv module reads no cell there, not one empty
    cell). ``pieces``: ``text.split('"')`` where the caller has it (it is changed here)."""
    if "" in lines:
        return None
    if pieces is None:
        pieces = text.split('"')  # the odd ones are inside quotes
    pieces[1::2] = '"'.join(pieces[1::2]).replace(",", "\0").split('"')
    plain = "".join(pieces).split("\n")
    return plain if len(plain) == len(lines) else None


def _simple_quotes(text: str) -> list[str] | None:
    """``text.split('"')`` (the odd pieces inside quotes; each ``\\r`` of a ``\\r\\n`` taken
    off first) of ``text`` (lines joined by ``\\n``, a ``\\r`` perhaps ending each) where
    every quote opens or closes a whole cell on its line, as
    ``source._SIMPLE_QUOTES_RE`` takes them (no quote, line break or ``\\r`` inside a quoted
    cell, no NUL anywhere, a ``\\r`` only before a line break or at the end); ``None``
    otherwise. Found by splitting and counting in C: each quoted cell is a NUL in the text
    outside the quotes, which must stand between cell or line boundaries.

    >>> _simple_quotes('"1,2",3\\n4,"5"'), _simple_quotes('1"2",3')
    (['', '1,2', ',3\\n4,', '5', ''], None)
    """
    if "\0" in text:
        return None
    if "\r" in text:
        end = text.endswith("\r")
        if text.count("\r") != text.count("\r\n") + end:
            return None
        text = text.replace("\r\n", "\n")[:-1 if end else None]
    pieces = text.split('"')  # the odd ones are inside quotes
    if not len(pieces) % 2:
        return None
    inside = pieces[1::2]
    outside = "\0".join(pieces[0::2])  # (a NUL a quoted cell: none was there)
    m = len(inside)
    if "\n" in "".join(inside) \
            or outside.count(",\0") + outside.count("\n\0") + outside.startswith("\0") != m \
            or outside.count("\0,") + outside.count("\0\n") + outside.endswith("\0") != m:
        return None
    return pieces


def _quoted_columns(text: str, n: int) -> list[list[str]] | None:
    """The cells of ``text`` (``n`` lines joined by ``\\n``, no NUL, no ``\\r``) column by
    column where every cell of every line is quoted, each line has as many, and each holds a
    comma and no quote or line break (so the csv module reads the cells without their quotes,
    and ``csv.writer`` writes the lines as they are); ``None`` otherwise."""
    if not (text.startswith('"') and text.endswith('"')):  # (before a split of it all)
        return None
    pieces = text.split('"')  # the odd ones are inside quotes
    if len(pieces) % 2 == 0 or pieces[0] or pieces[-1]:
        return None
    between = pieces[2:-1:2]  # what separates the quoted cells: a comma or a line break
    cells = pieces[1::2]
    width = len(cells) // n
    if width * n != len(cells) or not set(between) <= {",", "\n"} \
            or between.count("\n") != n - 1 or between[width - 1::width].count("\n") != n - 1:
        return None  # (n - 1 line breaks between cells: none inside one)
    columns = [cells[j::width] for j in range(width)]
    for column in columns:  # (a test a cell, in C: a regular expression over the joined
        if not all(map(contains, column, repeat(",", n))):  # column took ten times longer)
            return None
    return columns
