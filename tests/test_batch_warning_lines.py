"""The ``warning:`` lines of a vectorised block that covers its whole chunk are made by joining
the line numbers around each warning made one line once (batch/write._same_warnings); they must
be exactly what the general path writes: ``one_line`` of each whole message, sorted by row and
then by warning."""
from hypothesis import given, settings, strategies as st

from dyncalc.batch.write import _same_warnings
from dyncalc.errors import one_line

_TEXT = st.text(alphabet=st.sampled_from(list("ab :;\n\t\x1b\x7f\u00e9\u202e  ")), max_size=12)


def _general(lines, warnings):
    rows = sorted((i, w) for i in range(len(lines)) for w in warnings)
    return "\n".join(one_line(f"warning: line {lines[i]}: {w}") for i, w in rows)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.integers(2, 10**7), min_size=1, max_size=20),
       st.lists(_TEXT, min_size=1, max_size=3))
def test_joined_warning_lines_equal_one_line_of_each_message(lines, warnings):
    assert _same_warnings(lines, sorted(warnings)) == _general(lines, warnings)


def test_a_blank_warning_and_a_spaced_one():
    assert _same_warnings([2, 3], ["  ", " a  b\nc "]) == (
        "warning: line 2:\nwarning: line 2: a b c\nwarning: line 3:\nwarning: line 3: a b c")
    assert _same_warnings(range(5, 7), ["x"]) == "warning: line 5: x\nwarning: line 6: x"
