"""Simple quotes found by splitting and counting (``dyncalc.batch.cells._simple_quotes``): the
same chunks as the regular expression that defines them (``source._SIMPLE_QUOTES_RE``), and
the same quoted cells without a comma (``source._QUOTED_NO_COMMA_RE``), on every text of a
few characters and on random longer ones; and the chunk reader's cells as the csv module's."""
from __future__ import annotations

import csv
import itertools
import random

import pytest

from dyncalc.batch.cells import _quoted_columns, _simple_quotes
from dyncalc.batch.source import _QUOTED_NO_COMMA_RE, _SIMPLE_QUOTES_RE

ALPHABET = ['"', ",", "\n", "\r", "\0", "a"]


def _agrees(text: str) -> None:
    pieces = _simple_quotes(text)
    assert (pieces is not None) is (_SIMPLE_QUOTES_RE.fullmatch(text) is not None), repr(text)
    if pieces is not None:
        inside = pieces[1::2]
        assert pieces == text.replace("\r\n", "\n").rstrip("\r").split('"')
        no_comma = not all("," in cell for cell in inside)
        assert no_comma is (_QUOTED_NO_COMMA_RE.search(text) is not None), repr(text)


def test_every_short_text_is_taken_as_the_regex_takes_it():
    for size in range(1, 8):
        for letters in itertools.product(ALPHABET, repeat=size):
            _agrees("".join(letters))


@pytest.mark.parametrize("seed", range(40))
def test_random_chunks_are_taken_as_the_regex_takes_them(seed):
    rng = random.Random(seed)
    cells = ['"1,2"', "3", '""', '"a b"', "", '"x\ny"', 'a"b', '"5"', '"1,\r"', "7\r"]
    for _ in range(200):
        lines = [",".join(rng.choice(cells) for _ in range(rng.randint(1, 4)))
                 for _ in range(rng.randint(1, 5))]
        text = rng.choice(["\n", "\r\n"]).join(lines)
        if rng.random() < 0.2:  # one character anywhere
            i = rng.randrange(len(text) + 1)
            text = text[:i] + rng.choice(ALPHABET) + text[i:]
        _agrees(text)


def test_quoted_cells_are_the_csv_modules():
    """The texts inside quotes are the cells the csv module reads that hold a comma; a chunk
    only of quoted cells is split by columns, one with a bare cell is not."""
    lines = ['"parallel(cantilever(l=1.5 m), 200 N/m)",300,2e4', '"a,b",2', '"1,2","3,4"']
    for line in lines:
        assert _simple_quotes(line)[1::2] == [c for c in next(csv.reader([line])) if "," in c]
    assert _simple_quotes('"a,b",2,"c"') == ["", "a,b", ",2,", "c", ""]
    assert _simple_quotes('"a,b"2') is None and _simple_quotes('"a\nb"') is None
    assert _quoted_columns('"1,2","3,4"\n"5,6","7,8"', 2) == [["1,2", "5,6"], ["3,4", "7,8"]]
    assert _quoted_columns('"1,2",3', 1) is None


@pytest.mark.parametrize("seed", range(4))
def test_a_single_cell_is_the_split_columns_cell(seed):
    """``Table.cell(i, j)`` (a block's probe reads one row without splitting the chunk) is
    ``table[j][i]``, for chunks without quotes and in simple quotes, all rows or some kept, and
    a ``later`` column gives the same cell, stripped where asked, before and after the split."""
    from dyncalc.batch.cells import _without_quotes
    from dyncalc.batch.source import _Chunk

    rng = random.Random(seed)
    cells = ["1", " 2.5 ", "-0", "x", "", '"1,2"', '" a, b "', "3e4"]
    for _ in range(50):
        width = rng.randint(1, 4)
        lines = [",".join(rng.choice(cells) for _ in range(width)) for _ in range(6)]
        if "" in lines:   # (the reader takes an empty line by itself: no cell)
            continue
        plain = _without_quotes(lines, "\n".join(lines)) if '"' in "".join(lines) else None
        if plain is None and '"' in "".join(lines):
            continue
        chunk = _Chunk(list(range(6)), lines=lines, plain=plain)
        keep = None if rng.random() < 0.5 else sorted(rng.sample(range(6), 3))
        expected = [list(c) for c in zip(*[next(csv.reader([lines[i]]))
                                           for i in (range(6) if keep is None else keep)])]
        table = chunk.table(width, keep)
        stripped = [table.later(j, lambda c: [x.strip() for x in c], str.strip)
                    for j in range(width)]
        for i in range(len(expected[0])):
            for j in range(width):
                assert table.cell(i, j) == expected[j][i]
                assert stripped[j][i] == expected[j][i].strip()
        assert [list(table[j]) for j in range(width)] == expected
        assert [stripped[j][0] for j in range(width)] == [c[0].strip() for c in expected]


def test_a_loop_over_a_later_column_splits_the_chunk_once():
    """A ``later`` column answers its first cells one row at a time (a probe) and then makes
    the column, so a loop over every row splits the chunk once, not a line a row."""
    from dyncalc.batch.cells import SINGLES
    from dyncalc.batch.source import _Chunk

    lines = [f"{i},{2 * i}" for i in range(100)]
    table = _Chunk(list(range(100)), lines=lines).table(2, None)
    splits = []
    original = table._split
    table._split = lambda: splits.append(1) or original()
    column = table.later(1)
    assert column[3] == "6" and not splits
    assert [column[i] for i in range(100)] == [str(2 * i) for i in range(100)]
    assert len(splits) == 1 and column.singles == SINGLES
