"""The fast reading of a @FILE.csv of plain numbers (units/matrix.py _plain_file) accepts
exactly the files the grammar's _PLAIN_FILE pattern accepts: checked on 50,000 random cells
over the characters of numbers, and on the cases that matter (leading zeros refused, signed
exponents accepted); refused files go to the entry-by-entry reader and its messages."""
import random

import numpy as np

from dyncalc.units.matrix import _PLAIN_FILE, _plain_file


def _fast_accepts(cell: str) -> bool:
    return _plain_file([f"{cell},1", "1,1"], "--M", 500) is not None


def test_same_language_as_the_pattern():
    rng = random.Random("plain-file")
    cells = ["1", "-1", "+1", "1.", ".5", "0.5", "-0.0", "1e5", "1E-5", "1.e5", "1e05",
             "1e+05", "3.0e-07", "007", "00", "-01", "+01", "01.5", "0", "10", "1.005", "5e",
             "e5", "1.5.2", "+-1", "-", ".", " 1 ", "1 2", "inf", "nan", "1_0", "0x1"]
    cells += ["".join(rng.choice("0123456789eE+-. ") for _ in range(rng.randint(1, 6)))
              for _ in range(50_000)]
    for cell in cells:
        plain = bool(_PLAIN_FILE.fullmatch(f"{cell},1\n1,1"))
        if plain and not np.isfinite(float(cell)):
            plain = False  # 6e831: plain, but the entry-by-entry reader says it overflows
        assert _fast_accepts(cell) == plain, cell


def test_values_are_the_floats():
    got = _plain_file(["1e+04,-2.5", "-2.5,3.0e-07"], "--K", 500)
    assert got.tolist() == [[1e4, -2.5], [-2.5, 3e-7]]
    assert isinstance(got, np.ndarray)
