"""The vectorised path of ``modes --batch``: rows whose ``M`` and ``K`` cells are matrices of
numbers (``"[[2, 0], [0, 1]]"`` or ``"2,0;0,1"``: SI, every coordinate a translation; or with
a unit, in the header, ``M [g]``, or after the matrix, ``"[[2, 0], [0, 1]] kg"``: the numbers
times the SI value of one unit, as the one-off reads them), with or without a ``C`` cell of
the same kind (proportional damping: ``zeta_i``, ``omega_d_i``; damping that is not
proportional from the state-space eigenvalues, a block of its own with the one-off's note;
the rows the stack leaves, near-critical, overdamped or barely damped, uncoupled, take the
one-off's physics a row at a time: :mod:`dyncalc.batch.fast_modes_rows`), grouped by
*template* (the cells with their numbers taken out: the same size, spelling and unit), their
numbers read in one pass a column, solved on a stack
(:func:`dyncalc.physics.modes_columns.stacked_modes`).

Unlike the other vectorised paths these rows are not the one-off's to the bit: the stacked
Cholesky reduction rounds otherwise than LAPACK's ``sygvd`` (a few units in the last place;
tests/test_batch_modes.py holds them to 1e-12 relative). The first row of each kind of rows
(templates and units) is computed by the one-off too, once a run (a *probe*): the rows take
the generic path unless the probe's results, model and method are the kernel's (to 1e-9)
and its input entries the ones assembled here. A chunk whose cells all share a template is
read in one pass of the number pattern a column (:func:`_uniform`).
Set ``DYNCALC_BATCH_GENERIC=1`` for the one-off's own digits.
"""
from __future__ import annotations

import functools
import itertools
import json
import re

import numpy as np

from ..errors import InputError
from .columns import _LITERAL_CELL
from .fast import FastBlock, json_head
from .floats import json_floats, parse_floats

__all__ = ["modes_fast"]

_NUMBER_RE = re.compile(_LITERAL_CELL)
_SPLIT_RE = re.compile(f"({_LITERAL_CELL})")
#: The relative agreement a probe must show.
PROBE_RTOL = 1e-9


def _size(template: str) -> int | None:
    """The order ``n`` of a template of an n x n matrix of numbers, or ``None``."""
    t = re.sub(r"[ \t]+", "", template)
    if t.startswith("[[") and t.endswith("]]"):
        rows = t[2:-2].split("],[")
    elif "[" in t or "]" in t:
        return None
    else:
        rows = t.split(";")
    n = len(rows)
    row = ",".join(["#"] * n)
    return n if n and all(r == row for r in rows) else None


def modes_fast(spec, columns, table, want_json: bool, cache: dict) -> list[FastBlock]:
    """The rows of this chunk the vectorised path computes, as blocks (one per pair of
    templates); every other row is left to the generic path."""
    if not table:
        return []
    by_key = {col.key: col for col in columns}
    if "M" not in by_key or "K" not in by_key:
        return []
    keys = ("M", "K", "C") if "C" in by_key else ("M", "K")
    cells = [list(table[by_key[key].index]) for key in keys]
    joined = ["\n".join(c) for c in cells]
    if any(j.count("\n") != len(c) - 1 for j, c in zip(joined, cells)):
        return []
    if len(keys) == 3 and not joined[2].strip():
        keys, cells, joined = keys[:2], cells[:2], joined[:2]  # empty C cells: undamped rows
    uniform = [_uniform(c, j) for c, j in zip(cells, joined)]  # one pass a column
    del joined
    groups: dict[tuple, list[int]] = {}
    if all(u is not None for u in uniform):
        groups[tuple(t for t, _numbers in uniform)] = list(range(len(cells[0])))
    else:
        uniform = None
        templates = [_NUMBER_RE.sub("#", "\n".join(c)).split("\n") for c in cells]
        for i, key in enumerate(zip(*templates)):
            groups.setdefault(key, []).append(i)
    blocks = []
    for group_key, members in groups.items():
        split = [_unit(t) for t in group_key]
        if len(split) == 3 and not split[2][0].strip():
            split = split[:2]  # no C in these rows
        units = _units(by_key, [u for _t, u in split], cache)
        n = _size(split[0][0])
        if n is None or any(_size(t) != n for t, _u in split) or units is None:
            continue
        rows = np.asarray(members, dtype=np.intp)
        every = len(members) == len(cells[0])
        group = [c if every else [c[i] for i in members] for c in cells[:len(split)]]
        matrices = [_numbers(g, n) for g in group] if uniform is None else \
            [None if values is None or len(values) != len(members) * n * n else
             values.reshape(len(members), n, n) for _t, values in uniform[:len(split)]]
        if any(m is None for m in matrices):
            continue
        matrices = [matrix * factor for matrix, (factor, _suffix) in zip(matrices, units)]
        blocks += _blocks(spec, by_key, rows, group, matrices, want_json, units, group_key)
    return blocks


_TRAILING_RE = re.compile(r"^(\s*\[.*\])[ \t]*([A-Za-z][A-Za-z/*^ \t]*?)?[ \t]*$")


def _unit(template: str) -> tuple[str, str]:
    """``(the matrix template, its trailing unit or "")``: ``[[#, #], [#, #]] kg``."""
    match = _TRAILING_RE.match(template)
    if match is None or not match.group(2):
        return template, ""
    return match.group(1), match.group(2)


def _units(by_key, cell_units: list[str], cache: dict):
    """``[(factor, text suffix) of M, of K (, of C)]``: the SI value of one unit (the header's or the
    cells' trailing one; the one-off multiplies the numbers by it) and what the input text
    gains (`` g`` under a header unit); ``None`` where both are given or a unit is not read."""
    from ..units import DAMPING, MASS, STIFFNESS

    out = []
    for key, cell_unit, dim in zip("MKC", cell_units, (MASS, STIFFNESS, DAMPING)):
        header = by_key[key].unit
        if header and cell_unit:
            return None
        unit = header or cell_unit
        if not unit:
            out.append((1.0, ""))
            continue
        if (dim.name, unit) not in cache:
            from ..units import parse_quantity

            try:
                cache[(dim.name, unit)] = float(parse_quantity("1 " + unit, dim,
                                                               label=key).si)
            except InputError:
                cache[(dim.name, unit)] = None
        if cache[(dim.name, unit)] is None:
            return None
        out.append((cache[(dim.name, unit)], " " + header if header else ""))
    return out


def _uniform(cells: list[str], joined: str):
    """``(the template, its numbers, a flat float array or None where ``float`` refuses
    one)`` of a column whose cells all have the first one's template, read in one pass;
    ``None`` where a cell's template differs.

    Where the text around the first cell's numbers holds no character a number may hold
    (``0-9 . e E + -``) and two numbers are never adjacent, a cell has that template exactly
    when it matches the template with each ``#`` a number (:func:`_template_re`): every
    number is then a whole run of number characters, as ``sub`` finds it. Otherwise ``split``
    finds the numbers ``sub`` replaces by ``#`` and the text between them, which must repeat
    the first cell's. ``joined``: the cells joined by line breaks (none in a cell)."""
    first = _SPLIT_RE.split(cells[0])
    between = first[0::2]  # the text around the first cell's numbers
    count = len(between) - 1
    if not count:
        return None
    if not any(map(_NUMBER_CHARS.intersection, between)) and all(between[1:-1]):
        values = _plain(joined, between, len(cells))
        if values is not None:
            return "#".join(between), values
        found = _template_re(tuple(between)).findall(joined)
        if len(found) != len(cells):
            return None
        if count > 1:
            found = list(itertools.chain.from_iterable(found))
    else:
        parts = _SPLIT_RE.split(joined)
        inner = between[1:-1] + [between[-1] + "\n" + between[0]]
        expected = [between[0], *inner * (len(cells) - 1), *between[1:]]
        if parts[0::2] != expected:
            return None
        found = parts[1::2]
        del parts
    return "#".join(between), _parsed(found)


#: The characters a number of a cell may hold (:data:`_NUMBER_RE`).
_NUMBER_CHARS = frozenset("0123456789.eE+-")
#: Numbers parsed at a time (orjson's document for a list of numbers takes some 13 bytes a
#: character of its text at once: smaller slices keep the peak low).
PARSE_SLICE = 8192


_IS_NUMBER = np.zeros(256, dtype=bool)
_IS_NUMBER[np.frombuffer("".join(sorted(_NUMBER_CHARS)).encode(), dtype=np.uint8)] = True
_NO_NUMBERS = str.maketrans("", "", "".join(sorted(_NUMBER_CHARS)))


def _plain(joined: str, between: list[str], rows: int):
    """The flat floats of a column of ASCII cells that are each the text ``between`` (which
    holds no number character, the inner pieces not empty) with a run of number characters
    at each gap, every run a JSON number (read by orjson: :func:`json_floats`), with numpy
    on the column's bytes; ``None`` where one is not (the template pattern decides then)."""
    if not joined.isascii() or joined.translate(_NO_NUMBERS) != "\n".join(
            ["".join(between)] * rows):
        return None  # the text around the numbers is not the template's in every cell
    count = len(between) - 1
    text = np.frombuffer(joined.encode("ascii"), dtype=np.uint8)
    number = _IS_NUMBER[text]
    edges = np.diff(number.view(np.int8))
    starts, ends = np.flatnonzero(edges == 1) + 1, np.flatnonzero(edges == -1) + 1
    if number[0]:
        starts = np.concatenate(([0], starts))
    if number[-1]:
        ends = np.append(ends, len(text))
    if len(starts) != rows * count:
        return None
    lengths = ends - starts
    before = np.cumsum(lengths) - lengths  # number characters before each run
    line = len("".join(between)) + 1  # a cell's text around its numbers, and its line break
    gaps = np.cumsum([len(piece) for piece in between[:-1]])
    if not np.array_equal((starts - before).reshape(rows, count),
                          np.arange(rows)[:, None] * line + gaps[None, :]):
        return None  # a run is not at a gap of the template: another template
    keep = number.copy()
    keep[starts[1:] - 1] = True  # the character before each run but the first: a comma
    numbers = np.where(number, text, ord(","))[keep].tobytes().decode("ascii")
    at = (before + np.arange(len(starts))).tolist() + [len(numbers) + 1]  # runs' offsets
    out = []
    for i in range(0, len(starts), PARSE_SLICE):
        j = min(i + PARSE_SLICE, len(starts))
        values = json_floats(numbers[at[i]:at[j] - 1], j - i)
        if values is None:
            return None
        out.append(values)
    return np.concatenate(out)


@functools.lru_cache(maxsize=64)
def _template_re(between: tuple[str, ...]):
    """A line (of cells joined by line breaks) that is the text ``between`` with a number
    (a group) between each two pieces."""
    number = f"({_LITERAL_CELL})"
    return re.compile("^" + number.join(map(re.escape, between)) + "$", re.M)


def _parsed(found: list[str]):
    """``float`` of each number's text, a flat array; ``None`` where ``float`` refuses one."""
    try:
        return np.concatenate([parse_floats(found[i:i + PARSE_SLICE])
                               for i in range(0, len(found), PARSE_SLICE)])
    except ValueError:
        return None


def _floats(found: list[str], rows: int, n: int):
    """The (rows, n, n) floats of a column's numbers' texts; ``None`` where the count is off
    or ``float`` refuses one."""
    if len(found) != rows * n * n:
        return None
    values = _parsed(found)
    return None if values is None else values.reshape(rows, n, n)


def _numbers(cells: list[str], n: int):
    """The (rows, n, n) numbers of cells of one template, read in one pass; ``None`` where
    the count is off."""
    return _floats(_NUMBER_RE.findall("\n".join(cells)), len(cells), n)


def _blocks(spec, by_key, rows, cells, matrices, want_json, units, kind) -> list:
    """The blocks of the rows the kernel takes: undamped or proportionally damped, then (of
    the rest, with C) damping that is not proportional (state-space eigenvalues), then the
    rest through the one-off's physics a row at a time, a block per model and notes."""
    from ..physics.modes_columns import stacked_modes

    normalize = spec.settings.get("normalize") or "max"
    out = stacked_modes(*matrices[:2], normalize, *matrices[2:])
    blocks = [_block(spec, by_key, rows, cells, matrices, want_json, units, kind, out)]
    left = np.flatnonzero(~np.asarray(out.exact, dtype=bool))
    if len(matrices) == 3 and len(left):
        rows, cells, matrices = _subset(rows, cells, matrices, left)
        out = stacked_modes(*matrices[:2], normalize, matrices[2], damping="complex")
        blocks.append(_block(spec, by_key, rows, cells, matrices, want_json, units, kind,
                             out))
        left = np.flatnonzero(~np.asarray(out.exact, dtype=bool))
    if len(left):  # the rest: the one-off's physics a row at a time, grouped by its notes
        from .fast_modes_rows import rowwise_modes

        rows, cells, matrices = _subset(rows, cells, matrices, left)
        blocks += [_block(spec, by_key, rows, cells, matrices, want_json, units, kind, out)
                   for out in rowwise_modes(*matrices[:2], matrices[2] if len(matrices) == 3
                                            else None, normalize)]
    return [block for block in blocks if block is not None]


def _subset(rows, cells, matrices, picked):
    """These rows (``picked``: positions in ``rows``) of a block's rows, cells and matrices."""
    at = picked.tolist()
    return rows[picked], [[c[i] for i in at] for c in cells], [X[picked] for X in matrices]


def _block(spec, by_key, rows, cells, matrices, want_json, units, kind, out):
    """The block of the rows the kernel takes (``out``), where the probe of this ``kind`` of
    rows (their templates and units, the model; probed once a run, in ``spec.probed``)
    agrees."""
    normalize = spec.settings.get("normalize") or "max"
    good = np.asarray(out.exact, dtype=bool)
    if not good.any():
        return None
    keep = np.flatnonzero(good)
    first = int(keep[0])
    probed = getattr(spec, "probed", None)
    kind = (kind, tuple(units), normalize, want_json, out.model, out.method, tuple(out.values),
            out.warnings)
    known = probed.get(kind) if probed is not None else None
    if known is None:
        known = _probe(spec, by_key,
                       [c[first] + suffix for c, (_f, suffix) in zip(cells, units)], out,
                       first)
        if known is None or want_json and not _same_inputs(cells, matrices, units, first,
                                                           known):
            return None
        known = ({name: entry.dim for name, entry in known.results.items()},
                 json.dumps(known.extra, allow_nan=False))
        if probed is not None:
            probed[kind] = known
    values = {name: array[keep] for name, array in out.values.items()}
    dims, extra = known
    head = inputs = None
    if want_json:
        head = json_head("modes", None, out.model, out.method)
        picked = keep.tolist()
        inputs = _inputs([[c[i] for i in picked] for c in cells], [X[keep] for X in matrices],
                         units)
    return FastBlock(rows[keep], values, dims, head, inputs, extra, out.warnings)


def _same_inputs(cells, matrices, units, first: int, probe) -> bool:
    """Whether the JSON input entries assembled here for row ``first`` are the probe's."""
    from ..result.encode import _json_inputs

    from .assemble import lines

    return lines(_inputs([[c[first]] for c in cells], [X[[first]] for X in matrices], units),
                 1)[0] == json.dumps(_json_inputs(probe.inputs))[1:-1]


def _probe(spec, by_key, texts: list[str], out, i: int):
    """The one-off Result of one row (its M, K (, C) texts), or ``None`` where it is not the
    kernel's (to :data:`PROBE_RTOL`)."""
    keys = "MKC"[:len(texts)]
    try:
        result = spec.compute(dict(zip(keys, texts)), {k: by_key[k].name for k in keys})
    except InputError:
        return None
    if (tuple(result.warnings) != out.warnings or result.model != out.model or result.method != out.method
            or list(result.results) != list(out.values)
            or any(c["kind"] != "translation" for c in result.extra.get("coordinates", []))):
        return None
    for name, entry in result.results.items():
        theirs = np.asarray(entry.si, dtype=float)
        mine = out.values[name][i]
        if entry.uncertainty is not None or not np.allclose(theirs, mine, rtol=PROBE_RTOL,
                                                            atol=0.0):
            return None
    return result


def _inputs(cells, matrices, units) -> list:
    """The parts (:func:`dyncalc.batch.assemble.lines`) of each row's input entries
    ``"M": {...}, "K": {...}`` (and ``"C"``; SI values; bare numbers assumed SI, or the text
    with its header unit), a component column at a time."""
    from .write import _component

    parts: list = []
    for name, cells_x, X, unit, (factor, suffix) in zip("MKC", cells, matrices,
                                                         ("kg", "N/m", "N*s/m"), units):
        n = X.shape[1]
        parts.append((", " if parts else "") + f'"{name}": {{"value": [')
        for i in range(n):
            parts.append(", [" if i else "[")
            for j in range(n):
                parts += [", "] if j else []
                parts.append(_component(X[:, i, j]))
            parts.append("]")
        joined = "".join(cells_x)
        plain = joined.isascii() and joined.isprintable() and not ('"' in joined
                                                                    or "\\" in joined)
        text = ['"', list(cells_x), suffix + '"'] if plain else [[json.dumps(c + suffix)
                                                                   for c in cells_x]]
        assumed = ', "assumed_si": true}' if factor == 1.0 and not suffix and not \
            _unit(cells_x[0])[1] else "}"
        parts += [f'], "unit": "{unit}", "text": ', *text, assumed]
    return parts
