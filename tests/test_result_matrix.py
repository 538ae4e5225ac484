"""Matrix (2-D) results: the human form, ``--value`` text, JSON nested lists, unit conversion.

The numbers are checked against the matrix's own entries and the exact factor between kg*m^2
and g*cm^2 (10^7)."""
import numpy as np

from dyncalc.result.encode import _json_value, batch_cell, full_number
from dyncalc.result.entries import Entry, format_number
from dyncalc.units import INERTIA

J = np.array([[1.5, -0.25, 0.0], [-0.25, 2.0, 0.0], [0.0, 0.0, 3.125]])


def test_human_form_is_nested_brackets():
    assert format_number(J, 3) == ("[[1.5, -0.25, 0], [-0.25, 2, 0], [0, 0, 3.12]]")


def test_value_text_rows_by_semicolon_components_by_comma():
    assert full_number(J) == "1.5,-0.25,0.0;-0.25,2.0,0.0;0.0,0.0,3.125"
    rows = [[float(c) for c in row.split(",")] for row in full_number(J).split(";")]
    assert np.array_equal(np.array(rows), J)


def test_json_is_nested_lists_with_null_for_non_finite():
    value = J.copy()
    value[2, 2] = np.inf
    assert _json_value(value) == [[1.5, -0.25, 0.0], [-0.25, 2.0, 0.0], [0.0, 0.0, None]]


def test_matrix_converts_entry_by_entry():
    entry = Entry("J_C", J, INERTIA, unit="kg*m^2")
    assert np.allclose(entry.value_in("g*cm^2"), J * 1e7, rtol=1e-15, atol=0)
    assert batch_cell(entry, "kg*m^2") == full_number(J)
