"""The JSON ``text`` of an input entry a column at a time: a text with nothing for
``json.dumps`` to escape is written between quotes as it is (``dyncalc.batch.inputs``)."""
from __future__ import annotations

import json

from dyncalc.batch.inputs import _ESCAPED_RE, _unescaped


def test_the_escape_test_agrees_with_json_dumps_on_every_character():
    for code in range(0x110000):
        text = f"2 {chr(code)}m"
        plain = json.dumps(text) == f'"{text}"'
        assert plain is (_ESCAPED_RE.search(text) is None), hex(code)
        assert _unescaped(text) is plain, hex(code)  # the string methods' test, the same


def test_a_column_as_typed_is_written_as_each_cell_alone():
    """Texts shown as typed (blanks kept): between quotes as they are, or each cell through
    ``json.dumps`` where one needs escaping."""
    import numpy as np

    from dyncalc.batch.assemble import lines
    from dyncalc.batch.inputs import _number_parts

    class Read:
        def __init__(self, n):
            self.shown = np.arange(n, dtype=float)
            self.unit_json = [('"m"', ', "assumed_si": false')] * n

    for cells in ([" 2 m", "0.5 m "], ["2 µm", "3 m"], ['2 "m"', "1\\2"], ["2\tm", ""]):
        n = len(cells)
        parts = _number_parts("k", Read(n), cells, "", "as typed", np.ones(n, bool), n)
        want = [f'"k": {{"value": {float(i)!r}, "unit": "m", "text": {json.dumps(c)}, '
                f'"assumed_si": false}}' for i, c in enumerate(cells)]
        assert lines(parts, n) == want



def test_a_column_of_texts_is_written_as_each_cell_alone():
    """The ``text`` parts of a column (plain numbers under a header unit, cells with their own
    units, texts to escape, a cell holding a line break, a word, ``?``) against
    ``json.dumps`` of ``with_header_unit`` of each cell, the one-cell-at-a-time form."""
    import numpy as np

    from dyncalc.batch.header import with_header_unit
    from dyncalc.batch.inputs import _number_parts

    class Read:
        def __init__(self, n):
            self.shown = np.arange(n, dtype=float)
            self.unit_json = [('"m"', ', "assumed_si": false')] * n

    columns = [["2", "-1.5e3", "+.5"], ["2 m", " 3 km ", "4 m"], ['2 "m"', "3 µm", "1\\2"],
               ["2", "3\n4"], ["2", "x"], ["2", "?"], ["007", "1"]]
    for unit in ("", "N/m", "µm"):
        for cells in columns:
            n = len(cells)
            text = _number_parts("k", Read(n), cells, unit, False, np.ones(n, bool), n)[3:-1]
            want = [json.dumps(with_header_unit(c.strip(), unit)) for c in cells]
            if len(text) == 1:  # a text a cell
                assert text[0] == want
            else:  # '"', the cells, the tail and '"'
                assert ['"' + t + text[2] for t in text[1]] == want
