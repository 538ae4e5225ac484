"""A column of numbers that all carry the first cell's unit text (``2.5 m``, ``-1e3 m``) is
split by slicing (``dyncalc.batch.columns._one_unit``): it must read every column exactly as
the one regex pass a column it stands in for, and leave every other column to that pass."""
from __future__ import annotations

import random

import numpy as np
import pytest

from dyncalc.batch import columns
from dyncalc.batch.fast_commands import _Param
from dyncalc.units import LENGTH, STIFFNESS

NUMBERS = ["2", "0.5", "-3", "+4", ".5", "5.", "1e5", "2E-3", "-0", "0", "007", "1e400",
           "1e-400", "5e-324", "1.7976931348623157e308", "2e", "x", "inf", "nan", "1_0"]
TAILS = [" m", "m", "  m", " m ", " mm", " km", " e5m", "e5m", " cm", "\tm", " m/s", ""]


def _read(cells, unit_of_header, dim, *, fast: bool):
    param = _Param("k", dim)
    saved = columns._one_unit
    try:
        if not fast:
            columns._one_unit = lambda cells: None
        return columns._read_column(list(cells), unit_of_header, param, False, {})
    finally:
        columns._one_unit = saved


def _same(a, b):
    assert np.array_equal(a.ok, b.ok)
    assert np.array_equal(a.si.view(np.int64), b.si.view(np.int64))
    assert np.array_equal(a.shown.view(np.int64), b.shown.view(np.int64))
    assert a.unit_json == b.unit_json


@pytest.mark.parametrize("seed", range(300))
def test_one_unit_reads_as_the_regex_pass(seed):
    rng = random.Random(seed)
    tail = rng.choice(TAILS[:-1])
    n = rng.randint(1, 12)
    cells = [rng.choice(NUMBERS[:9]) + tail for _ in range(n)]
    if rng.random() < 0.5:  # a cell that differs: another number, spacing or unit
        i = rng.randrange(n)
        cells[i] = rng.choice(NUMBERS) + rng.choice(TAILS)
    for dim, header in ((LENGTH, ""), (LENGTH, "mm"), (STIFFNESS, "N/m")):
        _same(_read(cells, header, dim, fast=True), _read(cells, header, dim, fast=False))


def test_the_slicing_takes_the_columns_it_is_for():
    literals, unit, values = columns._one_unit(["2 m", "-0.5 m", "1e5 m"])
    assert (literals, unit) == (["2", "-0.5", "1e5"], "m")
    assert values.tolist() == [2.0, -0.5, 1e5]
    literals, unit, values = columns._one_unit(["-0 m", ".5 m", "+2 m"])  # not JSON numbers
    assert (literals, unit) == (["-0", ".5", "+2"], "m")
    assert values.tolist() == [-0.0, 0.5, 2.0] and np.signbit(values[0])
    read = _read(["2 km", "0.5 km"], "", LENGTH, fast=True)
    assert read.ok.tolist() == [True, True] and read.si.tolist() == [2000.0, 500.0]


@pytest.mark.parametrize("cells", [
    ["2 m", "3  m"],       # other spacing
    ["2 m", "3 mm"],       # another unit
    [" 2 m", "3 m"],       # a leading blank
    ["2 m ", "3 m "],      # a trailing blank
    ["1e5e5m", "2e5m"],    # a text after the number that starts with an exponent's letter
    ["2 m", "2e m"],       # not a whole number literal
    ["007 m", "1 m"],      # a leading zero, which the one-off refuses
    ["2", "3"],            # no unit: the plain path's
    ["2 m", "3\n4 m"],      # a line break in a cell
    ["2 m", "3 m\n m"],     # a line break before the unit's text
    ["2 m", " m"],         # no number
])
def test_other_columns_are_left_to_the_regex_pass(cells):
    assert columns._one_unit(cells) is None
