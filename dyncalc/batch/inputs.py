"""The ``inputs`` object of the vectorised path's JSON lines, as *parts* a column at a time
(:func:`dyncalc.batch.assemble.lines`): texts the rows share, float columns, text columns."""
from __future__ import annotations

import json
import re

import numpy as np

from .header import _PLAIN_RE, with_header_unit

_PLAIN = _PLAIN_RE.pattern

#: A character ``json.dumps`` writes escaped (``"``, ``\\``, and all but printable ASCII):
#: a text without one is written as ``"`` + text + ``"``.
_ESCAPED_RE = re.compile(r'["\\\\]|[^ -~]')


def _unescaped(text: str) -> bool:
    """Whether ``json.dumps`` writes ``text`` as it is between quotes: no character of
    :data:`_ESCAPED_RE` (printable ASCII is what ``isascii`` and ``isprintable`` both take),
    found by C loops over the text instead of a regular expression.

    >>> _unescaped("2 m"), _unescaped('2"'), _unescaped("2 µm"), _unescaped("2\\tm")
    (True, False, False, False)
    """
    return text.isascii() and text.isprintable() and '"' not in text and "\\" not in text


#: Cells that are each a plain number (``with_header_unit`` appends the header's unit).
_PLAIN_LINES_RE = re.compile(rf"{_PLAIN}(?:\n{_PLAIN})*")


def input_parts(inputs, keep: np.ndarray, words: dict) -> list:
    """The parts of each kept row's ``inputs`` object text (without the braces), in the
    scene's parameter order. ``inputs`` holds ``(name, read, cells, header unit, plain
    column, word entry)`` of each parameter (:func:`dyncalc.batch.fast._scene_block`); for
    "plain column", ``(before, after)``: the cells are number literals, each shown between
    these texts (:func:`dyncalc.batch.fast_springs._uniform`), ``"as typed"``: the cells
    shown as they are (no header unit, blanks kept)."""
    parts: list = []
    n = len(keep)
    for name, read, column, header_unit, plain_column, entry in inputs:
        if parts:
            parts.append(", ")
        if entry is not None:  # a word: the same for every row of the block
            parts.append(f'{entry}, "text": {json.dumps(words[name])}}}')
        elif isinstance(read, str):
            parts.append(read)
        elif hasattr(read, "parts"):  # words or vectors (dyncalc.batch.fast_commands)
            parts.extend(read.parts(name, keep))
        else:
            parts.extend(_number_parts(name, read, column, header_unit, plain_column, keep, n))
    return parts


def _number_parts(name, read, column, header_unit, plain_column, keep, n) -> list:
    every = n == len(read.shown)
    shown = read.shown if every else read.shown[keep]
    unit_json = read.unit_json if every else [read.unit_json[i] for i in keep.tolist()]
    typed = column if every else [column[i] for i in keep.tolist()]
    prefix = json.dumps(name) + ': {"value": '
    if isinstance(plain_column, tuple):  # number literals, each between these texts
        before, after = (json.dumps(t)[1:-1] for t in plain_column)
        text = ['"' + before, typed, after + '"']
    elif plain_column == "as typed":  # the cells' texts as they are
        text = ['"', typed, '"'] if _unescaped("".join(typed)) \
            else [[json.dumps(c) for c in typed]]
    elif plain_column:  # plain numbers: the text is the cell and the header's unit
        suffix = json.dumps(" " + header_unit)[1:-1] if header_unit else ""
        joined = "".join(typed)
        if " " in joined or "\t" in joined:
            typed = [c.strip() for c in typed]
        text = ['"', typed, suffix + '"']
    else:
        texts = [c.strip() for c in typed]
        lines = "\n".join(texts)
        if header_unit and lines.count("\n") == len(texts) - 1 \
                and _PLAIN_LINES_RE.fullmatch(lines):
            texts, tail = texts, " " + header_unit  # with_header_unit of a plain number
        elif header_unit:
            texts, tail = [with_header_unit(c, header_unit) for c in texts], ""
        else:
            texts, tail = texts, ""
        text = ['"', texts, tail + '"'] if _unescaped("".join(texts) + tail) \
            else [[json.dumps(c + tail) for c in texts]]
    if unit_json and unit_json.count(unit_json[0]) == len(unit_json):
        unit, assumed = unit_json[0]
        return [prefix, np.asarray(shown, dtype=np.float64), ', "unit": ' + unit + ', "text": ',
                *text, assumed + "}"]
    units = [f', "unit": {u}, "text": ' for u, _a in unit_json]
    assumed = [a + "}" for _u, a in unit_json]
    return [prefix, np.asarray(shown, dtype=np.float64), units, *text, assumed]
