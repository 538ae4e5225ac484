"""Batch numbers a column at a time (dyncalc/batch/floats.py) are, to the byte, ``repr`` of each
float written and ``float`` of each cell read: over float64 bit patterns (hypothesis and a
seeded sweep of 2*10^5), the notation boundaries, subnormals, signed zeros, halfway decimal
strings and every string of the plain-number alphabet; with orjson and without it."""
from __future__ import annotations

import math
import struct
from decimal import Decimal, localcontext
from unittest import mock

import numpy as np
import pytest
from hypothesis import example, given, settings, strategies as st

from dyncalc.batch import floats

orjson = pytest.importorskip("orjson")  # the test extra installs it: never skipped in CI

SPECIAL = [0.0, -0.0, math.inf, -math.inf, math.nan, 5e-324, -5e-324, 2.2250738585072009e-308,
           2.2250738585072014e-308, 1.7976931348623157e308, 2.0 ** 53, 2.0 ** 53 + 2, 0.1,
           1 / 3, 2.0, -2.0, 1e23, 9007199254740993.0]


def bits(n: int) -> float:
    return struct.unpack("<d", struct.pack("<Q", n))[0]


def boundaries() -> list[float]:
    """Every power of ten a float holds and its neighbours (repr changes notation at 1e-4 and
    1e16; orjson's differs from 1e-9 to 1e-4), and the neighbours of the extremes."""
    out = []
    for e in range(-325, 309):
        x = float(f"1e{e}")
        out += [x, math.nextafter(x, 0.0), math.nextafter(x, math.inf), -x]
    return out + SPECIAL


def both(check):
    """Run ``check`` with orjson, then with the ``repr``/``float`` fallback (orjson absent)."""
    def run(values):
        assert floats._orjson() is orjson
        check(values)
        with mock.patch.object(floats, "_orjson", lambda: None):
            check(values)
    return run


@both
def check_reprs(values) -> None:
    values = [float(v) for v in values]
    assert floats.reprs(np.array(values)) == list(map(repr, values))


@both
def check_parse(cells) -> None:
    """``parse_floats`` gives ``float`` of every cell, to the bit, or raises ``ValueError``
    exactly when ``float`` refuses a cell."""
    try:
        expected = [float(c) for c in cells]
    except ValueError:
        with pytest.raises(ValueError):
            floats.parse_floats(cells)
        return
    got = floats.parse_floats(cells)
    assert got.dtype == np.float64 and got.shape == (len(cells),)
    assert got.view(np.int64).tolist() == np.array(expected).view(np.int64).tolist()


# --- writing ---------------------------------------------------------------------------------

def test_orjson_is_installed_and_passes_the_check():
    """The test extra installs an orjson that passes the check (the speed is a benchmark's)."""
    assert floats._orjson() is orjson


def test_boundaries_and_specials():
    check_reprs(boundaries())


def test_random_bit_patterns():
    rng = np.random.default_rng(17)
    check_reprs(rng.integers(0, 2**64, size=2 * 10**5, dtype=np.uint64).view(np.float64))


def test_every_subnormal_exponent_and_the_small_numbers_orjson_writes_otherwise():
    rng = np.random.default_rng(5)
    subnormal = rng.integers(1, 2**52, size=10**4, dtype=np.uint64).view(np.float64)
    small = 10.0 ** rng.uniform(-10, -3, size=10**4)  # 1e-9 .. 1e-4: repr's own notation
    check_reprs(np.concatenate([subnormal, -subnormal, small, -small]))


@settings(max_examples=1000)
@given(st.lists(st.floats(), max_size=40))
@example([1e16, 9999999999999998.0, 1e-4, 9.999999999999999e-05, 1e-9, 9.99e-10, -0.0])
def test_floats_of_hypothesis(values):
    check_reprs(values)


@settings(max_examples=1000)
@given(st.lists(st.integers(0, 2**64 - 1), min_size=1, max_size=40))
def test_bit_patterns_of_hypothesis(patterns):
    check_reprs(list(map(bits, patterns)))


@given(st.integers(0, 2**52 - 1), st.booleans())
def test_subnormals_of_hypothesis(mantissa, negative):
    check_reprs([bits(mantissa | (negative << 63))])


def test_vectors_as_csv_cells():
    @both
    def check(array):
        assert floats.reprs_rows(array) == ["1.0,-0.0,1e-05", "inf,1e+16,5e-324"]
        assert floats.reprs_rows(np.zeros((2, 0))) == ["", ""]
        assert floats.reprs(np.array([])) == []

    check(np.array([[1.0, -0.0, 1e-5], [math.inf, 1e16, 5e-324]]))


def test_an_orjson_that_writes_other_text_is_not_used():
    """orjson before 3.12 writes ``1e16`` for repr's ``1e+16``: such a module fails the check,
    and so does one that cannot write numpy arrays."""

    class Old:
        OPT_SERIALIZE_NUMPY = 0

        @staticmethod
        def dumps(array, option=0):
            return ("[" + ",".join(repr(x).replace("e+", "e") for x in array.tolist())
                    + "]").encode()

    class NoNumpy(Old):
        @staticmethod
        def dumps(array, option=0):
            raise TypeError("Type is not JSON serializable: numpy.ndarray")

    assert floats._trusted(orjson)
    assert not floats._trusted(Old) and not floats._trusted(NoNumpy)


# --- reading ---------------------------------------------------------------------------------

PLAIN = "0123456789.eE+- \t"


def halfway(x: float) -> str:
    """The exact decimal midway between ``x`` and the next float up (round half to even)."""
    with localcontext() as ctx:
        ctx.prec = 1200
        return str((Decimal(x) + Decimal(math.nextafter(x, math.inf))) / 2)


def test_plain_numbers_halfway_strings_and_refusals():
    rng = np.random.default_rng(3)
    sample = rng.integers(0, 2**64, size=2000, dtype=np.uint64).view(np.float64)
    finite = [float(x) for x in sample if math.isfinite(x)]
    column = [repr(x) for x in finite + boundaries() if math.isfinite(x)]
    check_parse(column)
    with mock.patch.object(np, "fromiter", side_effect=AssertionError("not read by orjson")):
        floats.parse_floats(column)  # (the column at once, not ``float`` cell by cell)
    mids = [halfway(abs(x)) for x in finite[:300] + [5e-324, 1.0, 2.0 ** 53, 1e22]]
    check_parse(mids)
    check_parse([m + "1" if "E" in m or "e" in m else m + "0000001" for m in mids])
    odd = ["-0", "0", "-0.0", "-0e5", " 12 ", "\t3e2", "1E5", "1e+5", "1e-400",
           "18446744073709551615", "18446744073709551616", "9007199254740993",
           "-9223372036854775809", "1" * 300, "0." + "0" * 400 + "1", "1" * 400]
    for cell in odd:
        check_parse([cell])
    check_parse(odd)
    for bad in ([""], ["1e400"], ["+4", ".5", "3."], ["1 2"], ["1e"], ["1-2"], ["--1"],
                ["1,2"], ["null"], ["true"], ['"5"'], ["[1]"], ["{}"], ["NaN"], ["1", "nan"]):
        check_parse(bad)


@settings(max_examples=1000)
@given(st.lists(st.text(PLAIN, max_size=12), min_size=1, max_size=8))
def test_strings_of_the_plain_alphabet(cells):
    check_parse(cells)


@settings(max_examples=1000)
@given(st.lists(st.one_of(st.integers(-10**30, 10**30).map(str),
                          st.floats(allow_nan=False, allow_infinity=False).map(repr),
                          st.decimals(allow_nan=False, allow_infinity=False).map(str)),
                min_size=1, max_size=8))
def test_numbers_of_hypothesis(cells):
    check_parse(cells)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.integers(min_value=-2 ** 63, max_value=2 ** 63 - 1), max_size=50))
@example([0, -1, 2 ** 63 - 1, -2 ** 63, 10, 100])
def test_int_texts_are_str_of_each_integer(values):
    """Line numbers written a column at a time are ``str`` of each, with orjson and without."""
    def check(ints):
        assert floats.int_texts(np.array(ints, dtype=np.int64)) == list(map(str, ints))

    both(check)(values)
