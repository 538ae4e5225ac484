"""The vectorised path of ``modes --batch``: rows whose ``M`` and ``K`` cells are matrices of
numbers (``"[[2, 0], [0, 1]]"`` or ``"2,0;0,1"``: SI, every coordinate a translation; or with
a unit, in the header, ``M [g]``, or after the matrix, ``"[[2, 0], [0, 1]] kg"``: the numbers
times the SI value of one unit, as the one-off reads them) and no ``C``, grouped by
*template* (the cells with their numbers taken out: the same size, spelling and unit), their
numbers read in one pass a column, solved on a stack
(:func:`dyncalc.physics.modes_columns.stacked_modes`).

Unlike the other vectorised paths these rows are not the one-off's to the bit: the stacked
Cholesky reduction rounds otherwise than LAPACK's ``sygvd`` (a few units in the last place;
tests/test_batch_modes.py holds them to 1e-12 relative). Each group's first row is computed
by the one-off too (a *probe*): the group takes the generic path unless the probe's results,
model and method are the kernel's (to 1e-9) and its input entries the ones assembled here.
Set ``DYNCALC_BATCH_GENERIC=1`` for the one-off's own digits.
"""
from __future__ import annotations

import json
import re

import numpy as np

from ..errors import InputError
from .columns import _LITERAL_CELL
from .fast import FastBlock, json_head
from .floats import parse_floats

__all__ = ["modes_fast"]

_NUMBER_RE = re.compile(_LITERAL_CELL)
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
    m_cells, k_cells = list(table[by_key["M"].index]), list(table[by_key["K"].index])
    candidates = range(len(m_cells))
    if "C" in by_key:
        c_cells = table[by_key["C"].index]
        if "".join(c_cells).strip():
            candidates = [i for i in candidates if not c_cells[i].strip()]
    if not candidates or "\n" in "".join(m_cells) + "".join(k_cells):
        return []
    whole = len(candidates) == len(m_cells)
    picked_m = m_cells if whole else [m_cells[i] for i in candidates]
    picked_k = k_cells if whole else [k_cells[i] for i in candidates]
    t_m = _NUMBER_RE.sub("#", "\n".join(picked_m)).split("\n")
    t_k = _NUMBER_RE.sub("#", "\n".join(picked_k)).split("\n")
    groups: dict[tuple, list[int]] = {}
    if t_m.count(t_m[0]) == len(t_m) and t_k.count(t_k[0]) == len(t_k):
        groups[(t_m[0], t_k[0])] = list(candidates)
    else:
        for i, a, b in zip(candidates, t_m, t_k):
            groups.setdefault((a, b), []).append(i)
    blocks = []
    for (template_m, template_k), members in groups.items():
        (template_m, unit_m), (template_k, unit_k) = _unit(template_m), _unit(template_k)
        units = _units(by_key, unit_m, unit_k, cache)
        n = _size(template_m)
        if n is None or _size(template_k) != n or units is None:
            continue
        rows = np.asarray(members, dtype=np.intp)
        every = len(members) == len(m_cells)
        group_m = m_cells if every else [m_cells[i] for i in members]
        group_k = k_cells if every else [k_cells[i] for i in members]
        matrices = [_numbers(group, n) for group in (group_m, group_k)]
        if matrices[0] is None or matrices[1] is None:
            continue
        matrices = [matrix * factor for matrix, (factor, _suffix) in zip(matrices, units)]
        block = _block(spec, by_key, rows, group_m, group_k, *matrices, want_json, units)
        if block is not None:
            blocks.append(block)
    return blocks


_TRAILING_RE = re.compile(r"^(\s*\[.*\])[ \t]*([A-Za-z][A-Za-z/*^ \t]*?)?[ \t]*$")


def _unit(template: str) -> tuple[str, str]:
    """``(the matrix template, its trailing unit or "")``: ``[[#, #], [#, #]] kg``."""
    match = _TRAILING_RE.match(template)
    if match is None or not match.group(2):
        return template, ""
    return match.group(1), match.group(2)


def _units(by_key, unit_m: str, unit_k: str, cache: dict):
    """``((factor, text suffix) of M, of K)``: the SI value of one unit (the header's or the
    cells' trailing one; the one-off multiplies the numbers by it) and what the input text
    gains (`` g`` under a header unit); ``None`` where both are given or a unit is not read."""
    from ..units import MASS, STIFFNESS

    out = []
    for key, cell_unit, dim in (("M", unit_m, MASS), ("K", unit_k, STIFFNESS)):
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


def _numbers(cells: list[str], n: int):
    """The (rows, n, n) numbers of cells of one template, read in one pass; ``None`` where
    the count is off."""
    found = _NUMBER_RE.findall("\n".join(cells))
    if len(found) != len(cells) * n * n:
        return None
    try:
        return np.asarray(parse_floats(found), dtype=float).reshape(len(cells), n, n)
    except ValueError:
        return None


def _block(spec, by_key, rows, cells_m, cells_k, M, K, want_json, units):
    from ..physics.modes_columns import stacked_modes

    normalize = spec.settings.get("normalize") or "max"
    out = stacked_modes(M, K, normalize)
    good = np.asarray(out.exact, dtype=bool)
    if not good.any():
        return None
    keep = np.flatnonzero(good)
    first = int(keep[0])
    suffixes = [suffix for _factor, suffix in units]
    probe = _probe(spec, by_key, cells_m[first] + suffixes[0], cells_k[first] + suffixes[1],
                   out, first)
    if probe is None:
        return None
    values = {name: array[keep] for name, array in out.values.items()}
    dims = {name: entry.dim for name, entry in probe.results.items()}
    head = inputs = None
    extra = json.dumps(probe.extra, allow_nan=False)
    if want_json:
        from ..result.encode import _json_inputs

        from .assemble import lines

        if lines(_inputs([cells_m[first]], [cells_k[first]], M[[first]], K[[first]], units),
                 1)[0] != json.dumps(_json_inputs(probe.inputs))[1:-1]:
            return None
        head = json_head("modes", None, out.model, out.method)
        inputs = _inputs([cells_m[i] for i in keep.tolist()],
                         [cells_k[i] for i in keep.tolist()], M[keep], K[keep], units)
    return FastBlock(rows[keep], values, dims, head, inputs, extra)


def _probe(spec, by_key, cell_m: str, cell_k: str, out, i: int):
    """The one-off Result of one row, or ``None`` where it is not the kernel's (to
    :data:`PROBE_RTOL`)."""
    try:
        result = spec.compute({"M": cell_m, "K": cell_k},
                              {"M": by_key["M"].name, "K": by_key["K"].name})
    except InputError:
        return None
    if (result.warnings or result.model != out.model or result.method != out.method
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


def _inputs(cells_m, cells_k, M, K, units) -> list:
    """The parts (:func:`dyncalc.batch.assemble.lines`) of each row's input entries
    ``"M": {...}, "K": {...}`` (SI values; bare numbers assumed SI, or the text with its
    header unit), a component column at a time."""
    from .write import _component

    parts: list = []
    for name, cells, X, unit, (factor, suffix) in (("M", cells_m, M, "kg", units[0]),
                                                     ("K", cells_k, K, "N/m", units[1])):
        n = X.shape[1]
        parts.append((", " if parts else "") + f'"{name}": {{"value": [')
        for i in range(n):
            parts.append(", [" if i else "[")
            for j in range(n):
                parts += [", "] if j else []
                parts.append(_component(X[:, i, j]))
            parts.append("]")
        joined = "".join(cells)
        plain = joined.isascii() and joined.isprintable() and not ('"' in joined
                                                                    or "\\" in joined)
        text = ['"', list(cells), suffix + '"'] if plain else [[json.dumps(c + suffix)
                                                                 for c in cells]]
        assumed = ', "assumed_si": true}' if factor == 1.0 and not suffix and not \
            _unit(cells[0])[1] else "}"
        parts += [f'], "unit": "{unit}", "text": ', *text, assumed]
    return parts
