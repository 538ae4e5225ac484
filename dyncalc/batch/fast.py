"""The vectorised path: whole chunks of rows through the column kernels of the physics
(:mod:`dyncalc.physics.columns`): every ``natural-frequency`` scene whose physics function has
one, on the rows its kernel marks exact."""
from __future__ import annotations

import json
from typing import Any

import numpy as np

from ..errors import InputError
from ..physics.columns import kernel_of
from ..physics.numerics import finite_nonzero
from ..physics.outcome import damped_arrays
from .cells import Table
from .columns import _plain_floats, _read_column
from .header import Column
from .inputs import input_parts as _input_texts


class FastBlock:
    """Rows of a chunk computed together: their positions in the chunk, the result arrays (SI,
    in the order the one-off gives them; vectors as rows of an (n, 3) array, words as str
    arrays) and their dimensions (``None`` for words), and for JSON the constant part of each
    line (``head``), each row's ``inputs`` object text and the ``extra`` object text (or
    its parts, where rows differ: :attr:`~dyncalc.physics.columns.Columns.extras`);
    ``warnings``: the one-off's warnings, the same on every row of the block, or with
    ``row_warnings`` (a list of tuples of texts, one a row) each row's own."""

    __slots__ = ("rows", "values", "dims", "head", "inputs", "extra", "warnings",
                 "row_warnings")

    def __init__(self, rows, values, dims, head, inputs, extra="{}", warnings=(),
                 row_warnings=None):
        self.rows, self.values, self.dims, self.head, self.inputs, self.extra = (
            rows, values, dims, head, inputs, extra)
        self.warnings = tuple(warnings)
        self.row_warnings = row_warnings

    def warned_rows(self):
        """``(row, warning)`` of every warning of the block, in row order (each row's in the
        one-off's order)."""
        if self.row_warnings is not None:
            return [(i, w) for i, texts in zip(self.rows.tolist(), self.row_warnings)
                    for w in texts]
        return [(i, w) for i in self.rows.tolist() for w in self.warnings]

    def warns(self) -> bool:
        """Whether any row of the block has a warning."""
        if self.row_warnings is not None:
            return any(self.row_warnings)
        return bool(self.warnings)


def json_head(command: str, scene: str | None, model: str, method: str) -> str:
    """The part of a block's JSON lines every line shares, after ``line``: the schema,
    command, scene, model and method members (contract v2's order)."""
    return (f'"schema": "dyncalc/2", "command": {json.dumps(command)}, '
            f'"scene": {json.dumps(scene)}, "model": {json.dumps(model)}, '
            f'"method": {json.dumps(method)}')


def _default_input(p, strict: bool, cache: dict):
    """(SI value, JSON text of the input entry) of a scene parameter's default."""
    key = ("default", p.name, p.default, strict)
    if key not in cache:
        from ..units import parse_quantity

        parsed = parse_quantity(p.default, p.dim, label=p.name, strict=strict,
                                constraint=p.constraint)
        shown = float(parsed.quantity.magnitude) if parsed.unit_text else parsed.si
        text = json.dumps({p.name: {"value": shown, "unit": parsed.unit_text or p.dim.si,
                                    "text": p.default}})
        cache[key] = (parsed.si, text[1:-1])
    return cache[key]


def _natural_frequency_fast(spec, columns: list[Column], table, want_json: bool,
                            cache: dict) -> list[FastBlock]:
    """The rows of this chunk the vectorised path computes, as blocks (one per scene, set of
    parameters given and choice words); every other row is left to the generic path. ``spec``
    is the run's :class:`~dyncalc.batch.rows.NaturalFrequencyRows` (which names this function
    its ``fast`` path); ``table`` holds the chunk's cells column by column."""
    if not table or len(columns) > 62:
        return []
    n = table.n if isinstance(table, Table) else len(table[0])
    # every cell a plain number: the values at once, the texts split only if needed (JSON)
    numbers = table.numbers() if isinstance(table, Table) else None
    present: dict[str, np.ndarray] = {}
    cells: dict[str, Any] = {}
    plain: dict[str, np.ndarray | None] = {}
    for col in columns:
        if numbers is not None:
            plain[col.key] = np.ascontiguousarray(numbers[:, col.index])
            present[col.key] = np.ones(n, dtype=bool)
            cells[col.key] = table[col.index] if want_json else table.later(col.index)
            continue
        column = table[col.index]
        values = _plain_floats(column)
        plain[col.key] = values
        if values is not None:
            present[col.key] = np.ones(n, dtype=bool)
            cells[col.key] = column
            continue
        column = [c.strip() for c in column]
        cells[col.key] = column
        present[col.key] = np.fromiter((c != "" for c in column), dtype=bool, count=n)
        if "?" in column:  # the unknown of an inverse problem (``k=?``): not a value given
            asked = np.fromiter((c == "?" for c in column), dtype=bool, count=n)
            present["?" + col.key] = asked
            present[col.key] &= ~asked
    keys = [col.key for col in columns] + [key for key in present if key[0] == "?"]
    units = {col.key: col.unit for col in columns}
    blocks = []
    for given, rows in _by_columns_given(keys, [present[key] for key in keys]):
        if given and (given[-1][0] == "?" or _gives_a_result(spec, given)):
            # an inverse problem: the spec's inverse path (dyncalc.batch.fast_inverse), if any
            if getattr(spec, "inverse", None) is not None:
                blocks += spec.inverse(spec, [k for k in given if k[0] != "?"],
                                       [k[1:] for k in given if k[0] == "?"], rows, cells,
                                       plain, units, want_json, cache)
            continue
        plan = _plan(spec, given, units) if given else None
        if plan is None:
            continue
        for words, subset in _by_words(plan, cells, rows):
            block = _scene_block(spec, plan, words, subset, len(subset) == n, cells, plain,
                                 units, want_json, cache)
            if block is not None:
                blocks.append(block)
    return blocks


def _by_columns_given(columns: list, present: list[np.ndarray]):
    """The rows of a chunk grouped by which of ``columns`` they give (``present``: one
    boolean array per column): ``(the columns given, their rows)`` pairs, in a fixed order;
    one group of every row is ``np.arange(n)``."""
    n = len(present[0]) if present else 0
    signature = np.zeros(n, dtype=np.int64)
    for bit, given in enumerate(present):
        signature |= given.astype(np.int64) << bit
    # the distinct signatures, in order (np.unique would import numpy.ma: 6 ms)
    for sig in sorted(set(signature.tolist())):
        rows = np.arange(n) if sig == int(signature[0]) and (signature == sig).all() \
            else np.flatnonzero(signature == sig)
        yield [column for bit, column in enumerate(columns) if (sig >> bit) & 1], rows


def _gives_a_result(spec, given: list[str]) -> bool:
    """Whether a row giving ``given`` gives a result to solve from (an inverse problem)."""
    from ..scenes.runner import is_result_name

    return any(k not in spec.params and is_result_name(k) for k in given)


class _Plan:
    """How the rows giving one set of parameters are computed: the scene, its kernel, the
    parameters read from columns (``given``), the choice parameters (``choices``: read as
    words), the parameters taken at their default, and the keyword arguments the kernel takes
    besides the parameters (``method``, ``rtol``)."""

    __slots__ = ("scene", "kernel", "given", "choices", "defaults", "settings")


def _plan(spec, given: list[str], units: dict) -> _Plan | None:
    """The plan of the rows that give ``given``, or ``None`` where the generic path must
    answer (no scene, no kernel, a refusal, a setting the kernel does not take)."""
    from ..scenes import get_scene
    from ..scenes.runner import DEFAULT_RTOL, _resolve_groups

    try:
        scene = get_scene(spec.scene_for(given))
        skipped = _resolve_groups(scene, dict.fromkeys(given, ""))
    except InputError:
        return None
    kernel = kernel_of(scene.compute)
    names = {p.name for p in scene.params}
    if kernel is None or any(k not in names for k in given) \
            or ("zeta" in given and not scene.accepts_zeta):
        return None
    if spec.method not in (None, "auto") and spec.method not in scene.methods:
        return None
    plan = _Plan()
    plan.scene, plan.kernel, plan.given = scene, kernel, given
    plan.choices = [p for p in scene.params if p.choices is not None and p.name in given]
    if any(units[p.name] for p in plan.choices):
        return None  # a unit on a column of words: the one-off refuses it
    plan.defaults = []
    for p in scene.params:
        if p.name in given or p.name in skipped:
            continue
        if p.default is None:
            if not p.optional:
                return None  # a required parameter missing: the one-off refuses the row
            continue
        plan.defaults.append(p)
    plan.settings = {}
    if scene.methods:
        plan.settings = {"method": spec.method or "auto",
                         "rtol": DEFAULT_RTOL if spec.rtol is None else spec.rtol}
    return plan


def _by_words(plan: _Plan, cells: dict, rows: np.ndarray):
    """The rows of a block split by the words of their choice columns (``body``):
    ``(words by parameter, rows)`` pairs; rows with a word the parameter has not are left out
    (the generic path refuses them)."""
    if not plan.choices:
        yield {}, rows
        return
    combos: dict[tuple, list[int]] = {}
    columns = [cells[p.name] for p in plan.choices]
    for i in rows.tolist():
        words = tuple(column[i].strip() for column in columns)
        if all(w in p.choices for w, p in zip(words, plan.choices)):
            combos.setdefault(words, []).append(i)
    for words, members in combos.items():
        yield ({p.name: w for p, w in zip(plan.choices, words)},
               np.asarray(members, dtype=np.intp))


def _scene_block(spec, plan: _Plan, words: dict, rows: np.ndarray, whole: bool, cells, plain,
                 units, want_json: bool, cache: dict) -> FastBlock | None:
    """One block of rows: read their columns, run the kernel, keep the exact rows."""
    from ..result.kinds import result_kind

    scene = plan.scene
    # a choice left to its default is its default word (body=solid-cylinder, sense=inward)
    words = {**{p.name: p.default for p in plan.defaults if p.choices is not None}, **words}
    good = np.ones(len(rows), dtype=bool)
    si: dict[str, Any] = {}
    inputs = []
    for p in scene.params:
        if p.name in words:
            word = words[p.name]
            value = p.choices[word]
            si["kappa" if p.name == "body" else p.name] = \
                np.full(len(rows), value) if not isinstance(value, str) else value
            entry = json.dumps({p.name: {"value": word, "unit": ""}})[1:-2]
            inputs.append((p.name, None, None, None, False, entry))
        elif p.name in plan.given:
            column = cells[p.name] if whole else [cells[p.name][i] for i in rows.tolist()]
            read = _read_column(column, units[p.name], p, spec.strict, cache,
                                plain[p.name] if whole else None)
            good &= read.ok
            si[p.name] = read.si
            inputs.append((p.name, read, column, units[p.name],
                           whole and plain[p.name] is not None, None))
        elif p in plan.defaults:
            value, text = _default_input(p, spec.strict, cache)
            si[p.name] = np.full(len(rows), value)
            inputs.append((p.name, text, None, None, False, None))
    if not good.any():
        return None
    zeta = si.pop("zeta", None)
    arguments = {name: (np.where(good, value, 1.0) if isinstance(value, np.ndarray) else value)
                 for name, value in si.items()}
    with np.errstate(all="ignore"):
        for constraint in scene.constraints:
            good &= np.asarray(constraint.holds(arguments), dtype=bool)
        if not good.any():
            return None
        out = plan.kernel(**_as_typed(plan, arguments, inputs, cache), **plan.settings)
        if out is None:
            return None
        good &= out.exact
        values = dict(out.values)
        if zeta is not None:
            good &= zeta < 1.0   # at or above critical: a warning, generic path
            damped = damped_arrays(values["omega"], np.where(good, zeta, 0.0))
            good &= finite_nonzero({k: v for k, v in damped.items() if k != "zeta"})
            values.update(damped)
    if not good.any():
        return None
    keep = np.flatnonzero(good)
    if len(keep) != len(rows):
        rows = rows[keep]
        values = {name: array[keep] for name, array in values.items()}
    dims = {name: result_kind(name).dim for name in values}
    head = texts = None
    extra: Any = "{}"
    if isinstance(out.error_estimate, np.ndarray):  # one per row (the shell's quadrature)
        extra = _per_row_estimates(out.error_estimate[keep] if len(keep) != len(good)
                                   else out.error_estimate) if want_json else "{}"
    elif out.error_estimate is not None:
        extra = json.dumps({"error_estimate": out.error_estimate})
    if want_json:
        head = json_head("natural-frequency", scene.name, out.model, out.method)
        texts = _input_texts(inputs, keep, words)
    return FastBlock(rows, values, dims, head, texts, extra)


def _per_row_estimates(estimates) -> list:
    """The parts of each row's ``extra`` object, ``{"error_estimate": e}`` (finite floats, as
    ``json.dumps`` writes them), as :attr:`~dyncalc.physics.columns.Columns.extras` gives
    them: shared texts and a list of one text a row."""
    from .floats import reprs

    return ['{"error_estimate": ', reprs(estimates), "}"]


def _as_typed(plan: _Plan, arguments: dict, inputs: list, cache: dict) -> dict:
    """The kernel's arguments, with each parameter the kernel computes in the unit typed
    (its ``typed_params``) read from cells as a :class:`~dyncalc.physics.columns.TypedColumn`."""
    wanted = getattr(plan.kernel, "typed_params", ())
    if not wanted:
        return arguments
    from ..physics.columns import TypedColumn

    out = dict(arguments)
    for name, read, _column, _unit, _plain, _entry in inputs:
        if name in wanted and hasattr(read, "shown"):
            dim = plan.scene.param(name).dim
            units = [_unit_name(unit_json, dim, cache) for unit_json, _ in read.unit_json]
            out[name] = TypedColumn(arguments[name], np.where(read.ok, read.shown, 1.0),
                                    np.array(units))
    return out


def _unit_name(unit_json: str, dim, cache: dict) -> str:
    """pint's name of the unit a value was typed in (``"degree"``, ``"millimeter"``) as the
    one-off's quantity carries it; ``""`` where it cannot be read."""
    key = ("unit-name", unit_json, dim)
    if key not in cache:
        from ..units import parse_quantity

        try:
            name = str(parse_quantity("1 " + json.loads(unit_json), dim,
                                      label="batch").quantity.units)
        except (InputError, ValueError):
            name = ""
        cache[key] = name
    return cache[key]

