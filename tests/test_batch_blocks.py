"""Batch reading a block at a time gives what reading line by line gives; numbers a column at
a time are read as ``float`` reads them; lines assembled a column at a time are the lines
joined one at a time.

The block reader (:meth:`dyncalc.batch.source._Reader._block_chunk`) hands over to the line by
line reader (quotes, lone carriage returns, long lines, I/O errors) with the text it read
ahead; hypothesis draws texts of those characters, block sizes that cut lines and CRLF pairs
anywhere, and chunk sizes, and the records, their line numbers and the chunks must be the
line by line reader's.
"""
from __future__ import annotations

import io
import itertools

import numpy as np
import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from dyncalc.batch import GENERIC_ENV, assemble, source
from dyncalc.cli import cli


def _assert_fast_is_generic(monkeypatch, args: list[str]) -> None:
    """``dyncalc ARGS`` on the vectorised path and with every row through the generic
    (one-off) path: the same exit status, stdout and stderr, byte for byte."""
    fast = CliRunner().invoke(cli, args)
    monkeypatch.setenv(GENERIC_ENV, "1")
    generic = CliRunner().invoke(cli, args)
    assert (fast.exit_code, fast.stdout, fast.stderr) == (
        generic.exit_code, generic.stdout, generic.stderr)


def _stream(text: str):
    return io.TextIOWrapper(io.BytesIO(text.encode("utf-8", "surrogateescape")),
                            encoding="utf-8-sig", newline="", errors="surrogateescape")


def _chunks(text: str, size: int, by_line: bool):
    reader = source._Reader(_stream(text))
    if by_line:
        reader.stream = source._bounded_lines(reader.source)
    out = []
    while (chunk := reader.chunk(size)) is not None:
        out.append([(chunk.numbers[i], chunk.row(i)) for i in range(len(chunk))])
    return out, reader.fatal


PIECES = ["1", "2.5", ",", "\n", "\r\n", "\r", '"', "a b", " ", "", "\u00e9"]


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(PIECES), max_size=40), st.integers(1, 6), st.integers(1, 9))
def test_blocks_read_what_lines_read(pieces, size, block):
    text = "".join(pieces)
    saved = source.BLOCK
    source.BLOCK = block
    try:
        assert _chunks(text, size, False) == _chunks(text, size, True)
    finally:
        source.BLOCK = saved


def test_a_big_file_with_crlf_line_ends_is_read_a_block_at_a_time(monkeypatch):
    rows = "".join(f"{i},{i + 1}\r\n" for i in range(5000))
    monkeypatch.setattr(source, "BLOCK", 1000)
    reader = source._Reader(_stream("k,m\r\n" + rows))
    chunks = []
    while (chunk := reader.chunk(1024)) is not None:
        chunks.append(chunk)
    assert reader.stream is None  # never handed over to the line by line reader
    assert [len(c) for c in chunks] == [1024] * 4 + [905]
    assert chunks[-1].lines[-1] == "4999,5000" and chunks[-1].numbers[-1] == 5001


def test_a_quote_hands_over_with_nothing_lost():
    text = "k,m\n1,2\n3,4\n\"5\",6\n7,8\n"
    assert _chunks(text, 2, False) == _chunks(text, 2, True) == (
        [[(1, ["k", "m"]), (2, ["1", "2"])], [(3, ["3", "4"]), (4, ["5", "6"])],
         [(5, ["7", "8"])]], None)


def test_buffered_readline_is_the_streams_readline():
    """``_Buffered`` (text read ahead, then the stream) splits where the stream alone would,
    at every cut of the text and every size asked."""
    text = "ab\r\ncd\re\n\nfgh\r"
    for cut, size in itertools.product(range(len(text) + 1), [-1, 1, 2, 3, 5]):
        alone = _stream(text)
        ahead = _stream(text)
        read = ahead.read(cut)
        while read.endswith("\r") and (more := ahead.read(1)):
            read += more
        both = source._Buffered(read, ahead)
        expected = list(iter(lambda: alone.readline(size), ""))
        got = list(iter(lambda: both.readline(size), ""))
        assert got == expected, (cut, size)


# --- numbers read a column at a time: float's semantics, hard strings ----------------------------

HARD = ["1e-320", "4.9e-324", "2e-324", "1e-400", "1e308", "1.8e308", "0x1p3", " 1.5", "1.5 ",
        "\t2", "1_000", "1e5", "1E5", "+5", "-0", "0.0", ".5", "5.", "007", "1e-05", "inf",
        "nan", "-inf", "1,5", "١٢", "0.1e1", "2.5e+3"]


@pytest.mark.parametrize("cell", HARD)
@pytest.mark.parametrize("as_json", [False, True], ids=["csv", "json"])
def test_hard_cells_read_as_the_one_off_reads_them(tmp_path, monkeypatch, cell, as_json):
    """A column of one hard cell among ordinary ones: the vectorised path's output, errors
    and exit status are the generic (one-off) path's, byte for byte."""
    path = tmp_path / "rows.csv"
    path.write_text("k [N/m],m [kg]\n100,2\n" + f'"{cell}"' * ("," in cell) + cell * (
        "," not in cell) + ",2\n300,3\n")
    args = ["natural-frequency", "--batch", str(path), "--on-error", "skip"] + (
        ["--json"] if as_json else [])
    _assert_fast_is_generic(monkeypatch, args)


# --- lines assembled a column at a time ----------------------------------------------------------

@settings(max_examples=200, deadline=None)
@given(st.lists(st.floats(allow_nan=True, allow_infinity=True), min_size=1, max_size=30),
       st.lists(st.text(max_size=5), min_size=30, max_size=30))
def test_column_lines_are_the_joined_lines(values, words):
    n = len(values)
    parts = ["{", np.array(values), ', "w": ', words[:n], "}", np.arange(n, dtype=np.int64)]
    expected = [f"{{{v!r}, \"w\": {w}}}{i}" for i, (v, w) in enumerate(zip(values, words))]
    assert assemble.lines(parts, n) == expected
    assert assemble.lines(parts, n, joined=True) == "".join(e + "\n" for e in expected)


def test_lines_of_texts_alone_and_of_tiny_floats():
    assert assemble.lines(["a", "", "b"], 2) == ["ab", "ab"]
    assert assemble.lines(["x=", np.array([1e-05, 0.5, float("inf")]), ";"], 3) == [
        "x=1e-05;", "x=0.5;", "x=inf;"]



@settings(max_examples=200, deadline=None)
@given(st.lists(st.sampled_from([0.0, -0.0, 1.0, 1.5, float("nan"), 1e-05, -2.0]),
                min_size=1, max_size=8), st.integers(0, 7))
def test_equal_float_columns_written_once_are_each_their_own_reprs(values, flip):
    """Columns equal bit for bit share their texts (written once); a column equal but for one
    row (``-0.0`` for ``0.0``, another value) gets its own, so each line is the ``repr``s."""
    a = np.array(values)
    b = a.copy()
    i = flip % len(values)
    b[i] = -b[i] if b[i] == 0.0 else b[i] + 1.0
    parts = [a, ",", a.copy(), ",", b, ",", a[::-1].copy()]
    expected = [f"{x!r},{x!r},{y!r},{z!r}"
                for x, y, z in zip(a.tolist(), b.tolist(), a[::-1].tolist())]
    assert assemble.lines(parts, len(values)) == expected


@settings(max_examples=200, deadline=None)
@given(st.sampled_from([0.0, -0.0, 1.0, float("nan"), 1e-05, 1e16, float("-inf"), 5e-324]),
       st.integers(2, 9), st.integers(0, 8))
def test_a_constant_float_column_is_one_text_and_each_line_its_repr(value, n, flip):
    """A column of one bit pattern is written as one shared text (``assemble._constant``); a
    column equal to it but in one row (``-0.0`` for ``0.0``, another value) stays a column;
    every line is the ``repr``s either way."""
    same = np.full(n, value)
    other = same.copy()
    i = flip % n
    other[i] = -other[i] if other[i] == 0.0 else 2.0
    assert assemble._constant(same) == repr(value)
    assert assemble._constant(other) is other
    parts = ["<", same, ",", other, ",", same[:1].repeat(n), ">"]
    expected = [f"<{value!r},{y!r},{value!r}>" for y in other.tolist()]
    assert assemble.lines(parts, n) == expected
    assert assemble.lines(parts, n, joined=True) == "".join(e + "\n" for e in expected)
    assert assemble.lines(["a", same, "b"], n) == [f"a{value!r}b"] * n

# --- simple quoted cells read a block at a time --------------------------------------------------

QUOTED = ['"0,0,1"', '"a b"', '""', '"', ",", "\n", "\r\n", "1", " ", '"x\ny"', "\0", "x"]


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(QUOTED), max_size=40), st.integers(1, 6), st.integers(1, 9))
def test_quoted_blocks_read_what_the_csv_module_reads(pieces, size, block):
    """Quoted cells, simple or not (a quote inside a cell, a line break in quotes, text after
    a closing quote, NUL): the block reader's records, line numbers, chunks and errors are
    those of the csv module read line by line."""
    text = "".join(pieces)
    saved = source.BLOCK
    source.BLOCK = block
    try:
        assert _chunks(text, size, False) == _chunks(text, size, True)
    finally:
        source.BLOCK = saved


def test_simple_quoted_cells_are_read_a_block_at_a_time():
    rows = "".join(f'"0,0,{i}","{i},1,0"\r\n' for i in range(3000))
    reader = source._Reader(_stream("omega,vr\r\n" + rows))
    chunks = []
    while (chunk := reader.chunk(1024)) is not None:
        chunks.append(chunk)
    assert reader.stream is None  # never handed over to the line by line reader
    assert [len(c) for c in chunks] == [1024, 1024, 953]
    assert chunks[-1].row(952) == ["0,0,2999", "2999,1,0"] and chunks[-1].numbers[-1] == 3001
    assert chunks[0].echo([1]) == ['"0,0,0","0,1,0"']
    assert chunks[0].rows is None  # split at commas without the csv module (quotes taken off)
    reader = source._Reader(_stream('a,b\n"1",2\n'))                # quoted without need
    chunk = reader.chunk(10)
    assert reader.stream is None and chunk.written is None and chunk.echo([1]) == ["1,2"]


@pytest.mark.parametrize("text, split", [
    ('"0,0,1","1,1,0"\n"0,0,2","2,1,0"\n', True),           # every cell quoted
    ('"0,0,1","1,1,0"\r\n"0, ,2",",x"\r\n', True),             # ... CRLF
    ('"0,0,1","1,1,0"\n"0,0,2","2,1,0","3,"\n', True),        # ... not as many on each line
    ('"0,0,1","1"\n"0,0,2","2,1,0"\n', False),               # ... one without a comma
    ('"0,0,1","1,""1",0"\n', False),                          # ... a quote inside
    ('"0,0,1"\n', True),                                      # one cell
    ('x,"1,2,3",,y\r\n"a,b",2,,"c,d"\r\n', True),            # mixed, an empty cell, CRLF
    ('",,,",","\n" , ",a\n', True),                          # commas and spaces only
    ('x,"1,2,3",,"",y\n"a,b",2,"",,"c"\n', False),            # "": csv.writer would not quote
    ('"1,2","3"\n"4,5",6\n', False),                         # nor "3"
    ('"1,2",3\n\n"4,5",6\n', False),                        # a blank line (no cell for csv)
])
def test_simple_quotes_split_as_the_csv_module_reads(text, split):
    """Lines in simple quotes are split at commas with their quotes off: their rows, cell
    counts, columns and echo are the csv module's (and csv.writer's), however they are read."""
    import csv
    import io

    records = list(csv.reader(io.StringIO(text), strict=True))
    chunk = source._Reader(_stream(text)).chunk(100)
    n = len(records)
    assert len(chunk) == n and (chunk.rows is None) == split
    assert [chunk.row(i) for i in range(n)] == records
    widths = chunk.widths()
    assert [w + (chunk.rows is None) for w in widths] == list(map(len, records))
    if len(set(map(len, records))) == 1:
        columns = [list(c) for c in chunk.table(len(records[0]), None)]
        assert columns == [list(c) for c in zip(*records)]
        assert [list(c) for c in chunk.table(len(records[0]), [n - 1])] == \
            [[c] for c in records[-1]]
    written = io.StringIO()
    csv.writer(written, lineterminator="\n").writerows(records)
    assert "\n".join(chunk.echo(None)) + "\n" == written.getvalue()


# --- vectors read a column at a time -------------------------------------------------------------

HARD_VECTORS = ["1,2,3", " 1 , 2 ,\t3 ", "1e400,0,0", "007,0,1", "1,2", "1,2,3,4", "+1,-0,.5",
                "1_0,2,3", "inf,0,0", "1.,2e-5,3E+2", "1 m,2,3", "a,b,c", "0x1p3,0,0",
                "05,1,2", "1,2,03", "0.0e05,0,0", "-.5,+5.,1E-2", "1 ,\t2, 3", "1,,2", "1 5,2,3",
                "+-1,0,0", "1e,0,0", ".,0,0", "1.2.3,0,0", "0,0,0", "-0.0,-0,0.0"]


@pytest.mark.parametrize("cell", HARD_VECTORS)
@pytest.mark.parametrize("as_json", [False, True], ids=["csv", "json"])
def test_hard_vector_cells_read_as_the_one_off_reads_them(tmp_path, monkeypatch, cell, as_json):
    path = tmp_path / "rows.csv"
    path.write_text(f'omega [rad/s],vr [m/s]\n"0,0,2","1,1,0"\n"0,0,3","{cell}"\n'
                    '"0,0,1","-2,0.5,0"\n')
    args = ["coriolis", "--batch", str(path), "--on-error", "skip"] + (
        ["--json"] if as_json else [])
    _assert_fast_is_generic(monkeypatch, args)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.sampled_from(HARD_VECTORS), min_size=1, max_size=8))
def test_a_vector_column_is_its_cells(column):
    """``_vectors`` of a column: each cell's regex match and ``float`` of its parts."""
    from dyncalc.batch.fast_commands import _VECTOR_RE, _vectors

    typed, ok = _vectors(column)
    for i, cell in enumerate(column):
        m = _VECTOR_RE.fullmatch(cell)
        assert ok[i] == (m is not None)
        if m is not None:
            assert typed[i].tolist() == [float(x) for x in m.groups()]


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(QUOTED + ['"1,2"', ",x"]), max_size=40), st.integers(1, 6))
def test_quoted_blocks_echo_what_the_csv_writer_writes(pieces, size):
    """The echo of a quoted block read a block at a time is ``csv.writer``'s line of each
    record (as for the csv module's records read line by line)."""
    from dyncalc.batch.csvlines import _csv_lines

    reader = source._Reader(_stream("".join(pieces)))
    while (chunk := reader.chunk(size)) is not None:
        if chunk.rows is None:  # no quotes: split at commas, the line is its echo
            continue
        rows = [chunk.row(i) for i in range(len(chunk))]
        assert chunk.echo(None) == _csv_lines(rows)
        assert chunk.echo([0]) == _csv_lines(rows[:1])


@pytest.mark.parametrize("text, plain", [
    ("1.5,2\n-0,3e2\n 4 ,\t5\n", True),          # -0 (an integer: float gives -0.0), blanks
    ("1e400,2\n3,4\n", False),                    # beyond float64 (orjson refuses it)
    ("1,2\n007,3\n", False),                      # a leading zero: the one-off refuses it
    ("1,2\n+3,4\n", False),                       # + and .5: float reads them, JSON does not
    ("1,2\n.5,4\n", False),
    ("1,2\n,4\n", False),                         # an empty cell
    ("1,2\n3 N,4\n", False),                      # a unit
])
def test_table_numbers_are_the_plain_floats_of_each_column(text, plain):
    """A chunk of plain numbers is read at once, each as ``_plain_floats`` reads its column
    (bit for bit); any other chunk gives None (and each column is read on its own)."""
    from dyncalc.batch.columns import _plain_floats

    chunk = source._Reader(_stream(text)).chunk(100)
    table = chunk.table(2, None)
    values = table.numbers()
    assert (values is not None) == plain
    if plain:
        for j in range(2):
            assert values[:, j].view(np.int64).tolist() == \
                _plain_floats(list(table[j])).view(np.int64).tolist()
        assert np.signbit(values[1, 0]) and values[2].tolist() == [4.0, 5.0]  # -0 as float


@pytest.mark.parametrize("columns, n", [(1, 5000), (100, 1000), (300, 700)])
def test_write_lines_in_steps_of_cells_writes_every_line_once(columns, n):
    """A wide result is assembled STEP_CELLS cells at a time (coriolis over times: 60-odd
    columns, memory flat): the lines are each row's ``repr``s joined, in order, whatever the
    step (1 column: 4096 lines a step; 100: 327; 300: the floor of 256)."""
    rng = np.random.default_rng(7)
    arrays = [rng.normal(size=n) * 10.0 ** rng.integers(-300, 300, size=n)
              for _ in range(columns)]
    words = [f"w{i}" for i in range(n)]
    parts = ["<"]
    for array in arrays:
        parts += [array, ","]
    parts += [words, ">"]
    out = io.StringIO()
    assemble.write_lines(out, parts, n)
    expected = ["<" + "".join(f"{float(a[i])!r}," for a in arrays) + f"w{i}>" for i in range(n)]
    assert out.getvalue() == "\n".join(expected) + "\n"
