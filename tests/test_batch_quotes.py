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
