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
import math
import random

import pytest

from dyncalc import batch
from dyncalc.batch import fast as fast_path
from dyncalc.batch.fast_commands import _command_fast
from dyncalc.commands.natural_frequency import STANDARD
from dyncalc.errors import InputError
from dyncalc.physics.columns import Columns, kernel_of
from dyncalc.scenes import computed_scenes, get_scene

SCENES = list(computed_scenes())


def _cell(rng: random.Random, param, ordinary: bool, others: bool = True) -> str:
    """A random cell for ``param``: a word for a choice, else a number, perhaps with a unit
    written in the cell (the header carries none): the SI one or, with ``others``, another."""
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
        text += " " + rng.choice([unit, *(OTHER_UNITS.get(unit, ()) if others else ())])
    return text


#: Units besides the SI one a cell may be typed in, by SI unit.
OTHER_UNITS = {
    "m": ("mm", "ft", "km"), "kg": ("g", "lb"), "N/m": ("kN/m", "lbf/in"),
    "m/s^2": ("ft/s^2", "mm/s^2"), "rad/s": ("rpm", "deg/s", "1/s", "rev/s"),
    "rad": ("deg", "turn"), "N*m/rad": ("N*m/deg", "kN*m/rad"),
    "kg*m^2": ("g*cm^2", "lb*ft^2"), "m/s": ("km/h", "mph"), "N*s/m": ("kN*s/m",),
    "Hz": ("rpm", "1/min"),
}


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


#: Scenes with a kernel that leaves ordinary rows to the one-off path, and why.
ONE_OFF_ONLY: dict[str, str] = {}


@pytest.mark.parametrize("name", [n for n in SCENES if kernel_of(get_scene(n).compute)
                                  and n not in ONE_OFF_ONLY])
def test_ordinary_rows_take_the_vectorised_path(name):
    """Rows giving every parameter at ordinary magnitudes in SI units (no amplitude, no zeta;
    a choice at its default word) are computed by the scene's kernel wherever the one-off
    computes them with no warning, cells typed in SI or in another unit (``rpm``, ``deg/s``
    for an angular rate: converted from the unit typed, as the one-off reader does)."""
    scene = get_scene(name)
    rng = random.Random(name)
    params = [p for p in scene.params if p.name not in ("zeta", "amplitude")
              and not (p.choices is None and p.name == "kappa")
              and not any(p.name in group[1:] for group in scene.one_of)]
    rows = [[p.default if p.choices is not None and p.default else _cell(rng, p, True)
             for p in params] for _ in range(200)]
    table = [list(column) for column in zip(*rows)]
    columns = [batch.Column(i, p.name, p.name, "", p.name) for i, p in enumerate(params)]
    spec = batch.NaturalFrequencyRows(STANDARD, scene=name)
    blocks = fast_path._natural_frequency_fast(spec, columns, table, True, {})
    covered = {i for block in blocks for i in block.rows.tolist()}
    clean = set()  # the rows the one-off computes with no warning and no refusal
    for i, row in enumerate(rows):
        try:
            result = spec.compute({p.name: cell for p, cell in zip(params, row)}, {})
        except InputError:
            continue
        if not result.warnings:
            clean.add(i)
    assert covered <= clean
    assert len(clean) >= 0.3 * len(rows)
    assert len(covered) >= 0.9 * len(clean), \
        f"{name}: {len(covered)} of {len(clean)} clean rows vectorised"


@pytest.mark.parametrize("name", ["pendulum", "physical-pendulum"])
def test_amplitude_rows_take_the_vectorised_path(tmp_path, name):
    """Rows with an amplitude typed in degrees, radians, turns, grads or bare (radians) up to a
    hair below 180 degrees: the elliptic rows (``auto`` at these amplitudes) are computed by the
    kernel in the unit typed, byte for byte the one-off's; the refused rows are the
    one-off's."""
    rng = random.Random(name)
    halves = {"deg": 180.0, "rad": math.pi, "": math.pi, "turn": 0.5, "grad": 200.0}
    params = ["l"] if name == "pendulum" else ["m", "a", "J"]
    rows = []
    for _ in range(300):
        unit = rng.choice(list(halves))
        x = rng.choice([rng.uniform(0.02, 0.999), 1.0 - 10.0 ** -rng.randint(2, 15), 1.0])
        rows.append([repr(rng.uniform(0.2, 5.0)) for _ in params]
                    + [f"{x * halves[unit]!r} {unit}".strip()])
    path = tmp_path / "rows.csv"
    path.write_text(",".join([*params, "amplitude"]) + "\n"
                    + "\n".join(",".join(r) for r in rows) + "\n")
    for as_json in (False, True):
        assert _run(name, path, True, as_json) == _run(name, path, False, as_json)
    spec = batch.NaturalFrequencyRows(STANDARD, scene=name)
    columns = [batch.Column(i, p, p, "", p) for i, p in enumerate([*params, "amplitude"])]
    blocks = fast_path._natural_frequency_fast(spec, columns, [list(c) for c in zip(*rows)],
                                               True, {})
    covered = {i for block in blocks for i in block.rows.tolist()}
    clean = set()
    for i, row in enumerate(rows):
        try:
            result = spec.compute(dict(zip([*params, "amplitude"], row)), {})
        except InputError:
            continue
        if not result.warnings and result.method == "elliptic":
            clean.add(i)
    assert len(clean) >= 150
    assert covered == clean


def _coriolis_spec(adapter):
    spec = batch.CoriolisRows()
    spec.adapter, spec.fast = adapter, _command_fast
    return spec


def _fake_coriolis(given, settings):
    """a_c = 2 omega x v_r for small whole-number vectors, where every product is exact."""
    import numpy as np

    if set(given) != {"omega", "vr"}:
        return None
    a_c = 2.0 * np.cross(given["omega"], given["vr"])
    size = np.sqrt((a_c * a_c).sum(axis=1))
    exact = (np.abs(given["omega"]) < 10).all(axis=1) & (np.abs(given["vr"]) < 10).all(axis=1)
    exact &= (size == np.round(size)) & (size > 0)
    return Columns({"a_c": a_c, "a_c_mag": size}, exact, model="vectors")


def _command_run(spec, path, fast, as_json):
    out, err = io.StringIO(), io.StringIO()
    code = batch.run_batch(spec, str(path), as_json=as_json, on_error="skip", out=out,
                           err=err, fast=fast)
    return code, out.getvalue(), err.getvalue()


def _same_both_ways(spec, path):
    """Assert the vectorised run of a file writes what the row-by-row run writes (exit status,
    stdout, stderr), CSV and JSON lines; the CSV run's ``(code, out, err)``."""
    runs = []
    for as_json in (False, True):
        fast = _command_run(spec, path, True, as_json)
        assert fast == _command_run(spec, path, False, as_json), as_json
        runs.append(fast)
    return runs[0]


@pytest.mark.parametrize("header", ["omega,vr", "omega [rpm],vr", "omega,vr [km/h]"])
@pytest.mark.parametrize("adapter", [_fake_coriolis, lambda given, settings: None])
def test_command_blocks_equal_the_one_off_rows(tmp_path, adapter, header):
    """The vectorised path of a record command (vectors read from cells, a header unit, cells
    refused, rows the adapter does not mark exact) writes what the one-off path writes."""
    rows = ['"0,0,2","1,0,0"', '"0,0,1","0,3,0"', '"0,0,2","4,0,0"', '"0,0,x","1,0,0"',
            '"0,0,2",', '"0,0,3","1 m/s,0,0"', '"0,0,50","1,0,0"', '"0,0,2","0,0,1"',
            '"0,0,1e400","1,0,0"', '" 0 , 0 , 2 ","-1,0,0"']
    path = tmp_path / "rows.csv"
    path.write_text(header + "\n" + "\n".join(rows) + "\n")
    spec = _coriolis_spec(adapter)
    for as_json in (False, True):
        fast = _command_run(spec, path, True, as_json)
        slow = _command_run(spec, path, False, as_json)
        assert fast == slow
    if adapter is _fake_coriolis and header == "omega,vr":
        table = [[r[1:r.index('",')] for r in rows],
                 [r[r.index('",') + 2:].strip('"') for r in rows]]
        columns = [batch.Column(0, "omega", "omega", "", "omega"),
                   batch.Column(1, "vr", "vr", "", "vr")]
        blocks = _command_fast(spec, columns, table, True, {})
        assert [b.rows.tolist() for b in blocks] == [[0, 1, 2, 9]]  # the others: generic


def test_a_wrong_adapter_is_caught_by_the_probe(tmp_path):
    """An adapter whose numbers are not the one-off's sends its block to the generic path."""
    def wrong(given, settings):
        out = _fake_coriolis(given, settings)
        out.values["a_c_mag"] = out.values["a_c_mag"] * 2.0
        return out

    path = tmp_path / "rows.csv"
    path.write_text('omega,vr\n"0,0,2","1,0,0"\n')
    spec = _coriolis_spec(wrong)
    table = [["0,0,2"], ["1,0,0"]]
    columns = [batch.Column(0, "omega", "omega", "", "omega"),
               batch.Column(1, "vr", "vr", "", "vr")]
    assert _command_fast(spec, columns, table, True, {}) == []
    assert len(_command_fast(_coriolis_spec(_fake_coriolis), columns, table, True, {})) == 1
    assert _command_run(spec, path, True, True) == _command_run(spec, path, False, True)


#: Per command: the spec, and the column sets its rows give (each a header of names).
COMMAND_FILES = {
    "spring-series": (lambda: batch.SpringRows("series"),
                      ["k1,k2", "k1,k2,k3", "k1 [kN/m],k2", "k1 [lbf/in],k2 [lbf/in],k3"]),
    "spring-parallel": (lambda: batch.SpringRows("parallel"),
                        ["k1,k2,k3", "k1,k2 [kN/m]", "k1 [kN/m],k2 [N/mm]"]),
    "damping-ratio": (batch.DampingRows, ["c,k,m", "decrement,omega", "decrement,k,m",
                                          "ratio,cycles,omega", "c [kN*s/m],k,m [g]"]),
    "rolling-onset": (batch.RollingRows, ["v0,mu", "v0,mu,body", "v0,mu,kappa,incline",
                                          "v0,mu,body,radius,omega0", "v0 [km/h],mu,g"]),
    "coriolis": (batch.CoriolisRows, ["omega,vr", "omega,vr,r,alpha", "omega,vr,r,a0,ar,mass",
                                      "omega [rpm],vr [km/h]"]),
    "forced-response": (batch.ForcedRows, ["k,m,zeta,F0,Omega", "omega,m,zeta,base,f_exc",
                                           "k [kN/m],m,c,unbalance,Omega [rpm]",
                                           "omega,zeta,base_accel,Omega",
                                           "k,m,Q,F0,Omega,x0,v0,t",
                                           "omega,m,zeta,base_accel,f_exc,x0,t",
                                           "omega [rpm],m,c,unbalance,Omega,v0,t [ms]",
                                           "k,m,zeta,base,f_exc,x0,v0,t"]),
}

_VECTORS = {"omega", "vr", "r", "alpha", "a0", "ar"}


def _command_cell(rng: random.Random, command: str, name: str) -> str:
    """A random cell for a command's column: plausible values, with now and then an edge
    (zero, negative, huge, tiny, a unit of its own, empty)."""
    edge = rng.random() < 0.15
    if name == "body":
        return rng.choice(["solid-sphere", "hoop", "solid-cylinder", "cube"])
    if name == "cycles":
        return str(rng.randint(1, 10)) if not edge else rng.choice(["0", "2.5", ""])
    if name in _VECTORS and (command == "coriolis" or edge):
        parts = [repr(rng.choice([0.0, float(rng.randint(-5, 5)), rng.uniform(-3, 3)]))
                 for _ in range(3)]
        if edge:
            parts[rng.randrange(3)] = rng.choice(["1e300", "1e-300", "x", "0"])
        return '"' + ",".join(parts) + '"'
    if command == "forced-response" and name in ("zeta", "Q", "Omega", "f_exc", "x0"):
        # light damping (a resonance peak), an excitation within a decade of omega
        value = {"zeta": rng.uniform(0.01, 0.3), "Q": rng.uniform(2, 50),
                 "Omega": rng.uniform(0.1, 10.0), "f_exc": rng.uniform(0.02, 2.0),
                 "x0": rng.uniform(-0.1, 0.1)}[name]
    elif name in ("mu", "kappa", "decrement", "ratio"):
        value = rng.uniform(0.05, 0.9) if name != "ratio" else rng.uniform(1.1, 5)
    elif name == "incline":
        value = rng.uniform(-0.3, 0.3)
    else:
        value = rng.uniform(0.2, 5.0) * 10.0 ** rng.randint(-2, 3)
    if edge:
        return rng.choice(["0", "-1", "1e300", "1e-300", "", "inf",
                           f"{value!r} {'kN/m' if name[0] == 'k' else 'g'}"])
    return repr(value)


@pytest.mark.parametrize("command", list(COMMAND_FILES))
def test_command_rows_vectorised_equal_the_one_off_rows(tmp_path, command):
    """Every command's batch: the vectorised path writes what the one-off path writes, CSV
    and JSON lines, and takes most rows of each file where its adapter exists."""
    make, headers = COMMAND_FILES[command]
    spec = make()
    assert spec.adapter is not None
    for number, header in enumerate(headers):
        rng = random.Random(f"{command}-{header}")
        names = [h.split("[")[0].strip() for h in header.split(",")]
        rows = [",".join(_command_cell(rng, command, name) for name in names)
                for _ in range(80)]
        path = tmp_path / f"rows{number}.csv"
        path.write_text(header + "\n" + "\n".join(rows) + "\n")
        for as_json in (False, True):
            fast = _command_run(spec, path, True, as_json)
            slow = _command_run(spec, path, False, as_json)
            assert fast[0] == slow[0], header
            assert fast[2] == slow[2], header
            assert fast[1].splitlines() == slow[1].splitlines(), header
        covered, clean = _coverage(spec, header, rows)
        assert covered <= clean, header
        share = ONE_OFF_FILES.get((command, header), (0.8, ""))[0]
        assert len(covered) >= share * len(clean), f"{header}: {len(covered)} of {len(clean)}"


#: Files whose rows stay on the one-off path, and why.
ONE_OFF_FILES = {
    # v_transport, v and a_transport_mag of rows with a 1e-300 component next to ordinary
    # ones: the twin of math.hypot is exact only down to 2^-450 of the largest component, and
    # a v_r 1e300 times smaller than Omega x r is summed by the one-off's plain branch
    ("coriolis", "omega,vr,r,alpha"): (0.75, "magnitudes of vectors with 1e-300 components"),
}


def _coverage(spec, header: str, rows: list[str]) -> tuple[set, set]:
    """(rows the vectorised path takes, rows the one-off computes with no warning, or with
    only warnings a vectorised block carries: forced-response undamped, past its peak's or
    its bandwidth's limit)."""
    from dyncalc.physics.forced import UNDAMPED_WARNING

    def carried(warning: str) -> bool:
        return warning == UNDAMPED_WARNING or warning.startswith(
            ("no lower half-power frequency at zeta = ",
             "no upper half-power frequency at zeta = ")) or (
            warning.startswith("zeta = ") and " >= 1/sqrt(2): the amplitude has no resonance "
            "peak; it is largest " in warning)

    import csv

    parsed = list(csv.reader(io.StringIO("\n".join(rows))))
    columns = batch.read_header(1, header.split(","), spec)
    table = [[row[c.index] for row in parsed] for c in columns]
    covered = {i for block in _command_fast(spec, columns, table, True, {})
               for i in block.rows.tolist()}
    clean = set()
    for i, row in enumerate(parsed):
        texts = {c.key: batch.with_header_unit(row[c.index].strip(), c.unit)
                 for c in columns if row[c.index].strip()}
        try:
            if all(map(carried, spec.compute(texts, {}).warnings)):
                clean.add(i)
        except InputError:
            pass
    return covered, clean


def test_a_text_column_is_the_text_in_every_cell():
    """text_column: an object array of n cells, each the str itself (eom's equations, an
    inverse's empty labels), as np.full(n, text, dtype=object) gives it, and none for n=0."""
    import numpy as np

    from dyncalc.physics.columns import text_column

    column = text_column(4, "phi'' = -g*sin(phi)/l")
    assert column.dtype == object and column.shape == (4,)
    assert column.tolist() == ["phi'' = -g*sin(phi)/l"] * 4
    assert (column == np.full(4, "phi'' = -g*sin(phi)/l", dtype=object)).all()
    assert text_column(0, "x").shape == (0,) and text_column(2, "").tolist() == ["", ""]
