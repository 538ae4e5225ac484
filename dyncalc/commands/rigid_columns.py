"""``rigid-body --scene NAME --batch``: the column adapter of a block of rows.

Every rigid-body scene has a column kernel (:mod:`dyncalc.physics.kinetics_columns`: the
exact rational closed forms in certified double-double; :mod:`dyncalc.physics.kinetics_loads_columns`:
the one-off's float formulas in the same order), so a block's rows are computed a column at a
time, bit for bit the one-off's. The rows a kernel leaves (a rounding it cannot certify, a
zero, a warning) get the scene's own physics function on the row's SI floats (no parsing, no
pint, no Result: a few microseconds a row), the very function the one-off calls, so each
value is the one-off's to the bit wherever the one-off is handed the same SI numbers (the
batch's probe checks one row of each block and sends the block to the generic path
otherwise). A row is exact when every input is finite and meets its constraint, the
scene's relations hold, and the physics neither raises nor warns; the other rows take the
generic path, which gives their message. A word column (``body``) stands for its number
(``kappa``), one word a block; a result column (an inverse problem) leaves the block to the
generic path.
"""
from __future__ import annotations

import math

from ..errors import InputError, PhysicsError

__all__ = ["scene_columns", "euler_columns_of"]

#: The modules whose column kernels serve the rigid-body scenes.
_KERNEL_MODULES = ("..physics.kinetics_columns", "..physics.kinetics_loads_columns")


def _defaults(scene, given: set[str]) -> dict[str, float]:
    """SI values of the defaulted parameters not given (``g``); refuses (``InputError``) a
    set of columns that leaves a required parameter or a one-of group open."""
    from ..scenes.runner import _resolve_groups
    from ..units import parse_quantity

    skipped = _resolve_groups(scene, given)
    out = {}
    for param in scene.params:
        if param.name in given or param.name in skipped:
            continue
        if param.default is not None:
            if param.choices is not None:
                raise InputError("a defaulted word")  # (the generic path reads it)
            out[param.name] = float(parse_quantity(param.default, param.dim).si)
        elif not param.optional:
            raise InputError(f"{param.name} missing")
    return out


def _admissible(scene, row: dict[str, float]) -> bool:
    for name, value in row.items():
        constraint = scene.param(name).constraint
        if not math.isfinite(value) or (constraint == "positive" and not value > 0.0) or (
                constraint == "nonnegative" and not value >= 0.0):
            return False
    return all(c.holds(row) for c in scene.constraints)


def _words(scene, given: dict) -> dict[str, float]:
    """The number each word column stands for, by the keyword the physics takes (``body``:
    ``kappa``); the batch hands the adapter one word per block. Refuses (``InputError``) a
    column of several words or of a word the parameter has not (the generic path answers)."""
    out = {}
    for name, column in given.items():
        param = scene.param(name)
        if param.choices is None:
            continue
        word = column[0] if len(column) else None
        value = param.choices.get(word) if isinstance(word, str) else None
        if value is None or isinstance(value, str) or any(w != word for w in column):
            raise InputError("not one number word")
        out["kappa" if name == "body" else name] = float(value)
    return out


def _kernel(scene):
    """The scene's column kernel (:mod:`dyncalc.physics.kinetics_columns`,
    :mod:`dyncalc.physics.kinetics_loads_columns`), or ``None``."""
    import importlib

    for module in _KERNEL_MODULES:   # importing them registers the kernels
        importlib.import_module(module, __package__)
    from ..physics.kinetics_columns import KERNELS

    return KERNELS.get(scene.compute)


def _by_kernel(scene, kernel, arrays: dict, defaults: dict, n: int):
    """The block through the scene's kernel: a row is exact where the kernel says so and
    every input is finite and meets its constraint and the scene's relations (the one-off
    refuses the others, on the generic path)."""
    from ..lazy import numpy as np

    ok = np.ones(n, dtype=bool)
    for name, value in arrays.items():
        constraint = scene.param(name).constraint
        ok &= np.isfinite(value)
        if constraint == "positive":
            ok &= value > 0.0
        elif constraint == "nonnegative":
            ok &= value >= 0.0
    values = {**{name: np.full(n, value) for name, value in defaults.items()}, **arrays}
    for c in scene.constraints:
        ok &= np.broadcast_to(np.asarray(c.holds(values), dtype=bool), (n,))
    safe = {name: np.where(ok, value, 1.0) for name, value in values.items()}
    with np.errstate(all="ignore"):
        out = kernel(**safe)
    out.exact = np.asarray(out.exact, dtype=bool) & ok
    return out


def scene_columns(given: dict, settings: dict):
    """The results of a block of rows of scene ``settings["scene"]`` (``given``: the columns
    by parameter name, float64 SI arrays), or ``None`` when the block is not the adapter's."""
    from ..lazy import numpy as np
    from ..physics.columns import Columns
    from ..scenes import get_scene

    scene = get_scene(settings["scene"])
    if not given or any(scene.param(n) is None for n in given):
        return None
    try:
        defaults = _defaults(scene, set(given))
        words = _words(scene, given)
    except InputError:
        return None
    arrays = {name: np.asarray(value, dtype=float) for name, value in given.items()
              if scene.param(name).choices is None}
    n = len(next(iter(given.values())))
    arrays.update({name: np.full(n, value) for name, value in words.items()})
    kernel = _kernel(scene)
    values: dict = {}
    exact = np.zeros(n, dtype=bool)
    if kernel is not None:
        out = _by_kernel(scene, kernel, arrays, defaults, n)
        if out.values:
            values, exact = dict(out.values), out.exact
    # the rows the kernel leaves (a rounding it cannot certify, a warning, a refusal): the
    # scene's physics on each row's floats
    columns = {name: array.tolist() for name, array in arrays.items()}
    for i in np.flatnonzero(~exact).tolist():
        row = {name: column[i] for name, column in columns.items()}
        if not _admissible(scene, row):
            continue
        try:
            out = scene.compute(**defaults, **row)
        except (InputError, PhysicsError, ArithmeticError, ValueError):
            continue
        if out.warnings or not all(  # a zero the physics does not call exact may be an
                type(v) is float and math.isfinite(v)  # underflow: the one-off's to tell
                and (v != 0.0 or name in out.exact_zeros) for name, v in out.values.items()):
            continue
        if not values:
            values = {name: np.full(n, math.nan) for name in out.values}
        if list(out.values) != list(values):
            continue
        for name, value in out.values.items():
            values[name][i] = value
        exact[i] = True
    if not values:
        return None
    return Columns(values, exact=exact)


def euler_columns_of(given: dict, settings: dict):
    """Euler rows (``inertia_tensor``, ``omega``, ``alpha`` columns: ``(n, 3, 3)`` and
    ``(n, 3)`` SI arrays; a vector left out is zero, as the one-off takes it) through
    :func:`dyncalc.physics.euler_columns.euler_columns`; ``None`` for another block."""
    from ..lazy import numpy as np
    from ..physics.euler_columns import euler_columns

    if settings.get("scene") is not None or "inertia_tensor" not in given \
            or set(given) - {"inertia_tensor", "omega", "alpha"}:
        return None
    J = np.asarray(given["inertia_tensor"], dtype=float)
    if J.ndim != 3 or J.shape[1:] != (3, 3):
        return None
    vectors = [np.asarray(given[name], dtype=float) if name in given else np.zeros((len(J), 3))
               for name in ("omega", "alpha")]
    if any(v.shape != (len(J), 3) for v in vectors):
        return None
    return euler_columns(J, *vectors)
