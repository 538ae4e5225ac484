"""``rigid-body --scene NAME --batch`` rows on the vectorised path: the forward rows through
the scene's column adapter (:func:`~dyncalc.batch.fast_commands._command_fast`), and the
inverse rows (a result column such as ``alpha`` and one parameter left out or given as ``?``,
as ``alpha=3rad/s^2 J_A=?``) whose result is a power of the unknown, solved in closed form on
columns (:func:`~dyncalc.scenes.inverse_columns.closed_form_columns`) through the scene's
column kernel (:mod:`dyncalc.physics.kinetics_columns`), or, where the result is monotone in
the unknown, by the one-off's bracketed search on columns
(:func:`~dyncalc.scenes.inverse_monotone.monotone_columns`), the one-off's steps bit for bit.
The first row of each block is also run by the one-off (a probe) and must agree to the bit
(values, order, model, method, ``extra``). Every other row (another bracketed search, a
refusal, a warning, a row the kernel cannot certify) runs the one-off."""
from __future__ import annotations

import json

import numpy as np

from ..errors import InputError
from .fast import FastBlock, _by_columns_given, _input_texts, json_head
from .fast_commands import _by_words, _command_fast, _inputs, _read_rows, _same, _stripped
from .header import with_header_unit


class _TargetParam:
    """A result column read as a quantity (what :func:`fast_commands._read` asks of it)."""

    kind, metavar, choices, constraint = "quantity", "Q", None, None

    def __init__(self, name: str, dim):
        self.name, self.dim = name, dim


class _View:
    """The run's spec with the scene's result columns read as quantities."""

    def __init__(self, spec, scene):
        self.spec, self.scene, self.strict = spec, scene, spec.strict

    def parameter(self, key):
        if self.scene.param(key) is None and key in self.scene.kinds:
            return _TargetParam(key, self.scene.kinds[key].dim)
        return self.spec.parameter(key)

    def input_names(self, keys):
        return self.spec.input_names(keys)


def rigid_fast(spec, columns, table, want_json: bool, cache: dict) -> list[FastBlock]:
    """The blocks of this chunk on the vectorised path: the forward rows, then the inverse
    rows (:func:`_inverse_blocks`) where a column gives one of the scene's results."""
    from ..scenes import get_scene

    blocks = _command_fast(spec, columns, table, want_json, cache)
    scene = get_scene(spec.settings["scene"])
    if table and any(scene.param(c.key) is None and c.key in scene.kinds for c in columns):
        blocks += _inverse_blocks(spec, scene, columns, table, want_json, cache)
    return blocks


def _inverse_blocks(spec, scene, columns, table, want_json, cache) -> list[FastBlock]:
    if len(columns) > 31:
        return []
    cells = {col.key: _stripped(table[col.index]) for col in columns}
    n = len(cells[columns[0].key])
    keys, present = [], []
    for col in columns:
        column = cells[col.key]
        asked = np.fromiter((c == "?" for c in column), dtype=bool, count=n)
        keys += [col, ("?", col)]
        present += [np.fromiter((c != "" for c in column), dtype=bool, count=n) & ~asked,
                    asked]
    blocks = []
    for given, rows in _by_columns_given(keys, present):
        asked = [k[1] for k in given if isinstance(k, tuple)]
        given = [k for k in given if not isinstance(k, tuple)]
        targets = [c for c in given if scene.param(c.key) is None]
        if len(targets) != 1 or len(asked) > 1 or targets[0].key not in scene.kinds \
                or (asked and scene.param(asked[0].key) is None):
            continue
        unknown = _unknown(scene, [c.key for c in given], asked)
        if unknown is None:
            continue
        view = _View(spec, scene)
        for subset in _by_words(view, given, rows, cells):
            blocks += _solved(spec, view, scene, given, unknown, targets[0],
                              asked[0] if asked else None, subset, cells, want_json, cache)
    return blocks


def _unknown(scene, given: list[str], asked: list):
    """The parameter solved for (asked as ``?`` or the one required left out), or ``None``
    where the one-off would refuse the rows or they are not a number to solve for."""
    missing = [p.name for p in scene.params if p.name not in given and p.default is None
               and not p.optional]
    if asked:
        name = asked[0].key
        missing = [m for m in missing if m != name]
    elif len(missing) == 1:
        name, missing = missing[0], []
    else:
        return None
    unknown = scene.param(name)
    if missing or unknown.dim is None:
        return None
    return unknown


def _solved(spec, view, scene, given, unknown, target, asked, rows, cells, want_json,
            cache) -> list[FastBlock]:
    from ..commands.rigid_columns import _defaults, _kernel, _words
    from ..scenes.inverse_columns import closed_form_columns
    from ..scenes.inverse_monotone import DETAIL, monotone_columns

    kernel = _kernel(scene)
    params = [c for c in given if c is not target]
    try:
        defaults = _defaults(scene, {*(c.key for c in params), unknown.name})
        words = _words(scene, {c.key: [cells[c.key][i] for i in rows[:1].tolist()]
                               for c in params if scene.param(c.key).choices is not None})
    except InputError:
        return []
    if kernel is None or any(c.unit for c in params if scene.param(c.key).choices is not None):
        return []
    read = _read_rows(view, given, rows, cells, cache)
    if read is None:
        return []
    reads, arrays, good = read
    m = len(rows)
    arguments = {name: np.full(m, value) for name, value in {**defaults, **words}.items()}
    for col in params:
        param = scene.param(col.key)
        if param.choices is not None:
            continue
        value = np.asarray(arrays[col.key], dtype=float)
        good &= np.isfinite(value)
        if param.constraint == "positive":
            good &= value > 0.0
        elif param.constraint == "nonnegative":
            good &= value >= 0.0
        arguments[col.key] = value
    goal = np.asarray(arrays[target.key], dtype=float)
    good &= np.isfinite(goal)
    if not good.any():
        return []
    arguments = {k: np.where(good, v, 1.0) for k, v in arguments.items()}
    goal = np.where(good, goal, 1.0)
    with np.errstate(all="ignore"):
        solved = closed_form_columns(scene, kernel, unknown, target.key, arguments, goal, {})
    blocks, taken = [], np.zeros(m, dtype=bool)
    block = (spec, view, given, asked, unknown, reads, rows, cells, want_json)
    if solved is not None:
        taken = good & solved.exact
        for exponent in sorted(set(solved.exponent[taken].tolist())):
            keep = np.flatnonzero(taken & (solved.exponent == exponent))
            detail = f"{target.key} is proportional to {unknown.name}^({exponent}): " \
                     "inverted exactly"
            blocks += _block(*block, solved, keep, "closed-form", detail)
    rest = np.flatnonzero(good & ~taken)
    if len(rest):
        bracketed = monotone_columns(scene, kernel, unknown, target.key,
                                     {k: v[rest] for k, v in arguments.items()}, goal[rest])
        if bracketed is not None and bracketed.exact.any():
            keep = np.flatnonzero(bracketed.exact)
            blocks += _block(*block, bracketed, keep, "bracketed-root",
                             DETAIL.format(unknown.name), at=rest)
    return blocks


def _block(spec, view, given, asked, unknown, reads, rows, cells, want_json, solved, keep,
           method: str, detail: str, at=None) -> list[FastBlock]:
    """The block of the rows ``keep`` of ``solved`` (rows ``at[keep]`` of the chunk's
    ``rows``, ``at`` all of them if ``None``), solved by ``method``; none where the one-off's
    probe of its first row differs."""
    where = keep if at is None else at[keep]
    values = {unknown.name: solved.x[keep]}
    values.update((name, array[keep]) for name, array in solved.out.values.items())
    extra = {"inverse": {"unknown": unknown.name, "method": method, "detail": detail}}
    probe = _probe(spec, given, asked, cells, int(rows[where[0]]),
                   {name: array[0] for name, array in values.items()}, extra, solved.out)
    if probe is None:
        return []
    head = texts = None
    if want_json:
        head = json_head("rigid-body", probe.scene, probe.model, probe.method)
        texts = _input_texts(_inputs(view, given, reads, probe), where, {})
    dims = {name: entry.dim for name, entry in probe.results.items()}
    return [FastBlock(rows[where], values, dims, head, texts, json.dumps(extra))]


def _probe(spec, given, asked, cells, row: int, values: dict, extra: dict, out):
    """The one-off Result of ``row`` (its cells in column order, the ``?`` one included)
    where it is the block's to the bit, else ``None``."""
    ordered = sorted([*given, *([asked] if asked is not None else [])], key=lambda c: c.index)
    texts = {col.key: "?" if col is asked else with_header_unit(cells[col.key][row], col.unit)
             for col in ordered}
    try:
        result = spec.compute(texts, {col.key: col.name for col in given})
    except InputError:
        return None
    if (result.warnings or list(result.results) != list(values) or result.model != out.model
            or result.method != out.method or json.dumps(result.extra) != json.dumps(extra)):
        return None
    for name, entry in result.results.items():
        if entry.uncertainty is not None or not _same(entry.si, values[name]):
            return None
    return result
