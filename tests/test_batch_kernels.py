"""Batch through the column kernels equals batch through the one-off, scene by scene.

For every scene of the catalog a file of random rows (ordinary and extreme magnitudes, units
typed in the cells or in the header, parameters left to their defaults, words for the
choices, refused values) runs twice: on the vectorised path and on the generic (one-off) path.
CSV and JSON lines must be identical byte for byte, and so must stderr and the exit status. A
scene whose physics has a column kernel must also have most ordinary rows on the vectorised
path, so a kernel that marks nothing exact fails here.
"""
from __future__ import annotations

import io
import random

import pytest

from dyncalc import batch
from dyncalc.batch import fast as fast_path
from dyncalc.commands.natural_frequency import STANDARD
from dyncalc.physics.columns import kernel_of
from dyncalc.scenes import catalog, get_scene

SCENES = list(catalog())


def _cell(rng: random.Random, param, ordinary: bool) -> str:
    """A random cell for ``param``: a word for a choice, else a number, perhaps with its SI
    unit written in the cell (the header carries none)."""
    if param.choices is not None:
        return rng.choice(list(param.choices))
    if param.name == "zeta":
        return rng.choice(["", repr(rng.uniform(0, 0.99)), "0", "1.5"])
    if param.name == "amplitude":
        return rng.choice(["", f"{rng.uniform(0, 170):.6g} deg", repr(rng.uniform(0, 3.0))])
    if param.name in ("mu", "kappa"):
        return repr(rng.uniform(0.05, 0.9))
    if ordinary:
        number = rng.uniform(0.2, 5.0) * 10.0 ** rng.randint(-2, 2)
    else:
        number = rng.choice([1e-300, 1e300, 0.0, -1.0, 5e-324, 1e-30, 1e30,
                             rng.uniform(1, 9) * 10.0 ** rng.randint(-200, 200)])
    text = repr(number)
    unit = param.dim.si if param.dim is not None else ""
    if unit and rng.random() < 0.5:
        text += " " + unit
    return text


def _table(scene, rng: random.Random, n: int, ordinary: bool) -> str:
    params = [p for p in scene.params if p.default is None or rng.random() < 0.5]
    lines = [",".join(p.name for p in params)]
    for _ in range(n):
        cells = []
        for p in params:
            cell = _cell(rng, p, ordinary)
            if p.default is not None and rng.random() < 0.3:
                cell = ""  # left to its default on this row
            cells.append(f'"{cell}"' if "," in cell else cell)
        lines.append(",".join(cells))
    return "\n".join(lines) + "\n"


def _run(scene: str, path, fast: bool, as_json: bool):
    out, err = io.StringIO(), io.StringIO()
    code = batch.run_batch(batch.NaturalFrequencyRows(STANDARD, scene=scene), str(path),
                           as_json=as_json, on_error="skip", out=out, err=err, fast=fast)
    return code, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("name", SCENES)
@pytest.mark.parametrize("ordinary", [True, False], ids=["ordinary", "extreme"])
def test_vectorised_rows_equal_the_one_off_rows(tmp_path, name, ordinary):
    rng = random.Random(f"{name}-{ordinary}")
    path = tmp_path / "rows.csv"
    path.write_text(_table(get_scene(name), rng, 60, ordinary))
    for as_json in (False, True):
        fast, slow = _run(name, path, True, as_json), _run(name, path, False, as_json)
        assert fast[0] == slow[0]
        assert fast[2] == slow[2]
        assert fast[1].splitlines() == slow[1].splitlines()


@pytest.mark.parametrize("name", [n for n in SCENES if kernel_of(get_scene(n).compute)])
def test_ordinary_rows_take_the_vectorised_path(name):
    """Rows giving every parameter at ordinary magnitudes (no amplitude, no zeta) are mostly
    computed by the scene's kernel."""
    scene = get_scene(name)
    rng = random.Random(name)
    params = [p for p in scene.params if p.name not in ("zeta", "amplitude")
              and not (p.choices is None and p.name == "kappa")
              and not any(p.name in group[1:] for group in scene.one_of)]
    rows = [[_cell(rng, p, True) for p in params] for _ in range(200)]
    table = [list(column) for column in zip(*rows)]
    columns = [batch.Column(i, p.name, p.name, "", p.name) for i, p in enumerate(params)]
    spec = batch.NaturalFrequencyRows(STANDARD, scene=name)
    blocks = fast_path._natural_frequency_fast(spec, columns, table, True, {})
    covered = sum(len(block.rows) for block in blocks)
    assert covered >= 0.5 * len(rows), f"{name}: {covered} of {len(rows)} rows vectorised"
