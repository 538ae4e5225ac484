"""``coriolis`` batch rows on the vectorised path: the command's column adapter
(:func:`~dyncalc.batch.fast_commands._command_fast`) and the perpendicular inverse problems
(a column ``a_c`` or ``F_c`` with ``?`` in the ``omega``, ``vr`` or ``mass`` column, as
``a_c=12m/s^2 --omega 2rad/s vr=?``), solved in closed form on columns
(:func:`~dyncalc.scenes.inverse_columns.closed_form_columns`) through the column kernel of
:func:`~dyncalc.physics.relative_motion.coriolis_perpendicular`. A probe row run by the
one-off must agree to the bit (values, order, model, method, ``extra``); the Earth's inverse
rows are :mod:`dyncalc.batch.fast_coriolis_earth`'s; every other row (a refusal, a value the
kernel does not take) runs the one-off."""
from __future__ import annotations

import json

import numpy as np

from ..errors import InputError
from .fast import FastBlock, _input_texts, json_head
from .fast_commands import _command_fast, _inputs, _read_rows, _same, _stripped
from .header import with_header_unit

#: The parameters of the perpendicular set-up and the results it solves from.
_PARAMS, _TARGETS = ("omega", "vr", "mass"), ("a_c", "F_c")


class _TargetParam:
    """A result column read as a quantity (what :func:`fast_commands._read` asks of it)."""

    kind, metavar, choices, constraint = "quantity", "Q", None, None

    def __init__(self, name: str, dim):
        self.name, self.dim = name, dim


class _View:
    """The run's spec with the result columns as parameters (for the column readers)."""

    def __init__(self, spec):
        self.spec, self.strict = spec, spec.strict

    def parameter(self, key):
        if key in _TARGETS:
            from ..result.kinds import result_kind

            return _TargetParam(key, result_kind(key).dim)
        return self.spec.parameter(key)

    def input_names(self, keys):
        return self.spec.input_names(keys)


def coriolis_fast(spec, columns, table, want_json: bool, cache: dict) -> list[FastBlock]:
    """The blocks of this chunk on the vectorised path: the forward rows, then the
    perpendicular inverse rows (:func:`_inverse_blocks`)."""
    blocks = _command_fast(spec, columns, table, want_json, cache)
    keys = {col.key for col in columns}
    if keys & set(_TARGETS) and keys <= set(_PARAMS) | set(_TARGETS) and table:
        blocks += _inverse_blocks(spec, columns, table, want_json, cache)
    return blocks


def _inverse_blocks(spec, columns, table, want_json: bool, cache: dict) -> list[FastBlock]:
    cells = {col.key: _stripped(table[col.index]) for col in columns}
    n = len(next(iter(cells.values())))
    targets = [col for col in columns if col.key in _TARGETS]
    if len(targets) != 1:
        return []
    target = targets[0]
    return asked_blocks(columns, _PARAMS, cells, n, lambda given, unknown, rows: _solved(
        spec, given, unknown, target, rows, cells, want_json, cache))


def asked_blocks(columns, unknowns, cells: dict, n: int, solve) -> list[FastBlock]:
    """The blocks of the rows that ask for one of the columns keyed in ``unknowns`` (``?`` in
    it) and give every other column: ``solve(given, unknown, rows)`` an unknown at a time."""
    blocks = []
    for unknown in (col for col in columns if col.key in unknowns):
        given = [col for col in columns if col is not unknown]
        mask = np.fromiter((c == "?" for c in cells[unknown.key]), dtype=bool, count=n)
        for col in given:
            mask &= np.fromiter((c not in ("", "?") for c in cells[col.key]), dtype=bool,
                                count=n)
        if mask.any():
            blocks += solve(given, unknown, np.flatnonzero(mask))
    return blocks


def _solved(spec, given, unknown, target, rows, cells, want_json, cache) -> list[FastBlock]:
    from ..physics.columns import kernel_of
    from ..physics.relative_motion import coriolis_perpendicular
    from ..scenes.coriolis_scalar import PERPENDICULAR
    from ..scenes.inverse_columns import closed_form_columns

    view = _View(spec)
    read = _read_rows(view, given, rows, cells, cache)
    if read is None:
        return []
    reads, arrays, good = read
    for value in arrays.values():
        good &= np.isfinite(value) & (value > 0.0)
    if not good.any():
        return []
    arguments = {key: np.where(good, value, 1.0) for key, value in arrays.items()
                 if key in _PARAMS}
    with np.errstate(all="ignore"):
        solved = closed_form_columns(PERPENDICULAR, kernel_of(coriolis_perpendicular),
                                     PERPENDICULAR.param(unknown.key), target.key, arguments,
                                     np.where(good, arrays[target.key], 1.0), {})
    if solved is None:
        return []
    exact = good & solved.exact
    blocks = []
    for exponent in sorted(set(solved.exponent[exact].tolist())):
        keep = np.flatnonzero(exact & (solved.exponent == exponent))
        values = {unknown.key: solved.x[keep]}
        values.update((name, array[keep]) for name, array in solved.out.values.items())
        extra = {"inverse": {"unknown": unknown.key, "method": "closed-form",
                            "detail": f"{target.key} is proportional to {unknown.key}^"
                                      f"({exponent}): inverted exactly"}}
        probe = _probe(spec, given, unknown, cells, int(rows[keep[0]]),
                       {name: array[0] for name, array in values.items()}, extra)
        if probe is None:
            continue
        head = texts = None
        if want_json:
            head = json_head("coriolis", probe.scene, probe.model, probe.method)
            texts = _input_texts(_inputs(view, given, reads, probe), keep, {})
        dims = {name: entry.dim for name, entry in probe.results.items()}
        blocks.append(FastBlock(rows[keep], values, dims, head, texts, json.dumps(extra)))
    return blocks


def _probe(spec, given, unknown, cells, row: int, values: dict, extra: dict):
    """The one-off Result of ``row`` where it is the block's to the bit, else ``None``."""
    texts = {col.key: with_header_unit(cells[col.key][row], col.unit) for col in given}
    texts[unknown.key] = "?"
    try:
        result = spec.compute(texts, {col.key: col.name for col in given})
    except InputError:
        return None
    if (result.warnings or list(result.results) != list(values)
            or json.dumps(result.extra) != json.dumps(extra)):
        return None
    for name, entry in result.results.items():
        if entry.uncertainty is not None or not _same(entry.si, values[name]):
            return None
    return result
