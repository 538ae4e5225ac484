"""Opening the ``--batch`` source (a file, ``-``, a FIFO) and reading its records in chunks."""
from __future__ import annotations

import csv
import io
import itertools
import operator
import re
import sys

from ..errors import InputError
from .cells import Table, _quoted_columns, _simple_quotes, _unquoted, _without_quotes
from .csvlines import _csv_lines


def open_source(source: str):
    """The CSV text stream of ``--batch SOURCE`` (``-``: standard input): UTF-8, with or
    without a byte-order mark, any line ending."""
    if source == "-":
        raw = getattr(sys.stdin, "buffer", sys.stdin)
    else:
        try:
            raw = open(source, "rb")  # noqa: SIM115 (closed by run_batch)
        except OSError as exc:
            raise InputError(f"--batch: cannot read {source!r}: "
                             f"{exc.strerror or exc}") from None
    # bytes that are not UTF-8 are kept as lone surrogates, so that the row holding them is
    # refused with its line number and the other rows go on
    return io.TextIOWrapper(raw, encoding="utf-8-sig", newline="", errors="surrogateescape")


#: Characters that make a chunk need the csv module: quotes, and line breaks that
#: ``str.splitlines`` knows but CSV does not.
_NEEDS_CSV_RE = re.compile('["\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029]')
_NEEDS_CSV_ASCII = ('"', "\x0b", "\x0c", "\x1c", "\x1d", "\x1e")
#: The same without the quote: what the block reader hands over for, even with simple quotes.
_ODD_LINE_BREAK_RE = re.compile("[\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029]")
_ODD_LINE_BREAK_ASCII = _NEEDS_CSV_ASCII[1:]
#: Lines whose every quote opens or closes a whole cell on its line (``"0,0,1"``, no quote or
#: line break inside, none in an unquoted cell, no NUL): the csv module reads each line as
#: one record, never fails, and needs no look at the next line. (The definition:
#: ``cells._simple_quotes`` finds the same without a regex pass, tests/test_batch_quotes.py.)
_CELL = '(?:"[^"\r\n\0]*"|[^",\r\n\0]*+)'
_SIMPLE_QUOTES_RE = re.compile(f"{_CELL}(?:,{_CELL})*+\r?(?:\n{_CELL}(?:,{_CELL})*+\r?)*+")
#: A quoted cell without a comma (which ``csv.writer`` would not quote), in simple quotes.
_QUOTED_NO_COMMA_RE = re.compile('"[^",\r\n\0]*"')
#: Bytes that were not UTF-8, kept by the ``surrogateescape`` decoding; and ``_TOO_LONG``, the
#: line that stands for a line longer than :data:`MAX_LINE` (a lone surrogate that decoding
#: never produces).
_NOT_UTF8_RE = re.compile("[\udc00\udc80-\udcff]")
_TOO_LONG = "\udc00"
#: Characters a line may hold; a longer one is refused without being held in memory.
MAX_LINE = 100_000


#: Characters of one over-long line skipped at most, looking for its end; a source with a
#: longer line is not CSV text (``/dev/zero``, a binary file) and its reading ends there.
MAX_SKIP = 1 << 24


class NotText(Exception):
    """The source is not CSV text: an endless line, or a long line of NUL bytes."""


def _bounded_lines(stream, limit: int = MAX_LINE, skip: int = MAX_SKIP):
    """The lines of ``stream``, each read ``limit + 1`` characters at most: a longer line is
    skipped to its end and yields ``_TOO_LONG`` in its place (so the line numbers hold). A
    long line that holds a NUL, or has no end within ``skip`` characters, raises
    :class:`NotText`: a binary source is refused at once, never read to its end."""
    while line := stream.readline(limit + 1):
        if len(line) <= limit or line.endswith(("\n", "\r")):
            yield line
            continue
        if "\0" in line:
            raise NotText(f"the line is longer than {limit} characters and holds NUL bytes: "
                          "this is not a CSV text file")
        skipped = len(line)
        while (rest := stream.readline(limit)) and not rest.endswith(("\n", "\r")):
            skipped += len(rest)
            if skipped > skip:
                raise NotText(f"the line is longer than {skip} characters: this is not a "
                              "CSV text file")
        yield _TOO_LONG + "\n"


#: Characters read from the source at a time (the block reader of :class:`_Reader`).
BLOCK = 1 << 20
#: Characters the block reader holds at most while gathering a chunk's lines; a chunk that
#: would need more (long lines) is read line by line instead.
MAX_BUFFER = 1 << 24


class _Buffered:
    """A stream's text already read (``text``) followed by the rest of the stream: what
    ``readline(size)`` of the stream itself would give (line ends ``\\n``, ``\\r\\n``, ``\\r``;
    ``text`` never ends in a ``\\r`` whose ``\\n`` is still in the stream). An error met while
    reading ahead (``error``) is raised where the stream raised it: after ``text``."""

    def __init__(self, text: str, stream, error: OSError | None = None):
        self.text, self.pos, self.stream, self.error = text, 0, stream, error

    def readline(self, size: int = -1) -> str:
        text, pos = self.text, self.pos
        if pos >= len(text):
            if self.error is not None:
                error, self.error = self.error, None
                raise error
            return self.stream.readline(size)
        stop = len(text) if size < 0 else min(len(text), pos + size)
        match = _LINE_END_RE.search(text, pos, stop)
        if match is not None:
            end = match.end()
            if match.group() == "\r" and end == stop and end < len(text) and text[end] == "\n":
                end = stop  # a "\r" at the size limit: the "\n" is the next call's, as readline
            self.pos = end
            return text[pos:end]
        self.pos = stop
        line = text[pos:stop]
        if stop == len(text) and (size < 0 or len(line) < size) and self.error is None:
            line += self.stream.readline(-1 if size < 0 else size - len(line))
        return line


_LINE_END_RE = re.compile("\r\n|\r|\n")


class _Chunk:
    """Consecutive records of the CSV: the line each starts on (``numbers``), and either the
    text lines of a chunk without quotes (``lines``: each is one record, split at commas), the
    lines of a chunk in simple quotes that ``csv.writer`` writes as they are (``lines``, and
    ``plain``: the same lines without their quotes, each comma inside a quoted cell a NUL, so
    that they too are split at commas), the lines of a chunk whose every cell is quoted (and
    written so by ``csv.writer``) with their cells column by column (``lines`` and
    ``columns``), or the records the csv module read (``rows``)."""

    __slots__ = ("numbers", "lines", "rows", "not_utf8", "written", "plain", "columns", "text")

    def __init__(self, numbers, *, lines=None, rows=None, suspect: bool = False,
                 written=None, plain=None, columns=None, text=None):
        self.numbers, self.lines, self.rows = numbers, lines, rows
        #: the lines joined by line breaks, if the reader has them so (else None)
        self.text = text
        #: the lines of ``rows`` when they are what ``csv.writer`` writes for them (else None)
        self.written = written
        self.plain = lines if plain is None else plain
        self.columns = columns
        #: rows refused before reading their cells: index -> why
        self.not_utf8: dict[int, str] = {}
        if suspect:
            records = lines if lines is not None else map(",".join, rows)
            self.not_utf8 = {
                i: (f"the line is longer than {MAX_LINE} characters" if _TOO_LONG in text
                    else "the line is not UTF-8 text")
                for i, text in enumerate(records) if _NOT_UTF8_RE.search(text)}

    def __len__(self) -> int:
        return len(self.numbers)

    def row(self, i: int) -> list[str]:
        if self.rows is not None:
            return self.rows[i]
        if self.columns is not None:
            return [column[i] for column in self.columns]
        cells = self.plain[i].split(",")
        return cells if self.plain is self.lines else [c.replace("\0", ",") for c in cells]

    def widths(self) -> list[int]:
        """The number of cells of each row (in a chunk split at commas, one more than its
        commas: one less than what is given)."""
        if self.rows is not None:
            return list(map(len, self.rows))
        if self.columns is not None:
            return [len(self.columns) - 1] * len(self.lines)
        return list(map(str.count, self.plain, itertools.repeat(",")))

    def table(self, width: int, keep: list[int] | None):
        """The cells column by column, of all rows (``keep`` None) or of the rows ``keep``;
        they all have ``width`` cells."""
        if self.rows is not None:
            return list(zip(*(self.rows if keep is None else [self.rows[i] for i in keep])))
        if self.columns is not None:
            return self.columns if keep is None else [[column[i] for i in keep]
                                                      for column in self.columns]
        lines = self.plain if keep is None else [self.plain[i] for i in keep]
        if not lines:
            return [[] for _ in range(width)]

        def split() -> list[list[str]]:
            flat = ",".join(lines).split(",")
            columns = [flat[j::width] for j in range(width)]
            if self.plain is not self.lines:  # the commas of quoted cells, back
                columns = [_unquoted(column) for column in columns]
            return columns

        def cell(i: int, j: int) -> str:
            text = lines[i].split(",")[j]
            return text if self.plain is self.lines else text.replace("\0", ",")

        text = None
        if self.plain is self.lines:
            text = self.text if keep is None and self.text is not None else "\n".join(lines)
        return Table(split, len(lines), width, text, cell)

    def echo(self, keep: list[int] | None) -> list[str]:
        """The rows (all, or ``keep``) as CSV lines, as ``csv.writer`` writes them."""
        if self.rows is None or self.written is not None:  # the line is its CSV
            lines = self.lines if self.rows is None else self.written
            return lines if keep is None else [lines[i] for i in keep]
        return _csv_lines(self.rows if keep is None else [self.rows[i] for i in keep])


class _Reader:
    """The CSV's records a chunk at a time, with the line each starts on (the header is line
    1). A chunk without quotes is split at commas directly (what the csv module does, faster);
    one with quotes goes through the csv module, which reads on past the chunk's lines to
    finish a quoted cell that holds line breaks. A record the csv module cannot read, or an
    I/O error (a failing disk, a broken pipe), ends the reading, with ``fatal`` set to its
    message; the records read before it are still handed out. Lines longer than
    :data:`MAX_LINE` are refused one by one (:func:`_bounded_lines`)."""

    def __init__(self, stream):
        self.source = stream
        self.stream = None  # the lines one at a time, once the block reader has handed over
        self.buffer = ""    # text read ahead by the block reader
        self.eof = False
        self.error: OSError | None = None
        self.last = 0      # lines read so far
        self.fatal: str | None = None
        self.done = False

    def chunk(self, size: int) -> _Chunk | None:
        if self.done:
            return None
        if self.stream is None:
            chunk = self._block_chunk(size)
            if chunk is not _BY_LINE:
                return chunk
            self.stream = _bounded_lines(_Buffered(self.buffer, self.source, self.error))
            self.buffer, self.error = "", None
        raw: list[str] = []
        try:
            raw.extend(itertools.islice(self.stream, size))  # keeps the lines read before
        except OSError as exc:  # a disk or pipe error: the lines before it are computed
            self._failed(self.last + len(raw) + 1, exc)
        except NotText as exc:
            self._not_text(self.last + len(raw) + 1, exc)
        if len(raw) < size:
            self.done = True
        if not raw:
            return None
        text = "".join(raw)
        ascii_only = text.isascii()
        suspect = not ascii_only and _NOT_UTF8_RE.search(text) is not None
        start = self.last + 1
        if not (any(c in text for c in _NEEDS_CSV_ASCII) if ascii_only
                else _NEEDS_CSV_RE.search(text)):
            lines = text.splitlines()
            self.last += len(lines)
            return _Chunk(list(range(start, start + len(lines))), lines=lines, suspect=suspect)
        # strict: a quote left open at the end, or text after a closing quote, is refused
        reader = csv.reader(itertools.chain(raw, self.stream), strict=True)
        rows, numbers = [], []
        try:
            while reader.line_num < len(raw):
                row = next(reader, None)
                if row is None:
                    break
                rows.append(row)
                numbers.append(start)
                start = self.last + reader.line_num + 1
        except csv.Error as exc:
            self.fatal = f"line {self.last + reader.line_num}: cannot read the CSV: {exc}"
            self.done = True
        except OSError as exc:
            self._failed(self.last + reader.line_num + 1, exc)
        except NotText as exc:
            self._not_text(self.last + reader.line_num + 1, exc)
        if reader.line_num > len(raw) and not self.fatal:
            self.done = False  # a quoted cell ran on past the chunk's lines: more may follow
        self.last += reader.line_num
        return _Chunk(numbers, rows=rows, suspect=suspect) if rows else None

    def _block_chunk(self, size: int):
        """The next ``size`` lines read a block at a time and split at once: the common file
        (``\\n`` or ``\\r\\n`` line ends, no quotes, lines within :data:`MAX_LINE`), or
        ``_BY_LINE`` where the lines must be read one at a time (:func:`_bounded_lines`, the
        csv module): the text read ahead is handed over, so nothing is lost or read twice."""
        buffer = self.buffer
        count = buffer.count("\n")
        while count < size and not self.eof and self.error is None:
            if len(buffer) > MAX_BUFFER:
                self.buffer = buffer
                return _BY_LINE
            try:
                block = self.source.read(BLOCK)
            except OSError as exc:  # raised again after the lines before it, as line by line
                self.error = exc
                break
            if not block:
                self.eof = True
                break
            while block.endswith("\r"):  # its "\n" may be the next block's first character
                more = self.source.read(1)
                if not more:
                    break
                block += more
            buffer += block
            count += block.count("\n")
        self.buffer = buffer
        if self.error is not None and count < size:
            return _BY_LINE
        if not self.eof and count < size:
            return _BY_LINE
        parts = buffer.split("\n", size)
        if len(parts) > size:
            rest = parts.pop()
        else:  # the end of the file: the text after the last line end is a line, if any
            rest = ""
            if parts[-1] == "":
                parts.pop()
        if not parts:
            self.done = True
            return None
        text = "\n".join(parts)
        ended = text + "\n"  # every part ends a line (the last may end in "\r", of "\r\n")
        quoted = '"' in text
        columns = None
        if quoted and "\0" not in text:  # every cell quoted (vectors): split at the quotes
            columns = _quoted_columns(text if "\r" not in text
                                      else ended.replace("\r\n", "\n")[:-1], len(parts))
        pieces = _simple_quotes(text) if quoted and columns is None else None
        if ((quoted and columns is None and pieces is None)
                or "\r" in text and text.count("\r") != ended.count("\r\n")
                or max(map(len, parts)) >= MAX_LINE
                or (_ODD_LINE_BREAK_RE.search(text) if not text.isascii()
                    else any(c in text for c in _ODD_LINE_BREAK_ASCII))):
            return _BY_LINE
        lines = ended.replace("\r\n", "\n").split("\n")[:-1] if "\r" in text else parts
        self.buffer = rest
        if len(parts) < size:
            self.done = True
        suspect = not text.isascii() and _NOT_UTF8_RE.search(text) is not None
        start = self.last + 1
        self.last += len(lines)
        numbers = list(range(start, start + len(lines)))
        if quoted:  # simple quotes: the csv module on the whole block, one record a line
            # quotes exactly where csv.writer puts them (around cells holding a comma): the
            # lines are the echo
            if columns is not None:
                return _Chunk(numbers, lines=lines, suspect=suspect, columns=columns)
            # (a quoted cell without a comma, which csv.writer would not quote: no echo)
            written = lines if all(map(operator.contains, pieces[1::2], itertools.repeat(","))) \
                else None
            plain = None
            if written is not None:  # (the quotes' pieces of the text split once, without \r)
                plain = _without_quotes(lines, text, pieces) if "\r" not in text else \
                    _without_quotes(lines, "\n".join(lines))
            if plain is not None:  # split at commas, as a chunk without quotes
                return _Chunk(numbers, lines=lines, suspect=suspect, plain=plain)
            return _Chunk(numbers, rows=list(csv.reader(lines, strict=True)), suspect=suspect,
                          written=written)
        return _Chunk(numbers, lines=lines, suspect=suspect,
                      text=text if lines is parts else None)

    def _failed(self, line: int, exc: OSError) -> None:
        self.fatal = f"line {line}: reading the file failed: {exc.strerror or exc}"
        self.done = True

    def _not_text(self, line: int, exc: NotText) -> None:
        self.fatal = f"line {line}: {exc}"
        self.done = True


#: What :meth:`_Reader._block_chunk` returns where the lines must be read one at a time.
_BY_LINE = object()
