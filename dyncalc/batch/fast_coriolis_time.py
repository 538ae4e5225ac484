"""``coriolis`` over times (``--r "s0 - b*t^2/2, 0, 0 m" --omega "0,0,2 rad/s"`` with a ``t``
column or a ``--t`` list) on whole columns, bit for bit the one-off.

The motion is derived once per run (:func:`~dyncalc.physics.relative_time.motion_in_time`
keeps it); its compiled functions are evaluated a time at a time, all vectors in one call
(:meth:`~dyncalc.physics.relative_time.TimeMotion.vectors_at`, the same expressions and
``math`` calls as the one-off), the frame's rotation on a stack
(:meth:`~dyncalc.physics.relative_time.TimeMotion.rotations_at`), and every term of the
relative-motion formula through the column kernels the vector form uses
(:func:`~dyncalc.commands.coriolis_frame_columns.frame_values`). Taken: a ``t`` column of
plain numbers in seconds (no other column), the rotating basis, no ``--R0``, a frame that does
not turn or turns about a fixed axis by a closed-form angle, no mass uncertainty. A probe row
run by the one-off must agree to the bit (values, order, inputs, ``extra``); every other row,
and rows the kernels cannot take (not defined, an overflow, an underflow's warning), run the
one-off.
"""
from __future__ import annotations

import json
import re

import numpy as np

from ..errors import InputError
from .columns import _LITERAL_CELL, _LITERALS_RE, _plain_floats
from .fast import FastBlock, json_head
from .fast_commands import _same, _stripped
from .floats import parse_floats

__all__ = ["coriolis_time_fast"]

#: A time cell: a number, or a number in seconds (``0.5 s``, as a ``--t`` list gives it).
_TIME_RE = re.compile(rf"({_LITERAL_CELL})([ \t]*s)?")
#: The vectors of the motion, as the one-off evaluates them.
_EVALUATED = ("r", "v_r", "a_r", "Omega", "alpha")


def coriolis_time_fast(spec, columns, table, want_json: bool, cache: dict) -> list[FastBlock]:
    """The rows of this chunk the vectorised path computes (one block), or none."""
    if len(columns) != 1 or columns[0].key != "t" or columns[0].unit not in ("s", "") \
            or not table:
        return []
    col = columns[0]
    cells = _stripped(table[col.index])
    times = _plain_times(cells)
    if times is not None:  # (the usual column: plain numbers, read at once)
        rows = np.arange(len(cells))
    else:
        rows, times = _times(cells, col)
        if rows is None:
            return []
    setup = _setup(spec, col, cells[int(rows[0])], cache)
    if setup is None:
        return []
    motion, mass, probe = setup
    values, exact, Q = _sliced_values(motion, times, mass)
    if not exact.any():
        return []
    keep = np.flatnonzero(exact)
    if len(keep) < len(exact):  # (all exact, the usual case: no copy of every result)
        values = {name: array[keep] for name, array in values.items()}
    first = {name: array[0] for name, array in values.items()}
    if int(rows[keep[0]]) != int(rows[0]) or list(probe.results) != list(values) \
            or not all(_same(probe.results[n].si, first[n]) for n in values):
        return []
    from .assemble import lines

    turned = motion.rotation != "none"
    first_extra = _extra(probe.extra, Q[keep[:1]], turned)  # (the probe's row alone: the
    if lines(first_extra if isinstance(first_extra, list) else [first_extra], 1)[0] \
            != json.dumps(probe.extra):                      # parts of every row are big)
        return []
    extra = _extra(probe.extra, Q[keep], turned) if want_json else "{}"
    head = inputs = None
    if want_json:
        from ..result.encode import _json_inputs

        inputs = _inputs(json.dumps(_json_inputs(probe.inputs))[1:-1], probe, times[keep],
                         [cells[i] for i in rows[keep].tolist()], col.unit)
        if inputs is None:
            return []
        head = json_head("coriolis", probe.scene, probe.model, probe.method)
    dims = {name: entry.dim for name, entry in probe.results.items()}
    return [FastBlock(rows[keep], values, dims, head, inputs, extra)]


def _plain_times(cells):
    """The times of a column whose every cell is a whole plain number, read in one pass;
    ``None`` otherwise."""
    joined = "\n".join(cells)
    if not _LITERALS_RE.fullmatch(joined):
        return None
    return _plain_floats(cells)


def _times(cells, col):
    """``(rows, times)``: the rows of one form (plain numbers, or numbers in seconds as a
    ``--t`` list gives them) and their times, a cell at a time; ``(None, None)`` if none."""
    found = [_TIME_RE.fullmatch(c) for c in cells]
    # one form a block: plain numbers, or (a --t list, no header unit) numbers in seconds
    seconds = found[0] is not None and found[0].group(2) is not None
    plain = np.fromiter((m is not None and (m.group(2) is not None) == seconds
                         and not (seconds and col.unit) for m in found), dtype=bool,
                        count=len(cells))
    if not plain.any():
        return None, None
    rows = np.flatnonzero(plain)
    try:
        times = np.asarray(parse_floats([found[i].group(1) for i in rows.tolist()]),
                           dtype=float)
    except ValueError:
        return None, None
    return rows, times


def _setup(spec, col, cell: str, cache: dict):
    """``(motion, mass, probe)`` of this run (kept in ``cache``): the motion derived once,
    the mass in kg (or ``None``), and the one-off's Result of the first row; ``None`` where
    the set-up is not the vectorised path's."""
    from ..commands.coriolis_time import read_time
    from ..physics.relative_time import motion_in_time

    text = f"{cell} {col.unit}" if col.unit else cell
    try:
        probe = spec.compute({"t": text}, {"t": col.name})
    except InputError:
        return None
    if probe.warnings or probe.sensitivity is not None:
        return None
    key = ("coriolis-time", "setup")
    if key not in cache:
        values = dict(spec.values, t=text)
        words = tuple(spec.words.values())
        try:
            inputs = read_time(values, words, spec.strict)
        except InputError:
            cache[key] = None
        else:
            vec = inputs.vectors
            motion = motion_in_time(vec.get("r"), vec.get("omega"), vec.get("R0"),
                                    inputs.params)
            fine = ("R0" not in vec and inputs.basis == "rotating"
                    and motion.rotation in ("none", "closed form")
                    and (inputs.mass is None or inputs.mass.uncertainty is None))
            mass = None if inputs.mass is None else float(inputs.mass.si)
            cache[key] = (motion, mass) if fine else None
    if cache[key] is None:
        return None
    return (*cache[key], probe)


#: Times evaluated at a time: the kernels' temporaries (a few dozen arrays of this many rows)
#: stay small whatever the chunk (issue 17: memory flat, <= 100 MB).
SLICE = 2048


def _sliced_values(motion, times, mass):
    """:func:`_values` of ``times`` a :data:`SLICE` of rows at a time, into whole arrays."""
    if len(times) <= SLICE:
        return _values(motion, times, mass)
    values = exact = Q = None
    for start in range(0, len(times), SLICE):
        part = slice(start, start + SLICE)
        v, e, q = _values(motion, times[part], mass)
        if values is None:
            n = len(times)
            values = {name: np.empty((n, *a.shape[1:]), dtype=a.dtype) for name, a in v.items()}
            exact, Q = np.empty(n, dtype=bool), np.empty((n, *q.shape[1:]), dtype=q.dtype)
        for name, array in v.items():
            values[name][part] = array
        exact[part], Q[part] = e, q
    return values, exact, Q


def _values(motion, times, mass):
    """The one-off's results at each time (its order), the rows where they are exact, and
    the rotation matrices."""
    from ..commands.coriolis_frame_columns import frame_values
    from ..physics.numerics_arrays import hypot_rows

    n = len(times)
    vectors, exact = motion.vectors_at(_EVALUATED, times)
    Q, theta, turned = motion.rotations_at(times)
    exact = exact & turned
    safe = {name: np.where(exact[:, None], v, 1.0) for name, v in vectors.items()}
    zero = np.zeros((n, 3))

    def magnitude(vector):
        nonlocal exact
        value, fine = hypot_rows(vector[:, 0], vector[:, 1], vector[:, 2])
        exact = exact & fine & np.isfinite(value)
        return value + 0.0

    arrays = {"r": safe["r"], "alpha": safe["alpha"], "a0": zero, "ar": safe["a_r"],
              "v0": zero}
    if mass is not None:
        arrays["mass"] = np.full(n, mass)
    with np.errstate(all="ignore"):
        terms, fine = frame_values(arrays, safe["Omega"], safe["v_r"], magnitude)
    exact = exact & fine
    values = {name: vectors[name] for name in _EVALUATED}
    values.update(v0=zero, a0=zero, R=vectors["r"] + 0.0)
    for name in ("v_transport", "v", "a_c", "a_euler", "a_centripetal", "a_transport", "a",
                 *(("F_c",) if mass is not None else ())):
        values[name] = terms[name] + 0.0
        if f"{name}_mag" in terms:
            values[f"{name}_mag"] = terms[f"{name}_mag"]
    values["theta"] = theta + 0.0
    return values, exact, Q


def _extra(extra: dict, Q, turned: bool):
    """The JSON text of the rows' ``extra`` (one text), or its parts with each row's
    ``rotation_matrix`` (a frame that turns)."""
    from .write import _component

    if not turned:
        return json.dumps(extra)
    shared = {k: v for k, v in extra.items() if k != "rotation_matrix"}
    parts: list = [json.dumps(shared)[:-1] + ', "rotation_matrix": [']
    for i in range(3):
        parts.append(", [" if i else "[")
        for j in range(3):
            parts += [", "] if j else []
            parts.append(_component(Q[:, i, j] + 0.0))
        parts.append("]")
    parts.append("]}")
    return parts


def _inputs(probe_text: str, probe, times, cells, unit: str):
    """The parts of each row's inputs: the probe's, its ``t`` entry a column; ``None``
    where the probe's text is not so made."""
    from ..result.encode import _json_inputs

    entry = json.dumps(_json_inputs({"t": probe.inputs["t"]}))[1:-1]
    at = probe_text.find(entry)
    joined = "".join(cells)
    if at < 0 or not (joined.isascii() and joined.isprintable()) or '"' in joined \
            or "\\" in joined:
        return None
    from .write import _component

    suffix = f" {unit}" if unit else ""
    t_json = json.loads("{" + entry + "}")["t"]
    if set(t_json) != {"value", "unit", "text"}:
        return None
    parts = [probe_text[:at] + '"t": {"value": ', _component(times),
             f', "unit": {json.dumps(t_json["unit"])}, "text": "', list(cells),
             suffix + '"}' + probe_text[at + len(entry):]]
    from .assemble import lines

    if lines(parts, len(cells))[0] != probe_text:
        return None
    return parts
