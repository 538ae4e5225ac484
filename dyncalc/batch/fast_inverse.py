"""Inverse problems on the vectorised path: rows of ``natural-frequency`` that give a result
(``f``, ``T``, ...) and leave out one parameter (or give it as ``?``), solved in closed form on
columns (:func:`dyncalc.scenes.inverse_columns.closed_form_columns`) where the result is a
power of the unknown, and for an angle (a pendulum's amplitude from its period) by the
one-off's bracket and Brent's method on columns
(:func:`dyncalc.scenes.inverse_brackets.bracketed_columns`); every other row (another
bracketed search, a refusal, a warning) is left to the generic path, which runs the one-off's
solver on it."""
from __future__ import annotations

import json

import numpy as np

from ..errors import InputError
from .columns import _read_column
from .fast import FastBlock, _by_words, _default_input, _input_texts, _plan, json_head


class _Target:
    """What :func:`~dyncalc.batch.columns._read_column` needs of the result given."""

    __slots__ = ("name", "dim", "constraint")

    def __init__(self, name: str, dim):
        self.name, self.dim, self.constraint = name, dim, None


def inverse_blocks(spec, given: list[str], asked: list[str], rows: np.ndarray, cells, plain,
                   units, want_json: bool, cache: dict) -> list[FastBlock]:
    """The blocks of rows giving ``given`` (parameters and one result) with ``asked`` cells
    ``?``: one per choice words and exponent; ``[]`` where the generic path answers."""
    from ..result.kinds import result_kind
    from ..scenes import get_scene
    from ..scenes.runner import is_result_name

    try:
        scene = get_scene(spec.scene_for(given))
    except InputError:
        return []
    targets = [k for k in given if scene.param(k) is None and is_result_name(k)]
    params = [k for k in given if k not in targets]
    if len(targets) != 1 or len(asked) > 1 or scene.one_of or "zeta" in given \
            or any(scene.param(k) is None for k in params):
        return []
    target = targets[0]
    if asked:
        unknown = scene.param(asked[0])
    else:
        missing = [p for p in scene.params if p.name not in params and p.default is None
                   and not p.optional]
        if len(missing) != 1:
            return []
        unknown = missing[0]
    if unknown is None or unknown.dim is None or unknown.name in params:
        return []
    forward = _plan(spec, [*params, unknown.name], {**units, unknown.name: ""})
    if forward is None:
        return []
    blocks = []
    for words, subset in _by_words(forward, cells, rows):
        blocks += _blocks(spec, forward, unknown, target, result_kind(target), words, subset,
                          len(subset) == len(rows) and len(rows) == len(cells[target]), cells,
                          plain, units, want_json, cache)
    return blocks


def _blocks(spec, plan, unknown, target, kind, words, rows, whole, cells, plain, units,
            want_json, cache) -> list[FastBlock]:
    from ..result.kinds import result_kind
    from ..scenes.inverse_columns import closed_form_columns

    scene = plan.scene
    words = {**{p.name: p.default for p in plan.defaults if p.choices is not None}, **words}
    good = np.ones(len(rows), dtype=bool)
    si: dict = {}
    inputs = []
    for p in scene.params:
        if p.name == unknown.name:
            continue
        if p.name in words:
            value = p.choices[words[p.name]]
            si["kappa" if p.name == "body" else p.name] = \
                np.full(len(rows), value) if not isinstance(value, str) else value
            entry = json.dumps({p.name: {"value": words[p.name], "unit": ""}})[1:-2]
            inputs.append((p.name, None, None, None, False, entry))
        elif p.name in plan.given:
            read = _read(cells, plain, p.name, p, units, rows, whole, spec, cache)
            good &= read.ok
            si[p.name] = read.si
            inputs.append((p.name, read, _column(cells, p.name, rows, whole), units[p.name],
                           whole and plain[p.name] is not None, None))
        elif p in plan.defaults:
            value, text = _default_input(p, spec.strict, cache)
            si[p.name] = np.full(len(rows), value)
            inputs.append((p.name, text, None, None, False, None))
    goal = _read(cells, plain, target, _Target(target, kind.dim), units, rows, whole, spec,
                 cache)
    good &= goal.ok
    inputs.append((target, goal, _column(cells, target, rows, whole), units[target],
                   whole and plain[target] is not None, None))
    if not good.any():
        return []
    arguments = {name: (np.where(good, value, 1.0) if isinstance(value, np.ndarray) else value)
                 for name, value in si.items()}
    how = "closed-form"
    solved = closed_form_columns(scene, plan.kernel, unknown, target, arguments,
                                 np.where(good, goal.si, 1.0), plan.settings)
    if solved is None:  # an angle: a bracket and Brent's method, as the one-off
        from ..scenes.inverse_brackets import bracketed_columns

        how = "bracketed-root"
        solved = bracketed_columns(scene, plan.kernel, unknown, target, arguments,
                                   np.where(good, goal.si, 1.0), plan.settings)
    if solved is None or isinstance(solved.out.error_estimate, np.ndarray):
        return []  # (an estimate per row, the shell's quadrature: the generic path's)
    exact = good & solved.exact
    blocks = []
    for exponent in sorted(set(solved.exponent[exact].tolist())):
        keep = np.flatnonzero(exact & (solved.exponent == exponent))
        values = {unknown.name: solved.x[keep]}
        values.update((name, array[keep]) for name, array in solved.out.values.items()
                      if name != unknown.name)
        dims = {name: (unknown.dim if name == unknown.name else result_kind(name).dim)
                for name in values}
        extra = {}
        if solved.out.error_estimate is not None:
            extra["error_estimate"] = solved.out.error_estimate
        extra["inverse"] = {"unknown": unknown.name, "method": how, "detail": (
            f"{target} is proportional to {unknown.name}^({exponent}): inverted exactly"
            if how == "closed-form" else f"a sign change on a grid of {unknown.name}, "
            "refined by Brent's method")}
        head = texts = None
        if want_json:
            head = json_head("natural-frequency", scene.name, solved.out.model,
                             solved.out.method)
            texts = _input_texts(inputs, keep, words)
        blocks.append(FastBlock(rows[keep], values, dims, head, texts, json.dumps(extra)))
    return blocks


def _column(cells, name, rows, whole):
    return cells[name] if whole else [cells[name][i] for i in rows.tolist()]


def _read(cells, plain, name, param, units, rows, whole, spec, cache):
    return _read_column(_column(cells, name, rows, whole), units[name], param, spec.strict,
                        cache, plain[name] if whole else None)
