"""``coriolis --batch`` Earth inverse rows on columns: a result column (``a_c_mag``,
``a_c_horizontal_mag``, ``F_c_mag``, ``F_c_horizontal_mag``) with ``?`` in the ``vr``,
``omega``, ``mass`` or ``latitude`` column (the speed given as ``vr`` or ``speed``) (``a_c_mag=0.01m/s^2 --latitude 45deg
vr=?``). The one-off poses them as :data:`dyncalc.scenes.coriolis_scalar.EARTH` and solves
them with :func:`dyncalc.scenes.inverse.solve`; here the same steps run through the scene's
column kernel (:func:`~dyncalc.physics.earth_scalar_columns.coriolis_earth_columns`): a
speed, rate or mass in closed form
(:func:`~dyncalc.scenes.inverse_columns.closed_form_columns`), a latitude by the one-off's
grid, bracket and Brent's method
(:func:`~dyncalc.scenes.inverse_brackets.bracketed_columns`). A probe row run by the one-off
must agree to the bit (values, order, model, method, ``extra``); every other row (a heading
to solve for, a refusal, a warning, a row the kernel cannot certify) runs the one-off."""
from __future__ import annotations

import json

import numpy as np

from .fast import FastBlock, _input_texts, json_head
from .fast_commands import _inputs, _read_rows, _stripped, _typed_units
from .fast_coriolis import _probe, _TargetParam, asked_blocks, coriolis_fast

#: The columns an Earth inverse row may give, by the scene parameter each gives.
_PARAMS = {"latitude": "latitude", "vr": "vr", "speed": "vr", "heading": "heading",
           "omega": "omega", "mass": "mass"}
#: The unknowns solved here (a heading, on whose sine squared the result depends, is not;
#: ``speed=?`` the one-off refuses: the scene's parameter is ``vr``).
_SOLVED = ("latitude", "vr", "omega", "mass")


class _Scene:
    """The Earth scene with its latitude constraint left to the kernel (which checks it on
    the SI radians, as the one-off does, whatever form the latitude column takes)."""

    constraints = ()


class _View:
    """The run's spec with the Earth's result columns read as quantities."""

    def __init__(self, spec):
        self.spec, self.strict = spec, spec.strict

    def parameter(self, key):
        from ..scenes.coriolis_scalar import TARGETS

        if key in TARGETS["earth"]:
            from ..result.kinds import result_kind

            return _TargetParam(key, result_kind(key).dim)
        return self.spec.parameter(key)

    def input_names(self, keys):
        return {key: _PARAMS.get(key, key) for key in keys}


def coriolis_rows_fast(spec, columns, table, want_json: bool, cache: dict) -> list:
    """``coriolis``'s vectorised path: :func:`~dyncalc.batch.fast_coriolis.coriolis_fast`
    (forward rows, perpendicular inverse rows), then the Earth's inverse rows."""
    blocks = coriolis_fast(spec, columns, table, want_json, cache)
    if table and any(col.key == "latitude" for col in columns):
        blocks += earth_inverse_blocks(spec, columns, table, want_json, cache)
    return blocks


def earth_inverse_blocks(spec, columns, table, want_json: bool, cache: dict) -> list:
    """The blocks of this chunk's Earth inverse rows solved on columns (see the module)."""
    from ..scenes.coriolis_scalar import TARGETS

    keys = [col.key for col in columns]
    targets = [col for col in columns if col.key in TARGETS["earth"]]
    if len(targets) != 1 or any(k not in _PARAMS and k not in TARGETS["earth"] for k in keys) \
            or "latitude" not in keys or len({_PARAMS.get(k, k) for k in keys}) != len(keys):
        return []
    cells = {col.key: _stripped(table[col.index]) for col in columns}
    n = len(cells[keys[0]])
    return asked_blocks(columns, _SOLVED, cells, n, lambda given, unknown, rows: _solved(
        spec, given, unknown, targets[0], rows, cells, want_json, cache))


def _solved(spec, given, unknown, target, rows, cells, want_json, cache) -> list[FastBlock]:
    from ..commands.coriolis_earth_columns import _degrees
    from ..physics.earth_scalar_columns import coriolis_earth_columns
    from ..scenes.coriolis_scalar import EARTH
    from ..scenes.inverse_brackets import bracketed_columns
    from ..scenes.inverse_columns import closed_form_columns

    view = _View(spec)
    read = _read_rows(view, given, rows, cells, cache)
    if read is None:
        return []
    reads, arrays, good = read
    settings = {"units": _typed_units(reads, good),
                "typed": {key: r[2].shown for key, (r, _c) in reads.items() if r[4] == "number"}}
    arguments = {}
    for col in given:
        if col is target:
            continue
        name, value = _PARAMS[col.key], np.asarray(arrays[col.key], dtype=float)
        if value.ndim != 1:
            return []
        good &= np.isfinite(value)
        if name in ("latitude", "heading"):
            degrees = _degrees(col.key, value, settings)
            if degrees is None:
                return []
            good &= degrees[1]
            arguments["phi" if name == "latitude" else "psi"] = degrees[0]
        elif name == "mass":
            good &= value > 0.0
        else:
            good &= value >= 0.0
        arguments[name] = value
    goal = np.asarray(arrays[target.key], dtype=float)
    good &= np.isfinite(goal)
    if not good.any():
        return []
    arguments = {k: np.where(good, v, 0.0 if k in ("phi", "psi", "latitude") else 1.0)
                 for k, v in arguments.items()}
    param = EARTH.param(_PARAMS[unknown.key])
    with np.errstate(all="ignore"):
        if param.name == "latitude":
            arguments.pop("phi", None)
            how = "bracketed-root"
            solved = bracketed_columns(_Scene, coriolis_earth_columns, param, target.key,
                                       arguments, np.where(good, goal, 1.0), {})
        else:
            how = "closed-form"
            solved = closed_form_columns(_Scene, coriolis_earth_columns, param, target.key,
                                         arguments, np.where(good, goal, 1.0), {})
    if solved is None:
        return []
    exact = good & solved.exact
    blocks = []
    for exponent in sorted(set(solved.exponent[exact].tolist())):
        keep = np.flatnonzero(exact & (solved.exponent == exponent))
        values = {param.name: solved.x[keep]}
        values.update((name, array[keep]) for name, array in solved.out.values.items())
        detail = (f"{target.key} is proportional to {param.name}^({exponent}): inverted "
                  "exactly" if how == "closed-form" else
                  f"a sign change on a grid of {param.name}, refined by Brent's method")
        extra = {"inverse": {"unknown": param.name, "method": how, "detail": detail}}
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
