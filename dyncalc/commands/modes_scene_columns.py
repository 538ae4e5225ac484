"""``modes --scene NAME --batch``: the column adapter of a block of rows.

The scene's linearised matrices (:attr:`dyncalc.scenes.Scene.matrices`) are built a column at
a time with the one-off's float operations in its order (so each row's M and K are the
one-off's to the bit), then solved on a stack
(:func:`dyncalc.physics.modes_columns.stacked_modes`, within 1e-12 of the one-off's
``sygvd``: the documented tolerance of ``modes --batch``). ``spring-coupled-pendulums``
finds each row's equilibrium ``phi2_0`` with the one-off's own bisection
(:func:`dyncalc.physics.lagrange.pendulums_equilibrium`, a row at a time: bit for bit).

``pendulum-on-sliding-block`` (K singular: a rigid-body drift and a swing) is solved in
closed form (:func:`dyncalc.physics.modes_drift.drift_modes`), every row with the one-off's
note of the drift.

A row is exact where every parameter is finite and meets its constraint and the kernel takes
it (the stacked kernel: no rigid-body mode; the closed form: see its module);
the other rows take the generic path, which gives their message. Rows are grouped by which
coordinate is each mode's largest component (``Columns.groups``): it decides whether a modal
mass is in kg or kg*m^2.

Example::

    >>> import numpy as np
    >>> out = scene_columns({n: np.array([v]) for n, v in dict(m1=1.0, m2=1.0, k1=100.0,
    ...                      k2=100.0, k3=50.0).items()}, {"scene": "coupled-blocks"})
    >>> round(float(out.values["omega_2"][0]) ** 2, 9)
    200.0
"""
from __future__ import annotations

import json
import math

__all__ = ["scene_columns", "SCENES", "TIE"]

#: A mode whose two largest components differ by less than this share is the one-off's.
TIE = 1e-9


def _coupled_blocks(v, np):
    zero = np.zeros_like(v["m1"])
    M = np.stack([np.stack([v["m1"], zero], -1), np.stack([zero, v["m2"]], -1)], -2)
    K = np.stack([np.stack([v["k1"] + v["k3"], -v["k3"]], -1),
                  np.stack([-v["k3"], v["k2"] + v["k3"]], -1)], -2)
    return M, K, None


def _block_disk_springs(v, np):
    M_, m, r, k = v["M"], v["m"], v["r"], v["k"]
    zero = np.zeros_like(m)
    M = np.stack([np.stack([M_ + m, -m * r], -1), np.stack([-m * r, 1.5 * m * r * r], -1)],
                 -2)
    K = np.stack([np.stack([k, zero], -1), np.stack([zero, k * r * r], -1)], -2)
    return M, K, None


def _pendulums(v, np):
    from ..physics.lagrange import pendulums_equilibrium

    m, l, k, b, g = (v[name] for name in ("m", "l", "k", "b", "g"))
    phi = np.array([pendulums_equilibrium(*row) for row in
                    zip(m.tolist(), l.tolist(), k.tolist(), b.tolist(), g.tolist())],
                   dtype=float).reshape(m.shape)
    s = np.array([math.sin(p) for p in phi.tolist()], dtype=float).reshape(m.shape)
    c = np.array([math.cos(p) for p in phi.tolist()], dtype=float).reshape(m.shape)
    zero = np.zeros_like(m)
    inertia = 2.0 * m * l * l
    k11 = 2.0 * m * g * l * c
    k22 = k11 + k * (4.0 * l * l * c * c - 2.0 * l * s * (2.0 * l * s - b))
    M = np.stack([np.stack([inertia, zero], -1), np.stack([zero, inertia], -1)], -2)
    K = np.stack([np.stack([k11, zero], -1), np.stack([zero, k22], -1)], -2)
    return M, K, phi


def _drift(v, normalize: str):
    from ..physics.modes_drift import drift_modes

    return drift_modes(v["m1"], v["m2"], v["l"], v["g"], normalize)


#: The scenes on columns: their matrices (``None``: solved in closed form, :data:`SOLVED`)
#: and their constant linearisation facts (coordinates, kinds, the equilibrium's words;
#: ``None``: per row, from ``phi2_0``).
SCENES = {
    "coupled-blocks": (_coupled_blocks, ("x1", "x2"), ("length", "length"),
                       "x1 = x2 = 0 (springs unstretched)"),
    "block-disk-springs": (_block_disk_springs, ("x", "phi"), ("length", "angle"),
                           "x = 0, phi = 0 (both springs unstressed)"),
    "spring-coupled-pendulums": (_pendulums, ("phi1", "phi2"), ("angle", "angle"), None),
    "pendulum-on-sliding-block": (None, ("x", "phi"), ("length", "angle"),
                                  "phi = 0 (bob below the pin), any x"),
}
#: The scenes whose modes come in closed form, not from the stacked kernel: (SI columns by
#: name, normalize) -> Columns.
SOLVED = {"pendulum-on-sliding-block": _drift}


def _defaults(scene, given) -> dict | None:
    """SI values of the defaulted parameters not given (``g``); ``None`` where a required
    one is missing (the generic path says so)."""
    from ..units import parse_quantity

    out = {}
    for param in scene.params:
        if param.name in given:
            continue
        if param.default is None:
            return None  # (block-disk-springs' optional r too: the one-off refuses it)
        out[param.name] = float(parse_quantity(param.default, param.dim).si)
    return out


def _holds(constraint, values: dict, rows: int, np):
    """Where a scene's relation holds: on the columns at once, else a row at a time."""
    try:
        with np.errstate(all="ignore"):
            held = np.asarray(constraint.holds(values), dtype=bool)
        return np.broadcast_to(held, (rows,))
    except (TypeError, ValueError, ArithmeticError):
        return np.fromiter((bool(constraint.holds({k: float(a[i]) for k, a in values.items()}))
                            for i in range(rows)), dtype=bool, count=rows)


def scene_columns(given: dict, settings: dict):
    """The results of a block of rows of scene ``settings["scene"]`` (``given``: the columns
    by parameter name, float64 SI arrays), or ``None`` where the block is not the adapter's."""
    from ..lazy import numpy as np
    from ..physics.columns import Columns
    from ..physics.modes_columns import stacked_modes
    from ..scenes import get_scene

    scene = get_scene(settings["scene"]) if settings.get("scene") else None
    if scene is None or scene.name not in SCENES or not given:
        return None
    name = scene.name
    if any(scene.param(key) is None or scene.param(key).choices is not None for key in given):
        return None
    defaults = _defaults(scene, given)
    if defaults is None:
        return None
    rows = len(next(iter(given.values())))
    values = {key: np.asarray(array, dtype=float) for key, array in given.items()}
    ok = np.ones(rows, dtype=bool)
    for key, array in values.items():
        constraint = scene.param(key).constraint
        with np.errstate(invalid="ignore"):
            ok &= np.isfinite(array) & ((array > 0.0) if constraint == "positive" else
                                        (array >= 0.0) if constraint == "nonnegative" else True)
    values = {key: np.where(ok, array, 1.0) for key, array in values.items()}
    values.update({key: np.full(rows, value) for key, value in defaults.items()})
    for constraint in scene.constraints:  # (the one-off's relations, such as "two k > 0")
        ok &= _holds(constraint, values, rows, np)
    build, coordinates, kinds, equilibrium = SCENES[name]
    normalize = settings.get("normalize") or "max"
    if build is None:
        out, phi = SOLVED[name](values, normalize), None
    else:
        with np.errstate(all="ignore"):
            M, K, phi = build(values, np)
        out = stacked_modes(M, K, normalize)
    exact = np.asarray(out.exact, dtype=bool) & ok
    results = dict(out.values)
    if phi is not None:
        results["phi2_0"] = phi
    n = len(coordinates)
    shapes = np.stack([results[f"mode_{i + 1}"] for i in range(n)], -1)  # (rows, n, modes)
    size = np.abs(shapes)
    # the largest and second largest component of each mode (of two, the larger and smaller:
    # numpy's sort along an axis of two costs as much as the rest of the modes' columns)
    top = size.max(axis=1)
    second = size.min(axis=1) if n == 2 else np.sort(size, axis=1)[:, -2, :]
    # a mode whose two largest components are nearly equal: the one-off's pick is its own
    exact &= (top - second > TIE * top).all(axis=1)
    reference = np.argmax(np.abs(shapes), axis=1)  # each mode's largest component
    rotation = (np.asarray(kinds) == "angle")[reference]  # modal mass in kg*m^2
    groups = (rotation * (2 ** np.arange(n))).sum(axis=1) if len(set(kinds)) > 1 else None
    extra = {"coordinates": [{"name": c, "kind": "translation" if k == "length" else "rotation",
                              "unit": "m" if k == "length" else "rad"}
                             for c, k in zip(coordinates, kinds)], "normalize": normalize}
    if equilibrium is not None:
        text = json.dumps({**extra, "equilibrium": equilibrium})

        def extras(keep):
            return [text]
    else:
        head = json.dumps(extra)[:-1] + ', "equilibrium": '

        def extras(keep):
            return [head, [json.dumps(f"phi1 = 0, phi2 = phi2_0 = {p:.6g} rad")
                           for p in phi[keep].tolist()], "}"]
    return Columns(results, exact, model=out.model, method=out.method, extras=extras,
                   groups=groups, warnings=out.warnings, warned=out.warned)
